"""Response series of a second-order system with delay (Bulgakov (1954), §4.13–4.14, eqs. (4.108)–(4.120)).

In units of the delay (4.103) the equation is

``l01 y'' + l11 y' + l21 y + l02 y''(u-1) + l12 y'(u-1) + l22 y(u-1) = x(u)``

with the characteristic quasi-polynomial ``f(p) = l01 p² + l11 p + l21 + e^{-p}(l02 p² + l12 p + l22)`` (4.108).
From rest (zero history), Heaviside's expansion gives the response to a unit impulse and to a unit step as series
over the roots ``γ_j`` of ``f`` (4.112)–(4.114):

``N(u) = Σ e^{γ_j u}/f'(γ_j)``,  ``A(u) = 1/f(0) + Σ e^{γ_j u}/(γ_j f'(γ_j))``,

with the double-root term (4.113) ``(2/f'')[g' + u g - g f'''/(3f'')] e^{γu}`` (``g = 1`` or ``1/p``).  A rectangular
pulse of unit area and length ``b`` gives ``(A(u) - A(u - b))/b`` (4.117)–(4.118).  The roots come from the certified
quasi-polynomial root finder :func:`symosc.nonlinear.quasi_polynomial_roots`; the series is truncated to the roots in
the rectangle, and :attr:`DelayResponseSeries.tail` reports the size of the outermost terms.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError

__all__ = ["DelayResponseSeries", "delay_response_series"]


@dataclass(frozen=True)
class DelayResponseSeries(SymPyPrintable):
    """Result of :func:`delay_response_series`; call ``impulse(u)``, ``step(u)``, ``pulse(u, b)``.

    Attributes
    ----------
    coefficients : tuple of float
        ``(l01, l11, l21, l02, l12, l22)``.
    roots : ndarray of complex
        Distinct roots used (all roots of ``f`` in ``region``).
    multiplicities : tuple of int
        Multiplicity (1 or 2) of each root.
    region : (float, float, float, float)
        The root rectangle ``(re_min, re_max, -im_max, im_max)``.
    d1, d2, d3 : ndarray of complex
        ``f'``, ``f''``, ``f'''`` at the roots.
    f0 : float
        ``f(0)`` (the static gain of the step response is ``1/f(0)``).
    """

    coefficients: tuple
    roots: np.ndarray
    multiplicities: tuple
    region: tuple
    d1: np.ndarray
    d2: np.ndarray
    d3: np.ndarray
    f0: float

    def _sum(self, u: Any, k: int) -> np.ndarray:
        """``Σ Res[g(p) e^{pu}/f(p)]`` over the roots with ``g = p^{-k}``, for ``u > 0``."""
        u = np.atleast_1d(np.asarray(u, dtype=float))
        out = np.zeros(u.shape, dtype=complex)
        for g, m, f1, f2, f3 in zip(self.roots, self.multiplicities, self.d1, self.d2, self.d3, strict=True):
            e = np.exp(g * u)
            gv = g ** (-k)
            if m == 1:
                out += gv / f1 * e
            else:
                dg = -k * g ** (-k - 1)
                out += (2 / f2) * (dg + u * gv - gv * f3 / (3 * f2)) * e
        return out.real

    def impulse(self, u: Any) -> np.ndarray:
        """Response ``N(u)`` to a unit impulse at ``u = 0`` (4.114); zero for ``u < 0``.

        Parameters
        ----------
        u : float or array_like
            Time(s) ``u = t/τ`` in units of the delay; real numbers.  The series converges for ``u > 0`` and is
            accurate there only once ``tail(u)`` is small.
        """
        u = np.atleast_1d(np.asarray(u, dtype=float))
        return np.where(u > 0, self._sum(np.maximum(u, 0), 0), 0.0)

    def step(self, u: Any) -> np.ndarray:
        """Response ``A(u)`` to a unit step at ``u = 0``; zero for ``u < 0``.

        Needs ``f(0) != 0``.

        Parameters
        ----------
        u : float or array_like
            Time(s) ``u = t/τ`` in units of the delay; real numbers.  The series converges for ``u > 0`` and is
            accurate there only once ``tail(u)`` is small.
        """
        if self.f0 == 0:
            raise ParameterError("f(0) = 0: the step response grows without bound (a zero root)")
        u = np.atleast_1d(np.asarray(u, dtype=float))
        return np.where(u > 0, 1 / self.f0 + self._sum(np.maximum(u, 0), 1), 0.0)

    def pulse(self, u: Any, width: float) -> np.ndarray:
        """Response to the rectangular pulse ``(1/b)[1(u) - 1(u - b)]`` of unit area (4.117)–(4.118).

        Parameters
        ----------
        u : float or array_like
            Time(s) ``u = t/τ`` in units of the delay; real numbers.
        width : float
            Length ``b`` of the pulse (in units of the delay); must be positive.
        """
        b = float(width)
        if not b > 0:
            raise ParameterError(f"width must be positive, got {width}")
        u = np.atleast_1d(np.asarray(u, dtype=float))
        return (self.step(u) - self.step(u - b)) / b

    def tail(self, u: float) -> float:
        """Sum of ``|terms|`` of the impulse series from the roots in the outer fifth of the rectangle at ``u``.

        Parameters
        ----------
        u : float
            Time ``u = t/τ`` in units of the delay at which to measure the tail; a positive number.
        """
        im_max = max(abs(self.region[2]), abs(self.region[3]))
        out = 0.0
        for g, m, f1 in zip(self.roots, self.multiplicities, self.d1, strict=True):
            if m == 1 and abs(g.imag) > 0.8 * im_max:
                out += abs(np.exp(g * u) / f1)
        return float(out)

    def __repr__(self) -> str:
        return f"DelayResponseSeries({len(self.roots)} roots in {self.region}, rightmost {self.roots[0]:.6g})"

    def plot(self, u: Any = None, *, ax=None, kind: str = "impulse"):
        """``N(u)`` (``kind="impulse"``) or ``A(u)`` (``"step"``) against ``u``; returns the Axes.

        Parameters
        ----------
        u : array_like, optional
            Times ``u = t/τ`` to plot at (positive numbers); default 400 points on ``[0.05, 10]``.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        kind : {"impulse", "step"}, optional
            Which response to draw (default ``"impulse"``).
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        u = np.linspace(0.05, 10, 400) if u is None else np.asarray(u, float)
        ax.plot(u, self.impulse(u) if kind == "impulse" else self.step(u), label=f"{kind} response (series)")
        ax.set_xlabel("u = t/τ")
        ax.legend()
        return ax


