"""symosc.periodic.mathieu_ce/se vs scipy.special.mathieu_cem/sem: accuracy and time per value in one run.

Reference: 40-digit Fourier coefficients from Sturm bisection and a Thomas solve in mpmath
(tests/periodic/mathieu_reference.py -- no symosc code), summed at 40 digits.  Grid: n in {0, 1, 5, 10, 20, 35, 50},
q in {0, 1, 10, 100, 1000, 5000, 1e4}, 16 x over a period.  SciPy takes x in degrees
(its derivative is returned per radian).
An error of order one for SciPy means a wrong function (wrong branch or lost normalisation).

    python benchmarks/mathieu_functions_vs_scipy.py
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np
import scipy.special as sp

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from symosc.periodic import mathieu_function
from tests.periodic import mathieu_reference as ref

NS = (0, 1, 5, 10, 20, 35, 50)
QS = (0.0, 1.0, 10.0, 100.0, 1000.0, 5000.0, 1e4)
X = np.linspace(0.0, 2 * np.pi, 17)[:-1]


def best(fn, repeat=3):
    t = math.inf
    for _ in range(repeat):
        t0 = time.process_time()
        fn()
        t = min(t, time.process_time() - t0)
    return t


def accuracy() -> None:
    print("| function | q | symosc max error (value) | symosc max error (d/dx, relative to max abs) | SciPy max error "
          "(value) | SciPy max error (d/dx, rel.) | SciPy n with error > 1e-6 |")  # fmt: skip
    print("|---|---|---|---|---|---|---|")
    for kind, scipy_fn in (("ce", sp.mathieu_cem), ("se", sp.mathieu_sem)):
        for q in QS:
            worst = [0.0, 0.0, 0.0, 0.0]
            bad = []
            for n in NS:
                if kind == "se" and n == 0:
                    continue
                co = ref.coefficients("a" if kind == "ce" else "b", n, q)
                exact = ref.function(kind, n, q, X, False, co)
                dexact = ref.function(kind, n, q, X, True, co)
                dscale = max(1.0, float(np.max(np.abs(dexact))))
                ours = mathieu_function(kind, n, q, X).values
                dours = mathieu_function(kind, n, q, X, derivative=True).values
                with np.errstate(all="ignore"):
                    sv, sd = scipy_fn(n, q, np.degrees(X))
                sd = np.asarray(sd)  # SciPy returns d/dx per radian (measured: scaling by 180/pi is off by 56x)
                errs = (np.max(np.abs(ours - exact)), np.max(np.abs(dours - dexact)) / dscale,
                        np.max(np.abs(sv - exact)), np.max(np.abs(sd - dexact)) / dscale)  # fmt: skip
                errs = [e if np.isfinite(e) else math.inf for e in errs]
                worst = [max(w, e) for w, e in zip(worst, errs, strict=True)]
                if errs[2] > 1e-6:
                    bad.append(n)
            print(f"| {kind} | {q:g} | {worst[0]:.1e} | {worst[1]:.1e} | {worst[2]:.1e} | {worst[3]:.1e} | "
                  f"{bad if bad else '-'} |")  # fmt: skip
    print()


def speed() -> None:
    print("| case | symosc (us/value) | SciPy (us/value) | ratio |")
    print("|---|---|---|---|")
    xd = np.linspace(0.0, 360.0, 10_000)
    xr = np.radians(xd)
    for kind, scipy_fn, n, q in (("ce", sp.mathieu_cem, 0, 1.0), ("ce", sp.mathieu_cem, 5, 10.0),
                                 ("se", sp.mathieu_sem, 20, 100.0), ("ce", sp.mathieu_cem, 50, 1000.0)):  # fmt: skip
        mathieu_function(kind, n, q, xr[:10])
        t_o = best(lambda kind=kind, n=n, q=q: mathieu_function(kind, n, q, xr))
        t_s = best(lambda f=scipy_fn, n=n, q=q: f(n, q, xd))
        print(f"| {kind}_{n}, q = {q:g}, 10^4 x | {t_o / xr.size * 1e6:.2f} | {t_s / xr.size * 1e6:.2f} | "
              f"{t_o / t_s:.1f}x |")  # fmt: skip
    qv = np.linspace(0.0, 100.0, 10_000)
    for kind, scipy_fn, n in (("ce", sp.mathieu_cem, 5), ("se", sp.mathieu_sem, 20)):
        t_o = best(lambda kind=kind, n=n: mathieu_function(kind, n, qv, 0.7, tol=1e-12))
        t_s = best(lambda f=scipy_fn, n=n: f(n, qv, np.degrees(0.7)))
        print(f"| {kind}_{n}, 10^4 q in [0, 100], one x | {t_o / qv.size * 1e6:.2f} | {t_s / qv.size * 1e6:.2f} | "
              f"{t_o / t_s:.1f}x |")  # fmt: skip
    print()


if __name__ == "__main__":
    speed()
    accuracy()
