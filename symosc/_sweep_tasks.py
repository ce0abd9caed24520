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


class PointTimeout(BaseException):
    """Raised inside a point that ran longer than ``timeout`` seconds.

    A ``BaseException`` (like ``KeyboardInterrupt``), so that a function's own ``except Exception:`` does not swallow
    it; a point that swallows it anyway (bare ``except:``) and returns late is still reported as timed out."""


#: failures of one sweep (or one worker's chunk) that keep their traceback; later ones keep only the error text
MAX_TRACES = 20


class LazyTrace:
    """The traceback of an exception, formatted when first asked for (formatting reads source files: a sweep in
    which thousands of points fail would spend most of its time there).  Pickled (to come back from a worker
    process) as its text."""

    __slots__ = ("_exc", "_text")

    def __init__(self, exc: BaseException) -> None:
        self._exc: BaseException | None = exc
        self._text: str | None = None

    def __str__(self) -> str:
        if self._text is None:
            exc, self._exc = self._exc, None
            self._text = "".join(traceback.format_exception(type(exc), exc, exc.__traceback__)) if exc else ""
        return self._text

    def __reduce__(self) -> tuple:
        return (str, (str(self),))


def trace(exc: BaseException, failures_so_far: int) -> LazyTrace | str:
    """A :class:`LazyTrace` of ``exc`` for the first :data:`MAX_TRACES` failures, then a note."""
    if failures_so_far < MAX_TRACES:
        return LazyTrace(exc)
    return f"(traceback not kept: only the first {MAX_TRACES} failures of a sweep keep theirs)\n"


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


def _nonfinite(value: Any, depth: int = 0) -> bool:
    """Whether ``value`` holds a NaN or infinity anywhere: floats and complex numbers, NumPy arrays and scalars,
    SymPy numbers (``nan``, ``zoo``, ``oo``), and the items of lists, tuples, dicts and object arrays."""
    if isinstance(value, bool | int | str | bytes) or value is None:
        return False
    if isinstance(value, float):
        return not math.isfinite(value)
    if isinstance(value, complex):
        return not (math.isfinite(value.real) and math.isfinite(value.imag))
    if depth > 20:
        return False
    import numpy as np

    if isinstance(value, np.ndarray | np.generic):
        if value.dtype.kind in "fc":
            return not bool(np.isfinite(value).all())
        if value.dtype.kind == "O":
            return any(_nonfinite(v, depth + 1) for v in value.flat)
        return False
    if isinstance(value, list | tuple | set | frozenset):
        return any(_nonfinite(v, depth + 1) for v in value)
    if isinstance(value, dict):
        return any(_nonfinite(v, depth + 1) for v in value.values())
    if type(value).__module__.startswith("sympy"):
        import sympy as sp

        if isinstance(value, sp.Basic):
            return bool(value.has(sp.nan, sp.zoo, sp.oo, -sp.oo)) or any(
                isinstance(a, sp.Float) and not math.isfinite(float(a)) for a in value.atoms(sp.Float)
            )
        if isinstance(value, sp.MatrixBase):
            return any(_nonfinite(v, depth + 1) for v in value)
    return False


def _alarm(signum, frame):  # pragma: no cover - signal handler
    raise PointTimeout


def run_task(task: Task) -> list:
    """Evaluate every point of a task: ``[(True, value) | (False, (error, traceback)), ...]`` in order.

    Exceptions (and ``SystemExit``) of a point are recorded, not raised; ``KeyboardInterrupt`` propagates.  With a
    ``timeout`` each point runs under ``SIGALRM``; the handler and any timer the caller had set are restored
    afterwards (the caller's timer less the time the task took).
    """
    import time

    func, names, consts = task.func, task.names, task.constants
    use_timer = task.timeout is not None
    if use_timer:
        old = signal.signal(signal.SIGALRM, _alarm)
        caller_timer = signal.getitimer(signal.ITIMER_REAL)
        signal.setitimer(signal.ITIMER_REAL, 0)
        began = time.monotonic()
    out: list = []
    late = f"TimeoutError: point ran longer than timeout={task.timeout} s"
    try:
        for i in range(task.start, task.stop):
            kwargs = dict(zip(names, point_values(task.axes, i), strict=True))
            try:
                if use_timer:
                    start = time.monotonic()
                    signal.setitimer(signal.ITIMER_REAL, task.timeout)
                    try:
                        value = func(**kwargs, **consts)
                    finally:
                        signal.setitimer(signal.ITIMER_REAL, 0)
                    if time.monotonic() - start > task.timeout:  # the function swallowed the alarm
                        out.append((False, (late, "")))
                        continue
                else:
                    value = func(**kwargs, **consts)
            except PointTimeout:
                out.append((False, (late, "")))
                continue
            except (Exception, SystemExit) as exc:  # a failing point must not kill the sweep
                kept = sum(1 for ok, _ in out if not ok)
                out.append((False, (f"{type(exc).__name__}: {exc}", trace(exc, kept))))
                continue
            if task.nan == "error" and _nonfinite(value):
                out.append((False, (f"{NONFINITE}: {value!r}", "")))
            else:
                out.append((True, value))
    finally:
        if use_timer:
            signal.signal(signal.SIGALRM, old)
            remaining, interval = caller_timer
            if remaining > 0:
                signal.setitimer(signal.ITIMER_REAL, max(remaining - (time.monotonic() - began), 1e-6), interval)
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
