"""Periodic Mathieu functions ce_n(x, q), se_n(x, q) and their x-derivatives (DLMF 28.2(vi), 28.4).

Convention (DLMF ch. 28; McLachlan 1947): the solutions of y'' + (a - 2q cos 2x) y = 0 at a = a_n(q) (even,
``ce_n``) and a = b_n(q) (odd, ``se_n``), x in radians, normalised by

    integral_0^{2 pi} ce_n(x, q)^2 dx = integral_0^{2 pi} se_n(x, q)^2 dx = pi        (DLMF 28.2.30)

with signs fixed by continuity in q from ``ce_0 = 1/sqrt(2)``, ``ce_n = cos nx``, ``se_n = sin nx`` at q = 0; for
q > 0 this makes the first Fourier coefficient (A_0, A_1, B_1 or B_2) positive.  Negative q by DLMF 28.2(vii):
ce_{2m}(x, -q) = (-1)^m ce_{2m}(pi/2 - x, q), ce_{2m+1}(x, -q) = (-1)^m se_{2m+1}(pi/2 - x, q),
se_{2m+1}(x, -q) = (-1)^m ce_{2m+1}(pi/2 - x, q), se_{2m+2}(x, -q) = (-1)^m se_{2m+2}(pi/2 - x, q).

Algorithm: the characteristic value from :func:`symosc.periodic.mathieu_characteristic` (certified index), the
Fourier coefficients (DLMF 28.4.1-28.4.4) as the eigenvector of the symmetric Hill matrix from the twisted
factorisation at that value, truncated where the tail (times the Fourier index, for derivatives) is below
``tol / 1000``, and the sum of the cosine or sine series.  The error bound adds the eigenvector perturbation
(value error and residual over the spacing of the eigenvalues), the rounding of the sums and the tail.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np
import sympy

from ..._plotting import new_axes, plot_method
from ..._printing import SymPyPrintable
from ..._validate import check_choice, check_finite_array, check_int, check_positive, validated
from ...errors import ConvergenceError, ParameterError
from . import _fourier

__all__ = [
    "MathieuCoefficients",
    "MathieuFunctionValues",
    "mathieu_ce",
    "mathieu_ce_prime",
    "mathieu_coefficient_series",
    "mathieu_fourier_coefficients",
    "mathieu_function",
    "mathieu_function_series",
    "mathieu_se",
    "mathieu_se_prime",
]

_DEFAULT_TOL = 1e-13
#: points per block of the sums (keeps the size x block arrays small)
_BLOCK = 4096


def _check_kind_n(kind: Any, n: Any) -> tuple[str, int]:
    kind = check_choice("kind", kind, ("ce", "se"))
    n = check_int("n", n, minimum=1 if kind == "se" else 0)
    return kind, n


def _check_tol(tol: Any) -> float:
    tol = check_positive("tol", tol)
    if tol < 1e-15:
        raise ParameterError(f"tol must be >= 1e-15 (float64 sums), got {tol!r}")
    return tol


# ----------------------------------------------------------------------------------------------- coefficients
def _coefficient_table(
    kind: str, n: int, q: np.ndarray, tol: float, derivative: bool = False, keep_tail: bool = False
) -> dict:
    """Coefficients for the distinct points q (1-d), in the sign convention of the requested function.

    Returns ``matrix`` (points x size, C order), ``coef`` (its transpose, size x points), ``rows``, ``index``
    (Fourier indices), ``lam``, ``lam_err``, ``err0``/``err1`` (error bounds for the function and its derivative,
    valid for every x), ``s0``/``s1`` (sum |A_k|, sum k |A_k|).
    """
    from ..mathieu import mathieu_characteristic

    ab = "a" if kind == "ce" else "b"
    npts = q.size
    parts = []
    for negative in (False, True):
        sel = np.nonzero((q < 0) == negative)[0]
        if not sel.size:
            continue
        eff, _m = _fourier.resolve(ab, n, negative)
        qa = np.abs(q[sel])
        res = mathieu_characteristic(eff, n, qa)
        lam = np.asarray(res.values, dtype=float).reshape(-1)
        co = _fourier.coefficients(eff, n, qa, lam, tol, derivative, keep_tail)
        if negative:
            co["coef"] = co["coef"] * _fourier.signs_negative_q(eff, n, co["coef"].shape[1])[None, :]
        co["lam"], co["lam_err"] = lam, np.asarray(res.error_estimate, dtype=float).reshape(-1)
        parts.append((sel, co))
    if len(parts) == 1 and parts[0][0].size == npts:  # one sign of q: no copies
        co = parts[0][1]
        matrix = np.ascontiguousarray(co["coef"])
        out = {key: co[key] for key in ("rows", "lam", "lam_err", "err0", "err1", "s0", "s1")}
    else:
        size = max((p[1]["coef"].shape[1] for p in parts), default=1)
        matrix = np.zeros((npts, size))
        out = {key: np.empty(npts) for key in ("lam", "lam_err", "err0", "err1", "s0", "s1")}
        out["rows"] = np.zeros(npts, dtype=np.intc)
        for sel, co in parts:
            matrix[sel, : co["coef"].shape[1]] = co["coef"]
            for key in out:
                out[key][sel] = co[key]
    # the Fourier indices of the |q| family equal those of the requested kind (odd n: both odd; even n: as kind)
    out["rows"] = np.ascontiguousarray(out["rows"], dtype=np.intc)
    out.update(matrix=matrix, coef=matrix.T, index=_fourier.fourier_indices(ab, n, matrix.shape[1]))
    return out


def _split(x: np.ndarray) -> np.ndarray:
    """x rounded to 26 significant bits (Dekker's split), so that k * x_hi is exact for integers k < 2**26."""
    c = x * 134217729.0  # 2^27 + 1
    return c - (c - x)


def _sum_numpy(kind: str, coef: np.ndarray, idx: np.ndarray, inv: np.ndarray, xf: np.ndarray, derivative: bool):
    """The Fourier sums in NumPy (fallback without a C compiler)."""
    out = np.empty(xf.shape)
    # k x split as k x_hi (exact: x_hi has 26 significant bits, k < 2^26) + k x_lo, so that the rounding of the
    # argument does not enter: trig(k x) = trig(A) + (k x_lo) trig'(A) + ...
    x_hi = _split(xf)
    x_lo = xf - x_hi
    for start in range(0, xf.size, _BLOCK):
        sl = slice(start, start + _BLOCK)
        c = coef[:, inv[sl]]
        big = np.multiply.outer(idx, x_hi[sl])
        small = np.multiply.outer(idx, x_lo[sl])
        cos_a, sin_a = np.cos(big), np.sin(big)
        s2 = 0.5 * small * small
        cos_k = cos_a * (1.0 - s2) - sin_a * small
        sin_k = sin_a * (1.0 - s2) + cos_a * small
        if not derivative:
            out[sl] = np.sum(c * (cos_k if kind == "ce" else sin_k), axis=0)
        elif kind == "ce":
            out[sl] = -np.sum((c * idx[:, None]) * sin_k, axis=0)
        else:
            out[sl] = np.sum((c * idx[:, None]) * cos_k, axis=0)
    return out


def _evaluate(kind: str, n: int, q: np.ndarray, x: np.ndarray, tol: float, derivative: bool):
    """Values (or derivatives), error bounds, terms, the coefficient table and the index of each point's q in it:
    q and x broadcast to one shape."""
    from .._hill_c import kernel

    qb, xb = np.broadcast_arrays(q, x)
    shape = qb.shape
    qf, xf = qb.reshape(-1), np.ascontiguousarray(xb.reshape(-1), dtype=float)
    uq, inv = np.unique(qf, return_inverse=True)
    tab = _coefficient_table(kind, n, uq, tol, derivative)
    rows = int(tab["rows"].max()) if uq.size else 1
    lib = kernel()
    if lib is not None:
        out = np.empty(qf.shape)
        col = np.ascontiguousarray(inv, dtype=np.int_)
        matrix = tab["matrix"]
        fam_offset = int(tab["index"][0]) if tab["index"].size else 0
        lib.symosc_mathieu_fourier_sum(fam_offset, int(kind == "se"), int(derivative), qf.size, col.ctypes.data,
                                       xf.ctypes.data, matrix.ctypes.data, matrix.shape[1], tab["rows"].ctypes.data,
                                       out.ctypes.data)  # fmt: skip
    else:
        out = _sum_numpy(kind, tab["coef"][:rows], tab["index"][:rows].astype(float), inv, xf, derivative)
    err = (tab["err1"] if derivative else tab["err0"])[inv]
    return out.reshape(shape), err.reshape(shape), rows, tab, inv


@dataclass(frozen=True)
class MathieuFunctionValues(SymPyPrintable):
    """Values of ce_n, se_n (or their x-derivatives) with what was achieved.

    Attributes
    ----------
    kind : str
        ``"ce"`` or ``"se"``.
    n : int
        Order.
    q, x : float or numpy.ndarray
        The points (broadcast to one shape), x in radians.
    values : float or numpy.ndarray
        ce_n(x, q), se_n(x, q), or their derivatives with respect to x.
    error_estimate : float or numpy.ndarray
        Bound on the absolute error of each value (normalised functions, DLMF 28.2.30).
    derivative : bool
        Whether ``values`` are x-derivatives.
    terms : int
        Fourier terms summed.
    characteristic_value : float or numpy.ndarray
        a_n(q) or b_n(q) at each point.
    """

    kind: str
    n: int
    q: Any
    x: Any
    values: Any
    error_estimate: Any
    derivative: bool
    terms: int
    characteristic_value: Any

    def __repr__(self) -> str:
        name = f"{self.kind}_{self.n}" + ("'" if self.derivative else "")
        worst = float(np.max(self.error_estimate)) if np.size(self.error_estimate) else 0.0
        size = np.size(self.values)
        return f"MathieuFunctionValues({name}, {size} value(s), terms={self.terms}, max error={worst:.2g})"

    def _repr_latex_(self) -> str:
        prime = "'" if self.derivative else ""
        if np.ndim(self.values) == 0:
            return (
                rf"$\mathrm{{{self.kind}}}_{{{self.n}}}{prime}({float(self.x):g}, {float(self.q):g}) = "
                rf"{float(self.values):.15g}$"
            )
        return rf"$\mathrm{{{self.kind}}}_{{{self.n}}}{prime}(x, q)$ at {np.size(self.values)} points"

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Plot the values against x (for one q), or against q (for one x); returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        ax = new_axes(ax)
        q, x, v = (np.broadcast_to(np.asarray(a, dtype=float), np.shape(self.values)).reshape(-1)
                   for a in (self.q, self.x, self.values))  # fmt: skip
        label = f"{self.kind}_{self.n}" + ("'" if self.derivative else "")
        if np.unique(q).size == 1:
            order = np.argsort(x)
            ax.plot(x[order], v[order], label=f"{label}(x, {q[0]:g})")
            ax.set_xlabel("x (rad)")
        else:
            order = np.argsort(q)
            ax.plot(q[order], v[order], label=f"{label}({x[0]:g}, q)")
            ax.set_xlabel("q")
        ax.legend()
        return ax


def _values(kind: str, n: int, q: Any, x: Any, tol: float, derivative: bool) -> MathieuFunctionValues:
    qa = check_finite_array("q", q)
    xa = check_finite_array("x", x)
    try:
        np.broadcast_shapes(qa.shape, xa.shape)
    except ValueError:
        raise ParameterError(f"q (shape {qa.shape}) and x (shape {xa.shape}) cannot be broadcast together") from None
    vals, err, rows, tab, inv = _evaluate(kind, n, qa, xa, tol, derivative)
    # tol is absolute for functions of size ~1: relative to the sup-norm scale sum |A_k| (sum k |A_k| for d/dx)
    scale = np.maximum(1.0, tab["s1" if derivative else "s0"])
    worst = float(np.max(tab["err1" if derivative else "err0"] / scale)) if scale.size else 0.0
    if worst > tol:
        raise ConvergenceError(f"{kind}_{n}: error estimate {worst:.3g} above tol={tol:g}", achieved=worst)
    lam = tab["lam"][inv]
    scalar = vals.ndim == 0
    cv = float(lam[0]) if scalar else lam.reshape(vals.shape)
    return MathieuFunctionValues(
        kind, n,
        float(qa) if qa.ndim == 0 else qa, float(xa) if xa.ndim == 0 else xa,
        float(vals) if scalar else vals, float(err) if scalar else err,
        derivative, rows, cv,
    )  # fmt: skip


@validated
def mathieu_function(
    kind: str, n: int, q: Any, x: Any, *, derivative: bool = False, tol: float = _DEFAULT_TOL
) -> MathieuFunctionValues:
    """ce_n(x, q) or se_n(x, q) (or the x-derivative) with its error bound.

    Parameters
    ----------
    kind : {"ce", "se"}
        Even (``ce_n``, n >= 0) or odd (``se_n``, n >= 1) periodic Mathieu function.
    n : int
        Order.
    q : float or array_like
        Any finite real q (negative q by DLMF 28.2(vii)); broadcasts against x.
    x : float or array_like
        Angle in radians.
    derivative : bool
        Return d/dx instead of the function.
    tol : float
        Target absolute error (for derivatives: relative to max(1, sqrt|q|), their scale); truncation is chosen
        for it and ``ConvergenceError`` is raised when the bound misses it.

    Returns
    -------
    MathieuFunctionValues

    Raises
    ------
    ParameterError
        Bad kind, n, q, x or tol.
    ConvergenceError
        The error bound is above ``tol``.

    See Also
    --------
    mathieu_ce, mathieu_se, mathieu_fourier_coefficients

    Examples
    --------
    >>> r = mathieu_function("ce", 0, 1.0, 0.0)
    >>> round(r.values, 12), r.error_estimate < 1e-13
    (0.384827829301, True)
    """
    kind, n = _check_kind_n(kind, n)
    tol = _check_tol(tol)
    if not isinstance(derivative, bool | np.bool_):
        raise ParameterError(f"derivative must be True or False, got {derivative!r}")
    return _values(kind, n, q, x, tol, bool(derivative))


@validated
def mathieu_ce(n: int, q: Any, x: Any, *, tol: float = _DEFAULT_TOL) -> Any:
    """Even periodic Mathieu function ce_n(x, q), normalised as DLMF 28.2.30 (x in radians).

    Parameters
    ----------
    n : int
        Order, n >= 0.
    q : float or array_like
        Any finite real q; broadcasts against x.
    x : float or array_like
        Angle in radians.
    tol : float
        Target absolute error (default 1e-13); see :func:`mathieu_function` for the bound.

    Returns
    -------
    float or numpy.ndarray

    See Also
    --------
    mathieu_se, mathieu_ce_prime, mathieu_function, mathieu_a

    Examples
    --------
    >>> abs(mathieu_ce(0, 0.0, 1.0) - 2**-0.5) < 1e-15    # ce_0 -> 1/sqrt(2) as q -> 0
    True
    >>> mathieu_ce(2, 1.0, [0.0, 0.5]).round(8)
    array([1.08596194, 0.76076844])
    """
    n = check_int("n", n, minimum=0)
    return _values("ce", n, q, x, _check_tol(tol), False).values


@validated
def mathieu_se(n: int, q: Any, x: Any, *, tol: float = _DEFAULT_TOL) -> Any:
    """Odd periodic Mathieu function se_n(x, q), n >= 1, normalised as DLMF 28.2.30 (x in radians).

    Parameters
    ----------
    n : int
        Order, n >= 1.
    q : float or array_like
        Any finite real q; broadcasts against x.
    x : float or array_like
        Angle in radians.
    tol : float
        Target absolute error (default 1e-13).

    Returns
    -------
    float or numpy.ndarray

    See Also
    --------
    mathieu_ce, mathieu_se_prime, mathieu_function, mathieu_b

    Examples
    --------
    >>> import math
    >>> abs(mathieu_se(1, 0.0, 0.5) - math.sin(0.5)) < 1e-15   # se_n -> sin nx as q -> 0
    True
    >>> round(mathieu_se(1, 1.0, 1.0), 10)
    0.8166845062
    """
    n = check_int("n", n, minimum=1)
    return _values("se", n, q, x, _check_tol(tol), False).values


@validated
def mathieu_ce_prime(n: int, q: Any, x: Any, *, tol: float = _DEFAULT_TOL) -> Any:
    """x-derivative of ce_n(x, q) (x in radians).

    Parameters
    ----------
    n : int
        Order, n >= 0.
    q : float or array_like
        Any finite real q; broadcasts against x.
    x : float or array_like
        Angle in radians.
    tol : float
        Target error relative to max(1, sqrt|q|) (default 1e-13).

    Returns
    -------
    float or numpy.ndarray

    See Also
    --------
    mathieu_ce, mathieu_se_prime, mathieu_function

    Examples
    --------
    >>> abs(mathieu_ce_prime(1, 0.0, 0.0)) < 1e-15       # ce_1 = cos x at q = 0: its slope vanishes at x = 0
    True
    >>> round(mathieu_ce_prime(0, 1.0, 0.5), 10)
    0.4481542814
    """
    n = check_int("n", n, minimum=0)
    return _values("ce", n, q, x, _check_tol(tol), True).values


@validated
def mathieu_se_prime(n: int, q: Any, x: Any, *, tol: float = _DEFAULT_TOL) -> Any:
    """x-derivative of se_n(x, q), n >= 1 (x in radians).

    Parameters
    ----------
    n : int
        Order, n >= 1.
    q : float or array_like
        Any finite real q; broadcasts against x.
    x : float or array_like
        Angle in radians.
    tol : float
        Target error relative to max(1, sqrt|q|) (default 1e-13).

    Returns
    -------
    float or numpy.ndarray

    See Also
    --------
    mathieu_se, mathieu_ce_prime, mathieu_function

    Examples
    --------
    >>> round(mathieu_se_prime(2, 0.0, 0.0), 12)
    2.0
    """
    n = check_int("n", n, minimum=1)
    return _values("se", n, q, x, _check_tol(tol), True).values


# ----------------------------------------------------------------------------------------------- coefficients
@dataclass(frozen=True)
class MathieuCoefficients(SymPyPrintable):
    """Fourier coefficients of ce_n or se_n at one q (DLMF 28.4).

    Attributes
    ----------
    kind : str
        ``"ce"`` or ``"se"``.
    n : int
        Order.
    q : float
        The parameter.
    index : numpy.ndarray
        Fourier indices k (ce_n = sum A_k cos kx, se_n = sum B_k sin kx).
    values : numpy.ndarray
        The coefficients A_k or B_k (normalised: 2 A_0^2 + sum A_k^2 = 1 for even n of ce, sum = 1 otherwise).
    characteristic_value : float
        a_n(q) or b_n(q).
    error_estimate : float
        Bound on the absolute error of each coefficient.
    """

    kind: str
    n: int
    q: float
    index: Any
    values: Any
    characteristic_value: float
    error_estimate: float

    def __repr__(self) -> str:
        letter = "A" if self.kind == "ce" else "B"
        return (
            f"MathieuCoefficients({self.kind}_{self.n}, q={self.q!r}, {letter}_k for k = {int(self.index[0])}.."
            f"{int(self.index[-1])}, error_estimate={self.error_estimate:.2g})"
        )

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Plot ``|coefficient|`` against the Fourier index on a log scale; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        ax = new_axes(ax)
        ax.semilogy(self.index, np.abs(self.values) + 1e-300, "o-", label=f"{self.kind}_{self.n}, q={self.q:g}")
        ax.set_xlabel("Fourier index k")
        ax.set_ylabel("|coefficient|")
        ax.legend()
        return ax


@validated
def mathieu_fourier_coefficients(kind: str, n: int, q: float, *, tol: float = _DEFAULT_TOL) -> MathieuCoefficients:
    """Normalised Fourier coefficients A_k^n(q) or B_k^n(q) of ce_n or se_n (DLMF 28.4).

    Parameters
    ----------
    kind : {"ce", "se"}
        Which function.
    n : int
        Order (n >= 1 for se).
    q : float
        Any finite real q (negative q by DLMF 28.2(vii)).
    tol : float
        Coefficients below ``tol / 1000`` (times the index) are dropped at the tail.

    Returns
    -------
    MathieuCoefficients

    See Also
    --------
    mathieu_coefficient_series, mathieu_function

    Examples
    --------
    >>> c = mathieu_fourier_coefficients("ce", 0, 1.0)
    >>> c.index[:3].tolist(), c.values[:2].round(10).tolist()
    ([0, 2, 4], [0.6729896723, -0.30630358])
    """
    kind, n = _check_kind_n(kind, n)
    qf = np.array([_fourier_q(q)])
    tol = _check_tol(tol)
    tab = _coefficient_table(kind, n, qf, tol)
    coef = tab["coef"][:, 0]
    nz = np.nonzero(coef)[0]
    rows = int(nz[-1]) + 1 if nz.size else 1
    return MathieuCoefficients(
        kind, n, float(qf[0]), tab["index"][:rows].copy(), coef[:rows].copy(), float(tab["lam"][0]),
        float(tab["err0"][0]),
    )  # fmt: skip


def _fourier_q(q: Any) -> float:
    from ..._validate import check_finite

    return check_finite("q", q)


# ----------------------------------------------------------------------------------------------- exact series
def _inverse_sqrt_series(norm: list[Fraction], order: int) -> list[Fraction]:
    """Coefficients of (norm(q) / norm_0)^(-1/2) up to q^order (exact)."""
    n0 = norm[0]
    r = [c / n0 for c in norm[: order + 1]]
    r[0] = Fraction(0)
    out = [Fraction(0)] * (order + 1)
    out[0] = Fraction(1)
    power = [Fraction(1)] + [Fraction(0)] * order  # r^i
    binom = Fraction(1)
    for i in range(1, order + 1):
        power = [sum((power[k] * r[s - k] for k in range(s + 1)), Fraction(0)) for s in range(order + 1)]
        binom = binom * (Fraction(-1, 2) - (i - 1)) / i
        if not any(power):
            break
        for s in range(order + 1):
            out[s] += binom * power[s]
    return out


@validated
def mathieu_coefficient_series(kind: str, n: int, order: int, *, symbol: sympy.Symbol | None = None) -> dict:
    """Exact power series in q of the normalised Fourier coefficients of ce_n or se_n (DLMF 28.6).

    Parameters
    ----------
    kind : {"ce", "se"}
        Which function.
    n : int
        Order (n >= 1 for se).
    order : int
        Highest power of q kept (0..60).
    symbol : sympy.Symbol, optional
        The variable (default ``q``).

    Returns
    -------
    dict
        Fourier index k -> SymPy polynomial in q (exact: Rational coefficients, times 1/sqrt(2) for ce_{2m},
        whose normalisation is 2 A_0^2 + sum A_k^2 = 1).

    See Also
    --------
    mathieu_function_series, mathieu_fourier_coefficients, mathieu_series_a

    Examples
    --------
    >>> c = mathieu_coefficient_series("ce", 0, 2)
    >>> c[0], c[2]
    (-sqrt(2)*q**2/32 + sqrt(2)/2, -sqrt(2)*q/4)
    """
    kind, n = _check_kind_n(kind, n)
    order = check_int("order", order, minimum=0, maximum=60)
    q = sympy.Symbol("q") if symbol is None else symbol
    if not isinstance(q, sympy.Symbol):
        raise ParameterError(f"symbol must be a sympy Symbol, got {symbol!r}")
    ab = "a" if kind == "ce" else "b"
    xs, norm = _fourier.coefficient_series(ab, n, order)
    inv = _inverse_sqrt_series(norm, order)
    scale = 1 / sympy.sqrt(sympy.Rational(norm[0].numerator, norm[0].denominator))
    idx = _fourier.fourier_indices(ab, n, len(xs[0]))
    out = {}
    for j in range(len(xs[0])):
        coeffs = [sum((xs[i][j] * inv[s - i] for i in range(s + 1)), Fraction(0)) for s in range(order + 1)]
        if any(coeffs):
            poly = sympy.Add(*[sympy.Rational(c.numerator, c.denominator) * q**s for s, c in enumerate(coeffs) if c])
            out[int(idx[j])] = sympy.expand(scale * poly)
    return out


@validated
def mathieu_function_series(
    kind: str, n: int, order: int, *, x: sympy.Symbol | None = None, symbol: sympy.Symbol | None = None
) -> sympy.Expr:
    """ce_n(x, q) or se_n(x, q) as an exact power series in q up to ``order`` (DLMF 28.6.21-28.6.26 and beyond).

    Parameters
    ----------
    kind : {"ce", "se"}
        Which function.
    n : int
        Order.
    order : int
        Highest power of q kept (0..60).
    x : sympy.Symbol, optional
        The angle (default ``x``).
    symbol : sympy.Symbol, optional
        The parameter (default ``q``).

    Returns
    -------
    sympy.Expr

    See Also
    --------
    mathieu_coefficient_series, mathieu_ce

    Examples
    --------
    >>> mathieu_function_series("ce", 0, 1)
    -sqrt(2)*q*cos(2*x)/4 + sqrt(2)/2
    """
    xs = sympy.Symbol("x") if x is None else x
    if not isinstance(xs, sympy.Symbol):
        raise ParameterError(f"x must be a sympy Symbol, got {x!r}")
    coeffs = mathieu_coefficient_series(kind, n, order, symbol=symbol)
    trig = sympy.cos if kind == "ce" else sympy.sin
    return sympy.Add(*[c * trig(k * xs) for k, c in sorted(coeffs.items())])
