"""Simulation: symosc's ``LagrangianSystem.simulate`` vs PyDy's ``System.integrate`` (Cython generator), plus the
energy drift, the GIF writer and the cost of presentation-ready simplification.

1. The n-link point pendulum (default n = 10) over 10 s, 1001 output times, both with LSODA (``odeint``) at the
   same tolerances, derivation and code generation done beforehand (PyDy: KanesMethod + Cython module built once;
   symosc: equations derived and the generated C in its disk cache).  Timed: one call of ``System.integrate()``
   against one call of ``system.simulate(...)`` (which builds its evaluator from the cache, integrates, and
   computes the energy along the motion).  Trajectories are compared before any time is reported.
2. Relative energy drift of a conservative double pendulum over 100 periods of its slow mode at rtol = 1e-12.
3. Writing a 200-frame GIF of the double pendulum.
4. Derivation time of M and F for n = 1..10 with ``simplify=True`` (default) and ``simplify=False``: CPU time of
   this process (other jobs on the machine do not count), SymPy's cache cleared before each derivation (a user
   derives a model once), best of 5.

    python benchmarks/simulation_vs_pydy.py            # n = 10 (the Cython build takes a minute or two)
    python benchmarks/simulation_vs_pydy.py --n 4      # a quicker comparison
    python benchmarks/simulation_vs_pydy.py --only-simplification
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import sympy as sp

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from symosc.mechanics import LagrangianSystem
from symosc.models import n_link_pendulum


def best(fn, repeat: int = 3) -> tuple[float, object]:
    out, times = None, []
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return min(times), out


def pydy_chain(n: int, values: dict, q0: np.ndarray, times: np.ndarray, workdir: str):
    """The same chain with sympy.physics.mechanics.KanesMethod and PyDy's System (Cython generator)."""
    from pydy.system import System
    from sympy.physics.mechanics import KanesMethod, Particle, Point, ReferenceFrame, dynamicsymbols

    q = dynamicsymbols(f"q0:{n}")
    u = dynamicsymbols(f"u0:{n}")
    m = sp.symbols(f"m1:{n + 1}", positive=True)
    l = sp.symbols(f"l1:{n + 1}", positive=True)
    g = sp.Symbol("g", positive=True)
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    P, particles, forces, kd = O, [], [], []
    for i in range(n):
        A = N.orientnew(f"A{i}", "Axis", [q[i], N.z])
        A.set_ang_vel(N, u[i] * N.z)
        Pi = P.locatenew(f"P{i}", -l[i] * A.y)  # x = l sin q, y = -l cos q (as symosc's hanging chain)
        Pi.v2pt_theory(P, N, A)
        particles.append(Particle(f"B{i}", Pi, m[i]))
        forces.append((Pi, -m[i] * g * N.y))
        kd.append(q[i].diff() - u[i])
        P = Pi
    start = time.perf_counter()
    kane = KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(particles, forces)
    derive = time.perf_counter() - start
    constants = {**{m[i]: values[f"m{i + 1}"] for i in range(n)}, **{l[i]: values[f"l{i + 1}"] for i in range(n)}}
    constants[g] = values["g"]
    initial = {**{q[i]: q0[i] for i in range(n)}, **{u[i]: 0.0 for i in range(n)}}
    system = System(kane, constants=constants, initial_conditions=initial, times=times)
    cwd = os.getcwd()
    os.chdir(workdir)  # the Cython generator writes its build files in the working directory
    try:
        start = time.perf_counter()
        system.generate_ode_function(generator="cython")
        build = time.perf_counter() - start
    finally:
        os.chdir(cwd)
    return system, derive, build


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--n", type=int, default=10)
    ap.add_argument("--only-simplification", action="store_true")
    args = ap.parse_args(argv)
    if args.only_simplification:
        return simplification_cost()
    n = args.n
    rtol = atol = 1e-10
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} (other jobs share it)")

    # 1. symosc vs PyDy --------------------------------------------------------------------------------------
    rng = np.random.default_rng(1)
    values = {**{f"m{i}": float(rng.uniform(0.5, 1.5)) for i in range(1, n + 1)}, "g": 9.81}
    values.update({f"l{i}": float(rng.uniform(0.5, 1.5)) for i in range(1, n + 1)})
    q0 = 0.1 * np.cos(np.arange(n))
    times = np.linspace(0.0, 10.0, 1001)
    initial = {f"phi{i + 1}": q0[i] for i in range(n)}
    start = time.perf_counter()
    system = n_link_pendulum(n)
    system.mass_matrix, system.forcing  # noqa: B018 - derivation
    derive_s = time.perf_counter() - start
    start = time.perf_counter()
    system.simulate(times[:2], initial, values, rtol=rtol, atol=atol)  # generated C built (or read from the cache)
    first_s = time.perf_counter() - start
    t_sym, traj = best(lambda: system.simulate(times, initial, values, rtol=rtol, atol=atol))

    with tempfile.TemporaryDirectory() as work:
        pydy_system, derive_p, build_p = pydy_chain(n, values, q0, times, work)
        t_pydy, ref = best(lambda: pydy_system.integrate(rtol=rtol, atol=atol, mxstep=200_000))
    diff = float(np.max(np.abs(traj.states[:, :n] - ref[:, :n])))
    print(f"\n1. n = {n} point chain, t in [0, 10] s, 1001 outputs, LSODA rtol = atol = {rtol:g}")
    print(f"   max |q_symosc - q_pydy| over the trajectory: {diff:.2e}  (target <= 1e-8)")
    print(f"   {'':28s}{'derive s':>10s}{'build s':>10s}{'integrate s':>13s}{'ratio':>8s}")
    print(f"   {'pydy System.integrate':28s}{derive_p:10.2f}{build_p:10.2f}{t_pydy:13.3f}{1.0:8.2f}")
    print(f"   {'symosc simulate':28s}{derive_s:10.2f}{first_s:10.2f}{t_sym:13.3f}{t_sym / t_pydy:8.2f}")
    print(f"   symosc right-hand-side evaluations: {traj.nfev}; energy drift {traj.energy_drift:.1e}")

    # 2. energy drift -------------------------------------------------------------------------------------------
    double = n_link_pendulum(2)
    dv = {"m1": 1.0, "m2": 1.0, "l1": 1.0, "l2": 1.0, "g": 9.81}
    w1 = double.linearize().natural_frequencies(dv)[0]
    t100 = np.linspace(0, 100 * 2 * np.pi / w1, 5001)
    for method in ("LSODA", "DOP853"):
        start = time.perf_counter()
        tr = double.simulate(t100, {"phi1": 0.3, "phi2": -0.2}, dv, method=method, rtol=1e-12, atol=1e-12)
        sec = time.perf_counter() - start
        print(
            f"\n2. double pendulum, 100 periods, {method}, rtol = 1e-12: relative energy drift "
            f"{tr.energy_drift:.2e} (target <= 1e-9), {sec:.2f} s"
        ) if method == "LSODA" else print(
            f"   same with DOP853: relative energy drift {tr.energy_drift:.2e}, {sec:.2f} s"
        )

    # 3. GIF --------------------------------------------------------------------------------------------------------
    tr = double.simulate(np.linspace(0, 10, 1001), {"phi1": 0.3, "phi2": -0.2}, dv)
    with tempfile.TemporaryDirectory() as work:
        start = time.perf_counter()
        anim = tr.animate(Path(work) / "double.gif", max_frames=200, trail=1.0)
        sec = time.perf_counter() - start
        size = (Path(work) / "double.gif").stat().st_size
    print(f"\n3. {anim.frames}-frame GIF of the double pendulum: {sec:.2f} s (target < 10 s), {size / 1e3:.0f} kB")

    return simplification_cost()


