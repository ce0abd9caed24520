"""Retarded (delay) systems: characteristic quasi-polynomials and their roots (Bulgakov §4.13–4.17).

The characteristic function of a linear system with delays is a quasi-polynomial
``f(p) = sum_k P_k(p) exp(-tau_k p)`` (``tau_k >= 0``).  It has infinitely many roots; this module counts them in a
rectangle with a *certified* argument-principle computation and then locates and polishes each one.

Certification.  On a contour segment ``[z0, z1]``, ``|f(z) - f(z0)| <= max|f'| |z1 - z0|``, and ``max|f'|`` is
bounded in closed form from the coefficients (``|exp(-tau p)| <= exp(-tau min Re p)``, ``|P(p)| <= sum |c_j| R^j``).
A segment is accepted when that bound plus a bound on the floating-point error of ``f(z0)`` is below ``|f(z0)|``:
then ``f`` has no zero on the segment and its argument turns by less than ``pi/2`` there, so the principal arguments
of ``f(z1)/f(z0)`` add up *exactly* to ``2 pi`` times the number of roots inside.  Segments are bisected until
accepted; a root on (or within rounding distance of) the contour raises :class:`~symosc.errors.ConvergenceError`.

Roots are then isolated by recursive bisection of the rectangle (each piece counted the same way) and polished by
Newton's method in mpmath; a cluster of ``m`` roots in a box smaller than ``cluster`` is reported as one root of
multiplicity ``m`` (a zero of ``f^(m-1)`` found by Newton), as happens at the optimal designs of §4.16–4.17.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from .._plotting import plot_method
from .._printing import SymPyPrintable
from .._validate import check_positive, validated
from ..errors import ConvergenceError, ModelError, ParameterError
from ..numeric import compile
from . import _checks

__all__ = [
    "DelayRoots",
    "QuasiPolynomial",
    "andronov_maier_optimum",
    "callender_hartree_porter_optimum",
    "characteristic_quasipolynomial",
    "count_roots",
    "quasi_polynomial",
    "quasi_polynomial_roots",
]

p = sp.Symbol("p")

_EPS = np.finfo(float).eps


@dataclass(frozen=True)
class QuasiPolynomial(SymPyPrintable):
    """``f(p) = sum_k P_k(p) exp(-tau_k p)`` with numeric coefficients; call it to evaluate ``f`` (vectorised).

    Attributes
    ----------
    expr : Expr
        The quasi-polynomial as a SymPy expression.
    variable : Symbol
        Its variable ``p``.
    terms : tuple of (float, tuple of complex)
        ``(tau_k, coefficients of P_k in ascending powers)`` for each delay ``tau_k >= 0``, ascending in ``tau_k``.
    """

    expr: sp.Expr
    variable: sp.Symbol
    terms: tuple[tuple[float, tuple[complex, ...]], ...]

    def __call__(self, z: Any) -> Any:
        z = np.asarray(z, dtype=complex)
        out = np.zeros(z.shape, dtype=complex)
        for tau, c in self.terms:
            out += np.exp(-tau * z) * np.polynomial.polynomial.polyval(z, c)
        return out

    def _pieces(self, k: int):
        """For ``f^(k)``: yield ``(tau, [(weight, coefficients of P^(j))])`` with ``weight = C(k, j) (-tau)^(k-j)``."""
        P = np.polynomial.polynomial
        for tau, c in self.terms:
            parts = []
            cj = np.asarray(c, dtype=complex)
            for j in range(k + 1):
                w = math.comb(k, j) * (-tau) ** (k - j)
                if w != 0 and cj.size:
                    parts.append((w, cj))
                cj = P.polyder(cj) if cj.size > 1 else np.zeros(0, dtype=complex)
            yield tau, parts

    def derivative(self, k: int, z: Any) -> Any:
        """``f^(k)(z)`` (vectorised).

        Parameters
        ----------
        k : int
            Order of the derivative, an integer >= 0.
        z : complex or array_like of complex
            Point(s) at which to evaluate.
        """
        z = np.asarray(z, dtype=complex)
        out = np.zeros(z.shape, dtype=complex)
        for tau, parts in self._pieces(k):
            acc = sum(w * np.polynomial.polynomial.polyval(z, c) for w, c in parts)
            out += np.exp(-tau * z) * acc
        return out

    def _abs_terms(self, z: np.ndarray, k: int = 0) -> np.ndarray:
        """``sum |weight| |exp(-tau z)| sum_j |c_j| |z|^j`` for ``f^(k)`` (scale of its rounding error)."""
        r = np.abs(z)
        out = np.zeros(z.shape)
        for tau, parts in self._pieces(k):
            acc = sum(abs(w) * np.polynomial.polynomial.polyval(r, np.abs(c)) for w, c in parts)
            out += np.exp(-tau * z.real) * acc
        return out

    def derivative_bound(self, z0: np.ndarray, z1: np.ndarray, k: int = 1) -> np.ndarray:
        """Upper bound of ``|f^(k)|`` on each segment ``[z0, z1]`` (vectorised).

        Parameters
        ----------
        z0 : ndarray of complex
            Start points of the segments.
        z1 : ndarray of complex
            End points of the segments, the same shape as ``z0``.
        k : int, optional
            Order of the derivative bounded, an integer >= 0 (default 1).
        """
        R = np.maximum(np.abs(z0), np.abs(z1))
        re_min = np.minimum(z0.real, z1.real)
        out = np.zeros(R.shape)
        for tau, parts in self._pieces(k):
            acc = sum(abs(w) * np.polynomial.polynomial.polyval(R, np.abs(c)) for w, c in parts)
            out += np.exp(-tau * re_min) * acc
        return out * (1 + 1e-12)

    @property
    def degree(self) -> int:
        return max(len(c) - 1 for _, c in self.terms)


@validated
def quasi_polynomial(f: Any, variable: sp.Symbol | None = None) -> QuasiPolynomial:
    """Parse ``f`` as ``sum_k P_k(p) exp(-tau_k p)`` with numeric coefficients and delays ``tau_k >= 0``.

    Parameters
    ----------
    f : Expr
        The quasi-polynomial, e.g. ``p**2 + rho*p + sigma*exp(-p)`` with numbers for the parameters: polynomials in
        the variable times ``exp(-tau*p)`` with numeric ``tau >= 0``.
    variable : Symbol, optional
        The variable of ``f`` (default: its only free symbol).

    Returns
    -------
    QuasiPolynomial

    Examples
    --------
    >>> import sympy as sp
    >>> q = quasi_polynomial(p**2 + sp.Rational(1, 5) * p + 2 * sp.exp(-p))
    >>> [(tau, [complex(c).real for c in cs]) for tau, cs in q.terms]
    [(0.0, [0.0, 0.2, 1.0]), (1.0, [2.0])]
    """
    f = sp.expand(sp.sympify(f))
    if variable is None:
        free = f.free_symbols
        if len(free) != 1:
            raise ModelError(
                f"the quasi-polynomial must have exactly one free symbol (the variable), got {sorted(map(str, free))};"
                " substitute the parameter values first"
            )
        variable = free.pop()
    extra = f.free_symbols - {variable}
    if extra:
        raise ParameterError("substitute values for: " + ", ".join(sorted(s.name for s in extra)))
    f = sp.expand(sp.powsimp(sp.expand(f), combine="exp"))
    groups: dict[Any, sp.Expr] = {}
    for term in sp.Add.make_args(f):
        tau = sp.S.Zero
        rest = sp.S.One
        for factor in sp.Mul.make_args(term):
            if isinstance(factor, sp.exp) or (factor.is_Pow and factor.base == sp.E):
                arg = sp.expand(factor.exp if factor.is_Pow else factor.args[0])
                k = arg.coeff(variable)
                const = sp.expand(arg - k * variable)
                if const.has(variable) or not k.is_number:
                    raise ModelError(f"exponential {factor} is not exp(-tau*{variable}) with numeric tau")
                tau += -k
                rest *= sp.exp(const)
            else:
                rest *= factor
        groups[tau] = groups.get(tau, sp.S.Zero) + rest
    terms = []
    for tau, poly in sorted(groups.items(), key=lambda kv: float(kv[0])):
        if not poly.is_polynomial(variable):
            raise ModelError(f"the factor {poly} of exp(-{tau}*{variable}) is not a polynomial in {variable}")
        if float(tau) < 0 or not sp.im(tau) == 0:
            raise ModelError(f"delay {tau} must be real and non-negative (advanced arguments are not supported)")
        coeffs = sp.Poly(poly, variable).all_coeffs()[::-1]
        terms.append((float(tau), tuple(complex(sp.N(c, 20)) for c in coeffs)))
    if not terms:
        raise ModelError("the quasi-polynomial is identically zero")
    return QuasiPolynomial(expr=f, variable=variable, terms=tuple(terms))


def _rect_contour(region: tuple[float, float, float, float]) -> list[complex]:
    x0, x1, y0, y1 = region
    if not (x0 < x1 and y0 < y1) or not all(map(math.isfinite, region)):
        raise ParameterError(f"region must be (re_min, re_max, im_min, im_max) with min < max, got {region}")
    return [complex(x0, y0), complex(x1, y0), complex(x1, y1), complex(x0, y1), complex(x0, y0)]


def _winding(q: QuasiPolynomial, vertices: list[complex], max_segments: int = 2_000_000) -> tuple[int, int]:
    """Certified winding number of ``f`` along the closed polygon; returns (count, number of evaluations)."""
    z0 = np.array(vertices[:-1], dtype=complex)
    z1 = np.array(vertices[1:], dtype=complex)
    scale = max(abs(v) for v in vertices) + 1.0
    total = 0.0
    n_eval = 0
    while z0.size:
        f0 = q(z0)
        f1 = q(z1)
        n_eval += 2 * z0.size
        h = np.abs(z1 - z0)
        # |f(z) - f(z0)| <= |f'(z0)| h + max|f''| h^2/2 on the segment (plus rounding of f(z0), f'(z0))
        err0 = 64 * _EPS * (q.degree + 2) * q._abs_terms(z0)
        d1 = np.abs(q.derivative(1, z0)) + 64 * _EPS * (q.degree + 2) * q._abs_terms(z0, 1)
        n_eval += z0.size
        ok = d1 * h + 0.5 * q.derivative_bound(z0, z1, 2) * h**2 + err0 < np.abs(f0)
        if np.any(ok):
            total += float(np.sum(np.angle(f1[ok] / f0[ok])))
        bad = ~ok
        if not np.any(bad):
            break
        if np.any(h[bad] < 1e-13 * scale) or n_eval > max_segments:
            where = z0[bad][np.argmin(h[bad])]
            raise ConvergenceError(
                f"cannot certify the root count: f is (numerically) zero on or very near the contour near {where:.6g};"
                " move the region boundary slightly"
            )
        mid = 0.5 * (z0[bad] + z1[bad])
        z0, z1 = np.concatenate([z0[bad], mid]), np.concatenate([mid, z1[bad]])
    count = total / (2 * math.pi)
    n = round(count)
    if abs(count - n) > 1e-6:  # pragma: no cover - guarded by the certification
        raise ConvergenceError(f"winding number {count} is not an integer", achieved=abs(count - n))
    return int(n), n_eval


@validated
def count_roots(f: Any, region: tuple[float, float, float, float], variable: sp.Symbol | None = None) -> int:
    """Certified number of roots (with multiplicity) of a quasi-polynomial inside the open rectangle.

    ``region = (re_min, re_max, im_min, im_max)``.  Raises ConvergenceError if a root lies on the boundary.

    Parameters
    ----------
    f : Expr or QuasiPolynomial
        The quasi-polynomial, an expression in one variable with numbers for the parameters (see
        :func:`quasi_polynomial`), or an already parsed one.
    region : tuple of float
        ``(re_min, re_max, im_min, im_max)``: finite bounds with ``re_min < re_max`` and ``im_min < im_max``; the
        boundary must not pass through a root.
    variable : Symbol, optional
        The variable of ``f`` (default: its only free symbol).

    Returns
    -------
    int
        The number of roots inside, counted with multiplicity.

    Examples
    --------
    >>> import sympy as sp
    >>> count_roots(p**2 + p + sp.exp(-p), (-3, 1, -2.1, 2.2))
    2
    """
    q = f if isinstance(f, QuasiPolynomial) else quasi_polynomial(f, variable)
    return _winding(q, _rect_contour(region))[0]


@dataclass(frozen=True)
class DelayRoots(SymPyPrintable):
    """Roots of a quasi-polynomial in a rectangle.

    Attributes
    ----------
    roots : tuple of mpmath.mpc
        Distinct roots, ordered by decreasing real part, then imaginary part.
    multiplicities : tuple of int
        Multiplicity of each root (a cluster smaller than ``cluster`` counts as one multiple root).
    count : int
        The certified number of roots in the region (with multiplicity); equals ``sum(multiplicities)``.
    region : tuple
        The rectangle ``(re_min, re_max, im_min, im_max)`` searched.
    dps : int
        Working precision of the Newton polish.
    evaluations : int
        Number of float evaluations of ``f`` used by the certified counting.
    """

    roots: tuple
    multiplicities: tuple[int, ...]
    count: int
    region: tuple[float, float, float, float]
    dps: int
    evaluations: int

    @property
    def rightmost(self) -> Any:
        """The root with the largest real part (``None`` if there is none in the region)."""
        return self.roots[0] if self.roots else None

    def as_array(self) -> np.ndarray:
        """Roots as a complex NumPy array (multiple roots listed once)."""
        return np.array([complex(r) for r in self.roots])

    def __repr__(self) -> str:
        items = ", ".join(
            (mpmath.nstr(r, 8) + (f" (x{m})" if m > 1 else ""))
            for r, m in zip(self.roots, self.multiplicities, strict=True)
        )
        return f"DelayRoots(count={self.count} in {self.region}: [{items}])"

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Scatter plot of the roots in the complex plane with the region outlined.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        z = self.as_array()
        ax.plot(z.real, z.imag, "o", ms=4)
        x0, x1, y0, y1 = self.region
        ax.plot([x0, x1, x1, x0, x0], [y0, y0, y1, y1, y0], "k-", lw=0.7)
        ax.axvline(0, color="0.6", lw=0.5)
        ax.set_xlabel("Re p")
        ax.set_ylabel("Im p")
        return ax


@validated
def quasi_polynomial_roots(
    f: Any,
    region: tuple[float, float, float, float],
    variable: sp.Symbol | None = None,
    *,
    dps: int = 30,
    tol: float = 1e-20,
    cluster: float = 1e-6,
) -> DelayRoots:
    """All roots of a quasi-polynomial in a rectangle: certified count, isolation, Newton polish in mpmath.

    Parameters
    ----------
    f : Expr or QuasiPolynomial
        The quasi-polynomial, an expression in one variable such as ``p**2 + rho*p + sigma*exp(-p)`` with numbers
        for the parameters (see :func:`quasi_polynomial`), or an already parsed one.
    region : (re_min, re_max, im_min, im_max)
        The boundary must not pass through a root (a ConvergenceError says so; shift it slightly).
    variable : Symbol, optional
        Default: the only free symbol of ``f``.
    dps : int
        mpmath digits of the Newton polish.
    tol : float
        Required ``|f(root)|`` relative to the size of its terms after polishing.
    cluster : float
        Boxes smaller than this that still hold ``m >= 2`` roots are reported as one root of multiplicity ``m``.

    Returns
    -------
    DelayRoots

    Examples
    --------
    >>> import sympy as sp
    >>> r = quasi_polynomial_roots(p + sp.exp(-p), (-4, 1, -0.3, 8))
    >>> r.count, [mpmath.nstr(z, 6) for z in r.roots]
    (2, ['(-0.318132 + 1.33724j)', '(-2.06228 + 7.58863j)'])
    """
    check_positive("cluster (the distance below which roots count as one multiple root)", cluster)
    q = f if isinstance(f, QuasiPolynomial) else quasi_polynomial(f, variable)
    total, n_eval = _winding(q, _rect_contour(region))
    with mpmath.workdps(dps):
        fm = compile(q.expr, [q.variable], backend="mpmath", dps=dps, check=False).raw
        derivs = [fm]
    found: list[tuple[Any, int]] = []
    stack = [(tuple(region), total)]
    evals = n_eval
    offsets = (0.5123, 0.4789, 0.5461, 0.4532)
    while stack:
        box, n = stack.pop()
        if n == 0:
            continue
        x0, x1, y0, y1 = box
        size = max(x1 - x0, y1 - y0)
        if n == 1 or size < cluster:
            root = _polish(q, derivs, box, n, dps, tol)
            if root is not None:
                found.append((root, n))
                continue
            if size < cluster:
                raise ConvergenceError(f"Newton did not converge to the {n} root(s) certified in the box {box}")
        for off in offsets:
            try:
                if x1 - x0 >= y1 - y0:
                    xm = x0 + off * (x1 - x0)
                    children = [(x0, xm, y0, y1), (xm, x1, y0, y1)]
                else:
                    ym = y0 + off * (y1 - y0)
                    children = [(x0, x1, y0, ym), (x0, x1, ym, y1)]
                c0, e0 = _winding(q, _rect_contour(children[0]))
                evals += e0
                break
            except ConvergenceError:
                continue
        else:
            # the roots sit too close together to separate in double precision: treat them as one cluster
            root = _polish(q, derivs, box, n, dps, tol)
            if root is None:
                raise ConvergenceError(f"cannot split the box {box} away from its {n} roots, nor polish them")
            found.append((root, n))
            continue
        stack.append((children[0], c0))
        stack.append((children[1], n - c0))
    found.sort(key=lambda rm: (-float(rm[0].real), float(rm[0].imag)))
    return DelayRoots(
        roots=tuple(r for r, _ in found),
        multiplicities=tuple(m for _, m in found),
        count=total,
        region=tuple(float(v) for v in region),
        dps=dps,
        evaluations=evals,
    )


def _polish(q: QuasiPolynomial, derivs: list, box: tuple, m: int, dps: int, tol: float) -> Any:
    """Newton from the box center on ``f^(m-1)``; the result must lie in the box (slightly enlarged)."""
    x0, x1, y0, y1 = box
    with mpmath.workdps(dps):
        while len(derivs) <= m:
            k = len(derivs)
            derivs.append(
                compile(sp.diff(q.expr, q.variable, k), [q.variable], backend="mpmath", dps=dps, check=False).raw
            )
        g, dg = derivs[m - 1], derivs[m]
        z = mpmath.mpc(0.5 * (x0 + x1), 0.5 * (y0 + y1))
        for _ in range(200):
            d = dg(z)
            if d == 0:
                return None
            step = g(z) / d
            z -= step
            if abs(step) <= mpmath.mpf(10) ** (-dps + 5) * (1 + abs(z)):
                break
        else:
            return None
        pad = 1e-9 * max(x1 - x0, y1 - y0, 1.0)
        if not (x0 - pad <= float(z.real) <= x1 + pad and y0 - pad <= float(z.imag) <= y1 + pad):
            return None
        scale = q._abs_terms(np.array([complex(z)]))[0]
        if m == 1 and abs(complex(derivs[0](z))) > max(tol, 10.0 ** (-dps + 8)) * scale:
            return None
        return z


@validated
def characteristic_quasipolynomial(
    l01: Any, l11: Any, l21: Any, l02: Any, l12: Any, l22: Any, variable: sp.Symbol = p
) -> sp.Expr:
    """Bulgakov (4.108): ``l01 p^2 + l11 p + l21 + exp(-p) (l02 p^2 + l12 p + l22)`` (time in units of the delay).

    The coefficients are those of (4.101) in the time ``u = t/tau``: ``l0j = k0j``, ``l1j = k1j tau``,
    ``l2j = k2j tau^2`` (4.105), where ``j = 1`` multiplies ``y``, ``y'``, ``y''`` at ``t`` and ``j = 2`` at
    ``t - tau``.

    Parameters
    ----------
    l01 : Expr or float
        Coefficient of ``p^2`` (the undelayed acceleration term).
    l11 : Expr or float
        Coefficient of ``p`` (the undelayed velocity term).
    l21 : Expr or float
        Constant term (the undelayed position term).
    l02 : Expr or float
        Coefficient of ``p^2 exp(-p)`` (the delayed acceleration term).
    l12 : Expr or float
        Coefficient of ``p exp(-p)`` (the delayed velocity term).
    l22 : Expr or float
        Coefficient of ``exp(-p)`` (the delayed position term).
    variable : Symbol, optional
        The variable of the result (default ``p``).

    Examples
    --------
    >>> characteristic_quasipolynomial(1, 0, 0, 0, sp.Symbol("rho"), sp.Symbol("sigma"))
    p**2 + (p*rho + sigma)*exp(-p)
    """
    names = ("l01", "l11", "l21", "l02", "l12", "l22")
    given = (l01, l11, l21, l02, l12, l22)
    l01, l11, l21, l02, l12, l22 = (_checks.expression(n, v, real=True) for n, v in zip(names, given, strict=True))
    s = _checks.symbol("variable", variable)
    return l01 * s**2 + l11 * s + l21 + sp.exp(-s) * (l02 * s**2 + l12 * s + l22)


@validated
def callender_hartree_porter_optimum() -> dict[str, sp.Expr]:
    """Optimal degree of stability of ``gamma^2 + (rho gamma + sigma) exp(-gamma) = 0`` (Bulgakov §4.16).

    The equal-stability curve's cusp ``rho0 = e^{-s}(2s - s^2)``, ``sigma0 = e^{-s} s^2 (1 - s)`` (4.136) has the slope
    of the real-root line ``sigma = rho s - s^2 e^{-s}`` when ``s^2 - 4 s + 2 = 0`` (4.137).

    >>> opt = callender_hartree_porter_optimum()
    >>> opt["s"], [round(float(opt[k]), 6) for k in ("rho", "sigma")]
    (2 - sqrt(2), [0.461159, 0.079122])
    """
    s, w = sp.symbols("s omega", positive=True)
    # complex roots -s +- i w of gamma^2 + (rho gamma + sigma) e^{-gamma}: solve the real/imaginary parts for rho, sigma
    G = sp.expand(-((-s + sp.I * w) ** 2) * sp.exp(-s) * (sp.cos(w) + sp.I * sp.sin(w)), complex=True)
    rho_w = sp.im(G) / w
    sigma_w = sp.re(G) + s * rho_w
    # the equal-stability curve (4.135) near its cusp w -> 0 (4.136), as series in w^2
    r_ser = sp.series(rho_w, w, 0, 4).removeO()
    s_ser = sp.series(sigma_w, w, 0, 4).removeO()
    cusp_rho, cusp_sigma = r_ser.coeff(w, 0), s_ser.coeff(w, 0)
    slope = sp.simplify(s_ser.coeff(w, 2) / r_ser.coeff(w, 2))
    # optimum: the cusp direction equals the slope s of the real-root line sigma = rho s - s^2 e^{-s} (4.134)
    cond = sp.factor(sp.numer(sp.together(slope - s)))
    roots = [r for r in sp.solve(cond, s) if r.is_positive and r < 1]
    if len(roots) != 1:  # pragma: no cover - fixed algebra
        raise ModelError(f"unexpected optimum conditions {cond}")
    s_star = sp.nsimplify(roots[0])
    return {
        "s": s_star,
        "rho": sp.simplify(cusp_rho.subs(s, s_star)),
        "sigma": sp.simplify(cusp_sigma.subs(s, s_star)),
        "cusp_slope": slope,
    }


@validated
def andronov_maier_optimum(rho: Any) -> dict[str, sp.Expr]:
    """Best degree of stability of ``gamma^2 + rho gamma + sigma exp(-gamma) = 0`` for a given ``rho`` (§4.17).

    ``-s`` is then a double real root: ``s* = 1 + rho/2 - sqrt(1 + rho^2/4)`` (4.149), ``sigma* = e^{-s}(rho s - s^2)``
    (4.146).  Derived here from ``f(-s) = f'(-s) = 0``.

    Parameters
    ----------
    rho : float, Rational or Symbol
        The damping ratio ``rho = l1/l0`` (time in units of the delay, (4.141)); a real number or a real symbol.
        ``rho = 0`` gives ``s* = 0``: without damping no gain makes the system asymptotically stable; for
        ``rho < 0`` the best ``s*`` is negative (the rightmost root ``-s*`` stays in the right half-plane).

    Returns
    -------
    dict
        ``{"s": s*, "sigma": sigma*}``: the optimal degree of stability and the gain that achieves it.

    Examples
    --------
    >>> opt = andronov_maier_optimum(sp.Rational(1, 5))
    >>> opt["s"], round(float(opt["sigma"]), 7)
    (11/10 - sqrt(101)/10, 0.009071)
    >>> andronov_maier_optimum(0)
    {'s': 0, 'sigma': 0}
    """
    rho = _checks.expression("rho", rho, real=True)
    s, sig, g = sp.symbols("s sigma gamma")
    f = g**2 + rho * g + sig * sp.exp(-g)
    e1 = sp.solve(f.subs(g, -s), sig)[0]  # f(-s) = 0: sigma = e^(-s) (rho s - s^2)   (4.146)
    # f'(-s) = 0 with that sigma: the quadratic s^2 - (2 + rho) s + rho = 0 (a double root at -s)
    quadratic = sp.Poly(sp.expand(sp.simplify(sp.diff(f, g).subs(g, -s).subs(sig, e1))), s)
    c2, c1, c0 = quadratic.all_coeffs()
    # its smaller root, (4.149) (the discriminant (2 + rho)^2 - 4 rho = 4 + rho^2 is positive for real rho; the
    # larger root's double real root is not the rightmost root)
    s_star = sp.simplify((-c1 - sp.sqrt(c1**2 - 4 * c0 * c2)) / (2 * c2))
    return {"s": s_star, "sigma": sp.simplify(e1.subs(s, s_star))}
