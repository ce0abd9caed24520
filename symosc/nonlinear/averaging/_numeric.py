"""Numerical side of :mod:`symosc.nonlinear.averaging`: stationary regimes, steady forced states, resonance curves.

Everything is evaluated from the symbolic shortened equations through :func:`symosc.numeric.compile`.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from ..._plotting import plot_method
from ..._printing import SymPyPrintable
from ...errors import ConvergenceError, ModelError, ParameterError
from ...numeric import bind, compile

if TYPE_CHECKING:  # pragma: no cover
    from .shortened import AveragedEquations

#: Amplitude symbol of the shortened equations.
a = sp.Symbol("a", positive=True)
#: Phase lag of the response behind the forcing (forced case) / total phase (autonomous case).
theta = sp.Symbol("theta", real=True)


__all__ = ["Fold", "FrequencyResponse", "StationaryRegime", "SteadyState"]


def _vcompile(exprs: Any, args: list) -> Any:
    """``numeric.compile(...).raw`` with the NumPy backend; expressions with special functions the NumPy printer
    does not know (Bessel functions from averaging sin/exp nonlinearities) fall back to the mpmath backend,
    vectorised element-wise (slower, same values)."""
    try:
        return compile(exprs, args, check=False).raw
    except Exception:  # the code printer raises several types for unsupported functions
        f = compile(exprs, args, backend="mpmath", check=False).raw
        many = isinstance(exprs, (list, tuple))

        def scalar(*vals):
            out = f(*vals)
            return tuple(float(v) for v in out) if many else float(out)

        if many:
            vec = np.vectorize(scalar, otypes=[float] * len(exprs))
            return lambda *vals: np.array(vec(*vals))
        return np.vectorize(scalar, otypes=[float])


def _bound(avg: AveragedEquations, expr: Any, values: dict | None, keep: set) -> sp.Expr:
    expr = sp.sympify(expr)
    if values is not None:
        expr = bind(expr, values)
    missing = sorted(s.name for s in expr.free_symbols - keep)
    if missing:
        raise ParameterError("missing values for: " + ", ".join(missing))
    return expr


# ---------------------------------------------------------------------------------------------- autonomous
def autonomous_stationary(avg: AveragedEquations, values: dict | None) -> tuple[StationaryRegime, ...]:
    g = sp.expand(a * avg.Phi)
    psi = avg.Psi
    if values is not None:
        g = _bound(avg, g, values, {a})
        psi = _bound(avg, psi, values, {a})
    dg = sp.diff(g, a)
    out = []
    g0 = sp.limit(g, a, 0, "+")
    if g0 == 0:
        out.append((sp.S.Zero, sp.limit(psi, a, 0, "+"), sp.limit(dg, a, 0, "+")))
    h = sp.numer(sp.together(sp.expand(g / a)))
    if values is not None and h.is_polynomial(a):
        poly = sp.Poly(h, a)
        roots = []
        if poly.degree() > 0:
            for r in poly.nroots(n=30):
                if abs(sp.im(r)) < 1e-20 and sp.re(r) > 0:
                    roots.append(sp.Float(sp.re(r), 15))
    else:
        roots = [r for r in sp.solve(h, a) if r.is_positive is not False]
        if values is not None:
            roots = [sp.Float(sp.N(r, 20), 15) for r in roots]
    for r in sorted(roots, key=lambda r: sp.N(r) if r.is_number else 0):
        out.append((r, sp.simplify(psi.subs(a, r)), sp.simplify(dg.subs(a, r))))
    regs = []
    for amp, freq, d in out:
        pos = d.is_positive
        stable = True if pos else (False if d.is_negative else None)
        if values is not None:
            freq, d = sp.Float(sp.N(freq), 15), sp.Float(sp.N(d), 15)
        regs.append(StationaryRegime(amplitude=amp, frequency=freq, exponent=-d, stable=stable))
    return tuple(regs)


def integrate_shortened(avg: AveragedEquations, a0: float, t_eval: Any, values: dict, theta0: float, rtol: float):
    from scipy.integrate import solve_ivp

    if not a0 > 0:
        raise ParameterError(f"a0 must be positive, got {a0}")
    t_eval = np.asarray(t_eval, dtype=float)
    ad = _bound(avg, avg.a_dot, values, {a, theta})
    pd = _bound(avg, avg.phase_dot, values, {a, theta})
    fn = _vcompile([ad, pd], [a, theta])

    def rhs(_t, y):
        return fn(y[0], y[1])

    sol = solve_ivp(rhs, (0.0, float(t_eval[-1])), [float(a0), float(theta0)], t_eval=t_eval, rtol=rtol, atol=1e-12)
    if not sol.success:
        raise ConvergenceError(f"integration of the shortened equations failed: {sol.message}")
    return sol.y[0] if avg.kind == "autonomous" else sol.y


# ---------------------------------------------------------------------------------------------- forced
@dataclass(frozen=True)
class SteadyState(SymPyPrintable):
    """A steady forced response ``x = a cos(nu t - theta)`` (first approximation).

    Attributes
    ----------
    nu : float
        Forcing frequency.
    amplitude : float
        Steady amplitude ``a`` (a root of ``W(nu, a) = 0``, Bulgakov (6.21)).
    theta : float
        Phase lag ``theta`` of the response behind the forcing, in radians in ``(-pi, pi]``.
    M1, M2 : float
        The Routh quantities of the variational equations (6.24): minus the trace and the determinant.
    kind : {"stable", "center", "saddle", "unstable"}
        ``"stable"`` (M1 > 0, M2 > 0), ``"center"`` (undamped, M1 = 0, M2 > 0: Lyapunov-stable), ``"saddle"``
        (M2 < 0) or ``"unstable"`` (M2 > 0, M1 < 0).
    """

    nu: float
    amplitude: float
    theta: float
    M1: float
    M2: float
    kind: str

    @property
    def stable(self) -> bool:
        return self.kind in ("stable", "center")


@dataclass(frozen=True)
class Fold(SymPyPrintable):
    """A fold (vertical tangent) of the resonance curve: a jump frequency.

    Attributes
    ----------
    nu : float
        Forcing frequency of the fold (the jump frequency).
    amplitude : float
        Amplitude at the fold.
    refined : bool
        Whether Newton's method on ``W = dW/da = 0`` converged (otherwise the values are the sampled estimate).
    """

    nu: float
    amplitude: float
    refined: bool


@dataclass(frozen=True)
class FrequencyResponse(SymPyPrintable):
    """Resonance curve ``W(nu, a) = 0`` sampled over ``nu``.

    Attributes
    ----------
    nu : ndarray, shape (n,)
        The sampled forcing frequencies, ascending.
    amplitudes : ndarray, shape (n, branches)
        ``amplitudes[i]`` holds every steady amplitude at ``nu[i]``, ascending (NaN-padded).
    stable : ndarray of bool, shape (n, branches)
        Marks the stable steady states.
    folds : tuple of Fold
        The fold (jump) points, ascending in ``nu``.
    """

    nu: np.ndarray
    amplitudes: np.ndarray
    stable: np.ndarray
    folds: tuple[Fold, ...]

    @property
    def jump_frequencies(self) -> tuple[float, ...]:
        """Forcing frequencies of the folds, ascending."""
        return tuple(sorted(fd.nu for fd in self.folds))

    def multivalued(self) -> np.ndarray:
        """Boolean mask of the sampled frequencies with more than one steady state."""
        return np.sum(np.isfinite(self.amplitudes), axis=1) > 1

    def __repr__(self) -> str:
        jumps = ", ".join(f"{fd.nu:.6g}" for fd in sorted(self.folds, key=lambda f: f.nu))
        return (
            f"FrequencyResponse(nu in [{self.nu[0]:.4g}, {self.nu[-1]:.4g}], {len(self.nu)} samples, "
            f"max branches {self.amplitudes.shape[1]}, folds at nu = [{jumps}])"
        )

    def branches(self) -> list[tuple[np.ndarray, np.ndarray, bool]]:
        """The curve as continuous pieces ``(nu, a, stable)``: the roots followed from sample to sample, pieces
        that appear or end between two samples joined at the fold there, each piece split where its stability
        changes (neighbouring pieces share their end point, so the drawn curve has no gaps)."""
        counts = np.sum(np.isfinite(self.amplitudes), axis=1)
        folds = [(f.nu, f.amplitude) for f in self.folds]
        tracks: list[list[tuple[float, float, bool | None]]] = []
        open_: list[int] = []  # index into tracks of the track holding root k of the previous sample

        def fold_between(lo: float, hi: float, a: float) -> tuple[float, float, None] | None:
            near = [f for f in folds if lo - 1e-12 <= f[0] <= hi + 1e-12]
            if not near:
                return None
            f = min(near, key=lambda f: abs(f[1] - a))
            return (f[0], f[1], None)

        for i, nu in enumerate(self.nu):
            rs, st = self.amplitudes[i, : counts[i]], self.stable[i, : counts[i]]
            if i > 0 and counts[i] == counts[i - 1]:
                for k in range(counts[i]):
                    tracks[open_[k]].append((nu, rs[k], bool(st[k])))
                continue
            prev = [tracks[j][-1][1] for j in open_]
            pairs = sorted(((abs(p - r), j, k) for j, p in enumerate(prev) for k, r in enumerate(rs)))
            used_prev, used_new, new_open = set(), set(), [None] * counts[i]
            for _, j, k in pairs:  # greedy one-to-one matching of the roots that continue
                if j in used_prev or k in used_new or len(used_prev) >= min(len(prev), counts[i]):
                    continue
                used_prev.add(j)
                used_new.add(k)
                new_open[k] = open_[j]
            lo = self.nu[i - 1] if i > 0 else nu
            for j, tj in enumerate(open_):  # roots that end: close their track at the fold
                if j not in used_prev:
                    f = fold_between(lo, nu, tracks[tj][-1][1])
                    if f is not None:
                        tracks[tj].append(f)
            for k in range(counts[i]):
                if new_open[k] is None:  # roots that appear: a new track starting at the fold
                    f = fold_between(lo, nu, rs[k]) if i > 0 else None
                    tracks.append([f] if f is not None else [])
                    new_open[k] = len(tracks) - 1
                tracks[new_open[k]].append((nu, rs[k], bool(st[k])))
            open_ = new_open
        pieces = []
        for tr in tracks:
            pts = [list(p) for p in tr]
            for m, p in enumerate(pts):  # a fold point takes the stability of its neighbour
                if p[2] is None:
                    p[2] = pts[m - 1][2] if m > 0 else (pts[1][2] if len(pts) > 1 else True)
            start = 0
            for m in range(1, len(pts) + 1):
                if m == len(pts) or pts[m][2] != pts[start][2]:
                    chunk = pts[start : m + 1] if m < len(pts) else pts[start:m]
                    if len(chunk) >= 2:
                        arr = np.array([(x[0], x[1]) for x in chunk], dtype=float)
                        pieces.append((arr[:, 0], arr[:, 1], bool(pts[start][2])))
                    start = m
        return pieces

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Draw the resonance curve as continuous branches: stable solid, unstable dashed, folds (jumps) circled.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Draw here; a new figure otherwise.

        Returns
        -------
        matplotlib Axes
        """
        from ..._plotting import new_axes

        ax = new_axes(ax)
        labelled = set()
        for nu, amp, stable in self.branches():
            label = "stable" if stable else "unstable"
            ax.plot(
                nu, amp, "-" if stable else "--", color="C0" if stable else "C3", lw=1.6 if stable else 1.3,
                label=None if label in labelled else label,
            )  # fmt: skip
            labelled.add(label)
        if self.folds:
            ax.plot(
                [f.nu for f in self.folds], [f.amplitude for f in self.folds], "o", mfc="none", color="k",
                label="jump (fold)",
            )  # fmt: skip
        ax.set_xlabel(r"forcing frequency $\nu$")
        ax.set_ylabel("amplitude $a$")
        ax.grid(True, lw=0.4, alpha=0.5)
        ax.legend(loc="best")
        return ax


