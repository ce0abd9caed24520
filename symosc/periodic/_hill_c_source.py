"""C source of the Mathieu kernel loaded by :mod:`symosc.periodic._hill_c` (private).

Operations per point as in :mod:`symosc.periodic._hill_batch` (twisted factorisation of the Hill matrix, Rayleigh
quotient steps, index by the pivot signs, truncation and rounding bounds), plus bisection on the Sturm count when
the seed is on a wrong branch, the gap estimates and the seed rule of :mod:`symosc.periodic._mathieu_auto`, and the
whole common case of method "auto" (own value, nearly degenerate neighbour, ordering clamp).
"""

SOURCE = r"""
#include <float.h>
#include <math.h>
#include <stdlib.h>

#define EPS 2.220446049250313e-16
#define RHO_MAX 1e-3
#define MAX_STEPS 4
/* no further step once rho^2 (which bounds the error of the Rayleigh quotient) is below STOP min(tol, 1e-13) */
#define STOP 1e-3
/* the Rayleigh quotient is summed again in long double when the rounding bound of the double sums is above
   LD_FRACTION tol (so that accepted values keep the last digits too) */
#define LD_FRACTION 0.1
#define MAX_SIZE 65536

/* Matrix sizes: a first try (measured: enough for n <= 100, q <= 1e4 -- the truncation is checked anyway) and a
   larger retry when the truncation estimate of the first is above target; -1 when q is too large. */
static int first_size(int k, double q) {
    double r = ceil(sqrt(q));
    return r < MAX_SIZE ? k + 10 + (int)r : -1;
}

static int retry_size(int k, double q) {
    double r = ceil(1.2 * sqrt(q));
    return r < MAX_SIZE ? k + 20 + (int)r : -1;
}

static inline double diag(int j, int offset) {
    int m = 2 * j + offset;
    return (double)m * (double)m;
}

/* Work layout per point: t, 1/t, 1/u, b_j/u_{j+1} (later overwritten by z), each n doubles. */
#define PIVOT_ROW(T, RT, RU, BQ, X, OK)                                                             \
    {                                                                                               \
        double tj_ = (diag(i, offset) - X) - (i == 1 ? b0 : bq) * RT[i - 1];                        \
        double bb_ = (j == 0 ? b0 : bq) * RU[j + 1];                                                \
        double uj_ = ((j == 0) ? d0 : diag(j, offset)) - X - bb_;                                   \
        if ((tj_ == 0.0 && i < n - 1) || (uj_ == 0.0 && j > 0)) OK = 0;                             \
        T[i] = tj_;                                                                                 \
        RT[i] = 1.0 / tj_;                                                                          \
        RU[j] = 1.0 / uj_;                                                                          \
        BQ[j] = bb_;                                                                                \
    }

/* Forward pivots t_j = (d_j - x) - b_{j-1} / t_{j-1} and backward pivots u_j = (d_j - x) - b_j / u_{j+1}: two
   independent chains of divisions, run in one loop so that the processor overlaps them (each keeps the operations
   of its own loop).  Returns 0 when a pivot that divides vanishes. */
static int pivots(int offset, double d0, double e0, int n, double q, double x, double *w) {
    double *t = w, *rt = w + n, *ru = w + 2 * n, *bq_ = w + 3 * n;
    double b0 = e0 * e0, bq = q * q;
    double t0 = d0 - x, un = diag(n - 1, offset) - x;
    if (t0 == 0.0 || un == 0.0) return 0;
    t[0] = t0;
    rt[0] = 1.0 / t0;
    ru[n - 1] = 1.0 / un;
    int ok = 1;
    for (int i = 1; i < n; i++) {
        int j = n - 1 - i;
        PIVOT_ROW(t, rt, ru, bq_, x, ok)
    }
    return ok;
}

/* pivots() for g <= LANES points with the same matrix size, interleaved (2 g independent chains of divisions);
   each point gets the bits pivots() gives it.  Lane l works in w + 4 n l. */
#define LANES 4
static void pivots_lanes(int offset, int g, const double *d0v, const double *e0v, int n, const double *qv,
                         const double *xv, double *w, int *okv) {
    double b0v[LANES], bqv[LANES];
    for (int l = 0; l < g; l++) {
        double *t = w + 4 * n * l, *rt = t + n, *ru = t + 2 * n;
        b0v[l] = e0v[l] * e0v[l];
        bqv[l] = qv[l] * qv[l];
        double t0 = d0v[l] - xv[l], un = diag(n - 1, offset) - xv[l];
        okv[l] = !(t0 == 0.0 || un == 0.0);
        t[0] = t0;
        rt[0] = 1.0 / t0;
        ru[n - 1] = 1.0 / un;
    }
    for (int i = 1; i < n; i++) {
        int j = n - 1 - i;
        for (int l = 0; l < g; l++) {
            double *t = w + 4 * n * l, *rt = t + n, *ru = t + 2 * n, *bq_ = t + 3 * n;
            double b0 = b0v[l], bq = bqv[l], d0 = d0v[l], x = xv[l];
            int ok = okv[l];
            PIVOT_ROW(t, rt, ru, bq_, x, ok)
            okv[l] = ok;
        }
    }
}

/* The rest of a twisted-factorisation step at x, after pivots(): twist m = argmin |gamma_j|, the index (negative
   pivots other than the twist), eigenvector z with z_m = 1 and its Rayleigh quotient.  The sums are done in double;
   when their rounding bound is above tol they are redone in long double. */
static void finish(int offset, double d0, double e0, int n, double q, double tol, double *work, double *value,
                   double *err, double *rho2, double *trunc, int *index) {
    double *t = work, *rt = work + n, *ru = work + 2 * n, *z = work + 3 * n, *bqj = z;
    int m = n - 1;
    double gm = fabs(t[n - 1]);
    for (int j = n - 2; j >= 0; j--) {
        double g = fabs(t[j] - bqj[j]);
        if (g <= gm) { m = j; gm = g; }  /* the first minimum */
    }
    int idx = 0;
    for (int j = 0; j < m; j++) idx += t[j] < 0.0;
    for (int j = m + 1; j < n; j++) idx += ru[j] < 0.0;
    z[m] = 1.0;
    for (int j = m - 1; j >= 0; j--) z[j] = (-(j == 0 ? e0 : q) * rt[j]) * z[j + 1];
    for (int j = m + 1; j < n; j++) z[j] = (-(j == 1 ? e0 : q) * ru[j]) * z[j - 1];
    double zz = z[0] * z[0];
    double norm2 = zz, dsum = d0 * zz, dabs = fabs(d0) * zz, cross = 0.0, cabs = 0.0;
    if (n > 1) { cross = e0 * (z[0] * z[1]); cabs = fabs(cross); }
    for (int j = 1; j < n; j++) {
        zz = z[j] * z[j];
        norm2 += zz;
        double dz = diag(j, offset) * zz;
        dsum += dz;
        dabs += dz;
        if (j < n - 1) {
            double c = q * (z[j] * z[j + 1]);
            cross += c;
            cabs += fabs(c);
        }
    }
    double v = (dsum + 2.0 * cross) / norm2;
    double scale = (dabs + 2.0 * cabs) / norm2;
    double r2 = (gm * gm) / norm2;
    double w = q * z[n - 1];
    double tr = (w * w) / norm2;
    double mag = fabs(v) > 1.0 ? fabs(v) : 1.0;
    double e = 8.0 * EPS * scale + 0.5 * EPS * fabs(v) + tr + r2;
    if (!(e <= LD_FRACTION * tol * mag) && LDBL_EPSILON < EPS) {
        /* where |value| << 2q the cancellation between the diagonal and off-diagonal sums limits the accuracy */
        long double zl = z[0], zzl = zl * zl;
        long double n2 = zzl, ds = (long double)d0 * zzl, cr = 0.0L;
        if (n > 1) cr = (long double)e0 * (zl * z[1]);
        for (int j = 1; j < n; j++) {
            zl = z[j];
            zzl = zl * zl;
            n2 += zzl;
            ds += (long double)diag(j, offset) * zzl;
            if (j < n - 1) cr += (long double)q * (zl * z[j + 1]);
        }
        v = (double)((ds + 2.0L * cr) / n2);
        e = 8.0 * LDBL_EPSILON * scale + 0.5 * EPS * fabs(v) + tr + r2;
    }
    *value = v;
    *err = e;
    *rho2 = r2;
    *trunc = tr;
    *index = idx;
}

static int step(int offset, double d0, double e0, int n, double q, double x, double tol, double *work,
                double *value, double *err, double *rho2, double *trunc, int *index) {
    if (!pivots(offset, d0, e0, n, q, x, work)) return 0;
    finish(offset, d0, e0, n, q, tol, work, value, err, rho2, trunc, index);
    return 1;
}

/* Rayleigh-quotient steps from x for eigenvalue k (0-based) of one Hill family at q >= 0 (the first one is enough
   for a seed accurate to rounding), then the index and error checks.  Returns 1 (accepted), 2 (right eigenvalue but
   error estimate above tol), 3 (truncation above target) or 0 (wrong index, seed too far, vanishing pivot). */
struct first_step {
    int ok;
    double value, err, rho2, trunc;
    int index;
};

static int rq_point(int offset, double d0, double e0, int n, int k, double q, double x, double tol, double *work,
                    const struct first_step *first, double *out_value, double *out_err) {
    double value = x, err = INFINITY, rho2 = 0.0, trunc = 0.0;
    int index = -1;
    for (int s = 0; s < MAX_STEPS; s++) {
        if (s == 0 && first) {  /* the first step, already done by the caller */
            if (!first->ok) return 0;
            value = first->value, err = first->err, rho2 = first->rho2, trunc = first->trunc, index = first->index;
        } else if (!step(offset, d0, e0, n, q, x, tol, work, &value, &err, &rho2, &trunc, &index)) {
            return 0;
        }
        double big = fabs(x) > 1.0 ? fabs(x) : 1.0;
        if (!(rho2 <= RHO_MAX * RHO_MAX * big * big)) return 0;
        if (rho2 <= STOP * (tol < 1e-13 ? tol : 1e-13) * (fabs(value) > 1.0 ? fabs(value) : 1.0)) break;
        x = value;
    }
    double mag = fabs(value) > 1.0 ? fabs(value) : 1.0;
    if (!(isfinite(value) && isfinite(err) && index == k)) return 0;
    if (!(trunc <= 1e-3 * EPS * mag)) return 3;
    *out_value = value;
    *out_err = err;
    return err <= tol * mag ? 1 : 2;
}

/* rq_point at the first matrix size, and at the retry size when the truncation estimate asks for it. */
static int rq_sizes(int offset, double d0, double e0, int k, double q, double x, double tol, double *work,
                    const struct first_step *first, double *out_value, double *out_err) {
    int status = rq_point(offset, d0, e0, first_size(k, q), k, q, x, tol, work, first, out_value, out_err);
    if (status == 3)
        status = rq_point(offset, d0, e0, retry_size(k, q), k, q, x, tol, work, NULL, out_value, out_err);
    return status;
}

/* Number of eigenvalues below x (negative pivots of the LDL^T factorisation of T - x I). */
static int sturm_count(int offset, double d0, double e0, int n, double q, double x) {
    double b0 = e0 * e0, bq = q * q, tj = d0 - x;
    int count = 0;
    for (int j = 0; j < n; j++) {
        if (j) tj = (diag(j, offset) - x) - (j == 1 ? b0 : bq) / tj;
        if (tj == 0.0) tj = -EPS * (fabs(x) + 1.0);
        count += tj < 0.0;
    }
    return count;
}

/* The seed refined, or (when it is rejected: SciPy's value on a wrong branch) a start found by bisection on the
   Sturm count, refined the same way. */
static int refine_point(int offset, int q_sign, int sqrt2, int k, double q, double x, double tol, double *work,
                        const struct first_step *first, double *out_value, double *out_err) {
    *out_value = NAN;
    *out_err = INFINITY;
    if (first_size(k, q) < 1 || retry_size(k, q) < 1) return 0;
    double e0 = sqrt2 ? 1.4142135623730951 * q : q;
    double d0 = (double)(offset * offset) + q_sign * q;
    double value, err;
    int status = isfinite(x) ? rq_sizes(offset, d0, e0, k, q, x, tol, work, first, &value, &err) : 0;
    if (status == 0) {
        int n = retry_size(k, q);
        double top = diag(k, offset);
        double lo = -4.0 * q - 1.0, hi = top + 4.0 * q + 1.0;
        for (int it = 0; it < 200; it++) {
            double mid = 0.5 * (lo + hi);
            double size = fabs(lo) > fabs(hi) ? fabs(lo) : fabs(hi);
            if (hi - lo <= 1e-7 * (size > 1.0 ? size : 1.0) || mid <= lo || mid >= hi) break;
            if (sturm_count(offset, d0, e0, n, q, mid) > k) hi = mid; else lo = mid;
        }
        status = rq_sizes(offset, d0, e0, k, q, 0.5 * (lo + hi), tol, work, NULL, &value, &err);
    }
    if (status != 1) return 0;
    *out_value = value;
    *out_err = err;
    return 1;
}

static int work_size(int k, long npts, const double *q) {
    int nmax = 8;
    for (long i = 0; i < npts; i++) {
        int n = retry_size(k, q[i]);
        if (n > nmax) nmax = n;
    }
    return nmax;
}

/* After pivots() of the first matrix size: the first step of rq_point(), and whether it is accepted as it stands
   (then refine_point() returns exactly this value and error; else refine_point() continues from it). */
static int accept_first(int offset, double d0, double e0, int n, int k, double q, double x, double tol, double *work,
                        struct first_step *f, double *out_value, double *out_err) {
    f->ok = 1;
    finish(offset, d0, e0, n, q, tol, work, &f->value, &f->err, &f->rho2, &f->trunc, &f->index);
    double big = fabs(x) > 1.0 ? fabs(x) : 1.0;
    double mag = fabs(f->value) > 1.0 ? fabs(f->value) : 1.0;
    if (!(f->rho2 <= RHO_MAX * RHO_MAX * big * big) || !(f->rho2 <= STOP * (tol < 1e-13 ? tol : 1e-13) * mag))
        return 0;
    if (!(isfinite(f->value) && isfinite(f->err) && f->index == k && f->trunc <= 1e-3 * EPS * mag &&
          f->err <= tol * mag))
        return 0;
    *out_value = f->value;
    *out_err = f->err;
    return 1;
}

/* refine_point() for a batch (work: 8 * work_size doubles). */
static void refine_core(int offset, int q_sign, int sqrt2, int k, long npts, const double *q, const double *x,
                        double tol, double *value, double *err, unsigned char *ok, double *work) {
    long i = 0;
    while (i < npts) {
        /* up to LANES neighbouring points with the same matrix size: their pivots interleaved and the first step
           done here; refine_point() goes on from it where it is not accepted as it stands (the same operations
           either way) */
        int n = first_size(k, q[i]);
        int g = 0;
        while (g < LANES && i + g < npts && n > 1 && first_size(k, q[i + g]) == n && retry_size(k, q[i + g]) > 0 &&
               isfinite(x[i + g]))
            g++;
        if (g >= 2) {
            double d0v[LANES], e0v[LANES];
            int okv[LANES];
            struct first_step fv[LANES];
            for (int l = 0; l < g; l++) {
                double ql = q[i + l];
                e0v[l] = sqrt2 ? 1.4142135623730951 * ql : ql;
                d0v[l] = (double)(offset * offset) + q_sign * ql;
                fv[l].ok = 0;
            }
            pivots_lanes(offset, g, d0v, e0v, n, q + i, x + i, work, okv);
            for (int l = 0; l < g; l++)
                okv[l] = okv[l] && accept_first(offset, d0v[l], e0v[l], n, k, q[i + l], x[i + l], tol,
                                                work + 4 * n * l, &fv[l], value + i + l, err + i + l);
            for (int l = 0; l < g; l++)
                ok[i + l] = okv[l] ? 1
                                   : (unsigned char)refine_point(offset, q_sign, sqrt2, k, q[i + l], x[i + l], tol,
                                                                 work, &fv[l], value + i + l, err + i + l);
            i += g;
            continue;
        }
        ok[i] = (unsigned char)refine_point(offset, q_sign, sqrt2, k, q[i], x[i], tol, work, NULL, value + i,
                                            err + i);
        i++;
    }
}

int symosc_mathieu_refine(int offset, int q_sign, int sqrt2, int k, long npts, const double *q, const double *x,
                          double tol, double *value, double *err, unsigned char *ok) {
    int nmax = work_size(k, npts, q);
    double *work = malloc(sizeof(double) * 4 * LANES * (size_t)nmax);
    if (!work) return -1;
    refine_core(offset, q_sign, sqrt2, k, npts, q, x, tol, value, err, ok, work);
    free(work);
    return 0;
}

double symosc_mathieu_refine1(int offset, int q_sign, int sqrt2, int k, double q, double x, double tol, double *err) {
    double value, stack[4 * 256];
    int n = work_size(k, 1, &q);
    double *work = n <= 256 ? stack : malloc(sizeof(double) * 4 * (size_t)n);
    if (!work) { *err = INFINITY; return NAN; }
    refine_point(offset, q_sign, sqrt2, k, q, x, tol, work, NULL, &value, err);
    if (work != stack) free(work);
    return value;
}

/* Log gap estimates of a_n (to b_n below and to b_{n+1} above); see _hill.log_gap_estimates.  The constants that
   depend on n only are computed once per call. */
struct gap_consts {
    int n;
    double small_c, large_c, cap;
};

static void gap_consts_init(int n, struct gap_consts *c) {
    c->n = n;
    c->small_c = n >= 1 ? -(2 * n - 3) * log(2.0) - 2 * lgamma((double)n) : 0.0;
    c->large_c = (4 * n + 5) * log(2.0) + 0.5 * log(2.0 / 3.141592653589793) - lgamma(n + 1.0);
    c->cap = log(2.0 * n + 1.0);
}

static void log_gaps_a(const struct gap_consts *c, double q, double lq, double h, double *below, double *above) {
    int n = c->n;
    *below = n >= 1 ? n * lq + c->small_c : INFINITY;
    *above = c->cap;
    if (h >= (n + 1.5) / 4) {
        double large = c->large_c + (n + 1.5) * (0.5 * lq) - 4 * h;
        if (large < c->cap) *above = large;
    }
}

/* Gaps of kind_n (is_b) to its chain neighbours, and the seed rule for b_n: -1 seed from a_{n-1}, +1 from a_n,
   0 its own seed (a_n always uses its own).  A neighbour is used as the seed when the gap estimate is below
   1e-6 (n^2 + 2q + 1) (one extra Rayleigh step costs less than a SciPy call). */
static int gaps_point(int is_b, const struct gap_consts *c0, const struct gap_consts *c1, double q, double *lo,
                      double *hi) {
    double lq = log(q > 1e-300 ? q : 1e-300), h = sqrt(q), b0, a0, b1, a1;
    if (!is_b) {
        log_gaps_a(c1, q, lq, h, lo, hi);
        return 0;
    }
    int n = c1->n;
    log_gaps_a(c0, q, lq, h, &b0, &a0);
    log_gaps_a(c1, q, lq, h, &b1, &a1);
    *lo = a0;
    *hi = b1;
    double thr = log(1e-6 * ((double)n * n + 2.0 * q + 1.0));
    if (a0 < thr && a0 <= b1) return -1;
    if (b1 < thr) return 1;
    return 0;
}

void symosc_mathieu_gaps(int is_b, int n, long npts, const double *q, double *lo, double *hi, signed char *rule) {
    struct gap_consts c0, c1;
    gap_consts_init(n > 0 ? n - 1 : 0, &c0);
    gap_consts_init(n, &c1);
    for (long i = 0; i < npts; i++) rule[i] = (signed char)gaps_point(is_b, &c0, &c1, q[i], lo + i, hi + i);
}

int symosc_mathieu_gaps1(int is_b, int n, double q, double *out) {
    struct gap_consts c0, c1;
    gap_consts_init(n > 0 ? n - 1 : 0, &c0);
    gap_consts_init(n, &c1);
    return gaps_point(is_b, &c0, &c1, q, out, out + 1);
}

/* ---- the whole "auto" method for the common case: kind_n from its seed, the nearly degenerate neighbour from it,
   the ordering clamp.  status 1: done; 0: this point needs the general (Python) path. ---- */
struct family { int offset, q_sign, sqrt2, k; };

static struct family family_of(int is_b, int n) {
    struct family f;
    if (!is_b) {
        if (n % 2 == 0) { f.offset = 0; f.q_sign = 0; f.sqrt2 = 1; f.k = n / 2; }
        else { f.offset = 1; f.q_sign = 1; f.sqrt2 = 0; f.k = (n - 1) / 2; }
    } else {
        if (n % 2 == 1) { f.offset = 1; f.q_sign = -1; f.sqrt2 = 0; f.k = (n - 1) / 2; }
        else { f.offset = 2; f.q_sign = 0; f.sqrt2 = 0; f.k = n / 2 - 1; }
    }
    return f;
}

/* refine_core() for the points idx[0..m-1] of q with seeds x (gathered; results scattered back to value/err/ok). */
static void refine_gather(struct family f, long m, const long *idx, const double *q, const double *x, double tol,
                          double *value, double *err, unsigned char *ok, double *buf, double *work) {
    double *qg = buf, *xg = buf + m, *vg = buf + 2 * m, *eg = buf + 3 * m;
    unsigned char *og = (unsigned char *)(buf + 4 * m);
    for (long i = 0; i < m; i++) { qg[i] = q[idx[i]]; xg[i] = x[idx[i]]; }
    refine_core(f.offset, f.q_sign, f.sqrt2, f.k, m, qg, xg, tol, vg, eg, og, work);
    for (long i = 0; i < m; i++) { value[idx[i]] = vg[i]; err[idx[i]] = eg[i]; ok[idx[i]] = og[i]; }
}

/* seed: SciPy's a_n for kind a; for kind b, SciPy's value of the seed's source by the rule of gaps_point (b_n for
   rule 0, a_{n-1} for -1, a_n for +1).  Raw values are refined in batches (two points interleaved); a point whose
   raw value or needed neighbour is not covered here gets ok = 0 and goes the general way. */
int symosc_mathieu_auto(int is_b, int n, long npts, const double *q, const double *seed, double tol, double *value,
                        double *err, unsigned char *ok) {
    struct gap_consts c0, c1, c2;
    gap_consts_init(n > 0 ? n - 1 : 0, &c0);
    gap_consts_init(n, &c1);
    gap_consts_init(n + 1, &c2);
    int nmax = 8;
    for (long i = 0; i < npts; i++) {
        int m = retry_size(n / 2 + 1, q[i]);
        if (m > nmax) nmax = m;
    }
    size_t np = (size_t)(npts > 0 ? npts : 1);
    double *work = malloc(sizeof(double) * 4 * LANES * (size_t)nmax);
    double *buf = malloc(sizeof(double) * 5 * np);
    double *raw = malloc(sizeof(double) * 5 * np);  /* own raw, partner raw, lo gap, hi gap, clamped */
    long *idx = malloc(sizeof(long) * np);
    unsigned char *flags = malloc(3 * np);
    if (!work || !buf || !raw || !idx || !flags) {
        free(work); free(buf); free(raw); free(idx); free(flags);
        return -1;
    }
    double *partner = raw + np, *lo = raw + 2 * np, *hi = raw + 3 * np, *clamped = raw + 4 * np;
    unsigned char *pok = flags, *rule_c = flags + np, *need = flags + 2 * np;
    long m;
    for (long i = 0; i < npts; i++) ok[i] = 0;
    if (!is_b) {
        m = 0;
        for (long i = 0; i < npts; i++) if (q[i] != 0.0) idx[m++] = i;
        refine_gather(family_of(0, n), m, idx, q, seed, tol, raw, err, ok, buf, work);
        for (long i = 0; i < npts; i++) clamped[i] = raw[i];
        /* neighbours: b_n (below) and b_{n+1} (above) where the gap estimate asks for the clamp, seeded from a_n */
        for (int side = 0; side < 2; side++) {
            m = 0;
            for (long i = 0; i < npts; i++) {
                need[i] = 0;
                if (!ok[i]) continue;
                double l, h, l2, h2, v = raw[i];
                gaps_point(0, &c0, &c1, q[i], &l, &h);
                double thr = log(1e-7 * (fabs(v) > 1.0 ? fabs(v) : 1.0));
                if (side == 0 && n >= 1 && l < thr) {
                    if (gaps_point(1, &c0, &c1, q[i], &l2, &h2) != 1) { ok[i] = 0; continue; }
                    need[i] = 1;
                    idx[m++] = i;
                }
                if (side == 1 && h < thr) {
                    if (gaps_point(1, &c1, &c2, q[i], &l2, &h2) != -1) { ok[i] = 0; continue; }
                    need[i] = 1;
                    idx[m++] = i;
                }
            }
            if (!m) continue;
            /* seeded from the raw a_n */
            refine_gather(family_of(1, side == 0 ? n : n + 1), m, idx, q, raw, tol, partner, lo, pok, buf, work);
            for (long j = 0; j < m; j++) {
                long i = idx[j];
                if (!pok[i]) { ok[i] = 0; continue; }
                if (side == 0 ? partner[i] > clamped[i] : partner[i] < clamped[i]) clamped[i] = partner[i];
            }
        }
        for (long i = 0; i < npts; i++) value[i] = ok[i] ? clamped[i] : NAN;
    } else {
        /* the seed rule, then the partner a (rule -1: a_{n-1}, +1: a_n) from its SciPy seed */
        for (long i = 0; i < npts; i++) {
            rule_c[i] = (unsigned char)(gaps_point(1, &c0, &c1, q[i], lo + i, hi + i) + 1);
            partner[i] = NAN;
            raw[i] = seed[i];
        }
        for (int r = 0; r <= 2; r += 2) {
            m = 0;
            for (long i = 0; i < npts; i++) if (q[i] != 0.0 && rule_c[i] == r) idx[m++] = i;
            if (!m) continue;
            refine_gather(family_of(0, r == 0 ? n - 1 : n), m, idx, q, seed, tol, partner, err, pok, buf, work);
            for (long j = 0; j < m; j++) {
                long i = idx[j];
                if (pok[i]) raw[i] = partner[i]; else raw[i] = NAN;  /* NAN: not refined below */
            }
        }
        m = 0;
        for (long i = 0; i < npts; i++) if (q[i] != 0.0 && raw[i] == raw[i]) idx[m++] = i;
        for (long j = 0; j < m; j++) value[idx[j]] = raw[idx[j]];
        refine_gather(family_of(1, n), m, idx, q, value, tol, raw, err, ok, buf, work);
        for (long j = 0; j < m; j++) {
            long i = idx[j];
            if (!ok[i]) continue;
            double v = raw[i], c = v;
            double thr = log(1e-7 * (fabs(v) > 1.0 ? fabs(v) : 1.0));
            int rule = (int)rule_c[i] - 1;
            if (lo[i] < thr) {
                if (rule != -1) { ok[i] = 0; continue; }
                if (partner[i] > c) c = partner[i];
            }
            if (hi[i] < thr) {
                if (rule != 1) { ok[i] = 0; continue; }
                if (partner[i] < c) c = partner[i];
            }
            raw[i] = c;
        }
        for (long i = 0; i < npts; i++) value[i] = ok[i] ? raw[i] : NAN;
    }
    free(work); free(buf); free(raw); free(idx); free(flags);
    return 0;
}

double symosc_mathieu_auto1(int is_b, int n, double q, double seed, double tol, double *err) {
    double value;
    unsigned char ok;
    if (symosc_mathieu_auto(is_b, n, 1, &q, &seed, tol, &value, err, &ok) || !ok) return NAN;
    return value;
}
"""
