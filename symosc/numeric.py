"""Compile SymPy expressions into fast numeric callables.

This module is the only place in symosc that turns symbolic objects into numbers.  :func:`compile`
performs common-subexpression elimination, writes a small Python function (its text is kept in
``.source`` so it can be copied into other programs), and checks its arguments on every call.

Two backends:

``"numpy"``
    Arguments may be scalars or arrays; they broadcast against each other.  For a matrix-valued
    expression of shape ``(r, c)`` the result has shape ``broadcast_shape + (r, c)`` (batch first, as
    ``numpy.linalg`` expects for stacks of matrices).
``"mpmath"``
    Scalar arguments, evaluated in mpmath at the working precision ``dps`` given to :func:`compile`
    (or the current ``mpmath.mp.dps``).  Matrix results are ``mpmath.matrix``.

Examples
--------
>>> import sympy as sp
>>> from symosc.numeric import compile
>>> g, l = sp.symbols("g l", positive=True)
>>> omega = compile(sp.sqrt(g / l), [g, l])
>>> float(omega(9.81, 9.81))
1.0
>>> omega([9.81, 39.24], 9.81).tolist()
[1.0, 2.0]
>>> omega(9.81, -1.0)
Traceback (most recent call last):
...
symosc.errors.ParameterError: l must be positive (declared positive), got -1.0
"""

from __future__ import annotations

import builtins
import inspect
import itertools
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import mpmath
import numpy as np
import sympy as sp
from sympy.printing.numpy import SciPyPrinter
from sympy.printing.pycode import MpmathPrinter

from .errors import ParameterError
from .symbols import natural_key

__all__ = ["CompiledFunction", "bind", "compile", "resolve"]

_BACKENDS = ("numpy", "mpmath")


def _as_symbol_list(args: Iterable[Any]) -> list[sp.Symbol]:
    out = []
    for a in args:
        if isinstance(a, (list, tuple)) or (isinstance(a, sp.MatrixBase)):
            out.extend(_as_symbol_list(a))
        elif isinstance(a, sp.Symbol):
            out.append(a)
        else:
            raise ParameterError(f"compile() arguments must be SymPy Symbols, got {a!r} ({type(a).__name__})")
    names = [s.name for s in out]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise ParameterError(f"argument names must be unique; repeated: {', '.join(dup)}")
    return out


def _flatten_exprs(exprs: Any) -> tuple[list[sp.Expr], tuple[int, ...] | None]:
    """Return the flat element list and the output shape (None for a scalar)."""
    if isinstance(exprs, sp.MatrixBase):
        return [sp.sympify(e) for e in exprs], tuple(exprs.shape)
    if isinstance(exprs, (list, tuple)):
        items = [sp.sympify(e) for e in exprs]
        if any(isinstance(e, sp.MatrixBase) for e in items):
            raise ParameterError("compile() takes an expression, a Matrix or a flat sequence of expressions")
        return items, (len(items),)
    return [sp.sympify(exprs)], None


class _SafeNumPyPrinter(SciPyPrinter):
    """NumPy printer (special functions through ``scipy.special``) with fully qualified module names."""

    def __init__(self) -> None:
        super().__init__({"fully_qualified_modules": True, "inline": True, "allow_unknown_functions": False})

    # Complete elliptic integrals: SymPy and SciPy both use the parameter m = k^2.
    def _print_elliptic_k(self, expr: sp.Expr) -> str:
        return f"scipy.special.ellipk({self._print(expr.args[0])})"

    def _print_elliptic_e(self, expr: sp.Expr) -> str:
        if len(expr.args) != 1:
            return self._print_not_supported(expr)
        return f"scipy.special.ellipe({self._print(expr.args[0])})"


