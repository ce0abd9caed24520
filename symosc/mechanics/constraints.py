"""Holonomic and non-holonomic constraints: Lagrange equations with multipliers.

A :class:`~symosc.mechanics.LagrangianSystem` built with ``constraints=[phi_1, ...]`` (holonomic,
``phi(q, t) = 0``) and/or ``nonholonomic=[g_1, ...]`` (linear in the velocities, ``g = E(q, t) q' + e(q, t) = 0``)
obeys Lagrange's equations with multipliers (Bulgakov (1954), §3.5, eq. (3.39)):

    M q'' = F + C^T lambda,     C q' + e = 0,

where the rows of ``C`` are ``d phi/dq`` for holonomic constraints (with ``e = d phi/dt``) and ``E`` for
non-holonomic ones.  ``C^T lambda`` are the generalized reaction forces of the ideal constraints (§3.2,
eq. (3.10)).  Differentiating the velocity-level constraints once more gives the index-1 form

    [[M, -C^T], [C, 0]] [q''; lambda] = [F; -gamma],   gamma = d/dt (C q' + e) at q'' = 0,

which is what :attr:`ConstrainedForm.augmented_mass_matrix` and :attr:`ConstrainedForm.augmented_forcing`
hold.  :meth:`ConstrainedForm.minimal_form` eliminates the dependent velocities (Maggi's equations, the
minimal-velocity form), and :meth:`LagrangianSystem.reduce_coordinates` substitutes a parametrization of
holonomic constraints (minimal coordinates).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from .._equality import ModelEquality
from .._printing import SymPyPrintable
from ..errors import ModelError
from ..numeric import compile, resolve
from ..symbols import t

if TYPE_CHECKING:
    from .lagrange import LagrangianSystem

__all__ = ["ConstrainedForm", "MinimalForm"]


def _random_point(symbols: Sequence[sp.Symbol], seed: int = 7) -> dict[sp.Symbol, sp.Float]:
    rng = np.random.default_rng(seed)
    return {s: sp.Float(float(rng.uniform(0.3, 1.7)), 30) for s in symbols}


RANK_TOLERANCE = 1e-9
"""Relative singular-value threshold of the numeric rank test (``sigma_min < tol * sigma_max`` counts as zero)."""

RANK_POINTS = 5
"""Number of random points of the numeric rank test (the generic rank is the largest rank found)."""


def _is_rational(matrix: sp.Matrix) -> bool:
    syms = sorted(matrix.free_symbols, key=str)
    return all(sp.sympify(e).is_rational_function(*syms) for e in matrix)


def _numeric_rank(matrix: sp.Matrix, point: Mapping[sp.Symbol, Any], tol: float) -> int:
    num = np.array(matrix.xreplace(dict(point)).evalf(30), dtype=complex)
    if not np.all(np.isfinite(num)):
        return -1
    sv = np.linalg.svd(num, compute_uv=False)
    if sv.size == 0 or sv[0] == 0:
        return 0
    return int(np.sum(sv > tol * sv[0]))


def _rank_points(symbols: Sequence[sp.Symbol], n_points: int) -> list[dict[sp.Symbol, sp.Float]]:
    pts = [_random_point(symbols)]
    rng = np.random.default_rng(20261124)
    for _ in range(n_points - 1):
        # both signs and a wider range than the first point; positive symbols stay positive
        pts.append(
            {
                s: sp.Float(
                    float(rng.uniform(0.2, 2.5) * (1 if s.is_positive or s.is_nonnegative else rng.choice([-1, 1]))), 30
                )
                for s in symbols
            }
        )
    return pts


def generic_rank(matrix: sp.Matrix, *, tol: float = RANK_TOLERANCE, n_points: int = RANK_POINTS) -> int:
    """Rank of ``matrix`` almost everywhere in its free symbols (its generic rank).

    Matrices whose entries are rational functions get the exact rank over the field of rational functions
    (fraction-free elimination, no tolerance).  Other entries (trigonometric, roots, ...) are evaluated at
    ``n_points`` random points (30 significant digits); a singular value below ``tol`` times the largest counts
    as zero, and the generic rank is the largest rank found, so an unlucky point on a special submanifold
    (where the rank drops) cannot make independent rows look dependent.  A matrix whose rank drops only on a
    submanifold has full generic rank.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> generic_rank(sp.Matrix([[1, 0], [1, 2 * y]]))   # singular only at y = 0
    2
    >>> generic_rank(sp.Matrix([[sp.sin(x), sp.cos(x)], [sp.sin(2 * x), 2 * sp.cos(x) ** 2]]))
    1
    """
    if matrix.rows == 0 or matrix.cols == 0:
        return 0
    if _is_rational(matrix):
        from sympy.polys.matrices import DomainMatrix

        try:
            return int(DomainMatrix.from_Matrix(matrix).to_field().rank())
        except (sp.PolificationFailed, NotImplementedError, ValueError, TypeError):  # pragma: no cover - fallback
            pass
    syms = sorted(matrix.free_symbols, key=str)
    best = max(_numeric_rank(matrix, pt, tol) for pt in _rank_points(syms, n_points))
    if best < 0:
        raise ModelError(f"cannot evaluate the matrix {matrix} at random points to find its rank")
    return best


def dependent_rows(matrix: sp.Matrix, *, tol: float = RANK_TOLERANCE, n_points: int = RANK_POINTS) -> list[int]:
    """Indices of a smallest-prefix dependent set of rows: the first row ``r`` that is a combination of the rows
    before it, together with the earlier rows that enter the combination (empty when the rows are independent)."""
    for r in range(1, matrix.rows + 1):
        sub = matrix[:r, :]
        if generic_rank(sub, tol=tol, n_points=n_points) < r:
            break
    else:
        return []
    # which earlier rows take part: left null vector of sub at a random point (at full rank of sub[:r-1])
    syms = sorted(sub.free_symbols, key=str)
    for pt in _rank_points(syms, n_points):
        num = np.array(sub.xreplace(pt).evalf(30), dtype=complex)
        if not np.all(np.isfinite(num)) or _numeric_rank(sub[: r - 1, :], pt, tol) < r - 1:
            continue
        vh = np.linalg.svd(num.T)[2]
        y = vh[-1].conj()
        scale = np.abs(y).max()
        return [i for i in range(r) if abs(y[i]) > 1e-6 * scale]
    return list(range(r))  # pragma: no cover - every point singular


def rank_on_constraint_set(
    holonomic: Sequence[sp.Expr],
    rows: sp.Matrix,
    coordinates: Sequence[sp.Symbol],
    *,
    tol: float = RANK_TOLERANCE,
    n_points: int = 3,
) -> int | None:
    """Largest rank of ``rows`` at points where the holonomic constraints hold (None if no point was found).

    Random configurations (random times and parameter values too) are projected onto ``phi(q, t) = 0`` by
    Gauss-Newton steps with minimum-norm corrections, iterated until the step stalls (so the projection also
    reaches a set where the Jacobian is singular).  Used to catch constraints that are independent at generic
    configurations but dependent everywhere on the set they define (e.g. ``x = 0, x + y^2 = 0``).
    """
    if not holonomic:
        return None
    q = list(coordinates)
    others = sorted((sp.Matrix(holonomic).free_symbols | rows.free_symbols) - set(q), key=str)
    phi = sp.lambdify([q, others], list(holonomic), "numpy")
    jac = sp.lambdify([q, others], sp.Matrix(holonomic).jacobian(q), "numpy")
    rank_fn = sp.lambdify([q, others], rows, "numpy")
    rng = np.random.default_rng(314159)
    best: int | None = None
    for _ in range(n_points):
        pars = [float(rng.uniform(0.3, 1.7)) for _ in others]
        x = rng.uniform(-1.5, 1.5, len(q))
        with np.errstate(all="ignore"):
            for _ in range(400):
                f = np.asarray(phi(x, pars), dtype=float)
                J = np.asarray(jac(x, pars), dtype=float)
                if not (np.all(np.isfinite(f)) and np.all(np.isfinite(J))):
                    break
                step = np.linalg.lstsq(J, -f, rcond=None)[0]
                x = x + step
                if np.linalg.norm(step) <= 1e-15 * max(1.0, np.linalg.norm(x)):
                    break
            f = np.asarray(phi(x, pars), dtype=float)
            if not np.all(np.isfinite(f)) or np.abs(f).max() > 1e-10:
                continue
            R = np.asarray(rank_fn(x, pars), dtype=complex)
        if not np.all(np.isfinite(R)):
            continue
        sv = np.linalg.svd(R, compute_uv=False)
        r = int(np.sum(sv > tol * sv[0])) if sv.size and sv[0] > 0 else 0
        best = r if best is None else max(best, r)
    return best


class ConstrainedForm(ModelEquality, SymPyPrintable):
    """Lagrange equations of the first kind of a constrained :class:`LagrangianSystem` (multiplier form).

    Not built directly: use :attr:`LagrangianSystem.constrained`.

    Parameters
    ----------
    system : LagrangianSystem
        The system with holonomic and/or non-holonomic constraints (reached as :attr:`LagrangianSystem.constrained`).

    Examples
    --------
    A pendulum written in Cartesian coordinates with the length constraint ``x^2 + y^2 - l^2 = 0``:

    >>> import sympy as sp
    >>> from symosc import dot
    >>> from symosc.mechanics import LagrangianSystem
    >>> x, y = sp.symbols("x y", real=True)
    >>> m, g, l = sp.symbols("m g l", positive=True)
    >>> s = LagrangianSystem(m / 2 * (dot(x) ** 2 + dot(y) ** 2), m * g * y, [x, y], constraints=[x**2 + y**2 - l**2])
    >>> c = s.constrained
    >>> c.jacobian
    Matrix([[2*x, 2*y]])
    >>> c.augmented_mass_matrix
    Matrix([
    [  m,   0, -2*x],
    [  0,   m, -2*y],
    [2*x, 2*y,    0]])
    >>> c.augmented_forcing.T
    Matrix([[0, -g*m, -2*x_dot**2 - 2*y_dot**2]])

    See Also
    --------
    LagrangianSystem.reduce_coordinates : minimal coordinates from a parametrization.
    MinimalForm : the equations with the dependent velocities eliminated.
    """

    def __init__(self, system: LagrangianSystem):
        self.system = system

    def _equality_data(self) -> tuple:
        return self.system._equality_data()

    def __repr__(self) -> str:
        s = self.system
        return (
            f"ConstrainedForm({len(s.coordinates)} coordinates, {len(s.holonomic_constraints)} holonomic and "
            f"{len(s.nonholonomic_constraints)} non-holonomic constraints)"
        )

    @cached_property
    def multipliers(self) -> tuple[sp.Symbol, ...]:
        """Multiplier symbols ``lambda1, lambda2, ...`` (holonomic constraints first)."""
        c = len(self.system.holonomic_constraints) + len(self.system.nonholonomic_constraints)
        return tuple(sp.Symbol(f"lambda{i + 1}", real=True) for i in range(c))

    @cached_property
    def _velocity_level(self) -> tuple[sp.Matrix, sp.Matrix]:
        s = self.system
        q, qd = s.coordinates, s.velocities
        rows, rhs = [], []
        for phi in s.holonomic_constraints:
            rows.append([phi.diff(v) for v in q])
            rhs.append(phi.diff(t))
        zero_v = {v: 0 for v in qd}
        for g in s.nonholonomic_constraints:
            rows.append([g.diff(v) for v in qd])
            rhs.append(g.xreplace(zero_v))
        n = len(q)
        return sp.Matrix(len(rows), n, lambda i, j: rows[i][j]), sp.Matrix(rhs)

    @property
    def jacobian(self) -> sp.Matrix:
        """``C(q, t)``: the velocity-level constraints are ``C q' + e = 0`` (Bulgakov (1954), eq. (3.28))."""
        return self._velocity_level[0]

    @property
    def velocity_bias(self) -> sp.Matrix:
        """``e(q, t)`` in ``C q' + e = 0`` (eq. (3.29)); zero for scleronomic constraints."""
        return self._velocity_level[1]

    @cached_property
    def acceleration_bias(self) -> sp.Matrix:
        """``gamma(q, q', t)``: the acceleration-level constraints are ``C q'' + gamma = 0``."""
        s = self.system
        C, e = self._velocity_level
        g = C * sp.Matrix(s.velocities) + e
        out = []
        for gi in g:
            out.append(
                sp.Add(*(gi.diff(qj) * vj for qj, vj in zip(s.coordinates, s.velocities, strict=True))) + gi.diff(t)
            )
        return sp.Matrix(out)

    @cached_property
    def reaction_forces(self) -> sp.Matrix:
        """Generalized reaction forces ``C^T lambda`` of the ideal constraints (eq. (3.39))."""
        return self.jacobian.T * sp.Matrix(self.multipliers)

    @cached_property
    def augmented_mass_matrix(self) -> sp.Matrix:
        """``[[M, -C^T], [C, 0]]`` of the index-1 system for ``(q'', lambda)``."""
        C = self.jacobian
        c = C.rows
        return self.system.mass_matrix.row_join(-C.T).col_join(C.row_join(sp.zeros(c, c)))

    @cached_property
    def augmented_forcing(self) -> sp.Matrix:
        """``[F; -gamma]`` of the index-1 system."""
        return self.system.forcing.col_join(-self.acceleration_bias)

    def dae_equations(self) -> sp.Matrix:
        """The differential-algebraic form: ``M q'' - F - C^T lambda`` (n rows), then the holonomic constraints
        ``phi(q, t)`` at position level and the non-holonomic ones at velocity level; all equal to zero."""
        s = self.system
        dyn = s.mass_matrix * sp.Matrix(s.accelerations) - s.forcing - self.reaction_forces
        return dyn.col_join(sp.Matrix([*s.holonomic_constraints, *s.nonholonomic_constraints]))

    def index_reduced_equations(self) -> sp.Matrix:
        """The index-1 form: ``M q'' - F - C^T lambda`` and ``C q'' + gamma`` (all equal to zero)."""
        s = self.system
        x = sp.Matrix([*s.accelerations, *self.multipliers])
        return self.augmented_mass_matrix * x - self.augmented_forcing

    def solved(self) -> tuple[sp.Matrix, sp.Matrix]:
        """Accelerations and multipliers as explicit expressions of ``(q, q', t)`` by symbolic LU.

        Returns ``(q'', lambda)``.  Only sensible for small systems.
        """
        n = len(self.system.coordinates)
        sol = self.augmented_mass_matrix.LUsolve(self.augmented_forcing)
        return sol[:n, :], sol[n:, :]

    @cached_property
    def _compiled(self):
        s = self.system
        C, e = self._velocity_level
        velocity_residual = C * sp.Matrix(s.velocities) + e
        position_residual = sp.Matrix([*s.holonomic_constraints, *([0] * len(s.nonholonomic_constraints))])
        stab = sp.zeros(len(s.coordinates), 2).col_join(velocity_residual.row_join(position_residual))
        both = self.augmented_mass_matrix.row_join(self.augmented_forcing).row_join(stab)
        return compile(both, [t, *s.coordinates, *s.velocities, *s.parameters], name="augmented")

    def accelerations(
        self, values: Mapping[Any, Any], time: float, state: Sequence[float]
    ) -> tuple[np.ndarray, np.ndarray]:
        """Numeric ``(q'', lambda)`` at one state ``x = (q, q')`` and time, parameters from ``values``.

        Parameters
        ----------
        values : mapping of Symbol or str to float
            One scalar value for every parameter of the system (keys are symbols or their names); a missing or
            non-finite value raises ParameterError.
        time : float
            The time ``t`` (matters for rheonomic systems and constraints).
        state : sequence of float
            The state ``x = (q, q')``, ``2 n`` numbers in the order of the coordinates then their velocities.
        """
        s = self.system
        n = len(s.coordinates)
        mf = np.asarray(self._compiled(time, *state, *resolve(s.parameters, values)), dtype=float)
        try:
            sol = np.linalg.solve(mf[:, :-3], mf[:, -3])
        except np.linalg.LinAlgError as exc:
            raise ModelError(
                f"the augmented matrix [[M, -C^T], [C, 0]] is singular at t={time}, state={list(state)}"
            ) from exc
        return sol[:n], sol[n:]

    def rhs(
        self, values: Mapping[Any, Any], *, stabilization: float = 0.0
    ) -> Callable[[float, np.ndarray], np.ndarray]:
        """Numeric ``f(t, x)``, ``x = (q, q')``, for ``scipy.integrate.solve_ivp`` (index-1 form).

        The constraints are integrated at acceleration level, so the position and velocity residuals drift at
        the rate of the integration error unless ``stabilization`` damps it.

        Parameters
        ----------
        values : mapping of Symbol or str to float
            One scalar value for every parameter of the system (keys are symbols or their names); checked once, so
            a missing or non-finite value raises ParameterError.
        stabilization : float, optional
            Baumgarte's rate ``a >= 0`` (default 0, no stabilization): ``a > 0`` replaces ``C q'' + gamma = 0`` by
            ``C q'' + gamma + 2 a (C q' + e) + a^2 phi = 0`` (Baumgarte (1972)), which damps the drift with rate
            ``a`` (choose ``a`` near the system's fastest natural frequency).
        """
        s = self.system
        n = len(s.coordinates)
        params = [float(v) for v in resolve(s.parameters, values)]
        self._compiled(0.0, *([0.5] * (2 * n)), *params)  # checks the parameter values once
        raw = self._compiled.raw
        a = float(stabilization)

        def f(time: float, x: np.ndarray) -> np.ndarray:
            mf = raw(time, *x, *params)
            rhs = mf[:, -3] - (2 * a * mf[:, -2] + a * a * mf[:, -1]) if a else mf[:, -3]
            sol = np.linalg.solve(mf[:, :-3], rhs)
            return np.concatenate([x[n:], sol[:n]])

        return f

    def residuals(self, values: Mapping[Any, Any], time: float, state: Sequence[float]) -> np.ndarray:
        """Constraint residuals at a state: holonomic ``phi`` then velocity-level ``C q' + e`` of every constraint.

        Parameters
        ----------
        values : mapping of Symbol or str to float
            One scalar value for every parameter of the system (keys are symbols or their names); a missing or
            non-finite value raises ParameterError.
        time : float
            The time ``t`` (matters for rheonomic systems and constraints).
        state : sequence of float
            The state ``x = (q, q')``, ``2 n`` numbers in the order of the coordinates then their velocities.
        """
        s = self.system
        expr = sp.Matrix([*s.holonomic_constraints]).col_join(
            self.jacobian * sp.Matrix(s.velocities) + self.velocity_bias
        )
        fn = compile(expr, [t, *s.coordinates, *s.velocities, *s.parameters], name="residuals")
        return np.asarray(fn(time, *state, *resolve(s.parameters, values)), dtype=float).ravel()

    def minimal_form(self, independent: Sequence[Any] | None = None) -> MinimalForm:
        """Eliminate the dependent velocities (Maggi's equations; Bulgakov (1954), §3.5).

        Parameters
        ----------
        independent : sequence of coordinates, optional
            Coordinates whose velocities stay independent (``n - c`` of them).  By default the dependent ones
            are chosen by column pivoting of ``C`` at a random point.

        Returns
        -------
        MinimalForm
        """
        return _minimal_form(self, independent)


