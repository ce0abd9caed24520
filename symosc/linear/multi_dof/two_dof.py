"""Two coupled oscillators: coupling coefficients, frequencies, modes, beats and tuning curves (Bulgakov (1954),
§8.13–8.15).

``2T = L y1'² + 2M y1'y2' + N y2'²``, ``2V = A y1² + 2B y1y2 + C y2²`` (8.66); partial frequencies
``ω_a² = A/L``, ``ω_b² = C/N``, inductive (inertial) and capacitive (elastic) coupling ``k = M/√(LN)``,
``l = -B/√(AC)`` (8.74)–(8.75); normal frequencies (8.79); beats after release from rest (8.93)–(8.96); tuning curves
``z = ω/ω_a`` against ``x = ω_b/ω_a`` (8.83)–(8.86).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError

__all__ = ["TuningCurves", "TwoDOFBeats", "TwoDOFSystem", "tuning_curves", "two_dof_beats", "two_dof_system"]


def _frequencies(wa: float, wb: float, k: float, l: float) -> tuple[float, float]:
    """(8.79): roots of ``(1-k²)ω⁴ - (ωa² + ωb² + 2klωaωb)ω² + (1-l²)ωa²ωb² = 0``."""
    s = wa**2 + wb**2 + 2 * k * l * wa * wb
    # discriminant as the sum of squares of (8.79), never negative in floating point
    disc = (wa - wb) ** 2 * ((wa - wb) ** 2 + 4 * (1 + k * l) * wa * wb) + 4 * (k + l) ** 2 * wa**2 * wb**2
    r = np.sqrt(max(disc, 0.0))
    w2_hi = (s + r) / (2 * (1 - k**2))
    w2_lo = (1 - l**2) * wa**2 * wb**2 / ((1 - k**2) * w2_hi)  # product of the roots: no cancellation
    return float(np.sqrt(w2_lo)), float(np.sqrt(w2_hi))


@dataclass(frozen=True)
class TwoDOFSystem(SymPyPrintable):
    """Result of :func:`two_dof_system`.

    Attributes
    ----------
    L, M, N : float
        Inertia coefficients ``2T = L y1'² + 2M y1'y2' + N y2'²``.
    A, B, C : float
        Stiffness coefficients ``2V = A y1² + 2B y1y2 + C y2²``.
    omega_a, omega_b : float
        Partial frequencies ``√(A/L)``, ``√(C/N)``.
    k, l : float
        Inductive and capacitive coupling coefficients (8.74)–(8.75).
    frequencies : (float, float)
        ``ω1 ≤ ω2`` (8.79).
    modes : ndarray, shape (2, 2)
        Columns ``(1, u2/u1)`` of the two normal modes (§8.14); ``(0, 1)`` when a mode leaves ``y1`` at rest.
    """

    L: float
    M: float
    N: float
    A: float
    B: float
    C: float
    omega_a: float
    omega_b: float
    k: float
    l: float
    frequencies: tuple[float, float]
    modes: np.ndarray

    def __repr__(self) -> str:
        w1, w2 = self.frequencies
        return (
            f"TwoDOFSystem(ωa = {self.omega_a:.6g}, ωb = {self.omega_b:.6g}, k = {self.k:.6g}, l = {self.l:.6g}; "
            f"ω1 = {w1:.6g}, ω2 = {w2:.6g})"
        )

    def _repr_latex_(self) -> str:
        w1, w2 = self.frequencies
        return (
            rf"$\omega_a = {self.omega_a:.6g},\ \omega_b = {self.omega_b:.6g},\ k = {self.k:.6g},\ "
            rf"l = {self.l:.6g};\ \omega_1 = {w1:.6g},\ \omega_2 = {w2:.6g}$"
        )


@validated
def two_dof_system(L: float, M: float, N: float, A: float, B: float, C: float) -> TwoDOFSystem:
    """Partial frequencies, coupling coefficients, normal frequencies and modes of (8.68) (Bulgakov (1954), §8.13–8.14).

    Parameters
    ----------
    L, M, N : float
        Inertia coefficients ``2T = L y1'² + 2M y1'y2' + N y2'²`` (positive definite).
    A, B, C : float
        Stiffness coefficients ``2V = A y1² + 2B y1y2 + C y2²`` (positive definite).

    Examples
    --------
    >>> from symosc.linear import two_dof_system
    >>> s = two_dof_system(2, 0.3, 1, 5, -0.8, 3)
    >>> [round(w, 8) for w in s.frequencies], [round(float(r), 8) for r in s.modes[1]]
    ([1.33234666, 2.05799018], [1.08792237, -1.67615766])

    See Also
    --------
    two_dof_beats, tuning_curves, conservative_modes
    """
    try:
        L, M, N, A, B, C = (float(v) for v in (L, M, N, A, B, C))
    except (TypeError, ValueError) as exc:
        raise ParameterError("L, M, N, A, B, C must be real numbers") from exc
    if not np.all(np.isfinite([L, M, N, A, B, C])):
        raise ParameterError("L, M, N, A, B, C must be finite")
    if L <= 0 or N <= 0 or L * N - M * M <= 0:
        raise ModelError("the kinetic energy L y1'² + 2M y1'y2' + N y2'² must be positive definite (8.67)")
    if A <= 0 or C <= 0 or A * C - B * B <= 0:
        raise ModelError("the potential energy A y1² + 2B y1y2 + C y2² must be positive definite (8.67)")
    wa, wb = np.sqrt(A / L), np.sqrt(C / N)
    k, l = M / np.sqrt(L * N), -B / np.sqrt(A * C)
    w = _frequencies(wa, wb, k, l)
    ka, kb = M / L, M / N
    la, lb = -B / (L * wa * wb), -B / (N * wa * wb)
    modes = np.eye(2)
    for h, wh in enumerate(w):
        # modal equations (§8.14): (ωa² - ωh²) u1 - (ka ωh² + la ωa ωb) u2 = 0,
        # -(kb ωh² + lb ωa ωb) u1 + (ωb² - ωh²) u2 = 0; the null vector of the better-scaled row
        r1 = np.array([wa**2 - wh**2, -(ka * wh**2 + la * wa * wb)])
        r2 = np.array([-(kb * wh**2 + lb * wa * wb), wb**2 - wh**2])
        r = r1 if np.abs(r1).max() >= np.abs(r2).max() else r2
        if np.abs(r).max() <= 1e-14 * max(wa, wb) ** 2:  # ω1 = ω2 (8.81): every column is a mode
            continue
        v = np.array([-r[1], r[0]])
        modes[:, h] = v / v[0] if abs(v[0]) > 1e-12 * np.abs(v).max() else v / v[1]
    return TwoDOFSystem(L, M, N, A, B, C, float(wa), float(wb), float(k), float(l), w, modes)


@dataclass(frozen=True)
class TwoDOFBeats(SymPyPrintable):
    """Result of :func:`two_dof_beats`: free motion from rest, ``y_j = a_j cos ω1t + b_j cos ω2t`` (8.92)–(8.93).

    Attributes
    ----------
    system : TwoDOFSystem
        The coupled system.
    y0 : (float, float)
        Initial displacements (zero initial velocities).
    a, b : ndarray, shape (2,)
        Modal amplitudes in each coordinate, ``a_j = v_j1 c1``, ``b_j = v_j2 c2``.
    carrier : float
        ``(ω1 + ω2)/2``.
    beat_period : float
        ``2π/(ω2 - ω1)`` (``inf`` when ``ω1 = ω2``).
    limits : ndarray, shape (2, 2)
        ``(min, max)`` of the envelope of each coordinate: ``||a_j| - |b_j||`` and ``|a_j| + |b_j|`` (8.96).
    """

    system: TwoDOFSystem
    y0: tuple[float, float]
    a: np.ndarray
    b: np.ndarray
    carrier: float
    beat_period: float
    limits: np.ndarray

    def displacement(self, t: Any) -> np.ndarray:
        """``y_j(t)``, shape ``(2, len(t))``.

        Parameters
        ----------
        t : float or array_like
            Time(s) since the release; real numbers.
        """
        t = np.atleast_1d(np.asarray(t, dtype=float))
        w1, w2 = self.system.frequencies
        return self.a[:, None] * np.cos(w1 * t) + self.b[:, None] * np.cos(w2 * t)

    def envelope(self, t: Any) -> np.ndarray:
        """``A_j(t) = √(a_j² + b_j² + 2 a_j b_j cos(ω2 - ω1)t)`` (8.94)–(8.95), shape ``(2, len(t))``.

        Parameters
        ----------
        t : float or array_like
            Time(s) since the release; real numbers.
        """
        t = np.atleast_1d(np.asarray(t, dtype=float))
        w1, w2 = self.system.frequencies
        a, b = self.a[:, None], self.b[:, None]
        return np.sqrt(np.maximum(a**2 + b**2 + 2 * a * b * np.cos((w2 - w1) * t), 0.0))

    def __repr__(self) -> str:
        return (
            f"TwoDOFBeats(carrier {self.carrier:.6g}, beat period {self.beat_period:.6g}, envelope limits "
            f"{np.round(self.limits, 6).tolist()})"
        )

    def plot(self, t: Any = None, *, ax=None):
        """Both coordinates with their envelopes; returns the Axes.

        Parameters
        ----------
        t : array_like, optional
            Times to plot at (real numbers); default 2000 points over two beat periods.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        period = self.beat_period if np.isfinite(self.beat_period) else 20 * np.pi / self.carrier
        t = np.linspace(0, 2 * period, 2000) if t is None else np.asarray(t, float)
        y, env = self.displacement(t), self.envelope(t)
        for j in range(2):
            (line,) = ax.plot(t, y[j], lw=0.8, label=f"y{j + 1}")
            ax.plot(t, env[j], "--", color=line.get_color(), lw=0.8, label=f"envelope of y{j + 1}")
            ax.plot(t, -env[j], "--", color=line.get_color(), lw=0.8)
        ax.set_xlabel("t")
        ax.legend()
        return ax


