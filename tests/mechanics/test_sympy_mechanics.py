"""sympy.physics.mechanics models in and out of symosc: double pendulums built with frames, points, particles and
joints through LagrangesMethod, KanesMethod and System, and a rolling disc (non-holonomic)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
import sympy.physics.mechanics as me

from symosc.errors import ModelError
from symosc.mechanics import LagrangianSystem
from symosc.models import n_link_pendulum
from symosc.symbols import dot, t

q1, q2 = me.dynamicsymbols("q1 q2")
u1, u2 = me.dynamicsymbols("u1 u2")
m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g", positive=True)
POINT_VALUES = {"m1": 1.3, "m2": 0.7, "l1": 0.9, "l2": 0.6, "g": 9.81}
#: the rigid double pendulum of Gribkov & Khokhlov (2015), Table 1
RIGID_VALUES = {"m1": 1.032e-3, "m2": 0.424e-3, "l1": 0.045, "lc1": 0.024917, "lc2": 0.012838,
                "I1": 146.804e-9, "I2": 32.871e-9, "g": 9.81}  # fmt: skip


def _point_pendulum_frames(speeds: bool):
    """Two particles on massless rods hinged at O: absolute angles q1, q2 about N.z."""
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [q1, N.z])
    B = N.orientnew("B", "Axis", [q2, N.z])
    if speeds:
        A.set_ang_vel(N, u1 * N.z)
        B.set_ang_vel(N, u2 * N.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    P1 = O.locatenew("P1", -l1 * A.y)
    P2 = P1.locatenew("P2", -l2 * B.y)
    P1.v2pt_theory(O, N, A)
    P2.v2pt_theory(P1, N, B)
    return N, O, (P1, P2), (me.Particle("b1", P1, m1), me.Particle("b2", P2, m2))


def test_lagranges_method_double_pendulum_matches_symosc():
    N, O, (P1, P2), (b1, b2) = _point_pendulum_frames(speeds=False)
    b1.potential_energy = m1 * g * P1.pos_from(O).dot(N.y)
    b2.potential_energy = m2 * g * P2.pos_from(O).dot(N.y)
    system = LagrangianSystem.from_sympy(me.LagrangesMethod(me.Lagrangian(N, b1, b2), [q1, q2]))
    own = n_link_pendulum(2)  # absolute angles phi1, phi2 from the downward vertical, the same convention
    rename = {
        sp.Symbol("phi1", real=True): sp.Symbol("q1", real=True),
        sp.Symbol("phi2", real=True): sp.Symbol("q2", real=True),
    }
    rename |= {dot(k): dot(v) for k, v in rename.items()}
    assert sp.simplify(own.mass_matrix.xreplace(rename) - system.mass_matrix) == sp.zeros(2, 2)
    assert sp.simplify(own.forcing.xreplace(rename) - system.forcing) == sp.zeros(2, 1)
    assert system.potential_energy != 0 and system.forces == (0, 0)


def test_kanes_method_double_pendulum_natural_frequencies():
    """Gravity as loads (no potential energy given): the frequencies of symosc's own derivation to 1e-12."""
    N, _, (P1, P2), (b1, b2) = _point_pendulum_frames(speeds=True)
    kane = me.KanesMethod(N, [q1, q2], [u1, u2], kd_eqs=[q1.diff(t) - u1, q2.diff(t) - u2])
    kane.kanes_equations([b1, b2], [(P1, -m1 * g * N.y), (P2, -m2 * g * N.y)])
    system = LagrangianSystem.from_sympy(kane)
    got = system.linearize().natural_frequencies(POINT_VALUES)
    want = n_link_pendulum(2).linearize().natural_frequencies(POINT_VALUES)
    np.testing.assert_allclose(got, want, rtol=1e-12)


