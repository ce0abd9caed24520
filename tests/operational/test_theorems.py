"""Theorems of the Carson calculus (Bulgakov §2.4-§2.17, seed 004; report §1 ch. 2), each checked on closed-form
originals against p * sympy.laplace_transform of the transformed original (an independent computation)."""

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.errors import ModelError, ParameterError
from symosc.operational import (
    advance,
    carson,
    convolution,
    delay,
    differentiate_image,
    differentiate_original,
    duhamel,
    final_value,
    initial_value,
    integral_to_infinity,
    integrate_original,
    inverse_carson,
    shift,
    similarity,
)

p = sp.Symbol("p")
t = sp.Symbol("t", positive=True)

ORIGINALS = [sp.exp(-2 * t), t**2 * sp.exp(t), sp.sin(3 * t), sp.cos(t) * sp.exp(-t / 2)]


def _img(x):
    return sp.simplify(p * sp.laplace_transform(x, t, p, noconds=True))


def _same(a, b) -> bool:
    """Equal symbolically, or (when simplify cannot tell) numerically at three real p."""
    return sp.simplify(a - b) == 0 or all(abs(complex((a - b).subs(p, v))) < 1e-12 for v in (2.3, 4.1, 7.7))


@pytest.mark.parametrize("x", ORIGINALS)
def test_shift_similarity_image_derivative(x):
    """(2.38) shift, (2.46) similarity, (2.23) t^m x(t)."""
    X = carson(x, t, p)
    assert _same(shift(X, p, 3), _img(sp.exp(-3 * t) * x))
    assert _same(similarity(X, p, sp.Rational(5, 2)), _img(x.subs(t, sp.Rational(5, 2) * t)))
    assert _same(differentiate_image(X, p, 2), _img(t**2 * x))


@pytest.mark.parametrize("x", ORIGINALS)
def test_differentiation_and_integration_of_original(x):
    """(2.18) with initial values x(0), x'(0); (2.11)-(2.12) repeated integration; (2.14) with a constant."""
    X = carson(x, t, p)
    init = [x.subs(t, 0), sp.diff(x, t).subs(t, 0)]
    assert _same(differentiate_original(X, p, init), _img(sp.diff(x, t, 2)))
    u = sp.Symbol("u", positive=True)
    once = sp.integrate(x.subs(t, u), (u, 0, t))
    assert _same(integrate_original(X, p), _img(once))
    assert _same(integrate_original(X, p, 2), _img(sp.integrate(once.subs(t, u), (u, 0, t))))
    assert _same(integrate_original(X, p, constant=5), _img(once + 5))


def test_convolution_and_duhamel():
    """(2.43)-(2.45): X Y/p <-> Integral(x(u) y(t-u)), X Y <-> its derivative."""
    u = sp.Symbol("u", positive=True)
    x, y = sp.exp(-t), sp.sin(2 * t)
    conv = sp.integrate(x.subs(t, u) * y.subs(t, t - u), (u, 0, t))
    X, Y = carson(x, t, p), carson(y, t, p)
    assert _same(convolution(X, Y, p), _img(conv))
    assert _same(duhamel(X, Y, p), _img(sp.diff(conv, t)))


def test_delay_and_advance():
    """(2.26a) delay and (2.28) advance, checked by inverting the result."""
    ts = sp.Symbol("t")
    X = carson(sp.exp(-ts), ts, p)
    x_delayed = inverse_carson(delay(X, p, 2), p, ts)
    assert sp.simplify(x_delayed - sp.exp(-(ts - 2)) * sp.Heaviside(ts - 2)) == 0
    adv = advance(X, p, 1, (sp.exp(-t), t))
    assert _same(sp.simplify(adv), _img(sp.exp(-(t + 1))))
    with pytest.raises(ParameterError, match=">= 0"):
        delay(X, p, -1)
    with pytest.raises(ParameterError, match="a > 0"):
        similarity(X, p, -2)


def test_initial_value():
    """(2.47): x(0+) = X(oo)."""
    for x in [*ORIGINALS, 3 + sp.cos(t)]:
        assert initial_value(carson(x, t, p), p) == x.subs(t, 0)
    with pytest.raises(ModelError, match="no finite limit"):
        initial_value(p**2 / (p + 1), p)


def test_final_value_valid_cases():
    """(2.49): x(oo) = X(0) for 2(1 - e^-t), 1 + t e^-t, and a damped oscillation."""
    assert final_value(carson(2 * (1 - sp.exp(-t)), t, p), p) == 2
    assert final_value(carson(1 + t * sp.exp(-t), t, p), p) == 1
    assert final_value(carson(sp.exp(-t) * sp.sin(4 * t), t, p), p) == 0


@pytest.mark.parametrize(
    "x",
    [sp.sin(t), sp.cos(2 * t) + 1, t, sp.exp(t), t * sp.exp(-t) + sp.exp(t / 10)],
    ids=["sin", "cos+1", "ramp", "growth", "mixed"],
)
def test_final_value_refuses(x):
    """Stability note 8: sin t has X(0) = 0 but no limit; the ramp, growth, cos all must be rejected."""
    with pytest.raises(ModelError, match="final value theorem not applicable"):
        final_value(carson(x, t, p), p)


