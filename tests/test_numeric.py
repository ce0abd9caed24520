"""symosc.numeric.compile: backends, broadcasting, CSE, argument checking."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

from symosc import ParameterError
from symosc.numeric import bind, compile, resolve

x, y = sp.symbols("x y", real=True)
m = sp.Symbol("m", positive=True)
a = sp.Symbol("a", nonnegative=True)


def test_scalar_and_broadcasting():
    f = compile(sp.sin(x) * y, [x, y])
    assert f(0.5, 2.0) == pytest.approx(2 * math.sin(0.5), rel=1e-15)
    out = f(np.linspace(0, 1, 5)[:, None], np.array([1.0, 2.0, 3.0]))
    assert out.shape == (5, 3)
    np.testing.assert_allclose(out, np.sin(np.linspace(0, 1, 5))[:, None] * np.array([1.0, 2.0, 3.0]), rtol=1e-15)


def test_matrix_shape_is_batch_first_and_constants_broadcast():
    f = compile(sp.Matrix([[x, 1], [0, y**2]]), [x, y])
    out = f(np.arange(4.0), 3.0)
    assert out.shape == (4, 2, 2)
    np.testing.assert_array_equal(out[:, 0, 1], 1.0)
    np.testing.assert_array_equal(out[:, 1, 1], 9.0)
    np.testing.assert_array_equal(out[:, 0, 0], np.arange(4.0))


def test_sequence_gives_vector():
    f = compile([x + y, x - y], [x, y])
    np.testing.assert_array_equal(f(3.0, 1.0), [4.0, 2.0])


def test_cse_shares_subexpressions_and_source_runs():
    e = sp.exp(sp.sin(x) ** 2 + y)
    f = compile([e * x, e * y], [x, y], name="shared")
    assert "def shared(x, y):" in f.source
    # the common exp(...) is computed once on each path (math for real scalars, NumPy for arrays)
    assert f.source.count("math.exp(") == 1 and f.source.count("numpy.exp(") == 1
    namespace: dict = {}
    exec(f.source, namespace)  # the generated code is self-contained Python that users can copy
    np.testing.assert_allclose(namespace["shared"](0.3, 0.2), f(0.3, 0.2), rtol=1e-15)
    np.testing.assert_allclose(namespace["shared"](np.array([0.3, 0.1]), 0.2)[0], f(0.3, 0.2), rtol=1e-15)


def test_mpmath_backend_is_high_precision():
    """exp(x) - 1 - x at x = 1e-10: float64 loses everything to cancellation, 50 digits keep ~30."""
    expr = sp.exp(x) - 1 - x
    got = compile(expr, [x], backend="mpmath", dps=50)("1e-10")
    with mpmath.workdps(80):
        ref = mpmath.expm1(mpmath.mpf("1e-10")) - mpmath.mpf("1e-10")
        assert abs(got - ref) / ref < mpmath.mpf("1e-28")
    as_float = compile(expr, [x])(1e-10)
    assert abs(as_float - float(ref)) / float(ref) > 1e-3


def test_mpmath_matrix():
    f = compile(sp.Matrix([[x, y], [x * y, 1]]), [x, y], backend="mpmath")
    out = f(2, 3)
    assert isinstance(out, mpmath.matrix)
    assert out[1, 0] == 6


def test_missing_symbols_are_named():
    with pytest.raises(ParameterError, match="not arguments: m, y"):
        compile(x + y + m, [x])


def test_wrong_argument_count():
    f = compile(x + y, [x, y])
    with pytest.raises(ParameterError, match=r"expected 2 arguments \(x, y\), got 1"):
        f(1.0)


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), [1.0, float("nan")]])
def test_non_finite_inputs_are_named(bad):
    f = compile(x * y, [x, y])
    with pytest.raises(ParameterError, match="y must be finite"):
        f(1.0, bad)


def test_sign_assumptions_checked():
    f = compile(m * a, [m, a])
    with pytest.raises(ParameterError, match="m must be positive"):
        f(0.0, 1.0)
    with pytest.raises(ParameterError, match="a must be non-negative"):
        f(1.0, [0.0, -1.0])
    assert f(1.0, 0.0) == 0.0
    with pytest.raises(ParameterError, match="m must be positive"):
        compile(m, [m], backend="mpmath")(-1)


def test_real_symbol_rejects_complex_and_unchecked_raw_skips_checks():
    f = compile(x**2, [x])
    with pytest.raises(ParameterError, match="declared real"):
        f(1j)
    assert np.isnan(f.raw(float("nan")))


def test_bad_arguments():
    with pytest.raises(ParameterError, match="must be SymPy Symbols"):
        compile(x, [x**2])
    with pytest.raises(ParameterError, match="unique"):
        compile(x, [x, sp.Symbol("x")])
    with pytest.raises(ParameterError, match="unknown backend"):
        compile(x, [x], backend="jax")
    with pytest.raises(ParameterError, match="expected a number"):
        compile(x, [x])("abc")


def test_resolve_and_bind():
    assert resolve([x, m], {"x": 1, m: 2}) == [1, 2]
    with pytest.raises(ParameterError, match="missing values for: x, m"):
        resolve([x, m], {})
    assert bind(x * m, {"x": sp.Rational(1, 3), "m": 3}) == 1


def test_complex_expression():
    f = compile(sp.exp(sp.I * x), [x])
    np.testing.assert_allclose(f(np.pi), -1.0 + 0j, atol=1e-15)


def test_algebraic_root_constants_are_evaluated():
    """CRootOf constants (roots of irreducible quintics) compile at the backend's precision."""
    r = sp.CRootOf(x**5 - x - 1, 0)
    f = compile(r * y, [y])
    assert f(2.0) == pytest.approx(2 * 1.1673039782614187, rel=1e-15)
    g = compile(r * y, [y], backend="mpmath", dps=40)
    with mpmath.workdps(40):
        ref = mpmath.findroot(lambda z: z**5 - z - 1, 1.17)
        assert abs(g(1) - ref) < mpmath.mpf("1e-38")


def test_special_functions_through_scipy():
    """Bessel and elliptic functions compile in the NumPy backend; values checked against mpmath."""
    k = sp.Symbol("k", positive=True)
    f = compile([sp.besselj(1, x), sp.besseli(0, x), sp.elliptic_k(k)], [x, k])
    got = f(2.5, 0.3)
    np.testing.assert_allclose(
        got, [float(mpmath.besselj(1, 2.5)), float(mpmath.besseli(0, 2.5)), float(mpmath.ellipk(0.3))], rtol=1e-14
    )
    assert "scipy.special" in f.source


def test_checked_array_call_names_the_bad_argument_and_matches_raw():
    """Small arrays take a whole-batch check; a single bad entry still gives the argument's name."""
    x = sp.Symbol("x", real=True)
    m = sp.Symbol("m", positive=True)
    f = compile(m * x**2 + sp.sqrt(m), [x, m])
    xs, ms = np.linspace(-1.0, 1.0, 5), np.linspace(0.5, 2.0, 5)
    np.testing.assert_array_equal(f(xs, ms), f.raw(xs, ms))
    np.testing.assert_array_equal(f(xs, 2), f.raw(xs, 2))  # mixed array and int
    bad = ms.copy()
    bad[3] = -1.0
    with pytest.raises(ParameterError, match="m must be positive"):
        f(xs, bad)
    bad[3] = np.nan
    with pytest.raises(ParameterError, match="m must be finite"):
        f(xs, bad)
    with pytest.raises(ParameterError, match="x must be finite"):
        f(np.array([0.0, np.inf]), ms[:2])
