"""derivations/bulgakov_networks.py runs and reproduces Bulgakov (1954) §8.31-8.49, ch. 9 B-D examples.

Independent references: a plain numpy ABCD cascade for T10, closed forms for T11 and E18.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np

SCRIPT = Path(__file__).resolve().parents[2] / "derivations" / "bulgakov_networks.py"


def _load():
    spec = importlib.util.spec_from_file_location("bulgakov_networks", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _t10_numpy(x):
    """Four T sections (series L, shunt 2C, series L), L = 1/(2 pi), C = 1e-6/(2 pi), Rg = 1500, Rl = 500."""
    L, C = 1 / (2 * np.pi), 1e-6 / (2 * np.pi)
    s = 2j * np.pi * 1000 * x
    za, zb = s * L, 1 / (2 * C * s)
    T = np.array([[1 + za / zb, 2 * za + za * za / zb], [1 / zb, 1 + za / zb]])
    A = np.linalg.matrix_power(T, 4)
    a12 = A[0, 0] * 500 + A[0, 1] + 1500 * (A[1, 0] * 500 + A[1, 1])
    return abs(a12) ** 2 / (4 * 1500 * 500)


def test_script_runs_and_reproduces(tmp_path, capsys):
    mod = _load()
    assert mod.main(["--out", str(tmp_path)]) == 0
    text = capsys.readouterr().out
    assert "quantity | book" in text.replace("  ", " ").replace("  ", " ") or "quantity" in text
    assert (tmp_path / "absorber.png").stat().st_size > 1000
    values = mod.t10()
    for x, v in values.items():
        assert abs(float(v) / _t10_numpy(x) - 1) < 1e-9
    pad = mod.t11()["pad"]
    assert abs(float(pad.Ra) - np.sqrt(1500 * 1000)) < 1e-9 and abs(float(pad.loss) - np.arccosh(np.sqrt(3))) < 1e-12
    g = mod.e18()["g"]
    assert abs(complex(g) - 2j * np.arctan(0.8)) < 1e-12
    # §9.40: the book's list of links with a bridged-T form; (9.250) and (8.427) against direct computations
    assert mod.correcting()["convertible"] == ["I", "II", "IV", "VII", "VIII"]
    energy = mod.energy()
    assert energy["slope"] == energy["energy"]
    junction = mod.junctions()
    assert abs(junction["direct"] - junction["formula"]) < 1e-12 * abs(junction["direct"])
