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


def test_awkward_terms_are_split_like_a_full_expansion():
    """Products of sums, powers of sums and terms that cancel only after expansion: the parts must sum to K and
    the time factors be exactly those a hand expansion gives (a term-by-term expansion must not invent or lose any)."""
    from symosc.mechanics import LinearModel

    a, b, c, p = sp.symbols("a b c p", positive=True)
    x, y = sp.symbols("x y")
    cos, sin = sp.cos(p * t), sp.sin(2 * p * t)
    K = sp.Matrix(
        [
            [(a + cos) * b - b * cos, (a + b) ** 2 * cos + c * sin],  # (0, 0): the cosine cancels after expansion
            [a * (b + c * cos) + 3, sp.exp(p * t + a) + c**2 * (a * cos) ** 2],
        ]
    )
    zero = sp.zeros(2, 2)
    lin = LinearModel(sp.eye(2), zero, K, sp.zeros(2, 1), (x, y))
    parts = lin.stiffness_harmonics()
    assert set(parts) == {sp.S.One, cos, sin, cos**2, sp.exp(p * t)}
    assert sp.expand(parts[sp.S.One] - sp.Matrix([[a * b, 0], [a * b + 3, 0]])) == zero
    assert sp.expand(parts[cos] - sp.Matrix([[0, (a + b) ** 2], [a * c, 0]])) == zero
    assert parts[sp.exp(p * t)] == sp.Matrix([[0, 0], [0, sp.exp(a)]])
    total = sum((f * M for f, M in parts.items()), zero)
    assert sp.expand(total - K) == zero
    parts[cos][0, 0] = 99  # a copy: the model's own split is unchanged
    assert lin.stiffness_harmonics()[cos][0, 0] == 0


def test_long_chain_split_matches_the_closed_form():
    """30 links on a vertically vibrating pivot: K = K0 + cos(p t) K1 with K1 = -(a p²/g) K0 on the diagonal."""
    from symosc.models import n_link_pendulum_linearization

    lin = n_link_pendulum_linearization(30, pivot="vertical")
    K0, K1, p = lin.periodic_stiffness()
    a, g = sp.Symbol("a", nonnegative=True), sp.Symbol("g", positive=True)
    assert sp.expand(K0 + sp.cos(p * t) * K1 - lin.K) == sp.zeros(30, 30)
    assert sp.expand(K1 * g + a * p**2 * K0) == sp.zeros(30, 30)
