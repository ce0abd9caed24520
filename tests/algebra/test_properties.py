"""Hypothesis property tests of the identities of the research report's feature items 8–11 (Bulgakov §1.29–1.36)
on exact matrices with a prescribed Jordan structure: A = S J S^-1 with J chosen and S unimodular."""

from __future__ import annotations

import numpy as np
import sympy as sp
from hypothesis import example, given, settings
from hypothesis import strategies as st

from symosc.algebra import (
    function_elementary_divisors,
    interpolation_basis,
    interpolation_polynomial,
    matrix_function,
    series_converges,
    spectral_decomposition,
)

from .conftest import jordan_matrix, similar

x = sp.Symbol("x")
l = sp.Symbol("l")

EIGS = [-2, -1, 0, 1, 2, sp.Rational(1, 2), sp.Rational(-3, 2)]
structures = st.lists(st.tuples(st.sampled_from(EIGS), st.integers(1, 3)), min_size=1, max_size=3).filter(
    lambda bl: sum(k for _, k in bl) <= 4
)
SETTINGS = settings(max_examples=10, deadline=None)


def _f_of_jordan(blocks, f):
    """f(J) block by block by (1.306): f(l) E + f'(l) v + ... + f^(e-1)(l) v^(e-1)/(e-1)!  (independent of the
    package's Sylvester code)."""
    mats = []
    for v, k in blocks:
        v_shift = sp.Matrix(k, k, lambda i, j: 1 if j == i + 1 else 0)
        mats.append(sum((sp.diff(f, x, p).subs(x, v) / sp.factorial(p) * v_shift**p for p in range(k)), sp.zeros(k)))
    return sp.diag(*mats)


@SETTINGS
@given(blocks=structures, seed=st.integers(0, 500))
def test_item9_projector_identities(blocks, seed):
    """(1.289–1.298): Σ ε = E, ε_σ ε_τ = δ_στ ε_σ, η_σ = (A - λ_σ E) ε_σ, η^p powers, η^e = 0, ε η^p = η^p; q_σ and
    e_σ match the prescribed Jordan structure."""
    A, _, _ = similar(blocks, seed)
    n = A.rows
    S = spectral_decomposition(A)
    comps = S.components
    assert sum(S.projectors, sp.zeros(n, n)) == sp.eye(n)
    for c in comps:
        sizes = [k for v, k in blocks if v == c.root]
        assert c.multiplicity == sum(sizes) and c.index == max(sizes)
        assert c.projector**2 == c.projector
        eta = (A - c.root * sp.eye(n)) * c.projector
        assert (c.nilpotents[0] if c.nilpotents else sp.zeros(n, n)) == eta
        for p, N in enumerate(c.nilpotents, start=1):
            assert N == eta**p and c.projector * N == N
        assert (eta**c.index).is_zero_matrix
        for d in comps:
            if d is not c:
                assert (c.projector * d.projector).is_zero_matrix
    # A = Σ (λ ε + η)
    rebuilt = sum((c.root * c.projector + (c.nilpotents[0] if c.nilpotents else 0 * A) for c in comps), sp.zeros(n))
    assert rebuilt == A


@SETTINGS
@given(blocks=structures, seed=st.integers(0, 500))
def test_item9_functions_against_jordan_form(blocks, seed):
    """f(A) = S f(J) S^-1 with f(J) from (1.306); (φ1 φ2)(A) = φ1(A) φ2(A) (§1.32); A^-1 = Σ λ^-1 ε (§1.33)."""
    A, S, _ = similar(blocks, seed)
    n = A.rows
    f = (x**3 - 2 * x + 1) / (x**2 + 4)  # rational: exact comparisons
    assert matrix_function(A, f) == S * _f_of_jordan(blocks, f) * S.inv()
    g1, g2 = sp.exp(x / 3), (x + 5) ** 2
    F1, F2 = matrix_function(A, g1), matrix_function(A, g2)
    F12 = matrix_function(A, g1 * g2)
    assert (F1 * F2 - F12).applyfunc(sp.simplify).is_zero_matrix
    assert (F1 * F2 - F2 * F1).applyfunc(sp.simplify).is_zero_matrix
    if all(v != 0 for v, _ in blocks):
        assert matrix_function(A, 1 / x) == A.inv()
    E = np.array(matrix_function(A, sp.exp).evalf(), dtype=float)
    Sn, Jn = np.array(S, dtype=float), np.array(jordan_matrix(blocks), dtype=float)
    from scipy.linalg import expm

    np.testing.assert_allclose(E, Sn @ expm(Jn) @ np.linalg.inv(Sn), rtol=1e-10, atol=1e-10)
    assert E.shape == (n, n)


