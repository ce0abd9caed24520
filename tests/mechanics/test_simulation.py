"""simulate() and Trajectory: checked against closed forms, hand-written equations and other integrators."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
import scipy.linalg
import scipy.special
from scipy.integrate import solve_ivp

from symosc.errors import ConvergenceError, ParameterError
from symosc.mechanics import Geometry, LinearModel
from symosc.mechanics.simulation import integrate_state
from symosc.models import body_on_springs, n_link_pendulum

DOUBLE = {"m1": 1.0, "m2": 0.7, "l1": 1.0, "l2": 0.8, "g": 9.81}


@pytest.fixture(scope="module")
def double():
    return n_link_pendulum(2)


@pytest.fixture(scope="module")
def kapitza():
    return n_link_pendulum(1, inverted=True, pivot="vertical")


def _double_energy(y, m1, m2, l1, l2, g):
    """T + V of the hanging double point pendulum, written out by hand."""
    p1, p2, w1, w2 = y.T
    T = 0.5 * (m1 + m2) * l1**2 * w1**2 + 0.5 * m2 * l2**2 * w2**2 + m2 * l1 * l2 * w1 * w2 * np.cos(p1 - p2)
    V = -(m1 + m2) * g * l1 * np.cos(p1) - m2 * g * l2 * np.cos(p2)
    return T + V


def test_large_swing_period_matches_the_elliptic_integral():
    """Simple pendulum released from 2.5 rad: the period 4 sqrt(l/g) K(sin^2(theta0/2)) (complete elliptic integral,
    SciPy's ellipk, parameter m = k^2) brings it back; at half the period it is at -theta0."""
    theta0, l, g = 2.5, 0.7, 9.81
    period = 4 * np.sqrt(l / g) * scipy.special.ellipk(np.sin(theta0 / 2) ** 2)
    traj = n_link_pendulum(1).simulate(
        [0.0, period / 2, period], {"phi1": theta0}, {"m1": 2.0, "l1": l, "g": g}, rtol=1e-12, atol=1e-13
    )
    np.testing.assert_allclose(traj.q["phi1"], [theta0, -theta0, theta0], atol=2e-8)
    np.testing.assert_allclose(traj.qd["phi1"][1:], 0.0, atol=2e-7)


def test_double_pendulum_energy_drift_over_100_periods(double):
    """Target: relative energy drift <= 1e-9 over 100 periods at rtol = 1e-12 (energy recomputed by hand)."""
    w_low = double.linearize().natural_frequencies(DOUBLE)[0]
    times = np.linspace(0.0, 100 * 2 * np.pi / w_low, 4001)
    traj = double.simulate(times, {"phi1": 0.3, "phi2": -0.2}, DOUBLE, rtol=1e-12, atol=1e-12)
    e = _double_energy(traj.states, **DOUBLE)
    drift = np.max(np.abs(e - e[0])) / abs(e[0])
    assert drift <= 1e-9
    np.testing.assert_allclose(traj.energy, e, rtol=1e-13)  # the trajectory's energy is T + V
    assert traj.conserved and traj.energy_drift == pytest.approx(drift, rel=1e-6)


def test_methods_agree_with_a_hand_written_double_pendulum(double):
    """LSODA, DOP853 and Radau (analytic Jacobian) against SciPy's DOP853 on equations written out by hand."""
    m1, m2, l1, l2, g = (DOUBLE[k] for k in ("m1", "m2", "l1", "l2", "g"))

    def rhs(t, y):
        p1, p2, w1, w2 = y
        c, s = np.cos(p1 - p2), np.sin(p1 - p2)
        M = np.array([[(m1 + m2) * l1**2, m2 * l1 * l2 * c], [m2 * l1 * l2 * c, m2 * l2**2]])
        F = np.array(
            [
                -m2 * l1 * l2 * s * w2**2 - (m1 + m2) * g * l1 * np.sin(p1),
                m2 * l1 * l2 * s * w1**2 - m2 * g * l2 * np.sin(p2),
            ]
        )
        return np.concatenate([[w1, w2], np.linalg.solve(M, F)])

    times = np.linspace(0, 4, 81)
    y0 = [0.9, -0.4, 0.3, 0.0]
    ref = solve_ivp(rhs, (0, 4), y0, t_eval=times, method="DOP853", rtol=1e-12, atol=1e-13).y.T
    initial = {"phi1": 0.9, "phi2": -0.4, "phi1_dot": 0.3}
    for method in ("LSODA", "DOP853", "Radau"):
        traj = double.simulate(times, initial, DOUBLE, method=method, rtol=1e-10, atol=1e-12)
        np.testing.assert_allclose(traj.states, ref, atol=2e-7, err_msg=method)
    fo = double.first_order().simulate(times, initial, DOUBLE, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(fo.states, ref, atol=2e-7)


def test_vibrating_pivot_keeps_the_inverted_pendulum_up(kapitza):
    """Kapitza's pendulum: l phi'' = (g - a p^2 cos p t) sin phi (written by hand); with a^2 p^2 > 2 g l it stays up,
    at a quarter of that amplitude it falls."""
    m, l, g, p = 0.05, 0.2, 9.81, 2 * np.pi * 60
    times = np.linspace(0, 1.0, 201)
    a_up = 2.0 * np.sqrt(2 * g * l) / p

    def rhs(t, y, a):
        return [y[1], (g - a * p**2 * np.cos(p * t)) * np.sin(y[0]) / l]

    for a, upright in ((a_up, True), (a_up / 4, False)):
        traj = kapitza.simulate(times, {"phi1": 0.2}, {"m1": m, "l1": l, "g": g, "a": a, "p": p}, rtol=1e-11)
        ref = solve_ivp(rhs, (0, 1), [0.2, 0.0], t_eval=times, args=(a,), method="DOP853", rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(traj.q["phi1"], ref.y[0], atol=1e-6)
        assert bool(np.max(np.abs(traj.q["phi1"])) < 0.5) is upright
        assert traj.energy_name == "energy (not conserved)" and traj.energy_drift is None


def test_linear_model_against_the_matrix_exponential():
    """M q'' + D q' + K q = 0: the state at t is expm(A t) x0 (SciPy), A = [[0, I], [-M^-1 K, -M^-1 D]]."""
    import sympy as sp

    x, y = sp.symbols("x y")
    m, k, c = sp.symbols("m k c", positive=True)
    model = LinearModel(
        M=sp.Matrix([[m, 0], [0, 2 * m]]),
        D=sp.Matrix([[c, 0], [0, 0]]),
        K=sp.Matrix([[2 * k, -k], [-k, k]]),
        f=sp.zeros(2, 1),
        coordinates=(x, y),
    )
    vals = {"m": 1.5, "k": 40.0, "c": 0.3}
    times = np.linspace(0, 3, 7)
    traj = model.simulate(times, {"x": 0.01, "y_dot": -0.2}, vals, rtol=1e-11, atol=1e-14)
    M, D, K = np.diag([1.5, 3.0]), np.diag([0.3, 0.0]), np.array([[80.0, -40.0], [-40.0, 40.0]])
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.linalg.solve(M, K), -np.linalg.solve(M, D)]])
    ref = np.array([scipy.linalg.expm(A * s) @ [0.01, 0, 0, -0.2] for s in times])
    np.testing.assert_allclose(traj.states, ref, atol=1e-9)
    assert not traj.conserved  # damped


