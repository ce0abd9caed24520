"""Pseudo-arclength continuation with step control and bifurcation detection (Keller 1977; Doedel, AUTO).

The branch ``X(s) = (u(s), lambda(s))`` of ``G(u, lambda) = 0`` is followed by an Euler predictor along the unit
tangent ``t`` and a Newton corrector on the bordered system ``[G; t . (X - X_pred)] = 0`` with the exact
Jacobian ``[[G_u, G_lambda], [t^T]]``.  The next tangent solves ``[[G_u, G_lambda], [t_old^T]] t = (0, 1)``, which
keeps the orientation through folds.  The step grows after corrections of at most 3 Newton iterations and
shrinks after slow or failed ones, or when the tangent turns by more than ``max_angle``.  Test functions are
evaluated at every point and their zeros located by Brent's method on the arclength (see
:mod:`symosc.continuation.bifurcations`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import ConvergenceError
from ._problem import Formulation, PointData

__all__: list[str] = []


@dataclass
class Options:
    step: float
    min_step: float
    max_step: float
    max_points: int
    newton_tol: float = 1e-10
    max_newton: int = 8
    max_angle: float = 0.3
    stability: bool = True
    detect: bool = True


@dataclass
class Raw:
    """What the driver collects: accepted points and located bifurcations."""

    X: list = field(default_factory=list)
    T: list = field(default_factory=list)
    data: list = field(default_factory=list)
    sizes: list = field(default_factory=list)
    bifurcations: list = field(default_factory=list)
    stopped: str = ""
    formulation: Any = None


def bordered(J: Any, Gl: np.ndarray, row: np.ndarray) -> Any:
    """``[[G_u, G_lambda], [row]]`` (dense or sparse like ``J``)."""
    if isinstance(J, np.ndarray):
        n = J.shape[0]
        A = np.empty((n + 1, n + 1))
        A[:n, :n] = J
        A[:n, n] = Gl
        A[n] = row
        return A
    import scipy.sparse as sps

    return sps.bmat(
        [[J, sps.csc_matrix(Gl.reshape(-1, 1))], [sps.csc_matrix(row[:-1].reshape(1, -1)), sps.csc_matrix([[row[-1]]])]]
    ).tocsc()


class LinearSystem:
    """A factorized bordered matrix: solves and the sign/log of its determinant."""

    def __init__(self, A: Any) -> None:
        self.dense = isinstance(A, np.ndarray)
        if self.dense:
            import scipy.linalg as sla

            self.lu = sla.lu_factor(A, check_finite=False)
        else:
            from scipy.sparse.linalg import splu

            self.lu = splu(A, permc_spec="COLAMD")

    def solve(self, b: np.ndarray) -> np.ndarray:
        if self.dense:
            import scipy.linalg as sla

            return sla.lu_solve(self.lu, b, check_finite=False)
        return self.lu.solve(b)

    def det_log(self) -> tuple[float, float]:
        """Sign and log of the absolute value of the determinant."""
        d = np.diag(self.lu[0]) if self.dense else self.lu.U.diagonal()
        with np.errstate(divide="ignore"):
            log = float(np.sum(np.log(np.abs(d))))
        return self.det_sign(), log

    def det_sign(self) -> float:
        if self.dense:
            lu, piv = self.lu
            d = np.diag(lu)
            swaps = np.sum(piv != np.arange(len(piv)))
            return float((-1) ** swaps * np.prod(np.sign(d)))
        d = self.lu.U.diagonal()
        sign = np.prod(np.sign(d)) * _perm_sign(self.lu.perm_r) * _perm_sign(self.lu.perm_c)
        return float(sign)


def _perm_sign(perm: np.ndarray) -> float:
    perm = np.asarray(perm)
    seen = np.zeros(len(perm), dtype=bool)
    sign = 1.0
    for i in range(len(perm)):
        if not seen[i]:
            j, length = i, 0
            while not seen[j]:
                seen[j] = True
                j = perm[j]
                length += 1
            if length % 2 == 0:
                sign = -sign
    return sign


def evaluate_full(prob: Formulation, X: np.ndarray, p: np.ndarray, k: int):
    """G, G_u, G_lambda at ``X = (u, lambda)``."""
    q = p.copy()
    q[k] = X[-1]
    G, J, Gp = prob._evaluate(X[:-1], q)
    return G, J, Gp[:, k]


def tangent(
    prob: Formulation, X: np.ndarray, p: np.ndarray, k: int, row: np.ndarray, jacobian: tuple | None = None
) -> tuple[np.ndarray, Any]:
    """Unit tangent with ``row . t > 0`` and the factorized bordered matrix (``jacobian``: G_u, G_lambda at X)."""
    J, Gl = jacobian if jacobian is not None else evaluate_full(prob, X, p, k)[1:]
    ls = LinearSystem(bordered(J, Gl, row))
    rhs = np.zeros(len(X))
    rhs[-1] = 1.0
    t = ls.solve(rhs)
    return t / np.sqrt(t @ (weights(prob, X) * t)), ls


def weights(prob: Formulation, X: np.ndarray) -> np.ndarray:
    """Weights of the arclength inner product (the formulation's for u, 1 for the parameter)."""
    return np.append(prob._weights(X[:-1]), 1.0)


def correct(
    prob: Formulation,
    Xp: np.ndarray,
    p: np.ndarray,
    k: int,
    t: np.ndarray,
    X0: np.ndarray,
    s: float,
    opt: Options,
    last: list | None = None,
) -> tuple[np.ndarray, int]:
    """Newton's method on ``G = 0, t . (X - X0) = s`` from ``Xp`` (``t``: the weighted tangent, a row of the
    bordered matrix); returns the point and the iterations used.

    ``last`` (a list) receives the Jacobian of the last iteration, evaluated within the tolerance of the point."""
    X = Xp.copy()
    for it in range(1, opt.max_newton + 1):
        G, J, Gl = evaluate_full(prob, X, p, k)
        F = np.append(G, t @ (X - X0) - s)
        if not np.all(np.isfinite(F)):
            raise ConvergenceError("non-finite residual in the corrector")
        try:
            dX = LinearSystem(bordered(J, Gl, t)).solve(F)
        except (np.linalg.LinAlgError, RuntimeError, ValueError) as exc:
            raise ConvergenceError(f"singular corrector matrix ({exc})") from exc
        X = X - dX
        if np.linalg.norm(dX) <= opt.newton_tol * (1 + np.linalg.norm(X)):
            if last is not None:  # evaluated a Newton step (below newton_tol) away: good for the tangent
                last.append((J, Gl))
            return X, it
    raise ConvergenceError(f"corrector did not converge in {opt.max_newton} iterations")


def correct_at_parameter(prob: Formulation, X: np.ndarray, p: np.ndarray, k: int, value: float, opt: Options):
    """Newton's method at the fixed parameter ``value`` (the branch's end point on the span boundary)."""
    row = np.zeros(len(X))
    row[-1] = 1.0
    Xs = X.copy()
    Xs[-1] = value
    return correct(prob, Xs, p, k, row, Xs, 0.0, opt)


def run(
    prob: Formulation,
    k: int,
    p: np.ndarray,
    u0: np.ndarray,
    lam0: float,
    bounds: tuple[float, float],
    opt: Options,
    tests: Any = None,
    t0: np.ndarray | None = None,
    direction: float = 1.0,
) -> Raw:
    """Follow the branch through ``(u0, lam0)`` in the direction of increasing (``direction`` = 1) or decreasing
    parameter (or along ``t0``) while the parameter stays within ``bounds``; ``tests`` evaluates/locates test
    functions."""
    lo, hi = bounds
    X = np.append(u0, lam0)
    out = Raw(formulation=prob)
    prob._begin_step(X[:-1])
    if t0 is None:
        row = np.zeros(len(X))
        row[-1] = direction
        t, ls = tangent(prob, X, p, k, row)
    else:
        t, ls = tangent(prob, X, p, k, weights(prob, X) * t0)
    data = point_data(prob, X, p, k, opt)
    _append(out, X, t, data, prob)
    state = tests.initial(prob, X, t, ls, data) if tests else None
    ds = opt.step
    while len(out.X) < opt.max_points:
        prob._begin_step(X[:-1])
        try:
            jac: list = []
            Wt = weights(prob, X) * t
            Xn, its = correct(prob, X + ds * t, p, k, Wt, X, ds, opt, jac)
            tn, lsn = tangent(prob, Xn, p, k, Wt, jac[0] if jac else None)
            if tn @ Wt < np.cos(opt.max_angle) and ds > opt.min_step:
                raise ConvergenceError("the tangent turned too much")
        except ConvergenceError:
            ds *= 0.5
            if ds < opt.min_step:
                out.stopped = f"step size below min_step={opt.min_step:g} at {_name(prob, k)}={X[-1]:.10g}"
                return out
            continue
        # span boundary: end exactly on it
        if Xn[-1] > hi or Xn[-1] < lo:
            edge = hi if Xn[-1] > hi else lo
            frac = (edge - X[-1]) / (Xn[-1] - X[-1]) if Xn[-1] != X[-1] else 0.0
            try:
                if tests:  # the whole step: a fold inside it may be what turns the branch out of the span
                    found = len(out.bifurcations)
                    tests.check(prob, X, t, Xn, tn, lsn, point_data(prob, Xn, p, k, opt), ds, state, out, p, k, opt)
                    out.bifurcations[found:] = [b for b in out.bifurcations[found:] if lo <= b.parameter <= hi]
                Xe, _ = correct_at_parameter(prob, X + frac * (Xn - X), p, k, edge, opt)
                te, _ = tangent(prob, Xe, p, k, weights(prob, Xe) * t)
                de = point_data(prob, Xe, p, k, opt)
                _append(out, Xe, te, de, prob)
            except ConvergenceError:
                pass
            out.stopped = f"reached {_name(prob, k)} = {edge:g}"
            return out
        dn = point_data(prob, Xn, p, k, opt)
        refined = prob._adapt(Xn[:-1], _with(p, k, Xn[-1]), dn)
        if refined is not None:  # more harmonics / mesh: move the last accepted point and redo the step
            new, transfer = refined
            X = np.append(transfer(X[:-1]), X[-1])
            prob = new
            prob._begin_step(X[:-1])
            t = np.append(transfer(t[:-1]), t[-1])
            Wt = weights(prob, X) * t
            X, _ = correct(prob, X, p, k, Wt, X, 0.0, opt)
            t, ls = tangent(prob, X, p, k, Wt)
            out.formulation = prob
            if tests:
                state = tests.initial(prob, X, t, ls, point_data(prob, X, p, k, opt))
            continue
        if tests:
            state = tests.check(prob, X, t, Xn, tn, lsn, dn, ds, state, out, p, k, opt)
        _append(out, Xn, tn, dn, prob)
        X, t, ls = Xn, tn, lsn
        if its <= 3:
            ds = min(ds * 1.4, opt.max_step)
        elif its >= 6:
            ds = max(ds * 0.6, opt.min_step)
    out.stopped = f"max_points={opt.max_points} reached"
    return out


def _with(p: np.ndarray, k: int, value: float) -> np.ndarray:
    q = p.copy()
    q[k] = value
    return q


def _name(prob: Formulation, k: int) -> str:
    return prob.model.params[k].name if k < len(prob.model.params) else "parameter"


def point_data(prob: Formulation, X: np.ndarray, p: np.ndarray, k: int, opt: Options) -> PointData:
    return prob._point(X[:-1], _with(p, k, X[-1]), stability=opt.stability)


def _append(out: Raw, X: np.ndarray, t: np.ndarray, data: PointData, prob: Formulation) -> None:
    out.X.append(X.copy())
    out.T.append(t.copy())
    out.data.append(data)
    out.sizes.append(data.size)
