"""symosc.periodic.mathieu_ce/se vs scipy.special.mathieu_cem/sem: accuracy and time per value in one run.

Reference: 40-digit Fourier coefficients from Sturm bisection and a Thomas solve in mpmath
(tests/periodic/mathieu_reference.py -- no symosc code), summed at 40 digits.  Grid: n in {0, 1, 5, 10, 20, 35, 50},
q in {0, 1, 10, 100, 1000, 5000, 1e4}, 16 x over a period.  SciPy takes x in degrees
(its derivative is returned per radian).
An error of order one for SciPy means a wrong function (wrong branch or lost normalisation).

    python benchmarks/mathieu_functions_vs_scipy.py
    python benchmarks/mathieu_functions_vs_scipy.py --plot   # also write docs/img/mathieu_functions.png
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


def figure(path: str = "docs/img/mathieu_functions.png", q: float = 2.0) -> None:
    """The first ce_n and se_n at q (solid) and at q = 0 (dotted: cos nx, sin nx; ce_0 = 1/sqrt(2)) over a period."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from symosc.periodic import mathieu_ce, mathieu_se

    x = np.linspace(0.0, 2 * np.pi, 401)
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.6), sharey=True)
    for ax, fun, name, orders in ((axes[0], mathieu_ce, "ce", range(4)), (axes[1], mathieu_se, "se", range(1, 5))):
        for i, n in enumerate(orders):
            ax.plot(x, fun(n, q, x), color=f"C{i}", label=f"{name}$_{n}$")
            ax.plot(x, fun(n, 0.0, x), color=f"C{i}", ls=":", lw=1)
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_xticks(np.arange(5) * np.pi / 2, ["0", "π/2", "π", "3π/2", "2π"])
        ax.set_xlabel("x (rad)")
        ax.set_title(f"{name}$_n$(x, q): q = {q:g} (solid), q = 0 (dotted)")
        ax.legend(fontsize="small", ncol=2, loc="lower left")
    axes[0].set_ylabel("normalised as DLMF 28.2.30")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


if __name__ == "__main__":
    if "--plot" in sys.argv[1:]:
        figure()
    speed()
    accuracy()
