"""docs/scenes.md: its scene file is valid and its Python block runs as written."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from symosc.scene import loads

ROOT = Path(__file__).resolve().parents[2]
DOC = (ROOT / "docs" / "scenes.md").read_text()


def test_docs_scene_is_the_gribkov_example():
    (block,) = re.findall(r"```toml\n(.*?)```", DOC, flags=re.S)
    res = loads(block, name="docs/scenes.md").run()
    ref = loads((ROOT / "examples" / "gribkov2015.toml").read_text()).run()
    assert res["stability_region"].data["stable"] is True
    np.testing.assert_allclose(
        res["stability_region"].data["amplitude_min"], ref["stability_region"].data["amplitude_min"]
    )


def test_docs_python_block_runs(monkeypatch, capsys):
    monkeypatch.chdir(ROOT)
    (block,) = re.findall(r"```python\n(.*?)```", DOC, flags=re.S)
    ns: dict = {}
    exec(compile(block, "docs/scenes.md", "exec"), ns)
    np.testing.assert_allclose(ns["result"]["natural_frequencies"].data["frequency_hz"], [2.3276, 5.0460], atol=5e-5)
    assert "Derivation log" in capsys.readouterr().out
