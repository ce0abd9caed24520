"""save/load of derived models: the pickle reloads an equal model, the JSON summary rebuilds the equations."""

from __future__ import annotations

import json

import numpy as np
import pytest
import sympy as sp

import symosc
from symosc.errors import ParameterError


def test_linear_model_round_trip(tmp_path):
    from symosc.models import n_link_pendulum

    lin = n_link_pendulum(2).linearize()
    pkl, js = symosc.save(lin, tmp_path / "double")
    assert pkl.name == "double.pkl" and js.name == "double.json"
    back = symosc.load(tmp_path / "double.pkl")
    assert back.M == lin.M and back.K == lin.K
    values = {"m1": 1.0, "m2": 2.0, "l1": 1.0, "l2": 0.5, "g": 9.81}
    np.testing.assert_allclose(back.natural_frequencies(values), lin.natural_frequencies(values), rtol=1e-14)
    info = symosc.io.load_summary(js)
    assert info["symbolic"]["M"] == lin.M and info["symbolic"]["K"] == lin.K
    raw = json.loads(js.read_text())
    assert raw["class"].endswith("LinearModel") and raw["symosc_version"] == symosc.__version__
    assert sp.sympify(raw["symbolic"]["K"]) == lin.K  # plain srepr, readable without symosc


def test_result_round_trip(tmp_path):
    from symosc.nonlinear import limit_cycle

    x, v = sp.symbols("x v")
    lc = limit_cycle((1 - x**2) * v, 4)
    symosc.save(lc, tmp_path / "vdp.json")  # suffix replaced
    back = symosc.load(tmp_path / "vdp")
    assert sp.sympify(back.frequency) == sp.sympify(lc.frequency)
    assert back.eps_symbol == lc.eps_symbol


def test_errors_name_the_problem(tmp_path):
    with pytest.raises(ParameterError, match="no saved object"):
        symosc.load(tmp_path / "missing")
    with pytest.raises(ParameterError, match="does not pickle"):
        symosc.save(lambda q: q, tmp_path / "f")
