"""Matrix power series (Bulgakov §1.28, §1.30) against scipy.linalg and symosc's matrix_function."""

import numpy as np
import pytest
import scipy.linalg
import sympy as sp

from symosc.algebra import matrix_function, matrix_power_series
from symosc.errors import ConvergenceError

k = sp.Symbol("k")
LOG1P = sp.Piecewise((0, sp.Eq(k, 0)), ((-1) ** (k + 1) / k, True))
A = np.array([[0.1, 0.6, 0.0], [-0.2, 0.3, 0.1], [0.05, 0.0, -0.4]])


def test_exp_series_vs_scipy_expm():
    S = matrix_power_series(A * 3, 1 / sp.factorial(k), float("inf"))
    assert np.allclose(S, scipy.linalg.expm(A * 3), rtol=1e-13, atol=1e-14)


def test_log_series_vs_scipy_logm_and_matrix_function():
    S = matrix_power_series(A, LOG1P, 1, tol=1e-16, max_terms=20000)
    assert np.allclose(S, scipy.linalg.logm(np.eye(3) + A), rtol=1e-12, atol=1e-13)
    x = sp.Symbol("x")
    ref = np.array(matrix_function(sp.nsimplify(sp.Matrix(A)), sp.log(1 + x)).evalf(30).tolist(), dtype=complex)
    assert np.allclose(S, ref.real, rtol=1e-12, atol=1e-13)


def test_divergence_names_spectral_radius():
    B = np.array([[0.0, 1.0], [-1.5, 0.0]])  # eigenvalues ±i·sqrt(1.5)
    with pytest.raises(ConvergenceError, match=r"spectral radius ρ\(A\) = 1.22474"):
        matrix_power_series(B, LOG1P, 1)


def test_too_few_terms_reports_achieved():
    with pytest.raises(ConvergenceError) as info:
        matrix_power_series(np.diag([0.99, 0.0]), LOG1P, 1, max_terms=50)
    assert info.value.achieved is not None and info.value.achieved > 1e-15
