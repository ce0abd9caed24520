"""Dynamic vibration absorber, Bulgakov (1954), §9.41-9.42 (example T9) and Den Hartog's fixed-point theory.

References: direct solution of the two-mass equations of motion with complex amplitudes (numpy.linalg.solve),
the printed T9 numbers, the closed forms sqrt(1 + 2/mu) and sqrt(3 mu / (8 (1 + mu)^3)), and a brute-force grid
search of the peak.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from symosc.errors import ParameterError
from symosc.networks import Absorber, absorber_fixed_points, absorber_hinf_optimum, absorber_optimum


def _direct_r1(mu, f, zeta, g):
    """|y1|/(P/C) from M y1'' = -C y1 + c (y2 - y1) + 2 m beta (y2' - y1)' + P e^{i nu t}, m y2'' = ..."""
    M, C = 1.0, 1.0
    m, c, beta = mu, mu * f**2, zeta
    w = g
    K = np.array(
        [
            [C + c - M * w**2 + 2j * m * beta * w, -c - 2j * m * beta * w],
            [-c - 2j * m * beta * w, c - m * w**2 + 2j * m * beta * w],
        ]
    )
    y = np.linalg.solve(K, np.array([1.0, 0.0]))
    return abs(y[0])


def test_amplification_matches_equations_of_motion():
    """Eq. (9.596) against the complex-amplitude solution of (9.585) with the damper (9.594)."""
    a = Absorber(0.15, 0.87, 0.11)
    for g in (0.3, 0.8, 0.95, 1.2, 2.0):
        assert abs(a.amplification(g) - _direct_r1(0.15, 0.87, 0.11, g)) < 1e-12


def test_t9_fixed_points():
    """T9: omega_M = 1, omega_m = 0.9, mu = 0.1: nu^2 = 0.701909, 1.099043; R1 = 4.38789, 4.78589 for any beta."""
    xs = [float(v) for v in absorber_fixed_points(0.1, 0.9)]
    assert np.allclose(xs, [0.701909, 1.099043], atol=1e-6)
    for zeta in (0.01, 0.1, 0.5, 3.0):
        r = [_direct_r1(0.1, 0.9, zeta, np.sqrt(x)) for x in xs]
        assert np.allclose(r, [4.38789, 4.78589], atol=1e-5)


def test_undamped_absorber_anti_resonance():
    """§9.41: R1 = 0 at nu = omega_m; natural frequencies (9.587) are the roots of (9.586)."""
    a = Absorber(0.2, 1.1, 0.0)
    assert a.amplification(1.1) == 0
    w1, w2 = a.natural_frequencies()
    roots = np.sort(np.sqrt(np.roots([1, -(1 + 1.21 + 0.2 * 1.21), 1.21]).real))
    assert np.allclose([w1, w2], roots, rtol=1e-12)


def test_absorber_optimum_symbolic():
    """The derived optimum equals 1/(1+mu) and sqrt(3 mu/(8 (1+mu)^3)) identically in mu."""
    mu = sp.Symbol("mu", positive=True)
    f, z = absorber_optimum(mu)
    assert sp.simplify(f - 1 / (1 + mu)) == 0
    assert sp.simplify(z**2 - 3 * mu / (8 * (1 + mu) ** 3)) == 0


@pytest.mark.parametrize(
    ("mu", "height", "beta_book"), [(0.05, 6.40312, 0.127267), (0.1, 4.58258, 0.167852), (0.25, 3.0, 0.219089)]
)
def test_equal_fixed_point_heights(mu, height, beta_book):
    """At the optimal tuning both fixed points have height sqrt(1 + 2/mu), for every damping, to 1e-12."""
    f, z = (float(v) for v in absorber_optimum(sp.Float(mu, 30)))
    assert abs(z - beta_book) < 1e-6
    xs = [float(v) for v in absorber_fixed_points(sp.Float(mu, 30), sp.Float(f, 30))]
    for zeta in (z, 0.05, 0.4):
        h = [_direct_r1(mu, f, zeta, np.sqrt(x)) for x in xs]
        assert abs(h[0] - h[1]) < 1e-12 * h[0]
        assert abs(h[0] - np.sqrt(1 + 2 / mu)) < 1e-12 * h[0]
    assert abs(np.sqrt(1 + 2 / mu) - height) < 1e-5


@pytest.mark.parametrize(("mu", "beta_num"), [(0.05, 0.12743), (0.1, 0.16828), (0.25, 0.22041)])
def test_hinf_damping_at_den_hartog_tuning(mu, beta_num):
    """T9 table: the min-max damping at f = 1/(1+mu) (book-independent numerical optimum) and peak <= DH peak."""
    r = absorber_hinf_optimum(mu, tune=False)
    assert abs(r.damping_ratio - beta_num) < 2e-4
    assert r.peak <= r.fixed_point_peak
    # brute-force check of the peak at the optimum
    g = np.linspace(0.5, 1.5, 200001)
    assert abs(Absorber(mu, r.frequency_ratio, r.damping_ratio).amplification(g).max() - r.peak) < 1e-6


@pytest.mark.parametrize("mu", [0.01, 0.1, 0.5, 1.0])
def test_hinf_optimum_not_above_fixed_point_optimum(mu):
    """The exact H-infinity optimum's peak is below the fixed-point optimum's, for mu = 0.01..1 (brute-force grid)."""
    r = absorber_hinf_optimum(mu)
    f0, z0 = (float(v) for v in absorber_optimum(sp.Float(mu, 30)))
    g = np.linspace(0.3, 1.7, 400001)
    dh = max(_direct_r1(mu, f0, z0, x) for x in g[::400])
    dh = max(dh, Absorber(mu, f0, z0).amplification(g).max())
    best = Absorber(mu, r.frequency_ratio, r.damping_ratio).amplification(g).max()
    assert best < dh  # Den Hartog's optimum is not exactly H-infinity optimal
    assert dh - best < 0.01 * best  # ... but within 1 %


def test_plot_and_bad_input():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    assert Absorber(0.1, 1 / 1.1, 0.17).plot(ax=ax) is ax
    assert len(ax.lines) == 2
    plt.close(fig)
    with pytest.raises(ParameterError, match="mu"):
        Absorber(-0.1, 1.0, 0.1)
    with pytest.raises(ParameterError, match="mu"):
        absorber_optimum(-1)
