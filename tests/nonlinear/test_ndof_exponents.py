"""Characteristic exponents of n-DOF Poincaré periodic solutions as series in eps (Bulgakov §12.5–12.6).

Reference values are the Floquet exponents of the numerically computed periodic orbit (shooting with the monodromy
matrix of the variational equation, scipy DOP853, in ``NDofPeriodicSolution.validate``) — an independent computation
that uses neither the series nor the perturbation theory.  Report: seed-bulgakov-part3b.md §2.7 ("Stability").
"""

from __future__ import annotations

import functools
import itertools

import numpy as np
import pytest
import sympy as sp
from sympy import Rational as R

from symosc.errors import ModelError, ParameterError
from symosc.nonlinear import CharacteristicExponentSeries, periodic_solution_ndof

q1, q2, q3, v1, v2, v3 = sp.symbols("q1 q2 q3 v1 v2 v3")
EYE2 = [[1, 0], [0, 1]]
VDP2 = ([[2, -1], [-1, 2]], [(1 - q1**2) * v1, (1 - q2**2) * v2])
ASYM = ([[R(6, 5), R(-1, 5)], [R(-1, 5), R(2)]], [(1 - q1**2) * v1 + q1 * q2, -v2 / 2 + q1**2 * q2])


@functools.cache
def _solution(name: str, order: int = 8):
    K, f = {"vdp2": VDP2, "asym": ASYM}[name]
    return periodic_solution_ndof(EYE2, K, f, [q1, q2], [v1, v2], order)


@functools.cache
def _numeric(name: str, eps: float) -> dict:
    return _solution(name).validate(eps)


def _errors(name: str, eps: float, orders) -> list[float]:
    sol = _solution(name)
    ref = _numeric(name, eps)["exponents_numeric_real"]
    return [float(np.max(np.abs(np.sort(sol.characteristic_exponents(eps, k).real) - ref))) for k in orders]


def test_first_order_coefficients_equal_the_averaged_exponents():
    """Order-1 coefficients of the Rayleigh–Schrödinger/Liouville series = the averaged first-order exponents."""
    for name in ("vdp2", "asym"):
        sol = _solution(name)
        ser = sol.exponent_series(1)
        assert isinstance(ser, CharacteristicExponentSeries)
        first = np.array([[a, b] for a, b in sol.exponents])
        assert np.allclose(ser.coefficients, first, atol=1e-12)


def test_coupled_van_der_pol_error_falls_like_eps_to_the_order_plus_one():
    """Two coupled van der Pol oscillators, in-phase cycle (w = 1, sqrt 3): real parts of all four exponents vs the
    numeric monodromy at eps = 0.05, 0.1, 0.2.  The error at order N is O(eps^(N+1)); odd powers only appear in the
    critical exponent's even-order coefficients' absence, so orders 1, 3, 5, 7 are compared."""
    orders = (1, 3, 5, 7)
    table = {e: _errors("vdp2", e, orders) for e in (0.05, 0.1, 0.2)}
    for e, errs in table.items():
        assert all(b < a / 20 for a, b in itertools.pairwise(errs) if a > 1e-11), (e, errs)
    assert table[0.1][0] < 1e-4 and table[0.1][-1] < 1e-11
    # doubling eps multiplies the order-3 error by about 2^5 (order-4 coefficient of the real parts ~ 0)
    assert 12 < table[0.2][1] / table[0.1][1] < 80


def test_coupled_van_der_pol_multipliers():
    """The multipliers exp(mu T) of the order-8 series match the eigenvalues of the numeric monodromy matrix
    (imaginary parts included, so no branch choice is involved)."""
    sol = _solution("vdp2")
    r = _numeric("vdp2", 0.1)
    mult = np.exp(sol.characteristic_exponents(0.1, 8) * r["period_numeric"])
    assert max(min(abs(r["multipliers"] - x)) for x in mult) < 1e-9


def test_asymmetric_system_error_shrinks_with_order():
    """A cycle that leaves every invariant subspace (w = 1.0737, 1.4308; combination gaps 0.33): the exponent
    series has a small radius (about 0.3 by the root test), so the test uses eps = 0.05 and 0.1 where it converges."""
    e05 = _errors("asym", 0.05, range(0, 9))
    assert e05[-1] < 1e-8 and e05[-1] < 1e-5 * e05[1]
    assert all(e05[k + 2] < e05[k] for k in range(0, 7))
    e10 = _errors("asym", 0.1, (1, 4, 8))
    assert e10[2] < e10[1] < e10[0] and e10[2] < 1e-5


def test_one_degree_of_freedom_scaled_van_der_pol():
    """2 x'' + 8 x = eps (1 - x^2) x' (w = 2): the critical exponent against the numeric monodromy (orders 1, 3, 5;
    the van der Pol exponent has odd powers only), and the time-scaling law mu(eps) = 2 mu_vdP(eps/4) against the
    in-phase cycle of the coupled two-DOF system."""
    sol = periodic_solution_ndof([[2]], [[8]], [(1 - q1**2) * v1], [q1], [v1], 6)
    r = sol.validate(0.2)
    ref = r["exponents_numeric_real"]
    err = [np.max(np.abs(np.sort(sol.characteristic_exponents(0.2, k).real) - ref)) for k in (1, 3, 5)]
    assert err[2] < 1e-10 and err[1] < 1e-8 < err[0] < 1e-4
    ser = sol.exponent_series()
    vdp = _solution("vdp2").exponent_series(6).coefficients[1]
    for k in range(7):
        assert abs(ser.coefficients[1, k] - 2 * vdp[k] / 4**k) < 1e-13
    assert ser.order == 6 and np.all(ser.coefficients[0] == 0)
    assert ser.error_estimate(0.2).shape == (2,)
    assert "critical" in repr(ser)


def test_high_order_is_exact_to_rounding():
    """Extreme: order 16 for the coupled van der Pol system; at eps = 0.1 the sum agrees to ~1e-12 with the
    numeric exponents and the imaginary parts of the critical row vanish identically."""
    sol = _solution("vdp2", 16)
    ser = sol.exponent_series(16)
    assert np.max(np.abs(ser.coefficients[:2].imag)) < 1e-12
    ref = _numeric("vdp2", 0.1)["exponents_numeric_real"]
    assert np.max(np.abs(np.sort(ser.evaluate(0.1).real) - ref)) < 1e-11
    expr = ser.series(1, 8)
    assert expr.coeff(sol.eps_symbol, 1) == sp.Float(-1.0, 8)


def test_validate_with_exponent_order():
    r = _solution("vdp2").validate(0.1, exponent_order=7)
    assert np.max(np.abs(r["exponents_numeric_real"] - r["exponents_series_real"])) < 1e-10


def test_bad_input():
    sol = _solution("vdp2", 8)
    with pytest.raises(ParameterError, match="known to order 8"):
        sol.exponent_series(9)
    with pytest.raises(ParameterError, match="order must be"):
        sol.exponent_series(-1)
    with pytest.raises(ParameterError, match="known to order"):
        sol.exponent_series(3).evaluate(0.1, 4)
    # w = 1, 1.3, 1.7: w1 + w2 = 3 w0 is a combination resonance of the non-critical modes
    K3 = [[1, 0, 0], [0, R(169, 100), 0], [0, 0, R(289, 100)]]
    sol3 = periodic_solution_ndof(
        [[1, 0, 0], [0, 1, 0], [0, 0, 1]], K3, [(1 - q1**2) * v1, -v2, -v3], [q1, q2, q3], [v1, v2, v3], 2
    )
    with pytest.raises(ModelError, match="combination resonance"):
        sol3.exponent_series(2)
