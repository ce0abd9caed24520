"""Python source for the "numpy" and "mpmath" backends (printers, preamble, scalar fast path)."""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.printing.numpy import SciPyPrinter
from sympy.printing.pycode import MpmathPrinter, PythonCodePrinter

from ..errors import ParameterError
from ._special import SpecialFunctions, helper_source


def big_number(expr: sp.Rational) -> str | None:
    """A float literal for an integer or rational with a part of 2**53 or more (None otherwise).

    Python's ``int * float`` raises ``OverflowError`` beyond the double range and NumPy refuses integers beyond
    int64; a correctly rounded double literal (``float("inf")`` beyond the range) gives the value every compiled
    backend uses.
    """
    if abs(expr.p) < 2**53 and expr.q < 2**53:
        return None
    from ._emit import double_literal, number_value

    value = number_value(expr)
    text = double_literal(value)
    if text is None:
        return 'float("inf")' if value > 0 else '(-float("inf"))'
    return f"({text})" if text.startswith("-") else text


class _ExactNumbers:
    """Printers of integer and rational constants that stay within the double range (see :func:`big_number`)."""

    def _print_Integer(self, expr: sp.Integer) -> str:
        return big_number(expr) or super()._print_Integer(expr)

    def _print_Rational(self, expr: sp.Rational) -> str:
        return big_number(expr) or super()._print_Rational(expr)


class SafeNumPyPrinter(SpecialFunctions, _ExactNumbers, SciPyPrinter):
    """NumPy printer (special functions through ``scipy.special``, with the corrections of
    :mod:`symosc.numeric._special`) with fully qualified module names."""

    def __init__(self) -> None:
        super().__init__({"fully_qualified_modules": True, "inline": True, "allow_unknown_functions": False})
        self.helpers = set()

    def _print_Pi(self, expr: sp.Expr) -> str:
        return self._module_format("numpy.pi")


class ScalarPrinter(_ExactNumbers, PythonCodePrinter):
    """``math``-module printer for real scalar arguments; anything ``math`` lacks goes through NumPy/SciPy.

    Non-integer powers print as ``math.pow`` so that a negative base raises (and the caller falls back to
    NumPy's NaN) instead of giving a Python complex number.
    """

    def __init__(self, fallback: SafeNumPyPrinter) -> None:
        super().__init__({"fully_qualified_modules": True, "inline": True, "allow_unknown_functions": False})
        self._fallback = fallback

    def _print_Pow(self, expr: sp.Pow, rational: bool = False) -> str:
        base, exp = expr.args
        if exp == sp.S.Half:
            return f"{self._module_format('math.sqrt')}({self._print(base)})"
        if exp.is_Integer or base.is_positive:
            return super()._print_Pow(expr, rational=rational)
        return f"{self._module_format('math.pow')}({self._print(base)}, {self._print(exp)})"

    def _print_not_supported(self, expr: Any) -> str:
        return self._fallback.doprint(expr)

    def _print_Function(self, expr: Any) -> str:
        return self._fallback.doprint(expr)

    def _print_elliptic_k(self, expr: sp.Expr) -> str:
        return self._fallback.doprint(expr)

    def _print_elliptic_e(self, expr: sp.Expr) -> str:
        return self._fallback.doprint(expr)

    # math.lgamma is log|Gamma| and math.factorial takes integers: SciPy's corrected mappings instead.
    def _print_loggamma(self, expr: sp.Expr) -> str:
        return self._fallback.doprint(expr)

    def _print_factorial(self, expr: sp.Expr) -> str:
        return self._fallback.doprint(expr)


def _imports(*printers: Any) -> str:
    modules = set()
    for p in printers:
        modules.update(p.module_imports)
    return "".join(f"import {m}\n" for m in sorted(modules))


def _printed(printer: Any, expr: sp.Expr) -> str:
    try:
        code = printer.doprint(expr)
    except (NotImplementedError, TypeError) as exc:  # sympy's PrintMethodNotImplementedError is a NotImplementedError
        raise ParameterError(f"the {_kind(printer)} backend cannot print {expr}: {exc}") from exc
    missing = getattr(printer, "_not_supported", set())
    if missing:
        names = ", ".join(sorted({type(e).__name__ for e in missing}))
        raise ParameterError(
            f"the {_kind(printer)} backend cannot evaluate {names}; use backend='mpmath' or rewrite the expression"
        )
    return code


def _kind(printer: Any) -> str:
    return "mpmath" if isinstance(printer, MpmathPrinter) else "numpy"


def mpmath_source(fname: str, doc: str, arg_names: list[str], replacements, reduced, shape) -> str:
    printer = MpmathPrinter({"fully_qualified_modules": True})
    lines = [f"def {fname}({', '.join(arg_names)}):", f'    """{doc}"""']
    for sym, sub in replacements:
        lines.append(f"    {sym} = {_printed(printer, sub)}")
    element_code = [_printed(printer, e) for e in reduced]
    if shape is None:
        lines.append(f"    return {element_code[0]}")
    else:
        rows, cols = (shape[0], 1) if len(shape) == 1 else shape
        lines.append(f"    _out = mpmath.matrix({rows}, {cols})")
        for idx, code in enumerate(element_code):
            lines.append(f"    _out[{idx // cols}, {idx % cols}] = {code}")
        lines.append("    return _out")
    return "import mpmath\n\n\n" + "\n".join(lines) + "\n"