class _Forced:
    """Compiled pieces of the forced shortened equations, with the parameter values bound."""

    def __init__(self, avg: AveragedEquations, values: dict):
        nu = avg.nu
        self.fixed_nu = None
        if not isinstance(nu, sp.Symbol):
            self.fixed_nu = float(nu)
            nu = sp.Dummy("nu", positive=True)
        self.nu_sym = nu
        keep = {a, nu}
        phi = _bound(avg, avg.Phi, values, keep)
        psi = _bound(avg, avg.Psi, values, keep)
        R = _bound(avg, avg.R, values, set())
        self.R = float(R)
        if self.R == 0:
            raise ParameterError("forcing amplitude R must be nonzero for a resonance curve")
        p2 = sp.expand(2 * nu * a * phi)
        q2 = sp.expand(2 * nu * a * (psi - nu))
        Wn = p2**2 + q2**2 - R**2
        self.conservative = sp.simplify(phi) == 0
        M1 = _bound(avg, avg.M1, values, keep)
        M2 = _bound(avg, avg.M2, values, keep)
        args = [nu, a]
        self.W = _vcompile(Wn, args)
        self.slow = isinstance(self.W, np.vectorize)  # mpmath fallback: use coarser sampling grids
        self.Wa = _vcompile(sp.diff(Wn, a), args)
        self.jac = _vcompile([sp.diff(Wn, nu), sp.diff(Wn, a), sp.diff(Wn, a, nu), sp.diff(Wn, a, 2)], args)
        self.M = _vcompile([M1, M2, p2, q2], args)
        self.poly = None
        if Wn.is_polynomial(a):
            coeffs = sp.Poly(Wn, a).all_coeffs()
            if all(c.is_polynomial(nu) or not c.has(a) for c in coeffs):
                self.poly = compile(coeffs, [nu], check=False).raw

    def a_max(self, nus: np.ndarray) -> float:
        """Twice the largest amplitude where ``W <= 0`` on a wide geometric scan (all branches lie below it)."""
        scale = max(abs(self.R), 1e-12)
        grid = scale * np.geomspace(1e-6, 1e9, 1500)
        if nus.size > 25:  # the scan only bounds the amplitudes: a subset of the frequencies suffices
            nus = nus[np.unique(np.linspace(0, nus.size - 1, 25).round().astype(int))]
        vals = self.W(nus[:, None], grid[None, :])
        neg = np.nonzero(np.any(vals <= 0, axis=0))[0]
        if neg.size and neg[-1] == grid.size - 1:
            raise ConvergenceError(
                "the steady amplitude is unbounded over this frequency range (W(nu, a) stays negative); "
                "add damping or a stiffening term"
            )
        return float(2 * grid[neg[-1] + 1]) if neg.size else float(grid[0])

    def roots(self, nus: np.ndarray, a_max: float, n_a: int = 3000) -> list[list[float]]:
        if self.poly is not None:
            return self._poly_roots(nus)
        return self._grid_roots(nus, a_max, 250 if self.slow else n_a)

    def _poly_roots(self, nus: np.ndarray) -> list[list[float]]:
        """Positive real roots of the polynomial ``W(nu, .)``, polished by Newton steps."""
        coeffs = np.atleast_2d(np.asarray(self.poly(nus), dtype=float))
        if coeffs.shape[0] != len(nus):
            coeffs = coeffs.T
        out = []
        for nu, c in zip(nus, coeffs, strict=True):
            rr = np.roots(c)
            rs = sorted(float(r.real) for r in rr if r.real > 0 and abs(r.imag) <= 1e-7 * (1 + abs(r)))
            pol = []
            for r in rs:
                for _ in range(3):
                    d = self.Wa(nu, r)
                    if d == 0:
                        break
                    step = self.W(nu, r) / d
                    if abs(step) > 1e-3 * r:
                        break
                    r -= step
                pol.append(float(r))
            out.append(pol)
        return out

    def _grid_roots(self, nus: np.ndarray, a_max: float, n_a: int) -> list[list[float]]:
        from scipy.optimize import brentq

        grid = np.unique(np.concatenate([[0.0], np.geomspace(a_max * 1e-7, a_max, n_a), np.linspace(0, a_max, n_a)]))
        vals = self.W(nus[:, None], grid[None, :])
        out = []
        for i, nu in enumerate(nus):
            row = vals[i]
            idx = np.nonzero(np.sign(row[:-1]) * np.sign(row[1:]) < 0)[0]
            rs = []
            for j in idx:
                rs.append(brentq(lambda s, nu=nu: self.W(nu, s), grid[j], grid[j + 1], xtol=1e-14, rtol=1e-13))
            out.append(rs)
        return out

    def classify(self, nu: float, amp: float) -> SteadyState:
        m1, m2, p2, q2 = (float(z) for z in self.M(nu, amp))
        scale = 1e-9 * (1 + abs(m2))
        if self.conservative:
            kind = "center" if m2 > 0 else "saddle"
        elif m2 < -scale:
            kind = "saddle"
        else:
            kind = "stable" if m1 > 0 else "unstable"
        th = float(np.arctan2(p2 / self.R, q2 / self.R))
        return SteadyState(nu=float(nu), amplitude=float(amp), theta=th, M1=m1, M2=m2, kind=kind)

    def fold(self, nu0: float, a0: float, lo: float, hi: float) -> Fold:
        from scipy.optimize import root

        def fun(z):
            return [self.W(z[0], z[1]), self.Wa(z[0], z[1])]

        def jac(z):
            wn, wa, wan, waa = self.jac(z[0], z[1])
            return [[wn, wa], [wan, waa]]

        sol = root(fun, [nu0, a0], jac=jac, method="hybr", options={"xtol": 1e-13})
        nu, amp = sol.x
        width = hi - lo
        if sol.success and lo - 1e-9 * width <= nu <= hi + 1e-9 * width and amp > 0:
            return Fold(nu=float(nu), amplitude=float(amp), refined=True)
        return Fold(nu=float(nu0), amplitude=float(a0), refined=False)


