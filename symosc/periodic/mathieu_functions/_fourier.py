"""Fourier coefficients of the periodic Mathieu functions, and the Hill determinants of the exponent (private).

Coefficients (DLMF 28.4).  With ``kind_n`` mapped to a Hill family and an index k inside it (see
:mod:`symosc.periodic._hill`), the coefficient vector is the eigenvector of the symmetric Hill matrix at the
characteristic value; it is computed here from the *twisted factorisation* of ``T - lambda I`` at the certified value
``lambda`` (Parlett & Dhillon 1997): forward pivots ``t_j``, backward pivots ``u_j``, twist
``m = argmin |gamma_j|``, ``z_m = 1``, ``z_j = -e_j z_{j+1} / t_j`` above and ``z_j = -e_{j-1} z_{j-1} / u_j`` below.
Every component is a product of ratios (no subtraction of nearly equal vectors), so small components keep their
relative accuracy.  Normalisation (DLMF 28.2.30): ``2 A_0^2 + sum A_{2j}^2 = 1`` for ce_{2m} (the symmetric form
carries ``sqrt(2) A_0``), ``sum = 1`` otherwise.  Sign: the first coefficient (A_0, A_1, B_1 or B_2) is positive for
q > 0 -- it never vanishes (the first component of an eigenvector of an unreduced tridiagonal matrix is nonzero), and
is positive at small q > 0 by perturbation theory, so this is DLMF's "continuity in q from q = 0".  Negative q by
DLMF 28.2(vii): coefficient j of the |q| function of the swapped kind (odd n) times (-1)^(m + j).

Exact q-series of the coefficients (DLMF 28.6): Rayleigh-Schrodinger perturbation theory on the non-symmetric Hill
matrix in ``fractions.Fraction`` (as in :mod:`symosc.periodic.mathieu_series`), then the normalisation by the series
of ``1 / sqrt(norm)``.

Exponent (DLMF 28.2(iv), Hill's determinant; Whittaker & Watson 1927, section 19.42): with ``D(nu)`` the normalised
infinite determinant, ``sin^2(pi nu / 2) = D(0) sin^2(pi sqrt(a) / 2)`` and ``cos^2(pi nu / 2) = D(1)
cos^2(pi sqrt(a) / 2)``.  Both are evaluated as products of LDL^T pivots of the four Hill families divided by the
squared Fourier indices, times the tail of the sine/cosine product (a Hurwitz zeta series), so no pole of ``D`` is
ever evaluated.  The number of negative pivots is the number of characteristic values below ``a``, which fixes the
integer part of nu.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from ...errors import ConvergenceError
from .._hill import FAMILIES, family_index

_EPS = float(np.finfo(float).eps)
_SQRT2 = math.sqrt(2.0)


# --------------------------------------------------------------------------------------------- family bookkeeping
def resolve(kind: str, n: int, q_negative: bool) -> tuple[str, int]:
    """(kind of the |q| function, sign pattern base m) per DLMF 28.2(vii); odd n swap ce <-> se for q < 0."""
    if q_negative and n % 2 == 1:
        return ("b" if kind == "a" else "a"), n
    return kind, n


def fourier_indices(kind: str, n: int, size: int) -> np.ndarray:
    """Fourier index (multiple of x in cos/sin) of the coefficient j = 0..size-1 of kind_n."""
    fam, _k = family_index(kind, n)
    return 2 * np.arange(size) + fam.offset


def row_budget(kind: str, n: int, q: np.ndarray) -> int:
    """Rows allowed per point: twice a first size that grows like sqrt(q) (the kernel starts smaller and doubles)."""
    _fam, k = family_index(kind, n)
    r = int(np.ceil(1.5 * np.sqrt(np.max(np.abs(q))))) if q.size else 0
    return 2 * 8 * ((k + 24 + r + 7) // 8)


def gap_estimates(kind: str, n: int, q: np.ndarray) -> np.ndarray:
    """A first guess of half the distance from kind_n to its neighbours in the same Hill family (certified, and
    reduced where needed, by Sturm counts): spacing 4n - 4 (4n + 4 without a lower neighbour) at q = 0,
    8 sqrt(q) - 2(n + 2) at large q (DLMF 28.8.1)."""
    _fam, k = family_index(kind, n)
    low = 4.0 * n - 4.0 if k > 0 else 4.0 * n + 4.0
    return 0.5 * np.maximum(max(low, 4.0), 8.0 * np.sqrt(np.abs(q)) - 2.0 * (n + 2))


# --------------------------------------------------------------------------------------------- eigenvectors
def coefficients(
    kind: str, n: int, q: np.ndarray, lam: np.ndarray, tol: float, derivative: bool = False, keep_tail: bool = False
) -> dict:
    """Fourier coefficients at the points q >= 0 (1-d) for the certified values lam, with sound error bounds.

    Returns ``coef`` (points x rows, zero beyond ``rows``; A_0 not symmetrised), ``rows``, ``index`` (Fourier indices
    of the columns), ``bound`` (2-norm error of the symmetric unit eigenvector, truncation included: Davis-Kahan with
    the residual and a Sturm-certified gap), ``err0``/``err1`` (bounds for the function and its x-derivative at
    every x, the rounding of the sums included).  ``derivative``: the vector is made accurate enough for the
    derivative's bound too (an extended-precision step more where needed); ``keep_tail``: the negligible last rows
    are kept (for the Bessel-product series of the modified functions).  Raises ConvergenceError where the last
    rows stay above ``tol / 1000`` or no gap is certified.
    """
    from .._hill_c import kernel

    fam, k = family_index(kind, n)
    budget = row_budget(kind, n, q)
    gaps = gap_estimates(kind, n, q)
    lib = kernel()
    q = np.ascontiguousarray(q, dtype=float)
    lam = np.ascontiguousarray(lam, dtype=float)
    if lib is not None:
        coef = np.empty((q.size, budget))
        rows = np.empty(q.size, dtype=np.intc)
        bound, err0, err1, s0, s1 = (np.empty(q.size) for _ in range(5))
        status = np.empty(q.size, dtype=np.uint8)
        if lib.symosc_mathieu_coefficients(fam.offset, fam.q_sign, int(fam.sqrt2), k, q.size, q.ctypes.data,
                                           lam.ctypes.data, gaps.ctypes.data, tol, int(derivative) + 2 * keep_tail,
                                           budget,
                                           coef.ctypes.data, rows.ctypes.data, bound.ctypes.data, err0.ctypes.data,
                                           err1.ctypes.data, s0.ctypes.data, s1.ctypes.data,
                                           status.ctypes.data):  # fmt: skip
            raise MemoryError("the Mathieu kernel could not allocate its work array")
        used = int(rows.max()) if q.size else 1
        co = {"coef": coef[:, :used], "rows": rows, "bound": bound, "err0": err0, "err1": err1, "s0": s0, "s1": s1}
    else:
        coef, rows, bound, tail, status = _coefficients_numpy(kind, n, q, lam, gaps, 1e-3 * tol, budget)
        used = int(rows.max()) if q.size else 1
        co = {"coef": coef[:, :used], "rows": rows, "bound": bound, "tail": tail}
    co["index"] = 2 * np.arange(used) + fam.offset
    if np.any(status != 1):
        bad = int(np.sum(status != 1))
        raise ConvergenceError(
            f"Fourier coefficients of the Mathieu function did not converge at {bad} point(s) (the last of {budget} "
            "rows above tol / 1000, or no certified gap); q is too large for this truncation",
            achieved=math.inf,
        )
    if lib is None:
        co["err0"], co["err1"] = error_bounds(kind, n, co)
        co["s0"] = np.sum(np.abs(co["coef"]), axis=1)
        co["s1"] = np.sum(np.abs(co["coef"]) * co["index"][None, :], axis=1)
    return co


def _sturm_counts(fam, q: np.ndarray, x: np.ndarray, size: int) -> np.ndarray:
    """Number of eigenvalues below x of the size x size matrices (vectorised over points)."""
    e0 = _SQRT2 * q if fam.sqrt2 else q
    b0, bq = e0 * e0, q * q
    with np.errstate(all="ignore"):
        t = float(fam.offset**2) + fam.q_sign * q - x
        t = np.where(t == 0.0, -_EPS * (np.abs(x) + 1.0), t)
        count = (t < 0.0).astype(int)
        for j in range(1, size):
            t = ((2.0 * j + fam.offset) ** 2 - x) - (b0 if j == 1 else bq) / t
            t = np.where(t == 0.0, -_EPS * (np.abs(x) + 1.0), t)
            count += t < 0.0
    return count


def _residual_numpy(fam, q, mu, z, size):
    """2-norm of (T - mu I) z per point (columns of z, long double; the truncated row included) with a bound on the
    rounding of that evaluation, and z . (T - mu I) z."""
    ld = np.longdouble
    idx = (2.0 * np.arange(size) + fam.offset)[:, None]
    e = np.full((size, q.size), 1.0, dtype=ld) * q.astype(ld)
    e[0] = (np.sqrt(ld(2)) if fam.sqrt2 else ld(1)) * q.astype(ld)
    d = np.broadcast_to(idx**2, (size, q.size)).astype(ld)
    d[0] = ld(fam.offset**2) + fam.q_sign * q.astype(ld)
    zl = z.astype(ld)
    r = (d - mu) * zl
    r[:-1] += e[:-1] * zl[1:]
    r[1:] += e[:-1] * zl[:-1]
    zd = np.abs(zl.astype(float))
    sj = np.abs((d - mu).astype(float)) * zd
    sj[:-1] += np.abs(e[:-1].astype(float)) * zd[1:]
    sj[1:] += np.abs(e[:-1].astype(float)) * zd[:-1]
    extra = q.astype(ld) * zl[-1]
    eps_ld = float(np.finfo(ld).eps)
    rnorm = np.sqrt(np.asarray(np.sum(r * r, axis=0) + extra * extra, dtype=float)) * (1 + 4 * _EPS)
    return rnorm + 8 * eps_ld * np.sqrt(np.sum(sj * sj, axis=0)), np.sum(zl * r, axis=0)


def _vector_ld(fam, q, mu, m, size):
    """The twisted vector at the shifts mu (long double) with twists m, in long double, unit, first component > 0."""
    ld = np.longdouble
    ql = q.astype(ld)
    el0 = (np.sqrt(ld(2)) if fam.sqrt2 else ld(1)) * ql
    diag = (2.0 * np.arange(size) + fam.offset) ** 2
    d = [ld(fam.offset**2) + fam.q_sign * ql] + [ld(v) + 0 * ql for v in diag[1:]]
    z = np.ones((size, q.size), dtype=ld)
    rho = np.ones((size, q.size), dtype=ld)
    with np.errstate(all="ignore"):
        t = d[0] - mu
        for j in range(size - 1):  # rho_j = z_j / z_{j+1} above the twist
            ej = el0 if j == 0 else ql
            rho[j] = -ej / t
            t = (d[j + 1] - mu) + ej * rho[j]
        u = d[size - 1] - mu
        below = np.ones((size, q.size), dtype=ld)
        for j in range(size - 1, 0, -1):  # z_j / z_{j-1} below the twist
            ej = el0 if j == 1 else ql
            below[j] = -ej / u
            u = (d[j - 1] - mu) + ej * below[j]
        rows = np.arange(size)[:, None]
        for j in range(size - 2, -1, -1):
            z[j] = np.where(j < m, rho[j] * z[j + 1], z[j])
        for j in range(1, size):
            z[j] = np.where(j > m, below[j] * z[j - 1], z[j])
        z = np.where(rows == m, ld(1), z)
        norm = np.sqrt(np.sum(z * z, axis=0))
        z = z / np.where(z[0] < 0, -norm, norm)
    return z


def _coefficients_numpy(kind, n, q, lam, gaps, tail_tol, budget):
    """The NumPy fallback of the C kernel (the same method: the twisted vector at lam, its Rayleigh quotient lam1 in
    long double and the vector again at lam1 in long double, its residual over a Sturm-certified gap), vectorised
    over the points at one matrix size, doubled while the tail is too large."""
    fam, k = family_index(kind, n)
    coef = np.zeros((q.size, budget))
    rows = np.zeros(q.size, dtype=int)
    bound, tail = np.full(q.size, np.inf), np.full(q.size, np.inf)
    status = np.zeros(q.size, dtype=np.uint8)
    todo = np.arange(q.size)
    size = min(budget, 8 * ((k + 12 + int(np.ceil(np.sqrt(np.max(q, initial=0.0)))) + 7) // 8))
    while todo.size:
        qt, lt = q[todo], lam[todo]
        z = eigenvectors(kind, n, qt, lt, size)[0]
        g = gaps[todo].copy()
        ok = np.zeros(qt.size, dtype=bool)
        for _ in range(8):
            now = ~ok & (_sturm_counts(fam, qt, lt - g, size) == k) & (_sturm_counts(fam, qt, lt + g, size) == k + 1)
            ok |= now
            g = np.where(ok, g, 0.25 * g)
        _r, dot = _residual_numpy(fam, qt, lt.astype(np.longdouble), z, size)
        lam1 = lt.astype(np.longdouble) + dot / np.sum(z.astype(np.longdouble) ** 2, axis=0)
        g1 = g - np.abs((lam1 - lt.astype(np.longdouble)).astype(float))
        zl = _vector_ld(fam, qt, lam1, np.argmax(np.abs(z), axis=0), size)
        rnorm, _dot = _residual_numpy(fam, qt, lam1, zl, size)
        z = zl.astype(float)
        ok &= (g1 > 0) & np.all(np.isfinite(z), axis=0)
        b = np.where(ok, _SQRT2 * rnorm / np.where(ok, g1, 1.0) * (1 + 8 * _EPS) + 0.5 * _EPS, np.inf)
        idx = (2.0 * np.arange(size) + fam.offset)[:, None]
        tl = np.max(np.abs(z[-4:]) * np.maximum(1.0, idx[-4:]), axis=0)
        done = ok & (tl <= tail_tol)
        last = size >= budget
        fin = done | last | ~ok
        sel = todo[fin]
        zf = z[:, fin].T.copy()
        if fam.sqrt2:
            zf[:, 0] /= _SQRT2
        coef[sel, :size] = zf
        rows[sel], bound[sel], tail[sel] = size, b[fin], tl[fin]
        status[sel] = np.where(done[fin], 1, np.where(ok[fin], 3, 0))
        todo = todo[~fin]
        size = min(2 * size, budget)
    return coef, rows, bound, tail, status


def eigenvectors(kind: str, n: int, q: np.ndarray, lam: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Unit eigenvectors (size x points) of the symmetric Hill matrices at q >= 0 for the values lam, and |gamma_m|,
    by the twisted factorisation (the NumPy fallback of the C kernel); first component made positive."""
    fam, _k = family_index(kind, n)
    npts = q.size
    diag = ((2.0 * np.arange(size) + fam.offset) ** 2)[:, None]
    e0 = _SQRT2 * q if fam.sqrt2 else q.copy()
    d0 = float(fam.offset**2) + fam.q_sign * q
    with np.errstate(all="ignore"):
        dx = np.broadcast_to(diag, (size, npts)) - lam
        dx[0] = d0 - lam
        b = np.empty((size, npts))  # b_j = e_j^2 (coupling of rows j and j+1)
        b[:] = q * q
        b[0] = e0 * e0
        t = np.empty((size, npts))
        t[0] = dx[0]
        tiny = _EPS * (np.abs(lam) + 4 * q + 1.0)
        for j in range(1, size):
            prev = np.where(t[j - 1] == 0.0, tiny, t[j - 1])
            t[j] = dx[j] - b[j - 1] / prev
        u = np.empty((size, npts))
        g = np.empty((size, npts))
        u[-1] = dx[-1]
        g[-1] = t[-1]
        for j in range(size - 2, -1, -1):
            nxt = np.where(u[j + 1] == 0.0, tiny, u[j + 1])
            r = b[j] / nxt
            u[j] = dx[j] - r
            g[j] = t[j] - r
        m = np.argmin(np.abs(g), axis=0)
        gm = np.abs(g[m, np.arange(npts)])
        rows = np.arange(size)[:, None]
        e = np.sqrt(b)  # e_j >= 0
        # ratios: above the twist z_j / z_{j+1} = -e_j / t_j; below z_j / z_{j-1} = -e_{j-1} / u_j
        up = np.where(rows < m, -e / np.where(t == 0.0, tiny, t), 1.0)
        down = np.ones((size, npts))
        down[1:] = np.where(rows[1:] > m, -e[:-1] / np.where(u[1:] == 0.0, tiny, u[1:]), 1.0)
        z = np.cumprod(up[::-1], axis=0)[::-1] * np.cumprod(down, axis=0)
        norm = np.sqrt(np.sum(z * z, axis=0))
        z /= np.where(z[0] < 0, -norm, norm)
    return z, gm / norm


