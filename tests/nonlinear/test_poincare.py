"""Poincaré's method for self-oscillations (Bulgakov 1954, seed 004, ch. 5 D; report seed-bulgakov-part2.md §2.1)."""

from __future__ import annotations

from fractions import Fraction

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.errors import ModelError, ParameterError
from symosc.nonlinear import limit_cycle, numeric_limit_cycle

x, v, eps = sp.symbols("x v eps")
R = sp.Rational
VDP = (1 - x**2) * v


def test_van_der_pol_known_coefficients():
    """Bulgakov §5.22 (5.282), (5.284): A* = 2, alpha = -mu^2/16; higher terms from Andersen & Geer (1982)."""
    lc = limit_cycle(VDP, 6)
    assert lc.generating_amplitude == 2
    assert lc.frequency.coefficients[:7] == (1, 0, R(-1, 16), 0, R(17, 3072), 0, R(35, 884736))
    assert lc.amplitude.coefficients[:5] == (1, 0, R(1, 192), 0, R(-1033, 1105920))  # times A* = 2
    assert lc.amplitude.coefficient(2) == R(1, 96)
    assert lc.amplitude.coefficient(4) == R(-1033, 552960)
    assert lc.frequency.order == lc.amplitude.order == 6
    assert lc.floquet_exponent.order == 7
    assert lc.stable


def test_van_der_pol_first_correction_book_5_283():
    """Bulgakov (5.283) with kappa = lambda = omega = 1: q = 2 cos u + (mu/4)(3 sin u - sin 3u) + O(mu^2)."""
    tau = sp.Symbol("tau")
    lc = limit_cycle(VDP, 2)
    first = lc.solution(1, tau)
    assert sp.simplify(first - (2 * sp.cos(tau) + eps / 4 * (3 * sp.sin(tau) - sp.sin(3 * tau)))) == 0
    # the whole second-order solution satisfies the ODE up to O(eps^3) (independent check by differentiation)
    xs = lc.solution(2, tau)
    om = lc.frequency.expr
    resid = om**2 * sp.diff(xs, tau, 2) + xs - eps * (1 - xs**2) * om * sp.diff(xs, tau)
    ser = sp.series(sp.expand(resid), eps, 0, 3).removeO()
    assert sp.simplify(sp.expand(sp.expand_trig(ser))) == 0


def test_book_cubic_generator_with_parameters_scaled():
    """Bulgakov (5.280)-(5.284): F = kappa q - lambda q^3/3 gives A* = 2 sqrt(kappa/lambda).

    And alpha = -kappa^2 mu^2/16 (seed 004, §5.22)."""
    kappa, lam = R(1, 2), R(9, 8)
    lc = limit_cycle((kappa - lam * x**2) * v, 4)
    assert lc.generating_amplitude == 2 * sp.sqrt(kappa / lam)
    assert lc.frequency.coefficients[2] == -(kappa**2) / 16
    ref = limit_cycle(VDP, 4)
    for k in range(5):
        assert lc.frequency.coefficients[k] == ref.frequency.coefficients[k] * kappa**k


def test_independent_of_how_f_is_written():
    forms = [VDP, v - x**2 * v, -(x - 1) * (x + 1) * v, sp.factor(v - v * x**2), (1 - x) * (1 + x) * v]
    ref = limit_cycle(forms[0], 8)
    for f in forms[1:]:
        lc = limit_cycle(f, 8)
        assert lc.frequency.coefficients == ref.frequency.coefficients
        assert lc.amplitude.coefficients == ref.amplitude.coefficients
        assert lc.harmonics() == ref.harmonics()


def test_rayleigh_has_the_van_der_pol_frequency():
    """y'' + y = eps (y' - y'^3/3) differentiates into van der Pol for x = y': the frequencies coincide exactly."""
    ray = limit_cycle(v - v**3 / 3, 10)
    vdp = limit_cycle(VDP, 10)
    assert ray.generating_amplitude == 2
    assert ray.frequency.coefficients == vdp.frequency.coefficients
    assert ray.amplitude.coefficients != vdp.amplitude.coefficients


