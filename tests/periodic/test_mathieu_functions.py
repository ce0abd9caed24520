"""ce_n, se_n, modified functions, exponent and Floquet solutions against independent references.

References: 40-digit coefficients from Sturm bisection + a Thomas solve in mpmath (tests/periodic/mathieu_reference.py,
no code of symosc), DLMF 28.2(vii) (negative q), 28.2.30 (normalisation), 28.20.21 (Wronskian), 28.23.6-7 (Bessel
series in 2h cosh z / 2h sinh z), 28.6.21 (q-series of ce_0), and the monodromy matrix of symosc.periodic (DOP853
integration of the ODE) for the exponent.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy

from symosc.errors import ConvergenceError, ParameterError
from symosc.periodic import (
    mathieu_a,
    mathieu_b,
    mathieu_ce,
    mathieu_ce_prime,
    mathieu_coefficient_series,
    mathieu_exponent,
    mathieu_floquet_exponent,
    mathieu_fourier_coefficients,
    mathieu_function,
    mathieu_function_series,
    mathieu_fundamental,
    mathieu_lambda,
    mathieu_mc,
    mathieu_me,
    mathieu_modified,
    mathieu_ms,
    mathieu_se,
    mathieu_se_prime,
    monodromy,
)

from . import mathieu_reference as ref

X = np.linspace(0.0, 2 * np.pi, 29)
CASES = [("ce", 0, 1.0), ("se", 1, 1.0), ("ce", 3, 10.0), ("se", 4, 100.0), ("ce", 25, 3000.0),
         ("se", 49, 500.0), ("ce", 50, 1e4), ("se", 50, 1e4), ("ce", 0, 1e4), ("se", 1, 1e4)]  # fmt: skip


@pytest.fixture(scope="module")
def references():
    return {(k, n, q): ref.coefficients("a" if k == "ce" else "b", n, q) for k, n, q in CASES}


@pytest.mark.parametrize("kind,n,q", CASES)
def test_functions_and_derivatives_against_40_digit_coefficients(kind, n, q, references):
    """Error <= 1e-13 absolute for ce/se (normalised) and for their derivatives (|ce'| reaches ~150 at q = 1e4);
    the error estimate (a sound bound) holds."""
    co = references[(kind, n, q)]
    for derivative in (False, True):
        r = mathieu_function(kind, n, q, X, derivative=derivative)
        exact = ref.function(kind, n, q, X, derivative, co)
        err = np.abs(r.values - exact)
        assert np.max(err) <= 1e-13
        assert np.all(err <= r.error_estimate)
        assert abs(float(r.characteristic_value[0]) - float(co[2])) <= 1e-13 * max(1.0, abs(float(co[2])))


def test_many_q_at_the_default_tolerance_with_sound_estimates(references):
    """ce_5 over 10^4 q in [0, 100] is computed at the default tol (the estimate once reached 1.8e-13 there and the
    call was refused); estimates <= 1e-13, and they bound the error at reference points (40 digits)."""
    q = np.linspace(0.0, 100.0, 10_000)
    r = mathieu_function("ce", 5, q, 0.7)
    assert np.max(r.error_estimate) <= 1e-13
    d = mathieu_function("ce", 5, q, 0.7, derivative=True)
    for i in (1234, 7777):
        co = ref.coefficients("a", 5, float(q[i]))
        for res, derivative in ((r, False), (d, True)):
            exact = ref.function("ce", 5, float(q[i]), np.array([0.7]), derivative, co)[0]
            assert abs(res.values[i] - exact) <= res.error_estimate[i] <= 1e-13


def test_numpy_fallback_functions_against_references(references, monkeypatch):
    """Without a C compiler the same method runs in NumPy: ce_25 at q = 3000, values and derivatives within 1e-13
    and within their estimates."""
    from symosc.periodic import _hill_c

    monkeypatch.setenv("SYMOSC_MATHIEU_KERNEL", "numpy")
    _hill_c.reset()
    try:
        co = references[("ce", 25, 3000.0)]
        for derivative in (False, True):
            r = mathieu_function("ce", 25, 3000.0, X, derivative=derivative)
            err = np.abs(r.values - ref.function("ce", 25, 3000.0, X, derivative, co))
            assert np.max(err) <= 1e-13 and np.all(err <= r.error_estimate)
    finally:
        monkeypatch.delenv("SYMOSC_MATHIEU_KERNEL")
        _hill_c.reset()


def test_normalisation_and_sign_convention():
    """DLMF 28.2.30: integral over a period of ce^2 = se^2 = pi; first coefficient positive for q > 0."""
    x = np.linspace(0, 2 * np.pi, 513)[:-1]
    for n, q in [(0, 5.0), (3, 40.0), (10, 200.0)]:
        for f, kind in ((mathieu_ce, "ce"), (mathieu_se, "se")):
            if kind == "se" and n == 0:
                continue
            y = f(n, q, x)
            assert abs(np.mean(y * y) * 2 * np.pi - np.pi) < 1e-12
            assert mathieu_fourier_coefficients(kind, n, q).values[0] > 0


def test_small_q_limits():
    """ce_0 -> 1/sqrt(2), ce_n -> cos nx, se_n -> sin nx as q -> 0 (DLMF 28.2.29)."""
    assert np.allclose(mathieu_ce(0, 0.0, X), 2**-0.5, atol=1e-15, rtol=0)
    for n in (1, 2, 7):
        assert np.allclose(mathieu_ce(n, 0.0, X), np.cos(n * X), atol=5e-15, rtol=0)
        assert np.allclose(mathieu_se(n, 0.0, X), np.sin(n * X), atol=5e-15, rtol=0)
        assert np.allclose(mathieu_ce(n, 1e-9, X), np.cos(n * X), atol=1e-8, rtol=0)


@pytest.mark.parametrize("n", [0, 1, 2, 3, 6, 7])
def test_negative_q_relations(n):
    """DLMF 28.2(vii): ce_2m(x,-q) = (-1)^m ce_2m(pi/2 - x, q), ce_2m+1(x,-q) = (-1)^m se_2m+1(pi/2 - x, q), ..."""
    q = 7.5
    m = n // 2
    sign = (-1) ** m
    y = np.pi / 2 - X
    if n % 2 == 0:
        assert np.allclose(mathieu_ce(n, -q, X), sign * mathieu_ce(n, q, y), atol=1e-14, rtol=0)
        if n:
            sm = (n - 2) // 2
            assert np.allclose(mathieu_se(n, -q, X), (-1) ** sm * mathieu_se(n, q, y), atol=1e-14, rtol=0)
    else:
        assert np.allclose(mathieu_ce(n, -q, X), sign * mathieu_se(n, q, y), atol=1e-14, rtol=0)
        assert np.allclose(mathieu_se(n, -q, X), sign * mathieu_ce(n, q, y), atol=1e-14, rtol=0)


def test_ode_residual_by_finite_differences_and_vectorised_broadcast():
    """y'' + (a - 2q cos 2x) y = 0 with y'' from central differences of the computed derivative."""
    q, n, h = 30.0, 5, 1e-5
    x = np.linspace(0.1, 3.0, 9)
    a = mathieu_a(n, q)
    ypp = (mathieu_ce_prime(n, q, x + h) - mathieu_ce_prime(n, q, x - h)) / (2 * h)
    assert np.max(np.abs(ypp + (a - 2 * q * np.cos(2 * x)) * mathieu_ce(n, q, x))) < 1e-6
    grid = mathieu_se(3, np.array([[1.0], [5.0]]), x)
    assert grid.shape == (2, x.size)
    assert np.allclose(grid[1], mathieu_se(3, 5.0, x), atol=0, rtol=0)


def test_near_degenerate_pair_keeps_parity():
    """At q = 2000, a_10 and b_11 agree to ~1e-9: ce_10 stays even about 0 and se_11 odd, each normalised."""
    q = 2000.0
    assert abs(mathieu_b(11, q) - mathieu_a(10, q)) < 1e-6
    x = np.array([0.3, 1.1])
    assert np.allclose(mathieu_ce(10, q, -x), mathieu_ce(10, q, x), atol=1e-13, rtol=0)
    assert np.allclose(mathieu_se(11, q, -x), -mathieu_se(11, q, x), atol=1e-13, rtol=0)
    assert abs(mathieu_se_prime(11, q, 0.0)) > 0


def test_coefficient_series_matches_dlmf_and_numbers():
    """DLMF 28.6.21: ce_0 = 2^(-1/2) (1 - (q/2) cos 2x + q^2 (cos 4x / 32 - 1/16) + ...); numerically at q = 0.1."""
    x, q = sympy.symbols("x q")
    s = mathieu_function_series("ce", 0, 2)
    dlmf = (1 - q / 2 * sympy.cos(2 * x) + q**2 * (sympy.cos(4 * x) / 32 - sympy.Rational(1, 16))) / sympy.sqrt(2)
    assert sympy.simplify(s - dlmf) == 0
    c = mathieu_coefficient_series("se", 3, 12)
    num = mathieu_fourier_coefficients("se", 3, 0.1)
    for k, v in zip(num.index[:4], num.values[:4], strict=True):
        assert abs(float(c[int(k)].subs(q, sympy.Rational(1, 10))) - v) < 1e-13


# ------------------------------------------------------------------------------------------------- exponent
def _monodromy_trace(a, q):
    t = sympy.Symbol("t")
    A = sympy.Matrix([[0, 1], [-(a - 2 * q * sympy.cos(2 * t)), 0]])
    return float(np.trace(monodromy(A, math.pi, rtol=1e-12, atol=1e-14).monodromy)) / 2


def test_exponent_against_monodromy_across_zones():
    """cos(pi nu) = trace(M) / 2 (DLMF 28.2.16) to 1e-11 on a grid crossing stable and unstable zones."""
    seen = set()
    for q in (0.5, 3.0, 12.0):
        for a in np.linspace(-6.0, 30.0, 13):
            r = mathieu_floquet_exponent(a, q)
            assert abs(r.cos_pi_nu - _monodromy_trace(a, q)) < 1e-11 * max(1.0, abs(r.cos_pi_nu))
            assert abs(complex(np.cos(np.pi * complex(r.nu))) - r.cos_pi_nu) < 1e-11 * max(1.0, abs(r.cos_pi_nu))
            seen.add(bool(r.stable))
    assert seen == {True, False}


def test_exponent_zones_and_limits():
    """nu = sqrt(a) at q = 0; nu real in (n, n+1) between a_n and b_{n+1}; n + i mu between b_n and a_n."""
    assert abs(mathieu_exponent(2.25, 0.0) - 1.5) < 1e-14
    q = 4.0
    a1, b2 = mathieu_a(1, q), mathieu_b(2, q)
    nu = mathieu_exponent(0.5 * (a1 + b2), q)
    assert isinstance(nu, float) and 1 < nu < 2
    nu = mathieu_exponent(0.5 * (mathieu_b(2, q) + mathieu_a(2, q)), q)
    assert isinstance(nu, complex) and nu.real == 2 and nu.imag > 0
    assert mathieu_exponent(mathieu_a(0, q) - 1, q).real == 0
    assert abs(mathieu_exponent(3.0, -q) - mathieu_exponent(3.0, q)) == 0  # nu(a, -q) = nu(a, q)


def test_exponent_against_mpmath_ode():
    """Independent route: cos(pi nu) = w_I(pi) by mpmath's Taylor integrator at 25 digits."""
    a, q = 3.7, 1.3
    with mpmath.workdps(25):
        f = mpmath.odefun(lambda x, y: [y[1], -(a - 2 * q * mpmath.cos(2 * x)) * y[0]], 0, [1, 0])
        w1 = f(mpmath.pi)[0]
    assert abs(mathieu_floquet_exponent(a, q).cos_pi_nu - float(w1)) < 1e-13


def test_lambda_me_and_fundamental_solutions():
    """lambda_nu inverts nu(a, q); me_nu solves the ODE; w_I, w_II at pi form the monodromy matrix."""
    q = 2.0
    lam = mathieu_lambda(1.5, q)
    assert abs(mathieu_exponent(lam, q) - 1.5) < 1e-12
    x, h = np.array([0.4, 1.7]), 1e-5
    ypp = (mathieu_me(1.5, q, x + h, derivative=True) - mathieu_me(1.5, q, x - h, derivative=True)) / (2 * h)
    assert np.max(np.abs(ypp + (lam - 2 * q * np.cos(2 * x)) * mathieu_me(1.5, q, x))) < 1e-6
    for a in (0.5, 3.0, mathieu_a(1, q)):  # stable, unstable, and a band edge (integration fallback)
        f = mathieu_fundamental(a, q, math.pi)
        t = sympy.Symbol("t")
        A = sympy.Matrix([[0, 1], [-(a - 2 * q * sympy.cos(2 * t)), 0]])
        assert np.allclose(f.monodromy(), monodromy(A, math.pi, rtol=1e-12, atol=1e-14).monodromy, atol=1e-9)


# ------------------------------------------------------------------------------------------------- modified
def _mc1_reference(func, n, q, z):
    """DLMF 28.23.7 / 28.23.11 (Bessel series in 2h sinh z, normalised by ce(pi/2) or se(pi/2)), 40 digits."""
    idx, v, _lam = ref.coefficients("a" if func == "Mc" else "b", n, q)
    p = idx[0]
    m = (n - p) // 2
    with mpmath.workdps(40):
        u = 2 * mpmath.sqrt(q) * mpmath.sinh(z)
        s = mpmath.fsum(c * mpmath.besselj(k, u) for k, c in zip(idx, v, strict=True))
        trig = mpmath.cos if func == "Mc" else mpmath.sin
        at = mpmath.fsum(c * trig(k * mpmath.pi / 2) for k, c in zip(idx, v, strict=True))
        return float((-1) ** m * s / at)


@pytest.mark.parametrize("func,n,q", [("Mc", 0, 1.0), ("Mc", 2, 25.0), ("Ms", 1, 9.0), ("Mc", 0, 1e4)])
def test_modified_first_kind_against_independent_series(func, n, q):
    """Mc^(1), Ms^(1) (DLMF 28.24) against DLMF 28.23.7/11 at 40 digits: <= 1e-12 relative."""
    for z in (0.3, 1.0, 2.5):
        got = mathieu_modified(func, 1, n, q, z)
        exact = _mc1_reference(func, n, q, z)
        assert abs(got.values - exact) <= 1e-12 * abs(exact)
        assert abs(got.values - exact) <= got.error_estimate + 1e-16


@pytest.mark.parametrize("func,n,q", [("Mc", 0, 1.0), ("Mc", 5, 25.0), ("Ms", 2, 5.0), ("Ms", 10, 100.0)])
def test_modified_wronskian_and_third_kind(func, n, q):
    """W{M^(1), M^(2)} = 2/pi (DLMF 28.20.21); M^(3) = M^(1) + i M^(2) (DLMF 28.20.15)."""
    z = np.array([0.2, 0.7, 1.5, 3.0])
    r1, r2 = mathieu_modified(func, 1, n, q, z), mathieu_modified(func, 2, n, q, z)
    w = r1.values * r2.derivatives - r1.derivatives * r2.values
    assert np.max(np.abs(w * math.pi / 2 - 1)) < 1e-12
    f = mathieu_mc if func == "Mc" else mathieu_ms
    assert np.allclose(f(3, n, q, z), r1.values + 1j * r2.values, rtol=1e-15, atol=0)


def _mc2_reference(n, q, z0, zs):
    """Mc^(2)_2m: value and z-derivative at z0 by the series in Y_2l(2h cosh z) (DLMF 28.23.6, converges for z > 0,
    quickly where cosh z is not close to 1), 22-digit coefficients; carried to the points zs (< z0) by DOP853
    integration of w'' = (a - 2q cosh 2z) w (rtol 2.5e-14)."""
    idx, v, lam = ref.coefficients("a", n, q, dps=22)
    with mpmath.workdps(22):
        h, sign = mpmath.sqrt(q), (-1) ** (n // 2) / mpmath.fsum(v)
        x, dx = 2 * h * mpmath.cosh(z0), 2 * h * mpmath.sinh(z0)
        w = sign * mpmath.fsum(
            (-1) ** i * c * mpmath.bessely(k, x) for i, (k, c) in enumerate(zip(idx, v, strict=True))
        )
        dw = sign * dx * mpmath.fsum((-1) ** i * c * mpmath.bessely(k, x, derivative=1)
                                     for i, (k, c) in enumerate(zip(idx, v, strict=True)))  # fmt: skip
    from scipy.integrate import solve_ivp

    a = float(lam)
    sol = solve_ivp(lambda z, y: [y[1], (a - 2 * q * np.cosh(2 * z)) * y[0]], (z0, min(zs)), [float(w), float(dw)],
                    method="DOP853", rtol=2.5e-14, atol=1e-16, t_eval=sorted(zs, reverse=True))  # fmt: skip
    return list(sol.y[0][::-1]) if list(zs) == sorted(zs) else list(sol.y[0])


def test_modified_second_kind_against_the_cosh_series_and_the_ode():
    """Mc^(2)_10 at q = 100 against DLMF 28.23.6 at z = 0.8, carried by an independent ODE integration to z = 0.25
    (just outside the region where the Bessel-product series is refused): <= 1e-12 relative."""
    zs = (0.25,)
    for z, exact in zip(zs, _mc2_reference(10, 100.0, 0.8, zs), strict=True):
        got = mathieu_modified("Mc", 2, 10, 100.0, z)
        assert abs(got.values - exact) <= 1e-12 * abs(exact)


def test_modified_refuses_instead_of_returning_garbage():
    """Second kind at small z for n = 20, q = 1000 (inside the documented region: the Bessel-product series loses
    digits): ConvergenceError, not a number; the first kind there, and the second kind from z = 0.8 on, are
    returned, with the Wronskian 2/pi (DLMF 28.20.21) to 1e-12."""
    for z in (0.0, 0.1):
        with pytest.raises(ConvergenceError):
            mathieu_mc(2, 20, 1000.0, z)
    z = np.linspace(0.8, 2.0, 25)
    r1, r2 = mathieu_modified("Mc", 1, 20, 1000.0, z), mathieu_modified("Mc", 2, 20, 1000.0, z)
    assert np.max(np.abs((r1.values * r2.derivatives - r1.derivatives * r2.values) * math.pi / 2 - 1)) < 1e-12
    assert np.all(np.isfinite(mathieu_mc(1, 20, 1000.0, np.array([0.0, 0.1]))))


def test_argument_checks():
    with pytest.raises(ParameterError, match="n must be >= 1"):
        mathieu_se(0, 1.0, 0.0)
    with pytest.raises(ParameterError, match="kind"):
        mathieu_function("cs", 1, 1.0, 0.0)
    with pytest.raises(ParameterError, match="q must be > 0"):
        mathieu_mc(1, 0, -1.0, 0.5)
    with pytest.raises(ParameterError, match="nu must not be an integer"):
        mathieu_me(2.0, 1.0, 0.0)
    with pytest.raises(ParameterError, match="x"):
        mathieu_ce(0, 1.0, float("nan"))
