"""Helpers of :class:`~symosc.mechanics.LagrangianSystem`: Christoffel symbols, change of coordinates."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef

from ..errors import ModelError
from ..symbols import dot, t


def christoffel(system: Any, kind: int) -> sp.Array:
    if kind not in (1, 2):
        raise ModelError(f"kind must be 1 or 2, got {kind!r}")
    g = system.mass_matrix
    q = system.coordinates
    n = len(q)
    dg = [g.diff(x) for x in q]
    first = [[[(dg[l][m, k] + dg[k][m, l] - dg[m][k, l]) / 2 for l in range(n)] for k in range(n)] for m in range(n)]
    if kind == 1:
        return sp.Array(first)
    ginv = g.inv(method="LU")
    second = [
        [[sp.Add(*(ginv[j, m] * first[m][k][l] for m in range(n))) for l in range(n)] for k in range(n)]
        for j in range(n)
    ]
    return sp.Array(second)


def _symbol(c: Any) -> sp.Symbol:
    if isinstance(c, sp.Symbol):
        return c
    if isinstance(c, AppliedUndef) and c.args == (t,):
        return sp.Symbol(c.func.__name__, real=True)
    if isinstance(c, str):
        return sp.Symbol(c, real=True)
    raise ModelError(f"coordinates must be Symbols, got {c!r}")


def _tidy(e: sp.Expr) -> sp.Expr:
    """Simplify small expressions (a substituted parametrization usually collapses, e.g. sin^2 + cos^2)."""
    return sp.simplify(e) if sp.count_ops(e) < 300 else e


def reduce_coordinates(system: Any, parametrization: Mapping[Any, Any], coordinates: Sequence[Any]) -> Any:
    new = [_symbol(c) for c in (coordinates if isinstance(coordinates, (list, tuple)) else [coordinates])]
    by_name = {q.name: q for q in system.coordinates}
    mapping: dict[sp.Symbol, sp.Expr] = {}
    for key, val in parametrization.items():
        name = key.name if isinstance(key, sp.Symbol) else str(key)
        if name not in by_name:
            raise ModelError(f"parametrization names {name!r}, which is not a coordinate")
        mapping[by_name[name]] = sp.sympify(val)
    new_names = {s.name for s in new}
    for q in system.coordinates:
        if q not in mapping:
            if q.name in new_names:
                mapping[q] = q
            else:
                raise ModelError(
                    f"coordinate {q.name} is neither given by the parametrization nor kept among the new coordinates"
                )
    allowed = set(new) | {t} | set(system.parameters)
    for q, e in mapping.items():
        stray = e.free_symbols - allowed
        if stray:
            raise ModelError(f"the expression for {q.name} contains {sorted(map(str, stray))}: not new coordinates")
    vel = {}
    for q, e in mapping.items():
        vel[dot(q)] = sp.Add(*(e.diff(s) * dot(s) for s in new)) + e.diff(t)
    sub = {**vel, **mapping}
    T = _tidy(system.kinetic_energy.xreplace(sub))
    V = _tidy(system.potential_energy.xreplace(sub))
    R = system.dissipation.xreplace(sub)
    Q = [f.xreplace(sub) for f in system.forces]
    forces = [sp.Add(*(Qi * mapping[q].diff(s) for Qi, q in zip(Q, system.coordinates, strict=True))) for s in new]
    hol = []
    for phi in system.holonomic_constraints:
        e = phi.xreplace(mapping)
        if sp.simplify(e) != 0:
            hol.append(e)
    non = []
    for g in system.nonholonomic_constraints:
        e = g.xreplace(sub)
        if sp.simplify(e) != 0:
            non.append(e)
    return type(system)(T, V, new, dissipation=R, forces=forces, constraints=hol, nonholonomic=non)
