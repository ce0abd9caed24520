"""Second-order systems of one degree of freedom, also with delay (Bulgakov 1954, ch. 4).

Free and forced response of ``(k0 D² + k1 D + k2) y = x(t)``, the canonical form and phase portrait, regulator
parameters chosen by a stability coefficient, and the stability lines and response series of systems with delay.
"""

from __future__ import annotations

from .delay_lines import DelayStabilityLines, delay_equal_stability_lines
from .delay_response import DelayResponseSeries, delay_response_series
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
from .regulator import EqualStabilityLines, RegulatorOptimum, equal_stability_lines, optimize_regulator

__all__ = [
    "DelayResponseSeries",
    "DelayStabilityLines",
    "EqualStabilityLines",
    "LinearFilter",
    "PhasePortrait",
    "RegulatorOptimum",
    "StabilityCoefficients",
    "classify_equilibrium",
    "delay_equal_stability_lines",
    "delay_response_series",
    "equal_stability_lines",
    "linear_filter",
    "optimize_regulator",
    "periodic_forced_response",
    "phase_portrait",
    "stability_coefficients",
    "volterra_march",
]
