"""The matrizant (Peano–Baker series) of ``X' = A(t) X``, ``X(t0) = E`` (Bulgakov §1.38).

``Ω = E + ΓA + ΓAΓA + ...`` with ``ΓA = ∫_(t0)^t A(s) · ds`` and the later argument on the left (1.319).  If
``|a_jk| <= U`` on the interval, the k-th term is bounded elementwise by ``U^k n^(k-1) |t - t0|^k / k!``, which gives
the a-priori truncation bound of :meth:`Matrizant.bound`.  :func:`matrizant_numeric` integrates the matrix ODE
with SciPy instead (the fallback for long intervals, large ``U`` or non-integrable entries).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_positive, validated
from ...errors import AccuracyWarning, ConvergenceError, ModelError, ParameterError, warn
from ...numeric import bind
from ...numeric import compile as _compile
from .._util import as_square_matrix

__all__ = ["Matrizant", "matrizant", "matrizant_numeric"]


def _integrate(expr: sp.Expr, s: sp.Symbol, t0: sp.Expr, t: sp.Symbol) -> sp.Expr:
    expr = sp.expand(expr)
    if expr == 0:
        return sp.Integer(0)
    if expr.is_polynomial(s):
        P = sp.Poly(expr, s).integrate()
        return sp.expand(P.as_expr().subs(s, t) - P.as_expr().subs(s, t0))
    from sympy.integrals.manualintegrate import manualintegrate

    anti = manualintegrate(expr, s)  # rule-based: fast, and it says when it fails (unlike a Risch attempt)
    res = None if anti.has(sp.Integral) else anti.subs(s, t) - anti.subs(s, t0)
    if res is None or res.has(sp.Integral):
        raise ModelError(
            f"cannot integrate {expr} in closed form; use matrizant_numeric() (or Matrizant.evaluate with fallback)"
        )
    return sp.expand(res)


def _tail_bound(x: float, order: int, n: int) -> float:
    """``(1/n) Σ_(k>order) x^k/k!`` summed directly (no cancellation)."""
    x = mpmath.mpf(x)
    term = mpmath.mpf(1)
    for k in range(1, order + 1):
        term *= x / k
    total = mpmath.mpf(0)
    k = order
    while True:
        k += 1
        term *= x / k
        total += term
        if term <= total * mpmath.mpf(2) ** -60 or k > order + 100000:
            break
    return float(total / n)


@dataclass(frozen=True)
class Matrizant(SymPyPrintable):
    """Truncated Peano–Baker series ``Ω(t) = E + T_1(t) + … + T_order(t)`` of ``X' = A(t) X``.

    Attributes
    ----------
    A : Matrix
        The square coefficient matrix ``A(t)``.
    t : Symbol
        The independent variable.
    t0 : Expr
        Initial point, where ``Ω(t0) = E``.
    order : int
        Number of iterated integrals kept (>= 0).
    series : Matrix
        The truncated sum, a symbolic matrix in ``t``.
    terms : tuple of Matrix
        ``T_0 = E, T_1, ..., T_order``.
    """

    A: sp.Matrix = field(repr=False)
    t: sp.Symbol
    t0: sp.Expr
    order: int
    series: sp.Matrix = field(repr=False)
    terms: tuple[sp.Matrix, ...] = field(repr=False)

    def sup_norm(self, t1: float, values: Mapping | None = None, samples: int = 2049) -> float:
        """``U ≈ max |a_jk(s)|`` on ``[t0, t1]``, estimated on a grid of ``samples`` points (plus 5 % margin).

        Parameters
        ----------
        t1 : float
            End of the interval ``[t0, t1]``; a finite real number.
        values : mapping of Symbol or name to number, optional
            Values of the parameters in ``A`` other than ``t`` (keys are symbols or their names).
        samples : int
            Number of grid points (>= 2) on which ``|a_jk|`` is sampled.

        Returns
        -------
        float
            The estimate of ``U``, 5 % above the largest sampled ``|a_jk|``.
        """
        A = bind(self.A, values or {})
        f = _compile(A, [self.t])
        grid = np.linspace(float(self.t0), float(t1), samples)
        vals = np.abs(np.asarray(f(grid)))
        return 1.05 * float(np.max(vals))

    def bound(self, t1: float, U: float | None = None, values: Mapping | None = None) -> float:
        """A-priori bound on every entry of the truncation error at ``t1`` (Bulgakov 1.319).

        ``Σ_(k>order) U^k n^(k-1) |t1 - t0|^k / k!``; ``U`` bounds ``|a_jk|`` on the interval (estimated on a grid
        when not given).

        Parameters
        ----------
        t1 : float
            End of the interval ``[t0, t1]``; a finite real number.
        U : float, optional
            Bound (>= 0) on every ``|a_jk(s)|`` for s in ``[t0, t1]``; estimated by :meth:`sup_norm` when omitted.
        values : mapping of Symbol or name to number, optional
            Values of the parameters in ``A`` other than ``t`` (keys are symbols or their names).

        Returns
        -------
        float
            The bound on every entry of ``Ω(t1) - series(t1)``.
        """
        n = self.A.rows
        if U is None:
            U = self.sup_norm(t1, values)
        return _tail_bound(n * U * abs(float(t1) - float(self.t0)), self.order, n)

    def evaluate(
        self, t1: float, values: Mapping | None = None, *, tol: float | None = None, fallback: bool = True
    ) -> np.ndarray:
        """``Ω(t1)`` from the series; if ``tol`` is given and the a-priori bound exceeds it, integrate numerically
        (``fallback=True``) or raise ConvergenceError.  Without ``tol`` the last term of the series at ``t1`` is
        checked instead (the a-priori bound is crude): a last term above ``1e-8`` of the value warns
        (:class:`~symosc.errors.AccuracyWarning`), one above the value itself raises ConvergenceError.

        Parameters
        ----------
        t1 : float
            Time at which ``Ω`` is evaluated; a finite real number.
        values : mapping of Symbol or name to number, optional
            Values of the parameters in ``A`` other than ``t`` (keys are symbols or their names);
            every parameter needs a value.
        tol : float, optional
            Largest acceptable a-priori bound (> 0) on the truncation error (:meth:`bound`); not checked when omitted.
        fallback : bool
            When the bound exceeds ``tol``: True integrates numerically (:func:`matrizant_numeric`), False raises
            ConvergenceError.

        Returns
        -------
        ndarray
            The n x n matrix ``Ω(t1)``.

        Examples
        --------
        >>> import sympy as sp
        >>> t = sp.Symbol("t")
        >>> M = matrizant(sp.Matrix([[0, 1], [-1, 0]]), t, 0, order=25)
        >>> M.evaluate(1.0, tol=1e-12).round(12).tolist()
        [[0.540302305868, 0.841470984808], [-0.841470984808, 0.540302305868]]
        """
        if tol is not None:
            b = self.bound(t1, values=values)
            if b > tol:
                if fallback:
                    return matrizant_numeric(self.A, self.t, self.t0, t1, values=values, rtol=min(1e-10, tol))
                raise ConvergenceError(
                    f"order {self.order} Peano–Baker series: a-priori bound {b:.3g} > tol {tol:.3g} at t={t1}; "
                    "raise order, shorten the interval, or use matrizant_numeric()",
                    achieved=b,
                )
        S = bind(self.series, values or {})
        free = S.free_symbols - {self.t}
        if free:
            raise ParameterError("missing values for: " + ", ".join(sorted(map(str, free))))
        out = np.asarray(_compile(S, [self.t])(float(t1)), dtype=float)
        if tol is None:  # no tolerance asked: still say when the truncation makes the value inaccurate or meaningless
            last = bind(self.terms[-1], values or {}) if self.order else sp.zeros(*self.A.shape)
            tail = float(np.max(np.abs(np.asarray(_compile(last, [self.t])(float(t1)), dtype=float))))
            scale = max(1.0, float(np.max(np.abs(out))))
            if not tail <= scale:
                raise ConvergenceError(
                    f"order {self.order} Peano–Baker series at t={t1}: its last term alone is {tail:.3g}, more than "
                    "the value itself; raise order, shorten the interval, or use matrizant_numeric()",
                    achieved=tail,
                )
            if tail > 1e-8 * scale:
                warn(
                    f"order {self.order} Peano–Baker series at t={t1}: the last term is {tail:.3g}, so the value is "
                    "accurate to about that (pass tol= for the a-priori bound and a numerical fallback)",
                    AccuracyWarning,
                )
        return out

    def __repr__(self) -> str:
        return f"Matrizant(n={self.A.rows}, t0={self.t0}, order={self.order})"

    def _repr_latex_(self) -> str:
        return rf"$\Omega_{{{self.order}}}({sp.latex(self.t)}) = {sp.latex(self.series)}$"


@validated
def matrizant(A: Any, t: sp.Symbol, t0: Any = 0, order: int = 10) -> Matrizant:
    """Peano–Baker series of ``X' = A(t) X``, ``X(t0) = E``, to ``order`` iterated integrals (Bulgakov 1.319).

    Parameters
    ----------
    A : Matrix
        Square matrix whose entries are functions of ``t`` (other symbols are kept as parameters).
    t : Symbol
        The independent variable.
    t0 : number or Expr
        Initial point.
    order : int
        Number of iterated integrals kept.

    Returns
    -------
    Matrizant
        With the symbolic ``series``, the a-priori ``bound(t1)`` and ``evaluate(t1, tol=...)``.

    See Also
    --------
    matrizant_numeric
    matrix_function

    Examples
    --------
    Constant A gives the truncated exponential series:

    >>> import sympy as sp
    >>> t = sp.Symbol("t")
    >>> matrizant(sp.Matrix([[0, 1], [0, 0]]), t, 0, order=3).series
    Matrix([
    [1, t],
    [0, 1]])
    """
    A = as_square_matrix(A)
    if not isinstance(t, sp.Symbol):
        raise ParameterError(f"t must be a SymPy Symbol, got {t!r}")
    if int(order) != order or order < 0:
        raise ParameterError(f"order must be a non-negative integer, got {order!r}")
    t0 = sp.sympify(t0)
    s = sp.Dummy("s")
    As = A.xreplace({t: s})
    n = A.rows
    terms = [sp.eye(n)]
    for _ in range(int(order)):
        prod = As * terms[-1].xreplace({t: s})
        terms.append(prod.applyfunc(lambda e: _integrate(e, s, t0, t)))
    series = sum(terms[1:], terms[0]).applyfunc(sp.expand)
    return Matrizant(A=A, t=t, t0=t0, order=int(order), series=series, terms=tuple(terms))


@validated
def matrizant_numeric(
    A: Any,
    t: sp.Symbol,
    t0: float,
    t1: float,
    *,
    values: Mapping | None = None,
    rtol: float = 1e-10,
    atol: float = 1e-12,
) -> np.ndarray:
    """``Ω(t1)`` by integrating ``X' = A(t) X``, ``X(t0) = E`` with SciPy's DOP853 (the numeric fallback).

    ``A`` is compiled with :func:`symosc.numeric.compile`; ``values`` supplies other parameters.

    Parameters
    ----------
    A : Matrix
        Square matrix whose entries are functions of ``t`` (and of the parameters named in ``values``).
    t : Symbol
        The independent variable.
    t0 : float
        Initial time, where ``Ω(t0) = E``; a finite real number.
    t1 : float
        Final time at which ``Ω`` is returned; a finite real number (``t1 < t0`` integrates backwards).
    values : mapping of Symbol or name to number, optional
        Values of every parameter in ``A`` other than ``t`` (keys are symbols or their names).
    rtol : float
        Relative tolerance (> 0) of the integrator.
    atol : float
        Absolute tolerance (> 0) of the integrator.

    Returns
    -------
    ndarray
        The n x n matrix ``Ω(t1)``.

    See Also
    --------
    matrizant, matrizant_product

    Examples
    --------
    >>> import sympy as sp
    >>> t = sp.Symbol("t")
    >>> matrizant_numeric(sp.Matrix([[0, 1], [-1, 0]]), t, 0.0, 1.0).round(10).tolist()
    [[0.5403023059, 0.8414709848], [-0.8414709848, 0.5403023059]]
    """
    from scipy.integrate import solve_ivp

    t0, t1 = check_finite("t0", t0), check_finite("t1", t1)
    rtol, atol = check_positive("rtol", rtol), check_positive("atol", atol)
    A = as_square_matrix(A)
    Ab = bind(A, values or {})
    free = Ab.free_symbols - {t}
    if free:
        raise ParameterError("missing values for: " + ", ".join(sorted(map(str, free))))
    if Ab.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise ParameterError("A(t) has non-finite entries after substituting values (nan or inf parameter?)")
    n = A.rows
    f = _compile(Ab, [t]).raw

    def rhs(tt: float, y: np.ndarray) -> np.ndarray:
        At = np.asarray(f(tt), dtype=float)
        if not np.all(np.isfinite(At)):
            raise ParameterError(f"A(t) is not finite at t = {tt:.6g}; check the parameter values")
        return (At @ y.reshape(n, n)).ravel()

    if not np.all(np.isfinite(np.asarray(f(t0), dtype=float))):
        raise ParameterError(f"A(t) is not finite at t0 = {t0:.6g}; check the parameter values")

    sol = solve_ivp(rhs, (float(t0), float(t1)), np.eye(n).ravel(), method="DOP853", rtol=rtol, atol=atol)
    if not sol.success:
        raise ConvergenceError(f"numeric integration of the matrizant failed: {sol.message}")
    return sol.y[:, -1].reshape(n, n)
