"""Bulgakov (1954), §5.23, eqs. (5.285)-(5.289): non-resonant periodic forcing, C1(mu) and C2(mu) as series.

References: the periodic orbit of the full equation by Newton shooting on the period map (scipy solve_ivp at
rtol 1e-12), and the first-order solution in closed form.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from symosc import ModelError, ParameterError
from symosc.nonlinear import nonresonant_forced_solution

q, v, t, mu = sp.symbols("q v t mu")
W = 1.7
PHI = sp.cos(W * t) + mu * (-(q**3) / 2 - v / 5 + q**2 * sp.sin(W * t) / 4)


def _shoot(m):
    def rhs(tt, z):
        x, y = z
        return [y, -x + np.cos(W * tt) + m * (-(x**3) / 2 - y / 5 + x**2 * np.sin(W * tt) / 4)]

    P = 2 * np.pi / W

    def F(z0):
        return solve_ivp(rhs, (0, P), z0, method="DOP853", rtol=1e-13, atol=1e-14).y[:, -1] - z0

    z = fsolve(F, [1 / (1 - W**2), 0.0], xtol=1e-12)
    assert np.max(np.abs(F(z))) < 1e-11
    return z, rhs


def test_series_against_shooting_with_error_slopes():
    """The error of the order-N truncation shrinks like mu^(N+1) (fitted slope), for C1 and C2 together."""
    sol = nonresonant_forced_solution(PHI, q, v, t, 1.0, W, 5)
    for N in (1, 2, 3):
        errs = []
        for m in (0.04, 0.02):
            z, _ = _shoot(m)
            errs.append(np.max(np.abs(sol.initial_state(m, N) - z)))
        slope = np.log(errs[0] / errs[1]) / np.log(2)
        assert N + 0.6 < slope < N + 1.5, (N, errs, slope)
    z, rhs = _shoot(0.02)
    assert np.max(np.abs(sol.initial_state(0.02) - z)) < 1e-10
    # the whole periodic solution, not just its initial state
    tt = np.linspace(0, 2 * np.pi / W, 9)
    orbit = solve_ivp(rhs, (0, tt[-1]), z, t_eval=tt, method="DOP853", rtol=1e-12, atol=1e-13).y[0]
    np.testing.assert_allclose(sol.evaluate(tt, 0.02), orbit, atol=1e-10)


def test_first_order_closed_form():
    """q'' + q = cos 2t - mu q^3: q0 = -cos(2t)/3, q1 = -(cos 2t + cos(6t)/35)/108 (harmonic balance by hand)."""
    sol = nonresonant_forced_solution(sp.cos(2 * t) - mu * q**3, q, v, t, 1.0, 2.0, 1)
    tt = np.linspace(0, np.pi, 7)
    q1 = -(np.cos(2 * tt) + np.cos(6 * tt) / 35) / 108
    np.testing.assert_allclose(sol.evaluate(tt, 1.0) - sol.evaluate(tt, 1.0, 0), q1, atol=1e-14)
    assert float(sol.C1.coefficients[1]) == pytest.approx(-1 / 105, rel=1e-13)
    assert float(sol.C2.coefficients[1]) == pytest.approx(0.0, abs=1e-15)


def test_resonance_and_bad_input_refused():
    with pytest.raises(ModelError, match="resonance"):
        nonresonant_forced_solution(sp.cos(t) - mu * q**3, q, v, t, 2.0, 1.0, 2)
    with pytest.raises(ModelError, match="mu = 0"):
        nonresonant_forced_solution(sp.cos(2 * t) - q**3, q, v, t, 1.0, 2.0, 2)
    with pytest.raises(ModelError, match="polynomial"):
        nonresonant_forced_solution(sp.cos(2 * t) - mu * sp.sin(q), q, v, t, 1.0, 2.0, 2)
    with pytest.raises(ParameterError, match="order"):
        nonresonant_forced_solution(sp.cos(2 * t), q, v, t, 1.0, 2.0, -1)
    with pytest.raises(ParameterError, match="k"):
        nonresonant_forced_solution(sp.cos(2 * t) * sp.Symbol("k"), q, v, t, 1.0, 2.0, 1)
