"""Averaging: Krylov–Bogoliubov / van der Pol shortened equations (Bulgakov ch. 5 E, ch. 6, §12.11–12.12).

One degree of freedom, ``x'' + f(x, v) = 0`` (autonomous) or ``x'' + f(x, v) = R cos(nu t)`` (forced), with
``v = x'``.  The exact change of variables ``x = a cos(psi)``, ``v = -a w sin(psi)`` (``w`` the comparison frequency,
``w = nu`` when forced, ``psi = nu t - theta``) followed by averaging over ``psi`` gives the shortened equations
(Bulgakov (5.330)–(5.332), (6.15)–(6.16))::

    autonomous:  a' = -a Phi(a),                          psi' = Psi(a)
    forced:      a' = -a Phi(a) + R sin(theta)/(2 nu),    theta' = nu - Psi(a) + R cos(theta)/(2 nu a)

    Phi = -<f(a cos psi, -a w sin psi) sin psi>/(w a),   Psi = w/2 + <f(a cos psi, -a w sin psi) cos psi>/(w a)

where ``<.>`` is the mean over one period.  For polynomial ``f`` the means are computed exactly (harmonic algebra,
no integration); ``sign``/``Abs``/``Heaviside`` of ``x`` and ``v`` are handled by splitting the period into quarters.

Stationary regimes, their stability (``d(a Phi)/da > 0``; forced: the Routh conditions ``M1 > 0, M2 > 0`` of
(6.24)), the resonance (frequency-response) curve ``W(nu, a) = 0`` of (6.21) with its folds (jump frequencies) and
the backbone curve follow.  Plotting helpers live in :mod:`symosc.nonlinear.averaging._numeric`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from ...symbols import sort_symbols, t
from .. import _checks
from . import _trig
from ._numeric import StationaryRegime, a, theta

__all__ = ["AveragedEquations", "StationaryRegime", "averaged_equations", "describing_function"]

_psi = sp.Dummy("psi", real=True)


def _lookup(expr: sp.Expr, name: str, given: sp.Symbol | None) -> sp.Symbol:
    if given is not None:
        if not isinstance(given, sp.Symbol):
            raise ModelError(f"{name}= must be a SymPy Symbol, got {given!r}")
        return given
    found = [s for s in expr.free_symbols if s.name == name]
    if len(found) > 1:
        raise ModelError(f"f contains several different symbols named {name!r}; pass the one you mean as {name}=")
    return found[0] if found else sp.Symbol(name, real=True)


def _const_sign(arg: sp.Expr, u: sp.Symbol, lo: float, hi: float) -> int:
    """Sign of ``arg`` on the open interval (lo, hi) of ``u``; ModelError if it is not constant there."""
    import random

    rng = random.Random(1234)
    others = sorted(arg.free_symbols - {u}, key=lambda s: s.name)
    signs = set()
    for trial in range(3):
        vals = {s: (1.0 if trial == 0 else rng.uniform(0.3, 3.0)) for s in others}
        for frac in (0.13, 0.5, 0.87):
            val = complex(arg.subs(vals).subs(u, lo + frac * (hi - lo)).evalf())
            if abs(val.imag) > 1e-12 * (1 + abs(val.real)):
                raise ModelError(f"sign({arg}) is not real on the averaging cycle")
            signs.add(0 if val.real == 0 else (1 if val.real > 0 else -1))
    if len(signs) != 1:
        raise ModelError(
            f"cannot average exactly: the argument {arg} of sign/Abs/Heaviside changes sign inside a quarter period "
            "(thresholds such as dead zones or saturation are not supported symbolically); approximate f by a "
            "polynomial or average numerically"
        )
    return signs.pop()


def _quarter_sign(u: sp.Symbol, lo: float, hi: float):
    return lambda arg: _const_sign(arg, u, lo, hi)


def _resolve_signs(expr: sp.Expr, sgn) -> sp.Expr:
    """Replace sign/Abs/Heaviside by their constant values on one quarter period."""
    expr = expr.replace(lambda e: isinstance(e, sp.sign), lambda e: sgn(e.args[0]))
    expr = expr.replace(lambda e: isinstance(e, sp.Abs), lambda e: sgn(e.args[0]) * e.args[0])
    return expr.replace(lambda e: isinstance(e, sp.Heaviside), lambda e: sp.Rational(1 + sgn(e.args[0]), 2))


def _piecewise_average(expr: sp.Expr, u: sp.Symbol) -> sp.Expr:
    pi = sp.pi
    total = sp.S.Zero
    for lo, hi in ((-pi, -pi / 2), (-pi / 2, 0), (0, pi / 2), (pi / 2, pi)):
        piece = _resolve_signs(expr, _quarter_sign(u, float(lo), float(hi)))
        val = sp.integrate(sp.expand(piece), (u, lo, hi))
        if val.has(sp.Integral):
            raise ModelError(
                f"cannot average {expr} exactly (SymPy could not integrate it); approximate f by a polynomial"
            )
        total += val
    return sp.simplify(total / (2 * pi))


def _cycle_average(expr: sp.Expr, u: sp.Symbol) -> sp.Expr:
    """Exact mean over one period of ``u``: harmonic algebra when possible, else quarter-period integration."""
    try:
        return _trig.average(expr, u)
    except ModelError:
        pass
    if expr.has(sp.sin, sp.cos, sp.exp, sp.sinh, sp.cosh) and not expr.has(sp.sign, sp.Abs, sp.Heaviside):
        try:  # sin(x), exp(x), ...: Jacobi-Anger (Bessel) series, exact for the mean
            return sp.simplify(_trig.average(_trig.bessel_expand(expr, u), u))
        except ModelError:
            pass
    return _piecewise_average(expr, u)


@validated
def describing_function(g: Any, x: sp.Symbol | None = None, amplitude: sp.Symbol = a) -> sp.Expr:
    """First-harmonic (describing-function) transform ``J(a) = (1/pi) Integral(g(a cos u) cos u, (u, -pi, pi))``.

    Bulgakov (5.274), (5.349), (12.78): ``omega(a)**2 = J(a)/a`` is the averaged frequency of ``x'' + g(x) = 0``.

    Parameters
    ----------
    g : SymPy expression in ``x``
        Polynomial, or with ``sign``/``Abs`` of ``x`` (relays, preloaded springs).
    x : Symbol, optional
        The variable of ``g`` (default: the symbol named ``x``).
    amplitude : Symbol
        The amplitude symbol of the result (default ``a``, positive).

    Examples
    --------
    >>> import sympy as sp
    >>> x, mu = sp.symbols("x mu")
    >>> describing_function(x + mu * x**3)
    3*a**3*mu/4 + a
    >>> b, c = sp.symbols("b c", positive=True)
    >>> describing_function(b * sp.sign(x) + c * x)
    a*c + 4*b/pi
    """
    g, amplitude = _checks.expression("g", g), _checks.symbol("amplitude", amplitude)
    x = _lookup(g, "x", x)
    return sp.expand(2 * _cycle_average(g.xreplace({x: amplitude * sp.cos(_psi)}) * sp.cos(_psi), _psi))


@dataclass(frozen=True)
class AveragedEquations(SymPyPrintable):
    """Shortened (first-order averaged) equations of ``x'' + f(x, v) = R cos(nu t)`` (``R = 0``: autonomous).

    Attributes
    ----------
    f : Expr
        The force function (restoring force plus damping, per unit mass).
    x : Symbol
        Symbol of the coordinate in ``f``.
    v : Symbol
        Symbol of the velocity ``x'`` in ``f``.
    kind : {"autonomous", "forced"}
        Whether a periodic force acts (``"forced"``) or not.
    frequency : Expr
        Comparison frequency ``w`` (``nu`` when forced).
    a_dot, phase_dot : Expr
        Right-hand sides for the amplitude ``a`` and the phase (``psi`` autonomous, ``theta`` forced).
    Phi, Psi : Expr
        Instantaneous damping coefficient and frequency (Bulgakov (5.332), (6.16)); functions of ``a``.
    R, nu : Expr
        Forcing amplitude and frequency (``0`` and ``None`` when autonomous).
    forcing_phase : Expr
        Phase ``gamma`` of the first harmonic ``R cos(nu t + gamma)`` of the forcing (0 for ``R cos(nu t)``); the
        phase ``theta`` is measured from it.
    center : Expr
        Center ``q*(a)`` of the oscillation, ``x = q* + a cos(psi)`` (Bulgakov (5.345)); 0 unless
        ``averaged_equations(..., center=True)``.
    amplitude : Symbol
        Symbol of the amplitude ``a`` in the equations (positive).
    phase : Symbol
        Symbol of the phase ``theta`` in the forced equations (real).
    """

    f: sp.Expr
    x: sp.Symbol
    v: sp.Symbol
    kind: str
    frequency: sp.Expr
    Phi: sp.Expr
    Psi: sp.Expr
    R: sp.Expr = sp.S.Zero
    nu: sp.Expr | None = None
    forcing_phase: sp.Expr = sp.S.Zero
    center: sp.Expr = sp.S.Zero
    amplitude: sp.Symbol = a
    phase: sp.Symbol = field(default=theta)

    # ------------------------------------------------------------------ symbolic objects
    @property
    def centre(self) -> sp.Expr:
        """Deprecated alias of :attr:`center`."""
        from ..._deprecation import warn_deprecated

        warn_deprecated("AveragedEquations.centre", "AveragedEquations.center")
        return self.center

    @property
    def a_dot(self) -> sp.Expr:
        """Right-hand side of ``da/dt``."""
        if self.kind == "autonomous":
            return sp.expand(-a * self.Phi)
        return sp.expand(-a * self.Phi) + self.R * sp.sin(theta) / (2 * self.nu)

    @property
    def phase_dot(self) -> sp.Expr:
        """Right-hand side of the phase equation (``dpsi/dt`` autonomous, ``dtheta/dt`` forced)."""
        if self.kind == "autonomous":
            return self.Psi
        return sp.expand(self.nu - self.Psi) + self.R * sp.cos(theta) / (2 * self.nu * a)

    @property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """Free parameter symbols (the amplitude and phase excluded)."""
        syms = set().union(*(sp.sympify(e).free_symbols for e in (self.a_dot, self.phase_dot)))
        return sort_symbols(syms - {a, theta})

    @property
    def frequency_squared(self) -> sp.Expr:
        """Describing-function frequency ``w(a)^2 = J(a)/a = 2 w Psi - w^2`` (Bulgakov (5.347)); for a conservative
        ``f`` it does not depend on the comparison frequency ``w``."""
        return sp.simplify(2 * self.frequency * self.Psi - self.frequency**2)

    @cached_property
    def W(self) -> sp.Expr:
        """Resonance-curve function ``W = a^2 (Phi^2 + (Psi - nu)^2) - R^2/(4 nu^2)`` (6.21); ``W = 0`` on the curve."""
        self._need_forced("W")
        return a**2 * (self.Phi**2 + (self.Psi - self.nu) ** 2) - self.R**2 / (4 * self.nu**2)

    @cached_property
    def M1(self) -> sp.Expr:
        """``M1 = Phi + d(a Phi)/da`` (6.24): minus the trace of the variational matrix."""
        self._need_forced("M1")
        return sp.simplify(self.Phi + sp.diff(a * self.Phi, a))

    @cached_property
    def M2(self) -> sp.Expr:
        """``M2 = Phi d(a Phi)/da + (Psi - nu)(Psi - nu + a dPsi/da)`` (6.24): the variational determinant."""
        self._need_forced("M2")
        d = self.Psi - self.nu
        return sp.simplify(self.Phi * sp.diff(a * self.Phi, a) + d * (d + a * sp.diff(self.Psi, a)))

    @cached_property
    def backbone_equation(self) -> sp.Expr:
        """``Psi(a) - w = 0`` read as an equation for the free-oscillation frequency (the skeleton curve (6.33))."""
        return sp.simplify(self.Psi - self.frequency)

    def cartesian(self) -> tuple[sp.Symbol, sp.Symbol, sp.Expr, sp.Expr]:
        """Van der Pol variables ``X = a cos(theta)``, ``Y = a sin(theta)`` (forced case).

        Returns ``(X, Y, dX/dt, dY/dt)``; for polynomial ``f`` the right-hand sides are polynomials.
        """
        self._need_forced("cartesian()")
        X, Y = sp.symbols("X Y", real=True)
        r = sp.sqrt(X**2 + Y**2)
        ad = self.a_dot.subs({sp.sin(theta): Y / a, sp.cos(theta): X / a})
        td = self.phase_dot.subs({sp.sin(theta): Y / a, sp.cos(theta): X / a})
        xd = ad * X / a - Y * td
        yd = ad * Y / a + X * td
        xd = sp.expand(sp.simplify(xd.subs(a, r)))
        yd = sp.expand(sp.simplify(yd.subs(a, r)))
        return X, Y, xd, yd

    def hamiltonian(self) -> tuple[sp.Symbol, sp.Symbol, sp.Expr]:
        """Rotating-frame Hamiltonian of the undamped forced system (Bulgakov (6.40)–(6.42)).

        Valid when ``Phi == 0`` (conservative restoring force).  Returns ``(X, Y, H)`` with
        ``dX/dt = dH/dY``, ``dY/dt = -dH/dX``, ``H = (K(a) - R X)/(2 nu)``,
        ``K(a) = Integral(J(s) - nu^2 s, (s, 0, a))``
        and ``J(a) = 2 a nu (Psi - nu/2)`` the describing function.
        """
        self._need_forced("hamiltonian()")
        if sp.simplify(self.Phi) != 0:
            raise ModelError("hamiltonian() needs a conservative restoring force (Phi == 0); this system is damped")
        X, Y = sp.symbols("X Y", real=True)
        s = sp.Dummy("s", positive=True)
        J = sp.expand(2 * a * self.nu * (self.Psi - self.nu / 2))
        K = sp.integrate((J - self.nu**2 * a).subs(a, s), (s, 0, a))
        H = (K.subs(a, sp.sqrt(X**2 + Y**2)) - self.R * X) / (2 * self.nu)
        return X, Y, sp.expand(H)

    def _need_forced(self, what: str) -> None:
        if self.kind != "forced":
            raise ModelError(f"{what} is defined for forced systems; pass forcing= to averaged_equations")

    # ------------------------------------------------------------------ stationary regimes (autonomous)
    def stationary(self, values: dict | None = None) -> tuple[StationaryRegime, ...]:
        """Stationary regimes of the autonomous shortened equations: ``a Phi(a) = 0`` (Bulgakov §5.28).

        With ``values=None`` the amplitudes are solved symbolically; otherwise numerically (all positive roots).
        Stability: ``d(a Phi)/da > 0`` (5.341)–(5.342).  The equilibrium ``a = 0`` is listed first when
        ``a Phi`` vanishes there.

        Parameters
        ----------
        values : mapping of Symbol or symbol name to number, optional
            Values of every free parameter of the equations (keys are symbols or their names); a missing one
            raises ParameterError. Omitted: the amplitudes are solved symbolically.

        Examples
        --------
        >>> import sympy as sp
        >>> x, v = sp.symbols("x v", real=True)
        >>> eps = sp.Symbol("epsilon", positive=True)
        >>> avg = averaged_equations(x - eps * (1 - x**2) * v)
        >>> avg.a_dot
        -a**3*epsilon/8 + a*epsilon/2
        >>> [r.amplitude for r in avg.stationary()], [r.stable for r in avg.stationary()]
        ([0, 2], [False, True])
        """
        if self.kind != "autonomous":
            raise ModelError("stationary() is for autonomous systems; use steady_states(values, nu) when forced")
        from ._numeric import autonomous_stationary

        return autonomous_stationary(self, values)

    # ------------------------------------------------------------------ numerics (forced and autonomous)
    def envelope(self, a0: float, t_eval: Any, values: dict, theta0: float = 0.0, rtol: float = 1e-10) -> Any:
        """Integrate the shortened equations numerically from ``a(0) = a0`` (and ``theta(0) = theta0`` if forced).

        Returns an array of shape ``(len(t_eval),)`` (autonomous: ``a``) or ``(2, len(t_eval))`` (forced: a, theta).

        Parameters
        ----------
        a0 : float
            Initial amplitude ``a(0)``; a positive number.
        t_eval : array_like of float
            Times at which the solution is returned, ascending and starting at or after 0 (integration runs from 0
            to the last one).
        values : mapping of Symbol or symbol name to number
            Values of every free parameter of the equations (keys are symbols or their names); a missing one
            raises ParameterError.
        theta0 : float, optional
            Initial phase ``theta(0)`` in radians (forced case; default 0).
        rtol : float, optional
            Relative tolerance of the integration, a positive number (default 1e-10).
        """
        from ._numeric import integrate_shortened

        return integrate_shortened(self, a0, t_eval, values, theta0, rtol)

    def steady_states(self, values: dict, nu: float | None = None) -> tuple:
        """Steady forced responses at the forcing frequency ``nu``: all roots of ``W = 0`` with stability.

        ``nu`` may be omitted when the equations were built with a numeric forcing frequency.

        Returns a tuple of :class:`~symosc.nonlinear.SteadyState`, ascending in amplitude.

        Parameters
        ----------
        values : mapping of Symbol or symbol name to number
            Values of every free parameter except ``nu`` (keys are symbols or their names); a missing one raises
            ParameterError, and the forcing amplitude must be nonzero.
        nu : float, optional
            Forcing frequency; a positive finite number, required unless the equations were built with a numeric
            ``nu`` (then it must equal that number).
        """
        self._need_forced("steady_states()")
        from ._numeric import steady_states

        return steady_states(self, values, nu)

    def frequency_response(self, values: dict, nu_range: tuple[float, float], n: int = 400, a_max=None):
        """Resonance curve over ``nu_range``: every branch, its stability and the fold (jump) points.

        Returns a :class:`~symosc.nonlinear.FrequencyResponse`.

        Parameters
        ----------
        values : mapping of Symbol or symbol name to number
            Values of every free parameter except ``nu`` (keys are symbols or their names); a missing one raises
            ParameterError, and the forcing amplitude must be nonzero.
        nu_range : tuple of float
            ``(lo, hi)``: the forcing-frequency interval sampled, with ``0 < lo < hi`` finite.
        n : int, optional
            Number of equally spaced frequencies sampled, an integer >= 3 (default 400).
        a_max : float, optional
            Largest amplitude searched when ``W`` is not a polynomial in ``a``; a positive number (default: twice
            the largest amplitude where ``W <= 0`` on a wide scan).
        """
        self._need_forced("frequency_response()")
        from ._numeric import frequency_response

        return frequency_response(self, values, nu_range, n, a_max)

    def backbone(self, values: dict, amplitudes: Any) -> Any:
        """Backbone (skeleton) curve: free-oscillation frequency ``w(a)`` solving ``Psi(a; w) = w`` (6.33).

        Parameters
        ----------
        values : mapping of Symbol or symbol name to number
            Values of every free parameter except ``nu`` and ``a`` (keys are symbols or their names); a missing one
            raises ParameterError.
        amplitudes : float or array_like of float
            Amplitudes ``a`` at which to evaluate the backbone frequency; positive numbers.

        Returns
        -------
        ndarray
            The frequency at each amplitude (NaN where no positive real frequency exists).
        """
        from ._numeric import backbone

        return backbone(self, values, amplitudes)

    # ------------------------------------------------------------------ display
    def __repr__(self) -> str:
        ph = "psi'" if self.kind == "autonomous" else "theta'"
        return f"AveragedEquations({self.kind}: a' = {self.a_dot}, {ph} = {self.phase_dot})"

    def _repr_latex_(self) -> str:
        ph = r"\dot\psi" if self.kind == "autonomous" else r"\dot\theta"
        return rf"$\dot a = {sp.latex(self.a_dot)},\quad {ph} = {sp.latex(self.phase_dot)}$"


def _first_harmonic(forcing: sp.Expr, nu: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """First harmonic ``R cos(nu t + gamma)`` of a ``2 pi/nu``-periodic forcing expression in ``t``."""
    vt = sp.Dummy("vt", real=True)
    if not forcing.has(t):
        raise ModelError("forcing must be a number/symbol (the amplitude R of R*cos(nu*t)) or an expression in t")
    expr = forcing.subs(t, vt / nu)
    expr = expr.replace(lambda e: isinstance(e, (sp.cos, sp.sin)), lambda e: e.func(sp.expand(e.args[0])))
    try:
        c0, harm = _trig.real_harmonics(expr, vt)
    except ModelError as exc:
        raise ModelError(f"forcing must be a trigonometric polynomial in nu*t: {exc}") from None
    if sp.simplify(c0) != 0:
        raise ModelError(f"forcing has a constant part {c0}; shift x so that the mean force is zero")
    A1, B1 = harm.get(1, (sp.S.Zero, sp.S.Zero))
    if B1 == 0:
        return A1, sp.S.Zero
    return sp.sqrt(A1**2 + B1**2), sp.atan2(-B1, A1)


@validated
def averaged_equations(
    f: Any,
    *,
    forcing: Any = None,
    nu: Any = None,
    omega: Any = None,
    x: sp.Symbol | None = None,
    v: sp.Symbol | None = None,
    center: bool = False,
) -> AveragedEquations:
    """Shortened (first-order averaged) equations of ``x'' + f(x, v) = forcing`` (Bulgakov §5.26, §6.1).

    Parameters
    ----------
    f : SymPy expression in ``x`` and ``v`` (= x')
        Restoring force plus damping per unit mass, e.g. ``x + mu*x**3 + 2*zeta*v``.  Exact for polynomials;
        ``sign``/``Abs``/``Heaviside`` of ``x`` or ``v`` are supported (Coulomb friction, relays).
    forcing : expression, optional
        ``R`` (the amplitude of ``R*cos(nu*t)``) or a ``2 pi/nu``-periodic expression in ``symosc.t`` whose first
        harmonic ``R cos(nu t + gamma)`` is used (phases are then measured from it).  ``None``: autonomous.
    nu : Symbol or number, optional
        Forcing frequency (default: the positive symbol ``nu``).
    omega : expression, optional
        Comparison frequency of the autonomous case (default ``sqrt(df/dx(0, 0))``).
    x, v : Symbol, optional
        The symbols used in ``f`` (default: those named ``x`` and ``v``).
    center : bool
        Oscillate about the center ``q*(a)`` solving ``<f(q* + a cos psi, ...)> = 0`` (5.345) instead of 0: needed
        for asymmetric restoring forces (e.g. ``exp(x) - 1``); the result's ``center`` holds ``q*(a)``.

    Returns
    -------
    AveragedEquations

    Raises
    ------
    ModelError
        If ``f`` cannot be averaged exactly, if the forcing has a constant part, or if no comparison frequency
        can be inferred.

    See Also
    --------
    describing_function
    averaged_equations_ndof
    harmonic_linearization

    Examples
    --------
    >>> import sympy as sp
    >>> x, v = sp.symbols("x v", real=True)
    >>> mu, zeta, R = sp.symbols("mu zeta R", positive=True)
    >>> avg = averaged_equations(x + mu * x**3 + 2 * zeta * v, forcing=R)
    >>> avg.Phi, sp.expand(avg.Psi)
    (zeta, 3*a**2*mu/(8*nu) + nu/2 + 1/(2*nu))
    """
    f = sp.sympify(f)
    x = _lookup(f, "x", x)
    v = _lookup(f, "v", v)
    if forcing is None:
        kind = "autonomous"
        if omega is None:
            k = sp.diff(f, x).subs({x: 0, v: 0})
            if k.has(sp.nan, sp.zoo) or (k.is_number and not k > 0) or k.is_nonpositive:
                raise ModelError(
                    f"cannot infer the comparison frequency: df/dx at rest is {k}; pass omega= (e.g. the "
                    "frequency at the design amplitude)"
                )
            omega = sp.sqrt(k)
        w = sp.sympify(omega)
        R, gamma, nu_ = sp.S.Zero, sp.S.Zero, None
    else:
        kind = "forced"
        nu_ = sp.Symbol("nu", positive=True) if nu is None else sp.sympify(nu)
        if nu_.is_number and not nu_ > 0:
            raise ParameterError(f"nu must be positive, got {nu_}")
        forcing = sp.sympify(forcing)
        if forcing.has(t):
            R, gamma = _first_harmonic(forcing, nu_)
        else:
            R, gamma = forcing, sp.S.Zero
        w = nu_
    if f.has(t):
        raise ModelError("f must not depend on t explicitly; put the periodic force into forcing=")
    qstar = _center(f, x, v, w) if center else sp.S.Zero
    sub = {x: qstar + a * sp.cos(_psi), v: -a * w * sp.sin(_psi)}
    fs = f.xreplace(sub)
    s_avg = _cycle_average(fs * sp.sin(_psi), _psi)
    c_avg = _cycle_average(fs * sp.cos(_psi), _psi)
    Phi = sp.expand(-s_avg / (w * a))
    Psi = sp.expand(w / 2 + c_avg / (w * a))
    return AveragedEquations(
        f=f, x=x, v=v, kind=kind, frequency=w, Phi=Phi, Psi=Psi, R=R, nu=nu_, forcing_phase=gamma, center=qstar
    )


def _center(f: sp.Expr, x: sp.Symbol, v: sp.Symbol, w: sp.Expr) -> sp.Expr:
    """Center ``q*(a)`` of the oscillation: ``<f(q* + a cos psi, -a w sin psi)> = 0`` (5.345), the branch with
    ``q*(0) = 0``."""
    qs = sp.Dummy("qstar", real=True)
    mean = _cycle_average(f.xreplace({x: qs + a * sp.cos(_psi), v: -a * w * sp.sin(_psi)}), _psi)
    if sp.simplify(mean.subs(qs, 0)) == 0:
        return sp.S.Zero
    sols = sp.solve(mean, qs)
    good = []
    for sol in sols:
        at0 = sp.simplify(sol.subs(a, 0))
        if at0.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            try:
                at0 = sp.limit(sol, a, 0, "+")
            except (NotImplementedError, ValueError):  # pragma: no cover - exotic branches
                continue
        if at0 == 0:
            good.append(sp.simplify(sp.expand_log(sol, force=True)))
    if len(good) != 1:
        raise ModelError(f"cannot single out the center q*(a) from <f> = 0 (solutions {sols}); pass center=False")
    return good[0]
