"""Tests of symosc.sweep: grid shape and order, executors agree, failures are reported, bad input."""

from __future__ import annotations

import functools
import math
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest
import sympy as sp

import symosc
from symosc.errors import ParameterError
from symosc.sweep import SweepResult, sweep


def _noisy_mean(seed, scale):
    """Deterministic per point: depends only on the arguments (Monte Carlo style)."""
    rng = np.random.default_rng(int(seed))
    return float(scale * rng.standard_normal(50).mean())


def _fragile(a, b):
    if a == 2 and b < 0:
        raise ValueError(f"bad point a={a}, b={b}")
    return a * 10 + b


def _vector(x, n=3):
    return np.arange(n) * x


def _mixed(x):
    return {"x": x} if x > 1 else x


def test_lazy_attribute_and_grid_shape_and_order():
    # symosc.sweep is callable whether the lazy attribute or the submodule is bound
    assert symosc.sweep(_vector, {"x": [2.0]}, executor="serial").values.tolist() == [[0.0, 2.0, 4.0]]
    res = sweep(
        lambda a, b, c: a * 100 + b * 10 + c, {"a": [1, 2], "b": [0, 1, 2], "c": np.arange(4)}, executor="serial"
    )
    assert isinstance(res, SweepResult)
    assert res.values.shape == (2, 3, 4) == res.shape
    assert res.values.dtype == float
    a, b, c = np.meshgrid([1, 2], [0, 1, 2], np.arange(4), indexing="ij")
    np.testing.assert_array_equal(res.values, a * 100 + b * 10 + c)
    assert res.points()[5] == {"a": 1, "b": 1, "c": 1}
    assert res.ok.all() and not res.failures


def test_failing_point_is_reported_not_fatal():
    res = sweep(_fragile, {"a": [1, 2, 3], "b": [-1, 1]}, executor="serial", chunksize=2)
    assert len(res.failures) == 1
    f = res.failures[0]
    assert f.index == (1, 0) and f.params == {"a": 2, "b": -1}
    assert "ValueError" in f.error and "bad point a=2" in f.error and "Traceback" in f.traceback
    assert np.isnan(res.values[1, 0])
    assert res.values[2, 1] == 31.0
    assert res.ok.tolist() == [[True, True], [False, True], [True, True]]


def test_array_and_object_results():
    res = sweep(_vector, {"x": [1.0, 2.0]}, executor="serial")
    assert res.values.shape == (2, 3)
    np.testing.assert_array_equal(res.values, [[0, 1, 2], [0, 2, 4]])
    res = sweep(_mixed, {"x": [1.0, 2.0]}, executor="serial")
    assert res.values.dtype == object and res.values[1] == {"x": 2.0}
    res = sweep(_vector, {"x": [1.0]}, executor="serial", constants={"n": 2})
    assert res.values.tolist() == [[0.0, 1.0]]


def test_serial_processes_and_dask_agree():
    """Serial, process pool, a user executor and a 2-worker Dask LocalCluster give identical results."""
    distributed = pytest.importorskip("distributed")
    grid = {"seed": np.arange(40), "scale": [0.5, 2.0]}
    ref = sweep(_noisy_mean, grid, executor="serial")
    procs = sweep(_noisy_mean, grid, executor="processes", chunksize=7, max_workers=2)
    with ThreadPoolExecutor(2) as pool:
        threads = sweep(_noisy_mean, grid, executor=pool, chunksize=5)
    with (
        distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as cl,
        distributed.Client(cl) as client,
    ):
        dask = sweep(_noisy_mean, grid, executor=client, chunksize=9)
        failing = sweep(_fragile, {"a": [1, 2], "b": [-1, 1]}, executor=client)
        by_address = sweep(_noisy_mean, grid, executor=cl.scheduler_address)
    np.testing.assert_array_equal(by_address.values, ref.values)
    for other in (procs, threads, dask):
        np.testing.assert_array_equal(other.values, ref.values)
        assert other.values.shape == (40, 2)
    assert procs.executor == "processes" and dask.executor == "dask" and threads.executor == "ThreadPoolExecutor"
    assert [f.params for f in failing.failures] == [{"a": 2, "b": -1}]
    procs_fail = sweep(_fragile, {"a": [1, 2], "b": [-1, 1]}, executor="processes", max_workers=2)
    assert [f.index for f in procs_fail.failures] == [(1, 0)]


