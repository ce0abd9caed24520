"""Bulgakov (1954) Part II, ch. 5 D / §5.4: Poincaré and Lindstedt worked examples reproduced with symosc.nonlinear.

Source: B. V. Bulgakov, "Oscillations" (Kolebaniya), Moscow, 1954, Part II.
Prints "book value | symosc value | difference | note".  Run: python derivations/bulgakov_nonlinear.py
(Other helpers append their sections -- averaging, piecewise systems, delay -- to SECTIONS below.)
"""

from __future__ import annotations

import math

import mpmath
import sympy as sp

from symosc.nonlinear import limit_cycle, lindstedt, numeric_limit_cycle, periodic_solution_ndof

x, v, eps, A = sp.symbols("x v eps A")
R = sp.Rational


def _row(what, book, ours, note=""):
    try:
        diff = sp.N(sp.nsimplify(ours) - sp.nsimplify(book), 6) if not isinstance(book, str) else ""
    except (TypeError, ValueError, sp.SympifyError):
        diff = ""
    print(f"{what:<42} | {book!s:<22} | {ours!s:<26} | {diff!s:<10} | {note}")


def poincare_van_der_pol() -> None:
    print("\n== §5.22 valve generator / van der Pol, Poincaré's method (5.280)-(5.284) ==")
    lc = limit_cycle((1 - x**2) * v, 4)
    _row("A* = 2 sqrt(kappa/lambda), kappa=lambda=1", 2, lc.generating_amplitude)
    _row("alpha2: omega = 1 - mu^2/16", R(-1, 16), lc.frequency.coefficients[2])
    tau = sp.Symbol("tau")
    x1 = sp.expand(lc.solution(1, tau).coeff(eps, 1))
    _row("(5.283) first correction", "(3 sin u - sin 3u)/4", x1)
    _row("stability (mu H'(A*) > 0)", "stable", "stable" if lc.stable else "unstable")
    # the general cubic characteristic by scaling: kappa = 1/2, lambda = 9/8 -> A* = 4/3, alpha2 = -kappa^2/16
    kappa, lam = R(1, 2), R(9, 8)
    lc2 = limit_cycle((kappa - lam * x**2) * v, 2)
    _row("A* for kappa=1/2, lambda=9/8", 2 * sp.sqrt(kappa / lam), lc2.generating_amplitude)
    _row("c = -kappa^2/8 -> alpha2 = -kappa^2/16", -(kappa**2) / 16, lc2.frequency.coefficients[2])
    print("  higher orders (not in the book; Andersen & Geer 1982 reached eps^24):")
    lc24 = limit_cycle((1 - x**2) * v, 24)
    for k in (4, 6, 8):
        print(f"    omega_{k} = {lc24.frequency.coefficients[k]}")
    print(f"    amplitude = {lc24.amplitude.coefficient(2)} eps^2 + {lc24.amplitude.coefficient(4)} eps^4 + ...")
    print(f"    radius of convergence: {lc24.frequency.radius_of_convergence()}")
    print("  independent numeric references (Radau, rtol 1e-10, in the 'book' column) vs symosc shooting:")
    for mu, amp_r, per_r in ((0.1, 2.00010, 6.28711), (0.5, 2.00249, 6.38068), (1.0, 2.00862, 6.66329)):
        cyc = numeric_limit_cycle((1 - x**2) * v, mu)
        _row(f"  mu={mu}: max x", amp_r, round(float(cyc.amplitude), 5), f"series {lc24.amplitude.evaluate(mu):.8f}")
        _row(f"  mu={mu}: period", per_r, round(float(cyc.period), 5), f"series {lc24.period.evaluate(mu):.8f}")
    cyc = numeric_limit_cycle((1 - x**2) * v, 10.0)
    _row("  mu=10 (stiff, LSODA): period", 19.07837, round(float(cyc.period), 5), "series diverges (|eps| > 1.85)")


