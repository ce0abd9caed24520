"""Integral square estimates ``Integral(x(t)**2, (t, 0, oo))`` of originals of rational images (Bulgakov §2.32).

**Convention.**  ``numerator/denominator`` is by default the **Laplace** image ``U(p)/H(p) = X(p)/p`` of ``x``
(Bulgakov writes ``xi(p)/p = U(p)/H(p)``, ``xi`` the Carson image).  Pass ``image="carson"`` if the rational
function is the Carson image ``xi(p)``; it is then divided by ``p`` first.

With ``H(p) = k0 p**s + k1 p**(s-1) + ... + ks`` (Hurwitz, ``deg U < s``) and the even polynomial
``G(p) = U(-p) U(p) = l0 p**(2s-2) + l1 p**(2s-4) + ... + l_(s-1)`` (note the alternating signs of the ``l``)::

    I = (-1)**(s+1) det(M_s) / (2 k0 det(Hw_s))

where ``Hw_s[i, j] = k_(2j-i)`` (1-based; ``k_m = 0`` outside ``0..s``) is the Hurwitz matrix and ``M_s`` is
``Hw_s`` with its first row replaced by ``(l0, ..., l_(s-1))``.  For ``s <= 4`` this reduces to the closed forms
``I1..I4`` of the book (Phillips–MacLane).  The residue method sums ``Res G(q)/(H(-q) H(q))`` over the roots of ``H``.
"""

from __future__ import annotations

import sympy as sp

from .._validate import validated
from ..errors import ModelError, ParameterError
from ._rational import as_rational, distinct_roots, exactify, has_floats

__all__ = ["cross_integral", "integral_square", "pairwise_root_sum_product"]

_METHODS = ("auto", "hurwitz", "closed", "residues")


def _hurwitz_rows(polynomial: sp.Poly) -> sp.Matrix:
    """``Hw_s[i, j] = k_(2j-i)`` (0-based ``k_m``, zero outside ``0..s``): the transpose of the Hurwitz matrix of
    Bulgakov (1954), eq. (8.117) (the criterion with its verdicts and margins is :func:`symosc.linear.hurwitz`)."""
    k = polynomial.all_coeffs()
    s = len(k) - 1
    return sp.Matrix(s, s, lambda i, j: k[2 * j - i + 1] if 0 <= 2 * j - i + 1 <= s else 0)


def _hurwitz_verdict(polynomial: sp.Poly) -> bool | None:
    """True / False when the Hurwitz conditions (Bulgakov (1954), §8.18: ``k0 > 0``, the leading minors
    ``Δ1 .. Δ_(s-1)`` and ``ks`` positive, after making ``k0`` positive) are decided, None when they stay symbolic.
    Floats are taken exactly."""
    k = [sp.nsimplify(c, rational=True) if isinstance(c, sp.Float) else c for c in polynomial.all_coeffs()]
    if k[0].is_negative:
        k = [-c for c in k]
    H = _hurwitz_rows(sp.Poly(k, polynomial.gens[0])).T
    s = len(k) - 1
    conditions = [k[0], *(H[:i, :i].det(method="bareiss") for i in range(1, s)), k[-1]]
    signs = [sp.simplify(c).is_positive for c in conditions]
    if any(sign is False for sign in signs):
        return False
    return True if all(signs) else None


