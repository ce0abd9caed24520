"""Bulgakov (1954), §12.2–12.6, eq. (12.35): Poincaré's first approximation for a general f(D) system.

Reference: long-time numeric integration (solve_ivp, DOP853) of the original equations; the first-harmonic
amplitudes must approach ``A* |V_j|`` like O(mu) and the frequency ``omega (1 + b mu)`` like O(mu^2).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc import ModelError
from symosc.nonlinear import poincare_operator_system

D, y1, y2, v1, v2 = sp.symbols("D y1 y2 v1 v2")


def _simulate(mu):
    """y1'' + y1 = mu((1 - y1^2) y1' + 0.8 y2),  y2' + 2 y2 - y1 = -mu y1^3: f(D) = [[D^2+1, 0], [-1, D+2]]."""

    def rhs(t, s):
        Y1, V1, Y2 = s
        return [V1, -Y1 + mu * ((1 - Y1**2) * V1 + 0.8 * Y2), Y1 - 2 * Y2 - mu * Y1**3]

    def down(t, s):
        return s[1]

    down.direction = -1
    sol = solve_ivp(rhs, (0, 12 / mu), [0.5, 0, 0], method="DOP853", rtol=1e-10, atol=1e-12, events=down,
                    dense_output=True)  # fmt: skip
    te = sol.t_events[0][-11:]
    tt = np.linspace(te[0], te[-1], 4096, endpoint=False)
    Y = sol.sol(tt)
    amps = [2 * abs(np.fft.rfft(Y[k])[10]) / tt.size for k in (0, 2)]
    return np.array(amps), 2 * np.pi / np.diff(te).mean()


def test_third_order_system_against_integration():
    sys = poincare_operator_system(
        sp.Matrix([[D**2 + 1, 0], [-1, D + 2]]), [(1 - y1**2) * v1 + 0.8 * y2, -(y1**3)], [y1, y2], [v1, v2], D
    )
    assert sys.omega == pytest.approx(1.0, rel=1e-12)
    np.testing.assert_allclose(sys.other_roots, [-2.0], rtol=1e-12)
    (cyc,) = sys.cycles(5.0)
    assert cyc.stable and cyc.slope < 0
    predicted = cyc.amplitude * np.abs(sys.V)
    errs_a, errs_w = [], []
    for mu in (0.02, 0.01):
        amps, w = _simulate(mu)
        errs_a.append(np.max(np.abs(amps - predicted) / predicted))
        errs_w.append(abs(w - sys.omega * (1 + cyc.b * mu)))
        assert abs(w - sys.omega) > 10 * errs_w[-1]  # the correction b is visible
    assert errs_a[0] < 0.06 and errs_a[1] < 0.6 * errs_a[0]  # O(mu)
    assert errs_w[0] < 2 * 0.02**2 and errs_w[1] < 0.35 * errs_w[0]  # O(mu^2)


def test_van_der_pol_and_its_unstable_mirror():
    f = sp.Matrix([[D**2 + 1]])
    (c,) = poincare_operator_system(f, [(1 - y1**2) * v1], [y1], [v1], D).cycles(5.0)
    assert c.amplitude == pytest.approx(2.0, rel=1e-10) and c.stable
    # van der Pol cycle: characteristic exponent -mu (textbook), multiplier exp(-2 pi mu) = 1 - 2 pi mu + O(mu^2)
    assert c.multiplier(0.1, 1.0) == pytest.approx(1 - 2 * np.pi * 0.1, rel=1e-8)
    (c,) = poincare_operator_system(f, [-(1 - y1**2) * v1], [y1], [v1], D).cycles(5.0)
    assert c.amplitude == pytest.approx(2.0, rel=1e-10) and not c.stable


def test_refuses_without_a_critical_pair():
    with pytest.raises(ModelError):
        poincare_operator_system(sp.Matrix([[D**2 + D + 1]]), [y1], [y1], [v1], D)


def test_shortened_amplitude_equation_against_transient():
    """dA/dt = mu G(A)/(2 omega) (12.152): the envelope of y1/|V1| during the build-up of the third-order system."""
    mu = 0.01
    sys = poincare_operator_system(
        sp.Matrix([[D**2 + 1, 0], [-1, D + 2]]), [(1 - y1**2) * v1 + 0.8 * y2, -(y1**3)], [y1, y2], [v1, v2], D
    )
    A0, t_end = 0.1, 400.0
    slow = solve_ivp(lambda t, a: [mu * sys.amplitude_rate(a[0])], (0, t_end), [A0], rtol=1e-10, dense_output=True)

    def rhs(t, s):
        Y1, V1, Y2 = s
        return [V1, -Y1 + mu * ((1 - Y1**2) * V1 + 0.8 * Y2), Y1 - 2 * Y2 - mu * Y1**3]

    V = sys.V
    y0 = [A0 * V[0].real, -A0 * sys.omega * V[0].imag, A0 * V[1].real]  # y* = A Re(V e^{iu}) at u = 0
    full = solve_ivp(rhs, (0, t_end), y0, method="DOP853", rtol=1e-10, atol=1e-12, dense_output=True)
    for t_check in (100.0, 200.0, 300.0):
        tt = np.linspace(t_check - np.pi, t_check + np.pi, 400)
        env = np.max(np.abs(full.sol(tt)[0])) / abs(V[0])
        assert env == pytest.approx(slow.sol(t_check)[0], rel=0.05)
    assert slow.sol(300.0)[0] > 3 * A0  # a real build-up was followed
