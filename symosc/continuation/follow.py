"""Public entry points: follow a branch of periodic solutions in one parameter, switch branches."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
import sympy as sp

from .._validate import check_bool, check_choice, check_finite, check_int, check_positive, validated
from ..errors import ConvergenceError, ParameterError
from . import arclength as _arc
from .bifurcations import Monitor, kernel_direction
from .branch import KINDS, Bifurcation, Branch

__all__ = ["continue_periodic", "switch_branch"]


def _check_problem(problem: Any) -> None:
    from ._problem import Formulation

    if not isinstance(problem, Formulation):
        raise ParameterError(
            "problem must be a HarmonicBalance, Shooting or Collocation problem (from harmonic_balance(), "
            f"shooting() or collocation()), got {type(problem).__name__}"
        )


def _check_span(span: Any) -> tuple[float, float]:
    if isinstance(span, str | bytes) or not isinstance(span, Sequence | np.ndarray) or len(span) != 2:
        raise ParameterError(f"span must be (start, end) with two numbers, got {span!r}")
    a, b = check_finite("span[0]", span[0]), check_finite("span[1]", span[1])
    if a == b:
        raise ParameterError(f"span must have start != end, got {span!r}")
    return a, b


@validated
def continue_periodic(
    problem: Any,
    parameter: sp.Symbol | str,
    span: Sequence[float],
    *,
    start: Any = None,
    step: float | None = None,
    max_step: float | None = None,
    min_step: float | None = None,
    max_points: int = 2000,
    stability: bool = True,
    detect: Sequence[str] | bool = True,
) -> Branch:
    """Follow a branch of periodic solutions in one parameter by pseudo-arclength continuation.

    The branch starts at ``parameter = span[0]`` from ``start`` (or the problem's default guess: the linearized
    response of a forced system, a first-harmonic guess of an autonomous one) and is followed through folds until
    the parameter leaves the span (the last point lies on its end), ``max_points`` are reached or the step falls
    below ``min_step``.  Every point carries its residual and its Floquet multipliers; folds, period doublings,
    Neimark–Sacker and branch points are detected by test functions and located.

    Parameters
    ----------
    problem : HarmonicBalance, Shooting or Collocation
        The problem to continue: a formulation from :func:`harmonic_balance`, :func:`shooting` or
        :func:`collocation`, holding the values of the other parameters.
    parameter : Symbol or str
        The continuation parameter: a parameter of the model, as Symbol or name (the forcing frequency, an
        amplitude, ``eps``, ...).
    span : (float, float)
        Start and end values of the parameter: two different finite numbers (the end may be smaller than the
        start).
    start : PeriodicSolution, LimitCycleSeries, array or None, optional
        Starting solution or guess at ``span[0]``: a solution of any formulation (a shooting solution started from
        a simulated state, for instance), a Poincaré series from :func:`symosc.nonlinear.limit_cycle` (harmonic
        balance of an autonomous problem), Fourier coefficients (harmonic balance), an initial state (shooting), or
        None (default) for the problem's own guess.
    step : float, optional
        First arclength step: a positive number (default 1/200 of the span's length).
    max_step : float, optional
        Largest arclength step: a positive number (default 1/50 of the span's length).
    min_step : float, optional
        Smallest step before the continuation stops: a positive number (default 1e-7 of the span's length).
    max_points : int, optional
        Largest number of points: an integer >= 2 (default 2000).
    stability : bool, optional
        Whether to compute the Floquet multipliers of every point: True (default) or False (they give the
        stability and the period-doubling and Neimark–Sacker detection).
    detect : bool or sequence of str, optional
        Which bifurcations to detect and locate: True (default: all of "fold", "period_doubling",
        "neimark_sacker", "branch_point"), False (none) or a sequence of those names.

    Returns
    -------
    Branch

    Raises
    ------
    ParameterError
        Invalid arguments (named).
    ConvergenceError
        No solution at the start, or a harmonic-balance residual above tolerance with the maximum harmonics.

    See Also
    --------
    harmonic_balance, shooting, collocation : the formulations.
    switch_branch : start a new branch at a branch point or a period doubling.
    continue_fold : follow a fold in two parameters.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.continuation import harmonic_balance, continue_periodic
    >>> x, v, t, w = sp.symbols("x v t w")
    >>> hb = harmonic_balance(-0.1 * v - x - 0.5 * x**3 + 0.3 * sp.cos(w * t), x, v, t, forcing_frequency=w)
    >>> br = continue_periodic(hb, w, (0.6, 2.0))
    >>> [(b.kind, round(b.parameter, 4)) for b in br.bifurcations]
    [('fold', 1.5556), ('fold', 1.2616)]
    >>> bool(br.stable[0]), bool(br.stable[-1])
    (True, True)
    """
    _check_problem(problem)
    lo, hi = _check_span(span)
    k = problem.model.param_index(parameter)
    length = abs(hi - lo)
    step = length / 200 if step is None else check_positive("step", step)
    max_step = length / 50 if max_step is None else check_positive("max_step", max_step)
    min_step = length * 1e-7 if min_step is None else check_positive("min_step", min_step)
    max_points = check_int("max_points", max_points, minimum=2)
    stability = check_bool("stability", stability)
    kinds = _kinds(detect, stability)
    opt = _arc.Options(min(step, max_step), min_step, max_step, max_points, stability=stability)
    prob = problem._with_values({problem.model.params[k]: lo})
    p = prob.values.copy()
    u0, prob = _start(prob, start, p)
    raw = _arc.run(
        prob,
        k,
        p,
        u0,
        lo,
        (min(lo, hi), max(lo, hi)),
        opt,
        Monitor(kinds) if kinds else None,
        direction=1.0 if hi > lo else -1.0,
    )
    return _branch(raw, problem, k, p)


def _kinds(detect: Any, stability: bool) -> tuple[str, ...]:
    if isinstance(detect, bool | np.bool_):
        kinds = KINDS if detect else ()
    else:
        if isinstance(detect, str):
            detect = [detect]
        kinds = tuple(check_choice("detect", d, KINDS) for d in detect)
    if not stability:
        kinds = tuple(kd for kd in kinds if kd not in ("period_doubling", "neimark_sacker"))
    return kinds


def _start(prob: Any, start: Any, p: np.ndarray) -> tuple[np.ndarray, Any]:
    """Converged unknowns at the start point (growing the truncation when adaptive)."""
    return prob._converge(start)


def _branch(raw: _arc.Raw, problem: Any, k: int, p: np.ndarray, name: str | None = None) -> Branch:
    if not raw.X:
        raise ConvergenceError("the continuation produced no point")
    X = np.array([x[-1] for x in raw.X])
    data = raw.data
    nmult = max(len(d.multipliers) for d in data)
    mult = np.full((len(data), nmult), np.nan + 0j)
    for i, d in enumerate(data):
        mult[i, : len(d.multipliers)] = d.multipliers
    from ._solve import _is_stable

    stable = np.array([_is_stable(d.multipliers, problem.autonomous) for d in data])
    params = problem.model.params
    values = {s.name: float(v) for i, (s, v) in enumerate(zip(params, p, strict=True)) if i != k and np.isfinite(v)}
    return Branch(
        method=problem.method,
        name=name or params[k].name,
        parameter=X,
        amplitude=np.array([d.amplitudes[0] for d in data]),
        frequency=np.array([d.frequency for d in data]),
        stable=stable,
        residual=np.array([d.residual for d in data]),
        size=np.array(raw.sizes, dtype=int),
        multipliers=mult,
        amplitudes=np.array([d.amplitudes for d in data]),
        bifurcations=list(raw.bifurcations),
        values=values,
        coordinates=tuple(s.name for s in problem.model.q),
        states=tuple(x[:-1].copy() for x in raw.X),
        initial_states=np.array([d.initial_state for d in data]),
        stopped=raw.stopped,
        tolerance=float(getattr(problem, "tol", np.nan)),
        autonomous=bool(problem.autonomous),
    )


@validated
def switch_branch(
    problem: Any,
    branch: Branch,
    bifurcation: Bifurcation,
    span: Sequence[float] | None = None,
    *,
    direction: int = 1,
    step: float | None = None,
    max_step: float | None = None,
    max_points: int = 2000,
    stability: bool = True,
    detect: Sequence[str] | bool = True,
) -> Branch:
    """Start the branch that crosses ``branch`` at a branch point, or the doubled-period branch at a period doubling.

    Parameters
    ----------
    problem : HarmonicBalance or Shooting
        The formulation that computed ``branch``: a harmonic-balance or shooting problem (switching needs a dense
        Jacobian, so collocation is refused).
    branch : Branch
        The branch with the bifurcation: a Branch from :func:`continue_periodic` (or from this function).
    bifurcation : Bifurcation
        Where to switch: a ``"branch_point"`` or ``"period_doubling"`` Bifurcation of ``branch``.
    span : (float, float), optional
        Range of the parameter for the new branch: two different finite numbers (default: the old branch's range);
        the new branch stops when the parameter leaves it.
    direction : {1, -1}, optional
        Which half of the new branch to follow: 1 (default) or -1, the sign of the step along the kernel direction.
    step : float, optional
        First arclength step: a positive number (default 1/200 of the span's length).
    max_step : float, optional
        Largest arclength step: a positive number (default 1/50 of the span's length).
    max_points : int, optional
        Largest number of points: an integer >= 2 (default 2000).
    stability : bool, optional
        Whether to compute the Floquet multipliers along the new branch: True (default) or False.
    detect : bool or sequence of str, optional
        Which bifurcations to detect on the new branch: True (default: all), False (none) or a sequence of "fold",
        "period_doubling", "neimark_sacker", "branch_point".

    Returns
    -------
    Branch
        The new branch; after a period doubling its solutions have twice the period (``period_multiple`` doubled
        for harmonic balance).

    See Also
    --------
    continue_periodic

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.continuation import harmonic_balance, continue_periodic, switch_branch
    >>> x, v, t, w = sp.symbols("x v t w")
    >>> hb = harmonic_balance(-0.1 * v - x - 0.5 * x**3 + 0.3 * sp.cos(w * t), x, v, t, forcing_frequency=w)
    >>> br = continue_periodic(hb, w, (0.6, 2.0), detect=["branch_point"])
    >>> br.bifurcations
    []
    """
    _check_problem(problem)
    if problem.method == "collocation":
        raise ParameterError("problem must be a HarmonicBalance or Shooting problem (switching needs a dense Jacobian)")
    if not isinstance(branch, Branch):
        raise ParameterError(f"branch must be a Branch from continue_periodic, got {type(branch).__name__}")
    if not isinstance(bifurcation, Bifurcation) or bifurcation.kind not in ("branch_point", "period_doubling"):
        raise ParameterError("bifurcation must be a 'branch_point' or 'period_doubling' Bifurcation of the branch")
    if bifurcation.state is None:
        raise ParameterError("bifurcation carries no state (was it unpickled from an old version?)")
    direction = check_choice("direction", direction, (1, -1))
    k = problem.model.param_index(branch.name)
    lo, hi = (float(branch.parameter.min()), float(branch.parameter.max())) if span is None else _check_span(span)
    lo, hi = min(lo, hi), max(lo, hi)
    p = problem.values.copy()
    for name, val in branch.values.items():
        p[problem.model.param_index(name)] = val
    prob = problem._at_size(bifurcation.size)
    X = bifurcation.state.copy()
    t_old = bifurcation.tangent.copy()
    if bifurcation.kind == "period_doubling":
        prob, embed = prob._doubled()
        X = np.append(embed(X[:-1]), X[-1])
        t_old = np.append(embed(t_old[:-1], tangent=True), t_old[-1])
    prob._begin_step(X[:-1])
    w = kernel_direction(prob, X, p, k, t_old) * direction
    length = abs(hi - lo)
    step = length / 200 if step is None else check_positive("step", step)
    max_step = length / 50 if max_step is None else check_positive("max_step", max_step)
    opt = _arc.Options(min(step, max_step), length * 1e-8, max_step, check_int("max_points", max_points, minimum=2))
    opt.stability = check_bool("stability", stability)
    ds = opt.step
    Ww = _arc.weights(prob, X) * w
    for _ in range(12):
        try:
            X1, _ = _arc.correct(prob, X + ds * w, p, k, Ww, X, ds, opt)
            break
        except ConvergenceError:
            ds /= 2
    else:
        raise ConvergenceError("could not step off the bifurcation onto the new branch")
    if not lo <= X1[-1] <= hi:
        raise ConvergenceError(f"the new branch leaves the span at once ({branch.name} = {X1[-1]:g}); widen span")
    raw = _arc.run(prob, k, p, X1[:-1], X1[-1], (lo, hi), opt, Monitor(_kinds(detect, opt.stability)), t0=w)
    return _branch(raw, prob, k, p, name=branch.name)
