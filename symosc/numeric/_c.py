"""C99 source for the "c" backend, and the ctypes caller of the built library."""

from __future__ import annotations

import ctypes
import keyword
import os
from typing import Any

import numpy as np
import sympy as sp
from sympy.printing.c import C99CodePrinter

from ..errors import ParameterError
from . import _build
from ._checks import c_condition

_C_KEYWORDS = set(
    "auto break case char const continue default do double else enum extern float for goto if inline int long "
    "register restrict return short signed sizeof static struct switch typedef union unsigned void volatile while "
    "_Bool _Complex _Imaginary".split()
)
_C_RESERVED = set(
    "a out count k i INFINITY NAN HUGE_VAL HUGE_VALF HUGE_VALL isfinite isnan isinf isnormal signbit fpclassify "
    "isgreater isgreaterequal isless islessequal islessgreater isunordered math_errhandling "
    "fabs sqrt cbrt pow exp exp2 "
    "expm1 log log2 log10 log1p sin cos tan asin acos atan atan2 sinh cosh tanh asinh acosh atanh hypot floor ceil "
    "fmin fmax fmod tgamma lgamma erf erfc j0 j1 jn y0 y1 yn round trunc copysign main".split()
)

MATH_MACROS = {
    "M_E": "2.718281828459045235360287471352662498",
    "M_LOG2E": "1.442695040888963407359924681001892137",
    "M_LOG10E": "0.434294481903251827651128918916605082",
    "M_LN2": "0.693147180559945309417232121458176568",
    "M_LN10": "2.302585092994045684017991454684364208",
    "M_PI": "3.141592653589793238462643383279502884",
    "M_PI_2": "1.570796326794896619231321691639751442",
    "M_PI_4": "0.785398163397448309615660845819875721",
    "M_1_PI": "0.318309886183790671537767526745028724",
    "M_2_PI": "0.636619772367581343075535053490057448",
    "M_2_SQRTPI": "1.128379167095512573896158903121545172",
    "M_SQRT2": "1.414213562373095048801688724209698079",
    "M_SQRT1_2": "0.707106781186547524400844362104849039",
}


def c_names(python_names: list[str], reserved: frozenset[str] = frozenset()) -> list[str]:
    """C identifiers for the arguments: the Python name unless it collides with C or ``math.h``."""
    out: list[str] = []
    for i, n in enumerate(python_names):
        ok = n.isidentifier() and n.isascii() and not keyword.iskeyword(n) and not n.startswith("_")
        ok = (
            ok
            and n not in _C_KEYWORDS
            and n not in _C_RESERVED
            and n not in reserved
            and n not in out
            and not n.startswith(("M_", "FP_", "MATH_", "symosc"))
        )
        out.append(n if ok else f"_a{i}")
    return out


class SafeC99Printer(C99CodePrinter):
    """SymPy's C99 printer with integers and rationals of 2**53 or more printed as correctly rounded doubles
    (a C integer literal of 2**64 or more wraps around or is refused; ``HUGE_VAL`` beyond the double range), and
    ``loggamma`` and ``Mod`` through :data:`C_HELPERS`."""

    def _print_loggamma(self, expr: sp.Expr) -> str:
        return f"symosc_loggamma({self._print(expr.args[0])})"

    def _print_Mod(self, expr: sp.Expr) -> str:
        return f"symosc_mod({self._print(expr.args[0])}, {self._print(expr.args[1])})"

    def _print_Integer(self, expr: sp.Integer) -> str:
        return _big_literal(expr) or super()._print_Integer(expr)

    def _print_Rational(self, expr: sp.Rational) -> str:
        return _big_literal(expr) or super()._print_Rational(expr)


def _big_literal(expr: sp.Rational) -> str | None:
    if abs(expr.p) < 2**53 and expr.q < 2**53:
        return None
    from ._emit import double_literal, number_value

    value = number_value(expr)
    text = double_literal(value)
    if text is None:
        return "HUGE_VAL" if value > 0 else "(-HUGE_VAL)"
    return f"({text})" if text.startswith("-") else text


