"""Lagrange's equations applied to systems that are not only mechanical (Bulgakov 1954, §3.8, §7.5–7.7, §7.10–7.11).

Loop equations of passive electrical networks from their graph, electromechanical systems in Maxwell's form, and the
steam engine with a centrifugal governor (Vyshnegradsky 1876).
"""

from __future__ import annotations

from .circuits import LoopEquations, loop_equations
from .electromechanical import electromechanical_system
from .governor import GovernorStatics, governor_statics, stodola_time_constant, vyshnegradsky_cubic

__all__ = [
    "GovernorStatics",
    "LoopEquations",
    "electromechanical_system",
    "governor_statics",
    "loop_equations",
    "stodola_time_constant",
    "vyshnegradsky_cubic",
]
