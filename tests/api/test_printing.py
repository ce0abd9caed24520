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


def _is_series(obj) -> bool:
    from symosc.nonlinear import EpsSeries
    from symosc.nonlinear.series._series import SeriesResult

    return isinstance(obj, EpsSeries | SeriesResult)


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_str_and_pretty_hooks(cls, examples):
    obj = _instance(examples, cls)
    assert sp.sstr(obj) == repr(obj)
    pretty = [line.rstrip() for line in sp.pretty(obj, wrap_line=False).splitlines()]
    if _is_series(obj):  # series print their mathematics in 2-D, eps as epsilon
        assert len(pretty) > 1 and any("O(" in line or "O⎝" in line for line in pretty), pretty
        return
    assert pretty == [line.rstrip() for line in repr(obj).splitlines()]


def test_series_converts_with_sympify():
    """van der Pol: omega = 1 - eps^2/16 + 17 eps^4/3072 + O(eps^6) (Andersen & Geer 1982, Table 1)."""
    from symosc.nonlinear import limit_cycle

    x, v = sp.symbols("x v")
    w = limit_cycle((1 - x**2) * v, 4).frequency
    eps = w.symbol
    known = 1 - eps**2 / 16 + sp.Rational(17, 3072) * eps**4
    assert sp.sympify(w) == known + sp.O(eps**5) and sp.sympify(w) != known  # the order term is kept
    assert sp.expand(w.removeO() - known) == 0 and w.getO() == sp.O(eps**5)
    assert sp.Integer(2) * w + 1 == 2 * known + 1 + sp.O(eps**5)  # SymPy operands defer to the series
    assert (
        sp.latex(w)
        == r"1 - \frac{\varepsilon^{2}}{16} + \frac{17 \varepsilon^{4}}{3072} + O\left(\varepsilon^{5}\right)"
    )
    pretty = sp.pretty(w, use_unicode=True)
    assert "ε" in pretty and len(pretty.splitlines()) == 4  # 2-D powers and fractions


def test_model_latex_shows_the_equations_and_simplifies():
    """Single pendulum: m l^2 phi'' = -m g l sin(phi) (after sin^2 + cos^2 = 1)."""
    from symosc.mechanics import LagrangianSystem
    from symosc.models import n_link_pendulum

    system = n_link_pendulum(1)
    raw = LagrangianSystem(system.kinetic_energy, system.potential_energy, system.coordinates, simplify=False)
    plain = sp.latex(raw)
    assert r"\sin^{2}" in plain and r"\ddot{\phi_{1}}" in plain
    assert r"\sin^{2}" not in sp.latex(system)  # the identities are applied by default
    simple = raw.latex(simplify=True)
    assert r"\sin^{2}" not in simple and r"l_{1}^{2} m_{1}" in simple and r"\sin{\left(\phi_{1} \right)}" in simple
