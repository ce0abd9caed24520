"""Mechanical ↔ electrical analogues of one-ports (force–voltage and force–current).

Mechanical impedance is force over velocity, ``F/v``.  Mechanical elements in *parallel* share a velocity
difference and add their forces; in *series* they carry one force and add their velocities.

* force–voltage (impedance analogy): mass ``m`` → inductor ``L = m``, damper ``c`` → resistor ``R = c``, spring
  ``k`` → capacitor ``C = 1/k``; mechanical parallel → electrical series, and ``Z_el = F/v``.
* force–current (mobility analogy): mass → capacitor ``C = m``, damper → resistor ``R = 1/c``, spring → inductor
  ``L = 1/k``; the topology is kept, and ``Y_el = F/v``.

>>> import sympy as sp
>>> from symosc.networks import Mass, Spring, Damper, to_electrical
>>> oscillator = Mass(2) | Spring(3) | Damper(1)          # a mass on a spring and damper to the ground
>>> to_electrical(oscillator, "force-voltage")
L(2) + C(1/3) + R(1)
>>> to_electrical(oscillator, "force-current")
C(2) | L(1/3) | R(1)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from .._util import P, as_symbol, connection_parts, element_value
from .oneports import Capacitor, Inductor, OnePort, Parallel, Resistor, Series

__all__ = [
    "Damper",
    "Mass",
    "MechanicalElement",
    "MechanicalParallel",
    "MechanicalSeries",
    "Spring",
    "chain_driving_point",
    "to_electrical",
    "to_mechanical",
]

_ANALOGIES = ("force-voltage", "force-current")


class MechanicalElement(SymPyPrintable):
    """Base of mechanical one-ports; ``a | b`` in parallel (common velocity), ``a + b`` in series (common force).

    ``sympy.latex`` of an element is its mechanical impedance ``F/v`` as a function of ``p`` (Bulgakov (1954), §9.28).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import Damper, Mass, Spring
    >>> m, k, c = Mass(2), Spring(8), Damper(1)
    >>> mount = k | c
    >>> chain = m + mount
    >>> mount.mechanical_impedance()
    (p + 8)/p
    >>> print(sp.latex(m))
    2 p

    See Also
    --------
    to_electrical, chain_driving_point
    """

    def mechanical_impedance(self, p: sp.Symbol = P) -> sp.Expr:  # pragma: no cover - abstract
        """Mechanical impedance ``F/v`` (force over velocity) as a rational expression in ``p``.

        Parameters
        ----------
        p : sympy.Symbol, optional
            Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.
        """
        raise NotImplementedError

    def __or__(self, other: MechanicalElement) -> MechanicalParallel:
        return MechanicalParallel((self, _check(other)))

    def __add__(self, other: MechanicalElement) -> MechanicalSeries:
        return MechanicalSeries((self, _check(other)))

    def __repr__(self) -> str:
        return self._sympystr(None)

    def _latex(self, printer: Any) -> str:
        Z = self.mechanical_impedance()
        return printer._print(Z) if printer is not None else sp.latex(Z)

    def _repr_latex_(self) -> str:
        return f"$Z_m(p) = {self._latex(None)}$"

    def _pretty(self, printer: Any) -> Any:
        from sympy.printing.pretty.stringpict import prettyForm

        return prettyForm(repr(self))


def _check(x: Any) -> MechanicalElement:
    if not isinstance(x, MechanicalElement):
        raise ParameterError(f"expected a mechanical element (Mass, Spring, Damper, ...), got {type(x).__name__}")
    return x


@dataclass(frozen=True, repr=False)
class Mass(MechanicalElement):
    """Mass ``m``: ``F = m p v``.

    Parameters
    ----------
    m : number or SymPy expression
        Mass, which must be positive (a number > 0 or a symbol not known to be zero or negative).
    """

    m: Any

    def __post_init__(self) -> None:
        object.__setattr__(self, "m", element_value(self.m, "m"))

    def mechanical_impedance(self, p: sp.Symbol = P) -> sp.Expr:
        return self.m * as_symbol(p)

    def _sympystr(self, printer: Any) -> str:
        return f"Mass({self.m})"


@dataclass(frozen=True, repr=False)
class Spring(MechanicalElement):
    """Spring of stiffness ``k``: ``F = (k/p) v``.

    Parameters
    ----------
    k : number or SymPy expression
        Stiffness, which must be positive (a number > 0 or a symbol not known to be zero or negative).
    """

    k: Any

    def __post_init__(self) -> None:
        object.__setattr__(self, "k", element_value(self.k, "k"))

    def mechanical_impedance(self, p: sp.Symbol = P) -> sp.Expr:
        return self.k / as_symbol(p)

    def _sympystr(self, printer: Any) -> str:
        return f"Spring({self.k})"


@dataclass(frozen=True, repr=False)
class Damper(MechanicalElement):
    """Viscous damper ``c``: ``F = c v``.

    Parameters
    ----------
    c : number or SymPy expression
        Viscous damping coefficient (force per velocity), which must be positive (a number > 0 or a symbol not known to
        be zero or negative).
    """

    c: Any

    def __post_init__(self) -> None:
        object.__setattr__(self, "c", element_value(self.c, "c"))

    def mechanical_impedance(self, p: sp.Symbol = P) -> sp.Expr:
        return self.c

    def _sympystr(self, printer: Any) -> str:
        return f"Damper({self.c})"


@dataclass(frozen=True, repr=False)
class MechanicalParallel(MechanicalElement):
    """Elements sharing one velocity difference: impedances add.

    Parameters
    ----------
    parts : tuple of MechanicalElement
        The elements sharing one velocity difference (nested parallel connections are flattened).
    """

    parts: tuple = ()

    def __post_init__(self) -> None:
        flat: list = []
        for part in connection_parts(self.parts, "MechanicalParallel", MechanicalElement, "a | b"):
            flat.extend(part.parts if isinstance(part, MechanicalParallel) else (_check(part),))
        object.__setattr__(self, "parts", tuple(flat))

    def mechanical_impedance(self, p: sp.Symbol = P) -> sp.Expr:
        return sp.cancel(sp.Add(*(part.mechanical_impedance(p) for part in self.parts)))

    def _sympystr(self, printer: Any) -> str:
        return " | ".join(f"({x!r})" if isinstance(x, MechanicalSeries) else repr(x) for x in self.parts)


@dataclass(frozen=True, repr=False)
class MechanicalSeries(MechanicalElement):
    """Elements carrying one force: mobilities (``1/Z``) add.

    Parameters
    ----------
    parts : tuple of MechanicalElement
        The elements carrying one force (nested series connections are flattened).
    """

    parts: tuple = ()

    def __post_init__(self) -> None:
        flat: list = []
        for part in connection_parts(self.parts, "MechanicalSeries", MechanicalElement, "a + b"):
            flat.extend(part.parts if isinstance(part, MechanicalSeries) else (_check(part),))
        object.__setattr__(self, "parts", tuple(flat))

    def mechanical_impedance(self, p: sp.Symbol = P) -> sp.Expr:
        return sp.cancel(1 / sp.Add(*(1 / part.mechanical_impedance(p) for part in self.parts)))

    def _sympystr(self, printer: Any) -> str:
        return " + ".join(f"({x!r})" if isinstance(x, MechanicalParallel) else repr(x) for x in self.parts)


def _analogy(analogy: str) -> str:
    if analogy not in _ANALOGIES:
        raise ParameterError(f"analogy must be one of {_ANALOGIES}, got {analogy!r}")
    return analogy


@validated
def to_electrical(mech: MechanicalElement, analogy: str = "force-voltage") -> OnePort:
    """Electrical analogue of a mechanical one-port.

    With ``"force-voltage"`` the network's impedance equals the mechanical impedance ``F/v``; with
    ``"force-current"`` its admittance does.

    Parameters
    ----------
    mech : MechanicalElement
        The mechanical one-port: masses, springs and dampers connected with ``|`` and ``+``.
    analogy : {"force-voltage", "force-current"}, optional
        The analogy: "force-voltage" (mass → inductor, spring → capacitor ``1/k``, damper → resistor, parallel ↔ series;
        the impedance is ``F/v``) or "force-current" (mass → capacitor, spring → inductor ``1/k``, damper → resistor
        ``1/c``, topology kept; the admittance is ``F/v``); default "force-voltage".

    Examples
    --------
    >>> from symosc.networks import Mass, Spring, to_electrical
    >>> to_electrical(Mass(1) | (Spring(4) + Mass(2)), "force-voltage")
    L(1) + (C(1/4) | L(2))

    See Also
    --------
    to_mechanical, chain_driving_point
    """
    analogy = _analogy(analogy)
    fv = analogy == "force-voltage"
    if isinstance(mech, Mass):
        return Inductor(mech.m) if fv else Capacitor(mech.m)
    if isinstance(mech, Spring):
        return Capacitor(1 / mech.k) if fv else Inductor(1 / mech.k)
    if isinstance(mech, Damper):
        return Resistor(mech.c) if fv else Resistor(1 / mech.c)
    parts = tuple(to_electrical(x, analogy) for x in _check(mech).parts)
    if isinstance(mech, MechanicalParallel):
        return Series(parts) if fv else Parallel(parts)
    return Parallel(parts) if fv else Series(parts)


@validated
def to_mechanical(net: OnePort, analogy: str = "force-voltage") -> MechanicalElement:
    """Mechanical analogue of an R, L, C one-port (the inverse of :func:`to_electrical`).

    Parameters
    ----------
    net : OnePort
        The electrical one-port, which must consist of resistors, inductors and capacitors in series and parallel.
    analogy : {"force-voltage", "force-current"}, optional
        The analogy: "force-voltage" (mass → inductor, spring → capacitor ``1/k``, damper → resistor, parallel ↔ series;
        the impedance is ``F/v``) or "force-current" (mass → capacitor, spring → inductor ``1/k``, damper → resistor
        ``1/c``, topology kept; the admittance is ``F/v``); default "force-voltage".

    Examples
    --------
    >>> from symosc.networks import Resistor, Inductor, Capacitor, to_mechanical
    >>> to_mechanical(Inductor(2) + Capacitor(1/3) + Resistor(1), "force-voltage")
    Mass(2) | Spring(3.00000000000000) | Damper(1)

    See Also
    --------
    to_electrical
    """
    analogy = _analogy(analogy)
    fv = analogy == "force-voltage"
    if isinstance(net, Inductor):
        return Mass(net.L) if fv else Spring(1 / net.L)
    if isinstance(net, Capacitor):
        return Spring(1 / net.C) if fv else Mass(net.C)
    if isinstance(net, Resistor):
        return Damper(net.R) if fv else Damper(1 / net.R)
    if isinstance(net, (Series, Parallel)):
        parts = tuple(to_mechanical(x, analogy) for x in net.parts)
        if isinstance(net, Series):
            return MechanicalParallel(parts) if fv else MechanicalSeries(parts)
        return MechanicalSeries(parts) if fv else MechanicalParallel(parts)
    raise ParameterError(f"no mechanical analogue for {type(net).__name__} (only R, L, C and their connections)")


@validated
def chain_driving_point(masses: list, springs: list, dampers: list | None = None) -> MechanicalElement:
    """Mechanical one-port of a chain wall–(k1, c1)–m1–(k2, c2)–m2–…–mN driven at the last mass.

    Parameters
    ----------
    masses : list of numbers or SymPy expressions
        The masses ``m1, ..., mN`` from the wall outwards, each positive.
    springs : list of numbers or SymPy expressions
        Stiffnesses ``k1, ..., kN``, which must be as many as the masses and positive; ``kj`` joins ``m(j-1)`` (the wall
        for ``j = 1``) to ``mj``.
    dampers : list of numbers or SymPy expressions, optional
        Damping coefficients ``c1, ..., cN`` in parallel with the springs, as many as the masses and non-negative (0
        leaves a damper out); no dampers when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import chain_driving_point
    >>> p = sp.Symbol("p")
    >>> chain_driving_point([1], [4]).mechanical_impedance(p)      # m p + k/p
    (p**2 + 4)/p

    See Also
    --------
    to_electrical
    """
    n = len(masses)
    if len(springs) != n or (dampers is not None and len(dampers) != n):
        raise ParameterError("masses, springs (and dampers) must have the same length")
    node: MechanicalElement | None = None
    for j in range(n):
        link: MechanicalElement = Spring(springs[j])
        if dampers is not None and dampers[j] != 0:
            link = link | Damper(dampers[j])
        toward_wall = link if node is None else link + node
        node = Mass(masses[j]) | toward_wall
    return node
