"""Tower number fields of the exact synthesis (Trager (1976), §3): arithmetic, numbers and norms checked against
SymPy's own algebraic fields (an independent primitive-element computation), and a nested Bott–Duffin case."""

from __future__ import annotations

import random
import time

import mpmath
import pytest
import sympy as sp
from sympy import QQ
from sympy.polys.densearith import dup_add, dup_mul, dup_sub
from sympy.polys.densebasic import dup_strip

from symosc.networks import bott_duffin_synthesis
from symosc.networks._exact import fields as ex
from symosc.networks._exact import tower as _tower
from symosc.networks._exact.tower import TowerElement, TowerField

from .test_synthesis_degree6 import _check_exact, _values

p = sp.Symbol("p")
SQ2, SQ3 = sp.sqrt(2), sp.sqrt(3)
TOP = sp.sqrt(1 + SQ3)


@pytest.fixture(scope="module")
def tower():
    """QQ(√2) ⊂ QQ(√2)[x]/(x² - 3) ⊂ (that)[y]/(y² - 1 - x): the numbers √2, √3, √(1 + √3) (degree 8)."""
    K = QQ.algebraic_field(SQ2)
    r1, L1 = ex.extend_with_root([K.one, K.zero, K(-3)], K, mpmath.sqrt(3), "√3")
    r2, L2 = ex.extend_with_root([L1.one, L1.zero, -(L1.one + r1)], L1, mpmath.sqrt(1 + mpmath.sqrt(3)), "top")
    M = QQ.algebraic_field(SQ2, SQ3, TOP)  # SymPy's field with its own primitive element
    return K, L1, L2, r1, r2, M


_IMAGES: dict = {}


def _image(c, F, M):
    """A tower element in SymPy's field ``M``, coefficient by coefficient through the images of the generators."""
    images = _IMAGES.get(id(M)) or _IMAGES.setdefault(id(M), [M.from_sympy(a) for a in (SQ2, SQ3, TOP)])
    levels = [F] if not isinstance(F, TowerField) else F.levels

    def walk(a, level):
        if level == 0:
            acc = M.zero
            for q in a.to_list():
                acc = acc * images[0] + M.convert(q)
            return acc
        acc = M.zero
        for b in a.rep:
            acc = acc * images[level] + walk(b, level - 1)
        return acc

    return walk(c, len(levels) - 1)


def _random_element(F, rng):
    """Random coordinates over the base field, built by field arithmetic (Horner in the adjoined root)."""
    if not isinstance(F, TowerField):
        return F([QQ(rng.randint(-9, 9), rng.randint(1, 5)) for _ in range(2)])
    acc = F.zero
    for _ in range(F.e):
        acc = acc * F.gen + F.convert(_random_element(F.base, rng))
    return acc


def test_tower_degrees_and_generators(tower):
    _, L1, L2, r1, r2, _ = tower
    assert (ex.field_degree(L1), ex.field_degree(L2)) == (4, 8)
    assert r1 * r1 == 3 and r2 * r2 == 1 + L2.convert(r1)
    assert r2 != r1 and r2 - r2 == 0 and not L2.zero and bool(r2)


def test_tower_arithmetic_agrees_with_sympy_fields(tower):
    K, L1, L2, _, _, M = tower
    rng = random.Random(7)
    for F in (L1, L2):
        for _ in range(6):
            a, b = _random_element(F, rng), _random_element(F, rng)
            if not b:
                continue
            A, B = _image(a, F, M), _image(b, F, M)
            assert _image(a + b, F, M) == A + B
            assert _image(a - b, F, M) == A - B
            assert _image(a * b, F, M) == A * B
            assert _image(a / b, F, M) == A / B
            assert _image(-a, F, M) == -A
            assert _image(a * 3, F, M) == A * 3 and _image(2 - a, F, M) == 2 - A
            assert _image(a * K.unit, F, M) == A * M.from_sympy(SQ2)
            assert hash(a * b) == hash(b * a) and a * b == b * a


