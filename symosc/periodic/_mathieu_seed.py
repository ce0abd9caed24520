"""Initial approximations of the Mathieu characteristic values, and where neighbours need the ordering clamp (private).

Seeds.  For each (kind, n), ``a_n(q) + 2q`` (or ``b_n(q) + 2q``) is a piecewise Chebyshev series of degree
:data:`DEG` in ``h = sqrt(q)`` on ``[0, h_max]``, ``h_max = 6 s + 20`` with ``s = 2m + 1`` (m = n for a_n, n - 1
for b_n), and beyond ``h_max`` the asymptotic expansion DLMF 28.8.1 (terms up to ``h^-5``), which is accurate to
~1e-12 relative there.  The pieces are generated on first use from certified values at the Chebyshev nodes (the
kernel started from a crude approximation, with bisection on the Sturm count where that is off) and split until the
last two Chebyshev coefficients are below ``1e-12 max(1, |value|)``: a few milliseconds per (kind, n), 10-25 pieces.
A seed is never trusted -- the kernel verifies the index of the eigenvalue it converges to and refines it -- it only
decides the cost: one Rayleigh-quotient step when it is within ~1e-8 sqrt(max(1, |value|)).

Clamp regions.  The chain a_0 <= b_1 <= a_1 <= b_2 <= ... has nearly degenerate neighbours (b_{n+1} - a_n is
exponentially small at large q, DLMF 28.8.2; a_n - b_n is O(q^n) at small q, DLMF 28.6): where the gap is below the
rounding error the two values are computed independently and clamped into order.  The regions where the gap is
below ``THRESHOLD (n^2 + 2q + 1)`` -- more than 50 times a bound on the rounding error of two values -- are measured
once per pair from certified values (the relative gap is monotone there): ``h >= h_c(n)`` for (a_n, b_{n+1}) and
``h <= h_s(n)`` for (b_n, a_n), each widened by 1 % on the safe side.  Measuring them replaces asymptotic gap
formulas, which are off by orders of magnitude where h is comparable to n.
"""

from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np

from . import _hill, _hill_batch, _hill_c

#: Chebyshev degree of a seed piece (the C kernel uses the same constant, SEED_DEG)
DEG = 16
#: relative gap (to n^2 + 2q + 1) below which neighbours are clamped into order
THRESHOLD = 1e-12
_TARGET = 1e-12
_NODES = np.cos(np.pi * (np.arange(DEG + 1) + 0.5) / (DEG + 1))
#: values at the nodes -> Chebyshev coefficients
_DCT = 2.0 / (DEG + 1) * np.cos(np.outer(np.arange(DEG + 1), np.pi * (np.arange(DEG + 1) + 0.5) / (DEG + 1)))
_DCT[0] *= 0.5
_HEADER = 9


def _s(kind: str, n: int) -> int:
    """s = 2m + 1 of the asymptotic expansion shared by a_m and b_{m+1}."""
    return 2 * n + 1 if kind == "a" else 2 * n - 1


def asymptotic(s: float, h: np.ndarray) -> np.ndarray:
    """DLMF 28.8.1 up to h^-5 (the operations of the C kernel's ``seed_asymptotic``)."""
    s2 = s * s
    r = 1.0 / h
    c3 = s * (s2 + 3.0) / 128.0
    c4 = (s2 * (5.0 * s2 + 34.0) + 9.0) / 4096.0
    c5 = s * (s2 * (33.0 * s2 + 410.0) + 405.0) / 131072.0
    c6 = (s2 * (s2 * (63.0 * s2 + 1260.0) + 2943.0) + 486.0) / 1048576.0
    c7 = s * (s2 * (s2 * (527.0 * s2 + 15617.0) + 69001.0) + 41607.0) / 33554432.0
    tail = r * (c3 + r * (c4 + r * (c5 + r * (c6 + r * c7))))
    return (-2.0 * h + 2.0 * s) * h - (s2 + 1.0) / 8.0 - tail


