"""Parameter sweeps and Monte Carlo runs: serial, on a local process pool, or on a Dask cluster.

``sweep(func, grid)`` calls ``func(**point)`` for every point of the Cartesian product of the 1-D arrays in
``grid`` and returns a :class:`SweepResult` whose ``values`` have the grid's shape.  Points are sent in chunks,
results come back in grid order whatever the executor, and a point whose call raises is recorded (with its
parameters and traceback) in ``failures`` instead of stopping the sweep.

Executors: ``"serial"``; ``"processes"`` (:class:`concurrent.futures.ProcessPoolExecutor`; the default when the grid
has at least ``PROCESS_THRESHOLD`` points and the machine more than one core); any
:class:`concurrent.futures.Executor` you created; a Dask ``distributed.Client`` or a scheduler address string
(``"tcp://host:8786"``; dask is imported only then).  ``func`` must be picklable (a module-level function or a
:func:`functools.partial` of one) for every executor except ``"serial"``.
"""

from __future__ import annotations

import itertools
import math
import os
import pickle
import sys
import traceback
import warnings
from collections.abc import Callable, Mapping
from concurrent.futures import Executor, ProcessPoolExecutor
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .errors import ParameterError

__all__ = ["PROCESS_THRESHOLD", "SweepFailure", "SweepResult", "sweep"]

PROCESS_THRESHOLD = 256


@dataclass(frozen=True)
class SweepFailure:
    """A grid point whose call raised: its index in the grid, its parameters, the error and the traceback."""

    index: tuple[int, ...]
    params: dict[str, Any]
    error: str
    traceback: str = field(repr=False)


@dataclass(frozen=True, repr=False, eq=False)
class SweepResult:
    """Result of :func:`sweep`.

    Attributes
    ----------
    values : ndarray
        Shape ``grid shape`` (+ the common shape of array-valued results).  Float when every successful result is
        a real number (or a real array of one common shape), failures as NaN; otherwise an object array with
        ``None`` at failures.
    grid : dict of str -> ndarray
        The axes, in order.
    failures : list of SweepFailure
    executor : str
        What ran the sweep.
    """

    values: np.ndarray
    grid: dict[str, np.ndarray]
    failures: list[SweepFailure]
    executor: str

    @property
    def shape(self) -> tuple[int, ...]:
        """Grid shape."""
        return tuple(a.size for a in self.grid.values())

    @property
    def ok(self) -> np.ndarray:
        """Boolean mask of the points that succeeded (grid shape)."""
        mask = np.ones(self.shape, dtype=bool)
        for f in self.failures:
            mask[f.index] = False
        return mask

    def points(self) -> list[dict[str, Any]]:
        """All grid points as keyword dictionaries, in grid (C) order."""
        names = list(self.grid)
        return [dict(zip(names, p, strict=True)) for p in itertools.product(*self.grid.values())]

    def __repr__(self) -> str:
        axes = ", ".join(f"{k}[{v.size}]" for k, v in self.grid.items())
        return (
            f"SweepResult(grid=({axes}), values dtype={self.values.dtype}, shape={self.values.shape}, "
            f"failures={len(self.failures)}, executor={self.executor!r})"
        )


def _run_chunk(func: Callable[..., Any], names: tuple[str, ...], chunk: list[tuple[Any, ...]], constants: dict) -> list:
    out = []
    for values in chunk:
        try:
            out.append((True, func(**dict(zip(names, values, strict=True)), **constants)))
        except Exception as exc:  # a failing point must not kill the sweep
            out.append((False, (f"{type(exc).__name__}: {exc}", traceback.format_exc())))
    return out


class _Progress:
    def __init__(self, total: int, enabled: bool):
        self.total, self.done, self.enabled = total, 0, enabled
        self._last = -1

    def update(self, n: int) -> None:
        self.done += n
        if not self.enabled:
            return
        pct = int(100 * self.done / max(self.total, 1))
        if pct != self._last:
            self._last = pct
            width = 30
            filled = width * self.done // max(self.total, 1)
            sys.stderr.write(f"\rsweep [{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} ({pct}%)")
            sys.stderr.flush()

    def close(self) -> None:
        if self.enabled:
            sys.stderr.write("\n")
            sys.stderr.flush()


