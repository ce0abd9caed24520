"""Analytic continuation of matrix functions through expansions about scalar matrices (Bulgakov (1954), §1.31).

References: 50-digit mpmath (``mpmath.logm``/``sqrtm`` on the same float matrix, or its ``eighe``/``eig``
decomposition at 50 digits), SciPy's ``logm``/``sqrtm``/``expm``; the multivalued cases against the principal value
plus the known monodromy (``log``: ``+2πi``; ``sqrt``: sign change).
"""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
import scipy.linalg as sla
import sympy as sp

from symosc.algebra import analytic_continuation
from symosc.errors import ConvergenceError, ModelError, ParameterError


def _rel(x, ref):
    return float(np.linalg.norm(x - ref) / np.linalg.norm(ref))


def _mp_ref(A, fun):
    with mp.workdps(50):
        return np.array(fun(mp.matrix(A.tolist())).tolist(), dtype=complex)


def _spd_ref(A, f):
    with mp.workdps(50):
        E, V = mp.eighe(mp.matrix(A.tolist()))
        return np.array((V * mp.diag([f(e) for e in E]) * V.T).tolist(), dtype=float)


def test_log_series_about_one_continued_outside_its_disk():
    """§1.31: the element log λ = Σ (-1)^(k+1)(λ-1)^k/k (disk |λ-1| < 1) continued to a spectrum {0.05, 2.5, 7}."""
    S = np.array([[1.0, 0.5, 0.0], [0.2, 1.0, 0.3], [0.0, -0.4, 1.0]])
    A = S @ np.diag([0.05, 2.5, 7.0]) @ np.linalg.inv(S)
    res = analytic_continuation(A, sp.log)
    ref = _mp_ref(A, mp.logm).real
    assert _rel(res.value, ref) < 1e-13
    assert _rel(sla.logm(A), ref) < 1e-12  # SciPy agrees with the reference
    assert res.converged and len(res.disks) == 3
    assert all(rho < R for _, R, rho in res.disks)  # the §1.30 criterion holds in every disk
    assert res.path[0] == 1


@pytest.mark.parametrize(
    "fun, mpfun, dd_max",
    [(sp.log, mp.log, 1e6), (sp.sqrt, mp.sqrt, 0.5e3)],  # largest divided difference: 1/λ_min, 1/(2√λ_min)
)
def test_wide_spectrum_spd(fun, mpfun, dd_max):
    """Eigenvalues 1e-6 … 1e6: no single disk avoiding 0 holds them; one disk per eigenvalue does.  Relative error
    against a 50-digit reference within 100 × (condition number) × 1e-16, the condition number of f at a symmetric
    A being ``max|f[λ_i, λ_j]| ||A|| / ||f(A)||`` (Higham (2008), §3.1)."""
    rng = np.random.default_rng(3)
    Q, _ = np.linalg.qr(rng.standard_normal((4, 4)))
    A = Q @ np.diag([1e-6, 3e-2, 40.0, 1e6]) @ Q.T
    A = (A + A.T) / 2
    ref = _spd_ref(A, mpfun)
    res = analytic_continuation(A, fun)
    cond = dd_max * np.linalg.norm(A, 2) / np.linalg.norm(ref, 2)
    assert _rel(res.value, ref) <= 100 * cond * 1e-16
    assert len(res.disks) == 4 and res.converged


def test_jordan_blocks_small_and_large_eigenvalues():
    """S J S⁻¹ with Jordan blocks at 0.01 (×2), 0.02 (×2) and 100: series about each block's center."""
    J = np.zeros((5, 5))
    J[0, 0] = J[1, 1] = 0.01
    J[0, 1] = 1.0
    J[2, 2] = J[3, 3] = 0.02
    J[2, 3] = 1.0
    J[4, 4] = 100.0
    S = np.array([[1, 0.2, 0, 0.1, 0], [0, 1, 0.3, 0, 0], [0.1, 0, 1, 0.2, 0], [0, 0, 0, 1, 0.4], [0.2, 0, 0, 0, 1]])
    A = S @ J @ np.linalg.inv(S)
    for fun, mpfun in ((sp.sqrt, mp.sqrtm), (sp.log, mp.logm)):
        ref = _mp_ref(A, mpfun).real
        assert _rel(analytic_continuation(A, fun).value, ref) < 1e-10


def test_log_round_the_origin_gains_two_pi_i():
    """Continuing log once round λ = 0 (counter-clockwise) adds 2πi: the element is log + 2πi."""
    A = np.array([[2.0, 1.0], [0.5, 3.0]])
    res = analytic_continuation(A, sp.log, path=[1j, -1, -1j, 1])
    assert np.allclose(res.value, sla.logm(A) + 2j * np.pi * np.eye(2), rtol=0, atol=1e-13)
    c, d = res.branches[0]
    assert abs(c - 1) < 1e-13 and abs(d - 2j * np.pi) < 1e-13


