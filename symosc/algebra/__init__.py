"""Matrix calculus (Bulgakov, "Oscillations", ch. 1).

* :func:`matrix_function` — f(A) by Sylvester's formula, confluent form for multiple roots, accurate divided
  differences for clusters of nearly equal floating-point roots; :func:`spectral_decomposition` gives the roots,
  principal idempotents and nilpotents.
* Polynomial matrices — :func:`determinantal_divisors`, :func:`invariant_factors`, :func:`elementary_divisors`,
  :func:`smith_form`, :func:`minimal_polynomial`, :func:`polymatrix_divmod`, :func:`pencil_divisors`.
* Characteristic polynomials — :func:`leverrier`, :func:`krylov`, :func:`danilevsky`, :func:`adjugate_poly`.
* The matrizant (Peano–Baker series) — :func:`matrizant`, :func:`matrizant_numeric`, and over long intervals
  :func:`matrizant_product` (a product of short series, checked against Liouville's formula).
* Block matrices (§1.5–1.7) — :func:`block_inverse`, :func:`block_determinant`, :func:`bordering_inverse`,
  :func:`cyclic_block_determinant`, :func:`triangular_inverse_series`, :func:`triangular_adjugate_series`.
* Modal matrices from the adjugate — :func:`modal_matrix`, :func:`pencil_modal_matrix`; Luzin's triangular form
  :func:`luzin_form`.
* Adjugate derivatives (§1.27) — :func:`adjugate_derivatives`, :func:`adjugate_derivative_at_root`.
* Cayley's real form (§1.16, §1.28) — :func:`cayley_real_form`, :func:`real_matrix_function`.
* Matrix-argument power series (§1.28, §1.30) — :func:`matrix_power_series`.
* Right/left series with matrix coefficients (§1.30, (1.279)–(1.288)) — :func:`matrix_coefficient_function`.
* Analytic continuation through expansions about scalar matrices (§1.31) — :func:`analytic_continuation`.
* Linear pencils (§1.24) — :func:`pencil_equivalence` (strict equivalence with exact u, v) and
  :func:`pencil_canonical_form` (Weierstrass/Jordan or Cayley real form).
"""

from .._deprecation import moved_modules as _moved_modules
from .canonical import (
    BorderingInverse,
    ModalMatrix,
    PencilCanonicalForm,
    PencilDivisors,
    PencilEquivalence,
    SmithForm,
    TriangularForm,
    adjugate_derivative_at_root,
    adjugate_derivatives,
    adjugate_poly,
    block_determinant,
    block_inverse,
    bordering_inverse,
    charpoly,
    cyclic_block_determinant,
    danilevsky,
    determinantal_divisors,
    elementary_divisors,
    invariant_factors,
    krylov,
    leverrier,
    luzin_form,
    minimal_polynomial,
    modal_matrix,
    pencil_canonical_form,
    pencil_divisors,
    pencil_equivalence,
    pencil_modal_matrix,
    polymatrix_divmod,
    smith_form,
    triangular_adjugate_series,
    triangular_inverse_series,
)
from .functions import (
    AnalyticContinuation,
    MatrixFunction,
    Matrizant,
    MatrizantProduct,
    SpectralComponent,
    SpectralDecomposition,
    analytic_continuation,
    cayley_real_form,
    function_elementary_divisors,
    interpolation_basis,
    interpolation_polynomial,
    matrix_coefficient_function,
    matrix_function,
    matrix_power_series,
    matrizant,
    matrizant_numeric,
    matrizant_product,
    real_matrix_function,
    series_converges,
    spectral_decomposition,
)
from .trig import trig_reduce, trig_reduce_groups

__all__ = [
    "AnalyticContinuation",
    "BorderingInverse",
    "MatrixFunction",
    "Matrizant",
    "MatrizantProduct",
    "ModalMatrix",
    "PencilCanonicalForm",
    "PencilDivisors",
    "PencilEquivalence",
    "SmithForm",
    "SpectralComponent",
    "SpectralDecomposition",
    "TriangularForm",
    "adjugate_derivative_at_root",
    "adjugate_derivatives",
    "adjugate_poly",
    "analytic_continuation",
    "block_determinant",
    "block_inverse",
    "bordering_inverse",
    "cayley_real_form",
    "charpoly",
    "cyclic_block_determinant",
    "danilevsky",
    "determinantal_divisors",
    "elementary_divisors",
    "function_elementary_divisors",
    "interpolation_basis",
    "interpolation_polynomial",
    "invariant_factors",
    "krylov",
    "leverrier",
    "luzin_form",
    "matrix_coefficient_function",
    "matrix_function",
    "matrix_power_series",
    "matrizant",
    "matrizant_numeric",
    "matrizant_product",
    "minimal_polynomial",
    "modal_matrix",
    "pencil_canonical_form",
    "pencil_divisors",
    "pencil_equivalence",
    "pencil_modal_matrix",
    "polymatrix_divmod",
    "real_matrix_function",
    "series_converges",
    "smith_form",
    "spectral_decomposition",
    "triangular_adjugate_series",
    "triangular_inverse_series",
    "trig_reduce",
    "trig_reduce_groups",
]

#: module paths before the split into families (old -> new): deprecated, kept so that code and pickles written
#: against them still load
_moved_modules(
    __name__,
    {
        "_schur_parlett": "functions._schur_parlett",
        "_taylor": "functions._taylor",
        "adjugate": "canonical.adjugate",
        "block": "canonical.block",
        "cayley": "functions.cayley",
        "charpoly": "canonical.charpoly",
        "continuation": "functions.continuation",
        "interpolation": "functions.interpolation",
        "matrix_coefficient_series": "functions.matrix_coefficient_series",
        "matrix_functions": "functions.matrix_functions",
        "matrizant": "functions.matrizant",
        "matrizant_product": "functions.matrizant_product",
        "modal": "canonical.modal",
        "pencils": "canonical.pencils",
        "polynomial_matrices": "canonical.polynomial_matrices",
        "power_series": "functions.power_series",
        "spectral": "functions.spectral",
    },
)