def steady_states(avg: AveragedEquations, values: dict, nu: float | None) -> tuple[SteadyState, ...]:
    fc = _Forced(avg, values)
    if fc.fixed_nu is not None:
        if nu is not None and abs(nu - fc.fixed_nu) > 1e-12 * fc.fixed_nu:
            raise ParameterError(f"the forcing frequency was fixed to {fc.fixed_nu} when averaging; got nu = {nu}")
        nu = fc.fixed_nu
    if nu is None or not np.isfinite(nu) or nu <= 0:
        raise ParameterError(f"nu must be positive and finite, got {nu}")
    nus = np.array([float(nu)])
    am = fc.a_max(nus) if fc.poly is None else 0.0
    return tuple(fc.classify(nu, r) for r in fc.roots(nus, am)[0])


def frequency_response(
    avg: AveragedEquations, values: dict, nu_range: tuple[float, float], n: int, a_max: float | None
) -> FrequencyResponse:
    lo, hi = (float(z) for z in nu_range)
    if not (0 < lo < hi) or not np.isfinite(hi):
        raise ParameterError(f"nu_range must be 0 < lo < hi, got {nu_range}")
    if n < 3:
        raise ParameterError(f"n must be at least 3, got {n}")
    fc = _Forced(avg, values)
    if fc.fixed_nu is not None:
        raise ModelError("the forcing frequency was fixed to a number; build averaged_equations with nu symbolic")
    nus = np.linspace(lo, hi, int(n))
    am = (fc.a_max(nus) if fc.poly is None else 0.0) if a_max is None else float(a_max)
    roots = fc.roots(nus, am)
    folds = _folds(fc, nus, roots)
    extra = _near_folds(folds, nus)
    if extra.size:  # the branches between the folds are steep in nu: sample them densely (clustered at the folds)
        more = fc.roots(extra, am)
        merged = sorted(zip([*nus, *extra], [*roots, *more], strict=True), key=lambda x: x[0])
        nus = np.array([m[0] for m in merged])
        roots = [m[1] for m in merged]
    width = max(len(r) for r in roots) if roots else 0
    amps = np.full((len(nus), max(width, 1)), np.nan)
    stab = np.zeros_like(amps, dtype=bool)
    for i, rs in enumerate(roots):
        for j, r in enumerate(rs):
            amps[i, j] = r
            stab[i, j] = fc.classify(nus[i], r).stable
    return FrequencyResponse(nu=nus, amplitudes=amps, stable=stab, folds=folds)


