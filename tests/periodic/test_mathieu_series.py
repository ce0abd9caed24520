"""Exact power series of a_n(q), b_n(q): the paper's (8)/(9), DLMF 28.6, and convergence against numerics."""

from __future__ import annotations

import itertools
from fractions import Fraction

import mpmath
import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.errors import ConvergenceError, ParameterError
from symosc.periodic import mathieu_series_a, mathieu_series_b
from symosc.periodic.mathieu_series import SeriesValue, mathieu_series_radius, mathieu_series_value

from .test_mathieu import reference_value

q = sympy.Symbol("q")
R = sympy.Rational


def test_paper_formula_8_a0():
    """Gribkov & Khokhlov 2015, seed 000_61b220062ca00c64, §2 formula (8) (quoted from McLachlan), term by term."""
    paper = -(q**2) / 2 + R(7, 128) * q**4 - R(29, 2304) * q**6 + R(68687, 18874368) * q**8
    assert sympy.expand(mathieu_series_a(0, 8) - paper) == 0


def test_paper_formula_9_b1_and_its_misprinted_last_coefficient():
    """Seed 000_61b220062ca00c64, §2 formula (9): orders 0..7 agree term by term; the q^8 coefficient printed as
    -265/113246208 is wrong -- it is -83/35389440 (DLMF 28.6.4), confirmed below independently by extracting it
    from 70-digit values of b_1(q) at tiny q."""
    paper_0_7 = (
        1 - q - q**2 / 8 + q**3 / 64 - q**4 / 1536 - R(11, 36864) * q**5 + R(49, 589824) * q**6 - R(55, 9437184) * q**7
    )
    series = mathieu_series_b(1, 8)
    assert sympy.expand(series - paper_0_7 - series.coeff(q, 8) * q**8) == 0
    assert series.coeff(q, 8) == R(-83, 35389440)
    assert series.coeff(q, 8) != R(-265, 113246208)
    # independent: c8 ~ (b_1(h) - sum_{k<=7} c_k h^k) / h^8 at h = 1e-5 (c9 h^9 term is 1e-5 relative)
    h = mpmath.mpf("1e-5")
    with mpmath.workdps(80):
        b1 = reference_value("b", 1, h, dps=75)
        rest = b1 - sum(
            mpmath.mpf(int(c.p)) / int(c.q) * h**k for k, c in enumerate(sympy.Poly(paper_0_7, q).all_coeffs()[::-1])
        )
        c8 = rest / h**8
    assert abs(c8 - mpmath.mpf(-83) / 35389440) < 1e-4 * 83 / 35389440
    assert abs(c8 - mpmath.mpf(-265) / 113246208) > 1e-3 * 265 / 113246208


def test_dlmf_28_6_low_orders():
    """DLMF 28.6.1-28.6.7 (McLachlan's tables): a_1, a_2, b_2 up to q^8."""
    a1 = (
        1
        + q
        - q**2 / 8
        - q**3 / 64
        - q**4 / 1536
        + R(11, 36864) * q**5
        + R(49, 589824) * q**6
        + R(55, 9437184) * q**7
        - R(83, 35389440) * q**8
    )
    a2 = 4 + R(5, 12) * q**2 - R(763, 13824) * q**4 + R(1002401, 79626240) * q**6 - R(1669068401, 458647142400) * q**8
    b2 = 4 - q**2 / 12 + R(5, 13824) * q**4 - R(289, 79626240) * q**6 + R(21391, 458647142400) * q**8
    assert sympy.expand(mathieu_series_a(1, 8) - a1) == 0
    assert sympy.expand(mathieu_series_a(2, 8) - a2) == 0
    assert sympy.expand(mathieu_series_b(2, 8) - b2) == 0


def test_large_index_leading_terms():
    """DLMF 28.6.14 for n >= 3 (no q^n cross-term below q^4 for n >= 5): a_n ~ n^2 + q^2/(2(n^2-1))
    + (5n^2+7) q^4 / (32 (n^2-1)^3 (n^2-4)); same for b_n."""
    for n in (5, 10, 50):
        expected = n**2 + q**2 / (2 * (n**2 - 1)) + R(5 * n**2 + 7, 32 * (n**2 - 1) ** 3 * (n**2 - 4)) * q**4
        assert sympy.expand(mathieu_series_a(n, 4) - expected) == 0
        assert sympy.expand(mathieu_series_b(n, 4) - expected) == 0


@pytest.mark.parametrize("n", [1, 2, 3, 4, 6])
def test_splitting_a_n_minus_b_n(n):
    """a_n - b_n = q^n / (2^(2n-3) ((n-1)!)^2) + O(q^(n+1)) (Meixner & Schafke; DLMF 28.6.21)."""
    diff = sympy.expand(mathieu_series_a(n, n + 1) - mathieu_series_b(n, n + 1))
    assert diff.coeff(q, n) == R(1, 2 ** (2 * n - 3) * sympy.factorial(n - 1) ** 2)
    for k in range(n):
        assert diff.coeff(q, k) == 0


