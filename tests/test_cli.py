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
    assert sorted(p.name for p in out.iterdir()) == [
        ".symosc-output",
        "gribkov2015-ince-strutt.png",
        "gribkov2015-motion-3.gif",  # the two time_response questions: animation and time series
        "gribkov2015-motion-3.png",
        "gribkov2015-motion-4.gif",
        "gribkov2015-motion-4.png",
        "report.md",
        "results.json",
        "timings.json",
    ]
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


def test_stability_interval_against_scipy_mathieu(tmp_path, capsys):
    """One inverted point pendulum, l = 0.2 m, pivot at 50 Hz: the interval ends solve a_0(q) = a1 and b_1(q) = a1."""
    from scipy.optimize import brentq

    png = tmp_path / "fig" / "st.png"
    argv = ["stability", "1", "--links", "point", "--set", "l1=200 mm", "--frequency", "50 Hz", "--plot", str(png)]
    assert main(argv) == 0
    out = capsys.readouterr().out
    lo, hi = (float(x) for x in re.search(r"stable amplitudes\s+([\d.]+) mm < a < ([\d.]+) mm", out).groups())
    l, g, p = 0.2, 9.81, 2 * np.pi * 50
    a1 = -4 * g / l / p**2
    q_lo = brentq(lambda q: scipy.special.mathieu_a(0, q) - a1, 1e-6, 5)
    q_hi = brentq(lambda q: scipy.special.mathieu_b(1, q) - a1, 1e-6, 5)
    np.testing.assert_allclose([lo, hi], [q_lo * l / 2 * 1e3, q_hi * l / 2 * 1e3], rtol=1e-5)
    assert png.read_bytes()[:4] == b"\x89PNG"


@pytest.mark.parametrize(
    ("argv", "code", "words"),
    [
        (["stability", "2", "--set", "l2=1"], 2, "Valid names: m1, m2, l1, lc1, lc2, I1, I2, g"),
        (["stability", "0"], 2, "N must be a positive integer"),
        (["stability", "1", "--frequency", "50 mm"], 2, "expected an angular frequency"),
    ],
)
def test_stability_bad_input(capsys, argv, code, words):
    assert main(argv) == code
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err


def test_series_vdp_against_the_known_coefficients(capsys):
    """Van der Pol: amplitude 2 + eps^2/96 - 1033 eps^4/552960, omega = 1 - eps^2/16 + 17 eps^4/3072 (Bulgakov §8,
    and the classic expansions of Andersen & Geer 1982)."""
    assert main(["series", "vdp", "--order", "4"]) == 0
    out = capsys.readouterr().out
    import sympy as sp

    eps = sp.Symbol("eps")
    amp = sp.sympify(re.search(r"x\(0\) = (.*)", out).group(1))
    om = sp.sympify(re.search(r"omega = (.*)", out).group(1))
    assert sp.expand(amp - (2 + eps**2 / 96 - sp.Rational(1033, 552960) * eps**4)) == 0
    assert sp.expand(om - (1 - eps**2 / 16 + sp.Rational(17, 3072) * eps**4)) == 0


def test_series_bad_order(capsys):
    assert main(["series", "vdp", "--order", "0"]) == 2
    assert main(["series", "duffing", "--order", "2"]) == 2
    assert "invalid choice" in capsys.readouterr().err


def test_identify_synthetic_record(tmp_path, capsys):
    """Two damped tones of known frequency and decay, written as CSV: the estimate recovers them."""
    dt = 0.01
    t = np.arange(600) * dt
    y1 = np.exp(-0.2 * t) * np.cos(2 * np.pi * 1.5 * t) + 0.5 * np.exp(-0.5 * t) * np.sin(2 * np.pi * 4.0 * t)
    y2 = 0.3 * np.exp(-0.2 * t) * np.cos(2 * np.pi * 1.5 * t + 1) - np.exp(-0.5 * t) * np.sin(2 * np.pi * 4.0 * t)
    path = tmp_path / "rec.csv"
    np.savetxt(path, np.c_[y1, y2], delimiter=",", header="a,b", comments="")
    assert main(["identify", str(path), "--dt", str(dt), "--modes", "2"]) == 0
    rows = re.findall(r"^\s+(\d)\s+([\d.]+)\s+([\d.]+)\s+([-\d.e+]+)", capsys.readouterr().out, flags=re.M)
    w = np.hypot(2 * np.pi * np.array([1.5, 4.0]), [0.2, 0.5])  # undamped |lambda|
    np.testing.assert_allclose([float(r[1]) for r in rows], w, rtol=2e-7)  # printed to 8 digits
    np.testing.assert_allclose([float(r[3]) for r in rows], np.array([0.2, 0.5]) / w, rtol=1e-3)


def test_identify_bad_input(tmp_path, capsys):
    assert main(["identify", str(tmp_path / "none.csv"), "--modes", "2"]) == 1
    path = tmp_path / "rec.csv"
    np.savetxt(path, np.ones((20, 2)), delimiter=",", header="a,b", comments="")
    assert main(["identify", str(path), "--modes", "2"]) == 1  # no 't' column and no --dt
    err = capsys.readouterr().err
    assert "none.csv" in err and "dt" in err and "Traceback" not in err


def test_reproduce_quick_table1(capsys):
    assert main(["reproduce", "gribkov2015", "--quick"]) == 0
    out = capsys.readouterr().out
    row = re.search(r"p1, Hz\s+([\d.]+)\s+([\d.]+)", out)
    assert float(row.group(1)) == 2.289
    assert float(row.group(2)) == pytest.approx(_hand_frequencies_hz(T1)[0], rel=1e-5)
    assert "[1/1] gribkov2015" in out and "done in" in out


def test_reproduce_bad_source(capsys):
    assert main(["reproduce", "gribkov"]) == 2
    assert "invalid choice" in capsys.readouterr().err


def test_errors_from_flags_name_the_flag_and_the_subcommand_usage(capsys):
    assert main(["stability", "2", "--amplitude", "-3 mm", "--frequency", "100 Hz"]) == 2
    err = capsys.readouterr().err
    assert "usage: symosc stability" in err and "--amplitude: expected a positive value" in err
    assert "line" not in err and "excitation" not in err  # no internal scene key
    assert main(["mathieu", "a", "-1", "1"]) == 2
    assert "usage: symosc mathieu" in capsys.readouterr().err


def test_reproduce_finds_the_derivations_of_the_checkout_it_runs_in(tmp_path, monkeypatch, capsys):
    """With the package installed elsewhere (no derivations/ beside it), the checkout in the working folder is used;
    with none, the message says where to run it."""
    import symosc.cli as cli

    monkeypatch.setattr(cli, "__file__", str(tmp_path / "site-packages" / "symosc" / "cli.py"))
    monkeypatch.chdir(tmp_path)
    assert main(["reproduce", "gribkov2015", "--quick"]) == 1
    assert "inside the checkout" in capsys.readouterr().err
    (tmp_path / "derivations").mkdir()
    (tmp_path / "derivations" / "gribkov_khokhlov_2015.py").write_text(
        "def table1_natural_frequencies():\n    print('stand-in table 1')\n"
    )
    (tmp_path / "sub").mkdir()
    monkeypatch.chdir(tmp_path / "sub")
    assert main(["reproduce", "gribkov2015", "--quick"]) == 0
    assert "stand-in table 1" in capsys.readouterr().out
