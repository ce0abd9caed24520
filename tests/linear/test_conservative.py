"""Conservative systems and eigenvalue bounds (Bulgakov (1954), §9.1–9.18, examples T1–T8).

References: exact SymPy eigen-computations written out in the test, scipy.linalg.eigh, closed forms of the book.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.linalg import eigh

from symosc.errors import ConvergenceError, ModelError, ParameterError
from symosc.linear import (
    a_orthonormalize,
    chain_matrices,
    conservative_modes,
    constrained_eigenvalues,
    dunkerley,
    dunkerley_bounds,
    influence_matrix,
    power_iteration,
    rayleigh_quotient,
    string_frequencies,
    string_modes,
)


def test_t1_t3_repeated_root_and_a_orthonormal_modes():
    """§9.2 / §9.5 Ex. 1: A = E, H = J - 2E (n = 3): λ = -2 double, λ = 1; vᵀAv = E, vᵀHv = diag(-2, -2, 1)."""
    A = sp.eye(3)
    H = sp.ones(3, 3) - 2 * sp.eye(3)
    r = conservative_modes(A, H)
    assert r.eigenvalues == (-2, -2, 1)
    V = sp.Matrix(r.modes)
    assert V.T * A * V == sp.eye(3)
    assert (V.T * H * V).applyfunc(sp.simplify) == sp.diag(-2, -2, 1)
    assert sp.simplify(V[:, 2] - sp.Matrix([1, 1, 1]) / sp.sqrt(3)) == sp.zeros(3, 1)


def test_t1_singular_h_rigid_body():
    """§9.2 n = 2: H = J - 2E is singular after adding... the two-mass free chain of §9.5 Ex. 2 has λ = 0."""
    m1, m2, c = 2, 3, 5
    r = conservative_modes(sp.diag(m1, m2), sp.Matrix([[c, -c], [-c, c]]))
    assert r.rigid_body_modes == 1
    assert r.eigenvalues[1] == sp.Rational(c * (m1 + m2), m1 * m2)  # ω² = c (m1 + m2)/(m1 m2)


def test_t2_krylov_example():
    """§9.4 Krylov: det h = -(λ-1)²(λ-4); modes span the columns (3, 0, -1), (0, 1, -1) and (1, 1, -1)."""
    A = sp.Matrix([[6, 6, 11], [6, 11, 14], [11, 14, 22]])
    H = sp.Matrix([[9, 15, 20], [15, 38, 41], [20, 41, 49]])
    r = conservative_modes(A, H)
    assert r.eigenvalues == (1, 1, 4)
    V = sp.Matrix(r.modes)
    book = sp.Matrix([[3, 0, 1], [0, 1, 1], [-1, -1, -1]])
    # the λ = 1 subspace is the span of the book's first two columns
    assert sp.Matrix.hstack(V[:, :2], book[:, :2]).rank() == 2
    assert sp.Matrix.hstack(V[:, 2], book[:, 2]).rank() == 1
    assert (V.T * A * V).applyfunc(sp.simplify) == sp.eye(3)


def test_t4_gram_schmidt_and_decoupled_forces():
    """§9.5 Ex. 3: v1* = (5,-4,4)/(12√15), v2* = (0,1,4)/(4√15); λ = 4: (1,1,-1)/(3√3) (the print's 6√3 is wrong)."""
    A = sp.Matrix([[32, -16, 4], [-16, 32, 4], [4, 4, 11]])
    H = sp.diag(48, 48, 12)
    lam = sp.Symbol("lam")
    assert sp.factor((H - lam * A).det()) == sp.factor(-6912 * (lam - 1) ** 2 * (lam - 4))
    V = a_orthonormalize(sp.Matrix([[5, -4], [-4, 5], [4, 4]]), A)
    assert sp.simplify(V[:, 0] - sp.Matrix([5, -4, 4]) / (12 * sp.sqrt(15))) == sp.zeros(3, 1)
    assert sp.simplify(V[:, 1] - sp.Matrix([0, 1, 4]) / (4 * sp.sqrt(15))) == sp.zeros(3, 1)
    r = conservative_modes(A, H)
    v3 = sp.Matrix(r.modes)[:, 2]
    assert sp.simplify(v3 * sp.sign(v3[0]) - sp.Matrix([1, 1, -1]) / (3 * sp.sqrt(3))) == sp.zeros(3, 1)
    x = sp.symbols("x1:4")
    f = r.modal_forces(x)
    assert sp.simplify(f[2] * sp.sign(v3[0]) - (x[0] + x[1] - x[2]) / (3 * sp.sqrt(3))) == 0


def test_bad_mass_matrices():
    with pytest.raises(ModelError, match="singular"):
        dunkerley([[1, 0], [0, 0]], [[2, -1], [-1, 2]])
    with pytest.raises(ModelError, match="indefinite"):
        conservative_modes(np.diag([1.0, -1.0]), np.eye(2))
    with pytest.raises(ModelError, match="positive definite"):
        conservative_modes(sp.diag(1, 0), sp.eye(2))
    with pytest.raises(ModelError, match="stiffness"):
        dunkerley(np.eye(2), [[1, -1], [-1, 1]])


@pytest.mark.parametrize("boundary", ["fixed-fixed", "fixed-free"])
@pytest.mark.parametrize("n", [1, 3, 10, 200])
def test_string_closed_forms_vs_eigh(n, boundary):
    """(9.65), (9.90) and the mode shapes (9.68), (9.91) against scipy.linalg.eigh to 1e-12."""
    P, m, h = 2.5, 0.7, 0.3
    M, K = chain_matrices(np.full(n, m), np.full(n + 1 if boundary == "fixed-fixed" else n, P / h), boundary=boundary)
    w = np.sqrt(eigh(K, M, eigvals_only=True))
    closed = string_frequencies(n, boundary=boundary, tension=P, mass=m, spacing=h)
    assert np.allclose(closed, w, rtol=1e-12, atol=0)
    V = string_modes(n, boundary=boundary)
    residual = K @ V - M @ V * closed**2
    assert np.abs(residual).max() <= 1e-12 * np.abs(K).max() * np.sqrt(n)


def test_t6_values_and_shaft_equivalence():
    """§9.6 n = 3 fixed-fixed: 0.765367, 1.414214, 1.847759; §9.7 fixed-free n = 3: 0.44504, 1.24698, 1.80194."""
    assert np.allclose(string_frequencies(3), [0.765367, 1.414214, 1.847759], atol=5e-7)
    assert np.allclose(string_frequencies(3, boundary="fixed-free"), [0.44504, 1.24698, 1.80194], atol=5e-6)
    # a shaft (J, c) has the same closed forms
    M, K = chain_matrices(np.full(5, 2.0), np.full(5, 8.0), boundary="fixed-free")
    assert np.allclose(
        np.sqrt(eigh(K, M, eigvals_only=True)),
        string_frequencies(5, boundary="fixed-free", tension=8.0, mass=2.0),
        rtol=1e-12,
    )


def test_influence_matrix_is_inverse_stiffness():
    """§9.11: the string influence function is H⁻¹ of the stiffness form (both boundary conditions)."""
    h = [sp.Rational(1, 2), 1, sp.Rational(3, 2), 1]
    x = [sum(h[: j + 1]) for j in range(3)]
    P = 3
    Phi = influence_matrix("string fixed-fixed", x, length=sum(h), rigidity=P)
    _, K = chain_matrices([1, 1, 1], [P / float(v) for v in h])
    assert np.allclose(np.array(Phi, dtype=float) @ K, np.eye(3), atol=1e-13)
    Phi2 = influence_matrix("string fixed-free", x, rigidity=P)
    _, K2 = chain_matrices([1, 1, 1], [P / float(v) for v in h[:3]], boundary="fixed-free")
    assert np.allclose(np.array(Phi2, dtype=float) @ K2, np.eye(3), atol=1e-13)


def test_t7_beam_dunkerley_papkovich_power_iteration():
    """§9.13 beam (masses m, 2m, m at quarter points): ζ³ - 50ζ² + 124ζ - 56; root 0.590600 (the print's 0.5896 is a
    misprint: the product of the roots must be 56); bound table and Table 6."""
    Phi = influence_matrix("beam", [1, 2, 3], length=4) * 768 / 64
    L = Phi * sp.diag(1, 2, 1)
    assert L == sp.Matrix([[9, 22, 7], [11, 32, 11], [7, 22, 9]])
    z = sp.Symbol("z")
    assert sp.expand(L.charpoly(z).as_expr()) == z**3 - 50 * z**2 + 124 * z - 56
    b = dunkerley_bounds(L, powers=(1, 2, 3, 4, 5))
    assert b.traces == (50, 2252, 106568, 5051952, 239509280)
    assert np.allclose(b.z_upper, [50, 47.46, 47.411, 47.4094, 47.4094], atol=6e-3)
    assert np.allclose(b.z_lower[1:], [45.04, 47.321, 47.4059, 47.4093], atol=6e-4)
    z1 = max(np.linalg.eigvals(np.array(L, dtype=float)).real)
    assert all(lo < z1 for lo in b.z_lower[1:]) and all(z1 < hi for hi in b.z_upper)
    r = power_iteration(np.array(L, dtype=float), start=[0.5, 1, 0.5], n_modes=3, mass=np.diag([1, 2, 1]))
    assert np.allclose(r.history[0], [30 / 43, 1, 30 / 43], rtol=1e-12)
    assert np.allclose(sorted(r.eigenvalues), sorted(np.linalg.eigvals(np.array(L, dtype=float)).real), rtol=1e-10)
    # a start orthogonal to the dominant mode converges to ζ = 2 (the antisymmetric mode)
    assert abs(power_iteration(np.array(L, dtype=float), start=[1, 0, -1]).eigenvalues[0] - 2) < 1e-12


def test_t8_aero_engine_shaft():
    """§9.16–9.18: L_jk = 1 + min(j, k); characteristic polynomial (Carter), bounds table (the m = 2 upper bound is
    √519 = 22.782; the printed 22.752 is a misprint), Table 7 and z1 = 22.625853."""
    n = 6
    Phi = influence_matrix("shaft fixed-free", None, compliances=[j + 2 for j in range(n)])
    L = Phi  # equal disks, J = 1
    assert L == sp.Matrix(n, n, lambda j, k: 2 + min(j, k))
    z = sp.Symbol("z")
    assert sp.expand(L.charpoly(z).as_expr()) == z**6 - 27 * z**5 + 105 * z**4 - 140 * z**3 + 81 * z**2 - 21 * z + 2
    b = dunkerley_bounds(L, powers=(1, 2, 3, 4, 5, 6))
    assert b.traces == (27, 519, 11598, 262107, 5929677, 134162280)
    assert np.allclose(b.z_upper[:3], [27, 22.782, 22.636], atol=6e-4)
    assert np.allclose(b.z_lower[1:], [19.222, 22.347, 22.599, 22.623, 22.626], atol=6e-4)
    Lf = np.array(L, dtype=float)
    r = power_iteration(Lf, start=np.eye(n)[-1], n_modes=6)
    assert np.allclose(r.history[0], np.array([2, 3, 4, 5, 6, 7]) / 7, rtol=1e-12)
    assert np.allclose(r.vectors[:, 0], [0.40303, 0.58673, 0.74450, 0.86936, 0.95580, 1], atol=6e-6)
    ref = np.sort(np.linalg.eigvalsh(Lf))[::-1]
    assert abs(r.eigenvalues[0] - 22.625853) < 1e-6
    assert np.allclose(r.eigenvalues, ref, rtol=1e-9)
    assert r.achieved[0] <= 1e-12 and r.iterations[0] > 5


@st.composite
def chains(draw):
    n = draw(st.integers(2, 500))
    seed = draw(st.integers(0, 2**31))
    boundary = draw(st.sampled_from(["fixed-fixed", "fixed-free"]))
    rng = np.random.default_rng(seed)
    m = rng.uniform(0.2, 5.0, n)
    c = rng.uniform(0.2, 5.0, n + 1 if boundary == "fixed-fixed" else n)
    return chain_matrices(m, c, boundary=boundary)


@settings(max_examples=25, deadline=None)
@given(chains())
def test_dunkerley_below_fundamental_below_rayleigh(MK):
    """Dunkerley ≤ ω1 (eigh) ≤ sqrt(Rayleigh) for the static-deflection trial shape, chains of 2..500 masses."""
    M, K = MK
    w1 = np.sqrt(eigh(K, M, eigvals_only=True, subset_by_index=[0, 0])[0])
    u = np.linalg.solve(K, np.diag(M))  # deflection under the weights
    assert dunkerley(M, K) <= w1 * (1 + 1e-12)
    assert w1 <= np.sqrt(rayleigh_quotient(M, K, u)) * (1 + 1e-12)


@settings(max_examples=15, deadline=None)
@given(st.integers(2, 40), st.integers(0, 2**31))
def test_power_iteration_converges(n, seed):
    """Power iteration on L = K⁻¹M of random chains: 1e-12 reached, iteration count reported, z1 matches eigh."""
    rng = np.random.default_rng(seed)
    M, K = chain_matrices(rng.uniform(0.5, 2, n), rng.uniform(0.5, 2, n + 1))
    L = np.linalg.solve(K, M)
    r = power_iteration(L, mass=M, n_modes=2)
    lam = eigh(K, M, eigvals_only=True)
    assert r.achieved[0] <= 1e-12 and r.iterations[0] >= 1
    assert abs(r.eigenvalues[0] * lam[0] - 1) < 1e-9
    assert abs(r.eigenvalues[1] * lam[1] - 1) < 1e-7


def test_power_iteration_equal_moduli_raises():
    with pytest.raises(ConvergenceError):
        power_iteration([[0, 1], [1, 0]], start=[1, 0], max_iterations=50)


@settings(max_examples=20, deadline=None)
@given(st.integers(3, 12), st.integers(1, 2), st.integers(0, 2**31))
def test_interlacing_under_constraints(n, c, seed):
    """§9.9 theorem I: λ_j ≤ λ'_j ≤ λ_(c+j) for c random constraints."""
    rng = np.random.default_rng(seed)
    X = rng.standard_normal((n, n))
    Y = rng.standard_normal((n, n))
    M, K = X @ X.T + n * np.eye(n), Y @ Y.T + np.eye(n)
    lam = eigh(K, M, eigvals_only=True)
    mu = constrained_eigenvalues(M, K, rng.standard_normal((c, n)))
    tol = 1e-10 * lam[-1]
    assert np.all(lam[: n - c] <= mu + tol) and np.all(mu <= lam[c:] + tol)


def test_t5_rayleigh_fixed_free_string():
    """§9.8: trial u_j = j - αj²; minimum λ' = 0.198487 at α = 0.119273; the maximum is 1.59099 (the printed
    2.7847 is inconsistent: it exceeds no bound it should respect, λ(α) ≤ λ3 = 3.24698)."""
    M, K = chain_matrices([1, 1, 1], [1, 1, 1], boundary="fixed-free")
    from scipy.optimize import minimize_scalar

    def lam(a):
        return rayleigh_quotient(M, K, [1 - a, 2 - 4 * a, 3 - 9 * a])

    lo = minimize_scalar(lam, bounds=(0, 0.3), method="bounded", options={"xatol": 1e-10})
    hi = minimize_scalar(lambda a: -lam(a), bounds=(0.3, 0.6), method="bounded", options={"xatol": 1e-10})
    assert abs(lo.x - 0.119273) < 1e-5 and abs(lo.fun - 0.198487) < 1e-6
    assert abs(hi.x - 0.399246) < 1e-5 and abs(-hi.fun - 1.59099) < 1e-5
    assert -hi.fun <= eigh(K, M, eigvals_only=True)[-1]


def test_bad_input_strings():
    with pytest.raises(ParameterError, match="needs 4 stiffnesses"):
        chain_matrices([1, 1, 1], [1, 1])
    with pytest.raises(ParameterError, match="boundary"):
        string_frequencies(3, boundary="free-free")
