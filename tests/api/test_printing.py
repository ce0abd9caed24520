"""SymPy citizenship of every public model and result type (found by walking ``__all__``)."""

from __future__ import annotations

import pytest
import sympy as sp

from .public import public_classes

CLASSES = public_classes()


def _balanced(text: str) -> bool:
    depth = 0
    escaped = False
    for c in text:
        if escaped:
            escaped = False
            continue
        if c == "\\":
            escaped = True
        elif c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth < 0:
                return False
    return depth == 0


def _instance(examples, cls):
    obj = examples.get(cls)
    assert obj is not None, (
        f"no documented example builds a {cls.__name__}: add one to its docstring (or to tests/api/examples.py)"
    )
    return obj


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_latex_is_real_latex(cls, examples):
    obj = _instance(examples, cls)
    text = sp.latex(obj)
    assert text and not text.startswith(r"\mathtt{\text{"), text[:80]  # SymPy's fallback for unknown objects
    assert "$" not in text and _balanced(text), text[:200]
    assert obj._repr_latex_().startswith("$")


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_str_and_pretty_hooks(cls, examples):
    obj = _instance(examples, cls)
    assert sp.sstr(obj) == repr(obj)
    pretty = [line.rstrip() for line in sp.pretty(obj, wrap_line=False).splitlines()]
    assert pretty == [line.rstrip() for line in repr(obj).splitlines()]


def test_series_converts_with_sympify():
    """van der Pol: omega = 1 - eps^2/16 + 17 eps^4/3072 + O(eps^6) (Andersen & Geer 1982, Table 1)."""
    from symosc.nonlinear import limit_cycle

    x, v = sp.symbols("x v")
    w = limit_cycle((1 - x**2) * v, 4).frequency
    eps = w.symbol
    known = 1 - eps**2 / 16 + sp.Rational(17, 3072) * eps**4
    assert sp.expand(sp.sympify(w) - known) == 0
    assert sp.expand(w.removeO() - known) == 0 and w.getO() == sp.O(eps**5)
    assert sp.expand((sp.Integer(2) * w + 1) - (2 * known + 1)) == 0  # SymPy arithmetic goes through _sympy_
    assert sp.latex(w) == sp.latex(known) + r" + O\left(" + sp.latex(eps**5) + r"\right)"


def test_model_latex_shows_the_equations_and_simplifies():
    """Single pendulum: m l^2 phi'' = -m g l sin(phi) (after sin^2 + cos^2 = 1)."""
    from symosc.models import n_link_pendulum

    system = n_link_pendulum(1)
    plain = sp.latex(system)
    assert r"\sin^{2}" in plain and r"\ddot{\phi_{1}}" in plain
    simple = system.latex(simplify=True)
    assert r"\sin^{2}" not in simple and r"l_{1}^{2} m_{1}" in simple and r"\sin{\left(\phi_{1} \right)}" in simple
