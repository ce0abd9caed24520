"""matrix_function: exact/symbolic Sylvester and confluent formulas, floating-point clusters, bad input."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import scipy.linalg as sla
import sympy as sp

from symosc.algebra import matrix_function, series_converges, spectral_decomposition
from symosc.errors import ModelError, ParameterError

from .conftest import similar

x, t = sp.symbols("x t")


def test_bulgakov_1_35_rational_function():
    """Bulgakov §1.35 (seed 004, research report §3 item 4): R(λ) = (λ+1)/(4λ) of z = [[4,-3],[2,-1]].

    Expected (1/8)[[1, 3], [-2, 6]]; checked against the direct product (z + E)(4z)^-1, and the book's remarks that the
    eigenvalues of R(z) are R(1) = 1/2, R(2) = 3/8 and that z = 5E - 8R(z).
    """
    z = sp.Matrix([[4, -3], [2, -1]])
    R = matrix_function(z, (x + 1) / (4 * x))
    assert R == sp.Matrix([[1, 3], [-2, 6]]) / 8
    assert R == (z + sp.eye(2)) * (4 * z).inv()
    assert set(R.eigenvals()) == {sp.Rational(1, 2), sp.Rational(3, 8)}
    assert 5 * sp.eye(2) - 8 * R == z


def test_bulgakov_1_36_divisor_splitting_value():
    """Bulgakov §1.36 (report §3 item 5): S(λ) = λ/(1+λ²) of the Jordan block J_2(1) is (1/2)E, since S'(1) = 0."""
    z = sp.Matrix([[1, 1], [0, 1]])
    S = matrix_function(z, sp.Lambda(x, x / (1 + x**2)))
    assert S == sp.eye(2) / 2
    assert S == z * (sp.eye(2) + z**2).inv()


@pytest.mark.parametrize(
    "blocks",
    [
        [(2, 3)],  # one Jordan block
        [(2, 1), (2, 1), (3, 1)],  # derogatory (report §3 item 14)
        [(1, 2), (1, 1), (-1, 1)],  # non-linear and linear divisors at the same root
        [(0, 2), (-2, 2)],
    ],
)
def test_exp_At_matches_sympy_exp(blocks):
    """exp(At) in the confluent case against SymPy's own Matrix.exp (Jordan-form based)."""
    A, _, _ = similar(blocks, seed=len(blocks))
    F = matrix_function(A, sp.Lambda(x, sp.exp(x * t)))
    ref = (A * t).exp()
    assert (F - ref).applyfunc(sp.simplify).is_zero_matrix


def test_symbolic_oscillator_exp():
    """exp(At) of the damped-oscillator matrix with symbolic ω, ζ (simple symbolic roots), checked numerically
    against scipy.linalg.expm at several parameter values."""
    w, z = sp.symbols("omega zeta", positive=True)
    A = sp.Matrix([[0, 1], [-(w**2), -2 * z * w]])
    F = matrix_function(A, sp.Lambda(x, sp.exp(x * t)))
    for wv, zv, tv in [(2.0, 0.1, 1.3), (1.0, 2.5, 0.7), (3.0, 0.7, 2.0)]:
        num = np.array(F.subs({w: wv, z: zv, t: tv}).evalf(), dtype=complex)
        ref = sla.expm(np.array([[0, 1], [-(wv**2), -2 * zv * wv]]) * tv)
        np.testing.assert_allclose(num.real, ref, rtol=1e-12, atol=1e-14)
        assert np.max(np.abs(num.imag)) < 1e-12


