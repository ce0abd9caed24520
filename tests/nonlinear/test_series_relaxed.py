"""Relaxed (blockwise) exact Cauchy products of Fourier series and the exact limit-cycle series built on them.

References, independent of the code under test: Fourier products written out here with ``fractions.Fraction``
(``cos a cos b = (cos(a+b) + cos(a-b))/2`` etc., summed pair by pair), and the pair-by-pair exact series engine that
symosc used before (cosine/sine arrays with one denominator, FLINT products folded by hand).
"""

from __future__ import annotations

import random
from fractions import Fraction as R

import pytest
import sympy as sp

from symosc.nonlinear import limit_cycle
from symosc.nonlinear.series import poincare
from symosc.nonlinear.series._arith import trig as _fourier
from symosc.nonlinear.series._arith.laurent import LaurentArith, block_products, pair_product

pytest.importorskip("flint", reason="the relaxed exact engine runs on python-flint (the 'exact' extra)")

x, v, eps = sp.symbols("x v eps")


def _product(a: dict, b: dict) -> dict:
    """Fourier product of {("c"|"s", n): Fraction} series, by the product-to-sum formulas."""
    out: dict = {}

    def put(kind, n, val):
        if n < 0:
            n, val = -n, (val if kind == "c" else -val)
        if kind == "s" and n == 0:
            return
        out[(kind, n)] = out.get((kind, n), 0) + val

    for (ka, n), x_ in a.items():
        for (kb, m), y_ in b.items():
            h = x_ * y_ / 2
            if ka == kb == "c":
                put("c", n + m, h), put("c", n - m, h)
            elif ka == kb == "s":
                put("c", n - m, h), put("c", n + m, -h)
            elif ka == "c":  # cos n sin m
                put("s", n + m, h), put("s", m - n, h)
            else:  # sin n cos m
                put("s", n + m, h), put("s", n - m, h)
    return {k: val for k, val in out.items() if val}


def _random_series(rng, top: int, parity: int | None, kind: str | None) -> dict:
    out = {}
    for n in range(top + 1):
        if parity is not None and n % 2 != parity:
            continue
        for k in ("c", "s"):
            if (kind is not None and k != kind) or (k == "s" and n == 0) or rng.random() < 0.3:
                continue
            out[(k, n)] = R(rng.randint(-(10**6), 10**6), rng.randint(1, 10**5))
    return out or {("c", parity or 0): R(1)}


def _to_half(ar: LaurentArith, s: dict):
    acc = ar.new(0)
    for (k, n), val in s.items():
        acc = ar.add_coeff(acc, k, n, val)
    return acc


def _from_half(ar: LaurentArith, t) -> dict:
    out = {}
    for n in range(t.hi + 1):
        for k in ("c", "s"):
            val = ar.coeff(t, k, n)
            if val:
                out[(k, n)] = val
    return out


@pytest.mark.parametrize(
    "pattern",
    ["general", "odd pure alternating", "even cosines", "odd sines", "mixed parity sides"],
)
def test_relaxed_cauchy_equals_pairwise_fraction_sums(pattern):
    """c_m = sum_i a_i b_(m-i) to m = 20 (blocks of 1..8 terms, truncated at the limit), and a square."""
    rng = random.Random(hash(pattern) % 1000)
    ar = LaurentArith()
    n_terms, limit = 21, 20

    def term(k, side):
        if pattern == "general":
            return _random_series(rng, 2 + k % 5, None, None)
        if pattern == "odd pure alternating":  # van der Pol's x_k: cosines at even k, sines at odd k
            return _random_series(rng, 2 * k + 1, 1, "c" if k % 2 == 0 else "s")
        if pattern == "even cosines":
            return _random_series(rng, 2 * (k % 4), 0, "c")
        if pattern == "odd sines":
            return _random_series(rng, 2 * (k % 3) + 1, 1, "s")
        return _random_series(rng, 3 + k % 3, side, None)  # one side odd harmonics, the other even

    A = [term(k, 1) for k in range(n_terms)]
    B = [term(k, 0) for k in range(n_terms)]
    a_list, b_list = [], []
    prod = ar.cauchy(a_list, b_list, limit=limit)
    square = ar.cauchy(a_list, a_list, limit=limit)
    for m in range(limit + 1):
        a_list.append(_to_half(ar, A[m]))
        b_list.append(_to_half(ar, B[m]))
        expected, expected_sq = {}, {}
        for i in range(m + 1):
            for key, val in _product(A[i], B[m - i]).items():
                expected[key] = expected.get(key, 0) + val
            for key, val in _product(A[i], A[m - i]).items():
                expected_sq[key] = expected_sq.get(key, 0) + val
        assert _from_half(ar, prod(m)) == {k: val for k, val in expected.items() if val}, m
        assert _from_half(ar, square(m)) == {k: val for k, val in expected_sq.items() if val}, m


