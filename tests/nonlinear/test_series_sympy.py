"""Series results as SymPy objects: arithmetic, order terms, substitution, derivatives, equality and printing.

Every product, quotient and power is checked against SymPy's own series engine (``sympy.series`` of the closed
form, and SymPy's ``Order`` arithmetic on the sympified operands), never against the series code itself.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
import sympy as sp

from symosc.nonlinear import (
    EpsSeries,
    limit_cycle,
    lindstedt,
    nonresonant_forced_solution,
    periodic_solution_ndof,
)

EPS = sp.Symbol("eps")
A = sp.Symbol("A")
X, V = sp.symbols("x v")
N = 5  # series known to eps**4

#: closed forms and their Maclaurin series from SymPy (the reference for every operation below)
F = sp.exp(EPS) / (1 - 2 * EPS)
G = sp.cos(EPS) + EPS / 3
H = 1 + A * EPS  # with a parameter


@functools.cache
def _reference(expr, n=N):
    return sp.series(expr, EPS, 0, n)


def _series(expr, n=N):
    return EpsSeries.from_sympy(_reference(expr, n) + sp.O(EPS**n), EPS)  # (a polynomial needs its O-term)


@pytest.fixture(scope="module")
def vdp():
    return limit_cycle((1 - X**2) * V, 6)


def test_from_sympy_reads_what_sympy_series_returns():
    s = _series(F)
    assert s.order == N - 1 and sp.sympify(s) == _reference(F)
    with pytest.raises(ValueError):
        EpsSeries.from_sympy(sp.sin(EPS))


@pytest.mark.parametrize(
    "build, closed",
    [
        (lambda f, g: f * g, F * G),
        (lambda f, g: f + g, F + G),
        (lambda f, g: f - 3 * g, F - 3 * G),
        (lambda f, g: f / g, F / G),
        (lambda f, g: 1 / f, 1 / F),
        (lambda f, g: 2 / g + f, 2 / G + F),
        (lambda f, g: f**3, F**3),
        (lambda f, g: f ** sp.Rational(1, 2), sp.sqrt(F)),
        (lambda f, g: g ** sp.Rational(-3, 2), G ** sp.Rational(-3, 2)),
        (lambda f, g: (f + A) * g - 1, (F + A) * G - 1),
        (lambda f, g: f / _series(H), F / H),
        (lambda f, g: f / (1 + EPS), F / (1 + EPS)),
    ],
    ids=[
        "mul",
        "add",
        "sub",
        "div",
        "inverse",
        "scalar-div",
        "cube",
        "sqrt",
        "power",
        "symbols",
        "parameter",
        "by-polynomial",
    ],
)
def test_arithmetic_matches_sympy_series_of_the_closed_form(build, closed):
    out = build(_series(F), _series(G))
    assert isinstance(out, EpsSeries)
    ref = _reference(closed)
    assert out.getO() == ref.getO()
    assert sp.expand(out.removeO() - ref.removeO()) == 0


def test_products_carry_the_order_term_of_sympy_order_arithmetic():
    """(eps f + O(eps**4)) (eps**2 g + O(eps**5)) is known to eps**5: SymPy's Order rules, expanded by SymPy."""
    a = EpsSeries.from_sympy(sp.series(EPS * F, EPS, 0, 4))
    b = EpsSeries.from_sympy(sp.series(EPS**2 * G, EPS, 0, 5))
    expected = sp.expand(sp.sympify(a) * sp.sympify(b))
    prod = a * b
    assert prod.getO() == expected.getO() == sp.O(EPS**6)
    assert sp.expand(prod.removeO() - expected.removeO()) == 0
    assert (a * 0) == 0 and (a - a).getO() == a.getO() and (a - a).removeO() == 0
    assert (EPS**3 * a).getO() == sp.O(EPS**7)  # an exact factor shifts the order, as in SymPy


def test_sympy_operands_on_the_left_give_series_too():
    f = _series(F)
    for out, ref in [(A * f, A * F), (A + f, A + F), (A - f, A - F), (EPS * f, EPS * F), (sp.pi / f, sp.pi / F)]:
        assert isinstance(out, EpsSeries)
        n = out.order + 1
        assert sp.expand(out.removeO() - sp.series(ref, EPS, 0, n).removeO()) == 0


