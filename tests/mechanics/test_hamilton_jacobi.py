"""Hamilton-Jacobi separation and action variables vs textbook closed forms (Goldstein §10.7-10.8; Landau &
Lifshitz §49-50) and vs the complete elliptic integral for the pendulum."""

from __future__ import annotations

import mpmath
import pytest
import sympy as sp

from symosc import ModelError, t
from symosc.mechanics import action_variable, action_variable_numeric, separate_hamilton_jacobi

q, p = sp.symbols("q p", real=True)
r, th, pr, pth = sp.symbols("r theta p_r p_theta", positive=True)
m, w, k, g, l = sp.symbols("m omega k g l", positive=True)
h = sp.Symbol("h", real=True)
E = sp.Symbol("E", negative=True)


def test_oscillator_action_and_frequency():
    av = action_variable(p**2 / (2 * m) + m * w**2 * q**2 / 2, q, p, h)
    assert av.action == h / w
    assert av.frequency == w and sp.simplify(av.period - 2 * sp.pi / w) == 0
    assert av.energy == av.action_symbol * w


def test_kepler_radial_action_and_degenerate_frequencies():
    """J_r = -p_theta + k sqrt(m / (-2E)); E = -m k^2 / (2 (J_r + J_theta)^2) (Goldstein, eq. (10.137))."""
    sep = separate_hamilton_jacobi(pr**2 / (2 * m) + pth**2 / (2 * m * r**2) - k / r, [r, th], [pr, pth], E)
    a = sep.constants[th]
    Hr = pr**2 / (2 * m) + a**2 / (2 * m * r**2) - k / r
    av = action_variable(Hr.xreplace({a: sp.Symbol("L", positive=True)}), r, pr, E)
    L = sp.Symbol("L", positive=True)
    assert sp.simplify(av.action - (-L + k * sp.sqrt(m / (-2 * E)))) == 0
    assert sp.simplify(av.energy - (-m * k**2 / (2 * (av.action_symbol + L) ** 2))) == 0
    # Kepler's third law: period 2 pi k sqrt(m) / (-2E)^(3/2), independent of L
    assert sp.simplify(av.period - 2 * sp.pi * k * sp.sqrt(m) / (-2 * E) ** sp.Rational(3, 2)) == 0
    # the separated momentum is dW/dr
    assert sp.simplify(sep.momenta[pr] ** 2 - 2 * m * (E + k / r - a**2 / (2 * m * r**2))) == 0


def test_pendulum_libration_elliptic_period():
    """Period of a libration 4 sqrt(l/g) K(k^2), k = sin(a/2) (Landau & Lifshitz, §11, problem 1); and the
    action's derivative dJ/dh = period / (2 pi)."""
    H = p**2 / (2 * m * l**2) - m * g * l * sp.cos(q)
    vals = {"m": 1.3, "g": 9.81, "l": 0.7}
    amp = 2.0
    energy = -1.3 * 9.81 * 0.7 * mpmath.cos(amp)
    J, T = action_variable_numeric(H, q, p, float(energy), vals, (-amp + 0.01, amp - 0.01))
    with mpmath.workdps(30):
        ref = 4 * mpmath.sqrt(mpmath.mpf("0.7") / mpmath.mpf("9.81")) * mpmath.ellipk(mpmath.sin(amp / 2) ** 2)
    assert abs(T - ref) / ref < 1e-12
    # J'(h) = T / (2 pi) by a finite difference of the numeric action
    dh = 1e-6
    J2, _ = action_variable_numeric(H, q, p, float(energy) + dh, vals, (-amp - 0.01, amp + 0.01))
    assert abs((J2 - J) / dh - T / (2 * mpmath.pi)) / (T / (2 * mpmath.pi)) < 1e-5


def test_bad_input():
    with pytest.raises(ModelError, match="no closed form"):
        action_variable(p**2 / 2 - sp.cos(q), q, p, h)
    with pytest.raises(ModelError, match="quadratic in p"):
        action_variable(p**4 + q**2, q, p, h)
    with pytest.raises(ModelError, match="separation order"):
        separate_hamilton_jacobi(pr**2 + pth**2 + r * th, [r, th], [pr, pth])
    with pytest.raises(ModelError, match="time"):
        separate_hamilton_jacobi(p**2 + q**2 * t, [q], [p])
