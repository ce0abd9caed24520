"""Long pendulum chains: the symbolic model refuses sizes whose cost is out of reach (with the measured growth),
and the closed-form linearization serves any length.

References: the Lagrangian route (``n_link_pendulum(n).linearize()``, a different derivation) for small n, and for
a long chain an independent numeric construction ``M = J^T diag(m) J + diag(I)`` from the Jacobian ``J`` of the mass
centers' horizontal positions at the equilibrium, with the potential's Hessian from finite differences of
``V = sum m_k g y_k``.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from symosc.errors import ModelError, ParameterError
from symosc.models import n_link_pendulum, n_link_pendulum_linearization


@pytest.mark.parametrize("links", ["point", "rigid"])
@pytest.mark.parametrize("inverted", [False, True])
@pytest.mark.parametrize("pivot", ["fixed", "vertical"])
def test_closed_form_equals_lagrangian_linearization(links, inverted, pivot):
    for n in (1, 3):
        a = n_link_pendulum(n, links=links, inverted=inverted, pivot=pivot).linearize()
        b = n_link_pendulum_linearization(n, links=links, inverted=inverted, pivot=pivot)
        for x, y in ((a.M, b.M), (a.K, b.K), (a.D, b.D), (a.f, b.f)):
            assert sp.expand(x - y) == sp.zeros(*x.shape)
        assert a.coordinates == b.coordinates and a.point == b.point


def _numeric_reference(m, l, lc, inertia, g, sign):
    """M and K of a chain from positions: x_k = sum_{i<k} l_i sin(phi_i) + lc_k sin(phi_k), y likewise."""
    n = len(m)
    J = np.zeros((n, n))
    for k in range(n):
        J[k, :k] = l[:k]
        J[k, k] = lc[k]
    M = J.T @ np.diag(m) @ J + np.diag(inertia)

    def V(phi):
        y = np.array([sign * (np.sum(l[:k] * np.cos(phi[:k])) + lc[k] * np.cos(phi[k])) for k in range(n)])
        return -np.sum(m * g * y) if sign > 0 else np.sum(m * g * y)

    h = 1e-3
    K = np.zeros(n)
    for i in range(n):
        e = np.zeros(n)
        e[i] = h
        K[i] = (V(e) - 2 * V(np.zeros(n)) + V(-e)) / h**2
    return M, K


def test_long_rigid_chain_matches_numeric_construction():
    n = 60  # beyond the symbolic model's limit
    rng = np.random.default_rng(3)
    m, l = rng.uniform(0.5, 2.0, n), rng.uniform(0.2, 1.0, n)
    lc, inertia = l * rng.uniform(0.3, 0.7, n), rng.uniform(0.01, 0.1, n)
    g = 9.81
    lin = n_link_pendulum_linearization(n, links="rigid")
    values = {f"{k}{i + 1}": v[i] for k, v in (("m", m), ("l", l), ("lc", lc), ("I", inertia)) for i in range(n)}
    values["g"] = g
    subs = {sym: values[sym.name] for sym in lin.parameters}
    M = np.array(sp.lambdify(list(subs), lin.M, "numpy")(*subs.values()), dtype=float)
    K = np.array(sp.lambdify(list(subs), lin.K, "numpy")(*subs.values()), dtype=float)
    M_ref, K_ref = _numeric_reference(m, l, lc, inertia, g, sign=1)
    np.testing.assert_allclose(M, M_ref, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(np.diag(K), K_ref, rtol=1e-6)  # h**2 truncation ~ 1e-7
    assert np.count_nonzero(K - np.diag(np.diag(K))) == 0


def test_two_hundred_links_refused_up_front_with_the_alternative():
    """n_link_pendulum(200) used to run for tens of minutes; now it says why, how much, and what to use."""
    with pytest.raises(
        ParameterError, match=r"n <= 40.*n\*\*[0-9.]+ \(measured\).*n_link_pendulum_linearization\(200"
    ) as info:
        n_link_pendulum(200)
    assert isinstance(info.value, ModelError)  # the scene loader catches ModelError for bad catalogue entries
    assert "max_links=None" in str(info.value)
    with pytest.raises(ParameterError, match="n <= 3"):
        n_link_pendulum(4, max_links=3)
    assert n_link_pendulum(4, max_links=None).coordinates[-1] == sp.Symbol("phi4", real=True)  # the limit is lifted
    lin = n_link_pendulum_linearization(200)
    assert lin.M.shape == (200, 200) and lin.K[199, 199] == sp.Symbol("g", positive=True) * lin.M[199, 199] / sp.Symbol(
        "l200", positive=True
    )


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"n": 0}, "positive integer"),
        ({"n": 2.5}, "positive integer"),
        ({"n": 2, "links": "rigd"}, "did you mean 'rigid'"),
        ({"n": 2, "pivot": "vertcal"}, "did you mean 'vertical'"),
        ({"n": 2, "inverted": "yes"}, "True or False"),
    ],
)
def test_bad_arguments_name_the_fix(kwargs, match):
    with pytest.raises(ParameterError, match=match):
        n_link_pendulum_linearization(**kwargs)
