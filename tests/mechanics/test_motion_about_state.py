"""Bulgakov ch. 7 (motion about a given state), the governor, and electromechanical Lagrangians (§3.8).

Independent references: closed forms derived by hand in the docstrings, numeric integration, SciPy eigenvalues.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad, solve_ivp

from symosc import ModelError, ddot, dot, t
from symosc.mechanics import (
    LagrangianSystem,
    decompose_forces,
    electromechanical_system,
    governor_statics,
    stodola_time_constant,
    variational_equations,
    vyshnegradsky_cubic,
)

x, z, th, q = sp.symbols("x z theta q", real=True)
m, k, g, l, w, Lq, R, C, e, c = sp.symbols("m k g l omega L R C e c", positive=True)
lam = sp.Symbol("lambda")


def test_variations_about_rotation_mathieu_like():
    """Pendulum on a shaft spinning at omega about its rotation theta = omega t in a plane with gravity:
    the variational equation y'' + (g/l) cos(omega t) y = 0 has time-periodic coefficients (§7.1)."""
    s = LagrangianSystem(m * l**2 * dot(th) ** 2 / 2, -m * g * l * sp.cos(th), [th])
    ve = variational_equations(s, reference={th: w * t})
    a0, a1, a2 = ve.coefficients
    assert a0[0] == m * l**2 and a1[0] == 0
    assert sp.simplify(a2[0] - m * g * l * sp.cos(w * t)) == 0
    # the reference is not a solution: w = -phi(q_bar) = -m g l sin(omega t)
    assert sp.simplify(ve.w[0] + m * g * l * sp.sin(w * t)) == 0
    A, H, W = ve.first_order()
    assert W == sp.zeros(1, 1).col_join(ve.w)
    assert A == sp.diag(1, m * l**2) and H == sp.Matrix([[0, -1], [a2[0], 0]])


def test_variations_from_general_solution():
    """Duffing x'' + k x^3 = 0 about x = a cos t: f(D) = D^2 + 3 k a^2 cos^2 t (§7.1, eq. (7.11))."""
    a = sp.Symbol("a")
    ve = variational_equations([ddot(x) + k * x**3], [x], {x: a * sp.cos(t)})
    f = ve.operator_matrix()[0]
    assert sp.simplify(f - (sp.Symbol("D") ** 2 + 3 * k * a**2 * sp.cos(t) ** 2)) == 0


def test_decomposition_energy_identity_along_trajectory():
    """d/dt (y'Ay' + yHy) = -2 (y'Ny' + y'Jy) along a numerically integrated trajectory (eq. (7.79))."""
    rng = np.random.default_rng(3)
    Mn = np.diag([1.0, 2.0])
    Cn = rng.uniform(-1, 1, (2, 2)) + np.eye(2)
    Kn = rng.uniform(-1, 1, (2, 2)) + 3 * np.eye(2)
    fd = decompose_forces(sp.Matrix(Mn), sp.Matrix(Cn), sp.Matrix(Kn))
    y = sp.symbols("y1 y2")
    yd = sp.symbols("v1 v2")
    rate = sp.lambdify([*y, *yd], fd.energy_rate(y, yd))
    A, N, H, J = (np.array(mm, dtype=float) for mm in (fd.A, fd.N, fd.H, fd.J))

    def f(_, s):
        return np.concatenate([s[2:], np.linalg.solve(Mn, -Cn @ s[2:] - Kn @ s[:2])])

    sol = solve_ivp(f, (0, 3), [1, -0.5, 0.2, 0.3], method="DOP853", rtol=1e-12, atol=1e-12, dense_output=True)
    ts = np.linspace(0, 3, 7)
    energy = [s[2:] @ A @ s[2:] + s[:2] @ H @ s[:2] for s in sol.sol(ts).T]
    for i in range(1, len(ts)):  # the energy change equals the integral of the rate
        change = quad(lambda tt: rate(*sol.sol(tt)), ts[i - 1], ts[i], epsabs=1e-12, epsrel=1e-12)[0]
        assert abs(energy[i] - energy[i - 1] - change) < 1e-9
    assert np.allclose(N, N.T) and np.allclose(J, -J.T)


@pytest.mark.parametrize(
    ("C", "K", "stable", "asym"),
    [
        (np.zeros((2, 2)), np.diag([1.0, 2.0]), True, False),  # Lagrange-Dirichlet
        (np.array([[0, 3.0], [-3.0, 0]]), np.diag([-1.0, 2.0]), False, False),  # odd degree of instability
        (np.array([[0, 5.0], [-5.0, 0]]), np.diag([-1.0, -2.0]), None, False),  # gyroscopic stabilization possible
        (np.array([[0.1, 5.0], [-5.0, 0.1]]), np.diag([-1.0, -2.0]), False, False),  # destroyed by dissipation
        (np.array([[0.1, 5.0], [-5.0, 0.2]]), np.diag([1.0, 2.0]), True, True),  # complete dissipation
    ],
)
def test_thomson_tait_chetaev(C, K, stable, asym):
    fd = decompose_forces(sp.eye(2), sp.Matrix(C), sp.Matrix(K))
    v = fd.stability()
    assert v.stable is stable and v.asymptotically is asym
    # independent check with the eigenvalues of the first-order matrix
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-K, -C]])
    re = np.linalg.eigvals(A).real
    if stable is False:
        assert re.max() > 1e-9
    if asym:
        assert re.max() < 0
    if stable is None:  # this gyroscopic example is in fact stabilized: purely imaginary roots
        assert np.abs(re).max() < 1e-9


