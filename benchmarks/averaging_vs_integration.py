"""Averaging (symosc.nonlinear.averaged_equations) vs direct numerical integration (scipy.integrate.solve_ivp).

Task: the steady forced response of x'' + 2 zeta x' + x + mu x^3 = R cos(nu t) over a frequency band, with both stable
branches in the bistable band and the jump frequencies.  The peer a user would otherwise pick is a brute-force
frequency sweep with solve_ivp (up and down, continuing from the previous state so that both branches are found).

All three small quantities are scaled together by s (mu = 0.05 s, zeta = 0.02 s, R = 0.1 s) so that the error of
first-order averaging, O(s), can be read off the last column.

Run: python benchmarks/averaging_vs_integration.py [--quick]
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from symosc.nonlinear import averaged_equations

x, v = sp.symbols("x v", real=True)
mu_, zeta_, R_ = sp.symbols("mu zeta R", positive=True)


def direct_sweep(vals, nus, periods, direction):
    """Quasi-static sweep: integrate `periods` forcing periods at each nu, continuing from the last state."""
    mu, z, r = vals["mu"], vals["zeta"], vals["R"]
    order = nus if direction > 0 else nus[::-1]
    y = np.array([0.0, 0.0])
    amps = {}
    nfev = 0
    for nu in order:
        T = 2 * math.pi / nu

        def rhs(t, yy, nu=nu):
            return [yy[1], -yy[0] - mu * yy[0] ** 3 - 2 * z * yy[1] + r * math.cos(nu * t)]

        sol = solve_ivp(rhs, (0, periods * T), y, rtol=1e-8, atol=1e-10, dense_output=True)
        nfev += sol.nfev
        tail = np.linspace((periods - 2) * T, periods * T, 200)
        amps[nu] = float(np.max(np.abs(sol.sol(tail)[0])))
        # restart from the same phase of the forcing: the end state is at t = periods*T = 0 mod T
        y = sol.y[:, -1]
    return amps, nfev


def _plot(fr, nus, a_up, a_dn, backbone) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4))
    fr.plot(ax=ax)
    ax.plot(backbone, np.linspace(0.05, 2.6, 200), "k:", lw=0.8, label="backbone")
    ax.plot(nus, a_up, "^", mfc="none", color="C2", ms=5, label="solve_ivp sweep up")
    ax.plot(nus, a_dn, "v", mfc="none", color="C1", ms=5, label="solve_ivp sweep down")
    ax.set_title("x'' + 0.04 x' + x + 0.05 x^3 = 0.1 cos(nu t)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig("docs/img/averaging_duffing.png", dpi=110)
    print("wrote docs/img/averaging_duffing.png")


def main(quick: bool, plot: bool = False) -> None:
    n = 41 if quick else 81
    periods = 100 if quick else 150
    print("forced Duffing x'' + 2 zeta x' + x + mu x^3 = R cos(nu t)")
    print(
        f"{n} frequencies in the band; direct sweeps integrate {periods} forcing periods per frequency (up and down)\n"
    )
    header = (
        f"{'scale s':>7} | {'method':<22} | {'time [s]':>9} | {'ratio':>7} | {'jump down':>9} | {'jump up':>9} | "
        f"{'max |da|/a':>10}"
    )
    print(header)
    print("-" * len(header))
    t0 = time.perf_counter()
    avg = averaged_equations(x + mu_ * x**3 + 2 * zeta_ * v, forcing=R_)
    t_sym = time.perf_counter() - t0
    for s in (0.5, 1.0, 2.0):
        vals = {"mu": 0.05 * s, "zeta": 0.02 * s, "R": 0.1 * s}
        # band around the resonance, scaled with the backbone shift
        nus = np.linspace(0.9, 1.0 + 0.25 * s, n)
        t0 = time.perf_counter()
        fr = avg.frequency_response(vals, (nus[0], nus[-1]), n=len(nus))
        t_avg = time.perf_counter() - t0
        jumps = fr.jump_frequencies
        t0 = time.perf_counter()
        up, _ = direct_sweep(vals, nus, periods, +1)
        down, _ = direct_sweep(vals, nus, periods, -1)
        t_dir = time.perf_counter() - t0
        a_up = np.array([up[nu] for nu in nus])
        a_dn = np.array([down[nu] for nu in nus])
        k_up = int(np.argmax(a_up[:-1] - a_up[1:]))  # sweeping up: drop from the upper branch (jump down)
        k_dn = int(np.argmax(a_dn[:-1] - a_dn[1:]))  # sweeping down: rise onto the upper branch (jump up)
        jd = 0.5 * (nus[k_up] + nus[k_up + 1])
        ju = 0.5 * (nus[k_dn] + nus[k_dn + 1])
        # amplitude error of the averaged stable branches vs the sweeps (same branch = nearest amplitude), away from
        # the folds (within two grid steps of a fold the sweeps have not settled)
        step = nus[1] - nus[0]
        errs = []
        for i, nu in enumerate(nus):
            if any(abs(nu - j) < 2 * step for j in jumps):
                continue
            cand = [fr.amplitudes[i, j] for j in range(fr.amplitudes.shape[1]) if fr.stable[i, j]]
            for a_num in (a_up[i], a_dn[i]):
                a_avg = min(cand, key=lambda c, a_num=a_num: abs(c - a_num))
                errs.append(abs(a_avg - a_num) / a_num)
        err = max(errs)
        if plot and s == 1.0:
            _plot(fr, nus, a_up, a_dn, avg.backbone(vals, np.linspace(0.05, 2.6, 200)))
        label_avg = "averaging (symosc)"
        print(
            f"{s:>7} | {label_avg:<22} | {t_avg:>9.3f} | {1.0:>7.1f} | {max(jumps):>9.4f} | {min(jumps):>9.4f} | "
            f"{err:>10.2e}"
        )
        print(
            f"{s:>7} | {'solve_ivp sweeps':<22} | {t_dir:>9.3f} | {t_dir / t_avg:>7.1f} | {jd:>9.4f} | {ju:>9.4f} | "
            f"{'(ref)':>10}"
        )
    print(f"\nsymbolic averaging (once, reused for every parameter set): {t_sym:.3f} s")
    print("jump frequencies of the sweeps are resolved only to the grid step", f"{(nus[1] - nus[0]):.4f}")


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--plot", action="store_true", help="save docs/img/averaging_duffing.png (s = 1)")
    args = ap.parse_args()
    main(args.quick, args.plot)
