"""Constraints: multiplier form vs minimal form vs sympy.physics.mechanics, integrals, bad input.

References: sympy.physics.mechanics.LagrangesMethod with hol_coneqs / nonhol_coneqs (an independent engine),
closed forms (pendulum tension, the hoop's Jacobi integral), DOP853 integration at rtol 1e-12.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from sympy.physics.mechanics import LagrangesMethod, dynamicsymbols

from symosc import ModelError, dot, t
from symosc.mechanics import LagrangianSystem

RNG = np.random.default_rng(2026)

x, y, z, th, ph, X, Y = sp.symbols("x y z theta phi X Y", real=True)
m, g, l, R, w, I, J, a, alpha, k = sp.symbols("m g l R omega I J a alpha k", positive=True)


def _sympy_accelerations(L_expr, coords, hol, nonhol, subs):
    """q'' from LagrangesMethod (dynamicsymbols) at a numeric state; subs maps plain symbols to values."""
    qs = dynamicsymbols(" ".join(c.name for c in coords))
    qs = list(qs) if isinstance(qs, (list, tuple)) else [qs]
    to_dyn = {}
    for c, qf in zip(coords, qs, strict=True):
        to_dyn[dot(c)] = qf.diff(t)
        to_dyn[c] = qf
    lm = LagrangesMethod(
        L_expr.xreplace(to_dyn),
        qs,
        hol_coneqs=[h.xreplace(to_dyn) for h in hol] or None,
        nonhol_coneqs=[h.xreplace(to_dyn) for h in nonhol] or None,
    )
    lm.form_lagranges_equations()
    back = {}
    for c, qf in zip(coords, qs, strict=True):
        back[qf.diff(t)] = dot(c)
        back[qf] = c
    Mf = lm.mass_matrix_full.xreplace(back).xreplace(subs)
    Ff = lm.forcing_full.xreplace(back).xreplace(subs)
    sol = np.linalg.solve(np.array(Mf.evalf(30), dtype=float), np.array(Ff.evalf(30), dtype=float)).ravel()
    n = len(coords)
    return sol[n : 2 * n]


def _ours(system, subs):
    M = np.array(system.constrained.augmented_mass_matrix.xreplace(subs).evalf(30), dtype=float)
    F = np.array(system.constrained.augmented_forcing.xreplace(subs).evalf(30), dtype=float).ravel()
    sol = np.linalg.solve(M, F)
    n = len(system.coordinates)
    return sol[:n], sol[n:]


def _minimal(system, subs):
    mf = system.constrained.minimal_form()
    Mr = np.array(mf.mass_matrix.xreplace(subs).evalf(30), dtype=float)
    Fr = np.array(mf.forcing.xreplace(subs).evalf(30), dtype=float).ravel()
    ud = np.linalg.solve(Mr, Fr)
    # q'' of every coordinate: differentiate the velocity map along the motion
    vmap = mf.velocity_map()
    q = system.coordinates
    u = mf.independent
    qdd = []
    for k in range(len(q)):
        expr = sum(vmap[k].diff(qj) * vmap[j] for j, qj in enumerate(q)) + vmap[k].diff(t)
        expr += sum(vmap[k].diff(ui) * sp.Float(float(udi)) for ui, udi in zip(u, ud, strict=True))
        qdd.append(float(expr.xreplace(subs).evalf(30)))
    return np.array(qdd)


def _rel(a, b):
    return float(np.max(np.abs(a - b)) / max(1e-300, np.max(np.abs(b))))


# ---------------------------------------------------------------- systems
def cartesian_pendulum():
    return LagrangianSystem(m / 2 * (dot(x) ** 2 + dot(y) ** 2), m * g * y, [x, y], constraints=[x**2 + y**2 - l**2])


def hoop_cartesian():
    """Bead on a hoop of radius R spinning at rate omega about the vertical z axis."""
    T = m / 2 * (dot(x) ** 2 + dot(y) ** 2 + dot(z) ** 2)
    return LagrangianSystem(
        T, m * g * z, [x, y, z], constraints=[x * sp.sin(w * t) - y * sp.cos(w * t), x**2 + y**2 + z**2 - R**2]
    )


def rolling_disk():
    """Upright disk rolling on an incline: contact (X, Y), heading theta, spin phi; slope along X."""
    T = m / 2 * (dot(X) ** 2 + dot(Y) ** 2) + I / 2 * dot(th) ** 2 + J / 2 * dot(ph) ** 2
    V = m * g * sp.sin(alpha) * X + k * X**2 / 2
    non = [dot(X) - R * sp.cos(th) * dot(ph), dot(Y) - R * sp.sin(th) * dot(ph)]
    return LagrangianSystem(T, V, [X, Y, th, ph], nonholonomic=non)


def chaplygin_sleigh():
    """Blade at (X, Y) heading theta, centre of mass a ahead of the blade; no sideslip of the blade."""
    T = (
        m / 2 * ((dot(X) - a * sp.sin(th) * dot(th)) ** 2 + (dot(Y) + a * sp.cos(th) * dot(th)) ** 2)
        + I / 2 * dot(th) ** 2
    )
    return LagrangianSystem(T, 0, [X, Y, th], nonholonomic=[-sp.sin(th) * dot(X) + sp.cos(th) * dot(Y)])


def _params(rng):
    return {s: sp.Float(float(rng.uniform(0.5, 2.0)), 30) for s in (m, g, l, R, w, I, J, a, k)} | {
        alpha: sp.Float(float(rng.uniform(0.1, 1.0)), 30)
    }


# ---------------------------------------------------------------- agreement of the three forms
def test_cartesian_pendulum_three_ways_and_tension():
    """Multiplier form, minimal form, LagrangesMethod and the angle form agree; tension m(l th'^2 + g cos th)."""
    s = cartesian_pendulum()
    angle = s.reduce_coordinates({x: l * sp.sin(th), y: -l * sp.cos(th)}, [th])
    for _ in range(3):
        p = _params(RNG)
        a0, w0 = (sp.Float(float(v), 30) for v in RNG.uniform(-1.2, 1.2, 2))
        st = {
            x: p[l] * sp.sin(a0),
            y: -p[l] * sp.cos(a0),
            dot(x): p[l] * sp.cos(a0) * w0,
            dot(y): p[l] * sp.sin(a0) * w0,
        }
        subs = p | st | {t: 0}
        qdd, lam = _ours(s, subs)
        ref = _sympy_accelerations(
            s.kinetic_energy - s.potential_energy, s.coordinates, s.holonomic_constraints, [], subs
        )
        assert _rel(qdd, ref) < 1e-12
        assert _rel(_minimal(s, subs), ref) < 1e-12
        # the angle form: x'' = l (cos th th'' - sin th th'^2)
        thdd = float((angle.forcing[0] / angle.mass_matrix[0, 0]).xreplace(p | {th: a0}).evalf(30))
        xdd = float(p[l] * (sp.cos(a0) * thdd - sp.sin(a0) * w0**2))
        assert abs(qdd[0] - xdd) < 1e-12 * max(1, abs(xdd))
        # reaction: C^T lambda = 2 lambda (x, y); tension magnitude m (l th'^2 + g cos th)
        tension = float((p[m] * (p[l] * w0**2 + p[g] * sp.cos(a0))).evalf(30))
        assert abs(-2 * lam[0] * float(p[l]) - tension) < 1e-12 * abs(tension)


def test_hoop_multiplier_vs_sympy_and_angle_form():
    """Rheonomic holonomic constraints (bead on a spinning hoop) against LagrangesMethod and the angle form."""
    s = hoop_cartesian()
    for _ in range(3):
        p = _params(RNG)
        t0, a0, w0 = (sp.Float(float(v), 30) for v in RNG.uniform(-1.5, 1.5, 3))
        Rv, wv = p[R], p[w]
        ta, aa = sp.symbols("ta aa")
        P = sp.Matrix([Rv * sp.sin(aa) * sp.cos(wv * ta), Rv * sp.sin(aa) * sp.sin(wv * ta), -Rv * sp.cos(aa)])
        at = {ta: t0, aa: a0}
        pos = P.xreplace(at)
        vel = (P.diff(aa) * w0 + P.diff(ta)).xreplace(at)
        subs = p | {t: t0, x: pos[0], y: pos[1], z: pos[2], dot(x): vel[0], dot(y): vel[1], dot(z): vel[2]}
        qdd, _ = _ours(s, subs)
        ref = _sympy_accelerations(
            s.kinetic_energy - s.potential_energy, s.coordinates, s.holonomic_constraints, [], subs
        )
        assert _rel(qdd, ref) < 1e-12
        assert _rel(_minimal(s, subs), ref) < 1e-12
        # angle form (Landau & Lifshitz, Mechanics, §5 problem 3): th'' = (omega^2 cos th - g / R) sin th
        thdd = (wv**2 * sp.cos(a0) - p[g] / Rv) * sp.sin(a0)
        acc = (P.diff(aa) * thdd + P.diff(aa, 2) * w0**2 + 2 * P.diff(aa, ta) * w0 + P.diff(ta, 2)).xreplace(at)
        assert _rel(qdd, np.array(acc.evalf(30), dtype=float).ravel()) < 1e-12


@pytest.mark.parametrize("make", [rolling_disk, chaplygin_sleigh])
def test_nonholonomic_against_sympy(make):
    s = make()
    for _ in range(3):
        p = _params(RNG)
        mf = s.constrained.minimal_form()
        st = {c: sp.Float(float(RNG.uniform(-1, 1)), 30) for c in s.coordinates}
        st |= {u: sp.Float(float(RNG.uniform(-1, 1)), 30) for u in mf.independent}
        st |= {v: e.xreplace(st | p) for v, e in mf.dependent.items()}
        subs = p | st | {t: 0}
        qdd, _ = _ours(s, subs)
        ref = _sympy_accelerations(
            s.kinetic_energy - s.potential_energy, s.coordinates, [], s.nonholonomic_constraints, subs
        )
        assert _rel(qdd, ref) < 1e-12
        assert _rel(_minimal(s, subs), ref) < 1e-12
        assert np.max(np.abs(np.array(s.constrained.velocity_bias.xreplace(subs), dtype=float))) == 0


# ---------------------------------------------------------------- integrals over long runs
def _drift(system, integral, x0, values, t_end, stabilization=0.0):
    f = system.constrained.rhs(values, stabilization=stabilization)
    sol = solve_ivp(f, (0, t_end), x0, method="DOP853", rtol=1e-12, atol=1e-12, dense_output=False)
    assert sol.success
    args = [t, *system.coordinates, *system.velocities, *system.parameters]
    E = sp.lambdify(args, integral)
    pv = [values[s.name] for s in system.parameters]
    e = np.broadcast_to(E(sol.t, *sol.y, *pv), sol.t.shape)
    return float(np.max(np.abs(e - e[0])) / max(1.0, abs(e[0])))


def test_cartesian_pendulum_energy_drift_100_periods():
    s = cartesian_pendulum()
    vals = {"m": 1.0, "g": 9.81, "l": 1.0}
    a0 = 0.5
    x0 = [np.sin(a0), -np.cos(a0), 0.0, 0.0]
    period = 2 * np.pi * np.sqrt(1 / 9.81) * 1.02  # slightly longer than the small-amplitude period
    # Baumgarte stabilization keeps the length on the constraint; the energy then stays to ~1e-11
    assert _drift(s, s.jacobi_integral, x0, vals, 100 * period, stabilization=1.0) < 1e-9


def test_sleigh_energy_drift():
    """Chaplygin sleigh (Bloch, Nonholonomic Mechanics, §1.7): kinetic energy conserved."""
    s = chaplygin_sleigh()
    vals = {"m": 1.0, "a": 0.5, "I": 0.3}
    th0, thd0, u0 = 0.3, 1.0, 0.4
    x0 = [0.0, 0.0, th0, u0 * np.cos(th0), u0 * np.sin(th0), thd0]
    assert _drift(s, s.jacobi_integral, x0, vals, 100 * 2 * np.pi) < 1e-9


def test_rolling_disk_energy_and_constraints():
    s = rolling_disk()
    vals = {"m": 1.0, "g": 9.81, "alpha": 0.2, "R": 0.3, "I": 0.05, "J": 0.045, "k": 2.0}
    th0, phd0, thd0 = 0.4, 2.0, 0.7
    x0 = [0.0, 0.0, th0, 0.0, 0.3 * np.cos(th0) * phd0, 0.3 * np.sin(th0) * phd0, thd0, phd0]
    period = 2 * np.pi / np.sqrt(2.0 / (1.0 + 0.045 / 0.3**2))  # the spring's period along X
    assert _drift(s, s.jacobi_integral, x0, vals, 100 * period) < 1e-9


# ---------------------------------------------------------------- split, Christoffel, energy function
def test_hoop_angle_form_split_and_jacobi_integral():
    """Reduced hoop: T1 = 0, T0 = m R^2 omega^2 sin^2 th / 2 and h = T2 - T0 + V (Goldstein, §2.7)."""
    s = hoop_cartesian().reduce_coordinates(
        {x: R * sp.sin(th) * sp.cos(w * t), y: R * sp.sin(th) * sp.sin(w * t), z: -R * sp.cos(th)}, [th]
    )
    assert not s.holonomic_constraints
    T2, T1, T0 = (sp.simplify(e) for e in s.kinetic_energy_parts)
    assert sp.simplify(T2 - m * R**2 * dot(th) ** 2 / 2) == 0
    assert T1 == 0
    assert sp.simplify(T0 - m * R**2 * w**2 * sp.sin(th) ** 2 / 2) == 0
    h = s.jacobi_integral
    L = s.kinetic_energy - s.potential_energy
    assert sp.simplify(h - (dot(th) * L.diff(dot(th)) - L)) == 0
    # dh/dt = 0 along the motion (solved form)
    thdd = s.forcing[0] / s.mass_matrix[0, 0]
    rate = h.diff(th) * dot(th) + h.diff(dot(th)) * thdd
    assert sp.simplify(rate) == 0


def test_rheonomic_constraints_have_no_jacobi_integral():
    with pytest.raises(ModelError, match="rheonomic"):
        _ = hoop_cartesian().jacobi_integral


def test_christoffel_polar():
    """Polar coordinates: Gamma^r_{phi phi} = -r, Gamma^phi_{r phi} = 1/r (Bulgakov (1954), §3.7)."""
    r = sp.Symbol("r", positive=True)
    s = LagrangianSystem(m / 2 * (dot(r) ** 2 + r**2 * dot(ph) ** 2), 0, [r, ph])
    G = s.christoffel_symbols()
    assert G[0, 1, 1] == -r and sp.simplify(G[1, 0, 1] - 1 / r) == 0 and G[0, 0, 0] == 0
    G1 = s.christoffel_symbols(kind=1)
    assert sp.simplify(G1[0, 1, 1] + m * r) == 0


def test_christoffel_solved_form_matches_engine():
    """q'' = -Gamma q' q' - M^-1 dV/dq for a natural double pendulum (eq. (3.88)), vs the engine's M^-1 F."""
    from symosc.models import n_link_pendulum

    s = n_link_pendulum(2)
    G1 = s.christoffel_symbols(kind=1)
    q, qd = s.coordinates, s.velocities
    V = s.potential_energy
    subs = {sym: sp.Float(float(RNG.uniform(0.5, 1.5)), 30) for sym in (*s.parameters, *q, *qd)}
    Minv = s.mass_matrix.xreplace(subs).inv()
    ours = Minv * s.forcing.xreplace(subs)
    G1 = G1.subs(subs)
    for j in range(2):
        solved = -sum(
            Minv[j, mm] * G1[mm, k, ll] * qd[k] * qd[ll] for mm in range(2) for k in range(2) for ll in range(2)
        ) - sum(Minv[j, k] * V.diff(q[k]) for k in range(2))
        assert abs(float((solved.xreplace(subs) - ours[j]).evalf(30))) < 1e-20


# ---------------------------------------------------------------- bad input
def test_bad_constraints():
    T = m / 2 * (dot(x) ** 2 + dot(y) ** 2 + dot(z) ** 2)
    with pytest.raises(ModelError, match="linearly dependent"):
        LagrangianSystem(T, 0, [x, y, z], constraints=[x + y - 1, 2 * x + 2 * y - 3])
    with pytest.raises(ModelError, match="linearly dependent"):
        LagrangianSystem(T, 0, [x, y, z], constraints=[x - y], nonholonomic=[dot(x) - dot(y)])
    with pytest.raises(ModelError, match="no coordinate"):
        LagrangianSystem(T, 0, [x, y, z], constraints=[l - 1])
    with pytest.raises(ModelError, match="nonholonomic="):
        LagrangianSystem(T, 0, [x, y, z], constraints=[dot(x) - y])
    with pytest.raises(ModelError, match="not linear"):
        LagrangianSystem(T, 0, [x, y, z], nonholonomic=[dot(x) ** 2 - dot(y)])
    with pytest.raises(ModelError, match="no freedom"):
        LagrangianSystem(T, 0, [x, y, z], constraints=[x, y, z])
    with pytest.raises(ModelError, match="constraints"):
        cartesian_pendulum().first_order()
    with pytest.raises(ModelError, match="no constraints"):
        _ = LagrangianSystem(T, 0, [x, y, z]).constrained


def test_dae_and_index_reduced_forms_and_numeric_accelerations():
    """The DAE rows hold phi at position level; the index-1 rows vanish at the solved (q'', lambda); the numeric
    accelerations and residuals match a direct evaluation."""
    s = cartesian_pendulum()
    c = s.constrained
    dae = c.dae_equations()
    assert dae.shape == (3, 1) and dae[2] == x**2 + y**2 - l**2
    qdd, lam = c.solved()
    sub = {**dict(zip(s.accelerations, qdd, strict=True)), **dict(zip(c.multipliers, lam, strict=True))}
    assert c.index_reduced_equations().xreplace(sub).applyfunc(sp.simplify) == sp.zeros(3, 1)
    assert c.reaction_forces == sp.Matrix([2 * x * c.multipliers[0], 2 * y * c.multipliers[0]])
    vals = {"m": 1.5, "g": 9.81, "l": 2.0}
    a0, w0 = 0.4, -0.3
    state = [2 * np.sin(a0), -2 * np.cos(a0), 2 * np.cos(a0) * w0, 2 * np.sin(a0) * w0]
    acc, mult = c.accelerations(vals, 0.0, state)
    subs = {m: 1.5, g: 9.81, l: 2.0, x: state[0], y: state[1], dot(x): state[2], dot(y): state[3]}
    assert np.allclose(acc, np.array(qdd.xreplace(subs), dtype=float).ravel(), rtol=1e-12)
    assert np.allclose(mult, np.array(lam.xreplace(subs), dtype=float).ravel(), rtol=1e-12)
    assert np.max(np.abs(c.residuals(vals, 0.0, state))) < 1e-14
    assert np.max(np.abs(c.residuals(vals, 0.0, [3.0, 0.0, 0.0, 1.0]))) > 1


def test_dynamicsymbols_input_and_pickling():
    """Coordinates and constraints given as dynamicsymbols give the same augmented system; results pickle."""
    import pickle

    xd, yd = dynamicsymbols("x y")
    s = LagrangianSystem(
        m / 2 * (xd.diff(t) ** 2 + yd.diff(t) ** 2), m * g * yd, [xd, yd], constraints=[xd**2 + yd**2 - l**2]
    )
    ref = cartesian_pendulum()
    assert s.constrained.augmented_mass_matrix == ref.constrained.augmented_mass_matrix
    assert s.constrained.augmented_forcing == ref.constrained.augmented_forcing
    mf = ref.constrained.minimal_form()
    back = pickle.loads(pickle.dumps(mf))
    assert back.mass_matrix == mf.mass_matrix and back.dependent == mf.dependent


# ---------------------------------------------------------------- rank of the constraint Jacobian
def _rank_numpy(rows, point):
    """Independent reference: numpy's SVD rank of the Jacobian evaluated with lambdify at one point."""
    import numpy as np

    return int(np.linalg.matrix_rank(np.array(sp.lambdify(list(point), rows)(*point.values()), dtype=float)))


def test_constraints_dependent_everywhere():
    """Redundant/inconsistent constraints (Bulgakov (1954), §3.1: the c constraint equations must be independent):
    the Jacobian loses rank at every configuration; the error names the dependent constraint and the ones it
    depends on, also for trigonometric (non-rational) constraints that go through the numeric test."""
    T = m / 2 * (dot(x) ** 2 + dot(y) ** 2 + dot(z) ** 2)
    # sin(x) - y = 0 and exp(sin(x) - y) = 2 are functionally dependent (inconsistent): parallel gradients
    c1, c2 = sp.sin(x) - y, sp.exp(sp.sin(x) - y) - 2
    rows = sp.Matrix([[c.diff(v) for v in (x, y, z)] for c in (c1, c2)])
    assert _rank_numpy(rows, {x: 0.37, y: -1.1, z: 0.2}) == 1  # the reference agrees that they are dependent
    with pytest.raises(ModelError, match=r"constraint 2 \(.*\) is linearly dependent on constraint 1"):
        LagrangianSystem(T, 0, [x, y, z], constraints=[c1, c2])
    # the dependent set is named, constraints that do not take part are not
    with pytest.raises(
        ModelError, match=r"constraint 3 \(2\*x \+ 2\*y - 3\) is linearly dependent on constraint 1 \("
    ) as info:
        LagrangianSystem(T, 0, [x, y, z, l], constraints=[x + y - 1, z, 2 * x + 2 * y - 3])
    assert "constraint 2 (z)" not in str(info.value)
    # a trigonometric identity in disguise: the gradient vanishes identically (numeric path, 30 digits)
    with pytest.raises(ModelError, match=r"constraint 1 .* gradient vanishes identically"):
        LagrangianSystem(T, 0, [x, y, z], constraints=[sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1])


def test_constraints_dependent_on_the_set_they_define():
    """Independent at generic configurations but dependent at every point where they hold: x = 0, x + y^2 = 0
    (which forces y = 0, where the gradients (1, 0), (1, 2y) coincide) and the circle written three times."""
    T = m / 2 * (dot(x) ** 2 + dot(y) ** 2 + dot(z) ** 2)
    rows = sp.Matrix([[1, 0, 0], [1, 2 * y, 0]])
    assert _rank_numpy(rows, {y: 0.3}) == 2 and _rank_numpy(rows, {y: 0.0}) == 1
    with pytest.raises(ModelError, match="rank 1 < 2 everywhere on the set"):
        LagrangianSystem(T, 0, [x, y, z], constraints=[x, x + y**2])
    with pytest.raises(ModelError, match="rank 2 < 3 everywhere on the set"):
        LagrangianSystem(T, 0, [x, y, z, l], constraints=[sp.sin(x) - y, sp.cos(x) - z, y**2 + z**2 - 1])


def test_constraints_dependent_on_a_submanifold_only():
    """Documented behaviour: a helix x = l cos z on the cylinder x^2 + y^2 = l^2 is tangent to it where
    z = k pi (y = 0, gradients (2x, 2y, 0) and (1, 0, l sin z) parallel).  The set of such points has lower
    dimension than the constrained configuration space, so the system is accepted; the multiplier form then
    refuses that configuration (singular augmented matrix) and is regular elsewhere."""
    L0 = sp.Symbol("L0", positive=True)
    T = m / 2 * (dot(x) ** 2 + dot(y) ** 2 + dot(z) ** 2)
    s = LagrangianSystem(T, 0, [x, y, z], constraints=[x**2 + y**2 - L0**2, x - L0 * sp.cos(z)])
    vals = {"m": 1.0, "L0": 1.0}
    with pytest.raises(ModelError, match="singular"):
        s.constrained.accelerations(vals, 0.0, [1.0, 0.0, 0.0, 0.0, 1.0, 0.5])
    z0 = 0.7
    qdd, lam = s.constrained.accelerations(vals, 0.0, [np.cos(z0), np.sin(z0), z0, 0.0, 0.0, 0.0])
    assert abs(qdd).max() < 1e-12 and abs(lam).max() < 1e-12  # at rest, no forces: no reaction


def test_independent_constraints_accepted():
    """Independent constraints, including ones whose Jacobian is singular only away from the constraint set
    (the circle at the origin), pass; the multiplier count equals the constraint count."""
    T = m / 2 * (dot(x) ** 2 + dot(y) ** 2 + dot(z) ** 2)
    s = LagrangianSystem(T, 0, [x, y, z], constraints=[x**2 + y**2 - l**2], nonholonomic=[dot(z) - sp.sin(x) * dot(y)])
    assert len(s.constrained.multipliers) == 2
    s2 = LagrangianSystem(T, 0, [x, y, z], constraints=[x**2 + y**2 + z**2 - l**2, z - x * y])
    assert s2.constrained.jacobian.rows == 2
