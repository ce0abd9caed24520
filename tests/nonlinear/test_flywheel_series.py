"""Bulgakov (1954), §5.24, eqs. (5.303)-(5.309): the 1/M series of a flywheel machine's speed.

Reference: the periodic steady running of (M + a(q)) r' + a'(q) r^2/2 = T(q) + D(r) - E, D(r) = E + k (r_m - r),
found by shooting on r(q) over one period with solve_ivp; r - r_m - r1/M must shrink like 1/M^2.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from symosc.nonlinear import flywheel_speed_series

s = sp.Symbol("s")
R_M, K = 3.0, 0.8


def _steady(M, sigma):
    def rhs(q, r):
        T = math.cos(q) + 0.5 * math.sin(2 * q)
        a, da = 0.3 * math.cos(q), -0.3 * math.sin(q)
        return [(T + K * (R_M - r[0]) - 0.5 * da * r[0] ** 2) / ((M + a) * r[0])]

    def period_map(r0):
        return solve_ivp(rhs, (0, 2 * math.pi), [r0], rtol=1e-12, atol=1e-13).y[0, -1] - r0

    r0 = brentq(period_map, R_M * 0.9, R_M * 1.1, xtol=1e-14)
    return solve_ivp(rhs, (0, 2 * math.pi), [r0], t_eval=sigma, rtol=1e-12, atol=1e-13).y[0]


def test_first_order_speed_against_steady_running():
    ser = flywheel_speed_series(sp.cos(s) + sp.sin(2 * s) / 2, s, R_M, mass_variation=sp.cos(s) * 3 / 10, samples=256)
    sigma = ser.sigma[::8]
    errs = []
    for M in (50.0, 100.0, 200.0):
        r = _steady(M, sigma)
        errs.append(np.max(np.abs(r - ser.speed(M)[::8])))
        fluct = np.ptp(r) / R_M
        assert ser.irregularity(M) == pytest.approx(fluct, rel=4 / M)
    assert errs[1] < 0.3 * errs[0] and errs[2] < 0.3 * errs[1]  # O(1/M^2)
    assert errs[0] < 0.1 * np.ptp(ser.r1) / 50.0  # well below the first-order fluctuation itself


def test_zero_mean_required():
    from symosc import ModelError

    with pytest.raises(ModelError):
        flywheel_speed_series(1 + sp.cos(s), s, 1.0)
