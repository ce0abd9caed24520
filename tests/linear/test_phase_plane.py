"""Phase portrait of k0 y'' + k1 y' + k2 y = 0 (Bulgakov (1954), §4.1–4.2): closed-form trajectories vs solve_ivp."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from symosc.errors import ParameterError
from symosc.linear import phase_portrait


@pytest.mark.parametrize(
    ("k1", "k2", "kind"),
    [
        (0.4, 4.0, "stable focus"),
        (0.0, 4.0, "center"),
        (5.0, 4.0, "stable node"),
        (4.0, 4.0, "stable degenerate node"),
        (-0.3, 2.0, "unstable focus"),
        (1.0, -2.0, "saddle"),
    ],
)
def test_trajectories_match_solve_ivp(k1, k2, kind):
    """§4.2: every trajectory agrees with an independent DOP853 integration of the canonical equations
    q' = p/k0, p' = -k2 q - (k1/k0) p (p = k0 y')."""
    k0 = 1.5  # scale the equation: the type of the singular point is unchanged
    k1, k2 = k0 * k1, k0 * k2
    starts = [[1.0, 0.0], [0.0, 1.0], [-0.5, 0.7]]
    pp = phase_portrait(k0, k1, k2, starts, t_max=2.5, n_points=26)
    assert pp.kind == kind
    for (y0, v0), y, v in zip(starts, pp.y, pp.v, strict=True):
        sol = solve_ivp(
            lambda t, z: [z[1] / k0, -k2 * z[0] - k1 / k0 * z[1]],
            (0, 2.5),
            [y0, k0 * v0],
            t_eval=pp.t,
            method="DOP853",
            rtol=1e-12,
            atol=1e-14,
        )
        assert np.allclose(y, sol.y[0], atol=1e-9)
        assert np.allclose(v, sol.y[1] / k0, atol=1e-9)


def test_canonical_form_and_invariant_lines():
    """2h = k1/k0, k² = k2/k0; the eigenvalues are numpy's roots of k0 λ² + k1 λ + k2 and, for a node, a start on
    an invariant line y' = λ y stays on it."""
    pp = phase_portrait(2.0, 10.0, 8.0, [[1.0, -1.0]], t_max=4.0)
    assert (pp.h, pp.k_squared) == (2.5, 4.0)
    assert np.allclose(sorted(np.real(pp.eigenvalues)), sorted(np.roots([2.0, 10.0, 8.0]).real), atol=1e-14)
    assert sorted(pp.directions) == pytest.approx([-4.0, -1.0])
    assert np.allclose(pp.v[0], -pp.y[0], atol=1e-12)  # the slow line y' = -y


def test_plot_returns_axes_and_bad_input():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    pp = phase_portrait(1.0, 0.5, 1.0)
    assert pp.plot(ax=ax) is ax
    assert len(ax.lines) >= len(pp.initial_states)
    plt.close(fig)
    with pytest.raises(ParameterError, match="initial_states"):
        phase_portrait(1, 1, 1, [[1.0, 2.0, 3.0]])
    with pytest.raises(ParameterError, match="mass"):
        phase_portrait(-1, 1, 1)