def _check_value(symbol: sp.Symbol, value: Any, backend: str) -> Any:
    """Validate one argument value against finiteness and the symbol's sign assumptions."""
    if backend == "mpmath":
        try:
            v = mpmath.mpmathify(value)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"{symbol.name}: cannot convert {value!r} to an mpmath number") from exc
        finite = mpmath.isfinite(v)
        real = not isinstance(v, mpmath.mpc)
        arr_min = v if real else None
    else:
        v = np.asarray(value)
        if v.dtype == object:
            try:
                v = v.astype(float)
            except (TypeError, ValueError) as exc:
                raise ParameterError(f"{symbol.name}: cannot convert {value!r} to a number") from exc
        if not np.issubdtype(v.dtype, np.number) and v.dtype != bool:
            raise ParameterError(f"{symbol.name}: expected a number, got {value!r}")
        finite = bool(np.all(np.isfinite(v)))
        real = not np.iscomplexobj(v)
        arr_min = (v.min() if v.size else None) if real else None
    if not finite:
        raise ParameterError(f"{symbol.name} must be finite, got {value!r}")
    if symbol.is_real and not real:
        raise ParameterError(f"{symbol.name} is declared real but got a complex value {value!r}")
    if arr_min is not None:
        if symbol.is_positive and not arr_min > 0:
            raise ParameterError(f"{symbol.name} must be positive (declared positive), got {value!r}")
        if symbol.is_nonnegative and not arr_min >= 0:
            raise ParameterError(f"{symbol.name} must be non-negative (declared nonnegative), got {value!r}")
    if backend != "mpmath" and v.ndim == 0:
        return v.item()  # a plain scalar keeps the generated code on its scalar fast path
    return v


@dataclass(frozen=True)
class CompiledFunction:
    """A numeric function generated from SymPy expressions by :func:`compile`.

    Call it with one value per argument, in the order of :attr:`args`, or with a mapping through
    :meth:`call`.  :attr:`source` is the generated Python code.
    """

    args: tuple[sp.Symbol, ...]
    backend: str
    shape: tuple[int, ...] | None
    source: str
    dps: int | None
    check: bool
    _func: Callable = field(repr=False, compare=False)

    @property
    def raw(self) -> Callable:
        """The generated function without argument checks (for inner loops such as ODE right-hand sides)."""
        return self._func

    def __call__(self, *values: Any) -> Any:
        if len(values) != len(self.args):
            names = ", ".join(s.name for s in self.args)
            raise ParameterError(f"expected {len(self.args)} arguments ({names}), got {len(values)}")
        if self.backend == "mpmath":
            # Convert inputs at the working precision, so that strings such as "1e-10" keep all their digits.
            with mpmath.workdps(self.dps or mpmath.mp.dps):
                if self.check:
                    values = tuple(_check_value(s, v, self.backend) for s, v in zip(self.args, values, strict=True))
                else:
                    values = tuple(mpmath.mpmathify(v) for v in values)
                return self._func(*values)
        if self.check:
            values = tuple(_check_value(s, v, self.backend) for s, v in zip(self.args, values, strict=True))
        return self._func(*values)

    def call(self, values: Mapping[Any, Any]) -> Any:
        """Evaluate with a mapping from argument symbols (or their names) to values."""
        return self(*resolve(self.args, values))


def resolve(symbols: Sequence[sp.Symbol], values: Mapping[Any, Any]) -> list[Any]:
    """Pick the value of each symbol from ``values`` (keyed by Symbol or by name).

    Raises :class:`ParameterError` listing every missing name.

    >>> import sympy as sp
    >>> m, g = sp.symbols("m g")
    >>> resolve([m, g], {"m": 2.0, g: 9.81})
    [2.0, 9.81]
    >>> resolve([m, g], {"m": 2.0})
    Traceback (most recent call last):
    ...
    symosc.errors.ParameterError: missing values for: g
    """
    by_name: dict[str, Any] = {}
    for k, v in values.items():
        name = k.name if isinstance(k, sp.Symbol) else str(k)
        by_name[name] = v
    missing = [s.name for s in symbols if s.name not in by_name]
    if missing:
        raise ParameterError("missing values for: " + ", ".join(missing))
    return [by_name[s.name] for s in symbols]


def bind(expr: Any, values: Mapping[Any, Any]) -> Any:
    """Substitute numeric ``values`` (keyed by Symbol or name) into ``expr`` exactly (no floats added).

    >>> import sympy as sp
    >>> a, b = sp.symbols("a b")
    >>> bind(a + b, {"a": 1, "b": sp.Rational(1, 2)})
    3/2
    """
    expr = sp.sympify(expr)
    syms = {s.name: s for s in expr.free_symbols}
    sub = {}
    for k, v in values.items():
        name = k.name if isinstance(k, sp.Symbol) else str(k)
        if name in syms:
            sub[syms[name]] = sp.sympify(v)
    return expr.xreplace(sub)


