"""Floquet tools: monodromy matrix, multipliers, exponents, classification, Liouville check.

Sources: Bulgakov ch. 11 §11.1–11.4 (seed 004; research report seed-bulgakov-part3b.md §2.6) and
Gribkov & Khokhlov 2015 eq. (2)–(5) (seed 000; research report §2).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from scipy.linalg import eigvalsh_tridiagonal, expm

from symosc.errors import ModelError, ParameterError
from symosc.periodic import FloquetResult, floquet_multipliers, monodromy
from symosc.symbols import t


# ------------------------------------------------------------------ independent references (test-local)
def hill_value(kind: str, n: int, q: float, size: int = 80) -> float:
    """a_n(q) / b_n(q) from the symmetric tridiagonal Hill matrices (McLachlan ch. III), q >= 0."""
    if kind == "a" and n % 2 == 0:
        d = np.array([(2.0 * k) ** 2 for k in range(size)])
        e = np.full(size - 1, q)
        e[0] = np.sqrt(2.0) * q
        i = n // 2
    elif kind == "a":
        d = np.array([(2.0 * k + 1) ** 2 for k in range(size)])
        d[0] += q
        e = np.full(size - 1, q)
        i = n // 2
    elif n % 2:
        d = np.array([(2.0 * k + 1) ** 2 for k in range(size)])
        d[0] -= q
        e = np.full(size - 1, q)
        i = n // 2
    else:
        d = np.array([(2.0 * k + 2) ** 2 for k in range(size)])
        e = np.full(size - 1, q)
        i = n // 2 - 1
    return float(eigvalsh_tridiagonal(d, e, select="i", select_range=(i, i))[0])


def mathieu_A(a: float, q: float, c: float = 0.0):
    def A(tt: float) -> np.ndarray:
        return np.array([[0.0, 1.0], [-(a - 2.0 * q * np.cos(2.0 * tt)), -2.0 * c]])

    return A


def direct_monodromy(A, T: float) -> np.ndarray:
    """Column by column with solve_ivp (the way a user would do it without symosc)."""
    n = A(0.0).shape[0]
    cols = []
    for j in range(n):
        sol = solve_ivp(lambda tt, y: A(tt) @ y, (0, T), np.eye(n)[j], method="DOP853", rtol=1e-12, atol=1e-14)
        cols.append(sol.y[:, -1])
    return np.column_stack(cols)


R2 = np.diag([1.0, -1.0])


# ------------------------------------------------------------------ constant coefficients
def test_constant_matrix_gives_expm():
    """Constant A: X(T) = exp(A T) and the characteristic exponents are the eigenvalues of A."""
    rng = np.random.default_rng(1)
    A0 = rng.normal(size=(3, 3))
    res = monodromy(lambda tt: A0, 0.7)
    assert np.allclose(res.monodromy, expm(0.7 * A0), rtol=1e-10, atol=1e-12)
    ev = np.sort_complex(np.linalg.eigvals(A0))
    assert np.allclose(np.sort_complex(res.characteristic_exponents), ev, atol=1e-9)
    assert res.liouville_error < 1e-11
    assert res.trace_integral == pytest.approx(0.7 * np.trace(A0), rel=1e-12)


def test_constant_symbolic_matrix_with_parameters():
    k, c = sp.symbols("k c", positive=True)
    A = sp.Matrix([[0, 1], [-k, -c]])
    res = monodromy(A, 2.0, values={"k": 4.0, c: 0.5})
    assert np.allclose(res.monodromy, expm(2.0 * np.array([[0, 1], [-4.0, -0.5]])), rtol=1e-10, atol=1e-12)
    assert res.stability == "asymptotically stable"
    assert res.is_stable
    assert not res.reversor_used  # damping breaks reversibility


@settings(max_examples=15, deadline=None)
@given(st.lists(st.floats(-2, 2), min_size=4, max_size=4), st.floats(0.1, 3.0))
def test_property_constant_matrix(entries, T):
    A0 = np.array(entries).reshape(2, 2)
    res = monodromy(lambda tt: A0, T)
    assert np.allclose(res.monodromy, expm(T * A0), rtol=1e-9, atol=1e-11)
    assert np.prod(res.floquet_multipliers).real == pytest.approx(np.exp(T * np.trace(A0)), rel=1e-9)


# ------------------------------------------------------------------ Mathieu equation
@pytest.mark.parametrize("q", [0.1, 0.5, 1.0, 3.0])
def test_mathieu_boundaries_have_trace_pm2(q):
    """On a_0, b_2 (period pi) tr X(pi) = +2; on b_1, a_1 (period 2 pi) tr X(pi) = -2 (seed 000, eq. (4)–(5))."""
    for kind, n, sign in (("a", 0, 2.0), ("b", 1, -2.0), ("a", 1, -2.0), ("b", 2, 2.0)):
        a = hill_value(kind, n, q)
        res = monodromy(mathieu_A(a, q), np.pi, reversor=R2)
        assert np.trace(res.monodromy) == pytest.approx(sign, abs=2e-9), (kind, n)
        assert res.stability in ("critical", "stable")


@pytest.mark.parametrize("q", [0.2, 1.0, 2.5])
def test_mathieu_classification_against_hill_values(q):
    """Just inside a tongue (b_n, a_n) unstable, just outside stable; the band a_0 < a < b_1 is stable."""
    a0, b1, a1, b2 = (hill_value(k, n, q) for k, n in (("a", 0), ("b", 1), ("a", 1), ("b", 2)))
    eps = 1e-4
    cases = [(a0 - eps, False), (a0 + eps, True), (0.5 * (a0 + b1), True), (b1 - eps, True), (b1 + eps, False)]
    cases += [(0.5 * (b1 + a1), False), (a1 + eps, True), (b2 - eps, True)]
    for a, stable in cases:
        res = monodromy(mathieu_A(a, q), np.pi, reversor=R2)
        assert res.is_stable is stable, (a, q, res)
        assert (res.hamiltonian_indicator < 0) is stable


def test_reversor_matches_full_period_and_direct_integration():
    for a, q in [(-0.3, 0.9), (2.0, 0.4), (0.5, 0.5)]:
        half = monodromy(mathieu_A(a, q), np.pi, reversor=R2)
        full = monodromy(mathieu_A(a, q), np.pi, reversor=None)
        ref = direct_monodromy(mathieu_A(a, q), np.pi)
        assert half.reversor_used and not full.reversor_used
        assert np.allclose(half.monodromy, ref, rtol=1e-9, atol=1e-10)
        assert np.allclose(full.monodromy, ref, rtol=1e-9, atol=1e-10)
        assert np.linalg.det(half.monodromy) == pytest.approx(1.0, abs=1e-10)


def test_symbolic_mathieu_detects_reversor():
    a, q = sp.symbols("a q", real=True)
    A = sp.Matrix([[0, 1], [-(a - 2 * q * sp.cos(2 * t)), 0]])
    res = monodromy(A, sp.pi, values={"a": -0.1, "q": 0.5})
    assert res.reversor_used
    ref = direct_monodromy(mathieu_A(-0.1, 0.5), np.pi)
    assert np.allclose(res.monodromy, ref, rtol=1e-9, atol=1e-10)
    assert isinstance(res, FloquetResult)
    assert "stable" in repr(res)
    assert "rho" in res._repr_latex_()


def test_damped_mathieu_liouville():
    """Liouville (Bulgakov 11.26): det X(T) = exp(-2 c T) for x'' + 2c x' + (a - 2q cos 2t) x = 0."""
    c = 0.3
    res = monodromy(mathieu_A(1.0, 0.2, c), np.pi)
    assert np.linalg.det(res.monodromy) == pytest.approx(np.exp(-2 * c * np.pi), rel=1e-10)
    assert res.trace_integral == pytest.approx(-2 * c * np.pi, rel=1e-12)
    assert res.stability == "asymptotically stable"  # damping suppresses the first tongue at q = 0.2


