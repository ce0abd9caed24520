"""Block matrices: inverse and determinant by blocks, bordering, cyclic blocks, triangular series (Bulgakov §1.5–1.7).

With ``a = [[a11, a12], [a21, a22]]`` and the Schur complements ``beta1 = a11 - a12 a22^-1 a21``,
``beta2 = a22 - a21 a11^-1 a12`` (1.63):

* (1.67) ``a^-1 = [[a11^-1 + a11^-1 a12 beta2^-1 a21 a11^-1, -a11^-1 a12 beta2^-1], [-beta2^-1 a21 a11^-1, beta2^-1]]``
  (only ``a11^-1`` and ``beta2^-1`` are needed); (1.64) the form with ``beta1^-1`` and ``a22^-1``.
* (1.76) ``det a = det a11 det beta2``; (1.77) ``det a = det beta1 det a22``.
* Bordering (§1.5 Ex. 4, §1.7 Ex. 3–4): the inverse and the leading minors grow one row and column at a time with
  (1.67) and (1.76) for a scalar ``beta2``; a zero ``beta2`` is cured by a row permutation ``b = u a``, then
  ``a^-1 = b^-1 u`` and ``det a = det b / det u``.
* (1.79) the determinant of a cyclic block matrix; (1.73)/(1.74) the inverse and adjugate of an upper triangular
  matrix with equal diagonal ``c = a E + gamma`` as finite series in the nilpotent ``gamma``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import as_square_matrix

__all__ = [
    "BorderingInverse",
    "block_determinant",
    "block_inverse",
    "bordering_inverse",
    "cyclic_block_determinant",
    "triangular_adjugate_series",
    "triangular_inverse_series",
]


def _blocks(a11: Any, a12: Any, a21: Any, a22: Any) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix, sp.Matrix]:
    a11, a22 = as_square_matrix(a11, "a11"), as_square_matrix(a22, "a22")
    try:
        a12, a21 = sp.Matrix(a12), sp.Matrix(a21)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"a12 and a21 must be matrices: {exc}") from exc
    if a12.shape != (a11.rows, a22.rows) or a21.shape != (a22.rows, a11.rows):
        raise ModelError(
            f"block shapes do not fit: a11 {a11.shape}, a12 {a12.shape}, a21 {a21.shape}, a22 {a22.shape} "
            f"(need a12 {a11.rows}x{a22.rows} and a21 {a22.rows}x{a11.rows})"
        )
    return a11, a12, a21, a22


def _is_zero(e: sp.Expr) -> bool:
    return sp.simplify(e) == 0


def _inv(m: sp.Matrix, name: str) -> sp.Matrix:
    if _is_zero(m.det()):
        raise ModelError(f"{name} is singular")
    return m.inv().applyfunc(sp.simplify)


@validated
def block_inverse(a11: Any, a12: Any, a21: Any, a22: Any) -> sp.Matrix:
    """Inverse of ``[[a11, a12], [a21, a22]]`` by Bulgakov (1.67) (or (1.64) when ``a11`` is singular).

    Parameters
    ----------
    a11 : Matrix, nested list or ndarray
        Square top-left block (m x m, exact or symbolic entries); it or ``a22`` must be invertible.
    a12 : Matrix, nested list or ndarray
        Top-right block, which must be m x k (the rows of ``a11`` by the columns of ``a22``).
    a21 : Matrix, nested list or ndarray
        Bottom-left block, which must be k x m (the rows of ``a22`` by the columns of ``a11``).
    a22 : Matrix, nested list or ndarray
        Square bottom-right block (k x k, exact or symbolic entries); it or ``a11`` must be invertible.

    Returns
    -------
    Matrix
        The (m + k) x (m + k) inverse, simplified entry by entry.

    Raises
    ------
    ModelError
        If the blocks do not fit together, or the matrix (a Schur complement) is singular.

    See Also
    --------
    block_determinant, bordering_inverse

    Examples
    --------
    >>> import sympy as sp
    >>> block_inverse(sp.Matrix([[2]]), sp.Matrix([[1, 0]]), sp.Matrix([[0], [1]]), sp.Matrix([[1, 1], [0, 3]]))
    Matrix([
    [ 3/7, -3/7,  1/7],
    [ 1/7,  6/7, -2/7],
    [-1/7,  1/7,  2/7]])
    """
    a11, a12, a21, a22 = _blocks(a11, a12, a21, a22)
    if not _is_zero(a11.det()):
        a11i = _inv(a11, "a11")
        beta2 = a22 - a21 * a11i * a12
        b2i = _inv(beta2, "the Schur complement beta2 = a22 - a21 a11^-1 a12 (so the whole matrix)")
        top_left = a11i + a11i * a12 * b2i * a21 * a11i
        out = sp.BlockMatrix([[top_left, -a11i * a12 * b2i], [-b2i * a21 * a11i, b2i]]).as_explicit()
    else:
        a22i = _inv(a22, "a11 is singular and a22")
        beta1 = a11 - a12 * a22i * a21
        b1i = _inv(beta1, "the Schur complement beta1 = a11 - a12 a22^-1 a21 (so the whole matrix)")
        out = sp.BlockMatrix([[b1i, -b1i * a12 * a22i], [-a22i * a21 * b1i, a22i + a22i * a21 * b1i * a12 * a22i]])
        out = out.as_explicit()
    return sp.Matrix(out).applyfunc(sp.simplify)


@validated
def block_determinant(a11: Any, a12: Any, a21: Any, a22: Any) -> sp.Expr:
    """``det [[a11, a12], [a21, a22]] = det a11 det beta2`` (1.76), or ``det beta1 det a22`` (1.77).

    When both diagonal blocks are singular the determinant of the assembled matrix is returned.

    Parameters
    ----------
    a11 : Matrix, nested list or ndarray
        Square top-left block (m x m, exact or symbolic entries).
    a12 : Matrix, nested list or ndarray
        Top-right block, which must be m x k (the rows of ``a11`` by the columns of ``a22``).
    a21 : Matrix, nested list or ndarray
        Bottom-left block, which must be k x m (the rows of ``a22`` by the columns of ``a11``).
    a22 : Matrix, nested list or ndarray
        Square bottom-right block (k x k, exact or symbolic entries).

    Returns
    -------
    Expr
        The determinant, simplified.

    See Also
    --------
    block_inverse

    Examples
    --------
    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> block_determinant(sp.Matrix([[x]]), sp.Matrix([[1, 2]]), sp.Matrix([[3], [4]]), sp.eye(2))
    x - 11
    """
    a11, a12, a21, a22 = _blocks(a11, a12, a21, a22)
    d11 = a11.det()
    if not _is_zero(d11):
        return sp.simplify(d11 * (a22 - a21 * a11.adjugate() * a12 / d11).det())
    d22 = a22.det()
    if not _is_zero(d22):
        return sp.simplify((a11 - a12 * a22.adjugate() * a21 / d22).det() * d22)
    return sp.simplify(sp.Matrix(sp.BlockMatrix([[a11, a12], [a21, a22]]).as_explicit()).det())


@dataclass(frozen=True)
class BorderingInverse(SymPyPrintable):
    """Result of :func:`bordering_inverse`.

    Attributes
    ----------
    inverse : Matrix
        ``a^-1``.
    determinant : Expr
        ``det a``.
    leading_minors : tuple
        Determinants of the leading k x k blocks of the row-permuted matrix ``b = u a`` (k = 1..n).
    row_order : tuple of int
        Rows of ``a`` in the order used (the identity unless a zero ``beta2`` forced a permutation, §1.7 Ex. 4).
    """

    inverse: sp.Matrix = field(repr=False)
    determinant: sp.Expr
    leading_minors: tuple
    row_order: tuple

    def _repr_latex_(self) -> str:
        return f"$a^{{-1}} = {sp.latex(self.inverse)},\\ \\det a = {sp.latex(self.determinant)}$"


@validated
def bordering_inverse(a: Any) -> BorderingInverse:
    """Inverse and determinant by bordering (Bulgakov §1.5 Ex. 4, §1.7 Ex. 3–4).

    Starting from the top-left entry, each step borders the known inverse with one row and one column using (1.67)
    with a scalar ``beta2 = d - c a_k^-1 b`` and multiplies the determinant by ``beta2`` (1.76).  When ``beta2 = 0``
    a later row is swapped in (``b = u a``); finally ``a^-1 = b^-1 u``.

    Parameters
    ----------
    a : Matrix, nested list or ndarray
        Square, non-empty, invertible matrix (exact or symbolic entries).

    Returns
    -------
    BorderingInverse
        The inverse, the determinant, the leading minors and the row order used.

    Raises
    ------
    ModelError
        If ``a`` is singular (no row gives a non-zero bordering pivot).

    See Also
    --------
    block_inverse, block_determinant

    Examples
    --------
    >>> import sympy as sp
    >>> r = bordering_inverse(sp.Matrix([[0, 1], [2, 3]]))   # zero leading entry: rows swapped
    >>> r.inverse, r.determinant, r.row_order
    (Matrix([
    [-3/2, 1/2],
    [   1,   0]]), -2, (1, 0))
    """
    a = as_square_matrix(a)
    n = a.rows
    work = a.copy()
    order = list(range(n))
    inv = sp.zeros(0, 0)
    minor: sp.Expr = sp.Integer(1)  # det of the leading block of b = u a
    sign = 1  # det u
    minors = []
    for k in range(n):
        b = work[:k, k]
        for r in range(k, n):
            c, d = work[r, :k], work[r, k]
            beta = sp.simplify(d - (c * inv * b)[0, 0]) if k else sp.simplify(d)
            if beta != 0:
                break
        else:
            raise ModelError("the matrix is singular: no row gives a non-zero bordering pivot (det a = 0)")
        if r != k:
            work.row_swap(k, r)
            order[k], order[r] = order[r], order[k]
            sign = -sign
        c = work[k, :k]
        if k == 0:
            inv = sp.Matrix([[1 / beta]])
        else:
            u = inv * b / beta
            w = c * inv / beta
            inv = sp.Matrix(sp.BlockMatrix([[inv + u * c * inv, -u], [-w, sp.Matrix([[1 / beta]])]]).as_explicit())
            inv = inv.applyfunc(sp.simplify)
        minor = sp.simplify(minor * beta)
        minors.append(minor)
    # a^-1 = b^-1 u, with u the row permutation: b = u a, so the columns of b^-1 are permuted back
    u = sp.zeros(n, n)
    for i, r in enumerate(order):
        u[i, r] = 1
    return BorderingInverse(
        inverse=(inv * u).applyfunc(sp.simplify),
        determinant=sp.simplify(sign * minor),
        leading_minors=tuple(minors),
        row_order=tuple(order),
    )


@validated
def cyclic_block_determinant(g: Sequence[Any], d: Sequence[Any]) -> sp.Expr:
    """Determinant of the cyclic block matrix of Bulgakov §1.7 Ex. 2, eq. (1.79).

    ``a = [[g1, 0, ..., 0, d1], [-d2, g2, 0, ...], [0, -d3, g3, ...], ..., [0, ..., -dn, gn]]`` with square blocks
    ``g_k`` (``g2..gn`` invertible)::

        det a = det gn ... det g2 * det(g1 + d1 gn^-1 dn g(n-1)^-1 d(n-1) ... g2^-1 d2)

    Parameters
    ----------
    g : sequence of Matrix
        The n >= 2 square diagonal blocks ``[g1, ..., gn]`` (a list or tuple); ``g2, ..., gn`` must be invertible.
    d : sequence of Matrix
        The n off-diagonal blocks ``[d1, ..., dn]`` (same length as ``g``): ``d1`` in the top-right corner, ``dk``
        (k >= 2) below ``g(k-1)`` with a minus sign.

    Returns
    -------
    Expr
        ``det a``, simplified.

    See Also
    --------
    block_determinant

    Examples
    --------
    >>> import sympy as sp
    >>> cyclic_block_determinant([sp.Matrix([[1]]), sp.Matrix([[2]])], [sp.Matrix([[3]]), sp.Matrix([[4]])])
    14
    """
    if not isinstance(g, Sequence) or not isinstance(d, Sequence):
        raise ParameterError(f"g and d must be sequences of matrices, got {type(g).__name__} and {type(d).__name__}")
    if len(g) != len(d) or len(g) < 2:
        raise ParameterError(f"g and d must have the same length >= 2, got {len(g)} and {len(d)}")
    gs = [as_square_matrix(x, f"g{k + 1}") for k, x in enumerate(g)]
    ds = [sp.Matrix(x) for x in d]
    chain = ds[0]
    for k in range(len(gs) - 1, 0, -1):
        chain = chain * _inv(gs[k], f"g{k + 1}") * ds[k]
    out = (gs[0] + chain).det()
    for gk in gs[1:]:
        out *= gk.det()
    return sp.simplify(out)


def _equal_diagonal(c: Any) -> tuple[sp.Matrix, sp.Expr, sp.Matrix]:
    c = as_square_matrix(c, "c")
    n = c.rows
    if any(not _is_zero(c[i, j]) for i in range(n) for j in range(i)):
        raise ModelError("c must be upper triangular")
    a = c[0, 0]
    if any(not _is_zero(c[i, i] - a) for i in range(n)):
        raise ModelError("c must have equal diagonal entries (c = a E + gamma with gamma strictly upper)")
    return c, a, c - a * sp.eye(n)


@validated
def triangular_inverse_series(c: Any) -> sp.Matrix:
    """``c^-1 = E/a - gamma/a^2 + gamma^2/a^3 - … + (-1)^(n-1) gamma^(n-1)/a^n`` (Bulgakov (1.73), §1.6 Ex. 4).

    ``c = a E + gamma`` upper triangular with equal diagonal ``a != 0``; ``gamma^n = 0`` ends the series.

    Parameters
    ----------
    c : Matrix, nested list or ndarray
        Square upper triangular matrix whose diagonal entries all equal the same non-zero ``a``.

    See Also
    --------
    triangular_adjugate_series

    Examples
    --------
    >>> import sympy as sp
    >>> triangular_inverse_series(sp.Matrix([[1, 2, 3], [0, 1, 4], [0, 0, 1]]))
    Matrix([
    [1, -2,  5],
    [0,  1, -4],
    [0,  0,  1]])
    """
    c, a, gamma = _equal_diagonal(c)
    if _is_zero(a):
        raise ModelError("c is singular (a = 0): use triangular_adjugate_series, which holds for a = 0 (1.74)")
    n = c.rows
    out, power = sp.zeros(n, n), sp.eye(n)
    for k in range(n):
        out += (-1) ** k * power / a ** (k + 1)
        power = power * gamma
    return out.applyfunc(sp.simplify)


@validated
def triangular_adjugate_series(c: Any) -> sp.Matrix:
    """``adj c = E a^(n-1) - a^(n-2) gamma + … + (-1)^(n-1) gamma^(n-1)`` (Bulgakov (1.74)), valid also for a = 0.

    Parameters
    ----------
    c : Matrix, nested list or ndarray
        Square upper triangular matrix whose diagonal entries all equal the same ``a`` (zero allowed).

    See Also
    --------
    triangular_inverse_series

    Examples
    --------
    >>> import sympy as sp
    >>> triangular_adjugate_series(sp.Matrix([[0, 1, 0], [0, 0, 1], [0, 0, 0]]))   # a = 0: adj = gamma^2
    Matrix([
    [0, 0, 1],
    [0, 0, 0],
    [0, 0, 0]])
    """
    c, a, gamma = _equal_diagonal(c)
    n = c.rows
    out, power = sp.zeros(n, n), sp.eye(n)
    for k in range(n):
        out += (-1) ** k * a ** (n - 1 - k) * power
        power = power * gamma
    return out.applyfunc(sp.expand)
