"""Input handling and the order-by-order recurrence of Poincaré's method (used by :mod:`.poincare`).

The scaled problem ``y'' + y = eps g(y, w, eps)`` (generating amplitude 1) is solved on truncated Fourier series; see
:mod:`symosc.nonlinear.series.poincare` for the method and :mod:`symosc.nonlinear.series._arith.trig` for the
arithmetic.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import sympy as sp

from ...errors import ModelError, ParameterError
from ._arith.trig import ExactArith, Trig, _Arith


# ---------------------------------------------------------------------------------------------------------------
# input handling
# ---------------------------------------------------------------------------------------------------------------
def _polynomial_terms(f: Any, gens: tuple[sp.Symbol, ...], eps: sp.Symbol, what: str) -> dict[tuple, sp.Expr]:
    """Monomials ``{(exponents..., j): coefficient}`` of ``f`` in ``gens`` and ``eps`` (clear errors otherwise)."""
    f = sp.sympify(f)
    if not isinstance(f, sp.Expr):
        raise ModelError(f"{what} must be a SymPy expression, got {type(f).__name__}")
    f = canonical_symbols(f, gens, eps)
    allowed = set(gens) | {eps}
    extra = f.free_symbols - allowed
    if extra:
        names = ", ".join(sorted(s.name for s in extra))
        raise ParameterError(
            f"{what} depends on {names}; the series are computed with numeric coefficients: substitute numbers "
            f"(or rescale the equation so that the parameters disappear, e.g. x -> x*sqrt(kappa/lambda))"
        )
    try:
        poly = sp.Poly(sp.expand(f), *gens, eps)
    except sp.PolynomialError as exc:
        raise ModelError(
            f"{what} must be a polynomial in {', '.join(g.name for g in gens)} (and {eps.name}) for the series "
            f"method; got {f}. Expand the nonlinearity in a Taylor polynomial or use averaging/numerical validation"
        ) from exc
    terms = {}
    for monom, coeff in poly.terms():
        if coeff == 0:
            continue
        if coeff.free_symbols:
            raise ParameterError(f"{what}: coefficient {coeff} is not a number")
        if not coeff.is_real:
            raise ParameterError(f"{what}: coefficient {coeff} is not real")
        terms[tuple(int(e) for e in monom)] = coeff
    return terms


def canonical_symbols(f: sp.Expr, gens: tuple[sp.Symbol, ...], eps: sp.Symbol) -> sp.Expr:
    """Identify symbols by name (assumptions may differ) and accept ``x(t)``, ``x(t).diff(t)`` and ``x_dot``.

    ``gens`` is ``(x, v)`` (or ``(q1..qn, v1..vn)``): the second half are the velocities of the first half.
    """
    half = len(gens) // 2
    t = sp.Symbol("t")
    sub: dict[Any, Any] = {}
    for k in range(half):
        q, vq = gens[k], gens[half + k]
        for d in f.atoms(sp.Derivative):
            if isinstance(d.expr, sp.Function | sp.core.function.AppliedUndef) and d.expr.func.__name__ == q.name:
                if d.derivative_count == 1:
                    sub[d] = vq
        for fn in f.atoms(sp.core.function.AppliedUndef):
            if fn.func.__name__ == q.name and fn.args == (t,):
                sub[fn] = q
    if sub:
        derivs = {k: v for k, v in sub.items() if isinstance(k, sp.Derivative)}
        f = f.subs(derivs).subs({k: v for k, v in sub.items() if not isinstance(k, sp.Derivative)})
    by_name = {g.name: g for g in (*gens, eps)}
    for k in range(half):
        by_name.setdefault(f"{gens[k].name}_dot", gens[half + k])
    ren = {s_: by_name[s_.name] for s_ in f.free_symbols if s_.name in by_name and s_ != by_name[s_.name]}
    return f.xreplace(ren) if ren else f


@functools.lru_cache(maxsize=256)
def _trig_power_coefficients(p: int, q: int) -> tuple[Fraction, Fraction]:
    """(cos tau, sin tau) Fourier coefficients of ``cos(tau)**p * (-sin(tau))**q`` (exact)."""
    ar = ExactArith()
    one = ar.monomial("c", 0, Fraction(1))
    c1 = ar.monomial("c", 1, Fraction(1))
    ms = ar.monomial("s", 1, Fraction(-1))
    acc = one
    for _ in range(p):
        acc = ar.mul(acc, c1)
    for _ in range(q):
        acc = ar.mul(acc, ms)
    return ar.coeff(acc, "c", 1), ar.coeff(acc, "s", 1)


def amplitude_functions(terms: dict[tuple, sp.Expr], A: sp.Symbol) -> tuple[sp.Expr, sp.Expr]:
    """``H(A) = (1/pi) int f(A cos s, -A sin s, 0) sin s ds`` and the cosine integral ``G(A)`` (polynomials)."""
    H = sp.Integer(0)
    G = sp.Integer(0)
    for (p, q, j), c in terms.items():
        if j != 0:
            continue
        gc, hs = _trig_power_coefficients(p, q)
        H += c * sp.Rational(hs.numerator, hs.denominator) * A ** (p + q)
        G += c * sp.Rational(gc.numerator, gc.denominator) * A ** (p + q)
    return sp.expand(H), sp.expand(G)


def _positive_roots(H: sp.Expr, A: sp.Symbol) -> list[tuple[sp.Expr, int]]:
    """Positive real roots of the polynomial ``H`` with multiplicities (exact when the coefficients are rational)."""
    return list(_positive_roots_cached(H, A))


@functools.lru_cache(maxsize=256)
def _positive_roots_cached(H: sp.Expr, A: sp.Symbol) -> tuple[tuple[sp.Expr, int], ...]:
    return tuple(_find_positive_roots(H, A))


def _find_positive_roots(H: sp.Expr, A: sp.Symbol) -> list[tuple[sp.Expr, int]]:
    poly = sp.Poly(H, A)
    out: list[tuple[sp.Expr, int]] = []
    if poly.is_zero:
        return out
    if all(c.is_Rational for c in poly.all_coeffs()):
        roots = poly.real_roots()
        seen: dict[sp.Expr, int] = {}
        for r in roots:
            seen[r] = seen.get(r, 0) + 1
        for r, mult in seen.items():
            if r.is_positive:
                out.append((r, mult))
        return sorted(out, key=lambda t: float(t[0]))
    sq = sp.Poly(sp.gcd(poly, poly.diff(A)), A)
    for r in poly.nroots(n=30, maxsteps=200):
        if abs(sp.im(r)) < 1e-20 and sp.re(r) > 0:
            r = sp.re(r)
            mult = 2 if sq.degree() > 0 and abs(sq.eval(r)) < 1e-15 else 1
            out.append((r, mult))
    return sorted(out, key=lambda t: float(t[0]))


# ---------------------------------------------------------------------------------------------------------------
# the recurrence
# ---------------------------------------------------------------------------------------------------------------
@dataclass
class _RawSeries:
    x: list[Trig]  # x_k(tau), k = 0..order (scaled amplitude: x_0 = cos tau)
    s: list[Any]  # omega**2 coefficients, 0..order+1
    w: list[Any]  # omega coefficients, 0..order+1
    lam: list[Any]  # mean of f_v over the cycle, coefficients 0..order (Floquet exponent / eps)
    arith: _Arith


class _Tables:
    """Coefficients ``[eps^m] x^p v^q`` built incrementally (one new coefficient per order, Cauchy products in eps
    formed by :meth:`_Arith.cauchy`: pair by pair, or in relaxed blocks for the FLINT exact arithmetic)."""

    def __init__(self, ar: _Arith, pairs: set[tuple[int, int]], limit: int):
        self.ar = ar
        self.pmax = max([p for p, _ in pairs] + [1])
        self.qmax = max([q for _, q in pairs] + [1])
        self.mixed = sorted((p, q) for p, q in pairs if p > 0 and q > 0)
        self.X: dict[int, list[Trig]] = {p: [] for p in range(1, self.pmax + 1)}
        self.V: dict[int, list[Trig]] = {q: [] for q in range(1, self.qmax + 1)}
        self.M: dict[tuple[int, int], list[Trig]] = {pq: [] for pq in self.mixed}
        self.one = ar.monomial("c", 0, ar.scalar(1))
        self.products = {}
        for p in range(2, self.pmax + 1):
            self.products[("X", p)] = ar.cauchy(self.X[1], self.X[p - 1], limit=limit)
        for q in range(2, self.qmax + 1):
            self.products[("V", q)] = ar.cauchy(self.V[1], self.V[q - 1], limit=limit)
        for p, q in self.mixed:
            self.products[(p, q)] = ar.cauchy(self.X[p], self.V[q], limit=limit)

    def push(self, xm: Trig, vm: Trig) -> None:
        """Append the coefficients of order m = len(X[1]) given x_m and v_m."""
        m = len(self.X[1])
        self.X[1].append(xm)
        for p in range(2, self.pmax + 1):
            self.X[p].append(self.products[("X", p)](m))
        self.V[1].append(vm)
        for q in range(2, self.qmax + 1):
            self.V[q].append(self.products[("V", q)](m))
        for p, q in self.mixed:
            self.M[(p, q)].append(self.products[(p, q)](m))

    def get(self, p: int, q: int, m: int) -> Trig | None:
        if p == 0 and q == 0:
            return self.one if m == 0 else None
        if q == 0:
            return self.X[p][m]
        if p == 0:
            return self.V[q][m]
        return self.M[(p, q)][m]

    def variations(self) -> dict[tuple[int, int], Trig]:
        """d/da of ``[eps^m] x^p v^q`` when ``x_m -> x_m + a cos``, ``v_m -> v_m - a sin`` (same for every m >= 1)."""
        ar = self.ar
        cos1 = ar.monomial("c", 1, ar.scalar(1))
        msin1 = ar.monomial("s", 1, ar.scalar(-1))
        dX = {1: cos1}
        for p in range(2, self.pmax + 1):
            dX[p] = ar.scale_int(ar.mul(self.X[p - 1][0], cos1), p)
        dV = {1: msin1}
        for q in range(2, self.qmax + 1):
            dV[q] = ar.scale_int(ar.mul(self.V[q - 1][0], msin1), q)
        out: dict[tuple[int, int], Trig] = {}
        for p in range(1, self.pmax + 1):
            out[(p, 0)] = dX[p]
        for q in range(1, self.qmax + 1):
            out[(0, q)] = dV[q]
        for p, q in self.mixed:
            out[(p, q)] = ar.add(ar.mul(dX[p], self.V[q][0]), ar.mul(self.X[p][0], dV[q]))
        return out

    def correct(self, m: int, a: Any, var: dict[tuple[int, int], Trig]) -> None:
        ar = self.ar
        for p in range(1, self.pmax + 1):
            self.X[p][m] = ar.add(self.X[p][m], ar.scale(var[(p, 0)], a))
        for q in range(1, self.qmax + 1):
            self.V[q][m] = ar.add(self.V[q][m], ar.scale(var[(0, q)], a))
        for pq in self.mixed:
            self.M[pq][m] = ar.add(self.M[pq][m], ar.scale(var[pq], a))


def _combine(ar: _Arith, tables: _Tables, coeffs: dict[tuple[int, int, int], Any], m: int) -> Trig:
    """``[eps^m]`` of ``sum c x^p v^q eps^j``."""
    acc = ar.new(0)
    for (p, q, j), c in coeffs.items():
        if j > m:
            continue
        t = tables.get(p, q, m - j)
        if t is None:
            continue
        acc = ar.add(acc, ar.scale(t, c))
    return acc


def _poincare_raw(coeffs: dict, dcoeffs: dict, ar: _Arith, order: int) -> _RawSeries:
    """Run the recurrence for the scaled problem (generating amplitude 1) to ``order``."""
    pairs = {(p, q) for (p, q, _) in coeffs} | {(p, q) for (p, q, _) in dcoeffs}
    pairs.add((1, 0))
    pairs.add((0, 1))
    tables = _Tables(ar, pairs, order)
    one = ar.scalar(1)
    x: list[Trig] = [ar.monomial("c", 1, one)]
    s: list[Any] = [one]
    w: list[Any] = [one]
    # v_m = sum_i w_i x'_{m-i};  sum_{i=1}^{k-1} s_i x_{k-i} = (s_{.+1} * x_{.+1})_{k-2}
    w_x = ar.cauchy(w, x, limit=order, scalar_a=True)
    s_x = ar.cauchy(s, x, shift=1, limit=order - 1, scalar_a=True)
    var = None
    L = None
    for k in range(1, order + 2):
        m = k - 1
        vm = ar.deriv(w_x(m))
        tables.push(x[m], vm)
        R = _combine(ar, tables, coeffs, m)
        if k > 1:
            R = ar.sub(R, ar.deriv(ar.deriv(s_x(k - 2))))
        if k == 1:
            sk = _neg(ar, ar.coeff(R, "c", 1))
            var = tables.variations()
            L = _combine(ar, _VarView(var), {key: c for key, c in coeffs.items() if key[2] == 0}, 0)
            L = ar.add(L, ar.monomial("c", 1, sk))
            if ar.is_zero(ar.coeff(L, "s", 1)):
                raise ModelError(
                    "the amplitude equation has a multiple root at the generating amplitude (H'(A*) = 0): "
                    "the periodic solution is not continued by Poincaré's integer-power series"
                )
        else:
            a = _neg(ar, ar.sdiv(ar.coeff(R, "s", 1), ar.coeff(L, "s", 1)))
            sk = _neg(ar, _sadd(ar, ar.coeff(R, "c", 1), ar.smul(a, ar.coeff(L, "c", 1))))
            if not ar.is_zero(a):  # (zero for every other order of an odd nonlinearity)
                x[m] = ar.add_coeff(x[m], "c", 1, a)
                tables.correct(m, a, var)
                R = ar.add(R, ar.scale(L, a))
        R = ar.add_coeff(R, "c", 1, sk)
        s.append(sk)
        # omega = sqrt(omega**2): 2 w_k = s_k - sum_{i=1}^{k-1} w_i w_{k-i} (each product once, doubled)
        cross = ar.scalar(0)
        for i in range(1, (k + 1) // 2):
            cross = _sadd(ar, cross, ar.smul(w[i], w[k - i]))
        cross = _sadd(ar, cross, cross)
        if k % 2 == 0 and k > 0:
            cross = _sadd(ar, cross, ar.smul(w[k // 2], w[k // 2]))
        acc = _sadd(ar, sk, _neg(ar, cross))
        w.append(ar.sdiv(acc, ar.scalar(2)))
        if k == order + 1:
            break
        xk = ar.solve_forced(R)
        # phase condition x_k'(0) = 0: sum_n n b_n + D = 0
        xk = ar.add_coeff(xk, "s", 1, _neg(ar, ar.sine_moment(xk, 2)))
        x.append(xk)
    lam = []
    for mm in range(order + 1):
        lam.append(ar.coeff(_combine(ar, tables, dcoeffs, mm), "c", 0))
    return _RawSeries(x=x, s=s, w=w, lam=lam, arith=ar)


class _VarView:
    """Adapter so that :func:`_combine` can read the variation series like a table of order 0."""

    def __init__(self, var: dict[tuple[int, int], Trig]):
        self.var = var

    def get(self, p: int, q: int, m: int) -> Trig | None:
        return self.var.get((p, q)) if m == 0 and (p, q) != (0, 0) else None


def _neg(ar: _Arith, a: Any) -> Any:
    return -a


def _sadd(ar: _Arith, a: Any, b: Any) -> Any:
    return a + b
