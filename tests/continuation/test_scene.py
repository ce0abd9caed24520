"""The scene question ``continuation`` and its example file: folds against shooting-independent references."""

from __future__ import annotations

from pathlib import Path

import pytest

from symosc.scene import SceneError, load, loads

ROOT = Path(__file__).resolve().parents[2]


def test_example_scene_finds_the_two_folds():
    result = load(ROOT / "examples" / "duffing_continuation.toml").run()
    data = result.to_json()["questions"][0]
    folds = sorted(b["parameter"] for b in data["bifurcations"] if b["kind"] == "fold")
    # the same folds by harmonic balance directly (tests/continuation/test_continuation.py checks them by shooting)
    assert folds == pytest.approx([1.2616102, 1.5555786], abs=1e-6)
    assert data["max_residual"] <= 1e-8


def test_van_der_pol_scene_in_eps():
    scene = loads(
        """
[system]
model = "van_der_pol"
[[questions]]
kind = "continuation"
range = [0.1, 0.5]
plot = "frequency"
points = 10
"""
    )
    data = scene.run().to_json()["questions"][0]
    assert data["parameter"] == "eps" and data["points"] >= 5 and data["bifurcations"] == []


def test_scene_errors_name_the_key():
    with pytest.raises(SceneError, match="range"):
        loads('[system]\nmodel = "van_der_pol"\n[[questions]]\nkind = "continuation"\n')
    with pytest.raises(SceneError, match="parameter"):
        loads(
            '[system]\nmodel = "duffing"\n[parameters]\nw0 = 1\nzeta = 0.05\nmu = 0.5\n[excitation]\namplitude = 0.3\n'
            '[[questions]]\nkind = "continuation"\nparameter = "nope"\nrange = [0.6, 2.0]\n'
        ).run()
