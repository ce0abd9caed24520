"""Harmonic balance: periodic solutions as truncated Fourier series, with exact Jacobians (Krack & Gross 2019).

The equations ``M(q, t) q'' = F(q, q', t)`` are written in the phase ``tau = omega t``; the residual
``r(tau) = M omega**2 q_tautau - F(q, omega q_tau, tau)`` of the series ``q = a0 + sum a_k cos k tau + b_k sin k tau``
is projected on the same harmonics (Galerkin).  ``r`` and its derivatives with respect to ``q, q_tau, q_tautau``,
``omega`` and every parameter are SymPy expressions compiled once (C backend when a compiler works) and evaluated at
all samples of the period in one call (alternating frequency-time).  For a polynomial nonlinearity the number of
samples is chosen alias-free, so residual and Jacobian are the exact Fourier convolution; otherwise the period is
8x oversampled.  Forced problems have ``omega = w / m`` (``m = period_multiple`` for subharmonic responses);
autonomous ones have ``omega`` as an unknown and Doedel's integral phase condition.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import sympy as sp

from .._printing import SymPyPrintable
from .._validate import check_bool, check_int, check_positive, validated
from ..errors import ConvergenceError, ParameterError
from . import _fourier
from ._model import PeriodicModel, build_model
from ._problem import Formulation, PointData, checked_arguments
from ._solve import _sorted_multipliers, newton, solution_from

__all__ = ["HarmonicBalance", "harmonic_balance"]

_START_HARMONICS = 3
_MAX_HARMONICS = 400


class HarmonicBalance(Formulation, SymPyPrintable):
    """A harmonic-balance problem: the model, fixed parameter values and the truncation.

    Build it with :func:`harmonic_balance`; solve one point with :meth:`solve`, change parameter values with
    :meth:`with_values`, or follow a branch with :func:`~symosc.continuation.continue_periodic`.

    Parameters
    ----------
    model : PeriodicModel
        The equations ``M(q, t) q'' = F(q, q', t)`` with their parameters, exactly as :func:`harmonic_balance`
        builds them from the user's model (not constructed by hand).
    values : ndarray of float, shape (number of parameters,)
        Values of the model's parameters in the order of :attr:`parameters`: finite numbers, nan for a value not
        given yet (the continuation parameter).
    harmonics : int
        Number of harmonics H of the truncation: an integer from 1 to 800 (:func:`harmonic_balance` allows up to
        400; a period doubling doubles them).
    adaptive : bool
        Whether H grows (by half, up to 400) until the relative residual meets ``tol``: True or False.
    tol : float
        Requested relative residual ``max |M q'' - F| / max(|M q''|, |F|)`` of the truncated series in the equations
        of motion: a positive number.
    period_multiple : int, optional
        The response period in forcing periods, m: an integer >= 1 (1 for an autonomous problem; default 1).

    Attributes
    ----------
    parameters : tuple of Symbol
        Every parameter of the model (the forcing frequency included), in the order of ``values``.
    equations : str
        The equations of motion as text.
    autonomous : bool
        Whether the oscillations are self-excited (the frequency is an unknown).
    samples : int
        Time samples per period of the alternating frequency-time evaluation.
    exact : bool
        Whether that evaluation is alias-free (a polynomial nonlinearity: the exact Fourier convolution).

    The arguments are kept as attributes of the same names.
    """

    method = "harmonic balance"

    def __init__(
        self,
        model: PeriodicModel,
        values: np.ndarray,
        harmonics: int,
        adaptive: bool,
        tol: float,
        period_multiple: int = 1,
    ) -> None:
        values, period_multiple = checked_arguments(model, values, period_multiple)
        self.model = model
        self.values = values
        self.harmonics = check_int("harmonics", harmonics, minimum=1, maximum=2 * _MAX_HARMONICS)
        self.adaptive = check_bool("adaptive", adaptive)
        self.tol = check_positive("tol", tol)
        self.period_multiple = period_multiple
        self.autonomous = model.autonomous
        fn, degree = model.hb_function(self.period_multiple)
        self._raw = fn.raw
        self.backend = fn.backend
        self.polynomial_degree = degree
        self.samples = _fourier.sample_count(self.harmonics, degree)
        self._ref: np.ndarray | None = None
        self._w = None if model.autonomous else model.param_index(model.forcing_frequency)

    def __getstate__(self) -> dict:
        return {k: v for k, v in self.__dict__.items() if k != "_raw"}

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._raw = self.model.hb_function(self.period_multiple)[0].raw

    # ------------------------------------------------------------------ description
    @property
    def exact(self) -> bool:
        """True when the alternating frequency-time evaluation is alias-free (polynomial nonlinearity)."""
        return self.polynomial_degree is not None

    def __repr__(self) -> str:
        kind = "autonomous" if self.autonomous else f"forced by {self.model.forcing_frequency}"
        if self.period_multiple > 1:
            kind += f", period x{self.period_multiple}"
        vals = ", ".join(f"{s.name}={v:g}" for s, v in zip(self.parameters, self.values, strict=True) if np.isfinite(v))
        H = f"H={self.harmonics}{' (adaptive)' if self.adaptive else ''}"
        how = "exact convolution" if self.exact else "oversampled AFT"
        vals = f"; {vals}" if vals else ""
        return f"HarmonicBalance({self.equations}; {kind}; {H}, {self.samples} samples, {how}{vals})"

    # ------------------------------------------------------------------ the driver's protocol (private)
    def _with_vector(self, p: np.ndarray) -> HarmonicBalance:
        return HarmonicBalance(self.model, p, self.harmonics, self.adaptive, self.tol, self.period_multiple)

    def _with_harmonics(self, harmonics: int, period_multiple: int | None = None) -> HarmonicBalance:
        m = self.period_multiple if period_multiple is None else period_multiple
        return HarmonicBalance(self.model, self.values, harmonics, self.adaptive, self.tol, m)

    def _at_size(self, size: int) -> HarmonicBalance:
        """The same problem with ``size`` harmonics (fixed)."""
        return HarmonicBalance(self.model, self.values, size, False, self.tol, self.period_multiple)

    def _doubled(self):
        """The doubled-period problem (2H harmonics of half the base frequency) and the embedding of unknowns."""
        H = self.harmonics
        new = HarmonicBalance(
            self.model,
            self.values,
            2 * H,
            False,
            self.tol,
            self.period_multiple if self.autonomous else 2 * self.period_multiple,
        )
        n = self.model.n

        def embed(v: np.ndarray, tangent: bool = False) -> np.ndarray:
            c = self._coefficients_of(v)
            out = np.zeros((n, 4 * H + 1))
            out[:, 0] = c[:, 0]
            out[:, 3::4] = c[:, 1::2]  # harmonic k -> 2k: a_k at index 2(2k)-1, b_k at 2(2k)
            out[:, 4::4] = c[:, 2::2]
            u = out.ravel()
            return np.append(u, v[-1] / 2) if self.autonomous else u

        return new, embed

    # ------------------------------------------------------------------ layout
    def _frequency_of(self, u: np.ndarray, p: np.ndarray) -> float:
        return float(u[-1]) if self.autonomous else float(p[self._w]) / self.period_multiple

    def _coefficients_of(self, u: np.ndarray) -> np.ndarray:
        n, m = self.model.n, 2 * self.harmonics + 1
        return np.asarray(u[: n * m]).reshape(n, m)

    def _pack(self, coefficients: np.ndarray, omega: float | None = None) -> np.ndarray:
        c = np.atleast_2d(np.asarray(coefficients, dtype=float))
        H = self.harmonics
        out = np.zeros((self.model.n, 2 * H + 1))
        k = min(c.shape[1], 2 * H + 1)
        out[: c.shape[0], :k] = c[:, :k]
        u = out.ravel()
        if self.autonomous:
            if omega is None:
                raise ParameterError("an autonomous problem needs a frequency guess")
            u = np.append(u, float(omega))
        return u

    def _transfer(self, v: np.ndarray, other: HarmonicBalance) -> np.ndarray:
        """``v`` (unknowns of this truncation) in the layout of ``other`` (more or fewer harmonics)."""
        c = self._coefficients_of(v)
        return other._pack(c, v[-1] if self.autonomous else None)

    # ------------------------------------------------------------------ residual and Jacobian
    def _pieces(self, c: np.ndarray, omega: float, p: np.ndarray, samples: int):
        n = self.model.n
        tau, E, _, P = _fourier.basis(self.harmonics, samples)
        B1, B2 = _fourier.derivative_bases(self.harmonics, samples)
        z, zd, zdd = E @ c.T, B1 @ c.T, B2 @ c.T
        out = np.asarray(self._raw(tau, *z.T, *zd.T, *zdd.T, omega, *p))
        N = samples
        nn = n * n
        r = out[:, :n]
        G = [out[:, n + i * nn : n + (i + 1) * nn].reshape(N, n, n) for i in range(3)]
        off = n + 3 * nn
        r_om = out[:, off : off + n]
        r_p = out[:, off + n :].reshape(N, n, -1)
        return (tau, E, B1, B2, P), r, G, r_om, r_p, (z, zd, zdd)

    def _evaluate(self, u: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        n, H = self.model.n, self.harmonics
        m = 2 * H + 1
        c = self._coefficients_of(u)
        omega = self._frequency_of(u, p)
        (_, E, B1, B2, P), r, G, r_om, r_p, _ = self._pieces(c, omega, p, self.samples)
        N = self.samples
        R = (P @ r).T.ravel()
        T = G[0][..., None] * E[:, None, None, :] + G[1][..., None] * B1[:, None, None, :]
        T = T + G[2][..., None] * B2[:, None, None, :]
        J = (P @ T.reshape(N, -1)).reshape(m, n, n, m).transpose(1, 0, 2, 3).reshape(n * m, n * m)
        R_om = (P @ r_om).T.ravel()
        R_p = (P @ r_p.reshape(N, -1)).reshape(m, n, -1).transpose(1, 0, 2).reshape(n * m, -1)
        if self.autonomous:
            ref = self._ref if self._ref is not None else u
            cr = self._coefficients_of(ref)
            dref = _fourier.derivative(cr).ravel()  # phase condition: integral of z . z_ref' = 0
            g = float(dref @ c.ravel())
            G_all = np.append(R, g)
            Ju = np.zeros((n * m + 1, n * m + 1))
            Ju[: n * m, : n * m] = J
            Ju[: n * m, -1] = R_om
            Ju[-1, : n * m] = dref
            Gp = np.vstack([R_p, np.zeros((1, R_p.shape[1]))])
            return G_all, Ju, Gp
        # forced: omega = w / m, so dR/dw gets dR/domega / m besides the explicit dependence on w
        R_p = R_p.copy()
        R_p[:, self._w] += R_om / self.period_multiple
        return R, J, R_p

    def _begin_step(self, u: np.ndarray) -> None:
        self._ref = np.array(u, dtype=float)

    # ------------------------------------------------------------------ point data
    def _defect(self, u: np.ndarray, p: np.ndarray) -> float:
        """Relative residual of the truncated series in the equations: ``max |r|`` over the period divided by the
        larger of ``max |M q''|`` and ``max |F|`` (the terms that balance)."""
        c = self._coefficients_of(u)
        omega = self._frequency_of(u, p)
        N = max(4 * self.samples, 64)
        _, r, G, _, _, (_, _, zdd) = self._pieces(c, omega, p, N)
        inertia = np.einsum("jik,jk->ji", G[2], zdd)  # M omega^2 q_tautau; the other terms are inertia - r
        scale = max(np.abs(inertia).max(), np.abs(inertia - r).max(), 1e-300)
        return float(np.abs(r).max() / scale)

    def _hill_matrices(self, u: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``D0`` (the Jacobian), ``D1``, ``D2`` of Hill's quadratic eigenvalue problem (see ``_fourier``)."""
        n, m = self.model.n, 2 * self.harmonics + 1
        c = self._coefficients_of(u)
        omega = self._frequency_of(u, p)
        (_, E, B1, B2, P), _, G, _, _, _ = self._pieces(c, omega, p, self.samples)
        N = self.samples
        C, Mp = G[1] / omega, G[2] / omega**2

        def project(T: np.ndarray) -> np.ndarray:
            return (P @ T.reshape(N, -1)).reshape(m, n, n, m).transpose(1, 0, 2, 3).reshape(n * m, n * m)

        D0 = project(
            G[0][..., None] * E[:, None, None, :]
            + G[1][..., None] * B1[:, None, None, :]
            + G[2][..., None] * B2[:, None, None, :]
        )
        D1 = project(C[..., None] * E[:, None, None, :] + 2 * omega * Mp[..., None] * B1[:, None, None, :])
        D2 = project(Mp[..., None] * E[:, None, None, :])
        return D0, D1, D2

    def _hill_multipliers(self, u: np.ndarray, p: np.ndarray) -> np.ndarray:
        """Floquet multipliers by Hill's method in the problem's truncation (Krack & Gross 2019, §4.1)."""
        omega = self._frequency_of(u, p)
        lam = _fourier.hill_exponents(*self._hill_matrices(u, p), self.model.n, omega)
        return _sorted_multipliers(np.exp(lam * 2 * np.pi / omega))

    def _point(self, u: np.ndarray, p: np.ndarray, *, stability: bool = True) -> PointData:
        c = self._coefficients_of(u)
        omega = self._frequency_of(u, p)
        zeta = _fourier.evaluate(c, [0.0])[0]
        zd = _fourier.evaluate(_fourier.derivative(c), [0.0])[0] * omega
        rho = self._hill_multipliers(u, p) if stability else np.array([])
        return PointData(
            amplitudes=_fourier.amplitudes(c),
            frequency=omega,
            residual=self._defect(u, p),
            multipliers=rho,
            coefficients=c.copy(),
            initial_state=np.concatenate([zeta, zd]),
            size=self.harmonics,
        )

    def _adapt(self, u: np.ndarray, p: np.ndarray, data: PointData):
        if data.residual <= self.tol:
            return None
        if not self.adaptive:
            where = ", ".join(f"{s.name}={v:.8g}" for s, v in zip(self.model.params, p, strict=True))
            raise ConvergenceError(
                f"harmonic balance with harmonics={self.harmonics} reaches a relative residual {data.residual:.2e} "
                f"> tol={self.tol:g} at {where}; pass harmonics=None (adaptive), more harmonics or a larger tol",
                achieved=data.residual,
            )
        H = self.harmonics
        if H >= _MAX_HARMONICS:
            raise ConvergenceError(
                f"harmonic balance: relative residual {data.residual:.2e} > tol={self.tol:g} with the maximum of "
                f"{H} harmonics; use shooting or collocation for this orbit",
                achieved=data.residual,
            )
        new = self._with_harmonics(min(_MAX_HARMONICS, int(np.ceil(1.5 * H)) + 1))
        return new, (lambda v, old=self: old._transfer(v, new))

    # ------------------------------------------------------------------ one point
    def solve(
        self,
        guess: Any = None,
        *,
        values: Mapping[Any, Any] | None = None,
        frequency: float | None = None,
        max_iterations: int = 50,
    ) -> PeriodicSolution:
        """Solve for one periodic solution by Newton's method (damped), growing H when adaptive.

        Parameters
        ----------
        guess : PeriodicSolution, LimitCycleSeries, array or None, optional
            Starting point: a solution of any formulation, a Poincaré series of :func:`symosc.nonlinear.limit_cycle`
            (evaluated at the problem's value of its small parameter), Fourier coefficients of shape ``(n, 2H'+1)``
            (any H'), or None (default) for the linearized response (forced) / first-harmonic guesses (autonomous).
        values : mapping of Symbol or str to float, optional
            Parameter values that replace the problem's for this solve: finite numbers keyed by parameter Symbol or
            name (see :meth:`with_values`).
        frequency : float, optional
            Angular-frequency guess (rad/s) of an autonomous problem: a positive number (default: the guess's, else
            the linearization's).
        max_iterations : int, optional
            Newton iterations per truncation: an integer >= 1 (default 50).

        Returns
        -------
        PeriodicSolution

        Raises
        ------
        ConvergenceError
            Newton's method does not converge, or the residual stays above ``tol`` (fixed H, or H at its maximum).

        Examples
        --------
        >>> import sympy as sp
        >>> from symosc.continuation import harmonic_balance
        >>> x, v, t, w = sp.symbols("x v t w")
        >>> hb = harmonic_balance(-0.1 * v - x - x**3 + sp.cos(w * t), x, v, t, forcing_frequency=w,
        ...                       values={"w": 2.0})
        >>> sol = hb.solve()
        >>> round(sol.amplitude, 6), sol.harmonics >= 3, sol.residual < 1e-9
        (0.342901, True, True)
        """
        check_int("max_iterations", max_iterations, minimum=1)
        if frequency is not None:
            frequency = check_positive("frequency", frequency)
        prob = self.with_values(values) if values is not None else self
        u, prob = prob._converge(guess, frequency, max_iterations=max_iterations)
        data = prob._point(u, prob.values)
        if data.residual > prob.tol:
            raise ConvergenceError(
                f"harmonic balance with {prob.harmonics} harmonics reaches a relative residual {data.residual:.2e} "
                f"> tol={prob.tol:g}; pass harmonics=None (adaptive) or more harmonics",
                achieved=data.residual,
            )
        return solution_from(prob, u, prob.values, data)

    def _converge(
        self, guess: Any, frequency: float | None = None, *, max_iterations: int = 50
    ) -> tuple[np.ndarray, HarmonicBalance]:
        """Converged unknowns at the problem's values and the (possibly refined) problem."""
        p = self.values
        if guess is None and self.autonomous:  # avoid the trivial solution: try amplitudes until a cycle is found
            last: Exception | None = None
            frequency = _linear_frequency(self) if frequency is None else frequency
            for amp in (1.0, 2.0, 0.5, 4.0, 0.25, 8.0, 0.1, 20.0):
                c = np.zeros((self.model.n, 3))
                c[0, 1] = amp
                try:
                    u, prob = self._converge(c, frequency, max_iterations=max_iterations)
                except ConvergenceError as exc:
                    last = exc
                    continue
                if np.max(np.abs(prob._coefficients_of(u)[:, 1:])) > 1e-8:
                    return u, prob
            raise ConvergenceError(
                "harmonic balance found no nontrivial periodic solution from first-harmonic guesses of amplitude "
                f"0.1 to 20 ({last}); give a guess"
            )
        prob = self
        given = getattr(guess, "coefficients", guess)
        H = (given.shape[1] - 1) // 2 if isinstance(given, np.ndarray) and given.ndim == 2 else 0
        if self.adaptive and H > self.harmonics:
            # start at the guess's truncation: cutting its harmonics can leave Newton's method far from the solution
            prob = self._with_harmonics(min(H, _MAX_HARMONICS))
        u0 = prob._initial(guess, frequency)
        while True:
            prob._begin_step(u0)
            u = newton(prob, u0, p, max_iterations=max_iterations)
            data = prob._point(u, p, stability=False)
            refined = prob._adapt(u, p, data)
            if refined is None:
                return u, prob
            prob, transfer = refined
            u0 = transfer(u)

    def _initial(self, guess: Any, frequency: float | None) -> np.ndarray:
        from .branch import PeriodicSolution

        n = self.model.n
        if isinstance(guess, PeriodicSolution):
            c = guess.coefficients if guess.coefficients is not None else _coefficients_from_state(self, guess)
            return self._pack(c, frequency or guess.frequency)
        if hasattr(guess, "eps_symbol") and hasattr(guess, "solution") and self.autonomous:
            c, om = _coefficients_from_series(self, guess)
            return self._pack(c, frequency or om)
        if guess is not None:
            c = np.atleast_2d(np.asarray(guess, dtype=float))
            if c.shape[0] != n or c.shape[1] % 2 != 1:
                raise ParameterError(f"guess must be Fourier coefficients of shape ({n}, 2H+1), got {c.shape}")
            return self._pack(c, frequency)
        if self.autonomous:
            c = np.zeros((n, 3))
            c[0, 1] = 1.0
            omega = frequency if frequency is not None else _linear_frequency(self)
            return self._pack(c, omega)
        # forced: the linear response about q = 0 (first harmonic), by one Newton step from zero
        u = self._pack(np.zeros((n, 1)))
        G, J, _ = self._evaluate(u, self.values)
        try:
            return u - np.linalg.solve(J, G)
        except np.linalg.LinAlgError:
            return u


def _linear_frequency(prob: HarmonicBalance) -> float:
    """Imaginary part of the linearization's eigenvalues at q = 0 (the oscillating pair), else 1."""
    f = prob.model.first_order(prob.values)
    _, A, _ = f.all(0.0, np.zeros(2 * prob.model.n))
    lam = np.linalg.eigvals(A)
    im = np.abs(lam.imag)
    return float(im[im > 1e-12].min()) if np.any(im > 1e-12) else 1.0


def _coefficients_from_state(prob: HarmonicBalance, sol: Any) -> np.ndarray:
    """Fourier coefficients of the orbit of a shooting/collocation solution (one period integrated from its state)."""
    from scipy.integrate import solve_ivp

    n = prob.model.n
    N = 4 * (2 * prob.harmonics + 1)
    p = prob._with_values(sol.values).values
    f = prob.model.first_order(p)
    tt = sol.period * np.arange(N) / N
    res = solve_ivp(f.rhs, (0.0, sol.period), sol.initial_state, t_eval=tt, method="DOP853", rtol=1e-11, atol=1e-13)
    _, _, _, P = _fourier.basis(prob.harmonics, N)
    return (P @ res.y[:n].T).T


def _coefficients_from_series(prob: HarmonicBalance, series: Any) -> tuple[np.ndarray, float]:
    """Fourier coefficients and frequency of a Poincaré series (``symosc.nonlinear.limit_cycle``) at the problem's
    value of its small parameter."""
    name = series.eps_symbol.name
    try:
        e = float(prob.values[prob.model.param_index(name)])
    except ParameterError as exc:
        raise ParameterError(f"guess: the series' parameter {name!r} is not a parameter of the problem") from exc
    tau = sp.Symbol("tau")
    expr = series.solution(series.order)
    fn = sp.lambdify([tau, series.eps_symbol], expr.subs(sp.Symbol("tau"), tau), "numpy")
    N = 4 * (2 * prob.harmonics + 1)
    grid = 2 * np.pi * np.arange(N) / N
    _, _, _, P = _fourier.basis(prob.harmonics, N)
    values = np.broadcast_to(np.asarray(fn(grid, e), dtype=float), grid.shape)
    return (P @ values).reshape(1, -1), float(series.frequency.evaluate(e))


@validated
def harmonic_balance(
    acceleration: Any,
    x: Any = None,
    v: Any = None,
    t: Any = None,
    *,
    forcing_frequency: sp.Symbol | None = None,
    autonomous: bool = False,
    values: Mapping[Any, Any] | None = None,
    harmonics: int | None = None,
    tol: float = 1e-8,
    period_multiple: int = 1,
) -> HarmonicBalance:
    """Set up harmonic balance for the periodic solutions of an oscillator.

    Parameters
    ----------
    acceleration : Expr, sequence of Expr, LagrangianSystem or FirstOrderSystem
        The equations: ``x'' = acceleration(x, v, t)`` as SymPy expressions in the coordinate(s) ``x``,
        velocity(ies) ``v``, time ``t`` and parameters (one expression per coordinate for several degrees of
        freedom), or a mechanical system whose equations ``M(q, t) q'' = F(q, q', t)`` are used as they are (time is
        :data:`symosc.t`).
    x, v : Symbol or sequence of Symbol
        Coordinates and velocities used in ``acceleration``: SymPy Symbols, one of each per coordinate (not needed
        for a system).
    t : Symbol, optional
        The time symbol: a SymPy Symbol (default :data:`symosc.t`).
    forcing_frequency : Symbol, optional
        The angular-frequency symbol of the forcing (``w`` in ``F*cos(w*t)``): a Symbol of the equations; required
        unless ``autonomous``.  The response has the forcing period (times ``period_multiple``).
    autonomous : bool, optional
        Whether the oscillations are self-excited (the frequency is an unknown, fixed by a phase condition): True or
        False (default False).
    values : mapping of Symbol or str to float, optional
        Values of the model's parameters: finite numbers keyed by Symbol or name; the continuation parameter may be
        left out and given by the span of :func:`~symosc.continuation.continue_periodic`.
    harmonics : int, optional
        Number of harmonics H: an integer from 1 to 400, or None (default) to choose H for the requested ``tol``
        (starting from 3, growing by half until the relative residual is below ``tol``; also along a branch).
    tol : float, optional
        Requested relative residual of the truncated series in the equations of motion,
        ``max |M q'' - F| / max(|M q''|, |F|)`` over the period: a positive number (default 1e-8).
    period_multiple : int, optional
        The response period in forcing periods, m: an integer >= 1 (subharmonics, period doubling; 1 for an
        autonomous problem; default 1).

    Returns
    -------
    HarmonicBalance

    Raises
    ------
    ParameterError
        Invalid arguments (named).
    ModelError
        A forcing frequency for equations that do not depend on time, or time dependence with ``autonomous=True``.

    See Also
    --------
    continue_periodic : follow the solutions in a parameter.
    shooting, collocation : the same problems by two independent methods.
    symosc.nonlinear.averaged_equations : the first-order averaging of the same oscillators.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.continuation import harmonic_balance
    >>> x, v, t, eps = sp.symbols("x v t eps")
    >>> vdp = harmonic_balance(eps * (1 - x**2) * v - x, x, v, t, autonomous=True, values={"eps": 0.1})
    >>> sol = vdp.solve()
    >>> round(sol.frequency, 8), round(sol.amplitude, 6)          # omega = 1 - eps^2/16 + ...
    (0.99937555, 2.000104)
    """
    autonomous = check_bool("autonomous", autonomous)
    tol = check_positive("tol", tol)
    period_multiple = check_int("period_multiple", period_multiple, minimum=1)
    adaptive = harmonics is None
    H = _START_HARMONICS if adaptive else check_int("harmonics", harmonics, minimum=1, maximum=_MAX_HARMONICS)
    if values is not None and not isinstance(values, Mapping):
        raise ParameterError(f"values must be a mapping from parameter (Symbol or name) to number, got {values!r}")
    if autonomous and forcing_frequency is not None:
        raise ParameterError("give either forcing_frequency= (forced) or autonomous=True, not both")
    model = build_model(acceleration, x, v, t, forcing_frequency=forcing_frequency, autonomous=autonomous)
    p = model.values_vector(values or {}, skip=model.params)
    if autonomous and period_multiple != 1:
        raise ParameterError("period_multiple must be 1 for an autonomous problem (its frequency is an unknown)")
    return HarmonicBalance(model, p, H, adaptive, tol, period_multiple)


from .branch import PeriodicSolution  # noqa: E402 - result type used in annotations
