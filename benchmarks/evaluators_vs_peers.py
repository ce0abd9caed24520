"""Generated evaluators: symosc's backends vs the tools a user would otherwise pick.

Right-hand side y' = f(t, y) of the n-link point pendulum, including the solve of M q'' = F, for
n = 3, 6, 10, 20, by

* symosc ``FirstOrderSystem.rhs(values, backend="numpy")`` and ``backend="c"``;
* ``sympy.lambdify(cse=True)`` of [M | F] with ``numpy.linalg.solve``;
* symengine ``Lambdify(backend="llvm", cse=True)`` of [M | F] with ``numpy.linalg.solve``;
* PyDy's ``generate_ode_function(generator="cython")`` (M q'' = F solved by PyDy with NumPy);
* a numba-jitted lambdify of [M | F] with the solve inside the jitted function.

Reported: per scalar call (µs), 10^4 states in one call (µs per state), one-off build time (first, and cached
where the tool caches), an end-to-end ``solve_ivp`` (RK45, 10 s simulated) at n = 10, and the cost of symosc's
argument checks.  All evaluators are checked to agree (1e-10) before any time is reported.  PyDy, numba and
symengine are benchmark-only dependencies.

    python benchmarks/evaluators_vs_peers.py            # n = 3, 6, 10, 20 (several minutes: Cython builds)
    python benchmarks/evaluators_vs_peers.py --quick    # n = 3, 6
    python benchmarks/evaluators_vs_peers.py --builds   # cold rhs and Jacobian builds vs symengine (n = 10, 20)
    python benchmarks/evaluators_vs_peers.py --defaults # default rhs() backend per call and RK45 (n = 10, 20)
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
import timeit
from pathlib import Path

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from symosc.mechanics.first_order import FirstOrderSystem
from symosc.models import n_link_pendulum
from symosc.numeric import compile
from symosc.numeric._build import clear_memory_cache
from symosc.symbols import t

BATCH = 10_000


def per_call(f, *args, number: int | None = None) -> float:
    """Best of 5 timing runs, µs per call."""
    if number is None:
        start = time.perf_counter()
        f(*args)
        once = max(time.perf_counter() - start, 1e-7)
        number = max(3, int(0.05 / once))
    return min(timeit.repeat(lambda: f(*args), number=number, repeat=5)) / number * 1e6


class Case:
    def __init__(self, n: int) -> None:
        self.n = n
        self.system = n_link_pendulum(n)
        s = self.system
        self.M, self.F = s.mass_matrix, s.forcing  # derivation is not part of any build time
        self.q, self.u, self.params = list(s.coordinates), list(s.velocities), list(s.parameters)
        rng = np.random.default_rng(n)
        self.values = {p.name: (9.81 if p.name == "g" else float(rng.uniform(0.5, 1.5))) for p in self.params}
        self.p = np.array([self.values[p.name] for p in self.params])
        self.y = rng.uniform(-0.5, 0.5, 2 * n)
        self.Y = rng.uniform(-0.5, 0.5, (2 * n, BATCH))


def solve_batched(mf: np.ndarray, n: int, Y: np.ndarray) -> np.ndarray:
    """mf of shape (k, n, n+1) -> (2n, k) derivatives."""
    qdd = np.linalg.solve(mf[:, :, :n], mf[:, :, n:])[..., 0]
    return np.concatenate([Y[n:], qdd.T])


def build_symosc(case: Case, backend: str):
    start = time.perf_counter()
    f = FirstOrderSystem(case.system).rhs(case.values, backend=backend)
    first = time.perf_counter() - start
    cached = None
    if backend == "c":
        clear_memory_cache()
        start = time.perf_counter()
        f = FirstOrderSystem(case.system).rhs(case.values, backend=backend)
        cached = time.perf_counter() - start
    return f, (lambda Y: f(0.0, Y)), first, cached


def build_lambdify(case: Case):
    n, args = case.n, [t, *case.q, *case.u, *case.params]
    start = time.perf_counter()
    mf = sp.lambdify(args, case.M.row_join(case.F), modules="numpy", cse=True)
    first = time.perf_counter() - start
    p = list(case.p)

    def f(time_, y):
        a = mf(time_, *y, *p)
        return np.concatenate([y[n:], np.linalg.solve(a[:, :n], a[:, n])])

    def fb(Y):
        a = np.moveaxis(np.asarray(mf(0.0, *Y, *p), dtype=float), -1, 0)
        return solve_batched(a, n, Y)

    return f, fb, first, None


def build_llvm(case: Case):
    import symengine as se

    n, args = case.n, [t, *case.q, *case.u, *case.params]
    start = time.perf_counter()
    mf = se.Lambdify(args, list(case.M.row_join(case.F)), backend="llvm", cse=True)
    first = time.perf_counter() - start
    p = list(case.p)

    def f(time_, y):
        a = np.asarray(mf([time_, *y, *p])).reshape(n, n + 1)
        return np.concatenate([y[n:], np.linalg.solve(a[:, :n], a[:, n])])

    def fb(Y):
        stacked = np.column_stack([np.zeros(Y.shape[1]), Y.T, np.broadcast_to(case.p, (Y.shape[1], len(p)))])
        a = np.asarray(mf(stacked)).reshape(-1, n, n + 1)
        return solve_batched(a, n, Y)

    return f, fb, first, None


def build_pydy(case: Case, workdir: str):
    from pydy.codegen.ode_function_generators import generate_ode_function
    from sympy.physics.mechanics import dynamicsymbols

    n = case.n
    qf = [dynamicsymbols(f"q{i}") for i in range(n)]
    uf = [dynamicsymbols(f"u{i}") for i in range(n)]
    sub = {**dict(zip(case.q, qf, strict=True)), **dict(zip(case.u, uf, strict=True))}
    M, F = case.M.xreplace(sub), case.F.xreplace(sub)
    cwd = os.getcwd()
    os.chdir(workdir)  # PyDy's Cython generator writes its build files in the working directory
    try:
        start = time.perf_counter()
        rhs = generate_ode_function(
            F, qf, uf, constants=case.params, mass_matrix=M, coordinate_derivatives=sp.Matrix(uf), generator="cython"
        )
        first = time.perf_counter() - start
    finally:
        os.chdir(cwd)
    p = case.p

    def f(time_, y):
        return rhs(y, time_, p).copy()  # PyDy reuses its output buffer; solve_ivp needs a fresh array per call

    def fb(Y):  # PyDy evaluates one state per call: loop in Python
        Yt = np.ascontiguousarray(Y.T)
        return np.column_stack([f(0.0, Yt[k]) for k in range(Yt.shape[0])])

    return f, fb, first, None


def build_numba(case: Case):
    import numba

    n = case.n
    yb, pb = sp.IndexedBase("y"), sp.IndexedBase("p")
    sub = {s: yb[i] for i, s in enumerate([*case.q, *case.u])} | {s: pb[i] for i, s in enumerate(case.params)}
    expr = case.M.row_join(case.F).xreplace(sub)
    start = time.perf_counter()
    mf = numba.njit(sp.lambdify([t, yb.label, pb.label], expr, modules="numpy", cse=True))

    @numba.njit
    def f_jit(time_, y, p):
        a = mf(time_, y, p)
        out = np.empty(2 * n)
        out[:n] = y[n:]
        out[n:] = np.linalg.solve(a[:, :n], a[:, n])
        return out

    @numba.njit
    def fb_jit(Y, p):
        out = np.empty_like(Y)
        for k in range(Y.shape[1]):
            out[:, k] = f_jit(0.0, Y[:, k].copy(), p)
        return out

    f_jit(0.0, case.y, case.p)  # numba compiles on the first call: part of the build
    fb_jit(case.Y[:, :2].copy(), case.p)
    first = time.perf_counter() - start
    p = case.p
    return (lambda time_, y: f_jit(time_, y, p)), (lambda Y: fb_jit(Y, p)), first, None


def _fresh_cache() -> None:
    os.environ["SYMOSC_CACHE_DIR"] = tempfile.mkdtemp(prefix="symosc_bench_cache_")
    clear_memory_cache()


def _timed(fn) -> tuple[float, float]:
    """Wall and CPU seconds of ``fn()`` (CPU: this process and the compilers it ran)."""
    import resource

    r0, c0, w0 = resource.getrusage(resource.RUSAGE_CHILDREN), time.process_time(), time.perf_counter()
    fn()
    r1, c1, w1 = resource.getrusage(resource.RUSAGE_CHILDREN), time.process_time(), time.perf_counter()
    return w1 - w0, (c1 - c0) + (r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime)


def symengine_outputs(case: Case, jacobian: bool):
    """symengine: M, F (and dF/dy, the non-zero dM/dq) differentiated by symengine and LLVM-compiled."""
    import symengine as se

    args = [se.sympify(a) for a in [t, *case.q, *case.u, *case.params]]
    M = se.Matrix(case.M.tolist())
    F = se.Matrix(list(case.F))
    outs = list(M) + list(F)
    if jacobian:
        y = [se.sympify(v) for v in [*case.q, *case.u]]
        outs += list(F.jacobian(se.Matrix(y)))
        outs += [d for v in y[: case.n] for d in M.diff(v) if d != 0]
    return se.Lambdify(args, outs, backend="llvm", cse=True)


def builds(sizes: tuple[int, ...], repeats: int) -> None:
    """Cold builds (fresh disk cache) of the rhs and the analytic Jacobian: symosc C and symosc LLVM (the default
    where no C compiler works) vs symengine LLVM, best of ``repeats`` alternating runs (wall and CPU seconds); M and
    F are derived before the clock starts."""
    print(f"cold builds, best of {repeats} alternating runs; derivation of M and F excluded; wall s (CPU s)")
    head = f"{'n':>3} {'what':<9}{'symosc c':>18}{'symosc llvm':>18}{'symengine llvm':>18}"
    print(head + f"{'c / symengine':>15}{'llvm / symengine':>18}")
    for n in sizes:
        case = Case(n)
        for what, jac in (("rhs", False), ("jacobian", True)):
            runs: dict[str, list] = {"c": [], "llvm": [], "symengine": []}
            for _ in range(repeats):
                for backend in ("c", "llvm"):
                    _fresh_cache()
                    fo = FirstOrderSystem(case.system)
                    build = fo.jacobian if jac else fo.rhs
                    runs[backend].append(_timed(lambda b=build, k=backend, c=case: b(c.values, backend=k)))
                runs["symengine"].append(_timed(lambda c=case, j=jac: symengine_outputs(c, j)))
            (cw, cc), (lw, lc), (tw, tc) = (min(runs[k]) for k in ("c", "llvm", "symengine"))
            print(
                f"{n:3d} {what:<9}{cw:10.2f} ({cc:5.2f}){lw:10.2f} ({lc:5.2f}){tw:10.2f} ({tc:5.2f})"
                f"{cw / tw:15.2f}{lw / tw:18.2f}",
                flush=True,
            )


def defaults(sizes: tuple[int, ...]) -> None:
    """The default ``rhs(values)`` (backend="auto") per call and in RK45, against backend="c" and "numpy"."""
    print("default FirstOrderSystem.rhs(values) vs explicit backends (built once; cached builds not timed)")
    print(f"{'n':>3}{'backend':>10}{'picked':>8}{'µs/call':>10}{'/c':>7}{'RK45 s':>9}{'nfev':>8}")
    for n in sizes:
        case = Case(n)
        rows = {}
        for backend in ("auto", "c", "numpy"):
            f = FirstOrderSystem(case.system).rhs(case.values, backend=backend)
            start = time.perf_counter()
            sol = solve_ivp(f, (0, 10), case.y, method="RK45", rtol=1e-8, atol=1e-10)
            rows[backend] = (f.backend, per_call(f, 0.0, case.y), time.perf_counter() - start, sol.nfev)
        for backend, (picked, us, rk, nfev) in rows.items():
            print(f"{n:3d}{backend:>10}{picked:>8}{us:10.2f}{us / rows['c'][1]:7.2f}{rk:9.2f}{nfev:8d}", flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--builds", action="store_true", help="cold rhs/Jacobian builds: symosc C vs symengine LLVM")
    ap.add_argument("--defaults", action="store_true", help="default rhs() backend per call and in RK45")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--build-only", action="store_true", help="only symosc's build times (numpy and c backends)")
    ap.add_argument("--checks", action="store_true", help="only checked vs unchecked calls on scalars and small arrays")
    ns = ap.parse_args()
    if ns.builds:
        builds((10,) if ns.quick else (10, 20), ns.repeats)
        return
    if ns.defaults:
        defaults((10,) if ns.quick else (10, 20))
        return
    if ns.checks:
        print(f"{'n':>3}{'backend':>8}{'states k':>10}{'checked µs':>12}{'raw µs':>10}{'ratio':>7}")
        for n in (3, 10):
            case = Case(n)
            mf = compile(sp.Matrix.hstack(case.M, case.F), [*case.q, *case.u, *case.params])
            for k in (1, 4, 16, 64):
                vals = [float(v) for v in case.y] if k == 1 else list(case.Y[:, :k])
                vals += list(case.p)
                checked, raw = per_call(mf, *vals), per_call(mf.raw, *vals)
                print(f"{n:3d}{'numpy':>8}{k:10d}{checked:12.2f}{raw:10.2f}{checked / raw:7.2f}")
        return
    sizes = (3, 6) if ns.quick else (3, 6, 10, 20)
    workdir = tempfile.mkdtemp(prefix="symosc_bench_")
    os.environ["SYMOSC_CACHE_DIR"] = os.path.join(workdir, "cache")  # first C builds are really first builds
    if ns.build_only:
        print(f"{'n':>3}{'numpy first s':>15}{'c first s':>11}{'c cached ms':>13}")
        for n in sizes:
            case = Case(n)
            numpy_first = build_symosc(case, "numpy")[2]
            _, _, c_first, c_cached = build_symosc(case, "c")
            print(f"{n:3d}{numpy_first:15.2f}{c_first:11.2f}{c_cached * 1e3:13.1f}")
        return
    names = ["symosc numpy", "symosc c", "sympy lambdify(cse)", "symengine llvm", "pydy cython", "numba lambdify"]
    print(f"machine: {os.cpu_count()} cores, shared with other jobs (timings are noisy; ratios are from one run)")
    e2e_case = None
    results = {}
    for n in sizes:
        case = Case(n)
        builders = {
            "symosc numpy": lambda c=case: build_symosc(c, "numpy"),
            "symosc c": lambda c=case: build_symosc(c, "c"),
            "sympy lambdify(cse)": lambda c=case: build_lambdify(c),
            "symengine llvm": lambda c=case: build_llvm(c),
            "pydy cython": lambda c=case: build_pydy(c, workdir),
            "numba lambdify": lambda c=case: build_numba(c),
        }
        ref = None
        rows = {}
        for name in names:
            f, fb, first, cached = builders[name]()
            val = np.array(f(0.0, case.y))  # copy: PyDy returns a buffer it reuses on the next call
            batch = fb(case.Y)
            if ref is None:
                ref, ref_b = val, batch
            np.testing.assert_allclose(val, ref, rtol=1e-10, atol=1e-10, err_msg=name)
            np.testing.assert_allclose(batch, ref_b, rtol=1e-9, atol=1e-9, err_msg=name)
            scalar = per_call(f, 0.0, case.y)
            if name == "pydy cython":  # no batched entry point: a Python loop over the states, timed on 1000
                batched = per_call(fb, case.Y[:, :1000], number=1) / 1000
            else:
                batched = per_call(fb, case.Y, number=1) / BATCH
            rows[name] = (f, scalar, batched, first, cached)
        results[n] = rows
        if n == 10 or (e2e_case is None and n == sizes[-1]):
            e2e_case = (case, rows)
        base_s, base_b = rows["pydy cython"][1], rows["symengine llvm"][2]
        print(f"\nn = {n} (2n = {2 * n} states)")
        print(
            f"{'evaluator':<22}{'scalar µs':>10}{'/pydy':>7}{'batch µs/state':>16}{'/llvm':>7}"
            f"{'build s':>10}{'cached s':>10}"
        )
        for name, (_, scalar, batched, first, cached) in rows.items():
            cached_s = f"{cached:10.3f}" if cached is not None else f"{'-':>10}"
            print(
                f"{name:<22}{scalar:10.2f}{scalar / base_s:7.2f}{batched:16.3f}{batched / base_b:7.2f}"
                f"{first:10.3f}{cached_s}"
            )

    case, rows = e2e_case
    print(f"\nend to end: solve_ivp(RK45, t in [0, 10], rtol=1e-8, atol=1e-10) at n = {case.n}")
    print(f"{'evaluator':<22}{'seconds':>9}{'nfev':>8}{'/pydy':>7}")
    timings = {}
    for name, (f, *_) in rows.items():
        start = time.perf_counter()
        sol = solve_ivp(f, (0, 10), case.y, method="RK45", rtol=1e-8, atol=1e-10)
        timings[name] = (time.perf_counter() - start, sol.nfev)
    for name, (secs, nfev) in timings.items():
        print(f"{name:<22}{secs:9.2f}{nfev:8d}{secs / timings['pydy cython'][0]:7.2f}")

    print(f"\nchecked vs unchecked scalar call of compile([M | F], ...) at n = {case.n}")
    args = [t, *case.q, *case.u, *case.params]
    point = [0.0, *case.y.tolist(), *case.p.tolist()]
    for backend in ("numpy", "c"):
        fn = compile(case.M.row_join(case.F), args, backend=backend)
        checked, raw = per_call(fn, *point), per_call(fn.raw, *point)
        print(f"{backend:<8} checked {checked:8.2f} µs   raw {raw:8.2f} µs   ratio {checked / raw:5.2f}")
    g, ell = sp.symbols("g l", positive=True)
    small = compile(sp.sqrt(g / ell), [g, ell])
    print(f"numpy sqrt(g/l): checked {per_call(small, 9.81, 2.0):.2f} µs, raw {per_call(small.raw, 9.81, 2.0):.2f} µs")


if __name__ == "__main__":
    main()
