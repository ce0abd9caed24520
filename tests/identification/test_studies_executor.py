"""Error maps, Monte Carlo and noise studies run through symosc.sweep: the executor does not change the numbers,
counted failures stay counted, and an unexpected error in a user pipeline still stops the study."""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from symosc.errors import SymoscError
from symosc.identification import error_map, error_vs_noise, matrix_pencil, monte_carlo


def test_error_map_identical_serial_and_processes():
    kw = dict(dx=[-0.4, 0.3], dz=[0.0, 0.2], noise=[0.0, 0.06], runs=2, n_samples=200)
    serial = error_map(**kw, executor="serial")
    procs = error_map(**kw, executor="processes")
    assert np.array_equal(serial.errors, procs.errors, equal_nan=True)
    assert np.array_equal(serial.failures, procs.failures)
    # noiseless runs identify the exact model: errors at rounding level (an independent check of the plumbing)
    assert np.nanmax(serial.errors[0]) < 1e-6


def _pipe(y, dt):
    return {"w": matrix_pencil(y, dt, 1, constant=False).frequencies[0]}


def test_monte_carlo_and_error_vs_noise_identical_across_executors():
    t = np.arange(100) * 0.1
    y = np.cos(2.0 * t)
    with ThreadPoolExecutor(2) as pool:
        a = monte_carlo(matrix_pencil, y, 0.1, snr_db=30, runs=12, n_modes=1, constant=False, executor="serial")
        b = monte_carlo(matrix_pencil, y, 0.1, snr_db=30, runs=12, n_modes=1, constant=False, executor=pool)
        ev1 = error_vs_noise(_pipe, y, 0.1, {"w": 2.0}, [0.01, 0.1], runs=4, executor="serial")
        ev2 = error_vs_noise(_pipe, y, 0.1, {"w": 2.0}, [0.01, 0.1], runs=4, executor=pool)
    assert np.array_equal(a.frequencies, b.frequencies) and a.failures == b.failures == 0
    assert np.all(np.abs(a.frequencies - 2.0) < 1e-2)
    assert np.array_equal(ev1.errors, ev2.errors)


def _broken(y, dt):
    raise KeyError("bug in the user's pipeline")


def test_unexpected_error_in_a_pipeline_is_raised():
    t = np.arange(50) * 0.1
    with pytest.raises(SymoscError, match="KeyError"):
        error_vs_noise(_broken, np.cos(t), 0.1, {"w": 1.0}, [0.1], runs=2, executor="serial")
