"""Loop (mesh) equations of a passive network from its graph (Bulgakov (1954), §7.10-7.11).

Each branch joins two nodes and carries an operator impedance ``z(D) = L D + R + 1/(C D)`` and an
electromotive force.  Fundamental loops are taken from a spanning forest; their number is
``n = B - N + K`` (branches, nodes, connected parts; eq. (7.82)), and the loop equations are
``Z(D) i = e`` with ``Z = B_l diag(z) B_l^T`` symmetric (reciprocity, eq. (7.87)).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError

__all__ = ["LoopEquations", "loop_equations"]


@dataclass(frozen=True)
class LoopEquations(SymPyPrintable):
    """``Z i = e`` for the loop currents ``i``; branch currents are ``loop_matrix.T * i``.

    Attributes
    ----------
    loop_matrix : Matrix
        ``B_l`` (loops x branches) with entries 0, +1 (branch along the loop), -1 (against it).
    impedance : Matrix
        ``Z = B_l diag(z) B_l^T``.
    emf : Matrix
        ``B_l e``.

    See Also
    --------
    loop_equations
    """

    loop_matrix: sp.Matrix
    impedance: sp.Matrix
    emf: sp.Matrix

    def __repr__(self) -> str:
        return f"LoopEquations({self.loop_matrix.rows} loops, {self.loop_matrix.cols} branches)"

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(self.impedance)} i = {sp.latex(self.emf)}$$"

    @property
    def is_reciprocal(self) -> bool:
        """True when ``Z`` is symmetric (a passive network; an active element such as a triode breaks it)."""
        return (self.impedance - self.impedance.T).applyfunc(sp.simplify) == sp.zeros(*self.impedance.shape)


@validated
def loop_equations(branches: Sequence[Sequence[Any]]) -> LoopEquations:
    """Loop equations of a network given as branches ``(from_node, to_node, impedance[, emf])``.

    The emf drives current from ``from_node`` to ``to_node`` inside its branch.

    Parameters
    ----------
    branches : sequence of tuples
        The branches ``(from_node, to_node, impedance)`` or ``(from_node, to_node, impedance, emf)``: two different
        hashable node labels, the operator impedance ``z(D) = L D + R + 1/(C D)`` (a SymPy expression) and the optional
        electromotive force (default 0).

    Examples
    --------
    Two resistors in a ring with a source: one loop.

    >>> import sympy as sp
    >>> R1, R2, e = sp.symbols("R1 R2 e", positive=True)
    >>> le = loop_equations([(0, 1, R1, e), (1, 0, R2)])
    >>> le.impedance, le.emf
    (Matrix([[R1 + R2]]), Matrix([[e]]))

    See Also
    --------
    electromechanical_system
    """
    rows = []
    for k, b in enumerate(branches):
        if len(b) not in (3, 4):
            raise ModelError(f"branch {k} must be (from_node, to_node, impedance[, emf]), got {b!r}")
        a, c = b[0], b[1]
        if a == c:
            raise ModelError(f"branch {k} joins node {a!r} to itself")
        rows.append((a, c, sp.sympify(b[2]), sp.sympify(b[3]) if len(b) == 4 else sp.S.Zero))
    nodes = sorted({r[0] for r in rows} | {r[1] for r in rows}, key=str)
    adj: dict[Any, list[tuple[Any, int]]] = {v: [] for v in nodes}
    for k, (a, c, _, _) in enumerate(rows):
        adj[a].append((c, k))
        adj[c].append((a, k))
    parent: dict[Any, tuple[Any, int] | None] = {}
    depth: dict[Any, int] = {}
    tree: set[int] = set()
    parts = 0
    for root in nodes:
        if root in parent:
            continue
        parts += 1
        parent[root], depth[root] = None, 0
        queue = [root]
        while queue:
            v = queue.pop(0)
            for u, k in adj[v]:
                if u not in parent:
                    parent[u], depth[u] = (v, k), depth[v] + 1
                    tree.add(k)
                    queue.append(u)
    chords = [k for k in range(len(rows)) if k not in tree]
    n_loops = len(rows) - len(nodes) + parts  # eq. (7.82); equals len(chords)
    Bl = sp.zeros(n_loops, len(rows))

    def walk_up(v: Any, target: Any, row: int, sign: int) -> None:
        # the loop runs from v to target through the tree; record branch orientation relative to that run
        while v != target:
            u, k = parent[v]
            a, _, _, _ = rows[k]
            Bl[row, k] += sign * (1 if a == v else -1)
            v = u

    for row, k in enumerate(chords):
        a, c, _, _ = rows[k]
        Bl[row, k] = 1
        # continue the loop from c back to a through the tree: c -> lca -> a
        x, y = c, a
        while x != y:
            if depth[x] >= depth[y]:
                x = parent[x][0]
            else:
                y = parent[y][0]
        lca = x
        walk_up(c, lca, row, 1)
        walk_up(a, lca, row, -1)
    z = sp.diag(*[r[2] for r in rows])
    e = sp.Matrix([r[3] for r in rows])
    return LoopEquations(loop_matrix=Bl, impedance=(Bl * z * Bl.T).applyfunc(sp.expand), emf=Bl * e)
