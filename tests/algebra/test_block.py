"""Block matrices (Bulgakov §1.5–1.7): every result against SymPy's own inverse/determinant."""

from __future__ import annotations

import random

import pytest
import sympy as sp

from symosc.algebra import (
    block_determinant,
    block_inverse,
    bordering_inverse,
    cyclic_block_determinant,
    triangular_adjugate_series,
    triangular_inverse_series,
)
from symosc.errors import ModelError


def _random_matrix(n: int, seed: int) -> sp.Matrix:
    rng = random.Random(seed)
    while True:
        A = sp.Matrix(n, n, lambda i, j: rng.randint(-4, 4))
        if A.det() != 0:
            return A


@pytest.mark.parametrize("seed", range(4))
def test_block_inverse_and_determinant_1_64_1_67_1_76_1_77(seed):
    """§1.5 (1.64)/(1.67) and §1.7 (1.76)/(1.77) on random 5x5 matrices split 2+3, against Matrix.inv()/det()."""
    A = _random_matrix(5, seed)
    a11, a12, a21, a22 = A[:2, :2], A[:2, 2:], A[2:, :2], A[2:, 2:]
    assert a11.det() != 0 or a22.det() != 0
    assert block_inverse(a11, a12, a21, a22) == A.inv()
    assert block_determinant(a11, a12, a21, a22) == A.det()


def test_block_inverse_with_singular_a11_uses_1_64():
    A = sp.Matrix([[0, 1, 2], [1, 0, 1], [2, 1, 1]])
    assert A[:1, :1].det() == 0
    assert block_inverse(A[:1, :1], A[:1, 1:], A[1:, :1], A[1:, 1:]) == A.inv()


def test_symbolic_block_determinant():
    x, y = sp.symbols("x y")
    A = sp.Matrix([[x, 1, 0], [1, y, 2], [0, 2, 1]])
    assert sp.expand(block_determinant(A[:1, :1], A[:1, 1:], A[1:, :1], A[1:, 1:]) - A.det()) == 0


def test_bordering_leading_minors_like_the_book():
    """§1.5 Ex. 4 / §1.7 Ex. 3: the book's leading minors 2, 1, 1, 7 (its matrix is illegible; this one has the
    same minors), the inverse and the determinant against SymPy."""
    A = sp.Matrix([[2, 1, 0, 0], [1, 1, 0, 0], [0, 0, 1, 1], [0, 0, 1, 8]])
    r = bordering_inverse(A)
    assert r.leading_minors == (2, 1, 1, 7) and r.determinant == 7 == A.det()
    assert r.inverse == A.inv() and r.row_order == (0, 1, 2, 3)


@pytest.mark.parametrize("seed", range(3))
def test_bordering_with_forced_pivoting(seed):
    """§1.7 Ex. 4: a zero bordering pivot (singular leading minor) is cured by a row permutation."""
    A = _random_matrix(4, seed)
    A[0, 0] = 0  # the first pivot is zero
    if A.det() == 0:
        A[3, 0] += 1
    r = bordering_inverse(A)
    assert r.inverse == A.inv() and r.determinant == A.det()
    assert r.row_order != (0, 1, 2, 3)
    with pytest.raises(ModelError, match="singular"):
        bordering_inverse(sp.Matrix([[1, 2], [2, 4]]))


def test_cyclic_block_determinant_1_79():
    """§1.7 Ex. 2, (1.79), n = 3 with 2x2 blocks, against the determinant of the assembled 6x6 matrix."""
    g = [_random_matrix(2, 10 + k) for k in range(3)]
    d = [sp.Matrix(2, 2, lambda i, j, k=k: (i + 2 * j + k) % 3 - 1) for k in range(3)]
    Z = sp.zeros(2, 2)
    A = sp.Matrix(sp.BlockMatrix([[g[0], Z, d[0]], [-d[1], g[1], Z], [Z, -d[2], g[2]]]).as_explicit())
    assert cyclic_block_determinant(g, d) == A.det()


def test_triangular_series_1_73_1_74():
    """§1.6 Ex. 4: c = aE + gamma with gamma^3 = 0 (the book's unit upper-triangular example, a = 1, and a
    symbolic a); (1.74) also for a = 0, against SymPy's inverse and adjugate."""
    c = sp.Matrix([[1, 0, 3, 1], [0, 1, 1, 6], [0, 0, 1, 2], [0, 0, 0, 1]])
    assert triangular_inverse_series(c) == c.inv()
    a = sp.Symbol("a")
    ca = c - sp.eye(4) + a * sp.eye(4)
    assert (triangular_inverse_series(ca) - ca.inv()).applyfunc(sp.simplify) == sp.zeros(4, 4)
    assert (triangular_adjugate_series(ca) - ca.adjugate()).applyfunc(sp.expand) == sp.zeros(4, 4)
    c0 = c - sp.eye(4)
    assert triangular_adjugate_series(c0) == c0.adjugate()
    with pytest.raises(ModelError, match="equal diagonal"):
        triangular_inverse_series(sp.Matrix([[1, 2], [0, 3]]))
