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
