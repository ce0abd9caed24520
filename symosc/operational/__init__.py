"""Carson (Heaviside) operational calculus, after Bulgakov ch. 2.

Images are **Carson** images ``X(p) = p * Laplace[x](p)`` unless a function says otherwise; originals are
functions of ``t > 0``.

>>> import sympy as sp
>>> from symosc.operational import carson, inverse_carson
>>> p, t = sp.symbols("p t")
>>> carson(sp.sin(t), t, p)
p/(p**2 + 1)
>>> inverse_carson(p / (p**2 + 1), p, t)
sin(t)
"""

from .difference import (
    DifferenceSolution,
    IndefiniteSum,
    indefinite_sum,
    inverse_step_image,
    solve_difference,
    step_image,
)
from .heaviside import first_expansion, heaviside_expand, residue_inverse
from .integral_square import cross_integral, hurwitz_matrix, integral_square, is_hurwitz, pairwise_root_sum_product
from .systems import OperationalSolution, solve_operational
from .table import CARSON_TABLE, TableEntry, carson_by_table, carson_matrix_exp, table_entry
from .theorems import (
    advance,
    convolution,
    delay,
    differentiate_image,
    differentiate_original,
    differentiate_parameter,
    duhamel,
    final_value,
    finite_difference,
    finite_sum,
    higher_difference,
    initial_value,
    integral_to_infinity,
    integrate_original,
    integrate_parameter,
    multiple_advance,
    product_of_originals,
    shift,
    similarity,
)
from .transform import NumericInversion, carson, inverse_carson, invert_numeric

__all__ = [
    "CARSON_TABLE",
    "DifferenceSolution",
    "IndefiniteSum",
    "NumericInversion",
    "OperationalSolution",
    "TableEntry",
    "advance",
    "carson",
    "carson_by_table",
    "carson_matrix_exp",
    "convolution",
    "cross_integral",
    "delay",
    "differentiate_image",
    "differentiate_original",
    "differentiate_parameter",
    "duhamel",
    "final_value",
    "finite_difference",
    "finite_sum",
    "first_expansion",
    "heaviside_expand",
    "higher_difference",
    "hurwitz_matrix",
    "indefinite_sum",
    "initial_value",
    "integral_square",
    "integral_to_infinity",
    "integrate_original",
    "integrate_parameter",
    "inverse_carson",
    "inverse_step_image",
    "invert_numeric",
    "is_hurwitz",
    "multiple_advance",
    "pairwise_root_sum_product",
    "product_of_originals",
    "residue_inverse",
    "shift",
    "similarity",
    "solve_difference",
    "solve_operational",
    "step_image",
    "table_entry",
]

# public functions refuse invalid arguments with ParameterError (symosc/_validate.py)
from .._validate import guard_public_api as _guard_public_api

_guard_public_api(__name__)
