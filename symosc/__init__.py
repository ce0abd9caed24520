"""symosc — symbolic-first theory of oscillations.

SymPy derives the equations; :func:`symosc.numeric.compile` turns the same objects into NumPy or mpmath
callables that validate every derivation.

>>> import symosc
>>> system = symosc.models.n_link_pendulum(1)
>>> system.linearize().natural_frequencies({"m1": 1.0, "l1": 9.81, "g": 9.81})
array([1.])
"""

from . import errors, numeric, symbols
from .errors import ConvergenceError, IdentificationError, ModelError, ParameterError, SymoscError
from .sweep import sweep  # eager (light), so that the function is not shadowed by its submodule
from .symbols import ddot, dot, t

__version__ = "0.1.0"

__all__ = [
    "ConvergenceError",
    "IdentificationError",
    "ModelError",
    "ParameterError",
    "SymoscError",
    "ddot",
    "dot",
    "errors",
    "numeric",
    "sweep",
    "symbols",
    "t",
]


def __getattr__(name: str):
    """Import subpackages lazily so that ``import symosc`` stays light."""
    import importlib

    if name in {
        "mechanics",
        "models",
        "periodic",
        "algebra",
        "operational",
        "nonlinear",
        "codegen",
        "identification",
        "linear",
        "plotting",
        "networks",
        "cli",
        "scene",
    }:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'symosc' has no attribute {name!r}")
