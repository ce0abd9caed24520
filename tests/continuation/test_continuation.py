"""Branches, bifurcations and branch switching against independent computations.

References: shooting (a second method: the period map integrated with the variational equations) for fold
locations; first-order averaging of ``symosc.nonlinear`` (Bulgakov 1954, ch. 6; Nayfeh & Mook 1979, §4.1) in the
weakly nonlinear limit; ``symosc.periodic.monodromy`` of the linear Mathieu equation for the period-doubling
threshold of the trivial solution; direct integration for the doubled-period orbit.
"""

from __future__ import annotations

import pickle

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc.continuation import (
    Branch,
    continue_fold,
    continue_periodic,
    harmonic_balance,
    shooting,
    switch_branch,
)
from symosc.errors import ParameterError

x, v, t, w, F = sp.symbols("x v t w F")
DUFFING = -0.1 * v - x - 0.5 * x**3 + F * sp.cos(w * t)


@pytest.fixture(scope="module")
def duffing():
    hb = harmonic_balance(DUFFING, x, v, t, forcing_frequency=w, values={"F": 0.3}, tol=1e-10)
    return hb, continue_periodic(hb, w, (0.6, 2.0))


def test_duffing_branch_has_two_folds_and_the_middle_part_unstable(duffing):
    _, br = duffing
    folds = br.of_kind("fold")
    assert len(folds) == 2 and all(f.located for f in folds)
    hi, lo = folds[0].parameter, folds[1].parameter
    assert hi > lo
    # stability changes exactly at the folds: the part between them (in arclength) is unstable
    i, j = folds[0].index, folds[1].index
    assert br.stable[: i + 1].all() and not br.stable[i + 1 : j + 1].any() and br.stable[j + 1 :].all()
    assert np.all(br.residual <= 1e-10)
    for f in folds:  # at a fold one multiplier is +1
        assert np.min(np.abs(f.multipliers - 1)) < 1e-6


def test_fold_agrees_with_shooting(duffing):
    _, br = duffing
    fold = br.of_kind("fold")[0]
    sh = shooting(DUFFING, x, v, t, forcing_frequency=w, values={"F": 0.3})
    start = br.parameter[fold.index]
    brs = continue_periodic(
        sh, w, (start, start + 0.01), start=br.solution(fold.index), step=0.002, max_step=0.004, detect=["fold"]
    )
    (f2,) = brs.of_kind("fold")
    assert f2.parameter == pytest.approx(fold.parameter, abs=1e-8)
    assert f2.amplitude == pytest.approx(fold.amplitude, abs=1e-6)
    # the state at t = 0 reported with the fold: Fourier series (harmonic balance) against the period map's fixed point
    np.testing.assert_allclose(f2.initial_state, fold.initial_state, atol=1e-8)


def test_a_fold_right_after_the_start_is_found_when_the_branch_turns_out_of_the_span(duffing):
    """Started from a point of the branch just before a fold, at the low end of the span, with a long step: the step
    turns round the fold and leaves the span, and the fold is still located (where the full branch has it).  The
    start, a solution with many harmonics, is not cut to the adaptive problem's first 3 harmonics (Newton's method
    fails from the cut series this close to the fold)."""
    hb, br = duffing
    fold = br.of_kind("fold")[0]
    for i in (fold.index, fold.index - 1):
        short = continue_periodic(hb, w, (br.parameter[i], fold.parameter + 0.05), start=br.solution(i), step=0.2)
        (found,) = short.bifurcations
        assert found.kind == "fold" and found.parameter == pytest.approx(fold.parameter, abs=1e-9)


def test_weakly_nonlinear_folds_approach_averaging():
    """mu = 0.05, zeta = 0.02, R = 0.1: averaging puts the folds at nu = 1.06089, 1.09458 (docs example)."""
    from symosc.nonlinear import averaged_equations

    mu, zeta, R = 0.05, 0.02, 0.1
    X, V = sp.symbols("x v", real=True)
    avg = averaged_equations(X + sp.Rational(1, 20) * X**3 + sp.Rational(1, 25) * V, forcing=sp.Rational(1, 10))
    ref = sorted(avg.frequency_response({}, (0.95, 1.15), n=201).jump_frequencies)
    hb = harmonic_balance(-2 * zeta * v - x - mu * x**3 + R * sp.cos(w * t), x, v, t, forcing_frequency=w, tol=1e-10)
    br = continue_periodic(hb, w, (0.95, 1.15), detect=["fold"], stability=False, max_step=0.05)
    got = sorted(b.parameter for b in br.bifurcations)
    # first-order averaging is accurate to O(mu a^2)^2 ~ 1e-4 here
    np.testing.assert_allclose(got, ref, atol=5e-4)


