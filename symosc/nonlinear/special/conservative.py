"""One-degree-of-freedom conservative systems ``T = m(q) q'^2 / 2``, potential ``V(q)`` (Bulgakov §5.2).

Equilibria are the zeros of ``V'(q)``: a minimum of V is a center (small oscillations with
``omega^2 = V''/m``), a maximum a saddle whose separatrices leave with slopes ``dq'/dq = ±sqrt(-V''/m)``.  The
period of a libration between the turning points ``q1 < q2`` of the energy level ``E`` and of a rotation over
one period ``L`` of V are the quadratures

    T = 2 ∫_{q1}^{q2} sqrt(m(q) / (2 (E - V(q)))) dq,     T_rot = ∫_0^L sqrt(m(q) / (2 (E - V(q)))) dq,

evaluated with mpmath's tanh-sinh rule, which handles the inverse-square-root end singularities.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_positive, validated
from ...errors import ModelError, ParameterError

__all__ = ["Equilibrium", "classify_equilibrium", "libration_period", "rotation_period"]


@dataclass(frozen=True)
class Equilibrium(SymPyPrintable):
    """Type of an equilibrium of ``m(q) q'' + m'(q) q'^2/2 + V'(q) = 0`` (Bulgakov §5.2).

    Attributes
    ----------
    q : Expr
        The equilibrium.
    kind : str
        ``"center"`` (V has a minimum), ``"saddle"`` (a maximum) or ``"degenerate"`` (``V'' = 0``).
    frequency : Expr or None
        ``sqrt(V''/m)`` at a center.
    separatrix_slopes : tuple or None
        ``(-sqrt(-V''/m), +sqrt(-V''/m))`` at a saddle: slopes ``dq'/dq`` of the separatrices in the phase plane.
    """

    q: sp.Expr
    kind: str
    frequency: sp.Expr | None
    separatrix_slopes: tuple | None

    def _repr_latex_(self) -> str:
        return rf"$q = {sp.latex(self.q)}:\quad \text{{{self.kind}}}$"


def _prepare(V: Any, q: Any, m: Any) -> tuple[sp.Expr, sp.Symbol, sp.Expr]:
    if not isinstance(q, sp.Symbol):
        raise ParameterError(f"q must be a SymPy Symbol, got {q!r}")
    V, m = sp.sympify(V), sp.sympify(m)
    return V, q, m


@validated
def classify_equilibrium(V: Any, q: sp.Symbol, q0: Any, *, m: Any = 1) -> Equilibrium:
    """Classify the equilibrium ``q0`` of a system with inertia ``m(q)`` and potential ``V(q)`` (Bulgakov §5.2).

    Parameters
    ----------
    V : Expr
        Potential energy ``V(q)``, an expression in ``q`` (other symbols are kept, but the sign of ``V''/m`` at
        ``q0`` must then be decidable).
    q : Symbol
        The coordinate, the variable of ``V`` and ``m``.
    q0 : Expr or float
        The equilibrium to classify, a zero of ``V'(q)``; a number or expression.
    m : Expr or float, optional
        Inertia coefficient ``m(q)``, positive at ``q0`` (default 1).

    Returns
    -------
    Equilibrium

    See Also
    --------
    libration_period, rotation_period

    Examples
    --------
    >>> import sympy as sp
    >>> q = sp.Symbol("q")
    >>> classify_equilibrium(-sp.cos(q), q, 0).frequency
    1
    >>> classify_equilibrium(-sp.cos(q), q, sp.pi).separatrix_slopes
    (-1, 1)
    """
    V, q, m = _prepare(V, q, m)
    q0 = sp.sympify(q0)
    d1 = sp.simplify(V.diff(q).subs(q, q0))
    if d1 != 0 and not (d1.is_number and abs(complex(d1)) < 1e-12):
        raise ModelError(f"q0 = {q0} is not an equilibrium: V'(q0) = {d1}")
    d2 = sp.simplify(V.diff(q, 2).subs(q, q0))
    m0 = sp.simplify(m.subs(q, q0))
    if m0.is_number and not m0.is_positive:
        raise ModelError(f"the inertia m(q0) = {m0} must be positive")
    ratio = sp.simplify(d2 / m0)
    if ratio.is_positive:
        return Equilibrium(q0, "center", sp.sqrt(ratio), None)
    if ratio.is_negative:
        s = sp.sqrt(-ratio)
        return Equilibrium(q0, "saddle", None, (-s, s))
    if ratio == 0:
        return Equilibrium(q0, "degenerate", None, None)
    raise ModelError(f"the sign of V''(q0)/m(q0) = {ratio} is not known; substitute numbers for the parameters")


def _numeric(expr: sp.Expr, q: sp.Symbol):
    free = expr.free_symbols - {q}
    if free:
        raise ParameterError(f"substitute numbers for the parameters {sorted(map(str, free))}")
    return sp.lambdify(q, expr, "mpmath")


@validated
def libration_period(V: Any, q: sp.Symbol, energy: float, center: float, *, m: Any = 1, dps: int = 30) -> float:
    """Period of the libration of energy ``E`` around the center ``center`` (Bulgakov §5.2 quadrature).

    The turning points are the nearest zeros of ``E - V`` on each side of the center.

    Parameters
    ----------
    V : Expr
        Potential energy ``V(q)``.
    q : Symbol
        The coordinate.
    energy : float
        Total energy ``E`` (above ``V(center)``).
    center : float
        The center (a minimum of ``V``) around which the libration takes place.
    m : Expr or float
        Inertia coefficient ``m(q) > 0`` (default 1).
    dps : int
        mpmath working digits of the quadrature.

    Examples
    --------
    Pendulum ``V = -cos q`` with amplitude 1 rad: ``T = 4 K(sin^2(1/2))`` (K of parameter m):

    >>> import sympy as sp
    >>> q = sp.Symbol("q")
    >>> round(libration_period(-sp.cos(q), q, -float(sp.cos(1)), 0.0), 10)
    6.6999756644

    See Also
    --------
    rotation_period, classify_equilibrium
    """
    V, q, m = _prepare(V, q, m)
    E, c = check_finite("energy", energy), check_finite("center", center)
    f, mf = _numeric(V, q), _numeric(m, q)
    with mpmath.workdps(dps):
        if f(c) >= E:
            raise ModelError(f"energy {E} is not above V(center) = {float(f(c))}: no libration")
        turning = []
        for direction in (-1, 1):
            step, x = mpmath.mpf("0.01") * (1 + abs(c)), mpmath.mpf(c)
            for _ in range(4000):
                nxt = x + direction * step
                if f(nxt) >= E:
                    turning.append(mpmath.findroot(lambda z: f(z) - E, (x, nxt), solver="anderson"))
                    break
                x, step = nxt, step * 1.01
            else:
                raise ModelError(f"no turning point found on the {'left' if direction < 0 else 'right'}: a rotation?")
        q1, q2 = turning
        T = 2 * mpmath.quad(lambda z: mpmath.sqrt(mf(z) / (2 * (E - f(z)))), [q1, c, q2])
    return float(T)


@validated
def rotation_period(V: Any, q: sp.Symbol, energy: float, period: Any, *, m: Any = 1, dps: int = 30) -> float:
    """Time to advance ``q`` by one period ``L`` of V at energy ``E > max V`` (a rotation, Bulgakov §5.2).

    Parameters
    ----------
    V : Expr
        Periodic potential energy ``V(q)``.
    q : Symbol
        The coordinate.
    energy : float
        Total energy ``E > max V``.
    period : float or Expr
        The period ``L > 0`` of ``V``.
    m : Expr or float
        Inertia coefficient ``m(q) > 0`` (default 1).
    dps : int
        mpmath working digits of the quadrature.

    Examples
    --------
    >>> import sympy as sp
    >>> q = sp.Symbol("q")
    >>> round(rotation_period(-sp.cos(q), q, 3.0, 2 * sp.pi), 10)
    2.6220575543

    See Also
    --------
    libration_period
    """
    V, q, m = _prepare(V, q, m)
    E = check_finite("energy", energy)
    L = check_positive("period", sp.N(sp.sympify(period)))
    f, mf = _numeric(V, q), _numeric(m, q)
    with mpmath.workdps(dps):
        grid = [mpmath.mpf(L) * k / 64 for k in range(65)]
        vmax = max(f(z) for z in grid)
        if vmax >= E:
            raise ModelError(f"energy {E} does not exceed max V ~ {float(vmax)}: the motion is a libration")
        T = mpmath.quad(lambda z: mpmath.sqrt(mf(z) / (2 * (E - f(z)))), grid[::8])
    return float(T)
