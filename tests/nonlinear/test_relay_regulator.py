"""Bulgakov (1954), §12.13 (T17): periodic boundary of the relay position regulator, (12.188)-(12.193), (12.210).

Reference: numpy roots of Delta(E) = E^3 + (gamma h + M) E^2 + (beta gamma h + alpha) E + gamma h at the returned
gains (a pair on the imaginary axis, the third root -kappa) and just beside them (the pair crosses the axis);
the ideal relay's first harmonic by quadrature.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from symosc import ParameterError
from symosc.nonlinear import relay_regulator_boundary


def _roots(h, alpha, beta, gamma, M):
    return np.roots([1.0, gamma * h + M, beta * gamma * h + alpha, gamma * h])


@pytest.mark.parametrize("seed", range(6))
def test_boundary_gains_put_a_pair_on_the_axis(seed):
    rng = np.random.default_rng(seed)
    alpha, beta, gamma, M = rng.uniform(0.02, 0.4), rng.uniform(0.2, 2.0), rng.uniform(0.3, 3.0), rng.uniform(0.0, 0.4)
    res = relay_regulator_boundary(alpha, beta, gamma, M)
    # as many crossings of the imaginary axis over h > 0 as returned gains (scan of max Re of the roots)
    grid = np.geomspace(1e-4, 1e4, 4001)
    top = np.array([np.max(_roots(h, alpha, beta, gamma, M).real) for h in grid])
    crossings = grid[:-1][np.sign(top[:-1]) != np.sign(top[1:])]
    assert len(crossings) == len(res.gains)
    for h, w, k in zip(res.gains, res.omegas, res.kappas, strict=True):
        r = _roots(h, alpha, beta, gamma, M)
        np.testing.assert_allclose(np.sort(np.abs(r.imag))[1:], [w, w], rtol=1e-8)
        assert np.min(np.abs(r + k)) < 1e-9 * max(1, k)
        assert np.max(np.abs(r.real[np.abs(r.imag) > 0])) < 1e-8
        # beside the gain the oscillatory pair leaves the axis: max Re changes sign across h
        lo, hi = (np.max(_roots(h * f, alpha, beta, gamma, M).real) for f in (1 - 1e-4, 1 + 1e-4))
        assert lo * hi < 0


def test_no_boundary_when_discriminant_negative():
    # R^2 < 0 between the parabola's branches: alpha = 0.5, M beta = 0.5 gives R^2 = 0.25 - 1.5 + 0.25 < 0
    assert relay_regulator_boundary(0.5, 0.5, 1.0, 1.0).gains == ()


def test_relay_amplitude_from_first_harmonic():
    res = relay_regulator_boundary(0.2, 0.5, 1.0, 0.3)
    J = quad(lambda u: math.copysign(1.0, math.cos(u)) * math.cos(u), -math.pi, math.pi, points=[-math.pi / 2,
             math.pi / 2])[0] / math.pi  # fmt: skip
    for h, b in zip(res.gains, res.relay_amplitudes(), strict=True):
        assert h * b == pytest.approx(J, rel=1e-10)
    with pytest.raises(ParameterError):
        relay_regulator_boundary(0.2, 0.5, -1.0, 0.3)
