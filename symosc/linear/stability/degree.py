"""Degree of stability and the Tsypkin–Bromberg shift (Bulgakov (1954), §8.22, eqs. (8.127)–(8.135))."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ParameterError
from .._util import as_coefficients, is_numeric
from .criteria import StabilityVerdict, hurwitz

__all__ = ["StabilityDegree", "hurwitz_at_degree", "shifted_coefficients", "stability_degree"]


@validated
def shifted_coefficients(coefficients: Any, delta: Any) -> tuple:
    """Coefficients ``K0 … Ks`` of ``Δ(-δ + x)`` (Bulgakov (1954), eq. (8.129)), exact Taylor shift.

    ``K_j = Δ^(s-j)(-δ)/(s-j)!``; all roots of the original polynomial lie left of ``Re λ = -δ`` iff the shifted
    polynomial is Hurwitz.

    Parameters
    ----------
    coefficients : sequence or sympy.Poly
        Coefficients ``k0, ..., ks`` highest power first (numbers or SymPy expressions, ``k0 != 0``, at least two).
    delta : number or sympy.Expr
        The shift ``δ`` (the degree of stability to test); a real number or a symbol.

    Returns
    -------
    tuple of sympy.Expr
        ``K0, ..., Ks`` highest power first.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import shifted_coefficients
    >>> k0, k1, k2, k3, d = sp.symbols("k0:4 delta")
    >>> shifted_coefficients([k0, k1, k2, k3], d)[3]      # (8.133)
    -delta**3*k0 + delta**2*k1 - delta*k2 + k3

    See Also
    --------
    stability_degree, hurwitz_at_degree
    """
    k = as_coefficients(coefficients)
    x = sp.Dummy("x")
    poly = sp.Poly(sum(c * x ** (len(k) - 1 - i) for i, c in enumerate(k)), x)
    shifted = sp.Poly(poly.as_expr().subs(x, x - sp.sympify(delta)), x)
    out = shifted.all_coeffs()
    return tuple(sp.expand(c) for c in [0] * (len(k) - len(out)) + out)


@validated
def hurwitz_at_degree(coefficients: Any, delta: Any, *, tol: float = 1e-9) -> StabilityVerdict:
    """Hurwitz conditions for the shifted polynomial: every root has ``Re λ < -δ`` (Tsypkin–Bromberg, §8.22).

    Parameters
    ----------
    coefficients : sequence or sympy.Poly
        Coefficients ``k0, ..., ks`` highest power first (numbers or SymPy expressions, ``k0 != 0``, at least two).
    delta : number or sympy.Expr
        The required degree of stability ``δ``; a real number or a symbol.
    tol : float, optional
        Relative tolerance (> 0 and < 1) for flagging a numeric verdict as ``near_boundary``.

    Returns
    -------
    StabilityVerdict

    Examples
    --------
    >>> from symosc.linear import hurwitz_at_degree
    >>> hurwitz_at_degree([1, 3, 3, 1], 0.5).stable, hurwitz_at_degree([1, 3, 3, 1], 1).stable
    (True, False)

    See Also
    --------
    shifted_coefficients, stability_degree
    """
    return hurwitz(shifted_coefficients(coefficients, delta), tol=tol)


@dataclass(frozen=True)
class StabilityDegree(SymPyPrintable):
    """Result of :func:`stability_degree`.

    Attributes
    ----------
    degree : float
        ``δ = -max Re λ`` (positive for an asymptotically stable polynomial).
    dominant_roots : tuple of complex
        The roots attaining ``max Re λ``.
    roots : tuple of complex
        All roots (mpmath, polished).
    error_estimate : float
        Bound on the error of ``degree`` from the root finder.
    """

    degree: float
    dominant_roots: tuple
    roots: tuple
    error_estimate: float

    def __repr__(self) -> str:
        return f"StabilityDegree(degree={self.degree:.12g}, dominant_roots={list(self.dominant_roots)})"

    def plot(self, *, ax=None):
        """Roots in the complex plane with the line ``Re λ = -δ``; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        ax.plot([r.real for r in self.roots], [r.imag for r in self.roots], "x")
        ax.axvline(-self.degree, ls="--", color="C1", label=f"Re λ = −δ = {-self.degree:.4g}")
        ax.axvline(0, color="k", lw=0.5)
        ax.set_xlabel("Re λ")
        ax.set_ylabel("Im λ")
        ax.legend()
        return ax