def test_non_series_operands_give_what_sympy_builds():
    f = _series(F)
    assert f * sp.sin(EPS) == sp.sympify(f) * sp.sin(EPS)
    assert (f / EPS).has(sp.Order) and not isinstance(f / EPS, EpsSeries)
    assert f * sp.Matrix([1, 2]) == sp.Matrix([sp.sympify(f), 2 * sp.sympify(f)])


def test_subs_diff_and_free_symbols():
    g = _series(G) * _series(H)
    assert g.free_symbols == {EPS, A}
    at = g.subs(A, 3)
    assert isinstance(at, EpsSeries) and at == _series(G * H.subs(A, 3))
    value = g.subs({A: 2, EPS: sp.Rational(1, 5)})
    assert value == _reference(G * H).removeO().subs({A: 2, EPS: sp.Rational(1, 5)})  # the truncated sum, exact
    mu = sp.Symbol("mu")
    assert g.subs(EPS, mu) == _reference(G * H).subs(EPS, mu)
    scaled, ref = g.subs(EPS, 2 * mu), _reference(G * H).subs(EPS, 2 * mu)
    assert scaled.getO() == ref.getO() == sp.O(mu**5) and sp.expand(scaled.removeO() - ref.removeO()) == 0
    d = sp.diff(_series(F), EPS)
    assert d == sp.series(sp.diff(F, EPS), EPS, 0, N - 1)  # one order lost
    assert _series(F).diff(EPS, 2) == sp.series(sp.diff(F, EPS, 2), EPS, 0, N - 2)
    dg = g.diff(A)  # the order term kept (SymPy drops it: d/dA O(eps**5) = 0 there)
    assert dg.getO() == g.getO() and dg.removeO() == sp.expand(sp.diff(g.removeO(), A))


def test_equality_respects_the_order_term():
    f = _series(F)
    assert f == sp.sympify(f) and f == sp.S(f) and hash(f) == hash(sp.sympify(f))
    assert f != f.removeO() and f != _series(F, N + 1)
    assert f == EpsSeries(tuple(2 * c for c in f.coefficients), EPS, f.order, sp.Rational(1, 2), name="other")
    assert len({f, sp.sympify(f), _series(F)}) == 1


def test_van_der_pol_frequency_squared_and_period(vdp):
    """omega**2 and 2 pi/omega from the series arithmetic against the recurrence's own omega**2 and period."""
    w = vdp.frequency
    assert w * w == vdp.frequency_squared
    assert 2 * sp.pi / w == vdp.period
    assert (w * w).getO() == sp.O(EPS**7)


def test_lindstedt_frequency_squared_is_the_recurrence_value():
    """Duffing x'' + x = -eps x**3: omega**2 of the recurrence (Bulgakov (1954) eq. (5.58)) is omega*omega."""
    ls = lindstedt(-(X**3), 5)
    assert ls.frequency**2 == ls.frequency_squared
    dw = ls.frequency.diff(A)
    assert dw.getO() == ls.frequency.getO() and sp.expand(dw.removeO() - sp.diff(ls.frequency.removeO(), A)) == 0


def _scalar_series_checks(obj, eps, value):
    expr = sp.sympify(obj)
    assert expr.getO() is not None and sp.S(obj) == expr
    plus = obj + 1
    assert sp.expand(sp.sympify(plus).removeO() - expr.removeO() - 1) == 0
    sq = obj * obj
    reference = sp.expand(expr * expr)  # SymPy's Order arithmetic
    assert sq.getO() == reference.getO()
    assert sp.expand(sq.removeO() - reference.removeO()) == 0
    at = obj.subs(eps, value)
    assert not at.has(sp.Order) and eps not in at.free_symbols
    return at


def test_limit_cycle_is_its_solution_series(vdp):
    tau = sp.Symbol("tau")
    at = _scalar_series_checks(vdp, EPS, 0.1)
    taus = np.linspace(0, 2 * np.pi, 7)
    numeric = vdp.evaluate_solution(0.1, taus)[0]
    assert np.allclose([float(at.subs(tau, s)) for s in taus], numeric, rtol=0, atol=1e-13)


