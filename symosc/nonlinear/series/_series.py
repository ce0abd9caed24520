"""Power series in the small parameter with the order reached, numeric evaluation and convergence estimates."""

from __future__ import annotations

import functools
import math
import operator
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import mpmath
import mpmath.libmp as mlib
import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ...errors import SeriesWarning, warn
from . import _series_algebra
from . import _series_checks as checks
from ._series_algebra import SeriesResult

__all__ = ["EpsSeries", "RadiusEstimate", "SeriesResult"]

_ONE = sp.Integer(1)
_PREC17 = mlib.libmpf.dps_to_prec(17)
_FLOAT_ZERO = sp.Float(0.0, 17)


def to_sympy_number(value: Any, dps: int = 17) -> sp.Expr:
    """A coefficient (Fraction, mpf, float, int, SymPy) as a SymPy number."""
    if isinstance(value, Fraction):
        return sp.Rational(value.numerator, value.denominator)
    if isinstance(value, mpmath.mpf):
        return sp.Float(value, dps)
    if isinstance(value, float | np.floating):
        value = float(value)
        if value == 0.0:
            return _FLOAT_ZERO
        if math.isfinite(value):  # what Float(value, 17) builds, without its generic input handling
            return sp.Float._new(mlib.from_float(value, _PREC17, mlib.round_nearest), _PREC17, zero=False)
        return sp.Float(value, 17)
    return sp.sympify(value)


@dataclass(frozen=True)
class RadiusEstimate(SymPyPrintable):
    """Radius of convergence of a power series estimated from its coefficients.

    Attributes
    ----------
    radius : float
        The estimate in the original variable (``eps``).
    method : str
        ``"domb-sykes"`` (ratio of consecutive coefficients extrapolated linearly in 1/k: a real dominant
        singularity), ``"mercer-roberts"`` (a complex-conjugate pair of singularities) or ``"root"`` (``|c_k|^(-1/k)``).
    even : bool
        True when only even powers occur; the analysis is then done in ``eps**2``.
    singularity_on_real_axis : bool or None
        For Domb–Sykes, the sign of the ratios tells whether the nearest singularity is on the positive (+) or
        negative (-) real axis of the series variable.
    estimates : dict
        All three estimates (those that could be formed).
    terms_used : int
        Number of coefficients used.
    """

    radius: float
    method: str
    even: bool
    singularity_on_real_axis: bool | None
    estimates: dict
    terms_used: int

    def __repr__(self) -> str:
        others = ", ".join(f"{k}={v:.6g}" for k, v in self.estimates.items())
        return f"RadiusEstimate(radius={self.radius:.6g} by {self.method}; {others}; terms={self.terms_used})"


