"""Modal matrices from the adjugate (Bulgakov §1.26, §1.37) and Luzin's triangular canonical form (§1.22).

Source: seed 004_e76fcda81caa05d8 (Bulgakov 1954) §1.22, §1.26, §1.37; research report seed-bulgakov-part1.md §1
and §3 items 3 and 14.  Independent checks: explicit matrix algebra (A V = V diag(l), W A = diag(l) W), the adjugate
computed by SymPy, characteristic polynomials by ``Matrix.charpoly``, numpy/scipy eigenvalues, and the uniqueness of
the canonical form under random unimodular row transforms.
"""

from __future__ import annotations

import random

import numpy as np
import pytest
import scipy.linalg
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.algebra import luzin_form, modal_matrix, pencil_modal_matrix
from symosc.errors import ModelError, ParameterError

from .conftest import similar

lam = sp.Symbol("lam")


def _zero(M: sp.Matrix) -> bool:
    return M.applyfunc(lambda e: sp.simplify(sp.expand(e))).is_zero_matrix


def _expected_norms(a: sp.Matrix, b: sp.Matrix, eigenvalues) -> sp.Matrix:
    """blockdiag((q-1)! D_sig(l_sig) E_q) with Delta = det(a lam + b) from SymPy's det (1.312, 1.315, 1.316);
    (q-1)! D_sig(l_sig) = Delta^(q)(l_sig)/q by Taylor's formula."""
    delta = sp.expand((a * lam + b).det())
    out = []
    for root in eigenvalues:
        q = list(eigenvalues).count(root)
        out.append(sp.diff(delta, lam, q).subs(lam, root) / q)
    return sp.diag(*[sp.simplify(v) for v in out])


def _check_modal(A: sp.Matrix) -> None:
    m = modal_matrix(A)
    V, W = m
    L = sp.diag(*m.eigenvalues)
    assert _zero(A * V - V * L)
    assert _zero(W * A - L * W)
    assert sp.simplify(V.det()) != 0
    assert _zero(W * V - _expected_norms(sp.eye(A.rows), -A, m.eigenvalues))
    assert _zero(m.inverse - V.inv())


# --- modal matrix ----------------------------------------------------------------------------------------------------


def test_book_example_1_37():
    """§1.37 (report §3 item 14): z = [[4,-3],[2,-1]], roots 1, 2; F(1)^2 = Delta'(1) F(1) with Delta'(1) = -1,
    F(l_k) = V_k W_k and W V = diag(Delta'(1), Delta'(2)) = diag(-1, 1)."""
    z = sp.Matrix([[4, -3], [2, -1]])
    m = modal_matrix(z)
    assert m.eigenvalues == (1, 2)
    F1 = (sp.eye(2) - z).adjugate()
    assert F1**2 == -F1
    for k, root in enumerate(m.eigenvalues):
        assert m.V[:, k] * m.W[k, :] == (root * sp.eye(2) - z).adjugate()
    assert m.W * m.V == sp.diag(-1, 1)
    assert z * m.V == m.V * sp.diag(1, 2)


def test_derogatory_example_1_37():
    """§1.37 (report §3 item 14): z = [[2,0,0],[0,2,0],[1,1,3]], double root 2 with linear divisors.
    F'(2) = [[-1,0,0],[0,-1,0],[1,1,0]] has rank 2 = q; the modal columns span the eigenspace and W V is
    blockdiag(1! D_2(2) E_2, D_3(3)) = diag(-1, -1, 1)."""
    z = sp.Matrix([[2, 0, 0], [0, 2, 0], [1, 1, 3]])
    Fp = sp.diff((lam * sp.eye(3) - z).adjugate(), lam).subs(lam, 2)
    assert Fp == sp.Matrix([[-1, 0, 0], [0, -1, 0], [1, 1, 0]]) and Fp.rank() == 2
    m = modal_matrix(z)
    assert m.eigenvalues == (2, 2, 3)
    assert m.W * m.V == sp.diag(-1, -1, 1)
    assert (z - 2 * sp.eye(3)) * m.V[:, :2] == sp.zeros(3, 2)
    _check_modal(z)


@settings(max_examples=15, deadline=None)
@given(
    st.lists(st.integers(-4, 4), min_size=2, max_size=4),
    st.integers(0, 10_000),
)
def test_property_diagonalisable_with_repeats(eigs, seed):
    """Random exact A = S diag(eigs) S^-1 (repeated eigenvalues allowed, all divisors linear): A V = V Lambda,
    W A = Lambda W, W V = blockdiag((q-1)! D_sig(l_sig) E_q) (1.313–1.316), V^-1 = (W V)^-1 W."""
    A, _, _ = similar([(sp.Integer(e), 1) for e in eigs], seed)
    _check_modal(A)