def error_bounds(kind: str, n: int, co: dict) -> tuple[np.ndarray, np.ndarray]:
    """(bound for the function, bound for its x-derivative) per point for the NumPy fallback (the C kernel returns
    its own), valid for every x: the 2-norm error of the coefficients times the 2-norm of the basis functions'
    maxima over the rows kept, the neglected coefficients beyond them, and the rounding of the double sums
    (``rows + 6`` units per term)."""
    fam, _k = family_index(kind, n)
    coef, rows, bound, tail = co["coef"], co["rows"], co["bound"], co["tail"]
    idx = co["index"].astype(float)
    keep = np.arange(coef.shape[1])[None, :] < rows[:, None]
    w0 = np.where(keep, 1.0, 0.0)
    if fam.sqrt2:
        w0[:, 0] = 0.5  # A_0 = z_0 / sqrt(2): the basis function of z_0 is 1 / sqrt(2)
    w1 = np.where(keep, idx * idx, 0.0)
    kmax = 2.0 * rows + fam.offset
    absc = np.abs(coef)
    units = _EPS * (rows[:, None] + 6.0)
    rnd0 = np.sum(absc * units, axis=1)
    rnd1 = np.sum(absc * idx * units, axis=1)
    beyond = 2.0 * (tail + bound)
    err0 = bound * np.sqrt(np.sum(w0, axis=1)) + beyond + rnd0
    err1 = bound * np.sqrt(np.sum(w1, axis=1)) + beyond * kmax + rnd1
    return err0 * (1 + 1e-6), err1 * (1 + 1e-6)


