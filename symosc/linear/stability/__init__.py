"""Stability criteria of linear systems with constant coefficients (Bulgakov 1954, §8.16–8.27, §10.1–10.9).

The fraction-free Routh array, the Hurwitz and Liénard–Chipart criteria, Routh's criteria from quadratic forms, the
degree of stability, stability regions in parameter space, D-partition and discriminant curves, the equal degree of
stability of the third-order servo, the loop algebra of regulated systems and the Nyquist criterion.
"""

from __future__ import annotations

from .criteria import StabilityVerdict, hurwitz, hurwitz_matrix, lienard_chipart
from .degree import (
    CubicOptimum,
    StabilityDegree,
    hurwitz_at_degree,
    max_stability_degree_cubic,
    shifted_coefficients,
    stability_degree,
)
from .dpartition import DiscriminantCurve, DPartition, d_partition, discriminant_curve, vyshnegradsky_diagram
from .loops import chain_transmittance, closed_loop_characteristic, return_difference
from .nyquist import NyquistResult, StabilityMargins, nyquist, stability_margins
from .quadratic_forms import QuadraticFormVerdict, routh_form_criteria
from .regions import StabilityRegion, robust_boundary, stability_region
from .routh import RouthArray, routh_array
from .servo import ServoOptimum, ServoStabilityLines, servo_optimum, servo_stability_lines

__all__ = [
    "CubicOptimum",
    "DPartition",
    "DiscriminantCurve",
    "NyquistResult",
    "QuadraticFormVerdict",
    "RouthArray",
    "ServoOptimum",
    "ServoStabilityLines",
    "StabilityDegree",
    "StabilityMargins",
    "StabilityRegion",
    "StabilityVerdict",
    "chain_transmittance",
    "closed_loop_characteristic",
    "d_partition",
    "discriminant_curve",
    "hurwitz",
    "hurwitz_at_degree",
    "hurwitz_matrix",
    "lienard_chipart",
    "max_stability_degree_cubic",
    "nyquist",
    "return_difference",
    "robust_boundary",
    "routh_array",
    "routh_form_criteria",
    "servo_optimum",
    "servo_stability_lines",
    "shifted_coefficients",
    "stability_degree",
    "stability_margins",
    "stability_region",
    "vyshnegradsky_diagram",
]