def test_irrational_and_complex_roots():
    """Roots (5 ± sqrt 33)/2 and -1 ± 2i: exact radicals survive."""
    _check_modal(sp.Matrix([[1, 2], [3, 4]]))
    m = modal_matrix(sp.Matrix([[0, 1], [-5, -2]]))
    assert set(m.eigenvalues) == {-1 - 2 * sp.I, -1 + 2 * sp.I}
    _check_modal(sp.Matrix([[0, 1], [-5, -2]]))


def test_symbolic_oscillator():
    """Undamped oscillator [[0, 1], [-w^2, 0]]: roots ±i w, A V = V Lambda symbolically."""
    w = sp.Symbol("w", positive=True)
    A = sp.Matrix([[0, 1], [-(w**2), 0]])
    m = modal_matrix(A)
    assert set(m.eigenvalues) == {sp.I * w, -sp.I * w}
    assert _zero(A * m.V - m.V * m.Lambda)
    assert _zero(m.W * m.V - sp.diag(*[2 * r for r in m.eigenvalues]))  # Delta' = 2 l


def test_nearly_repeated_exact_roots():
    """Extreme: eigenvalues 1 and 1 + 10^-12 given exactly: still exact, W V = diag(-1e-12, 1e-12)."""
    d = sp.Rational(1, 10**12)
    A, _, _ = similar([(sp.Integer(1), 1), (1 + d, 1), (sp.Integer(-2), 1)], 7)
    _check_modal(A)


def test_float_matrix_against_numpy():
    """Floating-point 5x5 with separated roots: eigenvalues agree with numpy, residual of A V - V Lambda small."""
    rng = np.random.default_rng(3)
    An = rng.normal(size=(5, 5))
    m = modal_matrix(sp.Matrix(An))
    got = np.array([complex(e) for e in m.eigenvalues])
    ref = np.linalg.eigvals(An)
    assert np.allclose(np.sort_complex(got), np.sort_complex(ref), atol=1e-10)
    V = np.array(m.V.evalf().tolist(), dtype=complex)
    W = np.array(m.W.evalf().tolist(), dtype=complex)
    scale = np.linalg.norm(V, axis=0)
    assert np.linalg.norm(An @ V - V * got, axis=0).max() <= 1e-9 * scale.max()
    assert np.linalg.norm(W @ An - got[:, None] * W) <= 1e-9 * np.linalg.norm(W)


def test_pencil_against_scipy_and_identity_1_312():
    """Pencil a l + b (1.311–1.312): columns solve (a l_k + b) V_k = 0, eigenvalues equal scipy's generalized ones,
    V_k W_k = adj(a l_k + b) and W a V = diag(Delta'(l_k)) with Delta = det(a l + b)."""
    a = sp.Matrix([[2, 1, 0], [1, 3, 0], [0, 0, 1]])
    C, _, _ = similar([(sp.Integer(1), 1), (sp.Rational(5, 2), 1), (sp.Integer(-1), 1)], 11)
    b = -a * C  # det(a l + b) = det(a) det(l E - C): roots 1, 5/2, -1
    m = pencil_modal_matrix(a, b)
    ref = scipy.linalg.eigvals(-np.array(b.tolist(), float), np.array(a.tolist(), float))
    got = np.array([complex(sp.N(e)) for e in m.eigenvalues])
    assert np.allclose(np.sort(got.real), np.sort(ref.real), atol=1e-10)
    assert _zero(a * m.V * m.Lambda + b * m.V)
    assert _zero(m.Lambda * m.W * a + m.W * b)
    k = 0
    Fk = (a * m.eigenvalues[k] + b).adjugate()
    assert _zero(m.V[:, k] * m.W[k, :] - Fk)
    assert _zero(Fk * a * Fk - sp.diff((a * lam + b).det(), lam).subs(lam, m.eigenvalues[k]) * Fk)  # (1.311)
    assert _zero(m.norms - _expected_norms(a, b, m.eigenvalues))


def test_pencil_with_casus_irreducibilis_roots():
    """Three real irrational roots of an irreducible cubic come as CRootOf (Cardano radicals would be complex and
    slow to simplify); the identities hold to 30 digits: (a l_k + b) V_k = 0, W a V = diag(Delta'(l_k))."""
    a = sp.Matrix([[2, 1, 0], [1, 3, 0], [0, 0, 1]])
    b = sp.Matrix([[-4, 1, 0], [1, -2, 1], [0, 1, -3]])
    m = pencil_modal_matrix(a, b)
    assert all(isinstance(r, sp.CRootOf) for r in m.eigenvalues)
    resid = (a * m.V * m.Lambda + b * m.V).evalf(30)
    assert max(abs(complex(e)) for e in resid) < 1e-25
    ddelta = sp.diff((a * lam + b).det(), lam)
    wav = (m.W * a * m.V).evalf(30)
    expected = sp.diag(*[ddelta.subs(lam, r) for r in m.eigenvalues]).evalf(30)
    assert max(abs(complex(e)) for e in wav - expected) < 1e-20


