"""Polynomial matrices: divisors, Smith form, division, minimal polynomial, pencils (Bulgakov §1.17–1.27)."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import example, given, settings
from hypothesis import strategies as st

from symosc.algebra import (
    adjugate_poly,
    determinantal_divisors,
    elementary_divisors,
    invariant_factors,
    minimal_polynomial,
    pencil_divisors,
    polymatrix_divmod,
    smith_form,
)
from symosc.errors import ModelError, ParameterError

from .conftest import similar

l = sp.Symbol("l")


def _is_unit(d: sp.Expr) -> bool:
    d = sp.cancel(sp.expand(d))
    return d != 0 and d.is_number


def test_bulgakov_1_18_divisors():
    """Bulgakov §1.18 (seed 004; research report §3 item 1): D1 = l-1, D2 = (l-1)^2 (l-2), E1 = l-1,
    E2 = (l-1)(l-2); elementary divisors l-1, l-1, l-2 (all linear). The 2x2 minors are l(l-2)(l-1)^2, (l-2)(l-1)^2,
    -(l-2)(l-1)^2 (checked here directly)."""
    f = sp.Matrix([[l**2 - 2 * l + 1, l - 1, l - 1], [l - 1, l**2 - 2 * l + 1, l - 1]])
    minors = [sp.factor(f.extract([0, 1], list(c)).det()) for c in [(0, 1), (0, 2), (1, 2)]]
    expected = [l * (l - 2) * (l - 1) ** 2, (l - 2) * (l - 1) ** 2, -(l - 2) * (l - 1) ** 2]
    assert {sp.expand(m) for m in minors} == {sp.expand(e) for e in expected}
    D = determinantal_divisors(f, l)
    assert [sp.factor(d) for d in D] == [l - 1, (l - 2) * (l - 1) ** 2]
    E = invariant_factors(f, l)
    assert [sp.factor(e) for e in E] == [l - 1, (l - 2) * (l - 1)]
    assert elementary_divisors(f, l) == {1: [1, 1], 2: [1]}
    # rank drop (1.166): rank f(1) = 0 = r - (number of divisors at 1) = 2 - 2
    assert f.subs(l, 1).rank() == 2 - 2 and f.subs(l, 2).rank() == 2 - 1
    sf = smith_form(f, l)
    assert (sf.U * f * sf.V).applyfunc(sp.expand) == sf.S
    assert _is_unit(sf.U.det()) and _is_unit(sf.V.det())
    assert [sp.factor(e) for e in sf.invariant_factors] == [l - 1, (l - 2) * (l - 1)]


def test_bulgakov_1_21_left_division():
    """Bulgakov §1.21 Ex. 5 (report §3 item 2, reconstructed and verified there): g = f S + T with
    S = [[-l+7, -1], [3l-22, 3]], T = [[59, -8], [10, 0]]."""
    f = sp.Matrix([[2 * l - 2, l + 2], [3 * l - 1, l]])
    g = sp.Matrix([[l**2 + 1, l], [3, 1]])
    S, T = polymatrix_divmod(f, g, l, side="left")
    assert S == sp.Matrix([[-l + 7, -1], [3 * l - 22, 3]])
    assert T == sp.Matrix([[59, -8], [10, 0]])
    assert sp.expand(f.det()) == -(l**2) - 7 * l + 2
    assert (f * S + T - g).applyfunc(sp.expand).is_zero_matrix


def test_right_division_and_proper_remainder():
    """Right division g = Q f + R with R f^-1 strictly proper, checked through degrees of numerator/denominator."""
    f = sp.Matrix([[l**2, 1], [l, l + 3]])  # leading coefficient singular: not plain long division
    g = sp.Matrix([[l**4 + 2, l**3], [l, 5 * l**2 - 1]])
    Q, R = polymatrix_divmod(f, g, l, side="right")
    assert (Q * f + R - g).applyfunc(sp.expand).is_zero_matrix
    for e in (R * f.inv()).applyfunc(sp.cancel):
        num, den = sp.fraction(e)
        assert sp.degree(num, l) < sp.degree(den, l) or num == 0
    with pytest.raises(ModelError, match="singular"):
        polymatrix_divmod(sp.Matrix([[l, l], [1, 1]]), g, l)
    with pytest.raises(ParameterError, match="side"):
        polymatrix_divmod(f, g, l, side="middle")


def test_bulgakov_1_22_triangular_example():
    """Bulgakov §1.22 Ex. 1 (report §3 item 3): f = [[2l^2+3, 2l+1], [l^2-2, l+2]], det f = 3l^2 + 7l + 8; the
    canonical form has the single non-trivial invariant factor l^2 + 7l/3 + 8/3."""
    f = sp.Matrix([[2 * l**2 + 3, 2 * l + 1], [l**2 - 2, l + 2]])
    assert sp.expand(f.det()) == 3 * l**2 + 7 * l + 8
    sf = smith_form(f, l)
    assert sf.S == sp.diag(1, l**2 + sp.Rational(7, 3) * l + sp.Rational(8, 3))
    assert (sf.U * f * sf.V).applyfunc(sp.expand) == sf.S


def test_minimal_polynomial_and_adjugate_book_examples():
    """Report §3 item 14 (Bulgakov §1.37): z = [[4,-3],[2,-1]], F(1)^2 = Δ'(1) F(1) with Δ'(1) = -1; derogatory
    z = [[2,0,0],[0,2,0],[1,1,3]]: F'(2) = [[-1,0,0],[0,-1,0],[1,1,0]] of rank 2, minimal polynomial (l-2)(l-3)."""
    z = sp.Matrix([[4, -3], [2, -1]])
    F = adjugate_poly(z, l)
    assert F == (l * sp.eye(2) - z).adjugate().applyfunc(sp.expand)
    F1 = F.subs(l, 1)
    assert F1**2 == -F1
    z3 = sp.Matrix([[2, 0, 0], [0, 2, 0], [1, 1, 3]])
    dF = adjugate_poly(z3, l).diff(l).subs(l, 2)
    assert dF == sp.Matrix([[-1, 0, 0], [0, -1, 0], [1, 1, 0]]) and dF.rank() == 2
    assert sp.factor(minimal_polynomial(z3, l)) == (l - 3) * (l - 2)


