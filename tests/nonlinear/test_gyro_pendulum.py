"""Bulgakov (1954), §12.14: gyroscopic pendulum frequencies (12.252)-(12.253), decay rates (12.288)-(12.289), (12.300).

References: roots of the quadratic eigenproblem of the linear system (12.250) (companion pencil), with small
viscous damping for the decay rates (Re s = -mu c + O(mu^2)).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from symosc.mechanics import complex_modes
from symosc.nonlinear import gyro_pendulum_modes

CASES = [(1.0, 1.0, 1.5, 0.7, 0.2), (2.0, 1.3, 0.4, 0.1, 0.9), (0.8, 1.7, 2.5, 0.5, 0.5), (1.0, 0.6, 0.05, 0.3, 0.1)]


def _roots(p, sigma, n, p_v, q_v, mu):
    kappa = 1.7 * n  # any split kappa * lambda = n^2
    lam = n * n / kappa if n else 0.0
    D = np.array([[mu * p_v, kappa], [-lam, mu * q_v]])
    return complex_modes(np.eye(2), D, np.diag([p * p, sigma * sigma])).eigenvalues


@pytest.mark.parametrize(("p", "sigma", "n", "p_v", "q_v"), CASES)
def test_frequencies_and_decay_rates_against_eigenvalues(p, sigma, n, p_v, q_v):
    res = gyro_pendulum_modes(p, sigma, n, p_v=p_v, q_v=q_v)
    s = _roots(p, sigma, n, 0, 0, 0)
    np.testing.assert_allclose(np.sort(s.imag[s.imag > 0]), [res.omega1, res.omega2], rtol=1e-12)
    mu = 1e-6
    s = _roots(p, sigma, n, p_v, q_v, mu)
    s = s[s.imag > 0]
    s = s[np.argsort(s.imag)]
    np.testing.assert_allclose(-s.real / mu, [res.c1, res.c2], rtol=1e-4)
    assert res.nutation_decays_faster == (-s[1].real > -s[0].real)


def test_symmetric_closed_form_and_dry_friction_threshold():
    """p = sigma: omega = sqrt(p^2 + n^2/4) -+ n/2; nutation dies first under dry friction iff n > p/sqrt(2)."""
    for n in (0.3, 0.7, 0.71, 2.0):
        res = gyro_pendulum_modes(1.0, 1.0, n)
        root = math.sqrt(1 + n * n / 4)
        assert res.omega1 == pytest.approx(root - n / 2, rel=1e-13)
        assert res.omega2 == pytest.approx(root + n / 2, rel=1e-13)
        # (12.299): the node condition (1 + n^2/f^2)/(1 - n^2/f^2) > max R = 2, with f^2 = n sqrt(n^2 + 4 p^2)
        f2 = n * math.sqrt(n * n + 4)
        assert res.dry_friction_nutation_first == ((1 + n * n / f2) / (1 - n * n / f2) > 2)
    assert gyro_pendulum_modes(1.0, 2.0, 1.0).dry_friction_nutation_first is None


def test_bad_input():
    from symosc import ParameterError

    with pytest.raises(ParameterError):
        gyro_pendulum_modes(-1.0, 1.0, 1.0)
    with pytest.raises(ParameterError):
        gyro_pendulum_modes(1.0, 1.0, 0.0)