def test_order_24_exact_and_arithmetics_agree():
    """Target: exact rationals to eps^24 (Andersen & Geer's order); mpmath and float reproduce them."""
    ex = limit_cycle(VDP, 24)
    assert all(isinstance(c, sp.Rational) for c in ex.frequency.coefficients)
    mp = limit_cycle(VDP, 24, arithmetic="mpmath", dps=40)
    fl = limit_cycle(VDP, 24, arithmetic="float")
    for a, b, c in zip(ex.frequency.coefficients, mp.frequency.coefficients, fl.frequency.coefficients, strict=True):
        scale = max(abs(float(a)), 1e-300)
        assert abs(sp.N(a - b, 50)) <= 1e-33 * scale + 1e-60
        assert abs(float(a) - float(c)) <= 1e-10 * scale
    for a, b in zip(ex.amplitude.coefficients, mp.amplitude.coefficients, strict=True):
        assert abs(sp.N(a - b, 50)) <= 1e-33 * max(abs(float(a)), 1e-300) + 1e-60


def test_order_60_float_against_mpmath():
    fl = limit_cycle(VDP, 64, arithmetic="float")
    mp = limit_cycle(VDP, 64, arithmetic="mpmath", dps=30)
    assert fl.order == 64
    # double precision loses digits slowly with the order (measured: 1e-12 relative at order 32, 1e-8 at 48)
    for k, (a, b) in enumerate(zip(fl.frequency.coefficients, mp.frequency.coefficients, strict=True)):
        tol = 1e-10 if k <= 32 else 1e-6
        assert abs(float(a) - float(b)) <= tol * abs(float(b)) + 1e-300


def test_radius_of_convergence_estimate():
    """Coefficients to eps^24 (exact) and eps^64 (float) give the same radius; both say |eps| ~ 1.85."""
    r24 = limit_cycle(VDP, 24).frequency.radius_of_convergence()
    r64 = limit_cycle(VDP, 64, arithmetic="float").frequency.radius_of_convergence()
    assert r24.even and r64.even
    assert abs(r24.radius - r64.radius) < 0.03 * r64.radius
    assert 1.7 < r64.radius < 2.0


def test_two_cycles_stability_signs():
    """f = (-4 + 6x^2 - x^4) v: H(A) = 4A - 3A^3/2 + A^5/8, roots 2 (unstable) and 2 sqrt 2 (stable)."""
    f = (-4 + 6 * x**2 - x**4) * v
    with pytest.raises(ModelError, match="several positive roots"):
        limit_cycle(f, 2)
    inner = limit_cycle(f, 10, amplitude0=2)
    outer = limit_cycle(f, 10, amplitude0=2.9)
    assert inner.generating_amplitude == 2 and not inner.stable
    assert outer.generating_amplitude == 2 * sp.sqrt(2) and outer.stable
    assert float(inner.floquet_exponent.coefficients[1]) > 0 > float(outer.floquet_exponent.coefficients[1])
    e = 0.05
    for lc, stable in ((inner, False), (outer, True)):
        cyc = numeric_limit_cycle(f, e, guess=float(lc.generating_amplitude))
        assert abs(cyc.amplitude - lc.amplitude.evaluate(e)) < 1e-10
        assert (cyc.multiplier < 1) == stable


def test_reversed_sign_is_unstable():
    lc = limit_cycle((x**2 - 1) * v, 4)
    assert lc.generating_amplitude == 2 and not lc.stable
    assert lc.floquet_exponent.coefficients[1] == 1


def test_f_depending_on_eps_and_even_terms():
    """f = (1 - x^2) v + x^2 + eps x^3 (asymmetric, eps-dependent); checked against the numeric cycle.

    The even term shrinks the radius of convergence (about 0.4 here), so the check is made at eps = 0.05.
    """
    f = (1 - x**2) * v + x**2 + eps * x**3
    lc = limit_cycle(f, 16)
    assert lc.frequency.radius_of_convergence().radius < 1
    e = 0.05
    cyc = numeric_limit_cycle(f, e)
    assert abs(cyc.amplitude - lc.amplitude.evaluate(e)) < 1e-10
    assert abs(cyc.frequency - lc.frequency.evaluate(e)) < 1e-10
    assert abs(cyc.amplitude - lc.amplitude.evaluate(e, 4)) > 1e-8  # truncation at order 4 is visibly worse


