"""Harmonic linearization and relay systems (Bulgakov 1954, §5.14, §5.26–5.27, §12.7–12.13).

Describing-function analysis of systems with one or two nonlinear elements, linearization at a design amplitude,
the relay position regulator and the relay servo with backlash.
"""

from __future__ import annotations

from .backlash_servo import BacklashServoRun, simulate_backlash_servo
from .design_linearization import DesignLinearization, design_amplitude_linearization
from .harmonic_linearization import (
    HarmonicCycle,
    HarmonicLinearization,
    LinearizationBoundary,
    TwoNonlinearityCycle,
    harmonic_linearization,
    linearization_boundary,
    neimark_curve,
    self_oscillations,
    servo_characteristic,
    servo_equations,
    servo_region,
    two_nonlinearity_cycles,
)
from .relay_regulator import (
    RelayCycle,
    RelayRegulatorBoundary,
    RelayRegulatorRegion,
    relay_regulator_boundary,
    relay_regulator_cycles,
    relay_regulator_region,
)

__all__ = [
    "BacklashServoRun",
    "DesignLinearization",
    "HarmonicCycle",
    "HarmonicLinearization",
    "LinearizationBoundary",
    "RelayCycle",
    "RelayRegulatorBoundary",
    "RelayRegulatorRegion",
    "TwoNonlinearityCycle",
    "design_amplitude_linearization",
    "harmonic_linearization",
    "linearization_boundary",
    "neimark_curve",
    "relay_regulator_boundary",
    "relay_regulator_cycles",
    "relay_regulator_region",
    "self_oscillations",
    "servo_characteristic",
    "servo_equations",
    "servo_region",
    "simulate_backlash_servo",
    "two_nonlinearity_cycles",
]
