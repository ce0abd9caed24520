"""Independent reference: the n-link pendulum built with sympy.physics.mechanics (vectors, LagrangesMethod)."""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import (
    LagrangesMethod,
    Lagrangian,
    Particle,
    Point,
    ReferenceFrame,
    RigidBody,
    dynamicsymbols,
    inertia,
)

from symosc.models import pendulum_symbols
from symosc.symbols import dot, t


def sympy_pendulum(n: int, links: str, inverted: bool, pivot: str):
    """Return (LagrangesMethod, replacement dict dynamicsymbols -> symosc plain symbols)."""
    s = pendulum_symbols(n)
    tt = dynamicsymbols._t
    q = dynamicsymbols(f"phi1:{n + 1}")
    N = ReferenceFrame("N")
    O = Point("O")
    y0 = s["a"] * sp.cos(s["p"] * tt) if pivot == "vertical" else sp.S.Zero
    O.set_vel(N, y0.diff(tt) * N.y)
    sign = 1 if inverted else -1
    pos = y0 * N.y
    bodies = []
    for k in range(n):
        frame = N.orientnew(f"A{k + 1}", "Axis", [sign * -q[k] if inverted else q[k], N.z])
        arm = s["l"][k] if links == "point" else s["lc"][k]
        center = pos + arm * (sp.sin(q[k]) * N.x + sign * sp.cos(q[k]) * N.y)
        P = Point(f"P{k + 1}")
        P.set_pos(O, center - y0 * N.y)
        P.set_vel(N, center.dt(N))
        if links == "point":
            body = Particle(f"B{k + 1}", P, s["m"][k])
        else:
            body = RigidBody(f"B{k + 1}", P, frame, s["m"][k], (inertia(frame, 0, 0, s["I"][k]), P))
        body.potential_energy = s["m"][k] * s["g"] * center.dot(N.y)
        bodies.append(body)
        pos = pos + s["l"][k] * (sp.sin(q[k]) * N.x + sign * sp.cos(q[k]) * N.y)
    L = Lagrangian(N, *bodies)
    lm = LagrangesMethod(L, q)
    lm.form_lagranges_equations()
    repl = {}
    for qk, phik in zip(q, s["phi"], strict=True):
        repl[qk.diff(tt)] = dot(phik)
        repl[qk] = phik
    return lm, repl


def sympy_pendulum_kane(n: int, links: str, inverted: bool, pivot: str):
    """Return (KanesMethod, replacement dict dynamicsymbols -> symosc plain symbols) for the same chain.

    Kane's method with ``u_k = q_k'`` (PyDy's usual set-up): the mass matrix and forcing of ``M u' = F`` equal
    those of the Lagrange equations.
    """
    from sympy.physics.mechanics import KanesMethod

    s = pendulum_symbols(n)
    tt = dynamicsymbols._t
    q = dynamicsymbols(f"phi1:{n + 1}")
    u = dynamicsymbols(f"w1:{n + 1}")
    N = ReferenceFrame("N")
    O = Point("O")
    y0 = s["a"] * sp.cos(s["p"] * tt) if pivot == "vertical" else sp.S.Zero
    O.set_vel(N, y0.diff(tt) * N.y)
    sign = 1 if inverted else -1
    bodies, loads = [], []
    hinge = O
    for k in range(n):
        frame = N.orientnew(f"A{k + 1}", "Axis", [-q[k] if inverted else q[k], N.z])
        frame.set_ang_vel(N, (-u[k] if inverted else u[k]) * N.z)
        arm = s["l"][k] if links == "point" else s["lc"][k]
        direction = sp.sin(q[k]) * N.x + sign * sp.cos(q[k]) * N.y
        P = hinge.locatenew(f"P{k + 1}", arm * direction)
        P.v2pt_theory(hinge, N, frame)
        if links == "point":
            bodies.append(Particle(f"B{k + 1}", P, s["m"][k]))
        else:
            bodies.append(RigidBody(f"B{k + 1}", P, frame, s["m"][k], (inertia(frame, 0, 0, s["I"][k]), P)))
        loads.append((P, -s["m"][k] * s["g"] * N.y))
        nxt = hinge.locatenew(f"H{k + 1}", s["l"][k] * direction)
        nxt.v2pt_theory(hinge, N, frame)
        hinge = nxt
    km = KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[qk.diff(tt) - uk for qk, uk in zip(q, u, strict=True)])
    km.kanes_equations(bodies, loads)
    repl = {}
    for qk, uk, phik in zip(q, u, s["phi"], strict=True):
        repl[uk] = dot(phik)
        repl[qk] = phik
    return km, repl


def typed_chain(n: int):
    """The point chain as a user would type it: the angles as functions of time, Cartesian positions of the masses,
    ``T = sum m/2 (x'^2 + y'^2)``.  Returns (T, V, coordinates)."""
    s = pendulum_symbols(n)
    q = [sp.Function(f"phi{k + 1}")(t) for k in range(n)]
    x = y = T = V = sp.S.Zero
    for k in range(n):
        x += s["l"][k] * sp.sin(q[k])
        y -= s["l"][k] * sp.cos(q[k])
        T += s["m"][k] / 2 * (x.diff(t) ** 2 + y.diff(t) ** 2)
        V += s["m"][k] * s["g"] * y
    return T, V, q
