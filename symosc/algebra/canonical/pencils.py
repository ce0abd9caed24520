"""Strict equivalence and the canonical (Weierstrass) form of regular linear pencils (Bulgakov §1.24).

Two pencils ``a λ + b`` and ``a1 λ + b1`` with constant square coefficients are strictly equivalent when constant
non-singular ``u``, ``v`` give ``u (a λ + b) v = a1 λ + b1``, i.e. ``u a v = a1`` and ``u b v = b1`` (1.187).  For
regular pencils (``det(a λ + b)`` not identically zero) this holds iff the finite and the infinite elementary
divisors agree (Bulgakov (1954), §1.24, for non-singular ``a``; Gantmacher (1959), ch. XII, for the general
regular case).  The canonical form is ``diag(E λ - J, N λ + E)``: ``u a v = diag(E, N)`` and
``u b v = diag(-J, E)`` with ``J`` in Jordan form (1.191) — or, with ``real=True``, in Cayley's real form ``Q``
(1.192) — and ``N`` nilpotent (one Jordan block at zero per infinite elementary divisor).

Everything is exact.  ``u`` and ``v`` come from the linear equations ``u a = a1 w``, ``u b = b1 w`` (``w = v⁻¹``):
their solutions form a vector space, and a random integer combination of a basis is non-singular unless the
pencils are not equivalent, so no eigenvector is ever computed.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Any

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import as_square_matrix

__all__ = ["PencilCanonicalForm", "PencilEquivalence", "pencil_canonical_form", "pencil_equivalence"]

_MU = sp.Dummy("mu")


@dataclass(frozen=True)
class PencilEquivalence(SymPyPrintable):
    """Verdict of :func:`pencil_equivalence`.

    Attributes
    ----------
    equivalent : bool
        True when constant non-singular ``u``, ``v`` with ``u (a λ + b) v = a1 λ + b1`` exist (also ``bool(result)``).
    u, v : Matrix or None
        The transforming matrices (exact), ``None`` when not equivalent.
    divisors, divisors1 : tuple
        ``(finite, infinite)`` elementary divisors of the two pencils: ``finite`` maps a root ``r`` to the exponents
        of ``(λ - r)^e``, ``infinite`` lists the exponents of the infinite elementary divisors.
    reason : str
        Why the pencils are (not) equivalent, in words.
    """

    equivalent: bool
    u: sp.Matrix | None
    v: sp.Matrix | None
    divisors: tuple
    divisors1: tuple
    reason: str

    def __bool__(self) -> bool:
        return self.equivalent

    def __repr__(self) -> str:
        return f"PencilEquivalence(equivalent={self.equivalent}, reason={self.reason!r})"

    def _repr_latex_(self) -> str:
        if not self.equivalent:
            return rf"$\text{{not equivalent: {self.reason}}}$"
        return rf"$u = {sp.latex(self.u)},\quad v = {sp.latex(self.v)}$"


@dataclass(frozen=True)
class PencilCanonicalForm(SymPyPrintable):
    """Canonical form of a regular pencil ``a λ + b`` (Bulgakov (1954), §1.24, eqs. (1.188)–(1.192)).

    Attributes
    ----------
    a, b : Matrix
        The canonical coefficients ``u a v = diag(E, N)`` and ``u b v = diag(-J, E)``.
    u, v : Matrix
        Constant non-singular transforming matrices.
    J : Matrix
        Jordan form (or Cayley's real form, ``real=True``) of the finite part.
    N : Matrix
        Nilpotent part, one Jordan block at zero per infinite elementary divisor (empty when ``a`` is non-singular).
    finite : dict
        ``{root: [exponents]}`` of the finite elementary divisors ``(λ - root)^e``.
    infinite : list of int
        Exponents of the infinite elementary divisors.
    """

    a: sp.Matrix
    b: sp.Matrix
    u: sp.Matrix
    v: sp.Matrix
    J: sp.Matrix
    N: sp.Matrix
    finite: dict
    infinite: list

    def __repr__(self) -> str:
        return f"PencilCanonicalForm(finite={self.finite}, infinite={self.infinite}, size={self.a.rows})"

    def _repr_latex_(self) -> str:
        lam = sp.Symbol("lambda")
        return rf"$u (a\lambda + b) v = {sp.latex(self.a * lam + self.b)}$"


def _exact_pair(a: Any, b: Any, names: tuple[str, str]) -> tuple[sp.Matrix, sp.Matrix]:
    A = as_square_matrix(a, names[0])
    B = as_square_matrix(b, names[1])
    if A.shape != B.shape:
        raise ModelError(f"{names[0]} and {names[1]} must have the same shape, got {A.shape} and {B.shape}")
    for name, M in zip(names, (A, B), strict=True):
        if M.free_symbols:
            raise ParameterError(
                f"{name} must have numeric entries (free symbols {sorted(map(str, M.free_symbols))}); substitute "
                "numbers first — the elementary divisors of a pencil change with its parameters"
            )
        if any(e.has(sp.Float) for e in M):
            raise ParameterError(
                f"{name} has floating-point entries; strict equivalence is decided exactly (the elementary divisors "
                "are not continuous in the entries): pass exact numbers, e.g. sympy.nsimplify(M, rational=True)"
            )
        if any(e.has(sp.nan, sp.zoo, sp.oo, -sp.oo) for e in M):
            raise ParameterError(f"{name} has an infinite or undefined entry")
    return A, B


def regular_pencil_divisors(a: sp.Matrix, b: sp.Matrix, which: str) -> tuple[dict, list[int]]:
    """Finite and infinite elementary divisors of the regular pencil ``a λ + b``, by exact ranks.

    With ``a c + b`` non-singular, ``a λ + b = (a c + b)(E + (λ - c) K)``, ``K = (a c + b)⁻¹ a``; the Möbius map
    ``μ = -1/(λ - c)`` sends the elementary divisors of the pencil at ``λ`` to the Jordan blocks of ``K`` at ``μ``
    (the infinite ones to ``μ = 0``).  For each irreducible factor ``p`` of the characteristic polynomial of ``K``
    the block sizes follow from the ranks of ``p(K)^k`` (Weyr's characteristic), so no root is needed to decide.
    """
    n = a.rows
    c = None
    for cand in range(n + 1):
        for s in (cand, -cand) if cand else (0,):
            if (a * s + b).det(method="bareiss") != 0:
                c = s
                break
        if c is not None:
            break
    if c is None:  # det(a λ + b) vanishes at n + 1 points: identically zero
        raise ModelError(
            f"the pencil {which} is singular: det(a λ + b) ≡ 0; strict equivalence of singular pencils needs the "
            "Kronecker minimal indices, which are not implemented (only regular pencils)"
        )
    base = DomainMatrix.from_Matrix(sp.Matrix.hstack(a * c + b, a), extension=True).to_field()
    dom = base.domain
    shifted, lead = base[:, :n], base[:, n:]
    K = shifted.inv() * lead
    poly = sp.Poly(K.charpoly(), _MU, domain=dom)
    lam = sp.Symbol("lambda")
    finite: dict = {}
    infinite: list[int] = []
    eye = DomainMatrix.eye(n, dom)
    for factor, mult in poly.factor_list()[1]:
        coeffs = factor.all_coeffs()
        pK = DomainMatrix.zeros((n, n), dom)
        for co in coeffs:  # Horner: p(K)
            pK = pK * K + eye * dom.convert(co)
        d = factor.degree()
        ranks, power = [n], eye
        for _ in range(mult):
            power = power * pK
            ranks.append(power.rank())
        at_least = [(ranks[k - 1] - ranks[k]) // d for k in range(1, mult + 1)]  # blocks of size >= k
        sizes = sorted(k for k in range(1, mult + 1) for _ in range(at_least[k - 1] - (at_least[k] if k < mult else 0)))
        if factor.degree() == 1 and factor.eval(0) == 0:
            infinite = sizes
            continue
        # the same factor in λ: p(-1/(λ - c)) (λ - c)^d, monic
        expr = sp.expand(sp.cancel(factor.as_expr().subs(_MU, -1 / (lam - c)) * (lam - c) ** d))
        q = sp.Poly(expr, lam)
        roots = sp.roots(q, cubics=False, quartics=False, quintics=False)
        if sum(roots.values()) == q.degree():
            for r in roots:
                r = sp.radsimp(sp.expand(r))
                finite[r] = sorted(finite.get(r, []) + sizes)
        else:
            key = q.monic().as_expr()
            finite[key] = sorted(finite.get(key, []) + sizes)
    return finite, sorted(infinite)


def _same_divisors(fin0: dict, fin1: dict) -> bool:
    """Equal finite divisors: keys matched exactly, or (roots written differently) by value to 30 digits."""
    if len(fin0) != len(fin1):
        return False
    unmatched = dict(fin1)
    for r, sizes in fin0.items():
        if r in unmatched:
            match = r
        else:
            match = next(
                (
                    k
                    for k in unmatched
                    if not k.has(sp.Symbol("lambda"))
                    and not r.has(sp.Symbol("lambda"))
                    and abs(complex(sp.N(k - r, 30))) < 1e-25
                ),
                None,
            )
        if match is None or unmatched.pop(match) != sizes:
            return False
    return True


def _format(finite: dict, infinite: list[int]) -> str:
    lam = sp.Symbol("λ")
    names = {r: r.subs(sp.Symbol("lambda"), lam) if r.has(sp.Symbol("lambda")) else lam - r for r in finite}
    parts = [f"({names[r]})^{e}" if e > 1 else f"({names[r]})" for r, es in finite.items() for e in es]
    parts += [f"∞^{e}" for e in infinite]
    return ", ".join(parts) if parts else "none"


def _vec_kron(M: sp.Matrix, left: bool, n: int) -> sp.Matrix:
    """Matrix of ``X -> X M`` (left=False) or ``X -> M X`` (left=True) acting on the row-major ``vec(X)``."""
    E = sp.eye(n)
    return sp.kronecker_product(M, E) if left else sp.kronecker_product(E, M.T)


def _transformation(
    a: sp.Matrix, b: sp.Matrix, a1: sp.Matrix, b1: sp.Matrix, attempts: int = 40
) -> tuple[sp.Matrix, sp.Matrix] | None:
    """Constant non-singular ``u``, ``v`` with ``u a v = a1`` and ``u b v = b1``, or None when none exists."""
    n = a.rows
    # unknowns (vec u, vec w), w = v^-1:  u a - a1 w = 0,  u b - b1 w = 0
    top = sp.Matrix.hstack(_vec_kron(a, False, n), -_vec_kron(a1, True, n))
    bottom = sp.Matrix.hstack(_vec_kron(b, False, n), -_vec_kron(b1, True, n))
    system = DomainMatrix.from_Matrix(sp.Matrix.vstack(top, bottom), extension=True).to_field()
    K = system.domain
    basis = system.nullspace()
    d = basis.shape[0]
    if d == 0:
        return None
    rows = [basis[i, :] for i in range(d)]
    rng = random.Random(20261124)
    for attempt in range(attempts if d > 1 else 1):
        span = 3 * (1 + attempt // 4)
        coeffs = [1] if d == 1 else [rng.randint(-span, span) for _ in range(d)]
        x = rows[0] * K.convert(coeffs[0])
        for c, r in zip(coeffs[1:], rows[1:], strict=True):
            x = x + r * K.convert(c)
        flat = x.to_Matrix()
        u = DomainMatrix.from_Matrix(sp.Matrix(n, n, list(flat[: n * n]))).convert_to(K)
        w = DomainMatrix.from_Matrix(sp.Matrix(n, n, list(flat[n * n :]))).convert_to(K)
        if u.det() != K.zero and w.det() != K.zero:
            return u.to_Matrix(), w.inv().to_Matrix()
    return None


@validated
def pencil_equivalence(a: Any, b: Any, a1: Any, b1: Any) -> PencilEquivalence:
    """Decide strict equivalence ``u (a λ + b) v = a1 λ + b1`` of two regular pencils, exactly (Bulgakov (1954), §1.24).

    With constant non-singular ``u``, ``v`` this means ``u a v = a1`` and ``u b v = b1`` (1.187).  Regular pencils
    are strictly equivalent iff their finite and infinite elementary divisors coincide (§1.24 for non-singular
    ``a``; Gantmacher (1959), ch. XII, §2 for a singular ``a``: the infinite divisors are those of ``a + μ b`` at
    μ = 0).

    Parameters
    ----------
    a, b, a1, b1 : Matrix
        Square matrices of one size with exact numeric entries (integers, rationals, algebraic numbers such as
        ``sqrt(2)`` or ``I``); ``a`` may be singular as long as the pencil is regular.

    Returns
    -------
    PencilEquivalence
        ``equivalent``, the exact ``u`` and ``v`` (verified by multiplication), both pencils' elementary
        divisors and a ``reason``; ``bool(result)`` is ``equivalent``.

    Raises
    ------
    ParameterError
        Symbolic or floating-point entries (the answer is not continuous in the entries).
    ModelError
        A singular pencil (``det(a λ + b) ≡ 0``): Kronecker's minimal indices are not implemented.

    See Also
    --------
    pencil_canonical_form, pencil_divisors, elementary_divisors, smith_form

    Examples
    --------
    A Jordan block and a diagonal matrix with the same eigenvalues are not equivalent:

    >>> import sympy as sp
    >>> E = sp.eye(2)
    >>> res = pencil_equivalence(E, -sp.Matrix([[2, 1], [0, 2]]), E, -sp.Matrix([[2, 0], [0, 2]]))
    >>> res.equivalent
    False
    >>> res.reason
    'the elementary divisors differ: (λ - 2)^2 against (λ - 2), (λ - 2)'

    A pencil and its transform by integer matrices are:

    >>> a, b = sp.Matrix([[1, 2], [0, 1]]), sp.Matrix([[0, 1], [-2, 3]])
    >>> p, q = sp.Matrix([[1, 1], [1, 2]]), sp.Matrix([[2, 1], [1, 1]])
    >>> res = pencil_equivalence(a, b, p * a * q, p * b * q)
    >>> bool(res), res.u * a * res.v == p * a * q, res.u * b * res.v == p * b * q
    (True, True, True)
    """
    A, B = _exact_pair(a, b, ("a", "b"))
    A1, B1 = _exact_pair(a1, b1, ("a1", "b1"))
    if A.shape != A1.shape:
        raise ModelError(f"the two pencils must have the same size, got {A.shape} and {A1.shape}")
    fin0, inf0 = regular_pencil_divisors(A, B, "a λ + b")
    fin1, inf1 = regular_pencil_divisors(A1, B1, "a1 λ + b1")
    divisors, divisors1 = (fin0, inf0), (fin1, inf1)
    same_finite = _same_divisors(fin0, fin1)
    if not same_finite or inf0 != inf1:
        reason = f"the elementary divisors differ: {_format(fin0, inf0)} against {_format(fin1, inf1)}"
        return PencilEquivalence(False, None, None, divisors, divisors1, reason)
    found = _transformation(A, B, A1, B1)
    if found is None:  # pragma: no cover - equal divisors guarantee a solution (Gantmacher, ch. XII)
        raise ModelError("equal elementary divisors but no non-singular u, v was found; please report this pencil")
    u, v = found
    residual = sp.Matrix.vstack(u * A * v - A1, u * B * v - B1).applyfunc(lambda e: sp.nsimplify(sp.expand(e)))
    if residual.is_zero_matrix is not True:  # pragma: no cover - the linear equations are solved exactly
        raise ModelError("the computed u, v fail the exact check u a v = a1, u b v = b1; please report this pencil")
    reason = f"same elementary divisors: {_format(fin0, inf0)}"
    return PencilEquivalence(True, u, v, divisors, divisors1, reason)


def _root_key(r: sp.Expr) -> tuple:
    z = complex(sp.N(r, 30))
    return (round(z.real, 12), round(z.imag, 12), sp.default_sort_key(r))


def _jordan_block(root: sp.Expr, size: int) -> sp.Matrix:
    return sp.Matrix(size, size, lambda i, j: root if i == j else (1 if j == i + 1 else 0))


def _real_block(root: sp.Expr, size: int) -> sp.Matrix:
    e, w = sp.re(root), sp.im(root)
    C = sp.Matrix([[e, w], [-w, e]])
    M = sp.zeros(2 * size, 2 * size)
    for i in range(size):
        M[2 * i : 2 * i + 2, 2 * i : 2 * i + 2] = C
        if i + 1 < size:
            M[2 * i : 2 * i + 2, 2 * i + 2 : 2 * i + 4] = sp.eye(2)
    return M


def _finite_part(finite: dict, real: bool) -> sp.Matrix:
    blocks: list[sp.Matrix] = []
    for root in sorted(finite, key=_root_key):
        im = sp.im(root)
        if not real or im == 0:
            blocks += [_jordan_block(root, e) for e in finite[root]]
        elif im.is_positive:
            blocks += [_real_block(root, e) for e in finite[root]]
    return sp.diag(*blocks) if blocks else sp.zeros(0, 0)


@validated
def pencil_canonical_form(a: Any, b: Any, *, real: bool = False) -> PencilCanonicalForm:
    """Weierstrass canonical form ``u (a λ + b) v = diag(E λ - J, N λ + E)`` of a regular pencil, exactly.

    For non-singular ``a`` this is Bulgakov (1954), §1.24, eq. (1.191): ``u a v = E``, ``u b v = -J`` with ``J``
    the Jordan form built from the elementary divisors; with ``real=True`` and real ``a``, ``b`` it is (1.192):
    real ``u``, ``v`` and Cayley's real form ``Q`` (blocks ``[[e, ω], [-ω, e]]`` for ``e ± iω``, with ``E`` on the
    block superdiagonal for a non-linear divisor) in place of ``J``.  A singular ``a`` of a regular pencil adds
    the infinite elementary divisors as the nilpotent ``N`` (Gantmacher (1959), ch. XII, §2): ``u a v = diag(E, N)``,
    ``u b v = diag(-J, E)``.

    Parameters
    ----------
    a, b : Matrix
        Square, exact numeric entries.
    real : bool
        Real canonical form (1.192); needs real ``a``, ``b``.

    Returns
    -------
    PencilCanonicalForm
        ``a``, ``b`` (canonical coefficients), ``u``, ``v``, ``J``, ``N`` and the elementary divisors.

    Raises
    ------
    ParameterError
        Symbolic or floating-point entries, complex entries with ``real=True``.
    ModelError
        A singular pencil, or an elementary divisor whose root has no expression in radicals of degree ≤ 2 (use
        :func:`pencil_equivalence`, which works without roots).

    See Also
    --------
    pencil_equivalence, pencil_divisors, cayley_real_form

    Examples
    --------
    >>> import sympy as sp
    >>> a, b = sp.Matrix([[1, 1], [0, 1]]), sp.Matrix([[-1, -2], [0, -1]])
    >>> cf = pencil_canonical_form(a, b)
    >>> cf.J
    Matrix([
    [1, 1],
    [0, 1]])
    >>> cf.u * a * cf.v, cf.u * b * cf.v
    (Matrix([
    [1, 0],
    [0, 1]]), Matrix([
    [-1, -1],
    [ 0, -1]]))

    A singular leading coefficient gives an infinite elementary divisor:

    >>> cf = pencil_canonical_form(sp.Matrix([[1, 0], [0, 0]]), sp.Matrix([[-5, 0], [0, 1]]))
    >>> cf.finite, cf.infinite
    ({5: [1]}, [1])
    """
    if not isinstance(real, bool):
        raise ParameterError(f"real must be True or False, got {real!r}")
    A, B = _exact_pair(a, b, ("a", "b"))
    if real and any(sp.im(e) != 0 for e in (*A, *B)):
        raise ParameterError("real=True needs real a and b (Bulgakov (1954), eq. (1.192)); got complex entries")
    finite, infinite = regular_pencil_divisors(A, B, "a λ + b")
    lam = sp.Symbol("lambda")
    for root in finite:
        if root.has(lam):
            raise ModelError(
                f"the elementary divisor with factor {root} is irreducible of degree ≥ 3 (its roots have no "
                "practical closed form); use pencil_equivalence to compare pencils without roots"
            )
    J = _finite_part(finite, real)
    N = sp.diag(*[_jordan_block(sp.Integer(0), e) for e in infinite]) if infinite else sp.zeros(0, 0)
    ca = sp.diag(sp.eye(J.rows), N) if N.rows else sp.eye(J.rows)
    cb = sp.diag(-J, sp.eye(N.rows)) if N.rows else -J
    res = pencil_equivalence(A, B, ca, cb)
    if not res.equivalent:  # pragma: no cover - the canonical pair is built from the same divisors
        raise ModelError(f"canonical form construction failed: {res.reason}")
    return PencilCanonicalForm(ca, cb, res.u, res.v, J, N, finite, infinite)
