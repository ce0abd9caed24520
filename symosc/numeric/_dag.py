"""Straight-line programs: SymPy expressions as one graph of shared nodes, differentiated on the graph.

A :class:`Graph` holds every distinct subexpression of a set of outputs once (hash-consing, "value numbering"):
``cos(phi1)`` or ``l1*l2*m3`` met in a thousand terms is one node.  Node ids are topological (children before
parents), so a list of ids is already an evaluation order.  :meth:`Graph.derivative` differentiates nodes with
respect to an argument by the chain rule on the graph (forward mode): only nodes that depend on the argument get a
derivative, the derivatives are nodes of the same graph, so they share subexpressions with each other and with the
undifferentiated outputs.  This is the analytic derivative (the same expression SymPy's ``diff`` gives, up to the
order of floating-point operations), at the cost of one pass over the dependent part of the graph instead of
SymPy's tree rebuilding (Griewank & Walther (2008), *Evaluating Derivatives*, 2nd ed., §3.1 "forward mode").

The graph knows sums, products, powers and functions.  Anything else (``Piecewise``, relational tests) is kept as
an opaque SymPy expression, printed by SymPy's printers and differentiated by SymPy.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence

import sympy as sp

ARG, CONST, ADD, MUL, POW, FUNC, OPAQUE = range(7)


class Graph:
    """Nodes ``(kind, data)``: ``ARG`` -> argument index, ``CONST`` -> SymPy number, ``ADD``/``MUL`` -> sorted child
    ids, ``POW`` -> (base id, exponent id), ``FUNC`` -> (SymPy function class, child ids), ``OPAQUE`` -> SymPy
    expression in the argument symbols."""

    def __init__(self, args: Sequence[sp.Symbol], varying: int = 0) -> None:
        self.args = list(args)
        self.varying = varying
        self.kind: list[int] = []
        self.data: list = []
        self.deps: list[int] = []  # bit i set: the node depends on argument i
        self._table: dict = {}
        self._memo: dict = {}
        self._index = {s: i for i, s in enumerate(self.args)}
        for i, s in enumerate(self.args):
            self._memo[s] = self._new(ARG, i, 1 << i)
        self.zero = self.const(sp.S.Zero)
        self.one = self.const(sp.S.One)
        self._derivatives: dict[tuple[int, int], int] = {}
        self._templates: dict = {}
        self._expressions: dict[int, sp.Expr] = {}

    def __len__(self) -> int:
        return len(self.kind)

    # ------------------------------------------------------------------ construction
    def _new(self, kind: int, data, deps: int) -> int:
        key = (kind, data)
        k = self._table.get(key)
        if k is None:
            k = len(self.kind)
            self.kind.append(kind)
            self.data.append(data)
            self.deps.append(deps)
            self._table[key] = k
        return k

    def const(self, value: sp.Expr) -> int:
        return self._new(CONST, value, 0)

    def number(self, k: int) -> sp.Expr | None:
        """The SymPy number of a rational or floating constant node, else None."""
        if self.kind[k] == CONST and self.data[k].is_Number:
            return self.data[k]
        return None

    def add(self, children: Sequence[int]) -> int:
        total, rest = sp.S.Zero, []
        for c in children:
            v = self.number(c)
            if v is None:
                rest.append(c)
            else:
                total += v
        if total != 0:
            rest.append(self.const(total))
        if not rest:
            return self.zero
        if len(rest) == 1:
            return rest[0]
        terms = [self._term(c) for c in rest]
        # a*x + a*y -> a*(x + y): one multiplication instead of two, and x + y may be shared elsewhere.
        common = set(terms[0][1])
        for _, factors in terms[1:]:
            common.intersection_update(factors)
            if not common:
                break
        if common:
            pulled = [min(common)]
            reduced = [self.mul([self.const(c), *self._without(f, pulled[0])]) for c, f in terms]
            return self.mul([*pulled, self.add(reduced)])
        # Sign: x - y and y - x are one node (the second is -1 times the first).
        lead = min(range(len(terms)), key=lambda i: terms[i][1])
        if terms[lead][0].is_negative:
            negated = self.add([self.mul([self.const(-c), *f]) for c, f in terms])
            return self.mul([self.const(sp.S.NegativeOne), negated])
        rest.sort()
        deps = 0
        for c in rest:
            deps |= self.deps[c]
        return self._new(ADD, tuple(rest), deps)

    def _term(self, k: int) -> tuple[sp.Expr, tuple[int, ...]]:
        """(numeric coefficient, sorted other factors) of a term."""
        v = self.number(k)
        if v is not None:
            return v, ()
        coeff, body = self.signed(k)
        if self.kind[body] == MUL:
            return coeff, self.data[body]
        return coeff, (body,)

    @staticmethod
    def _without(factors: tuple[int, ...], k: int) -> list[int]:
        i = factors.index(k)
        return [*factors[:i], *factors[i + 1 :]]

    def mul(self, children: Sequence[int]) -> int:
        """The product node; a numeric coefficient stays outside (``c * P``), so that ``P`` is shared by ``P``,
        ``-P`` and ``2*P``."""
        coeff, rest = None, []  # coeff None: 1 (no SymPy arithmetic in the common case of no coefficient)
        kind, data = self.kind, self.data
        for c in children:
            if kind[c] == CONST and data[c].is_Number:
                coeff = data[c] if coeff is None else coeff * data[c]
                continue
            if kind[c] == MUL and len(data[c]) == 2:
                cc, inner = self.signed(c)
                if inner != c:
                    coeff = cc if coeff is None else coeff * cc
                    c = inner
            rest.append(c)
        if coeff is not None and coeff == 0:
            return self.zero
        if not rest:
            return self.one if coeff is None else self.const(coeff)
        body = rest[0] if len(rest) == 1 else self._split_product(rest)
        if coeff is None or coeff == 1:
            return body
        return self._new(MUL, tuple(sorted((self.const(coeff), body))), self.deps[body])

    def signed(self, k: int) -> tuple[sp.Expr, int]:
        """``(c, P)`` with node ``k`` = ``c * P`` (``c = 1`` for a node without a numeric coefficient)."""
        kind, data = self.kind, self.data
        if kind[k] == MUL and len(data[k]) == 2:
            a, b = data[k]
            if kind[a] == CONST and data[a].is_Number:
                return data[a], b
            if kind[b] == CONST and data[b].is_Number:
                return data[b], a
        return sp.S.One, k

    def _split_product(self, rest: list[int]) -> int:
        if self.varying:
            # Products of parameters and products of varying quantities are shared by many terms: make each a
            # node of its own (``(l1*l2*m3) * (cos(phi1)*sin(phi2))``) so that the graph shares them.
            fixed, moving = [], []
            deps, varying = self.deps, self.varying
            for c in rest:
                (moving if deps[c] & varying else fixed).append(c)
            if (len(fixed) > 1 and moving) or (len(moving) > 1 and fixed):
                return self._product([self._product(fixed), self._product(moving)])
        return self._product(rest)

    def _product(self, factors: list[int]) -> int:
        if len(factors) == 1:
            return factors[0]
        factors = sorted(factors)
        deps = 0
        for c in factors:
            deps |= self.deps[c]
        return self._new(MUL, tuple(factors), deps)

    def pow(self, base: int, exponent: int) -> int:
        e = self.number(exponent)
        if e is not None:
            if e == 0:
                return self.one
            if e == 1:
                return base
            b = self.number(base)
            if b is not None:
                return self.const(b**e)
        return self._new(POW, (base, exponent), self.deps[base] | self.deps[exponent])

    def func(self, cls: type, children: Sequence[int]) -> int:
        deps = 0
        for c in children:
            deps |= self.deps[c]
        return self._new(FUNC, (cls, tuple(children)), deps)

    def opaque(self, expr: sp.Expr) -> int:
        deps = 0
        for s in expr.free_symbols:
            i = self._index.get(s)
            if i is not None:
                deps |= 1 << i
        return self._new(OPAQUE, expr, deps)

    def node(self, expr: sp.Expr, env: dict | None = None) -> int:
        """The node of a SymPy expression (its subexpressions become nodes, shared with everything before).

        ``env`` maps further symbols to nodes (used to instantiate derivative templates); without it the
        conversion is memoized per SymPy subexpression.
        """
        memo = self._memo if env is None else env
        k = memo.get(expr)
        if k is not None:
            return k
        if expr.is_Number or expr.is_NumberSymbol or expr is sp.I or expr in (sp.zoo, sp.nan):
            k = self.const(expr)
        elif (
            expr.is_Add
            or expr.is_Mul
            or expr.is_Pow
            or (isinstance(expr, sp.Function) and all(isinstance(a, sp.Expr) for a in expr.args))
        ):
            children = [self.node(a, env) for a in expr.args]
            if all(self.kind[c] == CONST for c in children) and _is_constant(expr):
                # A constant such as pi/3, sqrt(2) or exp(2): one number, rounded once when printed.
                k = self.const(expr)
            elif expr.is_Add:
                k = self.add(children)
            elif expr.is_Mul:
                k = self.mul(children)
            elif expr.is_Pow:
                k = self.pow(*children)
            else:
                k = self.func(expr.func, children)
        elif expr.is_Symbol:
            raise ValueError(f"{expr} is not an argument")
        else:
            k = self.opaque(expr if env is None else self.expression(self.node_of_opaque(expr, env)))
        memo[expr] = k
        return k

    def node_of_opaque(self, expr: sp.Expr, env: dict) -> int:
        """An opaque expression written in template symbols: substitute the nodes' expressions."""
        sub = {s: self.expression(k) for s, k in env.items() if isinstance(s, sp.Symbol)}
        return self.opaque(expr.xreplace(sub))

    def expression(self, k: int) -> sp.Expr:
        """The SymPy expression of node ``k`` (rebuilt from the graph, shared subexpressions built once)."""
        memo = self._expressions
        for j in reachable(self, [k])[0]:
            if j in memo:
                continue
            kind, data = self.kind[j], self.data[j]
            if kind == ARG:
                e = self.args[data]
            elif kind in (CONST, OPAQUE):
                e = data
            elif kind == ADD:
                e = sp.Add(*(memo[c] for c in data))
            elif kind == MUL:
                e = sp.Mul(*(memo[c] for c in data))
            elif kind == POW:
                e = sp.Pow(memo[data[0]], memo[data[1]])
            else:
                e = data[0](*(memo[c] for c in data[1]))
            memo[j] = e
        return memo[k]

    # ------------------------------------------------------------------ differentiation
    def derivative(self, k: int, i: int) -> int:
        """The node of d(node k)/d(argument i)."""
        bit = 1 << i
        if not self.deps[k] & bit:
            return self.zero
        cache = self._derivatives
        got = cache.get((k, i))
        if got is not None:
            return got
        # Iterative post-order over the dependent part of the graph (the recursion could be thousands deep).
        stack = [k]
        while stack:
            top = stack[-1]
            pending = [c for c in self._children(top) if self.deps[c] & bit and (c, i) not in cache]
            if pending:
                stack.extend(pending)
                continue
            stack.pop()
            if (top, i) not in cache:
                cache[(top, i)] = self._derivative_of(top, i)
        return cache[(k, i)]

    def _children(self, k: int) -> tuple[int, ...]:
        kind, data = self.kind[k], self.data[k]
        if kind in (ADD, MUL):
            return data
        if kind == POW:
            return data
        if kind == FUNC:
            return data[1]
        return ()

    def _d(self, c: int, i: int) -> int:
        return self._derivatives[(c, i)] if self.deps[c] & (1 << i) else self.zero

    def _derivative_of(self, k: int, i: int) -> int:
        kind, data = self.kind[k], self.data[k]
        bit = 1 << i
        if kind == ARG:
            return self.one if data == i else self.zero
        if kind == ADD:
            return self.add([self._d(c, i) for c in data if self.deps[c] & bit])
        if kind == MUL:
            terms = []
            for pos, c in enumerate(data):
                if self.deps[c] & bit:
                    terms.append(self.mul([*data[:pos], self._d(c, i), *data[pos + 1 :]]))
            return self.add(terms)
        if kind == POW:
            base, exponent = data
            e = self.number(exponent)
            if e is not None or not self.deps[exponent] & bit:
                # d(b**e) = e * b**(e - 1) * db
                lowered = (
                    self.pow(base, self.const(e - 1))
                    if e is not None
                    else self.pow(base, self.add([exponent, self.const(sp.S.NegativeOne)]))
                )
                return self.mul([exponent, lowered, self._d(base, i)])
            # d(b**e) = b**e * (de * log(b) + e * db / b)
            log_b = self.func(sp.log, [base])
            inner = [self.mul([self._d(exponent, i), log_b])]
            if self.deps[base] & bit:
                inner.append(self.mul([exponent, self._d(base, i), self.pow(base, self.const(sp.S.NegativeOne))]))
            return self.mul([k, self.add(inner)])
        if kind == FUNC:
            cls, children = data
            terms = []
            for pos, c in enumerate(children):
                if self.deps[c] & bit:
                    terms.append(self.mul([self._partial(cls, children, pos), self._d(c, i)]))
            return self.add(terms)
        if kind == OPAQUE:
            return self.node(sp.diff(data, self.args[i]))
        raise AssertionError(kind)

    def _partial(self, cls: type, children: tuple[int, ...], pos: int) -> int:
        """The node of d f(u_0, .., u_m) / d u_pos at u = children (SymPy's own derivative, instantiated)."""
        key = (cls, len(children), pos)
        template = self._templates.get(key)
        if template is None:
            dummies = sp.symbols(f"_symosc_u0:{len(children)}", real=True)
            template = (dummies, sp.diff(cls(*dummies), dummies[pos]))
            self._templates[key] = template
        dummies, expr = template
        if expr.has(sp.Derivative, sp.Subs):
            raise NotImplementedError(f"no closed-form derivative of {cls.__name__} in argument {pos + 1}")
        return self.node(expr, dict(zip(dummies, children, strict=True)))


