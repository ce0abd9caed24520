"""High-frequency forcing: Bulgakov's appendix (1940) and Kapitza's pendulum (seed-bulgakov-part3b.md §2.9, T19).

The averaged results are checked against Floquet theory computed here directly with SciPy (monodromy of the
linearized Mathieu-type equation) and against direct integration of the full equations.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc.errors import ModelError, ParameterError
from symosc.nonlinear.averaging.high_frequency import fast_averaged_system, vibrational_averaging
from symosc.symbols import dot, t

th = sp.Symbol("theta")
m, g, l, a, p = sp.symbols("m g l a p", positive=True)


@pytest.fixture(scope="module")
def kapitza():
    """Pendulum on a vertically vibrating pivot y = a cos(p t); theta from the downward vertical."""
    return vibrational_averaging(
        th, m * l**2, -m * g * l * sp.cos(th), m * l * a * p**2 * sp.sin(th) * sp.cos(p * t), p
    )


def test_kapitza_condition_recovered_symbolically(kapitza):
    """Appendix §2.9 [D]: V_eff = -m g l cos(theta) + m a^2 p^2 sin^2(theta)/4; inverted position stable iff
    a^2 p^2 > 2 g l; slow frequency Omega^2 = a^2 p^2/(2 l^2) - g/l."""
    assert (
        sp.simplify(kapitza.effective_potential - (-m * g * l * sp.cos(th) + m * a**2 * p**2 * sp.sin(th) ** 2 / 4))
        == 0
    )
    cond = kapitza.stability_condition({th: sp.pi})
    assert sp.simplify(cond - m * (a**2 * p**2 - 2 * g * l) / 2) == 0
    omega2 = sp.simplify(kapitza.stiffness({th: sp.pi})[0, 0] / (m * l**2))
    assert sp.simplify(omega2 - (a**2 * p**2 / (2 * l**2) - g / l)) == 0
    # hanging position: always stable, stiffened
    assert sp.simplify(kapitza.stability_condition({th: 0}) - m * (a**2 * p**2 + 2 * g * l) / 2) == 0


def _monodromy(delta, eps_, period):
    """Monodromy of phi'' + (delta + eps cos(2 pi t/period)) phi = 0 over one period (SciPy DOP853)."""
    w = 2 * math.pi / period

    def rhs(tt, y):
        c = delta + eps_ * math.cos(w * tt)
        return [y[2], y[3], -c * y[0], -c * y[1]]

    sol = solve_ivp(rhs, (0, period), [1, 0, 0, 1], method="DOP853", rtol=1e-12, atol=1e-14)
    return sol.y[:, -1].reshape(2, 2)  # rows (phi, phi') x columns (two solutions)


@pytest.mark.parametrize("ratio, stable", [(0.8, False), (0.9, False), (1.12, True), (1.5, True), (3.0, True)])
def test_kapitza_threshold_vs_floquet(ratio, stable):
    """Linearized about theta = pi: phi'' + (-g/l + (a p^2/l) cos p t) phi = 0.  With a/l = 0.01 the Floquet
    multipliers are on the unit circle exactly when a^2 p^2 > 2 g l (points >= 10 % from the threshold)."""
    gv, lv, av = 9.81, 1.0, 0.01
    pv = math.sqrt(ratio * 2 * gv * lv) / av
    M = _monodromy(-gv / lv, av * pv**2 / lv, 2 * math.pi / pv)
    assert abs(np.linalg.det(M) - 1) < 1e-8  # Liouville
    assert (abs(np.trace(M)) < 2) == stable


def test_kapitza_slow_frequency_vs_floquet(kapitza):
    """The slow frequency from V_eff equals the Floquet exponent (a/l = 0.001, p ~ 6300 rad/s: extreme frequency)."""
    gv, lv, av = 9.81, 1.0, 1e-3
    pv = math.sqrt(2 * 2 * gv * lv) / av  # a^2 p^2 = 4 g l
    om2 = float(kapitza.stiffness({th: sp.pi})[0, 0].subs({m: 1, l: lv, a: av, p: pv, g: gv}))
    T = 2 * math.pi / pv
    M = _monodromy(-gv / lv, av * pv**2 / lv, T)
    rho = np.linalg.eigvals(M)
    omega_floquet = abs(np.angle(rho[0])) / T
    assert omega_floquet == pytest.approx(math.sqrt(om2), rel=2e-3)


def test_kapitza_full_nonlinear_simulation():
    """Report §2.9 check: g = 9.81, l = 1; a = 0.05, p = 200 (ratio 5.1) stays within 0.1 rad of pi for 20 s;
    a = 0.05, p = 80 (ratio 0.82) falls over."""

    def run(av, pv, T):
        rhs = lambda tt, y: [y[1], -9.81 * math.sin(y[0]) + av * pv**2 * math.cos(pv * tt) * math.sin(y[0])]  # noqa: E731
        sol = solve_ivp(rhs, (0, T), [math.pi + 0.05, 0], method="DOP853", rtol=1e-9, atol=1e-11, max_step=0.2 / pv)
        return np.max(np.abs(sol.y[0] - math.pi))

    assert run(0.05, 200, 20.0) < 0.1
    assert run(0.05, 80, 5.0) > 1.0


def test_two_dof_effective_potential_formula():
    """V_eff - V = sum_m (Phi_m^T M^-1 Phi_m + Psi_m^T M^-1 Psi_m)/(4 m^2 p^2) for a 2-DOF system with a cos(p t)
    force on q1 and a sin(2 p t) force on q2 (closed form of the averaging, report §2.9)."""
    q1, q2, k = sp.symbols("q1 q2 k")
    M = sp.Matrix([[1, 0], [0, 2]])
    V = (q1**2 + q2**2) / 2 + k * (q1 - q2) ** 2 / 2
    res = vibrational_averaging([q1, q2], M, V, [a * p**2 * q1 * sp.cos(p * t), a * p**2 * q2 * sp.sin(2 * p * t)], p)
    expected = (a * p**2 * q1) ** 2 / (4 * p**2) + (a * p**2 * q2) ** 2 / 2 / (4 * 4 * p**2)
    assert sp.simplify(res.correction - expected) == 0


def test_damped_slow_force_keeps_damping(kapitza):
    """Linear damping averages to itself: M Q'' = -grad V_eff - c Q'."""
    c = sp.Symbol("c", positive=True)
    res = vibrational_averaging(
        th, m * l**2, -m * g * l * sp.cos(th), m * l * a * p**2 * sp.sin(th) * sp.cos(p * t), p, force=-c * dot(th)
    )
    assert sp.simplify(res.slow_force[0] - (-sp.diff(kapitza.effective_potential, th) - c * dot(th))) == 0


