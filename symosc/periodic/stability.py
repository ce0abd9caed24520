"""Stability region of a statically unstable pendulum system with a vertically vibrating pivot.

Gribkov & Khokhlov (2015), §3.  The linearized inverted N-link pendulum
with pivot ``y = a cos(p t)``,

    M phi'' + (-g + a p^2 cos(p t)) C phi = 0,                                              (6)

has ``K0 = -g C`` and ``K1 = a p^2 C`` (gravity and pivot acceleration multiply the same matrix ``C``), so the
normal coordinates of the hanging pendulum (natural frequencies ``p_1 < ... < p_N`` of ``(M, g C)``) decouple
it exactly into Mathieu equations with ``a_i = -4 (p_i/p)^2``, ``q_i = 2 a p_i^2 / g``.  In the first-tone
coordinates ``a^1 = -4 (p_1/p)^2``, ``q^1 = 2 a p_1^2 / g`` the stability region is bounded below by
``a_0(q^1)`` (mode 1) and above by ``r_N b_1(q^1 / r_N)`` (mode N), ``r_i = (p_1/p_i)^2``.

Generalisation used here: any linear model ``M q'' + (K0 + K1 cos(p t)) q = 0`` with ``-K0`` positive definite
relative to ``M`` and ``K1 = mu (-K0)`` for a scalar ``mu(amplitude, p)`` linear in the amplitude; for the
pendulum ``mu = a p^2 / g``.  Then ``q^1 = 2 |mu| p_1^2 / p^2``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from .._plotting import plot_method
from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ConvergenceError, ModelError, ParameterError
from ..numeric import compile, resolve
from ..numeric._lazy import LazyFunction
from ..symbols import sort_symbols, t
from .floquet import monodromy
from .ince_strutt import ModifiedInceStruttDiagram, _as_float_array, modified_ince_strutt, series_boundary

__all__ = ["METHODS", "StabilityRegion", "stability_region"]

METHODS = ("modified-ince-strutt", "floquet", "otterbein", "acheson", "chelomei")


# ---------------------------------------------------------------------------------------- the model
@dataclass(frozen=True)
class _ParametricModel:
    """Numbers of ``M q'' + (K0 + mu(amp, p) (-K0) cos(p t)) q = 0`` at given parameter values."""

    M: np.ndarray
    S: np.ndarray  # -K0, positive definite relative to M
    natural_frequencies: np.ndarray  # hanging (direct) system, rad/s, ascending
    amplitude: sp.Symbol
    frequency: sp.Symbol
    nu_expr: sp.Expr  # mu / amplitude, a function of the frequency only
    _nu: Callable = field(repr=False)
    q_independent_of_p: bool = False

    @property
    def ratios(self) -> np.ndarray:
        w = self.natural_frequencies
        return (w[0] / w) ** 2

    def first_tone(self, p: Any, amp: Any) -> tuple[np.ndarray, np.ndarray]:
        p = _as_float_array(p, "p")
        amp = _as_float_array(amp, "a")
        if np.any(p <= 0):
            raise ParameterError(f"excitation frequency p must be positive, got {p}")
        if np.any(amp < 0):
            raise ParameterError(f"amplitude must be non-negative, got {amp}")
        p1 = self.natural_frequencies[0]
        a1 = -4.0 * (p1 / p) ** 2
        q1 = 2.0 * np.abs(amp * self._nu(p)) * p1**2 / p**2
        return a1, q1

    def amplitude_from_q(self, p: np.ndarray, q1: np.ndarray) -> np.ndarray:
        p1 = self.natural_frequencies[0]
        return q1 * p**2 / (2.0 * p1**2 * np.abs(self._nu(p)))


class _ExcitationFactor:
    """``nu(p)`` as a float array (picklable: holds the expression, not a closure)."""

    def __init__(self, fn: LazyFunction) -> None:
        self.fn = fn

    def __call__(self, pp: Any) -> np.ndarray:
        return np.asarray(self.fn(np.asarray(pp, dtype=float)), dtype=float)


def _linear_model(system: Any) -> Any:
    from ..mechanics import LagrangianSystem, LinearModel

    if isinstance(system, LinearModel):
        return system
    if isinstance(system, LagrangianSystem):
        return system.linearize()
    raise ModelError(
        f"system must be a LagrangianSystem or a LinearModel, got {type(system).__name__}; "
        "build one with e.g. symosc.models.n_link_pendulum(N, inverted=True, pivot='vertical')"
    )


def _extract_model(system: Any, values: Mapping[Any, Any]) -> _ParametricModel:
    lin = _linear_model(system)
    if t not in lin.K.free_symbols:
        raise ModelError(
            "the system has no pivot excitation: its stiffness does not depend on time. "
            "Build it with a vibrating pivot, e.g. n_link_pendulum(N, inverted=True, pivot='vertical')"
        )
    if any(e != 0 for e in lin.D):
        raise ModelError("the system has damping or gyroscopic terms (D != 0); the Ince–Strutt methods need D = 0")
    K0, K1, p = lin.periodic_stiffness()
    n = K0.shape[0]
    ij = next(((i, j) for i in range(n) for j in range(n) if K0[i, j] != 0), None)
    if ij is None:
        raise ModelError("K0 = 0: there is no gravity (static) stiffness to scale the diagram with")
    mu = sp.cancel(-K1[ij] / K0[ij])
    residual = [sp.expand(e) for e in (K1 + mu * K0)]
    if t in mu.free_symbols or any(e != 0 and sp.simplify(e) != 0 for e in residual):
        raise ModelError(
            "gravity and pivot acceleration do not multiply the same matrix (K1 is not a scalar multiple of K0), "
            "so the normal coordinates do not decouple the equations; use method='floquet' on a model "
            "where they do, or a general Floquet analysis (symosc.periodic.monodromy)"
        )
    cand = mu.free_symbols - K0.free_symbols - {p}
    if len(cand) != 1:
        raise ModelError(
            f"cannot identify the excitation amplitude in K1/(-K0) = {mu}: expected exactly one symbol that is "
            f"not in K0, found {sorted(s.name for s in cand)}"
        )
    amp = cand.pop()
    nu = sp.cancel(mu / amp)
    if amp in nu.free_symbols:
        raise ModelError(f"the excitation term K1/(-K0) = {mu} is not linear in the amplitude {amp}")
    params = sort_symbols((lin.M.free_symbols | K0.free_symbols) - {t})
    mats = compile(lin.M.row_join(-K0), list(params), name="pendulum_matrices")
    MS = np.asarray(mats.call(values), dtype=float)
    M, S = MS[:, :n], MS[:, n:]
    nu_params = sort_symbols(nu.free_symbols - {p})
    nu_fn = compile(nu, [p, *nu_params], name="excitation_factor")
    nu_vals = [float(v) for v in resolve(nu_params, values)]
    nu_fn(1.0, *nu_vals)
    nu_num = _ExcitationFactor(LazyFunction(nu, [p, *nu_params], bound=nu_vals, name="excitation_factor"))

    from scipy.linalg import eigh

    if not np.allclose(M, M.T, rtol=1e-12, atol=0) or not np.allclose(S, S.T, rtol=1e-10, atol=0):
        raise ModelError("M and K0 must be symmetric")
    try:
        lam = eigh(S, M, eigvals_only=True)
    except np.linalg.LinAlgError as exc:
        raise ModelError("the mass matrix is not positive definite at these parameter values") from exc
    if np.any(lam <= 0):
        raise ModelError(
            "the equilibrium is not statically unstable in every mode (-K0 is not positive definite): the "
            "modified Ince–Strutt diagram is for inverted systems; was the model built with inverted=True?"
        )
    q_indep = sp.cancel(sp.diff(nu / p**2, p)) == 0
    return _ParametricModel(
        M=M,
        S=S,
        natural_frequencies=np.sqrt(np.sort(lam)),
        amplitude=amp,
        frequency=p,
        nu_expr=nu,
        _nu=nu_num,
        q_independent_of_p=bool(q_indep),
    )


# ---------------------------------------------------------------------------------------- the region
def _solve_decreasing(f: Callable[[np.ndarray], np.ndarray], target: np.ndarray) -> np.ndarray:
    """Vectorised bisection for ``f(q) = target`` with ``f`` decreasing on ``q >= 0`` and ``f(0) > target``."""
    target = np.asarray(target, dtype=float)
    lo = np.zeros_like(target)
    hi = np.maximum(1.0, 2.0 * np.sqrt(np.abs(2.0 * target)))
    for _ in range(60):
        bad = f(hi) >= target
        if not bad.any():
            break
        hi = np.where(bad, 2.0 * hi, hi)
    else:
        raise ConvergenceError("could not bracket the boundary (is the boundary curve decreasing?)")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        above = f(mid) >= target
        lo = np.where(above, mid, lo)
        hi = np.where(above, hi, mid)
        if np.all(hi - lo <= 1e-15 * np.maximum(1.0, hi)):
            break
    return 0.5 * (lo + hi)


@dataclass(frozen=True)
class StabilityRegion(SymPyPrintable):
    """Stability region of the inverted system with a vibrating pivot.

    First-tone coordinates ``(a^1, q^1)``: ``a^1 = -4 (p_1/p)^2``, ``q^1 = 2 a p_1^2 / g`` (``p`` excitation
    frequency, ``a`` amplitude, ``p_1`` lowest natural frequency of the hanging system).

    Attributes
    ----------
    method : str
        How the boundaries were obtained (one of :data:`METHODS`).
    natural_frequencies : ndarray
        ``p_1 < ... < p_N`` (rad/s) of the hanging system.
    ratios : tuple of float
        ``r_i = (p_1/p_i)^2``.
    diagram : ModifiedInceStruttDiagram or None
        The modified diagram behind the region (methods other than ``"floquet"``).
    notes : str
        What the method assumes / reconstructs.
    _lower : callable
        Internal (set by :func:`stability_region`): ``q^1 -> a^1`` of the lower boundary, behind :meth:`lower`.
    _upper : callable
        Internal: ``q^1 -> a^1`` of the upper boundary, behind :meth:`upper`.
    _classify : callable
        Internal: ``(a^1, q^1) -> bool array``, behind :meth:`contains`.
    _model : object
        Internal: the numeric model (mass and stiffness matrices, natural frequencies, excitation factor) the
        region was computed from; pickling keeps it and rebuilds the rest.
    _q_bounds : callable or None
        Internal: ``a^1 -> (q_lo, q_hi)`` in closed form (approximate methods, Floquet); None to solve the
        boundaries for ``q^1`` numerically.
    _options : dict
        Internal: the options of :func:`stability_region` (order, series terms, tolerance), used to rebuild the
        region on unpickling.
    """

    method: str
    natural_frequencies: np.ndarray
    ratios: tuple
    diagram: ModifiedInceStruttDiagram | None
    notes: str
    _lower: Callable = field(repr=False, compare=False)
    _upper: Callable = field(repr=False, compare=False)
    _classify: Callable = field(repr=False, compare=False)
    _model: _ParametricModel = field(repr=False, compare=False)
    _q_bounds: Callable | None = field(default=None, repr=False, compare=False)
    _options: dict = field(default_factory=dict, repr=False, compare=False)

    def __reduce__(self) -> tuple:
        """Pickle the model and the method; the boundary functions are rebuilt on loading (they are closures)."""
        return (_region_from_model, (self.method, self._model), dict(self._options))

    # ---------------------------------------------------------------- first-tone coordinates
    def lower(self, q: Any) -> np.ndarray:
        """Lower boundary ``a^1(q^1)`` in first-tone coordinates (``-inf``: none).

        Parameters
        ----------
        q : float or array_like
            First-tone amplitude parameter(s) ``q^1``, finite real numbers (the sign is ignored: ``|q^1|`` is used).

        Returns
        -------
        ndarray
            ``a^1`` on the lower boundary, shaped like ``q``.
        """
        return np.asarray(self._lower(np.abs(_as_float_array(q, "q"))), dtype=float)

    def upper(self, q: Any) -> np.ndarray:
        """Upper boundary ``a^1(q^1)`` in first-tone coordinates (``+inf``: none).

        Parameters
        ----------
        q : float or array_like
            First-tone amplitude parameter(s) ``q^1``, finite real numbers (the sign is ignored: ``|q^1|`` is used).

        Returns
        -------
        ndarray
            ``a^1`` on the upper boundary, shaped like ``q``.
        """
        return np.asarray(self._upper(np.abs(_as_float_array(q, "q"))), dtype=float)

    def contains(self, a1: Any, q1: Any) -> np.ndarray:
        """Classification of first-tone points ``(a^1, q^1)`` by this method.

        Parameters
        ----------
        a1 : float or array_like
            First-tone frequency parameter(s) ``a^1 = -4 (p_1/p)^2``, finite real numbers (broadcast with ``q1``).
        q1 : float or array_like
            First-tone amplitude parameter(s) ``q^1``, finite real numbers (the sign is ignored).

        Returns
        -------
        ndarray of bool
            True inside the stability region, with the broadcast shape.
        """
        a1, q1 = np.broadcast_arrays(_as_float_array(a1, "a1"), _as_float_array(q1, "q1"))
        return np.asarray(self._classify(a1, np.abs(q1)), dtype=bool)

    # ---------------------------------------------------------------- dimensional coordinates
    def first_tone(self, p: Any, a: Any) -> tuple[np.ndarray, np.ndarray]:
        """``(a^1, q^1)`` of excitation frequency ``p`` (rad/s) and amplitude ``a`` (m).

        Parameters
        ----------
        p : float or array_like
            Excitation frequency (rad/s), finite and positive.
        a : float or array_like
            Pivot amplitude (m), finite and non-negative (broadcast with ``p``).

        Returns
        -------
        (a1, q1) : tuple of ndarray
            The first-tone coordinates.
        """
        return self._model.first_tone(p, a)

    def is_stable(self, p: Any, a: Any) -> np.ndarray:
        """Stability at excitation frequency ``p`` (rad/s) and amplitude ``a``; vectorised (broadcasts).

        Parameters
        ----------
        p : float or array_like
            Excitation frequency (rad/s), finite and positive.
        a : float or array_like
            Pivot amplitude (m), finite and non-negative (broadcast with ``p``).

        Returns
        -------
        ndarray of bool
            True where the inverted equilibrium is stable by this method.
        """
        a1, q1 = self.first_tone(p, a)
        return self.contains(a1, q1)

    def amplitude_bounds(self, p: Any) -> tuple[np.ndarray, np.ndarray]:
        """``(a_min, a_max)``: the principal region at frequency ``p`` is ``a_min < a < a_max`` (nan if empty).

        Parameters
        ----------
        p : float or array_like
            Excitation frequency (rad/s), finite and positive; arrays give the bounds elementwise.

        Returns
        -------
        (a_min, a_max) : tuple of ndarray
            Amplitude bounds (m), nan where the region is empty at that frequency.
        """
        p = _as_float_array(p, "p")
        a1, _ = self._model.first_tone(p, np.zeros_like(p))
        if self._q_bounds is not None:
            q_lo, q_hi = self._q_bounds(a1)
        else:
            q_lo = _solve_decreasing(self.lower, a1) if np.all(np.isfinite(self.lower(1.0))) else np.zeros_like(a1)
            q_hi = self._q_upper(a1)
        amin = self._model.amplitude_from_q(p, q_lo)
        amax = self._model.amplitude_from_q(p, q_hi)
        empty = ~(amin < amax)
        return np.where(empty, np.nan, amin), np.where(empty, np.nan, amax)

    def _q_upper(self, a1: np.ndarray) -> np.ndarray:
        up0 = self.upper(np.array([0.0, 1.0]))
        if not np.all(np.isfinite(up0)):
            # step-shaped or missing upper boundary: q at which the upper boundary drops below a1
            qs = np.linspace(0, 4.0, 40001)
            u = self.upper(qs)
            return np.array([qs[np.argmax(u <= x)] if np.any(u <= x) else np.inf for x in np.ravel(a1)]).reshape(
                np.shape(a1)
            )
        return _solve_decreasing(self.upper, a1)

    def lower_dimensional(self, p: Any) -> np.ndarray:
        """Minimum stabilising amplitude (m) at excitation frequency ``p`` (rad/s).

        Parameters
        ----------
        p : float or array_like
            Excitation frequency (rad/s), finite and positive; arrays give the bounds elementwise.

        Returns
        -------
        ndarray
            ``a_min`` of :meth:`amplitude_bounds` (nan where the region is empty).
        """
        return self.amplitude_bounds(p)[0]

    def upper_dimensional(self, p: Any) -> np.ndarray:
        """Maximum stable amplitude (m) at excitation frequency ``p`` (rad/s).

        Parameters
        ----------
        p : float or array_like
            Excitation frequency (rad/s), finite and positive; arrays give the bounds elementwise.

        Returns
        -------
        ndarray
            ``a_max`` of :meth:`amplitude_bounds` (nan where the region is empty).
        """
        return self.amplitude_bounds(p)[1]

    def frequency_bounds(self, a: Any) -> tuple[np.ndarray, np.ndarray]:
        """``(p_min, p_max)`` in rad/s at amplitude ``a`` (``p_max = inf`` when the upper boundary is at
        ``a^1 >= 0``; nan when the region is empty).  Needs ``q^1`` independent of ``p`` (true for the pendulum).

        Parameters
        ----------
        a : float or array_like
            Pivot amplitude (m), finite and non-negative; arrays give the bounds elementwise.

        Returns
        -------
        (p_min, p_max) : tuple of ndarray
            Frequency bounds (rad/s).

        Raises
        ------
        ModelError
            If ``q^1`` depends on the excitation frequency for this model.
        """
        if not self._model.q_independent_of_p:
            raise ModelError("q^1 depends on the excitation frequency for this model; use amplitude_bounds(p)")
        amp = _as_float_array(a, "a")
        _, q1 = self._model.first_tone(np.ones_like(amp), amp)
        p1 = self.natural_frequencies[0]
        lo, hi = self.lower(q1), self.upper(q1)
        with np.errstate(divide="ignore", invalid="ignore"):
            pmin = np.where(lo < 0, 2 * p1 / np.sqrt(-lo), np.nan)
            pmax = np.where(hi < 0, 2 * p1 / np.sqrt(-hi), np.inf)
        empty = ~(pmin < pmax)
        return np.where(empty, np.nan, pmin), np.where(empty, np.nan, pmax)

    # ---------------------------------------------------------------- presentation
    def __repr__(self) -> str:
        f = ", ".join(f"{w:.6g}" for w in self.natural_frequencies)
        r = ", ".join(f"{x:.6g}" for x in self.ratios)
        return f"StabilityRegion(method={self.method!r}, natural_frequencies=[{f}] rad/s, ratios=[{r}])"

    def _repr_latex_(self) -> str:
        if self.method != "modified-ince-strutt":
            return f"$$\\text{{{self.method}: {self.notes}}}$$"
        rn = self.ratios[-1]
        return (
            rf"$$a_0(q^1) < a^1 < {rn:.6g}\,b_1(q^1/{rn:.6g}),\quad a^1 = -4\left(\frac{{p_1}}{{p}}\right)^2,"
            rf"\ q^1 = \frac{{2 a p_1^2}}{{g}},\ p_1 = {self.natural_frequencies[0]:.6g}$$"
        )

    @plot_method
    def plot(
        self,
        *,
        ax: Any = None,
        coords: str = "first-tone",
        q_max: float | None = None,
        p_range: tuple[float, float] | None = None,
        num: int = 200,
        point: tuple[float, float] | None = None,
        **style: Any,
    ) -> Any:
        """Boundaries in first-tone axes (``a^1`` horizontal, ``q^1`` vertical, as the paper's Fig. 3–5) or in
        dimensional axes (``coords="dimensional"``: excitation frequency ``p`` in rad/s vs amplitude ``a``).

        In first-tone axes the picture is the one scene reports draw: the modified Ince–Strutt diagram of the
        chain's frequency ratios (every mode's boundaries, the principal region shaded, a legend), with this
        method's boundaries drawn over it when they differ from the diagram's.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Draw here; a new figure otherwise.
        coords : {"first-tone", "dimensional"}
            Axes of the picture.
        q_max : float, optional
            Top of the ``q^1`` axis (first-tone).
        p_range : (float, float), optional
            Frequency range (dimensional).
        num : int
            Points per curve.
        point : (float, float), optional
            Operating point to mark: ``(a^1, q^1)`` in first-tone axes, ``(p, a)`` in dimensional ones.
        **style
            Line style of this method's boundaries (``label``, ``color``, ``ls``, ...).

        Returns
        -------
        matplotlib Axes
            The axes drawn on.
        """
        from .._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots(figsize=(8, 4.5), layout="constrained")
        label = style.pop("label", f"{self.method} boundaries")
        color = style.pop("color", None)
        if coords == "first-tone":
            from .ince_strutt import modified_ince_strutt

            q_max = q_max if q_max is not None else 1.2 * self.ratios[-1]
            lo_a = min(-0.05, 2.0 * point[0]) if point is not None else -0.05
            modified_ince_strutt(self.ratios).plot(
                ax=ax, q_max=q_max, a_range=(lo_a, 1.2 * min(self.ratios)), point=point
            )
            if self.method == "modified-ince-strutt":
                return ax
            q = np.linspace(q_max / num, q_max, num)
            lo, hi = self.lower(q), self.upper(q)
            (line,) = ax.plot(lo, q, label=label, color=color or "C1", lw=1.6, **style)
            hi_plot = np.where(np.isfinite(hi), hi, np.nan)
            ax.plot(hi_plot, q, color=line.get_color(), lw=1.6, **style)
            if not np.all(np.isfinite(hi)):  # step-shaped upper boundary (Acheson): q = const
                jump = q[np.argmax(~np.isfinite(hi) & (hi < 0))] if np.any(hi < 0) else None
                if jump is not None:
                    ax.axhline(jump, color=line.get_color(), **style)
            ax.set_xlabel("frequency parameter $a^1$")
            ax.set_ylabel("amplitude parameter $q^1$")
        elif coords == "dimensional":
            w1, wn = self.natural_frequencies[0], self.natural_frequencies[-1]
            p_range = p_range or (2.0 * w1, 40.0 * wn)
            p = np.geomspace(p_range[0], p_range[1], num)
            amin, amax = self.amplitude_bounds(p)
            (line,) = ax.plot(p, amin, label=label, color=color or "k", **style)
            ax.plot(p, amax, color=line.get_color(), **style)
            ok = np.isfinite(amin) & np.isfinite(amax)
            ax.fill_between(p[ok], amin[ok], amax[ok], color="0.85", label="stable (principal region)")
            if point is not None:
                ax.plot([point[0]], [point[1]], "o", color="C3", ms=7, label="operating point")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("excitation frequency $p$, rad/s")
            ax.set_ylabel("amplitude $a$")
        else:
            raise ParameterError(f"coords must be 'first-tone' or 'dimensional', got {coords!r}")
        from .._plotting import outside_legend

        outside_legend(ax)
        return ax


# ---------------------------------------------------------------------------------------- entry point
@validated
def stability_region(
    system: Any,
    values: Mapping[Any, Any],
    *,
    method: str = "modified-ince-strutt",
    order: int = 1,
    lower_terms: int | None = None,
    upper_terms: int | None = None,
    rtol: float = 1e-12,
) -> StabilityRegion:
    """Stability region of an inverted system with a vertically vibrating pivot.

    Parameters
    ----------
    system : LagrangianSystem or LinearModel
        Inverted system with a vertically vibrating pivot, such as
        ``n_link_pendulum(N, inverted=True, pivot="vertical")`` (linearized at ``q = 0``).
    values : mapping
        Parameter values (keyed by Symbol or name) except the excitation amplitude and frequency.
    method : {"modified-ince-strutt", "floquet", "otterbein", "acheson", "chelomei"}
        ``"modified-ince-strutt"`` (Gribkov & Khokhlov 2015: two Mathieu curves, exact within the linear
        model); ``"floquet"`` (monodromy matrix of the full coupled 2N-dimensional system, boundaries by root
        finding on the multipliers; slow reference); ``"otterbein"``, ``"acheson"``, ``"chelomei"`` (the
        approximate methods the paper compares with, see :mod:`symosc.periodic.comparison`).
    order : int
        Approximation order for ``"chelomei"`` (1 or 2).
    lower_terms, upper_terms : int, optional
        ``"modified-ince-strutt"`` only: boundaries from that many terms of the series (8)/(9).
    rtol : float
        Integrator tolerance for ``"floquet"``.

    Returns
    -------
    StabilityRegion

    Raises
    ------
    ModelError
        No pivot excitation, damping, gravity and excitation not proportional (``K1`` not a multiple of
        ``K0``), a system that is not statically unstable, or an unknown system type.
    ParameterError
        Unknown method or missing parameter values.

    See Also
    --------
    modified_ince_strutt
    compare_methods
    floquet_multipliers

    Examples
    --------
    >>> from symosc.models import n_link_pendulum
    >>> sys1 = n_link_pendulum(1, inverted=True, pivot="vertical")
    >>> reg = stability_region(sys1, {"m1": 1.0, "l1": 1.0, "g": 9.81})
    >>> reg.natural_frequencies.round(6).tolist()
    [3.132092]
    >>> reg.is_stable(p=[50.0, 50.0, 300.0], a=[0.05, 0.2, 0.05]).tolist()   # Kapitza: a p > sqrt(2 g l)
    [False, True, True]
    """
    if method not in METHODS:
        raise ParameterError(f"unknown method {method!r}; choose one of {METHODS}")
    model = _extract_model(system, values)
    return _region_from_model(method, model, order=order, lower_terms=lower_terms, upper_terms=upper_terms, rtol=rtol)


def _region_from_model(
    method: str,
    model: _ParametricModel,
    state: dict | None = None,
    *,
    order: int = 1,
    lower_terms: int | None = None,
    upper_terms: int | None = None,
    rtol: float = 1e-12,
) -> StabilityRegion:
    """The region of ``method`` for an extracted model (``state``: the options, when called by unpickling)."""
    if state:
        return _region_from_model(method, model, **state)
    options = {"order": order, "lower_terms": lower_terms, "upper_terms": upper_terms, "rtol": rtol}
    ratios = tuple(float(r) for r in model.ratios)
    if method == "modified-ince-strutt":
        diag = modified_ince_strutt(ratios, lower_terms=lower_terms, upper_terms=upper_terms)
        src = "exact characteristic values" if lower_terms is None and upper_terms is None else "power series"
        return StabilityRegion(
            method=method,
            natural_frequencies=model.natural_frequencies,
            ratios=ratios,
            diagram=diag,
            notes=f"Gribkov & Khokhlov (2015) modified Ince–Strutt diagram, {src}",
            _lower=diag.lower,
            _upper=diag.upper,
            _classify=diag.is_stable,
            _model=model,
            _options=options,
        )
    region = _build(method, model, ratios, order=order, rtol=rtol)
    region._options.update(options)
    return region


# ------------------------------------------------------------------------ the methods compared with
#: Acheson's bound on beta_N = q_N / 2 (his Mathieu scaling) for the highest mode.
ACHESON_BETA = 0.450


# ---------------------------------------------------------------------------------------- Floquet
class _CoupledFloquet:
    """Monodromy of the full coupled system in first-tone coordinates."""

    def __init__(self, model: _ParametricModel, rtol: float):
        p1 = model.natural_frequencies[0]
        B = np.linalg.solve(model.M, model.S / p1**2)
        n = B.shape[0]
        self.n = n
        self.rtol = rtol
        self.base = np.zeros((2 * n, 2 * n))
        self.base[:n, n:] = np.eye(n)
        self.negB = np.zeros((2 * n, 2 * n))
        self.negB[n:, :n] = -B
        self.R = np.diag([1.0] * n + [-1.0] * n)
        self.rN = float(model.ratios[-1])
        self.evaluations = 0

    def result(self, a1: float, q1: float) -> Any:
        base, negB = self.base, self.negB

        def A(tau: float) -> np.ndarray:
            return base + (a1 - 2.0 * q1 * np.cos(2.0 * tau)) * negB

        self.evaluations += 1
        return monodromy(A, np.pi, reversor=self.R, rtol=self.rtol, atol=1e-14, check_periodic=False)

    def indicator(self, a1: float, q1: float) -> float:
        return self.result(float(a1), float(q1)).hamiltonian_indicator

    def classify(self, a1: np.ndarray, q1: np.ndarray) -> np.ndarray:
        out = np.array([self.indicator(x, y) < 0 for x, y in zip(a1.ravel(), q1.ravel(), strict=True)])
        return out.reshape(a1.shape)

    def _stable_point(self, q: float) -> float | None:
        lo_g, hi_g = -q * q / 2, self.rN - q  # Otterbein's approximations, used only as search hints
        a, b = min(lo_g, hi_g) - 0.1 * q - 1e-3, max(lo_g, hi_g) + 0.1 * q + 1e-3
        cands = np.linspace(a, b, 25)
        mid = 0.5 * (lo_g + hi_g)
        for x in cands[np.argsort(np.abs(cands - mid))]:
            if self.indicator(x, q) < 0:
                return float(x)
        return None

    @lru_cache(maxsize=4096)  # noqa: B019 - one engine per region, kept alive by it
    def boundaries(self, q: float) -> tuple[float, float]:
        from scipy.optimize import brentq

        if not q > 0:
            return (np.nan, np.nan)
        xs = self._stable_point(q)
        if xs is None:
            return (np.nan, np.nan)

        def g(x: float) -> float:
            return self.indicator(x, q)

        h = max(0.25 * q * q, 1e-4)
        x_prev, x = xs, xs - h
        while g(x) < 0:
            x_prev, h = x, 2 * h
            x = x_prev - h
            if h > 1e6:
                raise ConvergenceError(f"floquet: no lower boundary found at q = {q}")
        lower = brentq(g, x, x_prev, xtol=1e-14, rtol=1e-13)
        h = 0.25 * q
        x_prev, x = xs, xs + h
        steps = 0
        while g(x) < 0:
            x_prev, x = x, x + h
            steps += 1
            if steps > 400:
                return (float(lower), np.nan)
        upper = brentq(g, x_prev, x, xtol=1e-14, rtol=1e-13)
        return (float(lower), float(upper))

    def lower(self, q: np.ndarray) -> np.ndarray:
        return np.array([self.boundaries(float(x))[0] for x in np.ravel(q)]).reshape(np.shape(q))

    def upper(self, q: np.ndarray) -> np.ndarray:
        return np.array([self.boundaries(float(x))[1] for x in np.ravel(q)]).reshape(np.shape(q))

    def q_bounds(self, a1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Principal interval ``q_lo < q < q_hi`` at fixed ``a^1 < 0`` by root finding along q."""
        from scipy.optimize import brentq

        lo_out, hi_out = [], []
        for a in np.ravel(a1):
            a = float(a)

            def g(q: float, a: float = a) -> float:
                return self.indicator(a, q)

            ql_g, qh_g = np.sqrt(max(-2 * a, 0.0)), self.rN - a
            cands = np.linspace(min(ql_g, qh_g) * 0.8, max(ql_g, qh_g) * 1.2, 25)
            mid = 0.5 * (ql_g + qh_g)
            qs = next((float(c) for c in cands[np.argsort(np.abs(cands - mid))] if c > 0 and g(c) < 0), None)
            if qs is None:
                lo_out.append(np.nan)
                hi_out.append(np.nan)
                continue
            tiny = 1e-9 * qs
            lo_out.append(brentq(g, tiny, qs, xtol=1e-15, rtol=1e-13) if g(tiny) > 0 else 0.0)
            h = 0.1 * qs
            x_prev, x = qs, qs + h
            while g(x) < 0:
                x_prev, x = x, x + h
                if x > 1e3 * qs:
                    break
            hi_out.append(brentq(g, x_prev, x, xtol=1e-15, rtol=1e-13) if g(x) > 0 else np.inf)
        shape = np.shape(a1)
        return np.array(lo_out).reshape(shape), np.array(hi_out).reshape(shape)


