"""Benchmark: symosc.algebra.matrix_function against SymPy's Matrix.exp / analytic_func and scipy.linalg.expm.

Part A (exact and symbolic matrices): time of exp(A t) (and sin(A t)) by symosc and by SymPy, and the largest
difference of the two results evaluated at t = 0.7 with 30 digits.  SymPy's cache is cleared before every run, so
times are cold-start times (best of the repeats).

Part B (float matrices with clustered eigenvalues, gap δ): relative error of exp(A) against a 50-digit mpmath
reference of the same float matrix, for symosc "auto", the plain Sylvester formula, scipy.linalg.expm and SymPy's
Matrix.exp on the float matrix.

Part C (integer matrices with irreducible characteristic polynomials of degree 3 and 4, roots CRootOf): exact
log A, exp A and exp(A t) by symosc against SymPy's Matrix.log / Matrix.exp (60 s limit), and the largest
difference to mpmath's logm / expm of the same matrix at 30 digits (scipy's logm, in double precision, where an
eigenvalue lies on the negative axis: mpmath's logm takes the other side of the cut there).

Run:  python benchmarks/algebra_vs_sympy.py [--quick] [--part C]
"""

from __future__ import annotations

import argparse
import signal
import time

import mpmath
import numpy as np
import scipy.linalg as sla
import sympy as sp

from symosc.algebra import matrix_function

x, t = sp.symbols("x t")
TIMEOUT = 60


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout


def timed(fn, repeat: int, timeout: int | None = None):
    """Best wall time of ``repeat`` runs (seconds) and the last result; (None, None) after ``timeout`` seconds."""
    signal.signal(signal.SIGALRM, _alarm)
    best, out = float("inf"), None
    for _ in range(repeat):
        signal.alarm(timeout or TIMEOUT)
        try:
            sp.core.cache.clear_cache()  # cold SymPy cache: repeated runs must not be served from it
            t0 = time.perf_counter()
            out = fn()
            best = min(best, time.perf_counter() - t0)
        except _Timeout:
            return None, None
        finally:
            signal.alarm(0)
    return best, out


def _fmt_t(v):
    if v is None:
        return f">{TIMEOUT}s"
    return f"{v * 1e6:.0f} µs" if v < 1e-3 else (f"{v * 1e3:.1f} ms" if v < 1 else f"{v:.2f} s")


def _max_diff(F, G, subs) -> float:
    a = F.subs(subs).evalf(30)
    b = G.subs(subs).evalf(30)
    return float(max(abs(sp.N(u - v, 30)) for u, v in zip(a, b, strict=True)))


