"""Presentation-ready equations: the short trigonometric forms by default, equal to the unsimplified ones, in LaTeX
and in generated code; the small parameter printed as epsilon."""

from __future__ import annotations

import itertools

import pytest
import sympy as sp

from symosc.algebra import trig_reduce
from symosc.mechanics import LagrangianSystem
from symosc.models import n_link_pendulum


def _has_pythagorean_pair(expr) -> bool:
    """True when some argument u has both sin(u)**2 and cos(u)**2 in the expanded expression."""
    terms = sp.Add.make_args(sp.expand(expr))
    sq = {(type(f.base), f.base.args[0]) for t in terms for f in sp.Mul.make_args(t) if f.is_Pow and f.exp == 2
          and isinstance(f.base, sp.sin | sp.cos)}  # fmt: skip
    return any((sp.sin, u) in sq and (sp.cos, u) in sq for _, u in sq)


@pytest.mark.parametrize(("n", "links"), [(1, "point"), (2, "point"), (3, "point"), (1, "rigid"), (2, "rigid")])
def test_chain_equations_hold_no_sin2_cos2_pair_and_equal_the_raw_ones(n, links):
    """n = 1..3: no sin^2 + cos^2 pair left in M or F; the same equations as without simplification (difference
    reduced to zero by SymPy's trigsimp, an independent simplifier)."""
    s = n_link_pendulum(n, links=links, inverted=links == "rigid", pivot="vertical" if links == "rigid" else "fixed")
    raw = LagrangianSystem(s.kinetic_energy, s.potential_energy, s.coordinates, simplify=False)
    for a, b in itertools.chain(
        zip(s.mass_matrix, raw.mass_matrix, strict=True), zip(s.forcing, raw.forcing, strict=True)
    ):
        assert not _has_pythagorean_pair(a)
        assert sp.trigsimp(sp.expand(a - b)) == 0
    assert any(_has_pythagorean_pair(e) for e in raw.mass_matrix)  # the check can fail: the raw form has them


def test_double_pendulum_textbook_form():
    """M12 = l1 l2 m2 cos(phi1 - phi2), F1 = -g l1 (m1 + m2) sin phi1 - l1 l2 m2 phi2'^2 sin(phi1 - phi2)."""
    s = n_link_pendulum(2)
    phi1, phi2 = s.coordinates
    m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g", positive=True)
    w2 = s.velocities[1]
    assert s.mass_matrix[0, 1] == l1 * l2 * m2 * sp.cos(phi1 - phi2)
    assert s.mass_matrix[0, 0] == l1**2 * (m1 + m2)
    assert (
        sp.expand(s.forcing[0] - (-g * l1 * (m1 + m2) * sp.sin(phi1) - l1 * l2 * m2 * w2**2 * sp.sin(phi1 - phi2))) == 0
    )
    assert len(sp.Add.make_args(s.forcing[0])) == 2


def test_trig_reduce_identities_against_numbers():
    x, y, z, c = sp.symbols("x y z c")
    cases = [
        c * sp.sin(x) ** 2 + c * sp.cos(x) ** 2,
        3 * sp.sin(x) * sp.sin(y) + 3 * sp.cos(x) * sp.cos(y) + sp.sin(z),
        sp.sin(x) * sp.cos(y) - sp.cos(x) * sp.sin(y),
        sp.sin(x) ** 2 * sp.sin(y) ** 2 + sp.sin(x) ** 2 * sp.cos(y) ** 2 + sp.cos(x) ** 2,
    ]
    expected = [c, 3 * sp.cos(x - y) + sp.sin(z), sp.sin(x - y), 1]
    for e, want in zip(cases, expected, strict=True):
        got = trig_reduce(e)
        assert sp.simplify(got - want) == 0
        assert sp.count_ops(got) <= sp.count_ops(want)
    # unequal coefficients are left alone
    assert trig_reduce(2 * sp.sin(x) ** 2 + sp.cos(x) ** 2) == 2 * sp.sin(x) ** 2 + sp.cos(x) ** 2


def test_generated_code_and_latex_use_the_short_forms():
    from symosc.codegen import export

    s = n_link_pendulum(2)
    c_source = export(s.first_order(), "c", name="pend")
    assert "cos(phi1 - phi2)" in c_source and "pow(sin(phi1), 2)" not in c_source
    tex = s.latex()
    assert r"\cos{\left(\phi_{1} - \phi_{2} \right)}" in tex and r"\sin^{2}" not in tex


def test_small_parameter_prints_as_varepsilon():
    from symosc.nonlinear import limit_cycle

    x, v = sp.symbols("x v")
    series = limit_cycle((1 - x**2) * v, 2).frequency
    assert r"\varepsilon^{2}" in sp.latex(series) and "eps" not in sp.latex(series).replace("varepsilon", "")
    assert r"\varepsilon" in series._repr_latex_()
