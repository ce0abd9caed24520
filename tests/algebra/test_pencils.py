"""Strict equivalence and canonical form of regular pencils (Bulgakov (1954), §1.24, eqs. (1.187)–(1.192)).

References are independent of the code under test: exact matrix products (u a v = a1, u b v = b1), SymPy's own
``Matrix.jordan_form`` for the Jordan structure and the degree of ``det(a λ + b)`` for the infinite part.
"""

from __future__ import annotations

import random

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from symosc.algebra import pencil_canonical_form, pencil_divisors, pencil_equivalence
from symosc.errors import ModelError, ParameterError

lam = sp.Symbol("lam")


def _unimodular(n: int, rng: random.Random, steps: int = 6) -> sp.Matrix:
    """Product of elementary integer row operations: integer entries, determinant ±1."""
    M = sp.eye(n)
    for _ in range(steps):
        i, j = rng.sample(range(n), 2)
        E = sp.eye(n)
        E[i, j] = rng.choice([-2, -1, 1, 2])
        M = M * E
        if rng.random() < 0.3:
            M.row_swap(i, j)
    return M


def _jordan(blocks: list[tuple[int, int]]) -> sp.Matrix:
    return sp.diag(*[sp.Matrix(s, s, lambda i, j, r=r: r if i == j else int(j == i + 1)) for r, s in blocks])


def _structure(J: sp.Matrix) -> list[tuple]:
    """Sorted (eigenvalue, block size) pairs of a matrix in Jordan form, read off its diagonals."""
    out, start, n = [], 0, J.rows
    for i in range(n):
        if i == n - 1 or J[i, i + 1] == 0:
            out.append((sp.nsimplify(J[start, start]), i - start + 1))
            start = i + 1
    return sorted(out, key=lambda t: (sp.default_sort_key(t[0]), t[1]))


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(min_value=0, max_value=10**6), st.sampled_from([2, 3, 4]))
def test_random_conjugated_pencils_recover_u_v_exactly(seed, n):
    """§1.24, (1.187): a pencil transformed by random integer unimodular/invertible p, q is equivalent, and the
    returned u, v satisfy u a v = a1 and u b v = b1 by exact multiplication."""
    rng = random.Random(seed)
    a = _unimodular(n, rng) * sp.diag(*[rng.choice([1, 2, 3]) for _ in range(n)])
    b = sp.Matrix(n, n, lambda i, j: rng.randint(-3, 3))
    p, q = _unimodular(n, rng), _unimodular(n, rng) * sp.diag(*[rng.choice([1, -2]) for _ in range(n)])
    a1, b1 = p * a * q, p * b * q
    res = pencil_equivalence(a, b, a1, b1)
    assert res.equivalent
    assert (res.u * a * res.v - a1).applyfunc(sp.simplify).is_zero_matrix
    assert (res.u * b * res.v - b1).applyfunc(sp.simplify).is_zero_matrix
    assert res.u.det() != 0 and res.v.det() != 0


def test_prescribed_jordan_structure_with_repeated_roots():
    """A derogatory pencil (blocks J2(1), J1(1), J1(-2)) hidden behind integer p, q is recognised and transformed."""
    rng = random.Random(7)
    J = _jordan([(1, 2), (1, 1), (-2, 1)])
    p, q = _unimodular(4, rng), _unimodular(4, rng)
    a, b = p * q, -p * J * q  # a λ + b = p (E λ - J) q
    p2, q2 = _unimodular(4, rng), _unimodular(4, rng)
    res = pencil_equivalence(a, b, p2 * a * q2, p2 * b * q2)
    assert res and res.u * a * res.v == p2 * a * q2 and res.u * b * res.v == p2 * b * q2
    cf = pencil_canonical_form(a, b)
    assert cf.u * a * cf.v == sp.eye(4) and cf.u * b * cf.v == -cf.J
    assert _structure(cf.J) == _structure(J)


def test_jordan_block_not_equivalent_to_diagonal_with_same_eigenvalues():
    """§1.24: equal characteristic polynomials are not enough — the elementary divisors (λ-2)², (λ-2)
    differ from (λ-2), (λ-2), (λ-2), and the result says so."""
    E = sp.eye(3)
    res = pencil_equivalence(E, -_jordan([(2, 2), (2, 1)]), E, -_jordan([(2, 1), (2, 1), (2, 1)]))
    assert not res and res.u is None and res.v is None
    assert res.reason == "the elementary divisors differ: (λ - 2), (λ - 2)^2 against (λ - 2), (λ - 2), (λ - 2)"
    assert (E * lam - _jordan([(2, 2), (2, 1)])).det() == (E * lam - _jordan([(2, 1)] * 3)).det()


def test_different_eigenvalues_not_equivalent():
    res = pencil_equivalence(sp.eye(2), sp.diag(1, 2), sp.eye(2), sp.diag(1, 3))
    assert not res.equivalent and "differ" in res.reason


def test_canonical_form_matches_sympy_jordan_form():
    """(1.191): J agrees with SymPy's Jordan form of -a⁻¹b (an independent algorithm)."""
    a = sp.Matrix([[2, 1, 0], [1, 1, 0], [0, 0, 1]])
    S = sp.Matrix([[1, 2, 0], [0, 1, -1], [1, 0, 1]])
    b = -a * S * _jordan([(3, 2), (-1, 1)]) * S.inv()
    cf = pencil_canonical_form(a, b)
    _, Jref = (-a.inv() * b).jordan_form()
    assert _structure(cf.J) == _structure(Jref)
    assert (cf.u * a * cf.v - sp.eye(3)).applyfunc(sp.simplify).is_zero_matrix
    assert (cf.u * b * cf.v + cf.J).applyfunc(sp.simplify).is_zero_matrix


