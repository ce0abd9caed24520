"""Pole removal steps shared by the synthesis modules (private), Bulgakov (1954), §9.23, Theorem IV."""

from __future__ import annotations

import sympy as sp

from ..errors import ModelError


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
