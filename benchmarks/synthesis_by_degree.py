"""Time per one-port synthesis by degree: symosc (exact, number-field arithmetic) vs lcapy (Foster/Cauer forms).

Targets are impedances of random networks of positive elements (fixed random generator state):
- LC: Foster sums with distinct rational resonances (degree 2..6); symosc's four forms vs lcapy's
  ``Z.network("cauerI" | "cauerII" | "fosterI" | "fosterII")`` (lcapy has no Brune or Bott–Duffin);
- RLC: random series/parallel trees with ``d`` reactive elements and 1-3 resistors, kept when the impedance has
  degree exactly ``d``; Brune and Bott–Duffin in symosc, counting exact realisations and documented refusals
  (the element values would need a number field of degree > 64 with python-flint, > 8 without).

``--sample N`` adds a larger random sample (random generator state 7: N R-L-C targets of degree 5 and 2N of
degree 6) run with Brune and Bott–Duffin at the default field-degree limit and at each ``--max-degree`` given,
counting exact results, refusals (with the field degree each refused target needed) and calls stopped after
``--timeout`` seconds.

Run: ``python -W ignore benchmarks/synthesis_by_degree.py [--n 6] [--sample 25 --max-degree 40]``.  Wall-clock
medians on a shared machine.
"""

from __future__ import annotations

import argparse
import random
import re
import signal
import statistics
import time

import sympy as sp

from symosc.errors import ModelError
from symosc.networks import (
    Capacitor,
    Inductor,
    Resistor,
    bott_duffin_synthesis,
    brune_synthesis,
    cauer_first,
    cauer_second,
    foster_first,
    foster_second,
)

p = sp.Symbol("p")


def degree(Z):
    N, D = sp.fraction(sp.cancel(Z))
    return max(sp.degree(N, p), sp.degree(D, p))


def rnd(rng):
    return sp.Rational(rng.randint(1, 30), rng.randint(1, 6))


