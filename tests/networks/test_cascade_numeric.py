"""Long cascades kept as products: numeric chain matrices per frequency, exact products on demand.

References are computed here, independently of symosc: the sections' chain matrices typed in from Bulgakov (1954),
§8.35 (series arm ``[[1, Z], [0, 1]]``, shunt arm ``[[1, 0], [1/Z, 1]]``) and multiplied in 50-digit mpmath, or
exact rational matrix powers.
"""

from __future__ import annotations

import pickle
import warnings

import mpmath
import numpy as np
import pytest
import sympy as sp

from symosc.errors import AccuracyWarning, ParameterError
from symosc.networks import FourPole, cascade, chain_power, series_element, shunt_element, t_section

p = sp.Symbol("p")


def _lc_reference(z, n: int, L=1, C=1) -> np.ndarray:
    """(series L) then (shunt C), n times, at p = z, in 50-digit mpmath."""
    with mpmath.workdps(50):
        z = mpmath.mpmathify(z)
        S = mpmath.matrix([[1, L * z], [0, 1]]) * mpmath.matrix([[1, 0], [C * z, 1]])
        R = mpmath.eye(2)
        for _ in range(n):
            R = R * S
        return np.array(R.tolist(), dtype=complex)


def _normwise(A: np.ndarray, ref: np.ndarray) -> float:
    return float(np.max(np.abs(A - ref)) / np.max(np.abs(ref)))


@pytest.fixture(scope="module")
def lc_section() -> FourPole:
    return cascade(series_element(p), shunt_element(1 / p))


def test_hundred_sections_pass_and_stop_band(lc_section):
    """100 L-C sections (cut-off 2 rad/s): <= 1e-10 normwise against the 50-digit product, in both bands.

    The multiplied-out chain has polynomials of degree 200 whose terms reach 1e60 in the pass band; evaluating it
    (rather than the product) loses every digit there, which the first assertion block also shows."""
    omega = np.array([0.1, 0.7, 1.3, 1.9, 1.999, 2.001, 2.5, 6.0, 10.0])
    refs = [_lc_reference(1j * w, 100) for w in omega]
    for line in (cascade(*[lc_section] * 100), chain_power(lc_section, 100), lc_section**100):
        A = line.evaluate_numeric(omega)
        assert A.shape == (len(omega), 2, 2)
        for k in range(len(omega)):
            assert _normwise(A[k], refs[k]) <= 1e-10, omega[k]
    # the expanded form really is useless in floating point (why the product form is evaluated)
    expanded = sp.lambdify(p, chain_power(lc_section, 100).chain, "numpy")(0.7j)
    assert _normwise(np.array(expanded, dtype=complex), refs[1]) > 1e-3


def test_exact_chain_of_power_and_cascade(lc_section):
    """The exact chain matrix, formed on first read, equals an exact rational matrix power (at p = 3/7)."""
    line = chain_power(lc_section, 40)
    r = sp.Rational(3, 7)
    S = sp.Matrix([[1 + r**2, r], [r, 1]])
    assert line.chain.subs(p, r) == S**40
    assert cascade(*[lc_section] * 40).chain == line.chain
    assert sp.Poly(line.chain[0, 0], p).degree() == 80
    # a cascade of different sections, with a power inside
    T = t_section(p, 1 / (2 * p), 3 * p)
    mixed = cascade(T, lc_section**3, T.reversed())
    M = sp.Matrix(T.chain) * sp.Matrix(lc_section.chain) ** 3 * sp.Matrix(T.reversed().chain)
    assert (mixed.chain - M).applyfunc(sp.cancel).is_zero_matrix
    z = 0.3 + 1.1j
    num = mixed.evaluate_numeric(p_values=[z])[0]
    assert _normwise(num, np.array(M.subs(p, z).evalf(30).tolist(), dtype=complex)) < 1e-13


def test_element_values_and_complex_frequency():
    """Symbolic element values given numerically; p off the imaginary axis."""
    L, C = sp.symbols("L C", positive=True)
    line = cascade(series_element(L * p), shunt_element(1 / (C * p))) ** 50
    z = np.array([0.05 + 1.0j, 0.2 + 3.0j])
    A = line.evaluate_numeric(p_values=z, values={"L": 0.5, C: 2.0})
    for k in range(2):
        assert _normwise(A[k], _lc_reference(z[k], 50, L=0.5, C=2.0)) <= 1e-11
    with pytest.raises(ParameterError, match="C"):
        line.evaluate_numeric([1.0], {"L": 0.5})


def test_overflow_far_in_the_stop_band_warns(lc_section):
    with pytest.warns(AccuracyWarning, match="not finite"):
        A = chain_power(lc_section, 1000).evaluate_numeric([50.0, 1.0])
    assert not np.all(np.isfinite(A[0])) and np.all(np.isfinite(A[1]))


def test_refusals(lc_section):
    with pytest.raises(ParameterError, match="exactly one"):
        lc_section.evaluate_numeric()
    with pytest.raises(ParameterError, match="exactly one"):
        lc_section.evaluate_numeric([1.0], p_values=[1j])
    with pytest.raises(ParameterError, match="finite"):
        lc_section.evaluate_numeric([np.nan])
    for bad in (0, -2, 1.5, True):
        with pytest.raises(ParameterError):
            lc_section**bad


def test_products_keep_their_structure(lc_section):
    """reversed, subs and pickling of a cascade before it is multiplied out agree with the multiplied-out form."""
    R = sp.Symbol("R", positive=True)
    line = cascade(t_section(R, 1 / p, 2 * R), lc_section**5)
    rev = line.reversed()
    A = sp.Matrix(line.chain)
    expected = sp.Matrix([[A[1, 1], A[0, 1]], [A[1, 0], A[0, 0]]]) / A.det()
    assert (sp.Matrix(rev.chain) - expected).applyfunc(sp.cancel).is_zero_matrix
    fresh = cascade(t_section(R, 1 / p, 2 * R), lc_section**5)
    sub = fresh.subs(R, 3)
    assert (sp.Matrix(sub.chain) - A.subs(R, 3)).applyfunc(sp.cancel).is_zero_matrix
    again = pickle.loads(pickle.dumps(cascade(t_section(R, 1 / p, 2 * R), lc_section**5)))
    assert again == line
    assert again.netlist is not None and len(again.netlist.branches) == 3 + 10
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        np.testing.assert_allclose(
            again.evaluate_numeric([0.4], {R: 3})[0], sub.evaluate_numeric([0.4])[0], rtol=1e-13, atol=0
        )
