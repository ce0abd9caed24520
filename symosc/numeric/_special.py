"""Special functions in the "numpy" backend: mappings to SciPy checked against mpmath, and the replacements.

SymPy's SciPy printer maps several functions to SciPy routines that are wrong for part of their domain; each
such mapping is replaced here (or refused, naming the function) so that every mapped function agrees with
mpmath to 1e-12 on real and complex arguments (``tests/test_special_functions.py``):

* ``loggamma``: ``gammaln`` is ``log|Gamma(x)|``; :func:`scipy.special.loggamma` is the principal branch (NaN for
  real x < 0, where the value is complex).
* ``factorial(x)``: SciPy's ``factorial`` returns 0 for negative x; ``gamma(x + 1)`` instead.
* ``digamma`` (``polygamma(0, x)``): ``psi``, which takes complex arguments; ``harmonic(x) = psi(x + 1) + gamma_E``.
* Classical orthogonal polynomials (``chebyshevt``, ``chebyshevu``, ``legendre``, ``hermite``, ``laguerre``,
  ``assoc_laguerre``, ``gegenbauer``, ``jacobi``) of integer degree: three-term recurrences (Abramowitz &
  Stegun (1964), Table 22.7), which are accurate for complex arguments where SciPy's ``eval_*`` loses everything
  (``eval_chebyu(99, 0.5+0j)`` = 4.6e24, true -1).  A non-integer degree uses SciPy for real arguments and is
  refused for complex ones.
* ``Ci(x)``: ``sici`` gives the real part only for x < 0 (the value is complex there): NaN for real x < 0.
* ``betainc``: SciPy's regularized incomplete beta function is defined on [0, 1] only; other limits are refused.
* Functions that SciPy or NumPy evaluate for real arguments only (``polygamma(n, x)`` with n >= 1, ``beta``,
  ``elliptic_k``, ``elliptic_e``, ``atan2``, ``floor``, ``ceiling``, ``frac``, ``Mod``, ``Heaviside``, ``hypot``,
  ``Min``, ``Max``) refuse complex arguments with a ``TypeError`` naming the SymPy function.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

HELPERS = {
    "_symosc_real": '''
def _symosc_real(name, value):
    """value, or TypeError naming the function when it is complex (the mapping is for real arguments)."""
    if numpy.iscomplexobj(value):
        raise TypeError(f"{name} is evaluated for real arguments only by this backend; got a complex value")
    return value
''',
    "_symosc_orthopoly": '''
def _symosc_orthopoly(kind, n, x, a=0.0, b=0.0):
    """Classical orthogonal polynomials of integer degree n >= 0 by their three-term recurrences."""
    n, x, a, b = numpy.broadcast_arrays(*map(numpy.asarray, (n, x, a, b)))
    integer = numpy.isrealobj(n) and bool(numpy.all((n == numpy.floor(n)) & (n >= 0)))
    if not integer:
        if numpy.iscomplexobj(x):
            raise TypeError(f"{kind}: a complex argument needs an integer degree n >= 0 in this backend")
        return _SCIPY_ORTHOPOLY[kind](n, x, a, b)
    x = x.astype(complex) if numpy.iscomplexobj(x) else x.astype(float)
    one = numpy.ones_like(x)
    if kind == "chebyshevt":
        p1 = x
    elif kind in ("chebyshevu", "hermite"):
        p1 = 2 * x
    elif kind == "legendre":
        p1 = x
    elif kind == "laguerre":
        p1 = 1 - x
    elif kind == "assoc_laguerre":
        p1 = 1 + a - x
    elif kind == "gegenbauer":
        p1 = 2 * a * x
    else:  # jacobi
        p1 = (a + 1) + (a + b + 2) * (x - 1) / 2
    out = numpy.where(n == 0, one, p1)
    p0 = one
    top = int(numpy.max(n)) if n.size else 0
    for k in range(1, top):
        if kind == "chebyshevt" or kind == "chebyshevu":
            p2 = 2 * x * p1 - p0
        elif kind == "legendre":
            p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1)
        elif kind == "hermite":
            p2 = 2 * x * p1 - 2 * k * p0
        elif kind == "laguerre":
            p2 = ((2 * k + 1 - x) * p1 - k * p0) / (k + 1)
        elif kind == "assoc_laguerre":
            p2 = ((2 * k + 1 + a - x) * p1 - (k + a) * p0) / (k + 1)
        elif kind == "gegenbauer":
            p2 = (2 * (k + a) * x * p1 - (k + 2 * a - 1) * p0) / (k + 1)
        else:
            s = 2 * k + a + b
            p2 = ((s + 1) * ((s + 2) * s * x + a * a - b * b) * p1 - 2 * (k + a) * (k + b) * (s + 2) * p0) / (
                2 * (k + 1) * (k + a + b + 1) * s
            )
        p0, p1 = p1, p2
        out = numpy.where(n == k + 1, p1, out)
    return out


_SCIPY_ORTHOPOLY = {
    "chebyshevt": lambda n, x, a, b: scipy.special.eval_chebyt(n, x),
    "chebyshevu": lambda n, x, a, b: scipy.special.eval_chebyu(n, x),
    "legendre": lambda n, x, a, b: scipy.special.eval_legendre(n, x),
    "hermite": lambda n, x, a, b: scipy.special.eval_hermite(n, x),
    "laguerre": lambda n, x, a, b: scipy.special.eval_laguerre(n, x),
    "assoc_laguerre": lambda n, x, a, b: scipy.special.eval_genlaguerre(n, a, x),
    "gegenbauer": lambda n, x, a, b: scipy.special.eval_gegenbauer(n, a, x),
    "jacobi": lambda n, x, a, b: scipy.special.eval_jacobi(n, a, b, x),
}
''',
    "_symosc_ci": '''
def _symosc_ci(x):
    """Ci(x); NaN for real x < 0, where the value is complex (SciPy's sici gives its real part there)."""
    if numpy.iscomplexobj(x):
        return scipy.special.sici(x)[1]
    x = numpy.asarray(x, dtype=float)
    return numpy.where(x < 0, numpy.nan, scipy.special.sici(numpy.abs(x))[1])
''',
    "_symosc_betainc": '''
def _symosc_betainc(regularized, a, b, x1, x2):
    """SymPy's betainc(a, b, x1, x2) (or the regularized one) for limits in [0, 1], where SciPy defines it."""
    name = "betainc_regularized" if regularized else "betainc"
    for v in (a, b, x1, x2):
        _symosc_real(name, v)
    x1, x2 = numpy.asarray(x1, dtype=float), numpy.asarray(x2, dtype=float)
    if numpy.any((x1 < 0) | (x1 > 1) | (x2 < 0) | (x2 > 1)):
        raise ValueError(f"{name}: this backend evaluates the incomplete beta function for limits in [0, 1] only")
    value = scipy.special.betainc(a, b, x2) - scipy.special.betainc(a, b, x1)
    return value if regularized else value * scipy.special.beta(a, b)
''',
}
#: Helpers a helper needs.
_NEEDS = {"_symosc_betainc": ["_symosc_real"]}

ORTHOGONAL = ("chebyshevt", "chebyshevu", "legendre", "hermite", "laguerre", "assoc_laguerre", "gegenbauer", "jacobi")
#: SymPy functions whose NumPy/SciPy mapping takes real arguments only.
REAL_ONLY = frozenset({"atan2", "floor", "ceiling", "frac", "Mod", "Heaviside", "Min", "Max", "beta", "hypot"})


def helper_source(names: set[str]) -> str:
    """Definitions of the helpers ``names`` (and those they need), in a fixed order."""
    wanted = set(names)
    for name in list(wanted):
        wanted.update(_NEEDS.get(name, ()))
    return "".join(HELPERS[name] for name in HELPERS if name in wanted)


class SpecialFunctions:
    """Mixin for SymPy's SciPy printer: the replacements listed in this module's docstring."""

    helpers: set[str]

    def _helper(self, name: str) -> str:
        if not hasattr(self, "helpers"):
            self.helpers = set()
        self.helpers.add(name)
        if name in ("_symosc_orthopoly", "_symosc_ci", "_symosc_betainc"):
            self.module_imports.setdefault("scipy.special", set())
        return name

    def _real(self, name: str, arg: sp.Expr) -> str:
        return f'{self._helper("_symosc_real")}("{name}", {self._print(arg)})'

    def _call(self, function: str, *args: str) -> str:
        return f"{self._module_format(function)}({', '.join(args)})"

    def _print_loggamma(self, expr: Any) -> str:
        return self._call("scipy.special.loggamma", self._print(expr.args[0]))

    def _print_factorial(self, expr: Any) -> str:
        return self._call("scipy.special.gamma", f"{self._print(expr.args[0])} + 1")

    def _print_polygamma(self, expr: Any) -> str:
        n, x = expr.args
        if n == 0:
            return self._call("scipy.special.psi", self._print(x))
        return self._call("scipy.special.polygamma", self._real("polygamma", n), self._real("polygamma", x))

    def _print_harmonic(self, expr: Any) -> str:
        if len(expr.args) != 1:
            return self._print_not_supported(expr)
        psi = self._call("scipy.special.psi", f"{self._print(expr.args[0])} + 1")
        return f"({psi} + {self._module_format('numpy.euler_gamma')})"

    def _print_beta(self, expr: Any) -> str:
        if len(expr.args) != 2:
            return self._print_not_supported(expr)
        return self._call("scipy.special.beta", *(self._real("beta", a) for a in expr.args))

    def _print_Ci(self, expr: Any) -> str:
        return f"{self._helper('_symosc_ci')}({self._print(expr.args[0])})"

    def _print_betainc(self, expr: Any) -> str:
        return f"{self._helper('_symosc_betainc')}(False, {', '.join(self._print(a) for a in expr.args)})"

    def _print_betainc_regularized(self, expr: Any) -> str:
        return f"{self._helper('_symosc_betainc')}(True, {', '.join(self._print(a) for a in expr.args)})"

    # Complete elliptic integrals: SymPy and SciPy both use the parameter m = k^2 (real m only in SciPy).
    def _print_elliptic_k(self, expr: Any) -> str:
        return self._call("scipy.special.ellipk", self._real("elliptic_k", expr.args[0]))

    def _print_elliptic_e(self, expr: Any) -> str:
        if len(expr.args) != 1:
            return self._print_not_supported(expr)
        return self._call("scipy.special.ellipe", self._real("elliptic_e", expr.args[0]))

    def _orthopoly(self, expr: Any, kind: str) -> str:
        args = [self._print(a) for a in expr.args]
        n, x = args[0], args[-1]
        extra = args[1:-1]
        return f'{self._helper("_symosc_orthopoly")}("{kind}", {", ".join([n, x, *extra])})'

    def _print_Mod(self, expr: Any) -> str:
        return self._call("numpy.mod", *(self._real("Mod", a) for a in expr.args))

    def _print_frac(self, expr: Any) -> str:
        x = self._real("frac", expr.args[0])
        return f"({x} - {self._call('numpy.floor', x)})"

    def _print_Heaviside(self, expr: Any) -> str:
        x = self._real("Heaviside", expr.args[0])
        half = self._print(expr.args[1]) if len(expr.args) > 1 else "0.5"
        return self._call("numpy.heaviside", x, half)

    def _print_hypot(self, expr: Any) -> str:
        return self._call("numpy.hypot", *(self._real("hypot", a) for a in expr.args))

    def _print_Min(self, expr: Any) -> str:
        return self._fold("numpy.minimum", "Min", expr.args)

    def _print_Max(self, expr: Any) -> str:
        return self._fold("numpy.maximum", "Max", expr.args)

    def _fold(self, function: str, name: str, args: Any) -> str:
        out = self._real(name, args[0])
        for a in args[1:]:
            out = self._call(function, out, self._real(name, a))
        return out


for _kind in ORTHOGONAL:
    setattr(SpecialFunctions, f"_print_{_kind}", lambda self, expr, _k=_kind: self._orthopoly(expr, _k))
