"""Bulgakov (1954), §5.23, eqs. (5.285)-(5.288): resonant periodic solutions with a periodic right-hand side.

Reference: the periodic solution of the full equation found by Newton shooting on the period map (solve_ivp), its
first harmonic and its Floquet multipliers (finite-difference Jacobian of the period map).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from symosc.nonlinear import forced_periodic_solution


def phi(q, v, t):
    return -0.2 * v - 0.5 * q**3 + np.cos(t)


def _period_map(mu, x0):
    sol = solve_ivp(lambda t, y: [y[1], -y[0] + mu * phi(y[0], y[1], t)], (0, 2 * np.pi), x0, rtol=1e-12, atol=1e-13)
    return sol.y[:, -1]


@pytest.mark.parametrize("mu", [0.02, 0.005])
def test_forced_duffing_at_resonance_against_shooting(mu):
    sol = forced_periodic_solution(phi, 1.0, (0.5, 1.0))
    A_pred = np.array(sol.C)
    # full periodic solution: q(0) = C1 + O(mu), q'(0) = C2 + O(mu)
    x = fsolve(lambda x: _period_map(mu, x) - x, A_pred, xtol=1e-13)
    assert np.max(np.abs(x - A_pred)) < 30 * mu * np.max(np.abs(A_pred))
    # Floquet multipliers of the full solution vs 1 + mu P lambda
    h = 1e-6
    J = np.column_stack([(_period_map(mu, x + h * e) - _period_map(mu, x - h * e)) / (2 * h) for e in np.eye(2)])
    rho = np.sort_complex(np.linalg.eigvals(J))
    pred = np.sort_complex(sol.multipliers(mu))
    np.testing.assert_allclose(rho, pred, atol=10 * mu**2 + 1e-7)
    assert sol.stable == bool(np.all(np.abs(rho) < 1))


def test_cubic_amplitude_equation():
    """Closed form: at resonance A^2 [(3 c A^2 / 8)^2 + beta^2] = (F / 2)^2 with Phi = -2 beta v - c q^3 + F cos t."""
    sol = forced_periodic_solution(phi, 1.0, (0.5, 1.0))
    A, c, beta, F = sol.amplitude, 0.5, 0.1, 1.0
    assert A**2 * ((3 * c * A**2 / 8) ** 2 + beta**2) == pytest.approx((F / 2) ** 2, rel=1e-9)
