"""Routh reduction, steady motions and small oscillations about them (closed forms from Landau & Lifshitz,
Goldstein; the full Lagrange equations as an independent check)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from symosc import ModelError, dot
from symosc.mechanics import LagrangianSystem, routh_reduction

RNG = np.random.default_rng(5)
r, th, ph, ps = sp.symbols("r theta phi psi", real=True)
m, k, g, l, I1, I3, M = sp.symbols("m k g l I1 I3 M", positive=True)
th0 = sp.Symbol("theta0", positive=True)


def central():
    return LagrangianSystem(m / 2 * (dot(r) ** 2 + r**2 * dot(ph) ** 2), -k / r, [r, ph])


def spherical_pendulum():
    T = m * l**2 / 2 * (dot(th) ** 2 + sp.sin(th) ** 2 * dot(ph) ** 2)
    return LagrangianSystem(T, -m * g * l * sp.cos(th), [th, ph])


def heavy_top():
    """Lagrange's top, Euler angles (theta, phi, psi), pivot below the centre of mass (Goldstein, §5.7)."""
    T = I1 / 2 * (dot(th) ** 2 + sp.sin(th) ** 2 * dot(ph) ** 2) + I3 / 2 * (dot(ps) + sp.cos(th) * dot(ph)) ** 2
    return LagrangianSystem(T, M * g * l * sp.cos(th), [th, ph, ps])


def test_central_force_routhian_book_sign():
    """R = m r'^2/2 - V - p^2/(2 m r^2) (Bulgakov (1954), eqs. (3.110)-(3.114)) and m r'' = p^2/(m r^3) - V'."""
    red = routh_reduction(central(), [ph])
    p = red.momenta[0]
    assert sp.simplify(red.routhian - (m * dot(r) ** 2 / 2 + k / r - p**2 / (2 * m * r**2))) == 0
    rs = red.reduced_system
    assert sp.simplify(rs.forcing[0] - (p**2 / (m * r**3) - k / r**2)) == 0
    assert rs.mass_matrix[0, 0] == m


def test_reduced_accelerations_match_full_system():
    """The top's reduced theta'' equals the full Lagrange equations' theta'' at random states."""
    s = heavy_top()
    red = routh_reduction(s, [ph, ps])
    rs = red.reduced_system
    L = s.kinetic_energy - s.potential_energy
    for _ in range(3):
        vals = {sym: sp.Float(float(RNG.uniform(0.3, 1.5)), 30) for sym in (*s.parameters, th, *s.velocities)}
        mom = {pm: L.diff(dot(c)).xreplace(vals) for pm, c in zip(red.momenta, red.cyclic, strict=True)}
        full = s.mass_matrix.xreplace(vals).LUsolve(s.forcing.xreplace(vals))[0]
        reduced = (rs.forcing[0] / rs.mass_matrix[0, 0]).xreplace(vals | mom)
        assert abs(float(full - reduced)) < 1e-20
        # the cyclic velocities are recovered from the momenta
        for vel, expr in red.cyclic_velocities.items():
            assert abs(float(expr.xreplace(vals | mom) - vals[vel])) < 1e-20


def test_spherical_pendulum_conical_motion():
    """Conical motion at theta0: stable, and small oscillations at Omega^2 = (g / (l cos th0)) (1 + 3 cos^2 th0)
    (Landau & Lifshitz, Mechanics, §14 problem; Goldstein problem 3.x)."""
    s = spherical_pendulum()
    red = routh_reduction(s, [ph])
    p = red.momenta[0]
    # Helmholtz: the kinetic energy of the hidden cyclic motion acts as a potential
    assert sp.simplify(red.reduced_potential - (-m * g * l * sp.cos(th) + p**2 / (2 * m * l**2 * sp.sin(th) ** 2))) == 0
    p0 = sp.sqrt(m**2 * g * l**3 * sp.sin(th0) ** 4 / sp.cos(th0))
    val = {th0: sp.pi / 5}
    sm = red.steady_motion({th: sp.pi / 5}, {p: p0.xreplace(val)})
    assert sm.stable is True
    lin = red.small_oscillations({th: sp.pi / 5}, {p: p0.xreplace(val)})
    omega2 = sp.simplify(lin.K[0, 0] / lin.M[0, 0])
    expected = (g / (l * sp.cos(th0)) * (1 + 3 * sp.cos(th0) ** 2)).xreplace(val)
    assert sp.simplify(omega2 - expected) == 0
    with pytest.raises(ModelError, match="not a steady motion"):
        red.steady_motion({th: sp.pi / 5}, {p: 2 * p0.xreplace(val)})


def test_sleeping_top_stability_threshold():
    """A sleeping top is stable iff I3^2 w3^2 > 4 I1 M g l (Goldstein, §5.7, eq. (5.79))."""
    red = routh_reduction(heavy_top(), [ph, ps])
    pphi, ppsi = red.momenta
    P = sp.Symbol("P", positive=True)
    sm = red.steady_motion({th: 0}, {pphi: P, ppsi: P})
    assert sp.simplify(sm.hessian[0, 0] - (P**2 / (4 * I1) - M * g * l)) == 0
    assert sm.stable is None  # the sign depends on P