def test_stodola_and_statics():
    J, K0 = sp.symbols("J K0", positive=True)
    assert stodola_time_constant(J, K0 - c * w, w) == J / c
    with pytest.raises(ModelError, match="self-regulation"):
        stodola_time_constant(J, K0, w)
    a, b = sp.symbols("a b", positive=True)
    st = governor_statics(a + b * z**2, sp.Integer(1), z)  # omega^2 = a + b z^2: stable for z > 0
    assert st.stability_index == 2 * b * z


def test_vyshnegradsky_from_the_governor_lagrangian():
    """The engine-governor Lagrangian (Bulgakov (1954), eq. (7.51)) linearized about the steady state gives
    det f(lambda) proportional to lambda * (U V^2 l^3 + U W l^2 + (U delta + N) l + 1) (eqs. (7.55)-(7.57))."""
    vt, zs, Jm, gam, kf, a0, a1, a2, K0, cz, e1 = sp.symbols(
        "vartheta z_s J gamma k_f a0 a1 a2 K0 c_z e1", positive=True
    )
    alpha = a0 + a1 * z + a2 * z**2  # the flyballs' inertia about the shaft, alpha(z)
    A = alpha.diff(z) / 2
    Kz = K0 - cz * z  # engine torque falls as the sleeve rises
    Lload = Kz.xreplace({z: zs})  # steady: K(z*) = L
    e0 = (A * w**2).xreplace({z: zs}) - e1 * zs  # steady: E(z*) = A(z*) omega^2 with E = e0 + e1 z
    T = (Jm + alpha) * dot(vt) ** 2 / 2 + gam * dot(z) ** 2 / 2
    V = e0 * z + e1 * z**2 / 2
    s = LagrangianSystem(T, V, [vt, z], forces=[Kz - Lload, -kf * dot(z)])
    ve = variational_equations(s, reference={vt: w * t, z: zs})
    assert ve.w == sp.zeros(2, 1)  # the steady state solves the equations
    det = ve.characteristic_polynomial(lam)
    Kp = -cz
    Az = A.xreplace({z: zs})
    U = (Jm + alpha.xreplace({z: zs})) / (-Kp)
    N = 2 * Az * w / (-Kp)
    V2 = gam / (2 * Az * w)
    W = kf / (2 * Az * w)
    delta = (e1 - A.diff(z) * w**2) / (2 * Az * w)
    cubic, _ = vyshnegradsky_cubic(U, V2, W, delta, N, lam)
    ratio = sp.simplify(det / (lam * cubic))
    assert lam not in ratio.free_symbols and ratio != 0


def test_electromechanical_ponderomotive_forces():
    """Solenoid plunger: force i^2 L'(x)/2; moving-plate capacitor: force -q^2 B'(x)/2 (Bulgakov (1954), §3.8)."""
    L0, L1, d, eps = sp.symbols("L0 L1 d epsilon", positive=True)
    ind = L0 + L1 * x
    s = electromechanical_system(m * dot(x) ** 2 / 2, k * x**2 / 2, [x], [q], inductance=sp.Matrix([[ind]]))
    assert sp.expand(s.forcing[0] - (-k * x + L1 * dot(q) ** 2 / 2)) == 0
    # voltage balance: d/dt (L i) = e - R i  ->  L q'' = -L1 x' q' (no emf, no resistance here)
    assert sp.expand(s.forcing[1] + L1 * dot(x) * dot(q)) == 0
    mic = electromechanical_system(
        m * dot(x) ** 2 / 2,
        k * x**2 / 2,
        [x],
        [q],
        inductance=sp.Matrix([[Lq]]),
        elastance=sp.Matrix([[(d + x) / eps]]),
        resistance=sp.Matrix([[R]]),
        emf=[e],
    )
    assert sp.expand(mic.forcing[0] - (-k * x - q**2 / (2 * eps))) == 0
    assert sp.expand(mic.forcing[1] - (e - R * dot(q) - (d + x) * q / eps)) == 0
    with pytest.raises(ModelError, match="symmetric"):
        electromechanical_system(0, 0, [x], [q, th], inductance=sp.Matrix([[1, 2], [3, 1]]))


