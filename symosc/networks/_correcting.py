"""Helpers of the correcting-network module (private): realisability tests, duals, link catalogue."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import mpmath
import sympy as sp

from ..errors import ParameterError
from .oneports import Capacitor, Inductor, OnePort, Parallel, Resistor, Series

_DIGITS = 30


def routh_first_column(D: sp.Poly) -> list[sp.Expr]:
    """First column of the Routh array of ``D`` (exact); the array stops at a zero leading entry."""
    c, n = D.all_coeffs(), D.degree()
    rows = [list(c[0::2]), list(c[1::2])]
    width = len(rows[0])
    rows = [r + [sp.Integer(0)] * (width - len(r)) for r in rows]
    while len(rows) < n + 1:
        a, b = rows[-2], rows[-1]
        if b[0] == 0:
            break
        rows.append([sp.cancel((b[0] * a[i + 1] - a[0] * b[i + 1]) / b[0]) for i in range(width - 1)] + [0])
    return [r[0] for r in rows[: n + 1]]


def is_strictly_hurwitz(D: sp.Poly) -> bool:
    """All roots of ``D`` in the open left half-plane (Routh: first column non-zero, one sign)."""
    if D.degree() == 0:
        return True
    first = routh_first_column(D)
    if len(first) != D.degree() + 1:
        return False
    signs = {sp.sign(v) for v in first}
    return signs in ({1}, {-1})


def nonnegative_on_half_line(f: sp.Poly) -> bool:
    """Exact test that the polynomial ``f(x) >= 0`` for all ``x >= 0``."""
    if f.is_zero:
        return True
    if f.eval(0) < 0:
        return False
    odd = sp.Integer(1)
    for factor, mult in f.sqf_list()[1]:
        if mult % 2:
            odd *= factor.as_expr()
    g = sp.Poly(odd, f.gens[0])
    if g.degree() > 0:
        n_roots = g.count_roots(0, None) - (1 if g.eval(0) == 0 else 0)
        if n_roots:
            return False
    return bool(f.LC() > 0)


def max_gain_on_axis(N: sp.Poly, D: sp.Poly) -> float:
    """``max |N(iω)/D(iω)|`` over ``ω >= 0`` (including ``ω -> ∞``), numerically from the critical points."""
    x = sp.Dummy("x")
    p = N.gens[0]

    def sq(P: sp.Poly) -> sp.Poly:
        e = sp.expand(P.as_expr().subs(p, sp.I * sp.sqrt(x)) * P.as_expr().subs(p, -sp.I * sp.sqrt(x)))
        return sp.Poly(e, x)

    A, B = sq(N), sq(D)
    crit = sp.Poly(sp.expand(A.diff(x).as_expr() * B.as_expr() - A.as_expr() * B.diff(x).as_expr()), x)
    xs = [sp.Integer(0)]
    if not crit.is_zero and crit.degree() > 0:
        xs += [r for r in dict.fromkeys(roots_numeric(crit, real=True)) if r > 0]
    vals = [abs(A.eval(v) / B.eval(v)) for v in xs]
    if A.degree() == B.degree():
        vals.append(abs(A.LC() / B.LC()))
    return float(mpmath.sqrt(max(mpmath.mpf(sp.N(v, _DIGITS)) for v in vals)))


def roots_numeric(f: sp.Poly, real: bool = False) -> list[sp.Expr]:
    """The roots of ``f`` (only the real ones with ``real=True``), repeated by multiplicity, to ``_DIGITS`` digits:
    certified isolation (``real_roots``, ``all_roots``) when the coefficients are rational, which copes with
    multiple roots (mpmath's ``polyroots``, behind ``nroots``, need not converge on them: a double critical point
    and a triple pole raised ``NoConvergence``); ``nroots`` with more steps otherwise."""
    if f.get_domain().is_QQ or f.get_domain().is_ZZ:
        return [sp.N(r, _DIGITS) for r in (f.real_roots() if real else f.all_roots())]
    return [r for r in f.nroots(n=_DIGITS, maxsteps=500) if r.is_real or not real]


def dual(net: OnePort, W2: Any, scale: Callable[[Any, str], Any] | None = None) -> OnePort | None:
    """The inverse network with ``Z_dual = W2 / Z`` (series <-> parallel, L <-> C); None when it has no dual.

    ``scale(value, kind)`` computes the new values when given (``kind`` ``"R"``: the resistance ``W2/R``, ``"L"``:
    the capacitance ``L/W2``, ``"C"``: the inductance ``W2 C``), e.g. in exact field arithmetic; by default they
    are SymPy expressions."""
    if scale is None:
        scale = scale_expr(W2)
    if isinstance(net, Resistor):
        return Resistor(scale(net.R, "R"))
    if isinstance(net, Inductor):
        return Capacitor(scale(net.L, "L"))
    if isinstance(net, Capacitor):
        return Inductor(scale(net.C, "C"))
    if isinstance(net, Series | Parallel):
        parts = [dual(part, W2, scale) for part in net.parts]
        if any(part is None for part in parts):
            return None
        return Parallel(tuple(parts)) if isinstance(net, Series) else Series(tuple(parts))
    return None


def scale_expr(W2: sp.Expr) -> Callable[[sp.Expr, str], sp.Expr]:
    return lambda v, kind: {"R": W2 / v, "L": v / W2, "C": W2 * v}[kind]


def positive(value: Any, name: str) -> sp.Expr:
    """A positive time constant or ratio (a number > 0 or a symbol not known to be non-positive)."""
    try:
        expr = sp.sympify(value)
    except (sp.SympifyError, TypeError) as exc:
        raise ParameterError(f"{name} must be a positive number, got {value!r}") from exc
    if not isinstance(expr, sp.Expr) or expr.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or expr.is_extended_real is False:
        raise ParameterError(f"{name} must be a positive real number, got {value!r}")
    if expr.is_positive is False:
        raise ParameterError(f"{name} = {expr} must be positive")
    return expr


def require_less(small: sp.Expr, large: sp.Expr, text: str) -> None:
    if (large - small).is_positive is False:
        raise ParameterError(text)


#: link name -> (Bulgakov's numeral, table, the transfer in words)
LINKS: dict[str, tuple[str, str, str]] = {
    "attenuator": ("I", "Table 8", "X = 1/k"),
    "lead": ("II", "Table 8", "X = (T2/(k T1)) (T1 p + 1)/(T2 p + 1), T1 > T2"),
    "lead-stabilizing": ("III", "Table 8", "X = (T2/(k T1)) (T1 p - 1)/(T2 p + 1), T1 > T2"),
    "lag": ("IV", "Table 8", "X = (1/k) (T1 p + 1)/(T2 p + 1), T1 < T2"),
    "lag-stabilizing": ("V", "Table 8", "X = (1/k) (T1 p - 1)/(T2 p + 1), T1 < T2"),
    "all-pass": ("VI", "Table 9", "X = (1/k) (T p - 1)/(T p + 1)"),
    "differentiating": ("VII", "Table 9", "X = (1/k) T p/(T p + 1)"),
    "low-pass": ("VIII", "Table 9", "X = (1/k) /(T p + 1)"),
    "second-order": ("IX-XV", "§9.39", "X = (1/k) (T1² p² + 2 ζ1 T1 p ± 1)/(T2² p² + 2 ζ2 T2 p + 1)"),
}


def axis_gain_at_most(N: sp.Poly, D: sp.Poly, k: sp.Expr) -> bool:
    """Exact test of ``|N(iω)/D(iω)| <= k`` for all real ``ω``."""
    x = sp.Dummy("x")
    p = N.gens[0]

    def sq(Pl: sp.Poly) -> sp.Expr:
        return sp.expand(Pl.as_expr().subs(p, sp.I * sp.sqrt(x)) * Pl.as_expr().subs(p, -sp.I * sp.sqrt(x)))

    return nonnegative_on_half_line(sp.Poly(k**2 * sq(D) - sq(N), x))


def flat_factor(N: sp.Poly, D: sp.Poly) -> sp.Expr:
    """A simple rational ``k >= max |N(iω)/D(iω)|``: the exact maximum when it is rational, else 6 digits above."""
    import math

    m = max_gain_on_axis(N, D)
    k = sp.nsimplify(m, rational=True, tolerance=1e-12)
    if k > 0 and axis_gain_at_most(N, D, k):
        return k
    return sp.Rational(math.ceil(m * 10**6), 10**6)