def _axes(grid: Mapping[str, Any]) -> dict[str, np.ndarray]:
    if not isinstance(grid, Mapping) or not grid:
        raise ParameterError("grid must be a non-empty mapping of argument names to 1-D arrays")
    axes = {}
    for name, vals in grid.items():
        if not isinstance(name, str) or not name.isidentifier():
            raise ParameterError(f"grid keys must be argument names, got {name!r}")
        try:
            arr = np.asarray(vals)
        except ValueError:  # ragged entries: keep them as objects
            arr = np.empty(len(vals), dtype=object)
            arr[:] = list(vals)
        if arr.ndim == 0:
            arr = arr.reshape(1)
        if arr.ndim != 1 or arr.size == 0:
            raise ParameterError(f"grid[{name!r}] must be a non-empty 1-D array, got shape {arr.shape}")
        axes[name] = arr
    return axes


def _pack(results: list, shape: tuple[int, ...], failed: set[int]) -> np.ndarray:
    good = [r for i, r in enumerate(results) if i not in failed]

    def is_real_scalar(v: Any) -> bool:
        return isinstance(v, (int, float, np.integer, np.floating, np.bool_, bool))

    if good and all(is_real_scalar(v) for v in good):
        out = np.full(len(results), np.nan)
        for i, v in enumerate(results):
            if i not in failed:
                out[i] = float(v)
        return out.reshape(shape)
    if good and all(isinstance(v, np.ndarray) and v.dtype.kind in "biuf" for v in good):
        s0 = good[0].shape
        if all(v.shape == s0 for v in good):
            out = np.full((len(results), *s0), np.nan)
            for i, v in enumerate(results):
                if i not in failed:
                    out[i] = v
            return out.reshape(shape + s0)
    out = np.empty(len(results), dtype=object)
    for i, v in enumerate(results):
        out[i] = None if i in failed else v
    return out.reshape(shape)


