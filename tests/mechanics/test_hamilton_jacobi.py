"""Hamilton-Jacobi separation and action variables vs textbook closed forms (Goldstein §10.7-10.8; Landau &
Lifshitz §49-50) and vs the complete elliptic integral for the pendulum."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc import ModelError, t
from symosc.mechanics import action_variable, action_variable_numeric, separate_hamilton_jacobi

q, p = sp.symbols("q p", real=True)
r, th, pr, pth = sp.symbols("r theta p_r p_theta", positive=True)
m, w, k, g, l = sp.symbols("m omega k g l", positive=True)
h = sp.Symbol("h", real=True)
E = sp.Symbol("E", negative=True)
_TIGHT = {"method": "DOP853", "rtol": 1e-12, "atol": 1e-12}


def test_oscillator_action_and_frequency():
    av = action_variable(p**2 / (2 * m) + m * w**2 * q**2 / 2, q, p, h)
    assert av.action == h / w
    assert av.frequency == w and sp.simplify(av.period - 2 * sp.pi / w) == 0
    assert av.energy == av.action_symbol * w


def test_kepler_radial_action_and_degenerate_frequencies():
    """J_r = -p_theta + k sqrt(m / (-2E)); E = -m k^2 / (2 (J_r + J_theta)^2) (Goldstein, eq. (10.137))."""
    sep = separate_hamilton_jacobi(pr**2 / (2 * m) + pth**2 / (2 * m * r**2) - k / r, [r, th], [pr, pth], E)
    a = sep.constants[th]
    Hr = pr**2 / (2 * m) + a**2 / (2 * m * r**2) - k / r
    av = action_variable(Hr.xreplace({a: sp.Symbol("L", positive=True)}), r, pr, E)
    L = sp.Symbol("L", positive=True)
    assert sp.simplify(av.action - (-L + k * sp.sqrt(m / (-2 * E)))) == 0
    assert sp.simplify(av.energy - (-m * k**2 / (2 * (av.action_symbol + L) ** 2))) == 0
    # Kepler's third law: period 2 pi k sqrt(m) / (-2E)^(3/2), independent of L
    assert sp.simplify(av.period - 2 * sp.pi * k * sp.sqrt(m) / (-2 * E) ** sp.Rational(3, 2)) == 0
    # the separated momentum is dW/dr
    assert sp.simplify(sep.momenta[pr] ** 2 - 2 * m * (E + k / r - a**2 / (2 * m * r**2))) == 0


def test_pendulum_libration_elliptic_period():
    """Period of a libration 4 sqrt(l/g) K(k^2), k = sin(a/2) (Landau & Lifshitz, §11, problem 1); and the
    action's derivative dJ/dh = period / (2 pi)."""
    H = p**2 / (2 * m * l**2) - m * g * l * sp.cos(q)
    vals = {"m": 1.3, "g": 9.81, "l": 0.7}
    amp = 2.0
    energy = -1.3 * 9.81 * 0.7 * mpmath.cos(amp)
    J, T = action_variable_numeric(H, q, p, float(energy), vals, (-amp + 0.01, amp - 0.01))
    with mpmath.workdps(30):
        ref = 4 * mpmath.sqrt(mpmath.mpf("0.7") / mpmath.mpf("9.81")) * mpmath.ellipk(mpmath.sin(amp / 2) ** 2)
    assert abs(T - ref) / ref < 1e-12
    # J'(h) = T / (2 pi) by a finite difference of the numeric action
    dh = 1e-6
    J2, _ = action_variable_numeric(H, q, p, float(energy) + dh, vals, (-amp - 0.01, amp + 0.01))
    assert abs((J2 - J) / dh - T / (2 * mpmath.pi)) / (T / (2 * mpmath.pi)) < 1e-5


def test_bad_input():
    with pytest.raises(ModelError, match="no closed form"):
        action_variable(p**2 / 2 - sp.cos(q), q, p, h)
    with pytest.raises(ModelError, match="quadratic in p"):
        action_variable(p**4 + q**2, q, p, h)
    with pytest.raises(ModelError, match=r"does not separate additively in r, theta.*coupling terms r\*theta"):
        separate_hamilton_jacobi(pr**2 + pth**2 + r * th, [r, th], [pr, pth])
    with pytest.raises(ModelError, match="time"):
        separate_hamilton_jacobi(p**2 + q**2 * t, [q], [p])


