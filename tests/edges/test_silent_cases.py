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
