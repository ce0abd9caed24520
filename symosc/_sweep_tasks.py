"""Worker side of :func:`symosc.sweep` (private): one chunk of grid points as one picklable task, and progress bars.

A :class:`Task` carries the function, the grid axes and a range of flat point indices, so that a chunk travels to a
process or a Dask worker as one small object (the points are generated where they run, not shipped one by one).
"""

from __future__ import annotations

import math
import signal
import sys
import threading
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

#: what a point whose result is NaN/inf reports when ``nan="error"``
NONFINITE = "non-finite result"


class PointTimeout(Exception):
    """Raised inside a point that ran longer than ``timeout`` seconds."""


@dataclass(frozen=True)
class Task:
    """Points ``start <= i < stop`` (flat C order) of the grid ``axes``, evaluated by ``func``."""

    func: Callable[..., Any]
    names: tuple[str, ...]
    axes: tuple[list, ...]
    constants: dict
    start: int
    stop: int
    timeout: float | None = None
    nan: str = "keep"


def point_values(axes: tuple[list, ...], i: int) -> tuple:
    """The grid values of flat index ``i`` (C order)."""
    out = []
    for ax in reversed(axes):
        i, r = divmod(i, len(ax))
        out.append(ax[r])
    return tuple(reversed(out))


def _nonfinite(value: Any) -> bool:
    if isinstance(value, float):
        return not math.isfinite(value)
    try:
        import numpy as np

        if isinstance(value, np.ndarray | np.number) and value.dtype.kind in "fc":
            return not bool(np.isfinite(value).all())
    except Exception:  # pragma: no cover - numpy is a dependency
        pass
    return False


def _alarm(signum, frame):  # pragma: no cover - signal handler
    raise PointTimeout


def run_task(task: Task) -> list:
    """Evaluate every point of a task: ``[(True, value) | (False, (error, traceback)), ...]`` in order.

    Exceptions (and ``SystemExit``) of a point are recorded, not raised; ``KeyboardInterrupt`` propagates.
    """
    func, names, consts = task.func, task.names, task.constants
    use_timer = task.timeout is not None
    if use_timer:
        old = signal.signal(signal.SIGALRM, _alarm)
    out: list = []
    try:
        for i in range(task.start, task.stop):
            kwargs = dict(zip(names, point_values(task.axes, i), strict=True))
            try:
                if use_timer:
                    signal.setitimer(signal.ITIMER_REAL, task.timeout)
                    try:
                        value = func(**kwargs, **consts)
                    finally:
                        signal.setitimer(signal.ITIMER_REAL, 0)
                else:
                    value = func(**kwargs, **consts)
            except PointTimeout:
                out.append((False, (f"TimeoutError: point ran longer than timeout={task.timeout} s", "")))
                continue
            except (Exception, SystemExit) as exc:  # a failing point must not kill the sweep
                out.append((False, (f"{type(exc).__name__}: {exc}", traceback.format_exc())))
                continue
            if task.nan == "error" and _nonfinite(value):
                out.append((False, (f"{NONFINITE}: {value!r}", "")))
            else:
                out.append((True, value))
    finally:
        if use_timer:
            signal.signal(signal.SIGALRM, old)
    return out


def timer_available() -> bool:
    """Per-point timeouts use ``SIGALRM``: POSIX, main thread of the process running the point."""
    return hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()


class Progress:
    """tqdm bar when tqdm is installed (terminals and Jupyter via ``tqdm.auto``), else a text bar on stderr."""

    def __init__(self, total: int, enabled: bool, desc: str = "sweep"):
        self.total, self.done, self.enabled = total, 0, enabled
        self._last = -1
        self._bar = None
        if enabled:
            try:
                from tqdm.auto import tqdm
            except ImportError:
                tqdm = None
            if tqdm is not None:
                self._bar = tqdm(total=total, desc=desc, unit="pt", file=sys.stderr)

    def update(self, n: int) -> None:
        self.done += n
        if not self.enabled:
            return
        if self._bar is not None:
            self._bar.update(n)
            return
        pct = int(100 * self.done / max(self.total, 1))
        if pct != self._last:
            self._last = pct
            width = 30
            filled = width * self.done // max(self.total, 1)
            sys.stderr.write(f"\rsweep [{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} ({pct}%)")
            sys.stderr.flush()

    def note(self, text: str) -> None:
        if self._bar is not None:
            self._bar.set_postfix_str(text)

    def close(self) -> None:
        if not self.enabled:
            return
        if self._bar is not None:
            self._bar.close()
        else:
            sys.stderr.write("\n")
            sys.stderr.flush()