def sweep(
    func: Callable[..., Any],
    grid: Mapping[str, Any],
    *,
    executor: Any = None,
    chunksize: int | None = None,
    progress: bool | None = None,
    constants: Mapping[str, Any] | None = None,
    max_workers: int | None = None,
) -> SweepResult:
    """Evaluate ``func(**point, **constants)`` on the Cartesian product of ``grid``.

    Parameters
    ----------
    func : callable
        Called with keyword arguments named like the grid axes (plus ``constants``).
    grid : mapping of str -> 1-D array_like
        The axes; the result has shape ``tuple(len(axis) for axis in grid.values())``.
    executor : None, "serial", "processes", Executor, distributed.Client or str
        ``None`` picks ``"processes"`` for grids of at least ``PROCESS_THRESHOLD`` points (when there is more than
        one CPU and ``func`` pickles) and ``"serial"`` otherwise.  A string other than "serial"/"processes" is a
        Dask scheduler address; a ``distributed.Client`` is used as is (not closed).
    chunksize : int, optional
        Points per task (default: about 4 chunks per worker, at least 1).
    progress : bool, optional
        Text progress bar on stderr (default: only when stderr is a terminal).
    constants : mapping, optional
        Extra keyword arguments passed unchanged to every call.
    max_workers : int, optional
        Size of the process pool for ``"processes"``.

    Returns
    -------
    SweepResult

    Examples
    --------
    >>> import math
    >>> res = sweep(lambda x, y: math.hypot(x, y), {"x": [3.0, 5.0], "y": [4.0, 12.0]}, executor="serial")
    >>> res.values.tolist()
    [[5.0, 12.36931687685298], [6.4031242374328485, 13.0]]
    >>> res = sweep(lambda x: math.log(x), {"x": [1.0, -1.0]}, executor="serial")
    >>> res.values.tolist(), res.failures[0].params, res.failures[0].error
    ([0.0, nan], {'x': -1.0}, 'ValueError: math domain error')
    """
    if not callable(func):
        raise ParameterError(f"func must be callable, got {func!r}")
    axes = _axes(grid)
    names = tuple(axes)
    shape = tuple(a.size for a in axes.values())
    points = list(itertools.product(*(a.tolist() for a in axes.values())))
    total = len(points)
    consts = dict(constants or {})
    if progress is None:
        progress = bool(getattr(sys.stderr, "isatty", lambda: False)())

    if chunksize is not None and (int(chunksize) != chunksize or chunksize < 1):
        raise ParameterError(f"chunksize must be a positive integer, got {chunksize!r}")
    if max_workers is not None and (int(max_workers) != max_workers or max_workers < 1):
        raise ParameterError(f"max_workers must be a positive integer, got {max_workers!r}")
    ncpu = os.cpu_count() or 1
    kind, client, own_client = _resolve_executor(executor, func, total, ncpu)
    workers = max_workers or (ncpu if kind == "processes" else 1)
    if kind == "dask":
        workers = max(1, len(client.scheduler_info().get("workers", {})) or 1)
    if chunksize is None:
        chunksize = max(1, math.ceil(total / (4 * max(workers, 1))))
    chunks = [points[i : i + int(chunksize)] for i in range(0, total, int(chunksize))]

    bar = _Progress(total, progress)
    results: list[Any] = [None] * total
    failures: list[SweepFailure] = []
    failed: set[int] = set()

    def result(ci: int, fut: Any) -> list:
        """A chunk whose task itself died (worker crash, unpicklable result) marks all its points as failed."""
        try:
            return fut.result()
        except Exception as exc:
            msg = f"chunk failed: {type(exc).__name__}: {exc}"
            return [(False, (msg, traceback.format_exc()))] * len(chunks[ci])

    def collect(ci: int, out: list) -> None:
        start = ci * int(chunksize)
        for j, (ok, val) in enumerate(out):
            i = start + j
            if ok:
                results[i] = val
            else:
                failed.add(i)
                idx = tuple(int(v) for v in np.unravel_index(i, shape))
                failures.append(
                    SweepFailure(
                        index=idx, params=dict(zip(names, points[i], strict=True)), error=val[0], traceback=val[1]
                    )
                )
        bar.update(len(out))

    try:
        if kind == "serial":
            for ci, ch in enumerate(chunks):
                collect(ci, _run_chunk(func, names, ch, consts))
        elif kind == "dask":
            futs = client.map(
                _run_chunk, [func] * len(chunks), [names] * len(chunks), chunks, [consts] * len(chunks), pure=False
            )
            for ci, fut in enumerate(futs):
                collect(ci, result(ci, fut))
        else:
            pool = ProcessPoolExecutor(max_workers=workers) if kind == "processes" else client
            try:
                futs = [pool.submit(_run_chunk, func, names, ch, consts) for ch in chunks]
                for ci, fut in enumerate(futs):
                    collect(ci, result(ci, fut))
            finally:
                if kind == "processes":
                    pool.shutdown()
    finally:
        bar.close()
        if own_client:
            client.close()
    failures.sort(key=lambda f: f.index)
    label = type(client).__name__ if kind == "executor" else kind
    return SweepResult(values=_pack(results, shape, failed), grid=axes, failures=failures, executor=label)


def _picklable(obj: Any) -> bool:
    try:
        pickle.dumps(obj)
    except Exception:
        return False
    return True


def _resolve_executor(executor: Any, func: Any, total: int, ncpu: int) -> tuple[str, Any, bool]:
    if executor is None:
        if total >= PROCESS_THRESHOLD and ncpu > 1:
            if _picklable(func):
                return "processes", None, False
            warnings.warn("sweep: func cannot be pickled; running serially", RuntimeWarning, stacklevel=3)
        return "serial", None, False
    if isinstance(executor, str):
        if executor == "serial":
            return "serial", None, False
        if executor == "processes":
            if not _picklable(func):
                raise ParameterError(
                    "executor='processes' needs a picklable func (a module-level function or functools.partial of "
                    "one, not a lambda or closure); use executor='serial' otherwise"
                )
            return "processes", None, False
        try:
            from distributed import Client
        except ImportError:  # pragma: no cover - depends on the environment
            raise ParameterError(
                f"executor={executor!r} is not 'serial' or 'processes', so it must be a Dask scheduler address, "
                "but dask.distributed is not installed (pip install 'dask[distributed]')"
            ) from None
        return "dask", Client(executor), True
    if type(executor).__module__.split(".")[0] == "distributed":
        return "dask", executor, False
    if isinstance(executor, Executor):
        return "executor", executor, False
    raise ParameterError(
        f"executor must be None, 'serial', 'processes', a concurrent.futures.Executor, a distributed.Client or a "
        f"scheduler address; got {executor!r}"
    )
