"""Analytic mechanics: Lagrange equations, linearization, first-order form.

>>> from symosc.mechanics import LagrangianSystem, LinearModel, FirstOrderSystem
"""

from .first_order import FirstOrderSystem
from .lagrange import LagrangianSystem
from .linear_model import LinearModel

__all__ = ["FirstOrderSystem", "LagrangianSystem", "LinearModel"]
