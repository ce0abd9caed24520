"""FirstOrderSystem.rhs / .jacobian with the NumPy and C backends, against the textbook double-pendulum equations."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc import ModelError, ParameterError, dot
from symosc.mechanics import LagrangianSystem
from symosc.models import n_link_pendulum

VALUES = {"m1": 1.3, "m2": 0.7, "l1": 0.9, "l2": 1.4, "g": 9.81}
BACKENDS = ["numpy", "c"]


pytestmark = pytest.mark.usefixtures("private_symosc_cache")


@pytest.fixture(scope="module")
def double():
    return n_link_pendulum(2).first_order()


def closed_form(_t: float, y: np.ndarray) -> np.ndarray:
    """The double pendulum with point masses, angles from the downward vertical (e.g. Goldstein; any textbook)."""
    m1, m2, l1, l2, g = (VALUES[k] for k in ("m1", "m2", "l1", "l2", "g"))
    th1, th2, w1, w2 = y
    d = th1 - th2
    den = 2 * m1 + m2 - m2 * np.cos(2 * d)
    a1 = (
        -g * (2 * m1 + m2) * np.sin(th1)
        - m2 * g * np.sin(th1 - 2 * th2)
        - 2 * np.sin(d) * m2 * (w2**2 * l2 + w1**2 * l1 * np.cos(d))
    ) / (l1 * den)
    a2 = (2 * np.sin(d) * (w1**2 * l1 * (m1 + m2) + g * (m1 + m2) * np.cos(th1) + w2**2 * l2 * m2 * np.cos(d))) / (
        l2 * den
    )
    return np.array([w1, w2, a1, a2])


STATES = np.random.default_rng(7).uniform(-2, 2, size=(4, 6))


@pytest.mark.parametrize("backend", BACKENDS)
def test_rhs_matches_the_textbook_equations_for_single_and_batched_states(double, backend):
    f = double.rhs(VALUES, backend=backend)
    for y in STATES.T:
        np.testing.assert_allclose(f(0.0, y), closed_form(0.0, y), rtol=1e-12, atol=1e-12)
    batch = f(0.0, STATES)
    assert batch.shape == STATES.shape
    np.testing.assert_allclose(batch, np.column_stack([closed_form(0.0, y) for y in STATES.T]), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(f(0.0, np.asfortranarray(STATES[:, ::2])), batch[:, ::2], rtol=1e-15)


@pytest.mark.parametrize("backend", BACKENDS)
def test_jacobian_matches_central_differences_of_the_textbook_equations(double, backend):
    jac = double.jacobian(VALUES, backend=backend)
    h = 1e-6
    for y in STATES.T[:3]:
        fd = np.column_stack([(closed_form(0, y + h * e) - closed_form(0, y - h * e)) / (2 * h) for e in np.eye(4)])
        np.testing.assert_allclose(jac(0.0, y), fd, rtol=1e-7, atol=1e-7)


def test_vectorized_solve_ivp_with_jacobian_matches_a_tight_reference(double):
    y0 = np.array([1.2, -0.4, 0.0, 0.3])
    ref = solve_ivp(closed_form, (0, 1.5), y0, method="DOP853", rtol=1e-12, atol=1e-12)
    for backend in BACKENDS:
        f, jac = double.rhs(VALUES, backend=backend), double.jacobian(VALUES, backend=backend)
        sol = solve_ivp(f, (0, 1.5), y0, method="Radau", vectorized=True, jac=jac, rtol=1e-10, atol=1e-10)
        assert sol.success
        np.testing.assert_allclose(sol.y[:, -1], ref.y[:, -1], rtol=1e-6, atol=1e-7, err_msg=backend)


def test_stiff_chain_needs_far_fewer_rhs_calls_with_the_analytic_jacobian():
    """A chain of 4 unit masses joined by very stiff, strongly damped links (K = 1e6, c = 1e4) on a soft spring
    (k = 1): BDF without ``jac`` rebuilds the Jacobian by finite differences (2n calls each time) and, with a
    less accurate Jacobian, takes more steps; with the analytic one it needs fewer calls."""
    N = 4
    xs = sp.symbols(f"x1:{N + 1}", real=True)
    m, k, K, c = sp.symbols("m k K c", positive=True)
    T = m * sum(dot(x) ** 2 for x in xs) / 2
    V = k * xs[0] ** 2 / 2 + K * sum((xs[i + 1] - xs[i]) ** 2 for i in range(N - 1)) / 2
    R = c * sum((dot(xs[i + 1]) - dot(xs[i])) ** 2 for i in range(N - 1)) / 2
    fo = LagrangianSystem(T, V, list(xs), dissipation=R).first_order()
    values = {"m": 1.0, "k": 1.0, "K": 1e6, "c": 1e4}
    y0 = np.r_[np.linspace(1.0, 1.01, N), np.zeros(N)]
    f, jac = fo.rhs(values, backend="c"), fo.jacobian(values, backend="c")
    without = solve_ivp(f, (0, 5), y0, method="BDF", rtol=1e-8, atol=1e-10)
    with_jac = solve_ivp(f, (0, 5), y0, method="BDF", jac=jac, rtol=1e-8, atol=1e-10)
    assert without.success and with_jac.success
    assert without.nfev - with_jac.nfev >= 2 * N * without.njev  # at least the finite-difference calls are saved
    # The analytic Jacobian is the exact linear one: K, c, k enter the stiffness and damping matrices.
    Kmat = np.diag([1.0 + 1e6, 2e6, 2e6, 1e6]) - 1e6 * (np.eye(N, k=1) + np.eye(N, k=-1))
    Cmat = np.diag([1e4, 2e4, 2e4, 1e4]) - 1e4 * (np.eye(N, k=1) + np.eye(N, k=-1))
    np.testing.assert_allclose(jac(0.0, y0), np.block([[np.zeros((N, N)), np.eye(N)], [-Kmat, -Cmat]]), rtol=1e-14)
    np.testing.assert_allclose(with_jac.y[:, -1], without.y[:, -1], atol=1e-6)


def test_bad_input_is_named(double):
    f = double.rhs(VALUES, backend="c")
    with pytest.raises(ParameterError, match=r"state y must have shape \(4,\) or \(4, k\), got \(3,\)"):
        f(0.0, np.zeros(3))
    with pytest.raises(ParameterError, match="missing values for: g"):
        double.rhs({k: v for k, v in VALUES.items() if k != "g"}, backend="c")
    with pytest.raises(ParameterError, match="m2 must be finite"):
        double.rhs({**VALUES, "m2": float("nan")}, backend="c")
    with pytest.raises(ParameterError, match="backend must be"):
        double.rhs(VALUES, backend="fortran")


@pytest.mark.parametrize("backend", BACKENDS)
def test_singular_mass_matrix_raises_model_error(backend):
    q = sp.Symbol("q", real=True)
    a = sp.Symbol("a", real=True)
    fo = LagrangianSystem(a**2 * dot(q) ** 2 / 2, q**2 / 2, [q]).first_order()
    f = fo.rhs({"a": 0.0}, backend=backend)
    with pytest.raises(ModelError, match="mass matrix is singular"):
        f(0.0, np.array([0.1, 0.0]))
