"""Analytic dynamics beyond Lagrange's equations (Bulgakov 1954, §3.10–3.16, §5.3, §7.9).

Hamilton's canonical equations and Poisson brackets, canonical transformations from generating functions, the
Hamilton–Jacobi equation with separation of variables and action–angle variables, and Routh's reduction of cyclic
coordinates with steady motions.
"""

from __future__ import annotations

from .canonical import CanonicalTransformation, canonical_transformation, is_canonical
from .hamilton_jacobi import (
    ActionVariable,
    HamiltonJacobiSeparation,
    action_variable,
    action_variable_numeric,
    separate_hamilton_jacobi,
)
from .hamiltonian import HamiltonianSystem, poisson_bracket
from .routh import RouthReduction, SteadyMotion, routh_reduction

__all__ = [
    "ActionVariable",
    "CanonicalTransformation",
    "HamiltonJacobiSeparation",
    "HamiltonianSystem",
    "RouthReduction",
    "SteadyMotion",
    "action_variable",
    "action_variable_numeric",
    "canonical_transformation",
    "is_canonical",
    "poisson_bracket",
    "routh_reduction",
    "separate_hamilton_jacobi",
]
