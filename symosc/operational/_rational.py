"""Private helpers: rational functions of the image variable, their poles and residues.

Everything here works on ``(numerator, denominator)`` pairs of :class:`sympy.Poly` in one variable.  Exact input
(Integer/Rational/symbolic coefficients) gives exact roots (radicals for factors of degree <= 2 or where
:func:`sympy.roots` finds them, :class:`sympy.CRootOf` otherwise).  Input with floating-point coefficients is
converted exactly to rationals, split into square-free factors exactly (so a repeated root of the float data is
found as a repeated root), and the roots of each factor are computed numerically with 30 digits.
"""

from __future__ import annotations

import sympy as sp

from ..errors import ModelError, ParameterError

_NUMERIC_DPS = 30


def as_rational(expr, var: sp.Symbol) -> tuple[sp.Poly, sp.Poly]:
    """Numerator and denominator of ``expr`` as polynomials in ``var``; ModelError if not rational in ``var``."""
    expr = sp.sympify(expr)
    if not expr.is_rational_function(var):
        raise ModelError(
            f"{expr} is not a rational function of {var}; use inverse_carson(..., method='numeric') or the delay "
            "theorem for exponential factors"
        )
    num, den = sp.fraction(sp.cancel(sp.together(expr)))
    num_poly, den_poly = sp.Poly(num, var), sp.Poly(den, var)
    if den_poly.is_zero:
        raise ModelError("the denominator is zero")
    return num_poly, den_poly


def has_floats(*polys: sp.Poly) -> bool:
    return any(c.has(sp.Float) for poly in polys for c in poly.all_coeffs())


def exactify(expr):
    """Replace every Float in ``expr`` by the exactly equal Rational."""
    return sp.sympify(expr).replace(lambda e: isinstance(e, sp.Float), lambda e: sp.Rational(e))


def distinct_roots(den: sp.Poly, numeric: bool = False) -> list[tuple[sp.Expr, int]]:
    """Distinct roots of ``den`` with their multiplicities, ordered by (real part, imaginary part) where numeric.

    With ``numeric=True`` exact coefficients are treated like floats (30-digit numeric roots).

    Raises
    ------
    ModelError
        When the roots of a polynomial with symbolic coefficients cannot be found in closed form.
    """
    var = den.gen
    numeric = numeric or has_floats(den)
    if numeric and not den.free_symbols - {var}:
        fast = _numeric_simple_roots(den)
        if fast is not None:
            return fast
    poly = sp.Poly(exactify(den.as_expr()), var) if numeric else den
    if poly.degree() <= 0:
        return []
    out: list[tuple[sp.Expr, int]] = []
    symbolic = bool(poly.free_symbols - {var})
    if symbolic:
        found = sp.roots(poly, var)
        if sum(found.values()) != poly.degree():
            raise ModelError(
                f"cannot find the roots of {poly.as_expr()} in closed form (symbolic coefficients, degree "
                f"{poly.degree()}); substitute numbers for the parameters first"
            )
        return list(found.items())
    _, factors = poly.sqf_list()
    for sqf, mult in factors:
        for irreducible, _ in sqf.factor_list()[1]:
            deg = irreducible.degree()
            if numeric and deg > 2:
                rts = irreducible.nroots(n=_NUMERIC_DPS, maxsteps=500)
            elif deg <= 2:
                rts = list(sp.roots(irreducible, var, multiple=True))
            else:
                rts = list(sp.roots(irreducible, var, multiple=True, cubics=False, quartics=False))
                if len(rts) != deg:
                    rts = irreducible.all_roots()
            if numeric:
                rts = [sp.N(r, _NUMERIC_DPS) for r in rts]
            out.extend((r, mult) for r in rts)
    return _sort_roots(out)


def _numeric_simple_roots(den: sp.Poly) -> list[tuple[sp.Expr, int]] | None:
    """Roots of a polynomial with numeric coefficients by mpmath at 30 digits if they are well separated (else
    None)."""
    import mpmath

    with mpmath.workdps(_NUMERIC_DPS + 10):  # any numeric coefficient: rational, float, sqrt(2), pi, complex
        coeffs = [mpmath.mpmathify(sp.N(c, _NUMERIC_DPS + 10)) for c in den.all_coeffs()]
    if len(coeffs) < 2:
        return []
    with mpmath.workdps(_NUMERIC_DPS):
        try:
            rts = mpmath.polyroots(coeffs, maxsteps=100, extraprec=60)
        except mpmath.libmp.NoConvergence:
            return None
        scale = max([abs(r) for r in rts] + [mpmath.mpf(1)])
        for i, a in enumerate(rts):
            for b in rts[i + 1 :]:
                if abs(a - b) < mpmath.mpf(10) ** -6 * scale:
                    return None
        out = []
        for r in rts:
            re_part, im_part = sp.Float(mpmath.re(r), _NUMERIC_DPS), sp.Float(mpmath.im(r), _NUMERIC_DPS)
            if abs(im_part) <= sp.Float(10) ** (5 - _NUMERIC_DPS) * scale:
                im_part = sp.S.Zero
            out.append((re_part + sp.I * im_part, 1))
    return _sort_roots(out)


