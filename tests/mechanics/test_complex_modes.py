"""Damped/gyroscopic modes (quadratic eigenproblem) and the Floquet route of a LinearModel.

References: the first-order matrix ``[[0, I], [-M^-1 K, -M^-1 D]]`` built here and solved with
``scipy.linalg.eig``; the rotating-frame isotropic oscillator (roots ``+-i(omega0 +- Omega)``); the damped
oscillator; Mathieu characteristic values (stability chart, Bulgakov (1954), §11.6) and direct numeric
integration of the second-order equations with ``solve_ivp``.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg
import sympy as sp
from scipy.integrate import solve_ivp

from symosc import ModelError, ParameterError, dot, t
from symosc.mechanics import LagrangianSystem, LinearModel, complex_modes
from symosc.periodic import mathieu_a, mathieu_b


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_roots_match_first_order_matrix(seed):
    rng = np.random.default_rng(seed)
    n = 4
    X = rng.normal(size=(n, n))
    M = X @ X.T + n * np.eye(n)
    D = rng.normal(size=(n, n))
    K = rng.normal(size=(n, n)) + 5 * np.eye(n)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, D)]])
    ref = scipy.linalg.eig(A, right=False)
    res = complex_modes(M, D, K)
    # match each root to the nearest reference root
    for s in res.eigenvalues:
        assert np.min(np.abs(ref - s)) < 1e-10 * max(1, abs(s))
    assert res.eigenvalues.size == 2 * n
    assert res.residual < 1e-12
    for k, s in enumerate(res.eigenvalues):
        phi = res.vectors[:, k]
        np.testing.assert_allclose((M * s**2 + D * s + K) @ phi, 0, atol=1e-10)


def test_rotating_frame_oscillator_from_lagrangian():
    """Isotropic oscillator seen from a frame rotating at Omega: roots s = +-i (omega0 +- Omega)."""
    x, y = sp.symbols("x y", real=True)
    m, k, W = sp.symbols("m k Omega", positive=True)
    T = m / 2 * ((dot(x) - W * y) ** 2 + (dot(y) + W * x) ** 2)
    V = k * (x**2 + y**2) / 2
    lin = LagrangianSystem(T, V, [x, y]).linearize()
    assert any(e != 0 for e in lin.D)  # Coriolis (gyroscopic) terms present
    vals = {"m": 2.0, "k": 18.0, "Omega": 0.7}  # omega0 = 3
    res = lin.complex_modes(vals)
    np.testing.assert_allclose(res.frequencies, [3 - 0.7, 3 + 0.7], rtol=1e-12)
    np.testing.assert_allclose(res.eigenvalues.real, 0, atol=1e-12)
    assert res.stability == "marginally stable"
    # above omega0 the static stiffness k - m Omega^2 is negative yet gyroscopic coupling keeps the roots imaginary
    res = lin.complex_modes({**vals, "Omega": 4.0})
    np.testing.assert_allclose(np.sort(np.abs(res.eigenvalues.imag))[::2], [1.0, 7.0], rtol=1e-12)
    with pytest.raises(ModelError):  # the undamped symmetric analysis refuses the same model
        lin.natural_frequencies({**vals, "Omega": 4.0})


def test_damped_oscillator_closed_form():
    w0, zeta = 3.0, 0.2
    res = complex_modes([[1.0]], [[2 * zeta * w0]], [[w0**2]])
    expected = -zeta * w0 + 1j * w0 * np.sqrt(1 - zeta**2)
    np.testing.assert_allclose(res.eigenvalues, [expected, expected.conjugate()], rtol=1e-14)
    np.testing.assert_allclose(res.damping_ratios, [zeta, zeta], rtol=1e-13)
    np.testing.assert_allclose(res.natural_frequencies, [w0], rtol=1e-14)
    assert res.stability == "asymptotically stable"
    assert "asymptotically stable" in repr(res)


def test_bad_input():
    with pytest.raises(ParameterError):
        complex_modes(np.eye(2), np.eye(3), np.eye(2))
    with pytest.raises(ParameterError):
        complex_modes(np.eye(2), np.eye(2), [[np.nan, 0], [0, 1]])
    with pytest.raises(ModelError):
        complex_modes(np.zeros((2, 2)), np.eye(2), np.eye(2))


def _mathieu_model(damping=0):
    a, q, c = sp.symbols("a q c", real=True)
    M = sp.Matrix([[1]])
    return LinearModel(
        M=M,
        D=sp.Matrix([[c * damping]]),
        K=sp.Matrix([[a - 2 * q * sp.cos(2 * t)]]),
        f=sp.zeros(1, 1),
        coordinates=(sp.Symbol("x"),),
    )


@pytest.mark.parametrize("q", [0.5, 1.5])
def test_mathieu_stability_from_characteristic_values(q):
    """x'' + (a - 2q cos 2t) x = 0: stable for a0 < a < b1 and a1 < a < b2, unstable for b1 < a < a1, b2 < a < a2."""
    lin = _mathieu_model()
    a0, a1, a2 = (float(mathieu_a(n, q)) for n in (0, 1, 2))
    b1, b2 = (float(mathieu_b(n, q)) for n in (1, 2))
    cases = [
        ((a0 + b1) / 2, True),
        ((b1 + a1) / 2, False),
        ((a1 + b2) / 2, True),
        ((b2 + a2) / 2, False),
        (a0 - 0.3, False),
    ]
    for a, stable in cases:
        res = lin.monodromy({"a": a, "q": q})
        assert res.is_stable == stable, (a, q, res)
        assert res.period == pytest.approx(np.pi)


def test_damped_periodic_model_matches_direct_integration():
    """Damped Mathieu: monodromy columns equal solve_ivp solutions over one period started from unit data."""
    lin = _mathieu_model(damping=1)
    vals = {"a": 1.0, "q": 0.6, "c": 0.1}
    res = lin.monodromy(vals)
    assert not res.reversor_used

    def rhs(tt, y):
        return [y[1], -0.1 * y[1] - (1.0 - 1.2 * np.cos(2 * tt)) * y[0]]

    cols = [solve_ivp(rhs, (0, np.pi), y0, rtol=1e-12, atol=1e-14).y[:, -1] for y0 in ([1, 0], [0, 1])]
    np.testing.assert_allclose(res.monodromy, np.array(cols).T, rtol=1e-8, atol=1e-10)


def test_monodromy_needs_periodic_stiffness():
    lin = _mathieu_model().__class__(
        M=sp.Matrix([[1]]), D=sp.zeros(1, 1), K=sp.Matrix([[2]]), f=sp.zeros(1, 1), coordinates=(sp.Symbol("x"),)
    )
    with pytest.raises(ModelError):
        lin.monodromy({})