def printed(printer: C99CodePrinter, expr: sp.Expr) -> str:
    """C code of ``expr``, or :class:`ParameterError` naming what the C printer cannot print."""
    if expr.has(sp.I) or any(a.is_real is False for a in expr.atoms(sp.Number)):
        raise ParameterError(
            f"the C backend evaluates real-valued expressions only; {expr} is complex (use backend='numpy')"
        )
    try:
        return printer.doprint(expr)
    except NotImplementedError as exc:  # sympy's PrintMethodNotImplementedError
        funcs = sorted({type(f).__name__ for f in expr.atoms(sp.Function)} - _PRINTABLE)
        what = ", ".join(funcs) if funcs else str(expr)
        raise ParameterError(
            f"the C backend cannot print {what}; use backend='numpy' (SciPy special functions) or 'mpmath'"
        ) from exc


_PRINTABLE = {
    "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh",
    "exp", "log", "Abs", "sign", "floor", "ceiling", "gamma", "loggamma", "erf", "erfc", "Min", "Max", "Piecewise",
}  # fmt: skip


#: Replacements of C library functions whose meaning differs from SymPy's (``lgamma`` is ``log|Gamma|``, ``fmod``
#: truncates where SymPy's ``Mod`` floors), and ``arg`` of a real number; included in every generated unit.
C_HELPERS = """\
static inline double symosc_loggamma(double x) { return x > 0.0 ? lgamma(x) : (x == 0.0 ? HUGE_VAL : NAN); }
static inline double symosc_arg(double x) { return x > 0.0 ? 0.0 : (x < 0.0 ? 3.141592653589793 : NAN); }
static inline double symosc_mod(double x, double y)
{
    const double r = fmod(x, y);
    return (r != 0.0 && ((r < 0.0) != (y < 0.0))) ? r + y : r;
}
"""


def header_lines(used: str) -> list[str]:
    lines = ["#include <math.h>", C_HELPERS]
    for name, value in MATH_MACROS.items():
        if name in used:
            lines.append(f"#ifndef {name}\n#define {name} {value}\n#endif")
    return lines


#: Characters of expression text per function of a long straight-line kernel.  GCC's instruction combiner and
#: register allocator grow faster than linearly with a function's size; splitting keeps the build time linear.
SEGMENT_TEXT = 1200
#: A kernel is spread over several translation units (compiled in parallel, one per core) from this much
#: expression text per unit on.
UNIT_TEXT = 8000


