"""Minimum excitation time under bounded control (Belyakov 2005, seed 001, Ch. II §4; report §3.6 and §4.8)."""

import itertools

import numpy as np
import pytest
import scipy.integrate

from symosc.errors import ModelError, ParameterError
from symosc.identification.min_time import (
    excitation_time,
    excitation_time_bound,
    min_time_1dof,
    quasi_optimal_control,
    simulate_quasi_optimal,
    sine_forcing_time,
    switching_curves,
)


def _stand():
    lx, lz, k = 4.0, 1.74, 7.4e5
    C = np.array([[1, -lx / 2, lz / 2], [1, lx / 2, lz / 2], [1, lx / 2, -lz / 2], [1, -lx / 2, -lz / 2]])
    return np.diag([15000.0, 44000.0, 3000.0]), k * C.T @ C, C.T, lx, lz, k


def test_stand_example_ch2_4_5():
    """Ch. II §4.5 (report §4.8): 33.0987 s, 14.1720 s, 8.50701 s for ±5 N actuators and 2 mm amplitudes.

    Checked against the closed forms T1 = (pi a/4U) sqrt(mk), T2 = (pi a/4U) sqrt(Izz k)/Lx,
    T3 = (pi a/4U) sqrt(Ixx k)/Lz (the printed 33 / 14 / 8.5 s need the pi lost by the OCR).
    """
    M, K, B, lx, lz, k = _stand()
    am, U = 2e-3, 5.0
    res = excitation_time_bound(M, K, B, U, [am, am / lx, am / lz])
    c = np.pi * am / (4 * U)
    closed = [c * np.sqrt(15000 * k), c * np.sqrt(44000 * k) / lx, c * np.sqrt(3000 * k) / lz]
    np.testing.assert_allclose(res.times, closed, rtol=1e-12)
    np.testing.assert_allclose(res.times, [33.0987, 14.1720, 8.50701], rtol=3e-6)
    assert res.bound == pytest.approx(33.0987, rel=2e-6)
    np.testing.assert_allclose(res.omega, [2 * np.sqrt(k / 15000), lx * np.sqrt(k / 44000), lz * np.sqrt(k / 3000)])
    # the same with the mass normalisation: amplitudes of z = sqrt(m_i) q_i
    res_mass = excitation_time_bound(M, K, B, U, np.sqrt([15000, 44000, 3000]) * [am, am / lx, am / lz],
                                     normalization="mass")  # fmt: skip
    np.testing.assert_allclose(res_mass.times, res.times, rtol=1e-12)
    # the vertical mode alone is the 1-DOF formula (76) with u_bar = 4 U acting on m
    assert excitation_time(am, res.omega[0], 4 * U, 15000) == pytest.approx(res.times[0], rel=1e-12)


def test_sine_vs_bang_bang_ratio():
    """Resonant sine forcing is 4/pi = 1.27324 times slower (eq. 78); checked by integrating the sine-forced ODE."""
    a, w, u, m = 0.3, 2.0, 0.5, 1.5
    assert sine_forcing_time(a, w, u, m) / excitation_time(a, w, u, m) == pytest.approx(4 / np.pi, rel=1e-14)

    def amp(t, y):
        return np.hypot(y[0], y[1] / w) - a

    amp.terminal = True
    sol = scipy.integrate.solve_ivp(
        lambda t, y: [y[1], -(w**2) * y[0] + u / m * np.sin(w * t)], (0, 100), [0, 0], events=amp,
        rtol=1e-10, atol=1e-12, max_step=0.05,
    )  # fmt: skip
    # amplitude envelope u t/(2 m w) reaches a at 2 a m w / u (up to one oscillation)
    assert sol.t_events[0][0] == pytest.approx(sine_forcing_time(a, w, u, m), abs=np.pi / w)


def _first_hits(x0, phases, a, u_m, w, t_max, inside=True):
    """Independent brute force: controls u_m sign(sin(w t + phase)), exact arcs on a fine time grid (all phases)."""
    x = np.tile(np.asarray(x0, float), (len(phases), 1))
    hit = np.full(len(phases), np.inf)
    dt = 2e-3 / w
    c, s = np.cos(w * dt), np.sin(w * dt)
    for n in range(int(t_max / dt) + 1):
        t = (n + 1) * dt
        u = np.where(np.sin(w * (t - dt / 2) + phases) >= 0, u_m, -u_m)
        d0, d1 = x[:, 0] - u, x[:, 1]
        x = np.column_stack([u + d0 * c + d1 * s, -d0 * s + d1 * c])
        r = np.hypot(x[:, 0], x[:, 1])
        new = (r >= a) if inside else (r <= a)
        hit = np.where(new & np.isinf(hit), t, hit)
    return hit


