"""Own initial approximations of a_n, b_n and the ordering clamp of nearly degenerate neighbours.

References: the independent Sturm bisection in mpmath of ``test_mathieu.reference_value``; the chain
a_0 <= b_1 <= a_1 <= b_2 <= ... (McLachlan 1947, section 2.151; DLMF 28.2(v)).
"""

from __future__ import annotations

import functools

import mpmath
import numpy as np
import pytest
import scipy.special

from symosc.periodic import _hill_c, _mathieu_seed, mathieu_a, mathieu_b

from .test_mathieu import reference_value, rel_err


@functools.cache
def _ref(kind: str, n: int, q: float):
    return reference_value(kind, n, q, dps=30)


def _relative_gap(lower, upper, q: float) -> float:
    n = max(lower[1], upper[1])
    with mpmath.workdps(40):
        return float((_ref(*upper, q) - _ref(*lower, q)) / (n * n + 2 * q + 1))


@pytest.mark.parametrize("n", [45, 50, 55, 60, 80, 100])
def test_ordering_where_large_n_pairs_become_degenerate(n):
    """a_n <= b_{n+1} and b_n <= a_n on 3000 q where b_{n+1} - a_n falls below the rounding error (q up to 1e4).
    Asymptotic gap formulas (DLMF 28.8.2) overestimate the gap there by up to 5e7, which let a_80 > b_81 by
    3.6e-12 at q = 5966 and a_100 > b_101 at q = 8721 before the clamp regions were measured."""
    q = np.linspace((0.6 * n) ** 2, min(1e4, (1.4 * n) ** 2), 3000)
    a, b_up, b_low = mathieu_a(n, q), mathieu_b(n + 1, q), mathieu_b(n, q)
    assert np.all(a <= b_up)
    assert np.all(b_low <= a)
    for i in (0, 1234, 2999):  # scalar calls: the same values
        assert mathieu_a(n, float(q[i])) == a[i] and mathieu_b(n + 1, float(q[i])) == b_up[i]


@pytest.mark.parametrize(
    ("kind", "n", "side"), [("a", 0, "upper"), ("a", 60, "upper"), ("a", 5, "lower"), ("a", 45, "lower")]
)
def test_clamp_regions_are_safe_and_tight(kind, n, side):
    """Just outside a clamp region the true gap (30-digit references) is well above the rounding error, just inside it
    is below 1e-11 (n^2 + 2q + 1): the region is where the neighbours can come out of order, and not much more."""
    lower, upper = _mathieu_seed.neighbours(kind, n)
    if side == "upper":
        pair, edge = ((kind, n), (upper.kind, upper.n)), upper.h_low
        outside, inside = 0.97 * edge, 1.03 * edge
    else:
        pair, edge = ((lower.kind, lower.n), (kind, n)), lower.h_high
        outside, inside = 1.03 * edge, 0.97 * edge
    assert _relative_gap(*pair, outside**2) > 1e-13
    assert _relative_gap(*pair, inside**2) < 1e-11


@pytest.mark.parametrize(("kind", "n"), [("a", 0), ("b", 1), ("a", 7), ("b", 20), ("a", 50)])
def test_seeds_are_accurate_from_small_to_huge_q(kind, n):
    """The piecewise Chebyshev seeds and the asymptotic expansion beyond them are within 1e-10 (relative to
    max(1, |value|)) of the values on q in [0, 1e6] -- one Rayleigh-quotient step then reaches full accuracy."""
    q = np.concatenate([np.linspace(0.0, 100.0, 401), np.geomspace(100.0, 1e6, 401)])
    values = (mathieu_a if kind == "a" else mathieu_b)(n, q)
    seeds = _mathieu_seed.seeds(kind, n, q)
    assert np.max(np.abs(seeds - values) / np.maximum(1.0, np.abs(values))) < 1e-10


def _forget_seed_tables() -> None:
    for cached in (_mathieu_seed.table, _mathieu_seed.plan, _mathieu_seed.neighbours,
                   _mathieu_seed.upper_threshold, _mathieu_seed.lower_threshold):  # fmt: skip
        cached.cache_clear()
    _hill_c.reset()  # the scalar path forgets the plans it knew


def test_values_do_not_depend_on_scipy_or_on_the_seeds(monkeypatch):
    """No SciPy value is used (seed tables generated afresh); a seed table of the next eigenvalue of the family (a_2
    for a_0) still gives the right values (the kernel checks the index and bisects)."""

    def refuse(*_args):
        raise AssertionError("scipy.special.mathieu_a/b must not be called")

    monkeypatch.setattr(scipy.special, "mathieu_a", refuse)
    monkeypatch.setattr(scipy.special, "mathieu_b", refuse)
    _forget_seed_tables()
    q = np.array([0.3, 4.0, 37.0, 450.0])
    try:
        good = mathieu_a(0, q)
        scalar = mathieu_a(0, 37.0)
        wrong_seeds = _hill_c.seeds(_hill_c.kernel(), _mathieu_seed.table("a", 2), q)
        from_wrong = _mathieu_seed.refine("a", 0, q, wrong_seeds, 1e-13)[0]
    finally:
        _forget_seed_tables()
    assert scalar == good[2]
    for v, g, x in zip(from_wrong, good, q, strict=True):
        assert rel_err(v, _ref("a", 0, float(x))) <= 1e-13
        assert rel_err(g, _ref("a", 0, float(x))) <= 1e-13


def test_extension_and_ctypes_scalar_paths_agree():
    """The scalar fast path (a CPython extension where the interpreter's headers are found) returns the bits of the
    kernel's ctypes entry point and of the vectorised call, including negative q (DLMF 28.2(vii))."""
    lib = _hill_c.kernel()
    q = np.concatenate([np.linspace(-60.0, 150.0, 211), [2500.0, 7777.7]])
    for kind, n in (("a", 0), ("a", 3), ("b", 3), ("b", 20)):
        fun = mathieu_a if kind == "a" else mathieu_b
        vec = fun(n, q)
        scalars = np.array([fun(n, float(x)) for x in q])
        assert np.array_equal(vec, scalars)
        for x, v in zip(q, vec, strict=True):
            is_b = int(kind == "b") if (x >= 0 or n % 2 == 0) else int(kind == "a")
            plan = _mathieu_seed.plan("b" if is_b else "a", n)
            assert _hill_c.FAST.value(int(kind == "b"), n, float(x)) == v
            assert lib.symosc_mathieu_auto1(plan.ctypes.data, abs(float(x)), 1e-13, None) == v
    assert _hill_c.FAST.value(0, 10**6, 1.0) != _hill_c.FAST.value(0, 10**6, 1.0)  # no plan: nan, general path
    assert type(_hill_c.FAST.value).__name__ == "builtin_function_or_method"  # the extension built on this machine
