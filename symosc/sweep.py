"""Parameter sweeps and Monte Carlo runs: serial, on a local process pool, or on a Dask cluster.

``sweep(func, grid)`` calls ``func(**point)`` for every point of the Cartesian product of the 1-D arrays in
``grid`` and returns a :class:`SweepResult` whose ``values`` have the grid's shape.  Points are sent in chunks,
results come back in grid order whatever the executor, and a point whose call raises is recorded (with its
parameters and traceback) in ``failures`` instead of stopping the sweep.

Executors: ``"serial"``; ``"processes"`` (:class:`concurrent.futures.ProcessPoolExecutor`); ``"auto"`` (the
default: the first chunk runs serially and is timed; the rest goes to a process pool only when the measured cost
says it pays, and the result's ``executor_note`` says what was chosen and why); any
:class:`concurrent.futures.Executor` you created; a Dask ``distributed.Client`` or a scheduler address string
(``"tcp://host:8786"``; dask is imported only then).  ``func`` must be picklable (a module-level function or a
:func:`functools.partial` of one) for every executor except ``"serial"``.  Each chunk travels as one object (the
function, the axes and a range of point indices; the points are generated where they run).
"""

from __future__ import annotations

import difflib
import functools
import itertools
import math
import os
import pickle
import sys
import time
from collections.abc import Callable, Mapping
from concurrent.futures import Executor
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import _sweep_tasks as _tasks
from ._validate import check_choice
from .errors import ParameterError, warn

__all__ = ["PROCESS_THRESHOLD", "SweepFailure", "SweepResult", "sweep"]

#: "auto" never starts processes for fewer points than this
PROCESS_THRESHOLD = 256
#: "auto" starts a process pool only when the serial estimate for the remaining points exceeds this (seconds)
AUTO_PARALLEL_SECONDS = 2.0
_EXECUTOR_NAMES = ("auto", "serial", "processes")


