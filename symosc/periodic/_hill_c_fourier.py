"""C source of the Fourier-coefficient kernel of the periodic Mathieu functions (private).

Appended to :data:`symosc.periodic._hill_c_source.SOURCE` (it uses its pivots, Sturm count and matrix sizes).  Per
point (q >= 0 and the certified characteristic value lambda of one Hill family, DLMF 28.4):

* the eigenvector by the twisted factorisation of ``T - lambda I`` (Parlett & Dhillon 1997): twist ``m`` at the
  smallest ``|gamma_j|``, ``z_m = 1`` and products of pivot ratios away from it; normalised to unit length in the
  symmetric form (``sqrt(2) A_0`` for ce_{2m}), first component positive (DLMF 28.2(vi): continuity from q = 0);
* then its Rayleigh quotient ``lambda_1`` in extended precision and the vector again at ``lambda_1``, in extended
  precision (one step of inverse iteration from a shift far closer than the double ``lambda``: the error of a vector
  computed at a shift is about the shift's error over the gap);
* a sound bound on the error of that vector: its residual ``r = (T - lambda_1 I) z`` with the truncated row,
  evaluated in extended precision (plus a bound on that evaluation's rounding), and the Davis-Kahan sin(theta)
  theorem ``|z - v| <= sqrt(2) |r| / g`` where ``g`` is a gap certified by two Sturm counts: exactly one eigenvalue
  (the k-th) lies in ``(lambda - g, lambda + g)`` (a first estimate of the spacing, divided by four until the counts
  confirm it), less ``|lambda_1 - lambda|``; plus the rounding of the vector to double;
* the matrix size doubled until the last four components times their Fourier index are below the tail tolerance.

A second function sums the Fourier series (or its x-derivative) at one x per point in extended precision, the
cosines and sines of ``(2j + p) x`` by rotation from ``cos 2x, sin 2x`` (themselves from ``cos x, sin x``; error
below ``8j + 3`` units of the extended rounding: the argument ``(2j + p) x`` itself is never rounded), so that the
only double rounding of the sum is the final one.
"""

