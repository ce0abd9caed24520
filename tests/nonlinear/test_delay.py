"""Retarded systems: certified root counts of quasi-polynomials and their roots (Bulgakov §4.13–4.17).

References are independent: Lambert W (scipy) for ``p + c exp(-p)``, closed forms for ``exp(-p) - c``, mpmath
``findroot`` started from the book's printed values, and the recomputed values of seed-bulgakov-part2.md §3.
"""

from __future__ import annotations

import math

import matplotlib
import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy.special import lambertw

from symosc.errors import ConvergenceError, ModelError, ParameterError
from symosc.nonlinear.delay import (
    andronov_maier_optimum,
    callender_hartree_porter_optimum,
    characteristic_quasipolynomial,
    count_roots,
    quasi_polynomial,
    quasi_polynomial_roots,
)

p = sp.Symbol("p")


def test_lambert_w_roots_all_found():
    """p + exp(-p) = 0 <=> p = W_k(-1): every branch with Im in the region is found, none extra."""
    res = quasi_polynomial_roots(p + sp.exp(-p), (-6, 2, -0.4, 60))
    ref = [complex(lambertw(-1, k)) for k in range(-15, 16)]
    ref = sorted((z for z in ref if -0.4 < z.imag < 60 and -6 < z.real < 2), key=lambda z: z.imag)
    got = sorted(res.as_array(), key=lambda z: z.imag)
    assert res.count == len(ref) == len(got)
    np.testing.assert_allclose(got, ref, rtol=1e-13)


def test_count_exact_lattice_of_roots():
    """exp(-p) - 2 has roots -ln 2 + 2 pi i k: the certified count in rectangles equals the lattice count."""
    f = sp.exp(-p) - 2
    for y1, expected in ((1.0, 1), (7.0, 2), (100.0, 16)):
        assert count_roots(f, (-3, 3, -0.5, y1)) == expected
    assert count_roots(f, (0, 3, -0.5, 100)) == 0


def test_table1_andronov_maier_roots():
    """Seed 004, §4.17, Table 1 (report §3 item 18): k1/k0 = 2 1/s, tau = 0.1 s, rho* = 0.2, sigma* = 0.0090710.

    Roots of gamma^2 + 0.2 gamma + sigma* e^{-gamma} = 0 as (|Re|, Im)/tau in 1/s, tested against the report's
    recomputed values (the book prints e.g. 93.10 for 93.13): tolerance 0.05 1/s.  The double real root is -s*/tau.
    """
    opt = andronov_maier_optimum(sp.Rational(1, 5))
    assert sp.simplify(opt["s"] - (sp.Rational(11, 10) - sp.sqrt(sp.Rational(101, 100)))) == 0
    assert float(opt["sigma"]) == pytest.approx(0.0090710, abs=5e-8)
    f = p**2 + sp.Rational(1, 5) * p + opt["sigma"] * sp.exp(-p)
    res = quasi_polynomial_roots(f, (-13, 1, -0.3137, 40))
    tau = 0.1
    table = [(0.95012, 0.0), (93.13, 39.52), (101.12, 110.98), (107.65, 177.68), (112.73, 242.70), (116.84, 306.94)]
    table.append((120.27, 370.77))
    assert res.count == 8 and res.multiplicities[0] == 2
    assert sum(res.multiplicities) == res.count
    got = [(-float(z.real) / tau, float(z.imag) / tau) for z in res.roots]
    for (re_, im_), (re_b, im_b) in zip(got, table, strict=True):
        assert re_ == pytest.approx(re_b, abs=0.05) and im_ == pytest.approx(im_b, abs=0.05)
    assert float(-res.roots[0].real) == pytest.approx(float(opt["s"]), abs=1e-12)
    # independent polish: mpmath.findroot from the book's printed (rounded) values
    fm = sp.lambdify(p, f, "mpmath")
    for z, (re_b, im_b) in zip(res.roots[1:], [(93.10, 39.52), (101.15, 110.97), (107.64, 177.67)], strict=False):
        ref = mpmath.findroot(fm, mpmath.mpc(-re_b * tau, im_b * tau))
        assert abs(complex(ref) - complex(z)) < 1e-12


def test_table1_rounded_sigma_splits_double_root():
    """Report §3 item 18 / §5 item 7: with sigma rounded to 0.00907 the double root splits into -0.0940 and -0.0961."""
    f = p**2 + sp.Rational(1, 5) * p + sp.Rational(907, 100000) * sp.exp(-p)
    res = quasi_polynomial_roots(f, (-0.5, 0.2, -0.3137, 0.4))
    z = sorted(float(r.real) for r in res.roots)
    assert res.count == 2 and z == pytest.approx([-0.0961, -0.0940], abs=1e-4)


