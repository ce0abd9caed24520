"""Linear systems (Bulgakov, "Oscillations" (1954), ch. 4, 8, 9 A and 10).

* Stability criteria — :func:`routh_array` (fraction-free), :func:`hurwitz`, :func:`lienard_chipart`.
"""

from .criteria import StabilityVerdict, hurwitz, hurwitz_matrix, lienard_chipart
from .degree import StabilityDegree, hurwitz_at_degree, shifted_coefficients, stability_degree
from .quadratic_forms import QuadraticFormVerdict, routh_form_criteria
from .routh import RouthArray, routh_array

__all__ = [
    "QuadraticFormVerdict",
    "RouthArray",
    "StabilityDegree",
    "StabilityVerdict",
    "hurwitz",
    "hurwitz_at_degree",
    "hurwitz_matrix",
    "lienard_chipart",
    "routh_array",
    "routh_form_criteria",
    "shifted_coefficients",
    "stability_degree",
]