@dataclass(frozen=True)
class SweepFailure:
    """A grid point whose call raised: its index in the grid, its parameters, the error and the traceback.

    Attributes
    ----------
    index : tuple of int
        The point's index in the grid.
    params : dict
        The point's arguments.
    error : str
        ``"ExceptionType: message"`` (or the timeout / non-finite result that failed it).
    trace : str or object
        The traceback, formatted when :attr:`traceback` is first read (kept for the first 20 failures of a
        sweep; later ones keep only ``error``).
    """

    index: tuple[int, ...]
    params: dict[str, Any]
    error: str
    trace: Any = field(default="", repr=False, compare=False)

    @property
    def traceback(self) -> str:
        """The formatted traceback ("" for a timeout or a non-finite result)."""
        return str(self.trace)


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
    executor_note : str
        Why (for ``executor="auto"``: the measured cost of the first chunk).
    interrupted : bool
        True when Ctrl-C stopped the sweep; points that did not run are NaN/None and listed in ``failures`` with
        the error ``"KeyboardInterrupt: not run"``.
    """

    values: np.ndarray
    grid: dict[str, np.ndarray]
    failures: list[SweepFailure]
    executor: str
    executor_note: str = ""
    interrupted: bool = False

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
        extra = ", interrupted=True" if self.interrupted else ""
        return (
            f"SweepResult(grid=({axes}), values dtype={self.values.dtype}, shape={self.values.shape}, "
            f"failures={len(self.failures)}, executor={self.executor!r}{extra})"
        )

    def _value_dims(self, dims: Any = None) -> list[str]:
        extra = self.values.ndim - len(self.grid)
        if dims is not None:
            names = [dims] if isinstance(dims, str) else list(dims)
            if len(names) != extra or not all(isinstance(d, str) for d in names):
                raise ParameterError(f"dims must name the {extra} axes of each point's value, got {dims!r}")
            return names
        return {0: [], 1: ["component"], 2: ["row", "column"]}.get(extra, [f"axis_{i}" for i in range(extra)])

    def _dict_results(self) -> list[str] | None:
        """The common keys when every successful point returned a dict with the same keys (else None)."""
        if self.values.dtype != object:
            return None
        ok = [v for v in self.values.reshape(-1) if v is not None]
        if not ok or not all(isinstance(v, dict) for v in ok):
            return None
        keys = list(ok[0])
        return keys if all(list(v) == keys for v in ok) else None

    def to_xarray(self, name: str = "value", *, dims: Any = None):
        """The values as an ``xarray.DataArray`` with one coordinate per grid axis (named after it).

        Array-valued results add trailing dimensions, named by ``dims`` (default ``"component"`` for vectors,
        ``"row", "column"`` for matrices).  When every point returns a dict with the same keys, the result is an
        ``xarray.Dataset`` with one variable per key.  Needs xarray (``pip install xarray``).

        Parameters
        ----------
        name : str
            Name of the DataArray (ignored for a Dataset, whose variables are named by the keys).
        dims : str or sequence of str, optional
            Names of the trailing dimensions of array-valued results.

        Examples
        --------
        >>> res = sweep(lambda x, y: x * y, {"x": [1.0, 2.0], "y": [10.0, 20.0, 30.0]}, executor="serial")
        >>> da = res.to_xarray()
        >>> float(da.sel(x=2.0, y=30.0))
        60.0
        >>> ds = sweep(lambda x: {"a": x, "b": [x, -x]}, {"x": [1.0, 2.0]}, executor="serial").to_xarray()
        >>> float(ds["a"].sel(x=2.0)), ds["b"].dims
        (2.0, ('x', 'component'))

        See Also
        --------
        to_pandas
        """
        try:
            import xarray as xr
        except ImportError:
            raise ImportError("SweepResult.to_xarray needs xarray: pip install xarray") from None
        keys = self._dict_results()
        if keys is not None:
            flat = self.values.reshape(-1)
            failed = {i for i, v in enumerate(flat) if v is None}
            variables = {}
            for key in keys:
                entries = [None if v is None else v[key] for v in flat]
                entries = [np.asarray(e) if isinstance(e, list | tuple) else e for e in entries]
                column = _pack(entries, self.shape, failed)
                part = SweepResult(column, self.grid, self.failures, self.executor)
                variables[key] = part.to_xarray(name=key, dims=dims if column.ndim > len(self.grid) else None)
            return xr.Dataset(variables)
        dims_all = [*self.grid, *self._value_dims(dims)]
        return xr.DataArray(self.values, coords=dict(self.grid), dims=dims_all, name=name)

    def to_pandas(self, name: str = "value"):
        """The values as a ``pandas.Series`` indexed by a MultiIndex named after the grid axes.

        Array-valued results give a ``DataFrame`` with one column per entry of the flattened value.  Needs pandas.

        Examples
        --------
        >>> res = sweep(lambda x, y: x * y, {"x": [1.0, 2.0], "y": [10.0, 20.0]}, executor="serial")
        >>> s = res.to_pandas()
        >>> list(s.index.names), float(s.loc[(2.0, 20.0)])
        (['x', 'y'], 40.0)

        See Also
        --------
        to_xarray
        """
        try:
            import pandas as pd
        except ImportError:
            raise ImportError("SweepResult.to_pandas needs pandas: pip install pandas") from None
        index = pd.MultiIndex.from_product(list(self.grid.values()), names=list(self.grid))
        n = len(index)
        if self.values.ndim == len(self.grid):
            return pd.Series(self.values.reshape(n), index=index, name=name)
        return pd.DataFrame(self.values.reshape(n, -1), index=index)


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


_REAL_TYPES = frozenset({int, float, bool, np.float64, np.float32, np.int64, np.int32, np.bool_})


def _pack(results: list, shape: tuple[int, ...], failed: set[int]) -> np.ndarray:
    if not failed and set(map(type, results)) <= _REAL_TYPES:
        return np.fromiter(results, dtype=float, count=len(results)).reshape(shape)
    good = [r for i, r in enumerate(results) if i not in failed]

    def is_real_scalar(v: Any) -> bool:
        return isinstance(v, int | float | np.integer | np.floating | np.bool_ | bool)

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


def _positional(func, names: tuple[str, ...]) -> bool:
    """True when ``func(*values)`` means ``func(**dict(zip(names, values)))`` (leading parameters named so)."""
    import inspect

    try:
        params = list(inspect.signature(func).parameters.values())
    except (TypeError, ValueError):
        return False
    if len(params) < len(names):
        return False
    return all(
        p.name == name and p.kind is inspect.Parameter.POSITIONAL_OR_KEYWORD
        for p, name in zip(params, names, strict=False)
    )


def _serial_plain(func, names, points, consts, results, start, stop, nan_error, finished, bad, positional) -> None:
    """The serial hot loop (no timeout): fill ``results[start:stop]``, append ``(i, error, traceback)`` to ``bad``.

    On Ctrl-C the points already run are marked in ``finished`` before ``KeyboardInterrupt`` propagates.
    """
    n_bad = len(bad)
    out: list = []
    if positional and len(names) == 1:  # points are the values themselves
        call = functools.partial(map, functools.partial(func, **consts) if consts else func)
    elif positional:
        call = functools.partial(itertools.starmap, functools.partial(func, **consts) if consts else func)
    else:
        call = functools.partial(map, lambda p: func(**dict(zip(names, p, strict=True)), **consts))
    it = iter(points)
    try:
        while True:
            try:
                out.extend(call(it))  # a C loop; on an exception the points before it are already in ``out``
                break
            except (Exception, SystemExit) as exc:  # the failing point was consumed: record it and go on
                bad.append((start + len(out), f"{type(exc).__name__}: {exc}", _tasks.trace(exc, len(bad))))
                out.append(None)
    except KeyboardInterrupt:
        results[start : start + len(out)] = out
        finished[start : start + len(out)] = True
        raise
    results[start:stop] = out
    finished[start:stop] = True
    if nan_error:
        failed = {b[0] for b in bad[n_bad:]}
        for j in range(start, stop):
            if j not in failed and _tasks._nonfinite(results[j]):
                bad.append((j, f"{_tasks.NONFINITE}: {results[j]!r}", ""))


def sweep(
    func: Callable[..., Any],
    grid: Mapping[str, Any],
    *,
    executor: Any = "auto",
    chunksize: int | None = None,
    progress: bool | None = None,
    constants: Mapping[str, Any] | None = None,
    max_workers: int | None = None,
    timeout: float | None = None,
    nan: str = "keep",
) -> SweepResult:
    """Evaluate ``func(**point, **constants)`` on the Cartesian product of ``grid``.

    Parameters
    ----------
    func : callable
        Called with keyword arguments named like the grid axes (plus ``constants``).
    grid : mapping of str -> 1-D array_like
        The axes; the result has shape ``tuple(len(axis) for axis in grid.values())``.
    executor : "auto", "serial", "processes", Executor, distributed.Client or str
        ``"auto"`` (or ``None``) runs a first chunk serially, measures its cost per point and sends the rest to a
        process pool only when the grid has at least ``PROCESS_THRESHOLD`` points, the serial estimate for the
        rest exceeds ``AUTO_PARALLEL_SECONDS``, there is more than one CPU and ``func`` pickles; the choice and
        the measurement are in ``SweepResult.executor_note``.  A string containing ``"://"`` or ``":"`` is a Dask
        scheduler address; a ``distributed.Client`` is used as is (not closed).
    chunksize : int, optional
        Points per task (default: about 4 chunks per worker; serially, chunks of ~1 % for the progress bar).
    progress : bool, optional
        Progress bar (tqdm when installed -- terminals and Jupyter -- else text on stderr); default: only when
        stderr is a terminal.
    constants : mapping, optional
        Extra keyword arguments passed unchanged to every call.
    max_workers : int, optional
        Size of the process pool for ``"processes"`` (and ``"auto"``).
    timeout : float, optional
        Seconds allowed per point; a point that runs longer is reported as a failure (``TimeoutError``).  Needs a
        POSIX timer in the process running the point: ``"serial"`` (main thread), ``"processes"`` and ``"auto"``.
    nan : {"keep", "error"}
        ``"keep"``: NaN/inf results are values; ``"error"``: such points are reported as failures.

    Returns
    -------
    SweepResult
        A point whose call raises (or exits through ``SystemExit``) is a failure with its parameters; Ctrl-C
        (``KeyboardInterrupt``) stops the sweep and returns the finished points with ``interrupted=True``.

    Raises
    ------
    ParameterError
        Bad grid, chunksize, max_workers, timeout or nan; an executor name that is not one of "auto", "serial",
        "processes" (nor an address); an unpicklable ``func`` for a parallel executor.

    See Also
    --------
    SweepResult.to_xarray, SweepResult.to_pandas

    Examples
    --------
    >>> import math
    >>> res = sweep(lambda x, y: math.hypot(x, y), {"x": [3.0, 5.0], "y": [4.0, 12.0]}, executor="serial")
    >>> res.values.tolist()
    [[5.0, 12.36931687685298], [6.4031242374328485, 13.0]]
    >>> res = sweep(lambda x: math.log(x), {"x": [1.0, -1.0]}, executor="serial")
    >>> res.values.tolist(), res.failures[0].params, res.failures[0].error
    ([0.0, nan], {'x': -1.0}, 'ValueError: math domain error')
    >>> sweep(lambda x: [x, math.inf] if x else [x, 1.0], {"x": [0.0, 2.0]}, nan="error").failures[0].error
    'non-finite result: [2.0, inf]'
    """
    if not callable(func):
        raise ParameterError(f"func must be callable, got {func!r}")
    axes = _axes(grid)
    names = tuple(axes)
    shape = tuple(a.size for a in axes.values())
    axes_lists = tuple(a.tolist() for a in axes.values())
    total = math.prod(shape)
    consts = dict(constants or {})
    if progress is None:
        progress = bool(getattr(sys.stderr, "isatty", lambda: False)())
    if chunksize is not None and (isinstance(chunksize, bool) or int(chunksize) != chunksize or chunksize < 1):
        raise ParameterError(f"chunksize must be a positive integer, got {chunksize!r}")
    if max_workers is not None and (
        isinstance(max_workers, bool) or int(max_workers) != max_workers or max_workers < 1
    ):
        raise ParameterError(f"max_workers must be a positive integer, got {max_workers!r}")
    try:
        check_choice("nan", nan, ("keep", "error"))
    except ParameterError as exc:
        raise ParameterError(f"nan must be 'keep' or 'error': {exc}") from None
    if timeout is not None:
        if isinstance(timeout, bool) or not isinstance(timeout, int | float) or not (0 < timeout < math.inf):
            raise ParameterError(f"timeout must be a positive number of seconds, got {timeout!r}")
        timeout = float(timeout)
    kind, client, own_client = _resolve_executor(executor, func)
    ncpu = (os.cpu_count() or 1) if kind != "serial" else 1
    if timeout is not None and kind not in ("auto", "serial", "processes"):
        raise ParameterError(
            "timeout= needs executor 'serial', 'processes' or 'auto' (a per-point timer in the worker process); "
            f"got {kind!r}: bound the run time inside func instead"
        )
    if timeout is not None and kind in ("auto", "serial") and not _tasks.timer_available():
        raise ParameterError("timeout= with a serial sweep needs a POSIX system and the main thread")
    workers = int(max_workers or (ncpu if kind in ("processes", "auto") else 1))
    if kind == "dask":
        workers = max(1, len(client.scheduler_info().get("workers", {})) or 1)
    elif kind == "executor":
        workers = max(1, getattr(client, "_max_workers", 1) or 1)

    state = _State(total, shape, names, axes_lists, progress)
    note = ""
    try:
        try:
            if kind in ("auto", "serial"):
                first = min(total, int(chunksize) if chunksize else max(1, min(64, total)))
                t0 = time.perf_counter()
                state.run_serial(func, consts, 0, first, timeout, nan)
                per_point = (time.perf_counter() - t0) / first
                start = first
                if kind == "auto":
                    kind, note = _auto_choice(func, total, first, per_point, ncpu, workers)
                    state.bar.note(kind)
                if kind == "serial":
                    step = int(chunksize) if chunksize else (max(1, math.ceil(total / 100)) if progress else total)
                    while start < total:
                        stop = min(total, start + step)
                        state.run_serial(func, consts, start, stop, timeout, nan)
                        start = stop
            else:
                start = 0
            if kind != "serial" and start < total:
                size = int(chunksize) if chunksize else max(1, math.ceil((total - start) / (4 * workers)))
                tasks = [
                    _tasks.Task(func, names, axes_lists, consts, a, min(total, a + size), timeout, nan)
                    for a in range(start, total, size)
                ]
                state.run_parallel(kind, client, tasks, workers)
        except KeyboardInterrupt:
            state.interrupted = True
    finally:
        state.bar.close()
        if own_client:
            client.close()
    label = type(client).__name__ if kind == "executor" else kind
    return state.result(axes, label, note)


def _auto_choice(func, total: int, done: int, per_point: float, ncpu: int, workers: int) -> tuple[str, str]:
    rest = (total - done) * per_point
    measured = f"first {done} points: {per_point * 1e6:.3g} us/point, serial estimate for the rest {rest:.3g} s"
    if total < PROCESS_THRESHOLD or ncpu < 2 or workers < 2:
        return "serial", f"auto -> serial ({measured}; fewer than {PROCESS_THRESHOLD} points or one CPU)"
    if rest < AUTO_PARALLEL_SECONDS:
        return "serial", f"auto -> serial ({measured} < {AUTO_PARALLEL_SECONDS} s)"
    if not _picklable(func):
        warn("sweep: func cannot be pickled; running serially", RuntimeWarning)
        return "serial", f"auto -> serial ({measured}; func cannot be pickled)"
    return "processes", f"auto -> processes ({measured} >= {AUTO_PARALLEL_SECONDS} s)"


class _State:
    """Results, failures and progress of one sweep."""

    def __init__(self, total, shape, names, axes_lists, progress):
        self.total, self.shape, self.names, self.axes_lists = total, shape, names, axes_lists
        self.results: list[Any] = [None] * total
        self.bad: list[tuple[int, str, str]] = []
        self.finished = np.zeros(total, dtype=bool) if total else np.zeros(0, dtype=bool)
        self.interrupted = False
        self.bar = _tasks.Progress(total, progress)
        self._points = itertools.product(*axes_lists)  # serial chunks run in order and share this iterator
        self._next = 0
        self._call_style: dict[int, bool] = {}

    def _positional(self, func) -> bool:
        key = id(func)
        if key not in self._call_style:
            self._call_style[key] = _positional(func, self.names)
        return self._call_style[key]

    def run_serial(self, func, consts, start, stop, timeout, nan) -> None:
        if timeout is not None:
            task = _tasks.Task(func, self.names, self.axes_lists, consts, start, stop, timeout, nan)
            self.collect(start, _tasks.run_task(task))  # (updates the bar)
            return
        positional = self._positional(func)
        if len(self.names) == 1 and positional:
            points = self.axes_lists[0][start:stop]  # the values themselves
        else:
            if start != self._next:  # bring the shared product iterator to ``start`` (it only moves forward)
                for _ in itertools.islice(self._points, start - self._next):
                    pass
            points = itertools.islice(self._points, stop - start)
            self._next = stop
        _serial_plain(
            func,
            self.names,
            points,
            consts,
            self.results,
            start,
            stop,
            nan == "error",
            self.finished,
            self.bad,
            positional,
        )
        self.bar.update(stop - start)

    def collect(self, start: int, out: list) -> None:
        for j, (ok, val) in enumerate(out):
            i = start + j
            if ok:
                self.results[i] = val
            else:
                self.bad.append((i, val[0], val[1]))
        self.finished[start : start + len(out)] = True
        self.bar.update(len(out))

    def chunk_failed(self, task, exc: BaseException) -> None:
        msg = f"chunk failed: {type(exc).__name__}: {exc}"
        self.collect(task.start, [(False, (msg, _tasks.trace(exc, len(self.bad))))] * (task.stop - task.start))

    def run_parallel(self, kind, client, tasks, workers) -> None:
        if kind == "dask":
            futs = client.map(_tasks.run_task, tasks, pure=False)
            try:
                for task, fut in zip(tasks, futs, strict=True):
                    try:
                        self.collect(task.start, fut.result())
                    except Exception as exc:
                        self.chunk_failed(task, exc)
            except KeyboardInterrupt:
                client.cancel(futs)
                raise
            return
        if kind == "processes":
            from concurrent.futures import ProcessPoolExecutor

            pool = ProcessPoolExecutor(max_workers=workers)
        else:
            pool = client
        futs = []
        try:
            futs = [pool.submit(_tasks.run_task, task) for task in tasks]
            for task, fut in zip(tasks, futs, strict=True):
                try:
                    self.collect(task.start, fut.result())
                except Exception as exc:
                    self.chunk_failed(task, exc)
        except KeyboardInterrupt:
            for fut in futs:
                fut.cancel()
            if kind == "processes":
                pool.shutdown(wait=False, cancel_futures=True)
                kind = "done"
            raise
        finally:
            if kind == "processes":
                pool.shutdown()

    def result(self, axes, label: str, note: str) -> SweepResult:
        failed = {b[0] for b in self.bad}
        for i in np.nonzero(~self.finished)[0].tolist() if self.interrupted else ():
            self.results[i] = None
        if self.interrupted:
            for i in np.nonzero(~self.finished)[0].tolist():
                self.bad.append((i, "KeyboardInterrupt: not run", ""))
                failed.add(i)
        self.bad.sort(key=lambda b: b[0])
        failures = []
        if self.bad:
            flat = np.array([b[0] for b in self.bad])
            indices = np.array(np.unravel_index(flat, self.shape)).T.tolist() if self.shape else [[]] * len(flat)
            for (_, err, tb), idx in zip(self.bad, indices, strict=True):
                params = {n: self.axes_lists[k][j] for k, (n, j) in enumerate(zip(self.names, idx, strict=True))}
                failures.append(SweepFailure(index=tuple(idx), params=params, error=err, trace=tb))
        values = _pack(self.results, self.shape, failed)
        if failures and len(failures) == self.total and not self.interrupted:
            from .errors import SweepWarning

            warn(
                f"every one of the {self.total} points of the sweep failed; the first with {failures[0].error} "
                f"(at {failures[0].params}); see result.failures[0].traceback",
                SweepWarning,
            )
        return SweepResult(values, axes, failures, label, note, self.interrupted)


def _picklable(obj: Any) -> bool:
    try:
        pickle.dumps(obj)
    except Exception:
        return False
    return True


def _resolve_executor(executor: Any, func: Any) -> tuple[str, Any, bool]:
    if executor is None:
        executor = "auto"
    if isinstance(executor, str):
        if executor in ("auto", "serial"):
            return executor, None, False
        if executor == "processes":
            if not _picklable(func):
                raise ParameterError(
                    "executor='processes' needs a picklable func (a module-level function or functools.partial of "
                    "one, not a lambda or closure); use executor='serial' otherwise"
                )
            return "processes", None, False
        if ":" not in executor:
            close = difflib.get_close_matches(executor, _EXECUTOR_NAMES, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise ParameterError(
                f"executor={executor!r} is not one of {_EXECUTOR_NAMES}{hint}; a Dask scheduler address looks like "
                "'tcp://host:8786'"
            )
        try:
            from distributed import Client
        except ImportError:  # pragma: no cover - depends on the environment
            raise ParameterError(
                f"executor={executor!r} is a Dask scheduler address, but dask.distributed is not installed "
                "(pip install 'dask[distributed]')"
            ) from None
        return "dask", Client(executor), True
    if type(executor).__module__.split(".")[0] == "distributed":
        return "dask", executor, False
    if isinstance(executor, Executor):
        return "executor", executor, False
    raise ParameterError(
        f"executor must be 'auto', 'serial', 'processes', a concurrent.futures.Executor, a distributed.Client or a "
        f"scheduler address; got {executor!r}"
    )
