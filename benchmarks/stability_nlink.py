"""Stability region of inverted N-link pendulums, N = 2..10.

Modified Ince–Strutt diagram (two Mathieu curves, Gribkov & Khokhlov 2015) versus the brute-force reference a
user would otherwise write: Floquet multipliers of the full coupled 2N-dimensional system (monodromy matrix by
DOP853 at rtol 1e-12, half period by reversibility) with the boundary at each q located by Brent's method on
the multiplier indicator max|rho + 1/rho| - 2.  Both locate the same boundaries; the table shows the achieved
agreement (max relative difference), so the timings are at equal boundary accuracy.  A plain grid sweep would
need ~1/accuracy monodromy matrices per q value to reach the same accuracy, so root finding is already the
favourable form of the brute-force method.

Run:  python benchmarks/stability_nlink.py [--quick] [--plot docs/img/stability_nlink.png]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from symosc.models import n_link_pendulum
from symosc.periodic import stability_region


def values_for(n: int) -> dict:
    """A slightly non-uniform chain (masses and lengths decreasing towards the free end), total length 1 m."""
    w = np.linspace(1.0, 0.6, n)
    lengths = w / w.sum()
    vals = {"g": 9.81}
    for i in range(n):
        vals[f"m{i + 1}"] = float(1.0 - 0.3 * i / max(n - 1, 1))
        vals[f"l{i + 1}"] = float(lengths[i])
    return vals


def run(ns: list[int], n_q: int) -> list[dict]:
    rows = []
    for n in ns:
        t0 = time.perf_counter()
        sysn = n_link_pendulum(n, inverted=True, pivot="vertical")
        lin = sysn.linearize()
        t_model = time.perf_counter() - t0
        vals = values_for(n)

        t0 = time.perf_counter()
        mod = stability_region(lin, vals)
        t_setup = time.perf_counter() - t0
        rN = mod.ratios[-1]
        qg = np.linspace(0.01, 3.0, 2000) * rN
        q_close = qg[np.argmax(mod.lower(qg) >= mod.upper(qg))]
        q = np.linspace(0.1, 0.95, n_q) * q_close

        t_mod = np.inf  # best of 20 (the machine is shared; the minimum is the least disturbed run)
        for _ in range(20):
            t0 = time.perf_counter()
            lo_m, up_m = mod.lower(q), mod.upper(q)
            t_mod = min(t_mod, time.perf_counter() - t0)

        flo = stability_region(lin, vals, method="floquet")
        t0 = time.perf_counter()
        lo_f, up_f = flo.lower(q), flo.upper(q)
        t_flo = time.perf_counter() - t0
        engine = flo._lower.__self__
        err = max(np.max(np.abs(lo_f / lo_m - 1)), np.max(np.abs(up_f / up_m - 1)))
        rows.append(
            {
                "N": n,
                "r_N": rN,
                "model_s": t_model,
                "setup_s": t_setup,
                "modified_s": t_mod,
                "floquet_s": t_flo,
                "monodromies": engine.evaluations,
                "max_rel_diff": err,
                "speedup": t_flo / t_mod,
                "speedup_with_setup": (t_flo + t_setup) / (t_mod + t_setup),
            }
        )
        r = rows[-1]
        print(
            f"N={n:2d} r_N={rN:.4g} modified {t_mod * 1e3:8.3f} ms  floquet {t_flo:8.2f} s "
            f"({engine.evaluations} monodromy matrices)  max rel diff {err:.1e}  speed-up {r['speedup']:.0f}x",
            flush=True,
        )
    return rows


def table(rows: list[dict], n_q: int) -> str:
    head = (
        f"| N | r_N = (p1/pN)^2 | modified diagram, {2 * n_q} boundary points | Floquet (Brent), same points "
        "| monodromy matrices | max rel. difference | speed-up | speed-up incl. setup |"
    )
    lines = [head, "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['N']} | {r['r_N']:.4g} | {r['modified_s'] * 1e3:.3f} ms | {r['floquet_s']:.2f} s "
            f"| {r['monodromies']} | {r['max_rel_diff']:.1e} | {r['speedup']:.0f}x | {r['speedup_with_setup']:.0f}x |"
        )
    return "\n".join(lines)


def plot(rows: list[dict], path: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    ns = [r["N"] for r in rows]
    ax1.semilogy(ns, [r["modified_s"] for r in rows], "o-", label="modified Ince–Strutt")
    ax1.semilogy(ns, [r["floquet_s"] for r in rows], "s-", label="Floquet + Brent")
    ax1.set_xlabel("number of links N")
    ax1.set_ylabel("time for the boundary points, s")
    ax1.legend()
    ax1.grid(True, which="both", alpha=0.3)
    ax2.semilogy(ns, [r["speedup"] for r in rows], "o-", color="C2")
    ax2.set_xlabel("number of links N")
    ax2.set_ylabel("speed-up (Floquet time / modified time)")
    ax2.grid(True, which="both", alpha=0.3)
    fig.suptitle("Stability region of inverted N-link pendulums: modified diagram vs Floquet")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="N = 2, 3, 5 and 4 q values")
    ap.add_argument("--plot", default=None, help="write a PNG with timings and speed-ups")
    args = ap.parse_args()
    ns = [2, 3, 5] if args.quick else list(range(2, 11))
    n_q = 4 if args.quick else 8
    rows = run(ns, n_q)
    print()
    print(table(rows, n_q))
    if args.plot:
        plot(rows, args.plot)


if __name__ == "__main__":
    main()
