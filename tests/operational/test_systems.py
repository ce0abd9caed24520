"""Operational solution of constant-coefficient systems (Bulgakov §2.20-2.21, seed 004; report §3 item 9)."""

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc.errors import ModelError, ParameterError
from symosc.operational import solve_operational

D, t = sp.symbols("D t")
y1_0, y1_1, y2_0 = sp.symbols("y1_0 y1_1 y2_0")
x1_0, x1_1 = sp.symbols("x1_0 x1_1")

F_BOOK = sp.Matrix([[D**2 - 2, D], [D**2 + D - 3, D + 1]])
E_BOOK = sp.Matrix([1, 0])


def test_book_example_2_21_structure():
    """§2.21 example: Delta = D - 2, F = adj f, S = [1, -D-3], N = e^(2t)[3, -3],
    M = e^(2t)[y1'(0)+y2(0), -y1'(0)-y2(0)], m = 3, s = 1, two constraints."""
    sol = solve_operational(F_BOOK, E_BOOK, D=D, t=t)
    p = sol.p
    assert sp.expand(sol.delta - (p - 2)) == 0
    assert sol.adjugate == sp.Matrix([[p + 1, -p], [-(p**2 + p - 3), p**2 - 2]])
    assert sol.feedthrough == sp.Matrix([1, -p - 3])
    assert sp.simplify(sol.impulse - sp.exp(2 * t) * sp.Matrix([3, -3])) == sp.zeros(2, 1)
    c = y1_1 + y2_0
    assert sp.simplify(sol.free - sp.exp(2 * t) * sp.Matrix([c, -c])) == sp.zeros(2, 1)
    assert sol.orders == (2, 1) and sol.degree == 1 and not sol.normal_form
    assert len(sol.constraints) == 2


def test_book_example_2_21_constraints():
    """§2.21: the m - s = 2 relations (D-1)y1 + y2 = -x and (D-2)y1 = (D+1)x at t = 0, i.e.
    y1'(0) + y2(0) = y1(0) - x(0) and y1'(0) - 2 y1(0) = x'(0) + x(0): same solution set."""
    sol = solve_operational(F_BOOK, E_BOOK, D=D, t=t)
    book = [sp.Eq(y1_1 + y2_0, y1_0 - x1_0), sp.Eq(y1_1 - 2 * y1_0, x1_1 + x1_0)]
    ours = sp.solve(sol.constraints, [y1_1, y2_0], dict=True)
    theirs = sp.solve(book, [y1_1, y2_0], dict=True)
    assert ours == theirs


def test_book_example_2_21_final_solution_with_one_free_constant():
    """§2.21 final solution with x = sin t + t^2 (report: verified):
    y1 = [y1(0) - x(0)] e^(2t) + x + 3 Integral(e^(2(t-u)) x(u)),
    y2 = [-y1(0) + x(0)] e^(2t) - x' - 3x - 3 Integral(e^(2(t-u)) x(u))."""
    x = sp.sin(t) + t**2
    sol = solve_operational(F_BOOK, E_BOOK, [x], D=D, t=t)
    rel = sp.solve(sol.constraints, [y1_1, y2_0], dict=True)[0]
    y = sol.response.subs(rel)
    u = sp.Symbol("u")
    conv = sp.integrate(sp.exp(2 * (t - u)) * x.subs(t, u), (u, 0, t))
    y1_book = (y1_0 - x.subs(t, 0)) * sp.exp(2 * t) + x + 3 * conv
    y2_book = (-y1_0 + x.subs(t, 0)) * sp.exp(2 * t) - sp.diff(x, t) - 3 * x - 3 * conv
    assert sp.simplify(y[0] - y1_book) == 0
    assert sp.simplify(y[1] - y2_book) == 0
    # and the response satisfies the differential equations
    res = F_BOOK.applyfunc(lambda e: e).subs(D, 0) * 0
    lhs = sp.Matrix(
        [
            sp.diff(y[0], t, 2) - 2 * y[0] + sp.diff(y[1], t) - x,
            sp.diff(y[0], t, 2) + sp.diff(y[0], t) - 3 * y[0] + sp.diff(y[1], t) + y[1],
        ]
    )
    assert sp.simplify(lhs) == res.col(0)


