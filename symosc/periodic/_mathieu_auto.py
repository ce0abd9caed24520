"""Method "auto" of :func:`symosc.periodic.mathieu_characteristic`: refined SciPy seeds (private).

Raw values (q >= 0, no ordering clamp):

* a_n: SciPy's ``mathieu_a`` value as the seed, refined and verified by the kernel (C, or NumPy without a compiler);
* b_n: where its gap estimate to a_{n-1} or a_n is tiny (a nearly degenerate pair), the seed is that neighbour's
  raw value (so both members of the pair are computed from the same SciPy seed, whichever function is called, and
  one SciPy call is saved); elsewhere SciPy's ``mathieu_b`` value.

A point the kernel does not accept (wrong index, error above target) is recomputed by the LAPACK/mpmath solvers.
Near-degenerate neighbours are then clamped as in :func:`symosc.periodic.mathieu._value_at`.  The raw value of each
(kind, n, q) is a function of (kind, n, q) only, so a_n <= b_{n+1} etc. hold exactly however the values are called,
and scalar calls give the same bits as vectorised ones (the same kernel code per point).
"""

from __future__ import annotations

import math

import numpy as np

from . import _hill, _hill_batch, _hill_c

DEFAULT_TOL = 1e-13
_SCIPY: dict = {}


def mathieu_kernel() -> str:
    """``"c"`` when the compiled kernel runs, ``"numpy"`` for the fallback (no C compiler, or
    ``SYMOSC_MATHIEU_KERNEL=numpy`` in the environment)."""
    return "numpy" if _hill_c.kernel() is None else "c"


def _scipy(kind: str):
    try:
        return _SCIPY[kind]
    except KeyError:
        import scipy.special as sp

        _SCIPY.update(a=sp.mathieu_a, b=sp.mathieu_b)
        return _SCIPY[kind]


def _fallback(kind: str, n: int, q: float, tol) -> tuple[float, float]:
    return _hill.refined_value(*_hill.family_index(kind, n), q, tol or DEFAULT_TOL)


# ----------------------------------------------------------------------------------------------------------- scalar
def _refine1(kind: str, n: int, q: float, seed: float, tol) -> tuple[float, float]:
    fam, k = _hill.family_index(kind, n)
    if q == 0.0:
        return float((2 * k + fam.offset) ** 2), 0.0
    t = tol or DEFAULT_TOL
    lib = _hill_c.kernel()
    if lib is not None:
        value, err, ok = _hill_c.refine1(lib, fam, k, q, seed, t)
    else:
        value, err, ok = _hill_batch.refine_scalar(
            fam.offset, fam.q_sign, fam.sqrt2, k, q, seed, _hill_batch.batch_size(k, q), t
        )
    return (value, err) if ok else _fallback(kind, n, q, tol)


def _gaps1(kind: str, n: int, q: float) -> tuple[float, float, int]:
    lib = _hill_c.kernel()
    if lib is not None:
        return _hill_c.gaps1(lib, kind == "b", n, q)
    return _hill_batch.gaps_scalar(kind == "b", n, q)


def _raw_a1(n: int, q: float, tol, memo: dict) -> tuple[float, float]:
    out = memo.get(n)
    if out is None:
        out = memo[n] = _refine1("a", n, q, float(_scipy("a")(n, q)), tol)
    return out


def _raw_b1(n: int, q: float, tol, memo: dict, rule: int | None = None) -> tuple[float, float]:
    if rule is None:
        rule = _gaps1("b", n, q)[2]
    if rule == -1:
        seed = _raw_a1(n - 1, q, tol, memo)[0]
    elif rule == 1:
        seed = _raw_a1(n, q, tol, memo)[0]
    else:
        seed = float(_scipy("b")(n, q))
    return _refine1("b", n, q, seed, tol)


def auto_scalar(kind: str, n: int, q: float, tol) -> tuple[float, float]:
    """kind_n(q) for one q >= 0 with the ordering clamp: the compiled common case, else :func:`general_scalar`."""
    lib = _hill_c.kernel()
    if lib is not None and q != 0.0:
        if kind == "a":
            seed = _scipy("a")(n, q)
        else:
            rule = lib.symosc_mathieu_gaps1(1, n, q, _hill_c.SCRATCH)
            seed = _scipy("b")(n, q) if rule == 0 else _scipy("a")(n - 1 if rule < 0 else n, q)
        err = _hill_c.ctypes.c_double()
        value = lib.symosc_mathieu_auto1(kind == "b", n, q, seed, tol or DEFAULT_TOL, err)
        if value == value:
            return value, err.value
    return general_scalar(kind, n, q, tol)


def general_scalar(kind: str, n: int, q: float, tol) -> tuple[float, float]:
    """kind_n(q) for one q >= 0 with the ordering clamp, step by step (each raw value by the kernel or the solvers)."""
    memo: dict = {}
    lo, hi, rule = _gaps1(kind, n, q)
    if kind == "a":
        value, err = _raw_a1(n, q, tol, memo)
        threshold = math.log(1e-7 * max(1.0, abs(value)))
        if n >= 1 and lo < threshold:
            value = max(value, _raw_b1(n, q, tol, memo)[0])
        if hi < threshold:
            value = min(value, _raw_b1(n + 1, q, tol, memo)[0])
        return value, err
    value, err = _raw_b1(n, q, tol, memo, rule)
    threshold = math.log(1e-7 * max(1.0, abs(value)))
    clamped = value
    if lo < threshold:
        clamped = max(clamped, _raw_a1(n - 1, q, tol, memo)[0])
    if hi < threshold:
        clamped = min(clamped, _raw_a1(n, q, tol, memo)[0])
    return clamped, err


