"""Piecewise and special systems of Bulgakov ch. 5 B–C and §5.24.

The exact piecewise solutions and point maps are checked against event-driven numerical integration with SciPy
(stick/slip handled explicitly), and the tables against the recomputed values of seed-bulgakov-part2.md §3.
"""

from __future__ import annotations

import math

import matplotlib
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc.errors import ConvergenceError, ModelError, ParameterError
from symosc.nonlinear.special.piecewise import (
    coulomb_oscillator,
    half_swing_map,
    quadratic_drag_eta,
    quadratic_drag_eta_series,
    quadratic_drag_half_swing_times,
)
from symosc.nonlinear.special.special_systems import (
    backlash_critical_gap,
    clock_escapement,
    radinger_flywheel,
    step_valve_generator,
)

x = sp.Symbol("x")
RTOL = dict(rtol=1e-12, atol=1e-13)


def _event_v0(direction):
    ev = lambda _t, y: y[1]  # noqa: E731
    ev.terminal, ev.direction = True, direction
    return ev


def _simulate_coulomb(x0, B, k, eps, max_swings=400):
    """Reference: event-driven integration of x'' + 2 eps x' + k^2 (x + B sign x') = 0 with an explicit stick test."""
    pts, times, t, q = [x0], [0.0], 0.0, x0
    for _ in range(max_swings):
        if abs(q) <= B:
            break
        s = -np.sign(q)  # direction of motion
        rhs = lambda _t, y, s=s: [y[1], -2 * eps * y[1] - k**2 * (y[0] + B * s)]  # noqa: E731
        T = 2 * math.pi / math.sqrt(k**2 - eps**2)
        sol = solve_ivp(rhs, (t, t + T), [q, 0.0], events=_event_v0(-s), **RTOL)
        t, q = float(sol.t_events[0][-1]), float(sol.y_events[0][-1][0])
        pts.append(q)
        times.append(t)
    return pts, times


# ---------------------------------------------------------------------------------------------- Coulomb
def test_coulomb_alone_decrement_2B_vs_event_driven():
    """Seed 004, §5.6 (5.68)–(5.72): a_{j+1} = a_j - 2B, last step 2B - a_n, period 2 pi/k unchanged."""
    B = sp.Rational(1, 10)
    m = coulomb_oscillator(sp.Rational(3, 2), B, k=2)
    assert m.amplitudes[:3] == (sp.Rational(3, 2), sp.Rational(13, 10), sp.Rational(11, 10))
    assert all(m.amplitudes[j] - m.amplitudes[j + 1] == 2 * B for j in range(m.half_swings - 1))
    pts, times = _simulate_coulomb(1.5, 0.1, 2.0, 0.0)
    np.testing.assert_allclose([float(q) for q in m.turning_points], pts, atol=1e-10)
    np.testing.assert_allclose(m.times, times, atol=1e-9)
    np.testing.assert_allclose(np.diff(times), math.pi / 2, atol=1e-9)  # half period pi/k
    # the closed-form x(t) agrees with the integrated trajectory inside a half-swing
    sol = solve_ivp(lambda _t, y: [y[1], -4 * (y[0] - 0.1)], (0, 0.7), [1.5, 0.0], dense_output=True, **RTOL)
    tt = np.linspace(0, 0.7, 50)
    np.testing.assert_allclose(m(tt), sol.sol(tt)[0], atol=1e-10)
    np.testing.assert_allclose(m.velocity(tt), sol.sol(tt)[1], atol=1e-9)


def test_coulomb_final_step_rules():
    """(5.71): from B < a_n <= 2B one more half-swing ends at 2B - a_n on the same side; from |a| <= B no motion."""
    m = coulomb_oscillator(sp.Rational(17, 100), sp.Rational(1, 10))
    assert m.turning_points == (sp.Rational(17, 100), sp.Rational(3, 100))
    assert coulomb_oscillator(sp.Rational(1, 20), sp.Rational(1, 10)).half_swings == 0


def test_pocket_watch_example():
    """Seed 004, §5.6 example (report §3 item 2): a0 = 135 deg stops after 200 half-swings (40 s, period 0.4 s)
    when B = 3 pi/1600."""
    m = coulomb_oscillator(3 * sp.pi / 4, 3 * sp.pi / 1600, k=5 * sp.pi)
    assert m.half_swings == 200 and abs(float(m.final_position)) < 1e-25
    assert m.stop_time == pytest.approx(40.0, rel=1e-12)


