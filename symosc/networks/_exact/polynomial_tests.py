"""Tests and roots of real polynomials used by the network procedures (private): Hurwitz and half-line positivity
tests, the largest gain on the imaginary axis, roots with multiplicities."""

from __future__ import annotations

import mpmath
import sympy as sp

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
