"""Adversarial netlists: code-execution attempts in every field, huge numbers, deep nesting, resource bombs.

``parse_netlist`` reads files people share: nothing in them may be evaluated, and every size is bounded before any
work is done.  Each attempt must end in a ParameterError naming the line, with no evaluator ever called.
"""

from __future__ import annotations

import builtins
import re
import sys

import pytest
import sympy as sp

from symosc.errors import ParameterError
from symosc.networks import parse_netlist

PAYLOADS = [
    "__import__('os').system('echo pwned')",
    "eval('1')",
    "exec('x=1')",
    "lambda:0",
    "os.system",
    "${IFS}",
    "$(rm -rf /)",
    "`id`",
    "1+1",
    "2*R",
    "(1)",
    "R[0]",
    "{__class__}",
    "__builtins__",
    "a.b",
    "1e3e3",
    "0x10",
    "1_000",
    "\x00",
    "١٢",  # Arabic-Indic digits
    "１k",  # full-width digit
]

TEMPLATES = {
    "element name": "{x} a 0 1\nP1 a 0",
    "node": "R1 {x} 0 1\nP1 a 0",
    "second node": "R1 a {x} 1\nP1 a 0",
    "value": "R1 a 0 {x}\nP1 a 0",
    "source keyword": "V1 a 0 {x} 1\nR1 a 0 1",
    "coupled inductor": "L1 a 0 1\nK1 L1 {x} 0.5",
    "coupling": "L1 a 0 1\nL2 b 0 1\nK1 L1 L2 {x}",
    "parameter name": ".param {x}=1\nR1 a 0 1",
    "parameter value": ".param R={x}\nR1 a 0 R",
    "directive": ".{x}\nR1 a 0 1",
}


@pytest.fixture
def no_evaluation(monkeypatch):
    """Fail the test if eval/exec or SymPy's string parsers run while a netlist is read."""

    def refuse(name):
        def spy(*args, **kwargs):
            raise AssertionError(f"{name} was called while parsing a netlist: {str(args)[:80]}")

        return spy

    import sympy.parsing.sympy_parser as parser

    monkeypatch.setattr(builtins, "eval", refuse("eval"))
    monkeypatch.setattr(builtins, "exec", refuse("exec"))
    monkeypatch.setattr(parser, "parse_expr", refuse("parse_expr"))
    real_sympify = sp.sympify

    def sympify_spy(a, *args, **kwargs):
        if isinstance(a, str):
            raise AssertionError(f"sympify of a string while parsing a netlist: {a[:80]!r}")
        return real_sympify(a, *args, **kwargs)

    monkeypatch.setattr(sp, "sympify", sympify_spy)
    monkeypatch.setattr(sys.modules["sympy.core.sympify"], "sympify", sympify_spy)


@pytest.mark.parametrize("field", list(TEMPLATES))
@pytest.mark.parametrize("payload", PAYLOADS, ids=range(len(PAYLOADS)))
def test_code_in_any_field_is_refused_without_evaluation(field, payload, no_evaluation):
    text = TEMPLATES[field].format(x=payload)
    if field.endswith("node") and re.fullmatch(r"[A-Za-z0-9_]+", payload):
        circuit = parse_netlist(text)  # a node name is a label: kept as the string written, never evaluated
        assert payload in circuit.elements[0].nodes
        return
    with pytest.raises(ParameterError, match=r"line \d+|not|must|takes|only|couples|DC or AC"):
        parse_netlist(text)


def test_names_are_identifiers_and_dunders_are_refused(no_evaluation):
    for bad in ("__class__", "{__import__}", "_private"):
        with pytest.raises(ParameterError, match="line 1"):
            parse_netlist(f"R1 a 0 {bad}")
    circuit = parse_netlist("R1 a 0 {Rload}\nP1 a 0")  # an ordinary name is a positive symbol, not evaluated
    assert circuit.elements[0].value == sp.Symbol("Rload", positive=True)


@pytest.mark.parametrize(
    "value, match",
    [
        ("1e999999999", "exponent"),
        ("1e-400", "exponent"),
        ("9" * 4000, "digits"),
        ("1" + "0" * 61, "digits"),
        ("1e" + "9" * 4000, "exponent"),
    ],
)
def test_huge_numbers_are_refused_before_any_arithmetic(value, match, no_evaluation):
    with pytest.raises(ParameterError, match=match):
        parse_netlist(f"R1 a 0 {value}")


def test_deep_nesting_and_unsupported_structure(no_evaluation):
    for text in (
        "R1 a 0 " + "{" * 500 + "R" + "}" * 500,
        "R1 a 0 " + "(" * 500 + "1" + ")" * 500,
        ".subckt X a b\nR1 a b 1\n.ends",
        ".include /etc/passwd",
        ".lib models.lib",
        ".control\nshell rm -rf /\n.endc",
        "X1 a b sub",
        "E1 a 0 b 0 1e6",
    ):
        with pytest.raises(ParameterError):
            parse_netlist(text)


def test_size_limits(no_evaluation):
    with pytest.raises(ParameterError, match="characters"):
        parse_netlist("*" * 1_000_001)
    with pytest.raises(ParameterError, match="lines"):
        parse_netlist("\n" * 20_001)
    with pytest.raises(ParameterError, match="characters"):
        parse_netlist("R1 a 0 1 " + "x" * 5000)
    with pytest.raises(ParameterError, match="characters"):  # a long line built from continuations
        parse_netlist("R1 a 0\n" + "+ 1\n" * 3000)
    with pytest.raises(ParameterError, match="elements"):
        parse_netlist("\n".join(f"R{i} a{i} 0 1" for i in range(2001)))
    with pytest.raises(ParameterError, match="name"):
        parse_netlist("R" + "x" * 100 + " a 0 1")


def test_a_semicolon_starts_a_comment(no_evaluation):
    circuit = parse_netlist("R1 a 0 1;import os\nP1 a 0")
    assert [e.value for e in circuit.elements] == [1, None]


def test_non_text_input_is_refused():
    for bad in (b"R1 a 0 1", None, 42, ["R1 a 0 1"]):
        with pytest.raises(ParameterError):
            parse_netlist(bad)
