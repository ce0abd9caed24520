"""The ``mathieu_functions`` scene question: values against 40-digit references, the figure, refusals.

References: tests/periodic/mathieu_reference.py (Sturm bisection + Thomas solve in mpmath, no symosc code).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from symosc.scene import loads
from symosc.scene._errors import SceneError

from . import mathieu_reference as ref

SCENE = """
title = "Mathieu functions"
source = "McLachlan (1947); DLMF 28.2"
[system]
model = "mathieu"
[[questions]]
kind = "mathieu_functions"
function = "se"
n = [1, 4]
q = [2.5]
x = [0.3, "90 deg"]
[[questions]]
kind = "mathieu_functions"
n = [0]
q = [10.0]
x = [1.0]
derivative = true
figure = false
"""


def test_values_coefficients_and_figure(tmp_path):
    """se_1, se_4 at q = 2.5 and ce_0' at q = 10 within 1e-13 of 40-digit references; b_n in the table; the figure
    of se_n over a period is written (ce_0's question asked for none)."""
    res = loads(SCENE, name="mathieu.toml").run()
    first, second = res.results
    x = np.array([0.3, math.pi / 2])
    for pair in first.data["pairs"]:
        co = ref.coefficients("b", pair["n"], 2.5)
        assert abs(pair["characteristic_value"] - float(co[2])) <= 1e-13 * abs(float(co[2]))
        np.testing.assert_allclose(pair["values"], ref.function("se", pair["n"], 2.5, x, False, co), rtol=0, atol=1e-13)
    (pair,) = second.data["pairs"]
    exact = ref.function("ce", 0, 10.0, np.array([1.0]), True, ref.coefficients("a", 0, 10.0))
    assert abs(pair["values"][0] - exact[0]) <= 1e-13
    res.write(tmp_path / "out")
    out = tmp_path / "out"
    assert [p.name for p in sorted(out.glob("*.png"))] == ["mathieu-se.png"]
    assert (out / "mathieu-se.png").stat().st_size > 10_000
    saved = json.loads((out / "results.json").read_text())
    assert "se_n(x, q)" in (out / "report.md").read_text()
    assert json.dumps(saved).count("characteristic_value") == 3


def test_refuses_se_0_and_missing_options():
    with pytest.raises(SceneError, match="needs the option 'q'"):
        loads(SCENE.replace("q = [2.5]\n", ""), name="m.toml")
    with pytest.raises(SceneError, match="se_0 does not exist"):
        loads(SCENE.replace("n = [1, 4]", "n = [0, 1]"), name="m.toml").run()