def test_callender_hartree_porter_optimum_is_a_triple_root():
    """Seed 004, §4.16 (4.137)–(4.138): s* = 2 - sqrt2, rho* = 0.461159, sigma* = 0.079122 (book 0.07913).

    Independent check: no root has Re > -s* (certified count), and -s* is a triple root (f = f' = f'' = 0 in mpmath).
    """
    opt = callender_hartree_porter_optimum()
    assert opt["s"] == 2 - sp.sqrt(2)
    assert float(opt["rho"]) == pytest.approx(0.461159, abs=1e-6)
    assert float(opt["sigma"]) == pytest.approx(0.079122, abs=1e-6)
    (s,) = opt["cusp_slope"].free_symbols
    assert sp.simplify(opt["cusp_slope"] - (s**3 - 3 * s**2 - 6 * s + 6) / (s**2 - 6 * s + 6)) == 0
    f = characteristic_quasipolynomial(1, 0, 0, 0, opt["rho"], opt["sigma"])
    g = -float(opt["s"])
    for k in range(3):
        assert abs(float(sp.diff(f, p, k).subs(p, opt["s"] * -1).evalf(40))) < 1e-30
    assert abs(float(sp.diff(f, p, 3).subs(p, g))) > 0.1
    assert count_roots(f, (g + 1e-3, 5, -60.3, 60.1)) == 0
    res = quasi_polynomial_roots(f, (-4, 1, -0.3137, 15))
    assert res.multiplicities[0] == 3 and float(res.roots[0].real) == pytest.approx(g, abs=1e-9)


def test_stability_boundary_chp_spiral():
    """(4.132): on rho = w sin w, sigma = w^2 cos w the pair +-i w is on the imaginary axis; inside (smaller gain)
    the system is stable, outside unstable (certified counts in the right half-plane)."""
    w = 1.0
    rho, sigma = w * math.sin(w), w**2 * math.cos(w)
    f = lambda k: p**2 + (k * rho * p + k * sigma) * sp.exp(-p)  # noqa: E731
    box = (0.0, 5.0, -50.3, 50.1)
    assert count_roots(f(0.9), box) == 0
    assert count_roots(f(1.1), box) == 2
    with pytest.raises(ConvergenceError, match="near the contour"):
        count_roots(f(1.0), (0.0, 1.0, 0.5, 1.5))  # the root i*w lies on the edge Re p = 0


def test_root_on_contour_raises():
    with pytest.raises(ConvergenceError, match="move the region boundary"):
        count_roots(sp.exp(-p) - 1, (-1, 1, 0.0, 1.0))  # p = 0 is a root on the bottom edge


def test_extreme_many_roots_and_large_delay():
    """Far up the root chain (Im p ~ 600) and a long delay (tau = 25): counts still match Lambert W."""
    res = quasi_polynomial_roots(p + sp.exp(-p), (-8, 1, 550.3, 650.1))
    ref = [complex(lambertw(-1, k)) for k in range(80, 110)]
    ref = [z for z in ref if 550.3 < z.imag < 650.1]
    np.testing.assert_allclose(sorted(res.as_array(), key=lambda z: z.imag), ref, rtol=1e-12)
    # p + exp(-25 p)/25: roots (1/25) W_k(-1)
    res2 = quasi_polynomial_roots(p + sp.exp(-25 * p) / 25, (-0.3, 0.1, -0.01, 2.0))
    ref2 = [complex(lambertw(-1, k)) / 25 for k in range(0, 10)]
    ref2 = [z for z in ref2 if -0.01 < z.imag < 2.0]
    np.testing.assert_allclose(sorted(res2.as_array(), key=lambda z: z.imag), ref2, rtol=1e-12)


def test_repr_and_plot():
    matplotlib.use("Agg")
    res = quasi_polynomial_roots(p + sp.exp(-p), (-3, 1, -0.3, 10))
    assert "count=2" in repr(res)
    res.plot()


def test_bad_inputs():
    rho = sp.Symbol("rho")
    with pytest.raises(ModelError, match="exactly one free symbol"):
        quasi_polynomial(p**2 + rho * sp.exp(-p))
    with pytest.raises(ParameterError, match="substitute values for: rho"):
        quasi_polynomial(p**2 + rho * sp.exp(-p), p)
    with pytest.raises(ModelError, match="non-negative"):
        quasi_polynomial(p + sp.exp(p))
    with pytest.raises(ModelError, match="not a polynomial"):
        quasi_polynomial(sp.sin(p) + sp.exp(-p))
    with pytest.raises(ParameterError, match="region"):
        count_roots(p + 1, (1, 0, 0, 1))