def test_default_executor_small_grid_is_serial_and_progress(capsys):
    res = sweep(functools.partial(_fragile, b=1), {"a": [1, 2, 3]}, progress=True)
    assert res.executor == "serial"
    assert res.values.tolist() == [11.0, 21.0, 31.0]
    err = capsys.readouterr().err
    assert "3/3" in err  # tqdm's bar (or the text bar without tqdm)
    assert res.executor_note.startswith("auto -> serial")


def _slow_square(x):
    import time

    time.sleep(0.002)
    return x * x


def test_auto_measures_a_first_chunk_and_decides(monkeypatch):
    """Cheap points stay serial; points whose measured cost makes the rest long go to processes (or serial when
    func cannot be pickled, with a warning)."""
    sw = sys.modules["symosc.sweep"]

    res = sweep(lambda x: x + 1, {"x": np.arange(300)})
    assert res.executor == "serial" and res.values[-1] == 300
    assert "us/point" in res.executor_note
    monkeypatch.setattr(sw, "AUTO_PARALLEL_SECONDS", 0.05)
    monkeypatch.setattr(sw.os, "cpu_count", lambda: 2)
    res = sweep(_slow_square, {"x": np.arange(300.0)}, max_workers=2)
    assert res.executor == "processes" and "auto -> processes" in res.executor_note
    assert res.values.tolist() == [v * v for v in range(300)]
    with pytest.warns(RuntimeWarning, match="cannot be pickled"):
        res = sweep(lambda x: _slow_square(x) + 1, {"x": np.arange(300.0)})
    assert res.executor == "serial" and res.values[-1] == 299.0**2 + 1


def test_bad_input():
    with pytest.raises(ParameterError, match="non-empty mapping"):
        sweep(math.sqrt, {})
    with pytest.raises(ParameterError, match="1-D"):
        sweep(math.sqrt, {"x": np.ones((2, 2))})
    with pytest.raises(ParameterError, match="argument names"):
        sweep(math.sqrt, {"not a name": [1]})
    with pytest.raises(ParameterError, match="callable"):
        sweep(3, {"x": [1]})
    with pytest.raises(ParameterError, match="picklable"):
        sweep(lambda x: x, {"x": [1]}, executor="processes")
    with pytest.raises(ParameterError, match="chunksize"):
        sweep(_vector, {"x": [1]}, chunksize=0)
    with pytest.raises(ParameterError, match="max_workers"):
        sweep(_vector, {"x": [1]}, executor="processes", max_workers=0)
    with pytest.raises(ParameterError, match="executor must be"):
        sweep(_vector, {"x": [1]}, executor=42)
    with pytest.raises(ParameterError, match=r"'auto', 'serial', 'processes'\) \(did you mean 'processes'"):
        sweep(_vector, {"x": [1]}, executor="proceses")
    with pytest.raises(ParameterError, match="nan must be"):
        sweep(_vector, {"x": [1]}, nan="drop")
    with pytest.raises(ParameterError, match="timeout must be"):
        sweep(_vector, {"x": [1]}, timeout=-1)
    with ThreadPoolExecutor(1) as pool, pytest.raises(ParameterError, match="timeout= needs"):
        sweep(_vector, {"x": [1]}, executor=pool, timeout=1.0)


def _unpicklable_result(x):
    return lambda: x  # cannot be sent back from a worker process


def test_chunk_that_cannot_return_is_reported():
    res = sweep(_unpicklable_result, {"x": [1, 2]}, executor="processes", chunksize=1, max_workers=1)
    assert len(res.failures) == 2 and "chunk failed" in res.failures[0].error
    assert res.values.tolist() == [None, None]


def _exits(x):
    if x == 2:
        raise SystemExit(3)
    return x


def _nan_at(x):
    return math.nan if x == 1 else (math.inf if x == 2 else float(x))


def _sleepy(x):
    import time

    time.sleep(5.0 if x == 1 else 0.0)
    return x


@pytest.mark.parametrize("executor", ["serial", "processes"])
def test_system_exit_nan_and_timeout_are_failures_of_their_point(executor):
    kw = {"executor": executor, "max_workers": 2} if executor == "processes" else {"executor": executor}
    res = sweep(_exits, {"x": [1, 2, 3]}, **kw)
    assert res.values[0] == 1.0 and res.values[2] == 3.0 and np.isnan(res.values[1])
    assert [(f.params, f.error) for f in res.failures] == [({"x": 2}, "SystemExit: 3")]
    kept = sweep(_nan_at, {"x": [0, 1, 2]}, **kw)
    assert kept.failures == [] and np.isnan(kept.values[1]) and np.isinf(kept.values[2])
    err = sweep(_nan_at, {"x": [0, 1, 2]}, nan="error", **kw)
    assert [f.index for f in err.failures] == [(1,), (2,)]
    assert err.failures[0].error.startswith("non-finite result")
    timed = sweep(_sleepy, {"x": [0, 1, 2]}, timeout=0.2, **kw)
    assert [(f.params, f.error.split(":")[0]) for f in timed.failures] == [({"x": 1}, "TimeoutError")]
    assert timed.values[0] == 0 and timed.values[2] == 2


