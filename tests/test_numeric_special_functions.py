"""Every function the numpy, C and LLVM backends map, against mpmath (SymPy's 30-digit evalf at exact arguments).

For real arguments the value must agree to 1e-12 relative; where the true value is complex (``asin(2)``,
``loggamma(-0.5)``) a real evaluator gives NaN (or, for NumPy, the complex value itself).  For complex arguments
(NumPy backend) the value must agree to 1e-12 or the call must fail with a ``TypeError`` naming the SymPy function.
A function a backend cannot evaluate must be refused at compile time, by name.  The points avoid poles and the
branch cuts themselves (on a cut the sign of a zero imaginary part decides, NumPy following C99).
"""

from __future__ import annotations

import functools
import warnings

import mpmath
import numpy as np
import pytest
import sympy as sp
from sympy.codegen.cfunctions import Cbrt, Sqrt, exp2, expm1, hypot, log1p, log2, log10

from symosc import ParameterError
from symosc.numeric import compile

x, y = sp.symbols("x y")
N = sp.Symbol("N")
Y = 0.65
REAL = [-3.7, -0.5, 0.3, 0.9, 1.7, 4.2]
COMPLEX = [0.3 + 0.4j, -1.2 + 0.7j, 2.5 - 1.5j]

FUNCTIONS = {
    "sin": sp.sin(x), "cos": sp.cos(x), "tan": sp.tan(x), "cot": sp.cot(x), "sec": sp.sec(x), "csc": sp.csc(x),
    "asin": sp.asin(x), "acos": sp.acos(x), "atan": sp.atan(x), "acot": sp.acot(x), "asec": sp.asec(x),
    "acsc": sp.acsc(x), "atan2": sp.atan2(x, y), "sinh": sp.sinh(x), "cosh": sp.cosh(x), "tanh": sp.tanh(x),
    "coth": sp.coth(x), "sech": sp.sech(x), "csch": sp.csch(x), "asinh": sp.asinh(x), "acosh": sp.acosh(x),
    "atanh": sp.atanh(x), "acoth": sp.acoth(x), "exp": sp.exp(x), "log": sp.log(x), "sqrt": sp.sqrt(x),
    "root3": x ** sp.Rational(1, 3), "power": x**y, "Abs": sp.Abs(x), "sign": sp.sign(x), "floor": sp.floor(x),
    "ceiling": sp.ceiling(x), "frac": sp.frac(x), "Mod": sp.Mod(x, y), "Min": sp.Min(x, y), "Max": sp.Max(x, y),
    "re": sp.re(x), "im": sp.im(x), "conjugate": sp.conjugate(x), "arg": sp.arg(x), "Heaviside": sp.Heaviside(x),
    "sinc": sp.sinc(x), "expm1": expm1(x), "log1p": log1p(x), "exp2": exp2(x), "log2": log2(x), "log10": log10(x),
    "Cbrt": Cbrt(x), "Sqrt": Sqrt(x), "hypot": hypot(x, y), "gamma": sp.gamma(x), "loggamma": sp.loggamma(x),
    "factorial": sp.factorial(x), "RisingFactorial": sp.RisingFactorial(x, 3), "digamma": sp.digamma(x),
    "polygamma": sp.polygamma(1, x), "harmonic": sp.harmonic(x), "beta": sp.beta(x, y), "erf": sp.erf(x),
    "erfc": sp.erfc(x), "besselj": sp.besselj(sp.Rational(5, 2), x), "bessely": sp.bessely(1, x),
    "besseli": sp.besseli(1, x), "besselk": sp.besselk(0, x), "airyai": sp.airyai(x), "airybi": sp.airybi(x),
    "airyaiprime": sp.airyaiprime(x), "airybiprime": sp.airybiprime(x), "LambertW": sp.LambertW(x),
    "Ei": sp.Ei(x), "Si": sp.Si(x), "Ci": sp.Ci(x), "fresnels": sp.fresnels(x), "fresnelc": sp.fresnelc(x),
    "lowergamma": sp.lowergamma(sp.Rational(3, 2), x), "uppergamma": sp.uppergamma(sp.Rational(3, 2), x),
    "betainc": sp.betainc(2, 3, 0, x), "betainc_regularized": sp.betainc_regularized(2, 3, 0, x),
    "elliptic_k": sp.elliptic_k(x), "elliptic_e": sp.elliptic_e(x), "assoc_legendre": sp.assoc_legendre(4, 2, x),
    # classical orthogonal polynomials of a degree given at call time (N) and of a fixed degree kept unevaluated
    "chebyshevt": sp.chebyshevt(N, x), "chebyshevu": sp.chebyshevu(N, x), "legendre": sp.legendre(N, x),
    "hermite": sp.hermite(N, x), "laguerre": sp.laguerre(N, x), "assoc_laguerre": sp.assoc_laguerre(N, y, x),
    "gegenbauer": sp.gegenbauer(N, y, x), "jacobi": sp.jacobi(N, y, 2 * y, x),
    "chebyshevu99": sp.chebyshevu(99, x, evaluate=False),
}  # fmt: skip
DEGREES = [0, 1, 7, 99]


def _exact(v: complex | float) -> sp.Expr:
    v = complex(v)
    return sp.Rational(v.real) + sp.I * sp.Rational(v.imag)


def _points(complex_too: bool, expr: sp.Expr) -> list[tuple]:
    xs = REAL + (COMPLEX if complex_too else [])
    degrees = DEGREES if N in expr.free_symbols else [None]
    return [(xv, n) for xv in xs for n in degrees]


