"""Root counts of many polynomials at once (private; region labels of :mod:`.dpartition` and :mod:`.regions`).

The roots are the eigenvalues of the companion matrices (what :func:`numpy.roots` computes, one polynomial at a
time), here for a whole stack in one LAPACK call per degree: polynomials whose leading coefficients vanish at some
points are grouped by their actual degree, and exact zero roots (trailing zero coefficients) are split off first.
"""

from __future__ import annotations

import numpy as np

from ...errors import ParameterError


def count_roots_right(coeffs: np.ndarray, epsilon: float = 0.0) -> np.ndarray:
    """Number of roots with ``Re λ > epsilon`` of each row of ``coeffs`` (highest power first), shape ``(N,)``.

    Raises ParameterError when a row vanishes identically (every λ is a root: no label).
    """
    c = np.atleast_2d(np.asarray(coeffs, dtype=complex))
    m = c.shape[1]
    nonzero = c != 0
    if not nonzero.any(axis=1).all():
        raise ParameterError("the characteristic polynomial vanishes identically at some parameter points")
    lead = nonzero.argmax(axis=1)  # index of the leading (first nonzero) coefficient
    zeros = nonzero[:, ::-1].argmax(axis=1)  # exact roots at 0 (trailing zero coefficients), as numpy.roots
    out = np.where(epsilon < 0, zeros, 0)
    groups = lead * (m + 1) + zeros
    for g in np.unique(groups):
        rows = np.flatnonzero(groups == g)
        k, z = divmod(int(g), m + 1)
        deg = m - 1 - k - z
        if deg == 0:
            continue
        monic = c[rows, k + 1 : m - z] / c[rows, k : k + 1]
        if deg == 1:
            out[rows] += (-monic[:, 0]).real > epsilon
            continue
        comp = np.zeros((len(rows), deg, deg), dtype=complex)
        comp[:, 0, :] = -monic
        comp[:, np.arange(1, deg), np.arange(deg - 1)] = 1.0
        if not np.any(comp.imag):
            comp = comp.real
        out[rows] += np.sum(np.linalg.eigvals(comp).real > epsilon, axis=1)
    return out
