"""A library of four-pole sections with closed-form chain matrices (Bulgakov (1954), §8.35–8.45).

Impedance arguments are SymPy expressions in ``p`` or one-port networks (:class:`Resistor`, ...).  Every section
also carries its terminal-level netlist, so non-cascade connections can be Brune-tested.

>>> import sympy as sp
>>> from symosc.networks import t_section
>>> ZA, ZB, ZC = sp.symbols("Z_A Z_B Z_C")
>>> t_section(ZA, ZB, ZC).chain                # eq. (8.409)
Matrix([
[(Z_A + Z_B)/Z_B, (Z_A*Z_B + Z_A*Z_C + Z_B*Z_C)/Z_B],
[          1/Z_B,                   (Z_B + Z_C)/Z_B]])
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import validated
from ...errors import ParameterError
from .._util import P, as_expr, element_value
from ._nodal import Netlist
from .conversions import convert_parameters
from .fourpoles import FourPole
from .oneports import OnePort

__all__ = [
    "bridged_t_section",
    "ideal_transformer",
    "l_section",
    "lattice",
    "lattice_phase_network",
    "pi_section",
    "series_element",
    "shunt_element",
    "t_section",
    "transformer",
    "twin_t_notch",
    "twin_t_section",
]


def _z(value: Any, name: str, p: sp.Symbol) -> sp.Expr:
    if isinstance(value, OnePort):
        return value.impedance(p)
    z = as_expr(value, name)
    if z == 0:
        raise ParameterError(f"{name} must not be zero (a short circuit); leave the arm out instead")
    return z


def _b(a: str, b: str, z: sp.Expr) -> tuple:
    return (((a, b),), sp.ImmutableMatrix([[z]]))


_GROUNDED = ("1", "0", "2", "0")


@validated
def series_element(Z: Any, p: sp.Symbol = P) -> FourPole:
    """Series impedance: ``A = [[1, Z], [0, 1]]`` (Bulgakov (1954), §8.35).

    Parameters
    ----------
    Z : number, SymPy expression or OnePort
        Impedance of the series arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is refused).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> from symosc.networks import series_element
    >>> series_element(5).chain
    Matrix([
    [1, 5],
    [0, 1]])

    See Also
    --------
    shunt_element, l_section
    """
    z = _z(Z, "Z", p)
    return FourPole([[1, z], [0, 1]], p, Netlist((_b("1", "2", z),), _GROUNDED), name="series")


@validated
def shunt_element(Z: Any, p: sp.Symbol = P) -> FourPole:
    """Shunt impedance: ``A = [[1, 0], [1/Z, 1]]`` (Bulgakov (1954), §8.35).

    Parameters
    ----------
    Z : number, SymPy expression or OnePort
        Impedance of the shunt arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is refused).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> from symosc.networks import shunt_element
    >>> shunt_element(5).chain
    Matrix([
    [  1, 0],
    [1/5, 1]])

    See Also
    --------
    series_element, l_section
    """
    z = _z(Z, "Z", p)
    return FourPole([[1, 0], [1 / z, 1]], p, Netlist((_b("1", "0", z),), ("1", "0", "1", "0")), name="shunt")


@validated
def l_section(series: Any, shunt: Any, shunt_first: bool = False, p: sp.Symbol = P) -> FourPole:
    """L (Γ) half-section: series arm then shunt arm, or shunt first (Bulgakov's Γ of Fig. 101, eq. (8.413)).

    Parameters
    ----------
    series : number, SymPy expression or OnePort
        Impedance of the series arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is refused).
    shunt : number, SymPy expression or OnePort
        Impedance of the shunt arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is refused).
    shunt_first : bool, optional
        Whether the shunt arm comes first, at the input (Γ turned round); by default the series arm is at the input.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import l_section
    >>> Za, Zb = sp.symbols("Z_a Z_b")
    >>> l_section(Za, Zb, shunt_first=True).chain
    Matrix([
    [    1,             Z_a],
    [1/Z_b, (Z_a + Z_b)/Z_b]])

    See Also
    --------
    t_section, pi_section
    """
    za, zb = _z(series, "series", p), _z(shunt, "shunt", p)
    if shunt_first:
        A = [[1, za], [1 / zb, 1 + za / zb]]
        net = Netlist((_b("1", "0", zb), _b("1", "2", za)), _GROUNDED)
    else:
        A = [[1 + za / zb, za], [1 / zb, 1]]
        net = Netlist((_b("1", "2", za), _b("2", "0", zb)), _GROUNDED)
    return FourPole(A, p, net, name="L")


@validated
def t_section(ZA: Any, ZB: Any, ZC: Any, p: sp.Symbol = P) -> FourPole:
    """T section: series ``ZA``, shunt ``ZB``, series ``ZC`` (Bulgakov (1954), eqs. (8.408)–(8.412)).

    ``A = [[(ZA+ZB)/ZB, Σ2/ZB], [1/ZB, (ZB+ZC)/ZB]]`` with ``Σ2 = ZA ZB + ZB ZC + ZC ZA``.

    Parameters
    ----------
    ZA : number, SymPy expression or OnePort
        Impedance of the input series arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is
        refused).
    ZB : number, SymPy expression or OnePort
        Impedance of the shunt arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is refused).
    ZC : number, SymPy expression or OnePort
        Impedance of the output series arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is
        refused).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> from symosc.networks import t_section
    >>> t_section(1, 2, 3).Z
    Matrix([
    [3, -2],
    [2, -5]])

    See Also
    --------
    pi_section, l_section, bridged_t_section
    """
    za, zb, zc = _z(ZA, "ZA", p), _z(ZB, "ZB", p), _z(ZC, "ZC", p)
    s2 = za * zb + zb * zc + zc * za
    A = [[(za + zb) / zb, s2 / zb], [1 / zb, (zb + zc) / zb]]
    net = Netlist((_b("1", "m", za), _b("m", "0", zb), _b("m", "2", zc)), _GROUNDED)
    return FourPole(A, p, net, name="T")


@validated
def pi_section(ZA: Any, ZB: Any, ZC: Any, p: sp.Symbol = P) -> FourPole:
    """Π section: shunt ``ZA``, series ``ZB``, shunt ``ZC`` (Bulgakov (1954), eqs. (8.416)–(8.418)).

    Parameters
    ----------
    ZA : number, SymPy expression or OnePort
        Impedance of the input shunt arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is
        refused).
    ZB : number, SymPy expression or OnePort
        Impedance of the series arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is refused).
    ZC : number, SymPy expression or OnePort
        Impedance of the output shunt arm: a nonzero expression in ``p`` or a one-port network (a zero impedance is
        refused).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> from symosc.networks import pi_section
    >>> pi_section(1, 2, 3).chain
    Matrix([
    [5/3, 2],
    [  2, 3]])

    See Also
    --------
    t_section
    """
    za, zb, zc = _z(ZA, "ZA", p), _z(ZB, "ZB", p), _z(ZC, "ZC", p)
    A = [[(zb + zc) / zc, zb], [(za + zb + zc) / (za * zc), (za + zb) / za]]
    net = Netlist((_b("1", "0", za), _b("1", "2", zb), _b("2", "0", zc)), _GROUNDED)
    return FourPole(A, p, net, name="Pi")


@validated
def lattice(ZA: Any, ZB: Any, ZC: Any = None, ZD: Any = None, p: sp.Symbol = P) -> FourPole:
    """Lattice (bridge) four-pole, Bulgakov (1954), eqs. (8.356)–(8.364).

    Arms ``ZA`` (1–2), ``ZB`` (1'–2'), ``ZC`` (1–2'), ``ZD`` (1'–2).  With two arguments the lattice is
    symmetric: series arms ``Za = ZA``, cross arms ``Zb = ZB``, and
    ``A = [[Zb + Za, 2 Za Zb], [2, Zb + Za]] / (Zb - Za)``.

    Parameters
    ----------
    ZA : number, SymPy expression or OnePort
        Impedance of arm 1–2 (the series arm of a symmetric lattice): a nonzero expression in ``p`` or a one-port
        network (a zero impedance is refused).
    ZB : number, SymPy expression or OnePort
        Impedance of arm 1'–2' (the cross arm of a symmetric lattice): a nonzero expression in ``p`` or a one-port
        network (a zero impedance is refused).
    ZC : number, SymPy expression or OnePort, optional
        Impedance of arm 1–2', given together with ``ZD`` or not at all (a symmetric lattice when both are omitted).
    ZD : number, SymPy expression or OnePort, optional
        Impedance of arm 1'–2, given together with ``ZC`` or not at all; ``ZC*ZD`` must differ from ``ZA*ZB`` (a
        balanced bridge transmits nothing).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import lattice
    >>> Za, Zb = sp.symbols("Z_a Z_b")
    >>> lattice(Za, Zb).chain
    Matrix([
    [(-Z_a - Z_b)/(Z_a - Z_b),   -2*Z_a*Z_b/(Z_a - Z_b)],
    [          -2/(Z_a - Z_b), (-Z_a - Z_b)/(Z_a - Z_b)]])

    See Also
    --------
    lattice_phase_network, lattice_from_transmission
    """
    if (ZC is None) != (ZD is None):
        raise ParameterError("give either two impedances (symmetric lattice) or all four ZA, ZB, ZC, ZD")
    if ZC is None:
        za = zb_ = _z(ZA, "ZA", p)
        zc = zd = _z(ZB, "ZB", p)
    else:
        za, zb_, zc, zd = (_z(v, n, p) for v, n in ((ZA, "ZA"), (ZB, "ZB"), (ZC, "ZC"), (ZD, "ZD")))
    den = zc * zd - za * zb_
    if sp.cancel(den) == 0:
        raise ParameterError(
            "the lattice is a balanced bridge (ZC*ZD = ZA*ZB): it transmits nothing and has no chain matrix"
        )
    s = za + zb_ + zc + zd
    s3 = za * zb_ * zc + zb_ * zc * zd + zc * zd * za + zd * za * zb_
    A = (sp.Matrix([[(za + zd) * (zb_ + zc), s3], [s, (za + zc) * (zb_ + zd)]]) / den).applyfunc(sp.cancel)
    net = Netlist((_b("1", "2", za), _b("1'", "2'", zb_), _b("1", "2'", zc), _b("1'", "2", zd)), ("1", "1'", "2", "2'"))
    return FourPole(A, p, net, name="lattice")


@validated
def bridged_t_section(ZA: Any, ZB: Any, ZC: Any, ZD: Any, p: sp.Symbol = P) -> FourPole:
    """Bridged T: a T section (``ZA``, ``ZB``, ``ZC``) bridged from input to output by ``ZD`` (eq. (8.420)).

    ``Y = Y_T + (1/ZD) [[1, -1], [1, -1]]`` (book convention).

    Parameters
    ----------
    ZA : number, SymPy expression or OnePort
        Impedance of the input series arm of the T: a nonzero expression in ``p`` or a one-port network (a zero
        impedance is refused).
    ZB : number, SymPy expression or OnePort
        Impedance of the shunt arm of the T: a nonzero expression in ``p`` or a one-port network (a zero impedance is
        refused).
    ZC : number, SymPy expression or OnePort
        Impedance of the output series arm of the T: a nonzero expression in ``p`` or a one-port network (a zero
        impedance is refused).
    ZD : number, SymPy expression or OnePort
        Impedance of the bridge from input to output: a nonzero expression in ``p`` or a one-port network (a zero
        impedance is refused).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> from symosc.networks import bridged_t_section
    >>> bridged_t_section(1, 1, 1, 1).is_symmetric()
    True

    See Also
    --------
    t_section, twin_t_section
    """
    za, zb, zc, zd = (_z(v, n, p) for v, n in ((ZA, "ZA"), (ZB, "ZB"), (ZC, "ZC"), (ZD, "ZD")))
    s2 = za * zb + zb * zc + zc * za
    Y = sp.Matrix([[zb + zc, -zb], [zb, -(za + zb)]]) / s2 + sp.Matrix([[1, -1], [1, -1]]) / zd
    A = convert_parameters(Y, "Y", "A")
    net = Netlist((_b("1", "m", za), _b("m", "0", zb), _b("m", "2", zc), _b("1", "2", zd)), _GROUNDED)
    return FourPole(A, p, net, name="bridged-T")


@validated
def twin_t_section(first: tuple, second: tuple, p: sp.Symbol = P) -> FourPole:
    """Two T sections ``(ZA, ZB, ZC)`` in parallel: ``Y = Y_T1 + Y_T2`` (Bulgakov (1954), eqs. (8.421)–(8.423)).

    Parameters
    ----------
    first : tuple of three impedances
        The arms ``(ZA, ZB, ZC)`` of the first T section (series, shunt, series), each a nonzero expression in ``p`` or
        a one-port network.
    second : tuple of three impedances
        The arms ``(ZA, ZB, ZC)`` of the second T section, connected in parallel with the first.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> from symosc.networks import twin_t_section
    >>> twin_t_section((1, 1, 1), (2, 2, 2)).Y
    Matrix([
    [  1, -1/2],
    [1/2,   -1]])

    See Also
    --------
    twin_t_notch, bridged_t_section
    """
    from .connections import parallel

    if len(first) != 3 or len(second) != 3:
        raise ParameterError("first and second must each be three impedances (ZA, ZB, ZC) of a T section")
    out = parallel(t_section(*first, p=p), t_section(*second, p=p), check=False)
    return FourPole(out.chain, p, out.netlist, name="twin-T")


@validated
def twin_t_notch(R: Any, C: Any, s: Any = 1, p: sp.Symbol = P) -> FourPole:
    """Twin-T null network of Bulgakov (1954), Fig. 110 (example E16): transmission zero at ``ω = 1/(s R C)``.

    T1: ``R``, shunt ``1/(2 C p)``, ``R``; T2: ``1/(s² C p)``, shunt ``R/(2 s²)``, ``1/(s² C p)``.  Then
    ``Y11 = -Y22 = (s²R²C²p² + 2(1+s²)RCp + 1)/(2R(RCp+1))`` and ``Y12 = -Y21 = -(s²R²C²p² + 1)/(2R(RCp+1))``.

    Parameters
    ----------
    R : number or SymPy expression
        Resistance of the series arms of the first T, which must be positive.
    C : number or SymPy expression
        Capacitance fixing the arms ``1/(2 C p)`` and ``1/(s² C p)``, which must be positive.
    s : number or SymPy expression, optional
        Scale factor of the second T, which must be positive; the transmission zero lies at ``ω = 1/(s R C)`` (default
        1, the symmetric twin T of Fig. 110).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol (Carson/Laplace ``p``; put ``p = iω`` for the steady state); the
        standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import twin_t_notch
    >>> net = twin_t_notch(1, 1)
    >>> sp.factor(net.Y[1, 0])
    (p**2 + 1)/(2*(p + 1))

    See Also
    --------
    twin_t_section
    """
    R, C, s = element_value(R, "R"), element_value(C, "C"), element_value(s, "s")
    t1 = (R, 1 / (2 * C * p), R)
    t2 = (1 / (s**2 * C * p), R / (2 * s**2), 1 / (s**2 * C * p))
    out = twin_t_section(t1, t2, p)
    return FourPole(out.chain, p, out.netlist, name="twin-T notch")


@validated
def transformer(LA: Any, LB: Any, M: Any, RA: Any = 0, RB: Any = 0, p: sp.Symbol = P) -> FourPole:
    """Transformer with self-inductances ``LA``, ``LB``, mutual ``M`` and winding resistances (eqs. (8.331)–(8.338)).

    ``Z = [[LA p + RA, -M p], [M p, -(LB p + RB)]]`` (book convention); the ports are galvanically isolated.

    Parameters
    ----------
    LA : number or SymPy expression
        Self-inductance of the primary (input) winding, which must be positive.
    LB : number or SymPy expression
        Self-inductance of the secondary (output) winding, which must be positive.
    M : number or SymPy expression
        Mutual inductance, which must be positive and at most ``sqrt(LA*LB)`` (coupling coefficient at most 1).
    RA : number or SymPy expression, optional
        Resistance of the primary winding, which must be non-negative (default 0).
    RB : number or SymPy expression, optional
        Resistance of the secondary winding, which must be non-negative (default 0).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol (Carson/Laplace ``p``; put ``p = iω`` for the steady state); the
        standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import transformer
    >>> LA, LB = sp.symbols("L_A L_B", positive=True)
    >>> sp.simplify(transformer(LA, LB, sp.sqrt(LA * LB)).chain)    # unit coupling, eq. (8.340)
    Matrix([
    [      sqrt(L_A)/sqrt(L_B),                   0],
    [1/(sqrt(L_A)*sqrt(L_B)*p), sqrt(L_B)/sqrt(L_A)]])

    See Also
    --------
    ideal_transformer
    """
    LA, LB, M = element_value(LA, "LA"), element_value(LB, "LB"), element_value(M, "M")
    RA, RB = as_expr(RA, "RA"), as_expr(RB, "RB")
    for name, v in (("RA", RA), ("RB", RB)):
        if v.is_negative:
            raise ParameterError(f"{name} = {v} must be non-negative")
    if (LA * LB - M**2).is_negative:
        raise ParameterError(f"M = {M} exceeds sqrt(LA*LB): a coupling coefficient above 1 is not physical")
    Z = sp.Matrix([[LA * p + RA, -M * p], [M * p, -(LB * p + RB)]])
    return FourPole(convert_parameters(Z, "Z", "A"), p, None, isolated=True, name="transformer")


@validated
def ideal_transformer(q: Any, p: sp.Symbol = P) -> FourPole:
    """Ideal transformer (converter) ``A = diag(1/q, q)``, voltage ratio ``Ey/Ex = q`` (eqs. (8.343)–(8.344)).

    It isolates its ports, so any connection through it passes the Brune test.

    Parameters
    ----------
    q : number or SymPy expression
        Voltage ratio ``Ey/Ex``, which must be nonzero.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> from symosc.networks import ideal_transformer
    >>> ideal_transformer(2).chain
    Matrix([
    [1/2, 0],
    [  0, 2]])

    See Also
    --------
    transformer
    """
    q = as_expr(q, "q")
    if q == 0:
        raise ParameterError("q must be non-zero (the voltage ratio of the ideal transformer)")
    return FourPole([[1 / q, 0], [0, q]], p, None, isolated=True, name="ideal transformer")


@validated
def lattice_phase_network(L: Any, C: Any, p: sp.Symbol = P) -> FourPole:
    """All-pass lattice: series arms ``L p``, cross arms ``1/(C p)`` (Bulgakov (1954), eqs. (8.365)–(8.368), E18).

    ``W = sqrt(L/C)``, ``e^g = (1 + i sqrt(LC) ω)/(1 - i sqrt(LC) ω)``: no attenuation, phase
    ``b = 2 arctan(sqrt(LC) ω)``.

    Parameters
    ----------
    L : number or SymPy expression
        Inductance of each series arm ``L p``, which must be positive.
    C : number or SymPy expression
        Capacitance of each cross arm ``1/(C p)``, which must be positive.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol (Carson/Laplace ``p``; put ``p = iω`` for the steady state); the
        standard symbol ``p`` when omitted.

    Examples
    --------
    >>> from symosc.networks import lattice_phase_network
    >>> lattice_phase_network(1, 1).chain
    Matrix([
    [(-p**2 - 1)/(p**2 - 1),        -2*p/(p**2 - 1)],
    [       -2*p/(p**2 - 1), (-p**2 - 1)/(p**2 - 1)]])

    See Also
    --------
    lattice, image_parameters
    """
    L, C = element_value(L, "L"), element_value(C, "C")
    out = lattice(L * p, 1 / (C * p), p=p)
    return FourPole(out.chain, p, out.netlist, name="lattice phase network")
