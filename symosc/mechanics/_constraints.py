"""Checking of constraint input for :class:`~symosc.mechanics.LagrangianSystem`."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import sympy as sp

from ..errors import ModelError
from . import _terms


def _as_list(items: Any, what: str) -> list[Any]:
    if items is None:
        return []
    if isinstance(items, (sp.Basic, str, int, float)):
        return [items]
    try:
        return list(items)
    except TypeError as exc:
        raise ModelError(f"{what} must be a sequence of expressions, got {items!r}") from exc


def check_constraints(
    system: Any, holonomic: Any, nonholonomic: Any, convert: Callable[[Any, str], sp.Expr]
) -> tuple[tuple[sp.Expr, ...], tuple[sp.Expr, ...]]:
    """Convert and validate the constraints; raise :class:`ModelError` naming the faulty one."""
    q, qd = system.coordinates, system.velocities
    qset, vset = set(q), set(qd)
    hol: list[sp.Expr] = []
    for k, phi in enumerate(_as_list(holonomic, "constraints")):
        e = convert(phi, f"constraint {k + 1}")
        if e.free_symbols & vset:
            raise ModelError(
                f"constraint {k + 1} ({e}) depends on velocities: pass constraints linear in the velocities "
                "through nonholonomic=, holonomic ones (phi(q, t) = 0) through constraints="
            )
        if not (e.free_symbols & qset):
            raise ModelError(
                f"constraint {k + 1} ({e}) involves no coordinate: it is either identically satisfied or "
                "inconsistent; remove it"
            )
        hol.append(e)
    non: list[sp.Expr] = []
    for k, g in enumerate(_as_list(nonholonomic, "nonholonomic")):
        e = convert(g, f"non-holonomic constraint {k + 1}")
        if not (e.free_symbols & vset):
            raise ModelError(
                f"non-holonomic constraint {k + 1} ({e}) contains no velocity: it is holonomic; pass it through "
                "constraints="
            )
        parts = _terms.velocity_parts(e, qd, f"non-holonomic constraint {k + 1}")
        if any(len(key) > 1 for key in parts):
            raise ModelError(
                f"non-holonomic constraint {k + 1} ({e}) is not linear in the velocities; only constraints "
                "E(q, t) q' + e(q, t) = 0 are supported (Bulgakov (1954), eq. (3.2))"
            )
        non.append(e)
    c = len(hol) + len(non)
    if c == 0:
        return (), ()
    n = len(q)
    if c >= n:
        raise ModelError(
            f"{c} constraints on {n} coordinates leave no freedom of motion; at most {n - 1} constraints are allowed"
        )
    rows = [[phi.diff(x) for x in q] for phi in hol] + [[g.diff(v) for v in qd] for g in non]
    from .constraints import RANK_TOLERANCE, dependent_rows, rank_on_constraint_set

    labels = [f"constraint {k + 1} ({e})" for k, e in enumerate(hol)] + [
        f"non-holonomic constraint {k + 1} ({e})" for k, e in enumerate(non)
    ]
    dep = dependent_rows(sp.Matrix(rows))
    if dep:
        last, others = labels[dep[-1]], [labels[i] for i in dep[:-1]]
        on = ("on " + ", ".join(others)) if others else "(its gradient vanishes identically)"
        raise ModelError(
            f"{last} is linearly dependent {on}: the constraint Jacobian (d phi/dq and the velocity coefficients "
            f"of the non-holonomic constraints) loses rank at every configuration (exact rank for rational "
            f"functions, else at random points with relative singular-value tolerance {RANK_TOLERANCE:g}), so "
            "the constraints are redundant or inconsistent; remove the dependent one"
        )
    on_set = rank_on_constraint_set(hol, sp.Matrix(rows), q)
    if on_set is not None and on_set < c:
        raise ModelError(
            "the constraints " + "; ".join(labels) + f" are independent at generic configurations but their "
            f"Jacobian has rank {on_set} < {c} everywhere on the set where the holonomic constraints hold "
            "(checked at random points projected onto that set): they define that set redundantly and the "
            "multipliers are not determined; describe it by independent constraints"
        )
    return tuple(hol), tuple(non)


def as_sequence(items: Sequence[Any] | Any) -> list[Any]:
    """A list from a single item or a sequence."""
    return _as_list(items, "argument")
