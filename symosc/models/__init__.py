"""Catalogue of concrete oscillating systems.

>>> from symosc.models import n_link_pendulum
"""

from .pendulum import gribkov_khokhlov_table1, n_link_pendulum, pendulum_symbols

__all__ = ["gribkov_khokhlov_table1", "n_link_pendulum", "pendulum_symbols"]
