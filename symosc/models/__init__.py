"""Catalogue of concrete oscillating systems.

>>> from symosc.models import n_link_pendulum
"""

from .body_on_springs import BodyOnSprings, body_on_springs
from .pendulum import gribkov_khokhlov_table1, n_link_pendulum, n_link_pendulum_linearization, pendulum_symbols

__all__ = [
    "BodyOnSprings",
    "body_on_springs",
    "gribkov_khokhlov_table1",
    "n_link_pendulum",
    "n_link_pendulum_linearization",
    "pendulum_symbols",
]

# public functions refuse invalid arguments with ParameterError (symosc/_validate.py)
from .._validate import guard_public_api as _guard_public_api

_guard_public_api(__name__)

# SymPy printer hooks (sympy.latex, sstr, pretty) and pickling support on every public model and result
from .._printing import add_printing_hooks_to_public as _add_printing_hooks_to_public  # noqa: E402

_add_printing_hooks_to_public(__name__)