@pytest.mark.parametrize(("x0", "a"), [((0.3, -0.5), 2.3), ((0.0, 0.0), 1.5), ((3.0, 1.0), 1.5)])
def test_min_time_is_minimal(x0, a):
    """The support-function minimum time equals the best of all bang-bang controls with half-period switches.

    By the maximum principle (eqs 63–68) optimal controls are u_m sign(sin(w t + phase)); a brute-force scan over
    the phase must not beat the computed time, and the best phase must match it.
    """
    u_m, w = 0.4, 2.0
    res = min_time_1dof(x0, a, u_m, w)
    inside = np.hypot(*x0) < a
    hits = _first_hits(x0, np.linspace(0, 2 * np.pi, 180, endpoint=False), a, u_m, w, res.time + 1, inside)
    assert min(hits) >= res.time - 2e-3 / w
    assert min(hits) == pytest.approx(res.time, abs=0.03)
    # the returned open-loop control, integrated independently, lands on the circle at res.time
    edges = np.concatenate([[0.0], res.switching_times, [res.time]])
    y = np.array([x0[0], x0[1] * w])  # (x1, x1')
    for t0, t1 in itertools.pairwise(edges):
        u = float(res.control(0.5 * (t0 + t1)))
        sol = scipy.integrate.solve_ivp(lambda t, s, u=u: [s[1], -(w**2) * (s[0] - u)], (t0, t1), y, rtol=1e-12,
                                        atol=1e-14)  # fmt: skip
        y = sol.y[:, -1]
    assert np.hypot(y[0], y[1] / w) == pytest.approx(a, abs=1e-8)


def test_min_time_small_targets_closed_form():
    """Cases a < u_m and a = u_m from rest (Figs 14–15): one arc about (u_m, 0), |x| = 2 u_m sin(w t / 2)."""
    u_m, w = 1.0, 3.0
    for a in (0.3, 1.0, 1.9):
        expected = 2 / w * np.arcsin(a / (2 * u_m))
        res = min_time_1dof((0.0, 0.0), a, u_m, w)
        assert res.time == pytest.approx(expected, abs=1e-9)
        assert res.switching_times.size == 0


def test_quasi_optimal_from_rest():
    """Quasi-optimal law from rest reaches amplitude a in about pi a / (2 w u_m) (eq. 76), here exactly a/(4u_m)
    periods; integrated independently with solve_ivp on the discontinuous feedback."""
    a, u_m, w = 2.4, 0.1, 1.5
    run = simulate_quasi_optimal((0.0, 0.0), a, u_m, w)
    # the last arc touches the circle tangentially, so the hit is located to about sqrt(machine eps)
    assert run.time == pytest.approx(np.pi * a / (2 * w * u_m), rel=1e-7)

    def rhs(t, x):
        u = float(quasi_optimal_control(x[0], x[1], a, u_m))
        return [w * x[1], -w * x[0] + w * u]

    def reach(t, x):
        return np.hypot(*x) - a * (1 - 1e-9)

    reach.terminal = True
    sol = scipy.integrate.solve_ivp(rhs, (0, 2 * run.time), [0.0, 0.0], events=reach, max_step=0.01, rtol=1e-10)
    assert sol.t_events[0][0] == pytest.approx(run.time, rel=2e-3)
    opt = min_time_1dof((0.0, 0.0), a, u_m, w)
    # from rest with a a multiple of 2 u_m the quasi-optimal law is optimal (the optimum is a double root of the
    # reachability gap, so it is located to about sqrt(machine eps))
    assert opt.time == pytest.approx(run.time, rel=1e-7)


@pytest.mark.parametrize(("x0", "a"), [((0.05, 0.02), 1.3), ((-0.2, 0.4), 2.0), ((3.0, -1.0), 1.0), ((0, 5.0), 4.2)])
def test_quasi_optimal_within_half_period(x0, a):
    """T_quasi - T_opt is in [0, pi/w] (report §3.6: quasi-optimal = optimal + O(u_m/a)/w), inside and outside."""
    u_m, w = 0.1, 2.0
    opt = min_time_1dof(x0, a, u_m, w)
    quasi = simulate_quasi_optimal(x0, a, u_m, w)
    assert opt.time * (1 - 1e-7) <= quasi.time <= opt.time + np.pi / w
    assert opt.inside == (np.hypot(*x0) < a)