@validated
def two_dof_beats(system: TwoDOFSystem, y0: Any) -> TwoDOFBeats:
    """Beats after release from rest at ``y(0) = y0`` (Bulgakov (1954), §8.14, (8.92)–(8.96)).

    Parameters
    ----------
    system : TwoDOFSystem
        The coupled system; must be the result of :func:`two_dof_system`.
    y0 : sequence of 2 floats
        Initial displacements ``(y1(0), y2(0))``, two finite numbers (the velocities start at zero).

    Returns
    -------
    TwoDOFBeats

    Examples
    --------
    >>> from symosc.linear import two_dof_beats, two_dof_system
    >>> s = two_dof_system(1, 0, 1, 1.1, -0.1, 1.1)              # two equal pendulums, weak spring
    >>> b = two_dof_beats(s, [1.0, 0.0])
    >>> [round(float(v), 12) for v in b.limits[1]]              # tuned: the energy passes over completely
    [0.0, 1.0]

    See Also
    --------
    two_dof_system, tuning_curves
    """
    if not isinstance(system, TwoDOFSystem):
        raise ParameterError("system must be the result of two_dof_system(L, M, N, A, B, C)")
    y = np.asarray(y0, dtype=float)
    if y.shape != (2,) or not np.all(np.isfinite(y)):
        raise ParameterError("y0 must be two finite initial displacements (y1(0), y2(0))")
    V = system.modes
    c = np.linalg.solve(V, y)  # (8.93)
    a, b = V[:, 0] * c[0], V[:, 1] * c[1]
    w1, w2 = system.frequencies
    lim = np.column_stack([np.abs(np.abs(a) - np.abs(b)), np.abs(a) + np.abs(b)])
    period = 2 * np.pi / (w2 - w1) if w2 > w1 else np.inf
    return TwoDOFBeats(system, (float(y[0]), float(y[1])), a, b, (w1 + w2) / 2, period, lim)


