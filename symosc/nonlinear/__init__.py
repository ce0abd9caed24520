"""Nonlinear oscillations: Poincaré and Lindstedt series, averaging, harmonic linearization, special systems, delay.

The methods are grouped by family, one subpackage each:

========================  ==================================================================================
:mod:`.series`            Poincaré and Lindstedt series to any order, n degrees of freedom, operator systems,
                          forced solutions, and their numerical validation
:mod:`.averaging`         Krylov–Bogoliubov averaging, resonance curves, several frequencies, normal forms,
                          vibrational averaging (high-frequency forcing)
:mod:`.harmonic`          harmonic linearization (describing functions), relay regulators, backlash
:mod:`.special`           conservative systems, dry friction and point maps, clocks, flywheels, gyro pendulum
:mod:`.delay`             characteristic quasi-polynomials of retarded systems and their roots
========================  ==================================================================================

Every public name is available here (``symosc.nonlinear.limit_cycle``).  A family is imported on first use of one
of its names (``import symosc.nonlinear`` itself loads none of them), so a program that needs only the series does
not pay for averaging, delay equations or harmonic linearization.
"""

from __future__ import annotations

import importlib as _importlib
from typing import Any as _Any

from .._deprecation import moved_modules as _moved_modules
from .._deprecation import warn_deprecated as _warn_deprecated

#: family subpackage -> the public names it provides (imported together on first access to any of them)
_FAMILY_NAMES = {
    "averaging": (
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
    ),
    "series": (
        "CharacteristicExponentSeries",
        "EpsSeries",
        "ForcedPeriodicSolution",
        "LimitCycleSeries",
        "LindstedtSeries",
        "NDofPeriodicSolution",
        "NonResonantForcedSolution",
        "NumericCycle",
        "OperatorCycle",
        "PoincareOperatorSystem",
        "RadiusEstimate",
        "SecondApproximation",
        "SeriesValidation",
        "forced_periodic_solution",
        "limit_cycle",
        "lindstedt",
        "nonresonant_forced_solution",
        "numeric_limit_cycle",
        "numeric_orbit",
        "numeric_period",
        "periodic_solution_ndof",
        "poincare_operator_system",
        "poincare_second_approximation",
        "validate_limit_cycle",
        "validate_lindstedt",
    ),
    "harmonic": (
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
    ),
    "special": (
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
    ),
    "delay": (
        "DelayRoots",
        "QuasiPolynomial",
        "andronov_maier_optimum",
        "callender_hartree_porter_optimum",
        "characteristic_quasipolynomial",
        "count_roots",
        "quasi_polynomial",
        "quasi_polynomial_roots",
    ),
}

#: every public name, from the table above (one list to keep)
__all__ = sorted(name for names in _FAMILY_NAMES.values() for name in names)

_FAMILY_OF = {name: family for family, names in _FAMILY_NAMES.items() for name in names}

#: deprecated spellings (old name -> new name)
_DEPRECATED_NAMES = {
    "harmonic_linearisation": "harmonic_linearization",
    "HarmonicLinearisation": "HarmonicLinearization",
    "LinearisationBoundary": "LinearizationBoundary",
    "linearisation_boundary": "linearization_boundary",
}

#: module paths before the split into families (old -> new, relative to this package): deprecated, kept so that
#: code and pickles written against them still load
_MOVED_MODULES = {
    "_averaging_numeric": "averaging._numeric",
    "_fourier": "series._arith.trig",
    "_fourier_products": "series._arith.products",
    "_ndof_exponents": "series._ndof_exponents",
    "_normal_form_support": "averaging._normal_form_support",
    "_poincare_core": "series._poincare_core",
    "_relay_cycles": "harmonic._relay_cycles",
    "_series": "series._series",
    "_trig": "averaging._trig",
    "averaging_ndof": "averaging.multi_frequency",
    "averaging_normal_form": "averaging.normal_form",
    "backlash_servo": "harmonic.backlash_servo",
    "conservative": "special.conservative",
    "design_linearization": "harmonic.design_linearization",
    "flywheel_series": "special.flywheel_series",
    "forced_nonresonant": "series.forced_nonresonant",
    "forced_poincare": "series.forced_poincare",
    "gyro_pendulum": "special.gyro_pendulum",
    "harmonic_linearisation": "harmonic.harmonic_linearization",
    "harmonic_linearization": "harmonic.harmonic_linearization",
    "high_frequency": "averaging.high_frequency",
    "implicit_point_map": "special.implicit_point_map",
    "lindstedt": "series.lindstedt",
    "piecewise": "special.piecewise",
    "poincare": "series.poincare",
    "poincare_fd": "series.poincare_fd",
    "poincare_ndof": "series.poincare_ndof",
    "poincare_second": "series.poincare_second",
    "point_map": "special.point_map",
    "relay_regulator": "harmonic.relay_regulator",
    "special_systems": "special.special_systems",
    "validate": "series.validate",
}
_moved_modules(__name__, _MOVED_MODULES)


def __getattr__(name: str) -> _Any:
    family = _FAMILY_OF.get(name)
    if family is not None:
        value = getattr(_importlib.import_module(f"{__name__}.{family}"), name)
        globals()[name] = value
        return value
    if name in _DEPRECATED_NAMES:
        new = _DEPRECATED_NAMES[name]
        _warn_deprecated(f"{__name__}.{name}", f"{__name__}.{new}")
        return __getattr__(new) if new not in globals() else globals()[new]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