@dataclass(frozen=True, eq=False)
class MinimalForm(ModelEquality, SymPyPrintable):
    """Equations with the dependent velocities eliminated: ``q' = S u + s0``, ``M_r u' = F_r``.

    ``u`` are the independent velocities (the velocity symbols of the independent coordinates); every field
    is an expression in ``(q, u, t)``.

    Attributes
    ----------
    independent : tuple of Symbol
        The independent velocities ``u``.
    dependent : dict
        Dependent velocity symbol -> its expression in ``(q, u, t)``.
    mass_matrix, forcing : sympy.Matrix
        ``M_r = S^T M S`` and ``F_r = S^T (F - M (S' u + s0'))``.
    coordinates : tuple of Symbol
        All coordinates ``q`` of the system (the fields are expressions in them, ``u`` and ``t``).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc import dot
    >>> from symosc.mechanics import LagrangianSystem
    >>> X, Y, th = sp.symbols("X Y theta", real=True)
    >>> s = LagrangianSystem((dot(X)**2 + dot(Y)**2 + dot(th)**2) / 2, 0, [X, Y, th],
    ...     nonholonomic=[-sp.sin(th) * dot(X) + sp.cos(th) * dot(Y)])
    >>> s.constrained.minimal_form(independent=[X, th]).dependent
    {Y_dot: X_dot*tan(theta)}

    See Also
    --------
    ConstrainedForm.minimal_form, LagrangianSystem.reduce_coordinates
    """

    independent: tuple[sp.Symbol, ...]
    dependent: dict
    mass_matrix: sp.Matrix
    forcing: sp.Matrix
    coordinates: tuple[sp.Symbol, ...]

    def _equality_data(self) -> tuple:
        dep = sorted(self.dependent.items(), key=lambda kv: str(kv[0]))
        key = (tuple(self.independent), tuple(self.coordinates), tuple(k for k, _ in dep))
        return key, (self.mass_matrix, self.forcing, *(v for _, v in dep))

    def __repr__(self) -> str:
        u = ", ".join(s.name for s in self.independent)
        d = ", ".join(s.name for s in self.dependent)
        return f"MinimalForm(independent velocities: {u}; eliminated: {d})"

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(self.mass_matrix)} \\dot{{u}} = {sp.latex(self.forcing)}$$"

    def velocity_map(self) -> sp.Matrix:
        """All velocities ``q'`` in terms of ``(q, u, t)``."""
        from ..symbols import dot

        return sp.Matrix([self.dependent.get(dot(q), dot(q)) for q in self.coordinates])


