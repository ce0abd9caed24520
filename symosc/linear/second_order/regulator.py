"""Choosing regulator parameters by a stability coefficient; lines of equal stability (Bulgakov (1954), §4.10–4.12).

* :func:`optimize_regulator` — the best ``k1`` (``k2`` fixed) or ``k2`` (``k1`` fixed) of ``k0 D² + k1 D + k2`` under
  one of the coefficients α, β, γ1, γ0, ϑ of :func:`stability_coefficients`, inside an admissible interval and
  under the frequency limit ``ω ≤ ω_m`` (4.93)–(4.98).
* :func:`equal_stability_lines` — the lines of equal α (4.77)–(4.78), β (4.83)–(4.84), γ1 (4.87), γ0 (4.89) and
  ϑ (4.92) in the ``(k1, k2)`` plane.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from .one_dof import StabilityCoefficients, _check, stability_coefficients

__all__ = ["EqualStabilityLines", "RegulatorOptimum", "equal_stability_lines", "optimize_regulator"]

_CRITERIA = ("alpha", "beta", "gamma1", "gamma0", "vartheta")


def _criterion(name: str) -> str:
    if name not in _CRITERIA:
        raise ParameterError(f"criterion must be one of {_CRITERIA}, got {name!r}")
    return name


def _theta(theta) -> tuple[float, float]:
    try:
        t1, t2 = (float(v) for v in theta)
    except (TypeError, ValueError) as exc:
        raise ParameterError("theta must be a pair (θ1, θ2) of non-negative weights") from exc
    if t1 < 0 or t2 < 0 or t1 + t2 == 0 or not np.isfinite(t1 + t2):
        raise ParameterError(f"theta must be non-negative and not both zero, got {theta}")
    return t1, t2


@dataclass(frozen=True)
class RegulatorOptimum(SymPyPrintable):
    """Result of :func:`optimize_regulator`.

    Attributes
    ----------
    k0, k1, k2 : float
        The optimal coefficients.
    free : str
        ``"k1"`` or ``"k2"``, the parameter that was chosen.
    criterion : {"alpha", "beta", "gamma1", "gamma0", "vartheta"}
        The stability coefficient that was maximised.
    value : float
        The achieved value of the criterion.
    coefficients : StabilityCoefficients
        All five coefficients at the optimum.
    kind : str
        ``"stationary point"`` (interior maximum), ``"plateau"`` (the criterion is constant from ``plateau[0]`` on;
        the smallest such value is returned) or ``"boundary"`` (an end of the admissible interval).
    interval : (float, float)
        Admissible interval of the free parameter (after the frequency limit).
    plateau : (float, float) or None
        The interval on which the criterion is constant at its maximum (``kind == "plateau"``), else None.
    theta : (float, float)
        Weights used by γ1 and γ0.
    """

    k0: float
    k1: float
    k2: float
    free: str
    criterion: str
    value: float
    coefficients: StabilityCoefficients
    kind: str
    interval: tuple[float, float]
    plateau: tuple[float, float] | None = None
    theta: tuple[float, float] = (1.0, 0.0)

    def __repr__(self) -> str:
        return (
            f"RegulatorOptimum({self.criterion} = {self.value:.6g} at k1 = {self.k1:.6g}, k2 = {self.k2:.6g}; "
            f"{self.kind})"
        )

    def _repr_latex_(self) -> str:
        names = {"alpha": r"\alpha", "beta": r"\beta", "gamma1": r"\gamma_1", "gamma0": r"\gamma_0"}
        sym = names.get(self.criterion, r"\vartheta")
        return (
            rf"${sym} = {self.value:.6g}\ \text{{at}}\ k_1 = {self.k1:.6g},\ k_2 = {self.k2:.6g}"
            rf"\quad \text{{({self.kind})}}$"
        )

    def plot(self, *, ax=None, n_points: int = 400):
        """The criterion against the free parameter over the admissible interval, optimum marked; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        n_points : int, optional
            Number of values of the free parameter plotted (an integer >= 2; default 400).
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        lo, hi = self.interval
        hi = hi if np.isfinite(hi) else 3 * (self.k1 if self.free == "k1" else self.k2)
        x = np.linspace(max(lo, 1e-9 * hi), hi, n_points)
        th = self.theta
        vals = [
            getattr(
                stability_coefficients(self.k0, *((v, self.k2) if self.free == "k1" else (self.k1, v)), theta=th),
                self.criterion,
            )
            for v in x
        ]
        ax.plot(x, vals)
        ax.plot([self.k1 if self.free == "k1" else self.k2], [self.value], "ro")
        ax.set_xlabel(self.free)
        ax.set_ylabel(self.criterion)
        return ax


