"""C source of the Mathieu kernel loaded by :mod:`symosc.periodic._hill_c` (private).

Operations per point as in :mod:`symosc.periodic._hill_batch` (twisted factorisation of the Hill matrix, Rayleigh
quotient steps, index by the pivot signs, truncation and rounding bounds), plus bisection on the Sturm count when
the seed is rejected, the initial approximations of :mod:`symosc.periodic._mathieu_seed` (piecewise Chebyshev
series in sqrt(q), the asymptotic expansion DLMF 28.8.1 beyond), and the whole common case of method "auto" (own
value, the nearly degenerate neighbours, the ordering clamp).
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

/* Matrix sizes: a first try and a larger retry when the truncation estimate of the first is above target; -1 when
   q is too large.  The first: k + 9 + sqrt(q) rows at moderate q, k + 11 + (5.4 + 0.95 sqrt(k)) q^(1/4) at large q
   (the Fourier coefficients then decay like a Hermite function of width ~q^(1/4); measured: enough for n <= 200 and
   q <= 4e6, with one or two rows to spare -- the truncation is checked anyway). */
static int first_size(int k, double q) {
    double h = sqrt(q), r = (5.4 + 0.95 * sqrt((double)k)) * sqrt(h) + 2.0;
    r = ceil(r < h ? r : h);
    return r < MAX_SIZE ? k + 9 + (int)r : -1;
}

/* below this q both sizes are defined (ceil(1.2 sqrt(q)) < MAX_SIZE) */
#define Q_LANES 2.9e9

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
                         const double *xv, double *restrict w, int *okv) {
    /* the state of each lane in local arrays (no aliasing with w), the previous reciprocals kept in registers */
    double b0v[LANES], bqv[LANES], dl[LANES], xl[LANES], prt[LANES], pru[LANES];
    int okl[LANES];
    for (int l = 0; l < g; l++) {
        double *t = w + 4 * n * l, *rt = t + n, *ru = t + 2 * n;
        b0v[l] = e0v[l] * e0v[l];
        bqv[l] = qv[l] * qv[l];
        dl[l] = d0v[l];
        xl[l] = xv[l];
        double t0 = d0v[l] - xv[l], un = diag(n - 1, offset) - xv[l];
        okl[l] = !(t0 == 0.0 || un == 0.0);
        t[0] = t0;
        rt[0] = prt[l] = 1.0 / t0;
        ru[n - 1] = pru[l] = 1.0 / un;
    }
#define LANE_ROW(l)                                                                                 \
    {                                                                                               \
        double *t = w + 4 * n * (l), *rt = t + n, *ru = t + 2 * n, *bq_ = t + 3 * n;                 \
        double tj_ = (di - xl[l]) - (i == 1 ? b0v[l] : bqv[l]) * prt[l];                            \
        double bb_ = (j == 0 ? b0v[l] : bqv[l]) * pru[l];                                           \
        double uj_ = ((j == 0) ? dl[l] : dj) - xl[l] - bb_;                                         \
        if ((tj_ == 0.0 && i < n - 1) || (uj_ == 0.0 && j > 0)) okl[l] = 0;                          \
        t[i] = tj_;                                                                                 \
        rt[i] = prt[l] = 1.0 / tj_;                                                                 \
        ru[j] = pru[l] = 1.0 / uj_;                                                                 \
        bq_[j] = bb_;                                                                               \
    }
    for (int i = 1; i < n; i++) {
        int j = n - 1 - i;
        double di = diag(i, offset), dj = diag(j, offset);
        if (g == LANES) {
            for (int l = 0; l < LANES; l++) LANE_ROW(l)
        } else {
            for (int l = 0; l < g; l++) LANE_ROW(l)
        }
    }
#undef LANE_ROW
    for (int l = 0; l < g; l++) okv[l] = okl[l];
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
    double norm2 = zz, dsum = d0 * zz, cross = 0.0;
    if (n > 1) cross = e0 * (z[0] * z[1]);
    for (int j = 1; j < n; j++) {
        zz = z[j] * z[j];
        norm2 += zz;
        dsum += diag(j, offset) * zz;
        if (j < n - 1) cross += q * (z[j] * z[j + 1]);
    }
    double v = (dsum + 2.0 * cross) / norm2;
    /* the scale of the sums' rounding: sum |d_j| z_j^2 (only d_0 can be negative) + 2 sum |e_j z_j z_{j+1}|, the
       latter at most max(e) ||z||^2 (Cauchy-Schwarz) */
    double emax = e0 > q ? e0 : q;
    double scale = (dsum + (fabs(d0) - d0) * (z[0] * z[0])) / norm2 + 2.0 * emax;
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
        if (!(trunc <= 1e-3 * EPS * big)) return 3;  /* the matrix is too small (the residual says nothing) */
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

/* The seed refined, or (when it is rejected: a start on a wrong branch) a start found by bisection on the
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
        int g = 1;
        if (!(n > 1 && q[i] < Q_LANES && isfinite(x[i]))) g = 0;
        while (g && g < LANES && i + g < npts && q[i + g] < Q_LANES && isfinite(x[i + g]) &&
               first_size(k, q[i + g]) == n)
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

/* ---- initial approximations (seeds): piecewise Chebyshev series in h = sqrt(q), the asymptotic expansion beyond ----
   Table layout (doubles): [0] number of pieces P, [1] h_max, [2] s = 2m + 1 of the expansion, [3 .. 3 + P] the
   breakpoints in h, then P blocks of SEED_DEG + 1 Chebyshev coefficients of a + 2 h^2 on each piece. */
#define SEED_DEG 16

/* DLMF 28.8.1: a_m(h^2) ~ b_{m+1}(h^2) ~ -2 h^2 + 2 s h - (s^2 + 1) / 8 - ..., s = 2m + 1, terms up to h^-5 */
static double seed_asymptotic(double s, double h) {
    double s2 = s * s, r = 1.0 / h;
    double c3 = s * (s2 + 3.0) / 128.0;
    double c4 = (s2 * (5.0 * s2 + 34.0) + 9.0) / 4096.0;
    double c5 = s * (s2 * (33.0 * s2 + 410.0) + 405.0) / 131072.0;
    double c6 = (s2 * (s2 * (63.0 * s2 + 1260.0) + 2943.0) + 486.0) / 1048576.0;
    double c7 = s * (s2 * (s2 * (527.0 * s2 + 15617.0) + 69001.0) + 41607.0) / 33554432.0;
    double tail = r * (c3 + r * (c4 + r * (c5 + r * (c6 + r * c7))));
    return (-2.0 * h + 2.0 * s) * h - (s2 + 1.0) / 8.0 - tail;
}

static double seed_value(const double *tab, double q) {
    double h = sqrt(q);
    int np = (int)tab[0];
    if (!(h < tab[1])) return seed_asymptotic(tab[2], h);
    const double *br = tab + 3;
    int lo = 0, hi = np;
    while (hi - lo > 1) {
        int mid = (lo + hi) >> 1;
        if (h >= br[mid]) lo = mid; else hi = mid;
    }
    const double *c = tab + 4 + np + lo * (SEED_DEG + 1);
    double t = (2.0 * h - (br[lo] + br[lo + 1])) / (br[lo + 1] - br[lo]);
    double t2 = 2.0 * t, b1 = 0.0, b2 = 0.0;
    for (int j = SEED_DEG; j >= 1; j--) {
        double b0 = (t2 * b1 - b2) + c[j];
        b2 = b1;
        b1 = b0;
    }
    return ((t * b1 - b2) + c[0]) - 2.0 * q;
}

void symosc_mathieu_seeds(const double *tab, long npts, const double *q, double *out) {
    for (long i = 0; i < npts; i++) out[i] = seed_value(tab, q[i]);
}

/* ---- the whole "auto" method: kind_n from its seed, the ordering clamp against the neighbours of the chain
   a_0 <= b_1 <= a_1 <= ... where they are closer than ~1e-12 (n^2 + 2q + 1).  Plan layout (doubles):
   [0] is_b, [1] n, [2] offset of the own seed table, [3] offset of the lower neighbour's table (-1: none),
   [4] offset of the upper neighbour's, [5], [6] the h-interval where the lower neighbour is needed, [7], [8] the same
   for the upper one; the tables follow.  status per point 1: done; 0: the general (Python) path. ---- */
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

/* refine_core() for the points idx[0..m-1] of q, seeds from the table (results scattered to value/err/ok) */
static void refine_gather(struct family f, const double *tab, long m, const long *idx, const double *q, double tol,
                          double *value, double *err, unsigned char *ok, double *buf, double *work) {
    double *qg = buf, *xg = buf + m, *vg = buf + 2 * m, *eg = buf + 3 * m;
    unsigned char *og = (unsigned char *)(buf + 4 * m);
    for (long i = 0; i < m; i++) { qg[i] = q[idx[i]]; xg[i] = seed_value(tab, qg[i]); }
    refine_core(f.offset, f.q_sign, f.sqrt2, f.k, m, qg, xg, tol, vg, eg, og, work);
    for (long i = 0; i < m; i++) { value[idx[i]] = vg[i]; err[idx[i]] = eg[i]; ok[idx[i]] = og[i]; }
}

static int plan_work(const double *plan, long npts, const double *q) {
    int is_b = (int)plan[0], n = (int)plan[1];
    int k = family_of(is_b, n).k + 1, nmax = 8;
    for (long i = 0; i < npts; i++) {
        int m = retry_size(k, q[i]);
        if (m > nmax) nmax = m;
    }
    return nmax;
}

static void auto_core(const double *plan, long npts, const double *q, double tol, double *value, double *err,
                      unsigned char *ok, double *work, double *buf, double *partner, double *perr,
                      unsigned char *pok, long *idx) {
    int is_b = (int)plan[0], n = (int)plan[1];
    struct family own = family_of(is_b, n);
    long m = 0;
    for (long i = 0; i < npts; i++) {
        if (q[i] != 0.0) { idx[m++] = i; continue; }
        double d = (double)(2 * own.k + own.offset);
        value[i] = d * d;  /* q = 0: a_n = b_n = n^2 exactly */
        err[i] = 0.0;
        ok[i] = 1;
    }
    refine_gather(own, plan + (long)plan[2], m, idx, q, tol, value, err, ok, buf, work);
    for (int side = 0; side < 2; side++) {
        double off = plan[3 + side];
        if (off < 0) continue;
        double hlo = plan[5 + 2 * side], hhi = plan[6 + 2 * side];
        struct family f = side == 0 ? (is_b ? family_of(0, n - 1) : family_of(1, n))
                                    : (is_b ? family_of(0, n) : family_of(1, n + 1));
        m = 0;
        for (long i = 0; i < npts; i++) {
            double h = sqrt(q[i]);
            if (ok[i] && q[i] != 0.0 && h >= hlo && h <= hhi) idx[m++] = i;
        }
        if (!m) continue;
        refine_gather(f, plan + (long)off, m, idx, q, tol, partner, perr, pok, buf, work);
        for (long j = 0; j < m; j++) {
            long i = idx[j];
            if (!pok[i]) { ok[i] = 0; continue; }
            if (side == 0 ? partner[i] > value[i] : partner[i] < value[i]) value[i] = partner[i];
        }
    }
    for (long i = 0; i < npts; i++)
        if (!ok[i]) { value[i] = NAN; err[i] = INFINITY; }
}

/* in chunks of CHUNK points, so that the buffers live on the stack (large temporary allocations cost page faults) */
#define CHUNK 512
int symosc_mathieu_auto(const double *plan, long npts, const double *q, double tol, double *value, double *err,
                        unsigned char *ok) {
    double stack[4 * LANES * 128], buf[7 * CHUNK];
    long idx[CHUNK];
    unsigned char pok[CHUNK];
    int nmax = plan_work(plan, npts, q);
    double *work = nmax <= 128 ? stack : malloc(sizeof(double) * 4 * LANES * (size_t)nmax);
    if (!work) return -1;
    for (long start = 0; start < npts; start += CHUNK) {
        long m = npts - start < CHUNK ? npts - start : CHUNK;
        auto_core(plan, m, q + start, tol, value + start, err + start, ok + start, work, buf, buf + 5 * CHUNK,
                  buf + 6 * CHUNK, pok, idx);
    }
    if (work != stack) free(work);
    return 0;
}

/* one point: the same operations as symosc_mathieu_auto(), on the stack where the matrix is small */
double symosc_mathieu_auto1(const double *plan, double q, double tol, double *err) {
    double stack[4 * LANES * 128], buf[7], e;
    long idx[1];
    unsigned char ok[1], pok[1];
    double value;
    int nmax = plan_work(plan, 1, &q);
    double *work = nmax <= 128 ? stack : malloc(sizeof(double) * 4 * LANES * (size_t)nmax);
    if (!err) err = &e;  /* NULL: the caller does not need the error estimate */
    if (!work) { *err = INFINITY; return NAN; }
    auto_core(plan, 1, &q, tol, &value, err, ok, work, buf, buf + 5, buf + 6, pok, idx);
    if (work != stack) free(work);
    return value;
}
"""

