"""Harmonic balance, shooting and collocation against independent references.

References: long direct integration (``scipy.integrate.solve_ivp`` at tight tolerances), the Poincaré series of
``symosc.nonlinear.limit_cycle`` (Bulgakov 1954, §5.16–5.22; Andersen & Geer 1982), brute-force Fourier
quadrature on a fine grid, and the methods against each other (harmonic balance and shooting share only the
model's symbolic equations).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc.continuation import (
    collocation,
    harmonic_balance,
    orbit_multipliers,
    shooting,
)
from symosc.errors import ConvergenceError, ModelError, ParameterError

x, v, t, w, eps, F = sp.symbols("x v t w eps F")
DUFFING = -0.1 * v - x - x**3 + F * sp.cos(w * t)
VDP = eps * (1 - x**2) * v - x


@pytest.fixture(scope="module")
def duffing_hb():
    return harmonic_balance(DUFFING, x, v, t, forcing_frequency=w, values={"F": 1.0, "w": 2.0}, harmonics=10, tol=1e-4)


@pytest.fixture(scope="module")
def vdp_hb():
    return harmonic_balance(VDP, x, v, t, autonomous=True, values={"eps": 0.1}, tol=1e-12)


def _steady_state_by_integration(w0: float) -> tuple[float, np.ndarray]:
    """Amplitude max|x| over one period after the transient of x'' + 0.1x' + x + x^3 = cos(w0 t) has died out."""
    T = 2 * np.pi / w0

    def f(tt, y):
        return [y[1], -0.1 * y[1] - y[0] - y[0] ** 3 + np.cos(w0 * tt)]

    burn = solve_ivp(f, (0, 120 * T), [0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-13)
    sol = solve_ivp(f, (120 * T, 121 * T), burn.y[:, -1], method="DOP853", rtol=1e-12, atol=1e-13, dense_output=True)
    tt = np.linspace(120 * T, 121 * T, 20001)
    xx = sol.sol(tt)[0]
    return float(np.abs(xx).max()), burn.y[:, -1]


def test_duffing_point_agrees_with_long_integration_and_shooting(duffing_hb):
    sol = duffing_hb.solve()
    assert sol.harmonics == 10 and sol.residual < 1e-10 and sol.stable
    amp_ref, y_ref = _steady_state_by_integration(2.0)
    assert sol.amplitude == pytest.approx(amp_ref, abs=1e-7)  # the reference's grid maximum limits it
    np.testing.assert_allclose(sol.initial_state, y_ref, atol=1e-9)  # the state at a multiple of the period
    sh = shooting(DUFFING, x, v, t, forcing_frequency=w, values={"F": 1.0, "w": 2.0}).solve(sol)
    np.testing.assert_allclose(sh.initial_state, sol.initial_state, atol=1e-10)


def test_exact_convolution_equals_fine_quadrature(duffing_hb):
    """The alias-free AFT residual is the Galerkin projection (checked against 4096-point quadrature)."""
    rng = np.random.default_rng(1)
    H = duffing_hb.harmonics
    c = rng.normal(size=(1, 2 * H + 1)) / np.arange(1, 2 * H + 2)
    p = duffing_hb.values.copy()
    G, J, _ = duffing_hb._evaluate(c.ravel(), p)
    assert duffing_hb.exact and duffing_hb.samples == 4 * H + 2
    N = 4096
    tau = 2 * np.pi * np.arange(N) / N
    k = np.arange(1, H + 1)
    a, b = c[0, 1::2], c[0, 2::2]
    z = c[0, 0] + np.cos(np.outer(tau, k)) @ a + np.sin(np.outer(tau, k)) @ b
    zd = np.cos(np.outer(tau, k)) @ (k * b) - np.sin(np.outer(tau, k)) @ (k * a)
    zdd = -(np.cos(np.outer(tau, k)) @ (k**2 * a) + np.sin(np.outer(tau, k)) @ (k**2 * b))
    om = p[duffing_hb.model.param_index("w")]
    r = om**2 * zdd + 0.1 * om * zd + z + z**3 - np.cos(tau)
    ref = np.concatenate(
        [
            [r.mean()],
            np.ravel(np.column_stack([2 * np.cos(np.outer(tau, k)).T @ r / N, 2 * np.sin(np.outer(tau, k)).T @ r / N])),
        ]
    )
    np.testing.assert_allclose(G, ref, atol=1e-12)
    # the Jacobian is the exact derivative of the residual (central differences agree to their own error)
    h = 1e-6
    col = (
        duffing_hb._evaluate(c.ravel() + h * np.eye(2 * H + 1)[3], p)[0]
        - duffing_hb._evaluate(c.ravel() - h * np.eye(2 * H + 1)[3], p)[0]
    ) / (2 * h)
    np.testing.assert_allclose(J[:, 3], col, atol=1e-7)


def test_hill_and_monodromy_multipliers_agree(duffing_hb):
    """Hill's method against symosc.periodic.monodromy along the same truncated orbit (H = 10), and against the
    variational equations integrated along the exact orbit for an accurate (adaptive) solution."""
    accurate = harmonic_balance(DUFFING, x, v, t, forcing_frequency=w, values={"F": 1.0}, tol=1e-11)
    for w0 in (1.2, 2.0, 3.2):
        sol = duffing_hb.solve(values={"w": w0})
        rs = np.sort_complex(orbit_multipliers(duffing_hb, sol, along="series"))
        rh = np.sort_complex(orbit_multipliers(duffing_hb, sol, method="hill", harmonics=20))
        np.testing.assert_allclose(rh, rs, atol=1e-8)
        good = accurate.solve(sol, values={"w": w0})
        rm = np.sort_complex(orbit_multipliers(accurate, good))
        np.testing.assert_allclose(np.sort_complex(good.multipliers), rm, atol=1e-8)
        # Liouville: rho1 rho2 = exp(-0.1 T)
        assert np.prod(rm).real == pytest.approx(np.exp(-0.1 * 2 * np.pi / w0), rel=1e-9)


def test_van_der_pol_against_the_poincare_series(vdp_hb):
    """HB agrees with the order-20 series to the series' truncation error; the order-2 error falls as eps^4."""
    from symosc.nonlinear import limit_cycle

    lc = limit_cycle((1 - x**2) * v, 20, x=x, v=v)
    errors2 = []
    for e in (0.05, 0.1, 0.3):
        sol = vdp_hb.solve(values={"eps": e})
        w20 = float(lc.frequency.evaluate(e))
        tail = abs(float(lc.frequency.evaluate(e)) - float(lc.frequency.evaluate(e, order=18)))
        assert abs(sol.frequency - w20) <= max(10 * tail, 1e-13)
        assert abs(sol.amplitude - float(lc.amplitude.evaluate(e))) <= 1e-10
        errors2.append(abs(sol.frequency - float(lc.frequency.evaluate(e, order=2))))
    slope = np.log(errors2[1] / errors2[0]) / np.log(2.0)
    assert slope == pytest.approx(4.0, abs=0.05)


def test_van_der_pol_collocation_and_shooting_agree_with_hb():
    e = 2.0
    hb = harmonic_balance(VDP, x, v, t, autonomous=True, values={"eps": e}, tol=1e-11).solve()
    co = collocation(VDP, x, v, t, autonomous=True, values={"eps": e}, tol=1e-5).solve(hb)
    sh = shooting(VDP, x, v, t, autonomous=True, values={"eps": e}).solve(hb)
    assert co.period == pytest.approx(hb.period, abs=1e-9)
    assert sh.period == pytest.approx(hb.period, abs=1e-9)
    assert co.amplitude == pytest.approx(hb.amplitude, abs=1e-8)
    np.testing.assert_allclose(np.sort(co.multipliers.real), np.sort(sh.multipliers.real), atol=1e-8)
    assert hb.harmonics > 10  # chosen for the tolerance, and reported


def test_lagrangian_two_degrees_of_freedom_agrees_with_shooting():
    from symosc import dot
    from symosc import t as tt
    from symosc.mechanics import LagrangianSystem

    q1, q2 = sp.symbols("q1 q2")
    k, W = sp.symbols("k W", positive=True)
    T = (dot(q1) ** 2 + dot(q2) ** 2) / 2
    V = q1**2 / 2 + q2**2 / 2 + k * (q1 - q2) ** 2 / 2 + q1**4 / 4
    system = LagrangianSystem(
        T, V, [q1, q2], dissipation=0.05 * (dot(q1) ** 2 + dot(q2) ** 2), forces=[0.2 * sp.cos(W * tt), 0]
    )
    values = {"k": 0.5, "W": 1.3}
    sol = harmonic_balance(system, forcing_frequency=W, values=values, harmonics=9).solve()
    sh = shooting(system.first_order(), forcing_frequency=W, values=values).solve(sol)
    np.testing.assert_allclose(sh.initial_state, sol.initial_state, atol=1e-9)
    assert len(sol.amplitudes) == 2 and sol.multipliers.size == 4


def test_truncation_is_reported_and_refused_when_too_coarse():
    hb = harmonic_balance(DUFFING, x, v, t, forcing_frequency=w, values={"F": 1.0, "w": 0.5}, harmonics=3, tol=1e-8)
    with pytest.raises(ConvergenceError, match="harmonics"):
        hb.solve()
    adaptive = harmonic_balance(DUFFING, x, v, t, forcing_frequency=w, values={"F": 1.0, "w": 0.5}, tol=1e-8)
    sol = adaptive.solve()
    assert sol.residual <= 1e-8 and sol.harmonics > 3


def test_arguments_are_checked():
    with pytest.raises(ParameterError, match="forcing_frequency"):
        harmonic_balance(DUFFING, x, v, t)
    with pytest.raises(ModelError, match="autonomous"):
        harmonic_balance(DUFFING, x, v, t, autonomous=True)
    with pytest.raises(ParameterError, match="harmonics"):
        harmonic_balance(DUFFING, x, v, t, forcing_frequency=w, harmonics=0)
    with pytest.raises(ParameterError, match="tol"):
        harmonic_balance(DUFFING, x, v, t, forcing_frequency=w, tol=-1.0)
    with pytest.raises(ParameterError, match="values"):
        harmonic_balance(DUFFING, x, v, t, forcing_frequency=w, values={"G": 1.0})
    with pytest.raises(ParameterError, match="x and v"):
        harmonic_balance(DUFFING, forcing_frequency=w)


def test_constructors_and_with_values_refuse_nonsense(duffing_hb, vdp_hb):
    """The problem classes check their arguments (each error names the argument); with_values checks its values."""
    from symosc.continuation import Collocation, HarmonicBalance, Shooting

    model, p = duffing_hb.model, duffing_hb.values
    cases = [
        (lambda: HarmonicBalance("x'' = -x", p, 5, False, 1e-8), "model"),
        (lambda: HarmonicBalance(model, p[:1], 5, False, 1e-8), "values"),
        (lambda: HarmonicBalance(model, [np.inf, 1.0], 5, False, 1e-8), "values"),
        (lambda: HarmonicBalance(model, p, 0, False, 1e-8), "harmonics"),
        (lambda: HarmonicBalance(model, p, 5, "yes", 1e-8), "adaptive"),
        (lambda: HarmonicBalance(model, p, 5, False, -1.0), "tol"),
        (lambda: HarmonicBalance(model, p, 5, False, 1e-8, period_multiple=0), "period_multiple"),
        (lambda: HarmonicBalance(vdp_hb.model, vdp_hb.values, 5, False, 1e-8, period_multiple=2), "period_multiple"),
        (lambda: Shooting(model, p, 0.0, "DOP853"), "rtol"),
        (lambda: Shooting(model, p, 1e-9, "Euler"), "integrator"),
        (lambda: Collocation(model, p, [0.0, 0.5, 0.4, 1.0], 4, 1e-6), "mesh"),
        (lambda: Collocation(model, p, np.linspace(0.0, 2.0, 5), 4, 1e-6), "mesh"),
        (lambda: Collocation(model, p, np.linspace(0.0, 1.0, 5), 11, 1e-6), "degree"),
        (lambda: duffing_hb.with_values({"G": 1.0}), "G"),
        (lambda: duffing_hb.with_values({"F": float("nan")}), "F"),
        (lambda: duffing_hb.with_values([("F", 1.0)]), "values"),
        (lambda: duffing_hb.solve(frequency=-1.0), "frequency"),
    ]
    for build, name in cases:
        with pytest.raises(ParameterError, match=name):
            build()
    changed = duffing_hb.with_values({F: 0.5})
    assert changed.values[model.param_index("F")] == 0.5 and changed.values[model.param_index("w")] == 2.0
    assert changed.harmonics == duffing_hb.harmonics and duffing_hb.values[model.param_index("F")] == 1.0
