"""Dry (Coulomb) friction, alone and with viscous or quadratic drag: exact piecewise solutions and point maps.

Bulgakov §5.6–5.9.  Between two stops of the velocity the equation of motion is smooth, so a motion is a chain of
half-swings; each is solved exactly and joined at the turning points.

* :func:`coulomb_oscillator` — ``x'' + 2 eps x' + k^2 (x + B sign x') = 0`` (linear spring, Coulomb friction, optional
  viscous damping; equivalent to the gyro-pilot with free play, §5.8).  The turning points obey
  ``x_{j+1} = c_j (1 + delta) - delta x_j`` with ``c_j = B sign(x_j)`` and ``delta = exp(-pi eps/omega)``: the amplitude
  drops by ``2B`` per half-swing when ``eps = 0`` (5.68) and by ``a(1 - delta) + B(1 + delta)`` in general (5.98); the
  motion stops, in finite time, at the first turning point inside the dead zone ``|x| <= B``.
* :func:`half_swing_map` — general potential ``V`` with Coulomb friction ``F`` and quadratic drag
  ``m x'' = ... + G x'^2``
  (5.73)–(5.82), (5.106)–(5.109): with ``eps = 2G/m`` the energy equation is linear in ``T`` and the next turning
  point ``-b`` after a turning point ``a`` solves ``Phi(a) = Phi(-b)``, ``Phi(q) = Integral((V'(s) - F) exp(-eps s))``.
* :func:`quadratic_drag_eta`, :func:`quadratic_drag_eta_series`, :func:`quadratic_drag_half_swing_times` — the linear
  spring with quadratic drag in Liebisch's variables (5.114)–(5.124), Tables 3 and 4 of the book.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ..._plotting import plot_method
from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ModelError, ParameterError
from ...numeric._lazy import LazyFunction

__all__ = [
    "CoulombMotion",
    "HalfSwingMap",
    "coulomb_oscillator",
    "half_swing_map",
    "quadratic_drag_eta",
    "quadratic_drag_eta_series",
    "quadratic_drag_half_swing_times",
]


def _num(x: Any, name: str) -> sp.Expr:
    v = sp.sympify(x)
    if not v.is_number or not v.is_real:
        raise ParameterError(f"{name} must be a real number, got {x!r}")
    return v


@dataclass(frozen=True)
class CoulombMotion(SymPyPrintable):
    """Exact motion of ``x'' + 2 eps x' + k^2 (x + B sign x') = 0`` from rest at ``x0``.

    Attributes
    ----------
    turning_points : tuple
        Signed positions ``x_0, x_1, ...`` where the velocity vanishes (exact SymPy numbers when the inputs are
        exact); the last one lies in the dead zone ``|x| <= B``, where the motion stops.
    times : tuple of float
        Times of the turning points (``j pi/omega``).
    B, k, eps, omega, delta
        Dead-zone half-width, undamped and damped frequencies, decrement ``exp(-pi eps/omega)``.
    """

    turning_points: tuple
    times: tuple[float, ...]
    B: Any
    k: Any
    eps: Any
    omega: Any
    delta: Any

    @property
    def amplitudes(self) -> tuple:
        """``|x_j|`` (the book's amplitude sequence a_j)."""
        return tuple(abs(q) for q in self.turning_points)

    @property
    def half_swings(self) -> int:
        """Number of half-swings before the stop."""
        return len(self.turning_points) - 1

    @property
    def stop_time(self) -> float:
        return self.times[-1]

    @property
    def final_position(self) -> Any:
        return self.turning_points[-1]

    def __call__(self, t: Any) -> np.ndarray:
        """Position at times ``t`` (vectorised); after the stop it stays at the final position."""
        t = np.asarray(t, dtype=float)
        tp = np.array([float(q) for q in self.turning_points])
        times = np.array(self.times)
        j = np.clip(np.searchsorted(times, t, side="right") - 1, 0, len(tp) - 1)
        out = np.full(t.shape, tp[-1])
        moving = j < len(tp) - 1
        B, eps, om = float(self.B), float(self.eps), float(self.omega)
        c = B * np.sign(tp[j])
        s = t - times[j]
        x = c + (tp[j] - c) * np.exp(-eps * s) * (np.cos(om * s) + eps / om * np.sin(om * s))
        return np.where(moving, x, out)

    def velocity(self, t: Any) -> np.ndarray:
        """Velocity at times ``t`` (zero after the stop).

        Parameters
        ----------
        t : float or array_like of float
            Time(s) since the start from rest at ``x0``; real numbers >= 0.
        """
        t = np.asarray(t, dtype=float)
        tp = np.array([float(q) for q in self.turning_points])
        times = np.array(self.times)
        j = np.clip(np.searchsorted(times, t, side="right") - 1, 0, len(tp) - 1)
        moving = j < len(tp) - 1
        B, eps, om, k = float(self.B), float(self.eps), float(self.omega), float(self.k)
        c = B * np.sign(tp[j])
        s = t - times[j]
        v = -(tp[j] - c) * np.exp(-eps * s) * (k**2 / om) * np.sin(om * s)
        return np.where(moving, v, 0.0)

    def __repr__(self) -> str:
        pts = ", ".join(f"{float(q):.6g}" for q in self.turning_points[:6])
        more = ", ..." if len(self.turning_points) > 6 else ""
        return (
            f"CoulombMotion({self.half_swings} half-swings, stops at t = {self.stop_time:.6g} "
            f"at x = {float(self.final_position):.6g}; turning points [{pts}{more}])"
        )

    @plot_method
    def plot(self, *, ax: Any = None, n: int = 2000) -> Any:
        """Draw ``x(t)`` with the dead zone shaded.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        n : int, optional
            Number of time samples from 0 to 1.1 times the stop time, an integer >= 2 (default 2000).
        """
        from ..._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        tt = np.linspace(0, self.stop_time * 1.1 + 1e-9, n)
        ax.plot(tt, self(tt))
        ax.axhspan(-float(self.B), float(self.B), color="0.9")
        ax.set_xlabel("t")
        ax.set_ylabel("x")
        return ax


@validated
def coulomb_oscillator(x0: Any, B: Any, k: Any = 1, eps: Any = 0, max_half_swings: int = 1_000_000) -> CoulombMotion:
    """Exact piecewise motion with Coulomb friction (and viscous damping ``2 eps x'``) from rest at ``x0``.

    Bulgakov §5.6–5.7: ``x_{j+1} = B sign(x_j)(1 + delta) - delta x_j`` while ``|x_j| > B``; the period
    ``2 pi/omega``, ``omega = sqrt(k^2 - eps^2)``, does not depend on the friction.

    Parameters
    ----------
    x0 : Expr or float
        Starting position (the motion starts at rest); a real number (exact rationals give exact turning points).
    B : Expr or float
        Dead-zone half-width ``F/k^2`` (Coulomb friction force per unit mass over ``k^2``); a non-negative number.
    k : Expr or float, optional
        Undamped natural frequency; a positive number (default 1).
    eps : Expr or float, optional
        Viscous damping coefficient in ``2 eps x'``; a number with ``0 <= eps < k`` (default 0).
    max_half_swings : int, optional
        Largest number of half-swings computed before ConvergenceError, an integer >= 1 (default 1000000).

    Returns
    -------
    CoulombMotion

    Examples
    --------
    >>> m = coulomb_oscillator(sp.Rational(3, 2), sp.Rational(1, 10))
    >>> m.amplitudes[:4], m.half_swings, m.final_position
    ((3/2, 13/10, 11/10, 9/10), 7, -1/10)
    """
    x0, B, k, eps = (_num(v, n) for v, n in ((x0, "x0"), (B, "B"), (k, "k"), (eps, "eps")))
    if not B >= 0:
        raise ParameterError(f"B (dead-zone half-width F/k^2) must be non-negative, got {B}")
    if not k > 0:
        raise ParameterError(f"k must be positive, got {k}")
    if not 0 <= eps < k:
        raise ParameterError(f"need 0 <= eps < k (oscillatory half-swings), got eps = {eps}, k = {k}")
    if B == 0 and x0 != 0:
        raise ParameterError(
            "B must be > 0 for the motion to stop: without dry friction (B = 0) the half-swings never end"
        )
    if eps == 0 and B > 0 and (abs(x0) - B) / (2 * B) > max_half_swings:  # each half-swing loses exactly 2 B
        raise ConvergenceError(
            f"the motion needs about {float((abs(x0) - B) / (2 * B)):.3g} half-swings (|x0| = {abs(x0)}, B = {B}): "
            f"more than max_half_swings = {max_half_swings}; raise max_half_swings"
        )
    omega = sp.sqrt(k**2 - eps**2)
    delta = sp.exp(-sp.pi * eps / omega) if eps != 0 else sp.S.One
    exact = all(v.is_Rational for v in (x0, B)) and delta == 1
    if exact:  # Fractions: exact and fast
        from fractions import Fraction

        q, Bq, d = Fraction(int(x0.p), int(x0.q)), Fraction(int(B.p), int(B.q)), 1
    else:
        with mpmath.workdps(30):
            q, Bq, d = mpmath.mpf(sp.N(x0, 30)), mpmath.mpf(sp.N(B, 30)), mpmath.mpf(sp.N(delta, 30))
    pts_raw = [q]
    with mpmath.workdps(30):
        while abs(q) > Bq:
            c = Bq if q > 0 else -Bq
            q = c * (1 + d) - d * q
            pts_raw.append(q)
            if len(pts_raw) > max_half_swings:
                raise ConvergenceError(
                    f"more than {max_half_swings} half-swings (B = {B} tiny?); raise max_half_swings"
                )
    if exact:
        pts = [sp.Rational(v.numerator, v.denominator) for v in pts_raw]
    else:
        pts = [sp.Float(mpmath.nstr(v, 30), 30) for v in pts_raw]
    half = math.pi / float(omega)
    return CoulombMotion(
        turning_points=tuple(pts),
        times=tuple(j * half for j in range(len(pts))),
        B=B,
        k=k,
        eps=eps,
        omega=omega,
        delta=delta,
    )


@dataclass(frozen=True)
class HalfSwingMap(SymPyPrintable):
    """Turning-point map of one right-to-left half-swing: from rest at ``a > 0`` to the next rest at ``-b``.

    Call the object with ``a`` to get ``b`` (negative when the motion ends on the starting side; ``None`` if the
    spring cannot overcome friction at ``a``, i.e. it never moves).

    Attributes
    ----------
    q : Symbol
        The coordinate symbol of ``phi`` and ``force``.
    phi : Expr
        The function ``Phi(q) = Integral((V'(s) - F) exp(-eps s), (s, 0, q))`` with ``Phi(a) = Phi(-b)``.
    force : Expr
        The net force ``-V'(q) + F`` at rest just before moving left (the motion starts only where it is negative).
    _phi_num, _force_num : callable
        Internal: compiled numeric versions of ``phi`` and ``force``.
    """

    q: sp.Symbol
    phi: sp.Expr
    force: sp.Expr
    _phi_num: Any
    _force_num: Any

    def __call__(self, a: float) -> float | None:
        from scipy.optimize import brentq

        a = float(a)
        if self._force_num(a) >= 0:  # net force at rest does not push to the left: stuck
            return None
        pa = self._phi_num(a)

        def T(q):  # proportional to the kinetic energy on the way left (positive while moving)
            return self._phi_num(q) - pa

        step = max(abs(a), 1.0) * 1e-3
        q = a - step
        # T(q) < 0 on the way (Phi decreasing from a), find where it returns to zero
        prev = a
        limit = 1e6 * max(1.0, abs(a))
        while abs(q) < limit:
            if T(q) >= 0:
                root = brentq(T, q, prev, xtol=1e-15, rtol=1e-15)
                return -root
            prev, q = q, q - step
            step *= 1.01
        raise ConvergenceError(f"no turning point found after the start at a = {a}: the motion does not stop")

    def sequence(self, a0: float, n: int) -> list[float]:
        """``a0, b1, a2, ...`` for a symmetric system (each half-swing mapped by the same map), up to ``n`` steps.

        The sequence stops early when the motion sticks or ends on the starting side.

        Parameters
        ----------
        a0 : float
            Starting turning point (at rest); a positive number.
        n : int
            Largest number of half-swings, an integer >= 0.

        Returns
        -------
        list of float
            At most ``n + 1`` amplitudes, starting with ``a0``.
        """
        out = [float(a0)]
        for _ in range(n):
            b = self(out[-1])
            if b is None or b <= 0:
                break
            out.append(b)
        return out


@validated
def half_swing_map(V: Any, q: sp.Symbol, *, friction: Any = 0, drag: Any = 0) -> HalfSwingMap:
    """Turning-point map for ``m x'' = -V'(x) + F + G x'^2`` on a right-to-left swing (Bulgakov (5.80), (5.107)).

    Parameters
    ----------
    V : expression in ``q``
        Potential energy per unit mass (e.g. ``1 - cos(q)`` for the pendulum in units of ``g/l``).
    q : Symbol
        The coordinate, the variable of ``V``.
    friction : number
        Coulomb friction force per unit mass ``F >= 0`` (opposes the motion).
    drag : number
        Quadratic drag ``eps = 2G/m >= 0``.

    Returns
    -------
    HalfSwingMap
        ``Phi(q) = Integral((V'(s) - F) exp(-eps s), (s, 0, q))``, so that the next turning point ``-b`` solves
        ``Phi(a) = Phi(-b)``.

    Examples
    --------
    Pendulum with Coulomb friction, ``sin B = 0.1`` (Bulgakov (5.87)):

    >>> x = sp.Symbol("x")
    >>> m = half_swing_map(1 - sp.cos(x), x, friction=sp.Rational(1, 10))
    >>> m.phi
    -x/10 - cos(x) + 1
    >>> round(m(1.0), 6)
    0.770764
    """
    friction, drag = _num(friction, "friction"), _num(drag, "drag")
    if friction < 0 or drag < 0:
        raise ParameterError("friction and drag must be non-negative")
    V = sp.sympify(V)
    extra = V.free_symbols - {q}
    if extra:
        raise ParameterError("substitute values for: " + ", ".join(sorted(s.name for s in extra)))
    s = sp.Dummy("s", real=True)
    integrand = (sp.diff(V, q).subs(q, s) - friction) * sp.exp(-drag * s)
    phi = sp.integrate(integrand, (s, 0, q))
    if phi.has(sp.Integral):
        raise ModelError(f"cannot integrate {integrand} in closed form; use a polynomial or trigonometric V")
    phi = sp.simplify(phi)
    force = -(sp.diff(V, q) - friction)  # force at rest just before moving left is -V' + F
    return HalfSwingMap(
        q=q,
        phi=phi,
        force=force,
        _phi_num=LazyFunction(phi, [q]),
        _force_num=LazyFunction(force, [q]),
    )


def _eta_mp(xi: Any, dps: int) -> Any:
    with mpmath.workdps(dps):
        x = mpmath.mpf(xi)
        rhs = (x + 1) * mpmath.exp(-x)

        def g(e):
            return (1 - e) * mpmath.exp(e) - rhs

        # (1 - e) e^e decreases from 1 (e = 0) to 0 (e = 1): a bracketing solver is safe
        return mpmath.findroot(g, (mpmath.mpf(0), mpmath.mpf(1)), solver="illinois")


@validated
def quadratic_drag_eta(xi: float, dps: int = 30) -> float:
    """Liebisch's turning-point function: the root ``eta in (0, 1)`` of ``(xi+1) e^{-xi} = (1-eta) e^{eta}`` (5.116).

    ``xi = eps a - beta`` is the reduced amplitude; the next reduced amplitude is ``eta`` (Table 3 of the book).

    Parameters
    ----------
    xi : float
        Reduced amplitude ``xi = eps a - beta`` (5.114); a positive finite number.
    dps : int, optional
        Decimal digits of the mpmath root finding, a positive integer (default 30).

    Examples
    --------
    >>> round(quadratic_drag_eta(1.0), 4)
    0.5936
    """
    if not xi > 0 or not math.isfinite(xi):
        raise ParameterError(f"xi must be positive and finite, got {xi}")
    return float(_eta_mp(xi, dps))


@validated
def quadratic_drag_eta_series(order: int) -> list[sp.Rational]:
    """Exact coefficients ``c_1..c_order`` of ``eta = sum c_n xi^n`` (5.123): ``1, -2/3, 4/9, -44/135, ...``.

    Solved order by order from ``f(-eta) = f(xi)``, ``f(x) = (1 + x) e^{-x}``.

    Parameters
    ----------
    order : int
        Number of coefficients (the highest power of ``xi``), an integer >= 1.

    Examples
    --------
    >>> quadratic_drag_eta_series(5)
    [1, -2/3, 4/9, -44/135, 104/405]
    """
    if order < 1:
        raise ParameterError(f"order must be at least 1, got {order}")
    x = sp.Symbol("x")
    N = order + 2
    fx = sp.series((1 + x) * sp.exp(-x), x, 0, N).removeO()
    coeffs = [sp.Integer(1)]
    for n in range(2, order + 1):
        c = sp.Symbol("c")
        eta = sum(ck * x ** (k + 1) for k, ck in enumerate(coeffs)) + c * x**n
        lhs = sp.expand(fx.subs(x, -eta))
        # f(-eta) - f(xi) must vanish through x^(n+1); the x^(n+1) coefficient is linear in c
        eq = sp.expand(lhs - fx).coeff(x, n + 1)
        sol = sp.solve(eq, c)
        if len(sol) != 1:  # pragma: no cover - fixed algebra
            raise ModelError("series reversion failed")
        coeffs.append(sp.Rational(sol[0]))
    return coeffs


@validated
def quadratic_drag_half_swing_times(xi: float, dps: int = 20) -> tuple[float, float]:
    """Durations of the two quarter-swings of a half-swing with quadratic drag (5.124), in units ``sqrt(m/sigma)``.

    ``t1`` runs from the turning point ``xi`` to the spring's rest position, ``t2`` from there to ``-eta``:
    ``t = (1/sqrt2) Integral(dx/sqrt(g(x)))`` with ``g(x) = x + 1 - (xi + 1) e^{x - xi}``.  The inverse-square-root
    endpoint singularities are handled by tanh-sinh quadrature.  Table 4 of the book; small ``xi``: ``(pi/2, pi/2)``.

    Parameters
    ----------
    xi : float
        Reduced amplitude ``xi = eps a - beta`` (5.114) at the start of the half-swing; a positive finite number.
    dps : int, optional
        Decimal digits of the mpmath quadrature, a positive integer (default 20; 10 more are used internally).

    Examples
    --------
    >>> [round(v, 3) for v in quadratic_drag_half_swing_times(1.0)]
    [1.747, 1.475]
    """
    if not xi > 0 or not math.isfinite(xi):
        raise ParameterError(f"xi must be positive and finite, got {xi}")
    with mpmath.workdps(dps + 10):
        X = mpmath.mpf(xi)
        E = _eta_mp(X, dps + 10)

        # x = X - X cos^2(phi) near the turning point xi, x = -E + E sin^2(phi) near -eta: the square-root
        # singularities cancel, and g is written relative to the turning point (expm1) to avoid cancellation
        def f1(phi):
            c, sn = mpmath.cos(phi), mpmath.sin(phi)
            d = -X * c**2
            return 2 * X * sn * c / mpmath.sqrt(d - (X + 1) * mpmath.expm1(d))

        def f2(phi):
            c, sn = mpmath.cos(phi), mpmath.sin(phi)
            h = E * sn**2
            return 2 * E * sn * c / mpmath.sqrt(h - (1 - E) * mpmath.expm1(h))

        t1 = mpmath.quad(f1, [0, mpmath.pi / 2]) / mpmath.sqrt(2)
        t2 = mpmath.quad(f2, [0, mpmath.pi / 2]) / mpmath.sqrt(2)
        return float(t1), float(t2)
