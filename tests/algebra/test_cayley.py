"""Cayley real form (Bulgakov §1.16, §1.28) against SymPy's Matrix.exp and scipy.linalg."""

import numpy as np
import pytest
import scipy.linalg
import sympy as sp

from symosc.algebra import cayley_real_form, real_matrix_function
from symosc.errors import ModelError

x = sp.Symbol("x")
t = sp.Symbol("t", real=True)
A3 = sp.Matrix([[0, 1, 0], [-5, -2, 0], [1, 0, 3]])


def test_real_form_similarity_and_blocks():
    T, Q = cayley_real_form(A3)
    assert all(e.is_real for e in T) and all(e.is_real for e in Q)
    assert (T * Q * T.inv() - A3).applyfunc(sp.simplify) == sp.zeros(3)
    # the 2x2 block represents -1 + 2i, the eigenvalue of A3 with positive imaginary part (SymPy's eigenvals)
    roots = A3.eigenvals()
    assert sp.Integer(3) in roots and (-1 + 2 * sp.I) in roots
    blocks = {(Q[i, i], Q[i, i + 1]) for i in range(2) if Q[i, i + 1] != 0}
    assert blocks == {(-1, 2)}


def test_symbolic_exp_equals_sympy_matrix_exp():
    F = real_matrix_function(A3, sp.exp(x * t), var=x)
    assert not F.has(sp.I)
    ref = (A3 * t).exp()
    assert (F - ref).applyfunc(lambda e: sp.simplify(sp.expand_complex(e))) == sp.zeros(3)


@pytest.mark.parametrize("fname", ["exp", "cos"])
def test_numeric_value_against_scipy(fname):
    A = sp.Matrix([[1, 2, 0, 0], [-3, 0, 0, 1], [0, 0, 2, 0], [0, 0, 0, -1]])
    F = real_matrix_function(A, getattr(sp, fname))
    val = np.array(F.evalf(30).tolist(), dtype=complex)
    An = np.array(A.tolist(), dtype=float)
    ref = scipy.linalg.expm(An) if fname == "exp" else scipy.linalg.funm(An, np.cos)
    assert np.allclose(val.imag, 0, atol=1e-25)
    assert np.allclose(val.real, ref.real, rtol=1e-12, atol=1e-12)


def test_nonlinear_divisor_refused():
    with pytest.raises(ModelError, match="elementary divisor"):
        cayley_real_form(sp.Matrix([[1, 1], [0, 1]]))
