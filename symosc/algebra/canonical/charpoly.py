"""Characteristic polynomials by the classical methods of Bulgakov §1.26–1.27 and the adjugate ``F(λ)``.

* :func:`leverrier` — Newton's sums ``s_k = tr A^k``: ``k_j = -(s_j + k_1 s_{j-1} + ... + k_{j-1} s_1)/j``.
* :func:`krylov` — the Krylov sequence ``v, Av, ..., A^n v`` and one linear solve.
* :func:`danilevsky` — similarity reduction to Frobenius (companion) form, with the degenerate case (a zero pivot
  with nothing to swap) split into block-triangular pieces.
* :func:`adjugate_poly` — ``F(λ) = adj(λE - A) = Φ(λ, A)`` as a matrix polynomial (1.218–1.219).

All work in exact arithmetic on SymPy matrices (symbolic entries allowed) and return ``sympy.Poly`` in ``λ``.
"""

from __future__ import annotations

import sympy as sp

from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import as_square_matrix, is_float_matrix

__all__ = ["adjugate_poly", "charpoly", "danilevsky", "krylov", "leverrier"]


def _check_symbol(lam: sp.Symbol) -> sp.Symbol:
    if not isinstance(lam, sp.Symbol):
        raise ParameterError(f"the polynomial variable must be a SymPy Symbol, got {lam!r}")
    return lam


def _poly_from_coeffs(coeffs: list[sp.Expr], lam: sp.Symbol) -> sp.Poly:
    """``λ^n + k_1 λ^(n-1) + ... + k_n`` from ``[k_1, ..., k_n]``."""
    n = len(coeffs)
    expr = lam**n + sum(sp.expand(k) * lam ** (n - 1 - i) for i, k in enumerate(coeffs))
    return sp.Poly(expr, lam)


@validated
def leverrier(A: sp.Matrix, lam: sp.Symbol) -> sp.Poly:
    """Characteristic polynomial ``det(λE - A)`` by Leverrier's method (Newton's sums of traces of powers).

    Parameters
    ----------
    A : Matrix
        Square matrix, exact or symbolic.
    lam : Symbol
        The variable of the polynomial.

    Returns
    -------
    Poly
        Monic polynomial of degree n.

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> leverrier(sp.Matrix([[4, -3], [2, -1]]), l).as_expr()
    l**2 - 3*l + 2
    """
    A = as_square_matrix(A)
    _check_symbol(lam)
    n = A.rows
    s = []
    P = sp.eye(n)
    for _ in range(n):
        P = (P * A).applyfunc(sp.expand)
        s.append(sp.expand(P.trace()))
    k: list[sp.Expr] = []
    for j in range(1, n + 1):
        acc = s[j - 1] + sum(k[i] * s[j - 2 - i] for i in range(j - 1))
        k.append(sp.expand(-acc / j))
    return _poly_from_coeffs(k, lam)


@validated
def krylov(A: sp.Matrix, lam: sp.Symbol, v: sp.Matrix | None = None, *, fallback: bool = True) -> sp.Poly:
    """Characteristic polynomial by Krylov's method.

    The sequence ``v, Av, ..., A^n v`` satisfies ``A^n v + k_1 A^(n-1) v + ... + k_n v = 0``; when the first n
    vectors are independent this linear system gives the coefficients.  Without ``v`` the unit vectors
    ``e_1, ..., e_n`` and their sum are tried in turn.

    Parameters
    ----------
    A : Matrix
        Square matrix.
    lam : Symbol
        Polynomial variable.
    v : Matrix, optional
        Start vector (n×1).
    fallback : bool
        If no start vector generates the whole space (always so for a derogatory matrix, whose minimal
        polynomial has degree < n), fall back to :func:`danilevsky`; otherwise raise ``ModelError``.

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> krylov(sp.Matrix([[2, 1], [0, 3]]), l).as_expr()
    l**2 - 5*l + 6
    """
    A = as_square_matrix(A)
    _check_symbol(lam)
    n = A.rows
    if v is not None:
        v = sp.Matrix(v)
        if v.shape != (n, 1):
            raise ParameterError(f"start vector must be {n}x1, got {v.shape[0]}x{v.shape[1]}")
        candidates = [v]
    else:
        candidates = [sp.eye(n)[:, i] for i in range(n)] + [sp.ones(n, 1)]
    for w in candidates:
        cols = [w]
        for _ in range(n):
            cols.append((A * cols[-1]).applyfunc(sp.expand))
        K = sp.Matrix.hstack(*cols[:n])
        det = sp.simplify(K.det())
        if det == 0:
            continue
        c = K.LUsolve(-cols[n]).applyfunc(sp.cancel)
        return _poly_from_coeffs([c[n - 1 - i] for i in range(n)], lam)
    if fallback:
        return danilevsky(A, lam)
    raise ModelError(
        "Krylov's method degenerates: no start vector generates the whole space (the matrix is derogatory "
        "or the vector lies in an invariant subspace); pass another v, or use danilevsky()/leverrier()"
    )


def _frobenius_charpoly(first_row: list[sp.Expr], lam: sp.Symbol) -> sp.Expr:
    m = len(first_row)
    return lam**m - sum(p * lam ** (m - 1 - i) for i, p in enumerate(first_row))


def _is_zero(e: sp.Expr) -> bool:
    return sp.simplify(e) == 0


