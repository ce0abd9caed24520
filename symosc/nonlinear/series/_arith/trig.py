"""Truncated real Fourier series with exact, fixed-point, float or polynomial-ring coefficients.

A series ``sum_n a_n cos(n tau) + b_n sin(n tau)`` (``n = 0..N``) is stored as two coefficient arrays.  Products
are computed with :func:`numpy.convolve` on the coefficient arrays (the ``n + m`` terms) and on one reversed array
(the ``n - m`` terms), so the inner loops run in C even for Python-object coefficients.  SymPy trigonometric
simplification is never used.

Arithmetic modes (:class:`_Arith` subclasses):

``exact``  numerators are Python ``int`` with one common ``int`` denominator per series (about 50x faster than
           :class:`fractions.Fraction` entries); the products of integer numerators run on FLINT's ``fmpz_poly``
           multiplication when python-flint is installed (``pip install symosc[exact]``), else on
           :func:`numpy.convolve` -- the same integers either way.  A Cauchy sum is accumulated on one common
           denominator and reduced once; series with only odd (or only even) harmonics are multiplied as
           polynomials in ``z**2`` (half the length), and a pair of pure cosine or sine series takes two products
           (the ``n + m`` and ``n - m`` terms) instead of six;
``fixed``  numerators are Python ``int`` with the implicit denominator ``2**prec`` (the mpmath option: binary
           fixed point, converted to ``mpmath.mpf`` on output); a Cauchy sum is formed exactly and rounded once;
``float``  float64 arrays; the Cauchy sums ``sum_i a_i * b_(m-i)`` are formed by direct convolution, on the
           half-length arrays when each factor is a pure cosine or sine series with odd-only or even-only
           harmonics, so every coefficient is a plain sum of products and small high-harmonic coefficients keep
           their relative accuracy (van der Pol: coefficient errors relative to the neighbouring coefficients'
           size ~1e-13 at order 20, ~1e-7 at order 100, ~1e-6 at order 120, growing with the order through the
           recurrence itself); use ``mpmath`` arithmetic for accurate high-order coefficients;
``ring``   elements of a SymPy polynomial ring over QQ (symbolic parameters such as the amplitude ``A``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import mpmath
import numpy as np

from .products import (
    _flint_dot,
    _flint_lincomb,
    _float_direct_dot,
    _int_products_flint,
    _object_array,
)


@dataclass
class Trig:
    """A truncated Fourier series: ``(cos[n] * cos(n tau) + sin[n] * sin(n tau)) / den`` summed over n."""

    cos: np.ndarray
    sin: np.ndarray
    den: int = 1
    #: FLINT forms of the numerators (exact arithmetic only; set on first use, never mutated afterwards)
    polys: Any = field(default=None, repr=False, compare=False)

    @property
    def n(self) -> int:
        return len(self.cos) - 1


_FMPZ_POLY: Any = None


def _fmpz_poly() -> Any:
    """``flint.fmpz_poly`` when python-flint is installed, else False (checked once)."""
    global _FMPZ_POLY
    if _FMPZ_POLY is None:
        try:
            from flint import fmpz_poly
        except ImportError:
            fmpz_poly = False
        _FMPZ_POLY = fmpz_poly
    return _FMPZ_POLY


def _pad(a: np.ndarray, n: int, zero: Any) -> np.ndarray:
    if len(a) >= n:
        return a
    out = np.empty(n, dtype=a.dtype)
    out[: len(a)] = a
    out[len(a) :] = zero
    return out


class _Arith:
    """Coefficient arithmetic shared by the series algorithms (subclasses fix the number type)."""

    dtype: Any = object
    zero: Any = 0
    name = "abstract"
    #: numerators are Python ints (products may use FLINT's integer polynomial multiplication)
    integer_numerators = False

    # --- scalars -------------------------------------------------------------------------------------------
    def scalar(self, q: Fraction | int) -> Any:  # rational -> scalar
        raise NotImplementedError

    # the field operations of Python's number types (Fraction, float); fixed-point and mpmath scalars override them
    def sdiv(self, a: Any, b: Any) -> Any:
        return a / b

    def smul(self, a: Any, b: Any) -> Any:
        return a * b

    def is_zero(self, a: Any) -> bool:
        return a == 0

    def output(self, a: Any) -> Any:  # scalar -> user-facing number (Fraction, mpf, float, PolyElement)
        return a

    # --- series construction ---------------------------------------------------------------------------------
    def new(self, n: int) -> Trig:
        z = np.empty(n + 1, dtype=self.dtype)
        z[:] = self.zero
        s = np.empty(n + 1, dtype=self.dtype)
        s[:] = self.zero
        return Trig(z, s, 1 if self.name != "fixed" else self.one_den)

    def monomial(self, kind: str, n: int, coeff: Any) -> Trig:
        t = self.new(n)
        self._set(t, kind, n, coeff)
        return t

    # --- generic operations on the numerator arrays -------------------------------------------------------
    def _norm(self, t: Trig) -> Trig:
        return t

    def _align(self, a: Trig, b: Trig) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, int]:
        n = max(len(a.cos), len(b.cos))
        return (
            _pad(a.cos, n, self.zero),
            _pad(a.sin, n, self.zero),
            _pad(b.cos, n, self.zero),
            _pad(b.sin, n, self.zero),
            1,
        )

    def add(self, a: Trig, b: Trig) -> Trig:
        ac, as_, bc, bs, _ = self._align(a, b)
        return Trig(ac + bc, as_ + bs, a.den)

    def sub(self, a: Trig, b: Trig) -> Trig:
        ac, as_, bc, bs, _ = self._align(a, b)
        return Trig(ac - bc, as_ - bs, a.den)

    def scale(self, a: Trig, s: Any) -> Trig:
        return Trig(a.cos * s, a.sin * s, a.den)

    def scale_int(self, a: Trig, k: int) -> Trig:
        return Trig(a.cos * k, a.sin * k, a.den)

    def deriv(self, a: Trig) -> Trig:
        k = np.arange(len(a.cos), dtype=object if self.dtype is object else float)
        return Trig(a.sin * k, -(a.cos * k), a.den)

    def _products(self, a: Trig, b: Trig) -> tuple[np.ndarray, np.ndarray]:
        """Twice the numerators of a*b (before dividing by 2 and by the denominators)."""
        ac, as_, bc, bs = a.cos, a.sin, b.cos, b.sin
        na, nb = len(ac) - 1, len(bc) - 1
        n = na + nb
        poly = _fmpz_poly() if self.integer_numerators else False
        if poly:
            lists = _int_products_flint(poly, ac, as_, bc, bs, na, nb)
            out_c, out_s, dc, ds = (_object_array(v) for v in lists)
        else:
            # n + m terms
            cc = np.convolve(ac, bc)
            ss = np.convolve(as_, bs)
            sc = np.convolve(as_, bc)
            cs = np.convolve(ac, bs)
            out_c = cc - ss
            out_s = sc + cs
            # n - m terms: index j + nb holds sum over n - m = j
            dcc = np.convolve(ac, bc[::-1])
            dss = np.convolve(as_, bs[::-1])
            dsc = np.convolve(as_, bc[::-1])
            dcs = np.convolve(ac, bs[::-1])
            dc = dcc + dss  # cos(n - m)
            ds = dsc - dcs  # sin(n - m)
        # fold j >= 0
        out_c[: na + 1] = out_c[: na + 1] + dc[nb:]
        out_s[: na + 1] = out_s[: na + 1] + ds[nb:]
        # fold j < 0: cos even, sin odd; j = -1..-nb at index nb-1..0
        if nb > 0:
            neg_c = dc[:nb][::-1]
            neg_s = ds[:nb][::-1]
            out_c[1 : nb + 1] = out_c[1 : nb + 1] + neg_c
            out_s[1 : nb + 1] = out_s[1 : nb + 1] - neg_s
        out_s[0] = self.zero
        assert len(out_c) == n + 1
        return out_c, out_s

    def mul(self, a: Trig, b: Trig) -> Trig:
        raise NotImplementedError

    def dot(self, pairs: list[tuple[Trig, Trig]]) -> Trig:
        """``sum a * b`` over the pairs (the Cauchy products of the series recurrences)."""
        acc = self.mul(*pairs[0])
        for a, b in pairs[1:]:
            acc = self.add(acc, self.mul(a, b))
        return acc

    def symmetric_dot(self, pairs: list[tuple[Trig, Trig]], middle: tuple[Trig, Trig] | None) -> Trig:
        """``2 * sum a * b`` over ``pairs`` plus ``middle[0] * middle[1]``: a Cauchy square ``sum_i a_i a_(m-i)``
        with the equal pairs ``(i, m - i)``, ``(m - i, i)`` formed once."""
        out = self.scale_int(self.dot(pairs), 2) if pairs else None
        if middle is not None:
            mid = self.mul(*middle)
            out = mid if out is None else self.add(out, mid)
        return out

    def lincomb(self, scalars: list[Any], series: list[Trig]) -> Trig:
        """``sum s * t`` over scalars and series (the Cauchy products with a scalar series)."""
        acc = self.scale(series[0], scalars[0])
        for c, t in zip(scalars[1:], series[1:], strict=True):
            acc = self.add(acc, self.scale(t, c))
        return acc

    def cauchy(self, a: list, b: list, *, shift: int = 0, limit: int, scalar_a: bool = False) -> _DirectCauchy:
        """``m -> sum_(i=0..m) a_(i+shift) b_(m-i+shift)`` for ``m = 0, 1, ...`` (``a``, ``b`` lists that grow;
        ``a`` of scalars when ``scalar_a``): here formed pair by pair at each order."""
        return _DirectCauchy(self, a, b, shift, scalar_a)

    def solve_forced(self, r: Trig) -> Trig:
        """Periodic solution of ``x'' + x = r`` with the n = 1 harmonics of ``r`` ignored (and set to 0)."""
        raise NotImplementedError

    def coeff(self, t: Trig, kind: str, n: int) -> Any:
        raise NotImplementedError

    def _set(self, t: Trig, kind: str, n: int, value: Any) -> None:
        raise NotImplementedError

    def add_coeff(self, t: Trig, kind: str, n: int, value: Any) -> Trig:
        """Return ``t + value * cos(n tau)`` (kind "c") or ``... sin(n tau)`` (kind "s")."""
        return self.add(t, self.monomial(kind, n, value))

    def sine_moment(self, t: Trig, start: int = 2) -> Any:
        """``sum n * b_n`` over the sine coefficients from harmonic ``start`` on (``d/dtau`` of them at 0)."""
        acc = self.scalar(0)
        for n in range(start, len(t.cos)):
            acc = acc + self.smul(self.scalar(n), self.coeff(t, "s", n))
        return acc

    def values(self, t: Trig) -> tuple[list, list]:
        """Coefficient lists (user-facing numbers)."""
        return [self.coeff(t, "c", k) for k in range(len(t.cos))], [self.coeff(t, "s", k) for k in range(len(t.cos))]

    def trim(self, t: Trig) -> Trig:
        """Drop trailing zero harmonics."""
        n = len(t.cos)
        while n > 1 and self.is_zero_num(t.cos[n - 1]) and self.is_zero_num(t.sin[n - 1]):
            n -= 1
        return Trig(t.cos[:n].copy(), t.sin[:n].copy(), t.den)

    def is_zero_num(self, x: Any) -> bool:
        return x == 0


class _DirectCauchy:
    """Cauchy coefficients formed pair by pair (see :meth:`_Arith.cauchy`); a square uses each pair once."""

    def __init__(self, ar: _Arith, a: list, b: list, shift: int, scalar_a: bool):
        self.ar, self.a, self.b, self.shift, self.scalar_a = ar, a, b, shift, scalar_a

    def __call__(self, m: int) -> Trig:
        a, b, sh, ar = self.a, self.b, self.shift, self.ar
        if self.scalar_a:
            return ar.lincomb([a[i + sh] for i in range(m + 1)], [b[m - i + sh] for i in range(m + 1)])
        if a is not b or m == 0:
            return ar.dot([(a[i + sh], b[m - i + sh]) for i in range(m + 1)])
        # a square: the pairs (i, m - i) and (m - i, i) give the same product
        pairs = [(a[i + sh], a[m - i + sh]) for i in range((m + 1) // 2)]
        middle = (a[m // 2 + sh], a[m // 2 + sh]) if m % 2 == 0 else None
        return ar.symmetric_dot(pairs, middle)


class ExactArith(_Arith):
    """Rational arithmetic: integer numerators with one common denominator per series."""

    name = "exact"
    integer_numerators = True

    def scalar(self, q: Fraction | int) -> Fraction:
        return Fraction(q)

    def _norm(self, t: Trig) -> Trig:
        g = math.gcd(t.den, *t.cos.tolist(), *t.sin.tolist())
        if g > 1:
            return Trig(t.cos // g, t.sin // g, t.den // g)
        return t

    def _align(self, a: Trig, b: Trig) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, int]:
        n = max(len(a.cos), len(b.cos))
        if a.den == b.den:
            fa = fb = 1
            den = a.den
        else:
            g = math.gcd(a.den, b.den)
            fa, fb = b.den // g, a.den // g
            den = a.den * fa
        return (
            _pad(a.cos * fa, n, 0),
            _pad(a.sin * fa, n, 0),
            _pad(b.cos * fb, n, 0),
            _pad(b.sin * fb, n, 0),
            den,
        )

    def add(self, a: Trig, b: Trig) -> Trig:
        ac, as_, bc, bs, den = self._align(a, b)
        return self._norm(Trig(ac + bc, as_ + bs, den))

    def sub(self, a: Trig, b: Trig) -> Trig:
        ac, as_, bc, bs, den = self._align(a, b)
        return self._norm(Trig(ac - bc, as_ - bs, den))

    def scale(self, a: Trig, s: Fraction) -> Trig:
        s = Fraction(s)
        return self._norm(Trig(a.cos * s.numerator, a.sin * s.numerator, a.den * s.denominator))

    def scale_int(self, a: Trig, k: int) -> Trig:
        return self._norm(Trig(a.cos * k, a.sin * k, a.den))

    def mul(self, a: Trig, b: Trig) -> Trig:
        if _fmpz_poly():
            return self.dot([(a, b)])
        c, s = self._products(a, b)
        return self._norm(Trig(c, s, 2 * a.den * b.den))

    def symmetric_dot(self, pairs: list[tuple[Trig, Trig]], middle: tuple[Trig, Trig] | None) -> Trig:
        """One FLINT sum with the doubled pairs weighted by 2 (the same reduced fractions as the generic form)."""
        P = _fmpz_poly()
        if not P:
            return super().symmetric_dot(pairs, middle)
        terms = pairs + ([middle] if middle is not None else [])
        dens = [2 * a.den * b.den for a, b in terms]
        den = math.lcm(*dens)
        weights = [2] * len(pairs) + [1] * (middle is not None)
        out_c, out_s = _flint_dot(P, terms, [den // d * w for d, w in zip(dens, weights, strict=True)])
        return self._norm(Trig(out_c, out_s, den))

    def dot(self, pairs: list[tuple[Trig, Trig]]) -> Trig:
        """``sum a * b`` on one common denominator, reduced once (the same reduced fraction as adding products)."""
        P = _fmpz_poly()
        if not P:
            return self._dot_numpy(pairs)
        dens = [2 * a.den * b.den for a, b in pairs]
        den = math.lcm(*dens)
        out_c, out_s = _flint_dot(P, pairs, [den // d for d in dens])
        return self._norm(Trig(out_c, out_s, den))

    def lincomb(self, scalars: list[Fraction], series: list[Trig]) -> Trig:
        """``sum s * t`` on one common denominator, reduced once."""
        n = max(len(t.cos) for t in series)
        terms = [(Fraction(c), t) for c, t in zip(scalars, series, strict=True) if c]
        if not terms:  # zero terms do not change the reduced result
            return Trig(np.zeros(n, dtype=object), np.zeros(n, dtype=object), 1)
        scalars, series = [c for c, _ in terms], [t for _, t in terms]
        dens = [c.denominator * t.den for c, t in terms]
        den = math.lcm(*dens)
        P = _fmpz_poly()
        if P:
            return self._norm(Trig(*_flint_lincomb(P, scalars, series, [den // d for d in dens], n), den))
        out_c = np.zeros(n, dtype=object)
        out_s = np.zeros(n, dtype=object)
        for c, t, d in zip(scalars, series, dens, strict=True):
            if c.numerator == 0:
                continue
            f = c.numerator * (den // d)
            k = len(t.cos)
            out_c[:k] += t.cos * f
            out_s[:k] += t.sin * f
        return self._norm(Trig(out_c, out_s, den))

    def _dot_numpy(self, pairs: list[tuple[Trig, Trig]]) -> Trig:
        dens = [2 * a.den * b.den for a, b in pairs]
        den = math.lcm(*dens)
        prods = [self._products(a, b) for a, b in pairs]
        n = max(len(c) for c, _ in prods)
        out_c = np.zeros(n, dtype=object)
        out_s = np.zeros(n, dtype=object)
        for (c, s_), d in zip(prods, dens, strict=True):
            f = den // d
            out_c[: len(c)] += c * f
            out_s[: len(s_)] += s_ * f
        return self._norm(Trig(out_c, out_s, den))

    def solve_forced(self, r: Trig) -> Trig:
        n = len(r.cos)
        divs = [1 - k * k for k in range(n)]
        lcm = 1
        for k, d in enumerate(divs):
            if k != 1:
                lcm = math.lcm(lcm, abs(d))
        mult = np.array([0 if k == 1 else lcm // divs[k] for k in range(n)], dtype=object)
        return self._norm(Trig(r.cos * mult, r.sin * mult, r.den * lcm))

    def coeff(self, t: Trig, kind: str, n: int) -> Fraction:
        arr = t.cos if kind == "c" else t.sin
        return Fraction(int(arr[n]), t.den) if n < len(arr) else Fraction(0)

    def exact_harmonics(self, t: Trig) -> tuple[int, list[int], list[int]]:
        """``(den, cos numerators, sin numerators)``."""
        return int(t.den), [int(c) for c in t.cos.tolist()], [int(c) for c in t.sin.tolist()]

    def sine_moment(self, t: Trig, start: int = 2) -> Fraction:
        """``sum n * b_n`` (n >= start) summed on the integer numerators, reduced once."""
        sin = t.sin.tolist()
        return Fraction(sum(n * int(sin[n]) for n in range(start, len(sin))), t.den)

    def _set(self, t: Trig, kind: str, n: int, value: Fraction) -> None:
        value = Fraction(value)
        t.polys = None
        t.cos *= value.denominator
        t.sin *= value.denominator
        t.den *= value.denominator
        (t.cos if kind == "c" else t.sin)[n] = value.numerator * (t.den // value.denominator)


class FixedArith(_Arith):
    """Binary fixed point: integer numerators over ``2**prec`` (the ``mpmath`` arithmetic)."""

    name = "fixed"
    integer_numerators = True

    def __init__(self, prec: int):
        self.prec = int(prec)
        self.one_den = 1 << self.prec

    def scalar(self, q: Fraction | int) -> int:
        q = Fraction(q)
        return _round_div(q.numerator << self.prec, q.denominator)

    def sdiv(self, a: int, b: int) -> int:
        return _round_div(a << self.prec, b)

    def smul(self, a: int, b: int) -> int:
        return _round_shift(a * b, self.prec)

    def is_zero(self, a: int) -> bool:
        return a == 0

    def output(self, a: int) -> mpmath.mpf:
        with mpmath.workprec(self.prec):
            return mpmath.mpf(a) / mpmath.mpf(self.one_den)

    def scale(self, a: Trig, s: int) -> Trig:
        return Trig(_shift_arr(a.cos * s, self.prec), _shift_arr(a.sin * s, self.prec), a.den)

    def mul(self, a: Trig, b: Trig) -> Trig:
        c, s = self._products(a, b)
        return Trig(_shift_arr(c, self.prec + 1), _shift_arr(s, self.prec + 1), a.den)

    def dot(self, pairs: list[tuple[Trig, Trig]]) -> Trig:
        """``sum a * b`` with the products summed exactly and rounded once."""
        P = _fmpz_poly()
        if P:
            c, s = _flint_dot(P, pairs, [1] * len(pairs))
        else:
            prods = [self._products(a, b) for a, b in pairs]
            n = max(len(pc) for pc, _ in prods)
            c = np.zeros(n, dtype=object)
            s = np.zeros(n, dtype=object)
            for pc, ps in prods:
                c[: len(pc)] += pc
                s[: len(ps)] += ps
        return Trig(_shift_arr(c, self.prec + 1), _shift_arr(s, self.prec + 1), pairs[0][0].den)

    def solve_forced(self, r: Trig) -> Trig:
        n = len(r.cos)
        c = r.cos.copy()
        s = r.sin.copy()
        for k in range(n):
            if k == 1:
                c[k] = 0
                s[k] = 0
            elif k > 1:
                d = 1 - k * k
                c[k] = _round_div(c[k], d)
                s[k] = _round_div(s[k], d)
        return Trig(c, s, r.den)

    def solve_detuned(self, r: Trig, nu2: int) -> Trig:
        """Periodic solution of ``x'' + nu2 x = r`` (``nu2`` a fixed-point scalar, not a square of a harmonic)."""
        c = r.cos.copy()
        s = r.sin.copy()
        for k in range(len(c)):
            d = nu2 - ((k * k) << self.prec)
            c[k] = _round_div(int(c[k]) << self.prec, d)
            s[k] = _round_div(int(s[k]) << self.prec, d)
        return Trig(c, s, r.den)

    def coeff(self, t: Trig, kind: str, n: int) -> int:
        arr = t.cos if kind == "c" else t.sin
        return int(arr[n]) if n < len(arr) else 0

    def sine_moment(self, t: Trig, start: int = 2) -> int:
        """``sum n * b_n`` (n >= start): integer weights, so the fixed-point sum is exact."""
        sin = t.sin.tolist()
        return sum(n * int(sin[n]) for n in range(start, len(sin)))

    def _set(self, t: Trig, kind: str, n: int, value: int) -> None:
        (t.cos if kind == "c" else t.sin)[n] = value

    def values(self, t: Trig) -> tuple[list, list]:
        c, s = super().values(t)
        return [self.output(x) for x in c], [self.output(x) for x in s]


class FloatArith(_Arith):
    """Double precision (numpy float64 arrays)."""

    name = "float"
    dtype = float
    zero = 0.0

    def scalar(self, q: Fraction | int) -> float:
        return float(Fraction(q))

    def mul(self, a: Trig, b: Trig) -> Trig:
        c, s = self._products(a, b)
        return Trig(0.5 * c, 0.5 * s, 1)

    def dot(self, pairs: list[tuple[Trig, Trig]]) -> Trig:
        """``sum a * b`` by direct convolution: every coefficient is a sum of products, so small (high harmonic)
        coefficients keep their relative accuracy (a transform would spread the rounding error of the largest)."""
        c, s = _float_direct_dot(pairs, self._products)
        return Trig(c, s, 1)

    def solve_forced(self, r: Trig) -> Trig:
        k = np.arange(len(r.cos), dtype=float)
        d = 1.0 - k * k
        d[1] = np.inf
        return Trig(r.cos / d, r.sin / d, 1)

    def solve_detuned(self, r: Trig, nu2: float) -> Trig:
        """Periodic solution of ``x'' + nu2 x = r`` (``nu2`` not the square of a harmonic number)."""
        k = np.arange(len(r.cos), dtype=float)
        d = nu2 - k * k
        return Trig(r.cos / d, r.sin / d, 1)

    def coeff(self, t: Trig, kind: str, n: int) -> float:
        arr = t.cos if kind == "c" else t.sin
        return float(arr[n]) if n < len(arr) else 0.0

    def _set(self, t: Trig, kind: str, n: int, value: float) -> None:
        t.polys = None
        (t.cos if kind == "c" else t.sin)[n] = value


class RingArith(_Arith):
    """Coefficients in a SymPy polynomial ring over QQ (division only by rationals)."""

    name = "ring"

    def __init__(self, ring: Any):
        self.ring = ring
        self.zero = ring.zero

    def scalar(self, q: Fraction | int) -> Any:
        q = Fraction(q)
        return self.ring.ground_new(self.ring.domain(q.numerator, q.denominator))

    def sdiv(self, a: Any, b: Any) -> Any:
        if b.is_ground and b:
            return a.quo_ground(b.LC)
        raise ArithmeticError("division by a non-constant polynomial coefficient")

    def smul(self, a: Any, b: Any) -> Any:
        return a * b

    def is_zero(self, a: Any) -> bool:
        return not a

    def mul(self, a: Trig, b: Trig) -> Trig:
        c, s = self._products(a, b)
        half = self.ring.domain(1, 2)
        return Trig(c * half, s * half, 1)

    def solve_forced(self, r: Trig) -> Trig:
        n = len(r.cos)
        c = r.cos.copy()
        s = r.sin.copy()
        for k in range(n):
            if k == 1:
                c[k] = self.zero
                s[k] = self.zero
            elif k > 1:
                f = self.ring.domain(1, 1 - k * k)
                c[k] = c[k] * f
                s[k] = s[k] * f
        return Trig(c, s, 1)

    def coeff(self, t: Trig, kind: str, n: int) -> Any:
        arr = t.cos if kind == "c" else t.sin
        return arr[n] if n < len(arr) else self.zero

    def _set(self, t: Trig, kind: str, n: int, value: Any) -> None:
        (t.cos if kind == "c" else t.sin)[n] = value

    def is_zero_num(self, x: Any) -> bool:
        return not x


def _round_div(a: int, b: int) -> int:
    """Round-to-nearest integer division."""
    if b < 0:
        a, b = -a, -b
    return (2 * a + b) // (2 * b)


def _round_shift(a: int, k: int) -> int:
    return (a + (1 << (k - 1))) >> k if k > 0 else a


def _shift_arr(arr: np.ndarray, k: int) -> np.ndarray:
    half = 1 << (k - 1)
    return (arr + half) >> k


def make_arith(arithmetic: str, dps: int | None, order: int) -> _Arith:
    """The arithmetic object for ``arithmetic`` in {"exact", "float", "mpmath"}."""
    if arithmetic == "exact":
        return ExactArith()
    if arithmetic == "float":
        return FloatArith()
    if arithmetic == "mpmath":
        digits = int(dps) if dps is not None else int(mpmath.mp.dps)
        # guard bits: high-order coefficients are small, so keep absolute precision for about 2 bits per order
        return FixedArith(int(3.33 * digits) + 4 * order + 64)
    raise ValueError(f"unknown arithmetic {arithmetic!r}")


def from_number(arith: _Arith, value: Any) -> Any:
    """Convert a SymPy/Python number into ``arith``'s scalar type (exact mode needs a rational)."""
    import sympy as sp

    value = sp.sympify(value)
    if arith.name == "exact":
        if not value.is_Rational:
            raise TypeError(f"{value} is not rational")
        return Fraction(int(value.p), int(value.q))
    if isinstance(arith, FixedArith):
        if value.is_Rational:
            return arith.scalar(Fraction(int(value.p), int(value.q)))
        with mpmath.workprec(arith.prec + 64):
            v = mpmath.mpf(sp.N(value, int(arith.prec / 3.3) + 20))
            return int(mpmath.nint(v * mpmath.mpf(2) ** arith.prec))
    if isinstance(arith, FloatArith):
        return float(value)
    raise TypeError(f"cannot convert {value} for arithmetic {arith.name}")