def signs_negative_q(kind: str, n: int, size: int) -> np.ndarray:
    """(-1)^(m + j) of DLMF 28.2(vii) for the coefficients j of the |q| function (m = n // 2, (n - 1) // 2, ...)."""
    if kind == "a":
        m = n // 2
    else:
        m = (n - 1) // 2 if n % 2 == 1 else n // 2 - 1
    return np.where((np.arange(size) + m) % 2 == 0, 1.0, -1.0)


# --------------------------------------------------------------------------------------------- exact q-series
def coefficient_series(kind: str, n: int, order: int) -> tuple[list[list[Fraction]], list[Fraction]]:
    """Unnormalised coefficient series (intermediate normalisation c_k = 1) and the norm series, exact.

    Returns (x, norm): ``x[s][j]`` is the q^s coefficient of the Fourier coefficient j (non-symmetric form, the
    actual A_j), ``norm[s]`` the q^s coefficient of ``w_0 A_0^2 + sum A_j^2`` (w_0 = 2 for ce_{2m}).
    """
    fam, k = family_index(kind, n)
    size = k + order + 2
    d = [(2 * j + fam.offset) ** 2 for j in range(size)]
    zero = Fraction(0)

    def apply_e(x: list[Fraction]) -> list[Fraction]:
        out = [zero] * size
        for j in range(size):
            s = zero
            if j > 0:
                s += (2 if (fam.sqrt2 and j == 1) else 1) * x[j - 1]
            if j + 1 < size:
                s += x[j + 1]
            if j == 0 and fam.q_sign:
                s += fam.q_sign * x[0]
            out[j] = s
        return out

    x0 = [zero] * size
    x0[k] = Fraction(1)
    xs = [x0]
    alpha = [Fraction(d[k])]
    for s in range(1, order + 1):
        ex = apply_e(xs[s - 1])
        alpha.append(ex[k])
        x = [zero] * size
        for j in range(size):
            if j == k:
                continue
            acc = -ex[j]
            for i in range(1, s + 1):
                if xs[s - i][j] and alpha[i]:
                    acc += alpha[i] * xs[s - i][j]
            x[j] = acc / (d[j] - d[k])
        xs.append(x)
    w = [2 if (fam.sqrt2 and j == 0) else 1 for j in range(size)]
    norm = []
    for s in range(order + 1):
        norm.append(sum((w[j] * xs[i][j] * xs[s - i][j] for i in range(s + 1) for j in range(size)), zero))
    return xs, norm


