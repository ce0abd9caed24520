"""D-partition (Neimark) and discriminant curves (Bulgakov (1954), §8.25–8.27, eqs. (8.157)–(8.179)).

For a characteristic polynomial affine in two real parameters, ``F(λ) = P(λ) μ + Q(λ) ν + R(λ)`` (``P, Q, R`` may have
complex coefficients), the boundary ``T_ε`` where a root crosses ``Re λ = ε`` is, with ``λ = ε + iω``,

``μ = Δμ/Δ,  ν = Δν/Δ``, ``Δ = P1 Q2 - P2 Q1``, ``Δμ = Q1 R2 - Q2 R1``, ``Δν = P2 R1 - P1 R2`` (8.161)–(8.162).

Shading rule: walking along ``T_ε`` towards increasing ``ω``, shade the left side where ``Δ > 0`` and the right side
where ``Δ < 0``; crossing from the unshaded to the shaded side removes one root from ``Re λ > ε`` (two for real
coefficients, whose curve is traversed twice).  One complex parameter ``μ`` is the case ``Q = iP``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from ._root_counts import count_roots_right

__all__ = ["DPartition", "DiscriminantCurve", "d_partition", "discriminant_curve", "vyshnegradsky_diagram"]


def _split_affine(F: sp.Expr, lam: sp.Symbol, params: tuple) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    F = sp.expand(sp.sympify(F))
    if not isinstance(lam, sp.Symbol):
        raise ParameterError(f"var must be a SymPy Symbol (the root variable λ), got {lam!r}")
    parts = []
    for p in params:
        d = sp.expand(sp.diff(F, p))
        if any(sp.diff(d, q) != 0 for q in params):
            raise ParameterError(
                f"the parameter {p} does not enter the characteristic polynomial linearly (D-partition needs "
                f"F = P(λ)·{params[0]} + Q(λ)·{params[-1]} + R(λ)); substitute a new parameter for the nonlinear "
                "combination"
            )
        parts.append(d)
    R = sp.expand(F.subs({p: 0 for p in params}))
    for e in (*parts, R):
        if not e.is_polynomial(lam) or (e.free_symbols - {lam}):
            raise ParameterError(
                f"after removing the parameters {params}, the coefficients must be numbers; free symbols: "
                f"{sorted(map(str, e.free_symbols - {lam}))} (substitute values first)"
            )
    return (parts[0], parts[1] if len(parts) > 1 else sp.I * parts[0], R)


def _coeffs(e: sp.Expr, lam: sp.Symbol, degree: int) -> np.ndarray:
    c = [complex(v) for v in sp.Poly(e, lam).all_coeffs()] if e != 0 else [0j]
    return np.array([0j] * (degree + 1 - len(c)) + c)


@dataclass(frozen=True)
class DPartition(SymPyPrintable):
    """Result of :func:`d_partition`.

    Attributes
    ----------
    P, Q, R : sympy.Expr
        ``F = P μ + Q ν + R`` (for one complex parameter ``Q = iP`` and ``(μ, ν) = (Re μ, Im μ)``).
    var : sympy.Symbol
        ``λ``.
    params : tuple of Symbol
        The parameter symbols (one or two).
    epsilon : float
        The boundary ``Re λ = ε`` (``-δ0`` for a stability-degree region).
    mu, nu, Delta : sympy.Expr
        The boundary ``μ(ω), ν(ω)`` and the Jacobian ``Δ(ω)`` (8.161)–(8.162).
    singular_lines : tuple of (a, b, c, omega)
        Lines ``a μ + b ν + c = 0`` at the singular frequencies ``ω`` (``Δ = Δμ = Δν = 0``, (8.172)), ``ω = ∞``
        for the leading coefficients (8.174).
    real : bool
        All coefficients real (Vyshnegradsky diagram: the curve is traversed twice, jumps of two roots).
    """

    P: sp.Expr
    Q: sp.Expr
    R: sp.Expr
    var: sp.Symbol
    params: tuple
    epsilon: float
    mu: sp.Expr
    nu: sp.Expr
    Delta: sp.Expr
    singular_lines: tuple
    real: bool

    @property
    def omega(self) -> sp.Symbol:
        return sp.Symbol("omega", real=True)

    def curve(self, omega: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(μ, ν, Δ)`` at the given frequencies (NaN where ``Δ = 0``).

        Parameters
        ----------
        omega : float or array_like
            Frequencies ``ω`` (the boundary point is ``λ = ε + iω``); real numbers, any shape.

        Returns
        -------
        mu, nu, Delta : ndarray
            Same shape as ``omega``.
        """
        w = np.asarray(omega, dtype=float)
        f = sp.lambdify(self.omega, (self.mu, self.nu, self.Delta), "numpy")
        with np.errstate(divide="ignore", invalid="ignore"):
            mu, nu, d = (np.broadcast_to(np.asarray(v, dtype=float), w.shape) for v in f(w))
        return mu, nu, d

    def roots_right(self, mu: Any, nu: Any = 0.0) -> Any:
        """Number of roots with ``Re λ > ε`` at parameter points: the region label ``C_ε(j)`` (§8.25).

        Parameters
        ----------
        mu : float or array_like of float
            First parameter (for one complex parameter: its real part).
        nu : float or array_like of float
            Second parameter (for one complex parameter: its imaginary part); broadcast against ``mu``.

        Returns
        -------
        int or ndarray of int
            An int for scalar arguments, else an array of the broadcast shape.  The roots are the eigenvalues of
            the companion matrices (as :func:`numpy.roots`), for a whole grid in one LAPACK call per degree; the
            coefficient arrays of ``P``, ``Q``, ``R`` are computed once per partition.
        """
        cP, cQ, cR = self._coefficient_arrays
        if not (np.all(np.isfinite(np.asarray(mu, dtype=float))) and np.all(np.isfinite(np.asarray(nu, dtype=float)))):
            raise ParameterError(f"roots_right(): mu and nu must be finite numbers, got mu={mu!r}, nu={nu!r}")
        if np.ndim(mu) == 0 and np.ndim(nu) == 0:  # one point: numpy.roots on the cached coefficients
            c = float(mu) * cP + float(nu) * cQ + cR
            nz = np.flatnonzero(c)
            if nz.size == 0:
                raise ParameterError(f"F vanishes identically at ({mu}, {nu})")
            c = c[nz[0] :]
            return int(np.sum(np.roots(c).real > self.epsilon)) if c.size > 1 else 0
        m, n = np.broadcast_arrays(np.asarray(mu, dtype=float), np.asarray(nu, dtype=float))
        c = m.reshape(-1, 1) * cP + n.reshape(-1, 1) * cQ + cR
        try:
            counts = count_roots_right(c, self.epsilon)
        except ParameterError:
            bad = np.flatnonzero(~(c != 0).any(axis=1))[0]
            raise ParameterError(f"F vanishes identically at ({m.flat[bad]}, {n.flat[bad]})") from None
        return counts.reshape(m.shape)

    @functools.cached_property
    def _coefficient_arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Coefficients of ``P``, ``Q``, ``R`` (highest power first, common length) as complex arrays."""
        deg = max(sp.degree(e, self.var) if e != 0 else 0 for e in (self.P, self.Q, self.R))
        return tuple(_coeffs(e, self.var, deg) for e in (self.P, self.Q, self.R))

    def shaded_normal(self, omega: float) -> tuple[np.ndarray, np.ndarray]:
        """Point of ``T_ε`` at ``ω`` and the unit normal pointing to its shaded side (the rule of §8.25).

        Parameters
        ----------
        omega : float
            Frequency ``ω`` of the boundary point; a finite number where ``Δ(ω) != 0`` and the curve is regular.

        Returns
        -------
        point, normal : ndarray, shape (2,)
        """
        h = 1e-6 * max(1.0, abs(omega))
        mu, nu, d = self.curve(np.array([omega - h, omega, omega + h]))
        tangent = np.array([mu[2] - mu[0], nu[2] - nu[0]])
        tangent /= np.linalg.norm(tangent)
        left = np.array([-tangent[1], tangent[0]])
        return np.array([mu[1], nu[1]]), left if d[1] > 0 else -left

    def __repr__(self) -> str:
        return f"DPartition(F = ({self.P})*{self.params[0]} + ({self.Q})*ν + {self.R}, ε={self.epsilon})"

    def _latex(self, printer) -> str:
        return rf"\mu(\omega) = {printer._print(self.mu)},\ \nu(\omega) = {printer._print(self.nu)}"

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(self)}$$"

    def plot(self, *, ax=None, xlim=(-5, 5), ylim=(-5, 5), n_omega: int = 4001, grid: int = 60, hatch_every: int = 80):
        """Boundary ``T_ε`` with its shading ticks, singular lines and region labels ``C_ε(j)`` from root counts.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        xlim, ylim : pair of float, optional
            Range ``(low, high)`` of the first and second parameter shown, ``low < high`` (default (-5, 5)).
        n_omega : int, optional
            Number of frequencies sampled along the boundary (an integer >= 3; ``ω = tan θ`` with ``θ`` uniform).
        grid : int, optional
            Number of grid points per axis at which the roots are counted for the region labels (an integer >= 2).
        hatch_every : int, optional
            A shading tick every ``hatch_every`` boundary samples (an integer >= 1).

        Returns
        -------
        matplotlib Axes
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        mus, nus = np.linspace(*xlim, grid), np.linspace(*ylim, grid)
        counts = self.roots_right(*np.meshgrid(mus, nus))
        ax.contourf(mus, nus, counts, levels=np.arange(counts.max() + 2) - 0.5, cmap="Greens_r", alpha=0.35)
        theta = np.linspace(-np.pi / 2 + 1e-4, np.pi / 2 - 1e-4, n_omega)
        w = np.tan(theta)
        if self.real:
            w = w[w >= 0]
        mu, nu, d = self.curve(w)
        ok = np.isfinite(mu) & np.isfinite(nu) & (np.abs(mu) < 1e3) & (np.abs(nu) < 1e3)
        mu_p, nu_p = np.where(ok, mu, np.nan), np.where(ok, nu, np.nan)
        ax.plot(mu_p, nu_p, "k-", lw=1.5, label=r"$T_\varepsilon$")
        span = 0.03 * max(xlim[1] - xlim[0], ylim[1] - ylim[0])
        for i in range(1, len(w) - 1, hatch_every):
            if ok[i] and xlim[0] < mu[i] < xlim[1] and ylim[0] < nu[i] < ylim[1] and d[i] != 0:
                p, nrm = self.shaded_normal(float(w[i]))
                ax.plot([p[0], p[0] + span * nrm[0]], [p[1], p[1] + span * nrm[1]], "k-", lw=0.8)
        x = np.linspace(*xlim, 2)
        for a, b, c, om in self.singular_lines:
            a, b, c = complex(a).real, complex(b).real, complex(c).real
            if abs(b) > 1e-14:
                ax.plot(x, -(a * x + c) / b, "--", label=f"singular line (ω = {om})")
            elif abs(a) > 1e-14:
                ax.axvline(-c / a, ls="--", label=f"singular line (ω = {om})")
        for j in np.unique(counts):
            iy, ix = np.argwhere(counts == j)[len(np.argwhere(counts == j)) // 2]
            ax.text(mus[ix], nus[iy], f"C({j})", ha="center")
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        ax.set_xlabel(str(self.params[0]) if len(self.params) == 2 else f"Re {self.params[0]}")
        ax.set_ylabel(str(self.params[1]) if len(self.params) == 2 else f"Im {self.params[0]}")
        ax.legend(loc="best", fontsize="small")
        return ax


@validated
def d_partition(F: Any, var: sp.Symbol, params: Any, *, epsilon: Any = 0) -> DPartition:
    """D-partition of the parameter plane by the boundary ``Re λ = ε`` (Neimark; Bulgakov (1954), §8.25–8.26).

    Parameters
    ----------
    F : sympy.Expr
        Characteristic polynomial in ``var``, affine in the parameters (numbers otherwise).
    var : sympy.Symbol
        The root variable ``λ``; must be a SymPy Symbol.
    params : Symbol or pair of Symbols
        Two real parameters ``(μ, ν)``, or one parameter ``μ`` treated as complex (the plane of ``Re μ, Im μ``).
    epsilon : number
        Shift of the imaginary axis; ``ε = -δ0`` gives the region of stability degree ``≥ δ0`` (§8.22, §8.25).

    Returns
    -------
    DPartition

    Raises
    ------
    ParameterError
        When a parameter enters nonlinearly or other symbols remain.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import d_partition
    >>> lam, mu, nu = sp.symbols("lambda mu nu")
    >>> dp = d_partition((lam**2 + lam) * mu + (lam**2 + 1) * nu - lam**2 + 2, lam, (mu, nu))   # Neimark, §8.26
    >>> dp.mu, sp.factor(dp.nu)
    (0, (omega**2 + 2)/((omega - 1)*(omega + 1)))
    >>> dp.roots_right(0, 0), dp.roots_right(1, 1)
    (1, 0)

    See Also
    --------
    discriminant_curve, vyshnegradsky_diagram, hurwitz
    """
    params = (params,) if isinstance(params, sp.Symbol) else tuple(params)
    if len(params) not in (1, 2) or not all(isinstance(p, sp.Symbol) for p in params):
        raise ParameterError(f"params must be one Symbol or a pair of Symbols, got {params!r}")
    P, Q, R = _split_affine(F, var, params)
    eps = sp.nsimplify(epsilon) if not isinstance(epsilon, sp.Basic) else epsilon
    w = sp.Symbol("omega", real=True)
    at = {var: eps + sp.I * w}
    parts = [sp.expand(e.subs(at)) for e in (P, Q, R)]
    (P1, P2), (Q1, Q2), (R1, R2) = [(sp.re(e), sp.im(e)) for e in parts]
    D = sp.expand(P1 * Q2 - P2 * Q1)
    Dmu = sp.expand(Q1 * R2 - Q2 * R1)
    Dnu = sp.expand(P2 * R1 - P1 * R2)
    if D == 0:
        raise ParameterError("P and Q are proportional: the two parameters cannot be separated (Δ ≡ 0)")
    g = sp.gcd(sp.gcd(sp.Poly(D, w), sp.Poly(Dmu, w)), sp.Poly(Dnu, w))
    singular = []
    for om in sp.Poly(g, w).real_roots() if g.degree() > 0 else []:
        vals = [sp.nsimplify(e.subs(w, om)) for e in (P1, Q1, R1)]
        singular.append((*vals, om))
    real = all(sp.im(c) == 0 for e in (P, Q, R) for c in (sp.Poly(e, var).all_coeffs() if e != 0 else [0]))
    if real:
        deg = max(sp.degree(e, var) for e in (P, Q, R) if e != 0)
        lead = [sp.Poly(e, var).coeff_monomial(var**deg) if e != 0 else 0 for e in (P, Q, R)]
        if lead[0] != 0 or lead[1] != 0:
            singular.append((*lead, sp.oo))
        if not any(s[-1] == 0 for s in singular):
            vals = [e.subs(var, eps) for e in (P, Q, R)]
            if vals[0] != 0 or vals[1] != 0:
                singular.append((*vals, 0))
    mu_w = sp.cancel(Dmu / D)
    nu_w = sp.cancel(Dnu / D)
    return DPartition(P, Q, R, var, params, float(eps), mu_w, nu_w, D, tuple(singular), bool(real))


@dataclass(frozen=True)
class DiscriminantCurve(SymPyPrintable):
    """Result of :func:`discriminant_curve`: ``μ(e) = Γμ/Γ``, ``ν(e) = Γν/Γ`` (8.177)–(8.179), a double root ``e``.

    Crossing it changes the number of complex pairs by one; the aperiodic-stability region is ``E(0) ∩ C_0(0)``.

    Attributes
    ----------
    mu, nu : sympy.Expr
        The curve ``μ(e) = Γμ/Γ``, ``ν(e) = Γν/Γ`` as functions of the double root ``e``.
    Gamma : sympy.Expr
        The determinant ``Γ(e) = P(e) Q'(e) - P'(e) Q(e)``.
    e : sympy.Symbol
        The double root ``e`` (real), the curve's parameter.
    """

    mu: sp.Expr
    nu: sp.Expr
    Gamma: sp.Expr
    e: sp.Symbol

    def curve(self, e: Any) -> tuple[np.ndarray, np.ndarray]:
        """``(μ, ν)`` at the given double roots (NaN where ``Γ = 0``).

        Parameters
        ----------
        e : float or array_like
            Values of the double root ``e``; real numbers, any shape.

        Returns
        -------
        mu, nu : ndarray
            Same shape as ``e``.
        """
        f = sp.lambdify(self.e, (self.mu, self.nu), "numpy")
        ev = np.asarray(e, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            mu, nu = (np.broadcast_to(np.asarray(v, dtype=float), ev.shape) for v in f(ev))
        return mu, nu

    def __repr__(self) -> str:
        return f"DiscriminantCurve(mu={self.mu}, nu={self.nu})"

    def plot(self, *, ax=None, e_range=(-10.0, 10.0), n: int = 4001):
        """The discriminant curve (dotted); returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        e_range : pair of float, optional
            Range ``(low, high)`` of the double root ``e`` traced (default (-10, 10)).
        n : int, optional
            Number of points along the curve (an integer >= 2; default 4001).

        Returns
        -------
        matplotlib Axes
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        mu, nu = self.curve(np.linspace(*e_range, n))
        ok = np.isfinite(mu) & np.isfinite(nu) & (np.abs(mu) < 1e3) & (np.abs(nu) < 1e3)
        ax.plot(np.where(ok, mu, np.nan), np.where(ok, nu, np.nan), "b:", label="discriminant curve")
        ax.legend(loc="best", fontsize="small")
        return ax


@validated
def discriminant_curve(F: Any, var: sp.Symbol, params: Any) -> DiscriminantCurve:
    """Curve of double real roots ``λ = e`` (Bulgakov (1954), §8.27, eqs. (8.177)–(8.179)), real coefficients.

    Parameters
    ----------
    F : sympy.Expr
        Characteristic polynomial in ``var`` with real coefficients, affine in the two parameters (numbers
        otherwise).
    var : sympy.Symbol
        The root variable ``λ``; must be a SymPy Symbol.
    params : pair of Symbols
        The two real parameters ``(μ, ν)``; exactly two Symbols.

    Returns
    -------
    DiscriminantCurve

    Raises
    ------
    ParameterError
        When a parameter enters nonlinearly, other symbols remain or ``P`` and ``Q`` are proportional.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import discriminant_curve
    >>> lam, x, y = sp.symbols("lambda x y")
    >>> c = discriminant_curve(lam**3 + x * lam**2 + y * lam + 1, lam, (x, y))      # Vyshnegradsky, §8.26
    >>> [sp.simplify(v.subs(c.e, -1)) for v in (c.mu, c.nu)]                         # the cusp (3, 3)
    [3, 3]

    See Also
    --------
    d_partition, vyshnegradsky_diagram
    """
    params = tuple(params)
    if len(params) != 2:
        raise ParameterError("discriminant_curve needs two real parameters")
    P, Q, R = _split_affine(F, var, params)
    e = sp.Symbol("e", real=True)
    Pe, Qe, Re_ = (x.subs(var, e) for x in (P, Q, R))
    dP, dQ, dR = (sp.diff(x, var).subs(var, e) for x in (P, Q, R))
    G = sp.expand(Pe * dQ - dP * Qe)
    Gmu = sp.expand(Qe * dR - dQ * Re_)
    Gnu = sp.expand(Re_ * dP - dR * Pe)
    if G == 0:
        raise ParameterError("P and Q are proportional: Γ ≡ 0")
    return DiscriminantCurve(sp.cancel(Gmu / G), sp.cancel(Gnu / G), G, e)


@validated
def vyshnegradsky_diagram() -> tuple[DPartition, DiscriminantCurve]:
    """Vyshnegradsky's diagram for ``λ³ + x λ² + y λ + 1`` (Bulgakov (1954), §8.19, §8.26, Figs. 65–67).

    Stability ``x y > 1``; the discriminant curve ``x = (1 + 2δ³)/δ²``, ``y = (2 + δ³)/δ`` (with ``e = -δ``) has its
    cusp at ``(3, 3)`` where ``λ³ + 3λ² + 3λ + 1 = (λ + 1)³``.

    Examples
    --------
    >>> from symosc.linear import vyshnegradsky_diagram
    >>> dp, disc = vyshnegradsky_diagram()
    >>> dp.roots_right(2, 1), dp.roots_right(2, 0.4)
    (0, 2)

    See Also
    --------
    d_partition, discriminant_curve
    """
    lam, x, y = sp.symbols("lambda x y")
    F = lam**3 + x * lam**2 + y * lam + 1
    return d_partition(F, lam, (x, y)), discriminant_curve(F, lam, (x, y))
