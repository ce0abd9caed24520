"""Shared driver of the one-port synthesis procedures (private): removals, minimum resistance, cycles.

Every step is exact arithmetic over a number field ``K`` (see ``_exact``): ``QQ`` for rational targets, extended
by an algebraic number (a square root or ``CRootOf``, then tower fields ``K[x]/(own)``, total degree <=
``_exact.max_field_degree()``) when the minimum of ``Re Z(iω)`` (Brune) or Richards' ``k`` (Bott–Duffin) is
irrational.  Element values are kept as field elements until the network is complete and then written as exact
algebraic numbers: radicals or polynomials in one ``CRootOf`` (the primitive element of the largest field used,
every other field used lying below it in its tower), in fields of degree above 24 polynomials in the root adjoined
at each level of the tower (``_tower.in_levels_all``).
"""

from __future__ import annotations

import dataclasses
from typing import Any

import mpmath
import sympy as sp
from sympy import QQ
from sympy.polys.constructor import construct_domain

from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._exact import fields as ex
from .._exact import tower as _tower
from .._exact.tower import TowerField
from .._util import P, as_symbol, rational_function, values_checked
from ..ports.oneports import BruneSection, Capacitor, Inductor, OnePort, Parallel, Resistor, Series
from ._correcting import dual, scale_expr

_MAX_DEPTH = 200
#: how many times one synthesis may undo a step whose continuation needs a field above the limit and take the other
#: minimum (of ``Re Z`` or of ``Re 1/Z``) instead
_MAX_RETRIES = 4


def to_exact(Z: Any, p: sp.Symbol) -> tuple[list, list, Any]:
    """Coprime coefficient lists of ``Z`` over the smallest exact domain holding its coefficients."""
    return exact_polys(*rational_function(Z, p))


def exact_polys(N: sp.Poly, D: sp.Poly) -> tuple[list, list, Any]:
    """Coefficient lists of coprime ``N``, ``D`` over the smallest exact domain holding their coefficients."""
    coeffs = [sp.nsimplify(c, rational=True) if c.has(sp.Float) else c for c in N.all_coeffs() + D.all_coeffs()]
    try:
        K, elems = construct_domain(coeffs, extension=True)
    except (sp.PolynomialError, NotImplementedError, ValueError) as exc:  # pragma: no cover - defensive
        raise ParameterError(f"Z must have exact numeric coefficients, got {coeffs}") from exc
    if K.is_ZZ:
        K, elems = QQ, [QQ.convert_from(c, K) for c in elems]
    if not (K.is_QQ or K.is_AlgebraicField):
        raise ParameterError(f"Z must have rational or algebraic coefficients for exact arithmetic, got domain {K}")
    n = len(N.all_coeffs())
    N_, D_ = ex.normalize(elems[:n], elems[n:], K)
    return N_, D_, K


@validated
def minimum_real_part(Z: Any, p: sp.Symbol = P) -> tuple[sp.Expr, sp.Expr]:
    """``(R, ω0²)``: the minimum of ``Re Z(iω)`` over ``ω >= 0`` and where it is reached (``oo`` at infinity).

    Exact: the critical points are the real roots of ``E' Q - E Q'`` (``Re Z(iω) = E(x)/Q(x)``, ``x = ω²``);
    irrational ones are radicals or ``CRootOf`` numbers, and ``R`` lies in the field they generate
    (Bulgakov (1954), §9.23, Theorem III).

    Parameters
    ----------
    Z : SymPy expression
        Rational function of ``p`` with rational or algebraic numeric coefficients (floats are taken exactly).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import minimum_real_part
    >>> p = sp.Symbol("p")
    >>> minimum_real_part((p**2 + p + 1) / (p**2 + p + 4), p)
    (0, 2)
    >>> minimum_real_part((p**2 + 2*p + 4) / (p**2 + p + 1), p)
    (7/3 - 2*sqrt(7)/3, sqrt(7)/2 + 3/2)

    See Also
    --------
    brune_synthesis, real_part_on_axis
    """
    p = as_symbol(p)
    N, D, K = to_exact(Z, p)
    if not N:
        return sp.Integer(0), sp.Integer(0)
    R, x0, K2, _, _ = _minimum(N, D, K, allow_pole=True)
    where = sp.oo if x0 == "oo" else (sp.Integer(0) if x0 == "0" else ex.sym(x0, K2))
    return ex.sym(R, K2), where