def part_a(repeat: int) -> None:
    w, z, k = sp.symbols("omega zeta k", positive=True)
    a, b = sp.symbols("a b")
    cases = [
        ("3x3 rational, distinct roots", sp.Matrix([[2, 1, 0], [1, 3, 1], [0, 1, 4]]) / 2, {}),
        ("3x3 Jordan block (triple root)", sp.Matrix([[3, 1, -1], [-1, 1, 1], [1, 1, 2]]), {}),
        ("4x4 derogatory + Jordan", sp.Matrix([[2, 1, 0, 0], [0, 2, 0, 0], [1, 1, 2, 0], [0, 3, 0, -1]]), {}),
        ("3x3 irreducible cubic", sp.Matrix([[1, 2, 0], [0, 3, 1], [1, 0, -2]]), {}),
        ("2x2 symbolic oscillator", sp.Matrix([[0, 1], [-(w**2), -2 * z * w]]), {w: 2, z: sp.Rational(1, 10)}),
        ("3x3 symbolic, repeated root a", sp.Matrix([[a, 1, 0], [0, a, 0], [1, 0, b]]), {a: -1, b: 2}),
        (
            "4x4 symbolic two-mass chain",
            sp.Matrix([[0, 0, 1, 0], [0, 0, 0, 1], [-2 * k, k, 0, 0], [k, -2 * k, 0, 0]]),
            {k: 3},
        ),
    ]
    print("Part A: exp(A t), exact and symbolic matrices (max |symosc - SymPy| at t = 0.7, 30 digits)\n")
    print(f"| {'case':32} | {'symosc':>10} | {'SymPy exp':>10} | {'ratio':>7} | {'max diff':>9} |")
    print(f"|{'-' * 34}|{'-' * 12}|{'-' * 12}|{'-' * 9}|{'-' * 11}|")
    for name, A, subs in cases:
        ts, F = timed(lambda A=A: matrix_function(A, sp.Lambda(x, sp.exp(x * t))), repeat)
        tp, G = timed(lambda A=A: (A * t).exp(), repeat)
        diff = "-" if F is None or G is None else f"{_max_diff(F, G, {**subs, t: sp.Rational(7, 10)}):.1e}"
        ratio = "-" if ts is None or tp is None else f"{tp / ts:.1f}x"
        print(f"| {name:32} | {_fmt_t(ts):>10} | {_fmt_t(tp):>10} | {ratio:>7} | {diff:>9} |")
    print("\nsin(A t) by symosc vs SymPy Matrix.analytic_func(sin(x t), x):\n")
    print(f"| {'case':32} | {'symosc':>10} | {'analytic_func':>13} | {'ratio':>7} | {'max diff':>9} |")
    print(f"|{'-' * 34}|{'-' * 12}|{'-' * 15}|{'-' * 9}|{'-' * 11}|")
    for name, A, subs in cases[:3] + cases[4:5]:
        ts, F = timed(lambda A=A: matrix_function(A, sp.Lambda(x, sp.sin(x * t))), repeat)
        tp, G = timed(lambda A=A: A.analytic_func(sp.sin(x * t), x), repeat)
        diff = "-" if F is None or G is None else f"{_max_diff(F, G, {**subs, t: sp.Rational(7, 10)}):.1e}"
        ratio = "-" if ts is None or tp is None else f"{tp / ts:.1f}x"
        print(f"| {name:32} | {_fmt_t(ts):>10} | {_fmt_t(tp):>13} | {ratio:>7} | {diff:>9} |")


def _near_jordan(delta: float) -> np.ndarray:
    J = np.array([[0.5, 1, 0, 0], [0, 0.5 + delta, 1, 0], [0, 0, 0.5 + 2 * delta, 0], [0, 0, 0, -1.0]])
    S = np.random.default_rng(0).normal(size=(4, 4))
    return S @ J @ np.linalg.inv(S)


def _rel(F: np.ndarray, R: mpmath.matrix) -> float:
    with mpmath.workdps(50):
        n = R.rows
        num = max(abs(mpmath.mpmathify(complex(F[i, j])) - R[i, j]) for i in range(n) for j in range(n))
        return float(num / max(abs(R[i, j]) for i in range(n) for j in range(n)))


def part_b(repeat: int) -> None:
    print("\nPart B: exp(A) for a dense 4x4 float matrix with a 3-eigenvalue cluster 0.5, 0.5+δ, 0.5+2δ")
    print("(Jordan-like coupling) and -1; relative error against 50-digit mpmath expm of the same float matrix.\n")
    cols = ["symosc auto", "plain Sylvester", "scipy expm", "SymPy exp (floats)"]
    hdr = f"| {'δ':>7} | " + " | ".join(f"{c:>22}" for c in cols) + " |"
    print(hdr)
    print("|" + "|".join("-" * (len(c) + 0) for c in hdr.split("|")[1:-1]) + "|")
    for i, delta in enumerate((1e-2, 1e-4, 1e-8, 1e-12, 0.0)):
        A = _near_jordan(delta)
        with mpmath.workdps(50):
            R = mpmath.expm(mpmath.matrix(A.tolist()))
        Am = sp.Matrix(A.tolist())
        runs = {
            "auto": lambda A=A: matrix_function(A, sp.exp),
            "sylv": lambda Am=Am: np.array(matrix_function(Am, sp.exp, method="sylvester"), dtype=float),
            "scipy": lambda A=A: sla.expm(A),
            "sympy": lambda Am=Am: np.array(Am.exp().evalf(), dtype=complex),
        }
        if i > 1:  # SymPy's exp of a float matrix is tried on the first two rows only (it times out)
            runs.pop("sympy")
        cells = []
        for key, fn in runs.items():
            try:
                tm, F = timed(fn, 1, 20) if key == "sympy" else timed(fn, 5 * repeat)
                cells.append("timeout >20 s" if F is None else f"{_rel(F, R):.1e} ({_fmt_t(tm)})")
            except Exception as exc:  # report any failure of a peer in the table
                cells.append(type(exc).__name__)
        cells += ["not run"] * (4 - len(cells))
        print(f"| {delta:7.0e} | " + " | ".join(f"{c:>22}" for c in cells) + " |")


