"""The README's Python examples run as written."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

README = Path(__file__).resolve().parents[1] / "README.md"


def test_readme_python_blocks_run():
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(), flags=re.S)
    assert blocks, "README has no python examples"
    namespace: dict = {}
    for block in blocks:
        exec(compile(block, str(README), "exec"), namespace)
    # the first session computes the Table 1 pendulum: report §4 recomputed 2.3276 Hz, 5.0460 Hz
    np.testing.assert_allclose(namespace["omega"] / (2 * np.pi), [2.3276, 5.0460], atol=5e-4)
    # the comments in the tour state what the calls return; check the numeric ones independently
    np.testing.assert_allclose(namespace["estimate"].frequencies, [3.0, 7.0], rtol=1e-9)
    assert namespace["grid"].values.tolist() == [[0.0, 0.0], [0.0, 1.0], [0.0, 2.0]]
    sp = namespace["sp"]
    assert sp.simplify(namespace["vdp"].amplitude.coefficient(0) - 2) == 0


def test_quick_start_has_exactly_two_commands():
    text = README.read_text()
    quick = text.split("## Quick start", 1)[1].split("\n## ", 1)[0]
    commands = re.findall(r"```bash\n(.*?)```", quick, flags=re.S)
    assert len(commands) == 2
    # the main job runs a shipped scene (tests/scene and tests/test_cli.py check what it prints)
    assert commands[0].strip() == 'pip install ".[plot]" && symosc run examples/gribkov2015.toml'
    assert (README.parent / "examples" / "gribkov2015.toml").is_file()
    ci = (README.parent / ".ci" / "run").read_text()
    assert "python -m pytest -n 2" in commands[1] and "python -m pytest -n 2" in ci
