"""Bulgakov (1954), §5.26–5.27 (design-amplitude linearization, shortened equations) and the arctan spring (§5.29).

References: closed forms derived by hand (arctan: omega^2 = 2(sqrt(1+a^2)-1)/a^2 by parts; Duffing with viscous
drag: eps = beta, omega^2 = 1 + 3 c a^2/4 - beta^2 (5.361); quadratic spring: q* from q* + q*^2 + a^2/2 = 0),
mpmath quadrature at 30 digits, and the true period of the arctan spring by numeric integration.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from symosc import ParameterError
from symosc.nonlinear import design_amplitude_linearization


@pytest.mark.parametrize("a", [0.1, 1.0, 3.0, 20.0])
def test_arctan_spring_frequency(a):
    lin = design_amplitude_linearization(lambda q, v: np.arctan(q), a)
    closed = math.sqrt(2 * (math.sqrt(1 + a * a) - 1)) / a
    with mpmath.workdps(30):
        J = (
            mpmath.quad(
                lambda u: mpmath.atan(a * mpmath.cos(u)) * mpmath.cos(u),
                [-mpmath.pi, -mpmath.pi / 2, 0, mpmath.pi / 2, mpmath.pi],
            )
            / mpmath.pi
        )
    assert lin.omega == pytest.approx(closed, rel=1e-12)
    assert lin.omega**2 == pytest.approx(float(J) / a, rel=1e-12)
    assert abs(lin.q_star) < 1e-12 and abs(lin.eps) < 1e-12
    assert abs(lin.damping(0.7 * a)) < 1e-12  # conservative: every amplitude is stationary (5.344)
    assert lin.frequency(a) == pytest.approx(lin.omega, rel=1e-12)  # omega = Psi(a*) (5.335)


def test_arctan_spring_against_true_period():
    """First-order averaging: the frequency of the actual oscillation of amplitude a agrees to a few per cent."""
    a = 2.0
    lin = design_amplitude_linearization(lambda q, v: np.arctan(q), a)

    def cross(t, y):
        return y[1]

    cross.direction = 1
    sol = solve_ivp(lambda t, y: [y[1], -math.atan(y[0])], (0, 40), [a, 0], events=cross, rtol=1e-11, atol=1e-12)
    period = sol.t_events[0][1] - sol.t_events[0][0]
    assert 2 * math.pi / period == pytest.approx(lin.omega, rel=0.03)


def test_duffing_with_viscous_drag():
    beta, c, a = 0.05, 0.4, 1.5
    lin = design_amplitude_linearization(lambda q, v: q + c * q**3 + 2 * beta * v, a)
    assert lin.eps == pytest.approx(beta, rel=1e-10)
    assert lin.omega == pytest.approx(math.sqrt(1 + 0.75 * c * a * a - beta**2), rel=1e-10)
    assert lin.damping(0.3) == pytest.approx(beta, rel=1e-10)  # Phi = beta for every amplitude (5.359)


def test_quadratic_spring_center_shift():
    a = 0.5
    lin = design_amplitude_linearization(lambda q, v: q + q**2, a)
    assert lin.q_star == pytest.approx((-1 + math.sqrt(1 - 2 * a * a)) / 2, rel=1e-10)
    # omega^2 = 1 + 2 q*  (first harmonic of (q* + a cos u)^2 is 2 q* a cos u)
    assert lin.omega**2 == pytest.approx(1 + 2 * lin.q_star, rel=1e-10)


def test_bad_input():
    with pytest.raises(ParameterError):
        design_amplitude_linearization(lambda q, v: q, -1.0)
    with pytest.raises(ParameterError):
        design_amplitude_linearization("q", 1.0)


def test_sympy_expression_force_matches_closed_form_and_pickles():
    """f = arctan(q) as a SymPy expression: omega**2 = 2 (sqrt(1 + a**2) - 1) / a**2 (Bulgakov (1954), §5.29)."""
    import pickle

    import sympy as sp

    q = sp.Symbol("q")
    a = 1.5
    lin = design_amplitude_linearization(sp.atan(q), a)
    assert abs(lin.omega - np.sqrt(2 * (np.sqrt(1 + a * a) - 1)) / a) < 1e-10
    back = pickle.loads(pickle.dumps(lin))
    assert back.omega == lin.omega and back.frequency(1.0) == lin.frequency(1.0)


def test_expression_with_parameters_needs_numbers():
    import sympy as sp

    q, k = sp.symbols("q k")
    with pytest.raises(ParameterError, match="variables"):
        design_amplitude_linearization(k * sp.atan(q), 1.0)