@pytest.mark.parametrize("pattern", ["general", "odd pure alternating", "mixed parity sides"])
@pytest.mark.parametrize("size", [4, 5, 8])
@pytest.mark.parametrize("cut", [None, 1, 3])
@pytest.mark.parametrize("square", [False, True])
def test_block_products_equal_fraction_sums(pattern, size, cut, square):
    """One block product (terms packed half a product apart and unfolded; a square packed once; ``count`` cut below
    ``2 size - 1``) against the pairs summed with Fractions; blocks of both length parities."""
    rng = random.Random(f"{pattern}{size}{cut}{square}")
    i0, j0 = 2 * size + 1, size

    def term(k, side):
        if pattern == "general":
            return _random_series(rng, 1 + (k * 7) % 6, None, None)
        if pattern == "odd pure alternating":
            return _random_series(rng, 2 * k + 1, 1, "c" if k % 2 == 0 else "s")
        return _random_series(rng, 2 + k % 4, side, None)

    A = [term(i0 + r, 1) for r in range(size)]
    B = A if square else [term(j0 + r, 0) for r in range(size)]
    first = (i0, i0) if square else (i0, j0)
    count = 2 * size - 1 if cut is None else cut
    ar = LaurentArith()
    HA = [_to_half(ar, t) for t in A]
    HB = HA if square else [_to_half(ar, t) for t in B]
    got = block_products(ar, HA[:count], HB[:count], count, first)
    for t in range(count):
        expected: dict = {}
        for i in range(max(0, t - size + 1), min(t, size - 1) + 1):
            for key, val in _product(A[i], B[t - i]).items():
                expected[key] = expected.get(key, 0) + val
        assert _from_half(ar, ar._sum([(got[t], 1)])) == {k: val for k, val in expected.items() if val}, t


@pytest.mark.parametrize("short_top", [11, 13, 15, 31])
def test_pair_product_of_a_short_and_a_long_series(short_top):
    """A short factor of 6..16 coefficients (multiplied in pieces) against one of large coefficients."""
    rng = random.Random(short_top)
    ar = LaurentArith()
    a = _random_series(rng, short_top, 1, "c")
    b = {key: val * 10**300 / 7**200 for key, val in _random_series(rng, 81, 1, "s").items()}
    got = ar._sum([(pair_product(ar, _to_half(ar, a), _to_half(ar, b)), 1)])
    assert _from_half(ar, got) == _product(a, b)


@pytest.fixture
def pairwise_engine(monkeypatch):
    """The exact series by the former pair-by-pair engine (cosine/sine arrays, FLINT products folded by hand)."""

    def use():
        monkeypatch.setattr(poincare, "relaxed_exact_arith", lambda: None)

    return use


@pytest.mark.parametrize(
    ("f", "order"),
    [
        ((1 - x**2) * v, 36),  # van der Pol: odd, pure cosine/sine terms alternating with the order
        ((1 - x**2 - x * v) * v + x**3 / 3, 20),  # odd, mixed cosine and sine terms
        ((1 - x**2) * v + x**2 / 4 + eps * x * v**2 / 3, 16),  # even and odd harmonics, eps in f
    ],
)
def test_limit_cycle_equals_the_pairwise_engine(f, order, pairwise_engine):
    """Every coefficient (frequency, period, amplitude, Floquet exponent, harmonics of every x_k)."""
    new = limit_cycle(f, order)
    pairwise_engine()
    old = limit_cycle(f, order)
    for name in ("frequency", "period", "amplitude", "floquet_exponent"):
        assert getattr(new, name).coefficients == getattr(old, name).coefficients, name
    assert tuple(new._harmonics) == tuple(old._harmonics)


def test_without_flint_the_pairwise_engine_runs(monkeypatch):
    monkeypatch.setattr(_fourier, "_FMPZ_POLY", False)
    assert poincare.relaxed_exact_arith() is None
    lc = limit_cycle((1 - x**2) * v, 6)
    assert lc.amplitude.coefficient(4) == R(-1033, 552960)  # Andersen & Geer (1982), Table 1


def test_relaxed_scalar_times_series_equals_pairwise_fraction_sums():
    """sum_i w_i x_(m-i) with scalar w (blocks of 8 by per-harmonic products when complete), to m = 34."""
    rng = random.Random(5)
    ar = LaurentArith()
    limit = 34
    W = [R(rng.randint(-(10**9), 10**9), rng.randint(1, 10**7)) if k % 3 else R(0) for k in range(limit + 1)]
    X = [_random_series(rng, 2 * (k % 4) + 1, 1, "c" if k % 2 else "s") for k in range(limit + 1)]
    w_list, x_list = [], []
    conv = ar.cauchy(w_list, x_list, limit=limit, scalar_a=True)
    for m in range(limit + 1):
        w_list.append(W[m])
        x_list.append(_to_half(ar, X[m]))
        expected: dict = {}
        for i in range(m + 1):
            for key, val in X[m - i].items():
                expected[key] = expected.get(key, 0) + W[i] * val
        assert _from_half(ar, conv(m)) == {k: val for k, val in expected.items() if val}, m
