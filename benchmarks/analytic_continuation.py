"""Accuracy and cost of symosc.algebra.analytic_continuation (Bulgakov 1954, §1.31) against SciPy's logm/sqrtm.

The element of log or sqrt about 1 is continued to each cluster of eigenvalues (method="disks").  Reference: the
same float matrix diagonalised in 50-digit mpmath.  Prints the relative Frobenius errors of both, their ratio, the
continuation steps taken and the times.  The cases are those of the matrix-function wide-spectrum benchmark.
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

from symosc.algebra import analytic_continuation

sys.path.insert(0, str(Path(__file__).resolve().parent))
from matrix_function_wide_spectra import SCIPY, SP, cases, err, reference  # the same cases and 50-digit reference


def main() -> None:
    cols = f"{'symosc':>9s} {'scipy':>9s} {'ratio':>7s} {'steps':>6s} {'t_symosc':>9s} {'t_scipy':>8s}"
    print(f"{'case':44s} {'f':5s} {cols}")
    for label, A in cases():
        for name in ("log", "sqrt"):
            R = reference(A, name)
            t0 = time.perf_counter()
            res = analytic_continuation(A, SP[name])
            t1 = time.perf_counter()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                theirs = SCIPY[name](A)
            t2 = time.perf_counter()
            e1, e2 = err(res.value, R), err(theirs, R)
            print(
                f"{label:44s} {name:5s} {e1:9.1e} {e2:9.1e} {e1 / e2:7.2f} {len(res.path):6d} {t1 - t0:9.4f} "
                f"{t2 - t1:8.4f}"
            )


if __name__ == "__main__":
    main()
