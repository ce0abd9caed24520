"""Poincaré series for the van der Pol limit cycle: truncation order vs error vs time (exact / float / mpmath).

Compares the series evaluated at eps = 0.1, 0.5, 1 with the numerically located limit cycle (shooting with scipy
DOP853 at rtol 1e-12: the reference the user would otherwise compute), and times the series generation in each
arithmetic against one shooting solve.  Writes docs/img/series_tradeoff.png.

``--exact-growth`` times only the exact series of high order (relaxed block products) against the former
pair-by-pair engine and the float series, with the local cost exponents, the size of the exact result (bits of all
its numerators and denominators, whose growth exponent bounds the cost's from below), and checks that both exact
engines give the same rationals.

    python benchmarks/series_tradeoff.py [--quick | --exact-growth [--max-order 200]]
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import sympy as sp

from symosc.nonlinear import limit_cycle, numeric_limit_cycle

x, v = sp.symbols("x v")
VDP = (1 - x**2) * v


def timed(fn, repeat=1):
    best = float("inf")
    out = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return out, best


def timed_cpu(fn, repeat=1):
    """(result, best wall time, best CPU time of this process): CPU time is what to compare on a shared machine."""
    best = best_cpu = float("inf")
    out = None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        best = min(best, time.perf_counter() - t0)
        best_cpu = min(best_cpu, time.process_time() - c0)
    return out, best, best_cpu


def envelope_error(ref, got, upto):
    """max_k |got_k - ref_k| / max_{|j-k|<=4} |ref_j| over k <= upto (coefficients near a sign change are small)."""
    ref = [float(c) for c in ref[: upto + 1]]
    got = [float(c) for c in got[: upto + 1]]
    return max(
        abs(g - r) / max(abs(c) for c in ref[max(0, k - 4) : k + 5])
        for k, (r, g) in enumerate(zip(ref, got, strict=True))
    )


def high_order() -> None:
    """The long series: exact to eps^48 and eps^100, float to eps^200, mpmath (30 digits) to eps^100."""
    import mpmath

    print("\n== long series (van der Pol), generation time, best of N runs after one warm-up ==")
    limit_cycle(VDP, 48)  # warm: imports, FLINT, caches
    runs = [("exact", 48, 7), ("float", 200, 3), ("mpmath", 100, 1), ("exact", 100, 1), ("mpmath", 120, 1)]
    out = {}
    for ar, n, rep in runs:
        lc, t, c = timed_cpu(lambda ar=ar, n=n: limit_cycle(VDP, n, arithmetic=ar, dps=30), repeat=rep)
        out[(ar, n)] = lc
        print(f"{ar:>7} to eps^{n:<3d}: {t:8.3f} s wall  {c:8.3f} s CPU  (best of {rep})")
    ex, fl, mp = out[("exact", 100)], out[("float", 200)], out[("mpmath", 100)]
    mp120 = out[("mpmath", 120)]

    def worst(a, b, upto):
        rel = [
            abs(float(x) - float(y)) / abs(float(x))
            for x, y in zip(a[: upto + 1], b[: upto + 1], strict=True)
            if x != 0
        ]
        return max(rel)

    for name in ("frequency", "amplitude"):
        e = getattr(ex, name).coefficients
        f = getattr(fl, name).coefficients
        print(
            f"{name:>9}: max relative coefficient difference to exact, orders 0..100: "
            f"mpmath30 {worst(e, getattr(mp, name).coefficients, 100):.1e}, "
            f"float {worst(e, f, 100):.1e} (orders 0..20: {worst(e, f, 20):.1e})"
        )
        e120 = getattr(mp120, name).coefficients
        print(
            f"{name:>9}: float error relative to the neighbouring coefficients' size (|j - k| <= 4), orders 0..N: "
            + ", ".join(f"N={k}: {envelope_error(e120, f, k):.1e}" for k in (20, 40, 60, 80, 100, 120))
        )
    with mpmath.workdps(30):
        radius = ex.frequency.radius_of_convergence()
    print(f"radius of convergence of the frequency series from the exact eps^100 series: {radius}")


def output_bits(lc) -> tuple[int, int, int]:
    """Size of the exact result: (bits of the harmonics, bits of the scalar series, bits of the largest coefficient).

    Every coefficient counts as the bits of its numerator plus those of its denominator in lowest terms: the
    harmonics ``cos``/``sin`` of ``x_0 .. x_N`` and the coefficients of frequency, period, amplitude and Floquet
    exponent.  Any exact algorithm writes at least this many bits, so its cost cannot grow more slowly.
    """
    from fractions import Fraction

    def size(q: Fraction) -> int:
        return abs(q.numerator).bit_length() + q.denominator.bit_length()

    harmonics = largest = 0
    for den, cos, sin in lc._harmonics._raw:
        for c in (*cos, *sin):
            if c:
                b = size(Fraction(c, den))
                harmonics += b
                largest = max(largest, b)
    scalars = 0
    for series in (lc.frequency, lc.period, lc.amplitude, lc.floquet_exponent):
        scalars += sum(size(Fraction(int(c.p), int(c.q))) for c in series.coefficients if c.is_Rational)
    return harmonics, scalars, largest


def _exponent(prev: tuple[int, float] | None, n: int, value: float) -> str:
    """Local growth exponent ``d log value / d log n`` from the previous row, right-aligned in 9 columns."""
    if prev is None:
        return " " * 9
    import math

    return f"{math.log(value / prev[1]) / math.log(n / prev[0]):9.2f}"


def exact_growth(max_order: int = 150) -> None:
    """Exact van der Pol to eps^max_order: CPU time per order, local exponent d log t / d log N, the size of the
    result (its exponent is a lower bound for the cost's), and the pairwise engine up to order 100."""
    import symosc.nonlinear.series.poincare as poincare

    relaxed = poincare.relaxed_exact_arith
    limit_cycle(VDP, 24)  # warm: imports, FLINT, caches
    print("== exact series (van der Pol): CPU seconds of this process, one run each ==")
    print("   output: Mbit of all exact coefficients (numerator + denominator, lowest terms), harmonics + scalars;")
    print("   largest: bits of the largest coefficient; ns/bit: CPU time per output bit")
    print(
        f"{'order':>5} {'relaxed':>9} {'exponent':>9} {'output':>9} {'exponent':>9} {'largest':>8} {'ns/bit':>7} "
        f"{'pairwise':>9} {'exponent':>9} {'same':>5}"
    )
    prev: dict[str, tuple[int, float]] = {}
    orders = [n for n in (48, 60, 80, 100, 120, 150, 200) if n <= max_order]
    for n in orders:
        lc, _, t_new = timed_cpu(lambda n=n: limit_cycle(VDP, n))
        harmonics, scalars, largest = output_bits(lc)
        bits = harmonics + scalars
        row = f"{n:>5d} {t_new:9.2f} {_exponent(prev.get('new'), n, t_new)} "
        row += f"{bits / 1e6:9.2f} {_exponent(prev.get('bits'), n, bits)} {largest:8d} {t_new / bits * 1e9:7.0f} "
        prev["new"], prev["bits"] = (n, t_new), (n, bits)
        if n <= 100:
            poincare.relaxed_exact_arith = lambda: None
            try:
                old, _, t_old = timed_cpu(lambda n=n: limit_cycle(VDP, n))
            finally:
                poincare.relaxed_exact_arith = relaxed
            expo = _exponent(prev.get("old"), n, t_old)
            prev["old"] = (n, t_old)
            same = all(
                getattr(lc, k).coefficients == getattr(old, k).coefficients
                for k in ("frequency", "amplitude", "floquet_exponent")
            ) and tuple(lc._harmonics) == tuple(old._harmonics)
            row += f"{t_old:9.2f} {expo} {same!s:>5}"
        print(row, flush=True)
    _, _, t_float = timed_cpu(lambda: limit_cycle(VDP, 100, arithmetic="float"), repeat=3)
    print(f"float to eps^100: {t_float:.2f} s CPU (best of 3)")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--exact-growth", action="store_true", help="only the high-order exact timings")
    ap.add_argument("--max-order", type=int, default=150, help="highest order of --exact-growth (up to 200)")
    args = ap.parse_args()
    if args.exact_growth:
        exact_growth(args.max_order)
        return
    orders = [2, 4, 8, 12, 16, 24] + ([] if args.quick else [32, 48, 64])
    eps_values = [0.1, 0.5, 1.0]

    print("== generation time (seconds) per order and arithmetic ==")
    print(f"{'order':>5} {'exact':>9} {'float':>9} {'mpmath30':>9}")
    gen = {}
    for n in orders:
        row = []
        for ar in ("exact", "float", "mpmath"):
            lc, t = timed(lambda ar=ar, n=n: limit_cycle(VDP, n, arithmetic=ar, dps=30), repeat=1 if n > 24 else 3)
            gen[(ar, n)] = (lc, t)
            row.append(t)
        print(f"{n:>5d} " + " ".join(f"{t:9.4f}" for t in row))

    if not args.quick:
        high_order()

    print("\n== numeric reference (shooting on v = 0, DOP853 rtol 1e-12) ==")
    refs = {}
    for e in eps_values:
        cyc, t = timed(lambda e=e: numeric_limit_cycle(VDP, e))
        refs[e] = (cyc, t)
        print(f"eps={e:<4} amplitude={cyc.amplitude:.13f} omega={cyc.frequency:.13f}  time={t:.3f} s")

    best = gen[("mpmath", orders[-1])][0]
    radius = best.frequency.radius_of_convergence()
    print(f"\nradius of convergence estimate from {orders[-1]} terms: {radius}")

    print("\n== frequency error |omega_N(eps) - omega_numeric| (series from mpmath arithmetic) ==")
    print(
        f"{'order':>5} "
        + " ".join(f"{'eps=' + str(e):>11}" for e in eps_values)
        + "   predicted (eps/R)^(N+2) at eps=1"
    )
    errs = {e: [] for e in eps_values}
    for n in orders:
        lc = gen[("mpmath", n)][0]
        row = []
        for e in eps_values:
            err = abs(lc.frequency.evaluate(e) - refs[e][0].frequency)
            errs[e].append(max(err, 1e-16))
            row.append(err)
        pred = (1.0 / radius.radius) ** (n + 2)
        print(f"{n:>5d} " + " ".join(f"{r:11.2e}" for r in row) + f"   {pred:9.1e}")

    print("\n== Pade [m/m] in eps^2 from the same coefficients: |omega_Pade - omega_numeric| ==")
    pade_eps = [1.0, 2.0, 3.0]
    prefs = {e: refs[e][0] if e in refs else numeric_limit_cycle(VDP, e) for e in pade_eps}
    print(f"{'order':>5} " + " ".join(f"{'eps=' + str(e):>11}" for e in pade_eps) + "   (series alone at eps=3)")
    for n in orders[2:]:
        lc = gen[("mpmath", n)][0]
        row = [abs(lc.frequency.evaluate_pade(e) - prefs[e].frequency) for e in pade_eps]
        plain = abs(lc.frequency.evaluate(3.0) - prefs[3.0].frequency)
        print(f"{n:>5d} " + " ".join(f"{r:11.2e}" for r in row) + f"   {plain:9.1e}")

    if not args.quick:
        print("\n== high-precision reference at eps = 1 (mpmath.odefun, 20 digits) ==")
        ref_hp, t_hp = timed(lambda: numeric_limit_cycle(VDP, 1.0, dps=20))
        print(f"omega = {ref_hp.frequency}  amplitude = {ref_hp.amplitude}  ({t_hp:.1f} s)")
        import mpmath

        for n in orders[3:]:
            lc = gen[("mpmath", n)][0]
            with mpmath.workdps(30):
                err = abs(lc.frequency.evaluate(1.0, dps=30) - ref_hp.frequency)
                aerr = abs(lc.amplitude.evaluate(1.0, dps=30) - ref_hp.amplitude)
            print(f"order {n:>2d}: |omega error| = {float(err):.2e}   |amplitude error| = {float(aerr):.2e}")

    print("\n== stiff relaxation regime, one limit-cycle solve (series useless here) ==")
    print(f"{'eps':>5} {'method':>7} {'time [s]':>9} {'period':>14} {'amplitude':>12}")
    for e in (10.0, 100.0):
        for method in ("LSODA", "Radau") + (("DOP853",) if e == 10.0 else ()):
            if args.quick and method == "Radau":
                continue
            cyc, t = timed(lambda e=e, method=method: numeric_limit_cycle(VDP, e, method=method, rtol=1e-10))
            print(f"{e:>5g} {method:>7} {t:9.2f} {cyc.period:14.9f} {cyc.amplitude:12.9f}")

    print("\n== time ratio: series generation / one numeric shooting solve (eps = 0.5) ==")
    tnum = refs[0.5][1]
    for n in orders:
        te = gen[("exact", n)][1]
        tf = gen[("float", n)][1]
        print(f"order {n:>2d}: exact {te / tnum:7.3f}x   float {tf / tnum:7.3f}x")

    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:  # pragma: no cover
        return
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    for e in eps_values:
        a1.semilogy(orders, errs[e], "o-", label=f"eps = {e}")
    a1.axhline(1e-11, color="grey", ls=":", lw=1)
    a1.set_xlabel("truncation order N")
    a1.set_ylabel("|omega_N - omega_numeric|")
    a1.set_title("van der Pol frequency series: error")
    a1.legend()
    for ar in ("exact", "float", "mpmath"):
        ns = [n for n in orders if (ar, n) in gen]
        a2.semilogy(ns, [gen[(ar, n)][1] for n in ns], "s-", label=ar)
    a2.axhline(tnum, color="k", ls="--", lw=1, label="one shooting solve")
    a2.set_xlabel("truncation order N")
    a2.set_ylabel("generation time [s]")
    a2.set_title("cost")
    a2.legend()
    fig.tight_layout()
    out = Path(__file__).resolve().parent.parent / "docs" / "img" / "series_tradeoff.png"
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110)
    print(f"\nplot written to {out}")


if __name__ == "__main__":
    main()
