"""First-order (state-space) form of a Lagrangian system, and its numeric right-hand side."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from .._equality import ModelEquality
from .._printing import SymPyPrintable
from ..errors import ParameterError
from ..numeric import compile, resolve
from ..numeric._checks import check_all
from ..symbols import t

if TYPE_CHECKING:
    from .lagrange import LagrangianSystem

__all__ = ["FirstOrderSystem"]


class FirstOrderSystem(ModelEquality, SymPyPrintable):
    """x' = f(t, x) with the state x = (q, q').

    Symbolically the system is kept in descriptor form ``E(x, t) x' = G(x, t)`` with
    ``E = diag(I, M)`` and ``G = (q', F)`` (inverting M symbolically is rarely wise);
    :meth:`solved` gives the explicit form for small systems, :meth:`rhs` a fast numeric f(t, x)
    that solves ``M q'' = F`` at every call (NumPy/LAPACK or generated C) and :meth:`jacobian` its analytic
    Jacobian.

    Parameters
    ----------
    system : LagrangianSystem
        The Lagrangian system (unconstrained) whose equations ``M q'' = F`` are put in first-order form; usually built
        by :meth:`LagrangianSystem.first_order`.

    Examples
    --------
    >>> from scipy.integrate import solve_ivp
    >>> from symosc.models import n_link_pendulum
    >>> fo = n_link_pendulum(1).first_order()
    >>> fo
    FirstOrderSystem(state: phi1, phi1_dot; parameters: g, l1, m1; diag(I, M) x' = (q', F))
    >>> f = fo.rhs({"m1": 1.0, "l1": 1.0, "g": 9.81})
    >>> f(0.0, [0.1, 0.0]).round(4).tolist()
    [0.0, -0.9794]
    """

    def __init__(self, system: LagrangianSystem):
        self.system = system
        self._parts: dict[Any, Any] = {}  # generated code per (backend, jacobian); "program": the first Program

    def _equality_data(self) -> tuple:
        return self.system._equality_data()  # equal when the systems are (same equations)

    @property
    def state(self) -> tuple[sp.Symbol, ...]:
        return self.system.coordinates + self.system.velocities

    def __repr__(self) -> str:  # cheap: names only, the forcing is not formed
        names = ", ".join(s.name for s in self.state)
        params = ", ".join(s.name for s in self.system.parameters)
        kind = "rheonomic; " if self.system.is_rheonomic else ""
        return f"FirstOrderSystem({kind}state: {names}; parameters: {params}; diag(I, M) x' = (q', F))"

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
        """``[M | F]`` compiled with NumPy (arguments t, q, q', parameters)."""
        s = self.system
        both = s.mass_matrix.row_join(s.forcing)
        return compile(both, [t, *s.coordinates, *s.velocities, *s.parameters], name="mass_and_forcing")

    def rhs(self, values: Mapping[Any, Any], backend: str = "auto") -> Callable[[float, np.ndarray], np.ndarray]:
        """Numeric f(t, y) for ``scipy.integrate.solve_ivp``, with the parameters fixed to ``values``.

        Parameters
        ----------
        values : mapping
            Parameter values keyed by Symbol or name.  Checked once (missing, non-finite or wrongly
            signed values raise :class:`~symosc.errors.ParameterError`).
        backend : {"auto", "c", "llvm", "numpy"}
            ``"c"``: one call into generated C that evaluates M and F and solves ``M q'' = F`` by Gaussian
            elimination with partial pivoting (see :func:`symosc.numeric.compile` for the compiler and the disk
            cache).  ``"llvm"``: M and F by symengine's LLVM JIT, solved with LAPACK.  ``"numpy"``: M and F in
            Python (``math`` for one state, NumPy for a batch), solved with LAPACK.  ``"auto"`` (default): the
            fastest available -- ``"c"`` when a C compiler works, else ``"llvm"`` when symengine is installed,
            else ``"numpy"``; the result's ``.backend`` says which.  All agree to rounding.

        Returns
        -------
        callable
            ``f(t, y)`` for a state of shape ``(2n,)`` or a batch of shape ``(2n, k)`` (one state per
            column, as ``solve_ivp(..., vectorized=True)`` passes); the result has the same shape.  A
            singular mass matrix met during integration raises :class:`~symosc.errors.ModelError`.
            ``.backend`` is the backend used, ``.source`` the generated code.

        See Also
        --------
        jacobian, symosc.numeric.compile, symosc.codegen.export

        Notes
        -----
        Expressions that depend on the parameters alone are evaluated once, when ``values`` are bound; a call
        evaluates only what depends on t and the state.

        Examples
        --------
        >>> import numpy as np
        >>> from symosc.models import n_link_pendulum
        >>> fo = n_link_pendulum(1).first_order()
        >>> f = fo.rhs({"m1": 1.0, "l1": 1.0, "g": 9.81})
        >>> f(0.0, np.array([[0.1, 0.2], [0.0, 0.0]])).round(4).tolist()
        [[0.0, 0.0], [-0.9794, -1.9489]]
        >>> f.backend in ("c", "llvm", "numpy")
        True
        """
        backend = self._backend(backend)
        return _OdeFunction(self._evaluator(values, backend, jacobian=False), "rhs", self._size, backend)

    def jacobian(self, values: Mapping[Any, Any], backend: str = "auto") -> Callable[[float, np.ndarray], np.ndarray]:
        """Analytic Jacobian ``df/dy(t, y)`` of :meth:`rhs`, for stiff solvers (``solve_ivp(..., jac=...)``).

        With ``u = q'`` and ``f = (u, M^{-1} F)`` the lower block is
        ``M^{-1} (dF/dy - (dM/dy) M^{-1} F)``.  The derivatives are symbolic, taken on the shared expression graph
        of M and F (only the entries that can be non-zero; see :mod:`symosc.numeric`), the solves numeric.

        Parameters
        ----------
        values : mapping of Symbol or str to float
            One scalar value for every parameter of the system (keys are symbols or their names); checked once, so
            missing, non-finite or wrongly signed values raise ParameterError.
        backend : {"auto", "c", "llvm", "numpy"}, optional
            As in :meth:`rhs`: "auto" (the default) takes "c" when a C compiler is available, else "llvm", else
            "numpy".

        Returns
        -------
        callable
            ``jac(t, y)`` for a state of shape ``(2n,)``, giving a ``(2n, 2n)`` array; ``.backend`` says which
            backend evaluates it.

        See Also
        --------
        rhs

        Examples
        --------
        >>> from symosc.models import n_link_pendulum
        >>> jac = n_link_pendulum(1).first_order().jacobian({"m1": 1.0, "l1": 2.0, "g": 9.81})
        >>> jac(0.0, [0.0, 0.0]).tolist()
        [[0.0, 1.0], [-4.905, 0.0]]
        """
        backend = self._backend(backend)
        return _OdeFunction(self._evaluator(values, backend, jacobian=True), "jacobian", self._size, backend)

    @property
    def _size(self) -> int:
        return 2 * len(self.system.coordinates)

    @staticmethod
    def _backend(backend: str) -> str:
        from ..numeric import available_backends

        if backend not in ("auto", "c", "llvm", "numpy"):
            raise ParameterError(f"backend must be 'auto', 'c', 'llvm' or 'numpy', got {backend!r}")
        if backend == "auto":
            found = available_backends()
            return "c" if "c" in found else "llvm" if "llvm" in found else "numpy"
        return backend

    def _program(self, jacobian: bool) -> Any:
        """The :class:`~symosc.numeric._ode.Program` of the right-hand side or the Jacobian; the second one made
        extends the graph of the first (M and F are converted once)."""
        from ..numeric import _ode

        s = self.system
        base = self._parts.get("program")
        program = _ode.Program(s.mass_matrix, s.forcing, t, s.coordinates, s.velocities, s.parameters, jacobian, base)
        self._parts.setdefault("program", program)
        return program

    def _evaluator(self, values: Mapping[Any, Any], backend: str, jacobian: bool) -> Any:
        from ..numeric import _ode

        s = self.system
        params = check_all(s.parameters, tuple(resolve(s.parameters, values)), "numpy")
        if any(np.ndim(v) for v in params):
            raise ParameterError("rhs()/jacobian() take one scalar value per parameter")
        values = [float(v) for v in params]
        key = (backend, jacobian)
        parts = self._parts.get(key)
        if parts is None:
            if backend == "c":
                from ..numeric import _build

                items = [*s.mass_matrix, *s.forcing, t, *s.coordinates, *s.velocities, *s.parameters]
                tag = _build.expression_digest(items, "first_order", str(jacobian), str(len(s.coordinates)))
                parts = _build.memoized_source(tag, lambda: self._program(jacobian).c_source())
            else:
                program = self._program(jacobian)
                parts = (program, program.llvm_function() if backend == "llvm" else program.python_functions())
            self._parts[key] = parts
        n = len(s.coordinates)
        if backend == "c":
            return _ode.CFirstOrder(parts, n, values, jacobian=jacobian)
        return _ode.NumpyFirstOrder(*parts, values)

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
    ) -> Any:
        """Integrate ``x' = f(t, x)`` with the compiled :meth:`rhs` and :meth:`jacobian`; see
        :meth:`LagrangianSystem.simulate <symosc.mechanics.LagrangianSystem.simulate>` for the arguments.

        Parameters
        ----------
        t : array_like or float
            Output times, or a duration.
        initial : mapping or array_like
            Coordinate name (and ``"<name>_dot"``) -> initial value, or the full state.
        values : mapping
            Parameter values.
        method : {"LSODA", "DOP853", "RK45", "Radau", "BDF"}
            Integrator.
        rtol, atol : float
            Tolerances.
        backend : {"auto", "c", "numpy"}
            Evaluator of the right-hand side.

        Returns
        -------
        Trajectory

        Examples
        --------
        >>> from symosc.models import n_link_pendulum
        >>> fo = n_link_pendulum(1).first_order()
        >>> traj = fo.simulate(1.0, {"phi1": 0.1}, {"m1": 1.0, "l1": 1.0, "g": 9.81})
        >>> traj.t.size
        1001
        """
        return self.system.simulate(t, initial, values, method=method, rtol=rtol, atol=atol, backend=backend)

    def energy_function(self, values: Mapping[Any, Any]) -> Callable[[float, np.ndarray], float]:
        """Numeric E(t, x) = T + V with the parameters fixed (useful to check conservation).

        Parameters
        ----------
        values : mapping of Symbol or str to float
            One scalar value for every parameter of the system (keys are symbols or their names); checked once, so
            missing, non-finite or wrongly signed values raise ParameterError.
        """
        s = self.system
        fn = compile(s.energy, [t, *s.coordinates, *s.velocities, *s.parameters], name="energy")
        params = resolve(s.parameters, values)
        n = len(s.coordinates)
        fn(0.0, *([0.0] * (2 * n)), *params)  # checks the parameter values once
        params = [float(v) for v in params]
        return lambda time, x: float(fn.raw(time, *np.asarray(x, dtype=float), *params))


class _OdeFunction:
    """``f(t, y)`` (or ``jac(t, y)``) with the shape of ``y`` checked; ``.backend`` names the backend."""

    def __init__(self, evaluator: Any, kind: str, size: int, backend: str) -> None:
        self._ev, self._kind, self._size = evaluator, kind, size
        self.backend = backend
        self._call = evaluator.rhs if kind == "rhs" else evaluator.jacobian

    def __repr__(self) -> str:
        return f"<{self._kind} of a first-order system ({self._size} states), backend {self.backend!r}>"

    @property
    def source(self) -> str | None:
        """The generated code (C for backend "c", Python for "numpy", a symengine script for "llvm")."""
        return getattr(self._ev, "source", None)

    def __call__(self, time: float, y: Any) -> np.ndarray:
        y = np.asarray(y, dtype=float)
        if y.shape[:1] != (self._size,) or y.ndim > (2 if self._kind == "rhs" else 1):
            want = f"({self._size},) or ({self._size}, k)" if self._kind == "rhs" else f"({self._size},)"
            raise ParameterError(f"state y must have shape {want}, got {y.shape}")
        return self._call(time, y)
