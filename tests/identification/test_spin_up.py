"""Belyakov (2005), §3.12: motor spin-up/brake inertia formula and the Huygens–Steiner transfer.

References: numeric integration (solve_ivp) of the shaft dynamics ``(I + J) omega' = T_motor - M_friction(omega)``
with the motor work and the friction work integrated as extra states; a SymPy re-derivation from the kinematics of
uniformly accelerated rotation; a disk's moment of inertia by numeric quadrature.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import dblquad, solve_ivp

from symosc import ModelError, ParameterError
from symosc.identification import central_gyration, motor_spin_up_brake

I_BODY, J_DEV = 2.3, 0.4


def _run(torque, omega_start, omega_stop, coulomb, viscous):
    """Integrate omega, motor work and friction work until omega reaches omega_stop."""

    def rhs(t, y):
        w = y[0]
        fr = coulomb * np.sign(w) + viscous * w
        return [(torque - fr) / (I_BODY + J_DEV), torque * w, fr * w]

    def reach(t, y):
        return y[0] - omega_stop

    reach.terminal = True
    sol = solve_ivp(rhs, (0, 1e3), [omega_start, 0.0, 0.0], events=reach, rtol=1e-12, atol=1e-12)
    assert sol.status == 1
    return sol.y_events[0][0][1], sol.y_events[0][0][2]  # motor work, friction work


def test_spin_up_brake_recovers_inertia_with_coulomb_friction():
    """Equal acceleration and deceleration under a constant friction moment: equal friction work, exact formula."""
    w0, w1, Mc, T = 5.0, 40.0, 0.7, 3.0
    A1, W1 = _run(T, w0, w1, Mc, 0.0)
    A2, W2 = _run(-(T - 2 * Mc), w1, w0, Mc, 0.0)
    assert A2 < 0 and W1 > 0
    assert W1 == pytest.approx(W2, rel=1e-9)
    got = motor_spin_up_brake()({"A1": A1, "A2": A2, "omega0": w0, "omega1": w1, "J": J_DEV})
    assert float(got) == pytest.approx(I_BODY, rel=1e-9)


def test_bias_with_unequal_friction_work():
    """Viscous friction and constant torques: the bias is (W1 - W2)/(omega1^2 - omega0^2), as stated."""
    w0, w1, T = 5.0, 40.0, 6.0
    A1, W1 = _run(T, w0, w1, 0.3, 0.02)
    A2, W2 = _run(-T, w1, w0, 0.3, 0.02)
    got = float(motor_spin_up_brake()({"A1": A1, "A2": A2, "omega0": w0, "omega1": w1, "J": J_DEV}))
    assert abs(got / I_BODY - 1) > 1e-2  # the premise matters
    assert got - I_BODY == pytest.approx((W1 - W2) / (w1**2 - w0**2), rel=1e-8)


def test_formula_rederived_from_uniform_acceleration():
    """Constant motor torques T (spin-up) and T - 2 Mc (brake) with Coulomb friction Mc, solved kinematically."""
    I, J, T, Mc, w0, w1 = sp.symbols("I J T M_c omega0 omega1", positive=True)
    alpha = (T - Mc) / (I + J)  # same magnitude of acceleration in both runs
    angle = (w1**2 - w0**2) / (2 * alpha)
    A1, A2 = T * angle, -(T - 2 * Mc) * angle
    f = motor_spin_up_brake().expr
    sub = {sp.Symbol("A1"): A1, sp.Symbol("A2"): A2, sp.Symbol("J"): J}
    sub.update({s: {"omega0": w0, "omega1": w1}[s.name] for s in f.free_symbols if s.name.startswith("omega")})
    assert sp.simplify(f.xreplace(sub) - I) == 0


def test_huygens_steiner_for_offset_disk():
    """Uniform disk radius a, axis perpendicular to it at distance r from the center: rho_m^2 = a^2 / 2."""
    a, r = 0.3, 2.0
    area = math.pi * a**2
    moment, _ = dblquad(lambda y, x: (x - r) ** 2 + y**2, -a, a, lambda x: -math.sqrt(a * a - x * x),
                        lambda x: math.sqrt(a * a - x * x), epsabs=1e-13, epsrel=1e-13)  # fmt: skip
    rho = math.sqrt(moment / area)
    res = central_gyration(rho, r, rel_error_rho=1e-5, rel_error_r=1e-5)
    assert res.radius == pytest.approx(a / math.sqrt(2), rel=1e-9)
    # worst case: rho too large and r too small by the given relative errors
    perturbed = math.sqrt((rho * (1 + 1e-5)) ** 2 - (r * (1 - 1e-5)) ** 2)
    assert perturbed / res.radius - 1 == pytest.approx(res.relative_error, rel=1e-3)
    assert res.relative_error > 1e-3  # 10 ppm inputs, > 1000 ppm output: the amplification the text warns about


def test_central_gyration_bad_input():
    with pytest.raises(ModelError):
        central_gyration(1.0, 1.5)
    with pytest.raises(ParameterError):
        central_gyration(float("nan"), 0.1)
    with pytest.raises(ParameterError):
        central_gyration(1.0, -0.1)
