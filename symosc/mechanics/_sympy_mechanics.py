"""Bridge to ``sympy.physics.mechanics`` (private): :class:`LagrangianSystem` from a ``LagrangesMethod``,
``KanesMethod`` or ``System``, and a :class:`LagrangianSystem` as a ``LagrangesMethod``.

Import.  A ``LagrangesMethod`` brings its Lagrangian ``L``: the parts of degree 2 and 1 in the velocities become
``T``, minus the velocity-free part becomes ``V`` (``V - T0``: for a rheonomic system the velocity-free kinetic
energy goes with the potential, which leaves the equations unchanged).  A ``KanesMethod`` or ``System`` brings its
bodies: ``T`` is their kinetic energy in the inertial frame, with the generalized speeds replaced by the coordinate
rates through the kinematic differential equations; ``V`` is the bodies' ``potential_energy`` plus, for a ``System``
(which knows a fixed point), ``-F . r`` of every constant force (uniform gravity).  Other loads become generalized
forces ``Q_i = sum F . dv/dq'_i + M . dw/dq'_i`` (Kane 1985, §4.4; Greenwood, *Advanced Dynamics* 2003, §2.3).
Configuration and velocity constraints become holonomic and non-holonomic constraints.

Kane's method can impose velocity constraints without coordinates for them (a rolling contact point given
``set_vel(N, 0)``); Lagrange's equations of the kinetic energy of such a model are wrong.  For an unconstrained
model the import therefore compares the accelerations of both formulations at random states and raises
:class:`~symosc.errors.ModelError` when they differ.

Export.  ``T - V`` becomes the Lagrangian of a ``LagrangesMethod`` in ``dynamicsymbols``; each generalized force
(with ``-dR/dq'`` of the dissipation function) acts at a point of its own moving with ``q'_i`` along the inertial
``x`` axis, so that ``LagrangesMethod`` forms exactly ``Q_i``; the constraints are passed as ``hol_coneqs`` and
``nonhol_coneqs``.
"""

from __future__ import annotations

import random
from typing import TYPE_CHECKING, Any

import sympy as sp

from ..errors import ModelError
from ..symbols import dot, t

if TYPE_CHECKING:
    from .lagrange import LagrangianSystem

__all__ = ["from_sympy_mechanics", "to_sympy_mechanics"]


def _me() -> Any:
    import sympy.physics.mechanics as me

    return me


def _generalized_forces(loads: Any, frame: Any, rates: list, speeds: dict) -> list[sp.Expr]:
    """``Q_i = sum F . dv/dq'_i (+ M . dw/dq'_i)`` over ``(Point, Vector)`` / ``(ReferenceFrame, Vector)`` loads."""
    me = _me()
    Q = [sp.S.Zero] * len(rates)
    for load in loads or ():
        location, vector = load
        v = location.ang_vel_in(frame) if isinstance(location, me.ReferenceFrame) else location.vel(frame)
        v = v.subs(speeds) if speeds else v
        for i, qd in enumerate(rates):
            Q[i] += v.diff(qd, frame).dot(vector)
    return Q


def _split_lagrangian(system: LagrangianSystem) -> LagrangianSystem:
    """The system ``LagrangianSystem(L, 0, ...)`` with ``T = T2 + T1`` and ``V = -T0`` (see the module docstring)."""
    T2, T1, T0 = system.kinetic_energy_parts
    return type(system)(
        T2 + T1,
        -T0,
        system.coordinates,
        forces=system.forces,
        constraints=system.holonomic_constraints,
        nonholonomic=system.nonholonomic_constraints,
    )


def _from_lagranges(cls: type, lm: Any) -> LagrangianSystem:
    q = list(lm.q)
    rates = [c.diff(t) for c in q]
    loads = getattr(lm, "loads", None) or lm.forcelist
    forces = _generalized_forces(loads, lm.inertial, rates, {}) if loads else None
    hol = list(lm._hol_coneqs)  # the position-level constraints as given (LagrangesMethod keeps their rates)
    nonhol = list(lm.coneqs[len(hol) :])
    raw = cls(lm._L[0], 0, q, forces=forces, constraints=hol, nonholonomic=nonhol)
    return _split_lagrangian(raw)


def _speed_map(kdes: Any, u: list, rates: list) -> dict:
    """``{u_j: u_j(q, q', t)}`` from the kinematic differential equations (linear in the speeds)."""
    A, b = sp.linear_eq_to_matrix([sp.expand(e) for e in kdes], u)
    if A.shape[0] != A.shape[1] or A.det() == 0:
        raise ModelError(
            "the kinematic differential equations do not determine the generalized speeds from the coordinate "
            f"rates (speeds {u}, rates {rates}); give one equation per speed, linear in the speeds"
        )
    return dict(zip(u, A.LUsolve(b), strict=True))