# mpmath's own (hypergeometric) evaluation of the polynomials: exact rational arithmetic at degree 99 is slow.
MPMATH_POLYNOMIALS = {
    sp.chebyshevt: lambda n, a, b, z: mpmath.chebyt(n, z),
    sp.chebyshevu: lambda n, a, b, z: mpmath.chebyu(n, z),
    sp.legendre: lambda n, a, b, z: mpmath.legendre(n, z),
    sp.hermite: lambda n, a, b, z: mpmath.hermite(n, z),
    sp.laguerre: lambda n, a, b, z: mpmath.laguerre(n, 0, z),
    sp.assoc_laguerre: lambda n, a, b, z: mpmath.laguerre(n, a, z),
    sp.gegenbauer: lambda n, a, b, z: mpmath.gegenbauer(n, a, z),
    sp.jacobi: lambda n, a, b, z: mpmath.jacobi(n, a, b, z),
}


@functools.cache
def _reference(expr: sp.Expr, xv, n) -> complex | None:
    if type(expr) in MPMATH_POLYNOMIALS:
        with mpmath.workdps(40):
            z = mpmath.mpmathify(xv)
            degree = n if n is not None else int(expr.args[0])
            a = mpmath.mpf(Y)
            return complex(MPMATH_POLYNOMIALS[type(expr)](degree, a, 2 * a, z))
    sub = {x: _exact(xv), y: sp.Rational(Y)} | ({N: sp.Integer(n)} if n is not None else {})
    try:
        value = complex(sp.N(expr.xreplace(sub), 30))
    except (TypeError, ValueError, ZeroDivisionError, AttributeError):  # no mpmath value (e.g. hypot of complex)
        return None
    return None if not np.isfinite(value.real) or not np.isfinite(value.imag) else value


def _check(name: str, backend: str, f, expr: sp.Expr) -> list:
    """Disagreements (point, value, reference) of ``f`` over the grid."""
    bad = []
    for xv, n in _points(backend == "numpy", expr):
        ref = _reference(expr, xv, n)
        try:
            with warnings.catch_warnings(), np.errstate(all="ignore"):
                warnings.simplefilter("ignore")
                got = complex(np.asarray(f(xv, Y, 0 if n is None else n)))
        except TypeError as exc:  # refused for complex arguments, naming the SymPy function
            if isinstance(xv, complex) and name.rstrip("0123456789") in str(exc):
                continue
            bad.append((xv, n, repr(exc), ref))
            continue
        except ValueError as exc:  # refused outside the mapped domain, naming the function
            if "betainc" in name and "betainc" in str(exc):
                continue
            bad.append((xv, n, repr(exc), ref))
            continue
        if ref is None:
            continue
        complex_value = abs(ref.imag) > 1e-15 * abs(ref)
        if complex_value and isinstance(xv, float) and np.isnan(got):
            continue  # a real evaluator: NaN where the value is complex
        if not abs(got - ref) <= 1e-12 * abs(ref) + 1e-300:
            bad.append((xv, n, got, ref))
    return bad


def _compiled(backend: str) -> dict:
    """One callable per function the backend accepts; refusals must name the function."""
    out = {}
    for name, expr in FUNCTIONS.items():
        try:
            out[name] = expr
            compile(expr, [x, y, N], backend="numpy" if backend == "c" else backend, check=False)
        except ParameterError as exc:
            del out[name]
            function = type(expr).__name__.lower()
            assert function in str(exc).lower() or name.lower() in str(exc).lower(), (name, backend, str(exc))
    if backend == "c":  # one library for all of them; what the C printer cannot print is refused by name
        printable = {}
        for name, expr in out.items():
            try:
                from symosc.numeric._c import function_source

                function_source("probe", [x, y, N], ["x", "y", "N"], [expr], None)
                printable[name] = expr
            except ParameterError as exc:
                assert type(expr).__name__.lower() in str(exc).lower(), (name, str(exc))
        lib = compile(list(printable.values()), [x, y, N], backend="c", check=False).raw
        return {name: (lambda *a, i=i: lib(*a)[i]) for i, name in enumerate(printable)}
    return {name: compile(expr, [x, y, N], backend=backend, check=False).raw for name, expr in out.items()}


@pytest.mark.parametrize("backend", ["numpy", "c", "llvm"])
def test_mapped_functions_agree_with_mpmath_or_are_refused_by_name(backend, private_symosc_cache):
    functions = _compiled(backend)
    assert len(functions) >= {"numpy": 80, "c": 40, "llvm": 25}[backend]
    failures = {name: bad for name in functions if (bad := _check(name, backend, functions[name], FUNCTIONS[name]))}
    assert not failures, failures


def test_chebyshev_u_of_degree_99_at_a_complex_point_is_right():
    """SciPy's eval_chebyu(99, 0.5+0j) gives 4.6e24; U_99(cos t) = sin(100 t)/sin t = -1 at t = pi/3."""
    f = compile(sp.chebyshevu(N, x), [N, x]).raw
    assert complex(f(99, 0.5 + 0j)) == pytest.approx(-1.0, rel=1e-13)
    assert complex(f(99, np.array([0.5 + 0j, 0.5 + 1e-3j]))[0]) == pytest.approx(-1.0, rel=1e-13)


def test_loggamma_and_mod_follow_sympy_in_c():
    """C's lgamma is log|Gamma| and fmod truncates; SymPy's loggamma(-0.5) is complex, Mod(-0.5, 0.7) = 0.2."""
    f = compile([sp.loggamma(x), sp.Mod(x, y)], [x, y], backend="c", check=False).raw
    out = f(-0.5, 0.7)
    assert np.isnan(out[0]) and out[1] == pytest.approx(0.2, rel=1e-14)
    with pytest.raises(ParameterError, match="loggamma"):
        compile(sp.loggamma(x), [x], backend="llvm")
