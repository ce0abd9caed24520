"""m-fold advance / m-th difference (2.29–2.30, 2.35–2.37), parameter differentiation and integration (2.41–2.42),
and the indefinite sum with an arbitrary periodic function (2.67–2.68).

Source: seed 004_e76fcda81caa05d8 (Bulgakov 1954) §2.9–§2.13 and §2.18; research report seed-bulgakov-part1.md,
§2 "Chapter 2".  Independent checks: ``p * sympy.laplace_transform`` of the transformed original, numeric
quadrature of ``p Integral(x exp(-p t))`` with mpmath, and the difference equation checked pointwise.
"""

from __future__ import annotations

import mpmath
import pytest
import sympy as sp

from symosc.errors import ParameterError
from symosc.operational import (
    advance,
    differentiate_parameter,
    finite_difference,
    higher_difference,
    indefinite_sum,
    integrate_parameter,
    multiple_advance,
)

p = sp.Symbol("p", positive=True)
t = sp.Symbol("t", positive=True)
s = sp.Symbol("s", positive=True)
u = sp.Symbol("u", positive=True)


def _laplace_carson(x):
    return p * sp.laplace_transform(x, t, p, noconds=True)


def _quad_carson(f, pv: float, *, upper=mpmath.inf) -> mpmath.mpf:
    """p Integral(f(t) exp(-p t), (t, 0, upper)) by mpmath quadrature (f a Python callable)."""
    return pv * mpmath.quad(lambda tt: f(tt) * mpmath.exp(-pv * tt), [0, 1, 4, upper])


def _close(a, b, tol=1e-20):
    return abs(complex(sp.N(a, 40)) - complex(sp.N(b, 40))) <= tol * max(1.0, abs(complex(sp.N(b, 40))))


# --- m-fold advance (2.29–2.30) -------------------------------------------------------------------------------------


def test_multiple_advance_matches_laplace_of_shifted_original():
    """Bulgakov §2.9 (2.29–2.30): image of x(t + m tau) for x = t**2 exp(-t), tau = 1/2, m = 3."""
    x = t**2 * sp.exp(-t)
    tau = sp.Rational(1, 2)
    image = 2 * p / (p + 1) ** 3
    got = multiple_advance(image, p, tau, 3, original=(x, t))
    ref = _laplace_carson(x.subs(t, t + 3 * tau))
    for pv in (sp.Rational(1, 3), 2, sp.Rational(17, 4)):
        assert _close(got.subs(p, pv), ref.subs(p, pv))


def test_multiple_advance_with_given_heads_from_cut_images():
    """Heads alpha_j built independently: image of T^j x cut to (0, tau) = image(T^j x) - exp(-p tau) image(T^(j+1) x),
    with the images from sympy.laplace_transform; x = sin t, tau = 1, m = 4."""
    x, tau, m = sp.sin(t), 1, 4
    full = [_laplace_carson(x.subs(t, t + j * tau)) for j in range(m + 1)]
    heads = [full[j] - sp.exp(-p * tau) * full[j + 1] for j in range(m)]
    got = multiple_advance(p / (p**2 + 1), p, tau, m, heads)
    assert sp.simplify(sp.expand_trig(got - full[m])) == 0


def test_multiple_advance_numeric_quadrature():
    """x = exp(-t/3) sin(2 t), tau = 0.7, m = 2: against mpmath quadrature of p Integral(x(t + 1.4) exp(-p t))."""
    x = sp.exp(-t / 3) * sp.sin(2 * t)
    tau = sp.Rational(7, 10)
    image = _laplace_carson(x)
    got = multiple_advance(image, p, tau, 2, original=(x, t))
    for pv in (0.5, 2.0, 6.0):
        ref = _quad_carson(lambda tt: mpmath.exp(-(tt + 1.4) / 3) * mpmath.sin(2 * (tt + 1.4)), pv)
        assert abs(complex(sp.N(got.subs(p, sp.Rational(str(pv))), 30)) - complex(ref)) < 1e-14


def test_multiple_advance_reduces_to_advance_and_identity():
    """m = 1 is the advance theorem (2.28); m = 0 leaves the image unchanged."""
    x = t * sp.exp(-2 * t)
    image = p / (p + 2) ** 2
    one = multiple_advance(image, p, 1, 1, original=(x, t))
    assert sp.simplify(one - advance(image, p, 1, (x, t))) == 0
    assert multiple_advance(image, p, 1, 0, []) == image


def test_multiple_advance_long_chain():
    """Extreme: m = 12 advances of exp(-t) by tau = 1/4 give exp(-3) exp(-t) exactly."""
    got = multiple_advance(p / (p + 1), p, sp.Rational(1, 4), 12, original=(sp.exp(-t), t))
    assert sp.simplify(got - sp.exp(-3) * p / (p + 1)) == 0


# --- m-th difference (2.35–2.37) ------------------------------------------------------------------------------------


