"""Sum of a scalar power series with a matrix argument (Bulgakov §1.28, §1.30)."""

from __future__ import annotations

from typing import Any

import numpy as np
import sympy as sp

from ..._validate import validated
from ...errors import ConvergenceError, ParameterError
from .._util import as_square_matrix

__all__ = ["matrix_power_series"]


@validated
def matrix_power_series(
    A: Any, coefficient: Any, radius: float, *, k: sp.Symbol | None = None, tol: float = 1e-15, max_terms: int = 5000
) -> np.ndarray:
    """``Σ_(k>=0) a_k A^k`` summed numerically (Bulgakov (1954), §1.28 and §1.30, eq. (1.239)).

    The series converges when every eigenvalue lies inside the scalar disk of convergence, i.e. the spectral
    radius ``ρ(A) < R`` (§1.30); otherwise a ConvergenceError naming ``ρ(A)`` is raised instead of a number.

    Parameters
    ----------
    A : Matrix or ndarray
        Square matrix with numeric entries.
    coefficient : callable or Expr
        ``a_k``: a function of the integer k, or a SymPy expression in ``k``.
    radius : float
        Radius of convergence R of the scalar series (``float("inf")`` for an entire function).
    k : Symbol, optional
        Index symbol of an expression coefficient (default: its only free symbol).
    tol : float
        Stop when three successive terms are below ``tol`` times the norm of the partial sum.
    max_terms : int
        Number of terms after which ConvergenceError is raised.

    Returns
    -------
    ndarray

    Raises
    ------
    ConvergenceError
        ``ρ(A) >= R`` or the tolerance was not reached within ``max_terms`` terms (``achieved`` holds the last
        relative term size).

    See Also
    --------
    matrix_function, series_converges

    Examples
    --------
    ``log(E + A) = Σ (-1)^(k+1) A^k / k`` (radius 1):

    >>> import sympy as sp
    >>> k = sp.Symbol("k")
    >>> a = sp.Piecewise((0, sp.Eq(k, 0)), ((-1) ** (k + 1) / k, True))
    >>> L = matrix_power_series(sp.Matrix([[0, 0.5], [0, 0.25]]), a, 1)
    >>> [round(float(v), 12) for v in L.ravel()]
    [0.0, 0.446287102628, 0.0, 0.223143551314]
    """
    M = np.array(as_square_matrix(A).evalf().tolist(), dtype=complex)
    if not np.isfinite(M).all():
        raise ParameterError("A must have finite numeric entries")
    if callable(coefficient) and not isinstance(coefficient, sp.Basic):
        coef = coefficient
    else:
        expr = sp.sympify(coefficient)
        if k is None:
            free = sorted(expr.free_symbols, key=str)
            if len(free) > 1:
                raise ParameterError(f"coefficient has several symbols {free}; pass the index as k=")
            k = free[0] if free else sp.Symbol("k")
        coef = sp.lambdify(k, expr, modules=["mpmath"])
    rho = float(np.max(np.abs(np.linalg.eigvals(M))))
    if not rho < float(radius):
        raise ConvergenceError(
            f"the series diverges: spectral radius ρ(A) = {rho:.6g} is not below the radius of convergence "
            f"R = {float(radius):.6g} (Bulgakov (1954), §1.30)"
        )
    n = M.shape[0]
    P = np.eye(n, dtype=complex)
    S = np.zeros((n, n), dtype=complex)
    small, rel = 0, np.inf
    for j in range(max_terms):
        term = complex(coef(j)) * P
        S += term
        norm_s = np.linalg.norm(S)
        rel = np.linalg.norm(term) / norm_s if norm_s else np.linalg.norm(term)
        small = small + 1 if rel <= tol else 0
        if small >= 3 and j >= n:
            return S.real if np.allclose(S.imag, 0, atol=0) else S
        P = P @ M
    raise ConvergenceError(
        f"the series did not reach tol={tol:g} in {max_terms} terms (last relative term {rel:.3g}; ρ(A) = {rho:.6g})",
        achieved=float(rel),
    )
