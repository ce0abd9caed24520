"""Modified (radial) Mathieu functions Mc_n^(j)(z, h), Ms_n^(j)(z, h), j = 1..4, h = sqrt(q), q > 0 (DLMF 28.20).

They solve the modified Mathieu equation w'' - (a - 2q cosh 2z) w = 0 with a = a_n(q) (Mc) or b_n(q) (Ms), and
behave like the Bessel functions C_n^(j)(2h cosh z) for large z (DLMF 28.20.11-28.20.14):
C^(1) = J, C^(2) = Y, C^(3) = H^(1) = J + iY, C^(4) = H^(2) = J - iY.  Wronskian W{Mc^(1), Mc^(2)} =
W{Ms^(1), Ms^(2)} = 2/pi (DLMF 28.20.21).

Evaluated by the series in products of Bessel functions (DLMF 28.24.2-28.24.5), with u1 = h e^{-z}, u2 = h e^{z}
and the Fourier coefficients A, B of :mod:`~symosc.periodic.mathieu_functions.angular` (index p = 0, 1, 1, 2 for
Mc_{2m}, Mc_{2m+1}, Ms_{2m+1}, Ms_{2m+2}):

    eps_s Mc_n^(j) = (-1)^m sum_l (-1)^l (A_{2l+p} / A_{2s+p})
                     [J_{l-s}(u1) C^(j)_{l+s+p}(u2) + J_{l+s+p}(u1) C^(j)_{l-s}(u2)]

(minus between the two products for Ms; eps_0 = 2 for Mc_{2m} and s = 0, else 1).  These converge for every z and
are well conditioned where the terms do not cancel; the shift s is the index of the largest coefficient (no division
by a small one); every coefficient the eigenvector kernel computes is kept (the second kind multiplies tiny ones by
large Bessel functions).  The error estimate is the rounding of the sum relative to the sum of |terms| (Bessel
values to a few ulp) plus the coefficient error plus the last terms of the sum.  It is compared with ``tol`` relative
to the local amplitude ``sqrt(|w|^2 + |w'|^2 / omega^2)``, ``omega^2 = 2q cosh 2z - a``, where the function
oscillates (WKB: errors are measured against the size of the oscillation, not against a value near one of its
zeros), and relative to ``|w|`` elsewhere.

Where the series loses digits, ``ConvergenceError`` is raised rather than a wrong value returned.  With the default
``tol = 1e-12`` this happens only for the second kind (and kinds 3, 4) at small z for moderate-to-large orders:
measured on n <= 50, q <= 1e4, z in [0, 1], only for n >= 10, q from about 100 to 4 n^2, z below 0.75 (below 0.4
in most cases); the first kind is never refused there.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._plotting import new_axes, plot_method
from ..._printing import SymPyPrintable
from ..._validate import check_choice, check_finite_array, check_int, check_positive, validated
from ...errors import ConvergenceError, ParameterError
from .._hill import family_index
from .angular import _coefficient_table

__all__ = [
    "ModifiedMathieuValues",
    "mathieu_mc",
    "mathieu_mc_prime",
    "mathieu_modified",
    "mathieu_ms",
    "mathieu_ms_prime",
]

_EPS = float(np.finfo(float).eps)


def _bessel(j: int, order: np.ndarray, u: np.ndarray, derivative: bool) -> np.ndarray:
    import scipy.special as sp

    if j == 1:
        return sp.jvp(order, u) if derivative else sp.jv(order, u)
    if j == 2:
        return sp.yvp(order, u) if derivative else sp.yv(order, u)
    jv = sp.jvp(order, u) if derivative else sp.jv(order, u)
    yv = sp.yvp(order, u) if derivative else sp.yv(order, u)
    return jv + 1j * yv if j == 3 else jv - 1j * yv


def _series(func: str, j: int, n: int, q: float, z: np.ndarray, coef: np.ndarray, lam_err: float, coef_err: float):
    """(values, derivatives, error estimate of values, of derivatives) at the points z for one q > 0."""
    fam, _k = family_index("a" if func == "Mc" else "b", n)
    p = fam.offset  # 0, 1, 1, 2 for Mc_2m, Mc_2m+1, Ms_2m+1, Ms_2m+2
    m_sign = -1.0 if ((n - p) // 2) % 2 else 1.0  # (-1)^m with n = 2m + p
    sigma = 1.0 if func == "Mc" else -1.0
    s = int(np.argmax(np.abs(coef)))
    keep = np.nonzero(coef != 0.0)[0]
    ell = np.arange(int(keep[-1]) + 1)
    w = ((-1.0) ** ell) * coef[: ell.size] / coef[s] * m_sign
    if func == "Mc" and p == 0 and s == 0:
        w = w / 2.0
    h = float(np.sqrt(q))
    u1 = h * np.exp(-z)[None, :]
    u2 = h * np.exp(z)[None, :]
    o1 = (ell - s)[:, None].astype(float)
    o2 = (ell + s + p)[:, None].astype(float)
    ja1, ja2 = _bessel(1, o1, u1, False), _bessel(1, o2, u1, False)
    ca2, ca1 = _bessel(j, o2, u2, False), _bessel(j, o1, u2, False)
    jd1, jd2 = _bessel(1, o1, u1, True), _bessel(1, o2, u1, True)
    cd2, cd1 = _bessel(j, o2, u2, True), _bessel(j, o1, u2, True)
    term = ja1 * ca2 + sigma * ja2 * ca1
    dterm = (-u1 * jd1) * ca2 + ja1 * (u2 * cd2) + sigma * ((-u1 * jd2) * ca1 + ja2 * (u2 * cd1))
    wv = w[:, None]
    val = np.sum(wv * term, axis=0)
    der = np.sum(wv * dterm, axis=0)
    mag = np.sum(np.abs(wv) * (np.abs(ja1 * ca2) + np.abs(ja2 * ca1)), axis=0)
    dmag = np.sum(np.abs(wv) * (np.abs(u1 * jd1 * ca2) + np.abs(ja1 * u2 * cd2) + np.abs(u1 * jd2 * ca1)
                                + np.abs(ja2 * u2 * cd1)), axis=0)  # fmt: skip
    # Bessel values to ~8 ulp, the sum's rounding, and the coefficients' relative error
    rel = 16 * _EPS * np.sqrt(ell.size) + coef_err / abs(coef[s])
    # truncation: the last terms (coefficients below the float range are dropped; where the second-kind Bessel
    # factors grow faster than the coefficients decay -- small z, large q -- this is what limits the accuracy)
    tail = 10.0 * np.sum(np.abs(wv[-3:] * term[-3:]), axis=0)
    dtail = 10.0 * np.sum(np.abs(wv[-3:] * dterm[-3:]), axis=0)
    return val, der, rel * mag + tail, rel * dmag + dtail


def _amplitude(vals, ders, q, z, lam) -> np.ndarray:
    """The local amplitude of a solution of w'' = (a - 2q cosh 2z) w: where it oscillates (2q cosh 2z > a, local
    frequency omega), sqrt(|w|^2 + |w'|^2 / omega^2) (WKB; constant along z to leading order, so errors are measured
    against the size of the oscillation, not against a value near one of its zeros); else |w|."""
    omega2 = 2.0 * q * np.cosh(2.0 * z) - lam
    with np.errstate(divide="ignore", invalid="ignore"):
        osc = np.sqrt(np.abs(vals) ** 2 + np.abs(ders) ** 2 / np.where(omega2 > 0, omega2, np.inf))
    return np.maximum(np.where(omega2 > 0, osc, np.abs(vals)), 1e-300)


@dataclass(frozen=True)
class ModifiedMathieuValues(SymPyPrintable):
    """Values of a modified Mathieu function Mc_n^(j) or Ms_n^(j) and its z-derivative, with error estimates.

    Attributes
    ----------
    func : str
        ``"Mc"`` or ``"Ms"``.
    kind : int
        j = 1 (first kind, J-like), 2 (Y-like), 3 (H^(1)), 4 (H^(2)).
    n : int
        Order.
    q, z : float or numpy.ndarray
        The points (broadcast); h = sqrt(q).
    values, derivatives : float, complex or numpy.ndarray
        The function and its z-derivative (complex for kinds 3 and 4).
    error_estimate, derivative_error_estimate : float or numpy.ndarray
        Estimated absolute errors.
    """

    func: str
    kind: int
    n: int
    q: Any
    z: Any
    values: Any
    derivatives: Any
    error_estimate: Any
    derivative_error_estimate: Any

    def relative_error_estimate(self) -> Any:
        """``error_estimate / |value|`` (large near zeros of the function)."""
        with np.errstate(divide="ignore"):
            return np.asarray(self.error_estimate) / np.abs(self.values)

    def __repr__(self) -> str:
        worst = float(np.max(self.relative_error_estimate())) if np.size(self.values) else 0.0
        return (
            f"ModifiedMathieuValues({self.func}_{self.n}^({self.kind}), {np.size(self.values)} value(s), "
            f"max relative error estimate={worst:.2g})"
        )

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Plot the (real part of the) values against z for one q; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        ax = new_axes(ax)
        z = np.reshape(np.broadcast_to(self.z, np.shape(self.values)), -1)
        v = np.reshape(self.values, -1)
        order = np.argsort(z)
        ax.plot(z[order], np.real(v[order]), label=f"{self.func}_{self.n}^({self.kind})")
        ax.set_xlabel("z")
        ax.legend()
        return ax


@validated
def mathieu_modified(func: str, kind: int, n: int, q: Any, z: Any, *, tol: float = 1e-12) -> ModifiedMathieuValues:
    """Modified Mathieu function Mc_n^(j)(z, h) or Ms_n^(j)(z, h), h = sqrt(q), with its z-derivative.

    Parameters
    ----------
    func : {"Mc", "Ms"}
        Even-type (from a_n, n >= 0) or odd-type (from b_n, n >= 1) radial function.
    kind : {1, 2, 3, 4}
        Kind j: J-like, Y-like, H^(1)-like, H^(2)-like (DLMF 28.20(iii)).
    n : int
        Order.
    q : float or array_like
        Parameter q > 0 (h = sqrt(q)); broadcasts against z.
    z : float or array_like
        Real radial argument.
    tol : float
        Largest accepted error estimate (default 1e-12), relative to the local amplitude where the function
        oscillates and to ``|value|`` elsewhere (a ConvergenceError above it; see the module notes for the region).

    Returns
    -------
    ModifiedMathieuValues

    Raises
    ------
    ParameterError
        Bad arguments (q <= 0 included).
    ConvergenceError
        An error estimate above ``tol`` (second kind at small z for n >= 10, see the module notes).

    See Also
    --------
    mathieu_mc, mathieu_ms, mathieu_ce

    Examples
    --------
    >>> r = mathieu_modified("Mc", 1, 0, 1.0, 0.5)
    >>> bool(r.error_estimate < 1e-13 * abs(r.values))
    True
    """
    func = check_choice("func", func, ("Mc", "Ms"))
    tol = check_positive("tol", tol)
    kind = check_int("kind", kind, minimum=1, maximum=4)
    n = check_int("n", n, minimum=1 if func == "Ms" else 0)
    qa = check_finite_array("q", q)
    za = check_finite_array("z", z)
    if np.any(qa <= 0):
        raise ParameterError("q must be > 0 for the modified Mathieu functions Mc, Ms (h = sqrt(q)); got q <= 0")
    try:
        qb, zb = np.broadcast_arrays(qa, za)
    except ValueError:
        raise ParameterError(f"q (shape {qa.shape}) and z (shape {za.shape}) cannot be broadcast together") from None
    qf, zf = qb.reshape(-1), zb.reshape(-1)
    if np.any(np.abs(zf) > 700):
        raise ParameterError("z must satisfy |z| <= 700 (h e^z overflows beyond)")
    cplx = kind >= 3
    vals = np.empty(qf.shape, dtype=complex if cplx else float)
    ders = np.empty(qf.shape, dtype=complex if cplx else float)
    err = np.empty(qf.shape)
    derr = np.empty(qf.shape)
    uq, inv = np.unique(qf, return_inverse=True)
    tab = _coefficient_table("ce" if func == "Mc" else "se", n, uq, 1e-13, keep_tail=True)
    for i, qv in enumerate(uq):
        sel = np.nonzero(inv == i)[0]
        v, d, e, de = _series(func, kind, n, float(qv), zf[sel], tab["coef"][:, i], float(tab["lam_err"][i]),
                              float(tab["err0"][i]))  # fmt: skip
        vals[sel] = v if cplx else np.real(v)
        ders[sel] = d if cplx else np.real(d)
        err[sel], derr[sel] = e, de
    if not np.all(np.isfinite(vals)):
        raise ConvergenceError(f"{func}_{n}^({kind}): a Bessel function overflowed (z or q too large)")
    worst = float(np.max(err / _amplitude(vals, ders, qf, zf, tab["lam"][inv]))) if err.size else 0.0
    if worst > tol:
        raise ConvergenceError(
            f"{func}_{n}^({kind}): error estimate {worst:.3g} (relative to the local amplitude) above tol={tol:g}; "
            "the Bessel-product series loses accuracy here (see the module notes for the region)",
            achieved=worst,
        )
    shape = qb.shape
    if qb.ndim == 0:
        cast = complex if cplx else float
        return ModifiedMathieuValues(func, kind, n, float(qb), float(zb), cast(vals[0]), cast(ders[0]), float(err[0]),
                                     float(derr[0]))  # fmt: skip
    return ModifiedMathieuValues(func, kind, n, qb.copy(), zb.copy(), vals.reshape(shape), ders.reshape(shape),
                                 err.reshape(shape), derr.reshape(shape))  # fmt: skip


@validated
def mathieu_mc(kind: int, n: int, q: Any, z: Any) -> Any:
    """Modified Mathieu function Mc_n^(j)(z, h), h = sqrt(q) > 0, of kind j = 1..4 (DLMF 28.20, 28.24.2-3).

    Parameters
    ----------
    kind : {1, 2, 3, 4}
        Kind j (J-, Y-, H^(1)-, H^(2)-like).
    n : int
        Order, n >= 0.
    q : float or array_like
        Parameter q > 0; broadcasts against z.
    z : float or array_like
        Radial argument.

    Returns
    -------
    float, complex or numpy.ndarray

    See Also
    --------
    mathieu_ms, mathieu_mc_prime, mathieu_modified

    Examples
    --------
    >>> import math
    >>> import scipy.special as sp
    >>> z = 3.0                                   # large z: Mc^(1) ~ J_n(2h cosh z) (DLMF 28.20.11)
    >>> bool(abs(mathieu_mc(1, 0, 1.0, z) - sp.jv(0, 2 * math.cosh(z))) < 0.01)
    True
    """
    return mathieu_modified("Mc", kind, n, q, z).values


@validated
def mathieu_ms(kind: int, n: int, q: Any, z: Any) -> Any:
    """Modified Mathieu function Ms_n^(j)(z, h), h = sqrt(q) > 0, n >= 1, of kind j = 1..4 (DLMF 28.24.4-5).

    Parameters
    ----------
    kind : {1, 2, 3, 4}
        Kind j.
    n : int
        Order, n >= 1.
    q : float or array_like
        Parameter q > 0; broadcasts against z.
    z : float or array_like
        Radial argument.

    Returns
    -------
    float, complex or numpy.ndarray

    See Also
    --------
    mathieu_mc, mathieu_ms_prime, mathieu_modified

    Examples
    --------
    >>> round(mathieu_ms(1, 1, 1.0, 0.0), 15)          # Ms^(1) is odd in z
    0.0
    """
    return mathieu_modified("Ms", kind, n, q, z).values


@validated
def mathieu_mc_prime(kind: int, n: int, q: Any, z: Any) -> Any:
    """z-derivative of Mc_n^(j)(z, h).

    Parameters
    ----------
    kind : {1, 2, 3, 4}
        Kind j.
    n : int
        Order, n >= 0.
    q : float or array_like
        Parameter q > 0.
    z : float or array_like
        Radial argument.

    Returns
    -------
    float, complex or numpy.ndarray

    See Also
    --------
    mathieu_mc, mathieu_modified

    Examples
    --------
    >>> round(mathieu_mc_prime(1, 0, 1.0, 0.0), 15)    # Mc^(1) is even in z
    0.0
    """
    return mathieu_modified("Mc", kind, n, q, z).derivatives


@validated
def mathieu_ms_prime(kind: int, n: int, q: Any, z: Any) -> Any:
    """z-derivative of Ms_n^(j)(z, h).

    Parameters
    ----------
    kind : {1, 2, 3, 4}
        Kind j.
    n : int
        Order, n >= 1.
    q : float or array_like
        Parameter q > 0.
    z : float or array_like
        Radial argument.

    Returns
    -------
    float, complex or numpy.ndarray

    See Also
    --------
    mathieu_ms, mathieu_modified

    Examples
    --------
    >>> import math
    >>> w = mathieu_ms(1, 2, 2.0, 0.4) * mathieu_ms_prime(2, 2, 2.0, 0.4) - \\
    ...     mathieu_ms_prime(1, 2, 2.0, 0.4) * mathieu_ms(2, 2, 2.0, 0.4)
    >>> round(w * math.pi / 2, 12)                   # Wronskian 2/pi (DLMF 28.20.21)
    1.0
    """
    return mathieu_modified("Ms", kind, n, q, z).derivatives
