"""Exact arithmetic of the synthesis procedures (private): rational functions over a number field.

Numerators and denominators are dense coefficient lists (highest power first) over a SymPy domain ``K``: the
rationals ``QQ``, an algebraic field ``QQ<a, b, ...>`` (square roots and ``CRootOf`` numbers, with a primitive
element) or a tower field ``K[x]/(own)`` over one of them (``_tower``, for roots of polynomials whose coefficients
are algebraic).  All arithmetic,
cancellation and division is exact polynomial arithmetic in ``K`` (no ``simplify``); numbers are evaluated only to
decide signs and to pick the smallest of several exactly known candidates.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

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
from sympy.polys.densetools import dup_diff, dup_eval, dup_shift
from sympy.polys.euclidtools import dup_inner_gcd, dup_invert
from sympy.polys.factortools import dup_factor_list
from sympy.polys.polyerrors import ExactQuotientFailed

from ...errors import ModelError
from . import tower as _tower
from .tower import TowerField

_DIGITS = 40
#: largest degree over QQ of the number field holding one network's element values (without python-flint)
MAX_FIELD_DEGREE = 8
#: the same with python-flint installed (tower fields: random degree-6 targets needing degree 32–40 take seconds, the
#: Bott–Duffin ones needing 64 half a minute to three minutes; the targets of the benchmark's 300-target sample
#: refused at 64 need 128 or 200 whichever minimum is taken: beyond any practical limit)
MAX_FIELD_DEGREE_FLINT = 64
NESTED = (
    "the exact element values would need algebraic numbers of degree {degree} > {limit} over the rationals (a root "
    "of {what}); exact synthesis keeps every element of a network in one number field of degree <= {limit}; "
    "brune_synthesis, bott_duffin_synthesis and "
    "m_function_synthesis allow it with max_degree={degree} or more (fields of degree 32-40 take seconds, "
    "degree 64 up to minutes, degree 128 a quarter of an hour or more)"
)


class Nested(ModelError):
    """A step needs an algebraic number outside the current field (the limitation of the exact synthesis); ``degree``
    is the degree over the rationals of the field it needs (None when unknown)."""

    def __init__(self, message: str, degree: int | None = None) -> None:
        super().__init__(message)
        self.degree = degree


def sym(c, K) -> sp.Expr:
    """A domain element as a SymPy number (Rational, radical or polynomial in a CRootOf)."""
    return K.to_sympy(c)


_GENERATORS = _tower.FieldCache()


def flint_module():
    """python-flint when installed (``pip install symosc[exact]``), else None."""
    try:
        import flint
    except ImportError:  # pragma: no cover - the test environment installs python-flint
        return None
    return flint


def _generator_value(K, digits: int):
    key = (K, digits)
    if key not in _GENERATORS:
        root = K.ext.as_expr()
        if flint_module() is not None and isinstance(root, sp.CRootOf) and root.is_real:
            coeffs = [QQ.from_sympy(c) for c in root.poly.all_coeffs()]
            _GENERATORS[key] = real_roots_numeric(coeffs, digits + 10)[root.index]
        else:
            with mpmath.workdps(digits + 10):
                _GENERATORS[key] = mpmath.mpf(str(sp.N(root, digits + 10)))
    return _GENERATORS[key]


def _qq(c):
    return mpmath.mpf(int(c.numerator)) / int(c.denominator)


def num(c, K, digits: int = _DIGITS):
    """Numerical value (mpmath) of a domain element: Horner's rule in the generator's value."""
    if isinstance(K, TowerField):
        return _tower.value(c, K, digits)
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


def require_positive(c, K, what: str, sign_of=None) -> None:
    """ModelError unless ``c`` (or ``sign_of``, a number of the same sign) is positive."""
    if sign(c if sign_of is None else sign_of, K) <= 0:
        raise ModelError(f"synthesis reached a non-positive {what} = {sym(c, K)} (the target is not positive real?)")


def positive(c, K, what: str) -> sp.Expr:
    """``c`` as an exact SymPy number, after :func:`require_positive`."""
    require_positive(c, K, what)
    return sym(c, K)


def reflect(f: list, K) -> list:
    """``f(-p)``."""
    n = len(f) - 1
    return [c if (n - i) % 2 == 0 else K.neg(c) for i, c in enumerate(f)]


def even_in_y(f: list, K) -> list:
    """The even part of a polynomial in ``p`` (all of it when ``f`` is even) as a polynomial in ``y = p**2``."""
    n = len(f) - 1
    return dup_strip([c for i, c in enumerate(f) if (n - i) % 2 == 0]) if f else []


def in_x(f: list, K) -> list:
    """An even polynomial in ``p`` as a polynomial in ``x = -p**2`` (``x = ω²`` on the imaginary axis)."""
    g = even_in_y(f, K)
    n = len(g) - 1
    return [c if (n - i) % 2 == 0 else K.neg(c) for i, c in enumerate(g)]


def mul_p(f: list, K) -> list:
    return [*f, K.zero] if f else []


def normalize(N: list, D: list, K) -> tuple[list, list]:
    """Cancel the common factor and make the denominator monic."""
    if not N:
        return [], [K.one]
    if isinstance(K, TowerField):
        g = gcd(N, D, K)  # the modular coprimality test first
        if dup_degree(g) > 0:
            N, D = dup_exquo(N, g, K), dup_exquo(D, g, K)
    elif K.is_QQ or not coprime(N, D, K):
        _, N, D = dup_inner_gcd(N, D, K)
    inv = _tower.inverse(dup_LC(D, K), K)  # one inversion (not one per coefficient)
    return dup_mul_ground(N, inv, K), dup_mul_ground(D, inv, K)


def coprime(f: list, g: list, K) -> bool:
    """True when ``f`` and ``g`` over a number field are certainly coprime: their images modulo a prime ``q`` (each
    generator of the field, or of each level of a tower, sent to a root mod ``q`` of its defining polynomial) keep
    their degrees and have gcd 1, so the resultant is nonzero.  False means "not decided" (the caller then computes
    the gcd over the field).  Needs python-flint; without it always False."""
    if flint_module() is None:
        return False
    for q, roots in _reductions(K):
        F, G = _reduce(f, K, q, roots), _reduce(g, K, q, roots)
        if F is None or G is None or F.degree() != dup_degree(f) or G.degree() != dup_degree(g):
            continue
        return F.gcd(G).degree() == 0
    return False


def irreducible_modulo_primes(f: list, K) -> bool:
    """True when ``f`` (monic, over an algebraic or a tower field ``K``) is certainly irreducible over ``K``: for
    each prime of :func:`_reductions` where ``f`` keeps its degree and stays squarefree, every factor of ``f`` over
    ``K`` reduces to a product of irreducible factors modulo that prime, so its degree is a sum of some of their
    degrees; when no degree below ``deg f`` is such a sum for all the primes at once, ``f`` has no proper factor.
    False means "not decided".  Only primes at which every level's defining polynomial stays squarefree are used
    (Dedekind's criterion: the generators then span the local ring of integers and the residue field is ``F_q``;
    at other primes a factor could reduce over a larger residue field).  Needs python-flint; without it always
    False."""
    n = dup_degree(f)
    if flint_module() is None or K.is_QQ or n < 2:
        return False
    possible = (1 << n) - 2  # bit d set: a factor of degree d (0 < d < n) not yet excluded
    for q, roots in _unramified_reductions(K):
        F = _reduce(f, K, q, roots)
        if F is None or F.degree() != n:
            continue
        _, factors = F.factor()
        if any(mult > 1 for _, mult in factors):
            continue
        sums = 1  # bit d set: d is a sum of degrees of some of the factors modulo q
        for g, _ in factors:
            sums |= sums << g.degree()
        possible &= sums
        if not possible:
            return True
    return False


def _unramified_reductions(K) -> list:
    """The pairs of :func:`_reductions` at which every level's defining polynomial stays squarefree (cached)."""
    if K not in _UNRAMIFIED:
        _UNRAMIFIED[K] = [(q, roots) for q, roots in _reductions(K) if _levels_squarefree(K, q, roots)]
    return _UNRAMIFIED[K]


