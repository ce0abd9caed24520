"""Energy functions and Foster's reactance theorem (Bulgakov (1954), §9.19–9.21, eqs. (9.223)–(9.255)).

References: the driving-point impedance by element-level nodal analysis (test helper) and by series/parallel
reduction of the one-port, at random complex p in exact rational arithmetic; the derivative of the reactance
by SymPy differentiation of that impedance; Foster's partial-fraction form for random lossless networks.
"""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from symosc.errors import ModelError, ParameterError
from symosc.networks import (
    BruneSection,
    Capacitor,
    Impedance,
    Inductor,
    Parallel,
    Resistor,
    Series,
    check_reactance_theorem,
    energy_functions,
    is_reactance_function,
)

from ._element_nodal import driving_point_impedance, flatten

p = sp.Symbol("p")
pos = st.fractions(min_value=sp.Rational(1, 5), max_value=5, max_denominator=7).map(lambda f: sp.Rational(f))
SETTINGS = settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def networks(kinds=(Resistor, Inductor, Capacitor), depth: int = 3):
    leaf = st.builds(lambda cls, v: cls(v), st.sampled_from(kinds), pos)
    return st.recursive(
        leaf,
        lambda children: st.one_of(
            st.lists(children, min_size=2, max_size=3).map(lambda xs: Series(tuple(xs))),
            st.lists(children, min_size=2, max_size=3).map(lambda xs: Parallel(tuple(xs))),
        ),
        max_leaves=6,
    )


complex_points = st.tuples(
    st.integers(min_value=-5, max_value=5), st.integers(min_value=1, max_value=6), st.integers(min_value=1, max_value=6)
).map(lambda t: sp.Rational(t[0], 3) + sp.I * sp.Rational(t[1], t[2]))


def nodal_impedance(net) -> sp.Expr:
    return driving_point_impedance(flatten(net, "a", "b", [], p), "a", "b")


@SETTINGS
@given(networks(), complex_points)
def test_impedance_from_energy_functions_matches_nodal_analysis(net, at):
    """Z(p)|I1|² = F0 + p T0 + V0/p (Brune; §9.21) at a random complex p, exactly; the forms are >= 0."""
    ef = energy_functions(net)
    values = ef.evaluate(at)
    Z = nodal_impedance(net)
    assert sp.cancel(Z - net.impedance(p)) == 0  # two independent references agree
    assert sp.expand(values.impedance - Z.subs(p, at)) == 0
    for form in (values.F0, values.T0, values.V0):
        assert form.is_real and form >= 0
    assert sp.cancel(ef.impedance() - Z) == 0


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(kinds=(Inductor, Capacitor)), st.integers(min_value=1, max_value=12))
def test_reactance_slope_equals_energy_sum(net, n):
    """Foster, eq. (9.250): dX/dω = (T0 + V0/ω²)/|I1|² for a lossless one-port at p = iω."""
    omega = sp.Rational(n, 5)
    Z = nodal_impedance(net)
    w = sp.Symbol("w", positive=True)
    X = sp.cancel(-sp.I * Z.subs(p, sp.I * w))
    slope = sp.diff(X, w).subs(w, omega)
    if not sp.fraction(sp.cancel(Z))[1].subs(p, sp.I * omega) or not Z.subs(p, sp.I * omega).is_finite:
        return  # a pole of Z at this frequency
    try:
        values = energy_functions(net).evaluate(sp.I * omega)
    except ModelError:
        return  # a resonance of a loop at exactly this frequency
    assert values.F0 == 0
    assert sp.simplify(values.reactance_slope() - slope) == 0


def test_bridge_network_by_branch_list():
    """A non-series-parallel bridge (branch list) against nodal analysis."""
    branches = [
        ("a", "c", Resistor(1)),
        ("a", "d", Inductor(2)),
        ("c", "b", Capacitor(3)),
        ("d", "b", Resistor(4)),
        ("c", "d", Inductor(5) + Resistor(1)),
    ]
    ef = energy_functions(branches, terminals=("a", "b"))
    flat: list = []
    for a, b, element in branches:
        flatten(element, a, b, flat, p)
    Z = driving_point_impedance(flat, "a", "b")
    assert sp.cancel(ef.impedance() - Z) == 0
    at = sp.Rational(2, 3) + sp.I
    values = ef.evaluate(at)
    assert sp.expand(values.impedance - Z.subs(p, at)) == 0
    assert ef.R.is_symmetric() and ef.L.is_symmetric() and ef.S.is_symmetric()