def test_bridge_loop_equations_against_nodal_analysis():
    """Wheatstone bridge (Bulgakov (1954), Fig. 49): B = 6, N = 4, K = 1 gives 3 loops; Z symmetric; branch
    currents agree with an independent nodal analysis; a triode-like mu Z_g term breaks reciprocity."""
    from symosc.mechanics import loop_equations

    rng = np.random.default_rng(1)
    zb = rng.uniform(1, 3, 6)
    br = [(0, 1, zb[0], 3.0), (1, 2, zb[1]), (1, 3, zb[2]), (2, 3, zb[3]), (2, 0, zb[4]), (3, 0, zb[5])]
    le = loop_equations(br)
    assert le.loop_matrix.shape == (3, 6) and le.is_reciprocal
    Z = np.array(le.impedance, dtype=float)
    ib = np.array(le.loop_matrix.T, dtype=float) @ np.linalg.solve(Z, np.array(le.emf, dtype=float).ravel())
    Y, Inj = np.zeros((4, 4)), np.zeros(4)
    for b in br:
        a, c_, zz = b[:3]
        ee = b[3] if len(b) > 3 else 0.0
        Y[a, a] += 1 / zz
        Y[c_, c_] += 1 / zz
        Y[a, c_] -= 1 / zz
        Y[c_, a] -= 1 / zz
        Inj[a] -= ee / zz
        Inj[c_] += ee / zz
    v = np.zeros(4)
    v[1:] = np.linalg.solve(Y[1:, 1:], Inj[1:])
    ref = np.array([(v[b[0]] - v[b[1]] + (b[3] if len(b) > 3 else 0.0)) / b[2] for b in br])
    assert np.allclose(ib, ref, rtol=1e-12, atol=1e-14)
    Dop, L1, R1, C1 = sp.symbols("D L1 R1 C1", positive=True)
    sym = loop_equations([(0, 1, L1 * Dop + R1 + 1 / (C1 * Dop)), (1, 2, R1), (2, 0, L1 * Dop), (1, 0, R1)])
    assert sym.is_reciprocal
    active = type(sym)(sym.loop_matrix, sym.impedance + sp.Matrix([[0, 0], [R1, 0]]), sym.emf)
    assert not active.is_reciprocal


def test_result_objects_pickle_and_print():
    import pickle

    from symosc.mechanics import action_variable, canonical_transformation, loop_equations

    p_, u_, v_ = sp.symbols("p u v", real=True)
    objs = [
        action_variable(p_**2 / 2 + q**2 / 2, q, p_),
        canonical_transformation(q * u_, [q], [p_], [u_], [v_], kind=1),
        decompose_forces(sp.eye(1), sp.Matrix([[c]]), sp.Matrix([[k]])),
        loop_equations([(0, 1, R, e), (1, 0, R)]),
        variational_equations([ddot(x) + k * x], [x]),
        governor_statics(k + c * z, sp.Integer(1), z),
    ]
    for o in objs:
        back = pickle.loads(pickle.dumps(o))
        assert back == o
        assert type(o).__name__ in repr(o)


# ---------------------------------------------------------------- §7.2: reduction to first order, methods 1 and 2
W_ = sp.Symbol("W_", real=True)  # a coordinate of order 1 (a speed)
y3 = sp.Symbol("y3", real=True)  # a coordinate of order 0


def _governor_like(eps=0):
    """Sleeve x of a governor (order 2) driven by the engine speed W_ (order 1): Bulgakov (1954), §7.5-7.6
    structure, m x'' + c x' + k (1 + eps cos t) x - b W_ = 0, J W_' + kappa x = sin t."""
    b, J, kap = sp.symbols("b J kappa", positive=True)
    phis = [m * ddot(x) + c * dot(x) + k * (1 + eps * sp.cos(t)) * x - b * W_, J * dot(W_) + kap * x - sp.sin(t)]
    return variational_equations(phis, [x, W_]), (b, J, kap)