@validated
def delay_response_series(
    l01: float,
    l11: float,
    l21: float,
    l02: float,
    l12: float,
    l22: float,
    *,
    im_max: float = 60.0,
    re_min: float | None = None,
    re_max: float = 10.0,
) -> DelayResponseSeries:
    """Heaviside series of the impulse and step responses of a system with delay (Bulgakov (1954), §4.14).

    Parameters
    ----------
    l01, l11, l21, l02, l12, l22 : float
        Coefficients of (4.105) (time in units of the delay).  ``l01`` must be nonzero; ``l02 = 0`` for the
        retarded type.
    im_max : float
        Roots with ``|Im γ| < im_max`` are used; more roots make the series accurate closer to ``u = 0``.
    re_min, re_max : float
        Real extent of the root rectangle; default ``re_min = -(3 ln(1 + im_max) + 10)``.  ``re_max`` must exceed
        the real part of every root.

    Examples
    --------
    >>> from symosc.linear import delay_response_series
    >>> r = delay_response_series(1.0, 0.6, 0.5, 0.0, 0.3, 0.4, im_max=40)
    >>> round(float(r.step(200.0)[0]), 6)                  # the static gain 1/f(0) = 1/(l21 + l22)
    1.111111

    See Also
    --------
    symosc.nonlinear.quasi_polynomial_roots, delay_equal_stability_lines, linear_filter
    """
    from ...nonlinear import characteristic_quasipolynomial, quasi_polynomial, quasi_polynomial_roots

    try:
        coeffs = tuple(float(v) for v in (l01, l11, l21, l02, l12, l22))
    except (TypeError, ValueError) as exc:
        raise ParameterError("the coefficients l01 ... l22 must be real numbers") from exc
    if not np.all(np.isfinite(coeffs)):
        raise ParameterError("the coefficients l01 ... l22 must be finite")
    if coeffs[0] == 0:
        raise ParameterError("l01 (the undelayed inertia) must be nonzero; otherwise the equation is not of 2nd order")
    if abs(coeffs[3]) >= abs(coeffs[0]):
        raise ParameterError(
            "|l02| must be smaller than |l01| (a neutral equation with |l02| ≥ |l01| has roots "
            "with unbounded real parts)"
        )
    im_max = float(im_max)
    if not im_max > 0:
        raise ParameterError(f"im_max must be positive, got {im_max}")
    if re_min is None:
        re_min = -(3 * np.log1p(im_max) + 10)
    region = (float(re_min), float(re_max), -im_max, im_max)
    import sympy as sp

    expr = characteristic_quasipolynomial(*(sp.nsimplify(c) for c in coeffs))
    q = quasi_polynomial(expr)
    found = quasi_polynomial_roots(q, region)
    if any(m > 2 for m in found.multiplicities):
        raise ParameterError("a root of multiplicity > 2: (4.113) covers simple and double roots only")
    roots = found.as_array()
    if roots.size and roots.real.max() > re_max - 1e-6:
        raise ParameterError("a root lies near re_max: increase re_max")
    f0 = float(np.real(q(np.array(0.0))))
    return DelayResponseSeries(
        coefficients=coeffs,
        roots=roots,
        multiplicities=tuple(found.multiplicities),
        region=region,
        d1=q.derivative(1, roots),
        d2=q.derivative(2, roots),
        d3=q.derivative(3, roots),
        f0=f0,
    )
