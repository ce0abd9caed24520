"""Averaging (Krylov–Bogoliubov / van der Pol shortened equations): Bulgakov ch. 5 E and ch. 6.

Every numeric claim is checked against direct integration of the original equation with SciPy (independent of the
averaging code), or against exact closed forms from the research report seed-bulgakov-part2.md.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from symosc.errors import ModelError, ParameterError
from symosc.nonlinear.averaging.shortened import a, averaged_equations, describing_function
from symosc.symbols import t

x, v = sp.symbols("x v", real=True)
eps, mu, zeta, R = sp.symbols("epsilon mu zeta R", positive=True)


# ------------------------------------------------------------------------------------------ autonomous
def test_van_der_pol_shortened_equation_matches_book():
    """Seed 004, §5.31 (report §2.3): a' = (1/2)(kappa a - lambda a^3/4), closed form (5.373) solves it."""
    kappa, lam = sp.symbols("kappa lambda", positive=True)
    avg = averaged_equations(x - (kappa - lam * x**2) * v)
    assert sp.simplify(avg.a_dot - (kappa * a - lam * a**3 / 4) / 2) == 0
    assert sp.simplify(avg.phase_dot - 1) == 0
    # the book's closed-form transient satisfies the shortened equation exactly
    a0, tt = sp.symbols("a0 t", positive=True)
    astar = 2 * sp.sqrt(kappa / lam)
    at = a0 * astar / sp.sqrt(a0**2 + (astar**2 - a0**2) * sp.exp(-kappa * tt))
    assert sp.simplify(sp.diff(at, tt) - avg.a_dot.subs(a, at)) == 0
    regimes = avg.stationary()
    assert [r.amplitude for r in regimes] == [0, astar]
    assert [r.stable for r in regimes] == [False, True]


def test_van_der_pol_envelope_vs_direct_integration():
    """Seed 004, §5.31 / report §3 item 11: averaged envelope vs integrated vdP, eps = 0.05: error O(eps)."""
    e = 0.05
    avg = averaged_equations(x - eps * (1 - x**2) * v)
    tt = np.linspace(0, 150, 301)
    env = avg.envelope(0.2, tt, {"epsilon": e})
    sol = solve_ivp(
        lambda _t, y: [y[1], -y[0] + e * (1 - y[0] ** 2) * y[1]],
        (0, 150),
        [0.2, 0.0],
        t_eval=tt,
        rtol=1e-10,
        atol=1e-12,
    )
    amp = np.hypot(sol.y[0], sol.y[1])
    closed = 0.2 * 2 / np.sqrt(0.04 + (4 - 0.04) * np.exp(-e * tt))
    assert np.max(np.abs(env - closed)) < 1e-7  # the shortened ODE integrated numerically = the closed form
    assert np.max(np.abs(amp - env)) < 2 * e  # first-order averaging: O(eps) error
    assert abs(amp[-1] - 2) < 2 * e


def test_stationary_numeric_rayleigh_type():
    """x'' + x = eps (v - v^3/3)*... : Rayleigh oscillator, numeric stationary amplitude 2/sqrt(3)... vs integration."""
    e = 0.05
    avg = averaged_equations(x - eps * (v - v**3))
    regs = avg.stationary({"epsilon": e})
    amps = [float(r.amplitude) for r in regs]
    assert amps[0] == 0 and not regs[0].stable
    # a' = eps a (1/2 - 3 a^2/8) -> a* = 2/sqrt(3)
    assert amps[1] == pytest.approx(2 / math.sqrt(3), rel=1e-12) and regs[1].stable
    sol = solve_ivp(lambda _t, y: [y[1], -y[0] + e * (y[1] - y[1] ** 3)], (0, 400), [0.3, 0], rtol=1e-9, atol=1e-12)
    tail = sol.y[0][sol.t > 350]
    assert np.max(np.abs(tail)) == pytest.approx(2 / math.sqrt(3), rel=0.03)