@settings(max_examples=10, deadline=None)
@given(m=st.integers(min_value=0, max_value=6), order=st.integers(min_value=1, max_value=14))
def test_symmetry_of_series(m, order):
    """a_{2m+1}(-q) = b_{2m+1}(q); even index series contain only even powers (DLMF 28.2(vii))."""
    assert sympy.expand(mathieu_series_a(2 * m + 1, order).subs(q, -q) - mathieu_series_b(2 * m + 1, order)) == 0
    even = sympy.Poly(mathieu_series_a(2 * m, order), q)
    assert all(k % 2 == 0 for (k,) in even.monoms())
    assert all(isinstance(c, sympy.Rational) for c in even.coeffs())


@pytest.mark.parametrize(("kind", "n", "qv", "orders"), [("a", 0, 0.5, range(2, 30, 2)), ("b", 1, 1.0, range(1, 30))])
def test_truncation_error_decreases_with_order(kind, n, qv, orders):
    """Inside the radius (a_0: 1.4688, b_1: ~3.77) the error against the 50-digit reference shrinks with the order
    (for b_1 the terms oscillate, so compare the envelope over blocks of four orders)."""
    ref = reference_value(kind, n, qv)
    series = mathieu_series_a if kind == "a" else mathieu_series_b
    errs = []
    for o in orders:
        poly = series(n, o)
        val = sympy.Poly(poly, q).eval(sympy.Rational(qv))
        errs.append(abs(mpmath.mpf(val.p) / val.q - ref))
    if kind == "a":
        assert all(e2 < e1 for e1, e2 in itertools.pairwise(errs))
    else:
        blocks = [max(errs[i : i + 4]) for i in range(0, len(errs) - 3, 4)]
        assert all(e2 < e1 for e1, e2 in itertools.pairwise(blocks))
    assert errs[-1] < 1e-9


def test_series_value_helper():
    r = mathieu_series_value("b", 1, 0.5)
    assert isinstance(r, SeriesValue) and r.converged and r.error_estimate < 1e-13
    assert abs(r.value - float(reference_value("b", 1, 0.5))) < 1e-14
    hi = mathieu_series_value("a", 0, "0.3", dps=40, tol=1e-35, max_order=64)
    with mpmath.workdps(50):
        ref = reference_value("a", 0, mpmath.mpf("0.3"))
        assert abs(hi.value - ref) < 1e-35
    fixed = mathieu_series_value("a", 0, 1.2, order=8)
    assert fixed.order == 8 and not fixed.converged
    # low fixed orders still give an honest (not zero) estimate: at least the true truncation error's size
    low = mathieu_series_value("b", 1, 0.3, order=4)
    true_err = abs(low.value - float(reference_value("b", 1, 0.3)))
    assert low.error_estimate >= true_err > 0
    assert "SeriesValue" in repr(fixed)
    with pytest.raises(ConvergenceError, match="radius"):
        mathieu_series_value("a", 0, 1.6)


def test_radius_estimates():
    """a_0 meets a_2 at q = +-1.46876852i (Mulholland & Goldstein 1929); b_2 meets b_4 at |q| = 6.9288."""
    assert abs(mathieu_series_radius("a", 0) - 1.4688) < 0.01 * 1.4688
    assert abs(mathieu_series_radius("b", 2) - 6.9288) < 0.01 * 6.9288


def test_high_order_is_exact_and_cached():
    """Order 40 exactly (Fractions all the way); the q^40 coefficient of a_0 is a tiny, exact rational."""
    s = mathieu_series_a(0, 40)
    c40 = s.coeff(q, 40)
    assert isinstance(c40, sympy.Rational) and c40 != 0
    assert abs(Fraction(int(c40.p), int(c40.q))) < Fraction(1, 10**6)
    assert sympy.expand(mathieu_series_a(0, 20) - sum(s.coeff(q, k) * q**k for k in range(21))) == 0


def test_custom_symbol():
    x = sympy.Symbol("x")
    assert mathieu_series_b(2, 2, symbol=x) == 4 - x**2 / 12


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: mathieu_series_a(-1, 4), "non-negative integer"),
        (lambda: mathieu_series_a(1.5, 4), "non-negative integer"),
        (lambda: mathieu_series_b(0, 4), "b_0 does not exist"),
        (lambda: mathieu_series_a(1, -2), "order"),
        (lambda: mathieu_series_a(1, 2.5), "order"),
        (lambda: mathieu_series_value("c", 1, 0.1), "kind"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ParameterError, match=match):
        call()
