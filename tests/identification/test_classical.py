"""Classical inertia-measurement formulas (Belyakov 2005, seed 001, Ch. I §1; report §3.12, feature 18)."""

import numpy as np
import pytest
import scipy.integrate
import sympy as sp

from symosc.identification.classical import flywheel, physical_pendulum, rocking_platform


def test_flywheel_matches_meshchersky_formula():
    """The SymPy derivation reproduces the printed two-weight flywheel formula (report §3.12, ref. [5])."""
    R, g, h, M1, M2, T1, T2 = sp.symbols("R g h M1 M2 T1 T2", positive=True)
    d = 1 / T1**2 - 1 / T2**2
    printed = R**2 * (g * (M1 - M2) / (2 * h * d) - (M1 / T1**2 - M2 / T2**2) / d)
    assert sp.simplify(flywheel().expr - printed) == 0


def test_flywheel_against_simulated_runs():
    """Simulate the drum with friction numerically for two weights; the formula recovers I without knowing Mf."""
    I_true, R, g, h, Mf = 0.8, 0.15, 9.81, 1.2, 0.7
    times = {}
    for M in (3.0, 5.0):

        def fall(t, y, M=M):
            return [y[1], (M * g * R - Mf) / (I_true + M * R**2) * R]

        def reached(t, y):
            return y[0] - h

        reached.terminal = True
        sol = scipy.integrate.solve_ivp(fall, (0, 100), [0.0, 0.0], events=reached, rtol=1e-12, atol=1e-14)
        times[M] = sol.t_events[0][0]
    vals = {"R": R, "g": g, "h": h, "M1": 3.0, "M2": 5.0, "T1": times[3.0], "T2": times[5.0]}
    assert float(flywheel()(vals)) == pytest.approx(I_true, rel=1e-9)


def test_physical_pendulum_from_simulated_period():
    """I_C = m g r / omega^2 - m r^2 recovers the inertia from a small-amplitude simulated period."""
    m, r, g, Ic = 2.0, 0.3, 9.81, 0.05
    sol = scipy.integrate.solve_ivp(
        lambda t, y: [y[1], -m * g * r * np.sin(y[0]) / (Ic + m * r**2)], (0, 20), [1e-5, 0.0],
        dense_output=True, rtol=1e-12, atol=1e-16, events=lambda t, y: y[1],
    )  # fmt: skip
    period = 2 * (sol.t_events[0][2] - sol.t_events[0][1])
    omega = 2 * np.pi / period
    assert float(physical_pendulum()({"m": m, "r": r, "g": g, "omega": omega})) == pytest.approx(Ic, rel=1e-8)


def test_rocking_platform_and_array_evaluation():
    """Rocking platform: exact on its own equation, and the evaluator broadcasts over arrays."""
    f = rocking_platform()
    c, l, J, m, d, I = 5e4, 0.8, 12.0, 40.0, 0.25, 3.5
    omega = np.sqrt(c * l**2 / (J + I + m * d**2))
    out = f({"c": c, "l": l, "J": J, "m": m, "d": d, "omega": np.array([omega, omega])})
    np.testing.assert_allclose(out, [I, I], rtol=1e-12)
    assert f._repr_latex_().startswith("$I = ")
