"""Tower number fields (private): ``L = K[x]/(own(x))`` over a number field ``K``.

``K`` is a SymPy ``AlgebraicField`` or another :class:`TowerField`; ``own`` is monic and irreducible over ``K``.
Elements are dense coefficient lists over ``K`` (highest power first, degree < ``deg own``), so the numbers of a
nested extension keep the small heights of their defining polynomials (the same numbers written in a primitive
element's power basis have coefficients of thousands of digits).  The field also records a primitive element of
the whole tower, ``γ = x + s Θ`` (``Θ`` the primitive element of ``K``), a real root (``index``) of the irreducible
rational polynomial ``φ``; it is used for the numerical value of ``x`` (certified root isolation of ``φ``), for
Trager's shift when the tower is extended again, and to write an element as an exact SymPy number, a polynomial in
``CRootOf(φ, index)``.  The construction is Trager's
(Trager (1976), §3; Cohen (1993), §3.6.2).
"""

from __future__ import annotations

import math

import mpmath
import sympy as sp
from sympy import QQ
from sympy.polys.densearith import dup_mul
from sympy.polys.densebasic import dup_strip
from sympy.polys.domains.characteristiczero import CharacteristicZero
from sympy.polys.domains.field import Field
from sympy.polys.domains.simpledomain import SimpleDomain
from sympy.polys.polyerrors import CoercionFailed


def _reduce(rep: list, own: list, K) -> list:
    """``rep`` modulo the monic ``own`` over ``K``."""
    e = len(own) - 1
    rep = list(rep)
    while len(rep) > e:
        c = rep.pop(0)
        if c:
            for i in range(e):
                rep[i] = rep[i] - c * own[i + 1]
    return dup_strip(rep)


class FieldCache(dict):
    """Per-field data (multiplication matrices, inverses, reductions, …) for the ``maxsize`` fields added last: the
    fields of large syntheses hold numbers of thousands of digits, and an unbounded cache would grow with every
    synthesis of a session.  Entries are pure functions of their key, so an evicted one is only recomputed."""

    def __init__(self, maxsize: int = 32) -> None:
        super().__init__()
        self.maxsize = maxsize

    def __setitem__(self, key, value) -> None:
        if key not in self and len(self) >= self.maxsize:
            del self[next(iter(self))]  # the oldest
        super().__setitem__(key, value)


def inverse(c, K):
    """``1/c`` in ``K`` (an algebraic or a tower field), remembering the last few inverses of each field (the dense
    routines divide many times by the same leading coefficient)."""
    cache = _INVERSES.get(K)
    if cache is None:
        cache = _INVERSES[K] = {}
    key = c if isinstance(c, TowerElement) else tuple(c.to_list()) if not K.is_QQ else c
    inv = cache.get(key)
    if inv is None:
        inv = c.inverse() if isinstance(c, TowerElement) else _algebraic_inverse(c, K)
        if len(cache) > 256:
            cache.clear()
        cache[key] = inv
    return inv


_INVERSES = FieldCache()


def _algebraic_inverse(c, K):
    """``1/c`` in QQ or an ``AlgebraicField``: with python-flint the solution of ``M x = 1``, ``M`` the rational
    matrix of multiplication by ``c`` in the basis ``1, θ, ..., θ^(n-1)`` (flint's fraction-free solver: several
    times faster than its extended gcd of ``c`` and the minimal polynomial on the coefficients of thousands of
    digits of nested fields); SymPy's dense gcdex without it."""
    from .fields import flint_module

    flint = flint_module()
    if flint is None or K.is_QQ:
        return K.quo(K.one, c)
    mod = _fq_poly(flint, K.mod.to_list())
    n = mod.degree()
    mod = mod / mod[n]
    v, columns = _fq_poly(flint, c.to_list()) % mod, []
    if v.is_zero():
        raise ZeroDivisionError("division by zero in an algebraic field")
    for _ in range(n):  # c θ^k modulo the minimal polynomial, lowest power first
        columns.append([v[i] for i in range(n)])
        v = v.left_shift(1)
        if v.degree() == n:
            v -= mod * v[n]
    M = flint.fmpq_mat(n, n, [columns[k][i] for i in range(n) for k in range(n)])
    x = M.solve(flint.fmpq_mat(n, 1, [1] + [0] * (n - 1)), algorithm="fflu")
    return K(dup_strip([QQ(int(x[i, 0].p), int(x[i, 0].q)) for i in reversed(range(n))]))


