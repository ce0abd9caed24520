"""The table of images of Bulgakov §2.18 (seed 004, research report seed-bulgakov-part1.md §2.4).

Each entry is checked independently: against ``p * sympy.laplace_transform`` for the analytic originals, and by
direct numeric integration ``p * Integral(x exp(-p t))`` (mpmath, piecewise over the steps) for step functions.
"""

import mpmath
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.errors import ModelError
from symosc.operational import CARSON_TABLE, carson, carson_by_table, carson_matrix_exp, inverse_carson, table_entry

p = sp.Symbol("p")
t = sp.Symbol("t")
T_TABLE = sp.Symbol("t")  # the table uses symosc.symbols.t == Symbol("t")

ANALYTIC = [e for e in CARSON_TABLE if not e.original.has(sp.floor, sp.Heaviside)]
STEPS = [e for e in CARSON_TABLE if e.original.has(sp.floor, sp.Heaviside)]


def _params(entry, m):
    vals = {}
    for s in entry.params:
        vals[s.name] = {
            "m": m,
            "lambda": sp.Rational(1, 2),
            "tau": sp.Rational(7, 10),
            "tau0": sp.Rational(3, 10),
            "a": sp.Rational(2, 5),
            "b": sp.Rational(11, 10),
            "epsilon": -sp.Rational(1, 3),
            "omega": 2,
        }[s.name]
    return vals


@pytest.mark.parametrize("entry", ANALYTIC, ids=lambda e: f"{e.equation} {e.name}")
def test_analytic_entries_against_sympy_laplace(entry):
    """§2.18 rows (2.7), (2.50)-(2.57), (2.146)-(2.149): image == p * laplace_transform(original), symbolic params."""
    ms = [1, 3] if any(s.name == "m" for s in entry.params) else [None]  # m = 0 rows are (2.50)-(2.57)
    for m in ms:
        orig, image = entry.original, entry.image
        if m is not None:  # general-m rows: numeric parameters keep SymPy's transform fast
            orig, image = entry.substitute(_params(entry, m))
        lap = sp.laplace_transform(orig, T_TABLE, p, noconds=True)
        diff = sp.simplify(sp.expand_complex(sp.together(p * lap - image)))
        if diff != 0:  # symbolic simplification can stall: check at random numbers
            for vals in (
                {"lambda": 0.3, "epsilon": -0.7, "omega": 1.3, "p": 2.1},
                {"lambda": -0.2, "epsilon": 0.1, "omega": 0.4, "p": 3.3},
            ):
                sub = {s: vals[s.name] for s in diff.free_symbols}
                assert abs(complex(diff.subs(sub))) < 1e-12


@pytest.mark.parametrize("entry", STEPS, ids=lambda e: f"{e.equation} {e.name}")
def test_step_entries_by_direct_integration(entry):
    """§2.18 rows (2.58)-(2.63), (2.69), (2.71): p * Integral(x exp(-p t)) by mpmath quadrature piecewise."""
    for m in [0, 2] if any(s.name == "m" for s in entry.params) else [None]:
        vals = _params(entry, m)
        orig, image = entry.substitute(vals)
        orig = sp.expand_func(orig)
        pv = sp.Rational(17, 10)
        f = sp.lambdify(
            T_TABLE,
            orig * sp.exp(-pv * T_TABLE),
            modules=["mpmath", {"Heaviside": lambda z, h=None: 1 if z > 0 else 0}],
        )
        # breakpoints at every jump: k tau, tau0 + k tau, a, b (up to t = 26, where exp(-p t) < 1e-19)
        tau, tau0 = vals.get("tau", sp.Rational(7, 10)), vals.get("tau0", 0)
        jumps = {sp.Rational(k) * tau for k in range(40)} | {tau0 + k * tau for k in range(40)}
        jumps |= {vals.get("a", 0), vals.get("b", 0)}
        pts = [*sorted(mpmath.mpf(sp.Rational(j).p) / sp.Rational(j).q for j in jumps if j < 26), mpmath.mpf(26)]
        with mpmath.workdps(20):
            val = pv * mpmath.quad(f, pts)
        expected = complex(image.subs(p, pv).evalf(20))
        assert abs(complex(val) - expected) < 1e-12 * (1 + abs(expected))


