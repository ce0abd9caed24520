"""Exact arithmetic of the synthesis procedures (private): rational functions over a number field.

Numerators and denominators are dense coefficient lists (highest power first) over a SymPy domain ``K``: the
rationals ``QQ`` or an algebraic field ``QQ<a, b, ...>`` (square roots and ``CRootOf`` numbers, with a primitive
element).  All arithmetic,
cancellation and division is exact polynomial arithmetic in ``K`` (no ``simplify``); numbers are evaluated only to
decide signs and to pick the smallest of several exactly known candidates.
"""

from __future__ import annotations

import mpmath
import sympy as sp
from sympy import QQ
from sympy.polys.densearith import (
    dup_add,
    dup_exquo,
    dup_mul,
    dup_mul_ground,
    dup_neg,
    dup_quo_ground,
    dup_rem,
    dup_sub,
)
from sympy.polys.densebasic import dup_degree, dup_LC, dup_strip
from sympy.polys.densetools import dup_diff, dup_eval
from sympy.polys.euclidtools import dup_inner_gcd, dup_invert
from sympy.polys.factortools import dup_factor_list
from sympy.polys.polyerrors import ExactQuotientFailed

from ..errors import ModelError

_DIGITS = 40
#: largest degree over QQ of the number field holding one network's element values
MAX_FIELD_DEGREE = 8
NESTED = (
    "the exact element values would need algebraic numbers of degree {degree} > {limit} over the rationals (a root "
    "of a polynomial whose coefficients are themselves algebraic numbers: {what}); exact synthesis keeps every "
    "element of a network in one number field of degree <= {limit}"
)


class Nested(ModelError):
    """A step needs an algebraic number outside the current field (the limitation of the exact synthesis)."""


def sym(c, K) -> sp.Expr:
    """A domain element as a SymPy number (Rational, radical or polynomial in a CRootOf)."""
    return K.to_sympy(c)


_GENERATORS: dict = {}


def _generator_value(K, digits: int):
    key = (K, digits)
    if key not in _GENERATORS:
        with mpmath.workdps(digits + 10):
            _GENERATORS[key] = mpmath.mpf(str(sp.N(K.ext.as_expr(), digits + 10)))
    return _GENERATORS[key]


def _qq(c):
    return mpmath.mpf(int(c.numerator)) / int(c.denominator)


def num(c, K, digits: int = _DIGITS):
    """Numerical value (mpmath) of a domain element: Horner's rule in the generator's value."""
    with mpmath.workdps(digits + 10):
        if K.is_QQ:
            return _qq(c)
        if not K.ext.is_real:  # pragma: no cover - fields of real targets have real generators
            return mpmath.mpmathify(complex(sp.N(sym(c, K), digits)))
        g, acc = _generator_value(K, digits), mpmath.mpf(0)
        for a in c.to_list():
            acc = acc * g + _qq(a)
        return acc