def test_dense_routines_over_a_tower(tower):
    _, _, L2, r1, r2, M = tower
    x2 = L2.convert(r1)
    f = [L2.one, -r2, L2.zero, x2]
    g = [L2.one, r2]
    q = ex.dup_mul(f, g, L2)
    assert ex.exquo(q, g, L2, "test") == f
    assert ex.gcd(q, ex.dup_mul(g, [L2.one, x2], L2), L2) == g
    assert ex.dup_eval(g, -r2, L2) == 0
    n = len(q) - 1
    mapped = [_image(c, L2, M) for c in q]
    assert [_image(c, L2, M) for c in ex.dup_diff(q, 1, L2)] == [c * (n - i) for i, c in enumerate(mapped[:-1])]
    assert [_image(c, L2, M) for c in ex.dup_rem(q, [L2.one, x2, L2.one], L2)] == [
        c
        for c in sp.Poly(mapped, p, domain=M).rem(sp.Poly([M.one, _image(x2, L2, M), M.one], p, domain=M)).rep.to_list()
    ]


def _horner(coeffs, x, M):
    acc = M.zero
    for c in coeffs:
        acc = acc * x + M.from_sympy(c)
    return acc


def test_tower_numbers_and_exact_values(tower):
    _, _, L2, r1, r2, M = tower
    rng = random.Random(3)
    for _ in range(3):
        a = _random_element(L2, rng)
        exact = M.to_sympy(_image(a, L2, M))
        with mpmath.workdps(70):
            assert abs(ex.num(a, L2, 60) - mpmath.mpf(str(sp.N(exact, 70)))) < mpmath.mpf(10) ** -55
        value = L2.to_sympy(a)  # a polynomial in one CRootOf
        (root,) = value.atoms(sp.CRootOf)
        # the primitive element γ = r2 + s2 (r1 + s1 √2) in SymPy's field: a root of CRootOf's polynomial, the
        # same real root numerically, and the value's polynomial in it equals the element
        gamma = _image(L2.primitive, L2, M)
        poly = root.poly
        assert _horner(poly.all_coeffs(), gamma, M) == M.zero
        assert abs(sp.N(M.to_sympy(gamma) - root, 50)) < 1e-40
        y = sp.Dummy("y")
        in_gamma = sp.Poly(value.xreplace({root: y}), y, domain=QQ)
        assert _horner(in_gamma.all_coeffs(), gamma, M) == _image(a, L2, M)
    assert ex.sign(r2 - L2.convert(r1), L2) == -1  # √(1 + √3) < √3


def test_factor_of_a_reducible_polynomial_over_a_tower(tower):
    """(t - √3)(t² - 5) over QQ(√2, √3): the root √5 gets the level polynomial t² - 5 (its minimal polynomial over
    QQ(√2, √3), of degree 2), a degree-8 field."""
    _, L1, _, r1, _, _ = tower
    f = ex.dup_mul([L1.one, -r1], [L1.one, L1.zero, L1(-5)], L1)
    r, L = ex.extend_with_root(f, L1, mpmath.sqrt(5), "√5")
    assert L.own == [L1.one, L1.zero, L1(-5)] and ex.field_degree(L) == 8
    assert r * r == 5
    with mpmath.workdps(50):
        assert abs(ex.num(r, L) - mpmath.sqrt(5)) < mpmath.mpf(10) ** -30


def test_norm_of_a_tower_polynomial(tower):
    _, _, L2, _, r2, _ = tower
    x = sp.Symbol("x")
    N = ex.norm([L2.one, -r2], L2)
    expected = sp.Poly(sp.minimal_polynomial(TOP, x) ** 2, x)  # [L2 : QQ(√(1 + √3))] = 2
    assert sp.Poly([QQ.to_sympy(c) for c in N], x) == expected


def test_nested_bott_duffin_case_is_exact():
    """A degree-5 target whose Bott–Duffin synthesis needs a degree-18 field (a root over a degree-6 field)."""
    Z = (8839116 * p**4 + 3312933 * p**3 + 2111630 * p**2 + 133060 * p + 2200) / (
        4988412 * p**5 + 1880073 * p**4 + 4594926 * p**3 + 1351665 * p**2 + 69970 * p + 1000
    )
    t0 = time.time()
    net = bott_duffin_synthesis(Z, p)
    assert time.time() - t0 < 120
    roots = {r.poly for v in _values(net) for r in sp.sympify(v).atoms(sp.CRootOf)}
    assert [q.degree() for q in roots] == [18]
    _check_exact(net, Z)


