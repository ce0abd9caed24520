"""The matrizant (Peano–Baker series), its a-priori bound and the numeric fallback (Bulgakov §1.38)."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import scipy.linalg as sla
import sympy as sp

from symosc.algebra import matrizant, matrizant_numeric
from symosc.errors import ConvergenceError, ModelError, ParameterError

t = sp.Symbol("t")


def _airy_reference(t1: float) -> np.ndarray:
    """Ω(t1) for X' = [[0, 1], [-t, 0]] X from the closed form: y'' = -t y has solutions Ai(-t), Bi(-t)."""
    with mpmath.workdps(30):

        def fund(s):
            s = mpmath.mpf(s)
            return mpmath.matrix(
                [
                    [mpmath.airyai(-s), mpmath.airybi(-s)],
                    [-mpmath.airyai(-s, derivative=1), -mpmath.airybi(-s, derivative=1)],
                ]
            )

        W = fund(t1) * mpmath.inverse(fund(0))
        return np.array(W.tolist(), dtype=float)


def test_airy_example():
    """Bulgakov §1.38 / report §3 item 13: f = [[0,1],[-t,0]]; the 25-term series at t = 1.5 against Airy
    functions, det Ω = exp(∫ tr f) = 1 (1.321), and the a-priori bound really bounds the error."""
    A = sp.Matrix([[0, 1], [-t, 0]])
    M = matrizant(A, t, 0, order=25)
    ref = _airy_reference(1.5)
    val = M.evaluate(1.5)
    np.testing.assert_allclose(val, ref, rtol=0, atol=1e-13)
    assert abs(np.linalg.det(val) - 1) < 1e-13
    low = matrizant(A, t, 0, order=6)
    err = np.max(np.abs(low.evaluate(1.5) - ref))
    assert err <= low.bound(1.5, U=1.5)  # the book's bound is crude (7.6 here vs 1.2e-3) but it is a bound
    assert M.bound(1.5, U=1.5) < low.bound(1.5, U=1.5)
    np.testing.assert_allclose(matrizant_numeric(A, t, 0.0, 1.5), ref, atol=1e-9)


def test_constant_matrix_is_exponential():
    """Constant f = a gives Ω = exp(a (t - t0)) (report §3 item 13), against scipy.linalg.expm."""
    a = sp.Matrix([[0, 1], [-4, -sp.Rational(1, 5)]])
    M = matrizant(a, t, 1, order=22)
    an = np.array(a, dtype=float)
    np.testing.assert_allclose(M.evaluate(1.8), sla.expm(an * 0.8), atol=1e-12)
    assert "Matrizant" in repr(M) and M.terms[0] == sp.eye(2)


def test_liouville_with_trace_and_fallback():
    """Non-zero trace: det Ω = exp(∫ tr f) (1.321). A long interval exceeds tol -> numeric fallback, or
    ConvergenceError without fallback."""
    A = sp.Matrix([[-t, 1], [0, sp.Rational(1, 2)]])
    M = matrizant(A, t, 0, order=20)
    d = np.linalg.det(M.evaluate(1.0))
    assert abs(d - np.exp(-0.5 + 0.5)) < 1e-12  # ∫0^1 (-s + 1/2) ds = 0
    long_val = M.evaluate(8.0, tol=1e-10)  # bound is huge at t = 8: integrates numerically
    assert abs(np.linalg.det(long_val) - np.exp(-32 + 4)) < 1e-8 * np.exp(-28) + 1e-20
    with pytest.raises(ConvergenceError, match="a-priori bound"):
        M.evaluate(8.0, tol=1e-10, fallback=False)


def test_parameters_and_errors():
    k = sp.Symbol("k")
    A = sp.Matrix([[0, 1], [-k, 0]])
    M = matrizant(A, t, 0, order=25)
    c = np.cos(2.0 * 1.0)
    assert abs(M.evaluate(1.0, {"k": 4.0})[0, 0] - c) < 1e-12
    assert abs(matrizant_numeric(A, t, 0, 1.0, values={k: 4.0})[0, 0] - c) < 1e-9
    with pytest.raises(ParameterError, match="missing values for: k"):
        M.evaluate(1.0)
    with pytest.raises(ParameterError, match="order"):
        matrizant(A, t, 0, order=-1)
    with pytest.raises(ModelError, match="closed form"):
        matrizant(sp.Matrix([[sp.exp(sp.sin(t))]]), t, 0, order=2)