@SETTINGS
@given(
    nodes=st.dictionaries(st.sampled_from(EIGS), st.integers(1, 3), min_size=1, max_size=3).filter(
        lambda d: sum(d.values()) <= 5
    )
)
def test_item8_interpolation(nodes):
    """(1.266–1.276): the Lagrange–Sylvester polynomial matches f^(p)(λ_σ) for p < q_σ; Σ ε_σ ≡ 1,
    ε_σ² ≡ ε_σ, ε_σ ε_τ ≡ 0 (mod Δ); η_(σ,p) ≡ (λ - λ_σ)^p ε_σ (mod Δ)."""
    f = sp.exp(x) * (x**2 + 1) + 1 / (x + 3)
    r = interpolation_polynomial(f, nodes, l)
    assert sp.degree(r, l) < sum(nodes.values()) or r.is_number
    for root, q in nodes.items():
        for p in range(q):
            lhs = sp.diff(r, l, p).subs(l, root)
            rhs = sp.diff(f, x, p).subs(x, root)
            assert sp.simplify(lhs - rhs) == 0
    delta = sp.prod([(l - a) ** q for a, q in nodes.items()])
    basis = interpolation_basis(nodes, l)
    eps = {a: polys[0] for a, polys in basis.items()}

    def rem(e):
        return sp.rem(sp.expand(e), sp.expand(delta), l)

    assert rem(sum(eps.values()) - 1) == 0
    for a in eps:
        assert rem(eps[a] ** 2 - eps[a]) == 0
        for b in eps:
            if a != b:
                assert rem(eps[a] * eps[b]) == 0
        for p, eta in enumerate(basis[a]):
            assert rem(eta - (l - a) ** p * eps[a]) == 0


@SETTINGS
@given(blocks=structures, seed=st.integers(0, 500))
def test_item10_series_convergence(blocks, seed):
    """§1.30: Σ (-1)^(k+1) z^k/k (= log(E+z)) converges iff all eigenvalues lie in |λ| < 1 (radius 1), checked on
    partial sums; the eigenvalue test is sharp even where the elementwise bound (1.239) fails."""
    A, _, _ = similar(blocks, seed)
    verdict = series_converges(A, 1)
    radius = max(abs(v) for v, _ in blocks)
    assert verdict == (None if radius == 1 else radius < 1)
    Z = np.array(A, dtype=float)
    P, term, partial = np.eye(Z.shape[0]), np.eye(Z.shape[0]), []
    total = np.zeros_like(Z)
    for k in range(1, 401):
        term = term @ Z
        total = total + (-1) ** (k + 1) * term / k
        if k in (200, 400):
            partial.append(total.copy())
    gap = np.max(np.abs(partial[1] - partial[0]))
    if verdict is True:
        assert gap < 1e-6
        if radius < 1:
            from scipy.linalg import logm

            np.testing.assert_allclose(partial[1], logm(P + Z), atol=1e-6)
    elif verdict is False:
        assert not np.isfinite(gap) or gap > 1e3


critical_structures = st.lists(st.tuples(st.sampled_from([-1, 0, 1, 2]), st.integers(1, 3)), min_size=1, max_size=2)


@SETTINGS
@given(blocks=critical_structures, seed=st.integers(0, 500), which=st.integers(0, 2))
@example(blocks=[(0, 3)], seed=1, which=0)
@example(blocks=[(1, 2), (-1, 2)], seed=2, which=1)
@example(blocks=[(1, 3), (2, 1)], seed=3, which=2)
def test_item11_spectral_mapping(blocks, seed, which):
    """§1.34–1.36: predicted elementary divisors of f(A) (Lappo-Danilevsky and splitting when f'(λ) = 0) against
    SymPy's own Jordan form of f(A); eigenvalues of f(A) are f(λ_σ)."""
    A, _, _ = similar(blocks, seed)
    f = [x**2, x**3 - 3 * x, x / (1 + x**2)][which]  # critical points at 0, ±1, ±1 respectively
    if any(sp.simplify(1 + v**2) == 0 for v, _ in blocks):
        return
    F = matrix_function(A, f)
    predicted = function_elementary_divisors(A, sp.Lambda(x, f))
    _, J = F.jordan_form()
    observed: dict = {}
    i = 0
    n = J.rows
    while i < n:
        k = 1
        while i + k < n and J[i + k - 1, i + k] == 1:
            k += 1
        observed.setdefault(sp.nsimplify(J[i, i]), []).append(k)
        i += k
    assert {k: sorted(v) for k, v in observed.items()} == predicted
    assert set(F.eigenvals()) == {f.subs(x, v) for v, _ in blocks}


def test_item11_book_examples():
    """§1.36 (report §3 item 5) and the item-11 test: J_3(1) with φ = (l-1)^2 has k = ceil(3/2) = 2 (divisors 1, 2
    at 0); S(l) = l/(1+l^2) splits J_2(1) into two linear divisors at 1/2; S(l) at J_2(2) keeps the quadratic one."""
    J3 = jordan_matrix([(1, 3)])
    assert function_elementary_divisors(J3, sp.Lambda(x, (x - 1) ** 2)) == {0: [1, 2]}
    S = sp.Lambda(x, x / (1 + x**2))
    assert function_elementary_divisors(jordan_matrix([(1, 2)]), S) == {sp.Rational(1, 2): [1, 1]}
    assert function_elementary_divisors(jordan_matrix([(2, 2)]), S) == {sp.Rational(2, 5): [2]}
