"""Nodal analysis of small terminal-level netlists (private): used for the Brune validity test."""

from __future__ import annotations

import random
from dataclasses import dataclass

import sympy as sp

from ...errors import ModelError


@dataclass(frozen=True)
class Netlist:
    """Branches between named nodes and the four terminals ``(1, 1', 2, 2')`` (some may coincide).

    ``branches`` is a tuple of ``(pairs, Zb)``: ``pairs`` a tuple of node pairs ``(a, b)`` and ``Zb`` the branch
    impedance matrix (1x1 for a plain element; 2x2 for coupled coils ``p*[[L1, M], [M, L2]]``).
    """

    branches: tuple
    terminals: tuple

    @property
    def nodes(self) -> tuple:
        seen: dict = {}
        for t in self.terminals:
            seen.setdefault(t, None)
        for pairs, _ in self.branches:
            for a, b in pairs:
                seen.setdefault(a, None)
                seen.setdefault(b, None)
        return tuple(seen)

    def renamed(self, prefix: str, merge: dict) -> Netlist:
        def r(n):
            key = f"{prefix}{n}"
            return merge.get(key, key)

        branches = tuple((tuple((r(a), r(b)) for a, b in pairs), Zb) for pairs, Zb in self.branches)
        return Netlist(branches, tuple(r(t) for t in self.terminals))


def admittance_matrix(net: Netlist) -> tuple[tuple, sp.Matrix]:
    nodes = net.nodes
    index = {n: i for i, n in enumerate(nodes)}
    Y = sp.zeros(len(nodes), len(nodes))
    for pairs, Zb in net.branches:
        Yb = sp.Matrix(Zb).inv()
        inc = sp.zeros(len(nodes), len(pairs))
        for j, (a, b) in enumerate(pairs):
            inc[index[a], j] += 1
            inc[index[b], j] -= 1
        Y += inc * Yb * inc.T
    return nodes, Y


def chain_from_netlist(net: Netlist, subs: dict | None = None) -> sp.Matrix:
    """Chain matrix (book convention) of a netlist by modified nodal analysis, optionally at numeric values."""
    nodes, Y = admittance_matrix(net)
    if subs:
        Y = Y.xreplace(subs)
    index = {n: i for i, n in enumerate(nodes)}
    n = len(nodes)
    t0, t1, t2, t3 = (index[t] for t in net.terminals)
    columns = []
    for Ey, Iy in ((1, 0), (0, 1)):
        # unknowns: node voltages (n) and the input current Ix; equations: KCL (n), V[t1] = 0, V[t2] - V[t3] = Ey
        M = sp.zeros(n + 2, n + 1)
        rhs = sp.zeros(n + 2, 1)
        M[:n, :n] = Y
        M[t0, n] -= 1  # the input current Ix is injected at terminal 1 ...
        M[t1, n] += 1  # ... and leaves at 1'
        rhs[t2] -= Iy  # the output current Iy leaves at 2 and returns at 2'
        rhs[t3] += Iy
        M[n, t1] = 1
        M[n + 1, t2] += 1
        M[n + 1, t3] -= 1
        rhs[n + 1] = Ey
        # one KCL row is redundant (total current balance): reduced row echelon form over the field of rational
        # functions (DomainMatrix: much faster than Matrix.gauss_jordan_solve on entries rational in p)
        sol = _exact_solve(M, rhs)
        columns.append((sp.cancel(sol[t0] - sol[t1]), sp.cancel(sol[n])))
    return sp.Matrix([[columns[0][0], columns[1][0]], [columns[0][1], columns[1][1]]])


def sample_points(exprs: list, p: sp.Symbol, count: int = 2, seed: int = 1) -> list[dict]:
    """Random positive rational values for every free symbol (and ``p``)."""
    rng = random.Random(seed)
    symbols = sorted(set().union(*(sp.sympify(e).free_symbols for e in exprs)) | {p}, key=str)
    return [{s: sp.Rational(rng.randint(3, 97), rng.randint(3, 29)) for s in symbols} for _ in range(count)]


def cascade_netlists(netlists: list[Netlist | None]) -> Netlist | None:
    """Terminal-level netlist of a cascade (output terminals of each joined to the input terminals of the next)."""
    if any(net is None for net in netlists):
        return None
    branches: list = []
    terminals = None
    prev = None
    for i, each in enumerate(netlists):
        t = each.terminals
        merge = {} if prev is None else {f"{i}.{t[0]}": prev[2], f"{i}.{t[1]}": prev[3]}
        net = each.renamed(f"{i}.", merge)
        branches.extend(net.branches)
        terminals = net.terminals if terminals is None else (terminals[0], terminals[1], *net.terminals[2:])
        prev = net.terminals
    return Netlist(tuple(branches), terminals)


def _exact_solve(M: sp.Matrix, rhs: sp.Matrix) -> list:
    """The unique solution of the (possibly overdetermined, consistent) system ``M x = rhs``."""
    from sympy.polys.matrices import DomainMatrix

    whole = DomainMatrix.from_Matrix(M.row_join(rhs))
    if whole.domain.is_EX or whole.domain.is_EXRAW:
        try:
            sol, params = M.gauss_jordan_solve(rhs)
        except ValueError as exc:
            raise ModelError("the connected network has no chain matrix (inconsistent port equations)") from exc
        if params.shape[0]:
            raise ModelError("the connected network is not determined by its ports (floating parts)")
        return list(sol)
    field = whole.to_field()
    rref, pivots = field.rref()
    unknowns = M.cols
    if unknowns in pivots:
        raise ModelError("the connected network has no chain matrix (inconsistent port equations)")
    if len(pivots) < unknowns:
        raise ModelError("the connected network is not determined by its ports (floating parts)")
    to_expr = field.domain.to_sympy
    rows = rref.to_list()
    x = [sp.S.Zero] * unknowns
    for i, col in enumerate(pivots):
        x[col] = to_expr(rows[i][unknowns])
    return x
