"""Nyquist criterion with indentation, shifted axis and Feldbaum's sector (Bulgakov (1954), §10.7–10.9).

For an open loop ``K(D) = M(D)/Δ0(D)`` the closed-loop characteristic polynomial is ``Δ = Δ0 + M`` (10.19)–(10.20).
Walking the boundary of a region ``G`` (the right half-plane, the half-plane ``Re D > -α``, or the outside of the
sector ``|arg(-D)| < π/2 - θ``) counter-clockwise, the argument principle gives ``N = P + W``: ``W`` the number of
counter-clockwise turns of ``K`` about ``-1``, ``P`` the open-loop poles in ``G`` and ``N`` the closed-loop roots in
``G`` (10.30)–(10.39).  Poles on the contour are avoided by small semicircles that leave them outside ``G`` — the
indentation of neutral links (10.35)–(10.37).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_int, check_memory, check_positive, validated
from ...errors import ConvergenceError, ModelError, ParameterError

__all__ = ["NyquistResult", "StabilityMargins", "nyquist", "stability_margins"]


def _poly(p: Any, what: str) -> np.ndarray:
    if isinstance(p, sp.Poly):
        p = p.all_coeffs()
    try:
        a = np.atleast_1d(np.asarray([complex(sp.sympify(c)) for c in p]))
    except (TypeError, ValueError, sp.SympifyError) as exc:
        raise ParameterError(f"{what} must be numeric coefficients, highest power first") from exc
    if not np.all(np.isfinite(a)):
        raise ParameterError(f"{what} must be finite")
    nz = np.flatnonzero(a)
    if nz.size == 0:
        raise ParameterError(f"{what} is identically zero")
    a = a[nz[0] :]
    return a.real if not np.any(a.imag) else a


#: fewest initial samples per contour piece (the adaptive refinement starts from them)
_MIN_POINTS = 16


def _proper_loop(numerator: Any, denominator: Any) -> tuple[np.ndarray, np.ndarray]:
    """``M`` and ``Δ0`` of a proper loop ``K = M/Δ0``; ModelError for an improper one."""
    M = _poly(numerator, "numerator")
    D0 = _poly(denominator, "denominator")
    if M.size > D0.size:
        raise ModelError(
            f"K = M/Δ0 must be proper: the numerator has degree {M.size - 1} > {D0.size - 1}, the degree of the "
            "denominator (deg M ≤ deg Δ0, Bulgakov (1954), §10.7); the frequency response of an improper loop grows "
            "without bound"
        )
    return M, D0


@dataclass(frozen=True)
class NyquistResult(SymPyPrintable):
    """Result of :func:`nyquist`.

    Attributes
    ----------
    region : str
        ``"Re D > 0"``, ``"Re D > -alpha"`` or the sector description.
    open_loop_poles : int
        ``P``: poles of ``K`` inside the region.
    encirclements : int
        ``S = N - P``: turns of ``K`` about ``-1`` along Bulgakov's contour (which encloses the region clockwise),
        counted clockwise; -1 is one counter-clockwise turn of the plot for ω from -∞ to +∞.
    closed_loop_roots : int
        ``N = S + P``: roots of ``Δ0 + M`` inside the region.
    stable : bool
        ``N == 0``.
    contour : ndarray
        The points of ``D`` walked (complex).
    values : ndarray
        ``K(D)`` on the contour.
    indented_poles : tuple
        Open-loop poles on the boundary that were bypassed.
    """

    region: str
    open_loop_poles: int
    encirclements: int
    closed_loop_roots: int
    stable: bool
    contour: np.ndarray
    values: np.ndarray
    indented_poles: tuple

    def __repr__(self) -> str:
        return (
            f"NyquistResult({self.region}: P={self.open_loop_poles}, S={self.encirclements}, "
            f"N={self.closed_loop_roots}, stable={self.stable})"
        )

    def plot(self, *, ax=None, clip: float = 1e3):
        """Nyquist plot ``K(D)`` along the contour with the critical point ``-1``; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        clip : float, optional
            Largest modulus drawn (positive): values with ``|K| > clip`` are drawn at radius ``clip``.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        v = self.values.copy()
        big = np.abs(v) > clip
        v[big] = v[big] / np.abs(v[big]) * clip
        ax.plot(v.real, v.imag, "-", lw=1.2, label="K along the contour")
        ax.plot([-1], [0], "r+", ms=12, label="−1")
        ax.set_xlabel("Re K")
        ax.set_ylabel("Im K")
        ax.set_title(f"{self.region}: P={self.open_loop_poles}, S={self.encirclements}, N={self.closed_loop_roots}")
        ax.legend()
        return ax


