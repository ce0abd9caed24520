"""derivations/bulgakov_dynamics.py: every printed symosc value equals the textbook closed form, typed here."""

from __future__ import annotations

import importlib.util
from functools import cache
from pathlib import Path

import sympy as sp

SCRIPT = Path(__file__).resolve().parents[2] / "derivations" / "bulgakov_dynamics.py"


@cache
def _load():
    spec = importlib.util.spec_from_file_location("bulgakov_dynamics", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_script_runs_and_writes_tables(tmp_path, capsys):
    mod = _load()
    assert mod.main(["--section", "3.7", "--section", "3.14", "--out", str(tmp_path)]) == 0
    text = (tmp_path / "tables.txt").read_text()
    assert "Gamma^r_phi,phi" in text and "omega*v" in text
    assert "symosc" in capsys.readouterr().out


def test_values_match_closed_forms():
    mod = _load()
    m, g, l, k, w, L, R, C, e, c, J = (mod.m, mod.g, mod.l, mod.k, mod.w, mod.L, mod.R, mod.C, mod.e, mod.c, mod.J)
    th, r, q, p, u, v, h, E = mod.th, mod.r, mod.q, mod.p, mod.u, mod.v, mod.h, mod.E
    from symosc import ddot, dot

    s33 = mod.section_3_3()
    assert sp.simplify(s33["kappa"] + m * (l * dot(th) ** 2 + g * sp.cos(th)) / (2 * l)) == 0
    assert sp.simplify(s33["reduced"] - (l * ddot(th) + g * sp.sin(th))) == 0
    s38 = mod.section_3_8()
    assert sp.expand(s38["voltage"] - (L * ddot(q) + R * dot(q) + q / C - e)) == 0
    assert sp.expand(s38["force"] - c * dot(q) ** 2 / 2) == 0
    s39 = mod.section_3_9()
    Rr = sp.Symbol("R", positive=True)
    assert s39["T1"] == 0
    assert sp.simplify(s39["T0"] - m * Rr**2 * w**2 * sp.sin(th) ** 2 / 2) == 0
    s310 = mod.section_3_10()
    assert sp.simplify(s310["omega2"] - g / (l * sp.cos(sp.pi / 4)) * (1 + 3 * sp.cos(sp.pi / 4) ** 2)) == 0
    s316 = mod.section_3_16()
    Lz = sp.Symbol("L_z", positive=True)
    assert s316["J_ho"] == h / w and s316["nu_ho"] == w
    assert sp.simplify(s316["J_kepler"] - (k * sp.sqrt(m / (-2 * E)) - Lz)) == 0
    assert sp.simplify(s316["T_kepler"] - 2 * sp.pi * k * sp.sqrt(m) / (-2 * E) ** sp.Rational(3, 2)) == 0
    factor, pth2, pr2, beta = s316["separation"]
    assert factor == 2 * m * r**2
    assert sp.expand(pth2 - (beta - 2 * m * c * sp.cos(th))) == 0
    assert sp.expand(pr2 - (2 * m * (h + k / r) - beta / r**2)) == 0
    s72 = mod.section_7_2()  # Bulgakov (1954), §8.52, Example 2: Delta = D - 3
    lam = sp.Symbol("lambda")
    assert s72["orders"] == (2, 1) and s72["sizes"] == (4, 3)
    assert sp.cancel(s72["char2"] / (lam - 3)) in (1, -1) and sp.cancel(s72["char1"] / (lam - 3)) in (1, -1)
    s7 = mod.section_7()
    assert s7["T"] == J / c
    assert sp.Symbol("lambda") not in s7["ratio"].free_symbols and s7["ratio"] != 0
    s314 = mod.section_3_14()
    assert s314["exchange"] == (p, -q) and s314["canonical"] is True
    assert s314["H_new"] == w * sp.Symbol("v", positive=True)
    assert u is not None and r is not None and v is not None
