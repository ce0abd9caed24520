"""Independent 40-digit references for the Mathieu functions (test helper, not part of symosc).

Characteristic value: bisection on the Sturm count of the (symmetric) Hill matrix in mpmath, to full precision.
Coefficients: the tridiagonal system (T - lambda I) v = 0 with the row of the largest component replaced by
v_m = 1, solved by the Thomas algorithm in mpmath (no twisted factorisation, no float64 eigenvector), normalised by
DLMF 28.2.30 with the sign convention of DLMF (first coefficient positive for q > 0; DLMF 28.2(vii) for q < 0 is
not used here: callers pass q >= 0).  Only numpy/scipy's float eigenvector picks the row m.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
from scipy.linalg import eigh_tridiagonal

DPS = 40


def family(kind: str, n: int):
    """(offset, q_sign, sqrt2, k): Hill family of a_n (kind "a") or b_n (kind "b")."""
    if kind == "a":
        return (0, 0, True, n // 2) if n % 2 == 0 else (1, 1, False, (n - 1) // 2)
    return (1, -1, False, (n - 1) // 2) if n % 2 == 1 else (2, 0, False, n // 2 - 1)


def _matrix(kind, n, q, size):
    off, qs, s2, k = family(kind, n)
    q = mpmath.mpf(q)
    d = [mpmath.mpf((2 * j + off) ** 2) for j in range(size)]
    d[0] += qs * q
    e = [q] * (size - 1)
    if s2:
        e[0] = mpmath.sqrt(2) * q
    return d, e, k


def _count(d, e, lam):
    c = 0
    t = d[0] - lam
    for j in range(len(d)):
        if j:
            t = d[j] - lam - e[j - 1] ** 2 / t
        if t == 0:
            t = mpmath.mpf(10) ** (-3 * DPS)
        c += t < 0
    return c


def characteristic(kind: str, n: int, q: float, dps: int = DPS):
    """40-digit a_n(q) or b_n(q), q >= 0, by Sturm bisection."""
    with mpmath.workdps(dps + 10):
        size = n // 2 + 30 + int(3 * math.sqrt(abs(q)))
        d, e, k = _matrix(kind, n, q, size)
        lo, hi = mpmath.mpf(-2 * abs(q) - 2), mpmath.mpf((n + 2) ** 2 + 2 * abs(q) + 2)
        while hi - lo > mpmath.mpf(10) ** (-(dps + 5)) * max(1, abs(hi)):
            mid = (lo + hi) / 2
            if _count(d, e, mid) > k:
                hi = mid
            else:
                lo = mid
        return (lo + hi) / 2


def coefficients(kind: str, n: int, q: float, dps: int = DPS):
    """(Fourier indices, 40-digit normalised coefficients A_k or B_k, characteristic value) at q >= 0."""
    with mpmath.workdps(dps + 10):
        lam = characteristic(kind, n, q, dps)
        size = n // 2 + 30 + int(3 * math.sqrt(abs(q)))
        d, e, k = _matrix(kind, n, q, size)
        # row of the largest component from a float64 eigenvector (LAPACK, independent of symosc)
        df = np.array([float(v) for v in d])
        ef = np.array([float(v) for v in e])
        _w, vec = eigh_tridiagonal(df, ef, select="i", select_range=(k, k))
        m = int(np.argmax(np.abs(vec[:, 0])))
        # tridiagonal system: rows j != m: e_{j-1} v_{j-1} + (d_j - lam) v_j + e_j v_{j+1} = 0; row m: v_m = 1
        lower = [mpmath.mpf(0)] + [e[j - 1] for j in range(1, size)]
        diag = [d[j] - lam for j in range(size)]
        upper = [e[j] for j in range(size - 1)] + [mpmath.mpf(0)]
        rhs = [mpmath.mpf(0)] * size
        lower[m], diag[m], upper[m], rhs[m] = mpmath.mpf(0), mpmath.mpf(1), mpmath.mpf(0), mpmath.mpf(1)
        for j in range(1, size):  # Thomas algorithm
            w = lower[j] / diag[j - 1]
            diag[j] -= w * upper[j - 1]
            rhs[j] -= w * rhs[j - 1]
        v = [mpmath.mpf(0)] * size
        v[-1] = rhs[-1] / diag[-1]
        for j in range(size - 2, -1, -1):
            v[j] = (rhs[j] - upper[j] * v[j + 1]) / diag[j]
        norm = mpmath.sqrt(mpmath.fsum(c * c for c in v))
        if v[0] < 0:
            norm = -norm
        v = [c / norm for c in v]
        off, _qs, s2, _k = family(kind, n)
        if s2:
            v[0] = v[0] / mpmath.sqrt(2)
        return [2 * j + off for j in range(size)], v, lam


def function(kind: str, n: int, q: float, x, derivative: bool = False, coef=None):
    """ce_n / se_n (kind "ce"/"se") or d/dx at the points x (floats), 40 digits, q >= 0; returns floats."""
    ab = "a" if kind == "ce" else "b"
    idx, v, _lam = coef if coef is not None else coefficients(ab, n, q)
    out = []
    with mpmath.workdps(DPS):
        for xv in np.atleast_1d(x):
            xm = mpmath.mpf(float(xv))
            if not derivative:
                f = mpmath.cos if kind == "ce" else mpmath.sin
                s = mpmath.fsum(c * f(k * xm) for k, c in zip(idx, v, strict=True))
            elif kind == "ce":
                s = -mpmath.fsum(k * c * mpmath.sin(k * xm) for k, c in zip(idx, v, strict=True))
            else:
                s = mpmath.fsum(k * c * mpmath.cos(k * xm) for k, c in zip(idx, v, strict=True))
            out.append(float(s))
    return np.array(out)
