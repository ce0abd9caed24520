"""Bulgakov (1954), §5.12, eqs. (5.152)-(5.154): stationary amplitudes of point maps and their stability.

References: direct iteration of the explicit maps (solved for the next amplitude by hand) — convergence to the
fixed point when stable, departure when unstable; closed forms (5.141) and (5.166).
"""

from __future__ import annotations

import math

import pytest
import sympy as sp

from symosc import ParameterError
from symosc.nonlinear import implicit_map_cycle

a, b, c = sp.symbols("a b c")


@pytest.mark.parametrize(("F", "H", "stable"), [(0.1, 0.2, True), (0.3, 0.05, True), (-0.1, -0.2, False)])
def test_escapement_map_against_iteration(F, H, stable):
    """a^2/2 - b^2/2 - F(a+b) + H = 0 (5.141): b = -F + sqrt((a - F)^2 + 2H); A = H/(2F)."""
    cyc = implicit_map_cycle(a**2 / 2 - b**2 / 2 - F * (a + b) + H, (a, b), 0.9 * H / (2 * F))
    assert cyc.amplitudes[0] == pytest.approx(H / (2 * F), rel=1e-12)
    assert cyc.stable == stable
    x = cyc.amplitudes[0] * 1.01
    for _ in range(200):
        x = -F + math.sqrt((x - F) ** 2 + 2 * H)
    assert (abs(x - cyc.amplitudes[0]) < 1e-8) == stable
    # the slope of the explicit map at A equals the reported multiplier
    A, h = cyc.amplitudes[0], 1e-6
    slope = ((-F + math.sqrt((A + h - F) ** 2 + 2 * H)) - (-F + math.sqrt((A - h - F) ** 2 + 2 * H))) / (2 * h)
    assert cyc.multiplier == pytest.approx(slope, rel=1e-7)


def test_step_generator_two_half_maps():
    """b = delta a (5.161), c = delta b + S(1 + delta) (5.164): A = S/(1 - delta), B = S delta/(1 - delta) (5.166)."""
    S, delta = 0.7, 0.6
    cyc = implicit_map_cycle((b - delta * a, c - delta * b - S * (1 + delta)), (a, b, c), (1.0, 1.0))
    A, B = cyc.amplitudes
    assert A == pytest.approx(S / (1 - delta), rel=1e-12) and B == pytest.approx(S * delta / (1 - delta), rel=1e-12)
    assert cyc.multiplier == pytest.approx(delta**2, rel=1e-12) and cyc.stable
    x = 0.1
    for _ in range(200):
        x = delta * (delta * x) + S * (1 + delta)
    assert x == pytest.approx(A, rel=1e-12)


def test_bad_input():
    with pytest.raises(ParameterError):
        implicit_map_cycle((a - b,), (a, b), 1.0)
    with pytest.raises(ParameterError):
        implicit_map_cycle(a - b / 2 - 1, (a, b), "x")