def test_multi_dof_bound_coupled_matches_modal_simulation():
    """For a coupled 2-DOF system the bound is the exact bang-bang time of each normal coordinate (eq. 82–84)."""
    M = np.array([[2.0, 0.3], [0.3, 1.0]])
    K = np.array([[5.0, -1.0], [-1.0, 3.0]])
    B = np.array([[1.0, 0.0], [0.5, 1.0]])
    U = np.array([0.2, 0.1])
    res = excitation_time_bound(M, K, B, U, [1.0, 2.0], normalization="mass")
    lam, phi = np.linalg.eig(np.linalg.solve(M, K))
    order = np.argsort(lam)
    lam, phi = lam[order], phi[:, order]
    phi = phi / np.sqrt(np.einsum("ij,jk,ki->i", phi.T, M, phi))
    b = np.abs(phi.T @ B) @ U
    np.testing.assert_allclose(res.times, np.pi * np.array([1.0, 2.0]) * np.sqrt(lam) / (2 * b), rtol=1e-10)
    # each normal coordinate driven by its bound b_i from rest: formula (76) is exact up to one half period, and the
    # rigorous bound uses the exact 1-DOF minimum time (never above the formula)
    for i in range(2):
        w = np.sqrt(lam[i])
        run = simulate_quasi_optimal((0.0, 0.0), [1.0, 2.0][i], b[i] / w**2, w)
        assert res.times[i] - np.pi / w <= run.time <= res.times[i] + 1e-9
        assert res.exact_times[i] == pytest.approx(min_time_1dof((0, 0), [1.0, 2.0][i], b[i] / w**2, w).time)
        assert res.exact_times[i] <= res.times[i] * (1 + 1e-9)
    assert res.exact_bound == pytest.approx(res.exact_times.max())


@pytest.mark.parametrize(("a", "inside"), [(3.0, True), (0.5, True), (1.0, True), (0.5, False)])
def test_switching_curves_are_optimal(a, inside):
    """Switching curves (Figs 14–17): from a point of the first curve the exact minimum time equals the backward
    time of the extremal through it (the last switch comes after the angle pi - (phi mod pi), eq. 74)."""
    u_m, w, n = 1.0, 2.0, 12
    curves = switching_curves(a, u_m, w, n_switches=2, inside=inside, points=n, optimal_only=True)
    phis = np.linspace(0, 2 * np.pi, n, endpoint=False) + np.pi / (2 * n)
    alphas = phis if inside else phis + np.pi
    tau1 = (np.ceil(alphas / np.pi) * np.pi - alphas) / w
    for p, t in zip(curves[0], tau1, strict=True):
        if a > u_m:  # for a <= u_m (Figs 14-15) some extremals leave the disk before their first switch
            assert np.all(np.isfinite(p))
        if np.all(np.isfinite(p)):
            assert (np.hypot(*p) < a) == inside
            assert min_time_1dof(p, a, u_m, w).time == pytest.approx(t, abs=1e-6)
    if a > u_m or not inside:
        assert np.isfinite(curves[0]).any()
    else:  # a <= u_m from inside: one arc always suffices, so no switching curve lies inside the disk
        assert not np.isfinite(curves[0]).any()
        rng = np.random.default_rng(1)
        for r, th in zip(rng.uniform(0, a, 5), rng.uniform(0, 2 * np.pi, 5), strict=True):
            assert min_time_1dof((r * np.cos(th), r * np.sin(th)), a, u_m, w).switching_times.size == 0
    # wherever a second-switch point is kept, it is optimal too
    for p, t in zip(curves[1], tau1 + np.pi / w, strict=True):
        if np.all(np.isfinite(p)):
            assert min_time_1dof(p, a, u_m, w).time == pytest.approx(t, abs=1e-6)


def test_bad_inputs():
    """Clear errors."""
    with pytest.raises(ParameterError, match="amplitude"):
        excitation_time(-1, 1, 1)
    with pytest.raises(ParameterError, match="u_m"):
        min_time_1dof((0, 0), 1.0, 0.0)
    with pytest.raises(ParameterError, match="x0"):
        simulate_quasi_optimal((0, 0, 0), 1.0, 0.1)
    M, K, B, *_ = _stand()
    with pytest.raises(ParameterError, match="amplitudes"):
        excitation_time_bound(M, K, B, 5.0, [1.0, 2.0])
    with pytest.raises(ModelError, match="not controllable"):
        excitation_time_bound(np.eye(2), np.diag([1.0, 2.0]), np.array([[1.0], [0.0]]), 1.0, [1.0, 1.0])
    with pytest.raises(ParameterError, match="normalization"):
        excitation_time_bound(M, K, B, 5.0, [1.0, 1.0, 1.0], normalization="unit")
    assert min_time_1dof((1.0, 0.0), 1.0, 0.1).time == 0.0


def test_quasi_optimal_plot():
    """Phase-plane picture of the quasi-optimal run (arcs about (±u_m, 0), Figs 13–17)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    run = simulate_quasi_optimal((0.0, 0.0), 1.0, 0.1)
    run.plot(ax=ax)
    assert len(ax.lines) == len(run.controls) == 5
    plt.close(fig)
