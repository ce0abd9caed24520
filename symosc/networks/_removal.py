"""Pole removal steps shared by the synthesis modules (private), Bulgakov (1954), §9.23, Theorem IV."""

from __future__ import annotations

import sympy as sp

from ..errors import ModelError
from .oneports import Capacitor, Inductor, OnePort, Parallel, Series


def pole_at_infinity(F: sp.Expr, p: sp.Symbol) -> sp.Expr:
    """Residue ``k`` of the pole of ``F`` at infinity (``F ~ k p``), 0 when there is none."""
    N, D = sp.fraction(sp.cancel(F))
    N, D = sp.Poly(N, p), sp.Poly(D, p)
    if N.degree() == D.degree() + 1:
        return sp.cancel(N.LC() / D.LC())
    if N.degree() > D.degree() + 1:
        raise ModelError("multiple pole at infinity: not a positive-real function")
    return sp.Integer(0)


def pole_at_zero(F: sp.Expr, p: sp.Symbol) -> sp.Expr:
    """Residue ``k`` of the pole of ``F`` at ``p = 0`` (``F ~ k/p``), 0 when there is none."""
    _N, D = sp.fraction(sp.cancel(F))
    D = sp.Poly(D, p)
    if D.eval(0) != 0:
        return sp.Integer(0)
    return sp.cancel(_lim0(p * F, p))


def _lim0(G: sp.Expr, p: sp.Symbol) -> sp.Expr:
    N, D = sp.fraction(sp.cancel(G))
    N, D = sp.Poly(N, p), sp.Poly(D, p)
    if D.eval(0) == 0:
        raise ModelError("multiple pole at p = 0: not a positive-real function")
    return N.eval(0) / D.eval(0)


def finite_axis_poles(F: sp.Expr, p: sp.Symbol) -> list[tuple[sp.Expr, sp.Expr]]:
    """Pairs ``(w2, k)``: poles at ``p = ±i sqrt(w2)``, ``w2 > 0``, with ``F ~ 2 k p/(p² + w2)``."""
    _N, D = sp.fraction(sp.cancel(F))
    Dp = sp.Poly(D, p)
    G = sp.gcd(Dp, sp.Poly(D.subs(p, -p), p))
    out = []
    for factor, _ in sp.factor_list(G.as_expr(), p)[1]:
        fpoly = sp.Poly(factor, p)
        if fpoly.degree() < 2 or fpoly.eval(0) == 0:
            continue
        y = sp.Dummy("y")
        H = sp.Poly(sp.expand(factor.subs(p, sp.sqrt(y))), y)  # polynomial in y = p**2
        if H.degree() <= 2:
            found = sp.roots(H, y, multiple=True)
        else:  # exact real roots (cubic formulas would bring spurious imaginary parts)
            found = [sp.CRootOf(H, i) for i in range(H.count_roots())]
        for r in found:
            w2 = -r
            if not sp.N(w2, 30).is_positive:
                continue
            num, den = sp.fraction(sp.cancel(F))
            k = even_at(num / sp.diff(den, p), p, w2)  # residue N/D' at p = i*sqrt(w2), real
            out.append((w2, k))
    return out


def remove_axis_poles(F: sp.Expr, p: sp.Symbol, mode: str) -> tuple[list[OnePort], sp.Expr]:
    """Remove every imaginary-axis pole of ``F`` (an impedance if ``mode == "Z"``, else an admittance).

    Returns the removed elements (series elements for an impedance, shunt branches for an admittance) and the
    remainder, which keeps the real part of ``F`` on the axis (Theorem IV).
    """
    parts: list[OnePort] = []
    k_inf = pole_at_infinity(F, p)
    k_0 = pole_at_zero(F, p)
    poles = finite_axis_poles(F, p)
    rest = F - k_inf * p - k_0 / p - sum((2 * k * p / (p**2 + w2) for w2, k in poles), sp.Integer(0))
    if k_inf != 0:
        parts.append(Inductor(k_inf) if mode == "Z" else Capacitor(k_inf))
    if k_0 != 0:
        parts.append(Capacitor(1 / k_0) if mode == "Z" else Inductor(1 / k_0))
    for w2, k in poles:
        if mode == "Z":  # parallel tank: 2kp/(p²+w2) = 1/(C p + 1/(L p)), C = 1/(2k), L = 2k/w2
            parts.append(Parallel((Capacitor(1 / (2 * k)), Inductor(2 * k / w2))))
        else:  # series L-C branch: admittance 2kp/(p²+w2), L = 1/(2k), C = 2k/w2
            parts.append(Series((Inductor(1 / (2 * k)), Capacitor(2 * k / w2))))
    return parts, sp.cancel(sp.together(rest))


def even_at(F: sp.Expr, p: sp.Symbol, x0: sp.Expr) -> sp.Expr:
    """Value of the even part of ``F`` at ``p² = -x0`` (exact, without square roots of ``x0``)."""
    Fe = sp.together((F + F.subs(p, -p)) / 2)
    radical = any(a.is_Pow and not a.exp.is_Integer and not a.has(sp.Symbol) for a in Fe.atoms(sp.Pow))
    Fe = sp.cancel(Fe, extension=True) if radical else sp.cancel(Fe)
    y = sp.Dummy("y")
    num, den = sp.fraction(Fe)
    num = sp.Poly(num, p).as_expr().subs(p, sp.sqrt(y))
    den = sp.Poly(den, p).as_expr().subs(p, sp.sqrt(y))
    value = sp.expand(num.subs(y, -x0)) / sp.expand(den.subs(y, -x0))
    return value if value.is_Rational else sp.radsimp(sp.simplify(value))


def remainder_is_zero(rest: sp.Expr, p: sp.Symbol) -> bool:
    """Exact zero test; with CRootOf coefficients (poles at roots of cubics or higher) a 50-digit test."""
    if rest == 0:
        return True
    if not rest.has(sp.CRootOf):
        return False
    return all(
        abs(sp.N(rest.subs(p, z), 50)) < sp.Float(10) ** -40 for z in (sp.Rational(3, 7) + sp.I, sp.Rational(5, 3))
    )