# --------------------------------------------------------------------------------------------- Hill determinants
def _log_tail(a: float, start: float, step_odd: bool, j_from: int) -> float:
    """log prod_{j >= j_from} (1 - a / m_j^2)^2 with m_j = 2j (even) or 2j + 1 (odd), by the zeta series."""
    from scipy.special import zeta

    # sum_{j >= j_from} m_j^(-2p) = 2^(-2p) zeta(2p, j_from + shift)
    shift = 0.5 if step_odd else 0.0
    ratio = abs(a) / (2.0 * (j_from + shift)) ** 2
    if ratio >= 0.5:  # pragma: no cover - the caller chooses j_from large enough
        raise ConvergenceError("Hill determinant: tail series does not converge (matrix too small)")
    total = 0.0
    p = 1
    while True:
        term = (a / 4.0) ** p * float(zeta(2 * p, j_from + shift)) / p
        total += term
        if abs(term) <= 1e-18 * max(abs(total), 1e-300) or p > 200:
            break
        p += 1
    return -2.0 * total


def _pivot_product(fam_name: str, q: float, a: float, size: int) -> tuple[float, int, int]:
    """(log |prod_j t_j / m_j^2|, sign of it, negative-pivot count) of T - a I for one infinite Hill family, q >= 0.

    m_j = 2j + offset is the Fourier index; for the family ``ae`` the j = 0 factor is t_0 itself (no division).
    The pivots are run exactly up to ``size``; beyond, ``log(t_j / (m_j^2 - a)) = -c_j - c_j c_{j-1} - c_j^2 / 2
    + O(c^3)`` with ``c_j = q^2 / ((m_j^2 - a)(m_{j-1}^2 - a))``, summed by the Euler-Maclaurin formula (midpoint
    integral plus the first derivative correction).  The tail of ``prod (1 - a / m_j^2)`` is added by the caller.
    """
    from scipy.integrate import quad

    fam = FAMILIES[fam_name]
    e0 = _SQRT2 * q if fam.sqrt2 else q
    t = float(fam.offset**2) + fam.q_sign * q - a
    logs = 0.0
    sign = 1
    count = 0
    tiny = _EPS * (abs(a) + 4 * q + 1.0)
    for j in range(size):
        m = 2 * j + fam.offset
        if j:
            bj = (e0 * e0) if j == 1 else q * q
            t = (m * m - a) - bj / t
        if t == 0.0:
            t = -tiny
        count += t < 0.0
        ratio = t / (m * m) if m else t
        if ratio < 0:
            sign = -sign
        logs += math.log(abs(ratio))
    # the factors m_j^2 - a of j < size are in the ratios above through m_j^2 and the caller's sine/cosine tail;
    # what is left is prod_{j >= size} t_j / (m_j^2 - a)
    if q == 0.0:
        return logs, sign, count
    off = fam.offset
    q2 = q * q

    def c(x: float) -> float:
        m1, m0 = 2 * x + off, 2 * x + off - 2
        return q2 / ((m1 * m1 - a) * (m0 * m0 - a))

    def f(x: float) -> float:
        cx = c(x)
        return cx + 1.5 * cx * cx

    # continue exactly while c is not small, then the integral
    j = size
    while True:
        m = 2 * j + off
        cj = c(j)
        if cj < 1e-8 and j > size + 10:
            break
        t = (m * m - a) - q2 / t
        logs += math.log(t / (m * m - a))  # the ratio is positive here (m^2 >> |a|, 2q)
        j += 1
    # pivots j and beyond: sum_{i >= j} f(i) = integral from j - 1/2 + f'(j - 1/2) / 24 - 7 f'''(j - 1/2) / 5760
    integral, _err = quad(f, j - 0.5, math.inf, epsabs=1e-22, epsrel=1e-13, limit=200)
    h = 1e-3 * j
    deriv = (f(j - 0.5 + h) - f(j - 0.5 - h)) / (2 * h)
    # third-derivative term of the midpoint rule, with f ~ x^-4 there: f''' = -120 f / x^3
    x0 = j - 0.5
    logs -= integral + deriv / 24.0 + 7.0 / 5760.0 * 120.0 * f(x0) / x0**3
    return logs, sign, count


