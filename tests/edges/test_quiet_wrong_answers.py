"""Answers that used to come back quietly wrong now come with a warning or an error (each case found by a probe)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
import sympy as sp

from symosc.algebra import matrix_function, matrizant
from symosc.errors import AccuracyWarning, ConvergenceError, IdentificationError, ModelError
from symosc.identification import era, esprit, matrix_pencil, prony
from symosc.operational import first_expansion

ESTIMATORS = [prony, era, matrix_pencil, esprit]


def test_matrizant_far_outside_its_validity_raises_and_near_it_warns():
    t = sp.Symbol("t")
    series = matrizant(sp.Matrix([[0, 1], [-1, 0]]), t, order=8)
    with pytest.raises(ConvergenceError, match="more than the value"):
        series.evaluate(100.0)  # returned 2.47e11 (true cos 100 = 0.862)
    with pytest.warns(AccuracyWarning, match="the last term is"):
        value = series.evaluate(1.0)[0, 0]
    assert abs(value - math.cos(1.0)) < 1e-6
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert abs(series.evaluate(0.01)[0, 0] - math.cos(0.01)) < 1e-15


def test_first_expansion_far_from_zero_raises_or_is_exact():
    p = sp.Symbol("p")
    with pytest.raises(ConvergenceError, match="raise order"):
        first_expansion(p / (p + 1), p, sp.Float(50), order=10)  # returned -4.5e9 (true exp(-50))
    with pytest.raises(ConvergenceError, match="rounding"):
        first_expansion(p / (p + 1), p, sp.Float(30), order=130)  # enough terms, but floats cancel
    exact = first_expansion(p / (p + 1), p, sp.Integer(30), order=130)
    assert float(exact) == pytest.approx(math.exp(-30), rel=1e-12)


@pytest.mark.parametrize("estimator", ESTIMATORS)
def test_pure_noise_is_not_reported_as_modes_quietly(estimator):
    record = np.random.default_rng(7).standard_normal(400)
    with pytest.warns(AccuracyWarning, match="no more than"):
        estimator(record, 0.02, 2)


@pytest.mark.parametrize("estimator", ESTIMATORS)
def test_a_record_without_oscillation_is_refused(estimator):
    with pytest.raises(IdentificationError):
        estimator(np.ones(400), 0.02, 1)


@pytest.mark.parametrize("estimator", [matrix_pencil, esprit, era])
def test_an_undersampled_record_warns_about_aliasing(estimator):
    dt = 0.7  # Nyquist pi/dt = 4.49 rad/s: a 7 rad/s mode folds to 1.98 rad/s
    t = np.arange(200) * dt
    with pytest.warns(AccuracyWarning, match="samples per period"):
        est = estimator(np.exp(-0.05 * t) * np.cos(7.0 * t), dt, 1)
    assert est.frequencies[0] == pytest.approx(2 * math.pi / dt - 7.0, rel=1e-6)  # the alias itself


def test_a_well_sampled_noisy_record_gives_no_warning():
    dt = 0.01
    t = np.arange(2000) * dt
    y = np.exp(-0.05 * t) * np.cos(3 * t) + 0.5 * np.exp(-0.02 * t) * np.cos(7 * t + 1)
    y = y + 0.05 * np.random.default_rng(3).standard_normal(t.size)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for estimator in ESTIMATORS:
            assert estimator(y, dt, 2).frequencies == pytest.approx([3.0, 7.0], rel=2e-2)


def test_prony_decimation_keeps_a_mode_80_db_below_the_strong_one():
    dt = 0.005
    t = np.arange(8000) * dt
    y = np.exp(-0.01 * t) * np.cos(3 * t) + 1e-4 * np.exp(-0.01 * t) * np.cos(13 * t + 0.3)
    est = prony(y, dt, 2, constant=False)  # decimated: was 13 rad/s reported as about 3.6 rad/s
    assert est.frequencies == pytest.approx([3.0, 13.0], rel=1e-6)
    assert est.details["decimate"] > 1


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("f", [sp.sqrt, sp.log])
def test_functions_not_analytic_at_a_perturbed_jordan_block_raise(seed, f):
    """A float matrix similar to the Jordan block J_2(0): sqrt and log do not exist; exp does (E + A)."""
    rng = np.random.default_rng(seed)
    S = rng.standard_normal((2, 2))
    A = S @ np.array([[0.0, 1.0], [0.0, 0.0]]) @ np.linalg.inv(S)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            matrix_function(sp.Matrix(A), f)
        except (ConvergenceError, ModelError):
            refused = True
        else:
            refused = False
    assert refused or any(issubclass(w.category, AccuracyWarning) and "not analytic" in str(w.message) for w in caught)
    exp_a = np.array(matrix_function(sp.Matrix(A), sp.exp).evalf(), dtype=float)
    np.testing.assert_allclose(exp_a, np.eye(2) + A, atol=1e-12 * (1 + np.abs(A).max()))
