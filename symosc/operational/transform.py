"""The Carson transform ``X(p) = p * Integral(x(t) exp(-p t), (t, 0, oo))`` and its inversion (Bulgakov §2.2, §2.29).

Carson's image differs from Laplace's by the factor ``p``: the unit step has image 1, a constant is its own
image, and ``x'(t) <-> p (X(p) - x(0))``.  Originals are functions of ``t > 0``; results carry no ``Heaviside(t)``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from .. import numeric
from .._plotting import new_axes, plot_method
from .._printing import SymPyPrintable
from .._validate import check_finite_array, check_int, check_positive, validated
from ..errors import ConvergenceError, ModelError, ParameterError
from ..symbols import t as _t
from ._rational import check_expression, check_symbol, distinct_roots
from .heaviside import heaviside_expand
from .table import _Unsupported, carson_by_table

__all__ = ["NumericInversion", "carson", "inverse_carson", "invert_numeric", "to_transfer_function"]

_METHODS = ("auto", "table", "sympy")
_INV_METHODS = ("auto", "heaviside", "sympy")


@validated
def carson(x, t: sp.Symbol = _t, p: sp.Symbol | None = None, *, method: str = "auto"):
    """Carson image ``p * Laplace[x](p)`` of an original ``x(t)`` (scalar or Matrix).

    Parameters
    ----------
    x : Expr or Matrix
        The original, for ``t > 0``.
    t, p : Symbol
        Time and image variable (``p`` defaults to ``Symbol("p")``).
    method : {"auto", "table", "sympy"}
        ``"table"``: the rewrite rules of §2.18 for quasi-polynomials with delayed steps (fast, exact);
        ``"sympy"``: ``p * sympy.laplace_transform``; ``"auto"``: table first, SymPy for the rest.

    Raises
    ------
    ModelError
        If no closed form is found.

    See Also
    --------
    inverse_carson
    carson_by_table
    invert_numeric

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t")
    >>> carson(sp.exp(-2 * t), t, p)
    p/(p + 2)
    >>> carson(sp.Integer(1), t, p)
    1
    >>> carson(t**2 / 2, t, p)
    p**(-2)
    """
    check_symbol(t, "t")
    p = sp.Symbol("p") if p is None else check_symbol(p, "p")
    if method not in _METHODS:
        raise ParameterError(f"unknown method {method!r}; choose one of {_METHODS}")
    if isinstance(x, sp.MatrixBase):
        return x.applyfunc(lambda e: carson(e, t, p, method=method))
    x = check_expression(x, "x")
    if method in ("auto", "table"):
        try:
            return carson_by_table(x, t, p)
        except _Unsupported as exc:
            if method == "table":
                raise ModelError(f"the table rules do not cover {x} ({exc}); use method='sympy'") from exc
    lap = sp.laplace_transform(x, t, p, noconds=True)
    if lap.has(sp.LaplaceTransform):
        raise ModelError(f"no closed-form Carson image found for {x}")
    return sp.simplify(p * lap)


@validated
def inverse_carson(
    image, p: sp.Symbol, t: sp.Symbol = _t, *, method: str = "auto", real: bool = True, roots: str = "exact"
):
    """Original ``x(t)``, ``t > 0``, of a Carson image ``X(p)``.

    ``"auto"`` uses the Heaviside expansion (:func:`heaviside_expand`) for rational images, the delay theorem
    ``exp(-p tau) X(p) <-> x(t - tau) 1(t - tau)`` for sums of rational images times ``exp(-p tau)``, and
    ``sympy.inverse_laplace_transform(X/p)`` for anything else.  For images without a closed-form original use
    :func:`invert_numeric`.

    Parameters
    ----------
    image : Expr or Matrix
        Carson image ``X(p)``, an expression in ``p`` (a Matrix is inverted entry by entry).
    p : Symbol
        The image variable; it must be a SymPy Symbol.
    t : Symbol
        Time, the variable of the original (default ``symosc.t``); it must be a SymPy Symbol.
    method : {"auto", "heaviside", "sympy"}
        ``"heaviside"``: the expansion theorem and the delay theorem only (rational images times ``exp(-p tau)``);
        ``"sympy"``: ``sympy.inverse_laplace_transform(X/p)``; ``"auto"``: the first where it applies, else the
        second.
    real : bool
        Combine conjugate complex poles into ``exp(a t) (A cos(b t) + B sin(b t))`` (Bulgakov 2.89–2.91).
    roots : {"exact", "numeric"}
        Poles of rational images: ``"exact"`` (radicals or ``CRootOf``) or ``"numeric"`` (30-digit numbers, see
        :func:`heaviside_expand`).

    Returns
    -------
    Expr or Matrix
        The original for ``t > 0`` (delayed parts carry ``Heaviside(t - tau)``).

    Raises
    ------
    ModelError
        For an improper rational image (``deg numerator > deg denominator``: the original is not an ordinary
        function) and when no closed form is found.

    See Also
    --------
    carson
    heaviside_expand
    invert_numeric

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t")
    >>> inverse_carson(p / (p + 1) ** 2, p, t)
    t*exp(-t)
    >>> inverse_carson(sp.exp(-2 * p) / p, p, t)
    (t - 2)*Heaviside(t - 2)
    >>> inverse_carson(p**2 / (p + 1), p, t)
    Traceback (most recent call last):
    ...
    symosc.errors.ModelError: improper Carson image: deg numerator 2 > deg denominator 1 (delta functions)
    """
    check_symbol(p, "p")
    check_symbol(t, "t")
    if method not in _INV_METHODS:
        raise ParameterError(f"unknown method {method!r}; choose one of {_INV_METHODS}")
    if isinstance(image, sp.MatrixBase):
        return image.applyfunc(lambda e: inverse_carson(e, p, t, method=method, real=real, roots=roots))
    image = check_expression(image, "image")
    if method in ("auto", "heaviside"):
        if image.is_rational_function(p):
            return heaviside_expand(image, p, t, real=real, roots=roots)
        delayed = _split_delays(image, p)
        if delayed is not None:
            out = sp.S.Zero
            for tau, part in delayed.items():
                x = heaviside_expand(part, p, t, real=real, roots=roots)
                out += x.subs(t, t - tau) * sp.Heaviside(t - tau) if tau != 0 else x
            return out
        if method == "heaviside":
            raise ModelError(f"{image} is not rational in {p} (nor rational times exp(-p*tau)); use method='sympy'")
    res = sp.inverse_laplace_transform(image / p, p, t)
    if res.has(sp.InverseLaplaceTransform):
        raise ModelError(f"no closed-form original found for {image}; use invert_numeric for numbers")
    return res.subs(sp.Heaviside(t), 1)


_MAX_DPS = 250


def _needed_dps(omega: float, t: float, method: str) -> int:
    """Working digits the Bromwich methods need for an oscillation rate ``omega`` up to time ``t``.

    Measured on ``cos(omega t)``: de Hoog is exact to 1e-15 while ``dps >= 0.5 omega t + 15``, Talbot needs about
    ``omega t + 15``, Stehfest cannot follow oscillations at all past a few periods.
    """
    factor = {"dehoog": 0.6, "talbot": 1.1, "stehfest": 3.0}[method]
    return int(np.ceil(factor * omega * t)) + 15


def _oscillation_rate(expr: sp.Expr, p: sp.Symbol) -> float:
    """Largest |Im s| over the singularities s of the image that are not strongly damped (Re s > -1).

    Singularities are the zeros of polynomial denominators and of the polynomial bases of non-integer powers (e.g.
    ``sqrt(p**2 + 1)``: branch points at ±i).  Unknown kinds contribute nothing.
    """
    candidates = set()
    _num, den = sp.fraction(sp.together(expr))
    candidates.add(den)
    for node in sp.preorder_traversal(expr):
        if isinstance(node, sp.Pow) and not (node.exp.is_Integer and node.exp > 0):
            candidates.add(node.base)
        elif isinstance(node, sp.Function) and node.args:
            candidates.add(node.args[0])
    rate = 0.0
    for c in candidates:
        for factor in sp.Mul.make_args(sp.factor_terms(c)):
            base = factor.base if isinstance(factor, sp.Pow) else factor
            if not base.has(p) or not base.is_polynomial(p):
                continue
            try:
                poly = sp.Poly(base, p)
            except sp.PolynomialError:
                continue
            if poly.degree() < 1 or poly.free_symbols - {p}:
                continue
            # on squarefree factors: mpmath's polyroots (behind nroots) need not converge on a multiple root, and
            # the rate of a resonant image such as 1/(p² + 4)³ (expanded) was lost
            roots = [complex(r) for r, _ in distinct_roots(poly, numeric=True)]
            for r in roots:
                if r.real > -1.0:
                    rate = max(rate, abs(r.imag))
    return rate


def _invert_rational(expr: sp.Expr, p: sp.Symbol, ts: np.ndarray, dps: int) -> NumericInversion:
    """Values of a rational image's original by partial fractions with 30-digit poles (no Bromwich integral)."""

    tt = sp.Dummy("t", positive=True)
    orig = heaviside_expand(expr, p, tt, roots="numeric", real=False)
    terms = sp.Add.make_args(sp.expand(orig))
    vals, errs = [], []
    for tv in ts:
        parts = [complex(sp.N(term.subs(tt, sp.Float(float(tv), 40)), 30)) for term in terms]
        total = sum(parts)
        vals.append(total)
        # 30-digit poles: relative error ~1e-25 of the largest term (cancellation between terms included)
        errs.append(1e-25 * max(1.0, max(abs(v) for v in parts)) * (1 + float(tv)))
    arr = np.array(vals)
    if np.all(np.abs(arr.imag) <= 1e-14 * (1 + np.abs(arr.real))):
        arr = arr.real
    return NumericInversion(t=ts, values=arr, error_estimate=np.array(errs), method="residues", converged=True)


