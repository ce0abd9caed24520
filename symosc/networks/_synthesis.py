"""Shared driver of the one-port synthesis procedures (private): removals, minimum resistance, cycles."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import sympy as sp

from ..errors import ModelError
from ._removal import even_at, remove_axis_poles
from ._util import P, as_symbol
from .oneports import BruneSection, OnePort, Parallel, Resistor, Series
from .positive_real import real_part_on_axis

_DIGITS = 50


def minimum_real_part(Z: Any, p: sp.Symbol = P) -> tuple[sp.Expr, sp.Expr]:
    """``(R, ω0²)``: the minimum of ``Re Z(iω)`` over ``ω >= 0`` and where it is reached (``oo`` at infinity).

    Exact: the critical points are the real roots of ``E' Q - E Q'`` (``Re Z(iω) = E(x)/Q(x)``, ``x = ω²``).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import minimum_real_part
    >>> p = sp.Symbol("p")
    >>> minimum_real_part((p**2 + p + 1) / (p**2 + p + 4), p)
    (0, 2)

    See Also
    --------
    brune_synthesis, real_part_on_axis
    """
    p = as_symbol(p)
    E, Q = real_part_on_axis(Z, p)
    x = E.gens[0]
    Q = sp.Poly(Q.as_expr(), x)
    f = E.as_expr() / Q.as_expr()
    candidates: list[tuple[sp.Expr, sp.Expr]] = [(sp.Integer(0), sp.cancel(f.subs(x, 0)))]
    crit = sp.Poly(sp.expand(E.diff(x).as_expr() * Q.as_expr() - E.as_expr() * Q.diff(x).as_expr()), x)
    if not crit.is_zero:
        for r in crit.real_roots():
            if r > 0:
                candidates.append((r, sp.cancel(f.subs(x, r)) if r.is_Rational else f.subs(x, r)))
    degE, degQ = E.degree(), Q.degree()
    if E.is_zero:
        return sp.Integer(0), sp.Integer(0)
    limit = sp.Integer(0) if degE < degQ else (E.LC() / Q.LC() if degE == degQ else sp.oo)
    candidates.append((sp.oo, limit))
    best = min(candidates, key=lambda c: sp.N(c[1], _DIGITS) if c[1] != sp.oo else sp.oo)
    return _simplify_algebraic(best[1]), best[0]


def _simplify_algebraic(value: sp.Expr) -> sp.Expr:
    if value in (sp.oo,) or value.is_Rational:
        return value
    return sp.radsimp(sp.simplify(value))


def join(parts: list[OnePort], rest: OnePort | None, cls: type) -> OnePort:
    items = parts + ([rest] if rest is not None else [])
    return items[0] if len(items) == 1 else cls(tuple(items))


def synthesize(Z: sp.Expr, p: sp.Symbol, depth: int, cycle: Callable | None = None) -> OnePort | None:
    """Network with impedance ``Z`` (None for a short circuit)."""
    if depth > 200:  # pragma: no cover - each step lowers the degree
        raise ModelError("Brune synthesis did not terminate")
    Z = cancel_algebraic(Z)
    if Z == 0:
        return None
    if not Z.has(p):
        value = sp.N(Z, _DIGITS)
        if abs(sp.im(value)) > sp.Float(10) ** (-_DIGITS + 10):
            raise ModelError(f"Brune synthesis reached a complex resistance {value}")
        if not Z.is_real:
            Z = sp.simplify(sp.re(sp.expand_complex(Z)))
        if not sp.re(value) > 0:
            raise ModelError(f"Brune synthesis reached a non-positive resistance {Z}")
        return Resistor(Z)
    parts, rest = remove_axis_poles(Z, p, "Z")
    if parts:
        return join(parts, synthesize(rest, p, depth + 1, cycle), Series)
    Y = sp.cancel(1 / Z)
    parts, rest = remove_axis_poles(Y, p, "Y")
    if parts:
        inner = None if rest == 0 else synthesize(sp.cancel(1 / rest), p, depth + 1, cycle)
        return join(parts, inner, Parallel)
    R, x0 = minimum_real_part(Z, p)
    if R != 0:
        return Series((Resistor(R), *as_list(synthesize(cancel_algebraic(Z - R), p, depth + 1, cycle))))
    if x0 in (0, sp.oo):  # pragma: no cover - excluded by the removals above
        raise ModelError("Re Z vanishes at 0 or infinity after the pole removals")
    return (cycle or brune_cycle)(Z, p, x0, depth)


def as_list(net: OnePort | None) -> list[OnePort]:
    return [] if net is None else [net]


def cancel_algebraic(expr: sp.Expr) -> sp.Expr:
    """Cancel a rational function whose coefficients may be algebraic numbers (square roots)."""
    expr = sp.together(expr)
    if expr.has(sp.Pow) and any(a.is_Pow and not a.exp.is_Integer and not a.has(sp.Symbol) for a in expr.atoms(sp.Pow)):
        return sp.cancel(expr, extension=True)
    return sp.cancel(expr)


def simple(value: sp.Expr) -> sp.Expr:
    return value if value.is_Rational else sp.radsimp(sp.simplify(value))


def brune_cycle(Z: sp.Expr, p: sp.Symbol, x0: sp.Expr, depth: int) -> OnePort:
    L1 = even_at(Z / p, p, x0)  # Z(iω0) = iω0 L1
    if L1 == 0:  # pragma: no cover - a zero on the axis was removed above
        raise ModelError("Brune cycle: Z(iω0) = 0 should have been removed as an axis zero")
    Z1 = cancel_algebraic(Z - L1 * p)
    Y1 = cancel_algebraic(1 / Z1)
    k = even_at(Y1 * (p**2 + x0) / p, p, x0) / 2  # Y1 ~ 2k p/(p² + ω0²)
    L2 = simple(1 / (2 * k))
    C = simple(2 * k / x0)
    Y2 = cancel_algebraic(Y1 - 2 * k * p / (p**2 + x0))
    Z2 = cancel_algebraic(1 / Y2)
    N2, D2 = sp.fraction(Z2)
    N2, D2 = sp.Poly(N2, p), sp.Poly(D2, p)
    if N2.degree() != D2.degree() + 1:
        raise ModelError("Brune cycle: the remainder has no pole at infinity (inexact minimum?)")
    L3 = simple(N2.LC() / D2.LC())
    Z3 = cancel_algebraic(Z2 - L3 * p)
    Lp, Ls, M = simple(L1 + L2), simple(L2 + L3), L2
    load = synthesize(Z3, p, depth + 1)
    if load is None:
        raise ModelError("Brune cycle ended in a short circuit: unexpected for a minimum function")
    return BruneSection(Lp, Ls, M, C, load)
