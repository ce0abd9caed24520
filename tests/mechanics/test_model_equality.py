"""Equality and hashing of models: the same equations compare equal whatever the written form."""

from __future__ import annotations

import pickle

import sympy as sp

from symosc.mechanics import LagrangianSystem
from symosc.models import body_on_springs, n_link_pendulum
from symosc.symbols import dot

x, phi = sp.symbols("x phi", real=True)
m, l, k, g = sp.symbols("m l k g", positive=True)


def _slider(expanded: bool, spring=k):
    """Pendulum on a spring-mounted slider; T written factored or expanded."""
    T = m / 2 * ((dot(x) + l * sp.cos(phi) * dot(phi)) ** 2 + (l * sp.sin(phi) * dot(phi)) ** 2)
    V = spring * x**2 / 2 - m * g * l * sp.cos(phi)
    return LagrangianSystem(sp.expand(T) if expanded else T, V, [x, phi])


def test_equal_systems_whatever_the_form_and_hash_alike():
    a, b = _slider(False), _slider(True)
    assert a == b and hash(a) == hash(b) and len({a, b}) == 1
    assert a != _slider(False, spring=2 * k)  # another stiffness
    assert a != LagrangianSystem(a.kinetic_energy, a.potential_energy, [phi, x])  # other coordinate order
    assert pickle.loads(pickle.dumps(a)) == a


def test_derived_models_compare_by_their_data():
    a, b = n_link_pendulum(2), n_link_pendulum(2)
    assert a == b and a.linearize() == b.linearize() and hash(a.linearize()) == hash(b.linearize())
    assert a.linearize() != n_link_pendulum(2, inverted=True).linearize()
    assert a.first_order() == b.first_order() and a != n_link_pendulum(2, links="rigid")
    assert n_link_pendulum(1).hamiltonian() == n_link_pendulum(1).hamiltonian()
    assert body_on_springs(4) == body_on_springs(4) and body_on_springs(4) != body_on_springs(3)