def _interrupt_at_5(x):
    if x == 5:
        raise KeyboardInterrupt
    return x


def test_ctrl_c_stops_cleanly_keeping_finished_points():
    res = sweep(_interrupt_at_5, {"x": np.arange(10)}, executor="serial", chunksize=3)
    assert res.interrupted
    assert res.values[:5].tolist() == [0.0, 1.0, 2.0, 3.0, 4.0]
    assert np.isnan(res.values[5:]).all()
    assert [f.index[0] for f in res.failures] == [5, 6, 7, 8, 9]
    assert res.failures[0].error == "KeyboardInterrupt: not run"


def test_labelled_results_and_pickle():
    import pickle

    res = sweep(_fragile, {"a": [1, 2, 3], "b": [-1, 1]}, executor="serial")
    da = res.to_xarray()
    assert da.dims == ("a", "b")
    assert float(da.sel(a=3, b=-1)) == 29.0 and np.isnan(float(da.sel(a=2, b=-1)))
    series = res.to_pandas()
    assert list(series.index.names) == ["a", "b"] and series.loc[(3, 1)] == 31.0
    vec = sweep(_vector, {"x": [1.0, 2.0]}, executor="serial").to_xarray()
    assert vec.dims == ("x", "component") and vec.sel(x=2.0).values.tolist() == [0.0, 2.0, 4.0]
    back = pickle.loads(pickle.dumps(res))
    assert np.array_equal(back.values, res.values, equal_nan=True)
    assert back.failures == res.failures and back.grid.keys() == res.grid.keys()


def test_dict_results_become_a_dataset_with_named_vector_axes():
    res = sweep(lambda x: {"energy": x**2, "state": [x, -x]}, {"x": [1.0, 2.0, 3.0]}, executor="serial")
    ds = res.to_xarray(dims="coordinate")
    assert set(ds.data_vars) == {"energy", "state"}
    assert ds["energy"].sel(x=3.0).item() == 9.0 and ds["state"].dims == ("x", "coordinate")
    assert ds["state"].sel(x=2.0).values.tolist() == [2.0, -2.0]
    with pytest.raises(ParameterError, match="dims must name"):
        res.to_xarray(dims=("a", "b"))


@pytest.mark.parametrize(
    "bad",
    [[1.0, float("nan")], {"a": (1.0, float("inf"))}, complex(float("nan"), 0.0), sp.nan, sp.zoo, [sp.oo],
     np.array([1.0, None, np.inf], dtype=object), sp.Matrix([[1, sp.nan]])],
)  # fmt: skip
def test_nan_error_sees_non_finite_values_anywhere(bad):
    res = sweep(lambda x: bad if x > 1 else 1.0, {"x": [1.0, 2.0]}, executor="serial", nan="error")
    assert [f.index for f in res.failures] == [(1,)] and res.failures[0].error.startswith("non-finite result")


def test_a_timeout_is_not_swallowed_and_the_callers_timer_is_restored():
    import signal
    import time

    def stubborn(x):
        try:
            end = time.monotonic() + 2.0
            while time.monotonic() < end:
                pass
        except Exception:  # a function that would hide an ordinary exception
            return -1.0
        return 1.0

    signal.setitimer(signal.ITIMER_REAL, 50.0)
    try:
        res = sweep(stubborn, {"x": [1.0]}, executor="serial", timeout=0.2)
        remaining = signal.getitimer(signal.ITIMER_REAL)[0]
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
    assert res.failures and res.failures[0].error.startswith("TimeoutError")
    assert 40.0 < remaining <= 50.0  # the caller's own timer still runs


def test_a_sweep_in_which_every_point_fails_warns_and_keeps_few_tracebacks():
    from symosc.errors import SweepWarning

    with pytest.warns(SweepWarning, match="every one of the 50 points"):
        res = sweep(lambda x: 1 / 0, {"x": np.arange(50.0)}, executor="serial")
    assert "ZeroDivisionError" in res.failures[0].traceback and "Traceback" in res.failures[0].traceback
    assert "not kept" in res.failures[-1].traceback and res.failures[-1].error.startswith("ZeroDivisionError")
