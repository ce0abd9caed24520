"""Power series in the small parameter with the order reached, numeric evaluation and convergence estimates."""

from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import mpmath
import mpmath.libmp as mlib
import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ...errors import SeriesWarning
from . import _series_checks as checks

__all__ = ["EpsSeries", "RadiusEstimate"]

_ONE = sp.Integer(1)
_PREC17 = mlib.libmpf.dps_to_prec(17)
_FLOAT_ZERO = sp.Float(0.0, 17)


def to_sympy_number(value: Any, dps: int = 17) -> sp.Expr:
    """A coefficient (Fraction, mpf, float, int, SymPy) as a SymPy number."""
    if isinstance(value, Fraction):
        return sp.Rational(value.numerator, value.denominator)
    if isinstance(value, mpmath.mpf):
        return sp.Float(value, dps)
    if isinstance(value, float | np.floating):
        value = float(value)
        if value == 0.0:
            return _FLOAT_ZERO
        if math.isfinite(value):  # what Float(value, 17) builds, without its generic input handling
            return sp.Float._new(mlib.from_float(value, _PREC17, mlib.round_nearest), _PREC17, zero=False)
        return sp.Float(value, 17)
    return sp.sympify(value)


@dataclass(frozen=True)
class RadiusEstimate(SymPyPrintable):
    """Radius of convergence of a power series estimated from its coefficients.

    Attributes
    ----------
    radius : float
        The estimate in the original variable (``eps``).
    method : str
        ``"domb-sykes"`` (ratio of consecutive coefficients extrapolated linearly in 1/k: a real dominant
        singularity), ``"mercer-roberts"`` (a complex-conjugate pair of singularities) or ``"root"`` (``|c_k|^(-1/k)``).
    even : bool
        True when only even powers occur; the analysis is then done in ``eps**2``.
    singularity_on_real_axis : bool or None
        For Domb–Sykes, the sign of the ratios tells whether the nearest singularity is on the positive (+) or
        negative (-) real axis of the series variable.
    estimates : dict
        All three estimates (those that could be formed).
    terms_used : int
        Number of coefficients used.
    """

    radius: float
    method: str
    even: bool
    singularity_on_real_axis: bool | None
    estimates: dict
    terms_used: int

    def __repr__(self) -> str:
        others = ", ".join(f"{k}={v:.6g}" for k, v in self.estimates.items())
        return f"RadiusEstimate(radius={self.radius:.6g} by {self.method}; {others}; terms={self.terms_used})"