_counter = itertools.count()


def compile(
    exprs: Any,
    args: Sequence[Any],
    *,
    backend: str = "numpy",
    dps: int | None = None,
    check: bool = True,
    name: str | None = None,
) -> CompiledFunction:
    """Compile a SymPy expression, Matrix or flat sequence of expressions into a numeric callable.

    Parameters
    ----------
    exprs : Expr, Matrix or sequence of Expr
        What to evaluate.  A sequence gives a 1-D result.
    args : sequence of Symbol
        The arguments, in call order.  Nested sequences and column matrices of symbols are flattened.
        Every free symbol of ``exprs`` must be among them.
    backend : {"numpy", "mpmath"}
        ``"numpy"`` broadcasts over array arguments; ``"mpmath"`` evaluates scalars at ``dps`` digits.
    dps : int, optional
        Decimal digits for the mpmath backend (default: the current ``mpmath.mp.dps``).
    check : bool
        Check argument count, finiteness and declared signs (``positive``/``nonnegative``/``real``
        assumptions) on every call.  The unchecked function is always available as ``.raw``.
    name : str, optional
        Name of the generated function (shown in ``.source``).

    Returns
    -------
    CompiledFunction

    Raises
    ------
    ParameterError
        If ``exprs`` has free symbols that are not arguments (all of them are named), if an argument is
        not a Symbol, or if argument names repeat.

    Examples
    --------
    >>> import sympy as sp
    >>> x, k = sp.symbols("x k", real=True)
    >>> f = compile(sp.Matrix([[sp.cos(k * x), 1], [0, x**2]]), [x, k])
    >>> f([0.0, 1.0], 2.0).shape
    (2, 2, 2)
    >>> compile(x + k, [x])
    Traceback (most recent call last):
    ...
    symosc.errors.ParameterError: expression depends on symbols that are not arguments: k
    >>> import mpmath
    >>> h = compile(sp.exp(x), [x], backend="mpmath", dps=30)
    >>> mpmath.nstr(h(1), 30)
    '2.71828182845904523536028747135'
    """
    if backend not in _BACKENDS:
        raise ParameterError(f"unknown backend {backend!r}; choose one of {_BACKENDS}")
    arg_syms = _as_symbol_list(args)
    items, shape = _flatten_exprs(exprs)
    free = set().union(*(e.free_symbols for e in items)) if items else set()
    missing = free - set(arg_syms)
    if missing:
        names = ", ".join(s.name for s in sorted(missing, key=natural_key))
        raise ParameterError(f"expression depends on symbols that are not arguments: {names}")
    fname = name or f"_symosc_f{next(_counter)}"
    if not fname.isidentifier():
        raise ParameterError(f"name must be a Python identifier, got {name!r}")

    items = [_evaluate_root_constants(e, (dps or mpmath.mp.dps) + 10 if backend == "mpmath" else 20) for e in items]
    arg_names = _argument_names(arg_syms)
    renamed = {s: sp.Symbol(n, **s.assumptions0) for s, n in zip(arg_syms, arg_names, strict=True)}
    items = [e.xreplace(renamed) for e in items]
    replacements, reduced = sp.cse(items, symbols=sp.numbered_symbols("_c"), optimizations=None, order="none")

    printer = MpmathPrinter({"fully_qualified_modules": True}) if backend == "mpmath" else _SafeNumPyPrinter()
    lines = [f"def {fname}({', '.join(arg_names)}):"]
    lines.append(f'    """Generated by symosc.numeric.compile; arguments: {", ".join(s.name for s in arg_syms)}."""')
    for sym, sub in replacements:
        lines.append(f"    {sym} = {printer.doprint(sub)}")
    element_code = [printer.doprint(e) for e in reduced]
    if backend == "mpmath":
        if shape is None:
            lines.append(f"    return {element_code[0]}")
        else:
            rows, cols = (shape[0], 1) if len(shape) == 1 else shape
            lines.append(f"    _out = mpmath.matrix({rows}, {cols})")
            for idx, code in enumerate(element_code):
                lines.append(f"    _out[{idx // cols}, {idx % cols}] = {code}")
            lines.append("    return _out")
    else:
        # Fast path for scalar calls (ODE right-hand sides): one array built directly, no broadcasting.
        elements = ", ".join(element_code)
        lines.append(f"    if _all_scalar({', '.join(arg_names)}):")
        lines.append(f"        return _scalar_out([{elements}], {shape or ()!r})")
        if arg_names:
            lines.append(f"    _shape = numpy.broadcast_shapes({', '.join(f'numpy.shape({a})' for a in arg_names)})")
        else:
            lines.append("    _shape = ()")
        if shape is None:
            lines.append(f"    return _bcast({element_code[0]}, _shape)")
        else:
            joined = ", ".join(f"_bcast({c}, _shape)" for c in element_code)
            lines.append(f"    return _stack([{joined}], _shape, {shape!r})")
    source = _preamble(backend) + "\n".join(lines) + "\n"
    namespace: dict[str, Any] = {"__builtins__": builtins}
    exec(builtins.compile(source, f"<symosc:{fname}>", "exec"), namespace)
    return CompiledFunction(
        args=tuple(arg_syms),
        backend=backend,
        shape=shape,
        source=source,
        dps=dps,
        check=check,
        _func=namespace[fname],
    )