@validated
def optimize_regulator(
    k0: float,
    *,
    k1: float | None = None,
    k2: float | None = None,
    criterion: str = "alpha",
    theta: tuple[float, float] = (1.0, 0.0),
    bounds: tuple[float, float] | None = None,
    omega_max: float | None = None,
) -> RegulatorOptimum:
    """Best ``k1`` or ``k2`` of ``k0 D² + k1 D + k2`` by a stability coefficient (Bulgakov (1954), §4.12).

    Give ``k1`` to choose ``k2``, or ``k2`` to choose ``k1``.  Each coefficient is unimodal in the free parameter,
    so the optimum is the unconstrained maximiser clipped to the admissible interval:

    * ``k1`` free: α is largest at ``k1 = 2√(k0 k2)`` (4.97); β and ϑ rise to ``k2`` and stay there from
      ``k1 = 2√(k0 k2)`` and ``k1 = √(2 k0 k2)`` on; γ1 grows without bound; γ0 is largest at
      ``k1 = √(k2 (θ1 k0 + θ2 k2)/θ1)`` (``√(k0 k2)`` for θ = (1, 0), (4.98)).
    * ``k2`` free: α stays ``k1/(2k0)`` for ``k2 ≥ k1²/(4k0)`` (4.95); β, γ1 and ϑ grow with ``k2``; γ0 is largest
      at ``k2 = √(θ1/θ2) k1`` (4.96).

    Parameters
    ----------
    k0 : float
        Mass ``k0``; must be positive and finite.
    k1, k2 : float
        Exactly one of them: the fixed coefficient (positive).
    criterion : {"alpha", "beta", "gamma1", "gamma0", "vartheta"}
        The stability coefficient to maximise (see :func:`stability_coefficients`; default ``"alpha"``).
    theta : (float, float)
        Weights of ``y²`` and ``y'²`` in γ1 and γ0.
    bounds : (float, float), optional
        Admissible interval of the free parameter; default ``(0, ∞)``.
    omega_max : float, optional
        Upper limit of the natural frequency ``ω = √(k2/k0 - k1²/(4k0²))`` (4.93): an upper bound on ``k2`` or a
        lower bound on ``k1``.

    Raises
    ------
    ParameterError
        When the criterion grows without bound on the admissible interval (give ``bounds`` or ``omega_max``), or
        the interval is empty.

    Examples
    --------
    >>> from symosc.linear import optimize_regulator
    >>> r = optimize_regulator(2.0, k2=8.0, criterion="alpha")          # k1 = 2√(k0 k2) = 8, α = k1/(2k0)
    >>> r.k1, r.value, r.kind
    (8.0, 2.0, 'stationary point')
    >>> r = optimize_regulator(1.0, k2=4.0, criterion="gamma0")         # k1 = √(k0 k2), γ0 = √(k2/k0)
    >>> r.k1, round(r.value, 12)
    (2.0, 2.0)
    >>> optimize_regulator(1.0, k1=2.0, criterion="beta", omega_max=1.0).k2     # top of (4.93): k1²/4k0 + k0ω²
    2.0

    See Also
    --------
    stability_coefficients, equal_stability_lines, max_stability_degree_cubic
    """
    crit = _criterion(criterion)
    t1, t2 = _theta(theta)
    if (k1 is None) == (k2 is None):
        raise ParameterError("give exactly one of k1 (to choose k2) or k2 (to choose k1)")
    free = "k2" if k2 is None else "k1"
    fixed = k1 if free == "k2" else k2
    k0f, fixed, _ = _check(k0, fixed, 1.0)
    if fixed <= 0:
        raise ParameterError(f"the fixed coefficient must be positive (asymptotic stability (4.73)), got {fixed}")
    lo, hi = (0.0, np.inf) if bounds is None else (float(bounds[0]), float(bounds[1]))
    if not (0 <= lo < hi) or np.isnan(hi):
        raise ParameterError(f"bounds must satisfy 0 <= lo < hi, got {bounds}")
    if omega_max is not None:
        wm = float(omega_max)
        if not wm > 0:
            raise ParameterError(f"omega_max must be positive, got {omega_max}")
        if free == "k2":  # (4.93): k2 < k1²/(4k0) + k0 ω_m²
            hi = min(hi, fixed**2 / (4 * k0f) + k0f * wm**2)
        elif fixed > k0f * wm**2:  # ω² = k2/k0 - k1²/(4k0²) ≤ ω_m²  ⇔  k1 ≥ 2√(k0 (k2 - k0 ω_m²))
            lo = max(lo, 2 * np.sqrt(k0f * (fixed - k0f * wm**2)))
        if not lo < hi:
            raise ParameterError("the admissible interval is empty under omega_max and bounds")
    # unconstrained maximiser: (start, is_plateau); start = inf when the criterion increases without bound
    if free == "k1":
        k2v = fixed
        peak = {
            "alpha": (2 * np.sqrt(k0f * k2v), False),
            "beta": (2 * np.sqrt(k0f * k2v), True),
            "gamma1": (np.inf, False),
            "gamma0": (np.sqrt(k2v * (t1 * k0f + t2 * k2v) / t1) if t1 > 0 else np.inf, False),
            "vartheta": (np.sqrt(2 * k0f * k2v), True),
        }[crit]
    else:
        k1v = fixed
        peak = {
            "alpha": (k1v**2 / (4 * k0f), True),
            "beta": (np.inf, False),
            "gamma1": (np.inf, False),
            "gamma0": (k1v * np.sqrt(t1 / t2) if t2 > 0 else np.inf, False),
            "vartheta": (np.inf, False),
        }[crit]
    start, flat = peak
    plateau = None
    if start >= hi:
        if not np.isfinite(hi):
            raise ParameterError(
                f"{crit} grows without bound as {free} grows; give bounds=(lo, hi) or omega_max to limit {free}"
            )
        x, kind = hi, "boundary"
    elif start <= lo:
        x = lo
        kind = "plateau" if flat else "boundary"
        if x == 0:
            raise ParameterError(f"the optimum of {crit} is at {free} = 0, outside the stability region (4.73)")
    else:
        x, kind = start, "plateau" if flat else "stationary point"
    if kind == "plateau":
        plateau = (x, hi)
    kk1, kk2 = (x, fixed) if free == "k1" else (fixed, x)
    c = stability_coefficients(k0f, kk1, kk2, theta=(t1, t2))
    return RegulatorOptimum(
        k0=k0f,
        k1=float(kk1),
        k2=float(kk2),
        free=free,
        criterion=crit,
        value=float(getattr(c, crit)),
        coefficients=c,
        kind=kind,
        interval=(lo, float(hi)),
        plateau=plateau,
        theta=(t1, t2),
    )


