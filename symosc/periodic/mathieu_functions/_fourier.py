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


def first_size(kind: str, n: int, q: np.ndarray) -> np.ndarray:
    """Matrix size per point: the eigenvalue index plus a margin that grows like sqrt(q) (checked afterwards)."""
    _fam, k = family_index(kind, n)
    r = np.ceil(1.5 * np.sqrt(np.abs(q))).astype(int)
    return 8 * ((k + 20 + r + 7) // 8)


# --------------------------------------------------------------------------------------------- eigenvectors
def eigenvectors(kind: str, n: int, q: np.ndarray, lam: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Unit eigenvectors (size x points) of the symmetric Hill matrices at q >= 0 for the values lam, and |gamma_m|.

    The sign of the first component is made positive.  Vectorised over the points (all of one matrix size).
    The componentwise relative rounding error of the result is left in ``eigenvectors.last_rel``.
    """
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
        # componentwise relative rounding error of z: each ratio carries eps (1 + condition of its pivot), the
        # pivot condition being (|d_j| + |lambda| + |b / previous pivot|) / |pivot|; accumulated along the path
        absd = np.broadcast_to(diag, (size, npts)) + np.abs(lam)
        cond_t = np.ones((size, npts))
        cond_t[1:] = (absd[1:] + np.abs(b[:-1] / np.where(t[:-1] == 0.0, tiny, t[:-1]))) / np.abs(
            np.where(t[1:] == 0.0, tiny, t[1:])
        )
        cond_u = np.ones((size, npts))
        cond_u[:-1] = (absd[:-1] + np.abs(b[:-1] / np.where(u[1:] == 0.0, tiny, u[1:]))) / np.abs(
            np.where(u[:-1] == 0.0, tiny, u[:-1])
        )
        # a tiny pivot (a node of the coefficient sequence) has a huge condition, but the product of its ratio with
        # the next one, t_j t_{j+1} = t_j (d_{j+1} - lambda) - b_j, is well conditioned: cap the single-ratio value
        cond_t = np.minimum(cond_t, 1e3)
        cond_u = np.minimum(cond_u, 1e3)
        c_up = np.where(rows < m, 3.0 + cond_t, 0.0)
        c_down = np.where(rows > m, 3.0 + cond_u, 0.0)
        # rounding errors of the ratios are independent: root-sum-square along the path (a linear sum overstates
        # the measured errors by two orders of magnitude at q = 1e4)
        rel = np.sqrt(np.cumsum((c_up * c_up)[::-1], axis=0)[::-1] + np.cumsum(c_down * c_down, axis=0)) * _EPS
        norm = np.sqrt(np.sum(z * z, axis=0))
        z /= np.where(z[0] < 0, -norm, norm)
    eigenvectors.last_rel = rel  # type: ignore[attr-defined]
    return z, gm / norm


def coefficients(kind: str, n: int, q: np.ndarray, lam: np.ndarray, tol: float) -> dict:
    """Fourier coefficients at q >= 0 (1-d arrays q, lam): matrix (size x points), Fourier indices, bounds.

    The size is increased until the tail (|z_j| of the last rows, times the Fourier index for derivatives) is below
    ``tol * 1e-3``; raises ConvergenceError when no size up to 16 times the first one reaches it.
    """
    sizes = first_size(kind, n, q)
    size = int(sizes.max()) if q.size else 8
    for _ in range(5):
        z, resid = eigenvectors(kind, n, q, lam, size)
        rel = eigenvectors.last_rel  # type: ignore[attr-defined]
        k_last = fourier_indices(kind, n, size)[-4:]
        tail = np.max(np.abs(z[-4:]) * np.maximum(1, k_last)[:, None], axis=0) if q.size else np.zeros(0)
        if not np.any(tail > 1e-3 * tol):
            break
        size *= 2
    else:
        raise ConvergenceError(
            f"Fourier coefficients of the Mathieu function did not converge (tail {float(tail.max()):.3g} at size "
            f"{size}); q is too large for this truncation",
            achieved=float(tail.max()),
        )
    fam, _k = family_index(kind, n)
    z = z.copy()
    if fam.sqrt2:
        z[0] /= _SQRT2  # symmetric component sqrt(2) A_0 -> A_0
    idx = fourier_indices(kind, n, size)
    return {"coef": z, "index": idx, "resid": resid, "tail": tail, "rel": rel}


def error_bounds(kind: str, n: int, q: np.ndarray, lam: np.ndarray, lam_err: np.ndarray, co: dict):
    """(bound for the function, bound for the derivative) per point, from the coefficient errors.

    Eigenvector perturbation: ``|dz| <= (|dlambda| + rho + c eps ||T||) / gap`` (Davis-Kahan), with ``gap`` a lower
    estimate of the distance to the neighbouring eigenvalues of the same family; rounding of the sums
    ``~ N eps sum |A_j|`` (resp. ``sum j |A_j|``); plus the truncated tail.
    """
    coef, idx = co["coef"], co["index"]
    size = coef.shape[0]
    h = np.sqrt(np.abs(q))
    # spacing to the neighbours of the same family: 4(n + 1) at q = 0, 8h - 2(n + 2) at large q (DLMF 28.8.1)
    gap = np.maximum(4.0 * (n + 1.0), 8.0 * h - 2.0 * (n + 2.0))
    dz = (lam_err + co["resid"]) / gap  # 2-norm of the eigenvector change (Davis-Kahan)
    absc = np.abs(coef)
    ik = idx[:, None].astype(float)
    s0 = np.sum(absc, axis=0)
    s1 = np.sum(absc * ik, axis=0)
    # componentwise rounding (relative, accumulated along the factorisation) and the normalisation
    comp = np.sum(absc * co["rel"], axis=0) + 2 * _EPS * s0
    comp1 = np.sum(absc * co["rel"] * ik, axis=0) + 2 * _EPS * s1
    sums = 2 * math.log2(size + 1) * _EPS
    # the change of the eigenvector changes the function by at most |dz| times its sup-norm scale sum |A_j|
    err0 = comp + dz * np.maximum(1.0, s0) + sums * s0 + co["tail"]
    err1 = comp1 + dz * np.maximum(1.0, s1) + sums * s1 + co["tail"] * idx[-1]
    return err0, err1


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