def _fq_poly(flint, coeffs: list):
    """A flint polynomial from dense coefficients (highest power first)."""
    return flint.fmpq_poly([_fq(flint, a) for a in reversed(coeffs)])


def monic(f: list, K) -> list:
    """``f`` divided by its leading coefficient (one inversion)."""
    if not f:
        return f
    inv = inverse(f[0], K)
    return [K.one, *(c * inv for c in f[1:])]


def multiplication_columns(a: list, own: list, K) -> list[list]:
    """Coordinates (length ``e = deg own``, highest power first) of ``a x^j`` modulo the monic ``own`` over ``K``
    for ``j = e - 1, ..., 0``: the columns of the matrix of multiplication by ``a`` in the basis
    ``x^(e-1), ..., 1`` (no division: ``own`` is monic)."""
    e = len(own) - 1
    v = [K.zero] * (e - len(a)) + list(a)
    cols = [v]
    for _ in range(e - 1):  # times x: shift, then reduce the overflowing coefficient with own
        c, v = v[0], [*v[1:], K.zero]
        if c:
            v = [v[i] - c * own[i + 1] for i in range(e)]
        cols.append(v)
    return cols[::-1]


def charpoly(A: list[list], K) -> list:
    """Characteristic polynomial ``det(t I - A)`` (highest power first) of the square matrix ``A`` (rows) over the
    ring ``K``, by Berkowitz's division-free algorithm (Berkowitz (1984); Abdeljaoued and Lombardi (2004), ch. 7):
    the polynomial of each leading principal submatrix from the previous one by a lower triangular Toeplitz
    matrix whose entries are ``-R A^k C`` (``R``, ``C`` the new row and column)."""
    poly = [K.one]
    for r in range(1, len(A) + 1):
        row, col = A[r - 1][: r - 1], [A[i][r - 1] for i in range(r - 1)]
        toeplitz = [K.one, -A[r - 1][r - 1]]
        for _ in range(r - 1):  # -R A_(r-1)^k C, k = 0, ..., r - 2
            acc = K.zero
            for x, y in zip(row, col, strict=True):
                acc = acc + x * y
            toeplitz.append(-acc)
            col = [sum((A[i][j] * col[j] for j in range(r - 1)), K.zero) for i in range(r - 1)]
        poly = [
            sum((toeplitz[i - j] * poly[j] for j in range(max(0, i - r), min(i, r - 1) + 1)), K.zero)
            for i in range(r + 1)
        ]
    return poly


def invert_charpoly(a: list, own: list, K) -> list:
    """``1/a`` modulo the monic irreducible ``own`` over ``K`` by the Cayley–Hamilton theorem: with
    ``χ(t) = t^e + c_1 t^(e-1) + ... + c_e`` the characteristic polynomial of multiplication by ``a`` (division-free,
    :func:`charpoly`), ``1/a = -(a^(e-1) + c_1 a^(e-2) + ... + c_(e-1)) / c_e``; ``c_e = ±`` the norm of ``a`` is
    the one element of ``K`` inverted (the Euclidean algorithm inverts one per division step)."""
    cols = multiplication_columns(a, own, K)
    e = len(cols)
    rows = [[cols[j][i] for j in range(e)] for i in range(e)]
    chi = charpoly(rows, K)
    if not chi[-1]:
        raise ZeroDivisionError("not invertible modulo an irreducible polynomial")
    h = [K.zero] * (e - 1) + [K.one]  # Horner's rule, coordinates: h <- a h + c_k (a h: the matrix times h)
    for c in chi[1:-1]:
        h = [sum((x * y for x, y in zip(row, h, strict=True)), K.zero) for row in rows]
        h[-1] = h[-1] + c
    inv = -inverse(chi[-1], K)
    return dup_strip([x * inv for x in h])


