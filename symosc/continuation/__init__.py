"""Numerical continuation of periodic solutions: harmonic balance, shooting, collocation, stability, bifurcations."""

from .collocation import Collocation, collocation
from .branch import Bifurcation, Branch, PeriodicSolution
from .follow import continue_periodic, switch_branch
from .harmonic_balance import HarmonicBalance, harmonic_balance
from .shooting import Shooting, shooting
from .stability import orbit_multipliers

__all__ = [
    "Bifurcation",
    "Branch",
    "Collocation",
    "HarmonicBalance",
    "PeriodicSolution",
    "Shooting",
    "collocation",
    "continue_periodic",
    "harmonic_balance",
    "orbit_multipliers",
    "shooting",
    "switch_branch",
]
