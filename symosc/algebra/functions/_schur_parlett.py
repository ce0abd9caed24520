"""Blocked Schur–Parlett evaluation of a matrix function in floating point (private).

Davies & Higham (2003), "A Schur–Parlett algorithm for computing matrix functions": the complex Schur form
``A = Q T Q^H`` is reordered so that eigenvalues that are close *relative to their own size* sit in contiguous
diagonal blocks; ``f`` is evaluated on each block (a scalar for a 1x1 block, the Newton interpolation polynomial
with accurately computed divided differences — the confluent machinery of :mod:`._taylor` — for a cluster);
the off-diagonal blocks follow from the Parlett recurrence, a triangular Sylvester equation per block pair.
Only well separated blocks are ever divided by their eigenvalue gap, so a spectrum spanning many decades keeps
its accuracy.  Products treat an exact zero times an overflowed entry as zero, so overflow stays in the entries
that overflow.
"""

from __future__ import annotations

from collections.abc import Callable

import mpmath
import numpy as np

from ...errors import ConvergenceError, ModelError, warn
from . import _taylor

#: eigenvalue gaps below cluster_tol * _NOISE * ||A|| * κ (κ the eigenvalue condition number) link; at the default
#: cluster_tol that is about their rounding uncertainty
_NOISE = 1e-12


def relative_clusters(
    eigs: np.ndarray, cluster_tol: float, scale: float, kappa: np.ndarray | None = None
) -> list[list[int]]:
    """Single-linkage clusters: λ_i, λ_j are linked when ``|λ_i - λ_j| <= cluster_tol*max(|λ_i|, |λ_j|)``.

    A gap within the eigenvalues' own uncertainty, ``cluster_tol * 1e-12 * scale * max(κ_i, κ_j)`` (``scale`` ~
    ||A||, κ the eigenvalue condition numbers), also links: a perturbed Jordan block at 0 stays one cluster.
    """
    n = len(eigs)
    parent = list(range(n))
    kappa = np.ones(n) if kappa is None else np.minimum(kappa, 1e16)

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    floor = cluster_tol * _NOISE * scale
    for i in range(n):
        for j in range(i + 1, n):
            gap = abs(eigs[i] - eigs[j])
            if gap <= cluster_tol * max(abs(eigs[i]), abs(eigs[j])) or gap <= floor * max(kappa[i], kappa[j]):
                parent[find(i)] = find(j)
    groups: dict[int, list[int]] = {}
    for i in range(n):
        groups.setdefault(find(i), []).append(i)
    return list(groups.values())


def eigenvalue_conditions(A: np.ndarray, eigs: np.ndarray) -> np.ndarray:
    """Condition numbers ``||x|| ||y|| / |y^H x|`` of the eigenvalues, matched to ``eigs`` by nearest value."""
    import scipy.linalg as sla  # SciPy on first use, not at import

    w, vl, vr = sla.eig(A, left=True, right=True)
    with np.errstate(divide="ignore", invalid="ignore"):
        k = np.linalg.norm(vl, axis=0) * np.linalg.norm(vr, axis=0) / np.abs(np.sum(vl.conj() * vr, axis=0))
    k = np.where(np.isfinite(k), k, 1e16)
    return np.array([k[int(np.argmin(np.abs(w - e)))] for e in eigs])


def _safe_real_matmul(A: np.ndarray, B: np.ndarray) -> np.ndarray:
    with np.errstate(invalid="ignore", over="ignore"):
        prod = A[:, :, None] * B[None, :, :]
        prod[(A[:, :, None] == 0) | (B[None, :, :] == 0)] = 0
        return prod.sum(axis=1)