def test_first_order_methods_characteristic_polynomial():
    """Both reductions of §7.2 have det(A lambda + H) = +-det f(lambda) (Bulgakov (1954), eqs. (7.25)-(7.26)):
    det f(lambda) written out by hand for the governor-like system, and for a system with an algebraic
    coordinate (order 0); method 2 has sum max(1, m_k) unknowns."""
    ve, (b, J, kap) = _governor_like()
    by_hand = sp.expand((m * lam**2 + c * lam + k) * J * lam + b * kap)  # det [[m l^2 + c l + k, -b], [kap, J l]]
    for method, size in ((1, 4), (2, 3)):
        red = ve.first_order(method=method)
        assert len(red.state) == size and red.A.shape == (size, size)
        ratio = sp.cancel(red.characteristic_polynomial(lam) / by_hand)
        assert ratio in (1, -1)
    assert ve.coordinate_orders() == (2, 1)
    assert ve.first_order(method=1).A.det() == 0 and ve.first_order(method=2).A.det() != 0
    # orders (2, 2, 0): y3 enters algebraically
    ve3 = variational_equations([ddot(x) + 2 * x - z + y3, ddot(z) + c * dot(z) + z - x, y3 - k * dot(x)], [x, z, y3])
    by_hand3 = sp.expand(sp.Matrix([[lam**2 + 2, -1, 1], [-1, lam**2 + c * lam + 1, 0], [-k * lam, 0, 1]]).det())
    red2 = ve3.first_order(method=2)
    assert ve3.coordinate_orders() == (2, 2, 0) and len(red2.state) == 5  # 2 + 2 + max(1, 0)
    for method in (1, 2):
        assert sp.cancel(ve3.first_order(method=method).characteristic_polynomial(lam) / by_hand3) in (1, -1)
    # numeric: eigenvalues of the method-2 pencil (scipy) are the roots of det f(lambda) (numpy)
    import scipy.linalg

    vals = {c: 0.3, k: 0.7}
    A2, H2, _ = (np.array(mm.xreplace(vals), dtype=float) for mm in red2)
    eig = scipy.linalg.eigvals(-H2, A2)
    eig = np.sort_complex(eig[np.isfinite(eig)])
    roots = np.sort_complex(np.roots([float(v) for v in sp.Poly(by_hand3.xreplace(vals), lam).all_coeffs()]))
    assert np.allclose(eig, roots, atol=1e-10)


def test_first_order_method_2_solutions_match_original_system():
    """Solutions of the method-2 system A Y' + H Y = W (time-varying coefficients, forcing) equal those of the
    original mixed-order system integrated directly with solve_ivp (hand-written right-hand side)."""
    ve, (b, J, kap) = _governor_like(eps=sp.Rational(1, 2))
    vals = {m: 1.3, c: 0.4, k: 2.0, b: 0.8, J: 1.7, kap: 0.6}
    red = ve.first_order(method=2)
    assert red.state == (x, W_, dot(x))
    A = sp.lambdify(t, red.A.xreplace(vals))
    Hm = sp.lambdify(t, red.H.xreplace(vals))
    Wv = sp.lambdify(t, red.W.xreplace(vals))

    def reduced(tt, Y):
        return np.linalg.solve(np.array(A(tt), dtype=float), np.ravel(Wv(tt)) - np.array(Hm(tt), dtype=float) @ Y)

    def original(tt, s):  # s = (x, x', W_)
        xx, xd, ww = s
        xdd = (-0.4 * xd - 2.0 * (1 + 0.5 * np.cos(tt)) * xx + 0.8 * ww) / 1.3
        return [xd, xdd, (np.sin(tt) - 0.6 * xx) / 1.7]

    x0, v0, w0 = 0.3, -0.2, 0.5
    ts = np.linspace(0, 10, 11)
    opts = {"method": "DOP853", "rtol": 1e-12, "atol": 1e-12, "t_eval": ts}
    a = solve_ivp(reduced, (0, 10), [x0, w0, v0], **opts).y
    o = solve_ivp(original, (0, 10), [x0, v0, w0], **opts).y
    assert np.allclose(a[0], o[0], atol=1e-9) and np.allclose(a[1], o[2], atol=1e-9)
    assert np.allclose(a[2], o[1], atol=1e-9)
    # method 1 of the same system is a descriptor system (A singular): not integrable as an explicit ODE
    assert ve.first_order(method=1).A.xreplace(vals).det() == 0
    with pytest.raises(ModelError, match="method must be 1 or 2"):
        ve.first_order(method=3)
