"""Cayley's real form of a real matrix with complex eigenvalues (Bulgakov §1.16, §1.28).

A complex number ``e + iω`` is represented by the real matrix ``[[e, ω], [-ω, e]]`` (1.139–1.140).  A real matrix
with simple (or semisimple) eigenvalues is similar, through a real matrix T, to the quasi-diagonal form
``Q = diag(κ, ..., [[e, ω], [-ω, e]], ...)`` (1.141, 1.147), and for a function with real Taylor coefficients
``Φ(Q)`` has the blocks ``[[Re Φ(e+iω), Im Φ(e+iω)], [-Im Φ(e+iω), Re Φ(e+iω)]]`` (1.248).
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import validated
from ...errors import ModelError
from .._util import as_scalar_function, as_square_matrix

__all__ = ["cayley_real_form", "real_matrix_function"]


def _blocks(A: sp.Matrix) -> list[tuple[sp.Expr, sp.Matrix | tuple[sp.Matrix, sp.Matrix]]]:
    if any(e.is_real is False for e in A) or any(e.is_real is None for e in A if e.is_number):
        raise ModelError("A must be a real matrix (Bulgakov §1.16 treats real matrices); got complex entries")
    out: list = []
    for root, mult, vecs in A.eigenvects(simplify=True):
        if len(vecs) != mult:
            raise ModelError(
                f"the eigenvalue {root} of A has a non-linear elementary divisor (multiplicity {mult}, "
                f"{len(vecs)} eigenvector(s)); the quasi-diagonal Cayley form (1.141) needs a semisimple matrix — "
                "use matrix_function for the confluent case"
            )
        im = sp.simplify(sp.im(root))
        if im == 0:
            out.extend((sp.simplify(sp.re(root)), v) for v in vecs)
        elif im.is_positive:
            for v in vecs:
                v = v.applyfunc(sp.expand_complex)
                x = v.applyfunc(lambda e: sp.simplify(sp.re(e)))
                y = v.applyfunc(lambda e: sp.simplify(sp.im(e)))
                out.append((root, (x, y)))
        elif im.is_negative:
            continue  # the conjugate partner is handled with the root of positive imaginary part
        else:
            raise ModelError(f"cannot decide the sign of Im({root}); give the symbols real=True/positive=True")
    return out


@validated
def cayley_real_form(A: Any) -> tuple[sp.Matrix, sp.Matrix]:
    """Real similarity ``A = T Q T⁻¹`` onto Cayley's quasi-diagonal form (Bulgakov (1954), §1.16, eq. (1.141), (1.147)).

    Parameters
    ----------
    A : Matrix
        Real square matrix, exact, with linear elementary divisors (a semisimple matrix).

    Returns
    -------
    (T, Q) : tuple of Matrix
        Real ``T`` (columns: real eigenvectors, and ``Re v``, ``Im v`` for an eigenvector ``v`` of
        ``e + iω``, ``ω > 0``) and ``Q`` quasi-diagonal with the real roots ``κ`` and the blocks
        ``[[e, ω], [-ω, e]]``.

    Raises
    ------
    ModelError
        A is complex or has a non-linear elementary divisor.

    See Also
    --------
    real_matrix_function, matrix_function, modal_matrix

    Examples
    --------
    >>> import sympy as sp
    >>> T, Q = cayley_real_form(sp.Matrix([[0, 1], [-5, -2]]))
    >>> Q
    Matrix([
    [-1,  2],
    [-2, -1]])
    >>> T * Q * T.inv()
    Matrix([
    [ 0,  1],
    [-5, -2]])
    """
    M = as_square_matrix(A)
    cols: list[sp.Matrix] = []
    diag: list[sp.Matrix] = []
    for root, v in _blocks(M):
        if isinstance(v, tuple):
            e, w = sp.simplify(sp.re(root)), sp.simplify(sp.im(root))
            cols.extend(v)
            diag.append(sp.Matrix([[e, w], [-w, e]]))
        else:
            cols.append(v)
            diag.append(sp.Matrix([[root]]))
    return sp.Matrix.hstack(*cols), sp.diag(*diag)


@validated
def real_matrix_function(A: Any, f: Any, *, var: sp.Symbol | None = None) -> sp.Matrix:
    """``Φ(A)`` for a real matrix in real form, by Cayley's blocks (Bulgakov (1954), §1.28, eq. (1.248)–(1.250)).

    ``Φ(A) = T Φ(Q) T⁻¹`` where ``Φ(Q)`` has ``Φ(κ)`` for a real root and
    ``[[Re Φ(e+iω), Im Φ(e+iω)], [-Im Φ(e+iω), Re Φ(e+iω)]]`` for a pair ``e ± iω``: no ``i`` appears in the
    result.  Φ must have real Taylor coefficients; declare its parameters real (``sympy.Symbol("t", real=True)``).

    Parameters
    ----------
    A : Matrix
        Real semisimple square matrix (see :func:`cayley_real_form`).
    f : Lambda, function class, callable or Expr
        Scalar function, as for :func:`matrix_function`.
    var : Symbol, optional
        The variable of f when f is an expression with several free symbols.

    Returns
    -------
    Matrix

    See Also
    --------
    cayley_real_form, matrix_function

    Examples
    --------
    Equation (1.250): ``exp(Q t)`` for ``Q = [[e, ω], [-ω, e]]``:

    >>> import sympy as sp
    >>> t = sp.Symbol("t", real=True)
    >>> x = sp.Symbol("x")
    >>> real_matrix_function(sp.Matrix([[-1, 2], [-2, -1]]), sp.exp(x * t), var=x)
    Matrix([
    [ exp(-t)*cos(2*t), exp(-t)*sin(2*t)],
    [-exp(-t)*sin(2*t), exp(-t)*cos(2*t)]])
    """
    M = as_square_matrix(A)
    expr, x = as_scalar_function(f, var)
    T, Q = cayley_real_form(M)
    blocks: list[sp.Matrix] = []
    i = 0
    while i < Q.rows:
        if i + 1 < Q.rows and Q[i, i + 1] != 0:
            val = sp.expand_complex(expr.subs(x, Q[i, i] + sp.I * Q[i, i + 1]))
            re, im = sp.simplify(sp.re(val)), sp.simplify(sp.im(val))
            blocks.append(sp.Matrix([[re, im], [-im, re]]))
            i += 2
        else:
            blocks.append(sp.Matrix([[expr.subs(x, Q[i, i])]]))
            i += 1
    return (T * sp.diag(*blocks) * T.inv()).applyfunc(sp.simplify)
