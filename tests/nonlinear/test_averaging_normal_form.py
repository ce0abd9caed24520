"""Bulgakov (1954), §12.11–12.12: normal form (12.144)–(12.153), shortened equations (12.154), regimes (12.155).

References, all independent of the normal-form code: the one-degree-of-freedom averaged equations (§5.26 code),
Poincaré's first approximation (12.34) computed by numeric first-harmonic quadrature, the Floquet multipliers of the
full system by Newton shooting (scipy solve_ivp), long-time numeric integration of the full system with amplitudes
taken from a NumPy modal decomposition, and a finite-difference Jacobian of torus averages computed on a grid.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from symosc import ConvergenceError, ModelError, ParameterError
from symosc.nonlinear import averaged_equations, averaging_normal_form, poincare_operator_system

D = sp.Symbol("D")
y1, y2, y3, v1, v2 = sp.symbols("y1 y2 y3 v1 v2", real=True)
mu = sp.Symbol("mu", positive=True)

K2 = np.array([[2.0, -1.0], [-1.0, 3.0]])  # two coupled van der Pol oscillators, w^2 = (5 -+ sqrt 5)/2


def _coupled_vdp():
    f = sp.Matrix([[D**2 + 2, -1], [-1, D**2 + 3]])
    psi = [mu * (1 - y1**2) * v1, mu * (1 - y2**2) * v2]
    return averaging_normal_form(f, psi, [y1, y2], D, derivatives={v1: (y1, 1), v2: (y2, 1)})


def test_single_dof_reduces_to_one_degree_of_freedom_averaging():
    """(12.157)-(12.160) with one pair: the shortened equation of x'' + x = mu (1 - x^2) x' is the §5.26 one."""
    x, v = sp.symbols("x v", real=True)
    nf = averaging_normal_form(sp.Matrix([[D**2 + 1]]), [mu * (1 - y1**2) * v1], [y1], D, derivatives={v1: (y1, 1)})
    ref = averaged_equations(x - mu * (1 - x**2) * v).a_dot
    (a,) = [s for s in ref.free_symbols if s.name == "a"]
    got = nf.shortened().rates[0].xreplace({nf.amplitudes[0]: a})
    assert sp.expand(got - ref) == 0
    assert ref != 0


def test_exact_normal_form_reproduces_the_equations_of_motion():
    """(12.151)-(12.153) are an exact change of variables: compare with the vector field of the full system."""
    nf = _coupled_vdp()
    rng = np.random.default_rng(1)
    Phi_w2, Phi = np.linalg.eigh(K2)
    for _ in range(5):
        vals = {nf.amplitudes[0]: rng.uniform(0.2, 2), nf.amplitudes[1]: rng.uniform(0.2, 2)}
        vals.update({nf.phases[0]: rng.uniform(-3, 3), nf.phases[1]: rng.uniform(-3, 3)})
        m = 0.3
        state = nf.to_state(vals)  # (y1, y2, v1, v2)
        q, qd = state[:2], state[2:]
        acc = -K2 @ q + m * np.array([(1 - q[0] ** 2) * qd[0], (1 - q[1] ** 2) * qd[1]])
        # d/dt of the state from the normal-form equations, by the chain rule through to_state
        rates = {s: float(e.subs({**vals, mu: m})) for s, e in zip(nf.amplitudes, nf.a_dot, strict=True)}
        rates.update({s: float(e.subs({**vals, mu: m})) for s, e in zip(nf.phases, nf.u_dot, strict=True)})
        h = 1e-6
        deriv = np.zeros(4)
        for s, r in rates.items():
            up, dn = dict(vals), dict(vals)
            up[s] += h
            dn[s] -= h
            deriv += r * (nf.to_state(up) - nf.to_state(dn)) / (2 * h)
        np.testing.assert_allclose(deriv, np.concatenate([qd, acc]), atol=1e-7)
        # from_state inverts to_state; the amplitudes agree with a NumPy modal decomposition
        back = nf.from_state(state)
        assert back[nf.amplitudes[0]] == pytest.approx(vals[nf.amplitudes[0]], rel=1e-10)
        eta, etad = Phi.T @ q, Phi.T @ qd
        A = np.sqrt(eta**2 + etad**2 / Phi_w2)
        for h_, m_ in enumerate(nf.reference):
            assert back[nf.amplitudes[h_]] == pytest.approx(A[h_] * abs(Phi[m_, h_]), rel=1e-9)  # no real roots


