"""Bulgakov (1954), §5.14: relay servo with backlash simulated as a piecewise ODE, against the critical gap.

The critical insulating gap k_c of (5.186) (friction on the follower) and (5.189) (friction on the motor) was
reconstructed from a damaged print; here the piecewise-linear model (5.167)-(5.174) is simulated half-swing by
half-swing: below k_c some initial amplitude keeps oscillating, above k_c every one comes to rest.
"""

from __future__ import annotations

import numpy as np
import pytest

from symosc import ParameterError
from symosc.nonlinear import backlash_critical_gap, simulate_backlash_servo


def _any_sustained(z, k, f, variant):
    for xi0 in np.linspace(k / 2 * 1.001, 5.0, 40):
        run = simulate_backlash_servo(z, k, f, float(xi0), variant=variant, max_half_swings=30)
        if not run.stopped:
            tail = run.amplitudes[-4:]
            assert np.all(tail > k / 2) and np.ptp(tail) < 1e-3 * tail.max()  # a settled cycle (fixed point)
            return True
    return False


@pytest.mark.parametrize(
    ("z", "f", "variant"),
    [(1.0, 0.0, "follower"), (1.0, 0.3, "follower"), (0.5, 0.2, "follower"), (1.0, 1.5, "follower"),
     (1.0, 0.3, "motor"), (2.0, 0.5, "motor")],
)  # fmt: skip
def test_critical_gap_separates_oscillation_from_rest(z, f, variant):
    kc = backlash_critical_gap(z, f, variant)
    below = 0.9 if f < 1 else 0.5
    assert _any_sustained(z, below * kc, f, variant)
    assert not _any_sustained(z, 1.1 * kc, f, variant)


def test_bad_input():
    with pytest.raises(ParameterError):
        simulate_backlash_servo(1.0, 0.5, 0.2, 0.1)  # xi0 inside the gap
    with pytest.raises(ParameterError):
        simulate_backlash_servo(1.0, 0.5, 1.2, 1.0, variant="motor")
