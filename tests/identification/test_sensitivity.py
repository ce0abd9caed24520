"""Sensitivity (Jacobian, elasticities), damping perturbation theory and the applicability criterion.

Sources: Belyakov 2005 (seed 001_b22cdb6b21550ad5.txt), Ch. III §3.1 (sensitivity, report §3.8), Ch. III §3.2
(applicability criterion, report §3.9), Ch. III §4 (damping, report §3.10).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.errors import ModelError, ParameterError
from symosc.identification import (
    applicability,
    damping_perturbation,
    jacobian,
    quadratic_modes,
    sensitivity,
)
from symosc.mechanics import complex_modes

# Appendix data (report §4.3/§4.4): identified C' (sensors x modes) and frequencies
C_PRIME = np.array(
    [
        [-0.0006753510, 0.0006737952, -0.0006730062],
        [-0.0006753488, -0.0007192560, -0.0006304674],
        [-0.0006753497, -0.0006737934, 0.0006730067],
        [-0.0006753526, 0.0007192575, 0.0006304678],
    ]
)
OMEGA = np.array([14.04726, 16.39794, 27.35160])


def _algorithm1(xi):
    """Independent Schur-complement closed form of Algorithm 1 (report §3.1), written for this test.

    xi = (p, Lx, Lz, omega1..3, C'11, C'12, ..., C'43) -> (m, rx, rz, Izz, Ixx, M23)."""
    p, lx, lz = xi[0], xi[1], xi[2]
    om = xi[3:6]
    c = xi[6:].reshape(4, 3)
    f = np.array([0 * p, p, 0 * p, 0 * p])
    g = c @ np.linalg.inv(c.T @ c)
    w = g @ np.diag((c.T @ f) / om**2) @ g.T
    z = 0 * lx
    c0 = np.array([[1 + z, z, z], [1 + z, lx, z], [1 + z, lx, -lz], [1 + z, z, -lz]])
    m0 = c0.T @ w @ c0
    m = m0[0, 0]
    return np.array(
        [m, m0[0, 1] / m, -m0[0, 2] / m, m0[1, 1] - m0[0, 1] ** 2 / m, m0[2, 2] - m0[0, 2] ** 2 / m,
         m0[1, 2] - m0[0, 1] * m0[0, 2] / m]
    )  # fmt: skip


XI = np.concatenate([[-2000.0, 4.0, 1.74], OMEGA, C_PRIME.ravel()])


def test_algorithm1_elasticities_belyakov_section_3_8():
    """Belyakov Ch. III §3.1 / report §3.8 and §6 item 13: at the Appendix point, the elasticity of m wrt omega1,
    of Izz wrt omega2 and of Ixx wrt omega3 is -2, and the sums of |elasticities| over the 18 arguments are
    (5.00, 2.77, 2.30, 7.01, 7.03, 71.4) (report's recomputation; the thesis's "<= 2 eps" holds per argument)."""
    res = jacobian(_algorithm1, XI)
    assert res.method == "complex"
    np.testing.assert_allclose(res.value[:5], [15007.7782092, 2.0000051417, 0.8699994282, 44031.4148685, 3005.9361692],
                               rtol=1e-9)  # fmt: skip
    el = res.elasticities
    assert el[0, 3] == pytest.approx(-2.0, abs=1e-6)
    assert el[3, 4] == pytest.approx(-2.0, abs=2e-3)
    assert el[4, 5] == pytest.approx(-2.0, abs=1e-2)
    np.testing.assert_allclose(res.sum_elasticities, [5.00, 2.77, 2.30, 7.01, 7.03, 71.4], rtol=5e-3)
    # per argument, the physical parameters m, Izz, Ixx are at most 2
    assert np.all(res.max_elasticities[[0, 3, 4]] <= 2.0 + 1e-6)
    # first-order error bound is linear in eps
    np.testing.assert_allclose(res.error_bound(0.01), 0.01 * res.sum_elasticities)


def test_sensitivity_of_package_algorithm1_matches_independent_closed_form():
    """Generic use on the package's reconstruction (takes (frequencies, C') arrays, returns a dataclass): its
    stage-3 moduli defeat the complex step, so central differences are used, and they agree with the complex-step
    Jacobian of the independent closed form above (report §3.8)."""
    from symosc.identification import inertia_from_release

    def recon(w, c):
        return inertia_from_release(w, c, [0.0, -2000.0, 0.0, 0.0], (4.0, 1.74), product_of_inertia="dissertation")

    with pytest.warns(RuntimeWarning, match="central differences"):
        res = sensitivity(recon, OMEGA, C_PRIME)
    assert res.method == "central" and res.output_names[:6] == ("mass", "rx", "rz", "Izz", "Ixx", "Ixz")
    ref = jacobian(_algorithm1, XI).jacobian[:, 3:]
    scale = np.abs(ref).max(axis=1, keepdims=True)
    np.testing.assert_allclose(res.jacobian[:6] / scale, ref / scale, atol=1e-8)


def test_complex_step_matches_central_differences_on_algorithm1():
    cs = jacobian(_algorithm1, XI, method="complex")
    cd = jacobian(_algorithm1, XI, method="central")
    assert cd.method == "central"
    scale = np.abs(cs.jacobian).max(axis=1, keepdims=True)
    np.testing.assert_allclose(cd.jacobian / scale, cs.jacobian / scale, atol=1e-7)
    assert cd.error_estimate > 0


def test_jacobian_against_sympy_exact_derivative():
    x, y, z = sp.symbols("x y z")
    exprs = [sp.exp(-x * y) * sp.cos(z), x**3 / (y + z), sp.log(x + y**2) * z]
    pt = {x: 0.7, y: 1.3, z: -0.4}
    exact = np.array(sp.Matrix(exprs).jacobian([x, y, z]).subs(pt).evalf(30), dtype=float)

    def f(v):
        return [np.exp(-v[0] * v[1]) * np.cos(v[2]), v[0] ** 3 / (v[1] + v[2]), np.log(v[0] + v[1] ** 2) * v[2]]

    res = jacobian(f, [0.7, 1.3, -0.4])
    np.testing.assert_allclose(res.jacobian, exact, rtol=1e-13, atol=1e-15)
    res_c = jacobian(f, [0.7, 1.3, -0.4], method="central")
    np.testing.assert_allclose(res_c.jacobian, exact, rtol=1e-8, atol=1e-10)


def test_non_analytic_function_falls_back_to_central():
    def f(v):
        return np.abs(v) ** 2 * np.array([1.0, 2.0])

    with pytest.warns(RuntimeWarning, match="central differences"):
        res = jacobian(f, [1.5, -2.0])
    assert res.method == "central"
    np.testing.assert_allclose(res.jacobian, np.diag([3.0, -8.0]), rtol=1e-8)
    with pytest.raises(ParameterError, match="not complex-analytic"):
        jacobian(f, [1.5, -2.0], method="complex")


def test_float_casting_function_falls_back_to_central():
    def f(v):
        return {"a": float(v[0]) * 2.0, "b": float(v[1]) ** 2}

    with pytest.warns(RuntimeWarning):
        res = jacobian(f, [1.0, 3.0])
    assert res.output_names == ("a", "b")
    np.testing.assert_allclose(res.jacobian, [[2.0, 0.0], [0.0, 6.0]], rtol=1e-8)


def test_sensitivity_wrapper_against_uncoupled_closed_form():
    """Equal springs, CM at the center (report §2.4): m = 4k/w1^2, Izz = k Lx^2/w2^2, Ixx = k Lz^2/w3^2.
    Derivatives compared with the hand-differentiated closed form."""
    k, lx, lz = 740000.0, 4.0, 1.74

    def recon(w, c):
        scale = np.sum(c[:, 0]) / 4.0  # enters only to exercise the amplitude block
        return {"m": 4 * k / w[0] ** 2 * scale, "Izz": k * lx**2 / w[1] ** 2, "Ixx": k * lz**2 / w[2] ** 2}

    w = np.array([14.04754, 16.40399, 27.32779])
    c = np.ones((4, 3))
    res = sensitivity(recon, w, c)
    assert res.input_names[3] == "C'11" and res.output_names == ("m", "Izz", "Ixx")
    expected = np.zeros((3, 15))
    expected[0, 0] = -8 * k / w[0] ** 3
    expected[1, 1] = -2 * k * lx**2 / w[1] ** 3
    expected[2, 2] = -2 * k * lz**2 / w[2] ** 3
    expected[0, [3, 6, 9, 12]] = 4 * k / w[0] ** 2 / 4.0
    np.testing.assert_allclose(res.jacobian, expected, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(res.value, [15000.0, 44000.0, 3000.0], rtol=1e-4)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.floats(0.2, 5.0), min_size=3, max_size=3), st.lists(st.floats(-3.0, 3.0), min_size=3, max_size=3))
