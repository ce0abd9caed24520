"""Benchmark: the 6-DOF stand simulator (virtual experiment of Belyakov 2005) against plain SymPy + lambdify.

The peer is what a SymPy user would write: the whole 12-state right-hand side as one SymPy matrix (numbers
substituted) passed to ``sympy.lambdify`` (with and without ``cse=True``).  symosc compiles the same matrix with
:func:`symosc.numeric.compile` (used by ``simulate_stand``); the "pieces" variant compiles only the rotation and
one spring law and assembles them with NumPy (used for the static equilibrium and the sensor outputs).

Run ``python benchmarks/stand_simulator.py [--quick]``.
"""

from __future__ import annotations

import sys
import time

import numpy as np
import scipy.integrate
import sympy as sp

from symosc.identification.simulator import _compiled, simulate_stand, stand_system
from symosc.models import body_on_springs

VALS = dict(m=15000, rx=2, rz=0.87, Ixx=3000, Iyy=43000, Izz=44000, Ixz=400, Lx=4, Lz=1.74)
VALS.update({f"k{i}": 7.4e5 for i in range(1, 5)})
VALS.update({f"c{i}": 3.1e5 for i in range(1, 5)})
FORCE = [0.0, -2000.0, 0.0, 0.0]


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    quick = "--quick" in argv
    n_samples = 12544 // 4 if quick else 12544
    model = body_on_springs(product_of_inertia="dissertation")

    t0 = time.perf_counter()
    _compiled.cache_clear()
    stand = stand_system(model, VALS)
    setup_pieces = time.perf_counter() - t0
    t0 = time.perf_counter()
    compiled = stand.compiled_rhs
    setup_symosc = time.perf_counter() - t0
    y0 = np.zeros(12)
    y0[3:6] = [1e-3, 2e-3, -1e-3]
    y0[10] = -0.05
    P = np.zeros(4)

    rows = []
    t0 = time.perf_counter()
    rhs_expr, state = stand.rhs_expression()
    derive = time.perf_counter() - t0
    peers = {}
    for label, kw in (("sympy.lambdify", {}), ("sympy.lambdify(cse=True)", {"cse": True})):
        t0 = time.perf_counter()
        f = sp.lambdify(state, rhs_expr, "numpy", **kw)
        peers[label] = (f, derive + time.perf_counter() - t0)

    def rate(fun, n=2000):
        fun(y0)
        t0 = time.perf_counter()
        for _ in range(n):
            fun(y0)
        return n / (time.perf_counter() - t0)

    ref = np.asarray(compiled.raw(*y0), float).ravel()
    rows.append(("symosc compile (full rhs)", setup_symosc, rate(lambda y: compiled.raw(*y)), 0.0))
    err = float(np.max(np.abs(stand.rhs(y0, P) - ref)) / np.max(np.abs(ref)))
    rows.append(("symosc pieces + NumPy", setup_pieces, rate(lambda y: stand.rhs(y, P)), err))
    for label, (f, setup) in peers.items():
        err = float(np.max(np.abs(np.asarray(f(*y0), float).ravel() - ref)) / np.max(np.abs(ref)))
        rows.append((label, setup, rate(lambda y, f=f: np.asarray(f(*y), float).ravel()), err))

    print(f"right-hand side of the 6-DOF stand (12 states, 4 springs)  [{'quick' if quick else 'full'} run]")
    print(f"{'implementation':<28} {'setup s':>9} {'rhs calls/s':>12} {'ratio':>7} {'rel. diff':>10}")
    base = rows[0][2]
    for name, setup, r, err in rows:
        print(f"{name:<28} {setup:>9.2f} {r:>12.0f} {r / base:>7.2f} {err:>10.1e}")

    # full virtual experiment: symosc vs the lambdified peer in the same integrator
    t0 = time.perf_counter()
    rec = simulate_stand(model, VALS, force=FORCE, n_samples=n_samples)
    t_sym = time.perf_counter() - t0
    f_peer = peers["sympy.lambdify(cse=True)"][0]
    y_start = rec.states[:, 0]
    jmax = float(np.max(np.linalg.eigvalsh(np.linalg.inv(stand.Jinv))))  # same tolerances as simulate_stand
    scale = np.concatenate([np.full(3, 100.0 * jmax), np.ones(3), np.full(3, 100.0), np.ones(3)])
    t0 = time.perf_counter()
    sol = scipy.integrate.solve_ivp(
        lambda t, y: np.asarray(f_peer(*y), float).ravel(), (0, rec.t[-1]), y_start, method="DOP853",
        t_eval=rec.t, rtol=1e-10, atol=1e-14 * scale,
    )  # fmt: skip
    t_peer = time.perf_counter() - t0
    diff = float(np.max(np.abs(sol.y - rec.states)[9:12]))
    print(f"\nvirtual experiment: {n_samples} samples, dt = 0.002212 s, DOP853 rtol 1e-10")
    print(f"{'implementation':<28} {'wall s':>9} {'ratio':>7}")
    print(f"{'symosc simulate_stand':<28} {t_sym:>9.2f} {1.0:>7.2f}")
    print(f"{'lambdify(cse) + solve_ivp':<28} {t_peer:>9.2f} {t_peer / t_sym:>7.2f}")
    print(f"max |difference| of the CM displacement: {diff:.2e} m")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
