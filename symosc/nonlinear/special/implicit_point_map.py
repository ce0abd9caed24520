"""Stationary amplitudes of implicit half-swing maps ``f(a, b) = 0`` and their stability (Bulgakov (1954), §5.12).

A half-swing of a piecewise (or impulsive) oscillator is described by an implicit relation between successive
amplitudes.  For a symmetric system one relation ``f(a, b) = 0`` maps every half swing; the stationary amplitude
solves ``f(A, A) = 0`` (5.152) and is stable iff ``|f_a / f_b| < 1`` at ``a = b = A`` (5.153).  With two half-maps
``f2(a, b) = 0`` (first half swing) and ``f1(b, c) = 0`` (second) the cycle ``(A, B)`` solves ``f2(A, B) = 0``,
``f1(B, A) = 0`` and is stable iff ``|f1_b f2_a| < |f1_c f2_b|`` (5.154): the product of the two slopes is less than
one in modulus.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ModelError, ParameterError

__all__ = ["ImplicitMapCycle", "implicit_map_cycle"]


@dataclass(frozen=True)
class ImplicitMapCycle(SymPyPrintable):
    """A fixed point of a (composed) point map.

    Attributes
    ----------
    amplitudes : tuple of float
        ``(A,)`` for a symmetric map, ``(A, B)`` for two half-maps.
    multiplier : float
        Slope of the composed map at the fixed point (``-f_a/f_b``, or the product of the two slopes).
    stable : bool
        ``|multiplier| < 1`` (Bulgakov (1954), eqs. (5.153)–(5.154)).
    """

    amplitudes: tuple[float, ...]
    multiplier: float
    stable: bool

    def __repr__(self) -> str:
        amps = ", ".join(f"{a:.8g}" for a in self.amplitudes)
        return (
            f"ImplicitMapCycle(({amps}), multiplier={self.multiplier:.6g}, {'stable' if self.stable else 'unstable'})"
        )

    def _repr_latex_(self) -> str:
        """Fixed-point amplitudes, the multiplier and the verdict of Bulgakov (1954), eqs. (5.153)–(5.154)."""
        from ..._printing import latex_value

        names = ("A", "B")
        amps = r",\ ".join(f"{n} = {latex_value(a)}" for n, a in zip(names, self.amplitudes, strict=False))
        verdict = r"\text{stable}" if self.stable else r"\text{unstable}"
        return rf"${amps},\ \lambda = {latex_value(self.multiplier)}\ \left({verdict}\right)$"


def _expr(e: Any, name: str) -> sp.Expr:
    try:
        return sp.sympify(e)
    except (sp.SympifyError, TypeError) as exc:
        raise ParameterError(f"{name} must be a SymPy expression, got {e!r}") from exc


@validated
def implicit_map_cycle(
    maps: Any, symbols: Sequence[sp.Symbol], guess: float | Sequence[float], *, tol: float = 1e-12
) -> ImplicitMapCycle:
    """Stationary amplitude(s) of a point map and their stability (Bulgakov (1954), §5.12).

    Parameters
    ----------
    maps : expression or pair of expressions
        ``f(a, b)`` for a symmetric system, or ``(f2(a, b), f1(b, c))`` for two half-maps; numeric apart from the
        amplitude symbols.
    symbols : sequence of Symbol
        ``(a, b)`` or ``(a, b, c)``.
    guess : float or pair of floats
        Starting value ``A`` or ``(A, B)`` for the root search (``sympy.nsolve``).
    tol : float
        Residual tolerance.

    Returns
    -------
    ImplicitMapCycle

    Raises
    ------
    ConvergenceError
        No root near the guess.
    ModelError
        ``f_b = 0`` (or ``f1_c f2_b = 0``) at the root: the map is not defined there.

    See Also
    --------
    symosc.nonlinear.half_swing_map : half-swing maps of conservative systems with friction.
    symosc.nonlinear.point_map_fixed_point : fixed point of an explicit map ``x -> P(x)``.
    symosc.nonlinear.clock_escapement : the clock with an escapement (§5.11).

    Examples
    --------
    Clock escapement with energy impulse ``H`` and Coulomb friction ``F``: ``a**2/2 - b**2/2 - F (a + b) + H = 0``
    gives ``A = H / (2 F)`` (5.141), stable.

    >>> import sympy as sp
    >>> a, b = sp.symbols("a b")
    >>> implicit_map_cycle(a**2 / 2 - b**2 / 2 - sp.Rational(1, 10) * (a + b) + sp.Rational(1, 5), (a, b), 1.0)
    ImplicitMapCycle((1), multiplier=0.818182, stable)
    """
    if isinstance(maps, list | tuple):
        if len(maps) != 2 or len(symbols) != 3:
            raise ParameterError("two half-maps need maps=(f2(a, b), f1(b, c)) and symbols=(a, b, c)")
        f2, f1 = _expr(maps[0], "f2"), _expr(maps[1], "f1")
        a, b, c = symbols
        for e, allowed, nm in ((f2, {a, b}, "f2"), (f1, {b, c}, "f1")):
            if e.free_symbols - allowed:
                raise ModelError(f"{nm} has symbols other than the amplitudes: {sorted(map(str, e.free_symbols))}")
        g = list(np.atleast_1d(np.asarray(guess, dtype=float)))
        if len(g) != 2:
            raise ParameterError("guess must be (A, B) for two half-maps")
        system = [f2, f1.xreplace({c: a})]
        try:
            sol = sp.nsolve(system, [a, b], g, tol=tol, prec=30)
        except (ValueError, ZeroDivisionError) as exc:
            raise ConvergenceError(f"no cycle of the point map near {g}: {exc}") from exc
        A, B = float(sol[0]), float(sol[1])
        at2, at1 = {a: A, b: B}, {b: B, c: A}
        den = float(sp.diff(f1, c).xreplace(at1)) * float(sp.diff(f2, b).xreplace(at2))
        if den == 0:
            raise ModelError("f1_c * f2_b = 0 at the cycle: the half-maps do not define b(a), c(b) there")
        mult = float(sp.diff(f1, b).xreplace(at1)) * float(sp.diff(f2, a).xreplace(at2)) / den
        return ImplicitMapCycle((A, B), mult, abs(mult) < 1)
    f = _expr(maps, "maps")
    if len(symbols) != 2:
        raise ParameterError("a symmetric map needs symbols=(a, b)")
    a, b = symbols
    if f.free_symbols - {a, b}:
        raise ModelError(f"the map has symbols other than the amplitudes: {sorted(map(str, f.free_symbols))}")
    try:
        g = float(guess)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"guess must be a number for a symmetric map, got {guess!r}") from exc
    try:
        A = float(sp.nsolve(f.xreplace({b: a}), a, g, tol=tol, prec=30))
    except (ValueError, ZeroDivisionError) as exc:
        raise ConvergenceError(f"no stationary amplitude near {g}: {exc}") from exc
    at = {a: A, b: A}
    fb = float(sp.diff(f, b).xreplace(at))
    if fb == 0:
        raise ModelError("f_b = 0 at the stationary amplitude: the map does not define b(a) there")
    mult = -float(sp.diff(f, a).xreplace(at)) / fb
    return ImplicitMapCycle((A,), mult, abs(mult) < 1)
