"""S and T parameters of four-poles and the scikit-rf bridge, against scikit-rf's own conversions and closed forms
(Pozar, Microwave Engineering, 4th ed. (2012), Table 4.2 and Example 4.4)."""

from __future__ import annotations

import numpy as np
import pytest
import skrf
import sympy as sp

from symosc.errors import ModelError, ParameterError
from symosc.networks import (
    cascade,
    convert_parameters,
    series_element,
    shunt_element,
    skrf_parameters,
    t_section,
)

p = sp.Symbol("p")  # the operator variable of symosc.networks

F = np.array([1e3, 3.3e5, 2e6, 7.1e7])


def _network():
    """A lossy T section (input arm, shunt, output arm): series R + L arms, shunt C (numbers in SI)."""
    return t_section(3 + p * sp.Rational(1, 10**5), 1 / (p * sp.Rational(1, 10**9)), 5 + p * sp.Rational(2, 10**5))


def test_series_impedance_closed_form():
    """Pozar, Table 4.2: a series impedance Z has S11 = Z/(Z + 2 Z0), S21 = 2 Z0/(Z + 2 Z0)."""
    Z, Z0 = sp.symbols("Z Z0", positive=True)
    S = series_element(Z).s_parameters(Z0)
    assert sp.simplify(S - sp.Matrix([[Z, 2 * Z0], [2 * Z0, Z]]) / (Z + 2 * Z0)) == sp.zeros(2, 2)
    Y = sp.Symbol("Y", positive=True)
    S = shunt_element(1 / Y).s_parameters(Z0)
    assert sp.simplify(S[0, 0] + Y * Z0 / (2 + Y * Z0)) == 0 and sp.simplify(S[1, 0] - 2 / (2 + Y * Z0)) == 0


@pytest.mark.parametrize("z0", [50, (50, 75), (10, 300)])
def test_to_skrf_matches_scikit_rf_conversions(z0):
    fp = _network()
    net = fp.to_skrf(F, z0=z0)
    chain_of, z_of = (sp.lambdify(p, m, "numpy") for m in (fp.chain, fp.parameters("Z", "ieee")))
    abcd = np.array([np.array(chain_of(2j * np.pi * f), dtype=complex) for f in F])
    zref = np.broadcast_to(np.asarray(z0, dtype=float), (2,))
    z_ieee = np.array([np.array(z_of(2j * np.pi * f), dtype=complex) for f in F])
    np.testing.assert_allclose(net.s, skrf.network.z2s(z_ieee, zref), rtol=1e-10, atol=1e-13)
    if np.ndim(z0) == 0:
        np.testing.assert_allclose(net.s, skrf.network.a2s(abcd, z0), rtol=1e-10, atol=1e-13)
    np.testing.assert_allclose(skrf_parameters(net, "T"), skrf.network.s2t(net.s), rtol=1e-10, atol=1e-13)
    np.testing.assert_allclose(skrf_parameters(net, "A"), abcd, rtol=1e-9)
    for kind, theirs in (("Z", net.z), ("Y", net.y)):  # per frequency, to the size of the matrix
        scale = np.abs(theirs).max(axis=(1, 2), keepdims=True)
        np.testing.assert_allclose(skrf_parameters(net, kind, "ieee") / scale, theirs / scale, atol=1e-9)


def _zero(M) -> bool:
    return all(sp.cancel(sp.radsimp(x)) == 0 for x in M)


def test_exact_round_trips_and_cascade_of_t_parameters():
    Z0 = sp.Symbol("Z0", positive=True)
    a, b = series_element(p + 2), shunt_element(3 / p)
    whole = cascade(a, b)
    assert _zero(convert_parameters(whole.s_parameters(Z0), "S", "A", z0=Z0) - whole.chain)
    T = a.t_parameters(Z0) * b.t_parameters(Z0)
    assert _zero(T - whole.t_parameters(Z0))
    assert _zero(convert_parameters(whole.t_parameters((8, 2)), "T", "S", z0=(8, 2)) - whole.s_parameters((8, 2)))


def test_lossless_network_has_unitary_s_matrix():
    fp = t_section(p * sp.Rational(1, 10**4), 1 / (p * sp.Rational(2, 10**8)), p * sp.Rational(3, 10**4))
    S_of = sp.lambdify(p, fp.s_parameters(50), "numpy")
    for f in (1e3, 5e4, 1e6):
        S = np.array(S_of(2j * np.pi * f), dtype=complex)
        np.testing.assert_allclose(S.conj().T @ S, np.eye(2), atol=1e-12)


def test_errors():
    with pytest.raises(ParameterError, match="real and positive"):
        series_element(1).s_parameters(-50)
    with pytest.raises(ParameterError, match="free symbols"):
        series_element(sp.Symbol("R")).to_skrf(F)
    with pytest.raises(ModelError, match="S21 = 0"):
        convert_parameters([[0, 0], [0, 0]], "S", "A")
