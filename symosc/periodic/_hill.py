"""Hill-matrix eigenvalue solvers for the Mathieu characteristic values (private).

The Mathieu equation y'' + (a - 2q cos 2x) y = 0 has a periodic solution of period pi or 2pi exactly when ``a`` is
an eigenvalue of one of four infinite symmetric tridiagonal ("Hill") matrices, one per parity/period class
(DLMF 28.4; McLachlan 1947, ch. III).  With j = 0, 1, 2, ... the Fourier index inside a class:

======  ==========  =======================  ==============================  ================
family  values      diagonal                 off-diagonal                    Fourier series
======  ==========  =======================  ==============================  ================
``ae``  a_{2k}      (2j)^2                   sqrt(2) q, q, q, ...            sum A cos 2jx
``ao``  a_{2k+1}    (2j+1)^2, first + q      q, q, ...                       sum A cos (2j+1)x
``bo``  b_{2k+1}    (2j+1)^2, first - q      q, q, ...                       sum B sin (2j+1)x
``be``  b_{2k+2}    (2j+2)^2                 q, q, ...                       sum B sin (2j+2)x
======  ==========  =======================  ==============================  ================

The k-th smallest eigenvalue of a family is the characteristic value with index k inside it.  Within one family the
eigenvalues are simple and far apart (spacing >= 4), so picking the k-th one by index is safe in floating point.

All solvers here take q >= 0 (the public functions map negative q by the DLMF 28.2(vii) symmetries) and a scalar q.

Three solvers:

* :func:`solve_hill` -- float64 eigenvalue by LAPACK ``dstebz`` (the bisection behind
  ``scipy.linalg.eigvalsh_tridiagonal``, called directly to save its overhead; ABSTOL at the underflow threshold for
  full accuracy) at size N and at a larger size; the two must agree (convergence verified by comparison).
* :func:`solve_refined` -- float64 eigenpair, then the Rayleigh quotient of the float eigenvector evaluated in
  extended precision (x87 ``long double``).  The Rayleigh quotient is second-order accurate in the eigenvector error,
  so this removes the ``eps * ||T|| ~ eps * 2q`` absolute error of a float64 eigenvalue; the truncation error is bounded
  a posteriori by ``(q v_{N-1})^2 / gap`` with the normalised eigenvector (Kato-Temple), ``gap >= 1``.
* :func:`solve_mp` -- Newton iteration on the continued fraction split at the eigenvector's largest component
  (Blanch's method) in mpmath at ``dps`` digits, at two sizes that must agree.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import mpmath
import numpy as np

from ..errors import ConvergenceError

_EPS = float(np.finfo(float).eps)
#: LAPACK: "eigenvalues will be computed most accurately when ABSTOL is twice the underflow threshold"
_ABSTOL = 2 * float(np.finfo(float).tiny)
_LD = np.longdouble
#: the extended type only helps where it has more bits than float64 (x86 Linux: 64-bit mantissa)
_HAVE_LD = float(np.finfo(_LD).eps) < 1e-17
_EPS_LD = float(np.finfo(_LD).eps) if _HAVE_LD else _EPS


@dataclass(frozen=True)
class _Family:
    name: str
    offset: int  # diagonal (2j + offset)^2
    q_sign: int  # first diagonal entry gets + q_sign * q
    sqrt2: bool  # first off-diagonal entry is sqrt(2) q


FAMILIES = {
    "ae": _Family("ae", 0, 0, True),
    "ao": _Family("ao", 1, 1, False),
    "bo": _Family("bo", 1, -1, False),
    "be": _Family("be", 2, 0, False),
}


def family_index(kind: str, n: int) -> tuple[_Family, int]:
    """Map (kind, n) to the Hill family and the eigenvalue index k inside it (q >= 0)."""
    if kind == "a":
        return (FAMILIES["ae"], n // 2) if n % 2 == 0 else (FAMILIES["ao"], (n - 1) // 2)
    return (FAMILIES["bo"], (n - 1) // 2) if n % 2 == 1 else (FAMILIES["be"], n // 2 - 1)


def default_size(k: int, q: float) -> int:
    """Heuristic truncation size: k + 12 + sqrt(q) (measured: tail < 1e-14 for n <= 200, q <= 1e5)."""
    return int(k + 12 + math.ceil(math.sqrt(abs(q))))


def _eigvalue(d: np.ndarray, e: np.ndarray, k: int) -> float:
    """k-th smallest eigenvalue (0-based) by LAPACK bisection (``dstebz``, what ``eigvalsh_tridiagonal`` calls)."""
    from scipy.linalg import lapack

    m, w, _iblock, _isplit, info = lapack.dstebz(d, e, 2, 0.0, 0.0, k + 1, k + 1, _ABSTOL, "E")
    if info != 0 or m != 1:  # pragma: no cover - LAPACK failure on finite input
        raise ConvergenceError(f"LAPACK dstebz failed (info={info})")
    return float(w[0])


def _eigpair(d: np.ndarray, e: np.ndarray, k: int) -> tuple[float, np.ndarray]:
    """k-th smallest eigenpair: ``dstebz`` + inverse iteration ``dstein`` (as ``eigh_tridiagonal``, less overhead)."""
    from scipy.linalg import lapack

    m, w, iblock, isplit, info = lapack.dstebz(d, e, 2, 0.0, 0.0, k + 1, k + 1, _ABSTOL, "B")
    if info != 0 or m != 1:  # pragma: no cover
        raise ConvergenceError(f"LAPACK dstebz failed (info={info})")
    z, info = lapack.dstein(d, e, w[:1], iblock, isplit)
    if info != 0:  # pragma: no cover
        raise ConvergenceError(f"LAPACK dstein failed (info={info})")
    return float(w[0]), z[:, 0]


@functools.lru_cache(maxsize=512)
def _squares(offset: int, size: int) -> tuple[np.ndarray, np.ndarray]:
    """(2j + offset)^2, j < size, as read-only float64 and long double arrays (exact in both)."""
    d = (2.0 * np.arange(size, dtype=float) + offset) ** 2
    dl = d.astype(_LD)
    d.setflags(write=False)
    dl.setflags(write=False)
    return d, dl


def _matrix(fam: _Family, q: float, size: int) -> tuple[np.ndarray, np.ndarray]:
    d = _squares(fam.offset, size)[0].copy()
    d[0] += fam.q_sign * q
    e = np.full(size - 1, q)
    if fam.sqrt2 and size > 1:
        e[0] *= math.sqrt(2.0)
    return d, e


@dataclass(frozen=True)
class Solution:
    """One characteristic value with what the solver achieved."""

    value: float | mpmath.mpf
    error_estimate: float
    size: int


def solve_hill(
    fam: _Family, k: int, q: float, tol: float | None = None, max_tries: int = 5, size: int | None = None
) -> Solution:
    """Float64 eigenvalue, size verified by comparison with a larger matrix (doubled up to ``max_tries`` times)."""
    size = default_size(k, q) if size is None else max(size, k + 1)
    for _ in range(max_tries):
        big = size + max(6, size // 3)
        lam1 = _eigvalue(*_matrix(fam, q, size), k)
        lam2 = _eigvalue(*_matrix(fam, q, big), k)
        noise = 16 * _EPS * (abs(lam2) + 4 * q + 1.0)
        diff = abs(lam1 - lam2)
        accept = max(noise, tol * max(1.0, abs(lam2))) if tol is not None else noise
        if diff <= accept:
            return Solution(lam2, max(diff, noise), big)
        size = 2 * big
    raise ConvergenceError(
        f"Hill matrix truncation did not converge for index {k} of family {fam.name} at q={q!r} "
        f"(last change {diff:.3g} between sizes {size // 2} and {big}); try method='mp'",
        achieved=diff,
    )


def solve_refined(
    fam: _Family, k: int, q: float, max_tries: int = 5, size: int | None = None
) -> tuple[Solution, np.ndarray]:
    """Float64 eigenpair refined by an extended-precision Rayleigh quotient; returns the eigenvector too."""
    size = default_size(k, q) if size is None else max(size, k + 1)
    for _ in range(max_tries):
        d, e = _matrix(fam, q, size)
        w0, vec = _eigpair(d, e, k)
        vec = vec / math.sqrt(float(vec @ vec))
        trunc = (q * vec[-1]) ** 2  # Kato-Temple with gap >= 1
        if trunc <= 1e-3 * _EPS * max(1.0, abs(w0)):
            break
        size = 2 * size
    else:
        raise ConvergenceError(
            f"Hill matrix truncation did not converge for index {k} of family {fam.name} at q={q!r}; try method='mp'",
            achieved=float(trunc),
        )
    if not _HAVE_LD:  # pragma: no cover - platforms without extended long double
        return Solution(w0, 16 * _EPS * (abs(w0) + 4 * q + 1.0) + trunc, size), vec
    # v^T T v / v^T v with T = diag((2j+offset)^2) + q_sign q e_0 e_0^T + q (off-diagonal, first one sqrt(2) q)
    ql = _LD(q)
    vl = vec.astype(_LD)
    vv = vl * vl
    cross = vl[:-1] * vl[1:]
    off = cross.sum()
    if fam.sqrt2:
        off += (np.sqrt(_LD(2)) - 1) * cross[0]
    num = (_squares(fam.offset, size)[1] * vv).sum() + fam.q_sign * ql * vv[0] + 2 * ql * off
    value = float(num / vv.sum())
    # rounding of the sum: sum of |terms| <= |lambda| + 4q, pairwise summation ~ log2(N) eps_ld at worst (typically
    # far less); the eigenvector error enters squared (negligible); plus the final rounding to float64
    err = 8 * _EPS_LD * (abs(value) + 4 * q + 1.0) + 0.5 * _EPS * abs(value) + trunc
    return Solution(value, err, size), vec


def _newton_cf(fam: _Family, q, lam, m: int, size: int, dps: int):
    """Newton on the continued fraction gamma_m(lam) of the size x size Hill matrix, in mpmath."""
    d = [mpmath.mpf((2 * j + fam.offset) ** 2) for j in range(size)]
    d[0] += fam.q_sign * q
    b2 = [q * q] * (size - 1)
    if fam.sqrt2 and size > 1:
        b2[0] = 2 * q * q
    tiny = mpmath.mpf(10) ** (-(dps + 3))
    step = mpmath.mpf(1)
    for _ in range(60):
        top = dtop = mpmath.mpf(0)
        if m > 0:
            t, dt = d[0] - lam, mpmath.mpf(-1)
            for j in range(1, m):
                t, dt = d[j] - lam - b2[j - 1] / t, -1 + b2[j - 1] * dt / (t * t)
            top, dtop = b2[m - 1] / t, -b2[m - 1] * dt / (t * t)
        bot = dbot = mpmath.mpf(0)
        if m < size - 1:
            u, du = d[size - 1] - lam, mpmath.mpf(-1)
            for j in range(size - 2, m, -1):
                u, du = d[j] - lam - b2[j] / u, -1 + b2[j] * du / (u * u)
            bot, dbot = b2[m] / u, -b2[m] * du / (u * u)
        g = d[m] - lam - top - bot
        dg = -1 - dtop - dbot
        step = g / dg
        lam = lam - step
        if abs(step) <= tiny * max(1, abs(lam)):
            return lam, abs(step)
    raise ConvergenceError(  # pragma: no cover - Newton from a 1e-15 start converges in 2-4 steps
        f"Newton iteration on the Hill continued fraction did not converge (last step {float(step):.3g})",
        achieved=float(abs(step)),
    )


def solve_mp(fam: _Family, k: int, q, dps: int, max_tries: int = 5) -> Solution:
    """mpmath solution at ``dps`` digits, truncation verified by comparison with a larger matrix."""
    qf = float(q)
    start, vec = solve_refined(fam, k, qf)
    m = int(np.argmax(np.abs(vec)))
    lam0 = start.value
    # extend the size until the (super-exponentially decaying) tail is below 10^-(dps+5) / max(1, q)
    size = start.size
    tail = max(abs(float(vec[-1])), 1e-300)
    target = 10.0 ** (-(dps + 5)) / max(1.0, qf)
    while tail > target and size < 100000:
        dj = (2.0 * size + fam.offset) ** 2
        ratio = qf / (dj - lam0 - 2 * qf) if dj - lam0 > 4 * qf else 0.5
        tail *= min(ratio, 0.5)
        size += 1
    with mpmath.workdps(dps + 10):
        qm = mpmath.mpf(q)
        for _ in range(max_tries):
            big = size + max(6, size // 4)
            lam1, _s = _newton_cf(fam, qm, mpmath.mpf(lam0), m, size, dps)
            lam2, _s = _newton_cf(fam, qm, lam1, m, big, dps)
            diff = abs(lam1 - lam2)
            if diff <= mpmath.mpf(10) ** (-(dps + 2)) * max(1, abs(lam2)):
                err = float(diff) + 10.0 ** (-(dps + 8)) * max(1.0, abs(float(lam2)))
                return Solution(+lam2, err, big)
            size = 2 * big
    raise ConvergenceError(
        f"mpmath Hill solution did not converge at dps={dps} for index {k} of family {fam.name} at q={qf!r}",
        achieved=float(diff),
    )


def refined_value(fam: str, k: int, qf: float, tol: float) -> tuple[float, float]:
    """``(value, error estimate)`` of the characteristic value ``k`` of family ``fam`` at ``q = qf``: the float64
    eigenpair refined by the Rayleigh quotient in extended precision (:func:`solve_refined`), and the mpmath solver
    when that misses ``tol`` relative (absolute below 1)."""
    s, _vec = solve_refined(fam, k, qf)
    if s.error_estimate <= tol * max(1.0, abs(s.value)):
        return s.value, s.error_estimate
    dps = max(20, int(-math.log10(tol)) + 6)
    s = solve_mp(fam, k, mpmath.mpf(qf), dps)
    return float(s.value), abs(float(s.value) - s.value) + s.error_estimate
