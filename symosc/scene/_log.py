"""Derivation log: which derivation steps ran for a scene, and how long each took."""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from .._printing import SymPyPrintable

__all__ = ["DerivationLog", "LogEntry"]


@dataclass(frozen=True)
class LogEntry(SymPyPrintable):
    """One derivation or evaluation step: its name, wall time in seconds and a short detail.

    Attributes
    ----------
    step : str
        Name of the step, such as ``"linearize at q = 0"``.
    seconds : float
        Wall time the step took, in seconds (>= 0).
    detail : str
        A short description of what was derived (empty when none).

    Examples
    --------
    >>> LogEntry("linearize at q = 0", 0.0123)
    LogEntry('linearize at q = 0', 12.3 ms)
    """

    step: str
    seconds: float
    detail: str = ""

    def __repr__(self) -> str:
        return f"LogEntry({self.step!r}, {self.seconds * 1e3:.1f} ms)"


class DerivationLog(SymPyPrintable):
    """An append-only list of :class:`LogEntry` filled while a scene runs.

    Examples
    --------
    >>> log = DerivationLog()
    >>> with log.step("linearize", "M, D, K from the energies"):
    ...     pass
    >>> log.steps()
    ['linearize']

    See Also
    --------
    symosc.scene.SceneResult : carries the log of a run (``result.log``).
    """

    def __init__(self) -> None:
        self.entries: list[LogEntry] = []

    @contextmanager
    def step(self, name: str, detail: str = "") -> Iterator[None]:
        """Time the body of the ``with`` block and record it as ``name``.

        Parameters
        ----------
        name : str
            Name of the step, recorded as :attr:`LogEntry.step`.
        detail : str
            A short description of what the step derives (empty when none).

        Yields
        ------
        None
            The entry is appended when the block ends without an exception.
        """
        t0 = time.perf_counter()
        yield
        self.entries.append(LogEntry(name, time.perf_counter() - t0, detail))

    def steps(self) -> list[str]:
        """Names of the steps in the order they ran."""
        return [e.step for e in self.entries]

    def __repr__(self) -> str:
        return f"DerivationLog({self.steps()})"
