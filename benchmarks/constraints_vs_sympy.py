"""Constrained derivation speed: symosc multiplier form vs sympy.physics.mechanics.LagrangesMethod(hol_coneqs=...).

System: the n-link point-mass pendulum with its tip held on the vertical through the pivot,
``sum_i l_i sin(phi_i) = 0`` (one holonomic constraint).  Timed from the energies (T, V and the constraint
expression, built once outside the timings; SymPy's cache cleared before each timing) to the augmented matrix
``[[M, -C^T], [C, 0]]`` and right-hand side ``[F; -gamma]``:

- symosc: ``LagrangianSystem(T, V, q, constraints=[...]).constrained.augmented_mass_matrix / _forcing``;
- sympy: vectors -> ``Lagrangian`` -> ``LagrangesMethod(L, q, hol_coneqs=[...])`` -> ``mass_matrix_full``,
  ``forcing_full``;
- symosc unconstrained: the same chain without the constraint (``mass_matrix``, ``forcing``), the target being a
  constrained/unconstrained ratio within 3x.

The accelerations of both constrained forms are checked to agree at random states before any time is reported.

    python benchmarks/constraints_vs_sympy.py            # n = 2..10
    python benchmarks/constraints_vs_sympy.py --quick    # n = 2..5
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import sympy as sp
from sympy.core.cache import clear_cache
from sympy.physics.mechanics import LagrangesMethod, Lagrangian, Particle, Point, ReferenceFrame, dynamicsymbols

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from symosc.mechanics import LagrangianSystem
from symosc.models import n_link_pendulum
from symosc.symbols import dot, t


def tip_constraint(system) -> sp.Expr:
    n = len(system.coordinates)
    ls = sp.symbols(f"l1:{n + 1}", positive=True)
    return sp.Add(*(li * sp.sin(q) for li, q in zip(ls, system.coordinates, strict=True)))


def energies(n: int):
    """T, V and the coordinates of the chain (built once, outside the timings)."""
    base = n_link_pendulum(n)
    return base.kinetic_energy, base.potential_energy, base.coordinates, tip_constraint(base)


def derive_unconstrained(n: int):
    T, V, q, _ = energies(n)
    clear_cache()
    start = time.perf_counter()
    s = LagrangianSystem(T, V, q)
    s.mass_matrix, s.forcing  # noqa: B018
    return time.perf_counter() - start


def derive_symosc(n: int):
    T, V, q, con = energies(n)
    clear_cache()
    start = time.perf_counter()
    s = LagrangianSystem(T, V, q, constraints=[con])
    A, b = s.constrained.augmented_mass_matrix, s.constrained.augmented_forcing
    return time.perf_counter() - start, s, A, b


def derive_sympy(n: int):
    clear_cache()
    start = time.perf_counter()
    q = dynamicsymbols(f"phi1:{n + 1}")
    m = sp.symbols(f"m1:{n + 1}", positive=True)
    ls = sp.symbols(f"l1:{n + 1}", positive=True)
    g = sp.Symbol("g", positive=True)
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    pos = 0 * N.x
    bodies = []
    for k in range(n):
        pos = pos + ls[k] * (sp.sin(q[k]) * N.x - sp.cos(q[k]) * N.y)
        P = Point(f"P{k + 1}")
        P.set_pos(O, pos)
        P.set_vel(N, pos.dt(N))
        b = Particle(f"B{k + 1}", P, m[k])
        b.potential_energy = m[k] * g * pos.dot(N.y)
        bodies.append(b)
    L = Lagrangian(N, *bodies)
    con = sp.Add(*(li * sp.sin(qk) for li, qk in zip(ls, q, strict=True)))
    lm = LagrangesMethod(L, q, hol_coneqs=[con])
    lm.form_lagranges_equations()
    Mf, Ff = lm.mass_matrix_full, lm.forcing_full
    elapsed = time.perf_counter() - start
    repl = {}
    for k in range(n):
        phi = sp.Symbol(f"phi{k + 1}", real=True)
        repl[q[k].diff(t)] = dot(phi)
        repl[q[k]] = phi
    return elapsed, Mf.xreplace(repl), Ff.xreplace(repl)


def agree(s, A, b, Mf, Ff, rng) -> float:
    """Largest relative difference of the accelerations at three random states and parameter sets."""
    n = len(s.coordinates)
    args = [*s.coordinates, *s.velocities, *s.parameters]
    fa = sp.lambdify(args, A.row_join(b), "numpy")
    fr = sp.lambdify(args, Mf.row_join(Ff), "numpy")
    worst = 0.0
    for _ in range(3):
        vals = [*rng.uniform(-1, 1, n), *rng.uniform(-1, 1, n), *rng.uniform(0.5, 2.0, len(s.parameters))]
        a = np.asarray(fa(*vals), dtype=float)
        r = np.asarray(fr(*vals), dtype=float)
        ours = np.linalg.solve(a[:, :-1], a[:, -1])[:n]
        ref = np.linalg.solve(r[:, :-1], r[:, -1])[n : 2 * n]
        worst = max(worst, float(np.max(np.abs(ours - ref)) / np.max(np.abs(ref))))
    return worst


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    sizes = range(2, 6) if args.quick else range(2, 11)
    rng = np.random.default_rng(0)
    print(
        f"{'n':>3} {'constrained, s':>15} {'unconstrained, s':>17} {'ratio':>6} {'sympy, s':>9} "
        f"{'sympy/ours':>11} {'max rel diff':>13}"
    )
    for n in sizes:
        tc, s, A, b = derive_symosc(n)
        tu = derive_unconstrained(n)
        tr, Mf, Ff = derive_sympy(n)
        diff = agree(s, A, b, Mf, Ff, rng)
        if diff > 1e-9:
            print(f"n={n}: results DISAGREE (max relative difference {diff:.2e})")
            return 1
        print(f"{n:>3} {tc:>15.3f} {tu:>17.3f} {tc / tu:>5.2f}x {tr:>9.3f} {tr / tc:>10.1f}x {diff:>13.1e}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
