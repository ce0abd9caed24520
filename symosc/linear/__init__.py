"""Linear systems (Bulgakov, "Oscillations" (1954), ch. 4, 8, 9 A and 10).

* One degree of freedom — :func:`linear_filter`, :func:`stability_coefficients`, :func:`classify_equilibrium`,
  :func:`phase_portrait`, :func:`periodic_forced_response`, :func:`volterra_march`;
  :func:`optimize_regulator`, :func:`equal_stability_lines`; with delay
  :func:`delay_equal_stability_lines`, :func:`delay_response_series`.
* Systems f(D) y = e(D) x — :func:`compatibility`, :func:`fundamental_solutions`, :func:`impulse_response`,
  :func:`modal_normal_form`, :func:`frequency_response`, two degrees of freedom :func:`two_dof_system`,
  :func:`two_dof_beats`, :func:`tuning_curves`,
  :func:`resonant_particular`, :func:`mean_power`, :func:`worst_case_gain`.
* Stability criteria — :func:`routh_array` (fraction-free), :func:`hurwitz`, :func:`lienard_chipart`,
  :func:`routh_form_criteria`; degree of stability :func:`stability_degree`, :func:`hurwitz_at_degree`,
  :func:`max_stability_degree_cubic`,
  :func:`servo_stability_lines`, :func:`servo_optimum`.
* Conservative systems — :func:`conservative_modes`, :func:`a_orthonormalize`, :func:`chain_matrices`,
  :func:`string_frequencies`, :func:`influence_matrix`.
* Bounds — :func:`rayleigh_quotient`, :func:`constrained_eigenvalues`, :func:`dunkerley`, :func:`dunkerley_bounds`,
  :func:`power_iteration`.
* Regulated loops — :func:`chain_transmittance`, :func:`return_difference`, :func:`closed_loop_characteristic`,
  :func:`nyquist` (indentation, shifted axis, Feldbaum sector), :func:`stability_margins`.
* Regions — :func:`stability_region`, :func:`robust_boundary`; D-partition — :func:`d_partition`,
  :func:`discriminant_curve`, :func:`vyshnegradsky_diagram`.
"""

from .bounds import (
    FrequencyBounds,
    PowerIteration,
    constrained_eigenvalues,
    dunkerley,
    dunkerley_bounds,
    power_iteration,
    rayleigh_quotient,
)
from .conservative import ModalAnalysis, a_orthonormalize, conservative_modes
from .criteria import StabilityVerdict, hurwitz, hurwitz_matrix, lienard_chipart
from .degree import (
    CubicOptimum,
    StabilityDegree,
    hurwitz_at_degree,
    max_stability_degree_cubic,
    shifted_coefficients,
    stability_degree,
)
from .delay_lines import DelayStabilityLines, delay_equal_stability_lines
from .delay_response import DelayResponseSeries, delay_response_series
from .dpartition import DiscriminantCurve, DPartition, d_partition, discriminant_curve, vyshnegradsky_diagram
from .fd_systems import (
    Compatibility,
    FrequencyResponse,
    FundamentalSolutions,
    ImpulseResponse,
    compatibility,
    frequency_response,
    fundamental_solutions,
    impulse_response,
    mean_power,
    resonant_particular,
    worst_case_gain,
)
from .loops import chain_transmittance, closed_loop_characteristic, return_difference
from .normal_form import NormalForm, modal_normal_form
from .nyquist import NyquistResult, StabilityMargins, nyquist, stability_margins
from .one_dof import (
    LinearFilter,
    StabilityCoefficients,
    classify_equilibrium,
    linear_filter,
    periodic_forced_response,
    stability_coefficients,
    volterra_march,
)
from .phase_plane import PhasePortrait, phase_portrait
from .quadratic_forms import QuadraticFormVerdict, routh_form_criteria
from .regions import StabilityRegion, robust_boundary, stability_region
from .regulator import EqualStabilityLines, RegulatorOptimum, equal_stability_lines, optimize_regulator
from .routh import RouthArray, routh_array
from .servo import ServoOptimum, ServoStabilityLines, servo_optimum, servo_stability_lines
from .strings import chain_matrices, influence_matrix, string_frequencies, string_modes
from .two_dof import TuningCurves, TwoDOFBeats, TwoDOFSystem, tuning_curves, two_dof_beats, two_dof_system

__all__ = [
    "Compatibility",
    "CubicOptimum",
    "DPartition",
    "DelayResponseSeries",
    "DelayStabilityLines",
    "DiscriminantCurve",
    "EqualStabilityLines",
    "FrequencyBounds",
    "FrequencyResponse",
    "FundamentalSolutions",
    "ImpulseResponse",
    "LinearFilter",
    "ModalAnalysis",
    "NormalForm",
    "NyquistResult",
    "PhasePortrait",
    "PowerIteration",
    "QuadraticFormVerdict",
    "RegulatorOptimum",
    "RouthArray",
    "ServoOptimum",
    "ServoStabilityLines",
    "StabilityCoefficients",
    "StabilityDegree",
    "StabilityMargins",
    "StabilityRegion",
    "StabilityVerdict",
    "TuningCurves",
    "TwoDOFBeats",
    "TwoDOFSystem",
    "a_orthonormalize",
    "chain_matrices",
    "chain_transmittance",
    "classify_equilibrium",
    "closed_loop_characteristic",
    "compatibility",
    "conservative_modes",
    "constrained_eigenvalues",
    "d_partition",
    "delay_equal_stability_lines",
    "delay_response_series",
    "discriminant_curve",
    "dunkerley",
    "dunkerley_bounds",
    "equal_stability_lines",
    "frequency_response",
    "fundamental_solutions",
    "hurwitz",
    "hurwitz_at_degree",
    "hurwitz_matrix",
    "impulse_response",
    "influence_matrix",
    "lienard_chipart",
    "linear_filter",
    "max_stability_degree_cubic",
    "mean_power",
    "modal_normal_form",
    "nyquist",
    "optimize_regulator",
    "periodic_forced_response",
    "phase_portrait",
    "power_iteration",
    "rayleigh_quotient",
    "resonant_particular",
    "return_difference",
    "robust_boundary",
    "routh_array",
    "routh_form_criteria",
    "servo_optimum",
    "servo_stability_lines",
    "shifted_coefficients",
    "stability_coefficients",
    "stability_degree",
    "stability_margins",
    "stability_region",
    "string_frequencies",
    "string_modes",
    "tuning_curves",
    "two_dof_beats",
    "two_dof_system",
    "volterra_march",
    "vyshnegradsky_diagram",
    "worst_case_gain",
]

# public functions refuse invalid arguments with ParameterError (symosc/_validate.py)
from .._validate import guard_public_api as _guard_public_api

_guard_public_api(__name__)