def _split_delays(image, p) -> dict | None:
    """``{tau: rational part}`` if image = sum_k R_k(p) exp(-p tau_k) with tau_k >= 0, else None."""
    parts: dict = {}
    for term in sp.Add.make_args(sp.expand(image, power_exp=True)):
        tau = sp.S.Zero
        rest = sp.S.One
        for f in sp.Mul.make_args(term):
            if isinstance(f, sp.exp) or (f.is_Pow and f.base == sp.E):
                arg = f.exp if f.is_Pow else f.args[0]
                c = sp.expand(arg).coeff(p)
                if sp.expand(arg - c * p).has(p) or c.has(p):
                    return None
                tau -= c
                rest *= sp.exp(sp.expand(arg - c * p))
            else:
                rest *= f
        if tau.is_negative or not rest.is_rational_function(p):
            return None
        parts[tau] = parts.get(tau, 0) + rest
    return {k: sp.cancel(v) for k, v in parts.items()}


@dataclass(frozen=True)
class NumericInversion(SymPyPrintable):
    """Values of an original found by numeric inversion of its image (:func:`invert_numeric`).

    Attributes
    ----------
    t : ndarray
        The times.
    values : ndarray
        ``x(t)`` (real part; complex images give complex values).
    error_estimate : ndarray
        ``|x_method - x_check|``: the difference to a second, independent method (de Hoog, Talbot or Stehfest;
        the third is consulted only when the second disagrees); at long times for oscillating originals
        (``t max|Im s| > 10`` over the singularities s) the difference to the same method with 20 more digits
        instead, since the methods share a blind spot there.
    method : str
        The Bromwich method that produced ``values`` (``"dehoog"``, ``"talbot"``, ``"stehfest"``), or
        ``"residues"`` for a rational image inverted exactly by partial fractions.
    converged : bool
        True when every value met the tolerance (otherwise :func:`invert_numeric` raises).
    """

    t: np.ndarray
    values: np.ndarray
    error_estimate: np.ndarray
    method: str
    converged: bool

    def __repr__(self) -> str:
        return (
            f"NumericInversion(method={self.method!r}, n={len(self.t)}, "
            f"max_error_estimate={float(np.max(self.error_estimate)):.2e}, converged={self.converged})"
        )

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Plot ``x(t)``.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
            The axes drawn on.
        """

        ax = new_axes(ax)
        ax.plot(self.t, self.values)
        ax.set_xlabel("t")
        ax.set_ylabel("x(t)")
        return ax


@validated
def invert_numeric(
    image,
    p: sp.Symbol,
    times,
    *,
    values: dict | None = None,
    method: str = "dehoog",
    dps: int = 30,
    tol: float = 1e-10,
) -> NumericInversion:
    """Numeric original of a Carson image by Bromwich inversion (mpmath ``invertlaplace`` on ``X(p)/p``).

    Each value is computed by ``method`` and checked by a second method (and a third if the second disagrees:
    Talbot's contour fails for singularities on the imaginary axis); the difference is the error estimate.

    Parameters
    ----------
    image : Expr
        Carson image; any analytic expression in ``p`` (exponentials, square roots, ...).
    p : Symbol
        The image variable; it must be a SymPy Symbol.
    times : float or array_like
        Times ``t > 0``.
    values : dict, optional
        Numbers for the other free symbols (keyed by Symbol or name).
    method : {"talbot", "dehoog", "stehfest"}
        The Bromwich method of mpmath's ``invertlaplace`` whose values are returned (the others check them).
    dps : int
        Working precision of mpmath.  It is raised automatically where the image has singularities near the
        imaginary axis and ``t`` is long (the methods otherwise return ~0 for an undamped original, and agree on
        it, e.g. ``cos(100)``).  A rational image that would need more digits is inverted exactly by partial
        fractions (``method == "residues"`` in the result); another image that would need more than 250 digits
        is refused with the reason.
    tol : float
        Largest accepted ``|difference| / (1 + |x|)``.

    Raises
    ------
    ConvergenceError
        If the two methods disagree by more than ``tol``.

    See Also
    --------
    inverse_carson
    carson

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> r = invert_numeric(p / sp.sqrt(p**2 + 1), p, [1.0, 2.0])   # J0(t)
    >>> [round(float(v), 10) for v in r.values]
    [0.7651976866, 0.2238907791]
    """
    check_symbol(p, "p")
    expr = check_expression(image, "image")
    if values:
        expr = numeric.bind(expr, values)
    extra = sorted(expr.free_symbols - {p}, key=lambda s: s.name)
    if extra:
        raise ParameterError("missing values for: " + ", ".join(s.name for s in extra))
    if method not in ("talbot", "dehoog", "stehfest"):
        raise ParameterError(f"unknown method {method!r}; choose talbot, dehoog or stehfest")
    checks = [m for m in ("dehoog", "talbot", "stehfest") if m != method]
    func = numeric.compile(expr / p, [p], backend="mpmath", dps=dps, check=False).raw
    ts = np.atleast_1d(check_finite_array("times", times))
    if np.any(ts <= 0):
        raise ParameterError("invert_numeric needs times t > 0")
    dps = check_int("dps", dps, minimum=5)
    tol = check_positive("tol", tol)
    omega = _oscillation_rate(expr, p)
    need = [_needed_dps(omega, tv, method) for tv in ts]
    if max(need) > dps:
        if expr.is_rational_function(p):
            return _invert_rational(expr, p, ts, dps)
        if max(need) > _MAX_DPS:
            i = int(np.argmax(need))
            raise ConvergenceError(
                f"the image has singularities near the imaginary axis (|Im p| up to {omega:.4g}); at t={ts[i]:.4g} the "
                f"Bromwich methods would need about {need[i]} digits (they return ~0 with a false agreement at long "
                f"times for undamped originals); use shorter times or a closed form (inverse_carson)"
            )
    vals, errs = [], []
    for tv, nd in zip(ts, need, strict=True):
        work = max(dps, nd)
        with mpmath.workdps(work):
            a = mpmath.invertlaplace(func, tv, method=method)
            err = mpmath.inf
            if omega * tv > 10:
                # oscillating original at long times: the methods share a blind spot (they agree on ~0), so the
                # second opinion is the same method with 20 more digits (more terms, a different approximation)
                with mpmath.workdps(work + 20):
                    err = abs(a - mpmath.invertlaplace(func, tv, method=method))
            else:
                for check in checks:  # a second opinion; the third only if the second disagrees
                    err = min(err, abs(a - mpmath.invertlaplace(func, tv, method=check)))
                    if err <= tol * (1 + abs(a)):
                        break
            vals.append(complex(a))
            errs.append(float(err))
    arr = np.array(vals)
    if np.all(np.abs(arr.imag) <= 1e-14 * (1 + np.abs(arr.real))):
        arr = arr.real
    err = np.array(errs)
    bad = err > tol * (1 + np.abs(arr))
    if np.any(bad):
        i = int(np.argmax(err))
        raise ConvergenceError(
            f"numeric inversion did not reach tol={tol} at t={ts[i]} ({method} and {'/'.join(checks)} differ by "
            f"{err[i]:.2e}); raise dps or check that the image is analytic for Re p > 0",
            achieved=float(err[i]),
        )
    return NumericInversion(t=ts, values=arr, error_estimate=err, method=method, converged=True)


@validated
def to_transfer_function(image: Any, p: sp.Symbol, values: dict | None = None, *, backend: str = "auto") -> Any:
    """A rational transfer function W(p), such as a ratio Y(p)/U(p) of Carson images, as a control object.

    Returns ``control.TransferFunction`` when python-control is installed, else ``scipy.signal.TransferFunction``;
    ``values`` gives numbers for the other symbols.  Delays (``exp(-p tau)``) do not convert.

    Parameters
    ----------
    image : Expr
        The transfer function, which must be rational in ``p`` with real coefficients once ``values`` are
        substituted.
    p : Symbol
        The image (Laplace) variable.
    values : mapping of Symbol or name to number, optional
        Numbers for the other symbols of ``image`` (keys are symbols or their names).
    backend : {"auto", "control", "scipy"}
        ``"control"``: a ``control.TransferFunction`` (python-control required); ``"scipy"``: a
        ``scipy.signal.TransferFunction``; ``"auto"``: python-control when installed, else SciPy.

    Returns
    -------
    control.TransferFunction or scipy.signal.TransferFunction
        Coefficients normalised to a monic denominator.

    Raises
    ------
    ModelError
        If ``image`` is not rational in ``p`` (a delay) or has complex coefficients.

    See Also
    --------
    symosc.mechanics.LinearModel.to_transfer_function

    Examples
    --------
    >>> import sympy as sp
    >>> p, k, T = sp.symbols("p k T", positive=True)
    >>> H = to_transfer_function(k / (T * p + 1), p, {"k": 2, "T": 0.5}, backend="scipy")
    >>> H.num.tolist(), H.den.tolist()
    ([4.0], [1.0, 2.0])
    """
    from .._control import transfer_function_from_expr

    return transfer_function_from_expr(image, p, values, backend=backend)
