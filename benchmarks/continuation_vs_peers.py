"""symosc.continuation against independent computations: shooting, long integration, scipy's solve_bvp.

Run: ``python benchmarks/continuation_vs_peers.py`` (a few minutes on one core).  Prints the table
task | symosc | peer | ratio | agreement recorded in docs/performance.md ("Continuation").
"""

from __future__ import annotations

import sys
import time

import numpy as np
import sympy as sp
from scipy.integrate import solve_bvp, solve_ivp

from symosc.continuation import (
    collocation,
    continue_periodic,
    harmonic_balance,
    orbit_multipliers,
    shooting,
    switch_branch,
)

x, v, t, w, F, eps = sp.symbols("x v t w F eps")
ROWS: list[tuple[str, str, str, str, str]] = []


def row(task: str, ours: float, peer: float | None, agreement: str) -> None:
    ratio = f"{peer / ours:.1f}x" if peer else "-"
    ROWS.append((task, f"{ours:.2f} s", f"{peer:.2f} s" if peer else "-", ratio, agreement))
    print(" | ".join(ROWS[-1]), file=sys.stderr, flush=True)


def hill_vs_monodromy(problem, branch, step: int, harmonics: int) -> float:
    """Largest difference between Hill's multipliers and the monodromy along the same truncated orbit."""
    worst = 0.0
    for k in range(0, len(branch), step):
        sol = branch.solution(k)
        rs = np.sort_complex(orbit_multipliers(problem, sol, along="series"))
        rh = np.sort_complex(orbit_multipliers(problem, sol, method="hill", harmonics=harmonics))
        worst = max(worst, float(np.max(np.abs(rs - rh))))
    return worst


def duffing() -> None:
    a = -0.1 * v - x - x**3 + F * sp.cos(w * t)
    t0 = time.perf_counter()
    hb = harmonic_balance(a, x, v, t, forcing_frequency=w, values={"F": 1.0}, harmonics=10, tol=1e-2)
    cold = time.perf_counter() - t0
    t0 = time.perf_counter()
    br = continue_periodic(hb, w, (0.5, 3.2), max_step=0.025)
    first = time.perf_counter() - t0 + cold
    t0 = time.perf_counter()
    br = continue_periodic(hb, w, (0.5, 3.2), max_step=0.025)
    warm = time.perf_counter() - t0
    folds = br.of_kind("fold")
    sh = shooting(a, x, v, t, forcing_frequency=w, values={"F": 1.0}, rtol=1e-12)
    t0 = time.perf_counter()
    diffs = []
    for f in folds:
        start = br.parameter[f.index]
        brs = continue_periodic(
            sh,
            w,
            (start, start + 0.02 * np.sign(f.parameter - start)),
            start=br.solution(f.index),
            step=0.002,
            max_step=0.004,
            detect=["fold"],
        )
        diffs.append(abs(brs.of_kind("fold")[0].parameter - f.parameter))
    peer = time.perf_counter() - t0
    inside = int(np.sum(br.parameter <= 3.0))
    row(
        f"Duffing FRC, H=10, {len(br)} points ({inside} in w<=3), folds at w = "
        + ", ".join(f"{f.parameter:.10f}" for f in folds),
        warm,
        peer,
        f"folds vs shooting {max(diffs):.1e}; residual {br.residual.min():.0e}..{br.residual.max():.0e}; "
        f"first call {first:.2f} s",
    )
    worst = hill_vs_monodromy(hb, br, 25, 30)
    ROWS.append(("Duffing branch, every 25th point: Hill (H=30) vs monodromy", "-", "-", "-", f"max diff {worst:.1e}"))


