"""Routh array, Hurwitz and Liénard–Chipart criteria (Bulgakov (1954), §8.16–8.22).

References are independent: SymPy's exact complex-root counting in a rectangle (Collins–Krandick) applied to the
exact rational value of the float coefficients, numpy.roots away from the boundary, and Hurwitz determinants
expanded directly by SymPy's Berkowitz method.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from symosc.errors import ParameterError
from symosc.linear import (
    hurwitz,
    hurwitz_at_degree,
    lienard_chipart,
    routh_array,
    routh_form_criteria,
    shifted_coefficients,
    stability_degree,
)

REAL_PARTS = st.one_of(
    st.floats(-3, 3, allow_nan=False),
    st.sampled_from([0.0, 1e-9, -1e-9, 1e-6, -1e-6, -1e-3]),
)


@st.composite
def polynomials(draw):
    """Float coefficients of a real polynomial of degree 1..20 built from random roots, some near the axis."""
    degree = draw(st.integers(1, 20))
    roots = []
    while len(roots) < degree:
        re = draw(REAL_PARTS)
        if degree - len(roots) >= 2 and draw(st.booleans()):
            im = draw(st.floats(0.05, 3))
            roots += [complex(re, im), complex(re, -im)]
        else:
            roots.append(complex(draw(st.floats(-3, 3)) if draw(st.booleans()) else re, 0))
    lead = draw(st.sampled_from([1.0, 2.5, -1.0, 0.3]))
    return [float(c) for c in lead * np.real(np.poly(roots))]


def _roots_in_closed_right_half_plane(coeffs) -> int:
    """Exact count of roots with Re >= 0 of the polynomial with these (exactly converted) coefficients."""
    exact = [sp.Rational(Fraction(c).numerator, Fraction(c).denominator) for c in coeffs]
    bound = 1 + int(max(abs(c / exact[0]) for c in exact[1:])) + 1
    return sp.Poly(exact, sp.Symbol("x")).count_roots(-bound * sp.I, bound + bound * sp.I)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(polynomials())
def test_verdicts_agree_with_root_location(coeffs):
    """Hurwitz, all four Liénard–Chipart forms and the Routh array agree with high-precision roots."""
    n_closed = _roots_in_closed_right_half_plane(coeffs)
    verdicts = [hurwitz(coeffs)] + [lienard_chipart(coeffs, form=f) for f in (1, 2, 3, 4)]
    for v in verdicts:
        assert v.stable == (n_closed == 0), (v, n_closed)
    arr = routh_array(coeffs)
    if arr.sign_changes is not None:  # regular array: no root on the axis, Routh's count is the RHP count
        assert arr.sign_changes == n_closed
    # away from the boundary, the double-precision root finder agrees too
    scale = max(abs(np.roots(coeffs)).max(), 1.0)
    np_max = np.roots(coeffs).real.max()
    if abs(np_max) > 1e-6 * scale:
        assert verdicts[0].stable == (np_max < 0)
    assert verdicts[0].tol == 1e-9


@pytest.mark.parametrize("eps", [1e-11, -1e-11, 1e-13])
def test_near_boundary_is_flagged_and_exact(eps):
    """A pair at Re = eps: the verdict follows the sign of eps exactly and is flagged near the boundary."""
    c = [float(v) for v in np.real(np.poly([complex(eps, 1.5), complex(eps, -1.5), -1.0, -2.0 + 1j, -2.0 - 1j]))]
    v = hurwitz(c)
    assert v.stable == (_roots_in_closed_right_half_plane(c) == 0) == (eps < 0)
    assert v.near_boundary and abs(v.margin) < 1e-9
    far = hurwitz([float(x) for x in np.real(np.poly([-0.5 + 1.5j, -0.5 - 1.5j, -1.0]))])
    assert far.stable and not far.near_boundary


def test_boundary_examples():
    """§8.12 Ex. 2 (E8): (D + 4)(D² + 16) lies on the boundary, Δ2 = k1 k2 - k0 k3 = 0."""
    v = hurwitz([1, 4, 16, 64])
    assert v.stable is False and v.minors[1] == 0 and v.near_boundary and v.margin == 0.0
    assert hurwitz([1, 4, 16, 63.999]).stable is True
    assert hurwitz([1, 4, 16, 64.001]).stable is False
    # numeric k0 < 0 is normalised
    assert hurwitz([-1, -3, -3, -1]).stable is True


@pytest.mark.parametrize("s", [2, 3, 4, 5, 6])
def test_symbolic_minors_equal_hurwitz_determinants(s):
    """The fraction-free Routh first column equals the Hurwitz minors expanded by Berkowitz's method."""
    k = sp.symbols(f"k0:{s + 1}")
    H = sp.Matrix(s, s, lambda i, j: k[2 * (i + 1) - (j + 1)] if 0 <= 2 * (i + 1) - (j + 1) <= s else 0)
    col = routh_array(k).first_column
    for i in range(1, s + 1):
        assert sp.expand(col[i] - H[:i, :i].det(method="berkowitz")) == 0


