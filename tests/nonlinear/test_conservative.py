"""Conservative one-degree-of-freedom systems (Bulgakov §5.2): equilibria, separatrix slopes, periods.

References: the pendulum's elliptic-integral periods (mpmath.ellipk) and numeric integration of the equation of
motion (SciPy), never the quadrature under test.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc.errors import ModelError
from symosc.nonlinear import classify_equilibrium, libration_period, rotation_period

q = sp.Symbol("q")


def test_pendulum_equilibria_and_separatrix_slopes_5_2():
    """§5.2: V = -cos q. q = 0 is a center with omega = 1; q = pi a saddle whose separatrix q' = 2 cos(q/2) has
    slope -sin(pi/2) = -1 (and +1 for the other branch) there."""
    c = classify_equilibrium(-sp.cos(q), q, 0)
    assert c.kind == "center" and c.frequency == 1
    s = classify_equilibrium(-sp.cos(q), q, sp.pi)
    assert s.kind == "saddle" and s.separatrix_slopes == (-1, 1)
    slope = sp.diff(2 * sp.cos(q / 2), q).subs(q, sp.pi)
    assert slope in s.separatrix_slopes
    # position-dependent inertia m(q) = 2 + cos q scales omega^2 = V''/m
    k = sp.Symbol("k", positive=True)
    e = classify_equilibrium(k * q**2 / 2, q, 0, m=2 + sp.cos(q))
    assert sp.simplify(e.frequency - sp.sqrt(k / 3)) == 0
    assert classify_equilibrium(q**4, q, 0).kind == "degenerate"
    with pytest.raises(ModelError, match="not an equilibrium"):
        classify_equilibrium(-sp.cos(q), q, 1)


@pytest.mark.parametrize("amplitude", [0.3, 1.0, 2.5])
def test_libration_period_against_elliptic_integral(amplitude):
    """T = 4 K(sin^2(theta0/2)) for the pendulum with amplitude theta0."""
    E = -float(np.cos(amplitude))
    T = libration_period(-sp.cos(q), q, E, 0.0)
    assert T == pytest.approx(float(4 * mpmath.ellipk(mpmath.sin(mpmath.mpf(amplitude) / 2) ** 2)), rel=1e-12)


def test_rotation_period_against_integration():
    """E = 3 > max V = 1: time for q to advance by 2 pi, against solve_ivp with an event."""
    T = rotation_period(-sp.cos(q), q, 3.0, 2 * sp.pi)
    v0 = np.sqrt(2 * (3.0 + 1.0))  # at q = 0, V = -1

    def passed(t, y):
        return y[0] - 2 * np.pi

    passed.terminal = True
    sol = solve_ivp(lambda t, y: [y[1], -np.sin(y[0])], (0, 10), [0.0, v0], events=passed, rtol=1e-12, atol=1e-12)
    assert T == pytest.approx(sol.t_events[0][0], rel=1e-9)
    with pytest.raises(ModelError, match="libration"):
        rotation_period(-sp.cos(q), q, 0.5, 2 * sp.pi)


def test_libration_with_variable_inertia_against_integration():
    """m(q) = 1 + q^2/2, V = q^2/2: the Lagrange equation m q'' + m' q'^2/2 + V' = 0 integrated numerically."""
    m = 1 + q**2 / 2
    T = libration_period(q**2 / 2, q, 0.5, 0.0, m=m)  # turning points ±1

    def rhs(t, y):
        x, v = y
        return [v, -(x * v**2 / 2 + x) / (1 + x**2 / 2)]

    def crossing(t, y):
        return y[1]

    crossing.direction = 1  # v goes - to + at the left turning point: half a period after the start at q = 1
    sol = solve_ivp(rhs, (0, 20), [1.0, 0.0], events=crossing, rtol=1e-12, atol=1e-12, dense_output=True)
    assert T == pytest.approx(2 * sol.t_events[0][0], rel=1e-8)
