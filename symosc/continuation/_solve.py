"""Newton's method, results and stability shared by the formulations (private)."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import ConvergenceError
from ._problem import Formulation, PointData


def _sorted_multipliers(rho: np.ndarray) -> np.ndarray:
    order = np.lexsort((-rho.imag, -np.abs(rho)))
    return rho[order]


def newton(prob: Formulation, u0: np.ndarray, p: np.ndarray, *, max_iterations: int = 50, tol: float = 1e-11):
    """Damped Newton's method for ``G(u, p) = 0`` at fixed p."""
    u = np.array(u0, dtype=float)
    G, J, _ = prob._evaluate(u, p)
    norm = np.linalg.norm(G)
    for _ in range(max_iterations):
        try:
            du = _solve(J, G)
        except (np.linalg.LinAlgError, RuntimeError) as exc:
            raise ConvergenceError(f"{prob.method}: singular Jacobian in Newton's method ({exc})") from exc
        lam = 1.0
        while True:
            trial = u - lam * du
            G2, J2, _ = prob._evaluate(trial, p)
            n2 = np.linalg.norm(G2)
            if np.isfinite(n2) and (n2 < norm or n2 < 1e-13 * (1 + np.linalg.norm(trial)) or lam < 1e-3):
                break
            lam /= 2
        u, G, J, norm = trial, G2, J2, n2
        if np.linalg.norm(lam * du) <= tol * (1 + np.linalg.norm(u)) and lam == 1.0:
            return u
    raise ConvergenceError(
        f"{prob.method}: Newton's method did not converge in {max_iterations} iterations (|G| = {norm:.2e}); "
        "give a better guess",
        achieved=float(norm),
    )


def _solve(J: Any, b: np.ndarray) -> np.ndarray:
    if isinstance(J, np.ndarray):
        return np.linalg.solve(J, b)
    from scipy.sparse.linalg import splu

    return splu(J.tocsc()).solve(b)


def solution_from(prob: Formulation, u: np.ndarray, p: np.ndarray, data: PointData) -> Any:
    from .branch import PeriodicSolution

    vals = {s.name: float(v) for s, v in zip(prob.model.params, p, strict=True)}
    rho = data.multipliers
    return PeriodicSolution(
        method=prob.method,
        frequency=float(data.frequency),
        amplitudes=tuple(float(a) for a in data.amplitudes),
        residual=float(data.residual),
        multipliers=rho,
        stable=_is_stable(rho, prob.autonomous),
        values=vals,
        coefficients=None if data.coefficients is None else np.asarray(data.coefficients),
        initial_state=np.asarray(data.initial_state),
        size=int(data.size),
        coordinates=tuple(s.name for s in prob.model.q),
        tolerance=float(getattr(prob, "tol", np.nan)),
    )


def _is_stable(rho: np.ndarray, autonomous: bool, tol: float = 1e-7) -> bool:
    if rho.size == 0:
        return False
    mags = np.abs(rho)
    if autonomous:  # drop the trivial multiplier (closest to 1)
        j = int(np.argmin(np.abs(rho - 1)))
        mags = np.delete(mags, j)
    return bool(np.all(mags < 1 - tol)) if mags.size else True
