"""Additive separation of ``H(q, dW/dq) = h`` for Liouville/Stäckel-type Hamiltonians (helpers of
:func:`~symosc.mechanics.separate_hamilton_jacobi`).

The equation ``Phi(q) (H - h) = 0`` is expanded into terms; terms are grouped into the connected components of
the coordinates they couple.  When there are at least two components, every component but the one holding the
energy equals a separation constant, and components with more than one coordinate are separated again with
their constant as the energy (Landau & Lifshitz, Mechanics, §48; Bulgakov (1954), §3.16).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy as sp

from ...errors import ModelError


def candidate_factors(H: sp.Expr, pairs: Sequence[tuple[sp.Symbol, sp.Symbol]]) -> list[sp.Expr]:
    """Factors tried when none is given: 1, and for each momentum ``p_j`` the reciprocal and the denominator of
    the coefficient of ``p_j^2`` (``2 m r^2`` for ``p_theta^2 / (2 m r^2)``)."""
    out: list[sp.Expr] = [sp.S.One]
    for _, p in pairs:
        coef = sp.cancel(H.diff(p, 2) / 2)
        if coef == 0 or coef.free_symbols & {pp for _, pp in pairs}:
            continue
        for f in (sp.cancel(1 / coef), sp.denom(coef)):
            if f.free_symbols & {q for q, _ in pairs} and f not in out:
                out.append(f)
    return out


def _components(terms: Sequence[sp.Expr], pairs: Sequence[tuple[sp.Symbol, sp.Symbol]]) -> tuple[list, list]:
    """Union-find of coordinate indices over the terms; returns (components as index lists, coupling terms)."""
    parent = list(range(len(pairs)))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    coupling = []
    for term in terms:
        fs = term.free_symbols
        idx = [i for i, (q, p) in enumerate(pairs) if q in fs or p in fs]
        if len(idx) > 1:
            coupling.append(term)
        for i in idx[1:]:
            parent[find(i)] = find(idx[0])
    groups: dict[int, list[int]] = {}
    for i in range(len(pairs)):
        groups.setdefault(find(i), []).append(i)
    return sorted(groups.values()), coupling


def _positive_root(expr: sp.Expr, p: sp.Symbol, what: str) -> sp.Expr:
    sols = sp.solve(expr, p)
    if not sols:
        raise ModelError(f"cannot solve the separated equation {what} = 0 for {p}")
    sol = max(sols, key=lambda e: sp.sympify(e).could_extract_minus_sign() is False)
    return sp.simplify(sol)


def separate(
    Hx: sp.Expr,
    energy: sp.Expr,
    pairs: Sequence[tuple[sp.Symbol, sp.Symbol]],
    factor: Any,
    equations: list,
    constants: dict,
    momenta: dict,
    used_factors: list,
) -> None:
    """Separate ``Hx = energy`` in ``pairs`` (recursively); fill equations, constants and momenta in place."""
    if len(pairs) == 1:
        p = pairs[0][1]
        equations.append(sp.Eq(Hx, energy))
        momenta[p] = _positive_root(Hx - energy, p, f"{Hx} - ({energy})")
        return
    factors = [sp.sympify(factor)] if factor is not None else candidate_factors(Hx, pairs)
    tried = []
    for phi in factors:
        # multiply term by term and cancel, so that phi is not distributed before it cancels a denominator
        terms = [
            u for v in sp.Add.make_args(sp.expand(Hx - energy)) for u in sp.Add.make_args(sp.expand(sp.cancel(phi * v)))
        ]
        comps, coupling = _components(terms, pairs)
        if len(comps) < 2:
            tried.append((phi, coupling))
            continue
        used_factors.append(phi)
        sums = {tuple(c): sp.S.Zero for c in comps}
        rest = sp.S.Zero
        for term in terms:
            fs = term.free_symbols
            idx = [i for i, (q, p) in enumerate(pairs) if q in fs or p in fs]
            if not idx:
                rest += term
                continue
            key = next(tuple(c) for c in comps if idx[0] in c)
            sums[key] += term
        energy_syms = energy.free_symbols
        main = next((key for key, g in sums.items() if g.free_symbols & energy_syms), tuple(comps[-1]))
        total = rest
        for key, g in sums.items():
            sub_pairs = [pairs[i] for i in key]
            missing = [p for q, p in sub_pairs if p not in g.free_symbols]
            if missing:
                raise ModelError(
                    f"after multiplying by {phi} the momenta {missing} drop out of their separated part {g}: H is "
                    "degenerate in them"
                )
            if key == main:
                continue
            name = "_".join(q.name for q, _ in sub_pairs)
            beta = sp.Symbol(f"beta_{name}", real=True)
            constants[sub_pairs[0][0] if len(sub_pairs) == 1 else tuple(q for q, _ in sub_pairs)] = beta
            total += beta
            separate(g, beta, sub_pairs, None, equations, constants, momenta, used_factors)
        separate(sums[main], -total, [pairs[i] for i in main], None, equations, constants, momenta, used_factors)
        return
    lines = []
    for phi, coupling in tried:
        shown = ", ".join(str(c) for c in coupling[:3]) or "(none)"
        lines.append(f"factor {phi}: coupling terms {shown}")
    raise ModelError(
        "H does not separate additively in " + ", ".join(q.name for q, _ in pairs) + " (Stäckel/Liouville "
        "separation after multiplying H - h by a factor; Landau & Lifshitz, §48): " + "; ".join(lines) + ". Pass "
        "factor= if a different factor separates it, or use other coordinates"
    )
