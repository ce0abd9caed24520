"""Richards' function (Bulgakov (1954), §9.27, eq. (9.408)) and the M-function realisation (§9.24).

References are independent of the code under test: positive realness is checked numerically on a grid of the
closed right half-plane (and with NumPy's polynomial roots for the poles), M-functions are built from random RLC
networks by the substitution ``p -> p + rho`` of eq. (9.276), and every realisation is compared with the target
exactly (``cancel`` to zero).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from symosc.errors import ParameterError
from symosc.networks import (
    Capacitor,
    Inductor,
    Parallel,
    Resistor,
    Series,
    m_abscissa,
    m_function_synthesis,
    richards_function,
)

p = sp.Symbol("p")
pos = st.fractions(min_value=sp.Rational(1, 5), max_value=5, max_denominator=6).map(lambda f: sp.Rational(f))


@st.composite
def rlc(draw, size=3):
    """Random series/parallel tree of ``size`` positive R, L, C elements."""
    if size == 1:
        kind = draw(st.sampled_from([Resistor, Inductor, Capacitor]))
        return kind(draw(pos))
    left = draw(st.integers(1, size - 1))
    a, b = draw(rlc(left)), draw(rlc(size - left))
    return a + b if draw(st.booleans()) else a | b


def _rank(Z):
    N, D = sp.fraction(sp.cancel(Z))
    return sp.degree(N, p) + sp.degree(D, p)


def _numerically_positive_real(Z, shift=0.0) -> bool:
    """Poles in Re p < -shift (NumPy roots) and Re Z >= 0 on Re p = -shift + sigma, sigma in [0, 3] (grid)."""
    _N, D = sp.fraction(sp.cancel(Z))
    den = np.array([float(c) for c in sp.Poly(D, p).all_coeffs()])
    if den.size > 1 and np.max(np.roots(den).real) > -shift + 1e-9:
        return False
    f = sp.lambdify(p, Z, "numpy")
    w = np.concatenate([np.linspace(-40, 40, 4001), [1e4, -1e4]])
    for sigma in (1e-9, 0.3, 1.0, 3.0):
        vals = f(-shift + sigma + 1j * w)
        if np.min(np.real(vals)) < -1e-9 * (1 + np.max(np.abs(vals))):
            return False
    return True


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(2, 4).flatmap(rlc), pos)
def test_richards_function_is_positive_real_of_no_higher_rank(net, k):
    """Richards' theorem (9.406)-(9.408): R is positive real and rank R <= rank Z, for random RLC impedances."""
    Z = net.impedance(p)
    if sp.cancel(k * Z.subs(p, k) - p * Z) == 0:  # Z = c/p: Richards' function undefined
        return
    R = richards_function(Z, k, p)
    assert _rank(R) <= _rank(Z)
    assert _numerically_positive_real(R)
    # the defining identity, solved back for Z (9.411): Z = (k Z(k) R + p Z(k)) / (k + p R)
    Zk = Z.subs(p, k)
    assert sp.cancel((k * Zk * R + p * Zk) / (k + p * R) - Z) == 0


def test_richards_function_vanishes_at_the_real_part_zero():
    """(9.409)-(9.410): with Z(k)/k = L and Z(i w0) = i w0 L, R(i w0) = 0.  Z = (p²+p+1)/(p²+p+4), w0² = 2."""
    Z = (p**2 + p + 1) / (p**2 + p + 4)
    assert sp.simplify(Z.subs(p, sp.I * sp.sqrt(2)) - sp.I * sp.sqrt(2) / 2) == 0  # L = 1/2
    k = 1  # Z(1)/1 = 3/6 = L
    R = richards_function(Z, k, p)
    assert sp.simplify(R.subs(p, sp.I * sp.sqrt(2))) == 0


def test_richards_function_rejects_bad_input():
    with pytest.raises(ParameterError, match="k must be a positive"):
        richards_function((p + 1) / (p + 2), -1, p)
    with pytest.raises(ParameterError, match="not positive real"):
        richards_function((p - 1) / (p + 2), 1, p)
    with pytest.raises(ParameterError, match="undefined for Z = c/p"):
        richards_function(3 / p, 2, p)


