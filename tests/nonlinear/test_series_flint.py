"""Exact series products: FLINT's integer polynomials and the pure NumPy fallback give the same fractions.

Independent reference: the van der Pol limit-cycle amplitude 2 + eps^2/96 - 1033 eps^4/552960
+ 1019689 eps^6/55738368000 + ... (Andersen & Geer 1982, Table 1).
"""

from __future__ import annotations

from fractions import Fraction as R

import pytest
import sympy as sp

from symosc.nonlinear import _fourier, limit_cycle

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
