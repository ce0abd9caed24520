"""C99 source for the "c" backend, and the ctypes caller of the built library."""

from __future__ import annotations

import ctypes
import functools
import keyword
import os
import re
from collections.abc import Callable
from typing import Any

import numpy as np
import sympy as sp

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


@functools.cache
def _printer_class() -> type:
    """``SafeC99Printer``, made on first use: importing SymPy's C printer and building its first instance cost
    about 10 ms, and most generated code never needs it (the graph printer prints sums, products, powers and
    the common functions itself)."""
    from sympy.printing.c import C99CodePrinter

    class SafeC99Printer(C99CodePrinter):
        """SymPy's C99 printer with integers and rationals of 2**53 or more printed as correctly rounded doubles
        (a C integer literal of 2**64 or more wraps around or is refused; ``HUGE_VAL`` beyond the double range),
        and ``loggamma`` and ``Mod`` through :data:`C_HELPERS`."""

        def _print_loggamma(self, expr: sp.Expr) -> str:
            return f"symosc_loggamma({self._print(expr.args[0])})"

        def _print_Mod(self, expr: sp.Expr) -> str:
            return f"symosc_mod({self._print(expr.args[0])}, {self._print(expr.args[1])})"

        def _print_Integer(self, expr: sp.Integer) -> str:
            return _big_literal(expr) or super()._print_Integer(expr)

        def _print_Rational(self, expr: sp.Rational) -> str:
            return _big_literal(expr) or super()._print_Rational(expr)

    return SafeC99Printer


def c_printer() -> Any:
    """A new ``SafeC99Printer``: SymPy's C99 printer with integers and rationals of 2**53 or more printed as
    correctly rounded doubles, and ``loggamma`` and ``Mod`` through :data:`C_HELPERS`."""
    return _printer_class()()


def fallback_printer(to_c: dict[sp.Symbol, sp.Symbol]) -> Callable[[sp.Expr], str]:
    """The fallback of :class:`symosc.numeric._emit.CPrinter`: the C code (:func:`printed`) of an expression whose
    argument symbols ``to_c`` renames to their C names; the printer is made at the first call."""
    printer = None

    def fallback(expr: sp.Expr) -> str:
        nonlocal printer
        if printer is None:
            printer = c_printer()
        return printed(printer, expr.xreplace(to_c))

    return fallback


def _big_literal(expr: sp.Rational) -> str | None:
    if abs(expr.p) < 2**53 and expr.q < 2**53:
        return None
    from ._emit import double_literal, number_value

    value = number_value(expr)
    text = double_literal(value)
    if text is None:
        return "HUGE_VAL" if value > 0 else "(-HUGE_VAL)"
    return f"({text})" if text.startswith("-") else text


def printed(printer: Any, expr: sp.Expr) -> str:
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


#: The declarations of ``<math.h>`` that generated code may use: the C99 functions of doubles and the macros, declared
#: directly for GCC and Clang (``__GNUC__``), ``#include <math.h>`` for any other compiler.  Parsing ``<math.h>``
#: takes GCC 12 about 7 ms, against 24 ms for compiling and linking an empty file; generated code is compiled with
#: ``-Werror=implicit-function-declaration``, so a function missing here is a build error, never an ``int`` result.
#: The ``M_`` constants (SymPy's printer writes ``M_PI``) are defined here because ``-std=c99`` hides them in glibc's
#: ``<math.h>``.
MATH_DECLARATIONS = """\
#if defined(__GNUC__)
double acos(double); double asin(double); double atan(double); double atan2(double, double); double cos(double);
double sin(double); double tan(double); double acosh(double); double asinh(double); double atanh(double);
double cosh(double); double sinh(double); double tanh(double); double exp(double); double exp2(double);
double expm1(double); double frexp(double, int *); int ilogb(double); double ldexp(double, int); double log(double);
double log10(double); double log1p(double); double log2(double); double logb(double); double modf(double, double *);
double scalbn(double, int); double scalbln(double, long); double cbrt(double); double fabs(double);
double hypot(double, double); double pow(double, double); double sqrt(double); double erf(double); double erfc(double);
double lgamma(double); double tgamma(double); double ceil(double); double floor(double); double nearbyint(double);
double rint(double); long lrint(double); long long llrint(double); double round(double); long lround(double);
long long llround(double); double trunc(double); double fmod(double, double); double remainder(double, double);
double remquo(double, double, int *); double copysign(double, double); double nan(const char *);
double nextafter(double, double); double nexttoward(double, long double); double fdim(double, double);
double fmax(double, double); double fmin(double, double); double fma(double, double, double);
#define HUGE_VAL (__builtin_huge_val())
#define INFINITY (__builtin_inff())
#define NAN (__builtin_nanf(""))
#define isfinite(x) __builtin_isfinite(x)
#define isinf(x) __builtin_isinf_sign(x)
#define isnan(x) __builtin_isnan(x)
#define signbit(x) __builtin_signbit(x)
#else
#include <math.h>
#endif
""" + "".join(f"#ifndef {name}\n#define {name} {value}\n#endif\n" for name, value in MATH_MACROS.items())

#: What every generated translation unit starts with (guarded, so that the units joined are one valid C file).
C_PRELUDE = "#ifndef SYMOSC_PRELUDE\n#define SYMOSC_PRELUDE\n" + MATH_DECLARATIONS + C_HELPERS + "#endif\n"


def header_lines(used: str) -> list[str]:
    lines = ["#include <math.h>", C_HELPERS]
    for name, value in MATH_MACROS.items():
        if name in used:
            lines.append(f"#ifndef {name}\n#define {name} {value}\n#endif")
    return lines