def _levels_squarefree(K, q: int, roots: list) -> bool:
    """Every level's defining polynomial, reduced modulo ``q`` (the lower levels' generators sent to ``roots``),
    is squarefree."""
    levels = _tower.levels(K)
    for level, F in enumerate(levels):
        image = _reduce(F.own, levels[level - 1], q, roots[:level]) if level else _reduce_qq(F.mod.to_list(), q)
        if image is None or image.gcd(image.derivative()).degree() != 0:
            return False
    return True


_REDUCTIONS = _tower.FieldCache()
_UNRAMIFIED = _tower.FieldCache()


def _reductions(K) -> list:
    """Up to six pairs ``(q, roots)``: word-size primes ``q`` with roots mod ``q`` of the defining polynomial of
    each level of ``K`` (bottom first; the polynomials ``q``-integral)."""
    if K not in _REDUCTIONS:
        levels = _tower.levels(K)
        out, q, tries = [], 2**62, 0
        while len(out) < 6 and tries < 400:
            q, tries = int(sp.prevprime(q)), tries + 1
            roots: list = []
            for level, F in enumerate(levels):
                defining = F.mod.to_list() if level == 0 else F.own
                image = _reduce(defining, levels[level - 1], q, roots) if level else _reduce_qq(defining, q)
                found = image.roots() if image is not None and image.degree() == len(defining) - 1 else []
                if not found:
                    break
                roots.append(int(found[0][0]))
            else:
                out.append((q, roots))
        _REDUCTIONS[K] = out
    return _REDUCTIONS[K]