def test_symbolic_known_inequalities():
    """Bulgakov (1954), §8.18: s = 2, 3, 4 closed forms (with k0 > 0 listed first)."""
    k0, k1, k2, k3, k4 = sp.symbols("k0:5")
    assert hurwitz([k0, k1, k2]).conditions == (k0, k1, k2)
    c3 = hurwitz([k0, k1, k2, k3]).conditions
    assert len(c3) == 4 and sp.expand(c3[2] - (k1 * k2 - k0 * k3)) == 0 and c3[1] == k1 and c3[3] == k3
    c4 = hurwitz([k0, k1, k2, k3, k4]).conditions
    assert sp.expand(c4[3] - ((k1 * k2 - k0 * k3) * k3 - k1**2 * k4)) == 0 and c4[-1] == k4


@settings(max_examples=15, deadline=None)
@given(st.integers(2, 6), st.lists(st.integers(-9, 9), min_size=7, max_size=7))
def test_symbolic_verdict_substitutes_to_numeric(s, values):
    """Symbolic Hurwitz inequalities evaluated at integers give the numeric verdict (degree <= 6)."""
    k = sp.symbols(f"k0:{s + 1}")
    vals = [1] + [v for v in values[:s]]
    sym = hurwitz(k).stable.subs(dict(zip(k, vals, strict=True)))
    assert bool(sym) == hurwitz(vals).stable


def test_bad_input():
    with pytest.raises(ParameterError, match="leading coefficient"):
        hurwitz([0, 1, 2])
    with pytest.raises(ParameterError, match="at least two"):
        routh_array([1])
    with pytest.raises(ParameterError, match="finite"):
        hurwitz([1, float("nan")])
    with pytest.raises(ParameterError, match="real coefficients"):
        hurwitz([1, 2j, 3])
    with pytest.raises(ParameterError, match="form"):
        lienard_chipart([1, 2, 3], form=5)


def test_tsypkin_bromberg_shift():
    """Bulgakov (1954), eq. (8.133): K_j of the cubic; the triple root (λ + δ)^3 is the tip L (8.138)."""
    k0, k1, k2, k3, d = sp.symbols("k0:4 delta")
    K = shifted_coefficients([k0, k1, k2, k3], d)
    assert sp.expand(K[1] - (k1 - 3 * d * k0)) == 0
    assert sp.expand(K[2] - (3 * d**2 * k0 - 2 * d * k1 + k2)) == 0
    # (λ+1)^3: degree of stability exactly 1; Hurwitz at δ slightly less holds, at δ = 1 fails
    sd = stability_degree([1, 3, 3, 1], tol=1e-4)
    assert abs(sd.degree - 1) < 1e-4 and sd.error_estimate < 1e-4
    assert hurwitz_at_degree([1, 3, 3, 1], sp.Rational(999, 1000)).stable is True
    assert hurwitz_at_degree([1, 3, 3, 1], 1).stable is False
    # random polynomial: numpy roots as the reference
    c = np.real(np.poly([-1.3, -2 + 1j, -2 - 1j, -0.7 + 3j, -0.7 - 3j]))
    assert abs(stability_degree(c).degree - 0.7) < 1e-12


def test_routh_quadratic_forms():
    """Bulgakov (1954), §8.16: 5° gyroscopic conservative -> imaginary roots; A, N, H > 0, J = 0 -> stable."""
    A, H, G = np.eye(2), np.diag([2.0, 3.0]), np.array([[0, 1.0], [-1.0, 0]])
    v = routh_form_criteria(A, H=H, G=G)
    lam = np.linalg.eigvals(np.block([[np.zeros((2, 2)), np.eye(2)], [-H, -G]]))
    assert v.complex_roots.startswith("purely imaginary") and np.abs(lam.real).max() < 1e-12
    N = np.array([[0.5, 0.1], [0.1, 0.3]])
    v2 = routh_form_criteria(A, N=N, G=G, H=H)
    lam2 = np.linalg.eigvals(np.block([[np.zeros((2, 2)), np.eye(2)], [-H, -(N + G)]]))
    assert v2.asymptotically_stable is True and lam2.real.max() < 0


def test_max_stability_degree_cubic_by_search():
    """§8.22 (8.138)–(8.141): the optimum over a box of coefficients, against a brute-force search of -max Re λ."""
    from symosc.linear import max_stability_degree_cubic

    opt = max_stability_degree_cubic(1.0, k1_max=3.0, k2_max=5.0, k3_max=4.0)
    assert opt.binding == "k1" and abs(opt.degree - 1.0) < 1e-15  # min(3/3, sqrt(5/3), 4^(1/3))
    best = 0.0
    for k1 in np.linspace(0.1, 3.0, 20):
        for k2 in np.linspace(0.1, 5.0, 20):
            for k3 in np.linspace(0.05, 4.0, 20):
                best = max(best, -np.roots([1.0, k1, k2, k3]).real.max())
    assert best <= opt.degree + 1e-6 and best > opt.degree - 0.06
    # at the optimum the polynomial is (λ + δ)^3
    assert np.allclose(np.poly([-opt.degree] * 3), [1.0, *opt.coefficients])