@validated
def pairwise_root_sum_product(polynomial, p: sp.Symbol) -> sp.Expr:
    """``prod_(i<j) (z_i + z_j)`` over the roots of ``A0 p**s + … + As`` by Orlando's formula (Bulgakov 2.165–2.167).

    ``prod_(i<j) (z_i + z_j) = (-1)**(s(s-1)/2) Delta_(s-1) / A0**(s-1)`` with ``Delta_(s-1)`` the leading
    ``(s-1) x (s-1)`` minor of the Hurwitz matrix; it vanishes exactly when two roots are symmetric about the
    imaginary axis (a stability boundary), which is why it is the denominator of the integral square estimates.

    Parameters
    ----------
    polynomial : Expr or Poly
        Polynomial ``A0 p**s + ... + As`` in ``p`` of degree s >= 1 (numeric or symbolic coefficients).
    p : Symbol
        The polynomial's variable.

    Returns
    -------
    Expr
        The product, factored (1 for degree 1).

    See Also
    --------
    symosc.linear.hurwitz_matrix, integral_square

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> pairwise_root_sum_product((p + 1) * (p + 2) * (p + 3), p)    # roots -1, -2, -3: (-3) * (-4) * (-5)
    -60
    """
    poly = sp.Poly(polynomial, p)
    s = poly.degree()
    if s < 1:
        raise ModelError(f"the polynomial must have degree >= 1 in {p}, got {polynomial}")
    if s == 1:
        return sp.Integer(1)
    delta = _hurwitz_rows(poly)[: s - 1, : s - 1].det()
    return sp.factor(sp.Integer(-1) ** (s * (s - 1) // 2) * delta / poly.LC() ** (s - 1))


def _prepare(numerator, denominator, p, image):
    if image not in ("laplace", "carson"):
        raise ParameterError(f"image must be 'laplace' or 'carson', got {image!r}")
    expr = sp.sympify(numerator) / sp.sympify(denominator)
    if image == "carson":
        expr = expr / p
    num, den = as_rational(expr, p)
    if num.is_zero:
        return num, den
    if num.degree() >= den.degree():
        kind = "Laplace image U/H" if image == "laplace" else "Carson image divided by p"
        raise ModelError(
            f"the {kind} must be strictly proper (deg U < deg H), got degrees {num.degree()} and {den.degree()}: "
            "x(t) then has a delta function or does not decay"
            + ("; did you mean image='carson'?" if image == "laplace" and num.degree() == den.degree() else "")
        )
    return num, den


def _check_hurwitz(den: sp.Poly, p) -> None:
    if _hurwitz_verdict(den) is False:
        raise ModelError(
            f"the denominator {den.as_expr()} is not Hurwitz (roots with Re p >= 0): the integral diverges"
        )


def _even_coeffs(g: sp.Expr, p, s: int) -> list[sp.Expr]:
    poly = sp.Poly(sp.expand(g), p)
    return [poly.coeff_monomial(p ** (2 * s - 2 - 2 * j)) for j in range(s)]


def _hurwitz_formula(ls, k, p) -> sp.Expr:
    s = len(k) - 1
    hw = _hurwitz_rows(sp.Poly(k, p))
    m = hw.copy()
    for j in range(s):
        m[0, j] = ls[j]
    return (-1) ** (s + 1) * m.det(method="bareiss") / (2 * k[0] * hw.det(method="bareiss"))


def _closed_form(ls, k) -> sp.Expr:
    s = len(k) - 1
    if s == 1:
        return ls[0] / (2 * k[0] * k[1])
    if s == 2:
        k0, k1, k2 = k
        l0, l1 = ls
        return (k0 * l1 - k2 * l0) / (2 * k0 * k1 * k2)
    if s == 3:
        k0, k1, k2, k3 = k
        l0, l1, l2 = ls
        return (k2 * k3 * l0 - k0 * k3 * l1 + k0 * k1 * l2) / (2 * k0 * k3 * (k1 * k2 - k0 * k3))
    if s == 4:
        k0, k1, k2, k3, k4 = k
        l0, l1, l2, l3 = ls
        num = k4 * (k2 * k3 - k1 * k4) * l0 - k0 * k3 * k4 * l1 + k0 * k1 * k4 * l2 + k0 * (k0 * k3 - k1 * k2) * l3
        return num / (2 * k0 * k4 * (k0 * k3**2 + k1**2 * k4 - k1 * k2 * k3))
    raise ParameterError(f"the closed forms I1..I4 cover orders 1..4, got order {s}; use method='hurwitz'")


def _residues(g: sp.Expr, den: sp.Poly, p) -> sp.Expr:
    roots = distinct_roots(den)
    h_minus = den.as_expr().subs(p, -p)
    lead = den.LC()
    total = sp.S.Zero
    for i, (root, q) in enumerate(roots):
        others = sp.Mul(*[(p - r) ** m for j, (r, m) in enumerate(roots) if j != i])
        f = g / (h_minus * lead * others)
        total += sp.diff(f, p, q - 1).subs(p, root) / sp.factorial(q - 1)
    return total


def _finish(value, floats: bool, method: str):
    if floats:
        return sp.Float(sp.re(sp.N(value, 30)), 17)
    if method == "residues":
        return sp.radsimp(sp.simplify(value))
    if value.is_Rational:
        return value
    return sp.factor(sp.cancel(value)) if value.free_symbols else sp.simplify(value)


@validated
def integral_square(numerator, denominator, p: sp.Symbol, *, image: str = "laplace", method: str = "auto"):
    """``Integral(x(t)**2, (t, 0, oo))`` for the original ``x`` of a rational image (Bulgakov 2.151–2.167).

    Parameters
    ----------
    numerator, denominator : Expr
        Polynomials in ``p``.  By default ``numerator/denominator`` is the **Laplace** image ``X(p)/p`` (the
        book's ``U/H``); with ``image="carson"`` it is the Carson image ``X(p)``.
    p : Symbol
        The image variable.
    image : {"laplace", "carson"}
        What ``numerator/denominator`` is: the Laplace image ``X(p)/p`` or the Carson image ``X(p)``.
    method : {"auto", "hurwitz", "closed", "residues"}
        ``"hurwitz"`` (default of ``"auto"``): the Hurwitz-determinant formula, any order; ``"closed"``: the
        book's ``I1..I4``; ``"residues"``: sum of residues at the roots of ``H``.

    Returns
    -------
    Expr
        Exact for exact input (Rational stays Rational), symbolic for symbolic coefficients (valid where ``H`` is
        Hurwitz), a Float for floating-point input (computed exactly from the binary values of the floats).

    Raises
    ------
    ModelError
        If ``H`` is not Hurwitz (decided exactly for numeric coefficients) or the image is not strictly proper.

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> integral_square(1, (p + 1) ** 3, p)        # x = t**2 exp(-t)/2 (Bulgakov §2.32: I3 = 3/16)
    3/16
    >>> integral_square(p, p + 2, p, image="carson")  # x = exp(-2t)
    1/4
    >>> integral_square(1, p**2 - 1, p)
    Traceback (most recent call last):
    ...
    symosc.errors.ModelError: the denominator p**2 - 1 is not Hurwitz (roots with Re p >= 0): the integral diverges
    """
    if method not in _METHODS:
        raise ParameterError(f"unknown method {method!r}; choose one of {_METHODS}")
    num, den = _prepare(numerator, denominator, p, image)
    if num.is_zero:
        return sp.S.Zero
    floats = has_floats(num, den)
    if floats:
        num, den = sp.Poly(exactify(num.as_expr()), p), sp.Poly(exactify(den.as_expr()), p)
    _check_hurwitz(den, p)
    g = sp.expand(num.as_expr().subs(p, -p) * num.as_expr())
    return _integral(g, den, p, method, floats)


def _integral(g, den, p, method, floats):
    s = den.degree()
    k = den.all_coeffs()
    if method == "residues" and floats:
        value = _residues(g, sp.Poly(sp.N(den.as_expr(), 30), p), p)
    elif method == "residues":
        value = _residues(g, den, p)
    else:
        ls = _even_coeffs(g, p, s)
        if method == "closed" or (method == "auto" and s <= 4 and not floats):
            value = _closed_form(ls, k)
        else:
            value = _hurwitz_formula(ls, k, p)
    return _finish(value, floats, method)


@validated
def cross_integral(
    numerator_x, denominator_x, numerator_y, denominator_y, p: sp.Symbol, *, image: str = "laplace",
    method: str = "auto",
):  # fmt: skip
    """``Integral(x(t) y(t), (t, 0, oo))`` for two rational images (Bulgakov 2.150), same conventions as
    :func:`integral_square`.

    Both images are put over a common denominator ``H`` and the even polynomial
    ``G = (U_x(-p) U_y(p) + U_x(p) U_y(-p))/2`` replaces ``U(-p) U(p)`` in the formulas.

    Parameters
    ----------
    numerator_x : Expr
        Numerator of the image of ``x``, a polynomial in ``p``.
    denominator_x : Expr
        Denominator of the image of ``x``, a Hurwitz polynomial in ``p`` (roots with ``Re p < 0``).
    numerator_y : Expr
        Numerator of the image of ``y``, a polynomial in ``p``.
    denominator_y : Expr
        Denominator of the image of ``y``, a Hurwitz polynomial in ``p`` (roots with ``Re p < 0``).
    p : Symbol
        The image variable.
    image : {"laplace", "carson"}
        What each ratio is: the Laplace image ``X(p)/p`` (each ratio strictly proper) or the Carson image ``X(p)``.
    method : {"auto", "hurwitz", "closed", "residues"}
        Formula, as for :func:`integral_square`: Hurwitz determinants (``"auto"``), the closed forms ``I1..I4``
        or residues.

    Returns
    -------
    Expr
        The integral (a Float for floating-point input).

    See Also
    --------
    integral_square

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> cross_integral(1, p + 1, 1, p + 2, p)      # Integral(exp(-t) exp(-2t)) = 1/3
    1/3
    """
    if method not in _METHODS:
        raise ParameterError(f"unknown method {method!r}; choose one of {_METHODS}")
    nx, dx = _prepare(numerator_x, denominator_x, p, image)
    ny, dy = _prepare(numerator_y, denominator_y, p, image)
    if nx.is_zero or ny.is_zero:
        return sp.S.Zero
    floats = has_floats(nx, dx, ny, dy)
    if floats:
        nx, dx, ny, dy = (sp.Poly(exactify(q.as_expr()), p) for q in (nx, dx, ny, dy))
    den = dx.lcm(dy)
    ux = sp.expand(nx.as_expr() * sp.cancel(den.as_expr() / dx.as_expr()))
    uy = sp.expand(ny.as_expr() * sp.cancel(den.as_expr() / dy.as_expr()))
    _check_hurwitz(den, p)
    g = sp.expand((ux.subs(p, -p) * uy + ux * uy.subs(p, -p)) / 2)
    return _integral(g, den, p, method, floats)