def subexpressions(exprs: Iterable[sp.Basic]) -> Iterator[sp.Basic]:
    """Every distinct subexpression of ``exprs`` (the expressions themselves included), once each.

    ``Basic.atoms`` and ``Basic.has`` visit a subexpression at every place it occurs; the equations of motion share
    most of theirs, so this walk is much shorter.
    """
    seen: set = set()
    stack = list(exprs)
    while stack:
        e = stack.pop()
        if e not in seen:
            seen.add(e)
            yield e
            stack.extend(e.args)


def _is_constant(expr: sp.Expr) -> bool:
    """True when ``expr`` (free of symbols) evaluates to a real or complex number."""
    if expr.is_Add or expr.is_Mul or expr.is_Pow:
        return True
    try:
        value = expr.evalf(30)
    except (TypeError, ValueError, ArithmeticError):
        return False
    re, im = value.as_real_imag()
    return re.is_Number and im.is_Number


def reachable(graph: Graph, outputs: Sequence[int], stop=()) -> tuple[list[int], dict[int, int]]:
    """Nodes the outputs need, in evaluation order, and how often each is used (by nodes and as an output).

    The search does not continue below the nodes in ``stop`` (values computed elsewhere)."""
    uses: dict[int, int] = {}
    seen = set()
    stack = list(outputs)
    for k in outputs:
        uses[k] = uses.get(k, 0) + 1
    order = []
    kind, data = graph.kind, graph.data
    while stack:
        k = stack.pop()
        if k in seen:
            continue
        seen.add(k)
        order.append(k)
        if k in stop:
            continue
        kk = kind[k]
        if kk == FUNC:
            children = data[k][1]
        elif kk == ADD or kk == MUL or kk == POW:
            children = data[k]
        else:
            continue
        for c in children:
            uses[c] = uses.get(c, 0) + 1
            if c not in seen:
                stack.append(c)
    order.sort()
    return order, uses


