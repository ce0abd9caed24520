"""Right and left series with matrix coefficients by Sylvester's formula (Bulgakov (1954), §1.30, eqs. (1.279),
(1.280), (1.287), (1.288)); references: the direct sums ``Σ a_k z^k`` / ``Σ z^k a_k`` and SymPy's ``Matrix.exp``."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla
import sympy as sp

from symosc.algebra import matrix_coefficient_function
from symosc.errors import ModelError, ParameterError

l = sp.Symbol("l")
A0 = sp.Matrix([[1, 2], [0, 1]])
A1 = sp.Matrix([[0, 1], [1, 0]])
A2 = sp.Matrix([[2, -1], [3, 0]])
PHI = A0 + A1 * l + A2 * l**2


@pytest.mark.parametrize(
    "z",
    [
        sp.Matrix([[4, -3], [2, -1]]),  # simple roots 1, 2: (1.279)-(1.280)
        sp.Matrix([[3, 1], [0, 3]]),  # Jordan block: confluent (1.287)-(1.288)
        sp.Matrix([[0, 1], [-2, -2]]),  # complex roots -1 ± i
    ],
)
def test_right_and_left_polynomials_match_direct_sums(z):
    right = matrix_coefficient_function(PHI, l, z)
    left = matrix_coefficient_function(PHI, l, z, side="left")
    assert (right - (A0 + A1 * z + A2 * z**2)).applyfunc(sp.simplify).is_zero_matrix
    assert (left - (A0 + z * A1 + z**2 * A2)).applyfunc(sp.simplify).is_zero_matrix
    assert right != left  # the coefficients do not commute with z


def test_rectangular_coefficients_and_derogatory_z():
    """A 1x3 right polynomial at a derogatory 3x3 z (double root 2 with linear divisors)."""
    z = sp.Matrix([[2, 0, 0], [0, 2, 0], [1, 1, 3]])
    a = [sp.Matrix([[1, 0, 2]]), sp.Matrix([[0, 1, -1]]), sp.Matrix([[3, 1, 0]])]
    phi = a[0] + a[1] * l + a[2] * l**3
    assert matrix_coefficient_function(phi, l, z) == a[0] + a[1] * z + a[2] * z**3


def test_power_series_against_truncated_sum():
    """The right series Σ C^k z^k / k! (matrix coefficients C^k/k!, closed form φ(λ) = exp(λC)) at a Jordan block,
    against the numerically summed series."""
    C = sp.Matrix([[0, 1], [-1, 0]])
    phi = (C * l).exp()  # [[cos l, sin l], [-sin l, cos l]]
    z = sp.Matrix([[sp.Rational(1, 2), 1], [0, sp.Rational(1, 2)]])
    val = np.array(matrix_coefficient_function(phi, l, z).evalf(), dtype=float)
    Cn, zn = np.array(C, dtype=float), np.array(z, dtype=float)
    direct = sum(
        np.linalg.matrix_power(Cn, k) @ np.linalg.matrix_power(zn, k) / float(sp.factorial(k)) for k in range(40)
    )
    assert np.allclose(val, direct, atol=1e-14, rtol=0)
    # scalar coefficients reduce to the ordinary matrix function
    B = sp.Matrix([[1, 2], [3, 4]])
    got = np.array(matrix_coefficient_function(B * sp.exp(l), l, z).evalf(), dtype=float)
    assert np.allclose(got, np.array(B, dtype=float) @ sla.expm(zn), atol=1e-13, rtol=0)


def test_errors():
    z = sp.Matrix([[0, 1], [0, 0]])
    with pytest.raises(ModelError, match="not analytic"):
        matrix_coefficient_function(A0 * sp.sqrt(l), l, z)
    with pytest.raises(ParameterError, match="side"):
        matrix_coefficient_function(PHI, l, z, side="middle")
    with pytest.raises(ParameterError, match="floating-point"):
        matrix_coefficient_function(PHI, l, sp.Matrix([[0.5, 1], [0, 1]]))
    with pytest.raises(ModelError, match="columns"):
        matrix_coefficient_function(PHI, l, sp.eye(3))