def _reduce_qq(coeffs: list, q: int):
    if any(int(c.denominator) % q == 0 for c in coeffs):
        return None
    return flint_module().nmod_poly([int(c.numerator) * pow(int(c.denominator), -1, q) for c in reversed(coeffs)], q)


def _reduce_element(c, K, q: int, roots: list):
    """Image in ``F_q`` of an element of ``K`` (None when a denominator is divisible by ``q``)."""
    if isinstance(K, TowerField):
        acc, a = 0, roots[-1]
        for b in c.rep:
            v = _reduce_element(b, K.base, q, roots[:-1])
            if v is None:
                return None
            acc = (acc * a + v) % q
        return acc
    acc, a = 0, roots[0]
    for b in c.to_list():
        den = int(b.denominator) % q
        if den == 0:
            return None
        acc = (acc * a + int(b.numerator) * pow(den, -1, q)) % q
    return acc


def _reduce(f: list, K, q: int, roots: list):
    """Image of a polynomial over ``K`` in ``F_q[x]`` (None when a denominator is divisible by ``q``)."""
    out = []
    for c in f:
        v = _reduce_element(c, K, q, roots)
        if v is None:
            return None
        out.append(v)
    return flint_module().nmod_poly(list(reversed(out)), q)


def even_value(N: list, D: list, x0, K):
    """Value of the even part of ``N/D`` at ``p² = -x0`` (in ``K``, no square root of ``x0`` needed).

    With ``N = Ne(y) + p No(y)`` and ``D = De(y) + p Do(y)`` (``y = p²``) the even part is
    ``(Ne De - y No Do)/(De² - y Do²)``: four evaluations at ``y = -x0`` and a handful of products, instead of
    the products of the polynomials themselves."""
    y0 = K.neg(x0)
    # the even part of f is even_in_y(f); its odd part, f(p) - fe(p²) = p fo(p²), is even_in_y(f / p) (f[:-1])
    (ne, no), (de, do) = ([dup_eval(even_in_y(g, K), y0, K) for g in (f, f[:-1])] for f in (N, D))
    den = K.sub(K.mul(de, de), K.mul(y0, K.mul(do, do)))
    if not den:
        raise ModelError("synthesis step evaluated a function at one of its poles")  # pragma: no cover
    return K.quo(K.sub(K.mul(ne, de), K.mul(y0, K.mul(no, do))), den)


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