def _brute_minimal_polynomial(A: sp.Matrix) -> sp.Expr:
    """Smallest k with A^k in the span of E, A, ..., A^(k-1): an independent linear-algebra computation."""
    n = A.rows
    vecs = [sp.eye(n).reshape(n * n, 1)]
    P = sp.eye(n)
    for k in range(1, n + 1):
        P = P * A
        M = sp.Matrix.hstack(*vecs)
        sol, params = (
            M.gauss_jordan_solve(P.reshape(n * n, 1))
            if M.rank() == sp.Matrix.hstack(M, P.reshape(n * n, 1)).rank()
            else (None, None)
        )
        if sol is not None:
            sol = sol.subs({p: 0 for p in params})
            return sp.expand(l**k - sum(sol[i] * l**i for i in range(k)))
        vecs.append(P.reshape(n * n, 1))
    raise AssertionError("unreachable")


jordan_structures = st.lists(st.tuples(st.integers(-2, 2), st.integers(1, 3)), min_size=1, max_size=3).filter(
    lambda bl: sum(k for _, k in bl) <= 4
)


@settings(max_examples=12, deadline=None)
@given(blocks=jordan_structures, seed=st.integers(0, 1000))
@example(blocks=[(1, 3), (1, 1)], seed=200)  # det U came out as l/(l-1) - 1/(l-1): must be recognised as 1
def test_divisors_of_similar_jordan_matrices(blocks, seed):
    """For A = S J S^-1 the elementary divisors of λE - A are the Jordan blocks of J (by construction); the Smith
    form's invariant factors agree with the determinantal-divisor route; the minimal polynomial agrees with brute
    force linear algebra; the adjugate polynomial (1.219) equals adj(λE - A)."""
    A, _, _ = similar(blocks, seed)
    n = A.rows
    P = l * sp.eye(n) - A
    expected: dict = {}
    for v, k in blocks:
        expected.setdefault(sp.Integer(v), []).append(k)
    assert elementary_divisors(P, l) == {k: sorted(v) for k, v in expected.items()}
    sf = smith_form(P, l)
    assert (sf.U * P * sf.V).applyfunc(sp.expand) == sf.S
    assert _is_unit(sf.U.det()) and _is_unit(sf.V.det())
    inv = [e for e in invariant_factors(P, l)]
    assert [sp.expand(e) for e in sf.invariant_factors] == [sp.expand(e) for e in inv]
    assert sp.expand(minimal_polynomial(A, l) - _brute_minimal_polynomial(A)) == 0
    assert adjugate_poly(A, l) == P.adjugate().applyfunc(sp.expand)


