"""Polynomial (λ-) matrices: divisors, Smith form, division, minimal polynomial, pencils (Bulgakov §1.17–1.27).

* determinantal divisors ``D_k`` = monic gcd of the k-th order minors; invariant factors ``E_k = D_k/D_(k-1)``;
  elementary divisors = the prime-power factors ``(λ - a)^e`` of the invariant factors (§1.18);
* the Smith form ``S = U f V`` with unimodular U, V (constant non-zero determinants, §1.19, §1.22);
* left/right division ``g = f S + T`` / ``g = Q f + R`` (§1.21);
* the minimal ("reduced") polynomial ``Δ(λ)/D_(n-1)(λ)`` of a constant matrix (1.221);
* elementary divisors of a regular pencil ``λB - A``, finite and infinite (§1.24).

Entries are polynomials in ``lam`` whose coefficients may contain other symbols (treated as constants).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from functools import reduce
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import as_square_matrix
from .charpoly import adjugate_poly, leverrier

__all__ = [
    "PencilDivisors",
    "SmithForm",
    "determinantal_divisors",
    "elementary_divisors",
    "invariant_factors",
    "minimal_polynomial",
    "pencil_divisors",
    "polymatrix_divmod",
    "smith_form",
]


def _as_poly_matrix(f: Any, lam: sp.Symbol) -> sp.Matrix:
    if not isinstance(lam, sp.Symbol):
        raise ParameterError(f"lam must be a SymPy Symbol, got {lam!r}")
    M = sp.Matrix(f).applyfunc(sp.expand)
    for e in M:
        if not sp.sympify(e).is_polynomial(lam):
            raise ParameterError(f"entry {e} is not a polynomial in {lam}")
    return M


def _monic(e: sp.Expr, lam: sp.Symbol) -> sp.Expr:
    e = sp.expand(e)
    if e == 0:
        return sp.Integer(0)
    p = sp.Poly(e, lam)
    return sp.expand(sp.cancel(p.as_expr() / p.LC()))


def _gcd(exprs: list[sp.Expr], lam: sp.Symbol) -> sp.Expr:
    nz = [sp.expand(e) for e in exprs if sp.expand(e) != 0]
    if not nz:
        return sp.Integer(0)
    return _monic(reduce(sp.gcd, nz), lam)


@validated
def determinantal_divisors(f: Any, lam: sp.Symbol) -> list[sp.Expr]:
    """``[D_1, ..., D_r]``: monic gcd of all k-th order minors, k = 1..rank (Bulgakov §1.17).

    Parameters
    ----------
    f : Matrix or nested list
        Rectangular matrix whose entries must be polynomials in ``lam`` (other symbols are constants).
    lam : Symbol
        The polynomial variable; it must be a SymPy Symbol.

    Returns
    -------
    list of Expr
        The monic divisors ``D_1, ..., D_r`` (r the rank of ``f``), each dividing the next.

    See Also
    --------
    invariant_factors, elementary_divisors, smith_form

    Examples
    --------
    Bulgakov §1.18:

    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> f = sp.Matrix([[l**2 - 2*l + 1, l - 1, l - 1], [l - 1, l**2 - 2*l + 1, l - 1]])
    >>> [sp.factor(d) for d in determinantal_divisors(f, l)]
    [l - 1, (l - 2)*(l - 1)**2]
    """
    M = _as_poly_matrix(f, lam)
    factors = _invariant_factors_exact(M, lam)
    if factors is not None:  # D_k = E_1 ... E_k
        out, d = [], sp.Integer(1)
        for e in factors:
            d = _monic(d * e, lam)
            out.append(d)
        return out
    return _divisors_by_minors(M, lam)


def _invariant_factors_exact(M: sp.Matrix, lam: sp.Symbol) -> list[sp.Expr] | None:
    """The non-zero invariant factors (monic) by SymPy's Smith-form routine over ``K[lam]``, ``K`` the exact field
    of the coefficients (rationals, algebraic numbers, rational functions of other symbols); None when the
    coefficients are not exact (floats: a Euclidean algorithm on them is not reliable)."""
    from sympy.polys.matrices import DomainMatrix
    from sympy.polys.matrices.normalforms import invariant_factors

    polys = [sp.Poly(e, lam) for e in M]
    coeffs = [c for P in polys for c in P.all_coeffs()]
    try:
        K, _ = sp.polys.constructor.construct_domain(coeffs, field=True, extension=True)
    except (NotImplementedError, sp.PolynomialError):  # pragma: no cover - unusual coefficients
        return None
    if not K.is_Exact or not K.is_Field:
        return None
    R = K[lam]
    m, n = M.shape
    rows = [[R.from_sympy(M[i, j]) for j in range(n)] for i in range(m)]
    found = invariant_factors(DomainMatrix(rows, (m, n), R))
    return [_monic(R.to_sympy(e), lam) for e in found if e]


def _divisors_by_minors(M: sp.Matrix, lam: sp.Symbol) -> list[sp.Expr]:
    """The definition: the monic gcd of all k-th order minors (used for inexact coefficients)."""
    m, n = M.shape
    out = []
    for k in range(1, min(m, n) + 1):
        minors = [
            M.extract(list(rows), list(cols)).det(method="berkowitz")
            for rows in itertools.combinations(range(m), k)
            for cols in itertools.combinations(range(n), k)
        ]
        d = _gcd(minors, lam)
        if d == 0:
            break
        out.append(d)
    return out


@validated
def invariant_factors(f: Any, lam: sp.Symbol) -> list[sp.Expr]:
    """``[E_1, ..., E_r]`` with ``E_k = D_k/D_(k-1)``; each divides the next (1.158).

    Parameters
    ----------
    f : Matrix or nested list
        Rectangular matrix whose entries must be polynomials in ``lam`` (other symbols are constants).
    lam : Symbol
        The polynomial variable; it must be a SymPy Symbol.

    Returns
    -------
    list of Expr
        The monic invariant factors ``E_1, ..., E_r`` (r the rank of ``f``), expanded.

    See Also
    --------
    determinantal_divisors, elementary_divisors, smith_form

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> f = sp.Matrix([[l**2 - 2*l + 1, l - 1, l - 1], [l - 1, l**2 - 2*l + 1, l - 1]])
    >>> [sp.factor(e) for e in invariant_factors(f, l)]
    [l - 1, (l - 2)*(l - 1)]
    """
    D = [sp.Integer(1), *determinantal_divisors(f, lam)]
    return [sp.expand(sp.cancel(D[k] / D[k - 1])) for k in range(1, len(D))]


def _prime_powers(poly: sp.Expr, lam: sp.Symbol) -> dict[sp.Expr, int]:
    poly = sp.expand(poly)
    if sp.degree(poly, lam) <= 0:
        return {}
    # roots of linear and quadratic factors; an irreducible factor of higher degree is the key itself (Cardano's and
    # Ferrari's radicals are unreadable and slow to compare) -- the convention of the pencils' rank method
    out: dict[sp.Expr, int] = {}
    for fac, mult in sp.factor_list(poly, lam)[1]:
        if sp.degree(fac, lam) <= 0:
            continue
        found = sp.roots(sp.Poly(fac, lam), cubics=False, quartics=False, quintics=False)
        if sum(found.values()) == sp.degree(fac, lam):
            for root, m in found.items():
                out[root] = out.get(root, 0) + m * mult
        else:
            key = _monic(fac, lam)
            out[key] = out.get(key, 0) + mult
    return out


def _divisors_from_factors(factors: list[sp.Expr], lam: sp.Symbol) -> dict[sp.Expr, list[int]]:
    out: dict[sp.Expr, list[int]] = {}
    for e in factors:
        for root, mult in _prime_powers(e, lam).items():
            out.setdefault(root, []).append(mult)
    return {r: sorted(v) for r, v in out.items()}


@validated
def elementary_divisors(f: Any, lam: sp.Symbol) -> dict[sp.Expr, list[int]]:
    """Elementary divisors as ``{a: [e_1, e_2, ...]}``, meaning ``(λ-a)^e_1, (λ-a)^e_2, ...`` (§1.18).

    Roots of linear and quadratic factors are the keys; an irreducible factor of degree 3 or more is its own key
    (monic), as in :func:`pencil_divisors`.

    Parameters
    ----------
    f : Matrix or nested list
        Rectangular matrix whose entries must be polynomials in ``lam`` (other symbols are constants).
    lam : Symbol
        The polynomial variable; it must be a SymPy Symbol.

    Returns
    -------
    dict
        ``{root (or monic irreducible factor): sorted list of exponents}``.

    See Also
    --------
    invariant_factors, pencil_divisors

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> f = sp.Matrix([[l**2 - 2*l + 1, l - 1, l - 1], [l - 1, l**2 - 2*l + 1, l - 1]])
    >>> elementary_divisors(f, l)
    {1: [1, 1], 2: [1]}
    >>> A = sp.Matrix([[2, 1, 0], [0, 2, 0], [0, 0, 2]])
    >>> elementary_divisors(l * sp.eye(3) - A, l)
    {2: [1, 2]}
    """
    return _divisors_from_factors(invariant_factors(f, lam), lam)


@dataclass(frozen=True)
class SmithForm(SymPyPrintable):
    """``S = U f V`` with S diagonal, each diagonal entry monic and dividing the next, U and V unimodular.

    Attributes
    ----------
    S : Matrix
        The diagonal Smith form ``U f V`` (same shape as ``f``).
    U : Matrix
        Unimodular row transform (square, constant non-zero determinant).
    V : Matrix
        Unimodular column transform (square, constant non-zero determinant).
    invariant_factors : list of Expr
        The non-zero diagonal entries of S.
    """

    S: sp.Matrix
    U: sp.Matrix = field(repr=False)
    V: sp.Matrix = field(repr=False)
    invariant_factors: list[sp.Expr]

    def _repr_latex_(self) -> str:
        return f"$S = {sp.latex(self.S)}$"


def _deg(e: sp.Expr, lam: sp.Symbol) -> float:
    e = sp.expand(e)
    return float("inf") if e == 0 else sp.degree(e, lam)


def _div(a: sp.Expr, b: sp.Expr, lam: sp.Symbol) -> tuple[sp.Expr, sp.Expr]:
    q, r = sp.div(sp.expand(a), sp.expand(b), lam)
    return sp.expand(q), sp.expand(r)


@validated
def smith_form(f: Any, lam: sp.Symbol) -> SmithForm:
    """Smith normal form of a polynomial matrix with the unimodular transforms (Bulgakov §1.19, §1.22).

    Elementary operations over the polynomials in ``lam`` (Euclid's algorithm on the pivot's row and column)
    give ``U f V = S = diag(E_1, ..., E_r, 0, ...)`` with ``det U`` and ``det V`` non-zero constants.

    Parameters
    ----------
    f : Matrix or nested list
        Rectangular matrix whose entries must be polynomials in ``lam`` (other symbols are constants).
    lam : Symbol
        The polynomial variable; it must be a SymPy Symbol.

    Returns
    -------
    SmithForm
        ``S``, ``U``, ``V`` and the invariant factors.

    See Also
    --------
    invariant_factors
    elementary_divisors
    determinantal_divisors

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> sf = smith_form(sp.Matrix([[l - 1, 0], [0, l - 2]]), l)
    >>> sf.S
    Matrix([
    [1,              0],
    [0, l**2 - 3*l + 2]])
    >>> (sf.U * sp.Matrix([[l - 1, 0], [0, l - 2]]) * sf.V).applyfunc(sp.expand) == sf.S
    True
    """
    M = _as_poly_matrix(f, lam)
    m, n = M.shape
    S, U, V = M.copy(), sp.eye(m), sp.eye(n)
    for k in range(min(m, n)):
        while True:
            cands = [(_deg(S[i, j], lam), i, j) for i in range(k, m) for j in range(k, n) if sp.expand(S[i, j]) != 0]
            if not cands:
                break
            _, i0, j0 = min(cands, key=lambda c: (c[0], c[1], c[2]))
            if i0 != k:
                S.row_swap(k, i0)
                U.row_swap(k, i0)
            if j0 != k:
                S.col_swap(k, j0)
                V.col_swap(k, j0)
            piv = S[k, k]
            dirty = False
            for i in range(k + 1, m):
                q, r = _div(S[i, k], piv, lam)
                if q != 0:
                    S[i, :] = (S[i, :] - q * S[k, :]).applyfunc(sp.expand)
                    U[i, :] = (U[i, :] - q * U[k, :]).applyfunc(sp.expand)
                dirty |= r != 0
            for j in range(k + 1, n):
                q, r = _div(S[k, j], piv, lam)
                if q != 0:
                    S[:, j] = (S[:, j] - q * S[:, k]).applyfunc(sp.expand)
                    V[:, j] = (V[:, j] - q * V[:, k]).applyfunc(sp.expand)
                dirty |= r != 0
            if dirty:
                continue
            bad = next((i for i in range(k + 1, m) for j in range(k + 1, n) if _div(S[i, j], piv, lam)[1] != 0), None)
            if bad is None:
                break
            S[k, :] = (S[k, :] + S[bad, :]).applyfunc(sp.expand)
            U[k, :] = (U[k, :] + U[bad, :]).applyfunc(sp.expand)
        if k < m and k < n and sp.expand(S[k, k]) != 0:
            lc = sp.Poly(S[k, k], lam).LC()
            if lc != 1:
                S[k, :] = (S[k, :] / lc).applyfunc(lambda e: sp.expand(sp.cancel(e)))
                U[k, :] = (U[k, :] / lc).applyfunc(lambda e: sp.expand(sp.cancel(e)))
    inv = [S[i, i] for i in range(min(m, n)) if S[i, i] != 0]
    return SmithForm(S=S, U=U, V=V, invariant_factors=inv)


@validated
def minimal_polynomial(A: Any, lam: sp.Symbol) -> sp.Expr:
    """Minimal (reduced) polynomial ``Δ(λ)/D_(n-1)(λ)`` of a constant matrix (Bulgakov 1.221).

    ``D_(n-1)`` is the gcd of the entries of the adjugate ``F(λ) = adj(λE - A)`` (computed by (1.219)).

    Parameters
    ----------
    A : Matrix, nested list or ndarray
        Square, non-empty constant matrix (exact or symbolic entries, no ``lam`` in them).
    lam : Symbol
        The polynomial variable; it must be a SymPy Symbol.

    Returns
    -------
    Expr
        The monic minimal polynomial in ``lam``, expanded.

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> sp.factor(minimal_polynomial(sp.Matrix([[2, 0, 0], [0, 2, 0], [1, 1, 3]]), l))
    (l - 3)*(l - 2)
    """
    A = as_square_matrix(A)
    delta = leverrier(A, lam).as_expr()
    if A.rows == 1:
        return sp.expand(delta)
    d = _gcd(list(adjugate_poly(A, lam)), lam)
    return sp.expand(sp.cancel(delta / d))


def _poly_part(e: sp.Expr, lam: sp.Symbol) -> sp.Expr:
    num, den = sp.fraction(sp.cancel(sp.together(e)))
    return _div(num, den, lam)[0]


@validated
def polymatrix_divmod(f: Any, g: Any, lam: sp.Symbol, side: str = "left") -> tuple[sp.Matrix, sp.Matrix]:
    """Division of polynomial matrices (Bulgakov §1.21).

    ``side="left"``: ``g = f S + T`` with ``f^-1 T`` strictly proper (S = polynomial part of ``f^-1 g``, 1.168–1.171);
    ``side="right"``: ``g = S f + T`` with ``T f^-1`` strictly proper (1.172).  When the leading coefficient of f is
    non-singular this is ordinary long division and ``deg T < deg f``.

    Parameters
    ----------
    f : Matrix or nested list
        The divisor: a square polynomial matrix in ``lam`` with ``det f`` not identically zero.
    g : Matrix or nested list
        The dividend: a polynomial matrix in ``lam`` with as many rows as ``f`` (``side="left"``) or as many
        columns (``side="right"``).
    lam : Symbol
        The polynomial variable; it must be a SymPy Symbol.
    side : {"left", "right"}
        Which division: ``"left"`` gives ``g = f S + T``, ``"right"`` gives ``g = S f + T``.

    Returns
    -------
    (S, T) : tuple of Matrix
        Quotient and remainder.

    Examples
    --------
    Bulgakov §1.21, Ex. 5:

    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> f = sp.Matrix([[2*l - 2, l + 2], [3*l - 1, l]])
    >>> g = sp.Matrix([[l**2 + 1, l], [3, 1]])
    >>> S, T = polymatrix_divmod(f, g, l)
    >>> S, T
    (Matrix([
    [   7 - l, -1],
    [3*l - 22,  3]]), Matrix([
    [59, -8],
    [10,  0]]))
    """
    F = _as_poly_matrix(f, lam)
    G = _as_poly_matrix(g, lam)
    if F.rows != F.cols:
        raise ModelError(f"the divisor f must be square, got {F.rows}x{F.cols}")
    det = sp.expand(F.det(method="berkowitz"))
    if det == 0:
        raise ModelError("the divisor f is singular (det f ≡ 0); division is not defined")
    adj = F.adjugate(method="berkowitz")
    if side == "left":
        if G.rows != F.rows:
            raise ModelError(f"left division needs g with {F.rows} rows, got {G.rows}")
        Q = (adj * G).applyfunc(lambda e: _poly_part(e / det, lam))
        R = (G - F * Q).applyfunc(sp.expand)
    elif side == "right":
        if G.cols != F.cols:
            raise ModelError(f"right division needs g with {F.cols} columns, got {G.cols}")
        Q = (G * adj).applyfunc(lambda e: _poly_part(e / det, lam))
        R = (G - Q * F).applyfunc(sp.expand)
    else:
        raise ParameterError(f"side must be 'left' or 'right', got {side!r}")
    return Q, R


@dataclass(frozen=True)
class PencilDivisors(SymPyPrintable):
    """Elementary divisors of a regular pencil ``λB - A``: finite ``{a: [e...]}`` and infinite ``[e...]``.

    Attributes
    ----------
    finite : dict
        ``{root a: sorted exponents [e...]}``, meaning the finite divisors ``(λ - a)^e``.
    infinite : list of int
        Exponents ``e`` of the infinite divisors ``μ^e`` (those of ``B - μA`` at μ = 0).
    determinant : Expr
        ``det(λB - A)``, expanded (not identically zero: the pencil is regular).
    """

    finite: dict
    infinite: list[int]
    determinant: sp.Expr


@validated
def pencil_divisors(A: Any, B: Any, lam: sp.Symbol) -> PencilDivisors:
    """Finite and infinite elementary divisors of the regular pencil ``λB - A`` (Bulgakov §1.24).

    Two regular pencils are strictly equivalent (``u(λB - A)v = λB1 - A1`` with constant u, v) iff these agree.
    The infinite divisors are the divisors ``μ^e`` at μ = 0 of the reversed pencil ``B - μA``.

    Parameters
    ----------
    A : Matrix, nested list or ndarray
        Square constant term of the pencil ``λB - A``.
    B : Matrix, nested list or ndarray
        Square coefficient of ``λ``, of the same shape as ``A``; ``det(λB - A)`` must not vanish identically.
    lam : Symbol
        The pencil's variable λ; it must be a SymPy Symbol.

    Returns
    -------
    PencilDivisors
        Finite and infinite elementary divisors and ``det(λB - A)``.

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> pd = pencil_divisors(sp.Matrix([[1, 0], [0, 1]]), sp.Matrix([[1, 0], [0, 0]]), l)
    >>> pd.finite, pd.infinite
    ({1: [1]}, [1])
    """
    A = as_square_matrix(A, "A")
    B = as_square_matrix(B, "B")
    if A.shape != B.shape:
        raise ModelError(f"A and B must have the same shape, got {A.shape} and {B.shape}")
    P = (lam * B - A).applyfunc(sp.expand)
    det = sp.expand(P.det(method="berkowitz"))
    if det == 0:
        raise ModelError(
            "singular pencil: det(λB - A) ≡ 0; its Kronecker minimal indices are not implemented (only regular pencils)"
        )
    if any(e.has(sp.Float) for e in (*A, *B)):  # inexact entries: the gcds of the minors (the definition)
        finite = elementary_divisors(P, lam)
        mu = sp.Dummy("mu")
        rev = (B - mu * A).applyfunc(sp.expand)
        infinite = elementary_divisors(rev, mu).get(sp.Integer(0), [])
        return PencilDivisors(finite=finite, infinite=infinite, determinant=det)
    # exact entries: ranks of powers of one matrix (Weyr's characteristic), the same procedure that decides strict
    # equivalence in symosc.algebra.pencil_equivalence -- no minors, no roots needed
    from .pencils import regular_pencil_divisors

    finite, infinite = regular_pencil_divisors(B, -A, "λB - A")
    own = sp.Symbol("lambda")  # the variable of the irreducible-factor keys there
    finite = {k.xreplace({own: lam}) if k.has(own) else k: v for k, v in finite.items()}
    return PencilDivisors(finite=finite, infinite=infinite, determinant=det)