# ---------------------------------------------------------------------------------------- builders
def _envelope_lower(ratios: Sequence[float], f: Any) -> Any:
    def lower(q: np.ndarray) -> np.ndarray:
        return np.max([r * f(q / r) for r in ratios], axis=0)

    return lower


def _build(method: str, model: _ParametricModel, ratios: tuple, *, order: int = 1, rtol: float = 1e-12) -> Any:
    rN = ratios[-1]
    kap = series_boundary("a", 0, 1)  # -q**2/2
    common = {"natural_frequencies": model.natural_frequencies, "ratios": ratios, "_model": model}

    def approximate(notes: str, lower: Any, upper: Any, q_bounds: Any) -> StabilityRegion:
        """A region given by closed-form boundary curves a1 = lower(q1), upper(q1)."""
        return StabilityRegion(
            method=method,
            diagram=None,
            notes=notes,
            _lower=lower,
            _upper=upper,
            _classify=lambda a1, q1: (a1 > lower(q1)) & (a1 < upper(q1)),
            _q_bounds=q_bounds,
            **common,
        )

    if method == "floquet":
        eng = _CoupledFloquet(model, rtol)
        return StabilityRegion(
            method=method,
            diagram=None,
            notes="Floquet multipliers of the full coupled 2N-dim. system (DOP853, half period by reversibility)",
            _lower=eng.lower,
            _upper=eng.upper,
            _classify=eng.classify,
            _q_bounds=eng.q_bounds,
            **common,
        )
    if method == "otterbein":
        lower = _envelope_lower(ratios, kap)
        b1 = series_boundary("b", 1, 2)  # 1 - q

        def upper(q: np.ndarray) -> np.ndarray:
            return np.min([r * b1(q / r) for r in ratios], axis=0)

        def qb(a1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            return np.sqrt(-2 * a1), rN - a1

        notes = "Otterbein (1982), reconstructed: a0 ~ -q^2/2 (mode 1), b1 ~ 1 - q (mode N)"
        return approximate(notes, lower, upper, qb)
    if method == "acheson":
        lower = _envelope_lower(ratios, kap)
        q_cap = 2 * ACHESON_BETA * rN

        def upper(q: np.ndarray) -> np.ndarray:
            return np.where(q < q_cap, np.inf, -np.inf)

        def qb(a1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            return np.sqrt(-2 * a1), np.full(np.shape(a1), q_cap)

        notes = "Acheson (1993) pendulum theorem, reconstructed: q1 > sqrt(-2 a1) and q_N < 2*0.450"
        return approximate(notes, lower, upper, qb)
    if method == "chelomei":
        if order not in (1, 2):
            raise ParameterError(f"chelomei: order must be 1 or 2, got {order!r}")
        f = series_boundary("a", 0, order)
        lower = _envelope_lower(ratios, f)

        def upper(q: np.ndarray) -> np.ndarray:
            return np.full(np.shape(q), np.inf)

        c = f.expr.as_coefficients_dict()

        def qb(a1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            if order == 1:
                return np.sqrt(-2 * a1), np.full(np.shape(a1), np.inf)
            # smallest positive root of c2 x + c4 x^2 = a1, x = q^2
            qs = next(iter(f.expr.free_symbols))
            c2, c4 = float(c[qs**2]), float(c[qs**4])
            disc = c2 * c2 + 4 * c4 * a1
            with np.errstate(invalid="ignore"):
                x = (-c2 - np.sqrt(disc)) / (2 * c4)
            return np.sqrt(x), np.full(np.shape(a1), np.inf)

        notes = f"Chelomei (1999) Kapitza averaging, approximation {order}, reconstructed (lower boundary only)"
        return approximate(notes, lower, upper, qb)
    raise ParameterError(f"unknown method {method!r}")
