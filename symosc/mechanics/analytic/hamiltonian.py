"""Hamiltonian systems: the Legendre transform and the canonical equations (Bulgakov (1954), §3.11-3.12)."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ..._equality import ModelEquality
from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from ...numeric import compile, resolve
from ...symbols import dot, sort_symbols, t

if TYPE_CHECKING:
    from ..lagrange import LagrangianSystem

__all__ = ["HamiltonianSystem", "poisson_bracket"]


def momentum_symbol(q: sp.Symbol) -> sp.Symbol:
    """The conjugate momentum symbol ``p_<q>`` of a coordinate."""
    return sp.Symbol(f"p_{q.name}", real=True)


@validated
def poisson_bracket(f: Any, g: Any, coordinates: Sequence[sp.Symbol], momenta: Sequence[sp.Symbol]) -> sp.Expr:
    """Poisson bracket ``{f, g} = sum (df/dq dg/dp - df/dp dg/dq)`` (Goldstein, Classical Mechanics, §9.5).

    Parameters
    ----------
    f : SymPy expression
        The first function of the coordinates and momenta (and time).
    g : SymPy expression
        The second function of the coordinates and momenta.
    coordinates : sequence of Symbol
        The canonical coordinates ``q``.
    momenta : sequence of Symbol
        The conjugate momenta ``p``, which must be as many as the coordinates (paired in order).

    Examples
    --------
    >>> import sympy as sp
    >>> q, p = sp.symbols("q p")
    >>> poisson_bracket(q, p, [q], [p])
    1

    See Also
    --------
    is_canonical
    """
    f, g = sp.sympify(f), sp.sympify(g)
    if len(coordinates) != len(momenta):
        raise ModelError(f"{len(coordinates)} coordinates but {len(momenta)} momenta")
    return sp.Add(*(f.diff(q) * g.diff(p) - f.diff(p) * g.diff(q) for q, p in zip(coordinates, momenta, strict=True)))


class HamiltonianSystem(ModelEquality, SymPyPrintable):
    """Canonical equations ``q' = dH/dp``, ``p' = -dH/dq + Q`` (Bulgakov (1954), eq. (3.117)).

    Parameters
    ----------
    H : Expr
        The Hamiltonian H(q, p, t).
    coordinates, momenta : sequence of Symbol
        Canonical coordinates q and momenta p (default momenta ``p_<q>``).
    forces : sequence of Expr, optional
        Non-conservative generalized forces Q(q, p, t) added to ``p'``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc import dot
    >>> from symosc.mechanics import LagrangianSystem
    >>> r, phi = sp.symbols("r phi", real=True)
    >>> m, k = sp.symbols("m k", positive=True)
    >>> h = LagrangianSystem(m / 2 * (dot(r) ** 2 + r**2 * dot(phi) ** 2), -k / r, [r, phi]).hamiltonian()
    >>> h.H
    -k/r + p_phi**2/(2*m*r**2) + p_r**2/(2*m)
    >>> h.equations()[1]
    Eq(phi_dot, p_phi/(m*r**2))

    See Also
    --------
    LagrangianSystem.hamiltonian, is_canonical, canonical_transformation
    """

    def __init__(
        self,
        H: Any,
        coordinates: Sequence[sp.Symbol],
        momenta: Sequence[sp.Symbol] | None = None,
        *,
        forces: Sequence[Any] | None = None,
    ) -> None:
        if H is None or isinstance(H, str | bytes):
            raise ParameterError(f"H must be a SymPy expression (build it from symbols, not text), got {H!r}")
        self._H = sp.sympify(H)
        self._q = _symbols("coordinates", coordinates)
        self._p = _symbols("momenta", momenta) if momenta is not None else tuple(momentum_symbol(q) for q in self._q)
        if forces is not None and (isinstance(forces, str | bytes) or not hasattr(forces, "__iter__")):
            raise ParameterError(f"forces must be a sequence of expressions (one per coordinate), got {forces!r}")
        if len(self._q) != len(self._p):
            raise ModelError(f"{len(self._q)} coordinates but {len(self._p)} momenta")
        if len(set(self._q) | set(self._p)) != 2 * len(self._q):
            raise ModelError("coordinates and momenta must be distinct symbols")
        self._Q = tuple(sp.sympify(f) for f in forces) if forces is not None else (sp.S.Zero,) * len(self._q)
        if len(self._Q) != len(self._q):
            raise ModelError(f"expected {len(self._q)} forces, got {len(self._Q)}")

    def _equality_data(self) -> tuple:
        return (self._q, self._p), (self._H, *self._Q)

    @classmethod
    def from_lagrangian(cls, system: LagrangianSystem) -> HamiltonianSystem:
        """Legendre transform of a natural system ``T = 1/2 q'^T M q' + b^T q' + T0``:
        ``H = 1/2 (p - b)^T M^-1 (p - b) - T0 + V`` (Bulgakov (1954), eq. (3.116))."""
        if system.is_constrained:
            raise ModelError("the Legendre transform needs an unconstrained system: call reduce_coordinates first")
        q, qd = system.coordinates, system.velocities
        p = [momentum_symbol(x) for x in q]
        M = system.mass_matrix
        _, T1, T0 = system.kinetic_energy_parts
        b = sp.Matrix([T1.diff(v) for v in qd])
        Minv = M.inv(method="LU")
        Minv = Minv.applyfunc(sp.cancel) if len(q) <= 3 else Minv
        w = sp.Matrix(p) - b
        v = Minv * w
        H = (w.T * v)[0] / 2 - T0 + system.potential_energy
        H = sp.expand(H) if len(q) <= 3 else H
        vel = dict(zip(qd, v, strict=True))
        forces = []
        for k, Qk in enumerate(system.forces):
            f = Qk - system.dissipation.diff(qd[k]) if system.dissipation != 0 else Qk
            forces.append(f.xreplace(vel))
        return cls(H, q, p, forces=forces)

    # ------------------------------------------------------------------ data
    @property
    def H(self) -> sp.Expr:
        """The Hamiltonian."""
        return self._H

    @property
    def coordinates(self) -> tuple[sp.Symbol, ...]:
        return self._q

    @property
    def momenta(self) -> tuple[sp.Symbol, ...]:
        return self._p

    @property
    def forces(self) -> tuple[sp.Expr, ...]:
        return self._Q

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        syms = set(self._H.free_symbols).union(*(f.free_symbols for f in self._Q))
        return sort_symbols(syms - set(self._q) - set(self._p) - {t})

    def __repr__(self) -> str:
        return f"HamiltonianSystem(H = {self._H}; coordinates: {', '.join(map(str, self._q))})"

    def _repr_latex_(self) -> str:
        return f"$$H = {sp.latex(self._H)}$$"

    def _latex(self, printer: Any) -> str:
        return f"H = {printer._print(self._H)}"

    # ------------------------------------------------------------------ equations
    @cached_property
    def vector_field(self) -> sp.Matrix:
        """``(dH/dp, -dH/dq + Q)``: the right-hand side for the state ``(q, p)``."""
        H = self._H
        return sp.Matrix([H.diff(p) for p in self._p] + [-H.diff(q) + f for q, f in zip(self._q, self._Q, strict=True)])

    def equations(self) -> list[sp.Eq]:
        """Hamilton's canonical equations as ``Eq(dot(q), dH/dp)``, then ``Eq(dot(p), -dH/dq + Q)``."""
        lhs = [dot(q) for q in self._q] + [dot(p) for p in self._p]
        return [sp.Eq(a, b) for a, b in zip(lhs, self.vector_field, strict=True)]

    @property
    def state(self) -> tuple[sp.Symbol, ...]:
        return self._q + self._p

    def phase_space_lagrangian(self) -> sp.Expr:
        """``sum p q' - H``, whose Euler-Lagrange equations in ``(q, p)`` are the canonical equations
        (Helmholtz's form of Hamilton's principle; Bulgakov (1954), §3.12, eq. (3.124))."""
        return sp.Add(*(p * dot(q) for q, p in zip(self._q, self._p, strict=True))) - self._H

    def lagrangian(self) -> sp.Expr:
        """The inverse Legendre transform ``L(q, q', t)`` (H must be quadratic in the momenta)."""
        p = sp.Matrix(self._p)
        grad = sp.Matrix([self._H.diff(x) for x in self._p])
        hess = grad.jacobian(p).applyfunc(sp.cancel)
        if any(e.free_symbols & set(self._p) for e in hess):
            raise ModelError("lagrangian() needs H quadratic in the momenta")
        from ..constraints import generic_rank

        if generic_rank(hess) < hess.rows:
            raise ModelError("H is degenerate in the momenta (singular Hessian): no Legendre transform")
        v = sp.Matrix([dot(q) for q in self._q])
        p0 = grad.xreplace({x: 0 for x in self._p})
        psol = (hess.inv(method="LU").applyfunc(sp.cancel) * (v - p0)).applyfunc(sp.expand)
        sub = dict(zip(self._p, psol, strict=True))
        return sp.expand((p.T * v)[0].xreplace(sub) - self._H.xreplace(sub))

    def rhs(self, values: Mapping[Any, Any]) -> Callable[[float, np.ndarray], np.ndarray]:
        """Numeric ``f(t, x)``, ``x = (q, p)``, with the parameters fixed (for ``solve_ivp``).

        Parameters
        ----------
        values : mapping of Symbol or str to float
            One scalar value for every parameter of the Hamiltonian and the forces (keys are symbols or their names);
            checked once, so a missing or non-finite value raises ParameterError.
        """
        fn = compile(self.vector_field, [t, *self.state, *self.parameters], name="canonical")
        params = resolve(self.parameters, values)
        fn(0.0, *([0.5] * len(self.state)), *params)  # checks the parameter values once
        params = [float(v) for v in params]
        raw = fn.raw
        return lambda time, x: np.asarray(raw(time, *x, *params), dtype=float).ravel()


def _symbols(what: str, given: Any) -> tuple[sp.Symbol, ...]:
    """``given`` (a Symbol or a sequence of them) as a tuple of Symbols."""
    items = (given,) if isinstance(given, sp.Symbol) else given
    if isinstance(items, str | bytes) or not hasattr(items, "__iter__"):
        raise ParameterError(f"{what} must be a sequence of SymPy Symbols, got {given!r}")
    items = tuple(items)
    if not items or not all(isinstance(x, sp.Symbol) for x in items):
        raise ParameterError(f"{what} must be a non-empty sequence of SymPy Symbols, got {given!r}")
    return items