def _bodies_energies(bodies: Any, frame: Any, speeds: dict) -> tuple[sp.Expr, sp.Expr]:
    T = sp.S.Zero
    V = sp.S.Zero
    for body in bodies or ():
        T += body.kinetic_energy(frame)
        V += getattr(body, "potential_energy", 0) or 0
    return sp.sympify(T).subs(speeds), sp.sympify(V).subs(speeds)


def _constant_force_potential(loads: Any, frame: Any, origin: Any, q: list) -> tuple[sp.Expr, list]:
    """``-sum F . r_P`` of the loads that are constant forces in ``frame`` (positions from the fixed ``origin``),
    and the loads left over."""
    me = _me()
    V = sp.S.Zero
    rest = []
    for load in loads or ():
        location, vector = load
        constant = (
            origin is not None
            and isinstance(location, me.Point)
            and all(vector.diff(c, frame) == 0 for c in q)
            and t not in vector.to_matrix(frame).free_symbols
            and not vector.to_matrix(frame).atoms(sp.Derivative)
        )
        if constant:
            try:
                r = location.pos_from(origin)
            except ValueError:
                constant = False
        if constant:
            V -= vector.dot(r)
        else:
            rest.append(load)
    return V, rest


def _from_bodies(
    cls: type,
    frame: Any,
    q: list,
    u: list,
    kdes: Any,
    bodies: Any,
    loads: Any,
    origin: Any,
    holonomic: list,
    velocity_constraints: list,
) -> LagrangianSystem:
    if frame is None:
        raise ModelError("the sympy.physics.mechanics model has no inertial frame")
    rates = [c.diff(t) for c in q]
    speeds = _speed_map(kdes, u, rates) if u else {}
    T, V = _bodies_energies(bodies, frame, speeds)
    Vg, rest = _constant_force_potential(loads, frame, origin, q)
    Q = _generalized_forces(rest, frame, rates, speeds)
    nonhol = [sp.sympify(c).subs(speeds) for c in velocity_constraints]
    if not sp.sympify(T).has(*rates):
        raise ModelError("the bodies have no kinetic energy in terms of the coordinate rates: add bodies")
    raw = cls(T - (V + Vg), 0, q, forces=Q, constraints=holonomic, nonholonomic=nonhol)
    return _split_lagrangian(raw)


def _check_against(system: LagrangianSystem, mass_full: Any, forcing_full: Any, q: list, u: list, kdes: Any) -> None:
    """Accelerations of ``system`` against those of a Kane/System model (``mass_full x' = forcing_full``,
    ``x = (q, u)``) at two random states: a :class:`ModelError` when they differ."""
    from ..symbols import ddot

    rng = random.Random(20250101)
    plain_q = system.coordinates
    to_plain = {}
    for dyn, pq in zip(q, plain_q, strict=True):
        to_plain[dyn.diff(t, 2)] = ddot(pq)
        to_plain[dyn.diff(t)] = dot(pq)
        to_plain[dyn] = pq
    u_syms = [sp.Symbol(f"_u{i}") for i in range(len(u))]
    to_plain.update({s.diff(t): sp.Symbol(f"_ud{i}") for i, s in enumerate(u)})
    to_plain.update(dict(zip(u, u_syms, strict=True)))
    lhs = sp.Matrix(mass_full).xreplace(to_plain)
    rhs = sp.Matrix(forcing_full).xreplace(to_plain)
    kin = [sp.sympify(e).xreplace(to_plain) for e in kdes]
    params = (lhs.free_symbols | rhs.free_symbols | system.mass_matrix.free_symbols | system.forcing.free_symbols) - {
        *plain_q,
        *system.velocities,
        *u_syms,
        t,
    }
    worst = 0.0
    for _ in range(2):
        at = {s: sp.Float(rng.uniform(0.5, 1.5), 30) for s in params}
        at[t] = sp.Float(rng.uniform(0.1, 1.0), 30)
        at.update({s: sp.Float(rng.uniform(-0.6, 0.6), 30) for s in plain_q})
        at.update({s: sp.Float(rng.uniform(-0.8, 0.8), 30) for s in u_syms})
        x_dot = sp.Matrix(lhs.xreplace(at)).LUsolve(sp.Matrix(rhs.xreplace(at)))  # (q', u') of the model
        n = len(plain_q)
        state = {**at, **{v: x_dot[i] for i, v in enumerate(system.velocities)}}
        M = system.mass_matrix.xreplace(state)
        acc = M.LUsolve(system.forcing.xreplace(state))
        # u' from the kinematic equations differentiated along the motion: d/dt kde(q, q', u) = 0
        full = {**state, **{ddot(pq): acc[i] for i, pq in enumerate(plain_q)}}
        for e in kin:
            de = _total_derivative(e, plain_q, system.velocities, u_syms)
            got = de.xreplace({**full, **{sp.Symbol(f"_ud{j}"): x_dot[n + j] for j in range(len(u_syms))}})
            scale = 1 + max(abs(float(x_dot[j])) for j in range(x_dot.shape[0]))
            worst = max(worst, abs(float(sp.N(got, 20))) / scale)
    if worst > 1e-12:
        raise ModelError(
            "the Lagrange equations of the bodies' kinetic energy disagree with the model's own (Kane) equations "
            f"(relative difference {worst:.2g} at a random state): the model constrains velocities through point "
            "velocities (e.g. a rolling contact point given set_vel(N, 0)) without coordinates for them, which only "
            "Kane's method handles; give the contact point coordinates and the rolling conditions as velocity "
            "constraints, or pass check=False"
        )


