"""Malformed scene files: each gives one paragraph naming the file and the key, with the fix; no traceback."""

from __future__ import annotations

import pytest

from symosc.cli import main
from symosc.scene import SceneError, load

GOOD_SYSTEM = """
[system]
model = "n_link_pendulum"
n = 1
[parameters]
m1 = "1 kg"
l1 = "1 m"
g = 9.81
"""
Q = '\n[[questions]]\nkind = "natural_frequencies"\n'
RIGID2 = """
[system]
model = "n_link_pendulum"
n = 2
links = "rigid"
[parameters]
m1 = 1.0
m2 = 1.0
l1 = 1.0
lc1 = 0.5
I1 = 0.1
I2 = 0.1
g = 9.81
"""

# (name, scene text, key the message must name, words it must contain)
CASES = [
    ("unknown top-level key", "paramters = 1\n" + GOOD_SYSTEM + Q, "paramters", "Did you mean 'parameters'?"),
    ("TOML syntax", "[system\nmodel = 1\n", "", "line 1"),
    ("missing model", "[system]\nn = 1\n" + Q, "system", "model"),
    (
        "unknown model",
        GOOD_SYSTEM.replace('"n_link_pendulum"', '"n_link_pendulm"') + Q,
        "system.model",
        "Did you mean 'n_link_pendulum'?",
    ),
    (
        "unknown system option",
        GOOD_SYSTEM.replace("n = 1", 'n = 1\npivit = "fixed"') + Q,
        "system.pivit",
        "Did you mean 'pivot'?",
    ),
    (
        "bad option value",
        GOOD_SYSTEM.replace("n = 1", 'n = 1\nlinks = "flexible"') + Q,
        "system.links",
        "'point', 'rigid'",
    ),
    ("n = 0", GOOD_SYSTEM.replace("n = 1", "n = 0") + Q, "system.n", "integer >= 1"),
    (
        "boolean as string",
        GOOD_SYSTEM.replace("n = 1", 'n = 1\ninverted = "yes"') + Q,
        "system.inverted",
        "true or false",
    ),
    ("unknown parameter", GOOD_SYSTEM + "foo = 1\n" + Q, "parameters.foo", "Valid parameters: g, l1, m1"),
    (
        "l2 of a rigid chain",
        RIGID2.replace("lc1 = 0.5", "lc1 = 0.5\nlc2 = 0.5\nl2 = 1.0") + Q,
        "parameters.l2",
        "Did you mean 'lc2'?",
    ),
    ("missing parameter", RIGID2 + Q, "parameters", "lc2"),
    ("wrong dimension", GOOD_SYSTEM.replace('m1 = "1 kg"', 'm1 = "2 mm"') + Q, "parameters.m1", "expected a mass"),
    ("unknown unit", GOOD_SYSTEM.replace('m1 = "1 kg"', 'm1 = "2 grams"') + Q, "parameters.m1", "unknown unit 'grams'"),
    ("negative mass", GOOD_SYSTEM.replace('m1 = "1 kg"', "m1 = -1") + Q, "parameters.m1", "positive"),
    ("no questions", GOOD_SYSTEM, "questions", "no question"),
    (
        "unknown kind",
        GOOD_SYSTEM + '[[questions]]\nkind = "natural_frequency"\n',
        "questions[0].kind",
        "Did you mean 'natural_frequencies'?",
    ),
    (
        "question the model cannot answer",
        GOOD_SYSTEM + '[[questions]]\nkind = "mathieu_values"\nn = 0\nq = 1\n',
        "questions[0].kind",
        "cannot answer 'mathieu_values'",
    ),
    (
        "unknown question option",
        GOOD_SYSTEM + Q + "reference_hzz = [1.0]\n",
        "questions[0].reference_hzz",
        "Did you mean 'reference_hz'?",
    ),
    (
        "missing question option",
        '[system]\nmodel = "van_der_pol"\n[[questions]]\nkind = "limit_cycle"\n',
        "questions[0]",
        "order",
    ),
    (
        "excitation of a fixed pivot",
        GOOD_SYSTEM + '[excitation]\namplitude = "1 mm"\n' + Q,
        "excitation.amplitude",
        "no excitation",
    ),
    (
        "unknown excitation key",
        GOOD_SYSTEM + '[excitation]\namplitud = "1 mm"\n' + Q,
        "excitation.amplitud",
        "Did you mean 'amplitude'?",
    ),
    (
        "T not SymPy",
        '[system]\nmodel = "lagrangian"\ncoordinates = ["x"]\nT = "m*x_dot**2/"\nV = "k*x**2/2"\n' + Q,
        "system.T",
        "SymPy expression",
    ),
    (
        "wrong unit of a question option",
        GOOD_SYSTEM.replace("n = 1", 'n = 1\ninverted = true\npivot = "vertical"')
        + '[[questions]]\nkind = "stability_region"\nfrequency = "100 mm"\n',
        "questions[0].frequency",
        "expected an angular frequency",
    ),
]


@pytest.mark.parametrize(("name", "text", "key", "words"), CASES, ids=[c[0] for c in CASES])
def test_malformed_scene_names_the_key(tmp_path, capsys, name, text, key, words):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(SceneError) as info:
        load(path)
    msg = str(info.value)
    assert msg.startswith(str(path))
    assert "\n" not in msg  # one paragraph
    if key:
        assert f"key '{key}'" in msg and info.value.key == key
    assert words in msg
    assert "Fix: " in msg or name == "TOML syntax"
    # the command line prints the same paragraph, exit code 1, no traceback, and writes nothing
    out = tmp_path / "out"
    assert main(["run", str(path), "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert msg in err and "Traceback" not in err
    assert not out.exists()


def test_line_numbers_point_at_the_key(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(GOOD_SYSTEM.replace('m1 = "1 kg"', 'm1 = "2 mm"') + Q)
    with pytest.raises(SceneError) as info:
        load(path)
    assert info.value.line == GOOD_SYSTEM.splitlines().index('m1 = "1 kg"') + 1


def test_a_question_the_system_cannot_answer_is_refused_before_computing(tmp_path, capsys):
    """A hanging pendulum has no stability region: refused at load, nothing is written."""
    path = tmp_path / "bad.toml"
    path.write_text(GOOD_SYSTEM + Q + '[[questions]]\nkind = "stability_region"\n')
    out = tmp_path / "out"
    assert main(["run", str(path), "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert "key 'questions[1].kind'" in err and "inverted chain on a vibrating pivot" in err
    assert not out.exists()


def test_failure_while_answering_names_the_question(tmp_path, capsys):
    """An unstable equilibrium (V = -k x^2/2) has no natural frequencies: the run stops, nothing is written."""
    path = tmp_path / "bad.toml"
    text = '[system]\nmodel = "lagrangian"\ncoordinates = ["x"]\nT = "m*x_dot**2/2"\nV = "-k*x**2/2"\n'
    path.write_text(text + "[parameters]\nm = 1\nk = 4\n" + Q)
    out = tmp_path / "out"
    assert main(["run", str(path), "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert "key 'questions[0].kind'" in err and "statically unstable" in err and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1
    assert not out.exists()


def test_there_are_twenty_malformed_cases():
    assert len(CASES) >= 20