def test_two_pair_shortened_equations_and_regimes():
    """Mode competition of two coupled van der Pol oscillators: single-mode regimes stable, the mixed one a saddle."""
    nf = _coupled_vdp()
    sh = nf.shortened()
    r1 = sh.regime([1.0, 0.0], {"mu": 0.05})
    r2 = sh.regime([0.0, 1.0], {"mu": 0.05})
    r12 = sh.regime([1.0, 1.0], {"mu": 0.05})
    assert r1.stable and r2.stable and not r12.stable
    # closed form for mode h alone: a_h' = mu a_h (1/2 - c a_h^2), c = sum_j phi_jh^4 / (8 phi_mh^2) (NumPy modes)
    _, Phi = np.linalg.eigh(K2)
    for h, reg in ((0, r1), (1, r2)):
        m = nf.reference[h]
        c = np.sum(Phi[:, h] ** 4) / (8 * Phi[m, h] ** 2)
        assert reg.values[h] == pytest.approx(np.sqrt(1 / (2 * c)), rel=1e-10)
    # the frequencies are not corrected at first order for van der Pol damping
    np.testing.assert_allclose(r12.frequencies, np.sqrt([(5 - np.sqrt(5)) / 2, (5 + np.sqrt(5)) / 2]), rtol=1e-12)


def _torus_rates(amps, m):
    """Averaged modal amplitude rates of q'' + K q = m psi by brute-force torus quadrature (NumPy modes)."""
    w2, Phi = np.linalg.eigh(K2)
    w = np.sqrt(w2)
    N = 64
    u1, u2 = np.meshgrid(2 * np.pi * np.arange(N) / N, 2 * np.pi * np.arange(N) / N, indexing="ij")
    us = (u1, u2)
    eta = [amps[h] * np.cos(us[h]) for h in range(2)]
    etad = [-amps[h] * w[h] * np.sin(us[h]) for h in range(2)]
    q = [Phi[j, 0] * eta[0] + Phi[j, 1] * eta[1] for j in range(2)]
    qd = [Phi[j, 0] * etad[0] + Phi[j, 1] * etad[1] for j in range(2)]
    psi = [m * (1 - q[j] ** 2) * qd[j] for j in range(2)]
    out = []
    for h in range(2):
        force = Phi[0, h] * psi[0] + Phi[1, h] * psi[1]
        out.append(-np.mean(force * np.sin(us[h])) / w[h])
    return np.array(out)


def test_r_matrix_against_numeric_jacobian_of_torus_averages():
    """Eigenvalues of the Jacobian of (12.154) at each regime vs finite differences of grid torus averages."""
    nf = _coupled_vdp()
    sh = nf.shortened()
    _, Phi = np.linalg.eigh(K2)
    scale = np.array([abs(Phi[nf.reference[h], h]) for h in range(2)])  # a_h = modal amplitude * |phi_mh|
    for guess in ([1.0, 0.0], [0.0, 1.0], [1.0, 1.0]):
        reg = sh.regime(guess, {"mu": 0.05})
        A = reg.values / scale
        assert np.max(np.abs(_torus_rates(A, 0.05))) < 1e-12
        h = 1e-6
        J = np.column_stack(
            [(_torus_rates(A + h * e, 0.05) - _torus_rates(A - h * e, 0.05)) / (2 * h) for e in np.eye(2)]
        )
        np.testing.assert_allclose(np.sort_complex(reg.eigenvalues), np.sort_complex(np.linalg.eigvals(J)), atol=1e-8)
        # the symbolic Jacobian is the same matrix as the numeric one stored on the regime
        Js = np.array(sh.jacobian().subs({**dict(zip(sh.variables, reg.values, strict=True)), mu: 0.05}), dtype=float)
        np.testing.assert_allclose(Js, reg.jacobian, atol=1e-12)


def _full_amplitudes(m, t_end, a0, nf, n_out=40):
    """Integrate q'' + K q = m psi and return the amplitudes a_h(t) (NumPy modal decomposition)."""
    w2, Phi = np.linalg.eigh(K2)
    state0 = nf.to_state({nf.amplitudes[0]: a0[0], nf.amplitudes[1]: a0[1], nf.phases[0]: 0.3, nf.phases[1]: -1.1})

    def rhs(_t, z):
        q, qd = z[:2], z[2:]
        return np.concatenate([qd, -K2 @ q + m * (1 - q**2) * qd])

    t = np.linspace(0, t_end, n_out)
    sol = solve_ivp(rhs, (0, t_end), state0, t_eval=t, method="DOP853", rtol=1e-10, atol=1e-12)
    q, qd = sol.y[:2], sol.y[2:]
    eta, etad = Phi.T @ q, Phi.T @ qd
    A = np.sqrt(eta**2 + etad**2 / w2[:, None])
    a = np.array([A[h] * abs(Phi[nf.reference[h], h]) for h in range(2)])
    return t, a


