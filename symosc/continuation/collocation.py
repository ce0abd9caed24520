"""Orthogonal collocation at Gauss points for periodic solutions (Doedel, AUTO; Ascher, Mattheij & Russell 1995).

In the normalized time ``s = t / T`` the orbit is a continuous piecewise polynomial of degree m on a mesh of N
intervals, required to satisfy ``y' = T f(T s, y)`` at the m Gauss–Legendre points of every interval and to be
periodic.  It is written in implicit Runge–Kutta form: unknowns are the mesh values ``Y_i`` and the stage
derivatives ``K_ij``, with ``K_ij = T f(t_ij, Y_i + h_i sum_l a_jl K_il)`` and
``Y_{i+1} = Y_i + h_i sum_j b_j K_ij`` (``Y_N = Y_0``), which is the same collocation solution (error
``O(h^(2m))`` at the mesh points).  An autonomous problem adds the period T and Doedel's integral phase condition.
The Jacobian is sparse and exact (the compiled ``A = df/dy`` and ``f_p`` at all stage points in one call); the
monodromy matrix is the product of the intervals' linearized transfer matrices.  When the relative defect of the
polynomial between the collocation points exceeds ``tol``, the mesh is refined (1.5 x intervals) and
redistributed to equidistribute ``|y^(m)|^(1/m)`` (de Boor's criterion).
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from .._printing import SymPyPrintable
from .._validate import check_bool, check_finite_array, check_int, check_positive, validated
from ..errors import ConvergenceError, ParameterError
from ._model import PeriodicModel, build_model
from ._problem import Formulation, PointData, checked_arguments

__all__ = ["Collocation", "collocation"]

_MAX_INTERVALS = 4000


@lru_cache(maxsize=8)
def gauss_tableau(m: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Gauss–Legendre nodes c, Runge–Kutta matrix a and weights b on [0, 1]."""
    x, _ = np.polynomial.legendre.leggauss(m)
    c = (x + 1) / 2
    a = np.empty((m, m))
    b = np.empty(m)
    for l in range(m):
        coef = np.poly1d([1.0])
        for j in range(m):
            if j != l:
                coef = coef * np.poly1d([1.0, -c[j]]) / (c[l] - c[j])
        integ = coef.integ()
        b[l] = integ(1.0) - integ(0.0)
        for j in range(m):
            a[j, l] = integ(c[j]) - integ(0.0)
    return c, a, b


def _checked_mesh(mesh: Any) -> np.ndarray:
    """The mesh as a float array after checking it increases strictly from 0 to 1 (1 to 4000 intervals)."""
    mesh = check_finite_array("mesh", mesh, ndim=1)
    if not 2 <= len(mesh) <= _MAX_INTERVALS + 1 or mesh[0] != 0.0 or mesh[-1] != 1.0 or np.any(np.diff(mesh) <= 0):
        raise ParameterError(
            f"mesh must increase strictly from 0 to 1 with 1 to {_MAX_INTERVALS} intervals, got {len(mesh)} points "
            f"from {mesh[0] if len(mesh) else 'nothing'} to {mesh[-1] if len(mesh) else 'nothing'}"
        )
    return mesh