@pytest.mark.parametrize("root", [sp.Rational(1, 7), sp.Rational(1, 3)])
def test_root_choice_survives_a_large_generator(root):
    """Over QQ(√m) with √m ≈ 1.25e15 the root is identified through γ = r + s√m; two roots 0.19 apart are 1.5e-16
    apart relative to γ, so the sum must be formed with all the digits (in double precision the other root was
    picked: a random degree-6 target was then refused as not positive real)."""
    K = QQ.algebraic_field(sp.sqrt(1571608388319572395013532841609))
    f = [K.one, K.convert(-sp.Rational(1, 7) - sp.Rational(1, 3)), K.convert(sp.Rational(1, 21))]  # (x - 1/7)(x - 1/3)
    r, L = ex.extend_with_root(f, K, mpmath.mpf(root.p) / root.q, "test roots")
    assert L == K and r == K.convert(root)


@pytest.fixture(scope="module")
def cubic_top(tower):
    """A third level of degree 3 over the tower: ∛(1 + √(1 + √3)) (a degree-24 field)."""
    _, _, L2, _, r2, _ = tower
    root = mpmath.cbrt(1 + mpmath.sqrt(1 + mpmath.sqrt(3)))
    r3, L3 = ex.extend_with_root([L2.one, L2.zero, L2.zero, -(L2.one + r2)], L2, root, "cube root")
    assert (L3.e, ex.field_degree(L3)) == (3, 24)
    return r3, L3


def test_berkowitz_charpoly_agrees_with_sympy():
    rng = random.Random(11)
    x = sp.Symbol("x")
    for n in (1, 2, 3, 5):
        rows = [[QQ(rng.randint(-9, 9), rng.randint(1, 4)) for _ in range(n)] for _ in range(n)]
        expected = sp.Matrix(n, n, [QQ.to_sympy(c) for row in rows for c in row]).charpoly(x).all_coeffs()
        assert [QQ.to_sympy(c) for c in _tower.charpoly(rows, QQ)] == expected


def _invert_by_euclid(a: list, m: list, K) -> list:
    """``1/a`` modulo the monic irreducible ``m`` over ``K`` by the extended Euclidean algorithm: the independent
    reference for the Cayley–Hamilton inverse of the tower fields."""
    r0, r1, s0, s1 = m, a, [], [K.one]
    while len(r1) > 1:
        inv = _tower.inverse(r1[0], K)
        q, r = [], list(r0)
        while len(r) >= len(r1):
            c = r[0] * inv
            q.append(c)
            for i in range(1, len(r1)):
                r[i] = r[i] - c * r1[i]
            r.pop(0)
        q = dup_strip(q)
        r = dup_strip(r)
        r0, r1, s0, s1 = r1, r, s1, dup_sub(s0, dup_mul(q, s1, K), K)
    if not r1:
        raise ZeroDivisionError("not invertible modulo an irreducible polynomial")
    inv = _tower.inverse(r1[0], K)
    return _tower._reduce([c * inv for c in s1], m, K)


def test_charpoly_inverse_agrees_with_euclid(tower, cubic_top):
    """The Cayley–Hamilton inverse (one inversion in the base field) against the extended Euclidean algorithm (one
    per division step) and against ``a · a⁻¹ = 1``, on two- and three-level towers (quadratic and cubic levels)."""
    _, L1, L2, _, _, M = tower
    _, L3 = cubic_top
    rng = random.Random(5)
    for F in (L1, L2, L3):
        for _ in range(6):
            a = _random_element(F, rng)
            if len(a.rep) < 2:
                continue
            inv = _tower.invert_charpoly(a.rep, F.own, F.base)
            assert inv == _invert_by_euclid(a.rep, F.own, F.base)
            assert a * TowerElement(inv, F) == F.one
            if F is not L3:
                assert _image(TowerElement(inv, F), F, M) == M.one / _image(a, F, M)


