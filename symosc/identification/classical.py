"""Classical inertia-measurement formulas surveyed by Belyakov (2005, Ch. I §1), derived from equations of motion.

Each function sets up the equations of motion of the rig with SymPy, solves them for the unknown moment of inertia
and returns an :class:`InertiaFormula`: the expression, the equations it came from, and a numeric evaluator
compiled with :func:`symosc.numeric.compile`.

* :func:`flywheel` — drum of radius R driven by a falling weight, two runs (M1, T1), (M2, T2) over the same height
  h eliminate a constant friction moment (Meshchersky);
* :func:`physical_pendulum` — ``I_C = m g r / omega**2 - m r**2``;
* :func:`rocking_platform` — body on a platform rocking on a spring: ``I = c l**2 / omega**2 - m d**2 - J``.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import sympy as sp

from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ModelError
from ..numeric import CompiledFunction
from ..numeric import compile as _compile
from ..symbols import sort_symbols

__all__ = ["InertiaFormula", "flywheel", "physical_pendulum", "rocking_platform"]


@dataclass(frozen=True)
class InertiaFormula(SymPyPrintable):
    """A moment-of-inertia formula derived from equations of motion.

    ``expr`` is the moment of inertia; ``equations`` the equations of motion/measurement it solves; calling the
    object with ``values`` (keyed by symbol or name) evaluates it.

    Attributes
    ----------
    name : str
        Name of the method (``"flywheel"``, ``"physical_pendulum"``, ``"rocking_platform"``).
    expr : sympy.Expr
        The moment of inertia in terms of the measured and known quantities.
    equations : tuple of sympy.Eq
        The equations of motion or measurement that ``expr`` solves.
    """

    name: str
    expr: sp.Expr
    equations: tuple[sp.Eq, ...] = field(repr=False)

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """Free symbols of the formula, in natural order."""
        return sort_symbols(self.expr.free_symbols)

    @cached_property
    def _compiled(self) -> CompiledFunction:
        return _compile(self.expr, list(self.parameters), name=f"inertia_{self.name}")

    def __call__(self, values: Mapping[Any, Any]) -> Any:
        """Numeric value for ``values`` (NumPy broadcasting over arrays)."""
        return self._compiled.call(values)

    def _repr_latex_(self) -> str:
        return f"$I = {sp.latex(self.expr)}$"


def _solve(eqs: list[sp.Eq], unknowns: list[sp.Symbol], target: sp.Symbol) -> sp.Expr:
    sol = sp.solve(eqs, unknowns, dict=True)
    if len(sol) != 1:
        raise ModelError(f"expected one solution for {unknowns}, got {sol}")  # pragma: no cover
    return sp.simplify(sol[0][target])


@validated
def flywheel() -> InertiaFormula:
    """Flywheel (drum radius ``R``) spun by a weight ``M`` falling height ``h`` from rest in time ``T``; friction
    moment ``Mf`` constant.  Two runs ``(M1, T1)``, ``(M2, T2)`` eliminate ``Mf``.

    Equations: ``(I + M R^2) eps = M g R - Mf`` and ``h = eps R T^2 / 2`` for each run.

    >>> f = flywheel()
    >>> round(float(f({"R": 0.1, "g": 9.81, "h": 1.0, "M1": 2.0, "M2": 1.0, "T1": 2.0, "T2": 3.0})), 6)
    0.32516
    """
    I, R, g, h, Mf = sp.symbols("I R g h M_f", positive=True)
    M1, M2, T1, T2 = sp.symbols("M1 M2 T1 T2", positive=True)
    eqs = []
    for M, T in ((M1, T1), (M2, T2)):
        eps = 2 * h / (R * T**2)  # angular acceleration from h = a T^2 / 2, a = eps R
        eqs.append(sp.Eq((I + M * R**2) * eps, M * g * R - Mf))
    return InertiaFormula("flywheel", _solve(eqs, [I, Mf], I), tuple(eqs))


@validated
def physical_pendulum() -> InertiaFormula:
    """Physical pendulum: mass ``m``, center of mass at distance ``r`` from the pivot, small-oscillation angular
    frequency ``omega``; returns the moment of inertia about the center of mass.

    Equation of motion ``(I + m r^2) phi'' + m g r phi = 0`` with ``phi = cos(omega t)``.

    >>> physical_pendulum().expr
    m*r*(g - omega**2*r)/omega**2
    """
    I, m, g, r, w = sp.symbols("I m g r omega", positive=True)
    t = sp.Symbol("t")
    phi = sp.cos(w * t)
    eq = sp.Eq(sp.simplify(((I + m * r**2) * phi.diff(t, 2) + m * g * r * phi) / phi), 0)
    return InertiaFormula("physical_pendulum", _solve([eq], [I], I), (eq,))


@validated
def rocking_platform() -> InertiaFormula:
    """Platform (own inertia ``J`` about its hinge) rocking on a spring of stiffness ``c`` at lever ``l``; the
    body's center of mass is at distance ``d`` from the hinge axis, in its plane (no gravity moment).  Returns the
    body's moment of inertia about its center of mass from the angular frequency ``omega``.

    Equation of motion ``(J + I + m d^2) phi'' + c l^2 phi = 0``.

    >>> rocking_platform().expr
    -J + c*l**2/omega**2 - d**2*m
    """
    I, J, m, d, c, l, w = sp.symbols("I J m d c l omega", positive=True)
    eq = sp.Eq(-(J + I + m * d**2) * w**2 + c * l**2, 0)
    return InertiaFormula("rocking_platform", _solve([eq], [I], I), (eq,))
