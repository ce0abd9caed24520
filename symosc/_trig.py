"""Cheap trigonometric identities on sums of products, for presentation-ready equations of motion.

The engine behind :func:`symosc.algebra.trig_reduce` (private: the Lagrange engine uses it without importing
:mod:`symosc.algebra`).

``sympy.trigsimp`` searches many rewritings and costs seconds on a long chain's mass matrix; the equations of motion
of linkages need only the identities their kinetic energies produce, which a hash lookup over the terms finds:

* ``c sin(u)**2 + c cos(u)**2 = c``;
* ``c sin(u) sin(v) + c cos(u) cos(v) = c cos(u - v)``;
* ``c sin(u) cos(v) - c cos(u) sin(v) = c sin(u - v)``;

where ``c`` is the same coefficient (or product with further factors) in both terms.  Each pass is linear in the
number of terms; passes repeat until nothing changes (products of several pairs).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import sympy as sp

from ._validate import validated

__all__ = ["trig_reduce_groups"]


def _split(term: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``(trigonometric factors, the rest)`` of one product term."""
    trig, rest = [], []
    for f in sp.Mul.make_args(term):
        base = f.base if f.is_Pow else f
        (trig if isinstance(base, sp.sin | sp.cos) else rest).append(f)
    return sp.Mul(*trig), sp.Mul(*rest)


def _signature(factors: Iterable[sp.Expr]) -> frozenset:
    """A product's factors as a multiset (hashable), so that partners are looked up without building products."""
    count: dict = {}
    for f in factors:
        count[f] = count.get(f, 0) + 1
    return frozenset(count.items())


class _Cos:
    """``sin(u) -> cos(u)`` and ``sin(u)**2 -> cos(u)**2``, each built once per argument."""

    def __init__(self) -> None:
        self.memo: dict = {}

    def __call__(self, f: sp.Expr) -> sp.Expr:
        out = self.memo.get(f)
        if out is None:
            out = self.memo[f] = _cos_of(f.args[0]) if isinstance(f, sp.sin) else _cos_of(f.base.args[0]) ** 2
        return out


def plain_argument(u: sp.Expr) -> bool:
    """Whether ``u`` is a symbol or a sum of rational multiples of symbols (``phi1 - phi2``).

    Such an argument of an evaluated ``sin`` or ``cos`` is already in the canonical form that both functions share
    (they normalise the sign of the argument the same way, and it has no multiple of pi to shift): the other
    function of it is built without SymPy's evaluation, whose assumption queries cost most of the time on a cold
    cache.
    """
    if u.is_Symbol:
        return True
    return u.is_Add and all(a.as_coeff_Mul()[1].is_Symbol and a.as_coeff_Mul()[0].is_Rational for a in u.args)


def _cos_of(u: sp.Expr) -> sp.Expr:
    """``cos(u)`` for the argument ``u`` of an evaluated ``sin(u)`` (see :func:`plain_argument`)."""
    return sp.cos(u, evaluate=False) if plain_argument(u) else sp.cos(u)


def _partners(factors: list, cos: _Cos) -> Iterable[tuple[frozenset, Any, int]]:
    """For a product with these factors: ``(partner signature, build combined, sign)`` such that
    ``c d + sign c partner = c combined`` (the combined product is built only on a match)."""
    for k, f in enumerate(factors):
        if f.is_Pow and f.exp == 2 and isinstance(f.base, sp.sin):
            rest = factors[:k] + factors[k + 1 :]
            yield _signature([*rest, cos(f)]), (lambda rest=rest: sp.Mul(*rest)), 1
    singles = [(k, f) for k, f in enumerate(factors) if isinstance(f, sp.sin | sp.cos)]
    for a in range(len(singles)):
        for b in range(len(singles)):
            (i, f), (j, g) = singles[a], singles[b]
            if a == b or f.args[0] == g.args[0]:
                continue
            u, v = f.args[0], g.args[0]
            rest = [x for k, x in enumerate(factors) if k not in (i, j)]
            if isinstance(f, sp.sin) and isinstance(g, sp.sin) and a < b:
                combine = lambda rest=rest, u=u, v=v: sp.Mul(*rest, _angle(sp.cos, u, v))  # noqa: E731
                yield _signature([*rest, cos(f), cos(g)]), combine, 1
            elif isinstance(f, sp.sin) and isinstance(g, sp.cos):
                yield (
                    _signature([*rest, cos(f), sp.sin(v)]),
                    (lambda rest=rest, u=u, v=v: sp.Mul(*rest, _angle(sp.sin, u, v))),
                    -1,
                )


def _angle(func: Any, u: sp.Expr, v: sp.Expr) -> sp.Expr:
    """``cos(u - v)`` or ``sin(u - v)`` in SymPy's canonical form (leading term without a minus sign), built without
    the trigonometric ``eval`` (its assumption queries cost milliseconds per call on a cold cache)."""
    arg = u - v
    if not arg.is_Add or not sp.Add.make_args(arg)[0].as_coeff_Mul()[0].is_negative:
        return func(arg, evaluate=False) if arg.is_Add else func(arg)
    flipped = func(-arg, evaluate=False)
    return flipped if func is sp.cos else -flipped


@validated
def trig_reduce_groups(groups: list) -> list:
    """Apply the identities to ``sum(c_k * d_k)`` given as pairs ``(d_k, c_k)`` (``d_k`` distinct products).

    Parameters
    ----------
    groups : list of (Expr, Expr)
        Factor depending on the variables and its constant coefficient, as the Lagrange engine collects the
        kinetic energy.

    Returns
    -------
    list of (Expr, Expr)
        The same sum with every matched pair replaced by one term (zero coefficients dropped).

    Examples
    --------
    >>> import sympy as sp
    >>> x, y, c = sp.symbols("x y c")
    >>> pairs = [(sp.sin(x) ** 2, c), (sp.cos(x) ** 2, c), (sp.sin(x) * sp.sin(y), 2), (sp.cos(x) * sp.cos(y), 2)]
    >>> trig_reduce_groups(pairs)
    [(1, c), (cos(x - y), 2)]

    See Also
    --------
    trig_reduce
    """
    table: dict[sp.Expr, sp.Expr] = {}
    for d, c in groups:
        table[d] = table.get(d, sp.S.Zero) + c
    if not any(f.has(sp.sin) for f in table):
        return [(d, c) for d, c in table.items() if c != 0]
    cos = _Cos()
    changed = True
    while changed:
        changed = False
        by_signature = {_signature(sp.Mul.make_args(d)): d for d in table}
        for d in list(table):
            if d not in table:
                continue
            c = table[d]
            for signature, combine, sign in _partners(list(sp.Mul.make_args(d)), cos):
                partner = by_signature.get(signature)
                if partner is not None and partner != d and partner in table and table[partner] == sign * c:
                    del table[d], table[partner]
                    combined = combine()
                    table[combined] = table.get(combined, sp.S.Zero) + c
                    by_signature[_signature(sp.Mul.make_args(combined))] = combined
                    changed = True
                    break
    return [(d, c) for d, c in table.items() if c != 0]


#: :func:`trig_reduce_groups` without the argument checks, for the Lagrange engine (its groups are built internally)
trig_reduce_groups_unchecked = trig_reduce_groups.__wrapped__