def lc_target(rng, d):
    """Foster sum of degree d: d//2 tanks, plus L p when d is odd."""
    while True:
        w2 = {rnd(rng) for _ in range(d // 2)}
        if len(w2) == d // 2:
            break
    Z = sum((rnd(rng) * p / (p**2 + w) for w in w2), sp.Integer(0))
    if d % 2:
        Z += rnd(rng) * p
    return sp.cancel(Z)


def rlc_target(rng, d):
    def build(items):
        if len(items) == 1:
            return items[0]
        cut = rng.randint(1, len(items) - 1)
        a, b = build(items[:cut]), build(items[cut:])
        return a + b if rng.random() < 0.5 else a | b

    while True:
        leaves = [rng.choice([Inductor, Capacitor])(rnd(rng)) for _ in range(d)]
        leaves += [Resistor(rnd(rng)) for _ in range(rng.randint(1, 3))]
        rng.shuffle(leaves)
        Z = sp.cancel(build(leaves).impedance(p))
        if degree(Z) == d:
            return Z


def timed(f, *args):
    t0 = time.perf_counter()
    out = f(*args)
    return out, time.perf_counter() - t0


def ms(values):
    return f"{1e3 * statistics.median(values):9.1f}" if values else "      n/a"


def lc_table(n, rng):
    import lcapy

    forms = [("foster I", foster_first, "fosterI"), ("foster II", foster_second, "fosterII")]
    forms += [("cauer I", cauer_first, "cauerI"), ("cauer II", cauer_second, "cauerII")]
    print("LC targets: median ms per synthesis (n targets per degree); 'agree' = lcapy's network impedance == target")
    print(f"{'degree':>6} {'form':>10} {'symosc':>9} {'lcapy':>9} {'ratio':>7} {'lcapy agree':>12}")
    for d in range(2, 7):
        targets = [lc_target(rng, d) for _ in range(n)]
        for name, ours, theirs in forms:
            t_ours, t_lc, agree = [], [], 0
            for Z in targets:
                _net, dt = timed(ours, Z, p)
                t_ours.append(dt)
                try:
                    lnet, dt = timed(lcapy.impedance(str(Z).replace("p", "s")).network, theirs)
                    t_lc.append(dt)
                    agree += sp.cancel(sp.sympify(str(lnet.Z.expr)).subs(sp.Symbol("s"), p) - Z) == 0
                except Exception:  # lcapy refuses some irrational expansions
                    pass
            ratio = statistics.median(t_lc) / statistics.median(t_ours) if t_lc else float("nan")
            print(f"{d:>6} {name:>10} {ms(t_ours)} {ms(t_lc)} {ratio:7.2f} {agree:>6}/{len(targets)}")


def rlc_table(n, rng):
    print()
    print("RLC targets (random R-L-C trees): median ms per synthesis, exact / refused (field degree above the limit)")
    print(f"{'degree':>6} {'Brune ms':>9} {'exact':>6} {'refused':>8} {'B-D ms':>9} {'exact':>6} {'refused':>8}")
    for d in range(2, 7):
        row = [f"{d:>6}"]
        targets = [rlc_target(rng, d) for _ in range(n)]
        for synth in (brune_synthesis, bott_duffin_synthesis):
            times, ok, refused = [], 0, 0
            for Z in targets:
                t0 = time.perf_counter()
                try:
                    synth(Z, p)
                    ok += 1
                except ModelError:
                    refused += 1
                times.append(time.perf_counter() - t0)
            row += [ms(times), f"{ok:>6}", f"{refused:>8}"]
        print(" ".join(row))


class _Timeout(Exception):
    pass


def _alarm(*_args):
    raise _Timeout


def sample_table(n, limits, timeout):
    rng = random.Random(7)
    targets = [rlc_target(rng, d) for d in (5, 6, 6) for _ in range(n)]
    print()
    print(f"Random sample (random state 7): {n} R-L-C targets of degree 5, {2 * n} of degree 6; seconds per synthesis")
    head = f"{'method':>12} {'limit':>6} {'exact':>6} {'refused':>8} {'stopped':>8} {'median s':>9} {'max s':>7}"
    print(head + "  field degrees the refused targets needed")
    signal.signal(signal.SIGALRM, _alarm)
    for name, synth in (("Brune", brune_synthesis), ("Bott-Duffin", bott_duffin_synthesis)):
        for limit in limits:
            times, ok, stopped, needed = [], 0, 0, []
            for Z in targets:
                t0 = time.perf_counter()
                signal.alarm(timeout)
                try:
                    synth(Z, p, max_degree=limit)
                    ok += 1
                except ModelError as exc:  # a field-degree refusal names the degree; any other is listed by its text
                    found = re.search(r"degree (\d+) >", str(exc))
                    needed.append(int(found.group(1)) if found else f"other: {str(exc)[:60]}")
                except _Timeout:
                    stopped += 1
                finally:
                    signal.alarm(0)
                times.append(time.perf_counter() - t0)
            shown = "default" if limit is None else str(limit)
            print(
                f"{name:>12} {shown:>6} {ok:>6} {len(needed):>8} {stopped:>8} {statistics.median(times):9.2f} "
                f"{max(times):7.1f}  {sorted(needed, key=lambda v: (isinstance(v, str), str(v).zfill(6)))}",
                flush=True,
            )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=6, help="targets per degree")
    parser.add_argument("--sample", type=int, default=0, help="targets of degree 5 in the random sample (0: none)")
    parser.add_argument("--max-degree", type=int, action="append", default=[], help="a field-degree limit to try")
    parser.add_argument("--timeout", type=int, default=300, help="seconds per synthesis in the sample")
    parser.add_argument("--skip-tables", action="store_true", help="only the random sample")
    args = parser.parse_args()
    rng = random.Random(2026)
    if not args.skip_tables:
        lc_table(args.n, rng)
        rlc_table(args.n, rng)
    if args.sample:
        sample_table(args.sample, [None, *args.max_degree], args.timeout)


if __name__ == "__main__":
    main()
