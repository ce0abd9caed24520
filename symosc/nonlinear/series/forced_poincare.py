"""Poincaré's method with an explicitly periodic right-hand side, resonant case (Bulgakov (1954), §5.23).

``q'' + omega**2 q = mu Phi(q, q', t)`` with ``Phi`` of period ``P = 2 pi / omega`` in ``t`` (5.285).  The period is
fixed (no frequency correction, no free phase); the generating solutions ``q* = C1 cos(omega t) + C2 sin(omega t)``
continue to periodic solutions for small ``mu`` where the periodicity conditions (5.288)

    g1(C) = -(1/(omega P)) Integral(Phi(q*, q*', t) sin(omega t), t, 0, P) = 0
    g2(C) =  (1/(omega P)) Integral(Phi(q*, q*', t) cos(omega t), t, 0, P) = 0

hold with a nonsingular Jacobian.  ``(C1, C2)' = mu g(C)`` is the averaged (variation-of-constants) system, so the
solution is stable when the eigenvalues ``lambda`` of ``dg/dC`` have negative real parts; the Floquet multipliers are
``1 + mu P lambda + O(mu**2)``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ModelError, ParameterError

__all__ = ["ForcedPeriodicSolution", "forced_periodic_solution"]

_N = 512


@dataclass(frozen=True)
class ForcedPeriodicSolution(SymPyPrintable):
    """First approximation ``q = C1 cos(omega t) + C2 sin(omega t)`` of a resonant forced periodic solution.

    Attributes
    ----------
    C : tuple of float
        ``(C1, C2)``.
    omega : float
        Natural (= forcing) frequency.
    jacobian : ndarray, shape (2, 2)
        ``dg/dC`` at the root.
    stable : bool
        Both eigenvalues of :attr:`jacobian` in the open left half-plane.
    """

    C: tuple[float, float]
    omega: float
    jacobian: np.ndarray

    @property
    def amplitude(self) -> float:
        """``sqrt(C1**2 + C2**2)``."""
        return float(np.hypot(*self.C))

    @property
    def stable(self) -> bool:
        return bool(np.all(np.linalg.eigvals(self.jacobian).real < 0))

    def multipliers(self, mu: float) -> np.ndarray:
        """First-order Floquet multipliers ``1 + mu P lambda``.

        Parameters
        ----------
        mu : float
            Value of the small parameter ``mu``; a real number (the multipliers are first order in it).
        """
        return 1.0 + mu * (2 * np.pi / self.omega) * np.linalg.eigvals(self.jacobian)

    def __repr__(self) -> str:
        return (
            f"ForcedPeriodicSolution(C1={self.C[0]:.8g}, C2={self.C[1]:.8g}, {'stable' if self.stable else 'unstable'})"
        )


def _g(Phi: Callable, omega: float, C: np.ndarray) -> np.ndarray:
    P = 2 * np.pi / omega
    t = P * np.arange(_N) / _N
    c, s = np.cos(omega * t), np.sin(omega * t)
    q = C[0] * c + C[1] * s
    v = omega * (-C[0] * s + C[1] * c)
    f = np.broadcast_to(np.asarray(Phi(q, v, t), dtype=float), t.shape)
    return np.array([-(f * s).mean(), (f * c).mean()]) / omega


@validated
def forced_periodic_solution(
    Phi: Callable[..., Any], omega: float, guess: Sequence[float], *, tol: float = 1e-12
) -> ForcedPeriodicSolution:
    """Resonant periodic solution of ``q'' + omega**2 q = mu Phi(q, q', t)`` to first order (Bulgakov (1954), §5.23).

    Parameters
    ----------
    Phi : callable
        ``Phi(q, v, t)`` (vectorized), of period ``2 pi / omega`` in ``t``.
    omega : float
        Natural frequency, equal to the forcing frequency.
    guess : pair of float
        Starting ``(C1, C2)``.
    tol : float
        Residual tolerance of the periodicity conditions.

    Returns
    -------
    ForcedPeriodicSolution

    Raises
    ------
    ConvergenceError
        No root of the periodicity conditions near ``guess``.
    ModelError
        Singular Jacobian at the root (the continuation in ``mu`` is not unique).

    See Also
    --------
    nonresonant_forced_solution : the non-resonant case, as series ``C1(mu)``, ``C2(mu)`` to any order.
    poincare_operator_system : autonomous systems (free phase, frequency correction).
    symosc.nonlinear.limit_cycle : higher orders in the autonomous one-degree-of-freedom case.

    Examples
    --------
    Damped oscillator at resonance, ``q'' + q = mu (-2 beta q' + F cos t)``: ``q = (F / (2 beta)) sin t``.

    >>> import numpy as np
    >>> sol = forced_periodic_solution(lambda q, v, t: -0.2 * v + np.cos(t), 1.0, (1.0, 1.0))
    >>> [round(c, 10) for c in sol.C], sol.stable
    ([0.0, 5.0], True)
    """
    from scipy.optimize import fsolve

    try:
        w = float(omega)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"omega must be a positive number, got {omega!r}") from exc
    if not np.isfinite(w) or w <= 0:
        raise ParameterError(f"omega must be a positive finite number, got {omega!r}")
    if not callable(Phi):
        raise ParameterError(f"Phi must be a callable Phi(q, v, t), got {type(Phi).__name__}")
    g0 = np.asarray(guess, dtype=float)
    if g0.shape != (2,) or not np.all(np.isfinite(g0)):
        raise ParameterError(f"guess must be a finite pair (C1, C2), got {guess!r}")
    C, _info, _ier, msg = fsolve(lambda x: _g(Phi, w, x), g0, full_output=True, xtol=1e-14)
    scale = max(1.0, float(np.max(np.abs(C))))
    res = float(np.max(np.abs(_g(Phi, w, C))))
    if not np.isfinite(res) or res > tol * scale:
        raise ConvergenceError(f"periodicity conditions not met near {tuple(g0)}: residual {res:.3g} ({msg.strip()})")
    h = 1e-6 * scale
    J = np.column_stack([(_g(Phi, w, C + h * e) - _g(Phi, w, C - h * e)) / (2 * h) for e in np.eye(2)])
    if abs(np.linalg.det(J)) < 1e-10 * max(1.0, float(np.max(np.abs(J)))) ** 2:
        raise ModelError("the Jacobian of the periodicity conditions is singular at the root (5.288)")
    return ForcedPeriodicSolution(C=(float(C[0]), float(C[1])), omega=w, jacobian=J)
