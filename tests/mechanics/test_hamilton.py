"""Hamiltonian systems and canonical transformations against closed forms (Goldstein, Landau & Lifshitz)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from symosc import ModelError, dot, t
from symosc.mechanics import (
    HamiltonianSystem,
    LagrangianSystem,
    canonical_transformation,
    is_canonical,
    poisson_bracket,
)
from symosc.models import n_link_pendulum

RNG = np.random.default_rng(11)
q, p, u, v = sp.symbols("q p u v", real=True)
x, y, th, ph = sp.symbols("x y theta phi", real=True)
m, w, k, c, g, l = sp.symbols("m omega k c g l", positive=True)


def elastic_pendulum():
    r = sp.Symbol("r", positive=True)
    return LagrangianSystem(
        m / 2 * (dot(r) ** 2 + r**2 * dot(th) ** 2), k / 2 * (r - l) ** 2 - m * g * r * sp.cos(th), [r, th]
    )


def rotating_frame():
    """A particle in a frame rotating at omega in a harmonic well: T has parts of degree 2, 1 and 0."""
    T = m / 2 * ((dot(x) - w * y) ** 2 + (dot(y) + w * x) ** 2)
    return LagrangianSystem(T, k / 2 * (x**2 + 2 * y**2), [x, y])


@pytest.mark.parametrize("make", [rotating_frame, elastic_pendulum])
def test_legendre_round_trip(make):
    """L -> H -> L is exact (Bulgakov (1954), eq. (3.116))."""
    s = make()
    L = s.kinetic_energy - s.potential_energy
    back = s.hamiltonian().lagrangian()
    assert sp.simplify(back - sp.expand(L)) == 0


@pytest.mark.parametrize("make", [rotating_frame, elastic_pendulum, lambda: n_link_pendulum(1)])
def test_canonical_equations_match_lagrange(make):
    """At a random state: q' = dH/dp reproduces the velocities and p' = -dH/dq equals dL/dq."""
    s = make()
    h = s.hamiltonian()
    L = s.kinetic_energy - s.potential_energy
    subs = {sym: sp.Float(float(RNG.uniform(0.5, 1.5)), 30) for sym in (*s.parameters, *s.coordinates, *s.velocities)}
    mom = {pk: L.diff(vk).xreplace(subs) for pk, vk in zip(h.momenta, s.velocities, strict=True)}
    at = {**{sym: subs[sym] for sym in (*s.parameters, *s.coordinates)}, **mom}
    f = h.vector_field.xreplace(at)
    n = len(s.coordinates)
    for i in range(n):
        assert abs(float(f[i] - subs[s.velocities[i]])) < 1e-20
        assert abs(float(f[n + i] - L.diff(s.coordinates[i]).xreplace(subs))) < 1e-20
    eqs = h.equations()
    assert eqs[0].lhs == dot(s.coordinates[0]) and eqs[n].lhs == dot(h.momenta[0])


def test_phase_space_lagrangian_gives_canonical_equations():
    """Helmholtz: the Euler-Lagrange equations of p q' - H in (q, p) are Hamilton's equations (eq. (3.124))."""
    h = rotating_frame().hamiltonian()
    Lp = h.phase_space_lagrangian()
    f = h.vector_field
    n = len(h.coordinates)
    for i, (qi, pi) in enumerate(zip(h.coordinates, h.momenta, strict=True)):
        # d/dt dLp/dq' - dLp/dq = 0  ->  p' = -dH/dq ; dLp/dp = 0 -> q' = dH/dp
        assert Lp.diff(dot(qi)) == pi
        assert sp.simplify(Lp.diff(qi) - f[n + i]) == 0
        assert sp.simplify(sp.solve(Lp.diff(pi), dot(qi))[0] - f[i]) == 0


def test_oscillator_energy_drift():
    h = HamiltonianSystem((p**2 / m + k * q**2) / 2, [q], [p])
    vals = {"m": 1.3, "k": 2.1}
    period = 2 * np.pi * np.sqrt(1.3 / 2.1)
    sol = solve_ivp(h.rhs(vals), (0, 100 * period), [0.7, 0.2], method="DOP853", rtol=1e-12, atol=1e-12)
    E = (sol.y[1] ** 2 / 1.3 + 2.1 * sol.y[0] ** 2) / 2
    assert np.max(np.abs(E - E[0])) / E[0] < 1e-9


# ---------------------------------------------------------------- canonical transformations
def test_exchange_transformation_kind1():
    """S = q u gives p = u, v = -q (Bulgakov (1954), §3.14; Goldstein, §9.2)."""
    ct = canonical_transformation(q * u, [q], [p], [u], [v], kind=1)
    assert ct.forward == {u: p, v: -q}
    assert ct.backward == {q: -v, p: u}
    assert ct.is_canonical()


def test_oscillator_action_angle_kind1():
    """S = (m w q^2 / 2) cot u: v = H / w and u the angle (Goldstein, §9.3, eqs. (9.41)-(9.46))."""
    qq, pp, uu, vv = sp.symbols("q p u v", positive=True)
    ct = canonical_transformation(m * w * qq**2 / 2 * sp.cot(uu), [qq], [pp], [uu], [vv], kind=1)
    H = pp**2 / (2 * m) + m * w**2 * qq**2 / 2
    assert sp.simplify(ct.forward[vv] - H / w) == 0
    assert sp.simplify(ct.new_hamiltonian(H) - w * vv) == 0
    assert ct.is_canonical()
    # Goldstein's closed form of the inverse: q = sqrt(2 v / (m w)) sin u, p = sqrt(2 m w v) cos u
    # (on the branch q > 0, i.e. 0 < u < pi, where |sin u| = sin u)
    back_q = sp.simplify(ct.backward[qq]).replace(sp.Abs, lambda e: e)
    assert sp.simplify(back_q - sp.sqrt(2 * vv / (m * w)) * sp.sin(uu)) == 0
    back_p = sp.simplify(ct.backward[pp]).replace(sp.Abs, lambda e: e)
    assert sp.simplify(back_p - sp.sqrt(2 * m * w * vv) * sp.cos(uu)) == 0


@pytest.mark.parametrize(
    ("S", "kind", "forward"),
    [
        (q * v, 2, {u: q, v: p}),
        (-p * u, 3, {u: q, v: p}),
        (p * v, 4, {v: -q, u: p}),
        (sp.exp(q) * v, 2, {u: sp.exp(q), v: p * sp.exp(-q)}),
    ],
)
def test_kinds_2_3_4(S, kind, forward):
    ct = canonical_transformation(S, [q], [p], [u], [v], kind=kind)
    for key, val in forward.items():
        assert sp.simplify(ct.forward[key] - val) == 0
    assert ct.is_canonical()
    # round trip: backward(forward(q, p)) == (q, p)
    for old in (q, p):
        assert sp.simplify(ct.backward[old].xreplace(ct.forward) - old) == 0


def test_time_dependent_generating_function():
    """Galilean shift S = (q - c t) v: H' = H + dS/dt = v^2 / (2 m) - c v (Goldstein, §9.1)."""
    ct = canonical_transformation((q - c * t) * v, [q], [p], [u], [v], kind=2)
    assert sp.expand(ct.new_hamiltonian(p**2 / (2 * m))) == v**2 / (2 * m) - c * v


