"""Argument checks of :class:`EpsSeries` methods and the truncation error of a summed series (private).

The error of ``sum_{k <= n} c_k x^k`` is estimated from its tail: the known terms beyond ``n`` (when the sum stops
below the order reached) plus a geometric continuation of the last terms, ``|t_N| q/(1 - q)`` (terms of one
sign) or ``|t_N| q/(1 + q)`` (alternating terms), ``q`` the median ratio per order of the last nonzero terms.
The estimate judges convergence where the evaluation happens, independently of the radius estimate: just inside
an estimated radius the terms may shrink too slowly for the sum to mean anything.
"""

from __future__ import annotations

import functools
import itertools
import math
from typing import Any

import mpmath
import numpy as np

from ..._validate import check_finite_array, check_int
from ...errors import ConvergenceError, ParameterError, SeriesWarning, warn

#: a truncated sum is flagged when its terms shrink by less than this factor per order ...
SLOW_RATIO = 0.5
#: ... and its estimated truncation error exceeds this fraction of its value (or when the terms do not shrink)
TAIL_RTOL = 1e-6
#: nonzero trailing terms the ratio is fitted over
_WINDOW = 6


class BeyondOrderError(ParameterError, IndexError):
    """A coefficient beyond the order a series was computed to (an ``IndexError`` too, as before)."""


def power_index(k: Any, order: int, name: str) -> int:
    """``k`` as the power of a known coefficient, ``0 <= k <= order``."""
    k = check_int("k (power of eps)", k, minimum=0)
    if k > order:
        raise BeyondOrderError(f"{name} is known to order {order} only; recompute with order >= {k}")
    return k


def optional_count(name: str, value: Any, minimum: int) -> int | None:
    """None, or ``value`` as an int >= ``minimum``."""
    return None if value is None else check_int(name, value, minimum=minimum)


def point(value: Any) -> Any:
    """The expansion variable's value: a finite real number or array (an ``mpf`` passes unchanged)."""
    if isinstance(value, mpmath.mpf):
        if not mpmath.isfinite(value):
            raise ParameterError(f"value (of eps) must be finite, got {value}")
        return value
    checked = check_finite_array("value (of eps)", value)
    return value if checked.ndim == 0 and not isinstance(value, np.ndarray) else checked


def pade_degrees(m: int | None, n: int | None, available: int) -> tuple[int, int]:
    """Numerator and denominator degrees of a Padé approximant from ``available + 1`` coefficients."""
    m = optional_count("m (numerator degree)", m, 0)
    n = optional_count("n (denominator degree)", n, 0)
    if m is None and n is None:
        m = available // 2
        n = available - m
    elif m is None:
        m = available - n
    elif n is None:
        n = available - m
    if m < 0 or n < 0 or m + n > available:
        raise ParameterError(
            f"the [{m}/{n}] Padé approximant needs m + n <= {available} (the coefficients known, less one): "
            "choose smaller degrees m, n or compute the series to a higher order"
        )
    return m, n


def dps(value: Any) -> int | None:
    """None, or the digits of the mpmath working precision (an int >= 1)."""
    return optional_count("dps", value, 1)


def no_pade(name: str, m: int, n: int) -> ParameterError:
    return ParameterError(
        f"the [{m}/{n}] Padé approximant of {name} does not exist (a singular linear system): choose other degrees m, n"
    )


def too_short(nonzero: int) -> ConvergenceError:
    return ConvergenceError(
        f"too few nonzero coefficients ({nonzero}) to estimate the radius of convergence (need >= 6): compute the "
        "series to a higher order"
    )


@functools.lru_cache(maxsize=256)
def _floats(coefficients: tuple) -> list[float] | None:
    try:
        cs = [float(c) for c in coefficients]
    except (TypeError, ValueError):
        return None
    return cs if all(math.isfinite(c) for c in cs) else None


def truncation_error(coefficients: tuple, n: int, x: float) -> tuple[float, float] | None:
    """``(error, q)``: estimated error of the sum to order ``n`` at ``x`` and the ratio per order of the last terms
    (``inf`` error when they do not shrink); None when the tail gives no judgement (fewer than three nonzero terms
    among the last ones, or coefficients that are not numbers)."""
    cs = _floats(coefficients)
    if cs is None or x == 0:
        return None
    known = abs(math.fsum(c * x**k for k, c in enumerate(cs[n + 1 :], start=n + 1)))
    last = [k for k, c in enumerate(cs) if c != 0 and k > 0][-_WINDOW:]
    if len(last) < 3 or last[-1] < len(cs) - 2 * (last[-1] - last[-2]) - 1:  # a polynomial: the tail is zero
        return (known, 0.0) if n < len(cs) - 1 else None
    with np.errstate(over="ignore", under="ignore"):
        terms = [cs[k] * x**k for k in last]
        mags = [abs(t) for t in terms]
    if not all(math.isfinite(m) and m > 0 for m in mags):
        return None
    # the median ratio per order of consecutive terms (one coefficient close to zero does not decide it)
    steps = zip(itertools.pairwise(mags), itertools.pairwise(last), strict=True)
    q = float(np.median([(b / a) ** (1.0 / (j - i)) for (a, b), (i, j) in steps]))
    step = q ** (last[-1] - last[-2])  # ratio from one nonzero term to the next
    if step >= 1:
        return math.inf, q
    alternating = all(a * b < 0 for a, b in itertools.pairwise(terms))
    beyond = mags[-1] * step / ((1 + step) if alternating else (1 - step))
    return known + beyond, q


def warn_slow_tail(series: Any, value: Any, n: int) -> None:
    """SeriesWarning, with the estimated error, when the sum to order ``n`` has not converged at ``value``: its
    terms do not shrink, or shrink by less than ``SLOW_RATIO`` per order while the estimated error exceeds
    ``TAIL_RTOL`` of the value."""
    try:
        xs = np.atleast_1d(np.asarray(value, dtype=float))
    except (TypeError, ValueError):
        return
    if xs.size == 0:
        return
    # the ends of the range: the largest positive and the most negative value (alternation depends on the sign)
    worst = None
    for x in {float(xs.max()), float(xs.min())}:
        found = truncation_error(tuple(series.coefficients), n, x)
        if found is None:
            continue
        error, q = found
        size = abs(math.fsum(c * x**k for k, c in enumerate(_floats(tuple(series.coefficients))[: n + 1])))
        slow = not math.isfinite(error) or (q > SLOW_RATIO and error > TAIL_RTOL * max(size, 1e-300))
        if slow and (worst is None or error / max(size, 1e-300) > worst[1] / max(worst[3], 1e-300)):
            worst = (x, error, q, size)
    if worst is None:
        return
    x, error, q, size = worst
    factor = abs(float(series.factor)) if series.factor.is_number else 1.0
    what = (
        "its terms do not decrease there"
        if not math.isfinite(error)
        else f"each order multiplies its terms by only about {q:.3g} there: the estimated truncation error is "
        f"{error * factor:.2g} (relative {error / max(size, 1e-300):.2g})"
    )
    warn(
        f"{series.name} summed to order {n} at {series.symbol} = {x:.4g} has not converged: {what}; raise the order, "
        "use evaluate_pade, or a numeric method",
        SeriesWarning,
    )