def test_real_canonical_form_with_complex_jordan_block():
    """(1.192): a real pencil with a double complex pair 1 ± 2i in one Jordan block each gets real u, v and Cayley's
    real form Q = [[C, E], [0, C]], C = [[1, 2], [-2, 1]]."""
    rng = random.Random(3)
    C = sp.Matrix([[1, 2], [-2, 1]])
    Q = sp.Matrix(sp.BlockMatrix([[C, sp.eye(2)], [sp.zeros(2), C]]))
    p, q = _unimodular(4, rng), _unimodular(4, rng)
    a, b = p * q, -p * Q * q
    cf = pencil_canonical_form(a, b, real=True)
    assert all(e.is_real for e in (*cf.u, *cf.v))
    assert cf.u * a * cf.v == sp.eye(4)
    assert cf.u * b * cf.v == -cf.J
    assert cf.J == Q
    assert cf.finite == {1 - 2 * sp.I: [2], 1 + 2 * sp.I: [2]}
    # the complex Jordan form of the same pencil, against SymPy's Jordan form of -a⁻¹b
    cfc = pencil_canonical_form(a, b)
    assert _structure(cfc.J) == _structure((-a.inv() * b).jordan_form()[1])


def test_singular_leading_coefficient_infinite_divisors():
    """A singular a with a regular pencil: the infinite elementary divisors are handled (Gantmacher, ch. XII §2).
    Their total degree is n - deg det(a λ + b)."""
    rng = random.Random(11)
    N2 = sp.Matrix([[0, 1], [0, 0]])
    a0, b0 = sp.diag(1, 1, N2), sp.diag(-_jordan([(4, 2)]), sp.eye(2))  # finite (λ-4)², infinite ∞²
    p, q = _unimodular(4, rng), _unimodular(4, rng)
    a, b = p * a0 * q, p * b0 * q
    assert a.det() == 0
    cf = pencil_canonical_form(a, b)
    assert cf.infinite == [2] and cf.finite == {4: [2]}
    assert sp.degree(sp.expand((a * lam + b).det()), lam) == 4 - sum(cf.infinite)
    assert cf.u * a * cf.v == a0 and cf.u * b * cf.v == b0
    # same finite part, infinite divisors ∞, ∞ instead of ∞²: not equivalent
    res = pencil_equivalence(a, b, sp.diag(1, 1, 0, 0), b0)
    assert not res and "∞^2 against" in res.reason


@pytest.mark.parametrize("seed", [1, 2])
def test_divisors_agree_with_the_minors_route(seed):
    """The rank-based divisors (Weyr characteristic of K = (ac + b)⁻¹a) agree with the gcd-of-minors route of
    pencil_divisors (§1.18, §1.24), finite and infinite, on pencils with a singular leading coefficient."""
    rng = random.Random(seed)
    a0 = sp.diag(1, 1, sp.Matrix([[0, 1], [0, 0]]))
    b0 = sp.diag(-_jordan([(rng.choice([-1, 2]), 1), (3, 1)]), sp.eye(2))
    p, q = _unimodular(4, rng), _unimodular(4, rng)
    a, b = p * a0 * q, p * b0 * q
    res = pencil_equivalence(a, b, a0, b0)
    ref = pencil_divisors(-b, a, lam)  # λ a - (-b) = a λ + b
    finite, infinite = res.divisors
    assert res.equivalent
    assert {sp.nsimplify(k): v for k, v in finite.items()} == ref.finite and infinite == ref.infinite


def test_singular_pencil_refused():
    a = sp.Matrix([[1, 0], [0, 0]])
    b = sp.Matrix([[1, 0], [0, 0]])  # det(a λ + b) ≡ 0
    with pytest.raises(ModelError, match="singular"):
        pencil_equivalence(a, b, a, b)
    with pytest.raises(ModelError, match="Kronecker"):
        pencil_canonical_form(a, b)


@pytest.mark.parametrize(
    "args, match",
    [
        ((sp.Matrix([[1.0, 0], [0, 1]]), sp.eye(2)), "floating-point"),
        ((sp.Matrix([[sp.Symbol("k"), 0], [0, 1]]), sp.eye(2)), "free symbols"),
    ],
)
def test_bad_entries(args, match):
    with pytest.raises(ParameterError, match=match):
        pencil_canonical_form(*args)


def test_cubic_factor_refused_by_canonical_form_but_equivalence_decided():
    """An irreducible cubic invariant factor: no Jordan form in practical radicals, yet the equivalence test works
    over the rationals (no roots are needed)."""
    b = sp.Matrix([[0, 0, -1], [-1, 0, -1], [0, -1, 0]])  # companion of λ³ - λ - 1
    with pytest.raises(ModelError, match="degree ≥ 3"):
        pencil_canonical_form(sp.eye(3), b)
    p, q = sp.Matrix([[1, 1, 0], [0, 1, 0], [2, 0, 1]]), sp.Matrix([[1, 0, 0], [1, 1, 0], [0, 3, 1]])
    res = pencil_equivalence(sp.eye(3), b, p * q, p * b * q)
    assert res and res.u * res.v == p * q and res.u * b * res.v == p * b * q


def test_shape_mismatch():
    with pytest.raises(ModelError, match="same size"):
        pencil_equivalence(sp.eye(2), sp.eye(2), sp.eye(3), sp.eye(3))
    with pytest.raises(ParameterError, match="real"):
        pencil_canonical_form(sp.eye(2), sp.eye(2) * sp.I, real=True)
