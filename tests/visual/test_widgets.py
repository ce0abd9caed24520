"""The explorers, driven headlessly: set a slider's value, check the verdict, the point and the drawn outputs
against computations that do not use the explorers' code paths."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.special
from scipy.optimize import brentq

pytest.importorskip("ipywidgets", reason="the explorers need the widgets extra (ipywidgets); .ci/run installs it")

from symosc.errors import ParameterError
from symosc.visual import mathieu_explorer, pivot_explorer, resonance_explorer


def test_pivot_explorer_moves_the_point_and_the_verdict():
    """Gribkov & Khokhlov (2015), Table 1 at 100 Hz: 2 mm keeps the chain up, 1 mm does not.  The first-tone point
    is q1 = 2 a p1^2 / g with p1 the lowest hanging frequency (eq. (8)); the simulated nonlinear motion confirms the
    verdict (bounded tilt vs a fall)."""
    ex = pivot_explorer(duration=0.5)
    p1 = ex.region.natural_frequencies[0]
    assert ex.stable is True
    assert ex.point[1] == pytest.approx(2 * 2e-3 * p1**2 / 9.81, rel=1e-12)
    assert ex.point[0] == pytest.approx(-4 * (p1 / (2 * np.pi * 100)) ** 2, rel=1e-12)
    assert np.max(np.abs(ex.trajectory.states[:, :2])) < 0.5
    chart = ex.chart.value
    ex.amplitude.value = 1.0
    assert ex.stable is False and "unstable" in ex.verdict.value
    assert ex.point[1] == pytest.approx(2 * 1e-3 * p1**2 / 9.81, rel=1e-12)
    assert np.max(np.abs(ex.trajectory.states[:, :2])) > 1.0  # it falls
    assert ex.chart.value != chart and ex.chart.value[:4] == b"\x89PNG"


def test_mathieu_explorer_agrees_with_scipy_characteristic_values():
    """Stable exactly between a_n(q) and b_(n+1)(q) (SciPy's mathieu_a/mathieu_b), in the first two bands."""
    ex = mathieu_explorer()
    for a, q in ((1.5, 0.5), (1.0, 0.3), (4.2, 0.5)):
        ex.a.value, ex.q.value = a, q
        bands = [(scipy.special.mathieu_a(n, q), scipy.special.mathieu_b(n + 1, q)) for n in range(3)]
        assert ex.stable is any(lo < a < hi for lo, hi in bands), (a, q)


def test_resonance_explorer_jumps_match_the_amplitude_equation():
    """Duffing, first approximation: a^2 [(w0^2 - nu^2 + 3 mu a^2 / 4)^2 + (2 zeta w0 nu)^2] = R^2 (Bulgakov 1954,
    ch. 6).  The jumps are where this cubic in a^2 has a double root (its discriminant vanishes)."""
    ex = resonance_explorer()

    def disc(nu, zeta, R, mu=0.5, w0=1.0):
        d = w0**2 - nu**2
        c = [9 * mu**2 / 16, 1.5 * mu * d, d**2 + (2 * zeta * w0 * nu) ** 2, -(R**2)]
        a, b, cc, dd = c
        return 18 * a * b * cc * dd - 4 * b**3 * dd + b**2 * cc**2 - 4 * a * cc**3 - 27 * a**2 * dd**2

    for zeta, R in ((0.05, 0.1), (0.03, 0.15)):
        ex.damping.value, ex.forcing.value = zeta, R
        nus = np.linspace(1.0, 1.8, 4001)
        sign = np.sign(disc(nus, zeta, R))
        idx = np.nonzero(sign[:-1] != sign[1:])[0]
        jumps = [brentq(disc, nus[i], nus[i + 1], args=(zeta, R)) for i in idx]
        np.testing.assert_allclose(ex.response.jump_frequencies, jumps, rtol=1e-6)
    ex.damping.value = 0.3
    assert ex.response.jump_frequencies == () and "none" in ex.verdict.value


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"amplitude": -1.0}, r"amplitude must be >= 0, got -1\.0"),
        ({"amplitude": float("inf")}, r"amplitude must be finite, got inf"),
        ({"tilt": float("nan")}, r"tilt must be finite, got nan"),
    ],
)
def test_pivot_explorer_refuses_a_negative_or_infinite_amplitude_and_a_nan_tilt(kwargs, message):
    with pytest.raises(ParameterError, match=message):
        pivot_explorer(duration=0.1, **kwargs)
