"""Hamilton-Jacobi separation and action-angle variables (Bulgakov (1954), §3.15-3.16, §5.3).

For a conservative H(q, p) = h the characteristic function W(q) solves ``H(q, dW/dq) = h`` (eq. (3.146)).
:func:`separate_hamilton_jacobi` separates cyclic coordinates (``W_j = alpha_j q_j``) and Liouville/Stäckel-type
Hamiltonians (after multiplying by a factor, each coordinate's terms separate; Landau & Lifshitz, §48);
:func:`action_variable` gives the action ``J = (1/2 pi) closed-integral p dq`` of a libration, its inverse
``h(J)`` and Poincaré's frequency ``nu = dh/dJ`` (eqs. (3.148)-(3.151)).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ModelError, ParameterError
from ...numeric import bind

__all__ = [
    "ActionVariable",
    "HamiltonJacobiSeparation",
    "action_variable",
    "action_variable_numeric",
    "separate_hamilton_jacobi",
]


def _momentum_squared(H: sp.Expr, q: sp.Symbol, p: sp.Symbol, h: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """For H = p^2 / (2 mu(q)) + U(q): return (p^2 as a function of q and h, mu(q))."""
    H = sp.expand(sp.sympify(H))
    if H.diff(p, 3) != 0 or sp.simplify(H.diff(p).xreplace({p: 0})) != 0:
        raise ModelError(
            f"action_variable needs H = p^2 / (2 mu(q)) + U(q) (quadratic in p without a linear term); got H = {H}"
        )
    a = sp.simplify(H.diff(p, 2) / 2)  # = 1 / (2 mu)
    U = sp.simplify(H.xreplace({p: 0}))
    return sp.simplify((h - U) / a), sp.simplify(1 / (2 * a))


@dataclass(frozen=True)
class ActionVariable(SymPyPrintable):
    """Action of a one-degree-of-freedom libration and what follows from it.

    Attributes
    ----------
    action : Expr
        ``J(h) = (1/2 pi) closed-integral p dq``.
    energy : Expr or None
        ``h(J)`` when it can be solved for.
    frequency : Expr
        ``nu = dh/dJ = 1 / J'(h)`` (angular frequency of the libration).
    period : Expr
        ``2 pi / nu = 2 pi dJ/dh``.
    energy_symbol : Symbol
        The energy ``h`` in :attr:`action`, :attr:`frequency` and :attr:`period`.
    action_symbol : Symbol
        The action ``J`` in :attr:`energy`.

    Examples
    --------
    >>> import sympy as sp
    >>> q, p = sp.symbols("q p", real=True)
    >>> action_variable(p**2 / 2 + q**2 / 2, q, p).period
    2*pi

    See Also
    --------
    action_variable, action_variable_numeric
    """

    action: sp.Expr
    energy: sp.Expr | None
    frequency: sp.Expr
    period: sp.Expr
    energy_symbol: sp.Symbol
    action_symbol: sp.Symbol

    def __repr__(self) -> str:
        return f"ActionVariable(J = {self.action}, nu = {self.frequency})"

    def _repr_latex_(self) -> str:
        return f"$$J = {sp.latex(self.action)},\\quad \\nu = {sp.latex(self.frequency)}$$"


def _require_libration(phi: sp.Expr, conditions: list) -> None:
    """ModelError when a condition for a bounded (librating) orbit of ``p^2 = phi(q)`` is known to fail; conditions
    whose sign SymPy cannot decide (symbols without assumptions) are taken to hold."""
    for expr, what, *nonstrict in conditions:
        e = sp.simplify(expr)
        fails = e.is_nonnegative is False if nonstrict else e.is_positive is False
        if fails:
            raise ModelError(
                f"the orbit p^2 = {phi} is not a libration ({what}): it is unbound or there is no motion, and has no "
                "action variable; give the energy of a bounded orbit (declare the energy symbol's sign, e.g. "
                "negative=True for a Kepler orbit)"
            )


@validated
def action_variable(
    H: Any, coordinate: sp.Symbol, momentum: sp.Symbol, energy: sp.Symbol | None = None
) -> ActionVariable:
    """Action variable of a libration of ``H = p^2 / (2 mu(q)) + U(q)`` in closed form.

    Two families have closed forms (Goldstein, Classical Mechanics, §10.7-10.8):

    - ``p^2 = alpha + beta q + gamma q^2`` (``gamma < 0``): ``J = (beta^2 - 4 alpha gamma) / (8 (-gamma)^(3/2))``;
    - ``p^2 = A + 2 B / q - C / q^2`` (``A < 0``; the radial Kepler problem): ``J = B / sqrt(-A) - sqrt(C)``.

    Anything else raises :class:`ModelError`; use :func:`action_variable_numeric` then.

    Parameters
    ----------
    H : SymPy expression
        The Hamiltonian, which must have the form ``p^2 / (2 mu(q)) + U(q)`` (quadratic in the momentum, no linear
        term).
    coordinate : sympy.Symbol
        The coordinate ``q`` of the libration.
    momentum : sympy.Symbol
        Its conjugate momentum ``p``.
    energy : sympy.Symbol, optional
        Symbol of the energy ``h`` in the results (a real symbol ``h`` when omitted).

    Examples
    --------
    >>> import sympy as sp
    >>> q, p = sp.symbols("q p", real=True)
    >>> m, w, h = sp.symbols("m omega h", positive=True)
    >>> av = action_variable(p**2 / (2 * m) + m * w**2 * q**2 / 2, q, p, h)
    >>> av.action, av.energy, av.frequency
    (h/omega, J*omega, omega)

    See Also
    --------
    action_variable_numeric, separate_hamilton_jacobi, canonical_transformation
    """
    for name, value in (("coordinate", coordinate), ("momentum", momentum), ("energy", energy)):
        if value is not None and not isinstance(value, sp.Symbol):
            raise ParameterError(f"{name} must be a SymPy Symbol, got {value!r}")
    h = energy if energy is not None else sp.Symbol("h", real=True)
    Jsym = sp.Symbol("J", positive=True)
    q = coordinate
    phi, _ = _momentum_squared(H, q, momentum, h)
    J = None
    poly = sp.Poly(sp.expand(phi), q) if sp.expand(phi).is_polynomial(q) else None
    if poly is not None and poly.degree() == 2:
        gamma, beta, alpha = poly.all_coeffs()
        _require_libration(
            phi,
            [
                (-gamma, "the coefficient of q^2 must be negative"),
                (beta**2 - 4 * alpha * gamma, "p^2 must be positive between two turning points"),
            ],
        )
        J = (beta**2 - 4 * alpha * gamma) / (8 * (-gamma) ** sp.Rational(3, 2))
    else:
        num = sp.expand(sp.cancel(phi * q**2))
        if num.is_polynomial(q) and sp.degree(num, q) == 2:
            A, B2, mC = sp.Poly(num, q).all_coeffs()
            _require_libration(
                phi,
                [
                    (
                        -A,
                        "the constant A in p^2 = A + 2B/q - C/q^2 must be negative (energy below "
                        "the level at infinity)",
                    ),
                    (B2, "B must be positive (an attracting 1/q term)"),
                    (-mC, "C must be >= 0 (no attracting 1/q^2 term: the motion would fall into q = 0)", True),
                    (B2**2 - 4 * A * mC, "p^2 must be positive between two turning points"),
                ],
            )
            J = B2 / 2 / sp.sqrt(-A) - sp.sqrt(-mC)
    if J is None:
        raise ModelError(
            f"no closed form for the action of p^2 = {phi}; use action_variable_numeric with parameter values"
        )
    J = sp.simplify(J)
    dJ = sp.simplify(J.diff(h))
    if dJ == 0:
        raise ModelError("the action does not depend on the energy: not a libration")
    sols = sp.solve(sp.Eq(J, Jsym), h)
    energy_of_action = sp.simplify(sols[0]) if len(sols) == 1 else None
    return ActionVariable(
        action=J,
        energy=energy_of_action,
        frequency=sp.simplify(1 / dJ),
        period=sp.simplify(2 * sp.pi * dJ),
        energy_symbol=h,
        action_symbol=Jsym,
    )


@validated
def action_variable_numeric(
    H: Any,
    coordinate: sp.Symbol,
    momentum: sp.Symbol,
    energy: float,
    values: Mapping[Any, Any],
    turning_points: tuple[float, float],
    *,
    dps: int = 30,
) -> tuple[mpmath.mpf, mpmath.mpf]:
    """``(J, period)`` of a libration at a numeric energy, by Gauss–Legendre quadrature between the turning points.

    ``turning_points`` are guesses of the ends of the libration (``U(q) = h`` there), refined with
    :func:`mpmath.findroot`; the substitution ``q = c + d sin s`` makes both integrands smooth (Gauss-Legendre).
    Raises :class:`ConvergenceError` when the quadrature error estimate exceeds ``10**(5 - dps)``.

    Parameters
    ----------
    H : SymPy expression
        The Hamiltonian, which must have the form ``p^2 / (2 mu(q)) + U(q)`` (quadratic in the momentum, no linear
        term).
    coordinate : sympy.Symbol
        The coordinate ``q`` of the libration.
    momentum : sympy.Symbol
        Its conjugate momentum ``p``.
    energy : float
        The energy ``h`` of the libration, a finite number between the minimum of ``U`` and the level where the motion
        stops being a libration.
    values : mapping of Symbol or name to float
        Numbers for every parameter of ``H`` (keys are symbols or their names; ``{}`` when there are none).
    turning_points : (float, float)
        Guesses of the two ends of the libration, where ``U(q) = h``; refined with ``mpmath.findroot``.
    dps : int, optional
        Working precision in decimal digits, an integer >= 1 (default 30); the quadrature must reach an error estimate
        of ``10**(5 - dps)``.

    Examples
    --------
    The oscillator ``H = (p^2 + q^2)/2`` at ``h = 1/2``: ``J = h = 1/2``, period ``2 pi``.

    >>> import sympy as sp
    >>> q, p = sp.symbols("q p", real=True)
    >>> J, T = action_variable_numeric(p**2 / 2 + q**2 / 2, q, p, 0.5, {}, (-0.9, 0.9))
    >>> round(float(J), 12), round(float(T), 12)
    (0.5, 6.28318530718)

    See Also
    --------
    action_variable
    """
    h = sp.Symbol("h_")
    q = coordinate
    phi, mu = _momentum_squared(bind(H, values), q, momentum, h)
    phi = phi.xreplace({h: sp.Float(energy, dps)})
    with mpmath.workdps(dps):
        f = sp.lambdify(q, phi, "mpmath")
        g = sp.lambdify(q, mu, "mpmath")
        a = mpmath.findroot(f, mpmath.mpf(turning_points[0]))
        b = mpmath.findroot(f, mpmath.mpf(turning_points[1]))
        if a > b:
            a, b = b, a
        c, d = (a + b) / 2, (b - a) / 2

        def at(s):  # q = c + d sin(s) removes the inverse-square-root singularities at the turning points
            x = c + d * mpmath.sin(s)
            return x, d * mpmath.cos(s)

        def dJ(s):
            x, dx = at(s)
            return mpmath.sqrt(max(f(x), 0)) * dx

        def dT(s):
            x, dx = at(s)
            fx = f(x)
            return g(x) * dx / mpmath.sqrt(fx) if fx > 0 else mpmath.mpf(0)

        half = mpmath.pi / 2
        J, errJ = mpmath.quad(dJ, [-half, 0, half], error=True, method="gauss-legendre")
        T, errT = mpmath.quad(dT, [-half, 0, half], error=True, method="gauss-legendre")
        tol = mpmath.mpf(10) ** (5 - dps)
        if errJ > tol * abs(J) or errT > tol * abs(T):
            raise ConvergenceError(
                f"quadrature did not converge (error estimates {errJ}, {errT})", float(max(errJ, errT))
            )
        return J / mpmath.pi, 2 * T


@dataclass(frozen=True)
class HamiltonJacobiSeparation(SymPyPrintable):
    """Additive separation ``W = sum_j W_j(q_j)`` of ``H(q, dW/dq) = h`` (Bulgakov (1954), eq. (3.146)).

    Attributes
    ----------
    constants : dict
        Coordinate -> its separation constant: ``alpha_q`` (the conserved momentum) for a cyclic coordinate,
        ``beta_q`` for a coordinate separated by :func:`separate_hamilton_jacobi`'s Stäckel step (a tuple of
        coordinates when a group of them shares one constant before being separated further).
    momenta : dict
        Momentum -> ``dW/dq`` in terms of its coordinate, the constants and ``h``.
    characteristic_function : Expr
        ``W`` with the quadratures left as unevaluated ``Integral``.
    energy_symbol : Symbol
        ``h``.
    equations : tuple of Eq
        The separated equations, one per coordinate, each in one coordinate and its momentum ``p_j = dW_j/dq_j``
        (the ordinary differential equations of the separation).
    factors : tuple of Expr
        The factors ``Phi`` by which ``H - h`` (then each group) was multiplied to separate (empty when only
        cyclic coordinates were separated).

    Examples
    --------
    >>> import sympy as sp
    >>> q, p = sp.symbols("q p", positive=True)
    >>> separate_hamilton_jacobi(p**2 / 2 + q, [q], [p]).characteristic_function
    Integral(sqrt(2*h - 2*q), q)

    See Also
    --------
    separate_hamilton_jacobi
    """

    constants: dict
    momenta: dict
    characteristic_function: sp.Expr
    energy_symbol: sp.Symbol
    equations: tuple = ()
    factors: tuple = ()

    def __repr__(self) -> str:
        return f"HamiltonJacobiSeparation(W = {self.characteristic_function})"

    def _repr_latex_(self) -> str:
        return "$$" + r",\quad ".join(sp.latex(e) for e in self.equations) + "$$"


@validated
def separate_hamilton_jacobi(
    H: Any,
    coordinates: Sequence[sp.Symbol],
    momenta: Sequence[sp.Symbol],
    energy: sp.Symbol | None = None,
    *,
    factor: Any = None,
) -> HamiltonJacobiSeparation:
    """Additive separation of the Hamilton-Jacobi equation ``H(q, dW/dq) = h`` of a conservative H
    (Bulgakov (1954), §3.16, eqs. (3.145)-(3.147); Landau & Lifshitz, Mechanics, §48).

    Cyclic coordinates get ``W_j = alpha_j q_j``.  The remaining ones are separated Stäckel-fashion: ``H - h`` is
    multiplied by a factor ``Phi(q)`` (``factor=``, or tried automatically: 1 and the reciprocal/denominator of
    each coefficient of ``p_j^2``) and its terms are grouped by the coordinates they involve; each group not
    holding the energy equals a separation constant ``beta``, groups with several coordinates are separated again.
    One coordinate left over gets its momentum from ``H = h`` directly.

    Parameters
    ----------
    H : Expr
        Hamiltonian (no explicit time).
    coordinates, momenta : sequence of Symbol
        The canonical coordinates ``q`` and their conjugate momenta ``p``, as many of each (paired in order).
    energy : Symbol, optional
        The energy constant ``h`` (default ``Symbol("h")``).
    factor : Expr, optional
        The separating factor ``Phi(q)`` (e.g. ``m (xi + eta)`` in parabolic coordinates); tried alone.

    Raises
    ------
    ModelError
        H depends on time, or does not separate: the message names the terms that couple the coordinates for
        each factor tried.

    Examples
    --------
    Kepler's problem in polar coordinates:

    >>> import sympy as sp
    >>> r, th, pr, pth = sp.symbols("r theta p_r p_theta", positive=True)
    >>> m, k = sp.symbols("m k", positive=True)
    >>> sep = separate_hamilton_jacobi(pr**2 / (2 * m) + pth**2 / (2 * m * r**2) - k / r, [r, th], [pr, pth])
    >>> sep.constants
    {theta: alpha_theta}
    >>> sep.momenta[pr]
    sqrt(-alpha_theta**2 + 2*h*m*r**2 + 2*k*m*r)/r

    A non-central term ``c cos(theta) / r^2`` (Landau & Lifshitz, §48): multiplying by ``2 m r^2`` separates it,
    with a separation constant ``beta_theta``:

    >>> c = sp.Symbol("c", positive=True)
    >>> H = pr**2 / (2 * m) + pth**2 / (2 * m * r**2) - k / r + c * sp.cos(th) / r**2
    >>> sep = separate_hamilton_jacobi(H, [r, th], [pr, pth])
    >>> sep.factors, sep.constants
    ((2*m*r**2,), {theta: beta_theta})
    >>> sep.equations[0]
    Eq(2*c*m*cos(theta) + p_theta**2, beta_theta)

    See Also
    --------
    action_variable, HamiltonJacobiSeparation
    """
    from ...symbols import t
    from ._separation import separate

    H = sp.sympify(H)
    if t in H.free_symbols:
        raise ModelError("H depends on time: use S = -h t + W only for conservative H")
    h = energy if energy is not None else sp.Symbol("h", real=True)
    const: dict[Any, sp.Symbol] = {}
    sub = {}
    rest = []
    cyclic: list[sp.Symbol] = []
    equations: list[sp.Eq] = []
    for q, p in zip(coordinates, momenta, strict=True):
        if q not in H.free_symbols:
            a = sp.Symbol(f"alpha_{q.name}", real=True)
            const[q] = a
            sub[p] = a
            cyclic.append(q)
            equations.append(sp.Eq(p, a))
        else:
            rest.append((q, p))
    Hs = H.xreplace(sub)
    mom: dict[sp.Symbol, sp.Expr] = dict(sub)
    used: list[sp.Expr] = []
    if rest:
        separate(Hs, h, rest, factor, equations, const, mom, used)
    W = sp.Add(*(const[q] * q for q in cyclic))
    for q, p in rest:
        W += sp.Integral(mom[p], q)
    return HamiltonJacobiSeparation(
        constants=const,
        momenta=mom,
        characteristic_function=W,
        energy_symbol=h,
        equations=tuple(equations),
        factors=tuple(used),
    )
