"""Analytic mechanics: Lagrange equations, linearisation, first-order form.

>>> from symosc.mechanics import LagrangianSystem, LinearModel, FirstOrderSystem
"""

from .first_order import FirstOrderSystem
from .lagrange import LagrangianSystem
from .linear_model import LinearModel

__all__ = ["FirstOrderSystem", "LagrangianSystem", "LinearModel"]

# public functions refuse invalid arguments with ParameterError (symosc/_validate.py)
from .._validate import guard_public_api as _guard_public_api

_guard_public_api(__name__)
