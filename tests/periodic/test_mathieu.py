"""Mathieu characteristic values a_n(q), b_n(q) against an independent 50-digit reference.

The reference below is written here, not taken from symosc: Sturm-sequence bisection (counting negative pivots of
the LDL^T factorisation of T - x) on the Hill matrices in mpmath at 50+ digits.  symosc's own methods use LAPACK
bisection + inverse iteration + a Rayleigh quotient ("auto"/"hill") and Newton on the continued fraction ("mp").
"""

from __future__ import annotations

import itertools
import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.errors import ConvergenceError, ParameterError
from symosc.periodic import _hill, mathieu_a, mathieu_b
from symosc.periodic.mathieu import MathieuValues, mathieu_characteristic


def reference_value(kind: str, n: int, q: float, dps: int = 50) -> mpmath.mpf:
    """kind_n(q) by Sturm bisection on a generously truncated Hill matrix, in mpmath (independent of symosc).

    Hill matrices (DLMF 28.4): cos-even diag (2j)^2, first coupling^2 = 2 q^2; cos-odd diag (2j+1)^2 + q at j = 0;
    sin-odd diag (2j+1)^2 - q at j = 0; sin-even diag (2j+2)^2; all other couplings q.  The index inside the class
    is k = n // 2 (n // 2 - 1 for even b).  Negative q: the matrices with signed q are exact (couplings enter squared).
    """
    if kind == "a":
        off, sign, k, two = (0, 0, n // 2, True) if n % 2 == 0 else (1, 1, n // 2, False)
    else:
        off, sign, k, two = (1, -1, n // 2, False) if n % 2 == 1 else (2, 0, n // 2 - 1, False)
    with mpmath.workdps(dps + 15):
        qm = mpmath.mpf(q)
        size = k + 40 + 2 * int(math.sqrt(abs(q)))
        d = [mpmath.mpf((2 * j + off) ** 2) for j in range(size)]
        d[0] += sign * qm
        b2 = [qm * qm] * (size - 1)
        if two:
            b2[0] = 2 * qm * qm
        tiny = mpmath.mpf(10) ** (-(dps + 60))

        def below(x):
            count, p = 0, d[0] - x
            for j in range(size):
                if j:
                    p = d[j] - x - b2[j - 1] / (p if p != 0 else tiny)
                count += p < 0
            return count

        # |lambda_k(H) - lambda_k(H0)| <= ||2q cos 2x|| = 2|q|
        lo, hi = mpmath.mpf(n * n) - 2 * abs(qm) - 1, mpmath.mpf(n * n) + 2 * abs(qm) + 1
        eps = mpmath.mpf(10) ** (-(dps - 5))
        while hi - lo > eps * max(1, abs(lo)):
            mid = (lo + hi) / 2
            if below(mid) > k:
                hi = mid
            else:
                lo = mid
        return (lo + hi) / 2


def rel_err(value, ref) -> float:
    with mpmath.workdps(80):
        return float(abs(mpmath.mpf(value) - ref) / max(1, abs(ref)))


CASES = [(kind, n) for n in (0, 1, 2, 10, 50) for kind in ("a", "b") if not (kind == "b" and n == 0)]


@pytest.mark.parametrize("q", [0.1, 3.0, 25.0, -7.5, 400.0])
@pytest.mark.parametrize(("kind", "n"), CASES)
def test_small_and_moderate_q_against_reference(kind, n, q):
    """a_n, b_n for n = 0, 1, 2, 10, 50 at small, moderate and negative q: 'auto' and 'hill' within 1e-13."""
    ref = reference_value(kind, n, q)
    f = mathieu_a if kind == "a" else mathieu_b
    assert rel_err(f(n, q), ref) <= 1e-13
    assert rel_err(f(n, q, method="hill"), ref) <= 1e-13


@pytest.mark.parametrize(("kind", "n"), CASES)
def test_very_large_q_against_reference(kind, n):
    """q = 1e4 (matrix norm ~ 2e4): relative error <= 1e-13 for 'auto'; 'mp' at 40 digits agrees to 1e-35."""
    q = 1e4
    ref = reference_value(kind, n, q)
    f = mathieu_a if kind == "a" else mathieu_b
    assert rel_err(f(n, q), ref) <= 1e-13
    assert rel_err(f(n, q, method="mp", dps=40), ref) <= 1e-35


@pytest.mark.parametrize(("kind", "n", "q"), [("a", 50, 8766.538942315901), ("b", 50, 8422.779651254905)])
def test_value_near_zero_at_large_q_is_absolutely_accurate(kind, n, q):
    """Extreme: a_50, b_50 cross zero near q ~ 8.5e3.  float64 eigenvalues there carry an absolute error ~eps*2q
    ~ 4e-12; 'auto' must still be within 1e-13 absolute (extended-precision Rayleigh quotient)."""
    ref = reference_value(kind, n, q)
    assert abs(ref) < 1e-6  # the point really is near the zero crossing
    f = mathieu_a if kind == "a" else mathieu_b
    assert abs(f(n, q) - float(ref)) <= 1e-13
    # a stricter tol makes "auto" fall back to mpmath internally (its own estimate ~3e-14 is above 1e-16)
    r = mathieu_characteristic(kind, n, q, tol=1e-16)
    assert r.error_estimate <= 1e-16 and abs(r.values - float(ref)) <= 1e-16


@pytest.mark.parametrize(("kind", "q"), [("a", 1.0), ("b", 1.0), ("a", 1e4), ("b", -1e4)])
def test_order_100(kind, q):
    """Orders up to at least 100."""
    ref = reference_value(kind, 100, q, dps=30)
    f = mathieu_a if kind == "a" else mathieu_b
    assert rel_err(f(100, q), ref) <= 1e-13


@pytest.mark.parametrize("n", [0, 1, 3])
def test_asymptotic_expansion_at_huge_q(n):
    """q = 1e6: DLMF 28.8.1, a_n ~ b_{n+1} ~ -2h^2 + 2sh - (s^2+1)/8 - (s^3+3s)/(2^7 h) - (5s^4+34s^2+9)/(2^12 h^2)
    - (33s^5+410s^3+405s)/(2^17 h^3), s = 2n+1, h = sqrt(q); next term ~ 1e-14 absolute."""
    h = mpmath.mpf(1000)
    s = 2 * n + 1
    asym = (
        -2 * h**2
        + 2 * s * h
        - mpmath.mpf(s**2 + 1) / 8
        - mpmath.mpf(s**3 + 3 * s) / (2**7 * h)
        - mpmath.mpf(5 * s**4 + 34 * s**2 + 9) / (2**12 * h**2)
        - mpmath.mpf(33 * s**5 + 410 * s**3 + 405 * s) / (2**17 * h**3)
    )
    for value in (mathieu_a(n, 1e6), mathieu_b(n + 1, 1e6)):
        assert rel_err(value, asym) <= 1e-13


def test_zero_q_gives_squares_and_symmetry_relations():
    """a_n(0) = b_n(0) = n^2; DLMF 28.2(vii): a_2m(-q) = a_2m(q), a_2m+1(-q) = b_2m+1(q), b_2m(-q) = b_2m(q)."""
    for n in range(0, 12):
        assert mathieu_a(n, 0.0) == n * n
        if n:
            assert mathieu_b(n, 0.0) == n * n
    q = np.array([0.3, 2.0, 40.0, 900.0])
    for m in range(4):
        assert np.array_equal(mathieu_a(2 * m, -q), mathieu_a(2 * m, q))
        assert np.array_equal(mathieu_a(2 * m + 1, -q), mathieu_b(2 * m + 1, q))
        assert np.array_equal(mathieu_b(2 * m + 1, -q), mathieu_a(2 * m + 1, q))
        if m:
            assert np.array_equal(mathieu_b(2 * m, -q), mathieu_b(2 * m, q))


@settings(max_examples=25, deadline=None)
@given(q=st.floats(min_value=0.0, max_value=1e4, allow_nan=False))
def test_ordering_property(q):
    """a_0 <= b_1 <= a_1 <= b_2 <= a_2 <= ... for q >= 0 (non-strict in float64: a_n and b_{n+1} at large q, and
    b_n, a_n at small q, differ by less than one ulp), and a_n < a_{n+1}, b_n < b_{n+1} strictly."""
    chain = [mathieu_a(0, q)]
    for n in range(1, 16):
        chain += [mathieu_b(n, q), mathieu_a(n, q)]
    assert all(x <= y for x, y in itertools.pairwise(chain))
    a = chain[0::2]
    b = chain[1::2]
    assert all(x < y for x, y in itertools.pairwise(a))
    assert all(x < y for x, y in itertools.pairwise(b))


def test_ordering_on_a_dense_grid_where_scipy_jumps():
    """On the benchmark grid q <= 2000, n <= 20 no ordering violation at all (SciPy's mathieu_a/b have >1000 here)."""
    q = np.linspace(0, 2000, 41)
    chain = [mathieu_a(0, q)]
    for n in range(1, 21):
        chain += [mathieu_b(n, q), mathieu_a(n, q)]
    assert np.all(np.diff(np.array(chain), axis=0) >= 0)


def test_vectorised_shapes_and_scalar_types():
    q2 = np.array([[0.5, 1.0], [2.0, -3.0]])
    v = mathieu_a(3, q2)
    assert isinstance(v, np.ndarray) and v.shape == (2, 2) and v.dtype == float
    assert v[1, 1] == mathieu_a(3, -3.0)
    assert isinstance(mathieu_b(2, 1.0), float)
    assert isinstance(mathieu_b(2, np.float64(1.0)), float)
    assert mathieu_a(2, [1.0, 2.0]).shape == (2,)
    assert mathieu_a(2, np.array([])).shape == (0,)
    mp = mathieu_a(1, [0.5, 1.0], method="mp", dps=20)
    assert mp.dtype == object and isinstance(mp[0], mpmath.mpf)


def test_array_of_indices_broadcasts_like_scipy():
    """n may be an array too; it broadcasts against q (scipy.special.mathieu_a(m, q) semantics)."""
    n = np.array([[1], [2], [7]])
    q = np.array([0.5, -3.0, 100.0, 1e3])
    v = mathieu_b(n, q)
    assert v.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            assert v[i, j] == mathieu_b(int(n[i, 0]), float(q[j]))
    r = mathieu_characteristic("a", [0, 3], 2.0)
    assert r.values.shape == (2,) and list(r.n) == [0, 3] and "n in [0, 3]" in repr(r)
    assert "a_{n}" in r._repr_latex_()
    with pytest.raises(ParameterError, match="broadcast"):
        mathieu_a([1, 2, 3], [1.0, 2.0])
    with pytest.raises(ParameterError, match="b_0 does not exist"):
        mathieu_b([1, 0], 1.0)


def test_mp_method_accepts_mpf_and_string_q():
    """q given to more digits than float64 keeps them on the mp path."""
    with mpmath.workdps(50):
        q = mpmath.mpf("0.1000000000000000000001")
    v = mathieu_a(0, q, method="mp", dps=40)
    ref = reference_value("a", 0, q, dps=50)
    assert rel_err(v, ref) < 1e-35
    assert rel_err(mathieu_a(0, "0.1000000000000000000001", method="mp", dps=40), ref) < 1e-35
    assert rel_err(mathieu_a(0, 0.1, method="mp", dps=40), ref) > 1e-22  # the extra digits of q mattered


def test_series_method_and_its_convergence_error():
    """method='series' agrees inside the radius and refuses beyond it (a_0: radius 1.4688)."""
    ref = reference_value("a", 0, 0.7)
    assert rel_err(mathieu_a(0, 0.7, method="series"), ref) <= 1e-13
    with pytest.raises(ConvergenceError, match="radius of convergence"):
        mathieu_a(0, 2.5, method="series")
    with pytest.raises(ConvergenceError, match="radius of convergence"):
        mathieu_b(1, 10.0, method="series")


def test_result_object_reports_error_estimate():
    r = mathieu_characteristic("b", 2, [1.0, 50.0])
    assert isinstance(r, MathieuValues)
    assert np.all(r.error_estimate < 1e-13 * np.maximum(1, np.abs(r.values)))
    assert "b_2" in repr(r) and "auto" in repr(r)
    s = mathieu_characteristic("a", 0, 1.0)
    assert "a_{0}" in s._repr_latex_()
    h = mathieu_characteristic("a", 5, 30.0, method="hill")
    assert h.method == "hill" and h.error_estimate < 1e-12


def test_truncation_that_cannot_converge_raises():
    """The size checks really check: a far too small matrix with no room to grow raises ConvergenceError."""
    fam, k = _hill.family_index("a", 0)
    with pytest.raises(ConvergenceError, match="did not converge"):
        _hill.solve_hill(fam, k, 1e4, size=4, max_tries=1)
    with pytest.raises(ConvergenceError, match="did not converge"):
        _hill.solve_refined(fam, k, 1e4, size=4, max_tries=1)
    # given room, the same start converges to the reference
    assert rel_err(_hill.solve_hill(fam, k, 1e4, size=4).value, reference_value("a", 0, 1e4, dps=30)) < 1e-13


def test_tol_too_strict_for_auto_raises():
    with pytest.raises(ConvergenceError, match="above tol"):
        mathieu_a(3, 5000.0, tol=1e-18)


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: mathieu_a(2.5, 1.0), "non-negative integer"),
        (lambda: mathieu_a(-1, 1.0), "non-negative integer"),
        (lambda: mathieu_a("2", 1.0), "non-negative integer|got the string"),
        (lambda: mathieu_a(True, 1.0), "non-negative integer"),
        (lambda: mathieu_b(0, 1.0), "b_0 does not exist"),
        (lambda: mathieu_a(1, float("nan")), "finite"),
        (lambda: mathieu_b(1, [1.0, np.inf]), "finite"),
        (lambda: mathieu_a(1, 1 + 2j), "real"),
        (lambda: mathieu_a(1, "abc"), "real"),
        (lambda: mathieu_a(1, 1.0, method="qr"), "method"),
        (lambda: mathieu_a(1, 1.0, method="hill", dps=30), "dps"),
        (lambda: mathieu_a(1, 1.0, method="mp", dps=2), "dps"),
        (lambda: mathieu_a(1, 1.0, tol=-1.0), "tol"),
        (lambda: mathieu_characteristic("c", 1, 1.0), "kind"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ParameterError, match=match):
        call()


def test_integral_float_index_is_accepted():
    """n = 2.0 is accepted (as in scipy.special), 2.5 is not."""
    assert mathieu_a(2.0, 1.0) == mathieu_a(2, 1.0)
