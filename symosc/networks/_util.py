"""Helpers shared by the network modules (private)."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any

import sympy as sp

from ..errors import ModelError, ParameterError

#: The default operator variable (Carson/Laplace ``p``; put ``p = i*omega`` for steady state).
P = sp.Symbol("p")


def as_expr(value: Any, name: str) -> sp.Expr:
    """Sympify ``value`` or raise ParameterError naming ``name`` (text is refused: write ``sp.Symbol("R1")``, not
    ``"R1"``, so that a typo is never silently a new symbol)."""
    if isinstance(value, str | bytes):
        raise ParameterError(
            f"{name} must be a number or SymPy expression, got the string {value!r} (use sympy.Symbol({value!r}) for a "
            "symbolic value)"
        )
    try:
        expr = sp.sympify(value)
    except (sp.SympifyError, TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a number or SymPy expression, got {value!r}") from exc
    if not isinstance(expr, sp.Expr):
        raise ParameterError(f"{name} must be a scalar expression, got {type(expr).__name__}")
    if expr.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise ParameterError(f"{name} must be finite, got {expr}")
    return expr


_CHECKED: ContextVar[bool] = ContextVar("values_checked", default=False)


@contextmanager
def values_checked() -> Iterator[None]:
    """Within this block :func:`element_value` does not ask SymPy for the sign: for a synthesis whose values were
    proved positive exactly as they were made (SymPy's own test evaluates polynomials in high-degree ``CRootOf``
    numbers numerically, a large part of the time of a large synthesis)."""
    token = _CHECKED.set(True)
    try:
        yield
    finally:
        _CHECKED.reset(token)


def element_value(value: Any, name: str) -> sp.Expr:
    """An element value (R, L, C, ...): a number > 0 or a symbol not known to be negative or zero."""
    expr = as_expr(value, name)
    if _CHECKED.get():
        return expr
    if expr.is_extended_real is False:
        raise ParameterError(f"{name} must be real, got {expr}")
    if expr.is_positive is False:
        raise ParameterError(
            f"{name} = {expr} is not positive; passive elements need positive values "
            "(use a positive number or a symbol declared positive=True)"
        )
    return expr


def connection_parts(parts: Any, cls: str, single: type, operator: str) -> tuple:
    """The parts of a series or parallel connection ``cls(parts)``: a non-empty sequence (a single element of type
    ``single`` is a sequence of one); ``operator`` names the shorthand (``"a + b"``)."""
    if isinstance(parts, single):
        return (parts,)
    try:
        out = () if isinstance(parts, str | bytes) else tuple(parts)
    except TypeError:
        out = ()
    if not out:
        raise ParameterError(
            f"{cls}(parts) needs a non-empty tuple of elements, got {parts!r} (or connect them with {operator})"
        )
    return out


def as_symbol(p: Any, name: str = "p") -> sp.Symbol:
    """Check that ``p`` is a SymPy Symbol."""
    if not isinstance(p, sp.Symbol):
        raise ParameterError(f"{name} must be a SymPy Symbol (the operator variable), got {p!r}")
    return p


def rational_function(Z: Any, p: sp.Symbol, name: str = "Z") -> tuple[sp.Poly, sp.Poly]:
    """Return coprime numerator and denominator polynomials of a rational function ``Z`` of ``p``."""
    expr = as_expr(Z, name)
    expr = sp.cancel(sp.together(expr))
    if not expr.is_rational_function(p):
        raise ModelError(f"{name} must be a rational function of {p}, got {expr}")
    num, den = sp.fraction(expr)
    try:
        N, D = sp.Poly(num, p), sp.Poly(den, p)
    except sp.PolynomialError as exc:
        raise ModelError(f"{name} must be a rational function of {p}, got {expr}") from exc
    if D.is_zero:
        raise ModelError(f"{name} has a zero denominator")
    g = sp.gcd(N, D)
    if g.degree() > 0:
        N, D = sp.div(N, g)[0], sp.div(D, g)[0]
    lc = D.LC()
    if lc != 1:
        N, D = sp.Poly(sp.expand(N.as_expr() / lc), p), sp.Poly(sp.expand(D.as_expr() / lc), p)
    return N, D


def is_zero(expr: sp.Expr) -> bool:
    """Exact test of a rational expression for zero (``cancel``)."""
    return sp.cancel(sp.together(expr)) == 0


def matrix_latex(printer: Any, M: sp.MatrixBase) -> str:
    return printer._print(M) if printer is not None else sp.latex(M)


def synthesis_target(Z: Any, p: Any) -> tuple[sp.Symbol, sp.Poly, sp.Poly]:
    """``(p, N, D)`` of a one-port to synthesise: a rational function of the Symbol ``p`` that is not zero."""
    p = as_symbol(p)
    N, D = rational_function(Z, p)
    if N.is_zero:
        raise ParameterError("Z is identically zero (a short circuit): nothing to synthesise")
    return p, N, D
