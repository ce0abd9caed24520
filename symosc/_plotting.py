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

__all__ = ["label_curves", "new_axes", "outside_legend", "plot_method", "pyplot", "require_matplotlib", "tex_name"]

MISSING_MATPLOTLIB = "drawing needs matplotlib, which is not installed: pip install 'symosc[plot]'"


def require_matplotlib() -> Any:
    """The ``matplotlib`` module; ``ImportError`` naming the ``plot`` extra when it is not installed."""
    try:
        import matplotlib
    except ImportError as err:
        raise ImportError(MISSING_MATPLOTLIB) from err
    return matplotlib


def pyplot() -> Any:
    """``matplotlib.pyplot``, imported when something is drawn (``ImportError`` naming the extra otherwise)."""
    require_matplotlib()
    import matplotlib.pyplot as plt

    return plt


def new_axes(ax: Any = None, **subplots: Any) -> Any:
    """``ax`` itself, or the Axes of a new figure (``plt.subplots(**subplots)``) when ``ax`` is None."""
    if ax is not None:
        return ax
    _, ax = pyplot().subplots(**subplots)
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


def label_curves(
    ax: Any, curves: list, *, fractions: tuple = (0.85, 0.7, 0.95, 0.55, 0.4, 0.25, 0.1), **text: Any
) -> list:
    """Label curves directly, each label where it overlaps no other label and stays inside the axes.

    ``curves`` holds ``(x, y, label)``; for each curve the candidates are its visible points at the given
    ``fractions`` of their count, tried in order; the first whose text box (measured with the figure's renderer)
    clears the labels already placed (and the legend, drawn first) is taken, else the first candidate.  Returns
    the Text artists.
    """
    import numpy as np

    fig = ax.figure
    renderer = fig.canvas.get_renderer()
    x0, x1 = sorted(ax.get_xlim())
    y0, y1 = sorted(ax.get_ylim())
    frame = ax.get_window_extent(renderer)
    legend = ax.get_legend()
    placed: list = [legend.get_window_extent(renderer)] if legend is not None else []
    out = []
    for x, y, label in curves:
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        inside = np.nonzero(np.isfinite(x) & np.isfinite(y) & (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1))[0]
        if inside.size == 0:
            continue
        style = {"fontsize": 9, "textcoords": "offset points", **text}
        xs, ys = x[inside], y[inside]
        spots = []
        for f in fractions:  # positions interpolated along the visible part, so short curves have candidates too
            u = f * (inside.size - 1)
            spots.append(
                (float(np.interp(u, np.arange(inside.size), xs)), float(np.interp(u, np.arange(inside.size), ys)))
            )
        chosen = None
        for offset in ((3, 2), (-14, 4), (4, -12)):
            for spot in spots:
                artist = ax.annotate(label, spot, xytext=offset, **style)
                box = artist.get_window_extent(renderer)
                inside_axes = frame.x0 <= box.x0 and box.x1 <= frame.x1 and frame.y0 <= box.y0 and box.y1 <= frame.y1
                if inside_axes and not any(box.overlaps(b) for b in placed):
                    chosen = (artist, box)
                    break
                artist.remove()
            if chosen is not None:
                break
        if chosen is None:
            artist = ax.annotate(label, spots[0], xytext=(3, 2), **style)
            chosen = (artist, artist.get_window_extent(renderer))
        placed.append(chosen[1])
        out.append(chosen[0])
    return out


def outside_legend(ax: Any, **kwargs: Any) -> Any:
    """A legend to the right of the axes, where it hides no curve (``tight_layout`` makes room for it)."""
    return ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, fontsize=8, **kwargs)


_GREEK = {"phi", "theta", "psi", "alpha", "beta", "gamma", "varphi", "chi", "xi", "eta", "zeta", "rho", "sigma"}


def tex_name(name: str, dot: bool = False) -> str:
    """A coordinate name as a mathtext label: ``"phi1" -> "$\\phi_{1}$"`` (dotted for a velocity)."""
    base = name.rstrip("0123456789")
    digits = name[len(base) :]
    sym = (f"\\{base}" if base in _GREEK else base) + (f"_{{{digits}}}" if digits else "")
    return f"$\\dot{{{sym}}}$" if dot else f"${sym}$"
