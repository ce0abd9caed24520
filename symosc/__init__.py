"""symosc — symbolic-first theory of oscillations.

SymPy derives the equations; :func:`symosc.numeric.compile` turns the same objects into NumPy or mpmath
callables that validate every derivation.

>>> import symosc
>>> system = symosc.models.n_link_pendulum(1)
>>> system.linearize().natural_frequencies({"m1": 1.0, "l1": 9.81, "g": 9.81})
array([1.])
"""

from . import errors, io, numeric, symbols
from .errors import ConvergenceError, IdentificationError, ModelError, ParameterError, SymoscError
from .io import load, save
from .sweep import sweep  # eager (light), so that the function is not shadowed by its submodule
from .symbols import ddot, dot, t

__version__ = "0.1.0"

# ``symosc._lazy`` moved into ``symosc.numeric`` (results pickled before the move name the old path)
from ._deprecation import moved_modules as _moved_modules

_moved_modules(__name__, {"_lazy": "numeric._lazy"})

__all__ = [
    "ConvergenceError",
    "IdentificationError",
    "ModelError",
    "ParameterError",
    "SymoscError",
    "ddot",
    "dot",
    "errors",
    "io",
    "load",
    "numeric",
    "save",
    "sweep",
    "symbols",
    "t",
]


# Subpackages imported on first access (``symosc.mechanics`` etc.), so that ``import symosc`` stays light.
_SUBPACKAGES = frozenset(
    {
        "algebra",
        "cli",
        "codegen",
        "continuation",
        "identification",
        "linear",
        "mechanics",
        "models",
        "networks",
        "nonlinear",
        "operational",
        "periodic",
        "scene",
        "visual",
    }
)


def __getattr__(name: str):
    """Import subpackages lazily so that ``import symosc`` stays light."""
    import importlib

    if name in _SUBPACKAGES:
        try:
            return importlib.import_module(f".{name}", __name__)
        except ModuleNotFoundError as err:
            if err.name != f"{__name__}.{name}":
                raise
    raise AttributeError(f"module 'symosc' has no attribute {name!r}")


def _installed_subpackages() -> list[str]:
    """Names of the lazily imported subpackages present in this installation of symosc."""
    import importlib.util
    import os

    here = os.path.dirname(os.path.abspath(__file__))
    out = []
    for name in sorted(_SUBPACKAGES):
        spec = importlib.util.find_spec(f"{__name__}.{name}")
        if spec is not None and spec.origin and os.path.abspath(spec.origin).startswith(here + os.sep):
            out.append(name)
    return out


def __dir__() -> list[str]:
    """Public names and the subpackages that are installed."""
    return sorted(set(__all__) | set(_installed_subpackages()) | {"__version__"})
