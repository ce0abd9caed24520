"""Bulgakov (1954), §12.4, eqs. (12.36)-(12.41): Poincaré's second approximation for f(D) y = mu psi.

References: the van der Pol frequency 1 - mu^2/16 (classical closed form), and the periodic orbit of the full
system by Newton shooting (scipy solve_ivp, rtol 1e-12) whose frequency and first-harmonic amplitude are compared at
two values of mu: the fitted error slopes rise by one with each approximation.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from symosc import ModelError
from symosc.nonlinear import poincare_second_approximation

D = sp.Symbol("D")
y1, y2, v1, v2 = sp.symbols("y1 y2 v1 v2")


def test_van_der_pol_closed_form():
    """omega = 1 - mu^2/16 + O(mu^4) and first-harmonic amplitude 2 + O(mu^2) for van der Pol."""
    sa = poincare_second_approximation(sp.Matrix([[D**2 + 1]]), [(1 - y1**2) * v1], [y1], [v1], D, 5.0)
    assert sa.amplitude == pytest.approx(2.0, abs=1e-12)
    assert sa.B == pytest.approx(0.0, abs=1e-12) and sa.b == pytest.approx(0.0, abs=1e-12)
    assert sa.c / 2 == pytest.approx(-1 / 16, abs=1e-12)
    # y1 = -sin(3u)/4 by hand: x1'' + x1 = 2 sin 3u, no homogeneous part (B = 0, cos-only first harmonic of y)
    u = np.linspace(0, 2 * np.pi, 9)
    np.testing.assert_allclose(sa.solution(u, 1.0) - sa.solution(u, 0.0), [-np.sin(3 * u) / 4], atol=1e-12)


def _shoot(rhs, z0, T0, n):
    """Periodic orbit with y1'(0) = 0: unknowns (state without y1', period)."""

    def flow(z, T):
        return solve_ivp(rhs, (0, T), z, method="DOP853", rtol=1e-12, atol=1e-13).y[:, -1]

    def F(x):
        z = np.insert(x[:-1], 1, 0.0)
        return flow(z, x[-1]) - z

    x = fsolve(F, np.append(np.delete(z0, 1), T0), xtol=1e-13)
    z = np.insert(x[:-1], 1, 0.0)
    T = x[-1]
    t = T * np.arange(256) / 256
    orbit = solve_ivp(rhs, (0, T), z, t_eval=t, method="DOP853", rtol=1e-12, atol=1e-13).y
    amp = 2 * abs(np.fft.rfft(orbit[0])[1]) / 256
    return 2 * np.pi / T, amp


@pytest.mark.parametrize("case", ["duffing_vdp", "with_real_root"])
def test_error_slopes_against_shooting(case):
    """Frequency: error O(mu^2) with b, O(mu^3) with c; amplitude: O(mu) with A*, O(mu^2) with A* + mu B."""
    if case == "duffing_vdp":
        f = sp.Matrix([[D**2 + 1]])
        psi, ys, dys = [(1 - y1**2) * v1 - y1**3], [y1], [v1]

        def make(m):
            return lambda _t, z: [z[1], -z[0] + m * ((1 - z[0] ** 2) * z[1] - z[0] ** 3)]

        z0 = lambda sa: np.array([sa.amplitude, 0.0])  # noqa: E731
    else:
        f = sp.Matrix([[D**2 + 1, 0], [-1, D + 2]])
        psi, ys, dys = [(1 - y1**2 - y2**2) * v1 - y1**3 / 2, 0], [y1, y2], [v1, v2]

        def make(m):
            return lambda _t, z: [
                z[1],
                -z[0] + m * ((1 - z[0] ** 2 - z[2] ** 2) * z[1] - z[0] ** 3 / 2),
                z[0] - 2 * z[2],
            ]

        z0 = lambda sa: np.array([sa.amplitude, 0.0, sa.amplitude * 0.4])  # noqa: E731
    sa = poincare_second_approximation(f, psi, ys, dys, D, 6.0)
    assert sa.reference == 0 and abs(sa.b) > 0.05 and abs(sa.B) > 1e-3
    ef = {1: [], 2: []}
    ea = {0: [], 1: []}
    mus = (0.04, 0.02)
    for m in mus:
        om, amp = _shoot(make(m), z0(sa), 2 * np.pi / sa.frequency(m), len(ys))
        for k in ef:
            ef[k].append(abs(om - sa.frequency(m, k)))
        for k in ea:
            ea[k].append(abs(amp - sa.reference_amplitude(m, k)))
    slope = lambda e: np.log(e[0] / e[1]) / np.log(2)  # noqa: E731
    assert 1.6 < slope(ef[1]) < 2.4 and 2.5 < slope(ef[2]) < 3.6, (ef, slope(ef[1]), slope(ef[2]))
    assert 0.7 < slope(ea[0]) < 1.3 and 1.6 < slope(ea[1]) < 2.5, (ea, slope(ea[0]), slope(ea[1]))


def test_tangent_amplitude_function_and_resonance_refused():
    """G(A) = A (A^2 - 4)^2 / 16 touches the axis at A = 2 (12.40): no transversal generating amplitude, refused.

    psi = (32 - 64 y^2 + 16 y^4) y' averages to A (32/2 - 64 A^2/8 + 16 A^4/16) = A (A^2 - 4)^2.  A root D = 0 of
    Delta (k = 0 multiple of omega) is a resonance (12.17).
    """
    with pytest.raises(ModelError, match="generating amplitude"):
        poincare_second_approximation(
            sp.Matrix([[D**2 + 1]]), [(32 - 64 * y1**2 + 16 * y1**4) * v1], [y1], [v1], D, 5.0
        )
    with pytest.raises(ModelError, match="resonant root 0i"):
        poincare_second_approximation(
            sp.Matrix([[D**2 + 1, 0], [-1, D]]), [v1 * (1 - y1**2), 0], [y1, y2], [v1, v2], D, 5.0
        )


def test_r_matrix_critical_multipliers_against_floquet():
    """(12.56)-(12.65): the critical block of R gives the multipliers 1 and 1 + mu eta; compare with the monodromy
    matrix of the full first-order system found by shooting (error O(mu^2)), and with the van der Pol value
    exp(-2 pi mu) for the plain oscillator."""
    x, vx, z = sp.symbols("x vx z")
    dummies = sp.symbols("d1:4")
    # y1' = v1, v1' = -y1 + mu (1 - y1^2 - z^2) v1, z' = y1 - 2 z   as (D E + H) Y = mu psi
    f = sp.Matrix([[D, -1, 0], [1, D, 0], [-1, 0, D + 2]])
    sa = poincare_second_approximation(f, [0, (1 - x**2 - z**2) * vx, 0], [x, vx, z], list(dummies), D, 5.0)
    m = 0.01
    rho_pred = sa.critical_multipliers(m)
    assert rho_pred[0] == pytest.approx(1.0, abs=1e-12)

    def rhs(_t, s):
        return [s[1], -s[0] + m * (1 - s[0] ** 2 - s[2] ** 2) * s[1], s[0] - 2 * s[2]]

    def flow(s0, T):
        return solve_ivp(rhs, (0, T), s0, method="DOP853", rtol=1e-12, atol=1e-13).y[:, -1]

    def F(xx):
        s0 = np.array([xx[0], 0.0, xx[1]])
        return flow(s0, xx[2]) - s0

    u_star = -np.angle(sa.harmonics[0][0, 1])  # phase where y1 is at its maximum (v1 = 0)
    y0 = sa.solution(u_star, m)[:, 0]
    xx = fsolve(F, [y0[0], y0[2], 2 * np.pi / sa.frequency(m)], xtol=1e-12)
    s0 = np.array([xx[0], 0.0, xx[1]])
    h = 1e-6
    mono = np.column_stack([(flow(s0 + h * e, xx[2]) - flow(s0 - h * e, xx[2])) / (2 * h) for e in np.eye(3)])
    rho = np.sort(np.abs(np.linalg.eigvals(mono)))[1:]  # drop exp(-2P), keep the critical pair
    assert rho[1] == pytest.approx(1.0, abs=1e-6)
    eta = (rho_pred[1] - 1) / m
    assert abs(rho[0] - rho_pred[1]) < (eta * m) ** 2  # 1 + mu eta is the first-order truncation
    assert abs(rho[0] - np.exp(eta * m)) < 3 * m**2  # the exponent mu eta itself is right to O(mu^2)
    assert abs(rho_pred[1] - 1) > 10 * m**2  # the first-order term is resolved, not just 1
    with pytest.raises(ModelError, match="first-order"):
        poincare_second_approximation(sp.Matrix([[D**2 + 1]]), [(1 - y1**2) * v1], [y1], [v1], D, 5.0).r_matrix()
