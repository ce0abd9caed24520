"""Single shooting: the periodic solution as a fixed point of the period map (Seydel 2010, §7.3).

Unknowns: the initial state ``y0 = (q(0), q'(0))`` (and the period T of an autonomous problem).  Equations:
``phi(T; y0) - y0 = 0`` (and the phase condition ``f(y0_ref) . (y0 - y0_ref) = 0``: the start lies on the plane
through the previous point orthogonal to the flow).  The flow, its monodromy matrix ``X = d phi / d y0`` and its
parameter sensitivities ``S = d phi / dp`` come from one integration of ``y' = f``, ``X' = A X``,
``S' = A S + f_p`` with the compiled ``f``, ``A = df/dy`` and ``f_p``; the Jacobian is exact up to the integration
tolerance and the Floquet multipliers are the eigenvalues of ``X``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import sympy as sp

from .._printing import SymPyPrintable
from .._validate import check_bool, check_choice, check_int, check_positive, validated
from ..errors import ConvergenceError, ParameterError
from ._model import PeriodicModel, build_model
from ._problem import Formulation, PointData, checked_arguments

__all__ = ["Shooting", "shooting"]

INTEGRATORS = ("DOP853", "Radau", "LSODA", "RK45", "BDF")


class Shooting(Formulation, SymPyPrintable):
    """A shooting problem for periodic solutions; build it with :func:`shooting`.

    Solve one point with :meth:`solve`, change parameter values with :meth:`with_values`, or follow a branch with
    :func:`~symosc.continuation.continue_periodic`.

    Parameters
    ----------
    model : PeriodicModel
        The equations ``M(q, t) q'' = F(q, q', t)`` with their parameters, exactly as :func:`shooting` builds them
        from the user's model (not constructed by hand).
    values : ndarray of float, shape (number of parameters,)
        Values of the model's parameters in the order of :attr:`parameters`: finite numbers, nan for a value not
        given yet (the continuation parameter).
    rtol : float
        Relative tolerance of the integrations: a positive number (the absolute tolerance is ``rtol * 1e-2``).
    integrator : {"DOP853", "Radau", "LSODA", "RK45", "BDF"}
        The ``scipy.integrate.solve_ivp`` method: one of these names (Radau or BDF for stiff orbits).
    period_multiple : int, optional
        The response period in forcing periods, m: an integer >= 1 (1 for an autonomous problem; default 1).

    Attributes
    ----------
    parameters : tuple of Symbol
        Every parameter of the model (the forcing frequency included), in the order of ``values``.
    equations : str
        The equations of motion as text.
    autonomous : bool
        Whether the oscillations are self-excited (the period is an unknown).

    The arguments are kept as attributes of the same names.
    """

    method = "shooting"

    def __init__(
        self, model: PeriodicModel, values: np.ndarray, rtol: float, integrator: str, period_multiple: int = 1
    ) -> None:
        values, period_multiple = checked_arguments(model, values, period_multiple)
        self.model = model
        self.values = values
        self.rtol = check_positive("rtol", rtol)
        self.tol = self.rtol
        self.integrator = check_choice("integrator", integrator, INTEGRATORS)
        self.period_multiple = period_multiple
        self.autonomous = model.autonomous
        self._w = None if model.autonomous else model.param_index(model.forcing_frequency)
        self._ref: np.ndarray | None = None
        self._cache: dict = {}

    def __getstate__(self) -> dict:
        return {k: (v if k != "_cache" else {}) for k, v in self.__dict__.items()}

    def __repr__(self) -> str:
        kind = "autonomous" if self.autonomous else f"forced by {self.model.forcing_frequency}"
        return f"Shooting({self.model.describe}; {kind}; {self.integrator}, rtol={self.rtol:g})"

    # ------------------------------------------------------------------ the driver's protocol (private)
    def _with_vector(self, p: np.ndarray) -> Shooting:
        return Shooting(self.model, p, self.rtol, self.integrator, self.period_multiple)

    def _at_size(self, size: int) -> Shooting:
        return self

    def _doubled(self):
        m = self.period_multiple if self.autonomous else 2 * self.period_multiple  # autonomous: T is an unknown
        new = Shooting(self.model, self.values, self.rtol, self.integrator, m)

        def embed(v: np.ndarray, tangent: bool = False) -> np.ndarray:
            v = np.array(v, dtype=float)
            if self.autonomous:
                v[-1] *= 2
            return v

        return new, embed

    # ------------------------------------------------------------------ layout
    def _period_of(self, u: np.ndarray, p: np.ndarray) -> float:
        return float(u[-1]) if self.autonomous else 2 * np.pi * self.period_multiple / float(p[self._w])

    def _frequency_of(self, u: np.ndarray, p: np.ndarray) -> float:
        return 2 * np.pi / self._period_of(u, p)

    def _flow(self, u: np.ndarray, p: np.ndarray, dense: bool = False):
        key = (u.tobytes(), p.tobytes(), dense)
        if key in self._cache:
            return self._cache[key]
        from scipy.integrate import solve_ivp

        f = self.model.first_order(p)
        d, npar = f.dim, f.npar
        y0 = u[:d]
        T = self._period_of(u, p)

        def rhs(tt: float, z: np.ndarray) -> np.ndarray:
            fy, A, fp = f.all(tt, z[:d])
            X = z[d : d + d * d].reshape(d, d)
            S = z[d + d * d :].reshape(d, npar)
            return np.concatenate([fy, (A @ X).ravel(), (A @ S + fp).ravel()])

        z0 = np.concatenate([y0, np.eye(d).ravel(), np.zeros(d * npar)])
        sol = solve_ivp(
            rhs, (0.0, T), z0, method=self.integrator, rtol=self.rtol, atol=self.rtol * 1e-2, dense_output=dense
        )
        if not sol.success:
            raise ConvergenceError(f"shooting: integration failed ({sol.message})")
        z = sol.y[:, -1]
        out = (z[:d], z[d : d + d * d].reshape(d, d), z[d + d * d :].reshape(d, npar), f, T, sol)
        if len(self._cache) > 8:
            self._cache.clear()
        self._cache[key] = out
        return out

    def _evaluate(self, u: np.ndarray, p: np.ndarray):
        d = 2 * self.model.n
        yT, X, S, f, T, _ = self._flow(u, p)
        G = yT - u[:d]
        J = X - np.eye(d)
        Gp = S.copy()
        fT = f.all(T, yT)[0]
        if self.autonomous:
            ref = self._ref if self._ref is not None else u
            nrm = f.all(0.0, ref[:d])[0]
            G = np.append(G, nrm @ (u[:d] - ref[:d]))
            Ju = np.zeros((d + 1, d + 1))
            Ju[:d, :d] = J
            Ju[:d, d] = fT
            Ju[d, :d] = nrm
            return G, Ju, np.vstack([Gp, np.zeros((1, Gp.shape[1]))])
        # the period 2 pi m / w depends on the forcing frequency
        Gp[:, self._w] += fT * (-T / float(p[self._w]))
        return G, J, Gp

    def _begin_step(self, u: np.ndarray) -> None:
        self._ref = np.array(u, dtype=float)

    def _point(self, u: np.ndarray, p: np.ndarray, *, stability: bool = True) -> PointData:
        d = 2 * self.model.n
        yT, X, _, _, T, sol = self._flow(u, p, dense=True)
        amps = _dense_maxima(sol.sol, T, self.model.n)
        rho = np.linalg.eigvals(X) if stability else np.array([])
        if rho.size:
            rho = rho[np.lexsort((-rho.imag, -np.abs(rho)))]
        res = float(np.linalg.norm(yT - u[:d]) / (1 + np.linalg.norm(u[:d])))
        return PointData(amps, 2 * np.pi / T, res, rho, None, u[:d].copy(), int(len(sol.t) - 1))

    # ------------------------------------------------------------------ one point
    def _initial(self, guess: Any, frequency: float | None) -> np.ndarray:
        from .branch import PeriodicSolution

        d = 2 * self.model.n
        if isinstance(guess, PeriodicSolution):
            y0 = np.asarray(guess.initial_state, dtype=float)
            T = guess.period
        elif guess is not None:
            y0 = np.asarray(guess, dtype=float).ravel()
            if y0.size not in (d, d + 1):
                raise ParameterError(f"guess must be an initial state of size {d} (and a period), got {y0.size}")
            T = float(y0[d]) if y0.size == d + 1 else (2 * np.pi / frequency if frequency else None)
            y0 = y0[:d]
        else:
            raise ParameterError("shooting needs a guess: a PeriodicSolution (e.g. from harmonic balance) or a state")
        if self.autonomous:
            if T is None:
                raise ParameterError("an autonomous shooting problem needs a period guess")
            return np.append(y0, T)
        return y0

    def solve(self, guess: Any = None, *, values: Mapping[Any, Any] | None = None, max_iterations: int = 30):
        """Solve for one periodic solution by Newton's method from ``guess``.

        Parameters
        ----------
        guess : PeriodicSolution or array
            Starting point (required): a solution of any formulation, or an initial state ``(q, q')`` of size 2n
            (with the period appended for an autonomous problem).
        values : mapping of Symbol or str to float, optional
            Parameter values that replace the problem's for this solve: finite numbers keyed by parameter Symbol or
            name (see :meth:`with_values`).
        max_iterations : int, optional
            Newton iterations: an integer >= 1 (default 30).

        Returns
        -------
        PeriodicSolution

        Raises
        ------
        ParameterError
            No guess, or a state of the wrong size.
        ConvergenceError
            Newton's method or an integration does not converge.
        """
        from ._solve import solution_from

        check_int("max_iterations", max_iterations, minimum=1)
        prob = self.with_values(values) if values is not None else self
        u, prob = prob._converge(guess, max_iterations=max_iterations)
        return solution_from(prob, u, prob.values, prob._point(u, prob.values))

    def _converge(self, guess: Any, frequency: float | None = None, *, max_iterations: int = 30):
        """Converged unknowns at the problem's values (and the problem)."""
        from ._solve import newton

        u0 = self._initial(guess, frequency)
        self._begin_step(u0)
        return newton(self, u0, self.values, max_iterations=max_iterations, tol=1e-11), self


def _dense_maxima(interp: Any, T: float, n: int) -> np.ndarray:
    """``max |q_i|`` over [0, T] from a dense interpolant: a grid, then a finer grid and a parabola at the maximum."""
    tt = np.linspace(0.0, T, 1025)
    y = np.abs(interp(tt)[:n])
    out = np.empty(n)
    h = tt[1] - tt[0]
    for i in range(n):
        j = int(np.argmax(y[i]))
        fine = np.linspace(max(tt[j] - h, 0.0), min(tt[j] + h, T), 65)
        yf = np.abs(interp(fine)[i])
        k = int(np.clip(np.argmax(yf), 1, len(fine) - 2))
        a, b, c = yf[k - 1], yf[k], yf[k + 1]
        den = a - 2 * b + c
        out[i] = max(b - (a - c) ** 2 / (8 * den) if den < 0 else b, y[i].max())
    return out


@validated
def shooting(
    acceleration: Any,
    x: Any = None,
    v: Any = None,
    t: Any = None,
    *,
    forcing_frequency: sp.Symbol | None = None,
    autonomous: bool = False,
    values: Mapping[Any, Any] | None = None,
    rtol: float = 1e-11,
    integrator: str = "DOP853",
    period_multiple: int = 1,
) -> Shooting:
    """Set up single shooting for the periodic solutions of an oscillator (same model input as harmonic balance).

    Parameters
    ----------
    acceleration : Expr, sequence of Expr, LagrangianSystem or FirstOrderSystem
        The equations, as for :func:`harmonic_balance` (a Lagrangian system needs at most 3 coordinates here).
    x, v : Symbol or sequence of Symbol
        Coordinates and velocities used in ``acceleration``: SymPy Symbols, one of each per coordinate (not needed
        for a system).
    t : Symbol, optional
        The time symbol: a SymPy Symbol (default :data:`symosc.t`).
    forcing_frequency : Symbol, optional
        The angular-frequency symbol of the forcing (``w`` in ``F*cos(w*t)``): a Symbol of the equations; required
        unless ``autonomous``.
    autonomous : bool, optional
        Whether the oscillations are self-excited (the period is an unknown): True or False (default False).
    values : mapping of Symbol or str to float, optional
        Values of the model's parameters: finite numbers keyed by Symbol or name; the continuation parameter may be
        left out.
    rtol : float, optional
        Relative tolerance of the integrations: a positive number (default 1e-11; absolute tolerance ``rtol * 1e-2``).
    integrator : {"DOP853", "Radau", "LSODA", "RK45", "BDF"}, optional
        The ``scipy.integrate.solve_ivp`` method: one of these names (default "DOP853"; Radau or BDF for stiff
        relaxation oscillations).
    period_multiple : int, optional
        The response period in forcing periods, m: an integer >= 1 (1 for an autonomous problem; default 1).

    Returns
    -------
    Shooting

    See Also
    --------
    harmonic_balance, collocation, continue_periodic

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.continuation import harmonic_balance, shooting
    >>> x, v, t, w = sp.symbols("x v t w")
    >>> a = -0.1 * v - x - x**3 + sp.cos(w * t)
    >>> hb = harmonic_balance(a, x, v, t, forcing_frequency=w, values={"w": 2.0})
    >>> sh = shooting(a, x, v, t, forcing_frequency=w, values={"w": 2.0})
    >>> s1, s2 = hb.solve(), sh.solve(hb.solve())
    >>> abs(s1.amplitude - s2.amplitude) < 1e-9
    True
    """
    autonomous = check_bool("autonomous", autonomous)
    rtol = check_positive("rtol", rtol)
    check_choice("integrator", integrator, INTEGRATORS)
    period_multiple = check_int("period_multiple", period_multiple, minimum=1)
    if values is not None and not isinstance(values, Mapping):
        raise ParameterError(f"values must be a mapping from parameter to number, got {values!r}")
    model = build_model(acceleration, x, v, t, forcing_frequency=forcing_frequency, autonomous=autonomous)
    p = model.values_vector(values or {}, skip=model.params)
    return Shooting(model, p, rtol, integrator, period_multiple)