def _minimum(N: list, D: list, K, allow_pole: bool = False, known: tuple = (), extend: bool = True):
    """Minimum of ``E/Q`` on ``x >= 0``: ``(R, x0, K', N, D)`` with ``x0`` in ``K'`` or ``"0"``/``"oo"``.

    ``known``: elements of ``K`` tried first as the interior minimum (a previous step's ``ω0²``: subtracting a
    constant leaves the critical points where they were).  ``extend=False``: None instead of building the field
    extension an interior minimum needs (decided from numbers)."""
    E, Q = ex.real_part_x(N, D, K)
    if not E:
        return K.zero, "0", K, N, D
    cands: list[tuple[Any, int, Any]] = []  # (value, field degree, where)
    q0 = ex.dup_eval(Q, K.zero, K)
    if q0:
        cands.append((ex.num(K.quo(ex.dup_eval(E, K.zero, K), q0), K), 0, "0"))
    dE, dQ = ex.dup_degree(E), ex.dup_degree(Q)
    if dE < dQ:
        cands.append((mpmath.mpf(0), 0, "oo"))
    elif dE == dQ:
        cands.append((ex.num(K.quo(E[0], Q[0]), K), 0, "oo"))
    crit = ex.dup_sub(ex.dup_mul(ex.dup_diff(E, 1, K), Q, K), ex.dup_mul(E, ex.dup_diff(Q, 1, K), K), K)
    if crit:
        if K.is_QQ:
            for r in ex.real_roots_qq(crit):
                if sp.N(r, ex._DIGITS) > 0:
                    val = ex.eval_num(E, r, K) / ex.eval_num(Q, r, K)
                    cands.append((val, 0 if r.is_Rational else 1, r if extend or r.is_Rational else "pending"))
        else:
            _interior_in_field(E, Q, crit, K, cands, known, extend)
    if not cands:  # pragma: no cover - Q(0) = 0 only with a pole at 0, removed before
        raise ModelError("no candidate for the minimum of Re Z(iω)")
    best = min(c[0] for c in cands)
    tol = mpmath.mpf(10) ** (-ex._DIGITS + 8) * (1 + abs(best))
    _value, _, where = min((c for c in cands if c[0] - best <= tol), key=lambda c: c[1])
    if where == "pending":
        return None
    if where in ("0", "oo"):
        if where == "0":
            R = K.quo(ex.dup_eval(E, K.zero, K), q0)
        else:
            R = K.zero if dE < dQ else K.quo(E[0], Q[0])
        return R, where, K, N, D
    if isinstance(where, tuple) and where[0] == "K":
        x0 = where[1]
    elif isinstance(where, tuple):  # a root in an extension of K
        x0, K2 = where[1], where[2]
        N, D = ex.to_field(N, K, K2), ex.to_field(D, K, K2)
        E, Q, K = ex.to_field(E, K, K2), ex.to_field(Q, K, K2), K2
    else:
        K2 = ex.extension(where, "the critical points of Re Z(iω)")
        N, D = ex.to_field(N, K, K2), ex.to_field(D, K, K2)
        E, Q, K = ex.to_field(E, K, K2), ex.to_field(Q, K, K2), K2
        x0 = K.from_sympy(where)
    R = K.quo(ex.dup_eval(E, x0, K), ex.dup_eval(Q, x0, K))
    return R, x0, K, N, D


