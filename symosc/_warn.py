"""Warnings attributed to the user's line: the first frame of the call stack outside symosc.

A fixed ``stacklevel`` is right for one call path only: the same function reached through a decorator, a deprecated
keyword's shim or another symosc function would point at a line inside symosc, where the warning tells the user
nothing (and Python's "once per location" filter would then merge warnings from different user lines).
"""

from __future__ import annotations

import os
import sys
import warnings

#: Files of the package (the same spelling as the ``co_filename`` of its functions: both come from one import).
_PACKAGE = os.path.dirname(__file__) + os.sep
#: Code that symosc generates and executes (``symosc.numeric.compile``'s checked wrappers) has this file name prefix.
_GENERATED = "<symosc"


def warn(message: str, category: type[Warning]) -> None:
    """``warnings.warn(message, category)`` with the location of the first caller outside symosc.

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     warn("a message", UserWarning)
    >>> caught[0].filename == __file__ or caught[0].filename.startswith("<doctest")
    True
    """
    level = 2  # the caller of warn()
    frame = sys._getframe(1)
    while frame is not None and frame.f_code.co_filename.startswith((_PACKAGE, _GENERATED)):
        frame = frame.f_back
        level += 1
    warnings.warn(message, category, stacklevel=level)
