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
from typing import Any

import numpy as np

from .._plotting import plot_method
from .._printing import SymPyPrintable
from .._validate import validated
from .stability import ACHESON_BETA, stability_region

__all__ = ["ACHESON_BETA", "MethodComparison", "compare_methods"]


# ---------------------------------------------------------------------------------------- comparison
@dataclass(frozen=True)
class MethodComparison(SymPyPrintable):
    """Boundaries of several methods on a common ``q^1`` grid (the paper's Fig. 5).

    Attributes
    ----------
    q : ndarray
        First-tone amplitude parameters.
    regions : dict[str, StabilityRegion]
        The region of each method, keyed by the method's name.
    lower, upper : dict[str, ndarray]
        Boundary values ``a^1`` per method on ``q``.
    """

    q: np.ndarray
    regions: dict
    lower: dict
    upper: dict

    def table(self, reference: str = "modified-ince-strutt") -> str:
        """Text table of the boundaries and their differences from ``reference``.

        Parameters
        ----------
        reference : str
            Name of the method the others are compared with, one of the compared methods (such as
            ``"modified-ince-strutt"``); no differences are listed when it was not compared.

        Returns
        -------
        str
            One row per ``q^1`` with the lower and upper boundary of every method, then the largest differences.
        """
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
        """All regions in first-tone axes (``a^1`` horizontal, ``q^1`` vertical), like the paper's Fig. 5.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        a_range : tuple of float, optional
            Limits ``(a_min, a_max)`` of the horizontal ``a^1`` axis; Matplotlib's choice when omitted.

        Returns
        -------
        matplotlib Axes
            The axes drawn on.
        """
        from .._plotting import pyplot

        plt = pyplot()

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


@validated
def compare_methods(
    system: Any,
    values: Any,
    *,
    methods: Sequence[str] = ("modified-ince-strutt", "floquet", "otterbein", "acheson", "chelomei"),
    q: Any = None,
    chelomei_order: int = 1,
) -> MethodComparison:
    """Stability boundaries of ``system`` by several methods on a common ``q^1`` grid.

    Parameters
    ----------
    system : LagrangianSystem or LinearModel
        Inverted system with a vertically vibrating pivot, such as
        ``n_link_pendulum(N, inverted=True, pivot="vertical")`` (see :func:`stability_region`).
    values : mapping of Symbol or name to float
        Values of every parameter except the excitation amplitude and frequency (keys are symbols or their
        names).
    methods : sequence of method names
        Methods to compare, each one of ``"modified-ince-strutt"``, ``"floquet"``, ``"otterbein"``,
        ``"acheson"``, ``"chelomei"`` (``"floquet"`` is slow).
    q : array_like, optional
        First-tone amplitude parameters ``q^1`` (finite real numbers) at which the boundaries are compared;
        25 points on ``[0.01, 0.5]`` when omitted.
    chelomei_order : int
        Approximation order of the ``"chelomei"`` method, 1 or 2.

    Returns
    -------
    MethodComparison

    See Also
    --------
    stability_region

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
