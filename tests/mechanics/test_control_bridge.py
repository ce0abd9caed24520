"""LinearModel -> python-control / SciPy, checked against closed-form transfer functions and responses."""

from __future__ import annotations

import sys

import control as ct
import numpy as np
import pytest
import sympy as sp
from scipy import signal

from symosc.errors import ModelError, ParameterError
from symosc.mechanics import LagrangianSystem
from symosc.models import n_link_pendulum
from symosc.symbols import dot


def _oscillator():
    """m x'' + c x' + k x = u from T = m x'^2/2, V = k x^2/2, R = c x'^2/2."""
    x = sp.Symbol("x")
    m, c, k = sp.symbols("m c k", positive=True)
    system = LagrangianSystem(m * dot(x) ** 2 / 2, k * x**2 / 2, [x], dissipation=c * dot(x) ** 2 / 2)
    return system.linearize({x: 0})


VALUES = {"m": 2.0, "c": 0.6, "k": 50.0}


def test_frequency_response_matches_closed_form():
    H = _oscillator().to_transfer_function(values=VALUES)
    assert isinstance(H, ct.TransferFunction)
    w = np.array([0.3, 2.0, 5.0, 7.0, 20.0])
    m, c, k = VALUES["m"], VALUES["c"], VALUES["k"]
    exact = 1.0 / (k - m * w**2 + 1j * c * w)
    np.testing.assert_allclose(H(1j * w), exact, rtol=1e-12)
    # Bode data in one line, same numbers
    resp = ct.frequency_response(H, w)
    np.testing.assert_allclose(resp.magnitude.ravel(), np.abs(exact), rtol=1e-12)


def test_step_response_matches_closed_form():
    sys_ = _oscillator().to_state_space(values=VALUES)
    t = np.linspace(0.0, 6.0, 301)
    res = ct.step_response(sys_, t)
    m, c, k = VALUES["m"], VALUES["c"], VALUES["k"]
    wn, zeta = np.sqrt(k / m), c / (2 * np.sqrt(k * m))
    wd = wn * np.sqrt(1 - zeta**2)
    exact = (1 - np.exp(-zeta * wn * t) * (np.cos(wd * t) + zeta / np.sqrt(1 - zeta**2) * np.sin(wd * t))) / k
    np.testing.assert_allclose(res.outputs.ravel(), exact, rtol=0, atol=1e-10)


def test_double_pendulum_poles_and_outputs():
    """Equal masses and lengths: omega^2 = (g/l)(2 -+ sqrt 2) (e.g. Goldstein, Classical Mechanics, §6.4)."""
    lin = n_link_pendulum(2).linearize()
    g, l = 9.81, 0.7
    values = {"m1": 1.3, "m2": 1.3, "l1": l, "l2": l, "g": g}
    sys_ = lin.to_state_space(values=values, inputs=["phi2"], outputs=[0, "phi2"])
    assert (sys_.ninputs, sys_.noutputs, sys_.nstates) == (1, 2, 4)
    w = np.sort(np.abs(ct.poles(sys_).imag))[::2]
    np.testing.assert_allclose(w, np.sqrt(g / l * np.array([2 - np.sqrt(2), 2 + np.sqrt(2)])), rtol=1e-12)
    vel = lin.to_state_space(values=values, outputs=["phi1"], velocities=True)
    np.testing.assert_array_equal(vel.C, [[0, 0, 1, 0]])


def test_scipy_backend_and_missing_control(monkeypatch):
    lin = _oscillator()
    ref = lin.to_state_space(values=VALUES)
    sc = lin.to_state_space(values=VALUES, backend="scipy")
    assert isinstance(sc, signal.StateSpace)
    for a, b in zip((sc.A, sc.B, sc.C, sc.D), (ref.A, ref.B, ref.C, ref.D), strict=True):
        np.testing.assert_array_equal(a, b)
    monkeypatch.setitem(sys.modules, "control", None)  # as if python-control were not installed
    auto = lin.to_transfer_function(values=VALUES)
    assert isinstance(auto, signal.TransferFunction)
    np.testing.assert_allclose(auto.den, [1.0, 0.3, 25.0], rtol=1e-12)  # s^2 + (c/m) s + k/m
    np.testing.assert_allclose(auto.num, [0.5], rtol=1e-12)
    with pytest.raises(ImportError, match="symosc\\[control\\]"):
        lin.to_state_space(values=VALUES, backend="control")
    with pytest.raises(ParameterError, match="one input"):
        n_link_pendulum(2).linearize().to_transfer_function(
            values={"m1": 1, "m2": 1, "l1": 1, "l2": 1, "g": 9.81}, backend="scipy"
        )


def test_bad_input_is_named():
    lin = _oscillator()
    with pytest.raises(ParameterError, match="missing values for: c, k"):
        lin.to_state_space(values={"m": 1.0})
    with pytest.raises(ParameterError, match="'y' is not a coordinate"):
        lin.to_state_space(values=VALUES, inputs=["y"])
    vib = n_link_pendulum(1, inverted=True, pivot="vertical").linearize()
    with pytest.raises(ModelError, match="not time-invariant"):
        vib.to_state_space(values={"m1": 1, "l1": 1, "g": 9.81, "a": 0.1, "p": 50})
    still = vib.to_state_space(values={"m1": 1, "l1": 1, "g": 9.81, "a": 0, "p": 50})  # no excitation: LTI
    np.testing.assert_allclose(np.sort(ct.poles(still).real), [-np.sqrt(9.81), np.sqrt(9.81)], rtol=1e-12)


def test_operational_transfer_function():
    """A first-order lag k/(T p + 1): |H(i w)| = k / sqrt(1 + w^2 T^2); delays do not convert."""
    from symosc.operational import to_transfer_function

    p, k, T = sp.symbols("p k T", positive=True)
    H = to_transfer_function(k / (T * p + 1), p, {"k": 3, "T": 0.2})
    w = np.array([0.1, 5.0, 40.0])
    np.testing.assert_allclose(np.abs(H(1j * w)), 3 / np.sqrt(1 + (0.2 * w) ** 2), rtol=1e-13)
    with pytest.raises(ModelError, match="not rational"):
        to_transfer_function(sp.exp(-p) / (p + 1), p)
    with pytest.raises(ParameterError, match="free symbols"):
        to_transfer_function(k / (T * p + 1), p)
