"""Junction voltages and currents of a cascade with equal iterative impedances, Bulgakov (1954), §8.46, (8.427).

Reference: the terminated cascade solved directly in 40-digit mpmath — input current from the input impedance of
the whole chain, then each junction from the previous one by the inverse chain matrix of the link between them —
without iterative parameters or hyperbolic functions.
"""

from __future__ import annotations

import mpmath
import pytest
import sympy as sp

from symosc.errors import ParameterError
from symosc.networks import (
    cascade_junctions,
    correcting_link,
    l_section,
    link_transfer,
    series_element,
    t_section,
)

p = sp.Symbol("p")


def direct(sections, E, Zr, ZH, at):
    """[(E_j, I_j)] for j = 0..n by chain matrices only."""
    mats = [fp.evaluate(at) for fp in sections]
    total = mpmath.eye(2)
    for M in mats:
        total = total * M
    z_in = (total[0, 0] * ZH + total[0, 1]) / (total[1, 0] * ZH + total[1, 1])
    Ix = E / (Zr + z_in)
    state = mpmath.matrix([E - Zr * Ix, Ix])
    out = [state]
    for M in mats:
        state = mpmath.inverse(M) * state
        out.append(state)
    return out


def assert_close(result, reference):
    tol = mpmath.mpf(10) ** -25
    for j, ref in enumerate(reference):
        scale = 1 + abs(ref[0]) + abs(ref[1])
        assert abs(result.E[j] - ref[0]) < tol * scale, j
        assert abs(result.I[j] - ref[1]) < tol * scale, j


@pytest.mark.parametrize("at", [mpmath.mpc(0.3, 1.7), mpmath.mpc(0, 0.8), mpmath.mpf(2)])
def test_identical_asymmetric_sections(at):
    """Four identical L sections (Z' != Z''), mismatched complex terminations, complex p."""
    with mpmath.workdps(40):
        section = l_section(p + 2, 3 / p + 1, shunt_first=True)
        sections = [section] * 4
        E, Zr, ZH = mpmath.mpc(2, -1), mpmath.mpc(5, 1), mpmath.mpc(0.5, 2)
        result = cascade_junctions(sections, E, Zr, ZH, at)
        assert abs(result.Z1 - result.Z2) > 0.1  # really asymmetric
        assert_close(result, direct(sections, E, Zr, ZH, at))
        assert abs(result.E[-1] - ZH * result.I[-1]) < mpmath.mpf(10) ** -30


def test_different_links_with_common_iterative_impedance():
    """Constant-resistance links (Z' = Z'' = W) of different kinds: only W is shared, s_k differ."""
    with mpmath.workdps(40):
        W = 2
        sections = [
            correcting_link(link_transfer("lag", T1=1, T2=4, k=2), W=W).four_pole,
            correcting_link(link_transfer("lead", T1=3, T2=1), W=W).four_pole,
            correcting_link(link_transfer("attenuator", k=5), W=W).four_pole,
        ]
        at = mpmath.mpc(0, 0.7)
        result = cascade_junctions(sections, 1, 3, 1, at)
        assert abs(result.Z1 - W) < 1e-30 and abs(result.Z2 - W) < 1e-30
        assert_close(result, direct(sections, 1, 3, 1, at))


def test_symbolic_terminations_in_p():
    """Zr and ZH may be expressions in p; a T-section chain with a reactive load."""
    with mpmath.workdps(40):
        sections = [t_section(1, p + 1, 2)] * 3
        at = mpmath.mpc(0.2, 1.1)
        result = cascade_junctions(sections, 1, 1 + p, 1 / p, at)
        assert_close(result, direct(sections, 1, 1 + at, 1 / at, at))


def test_unequal_iterative_impedances_are_refused():
    with pytest.raises(ParameterError, match="iterative impedances"):
        cascade_junctions([t_section(1, 2, 1), t_section(1, 3, 1)], 1, 1, 1, 1j)
    with pytest.raises(ParameterError, match="non-empty"):
        cascade_junctions([], 1, 1, 1, 1j)
    with pytest.raises(ParameterError, match="FourPole"):
        cascade_junctions([series_element(1), "x"], 1, 1, 1, 1j)
