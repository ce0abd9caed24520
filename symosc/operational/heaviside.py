"""Heaviside expansion theorems and residue inversion (Bulgakov §2.19, §2.30).

Convention: images are **Carson** images, ``X(p) = p * Laplace[x](p)``; originals are returned for ``t > 0``
(no ``Heaviside(t)`` factor).
"""

from __future__ import annotations

from typing import Any

import mpmath
import sympy as sp

from .._validate import validated
from ..errors import AccuracyWarning, ConvergenceError, ModelError, warn
from ..symbols import t as _t
from ._rational import as_rational, distinct_roots, has_floats, real_form, residue_terms

__all__ = ["first_expansion", "heaviside_expand", "residue_inverse"]


@validated
def heaviside_expand(image, p: sp.Symbol, t: sp.Symbol = _t, *, real: bool = True, roots: str = "exact"):
    """Original of a rational Carson image by the second expansion theorem (Bulgakov 2.74).

    For ``X(p) = p * eps(p)/Delta(p)`` with roots ``l`` of ``Delta`` of multiplicity ``q``::

        x(t) = sum_l sum_{rho<q} t**rho exp(l t)/(rho! (q-rho-1)!) [d^(q-rho-1)/dp (eps/D_l)](l)

    (simple roots: ``eps(l)/Delta'(l) exp(l t)``).  ``X/p`` must be strictly proper, i.e. the Carson image of an
    ordinary function has ``deg numerator <= deg denominator``.

    Parameters
    ----------
    image : Expr or Matrix
        Rational Carson image in ``p`` (a Matrix is inverted entry by entry).
    p, t : Symbol
        Image variable and time.
    real : bool
        Combine conjugate complex poles into ``exp(a t) (A cos(b t) + B sin(b t))`` (Bulgakov 2.89–2.91); free
        parameters are taken as real for this.
    roots : {"exact", "numeric"}
        ``"exact"``: radicals or ``CRootOf`` (exact, but ``CRootOf`` results stay complex and cannot be compiled);
        ``"numeric"``: 30-digit numeric roots (real form, compilable).  Float coefficients always use numeric roots.

    Returns
    -------
    Expr or Matrix
        The original for ``t > 0``.

    Raises
    ------
    ModelError
        If the image is not rational in ``p`` or improper (its original would contain delta functions).

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t")
    >>> heaviside_expand(p * (3 * p + 1) / ((p - 1) ** 2 * (p + 2)), p, t)
    (4*t/3 + 5/9)*exp(t) - 5*exp(-2*t)/9
    >>> heaviside_expand(p**2 / (p**2 + 4), p, t)
    cos(2*t)
    """
    if isinstance(image, sp.MatrixBase):
        return image.applyfunc(lambda e: heaviside_expand(e, p, t, real=real, roots=roots))
    if roots not in ("exact", "numeric"):
        raise ModelError(f"roots must be 'exact' or 'numeric', got {roots!r}")
    num, den = as_rational(image, p)
    if num.is_zero:
        return sp.S.Zero
    if num.degree() > den.degree():
        raise ModelError(
            f"improper Carson image: deg numerator {num.degree()} > deg denominator {den.degree()} (delta functions)"
        )
    lap_den = den * sp.Poly(p, p)
    lap_num = num
    lap_num, lap_den = _cancel_polys(lap_num, lap_den)
    found = distinct_roots(lap_den, numeric=roots == "numeric") if lap_den.degree() > 0 else []
    terms = residue_terms(lap_num, lap_den, p, t, found)
    if has_floats(lap_num, lap_den) or roots == "numeric":
        terms = _merge_near_multiple(terms, lap_num, lap_den, t)
    expr = sp.Add(*[term for _, _, term in terms])
    if real:
        expr = real_form(expr, t)
    return expr


