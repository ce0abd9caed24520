"""Special one-degree-of-freedom systems (Bulgakov 1954, ch. 5 A, C, §5.6–5.12, §5.24, §12.14).

Conservative systems (equilibria, libration and rotation periods), dry friction with exact piecewise solutions and
point maps, fixed points of explicit and implicit point maps, clocks, valve generators, flywheels and the
gyroscopic pendulum.
"""

from __future__ import annotations

from .conservative import Equilibrium, classify_equilibrium, libration_period, rotation_period
from .flywheel_series import FlywheelSpeedSeries, flywheel_speed_series
from .gyro_pendulum import GyroPendulumModes, gyro_pendulum_modes
from .implicit_point_map import ImplicitMapCycle, implicit_map_cycle
from .piecewise import (
    CoulombMotion,
    HalfSwingMap,
    coulomb_oscillator,
    half_swing_map,
    quadratic_drag_eta,
    quadratic_drag_eta_series,
    quadratic_drag_half_swing_times,
)
from .point_map import PointMapFixedPoint, point_map_fixed_point
from .special_systems import (
    ClockEscapement,
    FlywheelDesign,
    StepGenerator,
    backlash_critical_gap,
    clock_escapement,
    radinger_flywheel,
    step_valve_generator,
)

__all__ = [
    "ClockEscapement",
    "CoulombMotion",
    "Equilibrium",
    "FlywheelDesign",
    "FlywheelSpeedSeries",
    "GyroPendulumModes",
    "HalfSwingMap",
    "ImplicitMapCycle",
    "PointMapFixedPoint",
    "StepGenerator",
    "backlash_critical_gap",
    "classify_equilibrium",
    "clock_escapement",
    "coulomb_oscillator",
    "flywheel_speed_series",
    "gyro_pendulum_modes",
    "half_swing_map",
    "implicit_map_cycle",
    "libration_period",
    "point_map_fixed_point",
    "quadratic_drag_eta",
    "quadratic_drag_eta_series",
    "quadratic_drag_half_swing_times",
    "radinger_flywheel",
    "rotation_period",
    "step_valve_generator",
]
