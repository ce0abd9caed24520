"""Poincaré's method for self-oscillations of ``x'' + x = eps*f(x, x', eps)`` to any order.

With the phase ``tau = omega*t`` the equation becomes ``omega**2 x_tautau + x = eps f(x, omega x_tau, eps)``.  The
solution, the squared frequency and the amplitude are expanded in ``eps``; each order is a forced harmonic oscillator
whose secular (``cos tau``, ``sin tau``) terms must vanish.  Those two conditions fix the next coefficient of
``omega**2`` and the ``cos tau`` coefficient left free at the previous order (Bulgakov §§5.16–5.22; Poincaré's
"periodicity conditions").  The phase is fixed by ``x_tau(0) = 0``, so ``x(0)`` is the amplitude: the turning point
where the orbit crosses the half-line ``v = 0, x > 0``.

Harmonics are truncated Fourier series with exact rational, binary fixed-point (``mpmath``) or float coefficients
(see :mod:`symosc.nonlinear.series._arith.trig`): no symbolic trigonometry is involved, so the van der Pol series
reaches order 48 exactly in about 0.2 s and order 200 in floating point in about a second.

References: Bulgakov (1954) §§5.16–5.22; Andersen & Geer, SIAM J. Appl. Math. 42
(1982) 678–693 (van der Pol to order 24); Nayfeh, *Perturbation Methods* (1973) §3.1.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ..._deprecation import deprecated_attribute as _deprecated_attribute
from ..._deprecation import renamed_keyword
from ..._plotting import plot_method
from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from ._arith.trig import FloatArith, _fmpz_poly, from_number, make_arith
from ._poincare_core import _poincare_raw, _polynomial_terms, _positive_roots, _RawSeries, amplitude_functions
from ._series import EpsSeries, SeriesResult, to_sympy_number

__all__ = ["LimitCycleSeries", "limit_cycle"]

X = sp.Symbol("x")
V = sp.Symbol("v")
EPS = sp.Symbol("eps")
TAU = sp.Symbol("tau")
_ARITHMETICS = ("exact", "float", "mpmath")


# ---------------------------------------------------------------------------------------------------------------
# public API
# ---------------------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LimitCycleSeries(SeriesResult, SymPyPrintable):
    """The periodic solution of ``x'' + x = eps*f(x, x', eps)`` by Poincaré's method.

    The phase variable is ``tau = omega*t``; the phase is fixed by ``x'(0) = 0``, so ``x(0)`` is the amplitude
    (the crossing of the half-line ``v = 0, x > 0``).

    As a SymPy object the result is its solution ``x(tau) = sum_k eps**k x_k(tau) + O(eps**(order+1))``
    (:meth:`solution_series`): ``sympy.sympify(lc)``, ``lc + 1``, ``lc * lc``, ``lc.subs(eps, 0.1)`` act on it;
    the frequency, period and amplitude are the series attributes below.

    Attributes
    ----------
    f : Expr
        The right-hand side as given.
    x : Symbol
        Symbol of the coordinate in ``f``.
    v : Symbol
        Symbol of the velocity ``x'`` in ``f``.
    eps_symbol : Symbol
        Symbol of the small parameter (the expansion variable of the series).
    order : int
        The requested (and reached) order.
    generating_amplitude : Expr
        ``A*``, the positive simple root of the amplitude equation.
    amplitude_equation : Expr
        ``H(A) = (1/pi) int_{-pi}^{pi} f(A cos s, -A sin s, 0) sin s ds`` (a polynomial in ``A``).
    generating_amplitudes : tuple
        All positive roots of ``H`` with their multiplicity.
    frequency, period, amplitude : EpsSeries
        ``omega(eps)``, ``2 pi / omega`` and ``x(0)``, to ``eps**order``.
    floquet_exponent : EpsSeries
        The nontrivial characteristic exponent of the variational equation, ``(eps/2pi) int f_v dtau`` (the orbit's
        divergence average), to ``eps**(order + 1)``; the multiplier is ``exp(exponent*period)``.
    stable : bool
        Orbital stability for small ``eps > 0`` by the sign rule ``eps * H'(A*) > 0`` (reverse it for ``eps < 0``).
    arithmetic : str
        ``"exact"``, ``"float"`` or ``"mpmath"``.
    dps : int or None
        Decimal digits of the fixed-point arithmetic when ``arithmetic="mpmath"`` (None otherwise).
    _harmonics : tuple of (list, list)
        Internal: per order ``k``, the cosine and sine coefficients of ``x_k(tau)/A*``, used by :meth:`harmonics`,
        :meth:`solution` and :meth:`evaluate_solution`.
    """

    f: sp.Expr
    x: sp.Symbol
    v: sp.Symbol
    eps_symbol: sp.Symbol
    order: int
    arithmetic: str
    dps: int | None
    generating_amplitude: sp.Expr
    amplitude_equation: sp.Expr
    generating_amplitudes: tuple
    frequency: EpsSeries
    period: EpsSeries
    amplitude: EpsSeries
    floquet_exponent: EpsSeries
    stable: bool
    _harmonics: tuple = field(repr=False, compare=False)  # per order: (cos list, sin list) of scaled x_k
    eps = _deprecated_attribute("eps_symbol")  # the old name of the small-parameter symbol

    @property
    def frequency_squared(self) -> EpsSeries:
        """``omega**2`` as a series (the book's ``(1 + alpha)**2``)."""
        c = self.frequency.coefficients
        n = self.frequency.order
        sq = tuple(sp.Add(*[c[i] * c[k - i] for i in range(k + 1)]) for k in range(n + 1))
        return EpsSeries(sq, self.eps_symbol, n, name="omega**2")

    def harmonics(self, order: int | None = None) -> list[tuple[list, list]]:
        """Fourier coefficients ``(cos[n], sin[n])`` of ``x_k(tau)`` for k = 0..order (SymPy numbers, unscaled).

        Parameters
        ----------
        order : int, optional
            Highest order ``k`` returned, an integer from 0 to ``self.order``; all computed orders when omitted.
        """
        n = self.order if order is None else self._check_order(order)
        A0 = self.generating_amplitude
        return [([A0 * c for c in cs], [A0 * s for s in ss]) for cs, ss in self._harmonics[: n + 1]]

    def _check_order(self, order: int) -> int:
        order = int(order)
        if order < 0 or order > self.order:
            raise ParameterError(f"solution is known to order {self.order}; asked for {order}")
        return order

    def solution(self, order: int | None = None, tau: sp.Symbol = TAU) -> sp.Expr:
        """``x(tau) = sum_k eps**k x_k(tau)`` truncated at ``order`` as a SymPy expression in ``tau = omega*t``.

        Parameters
        ----------
        order : int, optional
            Highest power of ``eps`` kept, an integer from 0 to ``self.order``; all computed orders when omitted.
        tau : Symbol, optional
            Symbol of the phase ``tau = omega*t`` in the result (default ``tau``).
        """
        return sp.expand(self.solution_series(order, tau).removeO())

    def solution_series(self, order: int | None = None, tau: sp.Symbol = TAU) -> EpsSeries:
        """``x(tau) = sum_k eps**k x_k(tau) + O(eps**(order+1))`` as an :class:`EpsSeries` (coefficients in ``tau``).

        Parameters
        ----------
        order : int, optional
            Highest power of ``eps`` kept (default: all, ``self.order``).
        tau : Symbol
            The phase variable ``tau = omega*t``.

        Examples
        --------
        >>> import sympy as sp
        >>> x, v = sp.symbols("x v")
        >>> lc = limit_cycle((1 - x**2) * v, 1)
        >>> lc.solution_series()
        x = eps*(3*sin(tau)/4 - sin(3*tau)/4) + 2*cos(tau) + O(eps**2)
        >>> sp.sympify(lc) == lc.solution_series()
        True
        """
        n = self.order if order is None else self._check_order(order)
        A0 = self.generating_amplitude
        coefficients = []
        for cs, ss in self._harmonics[: n + 1]:
            terms = [c * sp.cos(h * tau) for h, c in enumerate(cs) if c != 0]
            terms += [s * sp.sin(h * tau) for h, s in enumerate(ss) if s != 0]
            coefficients.append(sp.expand(A0 * sp.Add(*terms)))
        return EpsSeries(tuple(coefficients), self.eps_symbol, n, name=self.x.name)

    def series_expression(self) -> EpsSeries:
        """The solution ``x(tau)`` with its order term (:meth:`solution_series`): what ``sympy.sympify`` gives."""
        return self._solution_series

    @functools.cached_property
    def _solution_series(self) -> EpsSeries:
        return self.solution_series()

    def _pretty_items(self) -> list:
        return [(sp.Symbol("omega"), self.frequency), (sp.Symbol("a"), self.amplitude)]

    def evaluate_solution(self, eps: float, tau: Any, order: int | None = None) -> np.ndarray:
        """Numeric ``(x, dx/dt)`` of the truncated series at phase(s) ``tau`` (dx/dt = omega dx/dtau).

        Parameters
        ----------
        eps : float
            Value of the small parameter at which to sum the series; a real number (a ``SeriesWarning`` beyond the
            estimated radius of convergence).
        tau : float or array_like of float
            Phase(s) ``tau = omega*t`` at which to evaluate, in radians; real numbers.
        order : int, optional
            Highest power of ``eps`` kept, an integer from 0 to ``self.order``; all computed orders when omitted.

        Returns
        -------
        ndarray
            Shape ``(2,) + shape(tau)``: ``x`` and ``dx/dt``.
        """
        n = self.order if order is None else self._check_order(order)
        tau = np.asarray(tau, dtype=float)
        A0 = float(self.generating_amplitude)
        x = np.zeros_like(tau)
        dx = np.zeros_like(tau)
        for k, (cs, ss) in enumerate(self._harmonics[: n + 1]):
            ek = eps**k
            for h, (c, s) in enumerate(zip(cs, ss, strict=True)):
                if c == 0 and s == 0:
                    continue
                c, s = float(c), float(s)
                x += ek * (c * np.cos(h * tau) + s * np.sin(h * tau))
                dx += ek * h * (-c * np.sin(h * tau) + s * np.cos(h * tau))
        omega = self.frequency.evaluate(eps, n)
        return np.stack([A0 * x, A0 * omega * dx])

    @plot_method
    def plot(self, eps: float, order: int | None = None, *, ax: Any = None, numeric: bool = True) -> Any:
        """Phase portrait ``(x, dx/dt)`` of the truncated series at ``eps``, with the numeric cycle for comparison.

        Parameters
        ----------
        eps : float
            Value of the small parameter at which to draw the cycle; a finite real number.
        order : int, optional
            Highest power of ``eps`` kept in the series, an integer from 0 to ``self.order``; all computed orders
            when omitted.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        numeric : bool, optional
            Whether to overlay the numerically integrated cycle (:func:`~symosc.nonlinear.numeric_orbit`); default
            True.
        """
        from ..._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        tau = np.linspace(0.0, 2 * np.pi, 400)
        xs, vs = self.evaluate_solution(eps, tau, order)
        n = self.order if order is None else order
        ax.plot(xs, vs, "-", label=f"series, order {n}")
        if numeric:
            from .validate import numeric_orbit

            xn, vn = numeric_orbit(self.f, eps, x=self.x, v=self.v, eps_symbol=self.eps_symbol)
            ax.plot(xn, vn, "--", label="numeric cycle")
        ax.set_xlabel(str(self.x))
        ax.set_ylabel(f"d{self.x}/dt")
        ax.set_title(f"limit cycle, {self.eps_symbol} = {eps:g}")
        ax.legend()
        return ax

    def validate(self, eps_values: Any, **kwargs: Any) -> Any:
        """Compare the truncated series with the numerically integrated limit cycle; see
        :func:`symosc.nonlinear.validate_limit_cycle`.

        Parameters
        ----------
        eps_values : float or sequence of float
            Values of the small parameter at which to compare; finite real numbers.
        **kwargs
            ``orders=``, ``rtol=`` and ``dps=``, passed to :func:`~symosc.nonlinear.validate_limit_cycle`.
        """
        from .validate import validate_limit_cycle

        return validate_limit_cycle(self, eps_values, **kwargs)

    def __repr__(self) -> str:
        st = "stable" if self.stable else "unstable"
        return (
            f"LimitCycleSeries(x'' + x = {self.eps_symbol}*({self.f}), order={self.order}, "
            f"arithmetic={self.arithmetic!r},\n"
            f"  A* = {self.generating_amplitude} ({st} for small {self.eps_symbol} > 0),\n"
            f"  {self._short(self.frequency)},\n  {self._short(self.amplitude)})"
        )

    @staticmethod
    def _short(s: EpsSeries, terms: int = 5) -> str:
        shown = EpsSeries(s.coefficients[:terms], s.symbol, min(s.order, terms - 1), s.factor, s.name)
        more = f" (+ terms to order {s.order})" if s.order >= terms else ""
        return f"{shown.name} = {shown.expr} + ...{more}"

    def _repr_latex_(self) -> str:
        return f"$\\omega = {self.frequency._latex()},\\quad a = {self.amplitude._latex()}$"


#: largest series order accepted by limit_cycle in exact arithmetic (see the error message for the cost)
_MAX_ORDER = 200


@validated
@renamed_keyword({"eps": "eps_symbol"})
def limit_cycle(
    f: Any,
    order: int,
    *,
    x: sp.Symbol = X,
    v: sp.Symbol = V,
    eps_symbol: sp.Symbol = EPS,
    arithmetic: str = "exact",
    dps: int | None = None,
    amplitude0: float | None = None,
) -> LimitCycleSeries:
    """Limit cycle of ``x'' + x = eps*f(x, v, eps)`` (``v = x'``) as series in ``eps`` by Poincaré's method.

    Parameters
    ----------
    f : Expr
        A polynomial in ``x``, ``v`` (and optionally ``eps``) with numeric coefficients.  How it is written (expanded,
        factored) does not matter.  For ``x'' + w0**2 x = mu*Phi(x, x')`` put ``t' = w0 t``: ``eps = mu/w0**2`` and
        ``f(x, v) = Phi(x, w0*v)``; parameters in the nonlinearity can usually be scaled out (for van der Pol
        ``(kappa - lambda x**2) x'`` use ``x -> sqrt(kappa/lambda) x``, ``eps -> kappa*eps``).
    order : int
        Highest power of ``eps`` in the frequency, period, amplitude and solution (>= 1).
    x : Symbol, optional
        Symbol of the coordinate in ``f`` (default ``x``).
    v : Symbol, optional
        Symbol of the velocity ``x'`` in ``f`` (default ``v``).
    eps_symbol : Symbol, optional
        Symbol of the small parameter in ``f`` and in the series (default ``eps``). The old keyword ``eps=`` is still
        accepted, with a deprecation warning.
    arithmetic : {"exact", "float", "mpmath"}
        Exact rationals (needs rational coefficients after scaling by the generating amplitude), double precision,
        or binary fixed point at ``dps`` decimal digits (mpmath numbers on output).
    dps : int, optional
        Digits for ``arithmetic="mpmath"`` (default ``mpmath.mp.dps``).
    amplitude0 : float, optional
        Which generating amplitude to continue when the amplitude equation has several positive roots (the root
        closest to this value is used).

    Returns
    -------
    LimitCycleSeries

    Raises
    ------
    ParameterError
        ``order < 1``, unknown arithmetic, free parameters in ``f``, irrational coefficients with exact arithmetic.
    ModelError
        ``f`` not polynomial; the amplitude equation has no positive root (no limit cycle), vanishes identically
        (conservative: a family of cycles, use :func:`~symosc.nonlinear.lindstedt`), or only a multiple root; several
        roots and no ``amplitude0``.

    See Also
    --------
    lindstedt
    numeric_limit_cycle
    validate_limit_cycle
    periodic_solution_ndof

    Examples
    --------
    Van der Pol (Bulgakov §5.22): amplitude 2, frequency ``1 - eps**2/16 + 17 eps**4/3072 + ...``

    >>> import sympy as sp
    >>> x, v = sp.symbols("x v")
    >>> lc = limit_cycle((1 - x**2) * v, 4)
    >>> lc.generating_amplitude, lc.stable
    (2, True)
    >>> lc.frequency.expr
    17*eps**4/3072 - eps**2/16 + 1
    >>> lc.floquet_exponent.coefficients[:2]
    (0, -1)
    """
    eps = eps_symbol
    if isinstance(order, bool) or not isinstance(order, int | np.integer) or order < 1:
        raise ParameterError(f"order must be an integer >= 1, got {order!r}")
    order = int(order)
    if arithmetic not in _ARITHMETICS:
        raise ParameterError(f"unknown arithmetic {arithmetic!r}; choose one of {_ARITHMETICS}")
    if arithmetic == "exact" and order > _MAX_ORDER:
        raise ParameterError(
            f"order {order} is beyond the supported range (<= {_MAX_ORDER} in exact arithmetic): the numbers grow "
            "like order**2 bits, so the exact result (every harmonic of every order) has about order**4 bits and "
            "the cost grows about as order**4.5 (van der Pol: order 100 takes about 2 s, order 150 about 11 s, "
            "order 200 about 40 s of CPU time); for the radius of convergence order 40 is "
            "ample, evaluate_pade continues the series beyond it, and arithmetic='mpmath' or 'float' is much cheaper"
        )
    f = sp.sympify(f)
    terms = _polynomial_terms(f, (x, v), eps, "f")
    if not terms:
        raise ModelError("f = 0: the linear oscillator has a family of periodic solutions, no isolated limit cycle")
    A = sp.Symbol("A")
    H, _G = amplitude_functions(terms, A)
    if H == 0:
        raise ModelError(
            "the amplitude equation H(A) vanishes identically (f is conservative at leading order, e.g. f = f(x)): "
            "every small amplitude gives a periodic solution; use lindstedt(f, order) for such systems"
        )
    roots = _positive_roots(H, A)
    if not roots:
        raise ModelError(
            f"no limit cycle: the amplitude equation H(A) = {H} has no positive root "
            "(the oscillations decay or grow without bound at leading order)"
        )
    if amplitude0 is not None:
        root, mult = min(roots, key=lambda r: abs(float(r[0]) - float(amplitude0)))
    else:
        simple = [r for r in roots if r[1] == 1]
        if len(roots) > 1:
            listing = ", ".join(f"{sp.nsimplify(r)} (x{m})" for r, m in roots)
            raise ModelError(
                f"the amplitude equation H(A) = {H} has several positive roots: {listing}; "
                "pass amplitude0= to choose the cycle to continue"
            )
        root, mult = (simple or roots)[0]
    if mult > 1:
        raise ModelError(
            f"the generating amplitude A* = {root} is a multiple root of H(A) = {H} (H'(A*) = 0): a semi-stable "
            "cycle; Poincaré's series in integer powers of eps does not exist there"
        )
    A0 = sp.nsimplify(root) if root.is_Rational else root
    dH = sp.diff(H, A).subs(A, A0)
    stable = bool(sp.N(dH, 30) > 0)

    # scale x = A0*y: y'' + y = eps g(y, w, eps), g = f(A0 y, A0 w)/A0
    ar = relaxed_exact_arith() if arithmetic == "exact" else None
    ar = ar or make_arith(arithmetic, dps, order)
    coeffs: dict[tuple, Any] = {}
    dcoeffs: dict[tuple, Any] = {}
    for (p, q, j), c in terms.items():
        scaled = sp.radsimp(sp.expand(c * A0 ** (p + q - 1)))
        try:
            coeffs[(p, q, j)] = from_number(ar, scaled)
            if q > 0:
                dscaled = sp.radsimp(sp.expand(q * c * A0 ** (p + q - 1)))
                key = (p, q - 1, j)
                val = from_number(ar, dscaled)
                dcoeffs[key] = dcoeffs[key] + val if key in dcoeffs else val
        except TypeError as exc:
            raise ParameterError(
                f"exact arithmetic needs rational coefficients after scaling x by the generating amplitude "
                f"A* = {A0}; coefficient {scaled} is not rational: use arithmetic='mpmath' (or 'float')"
            ) from exc
    raw = _poincare_raw(coeffs, dcoeffs, ar, order)
    return _package(f, x, v, eps, order, arithmetic, dps, A0, H, roots, stable, raw)


def relaxed_exact_arith() -> Any:
    """The exact arithmetic with relaxed block products (python-flint installed), else None."""
    if not _fmpz_poly():
        return None
    from ._arith.laurent import LaurentArith

    return LaurentArith()


def _package(f, x, v, eps, order, arithmetic, dps, A0, H, roots, stable, raw: _RawSeries) -> LimitCycleSeries:
    ar = raw.arith
    prec_digits = dps or mpmath.mp.dps

    def num(c: Any) -> sp.Expr:
        return to_sympy_number(ar.output(c), prec_digits)

    w = tuple(num(c) for c in raw.w[: order + 1])
    # period 2 pi / omega
    exact = ar.name == "exact"
    inv = [ar.scalar(1)]
    for k in range(1, order + 1):
        acc = 0 if not exact else Fraction(0)
        if isinstance(ar, FloatArith):
            acc = 0.0
        for i in range(1, k + 1):
            if raw.w[i]:  # (every odd coefficient vanishes for an odd nonlinearity)
                acc = acc - ar.smul(raw.w[i], inv[k - i])
        inv.append(acc)
    harmonics = []
    amp = []
    for xk in raw.x[: order + 1]:
        if exact:  # integer numerators; the Rationals are built when first read
            den, cos, sin = ar.exact_harmonics(xk)
            harmonics.append((den, tuple(cos), tuple(sin)))
            amp.append(sp.Rational(sum(cos), den))
            continue
        cs, ss = ar.values(xk)
        cs = [to_sympy_number(c, prec_digits) for c in cs]
        ss = [to_sympy_number(c, prec_digits) for c in ss]
        harmonics.append((cs, ss))
        amp.append(sp.Add(*cs))
    lam = (sp.Integer(0), *(num(c) for c in raw.lam))
    A0s = sp.sympify(A0)
    return LimitCycleSeries(
        f=f,
        x=x,
        v=v,
        eps_symbol=eps,
        order=order,
        arithmetic=arithmetic,
        dps=dps,
        generating_amplitude=A0s,
        amplitude_equation=H,
        generating_amplitudes=tuple(roots),
        frequency=EpsSeries(w, eps, order, name="omega"),
        period=EpsSeries(tuple(num(c) for c in inv), eps, order, 2 * sp.pi, name="period"),
        amplitude=EpsSeries(tuple(amp), eps, order, A0s, name="amplitude"),
        floquet_exponent=EpsSeries(lam, eps, order + 1, name="floquet_exponent"),
        stable=stable,
        _harmonics=_ExactHarmonics(tuple(harmonics)) if exact else tuple(harmonics),
    )


class _ExactHarmonics(Sequence):
    """Per order ``(cos list, sin list)`` of the scaled ``x_k`` as SymPy Rationals, built on first access.

    Stored as ``(denominator, cos numerators, sin numerators)`` per order (Python ints: picklable); indexing and
    slicing return the same values as a tuple of ``(list, list)`` of Rationals.
    """

    def __init__(self, raw: tuple):
        self._raw = raw
        self._built: dict[int, tuple[list, list]] = {}

    def __len__(self) -> int:
        return len(self._raw)

    def __getitem__(self, k: Any) -> Any:
        if isinstance(k, slice):
            return tuple(self[i] for i in range(*k.indices(len(self._raw))))
        k = range(len(self._raw))[k]
        if k not in self._built:
            den, cos, sin = self._raw[k]
            self._built[k] = ([sp.Rational(c, den) for c in cos], [sp.Rational(c, den) for c in sin])
        return self._built[k]

    def __repr__(self) -> str:
        return repr(tuple(self))

    def __getstate__(self) -> tuple:
        return self._raw

    def __setstate__(self, raw: tuple) -> None:
        self.__init__(raw)