def lindstedt_examples() -> None:
    print("\n== §5.4 Newcomb–Lindstedt (5.50)-(5.61) ==")
    c1, c2, c3, c4 = sp.symbols("c1:5")
    ls = lindstedt(-(c1 * x**2 + c2 * x**3 + c3 * x**4 + c4 * x**5), 4)
    om2 = sp.expand(ls.frequency_squared.expr.subs(eps, 1))
    _row("delta1", 0, om2.coeff(A, 1))
    _row("delta2 (5.52)", "3/4 c2 - 5/6 c1^2", sp.expand(om2.coeff(A, 2)))
    _row("delta3", "c1 c2/2 - 5/9 c1^3", sp.expand(om2.coeff(A, 3)))
    P = sp.expand(ls.period.expr.subs(eps, 1) / (2 * sp.pi))
    _row("P/P0, a^2 (5.58)", "5/12 c1^2 - 3/8 c2", sp.expand(P.coeff(A, 2)))
    _row("P/P0, a^3 (5.58)", "5/18 c1^3 - 1/4 c1 c2", sp.expand(P.coeff(A, 3)))
    print("  Duffing c1 = 0, c2 = eps (x'' + x + eps x^3 = 0), order 20 exact:")
    d = lindstedt(-(x**3), 20)
    _row("  omega, eps A^2 term", R(3, 8), d.frequency.coefficients[1] / A**2)
    _row("  omega, eps^2 A^4 term", R(-21, 256), d.frequency.coefficients[2] / A**4)
    print(f"    omega_20 = {d.frequency.coefficients[20]}")
    print("  pendulum (c2 = -1/6, c4 = 1/120), (5.61): P/P0 = 1 + a^2/16 + 11 a^4/3072")
    pend = lindstedt(x**3 / 6 - x**5 / 120, 2)
    Pp = sp.expand(pend.period.expr.subs(eps, 1) / (2 * sp.pi))
    _row("  a^2 coefficient", R(1, 16), Pp.coeff(A, 2))
    _row("  a^4 coefficient", R(11, 3072), Pp.coeff(A, 4))
    for deg, book in ((10, 1.001), (20, 1.006), (30, 1.014)):
        a = mpmath.radians(deg)
        ser = 1 + a**2 / 16 + 11 * a**4 / 3072
        exact = 2 / mpmath.pi * mpmath.ellipk(mpmath.sin(a / 2) ** 2)
        _row(f"  P/P0 at {deg} deg", book, f"{float(ser):.6f}", f"exact (2/pi)K = {float(exact):.6f}; book misprint")


def averaging_examples() -> None:
    """Ch. 5 E and ch. 6: shortened equations."""
    from symosc.nonlinear import averaged_equations, describing_function

    print("\n== §5.26-5.31 averaging (Krylov-Bogoliubov / van der Pol shortened equations) ==")
    kap, lam = sp.symbols("kappa lambda", positive=True)
    avg = averaged_equations(x - (kap - lam * x**2) * v)
    _row("(5.373) a' for the valve generator", "kappa a/2 - lambda a^3/8", avg.a_dot)
    _row("stationary amplitude, stable", "2 sqrt(kappa/lambda)", avg.stationary()[1].amplitude)
    b_, c_ = sp.symbols("b c", positive=True)
    J = describing_function(b_ * sp.sign(x) + c_ * x)
    _row("(5.350) J(a), preloaded spring", "4b/pi + c a", J)
    for amp, book in ((0.1, 2.8924), (1.0, 1.62377)):
        w = sp.sqrt(J.subs({b_: R(1, 2), c_: 2, sp.Symbol("a", positive=True): amp}) / amp)
        _row(f"  omega_avg(a={amp}), b=0.5, c=2", book, f"{float(w):.5f}", "book example")
    F = sp.Symbol("F", positive=True)
    _row("Coulomb friction: a' (4B per period)", "-2F/pi", averaged_equations(x + F * sp.sign(v)).a_dot)
    k_ = sp.Symbol("k", positive=True)
    sa = averaged_equations(k_**2 * (sp.exp(x) - 1), center=True)
    _row("(5.356) shock absorber center q*", "-ln I0(a)", sa.center)
    _row("(5.356) omega^2", "2 k^2 I1(a)/(a I0(a))", sa.frequency_squared)
    _row("(5.365) pendulum J(a)", "2 k^2 J1(a)", describing_function(k_**2 * sp.sin(x)))
    from symosc.nonlinear import dry_friction_ratio

    for kk, book in ((0.5, 0.554), (0.9, 0.778), (2.0, 1.806), (10.0, 1.992)):
        note = "recomputed; 1.991 would be a slip" if kk == 10.0 else ""
        _row(f"§12.14 Table 15: R(y/x = {kk})", book, round(dry_friction_ratio(kk), 3), note)
    print("  §6.3 softening Duffing example: lambda = 15, nu^2 = 10, mu = 16/3, R = 1")
    soft = averaged_equations(15 * x - R(16, 3) * x**3, forcing=1, nu=sp.sqrt(10))
    got = sorted(s.amplitude * math.cos(s.theta) for s in soft.steady_states({}))
    kinds = [s.kind for s in sorted(soft.steady_states({}), key=lambda s: s.amplitude * math.cos(s.theta))]
    for xs, book, kind in zip(got, ("-1/2 - 1/sqrt2", "-1/2 + 1/sqrt2", "1"), kinds, strict=True):
        _row(f"  steady state x* ({kind})", book, f"{xs:.10f}")
    X, Y, H = soft.hamiltonian()
    z = sp.expand(2 * sp.sqrt(10) * H)
    _row("  peak of z above A1", "21/16 + sqrt2", sp.nsimplify(z.subs({X: -R(1, 2) - 1 / sp.sqrt(2), Y: 0})))
    _row("  pit of z below A2", "21/16 - sqrt2", sp.nsimplify(z.subs({X: -R(1, 2) + 1 / sp.sqrt(2), Y: 0})))
    hard = averaged_equations(x + sp.Symbol("mu") * x**3 + 2 * sp.Symbol("zeta") * v, forcing=sp.Symbol("R"))
    fr = hard.frequency_response({"mu": 0.05, "zeta": 0.02, "R": 0.1}, (0.9, 1.2), n=241)
    _row("  hardening Duffing jump frequencies", "(not in book)", [round(f, 6) for f in fr.jump_frequencies])


