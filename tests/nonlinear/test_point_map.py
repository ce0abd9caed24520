"""Point-map fixed points (Bulgakov §5.12): exact maps and the section map of van der Pol's oscillator."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc.errors import ParameterError
from symosc.nonlinear import point_map_fixed_point

x = sp.Symbol("x")


def test_exact_map_fixed_points_and_multipliers():
    """P = 3x/(1+x): fixed points 0 (multiplier 3, unstable) and 2 (multiplier 1/3, stable)."""
    r = point_map_fixed_point(3 * x / (1 + x), 1.5)
    assert r.x == pytest.approx(2.0, abs=1e-12) and r.multiplier == pytest.approx(1 / 3, rel=1e-12) and r.stable
    u = point_map_fixed_point(3 * x / (1 + x), 0.1)
    assert u.x == pytest.approx(0.0, abs=1e-12) and u.multiplier == pytest.approx(3.0) and not u.stable
    with pytest.raises(ParameterError, match="free symbol"):
        point_map_fixed_point(x * sp.Symbol("a"), 1.0)


def _vdp_section_map(eps: float):
    """x(0) = a, x'(0) = 0 -> the next crossing of x' = 0 with x > 0 (one revolution)."""

    def rhs(t, y):
        return [y[1], eps * (1 - y[0] ** 2) * y[1] - y[0]]

    def back(t, y):
        return y[1]

    back.direction = -1  # x' goes + to - at the right extreme (x > 0)

    def P(a: float) -> float:
        sol = solve_ivp(rhs, (1e-6, 40), [a, -1e-9], events=back, rtol=1e-12, atol=1e-12)
        times = sol.t_events[0]
        ys = sol.y_events[0]
        k = next(i for i, yy in enumerate(ys) if yy[0] > 0)
        assert times[k] > 1.0
        return float(ys[k][0])

    return rhs, P


def test_van_der_pol_section_map():
    """The fixed point of the section map is the limit-cycle amplitude, which a long transient integration
    reaches independently; the cycle is stable (|P'| < 1)."""
    eps = 0.5
    rhs, P = _vdp_section_map(eps)
    r = point_map_fixed_point(P, 1.0, tol=1e-9)
    sol = solve_ivp(rhs, (0, 200), [1.0, 0.0], rtol=1e-11, atol=1e-11, dense_output=True)
    tt = np.linspace(190, 200, 20001)
    amp = float(np.max(sol.sol(tt)[0]))
    assert r.x == pytest.approx(amp, rel=1e-6)
    assert r.stable and 0 < r.multiplier < 1
