"""Scenes: describe a system and the questions about it in a TOML file; derive only what the questions need.

A scene file names a system (a catalogue model with its options, or a Lagrangian given by T, V, R and forces),
its parameters (numbers in SI units or strings such as ``"45 mm"``), the excitation and a list of questions.
:func:`load` validates the file (errors name the file, the key, its line, the expectation and the fix);
:meth:`Scene.run` answers the questions and returns a :class:`SceneResult` with a report and a derivation log.

>>> from symosc.scene import QUESTIONS
>>> "natural_frequencies" in QUESTIONS
True
"""

from ._errors import SceneError
from ._log import DerivationLog, LogEntry
from ._models import MODELS
from ._result import Figure, QuestionResult, SceneResult, Table
from ._units import UNITS
from .scene import QUESTIONS, Scene, load, loads

__all__ = [
    "MODELS",
    "QUESTIONS",
    "UNITS",
    "DerivationLog",
    "Figure",
    "LogEntry",
    "QuestionResult",
    "Scene",
    "SceneError",
    "SceneResult",
    "Table",
    "load",
    "loads",
]
