"""Test functions of the codimension-one bifurcations of periodic solutions, their location, branch switching.

Test functions (Seydel 2010, ch. 5; Kuznetsov 2004, §10.2), evaluated at every point of a branch:

* fold (limit point): the parameter component of the unit tangent, ``t_lambda``;
* branch point: the sign of ``det [[G_u, G_lambda], [t^T]]``, which keeps its sign through folds (the tangent's
  orientation is continuous) and changes it at a simple branch point;
* period doubling: ``prod (1 + rho_i)`` over the Floquet multipliers (a real multiplier through -1);
* Neimark–Sacker: ``prod_{i<j} (rho_i rho_j - 1)`` over the non-trivial multipliers (a complex pair through the unit
  circle; a zero from a real pair with ``rho_i rho_j = 1`` is a neutral saddle and is discarded).

A sign change between two points is located by Brent's method on the arclength from the first of them, each trial
point being corrected onto the branch.  Switching at a branch point uses the two-dimensional kernel of
``[G_u, G_lambda]``: the new direction is the kernel vector orthogonal to the old tangent.  A period doubling is a
branch point of the doubled-period problem, so the same construction switches to the doubled orbit.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import ConvergenceError
from . import arclength as _arc
from .branch import Bifurcation

__all__: list[str] = []

_MULTIPLIER_KINDS = ("period_doubling", "neimark_sacker")


def _nontrivial(rho: np.ndarray, autonomous: bool) -> np.ndarray:
    if autonomous and rho.size:
        return np.delete(rho, int(np.argmin(np.abs(rho - 1))))
    return rho


def test_values(kind: str, t: np.ndarray, ls: Any, rho: np.ndarray, autonomous: bool) -> float:
    if kind == "fold":
        return float(t[-1])
    if kind == "branch_point":
        return ls.det_sign()
    if rho.size == 0:
        return float("nan")
    if kind == "period_doubling":
        return float(np.real(np.prod(1 + rho)))
    r = _nontrivial(rho, autonomous)
    prod = 1.0 + 0j
    for i in range(len(r)):
        for j in range(i + 1, len(r)):
            prod *= r[i] * r[j] - 1
    return float(np.real(prod))


class Monitor:
    """Evaluates the test functions along a branch and locates their zeros."""

    def __init__(self, kinds: tuple[str, ...]) -> None:
        self.kinds = kinds

    def values(self, prob: Any, t: np.ndarray, ls: Any, data: Any) -> dict[str, float]:
        return {k: test_values(k, t, ls, data.multipliers, prob.autonomous) for k in self.kinds}

    def initial(self, prob: Any, X: np.ndarray, t: np.ndarray, ls: Any, data: Any) -> dict[str, float]:
        return self.values(prob, t, ls, data)

    def check(self, prob, X0, t0, X1, t1, ls1, data1, ds, state, out, p, k, opt) -> dict[str, float]:
        new = self.values(prob, t1, ls1, data1)
        found = []
        for kind in self.kinds:
            a, b = state.get(kind, np.nan), new[kind]
            if not (np.isfinite(a) and np.isfinite(b)) or np.sign(a) == np.sign(b) or a == 0:
                continue
            Wt = _arc.weights(prob, X0) * t0
            s1 = float(Wt @ (X1 - X0))
            bif = locate(kind, prob, X0, t0, s1, a, b, p, k, opt, index=len(out.X) - 1)
            if bif is not None:
                found.append((float(Wt @ (bif.state - X0)), bif))
        out.bifurcations.extend(b for _, b in sorted(found, key=lambda item: item[0]))
        return new


def locate(kind, prob, X0, t0, s1, f0, f1, p, k, opt, *, index: int) -> Bifurcation | None:
    """Zero of the test function ``kind`` between arclength 0 (value f0) and s1 (value f1) from ``X0``."""
    import dataclasses
    import itertools

    from scipy.optimize import brentq

    # near a branch point the corrector's matrix is nearly singular and Newton's method converges only linearly
    opt = dataclasses.replace(opt, max_newton=60)
    cache: dict[float, tuple] = {}
    Wt = _arc.weights(prob, X0) * t0
    log0 = None
    if kind == "branch_point":  # a continuous test function for Brent: det scaled by its size at the start
        log0 = _arc.tangent(prob, X0, p, k, Wt)[1].det_log()[1]
        f0 = float(np.sign(f0))
        f1 = float(np.sign(f1))

    def at(s: float) -> tuple:
        if s not in cache:
            X, _ = _arc.correct(prob, X0 + s * t0, p, k, Wt, X0, s, opt)
            t, ls = _arc.tangent(prob, X, p, k, Wt)
            data = _arc.point_data(prob, X, p, k, opt) if kind in _MULTIPLIER_KINDS else None
            rho = data.multipliers if data is not None else np.array([])
            if log0 is not None:
                sign, log = ls.det_log()
                value = sign * float(np.exp(np.clip(log - log0, -700, 700)))
            else:
                value = test_values(kind, t, ls, rho, prob.autonomous)
            cache[s] = (X, t, ls, data, value)
        return cache[s]

    def f(s: float) -> float:
        if s == 0.0:
            return f0
        if s == s1:
            return f1
        return at(s)[4]

    located = True
    try:
        s = brentq(f, 0.0, s1, xtol=1e-14 * max(1.0, abs(s1)), rtol=1e-15, maxiter=80)
        X, t, _, data, value = at(s)
    except (ConvergenceError, RuntimeError, ValueError):
        # the corrector fails very close to a branch point: interpolate in the tightest bracket found
        pts = sorted([(0.0, f0, X0), (s1, f1, None)] + [(q, c[4], c[0]) for q, c in cache.items()], key=lambda z: z[0])
        pairs = [(a, b) for a, b in itertools.pairwise(pts) if np.sign(a[1]) != np.sign(b[1])]
        if not pairs:
            return None
        (sa, fa, Xa), (sb, fb, Xb) = min(pairs, key=lambda ab: ab[1][0] - ab[0][0])
        if Xb is None:
            Xb, _ = _arc.correct(prob, X0 + sb * t0, p, k, Wt, X0, sb, opt)
        theta = fa / (fa - fb) if fa != fb else 0.5
        X = Xa + theta * (Xb - Xa)
        located = abs(sb - sa) <= 1e-6 * max(abs(s1), 1e-300)
        value = float(abs(sb - sa))
        t = t0
        data = _arc.point_data(prob, X, p, k, opt)
    if data is None:
        data = _arc.point_data(prob, X, p, k, opt)
    rho = data.multipliers
    if kind == "neimark_sacker":  # a complex pair on the unit circle (not a neutral saddle)
        r = _nontrivial(rho, prob.autonomous)
        pair = r[(np.abs(r.imag) > 1e-6) & (np.abs(np.abs(r) - 1) < 1e-3)]
        if pair.size == 0:
            return None
    if kind == "period_doubling" and rho.size and np.min(np.abs(rho + 1)) > 1e-3:
        return None
    if kind == "branch_point" and located:
        value = 0.0
    return Bifurcation(
        kind=kind,
        parameter=float(X[-1]),
        amplitude=float(data.amplitudes[0]),
        frequency=float(data.frequency),
        multipliers=rho,
        located=located,
        test=float(value),
        index=index,
        state=X.copy(),
        tangent=t.copy(),
        size=int(data.size),
        initial_state=np.asarray(data.initial_state, dtype=float).copy(),
    )


def kernel_direction(prob: Any, X: np.ndarray, p: np.ndarray, k: int, old: np.ndarray) -> np.ndarray:
    """The unit vector of the two-dimensional kernel of ``[G_u, G_lambda]`` at X orthogonal to ``old``."""
    import scipy.linalg as sla

    _, J, Gl = _arc.evaluate_full(prob, X, p, k)
    J = J.toarray() if hasattr(J, "toarray") else J
    A = np.hstack([J, Gl.reshape(-1, 1)])
    _, _, Vh = sla.svd(A)
    V = Vh[-2:].T  # the two right singular vectors of the smallest singular values (A is n x (n+1))
    old = old / np.linalg.norm(old)
    # remove the old tangent's projection from the kernel; what is left is the new branch's direction
    proj = V @ (V.T @ old)
    c = V.T @ old
    w = V @ np.array([-c[1], c[0]]) if np.linalg.norm(proj) > 1e-3 else V[:, 0]
    return w / np.linalg.norm(w)
