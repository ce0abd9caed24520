"""Right and left polynomials and power series with matrix coefficients (Bulgakov §1.15, §1.30).

A right polynomial (or series) ``φ(z) = Σ a_k z^k`` has the matrix coefficients ``a_k`` to the left of the powers
of the square matrix ``z``; a left one ``ψ(z) = Σ z^k a_k`` to the right (1.125)–(1.128).  Replacing ``z`` by the
scalar ``λ`` gives a λ-matrix ``φ(λ)``, and Sylvester's formula puts its values on the matching side of the
principal idempotents and nilpotents of ``z`` (1.279), (1.280), (1.287), (1.288):

    right:  φ(z) = Σ_σ Σ_(p<e_σ) φ^(p)(λ_σ)/p! · η_σ^p,        left:  ψ(z) = Σ_σ Σ_(p<e_σ) η_σ^p · ψ^(p)(λ_σ)/p!

with ``η_σ^0 = ε_σ``.  The series converges iff every eigenvalue of ``z`` lies in the disk of convergence of
``φ(λ)`` (§1.30).
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import as_square_matrix, has_singular_value, is_float_matrix
from .spectral import spectral_decomposition

__all__ = ["matrix_coefficient_function"]


@validated
def matrix_coefficient_function(phi: Any, lam: sp.Symbol, z: Any, *, side: str = "right") -> sp.Matrix:
    """Value at a square matrix ``z`` of a λ-matrix ``φ(λ) = Σ a_k λ^k`` read as a right or left matrix series.

    Bulgakov (1954), §1.30, eqs. (1.279)–(1.280) (simple roots) and (1.287)–(1.288) (confluent case):
    ``side="right"`` gives ``Σ a_k z^k``, ``side="left"`` gives ``Σ z^k a_k``, both by Sylvester's formula with
    the matrix coefficients kept on their side of the idempotents.

    Parameters
    ----------
    phi : Matrix
        Matrix (any shape compatible with ``z``: ``m×n`` for the right series, ``n×m`` for the left one) whose
        entries are polynomials or analytic functions of ``lam`` — a polynomial ``a_0 + a_1 λ + ...`` or the closed
        form of a power series, e.g. ``B*exp(lam)``.
    lam : Symbol
        The scalar variable of ``phi``.
    z : Matrix
        Square matrix with exact (or symbolic) entries.
    side : {"right", "left"}
        Right series ``Σ a_k z^k`` or left series ``Σ z^k a_k``.

    Returns
    -------
    Matrix

    Raises
    ------
    ModelError
        A derivative of ``φ`` needed at an eigenvalue is infinite (φ not analytic there), or shapes do not match.
    ParameterError
        Floating-point ``z`` (use exact entries), a bad ``side`` or ``lam``.

    See Also
    --------
    matrix_function, spectral_decomposition, matrix_power_series

    Examples
    --------
    ``φ(λ) = a_0 + a_1 λ`` with non-commuting coefficients, at a Jordan block:

    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> a0, a1 = sp.Matrix([[1, 2], [0, 1]]), sp.Matrix([[0, 1], [1, 0]])
    >>> z = sp.Matrix([[3, 1], [0, 3]])
    >>> matrix_coefficient_function(a0 + a1 * l, l, z) == a0 + a1 * z
    True
    >>> matrix_coefficient_function(a0 + a1 * l, l, z, side="left") == a0 + z * a1
    True
    """
    if not isinstance(lam, sp.Symbol):
        raise ParameterError(f"lam must be a SymPy Symbol, got {lam!r}")
    if side not in ("right", "left"):
        raise ParameterError(f"side must be 'right' or 'left', got {side!r}")
    try:
        Phi = sp.Matrix(phi)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"phi must be a SymPy Matrix of expressions in {lam}, got {type(phi).__name__}") from exc
    Z = as_square_matrix(z, "z")
    if is_float_matrix(Z):
        raise ParameterError(
            "z has floating-point entries; pass exact entries (sympy.nsimplify) — the Jordan structure that the "
            "confluent formula (1.287) needs is not defined in floating point"
        )
    n = Z.rows
    if (side == "right" and Phi.cols != n) or (side == "left" and Phi.rows != n):
        dim = "columns" if side == "right" else "rows"
        raise ModelError(f"a {side} series needs phi with {n} {dim} to multiply the {n}x{n} z, got {Phi.shape}")
    decomp = spectral_decomposition(Z)
    out = sp.zeros(*Phi.shape)
    for comp in decomp.components:
        mats = (comp.projector, *comp.nilpotents)
        deriv = Phi
        for p, eta in enumerate(mats[: comp.index]):
            if p:
                deriv = deriv.diff(lam)
            coeff = deriv.subs(lam, comp.root) / sp.factorial(p)
            bad = [e for e in coeff if has_singular_value(e)]
            if bad:
                raise ModelError(
                    f"phi is not analytic at the eigenvalue {comp.root}: its derivative of order {p} there is "
                    f"{bad[0]} (Bulgakov (1954), §1.30)"
                )
            out += coeff * eta if side == "right" else eta * coeff
    # roots of irreducible factors of degree >= 3 stay as CRootOf (simplifying them costs more than it gains)
    return out.applyfunc(lambda e: sp.expand(e) if e.has(sp.CRootOf) else sp.simplify(e))
