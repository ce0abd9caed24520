"""Loop (mesh) analysis of passive R, L, C networks (private): branch lists, fundamental loops, loop matrices."""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ...errors import ModelError, ParameterError
from .oneports import BruneSection, Capacitor, Inductor, OnePort, Parallel, Resistor, Series


@dataclass(frozen=True)
class Edge:
    """One element between nodes ``a -> b``: resistance, inductance and elastance (1/C) coefficients."""

    a: Any
    b: Any
    R: sp.Expr
    L: sp.Expr
    S: sp.Expr
    label: str


class _Names:
    def __init__(self) -> None:
        self.count = 0

    def new(self) -> str:
        self.count += 1
        return f"n{self.count}"


def expand_port(net: OnePort, a: Any, b: Any, names: _Names, edges: list, mutual: dict) -> None:
    """Append the edges of the one-port ``net`` connected between nodes ``a`` and ``b``."""
    zero = sp.Integer(0)
    if isinstance(net, Resistor):
        edges.append(Edge(a, b, net.R, zero, zero, repr(net)))
    elif isinstance(net, Inductor):
        edges.append(Edge(a, b, zero, net.L, zero, repr(net)))
    elif isinstance(net, Capacitor):
        edges.append(Edge(a, b, zero, zero, 1 / net.C, repr(net)))
    elif isinstance(net, Series):
        nodes = [a] + [names.new() for _ in net.parts[:-1]] + [b]
        for part, u, v in zip(net.parts, nodes[:-1], nodes[1:], strict=True):
            expand_port(part, u, v, names, edges, mutual)
    elif isinstance(net, Parallel):
        for part in net.parts:
            expand_port(part, a, b, names, edges, mutual)
    elif isinstance(net, BruneSection):
        # coils Lp (a -> m) and Ls (n -> m) with mutual M; capacitor m -> b; load n -> b.  Its T equivalent is
        # (Lp - M) from a, (Ls - M) from n and M in the common branch, as in BruneSection.impedance
        m, n = names.new(), names.new()
        zero = sp.Integer(0)
        i = len(edges)
        edges.append(Edge(a, m, zero, net.Lp, zero, f"Lp({net.Lp})"))
        edges.append(Edge(n, m, zero, net.Ls, zero, f"Ls({net.Ls})"))
        mutual[(i, i + 1)] = net.M
        edges.append(Edge(m, b, zero, zero, 1 / net.C, f"C({net.C})"))
        expand_port(net.load, n, b, names, edges, mutual)
    else:
        raise ParameterError(
            f"energy functions need a network of R, L, C elements (and Brune sections); got {type(net).__name__} "
            f"{net!r}, whose elements are unknown"
        )


def fundamental_loops(edges: list[Edge], a: Any, b: Any) -> tuple[sp.Matrix, list[str]]:
    """Loop matrix ``B`` (loops x edges, entries 0, ±1) with the source loop (b -> a through the source) first."""
    nodes: dict = {}
    for e in edges:
        nodes.setdefault(e.a, []).append(e)
        nodes.setdefault(e.b, []).append(e)
    if a not in nodes or b not in nodes:
        raise ModelError("the driving terminals are not connected to the network")
    parent: dict = {a: None}  # node -> (edge index, parent node)
    depth = {a: 0}
    index = {id(e): k for k, e in enumerate(edges)}
    tree: set[int] = set()
    queue = deque([a])
    while queue:
        u = queue.popleft()
        for e in nodes[u]:
            v = e.b if e.a == u else e.a
            if v not in parent:
                parent[v] = (index[id(e)], u)
                depth[v] = depth[u] + 1
                tree.add(index[id(e)])
                queue.append(v)
    if b not in parent:
        raise ModelError("the network is open between its terminals (no path from one terminal to the other)")
    if len(parent) != len(nodes):
        raise ModelError("the network has parts not connected to its terminals")

    def path(u: Any, v: Any) -> list[tuple[int, int]]:
        """Tree edges with the sign of traversal on the path u -> v."""
        up, down = [], []
        while depth[u] > depth[v]:
            k, w = parent[u]
            up.append((k, 1 if edges[k].a == u else -1))
            u = w
        while depth[v] > depth[u]:
            k, w = parent[v]
            down.append((k, 1 if edges[k].b == v else -1))
            v = w
        while u != v:
            k, w = parent[u]
            up.append((k, 1 if edges[k].a == u else -1))
            u = w
            k, w = parent[v]
            down.append((k, 1 if edges[k].b == v else -1))
            v = w
        return up + down[::-1]

    rows = []
    labels = []
    source = sp.zeros(1, len(edges))
    for k, s in path(a, b):  # the loop current enters the network at a and returns from b through the source
        source[0, k] += s
    rows.append(source)
    labels.append("driving loop")
    for k, e in enumerate(edges):
        if k in tree:
            continue
        row = sp.zeros(1, len(edges))
        row[0, k] = 1
        for j, s in path(e.b, e.a):
            row[0, j] += s
        rows.append(row)
        labels.append(f"loop through {e.label}")
    return sp.Matrix.vstack(*rows), labels


def loop_matrices(edges: list[Edge], mutual: dict, B: sp.Matrix) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix]:
    """``B diag(R) B^T``, ``B L_branch B^T`` (with mutual inductances), ``B diag(S) B^T``."""
    n = len(edges)
    Rb = sp.diag(*[e.R for e in edges]) if n else sp.zeros(0, 0)
    Lb = sp.diag(*[e.L for e in edges]) if n else sp.zeros(0, 0)
    Sb = sp.diag(*[e.S for e in edges]) if n else sp.zeros(0, 0)
    for (i, j), M in mutual.items():
        Lb[i, j] += M
        Lb[j, i] += M
    return (B * Rb * B.T).applyfunc(sp.expand), (B * Lb * B.T).applyfunc(sp.expand), (B * Sb * B.T).applyfunc(sp.expand)
