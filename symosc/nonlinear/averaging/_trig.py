"""Exact harmonic analysis of trigonometric polynomials (private helper of the averaging modules).

A trigonometric polynomial in a phase ``u`` (sums of products of ``cos(k*u + c)`` and ``sin(k*u + c)`` with integer
``k``, times anything independent of ``u``) is rewritten as a Laurent polynomial in ``z = exp(i*u)``; its
coefficients are the complex Fourier coefficients, obtained exactly without any integration.
"""

from __future__ import annotations

import sympy as sp

from ...errors import ModelError

__all__: list[str] = []

_z = sp.Dummy("z")  # exp(i u)
_w = sp.Dummy("w")  # exp(-i u): kept as a separate symbol so that no negative powers (and no z in denominators) arise


def _phase_multiple(arg: sp.Expr, u: sp.Symbol) -> tuple[int, sp.Expr]:
    """Split ``arg = k*u + c`` with integer ``k``; raise ModelError otherwise."""
    arg = sp.expand(arg)
    k = arg.coeff(u)
    c = sp.expand(arg - k * u)
    if c.has(u) or not (k.is_Integer):
        raise ModelError(
            f"cannot take harmonics of {arg!r} in {u}: only cos/sin of integer multiples of {u} are supported"
        )
    return int(k), c


def laurent_coefficients(expr: sp.Expr, u: sp.Symbol) -> dict[int, sp.Expr]:
    """Complex Fourier coefficients ``{m: c_m}`` of ``expr = sum c_m exp(i m u)`` (exact).

    Raises ModelError if ``expr`` is not a trigonometric polynomial in ``u``.
    """
    expr = sp.sympify(expr)
    reps = {}
    for fn in expr.atoms(sp.cos, sp.sin):
        if not fn.has(u):
            continue
        k, c = _phase_multiple(fn.args[0], u)
        zk, wk = (_z**k, _w**k) if k >= 0 else (_w ** (-k), _z ** (-k))
        e_plus = sp.exp(sp.I * c) * zk
        e_minus = sp.exp(-sp.I * c) * wk
        reps[fn] = (e_plus + e_minus) / 2 if isinstance(fn, sp.cos) else (e_plus - e_minus) / (2 * sp.I)
    new = expr.xreplace(reps)
    if new.has(u):
        raise ModelError(
            f"{expr} is not a trigonometric polynomial in {u} (it contains {u} outside cos/sin of integer multiples)"
        )
    new = sp.expand(new)
    out: dict[int, sp.Expr] = {}
    for term in sp.Add.make_args(new):
        coeff, power = sp.S.One, 0
        for factor in sp.Mul.make_args(term):
            base, ex = factor.as_base_exp()
            if base in (_z, _w):
                if not ex.is_Integer or ex < 0:
                    raise ModelError(f"{expr} is not a trigonometric polynomial in {u}")
                power += int(ex) if base == _z else -int(ex)
            elif factor.has(_z, _w):
                raise ModelError(f"{expr} is not a trigonometric polynomial in {u}")
            else:
                coeff *= factor
        out[power] = out.get(power, sp.S.Zero) + coeff
    return {m: c for m, c in out.items() if c != 0}


def average(expr: sp.Expr, u: sp.Symbol) -> sp.Expr:
    """Mean value of a trigonometric polynomial over one period of ``u`` (exact)."""
    return sp.expand(laurent_coefficients(expr, u).get(0, sp.S.Zero))


def _realify(expr: sp.Expr) -> sp.Expr:
    expr = sp.expand(expr)
    if expr.has(sp.exp):
        expr = sp.expand(expr.rewrite(sp.cos))
    return expr


def real_harmonics(expr: sp.Expr, u: sp.Symbol) -> tuple[sp.Expr, dict[int, tuple[sp.Expr, sp.Expr]]]:
    """``expr = F0 + sum_m (f_m cos(m u) + phi_m sin(m u))``: return ``(F0, {m: (f_m, phi_m)})`` for m >= 1."""
    c = laurent_coefficients(expr, u)
    f0 = _realify(c.get(0, sp.S.Zero))
    out = {}
    for m in sorted({abs(k) for k in c if k != 0}):
        cp, cm = c.get(m, sp.S.Zero), c.get(-m, sp.S.Zero)
        fm = _realify(cp + cm)
        phim = _realify(sp.I * (cp - cm))
        out[m] = (fm, phim)
    return f0, out


