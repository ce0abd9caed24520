"""Two-parameter continuation of folds by a minimally augmented system (Govaerts 2000; Kuznetsov 2004, §10.2).

At a fold of ``G(u, lambda, mu) = 0`` the Jacobian ``G_u`` is singular.  With fixed border vectors b, c (the left
and right null vectors at the starting fold) the bordered system

    [[G_u, b], [c^T, 0]] [v; g] = [0; 1]

defines a scalar ``g(u, lambda, mu)`` that vanishes exactly at folds and is regular there.  The fold curve solves
``G = 0, g = 0`` for ``(u, lambda)`` as ``mu`` varies, followed by the same pseudo-arclength driver.  Its
derivatives are ``g_z = -w^T G_uz v`` with ``w`` from the transposed system; ``G_uz v`` is the central difference of
the exact Jacobian ``[G_u, G_p]`` along ``v`` (two Jacobian evaluations).  A turning point of ``mu`` along the fold
curve (two folds meeting) is a cusp.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from .._plotting import new_axes, plot_method
from .._printing import SymPyPrintable
from .._validate import check_int, check_positive, validated
from ..errors import ParameterError
from . import arclength as _arc
from ._problem import Formulation, PointData
from .bifurcations import Monitor
from .branch import Bifurcation, Branch

__all__ = ["FoldCurve", "continue_fold"]


class _FoldSystem(Formulation):
    """``(u, lambda) -> (G, g)`` at fixed mu (the minimally augmented fold system of a formulation)."""

    def __init__(self, base: Formulation, k: int, b: np.ndarray, c: np.ndarray) -> None:
        self.base, self.k, self.b, self.c = base, k, b, c
        self.model, self.autonomous, self.method = base.model, base.autonomous, base.method
        self.values = base.values

    def _q(self, U: np.ndarray, p: np.ndarray) -> np.ndarray:
        q = p.copy()
        q[self.k] = U[-1]
        return q

    def _evaluate(self, U: np.ndarray, p: np.ndarray):
        u, q = U[:-1], self._q(U, p)
        G, J, Gp = self.base._evaluate(u, q)
        n = len(u)
        A = np.zeros((n + 1, n + 1))
        A[:n, :n] = J
        A[:n, n] = self.b
        A[n, :n] = self.c
        rhs = np.zeros(n + 1)
        rhs[-1] = 1.0
        vg = np.linalg.solve(A, rhs)
        wg = np.linalg.solve(A.T, rhs)
        v, g, w = vg[:n], vg[n], wg[:n]
        h = 1e-6 * (1 + np.linalg.norm(u)) / max(np.linalg.norm(v), 1e-300)
        _, Jp, Gpp = self.base._evaluate(u + h * v, q)
        _, Jm, Gpm = self.base._evaluate(u - h * v, q)
        gu = -(w @ (Jp - Jm)) / (2 * h)
        gp = -(w @ (Gpp - Gpm)) / (2 * h)
        Phi = np.append(G, g)
        JU = np.zeros((n + 1, n + 1))
        JU[:n, :n] = J
        JU[:n, n] = Gp[:, self.k]
        JU[n, :n] = gu
        JU[n, n] = gp[self.k]
        return Phi, JU, np.vstack([Gp, gp])

    def _weights(self, U: np.ndarray) -> np.ndarray:
        return np.append(self.base._weights(U[:-1]), 1.0)

    def _begin_step(self, U: np.ndarray) -> None:
        self.base._begin_step(U[:-1])

    def _point(self, U: np.ndarray, p: np.ndarray, *, stability: bool = True) -> PointData:
        d = self.base._point(U[:-1], self._q(U, p), stability=False)
        d.coefficients = np.array([U[-1]])  # the fold's first parameter, carried to the result
        return d


@dataclass(frozen=True)
class FoldCurve(SymPyPrintable):
    """A curve of folds in the plane of two parameters, with its cusps.

    Attributes
    ----------
    name : str
        The second parameter (varied along the curve).
    fold_name : str
        The first parameter (the one in which each point is a fold).
    parameter : ndarray
        Second parameter at each point.
    fold_parameter : ndarray
        First parameter at each point.
    amplitude, frequency, residual : ndarray
        ``max |q_1|``, base angular frequency and achieved residual of the solution at the fold.
    cusps : list of tuple
        ``(parameter, fold_parameter)`` where the curve turns in the second parameter (two folds meet).
    stopped : str
        Why the continuation ended.
    """

    name: str
    fold_name: str
    parameter: np.ndarray
    fold_parameter: np.ndarray
    amplitude: np.ndarray
    frequency: np.ndarray
    residual: np.ndarray
    cusps: list = field(default_factory=list)
    stopped: str = ""

    def __repr__(self) -> str:
        cusp = ", ".join(f"({a:.8g}, {b:.8g})" for a, b in self.cusps) or "none"
        return (
            f"FoldCurve({len(self.parameter)} points, {self.name} in [{self.parameter.min():.6g}, "
            f"{self.parameter.max():.6g}], {self.fold_name} in [{self.fold_parameter.min():.6g}, "
            f"{self.fold_parameter.max():.6g}]; cusps ({self.name}, {self.fold_name}): {cusp}; {self.stopped})"
        )

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Draw the fold curve in the (first parameter, second parameter) plane, cusps marked.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
        """
        ax = new_axes(ax)
        ax.plot(self.fold_parameter, self.parameter, "-")
        for a, b in self.cusps:
            ax.plot([b], [a], "o", mfc="none", color="k")
            ax.annotate("cusp", (b, a), textcoords="offset points", xytext=(4, 4), fontsize=8)
        ax.set_xlabel(self.fold_name)
        ax.set_ylabel(self.name)
        ax.set_title("fold (saddle-node) curve")
        return ax


