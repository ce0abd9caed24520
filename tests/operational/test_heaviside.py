"""Heaviside expansion theorems and residue inversion (Bulgakov §2.19, §2.30; seed 004; report §2.5)."""

import mpmath
import pytest
import sympy as sp

from symosc import numeric
from symosc.errors import ConvergenceError, ModelError
from symosc.operational import first_expansion, heaviside_expand, inverse_carson, residue_inverse

p, t = sp.symbols("p t")


def _close(a, b, ts=(0.1, 0.7, 2.3), tol=1e-11) -> bool:
    """The two originals agree (30-digit evaluation) at the times ``ts``."""
    for tv in ts:
        va, vb = complex(sp.N(a.subs(t, tv), 30)), complex(sp.N(b.subs(t, tv), 30))
        if abs(va - vb) > tol * (1 + abs(vb)):
            return False
    return True


def test_book_example_repeated_root():
    """§2.19, report §2.5: p(3p+1)/((p-1)^2 (p+2)) <-> ((12t+5) e^(3t) - 5) e^(-2t)/9 (exact)."""
    x = heaviside_expand(p * (3 * p + 1) / ((p - 1) ** 2 * (p + 2)), p, t)
    assert sp.simplify(x - ((12 * t + 5) * sp.exp(3 * t) - 5) * sp.exp(-2 * t) / 9) == 0


@pytest.mark.parametrize(
    "image",
    [
        p / ((p + 1) * (p + 2) * (p + 3)),
        p**2 / ((p + 1) ** 3 * (p + 2)),
        p * (p + 5) / ((p**2 + 2 * p + 5) * (p + 1)),
        p**3 / ((p**2 + 1) ** 2),
        (2 * p**2 + 1) / ((p**2 + 4) * (p + 1) ** 2),
        p / (p**2 * (p + 1)),
    ],
)
def test_agrees_with_sympy_inverse_laplace(image):
    """Common ground with SymPy: inverse_laplace_transform(X/p) (independent implementation)."""
    ref = sp.inverse_laplace_transform(image / p, p, t).subs(sp.Heaviside(t), 1)
    x = heaviside_expand(image, p, t)
    assert sp.simplify(x - ref) == 0 or _close(x, ref)


def test_real_form_for_complex_pairs():
    """(2.89)-(2.91): conjugate pairs give exp(a t)(A cos bt + B sin bt), no I in the result."""
    x = heaviside_expand(p * (p + 3) / ((p**2 + 2 * p + 10) ** 2), p, t)
    assert not x.has(sp.I)
    assert x.has(sp.cos) and x.has(sp.sin)
    xc = heaviside_expand(p * (p + 3) / ((p**2 + 2 * p + 10) ** 2), p, t, real=False)
    assert xc.has(sp.I)
    assert _close(x, xc)


def test_symbolic_parameters():
    """(2.55) with symbolic epsilon, omega through the expansion theorem."""
    eps = sp.Symbol("epsilon", real=True)
    w = sp.Symbol("omega", positive=True)
    x = heaviside_expand(p * w / ((p - eps) ** 2 + w**2), p, t)
    assert sp.simplify(x - sp.exp(eps * t) * sp.sin(w * t)) == 0


def test_high_degree_exact_and_numeric():
    """Degree 5 irreducible denominator: CRootOf residues, checked against mpmath numeric inversion."""
    image = p / (p**5 + 3 * p**4 + 5 * p**3 + 5 * p**2 + 3 * p + 1 + sp.Rational(1, 7))
    x = heaviside_expand(image, p, t)
    f = lambda s: 1 / (s**5 + 3 * s**4 + 5 * s**3 + 5 * s**2 + 3 * s + 1 + mpmath.mpf(1) / 7)  # noqa: E731
    for tv in (1.5,):
        with mpmath.workdps(30):
            ref = mpmath.invertlaplace(f, tv, method="dehoog")
        assert abs(complex(sp.N(x.subs(t, tv), 20)) - float(ref)) < 1e-12


def test_float_coefficients_with_exact_repeated_root():
    """Floats: a repeated root of the float data is found as repeated (no 1/delta blow-up)."""
    x = heaviside_expand(1.0 * p / (p**2 + 2.0 * p + 1.0), p, t)
    assert _close(x, t * sp.exp(-t))


def test_nearly_repeated_poles_stay_accurate():
    """Stability note 7: poles -1 and -1 + 1e-9 (exact data).  The exact result, evaluated through the mpmath
    backend at 40 digits, matches the analytic formula (e^(-t) - e^(-(1-d)t))/(-d) ~ t e^(-t)."""
    d = sp.Rational(1, 10**9)
    x = heaviside_expand(p / ((p + 1) * (p + 1 - d)), p, t)
    f = numeric.compile(x, [t], backend="mpmath", dps=40)
    for tv in (0.5, 3.0):
        with mpmath.workdps(40):
            ref = (mpmath.exp(-(1 - mpmath.mpf(d.p) / d.q) * tv) - mpmath.exp(-tv)) / (mpmath.mpf(d.p) / d.q)
        assert abs(f(tv) - ref) < 1e-25


