"""Polynomial matrices, characteristic polynomials and canonical forms (Bulgakov 1954, §1.16–1.27).

Characteristic polynomials by the classical methods, derivatives of the adjugate, λ-matrices (divisors, Smith form,
division, minimal polynomial), strict equivalence and the Weierstrass form of regular pencils, modal matrices and
Luzin's triangular form, and block matrices.
"""

from __future__ import annotations

from .adjugate import adjugate_derivative_at_root, adjugate_derivatives
from .block import (
    BorderingInverse,
    block_determinant,
    block_inverse,
    bordering_inverse,
    cyclic_block_determinant,
    triangular_adjugate_series,
    triangular_inverse_series,
)
from .charpoly import adjugate_poly, charpoly, danilevsky, krylov, leverrier
from .modal import ModalMatrix, TriangularForm, luzin_form, modal_matrix, pencil_modal_matrix
from .pencils import PencilCanonicalForm, PencilEquivalence, pencil_canonical_form, pencil_equivalence
from .polynomial_matrices import (
    PencilDivisors,
    SmithForm,
    determinantal_divisors,
    elementary_divisors,
    invariant_factors,
    minimal_polynomial,
    pencil_divisors,
    polymatrix_divmod,
    smith_form,
)

__all__ = [
    "BorderingInverse",
    "ModalMatrix",
    "PencilCanonicalForm",
    "PencilDivisors",
    "PencilEquivalence",
    "SmithForm",
    "TriangularForm",
    "adjugate_derivative_at_root",
    "adjugate_derivatives",
    "adjugate_poly",
    "block_determinant",
    "block_inverse",
    "bordering_inverse",
    "charpoly",
    "cyclic_block_determinant",
    "danilevsky",
    "determinantal_divisors",
    "elementary_divisors",
    "invariant_factors",
    "krylov",
    "leverrier",
    "luzin_form",
    "minimal_polynomial",
    "modal_matrix",
    "pencil_canonical_form",
    "pencil_divisors",
    "pencil_equivalence",
    "pencil_modal_matrix",
    "polymatrix_divmod",
    "smith_form",
    "triangular_adjugate_series",
    "triangular_inverse_series",
]
