"""Modal matrices from the adjugate (Bulgakov §1.26, §1.37) and Luzin's triangular canonical form (§1.22).

* :func:`modal_matrix` / :func:`pencil_modal_matrix` — right and left modal columns/rows ``V``, ``W`` taken from the
  adjugate ``F(l) = adj f(l)`` of the pencil at its characteristic roots, normalised as in the book:
  ``W a V = diag((q - 1)! D_sig(l_sig) E_q)`` (1.311–1.316).
* :func:`luzin_form` — the unique monic upper-triangular form of a polynomial matrix under row operations (1.176),
  with the unimodular transform.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError
from .._util import as_square_matrix, is_float_matrix
from .polynomial_matrices import _as_poly_matrix, _deg, _div

__all__ = ["ModalMatrix", "TriangularForm", "luzin_form", "modal_matrix", "pencil_modal_matrix"]


@dataclass(frozen=True)
class ModalMatrix(SymPyPrintable):
    """Result of :func:`modal_matrix` / :func:`pencil_modal_matrix`; unpacks as ``V, W = result``.

    Attributes
    ----------
    V : Matrix
        Right modal matrix: column ``k`` solves ``f(l_k) v = 0`` (for ``E l - A``: ``A V = V diag(l)``).
    W : Matrix
        Left modal matrix: row ``k`` solves ``w f(l_k) = 0``.
    eigenvalues : tuple
        ``l_k`` for each column, a root of multiplicity ``q`` repeated ``q`` times.
    roots : tuple of (root, multiplicity)
        The distinct characteristic roots.
    norms : Matrix
        ``W a V`` (``W V`` for ``E l - A``): block diagonal with blocks ``(q - 1)! D_sig(l_sig) E_q`` (1.312–1.316),
        ``D_sig = Delta/(l - l_sig)**q``; for simple roots ``diag(Delta'(l_k))`` (1.315).
    lead : Matrix
        ``a`` of the pencil ``a l + b`` (the identity for :func:`modal_matrix`).
    """

    V: sp.Matrix
    W: sp.Matrix
    eigenvalues: tuple
    roots: tuple
    norms: sp.Matrix
    lead: sp.Matrix

    def __iter__(self):
        return iter((self.V, self.W))

    @property
    def Lambda(self) -> sp.Matrix:
        """``diag(l_1, ..., l_n)``."""
        return sp.diag(*self.eigenvalues)

    @property
    def inverse(self) -> sp.Matrix:
        """``V**-1 = norms**-1 W a`` (from ``W a V = norms``)."""
        return (self.norms.inv() * self.W * self.lead).applyfunc(sp.simplify)

    def __repr__(self) -> str:
        return f"ModalMatrix(eigenvalues={list(self.eigenvalues)}, V={self.V.tolist()})"

    def _repr_latex_(self) -> str:
        return f"$$V = {sp.latex(self.V)},\\quad W = {sp.latex(self.W)}$$"


def _tidy(e: sp.Expr, floats: bool) -> sp.Expr:
    if floats or e.has(sp.CRootOf):
        return sp.expand(e)
    e = sp.radsimp(sp.expand(e))
    return sp.simplify(e) if e.free_symbols or e.has(sp.Pow) else e


def _distinct_roots(delta: sp.Poly, floats: bool) -> list[tuple[sp.Expr, int]]:
    n = delta.degree()
    if floats:
        found = {}
        try:
            roots = delta.nroots(n=17, maxsteps=200)
        except mpmath.libmp.NoConvergence as exc:  # mpmath's polyroots need not converge on a multiple root
            raise ModelError(
                "the characteristic roots of the floating-point matrix did not converge (a multiple root): the modal "
                "columns are ill-determined; give exact (Rational) entries or use spectral_decomposition"
            ) from exc
        for r in roots:
            found[r] = found.get(r, 0) + 1
    elif delta.free_symbols - set(delta.gens):
        found = sp.roots(delta, multiple=False)
        if sum(found.values()) != n:
            raise ModelError(
                f"the characteristic polynomial {delta.as_expr()} has no roots in closed form; substitute numbers"
            )
    else:  # exact numbers: radicals up to degree 2, CRootOf beyond (Cardano's radicals simplify very slowly)
        found = {}
        for fac, mult in delta.factor_list()[1]:
            rts = sp.roots(fac, multiple=True) if fac.degree() <= 2 else fac.all_roots()
            for r in rts:
                found[r] = found.get(r, 0) + mult
    out = list(found.items())
    try:
        out.sort(key=lambda rm: (float(sp.re(sp.N(rm[0]))), float(sp.im(sp.N(rm[0])))))
    except TypeError:
        out.sort(key=lambda rm: sp.default_sort_key(rm[0]))
    if floats and len(out) > 1:
        vals = [complex(sp.N(r)) for r, _ in out]
        scale = max(1.0, max(abs(v) for v in vals))
        gap = min(abs(vals[i] - vals[j]) for i in range(len(vals)) for j in range(i))
        if gap < 1e-6 * scale:
            raise ModelError(
                f"characteristic roots closer than {gap:.1e} (relative to {scale:.1e}) in a floating-point matrix: "
                "the modal columns are ill-determined; give exact (Rational) entries or use spectral_decomposition"
            )
    return out


def _factor_rank_one(G: sp.Matrix, floats: bool) -> tuple[sp.Matrix, sp.Matrix]:
    """``G = V W`` for a rank-one ``G``: ``V`` a non-zero column of ``G``, ``W`` a row of ``G`` scaled to 1 there."""
    cells = [(i, j) for j in range(G.cols) for i in range(G.rows)]  # first non-zero column, as in the book
    if floats:
        i, j = max(cells, key=lambda ij: abs(complex(G[ij])))  # partial pivoting
    elif not G.free_symbols:
        mags = {ij: abs(complex(sp.N(G[ij], 30))) for ij in cells}
        big = max(mags.values())
        i, j = next(ij for ij in cells if mags[ij] > 1e-20 * big)
    else:
        i, j = next((ij for ij in cells if not G[ij].is_zero), (None, None))
        if i is None:
            raise ModelError("the adjugate vanishes at a simple root (this cannot happen for an exact pencil)")
    return G[:, j], (G[i, :] / G[i, j]).applyfunc(lambda e: _tidy(e, floats))


def _modal(a: sp.Matrix, b: sp.Matrix, lam: sp.Symbol) -> ModalMatrix:
    n = a.rows
    floats = is_float_matrix(a) or is_float_matrix(b)
    pencil = a * lam + b
    delta = sp.Poly(sp.expand(pencil.det(method="berkowitz")), lam)
    if delta.is_zero:
        raise ModelError("det(a l + b) vanishes identically: a singular pencil has no modal matrix")
    if delta.degree() < n:
        raise ModelError(
            f"det(a l + b) has degree {delta.degree()} < {n}: the leading matrix a is singular (infinite roots); "
            "a modal matrix needs a nonsingular a"
        )
    adj = pencil.adjugate(method="berkowitz").applyfunc(sp.expand)
    cols, rows, eigs, blocks = [], [], [], []
    roots = _distinct_roots(delta, floats)
    for root, q in roots:
        G = sp.diff(adj, lam, q - 1).subs(lam, root).applyfunc(lambda e: _tidy(e, floats))
        if q == 1:
            V, W = _factor_rank_one(G, floats)
        else:
            if floats:
                raise ModelError("repeated roots of a floating-point pencil: give exact (Rational) entries")
            if not (pencil.subs(lam, root) * G).applyfunc(lambda e: _tidy(e, False)).is_zero_matrix:
                raise ModelError(
                    f"the root {root} (multiplicity {q}) has a non-linear elementary divisor: fewer than {q} "
                    "independent modal columns exist, so there is no modal matrix; use spectral_decomposition or "
                    "Matrix.jordan_form for the root vectors"
                )
            R, piv = G.rref(simplify=True)
            if len(piv) != q:
                raise ModelError(f"F^({q - 1})({root}) has rank {len(piv)}, expected {q}")
            V, W = G[:, list(piv)], R[: len(piv), :].applyfunc(lambda e: _tidy(e, False))
        cols.append(V)
        rows.append(W)
        eigs.extend([root] * q)
        dsig = sp.cancel(delta.as_expr() / (lam - root) ** q)
        blocks.append(sp.factorial(q - 1) * _tidy(dsig.subs(lam, root), floats))
    Vm = sp.Matrix.hstack(*cols)
    Wm = sp.Matrix.vstack(*rows)
    # diagonal blocks W_sig a V_sig; the off-diagonal blocks vanish by (1.314) (checked by explicit products in tests)
    norms = sp.diag(*[(W * a * V).applyfunc(lambda e: _tidy(e, floats)) for V, W in zip(cols, rows, strict=True)])
    return ModalMatrix(V=Vm, W=Wm, eigenvalues=tuple(eigs), roots=tuple(roots), norms=norms, lead=a)


@validated
def modal_matrix(A: Any) -> ModalMatrix:
    """Modal matrix of ``A`` from the adjugate ``F(l) = adj(E l - A)`` (Bulgakov §1.26, §1.37).

    For a simple root ``l_sig`` the adjugate ``F(l_sig)`` has rank 1 and factors as ``V_sig W_sig`` (a column times a
    row); for a root of multiplicity ``q`` with linear elementary divisors ``F^(q-1)(l_sig)`` has rank ``q`` and
    factors as ``V(sig) W(sig)`` (1.216).  The columns ``V`` are eigenvectors, the rows ``W`` left eigenvectors, and
    ``W V`` is block diagonal with blocks ``(q - 1)! D_sig(l_sig) E_q`` — ``diag(Delta'(l_k))`` for simple roots
    (1.313–1.316) — so ``V**-1 = (W V)**-1 W`` without inverting anything else.

    Parameters
    ----------
    A : square Matrix
        Exact (rational, algebraic, symbolic) or floating-point entries.  Floating-point matrices need well
        separated roots.

    Returns
    -------
    ModalMatrix
        Unpacks as ``V, W``; also ``eigenvalues``, ``norms`` (= ``W V``), ``Lambda``, ``inverse``.

    Raises
    ------
    ModelError
        If a multiple root has a non-linear elementary divisor (``A`` is not diagonalisable), if the roots cannot be
        found in closed form for a symbolic matrix, or if a floating-point matrix has nearly repeated roots.

    Examples
    --------
    §1.37 (roots 1 and 2):

    >>> import sympy as sp
    >>> A = sp.Matrix([[4, -3], [2, -1]])
    >>> m = modal_matrix(A)
    >>> m.V, m.W
    (Matrix([
    [2, 3],
    [2, 2]]), Matrix([
    [1, -3/2],
    [1,   -1]]))
    >>> m.norms                  # diag(Delta'(1), Delta'(2)), Delta = l**2 - 3 l + 2
    Matrix([
    [-1, 0],
    [ 0, 1]])
    >>> A * m.V == m.V * m.Lambda
    True
    """
    A = as_square_matrix(A)
    return _modal(sp.eye(A.rows), -A, sp.Dummy("l"))


@validated
def pencil_modal_matrix(a: Any, b: Any) -> ModalMatrix:
    """Modal matrix of the pencil ``f(l) = a l + b`` with nonsingular ``a`` (Bulgakov §1.37, 1.311–1.312).

    Columns ``V_k`` solve ``(a l_k + b) V_k = 0``, rows ``W_k`` solve ``W_k (a l_k + b) = 0``, and
    ``W a V = diag((q - 1)! D_sig(l_sig) E_q)`` with ``Delta = det(a l + b)``; for simple roots
    ``W_k a V_k = Delta'(l_k)`` (1.312).  :func:`modal_matrix` is the case ``a = E``, ``b = -A``.

    Parameters
    ----------
    a : Matrix, nested list or ndarray
        Nonsingular square coefficient of ``l`` in the pencil ``a l + b``.
    b : Matrix, nested list or ndarray
        Square constant term of the pencil, of the same shape as ``a``.

    Returns
    -------
    ModalMatrix
        Unpacks as ``V, W``; also ``eigenvalues``, ``norms`` (= ``W a V``), ``Lambda``, ``inverse``.

    Examples
    --------
    >>> import sympy as sp
    >>> a, b = sp.Matrix([[2, 0], [0, 1]]), sp.Matrix([[-2, 1], [1, -3]])
    >>> m = pencil_modal_matrix(a, b)
    >>> [sp.simplify(e) for e in (a * m.V * m.Lambda + b * m.V)]
    [0, 0, 0, 0]
    """
    a = as_square_matrix(a, "a")
    b = as_square_matrix(b, "b")
    if a.shape != b.shape:
        raise ModelError(f"a and b must have the same shape, got {a.shape} and {b.shape}")
    return _modal(a, b, sp.Dummy("l"))


@dataclass(frozen=True)
class TriangularForm(SymPyPrintable):
    """Result of :func:`luzin_form`: ``U f = H`` with ``det U`` a non-zero constant.

    Attributes
    ----------
    H : Matrix
        Upper echelon form: in row ``k`` the first non-zero entry (column ``pivots[k]``) is monic, and the entries
        above it have lower degree; rows ``rank..m-1`` vanish.  Unique for given ``f`` (1.176).
    U : Matrix
        Unimodular row transform.
    pivots : tuple of int
        Pivot columns; ``(0, 1, ..., rank - 1)`` is Luzin's case (a non-vanishing rank-``r`` minor in the first
        ``r`` columns), where ``H`` is upper triangular.
    lam : Symbol
        The variable of the polynomial entries of ``f``, ``H`` and ``U``.
    """

    H: sp.Matrix
    U: sp.Matrix
    pivots: tuple
    lam: sp.Symbol

    @property
    def rank(self) -> int:
        return len(self.pivots)

    @property
    def luzin(self) -> bool:
        """True in the case of Luzin's theorem: the pivots are the first ``rank`` columns."""
        return self.pivots == tuple(range(self.rank))

    def __repr__(self) -> str:
        return f"TriangularForm(H={self.H.tolist()}, pivots={self.pivots})"

    def _repr_latex_(self) -> str:
        return f"$$U f = {sp.latex(self.H)}$$"


@validated
def luzin_form(f: Any, lam: sp.Symbol) -> TriangularForm:
    """Triangular canonical form of a polynomial matrix under row operations (Luzin's theorem, Bulgakov §1.22).

    Row operations (swap, multiply by a non-zero constant, add a polynomial multiple of another row) bring ``f`` to
    the upper echelon form ``H = U f`` in which every pivot ``g_kk`` is monic and has the largest degree in its column
    (the entries above it are reduced modulo ``g_kk``).  When a non-vanishing rank-``r`` minor lies in the first ``r``
    columns the pivots are on the diagonal (1.176); the product of the pivots is then the determinantal divisor of
    those columns, ``D_r`` for a square matrix.  Coefficients are treated as elements of a field (symbolic leading
    coefficients are assumed non-zero).

    What is reconstructed: the book's displayed matrices are illegible in the available copy; the statement above
    and the example below are a reconstruction of §1.22 Ex. 1.

    Parameters
    ----------
    f : Matrix or nested list
        Rectangular m x n matrix whose entries must be polynomials in ``lam``.
    lam : Symbol
        The polynomial variable; it must be a SymPy Symbol.

    Returns
    -------
    TriangularForm
        ``H``, the unimodular ``U`` with ``U f = H``, and the pivot columns.

    Examples
    --------
    §1.22 Ex. 1:

    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> res = luzin_form(sp.Matrix([[2 * l**2 + 3, 2 * l + 1], [l**2 - 2, l + 2]]), l)
    >>> res.H
    Matrix([
    [1,               -3/7],
    [0, l**2 + 7*l/3 + 8/3]])
    >>> res.U.det()
    1/3
    """
    M = _as_poly_matrix(f, lam)
    m, n = M.shape
    U = sp.eye(m)
    row, pivots = 0, []

    def sub(dst: int, src: int, q: sp.Expr) -> None:
        M[dst, :] = (M[dst, :] - q * M[src, :]).applyfunc(sp.expand)
        U[dst, :] = (U[dst, :] - q * U[src, :]).applyfunc(sp.expand)

    for col in range(n):
        if row == m:
            break
        while True:
            live = [r for r in range(row, m) if M[r, col] != 0]
            if not live:
                break
            best = min(live, key=lambda r: _deg(M[r, col], lam))
            if best != row:
                M.row_swap(best, row)
                U.row_swap(best, row)
            rest = [r for r in range(row + 1, m) if M[r, col] != 0]
            if not rest:
                break
            for r in rest:
                sub(r, row, _div(M[r, col], M[row, col], lam)[0])
        if M[row, col] == 0:
            continue
        lc = sp.Poly(M[row, col], lam).LC()
        M[row, :] = (M[row, :] / lc).applyfunc(sp.expand)
        U[row, :] = (U[row, :] / lc).applyfunc(sp.expand)
        for r in range(row):
            if M[r, col] != 0:
                sub(r, row, _div(M[r, col], M[row, col], lam)[0])
        pivots.append(col)
        row += 1
    return TriangularForm(H=M, U=U, pivots=tuple(pivots), lam=lam)