def test_inconsistent_initial_data_are_overridden():
    """Stability note 10: with inconsistent y1'(0), y2(0) the solution satisfies the relations at 0+, not the
    given data; is_consistent reports it."""
    x = sp.Integer(1)
    sol = solve_operational(F_BOOK, E_BOOK, [x], [[2, 5], [7]], D=D, t=t)
    assert not sol.is_consistent()
    y = sol.response
    y1p, y10, y20 = sp.diff(y[0], t).subs(t, 0), y[0].subs(t, 0), y[1].subs(t, 0)
    assert y1p + y20 == y10 - 1  # relation 1 at 0+ with x(0) = 1
    assert y1p - 2 * y10 == 0 + 1  # relation 2: x'(0) + x(0) = 1
    assert (y10, y20) != (2, 7)
    ok = solve_operational(F_BOOK, E_BOOK, [x], [[2, 5], [-4]], D=D, t=t)
    assert ok.is_consistent()


def test_scalar_oscillator_vs_scipy():
    """Scalar (2.88): y'' + 0.4 y' + 4 y = 3 x' + x with x = sin(1.5 t), y(0)=1, y'(0)=-2, against solve_ivp."""
    k = sp.Rational(2, 5)
    x = sp.sin(sp.Rational(3, 2) * t)
    sol = solve_operational(D**2 + k * D + 4, 3 * D + 1, [x], [[1, -2]], D=D, t=t)
    f = sp.lambdify(t, sol.response[0])

    def rhs(tv, z):
        xv, dxv = np.sin(1.5 * tv), 1.5 * np.cos(1.5 * tv)
        return [z[1], 3 * dxv + xv - 0.4 * z[1] - 4 * z[0]]

    ts = np.linspace(0, 12, 25)
    ref = solve_ivp(rhs, (0, 12), [1.0, -2.0], t_eval=ts, rtol=1e-11, atol=1e-12, method="DOP853")
    assert np.max(np.abs(f(ts) - ref.y[0])) < 1e-8


def test_two_dof_system_vs_scipy():
    """Normal-form 2x2 system (coupled damped oscillators, Delta = (D^2+2D+2)(D^2+2D+4)) against solve_ivp."""
    f = sp.Matrix([[D**2 + 2 * D + 3, -1], [-1, D**2 + 2 * D + 3]])
    e = sp.Matrix([[1, 0], [0, D]])
    x1, x2 = sp.exp(-t / 2), sp.cos(t)
    sol = solve_operational(f, e, [x1, x2], [[1, 0], [0, 1]], D=D, t=t)
    assert sol.normal_form and sol.constraints == ()
    g = sp.lambdify(t, sol.response)

    def rhs(tv, z):
        a, da, b, db = z
        return [da, np.exp(-tv / 2) - 2 * da - 3 * a + b, db, -np.sin(tv) - 2 * db - 3 * b + a]

    ts = np.linspace(0, 10, 21)
    ref = solve_ivp(rhs, (0, 10), [1.0, 0.0, 0.0, 1.0], t_eval=ts, rtol=1e-11, atol=1e-12, method="DOP853")
    ours = np.array([np.real(np.asarray(g(tv), dtype=complex)).ravel() for tv in ts]).T
    assert np.max(np.abs(ours - ref.y[[0, 2]])) < 1e-8