def long_period(e: float) -> float:
    """Period of the van der Pol cycle from 60 periods of Radau integration (zero up-crossings, interpolated)."""

    def f(tt, y):
        return [y[1], e * (1 - y[0] ** 2) * y[1] - y[0]]

    def jac(tt, y):
        return [[0.0, 1.0], [-2 * e * y[0] * y[1] - 1.0, e * (1 - y[0] ** 2)]]

    def up(tt, y):
        return y[0]

    up.direction = 1
    sol = solve_ivp(f, (0, 60 * 19.1), [2.0, 0.0], method="Radau", jac=jac, rtol=1e-12, atol=1e-13, events=up)
    ev = sol.t_events[0]
    ev = ev[len(ev) // 4 :]
    return float((ev[-1] - ev[0]) / (len(ev) - 1))


def van_der_pol() -> None:
    a = eps * (1 - x**2) * v - x
    g = harmonic_balance(a, x, v, t, autonomous=True, values={"eps": 0.01}).solve()
    sh = shooting(a, x, v, t, autonomous=True, values={"eps": 0.01}, rtol=1e-12)
    t0 = time.perf_counter()
    br = continue_periodic(sh, eps, (0.01, 10.0), start=g, step=0.05, max_step=1.0)
    ours = time.perf_counter() - t0
    T_ours = 2 * np.pi / br.frequency[-1]
    t0 = time.perf_counter()
    T_ref = long_period(10.0)
    peer = time.perf_counter() - t0
    row(
        f"van der Pol eps 0.01->10 (shooting, {len(br)} points), T(10) = {T_ours:.12f}",
        ours,
        peer,
        f"vs 60-period Radau: {abs(T_ours - T_ref):.1e}",
    )
    # collocation at eps = 10 from the shooting orbit, and scipy's solve_bvp on the same orbit
    sol = br.solution(len(br) - 1)
    t0 = time.perf_counter()
    co = collocation(a, x, v, t, autonomous=True, values={"eps": 10.0}, intervals=100, tol=1e-6).solve(sol)
    ours = time.perf_counter() - t0
    t0 = time.perf_counter()
    T0 = sol.period
    s = np.linspace(0, 1, 400)
    y_guess = solve_ivp(
        lambda tt, y: [y[1], 10 * (1 - y[0] ** 2) * y[1] - y[0]],
        (0, T0),
        sol.initial_state,
        method="Radau",
        rtol=1e-10,
        atol=1e-12,
        dense_output=True,
    ).sol(s * T0)

    def fb(ss, y, p):
        return p[0] * np.vstack([y[1], 10 * (1 - y[0] ** 2) * y[1] - y[0]])

    def bc(ya, yb, p):
        return np.array([ya[0] - yb[0], ya[1] - yb[1], ya[1]])

    bvp = solve_bvp(fb, bc, s, y_guess, p=[T0], tol=1e-9, max_nodes=200000)
    peer = time.perf_counter() - t0
    row(
        f"van der Pol eps=10: collocation ({co.size} intervals) vs scipy solve_bvp ({len(bvp.x)} nodes)",
        ours,
        peer,
        f"T: {abs(co.period - T_ours):.1e} (coll-shoot), {abs(bvp.p[0] - T_ours):.1e} (solve_bvp-shoot)",
    )
    # the order-20 series at small eps
    from symosc.nonlinear import limit_cycle

    lc = limit_cycle((1 - x**2) * v, 20, x=x, v=v)
    hb = harmonic_balance(a, x, v, t, autonomous=True, values={"eps": 0.01}, tol=1e-12)
    t0 = time.perf_counter()
    brh = continue_periodic(hb, eps, (0.01, 0.3), max_step=0.05)
    ours = time.perf_counter() - t0
    err = max(abs(brh.frequency[i] - float(lc.frequency.evaluate(brh.parameter[i]))) for i in range(len(brh)))
    row("van der Pol eps 0.01->0.3 (harmonic balance) vs order-20 series", ours, None, f"max |omega diff| {err:.1e}")
    worst = hill_vs_monodromy(hb, brh, 1, 2 * int(brh.size.max()))
    ROWS.append(("van der Pol HB branch, every point: Hill vs monodromy", "-", "-", "-", f"max diff {worst:.1e}"))


def pendulum() -> None:
    a = -0.5 * v - sp.sin(x) + F * sp.cos(w * t)
    hb = harmonic_balance(a, x, v, t, forcing_frequency=w, values={"w": 2 / 3}, harmonics=24, tol=1e-7)
    t0 = time.perf_counter()
    br = continue_periodic(hb, F, (0.9, 1.1), max_step=0.01)
    (bp,) = br.of_kind("branch_point")
    asym = switch_branch(hb, br, bp, span=(0.9, 1.2), max_step=0.005)
    pd = asym.of_kind("period_doubling")[0]
    ours = time.perf_counter() - t0
    # simulation: multiplier -1 by the variational equations at the located point; the doubled orbit after switching
    t0 = time.perf_counter()
    sol = asym.solution(pd.index)
    sh = shooting(a, x, v, t, forcing_frequency=w, values={"w": 2 / 3, "F": pd.parameter}, rtol=1e-12)
    exact = sh.solve(sol)
    rho = orbit_multipliers(sh, exact)
    dbl = switch_branch(hb, asym, pd, span=(pd.parameter - 0.02, pd.parameter + 0.02), max_points=15)
    last = dbl.solution(len(dbl) - 1)
    Fv = last.values["F"]

    def f(tt, y):
        return [y[1], -0.5 * y[1] - np.sin(y[0]) + Fv * np.cos(2 / 3 * tt)]

    T = 3 * np.pi
    y0 = last.initial_state
    one = solve_ivp(f, (0, T), y0, method="DOP853", rtol=1e-12, atol=1e-13).y[:, -1]
    two = solve_ivp(f, (0, 2 * T), y0, method="DOP853", rtol=1e-12, atol=1e-13).y[:, -1]
    peer = time.perf_counter() - t0
    row(
        f"forced pendulum: pitchfork F={bp.parameter:.10f}, period doubling F={pd.parameter:.10f}",
        ours,
        peer,
        f"min|rho+1| by simulation {np.min(np.abs(rho + 1)):.1e}; doubled orbit |y(2T)-y0| "
        f"{np.linalg.norm(two - y0):.0e}, |y(T)-y0| {np.linalg.norm(one - y0):.1e}",
    )
    worst = max(hill_vs_monodromy(hb, br, 10, 48), hill_vs_monodromy(hb, asym, 40, 48))
    ROWS.append(
        ("pendulum branches, every 10th/40th point: Hill (H=48) vs monodromy", "-", "-", "-", f"max diff {worst:.1e}")
    )


def main() -> None:
    duffing()
    van_der_pol()
    pendulum()
    widths = [max(len(r[i]) for r in [("task", "symosc", "peer", "ratio", "agreement"), *ROWS]) for i in range(5)]
    head = ("task", "symosc", "peer", "ratio", "agreement")
    print(" | ".join(h.ljust(wd) for h, wd in zip(head, widths, strict=True)))
    print("-|-".join("-" * wd for wd in widths))
    for r in ROWS:
        print(" | ".join(c.ljust(wd) for c, wd in zip(r, widths, strict=True)))


if __name__ == "__main__":
    main()
