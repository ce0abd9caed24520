"""Term-level calculus used by the Lagrange engine.

Energies of mechanical systems are sums of many small products (``m_k l_i l_j cos(phi_i) cos(phi_j)
phi_i' phi_j'``).  Working term by term — splitting the kinetic energy into its parts of degree 0, 1
and 2 in the velocities without expanding anything else, and differentiating each term only with
respect to the few coordinates it contains — keeps the derivation of an n-link chain at O(n^3) term
operations, where differentiating whole expression trees costs O(n^4) or more.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable, Sequence

import sympy as sp

from ..errors import ModelError

Monomial = tuple[int, ...]  # sorted velocity indices: () constant, (i,) linear, (i, j) quadratic with i <= j
TermDict = dict[Monomial, list[sp.Expr]]


def _merge(a: TermDict, b: TermDict) -> TermDict:
    out: TermDict = defaultdict(list)
    for d in (a, b):
        for k, v in d.items():
            out[k].extend(v)
    return out


def _multiply(a: TermDict, b: TermDict, what: str) -> TermDict:
    out: TermDict = defaultdict(list)
    for ka, va in a.items():
        for kb, vb in b.items():
            key = tuple(sorted(ka + kb))
            if len(key) > 2:
                raise ModelError(f"{what} is not quadratic in the velocities (found a term of degree {len(key)})")
            out[key].extend(x * y for x in va for y in vb)
    return out


def velocity_parts(expr: sp.Expr, velocities: Sequence[sp.Symbol], what: str = "T") -> TermDict:
    """Split ``expr`` into terms of degree 0, 1, 2 in ``velocities``.

    Returns a mapping ``monomial -> list of coefficient terms``; only products, sums and integer powers
    are opened, everything free of velocities is kept as it is.
    """
    index = {v: i for i, v in enumerate(velocities)}
    vset = set(velocities)

    def walk(e: sp.Expr) -> TermDict:
        if not (e.free_symbols & vset):
            return {(): [e]}
        if e in index:
            return {(index[e],): [sp.S.One]}
        if isinstance(e, sp.Add):
            out: TermDict = {}
            for arg in e.args:
                out = _merge(out, walk(arg))
            return out
        if isinstance(e, sp.Mul):
            const = [a for a in e.args if not (a.free_symbols & vset)]
            out = {(): [sp.Mul(*const)]}
            for arg in e.args:
                if arg.free_symbols & vset:
                    out = _multiply(out, walk(arg), what)
            return out
        if isinstance(e, sp.Pow) and e.exp.is_Integer and e.exp > 0:
            base = walk(e.base)
            out = base
            for _ in range(int(e.exp) - 1):
                out = _multiply(out, base, what)
            return out
        raise ModelError(
            f"{what} is not a polynomial of degree <= 2 in the velocities: the velocities appear inside {e}"
        )

    return {k: v for k, v in walk(sp.sympify(expr)).items() if v}


def expand_terms(expr: sp.Expr, variables: set[sp.Symbol]) -> list[sp.Expr]:
    """The additive terms of ``expr``, opening products of sums that involve ``variables``.

    No trigonometric rewriting; sums of constants are left as they are.
    """
    out: list[sp.Expr] = []
    for term in sp.Add.make_args(expr):
        factors = term.args if isinstance(term, sp.Mul) else (term,)
        if any(
            (isinstance(f, sp.Add) or (isinstance(f, sp.Pow) and isinstance(f.base, sp.Add)))
            and (f.free_symbols & variables)
            for f in factors
        ):
            out.extend(sp.Add.make_args(sp.expand(term, power_base=False, power_exp=False, log=False)))
        else:
            out.append(term)
    return out


def _product(args: Sequence[sp.Expr]) -> sp.Expr:
    """Product of a subset of the arguments of a canonical Mul (already ordered and combined)."""
    if not args:
        return sp.S.One
    if len(args) == 1:
        return args[0]
    if any(isinstance(a, sp.Add) for a in args):
        return sp.Mul(*args)
    return sp.Mul._from_args(tuple(args))


Groups = list[tuple[sp.Expr, sp.Expr]]  # (factor depending on the variables, constant coefficient)


def group_terms(terms: Iterable[sp.Expr], variables: set[sp.Symbol]) -> Groups:
    """Collect ``sum(terms)`` as ``sum_k c_k * d_k`` with distinct factors ``d_k`` depending on ``variables``.

    Each distinct dependent factor (e.g. ``cos(phi1)*cos(phi2)``) then needs differentiating only once,
    whatever the number of terms that share it.
    """
    groups: dict[tuple, list[sp.Expr]] = {}
    for term in terms:
        factors = term.args if isinstance(term, sp.Mul) else (term,)
        dep = tuple(f for f in factors if f.free_symbols & variables)
        ind = [f for f in factors if not (f.free_symbols & variables)]
        groups.setdefault(dep, []).append(_product(ind))
    return [(_product(dep), sp.Add(*consts)) for dep, consts in groups.items()]


def grouped_gradient(groups: Groups, variables: Sequence[sp.Symbol]) -> list[list[sp.Expr]]:
    """Gradient of ``sum c_k d_k``: per variable the list of pieces ``c_k * d(d_k)/dv``."""
    index = {v: i for i, v in enumerate(variables)}
    out: list[list[sp.Expr]] = [[] for _ in variables]
    for dep, c in groups:
        for v in dep.free_symbols:
            i = index.get(v)
            if i is not None:
                d = d_term(dep, v)
                if d != 0:
                    out[i].append(c * d)
    return out


def _d_factor(f: sp.Expr, v: sp.Symbol) -> sp.Expr:
    """Derivative of one factor of a product term (fast paths for the shapes energies contain)."""
    if f == v:
        return sp.S.One
    if isinstance(f, sp.Pow) and f.exp.is_Number:
        return f.exp * f.base ** (f.exp - 1) * _d_factor(f.base, v)
    if isinstance(f, (sp.sin, sp.cos)):
        u = f.args[0]
        du = sp.S.One if u == v else _d_linear(u, v)
        return (sp.cos(u) if isinstance(f, sp.sin) else -sp.sin(u)) * du
    return f.diff(v)


def _d_linear(u: sp.Expr, v: sp.Symbol) -> sp.Expr:
    """du/dv, read off directly when ``u`` is a sum of numeric multiples of symbols (``phi1 - phi2``)."""
    if u.is_Add:
        total = sp.S.Zero
        for a in u.args:
            c, x = a.as_coeff_Mul()
            if not x.is_Symbol:
                return u.diff(v)
            if x == v:
                total += c
        return total
    return u.diff(v)


def d_term(term: sp.Expr, v: sp.Symbol) -> sp.Expr:
    """d(term)/dv by the product rule over the factors that contain ``v``.

    Equivalent to ``term.diff(v)`` but avoids SymPy's general ``Derivative`` dispatch, which costs about
    a millisecond a call and dominates the derivation of long chains.
    """
    if v not in term.free_symbols:
        return sp.S.Zero
    factors = term.args if isinstance(term, sp.Mul) else (term,)
    pieces = []
    for k, f in enumerate(factors):
        if v in f.free_symbols:
            pieces.append(sp.Mul(*factors[:k], _d_factor(f, v), *factors[k + 1 :]))
    return pieces[0] if len(pieces) == 1 else sp.Add(*pieces)
