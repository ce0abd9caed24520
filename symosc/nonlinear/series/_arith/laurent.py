"""Exact Fourier series on FLINT integer polynomials, and relaxed Cauchy products in ``eps``.

A real series ``sum_n a_n cos(n tau) + b_n sin(n tau)`` is stored by its complex exponential coefficients for
``n >= 0``, ``c_n = (u_n + i v_n)/den`` (``a_n = 2 u_n/den``, ``b_n = -2 v_n/den``, ``a_0 = u_0/den``;
``c_(-n) = conj(c_n)``), ``n = off + step*j`` for the ``j``-th coefficient of two ``flint.fmpz_poly`` numerators:
``step = 2`` and ``off`` 0 or 1 when only even or only odd harmonics occur (polynomials in ``z**2``).  Sums and
scalings work on these halves; a product expands both factors to the two-sided Laurent polynomials, multiplies them
once (three times with Karatsuba when both have cosine and sine parts) and keeps the half ``n >= 0``: no folding of
``n - m`` terms.

The Poincaré recurrence needs at every order ``m`` the Cauchy coefficients ``c_m = sum_i a_i b_(m-i)`` of products of
series that are themselves computed order by order (``x**2``, ``x**2 v``, ...).  Pair by pair (the plain method) that
costs ``m`` products of polynomials of length ``~m`` with ``~m**2``-bit coefficients at order ``m``: about
``order**5`` in total.  :class:`RelaxedCauchy` forms the same sums from products of *blocks* of consecutive terms,
each multiplied as soon as its terms are known (relaxed multiplication: van der Hoeven, "Relax, but don't be too
lazy", J. Symbolic Comput. 34 (2002) 479–542): the pairs ``(i, j)``, ``i, j >= 1``, are covered by the squares
``[s 2^k, (s+1) 2^k) x [2^k, 2^(k+1))`` and their mirror images, each one bivariate product (Kronecker substitution
into a single ``fmpz_poly``) formed when its last term becomes known, its results kept for the orders they
contribute to.  The terms ``a_0 b_m + a_m b_0`` of the current order are formed directly (the recurrence still
corrects the newest terms).  Blocks are multiplied as one product only from four terms on; below that the pairs
are cheaper.

What keeps the constant small: in a block product the terms are packed half as far apart as their products are
long, the half ``n < 0`` of each product overlapping the half ``n > 0`` of the one before, and recovered from the
evenness or oddness in ``n`` (:func:`_unfold`); a square block is packed once and squared; a block cut by the
truncation order packs only the terms that reach it; a short factor (``x_1 .. x_3`` against ``x_m``) is multiplied in
pieces small enough for FLINT's coefficient-by-coefficient product (:func:`_mul`); and the pending terms of an order
are summed on increasing denominators, each multiplier the small ratio of two consecutive ones (:meth:`_sum`).
"""

from __future__ import annotations

import math
from collections import defaultdict
from fractions import Fraction
from typing import Any

from .trig import _Arith, _fmpz_poly

#: blocks of fewer terms are multiplied pair by pair (measured: packing pays from 4 terms on)
_BLOCK_MIN = 4


class Half:
    """``c_n = (u_j + i v_j)/den`` for ``n = off + step j >= 0``: the half ``n >= 0`` of a real Fourier series."""

    __slots__ = ("den", "off", "step", "u", "v")

    def __init__(self, u: Any, v: Any, off: int, step: int, den: int):
        self.u, self.v, self.off, self.step, self.den = u, v, off, step, den

    @property
    def hi(self) -> int:
        """The highest harmonic present (0 for the zero series)."""
        d = max(self.u.degree(), self.v.degree())
        return self.off + self.step * d if d >= 0 else 0

    def is_zero(self) -> bool:
        return self.u.is_zero() and self.v.is_zero()


def _lcm(values: list[int]) -> int:
    return math.lcm(*values) if values else 1


