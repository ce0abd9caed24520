"""The per-point Mathieu kernel of :mod:`symosc.periodic._hill_batch` in C (private).

One C function refines a whole batch of seeds (matrix size choice, twisted factorisation, Rayleigh-quotient steps,
pivot count, error bounds -- the operations of :func:`symosc.periodic._hill_batch.refine_scalar`), and a second one
computes the gap estimates and the seed rule of :mod:`symosc.periodic._mathieu_auto`.  Scalar calls go through the
same C code, so scalar and vectorised results have the same bits.  The library is compiled once with the C
backend's build cache (:mod:`symosc.numeric._build`); without a C compiler (or with ``SYMOSC_MATHIEU_KERNEL=numpy``)
:func:`kernel` returns None and the NumPy implementation runs instead.
"""

from __future__ import annotations

import ctypes
import os

import numpy as np

SOURCE = r"""
#include <float.h>
#include <math.h>
#include <stdlib.h>

#define EPS 2.220446049250313e-16
#define RHO_MAX 1e-3
#define MAX_STEPS 4
#define MAX_SIZE 65536

static int batch_size(int k, double q) {
    double r = ceil(sqrt(q));
    if (!(r < MAX_SIZE)) return -1;
    int n = k + 12 + (int)r;
    return 8 * ((n + 7) / 8);
}

/* One twisted-factorisation step at x: returns 1 and fills the outputs, or 0 when a pivot vanishes. */
static int step(int offset, double d0, double e0, int n, double q, double x, double *t, double *u, double *z,
                double *value, double *scale, double *rho2, double *trunc, int *index) {
    double b0 = e0 * e0, bq = q * q;
    double tj = d0 - x, b = b0;
    for (int j = 0; j < n; j++) {
        if (j) {
            double sq = (double)(2 * j + offset) * (double)(2 * j + offset);
            tj = (sq - x) - b / tj;
            b = bq;
        }
        if (tj == 0.0 && j < n - 1) return 0;
        t[j] = tj;
    }
    double sqn = (double)(2 * (n - 1) + offset) * (double)(2 * (n - 1) + offset);
    double uj = (n == 1) ? d0 - x : sqn - x;
    if (uj == 0.0 && n > 1) return 0;
    u[n - 1] = uj;
    int m = n - 1;
    double gm = fabs(t[n - 1]);
    for (int j = n - 2; j >= 0; j--) {
        double bqj = (j == 0 ? b0 : bq) / uj;
        double dxj = (j == 0) ? d0 - x : (double)(2 * j + offset) * (double)(2 * j + offset) - x;
        uj = dxj - bqj;
        if (uj == 0.0 && j > 0) return 0;
        u[j] = uj;
        double g = fabs(t[j] - bqj);
        if (g <= gm) { m = j; gm = g; }  /* first minimum, as argmin */
    }
    int idx = 0;
    for (int j = 0; j < m; j++) idx += t[j] < 0.0;
    for (int j = m + 1; j < n; j++) idx += u[j] < 0.0;
    z[m] = 1.0;
    for (int j = m - 1; j >= 0; j--) z[j] = ((j == 0 ? -e0 : -q) / t[j]) * z[j + 1];
    for (int j = m + 1; j < n; j++) z[j] = ((j == 1 ? -e0 : -q) / u[j]) * z[j - 1];
    /* the Rayleigh quotient summed in long double: where |value| << 2q the cancellation between the diagonal and
       the off-diagonal sums is what limits the accuracy (the rounding bound uses LDBL_EPSILON for these sums) */
    long double zz = (long double)z[0] * z[0];
    long double norm2 = zz, dsum = (long double)d0 * zz, dabs = fabs(d0) * zz, c = 0.0L, cross = 0.0L, cabs = 0.0L;
    if (n > 1) { c = (long double)e0 * ((long double)z[0] * z[1]); cross = c; cabs = fabsl(c); }
    for (int j = 1; j < n; j++) {
        long double zj = z[j];
        zz = zj * zj;
        norm2 += zz;
        long double dz = (long double)((double)(2 * j + offset) * (double)(2 * j + offset)) * zz;
        dsum += dz;
        dabs += dz;
        if (j < n - 1) {
            c = (long double)q * (zj * z[j + 1]);
            cross += c;
            cabs += fabsl(c);
        }
    }
    *value = (double)((dsum + 2.0L * cross) / norm2);
    *scale = (double)((dabs + 2.0L * cabs) / norm2);
    *rho2 = (double)(((long double)gm * gm) / norm2);
    long double w = (long double)q * z[n - 1];
    *trunc = (double)((w * w) / norm2);
    *index = idx;
    return 1;
}

/* Rayleigh-quotient steps from x for eigenvalue k (0-based) of one Hill family at q >= 0 (the first one is enough
   for a seed accurate to rounding), then the index and error checks.  Returns 1 (accepted), 2 (right eigenvalue but
   error estimate above tol) or 0 (rejected: wrong index, seed too far, vanishing pivot). */
static int rq_point(int offset, double d0, double e0, int n, int k, double q, double x, double tol, double *work,
                    double *out_value, double *out_err) {
    double value = x, scale = 0.0, rho2 = 0.0, trunc = 0.0;
    int index = -1;
    for (int s = 0; s < MAX_STEPS; s++) {
        if (!step(offset, d0, e0, n, q, x, work, work + n, work + 2 * n, &value, &scale, &rho2, &trunc, &index))
            return 0;
        double big = fabs(x) > 1.0 ? fabs(x) : 1.0;
        if (!(rho2 <= RHO_MAX * RHO_MAX * big * big)) return 0;
        if (rho2 <= 0.01 * EPS * (fabs(value) > 1.0 ? fabs(value) : 1.0)) break;
        x = value;
    }
    double err = 8.0 * LDBL_EPSILON * scale + 0.5 * EPS * fabs(value) + trunc + rho2;
    double mag = fabs(value) > 1.0 ? fabs(value) : 1.0;
    if (!(isfinite(value) && isfinite(err) && index == k && trunc <= 1e-3 * EPS * mag)) return 0;
    *out_value = value;
    *out_err = err;
    return err <= tol * mag ? 1 : 2;
}

/* Number of eigenvalues below x (negative pivots of the LDL^T factorisation of T - x I). */
static int sturm_count(int offset, double d0, double e0, int n, double q, double x) {
    double b0 = e0 * e0, bq = q * q, tj = d0 - x;
    int count = 0;
    for (int j = 0; j < n; j++) {
        if (j) {
            double sq = (double)(2 * j + offset) * (double)(2 * j + offset);
            tj = (sq - x) - (j == 1 ? b0 : bq) / tj;
        }
        if (tj == 0.0) tj = -EPS * (fabs(x) + 1.0);
        count += tj < 0.0;
    }
    return count;
}

/* The seed refined, or (when it is rejected: SciPy's value on a wrong branch) a start found by bisection on the
   Sturm count, refined the same way. */
static int refine_point(int offset, int q_sign, int sqrt2, int k, double q, double x, double tol, double *work,
                        double *out_value, double *out_err) {
    *out_value = NAN;
    *out_err = INFINITY;
    int n = batch_size(k, q);
    if (n < 1) return 0;
    double e0 = sqrt2 ? 1.4142135623730951 * q : q;
    double d0 = (double)(offset * offset) + q_sign * q;
    double value, err;
    int status = isfinite(x) ? rq_point(offset, d0, e0, n, k, q, x, tol, work, &value, &err) : 0;
    if (status == 0) {
        double top = (double)(2 * k + offset) * (double)(2 * k + offset);
        double lo = -4.0 * q - 1.0, hi = top + 4.0 * q + 1.0;
        for (int it = 0; it < 200; it++) {
            double mid = 0.5 * (lo + hi);
            double size = fabs(lo) > fabs(hi) ? fabs(lo) : fabs(hi);
            if (hi - lo <= 1e-7 * (size > 1.0 ? size : 1.0) || mid <= lo || mid >= hi) break;
            if (sturm_count(offset, d0, e0, n, q, mid) > k) hi = mid; else lo = mid;
        }
        status = rq_point(offset, d0, e0, n, k, q, 0.5 * (lo + hi), tol, work, &value, &err);
    }
    if (status != 1) return 0;
    *out_value = value;
    *out_err = err;
    return 1;
}

static double work_size(int k, long npts, const double *q) {
    int nmax = 8;
    for (long i = 0; i < npts; i++) {
        int n = batch_size(k, q[i]);
        if (n > nmax) nmax = n;
    }
    return nmax;
}

int symosc_mathieu_refine(int offset, int q_sign, int sqrt2, int k, long npts, const double *q, const double *x,
                          double tol, double *value, double *err, unsigned char *ok) {
    int nmax = (int)work_size(k, npts, q);
    double *work = malloc(sizeof(double) * 3 * (size_t)nmax);
    if (!work) return -1;
    for (long i = 0; i < npts; i++) ok[i] = (unsigned char)refine_point(offset, q_sign, sqrt2, k, q[i], x[i], tol, work,
                                                                       value + i, err + i);
    free(work);
    return 0;
}

double symosc_mathieu_refine1(int offset, int q_sign, int sqrt2, int k, double q, double x, double tol, double *err) {
    double value;
    int n = batch_size(k, q);
    if (n < 8) n = 8;
    double *work = malloc(sizeof(double) * 3 * (size_t)n);
    if (!work) { *err = INFINITY; return NAN; }
    refine_point(offset, q_sign, sqrt2, k, q, x, tol, work, &value, err);
    free(work);
    return value;
}

/* Log gap estimates of a_n (to b_n below and to b_{n+1} above); see _hill.log_gap_estimates. */
static void log_gaps_a(int n, double q, double *below, double *above) {
    double lq = log(q > 1e-300 ? q : 1e-300);
    *below = n >= 1 ? n * lq - (2 * n - 3) * log(2.0) - 2 * lgamma((double)n) : INFINITY;
    double h = sqrt(q);
    double cap = log(2.0 * n + 1.0);
    *above = cap;
    if (h >= (n + 1.5) / 4) {
        double large = (4 * n + 5) * log(2.0) + 0.5 * log(2.0 / 3.141592653589793)
                       + (n + 1.5) * log(h > 1e-300 ? h : 1e-300) - 4 * h - lgamma(n + 1.0);
        if (large < cap) *above = large;
    }
}

/* Gaps of kind_n (is_b) to its chain neighbours, and the seed rule for b_n: -1 seed from a_{n-1}, +1 from a_n,
   0 its own seed (a_n always uses its own).  A neighbour is used as the seed when the gap estimate is below
   1e-6 (n^2 + 2q + 1), looser than the ordering clamp's 1e-7 max(1, |value|). */
static int gaps_point(int is_b, int n, double q, double *lo, double *hi) {
    double b0, a0, b1, a1;
    if (!is_b) {
        log_gaps_a(n, q, lo, hi);
        return 0;
    }
    log_gaps_a(n - 1, q, &b0, &a0);
    log_gaps_a(n, q, &b1, &a1);
    *lo = a0;
    *hi = b1;
    double thr = log(1e-6 * ((double)n * n + 2.0 * q + 1.0));
    if (a0 < thr && a0 <= b1) return -1;
    if (b1 < thr) return 1;
    return 0;
}

void symosc_mathieu_gaps(int is_b, int n, long npts, const double *q, double *lo, double *hi, signed char *rule) {
    for (long i = 0; i < npts; i++) rule[i] = (signed char)gaps_point(is_b, n, q[i], lo + i, hi + i);
}

int symosc_mathieu_gaps1(int is_b, int n, double q, double *out) {
    return gaps_point(is_b, n, q, out, out + 1);
}
"""

