"""Spectral decomposition of a square matrix: roots, projectors ε_σ and nilpotents η_σ^p (Bulgakov §1.30).

Exact or symbolic matrices use the book's confluent formulas (1.284–1.285):

    η_σ^p = 1/(q_σ-p-1)! · d^(q_σ-p-1)/dλ^(q_σ-p-1) [F(λ)/D_σ(λ)] at λ = λ_σ,   p = 0..q_σ-1  (η^0 = ε_σ),

with ``F(λ) = adj(λE - A)`` and ``D_σ(λ) = Δ(λ)/(λ - λ_σ)^q_σ``; the derivatives are taken as Taylor
coefficients (the Taylor shift of the polynomial F times the series of ``1/D_σ``).  Then any f analytic at the
roots is ``f(A) = Σ_σ Σ_(p<e_σ) f^(p)(λ_σ)/p! η_σ^p`` (1.287).

Floating-point matrices have no reliable Jordan structure (it is not a continuous
function of the entries), so their
eigenvalues are grouped into clusters of nearly equal values; each component then belongs to a cluster, its
projector is the spectral (Riesz) projector of the cluster, and its "nilpotent" ``(A - μE)P`` has spectral radius
at most the cluster radius.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import as_square_matrix, is_float_matrix
from ..canonical.charpoly import adjugate_poly
from ._schur_parlett import indicator_projectors, relative_clusters

__all__ = ["SpectralComponent", "SpectralDecomposition", "spectral_decomposition"]


@dataclass(frozen=True)
class SpectralComponent(SymPyPrintable):
    """One distinct root (or, in floating point, one cluster of nearly equal roots).

    Attributes
    ----------
    root : Expr
        λ_σ (for a cluster: its center).
    multiplicity : int
        Algebraic multiplicity q_σ (cluster: number of eigenvalues in it).
    index : int
        e_σ, the degree of the highest elementary divisor = size of the largest Jordan block (cluster: the
        multiplicity, an upper bound, since the Jordan structure is not defined numerically).
    projector : Matrix
        The principal idempotent ε_σ.
    nilpotents : tuple of Matrix
        ``(η_σ, η_σ^2, ..., η_σ^(e_σ-1))`` with ``η_σ = (A - λ_σE) ε_σ``.
    nodes : tuple
        Floating point only: the computed eigenvalues of the cluster.
    _family : tuple or None
        Internal, set by :func:`spectral_decomposition` (None when built by hand): ``(p, ρ, matrices)`` with ``p``
        the irreducible factor (a Poly) of the characteristic polynomial this root belongs to, ``ρ`` a generic root
        of ``p`` and the projector and nilpotents as polynomials in ``ρ``; it lets :meth:`SpectralDecomposition.apply`
        sum over all roots of ``p`` at once.
    """

    root: sp.Expr
    multiplicity: int
    index: int
    projector: sp.Matrix = field(repr=False)
    nilpotents: tuple[sp.Matrix, ...] = field(repr=False, default=())
    nodes: tuple = ()
    _family: tuple | None = field(default=None, repr=False, compare=False)

    @property
    def Z(self) -> tuple[sp.Matrix, ...]:
        """Frazer–Duncan–Collar components ``Z_j = η^j/j!`` (``Z_0 = ε``): ``f(A) = Σ_σ Σ_j f^(j)(λ_σ) Z_σj``."""
        return tuple(M / sp.factorial(j) for j, M in enumerate((self.projector, *self.nilpotents)))


@dataclass(frozen=True)
class SpectralDecomposition(SymPyPrintable):
    """Spectral data of a matrix: ``A = Σ_σ (λ_σ ε_σ + η_σ)`` and ``Σ ε_σ = E``.

    Use :meth:`apply` for ``f(A)`` (exact case only), :attr:`roots` and :attr:`projectors` to inspect it.

    Attributes
    ----------
    matrix : Matrix
        The decomposed square matrix ``A``.
    components : tuple of SpectralComponent
        One component per distinct root (floating point: per cluster of nearly equal roots).
    exact : bool
        True for an exact or symbolic decomposition (1.284–1.285); False for floating-point clusters.
    """

    matrix: sp.Matrix = field(repr=False)
    components: tuple[SpectralComponent, ...]
    exact: bool

    @property
    def roots(self) -> list[sp.Expr]:
        """Distinct roots (cluster centers in floating point)."""
        return [c.root for c in self.components]

    @property
    def projectors(self) -> list[sp.Matrix]:
        """Principal idempotents ε_σ in the order of :attr:`roots`."""
        return [c.projector for c in self.components]

    def apply(self, f, var: sp.Symbol | None = None) -> sp.Matrix:
        """``f(A)`` by (1.287) from these components (exact decompositions only).

        Parameters
        ----------
        f : Lambda, function class, callable or Expr
            Scalar function, analytic at every root: ``sympy.Lambda(x, ...)``, ``sympy.exp``, ``lambda x: ...`` or
            an expression in ``var``.
        var : Symbol, optional
            The variable of ``f`` when ``f`` is an expression with more than one free symbol.

        Returns
        -------
        Matrix
            ``f(A)``.

        Raises
        ------
        ModelError
            If the decomposition is not exact, or ``f`` (or a derivative the Jordan structure needs) is not defined
            at a root.

        Examples
        --------
        >>> import sympy as sp
        >>> S = spectral_decomposition(sp.Matrix([[1, 1], [0, 1]]))
        >>> S.apply(sp.Lambda(sp.Symbol("x"), sp.Symbol("x")**3))
        Matrix([
        [1, 3],
        [0, 1]])
        """
        from .._util import as_scalar_function

        if not self.exact:
            raise ModelError("apply() needs an exact decomposition; use matrix_function() for floating point")
        expr, x = as_scalar_function(f, var)
        n = self.matrix.rows
        out = sp.zeros(n, n)
        families_done: set[int] = set()
        for c in self.components:
            fam = c._family
            if fam is not None and fam[0].degree() >= 3:
                # all roots of one irreducible factor at once: Σ_roots g(ρ); exact RootSum when g is rational in ρ
                if id(fam) in families_done:
                    continue
                families_done.add(id(fam))
                p, rho, mats = fam[:3]
                # A = scale * B (see _scaled_decomposition): f(scale x) at B's roots with B's idempotents
                f_fam = expr.xreplace({x: fam[3] * x}) if len(fam) > 3 else expr
                for r in p.all_roots():
                    _terms(f_fam, x, r, c.index, mats[: c.index])  # singularity check at every root
                g = _terms(f_fam, x, rho, c.index, mats[: c.index])
                if all(e.is_rational_function(rho) for e in g):
                    out += g.applyfunc(lambda e, p=p, rho=rho: sp.RootSum(p.as_expr(), sp.Lambda(rho, e)))
                else:
                    out += sum((g.xreplace({rho: r}) for r in p.all_roots()), sp.zeros(n, n))
                continue
            out += _terms(expr, x, c.root, c.index, (c.projector, *c.nilpotents))
        if not self.matrix.free_symbols or any(len(c._family or ()) > 3 for c in self.components):
            out = out.applyfunc(_tidy_numeric)
        # (symbolic: the components are simplified already; simplifying the sum costs more than it gains)
        if all(e.is_real for e in self.matrix) and out.has(sp.I):
            out = out.applyfunc(_real_form)
        return out

    def __repr__(self) -> str:
        parts = ", ".join(f"{c.root} (q={c.multiplicity}, e={c.index})" for c in self.components)
        return f"SpectralDecomposition({parts}, exact={self.exact})"

    def _repr_latex_(self) -> str:
        rows = r" \\ ".join(
            rf"\lambda_{{{i + 1}}} = {sp.latex(c.root)},\ q={c.multiplicity},\ e={c.index}"
            for i, c in enumerate(self.components)
        )
        return rf"$\begin{{array}}{{l}} {rows} \end{{array}}$"


def _terms(expr: sp.Expr, x: sp.Symbol, root: sp.Expr, index: int, mats) -> sp.Matrix:
    """``Σ_(p<e) f^(p)(root)/p! M_p`` with a check that f is analytic at the root."""
    from .._util import has_singular_value

    n = mats[0].rows
    out = sp.zeros(n, n)
    deriv = expr
    for p, M in enumerate(mats):
        if p >= index:
            break
        if p:
            deriv = sp.diff(deriv, x)
        val = deriv.subs(x, root)
        if has_singular_value(val):
            kind = "value" if p == 0 else f"derivative of order {p}"
            raise ModelError(
                f"f is not analytic at the eigenvalue {root}: its {kind} there is {val} "
                f"(Jordan block of size {index}); f(A) is not defined"
            )
        out += val / sp.factorial(p) * M
    return out


def _tidy(e: sp.Expr) -> sp.Expr:
    """Light simplification of one matrix entry (factor/cancel where symbols are present; simplify only for zeros)."""
    if e.free_symbols:
        c = sp.factor(sp.cancel(e))
        return c if c == 0 or sp.count_ops(c) < 40 else sp.simplify(c)
    e = sp.expand(e)
    if e.has(sp.CRootOf):
        return e
    if e.has(sp.Pow) and not e.is_Rational:
        e = sp.radsimp(e)
    return sp.nsimplify(e) if e.is_Float else e


def _tidy_numeric(e: sp.Expr) -> sp.Expr:
    """Entries of f(A) for a matrix with numeric entries: components are already reduced, just expand."""
    e = sp.expand(e, power_exp=False)
    if e.has(sp.Pow) and not e.has(sp.CRootOf) and not e.free_symbols and not e.is_Rational:
        e = sp.radsimp(e)
    return e


def _real_form(e: sp.Expr) -> sp.Expr:
    """Rewrite ``exp(a + i b)`` as ``exp(a)(cos b + i sin b)``; keep the result only if every ``i`` cancels."""

    def has_imag(z: sp.Expr) -> bool:
        return isinstance(z, sp.exp) and sp.expand(z.args[0]).coeff(sp.I) != 0

    def rep(z: sp.Expr) -> sp.Expr:
        arg = sp.expand(z.args[0])
        c = arg.coeff(sp.I)
        return sp.exp(sp.expand(arg - sp.I * c)) * (sp.cos(c) + sp.I * sp.sin(c))

    new = sp.expand(e.replace(has_imag, rep), power_exp=False)
    if new.has(sp.I):
        return e
    return sp.collect(new, sorted(new.atoms(sp.exp), key=sp.default_sort_key))


def _exact_roots(A: sp.Matrix) -> list[tuple[sp.Expr, int]]:
    """Distinct characteristic roots with multiplicities.

    Linear and quadratic factors give radicals; irreducible factors of degree >= 3 with rational coefficients give
    ``CRootOf`` (exact, and much smaller than Cardano's formulas); symbolic ones use SymPy's closed forms.
    """
    poly = A.charpoly()
    found: dict[sp.Expr, int] = {}
    _, factors = sp.factor_list(poly.as_expr(), poly.gen)
    for fac, mult in factors:
        pf = sp.Poly(fac, poly.gen)
        if pf.degree() >= 3 and pf.free_symbols - {poly.gen}:
            raise ModelError(
                f"det(λE - A) has an irreducible factor of degree {pf.degree()} with symbolic coefficients; its roots "
                "are Cardano/Ferrari radicals and the projectors built from them grow beyond a practical size (a "
                "generic symbolic 3x3 runs for minutes). Substitute numbers for some parameters (exact numbers "
                "give exact CRootOf roots), or use sympy's eigenvals for the roots alone"
            )
        if pf.degree() >= 3 and not A.free_symbols and pf.get_domain().is_Exact:
            rts = {}
            for r in pf.all_roots():
                rts[r] = rts.get(r, 0) + 1
        else:
            rts = sp.roots(pf)
        if sum(rts.values()) != pf.degree():
            raise ModelError(
                "cannot find the characteristic roots in closed form (det(λE - A) has the factor "
                f"{fac}); substitute numbers for the parameters or use float entries"
            )
        for r, m in rts.items():
            found[r] = found.get(r, 0) + m * mult
    return sorted(found.items(), key=lambda item: _root_key(item[0]))


def _root_key(root: sp.Expr) -> tuple:
    if not root.free_symbols:
        try:
            z = complex(sp.N(root))
            return (0, z.real, z.imag, "")
        except (TypeError, ValueError):
            pass
    return (1, 0.0, 0.0, sp.srepr(root))


def _inverse_series(others: list[tuple[sp.Expr, int]], root: sp.Expr, order: int) -> list[sp.Expr]:
    """Taylor coefficients in h of ``1/D_σ(root + h) = Π (root - λ_τ + h)^(-q_τ)`` up to h^(order-1)."""
    series = [sp.Integer(1)] + [sp.Integer(0)] * (order - 1)
    for lt, qt in others:
        d = root - lt
        fac = [sp.binomial(-qt, k) * d ** (-qt - k) for k in range(order)]
        series = [sp.expand(sum(series[i] * fac[k - i] for i in range(k + 1))) for k in range(order)]
    return series


def _exact_decomposition(A: sp.Matrix) -> SpectralDecomposition:
    n = A.rows
    scaled = _scalar_multiple(A)
    if scaled is not None:  # A = c B with B rational (the idiom A*t): B's projectors, roots c λ, nilpotents c^p η^p
        return _scaled_decomposition(A, *scaled)
    lam = sp.Dummy("lambda")
    F = adjugate_poly(A, lam)
    if not A.free_symbols:
        delta = sp.Poly(A.charpoly().as_expr(lam), lam)
        if delta.get_domain().is_ZZ or delta.get_domain().is_QQ:
            return _rational_decomposition(A, F, delta, lam)
    roots = _exact_roots(A)
    comps = []
    for s, (root, q) in enumerate(roots):
        others = [rt for i, rt in enumerate(roots) if i != s]
        d = _inverse_series(others, root, q)
        Fj = []
        G = F
        for j in range(q):
            if j:
                G = G.diff(lam) / j
            Fj.append(G.subs(lam, root))
        coeffs = [sum((Fj[j] * d[k - j] for j in range(k + 1)), sp.zeros(n, n)) for k in range(q)]
        comps.append(_component(root, q, [c.applyfunc(_tidy) for c in coeffs]))
    return SpectralDecomposition(matrix=A, components=tuple(comps), exact=True)


def _scalar_multiple(A: sp.Matrix) -> tuple[sp.Expr, sp.Matrix] | None:
    """``(c, B)`` with ``A = c B``, ``c`` symbolic and ``B`` rational with a factor of degree >= 3 in its
    characteristic polynomial (whose roots, times ``c``, have no closed form), else None."""
    if not A.free_symbols:
        return None
    entry = next((e for e in A if e != 0), None)
    if entry is None:
        return None
    _, c = sp.sympify(entry).as_coeff_Mul()
    if not c.free_symbols:
        return None
    B = (A / c).applyfunc(sp.cancel)
    if B.free_symbols or not all(e.is_Rational for e in B):
        return None
    char = B.charpoly()
    factors = sp.factor_list(char.as_expr(), char.gen)[1]
    if all(sp.degree(fac, char.gen) < 3 for fac, _ in factors):
        return None  # radicals: the general path gives them (and the real cos/sin form)
    return c, B


def _scaled_decomposition(A: sp.Matrix, c: sp.Expr, B: sp.Matrix) -> SpectralDecomposition:
    """Components of ``A = c B`` from those of the rational ``B``: the same projectors, roots ``c λ``, nilpotents
    ``(c η)^p``; a family of conjugate roots keeps ``c`` so that :meth:`SpectralDecomposition.apply` evaluates
    ``f(c x)`` at the generic root."""
    inner = _rational_components(B)
    families: dict[int, tuple] = {}
    comps = []
    for comp in inner:
        fam = comp._family
        if fam is not None:
            fam = families.setdefault(id(fam), (*fam[:3], c))
        nil = tuple(sp.expand(c ** (p + 1)) * N for p, N in enumerate(comp.nilpotents))
        comps.append(
            SpectralComponent(sp.expand(c * comp.root), comp.multiplicity, comp.index, comp.projector, nil, (), fam)
        )
    return SpectralDecomposition(matrix=A, components=tuple(comps), exact=True)


def _rational_components(B: sp.Matrix) -> tuple[SpectralComponent, ...]:
    lam = sp.Dummy("lambda")
    delta = sp.Poly(B.charpoly().as_expr(lam), lam)
    return _rational_decomposition(B, adjugate_poly(B, lam), delta, lam).components


def _component(root: sp.Expr, q: int, coeffs: list[sp.Matrix]) -> SpectralComponent:
    """Component from the Taylor coefficients ``c_k`` of ``F/D_σ``: ``ε = c_(q-1)``, ``η^p = c_(q-1-p)``."""
    eps = coeffs[q - 1]
    nil = []
    for p in range(1, q):
        M = coeffs[q - 1 - p]
        if M.is_zero_matrix or (M.free_symbols and M.applyfunc(sp.simplify).is_zero_matrix):
            break
        nil.append(M)
    return SpectralComponent(root=root, multiplicity=q, index=len(nil) + 1, projector=eps, nilpotents=tuple(nil))


def _rational_decomposition(A: sp.Matrix, F: sp.Matrix, delta: sp.Poly, lam: sp.Symbol) -> SpectralDecomposition:
    """Components of a matrix with rational entries, computed once per irreducible factor ``p`` of Δ over Q.

    With a generic root ρ (``p(ρ) = 0``) the quotient ``D_σ(λ) = Δ(λ)/(λ-ρ)^q`` has coefficients in ``Q[ρ]``, so every
    Taylor coefficient of ``F/D_σ`` is reduced modulo p to a polynomial in ρ of degree < deg p; the roots
    (rational, quadratic radicals or ``CRootOf``) are substituted only at the end.  No radical simplification needed.
    """
    n = A.rows
    rho = sp.Dummy("rho")
    h = sp.Dummy("h")
    comps = []
    for pfac, q in sp.factor_list(delta.as_expr(), lam)[1]:
        p = sp.Poly(pfac.subs(lam, rho), rho, domain="QQ").monic()

        r0 = -p.nth(0) if p.degree() == 1 else None

        def red(e: sp.Expr, p=p, r0=r0) -> sp.Expr:
            if r0 is not None:  # rational root: plain substitution is exact and much faster
                return sp.cancel(sp.sympify(e).subs(rho, r0))
            num, den = sp.fraction(sp.together(sp.expand(e)))
            num_p = sp.Poly(num, rho, domain="QQ")
            den_p = sp.Poly(den, rho, domain="QQ")
            if den_p.degree() > 0:
                return (num_p * den_p.invert(p)).rem(p).as_expr()
            return (num_p.rem(p) / den_p).as_expr()

        Dsig = sp.div(delta.as_expr(), (lam - rho) ** q, lam)[0]
        shifted = sp.Poly(sp.expand(Dsig.subs(lam, rho + h)), h)
        b = [red(shifted.coeff_monomial(h**i)) for i in range(q)]
        b0_inv = red(1 / b[0])
        d = [b0_inv]
        for k in range(1, q):
            d.append(red(-b0_inv * sum(b[i] * d[k - i] for i in range(1, k + 1))))
        Fj, G = [], F
        for j in range(q):
            if j:
                G = G.diff(lam) / j
            Fj.append(G.subs(lam, rho).applyfunc(red))
        coeffs = [sum((Fj[j] * d[k - j] for j in range(k + 1)), sp.zeros(n, n)).applyfunc(red) for k in range(q)]
        if p.degree() <= 2:
            roots = list(sp.roots(p).keys())
        else:
            roots = p.all_roots()
        generic = _component(rho, q, coeffs)
        family = (p, rho, (generic.projector, *generic.nilpotents))
        for r in roots:
            comp = _component(r, q, [c.applyfunc(lambda e, r=r: sp.expand(e.subs(rho, r))) for c in coeffs])
            comps.append(
                SpectralComponent(comp.root, comp.multiplicity, comp.index, comp.projector, comp.nilpotents, (), family)
            )
    comps.sort(key=lambda c: _root_key(c.root))
    return SpectralDecomposition(matrix=A, components=tuple(comps), exact=True)


def _cluster(eigs: np.ndarray, cluster_tol: float) -> list[list[int]]:
    """Clusters of eigenvalues close relative to their own size, in Leja order of the centers."""
    n = len(eigs)
    scale = float(np.max(np.abs(eigs))) if n else 1.0
    clusters = relative_clusters(eigs, cluster_tol, scale)
    # Leja order of the centers: start with the largest, then maximize the product of distances.
    centers = [np.mean(eigs[g]) for g in clusters]
    order = [int(np.argmax(np.abs(centers)))]
    while len(order) < len(clusters):
        rest = [i for i in range(len(clusters)) if i not in order]
        best = max(rest, key=lambda i: np.prod([abs(centers[i] - centers[j]) for j in order]))
        order.append(best)
    return [clusters[i] for i in order]


def float_spectrum(A: np.ndarray, cluster_tol: float) -> tuple[np.ndarray, list[list[int]]]:
    """Eigenvalues reordered cluster by cluster, and the index ranges of the clusters."""
    eigs = np.linalg.eigvals(A)
    groups = _cluster(eigs, cluster_tol)
    nodes = np.concatenate([eigs[g] for g in groups])
    ranges, start = [], 0
    for g in groups:
        ranges.append(list(range(start, start + len(g))))
        start += len(g)
    return nodes, ranges


def newton_matrix(A: np.ndarray, nodes: np.ndarray, coeffs) -> np.ndarray:
    """``Σ_k c_k Π_(j<k) (A - x_j E)`` in complex floating point."""
    n = A.shape[0]
    E = np.eye(n)
    out = np.zeros((n, n), dtype=complex)
    P = E.astype(complex)
    for k, c in enumerate(coeffs):
        out += complex(c) * P
        if k < n - 1:
            P = P @ (A - nodes[k] * E)
    return out


def _float_decomposition(A: sp.Matrix, cluster_tol: float) -> SpectralDecomposition:
    An = np.array(A.evalf(), dtype=complex)
    if not np.all(np.isfinite(An)):
        raise ParameterError("A has non-finite entries (nan or inf); the spectral decomposition needs finite entries")
    real = not np.any(np.iscomplex(An))
    projectors, groups = indicator_projectors(An, cluster_tol)
    comps = []
    for P, members in zip(projectors, groups, strict=False):
        mu = complex(np.mean(members))
        N = (An - mu * np.eye(An.shape[0])) @ P
        pw, nil = N, []
        for _ in range(1, len(members)):
            nil.append(pw)
            pw = pw @ N
        conv = _to_sympy_real if real and abs(mu.imag) == 0 else _to_sympy
        root = sp.Float(mu.real) if mu.imag == 0 else sp.Float(mu.real) + sp.I * sp.Float(mu.imag)
        comps.append(
            SpectralComponent(
                root=root,
                multiplicity=len(members),
                index=len(members),
                projector=conv(P),
                nilpotents=tuple(conv(M) for M in nil),
                nodes=tuple(complex(v) for v in members),
            )
        )
    return SpectralDecomposition(matrix=A, components=tuple(comps), exact=False)


def _to_sympy(M: np.ndarray) -> sp.Matrix:
    return sp.Matrix(M.shape[0], M.shape[1], lambda i, j: sp.Float(M[i, j].real) + sp.I * sp.Float(M[i, j].imag))


def _to_sympy_real(M: np.ndarray) -> sp.Matrix:
    return sp.Matrix(M.shape[0], M.shape[1], lambda i, j: sp.Float(M[i, j].real))


@validated
def spectral_decomposition(A: sp.Matrix, *, cluster_tol: float = 1e-2) -> SpectralDecomposition:
    """Roots, principal idempotents and nilpotents of a square matrix (Bulgakov 1954, ch. 1).

    Eqs. (1.284)–(1.298) of the book: the idempotents are its ``ε_σ``, the nilpotents its ``η_σ^p``.

    Parameters
    ----------
    A : Matrix
        Square matrix: exact/symbolic entries give exact components; float entries give cluster components.
    cluster_tol : float
        Floating point only: eigenvalues with ``|λ_i - λ_j| <= cluster_tol * max(|λ_i|, |λ_j|)`` are linked into
        one cluster (relative to their own size).

    Returns
    -------
    SpectralDecomposition

    See Also
    --------
    matrix_function
    modal_matrix

    Examples
    --------
    >>> import sympy as sp
    >>> S = spectral_decomposition(sp.Matrix([[4, -3], [2, -1]]))
    >>> S
    SpectralDecomposition(1 (q=1, e=1), 2 (q=1, e=1), exact=True)
    >>> S.projectors[0]
    Matrix([
    [-2, 3],
    [-2, 3]])
    >>> spectral_decomposition(sp.Matrix([[2, 1], [0, 2]])).components[0].nilpotents
    (Matrix([
    [0, 1],
    [0, 0]]),)
    """
    A = as_square_matrix(A)
    if is_float_matrix(A):
        return _float_decomposition(A, cluster_tol)
    return _exact_decomposition(A)
