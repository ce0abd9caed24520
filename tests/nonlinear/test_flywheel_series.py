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


def test_second_order_speed_against_steady_running():
    """Bulgakov (1954), §5.24, (5.312)-(5.313): with r2 the error of r(q) drops to O(1/M^3) (fitted slope ~3).

    D(r) = E + k (r_m - r): D'(r_m) = -k, D'' = 0.  A second case with D'' != 0 checks the mean-fixing condition.
    """
    ser = flywheel_speed_series(
        sp.cos(s) + sp.sin(2 * s) / 2, s, R_M, mass_variation=sp.cos(s) * 3 / 10, samples=256, drive_slope=-K
    )
    sigma = ser.sigma[::8]
    e1, e2 = [], []
    for M in (40.0, 80.0, 160.0):
        r = _steady(M, sigma)
        e1.append(np.max(np.abs(r - ser.speed(M)[::8])))
        e2.append(np.max(np.abs(r - ser.speed(M, order=2)[::8])))
        assert abs(np.ptp(ser.speed(M, order=2)[::8]) - np.ptp(r)) <= 2 * e2[-1]
    slope1 = np.log(e1[0] / e1[2]) / np.log(4)
    slope2 = np.log(e2[0] / e2[2]) / np.log(4)
    assert 1.7 < slope1 < 2.3 and 2.6 < slope2 < 3.4, (e1, e2)
    assert e2[-1] < 0.05 * e1[-1]


def test_second_order_mean_speed_with_curved_drive():
    """D(r) = E + k (r_m - r) + c (r - r_m)^2: mean(r) - r_m = mean(r2)/M^2 = -c mean(r1^2)/(2 D') / M^2."""
    c = 0.5

    def steady(M):
        def rhs(q, r):
            T = math.cos(q)
            return [(T + K * (R_M - r[0]) + c * (r[0] - R_M) ** 2) / (M * r[0])]

        def period_map(r0):
            return solve_ivp(rhs, (0, 2 * math.pi), [r0], rtol=1e-12, atol=1e-13).y[0, -1] - r0

        r0 = brentq(period_map, R_M * 0.9, R_M * 1.1, xtol=1e-14)
        q = np.linspace(0, 2 * math.pi, 257)[:-1]
        return solve_ivp(rhs, (0, 2 * math.pi), [r0], t_eval=q, rtol=1e-12, atol=1e-13).y[0]

    ser = flywheel_speed_series(sp.cos(s), s, R_M, samples=256, drive_slope=-K, drive_curvature=2 * c)
    errs = []
    for M in (20.0, 40.0):
        r = steady(M)
        errs.append(np.max(np.abs(r - ser.speed(M, order=2))))
        # the mean speed shift is a pure second-order effect of the curvature
        assert np.mean(r) - R_M == pytest.approx(np.mean(ser.r2) / M**2, rel=3 / M)
    assert errs[1] < 0.2 * errs[0]
