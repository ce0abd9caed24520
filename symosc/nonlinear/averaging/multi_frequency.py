"""Multi-frequency averaging for n weakly nonlinear oscillators (Bulgakov §12.11–12.12, non-resonant case).

``x_i'' + f_i(x, v) = 0`` (``i = 1..n``) with comparison frequencies ``w_i``.  The substitution
``x_i = a_i cos(psi_i)``, ``v_i = -a_i w_i sin(psi_i)`` and averaging over the torus of all phases (valid when the
``w_i`` have no low-order integer relation, assumption (e) of §12.12) give

    a_i' = <f_i sin(psi_i)>/w_i,        psi_i' = w_i/2 + <f_i cos(psi_i)>/(w_i a_i)

the direct generalisation of the one-degree-of-freedom equations of :mod:`symosc.nonlinear.averaging`.  For
polynomial ``f_i`` the torus averages are exact (harmonic algebra, one phase after the other).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from ...numeric import bind
from . import _trig

__all__ = ["MultiAveragedEquations", "averaged_equations_ndof", "dry_friction_ratio", "dry_friction_torus_average"]


@dataclass(frozen=True)
class MultiAveragedEquations(SymPyPrintable):
    """Shortened equations of n non-resonant oscillators: amplitudes ``a_i``, phases ``psi_i``.

    Attributes
    ----------
    amplitudes : tuple of Symbol
        The amplitude symbols ``a1 .. an`` (positive).
    phases : tuple of Symbol
        The phase symbols ``psi1 .. psin`` (real).
    frequencies : tuple of Expr
        The comparison frequencies ``w_i``.
    a_dot : tuple of Expr
        Right-hand sides ``a_i' = <f_i sin(psi_i)>/w_i``, functions of the amplitudes only.
    phase_dot : tuple of Expr
        Right-hand sides ``psi_i' = w_i/2 + <f_i cos(psi_i)>/(w_i a_i)``.
    """

    amplitudes: tuple[sp.Symbol, ...]
    phases: tuple[sp.Symbol, ...]
    frequencies: tuple[sp.Expr, ...]
    a_dot: tuple[sp.Expr, ...]
    phase_dot: tuple[sp.Expr, ...]

    def stationary(self, values: dict | None = None) -> list[dict]:
        """All stationary amplitude sets (``a_i >= 0``) with their stability.

        Returns a list of ``{"amplitudes": (...), "eigenvalues": (...), "stable": bool}``; the eigenvalues are those
        of the Jacobian of ``a' `` with respect to ``a`` (all negative real parts: stable).  Each ``a_i' = a_i g_i``
        factor ``a_i = 0`` is treated separately, so mode-suppressed states are found.

        Parameters
        ----------
        values : mapping of Symbol or symbol name to number, optional
            Values of every free parameter of ``a_dot`` (keys are symbols or their names); a missing one raises
            ParameterError. Omitted: the equations must contain no parameters, and the amplitudes are kept exact.
        """
        A = sp.Matrix(self.a_dot)
        if values is not None:
            A = bind(A, values)
        free = A.free_symbols - set(self.amplitudes)
        if free:
            raise ParameterError("missing values for: " + ", ".join(sorted(s.name for s in free)))
        n = len(self.amplitudes)
        out = []
        J = A.jacobian(sp.Matrix(self.amplitudes))
        for active in itertools.product((False, True), repeat=n):
            zero = {a: 0 for a, on in zip(self.amplitudes, active, strict=True) if not on}
            eqs = []
            unknowns = []
            for a, on, e in zip(self.amplitudes, active, A, strict=True):
                if on:
                    g = sp.cancel(e.subs(zero) / a)
                    eqs.append(g)
                    unknowns.append(a)
            sols = [dict()] if not eqs else sp.solve(eqs, unknowns, dict=True)
            for sol in sols:
                amps = []
                ok = True
                for a, on in zip(self.amplitudes, active, strict=True):
                    val = sp.S.Zero if not on else sp.nsimplify(sol.get(a, sp.nan)) if values is None else sol.get(a)
                    if val is None or (val.is_number and (not val.is_real or val <= 0) and on):
                        ok = False
                        break
                    amps.append(val)
                if not ok:
                    continue
                Jv = J.subs(dict(zip(self.amplitudes, amps, strict=True)))
                if Jv.free_symbols:
                    eig, stable = None, None
                else:
                    eig = tuple(complex(e) for e in np.linalg.eigvals(np.array(Jv.evalf(), dtype=float)))
                    stable = all(e.real < 0 for e in eig)
                out.append({"amplitudes": tuple(amps), "eigenvalues": eig, "stable": stable})
        return out

    def __repr__(self) -> str:
        eqs = ", ".join(f"{a}' = {e}" for a, e in zip(self.amplitudes, self.a_dot, strict=True))
        return f"MultiAveragedEquations({eqs})"


@validated
def averaged_equations_ndof(
    forces: Any,
    coordinates: Any,
    velocities: Any,
    frequencies: Any = None,
    *,
    resonance_order: int | None = None,
) -> MultiAveragedEquations:
    """Torus-averaged shortened equations of ``x_i'' + f_i(x, v) = 0`` (non-resonant frequencies).

    Parameters
    ----------
    forces : sequence of expressions
        ``f_i`` in the coordinates and velocities (polynomial).
    coordinates, velocities : sequences of Symbol
        The coordinates ``x_i`` and velocities ``v_i`` used in the forces, one of each per force.
    frequencies : sequence, optional
        Comparison frequencies ``w_i`` (default ``sqrt(df_i/dx_i)`` at rest).
    resonance_order : int, optional
        With numeric frequencies, refuse (ModelError) integer relations ``k . w = 0`` with ``0 < |k|_1 <=
        resonance_order`` (default: the polynomial degree of the forces + 1), where the torus average is invalid.

    Examples
    --------
    >>> import sympy as sp
    >>> x1, x2, v1, v2 = sp.symbols("x1 x2 v1 v2", real=True)
    >>> e = sp.Rational(1, 10)
    >>> f = [x1 - e * (1 - x1**2 - x2**2) * v1, 2 * x2 - e * (1 - x2**2 - x1**2) * v2]
    >>> avg = averaged_equations_ndof(f, [x1, x2], [v1, v2])
    >>> avg.a_dot[0]
    -a1**3/80 - a1*a2**2/40 + a1/20
    """
    fs = [sp.sympify(f) for f in forces]
    xs, vs = list(coordinates), list(velocities)
    n = len(fs)
    if not (len(xs) == len(vs) == n):
        raise ModelError(f"{n} forces need {n} coordinates and {n} velocities")
    rest = {**{x: 0 for x in xs}, **{v: 0 for v in vs}}
    if frequencies is None:
        frequencies = []
        for f, x in zip(fs, xs, strict=True):
            k = sp.diff(f, x).subs(rest)
            if (k.is_number and not k > 0) or k.is_nonpositive:
                raise ModelError(f"cannot infer a comparison frequency from df/d{x} = {k}; pass frequencies=")
            frequencies.append(sp.sqrt(k))
    ws = [sp.sympify(w) for w in frequencies]
    if all(w.is_number for w in ws):
        deg = max(sp.Poly(f, *xs, *vs).total_degree() for f in fs) if all(f.is_polynomial(*xs, *vs) for f in fs) else 3
        order = resonance_order or deg + 1
        wv = [float(w) for w in ws]
        for k in itertools.product(range(-order, order + 1), repeat=n):
            if (
                0 < sum(map(abs, k)) <= order
                and any(k)
                and abs(sum(ki * wi for ki, wi in zip(k, wv, strict=True))) < 1e-9
            ):
                raise ModelError(
                    f"frequencies {wv} satisfy the resonance k.w = 0 with k = {k}; the torus average does not apply"
                )
    amps = tuple(sp.Symbol(f"a{i + 1}", positive=True) for i in range(n))
    phs = tuple(sp.Dummy(f"psi{i + 1}", real=True) for i in range(n))
    sub = {}
    for x, v, a, w, ph in zip(xs, vs, amps, ws, phs, strict=True):
        sub[x] = a * sp.cos(ph)
        sub[v] = -a * w * sp.sin(ph)
    a_dot, ph_dot = [], []
    for i, f in enumerate(fs):
        fsub = f.xreplace(sub)
        s_avg, c_avg = fsub * sp.sin(phs[i]), fsub * sp.cos(phs[i])
        for ph in phs:
            s_avg = _trig.average(s_avg, ph)
            c_avg = _trig.average(c_avg, ph)
        a_dot.append(sp.expand(s_avg / ws[i]))
        ph_dot.append(sp.expand(ws[i] / 2 + c_avg / (ws[i] * amps[i])))
    psis = tuple(sp.Symbol(f"psi{i + 1}", real=True) for i in range(n))
    return MultiAveragedEquations(
        amplitudes=amps, phases=psis, frequencies=tuple(ws), a_dot=tuple(a_dot), phase_dot=tuple(ph_dot)
    )


@validated
def dry_friction_torus_average(x: float, y: float) -> float:
    """``G(x, y) = Integral(sign(x sin u1 + y sin u2) sin u1, u1, u2 over [0, 2 pi]^2)`` (Bulgakov §12.14).

    Dry friction acting on the velocity ``x sin u1 + y sin u2`` of a two-frequency motion (gyroscopic pendulum),
    averaged over the torus.  Closed forms: ``16 E(k)``, ``k = y/x`` for ``x >= y >= 0``; ``16 k B(k)``, ``k = x/y``,
    ``B(k) = (E(k) - (1 - k^2) K(k))/k^2`` for ``0 <= x <= y`` (complete elliptic integrals of modulus ``k``).

    Parameters
    ----------
    x : float
        Velocity amplitude of the first oscillation (the one the average projects on); a non-negative finite number.
    y : float
        Velocity amplitude of the second oscillation; a non-negative finite number.

    Examples
    --------
    >>> round(dry_friction_torus_average(1.0, 0.0) / math.pi, 12)
    8.0
    """
    import mpmath

    if x < 0 or y < 0 or not (math.isfinite(x) and math.isfinite(y)):
        raise ParameterError(f"x and y must be non-negative and finite, got {x}, {y}")
    if x == 0:
        return 0.0
    if x >= y:
        return float(16 * mpmath.ellipe((y / x) ** 2))
    k = x / y
    return float(16 * k * _B(k))


def _B(k: float) -> Any:
    import mpmath

    if k == 0:
        return mpmath.pi / 4
    if k == 1:
        return mpmath.mpf(1)  # (1 - k^2) K(k) -> 0 as k -> 1 (log singularity of K)
    m = k * k
    return (mpmath.ellipe(m) - (1 - m) * mpmath.ellipk(m)) / m


@validated
def dry_friction_ratio(k: float) -> float:
    """``R(k) = [G(y, x)/y]/[G(x, y)/x]`` with ``k = y/x``: how much more the dry friction damps the second
    oscillation than the first, per unit velocity amplitude (Table 15 of §12.14).  ``R = B(k)/E(k)`` for
    ``k <= 1`` and ``R(1/k) = 1/R(k)``; ``R(0) = 1/2``, ``R(1) = 1``, ``R(oo) = 2``.

    Parameters
    ----------
    k : float
        Ratio ``y/x`` of the velocity amplitudes of the second and the first oscillation; a non-negative number
        (``inf`` allowed).

    Examples
    --------
    >>> round(dry_friction_ratio(0.5), 3), round(dry_friction_ratio(2.0), 3)
    (0.554, 1.806)
    """
    import mpmath

    if k < 0 or math.isnan(k):
        raise ParameterError(f"k must be non-negative, got {k}")
    if math.isinf(k):
        return 2.0
    if k > 1:
        return 1.0 / dry_friction_ratio(1.0 / k)
    return float(_B(k) / mpmath.ellipe(k * k))
