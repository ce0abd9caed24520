"""Newcomb–Lindstedt series for conservative oscillators ``x'' + x = eps*f(x)`` (Bulgakov §5.4).

The motion starts at the turning point ``x(0) = A, x'(0) = 0``.  With ``tau = omega*t`` and ``x = A*y`` the equation
becomes ``omega**2 y'' + y = eps*f(A*y)/A``; order by order ``y_k'' + y_k = R_k`` and the ``cos tau`` term of ``R_k``
fixes the k-th coefficient of ``omega**2`` (there are no sine terms: the motion is even in ``tau``).  Coefficients are
exact: rationals when ``f`` is homogeneous (then the series is really in ``eps*A**(d-1)``), otherwise polynomials in
``A`` and any parameters of ``f`` (SymPy polynomial ring over QQ).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import numpy as np
import sympy as sp

from ..._deprecation import deprecated_attribute as _deprecated_attribute
from ..._deprecation import renamed_keyword
from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from ...numeric import compile as _compile
from ._arith.trig import ExactArith, RingArith, Trig, _Arith
from ._series import EpsSeries, SeriesResult, to_sympy_number

__all__ = ["LindstedtSeries", "lindstedt"]

X = sp.Symbol("x")
EPS = sp.Symbol("eps")
AMP = sp.Symbol("A")
TAU = sp.Symbol("tau")


@dataclass(frozen=True)
class LindstedtSeries(SeriesResult, SymPyPrintable):
    """Periodic family of ``x'' + x = eps*f(x)`` through ``x(0) = A, x'(0) = 0`` (Newcomb–Lindstedt).

    As a SymPy object the result is its solution ``x(tau) = sum_k eps**k x_k(tau, A) + O(eps**(order+1))`` with
    ``tau = omega*t`` (:meth:`solution_series`).

    Attributes
    ----------
    f : Expr
        The conservative force ``f(x)``, a polynomial in ``x`` with ``f(0) = 0``.
    x : Symbol
        Symbol of the coordinate in ``f``.
    eps_symbol : Symbol
        Symbol of the small parameter (the expansion variable of the series).
    amplitude : Symbol
        Symbol of the amplitude ``A = x(0)`` (the motion starts at rest there).
    frequency : EpsSeries
        ``omega(eps, A)``; coefficients are polynomials in ``A`` (and the parameters of ``f``).
    frequency_squared : EpsSeries
        ``omega**2`` (the book's ``1 + delta``).
    period : EpsSeries
        ``2 pi/omega``.
    order : int
        Highest power of ``eps`` reached.
    _harmonics : tuple of tuple of Expr
        Internal: the cosine coefficients of ``y_k(tau)`` (``x = A*y``) for each order ``k``, used by
        :meth:`solution`.
    """

    f: sp.Expr
    x: sp.Symbol
    eps_symbol: sp.Symbol
    amplitude: sp.Symbol
    order: int
    frequency: EpsSeries
    frequency_squared: EpsSeries
    period: EpsSeries
    _harmonics: tuple = field(repr=False, compare=False)  # cos coefficients of y_k (x = A*y)
    eps = _deprecated_attribute("eps_symbol")  # the old name of the small-parameter symbol

    def solution(self, order: int | None = None, tau: sp.Symbol = TAU) -> sp.Expr:
        """``x(tau)`` truncated at ``order`` (a cosine polynomial in ``tau = omega*t``).

        Parameters
        ----------
        order : int, optional
            Highest power of ``eps`` kept, an integer from 0 to ``self.order``; all computed orders when omitted.
        tau : Symbol, optional
            Symbol of the phase ``tau = omega*t`` in the result (default ``tau``).
        """
        return sp.expand(self.solution_series(order, tau).removeO())

    def solution_series(self, order: int | None = None, tau: sp.Symbol = TAU) -> EpsSeries:
        """``x(tau) = sum_k eps**k x_k(tau) + O(eps**(order+1))`` as an :class:`EpsSeries` (coefficients in ``tau``
        and ``A``).

        Parameters
        ----------
        order : int, optional
            Highest power of ``eps`` kept (default: all, ``self.order``).
        tau : Symbol
            The phase variable ``tau = omega*t``.

        Examples
        --------
        >>> import sympy as sp
        >>> x = sp.Symbol("x")
        >>> lindstedt(-x**3, 1).solution_series()
        x = A*cos(tau) + eps*(-A**3*cos(tau)/32 + A**3*cos(3*tau)/32) + O(eps**2)
        """
        n = self.order if order is None else int(order)
        if n < 0 or n > self.order:
            raise ParameterError(f"solution is known to order {self.order}; asked for {order}")
        coefficients = tuple(
            sp.expand(self.amplitude * sp.Add(*[c * sp.cos(h * tau) for h, c in enumerate(cs) if c != 0]))
            for cs in self._harmonics[: n + 1]
        )
        return EpsSeries(coefficients, self.eps_symbol, n, name=self.x.name)

    def series_expression(self) -> EpsSeries:
        """The solution ``x(tau)`` with its order term (:meth:`solution_series`): what ``sympy.sympify`` gives."""
        return self.solution_series()

    def _pretty_items(self) -> list:
        return [(sp.Symbol("omega"), self.frequency)]

    def frequency_in_amplitude(self) -> sp.Expr:
        """``omega`` at ``eps = 1`` as a polynomial in ``A`` truncated where it is complete (book form (5.58)).

        Each power of ``eps`` carries at least ``A**(dmin - 1)`` (``dmin`` = lowest degree in ``f`` above 1), so all
        terms up to ``A**(order*(dmin-1))`` are exact.
        """
        expr = sp.expand(self.frequency.expr.subs(self.eps_symbol, 1))
        poly = sp.Poly(expr, self.amplitude)
        dmin = min(k for k in sp.Poly(self.f, self.x).monoms() if k[0] > 1)[0] if self._nonlinear_degrees() else 2
        top = self.order * (dmin - 1)
        return sp.Add(*[c * self.amplitude**m for (m,), c in poly.terms() if m <= top])

    def _nonlinear_degrees(self) -> list[int]:
        return [m[0] for m in sp.Poly(self.f, self.x).monoms() if m[0] > 1]

    def omega(self, eps: Any, A: Any, order: int | None = None, **values: Any) -> Any:
        """Numeric frequency of the truncated series (NumPy broadcasting over ``eps`` and ``A``).

        Parameters
        ----------
        eps : float or array_like of float
            Value(s) of the small parameter; real numbers, broadcast against ``A``.
        A : float or array_like of float
            Amplitude value(s) ``x(0)``; real numbers, broadcast against ``eps``.
        order : int, optional
            Highest power of ``eps`` kept, an integer >= 0; all computed orders when omitted (larger values are
            clipped to ``self.order``).
        **values : float
            Values of the other parameters of ``f``, keyed by symbol name (each one that occurs must be given).
        """
        expr = self._truncated(self.frequency, order)
        params = sorted(expr.free_symbols - {self.eps_symbol, self.amplitude}, key=lambda s: s.name)
        fn = _compile(expr, [self.eps_symbol, self.amplitude, *params])
        return fn(eps, A, *[values[p.name] for p in params])

    def _truncated(self, s: EpsSeries, order: int | None) -> sp.Expr:
        n = s.order if order is None else min(int(order), s.order)
        return s.factor * sp.Add(*[c * self.eps_symbol**k for k, c in enumerate(s.coefficients[: n + 1])])

    def validate(self, eps: float, A: float, **kwargs: Any) -> Any:
        """Compare with the numerically integrated period; see :func:`symosc.nonlinear.validate_lindstedt`.

        Parameters
        ----------
        eps : float
            Value of the small parameter at which to compare; a finite real number.
        A : float
            Amplitude (starting displacement at rest) at which to compare; a finite real number.
        **kwargs
            ``orders=`` and ``rtol=``, passed to :func:`~symosc.nonlinear.validate_lindstedt`.
        """
        from .validate import validate_lindstedt

        return validate_lindstedt(self, eps, A, **kwargs)

    def __repr__(self) -> str:
        shown = EpsSeries(
            self.frequency.coefficients[:4], self.eps_symbol, min(3, self.order), name="omega"
        )  # a readable head
        return (
            f"LindstedtSeries(x'' + x = {self.eps_symbol}*({self.f}), x(0) = {self.amplitude}, order={self.order},\n"
            f"  omega = {shown.expr} + ... (to {self.eps_symbol}**{self.order}))"
        )

    def _repr_latex_(self) -> str:
        return self.frequency._repr_latex_()


def _xtable_push(ar: _Arith, X: dict[int, list[Trig]], xm: Trig) -> None:
    m = len(X[1])
    X[1].append(xm)
    for p in range(2, len(X) + 1):
        acc = ar.mul(X[1][0], X[p - 1][m])
        for i in range(1, m + 1):
            acc = ar.add(acc, ar.mul(X[1][i], X[p - 1][m - i]))
        X[p].append(acc)


def _lindstedt_raw(coeffs: dict[int, Any], ar: _Arith, order: int) -> tuple[list[Trig], list[Any]]:
    pmax = max(max(coeffs), 1)
    one = ar.scalar(1)
    y = [ar.monomial("c", 1, one)]
    s = [one]
    X: dict[int, list[Trig]] = {p: [] for p in range(1, pmax + 1)}
    const = ar.monomial("c", 0, one)
    for k in range(1, order + 1):
        m = k - 1
        _xtable_push(ar, X, y[m])
        R = ar.new(0)
        for p, c in coeffs.items():
            t = (const if m == 0 else None) if p == 0 else X[p][m]
            if t is not None:
                R = ar.add(R, ar.scale(t, c))
        if k > 1:
            R = ar.sub(R, ar.deriv(ar.deriv(ar.lincomb(s[1:k], y[k - 1 : 0 : -1]))))
        sk = -ar.coeff(R, "c", 1)
        s.append(sk)
        R = ar.add_coeff(R, "c", 1, sk)
        yk = ar.solve_forced(R)
        total = ar.scalar(0)
        for h in range(len(yk.cos)):
            total = total + ar.coeff(yk, "c", h)
        yk = ar.add_coeff(yk, "c", 1, -total)
        y.append(yk)
    return y, s


@validated
@renamed_keyword({"eps": "eps_symbol"})
def lindstedt(
    f: Any,
    order: int,
    *,
    x: sp.Symbol = X,
    eps_symbol: sp.Symbol = EPS,
    amplitude: sp.Symbol = AMP,
) -> LindstedtSeries:
    """Newcomb–Lindstedt frequency series of ``x'' + x = eps*f(x)`` with ``x(0) = A``, ``x'(0) = 0``.

    Parameters
    ----------
    f : Expr
        A polynomial in ``x`` with ``f(0) = 0`` (a restoring force about the equilibrium ``x = 0``); its coefficients
        may contain other symbols (kept exact in the result).
    order : int
        Highest power of ``eps`` (>= 1).
    x : Symbol, optional
        Symbol of the coordinate in ``f`` (default ``x``).
    eps_symbol : Symbol, optional
        Symbol of the small parameter in the result (default ``eps``); ``f`` must not contain it. The old keyword
        ``eps=`` is still accepted, with a deprecation warning.
    amplitude : Symbol, optional
        Symbol of the amplitude ``A = x(0)`` in the result (default ``A``); ``f`` must not contain it.

    Returns
    -------
    LindstedtSeries

    See Also
    --------
    limit_cycle
    numeric_period
    validate_lindstedt

    Examples
    --------
    Duffing ``x'' + x + eps*x**3 = 0``:

    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> ls = lindstedt(-x**3, 3)
    >>> ls.frequency.expr
    81*A**6*eps**3/2048 - 21*A**4*eps**2/256 + 3*A**2*eps/8 + 1

    The book's general restoring force ``q'' + q(1 + c1 q + c2 q**2) = 0`` (eps = 1, series in A), Bulgakov (5.58):

    >>> c1, c2 = sp.symbols("c1 c2")
    >>> ls = lindstedt(-(c1 * x**2 + c2 * x**3), 2)
    >>> om2 = sp.expand(ls.frequency_squared.expr.subs(sp.Symbol("eps"), 1))
    >>> om2.coeff(sp.Symbol("A"), 2)
    -5*c1**2/6 + 3*c2/4
    """
    eps = eps_symbol
    if isinstance(order, bool) or not isinstance(order, int | np.integer) or order < 1:
        raise ParameterError(f"order must be an integer >= 1, got {order!r}")
    order = int(order)
    f = sp.sympify(f)
    ren = {s_: x for s_ in f.free_symbols if s_.name == x.name and s_ != x}
    f = f.xreplace(ren) if ren else f
    if eps in f.free_symbols or amplitude in f.free_symbols:
        raise ParameterError(f"f must not contain {eps} or {amplitude}")
    if f.has(sp.Derivative) or any(s.name.endswith("_dot") or s.name == "v" for s in f.free_symbols):
        raise ModelError("lindstedt() is for conservative forces f(x); for f(x, v) use limit_cycle()")
    try:
        poly = sp.Poly(sp.expand(f), x)
    except sp.PolynomialError as exc:
        raise ModelError(
            f"f must be a polynomial in {x} for the Lindstedt series; got {f}. Use its Taylor polynomial"
        ) from exc
    if not poly.free_symbols_in_domain and poly.is_zero:
        raise ModelError("f = 0: the frequency is exactly 1")
    terms = {int(m[0]): c for m, c in poly.terms()}
    if 0 in terms:
        raise ModelError(
            f"f(0) = {terms[0]} != 0: x = 0 is not an equilibrium; shift x to the equilibrium (and absorb the "
            "linear part into the unperturbed frequency) before expanding"
        )
    params = sorted(set().union(*(sp.sympify(c).free_symbols for c in terms.values())), key=lambda s: s.name)
    for c in terms.values():
        if not sp.sympify(c).is_polynomial(*params):
            raise ParameterError(f"coefficient {c} of f must be polynomial in its parameters")
    degrees = set(terms)
    homogeneous = len(degrees) == 1 and not params
    if homogeneous:
        (d,) = degrees
        ar: _Arith = ExactArith()
        c = sp.Rational(terms[d])
        if not c.is_Rational:
            raise ParameterError(f"coefficient {terms[d]} must be rational (or a symbol)")
        coeffs: dict[int, Any] = {d: Fraction(int(c.p), int(c.q))}
    else:
        ring = sp.ring([amplitude, *params], sp.QQ)[0]
        ar = RingArith(ring)
        coeffs = {}
        for p, c in terms.items():
            coeffs[p] = ring.from_expr(sp.expand(c * amplitude ** (p - 1)))
    y, s = _lindstedt_raw(coeffs, ar, order)

    def conv(c: Any, k: int) -> sp.Expr:
        if homogeneous:
            return to_sympy_number(c) * (amplitude ** (d - 1)) ** k
        return sp.expand(c.as_expr()) if not isinstance(c, int | Fraction) else to_sympy_number(c)

    # omega = sqrt(omega**2); period 2 pi/omega (in the ring/rational arithmetic, then converted)
    w = [s[0]]
    for k in range(1, order + 1):
        acc = s[k]
        for i in range(1, k):
            acc = acc - w[i] * w[k - i]
        w.append(ar.sdiv(acc, ar.scalar(2)))
    inv = [s[0]]
    for k in range(1, order + 1):
        acc = ar.scalar(0)
        for i in range(1, k + 1):
            acc = acc - w[i] * inv[k - i]
        inv.append(acc)
    harmonics = []
    for k, yk in enumerate(y):
        cs = [conv(ar.coeff(yk, "c", h), k) for h in range(len(yk.cos))]
        harmonics.append(tuple(cs))
    return LindstedtSeries(
        f=f,
        x=x,
        eps_symbol=eps,
        amplitude=amplitude,
        order=order,
        frequency=EpsSeries(tuple(conv(c, k) for k, c in enumerate(w)), eps, order, name="omega"),
        frequency_squared=EpsSeries(tuple(conv(c, k) for k, c in enumerate(s)), eps, order, name="omega**2"),
        period=EpsSeries(tuple(conv(c, k) for k, c in enumerate(inv)), eps, order, 2 * sp.pi, name="period"),
        _harmonics=tuple(harmonics),
    )
