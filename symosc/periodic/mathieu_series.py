"""Exact power series of the Mathieu characteristic values a_n(q), b_n(q) in q.

The coefficients are generated, to any order, by Rayleigh-Schrodinger perturbation theory on the Hill matrix of the
Mathieu equation y'' + (a - 2q cos 2x) y = 0 (McLachlan/DLMF convention): with H = D + q E (D the diagonal of squared
Fourier indices, E the coupling), a = sum_k alpha_k q^k and the eigenvector x = sum_k x^(k) q^k normalised by
x_n = 1 (intermediate normalisation), order k gives

    alpha_k = (E x^(k-1))_n,
    x^(k)_j = (sum_{i=1..k} alpha_i x^(k-i)_j - (E x^(k-1))_j) / (d_j - d_n),   j != n.

The Fourier indices inside each parity class are distinct, so the denominators never vanish, and everything stays in
exact rational arithmetic (``fractions.Fraction``; converted to SymPy ``Rational`` on output).  The non-symmetric
form of the Hill matrix (first coupling 2q instead of sqrt(2) q for the even cosine class) keeps the coefficients
rational.

Radius of convergence (not large): a_0 and a_2 meet at the branch points q = +-1.4688i, so the series of a_0 converges
only for ``|q| < 1.4688`` (Meixner & Schafke 1954; Mulholland & Goldstein 1929); :func:`mathieu_series_radius` estimates
the radius for any n from the coefficients themselves.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import mpmath
import sympy

from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ConvergenceError, ParameterError
from ._hill import family_index

__all__ = ["SeriesValue", "mathieu_series_a", "mathieu_series_b", "mathieu_series_radius", "mathieu_series_value"]

_CACHE: dict[tuple[str, int], tuple[Fraction, ...]] = {}


def _check_n(kind: str, n) -> int:
    if isinstance(n, bool) or (not isinstance(n, int | float) and not hasattr(n, "__index__")):
        raise ParameterError(f"order n must be a non-negative integer, got {n!r}")
    try:
        ni = int(n)
    except (TypeError, ValueError, OverflowError):
        raise ParameterError(f"order n must be a non-negative integer, got {n!r}") from None
    if ni != n or ni < 0:
        raise ParameterError(f"order n must be a non-negative integer, got {n!r}")
    if kind == "b" and ni == 0:
        raise ParameterError("b_0 does not exist (sin-type solutions start at n = 1); use n >= 1 for b_n")
    return ni


def _check_order(order) -> int:
    if isinstance(order, bool) or not hasattr(order, "__index__"):
        raise ParameterError(f"series order must be a non-negative integer (highest power of q kept), got {order!r}")
    order = int(order)
    if order < 0:
        raise ParameterError(f"series order must be a non-negative integer (highest power of q kept), got {order!r}")
    if order > _MAX_ORDER:
        raise ParameterError(
            f"series order {order} is beyond the supported range (<= {_MAX_ORDER}): exact Rational coefficients cost "
            "about order**4 (order 100 ~2 s, 150 ~9 s, 300 over a minute); the series converges only for "
            "|q| below ~1.47 (a_0), where order 60 already reaches double precision; use mathieu_characteristic"
        )
    return order


#: largest series order accepted (see the error message for the cost)
_MAX_ORDER = 150


def _generate(kind: str, n: int, order: int) -> tuple[Fraction, ...]:
    """Coefficients alpha_0..alpha_order of the series of kind_n(q), exact."""
    fam, k = family_index(kind, n)
    size = k + order + 2
    d = [(2 * j + fam.offset) ** 2 for j in range(size)]
    zero = Fraction(0)

    def apply_e(x: list[Fraction], lo: int, hi: int) -> dict[int, Fraction]:
        # (E x)_j for j in [lo, hi]; x is supported inside [lo + 1, hi - 1]
        out = {}
        for j in range(max(lo, 0), min(hi, size - 1) + 1):
            s = zero
            if j > 0:
                s += (2 if (fam.sqrt2 and j == 1) else 1) * x[j - 1]
            if j + 1 < size:
                s += x[j + 1]
            if j == 0 and fam.q_sign:
                s += fam.q_sign * x[0]
            out[j] = s
        return out

    x0 = [zero] * size
    x0[k] = Fraction(1)
    xs = [x0]
    alpha = [Fraction(d[k])]
    for kk in range(1, order + 1):
        ex = apply_e(xs[kk - 1], k - kk, k + kk)
        alpha.append(ex.get(k, zero))
        x = [zero] * size
        for j in range(max(0, k - kk), min(size - 1, k + kk) + 1):
            if j == k:
                continue
            s = -ex.get(j, zero)
            for i in range(1, kk + 1):
                xv = xs[kk - i][j]
                if xv and alpha[i]:
                    s += alpha[i] * xv
            x[j] = s / (d[j] - d[k])
        xs.append(x)
    return tuple(alpha)


def _coefficients(kind: str, n: int, order: int) -> tuple[Fraction, ...]:
    key = (kind, n)
    have = _CACHE.get(key)
    if have is None or len(have) <= order:
        have = _generate(kind, n, order)
        _CACHE[key] = have
    return have[: order + 1]


def _series(kind: str, n, order, symbol) -> sympy.Expr:
    n = _check_n(kind, n)
    order = _check_order(order)
    q = sympy.Symbol("q") if symbol is None else symbol
    coeffs = _coefficients(kind, n, order)
    return sympy.Add(
        *[sympy.Rational(c.numerator, c.denominator) * q**j for j, c in enumerate(coeffs) if c],
    )


@validated
def mathieu_series_a(n: int, order: int, *, symbol: sympy.Symbol | None = None) -> sympy.Expr:
    """Power series of the characteristic value a_n(q) up to and including q**order, exact.

    Parameters
    ----------
    n : int
        Index of the characteristic value (n >= 0), McLachlan/DLMF convention y'' + (a - 2q cos 2x) y = 0.
    order : int
        Highest power of q kept.
    symbol : sympy.Symbol, optional
        Variable of the polynomial; ``Symbol("q")`` by default.

    Returns
    -------
    sympy.Expr
        Polynomial in q with ``Rational`` coefficients (generated by a perturbation recurrence, see the module
        docstring).

    Examples
    --------
    The series (8) of Gribkov & Khokhlov (2015), quoted from McLachlan:

    >>> mathieu_series_a(0, 8)
    68687*q**8/18874368 - 29*q**6/2304 + 7*q**4/128 - q**2/2
    >>> mathieu_series_a(1, 3)
    -q**3/64 - q**2/8 + q + 1
    """
    return _series("a", n, order, symbol)


@validated
def mathieu_series_b(n: int, order: int, *, symbol: sympy.Symbol | None = None) -> sympy.Expr:
    """Power series of the characteristic value b_n(q) (n >= 1) up to and including q**order, exact.

    Parameters
    ----------
    n : int
        Index (n >= 1; b_0 does not exist).
    order : int
        Highest power of q kept.
    symbol : sympy.Symbol, optional
        Variable of the polynomial; ``Symbol("q")`` by default.

    Returns
    -------
    sympy.Expr
        Polynomial in q with ``Rational`` coefficients.

    Examples
    --------
    The q**8 coefficient of b_1 is -83/35389440 (DLMF 28.6.4), not -265/113246208 as printed in Gribkov &
    Khokhlov (2015), formula (9):

    >>> sympy.Poly(mathieu_series_b(1, 8)).all_coeffs()[0]
    -83/35389440
    >>> mathieu_series_b(2, 4)
    5*q**4/13824 - q**2/12 + 4
    """
    return _series("b", n, order, symbol)


@dataclass(frozen=True)
class SeriesValue(SymPyPrintable):
    """A numeric value of a truncated Mathieu series and what was achieved.

    Attributes
    ----------
    value : float or mpmath.mpf
        Sum of the series up to ``order``.
    error_estimate : float
        Estimated truncation error (first omitted terms, geometric tail).
    order : int
        Highest power of q used.
    converged : bool
        Whether ``error_estimate <= tol * max(1, |value|)``.
    """

    value: float | mpmath.mpf
    error_estimate: float
    order: int
    converged: bool

    def __repr__(self) -> str:
        return (
            f"SeriesValue(value={float(self.value)!r}, error_estimate={self.error_estimate:.3g}, "
            f"order={self.order}, converged={self.converged})"
        )


def _growth(coeffs: tuple[Fraction, ...]) -> float:
    """Per-power growth factor 1/R of the coefficients, from their envelope over the last half of the orders.

    The largest |c_j| in the windows (o/2, 3o/4] and (3o/4, o] are compared: robust to the sign and magnitude
    oscillation that complex-conjugate branch points cause (odd-index families).
    """
    o = len(coeffs) - 1
    windows = [(o // 2, (3 * o) // 4), ((3 * o) // 4, o)]
    peaks = []
    for lo, hi in windows:
        cand = [(math.log(abs(c)), j) for j, c in enumerate(coeffs) if c and lo < j <= hi]
        if not cand:
            return 0.0
        peaks.append(max(cand))
    (l1, j1), (l2, j2) = peaks
    if j2 == j1:  # pragma: no cover - windows are disjoint
        return 0.0
    # square-root branch points give |c_j| ~ C R^-j j^(-3/2): remove the power-law factor before the ratio
    return math.exp((l2 - l1 + 1.5 * math.log(j2 / j1)) / (j2 - j1))


@validated
def mathieu_series_value(
    kind: str, n: int, q, *, order: int | None = None, tol: float = 1e-13, max_order: int = 100, dps=None
) -> SeriesValue:
    """Evaluate the exact series of a_n or b_n at a number q, choosing the order for ``tol``.

    Parameters
    ----------
    kind : {"a", "b"}
        Which characteristic value: ``"a"`` (``a_n``, even solutions) or ``"b"`` (``b_n``, odd solutions).
    n : int
        Index of the characteristic value, an integer >= 0 for ``"a"`` and >= 1 for ``"b"``.
    q : float, mpmath.mpf or str
        Point (any real; the series is a polynomial in q, valid for ``|q|`` below the radius of convergence); with
        ``dps``, an ``mpf`` or a decimal string keeps every digit.
    order : int, optional
        Fixed order; by default the smallest of 8, 16, 32, ... up to ``max_order`` whose error estimate is below
        ``tol * max(1, |value|)``.
    tol : float
        Target error (relative where ``|value| >= 1``, absolute below).
    max_order : int
        Largest order tried when ``order`` is not given.
    dps : int, optional
        Evaluate in mpmath at this many digits (value is an ``mpf``); default float64.

    Returns
    -------
    SeriesValue

    Raises
    ------
    ConvergenceError
        When ``order`` is not given and no order up to ``max_order`` reaches ``tol`` (q too close to or beyond the
        radius of convergence).

    See Also
    --------
    mathieu_series_a
    mathieu_series_radius
    mathieu_a

    Examples
    --------
    >>> r = mathieu_series_value("a", 0, 0.5)
    >>> round(r.value, 12), r.converged
    (-0.121765544941, True)
    """
    if kind not in ("a", "b"):
        raise ParameterError(f"kind must be 'a' or 'b', got {kind!r}")
    n = _check_n(kind, n)
    orders = [_check_order(order)] if order is not None else [o for o in (8, 16, 32, 64) if o < max_order]
    if order is None:
        orders.append(max_order)
    for o in orders:
        coeffs = _coefficients(kind, n, o)
        if dps is None:
            qq, total = float(q), 0.0
            for c in reversed(coeffs):
                total = total * qq + c.numerator / c.denominator
        else:
            with mpmath.workdps(dps + 5):
                qq, total = mpmath.mpf(q), mpmath.mpf(0)
                for c in reversed(coeffs):
                    total = total * qq + mpmath.mpf(c.numerator) / c.denominator
        rho = abs(float(q)) * _growth(coeffs) if o >= 8 else math.nan
        # size of the last terms: the largest in the final quarter of the orders (robust to oscillating signs)
        last = max(
            (abs(float(c)) * abs(float(q)) ** j for j, c in enumerate(coeffs) if c and j > max(0, (3 * o) // 4)),
            default=0.0,
        )
        rounding = 0.0 if dps is not None else 4e-16 * abs(float(total))
        if o < 8:  # too few coefficients for a growth rate: the last terms themselves are the estimate
            err = last + rounding
        else:
            err = math.inf if rho >= 0.95 else last * rho / (1 - rho) + rounding
        ok = err <= tol * max(1.0, abs(float(total)))
        if ok or order is not None:
            return SeriesValue(total, err, o, ok)
        if o >= 32 and rho >= 1.0:  # |q| clearly beyond the radius: higher orders cannot help
            break
    raise ConvergenceError(
        f"the power series of {kind}_{n}(q) does not reach tol={tol:g} at q={float(q)!r} with order <= {max_order} "
        f"(error estimate {err:.3g}; |q| is too close to the radius of convergence "
        f"~{mathieu_series_radius(kind, n):.4g}); use method='auto'",
        achieved=err,
    )


@validated
def mathieu_series_radius(kind: str, n: int, order: int = 60) -> float:
    """Estimate the radius of convergence of the series of a_n or b_n from its coefficients.

    Ratio test on the envelope of the coefficients over the last half of the orders: ``R ~ |c_i / c_j|^(1/(j-i))``
    with i, j the largest coefficients in (order/2, 3 order/4] and (3 order/4, order], corrected for the
    j^(-3/2) law of square-root branch points.  An estimate: good to ~1 % for a_0 (1.4688, the branch point
    q = 1.4688i where a_0 meets a_2), a few per cent when complex branch points make the coefficients oscillate.

    Parameters
    ----------
    kind : {"a", "b"}
        Which characteristic value: ``"a"`` (``a_n``, even solutions) or ``"b"`` (``b_n``, odd solutions).
    n : int
        Index of the characteristic value, an integer >= 0 for ``"a"`` and >= 1 for ``"b"``.
    order : int
        Highest power of ``q`` whose coefficient is used, an integer between 0 and 150; below about 8 there are
        too few non-zero coefficients for the estimate and ``inf`` is returned.

    Returns
    -------
    float
        The estimated radius of convergence in ``q`` (``inf`` when the estimate is not possible).

    See Also
    --------
    mathieu_series_a, mathieu_series_b

    Examples
    --------
    >>> round(mathieu_series_radius("a", 0), 2)
    1.47
    """
    n = _check_n(kind, n)
    g = _growth(_coefficients(kind, n, _check_order(order)))
    return math.inf if g == 0 else 1.0 / g