class TowerElement:
    """An element of a :class:`TowerField`: ``rep`` over the base field, reduced modulo ``own``."""

    __slots__ = ("field", "rep")

    def __init__(self, rep: list, field: TowerField) -> None:
        self.rep = rep
        self.field = field

    def _coerce(self, other):
        F = self.field
        if isinstance(other, TowerElement) and other.field is F:
            return other
        try:
            return F.convert(other)
        except CoercionFailed:
            return None

    def to_list(self) -> list:
        return list(self.rep)

    def __bool__(self) -> bool:
        return bool(self.rep)

    def __eq__(self, other) -> bool:
        other = self._coerce(other)
        return other is not None and self.rep == other.rep

    def __ne__(self, other) -> bool:
        return not self == other

    def __hash__(self) -> int:
        if len(self.rep) <= 1:  # equal to the base element (or int) it comes from
            return hash(self.rep[0]) if self.rep else hash(0)
        return hash((id(self.field), tuple(self.rep)))

    def __neg__(self) -> TowerElement:
        return TowerElement([-c for c in self.rep], self.field)

    def __pos__(self) -> TowerElement:
        return self

    def __add__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        a, b = self.rep, o.rep
        if len(a) < len(b):
            a, b = b, a
        n = len(a) - len(b)
        return TowerElement(dup_strip(a[:n] + [x + y for x, y in zip(a[n:], b, strict=True)]), self.field)

    __radd__ = __add__

    def __sub__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return self + (-o)

    def __rsub__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return o + (-self)

    def __mul__(self, other):
        F = self.field
        if isinstance(other, TowerElement) and other.field is F:
            if len(other.rep) == 1:
                other = other.rep[0]
            elif len(self.rep) == 1:
                return other * self.rep[0]
            else:
                return TowerElement(_reduce(dup_mul(self.rep, other.rep, F.base), F.own, F.base), F)
        try:
            c = F.base.convert(other)
        except CoercionFailed:
            return NotImplemented
        return TowerElement(dup_strip([a * c for a in self.rep]), F)

    __rmul__ = __mul__

    def __pow__(self, n: int) -> TowerElement:
        if n < 0:
            return (self.field.one / self) ** (-n)
        out, sq = self.field.one, self
        while n:
            if n & 1:
                out = out * sq
            sq = sq * sq
            n >>= 1
        return out

    def inverse(self) -> TowerElement:
        F = self.field
        if not self.rep:
            raise ZeroDivisionError("division by zero in a tower field")
        if len(self.rep) == 1:
            return TowerElement([inverse(self.rep[0], F.base)], F)
        return TowerElement(invert_charpoly(self.rep, F.own, F.base), F)

    def __truediv__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        if len(o.rep) == 1:
            inv = inverse(o.rep[0], self.field.base)
            return TowerElement(dup_strip([a * inv for a in self.rep]), self.field)
        return self * inverse(o, self.field)

    def __rtruediv__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return o * inverse(self, self.field)

    def __repr__(self) -> str:
        return f"TowerElement({self.rep!r})"


class TowerField(Field, CharacteristicZero, SimpleDomain):
    """``base[x]/(own(x))``; ``phi``, ``index``, ``s``: ``γ = x + s Θ`` is ``CRootOf(phi, index)``."""

    dtype = TowerElement
    is_Numerical = True
    is_Exact = True
    has_assoc_Ring = False
    has_assoc_Field = True

    def __init__(self, base, own: list, phi: list, index: int, s: int) -> None:
        self.base = base
        lc = own[0]
        self.own = [base.quo(c, lc) for c in own]
        self.e = len(own) - 1
        self.degree = base_degree(base) * self.e
        self.phi, self.index, self.s = phi, index, s
        self.dom = QQ
        self.zero = TowerElement([], self)
        self.one = TowerElement([base.one], self)
        self.gen = TowerElement([base.one, base.zero], self)  # x: the root adjoined at this level
        theta = self.convert(primitive(base))
        self.primitive = self.gen + theta * s  # γ
        self._values: dict = {}
        self._solver = None
        self._root = None

    # --- domain protocol -------------------------------------------------------------------------------------
    def __eq__(self, other) -> bool:
        return self is other

    def __hash__(self) -> int:
        return id(self)

    def __str__(self) -> str:
        return f"{self.base}[x]/(deg {self.e})"

    __repr__ = __str__

    def new(self, a):
        return self.convert(a)

    def __call__(self, a):
        return self.convert(a)

    def of_type(self, a) -> bool:
        return isinstance(a, TowerElement) and a.field is self

    def convert(self, a, base=None):
        if isinstance(a, TowerElement) and a.field is self:
            return a
        c = self.base.convert(a)
        return TowerElement([c] if c else [], self)

    def convert_from(self, a, base):
        return self.convert(a)

    def from_base(self, c) -> TowerElement:
        return TowerElement([c] if c else [], self)

    def from_sympy(self, a):
        return self.convert(self.base.from_sympy(a))

    def to_sympy(self, a) -> sp.Expr:
        return in_crootof(a, self)

    def get_ring(self):  # pragma: no cover - no ring of integers is needed
        raise NotImplementedError("a tower field has no associated ring here")

    def is_negative(self, a) -> bool:  # the dense routines ask for it on leading coefficients only
        return False

    def is_positive(self, a) -> bool:
        return bool(a)

    def quo(self, a, b):
        return self.convert(a) / self.convert(b)

    exquo = quo

    def rem(self, a, b):
        return self.zero

    def div(self, a, b):
        return self.quo(a, b), self.zero

    def gcd(self, a, b):
        return self.one

    def lcm(self, a, b):
        return self.convert(a) * self.convert(b)

    @property
    def unit(self) -> TowerElement:
        return self.gen

    @property
    def levels(self) -> list:
        """The tower from the bottom ``AlgebraicField`` up to this field."""
        out, F = [], self
        while isinstance(F, TowerField):
            out.append(F)
            F = F.base
        return [F, *reversed(out)]

    # --- numbers ----------------------------------------------------------------------------------------------
    def crootof(self) -> sp.Expr:
        if self._root is None:
            y = sp.Dummy("y")
            self._root = sp.CRootOf(sp.Poly([QQ.to_sympy(c) for c in self.phi], y), self.index)
        return self._root

    def gamma_value(self, digits: int):
        """Certified value of ``γ`` (isolation of ``φ``'s real roots)."""
        if digits not in self._values:
            from .fields import real_roots_numeric

            self._values[digits] = real_roots_numeric(self.phi, digits + 10)[self.index]
        return self._values[digits]

    def root_value(self, digits: int):
        """Value of the adjoined root ``x = γ - s Θ``."""
        with mpmath.workdps(digits + 10):
            return self.gamma_value(digits) - self.s * primitive_value(self.base, digits)