def test_sqrt_round_the_origin_changes_sign():
    A = np.array([[4.0, 1.0], [0.0, 9.0]])
    once = analytic_continuation(A, sp.sqrt, path=[1j, -1, -1j, 1])
    twice = analytic_continuation(A, sp.sqrt, path=[1j, -1, -1j, 1, 1j, -1, -1j, 1])
    assert np.allclose(once.value, -sla.sqrtm(A), atol=1e-13, rtol=0)
    assert np.allclose(twice.value, sla.sqrtm(A), atol=1e-13, rtol=0)


@pytest.mark.parametrize("via, sign", [(1j, 1), (-1j, -1)])
def test_negative_eigenvalue_branch_follows_the_path(via, sign):
    """Reaching λ = -2 above the origin gives log 2 + iπ (the principal value), below it log 2 - iπ."""
    A = np.array([[-2.0, 1.0], [0.0, 3.0]])
    res = analytic_continuation(A, sp.log, path=[via])
    with mp.workdps(50):
        E, V = mp.eig(mp.matrix(A.tolist()))
        logs = [mp.log(abs(e)) + (sign * 1j * mp.pi if mp.re(e) < 0 else 0) for e in E]
        ref = np.array((V * mp.diag(logs) * mp.inverse(V)).tolist(), dtype=complex)
    assert np.allclose(res.value, ref, atol=1e-14, rtol=0)
    if sign == 1:
        assert np.allclose(res.value, sla.logm(A), atol=1e-13, rtol=0)


def test_single_expansion_about_a_scalar_matrix():
    """The book's single element χ(z - Eβ) = Σ b_k (z - Eβ)^k about β = 4 (radius 4 for log): spectrum
    (15 ± √17)/4 ≈ {2.72, 4.78}."""
    A = np.array([[3.0, 1.0], [0.5, 4.5]])
    res = analytic_continuation(A, sp.log, method="single", path=[4.0])
    assert np.allclose(res.value, sla.logm(A), atol=1e-14, rtol=0)
    ((beta, R, rho),) = res.disks
    assert beta == 4 and abs(R - 4) < 0.6 and abs(rho - (4 - (15 - np.sqrt(17)) / 4)) < 1e-12
    assert res.terms > 20 and res.error_estimate < 1e-14


def test_single_expansion_refuses_an_eigenvalue_outside_the_disk():
    """§1.30: the series diverges when an eigenvalue lies outside the disk (here λ = 9 about β = 4, R = 4)."""
    with pytest.raises(ConvergenceError, match=r"§1\.30"):
        analytic_continuation(np.diag([2.0, 9.0]), sp.log, method="single", path=[4.0])


def test_a_path_through_a_singularity_is_refused_and_one_close_to_it_is_followed():
    """The segment from the center -1 to the eigenvalue 0.001 runs through the branch point of log: refused once the
    radius of convergence stays below 1e-15 of the remaining distance (not after the 2000-step cap).  A path
    passing 1e-6 from the branch point is followed to the principal logarithm (SciPy's)."""
    A = np.array([[0.001, 1.0], [0.0, 50.0]])
    with pytest.raises(ConvergenceError, match=r"stalls .* too close to a singularity of f"):
        analytic_continuation(A, sp.log, center=-1)
    res = analytic_continuation(A, sp.log, path=[1e-6j])
    assert np.allclose(res.value, sla.logm(A), atol=1e-12, rtol=0)
    assert min(abs(b) for b in res.path) < 2e-6  # the path did pass the branch point that close


def test_order_too_small_raises():
    with pytest.raises(ConvergenceError, match="order=5"):
        analytic_continuation(np.array([[3.0, 1.0], [0.5, 4.5]]), sp.log, method="single", path=[4.0], order=5)


def test_entire_function_single_disk():
    A = np.array([[0.0, 1.0], [-4.0, -0.4]])
    res = analytic_continuation(A, sp.exp, method="single", center=0)
    assert np.allclose(res.value, sla.expm(A), atol=1e-14, rtol=0)
    assert res.disks[0][1] > 1e3  # entire: the root-test radius grows with the order


@pytest.mark.parametrize(
    "kwargs, exc, match",
    [
        ({"A": np.array([[np.nan, 0.0], [0.0, 1.0]])}, ParameterError, "non-finite"),
        ({"method": "disk"}, ParameterError, "method"),
        ({"step": 0.9}, ParameterError, "step"),
        ({"order": 0}, ParameterError, "order"),
        ({"f": sp.Lambda(sp.Symbol("x"), sp.log(sp.Symbol("x") * sp.Symbol("k")))}, ParameterError, "free"),
        ({"A": np.diag([0.0, 1.0])}, ModelError, "analytic"),
    ],
)
def test_bad_input(kwargs, exc, match):
    args = {"A": np.diag([1.0, 2.0]), "f": sp.log, **kwargs}
    with pytest.raises(exc, match=match):
        analytic_continuation(args.pop("A"), args.pop("f"), **args)


def test_plot_draws_disks():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    res = analytic_continuation(np.diag([0.5, 3.0]), sp.log)
    fig, ax = plt.subplots()
    assert res.plot(ax=ax) is ax
    assert len(ax.patches) == 4  # two disks of convergence, two spectral disks
    plt.close(fig)
