"""Stability boundaries and lines of equal degree of stability of regulators with delay (Bulgakov (1954), §4.16–4.17).

Time is measured in units of the delay (4.103).  Two models are covered:

* ``"callender-hartree-porter"`` (§4.16, no natural damping or restoring force): ``f(p) = p² + (ρ p + σ) e^{-p}``;
* ``"andronov-maier"`` (§4.17, no artificial damping): ``f(p) = p² + ρ p + λ + (σ - λ) e^{-p}``.

Both are affine in ``(ρ, σ)``, so the line of equal degree of stability ``s`` (all roots in ``Re p ≤ -s``, a root on
``Re p = -s``) is the D-partition boundary for the shifted axis ``p = -s + iω``: the straight line of the real root
``p = -s`` ((4.134), (4.146)) and the curve of the pair ``-s ± iω`` ((4.135), (4.147)), which start together at the
cusp where ``-s`` is a double root ((4.136), (4.148)).  ``s = 0`` gives the stability boundary (4.131)–(4.132),
(4.144)–(4.145).  The roots themselves are found by :func:`symosc.nonlinear.quasi_polynomial_roots`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError

__all__ = ["DelayStabilityLines", "delay_equal_stability_lines"]

_MODELS = ("callender-hartree-porter", "andronov-maier")


def _parts(model: str, lam: float, p: np.ndarray, k: int = 0):
    """``P0, P1, P2`` (or their k-th derivatives, k ≤ 1) with ``f = P0 + ρ P1 + σ P2``."""
    e = np.exp(-p)
    if model == "callender-hartree-porter":
        if k == 0:
            return p**2, p * e, e
        return 2 * p, (1 - p) * e, -e
    if k == 0:
        return p**2 + lam - lam * e, p, e
    return 2 * p + lam * e, np.ones_like(p), -e


@dataclass(frozen=True)
class DelayStabilityLines(SymPyPrintable):
    """Result of :func:`delay_equal_stability_lines`.

    Attributes
    ----------
    model : {"callender-hartree-porter", "andronov-maier"}
        The regulator model.
    s : float
        The degree of stability (0: the stability boundary).
    lam : float
        ``λ = l21/l0`` of the Andronov–Maier model (0 for Callender–Hartree–Porter).
    real_line : (ndarray, ndarray)
        ``(ρ, σ)`` samples of the line of the real root ``p = -s``.
    omega, rho, sigma : ndarray
        The curve of the pair ``p = -s ± iω``.
    cusp : (float, float)
        ``(ρ0, σ0)`` where ``-s`` is a double root.
    """

    model: str
    s: float
    lam: float
    real_line: tuple
    omega: np.ndarray
    rho: np.ndarray
    sigma: np.ndarray
    cusp: tuple[float, float]

    def characteristic(self, rho: float, sigma: float):
        """The quasi-polynomial ``f(p)`` at ``(ρ, σ)`` as a SymPy expression in ``p``.

        Parameters
        ----------
        rho : float
            Value of the parameter ``ρ`` (the coefficient of ``p`` in the delayed or undelayed term of the model); a
            finite number (kept exact where it is a short decimal).
        sigma : float
            Value of the parameter ``σ`` (the delayed restoring coefficient); a finite number.

        Returns
        -------
        sympy.Expr
        """
        import sympy as sp

        p = sp.Symbol("p")
        rho, sigma = sp.nsimplify(rho), sp.nsimplify(sigma)
        if self.model == "callender-hartree-porter":
            return p**2 + (rho * p + sigma) * sp.exp(-p)
        lam = sp.nsimplify(self.lam)
        return p**2 + rho * p + lam + (sigma - lam) * sp.exp(-p)

    def __repr__(self) -> str:
        return (
            f"DelayStabilityLines({self.model}, s = {self.s:.6g}: cusp (ρ0, σ0) = ({self.cusp[0]:.6g}, "
            f"{self.cusp[1]:.6g}), ω ∈ (0, {self.omega[-1]:.6g}))"
        )

    def plot(self, *, ax=None):
        """Draw the real-root line, the complex-root curve and the cusp in the ``(ρ, σ)`` plane; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        (line,) = ax.plot(self.rho, self.sigma, label=f"s = {self.s:.4g}: roots -s ± iω")
        ax.plot(*self.real_line, "--", color=line.get_color(), label="real root -s")
        ax.plot(*self.cusp, "o", color=line.get_color())
        ax.set_xlabel("ρ")
        ax.set_ylabel("σ")
        ax.legend(fontsize="small")
        return ax


