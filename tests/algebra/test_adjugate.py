"""Adjugate derivatives (Bulgakov §1.27) against SymPy's cofactor adjugate differentiated by SymPy."""

import pytest
import sympy as sp

from symosc.algebra import adjugate_derivative_at_root, adjugate_derivatives
from symosc.errors import ModelError, ParameterError

lam = sp.Symbol("lam")
MATS = [
    sp.Matrix([[4, -3], [2, -1]]),
    sp.Matrix([[2, 1, 0], [0, 2, 0], [0, 0, 5]]),
    sp.Matrix([[1, 2, 0, 1], [0, 1, 3, 0], [1, 0, 2, 1], [0, 1, 0, -1]]),
]


@pytest.mark.parametrize("A", MATS)
def test_derivatives_match_sympy_diff_of_cofactor_adjugate(A):
    n = A.rows
    ref = (lam * sp.eye(n) - A).adjugate()
    ders = adjugate_derivatives(A, lam, n)
    delta = (lam * sp.eye(n) - A).det()
    for p, F in enumerate(ders):
        assert (F - ref.diff(lam, p)).applyfunc(sp.expand) == sp.zeros(n)
        assert sp.expand(F.trace() - sp.diff(delta, lam, p + 1)) == 0
    assert ders[n] == sp.zeros(n)


@pytest.mark.parametrize(
    "A, root, q",
    [(MATS[1], 2, 2), (MATS[1], 5, 1), (sp.Matrix([[3, 1, 0], [0, 3, 1], [0, 0, 3]]), 3, 3), (sp.eye(3) * 2, 2, 3)],
)
def test_value_at_root_matches_derivative(A, root, q):
    ref = (lam * sp.eye(A.rows) - A).adjugate()
    for p in range(q):
        expected = (ref.diff(lam, p) / sp.factorial(p)).subs(lam, root)
        assert adjugate_derivative_at_root(A, root, p) == expected


def test_errors():
    with pytest.raises(ModelError, match="not an eigenvalue"):
        adjugate_derivative_at_root(MATS[1], 3, 0)
    with pytest.raises(ParameterError, match="multiplicity"):
        adjugate_derivative_at_root(MATS[1], 5, 1)
    with pytest.raises(ParameterError, match="count"):
        adjugate_derivatives(MATS[0], lam, -1)
