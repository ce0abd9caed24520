"""Derivatives of the adjugate ``F(λ) = adj(λE - A)`` (Bulgakov §1.27)."""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import as_square_matrix
from .charpoly import adjugate_poly

__all__ = ["adjugate_derivative_at_root", "adjugate_derivatives"]


@validated
def adjugate_derivatives(A: Any, lam: sp.Symbol, count: int) -> list[sp.Matrix]:
    """``F(λ), F'(λ), ..., F^(count)(λ)`` for ``F(λ) = adj(λE - A)`` (Bulgakov (1954), §1.27, eq. (1.219)).

    F is taken as the matrix polynomial (1.219), ``F(λ) = E λ^(n-1) + (A + k_1 E) λ^(n-2) + ...``, and
    differentiated term by term.  Its trace is ``Δ'(λ)``, the derivative of ``Δ(λ) = det(λE - A)``, and so
    ``tr F^(p)(λ) = Δ^(p+1)(λ)``.

    Parameters
    ----------
    A : Matrix
        Square matrix.
    lam : Symbol
        The variable λ.
    count : int
        Highest derivative order wanted (``count >= 0``); derivatives of order ``>= n`` are zero.

    Returns
    -------
    list of Matrix
        ``count + 1`` matrices, the p-th being ``d^p F / dλ^p``.

    See Also
    --------
    adjugate_derivative_at_root, adjugate_poly, charpoly

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> adjugate_derivatives(sp.Matrix([[4, -3], [2, -1]]), l, 1)
    [Matrix([
    [l + 1,    -3],
    [    2, l - 4]]), Matrix([
    [1, 0],
    [0, 1]])]
    """
    if not isinstance(count, int) or isinstance(count, bool) or count < 0:
        raise ParameterError(f"count must be a non-negative integer, got {count!r}")
    F = adjugate_poly(as_square_matrix(A), lam)
    out = [F]
    for _ in range(count):
        F = F.diff(lam)
        out.append(F)
    return out


@validated
def adjugate_derivative_at_root(A: Any, root: Any, p: int) -> sp.Matrix:
    """``F^(p)(λ_σ)/p!`` at an eigenvalue as a product of matrices (Bulgakov (1954), §1.27, eq. (1.227)–(1.228)).

    ``F^(p)(λ_σ)/p! = (A - λ_σ E)^(q_σ-p-1) D_σ(A)`` for ``p = 0, ..., q_σ - 1`` with ``q_σ`` the multiplicity of
    ``λ_σ`` in ``Δ(λ)`` and ``D_σ(λ) = Δ(λ)/(λ - λ_σ)^(q_σ)``; for a simple root ``F(λ_σ) = Π_(ρ≠σ)(A - λ_ρ E)``
    (1.225).  These vanish for ``p < q_σ - e_σ`` (``e_σ`` the largest elementary divisor exponent).

    Parameters
    ----------
    A : Matrix
        Exact square matrix.
    root : Expr
        An eigenvalue of A.
    p : int
        ``0 <= p < q_σ``.

    Returns
    -------
    Matrix

    Raises
    ------
    ModelError
        ``root`` is not an eigenvalue of A.
    ParameterError
        p out of range.

    See Also
    --------
    adjugate_derivatives, spectral_decomposition

    Examples
    --------
    >>> import sympy as sp
    >>> A = sp.Matrix([[2, 1, 0], [0, 2, 0], [0, 0, 5]])
    >>> adjugate_derivative_at_root(A, 2, 1)
    Matrix([
    [-3,  1, 0],
    [ 0, -3, 0],
    [ 0,  0, 0]])
    """
    M = as_square_matrix(A)
    root = sp.sympify(root)
    lam = sp.Dummy("lam")
    delta = sp.Poly(M.charpoly(lam).all_coeffs(), lam)
    q = 0
    rest = delta
    lin = sp.Poly(lam - root, lam)
    while True:
        quo, rem = sp.div(rest, lin)
        if not rem.is_zero:
            break
        rest, q = quo, q + 1
    if q == 0:
        raise ModelError(f"{root} is not an eigenvalue of A (Δ({root}) = {sp.simplify(delta.eval(root))} ≠ 0)")
    if not isinstance(p, int) or isinstance(p, bool) or not 0 <= p < q:
        raise ParameterError(f"p must be an integer with 0 <= p < {q} (the multiplicity of {root}), got {p!r}")
    n = M.rows
    D = sp.zeros(n)
    for c in rest.all_coeffs():
        D = D * M + c * sp.eye(n)
    return ((M - root * sp.eye(n)) ** (q - p - 1) * D).applyfunc(sp.expand)