@pytest.mark.parametrize("entry", [e for e in ANALYTIC if "m" not in [s.name for s in e.params]], ids=lambda e: e.name)
def test_rewrite_engine_reproduces_table(entry):
    """carson_by_table (rules 2.52 + linearity) gives each analytic entry of §2.18."""
    img = carson_by_table(entry.original, T_TABLE, sp.Symbol("p"))
    assert sp.simplify(img - entry.image) == 0


def test_rewrite_engine_general_m_entries():
    """(2.52) and (2.146)-(2.149) for m = 0..4 through the rewrite engine."""
    for entry in CARSON_TABLE:
        if entry.original.has(sp.floor, sp.Heaviside) or "m" not in [s.name for s in entry.params]:
            continue
        for m in range(4):
            orig, image = entry.substitute(_params(entry, m))
            img = carson_by_table(orig, T_TABLE, sp.Symbol("p"))
            for pv in (2.3, 3.1):
                d = complex((img - image).subs(sp.Symbol("p"), pv))
                assert abs(d) < 1e-12 * (1 + abs(complex(image.subs(sp.Symbol("p"), pv)))), (entry.name, m)


def test_delayed_steps_and_pulse():
    """(2.26a), (2.59): delayed quasi-polynomials through the engine."""
    assert sp.simplify(carson(sp.Heaviside(t - 2) * (t - 2) ** 2, t, p) - 2 * sp.exp(-2 * p) / p**2) == 0
    pulse = carson(sp.Heaviside(t - 1) - sp.Heaviside(t - 3), t, p)
    assert sp.simplify(pulse - (sp.exp(-p) - sp.exp(-3 * p))) == 0


def test_matrix_exponential_image():
    """(2.53): exp(a t) <-> p (E p - a)^-1, compared entrywise with the Carson image of Matrix.exp."""
    a = sp.Matrix([[0, 1], [-2, -3]])
    img = carson_matrix_exp(a, p)
    expm = (a * t).exp()
    for i in range(2):
        for j in range(2):
            lap = sp.laplace_transform(expm[i, j], t, p, noconds=True)
            assert sp.simplify(p * lap - img[i, j]) == 0
    with pytest.raises(ModelError, match="square"):
        carson_matrix_exp(sp.Matrix([[1, 2, 3]]), p)


def test_table_entry_lookup():
    assert table_entry("(2.51)").name == "exponential"
    with pytest.raises(KeyError, match="no table entry"):
        table_entry("bessel")


def test_carson_method_table_refuses_unsupported():
    with pytest.raises(ModelError, match="method='sympy'"):
        carson(sp.log(1 + t), t, p, method="table")


quasi = st.tuples(st.integers(-3, 3), st.integers(0, 2), st.integers(-2, 1), st.integers(0, 2))


@settings(max_examples=15, deadline=None)
@given(st.lists(quasi, min_size=1, max_size=3))
def test_roundtrip_quasi_polynomials(terms):
    """Property: inverse_carson(carson(x)) == x for quasi-polynomials c t^k e^(a t) cos/sin(w t)."""
    x = sum(c * t**k * sp.exp(a * t) * (sp.cos(w * t) if w % 2 == 0 else sp.sin(w * t)) for c, k, a, w in terms)
    back = inverse_carson(carson(x, t, p), p, t)
    for tv in (0.3, 1.7):
        assert abs(float(back.subs(t, tv)) - float(x.subs(t, tv))) < 1e-10 * (1 + abs(float(x.subs(t, tv))))


def test_phase_shifted_trigonometric_terms_stay_real():
    """Phases (sin(3t+1), cos(t+2)) come out real (no I) and agree with p * laplace_transform numerically."""
    for x in (sp.exp(-t) * sp.sin(3 * t + 1), sp.exp(-t - 2) * sp.cos(t + 2)):
        img = carson(x, t, p)
        assert not img.has(sp.I)
        ref = p * sp.laplace_transform(sp.expand_trig(x), t, p, noconds=True)
        for v in (1.1, 4.0):
            assert abs(complex((img - ref).subs(p, v))) < 1e-13


def test_symbolic_phase():
    """cos(w t + phi) <-> p (p cos phi - w sin phi)/(p^2 + w^2), real parameters, no I left."""
    w = sp.Symbol("w", positive=True)
    phi = sp.Symbol("phi", real=True)
    img = carson(sp.cos(w * t + phi), t, p)
    assert sp.simplify(img - p * (p * sp.cos(phi) - w * sp.sin(phi)) / (p**2 + w**2)) == 0
    assert not img.has(sp.I)