def test_pencils():
    """Regular pencils λB - A: with B invertible the finite divisors are those of λE - B^-1 A; a singular B gives
    infinite divisors (here one of degree 2 from a nilpotent block); a singular pencil is rejected."""
    A, _, _ = similar([(1, 2), (3, 1)], seed=2)
    B = sp.Matrix([[2, 1, 0], [0, 1, 0], [1, 0, 1]])
    pd = pencil_divisors(B * A, B, l)
    assert pd.finite == {1: [2], 3: [1]} and pd.infinite == []
    N = sp.Matrix([[0, 1, 0], [0, 0, 0], [0, 0, 1]])  # λN - E on the first 2x2 block: infinite divisor μ^2
    pd = pencil_divisors(sp.diag(1, 1, 5), N, l)
    assert pd.infinite == [2] and pd.finite == {5: [1]}
    with pytest.raises(ModelError, match="singular pencil"):
        pencil_divisors(sp.Matrix([[1, 0], [0, 0]]), sp.Matrix([[1, 0], [0, 0]]), l)


def test_bad_input():
    with pytest.raises(ParameterError, match="not a polynomial"):
        determinantal_divisors(sp.Matrix([[1 / l, 1]]), l)
    with pytest.raises(ModelError, match="square"):
        minimal_polynomial(sp.Matrix([[1, 2]]), l)


def _minor_gcds(M, lam):
    """The definition, written out: monic gcd of all k-th order minors (cofactor expansion), k = 1..rank."""
    from itertools import combinations

    out = []
    m, n = M.shape
    for k in range(1, min(m, n) + 1):
        g = sp.Integer(0)
        for rows in combinations(range(m), k):
            for cols in combinations(range(n), k):
                g = sp.gcd(g, sp.expand(M.extract(list(rows), list(cols)).det(method="laplace")))
        if g == 0:
            break
        out.append(sp.expand(sp.cancel(g / sp.Poly(g, lam).LC())))
    return out


entry = st.integers(-2, 2).map(sp.Integer)


@settings(max_examples=25, deadline=None)
@given(
    st.integers(1, 4).flatmap(
        lambda m: st.integers(1, 4).flatmap(
            lambda n: st.lists(st.tuples(entry, entry, entry), min_size=m * n, max_size=m * n).map(
                lambda cs: (m, n, cs)
            )
        )
    ),
    st.booleans(),
)
def test_determinantal_divisors_agree_with_the_minors(shape, rank_one_row):
    """Random rectangular polynomial matrices (quadratic entries, some with a dependent row): the Smith-form route
    gives the monic gcds of the minors computed by cofactor expansion."""
    m, n, cs = shape
    lam = sp.Symbol("l")
    M = sp.Matrix(m, n, [a * lam**2 + b * lam + c for a, b, c in cs])
    if rank_one_row and m > 1:
        M[m - 1, :] = (lam + 1) * M[0, :]
    got = determinantal_divisors(M, lam)
    want = _minor_gcds(M, lam)
    assert len(got) == len(want)
    assert all(sp.expand(g - w) == 0 for g, w in zip(got, want, strict=True))


def test_determinantal_divisors_with_symbols_radicals_and_floats():
    l, a = sp.symbols("l a")
    M = sp.Matrix([[l - a, a, 0], [0, l - a, 1], [0, 0, l - sp.sqrt(2)]])
    got = determinantal_divisors(M, l)
    want = _minor_gcds(M, l)
    assert all(sp.simplify(g - w) == 0 for g, w in zip(got, want, strict=True)) and len(got) == 3
    F = sp.Matrix([[l - 0.5, 0], [0, l - 0.5]])  # floats: the definition is used
    got = determinantal_divisors(F, l)
    assert len(got) == 2
    assert all(sp.expand(g - w) == 0 for g, w in zip(got, [l - 0.5, l**2 - l + 0.25], strict=True))
