"""Per-language emitters: one function computing an array from CSE'd expressions, and the solve glue."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.printing.c import C99CodePrinter

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
    items = [sp.sympify(e).xreplace(rename) for e in k.exprs]
    return sp.cse(items, symbols=sp.numbered_symbols("x_"), optimizations=None, order="none")


def _names(k: Kernel, reserved: set[str]) -> tuple[dict, list[tuple[str, int, str]]]:
    """Local variable names for the input symbols (renamed where they clash), and (array, index, local) triples."""
    rename, loads, used = {}, [], set(reserved)
    for arr, syms in k.inputs:
        if arr == "t":  # the time argument is passed as a scalar named t
            rename.update({s: sp.Symbol("t", **s.assumptions0) for s in syms if s.name != "t"})
            continue
        for i, s in enumerate(syms):
            local = s.name if (s.name.isidentifier() and s.name.isascii() and s.name.lower() not in used) else None
            if local is None or local.startswith("x_"):
                local = f"{arr}_{i}"
            used.add(local.lower())
            if local != s.name:
                rename[s] = sp.Symbol(local, **s.assumptions0)
            loads.append((arr, i, local))
    return rename, loads


_C_RES = {"out", "t", "y", "p", "v", "a", "i", "j", "k", "n"} | _cnum._C_KEYWORDS | _cnum._C_RESERVED


def c_kernel(k: Kernel) -> tuple[str, str]:
    rename, loads = _names(k, _C_RES)
    repl, reduced = _cse(k, rename)
    printer = C99CodePrinter()
    params = ", ".join([("double t" if a == "t" else f"const double *{a}") for a, _ in k.inputs] + ["double *out"])
    proto = f"void {k.name}({params})"
    body = [f"    const double {loc} = {a}[{i}];" for a, i, loc in loads]
    body += [f"    const double {s} = {_cnum.printed(printer, e)};" for s, e in repl]
    body += [f"    out[{i}] = {_cnum.printed(printer, e)};" for i, e in enumerate(reduced)]
    return f"/* {k.doc} */\n{proto}\n{{\n" + "\n".join(body) + "\n}\n", proto + ";"


def python_kernel(k: Kernel) -> str:
    from ..numeric._python import SafeNumPyPrinter, ScalarPrinter

    rename, loads = _names(k, {"out", "t", "y", "p", "v", "a", "numpy", "math", "scipy"})
    repl, reduced = _cse(k, rename)
    printer = ScalarPrinter(SafeNumPyPrinter())
    args = ", ".join(a for a, _ in k.inputs)
    lines = [f"def {k.name}({args}):", f'    """{k.doc}"""']
    lines += [f"    {loc} = {a}[{i}]" for a, i, loc in loads]
    lines += [f"    {s} = {printer.doprint(e)}" for s, e in repl]
    items = ", ".join(printer.doprint(e) for e in reduced)
    lines.append(f"    return numpy.array([{items}], dtype=float).reshape({k.shape!r})")
    return "\n".join(lines) + "\n"


def julia_kernel(k: Kernel) -> str:
    rename, loads = _names(k, {"out", "t", "y", "p", "v", "a", "pi", "e", "im"})
    repl, reduced = _cse(k, rename)
    args = ", ".join(a for a, _ in k.inputs)
    lines = [f'"""{k.doc}"""', f"function {k.name}({args})"]
    lines += [f"    {loc} = {a}[{i + 1}]" for a, i, loc in loads]
    lines += [f"    {s} = {_strict(sp.julia_code, e)}" for s, e in repl]
    lines.append(f"    out = zeros({', '.join(map(str, k.shape))})")
    lines += [f"    out[{_idx(i, k.shape, 1, ', ')}] = {_strict(sp.julia_code, e)}" for i, e in enumerate(reduced)]
    lines += ["    return out", "end"]
    return "\n".join(lines) + "\n"


def octave_kernel(k: Kernel) -> str:
    rename, loads = _names(k, {"out", "t", "y", "p", "v", "a", "pi", "e", "i", "j"})
    repl, reduced = _cse(k, rename)
    args = ", ".join(a for a, _ in k.inputs)
    lines = [f"function out = {k.name}({args})", f"  % {k.doc}"]
    lines += [f"  {loc} = {a}({i + 1});" for a, i, loc in loads]
    lines += [f"  {s} = {_strict(sp.octave_code, e)};" for s, e in repl]
    shape = k.shape if len(k.shape) == 2 else (k.shape[0], 1)
    lines.append(f"  out = zeros({shape[0]}, {shape[1]});")
    lines += [f"  out({_idx(i, k.shape, 1, ', ')}) = {_strict(sp.octave_code, e)};" for i, e in enumerate(reduced)]
    lines.append("end")
    return "\n".join(lines) + "\n"


def fortran_kernel(k: Kernel, sizes: dict[str, int]) -> str:
    rename, loads = _names(k, {"out", "t", "y", "p", "v", "a", "pi"})
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
    return "\n".join(lines) + "\n"


def _idx(i: int, shape: tuple[int, ...], base: int, sep: str) -> str:
    if len(shape) == 1:
        return str(i + base)
    return f"{i // shape[1] + base}{sep}{i % shape[1] + base}"


def _strict(printer, e: sp.Expr) -> str:
    try:
        return printer(e, strict=True)
    except NotImplementedError as exc:
        raise ParameterError(f"{printer.__name__} cannot print {e}: {exc}") from exc


def _fortran(e: sp.Expr) -> str:
    try:
        _consts, missing, code = sp.fcode(e, standard=95, source_format="free", human=False, strict=False)
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