def _lossy_everywhere(net, rho) -> bool:
    """Every inductor has a series resistor rho L, every capacitor a parallel resistor 1/(rho C)."""
    if isinstance(net, Resistor):
        return True
    if isinstance(net, Inductor | Capacitor):
        return False  # a bare L or C that is not wrapped with its loss resistor
    parts = net.parts
    wrapped = [q for q in parts if isinstance(q, Inductor | Capacitor)]
    for q in wrapped:
        if isinstance(q, Inductor) and not (isinstance(net, Series) and Resistor(rho * q.L) in parts):
            return False
        if isinstance(q, Capacitor) and not (isinstance(net, Parallel) and Resistor(1 / (rho * q.C)) in parts):
            return False
    return all(_lossy_everywhere(q, rho) for q in parts if not isinstance(q, Inductor | Capacitor))


def _check_realisation(net, Z, rho):
    assert sp.cancel(net.impedance(p) - Z) == 0
    assert all(v > 0 for e in net.elements() for v in vars(e).values())
    assert _lossy_everywhere(net, rho)


def test_m_function_example_1_realised():
    """§9.24, Ex. 1: Z = (2p + 3)/(p + 4) is an M-function for rho < min(4, 3/2)."""
    Z = (2 * p + 3) / (p + 4)
    for rho in (sp.Rational(1, 2), sp.Rational(7, 5)):
        _check_realisation(m_function_synthesis(Z, rho, p), Z, rho)
    assert _numerically_positive_real(Z, shift=1.4)
    with pytest.raises(ParameterError, match="not an M-function with this rho"):
        m_function_synthesis(Z, sp.Rational(8, 5), p)


def test_m_function_example_2_realised():
    """§9.24, Ex. 2: Z = (p² + 5p + 4)/(p + 2); rho < min(b2/b1 = 2, roots of rho² - 5 rho + 4: 1, 4) = 1."""
    Z = (p**2 + 5 * p + 4) / (p + 2)
    rho = sp.Rational(1, 2)
    _check_realisation(m_function_synthesis(Z, rho, p), Z, rho)
    assert _numerically_positive_real(Z, shift=0.99)
    assert not _numerically_positive_real(Z, shift=1.2)
    with pytest.raises(ParameterError, match="not an M-function"):
        m_function_synthesis(Z, sp.Rational(6, 5), p)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(2, 4).flatmap(rlc), pos)
def test_random_m_functions_are_realised_exactly(net, rho):
    """(9.276): Z(p) = Z*(p + rho) with Z* the impedance of a random RLC network is an M-function; its
    realisation reproduces Z exactly with lossy inductors and capacitors only."""
    Zstar = net.impedance(p)
    Z = sp.cancel(Zstar.subs(p, p + rho))
    assert _numerically_positive_real(Z, shift=float(rho) * 0.999)
    _check_realisation(m_function_synthesis(Z, rho, p), Z, rho)


def test_m_function_bad_rho():
    with pytest.raises(ParameterError, match="rho must be a positive"):
        m_function_synthesis((p + 1) / (p + 2), 0, p)
    with pytest.raises(ParameterError, match="rho must be a positive"):
        m_function_synthesis((p + 1) / (p + 2), sp.Symbol("r"), p)


