"""Derivation speed: symosc's Lagrange engine vs sympy.physics.mechanics.LagrangesMethod.

Equations of the n-link point-mass pendulum (fixed pivot), from the model definition to the mass matrix and
forcing vector, for n = 2..10 by both, then n = 15..40 by symosc alone.  The two results are checked to agree
numerically at random states and parameters before any time is reported.

    python benchmarks/lagrange_vs_sympy.py            # full run (a few minutes)
    python benchmarks/lagrange_vs_sympy.py --quick    # n = 2..6 and 15
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import sympy as sp

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from symosc.models import n_link_pendulum
from symosc.numeric import compile
from symosc.symbols import t
from tests.mechanics.reference import sympy_pendulum


def derive_symosc(n: int):
    start = time.perf_counter()
    system = n_link_pendulum(n)
    M, F = system.mass_matrix, system.forcing
    return time.perf_counter() - start, system, M, F


def derive_sympy(n: int):
    start = time.perf_counter()
    lm, repl = sympy_pendulum(n, "point", False, "fixed")
    M, F = lm.mass_matrix, lm.forcing
    return time.perf_counter() - start, M.xreplace(repl), F.xreplace(repl)


def agree(system, M, F, M_ref, F_ref, rng) -> float:
    """Largest relative difference of (M, F) at three random states/parameter sets."""
    args = [t, *system.coordinates, *system.velocities, *system.parameters]
    ours = compile(M.row_join(F), args)
    ref = sp.lambdify(args, M_ref.row_join(F_ref), "numpy")  # an independent evaluator for the reference
    worst = 0.0
    for _ in range(3):
        x = [
            0.0,
            *rng.uniform(-np.pi, np.pi, len(system.coordinates)),
            *rng.uniform(-2, 2, len(system.velocities)),
            *rng.uniform(0.5, 2.0, len(system.parameters)),
        ]
        a, b = ours(*x), np.asarray(ref(*x), dtype=float)
        worst = max(worst, float(np.max(np.abs(a - b)) / np.max(np.abs(b))))
    return worst


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    both = range(2, 7) if args.quick else range(2, 11)
    alone = (15,) if args.quick else (15, 20, 30, 40)
    rng = np.random.default_rng(0)
    print(f"{'n':>3} {'symosc, s':>10} {'sympy, s':>10} {'ratio':>8} {'max rel diff':>13}")
    for n in both:
        ts, system, M, F = derive_symosc(n)
        tr, M_ref, F_ref = derive_sympy(n)
        diff = agree(system, M, F, M_ref, F_ref, rng)
        if diff > 1e-10:
            print(f"n={n}: results DISAGREE (max relative difference {diff:.2e})")
            return 1
        print(f"{n:>3} {ts:>10.3f} {tr:>10.3f} {tr / ts:>7.1f}x {diff:>13.1e}", flush=True)
    for n in alone:
        ts, *_ = derive_symosc(n)
        print(f"{n:>3} {ts:>10.3f} {'-':>10} {'-':>8} {'-':>13}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
