"""Error types of symosc.

Every error says what was wrong and what to do about it.  All derive from :class:`SymoscError`, so
``except symosc.SymoscError`` catches anything symosc raises on purpose.
"""

from __future__ import annotations

__all__ = [
    "AccuracyWarning",
    "ConvergenceError",
    "IdentificationError",
    "ModelError",
    "ParameterError",
    "SeriesWarning",
    "SweepWarning",
    "SymoscError",
    "SymoscWarning",
]


class SymoscError(Exception):
    """Base class of every error raised on purpose by symosc."""


class ModelError(SymoscError, ValueError):
    """The model is ill-posed: singular or indefinite mass matrix, bad coordinates, non-quadratic T, ..."""


class ParameterError(SymoscError, ValueError):
    """A number is missing or invalid (non-finite, wrong sign, wrong count)."""


class ConvergenceError(SymoscError, ArithmeticError):
    """A truncating method did not reach the requested tolerance.

    Attributes
    ----------
    achieved : float or None
        The error estimate that was reached, when one is known.
    """

    def __init__(self, message: str, achieved: float | None = None):
        super().__init__(message)
        self.achieved = achieved


class IdentificationError(SymoscError, ValueError):
    """Identification is impossible or ill-conditioned (repeated frequencies, rank deficiency, ...)."""


class SymoscWarning(UserWarning):
    """Base class of the warnings symosc issues: the result is returned but may be inaccurate."""


class SeriesWarning(SymoscWarning):
    """A truncated series was evaluated where it is not reliable (beyond its estimated radius of convergence)."""


class AccuracyWarning(SymoscWarning):
    """A result is returned, but the problem's conditioning limits its accuracy (the message gives the estimate)."""


class SweepWarning(SymoscWarning):
    """A sweep returned, but every point of it failed (the result's ``failures`` say why)."""