def _harmonic_degree(expr: sp.Expr, u: sp.Symbol) -> int:
    """Upper bound of the highest harmonic of a product of powers of cos(k u)/sin(k u)."""
    deg = 0
    for factor in sp.Mul.make_args(expr):
        base, ex = factor.as_base_exp()
        if isinstance(base, (sp.cos, sp.sin)) and base.has(u) and ex.is_Integer and ex > 0:
            k, _ = _phase_multiple(base.args[0], u)
            deg += abs(k) * int(ex)
    return deg


def bessel_expand(expr: sp.Expr, u: sp.Symbol) -> sp.Expr:
    """Replace ``exp(c + alpha cos u)`` / ``exp(c + beta sin u)`` (also sin, cos, sinh, cosh of such arguments) by
    their Jacobi–Anger series, truncated at the highest harmonic that can survive averaging the term.

    ``exp(z cos u) = sum_n I_n(z) e^{i n u}``, ``exp(z sin u) = sum_n (-i)^n I_n(z) e^{i n u}``; for imaginary ``z``
    SymPy turns ``I_n(i a)`` into ``i^n J_n(a)``.  The result is a trigonometric polynomial in ``u`` whose mean equals
    the mean of ``expr`` exactly.  Raises ModelError for arguments with both ``cos u`` and ``sin u``.
    """
    targets = {}
    for f in expr.atoms(sp.sin, sp.cos, sp.sinh, sp.cosh, sp.exp):
        if not f.has(u):
            continue
        arg = sp.expand(f.args[0])
        if arg.coeff(u) != 0 and not (arg - arg.coeff(u) * u).has(u):
            continue  # a plain harmonic cos(k u + c)
        w = f.args[0]
        if isinstance(f, sp.sin):
            targets[f] = (sp.exp(sp.I * w) - sp.exp(-sp.I * w)) / (2 * sp.I)
        elif isinstance(f, sp.cos):
            targets[f] = (sp.exp(sp.I * w) + sp.exp(-sp.I * w)) / 2
        elif isinstance(f, sp.sinh):
            targets[f] = (sp.exp(w) - sp.exp(-w)) / 2
        elif isinstance(f, sp.cosh):
            targets[f] = (sp.exp(w) + sp.exp(-w)) / 2
        else:
            targets[f] = f
    if not targets:
        return expr
    e = sp.expand(sp.powsimp(sp.expand(expr.xreplace(targets)), combine="exp"))
    out = sp.S.Zero
    cu, su = sp.cos(u), sp.sin(u)
    for term in sp.Add.make_args(e):
        term = sp.powsimp(term, combine="exp")
        exps = [f for f in sp.Mul.make_args(term) if isinstance(f, sp.exp) and f.has(u)]
        if not exps:
            out += term
            continue
        if len(exps) > 1:  # pragma: no cover - powsimp combines them
            raise ModelError(f"cannot expand {term}")
        ex = exps[0]
        rest = term / ex
        arg = sp.expand(ex.args[0])
        alpha, beta = arg.coeff(cu), arg.coeff(su)
        c0 = sp.expand(arg - alpha * cu - beta * su)
        if c0.has(u) or alpha.has(u) or beta.has(u):
            raise ModelError(f"exp({arg}) is not exp(c + alpha cos u + beta sin u)")
        if alpha != 0 and beta != 0:
            raise ModelError(
                f"exp({arg}) mixes cos and sin of the phase (a function of both x and v); not supported exactly"
            )
        N = _harmonic_degree(rest, u)
        series = sp.S.Zero
        for n in range(-N, N + 1):
            if alpha != 0:
                cn = sp.besseli(abs(n), alpha)
            else:
                cn = (-sp.I) ** n * sp.besseli(abs(n), beta)
            series += cn * (sp.cos(n * u) + sp.I * sp.sin(n * u))
        out += rest * sp.exp(c0) * series
    return out