def test_improper_image_rejected():
    """Carson image of an ordinary function has deg num <= deg den; otherwise delta functions -> clear error."""
    with pytest.raises(ModelError, match="improper Carson image"):
        heaviside_expand(p**3 / (p**2 + 1), p, t)
    with pytest.raises(ModelError, match="not a rational function"):
        heaviside_expand(sp.exp(-p) / p, p, t)


def test_zero_and_constant_images():
    assert heaviside_expand(sp.Integer(0), p, t) == 0
    assert heaviside_expand(sp.Integer(3), p, t) == 3  # 3 <-> 3 (unit step times 3), (2.7)


def test_matrix_image():
    """Matrix images invert entry by entry: p (E p - a)^-1 <-> exp(a t) (2.53)."""
    a = sp.Matrix([[0, 1], [-2, -3]])
    img = (sp.eye(2) * p - a).inv() * p
    assert sp.simplify(heaviside_expand(img, p, t) - (a * t).exp()) == sp.zeros(2, 2)


def test_residue_inverse_rational_and_entire_numerator():
    """(2.141): residue sum equals the Heaviside expansion for rational images; exponential factors (Jordan's
    lemma fails below the delay) and non-polynomial denominators are refused with a hint."""
    assert sp.simplify(residue_inverse(p / (p + 2) ** 2, p, t) - t * sp.exp(-2 * t)) == 0
    with pytest.raises(ModelError, match="delay theorem"):
        residue_inverse(sp.exp(-p) / (p + 1), p, t)
    with pytest.raises(ModelError, match="polynomial denominator"):
        residue_inverse(sp.sinh(p) / sp.cosh(p), p, t)


def test_first_expansion_theorem():
    """(2.72): X = sum a_k p^-k <-> sum a_k t^k/k!; p/(p+1) <-> exp(-t) partial sums; and J0: p/sqrt(p^2+1)."""
    s = first_expansion(p / (p + 1), p, t, order=12)
    assert sp.expand(s - sp.series(sp.exp(-t), t, 0, 12).removeO()) == 0
    j0 = first_expansion(p / sp.sqrt(p**2 + 1), p, t, order=16)
    assert abs(float(j0.subs(t, 1)) - float(sp.besselj(0, 1))) < 1e-12
    with pytest.raises(ConvergenceError, match="raise order"):
        first_expansion(p / (p + 1), p, sp.Integer(30), order=5, tol=1e-6)
    with pytest.raises(ModelError, match="analytic at infinity"):
        first_expansion(p**2 + 1, p, t)


def test_inverse_carson_delay_and_sympy_fallback():
    """Delay theorem (2.26a) inside inverse_carson; SymPy fallback for a non-rational image."""
    x = inverse_carson(p * sp.exp(-2 * p) / (p + 1) + 1 / p, p, t)
    assert sp.simplify(x - (sp.exp(-(t - 2)) * sp.Heaviside(t - 2) + t)) == 0
    j0 = inverse_carson(p / sp.sqrt(p**2 + 1), p, t)
    assert sp.simplify(j0 - sp.besselj(0, t)) == 0


def test_extremes_high_multiplicity_and_stiff_poles():
    """Extremes: an 8-fold pole (t^7 e^-t/7!) and poles 1e-3 apart from 1e3 (stiff pair), exact."""
    x = heaviside_expand(p / (p + 1) ** 8, p, t)
    assert sp.simplify(x - t**7 * sp.exp(-t) / sp.factorial(7)) == 0
    x = heaviside_expand(p / ((p + sp.Rational(1, 1000)) * (p + 1000)), p, t)
    ref = (sp.exp(-t / 1000) - sp.exp(-1000 * t)) / (1000 - sp.Rational(1, 1000))
    assert sp.simplify(x - ref) == 0


def test_numeric_roots_option_gives_real_compilable_original():
    """roots='numeric': 30-digit poles, real form, compilable; equals the exact CRootOf result."""
    image = p * (p + 2) / (p**3 + 2 * p**2 + 3 * p + 1)
    exact = heaviside_expand(image, p, t)
    approx = heaviside_expand(image, p, t, roots="numeric")
    assert exact.has(sp.CRootOf) and not approx.has(sp.I)
    f = numeric.compile(approx, [t])
    for tv in (0.4, 3.0):
        assert abs(f(tv) - complex(sp.N(exact.subs(t, tv), 20)).real) < 1e-13
    with pytest.raises(ModelError, match="roots must be"):
        heaviside_expand(image, p, t, roots="approximate")


def test_symbolic_repeated_root_and_matrix_inverse_carson():
    """p/(p+a)^2 <-> t e^(-a t) with symbolic a; inverse_carson maps matrices entry by entry."""
    a = sp.Symbol("a", positive=True)
    assert sp.simplify(heaviside_expand(p / (p + a) ** 2, p, t) - t * sp.exp(-a * t)) == 0
    m = inverse_carson(sp.Matrix([[1, 1 / p], [p / (p + 1), 0]]), p, t)
    assert m == sp.Matrix([[1, t], [sp.exp(-t), 0]])
