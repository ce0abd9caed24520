"""Newcomb–Lindstedt series (Bulgakov 1954, seed 004, §5.4; report seed-bulgakov-part2.md §2.2 and §3 item 1)."""

from __future__ import annotations

from fractions import Fraction as F

import mpmath
import pytest
import sympy as sp

from symosc.errors import ModelError, ParameterError
from symosc.nonlinear import lindstedt, numeric_period

x, eps, A = sp.symbols("x eps A")
R = sp.Rational


def _series_mul(a, b, n):
    return [sum(a[i] * b[k - i] for i in range(k + 1)) for k in range(n + 1)]


def _duffing_exact_series(n):
    """omega(eps) of x'' + x + eps x^3 = 0, x(0) = 1 from omega = pi sqrt(1+eps) / (2 K(m)), m = eps/(2(1+eps)).

    Independent of the code under test: plain Fraction power-series arithmetic on the elliptic-integral formula.
    """
    m = [F(0)] + [F((-1) ** (k - 1), 2) for k in range(1, n + 1)]  # eps/(2(1+eps))
    # 2K(m)/pi = sum ((2j)!/(4^j j!^2))^2 m^j
    K = [F(0)] * (n + 1)
    mp = [F(1)] + [F(0)] * n
    for j in range(n + 1):
        c = F(sp.factorial(2 * j), 4**j * sp.factorial(j) ** 2) ** 2
        K = [K[k] + c * mp[k] for k in range(n + 1)]
        mp = _series_mul(mp, m, n)
    # sqrt(1 + eps): binomial series
    s = [F(sp.binomial(R(1, 2), k)) for k in range(n + 1)]
    # reciprocal of K
    inv = [F(1)]
    for k in range(1, n + 1):
        inv.append(-sum(K[i] * inv[k - i] for i in range(1, k + 1)))
    return _series_mul(s, inv, n)


def test_duffing_known_first_coefficients():
    """Report part 2 §2.2: omega = 1 + 3/8 eps A^2 - 21/256 eps^2 A^4 + ..."""
    ls = lindstedt(-(x**3), 4)
    c = ls.frequency.coefficients
    assert c[:4] == (1, R(3, 8) * A**2, R(-21, 256) * A**4, R(81, 2048) * A**6)


def test_duffing_order_20_exact_against_elliptic_integral():
    """Target: Duffing frequency to eps^20 exactly; every coefficient equals the elliptic-integral expansion."""
    ls = lindstedt(-(x**3), 20)
    ref = _duffing_exact_series(20)
    assert ls.order == 20
    for k, (c, r) in enumerate(zip(ls.frequency.coefficients, ref, strict=True)):
        assert c == sp.Rational(r.numerator, r.denominator) * A ** (2 * k)


def test_duffing_numeric_period_and_radius():
    ls = lindstedt(-(x**3), 20)
    e, a = 0.1, 1.0
    T = numeric_period(-(x**3), e, a)
    assert abs(float(ls.omega(e, a)) - 2 * mpmath.pi / T) < 1e-12
    # the series in eps*A^2 has radius 1 (singularity of K at eps*A^2 = -1): Domb-Sykes on the coefficients
    sub = type(ls.frequency)(tuple(c.subs(A, 1) for c in ls.frequency.coefficients), eps, 20)
    r = sub.radius_of_convergence()
    assert abs(r.radius - 1) < 0.05
    assert r.method == "domb-sykes" and r.singularity_on_real_axis is False


def test_softening_duffing_numeric():
    """Soft spring x'' + x - eps x^3 = 0 (f = +x^3): frequency decreases with amplitude."""
    ls = lindstedt(x**3, 12)
    e, a = 0.2, 1.0
    om = float(ls.omega(e, a))
    assert om < 1
    assert abs(om - 2 * mpmath.pi / numeric_period(x**3, e, a)) < 1e-9