def test_fast_averaging_error_orders():
    """Appendix §4–5: the first-order shortened solution has error O(mu), the second-order one (with the oscillating
    part (62)) O(mu^2), mu = 1/nu; measured against direct integration at nu = 20, 40, 80."""
    x1, x2, nu = sp.symbols("x1 x2 nu")
    rhs = [-x1 + x2 * sp.cos(nu * t) + x2**2 * sp.sin(nu * t), -x2 + x1 * sp.sin(nu * t) + sp.cos(2 * nu * t)]
    s1 = fast_averaged_system(rhs, [x1, x2], nu, order=1)
    s2 = fast_averaged_system(rhs, [x1, x2], nu, order=2)
    tt = np.linspace(0, 3, 61)
    x0 = [1.0, 0.5]
    errs1, errs2 = [], []
    for nv in (20.0, 40.0, 80.0):
        f = sp.lambdify((t, x1, x2), [e.subs(nu, nv) for e in rhs])
        ref = solve_ivp(
            lambda tt_, y, f=f: f(tt_, *y), (0, 3), x0, t_eval=tt, rtol=1e-11, atol=1e-13, method="DOP853"
        ).y
        errs1.append(np.max(np.abs(s1.solve(x0, tt, {nu: nv}) - ref)))
        errs2.append(np.max(np.abs(s2.solve(x0, tt, {nu: nv}) - ref)))
    slope1 = np.log2(errs1[0] / errs1[2]) / 2
    slope2 = np.log2(errs2[0] / errs2[2]) / 2
    assert 0.8 < slope1 < 1.3
    assert 1.7 < slope2 < 2.4
    assert errs2[-1] < errs1[-1] / 10


def test_fast_averaged_symbolic_correction():
    """F2 = sum_m (1/2m)[(d phi_m/dx) f_m - (d f_m/dx) phi_m], computed by hand for a linear example."""
    x1, x2, nu = sp.symbols("x1 x2 nu")
    s = fast_averaged_system([x2 * sp.cos(nu * t), x1 * sp.sin(nu * t)], [x1, x2], nu, order=2)
    # f_1 = (x2, 0), phi_1 = (0, x1): (d phi/dx) f = (0, x2), (d f/dx) phi = (x1, 0)
    assert list(s.correction) == [-x1 / 2, x2 / 2]
    assert list(s.mean) == [0, 0]
    assert "order=2" in repr(s)


def test_bad_inputs():
    with pytest.raises(ModelError, match="nonzero mean"):
        vibrational_averaging(th, 1, -sp.cos(th), sp.sin(th) * sp.cos(p * t) ** 2, p)
    q1, q2 = sp.symbols("q1 q2")
    with pytest.raises(ModelError, match="one degree of freedom only"):
        vibrational_averaging([q1, q2], sp.diag(1 + q2**2, 1), 0, [sp.cos(p * t), 0], p)
    with pytest.raises(ModelError, match="must not depend on t"):
        vibrational_averaging(th, 1 + sp.cos(t), -sp.cos(th), sp.sin(th) * sp.cos(p * t), p)
    with pytest.raises(ModelError, match="cos\\(k\\*nu\\*t\\)"):
        vibrational_averaging(th, 1, -sp.cos(th), sp.sin(th) * sp.cos(sp.sqrt(2) * t), p)
    x1 = sp.Symbol("x1")
    with pytest.raises(ParameterError, match="order"):
        fast_averaged_system([x1], [x1], p, order=3)
    with pytest.raises(ModelError, match="right-hand sides"):
        fast_averaged_system([x1, x1], [x1], p)
    s = fast_averaged_system([x1 * sp.cos(p * t) + sp.Symbol("k")], [x1], p)
    with pytest.raises(ParameterError, match="missing values for"):
        s.solve([1.0], [0, 1], {p: 10})


