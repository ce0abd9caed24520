"""Linearization and modal analysis against closed forms."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from symosc import ModelError, t
from symosc.models import n_link_pendulum


def test_single_pendulum_frequency_is_sqrt_g_over_l():
    lin = n_link_pendulum(1).linearize()
    l, g = sp.symbols("l1 g", positive=True)
    assert sp.simplify(lin.K[0] / lin.M[0] - g / l) == 0
    omega = lin.natural_frequencies({"m1": 2.0, "l1": [0.5, 1.0, 4.0], "g": 9.81})
    np.testing.assert_allclose(omega[..., 0], np.sqrt(9.81 / np.array([0.5, 1.0, 4.0])), rtol=1e-14)


def test_rigid_link_frequency():
    lin = n_link_pendulum(1, links="rigid").linearize()
    m, lc, I, g = sp.symbols("m1 lc1 I1 g", positive=True)
    assert sp.simplify(lin.K[0] / lin.M[0] - m * g * lc / (I + m * lc**2)) == 0
    vals = {"m1": 1.3, "lc1": 0.4, "I1": 0.05, "g": 9.81}
    expected = np.sqrt(1.3 * 9.81 * 0.4 / (0.05 + 1.3 * 0.4**2))
    np.testing.assert_allclose(lin.natural_frequencies(vals), [expected], rtol=1e-14)


@pytest.mark.parametrize(("m1", "m2", "l1", "l2"), [(1, 1, 1, 1), (2.0, 0.3, 0.7, 1.9), (1e-3, 1e3, 1.0, 1e-2)])
def test_double_pendulum_closed_form(m1, m2, l1, l2):
    """omega^2 = g/(2 m1 l1 l2) [ (m1+m2)(l1+l2) -+ sqrt((m1+m2)((m1+m2)(l1+l2)^2 - 4 m1 l1 l2)) ]."""
    g = 9.81
    mu = m1 + m2
    root = np.sqrt(mu * (mu * (l1 + l2) ** 2 - 4 * m1 * l1 * l2))
    w2_high = g / (2 * m1 * l1 * l2) * (mu * (l1 + l2) + root)
    w2_low = g**2 * mu / (m1 * l1 * l2) / w2_high  # Vieta: no cancellation at extreme mass/length ratios
    w2 = np.array([w2_low, w2_high])
    omega = n_link_pendulum(2).linearize().natural_frequencies({"m1": m1, "m2": m2, "l1": l1, "l2": l2, "g": g})
    np.testing.assert_allclose(omega, np.sqrt(w2), rtol=1e-9)


def test_modes_are_mass_normalised_eigenvectors():
    lin = n_link_pendulum(4, links="rigid").linearize()
    rng = np.random.default_rng(1)
    vals = {s.name: rng.uniform(0.5, 2) for s in lin.parameters}
    omega, Phi = lin.modes(vals)
    M, D, K = lin.matrices(vals)
    np.testing.assert_allclose(Phi.T @ M @ Phi, np.eye(4), atol=1e-12)
    np.testing.assert_allclose(K @ Phi, M @ Phi * omega**2, rtol=1e-10, atol=1e-10)
    assert np.all(np.diff(omega) > 0)
    assert np.all(D == 0)


def test_vectorised_over_parameter_arrays():
    lin = n_link_pendulum(2).linearize()
    l1 = np.linspace(0.5, 2.0, 7)
    omega = lin.natural_frequencies({"m1": 1.0, "m2": 1.0, "l1": l1, "l2": 1.0, "g": 9.81})
    assert omega.shape == (7, 2)
    for i, li in enumerate(l1):
        np.testing.assert_allclose(
            omega[i], lin.natural_frequencies({"m1": 1.0, "m2": 1.0, "l1": li, "l2": 1.0, "g": 9.81}), rtol=1e-14
        )


def test_near_repeated_frequencies_long_chain():
    """Nearly equal frequencies: two identical, very weakly coupled pendulums (coupling 1e-8)."""
    import symosc
    from symosc.mechanics import LagrangianSystem

    x, y = sp.symbols("x y", real=True)
    T = (symosc.dot(x) ** 2 + symosc.dot(y) ** 2) / 2
    eps = sp.Rational(1, 10**8)
    V = (x**2 + y**2) / 2 + eps * (x - y) ** 2 / 2
    lin = LagrangianSystem(T, V, [x, y]).linearize()
    omega, Phi = lin.modes({})
    np.testing.assert_allclose(omega, [1.0, np.sqrt(1 + 2e-8)], rtol=1e-15)
    np.testing.assert_allclose(np.abs(Phi), np.full((2, 2), np.sqrt(0.5)), rtol=1e-7)


def test_inverted_pendulum_periodic_stiffness_and_instability():
    """Inverted + vertical pivot: K = (-g + a p^2 cos pt) C with one matrix C (Gribkov & Khokhlov eq. 6)."""
    lin = n_link_pendulum(3, links="rigid", inverted=True, pivot="vertical").linearize()
    K0, K1, p = lin.periodic_stiffness()
    a, g = sp.Symbol("a", nonnegative=True), sp.Symbol("g", positive=True)
    C = -K0 / g
    assert sp.simplify(K1 - a * p**2 * C) == sp.zeros(3, 3)
    hanging = n_link_pendulum(3, links="rigid").linearize()
    assert sp.simplify(hanging.K - g * C) == sp.zeros(3, 3)
    vals = {s.name: 1.0 for s in lin.parameters}
    assert np.all(lin.eigenvalues(vals) < 0)
    with pytest.raises(ModelError, match="statically unstable"):
        lin.natural_frequencies(vals)
    assert t in lin.K.free_symbols


def test_periodic_stiffness_rejects_constant_model():
    with pytest.raises(ModelError, match="not of the form"):
        n_link_pendulum(2).linearize().periodic_stiffness()