def test_coulomb_plus_viscous_closed_form_and_simulation():
    """Seed 004, §5.7 (5.98)–(5.99): a_{j+1} = a_j delta - B(1 + delta) and the closed form, vs event-driven ODE."""
    B, k, eps, a0 = 0.05, 1.3, 0.08, 2.0
    m = coulomb_oscillator(a0, B, k=k, eps=eps)
    d = float(m.delta)
    assert d == pytest.approx(math.exp(-math.pi * eps / math.sqrt(k**2 - eps**2)), rel=1e-15)
    closed = lambda j: (a0 + B * (1 + d) / (1 - d)) * d**j - B * (1 + d) / (1 - d)  # noqa: E731
    amps = [float(v) for v in m.amplitudes]
    n = m.half_swings
    np.testing.assert_allclose(amps[:n], [closed(j) for j in range(n)], rtol=1e-13)
    pts, times = _simulate_coulomb(a0, B, k, eps)
    np.testing.assert_allclose([float(q) for q in m.turning_points], pts, atol=1e-10)
    np.testing.assert_allclose(m.times, times, atol=1e-8)


def test_gyropilot_free_play_is_coulomb():
    """Seed 004, §5.8: free play 2B in the feedback gives the same law; the ship settles within |q| <= B."""
    m = coulomb_oscillator(0.3, 0.02, k=0.5, eps=0.05)
    assert abs(float(m.final_position)) <= 0.02


def test_coulomb_extreme_many_half_swings():
    """Tiny friction: 10^5 half-swings, exact rationals, no drift (a_j = a0 - 2Bj exactly)."""
    m = coulomb_oscillator(1, sp.Rational(1, 200001))
    assert m.half_swings == 100000
    assert m.amplitudes[-1] == 1 - 2 * sp.Rational(1, 200001) * 100000


def test_coulomb_plot_and_bad_input():
    matplotlib.use("Agg")
    coulomb_oscillator(1.0, 0.1).plot()
    with pytest.raises(ParameterError, match="eps < k"):
        coulomb_oscillator(1.0, 0.1, k=1, eps=2)
    with pytest.raises(ParameterError, match="non-negative"):
        coulomb_oscillator(1.0, -0.1)
    with pytest.raises(ParameterError, match="real number"):
        coulomb_oscillator(sp.Symbol("a"), 0.1)


# ---------------------------------------------------------------------------------------------- maps
def _dm(deg, minutes):
    return math.radians(deg + minutes / 60)


TABLE2 = [  # (a, b) in degrees, minutes: recomputed values of report §3 item 4 (book outliers 140 deg excluded)
    ((15, 0), (4, 57)),
    ((20, 0), (9, 53)),
    ((30, 0), (19, 41)),
    ((45, 0), (34, 9)),
    ((60, 0), (48, 20)),
    ((90, 0), (75, 26)),
    ((135, 0), (109, 35)),
    ((175, 0), (122, 54)),
]


def test_table2_pendulum_coulomb_friction():
    """Seed 004, §5.6, Table 2 (B = 5 deg): cos a + a sin B = cos b - b sin B; recomputed values, 1 arcmin."""
    m = half_swing_map(1 - sp.cos(x), x, friction=sp.sin(sp.pi / 36))
    for a, b in TABLE2:
        assert math.degrees(m(_dm(*a))) == pytest.approx(math.degrees(_dm(*b)), abs=1 / 60)
    # the map's zero B' = 10 deg 01' (5.88): a pendulum released at B' stops at the bottom
    bp = _dm(10, 1)
    assert abs(math.degrees(m(bp))) < 1.0 / 60
    assert m(math.radians(4.0)) is None  # inside the dead zone: never starts


def test_table2_against_simulation():
    """The pendulum-with-Coulomb map vs event-driven integration of q'' = -sin q + sin B (leftward swing)."""
    sB = math.sin(math.radians(5))
    m = half_swing_map(1 - sp.cos(x), x, friction=sB)
    for a in (0.5, 2.0, 3.0):
        sol = solve_ivp(lambda _t, y: [y[1], -math.sin(y[0]) + sB], (0, 30), [a, 0], events=_event_v0(1), **RTOL)
        assert -sol.y_events[0][-1][0] == pytest.approx(m(a), abs=1e-9)