def _near_folds(folds: tuple, nus: np.ndarray, count: int = 80) -> np.ndarray:
    """Extra frequencies between consecutive folds (and just outside them), clustered at the folds, where the
    amplitude has a square-root singularity in nu."""
    if not folds:
        return np.array([])
    step = nus[1] - nus[0]
    xs = sorted(f.nu for f in folds)
    out = []
    k = np.arange(1, count)
    for a, b in itertools.pairwise(xs):
        out.append(a + (b - a) * (1 - np.cos(np.pi * k / count)) / 2)
    for x in xs:
        out.append(x + step * np.array([-0.5, -0.2, -0.05, -0.01, 0.01, 0.05, 0.2, 0.5]))
    extra = np.concatenate(out)
    extra = extra[(extra > nus[0]) & (extra < nus[-1])]
    return np.setdiff1d(np.unique(extra), nus)


def _folds(fc: _Forced, nus: np.ndarray, roots: list) -> tuple:
    """Folds (jump points) where the number of roots changes between samples, refined by Newton's method."""
    folds = []
    for i in range(len(nus) - 1):
        c0, c1 = len(roots[i]), len(roots[i + 1])
        if c0 == c1:
            continue
        k = i if c0 > c1 else i + 1
        rs = roots[k]
        if len(rs) < 2:
            continue
        best = None
        for j in np.argsort(np.diff(rs)):  # try the closest pair first, then the others
            cand = fc.fold(nus[k], 0.5 * (rs[j] + rs[j + 1]), nus[i], nus[i + 1])
            best = best or cand
            if cand.refined:
                best = cand
                break
        folds.append(best)
    # a pair of close roots missed on the sampling grid shows up as a spurious count change next to a true fold:
    # keep the Newton-refined folds and drop unrefined ones within three samples of a refined one
    step = nus[1] - nus[0]
    good = [f for f in folds if f.refined]
    kept = good + [f for f in folds if not f.refined and all(abs(f.nu - g.nu) > 3 * step for g in good)]
    unique = []
    for f in sorted(kept, key=lambda f: f.nu):
        if not any(abs(f.nu - u.nu) < 1e-9 * (1 + f.nu) and abs(f.amplitude - u.amplitude) < 1e-6 for u in unique):
            unique.append(f)
    return tuple(unique)


