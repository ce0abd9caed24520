"""Loop algebra of regulated systems (Bulgakov (1954), §10.1–10.3, 10.6).

Links ``f_j(D) y_j = e_j(D) y_(j-1)`` have transmittances ``X_j = f_j⁻¹ e_j``; a chain multiplies them right to
left, ``X = X_n ... X_1`` (§10.1).  Closing a loop with negative feedback gives the return difference
``E + X`` (Bode) and the characteristic polynomial ``Δ = Δ0 det(E + X)`` (10.15)–(10.16), expanded by principal
minors ``det(E + X) = 1 + Σ X_ii + Σ (2x2 principal minors) + ... + det X`` (10.17)–(10.18).
"""

from __future__ import annotations

from itertools import combinations
from typing import Any

import sympy as sp

from ..._validate import check_sympy_matrix, validated
from ...errors import ModelError, ParameterError

__all__ = ["chain_transmittance", "closed_loop_characteristic", "return_difference"]


@validated
def chain_transmittance(*links: Any) -> sp.Expr | sp.Matrix:
    """Transmittance of links in cascade, ``X_n … X_2 X_1`` (signal flows from ``X_1``) (§10.1).

    Parameters
    ----------
    links : sympy.Expr or sympy.Matrix
        The transmittances ``X_1, ..., X_n`` in the order the signal flows; at least one, scalar expressions or
        matrices of compatible sizes (``X_(j+1)`` has as many columns as ``X_j`` has rows).

    Returns
    -------
    sympy.Expr or sympy.Matrix
        The simplified product.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import chain_transmittance
    >>> D = sp.Symbol("D")
    >>> chain_transmittance(1 / (D + 1), 2 / D)
    2/(D*(D + 1))

    See Also
    --------
    closed_loop_characteristic, return_difference
    """
    if not links:
        raise ParameterError("give at least one link")
    out = links[0]
    for X in links[1:]:
        try:
            out = X * out
        except (TypeError, ValueError, sp.ShapeError) as exc:
            raise ModelError(f"links of incompatible sizes in the chain: {exc}") from exc
    return sp.simplify(out) if not isinstance(out, sp.MatrixBase) else out.applyfunc(sp.simplify)


@validated
def return_difference(X: Any, *, expand_minors: bool = False) -> sp.Expr:
    """``det(E + X)`` of a square transmittance matrix (10.16); with ``expand_minors`` the sum (10.17).

    Parameters
    ----------
    X : sympy.Matrix
        Open-chain transmittance matrix; must be a square SymPy matrix.
    expand_minors : bool, optional
        Compute ``1 + Σ X_ii + Σ (2x2 principal minors) + ... + det X`` (10.17) instead of the determinant
        (default False; the result is the same).

    Returns
    -------
    sympy.Expr

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import return_difference
    >>> a, b, c, d = sp.symbols("a b c d")
    >>> sp.expand(return_difference(sp.Matrix([[a, b], [c, d]]), expand_minors=True))
    a*d + a - b*c + d + 1

    See Also
    --------
    closed_loop_characteristic
    """
    X = check_sympy_matrix("X", X)
    if X.rows != X.cols:
        raise ModelError(f"the open-chain transmittance must be square, got {X.shape}")
    if not expand_minors:
        return sp.cancel((sp.eye(X.rows) + X).det())
    total = sp.Integer(1)
    for k in range(1, X.rows + 1):
        for idx in combinations(range(X.rows), k):
            total += X.extract(list(idx), list(idx)).det()
    return sp.cancel(total)


@validated
def closed_loop_characteristic(open_loop: Any, var: sp.Symbol) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """``(Δ0, M, Δ = Δ0 + M)`` of a scalar loop ``K = M/Δ0`` closed by negative feedback (10.19)–(10.20).

    Parameters
    ----------
    open_loop : sympy.Expr
        Open-loop transmittance ``K``: a proper rational function of ``var`` (``deg M <= deg Δ0``).
    var : sympy.Symbol
        The operator or Laplace variable ``D``; must be a SymPy Symbol.

    Returns
    -------
    tuple of sympy.Expr
        ``(Δ0, M, Δ)`` with ``Δ0`` made monic.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import closed_loop_characteristic
    >>> D, k = sp.symbols("D k")
    >>> closed_loop_characteristic(k / (D * (D + 1)), D)[2]
    D**2 + D + k

    See Also
    --------
    nyquist, hurwitz
    """
    K = sp.cancel(sp.together(sp.sympify(open_loop)))
    M, D0 = sp.fraction(K)
    if sp.degree(M, var) > sp.degree(D0, var):
        raise ModelError("the open loop K = M/Δ0 must be proper (deg M ≤ deg Δ0)")
    lc = sp.Poly(D0, var).LC()
    M, D0 = sp.expand(M / lc), sp.expand(D0 / lc)
    return D0, M, sp.expand(D0 + M)
