"""E12 Ex. 2 (Bulgakov (1954), §8.52): a system whose leading matrix is singular (Δ = D - 3 has degree 1 while the
orders add up to 3), reduced to one normal coordinate and M + e - s = 2 explicit constraints.

Reference: substitute the book's result y1 = -x2 + ξ, y2 = -x1 + x2' + x2 - ξ with ξ' = 3ξ + x1 - 2x2 into the
equations with SymPy (a direct check, no use of the code's algorithm), and a numerical integration of the reduced
first-order equation against the convolution form returned by impulse_response.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from scipy.integrate import quad, solve_ivp

from symosc.linear import impulse_response

D, t = sp.symbols("D t")
F = [[D**2 - 2 * D - 1, D - 1], [D - 2, 1]]


def test_book_result_satisfies_the_equations():
    x1, x2, xi = (sp.Function(n)(t) for n in ("x1", "x2", "xi"))
    y1 = -x2 + xi
    y2 = -x1 + sp.diff(x2, t) + x2 - xi
    rules = {sp.Derivative(xi, t): 3 * xi + x1 - 2 * x2}

    def d(expr, n=1):
        for _ in range(n):
            expr = sp.diff(expr, t).subs(rules)
        return expr

    eq1 = d(y1, 2) - 2 * d(y1) - y1 + d(y2) - y2 - x1
    eq2 = d(y1) - 2 * y1 + y2 - x2
    assert sp.simplify(eq1.subs(rules)) == 0 and sp.simplify(eq2.subs(rules)) == 0
    # the two constraints of the book: y1 + y2 = -x1 + x2' and the second equation itself
    assert sp.simplify(y1 + y2 - (-x1 + sp.diff(x2, t))) == 0


def test_impulse_response_reproduces_e12():
    r = impulse_response(F, sp.eye(2), D, t)
    assert sp.simplify(r.direct - sp.Matrix([[0, -1], [-1, D + 1]])) == sp.zeros(2, 2)
    v, b = sp.Matrix([1, -1]), sp.Matrix([[1, -2]])
    assert sp.simplify(r.kernel - sp.exp(3 * t) * v * b) == sp.zeros(2, 2)


def test_convolution_form_vs_integration():
    """y = S(D) x + ∫ N(t - τ) x(τ) dτ for x1 = sin t, x2 = cos 2t, against integrating ξ' = 3ξ + x1 - 2x2 from
    ξ(0) = 0."""
    r = impulse_response(F, sp.eye(2), D, t)
    N = sp.lambdify(t, r.kernel, "numpy")

    def x(s):
        return np.array([np.sin(s), np.cos(2 * s)])

    T = 1.3
    conv = np.array(
        [quad(lambda s, i=i: (np.asarray(N(T - s), float) @ x(s))[i], 0, T, epsabs=1e-12)[0] for i in (0, 1)]
    )
    direct = np.array([-np.cos(2 * T), -np.sin(T) + (-2 * np.sin(2 * T)) + np.cos(2 * T)])  # S(D) x
    sol = solve_ivp(lambda s, z: [3 * z[0] + np.sin(s) - 2 * np.cos(2 * s)], (0, T), [0.0], rtol=1e-12, atol=1e-14)
    xi = sol.y[0, -1]
    book = np.array([-np.cos(2 * T) + xi, -np.sin(T) - 2 * np.sin(2 * T) + np.cos(2 * T) - xi])
    assert np.allclose(direct + conv, book, atol=1e-9)
