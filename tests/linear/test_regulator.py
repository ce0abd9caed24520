"""Regulator optimisation and lines of equal stability (Bulgakov (1954), §4.10–4.12).

References: numpy.roots for α, the Lyapunov equation (scipy) for the quadratic integrals γ1, γ0, a dense frequency
sweep for ϑ, the Raushenbakh closed form (1/k2)(1 + δ)/(1 - δ) of §4.10 for β, and brute-force grid maxima.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import solve_continuous_lyapunov

from symosc.errors import ParameterError
from symosc.linear import equal_stability_lines, optimize_regulator


def _alpha(k0, k1, k2):
    return -np.roots([k0, k1, k2]).real.max()


def _quad_integral(k0, k1, k2, theta, x0):
    A = np.array([[0.0, 1.0], [-k2 / k0, -k1 / k0]])
    P = solve_continuous_lyapunov(A.T, -np.diag(theta))
    x0 = np.asarray(x0, float)
    return x0 @ P @ x0


def _gamma1(k0, k1, k2, theta):
    return 1 / _quad_integral(k0, k1, k2, theta, [0.0, 1 / k0])


def _gamma0(k0, k1, k2, theta):
    return 1 / _quad_integral(k0, k1, k2, theta, [1.0, 0.0])


def _beta(k0, k1, k2):
    if k1**2 >= 4 * k0 * k2:
        return k2
    delta = np.exp(-np.pi * k1 / np.sqrt(4 * k0 * k2 - k1**2))
    return k2 * (1 - delta) / (1 + delta)


def _vartheta(k0, k1, k2):
    """Grid sweep of |k2 - k0ν² + ik1ν| over ν, refined by a bounded scalar minimisation around the grid minimum."""
    from scipy.optimize import minimize_scalar

    nu = np.linspace(0, 4 * np.sqrt(k2 / k0) + 1, 2001)
    vals = np.abs(k2 - k0 * nu**2 + 1j * k1 * nu)
    j = int(vals.argmin())
    lo, hi = nu[max(j - 1, 0)], nu[min(j + 1, nu.size - 1)]
    res = minimize_scalar(
        lambda x: abs(k2 - k0 * x**2 + 1j * k1 * x), bounds=(lo, hi), method="bounded", options={"xatol": 1e-12}
    )
    return min(vals.min(), res.fun)


REF = {
    "alpha": lambda k0, k1, k2, th: _alpha(k0, k1, k2),
    "beta": lambda k0, k1, k2, th: _beta(k0, k1, k2),
    "gamma1": lambda k0, k1, k2, th: _gamma1(k0, k1, k2, th),
    "gamma0": lambda k0, k1, k2, th: _gamma0(k0, k1, k2, th),
    "vartheta": lambda k0, k1, k2, th: _vartheta(k0, k1, k2),
}


@pytest.mark.parametrize("crit", ["alpha", "beta", "gamma1", "gamma0", "vartheta"])
@pytest.mark.parametrize("free", ["k1", "k2"])
def test_optimum_is_grid_maximum(crit, free):
    """§4.12: the returned parameter attains the brute-force maximum of the independently computed criterion on a
    grid of the admissible interval (0.05, 12], with θ = (0.8, 0.5)."""
    k0, fixed, th = 1.3, 2.1, (0.8, 0.5)
    opt = optimize_regulator(
        k0, **{("k2" if free == "k1" else "k1"): fixed}, criterion=crit, theta=th, bounds=(0.05, 12)
    )
    grid = np.linspace(0.05, 12, 240 if crit == "vartheta" else 2400)
    vals = np.array([REF[crit](k0, *((g, fixed) if free == "k1" else (fixed, g)), th) for g in grid])
    best = vals.max()
    got = REF[crit](k0, opt.k1, opt.k2, th)
    assert got >= best - 1e-6 * max(1.0, best)
    assert abs(opt.value - got) < 1e-6 * max(1.0, got)
    if opt.kind == "stationary point":  # a strict interior maximum: the grid argmax is next to it
        x = opt.k1 if free == "k1" else opt.k2
        assert abs(grid[vals.argmax()] - x) < 2 * (grid[1] - grid[0])


def test_book_rules_and_frequency_limit():
    """(4.95)–(4.98): α-optimum k1 = 2√(k0k2); servo γ0 (θ = (1, 0)) k1 = √(k0k2), γ0 = √(k2/k0); tangency
    k2 = √(θ1/θ2) k1 with γ0 = 2k1/(θ1k0 + 2√(θ1θ2)k1); ω ≤ ω_m caps k2 at k1²/(4k0) + k0ω_m²."""
    r = optimize_regulator(2.0, k2=3.0)
    assert r.k1 == pytest.approx(2 * np.sqrt(6.0)) and r.kind == "stationary point"
    r = optimize_regulator(2.0, k2=3.0, criterion="gamma0")
    assert r.k1 == pytest.approx(np.sqrt(6.0)) and r.value == pytest.approx(np.sqrt(1.5))
    t1, t2, k1 = 0.8, 0.2, 1.5
    r = optimize_regulator(1.0, k1=k1, criterion="gamma0", theta=(t1, t2))
    assert r.k2 == pytest.approx(np.sqrt(t1 / t2) * k1)
    assert r.value == pytest.approx(2 * k1 / (t1 + 2 * np.sqrt(t1 * t2) * k1))
    r = optimize_regulator(1.0, k1=1.5, criterion="gamma0", theta=(t1, t2), omega_max=0.5)
    assert r.k2 == pytest.approx(1.5**2 / 4 + 0.25) and r.kind == "boundary"
    r = optimize_regulator(1.0, k1=1.0, criterion="alpha", omega_max=2.0)
    assert (r.kind, r.k2, r.plateau) == ("plateau", 0.25, (0.25, 4.25))
    r = optimize_regulator(1.0, k2=5.0, criterion="beta", omega_max=1.0)  # k1 ≥ 2√(k0(k2 - k0ω_m²)) = 4
    assert r.interval[0] == pytest.approx(4.0) and r.k1 == pytest.approx(np.sqrt(20.0)) and r.value == 5.0


def test_optimize_errors():
    with pytest.raises(ParameterError, match="grows without bound"):
        optimize_regulator(1.0, k2=1.0, criterion="gamma1")
    with pytest.raises(ParameterError, match="exactly one"):
        optimize_regulator(1.0, k1=1.0, k2=1.0)
    with pytest.raises(ParameterError, match="criterion"):
        optimize_regulator(1.0, k2=1.0, criterion="delta")
    with pytest.raises(ParameterError, match="positive"):
        optimize_regulator(1.0, k2=-1.0)


@pytest.mark.parametrize(
    ("crit", "value", "theta"),
    [
        ("alpha", 0.7, (1, 0)),
        ("beta", 1.3, (1, 0)),
        ("gamma1", 0.9, (0.8, 0.5)),
        ("gamma0", 0.6, (1.0, 0.0)),
        ("gamma0", 0.6, (0.8, 0.5)),
        ("vartheta", 1.1, (1, 0)),
    ],
)
def test_equal_stability_lines_have_the_value(crit, value, theta):
    """Every sampled point of every branch has the stated coefficient by the independent computation."""
    k0 = 1.4
    lines = equal_stability_lines(crit, value, k0, theta=theta, n_points=25)
    checked = 0
    for k1s, k2s in lines.branches:
        for k1, k2 in zip(k1s, k2s, strict=True):
            got = REF[crit](k0, k1, k2, np.asarray(theta, float))
            assert got == pytest.approx(value, rel=1e-6, abs=1e-9), (k1, k2)
            checked += 1
    assert checked >= 25


def test_lines_merge_with_boundary_and_plot():
    """As α → 0 the α-lines approach the axes k2 = 0 and k1 = 0 (§4.10)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lines = equal_stability_lines("alpha", 1e-6, 1.0, k1_max=5.0)
    assert np.abs(lines.branches[0][1]).max() < 1e-5 and np.abs(lines.branches[1][0]).max() < 1e-5
    fig, ax = plt.subplots()
    assert lines.plot(ax=ax) is ax
    assert optimize_regulator(1.0, k2=2.0).plot(ax=ax) is ax
    plt.close(fig)
    with pytest.raises(ParameterError, match="value"):
        equal_stability_lines("beta", 0.0)