_PTR = ctypes.POINTER(ctypes.c_double)
_state: dict = {}


def kernel():
    """The loaded C library, or None (no C compiler, or ``SYMOSC_MATHIEU_KERNEL=numpy``); decided once."""
    try:
        return _state["lib"]
    except KeyError:
        pass
    lib = None
    if os.environ.get("SYMOSC_MATHIEU_KERNEL", "").lower() != "numpy":
        from ..numeric._build import CompilerError, load

        try:
            lib = load(SOURCE)
        except CompilerError:
            lib = None
    if lib is not None:
        lib.symosc_mathieu_refine.restype = ctypes.c_int
        lib.symosc_mathieu_refine.argtypes = [ctypes.c_int] * 4 + [ctypes.c_long] + [ctypes.c_void_p] * 2 + [
            ctypes.c_double
        ] + [ctypes.c_void_p] * 3
        lib.symosc_mathieu_refine1.restype = ctypes.c_double
        lib.symosc_mathieu_refine1.argtypes = [ctypes.c_int] * 4 + [ctypes.c_double] * 3 + [_PTR]
        lib.symosc_mathieu_gaps.restype = None
        lib.symosc_mathieu_gaps.argtypes = [ctypes.c_int, ctypes.c_int, ctypes.c_long] + [ctypes.c_void_p] * 4
        lib.symosc_mathieu_gaps1.restype = ctypes.c_int
        lib.symosc_mathieu_gaps1.argtypes = [ctypes.c_int, ctypes.c_int, ctypes.c_double, _PTR]
    _state["lib"] = lib
    return lib