def _merge_near_multiple(terms: list, num: sp.Poly, den: sp.Poly, t: sp.Symbol) -> list:
    """Replace the terms of numerically near-multiple simple poles by their confluent (Taylor) form.

    For a cluster of simple roots ``λ_i = μ + d_i`` (``|d_i| <= 1e-6 |μ|``) with residues ``r_i`` the sum
    ``Σ r_i exp(λ_i t)`` equals ``exp(μ t) Σ_k t^k/k! Σ_i r_i d_i^k``; the inner sums are formed in 30-digit
    arithmetic, so the ±1/δ residues that cancel in double precision never appear in the result.  Only damped
    clusters (``Re μ < 0``) are rewritten: there the truncated series is uniformly accurate for all ``t >= 0``.
    """
    if num.free_symbols - {num.gen} or den.free_symbols - {den.gen}:
        return terms
    simple = [(i, complex(sp.N(r, 17))) for i, (r, q, _) in enumerate(terms) if q == 1 and r.is_number]
    if len(simple) < 2:
        return terms
    parent = {i: i for i, _ in simple}

    def find(i: int) -> int:
        while parent[i] != i:
            i = parent[i]
        return i

    for a, (i, li) in enumerate(simple):
        for j, lj in simple[a + 1 :]:
            if abs(li - lj) <= 1e-6 * max(abs(li), abs(lj)):
                parent[find(i)] = find(j)
    groups: dict[int, list[int]] = {}
    for i, _ in simple:
        groups.setdefault(find(i), []).append(i)
    drop, extra = set(), []
    dnum, dden = num.as_expr(), den.diff(den.gen).as_expr()
    for members in groups.values():
        if len(members) < 2:
            continue
        with mpmath.workdps(40):
            lams = [_to_mp(terms[i][0]) for i in members]
            mu = mpmath.fsum(lams) / len(lams)
            if mpmath.re(mu) >= 0:
                continue
            res = [_to_mp(dnum.subs(den.gen, terms[i][0]) / dden.subs(den.gen, terms[i][0])) for i in members]
            d = [lam - mu for lam in lams]
            rho = max(abs(v) for v in d)
            a = -mpmath.re(mu)
            coeffs, k, size = [], 0, mpmath.mpf(0)
            while True:
                ck = mpmath.fsum(r * dk**k for r, dk in zip(res, d, strict=True)) / mpmath.factorial(k)
                coeffs.append(ck)
                size = max(size, abs(ck) * (k / (a * mpmath.e)) ** k if k else abs(ck))
                bound = mpmath.fsum(abs(r) for r in res) * rho**k * (max(k, 1) / (a * mpmath.e)) ** k
                bound /= mpmath.factorial(k)
                if k >= len(members) and bound <= 1e-20 * max(size, mpmath.mpf("1e-300")):
                    break
                k += 1
                if k > 60:
                    break
            if k > 60:
                continue
        poly = sp.Add(*[_mp_to_sympy(c) * t**j for j, c in enumerate(coeffs) if c != 0])
        drop.update(members)
        extra.append((_mp_to_sympy(mu), len(members), poly * sp.exp(_mp_to_sympy(mu) * t)))
    if not drop:
        return terms
    return [term for i, term in enumerate(terms) if i not in drop] + extra


def _to_mp(value: sp.Expr) -> mpmath.mpc:
    re, im = sp.N(value, 40).as_real_imag()
    return mpmath.mpc(mpmath.mpf(str(sp.N(re, 40))), mpmath.mpf(str(sp.N(im, 40))))


def _mp_to_sympy(z) -> sp.Expr:
    z = mpmath.mpc(z)
    re, im = sp.Float(mpmath.nstr(z.real, 30), 30), sp.Float(mpmath.nstr(z.imag, 30), 30)
    return re if im == 0 else re + sp.I * im


def _cancel_polys(num: sp.Poly, den: sp.Poly) -> tuple[sp.Poly, sp.Poly]:
    if has_floats(num, den):  # gcd over RR[params] is unreliable: cancel only common powers of p
        var = den.gen
        while num.degree() > 0 and den.degree() > 0 and num.TC() == 0 and den.TC() == 0:
            num, den = num.quo(sp.Poly(var, var)), den.quo(sp.Poly(var, var))
        return num, den
    g = num.gcd(den)
    if g.degree() > 0:
        num, den = num.quo(g), den.quo(g)
    return num, den


@validated
def residue_inverse(image, p: sp.Symbol, t: sp.Symbol = _t, *, real: bool = True):
    """Original as the sum of residues of ``X(p) exp(p t)/p`` (Bulgakov 2.141), for images ``A(p)/B(p)``.

    ``B`` must be a polynomial in ``p`` and ``A`` analytic at the zeros of ``B`` (e.g. a polynomial times
    ``exp(a*p)`` with ``a <= 0`` is *not* allowed: Jordan's lemma fails for ``t`` below the delay; use
    :func:`~symosc.operational.delay` instead).  For rational images this equals :func:`heaviside_expand`.

    Parameters
    ----------
    image : Expr or Matrix
        Carson image ``A(p)/B(p)`` whose denominator must be a polynomial in ``p`` (a Matrix is inverted entry by
        entry).
    p : Symbol
        The image variable.
    t : Symbol
        Time, the variable of the original (default ``symosc.t``).
    real : bool
        Combine conjugate complex poles into ``exp(a t) (A cos(b t) + B sin(b t))`` (Bulgakov 2.89–2.91).

    Returns
    -------
    Expr or Matrix
        The original for ``t > 0``.

    Raises
    ------
    ModelError
        If the denominator is not a polynomial in ``p`` or the image has exponential factors ``exp(c p)``.

    See Also
    --------
    heaviside_expand, invert_numeric

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t")
    >>> residue_inverse(p / (p + 1) ** 2, p, t)
    t*exp(-t)
    >>> residue_inverse(sp.sinh(p) / sp.cosh(p), p, t)
    Traceback (most recent call last):
    ...
    symosc.errors.ModelError: residue_inverse needs a polynomial denominator in p, got p*cosh(p); try invert_numeric
    """
    if isinstance(image, sp.MatrixBase):
        return image.applyfunc(lambda e: residue_inverse(e, p, t, real=real))
    if any(e.args[0].as_coefficient(p) is not None for e in sp.sympify(image).atoms(sp.exp)):
        raise ModelError("exponential factors exp(c*p) in the image: use the delay theorem (symosc.operational.delay)")
    expr = sp.together(sp.sympify(image) / p)
    a, b = sp.fraction(expr)
    if not b.is_polynomial(p):
        raise ModelError(f"residue_inverse needs a polynomial denominator in p, got {b}; try invert_numeric")
    if a.is_polynomial(p):
        return heaviside_expand(image, p, t, real=real)
    den = sp.Poly(b, p)
    total = sp.S.Zero
    lead = den.LC()
    roots = distinct_roots(den)
    for i, (root, q) in enumerate(roots):
        others = sp.Mul(*[(p - r) ** m for j, (r, m) in enumerate(roots) if j != i])
        g = a * sp.exp(p * t) / (lead * others)
        total += sp.diff(g, p, q - 1).subs(p, root) / sp.factorial(q - 1)
    total = sp.expand(total)
    return real_form(total, t) if real else total


