"""Linear systems of several degrees of freedom (Bulgakov 1954, §8.2–8.12, §8.28, §8.52–8.54, ch. 9 A).

Systems ``f(D) y = e(D) x`` and their solution, normal coordinates of first-order systems, conservative systems
``A ÿ + H y = x(t)`` with their modes and eigenvalue bounds, loaded strings and shafts, and two coupled
oscillators.
"""

from __future__ import annotations

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
from .normal_form import NormalForm, modal_normal_form
from .strings import chain_matrices, influence_matrix, string_frequencies, string_modes
from .two_dof import TuningCurves, TwoDOFBeats, TwoDOFSystem, tuning_curves, two_dof_beats, two_dof_system

__all__ = [
    "Compatibility",
    "FrequencyBounds",
    "FrequencyResponse",
    "FundamentalSolutions",
    "ImpulseResponse",
    "ModalAnalysis",
    "NormalForm",
    "PowerIteration",
    "TuningCurves",
    "TwoDOFBeats",
    "TwoDOFSystem",
    "a_orthonormalize",
    "chain_matrices",
    "compatibility",
    "conservative_modes",
    "constrained_eigenvalues",
    "dunkerley",
    "dunkerley_bounds",
    "frequency_response",
    "fundamental_solutions",
    "impulse_response",
    "influence_matrix",
    "mean_power",
    "modal_normal_form",
    "power_iteration",
    "rayleigh_quotient",
    "resonant_particular",
    "string_frequencies",
    "string_modes",
    "tuning_curves",
    "two_dof_beats",
    "two_dof_system",
    "worst_case_gain",
]
