"""Lagrange–Sylvester (confluent Hermite) interpolation and the spectral mapping theorem (Bulgakov §1.29, §1.34–1.36).

* :func:`interpolation_basis` — the polynomials ``ε_σ(λ)`` and ``η_(σ,p)(λ)`` of (1.267–1.268): ``η_(σ,p)`` has
  ``p``-th normalised derivative 1 at ``λ_σ`` and every other datum (derivatives below ``q_τ`` at every node)
  zero; ``ε_σ = η_(σ,0)``.
* :func:`interpolation_polynomial` — ``r(λ) = Σ_σ Σ_p f^(p)(λ_σ)/p! η_(σ,p)(λ)`` of degree < Σ q_σ (1.266, 1.269);
  ``f(A) = r(A)`` when the nodes are the characteristic roots (Bulgakov (1954), §1.30).
* :func:`function_elementary_divisors` — elementary divisors of ``f(A)`` predicted from those of A: a Jordan
  block of size e at λ whose first non-vanishing derivative ``f^(s)(λ)`` (1 <= s < e) has order s splits into s
  blocks of sizes ⌈(e-i)/s⌉, i = 0..s-1, at ``f(λ)`` (Lappo-Danilevsky when s = 1, and ``k = ⌈e/s⌉`` (1.302)).
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import as_scalar_function, as_square_matrix, has_singular_value

__all__ = ["function_elementary_divisors", "interpolation_basis", "interpolation_polynomial"]


def _nodes(roots: Any) -> list[tuple[sp.Expr, int]]:
    if isinstance(roots, dict):
        items = list(roots.items())
    else:
        items = [(r, 1) for r in roots]
    out = []
    for r, q in items:
        if int(q) != q or q < 1:
            raise ParameterError(f"multiplicity of node {r} must be a positive integer, got {q}")
        out.append((sp.sympify(r), int(q)))
    if len({r for r, _ in out}) != len(out):
        raise ParameterError("interpolation nodes must be distinct (give multiplicities in a dict)")
    return out


@validated
def interpolation_basis(roots: Any, lam: sp.Symbol) -> dict[sp.Expr, list[sp.Expr]]:
    """Cardinal polynomials ``{λ_σ: [ε_σ(λ), η_(σ,1)(λ), ..., η_(σ,q_σ-1)(λ)]}`` (Bulgakov 1.267–1.268).

    Parameters
    ----------
    roots : dict or sequence
        ``{node: multiplicity}`` or a sequence of distinct simple nodes.
    lam : Symbol
        The variable λ of the cardinal polynomials.

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> interpolation_basis({1: 1, 2: 1}, l)
    {1: [2 - l], 2: [l - 1]}
    """
    nodes = _nodes(roots)
    out = {}
    h = sp.Dummy("h")
    for s, (root, q) in enumerate(nodes):
        D = sp.Mul(*[(lam - r) ** m for i, (r, m) in enumerate(nodes) if i != s])
        inv = sp.series(1 / D.subs(lam, root + h), h, 0, q).removeO() if q > 1 else 1 / D.subs(lam, root)
        inv = sp.expand(inv)
        polys = []
        for p in range(q):
            trunc = sum(inv.coeff(h, k) * (lam - root) ** k for k in range(q - p)) if q > 1 else inv
            polys.append(sp.expand(D * (lam - root) ** p * trunc))
        out[root] = polys
    return out


@validated
def interpolation_polynomial(f: Any, roots: Any, lam: sp.Symbol, *, var: sp.Symbol | None = None) -> sp.Expr:
    """The Lagrange–Sylvester polynomial of f on the nodes: it matches ``f^(p)(λ_σ)`` for ``p < q_σ``.

    Parameters
    ----------
    f : Lambda, function class, callable or Expr
        Scalar function, analytic at every node: ``sympy.Lambda(x, ...)``, ``sympy.exp``, ``lambda x: ...`` or an
        expression in ``var``.
    roots : dict or sequence
        Interpolation nodes: ``{node: multiplicity}`` (multiplicities positive integers) or a sequence of distinct
        simple nodes.
    lam : Symbol
        The variable λ of the returned polynomial.
    var : Symbol, optional
        The variable of ``f`` when ``f`` is an expression with more than one free symbol.

    Returns
    -------
    Expr
        The polynomial ``r(λ)`` of degree < Σ q_σ, expanded.

    See Also
    --------
    interpolation_basis, matrix_function

    Examples
    --------
    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> interpolation_polynomial(sp.Lambda(l, l**3), {0: 2, 1: 1}, l)
    l**2
    """
    expr, x = as_scalar_function(f, var)
    basis = interpolation_basis(roots, lam)
    total = sp.Integer(0)
    for root, polys in basis.items():
        d = expr
        for p, poly in enumerate(polys):
            if p:
                d = sp.diff(d, x)
            val = d.subs(x, root)
            if has_singular_value(val):
                raise ModelError(f"f is not analytic at the node {root} (derivative of order {p} is {val})")
            total += val / sp.factorial(p) * poly
    return sp.expand(total)


@validated
def function_elementary_divisors(A: Any, f: Any, *, var: sp.Symbol | None = None) -> dict[sp.Expr, list[int]]:
    """Elementary divisors ``{μ: [sizes]}`` of ``f(A)`` predicted from the Jordan structure of A (§1.34–1.36).

    Parameters
    ----------
    A : Matrix, nested list or ndarray
        Square, non-empty matrix with exact or symbolic entries.
    f : Lambda, function class, callable or Expr
        Scalar function, analytic at every eigenvalue of ``A``: ``sympy.Lambda(x, ...)``, ``sympy.exp``,
        ``lambda x: ...`` or an expression in ``var``.
    var : Symbol, optional
        The variable of ``f`` when ``f`` is an expression with more than one free symbol.

    Returns
    -------
    dict
        ``{μ = f(λ): sorted list of block sizes}``.

    See Also
    --------
    elementary_divisors, matrix_function

    Examples
    --------
    Bulgakov §1.36: ``z = [[1, 1], [0, 1]]`` and ``S(λ) = λ/(1+λ²)`` with ``S'(1) = 0``: the quadratic divisor
    splits into two linear ones at 1/2.

    >>> import sympy as sp
    >>> l = sp.Symbol("l")
    >>> function_elementary_divisors(sp.Matrix([[1, 1], [0, 1]]), sp.Lambda(l, l / (1 + l**2)))
    {1/2: [1, 1]}
    """
    from ..canonical.polynomial_matrices import elementary_divisors

    M = as_square_matrix(A)
    expr, x = as_scalar_function(f, var)
    lam = sp.Dummy("lambda")
    divs = elementary_divisors(lam * sp.eye(M.rows) - M, lam)
    out: dict[sp.Expr, list[int]] = {}
    for root, sizes in divs.items():
        mu = sp.simplify(expr.subs(x, root))
        if has_singular_value(mu):
            raise ModelError(f"f is not analytic at the eigenvalue {root}")
        for e in sizes:
            s, d = None, expr
            for p in range(1, e):
                d = sp.diff(d, x)
                v = sp.simplify(d.subs(x, root))
                if has_singular_value(v):
                    raise ModelError(f"f is not analytic at the eigenvalue {root} (derivative of order {p} is {v})")
                if v != 0:
                    s = p
                    break
            s = e if s is None else s
            out.setdefault(mu, []).extend(-(-(e - i) // s) for i in range(s) if e - i > 0)
    return {k: sorted(v) for k, v in out.items()}
