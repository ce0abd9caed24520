"""Floquet multipliers of periodic solutions: monodromy by the compiled variational equations, Hill's method.

The monodromy matrix ``X(T)`` solves ``X' = A(t, y(t)) X``, ``X(0) = I`` along the orbit ``y' = f(t, y)`` through the
solution's initial state; ``f`` and ``A = df/dy`` are the model's compiled expressions, integrated together with
``scipy.integrate.solve_ivp`` (DOP853, or Radau with the exact Jacobian of the augmented system for stiff orbits).
Hill's method (harmonic balance only) takes the eigenvalues of the truncated Hill matrix (Krack & Gross 2019,
§4.1; Lazarus & Thomas 2010); the two computations are independent.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._validate import check_choice, check_int, check_positive, validated
from ..errors import ConvergenceError, ParameterError

__all__ = ["orbit_multipliers"]


def _integrated_monodromy(
    model: Any, p: np.ndarray, y0: np.ndarray, period: float, *, rtol: float = 1e-12, method: str = "DOP853"
) -> np.ndarray:
    """``X(T)`` by integrating the orbit and its variational equations together."""
    from scipy.integrate import solve_ivp

    f = model.first_order(p)
    d = f.dim

    def rhs(tt: float, z: np.ndarray) -> np.ndarray:
        fy, A, _ = f.all(tt, z[:d])
        X = z[d:].reshape(d, d)
        return np.concatenate([fy, (A @ X).ravel()])

    z0 = np.concatenate([np.asarray(y0, dtype=float), np.eye(d).ravel()])
    sol = solve_ivp(rhs, (0.0, period), z0, method=method, rtol=rtol, atol=rtol * 1e-2)
    if not sol.success:
        raise ConvergenceError(f"integration of the variational equations failed: {sol.message}")
    return sol.y[d:, -1].reshape(d, d)


def _series_monodromy(model: Any, p: np.ndarray, solution: Any, rtol: float) -> np.ndarray:
    """``X(T)`` of ``x' = A(t) x`` with A the Jacobian along the solution's Fourier series (symosc.periodic)."""
    from ..periodic import monodromy
    from . import _fourier

    f = model.first_order(p)
    c, om = solution.coefficients, solution.frequency
    dc = _fourier.derivative(c)

    def A(tt: float) -> np.ndarray:
        y = np.concatenate([_fourier.evaluate(c, [om * tt])[0], _fourier.evaluate(dc, [om * tt])[0] * om])
        return f.all(tt, y)[1]

    return monodromy(A, solution.period, rtol=rtol, atol=rtol * 1e-2, reversor=None, check_periodic=False).monodromy


@validated
def orbit_multipliers(
    problem: Any,
    solution: Any,
    *,
    method: str = "monodromy",
    along: str = "integrated",
    rtol: float = 1e-12,
    harmonics: int | None = None,
) -> np.ndarray:
    """Floquet multipliers of a periodic solution, by the monodromy matrix or by Hill's method.

    Parameters
    ----------
    problem : HarmonicBalance, Shooting or Collocation
        The formulation of the model: a problem from :func:`harmonic_balance`, :func:`shooting` or
        :func:`collocation` (its compiled equations are used).
    solution : PeriodicSolution
        The solution: a PeriodicSolution of that model (from ``problem.solve`` or ``Branch.solution``).
    method : {"monodromy", "hill"}, optional
        How the multipliers are computed: "monodromy" (default) or "hill".  ``"monodromy"``: integrate the
        variational equations over one period (compiled Jacobian).  ``"hill"``: eigenvalues of Hill's matrix
        (harmonic-balance solutions only).
    along : {"integrated", "series"}, optional
        The orbit of the monodromy computation: "integrated" (default) or "series".  Along the orbit integrated
        from the solution's initial state together with the variational equations (the exact orbit's
        multipliers), or along the solution's own Fourier series (:func:`symosc.periodic.monodromy` of ``A(t)``:
        the same linear periodic system as Hill's method, so that the two stability computations can be compared
        independently of the truncation of the orbit).  Ignored by Hill's method.
    rtol : float, optional
        Relative tolerance of the integration (monodromy): a positive number (default 1e-12).
    harmonics : int, optional
        Truncation of Hill's matrix: an integer from 1 to 800 (default: the solution's harmonics).

    Returns
    -------
    ndarray
        The 2n multipliers, largest modulus first.

    See Also
    --------
    symosc.periodic.monodromy : Floquet theory of linear periodic systems.

    Examples
    --------
    >>> import numpy as np, sympy as sp
    >>> from symosc.continuation import harmonic_balance, orbit_multipliers
    >>> x, v, t, w = sp.symbols("x v t w")
    >>> hb = harmonic_balance(-0.1 * v - x - x**3 + sp.cos(w * t), x, v, t, forcing_frequency=w, values={"w": 2.0})
    >>> sol = hb.solve()
    >>> rho_m = orbit_multipliers(hb, sol)
    >>> rho_h = orbit_multipliers(hb, sol, method="hill")
    >>> bool(np.max(np.abs(np.sort_complex(rho_m) - np.sort_complex(rho_h))) < 1e-8)
    True
    """
    from ._problem import Formulation
    from .branch import PeriodicSolution

    if not isinstance(problem, Formulation):
        raise ParameterError(
            f"problem must be a HarmonicBalance, Shooting or Collocation, got {type(problem).__name__}"
        )
    if not isinstance(solution, PeriodicSolution):
        raise ParameterError(f"solution must be a PeriodicSolution, got {type(solution).__name__}")
    check_choice("method", method, ("monodromy", "hill"))
    check_choice("along", along, ("integrated", "series"))
    rtol = check_positive("rtol", rtol)
    p = problem._with_values(solution.values).values
    if method == "monodromy":
        if along == "series":
            if solution.coefficients is None:
                raise ParameterError("along='series' needs a harmonic-balance solution (Fourier coefficients)")
            M = _series_monodromy(problem.model, p, solution, rtol)
        else:
            M = _integrated_monodromy(problem.model, p, solution.initial_state, solution.period, rtol=rtol)
        rho = np.linalg.eigvals(M)
        return rho[np.lexsort((-rho.imag, -np.abs(rho)))]
    if problem.method != "harmonic balance" or solution.coefficients is None:
        raise ParameterError("method='hill' needs a harmonic-balance problem and solution")
    H = solution.size if harmonics is None else check_int("harmonics", harmonics, minimum=1, maximum=800)
    prob = problem._at_size(H)
    if not problem.autonomous:
        ratio = solution.values[problem.model.forcing_frequency.name] / solution.frequency
        m = round(ratio)
        if m != prob.period_multiple:
            prob = prob._with_harmonics(H, period_multiple=m)
    u = prob._pack(solution.coefficients, solution.frequency if problem.autonomous else None)
    return prob._hill_multipliers(u, p)