def piecewise_examples() -> None:
    """Ch. 5 B-C: Coulomb friction, quadratic drag, clocks, valve generator."""
    from symosc.nonlinear import (
        clock_escapement,
        coulomb_oscillator,
        half_swing_map,
        quadratic_drag_eta,
        quadratic_drag_eta_series,
        quadratic_drag_half_swing_times,
        step_valve_generator,
    )

    print("\n== §5.6-5.13 dry friction, quadratic drag, clocks (exact piecewise solutions) ==")
    watch = coulomb_oscillator(3 * sp.pi / 4, 3 * sp.pi / 1600, k=5 * sp.pi)
    _row("pocket watch: half-swings to stop", 200, watch.half_swings, "B = 3 pi/1600")
    _row("pocket watch: stop time [s]", 40, round(watch.stop_time, 9))
    q = sp.Symbol("q")

    def dm(r):
        d = abs(math.degrees(r))
        return f"{int(d)}°{round((d - int(d)) * 60):02d}'"

    m2 = half_swing_map(1 - sp.cos(q), q, friction=sp.sin(sp.pi / 36))
    for a, book in ((30, "19°44'"), (45, "34°10'"), (90, "75°26'"), (140, "112°40'"), (175, "122°54'")):
        _row(f"Table 2 (B = 5°): a = {a}°", book, dm(m2(math.radians(a))), "recomputed")
    for xi, book in ((1, 0.5936), (3, 0.9207), (10, 0.9998)):
        _row(f"Table 3: eta({xi})", book, round(quadratic_drag_eta(xi), 4))
    _row("(5.123) eta series", "1, -2/3, 4/9, -44/135, 104/405", quadratic_drag_eta_series(5))
    for xi, book in ((1, "1.747/1.475"), (5, "2.579/1.419"), (1000, "48.36 (sum 49.77)")):
        t1, t2 = quadratic_drag_half_swing_times(xi, dps=15)
        _row(f"Table 4: t1/t2 at xi = {xi}", book, f"{t1:.3f}/{t2:.3f}", "book 1000: misprint" if xi == 1000 else "")
    m5 = half_swing_map(1 - sp.cos(q), q, drag=R(2, 5))
    for a, book in ((5, "4°37'"), (10, "9°31'"), (90, "60°45'"), (150, "75°33'")):
        note = "book misprint (series check)" if a <= 10 else ""
        _row(f"Table 5 (eps = 0.4): a = {a}°", book, dm(m5(math.radians(a))), note)
    c = clock_escapement(R(1, 50), R(1, 25), R(1, 10))
    _row("(5.138) clock: A = h/(4B)", R(1, 2), c.amplitude, "B = 0.02, h = 0.04")
    _row("(5.153) map slope at A", "(A-B)/(A+B) = 12/13", c.multiplier)
    g = step_valve_generator(1, R(1, 10))
    _row("(5.166) step generator A = S/(1-delta)", "S/(1-delta)", sp.N(g.A, 8), "S = 1, eps = 0.1, k = 1")


