"""Equal degree of stability of the third-order servo (Bulgakov (1954), §8.24): numpy.roots on the curves and a
brute-force grid for the optimum."""

from __future__ import annotations

import numpy as np
import pytest

from symosc.errors import ParameterError
from symosc.linear import servo_optimum, servo_stability_lines


def _degree(k1, k2, z):
    return -np.roots([1.0, k1, k2, z]).real.max()


@pytest.mark.parametrize(("z", "delta"), [(8.0, 1.0), (2.0, 0.5), (5.0, 1.6)])
def test_boundary_has_the_degree_and_interior_exceeds_it(z, delta):
    c = servo_stability_lines(z, delta, n_points=21)
    for k1, k2 in zip(*c.line, strict=True):
        assert _degree(k1, k2, z) == pytest.approx(delta, abs=1e-6)
    for k1, k2 in zip(*c.hyperbola, strict=True):
        assert _degree(k1, k2, z) == pytest.approx(delta, abs=1e-6)
    for j in range(2, 19, 4):  # between the two curves: strictly more stable
        k1 = c.line[0][j]
        mid = 0.5 * (c.line[1][j] + c.hyperbola[1][j])
        assert _degree(k1, mid, z) > delta + 1e-6
    # just outside (beyond the line, away from the hyperbola): less stable
    k1, k2 = c.line[0][10], c.line[1][10]
    outward = -np.sign(c.hyperbola[1][10] - k2)
    assert _degree(k1, k2 + outward * 1e-3, z) < delta


def test_optimum_vs_grid():
    """§8.24: the largest degree over a (k1, k2) grid is z^{1/3}, reached near (3z^{1/3}, 3z^{2/3})."""
    z, k = 3.0, 0.4
    opt = servo_optimum(z, k)
    k1g, k2g = np.meshgrid(np.linspace(0.5, 8, 151), np.linspace(0.5, 8, 151))
    deg = np.array([_degree(a, b, z) for a, b in zip(k1g.ravel(), k2g.ravel(), strict=True)])
    assert deg.max() <= opt.delta + 1e-6
    j = deg.argmax()
    assert abs(k1g.ravel()[j] - opt.k1) < 0.2 and abs(k2g.ravel()[j] - opt.k2) < 0.2
    assert np.allclose(np.roots([1, opt.x * z + 1, opt.y * z + k, z]), -opt.delta, atol=1e-4)  # triple root
    with pytest.raises(ParameterError, match="δ³"):
        servo_stability_lines(1.0, 1.5)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    assert servo_stability_lines(8.0, 1.0).plot(ax=ax) is ax
    plt.close(fig)
