"""Functions of a matrix (Bulgakov 1954, §1.15, §1.28–1.38).

Sylvester's formula (confluent, cluster-aware for floats), Lagrange–Sylvester interpolation and the spectral mapping
theorem, the spectral decomposition into projectors and nilpotents, power series with a matrix argument and with
matrix coefficients, Cayley's real form, analytic continuation through expansions about scalar matrices, and the
matrizant of ``X' = A(t) X``.
"""

from __future__ import annotations

from .cayley import cayley_real_form, real_matrix_function
from .continuation import AnalyticContinuation, analytic_continuation
from .interpolation import function_elementary_divisors, interpolation_basis, interpolation_polynomial
from .matrix_coefficient_series import matrix_coefficient_function
from .matrix_functions import MatrixFunction, matrix_function, series_converges
from .matrizant import Matrizant, matrizant, matrizant_numeric
from .matrizant_product import MatrizantProduct, matrizant_product
from .power_series import matrix_power_series
from .spectral import SpectralComponent, SpectralDecomposition, spectral_decomposition

__all__ = [
    "AnalyticContinuation",
    "MatrixFunction",
    "Matrizant",
    "MatrizantProduct",
    "SpectralComponent",
    "SpectralDecomposition",
    "analytic_continuation",
    "cayley_real_form",
    "function_elementary_divisors",
    "interpolation_basis",
    "interpolation_polynomial",
    "matrix_coefficient_function",
    "matrix_function",
    "matrix_power_series",
    "matrizant",
    "matrizant_numeric",
    "matrizant_product",
    "real_matrix_function",
    "series_converges",
    "spectral_decomposition",
]