FOURIER_SOURCE = r"""
/* ---- Fourier coefficients of ce_n, se_n (eigenvectors of the Hill matrices) ---- */

/* ||(T - mu I) v|| for a unit vector v (extended precision; the truncated row n included), plus a bound on the
   rounding of that evaluation; *dot = v . (T - mu I) v */
static double residual(int offset, double d0, long double el0, long double ql, int n, long double mu,
                       const long double *v, long double *dot) {
    long double r2 = 0.0L, vr = 0.0L, r;
    if (n == 1) {
        r = ((long double)d0 - mu) * v[0];
        r2 = r * r;
        vr = v[0] * r;
    } else {
        r = ((long double)d0 - mu) * v[0] + el0 * v[1];
        r2 = r * r;
        vr = v[0] * r;
        r = ((long double)diag(1, offset) - mu) * v[1] + el0 * v[0] + (n > 2 ? ql * v[2] : 0.0L);
        r2 += r * r;
        vr += v[1] * r;
        for (int j = 2; j < n - 1; j++) {
            r = ((long double)diag(j, offset) - mu) * v[j] + ql * (v[j - 1] + v[j + 1]);
            r2 += r * r;
            vr += v[j] * r;
        }
        if (n > 2) {
            r = ((long double)diag(n - 1, offset) - mu) * v[n - 1] + ql * v[n - 2];
            r2 += r * r;
            vr += v[n - 1] * r;
        }
    }
    long double extra = ql * v[n - 1];
    r2 += extra * extra;
    *dot = vr;
    /* |evaluation error of r_j| <= 4 eps_ld s_j, s_j = |d_j - mu| |v_j| + e (|v_{j-1}| + |v_{j+1}|) (in double) */
    double s2 = 0.0, e = (double)(el0 > ql ? el0 : ql), m = (double)mu;
    for (int j = 0; j < n; j++) {
        double vj = (double)v[j], dj = j == 0 ? d0 : diag(j, offset);
        double sj = fabs(dj - m) * fabs(vj) + e * ((j ? fabs((double)v[j - 1]) : 0.0) +
                                                   (j < n - 1 ? fabs((double)v[j + 1]) : 0.0));
        s2 += sj * sj;
    }
    return (double)sqrtl(r2) * (1.0 + 4.0 * EPS) + 8.0 * LDBL_EPSILON * sqrt(s2) * (1.0 + 1e-6);
}

/* 1 when the k-th eigenvalue is the only one in (x - g, x + g): Sturm counts at both ends, interleaved */
static int isolated(int offset, double d0, double e0, int n, double q, int k, double x, double g) {
    double b0 = e0 * e0, bq = q * q, lo = x - g, hi = x + g, tl = d0 - lo, th = d0 - hi;
    int cl = 0, ch = 0;
    for (int j = 0; j < n; j++) {
        if (j) {
            double dj = diag(j, offset), b = j == 1 ? b0 : bq;
            tl = (dj - lo) - b / tl;
            th = (dj - hi) - b / th;
        }
        if (tl == 0.0) tl = -EPS * (fabs(lo) + 1.0);
        if (th == 0.0) th = -EPS * (fabs(hi) + 1.0);
        cl += tl < 0.0;
        ch += th < 0.0;
    }
    return cl == k && ch == k + 1;
}

/* the unit eigenvector of the size-n matrix at lam (first component > 0) into z; its 2-norm error bound; the tail
   measure max |z_j| max(1, 2j + offset) over the last four rows.  Returns 1, or 0 (a pivot vanished, no gap).
   The twisted vector at lam in double; its residual at lam (extended precision) over a Sturm-certified gap bounds
   its error (Davis-Kahan).  Where that bound, times the 2-norm of the weights of the requested sum (1, or the
   Fourier indices for derivatives), is above tol / 5 (at large q: the error of a vector computed at a shift is about
   the shift's error over the gap), the Rayleigh quotient lam1 = lam + z . (T - lam) z in extended precision and the
   vector again at lam1 in extended precision from the same twist, with its residual at lam1. */
static int eigvec_point(int offset, int q_sign, int sqrt2, int k, int n, double q, double lam, double gap_est,
                        double tol, int deriv, double *work, double *z, double *bound, double *tail) {
    double e0 = sqrt2 ? 1.4142135623730951 * q : q;
    double d0 = (double)(offset * offset) + q_sign * q;
    double x = lam;
    if (!pivots(offset, d0, e0, n, q, x, work)) {
        x = lam + 4.0 * EPS * (fabs(lam) + 1.0);  /* an exact zero pivot: a neighbouring shift */
        if (!pivots(offset, d0, e0, n, q, x, work)) return 0;
    }
    double *t = work, *rt = work + n, *ru = work + 2 * n, *bqj = work + 3 * n;
    int m = n - 1;
    double gm = fabs(t[n - 1]);
    for (int j = n - 2; j >= 0; j--) {
        double g = fabs(t[j] - bqj[j]);
        if (g <= gm) { m = j; gm = g; }
    }
    z[m] = 1.0;
    for (int j = m - 1; j >= 0; j--) z[j] = (-(j == 0 ? e0 : q) * rt[j]) * z[j + 1];
    for (int j = m + 1; j < n; j++) z[j] = (-(j == 1 ? e0 : q) * ru[j]) * z[j - 1];
    double norm2 = 0.0;
    for (int j = 0; j < n; j++) norm2 += z[j] * z[j];
    double scale = 1.0 / sqrt(norm2);
    if (z[0] < 0.0) scale = -scale;
    for (int j = 0; j < n; j++) z[j] *= scale;
    /* a gap certified by Sturm counts: the k-th eigenvalue is the only one within g of lam */
    double g = gap_est;
    int it = 0;
    while (!isolated(offset, d0, e0, n, q, k, lam, g)) {
        if (++it == 8) return 0;
        g *= 0.25;
    }
    long double ql = q, el0 = sqrt2 ? sqrtl(2.0L) * ql : ql, dot;
    long double *zl = (long double *)(work + 4 * n);  /* 2 n doubles hold n long doubles on every platform */
    long double *rl = (long double *)(work);          /* the double pivots are no longer needed */
    for (int j = 0; j < n; j++) zl[j] = z[j];
    /* the norm of the double vector is 1 within n eps: a factor (1 + n eps) covers it */
    double b = 1.4142135623730951 * residual(offset, d0, el0, ql, n, (long double)lam, zl, &dot) / g *
               (1.0 + (n + 8) * EPS);
    double w = 0.0;
    for (int j = 0; j < n; j++) {
        double kj = (double)(2 * j + offset);
        w += deriv && kj > 1.0 ? kj * kj : 1.0;
    }
    if (b * sqrt(w) > 0.2 * tol) {
        long double n2 = 0.0L;
        for (int j = 0; j < n; j++) n2 += zl[j] * zl[j];
        long double lam1 = (long double)lam + dot / n2;
        double g1 = g - (double)fabsl(lam1 - (long double)lam);  /* lam1 to the rest of the spectrum */
        if (!(g1 > 0.0)) return 0;
        /* the vector at lam1, one division per row: rho_j = z_j / z_{j+1} = -e_j / t_j, then
           t_{j+1} = (d_{j+1} - lam1) + e_j rho_j (and the same from below) */
        long double tp = (long double)d0 - lam1;
        for (int j = 0; j < m; j++) {
            if (tp == 0.0L) return 0;
            long double ej = j == 0 ? el0 : ql;
            rl[j] = -ej / tp;
            tp = ((long double)diag(j + 1, offset) - lam1) + ej * rl[j];
        }
        zl[m] = 1.0L;
        for (int j = m - 1; j >= 0; j--) zl[j] = rl[j] * zl[j + 1];
        long double up = (n - 1 == 0 ? (long double)d0 : (long double)diag(n - 1, offset)) - lam1;
        for (int j = n - 1; j > m; j--) {
            if (up == 0.0L) return 0;
            long double ej = j == 1 ? el0 : ql;  /* couples rows j - 1 and j */
            rl[j] = -ej / up;                     /* z_j / z_{j-1} */
            up = (j - 1 == 0 ? (long double)d0 : (long double)diag(j - 1, offset)) - lam1 + ej * rl[j];
        }
        for (int j = m + 1; j < n; j++) zl[j] = rl[j] * zl[j - 1];
        n2 = 0.0L;
        for (int j = 0; j < n; j++) n2 += zl[j] * zl[j];
        long double sc = 1.0L / sqrtl(n2);
        if (zl[0] < 0.0L) sc = -sc;
        for (int j = 0; j < n; j++) zl[j] *= sc;
        /* Davis-Kahan at lam1 for the extended vector, plus its rounding to double (2-norm <= eps / 2) */
        b = 1.4142135623730951 * residual(offset, d0, el0, ql, n, lam1, zl, &dot) / g1 * (1.0 + 8.0 * EPS) +
            0.5 * EPS;
        for (int j = 0; j < n; j++) z[j] = (double)zl[j];
    }
    double tlmax = 0.0;
    for (int j = n - 4 > 0 ? n - 4 : 0; j < n; j++) {
        double idx = (double)(2 * j + offset), a = fabs(z[j]) * (idx > 1.0 ? idx : 1.0);
        if (a > tlmax) tlmax = a;
    }
    *bound = b;
    *tail = tlmax;
    return 1;
}

/* Coefficients for npts points q >= 0 with values lam: coef (npts x max_rows, row j = A_{2j+offset} or B_..., A_0
   not symmetrised; zero beyond rows[i]), bound (2-norm error of the symmetric unit vector), err0 / err1 (bounds for
   the function and its derivative valid for every x, the rounding of symosc_mathieu_fourier_sum included), status
   (1 ok, 0 failure, 3 the last rows above tol / 1000 at max_rows).  gap_est: a first guess of the distance to the
   neighbouring eigenvalues of the family; deriv: bit 0, the accuracy is needed for derivatives too; bit 1, keep the
   negligible last rows (the Bessel-product series of the modified functions of the second kind multiply them by
   large Bessel functions); s0, s1: sum |A_j|, sum (2j + offset) |A_j|. */
int symosc_mathieu_coefficients(int offset, int q_sign, int sqrt2, int k, long npts, const double *q, const double *lam,
                                const double *gap_est, double tol, int deriv, int max_rows, double *coef, int *rows,
                                double *bound, double *err0, double *err1, double *s0, double *s1,
                                unsigned char *status) {
    double *work = malloc(sizeof(double) * 7 * (size_t)max_rows);
    if (!work) return -1;
    double *z = work + 6 * max_rows;
    double tail_tol = 1e-3 * tol, eps_sum = LDBL_EPSILON;
    for (long i = 0; i < npts; i++) {
        double *c = coef + i * (long)max_rows;
        rows[i] = 0;
        bound[i] = err0[i] = err1[i] = INFINITY;
        s0[i] = s1[i] = 0.0;
        status[i] = 0;
        int fs = first_size(k, q[i]);
        double tail = INFINITY;
        if (fs < 1) continue;
        int n = fs + 6 + fs / 4;
        if (n > max_rows) n = max_rows;
        for (int attempt = 0; attempt < 4; attempt++) {
            double b, tl;
            if (!eigvec_point(offset, q_sign, sqrt2, k, n, q[i], lam[i], gap_est[i], tol, deriv, work, z, &b, &tl))
                break;
            bound[i] = b;
            tail = tl;
            rows[i] = n;
            if (tl <= tail_tol) {
                status[i] = 1;
                break;
            }
            status[i] = 3;
            if (n == max_rows) break;
            n = n + n / 2 < max_rows ? n + n / 2 : max_rows;
        }
        if (status[i] == 0) continue;
        /* rows whose coefficients are negligible (|z_j| max(1, index) below tol / 1e6) are dropped; their total
           goes into the tail */
        int r = rows[i];
        while (r > 1) {
            double idx = (double)(2 * (r - 1) + offset), a = fabs(z[r - 1]) * (idx > 1.0 ? idx : 1.0);
            if (a > 1e-3 * tail_tol || (deriv & 2)) break;
            tail += a;
            r--;
        }
        rows[i] = r;
        for (int j = 0; j < r; j++) c[j] = z[j];
        if (sqrt2) c[0] = z[0] / 1.4142135623730951;
        for (int j = r; j < max_rows; j++) c[j] = 0.0;
        /* error bounds: the coefficients' 2-norm error times the 2-norm of the basis functions' maxima (1, 1/sqrt(2)
           for A_0 of ce_2m, the Fourier index for derivatives), the neglected tail, and the rounding of the
           extended-precision sum (8j + rows + 12 units per term: rotation, summation, products) and of its result */
        double b = bound[i], w0 = 0.0, w1 = 0.0, r0 = 0.0, r1 = 0.0;
        for (int j = 0; j < r; j++) {
            double kj = (double)(2 * j + offset), a = fabs(c[j]), units = eps_sum * (8.0 * j + r + 12.0) + 0.5 * EPS;
            w0 += (j == 0 && sqrt2) ? 0.5 : 1.0;
            w1 += kj * kj;
            r0 += a * units;
            r1 += a * kj * units;
            s0[i] += a;
            s1[i] += a * kj;
        }
        double beyond = 2.0 * (tail + b), kmax = 2.0 * r + offset;
        err0[i] = (b * sqrt(w0) + beyond + r0) * (1.0 + 1e-6);
        err1[i] = (b * sqrt(w1) + beyond * kmax + r1) * (1.0 + 1e-6);
    }
    free(work);
    return 0;
}

/* The Fourier sum at one x per point: point i uses the coefficient row col[i] of coef (ncoef x max_rows, rows[]).
   sine: 0 for a cosine series (ce), 1 for a sine series (se); deriv: the x-derivative. */
void symosc_mathieu_fourier_sum(int offset, int sine, int deriv, long npts, const long *col, const double *x,
                                const double *coef, int max_rows, const int *rows, double *out) {
    for (long i = 0; i < npts; i++) {
        const double *c = coef + col[i] * (long)max_rows;
        int nr = rows[col[i]];
        long double xi = x[i], c1 = cosl(xi), s1 = sinl(xi);
        long double c2 = (c1 - s1) * (c1 + s1), s2 = 2.0L * s1 * c1;
        long double ck, sk;
        if (offset == 0) { ck = 1.0L; sk = 0.0L; }
        else if (offset == 1) { ck = c1; sk = s1; }
        else { ck = c2; sk = s2; }
        long double sum = 0.0L;
        for (int j = 0; j < nr; j++) {
            long double a = c[j];
            if (deriv) a *= (long double)(2 * j + offset);
            if (!deriv) sum += sine ? a * sk : a * ck;
            else sum += sine ? a * ck : -a * sk;
            long double cn = ck * c2 - sk * s2;
            sk = sk * c2 + ck * s2;
            ck = cn;
        }
        out[i] = (double)sum;
    }
}

/* the unit roundoff of the sums above (long double, where it is wider than double) */
double symosc_mathieu_sum_eps(void) { return LDBL_EPSILON; }
/* ---- Hill determinants of the characteristic exponent (DLMF 28.2(iv); Whittaker & Watson 1927, 19.42) ----
   sin^2(pi nu / 2) = -(pi^2 / 4) t_0 prod_{j>=1} t_j / (2j)^2 (family ae) prod_{j>=0} t_j / (2j + 2)^2 (be),
   cos^2(pi nu / 2) = prod_{j>=0} t_j / (2j + 1)^2 (ao) prod_{j>=0} t_j / (2j + 1)^2 (bo), t_j the LDL^T pivots of
   T - a I of each family.  The pivots are run exactly up to N (where c_j = q^2 / ((m_j^2 - a)(m_{j-1}^2 - a)) <=
   1e-6 and a / m_j^2 <= 1/16), the product kept as a long double mantissa and a binary exponent; beyond N
   log(t_j / m_j^2) = log(1 - a / m_j^2) + log(1 - c_j / p_{j-1}) with p the normalised pivots: the first summed as
   -sum_p (a/4)^p / p zeta(2p, N + off/2) (Hurwitz zeta by Euler-Maclaurin), the second as -(c + c c_- + c^2 / 2)
   (neglected: O(c^3)) by Euler-Maclaurin with a Gauss-Legendre integral in u = N / x. */
#define GL_N 20
static const double GL_X[GL_N] = {
    -0.993128599185095, -0.9639719272779138, -0.912234428251326, -0.8391169718222188, -0.7463319064601508,
    -0.636053680726515, -0.5108670019508271, -0.37370608871541955, -0.22778585114164507, -0.07652652113349734,
    0.07652652113349734, 0.22778585114164507, 0.37370608871541955, 0.5108670019508271, 0.636053680726515,
    0.7463319064601508, 0.8391169718222188, 0.912234428251326, 0.9639719272779138, 0.993128599185095};
static const double GL_W[GL_N] = {
    0.017614007139150893, 0.040601429800386446, 0.06267204833410879, 0.08327674157670471, 0.1019301198172407,
    0.1181945319615186, 0.1316886384491769, 0.1420961093183824, 0.14917298647260424, 0.15275338713072628,
    0.15275338713072628, 0.14917298647260424, 0.1420961093183824, 0.1316886384491769, 0.1181945319615186,
    0.1019301198172407, 0.08327674157670471, 0.06267204833410879, 0.040601429800386446, 0.017614007139150893};

/* Hurwitz zeta(s, x), s >= 2, x >= 10, by Euler-Maclaurin (B_2k / (2k)! up to k = 8); xs = x^-s */
static long double hurwitz(int s, long double x, long double xs) {
    static const long double B[8] = {1.0L / 12, -1.0L / 720, 1.0L / 30240, -1.0L / 1209600, 1.0L / 47900160,
                                     -691.0L / 1307674368000.0L, 1.0L / 74724249600.0L,
                                     -3617.0L / 10670622842880000.0L};
    long double sum = x * xs / (s - 1) + 0.5L * xs;
    long double term = xs / x, poch = s;  /* poch = s (s+1) ... (s + 2k - 2) */
    for (int k = 0; k < 8; k++) {
        long double add = B[k] * poch * term;
        sum += add;
        if (fabsl(add) < 1e-21L * sum) break;
        poch *= (long double)(s + 2 * k + 1) * (s + 2 * k + 2);
        term /= x * x;
    }
    return sum;
}

static long double c_tail(double a, double q2, int off, long double x) {
    long double m1 = 2.0L * x + off, m0 = m1 - 2.0L;
    return q2 / ((m1 * m1 - a) * (m0 * m0 - a));
}

static int hill_rows(double a, double q) { return (int)ceil(16.0 * sqrt(q) + 4.0 * sqrt(fabs(a))) + 100; }

/* log of prod_{j >= n} t_j / m_j^2 of one family (m_j = 2j + offset): log(1 - a / m_j^2) by the zeta series, the
   log of the normalised pivots by Euler-Maclaurin */
static long double hill_tail(int offset, double a, double q, int n) {
    long double al = a, x0 = n + 0.5L * offset, sum = 0.0L, zp = 1.0L, a4 = al / 4.0L, xs = 1.0L;
    long double ix2 = 1.0L / (x0 * x0);
    for (int p = 1; p < 60; p++) {
        zp *= a4;
        xs *= ix2;
        long double add = zp / p * hurwitz(2 * p, x0, xs);
        sum -= add;
        if (fabsl(add) < 1e-21L * (fabsl(sum) + 1e-300L)) break;
    }
    /* the normalised pivots' logs are of the size of c <= 1e-6: double precision is enough for them */
    double q2 = q * q, integral = 0.0;
    for (int i = 0; i < GL_N; i++) {
        double u = 0.5 * (GL_X[i] + 1.0), x = n / u;  /* u in (0, 1) */
        double c = (double)c_tail(a, q2, offset, x), cm = (double)c_tail(a, q2, offset, x - 1.0);
        integral += 0.5 * GL_W[i] * (c + c * cm + 0.5 * c * c) * n / (u * u);
    }
    double cn = (double)c_tail(a, q2, offset, n), mn1 = 2.0 * n + offset, mn0 = mn1 - 2.0;
    double dcn = -cn * (4.0 * mn1 / (mn1 * mn1 - a) + 4.0 * mn0 / (mn0 * mn0 - a));
    /* sum_{j >= n} g(j) = integral + g(n) / 2 - g'(n) / 12 + g3(n) / 720, g3 (third derivative) ~ -120 g / n^3 */
    return sum - (integral + 0.5 * cn - dcn / 12.0 - cn / (6.0 * (double)n * n * n));
}

/* prod_{j>=0} t_j / m_j^2 (t_0 itself for m_0 = 0) of the four families (ae, be, ao, bo), as mantissa 2^exponent
   exp(tail); neg = the negative pivots.  The four chains of divisions run in one loop (the processor overlaps
   them). */
static void hill_products(double a, double q, long double *mant, int *ex, long double *tail, int *neg) {
    static const int off[4] = {0, 2, 1, 1}, sgn[4] = {0, 0, 1, -1};
    int n = hill_rows(a, q);
    long double ql = q, al = a, bq = ql * ql, b0[4] = {2.0L * bq, bq, bq, bq}, t[4], m[4] = {1, 1, 1, 1};
    int e[4] = {0, 0, 0, 0}, count[4] = {0, 0, 0, 0};
    long double tiny = -LDBL_EPSILON * (fabsl(al) + 4.0L * ql + 1.0L);
    for (int f = 0; f < 4; f++) t[f] = (long double)(off[f] * off[f]) + sgn[f] * ql - al;
    for (int j = 0; j < n; j++) {
        for (int f = 0; f < 4; f++) {
            long double mj = 2.0L * j + off[f], tf = t[f];
            if (j) tf = (mj * mj - al) - (j == 1 ? b0[f] : bq) / tf;
            if (tf == 0.0L) tf = tiny;
            count[f] += tf < 0.0L;
            m[f] *= mj > 0.0L ? tf / (mj * mj) : tf;
            t[f] = tf;
            if (!(fabsl(m[f]) < 0x1p64L && fabsl(m[f]) > 0x1p-64L)) {
                int de;
                m[f] = frexpl(m[f], &de);
                e[f] += de;
            }
        }
    }
    for (int f = 0; f < 4; f++) {
        mant[f] = m[f];
        ex[f] = e[f];
        neg[f] = count[f];
        tail[f] = hill_tail(off[f], a, q, n);
    }
}

/* S = sin^2(pi nu / 2), C = cos^2(pi nu / 2) (as double, and the logs of |S|, |C|), the number of characteristic
   values below a, and an error estimate (rounding, and |S + C - 1|), for q >= 0 */
void symosc_mathieu_hill_sc(long npts, const double *a, const double *q, double *S, double *C, double *logS,
                            double *logC, int *count, double *err) {
    const long double pi = 3.14159265358979323846264338327950288L, ln2 = 0.69314718055994530941723212145817657L;
    for (long i = 0; i < npts; i++) {
        long double mant[4], tail[4];
        int ex[4], neg[4], cnt = 0, n = hill_rows(a[i], q[i]);
        hill_products(a[i], q[i], mant, ex, tail, neg);
        for (int f = 0; f < 4; f++) cnt += neg[f];
        long double ms = -pi * pi / 4.0L * mant[0] * mant[1], mc = mant[2] * mant[3];
        long double ls = logl(fabsl(ms)) + (ex[0] + ex[1]) * ln2 + tail[0] + tail[1];
        long double lc = logl(fabsl(mc)) + (ex[2] + ex[3]) * ln2 + tail[2] + tail[3];
        long double sv = (ms < 0 ? -1.0L : 1.0L) * expl(ls), cv = (mc < 0 ? -1.0L : 1.0L) * expl(lc);
        S[i] = (double)sv;
        C[i] = (double)cv;
        logS[i] = (double)ls;
        logC[i] = (double)lc;
        count[i] = cnt;
        err[i] = (double)(16.0L * n * LDBL_EPSILON * (fabsl(sv) + fabsl(cv)) + fabsl(sv + cv - 1.0L)) + 1e-17;
    }
}
"""
