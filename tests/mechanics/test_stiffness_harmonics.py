"""``LinearModel.stiffness_harmonics`` splits K(t) into time factors, with no spurious entries."""

from __future__ import annotations

import sympy as sp

from symosc.models import n_link_pendulum
from symosc.symbols import t


def test_zero_entries_add_no_harmonic_and_the_parts_sum_to_k():
    # the 2-link inverted pendulum on a vertically vibrating pivot has K = K0 + K1 cos(p t) with zero off-diagonal
    # entries; they used to add a key 0 (a "harmonic" 0 with a zero matrix) to the result
    lin = n_link_pendulum(2, links="rigid", inverted=True, pivot="vertical").linearize()
    parts = lin.stiffness_harmonics()
    p = sp.Symbol("p", positive=True)
    assert set(parts) == {sp.S.One, sp.cos(p * t)}
    total = sum((f * K for f, K in parts.items()), sp.zeros(2, 2))
    assert sp.simplify(total - lin.K) == sp.zeros(2, 2)
    # independent reference for the time-varying part: dK/dt = -p sin(p t) K1
    assert sp.simplify(lin.K.diff(t) + p * sp.sin(p * t) * parts[sp.cos(p * t)]) == sp.zeros(2, 2)


def test_constant_stiffness_has_only_the_constant_part():
    lin = n_link_pendulum(2).linearize()
    assert list(lin.stiffness_harmonics()) == [sp.S.One]