def test_table3_quadratic_drag_map_and_series():
    """Seed 004, §5.9, Table 3 (Liebisch): (xi + 1) e^{-xi} = (1 - eta) e^{eta}; series coefficients (5.123)."""
    table = {1: 0.5936, 1.5: 0.7316, 2: 0.8214, 2.5: 0.8809, 3: 0.9207, 4: 0.9651, 5: 0.9849, 6: 0.9936, 8: 0.9989}
    for xi, eta in table.items():
        assert quadratic_drag_eta(xi) == pytest.approx(eta, abs=1e-4)
    # the same numbers from the general map: linear spring V = q^2/2 with quadratic drag eps = 1 (x = eps q)
    m = half_swing_map(x**2 / 2, x, drag=1)
    for xi in (1, 3, 6):
        assert m(xi) == pytest.approx(quadratic_drag_eta(xi), abs=1e-10)
    # first column of the table: the iterated sequence from 1 ends at 0.0767, 0.0730 (report §3 item 5)
    seq = [1.0]
    while seq[-1] > 0.0731:
        seq.append(quadratic_drag_eta(seq[-1]))
    assert seq[1:3] == pytest.approx([0.5936, 0.4240], abs=1e-4)
    assert seq[-2:] == pytest.approx([0.0767, 0.0730], abs=1e-4)
    c = quadratic_drag_eta_series(6)
    assert c == [sp.Integer(n) / d for n, d in ((1, 1), (-2, 3), (4, 9), (-44, 135), (104, 405), (-40, 189))]
    xi = 0.05
    assert sum(float(ck) * xi ** (k + 1) for k, ck in enumerate(c)) == pytest.approx(quadratic_drag_eta(xi), abs=1e-9)


def test_table4_half_swing_times():
    """Seed 004, §5.9, Table 4 (units sqrt(m/sigma)); recomputed values (book's 48.36 at xi = 1000 is wrong: 43.36)."""
    table = {1: (1.747, 1.475), 2: (1.940, 1.441), 5: (2.578, 1.416), 10: (3.612, 1.414), 1000: (43.36, 1.414)}
    for xi, (t1, t2) in table.items():
        g1, g2 = quadratic_drag_half_swing_times(xi, dps=15)
        assert g1 == pytest.approx(t1, rel=5e-4) and g2 == pytest.approx(t2, rel=5e-4)
    g1, g2 = quadratic_drag_half_swing_times(1e-6, dps=15)
    assert (g1, g2) == pytest.approx((math.pi / 2, math.pi / 2), rel=1e-5)


def test_table4_against_simulation():
    """Half-swing times vs integration of q'' + q = -q'|q'| ... in Liebisch's scaling (m = sigma = 1, eps = 1)."""
    xi = 2.0
    t1, t2 = quadratic_drag_half_swing_times(xi, dps=15)
    # leftward swing from q = xi: q'' = -q + q'^2 (drag G q'^2 with 2G/m = eps = 1 opposes the motion)
    ev0 = lambda _t, y: y[0]  # noqa: E731
    sol = solve_ivp(lambda _t, y: [y[1], -y[0] + 0.5 * y[1] ** 2], (0, 10), [xi, 0], events=[ev0, _event_v0(1)], **RTOL)
    assert sol.t_events[0][0] == pytest.approx(t1, rel=1e-8)
    assert sol.t_events[1][0] - sol.t_events[0][0] == pytest.approx(t2, rel=1e-8)


TABLE5 = [((50, 0), (40, 12)), ((90, 0), (60, 45)), ((100, 0), (64, 29)), ((135, 0), (73, 28)), ((150, 0), (75, 33))]


def test_table5_pendulum_quadratic_drag():
    """Seed 004, §5.9, Table 5 (eps = 0.4): e^{-eps a}(cos a + eps sin a) = e^{eps b}(cos b - eps sin b).

    Recomputed values (the book's 5 deg -> 4 deg 37' is a misprint; 4 deg 53' is correct, checked by the series)."""
    m = half_swing_map(1 - sp.cos(x), x, drag=sp.Rational(2, 5))
    for a, b in TABLE5:
        assert math.degrees(m(_dm(*a))) == pytest.approx(math.degrees(_dm(*b)), abs=1 / 60)
    assert math.degrees(m(math.radians(5))) == pytest.approx(4 + 53 / 60, abs=1 / 60)
    assert math.degrees(m(math.pi - 1e-9)) == pytest.approx(77 + 4 / 60, abs=1 / 60)


