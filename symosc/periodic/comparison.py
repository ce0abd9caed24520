"""The methods Gribkov & Khokhlov (2015) compare their modified Ince–Strutt diagram with.

All regions are expressed in the first-tone coordinates ``a^1 = -4 (p_1/p)^2``, ``q^1 = 2 a p_1^2 / g`` of
:mod:`symosc.periodic.stability`; ``r_i = (p_1/p_i)^2``.  The paper (introduction and Fig. 5) only
cites the approximate methods; what is implemented is reconstructed from the cited works' known results:

``"floquet"`` (Demidovich [4])
    Not an approximation: the monodromy matrix of the full, *coupled* 2N-dimensional system
    ``M phi'' + (a^1 - 2 q^1 cos 2 tau) C_hat phi = 0`` (``C_hat = -K0 / p_1^2``, ``tau = p t / 2``, period pi) is
    integrated numerically (:func:`symosc.periodic.monodromy`, half period by reversibility) and the point is
    stable when every multiplier lies on the unit circle.  Boundaries at fixed ``q^1`` are the zeros of the
    smooth indicator ``max |rho + 1/rho| - 2`` (Brent's method); the approximate curves below are used only as
    starting guesses.  Slow: a reference, not a tool.
``"otterbein"`` (Otterbein 1982) [reconstructed]
    "Boundaries from the simplest approximate single-pendulum expressions" applied to the normal modes:
    ``a_0(q) ~ -q^2/2`` (Kapitza) for mode 1 and ``b_1(q) ~ 1 - q`` for mode N, i.e. ``-q^2/2 < a^1 < r_N - q^1``.
    Both are the leading terms of the series (8)/(9).  Otterbein treats chains of identical point masses; the
    same expressions are applied here to whatever ``r_N`` the model has.
``"acheson"`` (Acheson 1993, "A pendulum theorem") [reconstructed]
    The theorem's high-frequency conditions in terms of the hanging system's lowest and highest natural
    frequencies: ``a p p_1 > sqrt(2) g`` (Kapitza for mode 1, i.e. ``q^1 > sqrt(-2 a^1)``) and
    ``a p_N^2 / g < 0.450`` (the upper boundary replaced by the straight line ``q_N = 0.900``, i.e.
    ``q^1 < 0.900 r_N``; the exact value ``b_1(q) = 0`` at ``q = 0.9081`` is the ``a^1 -> 0`` limit).
``"chelomei"`` (S.V. Chelomei 1999, Kapitza averaging for multi-link pendulums) [reconstructed]
    First approximation: the averaged (slow) equations ``M phi'' + (-g C + (a^2 p^2/2) C M^{-1} C) phi = 0``,
    which in the normal coordinates give ``a^1 > -q^2/2`` for every mode (mode 1 decides); no upper
    boundary.  Second approximation: the next order of the averaging, reconstructed as the next term of
    the same per-mode expansion, ``a^1 > -q^2/2 + 7 q^4/128`` (the first two terms of (8), taken from the
    exact series of :func:`symosc.periodic.mathieu_series_a`).  No upper boundary.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from .._plotting import plot_method
from .._printing import SymPyPrintable
from ..errors import ConvergenceError, ParameterError
from .floquet import monodromy
from .ince_strutt import series_boundary
from .stability import StabilityRegion, _ParametricModel, stability_region

__all__ = ["ACHESON_BETA", "MethodComparison", "compare_methods"]

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


# ---------------------------------------------------------------------------------------- comparison
@dataclass(frozen=True)
class MethodComparison(SymPyPrintable):
    """Boundaries of several methods on a common ``q^1`` grid (the paper's Fig. 5).

    Attributes
    ----------
    q : ndarray
        First-tone amplitude parameters.
    regions : dict[str, StabilityRegion]
    lower, upper : dict[str, ndarray]
        Boundary values ``a^1`` per method on ``q``.
    """

    q: np.ndarray
    regions: dict
    lower: dict
    upper: dict

    def table(self, reference: str = "modified-ince-strutt") -> str:
        """Text table of the boundaries and their differences from ``reference``."""
        names = list(self.regions)
        head = f"{'q1':>8} | " + " | ".join(f"{n + ' lo':>22} {n + ' up':>22}" for n in names)
        lines = [head, "-" * len(head)]
        for k, q in enumerate(self.q):
            cells = []
            for n in names:
                lo, up = self.lower[n][k], self.upper[n][k]
                cells.append(f"{lo:>22.12g} {up:>22.12g}")
            lines.append(f"{q:>8.4g} | " + " | ".join(cells))
        if reference in self.regions:
            lines.append("")
            for n in names:
                if n == reference:
                    continue
                dl = np.nanmax(np.abs(self.lower[n] - self.lower[reference]))
                fin = np.isfinite(self.upper[n]) & np.isfinite(self.upper[reference])
                du = np.nanmax(np.abs(self.upper[n][fin] - self.upper[reference][fin])) if fin.any() else np.nan
                lines.append(f"max |{n} - {reference}|: lower {dl:.3g}, upper {du:.3g}")
        return "\n".join(lines)

    def __repr__(self) -> str:
        return f"MethodComparison(methods={list(self.regions)}, {self.q.size} q values)"

    @plot_method
    def plot(self, *, ax: Any = None, a_range: tuple[float, float] | None = None) -> Any:
        """All regions in first-tone axes (``a^1`` horizontal, ``q^1`` vertical), like the paper's Fig. 5."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6.5, 4.5))
        styles = {
            "modified-ince-strutt": {"color": "k", "ls": "-", "lw": 2.0},
            "floquet": {"color": "C3", "ls": ":", "lw": 2.5},
            "otterbein": {"color": "C0", "ls": "--", "lw": 1.2},
            "acheson": {"color": "C2", "ls": "-.", "lw": 1.2},
            "chelomei": {"color": "C1", "ls": (0, (5, 1, 1, 1)), "lw": 1.2},
        }
        for name in self.regions:
            st = dict(styles.get(name, {}))
            lo, up = self.lower[name], self.upper[name]
            ax.plot(lo, self.q, label=name, **st)
            fin = np.isfinite(up)
            if fin.any():
                ax.plot(np.where(fin, up, np.nan), self.q, **st)
            if name == "acheson":
                cap = 2 * ACHESON_BETA * self.regions[name].ratios[-1]
                ax.axhline(cap, **st)
        if a_range is not None:
            ax.set_xlim(*a_range)
        ax.set_xlabel("frequency parameter $a^1$")
        ax.set_ylabel("amplitude parameter $q^1$")
        ax.set_title("Stability region of the inverted pendulum: methods compared")
        ax.legend(fontsize=8)
        return ax


def compare_methods(
    system: Any,
    values: Any,
    *,
    methods: Sequence[str] = ("modified-ince-strutt", "floquet", "otterbein", "acheson", "chelomei"),
    q: Any = None,
    chelomei_order: int = 1,
) -> MethodComparison:
    """Stability boundaries of ``system`` by several methods on a common ``q^1`` grid.

    Examples
    --------
    >>> from symosc.models import n_link_pendulum
    >>> sys1 = n_link_pendulum(1, inverted=True, pivot="vertical")
    >>> cmp = compare_methods(sys1, {"m1": 1, "l1": 1, "g": 9.81}, methods=("modified-ince-strutt", "chelomei"),
    ...                       q=[0.1, 0.2])
    >>> (cmp.lower["chelomei"] - cmp.lower["modified-ince-strutt"]).round(7).tolist()   # -q^2/2 vs a_0(q)
    [-5.5e-06, -8.67e-05]
    """
    if q is None:
        q = np.linspace(0.01, 0.5, 25)
    q = np.asarray(q, dtype=float)
    regions, lower, upper = {}, {}, {}
    for m in methods:
        reg = stability_region(system, values, method=m, order=chelomei_order)
        regions[m] = reg
        lower[m] = reg.lower(q)
        upper[m] = reg.upper(q)
    return MethodComparison(q=q, regions=regions, lower=lower, upper=upper)