# --- the largest rho (m_abscissa) ---------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("Z", "expected"),
    [
        ((2 * p + 3) / (p + 4), sp.Rational(3, 2)),  # Ex. 1: min(b1/b0, a1/a0)
        ((5 * p + 2) / (3 * p + 7), sp.Rational(2, 5)),  # Ex. 1 again, the numerator's zero nearer the axis
        ((p**2 + 5 * p + 4) / (p + 2), sp.Integer(1)),  # Ex. 2: min(2, roots 1 and 4 of rho² - 5 rho + 4)
        (p + 1, sp.Integer(1)),
        (1 / (p + 3), sp.Integer(3)),
    ],
)
def test_m_abscissa_of_the_book_examples(Z, expected):
    """Bulgakov (1954), §9.24, Ex. 1 and Ex. 2: the bounds on rho stated there are attained."""
    assert m_abscissa(Z, p) == expected


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(1, 3).flatmap(rlc), pos, pos)
def test_m_abscissa_of_a_shifted_network_with_an_axis_pole(net, C, rho):
    """A network with a series capacitor has a pole at p = 0, so Z*(p) = Z(p) is an M-function for no rho > 0;
    Z*(p + rho) is one exactly up to rho (the pole at -rho); without rho the synthesis uses that value."""
    Zstar = (net + Capacitor(C)).impedance(p)
    assert m_abscissa(Zstar, p) == 0
    Z = sp.cancel(Zstar.subs(p, p + rho))
    assert m_abscissa(Z, p) == rho
    _check_realisation(m_function_synthesis(Z, p=p), Z, rho)


def test_m_abscissa_at_a_zero_of_the_real_part():
    """Z* = (p² + p + 1)/(p² + p + 4) has Re Z*(iω) = 0 at ω² = 2 (its Brune minimum is 0), so Z*(p + 1/3) is an
    M-function exactly up to 1/3; checked numerically on both sides as well."""
    Zstar = (p**2 + p + 1) / (p**2 + p + 4)
    assert m_abscissa(Zstar, p) == 0
    Z = sp.cancel(Zstar.subs(p, p + sp.Rational(1, 3)))
    assert m_abscissa(Z, p) == sp.Rational(1, 3)
    assert _numerically_positive_real(Z, shift=0.3333)
    assert not _numerically_positive_real(Z, shift=0.35)


def test_m_abscissa_irrational_and_its_synthesis():
    """Z = (p² + 2p + 4)/(p² + p + 1): the bound is where the minimum of Re Z(-rho + iω) reaches zero, an
    irrational number; the grid test of the closed half-plane Re p >= -rho agrees on both sides, and the
    realisation with that rho is exact."""
    Z = (p**2 + 2 * p + 4) / (p**2 + p + 1)
    rho = m_abscissa(Z, p)
    assert sp.simplify(rho - (21 - 4 * sp.sqrt(14)) / 31) == 0
    assert _numerically_positive_real(Z, shift=float(rho) - 1e-4)
    assert not _numerically_positive_real(Z, shift=float(rho) + 1e-2)
    net = m_function_synthesis(Z, p=p)
    assert sp.simplify(net.impedance(p) - Z) == 0


def test_m_abscissa_degree_6():
    """A degree-6 network with a series capacitor, shifted by 2/7 (the pole at p = 0 moves to -2/7)."""
    star = (Resistor(1) | Inductor(2)) + (Capacitor(sp.Rational(1, 3)) | (Resistor(2) + Inductor(1)))
    star = (star | Capacitor(1)) + (Inductor(3) | Resistor(5)) + Capacitor(2)
    Zstar = star.impedance(p)
    N, D = sp.fraction(sp.cancel(Zstar))
    assert max(sp.degree(N, p), sp.degree(D, p)) == 6
    Z = sp.cancel(Zstar.subs(p, p + sp.Rational(2, 7)))
    assert m_abscissa(Z, p) == sp.Rational(2, 7)


def test_m_abscissa_bad_input_and_edges():
    assert m_abscissa(sp.Integer(3), p) == sp.oo
    assert m_abscissa(p + 1 / p, p) == 0
    with pytest.raises(ParameterError, match="not positive real"):
        m_abscissa((p**2 + 1) / (p**2 + p + 4), p)
    with pytest.raises(ParameterError, match="rational or algebraic coefficients"):
        m_abscissa((p + sp.pi) / (p + 1), p)
    with pytest.raises(ParameterError, match="rational or algebraic coefficients"):
        m_abscissa((p + sp.Symbol("a", positive=True)) / (p + 1), p)
    with pytest.raises(ParameterError, match="for no rho > 0"):
        m_function_synthesis((p**2 + p + 1) / (p**2 + p + 4), p=p)
    assert m_function_synthesis(sp.Integer(3), p=p) == Resistor(3)