def safe_matmul(A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """``A @ B`` where an exact zero times inf/nan counts as zero (overflow stays local).

    Complex products are formed from their real and imaginary parts, so ``(inf + 0j) * (1 + 0j)`` is ``inf``
    (IEEE complex multiplication would give ``inf + nan j``).
    """
    if np.all(np.isfinite(A)) and np.all(np.isfinite(B)):
        return A @ B
    Ar, Ai, Br, Bi = A.real, np.imag(A), B.real, np.imag(B)
    real = _safe_real_matmul(Ar, Br) - _safe_real_matmul(Ai, Bi)
    imag = _safe_real_matmul(Ar, Bi) + _safe_real_matmul(Ai, Br)
    return real + 1j * np.where(imag == 0, 0.0, imag) if np.any(imag) else real.astype(complex)


def ordered_schur(A: np.ndarray, cluster_tol: float) -> tuple[np.ndarray, np.ndarray, list[list[int]]]:
    """Complex Schur form ``A = Q T Q^H`` with each cluster contiguous; returns T, Q and the block index ranges."""
    import scipy.linalg as sla
    from scipy.linalg import lapack

    A = A.astype(complex)
    if np.array_equal(A, A.conj().T):
        # Hermitian: the symmetric eigensolver is more accurate than the general QR algorithm
        w, V = np.linalg.eigh(A)
        T, Q = np.diag(w).astype(complex), V.astype(complex)
    else:
        T, Q = sla.schur(A, output="complex")
    eigs = np.diag(T).copy()
    scale = max(float(np.linalg.norm(A, 1)), np.finfo(float).tiny)
    hermitian = np.array_equal(A, A.conj().T)
    kappa = None if hermitian else eigenvalue_conditions(A, eigs)
    groups = relative_clusters(eigs, cluster_tol, scale, kappa)
    label = np.empty(len(eigs), dtype=int)
    # blocks ordered by the mean position of their members (few swaps)
    groups.sort(key=lambda g: float(np.mean(g)))
    for k, g in enumerate(groups):
        label[g] = k
    labels = label.tolist()
    pos = 0
    for k, g in enumerate(groups):
        for _ in g:
            q = labels.index(k, pos)
            if q != pos:
                # adjacent swaps only ever exchange eigenvalues of different (well separated) clusters
                T, Q, info = lapack.ztrexc(T, Q, q + 1, pos + 1)
                if info != 0:  # pragma: no cover - LAPACK reports failure only for bad arguments
                    raise ModelError(f"reordering the Schur form failed (LAPACK ztrexc info={info})")
                labels.insert(pos, labels.pop(q))
            pos += 1
    ranges, start = [], 0
    for g in groups:
        ranges.append(list(range(start, start + len(g))))
        start += len(g)
    return T, Q, ranges


def _sylvester(T11: np.ndarray, T22: np.ndarray, C: np.ndarray) -> np.ndarray:
    """Solve ``T11 X - X T22 = C`` for upper triangular T11, T22."""
    from scipy.linalg import lapack

    if T11.shape == (1, 1) and T22.shape == (1, 1):
        with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
            return C / (T11[0, 0] - T22[0, 0])
    if not np.all(np.isfinite(C)):
        return np.full(C.shape, np.nan, dtype=complex)
    X, scale, info = lapack.ztrsyl(T11, T22, C, isgn=-1)
    if info < 0:  # pragma: no cover
        raise ModelError(f"triangular Sylvester solve failed (LAPACK ztrsyl info={info})")
    return X / scale


def schur_parlett(
    A: np.ndarray,
    block_f: Callable[[int, np.ndarray], np.ndarray],
    cluster_tol: float,
    divided_difference: Callable[[complex, complex], complex] | None = None,
) -> np.ndarray:
    """``f(A)`` from the reordered Schur form; ``block_f(k, T_kk)`` returns f on diagonal block k.

    ``divided_difference(a, b)`` (optional) returns ``f[a, b]`` accurately; it is used for the coupling of two
    1x1 blocks instead of ``(f(b) - f(a))/(b - a)``.
    """
    T, Q, ranges = ordered_schur(A, cluster_tol)
    nb = len(ranges)
    sl = [slice(r[0], r[-1] + 1) for r in ranges]
    n = T.shape[0]
    F = np.zeros((n, n), dtype=complex)
    for k in range(nb):
        F[sl[k], sl[k]] = block_f(k, T[sl[k], sl[k]])
    for j in range(1, nb):
        for i in range(j - 1, -1, -1):
            Tij = T[sl[i], sl[j]]
            scalar = len(ranges[i]) == 1 and len(ranges[j]) == 1 and divided_difference is not None
            if scalar:
                C = np.zeros((1, 1), dtype=complex)
            else:
                C = safe_matmul(F[sl[i], sl[i]], Tij) - safe_matmul(Tij, F[sl[j], sl[j]])
            for k in range(i + 1, j):
                C = C + safe_matmul(F[sl[i], sl[k]], T[sl[k], sl[j]]) - safe_matmul(T[sl[i], sl[k]], F[sl[k], sl[j]])
            X = _sylvester(T[sl[i], sl[i]], T[sl[j], sl[j]], C)
            if scalar and Tij[0, 0] != 0:
                dd = divided_difference(T[sl[i], sl[i]][0, 0], T[sl[j], sl[j]][0, 0])
                X = X + safe_matmul(Tij, np.array([[dd]]))
            F[sl[i], sl[j]] = X
    return safe_matmul(safe_matmul(Q, F), Q.conj().T)


def function_blocks(source: _taylor.TaylorSource, tol: float, dps: int = 30):
    """``block_f`` and ``divided_difference`` callables for :func:`schur_parlett` from a Taylor source."""

    def value(z: complex) -> mpmath.mpc:
        return source.coefficient(0, mpmath.mpmathify(complex(z)))

    def block_f(k: int, Tk: np.ndarray) -> np.ndarray:
        s = Tk.shape[0]
        if s == 1:
            with mpmath.workdps(dps):
                return np.array([[complex(value(Tk[0, 0]))]])
        nodes = np.diag(Tk).copy()
        coeffs = _taylor.divided_differences(nodes, [list(range(s))], source, tol=tol)
        out = np.zeros((s, s), dtype=complex)
        P = np.eye(s, dtype=complex)
        for m, c in enumerate(coeffs):
            out += complex(c) * P
            if m < s - 1:
                P = P @ (Tk - nodes[m] * np.eye(s))
        return out

    def divided_difference(a: complex, b: complex) -> complex:
        with mpmath.workdps(dps):
            am, bm = mpmath.mpmathify(complex(a)), mpmath.mpmathify(complex(b))
            return complex((value(bm) - value(am)) / (bm - am))

    return block_f, divided_difference


def float_matrix_function(A: np.ndarray, source: _taylor.TaylorSource, tol: float, cluster_tol: float) -> np.ndarray:
    """f(A) by blocked Schur–Parlett; on a cluster whose Taylor series does not converge the clusters shrink."""
    block_f, dd = function_blocks(source, tol)
    ctol = cluster_tol
    while True:
        try:
            value = schur_parlett(A, block_f, ctol, dd)
            break
        except ConvergenceError:
            if ctol <= 1e-8:
                raise
            ctol /= 100
    if ctol < cluster_tol:
        _warn_if_split_within_uncertainty(A, cluster_tol, ctol)
    return value


def _warn_if_split_within_uncertainty(A: np.ndarray, cluster_tol: float, ctol: float) -> None:
    """After f's Taylor series diverged on a cluster and the clusters shrank: warn (AccuracyWarning) when eigenvalues
    that differ by less than their own rounding uncertainty were separated.  f is then evaluated at eigenvalues that
    are not known to be distinct (a perturbed Jordan block, where f(A) may not even exist)."""

    from ...errors import AccuracyWarning

    A = A.astype(complex)
    eigs = np.linalg.eigvals(A)
    scale = max(float(np.linalg.norm(A, 1)), np.finfo(float).tiny)
    kappa = eigenvalue_conditions(A, eigs)
    before = relative_clusters(eigs, cluster_tol, scale, kappa)
    after = relative_clusters(eigs, ctol, scale, kappa)
    if len(after) == len(before):
        return
    for group in before:
        if len(group) < 2:
            continue
        gap = min(abs(eigs[i] - eigs[j]) for i in group for j in group if i < j)
        uncertainty = np.finfo(float).eps * scale * float(np.max(kappa[group]))
        if gap <= uncertainty * 1e3:
            shown = ", ".join(f"{complex(eigs[i]):.3g}" for i in group)
            warn(
                f"f(A): f is not analytic across the eigenvalues {shown}, "
                f"whose differences ({gap:.2g}) are within about a thousand times their rounding uncertainty "
                f"({uncertainty:.2g}, condition {float(np.max(kappa[group])):.2g}); they were treated as distinct, and "
                "the result may be meaningless if A is (nearly) defective there (f(A) of a Jordan block at a branch "
                "point does not exist). Pass exact entries to decide",
                AccuracyWarning,
            )
            return


def indicator_projectors(A: np.ndarray, cluster_tol: float) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """Riesz projectors of the relative clusters (block diagonalisation by Parlett), and the clusters' eigenvalues."""
    T, _, ranges = ordered_schur(A, cluster_tol)
    eig_groups = [np.diag(T)[r[0] : r[-1] + 1].copy() for r in ranges]
    projectors = []
    for c in range(len(ranges)):

        def block_f(k: int, Tk: np.ndarray, c=c) -> np.ndarray:
            return np.eye(Tk.shape[0], dtype=complex) * (1.0 if k == c else 0.0)

        projectors.append(schur_parlett(A, block_f, cluster_tol))
    return projectors, eig_groups
