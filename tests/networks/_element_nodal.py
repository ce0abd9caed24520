"""Reference nodal analysis at element level (tests only): independent of the package's loop and chain code.

A network is flattened to two-terminal elements (R, L, C; coupled coils of a Brune section by their T equivalent)
between named nodes; node voltages solve Kirchhoff's current law with SymPy's linear solver.
"""

from __future__ import annotations

import itertools

import sympy as sp

from symosc.networks import BruneSection, Capacitor, Inductor, Parallel, Resistor, Series

_counter = itertools.count()


def flatten(net, a, b, out: list, p: sp.Symbol) -> list:
    """Append ``(a, b, admittance)`` for every element of ``net`` connected between nodes ``a`` and ``b``."""
    if isinstance(net, Resistor):
        out.append((a, b, 1 / net.R))
    elif isinstance(net, Inductor):
        out.append((a, b, 1 / (net.L * p)))
    elif isinstance(net, Capacitor):
        out.append((a, b, net.C * p))
    elif isinstance(net, Series):
        nodes = [a] + [f"s{next(_counter)}" for _ in net.parts[:-1]] + [b]
        for part, u, v in zip(net.parts, nodes[:-1], nodes[1:], strict=True):
            flatten(part, u, v, out, p)
    elif isinstance(net, Parallel):
        for part in net.parts:
            flatten(part, a, b, out, p)
    elif isinstance(net, BruneSection):  # T equivalent: (Lp - M) p, shunt M p + 1/(C p), (Ls - M) p, then the load
        c, m, n = (f"b{next(_counter)}" for _ in range(3))
        out.append((a, c, 1 / ((net.Lp - net.M) * p)))
        out.append((c, m, 1 / (net.M * p)))
        out.append((m, b, net.C * p))
        out.append((c, n, 1 / ((net.Ls - net.M) * p)))
        flatten(net.load, n, b, out, p)
    else:
        raise TypeError(type(net))
    return out


def node_voltages(branches: list, fixed: dict, injected: dict | None = None) -> dict:
    """Solve KCL for the free node voltages; ``fixed`` maps nodes to given voltages, ``injected`` adds currents."""
    nodes = sorted({n for a, b, _ in branches for n in (a, b)} - set(fixed), key=str)
    V = {n: sp.Symbol(f"V_{n}") for n in nodes}
    V.update(fixed)
    eqs = []
    for n in nodes:
        expr = sum(((V[n] - V[b]) * y for a, b, y in branches if a == n), sp.Integer(0))
        expr += sum(((V[n] - V[a]) * y for a, b, y in branches if b == n), sp.Integer(0))
        eqs.append(expr - (injected or {}).get(n, 0))
    sol = sp.solve(eqs, [V[n] for n in nodes], dict=True)[0] if nodes else {}
    return {n: sp.cancel(sp.sympify(V[n]).subs(sol)) for n in V}


def driving_point_impedance(branches: list, a, b) -> sp.Expr:
    """``1 / (current drawn from a unit source between a and b)``."""
    V = node_voltages(branches, {a: sp.Integer(1), b: sp.Integer(0)})
    current = sum(((V[a] - V[v]) * y for u, v, y in branches if u == a), sp.Integer(0))
    current += sum(((V[a] - V[u]) * y for u, v, y in branches if v == a), sp.Integer(0))
    return sp.cancel(1 / current)


def node_voltages_at(branches: list, fixed: dict, p: sp.Symbol, at, dps: int = 50) -> dict:
    """Node voltages at ``p = at`` in ``dps``-digit mpmath arithmetic (for element values with radicals)."""
    import mpmath

    with mpmath.workdps(dps):
        x = mpmath.mpmathify(at)
        nodes = sorted({n for a, b, _ in branches for n in (a, b)} - set(fixed), key=str)
        index = {n: i for i, n in enumerate(nodes)}
        A = mpmath.zeros(len(nodes), len(nodes))
        rhs = mpmath.zeros(len(nodes), 1)
        for a, b, y in branches:
            yv = mpmath.mpmathify(complex(0)) + sp.lambdify(p, y, "mpmath")(x) if y.has(p) else mpmath.mpf(0)
            if not y.has(p):
                yv = mpmath.mpmathify(sp.N(y, dps + 10))
            for u, v in ((a, b), (b, a)):
                if u in index:
                    A[index[u], index[u]] += yv
                    if v in index:
                        A[index[u], index[v]] -= yv
                    else:
                        rhs[index[u]] += yv * mpmath.mpmathify(fixed[v])
        sol = mpmath.lu_solve(A, rhs)
        out = {n: sol[index[n]] for n in nodes}
        out.update({n: mpmath.mpmathify(v) for n, v in fixed.items()})
        return out
