"""Fixed points of a one-dimensional point map and their stability (Bulgakov §5.12).

A periodic motion is a fixed point ``x* = P(x*)`` of the point (succession) map of a section; it is stable when
the multiplier ``|P'(x*)| < 1``.  The map may be a SymPy expression (derivative exact) or any Python callable
(derivative by a central difference); the fixed point is found by the secant method on ``P(x) - x``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_positive, validated
from ...errors import ConvergenceError, ParameterError

__all__ = ["PointMapFixedPoint", "point_map_fixed_point"]


@dataclass(frozen=True)
class PointMapFixedPoint(SymPyPrintable):
    """A fixed point of a point map.

    Attributes
    ----------
    x : float
        The fixed point ``x* = P(x*)``.
    multiplier : float
        ``P'(x*)``.
    stable : bool
        ``|P'(x*)| < 1`` (asymptotically stable periodic motion).
    residual : float
        ``|P(x*) - x*|`` reached.
    """

    x: float
    multiplier: float
    stable: bool
    residual: float


@validated
def point_map_fixed_point(
    P: Any, x0: float, *, var: sp.Symbol | None = None, tol: float = 1e-12, step: float = 1e-6
) -> PointMapFixedPoint:
    """Fixed point of the point map ``P`` near ``x0`` and its multiplier (Bulgakov §5.12).

    Parameters
    ----------
    P : Expr or callable
        The map: an expression in ``var`` (or its only free symbol) or a function of one float.
    x0 : float
        Starting guess.
    var : Symbol, optional
        The variable of ``P`` when it is an expression (default: its only free symbol); any other free symbol
        raises ParameterError. Ignored for a callable.
    tol : float
        Tolerance on ``|P(x) - x|``.
    step : float
        Relative step of the central difference for a callable map.

    Examples
    --------
    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> r = point_map_fixed_point(3 * x / (1 + x), 1.0)    # x* = 2, P'(x*) = 3/(1+x*)^2 = 1/3
    >>> round(r.x, 12), round(r.multiplier, 12), r.stable
    (2.0, 0.333333333333, True)

    See Also
    --------
    symosc.nonlinear.half_swing_map
    """
    x0, tol, step = check_finite("x0", x0), check_positive("tol", tol), check_positive("step", step)
    f, df = _as_map(P, var, step)
    g = lambda z: f(z) - z  # noqa: E731
    try:
        xs = float(mpmath.findroot(g, (x0, x0 * (1 + 1e-3) + 1e-3), solver="secant", tol=tol**2, maxsteps=100))
    except (ValueError, ZeroDivisionError) as exc:
        raise ConvergenceError(f"no fixed point of the point map found near x0 = {x0}: {exc}") from exc
    res = abs(f(xs) - xs)
    if not res <= tol * (1 + abs(xs)):
        raise ConvergenceError(f"the fixed-point iteration stopped at x = {xs} with |P(x) - x| = {res}", achieved=res)
    mult = df(xs)
    return PointMapFixedPoint(x=xs, multiplier=mult, stable=abs(mult) < 1, residual=res)


def _as_map(P: Any, var: sp.Symbol | None, step: float) -> tuple[Callable[[float], float], Callable[[float], float]]:
    if isinstance(P, sp.Basic):
        free = P.free_symbols
        if var is None:
            if len(free) != 1:
                raise ParameterError(f"P must have one free symbol (or pass var=), got {sorted(map(str, free))}")
            var = next(iter(free))
        if free - {var}:
            raise ParameterError(f"substitute numbers for {sorted(map(str, free - {var}))}")
        f0 = sp.lambdify(var, P, "mpmath")
        d0 = sp.lambdify(var, sp.diff(P, var), "mpmath")
        return (lambda z: float(f0(z))), (lambda z: float(d0(z)))
    if not callable(P):
        raise ParameterError(f"P must be a SymPy expression or a callable, got {type(P).__name__}")

    def f(z: float) -> float:
        return float(P(float(z)))

    def df(z: float) -> float:
        h = step * max(1.0, abs(z))
        return (f(z + h) - f(z - h)) / (2 * h)

    return f, df