def test_preloaded_spring_frequency_vs_exact_period():
    """Seed 004, §5.29 example (1), report §3 item 12: f = b sign q + c q, omega^2 = c + 4b/(pi a)."""
    b, c = sp.symbols("b c", positive=True)
    avg = averaged_equations(b * sp.sign(x) + c * x, omega=sp.sqrt(c))
    # averaged frequency of the conservative system: omega^2 = J(a)/a; Psi is that to first order in the
    # detuning; use the describing function directly (Bulgakov (5.347))
    J = describing_function(b * sp.sign(x) + c * x)
    assert sp.simplify(J - (c * a + 4 * b / sp.pi)) == 0
    assert sp.simplify(avg.Phi) == 0
    bv, cv = 0.5, 2.0
    for amp, book_avg, book_exact, tol in ((0.1, 2.8924, 2.8657, 0.012), (1.0, 1.62377, 1.62216, 0.0015)):
        w_avg = math.sqrt(float(J.subs({a: amp, b: bv, c: cv})) / amp)
        assert w_avg == pytest.approx(book_avg, abs=1e-4)
        # exact period by event-driven integration (x = 0 crossings), independent of the formulae
        ev = lambda _t, y: y[0]  # noqa: E731
        ev.direction = -1
        sol = solve_ivp(
            lambda _t, y: [y[1], -bv * np.sign(y[0]) - cv * y[0]],
            (0, 20),
            [amp, 0.0],
            events=ev,
            rtol=1e-11,
            atol=1e-13,
        )
        tz = sol.t_events[0]
        w_exact = 2 * math.pi / (tz[1] - tz[0])
        assert w_exact == pytest.approx(book_exact, abs=2e-4)
        assert abs(w_avg - w_exact) / w_exact < tol


def test_coulomb_friction_average_decrement():
    """Seed 004, §5.6: Coulomb friction loses 4B per period; averaging gives a' = -2F/pi (B = F/k^2, k = 1)."""
    F = sp.Symbol("F", positive=True)
    avg = averaged_equations(x + F * sp.sign(v))
    assert sp.simplify(avg.a_dot + 2 * F / sp.pi) == 0
    assert 4 * 0.01 / (2 * math.pi) == pytest.approx(float((-avg.a_dot).subs(F, 0.01)))