def test_elasticity_of_power_law_is_its_exponent(x, exps):
    """Property: f = prod x_j^a_j has elasticities a_j exactly (Euler's identity for homogeneous functions)."""
    a = np.array(exps)
    res = jacobian(lambda v: np.prod(v**a), x)
    np.testing.assert_allclose(res.elasticities[0], a, atol=1e-9)


def test_jacobian_bad_input():
    with pytest.raises(ParameterError, match="method"):
        jacobian(np.sin, [1.0], method="forward")
    with pytest.raises(ParameterError, match="finite"):
        jacobian(np.sin, [np.nan])
    with pytest.raises(ParameterError, match="shape"):
        sensitivity(lambda w, c: w, [1.0, 2.0], np.ones((4, 3)))


def test_error_vs_noise_end_to_end_linear_stand():
    """Belyakov Ch. III §3.2 (Fig. 20) and report §4.9 pipeline: linear 3-DOF stand (independent model from
    test_era), noise as a % of 0.00067 m, ERA then Algorithm 1.  At 1 % noise Izz and Ixx are within 0.5 %
    (report: ~0.06-0.07 %), the Izz error grows with the noise, and the thesis's "<= 2 % error up to 6 % noise"
    holds (loose)."""
    from symosc.identification import era, error_vs_noise, inertia_from_release

    from .test_era import _signals

    y, _, _ = _signals(0.02212, 1254)

    def pipe(sig, dt):
        est = era(sig, dt, 3, constant=False, hankel_size=30)
        return inertia_from_release(est.frequencies, est.mode_shapes, [0.0, -2000.0, 0.0, 0.0], (4.0, 1.74))

    truth = {"Izz": 44000.0, "Ixx": 3000.0, "mass": 15000.0}
    ev = error_vs_noise(pipe, y, 0.02212, truth, [0.01, 0.06, 0.12], reference=0.00067, runs=4, seed=5)
    assert ev.failures.sum() == 0
    assert ev.mean[0, 0] < 5e-3 and ev.mean[0, 1] < 5e-3
    assert ev.mean[0, 0] < ev.mean[1, 0] < ev.mean[2, 0]
    assert ev.threshold("Izz", 0.02) >= 0.06
    assert "ErrorVsNoise" in repr(ev)