def delay_examples() -> None:
    """§4.16-4.17: optimal degree of stability and Table 1."""
    from symosc.nonlinear import andronov_maier_optimum, callender_hartree_porter_optimum, quasi_polynomial_roots

    print("\n== §4.16-4.17 retarded systems (certified quasi-polynomial roots) ==")
    chp = callender_hartree_porter_optimum()
    _row("(4.137) s*", "2 - sqrt 2", chp["s"])
    _row("(4.138) rho*", 0.46116, round(float(chp["rho"]), 6))
    _row("(4.138) sigma*", 0.07913, round(float(chp["sigma"]), 6), "4th-digit rounding in the book")
    am = andronov_maier_optimum(R(1, 5))
    _row("(4.149) Andronov-Maier s*, rho = 0.2", "1.1 - sqrt(1.01)", am["s"])
    _row("sigma*", 0.00907, round(float(am["sigma"]), 7))
    p_ = sp.Symbol("p")
    res = quasi_polynomial_roots(p_**2 + R(1, 5) * p_ + am["sigma"] * sp.exp(-p_), (-13, 1, -0.3137, 40))
    book = ["(0.9501, 0) double", (93.10, 39.52), (101.15, 110.97), (107.64, 177.67), (112.73, 242.70)]
    book += [(116.84, 306.93), (120.27, 370.76)]
    print(f"  certified count in the rectangle: {res.count} (with multiplicity)")
    for z, mult, bk in zip(res.roots, res.multiplicities, book, strict=True):
        digits = 4 if mult > 1 else 2
        ours = f"({-float(z.real) * 10:.{digits}f}, {float(z.imag) * 10:.2f})" + (f" x{mult}" if mult > 1 else "")
        _row("  Table 1 root (|Re|, Im)/tau [1/s]", str(bk), ours)


def high_frequency_examples() -> None:
    """Appendix (Bulgakov 1940) -> Kapitza."""
    from symosc.nonlinear import vibrational_averaging
    from symosc.symbols import t

    print("\n== Appendix: fast forcing, vibrating-pivot pendulum ==")
    th = sp.Symbol("theta")
    m, g, l, a, p = sp.symbols("m g l a p", positive=True)
    res = vibrational_averaging(th, m * l**2, -m * g * l * sp.cos(th), m * l * a * p**2 * sp.sin(th) * sp.cos(p * t), p)
    _row("V_eff - V", "m a^2 p^2 sin^2(theta)/4", res.correction, "[D] not in the book")
    _row("V_eff''(pi) > 0", "a^2 p^2 > 2 g l", res.stability_condition({th: sp.pi}))


def ndof_poincare() -> None:
    print("\n== ch. 12 A, n-DOF Poincaré ==")
    H = limit_cycle((1 - x**2) * v, 1).amplitude_equation
    for a, g in ((R(3, 2), 0.65625), (2, 0), (R(5, 2), -1.40625)):
        _row(f"T14: G({a}) = (1/pi) Im int psi e^(-iu) du", g, -H.subs(A, a), "G = -H in symosc's sign")
    d = lindstedt(-(x**3), 1)
    _row("T14: y'' + y = -mu y^3: b = 3A^2/8", "3*A**2/8", d.frequency.coefficients[1], "G = 0: lindstedt()")
    q1, q2, v1, v2 = sp.symbols("q1 q2 v1 v2")
    sol = periodic_solution_ndof(
        [[1, 0], [0, 1]], [[2, -1], [-1, 2]], [(1 - q1**2) * v1, (1 - q2**2) * v2], [q1, q2], [v1, v2], 6
    )
    _row("coupled vdP in-phase: modal A* = 2 sqrt 2", "2.8284271", f"{sol.generating_amplitude:.8f}", "not in book")
    _row("  omega_2 (= one-DOF vdP)", -0.0625, f"{float(sol.frequency.coefficients[2]):.10f}")
    ex = sol.exponents_at(0.1)
    _row("  exponents at eps = 0.1 (Re)", "0, -0.1, -0.05, -0.05", ", ".join(f"{e.real:.4g}" for e in ex))
    r = sol.validate(0.1)
    _row("  numeric Floquet exponents (Re)", "", ", ".join(f"{e:.4g}" for e in r["exponents_numeric_real"]))