def test_two_pair_transient_against_long_time_integration():
    """Amplitudes of the shortened equations follow the full solution to O(mu) over times ~ 1/mu (error slope 1)."""
    nf = _coupled_vdp()
    sh = nf.shortened()
    errs = []
    for m in (0.04, 0.02):
        t_end = 4.0 / m
        t, a_full = _full_amplitudes(m, t_end, (0.6, 0.5), nf)
        _, a_avg = sh.integrate((0, t_end), [0.6, 0.5], {"mu": m}, t_eval=t)
        errs.append(np.max(np.abs(a_full - a_avg)))
        assert errs[-1] < 2 * m * np.max(a_full)
    slope = np.log(errs[0] / errs[1]) / np.log(2)
    assert 0.7 < slope < 1.4
    # long time: the in-phase-like mode 1 wins and reaches the stable regime of the shortened equations
    m = 0.04
    t, a_full = _full_amplitudes(m, 25 / m, (1.0, 0.3), nf, n_out=5)
    winner = sh.regime([1.0, 0.0], {"mu": m})
    assert a_full[0, -1] == pytest.approx(winner.values[0], abs=3 * m)
    assert a_full[1, -1] < 2 * m  # only the O(mu) forced combination tones remain in mode 2


def _triangular():
    """(D^2 + 1) y1 = mu (1 - y1^2 - y2^2) Dy1, (D + 2) y2 = y1: one imaginary pair and the real root -2."""
    f = sp.Matrix([[D**2 + 1, 0], [-1, D + 2]])
    return f, [mu * (1 - y1**2 - y2**2) * v1, 0]


def test_one_pair_with_real_root_is_poincare_first_approximation():
    """(12.159)-(12.160) = (12.34): rate, amplitude, frequency and multiplier vs Poincaré's first approximation."""
    f, psi = _triangular()
    nf = averaging_normal_form(f, psi, [y1, y2], D, derivatives={v1: (y1, 1)})
    assert nf.real_roots == (-2,) and nf.complex_roots == (sp.I,)
    sh = nf.shortened()
    poin = poincare_operator_system(f, [e / mu for e in psi], [y1, y2], [v1, sp.Symbol("v2")], D)
    m = nf.reference[len(nf.real_roots)]  # y_m has amplitude a in the pair
    Vm = abs(poin.V[m])
    for a in (0.5, 1.0, 1.7):
        rate = sh.rate_values([0.0, a], {"mu": 1.0})
        assert rate[0] == pytest.approx(0.0, abs=1e-14)  # xi = 0 stays 0 (odd psi)
        assert rate[1] == pytest.approx(Vm * poin.amplitude_rate(a / Vm), rel=1e-9)
    cyc = poin.cycles(5.0)[0]
    reg = sh.regime([0.0, 1.0], {"mu": 0.01})
    assert reg.values[1] == pytest.approx(cyc.amplitude * Vm, rel=1e-9)
    assert reg.frequencies[0] == pytest.approx(1.0 * (1 + 0.01 * cyc.b), rel=1e-12)
    lam = max(reg.eigenvalues, key=lambda z: z.real)
    assert 1 + lam.real * 2 * np.pi == pytest.approx(cyc.multiplier(0.01, 1.0), abs=1e-8)  # G' by differences there


