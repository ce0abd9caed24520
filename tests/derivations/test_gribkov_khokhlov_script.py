"""derivations/gribkov_khokhlov_2015.py reproduces the report's recomputed Table 1 numbers."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "derivations" / "gribkov_khokhlov_2015.py"


def _load():
    spec = importlib.util.spec_from_file_location("gk2015", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_table1_recomputed_values():
    """Seed report §4 [C]: 2.3276 Hz, 5.0460 Hz, ratio 0.2128 from Table 1 (the paper prints 2.289/5.094/0.2019)."""
    result = _load().table1_natural_frequencies()
    assert result["p1_hz"] == pytest.approx(2.3276, abs=1e-4)
    assert result["p2_hz"] == pytest.approx(5.0460, abs=1e-4)
    assert result["r"] == pytest.approx(0.2128, abs=1e-4)
