"""Impedance of one-port trees (Bulgakov (1954), §8.31): exact, in SymPy's ``cancel`` normal form, whatever the
element values (rational ones take the polynomial route over QQ, others SymPy's ``cancel`` level by level)."""

from __future__ import annotations

import random

import sympy as sp

from symosc.networks import BruneSection, Capacitor, Inductor, Resistor

from ._element_nodal import driving_point_impedance, flatten

p = sp.Symbol("p")


def _random_tree(rng: random.Random, values):
    """A random series/parallel tree of 2-7 elements, sometimes closed by a Brune section, values from ``values``."""
    leaves = [rng.choice([Inductor, Capacitor, Resistor])(values()) for _ in range(rng.randint(2, 7))]
    while len(leaves) > 1:
        a, b = (leaves.pop(rng.randrange(len(leaves))) for _ in range(2))
        leaves.append(a + b if rng.random() < 0.5 else a | b)
    net = leaves[0]
    if rng.random() < 0.4:  # unit coupling: Lp = k a², Ls = k b², M = k a b
        k, a, b = values(), *rng.sample(range(1, 6), 2)  # a != b: no zero arm in the T equivalent
        net = Resistor(values()) + BruneSection(k * a**2, k * b**2, k * a * b, values(), load=net)
    return net


def _rational_value(rng):
    return lambda: sp.Rational(rng.randint(1, 40), rng.randint(1, 9))


def test_rational_trees_agree_with_nodal_analysis_in_cancel_form():
    """Twenty random trees with rational values, some closed by a Brune section: the impedance equals the
    driving-point impedance from Kirchhoff's current law at element level (an independent linear solve), exactly,
    and is already in SymPy's ``cancel`` normal form."""
    rng = random.Random(11)
    for _ in range(20):
        net = _random_tree(rng, _rational_value(rng))
        Z = net.impedance(p)
        reference = driving_point_impedance(flatten(net, "a", "b", [], p), "a", "b")
        assert sp.cancel(Z - reference) == 0
        assert sp.cancel(Z) == Z


def test_symbolic_and_radical_values_take_sympy_route_with_the_same_result():
    """A tree mixing a symbol, a square root and rationals: the impedance is the nodal-analysis one, in
    ``cancel`` form."""
    R = sp.Symbol("R", positive=True)
    net = (Resistor(R) + Inductor(sp.sqrt(2))) | (Capacitor(sp.Rational(1, 3)) + Resistor(2))
    Z = net.impedance(p)
    reference = driving_point_impedance(flatten(net, "a", "b", [], p), "a", "b")
    assert sp.cancel(sp.radsimp(Z - reference)) == 0
    assert sp.cancel(Z) == Z


def test_rational_values_are_exact_for_wide_magnitudes():
    """Values from 1e-30 to 1e30 (exact rationals): the polynomial route keeps every digit (the nodal reference
    agrees exactly)."""
    tiny, huge = sp.Rational(1, 10**30), sp.Integer(10) ** 30
    net = (Inductor(tiny) | Capacitor(huge)) + (Resistor(huge) | Inductor(3) | Capacitor(tiny)) + Resistor(tiny)
    reference = driving_point_impedance(flatten(net, "a", "b", [], p), "a", "b")
    assert sp.cancel(net.impedance(p) - reference) == 0