def _lossy_tree(rng, n, surd=1):
    """Random series/parallel tree of ``n`` resistors, lossy inductors (L + R) and lossy capacitors (C | R); with
    ``surd`` = sqrt(2) about half of the values are rational multiples of it."""
    value = lambda: sp.Rational(rng.randint(1, 9), rng.randint(1, 5)) * (surd if rng.random() < 0.5 else 1)  # noqa: E731
    if n == 1:
        kind = rng.choice("RLC")
        if kind == "R":
            return Resistor(value())
        return Inductor(value()) + Resistor(value()) if kind == "L" else Capacitor(value()) | Resistor(value())
    k = rng.randint(1, n - 1)
    a, b = _lossy_tree(rng, k, surd), _lossy_tree(rng, n - k, surd)
    return a + b if rng.random() < 0.5 else a | b


def _numerically_m_function(Z, rho) -> bool:
    """Poles and zeros left of Re p = -rho (NumPy roots) and Re Z >= 0 on that line (dense grid to |ω| = 1e5)."""
    for poly in sp.fraction(sp.cancel(Z)):
        c = np.array([float(a) for a in sp.Poly(poly, p).all_coeffs()])
        if c.size > 1 and np.max(np.roots(c).real) > -rho + 1e-9:
            return False
    f = sp.lambdify(p, Z, "numpy")
    far = np.geomspace(30, 1e5, 2000)
    w = np.concatenate([np.linspace(-30, 30, 30001), far, -far])
    return bool(np.min(np.real(f(-rho + 1j * w))) >= -1e-9)


@pytest.mark.parametrize("state", range(8))
def test_m_abscissa_of_random_lossy_networks(state):
    """Networks whose every L and C carries loss have a positive abscissa, often irrational; NumPy roots and a
    dense grid on the line Re p = -rho agree that it is the largest: PR just left of it, not PR 2 % beyond."""
    import random

    rng = random.Random(state)
    Z = sp.cancel(_lossy_tree(rng, rng.randint(2, 4)).impedance(p))
    rho = m_abscissa(Z, p)
    if rho == sp.oo:
        assert not Z.has(p)
        return
    r = float(rho)
    assert r > 0
    assert _numerically_m_function(Z, r * (1 - 1e-6) - 1e-9)
    assert not _numerically_m_function(Z, r * 1.02 + 1e-3)


def test_m_abscissa_with_algebraic_coefficients():
    """Z = (p + sqrt 2)/(p + 1): Z(p - rho) keeps its zero and pole in Re p <= 0 up to rho = 1, and
    Re[(a + iω)/(b + iω)] = (ab + ω²)/(b² + ω²) >= 0 needs a b >= 0 (a = sqrt 2 - rho, b = 1 - rho): rho* = 1 by
    hand; the realisation with R_L/L = 1 is exact."""
    Z = (p + sp.sqrt(2)) / (p + 1)
    assert m_abscissa(Z, p) == 1
    net = m_function_synthesis(Z, p=p)
    assert sp.simplify(net.impedance(p) - Z) == 0
    assert all(sp.N(v) > 0 for e in net.elements() for v in vars(e).values())


@pytest.mark.parametrize("state", [102, 103, 104, 105, 109])
def test_m_abscissa_of_random_lossy_networks_with_surds(state):
    """Lossy networks with element values in QQ(sqrt 2): the abscissa is exact (a root of a rational norm) and
    NumPy roots and the dense grid agree that it is the largest (the states give rational, surd and quartic
    abscissae)."""
    import random

    rng = random.Random(state)
    Z = sp.cancel(_lossy_tree(rng, rng.randint(2, 3), sp.sqrt(2)).impedance(p))
    assert Z.has(sp.sqrt(2))
    rho = m_abscissa(Z, p)
    r = float(rho)
    assert r > 0
    assert _numerically_m_function(Z, r * (1 - 1e-6) - 1e-9)
    assert not _numerically_m_function(Z, r * 1.02 + 1e-3)
