"""Analytic mechanics: Lagrange equations (with constraints), Routh, Hamilton, canonical transformations,
Hamilton-Jacobi, linearization about equilibria and motions, first-order form.

>>> from symosc.mechanics import LagrangianSystem, LinearModel, FirstOrderSystem, HamiltonianSystem
"""

from ._quadratic import ComplexModes, complex_modes
from .canonical import CanonicalTransformation, canonical_transformation, is_canonical
from .circuits import LoopEquations, loop_equations
from .constraints import ConstrainedForm, MinimalForm
from .electromechanical import electromechanical_system
from .first_order import FirstOrderSystem
from .governor import GovernorStatics, governor_statics, stodola_time_constant, vyshnegradsky_cubic
from .hamilton_jacobi import (
    ActionVariable,
    HamiltonJacobiSeparation,
    action_variable,
    action_variable_numeric,
    separate_hamilton_jacobi,
)
from .hamiltonian import HamiltonianSystem, poisson_bracket
from .lagrange import LagrangianSystem
from .linear_model import LinearModel
from .routh import RouthReduction, SteadyMotion, routh_reduction
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

# public functions refuse invalid arguments with ParameterError (symosc/_validate.py)
from .._validate import guard_public_api as _guard_public_api

_guard_public_api(__name__)


# SymPy printer hooks (sympy.latex, sstr, pretty) and pickling support on every public model and result
from .._printing import add_printing_hooks_to_public as _add_printing_hooks_to_public  # noqa: E402

_add_printing_hooks_to_public(__name__)