# ---------------------------------------------------------------- Stäckel/Liouville separation (Landau & Lifshitz §48)
x, y, px, py = sp.symbols("x y p_x p_y", real=True)
ph, pph = sp.symbols("phi p_phi", positive=True)
c = sp.Symbol("c", positive=True)
fa, fb, ff = sp.Function("a"), sp.Function("b"), sp.Function("f")


def _solves_hamilton_jacobi(H, sep, coordinates, momenta):
    """Independent check of a complete integral: dW/dq_j = p_j(q_j) substituted into H gives h identically
    (Bulgakov (1954), eq. (3.146)), and each p_j depends on its own coordinate only."""
    W = sep.characteristic_function
    sub = {}
    for q_, p_ in zip(coordinates, momenta, strict=True):
        dW = W.diff(q_).doit()
        assert not (dW.free_symbols & (set(coordinates) - {q_}))
        sub[p_] = dW
    return sp.simplify(H.xreplace(sub) - sep.energy_symbol) == 0


def _hamilton_rhs(H, qs, ps, vals):
    """Canonical equations dq/dt = dH/dp, dp/dt = -dH/dq by lambdify (no symosc machinery)."""
    Hn = H.xreplace(vals)
    grads = [Hn.diff(p_) for p_ in ps] + [-Hn.diff(q_) for q_ in qs]
    fn = sp.lambdify([*qs, *ps], grads, "numpy")
    return lambda _t, s: fn(*s)


def test_separation_cartesian_separable_potential():
    """U = k x^2/2 + c y^4 separates in Cartesian coordinates with the factor 1: p_x^2/(2m) + k x^2/2 = beta_x,
    p_y^2/(2m) + c y^4 = h - beta_x (Landau & Lifshitz, §48); beta_x is conserved along a numerical orbit."""
    H = (px**2 + py**2) / (2 * m) + k * x**2 / 2 + c * y**4
    sep = separate_hamilton_jacobi(H, [x, y], [px, py], h)
    bx = sep.constants[x]
    assert sep.factors == (1,)
    assert sp.simplify(sep.momenta[px] ** 2 - 2 * m * (bx - k * x**2 / 2)) == 0
    assert sp.simplify(sep.momenta[py] ** 2 - 2 * m * (h - bx - c * y**4)) == 0
    assert _solves_hamilton_jacobi(H, sep, [x, y], [px, py])
    vals = {m: 1.2, k: 2.0, c: 0.7}
    sol = solve_ivp(_hamilton_rhs(H, [x, y], [px, py], vals), (0, 30), [0.4, -0.3, 0.5, 0.9], **_TIGHT)
    eq_x = next(e for e in sep.equations if bx in e.rhs.free_symbols and py not in e.lhs.free_symbols)
    G = sp.lambdify([x, px], eq_x.lhs.xreplace(vals))
    beta = G(sol.y[0], sol.y[2])
    assert np.ptp(beta) < 1e-10 * abs(beta[0])
    assert np.ptp(sol.y[2]) > 0.1  # p_x itself is not conserved


def test_separation_polar_noncentral_term():
    """2-D motion in U = -k/r + c cos(theta)/r^2 (Landau & Lifshitz, §48, problem of the form a(r) + b(theta)/r^2):
    multiplying by 2 m r^2 gives p_theta^2 + 2 m c cos(theta) = beta and p_r^2 = 2m (h + k/r) - beta/r^2.
    beta (not p_theta) is conserved along a numerically integrated orbit."""
    H = pr**2 / (2 * m) + pth**2 / (2 * m * r**2) - k / r + c * sp.cos(th) / r**2
    sep = separate_hamilton_jacobi(H, [r, th], [pr, pth], h)
    beta = sep.constants[th]
    assert sep.factors == (2 * m * r**2,)
    assert sp.Eq(pth**2 + 2 * m * c * sp.cos(th), beta) in sep.equations
    assert sp.simplify(sep.momenta[pr] ** 2 - (2 * m * (h + k / r) - beta / r**2)) == 0
    assert sp.simplify(sep.momenta[pth] ** 2 - (beta - 2 * m * c * sp.cos(th))) == 0
    assert _solves_hamilton_jacobi(H, sep, [r, th], [pr, pth])
    vals = {m: 1.0, k: 1.0, c: 0.05}
    sol = solve_ivp(_hamilton_rhs(H, [r, th], [pr, pth], vals), (0, 40), [1.0, 0.3, 0.1, 1.0], **_TIGHT)
    b_num = sol.y[3] ** 2 + 2 * 0.05 * np.cos(sol.y[1])
    assert np.ptp(b_num) < 1e-9 * abs(b_num[0])
    assert np.ptp(sol.y[3]) > 1e-2  # angular momentum is not conserved
    # the radial separated equation holds along the orbit with h = H(initial state) and this beta
    h0 = float(H.xreplace(vals).xreplace(dict(zip([r, th, pr, pth], sol.y[:, 0], strict=True))))
    radial = next(e for e in sep.equations if pr in e.lhs.free_symbols)
    res = sp.lambdify([r, pr], (radial.lhs - radial.rhs).xreplace({**vals, h: h0, beta: b_num[0]}))
    assert np.abs(res(sol.y[0], sol.y[2])).max() < 1e-8


