"""Step functions and difference equations (Bulgakov §2.22-2.26, seed 004; report §1 ch. 2 and feature 18).

The OCR of these sections is poor; the formulas are the report's reconstruction, so every test here compares with
direct recursion or direct summation (independent of the operational formulas)."""

import mpmath
import pytest
import sympy as sp

from symosc.errors import ModelError, ParameterError
from symosc.operational import inverse_step_image, solve_difference, step_image

n = sp.Symbol("n", integer=True, nonnegative=True)
g = sp.Symbol("gamma")
T = sp.Symbol("T")


@pytest.mark.parametrize("m", [0, 1, 2, 3])
def test_binomial_pair_2_117(m):
    """(2.117): (gamma-1)/(gamma-l)^(m+1) <-> binomial(n, m) l^(n-m), checked by direct series expansion of
    (1 - 1/gamma)^-1 X in powers of 1/gamma (the definition (2.104))."""
    lam = sp.Rational(3, 2)
    x = inverse_step_image((g - 1) / (g - lam) ** (m + 1), g, n)
    z = sp.Symbol("z")
    series = sp.series(((g - 1) / (g - lam) ** (m + 1) / (1 - 1 / g)).subs(g, 1 / z), z, 0, 12).removeO()
    for k in range(12):
        assert x.subs(n, k) == series.coeff(z, k) == sp.binomial(k, m) * lam ** (k - m)


def test_pair_2_118_and_zero_root():
    """(2.118): 1/(gamma-1)^m <-> binomial(n, m); a pole at gamma = 0 gives a Kronecker delta."""
    for m in range(1, 4):
        x = inverse_step_image(1 / (g - 1) ** m, g, n)
        assert [x.subs(n, k) for k in range(8)] == [sp.binomial(k, m) for k in range(8)]
    x = inverse_step_image((g - 1) / g**2, g, n)  # = 1/gamma - 1/gamma^2 -> x_1 = 1
    assert [x.subs(n, k) for k in range(4)] == [0, 1, 0, 0]


def test_step_image_is_scaled_z_transform():
    """(2.104): X = (1 - 1/gamma) sum x_n gamma^-n, against direct numeric summation at gamma = 3."""
    for h in (sp.Rational(1, 2) ** n, n**2, n * sp.Rational(-1, 3) ** n + 1):
        img = step_image(h, n, g)
        direct = (1 - mpmath.mpf(1) / 3) * mpmath.nsum(
            lambda k, h=h: sp.N(h.subs(n, int(k))) * mpmath.mpf(3) ** (-k), [0, 200]
        )
        assert abs(float(img.subs(g, 3)) - float(direct)) < 1e-13
        assert sp.simplify(inverse_step_image(img, g, n) - h) == 0 or all(
            inverse_step_image(img, g, n).subs(n, k) == h.subs(n, k) for k in range(8)
        )


def _recurse(coeffs, rhs, init, count):
    """y_{n+s} = (rhs_n - sum_{i<s} c_i y_{n+i}) / c_s, exact rationals."""
    s = len(coeffs) - 1
    y = list(init)
    for k in range(count - s):
        y.append((rhs(k) - sum(coeffs[i] * y[k + i] for i in range(s))) / coeffs[s])
    return y


def test_scalar_first_order_vs_recursion():
    """y(t+tau) - l y(t) = x(t) (report feature 18) with x_n = n, l = 1/2, y_0 = 3."""
    lam = sp.Rational(1, 2)
    sol = solve_difference(T - lam, 1, [n], [[3]], T=T, n=n)
    ref = _recurse([-lam, 1], lambda k: sp.Integer(k), [sp.Integer(3)], 10)
    assert [v[0] for v in sol.values(10)] == ref


def test_second_order_with_input_operator_vs_recursion():
    """y_{n+2} - y_{n+1}/2 + y_n/8 = x_{n+1} + 2 x_n (e(T) = T + 2) with x_n = (-1)^n, y_0 = 1, y_1 = 0."""
    a1, a0 = -sp.Rational(1, 2), sp.Rational(1, 8)
    x = (-1) ** n
    sol = solve_difference(T**2 + a1 * T + a0, T + 2, [x], [[1, 0]], T=T, n=n)
    ref = _recurse([a0, a1, 1], lambda k: (-1) ** (k + 1) + 2 * (-1) ** k, [sp.Integer(1), sp.Integer(0)], 10)
    assert [sp.simplify(v[0]) for v in sol.values(10)] == ref


