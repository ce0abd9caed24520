"""Accuracy of symosc.algebra.matrix_function on wide spectra against SciPy (logm, sqrtm, sinm, expm).

Reference: the same float matrix diagonalised in 50-digit mpmath.  Prints the relative Frobenius errors of both
and their ratio, for the quoted cases and random matrices with spectra spanning 1e-6..1e6.
"""

from __future__ import annotations

import time
import warnings

import mpmath
import numpy as np
import scipy.linalg as sla
import sympy as sp

from symosc.algebra import matrix_function

MP = {"log": mpmath.log, "sqrt": mpmath.sqrt, "sin": mpmath.sin}
SP = {"log": sp.log, "sqrt": sp.sqrt, "sin": sp.sin}
SCIPY = {"log": sla.logm, "sqrt": sla.sqrtm, "sin": sla.sinm}


def reference(A: np.ndarray, name: str) -> np.ndarray:
    n = A.shape[0]
    with mpmath.workdps(50):
        E, V = mpmath.eig(mpmath.matrix(A.tolist()))
        R = V * mpmath.diag([MP[name](e) for e in E]) * mpmath.inverse(V)
        return np.array([[complex(R[i, j]) for j in range(n)] for i in range(n)])


def err(F, R) -> float:
    return float(np.linalg.norm(np.asarray(F, dtype=complex) - R) / np.linalg.norm(R))


def cases():
    spectrum = np.diag([0.002, 0.04, 0.06, 0.5, 540.0])
    Q, _ = np.linalg.qr(np.random.default_rng(0).normal(size=(5, 5)))
    spd = Q @ spectrum @ Q.T
    yield "SPD, spectrum 0.002..540", (spd + spd.T) / 2
    J = np.diag([0.01, 0.01, 0.02, 0.02, 100.0])
    J[0, 1] = J[2, 3] = 1.0
    S = np.eye(5) + 0.25 * np.random.default_rng(11).normal(size=(5, 5))
    yield f"Jordan 0.01(x2) 0.02(x2) 100, cond S {np.linalg.cond(S):.1f}", S @ J @ np.linalg.inv(S)
    rng = np.random.default_rng(7)
    for k in range(3):
        eigs = 10.0 ** np.sort(np.r_[-6, 6, rng.uniform(-6, 6, 3)])
        S = rng.normal(size=(5, 5)) + 2 * np.eye(5)
        yield f"random 5x5, spectrum 1e-6..1e6 #{k}", S @ np.diag(eigs) @ np.linalg.inv(S)


def main() -> None:
    print(f"{'case':44s} {'f':5s} {'symosc':>9s} {'scipy':>9s} {'ratio':>7s} {'t_symosc':>9s} {'t_scipy':>8s}")
    for label, A in cases():
        for name in ("log", "sqrt", "sin"):
            R = reference(A, name)
            t0 = time.perf_counter()
            ours = matrix_function(A, SP[name])
            t1 = time.perf_counter()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                theirs = SCIPY[name](A)
            t2 = time.perf_counter()
            e1, e2 = err(ours, R), err(theirs, R)
            print(f"{label:44s} {name:5s} {e1:9.1e} {e2:9.1e} {e1 / e2:7.2f} {t1 - t0:9.4f} {t2 - t1:8.4f}")


if __name__ == "__main__":
    main()