def _mp_value(M: sp.Matrix, digits: int = 30) -> mpmath.matrix:
    """Entries at ``digits`` digits, each CRootOf polished by Newton's method in mpmath from 15 digits."""
    values = {}
    for r in M.atoms(sp.CRootOf):
        with mpmath.workdps(digits + 15):
            z = mpmath.findroot(sp.lambdify(r.poly.gen, r.expr, "mpmath"), mpmath.mpc(complex(r.n(15))))
        values[r] = sp.Float(z.real, digits + 15) + sp.I * sp.Float(z.imag, digits + 15)
    rows = []
    for row in M.xreplace(values).tolist():
        vals = [sp.N(e, digits) for e in row]
        rows.append([mpmath.mpc(mpmath.mpf(str(sp.re(v))), mpmath.mpf(str(sp.im(v)))) for v in vals])
    return mpmath.matrix(rows)


def part_c(repeat: int) -> None:
    print("\nPart C: exact functions of integer matrices with irreducible characteristic polynomials (CRootOf roots)")
    print("error: largest |symosc - reference| / largest |reference| (mpmath 30 digits; * = scipy logm)\n")
    print(f"| {'case':36} | {'symosc':>10} | {'SymPy':>10} | {'error':>9} |")
    print(f"|{'-' * 38}|{'-' * 12}|{'-' * 12}|{'-' * 11}|")
    tv = sp.Rational(7, 10)
    for poly in (x**3 - x - 1, x**4 - x - 1):
        A = sp.Matrix.companion(sp.Poly(poly, x))
        name = f"{A.rows}x{A.rows} companion of {poly}"
        cases = [
            ("log", lambda A=A: matrix_function(A, sp.log), lambda A=A: A.log(), "log"),
            ("exp", lambda A=A: matrix_function(A, sp.exp), lambda A=A: A.exp(), "exp"),
            ("exp(A t)", lambda A=A: matrix_function(A * t, sp.exp), lambda A=A: (A * t).exp(), "expt"),
        ]
        for label, ours, peer, kind in cases:
            ts, F = timed(ours, repeat)
            try:
                tp, _ = timed(peer, 1)
                peer_time = _fmt_t(tp)
            except Exception as exc:  # SymPy refuses some of these
                peer_time = type(exc).__name__
            with mpmath.workdps(30):
                An = mpmath.matrix((A * tv if kind == "expt" else A).tolist())
                got = _mp_value(F.subs(t, tv) if kind == "expt" else F)
                star = ""
                if kind == "log" and any(r.is_real and r < 0 for r in sp.Poly(poly, x).all_roots()):
                    ref = mpmath.matrix(sla.logm(np.array(A, dtype=float)).tolist())
                    star = "*"
                else:
                    ref = mpmath.logm(An) if kind == "log" else mpmath.expm(An)
                diff = got - ref
                err = max(abs(diff[i, j]) for i in range(A.rows) for j in range(A.rows)) / max(
                    abs(ref[i, j]) for i in range(A.rows) for j in range(A.rows)
                )
            print(
                f"| {name + ': ' + label:36} | {_fmt_t(ts):>10} | {peer_time:>10} | {float(err):>8.1e}{star or ' '} |"
            )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one timing run per case instead of three")
    parser.add_argument("--part", choices=["A", "B", "C"], help="run one part only")
    args = parser.parse_args()
    repeat = 1 if args.quick else 3
    if args.part in (None, "A"):
        part_a(repeat)
    if args.part in (None, "B"):
        part_b(repeat)
    if args.part in (None, "C"):
        part_c(repeat)


if __name__ == "__main__":
    main()