#: A CPython extension module around ``symosc_mathieu_auto1`` for the scalar calls of ``mathieu_a/b`` (a ctypes call
#: alone costs ~0.6 us, this one ~0.05 us).  ``{python_h}`` is the running interpreter's header (absolute path, so
#: that the build needs no include flags); the kernel's address is passed in at run time.
EXTENSION = r"""
#define PY_SSIZE_T_CLEAN
#include "{python_h}"
#include <float.h>
#include <math.h>
#include <string.h>

typedef double (*kernel_t)(const double *, double, double, double *);
static kernel_t kernel = 0;
#define NMAX 4096
static const double *plans[2][NMAX];

/* set_kernel(address of symosc_mathieu_auto1): also forgets every registered plan */
static PyObject *set_kernel(PyObject *self, PyObject *arg) {
    kernel = (kernel_t)PyLong_AsVoidPtr(arg);
    if (PyErr_Occurred()) return NULL;
    memset(plans, 0, sizeof(plans));
    Py_RETURN_NONE;
}

/* register(is_b, n, address of the plan): the plan must stay alive (the caller keeps it) */
static PyObject *register_plan(PyObject *self, PyObject *const *args, Py_ssize_t nargs) {
    if (nargs != 3) { PyErr_SetString(PyExc_TypeError, "register(is_b, n, address)"); return NULL; }
    long is_b = PyLong_AsLong(args[0]), n = PyLong_AsLong(args[1]);
    void *plan = PyLong_AsVoidPtr(args[2]);
    if (PyErr_Occurred()) return NULL;
    if (is_b >= 0 && is_b < 2 && n >= 0 && n < NMAX) plans[is_b][n] = (const double *)plan;
    Py_RETURN_NONE;
}

/* value(is_b, n, q) for a Python int n and float q: a_n(q) or b_n(q) (q < 0 by DLMF 28.2(vii)) from the registered
   plan with the default tolerance; nan when there is no plan, q is not finite or the kernel did not accept */
static PyObject *value(PyObject *self, PyObject *const *args, Py_ssize_t nargs) {
    if (nargs != 3) { PyErr_SetString(PyExc_TypeError, "value(is_b, n, q)"); return NULL; }
    long is_b = PyLong_AsLong(args[0]), n = PyLong_AsLong(args[1]);
    double q = PyFloat_AsDouble(args[2]);
    if (PyErr_Occurred()) return NULL;
    if (q < 0.0) {
        q = -q;
        if (n % 2) is_b = 1 - is_b;
    }
    if (!kernel || is_b < 0 || is_b > 1 || n < 0 || n >= NMAX || !plans[is_b][n] || !(q <= DBL_MAX))
        return PyFloat_FromDouble(NAN);
    return PyFloat_FromDouble(kernel(plans[is_b][n], q, 1e-13, NULL));
}

static PyMethodDef methods[] = {
    {"set_kernel", set_kernel, METH_O, NULL},
    {"register", (PyCFunction)(void (*)(void))register_plan, METH_FASTCALL, NULL},
    {"value", (PyCFunction)(void (*)(void))value, METH_FASTCALL, NULL},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_symosc_mathieu", NULL, -1, methods};

PyMODINIT_FUNC PyInit__symosc_mathieu(void) { return PyModule_Create(&module); }
"""