def test_lindstedt_is_its_solution_series():
    ls = lindstedt(-(X**3), 3)
    at = _scalar_series_checks(ls, EPS, sp.Rational(1, 10))
    assert sp.expand(at - ls.solution(3).subs(EPS, sp.Rational(1, 10))) == 0


def test_forced_nonresonant_solution_is_its_series():
    """q'' + q = cos(2t) - mu q**3: q(t) as a series in mu; sums and products agree with ``evaluate`` pointwise."""
    q, v, t, mu = sp.symbols("q v t mu")
    sol = nonresonant_forced_solution(sp.cos(2 * t) - mu * q**3, q, v, t, 1.0, 2.0, 1, n_harmonics=4)
    expr = sp.sympify(sol)
    assert expr.getO() == sp.O(mu**2) and sp.S(sol) == expr
    ts = np.linspace(0.0, np.pi, 5)
    direct, first = sol.evaluate(ts, 0.05), sol.evaluate(ts, 0.05, order=0)
    # the product is known to mu**1: q0**2 + 2 mu q0 q1
    for combined, expected in [(sol + 1, direct + 1), (sol * sol, first**2 + 2 * first * (direct - first))]:
        at = combined.subs(mu, 0.05)
        got = np.array([float(at.subs(sp.Symbol("t"), s)) for s in ts])
        assert np.allclose(got, expected, rtol=0, atol=1e-13)
    assert (sol * sol).getO() == sp.O(mu**2)


def test_vector_results_sympify_to_a_matrix_of_series():
    q1, q2, v1, v2 = sp.symbols("q1 q2 v1 v2")
    f = [(1 - q1**2) * v1, (1 - q2**2) * v2]
    sol = periodic_solution_ndof([[1, 0], [0, 1]], [[2, -1], [-1, 2]], f, [q1, q2], [v1, v2], 2)
    m = sp.sympify(sol)
    assert isinstance(m, sp.ImmutableMatrix) and m.shape == (2, 1)
    assert all(e.getO() == sp.O(EPS**3) for e in m)
    assert (sol + sol) == 2 * m and sol.getO() == sp.O(EPS**3)
    ex = sol.exponent_series(2)
    mex = sp.sympify(ex)
    assert mex.shape == (4, 1) and all(e.getO() == sp.O(EPS**3) for e in mex)
    assert np.allclose([complex(e.removeO().subs(EPS, 0.1)) for e in mex], ex.evaluate(0.1), rtol=1e-13, atol=1e-13)


def test_printing_is_two_dimensional_with_epsilon(vdp):
    w = vdp.frequency
    text = sp.pretty(w, use_unicode=True)
    lines = text.splitlines()
    assert len(lines) == 4 and "ε" in text and "eps" not in text and any(x.startswith("ω = 1 - ──") for x in lines)
    assert sp.latex(w) == (
        r"1 - \frac{\varepsilon^{2}}{16} + \frac{17 \varepsilon^{4}}{3072} + \frac{35 \varepsilon^{6}}{884736}"
        r" + O\left(\varepsilon^{7}\right)"
    )
    period = sp.latex(vdp.period)
    assert period.startswith(r"2 \pi \left(") and r"O\left(\varepsilon^{7}\right)" in period
    assert r"\varepsilon" in sp.latex(vdp) and "ε" in sp.pretty(vdp, use_unicode=True)
    mu = sp.Symbol("mu")
    assert "mu" in sp.latex(w.subs(EPS, mu))  # only eps is shown as epsilon


def test_high_order_exact_series_stay_exact():
    """Order 24 exact: 1/omega**2 against SymPy's series of 1/(the polynomial)."""
    lc = limit_cycle((1 - X**2) * V, 24)
    w2 = lc.frequency**2
    inv = 1 / w2
    ref = sp.series(1 / w2.removeO(), EPS, 0, 25)
    assert inv == ref and all(c.is_Rational for c in inv.coefficients)


def test_float_series_arithmetic():
    lc = limit_cycle((1 - X**2) * V, 6, arithmetic="float")
    exact = limit_cycle((1 - X**2) * V, 6).frequency
    prod = lc.frequency * lc.frequency
    ref = exact * exact
    assert all(abs(float(a) - float(b)) < 1e-15 for a, b in zip(prod.coefficients, ref.coefficients, strict=True))
