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
from symosc.symbols import dot


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
