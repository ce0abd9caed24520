"""Arithmetic of truncated power series and the SymPy protocol of the series results (private).

A series is held as ``(coefficients, order)``: ``c_0 .. c_order`` free of the expansion variable, standing for
``sum c_k eps**k + O(eps**(order + 1))``; ``order=None`` marks an exact polynomial (a number, a symbol free of
``eps``, ``eps`` itself), which carries no order term.  The rules are those of ``sympy.series`` (and of
``sympy.Order``): a sum keeps the lower order; a product of ``a + O(eps**(m+1))`` and ``b + O(eps**(n+1))`` with
lowest powers ``eps**va`` and ``eps**vb`` is known to ``min(m + vb, n + va)``; a power ``a**p`` with ``a_0 != 0``
keeps the order of ``a`` and is formed by J. C. P. Miller's recurrence (Knuth, *The Art of Computer Programming*,
vol. 2, §4.7, eq. (9); Henrici, *Applied and Computational Complex Analysis* I (1974), §1.6).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import sympy as sp

#: the expansion variable shown as epsilon in LaTeX and pretty printing (SymPy's names for the Greek letter)
_EPS_NAMES = ("eps", "epsilon", "varepsilon")


def tidy(c: Any) -> sp.Expr:
    """A coefficient in canonical form: numbers as they are, other expressions expanded."""
    c = sp.sympify(c)
    return c if c.is_number else sp.expand(c)


def is_zero(c: Any) -> bool:
    return c == 0 or c.is_zero is True


def valuation(cs: tuple, order: int | None) -> int | None:
    """Lowest power with a nonzero coefficient (``order + 1`` for a truncated zero, None for an exact zero)."""
    for k, c in enumerate(cs):
        if not is_zero(c):
            return k
    return None if order is None else order + 1


def _min_order(*orders: int | None) -> int | None:
    finite = [o for o in orders if o is not None]
    return min(finite) if finite else None


def _trimmed(cs: list, order: int | None) -> tuple:
    if order is not None:
        cs = (cs + [sp.S.Zero] * (order + 1 - len(cs)))[: order + 1]
        return tuple(cs)
    while cs and is_zero(cs[-1]):
        cs.pop()
    return tuple(cs)


def add(a: tuple, oa: int | None, b: tuple, ob: int | None) -> tuple[tuple, int | None]:
    """``a + b`` (the order is the lower one)."""
    order = _min_order(oa, ob)
    n = max(len(a), len(b)) if order is None else order + 1
    at = lambda cs, k: cs[k] if k < len(cs) else sp.S.Zero  # noqa: E731
    return _trimmed([tidy(at(a, k) + at(b, k)) for k in range(n)], order), order


def mul(a: tuple, oa: int | None, b: tuple, ob: int | None) -> tuple[tuple, int | None]:
    """Cauchy product; known to ``min(oa + vb, ob + va)``."""
    va, vb = valuation(a, oa), valuation(b, ob)
    if (va is None and oa is None) or (vb is None and ob is None):
        return (), None  # an exact zero annihilates the order term too (0*O(eps) = 0)
    order = _min_order(None if oa is None else oa + vb, None if ob is None else ob + va)
    n = len(a) + len(b) - 1 if order is None else order + 1
    out = []
    for k in range(n):
        terms = [a[i] * b[k - i] for i in range(max(0, k - len(b) + 1), min(k, len(a) - 1) + 1)]
        out.append(tidy(sp.Add(*terms)))
    return _trimmed(out, order), order


def power(a: tuple, oa: int | None, p: Any) -> tuple[tuple, int | None] | None:
    """``a**p``: repeated products for integers ``p >= 0``, Miller's recurrence when ``a_0 != 0``; None when the
    result is not a power series with the same variable (negative powers of ``eps``, or an exact polynomial raised
    to a power that is no polynomial)."""
    p = sp.sympify(p)
    if p.is_Integer and p >= 0:
        result: tuple[tuple, int | None] = ((sp.S.One,), None)
        base, n = (a, oa), int(p)
        while n:
            if n & 1:
                result = mul(*result, *base)
            n >>= 1
            if n:
                base = mul(*base, *base)
        return result
    if oa is None or not a or is_zero(a[0]):
        return None
    a0 = a[0]
    a = tuple(a) + (sp.S.Zero,) * (oa + 1 - len(a))
    out = [tidy(a0**p)]
    for k in range(1, oa + 1):
        acc = sp.Add(*[((p + 1) * j - k) * a[j] * out[k - j] for j in range(1, k + 1) if not is_zero(a[j])])
        out.append(tidy(acc / (k * a0)))
    return tuple(out), oa


def from_expr(expr: sp.Expr, x: sp.Symbol) -> tuple[tuple, int | None] | None:
    """``(coefficients, order)`` of a SymPy expression that is a polynomial in ``x`` plus, optionally, an order
    term ``O(x**m)`` at ``x = 0``; None for anything else (a function of ``x``, another order term, a matrix)."""
    if not isinstance(expr, sp.Expr) or getattr(expr, "is_Matrix", False):
        return None
    order = None
    if expr.has(sp.Order):
        o = expr.getO()
        body = expr.removeO()
        if o is None or body.has(sp.Order) or o.variables != (x,) or o.point != (0,):
            return None
        m = 0 if o.expr == 1 else (o.expr.as_base_exp()[1] if o.expr.as_base_exp()[0] == x else None)
        if m is None or not (sp.sympify(m).is_Integer and m >= 0):
            return None
        order = int(m) - 1
        expr = body
    if x not in expr.free_symbols:
        cs: list = [expr]
    else:
        poly = expr.as_poly(x)
        if poly is None:
            return None
        cs = poly.all_coeffs()[::-1]
    if order is not None and order < 0:
        return None  # O(1): nothing left
    return _trimmed([tidy(c) for c in cs], order), order


def as_sympy_expr(cs: tuple, order: int | None, x: sp.Symbol) -> sp.Expr:
    """``sum c_k x**k + O(x**(order + 1))`` as SymPy builds it."""
    body = sp.Add(*[c * x**k for k, c in enumerate(cs)])
    return body if order is None else body + sp.Order(x ** (order + 1), x)


def display(expr: Any, x: sp.Symbol, latex: bool) -> Any:
    """``expr`` with the expansion variable shown as epsilon (``\\varepsilon`` in LaTeX, ``ε`` in pretty print)."""
    if x.name not in _EPS_NAMES:
        return expr
    shown = sp.Symbol("varepsilon" if latex else "epsilon", **x.assumptions0)
    return expr.xreplace({x: shown})


def substitution_pairs(args: tuple) -> list[tuple[Any, Any]]:
    """``subs`` arguments as SymPy accepts them (``old, new``; a mapping; an iterable of pairs), sympified."""
    if len(args) == 2:
        pairs = [args]
    elif len(args) == 1:
        seq = args[0]
        pairs = list(seq.items()) if isinstance(seq, Mapping) else list(seq)
    else:
        raise ValueError("subs accepts either one or two arguments (as sympy.Basic.subs)")
    return [(sp.sympify(old), sp.sympify(new)) for old, new in pairs]


def derivative_variables(symbols: tuple) -> list[Any]:
    """``diff`` arguments as SymPy accepts them (``x``, ``x, 2``, ``(x, 2)``, ``x, y``) as a flat list."""
    out: list[Any] = []
    for s in symbols:
        if isinstance(s, int) or (isinstance(s, sp.Basic) and s.is_Integer):
            if not out:
                raise ValueError("diff: a count must follow a variable")
            out.extend([out[-1]] * (int(s) - 1))
        elif isinstance(s, tuple | sp.Tuple):
            var, count = s
            out.extend([sp.sympify(var)] * int(count))
        else:
            out.append(sp.sympify(s))
    return out


def pretty_label(name: str, printer: Any) -> Any:
    """The name of a series as a pretty-print label (Greek names as letters, a trailing ' kept), None for a generic
    or unprintable name."""
    from sympy.printing.pretty.stringpict import prettyForm

    base = name.rstrip("'")
    primes = name[len(base) :]
    if not base.isidentifier() or base == "series":
        return None
    if "_" in base:
        return prettyForm(name)
    shown = printer._print(sp.Symbol(base)) if printer is not None else prettyForm(sp.pretty(sp.Symbol(base)))
    return prettyForm(*shown.right(primes)) if primes else shown


class SeriesResult:
    """Mixin for results whose mathematics is a series: the SymPy protocol of :class:`EpsSeries`, applied to the
    result's main expression (:meth:`series_expression`).

    ``sympy.sympify(result)`` is :meth:`as_series` (the main series with its order term: an expression, or an
    ``ImmutableMatrix`` for vector-valued results); arithmetic, :meth:`subs`, :meth:`diff`, :attr:`free_symbols`,
    :meth:`removeO` and :meth:`getO` act on it and return series (or SymPy objects), not results of the same class.
    """

    __slots__ = ()
    _op_priority = 20.0

    def series_expression(self) -> Any:
        """The main expression: an :class:`EpsSeries`, or a tuple of them for a vector-valued result."""
        raise NotImplementedError

    def _main(self) -> Any:
        main = self.series_expression()
        return main if _is_series(main) else sp.ImmutableMatrix([sp.sympify(s) for s in main])

    def _sympy_(self) -> Any:
        return self.as_series()

    def as_series(self) -> Any:
        """The main expression with its order term(s), as ``sympy.sympify(result)`` gives it."""
        return sp.sympify(self._main())

    def removeO(self) -> Any:
        """The main expression without its order term(s)."""
        main = self.series_expression()
        return main.removeO() if _is_series(main) else sp.ImmutableMatrix([s.removeO() for s in main])

    def getO(self) -> sp.Order:
        """The order term of the main expression."""
        main = self.series_expression()
        return (main if _is_series(main) else main[0]).getO()

    @property
    def free_symbols(self) -> set:
        """Symbols of the main expression (the expansion variable, the phase, parameters)."""
        main = self.series_expression()
        return main.free_symbols if _is_series(main) else set().union(*(s.free_symbols for s in main))

    def subs(self, *args: Any, **kwargs: Any) -> Any:
        """:meth:`EpsSeries.subs` of the main expression (elementwise for a vector, giving an ``ImmutableMatrix``).

        Parameters
        ----------
        args : pair, mapping or iterable of pairs
            As ``sympy.Basic.subs``.
        kwargs
            Passed on to ``sympy.Basic.subs``.
        """
        return self._map(lambda s: s.subs(*args, **kwargs))

    def diff(self, *symbols: Any, **kwargs: Any) -> Any:
        """:meth:`EpsSeries.diff` of the main expression (elementwise for a vector).

        Parameters
        ----------
        symbols : Symbol, or Symbol and count
            Variables as in ``sympy.diff``.
        kwargs
            Passed on to ``sympy.diff``.
        """
        return self._map(lambda s: s.diff(*symbols, **kwargs))

    def _map(self, fn: Any) -> Any:
        main = self.series_expression()
        return fn(main) if _is_series(main) else sp.ImmutableMatrix([sp.sympify(fn(s)) for s in main])

    def __add__(self, other: Any) -> Any:
        return self._main() + other

    def __radd__(self, other: Any) -> Any:
        return other + self._main()

    def __sub__(self, other: Any) -> Any:
        return self._main() - other

    def __rsub__(self, other: Any) -> Any:
        return other - self._main()

    def __mul__(self, other: Any) -> Any:
        return self._main() * other

    def __rmul__(self, other: Any) -> Any:
        return other * self._main()

    def __truediv__(self, other: Any) -> Any:
        return self._main() / other

    def __rtruediv__(self, other: Any) -> Any:
        return other / self._main()

    def __pow__(self, exponent: Any) -> Any:
        return self._main() ** exponent

    def __neg__(self) -> Any:
        return -self._main()

    def _pretty(self, printer: Any = None) -> Any:
        """2-D pretty print of the mathematics the LaTeX shows (:meth:`_pretty_items`)."""
        from sympy.printing.pretty.stringpict import prettyForm, stringPict

        rows = []
        for label, value in self._pretty_items():
            shown = display(sp.sympify(value), self._pretty_symbol(), latex=False)
            body = printer._print(shown) if printer is not None else prettyForm(sp.pretty(shown))
            if isinstance(label, sp.Basic):
                label = printer._print(label) if printer is not None else prettyForm(sp.pretty(label))
            else:
                label = prettyForm(label)
            rows.append(prettyForm(*stringPict.next(label, " = ", body)))
        out = rows[0]
        for row in rows[1:]:
            out = prettyForm(*stringPict.stack(out, row))
        return out

    def _pretty_items(self) -> list[tuple[str, Any]]:
        main = self.series_expression()
        return [("x", main)] if _is_series(main) else [(f"x{i + 1}", s) for i, s in enumerate(main)]

    def _pretty_symbol(self) -> sp.Symbol:
        main = self.series_expression()
        return (main if _is_series(main) else main[0]).symbol


def _is_series(obj: Any) -> bool:
    from ._series import EpsSeries

    return isinstance(obj, EpsSeries)


def subs_one(s: Any, old: sp.Basic, new: sp.Basic, **kwargs: Any) -> Any:
    """One substitution ``old -> new`` in the series ``s`` (see :meth:`EpsSeries.subs`)."""
    from ._series import EpsSeries

    if not isinstance(s, EpsSeries):
        return s.subs(old, new, **kwargs)
    x = s.symbol
    inner = set(s.factor.free_symbols).union(*(sp.sympify(c).free_symbols for c in s.coefficients))
    if old == x and isinstance(new, sp.Expr) and not new.has(sp.Order):
        if new.is_number:  # the truncated sum at a point (the order term has no value there)
            return sp.Add(*[c * new**k for k, c in enumerate(s._folded)])
        if isinstance(new, sp.Symbol) and new not in inner:
            return EpsSeries(s.coefficients, new, s.order, s.factor, s.name)
    elif x not in old.free_symbols and x not in new.free_symbols and not new.has(sp.Order):
        cs = tuple(tidy(sp.sympify(c).subs(old, new, **kwargs)) for c in s.coefficients)
        return EpsSeries(cs, x, s.order, sp.sympify(s.factor).subs(old, new, **kwargs), s.name)
    return EpsSeries.from_sympy(s.as_series().subs(old, new, **kwargs), strict=False)


def derivative(s: Any, var: Any, **kwargs: Any) -> Any:
    """``d s / d var`` for one variable (see :meth:`EpsSeries.diff`)."""
    from ._series import EpsSeries

    if not isinstance(s, EpsSeries):
        return sp.diff(s, var, **kwargs)
    base = s.name.rstrip("'")
    name = f"{s.name}'" if base.isidentifier() and base != "series" else "series"
    if var == s.symbol and s.order >= 1:
        cs = tuple(k * c for k, c in enumerate(s.coefficients) if k)
        return EpsSeries(cs, s.symbol, s.order - 1, s.factor, name)
    if var == s.symbol or not isinstance(var, sp.Symbol):
        return sp.diff(s.as_series(), var, **kwargs)  # O(1), or a variable SymPy must handle
    cs = tuple(tidy(sp.diff(c, var)) for c in s._folded)
    return EpsSeries(cs, s.symbol, s.order, sp.S.One, name)
