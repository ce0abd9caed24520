"""See it move: animations of simulated motions and interactive explorers for notebooks.

``Trajectory.animate`` (from :meth:`LagrangianSystem.simulate <symosc.mechanics.LagrangianSystem.simulate>`) draws
frames with matplotlib; the explorers (:func:`pivot_explorer`, :func:`resonance_explorer`,
:func:`mathieu_explorer`) need the ``widgets`` extra (ipywidgets), imported when one is built.

>>> from symosc.visual import Animation
"""

from .animation import Animation, animate_trajectory
from .widgets import mathieu_explorer, pivot_explorer, resonance_explorer

__all__ = [
    "Animation",
    "animate_trajectory",
    "mathieu_explorer",
    "pivot_explorer",
    "resonance_explorer",
]
