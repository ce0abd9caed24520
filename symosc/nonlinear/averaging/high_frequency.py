"""Motion under high-frequency forcing (Bulgakov's 1940 appendix; Kapitza's pendulum).

Two tools:

* :func:`fast_averaged_system` — the appendix's general scheme for ``dx/dt = F(x) + sum_m (f_m(x) cos(m nu t) +
  phi_m(x) sin(m nu t))``: the shortened (averaged) system ``dX/dt = F(X)`` (first order, (58)), the second-order
  correction ``dX/dt = F + mu F2`` with ``F2 = sum_m (1/(2m)) [(d phi_m/dx) f_m - (d f_m/dx) phi_m]`` and
  ``mu = 1/nu``, and the oscillating part ``x = X + mu sum_m (1/m)(f_m sin(m nu t) - phi_m cos(m nu t))`` (62).
  The Fourier split is exact (harmonic algebra).
* :func:`vibrational_averaging` — mechanical systems ``M q'' = -grad V(q) + Q(q, q') + Phi(q, t)`` with a fast,
  zero-mean generalised force ``Phi``, whose amplitude may grow like ``p^2`` (vibrating supports).  The substitution
  ``y = q' - M^{-1} Integral(Phi dt)`` makes the right-hand sides bounded, and first-order averaging then gives the
  slow equations ``M Q'' = -grad V_eff + <Q>`` with the effective potential
  ``V_eff = V + sum_m (Phi_m^T M^{-1} Phi_m + Psi_m^T M^{-1} Psi_m)/(4 m^2 p^2)`` (derived, not typed in: the module
  averages the transformed equations symbolically and integrates the averaged force back to a potential).
  For the pendulum on a vertically vibrating pivot this recovers Kapitza's condition ``a^2 p^2 > 2 g l``.

Kapitza's result is not in Bulgakov's appendix (it came in 1951); it follows from the appendix's first-order scheme.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ModelError, ParameterError
from ...numeric import bind, compile
from ...symbols import dot, t
from . import _trig

__all__ = [
    "FastAveragedSystem",
    "VibrationalAveraging",
    "fast_averaged_system",
    "vibrational_averaging",
    "vibrational_averaging_of",
    "vibrational_stiffness",
]

_th = sp.Dummy("vartheta", real=True)


def _fast_split(expr: sp.Expr, nu: sp.Expr) -> tuple[sp.Expr, dict[int, tuple[sp.Expr, sp.Expr]]]:
    """Split ``expr(t)`` into its mean and the harmonics of ``nu t`` (exact)."""
    e = sp.sympify(expr).subs(t, _th / nu)
    e = e.replace(lambda z: isinstance(z, (sp.cos, sp.sin)), lambda z: z.func(sp.expand(z.args[0])))
    try:
        return _trig.real_harmonics(e, _th)
    except ModelError as exc:
        raise ModelError(
            f"the right-hand side must depend on t only through cos(k*nu*t), sin(k*nu*t) (integer k): {exc}"
        ) from None


@dataclass(frozen=True)
class FastAveragedSystem(SymPyPrintable):
    """Shortened equations of ``dx/dt = F(x) + sum_m (f_m cos(m nu t) + phi_m sin(m nu t))``.

    Attributes
    ----------
    state : tuple of Symbol
        The state variables ``x``, in the order of the right-hand sides.
    nu : Expr
        Fast frequency; ``mu = 1/nu`` is the small parameter of the appendix.
    mean : Matrix
        ``F(X)``: the first-order shortened right-hand side (58).
    correction : Matrix
        ``F2(X)``: the second-order term; the order-2 system is ``dX/dt = F + F2/nu``.
    harmonics : dict
        ``{m: (f_m, phi_m)}`` as column matrices.
    order : int
        Order of the shortened system (1 or 2) used by :attr:`rhs` and :meth:`solve`.
    """

    state: tuple[sp.Symbol, ...]
    nu: sp.Expr
    mean: sp.Matrix
    correction: sp.Matrix
    harmonics: dict
    order: int

    @property
    def rhs(self) -> sp.Matrix:
        """Right-hand side of the shortened system of the requested order."""
        return self.mean if self.order == 1 else self.mean + self.correction / self.nu

    def oscillating_part(self) -> sp.Matrix:
        """``w(X, t)`` with ``x = X + w``: ``(1/nu) sum_m (1/m)(f_m sin(m nu t) - phi_m cos(m nu t))`` (62)."""
        w = sp.zeros(len(self.state), 1)
        for m, (fm, pm) in self.harmonics.items():
            w += (fm * sp.sin(m * self.nu * t) - pm * sp.cos(m * self.nu * t)) / (m * self.nu)
        return w

    def solve(self, x0: Any, t_eval: Any, values: dict | None = None, rtol: float = 1e-10) -> np.ndarray:
        """Integrate the shortened system and return the reconstructed ``x(t) ~ X(t) + w(X, t)`` (order 2) or
        ``X(t)`` (order 1), shape ``(n, len(t_eval))``.  ``X(0)`` is chosen so that ``x(0) = x0``.

        Parameters
        ----------
        x0 : array_like of float, shape (n,)
            Initial state ``x`` at the first time of ``t_eval``; finite numbers, one per state variable.
        t_eval : array_like of float
            Times at which the solution is returned, ascending; the integration runs from the first to the last.
        values : mapping of Symbol or symbol name to number, optional
            Values of every free parameter (including ``nu`` when it is a symbol; keys are symbols or their names);
            a missing one raises ParameterError.
        rtol : float, optional
            Relative tolerance of the integration, a positive number (default 1e-10).
        """
        from scipy.integrate import solve_ivp
        from scipy.optimize import fsolve

        values = values or {}
        rhs = bind(self.rhs, values)
        w = bind(self.oscillating_part(), values)
        extra = (rhs.free_symbols | w.free_symbols) - set(self.state) - {t}
        if extra:
            raise ParameterError("missing values for: " + ", ".join(sorted(s.name for s in extra)))
        f = compile(rhs, list(self.state), check=False).raw
        wf = compile(w, [*self.state, t], check=False).raw
        n = len(self.state)
        x0 = np.asarray(x0, dtype=float)
        t_eval = np.asarray(t_eval, dtype=float)
        if self.order == 2:
            X0 = fsolve(lambda X: X + np.asarray(wf(*X, t_eval[0])).reshape(n) - x0, x0, xtol=1e-14)
        else:
            X0 = x0
        sol = solve_ivp(
            lambda _t, X: np.asarray(f(*X)).reshape(n),
            (t_eval[0], t_eval[-1]),
            X0,
            t_eval=t_eval,
            rtol=rtol,
            atol=1e-13,
        )
        if not sol.success:
            raise ConvergenceError(f"integration of the shortened system failed: {sol.message}")
        if self.order == 1:
            return sol.y
        corr = np.asarray(wf(*sol.y, t_eval)).reshape(sol.y.shape[1], n).T
        return sol.y + corr

    def __repr__(self) -> str:
        return f"FastAveragedSystem(order={self.order}, dX/dt = {list(self.rhs)})"

    def _repr_latex_(self) -> str:
        return rf"$\dot X = {sp.latex(self.rhs)}$"


@validated
def fast_averaged_system(rhs: Any, state: Any, nu: Any, order: int = 1) -> FastAveragedSystem:
    """Shortened equations of a system with a fast periodic time dependence (Bulgakov's appendix, (54)–(78)).

    Parameters
    ----------
    rhs : sequence of expressions in ``state`` and ``symosc.t``
        ``t`` may appear only through ``cos(k nu t)``, ``sin(k nu t)``.
    state : sequence of Symbol
        The state variables, one per right-hand side.
    nu : Symbol or number
        The fast frequency (``mu = 1/nu`` small).
    order : {1, 2}
        Order of the shortened system: 1 (the mean ``F``) or 2 (with the correction ``F2/nu``).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.symbols import t
    >>> x1, x2, nu = sp.symbols("x1 x2 nu")
    >>> s = fast_averaged_system([-x1 + x2 * sp.cos(nu * t), -x2 + x1 * sp.sin(nu * t)], [x1, x2], nu, order=2)
    >>> list(s.correction)
    [-x1/2, x2/2]
    """
    if order not in (1, 2):
        raise ParameterError(f"order must be 1 or 2, got {order}")
    state = tuple(state)
    if not all(isinstance(s, sp.Symbol) for s in state):
        raise ModelError("state must be a sequence of SymPy Symbols")
    rhs = [sp.sympify(e) for e in (rhs if isinstance(rhs, (list, tuple, sp.MatrixBase)) else [rhs])]
    if len(rhs) != len(state):
        raise ModelError(f"{len(rhs)} right-hand sides for {len(state)} state variables")
    nu = sp.sympify(nu)
    n = len(state)
    means, harm = [], {}
    for j, e in enumerate(rhs):
        f0, hs = _fast_split(e, nu)
        means.append(f0)
        for m, (fm, pm) in hs.items():
            harm.setdefault(m, (sp.zeros(n, 1), sp.zeros(n, 1)))
            harm[m][0][j] = fm
            harm[m][1][j] = pm
    F = sp.Matrix(means)
    xs = sp.Matrix(state)
    F2 = sp.zeros(n, 1)
    for m, (fm, pm) in harm.items():
        F2 += (pm.jacobian(xs) * fm - fm.jacobian(xs) * pm) / (2 * m)
    F2 = F2.applyfunc(sp.expand)
    return FastAveragedSystem(state=state, nu=nu, mean=F, correction=F2, harmonics=harm, order=order)


@dataclass(frozen=True)
class VibrationalAveraging(SymPyPrintable):
    """Slow equations of ``M q'' = -grad V + Q + Phi(q, t)`` with fast zero-mean ``Phi`` (Kapitza averaging).

    Attributes
    ----------
    coordinates : tuple of Symbol
        The generalised coordinates ``q``.
    mass : Matrix
        The mass matrix ``M``.
    potential : Expr
        ``V``.
    effective_potential : Expr or None
        ``V_eff`` with ``-grad V_eff`` equal to the averaged conservative force (``None`` if the averaged force is not
        a gradient, which happens when the fast force is not itself potential).
    vibrational_force : Matrix
        The averaged extra force ``-M <J_U U>`` (``U = M^{-1} Integral(Phi dt)``).
    slow_force : Matrix
        Full right-hand side of ``M Q'' = slow_force(Q, Q')`` (velocities as ``dot(q)`` symbols).
    p : Expr
        Fast frequency.
    """

    coordinates: tuple[sp.Symbol, ...]
    mass: sp.Matrix
    potential: sp.Expr
    effective_potential: sp.Expr | None
    vibrational_force: sp.Matrix
    slow_force: sp.Matrix
    p: sp.Expr

    @property
    def correction(self) -> sp.Expr | None:
        """``V_eff - V``."""
        return None if self.effective_potential is None else sp.simplify(self.effective_potential - self.potential)

    def stiffness(self, point: dict) -> sp.Matrix:
        """Hessian of ``V_eff`` at an equilibrium ``point`` (mapping coordinate -> value).

        Parameters
        ----------
        point : mapping of Symbol or symbol name to Expr
            The equilibrium: a value for each coordinate (keys are the coordinate symbols or their names); other
            symbols stay symbolic.
        """
        if self.effective_potential is None:
            raise ModelError("the averaged force is not potential; linearize slow_force instead")
        q = sp.Matrix(self.coordinates)
        H = sp.hessian(self.effective_potential, q)
        return sp.simplify(
            H.subs({sp.sympify(k) if not isinstance(k, str) else sp.Symbol(k): v for k, v in point.items()})
        )

    def stability_condition(self, point: dict) -> sp.Expr:
        """1-DOF: ``V_eff''(q*)`` (the equilibrium is stable iff it is positive); n-DOF: the Hessian's determinant
        (necessary condition; check all leading minors with :meth:`stiffness`).

        Parameters
        ----------
        point : mapping of Symbol or symbol name to Expr
            The equilibrium: a value for each coordinate (keys are the coordinate symbols or their names).
        """
        H = self.stiffness(point)
        return sp.factor(H[0, 0] if H.shape == (1, 1) else H.det())

    def __repr__(self) -> str:
        return f"VibrationalAveraging(V_eff = {self.effective_potential})"

    def _repr_latex_(self) -> str:
        return rf"$V_{{\mathrm{{eff}}}} = {sp.latex(self.effective_potential)}$"


@validated
def vibrational_averaging(
    coordinates: Any,
    mass: Any,
    potential: Any,
    fast_force: Any,
    p: Any,
    *,
    force: Any = 0,
) -> VibrationalAveraging:
    """Averaged (effective) equations for a mechanical system under fast periodic forcing.

    Parameters
    ----------
    coordinates : Symbol or sequence of Symbol
        The generalised coordinates ``q`` (SymPy Symbols).
    mass : expression or Matrix
        Mass matrix: constant, or ``M(q)`` for one degree of freedom (never dependent on ``t``).
    potential : expression
        ``V(q)``.
    fast_force : expression or sequence
        Fast generalised force ``Phi(q, t)``; ``t`` (``symosc.t``) only through ``cos(k p t)``, ``sin(k p t)``,
        zero mean.  Its amplitude may be large (``~ p^2``).
    p : Symbol or number
        Fast angular frequency.
    force : expression or sequence
        Slow non-potential generalised force ``Q(q, dot(q))`` (e.g. damping), polynomial in the velocities.

    Returns
    -------
    VibrationalAveraging

    Examples
    --------
    Pendulum on a vertically vibrating pivot (``y = a cos(p t)``), angle from the downward vertical:

    >>> import sympy as sp
    >>> from symosc.symbols import t
    >>> th = sp.Symbol("theta")
    >>> m, g, l, a, p = sp.symbols("m g l a p", positive=True)
    >>> fast = m * l * a * p**2 * sp.sin(th) * sp.cos(p * t)
    >>> res = vibrational_averaging(th, m * l**2, -m * g * l * sp.cos(th), fast, p)
    >>> res.correction
    a**2*m*p**2*sin(theta)**2/4
    >>> res.stability_condition({th: sp.pi})
    m*(a**2*p**2 - 2*g*l)/2
    """
    q = tuple(coordinates) if isinstance(coordinates, (list, tuple)) else (coordinates,)
    if not all(isinstance(s, sp.Symbol) for s in q):
        raise ModelError("coordinates must be SymPy Symbols")
    n = len(q)
    M = sp.Matrix(mass) if isinstance(mass, (list, tuple, sp.MatrixBase)) else sp.Matrix([[sp.sympify(mass)]])
    if M.shape != (n, n):
        raise ModelError(f"mass matrix must be {n}x{n}, got {M.shape}")
    if M.has(t):
        raise ModelError("the mass matrix must not depend on t (only the forces may be fast)")
    if n > 1 and any(M.has(s) for s in q):
        raise ModelError(
            "a coordinate-dependent mass matrix is supported for one degree of freedom only (the symbolic averaging "
            "of M(q)^-1 terms blows up for n >= 2); linearize about the equilibrium first"
        )
    V = sp.sympify(potential)
    if V.has(t):
        raise ModelError("the potential must not depend on t; put the fast part into fast_force")
    as_vec = lambda e: sp.Matrix(e if isinstance(e, (list, tuple, sp.MatrixBase)) else [e])  # noqa: E731
    Phi = as_vec(fast_force)
    Q = as_vec(force) if force != 0 else sp.zeros(n, 1)
    if Phi.shape != (n, 1) or Q.shape != (n, 1):
        raise ModelError(f"fast_force and force must have {n} components")
    p = sp.sympify(p)
    qd = tuple(dot(s) for s in q)
    if Q.has(t):
        raise ModelError("force must not depend on t (slow forces only)")
    # U = M^{-1} * (antiderivative of Phi in t, zero mean)
    Minv = M.inv().applyfunc(sp.simplify) if n > 1 else sp.Matrix([[1 / M[0, 0]]])
    G = sp.zeros(n, 1)
    for j in range(n):
        c0, hs = _fast_split(Phi[j], p)
        if sp.simplify(c0) != 0:
            raise ModelError(f"fast_force component {j} has a nonzero mean {c0}; move it into potential/force")
        for m, (fm, pm) in hs.items():
            G[j] += (fm * sp.sin(m * p * t) - pm * sp.cos(m * p * t)) / (m * p)
    U = Minv * G
    Y = sp.Matrix([sp.Dummy(f"y{j}") for j in range(n)])
    qv = sp.Matrix(q)
    # transformed equations: q' = y + U,  M y' = Q(q, y + U) - grad V - M J_U (y + U)   (M dU/dt = Phi cancels)
    Q_sub = Q.subs(dict(zip(qd, list(Y + U), strict=True)))
    rhs_y = Q_sub - sp.Matrix([sp.diff(V, s) for s in q]) - M * U.jacobian(qv) * (Y + U)
    avg = sp.zeros(n, 1)
    for j in range(n):
        e = sp.expand(rhs_y[j].subs(t, _th / p))
        avg[j] = _trig.average(e, _th)
    avg = avg.subs(dict(zip(list(Y), qd, strict=True))).applyfunc(sp.simplify)
    slow = avg
    # the part of the averaged force that does not depend on the velocities and is not -grad V
    vib = avg.subs({v: 0 for v in qd}) + sp.Matrix([sp.diff(V, s) for s in q]) - Q.subs({v: 0 for v in qd})
    vib = vib.applyfunc(sp.simplify)
    # integrate -vib back to a potential (along straight lines from 0); verify it reproduces vib
    W = _line_potential(vib, q)
    ok = W is not None
    V_eff = sp.simplify(V + W) if ok else None
    return VibrationalAveraging(
        coordinates=q,
        mass=M,
        potential=V,
        effective_potential=V_eff,
        vibrational_force=vib,
        slow_force=slow,
        p=p,
    )


def _line_potential(force: sp.Matrix, q: tuple[sp.Symbol, ...]) -> sp.Expr | None:
    """``W`` with ``-grad W = force`` (line integral from 0), or None if ``force`` is not a gradient."""
    lam = sp.Dummy("lam", positive=True)
    W = sp.S.Zero
    for j in range(len(q)):
        W -= sp.integrate(sp.expand(force[j].xreplace({s: lam * s for s in q}) * q[j]), (lam, 0, 1), conds="none")
    W = sp.simplify(sp.trigsimp(W))
    if W.has(sp.Integral) or any(sp.simplify(sp.diff(W, q[j]) + force[j]) != 0 for j in range(len(q))):
        return None
    return W


@validated
def vibrational_averaging_of(system: Any, p: Any = None) -> VibrationalAveraging:
    """:func:`vibrational_averaging` for a mechanics model (``LagrangianSystem`` with ``M(q) q'' = F(q, q', t)``).

    The forcing is split exactly into its mean (slow: gravity, Coriolis, damping) and its harmonics in ``p t``
    (fast: must not depend on the velocities); the slow conservative part is integrated back to a potential.

    Parameters
    ----------
    system : LagrangianSystem
        The mechanics model: any object with ``coordinates``, ``velocities``, ``mass_matrix`` and ``forcing``
        (``M(q) q'' = forcing``), the forcing periodic in ``t`` with frequency ``p``.
    p : Symbol or number, optional
        Fast angular frequency; by default the single symbol named ``p`` in the forcing (ModelError when there is
        none or several).

    Returns
    -------
    VibrationalAveraging

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.models import n_link_pendulum
    >>> res = vibrational_averaging_of(n_link_pendulum(1, inverted=True, pivot="vertical"))
    >>> phi1 = res.coordinates[0]
    >>> sp.factor(res.stability_condition({phi1: 0}))
    m1*(a**2*p**2 - 2*g*l1)/2
    """
    q = tuple(system.coordinates)
    qd = tuple(system.velocities)
    M = sp.Matrix(system.mass_matrix).applyfunc(sp.trigsimp)
    F = sp.Matrix(system.forcing)
    if p is None:
        cands = [s for s in F.free_symbols if s.name == "p"]
        if len(cands) != 1:
            raise ModelError("cannot tell the fast frequency; pass p=")
        p = cands[0]
    slow, fast = sp.zeros(len(q), 1), sp.zeros(len(q), 1)
    for j in range(len(q)):
        c0, hs = _fast_split(sp.expand(F[j]), p)
        slow[j] = sp.simplify(c0)
        for m, (fm, pm) in hs.items():
            if any(fm.has(v) or pm.has(v) for v in qd):
                raise ModelError("the fast force depends on the velocities; this averaging needs Phi(q, t) only")
            fast[j] += fm * sp.cos(m * p * t) + pm * sp.sin(m * p * t)
    V = _line_potential(slow.subs({v: 0 for v in qd}), q)
    if V is None:
        raise ModelError("the slow positional force is not potential; use vibrational_averaging with force=")
    rest = (slow + sp.Matrix([sp.diff(V, s) for s in q])).applyfunc(sp.simplify)
    return vibrational_averaging(list(q), M, V, list(fast), p, force=list(rest) if any(e != 0 for e in rest) else 0)


@validated
def vibrational_stiffness(
    model: Any = None, *, M: Any = None, K0: Any = None, K1: Any = None, p: Any = None
) -> sp.Matrix:
    """Effective stiffness of ``M q'' + (K0 + K1 cos(p t)) q = 0`` after averaging over the fast forcing.

    Pass a linear model (anything with ``.M``, ``.coordinates`` and ``.periodic_stiffness() -> (K0, K1, p)``, e.g.
    ``LagrangianSystem.linearize()``) or the matrices.  The result is the Hessian of the effective potential of
    :func:`vibrational_averaging` (``V = q^T K0 q/2``, fast force ``-K1 q cos(p t)``), i.e.
    ``K0 + K1^T M^{-1} K1/(2 p^2)`` for symmetric ``K1``; the equilibrium is stable (first approximation) iff it is
    positive definite.

    Parameters
    ----------
    model : linear model, optional
        A linear model with ``.M``, ``.coordinates`` and ``.periodic_stiffness() -> (K0, K1, p)`` (e.g.
        ``LagrangianSystem.linearize()``); when omitted, all of ``M``, ``K0``, ``K1`` and ``p`` must be given.
    M : Matrix, optional
        Mass matrix, square ``n x n`` (used when ``model`` is omitted).
    K0 : Matrix, optional
        Constant part of the stiffness matrix, ``n x n`` (used when ``model`` is omitted).
    K1 : Matrix, optional
        Amplitude of the stiffness modulation ``K1 cos(p t)``, ``n x n`` and symmetric (used when ``model`` is
        omitted).
    p : Symbol or number, optional
        Fast angular frequency of the modulation (used when ``model`` is omitted).

    Returns
    -------
    Matrix
        The effective stiffness ``n x n`` (Hessian of ``V_eff``).

    See Also
    --------
    vibrational_averaging

    Examples
    --------
    >>> import sympy as sp
    >>> g, l, a, p = sp.symbols("g l a p", positive=True)
    >>> vibrational_stiffness(M=sp.Matrix([[l**2]]), K0=sp.Matrix([[-g * l]]), K1=sp.Matrix([[a * p**2 * l]]), p=p)
    Matrix([[a**2*p**2/2 - g*l]])
    """
    if model is not None:
        K0, K1, p = model.periodic_stiffness()
        M = model.M
        coords = tuple(model.coordinates)
    else:
        if any(v is None for v in (M, K0, K1, p)):
            raise ParameterError("pass a linear model or all of M, K0, K1, p")
        M, K0, K1 = sp.Matrix(M), sp.Matrix(K0), sp.Matrix(K1)
        coords = tuple(sp.Dummy(f"q{j}") for j in range(M.shape[0]))
    q = sp.Matrix(coords)
    V = sp.expand((q.T * K0 * q)[0, 0] / 2)
    fast = list(-(K1 * q) * sp.cos(p * t))
    res = vibrational_averaging(list(coords), M, V, fast, p)
    if res.effective_potential is None:  # pragma: no cover - K1 is symmetric for mechanical models
        raise ModelError("the averaged vibrational force is not potential (K1 not symmetric?)")
    return sp.hessian(res.effective_potential, q).applyfunc(sp.simplify)