def test_one_pair_regime_against_shooting():
    """The regime's amplitude and its multipliers exp(lambda P) vs the periodic orbit of the full system."""
    f, psi = _triangular()
    nf = averaging_normal_form(f, psi, [y1, y2], D, derivatives={v1: (y1, 1)})
    m = 0.02
    reg = nf.shortened().regime([0.0, 1.0], {"mu": m})

    def rhs(_t, z):
        a, b, c = z
        return [b, -a + m * (1 - a**2 - c**2) * b, a - 2 * c]

    def flow(z0, T):
        return solve_ivp(rhs, (0, T), z0, method="DOP853", rtol=1e-12, atol=1e-13).y[:, -1]

    T0 = 2 * np.pi / reg.frequencies[0]
    z0 = nf.to_state({nf.amplitudes[0]: reg.values[1], nf.phases[0]: 0.0, nf.xi[0]: 0.0})

    def F(x):
        z = np.array([x[0], 0.0, x[1]])
        zT = flow(z, x[2])
        return [zT[0] - z[0], zT[1], zT[2] - z[2]]

    x = fsolve(F, [z0[0], z0[1] if len(z0) > 1 else 0.0, T0], xtol=1e-12)
    zstar = np.array([x[0], 0.0, x[1]])
    h = 1e-6
    Mono = np.column_stack([(flow(zstar + h * e, x[2]) - flow(zstar - h * e, x[2])) / (2 * h) for e in np.eye(3)])
    rho = np.sort(np.abs(np.linalg.eigvals(Mono)))
    pred = np.sort(np.abs(np.exp(reg.eigenvalues * x[2])))
    assert rho[0] == pytest.approx(pred[0], rel=0.05)  # the real-root mode, e^{-2P}(1 + O(mu))
    assert abs(rho[1] - pred[1]) < 5 * m**2 + 1e-6  # the critical pair: 1 + mu pi G'/omega^2 + O(mu^2)
    assert rho[2] == pytest.approx(1.0, abs=1e-6)
    amp = np.hypot(x[0], 0.0)  # at the turning point y1' = 0 the amplitude of y1 is |y1|
    assert amp == pytest.approx(reg.values[1], abs=5 * m)


def test_non_polynomial_psi_by_torus_quadrature():
    """Relay plus negative damping, x'' + x = mu (x' - F sign x'): a' = mu (a/2 - 2F/pi), a* = 4F/pi, unstable."""
    F = 0.3
    nf = averaging_normal_form(
        sp.Matrix([[D**2 + 1]]), [mu * (v1 - F * sp.sign(v1))], [y1], D, derivatives={v1: (y1, 1)}
    )
    sh = nf.shortened(n_samples=4096)
    assert sh.rates is None
    assert sh.rate_values([1.0], {"mu": 0.1})[0] == pytest.approx(0.1 * (0.5 - 2 * F / np.pi), rel=1e-6)
    reg = sh.regime([1.0], {"mu": 0.1}, tol=1e-8)
    assert reg.values[0] == pytest.approx(4 * F / np.pi, rel=1e-6)
    assert not reg.stable and reg.eigenvalues[0].real == pytest.approx(0.05, rel=1e-4)


def test_bad_input():
    with pytest.raises(ModelError, match="multiple"):
        averaging_normal_form(sp.Matrix([[(D**2 + 1) ** 2]]), [0], [y1], D)
    with pytest.raises(ModelError, match="assumption \\(d\\)"):
        averaging_normal_form(sp.Matrix([[D + 1]]), [v1], [y1], D, derivatives={v1: (y1, 1)})
    with pytest.raises(ModelError, match="assumption \\(c\\)"):
        averaging_normal_form(sp.Matrix([[D, D], [D, D + 1]]), [0, 0], [y1, y2], D)
    with pytest.raises(ParameterError, match="numeric"):
        averaging_normal_form(sp.Matrix([[D**2 + mu]]), [0], [y1], D)
    nf = _coupled_vdp()
    with pytest.raises(ParameterError, match="active"):
        nf.shortened(active=[5])
    sh = nf.shortened()
    with pytest.raises(ParameterError, match="missing values for: mu"):
        sh.regime([1.0, 0.0])
    with pytest.raises(ConvergenceError):
        sh.regime([1.0, 0.0], {"mu": 0.05}, tol=-1.0)


def test_three_pairs_with_numeric_roots():
    """A cubic in D^2 (roots in floats): each single-mode regime of three coupled van der Pol oscillators has the
    amplitude of the NumPy modal closed form, and the shortened rates vanish there."""
    K3 = np.array([[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 3.0]])
    ys = sp.symbols("q1:4", real=True)
    vs = sp.symbols("w1:4", real=True)
    f = D**2 * sp.eye(3) + sp.Matrix(K3.astype(int))
    nf = averaging_normal_form(
        f,
        [mu * (1 - ys[i] ** 2) * vs[i] for i in range(3)],
        list(ys),
        D,
        derivatives={vs[i]: (ys[i], 1) for i in range(3)},
    )
    w2, Phi = np.linalg.eigh(K3)
    np.testing.assert_allclose([complex(r).imag for r in nf.complex_roots], np.sqrt(w2), rtol=1e-13)
    sh = nf.shortened()
    for h in range(3):
        guess = np.zeros(3)
        guess[h] = 1.0
        reg = sh.regime(guess, {"mu": 0.05})
        m = nf.reference[h]
        c = np.sum(Phi[:, h] ** 4) / (8 * Phi[m, h] ** 2)
        assert reg.values[h] == pytest.approx(np.sqrt(1 / (2 * c)), rel=1e-10)
