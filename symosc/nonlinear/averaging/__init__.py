"""Averaging: Krylov–Bogoliubov / van der Pol shortened equations (Bulgakov 1954, ch. 5 E, ch. 6, §12.11–12.12).

One degree of freedom (:func:`averaged_equations`, stationary regimes, resonance curves), several frequencies
(:func:`averaged_equations_ndof`), normal coordinates of ``f(D) y = psi`` (:func:`averaging_normal_form`) and
vibrational averaging under high-frequency forcing (Kapitza's pendulum, :func:`vibrational_averaging`).
"""

from __future__ import annotations

from ._numeric import Fold, FrequencyResponse, SteadyState
from .high_frequency import (
    FastAveragedSystem,
    VibrationalAveraging,
    fast_averaged_system,
    vibrational_averaging,
    vibrational_averaging_of,
    vibrational_stiffness,
)
from .multi_frequency import (
    MultiAveragedEquations,
    averaged_equations_ndof,
    dry_friction_ratio,
    dry_friction_torus_average,
)
from .normal_form import AveragingNormalForm, QuasiPeriodicRegime, ShortenedEquations, averaging_normal_form
from .shortened import AveragedEquations, StationaryRegime, averaged_equations, describing_function

__all__ = [
    "AveragedEquations",
    "AveragingNormalForm",
    "FastAveragedSystem",
    "Fold",
    "FrequencyResponse",
    "MultiAveragedEquations",
    "QuasiPeriodicRegime",
    "ShortenedEquations",
    "StationaryRegime",
    "SteadyState",
    "VibrationalAveraging",
    "averaged_equations",
    "averaged_equations_ndof",
    "averaging_normal_form",
    "describing_function",
    "dry_friction_ratio",
    "dry_friction_torus_average",
    "fast_averaged_system",
    "vibrational_averaging",
    "vibrational_averaging_of",
    "vibrational_stiffness",
]