def _interior_in_field(E: list, Q: list, crit: list, K, cands: list, known: tuple, extend: bool) -> None:
    """Over an algebraic field only critical points inside the field are exact; a lower interior minimum elsewhere
    is the limitation of one extension.  Numbers first: the field is factored only when the interior wins."""
    crit = ex.squarefree_part(crit, K)
    interior = [(ex.eval_num(E, x, K) / ex.eval_num(Q, x, K), x) for x in _as_sympy(ex.numeric_positive_roots(crit, K))]
    if not interior:
        return
    best_val, best_x = min(interior, key=lambda c: c[0])
    tol = mpmath.mpf(10) ** -20 * (1 + abs(best_val))
    if cands and min(c[0] for c in cands) <= best_val + tol:
        return
    with mpmath.workdps(ex._DIGITS):
        best_x = mpmath.mpf(str(best_x))  # all 40 digits
    for x in known:  # exact: a zero of crit; numerically the winning one
        if abs(ex.num(x, K) - best_x) <= mpmath.mpf(10) ** -12 * (1 + abs(best_x)) and not ex.dup_eval(crit, x, K):
            cands.append((best_val, 1, ("K", x)))
            return
    if not extend:
        cands.append((best_val, 1, "pending"))
        return
    r, K2 = ex.extend_with_root(crit, K, best_x, "the critical points of Re Z(iω)")
    cands.append((best_val, 1, ("X", r, K2) if K2 != K else ("K", r)))


def _as_sympy(values: list) -> list:
    return [sp.Float(mpmath.nstr(v, 35), 40) for v in values]  # all digits computed (str gives 15)


def join(parts: list[OnePort], rest: OnePort | None, cls: type) -> OnePort:
    items = parts + ([rest] if rest is not None else [])
    return items[0] if len(items) == 1 else cls(tuple(items))


def _tank(v1: sp.Expr, v2: sp.Expr, mode: str) -> OnePort:
    """``c p/(p² + w2)`` with ``v1 = 1/c``, ``v2 = c/w2``: a parallel tank (C = v1, L = v2) in an impedance, a
    series branch (L = v1, C = v2) in an admittance."""
    if mode == "Z":
        return Parallel((Capacitor(v1), Inductor(v2)))
    return Series((Inductor(v1), Capacitor(v2)))


def _clean(value: sp.Expr) -> sp.Expr:
    if value.is_Rational or value.has(sp.CRootOf):
        return value
    return sp.radsimp(sp.expand(value))


def _at_root(poly: list, root: sp.Expr) -> sp.Expr:
    """A polynomial over QQ (coefficient list) at an exact algebraic root, as a polynomial in that root."""
    y = sp.Dummy("y")
    value = sp.Poly([QQ.to_sympy(c) for c in poly], y).as_expr().subs(y, root) if poly else sp.Integer(0)
    return _clean(value)


def _family_values(a: list, h: list, K, values: _Values) -> list[tuple[sp.Expr, sp.Expr]]:
    """``p a(p²)/h(p²) = Σ c_i p/(p² + w2_i)`` over the roots ``y_i = -w2_i`` of ``h`` (linear, or over the
    rationals): pairs ``(1/c_i, c_i/w2_i)``, each computed in the field of its root (as polynomials in the root
    reduced modulo ``h``; over an algebraic field a nonlinear ``h`` is realised by :func:`_axis_ladder`)."""
    if ex.dup_degree(h) == 1:
        yi = K.quo(K.neg(h[1]), h[0])
        c = K.quo(ex.dup_eval(a, yi, K), ex.dup_eval(ex.dup_diff(h, 1, K), yi, K))
        return [
            (
                values.positive(K.quo(K.one, c), K, "tank element"),
                values.positive(K.quo(c, K.neg(yi)), K, "tank element"),
            )
        ]
    r = ex.dup_rem(ex.dup_mul(a, ex.dup_invert(ex.dup_diff(h, 1, K), h, K), K), h, K)  # c(y) = a(y)/h'(y) mod h
    inv_r = ex.dup_invert(r, h, K)  # 1/c(y)
    r_over_w2 = ex.dup_rem(ex.dup_mul(r, ex.dup_invert([K.neg(K.one), K.zero], h, K), K), h, K)  # c(y)/(-y)
    out = [(_at_root(inv_r, yi), _at_root(r_over_w2, yi)) for yi in ex.real_roots_qq(h)]
    if len(out) != ex.dup_degree(h):  # pragma: no cover - a PR function has its axis poles on the axis
        raise ModelError("poles expected on the imaginary axis are not all there")
    return out