@validated
def stability_degree(coefficients: Any, *, tol: float = 1e-12) -> StabilityDegree:
    """Degree of stability ``δ = -max Re λ`` of a numeric polynomial (Bulgakov (1954), §8.22).

    Roots by mpmath ``polyroots`` with extra precision; raises ConvergenceError when ``tol`` is not reached.

    Parameters
    ----------
    coefficients : sequence or sympy.Poly
        Coefficients ``k0, ..., ks`` highest power first; real numbers (no symbols), ``k0 != 0``, at least two.
    tol : float, optional
        Largest acceptable error bound of the roots (> 0); a larger error raises ConvergenceError.

    Returns
    -------
    StabilityDegree

    Examples
    --------
    >>> from symosc.linear import stability_degree
    >>> round(stability_degree([1, 4, 16, 64]).degree, 12) + 0.0    # roots -4, ±4i
    0.0

    See Also
    --------
    hurwitz_at_degree, shifted_coefficients
    """
    import mpmath

    k = as_coefficients(coefficients)
    if not is_numeric(k):
        raise ParameterError("stability_degree needs numbers; use hurwitz_at_degree for symbolic coefficients")
    with mpmath.workdps(40):
        try:
            roots, err = mpmath.polyroots(
                [mpmath.mpf(sp.Float(c, 40)) for c in k], maxsteps=200, extraprec=200, error=True
            )
            roots = [complex(r) for r in (roots if isinstance(roots, list) else [roots])]
            err = float(err)
        except mpmath.libmp.NoConvergence:
            # multiple roots: companion eigenvalues with the rigorous bound min|z - λ_j| <= (|p(z)|/|k0|)^(1/s)
            import numpy as np

            kf = [float(c) for c in k]
            roots = [complex(r) for r in np.roots(kf)]
            s = len(kf) - 1
            err = max(
                float(abs(mpmath.polyval([mpmath.mpf(c) for c in kf], mpmath.mpc(r))) / abs(kf[0])) ** (1 / s)
                for r in roots
            )
    if err > tol:
        raise ConvergenceError(
            f"the roots are known only to {err:.3g} > tol={tol:g} (multiple or clustered roots); raise tol",
            achieved=err,
        )
    top = max(r.real for r in roots)
    dom = tuple(r for r in roots if r.real >= top - max(1e3 * err, 1e-14 * (1 + abs(top))))
    return StabilityDegree(-top, dom, tuple(roots), err)


@dataclass(frozen=True)
class CubicOptimum(SymPyPrintable):
    """Result of :func:`max_stability_degree_cubic`: the best degree of stability and where it is attained.

    Attributes
    ----------
    degree : float
        The largest degree of stability ``δ*``.
    coefficients : tuple of float
        ``(k1, k2, k3) = (3δ*k0, 3δ*²k0, δ*³k0)``, the coefficients of the optimal triple root ``-δ*``.
    binding : {"k1", "k2", "k3"}
        The coefficient whose bound limits ``δ*``.
    """

    degree: float
    coefficients: tuple
    binding: str

    def __repr__(self) -> str:
        return f"CubicOptimum(degree={self.degree:.12g}, coefficients={self.coefficients}, binding={self.binding!r})"


@validated
def max_stability_degree_cubic(
    k0: float, *, k1_max: float | None = None, k2_max: float | None = None, k3_max: float | None = None
) -> CubicOptimum:
    """Largest degree of stability of ``k0 λ³ + k1 λ² + k2 λ + k3`` with bounded coefficients (§8.22, (8.138)–(8.141)).

    The optimum is the triple root ``-δ`` at ``L = (3δk0, 3δ²k0, δ³k0)``, with ``δ* = min(k1*/(3k0),
    sqrt(k2*/(3k0)), (k3*/k0)^(1/3))`` over the bounds given.

    Parameters
    ----------
    k0 : float
        Leading coefficient ``k0``; must be positive.
    k1_max, k2_max, k3_max : float, optional
        Upper bounds ``k1*, k2*, k3*`` on the other coefficients; each given bound must be positive, and at least
        one must be given.

    Returns
    -------
    CubicOptimum

    Examples
    --------
    >>> from symosc.linear import max_stability_degree_cubic
    >>> max_stability_degree_cubic(1, k1_max=3, k2_max=12)
    CubicOptimum(degree=1, coefficients=(3.0, 3.0, 1.0), binding='k1')

    See Also
    --------
    stability_degree, hurwitz_at_degree
    """
    if not (k0 and k0 > 0):
        raise ParameterError(f"k0 must be positive, got {k0}")
    cands = {}
    if k1_max is not None:
        cands["k1"] = k1_max / (3 * k0)
    if k2_max is not None:
        cands["k2"] = (k2_max / (3 * k0)) ** 0.5
    if k3_max is not None:
        cands["k3"] = (k3_max / k0) ** (1 / 3)
    if not cands or any(not (v > 0) for v in cands.values()):
        raise ParameterError("give at least one positive bound k1_max, k2_max or k3_max")
    name = min(cands, key=cands.get)
    d = cands[name]
    return CubicOptimum(d, (3 * d * k0, 3 * d**2 * k0, d**3 * k0), name)