def extension(root: sp.Expr, what: str = "a polynomial"):
    """The field ``QQ<a>`` generated by an algebraic ``root`` (of the polynomial giving ``what``); square roots are
    kept as ``sqrt(m)``.  A limit given by the caller (:func:`field_degree_limit`) bounds this first extension too;
    the default limits are for nested ones (a first extension has degree at most ``2n - 2``)."""
    if root.is_Rational:
        return QQ
    radicals = [a for a in root.atoms(sp.Pow) if a.exp == sp.Rational(1, 2)]
    gen = radicals[0] if radicals else root
    K = QQ.algebraic_field(gen)
    chosen = _LIMIT.get()
    if chosen is not None and field_degree(K) > chosen:
        what = f"the polynomial of degree {field_degree(K)} over the rationals giving {what}"
        raise Nested(NESTED.format(degree=field_degree(K), limit=chosen, what=what), field_degree(K))
    return K


def to_field(f: list, K_old, K_new) -> list:
    if K_old == K_new:
        return f
    return [convert(c, K_old, K_new) for c in f]


def norm(f: list, K) -> list:
    """Norm of a monic ``f`` over ``K`` (an algebraic or a tower field) down to QQ.

    With python-flint: ``det(Σ M(c_i) x^i)`` with ``M(c)`` the rational matrix of multiplication by ``c`` in ``K``'s
    monomial basis, computed as the characteristic polynomial of the block companion matrix of that matrix
    polynomial (Gohberg, Lancaster and Rodman (1982), §1.1).  Without it (algebraic fields only): SymPy's
    ``Res_z(m(z), f(z, x))``."""
    flint = flint_module()
    if flint is None:
        if isinstance(K, TowerField):  # pragma: no cover - the test environment installs python-flint
            raise Nested("nested number fields need python-flint (pip install symosc[exact])")
        from sympy.polys.sqfreetools import dmp_norm

        return dmp_norm(f, 0, K)
    n, d = dup_degree(f), field_degree(K)
    blocks = [_tower.matrix(c, K) for c in reversed(f[1:])]  # M(c_0), ..., M(c_{n-1})
    C = flint.fmpq_mat(n * d, n * d)
    for i in range(n - 1):
        for k in range(d):
            C[i * d + k, (i + 1) * d + k] = 1
    for j, B in enumerate(blocks):
        for r in range(d):
            for k in range(d):
                if B[r, k] != 0:
                    C[(n - 1) * d + r, j * d + k] = -B[r, k]
    # charpoly(C)(x) = charpoly(d C)(d x) / d^(n d) with d C integral (flint's multimodular integer charpoly)
    charpoly, den = _tower.scaled_charpoly(C)
    size = n * d
    return _from_flint(
        flint.fmpq_poly(
            [flint.fmpq(int(c), 1) / flint.fmpq(int(den)) ** (size - i) for i, c in enumerate(charpoly.coeffs())]
        )
    )


def field_degree(K) -> int:
    return _tower.base_degree(K)


