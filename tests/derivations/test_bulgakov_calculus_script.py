"""derivations/bulgakov_calculus.py reproduces the worked examples of Bulgakov (1954) ch. 1-2.

Source: seed 004_e76fcda81caa05d8 (Bulgakov, "Oscillations"); digest ../shared/research/seed-bulgakov-part1.md.
Every expected value below is computed here independently of symosc: minors and gcds, direct products and
inverses, ``Matrix.exp``, ``Matrix.jordan_form``, ``sympy.inverse_laplace_transform``, direct substitution into the
differential equations, and Parseval quadrature with mpmath.
"""

from __future__ import annotations

import importlib.util
from functools import cache
from itertools import combinations
from pathlib import Path

import mpmath
import pytest
import sympy as sp

SCRIPT = Path(__file__).resolve().parents[2] / "derivations" / "bulgakov_calculus.py"
R = sp.Rational


@cache
def _load():
    spec = importlib.util.spec_from_file_location("bulgakov_calculus", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _zero(m) -> bool:
    return sp.Matrix(m).applyfunc(sp.simplify).is_zero_matrix


def _monic(expr, var):
    return sp.Poly(expr, var).monic().as_expr()


def test_1_18_divisors_from_minors():
    """Seed §3 item 1 (§1.18): D1 = l-1, D2 = (l-1)^2 (l-2), E1 = l-1, E2 = (l-1)(l-2), elementary divisors
    l-1, l-1, l-2; expected values from the gcd of the minors, and U f V = S with unimodular U, V."""
    mod = _load()
    res = mod.section_1_18()
    l, f = mod.l, res["f"]
    d1 = _monic(sp.gcd_list(list(f)), l)
    minors = [f[:, list(c)].det() for c in combinations(range(3), 2)]
    d2 = _monic(sp.gcd_list(minors), l)
    assert sp.expand(res["D"][0] - d1) == 0 and sp.expand(res["D"][1] - d2) == 0
    assert sp.expand(d2 - (l - 1) ** 2 * (l - 2)) == 0
    e2 = sp.cancel(d2 / d1)
    assert sp.expand(res["E"][0] - d1) == 0 and sp.expand(res["E"][1] - e2) == 0
    roots = {}
    for e in (d1, e2):
        for r, k in sp.roots(e, l).items():
            roots.setdefault(r, []).append(k)
    assert {r: sorted(v) for r, v in res["elementary_divisors"].items()} == roots == {1: [1, 1], 2: [1]}
    assert sp.expand(res["U"] * f * res["V"] - res["S"]) == sp.zeros(2, 3)
    for m in (res["U"], res["V"]):
        det = sp.simplify(m.det())
        assert det.is_number and det != 0


def test_1_21_left_division():
    """Seed §3 item 2 (§1.21 Ex. 5, reconstructed): g = f S + T with S = [[-l+7, -1], [3l-22, 3]], T = [[59, -8],
    [10, 0]]; S is the polynomial part of f^-1 g (computed here by scalar polynomial division)."""
    mod = _load()
    res = mod.section_1_21()
    l, f, g = mod.l, res["f"], res["g"]
    assert sp.expand(f * res["S"] + res["T"] - g) == sp.zeros(2, 2)
    assert sp.expand(f.det() - (-(l**2) - 7 * l + 2)) == 0 == sp.expand(res["det_f"] - f.det())
    q = (f.inv() * g).applyfunc(sp.cancel)
    poly_part = q.applyfunc(lambda e: sp.div(*sp.fraction(e), l)[0])
    assert sp.expand(poly_part - res["S"]) == sp.zeros(2, 2)
    assert res["S"] == sp.Matrix([[-l + 7, -1], [3 * l - 22, 3]])
    assert res["T"] == sp.Matrix([[59, -8], [10, 0]])


def test_1_22_luzin_form():
    """Seed §3 item 3 (§1.22 Ex. 1, reconstructed): u f = [[1, -3/7], [0, l^2 + 7l/3 + 8/3]], det u = 1/3
    (report's computation; the print is illegible); det f = 3l^2 + 7l + 8 = 3 * product of the pivots."""
    mod = _load()
    res = mod.section_1_22()
    l, f = mod.l, res["f"]
    assert sp.expand(res["U"] * f - res["H"]) == sp.zeros(2, 2)
    assert res["det_U"] == R(1, 3) == sp.simplify(res["U"].det())
    assert sp.expand(res["H"] - sp.Matrix([[1, R(-3, 7)], [0, l**2 + R(7, 3) * l + R(8, 3)]])) == sp.zeros(2, 2)
    assert sp.expand(3 * res["H"][0, 0] * res["H"][1, 1] - f.det()) == 0


def test_1_35_rational_function():
    """Seed §3 item 4 (§1.35): R(l) = (l+1)/(4l) of z = [[4,-3],[2,-1]] is (1/8)[[1,3],[-2,6]] = (z + E)(4z)^-1,
    with eigenvalues R(1) = 1/2, R(2) = 3/8."""
    res = _load().section_1_35()
    z = res["z"]
    direct = (z + sp.eye(2)) * (4 * z).inv()
    assert res["R"] == direct == sp.Matrix([[1, 3], [-2, 6]]) / 8
    assert set(res["eigenvalues"]) == set(direct.eigenvals()) == {R(1, 2), R(3, 8)}


def test_1_36_divisor_splitting():
    """Seed §3 item 5 (§1.36): S(l) = l/(1+l^2) of J_2(1) is E/2 (two linear divisors, S'(1) = 0); of J_2(2) it
    keeps one quadratic divisor.  Direct product z (E + z^2)^-1 and sympy's Jordan form."""
    res = _load().section_1_36()
    for key, z in (("Sz", sp.Matrix([[1, 1], [0, 1]])), ("Sz2", sp.Matrix([[2, 1], [0, 2]]))):
        assert res[key] == z * (sp.eye(2) + z**2).inv()
    assert res["Sz"] == sp.eye(2) / 2 and res["divisors"] == {R(1, 2): [1, 1]}
    _, J = res["Sz2"].jordan_form()
    assert J == sp.Matrix([[R(2, 5), 1], [0, R(2, 5)]]) and res["divisors2"] == {R(2, 5): [2]}


def test_sylvester_and_confluent_exp():
    """Seed §2.1 and §3 item 14 (§1.30, §1.37): exp(zt) by Sylvester (simple roots) and by the confluent formula
    (derogatory double root; Jordan block) against Matrix.exp; F(1)^2 = Delta'(1) F(1) with Delta'(1) = -1;
    F'(2) = [[-1,0,0],[0,-1,0],[1,1,0]] of rank 2 from sympy's adjugate; eps, eta from the resolvent's Laurent
    coefficients at the double root."""
    mod = _load()
    res = mod.section_sylvester()
    l, t = mod.l, mod.t
    for z, key in (("z_simple", "exp_simple"), ("z_derogatory", "exp_derogatory"), ("z_jordan", "exp_jordan")):
        assert _zero(res[key] - (res[z] * t).exp())
    F1 = (l * sp.eye(2) - res["z_simple"]).adjugate().subs(l, 1)
    assert res["dDelta_1"] == -1 and F1**2 == -F1
    F2p = sp.diff((l * sp.eye(3) - res["z_derogatory"]).adjugate(), l).subs(l, 2)
    assert res["F_prime_2"] == F2p == sp.Matrix([[-1, 0, 0], [0, -1, 0], [1, 1, 0]]) and F2p.rank() == 2
    assert res["index_derogatory"] == {2: (2, 1), 3: (1, 1)}
    g = ((l - 2) ** 2 * (l * sp.eye(3) - res["z_jordan"]).inv()).applyfunc(sp.cancel)
    assert res["eta_jordan"] == g.subs(l, 2)
    assert res["eps_jordan"] == sp.diff(g, l).subs(l, 2)


def test_2_19_heaviside_expansion():
    """Seed §2.5 (§2.19): p(3p+1)/((p-1)^2 (p+2)) <-> ((12t+5) e^(3t) - 5) e^(-2t)/9, and the real form
    (2.89)-(2.91) of p(p+3)/(p^2+2p+10); both against sympy.inverse_laplace_transform(X/p)."""
    mod = _load()
    res = mod.section_2_19()
    p, t = mod.p, mod.t
    tp = sp.Symbol("t", positive=True)
    book = ((12 * tp + 5) * sp.exp(3 * tp) - 5) * sp.exp(-2 * tp) / 9
    for X, key in (("X1", "x1"), ("X2", "x2")):
        ref = sp.inverse_laplace_transform(res[X] / p, p, tp)
        assert sp.simplify(res[key].subs(t, tp) - ref) == 0
    assert sp.simplify(res["x1"].subs(t, tp) - book) == 0


def test_2_21_operational_system():
    """Seed §3 item 9 (§2.21): Delta = p - 2 = det f, F = adj f, f(p)^-1 e = S(p) + Laplace[N], M = e^(2t)[c, -c],
    m = 3, s = 1; for x = sin t + t^2 the solution (one free constant y1(0)) satisfies both equations and the
    book's relation y1'(0) + y2(0) = y1(0) - x(0) at t = 0."""
    mod = _load()
    res = mod.section_2_21()
    D, t, pp = mod.D, mod.t, res["p"]
    f = res["f"].subs(D, pp)
    assert sp.expand(res["delta"] - f.det()) == 0 and sp.expand(res["delta"] - (pp - 2)) == 0
    assert sp.expand(res["adjugate"] - f.adjugate()) == sp.zeros(2, 2)
    tp = sp.Symbol("t", positive=True)
    lap_N = res["impulse"].subs(t, tp).applyfunc(lambda e: sp.laplace_transform(e, tp, pp, noconds=True))
    assert _zero(f.inv() * sp.Matrix([1, 0]) - res["feedthrough"] - lap_N)
    assert res["feedthrough"] == sp.Matrix([1, -pp - 3])
    assert _zero(res["impulse"] - sp.exp(2 * t) * sp.Matrix([3, -3]))
    y1_1, y2_0, y1_0 = sp.symbols("y1_1 y2_0 y1_0")
    assert _zero(res["free"] - sp.exp(2 * t) * (y1_1 + y2_0) * sp.Matrix([1, -1]))
    assert sum(res["orders"]) == 3 and res["degree"] == 1 and len(res["constraints"]) == 2
    x, y = res["x"], res["y"]
    eqs = [
        sp.diff(y[0], t, 2) - 2 * y[0] + sp.diff(y[1], t) - x,
        sp.diff(y[0], t, 2) + sp.diff(y[0], t) - 3 * y[0] + sp.diff(y[1], t) + y[1],
    ]
    assert all(sp.simplify(e) == 0 for e in eqs)
    at0 = {k: v.subs(t, 0) for k, v in (("y1", y[0]), ("y1p", sp.diff(y[0], t)), ("y2", y[1]), ("x", x))}
    assert sp.simplify(at0["y1p"] + at0["y2"] - (at0["y1"] - at0["x"])) == 0
    assert sp.simplify(at0["y1"] - y1_0) == 0 and y.free_symbols == {t, y1_0}


def _parseval(U, H, p) -> mpmath.mpf:
    """Integral(x^2, (t, 0, oo)) = (1/pi) Integral(|U/H (i w)|^2, (w, 0, oo)) for the Laplace image U/H."""
    fn = sp.lambdify(p, U / H, "mpmath")
    with mpmath.workdps(30):
        return mpmath.quad(lambda w: abs(fn(1j * w)) ** 2, [0, 1, 10, mpmath.inf]) / mpmath.pi


def test_2_32_integral_squares():
    """Seed §2.6 and §3 item 11 (§2.32): I2 = (a^2 w^2 + b^2)/(4 k0^2 w^3 zeta) (2.153) and the report's spot values
    0.0470679, 0.0141204, 0.0056481 by Parseval quadrature; I3 = 3/16 as Integral((t^2 e^-t/2)^2); I4 at a numeric
    Hurwitz point by quadrature, and its denominator equals the printed 2 k4 (k1k2k3 - k0k3^2 - k1^2k4) times -k0."""
    mod = _load()
    res = mod.section_2_32()
    p = mod.p
    a, b, k0, w, z, k, u = res["symbols"]
    for zv, ref in ((R(3, 10), 0.0470679), (R(1), 0.0141204), (R(5, 2), 0.0056481)):
        vals = {a: R(7, 10), b: R(13, 10), k0: 2, w: 3, z: zv}
        quad = _parseval(vals[a] * p + vals[b], 2 * (p**2 + 6 * zv * p + 9), p)
        assert res["I2_spots"][zv] == res["I2"].subs(vals)
        assert float(res["I2_spots"][zv]) == pytest.approx(float(quad), rel=1e-12)
        assert float(quad) == pytest.approx(ref, abs=5e-8)
    tp = sp.Symbol("t", positive=True)
    x3 = sp.inverse_laplace_transform(1 / (p + 1) ** 3, p, tp)
    assert sp.simplify(x3 - tp**2 * sp.exp(-tp) / 2) == 0
    assert res["I3"] == sp.integrate(x3**2, (tp, 0, sp.oo)) == R(3, 16)
    kv = dict(zip(k, (1, 4, 8, 7, 2), strict=True))  # Hurwitz: all minors positive
    uv = dict(zip(u, (R(1, 2), -1, 3, 2), strict=True))
    quad = _parseval(sum(uv[u[i]] * p ** (3 - i) for i in range(4)), sum(kv[k[i]] * p ** (4 - i) for i in range(5)), p)
    assert float(res["I4"].subs({**kv, **uv})) == pytest.approx(float(quad), rel=1e-12)
    k0_, k1, k2, k3, k4 = k
    printed = 2 * k4 * (k1 * k2 * k3 - k0_ * k3**2 - k1**2 * k4)
    assert sp.expand(res["I4_den"] - printed) == 0


def test_main_prints_every_section(capsys):
    """The script runs end to end and prints one table per section."""
    mod = _load()
    assert mod.main([]) == 0
    out = capsys.readouterr().out
    assert out.count("\n== ") == len(mod.SECTIONS)
    assert "3/16" in out and "[[59, -8], [10, 0]]" in out