def test_system_with_pin_joints_and_uniform_gravity():
    """A compound double pendulum assembled from rigid bodies and pin joints (relative angles): frequencies of
    symosc's rigid-link model to 1e-12, the potential of gravity recovered from the fixed point."""
    lc1, lc2, I1, I2 = sp.symbols("lc1 lc2 I1 I2", positive=True)
    ceiling = me.RigidBody("ceiling")
    link1, link2 = me.RigidBody("link1", mass=m1), me.RigidBody("link2", mass=m2)
    link1.central_inertia = me.inertia(link1.frame, 0, 0, I1)
    link2.central_inertia = me.inertia(link2.frame, 0, 0, I2)
    J1 = me.PinJoint("J1", ceiling, link1, coordinates=q1, speeds=u1, child_point=lc1 * link1.y, joint_axis=ceiling.z)
    J2 = me.PinJoint("J2", link1, link2, coordinates=q2, speeds=u2, parent_point=-(l1 - lc1) * link1.y,
                     child_point=lc2 * link2.y, joint_axis=link1.z)  # fmt: skip
    model = me.System.from_newtonian(ceiling)
    model.add_joints(J1, J2)
    model.apply_uniform_gravity(-g * ceiling.y)
    model.form_eoms()
    system = LagrangianSystem.from_sympy(model)
    assert system.forces == (0, 0) and g in system.potential_energy.free_symbols
    got = system.linearize().natural_frequencies(RIGID_VALUES)
    want = n_link_pendulum(2, links="rigid").linearize().natural_frequencies(RIGID_VALUES)
    np.testing.assert_allclose(got, want, rtol=1e-12)


def _trig_zero(m: sp.Matrix) -> bool:
    """Whether every entry vanishes identically (angle sums expanded, then SymPy's trigsimp)."""
    return all(sp.trigsimp(sp.expand(sp.expand_trig(e))) == 0 for e in m)


def test_round_trip_keeps_mass_matrix_and_forcing_and_sympy_agrees():
    """symosc -> LagrangesMethod -> symosc with damping and a generalized force; SymPy's own Lagrange equations
    of the exported object are symosc's equations."""
    own = n_link_pendulum(2, links="rigid", inverted=True, pivot="vertical")
    phi1, phi2 = own.coordinates
    c, F = sp.symbols("c F", positive=True)
    system = LagrangianSystem(own.kinetic_energy, own.potential_energy, own.coordinates,
                              dissipation=c * (dot(phi1) ** 2 + dot(phi2) - dot(phi1)) ** 2 / 2,
                              forces={phi2: F * sp.cos(t)})  # fmt: skip
    lm = system.to_sympy()
    back = LagrangianSystem.from_sympy(lm)
    assert back.coordinates == system.coordinates
    assert sp.expand(back.mass_matrix - system.mass_matrix) == sp.zeros(2, 2)
    assert sp.expand(back.forcing - system.forcing) == sp.zeros(2, 1)
    lm.form_lagranges_equations()
    to_plain = {}
    for d, p in zip(lm.q, system.coordinates, strict=True):
        to_plain |= {d.diff(t): dot(p), d: p}
    # symosc's equations are presented with sin^2 + cos^2 = 1 and angle differences collected (simplify=True)
    assert _trig_zero(lm.mass_matrix.xreplace(to_plain) - system.mass_matrix)
    assert _trig_zero(lm.forcing.xreplace(to_plain) - system.forcing)
    # the periodic stiffness survives: Floquet/Ince-Strutt analysis of the imported model is the original's
    K0, K1, p = back.linearize().periodic_stiffness()
    assert (K0, K1, p) == own.linearize().periodic_stiffness()


def _rolling_disc():
    """Thin disc (mass m, radius r) rolling without slipping: contact point (x, y), yaw q1, lean q2, spin q3."""
    x, y, yaw, lean, spin = me.dynamicsymbols("x y q1 q2 q3")
    r, m = sp.symbols("r m", positive=True)
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    R = L.orientnew("R", "Axis", [spin, L.y])
    O = me.Point("O")
    O.set_vel(N, 0)
    center = O.locatenew("C", x * N.x + y * N.y).locatenew("D", r * L.z)
    center.set_vel(N, center.pos_from(O).dt(N))
    disc = me.RigidBody("disc", center, R, m, (me.inertia(L, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), center))
    disc.potential_energy = m * g * r * sp.cos(lean)
    contact = center.vel(N) + R.ang_vel_in(N).cross(-r * L.z)  # velocity of the disc's material contact point
    return me.LagrangesMethod(me.Lagrangian(N, disc), [x, y, yaw, lean, spin],
                              nonhol_coneqs=[contact.dot(N.x), contact.dot(N.y)], frame=N)  # fmt: skip