def test_half_swing_map_bad_input():
    with pytest.raises(ParameterError, match="substitute values for: g"):
        half_swing_map(sp.Symbol("g") * x**2, x)
    with pytest.raises(ParameterError, match="non-negative"):
        half_swing_map(x**2, x, friction=-1)
    m = half_swing_map(x**2 / 2 + x**3 / 3, x)  # released above the barrier on the left: never returns
    with pytest.raises(ConvergenceError, match="does not stop"):
        m(0.5)


# ---------------------------------------------------------------------------------------------- clocks
def _simulate_clock(a0, B, h, f, swings):
    """Kicked Coulomb oscillator x'' + x = -B sign x', kick v -> sign(v) sqrt(v^2 + h) at x = +f (leftward) and
    x = -f (rightward).  Returns the turning amplitudes and the half-swing durations."""
    amps, durs, q = [a0], [], a0
    for _ in range(swings):
        s = -np.sign(q)
        rhs = lambda _t, y, s=s: [y[1], -y[0] - B * s]  # noqa: E731
        kick = lambda _t, y, s=s: y[0] + s * f  # noqa: E731
        kick.terminal, kick.direction = True, s
        t0, y0, kicked = 0.0, [q, 0.0], False
        while True:
            sol = solve_ivp(rhs, (t0, t0 + 10), y0, events=[_event_v0(-s)] + ([] if kicked else [kick]), **RTOL)
            if not kicked and sol.t_events[1].size:
                t0 = float(sol.t_events[1][0])
                xk, vk = sol.y_events[1][0]
                y0, kicked = [xk, s * math.sqrt(vk**2 + h)], True
                continue
            t_end, q = float(sol.t_events[0][0]), float(sol.y_events[0][0][0])
            break
        amps.append(abs(q))
        durs.append(t_end)
        if abs(q) <= B:
            break
    return amps, durs


def test_clock_map_and_cycle_vs_simulation():
    """Seed 004, §5.11 (5.135), (5.138), (5.137): map, A = h/(4B), half-swing time, monotone convergence."""
    B, h, f = 0.02, 0.04, 0.1
    c = clock_escapement(sp.Rational(1, 50), sp.Rational(1, 25), sp.Rational(1, 10))
    assert c.amplitude == sp.Rational(1, 2) and c.exists
    assert sp.simplify(c.multiplier - (c.amplitude - c.B) / (c.amplitude + c.B)) == 0
    amps, durs = _simulate_clock(0.3, B, h, f, 30)
    pred = c.sequence(0.3, 30)
    np.testing.assert_allclose(amps, pred[: len(amps)], atol=1e-9)
    assert abs(amps[-1] - 0.5) < 0.03 and all(np.diff(amps) > 0)  # from below, monotone
    for a, d in zip(amps[:5], durs[:5], strict=False):
        assert d == pytest.approx(float(c.half_swing_time(a)), abs=1e-8)
    amps2, _ = _simulate_clock(0.8, B, h, f, 25)
    assert all(np.diff(amps2) < 0) and amps2[-1] > 0.5  # from above, monotone
    np.testing.assert_allclose(amps2, c.sequence(0.8, 25)[: len(amps2)], atol=1e-9)


def test_clock_airy_theorem_and_existence():
    """Airy: a kick exactly at the dead-zone edge (f = B) leaves the half-period pi; kicks before/after it
    shorten/lengthen it.  No cycle if the escapement is out of reach (5.139)."""
    c = clock_escapement(sp.Rational(1, 50), sp.Rational(1, 25), sp.Rational(1, 50))
    assert sp.simplify(c.half_swing_time(sp.Rational(3, 10)) - sp.pi) == 0
    assert float(clock_escapement(0.02, 0.04, 0.1).half_swing_time(0.3)) < math.pi
    assert float(clock_escapement(0.05, 0.04, 0.01).half_swing_time(0.3)) > math.pi
    far = clock_escapement(sp.Rational(1, 50), sp.Rational(1, 25), sp.Rational(3, 5))  # f = 0.6 > A = 0.5
    assert not far.exists
    amps, _ = _simulate_clock(0.55, 0.02, 0.04, 0.6, 60)
    assert amps[-1] <= 0.02  # the clock stops