@validated
def delay_equal_stability_lines(
    model: str = "callender-hartree-porter",
    s: float = 0.0,
    *,
    lam: float = 0.0,
    omega_max: float | None = None,
    n_points: int = 200,
) -> DelayStabilityLines:
    """Line of equal degree of stability ``s`` of a regulator with delay (Bulgakov (1954), §4.16–4.17).

    Parameters
    ----------
    model : {"callender-hartree-porter", "andronov-maier"}
        ``p² + (ρp + σ)e^{-p}`` (§4.16) or ``p² + ρp + λ + (σ - λ)e^{-p}`` (§4.17).
    s : float
        Degree of stability (``s = 0``: the stability boundary (4.132), (4.144)).
    lam : float
        ``λ`` of the Andronov–Maier model.
    omega_max : float, optional
        End of the complex-root curve; default: where it meets the real-root line again or runs off to infinity
        (for ``s = 0``: ``π/2`` in both models).
    n_points : int
        Number of points on the complex-root curve and on the real-root line (an integer >= 2; default 200).

    Returns
    -------
    DelayStabilityLines

    Examples
    --------
    >>> from symosc.linear import delay_equal_stability_lines
    >>> b = delay_equal_stability_lines("callender-hartree-porter", 0.0)          # (4.132): ρ = ω sin ω, σ = ω² cos ω
    >>> [round(float(v), 9) for v in (b.omega[-1], b.rho[-1], abs(b.sigma[-1]))]
    [1.570796327, 1.570796327, 0.0]
    >>> opt = delay_equal_stability_lines("callender-hartree-porter", 2 - 2**0.5)   # the optimum of §4.16 (4.138)
    >>> [round(v, 6) for v in opt.cusp]
    [0.461159, 0.079122]

    See Also
    --------
    symosc.nonlinear.quasi_polynomial_roots, symosc.nonlinear.callender_hartree_porter_optimum, d_partition
    """
    if model not in _MODELS:
        raise ParameterError(f"model must be one of {_MODELS}, got {model!r}")
    s, lam = float(s), float(lam)
    if not np.isfinite(s) or s < 0:
        raise ParameterError(f"s (the degree of stability) must be a non-negative number, got {s}")
    if model == "callender-hartree-porter" and lam != 0:
        raise ParameterError("lam applies to the Andronov-Maier model only")
    n = int(n_points)
    if n < 2:
        raise ParameterError("n_points must be at least 2")
    # cusp: f(-s) = f'(-s) = 0, linear in (ρ, σ)
    ps = np.array(-s)
    a0, a1, a2 = _parts(model, lam, ps)
    b0, b1, b2 = _parts(model, lam, ps, 1)
    M = np.array([[a1, a2], [b1, b2]], dtype=float)
    if abs(np.linalg.det(M)) < 1e-14:
        raise ParameterError(f"no double root at -s for s = {s} in this model (the cusp is at infinity); take s < 1")
    cusp = tuple(float(v) for v in np.linalg.solve(M, -np.array([a0, b0], dtype=float)))

    def solve(w: np.ndarray):
        P0, P1, P2 = _parts(model, lam, -s + 1j * w)
        det = P1.real * P2.imag - P2.real * P1.imag
        with np.errstate(divide="ignore", invalid="ignore"):  # det = 0 only at the pole the caller brackets
            rho = (-P0.real * P2.imag + P2.real * P0.imag) / det
            sig = (-P1.real * P0.imag + P0.real * P1.imag) / det
        return rho, sig, det

    def on_line(rho, sig):
        return a0 + rho * a1 + sig * a2

    if omega_max is None:
        w = np.linspace(1e-4, np.pi, 20001)
        rho, sig, det = solve(w)
        res = on_line(rho, sig) / (1 + np.abs(rho) + np.abs(sig))
        cross = (np.sign(res[1:]) != np.sign(res[:-1])) & (w[1:] > 0.05)  # not the tangency at the cusp
        bad = np.flatnonzero(cross | (np.sign(det[1:]) != np.sign(det[:-1])))
        if bad.size:
            from scipy.optimize import brentq

            j = int(bad[0])
            if np.sign(det[j + 1]) != np.sign(det[j]):
                wm = brentq(lambda x: solve(np.array(x))[2], w[j], w[j + 1], xtol=1e-14)
                wm *= 1 - 1e-2  # stop short of the pole of the curve
            else:
                wm = brentq(lambda x: float(on_line(*solve(np.array(x))[:2])), w[j], w[j + 1], xtol=1e-15)
        else:
            wm = np.pi
    else:
        wm = float(omega_max)
        if not wm > 0:
            raise ParameterError(f"omega_max must be positive, got {omega_max}")
    omega = np.linspace(0.0, wm, n)
    rho, sig = np.empty(n), np.empty(n)
    rho[1:], sig[1:], _ = solve(omega[1:])
    rho[0], sig[0] = cusp
    r_line = np.linspace(min(0.0, rho.min()), max(rho.max(), cusp[0]) * 1.2 + 1e-12, n)
    s_line = -(a0 + r_line * a1) / a2
    return DelayStabilityLines(
        model=model,
        s=s,
        lam=lam,
        real_line=(r_line, s_line),
        omega=omega,
        rho=rho,
        sigma=sig,
        cusp=cusp,
    )
