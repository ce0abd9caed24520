"""Series products: FLINT's integer polynomials and the pure NumPy fallback give the same fractions; the float and
fixed-point products against direct sums.

Independent reference: the van der Pol limit-cycle amplitude 2 + eps^2/96 - 1033 eps^4/552960
+ 1019689 eps^6/55738368000 + ... (Andersen & Geer 1982, Table 1).
"""

from __future__ import annotations

from fractions import Fraction as R

import pytest
import sympy as sp

from symosc.nonlinear import limit_cycle
from symosc.nonlinear.series._arith import trig as _fourier

x, v = sp.symbols("x v")


@pytest.fixture
def without_flint(monkeypatch):
    monkeypatch.setattr(_fourier, "_FMPZ_POLY", False)


def _coefficients(f, order, arithmetic="exact"):
    lc = limit_cycle(f, order, arithmetic=arithmetic, dps=30)
    return [tuple(map(str, s.coefficients)) for s in (lc.amplitude, lc.frequency, lc.floquet_exponent)]


@pytest.mark.parametrize("f", [(1 - x**2) * v, (1 - v**2) * v, (1 - x**2 - x * v) * v + x**3 / 3])
@pytest.mark.parametrize("arithmetic", ["exact", "mpmath"])
def test_flint_and_numpy_products_agree(f, arithmetic, monkeypatch):
    assert _fourier._fmpz_poly()  # python-flint is installed in the test environment
    with_flint = _coefficients(f, 14, arithmetic)
    monkeypatch.setattr(_fourier, "_FMPZ_POLY", False)
    assert _coefficients(f, 14, arithmetic) == with_flint


def test_van_der_pol_amplitude_against_the_literature(without_flint):
    lc = limit_cycle((1 - x**2) * v, 6)
    expected = [2, 0, R(1, 96), 0, R(-1033, 552960), 0, R(1019689, 55738368000)]
    assert [lc.amplitude.coefficient(k) for k in range(7)] == expected


# sha256 of repr([amplitude, frequency, floquet_exponent coefficients, harmonics of x_32]) at order 32, computed by
# symosc before the products were reorganised (per-pair FLINT products, no parity packing, no shared denominators):
# the rational numbers must not change.
_PINNED_ORDER_32 = {
    "van der Pol": "57c45b329f397310c1e2a1a94a6ae44589dd70dc78bec6f6db2ba6d0c54969c1",
    "mixed": "57a833d1f9875ae99fd78dff3adce69fd07836b03fd347e3681640b3f6f4dfb5",
}


@pytest.mark.parametrize(("name", "f"), [("van der Pol", (1 - x**2) * v), ("mixed", (1 - x**2 - x * v) * v + x**3 / 3)])
def test_exact_coefficients_unchanged_at_order_32(name, f):
    import hashlib

    lc = limit_cycle(f, 32)
    text = repr([lc.amplitude.coefficients, lc.frequency.coefficients, lc.floquet_exponent.coefficients])
    text = text[:-1] + ", " + repr(lc._harmonics[32]) + "]"
    assert hashlib.sha256(text.encode()).hexdigest() == _PINNED_ORDER_32[name]


def test_mpmath_arithmetic_matches_exact_at_order_40():
    f = (1 - x**2) * v
    ex = limit_cycle(f, 40)
    mp = limit_cycle(f, 40, arithmetic="mpmath", dps=30)
    for s_ex, s_mp in [(ex.frequency, mp.frequency), (ex.amplitude, mp.amplitude)]:
        for a, b in zip(s_ex.coefficients, s_mp.coefficients, strict=True):
            assert abs(sp.N(a - b, 40)) <= sp.Float("1e-25") * abs(sp.N(a, 40)) + sp.Float("1e-60")


def _random_trig(rng, n, parity=None, kind=None):
    c, s = rng.standard_normal(n), rng.standard_normal(n)
    s[0] = 0.0
    if parity is not None:
        c[1 - parity :: 2] = 0.0
        s[1 - parity :: 2] = 0.0
    if kind == "c":
        s[:] = 0.0
    return _fourier.Trig(c, s, 1)


@pytest.mark.parametrize(("parity", "kind"), [(None, None), (1, "c"), (0, None), (1, "s"), (0, "c")])
def test_float_dot_matches_per_pair_convolution(parity, kind):
    import numpy as np

    rng = np.random.default_rng(7)
    ar = _fourier.FloatArith()
    # mixed kinds in one sum (cos x sin, sin x sin, ...) as in the van der Pol tables
    pairs = [
        (_random_trig(rng, 5 + 3 * i, parity, kind), _random_trig(rng, 40 - 2 * i, parity, "c" if i % 2 else kind))
        for i in range(12)
    ]
    fast = ar.dot(pairs)
    direct = _fourier._Arith.dot(ar, pairs)  # numpy.convolve on each pair, all eight products
    assert len(fast.cos) == len(direct.cos)
    assert np.allclose(fast.cos, direct.cos, rtol=0, atol=1e-12)
    assert np.allclose(fast.sin, direct.sin, rtol=0, atol=1e-12)
    if parity is not None:  # products of equal parity: odd harmonics vanish exactly, not up to rounding noise
        assert not np.any(fast.cos[1::2]) and not np.any(fast.sin[1::2])