def test_two_dof_polar_point_transformation():
    """Polar coordinates as a kind-3 point transformation S = -(p_x r cos phi + p_y r sin phi)."""
    r, pr, pphi = sp.symbols("r p_r p_phi", real=True)
    px, py = sp.symbols("p_x p_y", real=True)
    S = px * r * sp.cos(ph) + py * r * sp.sin(ph)
    ct = canonical_transformation(-S, [x, y], [px, py], [r, ph], [pr, pphi], kind=3, solve=False)
    assert ct.forward == {} and ct.backward == {}
    assert ct.relations[0] == sp.Eq(x, r * sp.cos(ph)) and ct.relations[1] == sp.Eq(y, r * sp.sin(ph))
    # the momenta transform covariantly (Goldstein, §9.1): p_r = p_x cos phi + p_y sin phi, p_phi = -p_x r sin phi + ...
    assert ct.relations[2] == sp.Eq(pr, px * sp.cos(ph) + py * sp.sin(ph))
    assert ct.relations[3] == sp.Eq(pphi, -px * r * sp.sin(ph) + py * r * sp.cos(ph))


@settings(max_examples=25, deadline=None)
@given(st.lists(st.integers(-3, 3), min_size=4, max_size=4))
def test_linear_maps_canonical_iff_unit_determinant(abcd):
    a, b, cc, d = abcd
    assert is_canonical([a * q + b * p], [cc * q + d * p], [q], [p]) == (a * d - b * cc == 1)


def test_poisson_bracket_angular_momentum():
    """{L_x, L_y} = L_z (Goldstein, eq. (9.121))."""
    z, px, py, pz = sp.symbols("z p_x p_y p_z")
    Q, P = [x, y, z], [px, py, pz]
    Lx, Ly, Lz = y * pz - z * py, z * px - x * pz, x * py - y * px
    assert sp.expand(poisson_bracket(Lx, Ly, Q, P) - Lz) == 0


def test_bad_generating_functions():
    with pytest.raises(ModelError, match="singular"):
        canonical_transformation(q**2 + u**2, [q], [p], [u], [v], kind=1)
    with pytest.raises(ModelError, match="depends on q and u only"):
        canonical_transformation(q * v, [q], [p], [u], [v], kind=1)
    with pytest.raises(ModelError, match="kind"):
        canonical_transformation(q * u, [q], [p], [u], [v], kind=5)
    with pytest.raises(ModelError, match="as many"):
        is_canonical([q], [p, u], [q], [p])
    with pytest.raises(ModelError, match="constrained"):
        LagrangianSystem(m / 2 * (dot(x) ** 2 + dot(y) ** 2), 0, [x, y], constraints=[x - y**2]).hamiltonian()
    with pytest.raises(ModelError, match="degenerate"):
        HamiltonianSystem(q**2, [q], [p]).lagrangian()