def hill_determinants(a: float, q: float) -> tuple[float, float, int, float]:
    """(S, C, N, err): S = sin^2(pi nu / 2), C = cos^2(pi nu / 2), N = number of characteristic values below a.

    ``err`` bounds the rounding of S and C from the pivots (``size * eps * condition``) and the mismatch
    ``|S + C - 1|`` (an exact identity).
    """
    q = abs(q)
    # Fourier indices up to M with M^2 >> |a|, 4q: pivots t_j ~ m_j^2 there; the tail product converges like
    # (|a| / M^2)^p and the truncation of the determinant like (q / M^2)^2
    size = int(12 + 2 * math.sqrt(abs(a) + 4 * q) + 8)
    logs = {}
    for name in ("ae", "be", "ao", "bo"):
        logs[name] = _pivot_product(name, q, a, size)
    # S = -(pi^2 / 4) * t_0^{ae} * prod_{j>=1} t_j^{ae} / (2j)^2 * prod_{j>=0} t_j^{be} / (2j+2)^2 * Q_even
    # where Q_even = prod_{j > size - 1 or size} (1 - a / (2j)^2)^2 (the two families end at indices 2(size-1), 2 size)
    lae, sae, cae = logs["ae"]
    lbe, sbe, cbe = logs["be"]
    lao, sao, cao = logs["ao"]
    lbo, sbo, cbo = logs["bo"]
    # tails: the ae family covers (2j)^2 for j < size, be covers (2j)^2 for 1 <= j <= size; the sine product needs
    # each (2j)^2, j >= 1, twice: ae is missing j >= size, be is missing j >= size + 1
    tail_e = 0.5 * (_log_tail(a, 0, False, size) + _log_tail(a, 0, False, size + 1))
    tail_o = _log_tail(a, 0, True, size)  # both odd families cover (2j+1)^2 for j < size
    log_s = lae + lbe + tail_e + math.log(math.pi**2 / 4)
    s_val = -sae * sbe * math.exp(log_s)
    log_c = lao + lbo + tail_o
    c_val = sao * sbo * math.exp(log_c)
    count = cae + cbe + cao + cbo
    err = 8 * size * _EPS * (abs(s_val) + abs(c_val)) + abs(s_val + c_val - 1.0)
    return s_val, c_val, count, err