def _total_derivative(e: sp.Expr, q: tuple, qd: tuple, u: list) -> sp.Expr:
    from ..symbols import ddot

    out = e.diff(t)
    for c, v in zip(q, qd, strict=True):
        out += e.diff(c) * v + e.diff(v) * ddot(c)
    for i, s in enumerate(u):
        out += e.diff(s) * sp.Symbol(f"_ud{i}")
    return out


def from_sympy_mechanics(cls: type, obj: Any, *, check: bool = True) -> LagrangianSystem:
    """See :meth:`LagrangianSystem.from_sympy` (``cls`` is that class: this module does not import it)."""
    me = _me()
    if isinstance(obj, me.LagrangesMethod):
        return _from_lagranges(cls, obj)
    if isinstance(obj, me.System):
        if obj.eom_method is None:
            obj.form_eoms()
        q, u = list(obj.q), list(obj.u)
        system = _from_bodies(
            cls,
            obj.frame,
            q,
            u,
            obj.kdes,
            obj.bodies,
            obj.loads,
            obj.fixed_point,
            list(obj.holonomic_constraints),
            list(obj.nonholonomic_constraints),
        )
        if check and not system.is_constrained:
            _check_against(system, obj.mass_matrix_full, obj.forcing_full, q, u, obj.kdes)
        return system
    if isinstance(obj, me.KanesMethod):
        q, u = list(obj.q), list(obj.u)
        kdes = [qd - rhs for qd, rhs in obj.kindiffdict().items()]
        velocity = []
        if getattr(obj, "_k_nh", None) is not None and len(obj._k_nh):
            velocity = list(obj._k_nh * obj.u + obj._f_nh)
        system = _from_bodies(
            cls, obj._inertial, q, u, kdes, obj.bodies, obj.loads, None, list(getattr(obj, "_f_h", [])), velocity
        )
        if check and not system.is_constrained:
            if obj._fr is None:
                obj.kanes_equations(obj.bodies, obj.loads)
            _check_against(system, obj.mass_matrix_full, obj.forcing_full, q, u, kdes)
        return system
    raise ModelError(
        f"from_sympy takes a sympy.physics.mechanics LagrangesMethod, KanesMethod or System, got {type(obj).__name__}"
    )


def to_sympy_mechanics(system: LagrangianSystem) -> Any:
    """See :meth:`LagrangianSystem.to_sympy`."""
    me = _me()
    q = system.coordinates
    dyn = [me.dynamicsymbols(c.name) for c in q]
    back = {}
    for c, v, d in zip(q, system.velocities, dyn, strict=True):
        back[v] = d.diff(t)
        back[c] = d
    L = (system.kinetic_energy - system.potential_energy).xreplace(back)
    N = me.ReferenceFrame("N")
    loads = []
    for i, (c, v, d) in enumerate(zip(q, system.velocities, dyn, strict=True)):
        Qi = system.forces[i] - (system.dissipation.diff(v) if system.dissipation != 0 else 0)
        if Qi != 0:
            P = me.Point(f"Q_{c.name}")
            P.set_vel(N, d.diff(t) * N.x)  # dv/dq'_i = N.x: LagrangesMethod forms Q_i from this load
            loads.append((P, Qi.xreplace(back) * N.x))
    return me.LagrangesMethod(
        L,
        dyn,
        forcelist=loads or None,
        frame=N,
        hol_coneqs=[c.xreplace(back) for c in system.holonomic_constraints] or None,
        nonhol_coneqs=[c.xreplace(back) for c in system.nonholonomic_constraints] or None,
    )