# ------------------------------------------------------------------------------------------------- damping
def _random_system(seed, n=3):
    rng = np.random.default_rng(seed)
    a = rng.standard_normal((n, n))
    m = a @ a.T + n * np.eye(n)
    b = rng.standard_normal((n, n))
    k = b @ b.T + n * np.eye(n) * 10
    e = rng.standard_normal((n, n))
    d = e @ e.T + 0.1 * np.eye(n)
    return m, d, k


def _companion_eig(m, d, k):
    """Independent reference: eigenvalues of the first-order companion form [[0, I], [-M^-1 K, -M^-1 D]]."""
    n = m.shape[0]
    a = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(m, k), -np.linalg.solve(m, d)]])
    lam = np.linalg.eigvals(a)
    lam = lam[lam.imag > 0]
    return lam[np.argsort(np.abs(lam))]


def _oscillatory(m, d, k):
    """The roots with Im > 0 of complex_modes and their vectors (Belyakov's quadratic eigenproblem, eq. 97)."""
    modes = complex_modes(m, d, k)
    up = modes.eigenvalues.imag > 0
    return modes.eigenvalues[up], modes.vectors[:, up], modes.mode_shape_moduli[:, up]


def test_quadratic_modes_match_companion_form():
    """Belyakov (2005), Ch. III §4: the quadratic eigenproblem vs scipy eig of the companion form."""
    m, d, k = _random_system(1)
    lam, vec, _ = _oscillatory(m, 0.3 * d, k)
    np.testing.assert_allclose(np.sort_complex(lam), np.sort_complex(_companion_eig(m, 0.3 * d, k)), rtol=1e-11)
    for s, u in zip(lam, vec.T, strict=True):
        assert np.linalg.norm((s**2 * m + s * 0.3 * d + k) @ u) < 1e-10 * np.linalg.norm(k)