def test_third_difference_of_cubic_is_constant():
    """Delta^3 t^3 = 6 tau^3 (2.35 with m = 3); tau = 1/2 -> 3/4, whose Carson image is the constant 3/4."""
    got = higher_difference(6 / p**3, p, sp.Rational(1, 2), 3, original=(t**3, t))
    assert sp.simplify(got) == sp.Rational(3, 4)


def test_high_order_difference_of_power():
    """Extreme: Delta^6 t^6 = 6! tau^6 exactly (tau = 1/3)."""
    tau = sp.Rational(1, 3)
    x, image = t**6, sp.factorial(6) / p**6
    assert sp.simplify(higher_difference(image, p, tau, 6, original=(x, t))) == sp.factorial(6) * tau**6


def test_higher_difference_numeric_quadrature():
    """Delta^2 x for x = exp(-t) cos t, tau = 0.7, written out directly (x(t+2 tau) - 2 x(t+tau) + x(t)) and
    transformed by mpmath quadrature."""
    x = sp.exp(-t) * sp.cos(t)
    tau = sp.Rational(7, 10)
    got = higher_difference(_laplace_carson(x), p, tau, 2, original=(x, t))

    def xf(tt):
        return mpmath.exp(-tt) * mpmath.cos(tt)

    for pv in (0.3, 5.0):
        ref = _quad_carson(lambda tt: xf(tt + 1.4) - 2 * xf(tt + 0.7) + xf(tt), pv)
        assert abs(complex(sp.N(got.subs(p, sp.Rational(str(pv))), 30)) - complex(ref)) < 1e-14


def test_higher_difference_symbolic_tau_against_laplace():
    """Delta^2 exp(a t) = (exp(a tau) - 1)^2 exp(a t), symbolic tau, via heads computed by direct integration."""
    a = sp.Rational(-3, 2)
    tau = sp.Symbol("tau", positive=True)
    x = sp.exp(a * t)
    got = higher_difference(p / (p - a), p, tau, 2, original=(x, t))
    ref = (sp.exp(a * tau) - 1) ** 2 * p / (p - a)
    assert sp.simplify(got - ref) == 0


def test_first_difference_agrees_with_finite_difference():
    """m = 1 reproduces (2.34)."""
    x = sp.sin(t)
    one = higher_difference(p / (p**2 + 1), p, 2, 1, original=(x, t))
    assert sp.simplify(one - finite_difference(p / (p**2 + 1), p, 2, (x, t))) == 0


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: multiple_advance(1 / p, p, 1, 2), "exactly one"),
        (lambda: multiple_advance(1 / p, p, 1, 2, [0], original=(t, t)), "exactly one"),
        (lambda: multiple_advance(1 / p, p, 1, 2, [0]), "needs 2 head"),
        (lambda: multiple_advance(1 / p, p, -1, 2, [0, 0]), "tau >= 0"),
        (lambda: multiple_advance(1 / p, p, 1, -1, []), "integer >= 0"),
        (lambda: higher_difference(1 / p, p, 1, 1.5, [0]), "integer >= 0"),
        (lambda: higher_difference(1 / p, p, 0, 1, [0]), "tau > 0"),
        (lambda: differentiate_parameter(p / (p - s), 2 * s), "Symbol"),
        (lambda: differentiate_parameter(p / (p - s), s, -1), "order"),
        (lambda: integrate_parameter(p / (p - s), "s", 0), "Symbol"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ParameterError, match=match):
        call()


# --- parameter differentiation and integration (2.41–2.42) --------------------------------------------------------


def test_differentiate_parameter_sin():
    """§2.13 (2.42): d/ds [p s/(p^2 + s^2)] is the image of d/ds sin(s t) = t cos(s t) (sympy.laplace_transform)."""
    got = differentiate_parameter(p * s / (p**2 + s**2), s)
    assert sp.simplify(got - _laplace_carson(t * sp.cos(s * t))) == 0


def test_differentiate_parameter_second_order():
    """d^2/ds^2 exp(s t) = t^2 exp(s t) <-> 2 p/(p - s)^3 (sympy.laplace_transform)."""
    got = differentiate_parameter(p / (p - s), s, 2)
    assert sp.simplify(got - _laplace_carson(t**2 * sp.exp(s * t))) == 0


def test_integrate_parameter_definite_limits():
    """§2.12 (2.41): Integral(cos(u t), (u, 0, 2)) = sin(2 t)/t <-> Integral(p^2/(p^2 + u^2), (u, 0, 2))."""
    got = integrate_parameter(p**2 / (p**2 + u**2), u, 0, 2)
    assert sp.simplify(got - _laplace_carson(sp.sin(2 * t) / t)) == 0


def test_integrate_parameter_variable_limit_numeric():
    """Integral(exp(-u t), (u, 0, s)) = (1 - exp(-s t))/t; its image checked by quadrature at s = 3."""
    got = integrate_parameter(p / (p + u), u, 0, s)
    assert got.has(s)
    for pv in (0.5, 2.0, 7.0):
        ref = _quad_carson(lambda tt: -mpmath.expm1(-3 * tt) / tt, pv)
        assert abs(complex(sp.N(got.subs({s: 3, p: sp.Rational(str(pv))}), 30)) - complex(ref)) < 1e-14


