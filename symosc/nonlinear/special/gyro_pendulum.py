"""Gyroscopic pendulum: precession and nutation frequencies and their decay (Bulgakov (1954), §12.14).

Equations (12.249) with ``kappa = H/A``, ``lambda = H/B``, ``n**2 = kappa*lambda``, ``p**2 = L/A``,
``sigma**2 = N/B``:

    y1'' + p**2 y1 + kappa y2' = -mu (p_v y1' + h1 sign y1'),
    y2'' - lambda y1' + sigma**2 y2 = -mu (q_v y2' + h2 sign y2').

The torus averages of the dry-friction terms are in :func:`dry_friction_torus_average` and
:func:`dry_friction_ratio` (Table 15).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError

__all__ = ["GyroPendulumModes", "gyro_pendulum_modes"]


def _positive(name: str, v: float, allow_zero: bool = False) -> float:
    try:
        x = float(v)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a real number, got {v!r}") from exc
    if not math.isfinite(x) or x < 0 or (x == 0 and not allow_zero):
        raise ParameterError(f"{name} must be {'non-negative' if allow_zero else 'positive'} and finite, got {v!r}")
    return x


@dataclass(frozen=True)
class GyroPendulumModes(SymPyPrintable):
    """Precession (``omega1``) and nutation (``omega2``) of the gyroscopic pendulum and their viscous decay rates.

    Attributes
    ----------
    omega1, omega2 : float
        ``omega_{1,2}**2 = (p**2 + sigma**2 + n**2 -+ f**2) / 2`` (Bulgakov (1954), §12.14, eq. (12.252)),
        ``f**2 = sqrt((p**2 + sigma**2 + n**2)**2 - 4 p**2 sigma**2)`` (12.253).
    c1, c2 : float
        Decay rates per unit ``mu`` of the precession and nutation amplitudes under viscous resistance,
        ``A_k = A_k0 exp(-mu c_k t)`` (12.288).
    nutation_decays_faster : bool
        ``c2 > c1``, i.e. ``n**2 > (p**2 - sigma**2)(q_v - p_v)/(p_v + q_v)`` (12.289).
    dry_friction_nutation_first : bool or None
        Symmetric device (``p = sigma``): under dry friction the nutation dies first when ``n > p/sqrt(2)``
        (12.300); ``None`` when ``p != sigma`` (the book treats the symmetric case only).
    """

    omega1: float
    omega2: float
    c1: float
    c2: float
    nutation_decays_faster: bool
    dry_friction_nutation_first: bool | None

    def __repr__(self) -> str:
        return (
            f"GyroPendulumModes(omega1={self.omega1:.6g}, omega2={self.omega2:.6g}, c1={self.c1:.6g}, c2={self.c2:.6g})"
        )


@validated
def gyro_pendulum_modes(p: float, sigma: float, n: float, *, p_v: float = 0.0, q_v: float = 0.0) -> GyroPendulumModes:
    """Frequencies and viscous decay rates of the gyroscopic pendulum (Bulgakov (1954), §12.14).

    Parameters
    ----------
    p, sigma : float
        Partial frequencies ``sqrt(L/A)`` of the pendulum and ``sqrt(N/B)`` of the gyroscope casing.
    n : float
        Gyroscopic coupling ``H / sqrt(A B)``.
    p_v, q_v : float, optional
        Viscous coefficients (per unit ``mu``) on ``y1'`` and ``y2'``.

    Returns
    -------
    GyroPendulumModes

    See Also
    --------
    symosc.nonlinear.dry_friction_ratio : Table 15 of §12.14.
    symosc.mechanics.LinearModel.complex_modes : roots of any gyroscopic linear model.

    Notes
    -----
    The decay rates follow from the shortened equations (12.287)-(12.288):
    ``c1 = [(sigma**2 - p**2)(p_v - q_v) + (f**2 - n**2)(p_v + q_v)] / (4 f**2)`` and
    ``c2 = [(p**2 - sigma**2)(p_v - q_v) + (f**2 + n**2)(p_v + q_v)] / (4 f**2)``.

    Examples
    --------
    Symmetric device: ``omega_{1,2} = sqrt(p**2 + n**2/4) -+ n/2``.

    >>> res = gyro_pendulum_modes(1.0, 1.0, 1.5, p_v=0.1, q_v=0.1)
    >>> round(res.omega1, 12), round(res.omega2, 12)
    (0.5, 2.0)
    >>> res.nutation_decays_faster, res.dry_friction_nutation_first
    (True, True)
    """
    p = _positive("p", p)
    sigma = _positive("sigma", sigma)
    n = _positive("n", n, allow_zero=True)
    p_v = _positive("p_v", p_v, allow_zero=True)
    q_v = _positive("q_v", q_v, allow_zero=True)
    s = p * p + sigma * sigma + n * n
    f2 = math.sqrt(n**4 + 2 * (p * p + sigma * sigma) * n * n + (p * p - sigma * sigma) ** 2)  # (12.253)
    if f2 == 0:
        raise ParameterError("p = sigma with n = 0 gives a double frequency; the normal coordinates are not unique")
    w1sq = 2 * p * p * sigma * sigma / (s + f2)  # = (s - f2)/2 without cancellation (Vieta: w1^2 w2^2 = p^2 sigma^2)
    w2sq = (s + f2) / 2
    dv, sv = p_v - q_v, p_v + q_v
    c1 = ((sigma * sigma - p * p) * dv + (f2 - n * n) * sv) / (4 * f2)
    c2 = ((p * p - sigma * sigma) * dv + (f2 + n * n) * sv) / (4 * f2)
    lhs, rhs = n * n * sv, (p * p - sigma * sigma) * (q_v - p_v)
    sym = None if not math.isclose(p, sigma, rel_tol=1e-12) else bool(n > p / math.sqrt(2))
    return GyroPendulumModes(
        omega1=math.sqrt(w1sq),
        omega2=math.sqrt(w2sq),
        c1=c1,
        c2=c2,
        nutation_decays_faster=bool(lhs > rhs),
        dry_friction_nutation_first=sym,
    )
