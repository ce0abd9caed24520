"""Dynamic vibration absorber (Frahm 1909; Den Hartog 1928), after Bulgakov (1954), §9.41–9.42.

Main system (mass ``M``, stiffness ``C``) with an absorber (mass ``m``, stiffness ``c``) and a damper of force
``2 m β (ẏ2 - ẏ1)``, forced by ``P sin νt`` on the main mass.  In dimensionless form (``ω_M = sqrt(C/M) = 1``):
mass ratio ``μ = m/M``, tuning ``f = ω_m/ω_M``, damping ratio ``ζ = β/ω_M``, forcing ratio ``g = ν/ω_M``.
The amplification of the main mass is eq. (9.596):

``R1² = [(f² - g²)² + 4ζ²g²] / {[g⁴ - (1 + f² + μf²)g² + f²]² + 4ζ²g²[1 - (1 + μ)g²]²}``.

>>> from symosc.networks import absorber_optimum
>>> absorber_optimum("mu")
(1/(mu + 1), sqrt(6)*sqrt(mu)/(4*(mu + 1)**(3/2)))
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_positive, validated
from ...errors import ConvergenceError, ParameterError

__all__ = [
    "Absorber",
    "HInfinityOptimum",
    "absorber_fixed_points",
    "absorber_hinf_optimum",
    "absorber_optimum",
    "amplification_squared",
]

MU, F, X, ZETA = sp.symbols("mu f x zeta", positive=True)


@validated
def amplification_squared(mu: Any = MU, f: Any = F, zeta: Any = ZETA, g: Any = None) -> sp.Expr:
    """``R1²`` of eq. (9.596) as a SymPy expression (in ``x = g²`` when ``g`` is None).

    Parameters
    ----------
    mu : number or SymPy expression, optional
        Mass ratio ``μ = m/M``, which must be positive (a number or a positive symbol; the symbol ``mu`` by default).
    f : number or SymPy expression, optional
        Tuning ``f = ω_m/ω_M``, which must be positive (the symbol ``f`` by default).
    zeta : number or SymPy expression, optional
        Damping ratio ``ζ = β/ω_M``, which must be non-negative (the symbol ``zeta`` by default).
    g : number or SymPy expression, optional
        Forcing ratio ``g = ν/ω_M``; when omitted the result is a function of ``x = g²`` (the symbol ``x``).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import amplification_squared
    >>> amplification_squared(zeta=0, f=1, mu=sp.Rational(1, 10), g=1)     # perfect tuning: R1 = 0 at g = f
    0

    See Also
    --------
    Absorber, absorber_fixed_points
    """
    mu, f, zeta = sp.sympify(mu), sp.sympify(f), sp.sympify(zeta)
    x = X if g is None else sp.sympify(g) ** 2
    num = (f**2 - x) ** 2 + 4 * zeta**2 * x
    den = (x**2 - (1 + f**2 + mu * f**2) * x + f**2) ** 2 + 4 * zeta**2 * x * (1 - (1 + mu) * x) ** 2
    return num / den


@validated
def absorber_fixed_points(mu: Any = MU, f: Any = F) -> list:
    """The forcing ratios² ``x = g²`` through which every curve ``R1(g; ζ)`` passes (eq. (9.600)).

    ``R1²`` is a linear-fractional function of ``ζ²``, independent of it where ``A/C = B/D``; the non-trivial
    branch is the quadratic ``(μ + 2)x² - 2(1 + f²(1 + μ))x + 2f² = 0``.

    Parameters
    ----------
    mu : number or SymPy expression, optional
        Mass ratio ``μ = m/M``, which must be positive (a number or a positive symbol; the symbol ``mu`` by default).
    f : number or SymPy expression, optional
        Tuning ``f = ω_m/ω_M``, which must be positive (the symbol ``f`` by default).

    Examples
    --------
    >>> from symosc.networks import absorber_fixed_points
    >>> [round(float(v), 6) for v in absorber_fixed_points(0.1, 0.9)]     # T9
    [0.701909, 1.099043]

    See Also
    --------
    absorber_optimum
    """
    quad = _fixed_point_polynomial()
    sols = sp.solve(quad.subs({MU: sp.sympify(mu), F: sp.sympify(f)}), X)
    return sorted(sols, key=lambda s: sp.N(s)) if all(s.is_number for s in sols) else sols


@cache
def _fixed_point_polynomial() -> sp.Expr:
    A = (F**2 - X) ** 2
    C = (X**2 - (1 + F**2 + MU * F**2) * X + F**2) ** 2
    B = 4 * X
    D = 4 * X * (1 - (1 + MU) * X) ** 2
    # zeta-independence: A D - B C = 0; factor out the trivial branch
    expr = sp.factor(sp.expand(A * D - B * C))
    for factor, _ in sp.factor_list(expr)[1]:
        poly = sp.Poly(factor, X)
        if poly.degree() == 2 and sp.expand(factor.subs(X, 0)) != 0:
            return sp.expand(poly.as_expr() / sp.Poly(factor, X).LC() * (MU + 2))
    raise ArithmeticError("fixed-point quadratic not found")  # pragma: no cover


@cache
def _optimum() -> tuple[sp.Expr, sp.Expr]:
    quad = sp.Poly(_fixed_point_polynomial(), X)
    a2, a1, _ = quad.all_coeffs()
    # equal heights: R1 = 1/|1 - (1+mu)x| at both fixed points (the zeta -> oo curve), one below and one above
    # the locked resonance, so x1 + x2 = 2/(1+mu); Vieta gives the tuning
    f_opt = next(s for s in sp.solve(sp.Eq(-a1 / a2, 2 / (1 + MU)), F) if s.is_positive is not False)
    xs = sp.solve(quad.as_expr().subs(F, f_opt), X)
    A = (F**2 - X) ** 2
    B = 4 * X
    C = (X**2 - (1 + F**2 + MU * F**2) * X + F**2) ** 2
    D = 4 * X * (1 - (1 + MU) * X) ** 2
    zetas = []
    for xi in xs:
        h2 = 1 / (1 - (1 + MU) * xi) ** 2
        # horizontal tangent at the fixed point: (A' + z B')/(C' + z D') = h2, linear in z = zeta^2
        num = (h2 * sp.diff(C, X) - sp.diff(A, X)).subs(F, f_opt).subs(X, xi)
        den = (sp.diff(B, X) - h2 * sp.diff(D, X)).subs(F, f_opt).subs(X, xi)
        zetas.append(num / den)
    zeta2 = sp.factor(sp.simplify((zetas[0] + zetas[1]) / 2))
    return sp.simplify(f_opt), sp.sqrt(zeta2)


@validated
def absorber_optimum(mu: Any = MU) -> tuple[sp.Expr, sp.Expr]:
    """Den Hartog's fixed-point optimum, derived symbolically: ``(f_opt, ζ_opt)``.

    The tuning ``f = ω_m/ω_M`` that makes the two fixed points equally high is ``1/(1 + μ)`` (heights
    ``sqrt(1 + 2/μ)``); the damping that gives a horizontal tangent at the fixed points, averaged over the two,
    is ``ζ = sqrt(3μ/(8(1 + μ)³))``.  Bulgakov (1954), §9.42 quotes the result from Den Hartog; the derivation
    here follows the fixed-point theory (eqs. (9.596)–(9.600)).  The exact H∞ optimum differs slightly; see
    :func:`absorber_hinf_optimum`.

    Parameters
    ----------
    mu : number, str or SymPy expression
        Mass ratio ``m/M`` (a positive number or a symbol).

    Returns
    -------
    tuple of SymPy expressions
        ``(frequency ratio, damping ratio)``.

    Examples
    --------
    >>> from symosc.networks import absorber_optimum
    >>> f, z = absorber_optimum(0.25)
    >>> float(f), round(float(z), 6)
    (0.8, 0.219089)

    See Also
    --------
    absorber_hinf_optimum, Absorber
    """
    mu = sp.sympify(mu)
    if mu.is_positive is False:
        raise ParameterError(f"mu = {mu} must be positive (absorber mass / main mass)")
    f_opt, z_opt = _optimum()
    if mu == MU or isinstance(mu, sp.Symbol):
        return f_opt.subs(MU, mu), z_opt.subs(MU, mu)
    return sp.nsimplify(f_opt.subs(MU, mu)) if mu.is_Rational else f_opt.subs(MU, mu), z_opt.subs(MU, mu)


@dataclass(frozen=True)
class Absorber(SymPyPrintable):
    """A main mass with a damped absorber in dimensionless form (Bulgakov (1954), §9.41–9.42).

    Parameters
    ----------
    mu : float
        Mass ratio ``m/M``.
    frequency_ratio : float
        Tuning ``f = ω_m/ω_M``.
    damping_ratio : float
        ``ζ = β/ω_M`` (damper force ``2mβ(ẏ2 - ẏ1)``); 0 for Frahm's undamped absorber.

    Examples
    --------
    >>> from symosc.networks import Absorber
    >>> a = Absorber(0.1, 0.9, 0.0)
    >>> [round(float(w), 6) for w in a.natural_frequencies()]
    [0.809768, 1.11143]
    >>> float(a.amplification(0.9))      # perfect cancellation at g = f (anti-resonance)
    0.0

    See Also
    --------
    absorber_optimum, absorber_hinf_optimum
    """

    mu: float
    frequency_ratio: float
    damping_ratio: float = 0.0

    def __post_init__(self) -> None:
        for name in ("mu", "frequency_ratio"):
            check_positive(name, getattr(self, name))
        check_positive("damping_ratio", self.damping_ratio, allow_zero=True)

    def amplification(self, g: Any) -> Any:
        """``R1(g)``, main-mass amplification at forcing ratio ``g = ν/ω_M`` (eq. (9.596)); vectorised.

        Parameters
        ----------
        g : float or array_like
            Forcing ratio ``g = ν/ω_M`` (a non-negative number or an array of them; the result has its shape).
        """
        g = np.asarray(g, dtype=float)
        mu, f, z = float(self.mu), float(self.frequency_ratio), float(self.damping_ratio)
        x = g * g
        num = (f * f - x) ** 2 + 4 * z * z * x
        den = (x * x - (1 + f * f + mu * f * f) * x + f * f) ** 2 + 4 * z * z * x * (1 - (1 + mu) * x) ** 2
        return np.sqrt(num / den)

    def natural_frequencies(self) -> tuple[float, float]:
        """Undamped natural frequencies (eq. (9.587)), in units of ``ω_M``."""
        f, mu = float(self.frequency_ratio), float(self.mu)
        a = np.sqrt((1 + f) ** 2 + mu * f * f)
        b = np.sqrt((1 - f) ** 2 + mu * f * f)
        return (0.5 * (a - b), 0.5 * (a + b))

    def peak(self, g_max: float = 4.0, tol: float = 1e-13) -> tuple[float, float]:
        """``(g, R1)`` at the highest resonance peak (dense grid, then golden-section refinement).

        Parameters
        ----------
        g_max : float, optional
            Upper end of the search grid of forcing ratios, which must be positive and above the highest resonance
            (default 4).
        tol : float, optional
            Tolerance on the peak's forcing ratio in the golden-section refinement, which must be positive (default
            1e-13).
        """
        from scipy.optimize import minimize_scalar

        if self.damping_ratio == 0:
            raise ParameterError("the undamped absorber has infinite peaks at its natural frequencies")
        grid = np.linspace(1e-3, g_max, 4001)
        vals = self.amplification(grid)
        best = (0.0, -np.inf)
        for i in np.flatnonzero((vals[1:-1] >= vals[:-2]) & (vals[1:-1] >= vals[2:])) + 1:
            res = minimize_scalar(
                lambda s: -float(self.amplification(s)),
                bounds=(grid[i - 1], grid[i + 1]),
                method="bounded",
                options={"xatol": tol},
            )
            if -res.fun > best[1]:
                best = (float(res.x), float(-res.fun))
        if not np.isfinite(best[1]):
            raise ConvergenceError("no resonance peak found below g_max; increase g_max")
        return best

    def plot(self, g: Any = None, *, ax: Any = None, **kwargs: Any) -> Any:
        """Plot ``R1(g)`` (with the undamped and locked curves for reference); returns the Axes.

        Parameters
        ----------
        g : array_like, optional
            Forcing ratios to plot, finite numbers; ``linspace(0.5, 1.5, 1001)`` when omitted.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from ..._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        g = np.linspace(0.5, 1.5, 1001) if g is None else np.asarray(g, dtype=float)
        ax.plot(g, self.amplification(g), label=f"ζ = {float(self.damping_ratio):.4g}", **kwargs)
        locked = 1 / np.abs(1 - (1 + float(self.mu)) * g**2)
        ax.plot(g, locked, ":", color="0.5", label="ζ → ∞ (locked)")
        ax.set_xlabel("forcing ratio ν/ω_M")
        ax.set_ylabel("amplification R1")
        ax.set_ylim(0, max(3 * float(np.max(self.amplification(g))), 1.0) if self.damping_ratio else 20)
        ax.legend()
        return ax

    def _repr_latex_(self) -> str:
        """Mass ratio, tuning and damping of the absorber (Bulgakov (1954), eq. (9.596))."""
        from ..._printing import latex_value

        return (
            rf"$\mu = {latex_value(self.mu)},\ f = \omega_m/\omega_M = {latex_value(self.frequency_ratio)},\ "
            rf"\zeta = \beta/\omega_M = {latex_value(self.damping_ratio)}$"
        )