def test_impulse_and_step_matrices():
    """N(t) is the inverse Laplace transform of F e/Delta (strictly proper part); step = S(0) + Integral(N)."""
    f = sp.Matrix([[D + 2, 1], [0, D + 1]])
    e = sp.eye(2)
    sol = solve_operational(f, e, D=D, t=t)
    p = sol.p
    tf = sp.Matrix([[p + 2, 1], [0, p + 1]]).inv()
    for i in range(2):
        for j in range(2):
            ref = sp.inverse_laplace_transform(tf[i, j], p, t).subs(sp.Heaviside(t), 1)
            assert sp.simplify(sol.impulse[i, j] - ref) == 0
            u = sp.Symbol("u")
            step_ref = sp.integrate(ref.subs(t, u), (u, 0, t))
            assert sp.simplify(sol.step[i, j] - step_ref) == 0


def test_repeated_roots_response():
    """Critically damped y'' + 2y' + y = 0, y(0)=1, y'(0)=0 -> (1 + t) e^-t (repeated root, 2.82)."""
    sol = solve_operational(D**2 + 2 * D + 1, 0, [sp.Integer(0)], [[1, 0]], D=D, t=t)
    assert sp.simplify(sol.response[0] - (1 + t) * sp.exp(-t)) == 0


def test_symbolic_input_keeps_integral():
    sol = solve_operational(D + 1, 1, None, [[0]], D=D, t=t)
    assert sol.response[0].has(sp.Integral)
    assert "OperationalSolution" in repr(sol)
    assert sol._repr_latex_().startswith("$$")


def test_bad_input():
    with pytest.raises(ModelError, match="square"):
        solve_operational(sp.Matrix([[D, 1, 2], [1, D, 3]]), sp.Matrix([1, 0]), D=D, t=t)
    with pytest.raises(ModelError, match="singular"):
        solve_operational(sp.Matrix([[D, D], [D, D]]), sp.Matrix([1, 0]), D=D, t=t)
    with pytest.raises(ModelError, match="polynomials"):
        solve_operational(sp.Matrix([[1 / D]]), 1, D=D, t=t)
    with pytest.raises(ParameterError, match="initial values"):
        solve_operational(D**2 + 1, 1, [sp.Integer(0)], [[1]], D=D, t=t)
    with pytest.raises(ParameterError, match="inputs"):
        solve_operational(D + 1, 1, [sp.Integer(0), sp.Integer(1)], [[1]], D=D, t=t)


def test_float_coefficients_irreducible_quartic_vs_scipy():
    """Float coefficients with an irreducible quartic Delta (numeric roots at 30 digits) against solve_ivp."""
    f = sp.Matrix([[D**2 + 0.7 * D + 3.1, -1.3], [-0.4, D**2 + 1.9 * D + 2.2]])
    e = sp.Matrix([1, 0])
    sol = solve_operational(f, e, [sp.exp(-t) * sp.cos(2 * t)], [[0.5, 0], [0, -1]], D=D, t=t)
    g = sp.lambdify(t, sol.response)

    def rhs(tv, z):
        a, da, b, db = z
        x = np.exp(-tv) * np.cos(2 * tv)
        return [da, x - 0.7 * da - 3.1 * a + 1.3 * b, db, -1.9 * db - 2.2 * b + 0.4 * a]

    ts = np.linspace(0, 10, 21)
    ref = solve_ivp(rhs, (0, 10), [0.5, 0.0, 0.0, -1.0], t_eval=ts, rtol=1e-11, atol=1e-12, method="DOP853")
    ours = np.array([np.real(np.asarray(g(tv), dtype=complex)).ravel() for tv in ts]).T
    assert np.max(np.abs(ours - ref.y[[0, 2]])) < 1e-8


def test_plot_draws_every_component():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    f = sp.Matrix([[D + 2, 1], [0, D + 1]])
    sol = solve_operational(f, sp.eye(2), [sp.Integer(1), sp.sin(t)], [[1], [0]], D=D, t=t)
    fig, ax = plt.subplots()
    out = sol.plot(t_max=5.0, ax=ax)
    assert out is ax and len(ax.lines) == 2
    y_end = ax.lines[0].get_ydata()[-1]
    assert abs(y_end - float(sol.response[0].subs(t, 5.0))) < 1e-9
    plt.close(fig)
