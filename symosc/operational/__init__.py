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
from .integral_square import cross_integral, integral_square, pairwise_root_sum_product
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
from .transform import NumericInversion, carson, inverse_carson, invert_numeric, to_transfer_function

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
    "indefinite_sum",
    "initial_value",
    "integral_square",
    "integral_to_infinity",
    "integrate_original",
    "integrate_parameter",
    "inverse_carson",
    "inverse_step_image",
    "invert_numeric",
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
    "to_transfer_function",
]


def _deprecated_hurwitz_matrix(denominator, p):
    import sympy as sp

    from .integral_square import _hurwitz_rows

    return _hurwitz_rows(sp.Poly(denominator, p))


def _deprecated_is_hurwitz(denominator, p):
    import sympy as sp

    from .integral_square import _hurwitz_verdict

    return _hurwitz_verdict(sp.Poly(denominator, p))


# one name per concept: the Hurwitz test lives in symosc.linear
_DEPRECATED = {
    "hurwitz_matrix": (
        _deprecated_hurwitz_matrix,
        "symosc.linear.hurwitz_matrix(sympy.Poly(denominator, p)) (rows as in Bulgakov (1954), eq. (8.117); "
        "this old function returned the transpose)",
    ),
    "is_hurwitz": (_deprecated_is_hurwitz, "symosc.linear.hurwitz(sympy.Poly(denominator, p)).stable"),
}


def __getattr__(name):
    if name in _DEPRECATED:
        from .._deprecation import warn_deprecated

        func, new = _DEPRECATED[name]
        warn_deprecated(f"symosc.operational.{name}", new)
        return func
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
