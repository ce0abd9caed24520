"""Error maps against the center-of-mass offset (Belyakov 2005, Ch. III §3.2, Figs 21–24; report §3.9, §4.7).

Seed 001 (../shared/seeds/001_b22cdb6b21550ad5.txt); digest ../shared/research/seed-belyakov.md.  The records are
shortened (200 samples at 3 x 0.02212 s) to keep the Monte Carlo cheap; the properties tested are qualitative, as
in the report (the figures' band values are not recoverable).
"""

import matplotlib
import numpy as np
import pytest

from symosc.errors import ParameterError
from symosc.identification import ErrorMap, error_map

matplotlib.use("Agg")

SHORT = dict(n_samples=200)
K, P = 7.4e5, 2000.0  # spring stiffness (N/m) and released force at spring 2 (N), Tables 1–2


def test_modal_energies_and_applicability_map():
    """Figs 23–24: the release stores 1/2 p y2 = 3 p^2 / (8 k) = 2.027 J whatever the CM offset (equal springs on a
    rectangle: y2 = 3p/4k from rigid-plane statics, report §3.9); the minimum modal energy is largest with the CM at
    the center of stiffness and collapses in the corner (-0.4, +0.3) m, which fails the applicability criterion."""
    dx, dz = [-0.4, -0.2, 0.0, 0.2, 0.4], [-0.3, 0.0, 0.3]
    em = error_map(dx, dz, noise=0.0, runs=1, **SHORT)
    np.testing.assert_allclose(em.energies.sum(axis=-1), 3 * P**2 / (8 * K), rtol=1e-10)
    assert 3 * P**2 / (8 * K) == pytest.approx(2.027, abs=5e-4)
    center = em.min_energy[2, 1]
    others = np.delete(em.min_energy.ravel(), 2 * 3 + 1)
    assert np.all(others < center)
    assert em.applicable[2, 1] and not em.applicable[0, 2]
    assert em.min_energy[0, 2] < 0.01  # the weak mode "drowns in noise"


def test_noise_free_maps_are_exact():
    """Without noise every algorithm recovers the body exactly at off-center points (truth = the input body)."""
    for alg in ("1", "2.1", "2.2"):
        em = error_map([-0.3, 0.25], [0.2], noise=0.0, runs=1, algorithm=alg, names=("Izz", "Ixx", "Ixz"), **SHORT)
        assert em.failures.sum() == 0
        assert np.nanmax(em.errors) < 1e-7, alg


def test_algorithm1_error_grows_away_from_center_of_stiffness():
    """Figs 21–22 (report §3.1, §3.9): with Algorithm 1 the Izz error grows as the CM moves away from the center of
    stiffness, where a mode is weakly excited; it also grows with the noise level (Fig. 20)."""
    em = error_map([-0.4, 0.0, 0.4], [-0.3, 0.0, 0.3], noise=[0.0, 0.01, 0.06], runs=8, **SHORT)
    izz = em.mean[..., em.names.index("Izz")]  # (noise, dx, dz)
    assert np.all(izz[0] < 1e-7)
    assert izz[1, 1, 1] < izz[2, 1, 1]
    at6 = izz[2]
    assert at6[0, 2] > 3 * at6[1, 1]  # corner (-0.4, +0.3): min modal energy 0.002 J
    assert at6[2, 0] > 1.5 * at6[1, 1]  # corner (+0.4, -0.3): 0.088 J
    # the worst point of the map is one that fails the applicability criterion
    worst = np.unravel_index(np.nanargmax(at6), at6.shape)
    assert not em.applicable[worst]


def test_algorithm22_error_grows_towards_center_of_stiffness():
    """Algorithm 2.2 is the opposite: ill-posed at the center of stiffness (report §4.4 remark, our finding), so its
    condition number and its errors grow as the CM approaches that point along the diagonal."""
    s = np.array([0.05, 0.25, 1.0])
    em = error_map(0.4 * s, 0.3 * s, noise=0.02, runs=6, algorithm="2.2", **SHORT)
    cond = em.condition.diagonal()
    assert cond[0] > cond[1] > cond[2]
    err = np.array([em.mean[0, i, i] for i in range(3)])  # (points, [Izz, Ixx])
    assert np.all(err[0] > 2 * err[2])
    center = error_map([0.0], [0.0], noise=0.0, runs=1, algorithm="2.2", **SHORT)
    assert np.isinf(center.condition[0, 0]) and center.failures[0, 0, 0] == 1


def test_error_map_repr_plot_and_bad_input():
    em = error_map([-0.2, 0.2], [-0.1, 0.1], noise=0.02, runs=2, **SHORT)
    assert isinstance(em, ErrorMap)
    assert "ErrorMap(algorithm='1', grid=2x2" in repr(em)
    table = repr(em).splitlines()[2:]  # header of dz values, then one row per dx: every number stands apart
    assert [float(v) for v in table[0].split()] == [-0.1, 0.1]
    for x, line in zip([-0.2, 0.2], table[1:], strict=True):
        values = [float(v) for v in line.split()]
        assert values[0] == x and len(values) == 3
    assert em.plot().get_xlabel() == "CM offset along x (m)"
    assert em.plot(energy=True).get_title() == "minimum modal energy of the release"
    with pytest.raises(ParameterError, match="algorithm"):
        error_map([0.1], [0.1], algorithm="3")
    with pytest.raises(ParameterError, match="names"):
        error_map([0.1], [0.1], names=("Iyy",))
    with pytest.raises(ParameterError, match="noise"):
        error_map([0.1], [0.1], noise=-0.01)
    with pytest.raises(ParameterError, match="runs"):
        error_map([0.1], [0.1], runs=0)
