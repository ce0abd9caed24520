"""symosc.operational vs SymPy: inversion of rational Carson images and forward transforms.

For each rational Carson image X(p) (denominator degree 2..6, simple, repeated and complex roots, exact and float
coefficients) we time

* symosc ``heaviside_expand`` (second expansion theorem, Bulgakov 2.74, i.e. residues), and
* SymPy ``inverse_laplace_transform(X/p, p, t)``,

and measure each original against a 40-digit mpmath de Hoog inversion at t = 0.5, 2, 5 (max abs error).
A second table times the forward transform: symosc ``carson`` (table rewrite) vs ``p * sympy.laplace_transform``.

Run:  python benchmarks/operational_vs_sympy.py [--quick]
"""

from __future__ import annotations

import argparse
import time

import mpmath
import sympy as sp

from symosc.operational import carson, heaviside_expand

p, t = sp.symbols("p t")
TS = (0.5, 2.0, 5.0)

CASES = [
    ("deg2 simple", p / ((p + 1) * (p + 2))),
    ("deg2 double", p / (p + 1) ** 2),
    ("deg3 double+simple", p * (3 * p + 1) / ((p - 1) ** 2 * (p + 2))),
    ("deg3 complex pair", p * (p + 5) / ((p**2 + 2 * p + 5) * (p + 1))),
    ("deg4 quadruple", p / (p + 1) ** 4),
    ("deg4 double complex", p * (p + 1) / (p**2 + 2 * p + 5) ** 2),
    ("deg5 triple+2 simple", p / ((p + 1) ** 3 * (p + 2) * (p + 3))),
    ("deg6 six simple", p / sp.Mul(*[(p + k) for k in range(1, 7)])),
    ("deg6 double + 2x double cplx", p**2 / ((p + 1) ** 2 * (p**2 + 2 * p + 5) ** 2)),
    ("deg4 float coeffs", 1.0 * p / (p**4 + 2.5 * p**3 + 3.25 * p**2 + 2.0 * p + 0.75)),
]
QUICK = {"deg2 double", "deg3 complex pair", "deg5 triple+2 simple", "deg4 float coeffs"}

FORWARD = [
    ("t^2 e^-t", t**2 * sp.exp(-t)),
    ("e^-t sin 3t", sp.exp(-t) * sp.sin(3 * t)),
    ("t^3 e^(-2t) cos t", t**3 * sp.exp(-2 * t) * sp.cos(t)),
    ("t sin^2 t + cosh 2t", t * sp.sin(t) ** 2 + sp.cosh(2 * t)),
    ("(t-1)^2 1(t-1)", (t - 1) ** 2 * sp.Heaviside(t - 1)),
]


def _reference(image):
    f = sp.lambdify(p, image / p, modules="mpmath")
    with mpmath.workdps(40):
        return [mpmath.invertlaplace(f, tv, method="dehoog") for tv in TS]


def _error(expr, ref):
    if expr is None:
        return float("nan")
    err = 0.0
    for tv, r in zip(TS, ref, strict=True):
        try:
            v = complex(sp.N(expr.subs(t, tv), 30))
        except (TypeError, ValueError):
            return float("nan")
        err = max(err, abs(v - complex(r)))
    return err


def _timed(fn):
    t0 = time.perf_counter()
    try:
        out = fn()
    except Exception as exc:  # report, don't crash the table
        out = None
        print(f"    ({type(exc).__name__}: {str(exc)[:80]})")
    return out, time.perf_counter() - t0


def main(quick: bool = False) -> None:
    print("Inversion of rational Carson images (time in s; error = max |x(t) - mpmath 40-digit| at t=0.5,2,5)")
    head = f"{'case':30s} {'symosc s':>9s} {'sympy s':>9s} {'ratio':>7s} {'symosc err':>11s} {'sympy err':>10s}"
    print(head)
    print("-" * len(head))
    for name, image in CASES:
        if quick and name not in QUICK:
            continue
        ref = _reference(image)
        ours, t_ours = _timed(lambda image=image: heaviside_expand(image, p, t))
        theirs, t_sympy = _timed(
            lambda image=image: sp.inverse_laplace_transform(image / p, p, t).subs(sp.Heaviside(t), 1)
        )
        if theirs is not None and theirs.has(sp.InverseLaplaceTransform):
            theirs = None
        print(
            f"{name:30s} {t_ours:9.3f} {t_sympy:9.3f} {t_sympy / t_ours:7.1f} "
            f"{_error(ours, ref):11.1e} {_error(theirs, ref):10.1e}"
        )
    print()
    print("Forward transform (time in s; 'same' = the two images agree symbolically)")
    head = f"{'original':30s} {'symosc s':>9s} {'sympy s':>9s} {'ratio':>7s} {'same':>5s}"
    print(head)
    print("-" * len(head))
    for name, x in FORWARD:
        if quick and name not in ("t^2 e^-t", "(t-1)^2 1(t-1)"):
            continue
        ours, t_ours = _timed(lambda x=x: carson(x, t, p, method="table"))
        theirs, t_sympy = _timed(lambda x=x: p * sp.laplace_transform(x, t, p, noconds=True))
        same = ours is not None and theirs is not None and sp.simplify(ours - theirs) == 0
        print(f"{name:30s} {t_ours:9.3f} {t_sympy:9.3f} {t_sympy / t_ours:7.1f} {same!s:>5s}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a few cases only")
    main(parser.parse_args().quick)
