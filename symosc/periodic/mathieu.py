"""Mathieu characteristic values a_n(q) and b_n(q).

Convention (McLachlan 1947; DLMF ch. 28; the same as ``scipy.special.mathieu_a``): the Mathieu equation is

    y'' + (a - 2q cos 2x) y = 0,

a_n(q) is the value of ``a`` with an even periodic solution ce_n (period pi for even n, 2pi for odd n) and b_n(q),
n >= 1, the value with an odd periodic solution se_n.  For q > 0 they are ordered

    a_0 < b_1 < a_1 < b_2 < a_2 < ...

and for q < 0 the DLMF 28.2(vii) relations hold: a_{2m}(-q) = a_{2m}(q), a_{2m+1}(-q) = b_{2m+1}(q),
b_{2m+1}(-q) = a_{2m+1}(q), b_{2m}(-q) = b_{2m}(q).

Methods (see :mod:`symosc.periodic._hill` and :mod:`symosc.periodic.mathieu_series` for the algorithms):

``"auto"`` (default)
    vectorised over q: an own initial approximation (piecewise Chebyshev series in sqrt(q) generated on first use
    from certified values, the asymptotic expansion DLMF 28.8.1 beyond; no SciPy value is used), then verified and
    refined by Rayleigh-quotient steps on the twisted factorisation of the Hill matrix (the negative pivots count the
    index of the eigenvalue found, so a start on a wrong branch is detected and replaced by a start found by
    bisection on the same count).  This per-point kernel is C, compiled once and cached on disk (the C backend's
    build cache; scalar calls through a small CPython extension around it); without a C compiler (or with the
    environment variable ``SYMOSC_MATHIEU_KERNEL=numpy``) the same checks run in NumPy and failing points go to the
    LAPACK/mpmath solvers -- :func:`mathieu_kernel` says which kernel runs.  A point whose index, truncation or
    rounding estimate still fails is recomputed by the float64 tridiagonal eigenpair (LAPACK) refined by the
    Rayleigh quotient in extended precision, and falls back to ``"mp"`` when the estimate misses the target.  Scalar
    and vectorised calls give the same bits (with either kernel).
    Measured: relative error <= 1e-13 (absolute where |value| < 1) against 50-digit values for n <= 100,
    ``|q| <= 1e4`` (``benchmarks/mathieu_vs_scipy.py``).
``"hill"``
    plain float64 eigenvalue at two matrix sizes that must agree; absolute error ``~ eps * 2|q|`` (so values near zero
    at large q lose digits -- that is why ``"auto"`` refines).
``"mp"``
    Newton iteration on the Hill continued fraction in mpmath at ``dps`` digits (default 30), two sizes that must
    agree; returns ``mpmath.mpf`` values.
``"series"``
    the exact power series of :mod:`~symosc.periodic.mathieu_series` with its order chosen for ``tol``; raises
    ``ConvergenceError`` when ``|q|`` is too close to (or beyond) the radius of convergence.

Near-degenerate neighbours (a_n, b_{n+1} at large q, b_n, a_n at small q for large n) differ by less than the
rounding error; where the gap is below 1e-12 (n^2 + 2q + 1) (regions measured once per pair, see
:mod:`symosc.periodic._mathieu_seed`) both neighbours are computed and the returned values are clamped so that the
ordering holds exactly (non-strictly) in floating point (methods "auto", "hill", "mp"; "series" values are returned
as summed).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import mpmath
import numpy as np

from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ConvergenceError, ParameterError
from . import _hill, _hill_c, _mathieu_auto, _mathieu_seed
from .mathieu_series import _check_n, mathieu_series_value

__all__ = ["MathieuValues", "mathieu_a", "mathieu_b", "mathieu_characteristic", "mathieu_kernel"]

_METHODS = ("auto", "hill", "mp", "series")
_DEFAULT_TOL = 1e-13
_FAST = _hill_c.FAST
_DEFAULT_DPS = 30


@dataclass(frozen=True)
class MathieuValues(SymPyPrintable):
    """Characteristic values with what the method achieved.

    Attributes
    ----------
    kind : str
        ``"a"`` or ``"b"``.
    n : int or numpy.ndarray
        Index (an array when an array of indices was given).
    q : float or numpy.ndarray
        The points (as given, converted to float).
    values : float, mpmath.mpf or numpy.ndarray
        a_n(q) or b_n(q); an object array of ``mpf`` for ``method="mp"`` with array input.
    error_estimate : float or numpy.ndarray
        Estimated absolute error of each value.
    method : str
        Method that was used.
    """

    kind: str
    n: int
    q: Any
    values: Any
    error_estimate: Any
    method: str

    def __repr__(self) -> str:
        shape = np.shape(self.q)
        where = f"q={float(self.q)!r}" if shape == () else f"q: array{shape}"
        worst = float(np.max(self.error_estimate)) if np.size(self.error_estimate) else 0.0
        which = (
            f"{self.kind}_{self.n}" if np.ndim(self.n) == 0 else f"{self.kind}_n for n in {np.unique(self.n).tolist()}"
        )
        return f"MathieuValues({which}, {where}, method={self.method!r}, max error_estimate={worst:.2g})"

    def _repr_latex_(self) -> str:
        if np.shape(self.q) == () and np.ndim(self.n) == 0:
            return f"${self.kind}_{{{self.n}}}({float(self.q):g}) = {float(self.values):.15g}$"
        n = self.n if np.ndim(self.n) == 0 else "n"
        return f"${self.kind}_{{{n}}}(q)$ at {np.size(self.q)} points"


def _check_q(q) -> tuple[np.ndarray, np.ndarray, bool]:
    """Return (float array, object array of the original entries, is_scalar)."""
    if isinstance(q, np.ndarray) and q.dtype.kind in "fiu":
        as_float = q.astype(float)
        if not np.isfinite(as_float).all():
            bad = ~np.isfinite(as_float)
            raise ParameterError(
                f"q must be finite; got {as_float[bad][:5].tolist()} at {np.count_nonzero(bad)} position(s)",
            )
        return as_float, as_float, q.ndim == 0
    try:
        raw = np.asarray(q, dtype=object)
        flat = raw.reshape(-1)
        as_float = np.empty(flat.shape, dtype=float)
        for i, v in enumerate(flat):
            if isinstance(v, complex | np.complexfloating | mpmath.mpc):
                raise TypeError
            as_float[i] = float(v)
    except (TypeError, ValueError):
        raise ParameterError(f"q must be a real number or an array of real numbers, got {q!r}") from None
    bad = ~np.isfinite(as_float)
    if bad.any():
        raise ParameterError(
            f"q must be finite; got {as_float[bad][:5].tolist()} at {np.count_nonzero(bad)} position(s)",
        )
    return as_float.reshape(raw.shape), raw, raw.ndim == 0


class _Solver:
    """Compute raw values kind_n(q) for q >= 0 with one method, memoised within one call."""

    def __init__(self, method: str, dps: int | None, tol: float | None):
        self.method, self.dps, self.tol = method, dps, tol
        self.memo: dict[tuple[str, int], tuple[Any, float]] = {}

    def raw(self, kind: str, n: int, qf: float, qm) -> tuple[Any, float]:
        key = (kind, n)
        if key not in self.memo:
            self.memo[key] = self._compute(kind, n, qf, qm)
        return self.memo[key]

    def _compute(self, kind: str, n: int, qf: float, qm) -> tuple[Any, float]:
        fam, k = _hill.family_index(kind, n)
        if self.method == "hill":
            s = _hill.solve_hill(fam, k, qf, self.tol)
            return s.value, s.error_estimate
        if self.method == "mp":
            s = _hill.solve_mp(fam, k, qm, self.dps)
            return s.value, s.error_estimate
        if self.method == "series":
            r = mathieu_series_value(kind, n, qm if self.dps else qf, tol=self.tol or _DEFAULT_TOL, dps=self.dps)
            return r.value, r.error_estimate
        return _hill.refined_value(fam, k, qf, self.tol or _DEFAULT_TOL)


def _value_at(kind: str, n: int, q: float, qm, solver: _Solver) -> tuple[Any, float]:
    """kind_n(q) for one q >= 0: solve, then enforce the ordering against the nearly degenerate neighbours.

    Inside the clamp regions of :func:`symosc.periodic._mathieu_seed.neighbours` (relative gap below 1e-12, where
    two values computed independently could come out of order) the neighbour is computed too and the value clamped
    into [lower neighbour, upper neighbour].  The clamped values of both members of a pair come from the same two raw
    numbers, so the ordering holds whichever of the two functions is called.
    """
    value, err = solver.raw(kind, n, q, qm)
    if solver.method == "series":
        return value, err
    lower, upper = _mathieu_seed.neighbours(kind, n)
    point = np.array([q])
    if lower is not None and lower.covers(point)[0]:
        value = max(value, solver.raw(lower.kind, lower.n, q, qm)[0])
    if upper is not None and upper.covers(point)[0]:
        value = min(value, solver.raw(upper.kind, upper.n, q, qm)[0])
    return value, err


@validated
def mathieu_characteristic(
    kind: str, n, q, *, method: str = "auto", dps: int | None = None, tol: float | None = None
) -> MathieuValues:
    """Characteristic value a_n(q) or b_n(q) with its error estimate.

    Parameters
    ----------
    kind : {"a", "b"}
        ``"a"`` for a_n (even solutions ce_n), ``"b"`` for b_n (odd solutions se_n, n >= 1).
    n : int or array_like of int
        Index, n >= 0 (n >= 1 for b); an array of indices broadcasts against q (as in ``scipy.special``).
    q : float, mpmath.mpf, str or array_like
        Any finite real q (negative q by the DLMF 28.2(vii) symmetries); for ``method="mp"`` an ``mpf`` or a decimal
        string keeps every digit.
    method : {"auto", "hill", "mp", "series"}
        See the module docstring.
    dps : int, optional
        Decimal digits for ``"mp"`` (default 30) and for ``"series"`` (mpmath evaluation).  ``"auto"`` with ``dps``
        means ``"mp"``.
    tol : float, optional
        Target error (relative where ``|value| >= 1``, absolute below): for ``"auto"`` (default 1e-13; the result is
        checked against it), ``"hill"`` (accepted difference between the two matrix sizes, never below float64
        noise), ``"series"`` (default 1e-13).

    Returns
    -------
    MathieuValues

    Raises
    ------
    ParameterError
        Bad n, q, method, dps or tol.
    ConvergenceError
        The method could not reach its tolerance (``"series"`` beyond its radius, truncation not converging).

    Examples
    --------
    >>> r = mathieu_characteristic("a", 0, 1.0)
    >>> round(r.values, 12), r.error_estimate < 1e-13
    (-0.455138604107, True)
    """
    if kind not in ("a", "b"):
        raise ParameterError(f"kind must be 'a' or 'b', got {kind!r}")
    fast = _scalar_fast_path(kind, n, q, method, dps, tol)
    if fast is not None:
        return MathieuValues(kind, n, float(q), fast[0], fast[1], method)
    if method not in _METHODS:
        raise ParameterError(f"method must be one of {_METHODS}, got {method!r}")
    if dps is not None:
        if isinstance(dps, bool) or not hasattr(dps, "__index__") or int(dps) < 5:
            raise ParameterError(f"dps must be an integer >= 5, got {dps!r}")
        if method == "hill":
            raise ParameterError("dps applies to method='mp' or 'series' (float64 Hill has ~16 digits)")
        dps = int(dps)
        if method == "auto":
            method = "mp"
    if method == "mp" and dps is None:
        dps = _DEFAULT_DPS
    if tol is not None and not (isinstance(tol, int | float) and math.isfinite(tol) and tol > 0):
        raise ParameterError(f"tol must be a positive finite number, got {tol!r}")
    qf, qo, scalar = _check_q(q)
    n_arr = np.asarray(n, dtype=object)
    if n_arr.ndim == 0:
        n = _check_n(kind, n)
        values, errors = _evaluate(kind, n, qf.reshape(-1), qo.reshape(-1), method, dps, tol)
        if scalar:
            out_v = values[0] if values.dtype == object else float(values[0])
            return MathieuValues(kind, n, float(qf), out_v, float(errors[0]), method)
        return MathieuValues(kind, n, qf, values.reshape(qf.shape), errors.reshape(qf.shape), method)
    # array n: broadcast against q, as scipy.special.mathieu_a(m, q) does
    try:
        nb, qfb = np.broadcast_arrays(n_arr, qf)
    except ValueError:
        raise ParameterError(f"n (shape {n_arr.shape}) and q (shape {qf.shape}) cannot be broadcast together") from None
    qob = np.broadcast_to(qo, qfb.shape).reshape(-1)
    n_flat = np.array([_check_n(kind, v) for v in nb.reshape(-1)], dtype=int)
    values = np.empty(n_flat.shape, dtype=object if method == "mp" or dps is not None else float)
    errors = np.empty(n_flat.shape, dtype=float)
    for nv in np.unique(n_flat):
        idx = np.nonzero(n_flat == nv)[0]
        values[idx], errors[idx] = _evaluate(kind, int(nv), qfb.reshape(-1)[idx], qob[idx], method, dps, tol)
    shape = qfb.shape
    return MathieuValues(kind, n_flat.reshape(shape), qfb.copy(), values.reshape(shape), errors.reshape(shape), method)


def _scalar_fast_path(kind: str, n, q, method: str, dps, tol) -> tuple[float, float] | None:
    """(value, error) for a plain int n and float q with the default method, else None (the general path)."""
    if method != "auto" or dps is not None or type(n) is not int or type(q) not in (float, int):
        return None
    if n < (1 if kind == "b" else 0) or not math.isfinite(q):
        return None
    if tol is not None and not (type(tol) is float and math.isfinite(tol) and tol > 0):
        return None
    q = float(q)
    which = kind
    if q < 0 and n % 2 == 1:
        which = "b" if kind == "a" else "a"
    value, err = _mathieu_auto.auto_scalar(which, n, abs(q), tol)
    _check_tol(kind, n, value, err, tol)
    return value, err


def _evaluate(kind: str, n: int, flat_f: np.ndarray, flat_o: np.ndarray, method: str, dps, tol):
    """Values and error estimates of kind_n at the 1-d points flat_f (floats) / flat_o (original objects)."""
    use_mp = method == "mp" or (method == "series" and dps is not None)
    # DLMF 28.2(vii): work at |q|; odd n swap a <-> b for q < 0
    swap = (flat_f < 0) & (n % 2 == 1)
    other = "b" if kind == "a" else "a"
    qabs = np.abs(flat_f)
    if method == "auto":
        if not swap.any():
            values, errors = _mathieu_auto.auto_array(kind, n, qabs, tol)
            _check_tol(kind, n, values, errors, tol)
            return values, errors
        values = np.empty(flat_f.shape)
        errors = np.empty(flat_f.shape)
        for which, sel in ((kind, ~swap), (other, swap)):
            idx = np.nonzero(sel)[0]
            if idx.size:
                values[idx], errors[idx] = _mathieu_auto.auto_array(which, n, qabs[idx], tol)
        _check_tol(kind, n, values, errors, tol)
        return values, errors
    values = np.empty(flat_f.shape, dtype=object if use_mp else float)
    errors = np.empty(flat_f.shape, dtype=float)
    for i, (x, xo) in enumerate(zip(flat_f, flat_o, strict=True)):
        qm = None
        if use_mp:  # keep every digit of an mpf or string q (abs() inside workdps: it rounds to the context)
            with mpmath.workdps(dps + 10):
                qm = abs(mpmath.mpf(xo) if isinstance(xo, str | mpmath.mpf) else mpmath.mpf(float(x)))
        solver = _Solver(method, dps, tol)
        values[i], errors[i] = _value_at(other if swap[i] else kind, n, float(qabs[i]), qm, solver)
    return values, errors


def _check_tol(kind: str, n: int, values, errors, tol) -> None:
    if tol is not None and np.size(values):
        scale = np.maximum(1.0, np.abs(np.asarray(values, dtype=float)))
        if np.any(errors > tol * scale):
            worst = float(np.max(errors / scale))
            raise ConvergenceError(f"{kind}_{n}: error estimate {worst:.3g} above tol={tol:g}", achieved=worst)


@validated
def mathieu_kernel() -> str:
    """Which kernel method ``"auto"`` runs: ``"c"`` (compiled) or ``"numpy"`` (fallback).

    The C kernel is compiled on first use and cached on disk (``$SYMOSC_CACHE_DIR``, see the C backend of
    :mod:`symosc.numeric`); ``"numpy"`` is used when no C compiler is found or the environment variable
    ``SYMOSC_MATHIEU_KERNEL`` is ``numpy`` (read once per process).  Both give values within 1e-13 of 50-digit
    references, in the same order; the compiled one is several times faster.

    Returns
    -------
    str
        ``"c"`` or ``"numpy"``.

    See Also
    --------
    mathieu_characteristic : the values and their error estimates.

    Examples
    --------
    >>> mathieu_kernel() in ("c", "numpy")
    True
    """
    return _mathieu_auto.mathieu_kernel()


def mathieu_a(n, q, *, method: str = "auto", dps: int | None = None, tol: float | None = None):
    """Characteristic value a_n(q) of the Mathieu equation y'' + (a - 2q cos 2x) y = 0.

    Parameters
    ----------
    n : int or array_like of int
        Index, n >= 0; arrays broadcast against q.
    q : float or array_like
        Any finite real q; arrays give arrays of the same shape.
    method, dps, tol
        See :func:`mathieu_characteristic`.

    Returns
    -------
    float or numpy.ndarray (``mpmath.mpf`` / object array for ``method="mp"``)

    See Also
    --------
    mathieu_b
    mathieu_characteristic
    mathieu_series_value

    Examples
    --------
    >>> round(mathieu_a(0, 1.0), 12)
    -0.455138604107
    >>> mathieu_a(2, [0.0, 1.0, -1.0]).round(10)
    array([4.        , 4.37130098, 4.37130098])
    >>> round(mathieu_a(1, -1.0), 12) == round(mathieu_b(1, 1.0), 12)
    True
    """
    if type(q) is float and type(n) is int and method == "auto" and dps is None and tol is None and _FAST.value:
        value = _FAST.value(0, n, q)  # the compiled scalar path (nan: not known yet, or the general path is needed)
        if value == value:
            return value
    fast = _scalar_fast_path("a", n, q, method, dps, tol)
    if fast is not None:
        return fast[0]
    return mathieu_characteristic("a", n, q, method=method, dps=dps, tol=tol).values


def mathieu_b(n, q, *, method: str = "auto", dps: int | None = None, tol: float | None = None):
    """Characteristic value b_n(q), n >= 1, of the Mathieu equation y'' + (a - 2q cos 2x) y = 0.

    Parameters
    ----------
    n : int or array_like of int
        Index, n >= 1 (b_0 does not exist); arrays broadcast against q.
    q : float or array_like
        Any finite real q; arrays give arrays of the same shape.
    method, dps, tol
        See :func:`mathieu_characteristic`.

    Returns
    -------
    float or numpy.ndarray (``mpmath.mpf`` / object array for ``method="mp"``)

    See Also
    --------
    mathieu_a
    mathieu_characteristic
    mathieu_series_value

    Examples
    --------
    >>> round(mathieu_b(1, 1.0), 12)
    -0.110248816992
    >>> import mpmath
    >>> mpmath.nstr(mathieu_b(1, 0.5, method="mp", dps=25), 22)
    '0.4706543549338391115705'
    """
    if type(q) is float and type(n) is int and method == "auto" and dps is None and tol is None and _FAST.value:
        value = _FAST.value(1, n, q)
        if value == value:
            return value
    fast = _scalar_fast_path("b", n, q, method, dps, tol)
    if fast is not None:
        return fast[0]
    return mathieu_characteristic("b", n, q, method=method, dps=dps, tol=tol).values