def _boundary(kind: str, alpha: float, theta: float, radius: float, n: int):
    """Points walking the region boundary counter-clockwise (region on the left), closed by a large arc."""
    t = np.logspace(-6, np.log10(radius), n)
    t = np.unique(np.concatenate([-t, [0.0], t]))
    if kind == "half-plane":
        line = -alpha + 1j * t[::-1]  # downwards along Re D = -alpha
        arc = -alpha + radius * np.exp(1j * np.linspace(-np.pi / 2, np.pi / 2, n))
        return line, arc
    # sector: rays D = ρ(-sin θ ± i cos θ); the region outside the sector lies to the right of the rays
    rho = np.logspace(-6, np.log10(radius), n)
    up = rho[::-1] * np.exp(1j * (np.pi / 2 + theta))
    down = rho * np.exp(-1j * (np.pi / 2 + theta))
    line = np.concatenate([up, [0.0], down])
    arc = radius * np.exp(1j * np.linspace(-np.pi / 2 - theta, np.pi / 2 + theta, n))
    return line, arc


def _inside(z: np.ndarray, kind: str, alpha: float, theta: float) -> np.ndarray:
    if kind == "half-plane":
        return z.real > -alpha
    return np.abs(np.angle(-z)) > np.pi / 2 - theta  # outside the sector around the negative real axis


