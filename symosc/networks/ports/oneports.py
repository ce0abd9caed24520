"""One-ports (two-poles): resistors, inductors, capacitors and their series/parallel trees (Bulgakov §8.31).

A network object knows its impedance ``Z(p)`` and admittance ``Y(p) = 1/Z(p)`` in the operator variable ``p``
(put ``p = i*omega`` for the steady state).  ``a + b`` connects in series and ``a | b`` in parallel, as in lcapy.

>>> from symosc.networks import Resistor, Inductor, Capacitor
>>> net = Resistor(1) + (Inductor(2) | Capacitor(3))
>>> net
R(1) + (L(2) | C(3))
>>> net.impedance()
(6*p**2 + 2*p + 1)/(6*p**2 + 1)
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import sympy as sp
from sympy import QQ
from sympy.polys.densearith import dup_add, dup_mul
from sympy.polys.densebasic import dup_strip
from sympy.polys.rings import PolyRing

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from .._exact.fields import normalize
from .._util import P, as_expr, as_symbol, connection_parts, element_value

__all__ = [
    "BruneSection",
    "Capacitor",
    "Impedance",
    "Inductor",
    "OnePort",
    "Parallel",
    "Resistor",
    "Series",
    "equivalent_two_pole",
]


class OnePort(SymPyPrintable):
    """Base class of one-port networks: impedance, admittance, series ``+`` and parallel ``|``.

    ``sympy.latex`` of a one-port is its impedance ``Z(p)`` (Bulgakov (1954), §9.21).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import BruneSection, Capacitor, Impedance, Inductor, Resistor
    >>> R, L, C = Resistor(1), Inductor(2), Capacitor(sp.Rational(1, 2))
    >>> Z = Impedance(sp.Symbol("Z_A"))
    >>> tank = L | C
    >>> net = R + tank
    >>> net
    R(1) + (L(2) | C(1/2))
    >>> net.impedance()
    (p**2 + 2*p + 1)/(p**2 + 1)
    >>> print(sp.latex(R + Z))
    Z_{A} + 1
    >>> brune = BruneSection(1, 4, 2, 1, load=R)
    >>> brune.coupling
    1

    See Also
    --------
    Series, Parallel, equivalent_two_pole
    """

    def impedance(self, p: sp.Symbol = P) -> sp.Expr:  # pragma: no cover - abstract
        """The impedance ``Z(p)`` as a cancelled rational expression in the operator variable.

        Parameters
        ----------
        p : sympy.Symbol, optional
            Operator variable, which must be a SymPy Symbol (Carson/Laplace ``p``; put ``p = iω`` for the steady
            state); the standard symbol ``p`` when omitted.
        """
        raise NotImplementedError

    def admittance(self, p: sp.Symbol = P) -> sp.Expr:
        """``1/Z(p)`` as a cancelled rational expression.

        Parameters
        ----------
        p : sympy.Symbol, optional
            Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.
        """
        return sp.cancel(1 / self.impedance(p))

    def elements(self) -> tuple:
        """The leaf elements in netlist order."""
        return (self,)

    def __add__(self, other: OnePort) -> Series:
        return Series((self, _check_port(other)))

    def __or__(self, other: OnePort) -> Parallel:
        return Parallel((self, _check_port(other)))

    def __str__(self) -> str:
        return self._sympystr(None)

    def __repr__(self) -> str:
        return self._sympystr(None)

    def _repr_latex_(self) -> str:
        return f"$Z(p) = {sp.latex(self.impedance())}$"

    def _latex(self, printer: Any) -> str:
        return printer._print(self.impedance()) if printer is not None else sp.latex(self.impedance())

    def _sympystr(self, printer: Any) -> str:  # pragma: no cover - every element defines its own
        return type(self).__name__

    def _pretty(self, printer: Any) -> Any:
        from sympy.printing.pretty.stringpict import prettyForm

        return prettyForm(repr(self))


def _check_port(other: Any) -> OnePort:
    if not isinstance(other, OnePort):
        raise ParameterError(f"can only connect one-port networks, got {type(other).__name__}")
    return other


def _fmt(value: sp.Expr) -> str:
    """An element value as text; an exact algebraic number too long to read (exact syntheses in large number fields
    give polynomials in a ``CRootOf`` with coefficients of thousands of digits) is shown by 15 digits after ``≈``."""
    if not (value.is_number and value.has(sp.CRootOf)):
        return sp.sstr(value)
    try:
        text = sp.sstr(value)
    except ValueError:  # an integer beyond Python's limit for decimal conversion
        text = None
    if text is not None and len(text) <= _LONGEST_VALUE:
        return text
    return f"≈{sp.N(value, 15)}"


#: Longest exact element value printed in full.
_LONGEST_VALUE = 300


@dataclass(frozen=True, repr=False)
class Resistor(OnePort):
    """Resistor ``Z = R``.

    Parameters
    ----------
    R : number or SymPy expression
        Resistance, which must be positive (a number > 0 or a symbol not known to be zero or negative).
    """

    R: Any

    def __post_init__(self) -> None:
        object.__setattr__(self, "R", element_value(self.R, "R"))

    def impedance(self, p: sp.Symbol = P) -> sp.Expr:
        return self.R

    def _sympystr(self, printer: Any) -> str:
        return f"R({_fmt(self.R)})"


@dataclass(frozen=True, repr=False)
class Inductor(OnePort):
    """Inductor ``Z = L p``.

    Parameters
    ----------
    L : number or SymPy expression
        Inductance, which must be positive (a number > 0 or a symbol not known to be zero or negative).
    """

    L: Any

    def __post_init__(self) -> None:
        object.__setattr__(self, "L", element_value(self.L, "L"))

    def impedance(self, p: sp.Symbol = P) -> sp.Expr:
        return self.L * as_symbol(p)

    def _sympystr(self, printer: Any) -> str:
        return f"L({_fmt(self.L)})"


@dataclass(frozen=True, repr=False)
class Capacitor(OnePort):
    """Capacitor ``Z = 1/(C p)``.

    Parameters
    ----------
    C : number or SymPy expression
        Capacitance, which must be positive (a number > 0 or a symbol not known to be zero or negative).
    """

    C: Any

    def __post_init__(self) -> None:
        object.__setattr__(self, "C", element_value(self.C, "C"))

    def impedance(self, p: sp.Symbol = P) -> sp.Expr:
        return 1 / (self.C * as_symbol(p))

    def _sympystr(self, printer: Any) -> str:
        return f"C({_fmt(self.C)})"


@dataclass(frozen=True, repr=False)
class Impedance(OnePort):
    """A generic impedance ``Z``, an expression in the standard symbol ``p`` (or free of it).

    No passivity is assumed: use it for symbolic section formulas such as ``Impedance(sympy.Symbol("Z_A"))``.

    Parameters
    ----------
    Z : number or SymPy expression
        The impedance, a finite scalar expression in the standard symbol ``p`` (or free of it) that must not be
        identically zero.
    """

    Z: Any

    def __post_init__(self) -> None:
        object.__setattr__(self, "Z", as_expr(self.Z, "Z"))
        if self.Z == 0:
            raise ParameterError("Z must not be identically zero (use a short circuit in the enclosing network)")

    def impedance(self, p: sp.Symbol = P) -> sp.Expr:
        return self.Z if p == P else self.Z.xreplace({P: as_symbol(p)})

    def _sympystr(self, printer: Any) -> str:
        return f"Z({_fmt(self.Z)})"


def _flatten(parts: tuple, cls: type) -> tuple:
    out: list = []
    for part in parts:
        _check_port(part)
        out.extend(part.parts if isinstance(part, cls) else (part,))
    return tuple(out)


@dataclass(frozen=True, repr=False)
class Series(OnePort):
    """Series connection: ``Z = Z_1 + Z_2 + ...``.

    Parameters
    ----------
    parts : tuple of OnePort
        The connected one-ports, at least one (nested series connections are flattened).
    """

    parts: tuple = ()

    def __post_init__(self) -> None:
        parts = connection_parts(self.parts, "Series", OnePort, "a + b")
        object.__setattr__(self, "parts", _flatten(parts, Series))

    def impedance(self, p: sp.Symbol = P) -> sp.Expr:
        fast = _rational_impedance(self, p)
        return fast if fast is not None else sp.cancel(sp.Add(*(part.impedance(p) for part in self.parts)))

    def elements(self) -> tuple:
        return tuple(e for part in self.parts for e in part.elements())

    def _sympystr(self, printer: Any) -> str:
        return " + ".join(_wrap(part, Parallel) for part in self.parts)


@dataclass(frozen=True, repr=False)
class Parallel(OnePort):
    """Parallel connection: ``1/Z = 1/Z_1 + 1/Z_2 + ...``.

    Parameters
    ----------
    parts : tuple of OnePort
        The connected one-ports, at least one (nested parallel connections are flattened).
    """

    parts: tuple = ()

    def __post_init__(self) -> None:
        parts = connection_parts(self.parts, "Parallel", OnePort, "a | b")
        object.__setattr__(self, "parts", _flatten(parts, Parallel))

    def impedance(self, p: sp.Symbol = P) -> sp.Expr:
        fast = _rational_impedance(self, p)
        return fast if fast is not None else sp.cancel(1 / sp.Add(*(1 / part.impedance(p) for part in self.parts)))

    def elements(self) -> tuple:
        return tuple(e for part in self.parts for e in part.elements())

    def _sympystr(self, printer: Any) -> str:
        return " | ".join(_wrap(part, Series) for part in self.parts)


def _rational_impedance(net: OnePort, p: sp.Symbol) -> sp.Expr | None:
    """The impedance of a network whose element values are all rational numbers, by exact polynomial arithmetic
    over QQ (one numerator/denominator pair per subnetwork, one gcd per connection) and a single ``cancel`` at the
    end; None when a value is not rational (symbols, radicals, ``CRootOf``: SymPy's ``cancel`` level by level)."""
    p = as_symbol(p)
    try:
        N, D = _pair(net)
    except _NotRational:
        return None
    if not N:
        return sp.S.Zero
    R = _ring(p)
    top, bottom = R.from_list(N).cancel(R.from_list(D))  # SymPy's cancel(), whose normal form this returns
    return top.as_expr() / bottom.as_expr()


@functools.lru_cache(maxsize=8)
def _ring(p: sp.Symbol) -> PolyRing:
    return PolyRing([p], QQ)


class _NotRational(Exception):
    pass


def _q(value: sp.Expr):
    if not value.is_Rational:
        raise _NotRational
    return QQ.from_sympy(value)


def _pair(net: OnePort) -> tuple[list, list]:
    """``(N, D)``: coprime dense coefficient lists over QQ (highest power of ``p`` first) with ``Z = N/D``."""
    one = [QQ.one]
    if isinstance(net, Resistor):
        return dup_strip([_q(net.R)]), one
    if isinstance(net, Inductor):
        return [_q(net.L), QQ.zero], one
    if isinstance(net, Capacitor):
        return one, [_q(net.C), QQ.zero]
    if isinstance(net, Series | Parallel):
        pairs = [_pair(part) for part in net.parts]
        if isinstance(net, Parallel):  # admittances add
            pairs = [(D, N) for N, D in pairs]
        top, bottom = pairs[0]
        for n, d in pairs[1:]:
            top, bottom = normalize(
                dup_add(dup_mul(top, d, QQ), dup_mul(n, bottom, QQ), QQ), dup_mul(bottom, d, QQ), QQ
            )
        return (bottom, top) if isinstance(net, Parallel) else (top, bottom)
    if isinstance(net, BruneSection):
        Lp, Ls, M, C = (_q(v) for v in (net.Lp, net.Ls, net.M, net.C))
        n_load, d_load = _pair(net.load)
        s_top, s_bottom = [M * C, QQ.zero, QQ.one], [C, QQ.zero]  # shunt M p + 1/(C p)
        o_top = dup_add(dup_mul([Ls - M, QQ.zero], d_load, QQ), n_load, QQ)  # output arm (Ls - M) p + Z_load
        bottom = dup_add(dup_mul(s_top, d_load, QQ), dup_mul(o_top, s_bottom, QQ), QQ)
        top = dup_add(dup_mul([Lp - M, QQ.zero], bottom, QQ), dup_mul(s_top, o_top, QQ), QQ)
        return normalize(top, bottom, QQ)
    raise _NotRational  # a generic Impedance


def _wrap(part: OnePort, cls: type) -> str:
    text = part._sympystr(None)
    return f"({text})" if isinstance(part, (cls, BruneSection)) else text


@dataclass(frozen=True, repr=False)
class BruneSection(OnePort):
    """Brune's section: perfectly coupled coils ``Lp``, ``Ls`` (mutual ``M``, ``M**2 = Lp*Ls``) and a capacitor.

    Its T equivalent has series arms ``Lp - M`` (input) and ``Ls - M`` (output), one of them negative, and the
    shunt branch ``M p + 1/(C p)``; the output is closed by ``load``.  All four values are positive, so the
    section is realisable with a transformer of unit coupling (Brune 1931; Bulgakov (1954), §9.27).

    ``Z = (Lp - M) p + [(M p + 1/(C p)) || ((Ls - M) p + Z_load)]``

    Parameters
    ----------
    Lp : number or SymPy expression
        Self-inductance of the input coil, which must be positive.
    Ls : number or SymPy expression
        Self-inductance of the output coil, which must be positive.
    M : number or SymPy expression
        Mutual inductance, which must be positive (``M**2 = Lp*Ls`` for Brune's section; :attr:`coupling` reports
        ``M/sqrt(Lp*Ls)``).
    C : number or SymPy expression
        Capacitance in the shunt branch, which must be positive.
    load : OnePort
        The one-port that closes the output of the section (the remainder of the synthesis).
    """

    Lp: Any
    Ls: Any
    M: Any
    C: Any
    load: OnePort

    def __post_init__(self) -> None:
        for name in ("Lp", "Ls", "M", "C"):
            object.__setattr__(self, name, element_value(getattr(self, name), name))
        _check_port(self.load)

    def impedance(self, p: sp.Symbol = P) -> sp.Expr:
        fast = _rational_impedance(self, p)
        if fast is not None:
            return fast
        p = as_symbol(p)
        shunt = self.M * p + 1 / (self.C * p)
        out = (self.Ls - self.M) * p + self.load.impedance(p)
        return sp.cancel((self.Lp - self.M) * p + shunt * out / (shunt + out))

    @property
    def coupling(self) -> sp.Expr:
        """Coupling coefficient ``M / sqrt(Lp Ls)`` (1 for Brune's section)."""
        return sp.simplify(self.M / sp.sqrt(self.Lp * self.Ls))

    def elements(self) -> tuple:
        return (self, *self.load.elements())

    def _sympystr(self, printer: Any) -> str:
        return (
            f"Brune(Lp={_fmt(self.Lp)}, Ls={_fmt(self.Ls)}, M={_fmt(self.M)}, C={_fmt(self.C)}; "
            f"load={self.load._sympystr(None)})"
        )


@validated
def equivalent_two_pole(a: Any, b: Any) -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr]:
    """Coefficients of the equivalent two-pole of Bulgakov (1954), §8.31, eqs. (8.248)–(8.252).

    The two-pole ``(Z1 || Z2) + a Z1 + b Z2`` equals ``(c Z1 + d Z2) || (e Z1 + f Z2)`` for all ``Z1``, ``Z2``
    when ``B = sqrt((1 + a + b)**2 - 4 a b)`` and

    ``c, e = (B/2) (B ± (1 - a + b))``,  ``d, f = (B/2) (B ∓ (1 + a - b))``

    with the signs coupled ("+" for ``c`` goes with "-" for ``d``); the other two sign combinations fail.

    Parameters
    ----------
    a, b : number or SymPy expression
        Non-negative coefficients of the series arms of network (a).

    Returns
    -------
    tuple
        ``(c, d, e, f)`` as SymPy expressions.

    Examples
    --------
    >>> from symosc.networks import equivalent_two_pole
    >>> equivalent_two_pole(1, 2)
    (4 - 2*sqrt(2), 4, 2*sqrt(2) + 4, 4)

    See Also
    --------
    Series, Parallel
    """
    a, b = as_expr(a, "a"), as_expr(b, "b")
    for name, v in (("a", a), ("b", b)):
        if v.is_negative:
            raise ParameterError(f"{name} = {v} must be non-negative (it multiplies an element of the network)")
    B = sp.sqrt(sp.expand((1 + a + b) ** 2 - 4 * a * b))
    c = sp.expand(B / 2 * (B - (1 - a + b)))
    e = sp.expand(B / 2 * (B + (1 - a + b)))
    d = sp.expand(B / 2 * (B + (1 + a - b)))
    f = sp.expand(B / 2 * (B - (1 + a - b)))
    return c, d, e, f