def normal_form_and_second_approximations() -> None:
    """§12.11-12.12 averaging normal form, §12.4 second approximation, §5.23 non-resonant forcing, §5.24 flywheel."""
    from symosc.nonlinear import (
        averaging_normal_form,
        flywheel_speed_series,
        nonresonant_forced_solution,
        poincare_second_approximation,
    )

    print("\n== §12.11-12.12 normal form and shortened equations; §12.4, §5.23, §5.24 second approximations ==")
    D, y1, y2, v1, v2, mu = sp.symbols("D y1 y2 v1 v2 mu")
    nf = averaging_normal_form(sp.Matrix([[D**2 + 1]]), [mu * (1 - y1**2) * v1], [y1], D, derivatives={v1: (y1, 1)})
    a1 = nf.amplitudes[0]
    _row("(12.160) = (12.34): a' for van der Pol", "mu a/2 - mu a^3/8", nf.shortened().rates[0].subs(a1, A))
    f2 = sp.Matrix([[D**2 + 2, -1], [-1, D**2 + 3]])
    nf2 = averaging_normal_form(
        f2, [mu * (1 - y1**2) * v1, mu * (1 - y2**2) * v2], [y1, y2], D, derivatives={v1: (y1, 1), v2: (y2, 1)}
    )
    sh = nf2.shortened()
    _row("two coupled vdP: w1^2, w2^2 (roots of Delta)", "(5 -+ sqrt5)/2", [sp.im(r) ** 2 for r in nf2.complex_roots])
    for guess in ([1.0, 0.0], [0.0, 1.0], [1.0, 1.0]):
        reg = sh.regime(guess, {"mu": 0.05})
        vals = ", ".join(f"{x:.6f}" for x in reg.values)
        eig = ", ".join(f"{e.real:.5f}" for e in reg.eigenvalues)
        _row(
            f"  regime (12.155) from {guess}",
            "(not in book)",
            vals,
            f"Re eig {eig}: {'stable' if reg.stable else 'saddle'}",
        )
    sa = poincare_second_approximation(sp.Matrix([[D**2 + 1]]), [(1 - y1**2) * v1], [y1], [v1], D, 5.0)
    _row("§12.4 van der Pol: c/2 (omega = 1 - mu^2/16)", R(-1, 16), sp.nsimplify(round(sa.c / 2, 12)))
    _row("  B (amplitude correction)", 0, sp.nsimplify(round(sa.B, 12)))
    sa2 = poincare_second_approximation(sp.Matrix([[D**2 + 1]]), [(1 - y1**2) * v1 - y1**3], [y1], [v1], D, 5.0)
    _row("  + cubic spring -mu y^3: b = 3A*^2/8", R(3, 2), sp.nsimplify(round(sa2.b, 12)), "T14, A* = 2")
    _row("  + cubic spring: B, c", "(not in book)", f"{sa2.B:.6f}, {sa2.c:.6f}")
    q, t_ = sp.symbols("q t")
    fs = nonresonant_forced_solution(sp.cos(2 * t_) - mu * q**3, q, sp.Symbol("v"), t_, 1.0, 2.0, 3)
    _row("§5.23 q''+q = cos 2t - mu q^3: C1 order 0", R(-1, 3), sp.nsimplify(round(float(fs.C1.coefficients[0]), 12)))
    _row(
        "  C1 order 1 (by hand: -1/105)",
        R(-1, 105),
        sp.nsimplify(float(fs.C1.coefficients[1]), tolerance=1e-12, rational=True),
    )
    s_ = sp.Symbol("s")
    fw = flywheel_speed_series(sp.cos(s_), s_, 2.0, samples=256, drive_slope=-1.0)
    # by hand from (5.312)-(5.313) with D' = -1, D'' = 0: r2 = cos(s)/r_m^2 + cos(2s)/(4 r_m^3)
    note = "by hand: cos s/r_m^2 + cos 2s/(4 r_m^3)"
    _row("§5.24 flywheel T = cos s, r_m = 2: r2(0)", R(9, 32), sp.nsimplify(round(float(fw.r2[0]), 12)), note)
    _row("  r2(pi)", R(-7, 32), sp.nsimplify(round(float(fw.r2[128]), 12)), note)


SECTIONS = [poincare_van_der_pol, lindstedt_examples, ndof_poincare]
SECTIONS += [averaging_examples, piecewise_examples, delay_examples, high_frequency_examples]
SECTIONS += [normal_form_and_second_approximations]


def main() -> None:
    print(f"{'quantity':<42} | {'book':<22} | {'symosc':<26} | {'diff':<10} | note")
    for section in SECTIONS:
        section()


if __name__ == "__main__":
    main()