def remove_axis_poles(
    N: list, D: list, K, mode: str, values: _Values | None = None
) -> tuple[list[OnePort], list, list]:
    """Remove the imaginary-axis poles of ``F = N/D`` (Bulgakov (1954), §9.23, Theorem IV), exactly over ``K``
    (element values as exact numbers at once unless a synthesis collects them in ``values``)."""
    values = values or _Values(immediate=True)
    parts: list[OnePort] = []
    dn, dd = ex.dup_degree(N), ex.dup_degree(D)
    if dn > dd + 1:
        raise ModelError("multiple pole at infinity: not a positive-real function")
    if dn == dd + 1:
        k = K.quo(N[0], D[0])
        N = ex.dup_sub(N, ex.dup_mul_ground(ex.mul_p(D, K), k, K), K)
        kv = values.positive(k, K, "residue at infinity")
        parts.append(Inductor(kv) if mode == "Z" else Capacitor(kv))
    if D and not D[-1]:
        D1 = D[:-1]
        if not D1[-1]:
            raise ModelError("multiple pole at p = 0: not a positive-real function")
        k = K.quo(ex.dup_eval(N, K.zero, K), D1[-1])
        N = ex.exquo(ex.dup_sub(N, ex.dup_mul_ground(D1, k, K), K), [K.one, K.zero], K, "pole at zero")
        D = D1
        kv = values.positive(K.quo(K.one, k), K, "residue at p = 0", sign_of=k)
        parts.append(Capacitor(kv) if mode == "Z" else Inductor(kv))
    G = ex.gcd(D, ex.reflect(D, K), K)
    if ex.dup_degree(G) > 0:
        H = ex.even_in_y(G, K)
        factors = ex.dup_factor_list(H, K)[1] if K.is_QQ else [(H, 1)]
        for h, _ in factors:
            Hp = _in_p2(h, K)
            D2 = ex.exquo(D, Hp, K, "denominator")
            A = ex.dup_rem(ex.dup_mul(N, ex.dup_invert(D2, Hp, K), K), Hp, K)
            N = ex.exquo(ex.dup_sub(N, ex.dup_mul(A, D2, K), K), Hp, K, "axis-pole remainder")
            D = D2
            if ex.dup_degree(h) > 1 and not K.is_QQ:
                parts.append(_axis_ladder(A, Hp, K, mode, values))
                continue
            a = ex.even_in_y(ex.exquo(A, [K.one, K.zero], K, "odd part"), K) if A else []
            for v1, v2 in _family_values(a, h, K, values):
                parts.append(_tank(v1, v2, mode))
    N, D = ex.normalize(N, D, K)
    return parts, N, D


def _axis_ladder(A: list, Hp: list, K, mode: str, values: _Values) -> OnePort:
    """The reactance ``A/Hp`` (an impedance in series for ``mode="Z"``, an admittance in parallel for ``"Y"``) of
    imaginary-axis poles at the conjugate roots of ``Hp``, irreducible over the algebraic field ``K``: one tank per
    pole would need each root's own conjugate field, while the Cauer ladder of the whole reactance (continued
    fraction at infinity, Bulgakov (1954), §9.21) has its elements in ``K`` and positive (Cauer's theorem)."""
    other = "Y" if mode == "Z" else "Z"  # A/Hp vanishes at infinity: the ladder starts with its inverse
    return cauer_ladder(Hp, A, K, other, True, positive=values.positive)


def _in_p2(h: list, K) -> list:
    """``h(p²)`` from ``h(y)``."""
    out: list = []
    for i, c in enumerate(h):
        out.append(c)
        if i < len(h) - 1:
            out.append(K.zero)
    return out