def test_fold_curve_has_a_cusp_and_passes_through_one_parameter_folds(duffing):
    hb, br = duffing
    curve = continue_fold(hb, br, br.of_kind("fold")[0], F, (0.02, 0.3), max_step=0.02)
    assert len(curve.cusps) == 1
    Fc, wc = curve.cusps[0]
    assert 0.05 < Fc < 0.1 and 1.0 < wc < 1.2
    # independent check: one-parameter continuation at F = 0.15 finds folds on the curve
    hb2 = hb.with_values({"F": 0.15})
    folds = [b.parameter for b in continue_periodic(hb2, w, (0.8, 1.6), detect=["fold"], stability=False).bifurcations]
    P = np.column_stack([curve.fold_parameter, curve.parameter])
    for f in folds:  # distance from (f, 0.15) to the polyline of the curve
        q = np.array([f, 0.15])
        a, b = P[:-1], P[1:]
        s = np.clip(np.einsum("ij,ij->i", q - a, b - a) / np.einsum("ij,ij->i", b - a, b - a), 0, 1)
        d = np.min(np.linalg.norm(a + s[:, None] * (b - a) - q, axis=1))
        assert d < 1e-4
    assert len(folds) == 2


def test_period_doubling_of_the_parametric_oscillator_and_switching():
    """x'' + 0.1x' + (1 - F cos 2t) x + x^3 = 0: the trivial solution doubles its period where the linear Mathieu
    equation has the multiplier -1 (symosc.periodic.monodromy); the new branch is a period-2 orbit (simulation)."""
    from scipy.optimize import brentq

    from symosc.periodic import monodromy
    from symosc.symbols import t as T_

    a = -0.1 * v - (1 - F * sp.cos(w * t)) * x - x**3
    hb = harmonic_balance(a, x, v, t, forcing_frequency=w, values={"w": 2.0}, harmonics=8, tol=1e-8)
    br = continue_periodic(hb, F, (0.05, 0.4), start=np.zeros((1, 17)))
    (pd,) = br.of_kind("period_doubling")
    Fs = sp.Symbol("Fs")
    A = sp.Matrix([[0, 1], [-(1 - Fs * sp.cos(2 * T_)), -0.1]])

    def g(Fv: float) -> float:
        rho = monodromy(A, np.pi, values={"Fs": Fv}, reversor=None).floquet_multipliers
        return float(np.min(rho.real)) + 1.0

    F_ref = brentq(g, 0.1, 0.4, xtol=1e-13)
    assert pd.parameter == pytest.approx(F_ref, abs=1e-8)
    new = switch_branch(hb, br, pd, span=(0.05, 0.4), max_points=30)
    sol = new.solution(len(new) - 1)
    assert sol.amplitude > 1e-3 and sol.frequency == pytest.approx(1.0)  # period 2 pi: twice the forcing period
    Fv = sol.values["F"]

    def f(tt, y):
        return [y[1], -0.1 * y[1] - (1 - Fv * np.cos(2 * tt)) * y[0] - y[0] ** 3]

    y0 = sol.initial_state
    one = solve_ivp(f, (0, np.pi), y0, rtol=1e-12, atol=1e-13).y[:, -1]
    two = solve_ivp(f, (0, 2 * np.pi), y0, rtol=1e-12, atol=1e-13).y[:, -1]
    assert np.linalg.norm(two - y0) < 1e-6 < np.linalg.norm(one - y0)


def test_branch_results_plot_label_and_pickle(duffing):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    _, br = duffing
    assert isinstance(br, Branch) and len(br) == len(br.amplitude) == len(br.stable)
    ax = br.plot()
    assert ax.get_lines() and any(line.get_linestyle() == "--" for line in ax.get_lines())
    plt.close("all")
    ds = br.to_xarray()
    assert ds.sizes["point"] == len(br) and "multipliers" in ds and ds.attrs["parameter"] == "w"
    back = pickle.loads(pickle.dumps(br))
    assert repr(back) == repr(br)
    sol = br.solution(10)
    assert sol.values["w"] == br.parameter[10] and sol.harmonics == br.size[10]


def test_continuation_arguments_are_checked(duffing):
    hb, br = duffing
    with pytest.raises(ParameterError, match="span"):
        continue_periodic(hb, w, (1.0, 1.0))
    with pytest.raises(ParameterError, match="parameter"):
        continue_periodic(hb, "nope", (0.5, 1.0))
    with pytest.raises(ParameterError, match="detect"):
        continue_periodic(hb, w, (0.5, 1.0), detect=["hopf"])
    with pytest.raises(ParameterError, match="problem"):
        continue_periodic("duffing", w, (0.5, 1.0))
    with pytest.raises(ParameterError, match="bifurcation"):
        switch_branch(hb, br, br.bifurcations[0])
