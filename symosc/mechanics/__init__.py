"""Analytic mechanics: Lagrange equations, linearization, first-order form.

>>> from symosc.mechanics import LagrangianSystem, LinearModel, FirstOrderSystem
"""

from .._printing import add_printing_hooks
from .first_order import FirstOrderSystem
from .lagrange import LagrangianSystem
from .linear_model import LinearModel

__all__ = ["FirstOrderSystem", "LagrangianSystem", "LinearModel"]

add_printing_hooks(FirstOrderSystem)  # SymPy printing (sympy.latex etc.) like the other models
