"""A warning points at the user's line, whatever path inside symosc issued it: through a decorator, a deprecated
keyword's shim, another symosc function or a generated wrapper (Python's "once per location" filter and every
traceback-reading tool rely on it)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import sympy as sp

from symosc.errors import AccuracyWarning
from symosc.identification import era, error_vs_noise
from symosc.numeric import compile

DT = 0.9  # 3.5 samples per period of the 2 rad/s mode: ERA warns that the record may be under-sampled
SIGNAL = np.exp(-0.01 * np.arange(200) * DT) * np.cos(2.0 * np.arange(200) * DT)


def _caught(call) -> list[warnings.WarningMessage]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call()
    return caught


def test_a_warning_of_a_decorated_function_points_at_the_call():
    (w,) = _caught(lambda: era(SIGNAL, DT, 1, constant=False))
    assert w.category is AccuracyWarning and "under-sampled" in str(w.message)
    assert w.filename == __file__


def test_a_warning_raised_under_a_deprecated_keyword_points_at_the_call():
    caught = _caught(lambda: era(SIGNAL, DT, order=2, constant=False))  # order: the old name of n_poles
    accuracy = [w for w in caught if w.category is AccuracyWarning]
    assert len(accuracy) == 1 and accuracy[0].filename == __file__


def test_a_warning_from_a_nested_symosc_call_points_at_the_outer_call():
    def pipeline(sig, dt):
        return {"w": float(era(sig, dt, 1, constant=False).frequencies[0])}

    caught = _caught(lambda: error_vs_noise(pipeline, SIGNAL, DT, {"w": 2.0}, [1e-6], reference=1.0, runs=1))
    accuracy = [w for w in caught if w.category is AccuracyWarning]
    # the user's pipeline calls era: its line is the first one outside symosc
    assert accuracy and all(w.filename == __file__ for w in accuracy)
    assert {w.lineno for w in accuracy} == {pipeline.__code__.co_firstlineno + 1}


@pytest.mark.parametrize("backend", ["numpy", "c"])
def test_a_warning_of_a_compiled_function_points_at_the_call(backend):
    x = sp.Symbol("x", real=True)
    f = compile(1 / x, [x], backend=backend)
    (w,) = _caught(lambda: f(0.0))
    assert w.category is RuntimeWarning and "non-finite" in str(w.message)
    assert w.filename == __file__
