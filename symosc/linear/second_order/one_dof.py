"""One degree of freedom ``(k0 D² + k1 D + k2) y = x(t)`` (Bulgakov (1954), §4.5–4.11).

* :func:`linear_filter` — the free motion ``M(t)``, the after-effect (impulse) function ``N(t)`` and the transition
  (step) function ``A(t)`` of (4.62)–(4.72), evaluated by one formula that is continuous through critical damping.
* :func:`stability_coefficients` — α (Tsypkin–Bromberg), β (Raushenbakh), γ1 (Moiseev–Fel'dbaum), γ0 (servo) and
  ϑ (harmonic) of §4.10–4.11.
* :func:`classify_equilibrium` — the singular point of the phase plane (§4.2, §4.9).
* :func:`periodic_forced_response` — the τ-periodic response of an undamped oscillator (§4.11c).
* :func:`volterra_march` — the integral-equation form of a perturbed linear system (§4.4).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError

__all__ = [
    "LinearFilter",
    "StabilityCoefficients",
    "classify_equilibrium",
    "linear_filter",
    "periodic_forced_response",
    "stability_coefficients",
    "volterra_march",
]


def _check(k0, k1, k2):
    try:
        k0, k1, k2 = float(k0), float(k1), float(k2)
    except (TypeError, ValueError) as exc:
        raise ParameterError("k0, k1, k2 must be real numbers") from exc
    if not all(np.isfinite([k0, k1, k2])):
        raise ParameterError("k0, k1, k2 must be finite")
    if k0 <= 0:
        raise ParameterError(f"k0 (the mass) must be positive, got {k0}")
    return k0, k1, k2


def _cs(d: float, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``C = cos(√d t)`` and ``S = sin(√d t)/√d`` for any real ``d`` (cosh/sinh for d < 0), series near d t² = 0."""
    t = np.asarray(t, dtype=float)
    z = d * t**2
    C = np.empty_like(t)
    S = np.empty_like(t)
    small = np.abs(z) < 1e-3
    # Taylor series in z: C = Σ (-z)^n/(2n)!, S = t Σ (-z)^n/(2n+1)!  (exact to rounding for |z| < 1e-3)
    zs = z[small]
    C[small] = 1 - zs / 2 + zs**2 / 24 - zs**3 / 720 + zs**4 / 40320
    S[small] = t[small] * (1 - zs / 6 + zs**2 / 120 - zs**3 / 5040 + zs**4 / 362880)
    big = ~small
    if d > 0:
        w = np.sqrt(d)
        C[big] = np.cos(w * t[big])
        S[big] = np.sin(w * t[big]) / w
    elif d < 0:
        w = np.sqrt(-d)
        C[big] = np.cosh(w * t[big])
        S[big] = np.sinh(w * t[big]) / w
    return C, S