def test_irrational_amplitude_needs_mpmath():
    f = (1 - 2 * x**2) * v + x**2
    with pytest.raises(ParameterError, match="not rational"):
        limit_cycle(f, 3)
    lc = limit_cycle(f, 14, arithmetic="mpmath", dps=30)
    assert lc.generating_amplitude == sp.sqrt(2)
    cyc = numeric_limit_cycle(f, 0.05, guess=1.4)
    assert abs(cyc.amplitude - lc.amplitude.evaluate(0.05)) < 1e-10


def test_symmetric_irrational_amplitude_stays_exact():
    lc = limit_cycle((1 - 2 * x**2) * v, 4)
    assert lc.generating_amplitude == sp.sqrt(2)
    assert lc.amplitude.coefficient(2) == sp.sqrt(2) * R(1, 192)
    assert lc.frequency.coefficients[2] == R(-1, 16)


@pytest.mark.parametrize(
    ("f", "order", "err", "match"),
    [
        (VDP, 0, ParameterError, "order"),
        (VDP, 2.5, ParameterError, "order"),
        (sp.sin(x) * v, 2, ModelError, "polynomial"),
        (-(x**3), 2, ModelError, "lindstedt"),
        (-v, 2, ModelError, "no limit cycle"),
        ((2 - 4 * x**2 + x**4) * v, 2, ModelError, "multiple root"),
        ((sp.Symbol("mu") - x**2) * v, 2, ParameterError, "mu"),
        (sp.Integer(0), 2, ModelError, "f = 0"),
    ],
)
def test_bad_input(f, order, err, match):
    with pytest.raises(err, match=match):
        limit_cycle(f, order)


def test_unknown_arithmetic():
    with pytest.raises(ParameterError, match="arithmetic"):
        limit_cycle(VDP, 2, arithmetic="decimal")


@settings(max_examples=15, deadline=None)
@given(
    c=st.sampled_from([Fraction(1, 2), Fraction(3), Fraction(2, 3)]),
    b=st.sampled_from([Fraction(1), Fraction(1, 4), Fraction(4)]),
)
def test_scaling_identity(c, b):
    """c*f(x/c, v/c) has the same frequency and c times the amplitude (x -> c x leaves the ODE form invariant)."""
    cq, bq = sp.Rational(c.numerator, c.denominator), sp.Rational(b.numerator, b.denominator)
    f = (1 - bq * x**2) * v + x**2 / 3
    g = sp.expand(cq * f.subs({x: x / cq, v: v / cq}, simultaneous=True))
    lf, lg = limit_cycle(f, 5), limit_cycle(g, 5)
    assert lf.frequency.coefficients == lg.frequency.coefficients
    for a1, a2 in zip(lf.amplitude.coefficients, lg.amplitude.coefficients, strict=True):
        assert sp.simplify(lg.amplitude.factor * a2 - cq * lf.amplitude.factor * a1) == 0


def test_repr_and_latex():
    lc = limit_cycle(VDP, 8)
    assert "A* = 2" in repr(lc) and "stable" in repr(lc)
    assert "O(eps**9)" in repr(lc.frequency)
    assert lc._repr_latex_().startswith("$")
    assert lc.period.coefficient(2) == 2 * sp.pi / 16
    assert lc.frequency_squared.coefficients[2] == R(-1, 8)
    with pytest.raises(IndexError):
        lc.frequency.coefficient(9)
    with pytest.raises(ParameterError):
        lc.solution(9)