def test_step_valve_generator_vs_simulation():
    """Seed 004, §5.13 (5.161)–(5.166): turning points converge to +A, -B with A = S/(1-delta), B = delta A."""
    S, eps, k = 0.3, 0.1, 1.0
    g = step_valve_generator(S, sp.Rational(1, 10), 1)
    d = float(g.delta)
    assert float(g.A) == pytest.approx(S / (1 - d), rel=1e-14) and float(g.B) == pytest.approx(S * d / (1 - d))
    assert float(g.multiplier) == pytest.approx(d**2)
    q, pts = 0.1, []
    for _ in range(30):
        s = -np.sign(q)  # moving left (s=-1): H = 0; moving right: H = 1
        rhs = lambda _t, y, s=s: [y[1], -2 * eps * y[1] - k**2 * y[0] + k**2 * S * (s > 0)]  # noqa: E731
        sol = solve_ivp(rhs, (0, 10), [q, 0.0], events=_event_v0(-s), **RTOL)
        q = float(sol.y_events[0][0][0])
        pts.append(q)
    target = sorted([float(g.A), -float(g.B)], reverse=pts[-2] > 0)
    assert pts[-2:] == pytest.approx(target, abs=1e-3)  # convergence factor delta per half-swing
    np.testing.assert_allclose(g.sequence(0.1, 30)[1:], pts, atol=1e-9)


def test_backlash_critical_gap_limits():
    """Seed 004, §5.14 (RECONSTRUCTED (5.186)–(5.190)): k_c(f=0) = M2(-z); motor variant -> 0 as f -> 1;
    k_c = 0 at z = 0; friction reduces k_c (friction stabilises); finite as z -> oo."""
    z = 1.0
    m2 = backlash_critical_gap(z, 0.0)
    assert m2 + math.log(1 - m2) == pytest.approx(-z, abs=1e-12)  # M2 inverts L = x + ln(1 - x)
    for variant in ("follower", "motor"):
        assert backlash_critical_gap(z, 1e-9, variant) == pytest.approx(m2, abs=1e-6)
        vals = [backlash_critical_gap(z, f, variant) for f in (0.1, 0.3, 0.6, 0.9)]
        assert all(np.diff(vals) < 0)
        assert backlash_critical_gap(0.0, 0.3, variant) == 0.0
    assert backlash_critical_gap(z, 0.999999, "motor") < 1e-5 and backlash_critical_gap(z, 1.5, "motor") == 0
    assert backlash_critical_gap(1e6, 0.3) == pytest.approx(backlash_critical_gap(1e3, 0.3), rel=1e-9)
    with pytest.raises(ParameterError, match="variant"):
        backlash_critical_gap(1, 0.1, "rotor")


@pytest.mark.parametrize("variation", [0, 1])
def test_radinger_flywheel_vs_simulation(variation):
    """Seed 004, §5.24 (5.319): the mass from Radinger's formula gives the requested cyclic irregularity delta when
    m(s) r' + a'(s) r^2/2 = torque(s) is integrated over a revolution (error O(delta))."""
    s = sp.Symbol("s")
    torque = sp.sin(s) + sp.Rational(3, 10) * sp.sin(2 * s)
    av = sp.Rational(3, 10) * sp.cos(2 * s) * variation
    delta, r_m = 0.02, 2.0
    d = radinger_flywheel(torque, s, delta, r_m, mass_variation=av, other_mass=1.0)
    assert d.flywheel_mass == pytest.approx(d.mass - 1.0)
    tq = sp.lambdify(s, torque)
    a_, da = sp.lambdify(s, av), sp.lambdify(s, sp.diff(av, s))
    M = d.mass

    def rhs(_t, y):
        return [y[1], (tq(y[0]) - 0.5 * da(y[0]) * y[1] ** 2) / (M + a_(y[0]))]

    sol = solve_ivp(rhs, (0, 3 * 2 * math.pi / r_m), [0.0, r_m], max_step=0.01, **RTOL)
    w = sol.y[1][sol.y[0] <= 2 * math.pi]
    measured = (w.max() - w.min()) / w.mean()
    assert measured == pytest.approx(delta, rel=0.05)
    if not variation:
        assert d.energy_swing == pytest.approx(2.0, rel=1e-9)  # E(s) = 1 - cos s + 0.15 (1 - cos 2s): swing 2


def test_flywheel_bad_input():
    s = sp.Symbol("s")
    with pytest.raises(ModelError, match="zero mean"):
        radinger_flywheel(1 + sp.sin(s), s, 0.02, 1.0)
    with pytest.raises(ParameterError, match="delta"):
        radinger_flywheel(sp.sin(s), s, 2.0, 1.0)