def sign(c, K) -> int:
    """Exact sign: zero is decided exactly, the sign of a nonzero algebraic number numerically."""
    if not c:
        return 0
    for digits in (_DIGITS, 4 * _DIGITS, 16 * _DIGITS):
        v = num(c, K, digits)
        if abs(v) > mpmath.mpf(10) ** (-digits // 2):
            return 1 if v > 0 else -1
    return 1 if num(c, K, 16 * _DIGITS) > 0 else -1  # pragma: no cover - a nonzero number below 1e-320


def positive(c, K, what: str) -> sp.Expr:
    if sign(c, K) <= 0:
        raise ModelError(f"synthesis reached a non-positive {what} = {sym(c, K)} (the target is not positive real?)")
    return sym(c, K)


def reflect(f: list, K) -> list:
    """``f(-p)``."""
    n = len(f) - 1
    return [c if (n - i) % 2 == 0 else K.neg(c) for i, c in enumerate(f)]


def even_in_y(f: list, K) -> list:
    """An even polynomial in ``p`` as a polynomial in ``y = p**2``."""
    n = len(f) - 1
    return dup_strip([c for i, c in enumerate(f) if (n - i) % 2 == 0]) if f else []


def in_x(f: list, K) -> list:
    """An even polynomial in ``p`` as a polynomial in ``x = -p**2`` (``x = ω²`` on the imaginary axis)."""
    g = even_in_y(f, K)
    n = len(g) - 1
    return [c if (n - i) % 2 == 0 else K.neg(c) for i, c in enumerate(g)]


def poly_p(coeffs: dict, K) -> list:
    """Polynomial from ``{power: coefficient}``."""
    if not coeffs:
        return []
    n = max(coeffs)
    return dup_strip([coeffs.get(n - i, K.zero) for i in range(n + 1)])


def mul_p(f: list, K) -> list:
    return [*f, K.zero] if f else []


def normalize(N: list, D: list, K) -> tuple[list, list]:
    """Cancel the common factor and make the denominator monic."""
    if not N:
        return [], [K.one]
    _, N, D = dup_inner_gcd(N, D, K)
    lc = dup_LC(D, K)
    return dup_quo_ground(N, lc, K), dup_quo_ground(D, lc, K)


def even_value(N: list, D: list, x0, K):
    """Value of the even part of ``N/D`` at ``p² = -x0`` (in ``K``, no square root of ``x0`` needed)."""
    Dm, Nm = reflect(D, K), reflect(N, K)
    top = in_x(dup_add(dup_mul(N, Dm, K), dup_mul(Nm, D, K), K), K)
    bottom = in_x(dup_mul_ground(dup_mul(D, Dm, K), K(2), K), K)
    den = dup_eval(bottom, x0, K)
    if not den:
        raise ModelError("synthesis step evaluated a function at one of its poles")  # pragma: no cover
    return K.quo(dup_eval(top, x0, K), den)


def real_part_x(N: list, D: list, K) -> tuple[list, list]:
    """``Re Z(iω) = E(x)/Q(x)``, ``x = ω²``."""
    Dm, Nm = reflect(D, K), reflect(N, K)
    E = dup_quo_ground(in_x(dup_add(dup_mul(N, Dm, K), dup_mul(Nm, D, K), K), K), K(2), K)
    Q = in_x(dup_mul(D, Dm, K), K)
    return E, Q


def eval_num(f: list, x: sp.Expr, K, digits: int = _DIGITS):
    """Numerical value (mpmath) of ``f`` (over ``K``) at an exact real SymPy number ``x``."""
    with mpmath.workdps(digits + 10):
        xv = mpmath.mpf(str(sp.N(x, digits + 10)))
        acc = mpmath.mpf(0)
        for c in f:
            acc = acc * xv + num(c, K, digits)
        return acc


def numeric_positive_roots(f: list, K, digits: int = 30) -> list:
    """Positive real roots of ``f`` (mpmath, for locating a minimum before any exact work)."""
    coeffs = [num(c, K, digits) for c in f]
    if len(coeffs) < 2:
        return []
    with mpmath.workdps(digits):
        roots = mpmath.polyroots(coeffs, maxsteps=400, extraprec=400)
    scale = mpmath.mpf(10) ** (-digits // 2)
    return [mpmath.re(r) for r in roots if abs(mpmath.im(r)) < scale * (1 + abs(r)) and mpmath.re(r) > 0]


def real_roots_qq(f: list) -> list[sp.Expr]:
    """Exact real roots of a polynomial over QQ: Rationals, radicals (degree 2) or CRootOf."""
    y = sp.Dummy("y")
    out: list[sp.Expr] = []
    for factor, _ in dup_factor_list(f, QQ)[1]:
        poly = sp.Poly([QQ.to_sympy(c) for c in factor], y)
        if poly.degree() == 2:
            out += [r for r in sp.roots(poly, y, multiple=True) if r.is_real]
        else:
            out += list(poly.real_roots())
    return out


def extension(root: sp.Expr):
    """The field ``QQ<a>`` generated by an algebraic ``root``; square roots are kept as ``sqrt(m)``."""
    if root.is_Rational:
        return QQ
    radicals = [a for a in root.atoms(sp.Pow) if a.exp == sp.Rational(1, 2)]
    gen = radicals[0] if radicals else root
    return QQ.algebraic_field(gen)


def to_field(f: list, K_old, K_new) -> list:
    if K_old == K_new:
        return f
    return [K_new.convert_from(c, K_old) for c in f]


def norm(f: list, K) -> list:
    """Norm of ``f`` over ``K`` down to QQ: ``Res_z(m(z), f(z, x))`` with ``m`` the minimal polynomial of ``K``'s
    generator (python-flint's resultant when available, SymPy's otherwise)."""
    try:
        import flint
    except ImportError:  # pragma: no cover - python-flint is installed with SymPy's fast ground types
        from sympy.polys.sqfreetools import dmp_norm

        return dmp_norm(f, 0, K)
    ctx = flint.fmpq_mpoly_ctx.get(("z", "x"), "lex")
    z, x = ctx.gens()

    def in_z(coeffs: list):
        acc = ctx.from_dict({})
        for c in coeffs:
            acc = acc * z + flint.fmpq(int(c.numerator), int(c.denominator))
        return acc

    m = in_z(K.mod.to_list())
    F = ctx.from_dict({})
    for c in f:
        F = F * x + in_z(c.to_list())
    res = m.resultant(F, "z").to_dict()
    degree = max(e[1] for e in res)
    out = [QQ.zero] * (degree + 1)
    for (_, ex_), c in res.items():
        out[degree - ex_] = QQ(int(c.p), int(c.q))
    return dup_strip(out)


def field_degree(K) -> int:
    return 1 if K.is_QQ else len(K.mod.to_list()) - 1


def extend_with_root(f: list, K, x_num, what: str):
    """``(r, K2)``: the real root ``r`` of ``f`` (over ``K``) nearest ``x_num``, exact in ``K2 = K(r)``.

    The norm of ``f`` is factored over QQ and the factor vanishing at ``r`` gives ``r`` as a radical or CRootOf;
    ``K2`` has a primitive element of both generators (``K2 = K`` in effect when ``r`` already lies in ``K``).
    ``Nested`` when the degree of ``K2`` would exceed :data:`MAX_FIELD_DEGREE`."""
    from sympy.polys.euclidtools import dup_gcd

    best = None
    for phi, _ in dup_factor_list(norm(f, K), QQ)[1]:
        for r in real_roots_qq(phi):
            dist = abs(mpmath.mpf(str(sp.N(r, _DIGITS))) - x_num)
            if best is None or dist < best[0]:
                best = (dist, r, phi)
    if best is None:  # pragma: no cover - the norm vanishes at every root of f
        raise ModelError(f"no real root found for {what}")
    _, r, phi = best
    if r.is_Rational:
        return K.convert(QQ.from_sympy(r)), K
    deg_k, deg_r = field_degree(K), dup_degree(phi)
    if deg_k * deg_r > MAX_FIELD_DEGREE:
        if deg_k % deg_r == 0:  # r may lie in K: its factor over K is then linear
            g = dup_gcd(f, [K.convert_from(c, QQ) for c in phi], K)
            for factor, _ in [(g, 1)] if dup_degree(g) == 1 else dup_factor_list(g, K)[1]:
                if dup_degree(factor) == 1:
                    root = K.quo(K.neg(factor[1]), factor[0])
                    if abs(num(root, K) - x_num) < mpmath.mpf(10) ** -10 * (1 + abs(x_num)):
                        return root, K
        raise Nested(NESTED.format(degree=f"up to {deg_k * deg_r}", limit=MAX_FIELD_DEGREE, what=what))
    K2 = QQ.algebraic_field(*K.orig_ext, r)
    return K2.from_sympy(r), K2


def exquo(f: list, g: list, K, what: str) -> list:
    try:
        return dup_exquo(f, g, K)
    except ExactQuotientFailed as exc:  # pragma: no cover - an exact identity of the procedure
        raise ModelError(f"synthesis step failed: {what} is not divisible exactly") from exc


__all__ = [
    "MAX_FIELD_DEGREE",
    "NESTED",
    "Nested",
    "dup_degree",
    "dup_diff",
    "dup_eval",
    "dup_invert",
    "dup_mul",
    "dup_mul_ground",
    "dup_neg",
    "dup_rem",
    "dup_sub",
    "even_value",
    "exquo",
    "extend_with_root",
    "extension",
    "field_degree",
    "in_x",
    "mul_p",
    "normalize",
    "positive",
    "real_part_x",
    "real_roots_qq",
    "reflect",
    "sign",
    "sym",
    "to_field",
]