def backbone(avg: AveragedEquations, values: dict, amplitudes: Any) -> np.ndarray:
    if avg.kind != "forced":
        raise ModelError("backbone() needs the forcing frequency symbol; build the equations with forcing=")
    nu = avg.nu
    expr = _bound(avg, sp.expand(2 * nu * a * (avg.Psi - nu)), values, {a, nu})
    sols = [s for s in sp.solve(expr, nu) if s.is_positive is not False]
    if not sols:
        raise ModelError(f"no positive backbone frequency solves {expr} = 0")
    fns = [compile(s, [a], check=False).raw for s in sols]
    amps = np.asarray(amplitudes, dtype=float)
    out = np.full(amps.shape, np.nan)
    for fn in fns:
        with np.errstate(invalid="ignore"):
            val = np.asarray(fn(amps.astype(complex)))
        good = (np.abs(val.imag) < 1e-12 * (1 + np.abs(val.real))) & (val.real > 0)
        out = np.where(np.isnan(out) & good, val.real, out)
    return out


@dataclass(frozen=True)
class StationaryRegime(SymPyPrintable):
    """A stationary amplitude of the autonomous shortened equations (``a = 0``: the equilibrium).

    Attributes
    ----------
    amplitude : Expr or Float
        The stationary amplitude (a root of ``a Phi(a) = 0``; 0 for the equilibrium).
    frequency : Expr or Float
        The frequency ``Psi(a)`` of the oscillation at that amplitude.
    exponent : Expr or Float
        ``-d(a Phi)/da`` at the amplitude: small deviations grow like ``exp(exponent * t)``.
    stable : bool or None
        ``True``/``False``, or ``None`` when the sign could not be decided symbolically.
    """

    amplitude: Any
    frequency: Any
    exponent: Any
    stable: bool | None

    def __repr__(self) -> str:
        word = {True: "stable", False: "unstable", None: "stability undecided"}[self.stable]
        return f"StationaryRegime(amplitude={self.amplitude}, frequency={self.frequency}, {word})"