# ---------------------------------------------------------------------------------------------- certified values
def refine(kind: str, n: int, q: np.ndarray, seeds: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray]:
    """Raw (unclamped) values and error estimates at the points q >= 0 from the given seeds: the kernel (C, or NumPy),
    and the LAPACK/mpmath solvers for points it does not accept."""
    fam, k = _hill.family_index(kind, n)
    values = np.full(q.shape, float((2 * k + fam.offset) ** 2))
    errors = np.zeros(q.shape)
    todo = np.nonzero(q != 0.0)[0]
    if not todo.size:
        return values, errors
    qt, st = q[todo], seeds[todo]
    lib = _hill_c.kernel()
    if lib is not None:
        v, e, accepted = _hill_c.refine(lib, fam, k, qt, st, tol)
    else:
        v, e = np.empty(qt.shape), np.empty(qt.shape)
        accepted = np.zeros(qt.shape, dtype=bool)
        sizes = 8 * ((k + 12 + np.ceil(np.sqrt(qt)).astype(int) + 7) // 8)
        for size in np.unique(sizes):
            idx = np.nonzero(sizes == size)[0]
            width = max(64, 2048 * 32 // int(size))  # keeps the size x block arrays in cache
            for sel in (idx[i : i + width] for i in range(0, idx.size, width)):
                v[sel], e[sel], accepted[sel] = _hill_batch.refine_batch(
                    fam.offset, fam.q_sign, fam.sqrt2, k, qt[sel], st[sel], int(size), tol
                )
    values[todo], errors[todo] = v, e
    for i in todo[~accepted]:
        values[i], errors[i] = _hill.refined_value(fam, k, float(q[i]), tol)
    return values, errors


# ---------------------------------------------------------------------------------------------- seed tables
def _clenshaw(c: np.ndarray, t: np.ndarray) -> np.ndarray:
    """sum c_j T_j(t) (the operations of the C kernel's ``seed_value``)."""
    t2 = 2.0 * t
    b1 = np.zeros_like(t)
    b2 = np.zeros_like(t)
    for cj in c[:0:-1]:
        b1, b2 = (t2 * b1 - b2) + cj, b1
    return (t * b1 - b2) + c[0]


def _crude(kind: str, n: int, h: np.ndarray) -> np.ndarray:
    """A start for the generation: the small-q series' first terms below h = s / 2, the expansion above."""
    s = _s(kind, n)
    q = h * h
    if n == 0:
        small = -0.5 * q * q
    elif n == 1:
        small = 1.0 + q if kind == "a" else 1.0 - q
    else:
        small = n * n + q * q / (2.0 * (n * n - 1.0))
    with np.errstate(divide="ignore"):
        return np.where(h > 0.5 * s, asymptotic(s, np.maximum(h, 1e-3)), small)


def _node_values(kind: str, n: int, q: np.ndarray, start: np.ndarray) -> np.ndarray:
    """kind_n at the nodes: the C kernel from ``start``, or (NumPy fallback) LAPACK's bisection per point, which needs
    no start (a seed table needs ~1e-13 relative accuracy, not certification)."""
    if _hill_c.kernel() is not None:
        return refine(kind, n, q, start, 1e-13)[0]
    fam, k = _hill.family_index(kind, n)
    return np.array([_hill.solve_hill(fam, k, float(x)).value if x else float((2 * k + fam.offset) ** 2) for x in q])


@functools.cache
def table(kind: str, n: int) -> np.ndarray:
    """The seed table of kind_n (layout of the C kernel: [P, h_max, s, P + 1 breakpoints, P (DEG + 1) coefficients])."""
    s = _s(kind, n)
    h_max = 6.0 * s + 20.0
    breaks = sorted({b for b in (0.0, 0.25 * s, 0.5 * s, 0.75 * s, s, 1.5 * s, 2.0 * s, 3.0 * s, 4.5 * s, h_max)})
    stack = [(lo, hi, None) for lo, hi in zip(breaks[-2::-1], breaks[:0:-1], strict=True)]
    pieces = []
    while stack:
        lo, hi, parent = stack.pop()
        h = 0.5 * (lo + hi) + 0.5 * (hi - lo) * _NODES
        if parent is None:
            start = _crude(kind, n, h)
        else:
            plo, phi, pc = parent
            start = _clenshaw(pc, (2.0 * h - (plo + phi)) / (phi - plo)) - 2.0 * (h * h)
        q = h * h
        values = _node_values(kind, n, q, start)
        c = _DCT @ (values + 2.0 * q)
        scale = max(1.0, float(np.min(np.abs(values))))
        if 2.0 * (abs(c[-1]) + abs(c[-2])) <= _TARGET * scale or hi - lo < 1e-3:
            pieces.append((lo, hi, c))
        else:
            mid = 0.5 * (lo + hi)
            stack += [(mid, hi, (lo, hi, c)), (lo, mid, (lo, hi, c))]
    pieces.sort(key=lambda p: p[0])
    out = np.concatenate(
        [[len(pieces), h_max, s], [p[0] for p in pieces], [pieces[-1][1]], np.concatenate([p[2] for p in pieces])]
    )
    out.setflags(write=False)
    return out


def seeds(kind: str, n: int, q: np.ndarray) -> np.ndarray:
    """Initial approximations of kind_n at the points q >= 0 (1-d float64)."""
    tab = table(kind, n)
    lib = _hill_c.kernel()
    if lib is not None:
        return _hill_c.seeds(lib, tab, q)
    npieces, h_max, s = int(tab[0]), tab[1], tab[2]
    breaks = tab[3 : 4 + npieces]
    coef = tab[4 + npieces :].reshape(npieces, DEG + 1)
    h = np.sqrt(q)
    out = np.empty(q.shape)
    big = ~(h < h_max)
    out[big] = asymptotic(s, h[big])
    piece = np.clip(np.searchsorted(breaks, h, side="right") - 1, 0, npieces - 1)
    for p in np.unique(piece[~big]):
        sel = np.nonzero((piece == p) & ~big)[0]
        lo, hi = breaks[p], breaks[p + 1]
        out[sel] = _clenshaw(coef[p], (2.0 * h[sel] - (lo + hi)) / (hi - lo)) - 2.0 * q[sel]
    return out


def raw(kind: str, n: int, q: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray]:
    """Raw values and error estimates of kind_n at the points q >= 0 from their seeds (no ordering clamp)."""
    return refine(kind, n, q, seeds(kind, n, q), tol)


# ---------------------------------------------------------------------------------------------- clamp regions
def _relative_gap(lower: tuple[str, int], upper: tuple[str, int], n2: float, h: np.ndarray) -> np.ndarray:
    q = h * h
    return (raw(*upper, q, 1e-13)[0] - raw(*lower, q, 1e-13)[0]) / (n2 + 2.0 * q + 1.0)


def _crossing(lower: tuple[str, int], upper: tuple[str, int], n2: float, h: np.ndarray, first: bool) -> float:
    """The h where the relative gap crosses THRESHOLD: the first crossing from above (``first``) or the last one
    from below, located on the grid ``h`` and then on two finer grids."""
    for _ in range(3):
        below = _relative_gap(lower, upper, n2, h) < THRESHOLD
        idx = np.nonzero(below)[0]
        if first:
            if not idx.size:
                return float(h[-1])
            j = int(idx[0])
            if j == 0:
                return float(h[0])
            lo, hi = h[j - 1], h[j]
        else:
            if not idx.size:
                return float(h[0])
            j = int(idx[-1])
            if j == h.size - 1:
                return float(h[-1])
            lo, hi = h[j], h[j + 1]
        h = np.linspace(lo, hi, 33)
    return float(hi if not first else lo)


@functools.cache
def upper_threshold(n: int) -> float:
    """h_c(n): the pair (a_n, b_{n+1}) is clamped where h >= h_c(n)."""
    s = 2 * n + 1
    h = np.linspace(0.0, 1.5 * s + 12.0, 97)
    return 0.99 * _crossing(("a", n), ("b", n + 1), float(n * n), h, first=True)


@functools.cache
def lower_threshold(n: int) -> float:
    """h_s(n), n >= 1: the pair (b_n, a_n) is clamped where h <= h_s(n)."""
    s = 2 * n + 1
    h = np.linspace(0.0, 1.5 * s + 12.0, 97)
    return 1.01 * _crossing(("b", n), ("a", n), float(n * n), h, first=False)


class Neighbour(NamedTuple):
    """A neighbour in the chain a_0 <= b_1 <= a_1 <= ... and the interval of h = sqrt(q) where it is clamped against."""

    kind: str
    n: int
    h_low: float
    h_high: float

    def covers(self, q: np.ndarray) -> np.ndarray:
        h = np.sqrt(q)
        return (q != 0.0) & (h >= self.h_low) & (h <= self.h_high)


@functools.cache
def neighbours(kind: str, n: int) -> tuple[Neighbour | None, Neighbour | None]:
    """(lower, upper) neighbours of kind_n with their clamp intervals (None: no lower neighbour of a_0)."""
    if kind == "a":
        lower = Neighbour("b", n, 0.0, lower_threshold(n)) if n >= 1 else None
        upper = Neighbour("b", n + 1, upper_threshold(n), math.inf)
    else:
        lower = Neighbour("a", n - 1, upper_threshold(n - 1), math.inf)
        upper = Neighbour("a", n, 0.0, lower_threshold(n))
    return lower, upper


@functools.cache
def plan(kind: str, n: int) -> np.ndarray:
    """The C kernel's plan of kind_n: header (kind, n, table offsets, clamp intervals), then the seed tables."""
    lower, upper = neighbours(kind, n)
    header = np.zeros(_HEADER)
    parts = [table(kind, n)]
    header[:3] = (kind == "b", n, _HEADER)
    offset = _HEADER + parts[0].size
    for side, nb in enumerate((lower, upper)):
        if nb is None:
            header[3 + side] = -1.0
            continue
        header[3 + side] = offset
        header[5 + 2 * side : 7 + 2 * side] = (nb.h_low, nb.h_high)
        parts.append(table(nb.kind, nb.n))
        offset += parts[-1].size
    out = np.ascontiguousarray(np.concatenate([header, *parts]))
    out.setflags(write=False)
    return out