def test_forced_linear_model_reaches_the_steady_amplitude():
    """x'' + 2 zeta w x' + w^2 x = F cos(nu t): after the transient the amplitude is F / |w^2 - nu^2 + 2i zeta w nu|."""
    import sympy as sp

    from symosc.symbols import t

    x = sp.Symbol("x")
    w, z, F, nu = 3.0, 0.2, 2.0, 2.5
    model = LinearModel(
        M=sp.Matrix([[1]]), D=sp.Matrix([[2 * z * w]]), K=sp.Matrix([[w**2]]), f=sp.Matrix([[F * sp.cos(nu * t)]]),
        coordinates=(x,),
    )  # fmt: skip
    times = np.linspace(40, 60, 2001)
    traj = model.simulate(np.concatenate([[0.0], times]), {}, {}, rtol=1e-10, atol=1e-12)
    amp = np.max(np.abs(traj.q["x"][1:]))
    assert amp == pytest.approx(F / abs(w**2 - nu**2 + 2j * z * w * nu), rel=1e-4)


def test_body_on_springs_against_modal_superposition():
    """The stand released from a static load: simulated sensor motion equals the modal sum C' cos(omega t) q0'
    (Belyakov 2005, eq. 34), computed from the generalised eigenproblem."""
    model = body_on_springs(product_of_inertia="dissertation")
    vals = dict(
        m=15000, rx=2, rz=0.87, Izz=44000, Ixx=3000, Ixz=400, Lx=4, Lz=1.74, k1=7.4e5, k2=7.4e5, k3=7.4e5, k4=7.4e5
    )
    data = model.modal(vals, force=[0, -2000, 0, 0])
    times = np.linspace(0, 2, 41)
    traj = model.simulate(times, data.q0, vals, projection="side", rtol=1e-11, atol=1e-15)
    np.testing.assert_allclose(traj.states[:, :3] @ data.C.T, data.response(times), atol=1e-9 * np.abs(data.y0).max())
    assert traj.energy_drift < 1e-8
    assert any(name.startswith("spring") for name in traj.geometry.points)


