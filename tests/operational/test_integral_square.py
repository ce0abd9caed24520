"""Integral square estimates (Bulgakov §2.32, seed 004; report §2.6 and §3 item 11)."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.linalg import solve_continuous_lyapunov

from symosc.errors import ModelError, ParameterError
from symosc.operational import cross_integral, integral_square

p = sp.Symbol("p")


def test_book_example_2_153_symbolic():
    """(2.152)-(2.153): (a p + b)/(k0 (p^2 + 2 zeta w p + w^2)) -> (a^2 w^2 + b^2)/(4 k0^2 w^3 zeta), all methods."""
    a, b, k0, w, z = sp.symbols("a b k0 omega zeta", positive=True)
    expected = (a**2 * w**2 + b**2) / (4 * k0**2 * w**3 * z)
    for method in ("auto", "hurwitz", "closed", "residues"):
        val = integral_square(a * p + b, k0 * (p**2 + 2 * z * w * p + w**2), p, method=method)
        assert sp.simplify(val - expected) == 0, method


@pytest.mark.parametrize("zeta,expected", [(0.3, 0.0470679), (1.0, 0.0141204), (2.5, 0.0056481)])
def test_book_example_numbers(zeta, expected):
    """Report §2.6: a=0.7, b=1.3, k0=2, w=3 -> 0.0470679, 0.0141204, 0.0056481 (7 printed digits)."""
    val = integral_square(0.7 * p + 1.3, 2 * (p**2 + 2 * zeta * 3 * p + 9), p)
    assert abs(float(val) - expected) < 5e-8


def test_spot_value_i3():
    """Report §3 item 11: H = (p+1)^3, U = 1 -> x = t^2 e^-t/2, I3 = 3/16 (every method, exact)."""
    for method in ("auto", "hurwitz", "closed", "residues"):
        assert integral_square(1, (p + 1) ** 3, p, method=method) == sp.Rational(3, 16)


@settings(max_examples=12, deadline=None)
@given(
    st.integers(1, 5),
    st.lists(st.integers(1, 4), min_size=5, max_size=5),
    st.lists(st.integers(-3, 3), min_size=5, max_size=5),
)
def test_methods_agree_exactly(s, roots, ucoef):
    """Property: residues, closed forms (s <= 4) and the Hurwitz determinant agree exactly (s <= 5)."""
    h = sp.expand(sp.Mul(*[(p + r) for r in roots[:s]]) + 0)
    u = sum(c * p**k for k, c in enumerate(ucoef[:s]))
    if u == 0:
        return
    hw = integral_square(u, h, p, method="hurwitz")
    assert hw.is_Rational
    assert sp.simplify(integral_square(u, h, p, method="residues") - hw) == 0
    if s <= 4:
        assert integral_square(u, h, p, method="closed") == hw


def _random_hurwitz(rng, s):
    roots = []
    while len(roots) < s:
        if s - len(roots) >= 2 and rng.random() < 0.6:
            re, im = -rng.uniform(0.3, 2.0), rng.uniform(0.2, 2.5)
            roots += [complex(re, im), complex(re, -im)]
        else:
            roots.append(complex(-rng.uniform(0.3, 2.0), 0))
    return np.real(np.poly(roots)) * rng.uniform(0.5, 2.0)


def _quadrature(u, h):
    """Integral(x^2, 0, oo) by mpmath quadrature of x(t) = sum of residues (roots by mpmath.polyroots)."""
    with mpmath.workdps(30):
        hc = [mpmath.mpf(float(c)) for c in h]
        uc = [mpmath.mpf(float(c)) for c in u]
        rts = mpmath.polyroots(hc, maxsteps=200, extraprec=60)
        dh = [c * (len(hc) - 1 - i) for i, c in enumerate(hc[:-1])]
        res = [mpmath.polyval(uc, r) / mpmath.polyval(dh, r) for r in rts]

        def x(tv):
            return mpmath.re(sum(c * mpmath.exp(r * tv) for c, r in zip(res, rts, strict=True)))

        decay = min(-mpmath.re(r) for r in rts)
        tmax = 80 / decay
        pts = mpmath.linspace(0, tmax, 60)
        return mpmath.quad(lambda tv: x(tv) ** 2, pts)


def _gramian(u, h):
    """Integral(x^2, 0, oo) as ``c P c^T``, P the controllability Gramian of the companion realisation of u/h
    (``A P + P A^T + b b^T = 0``, SciPy's Lyapunov solver): a third method, by linear algebra."""
    h, u = np.asarray(h, float), np.asarray(u, float)
    s = len(h) - 1
    A = np.zeros((s, s))
    A[:-1, 1:] = np.eye(s - 1)
    A[-1, :] = -h[:0:-1] / h[0]
    b = np.zeros(s)
    b[-1] = 1 / h[0]
    c = np.zeros(s)
    c[: len(u)] = u[::-1]
    return c @ solve_continuous_lyapunov(A, -np.outer(b, b)) @ c


def test_random_hurwitz_degrees_1_to_8_vs_quadrature():
    """Target: integral_square matches independent values to 1e-10 for random Hurwitz denominators of
    degree 1..8 (float coefficients): the controllability Gramian for every degree, and numeric quadrature of
    x(t)^2 (mpmath, 30 digits) for degree 8.  (The Gramian agrees with the quadrature to 2e-13 at every degree;
    quadrature at each degree made this test ten times longer.)"""
    rng = np.random.default_rng(4)
    for s in range(1, 9):
        for _ in range(2):
            h = _random_hurwitz(rng, s)
            u = rng.uniform(-1, 1, size=rng.integers(1, s + 1))
            num = sum(float(c) * p ** (len(u) - 1 - i) for i, c in enumerate(u))
            den = sum(float(c) * p ** (s - i) for i, c in enumerate(h))
            refs = [_gramian(u, h)] + ([float(_quadrature(u, h))] if s == 8 else [])
            for method in ("hurwitz", "residues"):
                val = float(integral_square(num, den, p, method=method))
                for ref in refs:
                    assert abs(val - ref) <= 1e-10 * abs(ref), (s, method, val, ref)


@pytest.mark.parametrize("zeta", [1e-2, 1e-4, 1e-6, 1e-8])
def test_near_stability_boundary(zeta):
    """Stability note 9: I2 ~ 1/zeta as damping -> 0, still exact (float data converted exactly)."""
    val = integral_square(1.0, p**2 + 2 * zeta * p + 1.0, p)
    expected = 1 / (4 * zeta)  # (2.153) with a=0, b=1, k0=1, w=1
    assert abs(float(val) - expected) <= 1e-13 * expected


def test_carson_convention():
    """image='carson': the rational function is X(p); p/(p+2) <-> exp(-2t), integral 1/4; and the Laplace
    reading of the same function is refused as not strictly proper (with a hint)."""
    assert integral_square(p, p + 2, p, image="carson") == sp.Rational(1, 4)
    with pytest.raises(ModelError, match="image='carson'"):
        integral_square(p, p + 2, p)
    with pytest.raises(ModelError, match="not Hurwitz"):
        integral_square(1, p + 2, p, image="carson")  # step response: x -> 1/2, integral diverges


@pytest.mark.parametrize("den", [p**2 - 1, p**2 + 1, p**3 + p**2 + p + 2, p**2 + 3 * p])
def test_non_hurwitz_rejected(den):
    """Non-Hurwitz H (growth, undamped pair, Hurwitz minor < 0, root at 0) -> clear error, never a number."""
    with pytest.raises(ModelError, match="not Hurwitz"):
        integral_square(1, den, p)


def test_bad_input():
    with pytest.raises(ModelError, match="strictly proper"):
        integral_square(p**2, p**2 + p + 1, p)
    with pytest.raises(ParameterError, match="unknown method"):
        integral_square(1, p + 1, p, method="magic")
    with pytest.raises(ParameterError, match=r"orders 1\.\.4"):
        integral_square(1, (p + 1) ** 5, p, method="closed")
    with pytest.raises(ParameterError, match="image must be"):
        integral_square(1, p + 1, p, image="fourier")
    assert integral_square(0, p + 1, p) == 0


def test_old_hurwitz_names_warn_and_forward_to_symosc_linear():
    """One name per concept: symosc.operational.hurwitz_matrix/is_hurwitz are deprecated aliases of symosc.linear."""
    import symosc.operational as op
    from symosc._deprecation import reset_warnings
    from symosc.linear import hurwitz_matrix

    reset_warnings()
    with pytest.warns(DeprecationWarning, match=r"symosc\.linear\.hurwitz_matrix"):
        old_matrix = op.hurwitz_matrix
    # the old function's orientation Hw[i, j] = k_(2j-i), written out by hand for 1 p^3 + 2 p^2 + 3 p + 4
    assert old_matrix(p**3 + 2 * p**2 + 3 * p + 4, p) == sp.Matrix([[2, 4, 0], [1, 3, 0], [0, 2, 4]])
    assert hurwitz_matrix([1, 2, 3, 4]) == sp.Matrix([[2, 1, 0], [4, 3, 2], [0, 0, 4]])
    with pytest.warns(DeprecationWarning, match=r"symosc\.linear\.hurwitz"):
        is_hurwitz = op.is_hurwitz
    assert is_hurwitz(-(p**2) - p - 1, p) is True
    assert is_hurwitz(p**2 + 1, p) is False
    k = sp.Symbol("k", real=True)
    assert is_hurwitz(p**2 + k * p + 1, p) is None
    with pytest.raises(AttributeError):
        op.no_such_name  # noqa: B018


def test_cross_integral_vs_quadrature():
    """(2.150): Integral(x y) for x <-> 1/(p^2+p+1), y <-> (p+2)/((p+1)(p+3)) (Laplace images), by scipy quad."""
    from scipy.integrate import quad

    t = sp.Symbol("t")
    x = sp.inverse_laplace_transform(1 / (p**2 + p + 1), p, t).subs(sp.Heaviside(t), 1)
    y = sp.inverse_laplace_transform((p + 2) / ((p + 1) * (p + 3)), p, t).subs(sp.Heaviside(t), 1)
    f = sp.lambdify(t, x * y)
    ref, _ = quad(f, 0, 60, epsabs=1e-14, epsrel=1e-13, limit=200)
    for method in ("auto", "hurwitz", "residues"):
        val = cross_integral(1, p**2 + p + 1, p + 2, (p + 1) * (p + 3), p, method=method)
        assert abs(float(val) - ref) < 1e-11
    assert cross_integral(1, p + 1, 1, p + 1, p) == integral_square(1, p + 1, p)


@settings(max_examples=10, deadline=None)
@given(st.lists(st.integers(-4, 4), min_size=2, max_size=2), st.lists(st.integers(-4, 4), min_size=3, max_size=3))
def test_polarization_identity(ux, uy):
    """Property (2.150)-(2.151): I[x + y] = I[x] + 2 Integral(x y) + I[y], exactly, with different denominators."""
    hx, hy = (p + 1) * (p**2 + p + 2), (p + 3) ** 2 * (p + 1)
    nx = ux[0] * p + ux[1]
    ny = uy[0] * p**2 + uy[1] * p + uy[2]
    lhs = integral_square(sp.cancel(nx * hy + ny * hx), hx * hy, p)
    rhs = integral_square(nx, hx, p) + 2 * cross_integral(nx, hx, ny, hy, p) + integral_square(ny, hy, p)
    assert lhs.is_Rational and rhs.is_Rational and lhs == rhs


def test_pairwise_root_sum_product_orlando_2_165():
    """Bulgakov (2.165)-(2.167), Orlando's formula: against the product over 30-digit numeric roots for degrees 2..6,
    and zero on a stability boundary (a root pair ±i)."""
    import itertools
    import random

    import mpmath

    from symosc.operational import pairwise_root_sum_product

    p = sp.Symbol("p")
    rng = random.Random(3)
    for s in range(2, 7):
        coeffs = [rng.randint(1, 5) for _ in range(s + 1)]
        poly = sum(c * p ** (s - k) for k, c in enumerate(coeffs))
        with mpmath.workdps(30):
            roots = mpmath.polyroots(coeffs, maxsteps=200, extraprec=60)
            ref = mpmath.fprod(a + b for a, b in itertools.combinations(roots, 2))
        got = pairwise_root_sum_product(poly, p)
        assert abs(complex(got) - complex(ref)) <= 1e-20 * max(1.0, abs(complex(ref)))
    assert pairwise_root_sum_product((p**2 + 1) * (p + 3), p) == 0
