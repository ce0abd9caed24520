"""Helpers of :mod:`symosc.nonlinear.averaging.normal_form` (private): roots of ``Delta``, exact-constant clean-up,
and the numeric evaluation of the shortened equations (compiled exact averages or torus quadrature)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ...errors import ModelError, ParameterError
from ...numeric import compile as _compile

if TYPE_CHECKING:  # pragma: no cover
    from .normal_form import ShortenedEquations

__all__: list[str] = []

_DPS = 30


def _roots(delta: sp.Poly) -> list:
    """Simple roots of ``Delta``: exact for rational factors of degree <= 2 (also quadratic in ``D**2``), otherwise
    30-digit floats (general radicals of cubics and quartics are too slow to simplify and no more useful)."""
    out: list = []
    _, factors = sp.factor_list(delta)
    for g, mult in factors:
        if mult > 1:
            raise ModelError(
                f"Delta(D) has the multiple factor ({g.as_expr()})**{mult}: the normal form needs simple roots "
                "(Bulgakov (1954), §12.11, formulas (12.146)-(12.153)); perturb the parameters slightly"
            )
        D = g.gen
        coeffs = g.all_coeffs()
        if g.degree() <= 2:
            out += [sp.expand_complex(r) for r in sp.roots(g, multiple=True)]
        elif g.degree() == 4 and all(c == 0 for c in coeffs[1::2]):  # quadratic in D**2: SymPy is quick here
            out += list(sp.roots(g, multiple=True))
        else:
            out += [sp.re(r) + sp.I * sp.im(r) for r in sp.Poly(g.as_expr(), D).nroots(n=_DPS, maxsteps=200)]
    vals = np.array([complex(sp.N(r, _DPS)) for r in out])
    scale = max(1.0, float(np.max(np.abs(vals))))
    for i in range(len(vals)):
        for j in range(i):
            if abs(vals[i] - vals[j]) < 1e-8 * scale:
                raise ModelError(
                    f"Delta(D) has (nearly) multiple roots near {vals[i]:.8g}: the normal form needs simple roots"
                )
    return out


def _is_real(r: sp.Expr) -> bool:
    im = sp.im(r)
    if im.is_zero:
        return True
    v = complex(sp.N(r, _DPS))
    return abs(v.imag) <= 1e-20 * max(1.0, abs(v))


def _clean(e: sp.Expr, exact: bool) -> sp.Expr:
    if exact:
        e = sp.expand_complex(e)
        return _simplest_number(e) if not e.free_symbols else e
    return sp.N(sp.expand_complex(e), _DPS)


def _operator(fD: Any, D: Any) -> sp.Matrix:
    if not isinstance(D, sp.Symbol):
        raise ParameterError(f"D must be a Symbol, got {type(D).__name__}")
    if fD is None:
        raise ParameterError("fD must be a square matrix of polynomials in D, got None")
    try:
        f = sp.Matrix(fD)
    except (TypeError, ValueError, sp.SympifyError) as exc:
        raise ParameterError(f"fD must be a square SymPy matrix, got {type(fD).__name__}") from exc
    n = f.shape[0]
    if n == 0 or f.shape != (n, n):
        raise ParameterError(f"fD must be square and non-empty, got shape {f.shape}")
    if f.free_symbols - {D}:
        raise ParameterError(f"fD must be numeric apart from {D}; substitute {sorted(map(str, f.free_symbols - {D}))}")
    for e in f:
        if not e.is_polynomial(D):
            raise ModelError(f"fD entries must be polynomials in {D}, got {e}")
        if any(not np.isfinite(complex(c)) for c in sp.Poly(e, D).all_coeffs()):
            raise ParameterError(f"fD has a non-finite coefficient in {e}")
    return f


def _tidy(e: sp.Expr, variables: Sequence[sp.Symbol]) -> sp.Expr:
    """Collect in the slow variables (and polynomial parameters) and simplify each constant coefficient."""
    e = sp.expand(e)
    gens = [*variables, *sorted(e.free_symbols - set(variables), key=lambda s: s.name)]
    if not gens or not e.is_polynomial(*gens):
        return e
    out = sp.S.Zero
    for mono, c in sp.Poly(e, *gens).terms():
        out += _simplest_number(c) * sp.Mul(*[v**k for v, k in zip(gens, mono, strict=True)])
    return out


def _simplest_number(c: sp.Expr) -> sp.Expr:
    """A shorter closed form of the constant ``c`` (nested radicals of the roots often collapse), accepted only if
    it agrees with ``c`` to 100 digits; otherwise ``c`` itself."""
    if c.is_Rational or c.has(sp.Float):
        return c
    try:
        cand = sp.nsimplify(sp.N(c, 60), rational=False)
        ok = abs(complex(sp.N(cand - c, 110))) < 1e-95 * max(1.0, abs(complex(sp.N(c, 20))))
    except (TypeError, ValueError, ArithmeticError, AssertionError):  # pragma: no cover - nsimplify gave up
        return c
    return cand if ok and sp.count_ops(cand) < sp.count_ops(c) else c


_CACHE: dict = {}


def _compiled(sh: ShortenedEquations) -> tuple:
    key = id(sh)
    hit = _CACHE.get(key)
    if hit is not None and hit[0] is sh:
        return hit[1]
    nf = sh.normal_form
    args = [*sh.variables, *sh.parameters]
    if sh.rates is not None:
        J = sp.Matrix(sh.rates).jacobian(sp.Matrix(sh.variables)) if sh.variables else sp.zeros(0, 0)
        out = (
            "exact",
            _compile(list(sh.rates), args, check=False).raw if sh.rates else None,
            _compile(list(sh.phase_rates), args, check=False).raw if sh.phase_rates else None,
            _compile(J, args, check=False).raw if J.shape[0] else None,
        )
    else:
        zero = {nf.amplitudes[h]: 0 for h in range(len(nf.complex_roots)) if h not in sh.active}
        phases = [nf.phases[h] for h in sh.active]
        slow = [e.xreplace(zero) for e in nf.xi_dot] + [nf.a_dot[h].xreplace(zero) for h in sh.active]
        fast = [(nf.u_dot[h] * nf.amplitudes[h]).xreplace(zero) for h in sh.active]
        out = ("torus", _compile(slow + fast, [*args, *phases], check=False).raw, phases)
    _CACHE.clear() if len(_CACHE) > 32 else None
    _CACHE[key] = (sh, out)
    return out


def _rates(sh: ShortenedEquations, x: np.ndarray, p: list[float]) -> tuple[np.ndarray, np.ndarray]:
    nf = sh.normal_form
    comp = _compiled(sh)
    ns = len(nf.xi)
    nvar = len(sh.variables)
    if comp[0] == "exact":
        _, fr, fp, _fj = comp
        r = np.asarray(fr(*x, *p), dtype=float).reshape(nvar) if fr is not None else np.zeros(0)
        if fp is None:
            return r, np.zeros(0)
        return r, np.asarray(fp(*x, *p), dtype=float).reshape(len(sh.active))
    _, f, phases = comp
    N = sh.n_samples
    grid = np.meshgrid(*[2 * np.pi * np.arange(N) / N] * len(phases), indexing="ij") if phases else []
    nout = nvar + len(sh.active)
    gshape = grid[0].shape if grid else ()
    vals = np.broadcast_to(np.asarray(f(*x, *p, *grid), dtype=float), (*gshape, nout))  # compiled: (..., n_out)
    avg = vals.reshape(-1, nout).mean(axis=0)
    amps = x[ns:]
    with np.errstate(divide="ignore", invalid="ignore"):
        om = avg[nvar:] / np.where(amps == 0, np.nan, amps)
    return avg[:nvar], om


def _jacobian_values(sh: ShortenedEquations, x: np.ndarray, p: list[float]) -> np.ndarray:
    comp = _compiled(sh)
    nvar = len(sh.variables)
    if nvar == 0:
        return np.zeros((0, 0))
    if comp[0] == "exact":
        return np.asarray(comp[3](*x, *p), dtype=float).reshape(nvar, nvar)
    scale = max(1.0, float(np.max(np.abs(x))))
    h = 1e-6 * scale
    cols = []
    for i in range(nvar):
        e = np.zeros(nvar)
        e[i] = h
        cols.append((_rates(sh, x + e, p)[0] - _rates(sh, x - e, p)[0]) / (2 * h))
    return np.column_stack(cols)