def test_strongly_unstable_extreme():
    """Large q: the growing multiplier is ~e^(|zeta| T) >> 1; half-period and full-period agree on it."""
    q = 25.0
    a = 0.0
    half = monodromy(mathieu_A(a, q), np.pi, reversor=R2)
    full = monodromy(mathieu_A(a, q), np.pi, reversor=None)
    assert half.stability == "unstable"
    assert half.spectral_radius > 1e3
    assert half.spectral_radius == pytest.approx(full.spectral_radius, rel=1e-7)
    zeta = half.characteristic_exponents
    assert zeta[0].real == pytest.approx(np.log(half.spectral_radius) / np.pi, rel=1e-12)


def test_two_dof_hill_system_with_symbolic_reversor():
    """Coupled Hill system M x'' + (K0 + K1 cos 2t) x = 0: reversor auto-detected; Hamiltonian: det = 1."""
    a, q = sp.symbols("a q", real=True)
    B = sp.Matrix([[2, -1], [-1, 2]])
    Z, E = sp.zeros(2), sp.eye(2)
    A = sp.Matrix(sp.BlockMatrix([[Z, E], [-(a - 2 * q * sp.cos(2 * t)) * B, Z]]))
    res = monodromy(A, sp.pi, values={"a": 0.3, "q": 0.1})
    assert res.reversor_used
    An = sp.lambdify(t, A.subs({a: 0.3, q: 0.1}), "numpy")
    ref = direct_monodromy(lambda tt: np.array(An(tt), dtype=float), np.pi)
    assert np.allclose(res.monodromy, ref, rtol=1e-9, atol=1e-10)
    rho = res.floquet_multipliers
    assert np.allclose(np.sort(np.abs(rho)), 1.0, atol=1e-8) == res.is_stable