def test_quadratic_modes_is_a_deprecated_alias_of_complex_modes():
    from symosc import _deprecation

    m, d, k = _random_system(1)
    _deprecation.reset_warnings()
    with pytest.warns(DeprecationWarning, match="complex_modes"):
        qm = quadratic_modes(m, 0.3 * d, k)
    lam, vec, _ = _oscillatory(m, 0.3 * d, k)
    np.testing.assert_array_equal(qm.eigenvalues, lam)
    np.testing.assert_array_equal(qm.vectors, vec)


def test_proportional_damping_leaves_frequencies_and_modes():
    """Belyakov Ch. III §4 case 1 (eqs 94–98): D = beta K gives |lambda_j| = omega_j exactly and real modes."""
    m, _, k = _random_system(2)
    w2, u0 = sla.eigh(k, m)
    lam, vec, moduli = _oscillatory(m, 0.02 * k, k)
    np.testing.assert_allclose(np.abs(lam), np.sqrt(w2), rtol=1e-12)
    u0n = u0 / np.linalg.norm(u0, axis=0)
    for j in range(3):
        assert np.abs(vec[:, j].imag).max() < 1e-12
        shape = moduli[:, j]
        assert min(np.abs(shape - u0n[:, j]).max(), np.abs(shape + u0n[:, j]).max()) < 1e-12


def test_small_damping_first_order_theory_is_second_order_accurate():
    """Belyakov eqs 100–106: lambda = i omega + eps lambda1 + O(eps^2); u1 purely imaginary; |u| = |u0| + O(eps^2)."""
    m, d, k = _random_system(3)
    pert = damping_perturbation(m, d, k)
    assert np.abs(pert.u1.real).max() == 0.0
    assert np.all(pert.lambda1 < 0)
    errs_lam, errs_mod = [], []
    for eps in (1e-2, 5e-3):
        lam, u, _ = _oscillatory(m, eps * d, k)
        errs_lam.append(np.abs(lam - pert.eigenvalues(eps)).max())
        # undamped frequency |lambda| differs from omega only at O(eps^2)
        assert np.abs(np.abs(lam) - pert.frequencies).max() < 50 * eps**2
        # eigenvector normalised like u0 + eps u1: u0^T u = u0^T u0
        u = u * (np.einsum("ij,ij->j", pert.modes, pert.modes) / np.einsum("ij,ij->j", pert.modes, u))[None, :]
        errs_mod.append(np.abs(u - pert.vectors(eps)).max())
    assert errs_lam[0] / errs_lam[1] == pytest.approx(4.0, rel=0.05)
    assert errs_mod[0] / errs_mod[1] == pytest.approx(4.0, rel=0.1)


@pytest.mark.filterwarnings("ignore::DeprecationWarning")
def test_damping_bad_input():
    with pytest.raises(ModelError, match="positive definite"):
        quadratic_modes(-np.eye(2), np.eye(2), np.eye(2))
    with pytest.raises(ModelError, match="overdamped"):
        quadratic_modes(np.eye(1), 10 * np.eye(1), np.eye(1))
    with pytest.raises(ModelError, match="repeated"):
        damping_perturbation(np.eye(2), np.eye(2), np.eye(2))
    with pytest.raises(ParameterError, match="symmetric"):
        quadratic_modes(np.eye(2), [[0, 1], [0, 0]], np.eye(2))


# ------------------------------------------------------------------------------------------------- applicability
def test_applicability_criterion_belyakov_section_3_9():
    """Report §3.9/§4.4: with the 2000 N release the modal energies are 1/2 K' = (0.675, 0.719, 0.630) J, so the
    criterion min E > 1/2 mean E holds; a weak mode fails it."""
    chk = applicability(mode_shapes=C_PRIME, force=[0.0, -2000.0, 0.0, 0.0])
    np.testing.assert_allclose(chk.energies, np.array([1.3506976, 1.4385120, 1.2609348]) / 2, rtol=1e-6)
    assert chk.ok and chk.weakest_mode == 2 and chk.threshold == pytest.approx(2.0250722 / 6, rel=1e-6)
    weak = applicability([1.0, 1.0, 0.3])
    assert not weak.ok and weak.weakest_mode == 2 and weak.margin < 1
    with pytest.raises(ParameterError, match="needs energies"):
        applicability()
