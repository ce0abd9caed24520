"""Lagrange engine: agreement with sympy.physics.mechanics, closed forms, conservation, bad input."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from symosc import ModelError, ParameterError, ddot, dot, t
from symosc.mechanics import LagrangianSystem
from symosc.models import n_link_pendulum, pendulum_symbols
from tests.mechanics.reference import sympy_pendulum, typed_chain

RNG = np.random.default_rng(20261121)


def _random_values(symbols, rng):
    """Positive random parameter values (and random states) for every symbol."""
    return {s: float(rng.uniform(0.5, 2.0)) for s in symbols}


CASES = [
    (n, links, inverted, pivot)
    for n in (1, 2, 3)
    for links, inverted, pivot in itertools.product(("point", "rigid"), (False, True), ("fixed", "vertical"))
] + [
    (n, links, inv, piv)
    for n in (4, 5)
    for links in ("point", "rigid")
    for inv, piv in ((False, "fixed"), (True, "vertical"))
]


@pytest.fixture(scope="module")
def sympy_reference():
    """``reference(n, links, inverted, pivot) -> (M, F)`` from sympy.physics.mechanics, in symosc's symbols.

    One LagrangesMethod per ``(n, inverted)``, built for rigid links on a vertically driven pivot (the general
    case); point masses are its ``lc_k = l_k, I_k = 0`` (a particle at the link's end) and a fixed pivot its
    ``a = 0``: the same Lagrangian exactly, so every case is checked against an independent derivation while the
    vector-based construction (most of this module's time) runs 10 times instead of 20."""
    built = {}

    def reference(n, links, inverted, pivot):
        if (n, inverted) not in built:
            lm, repl = sympy_pendulum(n, "rigid", inverted, "vertical")
            built[n, inverted] = (lm.mass_matrix.xreplace(repl), lm.forcing.xreplace(repl))
        M, F = built[n, inverted]
        s = pendulum_symbols(n)
        special = {s["a"]: 0} if pivot == "fixed" else {}
        if links == "point":
            special.update({lc: l for lc, l in zip(s["lc"], s["l"], strict=True)})
            special.update({inertia: 0 for inertia in s["I"]})
        return M.xreplace(special), F.xreplace(special)

    return reference


@pytest.mark.parametrize(("n", "links", "inverted", "pivot"), CASES)
def test_matches_sympy_mechanics(n, links, inverted, pivot, sympy_reference):
    """M and F agree with LagrangesMethod built from vectors, at random states, times and parameters."""
    system = n_link_pendulum(n, links=links, inverted=inverted, pivot=pivot)
    M_ref, F_ref = sympy_reference(n, links, inverted, pivot)
    syms = sorted(
        (M_ref.free_symbols | F_ref.free_symbols | system.mass_matrix.free_symbols | system.forcing.free_symbols),
        key=str,
    )
    # SymPy's own evaluator (lambdify to mpmath, 15 digits), once per matrix; then three random points
    evaluate = sp.lambdify(syms, [system.mass_matrix, system.forcing, M_ref, F_ref], "mpmath")
    for _ in range(3):
        vals = _random_values(syms, RNG)
        for s in syms:
            if s.name.startswith("phi"):
                vals[s] = float(RNG.uniform(-np.pi, np.pi))
        vals[t] = float(RNG.uniform(0, 10))
        M, F, Mr, Fr = (np.array(m.tolist(), dtype=float) for m in evaluate(*(vals[s] for s in syms)))
        np.testing.assert_allclose(M, Mr, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(F, Fr, rtol=1e-11, atol=1e-11)


def test_long_chain_against_closed_form():
    """n = 20: M_ij = (sum_{k>=max(i,j)} m_k) l_i l_j cos(phi_i - phi_j) and the classical chain forcing.

    The same derivation and compilation as for any n (no size-dependent branch); 20 links cost a third of 30."""
    n = 20
    system = n_link_pendulum(n)
    fo = system.first_order()
    rng = np.random.default_rng(3)
    m = rng.uniform(0.5, 2, n)
    l = rng.uniform(0.5, 2, n)
    g = 9.81
    phi = rng.uniform(-1, 1, n)
    w = rng.uniform(-1, 1, n)
    values = {**{f"m{i + 1}": m[i] for i in range(n)}, **{f"l{i + 1}": l[i] for i in range(n)}, "g": g}
    mf = fo._compiled.call(
        {**values, "t": 0.0, **{f"phi{i + 1}": phi[i] for i in range(n)}, **{f"phi{i + 1}_dot": w[i] for i in range(n)}}
    )
    tail = np.cumsum(m[::-1])[::-1]  # sum_{k >= i} m_k
    mu = tail[np.maximum.outer(np.arange(n), np.arange(n))]
    M_ref = mu * np.outer(l, l) * np.cos(np.subtract.outer(phi, phi))
    F_ref = -(mu * np.outer(l, l) * np.sin(np.subtract.outer(phi, phi))) @ (w**2) - tail * g * l * np.sin(phi)
    np.testing.assert_allclose(mf[:, :n], M_ref, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(mf[:, n], F_ref, rtol=1e-10, atol=1e-9)


def test_energy_conserved_three_link():
    """Undamped fixed-pivot 3-link pendulum: relative energy drift < 1e-8 over 10 periods."""
    system = n_link_pendulum(3, links="rigid")
    values = {
        "m1": 1.0,
        "m2": 0.7,
        "m3": 0.4,
        "l1": 1.0,
        "l2": 0.8,
        "lc1": 0.5,
        "lc2": 0.4,
        "lc3": 0.3,
        "I1": 0.08,
        "I2": 0.04,
        "I3": 0.02,
        "g": 9.81,
    }
    fo = system.first_order()
    period = 2 * np.pi / system.linearize().natural_frequencies(values)[0]
    x0 = np.array([0.8, -0.5, 1.2, 0.0, 0.3, -0.4])
    sol = solve_ivp(fo.rhs(values), (0, 10 * period), x0, method="DOP853", rtol=1e-13, atol=1e-13, dense_output=False)
    assert sol.success
    energy = fo.energy_function(values)
    e = np.array([energy(tt, x) for tt, x in zip(sol.t, sol.y.T, strict=True)])
    assert np.max(np.abs(e - e[0])) / abs(e[0]) < 1e-8
    # the motion is large: it is not a near-linear check
    assert np.ptp(sol.y[2]) > 1.0


def test_dynamicsymbols_and_plain_symbols_agree():
    from sympy.physics.mechanics import dynamicsymbols

    x = dynamicsymbols("x")
    m, k, c = sp.symbols("m k c", positive=True)
    a = LagrangianSystem(m * x.diff(t) ** 2 / 2, k * x**2 / 2, [x], dissipation=c * x.diff(t) ** 2 / 2)
    xs = sp.Symbol("x", real=True)
    b = LagrangianSystem(m * dot(xs) ** 2 / 2, k * xs**2 / 2, [xs], dissipation=c * dot(xs) ** 2 / 2)
    assert a.coordinates == b.coordinates
    assert sp.simplify(a.equations()[0] - (m * ddot(xs) + c * dot(xs) + k * xs)) == 0
    assert sp.simplify(b.equations()[0] - (m * ddot(xs) + c * dot(xs) + k * xs)) == 0


def test_forced_damped_oscillator_generalised_force():
    x = sp.Symbol("x", real=True)
    m, k, c, F0, w = sp.symbols("m k c F0 w", positive=True)
    s = LagrangianSystem(
        m * dot(x) ** 2 / 2, k * x**2 / 2, [x], dissipation=c * dot(x) ** 2 / 2, forces=[F0 * sp.cos(w * t)]
    )
    assert s.is_rheonomic
    lin = s.linearize()
    assert (lin.M[0], lin.D[0], lin.K[0], lin.f[0]) == (m, c, k, F0 * sp.cos(w * t))


def test_gyroscopic_rotating_frame():
    """Particle in a frame rotating at Omega, on an isotropic spring: D = 2 m Omega J, K = (k - m Omega^2) E."""
    x, y = sp.symbols("x y", real=True)
    m, k, W = sp.symbols("m k Omega", positive=True)
    T = m / 2 * ((dot(x) - W * y) ** 2 + (dot(y) + W * x) ** 2)
    lin = LagrangianSystem(T, k * (x**2 + y**2) / 2, [x, y]).linearize()
    assert lin.D == sp.Matrix([[0, -2 * m * W], [2 * m * W, 0]])
    assert sp.simplify(lin.K - (k - m * W**2) * sp.eye(2)) == sp.zeros(2, 2)


def test_linearization_equals_jacobian_of_forcing():
    """The energy route to (D, K) agrees with -dF/dq', -dF/dq of the full nonlinear forcing."""
    system = n_link_pendulum(3, links="rigid", inverted=True, pivot="vertical")
    lin = system.linearize()
    q, qd = system.coordinates, system.velocities
    at = {s: 0 for s in (*q, *qd)}
    K_ref = -system.forcing.jacobian(q).xreplace(at)
    D_ref = -system.forcing.jacobian(qd).xreplace(at)
    vals = _random_values(system.parameters, RNG)
    vals[t] = 0.37
    for A, B in ((lin.K, K_ref), (lin.D, D_ref)):
        np.testing.assert_allclose(
            np.array(A.evalf(subs=vals), float), np.array(B.evalf(subs=vals), float), rtol=1e-12, atol=1e-12
        )


def test_linearize_about_nonzero_point():
    """Pendulum linearized about the upright position phi = pi has K = -m g l."""
    s = n_link_pendulum(1)
    lin = s.linearize({"phi1": sp.pi})
    m, l, g = sp.symbols("m1 l1 g", positive=True)
    assert sp.simplify(lin.K[0] + m * g * l) == 0
    with pytest.raises(ModelError, match="not an equilibrium"):
        s.linearize({"phi1": sp.pi / 3})
    with pytest.raises(ModelError, match="not a coordinate"):
        s.linearize({"psi": 0})


# ---------------------------------------------------------------------------- bad input
def test_bad_coordinates():
    x = sp.Symbol("x")
    m = sp.Symbol("m", positive=True)
    with pytest.raises(ModelError, match="Symbols or dynamicsymbols"):
        LagrangianSystem(m * dot(x) ** 2 / 2, 0, [x**2])
    with pytest.raises(ModelError, match="Symbols or dynamicsymbols"):
        LagrangianSystem(m * dot(x) ** 2 / 2, 0, [1])
    with pytest.raises(ModelError, match="repeated"):
        LagrangianSystem(m * dot(x) ** 2 / 2, 0, [x, x])
    with pytest.raises(ModelError, match="time t"):
        LagrangianSystem(m * dot(x) ** 2 / 2, 0, [t])


def test_kinetic_energy_not_quadratic():
    x = sp.Symbol("x")
    m = sp.Symbol("m", positive=True)
    with pytest.raises(ModelError, match="not quadratic"):
        LagrangianSystem(m * dot(x) ** 3, 0, [x])
    with pytest.raises(ModelError, match="inside"):
        LagrangianSystem(m * sp.cos(dot(x)), 0, [x])
    with pytest.raises(ModelError, match="does not depend on any velocity"):
        LagrangianSystem(m * x**2, 0, [x])
    with pytest.raises(ModelError, match="V must not depend on velocities"):
        LagrangianSystem(m * dot(x) ** 2, dot(x) * x, [x])


def test_bad_parameter_values():
    lin = n_link_pendulum(2).linearize()
    good = {"m1": 1.0, "m2": 1.0, "l1": 1.0, "l2": 1.0, "g": 9.81}
    with pytest.raises(ParameterError, match="m1 must be positive"):
        lin.natural_frequencies({**good, "m1": -1.0})
    with pytest.raises(ParameterError, match="m2 must be positive"):
        lin.natural_frequencies({**good, "m2": 0.0})
    with pytest.raises(ParameterError, match="l1 must be finite"):
        lin.natural_frequencies({**good, "l1": float("nan")})
    with pytest.raises(ParameterError, match="missing values for: g, l2"):
        lin.natural_frequencies({"m1": 1.0, "m2": 1.0, "l1": 1.0})
    with pytest.raises(ParameterError, match="missing values for: m2"):
        n_link_pendulum(2).first_order().rhs({k: v for k, v in good.items() if k != "m2"})
    with pytest.raises(ParameterError, match="g must be positive"):
        n_link_pendulum(2).first_order().energy_function({**good, "g": -9.81})


def test_singular_mass_matrix():
    x, y = sp.symbols("x y", real=True)
    m, k = sp.symbols("m k", positive=True)
    s = LagrangianSystem(m * (dot(x) + dot(y)) ** 2 / 2, k * (x**2 + y**2) / 2, [x, y])
    with pytest.raises(ModelError, match="not positive definite"):
        s.linearize().natural_frequencies({"m": 1.0, "k": 1.0})
    f = s.first_order().rhs({"m": 1.0, "k": 1.0})
    with pytest.raises(ModelError, match="singular"):
        f(0.0, np.zeros(4))


def test_model_catalogue_bad_input():
    with pytest.raises(ModelError, match="positive integer"):
        n_link_pendulum(0)
    with pytest.raises(ModelError, match="links"):
        n_link_pendulum(2, links="rope")
    with pytest.raises(ModelError, match="pivot"):
        n_link_pendulum(2, pivot="horizontal")


def test_latex_representation():
    small = n_link_pendulum(1)._repr_latex_()
    assert small.startswith("$$") and r"\ddot{\phi_{1}}" in small
    assert "LagrangianSystem" in n_link_pendulum(5)._repr_latex_()


def test_dynamicsymbols_are_replaced_as_by_xreplace():
    """The energies in plain symbols are exactly ``xreplace`` of the typed ones (sin, cos and squares of sums are
    rebuilt without SymPy's evaluation, which would leave them as they are)."""
    T, V, q = typed_chain(3)
    system = LagrangianSystem(T, V, q)
    rule = {}
    for c, p in zip(q, system.coordinates, strict=True):
        rule |= {c.diff(t): dot(p), c: p}
    assert sp.srepr(system.kinetic_energy) == sp.srepr(T.xreplace(rule))
    assert sp.srepr(system.potential_energy) == sp.srepr(V.xreplace(rule))


def _forcing_without_pieces(system: LagrangianSystem, monkeypatch) -> sp.Matrix:
    from symosc.mechanics import _terms

    with monkeypatch.context() as m:
        m.setattr(_terms, "_piece", lambda coeff, d, depends: None)
        return system._forcing_collected()


@pytest.mark.parametrize("make", ["chain", "rigid", "typed", "mixed"])
def test_forcing_from_gradient_pieces_equals_the_products(make, monkeypatch):
    """Gradient terms filed as their factors (no product built) give the very same forcing as the products."""
    x, phi = sp.symbols("x phi", real=True)
    m, k, c, a, p, b = sp.symbols("m k c a p b", positive=True)
    if make == "chain":
        system = n_link_pendulum(4, pivot="vertical")
    elif make == "rigid":
        system = n_link_pendulum(3, links="rigid", inverted=True)
    elif make == "typed":
        system = LagrangianSystem(*typed_chain(3))
    else:
        T = (1 + m * sp.sin(phi) ** 2) * dot(phi) ** 2 / 2 + m * dot(x) ** 2 / 2 + c * sp.cos(2 * x) * dot(x) * dot(phi)
        V = k * x**2 / 2 + a * sp.cos(p * t) * x * sp.sin(phi) + sp.cos(phi) ** 3
        system = LagrangianSystem(T, V, [x, phi], dissipation=b * dot(x) ** 2 / 2)
    assert sp.srepr(system.forcing) == sp.srepr(_forcing_without_pieces(system, monkeypatch))


def test_chain_geometry_is_built_on_first_access():
    import pickle

    from symosc.mechanics import Geometry
    from symosc.mechanics.lagrange import DeferredGeometry

    system = n_link_pendulum(2)
    assert isinstance(system.__dict__["_geometry"], DeferredGeometry)
    copy = pickle.loads(pickle.dumps(system))
    assert isinstance(system.geometry, Geometry) and system.geometry is system.geometry
    assert list(copy.geometry.points) == list(system.geometry.points) == ["pivot", "m1", "m2"]
    system.geometry = None
    assert system.geometry is None