def test_float_dot_keeps_small_high_harmonics_accurate():
    """Geometrically decaying coefficients (as in the series): every product coefficient to 1e-13 relative."""
    from fractions import Fraction

    import numpy as np

    n = 60
    ar, ex = _fourier.FloatArith(), _fourier.ExactArith()
    pairs_f, pairs_x = [], []
    for i in range(8):
        # odd harmonics, cos-only / sin-only alternating, size 10**(-k/3): 20 decades across the series
        vals = [
            [Fraction(((-1) ** (k + i) * (k + 1 + i)), 10 ** (k // 3)) if k % 2 else Fraction(0) for k in range(n)]
            for _ in range(2)
        ]
        a_cos, b_sin = vals
        zero = [Fraction(0)] * n
        for (fc, fs), dst in (((a_cos, zero), "a"), ((zero, b_sin), "b")):
            tf = _fourier.Trig(np.array([float(v) for v in fc]), np.array([float(v) for v in fs]), 1)
            den = 10 ** (n // 3)
            tx = _fourier.Trig(
                _fourier._object_array([int(v * den) for v in fc]),
                _fourier._object_array([int(v * den) for v in fs]),
                den,
            )
            if dst == "a":
                af, ax = tf, tx
            else:
                bf, bx = tf, tx
        pairs_f.append((af, bf))
        pairs_x.append((ax, bx))
    got = ar.dot(pairs_f)
    ref = ex.dot(pairs_x)
    for kind, arr in (("c", got.cos), ("s", got.sin)):
        for h in range(len(arr)):
            exact = ex.coeff(ref, kind, h)
            if exact == 0:
                assert arr[h] == 0.0
            else:
                assert abs(Fraction(float(arr[h])) - exact) <= Fraction(1, 10**13) * abs(exact)


def test_fixed_point_dot_is_the_exact_sum_rounded_once():
    import random

    rng = random.Random(3)
    prec = 80
    fixed = _fourier.FixedArith(prec)
    exact = _fourier.ExactArith()

    def pair():
        return [[rng.randrange(-(1 << 90), 1 << 90) for _ in range(rng.randrange(2, 9))] for _ in range(4)]

    pairs_fixed, pairs_exact = [], []
    for _ in range(6):
        ac, as_, bc, bs = pair()
        as_[0] = 0
        bs = bs[: len(bc)] + [0] * (len(bc) - len(bs))
        bs[0] = 0
        as_ = as_[: len(ac)] + [0] * (len(ac) - len(as_))
        mk = _fourier._object_array
        pairs_fixed.append((_fourier.Trig(mk(ac), mk(as_), 1 << prec), _fourier.Trig(mk(bc), mk(bs), 1 << prec)))
        pairs_exact.append((_fourier.Trig(mk(ac), mk(as_), 1 << prec), _fourier.Trig(mk(bc), mk(bs), 1 << prec)))
    got = fixed.dot(pairs_fixed)
    ref = exact.dot(pairs_exact)
    for kind in ("c", "s"):
        for n in range(len(got.cos)):
            value = exact.coeff(ref, kind, n) * (1 << prec)
            assert abs(fixed.coeff(got, kind, n) - value) <= R(1, 2)


def test_exact_order_48_against_50_digit_fixed_point_series():
    """The exact rationals against the series computed in 50-digit binary fixed point (rounded arithmetic)."""
    f = (1 - x**2) * v
    ex = limit_cycle(f, 48)
    mp = limit_cycle(f, 48, arithmetic="mpmath", dps=50)
    for s_ex, s_mp in [(ex.frequency, mp.frequency), (ex.amplitude, mp.amplitude), (ex.period, mp.period)]:
        assert len(s_ex.coefficients) == 49
        for a, b in zip(s_ex.coefficients, s_mp.coefficients, strict=True):
            assert abs(sp.N(a, 60) - sp.N(b, 60)) <= sp.Float("1e-40", 60) * abs(sp.N(a, 60)) + sp.Float("1e-80", 60)


def _envelope_errors(ref, got):
    """|got_k - ref_k| relative to the largest |ref_j|, |j - k| <= 4 (coefficients near a sign change are small)."""
    return [
        abs(float(g) - float(r)) / max(abs(float(c)) for c in ref[max(0, k - 4) : k + 5])
        for k, (r, g) in enumerate(zip(ref, got, strict=True))
    ]


def test_float_series_accuracy_to_order_120():
    """Float coefficients against the 30-digit fixed-point series, orders 1..120 (van der Pol).

    Stated accuracy (relative to the size of the neighbouring coefficients): 1e-10 to order 40, 3e-7 to order 100,
    2e-5 to order 120.  A transform-based product loses the small high harmonics (about 1e-6 at order 100).
    """
    f = (1 - x**2) * v
    fl = limit_cycle(f, 120, arithmetic="float")
    mp = limit_cycle(f, 120, arithmetic="mpmath", dps=30)
    for name in ("frequency", "amplitude"):
        err = _envelope_errors(getattr(mp, name).coefficients, getattr(fl, name).coefficients)
        assert max(err[:41]) <= 1e-10, name
        assert max(err[:101]) <= 3e-7, name
        assert max(err) <= 2e-5, name
