"""Shared symbol conventions.

Time is :data:`t`.  A generalised coordinate ``q`` is a plain :class:`~sympy.Symbol`; its velocity and
acceleration are the plain symbols :func:`dot(q) <dot>` and :func:`ddot(q) <ddot>` (named ``q_dot`` and
``q_ddot``, with the same assumptions as ``q``).  Differentiating plain symbols and applying the chain
rule is much faster than differentiating trees of ``Function(t)`` objects.

Examples
--------
>>> import sympy as sp
>>> from symosc.symbols import dot, ddot, t
>>> x = sp.Symbol("x", real=True)
>>> dot(x), ddot(x), t
(x_dot, x_ddot, t)
"""

from __future__ import annotations

import re
from collections.abc import Iterable

import sympy as sp

from ._validate import validated

__all__ = ["ddot", "dot", "natural_key", "sort_symbols", "t"]

#: The time symbol.  Equal to ``sympy.physics.mechanics.dynamicsymbols._t``.
t = sp.Symbol("t")


@validated
def dot(q: sp.Symbol) -> sp.Symbol:
    """Velocity symbol of the coordinate ``q`` (named ``<q>_dot``).

    Parameters
    ----------
    q : sympy.Symbol
        The coordinate, a plain Symbol; the velocity symbol keeps its assumptions (``real=True``, ...).

    Examples
    --------
    >>> phi = sp.Symbol("phi", real=True)
    >>> dot(phi), dot(phi).is_real
    (phi_dot, True)
    """
    return sp.Symbol(f"{q.name}_dot", **q.assumptions0)


@validated
def ddot(q: sp.Symbol) -> sp.Symbol:
    """Acceleration symbol of the coordinate ``q`` (named ``<q>_ddot``).

    Parameters
    ----------
    q : sympy.Symbol
        The coordinate, a plain Symbol; the acceleration symbol keeps its assumptions (``real=True``, ...).

    Examples
    --------
    >>> ddot(sp.Symbol("x"))
    x_ddot
    """
    return sp.Symbol(f"{q.name}_ddot", **q.assumptions0)


@validated
def natural_key(symbol: sp.Symbol) -> tuple:
    """Sort key that orders ``m2`` before ``m10``.

    Parameters
    ----------
    symbol : sympy.Symbol
        The symbol whose name is split into text and integer parts.

    Examples
    --------
    >>> natural_key(sp.Symbol("m10")) > natural_key(sp.Symbol("m2"))
    True
    """
    parts = re.split(r"(\d+)", symbol.name)
    return tuple((0, int(p)) if p.isdigit() else (1, p) for p in parts)


@validated
def sort_symbols(symbols: Iterable[sp.Symbol]) -> tuple[sp.Symbol, ...]:
    """Symbols in natural name order (``l1, l2, ..., l10``), duplicates removed.

    Parameters
    ----------
    symbols : iterable of sympy.Symbol
        The symbols to sort (any iterable: a set, a tuple, ...).

    Examples
    --------
    >>> sort_symbols(sp.symbols("m10 m2 g"))
    (g, m2, m10)
    """
    return tuple(sorted(set(symbols), key=natural_key))
