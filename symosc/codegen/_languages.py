"""Per-language emitters: one function computing an array from CSE'd expressions, and the solve glue."""

from __future__ import annotations

import builtins
import keyword
from dataclasses import dataclass

import sympy as sp
from sympy.printing.fortran import FCodePrinter
from sympy.printing.julia import JuliaCodePrinter
from sympy.printing.octave import OctaveCodePrinter

from ..errors import ParameterError
from ..numeric import _c as _cnum
from ..numeric._ode import _SOLVE


@dataclass(frozen=True)
class Kernel:
    """``out = f(inputs)``: ``inputs`` is a list of (array name, symbols), ``out`` has ``shape`` (row-major exprs)."""

    name: str
    inputs: tuple[tuple[str, tuple[sp.Symbol, ...]], ...]
    shape: tuple[int, ...]
    exprs: tuple[sp.Expr, ...]
    doc: str


def _cse(k: Kernel, rename: dict) -> tuple[list, list]:
    """Common subexpressions through numeric's expression graph (temporaries ``x_0, x_1, ...``)."""
    from ..numeric._dag import cse

    items = [sp.sympify(e).xreplace(rename) for e in k.exprs]
    symbols = [rename.get(s, s) for _, syms in k.inputs for s in syms]
    return cse(items, symbols, prefix="x_")


_PYTHON_NAMES = set(keyword.kwlist) | set(dir(builtins)) | {"numpy", "math", "scipy"}
_JULIA_NAMES = set(
    "baremodule begin break catch const continue do else elseif end export false finally for function global if "
    "import let local macro module quote return struct true try using while abstract mutable primitive type where "
    "in isa outer sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh exp log log10 log2 sqrt abs sign "
    "floor ceil min max zeros vcat hcat pi im e Inf NaN ComplexF64 Float64 gamma".split()
)
_OCTAVE_NAMES = set(
    "break case catch classdef continue do else elseif end end_try_catch end_unwind_protect endclassdef "
    "endenumeration endevents endfor endfunction endif endmethods endparfor endproperties endswitch endwhile "
    "enumeration events for function global if methods otherwise parfor properties return switch try until "
    "unwind_protect unwind_protect_cleanup while spmd endspmd sin cos tan asin acos atan atan2 sinh cosh tanh asinh "
    "acosh atanh exp log log10 log2 sqrt abs sign floor ceil min max zeros eye pi e i j Inf NaN eps gamma".split()
)
_FORTRAN_NAMES = set(
    "sin cos tan asin acos atan atan2 sinh cosh tanh exp log log10 sqrt abs sign real dble int nint floor ceiling "
    "max min mod modulo huge tiny matmul maxloc cmplx aimag conjg gamma log_gamma erf erfc pi module contains end "
    "subroutine function implicit none intent in out inout do if then else call return program use integer real "
    "logical character complex parameter dimension".split()
)
#: Names an argument or a function may not take in each language (keywords and the library names the generated
#: code calls); an argument with such a name gets a local name of its own, a function name gets a trailing "_".
RESERVED = {
    "c": _cnum._C_KEYWORDS | _cnum._C_RESERVED | {"main", "memcpy", "memset", "symosc_solve", "symosc_loggamma",
                                                   "symosc_mod", "symosc_arg"},
    "python": _PYTHON_NAMES,
    "julia": _JULIA_NAMES,
    "octave": _OCTAVE_NAMES,
    "fortran": _FORTRAN_NAMES,
}  # fmt: skip


def _names(k: Kernel, language: str, locals_: set[str]) -> tuple[dict, list[tuple[str, int, str]], list]:
    """Local variable names for the input symbols, (array, index, local) triples, and (symbol name, local name)
    for every symbol whose own name could not be used (not an identifier, or a keyword or library name)."""
    reserved = {n.lower() for n in RESERVED[language] | locals_}
    rename, loads, used, renamed = {}, [], set(reserved), []
    for arr, syms in k.inputs:
        if arr == "t":  # the time argument is passed as a scalar named t
            rename.update({s: sp.Symbol("t", **s.assumptions0) for s in syms if s.name != "t"})
            continue
        for i, s in enumerate(syms):
            prefixes = ("_", "x_", "symosc") + (("M_", "FP_", "MATH_") if language == "c" else ())  # math.h macros
            ok = s.name.isidentifier() and s.name.isascii() and not s.name.startswith(prefixes)
            local = s.name if ok and s.name.lower() not in used else f"{arr}_{i}"
            used.add(local.lower())
            if local != s.name:
                rename[s] = sp.Symbol(local, **s.assumptions0)
                renamed.append((s.name, local))
            loads.append((arr, i, local))
    return rename, loads, renamed


def _real_only(k: Kernel, language: str) -> None:
    """C and Fortran kernels compute real arrays: refuse the imaginary unit by name."""
    for e in k.exprs:
        if sp.sympify(e).has(sp.I):
            raise ParameterError(
                f"{language} export computes real values; the expression {e} contains the imaginary unit I "
                "(export to python, julia or octave for complex values)"
            )


