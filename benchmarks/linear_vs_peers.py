"""Benchmark: symosc.linear against numpy/scipy root and eigen solvers and python-control.

Part A  Routh–Hurwitz verdicts (exact fraction-free array on the binary value of the float coefficients) against
        ``numpy.roots`` (max real part < 0) for random real polynomials of degree 5, 10, 20, half of them with a
        complex pair at Re = ±1e-12 (near the boundary).  Agreement is judged against SymPy's exact root count in
        the closed right half-plane.
Part B  Modal analysis of uniform and random chains: closed forms and power iteration against
        ``scipy.linalg.eigh``/``eigh_tridiagonal``; Dunkerley and Papkovich bounds (tightness).
Part C  Stability margins and Nyquist counts against python-control (``control.margin``,
        ``control.nyquist_response``).
Part D  Region labels of a 100 x 100 D-partition grid (``DPartition.roots_right``) and of a stability region
        (``StabilityRegion.roots_right``) against ``numpy.roots`` called point by point on the same coefficients;
        the labels must agree everywhere.

Run:  python benchmarks/linear_vs_peers.py [--quick]
"""

from __future__ import annotations

import argparse
import time
from fractions import Fraction

import numpy as np
import scipy.linalg as sla
import sympy as sp

from symosc.linear import (
    chain_matrices,
    d_partition,
    dunkerley,
    dunkerley_bounds,
    hurwitz,
    nyquist,
    power_iteration,
    stability_margins,
    stability_region,
    string_frequencies,
)


def best(fn, repeat=3):
    t = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        t.append(time.perf_counter() - t0)
    return min(t), out


def exact_unstable(c) -> bool:
    ex = [sp.Rational(Fraction(v).numerator, Fraction(v).denominator) for v in c]
    bound = 2 + int(max(abs(v / ex[0]) for v in ex[1:]))
    return sp.Poly(ex, sp.Symbol("x")).count_roots(-bound * sp.I, bound + bound * sp.I) > 0


def part_a(n_poly: int) -> None:
    print("\nPart A: stability verdicts of random real polynomials (times per polynomial)")
    print(
        f"{'degree':>6} {'set':>9} {'symosc hurwitz':>15} {'numpy.roots':>12} {'ratio':>6}"
        f" {'symosc agrees':>14} {'numpy agrees':>13}"
    )
    rng = np.random.default_rng(0)
    for degree in (5, 10, 20):
        for kind in ("generic", "boundary"):
            polys = []
            for _ in range(n_poly):
                roots = []
                while len(roots) < degree - 2:
                    re, im = rng.uniform(-2, 0.3), rng.uniform(0.1, 2)
                    if degree - 2 - len(roots) >= 2 and rng.random() < 0.5:
                        roots += [complex(re, im), complex(re, -im)]
                    else:
                        roots.append(re)
                eps = (1e-12 if kind == "boundary" else 0.1) * rng.choice([-1.0, 1.0])
                roots += [complex(eps, 1.0), complex(eps, -1.0)]
                polys.append([float(v) for v in np.real(np.poly(roots))])
            truth = [not exact_unstable(c) for c in polys]
            ts, vs = best(lambda polys=polys: [hurwitz(c).stable for c in polys])
            tn, vn = best(lambda polys=polys: [bool(np.roots(c).real.max() < 0) for c in polys])
            ag_s = np.mean([a == b for a, b in zip(vs, truth, strict=True)])
            ag_n = np.mean([a == b for a, b in zip(vn, truth, strict=True)])
            print(
                f"{degree:>6} {kind:>9} {ts / n_poly * 1e6:>12.0f} µs {tn / n_poly * 1e6:>9.0f} µs"
                f" {ts / tn:>6.1f} {ag_s:>14.0%} {ag_n:>13.0%}"
            )


def part_b(sizes) -> None:
    print("\nPart B: modal analysis of chains")
    print(
        f"{'n':>5} {'closed form vs eigh':>20} {'t closed':>10} {'t eigh':>9} {'t eigh_tridiag':>15}"
        f" {'power it. z1 err':>17} {'iters':>6} {'t power':>9} {'Dunkerley/ω1':>13} {'Papkovich m=8 ω1 range':>24}"
    )
    for n in sizes:
        M, K = chain_matrices(np.ones(n), np.ones(n + 1))
        tc, wc = best(lambda n=n: string_frequencies(n))
        te, lam = best(lambda M=M, K=K: sla.eigh(K, M, eigvals_only=True))
        tt, _ = best(lambda n=n: sla.eigh_tridiagonal(2 * np.ones(n), -np.ones(n - 1), eigvals_only=True))
        err = np.max(np.abs(wc - np.sqrt(lam)) / np.sqrt(lam))
        # random chain: power iteration on the flexibility form for the fundamental
        rng = np.random.default_rng(n)
        Mr, Kr = chain_matrices(rng.uniform(0.5, 2, n), rng.uniform(0.5, 2, n + 1))
        lr = sla.eigh(Kr, Mr, eigvals_only=True)
        L = np.linalg.solve(Kr, Mr)
        tp, pr = best(lambda L=L, Mr=Mr: power_iteration(L, mass=Mr, max_iterations=200_000), repeat=1)
        zerr = abs(pr.eigenvalues[0] * lr[0] - 1)
        w1 = np.sqrt(lr[0])
        dk = dunkerley(Mr, Kr) / w1
        b = dunkerley_bounds(L, powers=(1, 2, 4, 8))
        rng_txt = f"[{b.omega_lower[-1] / w1:.6f}, {b.omega_upper[-1] / w1:.6f}]"
        print(
            f"{n:>5} {err:>20.1e} {tc * 1e6:>7.0f} µs {te * 1e3:>6.2f} ms {tt * 1e3:>12.2f} ms {zerr:>17.1e}"
            f" {pr.iterations[0]:>6} {tp * 1e3:>6.1f} ms {dk:>13.4f} {rng_txt:>24}"
        )