def kernel_units(
    name: str, inputs: list[tuple[str, list[str]]], statements: list, outputs: str = "out"
) -> tuple[list[str], str]:
    """C99 definitions of ``void name(const double *<input>, ..., double *<outputs>)`` from straight-line
    ``statements`` (see :class:`symosc.numeric._emit.Statement`).

    ``inputs`` lists the input arrays and the variable name of each element.  A long kernel is cut into parts of
    :data:`SEGMENT_TEXT` characters of code (values passed between parts go through a stack array ``_w``), spread
    evenly over as many translation units as there are cores (at least :data:`UNIT_TEXT` characters each).
    Returns the units (the first holds ``name``; it has no ``#include``, the caller's source provides it) and the
    prototype of ``name``.
    """
    where = {var: (arr, i) for arr, names in inputs for i, var in enumerate(names)}
    params = ", ".join([f"const double *restrict {arr}" for arr, _ in inputs] + [f"double *restrict {outputs}"])
    proto = f"void {name}({params})"

    def loads(seg: list, local: set[str], cross: dict[str, int]) -> list[str]:
        lines, seen = [], set()
        for st in seg:
            for u in st.uses:
                if u in seen or u in local:
                    continue
                seen.add(u)
                if u in where:
                    arr, i = where[u]
                    lines.append(f"    const double {u} = {arr}[{i}];")
                else:
                    lines.append(f"    const double {u} = _w[{cross[u]}];")
        return lines

    def body(seg: list, cross: dict[str, int]) -> list[str]:
        lines = []
        for st in seg:
            if st.temp is None:
                lines.append(f"    {st.target} = {st.text};")
            else:
                lines.append(f"    const double {st.temp} = {st.text};")
                if st.temp in cross:
                    lines.append(f"    _w[{cross[st.temp]}] = {st.temp};")
        return lines

    if sum(len(st.text) for st in statements) <= SEGMENT_TEXT:
        local = {st.temp for st in statements if st.temp}
        lines = [f"{proto}", "{", *loads(statements, local, {}), *body(statements, {}), "}", ""]
        if not statements:
            lines[2:2] = [f"    (void){arr};" for arr, _ in inputs] + [f"    (void){outputs};"]
        return ["\n".join(lines)], proto
    segs: list[list] = [[]]
    size = 0
    for st in statements:
        if size > SEGMENT_TEXT:
            segs.append([])
            size = 0
        segs[-1].append(st)
        size += len(st.text) + 20
    defined = {st.temp: k for k, seg in enumerate(segs) for st in seg if st.temp}
    cross: dict[str, int] = {}
    for k, seg in enumerate(segs):
        for st in seg:
            for u in st.uses:
                if u not in where and defined[u] != k and u not in cross:
                    cross[u] = len(cross)
    part_params = ", ".join(
        [f"const double *restrict {arr}" for arr, _ in inputs] + [f"double *restrict {outputs}", "double *restrict _w"]
    )
    parts = []
    for k, seg in enumerate(segs):
        local = {st.temp for st in seg if st.temp}
        lines = [f"void {name}_part{k}({part_params})", "{", *loads(seg, local, cross), *body(seg, cross), "}", ""]
        parts.append("\n".join(lines))
    total = sum(len(st.text) for st in statements)
    count = max(1, min(os.cpu_count() or 1, total // UNIT_TEXT, len(parts)))
    groups = [parts[len(parts) * u // count : len(parts) * (u + 1) // count] for u in range(count)]
    call_args = ", ".join([arr for arr, _ in inputs] + [outputs, "_w"])
    main = [f"void {name}_part{k}({part_params});" for k in range(len(parts))]
    main += ["", *groups[0], proto, "{", f"    double _w[{max(len(cross), 1)}];"]
    main += [f"    {name}_part{k}({call_args});" for k in range(len(parts))]
    main += ["}", ""]
    return ["\n".join(main), *(f"#include <math.h>\n{C_HELPERS}\n" + "\n".join(g) for g in groups[1:])], proto


def function_source(fname: str, arg_syms: list[sp.Symbol], arg_names: list[str], items: list[sp.Expr], shape) -> str:
    """Complete C99 source of ``fname`` (scalar, checked scalar and batched entry points)."""
    from ._dag import Graph
    from ._emit import CPrinter, comment_text

    for e in items:
        if e.has(sp.I) or any(a.is_real is False for a in e.atoms(sp.Number)):
            raise ParameterError(
                f"the C backend evaluates real-valued expressions only; {e} is complex (use backend='numpy')"
            )
    names = c_names(arg_names)
    syms = [sp.Symbol(a, **s.assumptions0) for s, a in zip(arg_syms, arg_names, strict=True)]
    to_c = {s: sp.Symbol(c, **s.assumptions0) for s, c in zip(syms, names, strict=True)}
    graph = Graph(syms)
    try:
        nodes = [graph.node(e) for e in items]
    except ValueError as exc:
        raise ParameterError(str(exc)) from exc
    printer = SafeC99Printer()
    cprinter = CPrinter(graph, names, lambda e: printed(printer, e.xreplace(to_c)))
    statements = cprinter.statements(nodes, [f"out[{i}]" for i in range(len(nodes))])
    units, _ = kernel_units(f"{fname}_body", [("a", names)], statements)
    nargs, nout = len(names), len(items)
    what = "a scalar" if shape is None else f"an array of shape {shape}, flattened in row-major (C) order"
    argument_list = ", ".join(f"a[{i}] = {comment_text(s.name)}" for i, s in enumerate(arg_syms)) or "none"
    checks = [f"    if (!{c_condition(s, f'a[{i}]')}) return {i + 1};" for i, s in enumerate(arg_syms)]
    lines = [
        "/* Generated by symosc.numeric.compile (backend 'c').",
        f"   Arguments: {argument_list}.",
        f"   Result: {what} ({nout} double(s)).",
        f"   {fname}(a, out)            evaluates one point; returns 0.",
        f"   {fname}_checked(a, out)    also checks the arguments (finite, declared signs): returns i+1 for a bad",
        "                              argument a[i], -1 when a result is not finite, 0 otherwise.",
        f"   {fname}_batch(count, a, out)  evaluates count points: a is count x {nargs}, out is count x {nout}.",
        f"   Build: cc -O1 -fno-math-errno -std=c99 -fPIC -shared -o {fname}.so {fname}.c -lm */",
        "#include <math.h>",
        C_HELPERS,
        units[0],
        f"int {fname}(const double *a, double *out)",
        "{",
        f"    {fname}_body(a, out);",
        "    return 0;",
        "}",
        "",
        f"int {fname}_checked(const double *a, double *out)",
        "{",
        *checks,
        f"    {fname}_body(a, out);",
        f"    for (int i = 0; i < {nout}; i++)",
        "        if (!isfinite(out[i])) return -1;",
        "    return 0;",
        "}",
        "",
        f"void {fname}_batch(long count, const double *a, double *out)",
        "{",
        "    for (long k = 0; k < count; k++)",
        f"        {fname}_body(a + k * {nargs}, out + k * {nout});",
        "}",
        "",
    ]
    return join_units(["\n".join(lines), *units[1:]])


def join_units(units: list[str]) -> str:
    """One source text of several translation units, separated by :data:`symosc.numeric._build.UNIT_MARKER`
    (:func:`symosc.numeric._build.load` compiles the units in parallel; concatenated they form one valid C file)."""
    return f"\n{_build.UNIT_MARKER}\n".join(units)


class CCaller:
    """Calls the entry points of a built library; holds nothing that cannot be rebuilt from the source."""

    def __init__(self, source: str, fname: str, nargs: int, nout: int, shape) -> None:
        lib = _build.load(source, _build.GENERATED_FLAGS)
        self.lib = lib
        self.nargs, self.nout, self.shape = nargs, nout, shape
        self.scalar = getattr(lib, fname)
        self.checked = getattr(lib, f"{fname}_checked")
        self.batch = getattr(lib, f"{fname}_batch")
        for f in (self.scalar, self.checked):
            f.restype = ctypes.c_int
        self.batch.restype = None
        self.args_type = ctypes.c_double * max(nargs, 1)
        self.out_type = ctypes.c_double * max(nout, 1)
        self.out_shape = shape or ()

    def fast_checked(self, values: tuple) -> tuple[int, Any]:
        """Status and result of the checked scalar entry (status != 0: use the slow path)."""
        try:
            a = self.args_type(*values)
        except TypeError:
            return 1, None
        out = self.out_type()
        status = self.checked(a, out)
        if status:
            return status, None
        return 0, np.frombuffer(out)[: self.nout].reshape(self.out_shape)

    def __call__(self, *values: Any) -> np.ndarray:
        """Unchecked evaluation with NumPy broadcasting over array arguments."""
        try:
            a = self.args_type(*values)
        except TypeError:
            return self._broadcast(values)
        out = self.out_type()
        self.scalar(a, out)
        return np.frombuffer(out)[: self.nout].reshape(self.out_shape)

    def _broadcast(self, values: tuple) -> np.ndarray:
        arrays = [np.asarray(v) for v in values]
        for v in arrays:
            if np.iscomplexobj(v):
                raise ParameterError("the C backend evaluates real arguments only; got a complex value")
        arrays = [np.asarray(v, dtype=float) for v in arrays]
        batch = np.broadcast_shapes(*(v.shape for v in arrays)) if arrays else ()
        count = int(np.prod(batch, dtype=np.int64))
        a = np.empty((count, max(self.nargs, 1)))
        for i, v in enumerate(arrays):
            a[:, i] = np.broadcast_to(v, batch).reshape(-1)
        out = np.empty((count, max(self.nout, 1)))
        if count:
            self.batch(ctypes.c_long(count), a.ctypes.data_as(ctypes.c_void_p), out.ctypes.data_as(ctypes.c_void_p))
        return out[:, : self.nout].reshape(batch + self.out_shape)