def _is_complex(k: Kernel) -> bool:
    return any(sp.sympify(e).has(sp.I) for e in k.exprs)


_C_RES = {"out", "t", "y", "p", "v", "a", "i", "j", "k", "n"}


def c_kernel(k: Kernel) -> tuple[str, str, list]:
    _real_only(k, "C")
    rename, loads, renamed = _names(k, "c", _C_RES)
    repl, reduced = _cse(k, rename)
    printer = _cnum.c_printer()
    params = ", ".join([("double t" if a == "t" else f"const double *{a}") for a, _ in k.inputs] + ["double *out"])
    proto = f"void {k.name}({params})"
    body = [f"    const double {loc} = {a}[{i}];" for a, i, loc in loads]
    body += [f"    const double {s} = {_cnum.printed(printer, e)};" for s, e in repl]
    body += [f"    out[{i}] = {_cnum.printed(printer, e)};" for i, e in enumerate(reduced)]
    return f"/* {k.doc} */\n{proto}\n{{\n" + "\n".join(body) + "\n}\n", proto + ";", renamed


def python_kernel(k: Kernel) -> tuple[str, list]:
    from ..numeric._python import SafeNumPyPrinter, ScalarPrinter

    rename, loads, renamed = _names(k, "python", {"out", "t", "y", "p", "v", "a"})
    repl, reduced = _cse(k, rename)
    complex_valued = _is_complex(k)
    printer = SafeNumPyPrinter() if complex_valued else ScalarPrinter(SafeNumPyPrinter())
    args = ", ".join(a for a, _ in k.inputs)
    lines = [f"def {k.name}({args}):", f'    """{k.doc}"""']
    lines += [f"    {loc} = {a}[{i}]" for a, i, loc in loads]
    lines += [f"    {s} = {printer.doprint(e)}" for s, e in repl]
    items = ", ".join(printer.doprint(e) for e in reduced)
    dtype = "complex" if complex_valued else "float"
    lines.append(f"    return numpy.array([{items}], dtype={dtype}).reshape({k.shape!r})")
    return "\n".join(lines) + "\n", renamed


def julia_kernel(k: Kernel) -> tuple[str, list]:
    rename, loads, renamed = _names(k, "julia", {"out", "t", "y", "p", "v", "a"})
    repl, reduced = _cse(k, rename)
    printer = _JuliaPrinter()
    args = ", ".join(a for a, _ in k.inputs)
    lines = [f'"""{k.doc}"""', f"function {k.name}({args})"]
    lines += [f"    {loc} = {a}[{i + 1}]" for a, i, loc in loads]
    lines += [f"    {s} = {_strict(printer, e)}" for s, e in repl]
    element = "ComplexF64, " if _is_complex(k) else ""
    lines.append(f"    out = zeros({element}{', '.join(map(str, k.shape))})")
    lines += [f"    out[{_idx(i, k.shape, 1, ', ')}] = {_strict(printer, e)}" for i, e in enumerate(reduced)]
    lines += ["    return out", "end"]
    return "\n".join(lines) + "\n", renamed


def octave_kernel(k: Kernel) -> tuple[str, list]:
    rename, loads, renamed = _names(k, "octave", {"out", "t", "y", "p", "v", "a"})
    repl, reduced = _cse(k, rename)
    printer = _OctavePrinter()
    args = ", ".join(a for a, _ in k.inputs)
    lines = [f"function out = {k.name}({args})", f"  % {k.doc}"]
    lines += [f"  {loc} = {a}({i + 1});" for a, i, loc in loads]
    lines += [f"  {s} = {_strict(printer, e)};" for s, e in repl]
    shape = k.shape if len(k.shape) == 2 else (k.shape[0], 1)
    lines.append(f"  out = zeros({shape[0]}, {shape[1]});")
    lines += [f"  out({_idx(i, k.shape, 1, ', ')}) = {_strict(printer, e)};" for i, e in enumerate(reduced)]
    lines.append("end")
    return "\n".join(lines) + "\n", renamed


def fortran_kernel(k: Kernel, sizes: dict[str, int]) -> tuple[str, list]:
    _real_only(k, "Fortran")
    rename, loads, renamed = _names(k, "fortran", {"out", "t", "y", "p", "v", "a"})
    repl, reduced = _cse(k, rename)
    args = ", ".join([a for a, _ in k.inputs] + ["out"])
    dims = ", ".join(map(str, k.shape))
    lines = [f"  subroutine {k.name}({args})", f"    ! {k.doc}"]
    if any(a == "t" for a, _ in k.inputs):
        lines.append("    real(8), intent(in) :: t")
    lines += [f"    real(8), intent(in) :: {a}({sizes[a]})" for a, _ in k.inputs if a != "t"]
    lines.append(f"    real(8), intent(out) :: out({dims})")
    locals_ = [loc for _, _, loc in loads] + [str(s) for s, _ in repl]
    if locals_:
        for chunk in range(0, len(locals_), 8):
            lines.append(f"    real(8) :: {', '.join(locals_[chunk : chunk + 8])}")
    lines.append("    real(8), parameter :: pi = 3.14159265358979323846264338327950288d0")
    lines += [f"    {loc} = {a}({i + 1})" for a, i, loc in loads]
    lines += [f"    {s} = {_fortran(e)}" for s, e in repl]
    lines += [f"    out({_idx(i, k.shape, 1, ', ')}) = {_fortran(e)}" for i, e in enumerate(reduced)]
    lines.append(f"  end subroutine {k.name}")
    return "\n".join(lines) + "\n", renamed