def _lagrange(c: np.ndarray, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``ell_l(theta)`` and ``int_0^theta ell_l`` for the nodes c: arrays (len(theta), m)."""
    m = len(c)
    L = np.empty((len(theta), m))
    B = np.empty((len(theta), m))
    for l in range(m):
        coef = np.poly1d([1.0])
        for j in range(m):
            if j != l:
                coef = coef * np.poly1d([1.0, -c[j]]) / (c[l] - c[j])
        L[:, l] = coef(theta)
        B[:, l] = coef.integ()(theta) - coef.integ()(0.0)
    return L, B


class Collocation(Formulation, SymPyPrintable):
    """A collocation problem for periodic solutions; build it with :func:`collocation`.

    Solve one point with :meth:`solve`, change parameter values with :meth:`with_values`, or follow a branch with
    :func:`~symosc.continuation.continue_periodic`.

    Parameters
    ----------
    model : PeriodicModel
        The equations ``M(q, t) q'' = F(q, q', t)`` with their parameters, exactly as :func:`collocation` builds
        them from the user's model (not constructed by hand).
    values : ndarray of float, shape (number of parameters,)
        Values of the model's parameters in the order of :attr:`parameters`: finite numbers, nan for a value not
        given yet (the continuation parameter).
    mesh : ndarray of float
        Mesh points ``0 = s_0 < ... < s_N = 1`` of the normalized period: strictly increasing from 0 to 1, with 1 to
        4000 intervals.
    degree : int
        Collocation (Gauss) points per interval, the polynomial degree m: an integer from 1 to 10.
    tol : float
        Requested relative defect ``max |y' - T f(y)| / max |T f|`` between the collocation points: a positive
        number.
    adaptive : bool, optional
        Whether the mesh is refined and redistributed while the defect exceeds ``tol``: True (default) or False.
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
    N : int
        Number of mesh intervals.

    The arguments are kept as attributes of the same names.
    """

    method = "collocation"

    def __init__(
        self,
        model: PeriodicModel,
        values: np.ndarray,
        mesh: np.ndarray,
        degree: int,
        tol: float,
        adaptive: bool = True,
        period_multiple: int = 1,
    ) -> None:
        values, period_multiple = checked_arguments(model, values, period_multiple)
        self.model = model
        self.values = values
        self.mesh = _checked_mesh(mesh)
        self.degree = check_int("degree", degree, minimum=1, maximum=10)
        self.tol = check_positive("tol", tol)
        self.adaptive = check_bool("adaptive", adaptive)
        self.period_multiple = period_multiple
        self.autonomous = model.autonomous
        self._w = None if model.autonomous else model.param_index(model.forcing_frequency)
        self._ref: np.ndarray | None = None
        self.N = len(self.mesh) - 1
        self.d = 2 * model.n

    def __repr__(self) -> str:
        kind = "autonomous" if self.autonomous else f"forced by {self.model.forcing_frequency}"
        return f"Collocation({self.model.describe}; {kind}; {self.N} intervals x {self.degree} Gauss points)"

    # ------------------------------------------------------------------ the driver's protocol (private)
    def _with_vector(self, p: np.ndarray) -> Collocation:
        return Collocation(self.model, p, self.mesh, self.degree, self.tol, self.adaptive, self.period_multiple)

    def _weights(self, u: np.ndarray) -> np.ndarray:
        """Arclength weights: the mesh and stage values count as samples of a function (mean square)."""
        w = np.full(len(u), 1.0 / (self.N * (1 + self.degree)))
        if self.autonomous:
            w[-1] = 1.0
        return w

    def _period_of(self, u: np.ndarray, p: np.ndarray) -> float:
        return float(u[-1]) if self.autonomous else 2 * np.pi * self.period_multiple / float(p[self._w])

    def _frequency_of(self, u: np.ndarray, p: np.ndarray) -> float:
        return 2 * np.pi / self._period_of(u, p)

    def _split(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        N, m, d = self.N, self.degree, self.d
        Y = u[: N * d].reshape(N, d)
        K = u[N * d : N * d * (1 + m)].reshape(N, m, d)
        return Y, K

    def _stages(self, u: np.ndarray, p: np.ndarray):
        c, a, _ = gauss_tableau(self.degree)
        Y, K = self._split(u)
        h = np.diff(self.mesh)
        Z = Y[:, None, :] + h[:, None, None] * np.einsum("jl,ild->ijd", a, K)
        T = self._period_of(u, p)
        s = self.mesh[:-1, None] + c[None, :] * h[:, None]
        return Y, K, Z, T, s * T, h

    # ------------------------------------------------------------------ residual and Jacobian
    def _evaluate(self, u: np.ndarray, p: np.ndarray):
        import scipy.sparse as sps

        N, m, d = self.N, self.degree, self.d
        _, a, b = gauss_tableau(m)
        Y, K, Z, T, tt, h = self._stages(u, p)
        f = self.model.first_order(p)
        fv, A, fp = f.all(tt.ravel(), Z.reshape(-1, d))
        fv, A, fp = fv.reshape(N, m, d), A.reshape(N, m, d, d), fp.reshape(N, m, d, -1)
        stage = K - T * fv
        cont = np.roll(Y, -1, axis=0) - Y - h[:, None] * np.einsum("j,ijd->id", b, K)
        G = np.concatenate([stage.ravel(), cont.ravel()])
        rows, cols, vals = self._pattern(h, a, b)
        vals_sy = (-T * A).ravel()
        eye = np.eye(d)
        vals_sk = (
            np.eye(m)[None, :, None, :, None] * eye[None, None, :, None, :]
            - T * h[:, None, None, None, None] * a[None, :, None, :, None] * A[:, :, :, None, :]
        ).ravel()
        data = np.concatenate([vals_sy, vals_sk, vals])
        nrow = N * m * d + N * d
        ncol = N * d * (1 + m)
        Gp = np.zeros((nrow, fp.shape[-1]))
        Gp[: N * m * d] = (-T * fp).reshape(N * m * d, -1)
        if self.autonomous:
            ref = self._ref if self._ref is not None else u
            _, Kr = self._split(ref)
            wts = (h[:, None] * b[None, :])[:, :, None] * Kr  # d(phase)/dZ_ij
            phase = float(np.sum(wts * Z))
            dY = wts.sum(axis=1)
            dK = h[:, None, None] * np.einsum("ijd,jl->ild", wts, a)
            G = np.append(G, phase)
            colT = np.append(-fv.ravel(), np.zeros(N * d))
            J = sps.coo_matrix((data, (rows, cols)), shape=(nrow, ncol)).tocsr()
            J = sps.bmat([[J, colT.reshape(-1, 1)], [np.concatenate([dY.ravel(), dK.ravel()]).reshape(1, -1), None]])
            Gp = np.vstack([Gp, np.zeros((1, Gp.shape[1]))])
            return G, J.tocsc(), Gp
        J = sps.coo_matrix((data, (rows, cols)), shape=(nrow, ncol)).tocsc()
        # forcing frequency: T = 2 pi m / w and t = T s move with w; a central difference of the stage equations
        w = float(p[self._w])
        dw = 1e-6 * max(1.0, abs(w))
        cols_w = []
        for sgn in (1, -1):
            q = p.copy()
            q[self._w] = w + sgn * dw
            _, _, Zq, Tq, tq, _ = self._stages(u, q)
            cols_w.append(-(Tq * self.model.first_order(q).all(tq.ravel(), Zq.reshape(-1, d))[0]).ravel())
        Gp[: N * m * d, self._w] = (cols_w[0] - cols_w[1]) / (2 * dw)
        return G, J, Gp

    def _pattern(self, h: np.ndarray, a: np.ndarray, b: np.ndarray):
        """Row/column indices of the stage blocks and indices and values of the continuity rows."""
        N, m, d = self.N, self.degree, self.d
        key = (N, m, d)
        cache = self.__dict__.setdefault("_pat", {})
        if key not in cache:
            i, j, r, c = np.meshgrid(np.arange(N), np.arange(m), np.arange(d), np.arange(d), indexing="ij")
            row_sy = ((i * m + j) * d + r).ravel()
            col_sy = (i * d + c).ravel()
            i, j, r, l, c = np.meshgrid(*(np.arange(x) for x in (N, m, d, m, d)), indexing="ij")
            row_sk = ((i * m + j) * d + r).ravel()
            col_sk = (N * d + (i * m + l) * d + c).ravel()
            base = N * m * d
            ii, rr = np.meshgrid(np.arange(N), np.arange(d), indexing="ij")
            crow = base + ii * d + rr
            rows_c = [crow.ravel(), crow.ravel()]
            cols_c = [(((ii + 1) % N) * d + rr).ravel(), (ii * d + rr).ravel()]
            ii, jj, rr = np.meshgrid(np.arange(N), np.arange(m), np.arange(d), indexing="ij")
            rows_c.append((base + ii * d + rr).ravel())
            cols_c.append((N * d + (ii * m + jj) * d + rr).ravel())
            cache[key] = (row_sy, col_sy, row_sk, col_sk, np.concatenate(rows_c), np.concatenate(cols_c))
        row_sy, col_sy, row_sk, col_sk, rc, cc = cache[key]
        ones = np.ones(N * d)
        kvals = -(h[:, None, None] * b[None, :, None]) * np.ones((N, m, d))
        vals = np.concatenate([ones, -ones, kvals.ravel()])
        return np.concatenate([row_sy, row_sk, rc]), np.concatenate([col_sy, col_sk, cc]), vals

    def _begin_step(self, u: np.ndarray) -> None:
        self._ref = np.array(u, dtype=float)

    # ------------------------------------------------------------------ the polynomial
    def _values_at(self, u: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``y(s)`` and ``dy/ds`` of the collocation polynomial at normalized times s in [0, 1)."""
        c, _, _ = gauss_tableau(self.degree)
        Y, K = self._split(u)
        s = np.mod(np.asarray(s, dtype=float), 1.0)
        i = np.clip(np.searchsorted(self.mesh, s, side="right") - 1, 0, self.N - 1)
        h = np.diff(self.mesh)[i]
        theta = (s - self.mesh[i]) / h
        L, B = _lagrange(c, theta)
        y = Y[i] + h[:, None] * np.einsum("kl,kld->kd", B, K[i])
        dy = np.einsum("kl,kld->kd", L, K[i])
        return y, dy

    def _defect(self, u: np.ndarray, p: np.ndarray) -> float:
        """Relative defect ``max |y' - T f(y)| / max |T f|`` between the collocation points."""
        c, _, _ = gauss_tableau(self.degree)
        theta = np.concatenate([[0.0], (c[:-1] + c[1:]) / 2, [1.0 - 1e-12]])
        h = np.diff(self.mesh)
        s = (self.mesh[:-1, None] + theta[None, :] * h[:, None]).ravel()
        y, dy = self._values_at(u, s)
        T = self._period_of(u, p)
        fv = self.model.first_order(p).all(s * T, y)[0]
        scale = max(np.abs(T * fv).max(), 1e-300)
        return float(np.abs(dy - T * fv).max() / scale)

    def _monodromy(self, u: np.ndarray, p: np.ndarray) -> np.ndarray:
        """Product of the intervals' transfer matrices of the linearized collocation equations."""
        N, m, d = self.N, self.degree, self.d
        _, a, b = gauss_tableau(m)
        _, _, Z, T, tt, h = self._stages(u, p)
        A = self.model.first_order(p).all(tt.ravel(), Z.reshape(-1, d))[1].reshape(N, m, d, d)
        big = np.eye(m * d) - (T * h)[:, None, None] * (a[None, :, None, :, None] * A[:, :, :, None, :]).reshape(
            N, m * d, m * d
        )
        dK = np.linalg.solve(big, T * A.reshape(N, m * d, d)).reshape(N, m, d, d)
        S = np.eye(d) + h[:, None, None] * np.einsum("j,ijrc->irc", b, dK)
        M = np.eye(d)
        for i in range(N):
            M = S[i] @ M
        return M

    def _point(self, u: np.ndarray, p: np.ndarray, *, stability: bool = True) -> PointData:
        n = self.model.n
        h = np.diff(self.mesh)
        theta = np.linspace(0.0, 1.0, 9)[:-1]
        s = (self.mesh[:-1, None] + theta[None, :] * h[:, None]).ravel()
        y, _ = self._values_at(u, s)
        amps = np.empty(n)
        for i in range(n):
            j = int(np.argmax(np.abs(y[:, i])))
            fine = s[j] + np.linspace(-1, 1, 129) * (h.max() / 4)
            yf = np.abs(self._values_at(u, fine)[0][:, i])
            k = int(np.clip(np.argmax(yf), 1, len(fine) - 2))
            a_, b_, c_ = yf[k - 1], yf[k], yf[k + 1]
            den = a_ - 2 * b_ + c_
            amps[i] = max(b_ - (a_ - c_) ** 2 / (8 * den) if den < 0 else b_, np.abs(y[:, i]).max())
        rho = np.array([])
        if stability:
            rho = np.linalg.eigvals(self._monodromy(u, p))
            rho = rho[np.lexsort((-rho.imag, -np.abs(rho)))]
        Y, _ = self._split(u)
        return PointData(amps, self._frequency_of(u, p), self._defect(u, p), rho, None, Y[0].copy(), self.N)

    # ------------------------------------------------------------------ mesh refinement
    def _refined_mesh(self, u: np.ndarray, intervals: int) -> np.ndarray:
        """``intervals`` mesh intervals equidistributing ``|y^(m)|^(1/m)`` of the current solution."""
        m = self.degree
        c, _, _ = gauss_tableau(m)
        _, K = self._split(u)
        h = np.diff(self.mesh)
        # (m-1)-th divided difference of the stage derivatives: y^(m) = (m-1)! K[c_1..c_m] / h^(m-1)
        dd = K.copy()
        for level in range(1, m):
            dd = (dd[:, 1:] - dd[:, :-1]) / (c[level:] - c[:-level])[None, :, None]
        ym = np.linalg.norm(dd[:, 0], axis=1) * np.prod(np.arange(1, m)) / h ** (m - 1)
        dens = (ym + 1e-3 * ym.max() + 1e-300) ** (1.0 / m)
        dens = np.convolve(np.concatenate([dens[-1:], dens, dens[:1]]), np.ones(3) / 3, mode="valid")
        cum = np.concatenate([[0.0], np.cumsum(dens * h)])
        target = np.linspace(0.0, cum[-1], intervals + 1)
        new = np.interp(target, cum, self.mesh)
        new[0], new[-1] = 0.0, 1.0
        return new

    def _remeshed(self, u: np.ndarray, mesh: np.ndarray) -> tuple[Collocation, Any]:
        new = Collocation(self.model, self.values, mesh, self.degree, self.tol, self.adaptive, self.period_multiple)
        c, _, _ = gauss_tableau(self.degree)
        hn = np.diff(mesh)
        s_mesh = mesh[:-1]
        s_stage = (mesh[:-1, None] + c[None, :] * hn[:, None]).ravel()

        def transfer(v: np.ndarray) -> np.ndarray:
            Yn, _ = self._values_at(v, s_mesh)
            _, Kn = self._values_at(v, s_stage)
            out = np.concatenate([Yn.ravel(), Kn.ravel()])
            return np.append(out, v[-1]) if self.autonomous else out

        return new, transfer

    def _adapt(self, u: np.ndarray, p: np.ndarray, data: PointData):
        if not self.adaptive or data.residual <= self.tol:
            return None
        if self.N >= _MAX_INTERVALS:
            raise ConvergenceError(
                f"collocation: defect {data.residual:.2e} > tol={self.tol:g} with {self.N} intervals",
                achieved=data.residual,
            )
        return self._remeshed(u, self._refined_mesh(u, min(_MAX_INTERVALS, int(np.ceil(1.5 * self.N)))))

    # ------------------------------------------------------------------ one point
    def _initial(self, guess: Any, frequency: float | None) -> np.ndarray:
        from .branch import PeriodicSolution

        if not isinstance(guess, PeriodicSolution):
            raise ParameterError("collocation needs a PeriodicSolution as guess (from harmonic balance or shooting)")
        c, _, _ = gauss_tableau(self.degree)
        h = np.diff(self.mesh)
        s = np.concatenate([self.mesh[:-1], (self.mesh[:-1, None] + c[None, :] * h[:, None]).ravel()])
        T = guess.period
        y, dy = _sample_solution(self, guess, s * T)
        N = self.N
        u = np.concatenate([y[:N].ravel(), (T * dy[N:]).ravel()])
        return np.append(u, T) if self.autonomous else u

    def solve(self, guess: Any, *, values: Mapping[Any, Any] | None = None, max_iterations: int = 30):
        """Solve for one periodic solution by Newton's method, refining the mesh while the defect exceeds ``tol``.

        Parameters
        ----------
        guess : PeriodicSolution
            Starting orbit: a solution of harmonic balance or shooting (or collocation), at or near the values.
        values : mapping of Symbol or str to float, optional
            Parameter values that replace the problem's for this solve: finite numbers keyed by parameter Symbol or
            name (see :meth:`with_values`).
        max_iterations : int, optional
            Newton iterations per mesh: an integer >= 1 (default 30).

        Returns
        -------
        PeriodicSolution

        Raises
        ------
        ParameterError
            ``guess`` is not a PeriodicSolution.
        ConvergenceError
            Newton's method does not converge, or the defect stays above ``tol`` with 4000 intervals.
        """
        from ._solve import solution_from

        check_int("max_iterations", max_iterations, minimum=1)
        prob = self.with_values(values) if values is not None else self
        u, prob = prob._converge(guess, max_iterations=max_iterations)
        return solution_from(prob, u, prob.values, prob._point(u, prob.values))

    def _converge(self, guess: Any, frequency: float | None = None, *, max_iterations: int = 30):
        """Converged unknowns at the problem's values and the (possibly refined) problem."""
        from ._solve import newton

        prob = self
        u = prob._initial(guess, frequency)
        while True:
            prob._begin_step(u)
            u = newton(prob, u, prob.values, max_iterations=max_iterations, tol=1e-11)
            data = prob._point(u, prob.values, stability=False)
            refined = prob._adapt(u, prob.values, data)
            if refined is None:
                return u, prob
            prob, transfer = refined
            u = transfer(u)


def _sample_solution(prob: Any, sol: Any, tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """States and their time derivatives of a solution at times tt (Fourier series, else an integration)."""
    from . import _fourier

    n = prob.model.n
    if sol.coefficients is not None:
        c = sol.coefficients
        w = sol.frequency
        q = _fourier.evaluate(c, w * tt)
        q1 = _fourier.evaluate(_fourier.derivative(c), w * tt) * w
        q2 = _fourier.evaluate(_fourier.derivative(_fourier.derivative(c)), w * tt) * w * w
        return np.hstack([q, q1]), np.hstack([q1, q2])
    from scipy.integrate import solve_ivp

    p = prob._with_values(sol.values).values
    f = prob.model.first_order(p)
    res = solve_ivp(
        f.rhs, (0.0, sol.period), sol.initial_state, method="DOP853", rtol=1e-11, atol=1e-13, dense_output=True
    )
    y = res.sol(np.clip(tt, 0.0, sol.period)).T
    dy = f.all(tt, y)[0]
    return y, dy[:, : 2 * n]


@validated
def collocation(
    acceleration: Any,
    x: Any = None,
    v: Any = None,
    t: Any = None,
    *,
    forcing_frequency: sp.Symbol | None = None,
    autonomous: bool = False,
    values: Mapping[Any, Any] | None = None,
    intervals: int = 40,
    degree: int = 4,
    tol: float = 1e-6,
    adaptive: bool = True,
    period_multiple: int = 1,
) -> Collocation:
    """Set up orthogonal collocation for the periodic solutions of an oscillator (model input as harmonic balance).

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
    intervals : int, optional
        Mesh intervals N of the initial (uniform) mesh: an integer from 4 to 4000 (default 40).
    degree : int, optional
        Gauss points per interval, m: an integer from 1 to 10 (default 4; error ``O(h^(2m))`` at the mesh points).
    tol : float, optional
        Requested relative defect ``max |y' - T f(y)| / max |T f|`` of the collocation polynomial between the
        collocation points: a positive number (default 1e-6; an ``O(h^m)`` quantity, while the mesh values and the
        period are accurate to about ``O(h^(2m))``, far below it).
    adaptive : bool, optional
        Whether the mesh is refined and redistributed when the defect exceeds ``tol``: True (default) or False.
    period_multiple : int, optional
        The response period in forcing periods, m: an integer >= 1 (1 for an autonomous problem; default 1).

    Returns
    -------
    Collocation

    See Also
    --------
    harmonic_balance, shooting, continue_periodic

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.continuation import harmonic_balance, collocation
    >>> x, v, t, eps = sp.symbols("x v t eps")
    >>> a = eps * (1 - x**2) * v - x
    >>> guess = harmonic_balance(a, x, v, t, autonomous=True, values={"eps": 1.0}).solve()
    >>> co = collocation(a, x, v, t, autonomous=True, values={"eps": 1.0})
    >>> sol = co.solve(guess)
    >>> round(sol.period, 8)                                  # van der Pol, eps = 1
    6.66328686
    """
    autonomous = check_bool("autonomous", autonomous)
    intervals = check_int("intervals", intervals, minimum=4, maximum=_MAX_INTERVALS)
    degree = check_int("degree", degree, minimum=1, maximum=10)
    tol = check_positive("tol", tol)
    adaptive = check_bool("adaptive", adaptive)
    period_multiple = check_int("period_multiple", period_multiple, minimum=1)
    if values is not None and not isinstance(values, Mapping):
        raise ParameterError(f"values must be a mapping from parameter to number, got {values!r}")
    model = build_model(acceleration, x, v, t, forcing_frequency=forcing_frequency, autonomous=autonomous)
    p = model.values_vector(values or {}, skip=model.params)
    mesh = np.linspace(0.0, 1.0, intervals + 1)
    return Collocation(model, p, mesh, degree, tol, adaptive, period_multiple)
