"""Analytic mechanics: Lagrange equations (with constraints), Routh, Hamilton, canonical transformations,
Hamilton-Jacobi, linearization about equilibria and motions, first-order form.

>>> from symosc.mechanics import LagrangianSystem, LinearModel, FirstOrderSystem, HamiltonianSystem
"""

from .._deprecation import moved_modules as _moved_modules
from ._quadratic import ComplexModes, complex_modes
from .analytic import (
    ActionVariable,
    CanonicalTransformation,
    HamiltonianSystem,
    HamiltonJacobiSeparation,
    RouthReduction,
    SteadyMotion,
    action_variable,
    action_variable_numeric,
    canonical_transformation,
    is_canonical,
    poisson_bracket,
    routh_reduction,
    separate_hamilton_jacobi,
)
from .applications import (
    GovernorStatics,
    LoopEquations,
    electromechanical_system,
    governor_statics,
    loop_equations,
    stodola_time_constant,
    vyshnegradsky_cubic,
)
from .constraints import ConstrainedForm, MinimalForm
from .first_order import FirstOrderSystem
from .lagrange import LagrangianSystem
from .linear_model import LinearModel
from .simulation import Geometry, Trajectory
from .variational import (
    FirstOrderReduction,
    ForceDecomposition,
    StabilityVerdict,
    VariationalEquations,
    decompose_forces,
    variational_equations,
)

__all__ = [
    "ActionVariable",
    "CanonicalTransformation",
    "ComplexModes",
    "ConstrainedForm",
    "FirstOrderReduction",
    "FirstOrderSystem",
    "ForceDecomposition",
    "Geometry",
    "GovernorStatics",
    "HamiltonJacobiSeparation",
    "HamiltonianSystem",
    "LagrangianSystem",
    "LinearModel",
    "LoopEquations",
    "MinimalForm",
    "RouthReduction",
    "StabilityVerdict",
    "SteadyMotion",
    "Trajectory",
    "VariationalEquations",
    "action_variable",
    "action_variable_numeric",
    "canonical_transformation",
    "complex_modes",
    "decompose_forces",
    "electromechanical_system",
    "governor_statics",
    "is_canonical",
    "loop_equations",
    "poisson_bracket",
    "routh_reduction",
    "separate_hamilton_jacobi",
    "stodola_time_constant",
    "variational_equations",
    "vyshnegradsky_cubic",
]

#: module paths before the split into families (old -> new): deprecated, kept so that code and pickles written
#: against them still load
_moved_modules(
    __name__,
    {
        "_separation": "analytic._separation",
        "canonical": "analytic.canonical",
        "circuits": "applications.circuits",
        "electromechanical": "applications.electromechanical",
        "governor": "applications.governor",
        "hamilton_jacobi": "analytic.hamilton_jacobi",
        "hamiltonian": "analytic.hamiltonian",
        "routh": "analytic.routh",
    },
)
