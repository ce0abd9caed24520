"""Numerical continuation of periodic solutions: harmonic balance, shooting, collocation, stability, bifurcations."""

from .branch import Bifurcation, Branch, PeriodicSolution
from .collocation import Collocation, collocation
from .folds import FoldCurve, continue_fold
from .follow import continue_periodic, switch_branch
from .harmonic_balance import HarmonicBalance, harmonic_balance
from .shooting import Shooting, shooting
from .stability import orbit_multipliers

__all__ = [
    "Bifurcation",
    "Branch",
    "Collocation",
    "FoldCurve",
    "HarmonicBalance",
    "PeriodicSolution",
    "Shooting",
    "collocation",
    "continue_fold",
    "continue_periodic",
    "harmonic_balance",
    "orbit_multipliers",
    "shooting",
    "switch_branch",
]
