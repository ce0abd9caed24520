"""Vectorised refinement and verification of Mathieu characteristic values: the NumPy kernel (private).

This is the fallback when no C compiler is available; :mod:`symosc.periodic._hill_c` runs the same algorithm in C
(plus bisection for seeds on a wrong branch).  A seed value ``x`` (the initial approximation of
:mod:`symosc.periodic._mathieu_seed`; never trusted) is turned into a verified float64 value by
steps (one for a seed accurate to rounding, at most ``MAX_STEPS``) of Rayleigh-quotient iteration on the Hill
matrix of :mod:`symosc.periodic._hill`, computed from the *twisted* factorisation of ``T - x I`` (Parlett &
Dhillon 1997, "Fernando's solution to Wilkinson's problem"):

* forward pivots ``t_j = (d_j - x) - e_{j-1}^2 / t_{j-1}`` and backward pivots ``u_j = (d_j - x) - e_j^2 / u_{j+1}``;
* twist ``gamma_j = t_j - e_j^2 / u_{j+1}`` and twist index ``m = argmin |gamma_j|`` (largest eigenvector entry);
* eigenvector ``z_m = 1``, ``z_j = -e_j z_{j+1} / t_j`` above, ``z_j = -e_{j-1} z_{j-1} / u_j`` below, so that
  ``(T - x I) z = gamma_m e_m`` exactly: an eigenvalue lies within ``rho = |gamma_m| / ||z||`` of ``x``;
* the Rayleigh quotient ``z^T T z / z^T z`` has error ``<= rho^2 / gap`` (second order);
* the index of that eigenvalue is the number of negative pivots other than the twist (Sylvester's law of inertia
  on the twisted factorisation; the twist carries the sign of ``lambda - x``), so a seed on the wrong branch is
  detected, never silently refined.

Every point is computed independently of the others (its own matrix size, sums accumulated row by row), and the
scalar function performs exactly the same floating-point operations as the vectorised one, so both give the same
bits.  A point that fails a check (seed off by more than ``rho_max``, wrong index, truncation or rounding estimate
above target) is reported as not accepted and the caller falls back to the scalar LAPACK/mpmath solvers.
"""

from __future__ import annotations

import functools
import math

import numpy as np

_EPS = float(np.finfo(float).eps)
_TINY = float(np.finfo(float).tiny)
_SQRT2 = math.sqrt(2.0)
#: a seed further than this from an eigenvalue (residual relative to max(1, |seed|)) is not refined here
_RHO_MAX = 1e-3
#: Rayleigh-quotient steps at most (one for a seed accurate to rounding)
MAX_STEPS = 4
#: no further step once rho^2 (a bound on the error of the Rayleigh quotient) is below _STOP min(tol, 1e-13)
_STOP = 1e-3