def _kane_rolling_disc():
    """The rolling disc of Kane's method (body rates u1..u3 in the lean frame, contact point fixed), as in
    sympy.physics.mechanics' examples: the rolling constraint is in the point velocities."""
    yaw, lean, spin = me.dynamicsymbols("q1 q2 q3")
    w1, w2, w3 = me.dynamicsymbols("w1 w2 w3")
    r, m = sp.symbols("r m", positive=True)
    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [yaw, N.z])
    L = Y.orientnew("L", "Axis", [lean, Y.x])
    R = L.orientnew("R", "Axis", [spin, L.y])
    rates = R.ang_vel_in(N)
    R.set_ang_vel(N, w1 * L.x + w2 * L.y + w3 * L.z)
    C = me.Point("C")
    C.set_vel(N, 0)
    D = C.locatenew("D", r * L.z)
    D.v2pt_theory(C, N, R)
    disc = me.RigidBody("disc", D, R, m, (me.inertia(L, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), D))
    kane = me.KanesMethod(
        N, [yaw, lean, spin], [w1, w2, w3], kd_eqs=[rates.dot(e) - w for e, w in zip(L, (w1, w2, w3), strict=True)]
    )
    kane.kanes_equations([disc], [(D, -m * g * N.z)])
    return kane


def test_rolling_disc_round_trip_and_accelerations_against_kanes_method():
    lm = _rolling_disc()
    system = LagrangianSystem.from_sympy(lm)
    assert len(system.nonholonomic_constraints) == 2 and system.potential_energy != 0
    back = LagrangianSystem.from_sympy(system.to_sympy())
    assert back == system
    assert sp.expand(back.mass_matrix - system.mass_matrix) == sp.zeros(5, 5)
    assert sp.expand(back.forcing - system.forcing) == sp.zeros(5, 1)
    # Lagrange multipliers (symosc) against Kane's method with the constraint in the point velocities (SymPy)
    kane = _kane_rolling_disc()
    values = {"m": 1.1, "r": 0.3, "g": 9.81}
    q, w = [0.4, 0.25, 1.0], [0.7, -3.0, 1.2]
    sym = {
        s: values[s.name]
        for s in kane.mass_matrix_full.free_symbols | kane.forcing_full.free_symbols
        if s.name in values
    }
    state = dict(zip(kane.q, q, strict=True)) | dict(zip(kane.u, w, strict=True))
    xdot = np.linalg.solve(np.array(kane.mass_matrix_full.xreplace(sym | state), dtype=float),
                           np.array(kane.forcing_full.xreplace(sym | state), dtype=float)).ravel()  # fmt: skip
    qdot = xdot[:3]
    # the same motion in full coordinates: the contact point moves as the constraints require
    roll = values["r"] * qdot[2]  # the contact point moves at r * spin rate along the heading
    xd, yd = roll * np.cos(q[0]), roll * np.sin(q[0])
    full_state = [0.0, 0.0, *q, xd, yd, *qdot]
    np.testing.assert_allclose(system.constrained.residuals(values, 0.0, full_state), 0, atol=1e-12)
    acc, _ = system.constrained.accelerations(values, 0.0, full_state)
    # Kane's qdd: differentiate the kinematic equations q' = f(q, w) along the motion
    f = sp.Matrix([kane.kindiffdict()[c.diff(t)] for c in kane.q])
    qdd = f.jacobian(kane.q) * sp.Matrix(qdot) + f.jacobian(kane.u) * sp.Matrix(xdot[3:])
    want = np.array(qdd.xreplace(sym | state), dtype=float).ravel()
    np.testing.assert_allclose(acc[2:], want, rtol=1e-10, atol=1e-12)


def test_velocity_constraints_hidden_in_point_velocities_are_refused():
    with pytest.raises(ModelError, match="set_vel"):
        LagrangianSystem.from_sympy(_kane_rolling_disc())


def test_other_objects_are_refused():
    with pytest.raises(ModelError, match="LagrangesMethod, KanesMethod or System"):
        LagrangianSystem.from_sympy(me.ReferenceFrame("N"))
