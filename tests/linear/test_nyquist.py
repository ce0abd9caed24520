"""Nyquist criterion (Bulgakov (1954), §10.7–10.9, T13) against direct root counts of Δ0 + M (numpy.roots), and
stability margins against python-control."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.errors import ModelError
from symosc.linear import nyquist, stability_margins


def _count(closed, inside):
    r = np.roots(closed)
    return int(np.sum(inside(r)))


@st.composite
def loops(draw):
    """Random proper loops with stable, unstable, integrating (0, double 0) and oscillating (±iω) links."""
    rng = np.random.default_rng(draw(st.integers(0, 2**31)))
    poles = list(rng.uniform(-3, 2, draw(st.integers(0, 3))))
    kind = draw(st.sampled_from(["none", "integrator", "double", "oscillator"]))
    poles += {"none": [], "integrator": [0.0], "double": [0.0, 0.0], "oscillator": [1.5j, -1.5j]}[kind]
    if not poles:
        poles = [-1.0]
    den = np.real(np.poly(poles))
    zeros = list(rng.uniform(-3, 1, draw(st.integers(0, len(poles) - 1))))
    num = (
        draw(st.sampled_from([0.3, 1.0, 4.0, -2.0])) * np.real(np.poly(zeros))
        if zeros
        else np.array([draw(st.sampled_from([0.3, 1.0, 4.0, -2.0]))])
    )
    return num, den


@settings(max_examples=40, deadline=None)
@given(loops(), st.sampled_from([0.0, 0.2]))
def test_count_equals_direct_root_count(loop, alpha):
    num, den = loop
    closed = np.polyadd(den, num)
    r = np.roots(closed)
    if np.any(np.abs(r.real + alpha) < 1e-6):
        with pytest.raises(ModelError):
            nyquist(num, den, alpha=alpha)
        return
    if np.any(np.abs(np.roots(den).real + alpha) < 1e-9) and alpha:
        return  # a pole on the shifted line: covered by the indentation test below
    res = nyquist(num, den, alpha=alpha)
    assert res.closed_loop_roots == _count(closed, lambda z: z.real > -alpha)
    assert res.open_loop_poles == _count(den, lambda z: z.real > -alpha + 1e-9)
    assert res.stable == (res.closed_loop_roots == 0)


@pytest.mark.parametrize("theta_deg", [10, 25, 40])
def test_feldbaum_sector(theta_deg):
    """§10.9: roots outside the sector D = ρ(−sin θ ± i cos θ) have log decrement below π tan θ."""
    theta = np.radians(theta_deg)
    num, den = [3.0], np.real(np.poly([-0.5 + 2j, -0.5 - 2j, -3.0]))
    closed = np.polyadd(den, num)
    res = nyquist(num, den, sector_angle=theta)
    direct = _count(closed, lambda z: np.abs(np.angle(-z)) > np.pi / 2 - theta)
    assert res.closed_loop_roots == direct


def test_t13_feldbaum_numbers():
    """§10.9 (T13): θ = 25° gives tan θ = 0.466, π tan θ = 1.46; the printed decrement 0.232 is e^{-1.46} of the
    rounded exponent, the unrounded e^{-π tan θ} is 0.2311."""
    t = np.tan(np.radians(25))
    assert round(t, 3) == 0.466 and round(np.pi * t, 2) == 1.46
    assert round(np.exp(-1.46), 3) == 0.232 and round(np.exp(-np.pi * t), 4) == 0.2311


def test_neutral_links_need_indentation():
    with pytest.raises(ModelError, match="indentation"):
        nyquist([1], [1, 1, 0], indentation=None)
    with pytest.raises(ModelError, match="proper"):
        nyquist([1, 0, 0], [1, 1])
    # a double integrator with a lead: stable closed loop D^2 + 2D + 1 ... indented twice
    res = nyquist([2, 1], [1, 0, 0])
    assert res.closed_loop_roots == 0 and len(res.indented_poles) == 2


@pytest.mark.parametrize(
    "num, den",
    [([2.0], [1, 3, 3, 1]), ([10.0], [1, 6, 11, 6]), ([1.0, 2.0], [1, 2, 3, 4, 0]), ([5.0], [1, 2, 2, 0])],
)
def test_margins_vs_python_control(num, den):
    import control

    gm, pm, _wpc, _wgc = control.margin(control.tf(num, den))
    m = stability_margins(num, den)
    assert np.isclose(m.gain_margin, gm, rtol=1e-6) or (np.isinf(gm) and np.isinf(m.gain_margin))
    assert np.isclose(m.phase_margin, pm, rtol=1e-6, atol=1e-6) or (np.isinf(pm) and np.isinf(m.phase_margin))