def reset() -> None:
    """Forget the decision of :func:`kernel` (the tests switch between the C and NumPy kernels)."""
    _state.clear()


def refine(lib, fam, k: int, q: np.ndarray, x: np.ndarray, tol: float):
    """(values, errors, accepted) for contiguous float64 arrays q, x."""
    q = np.ascontiguousarray(q, dtype=float)
    x = np.ascontiguousarray(x, dtype=float)
    value = np.empty(q.shape)
    err = np.empty(q.shape)
    ok = np.empty(q.shape, dtype=np.uint8)
    status = lib.symosc_mathieu_refine(
        fam.offset, fam.q_sign, int(fam.sqrt2), k, q.size, q.ctypes.data, x.ctypes.data, tol,
        value.ctypes.data, err.ctypes.data, ok.ctypes.data,
    )  # fmt: skip
    if status:
        raise MemoryError("the Mathieu kernel could not allocate its work array")
    return value, err, ok.view(bool)


def refine1(lib, fam, k: int, q: float, x: float, tol: float) -> tuple[float, float, bool]:
    err = ctypes.c_double()
    value = lib.symosc_mathieu_refine1(fam.offset, fam.q_sign, fam.sqrt2, k, q, x, tol, err)
    return value, err.value, value == value


def gaps(lib, is_b: bool, n: int, q: np.ndarray):
    """(log gap below, log gap above, seed rule) for a 1-d float64 array q >= 0."""
    q = np.ascontiguousarray(q, dtype=float)
    lo = np.empty(q.shape)
    hi = np.empty(q.shape)
    rule = np.empty(q.shape, dtype=np.int8)
    lib.symosc_mathieu_gaps(int(is_b), n, q.size, q.ctypes.data, lo.ctypes.data, hi.ctypes.data, rule.ctypes.data)
    return lo, hi, rule


def gaps1(lib, is_b: bool, n: int, q: float) -> tuple[float, float, int]:
    out = (ctypes.c_double * 2)()
    rule = lib.symosc_mathieu_gaps1(is_b, n, q, ctypes.cast(out, _PTR))
    return out[0], out[1], rule
