"""Heaviside response series of a system with delay (Bulgakov (1954), §4.14) against a method-of-steps integration.

The reference integrates y'' = [x(u) - l11 y' - l21 y - l12 y'(u-1) - l22 y(u-1)]/l01 with solve_ivp piece by piece
between the break points (multiples of the delay and the pulse end), the delayed values read from the dense output
of the earlier pieces: an independent time-domain computation.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from symosc.errors import ParameterError
from symosc.linear import delay_response_series

L = (1.0, 0.6, 0.5, 0.0, 0.3, 0.4)


def _method_of_steps(l, y0, v0, force, breaks, u_end):
    l01, l11, l21, _, l12, l22 = l
    pieces = []

    def hist(s, start=None):
        """Solution at s; with ``start``, from the piece beginning there (the delayed image of the current piece,
        so values at a break point are taken from the right)."""
        if s < 0 or (start is not None and start < -1e-12):
            return np.zeros(2)
        for a, b, sol in pieces:
            if (abs(a - start) < 1e-9) if start is not None else (a <= s <= b):
                return sol(min(max(s, a), b))
        raise AssertionError(s)

    pts = sorted({0.0, u_end, *[b for b in breaks if 0 < b < u_end]})
    z = np.array([y0, v0])
    for a, b in itertools.pairwise(pts):
        mid = 0.5 * (a + b)
        xf = force(mid)

        def rhs(s, w, xf=xf, a=a):
            yd, vd = hist(s - 1, a - 1)
            return [w[1], (xf - l11 * w[1] - l21 * w[0] - l12 * vd - l22 * yd) / l01]

        sol = solve_ivp(rhs, (a, b), z, dense_output=True, rtol=1e-11, atol=1e-13, method="DOP853")
        pieces.append((a, b, sol.sol))
        z = sol.y[:, -1]
    return lambda s: np.array([hist(si)[0] for si in np.atleast_1d(s)])


@pytest.fixture(scope="module")
def series():
    return delay_response_series(*L, im_max=60)


def test_impulse_series_vs_method_of_steps(series):
    """(4.114) from rest: y(0+) = 0, y'(0+) = 1/l01; the truncated series agrees for u ≥ 1.5."""
    ref = _method_of_steps(L, 0.0, 1 / L[0], lambda s: 0.0, np.arange(1, 9), 8.0)
    u = np.linspace(1.5, 8, 14)
    assert np.allclose(series.impulse(u), ref(u), atol=1e-6)
    assert series.tail(1.5) < 1e-3
    assert all(series.roots.real < 0)  # the example is stable


def test_pulse_and_step_series_vs_method_of_steps(series):
    """(4.117)–(4.118): a rectangular pulse of unit area and length b = 0.5, and the static gain 1/f(0)."""
    b = 0.5
    breaks = sorted({*np.arange(1, 9), *(np.arange(0, 9) + b)})
    ref = _method_of_steps(L, 0.0, 0.0, lambda s: 1 / b if s < b else 0.0, breaks, 8.0)
    u = np.linspace(1.5, 8, 14)
    assert np.allclose(series.pulse(u, b), ref(u), atol=1e-6)
    assert series.step(200.0)[0] == pytest.approx(1 / (L[2] + L[5]), abs=1e-9)


def test_more_roots_converge_closer_to_zero():
    """The error at u = 0.6 decreases when more roots are kept (slow convergence near u = 0, §4.14)."""
    ref = _method_of_steps(L, 0.0, 1 / L[0], lambda s: 0.0, [1.0], 0.6)(0.6)[0]
    errs = [abs(delay_response_series(*L, im_max=m).impulse(0.6)[0] - ref) for m in (20.0, 80.0)]
    assert errs[1] < errs[0] / 3


def test_bad_input():
    with pytest.raises(ParameterError, match="l01"):
        delay_response_series(0, 1, 1, 0, 1, 1)
    with pytest.raises(ParameterError, match="neutral"):
        delay_response_series(1, 1, 1, 2, 1, 1)


def test_double_root_term_at_the_andronov_maier_optimum():
    """(4.113): at the optimum of §4.17 (ρ = 0.2) -s* is a double root; the series with the double-root term
    agrees with the method of steps."""
    import sympy as sp

    from symosc.nonlinear import andronov_maier_optimum

    sigma = float(andronov_maier_optimum(sp.Rational(1, 5))["sigma"])
    l = (1.0, 0.2, 0.0, 0.0, 0.0, sigma)
    r = delay_response_series(*l, im_max=30)
    assert r.multiplicities[0] == 2 and r.roots[0].real == pytest.approx(-(1.1 - np.sqrt(1.01)), abs=1e-9)
    ref = _method_of_steps(l, 0.0, 1.0, lambda s: 0.0, np.arange(1, 7), 6.0)
    u = np.linspace(1.5, 6, 10)
    assert np.allclose(r.impulse(u), ref(u), atol=1e-5)