@dataclass(frozen=True)
class LinearFilter(SymPyPrintable):
    """Result of :func:`linear_filter`; call ``M(t)``, ``N(t)``, ``A(t)`` and ``response(t, x)``.

    Attributes
    ----------
    k0, k1, k2 : float
        Coefficients of ``k0 D² + k1 D + k2`` (``k0 > 0``: the mass).
    y0, v0 : float
        Initial displacement and velocity for ``M``.
    """

    k0: float
    k1: float
    k2: float
    y0: float = 0.0
    v0: float = 0.0

    @property
    def eps(self) -> float:
        return self.k1 / (2 * self.k0)

    @property
    def d(self) -> float:
        """``ω² = k2/k0 - ε²`` (negative when the roots are real)."""
        return self.k2 / self.k0 - self.eps**2

    def M(self, t: Any) -> np.ndarray:
        """Free motion from ``y0, v0`` (4.62), (4.66), (4.70).

        Parameters
        ----------
        t : float or array_like
            Time(s) since the start; real numbers, any shape.
        """
        C, S = _cs(self.d, t)
        return np.exp(-self.eps * np.asarray(t, float)) * (self.y0 * C + (self.v0 + self.eps * self.y0) * S)

    def N(self, t: Any) -> np.ndarray:
        """After-effect (unit impulse) function (4.63), (4.67), (4.71).

        Parameters
        ----------
        t : float or array_like
            Time(s) since the start; real numbers, any shape.
        """
        _, S = _cs(self.d, t)
        return np.exp(-self.eps * np.asarray(t, float)) * S / self.k0

    def A(self, t: Any) -> np.ndarray:
        """Transition (unit step) function (4.64), (4.69), (4.72); ``A(0) = 0``, ``A' = N``.

        Needs ``k2 != 0``.

        Parameters
        ----------
        t : float or array_like
            Time(s) since the start; real numbers, any shape.
        """
        if self.k2 == 0:
            raise ParameterError("A(t) needs k2 != 0 (a zero root makes the step response grow)")
        C, S = _cs(self.d, t)
        return (1 - np.exp(-self.eps * np.asarray(t, float)) * (C + self.eps * S)) / self.k2

    def plot(self, t: Any = None, *, ax=None):
        """``M``, ``N`` and ``A`` against ``t``; returns the Axes.

        Parameters
        ----------
        t : array_like, optional
            Times to plot at (real numbers); default 500 points on ``[0, 10/max(ε, 0.1)]``, ``ε = k1/(2 k0)``.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        t = np.linspace(0, 10 / max(self.eps, 0.1), 500) if t is None else np.asarray(t, float)
        for name in ("M", "N", "A"):
            ax.plot(t, getattr(self, name)(t), label=f"{name}(t)")
        ax.set_xlabel("t")
        ax.legend()
        return ax


@validated
def linear_filter(k0: float, k1: float, k2: float, *, y0: float = 0.0, v0: float = 0.0) -> LinearFilter:
    """The oscillator ``(k0 D² + k1 D + k2) y = x`` as a linear filter (Bulgakov (1954), §4.8).

    ``y(t) = M(t) + ∫₀ᵗ N(t - u) x(u) du`` (4.55).  The three branches of the book (real, complex, double roots) are
    one formula in ``C = cos(ωt)``, ``S = sin(ωt)/ω`` continued analytically through ``ω² = 0`` (series there), so
    values stay accurate arbitrarily close to critical damping.

    Parameters
    ----------
    k0 : float
        Coefficient of ``D²`` (the mass); must be positive and finite.
    k1 : float
        Coefficient of ``D`` (the damping); a finite real number (negative: growing oscillations).
    k2 : float
        Coefficient of ``y`` (the stiffness); a finite real number (``A(t)`` needs ``k2 != 0``).
    y0 : float, optional
        Initial displacement for the free motion ``M(t)`` (default 0).
    v0 : float, optional
        Initial velocity for the free motion ``M(t)`` (default 0).

    Returns
    -------
    LinearFilter

    Examples
    --------
    >>> from symosc.linear import linear_filter
    >>> f = linear_filter(1, 2, 1)                 # critical damping: N = t e^{-t}
    >>> round(float(f.N(1.0)), 12) == round(float(1.0 * __import__("math").exp(-1)), 12)
    True

    See Also
    --------
    stability_coefficients, worst_case_gain
    """
    k0, k1, k2 = _check(k0, k1, k2)
    return LinearFilter(k0, k1, k2, float(y0), float(v0))


@dataclass(frozen=True)
class StabilityCoefficients(SymPyPrintable):
    """Result of :func:`stability_coefficients` (Bulgakov (1954), §4.10–4.11).

    Attributes
    ----------
    alpha : float
        Degree of stability, the smallest ``|Re λ|`` (4.75)–(4.76).
    beta : float
        ``1/∫|N| dt`` (Raushenbakh) (4.82); also the accumulation coefficient of §4.11a.
    gamma1 : float
        ``1/∫(θ1 y² + θ2 y'²) dt`` after a unit impulse (4.86).
    gamma0 : float
        The same after a unit jump of the servo error (4.88).
    vartheta : float
        ``min_ν |k2 - k0 ν² + i k1 ν|`` (harmonic disturbances, §4.11b).
    """

    alpha: float
    beta: float
    gamma1: float
    gamma0: float
    vartheta: float


@validated
def stability_coefficients(k0: float, k1: float, k2: float, *, theta: tuple = (1.0, 0.0)) -> StabilityCoefficients:
    """Quality (stability) coefficients α, β, γ1, γ0, ϑ of ``k0 D² + k1 D + k2`` (Bulgakov (1954), §4.10–4.11).

    Parameters
    ----------
    k0, k1, k2 : float
        Positive coefficients (an asymptotically stable oscillator).
    theta : (float, float)
        Weights ``θ1, θ2`` of ``y²`` and ``y'²`` in the quadratic criteria.

    Examples
    --------
    >>> from symosc.linear import stability_coefficients
    >>> c = stability_coefficients(1.3, 0.7, 2.1, theta=(0.8, 0.5))
    >>> round(1 / c.beta, 6), round(1 / c.gamma1, 6), round(1 / c.gamma0, 6)
    (1.452266, 0.546834, 1.62619)

    See Also
    --------
    linear_filter, stability_degree
    """
    k0, k1, k2 = _check(k0, k1, k2)
    if k1 <= 0 or k2 <= 0:
        raise ParameterError("the coefficients need k1 > 0 and k2 > 0 (asymptotic stability, (4.73))")
    t1, t2 = (float(v) for v in theta)
    disc = k1**2 - 4 * k0 * k2
    alpha = (k1 - np.sqrt(disc)) / (2 * k0) if disc > 0 else k1 / (2 * k0)
    beta = k2 if disc >= 0 else k2 * np.tanh(np.pi * k1 / (2 * np.sqrt(-disc)))
    gamma1 = 2 * k0 * k1 * k2 / (t1 * k0 + t2 * k2)
    gamma0 = 2 * k1 * k2 / (t1 * (k1**2 + k0 * k2) + t2 * k2**2)
    vartheta = (k1 / (2 * k0)) * np.sqrt(4 * k0 * k2 - k1**2) if k1**2 < 2 * k0 * k2 else k2
    return StabilityCoefficients(float(alpha), float(beta), float(gamma1), float(gamma0), float(vartheta))


@validated
def classify_equilibrium(k0: float, k1: float, k2: float) -> str:
    """Type of the singular point of ``k0 q'' + k1 q' + k2 q = 0`` in the phase plane (§4.2, §4.9).

    Parameters
    ----------
    k0 : float
        Coefficient of ``q''`` (the mass); must be positive and finite.
    k1 : float
        Coefficient of ``q'`` (the damping); a finite real number.
    k2 : float
        Coefficient of ``q`` (the stiffness); a finite real number.

    Returns
    -------
    str
        ``"saddle"``, ``"center"``, ``"stable focus"``, ``"unstable node"``, ``"stable degenerate node"``,
        ``"degenerate (zero root)"``, ...

    Examples
    --------
    >>> from symosc.linear import classify_equilibrium
    >>> classify_equilibrium(1, 0.5, 4), classify_equilibrium(1, 0, 4), classify_equilibrium(1, 1, -2)
    ('stable focus', 'center', 'saddle')

    See Also
    --------
    stability_coefficients
    """
    k0, k1, k2 = _check(k0, k1, k2)
    if k2 < 0:
        return "saddle"
    if k2 == 0:
        return "degenerate (zero root)"
    disc = k1**2 - 4 * k0 * k2
    if k1 == 0:
        return "center"
    side = "stable" if k1 > 0 else "unstable"
    if disc < 0:
        return f"{side} focus"
    return f"{side} node" if disc > 0 else f"{side} degenerate node"


@validated
def periodic_forced_response(force: Any, period: float, k0: float, omega: float, t: Any) -> np.ndarray:
    """τ-periodic steady response of the undamped ``k0 (y'' + ω² y) = x(t)`` (Bulgakov (1954), §4.11c).

    On ``0 ≤ t ≤ τ``: ``y1 = (1/(k0ω)) ∫₀ᵗ x(u) sin ω(t-u) du + (1/(2k0ω))[(s + c cot(ωτ/2)) cos ωt +
    (s cot(ωτ/2) - c) sin ωt]`` with ``c, s = ∫₀^τ x(u) (cos, sin)(ωu) du``, extended periodically.

    Parameters
    ----------
    force : callable
        ``x(t)`` on ``[0, τ]`` (one period).
    period : float
        Period ``τ`` of the force; must be positive.
    k0, omega : float
        Mass and natural angular frequency; both must be positive (and ``ωτ`` not a multiple of ``2π``).
    t : array_like
        Times (any real values; reduced modulo ``τ``).

    Raises
    ------
    ParameterError
        At resonance, ``ωτ = 2πn``.

    Examples
    --------
    >>> import numpy as np
    >>> from symosc.linear import periodic_forced_response
    >>> y = periodic_forced_response(lambda u: np.cos(2 * u), np.pi, 1.0, 1.0, [0.0])   # y = cos(2t)/(1 - 4)
    >>> round(float(y[0]), 12)
    -0.333333333333

    See Also
    --------
    linear_filter, frequency_response
    """
    from scipy.integrate import quad

    if not callable(force):
        raise ParameterError("force must be a callable x(t) on one period")
    tau, k0, w = float(period), float(k0), float(omega)
    if tau <= 0 or k0 <= 0 or w <= 0:
        raise ParameterError("period, k0 and omega must be positive")
    n = w * tau / (2 * np.pi)
    if abs(n - round(n)) < 1e-9:
        raise ParameterError(f"resonance: ωτ = 2π·{round(n)}; the response grows without bound")
    c = quad(lambda u: force(u) * np.cos(w * u), 0, tau, limit=200, epsabs=1e-13, epsrel=1e-13)[0]
    s = quad(lambda u: force(u) * np.sin(w * u), 0, tau, limit=200, epsabs=1e-13, epsrel=1e-13)[0]
    cot = 1 / np.tan(w * tau / 2)
    out = []
    for tk in np.atleast_1d(np.asarray(t, dtype=float)):
        tm = tk % tau
        conv = quad(lambda u, tm=tm: force(u) * np.sin(w * (tm - u)), 0, tm, limit=200, epsabs=1e-13)[0] if tm else 0
        free = ((s + c * cot) * np.cos(w * tm) + (s * cot - c) * np.sin(w * tm)) / 2
        out.append((conv + free) / (k0 * w))
    return np.array(out)


@validated
def volterra_march(g: Any, kernel: Any, t: Any) -> np.ndarray:
    """Left-rectangle solution of ``x(t) = g(t) + ∫_{t0}^t K(t, τ, x(τ)) dτ`` (Bulgakov (1954), §4.4, eq. (4.40)).

    The integral equation is the reduction of ``ẋ + f(t) x = y(t) + ψ(x, t)`` with ``K = Θ(t) Θ⁻¹(τ) ψ`` and
    ``g = Θ(t) Θ⁻¹(t0) x(t0) + ∫ Θ(t) Θ⁻¹(τ) y dτ`` (4.34)–(4.36).  First order in the step.

    Parameters
    ----------
    g : callable
        ``g(t)`` → array of shape ``(m,)``.
    kernel : callable
        ``K(t, τ, x)`` → array of shape ``(m,)``.
    t : array_like
        Time grid: a strictly increasing 1-D array of at least two points, ``t[0] = t0``.

    Returns
    -------
    ndarray, shape (len(t), m)

    Examples
    --------
    >>> import numpy as np
    >>> from symosc.linear import volterra_march
    >>> x = volterra_march(lambda s: np.array([1.0]), lambda s, u, x: -x, np.linspace(0, 1, 201))   # x' = -x
    >>> bool(abs(x[-1, 0] - np.exp(-1)) < 1e-3)
    True

    See Also
    --------
    linear_filter
    """
    tt = np.asarray(t, dtype=float)
    if tt.ndim != 1 or tt.size < 2 or np.any(np.diff(tt) <= 0):
        raise ParameterError("t must be an increasing 1-D grid with at least two points")
    x = [np.atleast_1d(np.asarray(g(tt[0]), dtype=float))]
    dt = np.diff(tt)
    for j in range(1, tt.size):
        acc = np.atleast_1d(np.asarray(g(tt[j]), dtype=float)).copy()
        for k in range(j):
            acc += np.asarray(kernel(tt[j], tt[k], x[k]), dtype=float) * dt[k]
        x.append(acc)
    return np.array(x)