@validated
def nyquist(
    numerator: Any,
    denominator: Any,
    *,
    alpha: float = 0.0,
    sector_angle: float | None = None,
    indentation: float | None = 1e-6,
    n_points: int = 2000,
    max_refinements: int = 30,
) -> NyquistResult:
    """Nyquist count ``N = S + P`` for the loop ``K = M/Δ0`` (Bulgakov (1954), §10.7–10.9).

    Parameters
    ----------
    numerator, denominator : sequence
        Coefficients of ``M`` and ``Δ0`` (highest power first); ``deg M ≤ deg Δ0``.
    alpha : float
        Degree of stability: count roots with ``Re D > -alpha`` (the substitution ``D = -α + D'``, §10.9).
    sector_angle : float, optional
        Feldbaum's sector angle ``θ`` (radians): count roots outside ``D = ρ(-sin θ ± i cos θ)``, i.e. with a
        logarithmic decrement below ``π tan θ`` (§10.9).
    indentation : float or None
        Radius (relative to the pole modulus + 1) of the semicircles around open-loop poles on the contour;
        ``None`` or ``0`` forbids indentation and raises if a pole lies on the contour.
    n_points : int
        Initial samples per contour piece (an integer >= 16; refined adaptively until each step turns by < 0.2 rad).
    max_refinements : int
        Largest number of adaptive refinement rounds (an integer >= 1); ConvergenceError when the plot is still
        unresolved.

    Returns
    -------
    NyquistResult

    Raises
    ------
    ModelError
        A pole of ``K`` on the contour without indentation, ``-1`` on the plot (a closed-loop root on the contour),
        or an improper ``K``.

    Examples
    --------
    >>> from symosc.linear import nyquist
    >>> r = nyquist([4], [1, 1, 0])        # K = 4/(D(D+1)): a neutral link, indented
    >>> r.open_loop_poles, r.closed_loop_roots, r.stable
    (0, 0, True)
    >>> r = nyquist([2], [1, -1])           # K = 2/(D-1): an unstable link, P = 1, one turn, closed loop D + 1
    >>> r.open_loop_poles, r.encirclements, r.closed_loop_roots
    (1, -1, 0)

    See Also
    --------
    stability_margins, hurwitz
    """
    if indentation is not None:
        check_positive("indentation (radius of the detour around poles on the contour; None or 0 forbids it)",
                       indentation, allow_zero=True)  # fmt: skip
    n_points = check_int("n_points (initial samples per contour piece)", n_points, minimum=_MIN_POINTS)
    alpha = check_finite("alpha (degree of stability)", alpha)
    check_memory(f"nyquist(): n_points = {n_points} samples per contour piece", 16.0 * 16 * n_points)
    M, D0 = _proper_loop(numerator, denominator)
    kind = "half-plane" if sector_angle is None else "sector"
    theta = 0.0 if sector_angle is None else float(sector_angle)
    if kind == "sector" and not (0 < theta < np.pi / 2):
        raise ParameterError(f"sector_angle must lie in (0, π/2), got {sector_angle}")
    if kind == "sector" and alpha:
        raise ParameterError("give either alpha or sector_angle, not both")
    poles = np.roots(D0) if D0.size > 1 else np.array([])
    closed = np.polyadd(D0, M)
    croots = np.roots(closed) if closed.size > 1 else np.array([])
    scale = 1.0 + max([*np.abs(poles), *np.abs(croots), 1.0])
    radius = 1e3 * scale

    def dist(z):
        if kind == "half-plane":
            return np.abs(z.real + alpha)
        return np.abs(np.abs(np.angle(-z)) - (np.pi / 2 - theta)) * np.abs(z) if z != 0 else 0.0

    on = [p for p in poles if dist(p) <= 1e-9 * (1 + abs(p))]
    if on and not indentation:
        raise ModelError(
            f"the open-loop poles {on} lie on the Nyquist contour; pass indentation=<small radius> to bypass them "
            "(neutral links, Bulgakov §10.8)"
        )
    for z in croots:
        if dist(z) <= 1e-9 * (1 + abs(z)):
            raise ModelError(f"the closed loop has a root {z} on the contour: K passes through -1 (stability boundary)")
    line, arc = _boundary(kind, alpha, theta, radius, n_points)
    pts = np.concatenate([line, arc])
    r_ind = indentation or 0.0
    distinct: list = []
    for p in on:
        if all(abs(p - q) > 1e-6 * (1 + abs(p)) for q in distinct):
            distinct.append(p)
    for p in distinct:
        p = complex(round(p.real, 12), round(p.imag, 12)) if abs(p) > 1e-12 else 0j
        rad = r_ind * (1 + abs(p))
        keep = np.abs(pts - p) > rad
        n_line = len(line) - int(np.sum(~keep[: len(line)]))  # the line part precedes the closing arc
        pts = pts[keep]
        a, b = pts[: n_line - 1], pts[1:n_line]
        ab = b - a
        tpar = np.clip(np.real((p - a) * np.conj(ab)) / np.maximum(np.abs(ab) ** 2, 1e-300), 0, 1)
        j = int(np.argmin(np.abs(a + tpar * ab - p)))
        direction = ab[j] / abs(ab[j])
        # bypass p on the region side (left of the walk), so that p stays outside the region
        semi = p + rad * np.exp(1j * (np.angle(-direction) - np.linspace(0, np.pi, 200)))
        pts = np.concatenate([pts[: j + 1], semi, pts[j + 1 :]])
        line = pts[: n_line + semi.size]
    inside_poles = int(np.sum(_inside(poles, kind, alpha, theta))) - sum(
        1 for p in on if _inside(np.array([p]), kind, alpha, theta)[0]
    )
    # adaptive refinement of the argument of 1 + K = Δ/Δ0
    for _ in range(max_refinements):
        f = np.polyval(closed, pts) / np.polyval(D0, pts)
        dphi = np.angle(f[1:] / f[:-1])
        bad = np.flatnonzero(np.abs(dphi) > 0.2)
        if bad.size == 0:
            break
        mids = 0.5 * (pts[bad] + pts[bad + 1])
        pts = np.insert(pts, bad + 1, mids)
    else:
        raise ConvergenceError("the Nyquist plot could not be resolved (K passes very close to -1)")
    f = np.polyval(closed, pts) / np.polyval(D0, pts)
    turns = np.sum(np.angle(np.append(f[1:], f[:1]) / f)) / (2 * np.pi)
    W = round(turns)
    if abs(turns - W) > 1e-3:
        raise ConvergenceError(
            f"winding number {turns:.4f} is not an integer; increase n_points", achieved=abs(turns - W)
        )
    K = np.polyval(M, pts) / np.polyval(D0, pts)
    region = (
        "Re D > 0"
        if kind == "half-plane" and alpha == 0
        else (
            f"Re D > -{alpha:g}" if kind == "half-plane" else f"outside Feldbaum's sector θ = {np.degrees(theta):.4g}°"
        )
    )
    N = inside_poles + W
    return NyquistResult(region, inside_poles, W, N, N == 0, pts, K, tuple(complex(p) for p in on))


