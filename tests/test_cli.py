"""The README's main job: ``symosc double-pendulum``."""

from __future__ import annotations

import re

import numpy as np

from symosc.cli import main


def test_double_pendulum_prints_frequencies_and_modes(capsys):
    """Table 1 pendulum (Gribkov & Khokhlov 2015, §4): the report recomputed 2.3276 Hz and 5.0460 Hz."""
    assert main(["double-pendulum"]) == 0
    out = capsys.readouterr().out
    rows = re.findall(r"^\s+(\d)\s+([\d.]+)\s+([\d.]+)\s+\(([^)]*)\)", out, flags=re.M)
    assert [r[0] for r in rows] == ["1", "2"]
    hz = np.array([float(r[2]) for r in rows])
    np.testing.assert_allclose(hz, [2.3276, 5.0460], atol=5e-4)
    assert "r = (p1/p2)^2 = 0.2127" in out


def test_override_parameter(capsys):
    """A point-mass-like override changes the result the way the closed form says."""
    assert main(["double-pendulum", "--set", "I1=1e-12", "--set", "I2=1e-12"]) == 0
    assert "2.3276" not in capsys.readouterr().out


def test_no_command_is_an_error(capsys):
    assert main([]) == 2
