"""Every example scene runs, and each answer is checked against an independent computation."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import scipy.linalg
import scipy.special
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from symosc.scene import load

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _run(name):
    scene = load(EXAMPLES / f"{name}.toml")
    return scene, scene.run()


def _floquet_radius(M, C, g, a, p):
    """Largest |multiplier| of M q'' + (-g + a p^2 cos pt) C q = 0 over one pivot period (SciPy DOP853)."""
    n = M.shape[0]
    A = np.linalg.solve(M, C)

    def rhs(t, y):
        Y = y.reshape(2 * n, 2 * n)
        return np.vstack([Y[n:], -(-g + a * p**2 * np.cos(p * t)) * A @ Y[:n]]).ravel()

    sol = solve_ivp(rhs, (0, 2 * np.pi / p), np.eye(2 * n).ravel(), rtol=1e-11, atol=1e-13, method="DOP853")
    return np.max(np.abs(np.linalg.eigvals(sol.y[:, -1].reshape(2 * n, 2 * n))))


def _point_chain(m, l, g):
    """Inverted chain of point masses written out by hand.

    M_ij = l_i l_j sum_{k >= max(i,j)} m_k,  C_ii = l_i sum_{k >= i} m_k."""
    n = len(m)
    tail = [sum(m[k:]) for k in range(n)]
    M = np.array([[l[i] * l[j] * tail[max(i, j)] for j in range(n)] for i in range(n)])
    return M, np.diag([l[i] * tail[i] for i in range(n)])


def test_example_inverted_pendulum_n1():
    """Kapitza pendulum: the interval ends solve a_0(q) = a and b_1(q) = a (SciPy's Mathieu functions)."""
    _, res = _run("inverted_pendulum_n1")
    m, l, g = 0.01, 0.2, 9.81
    mats = res["linear_matrices"].data["numeric"]
    np.testing.assert_allclose(mats["M"], [[m * l**2]], rtol=1e-14)
    np.testing.assert_allclose(mats["K0"], [[-m * g * l]], rtol=1e-14)
    d = res["stability_region"].data
    p = 2 * np.pi * 50
    a1 = -4 * (g / l) / p**2
    q_lo = brentq(lambda q: scipy.special.mathieu_a(0, q) - a1, 1e-6, 5)
    q_hi = brentq(lambda q: scipy.special.mathieu_b(1, q) - a1, 1e-6, 5)
    # q = 2 a p1^2 / g = 2 a / l
    assert d["amplitude_min"] == pytest.approx(q_lo * l / 2, rel=1e-7)
    assert d["amplitude_max"] == pytest.approx(q_hi * l / 2, rel=1e-7)
    assert d["stable"] is True
    # the sweep over the length: each interval from SciPy's Mathieu functions again
    sw = res["sweep"].data
    for length, lo, hi in zip(sw["values"], sw["amplitude_min"], sw["amplitude_max"], strict=True):
        a1 = -4 * (g / length) / p**2
        q_lo = brentq(lambda q, a1=a1: scipy.special.mathieu_a(0, q) - a1, 1e-6, 5)
        q_hi = brentq(lambda q, a1=a1: scipy.special.mathieu_b(1, q) - a1, 1e-6, 5)
        assert (lo, hi) == pytest.approx((q_lo * length / 2, q_hi * length / 2), rel=1e-7)


def test_example_inverted_pendulum_n3():
    """Triple chain: stability interval and Floquet verdicts against the hand-written 6-D system."""
    _, res = _run("inverted_pendulum_n3")
    M, C = _point_chain([0.02] * 3, [0.05] * 3, 9.81)
    lam = scipy.linalg.eigh(9.81 * C, M, eigvals_only=True)
    np.testing.assert_allclose(res["natural_frequencies"].data["omega_rad_s"], np.sqrt(lam), rtol=1e-10)
    d = res["stability_region"].data
    p = 2 * np.pi * 200
    assert _floquet_radius(M, C, 9.81, d["amplitude_min"] * 1.02, p) < 1 + 1e-6
    assert _floquet_radius(M, C, 9.81, d["amplitude_min"] * 0.98, p) > 1 + 1e-5
    assert _floquet_radius(M, C, 9.81, d["amplitude_max"] * 0.98, p) < 1 + 1e-6
    assert _floquet_radius(M, C, 9.81, d["amplitude_max"] * 1.02, p) > 1 + 1e-5
    rng = d["range"]
    assert rng["amplitude_min"][1] == pytest.approx(d["amplitude_min"]) and rng["frequency_rad_s"][1] == p
    p4, lo4, hi4 = rng["frequency_rad_s"][2], rng["amplitude_min"][2], rng["amplitude_max"][2]
    assert _floquet_radius(M, C, 9.81, lo4 * 0.98, p4) > 1 + 1e-5 > _floquet_radius(M, C, 9.81, lo4 * 1.02, p4) - 1e-5
    assert _floquet_radius(M, C, 9.81, hi4 * 1.02, p4) > 1 + 1e-5 > _floquet_radius(M, C, 9.81, hi4 * 0.98, p4) - 1e-5
    for row in res["floquet"].data["grid"]:
        ref = _floquet_radius(M, C, 9.81, row["amplitude"], row["frequency_rad_s"])
        assert row["max_abs_multiplier"] == pytest.approx(ref, rel=1e-6)
        inside = d["amplitude_min"] < row["amplitude"] < d["amplitude_max"]
        assert (row["stability"] == "stable") == inside


def test_example_van_der_pol_series():
    """Amplitude of the cycle at eps = 0.3 from a long SciPy integration, against the series in the report."""
    _, res = _run("van_der_pol_series")
    eps = 0.3
    sol = solve_ivp(lambda t, y: [y[1], eps * (1 - y[0] ** 2) * y[1] - y[0]], (0, 120), [2.0, 0.0], rtol=1e-12,
                    atol=1e-12, dense_output=True)  # fmt: skip
    t = np.linspace(100, 120, 100001)
    amp = sol.sol(t)[0].max()
    series = sp.sympify(res["limit_cycle"].data["amplitude"]).subs("eps", eps)
    assert float(series) == pytest.approx(amp, abs=1e-7)
    assert res["limit_cycle"].data["validation"][1]["amplitude_error"] < 1e-7


def test_example_duffing_resonance():
    """Every point of the curve solves the textbook equation
    [(w0^2 - nu^2 + 3 mu a^2/4)^2 + (2 zeta w0 nu)^2] a^2 = R^2;
    the number of steady states changes from 1 to 3 across each jump frequency."""
    _, res = _run("duffing_resonance")
    w0, zeta, mu, R = 1.0, 0.05, 0.5, 0.1
    fig = res["resonance_curve"].figures[0].data
    nu = np.array(fig["nu"])[:, None]
    a = np.array(fig["amplitudes"], dtype=float)
    ok = np.isfinite(a)
    lhs = ((w0**2 - nu**2 + 0.75 * mu * a**2) ** 2 + (2 * zeta * w0 * nu) ** 2) * a**2
    np.testing.assert_allclose(lhs[ok], np.broadcast_to(R**2, lhs.shape)[ok], rtol=1e-6)

    def n_states(v):  # real positive roots in s = a^2 of the cubic (expanded by hand)
        c = [(0.75 * mu) ** 2, 1.5 * mu * (w0**2 - v**2), (w0**2 - v**2) ** 2 + (2 * zeta * w0 * v) ** 2, -(R**2)]
        r = np.roots(c)
        return int(np.sum((np.abs(r.imag) < 1e-9) & (r.real > 0)))

    jumps = res["resonance_curve"].data["jump_frequencies"]
    assert len(jumps) == 2
    assert [n_states(jumps[0] - 1e-3), n_states(jumps[0] + 1e-3)] == [1, 3]
    assert [n_states(jumps[1] - 1e-3), n_states(jumps[1] + 1e-3)] == [3, 1]


def test_example_duffing_continuation():
    """The folds of the continued branch are saddle-nodes of the period map: the orbit integrated with SciPy from the
    reported state closes after one forcing period, and its monodromy matrix has a multiplier 1."""
    _, res = _run("duffing_continuation")
    w0, zeta, mu, R = 1.0, 0.05, 0.5, 0.3
    folds = [b for b in res["continuation"].data["bifurcations"] if b["kind"] == "fold"]
    assert len(folds) == 2
    for b in folds:
        nu = b["parameter"]

        def rhs(t, y, nu=nu):
            x, v = y[0], y[1]
            A = np.array([[0.0, 1.0], [-(w0**2) - 3 * mu * x**2, -2 * zeta * w0]])
            force = R * np.cos(nu * t)
            return np.concatenate(
                [[v, -2 * zeta * w0 * v - w0**2 * x - mu * x**3 + force], (A @ y[2:].reshape(2, 2)).ravel()]
            )

        y0 = np.array(b["initial_state"])
        z = solve_ivp(rhs, (0, 2 * np.pi / nu), np.concatenate([y0, np.eye(2).ravel()]), rtol=1e-12, atol=1e-13).y[
            :, -1
        ]
        assert np.linalg.norm(z[:2] - y0) < 1e-8
        rho = np.linalg.eigvals(z[2:].reshape(2, 2))
        assert np.min(np.abs(rho - 1)) < 1e-6


def test_example_carson_solution():
    """Against sympy.dsolve of y'' + 3y' + 2y = 1, y(0) = y'(0) = 0."""
    _, res = _run("carson_solution")
    t = sp.Symbol("t")
    y = sp.Function("y")
    ref = sp.dsolve(
        y(t).diff(t, 2) + 3 * y(t).diff(t) + 2 * y(t) - 1, y(t), ics={y(0): 0, y(t).diff(t).subs(t, 0): 0}
    ).rhs
    ours = sp.sympify(res["operational_solution"].data["response"], locals={"t": t})
    assert sp.simplify(ours - ref) == 0
    for tt, val in res["operational_solution"].data["values"]:
        assert val == pytest.approx(float(ref.subs(t, tt)), rel=1e-12)


def test_example_mathieu_values():
    _, res = _run("mathieu_values")
    rows = [r for qr in res.results if qr.kind == "mathieu_values" for r in qr.data["values"]]
    kinds = ["a"] * 9 + ["b"] * 4
    for kind, r in zip(kinds, rows, strict=True):
        ref = (scipy.special.mathieu_a if kind == "a" else scipy.special.mathieu_b)(r["n"], r["q"])
        assert r["value"] == pytest.approx(ref, rel=1e-9, abs=1e-12)
    assert res["ince_strutt"].figures[0].drawer == "ince_strutt"


def test_example_spring_pendulum():
    """Hand linearisation: M = [[M+m, m l], [m l, m l^2]], K = diag(k, m g l)."""
    _, res = _run("spring_pendulum")
    Mb, m, l, k, g = 2.0, 0.5, 0.4, 200.0, 9.81
    lam = scipy.linalg.eigh(np.diag([k, m * g * l]), np.array([[Mb + m, m * l], [m * l, m * l**2]]), eigvals_only=True)
    np.testing.assert_allclose(res["natural_frequencies"].data["omega_rad_s"], np.sqrt(lam), rtol=1e-10)
    steps = [e.step for e in res.log]
    assert steps.index("derive the nonlinear equations of motion") > steps.index("linearize at q = 0")
    assert r"\ddot{\phi}" in res["equations_of_motion"].data["latex"]


def test_example_belyakov_identification():
    """The record was simulated from the dissertation's body: Algorithm 1 recovers it."""
    _, res = _run("belyakov_identification")
    est = res["identify"].data["inertia"]
    true = dict(mass=15000, rx=2, rz=0.87, Izz=44000, Ixx=3000, Ixz=400)
    for key, val in true.items():
        assert est[key] == pytest.approx(val, rel=5e-3 if key == "Ixz" else 5e-4), key


def test_example_belyakov_stand():
    """Hand-built 3-DOF stand (springs at the rectangle's corners) and the dissertation's Table 3."""
    _, res = _run("belyakov_stand")
    m, rx, rz, Izz, Ixx, Ixz, k, Lx, Lz = 15000, 2, 0.87, 44000, 3000, 400, 7.4e5, 4, 1.74

    def freqs(rz):
        C = np.array([[1, x - rx, -(z - rz)] for x, z in ((0, 0), (Lx, 0), (Lx, Lz), (0, Lz))])
        M = np.array([[m, 0, 0], [0, Izz, Ixz], [0, Ixz, Ixx]])
        return np.sqrt(scipy.linalg.eigh(k * C.T @ C, M, eigvals_only=True))

    omega = res["natural_frequencies"].data["omega_rad_s"]
    np.testing.assert_allclose(omega, freqs(rz), rtol=1e-12)
    np.testing.assert_allclose(omega, [14.04726, 16.39794, 27.35160], rtol=1e-4)  # Table 3 as printed
    sw = res["sweep"].data
    for r, hz in zip(sw["values"], sw["frequency_hz"], strict=True):
        np.testing.assert_allclose(np.array(hz) * 2 * np.pi, freqs(r), rtol=1e-12)


CHECKS = {name[len("test_example_") :] for name in globals() if name.startswith("test_example_")}


# checked in test_scene.py (textbook double pendulum with SciPy; Floquet multipliers at the interval's ends)
CHECKED_ELSEWHERE = {"double_pendulum_frequencies", "gribkov2015"}


def test_every_example_has_an_independent_check():
    from tests.scene import test_scene

    assert hasattr(test_scene, "test_double_pendulum_frequencies_against_the_textbook_model")
    assert hasattr(test_scene, "test_gribkov2015_stability_interval_against_floquet")
    assert sorted({*CHECKS, *CHECKED_ELSEWHERE}) == sorted(p.stem for p in EXAMPLES.glob("*.toml"))
