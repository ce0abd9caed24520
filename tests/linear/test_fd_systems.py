"""Systems f(D) y = e(D) x (Bulgakov (1954), §8.2–8.12, 8.28, 8.54; examples E1–E5, E7, E8, E14, E19, E20).

Each fundamental matrix is checked by applying f(D) to it symbolically (f(D) ϑ = 0) and by its column count
deg Δ, and against the book's columns up to a change of basis.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from symosc.errors import ModelError, ParameterError
from symosc.linear import compatibility, frequency_response, fundamental_solutions, worst_case_gain
from symosc.linear.multi_dof.fd_systems import NEPERS_PER_DECIBEL

D, t, b = sp.symbols("D t b")


def _apply(f, Y):
    """f(D) applied to the columns of Y(t) (D = d/dt)."""
    f = sp.Matrix(f)
    out = sp.zeros(f.rows, Y.cols)
    for i in range(f.rows):
        for j in range(f.cols):
            poly = sp.Poly(f[i, j], D)
            for (k,), c in poly.terms():
                out[i, :] += c * sp.diff(Y[j, :], t, k) if k else c * Y[j, :]
    return out.applyfunc(lambda v: sp.simplify(sp.expand(v)))


def _same_span(A, B):
    return A.rank(simplify=True) == B.rank(simplify=True) == sp.Matrix.hstack(A, B).rank(simplify=True)


def test_e1_compatibility_modified_minors():
    """§8.4: modified minors 2(D+1)z, (D+1)z, -(D+1)z; compatibility (D+1) z = 0; a regular system has none."""
    f = [[D**2 - 2 * D - 1, D - 1, D**2 - D - 4], [D - 2, 1, D - 2], [-1, -1, D - 4]]
    c = compatibility(f, [2 * D, 1, -1], D)
    assert c.rank == 2 and c.operator == D + 1
    assert {sp.factor(m / (D + 1)) for m in c.modified_minors} <= {2, 1, -1, -2}
    assert compatibility([[D, 1], [0, D]], [1, 0], D).always_compatible


@pytest.mark.parametrize(
    "f, det, book",
    [
        # E2 §8.10 Ex. 1
        ([[D**3, D**2 + D + 1], [D**3 + D, D**2 + D + 2]], -D * (D + 1), sp.Matrix([[1, sp.exp(-t)], [0, sp.exp(-t)]])),
        # E3 §8.10 Ex. 2 (reconstructed matrix): roots -1 (double, linear divisors) and -2
        (
            [[D, D, -1], [D, 2 * D + 1, -1], [2, 2, D + 3]],
            (D + 1) ** 2 * (D + 2),
            sp.Matrix(
                [[-sp.exp(-t), sp.exp(-t), -sp.exp(-2 * t)], [sp.exp(-t), 0, 0], [0, -sp.exp(-t), 2 * sp.exp(-2 * t)]]
            ),
        ),
        # E4 §8.11 Ex. 1 (Bromwich): polynomial modal columns [t+4, -t], [1, -1]
        (
            [[2 * D**2 - 3, -1], [1, 2 * D**2 - 1]],
            4 * (D - 1) ** 2 * (D + 1) ** 2,
            sp.Matrix(
                [
                    [(t + 4) * sp.exp(t), sp.exp(t), (t - 4) * sp.exp(-t), sp.exp(-t)],
                    [-t * sp.exp(t), -sp.exp(t), -t * sp.exp(-t), -sp.exp(-t)],
                ]
            ),
        ),
        # E7 §8.12 Ex. 1 with b = 3
        (
            [[D**2 + 2 * D + 1, D - 1], [D**2 - 2 * D + 5, D + 3]],
            8 * (D**2 + 1),
            sp.Matrix([[sp.cos(t) + sp.sin(t), -sp.cos(t) + sp.sin(t)], [-2 * sp.sin(t), 2 * sp.cos(t)]]),
        ),
        # E8 §8.12 Ex. 2 (indirect regulation): (D+4)(D²+16)
        (
            [[D**3 + 2 * D**2 + 10 * D, -1], [2 * D**2 + 6 * D + 64, 1]],
            (D + 4) * (D**2 + 16),
            sp.Matrix(
                [
                    [sp.exp(-4 * t), sp.cos(4 * t), sp.sin(4 * t)],
                    [
                        -72 * sp.exp(-4 * t),
                        -32 * sp.cos(4 * t) + 24 * sp.sin(4 * t),
                        -32 * sp.sin(4 * t) - 24 * sp.cos(4 * t),
                    ],
                ]
            ),
        ),
    ],
)
def test_fundamental_solutions_book_examples(f, det, book):
    fs = fundamental_solutions(f, D, t)
    assert sp.expand(fs.determinant - det) == 0
    assert fs.degree == sp.degree(det, D) == fs.matrix.cols
    assert _apply(f, fs.matrix) == sp.zeros(len(f), fs.matrix.cols)
    assert _apply(f, book) == sp.zeros(len(f), book.cols)  # the book's solution, as a check of the transcription
    # same solution space: compare the Wronskian-like stacked values at several times
    times = [0, sp.Rational(1, 3), 1, 2]
    stack = lambda Y: sp.Matrix.vstack(*[Y.subs(t, s) for s in times]).evalf(30)  # noqa: E731
    A, B = stack(fs.matrix), stack(book)
    assert np.linalg.matrix_rank(np.array(sp.Matrix.hstack(A, B), dtype=float), tol=1e-9) == fs.degree


def test_e5_single_divisor_for_double_root():
    """§8.11 Ex. 2 (reconstructed f): Δ = D²(D+3), F(0) ≠ 0, so the double root 0 gives one divisor D² and a
    polynomial column."""
    f = [[7 - D, D**2 - 2 * D], [-2 * D, D**2]]
    fs = fundamental_solutions(f, D, t)
    assert sp.expand(fs.determinant - D**2 * (D + 3)) == 0 and fs.degree == 3
    assert _apply(f, fs.matrix) == sp.zeros(2, 3)
    assert any(v.has(t) and not v.has(sp.exp) for v in fs.matrix)  # a column polynomial in t (λ = 0)


def test_degenerate_and_bad_input():
    with pytest.raises(ModelError, match="compatibility"):
        fundamental_solutions([[D, D], [1, 1]], D, t)
    with pytest.raises(ParameterError, match="polynomial"):
        compatibility([[1 / D, 1], [1, 1]], [1, 1], D)
    with pytest.raises(ModelError, match="resonance"):
        frequency_response([[D**2 + 1]], [[1]], D, [1.0])


def test_e14_frequency_response():
    """§8.28 Ex. 1: X(iω) = [b + iω, ω² - (b+2) + i(b-1)ω] / (2(b+1)(1 - ω²))."""
    bv = 3.0
    f = [[D**2 + 2 * D + 1, D - 1], [D**2 + (1 - bv) * D + bv + 2, D + bv]]
    for w in (0.3, 2.0, 5.0):
        X = frequency_response(f, [[1], [0]], D, [w]).values[0, :, 0]
        book = np.array([bv + 1j * w, w**2 - (bv + 2) + 1j * (bv - 1) * w]) / (2 * (bv + 1) * (1 - w**2))
        assert np.allclose(X, book, rtol=1e-12)


def test_e19_units():
    """1 dB = 0.11513 Np; a gain of 10 is 20 dB and ln 10 Np."""
    assert round(NEPERS_PER_DECIBEL, 5) == 0.11513
    r = frequency_response([[1]], [[10]], D, [1.0])
    assert np.isclose(r.decibels[0, 0, 0], 20) and np.isclose(r.nepers[0, 0, 0], np.log(10))
    assert np.isclose(r.nepers[0, 0, 0], r.decibels[0, 0, 0] * NEPERS_PER_DECIBEL)


@pytest.mark.parametrize("zeta", [0.15, 0.05])
def test_e20_accumulation(zeta):
    """§8.54 (E20): (TD+1)y = x gives A = 1; y'' + 2ζωy' + ω²y = x gives A = coth(πζ/(2√(1-ζ²)))/ω²
    (ω = 2, ζ = 0.15: 1.06881328)."""
    assert abs(worst_case_gain([1], [0.7, 1]) - 1) < 1e-9
    w = 2.0
    A = worst_case_gain([1], [1, 2 * zeta * w, w**2])
    closed = 1 / np.tanh(np.pi * zeta / (2 * np.sqrt(1 - zeta**2))) / w**2
    assert abs(A - closed) < 1e-8 * closed
    if zeta == 0.15:
        assert round(A, 8) == 1.06881328


def test_e11_forced_solution_kernels():
    """§8.51: f as in E8, e = [0, 10D]: S(D) = [0, 10D - 20]; kernels (5/4)[-e^{-4t} + cos 4t + sin 4t] and
    5[18 e^{-4t} - 14 cos 4t - 2 sin 4t] as printed."""
    from symosc.linear import impulse_response

    f = [[D**3 + 2 * D**2 + 10 * D, -1], [2 * D**2 + 6 * D + 64, 1]]
    r = impulse_response(f, [0, 10 * D], D, t)
    assert r.direct[0] == 0 and sp.expand(r.direct[1] - (10 * D - 20)) == 0
    k1 = sp.Rational(5, 4) * (-sp.exp(-4 * t) + sp.cos(4 * t) + sp.sin(4 * t))
    k2 = 5 * (18 * sp.exp(-4 * t) - 14 * sp.cos(4 * t) - 2 * sp.sin(4 * t))
    assert sp.simplify(r.kernel[0] - k1) == 0 and sp.simplify(r.kernel[1] - k2) == 0


@pytest.mark.parametrize("seed", range(5))
def test_normal_form_random_pencils(seed):
    """§8.53: z A v = E and z H v = -diag(λ) for random pencils; M y'' + K y = x via the first-order form has
    λ = ±i ω with ω from scipy.linalg.eigh."""
    from scipy.linalg import eigh

    from symosc.linear import modal_normal_form

    rng = np.random.default_rng(seed)
    A, H = rng.standard_normal((4, 4)) + 4 * np.eye(4), rng.standard_normal((4, 4))
    nf = modal_normal_form(A, H)
    assert np.allclose(nf.z @ A @ nf.v, np.eye(4), atol=1e-10)
    assert np.allclose(nf.z @ H @ nf.v, -np.diag(nf.eigenvalues), atol=1e-10)
    X = rng.standard_normal((3, 3))
    M, K = X @ X.T + 3 * np.eye(3), np.diag([1.0, 2.0, 5.0])
    Z = np.zeros((3, 3))
    nf2 = modal_normal_form(np.block([[Z, M], [M, Z]]), np.block([[K, Z], [Z, -M]]))
    w = np.sqrt(eigh(K, M, eigvals_only=True))
    assert np.allclose(np.sort(nf2.eigenvalues.imag[nf2.eigenvalues.imag > 0]), w, rtol=1e-10)
    assert np.abs(nf2.eigenvalues.real).max() < 1e-10
    with pytest.raises(ModelError, match="singular"):
        modal_normal_form(np.diag([1.0, 0.0]), np.eye(2))


def test_resonant_particular_by_substitution():
    """(8.185), (8.209): the particular solution satisfies f(D) y = e(D) ξ e^{λt}, at resonance (E7 system,
    λ = i, growing like t) and off resonance (λ = 2i, equal to X(2i) ξ e^{2it} of E14)."""
    from symosc.linear import resonant_particular

    f = [[D**2 + 2 * D + 1, D - 1], [D**2 + (1 - b) * D + b + 2, D + b]]
    fb = [[v.subs(b, 3) for v in row] for row in f]
    for lam_ in (sp.I, 2 * sp.I):
        y = resonant_particular(fb, [1, 0], D, [1], lam_, t)
        lhs = _apply(fb, y)
        assert (lhs - sp.Matrix([sp.exp(lam_ * t), 0])).applyfunc(sp.simplify) == sp.zeros(2, 1)
    y_res = resonant_particular(fb, [1, 0], D, [1], sp.I, t)
    assert y_res[0].has(t * sp.exp(sp.I * t)) or sp.expand(y_res[0]).has(t)


def test_mean_power_identities():
    """§8.29: P = ½ Re ζ̄'ᵀ(N - iJ/ω)ζ' equals (iω/4)(ξ̄ᵀζ - ξᵀζ̄) and the time average of w·ẏ; G does no work."""
    from symosc.linear import mean_power

    rng = np.random.default_rng(1)
    n, w = 3, 1.7
    X = rng.standard_normal((n, n))
    A, N, H = X @ X.T + n * np.eye(n), np.diag([0.3, 0.1, 0.5]), np.diag([2.0, 3.0, 4.0])
    S = rng.standard_normal((n, n))
    G, J = S - S.T, 0.2 * (S.T - S)
    xi = rng.standard_normal(n) + 1j * rng.standard_normal(n)
    P = mean_power(A, N, G, H, J, xi, w)
    zeta = np.linalg.solve(-(w**2) * A + 1j * w * (N + G) + H + J, xi)
    assert abs(P - np.real(1j * w / 4 * (np.conj(xi) @ zeta - xi @ np.conj(zeta)))) < 1e-12
    ts = np.linspace(0, 2 * np.pi / w, 4001)[:-1]
    force = np.real(np.outer(np.exp(1j * w * ts), xi))
    vel = np.real(np.outer(1j * w * np.exp(1j * w * ts), zeta))
    assert abs(P - np.mean(np.sum(force * vel, axis=1))) < 1e-12
    assert abs(mean_power(A, 0 * N, G, H, 0 * J, xi, w)) < 1e-12


def test_e12_normal_coordinates_kernel():
    """§8.52 Ex. 1: y1'' + y2 = x, y1'' + y1' + y2' + y2 = 0, Δ = D(D-1)(D+1); from ξ1' = -x, ξ2' - ξ2 = x,
    ξ3' + ξ3 = 0, y1 = ξ1 + ξ2 + ξ3, y2 = -ξ2 - ξ3: the kernel of x is [-1 + e^t, -e^t]."""
    from symosc.linear import impulse_response

    r = impulse_response([[D**2, 1], [D**2 + D, D + 1]], [1, 0], D, t)
    assert r.direct == sp.zeros(2, 1)
    assert sp.simplify(r.kernel[0] - (-1 + sp.exp(t))) == 0 and sp.simplify(r.kernel[1] + sp.exp(t)) == 0