def _sort_roots(roots: list[tuple[sp.Expr, int]]) -> list[tuple[sp.Expr, int]]:
    def key(item):
        try:
            z = complex(sp.N(item[0]))
            return (0, z.real, z.imag)
        except TypeError:
            return (1, 0.0, 0.0)

    return sorted(roots, key=key)


def residue_terms(
    num: sp.Poly, den: sp.Poly, var: sp.Symbol, t: sp.Symbol, roots: list[tuple[sp.Expr, int]] | None = None
) -> list[tuple[sp.Expr, int, sp.Expr]]:
    """Residues of ``num/den * exp(var*t)`` at every pole, as ``(root, multiplicity, term)``.

    ``num/den`` must be strictly proper.  For a pole ``l`` of multiplicity ``q`` and ``g = num/D_l`` with
    ``D_l = den/(var - l)**q`` this is the second expansion theorem (Bulgakov 2.74)::

        sum_{rho<q} t**rho exp(l t) / (rho! (q-rho-1)!) * g^(q-rho-1)(l)
    """
    if num.degree() >= den.degree():
        raise ModelError("internal: residue_terms needs a strictly proper rational function")
    roots = distinct_roots(den) if roots is None else roots
    lead = den.LC()
    out = []
    for i, (root, q) in enumerate(roots):
        others = [(r, m) for j, (r, m) in enumerate(roots) if j != i]
        if q == 1 and (isinstance(root, sp.CRootOf) or root.has(sp.Float)):
            value = num.as_expr().subs(var, root) / den.diff(var).as_expr().subs(var, root)
            term = _clean(value) * sp.exp(root * t)
        elif q == 1:
            value = num.as_expr().subs(var, root) / (lead * sp.Mul(*[(root - r) ** m for r, m in others]))
            term = _clean(value) * sp.exp(root * t)
        else:
            z = sp.Dummy("z")
            g = num.as_expr().subs(var, z) / (lead * sp.Mul(*[(z - r) ** m for r, m in others]))
            term = sp.S.Zero
            deriv = g
            derivs = [g]
            for _ in range(q - 1):
                deriv = sp.diff(deriv, z)
                derivs.append(deriv)
            for rho in range(q):
                k = q - rho - 1
                coeff = _clean(derivs[k].subs(z, root)) / (sp.factorial(rho) * sp.factorial(k))
                term += coeff * t**rho
            term = term * sp.exp(root * t)
        out.append((root, q, term))
    return out


def _clean(value: sp.Expr) -> sp.Expr:
    if value.has(sp.Float):
        return sp.N(value, _NUMERIC_DPS)
    if value.free_symbols:
        return sp.cancel(value) if not value.has(sp.CRootOf) else value
    if value.has(sp.CRootOf) or value.is_Rational:
        return value
    return sp.expand(sp.radsimp(value))


def real_form(expr: sp.Expr, t: sp.Symbol) -> sp.Expr:
    """Rewrite a sum of ``t**k exp(l t)`` with conjugate complex ``l`` in real form ``exp(a t)(A cos bt + B sin bt)``.

    Parameters (free symbols other than ``t``) are treated as real.  Returns ``expr`` unchanged if its
    imaginary part cannot be shown to vanish, and for roots given as ``CRootOf`` (exact complex form; the
    imaginary parts cancel numerically).
    """
    if not expr.has(sp.I) or expr.has(sp.CRootOf):  # CRootOf terms stay in exact complex form
        return expr
    free = sorted(expr.free_symbols, key=lambda s: s.name)
    real = {s: sp.Dummy(s.name, real=True) for s in free}
    back = {v: k for k, v in real.items()}
    e = expr.xreplace(real)
    re_part, im_part = sp.expand_complex(e).as_real_imag()
    im_check = sp.simplify(im_part) if im_part.free_symbols else sp.N(im_part)
    if im_check != 0 and not (im_check.is_number and abs(complex(im_check)) < 1e-20 * (1 + _magnitude(re_part))):
        return expr
    re_part = sp.collect(sp.expand(re_part), [sp.exp(a) for a in re_part.atoms(sp.exp)], evaluate=True)
    return re_part.xreplace(back)


def _magnitude(e) -> float:
    try:
        return abs(complex(sp.N(e.subs(dict.fromkeys(e.free_symbols, 1)))))
    except (TypeError, ValueError):
        return 1.0


def check_symbol(var, name: str) -> sp.Symbol:
    if not isinstance(var, sp.Symbol):
        raise ParameterError(f"{name} must be a sympy Symbol, got {var!r}")
    return var


def check_expression(value, name: str) -> sp.Expr:
    """``value`` sympified, refusing None, non-expressions and infinite/undefined values (``p/0`` is ``zoo*p``)."""
    if value is None:
        raise ParameterError(f"{name} must be a SymPy expression, got None")
    try:
        expr = sp.sympify(value, strict=not isinstance(value, str))
    except (sp.SympifyError, TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a SymPy expression, got {value!r}") from exc
    if not isinstance(expr, sp.Expr):
        raise ParameterError(f"{name} must be a SymPy expression, got {type(value).__name__}")
    if expr.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise ParameterError(f"{name} is infinite or undefined ({expr}); check for a division by zero")
    return expr
