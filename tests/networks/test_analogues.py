"""Mechanical <-> electrical analogues: the driving-point impedance of a two-mass chain from its equations of motion."""

from __future__ import annotations

import pytest
import sympy as sp

from symosc.errors import ParameterError
from symosc.networks import Damper, Mass, Spring, chain_driving_point, to_electrical, to_mechanical

p = sp.Symbol("p")


def test_two_mass_chain_both_analogies():
    m1, m2, k1, k2, c1, c2 = sp.symbols("m1 m2 k1 k2 c1 c2", positive=True)
    x1, x2, F = sp.symbols("x1 x2 F")
    eqs = [
        m1 * p**2 * x1 + (k1 + c1 * p) * x1 - (k2 + c2 * p) * (x2 - x1),
        m2 * p**2 * x2 + (k2 + c2 * p) * (x2 - x1) - F,
    ]
    sol = sp.solve(eqs, [x1, x2])
    Z_ref = sp.cancel(F / (p * sol[x2]))
    mech = chain_driving_point([m1, m2], [k1, k2], [c1, c2])
    assert sp.cancel(mech.mechanical_impedance(p) - Z_ref) == 0
    fv = to_electrical(mech, "force-voltage")
    fc = to_electrical(mech, "force-current")
    assert sp.cancel(fv.impedance(p) - Z_ref) == 0
    assert sp.cancel(fc.admittance(p) - Z_ref) == 0
    for analogy, net in (("force-voltage", fv), ("force-current", fc)):
        back = to_mechanical(net, analogy)
        assert sp.cancel(back.mechanical_impedance(p) - Z_ref) == 0


def test_bad_input():
    with pytest.raises(ParameterError, match="positive"):
        Mass(-1)
    with pytest.raises(ParameterError, match="analogy"):
        to_electrical(Spring(1) | Damper(2), "force-speed")
    with pytest.raises(ParameterError, match="same length"):
        chain_driving_point([1, 2], [1])


def test_results_pickle_and_print():
    """Result objects are picklable and print through SymPy's printers."""
    import pickle

    from symosc.networks import Absorber, Capacitor, Inductor, Resistor, brune_synthesis, t_section

    net = brune_synthesis((p**2 + p + 1) / (p**2 + p + 4), p)
    for obj in (net, t_section(1, p, 2), Absorber(0.1, 0.9, 0.1), Resistor(1) + (Inductor(2) | Capacitor(3))):
        assert pickle.loads(pickle.dumps(obj)) == obj
    assert sp.sstr(t_section(1, p, 2)).startswith("FourPole(")
    assert sp.latex(Resistor(1) + Inductor(2)) == sp.latex(2 * p + 1)
    assert sp.latex(t_section(1, p, 2)).startswith(r"\mathbf{A} = ")
