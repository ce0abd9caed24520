"""Exact transfer matrices and the python-control objects built from them, against hand-derived closed forms and a
direct numerical solve of ``(M s**2 + D s + K) X = E``."""

from __future__ import annotations

import warnings

import control as ct
import numpy as np
import pytest
import sympy as sp
from scipy import signal

from symosc.mechanics import LagrangianSystem
from symosc.models import n_link_pendulum
from symosc.numeric import bind
from symosc.symbols import dot

G = 9.81
VALUES = {"m1": 1, "m2": 1, "l1": 1, "l2": 1, "g": G}


def _double_pendulum_exact():
    """Hanging double pendulum, point masses, m = l = 1: M = [[2, 1], [1, 1]], K = diag(2g, g) (Goldstein,
    Classical Mechanics, §6.4); H = adj(M s^2 + K) / det with det = s^4 + 4 g s^2 + 2 g^2."""
    det = [1.0, 0.0, 4 * G, 0.0, 2 * G**2]
    nums = [[[1.0, 0.0, G], [-1.0, 0.0, 0.0]], [[-1.0, 0.0, 0.0], [2.0, 0.0, 2 * G]]]
    return nums, det


def test_double_pendulum_transfer_function_is_exact_and_warning_free():
    lin = n_link_pendulum(2, links="point").linearize()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        H = lin.to_transfer_function(values=VALUES)
    nums, det = _double_pendulum_exact()
    for i in range(2):
        for j in range(2):
            num, den = H.num[i][j], H.den[i][j]
            want = np.trim_zeros(np.array(nums[i][j]), "f")
            scale = max(np.max(np.abs(num)), np.max(np.abs(den)))
            assert len(den) == 5 and len(num) == len(want)  # no spurious leading terms
            np.testing.assert_allclose(den, det, rtol=1e-12, atol=0)
            np.testing.assert_allclose(num, want, rtol=1e-12, atol=0)
            # every coefficient the exact answer does not have is exactly zero (not 1e-15 round-off)
            assert all(c == 0 for c, w in zip(num, want, strict=True) if w == 0)
            assert all(abs(c) == 0 or abs(c) > 1e-12 * scale for c in (*num, *den))
    assert H.input_labels == ["Q_phi1", "Q_phi2"] and H.output_labels == ["phi1", "phi2"]


def test_symbolic_transfer_function_of_a_damped_oscillator():
    """m x'' + c x' + k x = Q: H = 1/(m s^2 + c s + k); the velocity output is s H."""
    x = sp.Symbol("x")
    m, c, k, s = sp.symbols("m c k s", positive=True)
    lin = LagrangianSystem(m * dot(x) ** 2 / 2, k * x**2 / 2, [x], dissipation=c * dot(x) ** 2 / 2).linearize()
    H = lin.transfer_function(s=s)
    assert sp.simplify(H[0, 0] - 1 / (m * s**2 + c * s + k)) == 0
    Hv = lin.transfer_function(velocities=True, s=s)
    assert sp.simplify(Hv[0, 0] - s / (m * s**2 + c * s + k)) == 0
    sys_ = lin.to_state_space(values={"m": 2, "c": 0.3, "k": 5}, velocities=True)
    assert sys_.output_labels == ["x_dot"] and sys_.state_labels == ["x", "x_dot"] and sys_.input_labels == ["Q_x"]


def _rotating_oscillator():
    """A mass on springs in a frame turning at Omega, with damping: gyroscopic coupling 2 m Omega."""
    x, y = sp.symbols("x y")
    m, k1, k2, c, W = sp.symbols("m k1 k2 c Omega", positive=True)
    T = m / 2 * ((dot(x) - W * y) ** 2 + (dot(y) + W * x) ** 2)
    V = (k1 * x**2 + k2 * y**2) / 2
    return LagrangianSystem(T, V, [x, y], dissipation=c * (dot(x) ** 2 + dot(y) ** 2) / 2).linearize()


@pytest.mark.parametrize("velocities", [False, True])
def test_mimo_gyroscopic_damped_against_a_direct_solve(velocities):
    lin = _rotating_oscillator()
    vals = {"m": 1.5, "k1": 40.0, "k2": 25.0, "c": 0.4, "Omega": 2.5}
    E = np.array([[1.0, 0.5], [0.0, 2.0]])
    H = lin.to_transfer_function(values=vals, inputs=E, outputs=["y", "x"], velocities=velocities)
    exact = lin.transfer_function(inputs=sp.Matrix(E), outputs=["y", "x"], values=vals, velocities=velocities)
    M, D, K = (np.array(bind(mat, vals), dtype=float) for mat in (lin.M, lin.D, lin.K))
    assert D[0, 1] == -D[1, 0] != 0  # gyroscopic terms present
    for s in (0.3j, 2.0 + 1.0j, 7.5j, -0.1 + 11j):
        X = np.linalg.solve(M * s**2 + D * s + K, E)
        want = X[[1, 0], :] * (s if velocities else 1)
        np.testing.assert_allclose(H(s), want, rtol=1e-12)
        got = np.array(exact.subs(sp.Symbol("s"), s).evalf(), dtype=complex)
        np.testing.assert_allclose(got, want, rtol=1e-12)
    assert H.input_labels == ["u0", "u1"] and H.output_labels == (["y_dot", "x_dot"] if velocities else ["y", "x"])


def test_scipy_backend_single_input_several_outputs():
    lin = n_link_pendulum(2, links="point").linearize()
    H = lin.to_transfer_function(values=VALUES, inputs=["phi2"], backend="scipy")
    assert isinstance(H, signal.TransferFunction)
    _, det = _double_pendulum_exact()
    np.testing.assert_allclose(H.den, det, rtol=1e-12)
    np.testing.assert_allclose(H.num, [[-1.0, 0, 0], [2.0, 0, 2 * G]], rtol=1e-12, atol=0)  # over det


def test_state_space_and_transfer_function_agree_on_the_frequency_response():
    lin = _rotating_oscillator()
    vals = {"m": 1.0, "k1": 10.0, "k2": 30.0, "c": 0.2, "Omega": 1.2}
    sys_ = lin.to_state_space(values=vals)
    H = lin.to_transfer_function(values=vals)
    w = np.array([0.5, 3.0, 5.7])
    np.testing.assert_allclose(ct.frequency_response(sys_, w).frdata, ct.frequency_response(H, w).frdata, rtol=1e-9)
    assert sys_.input_labels == H.input_labels == ["Q_x", "Q_y"]
