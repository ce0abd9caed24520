"""Import time of symosc and its subpackages, each in a fresh interpreter (best of ``--repeat`` runs).

The target: every subpackage costs at most ``import symosc`` + 150 ms (SciPy submodules and optional libraries are
imported inside the functions that use them).  Also lists which heavy modules each import pulls in.

Two tables: as the environment is (with ``PYTHONDONTWRITEBYTECODE=1`` every symosc module is compiled from source on
every import, which is part of what is measured), and with cached bytecode (a private ``PYTHONPYCACHEPREFIX``
directory, one warm-up run per statement: what an installed package costs).

    python benchmarks/import_time.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

HEAVY = ("scipy", "matplotlib", "pandas", "xarray", "dask", "tqdm", "numba", "symengine", "control", "pint")
MODULES = ("sympy", "symosc", "symosc.models", "symosc.periodic", "symosc.nonlinear", "symosc.identification")
#: first use of the series (``symosc.nonlinear`` loads its modules when a name is first read)
FIRST_USE = {"symosc.nonlinear + limit_cycle": "import symosc.nonlinear as nl; nl.limit_cycle"}


def cpu(statement: str, repeat: int, env: dict | None = None) -> tuple[float, float]:
    """Best (CPU time user + sys, wall time) of a fresh interpreter running ``statement``.

    CPU time is what to compare on a shared machine; wall time is inflated by other jobs.
    """
    best_cpu = best_wall = float("inf")
    for _ in range(repeat):
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", statement], check=True, env=env)
        best_wall = min(best_wall, time.perf_counter() - t0)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        best_cpu = min(best_cpu, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime))
    return best_cpu, best_wall


def heavy_modules(module: str) -> list[str]:
    code = f"import sys, {module}; print(' '.join(sorted({{m.split('.')[0] for m in sys.modules}})))"
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout.split()
    return [m for m in out if m in HEAVY]


def table(repeat: int, env: dict | None, title: str) -> None:
    if env is not None:  # warm the bytecode cache
        for statement in ["pass", *(f"import {m}" for m in MODULES), *FIRST_USE.values()]:
            subprocess.run([sys.executable, "-c", statement], check=True, env=env)
    base, base_wall = cpu("pass", repeat, env)
    statements = {m: f"import {m}" for m in MODULES} | FIRST_USE
    res = {m: cpu(st, repeat, env) for m, st in statements.items()}
    times = {m: c - base for m, (c, _) in res.items()}
    print(f"\n{title}: interpreter start-up {base * 1e3:.0f} ms CPU (subtracted); best of {repeat} runs")
    print(f"{'module':32s} {'CPU ms':>7s} {'- symosc':>9s} {'wall ms':>8s}  heavy modules imported")
    for m, t in times.items():
        extra = f"{(t - times['symosc']) * 1e3:+9.0f}" if m.startswith("symosc.") else " " * 9
        wall = (res[m][1] - base_wall) * 1e3
        heavy = ", ".join(heavy_modules(m)) or "-" if m in MODULES else ""
        print(f"{m:32s} {t * 1e3:7.0f} {extra} {wall:8.0f}  {heavy}")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    dont_write = os.environ.get("PYTHONDONTWRITEBYTECODE")
    table(args.repeat, None, f"environment as is (PYTHONDONTWRITEBYTECODE={dont_write or 'unset'})")
    with tempfile.TemporaryDirectory() as prefix:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"} | {"PYTHONPYCACHEPREFIX": prefix}
        table(args.repeat, env, "cached bytecode")


if __name__ == "__main__":
    main()