@dataclass(frozen=True)
class EqualStabilityLines(SymPyPrintable):
    """Result of :func:`equal_stability_lines`: curves of constant criterion in the ``(k1, k2)`` plane.

    Attributes
    ----------
    criterion : {"alpha", "beta", "gamma1", "gamma0", "vartheta"}
        The stability coefficient held constant.
    value : float
        Its value.
    k0 : float
        The mass ``k0``.
    branches : tuple of (ndarray, ndarray)
        ``(k1, k2)`` samples of each branch.
    equations : tuple of str
        The book's equation of each branch.
    """

    criterion: str
    value: float
    k0: float
    branches: tuple
    equations: tuple[str, ...]

    def __repr__(self) -> str:
        return f"EqualStabilityLines({self.criterion} = {self.value:.6g}: {', '.join(self.equations)})"

    def plot(self, *, ax=None, boundary: bool = True):
        """Draw the branches (and the stability boundary ``k1 = 0``, ``k2 = 0`` and the parabola (4.74)).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        boundary : bool, optional
            Also draw the stability boundary and the parabola ``k2 = k1²/(4k0)`` of critical damping (default True).

        Returns
        -------
        matplotlib Axes
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        for (a, b), eq in zip(self.branches, self.equations, strict=True):
            ax.plot(a, b, label=f"{self.criterion} = {self.value:.4g}: {eq}")
        if boundary:
            top = max(float(np.nanmax(a)) for a, _ in self.branches)
            k1 = np.linspace(0, top, 200)
            ax.plot(k1, k1**2 / (4 * self.k0), "k:", lw=0.8, label="aperiodicity boundary k2 = k1²/(4 k0)")
            ax.axhline(0, color="k", lw=0.8)
            ax.axvline(0, color="k", lw=0.8)
        ax.set_xlabel("k1")
        ax.set_ylabel("k2")
        ax.legend(fontsize="small")
        return ax


@validated
def equal_stability_lines(
    criterion: str,
    value: float,
    k0: float = 1.0,
    *,
    theta: tuple[float, float] = (1.0, 0.0),
    k1_max: float | None = None,
    n_points: int = 200,
) -> EqualStabilityLines:
    """Lines of equal stability coefficient in the ``(k1, k2)`` plane (Bulgakov (1954), §4.10–4.11).

    * α: ``k2 = α k1 - k0 α²`` for ``k1 ≥ 2k0α`` (4.77) and ``k1 = 2k0α``, ``k2 ≥ k0α²`` (4.78).
    * β: ``k2 = β`` for ``k1 ≥ 2√(k0β)`` (4.83) and ``k2 tanh(π k1/(2√(4k0k2 - k1²))) = β`` (4.84), drawn
      parametrically: with ``q = π k1/(2√(4k0k2 - k1²))``, ``k2 = β/tanh q``,
      ``k1² = 4k0β/(tanh q (1 + π²/(4q²)))``.
    * γ1: the hyperbola ``k2 (2k0k1 - γ1θ2) = γ1θ1k0`` (4.87).
    * γ0: the conic ``γ0θ1k1² - 2k1k2 + γ0θ2k2² + γ0θ1k0k2 = 0`` (4.89).
    * ϑ: ``k2 = k0ϑ²/k1² + k1²/(4k0)`` for ``k1 < √(2k0ϑ)`` and ``k2 = ϑ`` beyond (4.92).

    As the value tends to 0 the lines merge with the boundary ``k1 = 0``, ``k2 = 0`` of the stability region.

    Parameters
    ----------
    criterion : {"alpha", "beta", "gamma1", "gamma0", "vartheta"}
        The stability coefficient held constant (see :func:`stability_coefficients`).
    value : float
        Its value; must be positive and finite (for γ0 also below ``1/√(θ1θ2)``).
    k0 : float, optional
        The mass ``k0``; must be positive and finite (default 1).
    theta : (float, float), optional
        Weights ``θ1, θ2`` of ``y²`` and ``y'²`` in γ1 and γ0; non-negative, not both zero (default (1, 0)).
    k1_max : float, optional
        Largest ``k1`` drawn on unbounded branches (a positive number; default a few times the branch's start).
    n_points : int, optional
        Number of points per branch (an integer >= 2; default 200).

    Returns
    -------
    EqualStabilityLines

    Examples
    --------
    >>> from symosc.linear import equal_stability_lines
    >>> lines = equal_stability_lines("alpha", 0.5, k0=2.0, k1_max=6.0, n_points=3)
    >>> [b.tolist() for b in lines.branches[0]]                         # k2 = α k1 - k0 α² from the tangency point
    [[2.0, 4.0, 6.0], [0.5, 1.5, 2.5]]

    See Also
    --------
    stability_coefficients, optimize_regulator
    """
    crit = _criterion(criterion)
    t1, t2 = _theta(theta)
    k0, _, _ = _check(k0, 1.0, 1.0)
    v = float(value)
    if not v > 0 or not np.isfinite(v):
        raise ParameterError(f"value must be positive and finite, got {value}")
    n = int(n_points)
    if n < 2:
        raise ParameterError("n_points must be at least 2")
    if crit == "alpha":
        a = 2 * k0 * v
        top = k1_max if k1_max is not None else 3 * a
        k1 = np.linspace(a, max(top, a), n)
        k2v = np.linspace(k0 * v**2, max(v * top - k0 * v**2, 2 * k0 * v**2), n)
        branches = ((k1, v * k1 - k0 * v**2), (np.full(n, a), k2v))
        eqs = ("k2 = αk1 - k0α² (4.77)", "k1 = 2k0α (4.78)")
    elif crit == "beta":
        a = 2 * np.sqrt(k0 * v)
        top = k1_max if k1_max is not None else 3 * a
        q = np.geomspace(0.05, 12.0, n)
        th = np.tanh(q)
        curve = (np.sqrt(4 * k0 * v / (th * (1 + np.pi**2 / (4 * q**2)))), v / th)
        branches = (curve, (np.linspace(a, max(top, a), n), np.full(n, v)))
        eqs = ("k2 tanh(πk1/(2√(4k0k2 - k1²))) = β (4.84)", "k2 = β (4.83)")
    elif crit == "gamma1":
        a = v * t2 / (2 * k0)
        top = k1_max if k1_max is not None else 10 * max(a, v * t1 / 2, 1.0)
        k1 = np.geomspace(max(a, 1e-12) * (1 + 1e-2) + 1e-3 * top, top, n)
        branches = ((k1, v * t1 * k0 / (2 * k0 * k1 - v * t2)),)
        eqs = ("k2 (2k0k1 - γ1θ2) = γ1θ1k0 (4.87)",)
    elif crit == "gamma0":
        if t1 == 0:
            top = k1_max if k1_max is not None else 10.0
            k1 = np.linspace(top / n, top, n)
            branches = ((k1, 2 * k1 / (v * t2)),)
        else:
            # for given k2 the conic is a quadratic in k1; real for k2² ≥ γ²θ1(θ2k2² + θ1k0k2)
            A = 1 - v**2 * t1 * t2
            if A > 0:
                k2_hi = v**2 * t1**2 * k0 / A
                k2 = np.geomspace(k2_hi, 50 * k2_hi, n)
            else:
                raise ParameterError(
                    f"no point of the stability region reaches γ0 = {v} with θ = {theta} (γ0 ≤ 1/√(θ1θ2))"
                )
            disc = np.sqrt(np.maximum(k2**2 - v**2 * t1 * (t2 * k2**2 + t1 * k0 * k2), 0.0))
            branches = (((k2 - disc) / (v * t1), k2), ((k2 + disc) / (v * t1), k2))
        eqs = ("γ0θ1k1² - 2k1k2 + γ0θ2k2² + γ0θ1k0k2 = 0 (4.89)",) * len(branches)
    else:
        a = np.sqrt(2 * k0 * v)
        top = k1_max if k1_max is not None else 3 * a
        k1 = np.linspace(a / 5, a, n)
        branches = ((k1, k0 * v**2 / k1**2 + k1**2 / (4 * k0)), (np.linspace(a, max(top, a), n), np.full(n, v)))
        eqs = ("k2 = k0ϑ²/k1² + k1²/(4k0) (4.92)", "k2 = ϑ (4.92)")
    return EqualStabilityLines(criterion=crit, value=v, k0=k0, branches=branches, equations=eqs)
