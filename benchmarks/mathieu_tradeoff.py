"""Speed/accuracy trade-off of the Mathieu characteristic-value methods.

1. Power series (exact coefficients, evaluated in float64 by Horner): order vs error vs time for a_0 and b_1 at
   q in {0.1, 0.5, 1, 2}; a_0's series diverges at q = 2 (radius 1.4688), b_1's converges (radius ~3.77).
2. Hill matrix (plain float64 LAPACK bisection, no refinement): matrix size vs error vs time at q in {1, 100, 1e4}.

Reference: symosc "mp" at 50 digits.  Saves docs/img/mathieu_tradeoff.png.

    python benchmarks/mathieu_tradeoff.py [--quick]
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import mpmath
import numpy as np

from symosc.periodic import mathieu_a, mathieu_b
from symosc.periodic._hill import _eigvalue, _matrix, family_index
from symosc.periodic.mathieu_series import _coefficients


def cpu_time_per_call(fn, min_time=0.02):
    """CPU seconds per call, repeating until ``min_time`` has elapsed."""
    calls, t0 = 0, time.process_time()
    while True:
        fn()
        calls += 1
        el = time.process_time() - t0
        if el >= min_time:
            return el / calls


def rel(x, ref) -> float:
    with mpmath.workdps(60):
        return float(abs(mpmath.mpf(float(x)) - ref) / max(1, abs(ref)))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-plot", action="store_true")
    args = ap.parse_args()
    funcs = {("a", 0): mathieu_a, ("b", 1): mathieu_b}
    qs = [0.1, 0.5, 1.0, 2.0]
    orders = list(range(2, 41, 2) if args.quick else range(2, 81, 2))

    print("## Series order vs error vs time (float64 Horner on exact coefficients)\n")
    t0 = time.process_time()
    _coefficients("a", 0, orders[-1])
    _coefficients("b", 1, orders[-1])
    print(f"exact coefficient generation up to order {orders[-1]} for a_0 and b_1: {time.process_time() - t0:.2f} s\n")
    series_rows = {}
    print("| value | q | order | rel. error | us per evaluation |")
    print("|---|---|---|---|---|")
    for (kind, n), f in funcs.items():
        for q in qs:
            ref = f(n, q, method="mp", dps=50)
            errs = []
            for o in orders:
                cs = [c.numerator / c.denominator for c in _coefficients(kind, n, o)][::-1]
                val = np.polyval(cs, q)
                errs.append(rel(val, ref))
                if o in (4, 8, 16, 32, 64, orders[-1]):
                    t = cpu_time_per_call(lambda cs=cs, q=q: np.polyval(cs, q))
                    print(f"| {kind}_{n} | {q} | {o} | {errs[-1]:.1e} | {t * 1e6:.1f} |")
            series_rows[(kind, n, q)] = errs

    print("\n## Hill matrix size vs error vs time (plain float64 LAPACK dstebz, one eigenvalue)\n")
    print("| value | q | matrix size | rel. error | us per eigenvalue |")
    print("|---|---|---|---|---|")
    hill_rows = {}
    for (kind, n), f in funcs.items():
        fam, k = family_index(kind, n)
        for q in (1.0, 100.0, 1e4):
            ref = f(n, q, method="mp", dps=50)
            top = k + 12 + int(2.5 * math.sqrt(q)) + 20
            sizes = sorted({int(s) for s in np.geomspace(k + 2, top, 16 if args.quick else 32)})
            errs = []
            for size in sizes:
                d, e = _matrix(fam, q, size)
                errs.append(rel(_eigvalue(d, e, k), ref))
            hill_rows[(kind, n, q)] = (sizes, errs)
            for size, err in list(zip(sizes, errs, strict=True))[:: max(1, len(sizes) // 8)]:
                d, e = _matrix(fam, q, size)
                t = cpu_time_per_call(lambda d=d, e=e, k=k: _eigvalue(d, e, k))
                print(f"| {kind}_{n} | {q:g} | {size} | {err:.1e} | {t * 1e6:.1f} |")

    print("\n## Full public calls (size chosen and verified automatically), us per value\n")
    print("| value | q | auto | hill | mp (dps=30) | series |")
    print("|---|---|---|---|---|---|")
    for (kind, n), f in funcs.items():
        for q in (0.5, 1.0, 100.0):
            row = []
            for method in ("auto", "hill", "mp", "series"):
                try:
                    f(n, q, method=method)
                    row.append(f"{cpu_time_per_call(lambda f=f, n=n, q=q, m=method: f(n, q, method=m)) * 1e6:.0f}")
                except Exception as exc:  # series beyond its radius
                    row.append(type(exc).__name__)
            print(f"| {kind}_{n} | {q:g} | " + " | ".join(row) + " |")

    if args.no_plot:
        return
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for (kind, n, q), errs in series_rows.items():
        style = "-" if kind == "a" else "--"
        ax1.semilogy(orders, np.maximum(errs, 1e-17), style, color=colours[qs.index(q)], marker=".", ms=3)
        ax1.plot([], [], style, color=colours[qs.index(q)], label=f"{kind}_{n}, q={q}")
    ax1.axhline(1e-13, color="gray", lw=0.8)
    ax1.set(xlabel="series order (highest power of q)", ylabel="relative error", ylim=(1e-17, 10))
    ax1.set_title("Power series (solid a_0, dashed b_1)")
    ax1.legend(fontsize=7, ncol=2)
    for i, ((kind, n, q), (sizes, errs)) in enumerate(hill_rows.items()):
        style = "-" if kind == "a" else "--"
        ax2.loglog(
            sizes, np.maximum(errs, 1e-17), style, color=colours[i % 3], marker=".", ms=3, label=f"{kind}_{n}, q={q:g}"
        )
    ax2.axhline(1e-13, color="gray", lw=0.8)
    ax2.set(xlabel="Hill matrix size", ylabel="relative error", ylim=(1e-17, 10))
    ax2.set_title("Hill matrix, plain float64 (solid a_0, dashed b_1)")
    ax2.legend(fontsize=7)
    fig.tight_layout()
    out = Path(__file__).resolve().parents[1] / "docs" / "img" / "mathieu_tradeoff.png"
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=120)
    print(f"\nplot saved to {out}")


if __name__ == "__main__":
    main()