def _idx(i: int, shape: tuple[int, ...], base: int, sep: str) -> str:
    if len(shape) == 1:
        return str(i + base)
    return f"{i // shape[1] + base}{sep}{i % shape[1] + base}"


def _float_literal(expr: sp.Rational, exponent: str = "e") -> str | None:
    """A correctly rounded double literal for an integer or rational with a part of 2**53 or more (a literal of
    the integer itself would overflow the target's integer type), "Inf" beyond the double range, else None."""
    if abs(expr.p) < 2**53 and expr.q < 2**53:
        return None
    from ..numeric._emit import double_literal, number_value

    value = number_value(expr)
    text = double_literal(value)
    if text is None:
        return None if exponent == "d" else ("Inf" if value > 0 else "(-Inf)")
    text = text if "e" in text or "." in text else text + ".0"
    text = text.replace("e", exponent) if "e" in text else (text + "d0" if exponent == "d" else text)
    return f"({text})" if text.startswith("-") else text


class _JuliaPrinter(JuliaCodePrinter):
    def __init__(self) -> None:
        super().__init__({"strict": True})

    def _print_Integer(self, expr: sp.Integer) -> str:
        return _float_literal(expr) or super()._print_Integer(expr)

    def _print_Rational(self, expr: sp.Rational) -> str:
        return _float_literal(expr) or super()._print_Rational(expr)


class _OctavePrinter(OctaveCodePrinter):
    def __init__(self) -> None:
        super().__init__({"strict": True})

    def _print_Integer(self, expr: sp.Integer) -> str:
        return _float_literal(expr) or super()._print_Integer(expr)

    def _print_Rational(self, expr: sp.Rational) -> str:
        return _float_literal(expr) or super()._print_Rational(expr)


class _FortranPrinter(FCodePrinter):
    def __init__(self) -> None:
        super().__init__({"standard": 95, "source_format": "free", "human": False, "strict": False})

    def _big(self, expr: sp.Rational) -> str | None:
        if abs(expr.p) < 2**53 and expr.q < 2**53:
            return None
        text = _float_literal(expr, "d")
        if text is None:
            raise ParameterError(f"the constant {expr} is beyond the double range, and Fortran has no infinite literal")
        return text

    def _print_Integer(self, expr: sp.Integer) -> str:
        return self._big(expr) or super()._print_Integer(expr)

    def _print_Rational(self, expr: sp.Rational) -> str:
        return self._big(expr) or super()._print_Rational(expr)


def _strict(printer, e: sp.Expr) -> str:
    try:
        return printer.doprint(e)
    except NotImplementedError as exc:
        raise ParameterError(f"the {printer.language} printer cannot print {e}: {exc}") from exc


def _fortran(e: sp.Expr) -> str:
    printer = _FortranPrinter()
    try:
        _consts, missing, code = printer.doprint(e)
    except NotImplementedError as exc:
        raise ParameterError(f"the Fortran printer cannot print {e}: {exc}") from exc
    if missing:
        raise ParameterError(f"the Fortran printer cannot print {', '.join(map(str, missing))}")
    return code.replace("\n", " ").replace("&", "")


C_SOLVE = _SOLVE

FORTRAN_SOLVE = """\
  subroutine symosc_solve(n, a, b, m, info)
    ! Solve a x = b in place (a n x n, b n x m) by Gaussian elimination with partial pivoting.
    integer, intent(in) :: n, m
    real(8), intent(inout) :: a(n, n), b(n, m)
    integer, intent(out) :: info
    integer :: c, r, piv
    real(8) :: f, tmp(max(n, m))
    info = 0
    do c = 1, n
      piv = c - 1 + maxloc(abs(a(c:n, c)), 1)
      if (.not. abs(a(piv, c)) > 0d0) then
        info = 1
        return
      end if
      if (piv /= c) then
        tmp(1:n) = a(c, :); a(c, :) = a(piv, :); a(piv, :) = tmp(1:n)
        tmp(1:m) = b(c, :); b(c, :) = b(piv, :); b(piv, :) = tmp(1:m)
      end if
      do r = c + 1, n
        f = a(r, c) / a(c, c)
        a(r, c:n) = a(r, c:n) - f * a(c, c:n)
        b(r, :) = b(r, :) - f * b(c, :)
      end do
    end do
    do r = n, 1, -1
      b(r, :) = (b(r, :) - matmul(a(r, r + 1:n), b(r + 1:n, :))) / a(r, r)
    end do
  end subroutine symosc_solve
"""