def extend_with_root(f: list, K, x_num, what: str):
    """``(r, K2)``: the real root ``r`` of ``f`` (over an algebraic or a tower field ``K``) nearest ``x_num``,
    exact in ``K2 = K(r)``.

    ``K2`` is the tower field ``K[x]/(own)`` with ``own`` the irreducible factor of ``f`` over ``K`` holding ``r``
    (``r`` is the class of ``x``).  ``own`` and a primitive element of the whole tower come from Trager's squarefree
    norm (Trager (1976), §3): ``γ = r + s Θ`` (``Θ`` the primitive element of ``K``) is a ``CRootOf`` of an
    irreducible factor ``φ`` of the norm of ``f(x - s Θ)``, and ``own = gcd(f(x), φ(x + s Θ))``: ``f`` itself when
    ``deg φ = [K : QQ] deg f``, else (over a tower) the factor found from the embeddings of ``K`` and certified by
    exact division (:func:`_tower.factor_holding`), or the gcd over ``K``.  ``K2 = K`` when ``r`` already lies in
    ``K``.  ``Nested`` (before the gcd and the new level) when the degree of ``K2`` would exceed
    :func:`max_field_degree`."""
    theta, f = _tower.primitive(K), _tower.monic(f, K)
    if dup_degree(f) == 1:
        return K.neg(f[1]), K
    degree = field_degree(K) * dup_degree(f)
    if degree > max_field_degree() and irreducible_modulo_primes(f, K):  # refused before the (costly) norm
        what = f"a polynomial whose coefficients are themselves algebraic numbers: {what}"
        raise Nested(NESTED.format(degree=degree, limit=max_field_degree(), what=what), degree)
    for s in (1, -1, 2, -2, 3, -3, 4, -4):
        shifted = dup_shift(f, K.mul(K.convert(-s), theta), K)  # f(x - s Θ)
        N = norm(shifted, K)
        if squarefree_qq(N):
            break
    else:  # pragma: no cover - all but finitely many shifts give a squarefree norm
        raise ModelError(f"no squarefree norm found for {what}")
    phi, index, dist = None, None, None
    with mpmath.workdps(_DIGITS):  # γ ≈ r + s Θ: Θ may be large (1e15), r's digits must survive the sum
        gamma_num = x_num + s * _tower.primitive_value(K, _DIGITS)
        for factor, _ in factor_qq(N):
            for i, root in enumerate(real_roots_numeric(factor)):
                if dist is None or abs(root - gamma_num) < dist:
                    phi, index, dist = factor, i, abs(root - gamma_num)
    if phi is None:  # pragma: no cover - f has the real root x_num
        raise ModelError(f"no real root found for {what}")
    degree, m = dup_degree(phi), field_degree(K)
    if degree > max_field_degree():
        what = f"a polynomial whose coefficients are themselves algebraic numbers: {what}"
        raise Nested(NESTED.format(degree=degree, limit=max_field_degree(), what=what), degree)
    if degree == m * dup_degree(f):
        own = f
    elif isinstance(K, TowerField) and (own := _tower.factor_holding(f, K, phi, s, degree // m)) is not None:
        pass
    else:  # φ(x + s Θ) modulo f by Horner's rule, then the gcd with f
        lin, acc = [K.one, K.mul(K.convert(s), theta)], []
        for c in phi:
            acc = _tower._reduce(dup_add(dup_mul(acc, lin, K), [K.convert(c)], K), f, K)
        own = gcd(f, acc, K)
    if dup_degree(own) == 1:  # r lies in K (then degree == m)
        r, L = K.neg(own[1]), K
    else:
        L = TowerField(K, own, phi, index, s)
        r = L.gen
    if abs(num(r, L) - x_num) > mpmath.mpf(10) ** -8 * (1 + abs(x_num)):  # x_num: a floating-point root of f
        raise ModelError(f"wrong root of {what}: {num(r, L)} vs {x_num}")  # pragma: no cover - a certified root choice
    return r, L


def gcd(f: list, g: list, K) -> list:
    """Monic gcd (SymPy's: heuristic over QQ, subresultants over an algebraic field after a modular coprimality
    test; Euclid's algorithm with monic remainders over a tower field)."""
    if not (f or g):
        return []
    if isinstance(K, TowerField):
        if f and g and coprime(f, g, K):
            return [K.one]
        while g:
            g = _tower.monic(g, K)
            f, g = g, _tower._reduce(f, g, K)
        return _tower.monic(f, K)
    if not K.is_QQ and f and g and coprime(f, g, K):
        return [K.one]
    h = dup_inner_gcd(f, g, K)[0]
    return dup_mul_ground(h, K.quo(K.one, dup_LC(h, K)), K)


def squarefree_part(f: list, K) -> list:
    """``f`` (over an algebraic or a tower field) without repeated factors: ``f / gcd(f, f')``, made monic, or ``f``
    itself when the gcd is 1 (decided modulo a prime when it can be, by :func:`gcd`).  A degenerate minimum of
    ``Re Z(iω)`` (a contact of order four or more) is a multiple root of the critical-point polynomial: its
    numerical value is poor (a root of multiplicity ``m`` from ``d`` digits has about ``d/m``) and no norm of the
    polynomial is squarefree, so the roots are located and extended on the squarefree part."""
    g = gcd(f, dup_diff(f, 1, K), K)
    if dup_degree(g) <= 0:
        return f
    return _tower.monic(exquo(f, g, K, "the squarefree part"), K)


def max_field_degree() -> int:
    """Largest degree over QQ of a network's number field: the one given to :func:`field_degree_limit`, else
    :data:`MAX_FIELD_DEGREE`, or :data:`MAX_FIELD_DEGREE_FLINT` with python-flint (its characteristic polynomials,
    factorisations, exact linear solves and certified root isolation make large fields affordable)."""
    chosen = _LIMIT.get()
    if chosen is not None:
        return chosen
    return MAX_FIELD_DEGREE if flint_module() is None else MAX_FIELD_DEGREE_FLINT


_LIMIT: ContextVar[int | None] = ContextVar("max_field_degree", default=None)


@contextmanager
def field_degree_limit(limit: int | None) -> Iterator[None]:
    """Within this block :func:`max_field_degree` is ``limit`` (the default when None)."""
    token = _LIMIT.set(limit)
    try:
        yield
    finally:
        _LIMIT.reset(token)


def squarefree_qq(f: list) -> bool:
    flint = flint_module()
    if flint is None:
        from sympy.polys.sqfreetools import dup_sqf_p

        return dup_sqf_p(f, QQ)
    g = _to_flint(f)
    return g.gcd(g.derivative()).degree() == 0


def factor_qq(f: list) -> list:
    """Irreducible factors over QQ with multiplicities (flint's factorisation when installed)."""
    flint = flint_module()
    if flint is None:
        return dup_factor_list(f, QQ)[1]
    return [(_from_flint(g), e) for g, e in _to_flint(f).factor()[1]]


def real_roots_numeric(f: list, digits: int = _DIGITS) -> list:
    """The real roots of an irreducible ``f`` over QQ, ascending, as mpmath numbers of ``_DIGITS`` digits (certified
    isolation: flint's when installed, SymPy's ``real_roots`` otherwise)."""
    flint = flint_module()
    if flint is None:
        with mpmath.workdps(digits):
            return sorted(mpmath.mpf(str(sp.N(r, digits))) for r in real_roots_qq(f))
    old = flint.ctx.prec
    try:
        flint.ctx.prec = int(3.33 * digits) + 20
        reals = []
        for g, _ in _to_flint(f).factor()[1]:
            reals += [r.real.mid() for r, _ in g.complex_roots() if r.imag == 0]
        with mpmath.workdps(digits):
            return sorted(mpmath.mpf(r.str(digits + 5, radius=False)) for r in reals)
    finally:
        flint.ctx.prec = old


def _fmpq(c):
    return flint_module().fmpq(int(c.numerator), int(c.denominator))


def _to_flint(f: list):
    return flint_module().fmpq_poly([_fmpq(c) for c in reversed(f)])


def _from_flint(g) -> list:
    return dup_strip([QQ(int(c.p), int(c.q)) for c in reversed(g.coeffs())])


def convert(c, K_old, K_new):
    """A domain element of ``K_old`` as an element of ``K_new`` (an extension of it: a field above it in a
    tower)."""
    if K_old == K_new:
        return c
    return K_new.convert_from(c, K_old)


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
    "gcd",
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