@dataclass(frozen=True)
class TuningCurves(SymPyPrintable):
    """Result of :func:`tuning_curves`: ``z_i = ω_i/ω_a`` against the tuning ``x = ω_b/ω_a`` (8.83)–(8.84).

    Attributes
    ----------
    k, l : float
        Inductive and capacitive coupling coefficients.
    x : ndarray
        Tuning ``ω_b/ω_a``.
    z1, z2 : ndarray
        Normal frequencies ``ω_1/ω_a <= ω_2/ω_a`` at each ``x``.
    """

    k: float
    l: float
    x: np.ndarray
    z1: np.ndarray
    z2: np.ndarray

    def __repr__(self) -> str:
        return f"TuningCurves(k = {self.k:.6g}, l = {self.l:.6g}, {self.x.size} points)"

    def plot(self, *, ax=None):
        """``z1(x)``, ``z2(x)`` and the uncoupled lines ``z = 1``, ``z = x``; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        ax.plot(self.x, self.z1, label="z1 = ω1/ωa")
        ax.plot(self.x, self.z2, label="z2 = ω2/ωa")
        ax.plot(self.x, np.ones_like(self.x), "k:", lw=0.7, label="uncoupled: z = 1, z = x")
        ax.plot(self.x, self.x, "k:", lw=0.7)
        ax.set_xlabel("x = ωb/ωa")
        ax.set_ylabel("z")
        ax.set_title(f"k = {self.k:.3g}, l = {self.l:.3g} (Bulgakov (1954), §8.13)")
        ax.legend()
        return ax


@validated
def tuning_curves(k: float, l: float, x: Any = None) -> TuningCurves:
    """Resonance (tuning) curves of two coupled oscillators (Bulgakov (1954), §8.13, (8.84)–(8.86)).

    ``z_{1,2}² = [1 + x² + 2klx ∓ √((1 + x² + 2klx)² - 4(1-k²)(1-l²)x²)]/(2(1-k²))``.

    Parameters
    ----------
    k : float
        Inductive (inertial) coupling coefficient ``M/√(LN)``; must satisfy ``k² < 1``.
    l : float
        Capacitive (elastic) coupling coefficient ``-B/√(AC)``; must satisfy ``l² < 1``.
    x : array_like, optional
        Tunings ``x = ω_b/ω_a``: finite non-negative numbers (default 301 points on ``[0, 3]``).

    Returns
    -------
    TuningCurves

    Examples
    --------
    >>> from symosc.linear import tuning_curves
    >>> c = tuning_curves(0.0, 0.2, [1.0])               # tuned, elastic coupling: z² = 1 ∓ l
    >>> round(float(c.z1[0]) ** 2, 12), round(float(c.z2[0]) ** 2, 12)
    (0.8, 1.2)

    See Also
    --------
    two_dof_system
    """
    k, l = float(k), float(l)
    if not (k * k < 1 and l * l < 1):
        raise ParameterError(f"the coupling coefficients need k² < 1 and l² < 1 (8.75), got k = {k}, l = {l}")
    xs = np.linspace(0.0, 3.0, 301) if x is None else np.atleast_1d(np.asarray(x, dtype=float))
    if np.any(xs < 0) or not np.all(np.isfinite(xs)):
        raise ParameterError("x = ωb/ωa must be finite and non-negative")
    z = np.array([_frequencies(1.0, xi, k, l) for xi in xs]).reshape(-1, 2)
    return TuningCurves(k, l, xs, z[:, 0], z[:, 1])