class _Values:
    """Element values of one synthesis, kept exact (field element and field) behind positive placeholder symbols
    until the network is complete; :meth:`finish` then writes them all in the largest field used."""

    def __init__(self, immediate: bool = False) -> None:
        self.pending: dict[sp.Dummy, tuple[Any, Any]] = {}
        self.immediate = immediate

    def positive(self, c, K, what: str, sign_of=None) -> sp.Expr:
        """A placeholder for the positive value ``c`` (its sign checked exactly now, on ``sign_of`` if given)."""
        ex.require_positive(c, K, what, sign_of)
        if K.is_QQ or self.immediate:
            return ex.sym(c, K)
        d = sp.Dummy(positive=True)
        self.pending[d] = (c, K)
        return d

    def dual(self, net: OnePort, r2, K) -> OnePort:
        """The dual of the R-L-C tree ``net``, impedance ``r2/Z`` (``r2 > 0`` in ``K``, below every field of ``net``'s
        values): its values lie in the same fields and are positive with those of ``net`` (not checked again)."""

        def scale(v: sp.Expr, kind: str) -> sp.Expr:
            if v not in self.pending:  # an exact number already
                return _clean(scale_expr(ex.sym(r2, K))(v, kind))
            c, F = self.pending[v]
            r = ex.convert(r2, K, F)
            d = sp.Dummy(positive=True)
            scaled = F.quo(r, c) if kind == "R" else F.quo(c, r) if kind == "L" else F.mul(r, c)  # only the one needed
            self.pending[d] = (scaled, F)
            return d

        out = dual(net, r2, scale)
        if out is None:  # pragma: no cover - the cycle builds R-L-C trees only
            raise ModelError("Bott–Duffin: a remainder network has no dual")
        return out

    def finish(self, net: OnePort | None) -> OnePort | None:
        """``net`` with its placeholders replaced by exact numbers, all written in the field above all others (the
        procedures extend one tower; Bott–Duffin's second branch is the dual of its first): one ``CRootOf`` for
        all values, or one per level of the tower above degree 24."""
        fields = {id(K): K for _, K in self.pending.values()}.values()
        top = max(fields, key=ex.field_degree, default=None)
        below = set(map(id, _tower.levels(top)))
        if not all(id(K) in below for K in fields):  # pragma: no cover - one tower by construction
            raise ModelError("synthesis values in fields of different towers")
        items = [(d, c if K == top else top.convert(c)) for d, (c, K) in self.pending.items()]
        if isinstance(top, TowerField):
            exact = _tower.in_sympy_all([c for _, c in items], top)
        else:
            exact = [ex.sym(c, top) for _, c in items]
        subs = {d: _clean(v) for (d, _), v in zip(items, exact, strict=True)}
        if net is None:
            return None
        with values_checked():  # each sign was decided exactly when the value was made
            return _substitute(net, subs)


def _substitute(net: OnePort, subs: dict) -> OnePort:
    changes = {}
    for field in dataclasses.fields(net):
        v = getattr(net, field.name)
        if isinstance(v, OnePort):
            changes[field.name] = _substitute(v, subs)
        elif isinstance(v, tuple):
            changes[field.name] = tuple(_substitute(x, subs) if isinstance(x, OnePort) else x for x in v)
        elif isinstance(v, sp.Basic):
            changes[field.name] = v.xreplace(subs)
    return dataclasses.replace(net, **changes)