def test_brune_section_coupled_coils():
    """Perfectly coupled coils (M² = Lp Ls) enter T0 through the mutual terms: compare with its impedance."""
    net = BruneSection(1, 4, 2, 1, load=Resistor(2) + Capacitor(3))
    ef = energy_functions(net)
    assert sp.cancel(ef.impedance() - net.impedance(p)) == 0
    values = ef.evaluate(1 + 2 * sp.I)
    assert sp.expand(values.impedance - net.impedance(p).subs(p, 1 + 2 * sp.I)) == 0
    assert values.T0 >= 0  # the inductance matrix is only semidefinite (unit coupling)


def test_series_rlc_forms_by_hand():
    """A series R, L, C: one loop, F0 = R, T0 = L, V0 = 1/C for I1 = 1."""
    ef = energy_functions(Resistor(2) + Inductor(3) + Capacitor(sp.Rational(1, 5)))
    assert (ef.R, ef.L, ef.S) == (sp.Matrix([[2]]), sp.Matrix([[3]]), sp.Matrix([[5]]))
    I1 = ef.currents[0]
    assert ef.T0 == 3 * I1 * sp.conjugate(I1)


@st.composite
def foster_networks(draw, negative: bool = False):
    """Foster I form: series L, series C and parallel LC tanks; with ``negative`` one tank has a negative residue."""
    n = draw(st.integers(min_value=1, max_value=3))
    w2 = sorted(set(draw(st.lists(pos, min_size=n, max_size=n))))
    ks = [draw(pos) for _ in w2]
    Z = draw(pos) * p + draw(pos) / p + sum((2 * k * p / (p**2 + w) for k, w in zip(ks, w2, strict=True)), 0)
    if negative:
        Z -= 2 * (sum(ks) + 1) * p / (p**2 + w2[0])  # the first residue becomes negative
    return sp.cancel(Z)


@SETTINGS
@given(foster_networks())
def test_reactance_theorem_holds_for_random_foster_networks(Z):
    check = check_reactance_theorem(Z, p)
    assert bool(check)
    assert is_reactance_function(Z, p)  # the interlacing test of the synthesis module agrees


@SETTINGS
@given(foster_networks(negative=True))
def test_reactance_theorem_fails_with_a_negative_residue(Z):
    """A tank with negative residue: X falls near that pole, and the check says so."""
    check = check_reactance_theorem(Z, p)
    assert check.lossless and not check.increasing
    assert not bool(check)


def test_reactance_theorem_on_lossy_and_simple_cases():
    assert not check_reactance_theorem(Resistor(1) + Inductor(1)).lossless
    assert not bool(check_reactance_theorem(p - 1 / p, p))
    assert not bool(check_reactance_theorem(-p, p))
    check = check_reactance_theorem((p**2 + 1) * (p**2 + 9) / (p * (p**2 + 4)), p)
    assert bool(check)
    w = check.omega
    # Z(iω) = (1-ω²)(9-ω²)/(iω(4-ω²)), so X = (ω²-1)(ω²-9)/(ω(ω²-4)) by hand (the form (9.255), h = 1)
    X = (w**2 - 1) * (w**2 - 9) / (w * (w**2 - 4))
    assert sp.cancel(check.reactance - X) == 0
    assert sp.cancel(check.slope - sp.diff(X, w)) == 0


def test_bad_input():
    with pytest.raises(ParameterError, match="R, L, C"):
        energy_functions(Impedance(p + 1))
    with pytest.raises(ParameterError, match="terminals"):
        energy_functions([("a", "b", Resistor(1))])
    with pytest.raises(ParameterError, match="branch"):
        energy_functions([("a", "b", 5)], terminals=("a", "b"))
    with pytest.raises(ModelError, match="open"):
        energy_functions([("a", "c", Resistor(1)), ("d", "b", Resistor(1))], terminals=("a", "b"))
    with pytest.raises(ParameterError, match="at"):
        energy_functions(Resistor(1)).evaluate(0)
    with pytest.raises(ParameterError, match="numeric"):
        check_reactance_theorem(sp.Symbol("L") * p, p)
    with pytest.raises(ParameterError, match="imaginary axis"):
        energy_functions(Inductor(1)).evaluate(1).reactance_slope()
