"""The matrizant as a product of short Peano–Baker series (Bulgakov (1954), §1.38, eqs. (1.319)–(1.321)).

References: Airy functions in 30-digit mpmath (x'' + t x = 0), SciPy's ``expm`` for a constant A, and Liouville's
formula for the determinant computed by quadrature.
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
import scipy.linalg as sla
import sympy as sp

from symosc.algebra import matrizant_product
from symosc.errors import ConvergenceError, ParameterError

t = sp.Symbol("t")


def test_airy_over_a_long_interval():
    """x'' + t x = 0 on [0, 6]: Ω = Φ(6) Φ(0)⁻¹ with Φ = [[Ai(-t), Bi(-t)], [-Ai'(-t), -Bi'(-t)]]."""
    res = matrizant_product(sp.Matrix([[0, 1], [-t, 0]]), t, 0.0, 6.0, order=10, tol=1e-10)
    with mp.workdps(30):

        def phi(x):
            return mp.matrix([[mp.airyai(-x), mp.airybi(-x)], [-mp.airyai(-x, 1), -mp.airybi(-x, 1)]])

        ref = np.array((phi(6) * mp.inverse(phi(0))).tolist(), dtype=float)
    assert np.max(np.abs(res.value - ref)) < 1e-9
    assert res.bound <= 1e-10 and res.pieces > 1
    assert res.det_error < 1e-12  # tr A = 0: det Ω = 1


def test_constant_matrix_is_the_exponential_and_liouville_holds():
    A = sp.Matrix([[0, 1], [-4, sp.Rational(-1, 10)]])
    res = matrizant_product(A, t, 1.0, 21.0, order=10, tol=1e-12)
    ref = sla.expm(np.array(A, dtype=float) * 20.0)
    assert np.allclose(res.value, ref, atol=1e-11, rtol=0)
    assert abs(np.linalg.det(res.value) - np.exp(-0.1 * 20)) < 1e-12
    assert res.det_error < 1e-10


def test_time_dependent_trace_and_parameters():
    """A(t) with a time-varying trace and a parameter: det Ω = exp(∫ tr A) = exp(-k(t1² - t0²)/2 ...) checked."""
    k = sp.Symbol("k")
    A = sp.Matrix([[-k * t, 1], [-1, 0]])
    res = matrizant_product(A, t, 0.0, 3.0, order=6, tol=1e-11, values={"k": 0.2})
    assert res.det_error < 1e-10
    assert abs(np.linalg.det(res.value) - np.exp(-0.2 * 9 / 2)) < 1e-10


def test_errors():
    with pytest.raises(ConvergenceError, match="max_pieces"):
        matrizant_product(sp.Matrix([[0, 1], [-100, 0]]), t, 0.0, 100.0, order=2, tol=1e-14, max_pieces=10)
    with pytest.raises(ParameterError, match="missing values"):
        matrizant_product(sp.Matrix([[0, sp.Symbol("w")], [-1, 0]]), t, 0.0, 1.0)
    with pytest.raises(ParameterError, match="t1"):
        matrizant_product(sp.Matrix([[0, 1], [-1, 0]]), t, 0.0, float("nan"))