class Engine:
    """Brune (``cycle="brune"``) or Bott–Duffin (``cycle="bott_duffin"``) synthesis over a number field."""

    def __init__(self, cycle: str) -> None:
        self.cycle = cycle
        self.values = _Values()
        self._roots: list = []  # (field, ω0²) of the minima found so far
        self._retries = 0

    def _minimum(self, N: list, D: list, K, extend: bool = True):
        """:func:`_minimum` trying the earlier ``ω0²`` first; a new interior ``ω0²`` is remembered."""
        known = tuple(ex.convert(x, F, K) for F, x in self._roots if any(F == L for L in _tower.levels(K)))
        found = _minimum(N, D, K, known=known, extend=extend)
        if found is not None and found[1] not in ("0", "oo"):
            self._roots.append((found[2], found[1]))
        return found

    def run(self, N: list, D: list, K, depth: int = 0) -> OnePort | None:
        if depth > _MAX_DEPTH:  # pragma: no cover - each step lowers the degree
            raise ModelError("synthesis did not terminate")
        N, D = ex.normalize(N, D, K)
        if not N:
            return None
        if ex.dup_degree(N) == 0 and ex.dup_degree(D) == 0:
            return Resistor(self.values.positive(K.quo(N[0], D[0]), K, "resistance"))
        parts, N, D = remove_axis_poles(N, D, K, "Z", self.values)
        if parts:
            return join(parts, self.run(N, D, K, depth + 1), Series)
        parts, Yn, Yd = remove_axis_poles(D, N, K, "Y", self.values)
        if parts:
            inner = None if not Yn else self.run(Yd, Yn, K, depth + 1)
            return join(parts, inner, Parallel)
        # subtract the minimum resistance of Z or the minimum conductance of Y = 1/Z (both keep the function
        # positive real, Theorem III): first one that needs no field extension (decided from numbers), else the one
        # in the smaller field (the other one when the first leads to a field above the limit); a zero minimum
        # starts the cycle at its ω0
        zmin = self._minimum(N, D, K, extend=False)
        if zmin is not None:
            return self._step(zmin, True, depth)
        ymin = self._minimum(D, N, K, extend=False)
        if ymin is not None and ymin[0]:
            return self._remove_constant(*ymin, "Y", depth)
        refusals = []
        for *m, is_z in self._extensions(N, D, K):
            if refusals:  # the other minimum, when the retries allow
                if self._retries >= _MAX_RETRIES:
                    break
                self._retries += 1
            mark = (set(self.values.pending), len(self._roots))
            try:
                return self._step(m, is_z, depth)
            except ex.Nested as exc:  # undo the branch (its values and minima); the refusal naming the least degree
                refusals.append(exc)
                for d in set(self.values.pending) - mark[0]:
                    del self.values.pending[d]
                del self._roots[mark[1] :]
        raise min(refusals, key=lambda exc: exc.degree or float("inf"))

    def _step(self, m: tuple, is_z: bool, depth: int) -> OnePort:
        """Subtract the minimum ``m = (R, x0, K, N, D)`` of ``Re Z`` (``is_z``) or of ``Re Y``, or, when it is zero,
        run the cycle at its ``ω0``."""
        R, x0, K, N, D = m
        if R:
            return self._remove_constant(R, x0, K, N, D, "Z" if is_z else "Y", depth)
        if x0 in ("0", "oo"):  # pragma: no cover - excluded by the removals above
            raise ModelError("Re Z vanishes at 0 or infinity after the pole removals")
        if self.cycle == "brune":
            return self._brune(N, D, x0, K, depth)
        return self._bott_duffin(N, D, x0, K, depth)

    def _extensions(self, N: list, D: list, K) -> list[tuple]:
        """The minima of ``Re Z`` and of ``Re Y`` that need a field extension, tagged (``True`` for ``Z``), the one
        in the smaller field first; the refusal when both need fields above the limit.  A zero minimum is one of
        ``Z`` (``Re Y = Re Z / |Z|²``)."""
        found, refusal = [], None
        for is_z, (n, d) in ((True, (N, D)), (False, (D, N))):
            try:
                m = self._minimum(n, d, K)
            except ex.Nested as exc:
                refusal = refusal or exc
                continue
            if not m[0]:  # the same ω0 for Z: its cycle, in that field
                m = (m[0], m[1], m[2], m[4], m[3]) if not is_z else m
                is_z = True
            found.append((ex.field_degree(m[2]), not is_z, (*m, is_z)))
        if not found:
            raise refusal
        found.sort(key=lambda c: c[:2])
        if all(not c[2][0] for c in found):  # Re Z and Re Y vanish together: one cycle, in the smaller field
            found = found[:1]
        return [c[2] for c in found]

    def _remove_constant(self, R, x0, K, N: list, D: list, mode: str, depth: int) -> OnePort:
        """``Z = R + Z1`` (series resistor) or ``Y = G + Y1`` (shunt resistor ``1/G``)."""
        rest_n = ex.dup_sub(N, ex.dup_mul_ground(D, R, K), K)
        if mode == "Z":
            Rv = self.values.positive(R, K, "minimum resistance")
            return join([Resistor(Rv)], self.run(rest_n, D, K, depth + 1), Series)
        Rv = self.values.positive(K.quo(K.one, R), K, "minimum conductance", sign_of=R)
        inner = None if not rest_n else self.run(D, rest_n, K, depth + 1)
        return join([Resistor(Rv)], inner, Parallel)

    def _brune(self, N: list, D: list, x0, K, depth: int) -> OnePort:
        pD = ex.mul_p(D, K)
        L1 = ex.even_value(N, pD, x0, K)  # Z(iω0) = iω0 L1
        N1 = ex.dup_sub(N, ex.dup_mul_ground(pD, L1, K), K)
        quad = [K.one, K.zero, x0]
        N1q = ex.exquo(N1, quad, K, "Z - L1 p by p² + ω0²")
        twok = ex.even_value(D, ex.mul_p(N1q, K), x0, K)  # Y1 ~ 2k p/(p² + ω0²)
        Y2n = ex.exquo(ex.dup_sub(D, ex.dup_mul_ground(ex.mul_p(N1q, K), twok, K), K), quad, K, "Y1 remainder")
        Z2n, Z2d = ex.normalize(N1q, Y2n, K)
        if ex.dup_degree(Z2n) != ex.dup_degree(Z2d) + 1:
            raise ModelError("Brune cycle: the remainder has no pole at infinity")  # pragma: no cover
        L3 = K.quo(Z2n[0], Z2d[0])
        Z3n = ex.dup_sub(Z2n, ex.dup_mul_ground(ex.mul_p(Z2d, K), L3, K), K)
        L2 = K.quo(K.one, twok)
        Lp, Ls, C = K.add(L1, L2), K.add(L2, L3), K.quo(twok, x0)
        load = self.run(Z3n, Z2d, K, depth + 1)
        if load is None:
            raise ModelError("Brune cycle ended in a short circuit: unexpected for a minimum function")
        vals = [self.values.positive(v, K, name) for v, name in ((Lp, "Lp"), (Ls, "Ls"), (L2, "M"), (C, "C"))]
        return BruneSection(*vals, load)

    def _bott_duffin(self, N: list, D: list, x0, K, depth: int) -> OnePort:
        L = ex.even_value(N, ex.mul_p(D, K), x0, K)  # Z(iω0) = iω0 L
        inductive = ex.sign(L, K) > 0
        if not inductive:  # dual step on the admittance: Y(iω0) = iω0 C, C > 0
            N, D = D, N
            L = ex.even_value(N, ex.mul_p(D, K), x0, K)
        # Richards' k > 0 with F(k) = L k: roots of N - L p D other than ±iω0
        P1 = ex.dup_sub(N, ex.dup_mul_ground(ex.mul_p(D, K), L, K), K)
        P1 = ex.exquo(P1, [K.one, K.zero, x0], K, "F - L p by p² + ω0²")
        k, K2 = _richards_k(P1, K)
        if K2 != K:
            N, D, L, K = ex.to_field(N, K, K2), ex.to_field(D, K, K2), ex.convert(L, K, K2), K2
        Fk = K.mul(L, k)
        # R = (k F - p F(k)) / (k F(k) - p F),  F = N/D
        Rn = ex.dup_sub(ex.dup_mul_ground(N, k, K), ex.dup_mul_ground(ex.mul_p(D, K), Fk, K), K)
        Rd = ex.dup_sub(ex.dup_mul_ground(D, K.mul(k, Fk), K), ex.mul_p(N, K), K)

        def sub(n: list, d: list) -> OnePort:
            net = self.run(n, d, K, depth + 1)
            if net is None:  # pragma: no cover
                raise ModelError("Bott–Duffin: a remainder vanished identically")
            return net

        if ex.sign(k, K) <= 0:  # pragma: no cover - a positive root was chosen
            raise ModelError("Bott–Duffin: Richards' k is not positive")
        C1 = self.values.positive(K.quo(K.one, K.mul(k, Fk)), K, "Bott–Duffin element")
        L1 = self.values.positive(K.quo(Fk, k), K, "Bott–Duffin element")
        # the second remainder is the first one's dual: Fk/R = Fk²/(Fk R), so it is built from it (same field)
        # instead of synthesised again, where it would extend the field separately (Bott & Duffin 1949)
        r2 = K.mul(Fk, Fk)
        if inductive:
            z1 = sub(ex.dup_mul_ground(Rn, Fk, K), Rd)  # Fk R
            return Series((Parallel((Capacitor(C1), z1)), Parallel((Inductor(L1), self.values.dual(z1, r2, K)))))
        y1 = sub(Rd, ex.dup_mul_ground(Rn, Fk, K))  # 1/(Fk R)
        r2 = K.quo(K.one, r2)  # R/Fk = (1/Fk²) Fk R
        return Parallel((Series((y1, Inductor(C1))), Series((Capacitor(L1), self.values.dual(y1, r2, K)))))


