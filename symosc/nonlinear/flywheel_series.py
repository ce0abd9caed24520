"""Speed of a machine with a heavy flywheel as a series in ``1/M`` (Bulgakov (1954), §5.24).

Model (5.293)–(5.296): ``(M + a(q)) r' + a'(q) r**2 / 2 = T(q) + D(r) - E`` with ``r = q'``, ``T = F - G`` the excess
driving force along the crank-pin path (zero mean over the period), ``a(q)`` the zero-mean variable part of the
reduced mass and ``D(r_m) = E`` fixing the mean speed (5.306).  With ``q = sigma + psi`` and
``r = r_m + r1/M + O(1/M**2)`` the first correction is (5.303), (5.307)–(5.309)

    r1(sigma) = -(1/r_m) [V(sigma) + b1] - (r_m / 2) a(sigma),    V = -Integral(T),   b1 = -mean(V),

so the cyclic irregularity is ``delta = (max r1 - min r1) / (M r_m) + O(1/M**2)``; solving for ``M`` gives
Radinger's formula (5.319).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..errors import ModelError, ParameterError
from ..numeric import compile

__all__ = ["FlywheelSpeedSeries", "flywheel_speed_series"]


@dataclass(frozen=True)
class FlywheelSpeedSeries:
    """First-order speed fluctuation ``r1(sigma)`` of a machine with a heavy flywheel (Bulgakov (1954), §5.24).

    Attributes
    ----------
    sigma : ndarray
        Grid of the path coordinate over one period.
    r1 : ndarray
        ``r1(sigma)`` (zero mean): ``r = r_m + r1 / M + O(1/M**2)``.
    r_m : float
        Mean speed.
    """

    sigma: np.ndarray
    r1: np.ndarray
    r_m: float

    def __repr__(self) -> str:
        return f"FlywheelSpeedSeries(r_m={self.r_m:.6g}, swing of r1 = {float(np.ptp(self.r1)):.6g})"

    def speed(self, M: float) -> np.ndarray:
        """``r_m + r1(sigma) / M`` on :attr:`sigma`."""
        return self.r_m + self.r1 / float(M)

    def irregularity(self, M: float) -> float:
        """Cyclic irregularity ``(r_max - r_min) / r_m`` to first order in ``1/M``."""
        if not M > 0:
            raise ParameterError(f"M must be positive, got {M}")
        return float(np.ptp(self.r1)) / (float(M) * self.r_m)

    def mass_for(self, delta: float) -> float:
        """Total reduced mass for an irregularity ``delta`` (first order; Radinger's formula (5.319))."""
        if not 0 < delta < 1:
            raise ParameterError(f"delta must lie in (0, 1), got {delta}")
        return float(np.ptp(self.r1)) / (delta * self.r_m)


def flywheel_speed_series(
    torque: Any, s: sp.Symbol, r_m: float, *, mass_variation: Any = 0, period: float = 2 * math.pi, samples: int = 2048
) -> FlywheelSpeedSeries:
    """First term of the ``1/M`` series for the speed of a machine with a flywheel (Bulgakov (1954), §5.24).

    Parameters
    ----------
    torque : expression in ``s``
        Excess driving force ``T(s) = F(s) - G(s)`` along the path (zero mean over a period).
    s : Symbol
        The path coordinate.
    r_m : float
        Mean speed (``D(r_m) = E``, eq. (5.306)).
    mass_variation : expression in ``s``
        Zero-mean variable part ``a(s)`` of the reduced mass.
    period : float
        Period of ``T`` and ``a`` in ``s``.
    samples : int
        Grid points over one period (spectral quadrature of the periodic integrals).

    Returns
    -------
    FlywheelSpeedSeries

    Raises
    ------
    ModelError
        Nonzero mean of ``T`` (no steady running) or of ``a``.

    See Also
    --------
    symosc.nonlinear.radinger_flywheel : the flywheel mass from the energy swing (leading term of (5.317)).

    Examples
    --------
    ``T = cos s``, ``a = 0``: ``r1 = sin(s) / r_m``, so ``delta = 2 / (M r_m**2)``.

    >>> import sympy as sp
    >>> s = sp.Symbol("s")
    >>> ser = flywheel_speed_series(sp.cos(s), s, 2.0)
    >>> round(ser.irregularity(100.0), 10), round(ser.mass_for(0.005), 6)
    (0.005, 100.0)
    """
    torque, av = sp.sympify(torque), sp.sympify(mass_variation)
    for e, n in ((torque, "torque"), (av, "mass_variation")):
        if e.free_symbols - {s}:
            raise ParameterError(
                f"{n}: substitute values for " + ", ".join(sorted(x.name for x in e.free_symbols - {s}))
            )
    if not (math.isfinite(r_m) and r_m > 0) or not (math.isfinite(period) and period > 0):
        raise ParameterError(f"r_m and period must be positive, got r_m={r_m}, period={period}")
    if not isinstance(samples, int) or samples < 64:
        raise ParameterError(f"samples must be an integer >= 64, got {samples!r}")
    sig = period * np.arange(samples) / samples
    T = np.broadcast_to(np.asarray(compile(torque, [s], check=False).raw(sig), dtype=float), sig.shape)
    A = np.broadcast_to(np.asarray(compile(av, [s], check=False).raw(sig), dtype=float), sig.shape)
    scale = float(np.max(np.abs(T))) or 1.0
    if abs(T.mean()) > 1e-9 * scale:
        raise ModelError(f"the excess force must have zero mean over a period (steady running); mean {T.mean():.3g}")
    if abs(A.mean()) > 1e-9 * (float(np.max(np.abs(A))) or 1.0):
        raise ModelError("mass_variation must have zero mean (put its mean into M)")
    # W(sigma) = Integral(T, 0, sigma) spectrally: T has zero mean, so W is periodic
    k = np.fft.rfftfreq(samples, d=period / samples) * 2 * np.pi
    That = np.fft.rfft(T)
    What = np.zeros_like(That)
    What[1:] = That[1:] / (1j * k[1:])
    W = np.fft.irfft(What, n=samples)
    r1 = (W - 0.5 * r_m**2 * A) / r_m
    r1 = r1 - r1.mean()
    return FlywheelSpeedSeries(sigma=sig, r1=r1, r_m=float(r_m))