class LaurentArith(_Arith):
    """Exact arithmetic on :class:`Half` series (python-flint); :meth:`cauchy` gives relaxed Cauchy products."""

    name = "exact"
    integer_numerators = True

    def __init__(self) -> None:
        self.P = _fmpz_poly()
        if not self.P:  # pragma: no cover - the caller checks
            raise ImportError("python-flint is needed for the relaxed exact series")
        self.zero_poly = self.P(0)

    # --- scalars (Fractions) ---------------------------------------------------------------------------------------
    def scalar(self, q: Fraction | int) -> Fraction:
        return Fraction(q)

    # --- construction and normal form -----------------------------------------------------------------------------
    def new(self, n: int) -> Half:
        return Half(self.zero_poly, self.zero_poly, 0, 2, 1)

    def monomial(self, kind: str, n: int, coeff: Any) -> Half:
        """``coeff * cos(n tau)`` (kind "c") or ``coeff * sin(n tau)`` (kind "s")."""
        q = Fraction(coeff)
        if kind == "s" and n == 0:
            return self.new(0)
        c = [0] * (n // 2) + [q.numerator if kind == "c" else -q.numerator]
        poly = self.P(c)
        den = q.denominator * (1 if n == 0 else 2)  # cos = (e^(in) + e^(-in))/2, sin = (e^(in) - e^(-in))/(2i)
        u, v = (poly, self.zero_poly) if kind == "c" else (self.zero_poly, poly)
        return self._norm(Half(u, v, n % 2, 2, den))

    def _norm(self, t: Half) -> Half:
        """Lowest terms."""
        if t.is_zero():
            return self.new(0)
        g = math.gcd(int(t.u.content()), int(t.v.content()), t.den)
        if g > 1:
            return Half(t.u // g, t.v // g, t.off, t.step, t.den // g)
        return t

    @staticmethod
    def _layout(ts: list[Half]) -> tuple[int, int]:
        """``(off, step)`` that holds every (nonzero) series: ``(off, 2)`` when all have only harmonics of the parity
        ``off``, else ``(0, 1)``."""
        offs = {t.off for t in ts if not t.is_zero()}
        if all(t.step == 2 for t in ts if not t.is_zero()) and len(offs) <= 1:
            return (offs.pop() if offs else 0), 2
        return 0, 1

    @staticmethod
    def _at(t: Half, off: int, step: int) -> tuple[Any, Any]:
        """Numerators of ``t`` in the layout ``(off, step)``."""
        if t.step == step or t.is_zero():
            return t.u, t.v
        return t.u.inflate(2).left_shift(t.off), t.v.inflate(2).left_shift(t.off)

    # --- linear operations -----------------------------------------------------------------------------------------
    def _sum(self, terms: list[tuple[Half, int]]) -> Half:
        """``sum f * t`` over ``(t, f)`` (integer ``f``) on one common denominator, reduced once.

        Terms of one denominator are added first; the groups are then taken by increasing denominator, the running
        sum brought to each next one (Horner's scheme): when the denominators divide one another, as the orders of a
        series do, every multiplier is the small ratio of consecutive denominators instead of the large ratio of
        the common denominator to each term's.
        """
        terms = [(t, f) for t, f in terms if f and not t.is_zero()]
        if not terms:
            return self.new(0)
        if len(terms) == 1 and terms[0][1] == 1:
            return self._norm(terms[0][0])
        off, step = self._layout([t for t, _ in terms])
        groups: dict[int, list[tuple[Half, int]]] = defaultdict(list)
        for t, f in terms:
            groups[t.den].append((t, f))
        u = v = self.zero_poly
        den = 0
        for d in sorted(groups):
            gu, gv = self._group_sum(groups[d], off, step)
            if not den:
                u, v, den = gu, gv, d
                continue
            q, r = divmod(d, den)
            if r:
                g = math.gcd(d, den)
                q, k = d // g, den // g
                gu, gv = gu * k, gv * k
            u, v, den = u * q + gu, v * q + gv, den * q
        return self._norm(Half(u, v, off, step, den))

    def _group_sum(self, terms: list[tuple[Half, int]], off: int, step: int) -> tuple[Any, Any]:
        """Numerators of ``sum f * t`` for terms of one denominator, in the layout ``(off, step)``."""
        u = v = self.zero_poly
        for t, f in terms:
            tu, tv = self._at(t, off, step)
            u += tu * f if f != 1 else tu
            v += tv * f if f != 1 else tv
        return u, v

    def add(self, a: Half, b: Half) -> Half:
        return self._sum([(a, 1), (b, 1)])

    def sub(self, a: Half, b: Half) -> Half:
        return self._sum([(a, 1), (b, -1)])

    def scale(self, a: Half, s: Any) -> Half:
        s = Fraction(s)
        return self._norm(Half(a.u * s.numerator, a.v * s.numerator, a.off, a.step, a.den * s.denominator))

    def scale_int(self, a: Half, k: int) -> Half:
        return self._norm(Half(a.u * k, a.v * k, a.off, a.step, a.den))

    @staticmethod
    def _times_n(p: Any, t: Half) -> Any:
        """Coefficient ``j`` times its harmonic ``n = off + step j``."""
        out = p.derivative().left_shift(1) * t.step
        return out + p * t.off if t.off else out

    def deriv(self, a: Half) -> Half:
        # d/dtau (u + i v) e^{i n tau} = (-n v + i n u) e^{i n tau}
        return Half(-self._times_n(a.v, a), self._times_n(a.u, a), a.off, a.step, a.den)

    def lincomb(self, scalars: list, series: list[Half]) -> Half:
        terms = [(Fraction(c), t) for c, t in zip(scalars, series, strict=True) if c]
        if not terms:
            return self.new(0)
        den = _lcm([c.denominator for c, _ in terms])
        out = self._sum([(t, c.numerator * (den // c.denominator)) for c, t in terms])
        return self._norm(Half(out.u, out.v, out.off, out.step, out.den * den))

    def mul(self, a: Half, b: Half) -> Half:
        return self._norm(pair_product(self, a, b))

    def dot(self, pairs: list[tuple[Half, Half]]) -> Half:
        return self._sum([(pair_product(self, a, b), 1) for a, b in pairs])

    # --- coefficients ----------------------------------------------------------------------------------------------
    def _index(self, t: Half, n: int) -> int | None:
        j, r = divmod(n - t.off, t.step)
        return j if r == 0 and j >= 0 else None

    def coeff(self, t: Half, kind: str, n: int) -> Fraction:
        """``a_n`` (kind "c") or ``b_n`` (kind "s"): ``a_n = 2 Re c_n``, ``b_n = -2 Im c_n`` (``a_0 = c_0``)."""
        j = self._index(t, n)
        if j is None:
            return Fraction(0)
        if kind == "c":
            return Fraction(int(t.u[j]) * (1 if n == 0 else 2), t.den)
        return Fraction(-2 * int(t.v[j]), t.den) if n else Fraction(0)

    def add_coeff(self, t: Half, kind: str, n: int, value: Any) -> Half:
        return self.add(t, self.monomial(kind, n, value))

    def solve_forced(self, r: Half) -> Half:
        """Periodic solution of ``x'' + x = r``: ``c_n / (1 - n**2)``, the ``n = 1`` terms dropped."""
        size = max(r.u.length(), r.v.length())
        divs = [1 - (r.off + r.step * j) ** 2 for j in range(size)]
        lcm = _lcm([abs(d) for d in divs if d])
        mult = [0 if d == 0 else lcm // d for d in divs]
        P = self.P
        u = P([c * f for c, f in zip(r.u.coeffs(), mult, strict=False)])
        v = P([c * f for c, f in zip(r.v.coeffs(), mult, strict=False)])
        return self._norm(Half(u, v, r.off, r.step, r.den * lcm))

    def sine_moment(self, t: Half, start: int = 2) -> Fraction:
        """``sum n b_n`` over ``n >= start`` (``b_n = -2 v_n / den``)."""
        acc = 0
        for j, c in enumerate(t.v.coeffs()):
            n = t.off + t.step * j
            if n >= start and c:
                acc += n * int(c)
        return Fraction(-2 * acc, t.den)

    def exact_harmonics(self, t: Half) -> tuple[int, list[int], list[int]]:
        """``(den, cos numerators, sin numerators)`` for harmonics ``0..hi`` (the form of :class:`Trig`)."""
        hi = t.hi
        cos, sin = [0] * (hi + 1), [0] * (hi + 1)
        for j, c in enumerate(t.u.coeffs()):
            n = t.off + t.step * j
            if c:
                cos[n] = int(c) * (1 if n == 0 else 2)
        for j, c in enumerate(t.v.coeffs()):
            n = t.off + t.step * j
            if n > 0 and c:
                sin[n] = -2 * int(c)
        return int(t.den), cos, sin

    # --- Cauchy products in eps ------------------------------------------------------------------------------------
    def cauchy(self, a: list, b: list, *, shift: int = 0, limit: int, scalar_a: bool = False) -> Any:
        """``m -> sum_(i=0..m) a_(i+shift) b_(m-i+shift)`` by relaxed block products (see :class:`RelaxedCauchy`;
        ``a`` scalars when ``scalar_a``)."""
        return RelaxedCauchy(self, a, b, shift=shift, limit=limit, scalar_a=scalar_a)


def _phases(side: list[Half], first: int) -> set[tuple[int, int]]:
    """The ``(alpha, beta)`` in {0, 1}^2 for which ``i**(alpha + beta k) * side[k - first]`` is a real polynomial
    (cosine part only) for every ``k``: every term a pure cosine series (0, 0) or sine series (1, 0), or the two
    alternating with the index (beta = 1), as the terms of van der Pol's series do."""
    kinds = []
    for k, t in enumerate(side, start=first):
        has_u, has_v = not t.u.is_zero(), not t.v.is_zero()
        if has_u and has_v:
            return set()
        if has_u or has_v:
            kinds.append((k, 1 if has_v else 0))
    return {(a, b) for a in (0, 1) for b in (0, 1) if all((a + b * k) % 2 == kind for k, kind in kinds)}


def _two_sided(pos: Any, neg: Any, off: int, count: int) -> list:
    """Coefficients for ``n = -hi .. hi`` (in steps) of the Laurent polynomial whose coefficients for ``n >= 0``
    are those of ``pos`` (``count`` of them from ``n = off``) and for ``n < 0`` those of ``neg`` at ``-n``."""
    if pos.is_zero():
        return []
    p = pos.coeffs()
    p += [0] * (count - len(p))
    q = neg.coeffs()
    q += [0] * (count - len(q))
    q.reverse()
    return (q[:-1] if off == 0 else q) + p


def _side(t: Half, step: int) -> tuple[Any, Any, int]:
    """Two-sided real and imaginary parts of ``t`` as ``fmpz_poly`` in steps of ``step`` from ``n = -hi``, and
    ``hi``."""
    off, st = (t.off, t.step) if t.step == step else (0, 1)
    u, v = LaurentArith._at(t, off, st)
    hi = t.hi
    count = (hi - off) // step + 1
    P = type(u)
    return P(_two_sided(u, u, off, count)), P(_two_sided(v, -v, off, count)), hi


#: FLINT multiplies coefficient by coefficient only while the shorter polynomial has fewer terms than this; from
#: there on it pads every coefficient to the size of the largest (measured, python-flint 0.9: 8 coefficients of
#: 30 bits times 150 of 16000 bits take 4 ms at once, 0.4 ms in two pieces; x_3 against x_150 is such a product)
_CLASSICAL = 7
#: a shorter factor up to this length is multiplied in pieces of ``_CLASSICAL - 1`` terms
_PIECEWISE_MAX = 16


def _mul(x: Any, y: Any) -> Any:
    """``x * y``; a short factor (``_CLASSICAL <= length <= _PIECEWISE_MAX``) in pieces of ``_CLASSICAL - 1``."""
    if x.length() > y.length():
        x, y = y, x
    if not _CLASSICAL <= x.length() <= _PIECEWISE_MAX:
        return x * y
    P, k = type(x), _CLASSICAL - 1
    c = x.coeffs()
    out = P(c[:k]) * y
    for i in range(k, len(c), k):
        out += (P(c[i : i + k]) * y).left_shift(i)
    return out


def pair_product(ar: LaurentArith, a: Half, b: Half) -> Half:
    """``a b`` (not reduced): :func:`block_products` of one term on each side, without packing or phases."""
    if a.is_zero() or b.is_zero():
        return ar.new(0)
    step = 2 if a.step == b.step == 2 else 1
    au, av, ha = _side(a, step)
    bu, bv, hb = _side(b, step)
    # (au + i av)(bu + i bv) = (au bu - av bv) + i (au bv + av bu); pure cosine or sine series need one product
    if av.is_zero() and bv.is_zero():
        re, im = _mul(au, bu), ar.zero_poly
    elif au.is_zero() and bu.is_zero():
        re, im = -_mul(av, bv), ar.zero_poly
    elif av.is_zero() and bu.is_zero():
        re, im = ar.zero_poly, _mul(au, bv)
    elif au.is_zero() and bv.is_zero():
        re, im = ar.zero_poly, _mul(av, bu)
    else:
        p1, p2, p3 = _mul(au, bu), _mul(av, bv), _mul(au + av, bu + bv)
        re, im = p1 - p2, p3 - p1 - p2
    # the product's harmonics run from -(ha + hb) in steps of ``step``; keep n >= 0
    zero = (ha + hb + step - 1) // step
    off = -(ha + hb) + step * zero
    return Half(re.right_shift(zero), im.right_shift(zero), off, step, a.den * b.den)


def block_products(
    ar: LaurentArith, A: list[Half], B: list[Half], count: int, first: tuple[int, int] = (0, 0)
) -> list[Half]:
    """``C_t = sum_(i+j=t) A_i B_j`` for ``t < count`` (not reduced): one bivariate product by Kronecker substitution.

    ``first`` are the indices (orders) of ``A[0]`` and ``B[0]``.  When the terms of each block are pure cosine or
    sine series in a pattern ``i**(alpha + beta k)`` (the same ``beta`` on both sides), each term is made real by that
    factor and the block product is one product of integer polynomials; otherwise the cosine and sine parts are
    multiplied with Karatsuba's three products (squares when ``A is B``).

    Every ``C_t`` is a two-sided Laurent polynomial of ``L`` coefficients whose real and imaginary parts are even or
    odd in ``n``; its terms are placed only ``ceil(L/2)`` apart, so that the half ``n < 0`` of ``C_(t+1)`` falls on
    the half ``n > 0`` of ``C_t``: the products are half as long, and :func:`_unfold` separates the two halves from
    ``t = 0`` up by that symmetry.
    """
    sides = []
    for side in (A, B):
        off, step = ar._layout(side)
        sides.append([side, off, step, max(t.hi for t in side), _lcm([t.den for t in side])])
    if sides[0][2] != sides[1][2]:  # one side has odd and even harmonics: both in steps of 1
        for q in sides:
            q[1], q[2] = 0, 1
    step = sides[0][2]
    for q in sides:  # the two-sided range -hi..hi must be a whole number of steps from the parity offset
        q[3] += (q[3] - q[1]) % step
    (_, oa, _, ha, da), (_, ob, _, hb, db) = sides
    length = 2 * ha // step + 2 * hb // step + 1  # of each C_t
    stride = length - length // 2
    square = A is B and first[0] == first[1]  # one packed polynomial: FLINT squares it
    pa = _phases(A, first[0])
    pb = pa if square else _phases(B, first[1])
    common = [(x, y) for x in pa for y in pb if x[1] == y[1] and (x == y or not square)]
    phase = common[0] if common else None
    au, av = _pack(ar, A, oa, step, ha, da, stride, first[0], phase[0] if phase else None)
    bu, bv = (au, av) if square else _pack(ar, B, ob, step, hb, db, stride, first[1], phase[1] if phase else None)
    n = count * stride

    def mul(x, y):
        if x.is_zero() or y.is_zero():
            return ar.zero_poly
        return x.mul_low(y, n) if n < x.length() + y.length() - 1 else x * y

    # (au + i av)(bu + i bv) = (au bu - av bv) + i (au bv + av bu)
    if av.is_zero() or bv.is_zero() or au.is_zero() or bu.is_zero():
        re = mul(au, bu) - mul(av, bv)
        im = mul(au, bv) + mul(av, bu)
    else:
        sa = au + av
        p1, p2, p3 = mul(au, bu), mul(av, bv), mul(sa, sa if square else bu + bv)
        re, im = p1 - p2, p3 - p1 - p2
    # the factor i**e_t of the order first + t (phases) makes the real part even for even e_t, odd for odd e_t
    if phase is not None:
        (xa, beta), (xb, _) = phase
        turns = [(xa + xb + beta * (first[0] + first[1] + t)) % 4 for t in range(count)]
    else:
        turns = [0] * count
    res = _unfold(ar.P, re.coeffs(), length, count, [e % 2 == 0 for e in turns])
    ims = _unfold(ar.P, im.coeffs(), length, count, [e % 2 == 1 for e in turns])
    # the product's harmonics run from -(ha + hb) in steps of ``step``; keep n >= 0
    zero = (ha + hb + step - 1) // step
    off = -(ha + hb) + step * zero
    out = []
    for e, u, v in zip(turns, res, ims, strict=True):
        u, v = ((u, v), (v, -u), (-u, -v), (-v, u))[e]  # undo the factor i**e_t
        out.append(Half(u, v, off, step, da * db))  # reduced when summed
    return out


def _pack(
    ar: LaurentArith, side: list[Half], off: int, step: int, hi: int, den: int, stride: int, k0: int, ph: Any
) -> tuple[Any, Any]:
    """Real and imaginary parts of ``sum_r i**e_r side[r] y**r`` on the denominator ``den``, each term two-sided
    (``n = -hi .. hi``), with ``y = z**stride``; overlapping terms add up."""
    n_half = (hi - off) // step + 1
    us: list = []
    vs: list = []
    for r, t in enumerate(side):
        tu, tv = ar._at(t, off, step)
        f = den // t.den
        if f != 1:
            tu, tv = tu * f, tv * f
        # two-sided: the real part is even in n, the imaginary part odd; i**e (u + i v) for the phase e
        e = (ph[0] + ph[1] * (k0 + r)) % 4 if ph is not None else 0
        if e == 0:
            cu, cv = _two_sided(tu, tu, off, n_half), _two_sided(tv, -tv, off, n_half)
        elif e == 1:
            cu, cv = _two_sided(-tv, tv, off, n_half), _two_sided(tu, tu, off, n_half)
        elif e == 2:
            cu, cv = _two_sided(-tu, -tu, off, n_half), _two_sided(-tv, tv, off, n_half)
        else:
            cu, cv = _two_sided(tv, -tv, off, n_half), _two_sided(-tu, -tu, off, n_half)
        for out, c in ((us, cu), (vs, cv)):
            if c:
                _place(out, c, r * stride)
    return ar.P(us), ar.P(vs)


def _place(out: list, c: list, start: int) -> None:
    """Add the coefficients ``c`` into ``out`` from index ``start`` (extending it)."""
    if len(out) <= start:
        out.extend([0] * (start - len(out)))
        out.extend(c)
        return
    overlap = min(len(out) - start, len(c))
    for k in range(overlap):
        out[start + k] += c[k]
    out.extend(c[overlap:])


def _unfold(P: Any, coeffs: list, length: int, count: int, even: list[bool]) -> list:
    """The halves ``n >= 0`` (``fmpz_poly``) of ``count`` Laurent polynomials of ``length`` coefficients each, even
    (``even[t]``) or odd in ``n``, packed ``stride = ceil(length/2)`` apart (the half ``n < 0`` of the ``t+1``-st on
    the half ``n > 0`` of the ``t``-th): term by term, the negative half is what remains after the previous positive
    half is removed, and the positive half is its mirror image (negated when odd; the middle coefficient ``n = 0``
    of an odd one is zero)."""
    if not coeffs:
        return [P(0)] * count
    neg = length // 2  # coefficients for n < 0 (and as many for n > 0; the middle one is n = 0 when length is odd)
    stride = length - neg
    coeffs = coeffs + [0] * (count * stride - len(coeffs))
    out = []
    mirror: list = [0] * neg  # the previous negative half reversed: +- its positive half
    for t in range(count):
        seg = coeffs[t * stride : (t + 1) * stride]
        if t == 0:
            low = seg[:neg]
        elif even[t - 1]:
            low = [a - b for a, b in zip(seg[:neg], mirror, strict=True)]
        else:
            low = [a + b for a, b in zip(seg[:neg], mirror, strict=True)]
        low.reverse()
        mirror = low
        half = P(seg[neg:] + low)
        out.append(half if even[t] else -half)
    return out


def scalar_block_products(ar: LaurentArith, W: list, X: list[Half]) -> list[Half]:
    """``C_t = sum_(i+j=t) W_i X_j`` (``W`` scalars): for every harmonic one product of integer polynomials in the
    order (a Kronecker product over all harmonics would pad each scalar to the size of a series coefficient)."""
    P = ar.P
    dw = _lcm([Fraction(w).denominator for w in W])
    pw = P([Fraction(w).numerator * (dw // Fraction(w).denominator) for w in W])
    off, step = ar._layout(X)
    dx = _lcm([t.den for t in X])
    parts = [ar._at(t, off, step) for t in X]
    size = max(max(u.length(), v.length()) for u, v in parts)
    columns = ([[0] * len(X) for _ in range(size)], [[0] * len(X) for _ in range(size)])
    for j, ((u, v), t) in enumerate(zip(parts, X, strict=True)):
        f = dx // t.den
        for cols, p in zip(columns, (u, v), strict=True):
            if not p.is_zero():
                for h, c in enumerate((p * f).coeffs() if f != 1 else p.coeffs()):
                    cols[h][j] = c
    prods = [[(pw * P(c)).coeffs() if any(c) else [] for c in cols] for cols in columns]
    count = len(W) + len(X) - 1
    return [
        Half(*(P([o[t] if t < len(o) else 0 for o in outs]) for outs in prods), off, step, dw * dx)
        for t in range(count)
    ]


#: blocks of scalars times series: per-harmonic products from this size on, and only untruncated blocks
_SCALAR_BLOCK_MIN = 8


class RelaxedCauchy:
    """``c_m = sum_(i=0..m) a_i b_(m-i)`` for ``m = 0, 1, ...`` (each once, in order) of sequences that grow.

    ``a_i = a[i + shift]`` (a list that the recurrence extends and may still correct at its newest index), likewise
    ``b``; scalars (Fractions) with ``scalar_a``.  At order ``m`` the terms ``a_i, b_i`` with ``i < m`` must be
    final.  The pairs ``(i, m - i)`` with ``1 <= i <= m - 1`` come from block products formed when their blocks are
    complete; ``a_0 b_m + a_m b_0`` is formed directly.  A square (``a is b``) uses each block once.
    """

    def __init__(self, ar: LaurentArith, a: list, b: list, *, shift: int, limit: int, scalar_a: bool = False):
        self.ar, self.a, self.b, self.shift, self.limit = ar, a, b, shift, limit
        self.square = a is b
        self.scalar_a = scalar_a
        self.pending: dict[int, list[tuple[Half, int]]] = defaultdict(list)
        self.next = 0

    def _get(self, seq: list, i: int) -> Half:
        return seq[i + self.shift]

    def _block(self, i0: int, j0: int, size: int, weight: int) -> None:
        """Products of ``a_i`` (``i0 <= i < i0 + size``) with ``b_j`` (``j0 <= j < j0 + size``), kept by order."""
        first = i0 + j0
        count = min(2 * size - 1, self.limit - first + 1)
        if count <= 0:
            return
        used = min(size, count)  # terms beyond the limit's reach are not needed
        A = [self._get(self.a, i) for i in range(i0, i0 + used)]
        B = A if self.square and i0 == j0 else [self._get(self.b, j) for j in range(j0, j0 + used)]
        if self.scalar_a:
            blocked = size >= _SCALAR_BLOCK_MIN and count == 2 * size - 1
        else:
            blocked = used >= _BLOCK_MIN  # small blocks: the products of the pairs cost less than packing them
        if not blocked:
            for i, a in enumerate(A):
                if self.scalar_a and not a:  # (every other frequency coefficient of an odd nonlinearity)
                    continue
                for j, b in enumerate(B[: count - i]):
                    self.pending[first + i + j].append((self._pair(a, b), weight))
            return
        if self.scalar_a:
            blocks = scalar_block_products(self.ar, A, B)
        else:
            blocks = block_products(self.ar, A, B, count, (i0, j0))
        for t, c in enumerate(blocks[:count]):
            self.pending[first + t].append((c, weight))

    def _pair(self, a: Any, b: Half) -> Half:
        if self.scalar_a:
            q = Fraction(a)
            return Half(b.u * q.numerator, b.v * q.numerator, b.off, b.step, b.den * q.denominator)
        return pair_product(self.ar, a, b)

    def __call__(self, m: int) -> Half:
        if m != self.next:
            raise RuntimeError(f"relaxed Cauchy product asked for order {m}, expected {self.next}")
        self.next += 1
        k = 0
        while (1 << k) <= m:  # blocks that become complete now: [s 2^k, (s+1) 2^k) x [2^k, 2^(k+1)), m = (s+1) 2^k
            size = 1 << k
            if m % size:
                break
            s = m // size - 1
            if s >= 1:
                if self.square:
                    self._block(s * size, size, size, 1 if s == 1 else 2)
                else:
                    self._block(s * size, size, size, 1)
                    if s >= 2:
                        self._block(size, s * size, size, 1)
            k += 1
        a0, b0, am, bm = self._get(self.a, 0), self._get(self.b, 0), self._get(self.a, m), self._get(self.b, m)
        edge = self._pair(a0, bm)
        if m == 0:
            terms = [(edge, 1)]
        elif self.square:
            terms = [(edge, 2)]
        else:
            terms = [(edge, 1), (self._pair(am, b0), 1)]
        return self.ar._sum(terms + self.pending.pop(m, []))
