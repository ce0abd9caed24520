"""Regression tests: inputs that used to hang, return a silently wrong number or leak a generic exception.

Every expected value comes from an independent computation (closed forms, mpmath, numpy).
"""

from __future__ import annotations

import warnings

import mpmath
import numpy as np
import pytest
import sympy as sp

from symosc.errors import ParameterError, SeriesWarning

p, t = sp.symbols("p t")


def test_matrizant_numeric_rejects_nan_parameters():
    """NaN parameters used to make the integrator run forever."""
    from symosc.algebra import matrizant_numeric

    a = sp.Symbol("a")
    A = sp.Matrix([[0, 1], [-a, 0]])
    with pytest.raises(ParameterError, match="non-finite"):
        matrizant_numeric(A, t, 0.0, 1.0, values={a: float("nan")})
    with pytest.raises(ParameterError, match="t1"):
        matrizant_numeric(A, t, 0.0, float("nan"), values={a: 1.0})
    # a finite call still agrees with the closed form (rotation by t)
    X = matrizant_numeric(A, t, 0.0, 1.0, values={a: 1.0})
    np.testing.assert_allclose(X, [[np.cos(1), np.sin(1)], [-np.sin(1), np.cos(1)]], atol=1e-9)


def test_validate_lindstedt_rejects_nan():
    from symosc.nonlinear import lindstedt, validate_lindstedt

    x = sp.Symbol("x")
    ls = lindstedt(-(x**3), 4)
    for eps, amp in [(float("nan"), 1.0), (0.1, float("inf"))]:
        with pytest.raises(ParameterError, match="finite"):
            validate_lindstedt(ls, eps, amp)