@dataclass(frozen=True)
class StabilityMargins(SymPyPrintable):
    """Result of :func:`stability_margins` (python-control's convention).

    Attributes
    ----------
    gain_margin : float
        ``1/|K(iω_pc)|`` at the phase crossover (``inf`` if none).
    phase_margin : float
        ``180° + arg K(iω_gc)`` at the gain crossover, degrees (``inf`` if none).
    phase_crossover, gain_crossover : float
        The frequencies (NaN if none).
    """

    gain_margin: float
    phase_margin: float
    phase_crossover: float
    gain_crossover: float


@validated
def stability_margins(numerator: Any, denominator: Any) -> StabilityMargins:
    """Gain and phase margins from polynomial equations in ``ω`` (exact crossovers, no frequency grid).

    Phase crossovers solve ``Im[M(iω) conj Δ0(iω)] = 0`` with ``Re K < 0``; gain crossovers solve
    ``|M(iω)|² = |Δ0(iω)|²``.  The smallest margins are returned.

    Parameters
    ----------
    numerator : sequence or sympy.Poly
        Coefficients of ``M`` (highest power first); finite numbers, not all zero.
    denominator : sequence or sympy.Poly
        Coefficients of ``Δ0`` (highest power first); finite numbers, not all zero.

    Returns
    -------
    StabilityMargins

    Examples
    --------
    >>> from symosc.linear import stability_margins
    >>> m = stability_margins([2], [1, 3, 3, 1])      # K = 2/(D+1)^3
    >>> round(m.gain_margin, 6), round(m.phase_crossover ** 2, 6)
    (4.0, 3.0)

    See Also
    --------
    nyquist
    """
    M, D0 = _proper_loop(numerator, denominator)
    M, D0 = M.astype(complex), D0.astype(complex)

    def at_iw(p):
        # p(iω) as a polynomial in ω with complex coefficients
        n = p.size - 1
        return np.array([c * (1j) ** (n - k) for k, c in enumerate(p)])

    Mw, Dw = at_iw(M), at_iw(D0)
    cross = np.polysub(np.polymul(Mw, np.conj(Dw)), np.polymul(np.conj(Mw), Dw)) / 2j  # Im(M conj D)
    mag = np.polysub(np.polymul(Mw, np.conj(Mw)), np.polymul(Dw, np.conj(Dw)))

    def pos_roots(c):
        c = np.real_if_close(c, tol=1e6)
        c = np.trim_zeros(np.real(c), "f")
        if c.size < 2:
            return []
        r = np.roots(c)
        return sorted(float(x.real) for x in r if abs(x.imag) < 1e-7 * (1 + abs(x)) and x.real > 0)

    gm, wpc = np.inf, np.nan
    zero = [0.0] if abs(np.polyval(D0, 0)) > 0 else []
    for w in zero + pos_roots(cross):
        k = np.polyval(M, 1j * w) / np.polyval(D0, 1j * w)
        if k.real < 0 and 1 / abs(k) < gm:
            gm, wpc = 1 / abs(k), w
    pm, wgc = np.inf, np.nan
    for w in pos_roots(mag):
        k = np.polyval(M, 1j * w) / np.polyval(D0, 1j * w)
        p = (np.degrees(np.angle(k)) + 180.0) % 360.0
        p = p - 360.0 if p > 180 else p
        if abs(p) < abs(pm):
            pm, wgc = p, w
    return StabilityMargins(float(gm), float(pm), float(wpc), float(wgc))
