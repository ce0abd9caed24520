"""Term-level calculus used by the Lagrange engine.

Energies of mechanical systems are sums of many small products (``m_k l_i l_j cos(phi_i) cos(phi_j)
phi_i' phi_j'``).  Working term by term — splitting the kinetic energy into its parts of degree 0, 1
and 2 in the velocities without expanding anything else, and differentiating each term only with
respect to the few coordinates it contains — keeps the derivation of an n-link chain at O(n^3) term
operations, where differentiating whole expression trees costs O(n^4) or more.

A term is kept as a tuple of factors (no SymPy ``Mul`` is built while the energy is opened: a product is a
tuple concatenation); SymPy expressions are built once per distinct product, when the terms are collected.
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Iterable, Sequence
from fractions import Fraction
from typing import NamedTuple

import sympy as sp

from .._trig import plain_argument
from ..errors import ModelError

Monomial = tuple[int, ...]  # sorted velocity indices: () constant, (i,) linear, (i, j) quadratic with i <= j
Factors = tuple[sp.Expr, ...]  # a product term, as its factors
TermDict = dict[Monomial, list[Factors]]


class Group(NamedTuple):
    """``coeff * dep``: ``dep`` the product of the factors that depend on the variables (``powers`` lists them as
    ``(base, exponent)``), ``coeff`` the sum of everything that multiplies it."""

    dep: sp.Expr
    coeff: sp.Expr
    powers: tuple[tuple[sp.Expr, sp.Expr], ...]


Groups = list[Group]


def _product(args: Sequence[sp.Expr]) -> sp.Expr:
    """Product of a subset of the arguments of a canonical Mul (already ordered and combined)."""
    if not args:
        return sp.S.One
    if len(args) == 1:
        return args[0]
    if any(isinstance(a, sp.Add) for a in args):
        return sp.Mul(*args)
    return sp.Mul._from_args(tuple(args))


def product_group(dep: sp.Expr, coeff: sp.Expr) -> Group:
    """``coeff * dep`` as a :class:`Group` (a numeric factor of ``dep`` moved into the coefficient)."""
    number, rest = sp.sympify(dep).as_coeff_Mul()
    powers = tuple(f.as_base_exp() for f in sp.Mul.make_args(rest) if f is not sp.S.One)
    return Group(rest, coeff if number is sp.S.One else number * coeff, powers)


class _Depends:
    """Memoized "does this expression contain one of ``symbols``" (``free_symbols`` is not cached by SymPy)."""

    def __init__(self, symbols: Iterable[sp.Symbol]) -> None:
        self.symbols = frozenset(symbols)
        self.memo: dict[sp.Expr, bool] = {}

    def __call__(self, e: sp.Expr) -> bool:
        got = self.memo.get(e)
        if got is None:
            if e.is_Symbol:
                got = e in self.symbols
            elif not e.args:
                got = False
            else:
                got = any(self(a) for a in e.args)
            self.memo[e] = got
        return got


def _flat(e: sp.Expr) -> Factors:
    return e.args if e.is_Mul else (e,)


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
            out[key].extend(x + y for x in va for y in vb)
    return out


def velocity_parts(expr: sp.Expr, velocities: Sequence[sp.Symbol], what: str = "T") -> TermDict:
    """Split ``expr`` into terms of degree 0, 1, 2 in ``velocities``.

    Returns a mapping ``monomial -> list of coefficient terms`` (each a tuple of factors); only products, sums
    and integer powers are opened, everything free of velocities is kept as it is.
    """
    index = {v: i for i, v in enumerate(velocities)}
    has_velocity = _Depends(velocities)

    def walk(e: sp.Expr) -> TermDict:
        if not has_velocity(e):
            return {(): [_flat(e)]}
        if e in index:
            return {(index[e],): [()]}
        if isinstance(e, sp.Add):
            out: TermDict = {}
            for arg in e.args:
                out = _merge(out, walk(arg))
            return out
        if isinstance(e, sp.Mul):
            out = {(): [tuple(a for a in e.args if not has_velocity(a))]}
            for arg in e.args:
                if has_velocity(arg):
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


def expand_terms(expr: sp.Expr | Iterable[Factors], variables: Iterable[sp.Symbol]) -> list[Factors]:
    """The additive terms of ``expr`` (an expression, or terms as factor tuples), each a tuple of factors, with
    the products of sums that involve ``variables`` opened.  No trigonometric rewriting."""
    depends = variables if isinstance(variables, _Depends) else _Depends(variables)
    if isinstance(expr, sp.Basic):
        expr = [_flat(term) for term in sp.Add.make_args(expr)]
    out: list[Factors] = []
    stack = list(expr)
    stack.reverse()
    while stack:
        term = stack.pop()
        for pos, f in enumerate(term):
            if f.is_Add and depends(f):
                rest = term[:pos] + term[pos + 1 :]
                stack.extend(reversed([rest + _flat(a) for a in f.args]))
                break
            if f.is_Pow and f.base.is_Add and f.exp.is_Integer and f.exp > 1 and depends(f.base):
                stack.append(term[:pos] + (f.base,) * int(f.exp) + term[pos + 1 :])
                break
        else:
            out.append(term)
    return out


def group_terms(terms: Iterable[Factors], variables: Iterable[sp.Symbol]) -> Groups:
    """Collect ``sum(terms)`` as ``sum_k c_k * d_k`` with distinct factors ``d_k`` depending on ``variables``.

    Each distinct dependent factor (e.g. ``cos(phi1)*cos(phi2)``) then needs differentiating only once,
    whatever the number of terms that share it.  Equal products are merged (their numeric coefficients added)
    and factors common to all the terms of a coefficient are taken out of its sum (``l1*l2*(m2 + m3)``).
    """
    depends = variables if isinstance(variables, _Depends) else _Depends(variables)
    ids: dict[sp.Expr, int] = {}  # base -> its index in the keys
    # id(factor) -> what it contributes (see _factor_info); `seen` keeps the factors alive (no id is reused)
    info: dict[int, tuple] = {}
    seen: list[sp.Expr] = []
    groups: dict[tuple, dict[tuple, int | Fraction | sp.Expr]] = {}
    for term in terms:
        coeff: int | Fraction | sp.Expr | None = None  # None: 1 (no number yet)
        dep: dict[int, int | sp.Expr] = {}
        ind: dict[int, int | sp.Expr] = {}
        for f in term:
            got = info.get(id(f))
            if got is None:
                got = info[id(f)] = _factor_info(f, ids, depends)
                seen.append(f)
            kind, b, e = got
            if kind == _DEPENDENT:
                dep[b] = dep.get(b, 0) + e
            elif kind == _CONSTANT:
                ind[b] = ind.get(b, 0) + e
            elif kind == _NUMBER:
                coeff = b if coeff is None else coeff * b
        if coeff is None:
            coeff = 1
        elif coeff == 0:
            continue
        dkey = tuple(sorted((b, e) for b, e in dep.items() if e != 0))
        ikey = tuple(sorted((b, e) for b, e in ind.items() if e != 0))
        sums = groups.setdefault(dkey, {})
        old = sums.get(ikey)
        sums[ikey] = coeff if old is None else old + coeff
    bases = list(ids)
    out: Groups = []
    for dkey, sums in groups.items():
        entries = [(ikey, _number(c)) for ikey, c in sums.items() if c != 0]
        if not entries:
            continue
        powers = tuple((bases[i], sp.Integer(e) if isinstance(e, int) else e) for i, e in dkey)
        dep = sp.Mul(*(b if e == 1 else b**e for b, e in powers))
        out.append(Group(dep, _coefficient(entries, bases), powers))
    return out


_ONE, _NUMBER, _DEPENDENT, _CONSTANT = range(4)  # kinds of factors in group_terms


def _factor_info(f: sp.Expr, ids: dict[sp.Expr, int], depends: _Depends) -> tuple:
    """What the factor ``f`` of a term contributes: ``(_ONE, None, None)``, ``(_NUMBER, value, None)`` (an int or
    a Fraction for a rational), or ``(_DEPENDENT or _CONSTANT, index of its base in ids, exponent)`` (an int
    exponent when it is an integer); a new base is given the next index."""
    if f.is_Number:
        return (_ONE, None, None) if f is sp.S.One else (_NUMBER, _python_number(f), None)
    if f.is_Pow and f.exp.is_Rational:
        base, e = f.base, int(f.exp) if f.exp.is_Integer else f.exp
    else:
        base, e = f, 1
    return (_DEPENDENT if depends(base) else _CONSTANT, ids.setdefault(base, len(ids)), e)


def _coefficient(entries: list[tuple[tuple, sp.Expr]], bases: list[sp.Expr]) -> sp.Expr:
    """``sum_k c_k prod_b b**e_bk`` with the rational content of the ``c_k`` and the factors common to every
    term taken out of the sum (``l1*l2*(m2 + m3)/2``)."""
    common = {b: e for b, e in entries[0][0] if e > 0}
    for ikey, _ in entries[1:]:
        powers = dict(ikey)
        common = {b: min(e, powers[b]) for b, e in common.items() if powers.get(b, 0) > 0}
        if not common:
            break
    content = sp.S.One
    if len(entries) > 1 and all(c.is_Rational for _, c in entries):
        content = sp.Rational(
            math.gcd(*(int(c.p) for _, c in entries)) * (-1 if entries[0][1].p < 0 else 1),
            math.lcm(*(int(c.q) for _, c in entries)),
        )
    terms = []
    for ikey, c in entries:
        rest = [_power(bases[b], e - common.get(b, 0)) for b, e in ikey if e != common.get(b, 0)]
        c = c / content if content != 1 else c
        terms.append(rest[0] if c == 1 and len(rest) == 1 else sp.Mul(c, *rest))
    return sp.Mul(content, *(_power(bases[b], e) for b, e in common.items()), sp.Add(*terms))


def _python_number(f: sp.Expr) -> int | Fraction | sp.Expr:
    """A SymPy number as an int (integers) or a Fraction (rationals); other numbers as they are."""
    if f.is_Integer:
        return int(f.p)
    return Fraction(int(f.p), int(f.q)) if f.is_Rational else f


def _number(c: int | Fraction | sp.Expr) -> sp.Expr:
    return sp.Rational(c.numerator, c.denominator) if isinstance(c, Fraction) else sp.sympify(c)


def _power(base: sp.Expr, e: int | sp.Expr) -> sp.Expr:
    return base if e == 1 else base**e


def power(base: sp.Expr, exp: sp.Expr | int) -> sp.Expr:
    """``base**exp``, built without SymPy's evaluation when that would leave it as it is
    (:func:`_power_fixed_point`)."""
    exp = sp.S(exp)
    return sp.Pow(base, exp, evaluate=False) if _power_fixed_point(base, exp) else base**exp


def trig(func: type[sp.Function], u: sp.Expr) -> sp.Expr:
    """``sin(u)`` or ``cos(u)``, built without SymPy's evaluation when that would leave it as it is
    (:func:`_trig_fixed_point`)."""
    return func(u, evaluate=False) if _trig_fixed_point(u) else func(u)


def _power_fixed_point(base: sp.Expr, exp: sp.Expr) -> bool:
    """Whether ``base**exp`` evaluates to itself: ``exp`` an integer > 1 and ``base`` a sum with a free symbol that
    :func:`_finite_sum` accepts (SymPy then only asks whether a term of a two-term sum is infinite, which such a sum
    cannot be, and leaves the power as it is; the question costs assumption queries on a cold cache)."""
    return exp.is_Integer and exp > 1 and base.is_Add and not base.is_number and _finite_sum(base)


def _finite_sum(e: sp.Expr) -> bool:
    """Whether ``e`` is built from finite rationals, symbols not declared infinite, ``sin``, ``cos``, sums, products
    and powers with positive integer exponents only: no term of such an expression can be infinite."""
    if e.is_Symbol:
        return e.is_infinite is not True
    if e.is_Rational:
        return True
    if isinstance(e, sp.Add | sp.Mul | sp.sin | sp.cos):
        return all(_finite_sum(a) for a in e.args)
    if e.is_Pow:
        return e.exp.is_Integer and e.exp > 0 and _finite_sum(e.base)
    return False


def _trig_fixed_point(u: sp.Expr) -> bool:
    """Whether ``sin(u)`` and ``cos(u)`` evaluate to themselves: ``u`` a symbol that is not known to be zero or
    infinite (their evaluation, with its assumption queries, is then skipped)."""
    return u.is_Symbol and u.is_zero is not True and u.is_finite is not False


class Piece(NamedTuple):
    """``number * prod(constants) * prod(dependent)``, a term of a gradient kept as its factors: what splitting the
    canonical product ``sympy.Mul(number, *constants, *dependent)`` into its number, its factors free of the variables
    and those that depend on them gives (each tuple in the product's order)."""

    number: sp.Expr
    constants: Factors
    dependent: Factors


def grouped_gradient(
    groups: Groups, variables: Sequence[sp.Symbol], depends: _Depends | None = None
) -> list[list[sp.Expr | Piece]]:
    """Gradient of ``sum c_k d_k``: per variable the list of pieces ``c_k * d(d_k)/dv``.

    With ``depends`` (the test for the variables the coefficients ``c_k`` are free of), the pieces of a group with a
    single dependent factor whose derivative is a number times one dependent factor come as :class:`Piece` (no
    product is built: the derivation of a chain has many such pieces); the others are products.
    """
    index = {v: i for i, v in enumerate(variables)}
    out: list[list[sp.Expr | Piece]] = [[] for _ in variables]
    memo: dict[sp.Expr, list[int]] = {}
    for g in groups:
        factors = [b**e for b, e in g.powers]
        single = depends is not None and len(g.powers) == 1 and g.powers[0][1] == 1
        for pos, (base, e) in enumerate(g.powers):
            found = memo.get(base)
            if found is None:
                found = memo[base] = sorted(index[v] for v in base.free_symbols if v in index)
            for i in found:
                d = _d_factor(base, variables[i])
                if d == 0:
                    continue
                piece = _piece(g.coeff, d, depends) if single else None
                if piece is None:
                    outer = e * base ** (e - 1) if e != 1 else sp.S.One
                    piece = sp.Mul(g.coeff, outer, d, *factors[:pos], *factors[pos + 1 :])
                out[i].append(piece)
    return out


def _piece(coeff: sp.Expr, d: sp.Expr, depends: _Depends) -> Piece | None:
    """``coeff * d`` as a :class:`Piece` when ``d`` is a number times one factor that depends on the variables
    (``-sin(phi1 - phi2)``), else None.

    The product's factors are then those of ``coeff`` (free of the variables, already in canonical order) and that
    factor: no two share a base, so the product would only sort them and multiply the two numbers.
    """
    number, factor = d.as_coeff_Mul()
    if factor.is_Mul or factor.is_Add or factor.is_Number or not depends(factor):
        return None
    c_number, rest = coeff.as_coeff_Mul()
    constants = () if rest is sp.S.One else sp.Mul.make_args(rest)
    return Piece(c_number * number, constants, (factor,))


def _d_factor(f: sp.Expr, v: sp.Symbol) -> sp.Expr:
    """Derivative of one factor of a product term (fast paths for the shapes energies contain)."""
    if f == v:
        return sp.S.One
    if isinstance(f, sp.Pow) and f.exp.is_Number:
        return f.exp * f.base ** (f.exp - 1) * _d_factor(f.base, v)
    if isinstance(f, (sp.sin, sp.cos)):
        u = f.args[0]
        du = sp.S.One if u == v else _d_linear(u, v)
        return _partner(f, u) * du
    return f.diff(v)


def _partner(f: sp.Expr, u: sp.Expr) -> sp.Expr:
    """``cos(u)`` for ``f = sin(u)``, ``-sin(u)`` for ``f = cos(u)``.

    When ``u`` is a symbol or a sum of rational multiples of symbols (``phi1 - phi2``), the function is built without
    SymPy's evaluation: ``f`` already holds ``u`` in the canonical form both functions share (the sign of an
    argument is normalised the same way for sin and cos, and such a ``u`` has no multiple of pi to shift), and the
    evaluation (``could_extract_minus_sign`` and the search for multiples of pi) is most of the cost of the
    derivatives of a long chain."""
    func = sp.cos if isinstance(f, sp.sin) else sp.sin
    value = func(u, evaluate=False) if plain_argument(u) else func(u)
    return value if func is sp.cos else -value


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
