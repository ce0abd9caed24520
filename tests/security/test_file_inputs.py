"""Scene files, saved summaries and command-line text are parsed, never run: every attempt to run code through them,
and every resource bomb, ends in a named error (and nothing is executed)."""

from __future__ import annotations

import json
import time

import pytest
import sympy as sp

from symosc._parsing import LIMITS, ExpressionError, parse_expression, parse_srepr
from symosc.errors import ParameterError
from symosc.io import load_summary, save
from symosc.scene import SceneError, loads

#: each payload, if it ran, would create the file CANARY in the working directory (``{canary}`` is its path)
CODE_EXECUTION = [
    "__import__('os').system('touch {canary}')",
    "sin(\"\\x5f\\x5fimport\\x5f\\x5f('os').system('touch {canary}')\")",  # a string literal hiding the payload
    'sin(\'__import__("os").system("touch {canary}")\')',
    "().__class__.__bases__[0].__subclasses__()",
    "x.__class__",
    "(lambda: __import__('os').system('touch {canary}'))()",
    "[__import__('os').system('touch {canary}') for _ in (1,)][0]",
    "eval(\"__import__('os').system('touch {canary}')\")",
    'exec(\'open("{canary}", "w")\')',
    "open('{canary}', 'w')",
    'ｅｘｅｃ(\'open("{canary}", "w")\')',  # fullwidth letters: Python reads them as exec
    "getattr(x, 'real')",
    "globals()",
    "sin(x=1)",
    "sin(*[1])",
    "f'{{1}}'",
    "(y := 1)",
    "x if x else 1",
    "x < 1",
    "x and 1",
    "x[0]",
    "{{1: 2}}",
    "Symbol('x')",
    "b'abc'",
    "1j",
    "True",
    "None",
    "x; 1",
    "import os",
]

#: short texts asking for enormous numbers, expansions or parse trees
BOMBS = [
    "0*9**9**9",
    "0*2**2**40",
    "0*10**10**10",
    "x**(10**6)",
    "(x + 1)**100000",
    "(" * 5000 + "x" + ")" * 5000,
    "-" * 100_000 + "1",
    "+".join(["x"] * 10_000),
    "1" + "0" * 5000,
    "1e999",
    "sin(" * 500 + "x" + ")" * 500,
    "x" * (LIMITS["characters"] + 1),
    "+".join(["x"] * 30_000),
    "2**(-10**7)",
    "(1/3)**(10**6)",
]

#: every expression field of a scene file: (field, scene text with {payload})
FIELDS = {
    "system.T": '[system]\nmodel = "lagrangian"\ncoordinates = ["x"]\nT = {payload}\nV = "k*x**2/2"\n',
    "system.V": '[system]\nmodel = "lagrangian"\ncoordinates = ["x"]\nT = "m*x_dot**2/2"\nV = {payload}\n',
    "system.R": '[system]\nmodel = "lagrangian"\ncoordinates = ["x"]\nT = "m*x_dot**2/2"\nV = "k*x**2/2"\n'
    "R = {payload}\n",
    "system.forces": '[system]\nmodel = "lagrangian"\ncoordinates = ["x"]\nT = "m*x_dot**2/2"\nV = "k*x**2/2"\n'
    "forces = [{payload}]\n",
    "system.f": '[system]\nmodel = "weakly_nonlinear"\nf = {payload}\n',
    "system.operator": '[system]\nmodel = "operator_ode"\noperator = {payload}\n',
    "system.input_operator": '[system]\nmodel = "operator_ode"\noperator = "D + 1"\ninput_operator = {payload}\n',
    "system.input": '[system]\nmodel = "operator_ode"\noperator = "D + 1"\ninput = {payload}\n',
}


def _toml_string(text: str) -> str:
    return json.dumps(text)  # a TOML basic string is a JSON string for these characters