def test_algebraic_inverse_agrees_with_sympy():
    """The inverse in an algebraic field by a rational linear solve against SymPy's own (extended gcd)."""
    K = QQ.algebraic_field(SQ2, SQ3, sp.sqrt(5))
    rng = random.Random(9)
    for _ in range(8):
        c = K([QQ(rng.randint(-99, 99), rng.randint(1, 50)) for _ in range(8)])
        if c:
            assert _tower._algebraic_inverse(c, K) == K.quo(K.one, c)
    with pytest.raises(ZeroDivisionError):
        _tower._algebraic_inverse(K.zero, K)


def test_gamma_coordinates_agree_with_a_linear_solve(tower, cubic_top):
    """The γ-coordinates from the products of the generators' polynomials in γ against the solution of
    ``A x = b`` (``A``: the powers of γ in the monomial basis; SymPy's solver)."""
    from sympy.polys.matrices import DomainMatrix

    _, _, L2, _, _, _ = tower
    _, L3 = cubic_top
    rng = random.Random(13)
    for F in (L2, L3):
        n = F.degree
        columns = _tower._gamma_powers(F)
        A = DomainMatrix([[columns[j][i] for j in range(n)] for i in range(n)], (n, n), QQ)
        cs = [_random_element(F, rng) for _ in range(3)] + [F.gen, F.primitive, F.one]
        b = DomainMatrix([[_tower.flatten(c, F)[i] for c in cs] for i in range(n)], (n, len(cs)), QQ)
        rows = A.lu_solve(b).to_list()
        expected = [dup_strip([rows[i][j] for i in reversed(range(n))]) for j in range(len(cs))]
        assert _tower.gamma_coordinates(cs, F) == expected
        assert _tower.gamma_coordinates(cs[:1], F) == expected[:1]


def test_trace_agrees_with_the_multiplication_matrix(tower, cubic_top):
    """``Tr(c)`` level by level (power sums of the levels' polynomials) against the trace of the rational matrix of
    multiplication by ``c``."""
    K, L1, L2, _, _, _ = tower
    _, L3 = cubic_top
    rng = random.Random(17)
    for F in (K, L1, L2, L3):
        for _ in range(4):
            c = _random_element(F, rng)
            M = _tower.matrix(c, F)
            diagonal = sum((M[i, i] for i in range(M.nrows())), QQ.zero)
            assert _tower.trace(c, F) == diagonal


def _random_monic(F, rng, degree):
    return [F.one, *(_random_element(F, rng) for _ in range(degree))]


def _irreducible_by_norm(f, F):
    """Ground truth (Trager (1976), §3): a monic squarefree ``f`` over ``F`` is irreducible iff the norm of some
    shift ``f(x - sΘ)`` with a squarefree norm is irreducible over the rationals."""
    theta = ex._tower.primitive(F)
    for s in (1, -1, 2, -2, 3):
        N = ex.norm(ex.dup_shift(f, F.mul(F.convert(-s), theta), F), F)
        if ex.squarefree_qq(N):
            return len(ex.factor_qq(N)) == 1 and ex.factor_qq(N)[0][1] == 1
    raise AssertionError("no squarefree norm")  # pragma: no cover


def test_modular_irreducibility_is_never_wrong(tower, cubic_top):
    """``irreducible_modulo_primes`` (used to refuse a too-large field before computing a norm) says True only for
    polynomials the norm proves irreducible; products of two polynomials are never called irreducible; and on
    irreducible ones of degree 2-4 it usually decides (at least half here)."""

    K, L1, L2, _, _, _ = tower
    _, L3 = cubic_top
    rng = random.Random(21)
    decided = checked = 0
    for F in (K, L1, L2, L3):
        for degree in (2, 3, 4):
            f = _random_monic(F, rng, degree)
            verdict = ex.irreducible_modulo_primes(f, F)
            if F is not L3:  # the norm of a degree-4 polynomial over a degree-24 field is slow to factor
                truth = _irreducible_by_norm(f, F)
                assert truth or not verdict
                checked += truth
                decided += verdict
            product = dup_mul(_random_monic(F, rng, 1), _random_monic(F, rng, degree - 1), F)
            assert not ex.irreducible_modulo_primes(product, F)
    assert checked >= 6 and decided * 2 >= checked