def _richards_k(P1: list, K):
    """A positive root ``k`` of ``P1`` (Bulgakov (1954), eq. (9.409)), exact; the field may be extended once."""
    if K.is_QQ:
        roots = sorted(
            (r for r in ex.real_roots_qq(P1) if sp.N(r, ex._DIGITS) > 0), key=lambda r: (not r.is_Rational, 0)
        )
        if not roots:  # pragma: no cover - guaranteed by Z(k)/k running from oo to 0
            raise ModelError("Bott–Duffin: Z(k) = L k has no positive root")
        r = roots[0]
        K2 = ex.extension(r, "Richards' k with Z(k) = L k")
        return K2.from_sympy(r), K2
    P1 = ex.squarefree_part(P1, K)
    positive = ex.numeric_positive_roots(P1, K)
    if not positive:  # pragma: no cover - guaranteed by Z(k)/k running from oo to 0
        raise ModelError("Bott–Duffin: Z(k) = L k has no positive root")
    return ex.extend_with_root(P1, K, positive[0], "Richards' k with Z(k) = L k")


def synthesize(Z: Any, p: sp.Symbol, cycle: str, max_degree: int | None = None) -> OnePort | None:
    """Network with impedance ``Z`` (None for a short circuit), by the Brune or the Bott–Duffin cycle, in number
    fields of degree at most ``max_degree`` (the default limit when None)."""
    N, D, K = to_exact(Z, p)
    engine = Engine(cycle)
    with ex.field_degree_limit(max_degree):
        return engine.values.finish(engine.run(N, D, K))