# --- indefinite sum with an arbitrary periodic function (2.67–2.68) ----------------------------------------------


def test_indefinite_sum_solves_the_difference_equation():
    """(2.67–2.68): y(t + tau) - y(t) = x(t) pointwise, exactly, with an arbitrary piece a(t) = cos(3 t) on (0, tau)."""
    tau = sp.Rational(1, 3)
    x = t**2 - 2 * t
    y = indefinite_sum(x, t, tau, piece=sp.cos(3 * t))
    for tv in (sp.Rational(1, 10), sp.Rational(5, 4), sp.Rational(29, 10), sp.Rational(71, 7)):
        assert sp.simplify(y(tv + tau) - y(tv) - x.subs(t, tv)) == 0
    for tv in (sp.Rational(1, 7), sp.Rational(3, 10)):  # y = a on (0, tau)
        assert y(tv) == sp.cos(3 * tv)
    # the symbolic original agrees with the evaluator
    tv = sp.Rational(13, 6)
    assert sp.simplify(y.original.subs(t, tv).doit() - y(tv)) == 0


def test_indefinite_sum_periodic_part_is_periodic():
    """A(t) = a(t - tau floor(t/tau)) has period tau: the difference of two solutions is tau-periodic."""
    tau = sp.Rational(1, 2)
    y1 = indefinite_sum(sp.exp(-t), t, tau, piece=sp.Integer(0))
    y2 = indefinite_sum(sp.exp(-t), t, tau, piece=t**2)
    for tv in (sp.Rational(1, 5), sp.Rational(7, 3)):
        d0 = y2(tv) - y1(tv)
        for k in range(1, 4):
            assert sp.simplify(y2(tv + k * tau) - y1(tv + k * tau) - d0) == 0


def test_indefinite_sum_image_against_quadrature():
    """eta(p) = (X + exp(p tau) alpha)/(exp(p tau) - 1) against p Integral(y exp(-p t)) by mpmath quadrature over
    the intervals (k tau, (k+1) tau); x = exp(-t), tau = 1/2, a(t) = t."""
    tau = 0.5
    y = indefinite_sum(sp.exp(-t), t, sp.Rational(1, 2), piece=t, p=p)

    def y_num(tt):
        k = int(mpmath.floor(tt / tau))
        return sum(mpmath.exp(-(tt - j * tau)) for j in range(1, k + 1)) + (tt - k * tau)

    for pv in (2.0, 3.5):
        ref = pv * mpmath.fsum(
            mpmath.quad(lambda tt, pv=pv: y_num(tt) * mpmath.exp(-pv * tt), [k * tau + 1e-30, (k + 1) * tau - 1e-30])
            for k in range(60)
        )
        assert abs(complex(sp.N(y.image.subs(p, sp.Rational(str(pv))), 30)) - complex(ref)) < 1e-12


def test_indefinite_sum_of_unit_is_floor():
    """Delta y = 1 with y = 0 on (0, tau): y = floor(t/tau), image 1/(exp(p tau) - 1), table row (2.62)."""
    tau = sp.Symbol("tau", positive=True)
    y = indefinite_sum(sp.Integer(1), t, tau, piece=sp.Integer(0), p=p, image=sp.Integer(1))
    assert sp.simplify(y.image - 1 / (sp.exp(p * tau) - 1)) == 0
    y1 = indefinite_sum(sp.Integer(1), t, 1, piece=sp.Integer(0))
    assert [y1(sp.Rational(2 * k + 1, 2)) for k in range(6)] == list(range(6))


def test_indefinite_sum_general_solution_keeps_arbitrary_function():
    """Without a piece the periodic part is an undefined function a(t - tau floor(t/tau))."""
    y = indefinite_sum(t, t, 2, p=p)
    a = sp.Function("a")
    assert y.periodic == a(t - 2 * sp.floor(t / 2))
    assert y.original.has(sp.Sum) and y.original.has(a)
    assert "IndefiniteSum" in repr(y) and "y(t)" in y._repr_latex_()


def test_indefinite_sum_bad_input():
    with pytest.raises(ParameterError, match="tau > 0"):
        indefinite_sum(t, t, -1)
    with pytest.raises(ParameterError, match="numeric t >= 0"):
        indefinite_sum(t, t, 1, piece=sp.Integer(0))(-2)


def test_advance_and_difference_heads_without_positive_p():
    """The integrated head carries no Piecewise when p has no sign assumption (entire in p)."""
    from symosc.operational import advance, carson, finite_difference

    q, tt = sp.symbols("q tt")
    head_adv = advance(q / (q + 1), q, 1, (sp.exp(-tt), tt))
    head_dif = finite_difference(1 / q, q, 1, (tt, tt))
    assert not head_adv.has(sp.Piecewise) and not head_dif.has(sp.Piecewise)
    t_pos, p_pos = sp.symbols("t p", positive=True)
    expected = carson(sp.exp(-(t_pos + 1)), t_pos, p_pos).subs(p_pos, q)
    assert sp.simplify(head_adv - expected) == 0
    assert sp.simplify(head_dif - 1) == 0