def batch_size(k: int, q: float) -> int:
    """Matrix size for index k at q: the heuristic of ``_hill.default_size`` rounded up to a multiple of 8."""
    n = k + 12 + math.ceil(math.sqrt(q))
    return 8 * ((n + 7) // 8)


@functools.lru_cache(maxsize=256)
def _squares(offset: int, size: int) -> tuple[float, ...]:
    return tuple(float((2 * j + offset) ** 2) for j in range(size))


def refine_scalar(offset: int, q_sign: int, sqrt2: bool, k: int, q: float, x: float, size: int, tol: float = 1.0):
    """(value, error_estimate, accepted) for one point; the same operations as :func:`refine_batch`.

    Up to ``MAX_STEPS`` Rayleigh-quotient steps (one suffices for a seed accurate to rounding; a neighbour's value
    used as a seed for a nearly degenerate pair needs two), then the index, truncation and error checks (the error
    estimate must be at most ``tol`` times max(1, |value|)).
    """
    if not math.isfinite(x):
        return math.nan, math.inf, False
    for _ in range(MAX_STEPS):
        out = _step_scalar(offset, q_sign, sqrt2, q, x, size)
        if out is None:
            return math.nan, math.inf, False
        value, scale, rho2, trunc, index = out
        if not rho2 <= _RHO_MAX * _RHO_MAX * max(1.0, abs(x)) ** 2:
            return math.nan, math.inf, False
        if rho2 <= _STOP * min(tol, 1e-13) * max(1.0, abs(value)):
            break
        x = value
    err = 8.0 * _EPS * scale + 0.5 * _EPS * abs(value) + trunc + rho2
    mag = max(1.0, abs(value))
    ok = math.isfinite(value) and math.isfinite(err) and index == k and trunc <= 1e-3 * _EPS * mag and err <= tol * mag
    return (value, err, True) if ok else (math.nan, math.inf, False)


def _step_scalar(offset: int, q_sign: int, sqrt2: bool, q: float, x: float, size: int):
    """One step at x: (Rayleigh quotient, scale, rho^2, truncation, index), or None when a pivot vanishes."""
    n = size
    e0 = _SQRT2 * q if sqrt2 else q
    d0 = float(offset * offset) + q_sign * q
    b0 = e0 * e0
    bq = q * q
    sq = _squares(offset, n)
    dx = [d0 - x] + [v - x for v in sq[1:]]
    t = [0.0] * n
    tj = dx[0]
    b = b0
    for j in range(n):
        if j:
            tj = dx[j] - b / tj
            b = bq
        if tj == 0.0 and j < n - 1:  # t_{n-1} and u_0 never divide
            return None
        t[j] = tj
    u = [0.0] * n
    g = [0.0] * n
    uj = dx[n - 1]
    if uj == 0.0 and n > 1:
        return None
    u[n - 1] = uj
    g[n - 1] = t[n - 1]
    for j in range(n - 2, -1, -1):
        bqj = (b0 if j == 0 else bq) / uj
        uj = dx[j] - bqj
        if uj == 0.0 and j > 0:
            return None
        u[j] = uj
        g[j] = t[j] - bqj
    m = 0
    gm = abs(g[0])
    for j in range(1, n):
        a = abs(g[j])
        if a < gm:
            m, gm = j, a
    index = sum(1 for j in range(m) if t[j] < 0.0) + sum(1 for j in range(m + 1, n) if u[j] < 0.0)
    z = [1.0] * n
    for j in range(m - 1, -1, -1):
        z[j] = ((-e0 if j == 0 else -q) / t[j]) * z[j + 1]
    for j in range(m + 1, n):
        z[j] = ((-e0 if j == 1 else -q) / u[j]) * z[j - 1]
    zz = z[0] * z[0]
    norm2 = zz
    dsum = d0 * zz
    dabs = abs(d0) * zz
    c = e0 * (z[0] * z[1])
    cross = c
    cabs = abs(c)
    zj = z[1]
    for j in range(1, n):
        zz = zj * zj
        norm2 = norm2 + zz
        dz = sq[j] * zz
        dsum = dsum + dz
        dabs = dabs + dz
        if j < n - 1:
            zn = z[j + 1]
            c = q * (zj * zn)
            cross = cross + c
            cabs = cabs + abs(c)
            zj = zn
    value = (dsum + 2.0 * cross) / norm2
    scale = (dabs + 2.0 * cabs) / norm2
    rho2 = (gm * gm) / norm2
    w = q * z[n - 1]
    trunc = (w * w) / norm2
    return value, scale, rho2, trunc, index


def _rowsum(a: np.ndarray) -> np.ndarray:
    """Sum over the rows in order (row 0 first), as the scalar loop adds."""
    out = a[0].copy()
    for row in a[1:]:
        out += row
    return out


def refine_batch(
    offset: int, q_sign: int, sqrt2: bool, k: int, q: np.ndarray, x: np.ndarray, size: int, tol: float = 1.0
):
    """Vectorised :func:`refine_scalar` over 1-d arrays ``q``, ``x`` (same size for all points)."""
    q = np.asarray(q, dtype=float)
    x = np.asarray(x, dtype=float)
    value = np.full(q.shape, np.nan)
    err = np.full(q.shape, np.inf)
    accepted = np.zeros(q.shape, dtype=bool)
    live = np.nonzero(np.isfinite(x))[0]
    xs = x[live]
    for it in range(MAX_STEPS):
        if not live.size:
            break
        v, scale, rho2, trunc, index, fine = _step_batch(offset, q_sign, sqrt2, q[live], xs, size)
        with np.errstate(all="ignore"):
            fine &= rho2 <= _RHO_MAX * _RHO_MAX * np.maximum(1.0, np.abs(xs)) ** 2
            done = fine & (rho2 <= _STOP * min(tol, 1e-13) * np.maximum(1.0, np.abs(v)))
        last = it == MAX_STEPS - 1
        fin = np.nonzero(done | (fine & last))[0]
        if fin.size:
            vf = v[fin]
            with np.errstate(all="ignore"):
                e = 8.0 * _EPS * scale[fin] + 0.5 * _EPS * np.abs(vf) + trunc[fin] + rho2[fin]
                mag = np.maximum(1.0, np.abs(vf))
                ok = (
                    np.isfinite(vf)
                    & np.isfinite(e)
                    & (index[fin] == k)
                    & (trunc[fin] <= 1e-3 * _EPS * mag)
                    & (e <= tol * mag)
                )
            pts = live[fin]
            value[pts] = np.where(ok, vf, np.nan)
            err[pts] = np.where(ok, e, np.inf)
            accepted[pts] = ok
        more = np.nonzero(fine & ~done)[0]
        live, xs = live[more], v[more]
    return value, err, accepted


def _step_batch(offset: int, q_sign: int, sqrt2: bool, q: np.ndarray, x: np.ndarray, size: int):
    """Vectorised :func:`_step_scalar` (plus a mask of the points where no pivot vanished).

    Only the two pivot recurrences loop over the rows; products and sums along the rows use ``cumprod`` and
    row-by-row sums (sequential, hence the same rounding as the scalar loop).
    """
    n = size
    e0 = _SQRT2 * q if sqrt2 else q
    d0 = float(offset * offset) + q_sign * q
    b0 = e0 * e0
    bq = q * q
    diag = np.array(_squares(offset, n))[:, None]
    with np.errstate(all="ignore"):
        dx = diag - x
        dx[0] = d0 - x
        t = np.empty_like(dx)
        tj = t[0] = dx[0]
        b = b0
        for j in range(1, n):
            tj = t[j] = dx[j] - b / tj
            b = bq
        u = np.empty_like(dx)
        g = np.empty_like(dx)
        uj = u[n - 1] = dx[n - 1]
        g[n - 1] = t[n - 1]
        for j in range(n - 2, -1, -1):
            bqj = (b0 if j == 0 else bq) / uj
            uj = u[j] = dx[j] - bqj
            g[j] = t[j] - bqj
        zero = (t[:-1] == 0.0).any(axis=0) | (u[1:] == 0.0).any(axis=0)
        ga = np.abs(g)
        m = np.argmin(ga, axis=0)
        gm = np.take_along_axis(ga, m[None, :], axis=0)[0]
        rows = np.arange(n)[:, None]
        above, below = rows < m, rows > m
        index = np.count_nonzero((t < 0.0) & above, axis=0) + np.count_nonzero((u < 0.0) & below, axis=0)
        neg_q = -q
        ratio = neg_q / t
        ratio[0] = (-e0) / t[0]
        ratio[~above] = 1.0
        zup = np.cumprod(ratio[::-1], axis=0)[::-1]
        ratio[1:] = neg_q / u[1:]
        ratio[1] = (-e0) / u[1]
        ratio[0] = 1.0
        ratio[~below] = 1.0
        z = zup * np.cumprod(ratio, axis=0)
        zz = z * z
        dz = diag * zz
        dz[0] = d0 * zz[0]
        norm2 = _rowsum(zz)
        dsum = _rowsum(dz)
        dz[0] = np.abs(d0) * zz[0]
        dabs = _rowsum(dz)
        c = z[:-1] * z[1:]
        c *= q
        c[0] = e0 * (z[0] * z[1])
        cross = _rowsum(c)
        np.abs(c, out=c)
        cabs = _rowsum(c)
        value = (dsum + 2.0 * cross) / norm2
        scale = (dabs + 2.0 * cabs) / norm2
        rho2 = (gm * gm) / norm2
        w = q * z[n - 1]
        trunc = (w * w) / norm2
    return value, scale, rho2, trunc, index, ~zero
