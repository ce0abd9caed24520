"""SPICE-like netlists: values, directives, nodal solutions and four-poles against closed forms and the section
library (Bulgakov (1954), §8.36, §8.40)."""

from __future__ import annotations

import pytest
import sympy as sp

from symosc.errors import ModelError, ParameterError
from symosc.networks import Circuit, parse_netlist, twin_t_section

p = sp.Symbol("p")


@pytest.mark.parametrize(
    "token, value",
    [
        ("4.7k", sp.Rational(4700)),
        ("10uF", sp.Rational(1, 10**5)),
        ("10µ", sp.Rational(1, 10**5)),
        ("1meg", sp.Integer(10**6)),
        ("1MEGohm", sp.Integer(10**6)),
        ("2.2n", sp.Rational(22, 10**10)),
        ("1m", sp.Rational(1, 1000)),
        ("3F", sp.Rational(3, 10**15)),  # SPICE: F is femto
        ("100mil", sp.Rational(254, 10**5)),
        ("1e3", sp.Integer(1000)),
        (".5", sp.Rational(1, 2)),
        ("2.5e-3k", sp.Rational(5, 2)),
        ("1e300", sp.Integer(10) ** 300),
        ("47ohm", sp.Integer(47)),
    ],
)
def test_values_are_exact(token, value):
    circuit = parse_netlist(f"R1 a 0 {token}\nP1 a 0")
    assert circuit.elements[0].value == value


def test_rc_low_pass_node_voltage_and_impedance():
    """V(out)/V(in) = 1/(1 + p R C); Z seen from the source side = R + 1/(p C)."""
    circuit = parse_netlist(
        """
        .title RC low-pass  ; a comment
        * full-line comment
        .param R=1k
        V1 in 0 AC 1
        R1 in out {R}
        C1 out
        + 0 C
        P1 in 0
        .end
        R9 x y 1
        """
    )
    assert isinstance(circuit, Circuit) and circuit.title == "RC low-pass" and len(circuit.elements) == 4
    C = sp.Symbol("C", positive=True)
    assert sp.simplify(circuit.node_voltages()["out"] - 1 / (1 + 1000 * p * C)) == 0
    assert sp.simplify(circuit.impedance(0) - (1000 + 1 / (p * C))) == 0
    assert circuit.parameters == {"R": 1000}


def test_current_source_sign_convention():
    """SPICE: I1 n+ n- pushes its current from n+ through the source to n-, i.e. into node n-."""
    circuit = parse_netlist("I1 0 a 2m\nR1 a 0 1k")
    assert circuit.node_voltages()["a"] == 2


def test_four_pole_of_a_t_section_closed_form_and_shorted_source():
    """T section Z1, Z2 arms, shunt Z3: A = [[1 + Z1/Z3, Z1 + Z2 + Z1 Z2/Z3], [1/Z3, 1 + Z2/Z3]] (eq. (8.408)).
    The voltage source in series with the input is shorted when the four-pole is formed."""
    circuit = parse_netlist(
        """
        P1 in 0
        V1 in a 5
        R1 a m 2
        L1 m out 3
        C1 m 0 1/4
        P2 out 0
        """.replace("1/4", "0.25")
    )
    Z1, Z2, Z3 = 2, 3 * p, 4 / p
    want = sp.Matrix([[1 + Z1 / Z3, Z1 + Z2 + Z1 * Z2 / Z3], [1 / Z3, 1 + Z2 / Z3]])
    fp = circuit.four_pole()
    assert (fp.chain - want).applyfunc(sp.cancel) == sp.zeros(2, 2)
    assert fp.netlist is not None  # Brune-testable in parallel/series connections


def test_twin_t_against_the_section_library():
    """Twin T: R-R arms with a shunt 2C, C-C arms with a shunt R/2, in parallel (Bulgakov (1954), eq. (8.423));
    R = 2, C = 1/2."""
    circuit = parse_netlist(
        """
        P1 in 0
        R1 in a 2
        R2 a out 2
        C3 a 0 1
        C1 in b 0.5
        C2 b out 0.5
        R3 b 0 1
        P2 out 0
        """
    ).four_pole()
    R, C = sp.Integer(2), sp.Rational(1, 2)
    # each T as (input arm, shunt, output arm), eq. (8.408)
    want = twin_t_section((R, 1 / (p * 2 * C), R), (1 / (p * C), R / 2, 1 / (p * C))).chain
    assert (circuit.chain - want).applyfunc(sp.cancel) == sp.zeros(2, 2)


def test_coupled_inductors():
    """L1 = 2, L2 = 8, k = 1/2 (M = 2) loaded by R = 5: chain of the coils then the shunt resistor."""
    fp = parse_netlist("P1 a 0\nL1 a 0 2\nL2 b 0 8\nK1 L1 L2 0.5\nR1 b 0 5\nP2 b 0").four_pole()
    coils = sp.Matrix([[1, 6 * p], [1 / (2 * p), 4]])  # Z = p [[2, 2], [2, 8]]: A = [[Z11, det], [1, Z22]] / Z21
    assert (fp.chain - coils * sp.Matrix([[1, 0], [sp.Rational(1, 5), 1]])).applyfunc(sp.cancel) == sp.zeros(2, 2)
    with pytest.raises(ModelError, match="k = 1"):
        parse_netlist("P1 a 0\nL1 a 0 2\nL2 b 0 8\nK1 L1 L2 1\nP2 b 0").four_pole()


@pytest.mark.parametrize(
    "text, match",
    [
        ("R1 a 0 -5", "positive"),
        ("R1 a a 5", "itself"),
        ("R1 a 0 5\nR1 b 0 5", "used twice"),
        ("Q1 a b c model", "only R, L, C"),
        ("R1 a 0", "takes 4"),
        ("K1 L1 L2 0.5", "not inductors"),
        ("L1 a 0 1\nL2 b 0 1\nK1 L1 L2 1.5", r"\(0, 1\]"),
        ("V1 a 0 SIN 1", "DC or AC"),
        ("R1 a 0 p", "operator variable"),
        ("+ R1 a 0 1", "continuation"),
    ],
)
def test_malformed_lines_are_refused_with_their_reason(text, match):
    with pytest.raises(ParameterError, match=match):
        parse_netlist(text)


def test_ports_are_required_where_used():
    circuit = parse_netlist("R1 a 0 1\nP1 a 0")
    with pytest.raises(ModelError, match="two ports"):
        circuit.four_pole()
    with pytest.raises(ParameterError, match="port must be"):
        circuit.impedance(3)
    with pytest.raises(ModelError, match="floating"):
        parse_netlist("R1 a b 1\nR2 c d 1\nP1 a c").impedance()