def test_steady_precession_against_full_equations():
    """Steady precession exists where the full theta'' vanishes; elsewhere steady_motion refuses."""
    s = heavy_top()
    red = routh_reduction(s, [ph, ps])
    vals = {I1: 2, I3: 1, M: 1, g: 10, l: sp.Rational(1, 2)}
    T0 = sp.pi / 3
    w3 = 10  # spin component; precession rate Omega from  M g l = Omega (I3 w3 - I1 Omega cos th)
    Om = sp.Symbol("Om")
    sols = sp.solve((M * g * l - Om * (I3 * w3 - I1 * Om * sp.cos(T0))).xreplace(vals), Om)
    slow = min(sols, key=lambda e: abs(float(e)))
    # omega3 = psi' + cos(th) phi'
    state = {th: T0, dot(th): 0, dot(ph): slow, dot(ps): w3 - sp.cos(T0) * slow}
    full = s.mass_matrix.xreplace(vals | state).LUsolve(s.forcing.xreplace(vals | state))[0]
    assert abs(float(full)) < 1e-12
    L = (s.kinetic_energy - s.potential_energy).xreplace(vals)
    mom = {pm: sp.nsimplify(L.diff(dot(c)).xreplace(state)) for pm, c in zip(red.momenta, red.cyclic, strict=True)}
    numeric = LagrangianSystem(s.kinetic_energy.xreplace(vals), s.potential_energy.xreplace(vals), [th, ph, ps])
    red_num = routh_reduction(numeric, [ph, ps])
    sm = red_num.steady_motion({th: T0}, {pm.name: v for pm, v in mom.items()})
    assert sm.stable is True  # slow precession of a fast top is stable
    bad = {pm.name: v * sp.Rational(11, 10) for pm, v in mom.items()}
    with pytest.raises(ModelError, match="not a steady motion"):
        red_num.steady_motion({th: T0}, bad)


def test_bad_input():
    with pytest.raises(ModelError, match="theta is not cyclic"):
        routh_reduction(spherical_pendulum(), [th])
    with pytest.raises(ModelError, match="not a coordinate"):
        routh_reduction(spherical_pendulum(), [r])
    forced = LagrangianSystem(m / 2 * (dot(r) ** 2 + r**2 * dot(ph) ** 2), 0, [r, ph], forces=[0, k])
    with pytest.raises(ModelError, match="generalized force"):
        routh_reduction(forced, [ph])
    red = routh_reduction(central(), [ph])
    with pytest.raises(ModelError, match="missing"):
        red.steady_motion({}, {})


def test_gyroscopic_stabilization_of_a_gimballed_rotor():
    """A rotor (cyclic psi) on a gimbal (a, b) with inverted stiffness: the Routh function has a gyroscopic term
    G = [[0, -p], [p, 0]] at rest (§7.9) and the steady state is stable iff p^2 > 4 A k, from
    det [[A s^2 - k, -p s], [p s, A s^2 - k]] = 0 (Merkin, Introduction to the Theory of Stability, §6.5)."""
    from symosc.mechanics import decompose_forces

    a, b, psi = sp.symbols("a b psi", real=True)
    A, Cr, kk = sp.symbols("A C k", positive=True)
    T = A / 2 * (dot(a) ** 2 + dot(b) ** 2) + Cr / 2 * (dot(psi) + sp.sin(a) * dot(b)) ** 2
    s = LagrangianSystem(T, -kk / 2 * (a**2 + b**2), [a, b, psi])
    red = routh_reduction(s, [psi])
    p = red.momenta[0]
    sm = red.steady_motion({a: 0, b: 0}, {p: 3})
    assert sm.stable is None  # two negative stiffnesses: an even degree of instability, gyroscopic forces may help
    for pv, stable in ((3, True), (1, False)):
        lin = red.small_oscillations({a: 0, b: 0}, {p: pv})
        assert sp.simplify(lin.D - sp.Matrix([[0, -pv], [pv, 0]])) == sp.zeros(2, 2)
        fd = decompose_forces(lin.M, lin.D, lin.K)
        verdict = fd.stability({"A": 1, "k": 1, "C": 1})
        assert verdict.stable is None and "gyroscopic" in verdict.reason
        Mn, Dn, Kn = (np.array(mm.xreplace({A: 1, kk: 1, Cr: 1}), dtype=float) for mm in (lin.M, lin.D, lin.K))
        lam = np.linalg.eigvals(
            np.vstack([np.hstack([np.zeros((2, 2)), np.eye(2)]), -np.linalg.solve(Mn, np.hstack([Kn, Dn]))])
        )
        assert bool(np.abs(lam.real).max() < 1e-9) == stable
        # closed form: s^2 = (-(p^2 - 2) +- sqrt((p^2 - 2)^2 - 4)) / 2 for A = k = 1
        roots = np.roots([1, pv**2 - 2, 1]).astype(complex)
        assert np.allclose(np.sort(np.abs(lam) ** 2), np.sort(np.repeat(np.abs(roots), 2)), rtol=1e-9)
