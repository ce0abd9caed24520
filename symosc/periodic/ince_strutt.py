"""Classic and modified Ince–Strutt diagrams of the Mathieu equation ``y'' + (a - 2 q cos 2x) y = 0``.

Classic diagram (Gribkov & Khokhlov 2015, Fig. 1; McLachlan): in the ``(a, q)`` plane the solutions are
bounded between the characteristic curves ``a_n(q) < a < b_{n+1}(q)`` (n = 0, 1, 2, ...; the ordering
``a_0 < b_1 < a_1 < b_2 < ...`` holds for ``q > 0``) and unbounded in the resonance tongues
``b_n < a < a_n``.  Negative ``q`` is mapped to ``|q|`` (the shift ``x -> x + pi/2`` changes the sign of
``q`` and only swaps ``a_{2k+1}`` with ``b_{2k+1}``, so the stable set is even in ``q``).

Modified diagram (Gribkov & Khokhlov (2015), §3, eq. (7)): an N-mode system whose
modes obey Mathieu equations with ``a_i = a^1 / r_i``, ``q_i = q^1 / r_i`` (``r_i = (p_1/p_i)^2``) is drawn in
the first-tone coordinates ``(a^1, q^1)``: each boundary curve ``a = f(q)`` of mode ``i`` becomes
``a^1 = r_i f(q^1 / r_i)``.  The principal stability region is bounded below by the highest ``a_0``-curve
(mode 1) and above by the lowest ``b_1``-curve (mode N).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from .._deprecation import deprecated_attribute as _deprecated_attribute
from .._deprecation import renamed_keyword
from .._plotting import label_curves, outside_legend, plot_method
from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ConvergenceError, ParameterError, warn

__all__ = [
    "InceStruttDiagram",
    "ModifiedInceStruttDiagram",
    "ince_strutt_diagram",
    "mathieu_stable",
    "modified_ince_strutt",
    "series_boundary",
]

_MAX_BANDS = 400


def _char(kind: str, n: int, q: np.ndarray) -> np.ndarray:
    """a_n(q) or b_n(q) from :mod:`symosc.periodic.mathieu` (imported lazily: it is a sibling module)."""
    from . import mathieu

    fn = mathieu.mathieu_a if kind == "a" else mathieu.mathieu_b
    return np.asarray(fn(n, q), dtype=float)


def _as_float_array(x: Any, name: str) -> np.ndarray:
    try:
        arr = np.asarray(x, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be real numbers, got {x!r}") from exc
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{name} must be finite, got {x!r}")
    return arr


@validated
def mathieu_stable(a: Any, q: Any) -> np.ndarray:
    """True where the Mathieu equation ``y'' + (a - 2q cos 2x) y = 0`` has only bounded solutions.

    Exact band test: stable iff ``a_n(|q|) < a < b_{n+1}(|q|)`` for some ``n >= 0`` (boundaries count as
    unstable).  Vectorised (broadcasts ``a`` against ``q``).

    Parameters
    ----------
    a : float or array_like
        Characteristic parameter(s) ``a``, finite real numbers.
    q : float or array_like
        Amplitude parameter(s) ``q``, finite real numbers broadcastable against ``a`` (the sign is ignored).

    Returns
    -------
    ndarray of bool
        True where the solutions are bounded, with the broadcast shape.

    Raises
    ------
    ConvergenceError
        If ``a`` lies above the first 400 stability bands.

    See Also
    --------
    mathieu_a, mathieu_b, ince_strutt_diagram

    Examples
    --------
    >>> mathieu_stable([-0.1, -0.5, 0.5, 2.0], 0.5).tolist()
    [True, False, False, True]
    """
    a = _as_float_array(a, "a")
    q = np.abs(_as_float_array(q, "q"))
    a, q = np.broadcast_arrays(a, q)
    shape = a.shape
    a, q = a.ravel(), q.ravel()
    out = np.zeros(a.size, dtype=bool)
    idx = np.arange(a.size)
    n = 0
    while idx.size:
        if n > _MAX_BANDS:
            raise ConvergenceError(f"mathieu_stable: a is above the first {_MAX_BANDS} bands; a too large")
        an = _char("a", n, q[idx])
        bn1 = _char("b", n + 1, q[idx])
        ai = a[idx]
        out[idx[(ai > an) & (ai < bn1)]] = True
        idx = idx[ai >= bn1]
        n += 1
    return out.reshape(shape)


# ---------------------------------------------------------------------------------------- series
@lru_cache(maxsize=64)
def series_boundary(kind: str, n: int, terms: int) -> Callable[[Any], np.ndarray]:
    """The first ``terms`` non-zero terms of the power series of ``a_n(q)`` (kind ``"a"``) or ``b_n(q)``
    (kind ``"b"``) as a vectorised numeric function of ``q`` (from the exact Rational series of
    :func:`symosc.periodic.mathieu_series_a` / ``_b``, compiled with :func:`symosc.numeric.compile`).

    Gribkov & Khokhlov 2015, eq. (8)–(9) and Fig. 4 keep 1–4 terms of ``a_0`` and 2, 3, 5 terms of ``b_1``.

    Parameters
    ----------
    kind : {"a", "b"}
        Which characteristic value: ``"a"`` (even solutions, ``a_n``) or ``"b"`` (odd solutions, ``b_n``).
    n : int
        Index of the characteristic value, an integer >= 0 for ``"a"`` and >= 1 for ``"b"``.
    terms : int
        Number of non-zero terms kept, a positive integer.

    Returns
    -------
    callable
        ``f(q) -> ndarray``; it warns (SeriesWarning) beyond the series' radius of convergence.  ``f.expr`` holds
        the truncated polynomial.

    Examples
    --------
    >>> f = series_boundary("a", 0, 1)      # a_0 ~ -q**2/2
    >>> round(float(f(0.2)), 15)
    -0.02
    """
    from ..numeric import compile
    from . import mathieu_series

    if kind not in ("a", "b"):
        raise ParameterError(f"kind must be 'a' or 'b', got {kind!r}")
    if isinstance(terms, bool) or not isinstance(terms, int) or terms < 1:
        raise ParameterError(f"terms must be a positive integer, got {terms!r}")
    gen = mathieu_series.mathieu_series_a if kind == "a" else mathieu_series.mathieu_series_b
    order = 2 * terms + n + 2
    poly = sp.expand(sp.sympify(gen(n, order)))
    syms = sorted(poly.free_symbols, key=lambda s: s.name)
    if len(syms) != 1:
        raise ParameterError(f"series of {kind}_{n} should be a polynomial in q, got {poly}")
    qs = syms[0]
    coeffs = sp.Poly(poly, qs).terms()  # (degree,), coeff, descending
    nz = sorted(((d[0], c) for d, c in coeffs if c != 0), key=lambda x: x[0])
    if len(nz) < terms:
        raise ConvergenceError(f"series of {kind}_{n} to order {order} has only {len(nz)} non-zero terms")
    expr = sp.Add(*[c * qs**d for d, c in nz[:terms]])
    fn = compile(expr, [qs], name=f"series_{kind}{n}_{terms}", check=False)
    raw = fn.raw

    def f(q: Any) -> np.ndarray:
        qa = np.asarray(q, dtype=float)
        size = float(np.nanmax(np.abs(qa))) if qa.size else 0.0
        if size > 0:
            radius = mathieu_series.mathieu_series_radius(kind, n)
            if size > radius:
                from ..errors import SeriesWarning

                warn(
                    f"series of {kind}_{n}(q) evaluated at |q| = {size:.4g}, beyond its radius of convergence "
                    f"~{radius:.4g}: the truncated sum is not meaningful there (use mathieu_characteristic)",
                    SeriesWarning,
                )
        return raw(qa)

    f.expr = expr  # type: ignore[attr-defined]
    return f


# ---------------------------------------------------------------------------------------- classic
@dataclass(frozen=True)
class InceStruttDiagram(SymPyPrintable):
    """The classic Ince–Strutt diagram: characteristic curves ``a_n(q)``, ``b_n(q)`` on a q grid.

    Attributes
    ----------
    q : ndarray
        Grid of ``q >= 0``.
    a_curves : dict[int, ndarray]
        ``a_n(q)`` on ``q`` for ``n = 0..n_max``.
    b_curves : dict[int, ndarray]
        ``b_n(q)`` on ``q`` for ``n = 1..n_max``.
    """

    q: np.ndarray
    a_curves: dict
    b_curves: dict

    @property
    def n_max(self) -> int:
        """Largest index ``n`` of the characteristic curves ``a_n``, ``b_n``."""
        return max(self.a_curves)

    orders = _deprecated_attribute("n_max")

    def is_stable(self, a: Any, q: Any) -> np.ndarray:
        """Exact stability of ``(a, q)`` (see :func:`mathieu_stable`).

        Parameters
        ----------
        a : float or array_like
            Characteristic parameter(s) ``a``, finite real numbers.
        q : float or array_like
            Amplitude parameter(s) ``q``, finite real numbers broadcastable against ``a`` (the sign is ignored).

        Returns
        -------
        ndarray of bool
            True where the solutions are bounded.
        """
        return mathieu_stable(a, q)

    def __repr__(self) -> str:
        return f"InceStruttDiagram(n = 0..{self.n_max}, q in [{self.q[0]:g}, {self.q[-1]:g}], {self.q.size} points)"

    def _repr_latex_(self) -> str:
        return r"$$y'' + (a - 2q\cos 2x)\,y = 0:\quad \text{stable for } a_n(q) < a < b_{n+1}(q)$$"

    @plot_method
    def plot(self, *, ax: Any = None, a_range: tuple[float, float] = (-2.0, 14.0), shade: bool = True) -> Any:
        """The paper's Fig. 1: frequency parameter ``a`` (horizontal) vs amplitude parameter ``q``, each curve
        labelled directly (labels placed where they overlap neither each other nor the legend).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Draw here; a new figure otherwise.
        a_range : (float, float)
            Range of the frequency parameter shown.
        shade : bool
            Shade the stable bands ``a_n < a < b_(n+1)``.

        Returns
        -------
        matplotlib Axes
            The axes drawn on.
        """
        from .._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots(figsize=(8, 5), layout="constrained")
        if shade:  # stable bands a_n < a < b_{n+1}; the last band is open to the right
            for n in range(self.n_max + 1):
                right = self.b_curves[n + 1] if n + 1 in self.b_curves else np.full(self.q.shape, a_range[1])
                ax.fill_betweenx(self.q, self.a_curves[n], np.maximum(right, self.a_curves[n]), color="0.85")
        labels = []
        for kind, curves, ls in (("a", self.a_curves, "k-"), ("b", self.b_curves, "k--")):
            for n, c in curves.items():
                ax.plot(c, self.q, ls, lw=1.2)
                labels.append((c, self.q, f"${kind}_{n}$"))
        ax.set_xlim(*a_range)
        ax.set_ylim(self.q[0], self.q[-1])
        from matplotlib.lines import Line2D
        from matplotlib.patches import Patch

        handles = [Line2D([], [], color="k", ls="-", label="$a_n$ (even)"), Line2D([], [], color="k", ls="--")]
        handles[1].set_label("$b_n$ (odd)")
        if shade:
            handles.append(Patch(color="0.85", label="stable"))
        outside_legend(ax, handles=handles)
        label_curves(ax, labels)  # direct labels, none on top of another (a_n and b_(n+1) approach at large q)
        ax.set_xlabel("frequency parameter $a$")
        ax.set_ylabel("amplitude parameter $q$")
        ax.set_title("Ince–Strutt diagram")
        return ax


@validated
@renamed_keyword({"orders": "n_max"})
def ince_strutt_diagram(n_max: int = 3, q_max: float = 8.0, num: int = 201) -> InceStruttDiagram:
    """Characteristic curves ``a_0..a_n_max``, ``b_1..b_n_max`` on ``q in [0, q_max]``.

    Parameters
    ----------
    n_max : int
        Largest index of the characteristic curves, a non-negative integer.
    q_max : float
        End of the grid ``[0, q_max]``, positive and finite.
    num : int
        Number of grid points in ``q`` (>= 2).

    Returns
    -------
    InceStruttDiagram

    See Also
    --------
    modified_ince_strutt
    mathieu_a
    mathieu_b

    Examples
    --------
    >>> d = ince_strutt_diagram(n_max=2, q_max=1.0, num=3)
    >>> sorted(d.a_curves), sorted(d.b_curves)
    ([0, 1, 2], [1, 2])
    >>> [round(float(d.a_curves[n][0]), 12) for n in range(3)]   # a_n(0) = n**2
    [0.0, 1.0, 4.0]
    """
    if isinstance(n_max, bool) or not isinstance(n_max, int) or n_max < 0:
        raise ParameterError(f"n_max must be a non-negative integer, got {n_max!r}")
    if not (np.isfinite(q_max) and q_max > 0):
        raise ParameterError(f"q_max must be positive and finite, got {q_max!r}")
    q = np.linspace(0.0, float(q_max), int(num))
    a_c = {n: _char("a", n, q) for n in range(n_max + 1)}
    b_c = {n: _char("b", n, q) for n in range(1, n_max + 1)}
    return InceStruttDiagram(q=q, a_curves=a_c, b_curves=b_c)


# ---------------------------------------------------------------------------------------- modified
def _normalise_ratios(ratios: Any) -> tuple[float, ...]:
    r = np.atleast_1d(_as_float_array(ratios, "ratios")).ravel()
    if r.size == 0 or np.any(r <= 0) or np.any(r > 1 + 1e-12):
        raise ParameterError(f"ratios r_i = (p_1/p_i)**2 must lie in (0, 1], got {r.tolist()}")
    r = np.sort(np.minimum(r, 1.0))[::-1]
    if r[0] < 1.0:
        r = np.concatenate([[1.0], r])
    return tuple(float(x) for x in r)


@dataclass(frozen=True)
class ModifiedInceStruttDiagram(SymPyPrintable):
    """Modified Ince–Strutt diagram of Gribkov & Khokhlov (2015) in first-tone coordinates ``(a^1, q^1)``.

    Attributes
    ----------
    ratios : tuple of float
        ``r_i = (p_1/p_i)**2``, descending, ``r_1 = 1``.
    lower_terms : int or None
        ``None``: exact characteristic values for the lower boundary; an integer: that many non-zero terms of the
        power series (8) of ``a_0`` (Fig. 4 of the paper).
    upper_terms : int or None
        ``None``: exact characteristic values for the upper boundary; an integer: that many non-zero terms of the
        power series (9) of ``b_1``.
    """

    ratios: tuple
    lower_terms: int | None = None
    upper_terms: int | None = None

    def curve(self, kind: str, n: int, mode: int, q: Any) -> np.ndarray:
        """Boundary ``a = f(q)`` (``f`` = ``a_n`` or ``b_n``) of mode ``mode`` (1-based) in first-tone axes:
        ``r_i f(q / r_i)``.

        Parameters
        ----------
        kind : {"a", "b"}
            Which characteristic value: ``"a"`` (``a_n``) or ``"b"`` (``b_n``).
        n : int
            Index of the characteristic value, an integer >= 0 for ``"a"`` and >= 1 for ``"b"``.
        mode : int
            1-based index of the mode, between 1 and the number of ratios.
        q : float or array_like
            First-tone amplitude parameter(s) ``q^1``, finite real numbers (the sign is ignored).

        Returns
        -------
        ndarray
            ``a^1`` on the curve, shaped like ``q``.
        """
        if not 1 <= mode <= len(self.ratios):
            raise ParameterError(f"mode must be in 1..{len(self.ratios)}, got {mode}")
        r = self.ratios[mode - 1]
        q = np.abs(_as_float_array(q, "q"))
        return r * _char(kind, n, q / r)

    def _f(self, kind: str, terms: int | None, q: np.ndarray) -> np.ndarray:
        if terms is None:
            return _char(kind, 0 if kind == "a" else 1, q)
        return series_boundary(kind, 0 if kind == "a" else 1, terms)(q)

    def lower(self, q: Any) -> np.ndarray:
        """Lower boundary ``max_i r_i a_0(q / r_i) = a_0(q)`` (mode 1).

        Only mode 1 is evaluated: ``a_0(q)`` is the lowest eigenvalue of a self-adjoint operator depending
        affinely on ``q``, hence concave with ``a_0(0) = 0``, so ``d/dr [r a_0(q/r)] = a_0(x) - x a_0'(x) >= 0``
        (``x = q/r``): the largest ratio (``r_1 = 1``) gives the highest curve.  (The series truncations keep
        the same choice, as the paper does.)  :meth:`lower_mode` checks it by evaluating every mode.

        Parameters
        ----------
        q : float or array_like
            First-tone amplitude parameter(s) ``q^1``, finite real numbers (the sign is ignored: ``|q^1|`` is used).

        Returns
        -------
        ndarray
            ``a^1`` on the lower boundary, shaped like ``q``.
        """
        q = np.abs(_as_float_array(q, "q"))
        r = self.ratios[0]
        return r * self._f("a", self.lower_terms, q / r)

    def upper(self, q: Any) -> np.ndarray:
        """Upper boundary ``min_i r_i b_1(q / r_i) = r_N b_1(q / r_N)`` (mode N).

        Only mode N is evaluated: ``b_1`` is the lowest eigenvalue in its symmetry class, concave in ``q`` with
        ``b_1(0) = 1``, so ``d/dr [r b_1(q/r)] = b_1(x) - x b_1'(x) >= 1 > 0``: the smallest ratio gives the lowest
        curve.  :meth:`upper_mode` checks it by evaluating every mode.

        Parameters
        ----------
        q : float or array_like
            First-tone amplitude parameter(s) ``q^1``, finite real numbers (the sign is ignored: ``|q^1|`` is used).

        Returns
        -------
        ndarray
            ``a^1`` on the upper boundary, shaped like ``q``.
        """
        q = np.abs(_as_float_array(q, "q"))
        r = self.ratios[-1]
        return r * self._f("b", self.upper_terms, q / r)

    def lower_mode(self, q: Any) -> np.ndarray:
        """1-based index of the mode whose ``a_0`` curve is the lower boundary (the paper: always 1).

        Parameters
        ----------
        q : float or array_like
            First-tone amplitude parameter(s) ``q^1``, finite real numbers (the sign is ignored: ``|q^1|`` is used).

        Returns
        -------
        ndarray of int
            The mode index at each ``q``.
        """
        q = np.abs(_as_float_array(q, "q"))
        return 1 + np.argmax([r * self._f("a", self.lower_terms, q / r) for r in self.ratios], axis=0)

    def upper_mode(self, q: Any) -> np.ndarray:
        """1-based index of the mode whose ``b_1`` curve is the upper boundary (the paper: always N).

        Parameters
        ----------
        q : float or array_like
            First-tone amplitude parameter(s) ``q^1``, finite real numbers (the sign is ignored: ``|q^1|`` is used).

        Returns
        -------
        ndarray of int
            The mode index at each ``q``.
        """
        q = np.abs(_as_float_array(q, "q"))
        return 1 + np.argmin([r * self._f("b", self.upper_terms, q / r) for r in self.ratios], axis=0)

    def is_stable(self, a: Any, q: Any, *, principal: bool = False) -> np.ndarray:
        """Stability of the point ``(a^1, q^1)``.

        With exact boundaries and ``principal=False``: every mode ``(a/r_i, q/r_i)`` must lie in a stable
        band of the Mathieu equation (exact, includes the higher stability bands at large q).  Otherwise:
        inside the principal region ``lower(q) < a < upper(q)``.

        Parameters
        ----------
        a : float or array_like
            First-tone frequency parameter(s) ``a^1``, finite real numbers.
        q : float or array_like
            First-tone amplitude parameter(s) ``q^1``, finite real numbers broadcastable against ``a``.
        principal : bool
            Test only the principal region ``lower(q) < a < upper(q)`` even with exact boundaries.

        Returns
        -------
        ndarray of bool or bool
            True where stable, with the broadcast shape (a NumPy bool for scalar input).
        """
        a = _as_float_array(a, "a")
        q = _as_float_array(q, "q")
        a, q = np.broadcast_arrays(a, q)
        if principal or self.lower_terms is not None or self.upper_terms is not None:
            return ((a > self.lower(q)) & (a < self.upper(q)))[()]  # scalar input gives a NumPy bool, as ufuncs do
        out = np.ones(a.shape, dtype=bool)
        for r in self.ratios:
            out &= mathieu_stable(a / r, q / r)
        return out[()]

    def __repr__(self) -> str:
        rs = ", ".join(f"{r:.6g}" for r in self.ratios)
        src = "exact" if self.lower_terms is None and self.upper_terms is None else "series"
        return f"ModifiedInceStruttDiagram(ratios=({rs}), boundaries={src})"

    def _repr_latex_(self) -> str:
        rn = self.ratios[-1]
        return rf"$$a_0(q) < a < {rn:.6g}\, b_1\!\left(\frac{{q}}{{{rn:.6g}}}\right)$$"

    @plot_method
    @renamed_keyword({"orders": "n_max"})
    def plot(
        self,
        *,
        ax: Any = None,
        n_max: int = 1,
        q_max: float = 1.0,
        a_range: tuple[float, float] | None = None,
        num: int = 201,
        shade: bool = True,
        point: tuple[float, float] | None = None,
    ) -> Any:
        """Boundary curves of resonances ``0..n_max`` for every mode (mode 1 solid, higher modes dashed) in
        first-tone axes, the principal stability region shaded (the paper's Fig. 3).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Draw here; a new figure otherwise.
        n_max : int
            Highest resonance drawn (``a_0..a_n``, ``b_1..b_n``).
        q_max : float
            Top of the amplitude axis.
        a_range : (float, float), optional
            Frequency-parameter axis range (default: the curves' extent).
        num : int
            Points per curve.
        shade : bool
            Shade the principal stability region.
        point : (float, float), optional
            An operating point ``(a^1, q^1)`` to mark.

        Returns
        -------
        matplotlib Axes
            The axes drawn on.
        """
        from .._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots(figsize=(8, 5), layout="constrained")
        q = np.linspace(0.0, float(q_max), int(num))
        styles = ["-", "--", ":", "-."]
        lo_a, hi_a = np.inf, -np.inf
        for m in range(1, len(self.ratios) + 1):
            ls = styles[min(m - 1, len(styles) - 1)]
            for n in range(n_max + 1):
                ca = self.curve("a", n, m, q)
                ax.plot(ca, q, "k" + ls, lw=1.0)
                lo_a, hi_a = min(lo_a, ca.min()), max(hi_a, ca.max())
                if n >= 1:
                    cb = self.curve("b", n, m, q)
                    ax.plot(cb, q, "k" + ls, lw=1.0)
                    lo_a, hi_a = min(lo_a, cb.min()), max(hi_a, cb.max())
        if a_range is None:
            a_range = (max(lo_a, -2.0 * q_max - 1.0), hi_a)
        if shade:  # principal stability region lower(q) < a < upper(q)
            lo, hi = self.lower(q), self.upper(q)
            ax.fill_betweenx(q, lo, np.maximum(hi, lo), color="0.85", label="stable (principal region)")
        for m in range(1, min(len(self.ratios), len(styles)) + 1):  # one legend entry per mode's line style
            ax.plot([], [], "k" + styles[m - 1], lw=1.0, label=f"mode {m} boundaries (r = {self.ratios[m - 1]:.4g})")
        if point is not None:
            ax.plot(
                [point[0]], [point[1]], "o", color="C3", ms=7, label=f"operating point ({point[0]:.3g}, {point[1]:.3g})"
            )
        ax.set_xlim(*a_range)
        ax.set_ylim(0, q_max)
        lo_b, hi_b = self.lower(q), self.upper(q)
        outside_legend(ax)
        label_curves(ax, [(lo_b, q, "$a_0$ (lower)"), (hi_b, q, f"$r_{len(self.ratios)} b_1$ (upper)")])
        ax.set_xlabel("frequency parameter $a^1$")
        ax.set_ylabel("amplitude parameter $q^1$")
        rs = ", ".join(f"{r:.4g}" for r in self.ratios[1:])
        ax.set_title(f"Modified Ince–Strutt diagram, r = {rs}")
        return ax


@validated
def modified_ince_strutt(
    ratios: float | Sequence[float], *, lower_terms: int | None = None, upper_terms: int | None = None
) -> ModifiedInceStruttDiagram:
    """Modified Ince–Strutt diagram for squared-frequency ratios ``r_i = (p_1/p_i)**2``.

    Parameters
    ----------
    ratios : float or sequence of float
        Ratios in ``(0, 1]``; ``r_1 = 1`` is added when absent (``0.7`` means a double pendulum with
        ``(p_1/p_2)**2 = 0.7``).
    lower_terms, upper_terms : int, optional
        Use that many non-zero terms of the power series (8) of ``a_0`` / (9) of ``b_1`` instead of the exact
        characteristic values.

    See Also
    --------
    ince_strutt_diagram
    stability_region
    mathieu_a

    Examples
    --------
    >>> d = modified_ince_strutt(0.2019)
    >>> d.ratios
    (1.0, 0.2019)
    >>> d2 = modified_ince_strutt(0.2019, lower_terms=1, upper_terms=2)
    >>> round(float(d2.lower(0.1)), 15), round(float(d2.upper(0.1)), 15)      # -q**2/2 and r - q
    (-0.005, 0.1019)
    """
    for name, v in (("lower_terms", lower_terms), ("upper_terms", upper_terms)):
        if v is not None and (isinstance(v, bool) or not isinstance(v, int) or v < 1):
            raise ParameterError(f"{name} must be a positive integer or None, got {v!r}")
    return ModifiedInceStruttDiagram(_normalise_ratios(ratios), lower_terms, upper_terms)