def test_final_value_symbolic_undecidable_and_nonrational():
    a = sp.Symbol("a", real=True)
    with pytest.raises(ModelError, match="cannot decide"):
        final_value(p / (p - a), p)
    assert final_value(p / (p + sp.Symbol("b", positive=True)), p) == 0
    with pytest.raises(ModelError, match="non-rational"):
        final_value(sp.exp(-p), p)


def test_integral_to_infinity():
    """(2.48): Integral(x, 0, oo) = [X/p](0) when sigma_c < 0; refused for a step (sigma_c = 0)."""
    x = t * sp.exp(-2 * t) + sp.exp(-t) * sp.cos(t)
    assert integral_to_infinity(carson(x, t, p), p) == sp.integrate(x, (t, 0, sp.oo))
    with pytest.raises(ModelError, match="does not converge"):
        integral_to_infinity(sp.Integer(1), p)


quasi = st.tuples(st.integers(-3, 3), st.integers(0, 2), st.integers(-2, 1), st.integers(0, 2))


@settings(max_examples=10, deadline=None)
@given(st.lists(quasi, min_size=1, max_size=3))
def test_property_derivative_and_shift(terms):
    """Property: carson(x') == differentiate_original(carson(x), [x(0)]) and carson(e^(-2t) x) == shift(X, 2)."""
    ts = sp.Symbol("t")
    x = sum(c * ts**k * sp.exp(a * ts) * (sp.cos(w * ts) if w % 2 == 0 else sp.sin(w * ts)) for c, k, a, w in terms)
    X = carson(x, ts, p)
    lhs = differentiate_original(X, p, [x.subs(ts, 0)])
    rhs = carson(sp.diff(x, ts), ts, p)
    sh = shift(X, p, 2) - carson(sp.exp(-2 * ts) * x, ts, p)
    for v in (1.7, 3.9):
        assert abs(complex((lhs - rhs).subs(p, v))) < 1e-9
        assert abs(complex(sh.subs(p, v))) < 1e-9


@pytest.mark.parametrize("m", [0, 2, 3])
def test_product_of_originals_worked_example(m):
    """§2.31 (report §3 item 10): x = t^m/m!, y = e^(eps t) cosh(l t): residues at q = eps +- l give (2.146);
    the sine variant (2.149) likewise; both against p * laplace_transform of the product."""
    from symosc.operational import product_of_originals, table_entry

    eps, lam, w = sp.Rational(-1, 3), sp.Rational(1, 2), 2
    X = 1 / p**m
    img = product_of_originals(X, carson(sp.exp(eps * t) * sp.cosh(lam * t), t, p), p)
    _, expected = table_entry("(2.146)").substitute({"m": m, "epsilon": eps, "lambda": lam})
    assert _same(img, expected)
    img = product_of_originals(X, carson(sp.exp(eps * t) * sp.sin(w * t), t, p), p)
    assert _same(img, _img(t**m / sp.factorial(m) * sp.exp(eps * t) * sp.sin(w * t)))
    with pytest.raises(ModelError, match="rational image"):
        product_of_originals(X, sp.exp(-p), p)


def test_finite_sum_by_direct_integration():
    """(2.31): X/(e^(p tau) - 1) <-> sum_{j=1}^{floor(t/tau)} x(t - j tau), for x = t and x = e^(-t),
    checked by p * Integral(... exp(-p t)) with mpmath quadrature over the steps (independent)."""
    import math

    import mpmath

    from symosc.operational import finite_sum

    tau, pv = 0.7, 1.7
    for x, xf in ((t, lambda s: s), (sp.exp(-t), lambda s: mpmath.exp(-s))):
        img = finite_sum(carson(x, t, p), p, sp.Rational(7, 10))

        def summed(tv, xf=xf):
            return sum(xf(tv - j * tau) for j in range(1, math.floor(tv / tau) + 1))

        pts = [k * tau for k in range(0, 50)]
        direct = pv * mpmath.quad(lambda tv, summed=summed: summed(tv) * mpmath.exp(-pv * tv), pts)
        assert abs(float(img.subs(p, pv)) - float(direct)) < 1e-10


def test_finite_difference():
    """(2.34): (e^(p tau) - 1) X - e^(p tau) alpha <-> x(t + tau) - x(t)."""
    from symosc.operational import finite_difference

    x = sp.exp(-t) * sp.cos(t)
    img = finite_difference(carson(x, t, p), p, 2, (x, t))
    ref = carson(sp.expand(x.subs(t, t + 2) - x, power_exp=True), t, p)
    for v in (1.3, 2.9, 5.0):
        assert abs(complex((img - ref).subs(p, v))) < 1e-12
    with pytest.raises(ParameterError, match="tau > 0"):
        finite_difference(p, p, -1, 0)