def cse(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol], prefix: str = "_c") -> tuple[list, list]:
    """Common subexpressions of ``exprs`` in the form of :func:`sympy.cse`: ``(replacements, reduced)``.

    The graph shares every repeated subexpression in one pass (SymPy's ``cse`` also searches sub-products and
    sub-sums pairwise, which costs seconds for equations of motion of a few dozen coordinates).  A node used more
    than once becomes a symbol ``_c0, _c1, ...``; every other node is rebuilt inline.
    """
    g = Graph(args)
    nodes = [g.node(e) for e in exprs]
    order, uses = reachable(g, nodes)
    built: dict[int, sp.Expr] = {}
    replacements = []
    for k in order:
        kind, data = g.kind[k], g.data[k]
        if kind == ARG:
            built[k] = g.args[data]
            continue
        if kind in (CONST, OPAQUE):
            e = data
        elif kind == ADD:
            e = sp.Add(*(built[c] for c in data))
        elif kind == MUL:
            e = sp.Mul(*(built[c] for c in data))
        elif kind == POW:
            e = sp.Pow(built[data[0]], built[data[1]])
        else:
            e = data[0](*(built[c] for c in data[1]))
        if uses.get(k, 0) > 1 and kind != CONST and not e.is_Atom:
            s = sp.Symbol(f"{prefix}{len(replacements)}")
            replacements.append((s, e))
            e = s
        built[k] = e
    return replacements, [built[k] for k in nodes]