@validated
def first_expansion(image, p: sp.Symbol, t: sp.Symbol = _t, *, order: int = 10, tol=None):
    """Original from the expansion ``X(p) = a0 + a1/p + a2/p**2 + ...`` (first expansion theorem, Bulgakov 2.72).

    Returns the partial sum ``a0 + a1 t + ... + a_{order-1} t**(order-1)/(order-1)!``, an entire-function series in
    ``t``.  With ``tol`` (and ``t`` a number) the call raises :class:`ConvergenceError` when the last retained term
    exceeds ``tol``.

    Parameters
    ----------
    image : Expr
        Carson image, analytic at ``p = oo`` (a series in ``1/p`` without positive powers of ``p``).
    p : Symbol
        The image variable.
    t : Symbol or number
        Time, the variable of the original (default ``symosc.t``); a number gives the numeric partial sum.
    order : int
        Number of terms kept (>= 1).
    tol : float, optional
        Largest acceptable magnitude (> 0) of the last term kept; checked only when that term is a number.

    Returns
    -------
    Expr
        The partial sum, a polynomial of degree ``order - 1`` in ``t``.

    Raises
    ------
    ModelError
        If the image grows at ``p -> oo``.
    ConvergenceError
        If the last term exceeds ``tol``.

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t")
    >>> first_expansion(p / (p + 1), p, t, order=4)
    -t**3/6 + t**2/2 - t + 1
    """
    if order < 1:
        raise ModelError("order must be a positive integer")
    s = sp.Dummy("s")
    expr = sp.sympify(image).subs(p, 1 / s)
    ser = sp.series(expr, s, 0, order).removeO()
    if ser.has(1 / s) or any(term.as_coeff_exponent(s)[1] < 0 for term in sp.Add.make_args(sp.expand(ser))):
        raise ModelError("the image grows at p -> oo; the first expansion theorem needs X(p) analytic at infinity")
    coeffs = [ser.coeff(s, k) if k else ser.subs(s, 0) for k in range(order)]
    terms = [c * t**k / sp.factorial(k) for k, c in enumerate(coeffs)]
    out = sp.Add(*terms)
    if tol is not None:
        last = terms[-1]
        if last.is_number and abs(complex(last)) > tol:
            raise ConvergenceError(
                f"first expansion: last term {float(abs(complex(last))):.3g} > tol={tol}; raise order",
                achieved=float(abs(complex(last))),
            )
    elif out.is_number:
        _check_partial_sum(terms, out, t, order)
    return out


def _check_partial_sum(terms: list, total: sp.Expr, t: Any, order: int) -> None:
    """Warn (AccuracyWarning) or raise (ConvergenceError) when a numeric partial sum is inaccurate: its error is at
    least the last term, plus the rounding of the largest term at the working precision when ``t`` is a float."""
    size = [abs(complex(sp.N(term, 30))) for term in terms]
    value = abs(complex(sp.N(total, 30)))
    rounding = max(size) * 2.0**-52 if any(isinstance(a, sp.Float) for a in sp.sympify(t).atoms(sp.Number)) else 0.0
    error = size[-1] + rounding
    if not error <= value:
        raise ConvergenceError(
            f"first expansion at t = {t}: the error of the {order}-term sum is about {error:.3g} (last term "
            f"{size[-1]:.3g}, rounding of terms up to {max(size):.3g}), more than the sum {value:.3g}; raise order, "
            "give t exactly (Rational) or use inverse_carson/invert_numeric",
            achieved=error,
        )
    if error > 1e-8 * max(value, 1e-300):
        warn(f"first expansion at t = {t}: the {order}-term sum {value:.6g} may be off by {error:.3g}", AccuracyWarning)
