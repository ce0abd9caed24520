"""First-order (state-space) form of a Lagrangian system, and its numeric right-hand side."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ..errors import ModelError
from ..numeric import compile, resolve
from ..symbols import t

if TYPE_CHECKING:
    from .lagrange import LagrangianSystem

__all__ = ["FirstOrderSystem"]


class FirstOrderSystem:
    """x' = f(t, x) with the state x = (q, q').

    Symbolically the system is kept in descriptor form ``E(x, t) x' = G(x, t)`` with
    ``E = diag(I, M)`` and ``G = (q', F)`` (inverting M symbolically is rarely wise);
    :meth:`solved` gives the explicit form for small systems and :meth:`rhs` a fast numeric f(t, x)
    that solves ``M q'' = F`` with LAPACK at every call.

    Examples
    --------
    >>> from scipy.integrate import solve_ivp
    >>> from symosc.models import n_link_pendulum
    >>> fo = n_link_pendulum(1).first_order()
    >>> [s.name for s in fo.state]
    ['phi1', 'phi1_dot']
    >>> f = fo.rhs({"m1": 1.0, "l1": 1.0, "g": 9.81})
    >>> f(0.0, [0.1, 0.0]).round(4).tolist()
    [0.0, -0.9794]
    """

    def __init__(self, system: LagrangianSystem):
        self.system = system

    @property
    def state(self) -> tuple[sp.Symbol, ...]:
        return self.system.coordinates + self.system.velocities

    @cached_property
    def mass_matrix_full(self) -> sp.Matrix:
        """``diag(I, M)``."""
        n = len(self.system.coordinates)
        return sp.diag(sp.eye(n), self.system.mass_matrix)

    @cached_property
    def forcing_full(self) -> sp.Matrix:
        """``(q', F)``."""
        return sp.Matrix(list(self.system.velocities)).col_join(self.system.forcing)

    def solved(self) -> sp.Matrix:
        """Explicit right-hand side ``(q', M^-1 F)`` by symbolic LU (only sensible for small systems)."""
        qdd = self.system.mass_matrix.LUsolve(self.system.forcing)
        return sp.Matrix(list(self.system.velocities)).col_join(qdd)

    @cached_property
    def _compiled(self):
        s = self.system
        both = s.mass_matrix.row_join(s.forcing)
        return compile(both, [t, *s.coordinates, *s.velocities, *s.parameters], name="mass_and_forcing")

    def rhs(self, values: Mapping[Any, Any]) -> Callable[[float, np.ndarray], np.ndarray]:
        """Numeric f(t, x) for ``scipy.integrate.solve_ivp``, with the parameters fixed to ``values``.

        Parameters are checked once (missing, non-finite or wrongly signed values raise
        :class:`~symosc.errors.ParameterError`); a singular mass matrix met during integration raises
        :class:`~symosc.errors.ModelError`.
        """
        s = self.system
        n = len(s.coordinates)
        fn = self._compiled
        params = resolve(s.parameters, values)
        # Validate parameter values through the checked path once.
        fn(0.0, *([0.0] * (2 * n)), *params)
        params = [float(v) for v in params]
        raw = fn.raw

        def f(time: float, x: np.ndarray) -> np.ndarray:
            x = np.asarray(x, dtype=float)
            mf = raw(time, *x, *params)
            try:
                qdd = np.linalg.solve(mf[:, :n], mf[:, n])
            except np.linalg.LinAlgError as exc:
                raise ModelError(f"mass matrix is singular at t={time}, state={x.tolist()}") from exc
            return np.concatenate([x[n:], qdd])

        return f

    def energy_function(self, values: Mapping[Any, Any]) -> Callable[[float, np.ndarray], float]:
        """Numeric E(t, x) = T + V with the parameters fixed (useful to check conservation)."""
        s = self.system
        fn = compile(s.energy, [t, *s.coordinates, *s.velocities, *s.parameters], name="energy")
        params = resolve(s.parameters, values)
        n = len(s.coordinates)
        fn(0.0, *([0.0] * (2 * n)), *params)  # checks the parameter values once
        params = [float(v) for v in params]
        return lambda time, x: float(fn.raw(time, *np.asarray(x, dtype=float), *params))
