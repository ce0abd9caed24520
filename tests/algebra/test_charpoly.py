"""Characteristic polynomial methods (Leverrier, Krylov, Danilevsky) against SymPy's Berkowitz charpoly."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.algebra import charpoly, danilevsky, krylov, leverrier
from symosc.errors import ModelError, ParameterError

l = sp.Symbol("l")

entries = st.integers(-5, 5) | st.fractions(min_value=-3, max_value=3, max_denominator=4)


@st.composite
def exact_matrices(draw, max_n=5):
    n = draw(st.integers(1, max_n))
    vals = draw(st.lists(entries, min_size=n * n, max_size=n * n))
    # sparse matrices make Danilevsky's zero pivots and Krylov's degenerate start vectors common
    mask = draw(st.lists(st.booleans(), min_size=n * n, max_size=n * n))
    return sp.Matrix(n, n, [sp.Rational(v) if m else 0 for v, m in zip(vals, mask, strict=True)])


@settings(max_examples=40, deadline=None)
@given(A=exact_matrices())
def test_methods_agree_with_sympy(A):
    ref = A.charpoly(l).as_expr()
    for method in (leverrier, krylov, danilevsky):
        assert sp.expand(method(A, l).as_expr() - ref) == 0, method.__name__


def test_danilevsky_degenerate_cases():
    """Zero pivot cured by a swap, and the degenerate split into block-triangular pieces (no swap possible)."""
    swap = sp.Matrix([[1, 2, 3], [4, 5, 6], [7, 0, 9]])  # a[2,1] = 0 but a[2,0] != 0
    split = sp.Matrix([[1, 2, 0], [3, 4, 0], [5, 6, 7]]).T  # row 2 = (0, 0, 7): splits off at once
    nested = sp.Matrix([[2, 1, 0, 0], [0, 2, 0, 0], [1, 1, 3, 0], [0, 0, 0, 3]])  # splits twice
    for A in (swap, split, nested, sp.zeros(3, 3), sp.eye(4)):
        assert sp.expand(danilevsky(A, l).as_expr() - A.charpoly(l).as_expr()) == 0


def test_krylov_derogatory_fallback_and_error():
    """A derogatory matrix has no cyclic vector: Krylov falls back to Danilevsky or raises if asked not to."""
    A = sp.diag(2, 2, 3)
    assert sp.factor(krylov(A, l).as_expr()) == (l - 3) * (l - 2) ** 2
    with pytest.raises(ModelError, match="degenerates"):
        krylov(A, l, fallback=False)
    with pytest.raises(ParameterError, match="start vector"):
        krylov(A, l, v=sp.Matrix([1, 0]))
    assert sp.expand(krylov(sp.Matrix([[0, 1], [-2, -3]]), l, v=sp.Matrix([1, 1])).as_expr()) == l**2 + 3 * l + 2


def test_symbolic_entries():
    a, b = sp.symbols("a b")
    A = sp.Matrix([[0, 1, 0], [0, 0, 1], [-a, -b, 0]])
    ref = A.charpoly(l).as_expr()
    for method in ("leverrier", "krylov", "danilevsky", "berkowitz"):
        assert sp.simplify(charpoly(A, l, method=method).as_expr() - ref) == 0
    with pytest.raises(ParameterError, match="unknown method"):
        charpoly(A, l, method="hessenberg")