def cauer_ladder(N: list, D: list, K, mode: str, at_infinity: bool, positive: Any = ex.positive) -> OnePort:
    """Continued fraction of ``F = N/D``: remove the pole at infinity (or zero), invert, repeat (exact over K).
    ``positive(c, K, what)`` turns a coefficient into an element value (checking its sign)."""
    elements: list[tuple[OnePort, str]] = []
    while True:
        if at_infinity:
            if ex.dup_degree(N) != ex.dup_degree(D) + 1:
                raise ParameterError("Cauer expansion stalled: the remainder has no pole where expected (not LC)")
            k = K.quo(N[0], D[0])
            kv = positive(k, K, "Cauer coefficient")
            element = Inductor(kv) if mode == "Z" else Capacitor(kv)
            N = ex.dup_sub(N, ex.dup_mul_ground(ex.mul_p(D, K), k, K), K)
        else:
            if not D or D[-1] or not D[:-1] or not D[-2]:
                raise ParameterError("Cauer expansion stalled: the remainder has no pole where expected (not LC)")
            D = D[:-1]
            k = K.quo(ex.dup_eval(N, K.zero, K), D[-1])
            kv = positive(k, K, "Cauer coefficient")
            element = Capacitor(1 / kv) if mode == "Z" else Inductor(1 / kv)
            N = ex.exquo(ex.dup_sub(N, ex.dup_mul_ground(D, k, K), K), [K.one, K.zero], K, "Cauer remainder")
        elements.append((element, mode))
        if not N:
            break
        N, D = ex.normalize(D, N, K)
        mode = "Y" if mode == "Z" else "Z"
    net = elements[-1][0]
    for element, m in reversed(elements[:-1]):
        net = Series((element, net)) if m == "Z" else Parallel((element, net))
    return net