def test_geometry_positions_are_the_chain_points(double):
    """The catalogue geometry puts mass k at sum_i l_i (sin phi_i, -cos phi_i) (hanging chain)."""
    traj = double.simulate(np.linspace(0, 0.5, 6), {"phi1": 0.4, "phi2": 1.0}, DOUBLE)
    pos = traj.geometry.positions(traj.t, traj.states, traj.coordinates, traj.values)
    p1, p2 = traj.q["phi1"], traj.q["phi2"]
    m2 = np.stack([np.sin(p1) + 0.8 * np.sin(p2), -np.cos(p1) - 0.8 * np.cos(p2)], axis=1)
    np.testing.assert_allclose(pos["m2"], m2, atol=1e-14)
    np.testing.assert_allclose(pos["pivot"], 0.0)


def test_rigid_chain_geometry_on_a_vibrating_pivot():
    """Rigid inverted chain: the pivot moves as a cos(p t); centre of mass 1 at lc1 (sin, cos) above it."""
    system = n_link_pendulum(2, links="rigid", inverted=True, pivot="vertical")
    g = system.geometry
    vals = {"l1": 0.045, "lc1": 0.025, "lc2": 0.013, "a": 0.002, "p": 600.0}
    times = np.array([0.0, 0.001, 0.002])
    states = np.array([[0.1, -0.05, 0, 0]] * 3)
    pos = g.positions(times, states, ("phi1", "phi2"), vals)
    np.testing.assert_allclose(pos["pivot"][:, 1], 0.002 * np.cos(600 * times), atol=1e-15)
    np.testing.assert_allclose(pos["m1"][:, 1] - pos["pivot"][:, 1], 0.025 * np.cos(0.1), atol=1e-15)
    np.testing.assert_allclose(pos["end"][:, 0], 0.045 * np.sin(0.1) + 0.026 * np.sin(-0.05), atol=1e-15)


def test_trajectory_tables_plot_animation_and_pickle(double, tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    from PIL import Image

    times = np.linspace(0, 8, 801)
    traj = double.simulate(times, {"phi1": 0.3, "phi2": -0.2}, DOUBLE)
    df = traj.to_pandas()
    ds = traj.to_xarray()
    np.testing.assert_array_equal(df["phi2_dot"].to_numpy(), traj.qd["phi2"])
    np.testing.assert_array_equal(ds["energy"].values, traj.energy)
    assert traj["phi1_dot"] is not None and list(df.index) == list(times)
    ax = traj.plot()
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [r"$\phi_{1}$", r"$\phi_{2}$"]
    gif = tmp_path / "double.gif"
    anim = traj.animate(gif, fps=25, max_frames=200, speed=1.0)
    with Image.open(gif) as im:
        assert im.n_frames == 200
        assert im.info["duration"] == round(1000 * 8 / 199)  # the frame time follows the simulated time
    html = anim.to_jshtml()
    assert html.count("iVBOR") == 200  # every frame embedded as PNG
    again = pickle.loads(pickle.dumps(traj))
    np.testing.assert_array_equal(again.states, traj.states)


def test_any_system_is_animated_with_a_given_geometry(tmp_path):
    import sympy as sp

    from symosc import dot
    from symosc.mechanics import LagrangianSystem

    x = sp.Symbol("x", real=True)
    m, k = sp.symbols("m k", positive=True)
    system = LagrangianSystem(m * dot(x) ** 2 / 2, k * x**2 / 2, [x])
    traj = system.simulate(np.linspace(0, 1, 11), {"x": 0.1}, {"m": 1.0, "k": 4.0})
    with pytest.raises(ParameterError, match="geometry"):
        traj.animate()
    geo = Geometry({"wall": (0, 0), "mass": (1 + x, 0)}, (("wall", "mass"),), ("mass",), ("wall",))
    anim = traj.animate(tmp_path / "spring.gif", geometry=geo, fps=10)
    assert anim.frames == 11 and (tmp_path / "spring.gif").stat().st_size > 0
    with pytest.raises(ParameterError, match="not in points"):
        Geometry({"a": (0, 0)}, (("a", "b"),))


def test_refusals(double):
    with pytest.raises(ParameterError, match="phi3"):
        double.simulate([0, 1], {"phi3": 0.1}, DOUBLE)
    with pytest.raises(ParameterError, match="increasing"):
        double.simulate([1, 0], {"phi1": 0.1}, DOUBLE)
    with pytest.raises(ParameterError, match="method"):
        double.simulate([0, 1], {"phi1": 0.1}, DOUBLE, method="Euler")
    with pytest.raises(ParameterError, match="l2"):
        double.simulate([0, 1], {"phi1": 0.1}, {k: v for k, v in DOUBLE.items() if k != "l2"})
    # y' = y^2 from y(0) = 1 blows up at t = 1: the integrator cannot reach t = 2
    for method in ("LSODA", "RK45"):
        with pytest.raises(ConvergenceError), np.errstate(over="ignore"):
            integrate_state(lambda t, y: y**2, None, np.array([0.0, 2.0]), np.array([1.0]), method=method)
