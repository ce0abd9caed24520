"""Characteristic exponents of n-DOF Poincaré cycles: series (exponent_series) vs numeric monodromy (shooting).

The peer a user would pick is the numerical route: find the periodic orbit by shooting and take the eigenvalues of
the monodromy matrix (``NDofPeriodicSolution.validate``, scipy DOP853).  The series is computed once and then
evaluated at any eps; the numeric route costs one shooting per eps.

    python benchmarks/ndof_exponents.py [--quick]
"""

from __future__ import annotations

import sys
import time

import numpy as np
import sympy as sp

from symosc.nonlinear import periodic_solution_ndof

q1, q2, v1, v2 = sp.symbols("q1 q2 v1 v2")
SYSTEMS = {
    "coupled vdP (w = 1, 1.732)": ([[2, -1], [-1, 2]], [(1 - q1**2) * v1, (1 - q2**2) * v2]),
    "asymmetric (w = 1.074, 1.431)": (
        [[sp.Rational(6, 5), sp.Rational(-1, 5)], [sp.Rational(-1, 5), 2]],
        [(1 - q1**2) * v1 + q1 * q2, -v2 / 2 + q1**2 * q2],
    ),
}


def main(quick: bool = False) -> None:
    orders = (2, 4, 8) if quick else (2, 4, 8, 12)
    eps_list = (0.05, 0.1, 0.2)
    print(
        f"{'system':32s} {'order':>5s} {'t_series [s]':>12s} "
        + " ".join(f"{'err eps=' + str(e):>13s}" for e in eps_list)
    )
    for name, (K, f) in SYSTEMS.items():
        sol = periodic_solution_ndof([[1, 0], [0, 1]], K, f, [q1, q2], [v1, v2], max(orders))
        t0 = time.perf_counter()
        refs = {e: sol.validate(e) for e in eps_list}
        t_num = (time.perf_counter() - t0) / len(eps_list)
        for N in orders:
            t0 = time.perf_counter()
            ser = sol.exponent_series(N)
            t_ser = time.perf_counter() - t0
            errs = [np.max(np.abs(np.sort(ser.evaluate(e).real) - refs[e]["exponents_numeric_real"])) for e in eps_list]
            print(f"{name:32s} {N:5d} {t_ser:12.4f} " + " ".join(f"{x:13.2e}" for x in errs))
        print(
            f"{name:32s} numeric monodromy (shooting): {t_num:.3f} s per eps; series/numeric time ratio at order "
            f"{max(orders)}: {t_ser / t_num:.3f}"
        )


if __name__ == "__main__":
    main("--quick" in sys.argv)
