"""Characteristic exponent nu(a, q), Floquet solutions me_nu and fundamental solutions of the Mathieu equation.

Exponent (DLMF 28.2(iv), 28.12-28.13): the equation y'' + (a - 2q cos 2x) y = 0 has a solution
``e^{i nu x} P(x)`` with P of period pi; ``cos(pi nu) = w_I(pi; a, q)`` (DLMF 28.2.16).  ``nu`` is taken
continuous in ``a`` with ``nu = sqrt(a)`` at q = 0 and ``nu = n`` on the curves a_n, b_n:

* in the stable zone between a_n and b_{n+1} (q > 0): real ``nu`` in (n, n + 1);
* in the unstable zone between b_n and a_n (below a_0 for n = 0): ``nu = n + i mu`` with mu > 0.

It is computed from Hill's determinant (Whittaker & Watson 1927, section 19.42; DLMF 28.2(iv)):
``sin^2(pi nu / 2) = D(0) sin^2(pi sqrt(a) / 2)`` and ``cos^2(pi nu / 2) = D(1) cos^2(pi sqrt(a) / 2)``, both from
the LDL^T pivots of the four Hill matrices (no pole of D is evaluated; the infinite tail is summed), and ``n`` from
the number of negative pivots (the number of characteristic values below a).  The smaller of the two squares gives
nu (no cancellation near either edge); their sum is 1 exactly, which is checked.  nu(a, -q) = nu(a, q).

Floquet solutions (DLMF 28.12-28.14): ``me_nu(x, q) = sum_m c_{2m}^nu(q) e^{i (nu + 2m) x}`` for real non-integer
nu, where ``lambda_nu(q)`` is the eigenvalue of the symmetric matrix ``diag((nu + 2m)^2) + q (couplings)`` that
tends to nu^2 as q -> 0; ``sum c_{2m}^2 = 1`` and ``c_0^nu(q) > 0``.

Fundamental solutions (DLMF 28.2.5): w_I (w_I(0) = 1, w_I'(0) = 0) and w_II (w_II(0) = 0, w_II'(0) = 1) from the
Floquet solution F(x) = e^{i nu x} P(x) at (a, q): ``w_I = (F(x) + F(-x)) / (2 F(0))``,
``w_II = (F(x) - F(-x)) / (2 F'(0))``; where that is ill-conditioned (nu near an integer: coexistence and band edges,
where the second solution is not of Floquet form) the ODE is integrated instead (DOP853, tight tolerances,
two tolerances compared for the error estimate).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._plotting import new_axes, plot_method
from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_finite_array, validated
from ...errors import ConvergenceError, ParameterError
from . import _fourier

__all__ = [
    "FundamentalSolutions",
    "MathieuExponent",
    "mathieu_exponent",
    "mathieu_floquet_exponent",
    "mathieu_fundamental",
    "mathieu_lambda",
    "mathieu_me",
]

_EPS = float(np.finfo(float).eps)


# ---------------------------------------------------------------------------------------------------- exponent
def _hill_sc(a: np.ndarray, q: np.ndarray):
    """(S, C, log|S|, log|C|, count, err) at the points (1-d float arrays, q >= 0): the C kernel, or the Python
    evaluation of :func:`._fourier.hill_determinants` point by point without a compiler."""
    from .._hill_c import kernel

    lib = kernel()
    a = np.ascontiguousarray(a, dtype=float)
    q = np.ascontiguousarray(q, dtype=float)
    if lib is not None:
        out = [np.empty(a.size) for _ in range(5)]
        count = np.empty(a.size, dtype=np.intc)
        lib.symosc_mathieu_hill_sc(a.size, a.ctypes.data, q.ctypes.data, *[o.ctypes.data for o in out[:4]],
                                   count.ctypes.data, out[4].ctypes.data)  # fmt: skip
        s, c, ls, lc, err = out
        return s, c, ls, lc, count.astype(int), err
    rows = [_fourier.hill_determinants(float(x), float(y)) for x, y in zip(a, q, strict=True)]
    s, c, count, err = (np.array(v) for v in zip(*rows, strict=True)) if rows else (np.zeros(0),) * 4
    with np.errstate(divide="ignore"):
        return s, c, np.log(np.abs(s)), np.log(np.abs(c)), count.astype(int), err


def _exponents(a: np.ndarray, q: np.ndarray):
    """(nu, cos(pi nu), error estimate of nu, zone n, stable) at the points (1-d arrays, q >= 0), vectorised."""
    s_val, c_val, log_s, log_c, count, err = _hill_sc(a, q)
    k = count // 2
    stable = count % 2 == 1
    with np.errstate(all="ignore"):
        # stable: 0 <= S, C <= 1 up to rounding; nu0 in [0, 1] with sin^2(pi nu0 / 2) = S (the smaller one used)
        nu0 = np.where(
            s_val <= 0.5,
            2.0 / np.pi * np.arcsin(np.sqrt(np.clip(s_val, 0.0, 1.0))),
            2.0 / np.pi * np.arccos(np.sqrt(np.clip(c_val, 0.0, 1.0))),
        )
        frac = np.where(k % 2 == 0, nu0, 1.0 - nu0)
        small = np.minimum(np.abs(s_val), np.abs(c_val))
        dnu_s = err / (np.pi * np.sqrt(np.maximum(small, err) * np.maximum(1.0 - small, err)))
        # unstable: -S (k even) or -C (k odd) = sinh^2(pi mu / 2); from the logarithm where it overflows
        neg = np.where(k % 2 == 0, -s_val, -c_val)
        log_neg = np.where(k % 2 == 0, log_s, log_c)
        mu = np.where(
            np.isfinite(neg),
            2.0 / np.pi * np.arcsinh(np.sqrt(np.maximum(neg, 0.0))),
            2.0 / np.pi * (0.5 * log_neg + np.log(2.0)),
        )
        dnu_u = err / (np.pi * np.sqrt(np.maximum(neg, err) * (1.0 + np.maximum(neg, 0.0))))
        nu = np.where(stable, k + frac, k + 1j * mu)
        dnu = np.where(stable, dnu_s, np.where(np.isfinite(neg), dnu_u, 2.0 / np.pi * 1e-15 * np.abs(log_neg)))
        cos_pi_nu = np.where(s_val <= 0.5, 1.0 - 2.0 * s_val, 2.0 * c_val - 1.0)
    return nu.astype(complex), cos_pi_nu, dnu, k, stable


def _exponent(a: float, q: float) -> tuple[complex, float, float, int, bool]:
    """(nu, cos(pi nu), error estimate of nu, zone n, stable) at one point."""
    nu, cpn, dnu, k, stable = _exponents(np.array([a]), np.array([q]))
    return complex(nu[0]), float(cpn[0]), float(dnu[0]), int(k[0]), bool(stable[0])


@dataclass(frozen=True)
class MathieuExponent(SymPyPrintable):
    """Characteristic exponent of the Mathieu equation at (a, q) with what was achieved.

    Attributes
    ----------
    a, q : float or numpy.ndarray
        The points (broadcast).
    nu : complex or numpy.ndarray
        The exponent: real in (n, n + 1) in a stable zone, n + i mu (mu >= 0) in an unstable zone.
    cos_pi_nu : float or numpy.ndarray
        cos(pi nu) = w_I(pi) = half the trace of the monodromy matrix over one period pi (DLMF 28.2.16).
    zone : int or numpy.ndarray
        n: the integer part of nu (the number of characteristic values below a, halved).
    stable : bool or numpy.ndarray
        Whether every solution is bounded (``|cos(pi nu)| < 1``).
    error_estimate : float or numpy.ndarray
        Estimated absolute error of nu (large only where nu is inherently ill-conditioned: at the edges of the
        zones, d nu / d a is unbounded).
    """

    a: Any
    q: Any
    nu: Any
    cos_pi_nu: Any
    zone: Any
    stable: Any
    error_estimate: Any

    def __repr__(self) -> str:
        if np.ndim(self.nu) == 0:
            return (
                f"MathieuExponent(a={float(self.a)!r}, q={float(self.q)!r}, nu={complex(self.nu)!r}, "
                f"stable={bool(self.stable)}, error_estimate={float(self.error_estimate):.2g})"
            )
        return f"MathieuExponent({np.size(self.nu)} points, {int(np.sum(self.stable))} stable)"

    def _repr_latex_(self) -> str:
        if np.ndim(self.nu) == 0:
            return rf"$\nu({float(self.a):g}, {float(self.q):g}) = {complex(self.nu):.12g}$"
        return rf"$\nu(a, q)$ at {np.size(self.nu)} points"


def _broadcast_aq(a: Any, q: Any) -> tuple[np.ndarray, np.ndarray]:
    aa = check_finite_array("a", a)
    qa = check_finite_array("q", q)
    try:
        return np.broadcast_arrays(aa, qa)
    except ValueError:
        raise ParameterError(f"a (shape {aa.shape}) and q (shape {qa.shape}) cannot be broadcast together") from None


@validated
def mathieu_floquet_exponent(a: Any, q: Any) -> MathieuExponent:
    """Characteristic exponent nu(a, q) with cos(pi nu), the zone, stability and an error estimate.

    Parameters
    ----------
    a : float or array_like
        Characteristic parameter a of y'' + (a - 2q cos 2x) y = 0.
    q : float or array_like
        Parameter q (any real; nu(a, -q) = nu(a, q)); broadcasts against a.

    Returns
    -------
    MathieuExponent

    See Also
    --------
    mathieu_exponent, mathieu_fundamental, symosc.periodic.monodromy

    Examples
    --------
    >>> r = mathieu_floquet_exponent(0.5, 0.3)
    >>> round(r.nu.real, 12), r.stable
    (0.776983424487, True)
    """
    ab, qb = _broadcast_aq(a, q)
    nu, cpn, err, zone, stable = _exponents(ab.reshape(-1), np.abs(qb.reshape(-1)))
    if ab.ndim == 0:
        return MathieuExponent(float(ab), float(qb), complex(nu[0]), float(cpn[0]), int(zone[0]), bool(stable[0]),
                               float(err[0]))  # fmt: skip
    shape = ab.shape
    return MathieuExponent(ab.copy(), qb.copy(), nu.reshape(shape), cpn.reshape(shape), zone.reshape(shape),
                           stable.reshape(shape), err.reshape(shape))  # fmt: skip


@validated
def mathieu_exponent(a: Any, q: Any) -> Any:
    """Characteristic exponent nu(a, q) of the Mathieu equation (DLMF 28.2(iv), 28.12-28.13).

    Real (a float) when every point is in a stable zone, complex ``n + i mu`` otherwise (as
    ``numpy.emath.sqrt`` does): continuous in a, ``nu = sqrt(a)`` at q = 0, integer n on the curves a_n(q), b_n(q).

    Parameters
    ----------
    a : float or array_like
        Characteristic parameter a.
    q : float or array_like
        Parameter q (any real); broadcasts against a.

    Returns
    -------
    float, complex or numpy.ndarray

    See Also
    --------
    mathieu_floquet_exponent, mathieu_me, mathieu_fundamental

    Examples
    --------
    >>> round(mathieu_exponent(2.25, 0.0), 14)
    1.5
    >>> nu = mathieu_exponent(1.0, 1.0)          # between b_1 and a_1: unstable
    >>> round(nu.real, 12), nu.imag > 0
    (1.0, True)
    """
    r = mathieu_floquet_exponent(a, q)
    nu = r.nu
    if np.ndim(nu) == 0:
        return nu.real if nu.imag == 0.0 else nu
    return nu.real.copy() if not np.any(nu.imag) else nu


# ---------------------------------------------------------------------------------------------------- me_nu
def _me_coefficients(nu: float, q: float) -> tuple[np.ndarray, np.ndarray, float]:
    """(indices m, coefficients c_{2m}, lambda_nu(q)) for real non-integer nu."""
    from scipy.linalg import eigh_tridiagonal

    half = int(12 + abs(nu) / 2 + 1.5 * math.sqrt(abs(q)) + 8)
    m = np.arange(-half - int(nu // 2), half - int(nu // 2) + 1)
    d = (nu + 2.0 * m) ** 2
    e = np.full(m.size - 1, float(q))
    r = int(np.sum(np.abs(nu + 2.0 * m) < abs(nu)))
    w, v = eigh_tridiagonal(d, e, select="i", select_range=(r, r))
    c = v[:, 0]
    if max(abs(c[0]), abs(c[-1])) > 1e-15:  # pragma: no cover - the size heuristic leaves a margin
        raise ConvergenceError(f"me_nu coefficients did not converge at nu={nu!r}, q={q!r}")
    c0 = c[m == 0][0]
    if c0 < 0:
        c = -c
    return m, c, float(w[0])


def _check_nu(nu: Any) -> float:
    nu = check_finite("nu", nu)
    if abs(nu - round(nu)) < 1e-12:
        raise ParameterError(
            f"nu must not be an integer (got {nu!r}): for integer order use mathieu_ce / mathieu_se "
            "(me_n is not defined there by DLMF 28.12)"
        )
    return nu


@validated
def mathieu_lambda(nu: float, q: Any) -> Any:
    """Eigenvalue lambda_nu(q) for real non-integer order nu (DLMF 28.12.1): the a with exponent nu.

    Parameters
    ----------
    nu : float
        Real, non-integer order.
    q : float or array_like
        Parameter q.

    Returns
    -------
    float or numpy.ndarray

    See Also
    --------
    mathieu_me, mathieu_exponent

    Examples
    --------
    >>> round(mathieu_lambda(0.5, 0.0), 14)
    0.25
    >>> lam = mathieu_lambda(1.5, 2.0)
    >>> round(float(mathieu_exponent(lam, 2.0)), 10)
    1.5
    """
    nu = _check_nu(nu)
    qa = check_finite_array("q", q)
    out = np.array([_me_coefficients(nu, float(v))[2] for v in qa.reshape(-1)])
    return float(out[0]) if qa.ndim == 0 else out.reshape(qa.shape)


@validated
def mathieu_me(nu: float, q: float, x: Any, *, derivative: bool = False) -> Any:
    """Floquet solution me_nu(x, q) = sum c_{2m} e^{i (nu + 2m) x} for real non-integer nu (DLMF 28.12).

    Parameters
    ----------
    nu : float
        Real, non-integer order.
    q : float
        Parameter q.
    x : float or array_like
        Argument in radians.
    derivative : bool
        Return the x-derivative instead.

    Returns
    -------
    complex or numpy.ndarray of complex

    See Also
    --------
    mathieu_lambda, mathieu_exponent, mathieu_fundamental

    Examples
    --------
    >>> import math
    >>> v = mathieu_me(0.5, 0.0, 1.0)
    >>> round(v.real, 12) == round(math.cos(0.5), 12), round(v.imag, 12) == round(math.sin(0.5), 12)
    (True, True)
    """
    nu = _check_nu(nu)
    qf = check_finite("q", q)
    xa = check_finite_array("x", x)
    if not isinstance(derivative, bool | np.bool_):
        raise ParameterError(f"derivative must be True or False, got {derivative!r}")
    m, c, _lam = _me_coefficients(nu, qf)
    k = nu + 2.0 * m
    phase = np.exp(1j * np.multiply.outer(xa, k))
    weights = c * (1j * k) if derivative else c
    out = phase @ weights
    return complex(out) if xa.ndim == 0 else out


# ---------------------------------------------------------------------------------------------------- fundamental
@dataclass(frozen=True)
class FundamentalSolutions(SymPyPrintable):
    """The fundamental solutions w_I, w_II of the Mathieu equation at (a, q) and their derivatives (DLMF 28.2.5).

    Attributes
    ----------
    a, q : float
        The point.
    x : float or numpy.ndarray
        Arguments (radians).
    w1, w1_prime, w2, w2_prime : float or numpy.ndarray
        w_I (even, w_I(0) = 1, w_I'(0) = 0), w_II (odd, w_II(0) = 0, w_II'(0) = 1) and their x-derivatives.
    nu : complex
        The characteristic exponent.
    method : str
        ``"floquet"`` (from the Floquet solution) or ``"ode"`` (integration, near integer nu).
    error_estimate : float
        Estimated absolute error (relative to ``max(1, |w|)``).
    """

    a: float
    q: float
    x: Any
    w1: Any
    w1_prime: Any
    w2: Any
    w2_prime: Any
    nu: complex
    method: str
    error_estimate: float

    def __repr__(self) -> str:
        return (
            f"FundamentalSolutions(a={self.a!r}, q={self.q!r}, {np.size(self.x)} point(s), nu={self.nu!r}, "
            f"method={self.method!r}, error_estimate={self.error_estimate:.2g})"
        )

    def monodromy(self) -> np.ndarray:
        """The matrix [[w_I, w_II], [w_I', w_II']] at the last x (the monodromy matrix when x = pi)."""
        pick = lambda v: float(np.reshape(v, -1)[-1])  # noqa: E731
        return np.array([[pick(self.w1), pick(self.w2)], [pick(self.w1_prime), pick(self.w2_prime)]])

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Plot w_I and w_II against x; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        ax = new_axes(ax)
        x = np.reshape(self.x, -1)
        order = np.argsort(x)
        ax.plot(x[order], np.reshape(self.w1, -1)[order], label="w_I")
        ax.plot(x[order], np.reshape(self.w2, -1)[order], label="w_II")
        ax.set_xlabel("x (rad)")
        ax.set_title(f"a = {self.a:g}, q = {self.q:g}, nu = {self.nu:.6g}")
        ax.legend()
        return ax


def _floquet_vector(nu: complex, a: float, q: float) -> tuple[np.ndarray, np.ndarray, float]:
    """Null vector of diag((nu + 2m)^2 - a) + q (couplings), complex nu, by the twisted factorisation; residual."""
    half = int(16 + abs(nu.real) / 2 + 1.5 * math.sqrt(abs(q)) + math.sqrt(abs(a)) / 2 + 8)
    base = round(nu.real) // 2
    m = np.arange(-half - base, half - base + 1)
    dx = (nu + 2.0 * m) ** 2 - a
    size = m.size
    b = q * q
    t = np.empty(size, dtype=complex)
    u = np.empty(size, dtype=complex)
    tiny = _EPS * (abs(a) + 4 * abs(q) + 1.0)
    t[0] = dx[0]
    for j in range(1, size):
        t[j] = dx[j] - b / (t[j - 1] if t[j - 1] != 0 else tiny)
    u[-1] = dx[-1]
    for j in range(size - 2, -1, -1):
        u[j] = dx[j] - b / (u[j + 1] if u[j + 1] != 0 else tiny)
    g = t + u - dx
    k = int(np.argmin(np.abs(g)))
    z = np.zeros(size, dtype=complex)
    z[k] = 1.0
    for j in range(k - 1, -1, -1):
        z[j] = -q * z[j + 1] / t[j]
    for j in range(k + 1, size):
        z[j] = -q * z[j - 1] / u[j]
    z /= np.sqrt(np.sum(np.abs(z) ** 2))
    return m, z, float(abs(g[k]))


def _ode(a: float, q: float, xs: np.ndarray, rtol: float) -> np.ndarray:
    """[w1, w1', w2, w2'] at the points xs by DOP853 (rows), integrating from 0 outwards in both directions."""
    from scipy.integrate import solve_ivp

    def rhs(x, y):
        f = a - 2 * q * math.cos(2 * x)
        return [y[1], -f * y[0], y[3], -f * y[2]]

    out = np.empty((4, xs.size))
    out[:, xs == 0] = np.array([[1.0], [0.0], [0.0], [1.0]])
    for sign in (1.0, -1.0):
        sel = np.nonzero(sign * xs > 0)[0]
        if not sel.size:
            continue
        order = sel[np.argsort(sign * xs[sel])]
        end = float(xs[order[-1]])
        sol = solve_ivp(rhs, (0.0, end), [1.0, 0.0, 0.0, 1.0], method="DOP853", t_eval=xs[order], rtol=rtol,
                        atol=rtol * 1e-3)  # fmt: skip
        if not sol.success:  # pragma: no cover
            raise ConvergenceError(f"integration of the Mathieu equation failed: {sol.message}")
        out[:, order] = sol.y
    return out


@validated
def mathieu_fundamental(a: float, q: float, x: Any, *, tol: float = 1e-10) -> FundamentalSolutions:
    """Fundamental solutions w_I, w_II (and derivatives) of y'' + (a - 2q cos 2x) y = 0 at any (a, q).

    Parameters
    ----------
    a : float
        Characteristic parameter.
    q : float
        Parameter q.
    x : float or array_like
        Arguments in radians.
    tol : float
        Target error (relative to ``max(1, |w|)``); the Floquet route is used when its conditioning allows it, the
        integration otherwise.

    Returns
    -------
    FundamentalSolutions

    See Also
    --------
    mathieu_exponent, symosc.periodic.monodromy

    Examples
    --------
    >>> import math
    >>> f = mathieu_fundamental(0.5, 0.3, math.pi)
    >>> M = f.monodromy()                          # trace / 2 = cos(pi nu) (DLMF 28.2.16)
    >>> bool(abs((M[0, 0] + M[1, 1]) / 2 - math.cos(math.pi * mathieu_exponent(0.5, 0.3))) < 1e-10)
    True
    """
    af = check_finite("a", a)
    qf = check_finite("q", q)
    tol = check_finite("tol", tol)
    if not tol > 0:
        raise ParameterError(f"tol must be positive, got {tol!r}")
    xa = check_finite_array("x", x)
    xs = xa.reshape(-1)
    nu, _cpn, dnu, _k, _stable = _exponent(af, abs(qf))
    frac = abs(nu.real - round(nu.real)) if nu.imag == 0 else 1.0
    scale = float(np.exp(abs(nu.imag) * np.max(np.abs(xs)))) if xs.size else 1.0
    result = None
    if frac > 1e-6 or abs(nu.imag) > 1e-6:
        mm, z, resid = _floquet_vector(complex(nu), af, qf)
        kx = complex(nu) + 2.0 * mm
        f0 = complex(np.sum(z))
        fp0 = complex(np.sum(1j * kx * z))
        cond = 1.0 / max(min(abs(f0), abs(fp0)), 1e-300)
        err = (resid + dnu * (1 + np.max(np.abs(xs), initial=0.0)) + 1e3 * _EPS) * cond * scale
        if err <= tol:
            ph_p = np.exp(1j * np.multiply.outer(xs, kx))
            ph_m = np.exp(-1j * np.multiply.outer(xs, kx))
            fp, fm = ph_p @ z, ph_m @ z
            dp, dm = ph_p @ (1j * kx * z), ph_m @ (1j * kx * z)  # F'(x) and F'(-x)
            w1 = ((fp + fm) / (2 * f0)).real
            w2 = ((fp - fm) / (2 * fp0)).real
            w1p = ((dp - dm) / (2 * f0)).real
            w2p = ((dp + dm) / (2 * fp0)).real
            result = (w1, w1p, w2, w2p, "floquet", float(err))
    if result is None:
        # two local tolerances a decade apart, well below tol (the global error over many periods exceeds the
        # local one): the difference estimates the error of the looser solution, a bound for the returned one
        rtol = max(tol * 1e-3, 2.5e-14)
        y1 = _ode(af, qf, xs, rtol)
        y2 = _ode(af, qf, xs, 10.0 * rtol)
        err = float(np.max(np.abs(y1 - y2) / np.maximum(1.0, np.abs(y1)))) if xs.size else 0.0
        if err > tol:
            raise ConvergenceError(f"fundamental solutions: integration error estimate {err:.3g} above tol={tol:g}",
                                   achieved=err)  # fmt: skip
        result = (y1[0], y1[1], y1[2], y1[3], "ode", err)
    w1, w1p, w2, w2p, method, err = result
    shape = xa.shape
    pack = lambda v: float(v[0]) if xa.ndim == 0 else np.asarray(v).reshape(shape)  # noqa: E731
    return FundamentalSolutions(af, qf, float(xa) if xa.ndim == 0 else xa, pack(w1), pack(w1p), pack(w2), pack(w2p),
                                complex(nu), method, err)  # fmt: skip
