"""Identification: modal models from sampled oscillations (Belyakov 2005) and their error studies.

Signal estimators share one interface, ``estimator(signals, dt, n_modes=None, *, n_poles=None, constant=True, ...)``
with ``signals`` of shape ``(samples,)`` or ``(channels, samples)``, and return a :class:`ModalEstimate`.
"""

from .._deprecation import module_getattr as _module_getattr
from .._deprecation import moved_modules as _moved_modules
from .classical import InertiaFormula, flywheel, physical_pendulum, rocking_platform
from .damping import DampingPerturbation, QuadraticModes, damping_perturbation, quadratic_modes  # noqa: F401
from .error_maps import ErrorMap, error_map
from .min_time import (
    ExcitationBound,
    MinTimeResult,
    QuasiOptimalRun,
    excitation_time,
    excitation_time_bound,
    min_time_1dof,
    quasi_optimal_control,
    simulate_quasi_optimal,
    sine_forcing_time,
    switching_curves,
)
from .reconstruction import (
    InertiaEstimate,
    InertiaTensor,
    assemble_tensor,
    central_identity,
    check_distinct,
    inertia_equal_springs,
    inertia_from_release,
    inertia_known_center,
    real_modes,
)
from .sensitivity import JacobianResult, jacobian, sensitivity
from .signals import (
    ApplicabilityCheck,
    CramerRaoBound,
    ErrorVsNoise,
    ModalEstimate,
    MonteCarloResult,
    SamplingAdvice,
    SecondOrderModel,
    add_noise,
    applicability,
    cramer_rao_bound,
    era,
    error_vs_noise,
    esprit,
    matrix_pencil,
    monte_carlo,
    noise_sigma,
    prony,
    realize,
    refine,
    sampling_advice,
    two_stage,
)
from .simulator import StandRecord, simulate_stand, stand_system
from .spin_up import CentralGyration, central_gyration, motor_spin_up_brake

__all__ = [
    "ApplicabilityCheck",
    "CentralGyration",
    "CramerRaoBound",
    "DampingPerturbation",
    "ErrorMap",
    "ErrorVsNoise",
    "ExcitationBound",
    "InertiaEstimate",
    "InertiaFormula",
    "InertiaTensor",
    "JacobianResult",
    "MinTimeResult",
    "ModalEstimate",
    "MonteCarloResult",
    "QuasiOptimalRun",
    "SamplingAdvice",
    "SecondOrderModel",
    "StandRecord",
    "add_noise",
    "applicability",
    "assemble_tensor",
    "central_gyration",
    "central_identity",
    "check_distinct",
    "cramer_rao_bound",
    "damping_perturbation",
    "era",
    "error_map",
    "error_vs_noise",
    "esprit",
    "excitation_time",
    "excitation_time_bound",
    "flywheel",
    "inertia_equal_springs",
    "inertia_from_release",
    "inertia_known_center",
    "jacobian",
    "matrix_pencil",
    "min_time_1dof",
    "monte_carlo",
    "motor_spin_up_brake",
    "noise_sigma",
    "physical_pendulum",
    "prony",
    "quasi_optimal_control",
    "real_modes",
    "realize",
    "refine",
    "rocking_platform",
    "sampling_advice",
    "sensitivity",
    "simulate_quasi_optimal",
    "simulate_stand",
    "sine_forcing_time",
    "stand_system",
    "switching_curves",
    "two_stage",
]

#: module paths before the split into families (old -> new): deprecated, kept so that code and pickles written
#: against them still load
_moved_modules(
    __name__,
    {
        "_signals": "signals._signals",
        "era": "signals.era",
        "noise": "signals.noise",
        "pencil": "signals.pencil",
        "prony": "signals.prony",
        "refine": "signals.refine",
        "two_stage": "signals.two_stage",
    },
)


_DEPRECATED_NAMES = {
    "algorithm1": "inertia_from_release",
    "algorithm21": "inertia_equal_springs",
    "algorithm22": "inertia_known_center",
}
__getattr__ = _module_getattr(__name__, _DEPRECATED_NAMES, globals())
