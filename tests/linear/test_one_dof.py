"""One degree of freedom (Bulgakov (1954), §4.8–4.11): closed forms against numerical integration and quadrature."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

from symosc.errors import ParameterError
from symosc.linear import classify_equilibrium, linear_filter, stability_coefficients


def _integrate(k0, k1, k2, y0, v0, force, t):
    sol = solve_ivp(
        lambda s, z: [z[1], (force - k1 * z[1] - k2 * z[0]) / k0],
        (0, t[-1]),
        [y0, v0],
        t_eval=t,
        rtol=1e-12,
        atol=1e-14,
        method="DOP853",
    )
    return sol.y[0]


@pytest.mark.parametrize("k1", [0.4, 2.0, 2.0 + 1e-9, 2.0 - 1e-9, 5.0])
def test_filter_functions_vs_ode(k1):
    """M, N, A (4.62)–(4.72) across under-, critical and over-damping, incl. 1e-9 from critical."""
    k0, k2 = 1.0, 1.0
    t = np.linspace(0, 8, 41)
    f = linear_filter(k0, k1, k2, y0=0.3, v0=-0.7)
    assert np.allclose(f.M(t), _integrate(k0, k1, k2, 0.3, -0.7, 0.0, t), atol=1e-10)
    assert np.allclose(f.N(t), _integrate(k0, k1, k2, 0.0, 1 / k0, 0.0, t), atol=1e-10)
    assert np.allclose(f.A(t), _integrate(k0, k1, k2, 0.0, 0.0, 1.0, t), atol=1e-10)


def test_item15_quadratic_integrals_by_quadrature():
    """§4.10 with k0 = 1.3, k1 = 0.7, k2 = 2.1, θ = (0.8, 0.5): ∫|N| = 1.452266, γ1 integral 0.546834, γ0 integral
    1.626190, each against scipy quadrature of the ODE solution."""
    k0, k1, k2, th = 1.3, 0.7, 2.1, (0.8, 0.5)
    c = stability_coefficients(k0, k1, k2, theta=th)
    imp = linear_filter(k0, k1, k2, v0=1 / k0)
    T = 80.0
    t = np.linspace(0, T, 200001)
    y = imp.M(t)
    assert abs(np.trapezoid(np.abs(y), t) - 1 / c.beta) < 1e-6
    sol = solve_ivp(
        lambda s, z: [z[1], (-k1 * z[1] - k2 * z[0]) / k0],
        (0, T),
        [0, 1 / k0],
        dense_output=True,
        rtol=1e-12,
        atol=1e-14,
    )
    I1 = quad(lambda s: th[0] * sol.sol(s)[0] ** 2 + th[1] * sol.sol(s)[1] ** 2, 0, T, limit=400)[0]
    assert abs(I1 - 1 / c.gamma1) < 1e-8
    sol0 = solve_ivp(
        lambda s, z: [z[1], (-k1 * z[1] - k2 * z[0]) / k0], (0, T), [1, 0], dense_output=True, rtol=1e-12, atol=1e-14
    )
    I0 = quad(lambda s: th[0] * sol0.sol(s)[0] ** 2 + th[1] * sol0.sol(s)[1] ** 2, 0, T, limit=400)[0]
    assert abs(I0 - 1 / c.gamma0) < 1e-8
    assert (round(1 / c.beta, 6), round(1 / c.gamma1, 6), round(1 / c.gamma0, 6)) == (1.452266, 0.546834, 1.62619)


def test_alpha_and_vartheta_against_roots_and_sweep():
    for k1 in (0.5, 1.9, 3.0):
        c = stability_coefficients(1.0, k1, 1.0)
        assert abs(c.alpha - (-np.roots([1.0, k1, 1.0]).real.max())) < 1e-12
        nu = np.linspace(0, 3, 300001)
        assert abs(c.vartheta - np.abs(1.0 - nu**2 + 1j * k1 * nu).min()) < 1e-6


def test_optimum_rules():
    """§4.12: α is maximal at k1 = 2√(k0 k2); γ0 (θ = (1, 0)) at k1 = √(k0 k2) with γ0 = √(k2/k0)... per unit θ1."""
    k0, k2 = 2.0, 3.0
    k1s = np.linspace(0.1, 10, 99001)
    alphas = [stability_coefficients(k0, k, k2).alpha for k in k1s[::100]]
    assert abs(k1s[::100][int(np.argmax(alphas))] - 2 * np.sqrt(k0 * k2)) < 0.02
    g0 = [stability_coefficients(k0, k, k2).gamma0 for k in k1s[::100]]
    assert abs(k1s[::100][int(np.argmax(g0))] - np.sqrt(k0 * k2)) < 0.02


def test_classification_and_errors():
    assert classify_equilibrium(1, 3, 1) == "stable node"
    assert classify_equilibrium(1, -0.5, 4) == "unstable focus"
    with pytest.raises(ParameterError, match="mass"):
        linear_filter(0, 1, 1)
    with pytest.raises(ParameterError, match="k1 > 0"):
        stability_coefficients(1, 0, 1)


@pytest.mark.parametrize("omega", [0.7, 2.3])
def test_periodic_forced_response_is_periodic_solution(omega):
    """§4.11c: starting the ODE from (y1(0), y1'(0)) returns to it after one period τ, and y1 matches the ODE
    solution along the period (sawtooth force, a non-smooth periodic input)."""
    from symosc.linear import periodic_forced_response

    tau, k0 = 2.0, 1.5

    def force(u):
        return (u % tau) - tau / 2

    h = 1e-3  # one-sided third-order difference inside the period (the force jumps at t = τ)
    y0, y1, y2, y3 = periodic_forced_response(force, tau, k0, omega, [0.0, h, 2 * h, 3 * h])
    v0 = (-11 * y0 + 18 * y1 - 9 * y2 + 2 * y3) / (6 * h)
    ts = np.linspace(0, tau, 9)
    sol = solve_ivp(
        lambda s, z: [z[1], force(s) / k0 - omega**2 * z[0]],
        (0, tau),
        [y0, v0],
        t_eval=ts,
        rtol=1e-11,
        atol=1e-13,
        max_step=0.01,
    )
    assert np.allclose(sol.y[0], periodic_forced_response(force, tau, k0, omega, ts), atol=1e-7)
    assert abs(sol.y[0][-1] - y0) < 1e-7
    with pytest.raises(ParameterError, match="resonance"):
        periodic_forced_response(force, tau, k0, np.pi, [0.0])


def test_volterra_march_first_order_against_ode():
    """§4.4 (4.40): q'' + q = -0.3 q³ reduced with the rotation Θ(t)Θ⁻¹(τ); the left-rectangle march converges
    at first order to the solve_ivp solution (error ratio ≈ 2 when the step halves)."""
    from symosc.linear import volterra_march

    eps, x0 = 0.3, np.array([1.0, 0.0])

    def rot(s):
        return np.array([[np.cos(s), np.sin(s)], [-np.sin(s), np.cos(s)]])

    def g(s):
        return rot(s) @ x0

    def kernel(s, u, x):
        return rot(s - u) @ np.array([0.0, -eps * x[0] ** 3])

    T = 2.0
    ref = solve_ivp(lambda s, z: [z[1], -z[0] - eps * z[0] ** 3], (0, T), x0, rtol=1e-12, atol=1e-14).y[:, -1]
    errs = [np.abs(volterra_march(g, kernel, np.linspace(0, T, n))[-1] - ref).max() for n in (101, 201)]
    assert errs[1] < errs[0] and 1.6 < errs[0] / errs[1] < 2.5