def simplification_cost() -> int:
    """Part 4: derivation of M and F with and without the presentation-ready identities."""
    from sympy.core.cache import clear_cache

    def cpu_best(fn, repeat: int = 5) -> tuple[float, object]:
        out, times = None, []
        for _ in range(repeat):
            clear_cache()
            start = time.process_time()
            out = fn()
            times.append(time.process_time() - start)
        return min(times), out

    print("\n4. derivation of M and F (CPU s, cold SymPy cache, best of 5): simplify=True vs simplify=False")
    print(f"   {'n':>3s}{'simplified s':>14s}{'raw s':>10s}{'ratio':>8s}{'ops simplified':>16s}{'ops raw':>10s}")
    for k in range(1, 11):
        chain = n_link_pendulum(k)
        T, V, q = chain.kinetic_energy, chain.potential_energy, chain.coordinates

        def derive(simplify: bool, T=T, V=V, q=q):
            s = LagrangianSystem(T, V, q, simplify=simplify)
            return s.mass_matrix, s.forcing

        ts, (Ms, Fs) = cpu_best(lambda d=derive: d(True))
        tr_, (Mr, Fr) = cpu_best(lambda d=derive: d(False))
        ops_s = sum(sp.count_ops(e) for e in (*Ms, *Fs))
        ops_r = sum(sp.count_ops(e) for e in (*Mr, *Fr))
        print(f"   {k:3d}{ts:14.4f}{tr_:10.4f}{ts / tr_:8.2f}{ops_s:16d}{ops_r:10d}")
    print("   derivation + first build of the C right-hand side and Jacobian (empty disk cache), wall s:")
    for k in (5, 10):
        chain = n_link_pendulum(k)
        vals = {p.name: 1.0 for p in chain.parameters}
        for simplify in (True, False):
            with tempfile.TemporaryDirectory() as cache:
                os.environ["SYMOSC_CACHE_DIR"] = cache
                from symosc.numeric._build import clear_memory_cache

                clear_memory_cache()
                clear_cache()
                start = time.perf_counter()
                s = LagrangianSystem(chain.kinetic_energy, chain.potential_energy, chain.coordinates, simplify=simplify)
                fo = s.first_order()
                fo.rhs(vals, backend="c"), fo.jacobian(vals, backend="c")
                print(f"   n = {k:2d}, simplify={simplify!s:5s}: {time.perf_counter() - start:7.2f}")
        os.environ.pop("SYMOSC_CACHE_DIR", None)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