def _danilevsky_factors(A: sp.Matrix, lam: sp.Symbol) -> list[sp.Expr]:
    A = A.copy()
    n = A.rows
    factors: list[sp.Expr] = []
    end = n  # rows/cols end..n-1 are already split off
    r = n - 1
    floating = is_float_matrix(A)
    # floating point: partial pivoting (largest entry left of the diagonal), entries below the rounding level
    # of ||A|| count as zero -- a 1e-17 pivot would otherwise put 1e17-sized numbers into the polynomial
    small = 1e-13 * max((abs(complex(v)) for v in A), default=0.0) if floating else 0.0
    while r >= 1:
        if floating:
            j = max(range(r), key=lambda c: abs(complex(A[r, c])))
            if abs(complex(A[r, j])) <= small:
                A[r, :r] = sp.zeros(1, r)
            elif j != r - 1:
                A.row_swap(j, r - 1)
                A.col_swap(j, r - 1)
        if _is_zero(A[r, r - 1]):
            j = next((j for j in range(r - 1) if not _is_zero(A[r, j])), None)
            if j is None:
                # degenerate case: row r has no entry left of the diagonal block -> block triangular split
                factors.append(_frobenius_charpoly(list(A[r, r:end]), lam))
                end = r
                r -= 1
                continue
            # permutation similarity swapping indices j and r-1
            A.row_swap(j, r - 1)
            A.col_swap(j, r - 1)
        piv = A[r, r - 1]
        Minv = sp.eye(n)
        M = sp.eye(n)
        for c in range(end):
            Minv[r - 1, c] = A[r, c]
            M[r - 1, c] = -A[r, c] / piv
        M[r - 1, r - 1] = 1 / piv
        A = (Minv * A * M).applyfunc(sp.cancel)
        r -= 1
    factors.append(_frobenius_charpoly(list(A[0, 0:end]), lam))
    return factors


@validated
def danilevsky(A: sp.Matrix, lam: sp.Symbol) -> sp.Poly:
    """Characteristic polynomial by Danilevsky's reduction to Frobenius form.

    Row by row from the bottom, a similarity ``A -> M^-1 A M`` turns row r into the unit row ``e_(r-1)``.  A zero
    pivot is cured by a permutation similarity with an earlier column; when there is none the matrix is block
    upper-triangular and the characteristic polynomial is the product of the blocks' polynomials (the
    degenerate case).  Float matrices use partial pivoting (the largest entry of the row left of the diagonal)
    and treat entries below ``1e-13 max|a_ij|`` as zero.

    Parameters
    ----------
    A : Matrix
        Square, non-empty matrix (exact, symbolic or float entries).
    lam : Symbol
        The variable of the polynomial; it must be a SymPy Symbol.

    Returns
    -------
    Poly
        Monic polynomial ``det(λE - A)`` of degree n in ``lam``.

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> sp.factor(danilevsky(sp.Matrix([[2, 0, 0], [0, 2, 0], [1, 1, 3]]), l).as_expr())
    (l - 3)*(l - 2)**2
    """
    A = as_square_matrix(A)
    _check_symbol(lam)
    expr = sp.Mul(*_danilevsky_factors(A, lam))
    return sp.Poly(sp.expand(expr), lam)


@validated
def charpoly(A: sp.Matrix, lam: sp.Symbol, method: str = "leverrier") -> sp.Poly:
    """``det(λE - A)`` by ``method`` in {"leverrier", "krylov", "danilevsky", "berkowitz"} (the last is SymPy's).

    Parameters
    ----------
    A : Matrix
        Square, non-empty matrix (exact or symbolic entries).
    lam : Symbol
        The variable of the polynomial; it must be a SymPy Symbol.
    method : {"leverrier", "krylov", "danilevsky", "berkowitz"}
        Method, one of the four names: :func:`leverrier`, :func:`krylov`, :func:`danilevsky` or SymPy's
        Berkowitz algorithm.

    Returns
    -------
    Poly
        Monic polynomial ``det(λE - A)`` of degree n in ``lam``.

    Examples
    --------
    >>> import sympy as sp
    >>> charpoly(sp.Matrix([[0, 1], [-4, 0]]), sp.Symbol("l"), method="danilevsky").as_expr()
    l**2 + 4
    """
    methods = {"leverrier": leverrier, "krylov": krylov, "danilevsky": danilevsky}
    if method == "berkowitz":
        A = as_square_matrix(A)
        return sp.Poly(A.charpoly(_check_symbol(lam)).as_expr(), lam)
    if method not in methods:
        raise ParameterError(f"unknown method {method!r}; choose leverrier, krylov, danilevsky or berkowitz")
    return methods[method](A, lam)


@validated
def adjugate_poly(A: sp.Matrix, lam: sp.Symbol) -> sp.Matrix:
    """The adjugate ``F(λ) = adj(λE - A)`` as a polynomial in λ, by Bulgakov (1.219).

    ``F(λ) = E λ^(n-1) + (A + k_1 E) λ^(n-2) + ... + (A^(n-1) + k_1 A^(n-2) + ... + k_(n-1) E)`` where
    ``det(λE - A) = λ^n + k_1 λ^(n-1) + ... + k_n``.

    Parameters
    ----------
    A : Matrix
        Square, non-empty n x n matrix (exact or symbolic entries).
    lam : Symbol
        The variable λ of ``F(λ)``; it must be a SymPy Symbol.

    Returns
    -------
    Matrix
        n x n matrix whose entries are polynomials of degree <= n - 1 in ``lam`` (expanded).

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> adjugate_poly(sp.Matrix([[4, -3], [2, -1]]), l)
    Matrix([
    [l + 1,    -3],
    [    2, l - 4]])
    """
    A = as_square_matrix(A)
    n = A.rows
    k = leverrier(A, lam).all_coeffs()[1:]
    B = sp.eye(n)
    F = B * lam ** (n - 1)
    for j in range(1, n):
        B = (A * B + k[j - 1] * sp.eye(n)).applyfunc(sp.expand)
        F += B * lam ** (n - 1 - j)
    return F.applyfunc(sp.expand)