@dataclass(frozen=True)
class EpsSeries(SymPyPrintable):
    """A truncated power series ``factor * sum_k c_k eps**k + O(eps**(order+1))``.

    Attributes
    ----------
    coefficients : tuple of SymPy numbers
        ``c_0 .. c_order`` (``Rational`` in exact arithmetic, ``Float`` otherwise).
    symbol : Symbol
        The expansion variable (``eps``).
    order : int
        The order reached: every coefficient up to ``eps**order`` is exact (or accurate to the working precision).
    factor : Expr
        An overall factor (``2*pi`` for a period, an irrational generating amplitude, ...).
    name : str
        What the series is (shown in the repr).
    """

    coefficients: tuple
    symbol: sp.Symbol
    order: int
    factor: sp.Expr = _ONE
    name: str = "series"

    @property
    def expr(self) -> sp.Expr:
        """The truncated series as a SymPy expression (without the O-term)."""
        poly = sp.Add(*[c * self.symbol**k for k, c in enumerate(self.coefficients)])
        return self.factor * poly if self.factor != 1 else poly

    def _sympy_(self) -> sp.Expr:
        """``sympy.sympify(series)`` gives the truncated sum (as :meth:`removeO`)."""
        return self.expr

    def removeO(self) -> sp.Expr:
        """The truncated sum without the order term, as ``sympy.Expr.removeO``.

        Examples
        --------
        >>> import sympy as sp
        >>> from symosc.nonlinear import limit_cycle
        >>> x, v = sp.symbols("x v")
        >>> w = limit_cycle((1 - x**2) * v, 2).frequency
        >>> w.removeO(), w.getO(), sp.sympify(w) == w.removeO()
        (1 - eps**2/16, O(eps**3), True)
        >>> w.as_series()
        1 - eps**2/16 + O(eps**3)
        """
        return self.expr

    def getO(self) -> sp.Order:
        """The order term ``O(eps**(order + 1))``."""
        return sp.O(self.symbol ** (self.order + 1), self.symbol)

    def as_expr(self) -> sp.Expr:
        """The truncated sum (the same as :meth:`removeO`)."""
        return self.expr

    def as_series(self) -> sp.Expr:
        """The truncated sum with its order term, as ``sympy.series`` returns it."""
        return self.expr + self.getO()

    def coefficient(self, k: int) -> sp.Expr:
        """Coefficient of ``eps**k`` (including ``factor``).

        Parameters
        ----------
        k : int
            Power of ``eps`` whose coefficient is wanted; an integer from 0 to ``order`` (a larger one raises
            IndexError).
        """
        k = checks.power_index(k, self.order, self.name)
        return self.factor * self.coefficients[k]

    def evaluate(self, value: Any, order: int | None = None, *, dps: int | None = None) -> Any:
        """Numeric value of the series truncated at ``order`` (default: all terms).

        With ``dps`` the sum is formed in mpmath at that precision and an ``mpf`` is returned; otherwise a float
        (or a float array when ``value`` is an array).

        Parameters
        ----------
        value : float, mpmath.mpf or array_like of float
            Value of the expansion variable ``eps`` at which to sum the series; real numbers (an array is summed
            element by element). A ``SeriesWarning`` is issued when ``|value|`` exceeds the estimated radius of
            convergence.
        order : int, optional
            Highest power of ``eps`` kept in the sum, an integer >= 0; all known terms when omitted (values above
            ``self.order`` are clipped to it).
        dps : int, optional
            Decimal digits of the mpmath working precision, an integer >= 1; when given the sum is formed in mpmath
            and an ``mpf`` is returned, otherwise in float64.
        """
        value, order, dps = checks.point(value), checks.optional_count("order", order, 0), checks.dps(dps)
        n = self.order if order is None else min(int(order), self.order)
        _warn_beyond_radius(self, value, n)
        if dps is not None:
            with mpmath.workdps(dps):
                x = mpmath.mpf(value) if not isinstance(value, mpmath.mpf) else value
                acc = mpmath.mpf(0)
                for c in reversed(self.coefficients[: n + 1]):
                    acc = acc * x + mpmath.mpf(sp.N(c, dps + 5))
                return acc * mpmath.mpf(sp.N(self.factor, dps + 5))
        x = np.asarray(value, dtype=float)
        acc = np.zeros_like(x)
        for c in reversed(self.coefficients[: n + 1]):
            acc = acc * x + float(c)
        out = acc * float(self.factor)
        return float(out) if out.ndim == 0 else out

    __call__ = evaluate

    def evaluate_pade(self, value: Any, m: int | None = None, n: int | None = None, *, dps: int | None = None) -> Any:
        """Diagonal (or ``[m/n]``) Padé approximant of the series at ``value`` (mpmath.pade).

        For a series in even powers only the approximant is built in ``eps**2``.  Padé continues the series beyond
        its radius of convergence when the nearest singularities are poles or branch points off the real axis, as for
        van der Pol (there ``[10/10]`` in ``eps**2`` gives the frequency at ``eps = 3`` to 1e-5).

        Parameters
        ----------
        value : float or mpmath.mpf
            Value of the expansion variable ``eps`` at which to evaluate the approximant; a real number.
        m : int, optional
            Degree of the numerator, an integer >= 0 with ``m + n`` at most the number of coefficients less one
            (counted in ``eps**2`` for an even series); ``N - n`` when omitted, and ``N // 2`` (diagonal) when both
            degrees are omitted.
        n : int, optional
            Degree of the denominator, an integer >= 0 with ``m + n`` at most the number of coefficients less one;
            ``N - m`` when omitted, and ``N - N // 2`` when both degrees are omitted.
        dps : int, optional
            Decimal digits of the mpmath working precision, an integer >= 1; when given an ``mpf`` is returned,
            otherwise a float computed at 30 digits.
        """
        value, dps = checks.point(value), checks.dps(dps)
        work = dps or 30
        with mpmath.workdps(work + 10):
            cs = [mpmath.mpf(sp.N(c, work + 10)) for c in self.coefficients]
            even = len(cs) > 4 and all(c == 0 for c in cs[1::2])
            seq = cs[::2] if even else cs
            m, n = checks.pade_degrees(m, n, len(seq) - 1)
            try:
                p, q = mpmath.pade(seq[: m + n + 1], m, n)
            except ZeroDivisionError:
                raise checks.no_pade(self.name, m, n) from None
            x = mpmath.mpf(value)
            u = x * x if even else x
            val = mpmath.polyval(p[::-1], u) / mpmath.polyval(q[::-1], u) * mpmath.mpf(sp.N(self.factor, work + 10))
            return +val if dps is not None else float(val)

    def radius_of_convergence(self, terms: int | None = None) -> RadiusEstimate:
        """Estimate the radius of convergence from the last coefficients (Domb–Sykes / Mercer–Roberts / root test).

        Uses the coefficients in the variable ``eps**2`` when the odd ones vanish.  The method chosen is the one whose
        underlying assumption fits: Domb–Sykes when the ratios keep one sign pattern, Mercer–Roberts when they oscillate
        irregularly (complex singularities).

        Parameters
        ----------
        terms : int, optional
            Number of trailing coefficients (of the series in ``eps``, or in ``eps**2`` for an even series) used by
            the ratio fits, a positive integer (fewer than 3 usable ratios leave only the root test); half of them,
            and at least 6, when omitted.
        """
        terms = checks.optional_count("terms", terms, 1)
        cs = [mpmath.mpf(sp.N(c, 30)) for c in self.coefficients]
        even = all(c == 0 for c in cs[1::2]) and len(cs) > 4
        seq = cs[::2] if even else cs
        # drop leading zeros; need enough terms
        idx = [k for k, c in enumerate(seq) if c != 0]
        if len(idx) < 6:
            raise checks.too_short(len(idx))
        kmax = len(seq) - 1
        m = terms or max(6, (kmax + 1) // 2)
        ks = [k for k in range(max(2, kmax - m + 1), kmax + 1) if seq[k] != 0 and seq[k - 1] != 0]
        estimates: dict[str, float] = {}
        power = 2 if even else 1
        # root test on the last coefficient
        last = kmax
        estimates["root"] = float(abs(seq[last]) ** (-mpmath.mpf(1) / last)) ** (1 / power)
        # Domb–Sykes: r_k = c_k / c_{k-1} ~ (1/R)(1 - g/k); fit linear in 1/k, intercept = 1/R
        ratios = [seq[k] / seq[k - 1] for k in ks]
        signs = {mpmath.sign(r) for r in ratios}
        dom_sign: bool | None = None
        if len(ks) >= 3:
            x = np.array([1.0 / k for k in ks])
            y = np.array([float(r) for r in ratios])
            _slope, icpt = np.polyfit(x, y, 1)
            if icpt != 0:
                estimates["domb-sykes"] = abs(1.0 / icpt) ** (1 / power)
                dom_sign = bool(icpt > 0)
        # Mercer–Roberts: B_k^2 = (c_{k+1} c_{k-1} - c_k^2)/(c_k c_{k-2} - c_{k-1}^2), fit linear in 1/k
        mr_k, mr_v = [], []
        for k in range(max(3, kmax - m + 1), kmax):
            den = seq[k] * seq[k - 2] - seq[k - 1] ** 2
            num = seq[k + 1] * seq[k - 1] - seq[k] ** 2
            if den != 0 and num / den > 0:
                mr_k.append(1.0 / k)
                mr_v.append(float(mpmath.sqrt(num / den)))
        if len(mr_k) >= 3:
            _slope, icpt = np.polyfit(np.array(mr_k), np.array(mr_v), 1)
            if icpt > 0:
                estimates["mercer-roberts"] = (1.0 / icpt) ** (1 / power)
        if len(signs) == 1 or all(a * b > 0 for a, b in zip(ratios[::2], ratios[2::2], strict=False)):
            method = "domb-sykes" if "domb-sykes" in estimates else "root"
        else:
            method = "mercer-roberts" if "mercer-roberts" in estimates else "root"
        return RadiusEstimate(
            radius=estimates[method],
            method=method,
            even=even,
            singularity_on_real_axis=dom_sign if method == "domb-sykes" else None,
            estimates=estimates,
            terms_used=len(ks),
        )

    def __repr__(self) -> str:
        return f"{self.name} = {self.expr} + O({self.symbol}**{self.order + 1})"

    def _repr_latex_(self) -> str:
        return f"${sp.latex(self.expr)} + O\\left({sp.latex(self.symbol ** (self.order + 1))}\\right)$"


@functools.lru_cache(maxsize=256)
def _radius(coefficients: tuple) -> float | None:
    series = EpsSeries(coefficients, sp.Symbol("eps"), len(coefficients) - 1)
    try:
        return float(series.radius_of_convergence().radius)
    except (ValueError, ArithmeticError):
        return None


def _warn_beyond_radius(series: EpsSeries, value: Any, n: int) -> None:
    """SeriesWarning when ``|value|`` exceeds the estimated radius of convergence of ``series``, or when the sum to
    order ``n`` has not converged there (judged by its tail)."""
    try:
        size = float(np.max(np.abs(np.asarray(value, dtype=complex))))
    except (TypeError, ValueError):
        return
    if not np.isfinite(size) or size == 0:
        return
    radius = _radius(tuple(series.coefficients))
    if radius is not None and np.isfinite(radius) and size > radius:
        warnings.warn(
            f"{series.name} evaluated at |{series.symbol}| = {size:.4g}, beyond its estimated radius of convergence "
            f"{radius:.4g}: the truncated sum is not meaningful there (use evaluate_pade, or a numeric method)",
            SeriesWarning,
            stacklevel=3,
        )
    else:
        checks.warn_slow_tail(series, value, n)
