"""Two coupled oscillators (Bulgakov (1954), §8.13–8.15): scipy.linalg.eigh and solve_ivp as references."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from scipy.linalg import eigh

from symosc.errors import ModelError, ParameterError
from symosc.linear import tuning_curves, two_dof_beats, two_dof_system


@settings(max_examples=60, deadline=None)
@given(
    st.floats(0.2, 5),
    st.floats(-0.9, 0.9),
    st.floats(0.2, 5),
    st.floats(0.2, 5),
    st.floats(-0.9, 0.9),
    st.floats(0.2, 5),
)
def test_frequencies_and_modes_vs_eigh(L, m, N, A, b, C):
    """(8.79) and the modal ratios of §8.14 against the generalized symmetric eigenproblem K v = ω² M v."""
    M, B = m * np.sqrt(L * N), b * np.sqrt(A * C)
    s = two_dof_system(L, M, N, A, B, C)
    Mm, K = np.array([[L, M], [M, N]]), np.array([[A, B], [B, C]])
    w2, V = eigh(K, Mm)
    assert np.allclose(s.frequencies, np.sqrt(w2), rtol=1e-9)
    for h in range(2):  # same direction as the eigh mode (when not degenerate)
        if abs(w2[1] - w2[0]) > 1e-6 * w2[1]:
            v = V[:, h] / np.linalg.norm(V[:, h])
            u = s.modes[:, h] / np.linalg.norm(s.modes[:, h])
            assert abs(abs(v @ u) - 1) < 1e-7
    # interlacing (8.80): ω1 ≤ min(ωa, ωb) ≤ max(ωa, ωb) ≤ ω2
    assert s.frequencies[0] <= min(s.omega_a, s.omega_b) * (1 + 1e-12)
    assert s.frequencies[1] >= max(s.omega_a, s.omega_b) * (1 - 1e-12)


def test_e9_numbers():
    """§8.13 with L = 2, M = 0.3, N = 1, A = 5, B = -0.8, C = 3 (values derived from (8.79), (8.90))."""
    s = two_dof_system(2, 0.3, 1, 5, -0.8, 3)
    assert s.frequencies == pytest.approx((1.33234666, 2.05799018), abs=1e-8)
    assert s.modes[1] == pytest.approx((1.08792237, -1.67615766), abs=1e-8)
    assert s.k == pytest.approx(0.3 / np.sqrt(2)) and s.l == pytest.approx(0.8 / np.sqrt(15))


@pytest.mark.parametrize("params", [(2, 0.3, 1, 5, -0.8, 3), (1, 0, 1, 1.1, -0.1, 1.1), (1, 0.1, 1.5, 2, 0.3, 2.5)])
def test_beats_vs_solve_ivp(params):
    """(8.92)–(8.96): the displacement from rest matches solve_ivp; |y_j| never exceeds the envelope and reaches it
    once per carrier period; the envelope limits are its min and max over a beat period."""
    L, M, N, A, B, C = params
    s = two_dof_system(*params)
    bt = two_dof_beats(s, [1.0, -0.3])
    Mi = np.linalg.inv(np.array([[L, M], [M, N]], float))
    K = np.array([[A, B], [B, C]], float)
    T = 2 * bt.beat_period
    t = np.linspace(0, T, 4001)
    sol = solve_ivp(
        lambda _, z: np.concatenate([z[2:], -Mi @ K @ z[:2]]),
        (0, T),
        [1.0, -0.3, 0, 0],
        t_eval=t,
        rtol=1e-11,
        atol=1e-13,
        method="DOP853",
    )
    y, env = bt.displacement(t), bt.envelope(t)
    assert np.allclose(y, sol.y[:2], atol=1e-8)
    assert np.all(np.abs(y) <= env + 1e-12)
    tf = np.linspace(0, bt.beat_period, 200001)
    ef = bt.envelope(tf)
    assert np.allclose(ef.min(axis=1), bt.limits[:, 0], atol=1e-6)
    assert np.allclose(ef.max(axis=1), bt.limits[:, 1], atol=1e-9)


def test_tuned_release_exchanges_energy_completely():
    """§8.14: equal partial frequencies and release of the first oscillator alone: y1's envelope falls to zero."""
    s = two_dof_system(1, 0, 1, 1.1, -0.1, 1.1)
    bt = two_dof_beats(s, [1.0, 0.0])
    assert bt.limits[0] == pytest.approx((0.0, 1.0), abs=1e-12)
    detuned = two_dof_beats(two_dof_system(1, 0, 1, 1.1, -0.1, 1.3), [1.0, 0.0])
    assert detuned.limits[0, 0] > 0.05


def test_tuning_curves_vs_eigh_and_limits():
    """(8.84) against eigh of the normalized system (ωa = 1, ωb = x); (8.85)–(8.86) limits."""
    k, l = 0.3, -0.2
    c = tuning_curves(k, l, np.linspace(0.1, 3, 30))
    for x, z1, z2 in zip(c.x, c.z1, c.z2, strict=True):
        w2 = eigh(np.array([[1, -l * x], [-l * x, x * x]]), np.array([[1, k], [k, 1]]), eigvals_only=True)
        assert (z1, z2) == pytest.approx(tuple(np.sqrt(w2)), rel=1e-10)
    c0 = tuning_curves(0.4, 0.0, [0.0])
    assert (c0.z1[0], c0.z2[0]) == pytest.approx((0.0, 1 / np.sqrt(1 - 0.16)))  # x = 0, l = 0 (8.86)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    assert c.plot(ax=ax) is ax
    assert two_dof_beats(two_dof_system(2, 0.3, 1, 5, -0.8, 3), [1, 0]).plot(ax=ax) is ax
    plt.close(fig)


def test_bad_input():
    with pytest.raises(ModelError, match="kinetic"):
        two_dof_system(1, 2, 1, 1, 0, 1)
    with pytest.raises(ModelError, match="potential"):
        two_dof_system(1, 0, 1, 1, 2, 1)
    with pytest.raises(ParameterError, match="k²"):
        tuning_curves(1.0, 0.0)
    with pytest.raises(ParameterError, match="y0"):
        two_dof_beats(two_dof_system(1, 0, 1, 1, 0, 2), [1.0])


def test_new_results_pickle_and_repr():
    """The result objects added for §4.1–4.17 and §8.13–8.24 survive pickling and print their key numbers."""
    import pickle

    from symosc.linear import (
        delay_equal_stability_lines,
        equal_stability_lines,
        optimize_regulator,
        phase_portrait,
        servo_optimum,
        servo_stability_lines,
    )

    objs = [
        phase_portrait(1, 0.5, 2),
        optimize_regulator(1.0, k2=2.0),
        equal_stability_lines("gamma1", 0.5, theta=(1, 1)),
        delay_equal_stability_lines("andronov-maier", 0.2),
        two_dof_system(2, 0.3, 1, 5, -0.8, 3),
        two_dof_beats(two_dof_system(2, 0.3, 1, 5, -0.8, 3), [1, 0]),
        tuning_curves(0.1, 0.2),
        servo_stability_lines(8.0, 1.0),
        servo_optimum(8.0),
    ]
    for o in objs:
        back = pickle.loads(pickle.dumps(o))
        assert repr(back) == repr(o)
    assert "stationary point" in repr(objs[1]) and "ω1 = 1.33235" in repr(objs[4])
    assert r"\alpha = 1.41421" in objs[1]._repr_latex_() and r"\omega_1 = 1.33235" in objs[4]._repr_latex_()