@validated
def continue_fold(
    problem: Any,
    branch: Branch,
    fold: Bifurcation,
    parameter: sp.Symbol | str,
    span: Sequence[float],
    *,
    step: float | None = None,
    max_step: float | None = None,
    max_points: int = 1000,
) -> FoldCurve:
    """Follow a fold of a branch in a second parameter (e.g. the cusp of a resonance curve in the forcing amplitude).

    Parameters
    ----------
    problem : HarmonicBalance or Shooting
        The formulation that computed ``branch``: a harmonic-balance or shooting problem (dense Jacobians;
        collocation is refused).
    branch : Branch
        The branch in the first parameter: a Branch from :func:`continue_periodic`.
    fold : Bifurcation
        The fold to follow: a ``"fold"`` Bifurcation of ``branch``.
    parameter : Symbol or str
        The second parameter: a parameter of the model (Symbol or name) other than the branch's.
    span : (float, float)
        Range of the second parameter: two numbers around the problem's value of it, where the curve starts; it
        stops when the parameter leaves the range (or turns back out of it after a cusp).
    step, max_step : float, optional
        First and largest arclength steps: positive numbers (defaults 1/200 and 1/50 of the span's length).
    max_points : int, optional
        Largest number of points: an integer >= 2 (default 1000).

    Returns
    -------
    FoldCurve

    See Also
    --------
    continue_periodic

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.continuation import harmonic_balance, continue_periodic, continue_fold
    >>> x, v, t, w, F = sp.symbols("x v t w F")
    >>> hb = harmonic_balance(-0.1 * v - x - 0.5 * x**3 + F * sp.cos(w * t), x, v, t, forcing_frequency=w,
    ...                       values={"F": 0.3})
    >>> br = continue_periodic(hb, w, (0.6, 2.0), detect=["fold"])
    >>> curve = continue_fold(hb, br, br.bifurcations[0], F, (0.01, 0.3), max_step=0.01)
    >>> [tuple(round(c, 3) for c in cusp) for cusp in curve.cusps]      # (F, w) of the cusp
    [(0.073, 1.09)]
    """
    if not isinstance(problem, Formulation) or problem.method == "collocation":
        raise ParameterError("problem must be a HarmonicBalance or Shooting problem (dense Jacobian)")
    if not isinstance(branch, Branch) or not isinstance(fold, Bifurcation) or fold.kind != "fold":
        raise ParameterError("branch must be a Branch and fold one of its 'fold' bifurcations")
    k = problem.model.param_index(branch.name)
    k2 = problem.model.param_index(parameter)
    if k2 == k:
        raise ParameterError("parameter must differ from the branch's parameter")
    if isinstance(span, str | bytes) or len(span) != 2:
        raise ParameterError(f"span must be (low, high), got {span!r}")
    lo, hi = float(min(span)), float(max(span))
    p = problem.values.copy()
    for name, val in branch.values.items():
        p[problem.model.param_index(name)] = val
    mu0 = float(p[k2])
    if not lo <= mu0 <= hi:
        raise ParameterError(f"span must contain the current value {parameter}={mu0:g}")
    base = problem._at_size(fold.size)
    u, lam = fold.state[:-1], fold.state[-1]
    q = p.copy()
    q[k] = lam
    base._begin_step(u)
    _, J, _ = base._evaluate(u, q)
    U_, _, Vh = np.linalg.svd(J)
    system = _FoldSystem(base, k, U_[:, -1], Vh[-1])
    length = hi - lo
    step = length / 200 if step is None else check_positive("step", step)
    max_step = length / 50 if max_step is None else check_positive("max_step", max_step)
    opt = _arc.Options(min(step, max_step), length * 1e-9, max_step, check_int("max_points", max_points, minimum=2))
    opt.stability = False
    branches = []
    for direction in (-1.0, 1.0):
        raw = _arc.run(system, k2, p, fold.state.copy(), mu0, (lo, hi), opt, Monitor(("fold",)), direction=direction)
        branches.append(raw)
    pts = [(r.X[::-1] if i == 0 else r.X[1:], r.data[::-1] if i == 0 else r.data[1:]) for i, r in enumerate(branches)]
    X = pts[0][0] + pts[1][0]
    data = pts[0][1] + pts[1][1]
    cusps = [(b.parameter, float(b.state[-2])) for r in branches for b in r.bifurcations]
    return FoldCurve(
        name=problem.model.params[k2].name,
        fold_name=branch.name,
        parameter=np.array([x[-1] for x in X]),
        fold_parameter=np.array([x[-2] for x in X]),
        amplitude=np.array([d.amplitudes[0] for d in data]),
        frequency=np.array([d.frequency for d in data]),
        residual=np.array([d.residual for d in data]),
        cusps=cusps,
        stopped="; ".join(r.stopped for r in branches),
    )
