"""The plotting protocol shared by every ``.plot`` method.

``obj.plot(..., ax=None)``: ``ax`` is keyword-only; the method draws on ``ax`` when given, otherwise on a new
figure, and returns the Axes it drew on.  matplotlib is imported only when something is drawn.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

from ._deprecation import warn_deprecated
from .errors import ParameterError

__all__ = ["new_axes", "plot_method"]


def new_axes(ax: Any = None, **subplots: Any) -> Any:
    """``ax`` itself, or the Axes of a new figure (``plt.subplots(**subplots)``) when ``ax`` is None."""
    if ax is not None:
        return ax
    try:
        import matplotlib.pyplot as plt
    except ImportError as err:  # pragma: no cover - depends on the environment
        raise ImportError("plotting needs matplotlib: pip install 'symosc[plot]'") from err
    _, ax = plt.subplots(**subplots)
    return ax


def _is_axes(value: Any) -> bool:
    return any(c.__name__ == "Axes" and c.__module__.startswith("matplotlib") for c in type(value).__mro__)


def plot_method(func: Callable) -> Callable:
    """Decorator: an Axes passed positionally (the old calling style) is moved to ``ax=`` with a warning."""

    @functools.wraps(func)
    def wrapper(self: Any, *args: Any, **kwargs: Any) -> Any:
        if any(_is_axes(a) for a in args):
            if "ax" in kwargs:
                raise ParameterError(f"{type(self).__name__}.plot: pass the Axes once, as ax=")
            warn_deprecated(f"{type(self).__name__}.{func.__name__}(<Axes>, ...)", f"{func.__name__}(..., ax=<Axes>)")
            kwargs["ax"] = next(a for a in args if _is_axes(a))
            args = tuple(a for a in args if not _is_axes(a))
        return func(self, *args, **kwargs)

    return wrapper