def _minimal_form(form: ConstrainedForm, independent: Sequence[Any] | None) -> MinimalForm:
    s = form.system
    q, qd = s.coordinates, s.velocities
    n = len(q)
    C, e = form.jacobian, form.velocity_bias
    c = C.rows
    by_name = {v.name: i for i, v in enumerate(q)}
    if independent is None:
        at = _random_point(sorted(C.free_symbols, key=str))
        num = np.array(C.xreplace(at).evalf(20), dtype=float)
        import scipy.linalg

        _, _, piv = scipy.linalg.qr(num, pivoting=True)
        dep = sorted(int(i) for i in piv[:c])
    else:
        names = [getattr(v, "name", str(v)) for v in independent]
        unknown = [nm for nm in names if nm not in by_name]
        if unknown:
            raise ModelError(f"independent= names {unknown}, which are not coordinates")
        if len(names) != n - c:
            raise ModelError(
                f"independent= must name {n - c} coordinates (n - number of constraints), got {len(names)}"
            )
        dep = sorted(set(range(n)) - {by_name[nm] for nm in names})
    ind = [i for i in range(n) if i not in dep]
    Cd = C.extract(list(range(c)), dep)
    if generic_rank(Cd) < c:
        raise ModelError(
            "the velocities of " + ", ".join(q[i].name for i in dep) + " cannot be solved from the constraints "
            "(singular block of the constraint Jacobian); choose other independent= coordinates"
        )
    Ci = C.extract(list(range(c)), ind)
    Cd_inv = Cd.inv(method="LU")
    B = -Cd_inv * Ci
    b0 = -Cd_inv * e
    S = sp.zeros(n, len(ind))
    s0 = sp.zeros(n, 1)
    for k, i in enumerate(ind):
        S[i, k] = 1
    for r, i in enumerate(dep):
        S[i, :] = B[r, :]
        s0[i] = b0[r]
    u = [qd[i] for i in ind]
    w = S * sp.Matrix(u) + s0  # q' in terms of (q, u, t)
    dependent = {qd[i]: sp.simplify(w[i]) if c <= 2 else w[i] for i in dep}
    sub = dict(dependent)
    # d/dt of w at u' = 0, along the constrained motion
    a0 = sp.Matrix([sum((wi.diff(qj) * w[j] for j, qj in enumerate(q)), sp.S.Zero) + wi.diff(t) for wi in w])
    M = s.mass_matrix
    F = s.forcing.xreplace(sub)
    Mr = S.T * M * S
    Fr = S.T * (F - M * a0)
    return MinimalForm(independent=tuple(u), dependent=dependent, mass_matrix=Mr, forcing=Fr, coordinates=tuple(q))