@dataclass(frozen=True)
class HInfinityOptimum(SymPyPrintable):
    """Result of :func:`absorber_hinf_optimum`: tuning, damping, the minimised peak and the fixed-point peak.

    Attributes
    ----------
    mu : float
        Mass ratio ``m/M``.
    frequency_ratio : float
        Optimal tuning ``f = ω_m/ω_M`` (Den Hartog's ``1/(1 + μ)`` when the tuning is kept fixed).
    damping_ratio : float
        Optimal damping ratio ``ζ = β/ω_M``.
    peak : float
        The minimised highest peak of ``R1``.
    fixed_point_peak : float
        The highest peak of ``R1`` at Den Hartog's fixed-point optimum, for comparison (never below :attr:`peak`).
    """

    mu: float
    frequency_ratio: float
    damping_ratio: float
    peak: float
    fixed_point_peak: float


@validated
def absorber_hinf_optimum(mu: float, tune: bool = True, tol: float = 1e-10) -> HInfinityOptimum:
    """Exact H∞ optimum: minimise the highest peak of ``R1`` over damping (and tuning when ``tune``).

    Starts from Den Hartog's fixed-point optimum and minimises the peak with Nelder–Mead; the result's
    ``peak`` is never above ``fixed_point_peak``, the highest peak at Den Hartog's values.

    Parameters
    ----------
    mu : float
        Mass ratio ``m/M``, which must be positive.
    tune : bool, optional
        Whether to optimise the tuning ``f`` together with the damping (default True); False keeps Den Hartog's ``f =
        1/(1 + μ)`` and optimises the damping only.
    tol : float, optional
        Tolerance of the Nelder–Mead minimisation on ``f`` and ``ζ`` (and, relative to the peak, on its value), which
        must be positive (default 1e-10).

    Examples
    --------
    >>> from symosc.networks import absorber_hinf_optimum
    >>> r = absorber_hinf_optimum(0.1, tune=False)
    >>> round(r.damping_ratio, 4), r.peak <= r.fixed_point_peak
    (0.1683, True)

    See Also
    --------
    absorber_optimum, Absorber
    """
    from scipy.optimize import minimize

    mu = float(mu)
    if not mu > 0:
        raise ParameterError(f"mu must be positive, got {mu}")
    f0, z0 = (float(v) for v in absorber_optimum(sp.Float(mu, 30)))
    dh_peak = Absorber(mu, f0, z0).peak()[1]

    def objective(v):
        f, z = (v[0], v[1]) if tune else (f0, v[0])
        if f <= 0 or z <= 0:
            return 1e300
        return Absorber(mu, f, z).peak()[1]

    start = [f0, z0] if tune else [z0]
    res = minimize(objective, start, method="Nelder-Mead", options={"xatol": tol, "fatol": tol * dh_peak})
    f, z = (res.x[0], res.x[1]) if tune else (f0, res.x[0])
    peak = float(res.fun)
    if peak > dh_peak:
        f, z, peak = f0, z0, dh_peak
    return HInfinityOptimum(mu, float(f), float(z), peak, dh_peak)