def test_book_general_coefficients_5_52_5_58():
    """Bulgakov (5.52), (5.58): delta2 = 3/4 c2 - 5/6 c1^2; P/P0 to a^4 with c1..c4 (verified in the report)."""
    c1, c2, c3, c4 = sp.symbols("c1:5")
    ls = lindstedt(-(c1 * x**2 + c2 * x**3 + c3 * x**4 + c4 * x**5), 4)
    om2 = sp.expand(ls.frequency_squared.expr.subs(eps, 1))
    assert sp.expand(om2.coeff(A, 1)) == 0  # delta1 = 0
    assert sp.expand(om2.coeff(A, 2) - (R(3, 4) * c2 - R(5, 6) * c1**2)) == 0
    assert sp.expand(om2.coeff(A, 3) - (-R(5, 9) * c1**3 + R(1, 2) * c1 * c2)) == 0
    d4 = -(940 * c1**4 - 2220 * c1**2 * c2 + 2016 * c1 * c3 + 27 * c2**2 - 720 * c4) / 1152
    assert sp.expand(om2.coeff(A, 4) - d4) == 0
    P = sp.expand(ls.period.expr.subs(eps, 1) / (2 * sp.pi))
    assert sp.expand(P.coeff(A, 2) - (R(5, 12) * c1**2 - R(3, 8) * c2)) == 0
    assert sp.expand(P.coeff(A, 3) - (R(5, 18) * c1**3 - R(1, 4) * c1 * c2)) == 0
    p4 = R(385, 576) * c1**4 - R(275, 192) * c1**2 * c2 + R(7, 8) * c1 * c3 + R(57, 256) * c2**2 - R(5, 16) * c4
    assert sp.expand(P.coeff(A, 4) - p4) == 0


def test_book_solution_terms_5_51():
    """Bulgakov (5.51): q2 = (c1/6)(-3 + 2 cos th + cos 2th) (coefficient of a^2)."""
    c1 = sp.Symbol("c1")
    tau = sp.Symbol("tau")
    ls = lindstedt(-c1 * x**2, 2)
    q = sp.expand(ls.solution(2, tau).subs(eps, 1))
    assert sp.expand(q.coeff(A, 2) - c1 / 6 * (-3 + 2 * sp.cos(tau) + sp.cos(2 * tau))) == 0


@pytest.mark.parametrize(
    ("deg", "exact"),
    [(10, 1.001907), (20, 1.007669), (30, 1.017409)],
)
def test_pendulum_period_ratio_recomputed(deg, exact):
    """Bulgakov §5.4 pendulum: P/P0 = 1 + a^2/16 + 11 a^4/3072 (5.61).  The printed 1.001/1.006/1.014 are wrong
    (report part 2 §3 item 1): we test against the exact (2/pi) K(sin^2(a/2)), recomputed values as cited."""
    ls = lindstedt(x**3 / 6 - x**5 / 120, 2)
    P = sp.expand(ls.period.expr.subs(eps, 1) / (2 * sp.pi))
    assert P.coeff(A, 0) == 1 and P.coeff(A, 1) == 0 and P.coeff(A, 3) == 0
    a = mpmath.radians(deg)
    series = 1 + a**2 / 16 + 11 * a**4 / 3072
    exact_k = 2 / mpmath.pi * mpmath.ellipk(mpmath.sin(a / 2) ** 2)
    assert abs(exact_k - exact) < 1e-6
    assert abs(series - exact_k) < (1e-5 if deg == 30 else 2e-6)
    assert P.coeff(A, 2) == R(1, 16) and P.coeff(A, 4) == R(11, 3072)


def test_asymmetric_quadratic_has_odd_powers_and_matches_numerics():
    ls = lindstedt(-(x**2), 10)
    assert ls.frequency.coefficients[1] == 0  # no first-order shift
    assert ls.frequency.coefficients[2] == R(-5, 12) * A**2
    e, a = 0.1, 1.0
    assert abs(float(ls.omega(e, a)) - 2 * mpmath.pi / numeric_period(-(x**2), e, a)) < 1e-9


def test_frequency_in_amplitude_and_repr():
    ls = lindstedt(-(x**2) - x**3, 4)
    poly = ls.frequency_in_amplitude()
    assert sp.Poly(poly, A).degree() <= 4
    assert "LindstedtSeries" in repr(ls)
    with pytest.raises(ParameterError):
        ls.solution(5)


@pytest.mark.parametrize(
    ("f", "order", "err", "match"),
    [
        (-(x**3), 0, ParameterError, "order"),
        (sp.sin(x), 2, ModelError, "polynomial"),
        (1 + x**3, 2, ModelError, "equilibrium"),
        (-(x**3) + sp.Symbol("v"), 2, ModelError, "limit_cycle"),
        (-eps * x**3, 2, ParameterError, "eps"),
        (-(x**3) / sp.Symbol("k"), 2, ParameterError, "polynomial"),
    ],
)
def test_bad_input(f, order, err, match):
    with pytest.raises(err, match=match):
        lindstedt(f, order)
