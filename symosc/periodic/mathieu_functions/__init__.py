"""Mathieu functions (DLMF ch. 28): ce_n, se_n and derivatives, modified (radial) functions, Floquet exponent and
solutions.  One module per family: :mod:`.angular` (periodic functions, Fourier coefficients, exact q-series),
:mod:`.modified` (Mc, Ms by Bessel-product series), :mod:`.floquet` (nu(a, q), me_nu, fundamental solutions)."""

from .angular import (
    MathieuCoefficients,
    MathieuFunctionValues,
    mathieu_ce,
    mathieu_ce_prime,
    mathieu_coefficient_series,
    mathieu_fourier_coefficients,
    mathieu_function,
    mathieu_function_series,
    mathieu_se,
    mathieu_se_prime,
)
from .floquet import (
    FundamentalSolutions,
    MathieuExponent,
    mathieu_exponent,
    mathieu_floquet_exponent,
    mathieu_fundamental,
    mathieu_lambda,
    mathieu_me,
)
from .modified import (
    ModifiedMathieuValues,
    mathieu_mc,
    mathieu_mc_prime,
    mathieu_modified,
    mathieu_ms,
    mathieu_ms_prime,
)

__all__ = [
    "FundamentalSolutions",
    "MathieuCoefficients",
    "MathieuExponent",
    "MathieuFunctionValues",
    "ModifiedMathieuValues",
    "mathieu_ce",
    "mathieu_ce_prime",
    "mathieu_coefficient_series",
    "mathieu_exponent",
    "mathieu_floquet_exponent",
    "mathieu_fourier_coefficients",
    "mathieu_function",
    "mathieu_function_series",
    "mathieu_fundamental",
    "mathieu_lambda",
    "mathieu_mc",
    "mathieu_mc_prime",
    "mathieu_me",
    "mathieu_modified",
    "mathieu_ms",
    "mathieu_ms_prime",
    "mathieu_se",
    "mathieu_se_prime",
]