# ------------------------------------------------------------------ classification details
def test_classification_jordan_and_semisimple():
    zero = monodromy(lambda tt: np.zeros((2, 2)), 1.0)
    assert zero.stability == "stable"  # X = I: semisimple double multiplier 1
    shear = monodromy(lambda tt: np.array([[0.0, 1.0], [0.0, 0.0]]), 1.0)
    assert shear.stability == "critical"  # X = [[1, 1], [0, 1]]: Jordan block, linear growth
    assert not shear.is_stable
    growth = monodromy(lambda tt: np.array([[1e-3]]), 1.0)
    assert growth.stability == "unstable"
    assert growth.effective_tol == pytest.approx(10 * np.sqrt(1e-12 * np.exp(1e-3)))
    assert monodromy(lambda tt: np.array([[1e-3]]), 1.0, unit_tol=1e-2).stability == "stable"


def test_floquet_multipliers_shortcut_and_plot():
    import matplotlib

    matplotlib.use("Agg")
    rho = floquet_multipliers(mathieu_A(2.0, 0.2), np.pi, reversor=R2)
    assert np.allclose(np.abs(rho), 1.0, atol=1e-9)
    ax = monodromy(mathieu_A(2.0, 0.2), np.pi).plot()
    assert ax.get_title().startswith("Floquet")


# ------------------------------------------------------------------ bad input
def test_bad_input():
    with pytest.raises(ParameterError, match="period"):
        monodromy(lambda tt: np.eye(2), -1.0)
    with pytest.raises(ParameterError, match="period"):
        monodromy(lambda tt: np.eye(2), float("nan"))
    with pytest.raises(ModelError, match="square"):
        monodromy(lambda tt: np.ones((2, 3)), 1.0)
    with pytest.raises(ModelError, match="square"):
        monodromy(sp.Matrix([[1, 2]]), 1.0)
    with pytest.raises(ModelError, match="not periodic"):
        monodromy(lambda tt: np.array([[0.0, 1.0], [-np.cos(tt), 0.0]]), 1.0)
    with pytest.raises(ParameterError, match=r"got the string 'A'; expected: sympy\.Matrix or callable"):
        monodromy("A", 1.0)
    k = sp.Symbol("k")
    with pytest.raises(ParameterError, match="missing values for: k"):
        monodromy(sp.Matrix([[0, 1], [-k, 0]]), 1.0)
    with pytest.raises(ModelError, match="involution"):
        monodromy(mathieu_A(1.0, 0.1), np.pi, reversor=np.eye(3))
    with pytest.raises(ModelError, match="R A"):
        monodromy(mathieu_A(1.0, 0.1, c=0.2), np.pi, reversor=R2)
    with pytest.raises(ParameterError, match="reversor"):
        monodromy(mathieu_A(1.0, 0.1), np.pi, reversor="yes")