def test_modal_errors():
    with pytest.raises(ModelError, match="non-linear elementary divisor"):
        modal_matrix(sp.Matrix([[1, 1], [0, 1]]))
    with pytest.raises(ModelError, match="square"):
        modal_matrix(sp.Matrix([[1, 2, 3], [4, 5, 6]]))
    with pytest.raises(ModelError, match="leading matrix a is singular"):
        pencil_modal_matrix(sp.Matrix([[1, 0], [0, 0]]), sp.Matrix([[1, 2], [3, 4]]))
    with pytest.raises(ModelError, match="closer than"):
        modal_matrix(sp.Matrix([[1.0, 1.0], [0.0, 1.0 + 1e-11]]))
    # a triple root in floats: mpmath's polyroots does not converge on it (NoConvergence escaped before)
    with pytest.raises(ModelError, match=r"did not converge .*give exact"):
        modal_matrix(sp.Matrix([[1.5, 0.0, 0.0], [0.0, 1.5, 0.0], [0.0, 0.0, 1.5]]))


# --- Luzin's triangular canonical form -------------------------------------------------------------------------------


def test_luzin_book_example_1_22():
    """§1.22 Ex. 1 [reconstructed in the report, §3 item 3]: f = [[2l^2+3, 2l+1],[l^2-2, l+2]],
    u f = [[1, -3/7],[0, l^2 + 7l/3 + 8/3]], u = [[1/7, -2/7],[-(l^2-2)/3, (2l^2+3)/3]], det u = 1/3."""
    f = sp.Matrix([[2 * lam**2 + 3, 2 * lam + 1], [lam**2 - 2, lam + 2]])
    res = luzin_form(f, lam)
    assert res.H == sp.Matrix([[1, sp.Rational(-3, 7)], [0, lam**2 + sp.Rational(7, 3) * lam + sp.Rational(8, 3)]])
    u = sp.Matrix([[sp.Rational(1, 7), sp.Rational(-2, 7)], [-(lam**2 - 2) / 3, (2 * lam**2 + 3) / 3]])
    assert _zero(res.U - u)
    assert res.U.det() == sp.Rational(1, 3)
    assert res.luzin and res.rank == 2


def _random_unimodular(n: int, rng: random.Random) -> sp.Matrix:
    P = sp.eye(n)
    for _ in range(5):
        i, j = rng.sample(range(n), 2)
        P[i, :] = (P[i, :] + (rng.randint(-2, 2) * lam + rng.randint(-2, 2)) * P[j, :]).applyfunc(sp.expand)
        P[rng.randrange(n), :] *= rng.choice([2, -3, sp.Rational(1, 2)])
    P.row_swap(0, n - 1)
    return P


def _check_canonical(f: sp.Matrix, res) -> None:
    assert (res.U * f).applyfunc(sp.expand) == res.H
    detu = sp.expand(res.U.det())
    assert detu != 0 and not detu.has(lam)
    for k, c in enumerate(res.pivots):
        piv = sp.Poly(res.H[k, c], lam)
        assert piv.LC() == 1
        for r in range(k):
            assert res.H[r, c] == 0 or sp.degree(res.H[r, c], lam) < piv.degree()
        assert all(res.H[k, j] == 0 for j in range(c))
    assert res.H[res.rank :, :].is_zero_matrix


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_luzin_uniqueness_under_unimodular_rows(seed):
    """Luzin's theorem (1.176): H is unique, so H(P f) = H(f) for any unimodular P; and det f / LC = prod g_kk."""
    rng = random.Random(seed)
    f = sp.Matrix(3, 3, lambda i, j: sp.Poly([rng.randint(-3, 3) for _ in range(3)], lam).as_expr())
    res = luzin_form(f, lam)
    _check_canonical(f, res)
    P = _random_unimodular(3, rng)
    assert luzin_form((P * f).applyfunc(sp.expand), lam).H == res.H
    det = sp.Poly(f.det(), lam)
    assert sp.expand(sp.prod([res.H[k, k] for k in range(3)]) - det.as_expr() / det.LC()) == 0


def test_luzin_rectangular_coprime_minors():
    """§1.22 Ex. 2 statement: a 3x2 matrix whose 2nd-order minors are coprime (D2 = 1) has the canonical form
    [[1,0],[0,1],[0,0]]."""
    f = sp.Matrix([[lam, 1], [lam**2 + 1, lam], [lam - 1, 2]])
    res = luzin_form(f, lam)
    assert res.H == sp.Matrix([[1, 0], [0, 1], [0, 0]])
    _check_canonical(f, res)


def test_luzin_pivot_not_in_first_column():
    """Outside Luzin's hypothesis the echelon pivots move right; the flag says so."""
    f = sp.Matrix([[0, lam**2, 1], [0, 2 * lam, lam]])
    res = luzin_form(f, lam)
    assert res.pivots[0] == 1 and not res.luzin
    _check_canonical(f, res)


def test_luzin_bad_input():
    with pytest.raises(ParameterError, match="not a polynomial"):
        luzin_form(sp.Matrix([[1 / lam, 1]]), lam)