def test_system_vs_recursion():
    """2x2 system: y1_{n+1} = y1_n/2 + y2_n + x_n, y2_{n+1} = -y1_n/4 + y2_n/3 against recursion."""
    f = sp.Matrix([[T - sp.Rational(1, 2), -1], [sp.Rational(1, 4), T - sp.Rational(1, 3)]])
    e = sp.Matrix([1, 0])
    sol = solve_difference(f, e, [sp.Integer(1)], [[1], [2]], T=T, n=n)
    y1, y2 = [sp.Integer(1)], [sp.Integer(2)]
    for _ in range(8):
        y1, y2 = [*y1, y1[-1] / 2 + y2[-1] + 1], [*y2, -y1[-1] / 4 + y2[-1] / 3]
    vals = sol.values(9)
    assert [sp.simplify(v[0]) for v in vals] == y1
    assert [sp.simplify(v[1]) for v in vals] == y2


def test_long_horizon_closed_form_vs_recursion():
    """Stability note 11: n up to 1000 with a root |gamma| > 1 and one near 1: the exact closed form equals the
    exact recursion; the float evaluation of the closed form keeps relative accuracy."""
    sol = solve_difference(
        T**2 - sp.Rational(201, 100) * T + sp.Rational(101, 100), 0, [sp.Integer(0)], [[1, 2]], T=T, n=n
    )
    y = sol.free[0]
    ref = _recurse(
        [sp.Rational(101, 100), -sp.Rational(201, 100), 1], lambda k: 0, [sp.Integer(1), sp.Integer(2)], 1001
    )
    assert sp.simplify(y.subs(n, 1000) - ref[1000]) == 0
    with mpmath.workdps(15):
        approx = float(sp.N(y.subs(n, 1000), 15))
    assert abs(approx - float(ref[1000])) <= 1e-12 * abs(float(ref[1000]))


def test_bad_input():
    with pytest.raises(ModelError, match="improper step image"):
        inverse_step_image(g**2 / (g - 1), g, n)
    with pytest.raises(ModelError, match="singular"):
        solve_difference(sp.Matrix([[T, T], [T, T]]), sp.Matrix([1, 0]), None, [[0], [0]], T=T, n=n)
    with pytest.raises(ParameterError, match="initial"):
        solve_difference(T - 1, 1, None, [[0, 1]], T=T, n=n)


def test_degenerate_system_constraints():
    """Difference analogue of the §2.21 example (leading matrix singular, deg Delta = 1 < m = 3): two relations
    among y1(0), y1(1), y2(0), equal to those of direct elimination: (T-2) y1 = (T+1) x, (T-1) y1 + y2 = -x;
    consistent data reproduce the recursion, inconsistent data are replaced by values satisfying the relations."""
    f = sp.Matrix([[T**2 - 2, T], [T**2 + T - 3, T + 1]])
    e = sp.Matrix([1, 0])
    y10, y11, y20 = sp.symbols("y1_0 y1_1 y2_0")
    sol = solve_difference(f, e, [sp.Integer(1)], None, T=T, n=n)
    assert sp.solve(sol.constraints, [y11, y20], dict=True) == [{y11: 2 * y10 + 2, y20: -y10 - 3}]
    y1 = [sp.Integer(1)]
    for _ in range(6):
        y1.append(2 * y1[-1] + 2)
    y2 = [-1 - y1[k + 1] + y1[k] for k in range(6)]
    ok = solve_difference(f, e, [sp.Integer(1)], [[1, 4], [-4]], T=T, n=n)
    vals = ok.values(6)
    assert [v[0] for v in vals] == y1[:6] and [v[1] for v in vals] == y2
    bad = solve_difference(f, e, [sp.Integer(1)], [[1, 2], [-3]], T=T, n=n).values(3)
    assert bad[1][0] == 2 * bad[0][0] + 2 and bad[0][1] == -bad[0][0] - 3