#: A kernel of up to this size (characters of expression text, plus 20 per statement) is one C function: shorter
#: to compile and faster to run than the same code cut into parts (values stay in registers, ``sin`` and ``cos`` of
#: one angle become one ``sincos``).
FUNCTION_TEXT = 8000
#: The size of each function ("part") of a longer kernel.  GCC's register allocator and instruction combiner grow
#: faster than linearly with a function's size; parts keep the build time linear.
SEGMENT_TEXT = 1200
#: A kernel is spread over several translation units (compiled in parallel, one per core) from this build cost
#: (:func:`text_cost`) per unit on.
UNIT_TEXT = 6000
#: The build cost of a function call in characters of expression text: GCC spills the live values around each call.
CALL_TEXT = 40
_CALL = re.compile(r"\w\(")


def text_cost(statements: list) -> int:
    """The build cost of ``statements`` in characters of expression text, 20 per statement and :data:`CALL_TEXT`
    per function call added: a rough model of GCC's time, used to balance the translation units."""
    return sum(len(st.text) + 20 + CALL_TEXT * len(_CALL.findall(st.text)) for st in statements)


def kernel_units(
    name: str, inputs: list[tuple[str, list[str]]], statements: list, outputs: str = "out", reserve: int = 0
) -> tuple[list[str], str]:
    """C99 definitions of ``void name(const double *<input>, ..., double *<outputs>)`` from straight-line
    ``statements`` (see :class:`symosc.numeric._emit.Statement`).

    Parameters
    ----------
    name : str
        The function's name.
    inputs : list of (str, list of str)
        The input arrays and the variable name of each element.
    statements : list of Statement
        The code, in evaluation order.
    outputs : str
        The output array.
    reserve : int
        The build cost (:func:`text_cost`) of the other code of the first unit; the first unit gets that much less
        of the kernel.

    Returns
    -------
    units : list of str
        The first unit goes into the caller's source (which provides the prelude): it defines ``name``, or only
        declares it when ``name`` is defined in a unit of its own.  The others start with :data:`C_PRELUDE`.
    proto : str
        The prototype of ``name``.

    Notes
    -----
    A kernel of up to :data:`FUNCTION_TEXT` characters (20 per statement counted) is one function, in a unit of its
    own when it and ``reserve`` each cost at least :data:`UNIT_TEXT` and there are several cores.  A longer one
    is cut into parts of :data:`SEGMENT_TEXT` characters (values passed between parts go through a stack array
    ``_w``), spread over as many translation units as there are cores (a build cost, :func:`text_cost`, of at
    least :data:`UNIT_TEXT` each, the first unit counting ``reserve``).  In every function an input is loaded
    right before its first use: loads all at the top would keep every input live through the whole function,
    which costs the register allocator time.
    """
    where = {var: (arr, i) for arr, names in inputs for i, var in enumerate(names)}
    params = ", ".join([f"const double *restrict {arr}" for arr, _ in inputs] + [f"double *restrict {outputs}"])
    proto = f"void {name}({params})"

    def code(seg: list, cross: dict[str, int]) -> list[str]:
        lines, seen = [], {st.temp for st in seg if st.temp}
        for st in seg:
            for u in st.uses:
                if u in seen:
                    continue
                seen.add(u)
                if u in where:
                    arr, i = where[u]
                    lines.append(f"    const double {u} = {arr}[{i}];")
                else:
                    lines.append(f"    const double {u} = _w[{cross[u]}];")
            if st.temp is None:
                lines.append(f"    {st.target} = {st.text};")
            else:
                lines.append(f"    const double {st.temp} = {st.text};")
                if st.temp in cross:
                    lines.append(f"    _w[{cross[st.temp]}] = {st.temp};")
        return lines

    cores = os.cpu_count() or 1
    if sum(len(st.text) + 20 for st in statements) <= FUNCTION_TEXT:
        lines = [f"{proto}", "{", *code(statements, {}), "}", ""]
        if not statements:
            lines[2:2] = [f"    (void){arr};" for arr, _ in inputs] + [f"    (void){outputs};"]
        if cores > 1 and min(text_cost(statements), reserve) >= UNIT_TEXT:  # both halves worth a compiler each
            return [f"{proto};\n", f"{C_PRELUDE}\n" + "\n".join(lines)], proto
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
    parts = [
        "\n".join([f"void {name}_part{k}({part_params})", "{", *code(seg, cross), "}", ""])
        for k, seg in enumerate(segs)
    ]
    costs = [text_cost(seg) for seg in segs]
    count = max(1, min(cores, (sum(costs) + reserve) // UNIT_TEXT, len(parts)))
    share = (sum(costs) + reserve) / count
    groups: list[list[str]] = [[] for _ in range(count)]
    done = reserve
    for part, cost in zip(parts, costs, strict=True):
        groups[min(count - 1, int((done + cost / 2) // share))].append(part)
        done += cost
    call_args = ", ".join([arr for arr, _ in inputs] + [outputs, "_w"])
    main = [f"void {name}_part{k}({part_params});" for k in range(len(parts))]
    main += ["", *groups[0], proto, "{", f"    double _w[{max(len(cross), 1)}];"]
    main += [f"    {name}_part{k}({call_args});" for k in range(len(parts))]
    main += ["}", ""]
    return ["\n".join(main), *(f"{C_PRELUDE}\n" + "\n".join(g) for g in groups[1:] if g)], proto


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
    cprinter = CPrinter(graph, names, fallback_printer(to_c))
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
        C_PRELUDE,
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
