"""Bott–Duffin synthesis: a positive-real impedance without transformers (Bott & Duffin 1949; Bulgakov (1954),
§9.27, eqs. (9.408)–(9.423)).

Where Brune's cycle needs unit-coupled coils, Bott and Duffin use Richards' function
``R(p) = (k Z(p) - p Z(k)) / (k Z(k) - p Z(p))`` with ``k > 0`` chosen so that ``Z(k)/k = L`` (``Z(iω0) = iω0 L``):

``Z = [1/(Z(k) R) + p/(k Z(k))]^-1 + [k/(p Z(k)) + R/Z(k)]^-1``,

two parallel pairs in series, each holding a remainder of lower degree after the imaginary-axis removals.  The
dual step (on ``1/Z``) handles ``Z(iω0) = -i|X|``.  The result uses only R, L and C (more of them than Brune).

>>> import sympy as sp
>>> from symosc.networks import bott_duffin_synthesis
>>> p = sp.Symbol("p")
>>> Z = (p**2 + p + 1) / (p**2 + p + 4)
>>> net = bott_duffin_synthesis(Z, p)
>>> sp.cancel(net.impedance(p) - Z)
0
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..errors import ModelError, ParameterError
from ._removal import even_at
from ._synthesis import cancel_algebraic, synthesize
from ._util import P, as_symbol, rational_function
from .oneports import Capacitor, Inductor, OnePort, Parallel, Series
from .positive_real import require_positive_real

__all__ = ["bott_duffin_synthesis"]


def bott_duffin_synthesis(Z: Any, p: sp.Symbol = P) -> OnePort:
    """Realise a positive-real impedance with resistors, inductors and capacitors only (Bott–Duffin).

    Parameters
    ----------
    Z : SymPy expression
        Rational positive-real function of ``p`` with numeric coefficients.
    p : sympy.Symbol

    Returns
    -------
    OnePort
        A series/parallel tree of positive R, L, C whose impedance equals ``Z`` exactly.

    Raises
    ------
    ParameterError
        When ``Z`` is not positive real (naming the failed condition).
    ModelError
        When the equation ``Z(k) = L k`` has no exactly representable positive root.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import bott_duffin_synthesis
    >>> p = sp.Symbol("p")
    >>> bott_duffin_synthesis((p**2 + p + 1) / (p**2 + p + 4), p)
    (C(2) | (L(1/6) + C(3)) | R(1/4)) + (L(1/2) | ((C(2/3) | L(3/4)) + R(1)))

    See Also
    --------
    brune_synthesis, is_positive_real
    """
    p = as_symbol(p)
    N, D = rational_function(Z, p)
    if N.is_zero:
        raise ParameterError("Z is identically zero (a short circuit): nothing to synthesise")
    Z = N.as_expr() / D.as_expr()
    require_positive_real(Z, p)
    return synthesize(Z, p, 0, _bott_duffin_cycle)


def _richards_k(F: sp.Expr, p: sp.Symbol, L: sp.Expr) -> sp.Expr:
    num, den = sp.fraction(cancel_algebraic(F))
    k = sp.Dummy("k", positive=True)
    poly = sp.Poly(sp.expand(num.subs(p, k) - L * k * den.subs(p, k)), k)
    roots = [r for r in poly.real_roots() if r > 0] if poly.domain.is_QQ or poly.domain.is_ZZ else []
    if not roots:
        sols = [s for s in sp.solve(poly.as_expr(), k) if s.is_positive]
        if not sols:
            raise ModelError("Bott–Duffin: Z(k) = L k has no positive root in closed form")
        roots = sols
    return roots[0]


def _bott_duffin_cycle(Z: sp.Expr, p: sp.Symbol, x0: sp.Expr, depth: int) -> OnePort:
    L = even_at(Z / p, p, x0)  # Z(i w0) = i w0 L
    if sp.N(L, 30) > 0:
        F = Z
    else:  # dual step on the admittance: Y(i w0) = i w0 C with C > 0
        F = cancel_algebraic(1 / Z)
        L = even_at(F / p, p, x0)
    k = _richards_k(F, p, L)
    Fk = L * k
    R = cancel_algebraic((k * F - p * Fk) / (k * Fk - p * F))

    def sub(expr: sp.Expr) -> OnePort:
        net = synthesize(cancel_algebraic(expr), p, depth + 1, _bott_duffin_cycle)
        if net is None:
            raise ModelError("Bott–Duffin: a remainder vanished identically")  # pragma: no cover
        return net

    if F is Z:
        first = Parallel((Capacitor(1 / (k * Fk)), sub(Fk * R)))
        second = Parallel((Inductor(Fk / k), sub(Fk / R)))
        return Series((first, second))
    first = Series((sub(1 / (Fk * R)), Inductor(1 / (k * Fk))))
    second = Series((Capacitor(Fk / k), sub(R / Fk)))
    return Parallel((first, second))
