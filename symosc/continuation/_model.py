"""The model every method of :mod:`symosc.continuation` works on (private).

Whatever the user gives (an acceleration ``x'' = a(x, x', t)``, several of them, a
:class:`~symosc.mechanics.LagrangianSystem` or a :class:`~symosc.mechanics.FirstOrderSystem`) becomes
``M(q, t) q'' = F(q, q', t)`` with parameter symbols, and two compiled forms of it:

* the harmonic-balance pieces: in the phase ``tau = omega t`` (with ``q' = omega q_tau``) the residual
  ``r = M omega**2 q_tautau - F(q, omega q_tau, tau)`` and its exact derivatives with respect to ``q``,
  ``q_tau``, ``q_tautau``, ``omega`` and every parameter, compiled in one function evaluated at all time samples
  at once (alternating frequency-time);
* the explicit first-order form ``y' = f(y, t)``, ``y = (q, q')``, with ``df/dy`` and ``df/dp`` (shooting,
  collocation, monodromy).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from functools import cached_property
from typing import Any

import numpy as np
import sympy as sp

from .._validate import check_finite
from ..errors import ModelError, ParameterError
from ..symbols import sort_symbols

TAU = sp.Symbol("tau_", real=True)
OMEGA = sp.Symbol("omega_", positive=True)


def _as_expr(value: Any, what: str) -> sp.Expr:
    if isinstance(value, str | bytes) or value is None:
        raise ParameterError(f"{what} must be a SymPy expression, got {value!r}")
    try:
        e = sp.sympify(value, strict=True)
    except (sp.SympifyError, TypeError) as exc:
        raise ParameterError(f"{what} must be a SymPy expression, got {value!r}") from exc
    if not isinstance(e, sp.Expr):
        raise ParameterError(f"{what} must be a scalar SymPy expression, got {type(e).__name__}")
    return e


def _symbols(value: Any, what: str, n: int | None = None) -> tuple[sp.Symbol, ...]:
    items = [value] if isinstance(value, sp.Symbol) else list(value) if isinstance(value, Sequence) else None
    if not items or not all(isinstance(s, sp.Symbol) for s in items):
        raise ParameterError(f"{what} must be a SymPy Symbol (or a sequence of Symbols), got {value!r}")
    if n is not None and len(items) != n:
        raise ParameterError(f"{what} must hold {n} symbols (one per coordinate), got {len(items)}")
    return tuple(items)


class PeriodicModel:
    """``M(q, t) q'' = F(q, q', t)`` with its parameters, the forcing frequency symbol and compiled pieces."""

    def __init__(
        self,
        M: sp.Matrix,
        F: sp.Matrix,
        q: tuple[sp.Symbol, ...],
        qd: tuple[sp.Symbol, ...],
        t: sp.Symbol,
        forcing_frequency: sp.Symbol | None,
        autonomous: bool,
        describe: str,
    ) -> None:
        self.M, self.F, self.q, self.qd, self.t = M, F, q, qd, t
        self.forcing_frequency = forcing_frequency
        self.autonomous = autonomous
        self.describe = describe
        n = len(q)
        self.n = n
        free = set().union(*(e.free_symbols for e in (*M, *F)))
        if autonomous and t in free:
            raise ModelError(
                f"the equations depend on time {t} but autonomous=True: a forced system needs forcing_frequency="
            )
        if not autonomous:
            if forcing_frequency is None:
                raise ParameterError(
                    "forcing_frequency must be the Symbol of the forcing frequency (or pass autonomous=True)"
                )
            if t not in free:
                raise ModelError(
                    f"forcing_frequency={forcing_frequency} was given but the equations do not depend on time {t}; "
                    "for a self-excited system pass autonomous=True"
                )
        params = free - set(q) - set(qd) - {t}
        if forcing_frequency is not None:
            params.add(forcing_frequency)
        self.params: tuple[sp.Symbol, ...] = sort_symbols(params)

    def __getstate__(self) -> dict:
        """Pickle the equations; the compiled functions are rebuilt on use (from the C build cache)."""
        return {k: v for k, v in self.__dict__.items() if k not in ("_hb_cache", "first_order_function", "explicit")}

    # ------------------------------------------------------------------ values
    def values_vector(self, values: Mapping[Any, Any], *, skip: tuple[sp.Symbol, ...] = ()) -> np.ndarray:
        """Parameter values in the order of :attr:`params` (``skip``: symbols whose value may be missing -> nan)."""
        by_name: dict[str, Any] = {}
        for k, v in (values or {}).items():
            by_name[k.name if isinstance(k, sp.Symbol) else str(k)] = v
        names = [s.name for s in self.params]
        unknown = sorted(set(by_name) - set(names))
        if unknown:
            raise ParameterError(f"values: unknown parameter(s) {unknown}; the model's parameters are {names}")
        out = np.full(len(self.params), np.nan)
        missing = []
        for i, s in enumerate(self.params):
            if s.name in by_name:
                out[i] = check_finite(f"values[{s.name!r}]", by_name[s.name])
                if s.is_positive and out[i] <= 0:
                    raise ParameterError(f"values[{s.name!r}] must be positive (declared positive), got {out[i]}")
            elif s not in skip:
                missing.append(s.name)
        if missing:
            raise ParameterError(f"values: missing value(s) for {', '.join(missing)}; give them in values=")
        return out

    def param_index(self, parameter: Any) -> int:
        name = parameter.name if isinstance(parameter, sp.Symbol) else str(parameter)
        for i, s in enumerate(self.params):
            if s.name == name:
                return i
        raise ParameterError(
            f"parameter {name!r} is not a parameter of the model; choose one of {[s.name for s in self.params]}"
        )

    # ------------------------------------------------------------------ harmonic balance pieces
    def phase_form(self, period_multiple: int) -> tuple[sp.Matrix, list, list, list]:
        """Residual ``r(tau, z, zd, zdd, omega, p)`` in the phase and the symbols z, zd, zdd."""
        n = self.n
        z = [sp.Symbol(f"z{i}_", real=True) for i in range(n)]
        zd = [sp.Symbol(f"zd{i}_", real=True) for i in range(n)]
        zdd = [sp.Symbol(f"zdd{i}_", real=True) for i in range(n)]
        sub: dict[sp.Symbol, sp.Expr] = dict(zip(self.q, z, strict=True))
        sub.update({v: OMEGA * d for v, d in zip(self.qd, zd, strict=True)})
        if not self.autonomous:  # omega = w / m: w t = m tau
            sub[self.t] = period_multiple * TAU / self.forcing_frequency
        M = self.M.xreplace(sub)
        F = self.F.xreplace(sub)
        r = M * sp.Matrix(zdd) * OMEGA**2 - F
        r = r.applyfunc(lambda e: sp.expand_trig(e) if e.has(TAU) else e)
        return r, z, zd, zdd

    def polynomial_degree(self, r: sp.Matrix, gens: list) -> tuple[int, int] | None:
        """(degree in the unknowns, harmonic degree in tau) when r is a polynomial in the unknowns whose
        coefficients are trigonometric polynomials of integer multiples of tau; None otherwise."""
        deg, tdeg = 0, 0
        for e in r:
            try:
                poly = sp.Poly(sp.expand(e), *gens)
            except sp.PolynomialError:
                return None
            deg = max(deg, poly.total_degree())
            for c in poly.coeffs():
                k = _trig_degree(c)
                if k is None:
                    return None
                tdeg = max(tdeg, k)
        return deg, tdeg

    def hb_function(self, period_multiple: int):
        """Compiled ``[r, dr/dz, dr/dzd, dr/dzdd, dr/domega, dr/dp]`` and the degree information (cached)."""
        key = period_multiple
        cache = self.__dict__.setdefault("_hb_cache", {})
        if key in cache:
            return cache[key]
        from ..numeric import compile

        r, z, zd, zdd = self.phase_form(period_multiple)
        gens = [*z, *zd, *zdd]
        degree = self.polynomial_degree(r, gens)
        J = [r.jacobian(z), r.jacobian(zd), r.jacobian(zdd), r.diff(OMEGA), r.jacobian(list(self.params))]
        items = list(r) + [e for m in J for e in m]
        fn = compile(items, [TAU, *z, *zd, *zdd, OMEGA, *self.params], backend="auto", check=False, name="hb_pieces")
        cache[key] = (fn, degree)
        return cache[key]

    # ------------------------------------------------------------------ first-order form
    @cached_property
    def explicit(self) -> sp.Matrix:
        """``f(y, t) = (q', M^-1 F)``."""
        n = self.n
        if self.M == sp.eye(n):
            acc = self.F
        else:
            if n > 3:
                raise ModelError(
                    "shooting, collocation and the monodromy matrix need the explicit form M^-1 F, formed "
                    f"symbolically for at most 3 coordinates (this model has {n}); "
                    "use harmonic balance with Hill's method"
                )
            acc = self.M.LUsolve(self.F)
        return sp.Matrix(list(self.qd)).col_join(sp.Matrix(acc))

    @cached_property
    def first_order_function(self):
        """Compiled ``[f, df/dy, df/dp]`` with arguments ``(t, y, p)``."""
        from ..numeric import compile

        y = [*self.q, *self.qd]
        f = self.explicit
        items = list(f) + list(f.jacobian(y)) + list(f.jacobian(list(self.params)))
        return compile(items, [self.t, *y, *self.params], backend="auto", check=False, name="first_order_pieces")

    def first_order(self, p: np.ndarray) -> FirstOrderEvaluator:
        return FirstOrderEvaluator(self.first_order_function, 2 * self.n, len(self.params), p)


class FirstOrderEvaluator:
    """``f(t, y)``, ``df/dy`` and ``df/dp`` at fixed parameter values, for a single state or a batch of states."""

    def __init__(self, fn: Any, dim: int, npar: int, p: np.ndarray) -> None:
        self.raw, self.dim, self.npar = fn.raw, dim, npar
        self.p = [float(x) for x in p]

    def all(self, t: Any, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """f (..., d), A (..., d, d), f_p (..., d, npar) for y of shape (d,) or (k, d) and t scalar or (k,)."""
        y = np.asarray(y, dtype=float)
        out = np.asarray(self.raw(t, *np.moveaxis(y, -1, 0), *self.p))
        d, npar = self.dim, self.npar
        f = out[..., :d]
        A = out[..., d : d + d * d].reshape(*out.shape[:-1], d, d)
        fp = out[..., d + d * d :].reshape(*out.shape[:-1], d, npar)
        return f, A, fp

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        return self.all(t, y)[0]


def _trig_degree(c: sp.Expr) -> int | None:
    """Largest harmonic of tau in a coefficient polynomial in cos(k tau), sin(k tau); None if not of that form."""
    if not c.has(TAU):
        return 0
    atoms = [a for a in c.atoms(sp.Function) if a.has(TAU)]
    ks = []
    for a in atoms:
        if not isinstance(a, sp.sin | sp.cos):
            return None
        k = sp.simplify(a.args[0] / TAU)
        if not (k.is_number and k.is_integer):
            return None
        ks.append(abs(int(k)))
    try:
        poly = sp.Poly(c, *atoms)
    except sp.PolynomialError:
        return None
    if TAU in poly.free_symbols_in_domain:
        return None
    best = 0
    for monom in poly.monoms():
        best = max(best, sum(e * k for e, k in zip(monom, ks, strict=True)))
    return best


def build_model(
    system: Any,
    x: Any = None,
    v: Any = None,
    t: Any = None,
    *,
    forcing_frequency: Any = None,
    autonomous: bool = False,
) -> PeriodicModel:
    """A :class:`PeriodicModel` from an acceleration expression (or several), a Lagrangian or first-order system."""
    from ..symbols import t as symosc_t

    if forcing_frequency is not None and not isinstance(forcing_frequency, sp.Symbol):
        raise ParameterError(f"forcing_frequency must be a SymPy Symbol (or None), got {forcing_frequency!r}")
    kind = type(system).__name__
    if kind == "FirstOrderSystem" and hasattr(system, "system"):
        system = system.system
        kind = type(system).__name__
    if kind == "LagrangianSystem" and hasattr(system, "mass_matrix"):
        if system.is_constrained:
            raise ModelError("the system has constraints: reduce it to independent coordinates first")
        tt = symosc_t if t is None else _symbols(t, "t")[0]
        return PeriodicModel(
            sp.Matrix(system.mass_matrix),
            sp.Matrix(system.forcing),
            tuple(system.coordinates),
            tuple(system.velocities),
            tt,
            forcing_frequency,
            autonomous,
            repr(system),
        )
    if isinstance(system, sp.MatrixBase | list | tuple):
        accs = [_as_expr(e, f"acceleration[{i}]") for i, e in enumerate(system)]
    else:
        accs = [_as_expr(system, "acceleration")]
    n = len(accs)
    if x is None or v is None:
        raise ParameterError("x and v must be the coordinate and velocity Symbols used in the acceleration")
    q = _symbols(x, "x", n)
    qd = _symbols(v, "v", n)
    if len(set(q) | set(qd)) != 2 * n:
        raise ParameterError("x and v must be distinct Symbols")
    tt = symosc_t if t is None else _symbols(t, "t")[0]
    text = "; ".join(f"{a}'' = {e}" for a, e in zip(q, accs, strict=True))
    return PeriodicModel(sp.eye(n), sp.Matrix(accs), q, qd, tt, forcing_frequency, autonomous, text)