def levels(K) -> list:
    """The fields of ``K``'s tower, bottom first (``[K]`` for QQ or an ``AlgebraicField``)."""
    return K.levels if isinstance(K, TowerField) else [K]


def base_degree(K) -> int:
    """Degree over QQ of ``QQ``, an ``AlgebraicField`` or a :class:`TowerField`."""
    if isinstance(K, TowerField):
        return K.degree
    return 1 if K.is_QQ else len(K.mod.to_list()) - 1


def primitive(K):
    """The primitive element of ``K`` as an element of ``K``."""
    return K.primitive if isinstance(K, TowerField) else K.unit


def primitive_value(K, digits: int):
    from .fields import _generator_value

    return K.gamma_value(digits) if isinstance(K, TowerField) else _generator_value(K, digits)


def value(c, K, digits: int):
    """Numerical value (mpmath, about ``digits`` digits) of an element of ``QQ``, an algebraic or a tower field."""
    if not isinstance(K, TowerField):
        from .fields import num

        return num(c, K, digits)
    with mpmath.workdps(digits + 20):
        x, acc = K.root_value(digits + 10), mpmath.mpf(0)
        for a in c.rep:
            acc = acc * x + value(a, K.base, digits + 10)
        return acc


# --- multiplication matrices -----------------------------------------------------------------------------------
def matrix(c, K):
    """The rational matrix (python-flint ``fmpq_mat``) of multiplication by ``c`` in ``K``'s monomial basis (the
    coordinates of :func:`flatten`): Horner's rule in the matrix of the generator, level by level."""
    from .fields import flint_module

    flint = flint_module()
    n = base_degree(K)
    if not isinstance(K, TowerField):
        coeffs = [c] if K.is_QQ else c.to_list()
        Y, one = companion(K), flint.fmpq_mat(n, n, [int(i == j) for i in range(n) for j in range(n)])
        acc = flint.fmpq_mat(n, n)
        for a in coeffs:
            acc = acc * Y + one * _fq(flint, a)
        return acc
    d = base_degree(K.base)
    acc = flint.fmpq_mat(n, n)
    for a in c.rep:
        B = matrix(a, K.base)
        blocks = flint.fmpq_mat(n, n)
        for i in range(K.e):
            for r in range(d):
                for k in range(d):
                    if B[r, k] != 0:
                        blocks[i * d + r, i * d + k] = B[r, k]
        acc = acc * companion(K) + blocks
    return acc


