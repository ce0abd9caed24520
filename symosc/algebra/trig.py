"""Cheap trigonometric identities on sums of products, for presentation-ready equations of motion.

``sympy.trigsimp`` searches many rewritings and costs seconds on a long chain's mass matrix; the equations of motion
of linkages need only the identities their kinetic energies produce, which a hash lookup over the terms finds:

* ``c sin(u)**2 + c cos(u)**2 = c``;
* ``c sin(u) sin(v) + c cos(u) cos(v) = c cos(u - v)``;
* ``c sin(u) cos(v) - c cos(u) sin(v) = c sin(u - v)``;

where ``c`` is the same coefficient (or product with further factors) in both terms.  Each pass is linear in the
number of terms; passes repeat until nothing changes (products of several pairs).
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from .._trig import _split, trig_reduce_groups
from .._validate import validated
from ..errors import ParameterError

__all__ = ["trig_reduce", "trig_reduce_groups"]


@validated
def trig_reduce(expr: Any) -> Any:
    """``expr`` with the identities applied term by term (a Matrix entry by entry); cheap, unlike ``trigsimp``.

    Parameters
    ----------
    expr : Expr or Matrix
        A sum of products (expanded first).

    Returns
    -------
    Expr or Matrix

    Examples
    --------
    >>> import sympy as sp
    >>> phi, l, m = sp.symbols("phi l m")
    >>> trig_reduce(l**2 * m * sp.sin(phi) ** 2 + l**2 * m * sp.cos(phi) ** 2)
    l**2*m
    >>> a, b = sp.symbols("a b")
    >>> trig_reduce(sp.sin(a) * sp.cos(b) - sp.cos(a) * sp.sin(b))
    sin(a - b)

    See Also
    --------
    trig_reduce_groups, sympy.trigsimp
    """
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(trig_reduce)
    e = sp.sympify(expr)
    if isinstance(e, sp.Basic) and e.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise ParameterError(f"trig_reduce(): expr must be finite, got {e} (nan or an infinity)")
    if not e.has(sp.sin, sp.cos):
        return e
    groups: dict[sp.Expr, list[sp.Expr]] = {}
    for term in sp.Add.make_args(sp.expand(e, power_exp=False, log=False)):
        d, c = _split(term)
        groups.setdefault(d, []).append(c)
    reduced = trig_reduce_groups([(d, sp.Add(*cs)) for d, cs in groups.items()])
    return sp.Add(*(c * d for d, c in reduced))