def test_field_caches_are_bounded():
    """The per-field caches keep the fields added last (an unbounded cache grew by about 8 MB per large synthesis)."""
    cache = _tower.FieldCache(maxsize=2)
    cache["a"], cache["b"] = 1, 2
    cache["a"] = 3  # an update keeps the entry count
    assert cache == {"a": 3, "b": 2}
    cache["c"] = 4
    assert cache == {"b": 2, "c": 4}
    assert all(
        isinstance(c, _tower.FieldCache)
        for c in (_tower._INVERSES, _tower._COMPANIONS, _tower._POWER_SUMS, ex._REDUCTIONS, ex._GENERATORS)
    )


def test_level_by_level_values_are_exact(tower, cubic_top):
    """``in_levels_all`` writes an element as polynomials in each level's adjoined root ``CRootOf(φ) - s Θ``.
    On the degree-8 tower the level ``CRootOf`` numbers are replaced by the radicals they stand for (checked to 40
    digits) and the result is compared exactly in SymPy's own field; on the degree-24 tower the value agrees to 50
    digits with the element's numerical value and with its form in the primitive element."""
    _, L1, L2, _, _, M = tower
    _, L3 = cubic_top
    gamma1 = SQ3 + L1.s * SQ2  # γ1 = √3 + s1 √2, γ2 = √(1 + √3) + s2 γ1
    gamma2 = TOP + L2.s * gamma1
    assert abs(sp.N(L1.crootof() - gamma1, 50)) < 1e-40
    assert abs(sp.N(L2.crootof() - gamma2, 50)) < 1e-40
    rng = random.Random(8)
    elements = [_random_element(L2, rng) for _ in range(3)]
    for a, value in zip(elements, _tower.in_levels_all(elements, L2), strict=True):
        assert {r.poly.degree() for r in value.atoms(sp.CRootOf)} <= {4, 8}
        radicals = value.xreplace({L1.crootof(): gamma1, L2.crootof(): gamma2})
        assert M.from_sympy(sp.expand(radicals)) == _image(a, L2, M)
    elements = [_random_element(L3, rng) for _ in range(2)]
    levels, primitive = _tower.in_levels_all(elements, L3), _tower.in_crootof_all(elements, L3)
    for a, value, other in zip(elements, levels, primitive, strict=True):
        with mpmath.workdps(70):
            exact = ex.num(a, L3, 60)
            assert abs(mpmath.mpf(str(sp.N(value, 60))) - exact) < mpmath.mpf(10) ** -50 * (1 + abs(exact))
            assert abs(mpmath.mpf(str(sp.N(other, 60))) - exact) < mpmath.mpf(10) ** -50 * (1 + abs(exact))


def test_even_part_value_agrees_with_sympy_fields(tower):
    """``even_value(N, D, x0)`` (the even part of ``N/D`` at ``p² = -x0``, from the even and odd parts of ``N`` and
    ``D``) equals ``(N(p) D(-p) + N(-p) D(p)) / (2 D(p) D(-p))`` from the full polynomial products, written in
    ``x = -p²`` and evaluated at ``x0`` in SymPy's own field (its own primitive element and arithmetic); random
    polynomials of degrees 0-6 over the degree-8 tower."""
    _, _, L2, _, _, M = tower
    rng = random.Random(5)
    for _ in range(12):
        N = dup_strip([_random_element(L2, rng) for _ in range(rng.randint(1, 7))])
        D = dup_strip([_random_element(L2, rng) for _ in range(rng.randint(1, 7))])
        x0 = _random_element(L2, rng)
        if not N or not D:
            continue
        Nm, Dm = ([_image(c, L2, M) for c in f] for f in (N, D))
        reflected = [ex.reflect(f, M) for f in (Nm, Dm)]
        top = ex.in_x(dup_add(dup_mul(Nm, reflected[1], M), dup_mul(reflected[0], Dm, M), M), M)
        bottom = ex.in_x(dup_mul(Dm, reflected[1], M), M)
        x0m = _image(x0, L2, M)
        expected = M.quo(ex.dup_eval(top, x0m, M), M.mul(M(2), ex.dup_eval(bottom, x0m, M)))
        assert _image(ex.even_value(N, D, x0, L2), L2, M) == expected