def test_separation_spherical_landau_48():
    """U = a(r) + b(theta)/r^2 in spherical coordinates, Landau & Lifshitz eqs. (48.5)-(48.6):
    (dS/dtheta)^2 + 2 m b(theta) + p_phi^2 / sin^2(theta) = beta, (1/2m)(dS/dr)^2 + a(r) + beta/(2 m r^2) = E;
    with an added f(phi)/(r^2 sin^2 theta) the (theta, phi) group separates again (factor sin^2 theta)."""
    T = pr**2 / (2 * m) + pth**2 / (2 * m * r**2) + pph**2 / (2 * m * r**2 * sp.sin(th) ** 2)
    H = T + fa(r) + fb(th) / r**2
    sep = separate_hamilton_jacobi(H, [r, th, ph], [pr, pth, pph], h)
    al, beta = sep.constants[ph], sep.constants[th]
    assert sp.simplify(sep.momenta[pth] ** 2 - (beta - 2 * m * fb(th) - al**2 / sp.sin(th) ** 2)) == 0
    assert sp.simplify(sep.momenta[pr] ** 2 / (2 * m) + fa(r) + beta / (2 * m * r**2) - h) == 0
    H2 = H + ff(ph) / (r**2 * sp.sin(th) ** 2)
    sep2 = separate_hamilton_jacobi(H2, [r, th, ph], [pr, pth, pph], h)
    assert sep2.factors == (2 * m * r**2, sp.sin(th) ** 2)
    assert set(sep2.constants) == {(th, ph), ph}
    assert sp.simplify(sep2.momenta[pph] ** 2 - (sep2.constants[ph] - 2 * m * ff(ph))) == 0
    assert _solves_hamilton_jacobi(H2, sep2, [r, th, ph], [pr, pth, pph])


def test_separation_parabolic_coordinates():
    """U = (a(xi) + b(eta))/(xi + eta) in parabolic coordinates (Landau & Lifshitz, eqs. (48.11)-(48.13)):
    the factor m (xi + eta) is found automatically; 2 xi p_xi^2 + m a(xi) - m E xi + p_phi^2/(2 xi) = -beta."""
    xi, eta, pxi, peta = sp.symbols("xi eta p_xi p_eta", positive=True)
    H = 2 / (m * (xi + eta)) * (xi * pxi**2 + eta * peta**2) + pph**2 / (2 * m * xi * eta)
    H += (fa(xi) + fb(eta)) / (xi + eta)
    sep = separate_hamilton_jacobi(H, [xi, eta, ph], [pxi, peta, pph], h)
    al, beta = sep.constants[ph], sep.constants[eta]
    assert sp.simplify(sep.factors[0] - m * (xi + eta)) == 0
    lhs_xi = 2 * xi * pxi**2 + m * fa(xi) - m * h * xi + al**2 / (2 * xi)
    assert any(sp.simplify(e.lhs - e.rhs - (lhs_xi + beta)) == 0 for e in sep.equations)
    assert _solves_hamilton_jacobi(H, sep, [xi, eta, ph], [pxi, peta, pph])


def test_separation_fails_with_named_obstacle():
    """Hénon-Heiles (x^2 y couples x and y) and a term r theta do not separate: the error names the coupling
    term for each factor tried; a bad explicit factor too."""
    H = (px**2 + py**2) / 2 + (x**2 + y**2) / 2 + x**2 * y - y**3 / 3
    with pytest.raises(ModelError, match=r"does not separate additively in x, y .*factor 1: coupling terms x\*\*2\*y"):
        separate_hamilton_jacobi(H, [x, y], [px, py])
    Hp = pr**2 / (2 * m) + pth**2 / (2 * m * r**2) + c * sp.cos(th) / r**2
    with pytest.raises(ModelError, match="factor r: coupling terms"):
        separate_hamilton_jacobi(Hp, [r, th], [pr, pth], factor=r)