def test_evaluate_solution_matches_symbolic():
    lc = limit_cycle(VDP, 4)
    tau = sp.Symbol("tau")
    expr = lc.solution(4, tau)
    num = lc.evaluate_solution(0.3, np.array([0.0, 1.0]))
    assert np.allclose(num[0], [float(expr.subs({tau: t, eps: 0.3})) for t in (0.0, 1.0)], rtol=1e-13)
    assert abs(num[1][0]) < 1e-14  # phase fixed by x'(0) = 0
    assert abs(mpmath.mpf(lc.amplitude.evaluate(0.3, dps=30)) - mpmath.mpf(num[0][0])) < 1e-13


# ---------------------------------------------------------------------------------------------------------------
# n degrees of freedom (Bulgakov §§12.1-12.6; report seed-bulgakov-part3b.md §2.7)
# ---------------------------------------------------------------------------------------------------------------
q1, q2, v1, v2 = sp.symbols("q1 q2 v1 v2")


def test_ndof_coupled_van_der_pol_in_phase_mode():
    """Two identical van der Pol oscillators coupled by a spring: the in-phase cycle is q1 = q2 = vdP cycle.

    The frequency must equal the one-DOF van der Pol series (exact rationals, computed by the 1-DOF recurrence) and
    the modal amplitude is sqrt(2) times the vdP amplitude; the anti-phase mode decays with exponent -eps/2."""
    from symosc.nonlinear import periodic_solution_ndof

    sol = periodic_solution_ndof(
        [[1, 0], [0, 1]], [[2, -1], [-1, 2]], [(1 - q1**2) * v1, (1 - q2**2) * v2], [q1, q2], [v1, v2], 10
    )
    ref = limit_cycle(VDP, 10)
    for a, b in zip(sol.frequency.coefficients, ref.frequency.coefficients, strict=True):
        assert abs(float(a) - float(b)) < 1e-14
    for a, b in zip(sol.amplitude.coefficients, ref.amplitude.coefficients, strict=True):
        assert abs(float(a) - float(b)) < 1e-13  # factor: modal amplitude sqrt(2)*2 = A*
    assert abs(sol.generating_amplitude - 2 * np.sqrt(2)) < 1e-13
    assert sol.stable
    ex = sol.exponents_at(0.1)
    assert np.allclose(sorted(ex.real), [-0.1, -0.05, -0.05, 0.0], atol=1e-12)
    x12 = sol.solution(1)
    assert sp.simplify(x12[0] - x12[1]) == 0


def test_ndof_asymmetric_system_against_shooting():
    """A system whose cycle leaves every invariant subspace: series vs numerical orbit and Floquet exponents."""
    from symosc.nonlinear import periodic_solution_ndof

    K = [[R(6, 5), R(-1, 5)], [R(-1, 5), R(21, 5)]]
    f = [(1 - q1**2) * v1 + q2**2, -v2 + q1**3]
    sol = periodic_solution_ndof([[1, 0], [0, 1]], K, f, [q1, q2], [v1, v2], 16)
    mp = periodic_solution_ndof([[1, 0], [0, 1]], K, f, [q1, q2], [v1, v2], 8, arithmetic="mpmath", dps=30)
    for a, b in zip(sol.frequency.coefficients[:9], mp.frequency.coefficients, strict=True):
        assert abs(float(a) - float(b)) <= 1e-10 * max(1.0, abs(float(b)))
    errs = []
    for e in (0.05, 0.1):
        r = sol.validate(e)
        assert r["frequency_error"] < 1e-8 and r["amplitude_error"] < 1e-7
        errs.append(np.max(np.abs(r["exponents_numeric_real"] - r["exponents_series_real"])))
    # first-order exponents: error O(eps^2) (ratio ~4 when eps doubles)
    assert errs[0] < 1e-3 and 2.5 < errs[1] / errs[0] < 6


@pytest.mark.parametrize(
    ("M", "K", "match"),
    [
        ([[1, 0], [0, 1]], [[1, 0], [0, 4]], "internal resonance"),
        ([[1, 0], [0, -1]], [[1, 0], [0, 3]], "positive definite"),
        ([[1, 0], [0, 1]], [[-1, 0], [0, 3]], "does not oscillate"),
    ],
)
def test_ndof_bad_input(M, K, match):
    from symosc.nonlinear import periodic_solution_ndof

    with pytest.raises(ModelError, match=match):
        periodic_solution_ndof(M, K, [(1 - q1**2) * v1, -v2], [q1, q2], [v1, v2], 2)


