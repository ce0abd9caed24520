"""Lagrange equations of the second kind.

:class:`LagrangianSystem` takes the kinetic energy T, the potential energy V, a Rayleigh dissipation
function R and generalised forces Q, and derives

    M(q, t) q'' = F(q, q', t),    M = d^2 T / dq' dq',
    F = dT/dq - d/dt(dT/dq')|_{q''=0} - dV/dq - dR/dq' + Q.

Everything is computed lazily on first access and cached.  Internally coordinates, velocities and
accelerations are plain symbols (:func:`symosc.symbols.dot`, :func:`symosc.symbols.ddot`); coordinates
given as ``dynamicsymbols`` are converted on entry.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from functools import cached_property
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef

from .._equality import ModelEquality
from .._printing import SymPyPrintable
from .._trig import trig_reduce_groups_unchecked
from ..errors import ModelError, ParameterError
from ..symbols import ddot, dot, sort_symbols, t
from . import _constraints, _terms

__all__ = ["LagrangianSystem"]


def _plain_coordinates(coordinates: Sequence[Any]) -> tuple[tuple[sp.Symbol, ...], dict[sp.Expr, sp.Symbol]]:
    """Plain coordinate symbols and the replacement map from dynamicsymbols (and their derivatives)."""
    if isinstance(coordinates, (sp.Symbol, AppliedUndef)):
        coordinates = [coordinates]
    if isinstance(coordinates, str | bytes) or not hasattr(coordinates, "__len__"):
        raise ModelError(
            f"coordinates must be a sequence of Symbols or dynamicsymbols (functions of symosc.t), got {coordinates!r}"
        )
    if len(coordinates) == 0:
        raise ModelError("at least one generalised coordinate is required")
    plain: list[sp.Symbol] = []
    replace: dict[sp.Expr, sp.Symbol] = {}
    for c in coordinates:
        if isinstance(c, sp.Symbol):
            if c == t:
                raise ModelError("time t cannot be a generalised coordinate")
            q = c
        elif isinstance(c, AppliedUndef) and c.args == (t,):
            q = sp.Symbol(c.func.__name__, real=True)
            # (Derivative objects built directly: c.diff(t) takes SymPy's general differentiation path)
            replace[sp.Derivative(c, (t, 2))] = ddot(q)
            replace[sp.Derivative(c, t)] = dot(q)
            replace[c] = q
        else:
            raise ModelError(
                f"coordinates must be Symbols or dynamicsymbols (functions of symosc.t), got {c!r} ({type(c).__name__})"
            )
        plain.append(q)
    names = [q.name for q in plain]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise ModelError(f"repeated coordinates: {', '.join(dup)}")
    return tuple(plain), replace


def _xreplace(expr: sp.Basic, rule: Mapping[sp.Basic, sp.Basic], memo: dict[sp.Basic, sp.Basic]) -> sp.Basic:
    """``expr.xreplace(rule)``, each distinct subexpression rebuilt once (``memo``: results so far).

    Energies typed by users repeat their subexpressions (every mass's velocity holds the terms of the links before
    it); ``xreplace`` rebuilds each occurrence.  The result is the same: a node whose arguments did not change is
    kept, the others are rebuilt by their class from the replaced arguments, as ``xreplace`` does.
    """
    got = memo.get(expr)
    if got is not None:
        return got
    if expr in rule:
        out = rule[expr]
    elif not expr.args:
        out = expr
    else:
        args = tuple(_xreplace(a, rule, memo) if isinstance(a, sp.Basic) else a for a in expr.args)
        if all(a is b for a, b in zip(args, expr.args, strict=True)):
            out = expr
        elif isinstance(expr, sp.sin | sp.cos):
            out = _terms.trig(expr.func, args[0])
        elif isinstance(expr, sp.Pow):
            out = _terms.power(args[0], args[1])
        else:
            out = expr.func(*args)
    memo[expr] = out
    return out


class DeferredGeometry:
    """A :class:`~symosc.mechanics.Geometry` built on first access of :attr:`LagrangianSystem.geometry` (catalogue
    models: the drawing data is not needed to derive the equations).

    Parameters
    ----------
    build : callable
        Called without arguments, returns the geometry; a picklable callable (e.g. a ``functools.partial`` of a
        module-level function) keeps the system picklable.
    """

    def __init__(self, build: Callable[[], Any]) -> None:
        self.build = build


class LagrangianSystem(ModelEquality, SymPyPrintable):
    """A holonomic mechanical system given by its energies.

    Two systems are equal (``==``, and hash alike) when they have the same coordinates and their energies, forces
    and constraints agree after expansion: the same equations of motion.

    Parameters
    ----------
    T : Expr
        Kinetic energy, a polynomial of degree <= 2 in the velocities (``dot(q)`` for plain-symbol
        coordinates, ``q(t).diff(t)`` for dynamicsymbols).  May depend explicitly on time
        :data:`symosc.t` (rheonomic systems, e.g. a moving pivot).
    V : Expr
        Potential energy; must not depend on velocities.
    coordinates : sequence of Symbol or dynamicsymbols
        Generalised coordinates q.
    dissipation : Expr, optional
        Rayleigh dissipation function R(q, q', t); adds -dR/dq' to the forces.
    forces : sequence or mapping, optional
        Generalised forces Q_i (one per coordinate, or a mapping coordinate -> Q).
    constraints : sequence of Expr, optional
        Holonomic constraints ``phi(q, t) = 0`` (give the expressions ``phi``).  The equations of motion
        then carry multipliers: see :attr:`constrained` (Bulgakov (1954), §3.3-3.5).
    nonholonomic : sequence of Expr, optional
        Non-holonomic constraints linear in the velocities, ``E(q, t) q' + e(q, t) = 0`` (eq. (3.28)).
    simplify : bool
        Apply the identities ``sin**2 + cos**2 = 1``, ``sin u sin v + cos u cos v = cos(u - v)`` and
        ``sin u cos v - cos u sin v = sin(u - v)`` to the kinetic energy's terms before anything is derived
        (:func:`symosc.algebra.trig_reduce_groups`: a hash lookup per term, no search), so that the mass matrix, the
        forces, LaTeX and generated code come out in the short form.  ``False`` keeps the terms as written.

    Examples
    --------
    A pendulum on a spring-mounted slider:

    >>> import sympy as sp
    >>> from symosc import dot
    >>> from symosc.mechanics import LagrangianSystem
    >>> x, phi = sp.symbols("x phi", real=True)
    >>> m, l, k, g = sp.symbols("m l k g", positive=True)
    >>> T = m / 2 * ((dot(x) + l * sp.cos(phi) * dot(phi)) ** 2 + (l * sp.sin(phi) * dot(phi)) ** 2)
    >>> V = k * x**2 / 2 - m * g * l * sp.cos(phi)
    >>> s = LagrangianSystem(T, V, [x, phi])
    >>> sp.trigsimp(s.mass_matrix)
    Matrix([
    [           m, l*m*cos(phi)],
    [l*m*cos(phi),       l**2*m]])
    >>> s.forcing
    Matrix([
    [-k*x + l*m*phi_dot**2*sin(phi)],
    [               -g*l*m*sin(phi)]])
    """

    def __init__(
        self,
        T: Any,
        V: Any,
        coordinates: Sequence[Any],
        *,
        dissipation: Any = 0,
        forces: Sequence[Any] | Mapping[Any, Any] | None = None,
        constraints: Sequence[Any] = (),
        nonholonomic: Sequence[Any] = (),
        simplify: bool = True,
    ) -> None:
        self._simplify = bool(simplify)
        q, replace = _plain_coordinates(coordinates)
        self._q = q
        self._qd = tuple(dot(s) for s in q)
        self._qdd = tuple(ddot(s) for s in q)

        memo: dict[sp.Basic, sp.Basic] = {}

        def convert(expr: Any, what: str) -> sp.Expr:
            if expr is None:
                raise ParameterError(f"{what} must be a SymPy expression (0 when there is none), got None")
            if isinstance(expr, str | bytes):
                raise ParameterError(
                    f"{what} must be a SymPy expression, got the string {expr!r}: build it from symbols "
                    "(sympy.symbols(...)) rather than text, so that a misspelt name is never silently a new symbol"
                )
            try:
                e = sp.sympify(expr)
            except (sp.SympifyError, TypeError) as exc:
                raise ModelError(f"{what} is not a SymPy expression: {expr!r}") from exc
            if isinstance(e, sp.MatrixBase) or not isinstance(e, sp.Expr):
                raise ModelError(f"{what} must be a scalar SymPy expression, got {type(e).__name__}")
            e = _xreplace(e, replace, memo) if replace else e
            stray = [f for f in e.atoms(AppliedUndef, sp.Derivative)]
            if stray:
                raise ModelError(
                    f"{what} contains functions of time that are not coordinates: {stray}; give prescribed motions "
                    "explicitly in terms of symosc.t, or add them to the coordinates"
                )
            if e.free_symbols & set(self._qdd):
                raise ModelError(f"{what} must not depend on accelerations")
            return e

        self._T = convert(T, "T")
        self._V = convert(V, "V")
        self._R = convert(dissipation, "dissipation")
        if self._V.free_symbols & set(self._qd):
            raise ModelError("V must not depend on velocities; pass velocity-dependent forces through forces=")
        self._Q = self._convert_forces(forces, convert, replace)
        if not (self._T.free_symbols & set(self._qd)):
            raise ModelError("T does not depend on any velocity: no mass matrix can be formed")
        self._parts  # noqa: B018 - split T now, so that a T that is not quadratic is reported at once
        self._holonomic, self._nonholonomic = _constraints.check_constraints(self, constraints, nonholonomic, convert)

    def _convert_forces(self, forces: Any, convert: Any, replace: dict) -> tuple[sp.Expr, ...]:
        n = len(self._q)
        if forces is None:
            return (sp.S.Zero,) * n
        if isinstance(forces, str | bytes) or not hasattr(forces, "__iter__"):
            raise ParameterError(
                f"forces must be a sequence of {n} expressions (one per coordinate) or a mapping coordinate -> force, "
                f"got {forces!r}"
            )
        if isinstance(forces, Mapping):
            by_name = {q.name: i for i, q in enumerate(self._q)}
            out = [sp.S.Zero] * n
            for key, val in forces.items():
                key = replace.get(key, key)
                name = key.name if isinstance(key, sp.Symbol) else str(key)
                if name not in by_name:
                    raise ModelError(f"force given for {name!r}, which is not a coordinate")
                out[by_name[name]] = convert(val, f"force on {name}")
            return tuple(out)
        forces = list(forces)
        if len(forces) != n:
            raise ModelError(f"expected {n} generalised forces (one per coordinate), got {len(forces)}")
        return tuple(convert(f, f"force {i + 1}") for i, f in enumerate(forces))

    def _equality_data(self) -> tuple:
        exprs = (self._T, self._V, self._R, *self._Q, *self._holonomic, *self._nonholonomic)
        return (self._q, len(self._holonomic), len(self._nonholonomic)), exprs

    # ------------------------------------------------------------------ basic data
    @property
    def coordinates(self) -> tuple[sp.Symbol, ...]:
        """Generalised coordinates q (plain symbols)."""
        return self._q

    @property
    def velocities(self) -> tuple[sp.Symbol, ...]:
        """Velocity symbols q'."""
        return self._qd

    @property
    def accelerations(self) -> tuple[sp.Symbol, ...]:
        """Acceleration symbols q''."""
        return self._qdd

    @property
    def kinetic_energy(self) -> sp.Expr:
        return self._T

    @property
    def potential_energy(self) -> sp.Expr:
        return self._V

    @property
    def dissipation(self) -> sp.Expr:
        return self._R

    @property
    def forces(self) -> tuple[sp.Expr, ...]:
        return self._Q

    @cached_property
    def energy(self) -> sp.Expr:
        """Total mechanical energy T + V (conserved when the system is scleronomic and undamped)."""
        return self._T + self._V

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """Free parameter symbols (everything but coordinates, velocities and time), in natural order."""
        syms = set().union(self._T.free_symbols, self._V.free_symbols, self._R.free_symbols)
        for f in (*self._Q, *self._holonomic, *self._nonholonomic):
            syms |= f.free_symbols
        return sort_symbols(syms - set(self._q) - set(self._qd) - {t})

    @cached_property
    def is_rheonomic(self) -> bool:
        """True when T, V, R or Q depend explicitly on time."""
        return t in (self._T.free_symbols | self._V.free_symbols | self._R.free_symbols) or any(
            t in f.free_symbols for f in (*self._Q, *self._holonomic, *self._nonholonomic)
        )

    @property
    def holonomic_constraints(self) -> tuple[sp.Expr, ...]:
        """Holonomic constraints ``phi(q, t)`` (each equal to zero)."""
        return self._holonomic

    @property
    def nonholonomic_constraints(self) -> tuple[sp.Expr, ...]:
        """Non-holonomic constraints ``E(q, t) q' + e(q, t)`` (each equal to zero)."""
        return self._nonholonomic

    @property
    def is_constrained(self) -> bool:
        """True when the system has holonomic or non-holonomic constraints."""
        return bool(self._holonomic or self._nonholonomic)

    def __repr__(self) -> str:
        kind = "rheonomic" if self.is_rheonomic else "scleronomic"
        q = ", ".join(s.name for s in self._q)
        p = ", ".join(s.name for s in self.parameters)
        c = ""
        if self.is_constrained:
            c = f"; {len(self._holonomic)} holonomic, {len(self._nonholonomic)} non-holonomic constraints"
        return f"LagrangianSystem({kind}; coordinates: {q}; parameters: {p}{c})"

    def _repr_latex_(self) -> str:
        """The equations ``M q'' = F`` in notebooks (a summary for more than four coordinates)."""
        if len(self._q) > 4:
            return f"$\\text{{{self!r}}}$"
        return f"$${self.latex()}$$"

    def latex(self, *, simplify: bool = False) -> str:
        """LaTeX of the equations of motion ``M(q) q'' = F(q, q', t)``.

        Parameters
        ----------
        simplify : bool
            Apply ``sympy.trigsimp`` to ``M`` and ``F`` first (e.g. ``sin**2 + cos**2 -> 1``).  Display only: the
            stored matrices are unchanged.

        Examples
        --------
        >>> from symosc.models import n_link_pendulum
        >>> print(n_link_pendulum(1).latex(simplify=True))  # doctest: +NORMALIZE_WHITESPACE
        \\left[\\begin{matrix}l_{1}^{2} m_{1}\\end{matrix}\\right]
        \\left[\\begin{matrix}\\ddot{\\phi_{1}}\\end{matrix}\\right]
        = \\left[\\begin{matrix}- g l_{1} m_{1} \\sin{\\left(\\phi_{1} \\right)}\\end{matrix}\\right]

        See Also
        --------
        mass_matrix, forcing
        """
        names = {}
        for q, qd, qdd in zip(self._q, self._qd, self._qdd, strict=True):
            names[qd] = rf"\dot{{{sp.latex(q)}}}"
            names[qdd] = rf"\ddot{{{sp.latex(q)}}}"
        M, F = self.mass_matrix, self.forcing
        if simplify:
            M, F = M.applyfunc(sp.trigsimp), F.applyfunc(sp.trigsimp)
        lhs = sp.MatMul(M, sp.Matrix(self._qdd), evaluate=False)
        return f"{sp.latex(lhs, symbol_names=names)} = {sp.latex(F, symbol_names=names)}"

    # ------------------------------------------------------------------ derivation
    @cached_property
    def _dependent(self) -> set[sp.Symbol]:
        """Symbols whose derivatives the engine takes: coordinates and time."""
        return set(self._q) | {t}

    @cached_property
    def _parts(self) -> dict[tuple[int, ...], _terms.Groups]:
        """T split by velocity monomial (``()``, ``(i,)``, ``(i, j)`` with i <= j), each coefficient
        collected by its factor that depends on the coordinates and time."""
        parts = _terms.velocity_parts(self._T, self._qd, "T")
        dep = _terms._Depends(self._dependent)
        out = {k: _terms.group_terms(_terms.expand_terms(v, dep), dep) for k, v in parts.items()}
        if self._simplify:  # sin**2 + cos**2 and angle-difference pairs, found by hashing (presentation-ready M, F)
            reduce = trig_reduce_groups_unchecked
            out = {
                k: [_terms.product_group(d, c) for d, c in reduce([(g.dep, g.coeff) for g in groups])]
                for k, groups in out.items()
            }
        return out

    @staticmethod
    def _sum(groups: _terms.Groups, scale: sp.Expr = sp.S.One) -> sp.Expr:
        return sp.Add(*(_times(_times(scale, g.coeff), g.dep) for g in groups))

    @cached_property
    def mass_matrix(self) -> sp.Matrix:
        """M(q, t) = d^2 T / dq' dq' (symmetric)."""
        n = len(self._q)
        M = sp.zeros(n, n)
        for key, groups in self._parts.items():
            if len(key) == 2:
                i, j = key
                if self._simplify:  # common factors of each coefficient taken out: l1*(l2*m3 + lc2*m2)*cos(...)
                    groups = [_terms.product_group(g.dep, _common_factor(g.coeff)) for g in groups]
                if i == j:  # T holds m_ii q_i'^2 / 2: double each constant before it multiplies its factor
                    M[i, i] = self._sum(groups, sp.S(2))
                else:
                    M[i, j] = M[j, i] = self._sum(groups)
        return M

    @cached_property
    def forcing(self) -> sp.Matrix:
        """F(q, q', t) in M q'' = F: everything but the acceleration terms, moved to the right."""
        if self._simplify:
            return self._forcing_collected()
        q, qd = self._q, self._qd
        n = len(q)
        qt = [*q, t]
        rates = [*qd, sp.S.One]
        pieces: list[list[sp.Expr]] = [[] for _ in range(n)]
        minus, minus2 = sp.S.NegativeOne, sp.Integer(-2)
        for key, groups in self._parts.items():
            grads = _terms.grouped_gradient(groups, qt)
            sums = [sp.Add(*g) if g else None for g in grads]
            mono = [qd[i] for i in key]
            # dT/dq_k: the coefficient's gradient times the velocity monomial.
            for k in range(n):
                if sums[k] is not None:
                    pieces[k].append(sp.Mul(sums[k], *mono))
            # d/dt of dT/dq'_i along the motion (accelerations excluded).
            rate = sp.Add(*(sp.Mul(g, r) for g, r in zip(sums, rates, strict=True) if g is not None))
            if rate == 0:
                continue
            if len(key) == 1:
                pieces[key[0]].append(sp.Mul(minus, rate))
            elif len(key) == 2:
                i, j = key
                if i == j:
                    pieces[i].append(sp.Mul(minus2, rate, qd[i]))
                else:
                    pieces[i].append(sp.Mul(minus, rate, qd[j]))
                    pieces[j].append(sp.Mul(minus, rate, qd[i]))
        dV = _terms.grouped_gradient(self._potential_groups, q)
        for k in range(n):
            pieces[k].extend(sp.Mul(minus, x) for x in dV[k])
            if self._R != 0:
                pieces[k].append(-self._R.diff(qd[k]))
            pieces[k].append(self._Q[k])
        return sp.Matrix([sp.Add(*p) for p in pieces])

    def _forcing_collected(self) -> sp.Matrix:
        """The same F as :attr:`forcing`, each term filed at once under its factor in the coordinates and time and
        its velocity monomial, so that the product rule's velocity terms cancel and like terms merge without any
        ``expand``; each coefficient's common factors are taken out (``-g*l1*(m1 + m2)*sin(phi1)``)."""
        q, qd = self._q, self._qd
        n = len(q)
        dep = self._dependent
        velocity = {v: i for i, v in enumerate(qd)}
        acc: list[dict] = [{} for _ in range(n)]
        depends = _terms._Depends(dep)  # memoized: free_symbols is recomputed by SymPy on every call
        depends_or_rate = _terms._Depends(dep | set(qd))

        def file(k: int, expr: sp.Expr | _terms.Piece, mono: tuple, scale: int) -> None:
            if isinstance(expr, _terms.Piece):
                consts = acc[k].setdefault((expr.dependent, tuple(sorted(mono))), {})
                consts[expr.constants] = consts.get(expr.constants, 0) + scale * expr.number
                return
            for x in _distribute(expr, depends_or_rate):
                num, rest = x.as_coeff_Mul()
                d, c, m = [], [], list(mono)
                for f in sp.Mul.make_args(rest):
                    base, exp = (f.base, f.exp) if f.is_Pow and f.exp.is_Integer and f.exp > 0 else (f, 1)
                    if base in velocity:
                        m += [velocity[base]] * int(exp)
                    elif depends(f):
                        d.append(f)
                    else:
                        c.append(f)
                consts = acc[k].setdefault((tuple(d), tuple(sorted(m))), {})
                c = tuple(c)
                consts[c] = consts.get(c, 0) + scale * num

        qt = [*q, t]
        for key, groups in self._parts.items():
            grads = _terms.grouped_gradient(groups, qt, depends)
            for k in range(n):  # dT/dq_k: the coefficient's gradient times the velocity monomial
                for x in grads[k]:
                    file(k, x, key, 1)
            for v, g in enumerate(grads):  # d/dt of dT/dq'_i along the motion (accelerations excluded)
                rate_mono = (v,) if v < n else ()
                for x in g:
                    if len(key) == 1:
                        file(key[0], x, rate_mono, -1)
                    elif len(key) == 2 and key[0] == key[1]:
                        file(key[0], x, (*rate_mono, key[0]), -2)
                    elif len(key) == 2:
                        file(key[0], x, (*rate_mono, key[1]), -1)
                        file(key[1], x, (*rate_mono, key[0]), -1)
        dV = _terms.grouped_gradient(self._potential_groups, q, depends)
        for k in range(n):
            for x in dV[k]:
                file(k, x, (), -1)
            if self._R != 0:
                file(k, self._R.diff(qd[k]), (), -1)
            if self._Q[k] != 0:
                file(k, self._Q[k], (), 1)
        rows = []
        for k in range(n):
            terms = []
            for (d, mono), consts in acc[k].items():
                c = _constant_sum(consts)
                if c != 0:
                    terms.append(_common_factor(c) * _terms._product(d) * sp.Mul(*(qd[i] for i in mono)))
            rows.append(sp.Add(*terms))
        return sp.Matrix(rows)

    @cached_property
    def _potential_groups(self) -> _terms.Groups:
        return _terms.group_terms(_terms.expand_terms(self._V, self._dependent), self._dependent)

    def equations(self) -> sp.Matrix:
        """Equations of motion M q'' - F = 0 as a column Matrix (accelerations are ``ddot(q)`` symbols)."""
        return self.mass_matrix * sp.Matrix(self._qdd) - self.forcing

    # ------------------------------------------------------------------ derived forms
    def first_order(self):
        """The solved first-order form x' = f(t, x) with x = (q, q'); see :class:`FirstOrderSystem`."""
        from .first_order import FirstOrderSystem

        if self.is_constrained:
            raise ModelError(
                "the system has constraints: use .constrained.rhs(values) (multiplier form) or "
                ".constrained.minimal_form() / .reduce_coordinates(...) (minimal form)"
            )

        return FirstOrderSystem(self)

    def linearize(self, point: Mapping[Any, Any] | None = None, *, check_equilibrium: bool = True):
        """Linearize about ``point`` (coordinates -> values, default all zero) with zero velocities.

        Builds M, D, K directly from the energies (no full nonlinear forcing is needed):
        with T = 1/2 q'^T M q' + b^T q' + T0,

        - ``D = G + dM/dt + d^2R/dq'^2 - dQ/dq'`` with the gyroscopic part ``G_ij = db_i/dq_j - db_j/dq_i``;
        - ``K = d/dq (dV/dq - dT0/dq + db/dt - Q)`` at the point;
        - ``f`` = the right-hand side left at the point (a prescribed excitation).

        Returns a :class:`~symosc.mechanics.LinearModel` ``M q'' + D q' + K q = f``.

        Parameters
        ----------
        point : mapping of Symbol or str to number or expression, optional
            Values of the coordinates at the linearization point (keys are coordinates or their names; a name that
            is not a coordinate raises ModelError); coordinates left out are 0, and all velocities are 0.
        check_equilibrium : bool, optional
            Whether to raise :class:`ModelError` when the point is not an equilibrium (a constant nonzero ``f``);
            default True, False linearizes anyway.
        """
        from .linear_model import linearize_system

        if self.is_constrained:
            raise ModelError("linearize() needs an unconstrained system: call reduce_coordinates(...) first")
        return linearize_system(self, point, check_equilibrium=check_equilibrium)

    # ------------------------------------------------------------------ analytic dynamics (Bulgakov ch. 3)
    @cached_property
    def constrained(self):
        """Lagrange equations with multipliers (:class:`~symosc.mechanics.ConstrainedForm`).

        Raises :class:`ModelError` when the system has no constraints.
        """
        from .constraints import ConstrainedForm

        if not self.is_constrained:
            raise ModelError("the system has no constraints; pass constraints= or nonholonomic=")
        return ConstrainedForm(self)

    @cached_property
    def kinetic_energy_parts(self) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        """``(T2, T1, T0)``: the parts of T of degree 2, 1 and 0 in the velocities (Bulgakov (1954), eq. (3.42))."""
        out = [sp.S.Zero, sp.S.Zero, sp.S.Zero]
        qd = self._qd
        for key, groups in self._parts.items():
            mono = sp.Mul(*(qd[i] for i in key))
            out[2 - len(key)] += self._sum(groups) * mono
        return out[0], out[1], out[2]

    @cached_property
    def energy_function(self) -> sp.Expr:
        """``h = sum q' dL/dq' - L = T2 - T0 + V`` (Bulgakov (1954), eqs. (3.98), (3.101)-(3.103))."""
        T2, _, T0 = self.kinetic_energy_parts
        return T2 - T0 + self._V

    @cached_property
    def jacobi_integral(self) -> sp.Expr:
        """The Jacobi integral ``T2 + V - T0`` (eq. (3.107)).

        Raises :class:`ModelError` when it is not conserved: L depends on time explicitly, there are
        generalized forces or dissipation, or the constraints are rheonomic.
        """
        reasons = []
        L = self._T - self._V
        if t in L.free_symbols and sp.simplify(L.diff(t)) != 0:
            reasons.append("L depends on time explicitly")
        if self._R != 0 or any(f != 0 for f in self._Q):
            reasons.append("there are generalized forces or dissipation")
        if self.is_constrained and any(e != 0 for e in self.constrained.velocity_bias):
            reasons.append("the constraints are rheonomic")
        if reasons:
            raise ModelError("no Jacobi integral: " + "; ".join(reasons) + "; use energy_function and its balance")
        return self.energy_function

    def christoffel_symbols(self, kind: int = 2) -> sp.Array:
        """Christoffel symbols of the metric ``g = M`` (Bulgakov (1954), §3.7, eqs. (3.83), (3.86)).

        Parameters
        ----------
        kind : {1, 2}, optional
            Kind of the symbols, which must be 1 or 2 (default 2).  ``kind=1``:
            ``Gamma[m, k, l] = (dg_mk/dq_l + dg_ml/dq_k - dg_kl/dq_m) / 2``; ``kind=2``:
            ``Gamma[j, k, l] = g^jm Gamma_m,kl`` so that for a natural scleronomic system
            ``q''^j + Gamma^j_kl q'^k q'^l = g^jm (-dV/dq^m)`` (eq. (3.88)).
        """
        from ._analytic import christoffel

        return christoffel(self, kind)

    def reduce_coordinates(self, parametrization: Mapping[Any, Any], coordinates: Sequence[Any]):
        """Minimal coordinates: substitute ``q = q(s, t)`` that satisfies the holonomic constraints.

        Returns a new :class:`LagrangianSystem` in ``coordinates`` ``s``; generalized forces are carried over as
        ``Q_s = (dq/ds)^T Q``.  Constraints that vanish identically are dropped (the rest are kept); raises
        :class:`ModelError` if a coordinate is missing from the parametrization.

        Parameters
        ----------
        parametrization : mapping of Symbol or str to expression
            The old coordinates as expressions ``q(s, t)`` in the new coordinates, time and the parameters (keys are
            coordinates or their names); an old coordinate that is also a new one may be left out.
        coordinates : sequence of Symbol or str
            The new (minimal) coordinates ``s``: Symbols, ``dynamicsymbols`` or names.
        """
        from ._analytic import reduce_coordinates

        return reduce_coordinates(self, parametrization, coordinates)

    # ------------------------------------------------------------------ sympy.physics.mechanics
    @classmethod
    def from_sympy(cls, model: Any, *, check: bool = True) -> LagrangianSystem:
        """The system of a ``sympy.physics.mechanics`` model: ``LagrangesMethod``, ``KanesMethod`` or ``System``.

        Frames, points, bodies, joints and loads built with SymPy come in through these objects, and get symosc's
        linearization, modal and Floquet analysis, Ince–Strutt diagrams and series.  A ``LagrangesMethod`` gives
        its Lagrangian (``T`` = the parts of degree 1 and 2 in the velocities, ``V`` = minus the rest); a
        ``KanesMethod`` or ``System`` gives the kinetic energy of its bodies (speeds replaced by coordinate rates
        through the kinematic differential equations), their ``potential_energy``, and, for a ``System`` (which has
        a fixed point), the potential of constant forces such as uniform gravity.  Other loads become generalized
        forces, configuration and velocity constraints holonomic and non-holonomic constraints.  Coordinates keep
        their names (as plain symbols).

        Parameters
        ----------
        model : sympy.physics.mechanics.LagrangesMethod, KanesMethod or System
            The model.  A ``KanesMethod`` or ``System`` needs its bodies; its equations are formed if they were not.
        check : bool
            For an unconstrained ``KanesMethod`` or ``System``: compare the accelerations of the imported system
            with the model's own at random states, and raise :class:`~symosc.errors.ModelError` when they differ (a
            velocity constraint imposed through a point velocity, which Lagrange's equations cannot see).

        Returns
        -------
        LagrangianSystem

        Raises
        ------
        ModelError
            An object of another type, no bodies, kinematic equations that do not fix the speeds, or (``check``)
            equations that differ from the model's.

        Examples
        --------
        A pendulum built from a frame, a point and a particle:

        >>> import sympy as sp
        >>> import sympy.physics.mechanics as me
        >>> q = me.dynamicsymbols("q")
        >>> m, l, g = sp.symbols("m l g", positive=True)
        >>> N = me.ReferenceFrame("N")
        >>> A = N.orientnew("A", "Axis", [q, N.z])
        >>> O = me.Point("O")
        >>> O.set_vel(N, 0)
        >>> P = O.locatenew("P", -l * A.y)
        >>> _ = P.v2pt_theory(O, N, A)
        >>> bob = me.Particle("bob", P, m)
        >>> bob.potential_energy = -m * g * l * sp.cos(q)
        >>> system = LagrangianSystem.from_sympy(me.LagrangesMethod(me.Lagrangian(N, bob), [q]))
        >>> system.mass_matrix, system.forcing
        (Matrix([[l**2*m]]), Matrix([[-g*l*m*sin(q)]]))

        See Also
        --------
        to_sympy
        """
        from ._sympy_mechanics import from_sympy_mechanics

        return from_sympy_mechanics(cls, model, check=check)

    def to_sympy(self) -> Any:
        """The system as a ``sympy.physics.mechanics.LagrangesMethod`` (coordinates as ``dynamicsymbols``).

        The Lagrangian is ``T - V``; each generalized force (with ``-dR/dq'`` of the dissipation function) is a load
        at a point of its own moving with ``q'_i`` along the inertial ``x`` axis, so that SymPy forms exactly
        ``Q_i``; the constraints are its ``hol_coneqs`` and ``nonhol_coneqs``.  ``LagrangianSystem.from_sympy`` of
        the result gives back the same mass matrix and forcing.

        Returns
        -------
        sympy.physics.mechanics.LagrangesMethod

        Examples
        --------
        >>> import sympy as sp
        >>> from symosc.models import n_link_pendulum
        >>> lm = n_link_pendulum(1).to_sympy()
        >>> lm.form_lagranges_equations().applyfunc(sp.trigsimp)
        Matrix([[l1*m1*(g*sin(phi1(t)) + l1*Derivative(phi1(t), (t, 2)))]])

        See Also
        --------
        from_sympy
        """
        from ._sympy_mechanics import to_sympy_mechanics

        return to_sympy_mechanics(self)

    # ------------------------------------------------------------------ numbers
    @cached_property
    def _simulation_cache(self) -> dict:
        """Compiled pieces :meth:`simulate` reuses (first-order form, energy); not pickled (a cached property)."""
        return {}

    @property
    def geometry(self) -> Any:
        """Points and lines for :meth:`Trajectory.animate <symosc.mechanics.Trajectory.animate>` (catalogue models set
        it; assign a :class:`~symosc.mechanics.Geometry` to animate any system); None when there is none."""
        value = self.__dict__.get("_geometry")
        if isinstance(value, DeferredGeometry):
            value = self.__dict__["_geometry"] = value.build()
        return value

    @geometry.setter
    def geometry(self, value: Any) -> None:
        self.__dict__["_geometry"] = value

    def simulate(
        self,
        t: Any,
        initial: Mapping[Any, Any] | Sequence[float],
        values: Mapping[Any, Any],
        *,
        method: str = "LSODA",
        rtol: float = 1e-9,
        atol: float = 1e-11,
        backend: str = "auto",
        geometry: Any = None,
    ):
        """Integrate the equations of motion and return a :class:`~symosc.mechanics.Trajectory`.

        The right-hand side and its analytic Jacobian are the compiled ones of :meth:`first_order` (generated C when
        a compiler exists); a prescribed motion such as a vibrating pivot is part of the equations, so it is
        simulated as it is.

        Parameters
        ----------
        t : array_like or float
            Output times (increasing; the motion starts at ``t[0]``), or a duration ``T`` (0..T, 1001 points).
        initial : mapping or array_like
            Coordinate name -> initial value; velocities ``"<name>_dot"`` (zero unless given).  An array is the
            full state ``(q, q')``.
        values : mapping
            Parameter values keyed by Symbol or name (for a vibrating pivot also ``a`` and ``p``).
        method : {"LSODA", "DOP853", "RK45", "Radau", "BDF"}
            Integrator: LSODA (``scipy.integrate.odeint``, switches to BDF with the analytic Jacobian when the
            problem is stiff), or a ``solve_ivp`` method (Radau and BDF use the analytic Jacobian).
        rtol, atol : float
            Relative and absolute tolerances.
        backend : {"auto", "c", "numpy"}
            Evaluator of the right-hand side (see :meth:`FirstOrderSystem.rhs`).
        geometry : Geometry, optional
            Points and lines for :meth:`Trajectory.animate`; default :attr:`geometry`.

        Returns
        -------
        Trajectory
            Times, coordinates and velocities by name, the energy (or Jacobi integral) and its drift when it is
            conserved.

        Raises
        ------
        ConvergenceError
            When the integrator cannot reach the last time.

        Examples
        --------
        >>> import numpy as np
        >>> from symosc.models import n_link_pendulum
        >>> pend = n_link_pendulum(2)
        >>> values = {"m1": 1.0, "m2": 1.0, "l1": 1.0, "l2": 1.0, "g": 9.81}
        >>> traj = pend.simulate(np.linspace(0, 5, 501), {"phi1": 0.3, "phi2": -0.2}, values, rtol=1e-11)
        >>> sorted(traj.q), bool(traj.energy_drift < 1e-8)
        (['phi1', 'phi2'], True)

        See Also
        --------
        first_order, symosc.mechanics.Trajectory
        """
        from .simulation import simulate_lagrangian

        if self.is_constrained:
            raise ModelError("simulate() needs an unconstrained system: call reduce_coordinates(...) first")
        return simulate_lagrangian(
            self, t, initial, values, method=method, rtol=rtol, atol=atol, backend=backend, geometry=geometry
        )

    def hamiltonian(self):
        """The Legendre transform: a :class:`~symosc.mechanics.HamiltonianSystem` (Bulgakov (1954), §3.11)."""
        from .analytic.hamiltonian import HamiltonianSystem

        return HamiltonianSystem.from_lagrangian(self)


def _times(a: sp.Expr, b: sp.Expr) -> sp.Expr:
    """``a * b``, without building a product when a factor is 1 (``sympy.Mul`` drops it: the result is the other)."""
    if a is sp.S.One:
        return b
    return a if b is sp.S.One else a * b


def _constant_sum(consts: dict[tuple[sp.Expr, ...], sp.Expr]) -> sp.Expr:
    """``sum(num * prod(factors))`` over ``factors -> num`` (factors taken from canonical products).

    Products with the same factors were merged by adding their numbers, as ``sympy.Add`` merges them; those whose
    numbers cancel are left out before any SymPy expression is built."""
    return sp.Add(*(num * _terms._product(c) for c, num in consts.items() if num != 0))


def _distribute(expr: sp.Expr, depends: Callable[[sp.Expr], bool]) -> list[sp.Expr]:
    """The additive terms of ``expr`` with every product distributed over its sums for which ``depends`` holds (sums
    of constants are kept whole); no other rewriting."""
    out: list[sp.Expr] = []
    for term in sp.Add.make_args(expr):
        if not term.is_Mul or not any(f.is_Add and depends(f) for f in term.args):
            out.append(term)
            continue
        parts: list[list[sp.Expr]] = [[]]
        for f in term.args:
            if f.is_Add and depends(f):
                inner = [x for a in f.args for x in _distribute(a, depends)]
                parts = [[*p, x] for p in parts for x in inner]
            else:
                for p in parts:
                    p.append(f)
        out.extend(sp.Mul(*p) for p in parts)
    return out


def _common_factor(c: sp.Expr) -> sp.Expr:
    """``c`` with the factors common to all its terms taken out: ``g*l1*m1 + g*l1*m2 -> g*l1*(m1 + m2)`` (powers of
    symbols and a common rational coefficient; a linear pass, unlike ``sympy.factor_terms``)."""
    if c.is_Mul:
        args = [_common_factor(f) if f.is_Add else f for f in c.args]
        return c if all(a is f for a, f in zip(args, c.args, strict=True)) else sp.Mul(*args)
    terms = sp.Add.make_args(c)
    if len(terms) < 2:
        return c
    split = []
    for term in terms:
        num, rest = term.as_coeff_Mul()
        powers: dict = {}
        for f in sp.Mul.make_args(rest):
            base, exp = (f.base, f.exp) if f.is_Pow and f.exp.is_Integer and f.exp > 0 else (f, sp.S.One)
            powers[base] = powers.get(base, 0) + exp
        split.append((num, powers))
    common = dict(split[0][1])
    for _, powers in split[1:]:
        common = {b: min(e, powers[b]) for b, e in common.items() if b in powers}
        if not common:
            break
    nums = [n for n, _ in split]
    num = abs(nums[0]) if nums[0].is_Rational and nums[0] != 0 and all(abs(n) == abs(nums[0]) for n in nums) else 1
    if all(n.is_negative for n in nums):  # -g*l1*(m1 + m2), not g*l1*(-m1 - m2)
        num = -num
    if not common and num == 1:
        return c

    def power(b: sp.Expr, e: Any) -> sp.Expr:
        return b if e == 1 else b**e

    inner = [
        sp.Mul(n / num, *(power(b, e - common.get(b, 0)) for b, e in powers.items() if e != common.get(b, 0)))
        for n, powers in split
    ]
    return sp.Mul(num, *(power(b, e) for b, e in common.items()), sp.Add(*inner))