def _evaluate_root_constants(expr: sp.Expr, digits: int) -> sp.Expr:
    """Replace algebraic-number constants (``CRootOf``) by floats with ``digits`` significant digits.

    Exact matrix functions of matrices with irreducible cubic (or higher) characteristic polynomials
    contain ``CRootOf`` objects, which no numeric printer knows.
    """
    roots = expr.atoms(sp.CRootOf)
    return expr.xreplace({r: r.evalf(digits) for r in roots}) if roots else expr


def _argument_names(symbols: list[sp.Symbol]) -> list[str]:
    """Readable parameter names for the generated code: the symbol's own name where it is a safe identifier."""
    import keyword

    reserved = {"numpy", "mpmath", "_bcast", "_stack", "_shape", "_out"}
    names = []
    for i, s in enumerate(symbols):
        ok = s.name.isidentifier() and not keyword.iskeyword(s.name) and not s.name.startswith("_c")
        ok = ok and s.name not in reserved and s.name not in names
        names.append(s.name if ok else f"_a{i}")
    return names


_SCALAR_TYPES = frozenset({float, int, complex, np.float64, np.float32, np.int64, np.complex128})


def _preamble(backend: str) -> str:
    """Imports and helpers the generated code needs, so that ``.source`` runs on its own."""
    if backend == "mpmath":
        return "import mpmath\n\n\n"
    helpers = "\n\n".join(inspect.getsource(h) for h in (_all_scalar, _scalar_out, _bcast, _stack))
    types = "{float, int, complex, np.float64, np.float32, np.int64, np.complex128}"
    imports = "import numpy\nimport numpy as np\nimport scipy.special\n"
    return f"{imports}\n_SCALAR_TYPES = frozenset({types})\n\n\n{helpers}\n\n"


def _all_scalar(*values: Any) -> bool:
    return all(type(v) in _SCALAR_TYPES for v in values)


def _scalar_out(elements: list, shape: tuple[int, ...]) -> np.ndarray:
    arr = np.array(elements)
    if not np.issubdtype(arr.dtype, np.inexact):
        arr = arr.astype(float)
    return arr.reshape(shape)


def _bcast(value: Any, shape: tuple[int, ...]) -> np.ndarray:
    arr = np.asarray(value)
    if arr.dtype == object:  # e.g. a SymPy-free constant printed as a Python int/float mix
        arr = arr.astype(complex if any(isinstance(x, complex) for x in arr.flat) else float)
    if not np.issubdtype(arr.dtype, np.inexact):
        arr = arr.astype(float)
    return np.broadcast_to(arr, shape) if arr.shape != shape else arr


def _stack(elements: list[np.ndarray], batch: tuple[int, ...], shape: tuple[int, ...]) -> np.ndarray:
    out = np.stack(elements, axis=-1)
    return out.reshape(batch + shape)