def companion(K):
    """Matrix of multiplication by ``K``'s adjoined generator (``θ`` of an algebraic field, ``x`` of a tower)."""
    from .fields import flint_module

    cache = _COMPANIONS.get(K)
    if cache is not None:
        return cache
    flint = flint_module()
    n = base_degree(K)
    Y = flint.fmpq_mat(n, n)
    if not isinstance(K, TowerField):  # basis θ^(n-1), ..., 1 (index n-1-k for θ^k)
        mod = K.mod.to_list()
        for k in range(n - 1):
            Y[n - 2 - k, n - 1 - k] = 1
        for i in range(1, n + 1):  # θ · θ^(n-1) = -Σ mod_i θ^(n-i)  (mod monic)
            Y[i - 1, 0] = -_fq(flint, mod[i]) / _fq(flint, mod[0])
    else:
        d, e = base_degree(K.base), K.e
        for k in range(e - 1):
            for r in range(d):
                Y[(e - 2 - k) * d + r, (e - 1 - k) * d + r] = 1
        for i in range(1, e + 1):
            B = matrix(-K.own[i], K.base)
            for r in range(d):
                for k in range(d):
                    if B[r, k] != 0:
                        Y[(i - 1) * d + r, k] = B[r, k]
    _COMPANIONS[K] = Y
    return Y


_COMPANIONS = FieldCache()


# --- exact conversion to one CRootOf ---------------------------------------------------------------------------
def flatten(c, K) -> list:
    """Rational coordinates of ``c`` in the tower's monomial basis (fixed length ``base_degree(K)``)."""
    if not isinstance(K, TowerField):
        coeffs = c.to_list() if not K.is_QQ else [c]
        n = base_degree(K)
        return [QQ.zero] * (n - len(coeffs)) + list(coeffs)
    rep = [K.base.zero] * (K.e - len(c.rep)) + list(c.rep)
    out: list = []
    for a in rep:
        out += flatten(a, K.base)
    return out


def gamma_coordinates(cs: list, K) -> list[list]:
    """Coefficients (highest power first) of each element of ``cs`` as a polynomial in ``γ``.

    With python-flint: the coordinate vectors in the monomial basis (:func:`flatten`) times the rational matrix
    whose columns are the monomials as polynomials in ``γ`` (:func:`_gamma_basis`, built once per field).  Without
    it: SymPy's DomainMatrix solves ``A x = b``, the columns of ``A`` the powers of ``γ`` in the monomial basis."""
    from .fields import flint_module

    flint = flint_module()
    n, m = K.degree, len(cs)
    targets = [flatten(c, K) for c in cs]
    if flint is not None:  # integer matrices: the basis over one denominator, each target over its own
        basis, den = _gamma_basis(K)
        rhs, dens = _integer_rows(targets)
        sol = basis * rhs.transpose()
        coeffs = [[QQ(int(sol[i, j]), den * dens[j]) for i in range(n)] for j in range(m)]
    else:
        from sympy.polys.matrices import DomainMatrix

        columns = _gamma_powers(K)
        A = DomainMatrix([[columns[j][i] for j in range(n)] for i in range(n)], (n, n), QQ)
        b = DomainMatrix([[targets[j][i] for j in range(m)] for i in range(n)], (n, m), QQ)
        rows = A.lu_solve(b).to_list()
        coeffs = [[rows[i][j] for i in range(n)] for j in range(m)]
    return [dup_strip(list(reversed(c))) for c in coeffs]


def _gamma_powers(K) -> list[list]:
    """``γ^k`` in the monomial basis, ``k = 0, ..., n - 1``."""
    columns, pw = [], K.one
    for _ in range(K.degree):
        columns.append(flatten(pw, K))
        pw = pw * K.primitive
    return columns


def _gamma_basis(K) -> tuple:
    """``(B, d)`` (cached on ``K``): ``B / d`` (``B`` a flint ``fmpz_mat``, ``d`` an integer) is the rational matrix
    whose column ``i`` holds the coefficients (lowest power first) of the ``i``-th monomial of :func:`flatten` as a
    polynomial in ``γ`` modulo ``φ``, the inverse of the matrix ``A`` of the powers of ``γ`` in the monomial basis.

    The generators of the levels (``θ`` of the bottom field, the adjoined roots ``x_i``) as polynomials in ``γ`` by
    :func:`_in_gamma` (traces, no linear solve), the monomials as their products modulo ``φ``.  Solving with ``A``
    (entries of 10 000-30 000 digits at degree 32-40) took most of the time of the hardest syntheses."""
    from .fields import flint_module

    if K._solver is not None:
        return K._solver
    flint, n = flint_module(), K.degree
    levels = K.levels
    gens = [levels[0].unit] + [F.gen for F in levels[1:]]
    polys = _in_gamma([K.convert(g) for g in gens], K)
    phi = _fq_poly(flint, K.phi)

    def powers(g, count: int) -> list:  # g^(count-1), ..., g, 1 modulo φ
        out = [flint.fmpq_poly([1])]
        for _ in range(count - 1):
            out.append((out[-1] * g) % phi)
        return out[::-1]

    monomials = powers(polys[0], base_degree(levels[0]))
    for i, F in enumerate(levels[1:], start=1):
        xs = powers(polys[i], F.e)
        monomials = [(x * mon) % phi if j < F.e - 1 else mon for j, x in enumerate(xs) for mon in monomials]
    den = math.lcm(*(int(mon.denom()) for mon in monomials))  # in practice one denominator for all
    columns = []
    for mon in monomials:
        scale = den // int(mon.denom())
        column = [int(c) * scale for c in mon.numer().coeffs()]
        columns.append(column + [0] * (n - len(column)))
    K._solver = flint.fmpz_mat(n, n, [columns[j][i] for i in range(n) for j in range(n)]), den
    return K._solver