# ------------------------------------------------------------------------------------------------------- vectorised
#: columns per block of the NumPy kernel at matrix size 32 (keeps the size x block arrays in cache)
_BLOCK = 2048


def _refine(kind: str, n: int, q: np.ndarray, seeds: np.ndarray, tol) -> tuple[np.ndarray, np.ndarray]:
    """Vectorised :func:`_refine1`."""
    fam, k = _hill.family_index(kind, n)
    values = np.full(q.shape, float((2 * k + fam.offset) ** 2))
    errors = np.zeros(q.shape)
    todo = np.nonzero(q != 0.0)[0]
    if not todo.size:
        return values, errors
    t = tol or DEFAULT_TOL
    qt, st = q[todo], seeds[todo]
    lib = _hill_c.kernel()
    if lib is not None:
        v, e, accepted = _hill_c.refine(lib, fam, k, qt, st, t)
    else:
        v, e = np.empty(qt.shape), np.empty(qt.shape)
        accepted = np.zeros(qt.shape, dtype=bool)
        sizes = 8 * ((k + 12 + np.ceil(np.sqrt(qt)).astype(int) + 7) // 8)
        for size in np.unique(sizes):
            idx = np.nonzero(sizes == size)[0]
            width = max(64, _BLOCK * 32 // int(size))
            for sel in (idx[i : i + width] for i in range(0, idx.size, width)):
                v[sel], e[sel], accepted[sel] = _hill_batch.refine_batch(
                    fam.offset, fam.q_sign, fam.sqrt2, k, qt[sel], st[sel], int(size), t
                )
    values[todo], errors[todo] = v, e
    for i in todo[~accepted]:
        values[i], errors[i] = _fallback(kind, n, float(q[i]), tol)
    return values, errors


def _gaps(kind: str, n: int, q: np.ndarray):
    lib = _hill_c.kernel()
    if lib is not None:
        return _hill_c.gaps(lib, kind == "b", n, q)
    return _hill_batch.gaps_array(kind == "b", n, q)


class _Memo:
    """Raw a_m values at (subsets of) the points q, computed on demand."""

    def __init__(self, q: np.ndarray, tol):
        self.q, self.tol = q, tol
        self.a: dict[int, tuple[np.ndarray, np.ndarray]] = {}

    def raw_a(self, m: int, idx: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        vals, errs = self.a.setdefault(m, (np.full(self.q.shape, np.nan), np.full(self.q.shape, np.nan)))
        missing = idx[np.isnan(vals[idx])]
        if missing.size:
            qm = self.q[missing]
            with np.errstate(all="ignore"):
                seeds = np.asarray(_scipy("a")(m, qm), dtype=float)
            vals[missing], errs[missing] = _refine("a", m, qm, seeds, self.tol)
        return vals[idx], errs[idx]

    def raw_b(self, m: int, idx: np.ndarray, rule: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        q = self.q[idx]
        if rule is None:
            rule = _gaps("b", m, q)[2]
        seeds = np.empty(q.shape)
        for r, which in ((-1, m - 1), (1, m)):
            sel = np.nonzero(rule == r)[0]
            if sel.size:
                seeds[sel] = self.raw_a(which, idx[sel])[0]
        own = np.nonzero(rule == 0)[0]
        if own.size:
            with np.errstate(all="ignore"):
                seeds[own] = _scipy("b")(m, q[own])
        return _refine("b", m, q, seeds, self.tol)


def auto_array(kind: str, n: int, q: np.ndarray, tol) -> tuple[np.ndarray, np.ndarray]:
    """Vectorised :func:`auto_scalar` over a 1-d array q >= 0 (the same bits per point)."""
    lib = _hill_c.kernel()
    if lib is None:
        return general_array(kind, n, q, tol)
    with np.errstate(all="ignore"):
        if kind == "a":
            seeds = _scipy("a")(n, q)
        else:
            rule = _hill_c.gaps(lib, True, n, q)[2]
            seeds = np.empty(q.shape)
            for r, fun, m in ((0, _scipy("b"), n), (-1, _scipy("a"), n - 1), (1, _scipy("a"), n)):
                sel = np.nonzero(rule == r)[0]
                if sel.size:
                    seeds[sel] = fun(m, q[sel])
    values, errors, done = _hill_c.auto(lib, kind == "b", n, q, seeds, tol or DEFAULT_TOL)
    rest = np.nonzero(~done)[0]
    if rest.size:
        values[rest], errors[rest] = general_array(kind, n, q[rest], tol)
    return values, errors


def general_array(kind: str, n: int, q: np.ndarray, tol) -> tuple[np.ndarray, np.ndarray]:
    """Vectorised :func:`general_scalar` (the same bits per point)."""
    memo = _Memo(q, tol)
    everything = np.arange(q.size)
    lo, hi, rule = _gaps(kind, n, q)
    if kind == "a":
        values, errors = memo.raw_a(n, everything)
        below, above = (("b", n) if n >= 1 else None), ("b", n + 1)
    else:
        values, errors = memo.raw_b(n, everything, rule)
        below, above = ("a", n - 1), ("a", n)
    with np.errstate(divide="ignore"):
        threshold = np.log(1e-7 * np.maximum(1.0, np.abs(values)))
    clamped = values.copy()
    for nb, gaps, op in ((below, lo, np.maximum), (above, hi, np.minimum)):
        if nb is None:
            continue
        idx = np.nonzero(gaps < threshold)[0]
        if idx.size:
            other = memo.raw_a(nb[1], idx)[0] if nb[0] == "a" else memo.raw_b(nb[1], idx)[0]
            clamped[idx] = op(clamped[idx], other)
    return clamped, errors