def test_series_warning_beyond_radius():
    """van der Pol's amplitude series at eps = 10 (estimated radius ~2) and the Mathieu a_0 series at q = 50
    (radius 1.4688, Meixner & Schafke) warn; inside the radius nothing is said."""
    from symosc.nonlinear import limit_cycle
    from symosc.periodic.ince_strutt import series_boundary

    x, v = sp.symbols("x v")
    lc = limit_cycle((1 - x**2) * v, 10)
    with pytest.warns(SeriesWarning, match="radius of convergence"):
        lc.amplitude.evaluate(10.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert abs(lc.amplitude.evaluate(0.1) - 2.0) < 1e-3  # amplitude 2 + O(eps^2)
    f = series_boundary("a", 0, 4)
    with pytest.warns(SeriesWarning, match=r"a_0\(q\)"):
        f(50.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        f(0.5)


def test_heaviside_expand_near_double_pole_is_confluent():
    """(p+1)(p+1+δ), δ = 1e-12: the original (e^-t - e^-(1+δ)t)/δ evaluated in double precision after lambdify must
    match 50-digit mpmath (it used to be two ±1e12 terms that cancel)."""
    from symosc.operational import heaviside_expand

    d = 1e-12
    x = heaviside_expand(p / ((p + 1) * (p + 1 + d)), p, t)
    f = sp.lambdify(t, x, "numpy")
    ts = np.array([0.1, 1.0, 5.0, 40.0])
    dd = mpmath.mpf(1 + d) - 1  # the float's exact gap
    with mpmath.workdps(50):
        ref = [float((mpmath.exp(-tv) - mpmath.exp(-(1 + dd) * tv)) / dd) for tv in ts]
    np.testing.assert_allclose(f(ts), ref, rtol=1e-13)
    assert len(x.atoms(sp.exp)) == 1  # one exponential times a polynomial in t: the confluent form


def test_invert_numeric_long_time_undamped():
    """cos(100): de Hoog and Talbot both used to return ~1e-23 with converged=True."""
    from symosc.operational import invert_numeric

    r = invert_numeric(p**2 / (p**2 + 1), p, [100.0, 1000.0])
    np.testing.assert_allclose(r.values, np.cos([100.0, 1000.0]), rtol=1e-12)
    assert r.method == "residues"
    # a non-rational image: J0(t) at t = 100, with the working precision raised automatically
    r = invert_numeric(p / sp.sqrt(p**2 + 1), p, [100.0])
    assert abs(r.values[0] - float(mpmath.besselj(0, 100))) < 1e-12
    assert r.error_estimate[0] < 1e-10
    from symosc.errors import ConvergenceError

    with pytest.raises(ConvergenceError, match="imaginary axis"):
        invert_numeric(p / sp.sqrt(p**2 + 1), p, [2000.0])
    with pytest.raises(ParameterError, match="finite"):
        invert_numeric(p / (p + 1), p, [float("nan")])


def test_inverse_carson_of_a_division_by_zero():
    from symosc.operational import carson, inverse_carson

    with pytest.raises(ParameterError, match="division by zero"):
        inverse_carson(p / 0, p, t)
    with pytest.raises(ParameterError, match="None"):
        carson(None, t, p)


def test_monodromy_rejects_negative_tolerance():
    from symosc.periodic import monodromy
    from symosc.symbols import t as tt

    A = sp.Matrix([[0, 1], [-1 - sp.Rational(1, 10) * sp.cos(tt), 0]])
    with pytest.raises(ParameterError, match="rtol"):
        monodromy(A, 2 * sp.pi, rtol=-1)


def test_danilevsky_tiny_pivot():
    """A 1e-17 pivot used to put a 1e19 coefficient into the polynomial; compare with numpy.poly."""
    from symosc.algebra import danilevsky

    lam = sp.Symbol("l")
    for last in ([0.7, 1e-17, 2.0], [1e-17, 1e-17, 2.0]):
        A = sp.Matrix([[1.0, 2.0, 0.5], [3.0, 1.0, 2.0], last])
        coeffs = [float(c) for c in danilevsky(A, lam).all_coeffs()]
        np.testing.assert_allclose(coeffs, np.poly(np.array(A, dtype=float)), rtol=1e-12, atol=1e-12)


def test_pendulum_and_linear_model_arguments():
    from symosc.models import n_link_pendulum

    with pytest.raises(ParameterError, match="inverted"):
        n_link_pendulum(2, inverted="yes")
    lin = n_link_pendulum(2).linearize()
    with pytest.raises(
        ParameterError, match=r"missing values for: g; unknown .* gg \(misspelt\? 'gg' -> 'g'\); valid names"
    ):
        lin.natural_frequencies({"m1": 1, "m2": 1, "l1": 1, "l2": 1, "gg": 1})
    with pytest.raises(ParameterError, match="mapping"):
        lin.natural_frequencies(None)
    # the double pendulum with unit data: omega^2 = 2 -+ sqrt(2)
    w = lin.natural_frequencies({"m1": 1, "m2": 1, "l1": 1, "l2": 1, "g": 1})
    np.testing.assert_allclose(w, np.sqrt([2 - np.sqrt(2), 2 + np.sqrt(2)]), rtol=1e-12)


@pytest.mark.parametrize("snr_db", [40, 60])
def test_prony_oversampled_noisy_record(snr_db):
    """Modes at 3 and 7 rad/s, dt = 0.02 s (omega_d/omega_max = 45): the default decimate='auto' applies rule (45);
    with decimate=1 the result used to be off by a factor ~17 (40 dB) or be called 'undersampled' (60 dB)."""
    from symosc.identification import prony

    dt = 0.02
    tt = np.arange(0, 10, dt)
    y0 = np.exp(-0.1 * tt) * np.cos(3 * tt) + 0.5 * np.exp(-0.2 * tt) * np.cos(7 * tt + 0.3)
    for seed in range(3):
        rng = np.random.default_rng(seed)
        y = y0 + rng.normal(size=tt.size) * np.std(y0) * 10 ** (-snr_db / 20)
        est = prony(y, dt, n_modes=2)
        assert est.details["decimate"] > 1
        np.testing.assert_allclose(est.frequencies, [3.0, 7.0], rtol=2e-3)
        np.testing.assert_allclose(est.damping, [0.1, 0.2], atol=0.01)


def test_ill_conditioned_rigid_chain_warns():
    """A rigid 3-link chain whose last link is 1e-6 of the others: the whitening by the mass matrix loses digits;
    an AccuracyWarning says so, while an ordinary chain stays silent."""
    from symosc.errors import AccuracyWarning
    from symosc.models import n_link_pendulum

    lin = n_link_pendulum(3, links="rigid").linearize()

    def values(r):
        return {"m1": 1, "m2": 1, "m3": r, "l1": 1, "l2": 1, "lc1": 0.5, "lc2": 0.5, "lc3": r / 2, "I1": 1 / 12,
                "I2": 1 / 12, "I3": r**3 / 12, "g": 9.81}  # fmt: skip

    with pytest.warns(AccuracyWarning, match="ill-conditioned"):
        lin.natural_frequencies(values(1e-6))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        w = lin.natural_frequencies(values(0.5))
    M, _, K = lin.matrices(values(0.5))
    import scipy.linalg as sla

    np.testing.assert_allclose(w, np.sqrt(sla.eigh(K, M, eigvals_only=True)), rtol=1e-10)


def test_very_large_series_orders_are_refused_up_front():
    """Order 500 used to run for minutes (Mathieu order 300: 72 s; limit cycle order 100: 65 s)."""
    from symosc.nonlinear import limit_cycle
    from symosc.periodic import mathieu_series_a

    x, v = sp.symbols("x v")
    with pytest.raises(ParameterError, match="supported range"):
        mathieu_series_a(0, 500)
    with pytest.raises(ParameterError, match="supported range"):
        limit_cycle((1 - x**2) * v, 500)
    # inside the range the exact coefficients are right: a_0(q) = -q^2/2 + 7 q^4/128 - ... (DLMF 28.6.1)
    q = sp.Symbol("q")
    a0 = sp.expand(mathieu_series_a(0, 6, symbol=q))
    assert a0 == -(q**2) / 2 + sp.Rational(7, 128) * q**4 - sp.Rational(29, 2304) * q**6


def test_generic_symbolic_3x3_spectral_decomposition_refused_up_front():
    """A generic symbolic 3x3 used to run for minutes; the refusal names the cause (a symbolic cubic factor), while
    a symbolic matrix whose characteristic polynomial splits into low-degree factors still works."""
    from symosc.algebra import spectral_decomposition
    from symosc.errors import ModelError

    a, b, c, d, e, f, g, h, i = sp.symbols("a:i")
    with pytest.raises(ModelError, match="degree 3 with symbolic coefficients"):
        spectral_decomposition(sp.Matrix([[a, b, c], [d, e, f], [g, h, i]]))
    w = sp.Symbol("w", positive=True)
    S = spectral_decomposition(sp.Matrix([[0, 1, 0], [-(w**2), 0, 0], [0, 0, a]]))
    assert sp.simplify(sum(S.projectors, sp.zeros(3, 3)) - sp.eye(3)) == sp.zeros(3, 3)


# ------------------------------------------------------------------------------------------------------------------
# nonsense parameters that used to be accepted (a NaN, an empty array, a verdict for 0/0) or to leak generic errors


def _nonsense_calls():
    from symosc.identification import quasi_optimal_control, real_modes
    from symosc.linear import lienard_chipart, nyquist, stability_margins, string_frequencies, string_modes
    from symosc.mechanics import LagrangianSystem
    from symosc.networks import Parallel, Series, biquadratic_is_positive_real
    from symosc.symbols import dot

    x = sp.Symbol("x")
    return {
        "lienard_chipart form=True": lambda: lienard_chipart([1, 3, 3, 1], form=True),
        "lienard_chipart leading 0.0": lambda: lienard_chipart([0.0, 1, 2], form=3),
        "nyquist n_points=1": lambda: nyquist([4], [1, 1, 0], n_points=1),
        "stability_margins improper": lambda: stability_margins([1, 0, 0, 1], [1, 1, 1]),
        "string tension=-1": lambda: string_frequencies(3, tension=-1),
        "string mass=-2": lambda: string_frequencies(3, mass=-2.0),
        "string spacing=-1": lambda: string_frequencies(3, spacing=-1),
        "string_modes(-1)": lambda: string_modes(-1),
        "biquadratic 0/0": lambda: biquadratic_is_positive_real(0, 0, 0, 0, 0, 0),
        "biquadratic 0.0/0.0": lambda: biquadratic_is_positive_real(*[0.0] * 6),
        "dissipation='abc'": lambda: LagrangianSystem(dot(x) ** 2 / 2, x**2 / 2, [x], dissipation="abc"),
        "quasi_optimal a=-1": lambda: quasi_optimal_control(0.1, 0.2, -1.0, 1.0),
        "quasi_optimal u_m=0": lambda: quasi_optimal_control(0.1, 0.2, 1.0, 0.0),
        "real_modes(None)": lambda: real_modes(None),
        "Series()": lambda: Series(),
        "Parallel()": lambda: Parallel(),
    }


@pytest.mark.parametrize("case", list(_nonsense_calls()))
def test_nonsense_parameters_are_refused(case):
    """Each call used to return nonsense (NaN frequencies, an empty mode matrix, True for 0/0, margins of an improper
    loop, a control for a negative radius, ``array(nan)``) or leak a TypeError/ValueError/ZeroDivisionError (a
    leading ``0.0``: SymPy's ``Float(0.0) == 0`` is False); now a symosc error that names the argument."""
    from symosc.errors import SymoscError

    with pytest.raises(SymoscError):
        _nonsense_calls()[case]()


def test_valid_neighbours_of_the_refused_calls():
    """The same functions with valid arguments, against independent computations: the loaded string against the
    eigenvalues of its chain matrices (scipy), Liénard–Chipart's third form against the roots (numpy)."""
    import scipy.linalg as sla

    from symosc.linear import chain_matrices, lienard_chipart, string_frequencies

    M, K = chain_matrices([2.0] * 4, [3.0 / 0.5] * 5)  # m = 2, P/h = 3/0.5
    expected = np.sqrt(sla.eigh(K, M, eigvals_only=True))
    np.testing.assert_allclose(string_frequencies(4, tension=3.0, mass=2.0, spacing=0.5), expected, rtol=1e-12)
    for c in ([1, 3, 3, 1], [1, 1, 4, 1, 2], [1, 2, -1, 3], [2, 5, 9, 7, 3, 1]):
        assert lienard_chipart(c, form=3).stable == bool(np.all(np.roots(c).real < 0))


# ------------------------------------------------------------------------------------------------------------------
def _rightmost_root(rho: float, sigma: float) -> float:
    """Largest real part of the roots of g^2 + rho g + sigma e^(-g) with Re g > -4, by Newton's method from a grid
    of starting points covering the disc that holds all of them (|g|^2 <= |rho||g| + |sigma| e^4)."""
    radius = abs(rho) + np.sqrt(abs(sigma) * np.exp(4.0)) + 2.0
    re, im = np.meshgrid(np.linspace(-4.0, radius, 30), np.linspace(0.0, radius, 30))
    g = (re + 1j * im).ravel()
    with np.errstate(all="ignore"):
        for _ in range(80):
            e = sigma * np.exp(-g)
            g = g - (g * g + rho * g + e) / (2 * g + rho - e)
        ok = np.isfinite(g) & (np.abs(g * g + rho * g + sigma * np.exp(-g)) < 1e-9) & (g.real > -4.0)
    return float(np.max(g[ok].real))


@pytest.mark.parametrize("rho", [0, -1, sp.Rational(1, 5), 2])
def test_andronov_maier_optimum_is_the_best_degree_of_stability(rho):
    """Bulgakov (1954), §4.17, eq. (4.149): s* = 1 + rho/2 - sqrt(1 + rho^2/4).  Independently: with sigma* the
    rightmost root of g^2 + rho g + sigma e^-g is the double root -s*, and a gain 5 % (or 0.01) off in either
    direction moves the rightmost root to the right.  rho = 0 used to give s = 2 (whose sigma = -4 e^-2 leaves a
    root in the right half-plane), negative rho the larger root."""
    from symosc.nonlinear import andronov_maier_optimum

    opt = andronov_maier_optimum(rho)
    s_star, sigma_star = float(opt["s"]), float(opt["sigma"])
    r = float(rho)
    assert s_star == pytest.approx(1 + r / 2 - np.sqrt(1 + r * r / 4), abs=1e-15)
    assert _rightmost_root(r, sigma_star) == pytest.approx(-s_star, abs=1e-4)
    d = 0.05 * abs(sigma_star) or 0.01
    assert _rightmost_root(r, sigma_star + d) > -s_star + 1e-5  # simple roots there: Newton is accurate to ~1e-12
    assert _rightmost_root(r, sigma_star - d) > -s_star + 1e-5


def test_andronov_maier_optimum_symbolic_rho():
    from symosc.nonlinear import andronov_maier_optimum

    rho = sp.Symbol("rho", positive=True)
    opt = andronov_maier_optimum(rho)
    assert sp.simplify(opt["s"] - (1 + rho / 2 - sp.sqrt(1 + rho**2 / 4))) == 0
    fifth = sp.Rational(1, 5)
    assert sp.simplify(opt["sigma"].subs(rho, fifth) - andronov_maier_optimum(fifth)["sigma"]) == 0


# ------------------------------------------------------------------------------------------------------------------
def test_requests_beyond_the_machine_memory_are_refused_with_the_estimate():
    """min_time_1dof((0, 0), 1e6, 1e-6) used to try to allocate 3.6 TiB of switching times (MemoryError)."""
    import os

    from symosc._validate import physical_memory
    from symosc.identification import min_time_1dof

    assert physical_memory() <= os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    with pytest.raises(ParameterError, match=r"switches .* would need about [\d.]+ TiB of memory, more than"):
        min_time_1dof((0.0, 0.0), 1e6, 1e-6)
    # pumping from rest to a = 4 u_m N takes N full periods (Belyakov 2005, eq. 76: 4 u_m gained per period)
    assert min_time_1dof((0.0, 0.0), 4e3, 1.0).time == pytest.approx(1e3 * 2 * np.pi, rel=1e-9)


def test_cramer_rao_bound_on_coincident_modes():
    """Two modes with the same pole used to raise numpy's LinAlgError; a well-separated pair still gives the inverse
    of the Fisher matrix (compared with numpy's inverse)."""
    from symosc.errors import IdentificationError
    from symosc.identification import cramer_rao_bound

    with pytest.raises(IdentificationError, match="coincide"):
        cramer_rao_bound([1.0, 1.0], [0.1, 0.1], [1.0, 0.5], [0.0, 0.3], 0.1, 200, 0.01)
    b = cramer_rao_bound([1.0, 2.5], [0.1, 0.05], [1.0, 0.5], [0.0, 0.3], 0.1, 200, 0.01)
    inv = np.diag(np.linalg.inv(b.fisher))
    np.testing.assert_allclose(np.concatenate([b.damping, b.frequency]), inv[:4], rtol=1e-9)


def test_eps_series_methods_raise_symosc_errors():
    """evaluate_pade and radius_of_convergence raised ValueError, coefficient IndexError, and coefficient(-1)
    silently returned the last coefficient."""
    from symosc.errors import SymoscError
    from symosc.nonlinear import EpsSeries, limit_cycle

    x, v = sp.symbols("x v")
    w = limit_cycle((1 - x**2) * v, 8).frequency
    with pytest.raises(SymoscError, match="m \\+ n"):
        w.evaluate_pade(1.0, 10, 10)
    with pytest.raises(SymoscError, match="too few nonzero coefficients"):
        EpsSeries((1, 1, 0, 0), sp.Symbol("eps"), 3).radius_of_convergence()
    with pytest.raises(SymoscError, match="order 8 only"):
        w.coefficient(9)
    with pytest.raises(IndexError):  # still an IndexError for callers that caught one
        w.coefficient(9)
    with pytest.raises(ParameterError, match="k"):
        w.coefficient(-1)
    assert w.coefficient(2) == sp.Rational(-1, 16)  # omega = 1 - eps^2/16 + ... (Bulgakov (1954), §5.22)


def test_series_warns_where_its_tail_has_not_converged():
    """x'' + x = eps((1 - x^2) x' - x^3), frequency to order 24: the estimated radius is 0.2009, so eps = 0.2 used to
    pass silently although the last terms are still +-2e-3.  The warning's estimated error must match the true error
    (the numeric cycle, direct integration) within a factor 3; at eps = 0.1 the sum is silent and right to 1e-9."""
    import re

    from symosc.nonlinear import limit_cycle, numeric_limit_cycle

    x, v = sp.symbols("x v")
    f = (1 - x**2) * v - x**3
    w = limit_cycle(f, 24).frequency
    assert w.radius_of_convergence().radius > 0.2
    with pytest.warns(SeriesWarning, match="has not converged") as info:
        value = w.evaluate(0.2)
    estimate = float(re.search(r"estimated truncation error is ([\d.e+-]+)", str(info[0].message)).group(1))
    error = abs(value - numeric_limit_cycle(f, 0.2).frequency)
    assert error / 3 < estimate < 3 * error
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert w.evaluate(0.1) == pytest.approx(numeric_limit_cycle(f, 0.1).frequency, abs=1e-9)


def test_hurwitz_exactly_on_the_boundary_is_near_boundary():
    """(D^2 + b^2)(D + a)(D^2 + D + c) has the roots +-ib on the imaginary axis (numpy confirms); its Hurwitz minor
    Delta_4 is exactly 0, and the float margin of the Routh pivots (-4e-9 for a = 1, b = 100, c = 1) used to leave
    near_boundary False."""
    from symosc.linear import hurwitz, lienard_chipart

    D = sp.Symbol("D")
    for a, b, c in [(1, 100, 1), (1, 1000, 50), (2, 100, 5), (2, 1000, 1), (7, 3, 2000)]:
        coeffs = [int(k) for k in sp.Poly(sp.expand((D**2 + b**2) * (D + a) * (D**2 + D + c)), D).all_coeffs()]
        assert np.max(np.roots(coeffs).real) == pytest.approx(0.0, abs=1e-6 * b)
        for verdict in (hurwitz(coeffs), lienard_chipart(coeffs, form=2)):
            assert verdict.stable is False and verdict.margin == 0.0 and verdict.near_boundary is True


def _symmetric_top():
    from symosc.mechanics import LagrangianSystem, routh_reduction
    from symosc.symbols import dot

    th, ph, ps = sp.symbols("theta phi psi", real=True)
    I1, I3, mgl = 1.3, 0.4, 2.0 * 9.81 * 0.25
    T = sp.Float(I1) / 2 * (dot(th) ** 2 + dot(ph) ** 2 * sp.sin(th) ** 2)
    T += sp.Float(I3) / 2 * (dot(ps) + dot(ph) * sp.cos(th)) ** 2
    return routh_reduction(LagrangianSystem(T, sp.Float(mgl) * sp.cos(th), [th, ph, ps]), [ph, ps]), th, (I1, I3, mgl)


def test_float_steady_precessions_of_the_top_are_accepted():
    """Steady precessions of the heavy symmetric top computed in floats (I1 phi'^2 cos(theta) - I3 w3 phi' + m g l = 0,
    the slow root): the residual dV_R/dtheta ~ 4e-12 (5e-16 of its terms) used to refuse 10 of these 20.  A point
    off by 1e-7 in a momentum is still refused."""
    from symosc.errors import ModelError

    red, th, (I1, I3, mgl) = _symmetric_top()
    rng = np.random.default_rng(1)
    for _ in range(20):
        theta0, w3 = rng.uniform(0.2, 1.3), rng.uniform(20.0, 60.0)
        a, b = I1 * np.cos(theta0), -I3 * w3
        phid = (-b - np.sqrt(b * b - 4 * a * mgl)) / (2 * a)
        momenta = {"p_phi": I1 * phid * np.sin(theta0) ** 2 + I3 * w3 * np.cos(theta0), "p_psi": I3 * w3}
        red.steady_motion({th: theta0}, momenta)
    momenta["p_phi"] *= 1 + 1e-7
    with pytest.raises(ModelError, match="not a steady motion"):
        red.steady_motion({th: theta0}, momenta)


def test_action_variable_of_an_unbound_orbit_is_refused():
    """H = (p^2 - q^2)/2 and a Kepler orbit of positive energy used to return complex actions; a bound Kepler orbit
    (h < 0) agrees with the quadrature of action_variable_numeric."""
    from symosc.errors import ModelError
    from symosc.mechanics import action_variable, action_variable_numeric

    q, p = sp.symbols("q p", real=True)
    k, ell = sp.symbols("k ell", positive=True)
    with pytest.raises(ModelError, match="not a libration"):
        action_variable((p**2 - q**2) / 2, q, p)
    H = p**2 / 2 - k / q + ell**2 / (2 * q**2)
    with pytest.raises(ModelError, match="not a libration"):
        action_variable(H, q, p, sp.Symbol("h", positive=True))
    h = sp.Symbol("h", negative=True)
    J = action_variable(H, q, p, h).action
    values = {k: 1.0, ell: 0.5}
    exact = float(J.subs({h: -0.3, **values}))
    r1, r2 = [float(r) for r in sp.solve(sp.Eq(H.subs(p, 0).subs(values), -0.3), q)]
    numeric, _ = action_variable_numeric(H, q, p, -0.3, values, (r1 * 1.01, r2 * 0.99))
    assert float(numeric) == pytest.approx(exact, rel=1e-12)