@dataclass(frozen=True)
class EpsSeries(SymPyPrintable):
    """A truncated power series ``factor * sum_k c_k eps**k + O(eps**(order+1))``, usable as a SymPy expression.

    ``sympy.sympify(s)`` (and ``sympy.S(s)``) gives the sum *with* its order term, exactly as ``sympy.series``
    returns it; :meth:`removeO` drops it, :meth:`getO` returns it.  Arithmetic with numbers, symbols, SymPy
    expressions and other series follows the rules of ``sympy.series`` and ``sympy.Order`` (a sum keeps the lower
    order, ``(a + O(eps**m)) * (b + O(eps**n))`` is known to ``min(m + vb, n + va)`` with ``va``, ``vb`` the lowest
    powers present, a power ``s**p`` with ``c_0 != 0`` keeps the order) and, unlike SymPy, products and powers are
    expanded at once; the result is again an :class:`EpsSeries` whenever it is a power series in the same variable,
    otherwise the SymPy expression SymPy itself would build.  :meth:`subs`, :meth:`diff`, :attr:`free_symbols`,
    :meth:`expand`, :meth:`evalf`, :meth:`has` act on the series; substituting a *number* for the expansion variable
    evaluates the truncated sum (the order term states how the error behaves as ``eps -> 0`` and has no value at a
    point: SymPy returns ``O(1)`` there).  Equality respects the order term: a series equals the SymPy expression
    ``sympify(series)`` and differs from its truncated sum.  LaTeX and pretty printing show ``eps`` as
    :math:`\\varepsilon`, in 2-D.

    Attributes
    ----------
    coefficients : tuple of SymPy numbers
        ``c_0 .. c_order`` (``Rational`` in exact arithmetic, ``Float`` otherwise; any SymPy expressions free of
        ``symbol`` after arithmetic or substitution).
    symbol : Symbol
        The expansion variable (``eps``).
    order : int
        The order reached: every coefficient up to ``eps**order`` is exact (or accurate to the working precision).
    factor : Expr
        An overall factor (``2*pi`` for a period, an irrational generating amplitude, ...).
    name : str
        What the series is (shown in the repr).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.nonlinear import limit_cycle
    >>> x, v = sp.symbols("x v")
    >>> w = limit_cycle((1 - x**2) * v, 4).frequency       # van der Pol, Bulgakov (1954) §5.22
    >>> sp.sympify(w)
    1 - eps**2/16 + 17*eps**4/3072 + O(eps**5)
    >>> (w * w).expr, (w * w).getO()                        # omega**2, with the order term it keeps
    (23*eps**4/1536 - eps**2/8 + 1, O(eps**5))
    >>> eps = w.symbol
    >>> (eps * w + 1).getO(), w.subs(eps, sp.Rational(1, 10))
    (O(eps**6), 30700817/30720000)
    >>> w == sp.sympify(w), w == w.removeO()
    (True, False)
    >>> print(sp.pretty(w.diff(eps), use_unicode=True))  # doctest: +NORMALIZE_WHITESPACE
                   3
           ε   17⋅ε     ⎛ 4⎞
    ω' = - ─ + ───── + O⎝ε ⎠
           8    768
    """

    coefficients: tuple
    symbol: sp.Symbol
    order: int
    factor: sp.Expr = _ONE
    name: str = "series"

    #: SymPy's binary operators defer to an operand of higher priority: ``A * series`` calls ``series.__rmul__``
    _op_priority = 20.0

    @property
    def expr(self) -> sp.Expr:
        """The truncated series as a SymPy expression (without the O-term)."""
        poly = sp.Add(*[c * self.symbol**k for k, c in enumerate(self.coefficients)])
        return self.factor * poly if self.factor != 1 else poly

    # ------------------------------------------------------------------ SymPy protocol
    def _sympy_(self) -> sp.Expr:
        """``sympy.sympify(series)`` gives the sum with its order term (as :meth:`as_series`)."""
        return self.as_series()

    def removeO(self) -> sp.Expr:
        """The truncated sum without the order term, as ``sympy.Expr.removeO``.

        Examples
        --------
        >>> import sympy as sp
        >>> from symosc.nonlinear import limit_cycle
        >>> x, v = sp.symbols("x v")
        >>> w = limit_cycle((1 - x**2) * v, 2).frequency
        >>> w.removeO(), w.getO(), sp.sympify(w) == w.as_series()
        (1 - eps**2/16, O(eps**3), True)
        >>> w.as_series()
        1 - eps**2/16 + O(eps**3)
        """
        return self.expr

    def getO(self) -> sp.Order:
        """The order term ``O(eps**(order + 1))``."""
        return sp.O(self.symbol ** (self.order + 1), self.symbol)

    def as_expr(self) -> sp.Expr:
        """The series as a SymPy expression with its order term (as ``sympy.Expr.as_expr``; see :meth:`removeO`)."""
        return self.as_series()

    def as_series(self) -> sp.Expr:
        """The truncated sum with its order term, as ``sympy.series`` returns it (factor multiplied out)."""
        return _series_algebra.as_sympy_expr(self._folded, self.order, self.symbol)

    @functools.cached_property
    def _folded(self) -> tuple:
        """The coefficients with the factor multiplied in."""
        if self.factor == 1:
            return tuple(_series_algebra.tidy(c) for c in self.coefficients)
        return tuple(_series_algebra.tidy(self.factor * c) for c in self.coefficients)

    @property
    def free_symbols(self) -> set:
        """The expansion variable and every symbol of the coefficients and the factor (as SymPy's)."""
        out = {self.symbol} | set(self.factor.free_symbols)
        for c in self.coefficients:
            out |= sp.sympify(c).free_symbols
        return out

    def has(self, *patterns: Any) -> bool:
        """Whether the series (with its order term) contains any of ``patterns`` (``sympy.Basic.has``).

        Parameters
        ----------
        patterns : Basic or type
            Subexpressions or types to look for.
        """
        return self.as_series().has(*patterns)

    def __eq__(self, other: Any) -> bool:
        if isinstance(other, EpsSeries):
            return (self.symbol, self.order, self._folded) == (other.symbol, other.order, other._folded)
        if isinstance(other, SeriesResult):
            return other.__eq__(self)
        try:
            other = sp.sympify(other, strict=True)
        except sp.SympifyError:
            return NotImplemented
        return self.as_series() == other

    def __hash__(self) -> int:
        return hash(self.as_series())

    # ------------------------------------------------------------------ arithmetic
    def _with(self, coefficients: tuple, order: int | None, factor: Any = _ONE) -> Any:
        if order is None:  # an exact polynomial (a product with an exact zero): no order term left
            return sp.sympify(factor) * _series_algebra.as_sympy_expr(tuple(coefficients), None, self.symbol)
        return EpsSeries(tuple(coefficients), self.symbol, order, sp.sympify(factor), name="series")

    def _operand(self, other: Any) -> Any:
        """``other`` as ``(coefficients, order, factor)`` in this series' variable, or a SymPy object, or
        NotImplemented."""
        if isinstance(other, SeriesResult):
            other = other.series_expression()
        if isinstance(other, EpsSeries):
            if other.symbol == self.symbol:
                return other.coefficients, other.order, other.factor
            return other.as_series()
        try:
            other = sp.sympify(other, strict=True)
        except sp.SympifyError:
            return NotImplemented
        data = _series_algebra.from_expr(other, self.symbol)
        return other if data is None else (*data, _ONE)

    def _binary(self, other: Any, op: str, reflected: bool = False) -> Any:
        data = self._operand(other)
        if data is NotImplemented:
            return NotImplemented
        if not isinstance(data, tuple):  # not a power series in this variable: what SymPy builds
            a, b = (data, self.as_series()) if reflected else (self.as_series(), data)
            return {"add": operator.add, "sub": operator.sub, "mul": operator.mul, "div": operator.truediv}[op](a, b)
        cs, order, factor = data
        if op == "sub":
            op, factor = "add", -factor
        if op == "add":
            if factor == self.factor and order is not None:
                out, o = _series_algebra.add(self.coefficients, self.order, cs, order)
                return self._with(out, o, self.factor)
            other_cs = cs if factor == 1 else tuple(_series_algebra.tidy(factor * c) for c in cs)
            out, o = _series_algebra.add(self._folded, self.order, other_cs, order)
            return self._with(out, o)
        if op == "mul":
            if order is None and not cs:  # an exact zero: 0*O(eps**n) = 0
                return sp.S.Zero
            if order is None and len(cs) == 1:  # a constant: into the factor
                return self._with(self.coefficients, self.order, self.factor * factor * cs[0])
            out, o = _series_algebra.mul(self.coefficients, self.order, cs, order)
            return self._with(out, o, self.factor * factor)
        # division: (reflected) other / self, or self / other
        num, den = ((cs, order, factor), self._parts()) if reflected else (self._parts(), (cs, order, factor))
        if den[1] is None and len(den[0]) <= 1:
            if not den[0] or _series_algebra.is_zero(den[0][0] * den[2]):
                raise ZeroDivisionError(f"division of {self.name} by zero")
            return EpsSeries(num[0], self.symbol, num[1], num[2] / (den[0][0] * den[2]), "series")
        cap = num[1] if den[1] is None else den[1]
        inv = _series_algebra.power(den[0][: None if cap is None else cap + 1], cap, -1) if cap is not None else None
        if inv is None:
            return data_expr(num, self.symbol) / data_expr(den, self.symbol)
        if num[1] is None and len(num[0]) <= 1:  # a constant over a series: the constant into the factor
            return self._with(inv[0], inv[1], (num[0][0] if num[0] else 0) * num[2] / den[2])
        out, o = _series_algebra.mul(num[0], num[1], *inv)
        return self._with(out, o, num[2] / den[2])

    def _parts(self) -> tuple:
        return self.coefficients, self.order, self.factor

    def __add__(self, other: Any) -> Any:
        return self._binary(other, "add")

    __radd__ = __add__

    def __sub__(self, other: Any) -> Any:
        return self._binary(other, "sub")

    def __rsub__(self, other: Any) -> Any:
        return (-self)._binary(other, "add")

    def __mul__(self, other: Any) -> Any:
        return self._binary(other, "mul")

    __rmul__ = __mul__

    def __truediv__(self, other: Any) -> Any:
        return self._binary(other, "div")

    def __rtruediv__(self, other: Any) -> Any:
        return self._binary(other, "div", reflected=True)

    def __neg__(self) -> EpsSeries:
        return EpsSeries(self.coefficients, self.symbol, self.order, -self.factor, self.name)

    def __pos__(self) -> EpsSeries:
        return self

    def __pow__(self, exponent: Any) -> Any:
        try:
            p = sp.sympify(exponent, strict=True)
        except sp.SympifyError:
            return NotImplemented
        out = _series_algebra.power(self.coefficients, self.order, p) if not p.free_symbols else None
        if out is None:
            return sp.Pow(self.as_series(), p)
        return self._with(out[0], out[1], self.factor**p)

    def __rpow__(self, base: Any) -> Any:
        return sp.Pow(sp.sympify(base), self.as_series())

    # ------------------------------------------------------------------ substitution and calculus
    def subs(self, *args: Any, **kwargs: Any) -> Any:
        """Substitute as ``sympy.Basic.subs``; an :class:`EpsSeries` while the result is a series in one variable.

        Parameters
        ----------
        args : pair, mapping or iterable of pairs
            ``old, new`` or ``{old: new, ...}`` or ``[(old, new), ...]``, applied in turn.
        kwargs
            Passed on to ``sympy.Basic.subs`` for the coefficients.

        Returns
        -------
        EpsSeries or Expr
            A parameter replaced: the series with new coefficients.  The expansion variable replaced by a symbol:
            the series in that symbol.  By a number: the truncated sum at that number (exact for an exact number).
            Otherwise what ``sympy.Basic.subs`` gives for :meth:`as_series`.

        Examples
        --------
        >>> import sympy as sp
        >>> from symosc.nonlinear import lindstedt
        >>> x, A = sp.symbols("x A")
        >>> w = lindstedt(-x**3, 2).frequency              # Duffing: omega(eps, A)
        >>> w.subs(A, 2)
        omega = -21*eps**2/16 + 3*eps/2 + 1 + O(eps**3)
        >>> w.subs({A: 2, w.symbol: sp.Rational(1, 10)})   # 1 + 3/20 - 21/1600
        1819/1600
        """
        out: Any = self
        for old, new in _series_algebra.substitution_pairs(args):
            out = _series_algebra.subs_one(out, old, new, **kwargs)
        return out

    def diff(self, *symbols: Any, **kwargs: Any) -> Any:
        """Derivative (``sympy.diff(series, x)`` works too): in ``eps`` the order drops by one, in a parameter the
        coefficients are differentiated.

        Parameters
        ----------
        symbols : Symbol, or Symbol and count
            Variables as in ``sympy.diff`` (``eps``, ``eps, 2``, ``A, eps``).
        kwargs
            Passed on to ``sympy.diff`` where SymPy takes over (an ``O(1)`` result).
        """
        out: Any = self
        for var in _series_algebra.derivative_variables(symbols):
            out = _series_algebra.derivative(out, var, **kwargs)
        return out

    def expand(self, **hints: Any) -> EpsSeries:
        """The series with ``sympy.expand`` applied to each coefficient (and the factor multiplied in).

        Parameters
        ----------
        hints
            Hints of ``sympy.expand`` (``trig=True``, ...).
        """
        return EpsSeries(tuple(sp.expand(c, **hints) for c in self._folded), self.symbol, self.order, _ONE, self.name)

    def evalf(self, n: int = 15, **options: Any) -> EpsSeries:
        """The series with floating-point coefficients of ``n`` significant digits (``sympy.N``).

        Parameters
        ----------
        n : int
            Significant digits.
        options
            Options of ``sympy.Basic.evalf``.
        """
        cs = tuple(sp.sympify(c).evalf(n, **options) for c in self._folded)
        return EpsSeries(cs, self.symbol, self.order, _ONE, self.name)

    n = evalf

    @classmethod
    def from_sympy(
        cls, expr: Any, symbol: sp.Symbol | None = None, *, name: str = "series", strict: bool = True
    ) -> Any:
        """The :class:`EpsSeries` of a SymPy series ``c_0 + c_1*x + c_2*x**2 + O(x**3)`` (``sympy.series`` output).

        Parameters
        ----------
        expr : Expr
            A polynomial in ``symbol`` plus an order term ``O(symbol**m)`` at 0.
        symbol : Symbol, optional
            The expansion variable (default: the variable of the order term).
        name : str
            What the series is (shown in the repr).
        strict : bool
            Raise ``ValueError`` when ``expr`` is no such series (True), or return ``expr`` unchanged (False).

        Examples
        --------
        >>> import sympy as sp
        >>> from symosc.nonlinear import EpsSeries
        >>> x = sp.Symbol("x")
        >>> s = EpsSeries.from_sympy(sp.series(sp.exp(x), x, 0, 4))
        >>> s.coefficients, s.order
        ((1, 1, 1/2, 1/6), 3)
        """
        e = sp.sympify(expr)
        o = e.getO() if isinstance(e, sp.Expr) else None
        x = symbol if symbol is not None else (o.variables[0] if o is not None and len(o.variables) == 1 else None)
        data = _series_algebra.from_expr(e, x) if x is not None else None
        if data is None or data[1] is None:
            if strict:
                raise ValueError(f"{expr} is not a power series with an order term O(x**m) at x = 0")
            return e
        return cls(data[0], x, data[1], _ONE, name)

    # ------------------------------------------------------------------ printing
    def _sympystr(self, printer: Any = None) -> str:
        return repr(self)

    def _latex(self, printer: Any = None) -> str:
        shown = _series_algebra.display(self._display_expr(), self.symbol, latex=True)
        return printer._print(shown) if printer is not None else sp.latex(shown)

    def _pretty(self, printer: Any = None) -> Any:
        from sympy.printing.pretty.stringpict import prettyForm, stringPict

        shown = _series_algebra.display(self._display_expr(), self.symbol, latex=False)
        body = printer._print(shown) if printer is not None else prettyForm(sp.pretty(shown))
        label = _series_algebra.pretty_label(self.name, printer)
        return body if label is None else prettyForm(*stringPict.next(label, " = ", body))

    def _display_expr(self) -> sp.Expr:
        """The series for display: the factor kept outside the sum (``2*pi*(1 + ...) + O(...)``)."""
        return self.expr + self.getO() if self.factor == 1 else sp.Add(self.expr, self.getO(), evaluate=False)

    def coefficient(self, k: int) -> sp.Expr:
        """Coefficient of ``eps**k`` (including ``factor``).

        Parameters
        ----------
        k : int
            Power of ``eps`` whose coefficient is wanted; an integer from 0 to ``order`` (a larger one raises
            IndexError).
        """
        k = checks.power_index(k, self.order, self.name)
        return self.factor * self.coefficients[k]

    def evaluate(self, value: Any, order: int | None = None, *, dps: int | None = None) -> Any:
        """Numeric value of the series truncated at ``order`` (default: all terms).

        With ``dps`` the sum is formed in mpmath at that precision and an ``mpf`` is returned; otherwise a float
        (or a float array when ``value`` is an array).

        Parameters
        ----------
        value : float, mpmath.mpf or array_like of float
            Value of the expansion variable ``eps`` at which to sum the series; real numbers (an array is summed
            element by element). A ``SeriesWarning`` is issued when ``|value|`` exceeds the estimated radius of
            convergence.
        order : int, optional
            Highest power of ``eps`` kept in the sum, an integer >= 0; all known terms when omitted (values above
            ``self.order`` are clipped to it).
        dps : int, optional
            Decimal digits of the mpmath working precision, an integer >= 1; when given the sum is formed in mpmath
            and an ``mpf`` is returned, otherwise in float64.
        """
        value, order, dps = checks.point(value), checks.optional_count("order", order, 0), checks.dps(dps)
        n = self.order if order is None else min(int(order), self.order)
        _warn_beyond_radius(self, value, n)
        if dps is not None:
            with mpmath.workdps(dps):
                x = mpmath.mpf(value) if not isinstance(value, mpmath.mpf) else value
                acc = mpmath.mpf(0)
                for c in reversed(self.coefficients[: n + 1]):
                    acc = acc * x + mpmath.mpf(sp.N(c, dps + 5))
                return acc * mpmath.mpf(sp.N(self.factor, dps + 5))
        x = np.asarray(value, dtype=float)
        acc = np.zeros_like(x)
        for c in reversed(self.coefficients[: n + 1]):
            acc = acc * x + float(c)
        out = acc * float(self.factor)
        return float(out) if out.ndim == 0 else out

    __call__ = evaluate

    def evaluate_pade(self, value: Any, m: int | None = None, n: int | None = None, *, dps: int | None = None) -> Any:
        """Diagonal (or ``[m/n]``) Padé approximant of the series at ``value`` (mpmath.pade).

        For a series in even powers only the approximant is built in ``eps**2``.  Padé continues the series beyond
        its radius of convergence when the nearest singularities are poles or branch points off the real axis, as for
        van der Pol (there ``[10/10]`` in ``eps**2`` gives the frequency at ``eps = 3`` to 1e-5).

        Parameters
        ----------
        value : float or mpmath.mpf
            Value of the expansion variable ``eps`` at which to evaluate the approximant; a real number.
        m : int, optional
            Degree of the numerator, an integer >= 0 with ``m + n`` at most the number of coefficients less one
            (counted in ``eps**2`` for an even series); ``N - n`` when omitted, and ``N // 2`` (diagonal) when both
            degrees are omitted.
        n : int, optional
            Degree of the denominator, an integer >= 0 with ``m + n`` at most the number of coefficients less one;
            ``N - m`` when omitted, and ``N - N // 2`` when both degrees are omitted.
        dps : int, optional
            Decimal digits of the mpmath working precision, an integer >= 1; when given an ``mpf`` is returned,
            otherwise a float computed at 30 digits.
        """
        value, dps = checks.point(value), checks.dps(dps)
        work = dps or 30
        with mpmath.workdps(work + 10):
            cs = [mpmath.mpf(sp.N(c, work + 10)) for c in self.coefficients]
            even = len(cs) > 4 and all(c == 0 for c in cs[1::2])
            seq = cs[::2] if even else cs
            m, n = checks.pade_degrees(m, n, len(seq) - 1)
            try:
                p, q = mpmath.pade(seq[: m + n + 1], m, n)
            except ZeroDivisionError:
                raise checks.no_pade(self.name, m, n) from None
            x = mpmath.mpf(value)
            u = x * x if even else x
            val = mpmath.polyval(p[::-1], u) / mpmath.polyval(q[::-1], u) * mpmath.mpf(sp.N(self.factor, work + 10))
            return +val if dps is not None else float(val)

    def radius_of_convergence(self, terms: int | None = None) -> RadiusEstimate:
        """Estimate the radius of convergence from the last coefficients (Domb–Sykes / Mercer–Roberts / root test).

        Uses the coefficients in the variable ``eps**2`` when the odd ones vanish.  The method chosen is the one whose
        underlying assumption fits: Domb–Sykes when the ratios keep one sign pattern, Mercer–Roberts when they oscillate
        irregularly (complex singularities).

        Parameters
        ----------
        terms : int, optional
            Number of trailing coefficients (of the series in ``eps``, or in ``eps**2`` for an even series) used by
            the ratio fits, a positive integer (fewer than 3 usable ratios leave only the root test); half of them,
            and at least 6, when omitted.
        """
        terms = checks.optional_count("terms", terms, 1)
        cs = [mpmath.mpf(sp.N(c, 30)) for c in self.coefficients]
        even = all(c == 0 for c in cs[1::2]) and len(cs) > 4
        seq = cs[::2] if even else cs
        # drop leading zeros; need enough terms
        idx = [k for k, c in enumerate(seq) if c != 0]
        if len(idx) < 6:
            raise checks.too_short(len(idx))
        kmax = len(seq) - 1
        m = terms or max(6, (kmax + 1) // 2)
        ks = [k for k in range(max(2, kmax - m + 1), kmax + 1) if seq[k] != 0 and seq[k - 1] != 0]
        estimates: dict[str, float] = {}
        power = 2 if even else 1
        # root test on the last coefficient
        last = kmax
        estimates["root"] = float(abs(seq[last]) ** (-mpmath.mpf(1) / last)) ** (1 / power)
        # Domb–Sykes: r_k = c_k / c_{k-1} ~ (1/R)(1 - g/k); fit linear in 1/k, intercept = 1/R
        ratios = [seq[k] / seq[k - 1] for k in ks]
        signs = {mpmath.sign(r) for r in ratios}
        dom_sign: bool | None = None
        if len(ks) >= 3:
            x = np.array([1.0 / k for k in ks])
            y = np.array([float(r) for r in ratios])
            _slope, icpt = np.polyfit(x, y, 1)
            if icpt != 0:
                estimates["domb-sykes"] = abs(1.0 / icpt) ** (1 / power)
                dom_sign = bool(icpt > 0)
        # Mercer–Roberts: B_k^2 = (c_{k+1} c_{k-1} - c_k^2)/(c_k c_{k-2} - c_{k-1}^2), fit linear in 1/k
        mr_k, mr_v = [], []
        for k in range(max(3, kmax - m + 1), kmax):
            den = seq[k] * seq[k - 2] - seq[k - 1] ** 2
            num = seq[k + 1] * seq[k - 1] - seq[k] ** 2
            if den != 0 and num / den > 0:
                mr_k.append(1.0 / k)
                mr_v.append(float(mpmath.sqrt(num / den)))
        if len(mr_k) >= 3:
            _slope, icpt = np.polyfit(np.array(mr_k), np.array(mr_v), 1)
            if icpt > 0:
                estimates["mercer-roberts"] = (1.0 / icpt) ** (1 / power)
        if len(signs) == 1 or all(a * b > 0 for a, b in zip(ratios[::2], ratios[2::2], strict=False)):
            method = "domb-sykes" if "domb-sykes" in estimates else "root"
        else:
            method = "mercer-roberts" if "mercer-roberts" in estimates else "root"
        return RadiusEstimate(
            radius=estimates[method],
            method=method,
            even=even,
            singularity_on_real_axis=dom_sign if method == "domb-sykes" else None,
            estimates=estimates,
            terms_used=len(ks),
        )

    def __repr__(self) -> str:
        return f"{self.name} = {self.expr} + O({self.symbol}**{self.order + 1})"

    def _repr_latex_(self) -> str:
        return f"${self._latex()}$"


def data_expr(data: tuple, x: sp.Symbol) -> sp.Expr:
    """SymPy expression of ``(coefficients, order, factor)``."""
    cs, order, factor = data
    return factor * _series_algebra.as_sympy_expr(tuple(cs), order, x)


@functools.lru_cache(maxsize=256)
def _radius(coefficients: tuple) -> float | None:
    series = EpsSeries(coefficients, sp.Symbol("eps"), len(coefficients) - 1)
    try:
        return float(series.radius_of_convergence().radius)
    except (ValueError, ArithmeticError):
        return None


def _warn_beyond_radius(series: EpsSeries, value: Any, n: int) -> None:
    """SeriesWarning when ``|value|`` exceeds the estimated radius of convergence of ``series``, or when the sum to
    order ``n`` has not converged there (judged by its tail)."""
    try:
        size = float(np.max(np.abs(np.asarray(value, dtype=complex))))
    except (TypeError, ValueError):
        return
    if not np.isfinite(size) or size == 0:
        return
    radius = _radius(tuple(series.coefficients))
    if radius is not None and np.isfinite(radius) and size > radius:
        warn(
            f"{series.name} evaluated at |{series.symbol}| = {size:.4g}, beyond its estimated radius of convergence "
            f"{radius:.4g}: the truncated sum is not meaningful there (use evaluate_pade, or a numeric method)",
            SeriesWarning,
        )
    else:
        checks.warn_slow_tail(series, value, n)
