"""Speed of a machine with a heavy flywheel as a series in ``1/M`` (Bulgakov (1954), §5.24).

Model (5.293)–(5.296): ``(M + a(q)) r' + a'(q) r**2 / 2 = T(q) + D(r) - E`` with ``r = q'``, ``T = F - G`` the excess
driving force along the crank-pin path (zero mean over the period), ``a(q)`` the zero-mean variable part of the
reduced mass and ``D(r_m) = E`` fixing the mean speed (5.306).  With ``q = sigma + psi`` and
``r = r_m + r1/M + O(1/M**2)`` the first correction is (5.303), (5.307)–(5.309)

    r1(sigma) = -(1/r_m) [V(sigma) + b1] - (r_m / 2) a(sigma),    V = -Integral(T),   b1 = -mean(V),

so the cyclic irregularity is ``delta = (max r1 - min r1) / (M r_m) + O(1/M**2)``; solving for ``M`` gives
Radinger's formula (5.319).

Second approximation (the ``1/M**2`` step (5.312)–(5.313)), written with the position ``q`` as the independent
variable, ``r(q) = r_m + r1(q)/M + r2(q)/M**2 + O(1/M**3)``: collecting ``1/M**2`` in ``(M + a) r dr/dq + a' r**2/2 =
M [T + D(r) - E] / M`` gives ``r_m r2' = D' r1 - (r1**2/2 + r_m a r1)'``, periodic only if ``mean(r1) = 0`` (which
fixes ``b1`` as (5.309)), so

    r2 = [D' R1 - r1**2/2 - r_m a r1] / r_m + b2,        R1' = r1,

with ``D' = D'(r_m)``; the ``1/M**3`` periodicity condition ``mean(D' r2 + D'' r1**2/2) = 0`` fixes ``b2``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from ...numeric import compile

__all__ = ["FlywheelSpeedSeries", "flywheel_speed_series"]


@dataclass(frozen=True)
class FlywheelSpeedSeries(SymPyPrintable):
    """First-order speed fluctuation ``r1(sigma)`` of a machine with a heavy flywheel (Bulgakov (1954), §5.24).

    Attributes
    ----------
    sigma : ndarray
        Grid of the path coordinate over one period.
    r1 : ndarray
        ``r1(sigma)`` (zero mean): ``r = r_m + r1 / M + O(1/M**2)``.
    r_m : float
        Mean speed.
    r2 : ndarray or None
        Second term ``r2(q)`` on the same grid (position ``q`` = :attr:`sigma`), when the drive's slope ``D'(r_m)``
        was given: ``r(q) = r_m + r1(q)/M + r2(q)/M**2 + O(1/M**3)``.
    """

    sigma: np.ndarray
    r1: np.ndarray
    r_m: float
    r2: np.ndarray | None = None

    def __repr__(self) -> str:
        second = "" if self.r2 is None else f", swing of r2 = {float(np.ptp(self.r2)):.6g}"
        return f"FlywheelSpeedSeries(r_m={self.r_m:.6g}, swing of r1 = {float(np.ptp(self.r1)):.6g}{second})"

    def _terms(self, M: float, order: int) -> np.ndarray:
        from ..._validate import check_int, check_positive

        m = check_positive("M", M)
        k = check_int("order", order, minimum=1, maximum=2)
        if k == 2 and self.r2 is None:
            raise ParameterError("the second term needs drive_slope= (D'(r_m)) in flywheel_speed_series")
        out = self.r_m + self.r1 / m
        return out + self.r2 / m**2 if k == 2 else out

    def speed(self, M: float, order: int = 1) -> np.ndarray:
        """``r_m + r1 / M`` (``order=1``) or ``r_m + r1 / M + r2 / M**2`` (``order=2``) on :attr:`sigma`.

        Parameters
        ----------
        M : float
            Constant part of the reduced mass (flywheel included), the large parameter of the series; a positive
            number.
        order : int, optional
            Highest power of ``1/M`` kept, 1 or 2 (default 1; 2 needs ``r2``, i.e. ``drive_slope=`` when the series
            was built).
        """
        return self._terms(M, order)

    def irregularity(self, M: float, order: int = 1) -> float:
        """Cyclic irregularity ``(r_max - r_min) / r_m`` from the series truncated at ``1/M**order``.

        Parameters
        ----------
        M : float
            Constant part of the reduced mass (flywheel included), the large parameter of the series; a positive
            number.
        order : int, optional
            Highest power of ``1/M`` kept, 1 or 2 (default 1; 2 needs ``r2``, i.e. ``drive_slope=`` when the series
            was built).
        """
        if not M > 0:
            raise ParameterError(f"M must be positive, got {M}")
        if order == 1:
            return float(np.ptp(self.r1)) / (float(M) * self.r_m)
        return float(np.ptp(self._terms(M, order))) / self.r_m

    def mass_for(self, delta: float) -> float:
        """Total reduced mass for an irregularity ``delta`` (first order; Radinger's formula (5.319)).

        Parameters
        ----------
        delta : float
            The required coefficient of cyclic irregularity ``(r_max - r_min)/r_m``; a number in ``(0, 1)``.
        """
        if not 0 < delta < 1:
            raise ParameterError(f"delta must lie in (0, 1), got {delta}")
        return float(np.ptp(self.r1)) / (delta * self.r_m)


@validated
def flywheel_speed_series(
    torque: Any,
    s: sp.Symbol,
    r_m: float,
    *,
    mass_variation: Any = 0,
    period: float = 2 * math.pi,
    samples: int = 2048,
    drive_slope: float | None = None,
    drive_curvature: float = 0.0,
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
    drive_slope, drive_curvature : float, optional
        ``D'(r_m)`` (nonzero; negative for a governed engine) and ``D''(r_m)`` of the speed-dependent driving
        force ``D(r)``.  With ``drive_slope`` the second term ``r2`` is computed (5.312)–(5.313).

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
    r2 = None
    if drive_slope is not None:
        from ..._validate import check_finite

        d1 = check_finite("drive_slope", drive_slope)
        d2 = check_finite("drive_curvature", drive_curvature)
        if d1 == 0:
            raise ModelError("drive_slope D'(r_m) = 0: the mean speed is not fixed by D(r_m) = E (no second term)")
        R1 = np.fft.irfft(np.where(k > 0, np.fft.rfft(r1) / np.where(k > 0, 1j * k, 1.0), 0.0), n=samples)
        r2 = (d1 * R1 - 0.5 * r1**2 - r_m * A * r1) / r_m
        r2 = r2 - r2.mean() - d2 * float(np.mean(r1**2)) / (2 * d1)  # mean(D' r2 + D'' r1^2 / 2) = 0
    return FlywheelSpeedSeries(sigma=sig, r1=r1, r_m=float(r_m), r2=r2)