def numpy_source(fname: str, doc: str, args: list[sp.Symbol], items: list[sp.Expr], shape) -> str:
    """Source of a NumPy function with a ``math``-module fast path for real scalar arguments.

    ``args`` are the argument symbols, already named as the generated code's parameters.  The expressions are
    shared through one graph (:mod:`symosc.numeric._dag`) and printed node by node (:mod:`symosc.numeric._emit`);
    functions outside the printers' small tables are printed by SymPy's NumPy/SciPy printer.  The fast path is
    left for the broadcasting NumPy path on any arithmetic or domain error, so that ``1/x`` at ``x = 0`` gives
    ``inf`` (with NumPy's RuntimeWarning) for scalars and arrays alike.
    """
    from ._dag import Graph
    from ._emit import PythonPrinter

    arg_names = [a.name for a in args]
    graph = Graph(args)
    try:
        nodes = [graph.node(e) for e in items]
    except ValueError as exc:
        raise ParameterError(str(exc)) from exc
    array_printer = SafeNumPyPrinter()
    complex_valued = any(e.has(sp.I) for e in items)
    scalar_printer = array_printer if complex_valued else ScalarPrinter(SafeNumPyPrinter())
    targets = [f"_o{i}" for i in range(len(nodes))]

    helpers: set[str] = set()

    def statements(module: str, printer: Any) -> list[str]:
        emitter = PythonPrinter(graph, arg_names, module, lambda e: _printed(printer, e))
        lines = [f"    {st.target} = {st.text}" for st in emitter.statements(nodes, targets)]
        helpers.update(emitter.helpers)
        return lines

    args_text = ", ".join(arg_names)
    scalar = [f"def _{fname}_scalar({args_text}):", *statements("numpy" if complex_valued else "math", scalar_printer)]
    scalar.append(f"    return [{', '.join(targets)}]")

    lines = [f"def {fname}({args_text}):", f'    """{doc}"""']
    condition = " and ".join(f"type({a}) in _SCALAR_TYPES" for a in arg_names) or "True"
    lines.append(f"    if {condition}:")
    lines.append("        try:")
    lines.append(f"            return _scalar_out(_{fname}_scalar({args_text}), {shape or ()!r})")
    lines.append("        except (ArithmeticError, ValueError, TypeError):")
    lines.append("            pass  # 1/0, a domain error or an overflow: NumPy's inf/nan semantics below")
    lines += [f"    {a} = numpy.asarray({a})" for a in arg_names]
    lines += statements("numpy", array_printer)
    if arg_names:
        lines.append(f"    _shape = numpy.broadcast_shapes({', '.join(f'numpy.shape({a})' for a in arg_names)})")
    else:
        lines.append("    _shape = ()")
    if shape is None:
        lines.append(f"    return _bcast({targets[0]}, _shape)")
    else:
        joined = ", ".join(f"_bcast({c}, _shape)" for c in targets)
        lines.append(f"    return _stack([{joined}], _shape, {shape!r})")
    modules = {"numpy", "math"} if not complex_valued else {"numpy"}
    for p in (array_printer, scalar_printer, getattr(scalar_printer, "_fallback", array_printer)):
        modules.update(p.module_imports)
        helpers.update(getattr(p, "helpers", ()))
    imports = "".join(f"import {m}\n" for m in sorted(modules))
    types = "{float, int, complex, numpy.float64, numpy.float32, numpy.int64, numpy.complex128}"
    preamble = f"{imports}\n_SCALAR_TYPES = frozenset({types})\n\n\n{_HELPERS}{helper_source(helpers)}\n\n"
    return preamble + "\n".join(scalar) + "\n\n\n" + "\n".join(lines) + "\n"


def checked_wrapper_source(fname: str, arg_names: list[str], conditions: list[str], shape) -> str:
    """A checked entry point: real finite (and correctly signed) scalars go straight to the fast path.

    Anything else -- arrays, NaN, a wrong sign, a non-finite result -- goes to ``_slow``, which raises
    or warns naming the argument.
    """
    args = ", ".join(arg_names)
    test = " and ".join([f"type({a}) in _REAL_TYPES" for a in arg_names] + conditions) or "True"
    return (
        f"def _checked({args}):\n"
        f"    if {test}:\n"
        "        try:\n"
        f"            _v = _{fname}_scalar({args})\n"
        "        except (ArithmeticError, ValueError, TypeError):\n"
        "            pass\n"
        "        else:\n"
        "            _s = sum(_v)\n"
        "            if _s - _s == 0:\n"
        f"                return _scalar_out(_v, {shape or ()!r})\n"
        f"    return _slow({args})\n"
    )


_HELPERS = """\
def _scalar_out(elements, shape):
    arr = numpy.array(elements)
    if not numpy.issubdtype(arr.dtype, numpy.inexact):
        arr = arr.astype(float)
    return arr.reshape(shape)


def _bcast(value, shape):
    arr = numpy.asarray(value)
    if arr.dtype == object:  # e.g. a constant printed as a Python int/float mix
        arr = arr.astype(complex if any(isinstance(x, complex) for x in arr.flat) else float)
    if not numpy.issubdtype(arr.dtype, numpy.inexact):
        arr = arr.astype(float)
    return numpy.broadcast_to(arr, shape) if arr.shape != shape else arr


def _stack(elements, batch, shape):
    return numpy.stack(elements, axis=-1).reshape(batch + shape)
"""
