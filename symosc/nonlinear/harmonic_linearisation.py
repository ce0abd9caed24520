"""The old import path of :mod:`symosc.nonlinear.harmonic_linearization`: every name is read from that module.

Kept from before the project settled on American spelling; the British-spelled names warn once.
"""

from __future__ import annotations

import importlib
from typing import Any

_MODULE = importlib.import_module("symosc.nonlinear.harmonic_linearization")


def __getattr__(name: str) -> Any:
    return getattr(_MODULE, name)


def __dir__() -> list[str]:
    return dir(_MODULE)
