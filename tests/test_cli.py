"""The command line: every subcommand's output against an independent computation, and a bad-input case each."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg
import scipy.special

from symosc.cli import main

ROOT = Path(__file__).resolve().parents[1]
T1 = dict(m1=1.032e-3, m2=0.424e-3, l1=45.0e-3, lc1=24.917e-3, lc2=12.838e-3, I1=146.804e-9, I2=32.871e-9, g=9.81)


def _hand_frequencies_hz(v):
    """Double physical pendulum written out by hand (hanging): M q'' + g C q = 0."""
    M = np.array(
        [
            [v["I1"] + v["m1"] * v["lc1"] ** 2 + v["m2"] * v["l1"] ** 2, v["m2"] * v["l1"] * v["lc2"]],
            [v["m2"] * v["l1"] * v["lc2"], v["I2"] + v["m2"] * v["lc2"] ** 2],
        ]
    )
    C = np.diag([v["m1"] * v["lc1"] + v["m2"] * v["l1"], v["m2"] * v["lc2"]])
    return np.sqrt(scipy.linalg.eigh(v["g"] * C, M, eigvals_only=True)) / (2 * np.pi)


def _rows(out):
    return re.findall(r"^\s+(\d)\s+([\d.]+)\s+([\d.]+)\s", out, flags=re.M)


def test_double_pendulum_prints_frequencies_and_the_paper_comparison(capsys):
    """Table 1 pendulum (Gribkov & Khokhlov 2015, §4): 2.3276 Hz and 5.0460 Hz; the paper's 2.289 Hz explained."""
    assert main(["double-pendulum"]) == 0
    out = capsys.readouterr().out
    hz = np.array([float(r[2]) for r in _rows(out)])
    np.testing.assert_allclose(hz, _hand_frequencies_hz(T1), atol=1e-6)
    assert "r = (p1/p2)^2 = 0.2127" in out
    assert "2.289" in out and "lc2 = 15.16 mm" in out
    assert "derive the nonlinear equations" not in out and "linearize at q = 0" in out


@pytest.mark.parametrize(
    ("name", "value", "si"), [("I1", "1e-12", 1e-12), ("m1", "2 g", 2e-3), ("lc2", "15.16 mm", 15.16e-3)]
)
def test_set_overrides_change_the_result_like_the_hand_model(capsys, name, value, si):
    assert main(["double-pendulum", "--set", f"{name}={value}"]) == 0
    out = capsys.readouterr().out
    hz = np.array([float(r[2]) for r in _rows(out)])
    np.testing.assert_allclose(hz, _hand_frequencies_hz({**T1, name: si}), atol=1e-6)
    assert "source, Hz" not in out  # the paper comparison is dropped when the parameters differ from Table 1


@pytest.mark.parametrize(
    ("arg", "code", "words"),
    [
        ("foo=1", 2, "Valid names: I1, I2, g, l1, lc1, lc2, m1, m2"),
        ("l2=0.03", 2, "Did you mean 'lc2'?"),  # l2 does not enter the equations, so it is not a parameter
        ("m1=abc", 2, "'abc' is not a number"),
        ("m1", 2, "NAME=VALUE"),
        ("m1=-1", 1, "m1 must be positive"),
        ("m1=2 mm", 2, "expected a mass"),
    ],
)
def test_bad_set_is_a_one_line_error(capsys, arg, code, words):
    assert main(["double-pendulum", "--set", arg]) == code
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err
    assert len([line for line in err.splitlines() if not line.startswith("usage:")]) == 1


def test_traceback_flag_reraises_for_developers():
    from symosc.cli import _RangeError

    with pytest.raises(_RangeError):
        main(["double-pendulum", "--traceback", "--set", "m1=-1"])


def test_run_writes_report_json_and_figure(tmp_path, capsys):
    out = tmp_path / "rep"
    assert main(["run", str(ROOT / "examples" / "gribkov2015.toml"), "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert "stable amplitudes" in text and "STABLE" in text
    assert sorted(p.name for p in out.iterdir()) == ["gribkov2015-ince-strutt.png", "report.md", "results.json"]
    data = json.loads((out / "results.json").read_text())
    np.testing.assert_allclose(data["questions"][0]["frequency_hz"], _hand_frequencies_hz(T1), rtol=1e-9)


def test_run_json_and_html(tmp_path, capsys):
    scene = str(ROOT / "examples" / "double_pendulum_frequencies.toml")
    assert main(["run", scene, "--format", "json", "--no-files"]) == 0
    data = json.loads(capsys.readouterr().out)
    np.testing.assert_allclose(data["questions"][0]["frequency_hz"], _hand_frequencies_hz(T1), rtol=1e-9)
    assert [e["step"] for e in data["derivation_log"]][:2] == ["build the Lagrangian system", "linearize at q = 0"]
    assert main(["run", scene, "--format", "html", "-o", str(tmp_path)]) == 0
    assert "<table>" in (tmp_path / "report.html").read_text()


def test_run_missing_file_is_an_error(tmp_path, capsys):
    assert main(["run", str(tmp_path / "nope.toml"), "--no-files"]) == 1
    assert "nope.toml" in capsys.readouterr().err


def test_mathieu_against_scipy(capsys):
    assert main(["mathieu", "a", "1", "0.5", "2"]) == 0
    vals = [float(x) for x in re.findall(r"^\s+[\d.]+\s+([-\d.e+]+)\s", capsys.readouterr().out, flags=re.M)]
    np.testing.assert_allclose(vals, scipy.special.mathieu_a(1, [0.5, 2.0]), rtol=1e-9)
    assert main(["mathieu", "b", "2", "1"]) == 0
    vals = [float(x) for x in re.findall(r"^\s+[\d.]+\s+([-\d.e+]+)\s", capsys.readouterr().out, flags=re.M)]
    np.testing.assert_allclose(vals, scipy.special.mathieu_b(2, [1.0]), rtol=1e-9)


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["mathieu", "b", "0", "1"], "b_0 does not exist"),
        (["mathieu", "c", "0", "1"], "invalid choice"),
        (["mathieu", "a", "0", "x"], "invalid float"),
    ],
)
def test_mathieu_bad_input(capsys, argv, words):
    assert main(argv) == 2
    assert words in capsys.readouterr().err


def test_no_command_and_help(capsys):
    assert main([]) == 2
    for cmd in ("run", "double-pendulum", "stability", "mathieu", "series", "identify", "reproduce"):
        assert main([cmd, "--help"]) == 0
        assert f"symosc {cmd}" in capsys.readouterr().out