def test_ndof_parameter_errors():
    from symosc.nonlinear import periodic_solution_ndof

    with pytest.raises(ParameterError, match="arithmetic"):
        periodic_solution_ndof([[1]], [[1]], [(1 - q1**2) * v1], [q1], [v1], 2, arithmetic="exact")
    with pytest.raises(ParameterError, match="order"):
        periodic_solution_ndof([[1]], [[1]], [(1 - q1**2) * v1], [q1], [v1], 0)
    with pytest.raises(ParameterError, match="numeric"):
        periodic_solution_ndof([[sp.Symbol("m")]], [[1]], [(1 - q1**2) * v1], [q1], [v1], 2)


def test_part3b_T14_amplitude_function_values():
    """Report part 3b §3 T14 (Bulgakov §12.3 sanity values): G(A) = (1/pi) Im int psi e^{-iu} du = -H(A) for vdP:
    G(1.5) = 0.65625, G(2) = 0, G(2.5) = -1.40625."""
    A = sp.Symbol("A")
    H = limit_cycle(VDP, 1).amplitude_equation
    assert [-H.subs(A, a) for a in (R(3, 2), 2, R(5, 2))] == [R(65625, 100000), 0, R(-140625, 100000)]


def test_symbol_spellings_are_equivalent():
    """x with assumptions, x(t) with Derivative, and x_dot all mean the same coordinate/velocity."""
    from symosc.symbols import dot

    ref = limit_cycle(VDP, 4).frequency.coefficients
    xr = sp.Symbol("x", real=True)
    t = sp.Symbol("t")
    xf = sp.Function("x")(t)
    for f in ((1 - xr**2) * dot(xr), (1 - xf**2) * xf.diff(t), (1 - xr**2) * sp.Symbol("v", real=True)):
        assert limit_cycle(f, 4).frequency.coefficients == ref


@settings(max_examples=20, deadline=None)
@given(
    a=st.lists(st.integers(-5, 5), min_size=1, max_size=5),
    b=st.lists(st.integers(-5, 5), min_size=1, max_size=4),
    tau=st.floats(0, 6.3),
)
def test_fourier_product_is_pointwise_product(a, b, tau):
    """The convolution product of trigonometric polynomials equals the product of their values (exact)."""
    from symosc.nonlinear.series._arith.trig import ExactArith

    ar = ExactArith()

    def build(cs):
        t_ = ar.new(0)
        for k, c in enumerate(cs):
            t_ = ar.add_coeff(t_, "c", k, Fraction(c, 3))
            if k:
                t_ = ar.add_coeff(t_, "s", k, Fraction(c - k, 2))
        return t_

    def value(t_):
        cs, ss = ar.values(t_)
        return sum(
            float(c) * np.cos(k * tau) + float(s) * np.sin(k * tau) for k, (c, s) in enumerate(zip(cs, ss, strict=True))
        )

    A_, B_ = build(a), build(b)
    assert abs(value(ar.mul(A_, B_)) - value(A_) * value(B_)) < 1e-9 * (1 + abs(value(A_) * value(B_)))


def test_ndof_single_degree_of_freedom_scaling():
    """n = 1 with M = 2, K = 8: q'' + q = (eps/4)(1 - q^2) q' in t' = 2t, so omega(eps) = 2 omega_vdP(eps/4)."""
    from symosc.nonlinear import periodic_solution_ndof

    sol = periodic_solution_ndof([[2]], [[8]], [(1 - q1**2) * v1], [q1], [v1], 8, arithmetic="mpmath", dps=25)
    ref = limit_cycle(VDP, 8)
    for e in (0.2, 1.0):
        assert abs(sol.frequency.evaluate(e) - 2 * ref.frequency.evaluate(e / 4)) < 1e-15
    assert abs(sol.generating_amplitude - 2 * np.sqrt(2)) < 1e-12  # modal amplitude: sqrt(M) * 2
    assert sol.stable and sol._repr_latex_().startswith("$")
