"""Import time of symosc and its subpackages, each in a fresh interpreter (best of ``--repeat`` runs).

The target: every subpackage costs at most ``import symosc`` + 150 ms (SciPy submodules and optional libraries are
imported inside the functions that use them).  Also lists which heavy modules each import pulls in.

    python benchmarks/import_time.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time

HEAVY = ("scipy", "matplotlib", "pandas", "xarray", "dask", "tqdm", "numba", "symengine", "control", "pint")
MODULES = ("sympy", "symosc", "symosc.models", "symosc.periodic", "symosc.nonlinear", "symosc.identification")


def wall(statement: str, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", statement], check=True)
        best = min(best, time.perf_counter() - t0)
    return best


def heavy_modules(module: str) -> list[str]:
    code = f"import sys, {module}; print(' '.join(sorted({{m.split('.')[0] for m in sys.modules}})))"
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout.split()
    return [m for m in out if m in HEAVY]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    base = wall("pass", args.repeat)
    times = {m: wall(f"import {m}", args.repeat) - base for m in MODULES}
    print(f"interpreter start-up {base * 1e3:.0f} ms (subtracted); best of {args.repeat} runs")
    print(f"{'module':24s} {'ms':>7s} {'- symosc':>9s}  heavy modules imported")
    for m, t in times.items():
        extra = f"{(t - times['symosc']) * 1e3:+9.0f}" if m.startswith("symosc.") else " " * 9
        print(f"{m:24s} {t * 1e3:7.0f} {extra}  {', '.join(heavy_modules(m)) or '-'}")


if __name__ == "__main__":
    main()