def part_c() -> None:
    import control

    print("\nPart C: against python-control")
    loops = {
        "2/(D+1)^3": ([2.0], [1, 3, 3, 1]),
        "10/((D+1)(D+2)(D+3))": ([10.0], [1, 6, 11, 6]),
        "(D+2)/(D(D^3+2D^2+3D+4))": ([1.0, 2.0], [1, 2, 3, 4, 0]),
        "5/(D(D^2+2D+2))": ([5.0], [1, 2, 2, 0]),
        "2/(D-1)": ([2.0], [1, -1]),
        "(D+3)/(D^2(D+10))": ([1.0, 3.0], [1, 10, 0, 0]),
    }
    print(
        f"{'K(D)':<26} {'gm symosc':>10} {'gm control':>11} {'pm symosc':>10} {'pm control':>11}"
        f" {'t symosc':>9} {'t control':>10} {'N symosc':>9} {'N control':>10} {'N roots':>8}"
    )
    for name, (num, den) in loops.items():
        ts, m = best(lambda num=num, den=den: stability_margins(num, den))
        sys_ = control.tf(num, den)
        tc, (gm, pm, _, _) = best(lambda sys_=sys_: control.margin(sys_))
        r = nyquist(num, den)
        resp = control.nyquist_response(sys_)
        P = int(np.sum(np.roots(den).real > 1e-12))
        N_control = int(resp.count + P)
        N_roots = int(np.sum(np.roots(np.polyadd(den, num)).real > 0))
        print(
            f"{name:<26} {m.gain_margin:>10.5g} {gm:>11.5g} {m.phase_margin:>10.5g} {pm:>11.5g}"
            f" {ts * 1e6:>6.0f} µs {tc * 1e6:>7.0f} µs {r.closed_loop_roots:>9} {N_control:>10} {N_roots:>8}"
        )


def part_d(n: int) -> None:
    print(f"\nPart D: region labels of a {n} x {n} grid (times per point)")
    lam, mu, nu = sp.symbols("lambda mu nu")
    cases = [
        ("Neimark (8.26)", (lam**2 + lam) * mu + (lam**2 + 1) * nu - lam**2 + 2, 0),
        ("Vyshnegradsky", lam**3 + mu * lam**2 + nu * lam + 1, 0),
        ("degree 6, eps=-0.2", lam**6 + 3 * lam**5 + mu * lam**4 + 5 * lam**3 + nu * lam**2 + 2 * lam + 1, -0.2),
    ]
    print(
        f"{'case':>20} {'grid call':>10} {'point calls':>12} {'numpy.roots':>12} {'grid/roots':>11}"
        f" {'points/roots':>13} {'agree':>6}"
    )
    xs = np.linspace(-4, 6, n)
    X, Y = np.meshgrid(xs, xs)
    for name, F, eps in cases:
        coeffs = [sp.lambdify((mu, nu), c) for c in sp.Poly(F, lam).all_coeffs()]

        def peer(F=F, coeffs=coeffs, eps=eps):
            out = np.empty(X.shape, dtype=int)
            for i, j in np.ndindex(X.shape):
                c = np.trim_zeros(np.array([f(X[i, j], Y[i, j]) for f in coeffs], dtype=float), "f")
                out[i, j] = np.sum(np.roots(c).real > eps)
            return out

        def fresh(F=F, eps=eps):  # a new partition: includes computing its coefficient arrays
            return d_partition(F, lam, (mu, nu), epsilon=eps)

        dp = fresh()
        tg, grid = best(lambda dp=dp: fresh().roots_right(X, Y), repeat=3)
        tp, points = best(lambda dp=dp: np.array([[dp.roots_right(a, b) for a in xs] for b in xs]), repeat=1)
        tr, ref = best(peer, repeat=1)
        agree = bool((grid == ref).all() and (points == ref).all())
        per = X.size
        print(
            f"{name:>20} {tg / per * 1e6:>7.1f} µs {tp / per * 1e6:>9.1f} µs {tr / per * 1e6:>9.1f} µs"
            f" {tg / tr:>11.3f} {tp / tr:>13.2f} {agree!s:>6}"
        )
    x, y = sp.symbols("x y")
    region = stability_region([1, x, y, 1], (x, y))
    tg, grid = best(lambda: stability_region([1, x, y, 1], (x, y)).roots_right({x: X, y: Y}), repeat=3)

    def peer_region():
        return np.array([[np.sum(np.roots([1.0, a, b, 1.0]).real > 0) for a in xs] for b in xs])

    tr, ref = best(peer_region, repeat=1)
    agree = bool((grid == ref).all()) and region.contains({x: 2, y: 1})
    print(
        f"{'stability_region':>20} {tg / X.size * 1e6:>7.1f} µs {'-':>12} {tr / X.size * 1e6:>9.1f} µs"
        f" {tg / tr:>11.3f} {'-':>13} {agree!s:>6}"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer polynomials and smaller chains")
    args = parser.parse_args()
    part_a(10 if args.quick else 40)
    part_b((10, 100) if args.quick else (10, 100, 500))
    part_c()
    part_d(40 if args.quick else 100)


if __name__ == "__main__":
    main()