def _integer_rows(vectors: list[list]) -> tuple:
    """``(M, dens)``: the rational vectors as the rows of an integer matrix (flint ``fmpz_mat``), each row multiplied
    by its least common denominator ``dens[i]``."""
    from .fields import flint_module

    dens = [math.lcm(*(int(a.denominator) for a in v)) for v in vectors]
    entries = [int(a.numerator) * (den // int(a.denominator)) for v, den in zip(vectors, dens, strict=True) for a in v]
    return flint_module().fmpz_mat(len(vectors), len(vectors[0]), entries), dens


def _in_gamma(cs: list, K) -> list:
    """Each element ``δ`` of ``cs`` as a polynomial ``T(y)`` (flint ``fmpq_poly``) with ``T(γ) = δ``, by
    Lagrange interpolation over the conjugates: ``G(y) = Tr(δ φ(y)/(y - γ))`` takes the value ``σ(δ) φ'(σ(γ))`` at
    each root ``σ(γ)`` of ``φ``, so ``T = G / φ'`` modulo ``φ``.  With ``φ(y)/(y - γ) = Σ_k b_k y^k``,
    ``b_k = Σ_(j>k) f_j γ^(j-1-k)``, the coefficients of ``G`` need only the traces ``τ_m = Tr(δ γ^m)``:
    ``G`` is ``φ(y) Σ_m τ_m y^(n-1-m)`` shifted down by ``n``; ``τ_m = u · (γ^m in the monomial basis)`` with
    ``u_i = Tr(δ · monomial_i)`` (:func:`trace`), the powers of ``γ`` by the rational matrix of multiplication by
    ``γ`` (flint's products; the same powers in the tower's own arithmetic take several times longer)."""
    from .fields import flint_module

    flint, n = flint_module(), K.degree
    monomials = [_unflatten([QQ.one if i == j else QQ.zero for j in range(n)], K) for i in range(n)]
    U = flint.fmpq_mat(len(cs), n, [_fq(flint, trace(c * mon, K)) for c in cs for mon in monomials])
    step, power = matrix(K.primitive, K), flint.fmpq_mat(n, 1, [0] * (n - 1) + [1])
    taus = []  # τ_m for every δ: U times γ^m in the monomial basis (the powers by flint's matrix products)
    for _ in range(n):
        taus.append(U * power)
        power = step * power
    phi = _fq_poly(flint, K.phi)
    g, inv, _ = phi.derivative().xgcd(phi)
    inv = inv / g[0]
    out = []
    for r in range(len(cs)):
        G = (phi * flint.fmpq_poly([taus[m][r, 0] for m in reversed(range(n))])).right_shift(n)
        out.append((G * inv) % phi)
    return out


def trace(c, K):
    """``Tr_(K/QQ)(c)``: level by level, ``Tr(Σ c_j x^j) = Σ c_j p_j`` with ``p_j`` the power sums of the roots of
    the level's monic polynomial (Newton's identities, cached per field)."""
    if not isinstance(K, TowerField) and K.is_QQ:
        return c
    sums = _power_sums(K)
    coeffs = c.rep if isinstance(K, TowerField) else c.to_list()
    base = K.base if isinstance(K, TowerField) else QQ
    acc = base.zero
    for a, p in zip(reversed(coeffs), sums, strict=False):
        acc = acc + a * p
    return trace(acc, K.base) if isinstance(K, TowerField) else acc


def _power_sums(K) -> list:
    """``p_0, ..., p_(e-1)``: power sums of the roots of ``K``'s defining polynomial (in the field below)."""
    if K in _POWER_SUMS:
        return _POWER_SUMS[K]
    if isinstance(K, TowerField):
        base, poly = K.base, K.own
    else:
        base, mod = QQ, K.mod.to_list()
        poly = [c / mod[0] for c in mod]
    e = len(poly) - 1
    sums = [base.convert(e)]
    for k in range(1, e):
        acc = poly[k] * base.convert(k)
        for i in range(1, k):
            acc = acc + poly[i] * sums[k - i]
        sums.append(-acc)
    _POWER_SUMS[K] = sums
    return sums


_POWER_SUMS = FieldCache()


def _fq(flint, c):
    return flint.fmpq(int(c.numerator), int(c.denominator))


def in_crootof(c, K) -> sp.Expr:
    """``c`` as an exact SymPy number: a polynomial in ``CRootOf(φ, index)``."""
    return in_crootof_all([c], K)[0]


def in_crootof_all(cs: list, K) -> list[sp.Expr]:
    """:func:`in_crootof` of several elements of ``K`` (one matrix product, :func:`gamma_coordinates`)."""
    out: list = [None] * len(cs)
    todo = []
    for i, c in enumerate(cs):
        flat = flatten(c, K)
        if not any(flat[:-1]):
            out[i] = QQ.to_sympy(flat[-1])
        else:
            todo.append(i)
    if todo:
        root = K.crootof()
        for i, coeffs in zip(todo, gamma_coordinates([cs[i] for i in todo], K), strict=True):
            n = len(coeffs) - 1
            out[i] = sp.Add(*[_rational(a) * root ** (n - k) for k, a in enumerate(coeffs) if a])
    return out


#: Largest field degree whose elements :func:`in_sympy_all` writes as polynomials in one ``CRootOf``.
PRIMITIVE_FORM_MAX_DEGREE = 24


def in_sympy_all(cs: list, K) -> list[sp.Expr]:
    """Elements of ``K`` as exact SymPy numbers: polynomials in the primitive element (:func:`in_crootof_all`) up
    to :data:`PRIMITIVE_FORM_MAX_DEGREE`, level by level (:func:`in_levels_all`) above it."""
    if base_degree(K) <= PRIMITIVE_FORM_MAX_DEGREE:
        return in_crootof_all(cs, K)
    return in_levels_all(cs, K)


def in_levels_all(cs: list, K) -> list[sp.Expr]:
    """Elements of the tower field ``K`` as exact SymPy numbers written level by level: at each level a polynomial
    in the root adjoined there, ``x = CRootOf(φ, index) - s Θ`` (``Θ`` the primitive element of the level below),
    whose coefficients are such polynomials one level down, down to the base field's own form.

    No conversion to the primitive element of the whole tower: the coefficients keep the small heights of the
    tower's arithmetic (27–34 times fewer characters than :func:`in_crootof_all` for the values of networks in
    fields of degree 32–36), and the conversion, most of the time of such a synthesis, is not needed."""
    adjoined: dict = {}

    def root(F) -> sp.Expr:
        if id(F) not in adjoined:
            below = F.base
            theta = below.crootof() if isinstance(below, TowerField) else below.to_sympy(primitive(below))
            adjoined[id(F)] = F.crootof() - F.s * theta
        return adjoined[id(F)]

    def write(c, F) -> sp.Expr:
        if not isinstance(F, TowerField):
            return F.to_sympy(c)
        n = len(c.rep) - 1
        return sp.Add(*[write(a, F.base) * root(F) ** (n - k) for k, a in enumerate(c.rep) if a])

    return [write(K.convert(c), K) for c in cs]


def _rational(a) -> sp.Rational:
    """``QQ.to_sympy(a)`` without SymPy's gcd of numerator and denominator (a domain element is in lowest terms
    with a positive denominator; the gcds of the 10 000-digit coefficients of nested fields took seconds)."""
    make = getattr(sp.Rational, "from_coprime_ints", sp.Rational)  # SymPy >= 1.13
    return make(int(a.numerator), int(a.denominator))


def scaled_charpoly(M) -> tuple:
    """``(χ, d)``: the characteristic polynomial (flint ``fmpz_poly``) of ``d M``, ``d`` the least common
    denominator of the rational square matrix ``M`` (flint's multimodular integer algorithm)."""
    from .fields import flint_module

    flint, n = flint_module(), M.nrows()
    den = flint.fmpz(1)
    for i in range(n):
        for k in range(n):
            if M[i, k] != 0:
                den = den.lcm(M[i, k].q)
    scaled = flint.fmpz_mat(n, n, [int(M[i, k] * den) for i in range(n) for k in range(n)])
    return scaled.charpoly(), den


# --- the factor of a polynomial holding a root, by the embeddings of the base ------------------------------------
def _embeddings(K) -> list:
    """All complex embeddings of ``K``: tuples of the generators' values, bottom level first (current precision)."""
    if not isinstance(K, TowerField):
        coeffs = [mpmath.mpf(int(c.numerator)) / int(c.denominator) for c in K.mod.to_list()]
        return [(z,) for z in mpmath.polyroots(coeffs, maxsteps=500, extraprec=4 * mpmath.mp.prec)]
    out = []
    for emb in _embeddings(K.base):
        coeffs = [_at(c, K.base, emb) for c in K.own]
        out += [(*emb, z) for z in mpmath.polyroots(coeffs, maxsteps=500, extraprec=4 * mpmath.mp.prec)]
    return out


def _at(c, K, emb):
    """Value of an element of ``K`` under the embedding ``emb``."""
    acc = mpmath.mpf(0)
    if not isinstance(K, TowerField):
        for a in c.to_list():
            acc = acc * emb[0] + mpmath.mpf(int(a.numerator)) / int(a.denominator)
        return acc
    for a in c.rep:
        acc = acc * emb[-1] + _at(a, K.base, emb[:-1])
    return acc


def _monomials(K, emb) -> list:
    """Values of the monomial basis (the order of :func:`flatten`) under ``emb``."""
    if not isinstance(K, TowerField):
        n = base_degree(K)
        return [emb[0] ** (n - 1 - i) for i in range(n)]
    lower = _monomials(K.base, emb[:-1])
    return [emb[-1] ** j * v for j in reversed(range(K.e)) for v in lower]


def _unflatten(coords: list, K):
    if not isinstance(K, TowerField):
        return K.from_list(list(coords)) if hasattr(K, "from_list") else K(list(coords))
    d = base_degree(K.base)
    return TowerElement(dup_strip([_unflatten(coords[i * d : (i + 1) * d], K.base) for i in range(K.e)]), K)


_EMBEDDINGS = FieldCache()


def factor_holding(f: list, K, phi: list, s: int, e: int) -> list | None:
    """The monic factor of ``f`` (monic, over ``K``) of degree ``e`` whose roots ``ρ`` make ``ρ + s Θ`` roots of
    ``φ``: under every embedding ``σ`` of ``K`` its coefficients are the elementary symmetric functions of those
    roots of ``σ(f)``, the coordinates follow by a linear solve and rational reconstruction, and the candidate is
    accepted only when it divides ``f`` exactly (then it is the minimal polynomial of the root over ``K``, Trager
    (1976), §3).  None when no precision tried gives an exact factor."""
    from fractions import Fraction

    theta = primitive(K)
    for dps in (60, 200, 600):
        with mpmath.workdps(dps):
            if (dps, K) not in _EMBEDDINGS:
                embs = _embeddings(K)
                if len(embs) != base_degree(K):  # pragma: no cover - polyroots returns all roots
                    return None
                _EMBEDDINGS[(dps, K)] = embs, mpmath.inverse(mpmath.matrix([_monomials(K, emb) for emb in embs]))
            embs, Vinv = _EMBEDDINGS[(dps, K)]
            phiv = [mpmath.mpf(int(c.numerator)) / int(c.denominator) for c in phi]
            rhs = []
            for emb in embs:
                t = s * _at(theta, K, emb)
                roots = mpmath.polyroots([_at(c, K, emb) for c in f], maxsteps=500, extraprec=4 * mpmath.mp.prec)
                scale = [sum(abs(c) * abs(z + t) ** (len(phiv) - 1 - i) for i, c in enumerate(phiv)) for z in roots]
                ranked = sorted(
                    zip(roots, scale, strict=True), key=lambda q: abs(mpmath.polyval(phiv, q[0] + t)) / q[1]
                )
                poly = [mpmath.mpf(1)]
                for z, _ in ranked[:e]:
                    poly = [a - z * b for a, b in zip([*poly, 0], [0, *poly], strict=True)]
                rhs.append(poly[1:])
            own = [K.one]
            for k in range(e):
                coords = Vinv * mpmath.matrix([row[k] for row in rhs])
                bound = 10 ** (dps // 3)
                exact = [
                    Fraction(
                        mpmath.nstr(mpmath.re(x), dps, min_fixed=-mpmath.inf, max_fixed=mpmath.inf)
                    ).limit_denominator(bound)
                    for x in coords
                ]
                own.append(_unflatten([QQ(q.numerator, q.denominator) for q in exact], K))
            if not _reduce(f, own, K):
                return own
    return None