@pytest.fixture
def canary(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "CANARY"
    yield path
    assert not path.exists(), "a payload ran"


@pytest.mark.parametrize("field", sorted(FIELDS))
def test_no_field_of_a_scene_file_runs_code(field, canary):
    for payload in CODE_EXECUTION:
        text = FIELDS[field].format(payload=_toml_string(payload.format(canary=canary)))
        with pytest.raises(SceneError) as info:
            loads(text)
        assert info.value.key == field, payload
    assert not canary.exists()


@pytest.mark.parametrize("field", sorted(FIELDS))
def test_resource_bombs_are_refused_at_once(field):
    for bomb in BOMBS:
        start = time.perf_counter()
        with pytest.raises(SceneError) as info:
            loads(FIELDS[field].format(payload=_toml_string(bomb)))
        assert time.perf_counter() - start < 5, bomb[:40]  # a refusal, not a computation that happens to finish
        assert info.value.key == field
        message = str(info.value)
        assert "limit" in message or "not" in message, message


def test_refusals_say_what_was_refused_and_the_limit():
    x = sp.Symbol("x")
    cases = {
        "0*9**9**9": "result digits",
        "x**(10**6)": "exponent",
        "(" * 5000 + "x" + ")" * 5000: "depth",
        "+".join(["x"] * 10_000): "nodes",
        "x.real": "attribute access",
        'sin("a")': "not a number",
        "eval(x)": "not a function an expression may call",
    }
    for text, words in cases.items():
        with pytest.raises(ExpressionError, match=words):
            parse_expression(text, names={"x": x})


def test_the_grammar_still_reads_the_books_notation():
    x, m, k = sp.symbols("x m k")
    got = parse_expression("m*x^2/2 + k*sin(x)**2 - 3/4*pi + 1.5e-3*abs(x)", names={"x": x, "m": m, "k": k})
    assert got == m * x**2 / 2 + k * sp.sin(x) ** 2 - sp.Rational(3, 4) * sp.pi + sp.Float("1.5e-3") * sp.Abs(x)
    assert parse_expression("2**10 * 10**300", names={}) == 2**10 * 10**300  # big but allowed


# ---------------------------------------------------------------------------------------------- saved summaries
SREPR_ATTACKS = [
    "__import__('os').system('touch {canary}')",
    "Symbol('x').__class__",
    "Add(Symbol('x'), eval('1'))",
    "Function('f')(Symbol('t')).__globals__",
    "Symbol(chr(120))",
    "Integer(" + "9" * 20_000 + ")",
    "Pow(Integer(9), Pow(Integer(9), Integer(9)))",
    "Symbol('x', positive=print('hi'))",
    "Add(" * 200 + "Integer(1)" + ")" * 200,
    "lambda: 1",
    "[Symbol('x')][0]",
]


def test_a_saved_summary_never_runs_code(tmp_path, canary):
    from symosc.models import n_link_pendulum

    _, js = save(n_link_pendulum(1), tmp_path / "model")
    good = json.loads(js.read_text())
    for attack in SREPR_ATTACKS:
        data = dict(good, symbolic={"mass_matrix": attack.format(canary=canary)})
        js.write_text(json.dumps(data))
        with pytest.raises(ParameterError, match="mass_matrix"):
            load_summary(js)
    js.write_text(json.dumps(good))
    assert load_summary(js)["symbolic"]["mass_matrix"] == n_link_pendulum(1).mass_matrix


@pytest.mark.parametrize("content", [b"\xff\xfe{", b"[1, 2]", b'{"symbolic": [1]}', b"not json"])
def test_a_file_that_is_not_a_summary_is_refused_by_name(tmp_path, content):
    path = tmp_path / "bad.json"
    path.write_bytes(content)
    with pytest.raises(ParameterError, match="not a summary"):
        load_summary(path)


def test_srepr_round_trip_of_the_objects_summaries_hold():
    t = sp.Symbol("t")
    q = sp.Function("q")(t)
    x = sp.Symbol("x", positive=True)
    objects = [
        sp.Matrix([[x**2 * sp.sin(x) + sp.Rational(1, 3), sp.Float("2.5", 30)], [sp.exp(-x), sp.pi * sp.I]]),
        sp.Derivative(q, t) + sp.besselj(0, x) + sp.atan2(x, 1),
        sp.Tuple(sp.oo, -sp.Integer(7), sp.sqrt(2)),
    ]
    for obj in objects:
        assert parse_srepr(sp.srepr(obj)) == obj
