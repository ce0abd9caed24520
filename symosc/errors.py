"""Error and warning types of symosc.

Every error says what was wrong and what to do about it.  All derive from :class:`SymoscError`, so
``except symosc.SymoscError`` catches anything symosc raises on purpose.  Warnings are issued through :func:`warn`,
which points them at the user's line.
"""

from __future__ import annotations

import os
import sys
import warnings

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


#: Files of the package (the same spelling as the ``co_filename`` of its functions: both come from one import).
_PACKAGE = os.path.dirname(__file__) + os.sep
#: Code that symosc generates and executes (``symosc.numeric.compile``'s checked wrappers) has this file name prefix.
_GENERATED = "<symosc"


def warn(message: str, category: type[Warning]) -> None:
    """``warnings.warn(message, category)`` with the location of the first caller outside symosc.

    A fixed ``stacklevel`` is right for one call path only: the same function reached through a decorator, a
    deprecated keyword's shim or another symosc function would point at a line inside symosc, where the warning
    tells the user nothing (and Python's "once per location" filter would merge warnings from different lines).

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     warn("a message", UserWarning)
    >>> caught[0].filename.startswith("<doctest")  # the line that called warn(), not a file of symosc
    True
    """
    level = 2  # the caller of warn()
    frame = sys._getframe(1)
    while frame is not None and frame.f_code.co_filename.startswith((_PACKAGE, _GENERATED)):
        frame = frame.f_back
        level += 1
    warnings.warn(message, category, stacklevel=level)