def test_vibrational_averaging_of_model_single_link():
    """The lead's n_link_pendulum(1, inverted=True, pivot="vertical") through vibrational_averaging_of: the same
    Kapitza condition (angle from the upward vertical, so the inverted position is phi1 = 0)."""
    from symosc.models import n_link_pendulum
    from symosc.nonlinear.averaging.high_frequency import vibrational_averaging_of

    res = vibrational_averaging_of(n_link_pendulum(1, inverted=True, pivot="vertical"))
    (phi1,) = res.coordinates
    syms = {s.name: s for s in res.effective_potential.free_symbols}
    a_, p_, g_, l1, m1 = (syms[k] for k in ("a", "p", "g", "l1", "m1"))
    assert sp.simplify(res.stability_condition({phi1: 0}) - m1 * (a_**2 * p_**2 - 2 * g_ * l1) / 2) == 0
    assert sp.simplify(res.correction - m1 * a_**2 * p_**2 * sp.sin(phi1) ** 2 / 4) == 0


def _floquet_stable(M, K0, K1, p):
    """|rho| <= 1 for all multipliers of M q'' + (K0 + K1 cos p t) q = 0 (SciPy, one period)."""
    n = M.shape[0]
    Minv = np.linalg.inv(M)

    def rhs(tt, y):
        Y = y.reshape(2 * n, 2 * n)
        A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ (K0 + K1 * math.cos(p * tt)), np.zeros((n, n))]])
        return (A @ Y).ravel()

    sol = solve_ivp(rhs, (0, 2 * math.pi / p), np.eye(2 * n).ravel(), method="DOP853", rtol=1e-11, atol=1e-13)
    rho = np.linalg.eigvals(sol.y[:, -1].reshape(2 * n, 2 * n))
    return bool(np.max(np.abs(rho)) < 1 + 1e-6)


def test_two_link_inverted_pendulum_vs_floquet():
    """Double inverted pendulum on a vibrating pivot: the averaged stiffness K0 + K1 M^-1 K1/(2 p^2) is positive
    definite exactly where the Floquet multipliers of the linearized system stay on the unit circle (a/l = 0.01,
    p at 0.85 and 1.2 times the averaged threshold)."""
    from symosc.models import n_link_pendulum
    from symosc.nonlinear.averaging.high_frequency import vibrational_stiffness

    lin = n_link_pendulum(2, inverted=True, pivot="vertical").linearize()
    K = vibrational_stiffness(lin)
    names = {"m1": 1.0, "m2": 1.0, "l1": 1.0, "l2": 1.0, "g": 9.81, "a": 0.01}
    syms = K.free_symbols | lin.M.free_symbols
    vals = {s: names[s.name] for s in syms if s.name in names}
    Kp = K.subs(vals)
    (psym,) = Kp.free_symbols
    from scipy.optimize import brentq

    def min_eig(pv):
        return float(min(np.linalg.eigvalsh(np.array(Kp.subs(psym, pv), dtype=float))))

    p_star = brentq(min_eig, 10.0, 1e4)
    M0 = np.array(lin.M.subs(vals), dtype=float)
    K0s, K1s, _p = lin.periodic_stiffness()
    K00 = np.array(K0s.subs(vals), dtype=float)
    for factor, stable in ((0.85, False), (1.2, True)):
        pv = factor * p_star
        K10 = np.array(K1s.subs(vals).subs(_p, pv), dtype=float)
        assert (min_eig(pv) > 0) == stable
        assert _floquet_stable(M0, K00, K10, pv) == stable


@pytest.mark.parametrize("ratio, stable", [(0.9, False), (1.12, True)])
def test_kapitza_threshold_vs_symosc_periodic_floquet(kapitza, ratio, stable):
    """Cross-check with the periodic-systems package: symosc.periodic.floquet.monodromy of the linearized equation
    about theta = pi agrees with the sign of V_eff''(pi) (10 % on either side of a^2 p^2 = 2 g l)."""
    from symosc.periodic.floquet import monodromy

    vals = {"g": 9.81, "l": 1.0, "a": 0.01}
    pv = math.sqrt(ratio * 2 * 9.81) / 0.01
    A = sp.Matrix([[0, 1], [g / l - a * p**2 / l * sp.cos(p * t), 0]])
    res = monodromy(A, 2 * math.pi / pv, values={**vals, "p": pv})
    assert (res.stability == "stable") == stable
    cond = float(kapitza.stability_condition({th: sp.pi}).subs({m: 1, g: 9.81, l: 1.0, a: 0.01, p: pv}))
    assert (cond > 0) == stable