def test_sin_cos_At():
    """sin and cos of At: sin² + cos² = E exactly, and numerically against scipy's sinm/cosm."""
    A, _, _ = similar([(1, 2), (-3, 1)], seed=3)
    s = matrix_function(A, sp.Lambda(x, sp.sin(x * t)))
    c = matrix_function(A, sp.Lambda(x, sp.cos(x * t)))
    assert (s**2 + c**2 - sp.eye(3)).applyfunc(sp.simplify).is_zero_matrix
    An = np.array(A, dtype=float)
    np.testing.assert_allclose(np.array(s.subs(t, 0.7), dtype=float), sla.sinm(0.7 * An), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(np.array(c.subs(t, 0.7), dtype=float), sla.cosm(0.7 * An), rtol=1e-12, atol=1e-12)


def test_resolvent_and_laurent():
    """(E - A)^-1 and the Laurent series A + A^-1 and A^-1 = Σ λ^-1 ε (Bulgakov §1.33), against Matrix.inv."""
    A, _, _ = similar([(2, 2), (-1, 1), (3, 1)], seed=7)
    E = sp.eye(4)
    assert matrix_function(A, 1 / (1 - x)) == (E - A).inv()
    assert matrix_function(A, x + 1 / x) == A + A.inv()
    assert matrix_function(A, 1 / x**2) == (A**2).inv()
    # an infinite Laurent series: exp(1/λ), numerically
    F = np.array(matrix_function(A, sp.exp(1 / x)).evalf(), dtype=float)
    np.testing.assert_allclose(F, sla.expm(np.array(A.inv(), dtype=float)), rtol=1e-12, atol=1e-14)


def test_square_root_and_log_of_jordan_blocks():
    """A^(1/2) squared gives A, and exp(log A) = A, with non-linear elementary divisors."""
    A, _, _ = similar([(4, 2), (9, 1)], seed=11)
    R = matrix_function(A, sp.sqrt)
    assert (R**2 - A).applyfunc(sp.simplify).is_zero_matrix
    L = np.array(matrix_function(A, sp.log).evalf(), dtype=float)
    np.testing.assert_allclose(sla.expm(L), np.array(A, dtype=float), rtol=1e-12)
    np.testing.assert_allclose(L, sla.logm(np.array(A, dtype=float)), rtol=1e-10, atol=1e-12)


def test_sqrt_at_simple_zero_is_defined():
    """sqrt needs only f(0) at a simple (or semisimple) zero eigenvalue."""
    A = sp.Matrix([[0, 1], [0, 4]])
    R = matrix_function(A, sp.sqrt)
    assert R**2 == A
    assert matrix_function(sp.zeros(2, 2), sp.sqrt) == sp.zeros(2, 2)


def test_polynomial_and_sylvester_method():
    """Sylvester's simple-root formula equals a direct polynomial evaluation, also when the characteristic
    polynomial is an irreducible cubic (roots as CRootOf; the sum over them is done exactly with RootSum)."""
    A = sp.Matrix([[1, 2, 0], [0, 3, 1], [1, 0, -2]])
    p = x**4 - 3 * x**2 + x - 7
    expected = A**4 - 3 * A**2 + A - 7 * sp.eye(3)
    assert matrix_function(A, p, method="sylvester") == expected
    assert matrix_function(A, 1 / (1 - x)) == (sp.eye(3) - A).inv()
    F = matrix_function(A, sp.exp).evalf(30)
    with mpmath.workdps(30):
        R = mpmath.expm(mpmath.matrix(A.tolist()))
        assert max(abs(mpmath.mpf(str(F[i, j])) - R[i, j]) for i in range(3) for j in range(3)) < 1e-25


def test_spectral_data_exact():
    """Spectral data on request: ε_σ sum to E, are orthogonal idempotents, η = (A - λE)ε (1.289–1.297)."""
    A, _, _ = similar([(2, 3), (-1, 1)], seed=5)
    res = matrix_function(A, sp.exp, spectral=True)
    S = res.spectral
    assert sum(S.projectors, sp.zeros(4, 4)) == sp.eye(4)
    by_root = {c.root: c for c in S.components}
    assert by_root[2].index == 3 and by_root[2].multiplicity == 3 and by_root[-1].index == 1
    eta = by_root[2].nilpotents[0]
    assert eta == (A - 2 * sp.eye(4)) * by_root[2].projector
    assert by_root[2].nilpotents[1] == eta**2 and (eta**3).is_zero_matrix
    # Frazer–Duncan–Collar components: f(A) = Σ f^(j)(λ) Z_j, here for f = x^5 against A^5
    fz = sum((sp.diff(x**5, x, j).subs(x, c.root) * Z for c in S.components for j, Z in enumerate(c.Z)), sp.zeros(4))
    assert fz == A**5
    assert "exact=True" in repr(S) and "MatrixFunction" in repr(res)


# ---------------------------------------------------------------------------------------------- floating point


def _mp_expm(A: np.ndarray) -> mpmath.matrix:
    with mpmath.workdps(50):
        return mpmath.expm(mpmath.matrix(A.tolist()))


def _rel_err(F, R: mpmath.matrix) -> float:
    n = R.rows
    with mpmath.workdps(50):
        num = max(abs(mpmath.mpf(float(F[i, j])) - R[i, j]) for i in range(n) for j in range(n))
        den = max(abs(R[i, j]) for i in range(n) for j in range(n))
        return float(num / den)


def _near_jordan(delta: float, seed: int) -> np.ndarray:
    """Dense float matrix S J S^-1 with eigenvalues 0.5, 0.5+δ, 0.5+2δ (coupled like a Jordan block) and -1."""
    J = np.array([[0.5, 1, 0, 0], [0, 0.5 + delta, 1, 0], [0, 0, 0.5 + 2 * delta, 0], [0, 0, 0, -1.0]])
    S = np.random.default_rng(seed).normal(size=(4, 4))
    return S @ J @ np.linalg.inv(S)


@pytest.mark.parametrize("delta", [1e-4, 1e-8, 1e-12])
def test_near_repeated_roots_target(delta):
    """Target: eigenvalue gaps δ = 1e-4, 1e-8, 1e-12 (float entries): relative error <= 1e-10 against a
    50-digit mpmath expm of the same float matrix (research report §5 item 1)."""
    for seed in (0, 1):
        A = _near_jordan(delta, seed)
        F = matrix_function(sp.Matrix(A.tolist()), sp.exp)
        assert _rel_err(F, _mp_expm(A)) <= 1e-10
    # the 2x2 example of the research report
    A2 = np.array([[1.0, 1.0], [0.0, 1.0 + delta]])
    assert _rel_err(matrix_function(sp.Matrix(A2.tolist()), sp.exp), _mp_expm(A2)) <= 1e-13


def test_plain_sylvester_loses_accuracy_as_roots_merge():
    """The simple formula loses ~1e-16/δ (report §5 item 1); 'auto' does not. Guards the reason 'auto' exists."""
    A = _near_jordan(1e-12, 0)
    R = _mp_expm(A)
    plain = _rel_err(matrix_function(sp.Matrix(A.tolist()), sp.exp, method="sylvester"), R)
    auto = _rel_err(matrix_function(sp.Matrix(A.tolist()), sp.exp), R)
    assert plain > 1e-8 > 1e-13 > auto


def test_exactly_defective_float_matrix():
    """A float matrix with an exact 3x3 Jordan block (numpy splits its eigenvalues by ~1e-5)."""
    J = np.array([[2.0, 1, 0], [0, 2, 1], [0, 0, 2]])
    S = np.array([[1.0, 2, 0], [0, 1, 3], [1, 0, 1]])
    A = S @ J @ np.linalg.inv(S)
    F = matrix_function(A, sp.exp)  # ndarray in, ndarray out
    assert isinstance(F, np.ndarray) and F.dtype == float
    R = _mp_expm(A)
    assert _rel_err(sp.Matrix(F.tolist()), R) <= 1e-11


@pytest.mark.parametrize("eigs", [list(range(1, 13)), [-50, 0, 50]])
def test_wide_spectra(eigs):
    """Research report §5 item 3: spectra {1..12} and {-50, 0, 50} for exp, against 50-digit mpmath."""
    n = len(eigs)
    rng = np.random.default_rng(4)
    S = np.eye(n) + 0.3 * rng.normal(size=(n, n))
    A = S @ np.diag(np.array(eigs, dtype=float)) @ np.linalg.inv(S)
    F = matrix_function(A, sp.exp)
    assert _rel_err(sp.Matrix(F.tolist()), _mp_expm(A)) <= 1e-10


def test_float_complex_pair_gives_real_result_and_spectral_data():
    """A real matrix with complex eigenvalues: the result is real; float projectors sum to E and are idempotent."""
    A = sp.Matrix([[0.0, 1.0, 0.0], [-4.0, -0.2, 0.0], [1.0, 0.0, -1.0]])
    res = matrix_function(A, sp.Lambda(x, sp.cos(x)), spectral=True)
    assert all(v.is_real for v in res.value)
    ref = sla.cosm(np.array(A, dtype=float))
    np.testing.assert_allclose(np.array(res.value, dtype=float), ref, rtol=1e-13, atol=1e-14)
    P = [np.array(p.evalf(), dtype=complex) for p in res.spectral.projectors]
    np.testing.assert_allclose(sum(P), np.eye(3), atol=1e-12)
    for p in P:
        np.testing.assert_allclose(p @ p, p, atol=1e-12)


def test_float_cluster_spectral_data():
    """A float cluster is one component with multiplicity 2; its 'nilpotent' (A - μE)P has tiny square."""
    A = sp.Matrix([[1.0, 1.0], [0.0, 1.0 + 1e-9]])
    S = spectral_decomposition(A)
    (c,) = S.components
    assert c.multiplicity == 2 and len(c.nodes) == 2
    N = np.array(c.nilpotents[0], dtype=float)
    assert np.max(np.abs(N @ N)) < 1e-17


def test_sqrt_of_negative_eigenvalue_is_complex():
    A = np.array([[-4.0, 1.0], [0.0, 9.0]])
    R = matrix_function(A, sp.sqrt)
    assert np.iscomplexobj(R)
    np.testing.assert_allclose(R @ R, A, atol=1e-13)


# ---------------------------------------------------------------------------------------------- bad input


def test_non_square_rejected():
    with pytest.raises(ModelError, match="square"):
        matrix_function(sp.Matrix([[1, 2, 3], [4, 5, 6]]), sp.exp)


@pytest.mark.parametrize(
    ("A", "f", "match"),
    [
        (sp.Matrix([[0, 1], [0, 2]]), sp.log, "not analytic at the eigenvalue 0"),
        (sp.Matrix([[0, 1], [0, 0]]), sp.sqrt, "derivative of order 1"),
        (sp.Matrix([[2, 1], [0, 3]]), 1 / (x - 2), "not analytic at the eigenvalue 2"),
        (sp.Matrix([[0.0, 1.0], [0.0, 2.0]]), sp.log, "not analytic at the eigenvalue 0"),
        (sp.Matrix([[0.0, 1.0], [0.0, 0.0]]), sp.sqrt, "not analytic at the eigenvalue 0"),
    ],
)
def test_not_analytic_at_eigenvalue(A, f, match):
    with pytest.raises(ModelError, match=match):
        matrix_function(A, f)


def test_other_bad_input():
    with pytest.raises(ModelError, match="repeated roots"):
        matrix_function(sp.Matrix([[1, 1], [0, 1]]), sp.exp, method="sylvester")
    with pytest.raises(ParameterError, match="unknown method"):
        matrix_function(sp.eye(2), sp.exp, method="pade")
    with pytest.raises(ParameterError, match="free parameters"):
        matrix_function(sp.Matrix([[1.0, 0], [0, 2.0]]), sp.Lambda(x, sp.exp(x * t)))
    with pytest.raises(ParameterError, match="var="):
        matrix_function(sp.eye(2), sp.exp(x * t))
    assert matrix_function(sp.eye(2), sp.exp(x * t), var=x) == sp.eye(2) * sp.exp(t)


# ---------------------------------------------------------------------------------------------- closed forms


def test_nilpotent_closed_forms_and_cayley_block():
    """Bulgakov §1.28 Ex. 3 / §1.6 Ex. 3-4 (report §3 items 8 and 12): for the n×n shift v, exp(v) = Σ_(k<n) v^k/k!,
    log(E+v) = Σ (-1)^(k+1) v^k/k, (E+v)^m = Σ binom(m,k) v^k (1.251–1.253), (2E+γ)^-1 by (1.73); and the Cayley
    block Q = [[e, w], [-w, e]]: exp(Qt) = e^(et) [[cos wt, sin wt], [-sin wt, cos wt]] (1.249–1.250)."""
    n = 4
    v = sp.Matrix(n, n, lambda i, j: 1 if j == i + 1 else 0)
    E = sp.eye(n)
    m = sp.Symbol("m")
    assert matrix_function(v, sp.exp) == sum((v**k / sp.factorial(k) for k in range(n)), sp.zeros(n))
    assert matrix_function(E + v, sp.log) == sum(((-1) ** (k + 1) * v**k / k for k in range(1, n)), sp.zeros(n))
    power = matrix_function(E + v, sp.Lambda(x, x**m))
    expected = sum((sp.binomial(m, k) * v**k for k in range(n)), sp.zeros(n))
    assert (power - expected).applyfunc(lambda e: sp.simplify(sp.expand_func(e))).is_zero_matrix
    gamma = sp.Matrix([[0, 1, 3, 1], [0, 0, 1, 6], [0, 0, 0, 2], [0, 0, 0, 0]])
    c = 2 * E + gamma
    series = sum(((-1) ** k * sp.Rational(1, 2) ** (k + 1) * gamma**k for k in range(n)), sp.zeros(n))
    assert matrix_function(c, 1 / x) == series == c.inv()
    e, w = sp.symbols("e w", positive=True)
    Q = sp.Matrix([[e, w], [-w, e]])
    got = matrix_function(Q, sp.Lambda(x, sp.exp(x * t)))
    rot = sp.exp(e * t) * sp.Matrix([[sp.cos(w * t), sp.sin(w * t)], [-sp.sin(w * t), sp.cos(w * t)]])
    assert (got - rot).applyfunc(lambda z: sp.simplify(z.rewrite(sp.exp))).is_zero_matrix


def test_confluent_limit_and_tiny_gap():
    """Report §5 item 1: the exact 2-root formula for [[1,1],[0,1+d]] tends to the confluent value as d -> 0
    (SymPy limit), and in floating point d = 1e-15 still gives full accuracy with 'auto'."""
    d = sp.Symbol("d")
    F = matrix_function(sp.Matrix([[1, 1], [0, 1 + d]]), sp.exp)
    assert sp.limit(F[0, 1], d, 0) == matrix_function(sp.Matrix([[1, 1], [0, 1]]), sp.exp)[0, 1] == sp.E
    A = np.array([[1.0, 1.0], [0.0, 1.0 + 1e-15]])
    assert _rel_err(sp.Matrix(matrix_function(A, sp.exp).tolist()), _mp_expm(A)) <= 1e-15
    assert matrix_function(sp.Matrix([[2]]), sp.exp) == sp.Matrix([[sp.exp(2)]])


def test_cluster_next_to_a_singularity():
    """Eigenvalues 0 and 1e-9 with sqrt: clusters are relative to each eigenvalue's size, so the two are separate
    (no refusal) and the result squares back to A.  A pole between two linked eigenvalues (1 and 1.01, pole at
    1.0051) makes the cluster's Taylor series diverge; the clusters shrink and the result matches the inverse."""
    A = np.array([[1e-9, 1.0], [0.0, 0.0]])
    R = matrix_function(A, sp.sqrt)
    np.testing.assert_allclose(R @ R, A, rtol=1e-9, atol=1e-18)
    B = np.array([[1.0, 2.0], [0.0, 1.01]])
    F = matrix_function(B, sp.Lambda(x, 1 / (x - 1.0051)))
    np.testing.assert_allclose(F, np.linalg.inv(B - 1.0051 * np.eye(2)), rtol=1e-10)


def test_log_near_convergence_boundary_non_normal():
    """Report §5 item 5: log(E + z) for a strongly non-normal z with spectral radius 0.99 (the power series would
    converge very slowly); matrix_function needs no series and agrees with scipy.linalg.logm; exp undoes it."""
    z = np.array([[0.99, 50.0, 0.0], [0.0, -0.5, 30.0], [0.0, 0.0, 0.2]])
    assert series_converges(sp.Matrix(z.tolist()), 1) is True
    L = matrix_function(np.eye(3) + z, sp.log)
    np.testing.assert_allclose(L, sla.logm(np.eye(3) + z), rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(matrix_function(L, sp.exp), np.eye(3) + z, rtol=1e-11, atol=1e-11)


def _mp_matrix(M, digits=30):
    """Entries at ``digits`` digits as an mpmath matrix; each CRootOf replaced by its value polished by Newton's
    method in mpmath from a 15-digit start (SymPy's own refinement to 40 digits takes seconds per root)."""
    values = {}
    for r in M.atoms(sp.CRootOf):
        with mpmath.workdps(digits + 15):
            z = mpmath.findroot(sp.lambdify(r.poly.gen, r.expr, "mpmath"), mpmath.mpc(complex(r.n(15))))
        values[r] = sp.Float(z.real, digits + 15) + sp.I * sp.Float(z.imag, digits + 15)
    M = M.xreplace(values)

    def mp(e):
        v = sp.N(e, digits)
        return mpmath.mpc(mpmath.mpf(str(sp.re(v))), mpmath.mpf(str(sp.im(v))))

    return mpmath.matrix([[mp(e) for e in row] for row in M.tolist()])


@pytest.mark.parametrize("poly", ["x**3 - x - 1", "x**4 - x - 1"])
def test_log_and_exp_of_companions_with_irreducible_characteristic_polynomials(poly):
    """Exact log A and exp A (CRootOf roots) of the companion matrices of x³ - x - 1 and x⁴ - x - 1, against
    mpmath's expm and logm at 30 digits; x⁴ - x - 1 has a root near -0.72, where the principal logarithm
    (ln|λ| + iπ) is checked against scipy's logm (mpmath's logm takes the other side of the cut there)."""
    A = sp.Matrix.companion(sp.Poly(sp.sympify(poly), x))
    with mpmath.workdps(30):
        An = mpmath.matrix(A.tolist())
        ref = mpmath.expm(An)
        got = _mp_matrix(matrix_function(A, sp.exp))
        assert mpmath.mnorm(got - ref, 1) < mpmath.mpf(10) ** -25 * mpmath.mnorm(ref, 1)
        log = _mp_matrix(matrix_function(A, sp.log))
        if A.rows == 3:
            ref = mpmath.logm(An)
            assert mpmath.mnorm(log - ref, 1) < mpmath.mpf(10) ** -25 * mpmath.mnorm(ref, 1)
        else:
            got = np.array(log.tolist(), dtype=complex)
            assert np.max(np.abs(got - sla.logm(np.array(A, dtype=float)))) < 1e-12
            assert mpmath.mnorm(mpmath.expm(log) - An, 1) < mpmath.mpf(10) ** -25


def test_exp_At_of_an_irreducible_cubic_with_a_symbolic_scale():
    """exp(A t) for A with an irreducible cubic (and a Jordan block): A t = t * B, B's projectors, roots t λ
    (CRootOf), nilpotent t η; against mpmath.expm at two values of t.  The quadratic case keeps its cos/sin form."""
    C = sp.Matrix.companion(sp.Poly(x**3 - x - 1, x))
    A = sp.diag(C, sp.Matrix([[1, 1], [0, 1]]))
    A[0, 4] = A[1, 3] = 1  # couple the blocks (block triangular: det(λE - A) = (λ³ - λ - 1)(λ - 1)²)
    result = matrix_function(A * t, sp.exp, spectral=True)
    E, S = result.value, result.spectral
    assert E.has(sp.CRootOf) and E.free_symbols == {t}
    with mpmath.workdps(30):
        for tv in (sp.Rational(2, 5), sp.Rational(-13, 10)):
            ref = mpmath.expm(mpmath.matrix((A * tv).tolist()))
            got = _mp_matrix(E.subs(t, tv))
            assert mpmath.mnorm(got - ref, 1) < mpmath.mpf(10) ** -25 * mpmath.mnorm(ref, 1)
    assert sorted(c.index for c in S.components) == [1, 1, 1, 2]
    assert any(c.root == t for c in S.components)
    # a polynomial f: the sum over the conjugate roots is exact (RootSum), here (A t)**2
    assert (matrix_function(A * t, sp.Lambda(x, x**2)) - (A * t) ** 2).applyfunc(sp.expand).is_zero_matrix
    osc = matrix_function(sp.Matrix([[0, 1], [-4, 0]]) * t, sp.exp)
    assert sp.simplify(osc[0, 0] - sp.cos(2 * t)) == 0