@settings(max_examples=15, deadline=None)
@given(st.integers(min_value=0, max_value=6), st.integers(min_value=-5, max_value=5))
def test_describing_function_of_odd_powers(k, c):
    """J(c x^(2k+1)) = c a^(2k+1) * 2 binom(2k+2, k+1)/2^(2k+2) (Wallis), linear in g."""
    n = 2 * k + 1
    J = describing_function(c * x**n + x)
    expected = c * a**n * sp.Rational(2 * math.comb(n + 1, (n + 1) // 2), 2 ** (n + 1)) + a
    assert sp.expand(J - expected) == 0


def test_describing_function_even_power_vanishes():
    """Even nonlinearities have no first harmonic (they shift the center instead, §5.29)."""
    assert describing_function(x**2 + x**4) == 0


# ------------------------------------------------------------------------------------------ forced
def test_forced_duffing_shortened_equations_symbolic():
    """Seed 004, §6.4 (6.61): W for Duffing with viscous damping; M1 = 2 eps."""
    avg = averaged_equations(x + mu * x**3 + 2 * zeta * v, forcing=R)
    nu = avg.nu
    J = a + 3 * mu * a**3 / 4
    W_book = (4 * zeta**2 * a**2 * nu**2 + (nu**2 * a - J) ** 2 - R**2) / (4 * nu**2)
    assert sp.simplify(avg.W - W_book) == 0
    assert sp.simplify(avg.M1 - 2 * zeta) == 0
    M2_book = (4 * zeta**2 * nu**2 * a + (nu**2 * a - J) * (nu**2 - sp.diff(J, a))) / (4 * nu**2 * a)
    assert sp.simplify(avg.M2 - M2_book) == 0


def test_forcing_given_as_expression_in_t():
    """A forcing written as an expression in t: its first harmonic is used (here 3 cos(nu t + 1) + harmonics)."""
    nu = sp.Symbol("nu", positive=True)
    f1 = averaged_equations(x + mu * x**3, forcing=3 * sp.cos(nu * t + 1) + sp.cos(2 * nu * t) ** 2 - sp.S.Half)
    assert sp.simplify(f1.R - 3) == 0 and sp.simplify(f1.forcing_phase - 1) == 0


DUFF = {"mu": 0.05, "zeta": 0.02, "R": 0.1}


def _duffing_rhs(nu):
    m, z, r = DUFF["mu"], DUFF["zeta"], DUFF["R"]
    return lambda tt, y: [y[1], -y[0] - m * y[0] ** 3 - 2 * z * y[1] + r * np.cos(nu * tt)]


def _steady_amplitude(nu, x0, v0, periods=120):
    T = 2 * math.pi / nu
    sol = solve_ivp(_duffing_rhs(nu), (0, periods * T), [x0, v0], rtol=1e-8, atol=1e-10, dense_output=True)
    tail = np.linspace((periods - 3) * T, periods * T, 600)
    return float(np.max(np.abs(sol.sol(tail)[0])))


@pytest.fixture(scope="module")
def duffing_response():
    avg = averaged_equations(x + mu * x**3 + 2 * zeta * v, forcing=R)
    return avg, avg.frequency_response(DUFF, (0.9, 1.2), n=241)


def test_forced_duffing_branches_vs_direct_integration(duffing_response):
    """Seed 004, §6.4: in the bistable band both stable branches are reached by direct integration; the middle one
    is a saddle (M2 < 0)."""
    avg, fr = duffing_response
    lo, hi = fr.jump_frequencies
    nu = 0.5 * (lo + hi)
    states = avg.steady_states(DUFF, nu)
    assert [s.kind for s in states] == ["stable", "saddle", "stable"]
    for s in (states[0], states[2]):
        # start on the predicted state: x = a cos(nu t - theta) at t = 0
        x0, v0 = s.amplitude * math.cos(-s.theta), -s.amplitude * nu * math.sin(-s.theta)
        amp = _steady_amplitude(nu, x0, v0)
        assert amp == pytest.approx(s.amplitude, rel=0.03)


def test_forced_duffing_jump_frequencies_vs_direct_integration(duffing_response):
    """Seed 004, §6.4: past the upper fold the large-amplitude state no longer exists (jump down); just below it,
    it persists.  Checked by direct integration at nu = fold -/+ 1.5 %."""
    avg, fr = duffing_response
    lo, hi = fr.jump_frequencies
    assert all(f.refined for f in fr.folds)
    assert hi - lo > 0.02
    below = avg.steady_states(DUFF, hi * 0.985)[-1]
    x0, v0 = below.amplitude * math.cos(below.theta), below.amplitude * hi * 0.985 * math.sin(below.theta)
    assert _steady_amplitude(hi * 0.985, x0, v0) == pytest.approx(below.amplitude, rel=0.04)
    nu_up = hi * 1.015
    (only,) = avg.steady_states(DUFF, nu_up)
    amp = _steady_amplitude(nu_up, below.amplitude * math.cos(below.theta), 0.0, periods=200)
    assert amp == pytest.approx(only.amplitude, rel=0.05)  # jumped down to the single small state
    assert amp < 0.5 * below.amplitude


def test_duffing_folds_vs_polynomial_discriminant(duffing_response):
    """Folds = double roots of the cubic in s = a^2 (independent: numpy polynomial discriminant, bisection)."""
    _, fr = duffing_response
    m, z, r = DUFF["mu"], DUFF["zeta"], DUFF["R"]

    def nroots(nu):
        c0, k = 1 - nu**2, 0.75 * m
        rr = np.roots([k**2, 2 * c0 * k, (2 * nu * z) ** 2 + c0**2, -(r**2)])
        return int(np.sum((np.abs(rr.imag) < 1e-12) & (rr.real > 0)))

    def disc(nu):
        c0, k = 1 - nu**2, 0.75 * m
        A, B, C, D = k**2, 2 * c0 * k, (2 * nu * z) ** 2 + c0**2, -(r**2)
        return 18 * A * B * C * D - 4 * B**3 * D + B**2 * C**2 - 4 * A * C**3 - 27 * A**2 * D**2

    from scipy.optimize import brentq

    folds = sorted(brentq(disc, f - 0.01, f + 0.01, xtol=1e-14) for f in fr.jump_frequencies)
    np.testing.assert_allclose(fr.jump_frequencies, folds, rtol=1e-9)
    assert nroots(0.5 * sum(folds)) == 3 and nroots(folds[0] - 0.01) == 1 and nroots(folds[1] + 0.01) == 1


def test_backbone_duffing():
    """Skeleton curve nu^2 = J(a)/a = 1 + 3 mu a^2/4 (6.33)."""
    avg = averaged_equations(x + mu * x**3 + 2 * zeta * v, forcing=R)
    amps = np.array([0.1, 1.0, 3.0])
    np.testing.assert_allclose(avg.backbone(DUFF, amps), np.sqrt(1 + 0.75 * DUFF["mu"] * amps**2), rtol=1e-13)


def test_softening_duffing_example_book():
    """Seed 004, §6.3 worked example (report §3 item 14): lambda = 15, nu^2 = 10, mu = 16/3, R = 1.

    Steady states x* = -1/2 - 1/sqrt2 (stable), -1/2 + 1/sqrt2 (stable), 1 (unstable); the rotating-frame surface
    z = 2 nu H has its peak 21/16 + sqrt2 above A1 and its pit 21/16 - sqrt2 below A2; the separatrix level is 1/2.
    """
    lam, m_ = sp.Integer(15), sp.Rational(16, 3)
    nu = sp.sqrt(10)
    avg = averaged_equations(lam * x - m_ * x**3, forcing=1, nu=nu)
    X, Y, H = avg.hamiltonian()
    z = sp.expand(2 * nu * H)
    assert sp.expand(z - (sp.Rational(5, 2) * (X**2 + Y**2) - (X**2 + Y**2) ** 2 - X)) == 0
    x1, x2, x3 = -sp.S.Half - 1 / sp.sqrt(2), -sp.S.Half + 1 / sp.sqrt(2), sp.S.One
    for xs in (x1, x2, x3):
        assert sp.simplify(sp.diff(z, X).subs({X: xs, Y: 0})) == 0
    assert sp.simplify(z.subs({X: x1, Y: 0}) - (sp.Rational(21, 16) + sp.sqrt(2))) == 0
    assert sp.simplify(z.subs({X: x2, Y: 0}) - (sp.Rational(21, 16) - sp.sqrt(2))) == 0
    assert sp.simplify(z.subs({X: x3, Y: 0}) - sp.S.Half) == 0
    # Hamiltonian structure agrees with the van der Pol-variable equations
    _, _, xd, yd = avg.cartesian()
    assert sp.simplify(xd - sp.diff(H, Y)) == 0 and sp.simplify(yd + sp.diff(H, X)) == 0
    # numeric classification: x* = a cos(theta)
    states = avg.steady_states({})
    got = sorted((s.amplitude * math.cos(s.theta), s.kind) for s in states)
    assert [k for _, k in got] == ["center", "center", "saddle"]
    np.testing.assert_allclose([g for g, _ in got], [float(x1), float(x2), 1.0], atol=1e-10)


def test_forced_plot_runs(duffing_response):
    import matplotlib

    matplotlib.use("Agg")
    _, fr = duffing_response
    ax = fr.plot()
    assert ax.get_xlabel() == r"forcing frequency $\nu$"
    assert "folds" in repr(fr)
    styles = {line.get_label(): line.get_linestyle() for line in ax.get_lines()}
    assert styles["stable"] == "-" and styles["unstable"] == "--"  # continuous branches, stable solid
    pieces = fr.branches()
    for f in fr.folds:  # each jump joins a stable and an unstable branch at the fold point itself
        ends = [(s, (nu[0], a[0])) for nu, a, s in pieces] + [(s, (nu[-1], a[-1])) for nu, a, s in pieces]
        meeting = {s for s, end in ends if end == (f.nu, f.amplitude)}
        assert meeting == {True, False}


def test_extreme_light_damping_large_response():
    """Very light damping (zeta = 1e-4): amplitude ~ R/(2 zeta) and folds still resolved (Newton refined)."""
    avg = averaged_equations(x + mu * x**3 + 2 * zeta * v, forcing=R)
    vals = {"mu": 0.001, "zeta": 1e-4, "R": 0.01}
    fr = avg.frequency_response(vals, (0.95, 2.0), n=200)
    assert len(fr.folds) == 2 and all(f.refined for f in fr.folds)
    top = max(f.amplitude for f in fr.folds)
    # the peak lies on the backbone with a ~ R/(2 zeta nu): the upper fold amplitude is close to it
    nu_top = fr.jump_frequencies[-1]
    assert top == pytest.approx(0.01 / (2e-4 * nu_top), rel=0.01)
    assert nu_top == pytest.approx(math.sqrt(1 + 0.00075 * top**2), rel=1e-3)


# ------------------------------------------------------------------------------------------ bad input
def test_bad_inputs():
    with pytest.raises(ModelError, match="depend on t"):
        averaged_equations(x + sp.cos(t) * x)
    with pytest.raises(ModelError, match="comparison frequency"):
        averaged_equations(x**3 - eps * v)
    with pytest.raises(ModelError, match="changes sign inside a quarter"):
        describing_function(sp.sign(x - sp.Rational(1, 3)))
    with pytest.raises(ModelError, match="constant part"):
        averaged_equations(x, forcing=1 + sp.cos(sp.Symbol("nu", positive=True) * t))
    avg = averaged_equations(x + mu * x**3 + 2 * zeta * v, forcing=R)
    with pytest.raises(ParameterError, match="missing values for: R"):
        avg.steady_states({"mu": 1, "zeta": 0.1}, 1.0)
    with pytest.raises(ModelError, match="autonomous"):
        avg.stationary()
    with pytest.raises(ParameterError, match="nu_range"):
        avg.frequency_response(DUFF, (1.2, 0.9))
    with pytest.raises(ModelError, match="forced"):
        averaged_equations(x - eps * (1 - x**2) * v).M2  # noqa: B018
    with pytest.raises(ModelError, match="damped"):
        avg.hamiltonian()


# ------------------------------------------------------------------------------------------ n degrees of freedom
def test_two_mode_competition_vs_direct_integration():
    """§12.11–12.12 (multi-frequency averaging, non-resonant w = 1, sqrt2): two van der Pol modes with cross
    saturation beta.  Averaging: a_i' = (eps/2) a_i (1 - a_i^2/4 - beta a_j^2/2); both modes coexist for
    beta < 1/2 (a^2 = 4/(1 + 2 beta)), one suppresses the other for beta > 1/2.  Checked by direct integration."""
    from symosc.nonlinear.averaging.multi_frequency import averaged_equations_ndof

    x1, x2, v1, v2 = sp.symbols("x1 x2 v1 v2", real=True)
    beta = sp.Symbol("beta", positive=True)
    f = [x1 - eps * (1 - x1**2 - beta * x2**2) * v1, 2 * x2 - eps * (1 - x2**2 - beta * x1**2) * v2]
    avg = averaged_equations_ndof(f, [x1, x2], [v1, v2])
    a1, a2 = avg.amplitudes
    assert sp.expand(avg.a_dot[0] - eps / 2 * a1 * (1 - a1**2 / 4 - beta * a2**2 / 2)) == 0
    e = 0.05
    for bv, both in ((0.2, True), (1.0, False)):
        regs = avg.stationary({"epsilon": e, "beta": bv})
        stable = [r["amplitudes"] for r in regs if r["stable"]]
        if both:
            assert len(stable) == 1 and float(stable[0][0]) == pytest.approx(2 / math.sqrt(1 + 2 * bv), rel=1e-12)
        else:
            assert sorted(tuple(float(v) for v in s) for s in stable) == [(0.0, 2.0), (2.0, 0.0)]

        def rhs(_t, y, bv=bv):
            X1, V1, X2, V2 = y
            return [V1, -X1 + e * (1 - X1**2 - bv * X2**2) * V1, V2, -2 * X2 + e * (1 - X2**2 - bv * X1**2) * V2]

        sol = solve_ivp(rhs, (0, 500), [0.3, 0, 0.2, 0], rtol=1e-8, atol=1e-10, dense_output=True)
        tail = np.linspace(450, 500, 2000)
        y = sol.sol(tail)
        amp1 = np.max(np.hypot(y[0], y[1]))
        amp2 = np.max(np.hypot(y[2], y[3] / math.sqrt(2)))
        if both:
            assert amp1 == pytest.approx(2 / math.sqrt(1.4), rel=0.05) and amp2 == pytest.approx(
                2 / math.sqrt(1.4), rel=0.05
            )
        else:
            assert max(amp1, amp2) == pytest.approx(2.0, rel=0.05) and min(amp1, amp2) < 0.05


def test_ndof_resonance_refused():
    from symosc.nonlinear.averaging.multi_frequency import averaged_equations_ndof

    x1, x2, v1, v2 = sp.symbols("x1 x2 v1 v2", real=True)
    with pytest.raises(ModelError, match="resonance"):
        averaged_equations_ndof([x1 + x1**3, 4 * x2 + x1**2 * x2], [x1, x2], [v1, v2])
    with pytest.raises(ModelError, match="2 forces need 2"):
        averaged_equations_ndof([x1, x2], [x1], [v1, v2])


# ------------------------------------------------------------------------------------------ non-polynomial forces
def test_exponential_shock_absorber_book():
    """Seed 004, §5.29 example (3) (5.355)–(5.357): f = k^2 (e^q - 1): center q* = -ln I0(a),
    omega = k sqrt(2 I1(a)/(a I0(a))) = k (1 - a^2/16 + 13 a^4/1536 - ...) (Jacobi–Anger averaging)."""
    import mpmath

    k = sp.Symbol("k", positive=True)
    avg = averaged_equations(k**2 * (sp.exp(x) - 1), center=True)
    assert avg.center == -sp.log(sp.besseli(0, a))
    assert sp.simplify(avg.frequency_squared - 2 * k**2 * sp.besseli(1, a) / (a * sp.besseli(0, a))) == 0
    assert sp.simplify(avg.Phi) == 0
    for av in (0.05, 0.2):
        w = mpmath.sqrt(2 * mpmath.besseli(1, av) / (av * mpmath.besseli(0, av)))
        series = 1 - av**2 / 16 + 13 * av**4 / 1536
        assert abs(w - series) < 0.01 * av**6  # next term of the series is O(a^6) with a small coefficient


def test_damped_pendulum_by_averaging_book():
    """Seed 004, §5.30 (5.359)–(5.368): f = k^2 sin q + 2 beta q': Phi = beta (a = a0 e^{-beta t}),
    J(a) = 2 k^2 J1(a) = k^2 (a - a^3/8 + a^5/192 - ...), Psi = k (1 - a^2/16 + a^4/384 - ...) for w = k; the envelope
    is checked against direct integration (beta = 0.03): error < 1 % at a0 = 0.5, growing like a0^2."""
    k, beta = sp.symbols("k beta", positive=True)
    assert sp.simplify(describing_function(k**2 * sp.sin(x)) - 2 * k**2 * sp.besselj(1, a)) == 0
    avg = averaged_equations(k**2 * sp.sin(x) + 2 * beta * v)
    assert sp.simplify(avg.Phi - beta) == 0
    ser = sp.series(avg.Psi.subs(k, 1), a, 0, 6).removeO()
    assert sp.expand(ser - (1 - a**2 / 16 + a**4 / 384)) == 0
    b = 0.03

    def envelope_error(a0):
        sol = solve_ivp(
            lambda _t, y: [y[1], -math.sin(y[0]) - 2 * b * y[1]],
            (0, 60),
            [a0, 0],
            rtol=1e-10,
            atol=1e-12,
            dense_output=True,
        )
        tt = np.linspace(0, 60, 3001)
        q = sol.sol(tt)[0]
        peaks = [i for i in range(1, len(q) - 1) if q[i] > q[i - 1] and q[i] >= q[i + 1]]
        return max(abs(q[i] / (a0 * math.exp(-b * tt[i])) - 1) for i in peaks)

    e1, e2 = envelope_error(0.5), envelope_error(0.8)
    assert e1 < 0.01
    assert 1.8 < e2 / e1 < 3.2  # the averaging error grows like a0^2 (neglected amplitude-dependent terms)


def test_quadratic_spring_center_shift():
    """Asymmetric polynomial spring f = q + c q^2: <f(q* + a cos)> = 0 gives q* = (sqrt(1 - 2 c^2 a^2) - 1)/(2c);
    checked against the mean position of the integrated motion (c = 0.1, a = 0.5)."""
    c = sp.Symbol("c", positive=True)
    avg = averaged_equations(x + c * x**2, center=True)
    assert sp.simplify(avg.center - (sp.sqrt(1 - 2 * c**2 * a**2) - 1) / (2 * c)) == 0
    cv, av = 0.1, 0.5
    qs = float(avg.center.subs({c: cv, a: av}))
    ev = lambda _t, y: y[1]  # noqa: E731
    sol = solve_ivp(
        lambda _t, y: [y[1], -y[0] - cv * y[0] ** 2],
        (0, 30),
        [qs + av, 0],
        rtol=1e-11,
        atol=1e-13,
        dense_output=True,
        events=ev,
    )
    t_ev = sol.t_events[0]
    lo = float(sol.sol(t_ev[1])[0])
    T = t_ev[2] - t_ev[0]
    tt = np.linspace(t_ev[0], t_ev[2], 4001)
    mean = np.trapezoid(sol.sol(tt)[0], tt) / T  # time average of x over one period
    assert mean == pytest.approx(qs, abs=5e-4)
    assert 0.5 * (qs + av - lo) == pytest.approx(av, rel=1e-2)


def test_dry_friction_torus_average_table15():
    """Seed 004 §12.14 (seed-bulgakov-part3b.md T18): G(x, y) closed forms vs a direct 2-D midpoint average of
    sign(x sin u1 + y sin u2) sin u1 (independent), and Table 15 (B, R for y/x = 0.1 ... 1, 2, 5, oo)."""
    from symosc.nonlinear.averaging.multi_frequency import _B, dry_friction_ratio, dry_friction_torus_average

    n = 1200
    u = (np.arange(n) + 0.5) * 2 * np.pi / n
    U1, U2 = np.meshgrid(u, u, indexing="ij")

    def G_num(xv, yv):
        return float(np.sum(np.sign(xv * np.sin(U1) + yv * np.sin(U2)) * np.sin(U1)) * (2 * np.pi / n) ** 2)

    for xv, yv in ((1, 0), (1, 0.3), (1, 0.9), (0.5, 1), (1, 1)):
        assert dry_friction_torus_average(xv, yv) == pytest.approx(G_num(xv, yv), abs=5e-3 * 16)
    # R as the ratio of friction per unit velocity amplitude, from the numeric G
    for kv in (0.3, 0.7):
        num = (G_num(kv, 1.0) / kv) / (G_num(1.0, kv) / 1.0)
        assert dry_friction_ratio(kv) == pytest.approx(num, rel=5e-3)
    B_tab = {0.1: 0.786, 0.2: 0.789, 0.5: 0.813, 0.8: 0.872, 0.9: 0.912, 1.0: 1.000}
    R_tab = {0.1: 0.502, 0.2: 0.508, 0.5: 0.554, 0.8: 0.683, 0.9: 0.778, 1.0: 1.000, 2.0: 1.806, 5.0: 1.970}
    for kv, bv in B_tab.items():
        assert float(_B(kv)) == pytest.approx(bv, abs=6e-4)
    for kv, rv in R_tab.items():
        assert dry_friction_ratio(kv) == pytest.approx(rv, abs=6e-4)
    # the book prints 1.992 at y/x = 10; the report's "computed 1.991" is a slip: R(10) = 1/R(0.1) = 1/0.501884
    assert dry_friction_ratio(10.0) == pytest.approx(1.992, abs=6e-4)
    assert dry_friction_ratio(10.0) * dry_friction_ratio(0.1) == pytest.approx(1.0, rel=1e-14)
    assert dry_friction_ratio(0.0) == 0.5 and dry_friction_ratio(math.inf) == 2.0
    with pytest.raises(ParameterError, match="non-negative"):
        dry_friction_torus_average(-1.0, 1.0)


def test_forced_pendulum_bessel_resonance_curve():
    """Non-polynomial W (Bessel J1 from averaging sin x): x'' + 0.04 x' + sin x = 0.05 cos(nu t).  The softening
    resonance curve has two Newton-refined folds; both stable states in between are reached by direct integration
    (first-order averaging error at a ~ 1.3 rad: a few per cent)."""
    z, R_ = sp.Symbol("zeta", positive=True), sp.Symbol("R", positive=True)
    avg = averaged_equations(sp.sin(x) + 2 * z * v, forcing=R_)
    vals = {"zeta": 0.02, "R": 0.05}
    fr = avg.frequency_response(vals, (0.75, 1.05), n=41)
    assert len(fr.folds) == 2 and all(f.refined for f in fr.folds)
    nu = sum(fr.jump_frequencies) / 2
    states = avg.steady_states(vals, nu)
    assert [s.kind for s in states] == ["stable", "saddle", "stable"]
    for s in (states[0], states[2]):
        x0, v0 = s.amplitude * math.cos(s.theta), s.amplitude * nu * math.sin(s.theta)
        T = 2 * math.pi / nu
        sol = solve_ivp(
            lambda tt, y: [y[1], -math.sin(y[0]) - 0.04 * y[1] + 0.05 * math.cos(nu * tt)],
            (0, 150 * T),
            [x0, v0],
            rtol=1e-8,
            atol=1e-10,
            dense_output=True,
        )
        tail = np.linspace(147 * T, 150 * T, 600)
        assert float(np.max(np.abs(sol.sol(tail)[0]))) == pytest.approx(s.amplitude, rel=0.06)
