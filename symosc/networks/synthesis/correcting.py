"""Constant-resistance correcting networks: symmetric lattices and bridged T's (Bulgakov (1954), §9.34–9.40).

A symmetric lattice with series arms ``Za`` and cross arms ``Zb = W²/Za`` has the image impedance ``W`` at every
frequency; closed by ``W`` its transfer (transmittance) is ``X = Ey/Ex = (W - Za)/(W + Za)``, so a desired ``X(p)``
gives ``Za = W (1 - X)/(1 + X)``, eqs. (9.509)–(9.513).  ``X`` is realisable by a passive lattice iff it is regular
in the closed right half-plane (infinity included) and ``|X(iω)| <= 1`` (9.518); a cascade of such links with the
same ``W`` multiplies the transfers.

>>> import sympy as sp
>>> from symosc.networks import correcting_link, link_transfer
>>> p = sp.Symbol("p")
>>> link = correcting_link(link_transfer("lead", T1=2, T2=1), W=1)     # link II
>>> link.Za, link.Zb
(C(4) | R(1/3), L(4) + R(3))
>>> sp.factor(link.realized_transfer())
(2*p + 1)/(2*(p + 1))
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._exact.polynomial_tests import is_strictly_hurwitz, max_gain_on_axis, nonnegative_on_half_line, roots_numeric
from .._util import P, as_expr, as_symbol, element_value, rational_function
from ..ports._nodal import Netlist
from ..ports.fourpoles import FourPole
from ..ports.oneports import OnePort, Resistor
from ..ports.sections import bridged_t_section, lattice, t_section
from ._correcting import LINKS, dual, positive, require_less
from ._synthesis import minimum_real_part

__all__ = [
    "CORRECTING_LINKS",
    "BridgedTLink",
    "CorrectingLink",
    "constant_resistance_bridged_t",
    "correcting_link",
    "lattice_from_transmission",
    "link_transfer",
]

#: The links of Bulgakov (1954), Tables 8–9 and §9.39: name -> (book numeral, table, transfer).
CORRECTING_LINKS = LINKS


@validated
def link_transfer(
    kind: str,
    *,
    T1: Any = None,
    T2: Any = None,
    T: Any = None,
    zeta1: Any = None,
    zeta2: Any = None,
    k: Any = 1,
    sign: int = 1,
    p: sp.Symbol = P,
) -> sp.Expr:
    """Transfer ``X(p)`` of a standard correcting link (Bulgakov (1954), §9.38, Tables 8–9; §9.39).

    ========================  =====  ======================================================================
    ``kind``                  book   ``X(p)``
    ========================  =====  ======================================================================
    ``"attenuator"``          I      ``1/k``  (``k > 1``)
    ``"lead"``                II     ``(T2/(k T1)) (T1 p + 1)/(T2 p + 1)``,  ``T1 > T2``
    ``"lead-stabilizing"``    III    ``(T2/(k T1)) (T1 p - 1)/(T2 p + 1)``,  ``T1 > T2``
    ``"lag"``                 IV     ``(1/k) (T1 p + 1)/(T2 p + 1)``,  ``T1 < T2``
    ``"lag-stabilizing"``     V      ``(1/k) (T1 p - 1)/(T2 p + 1)``,  ``T1 < T2``
    ``"all-pass"``            VI     ``(1/k) (T p - 1)/(T p + 1)``
    ``"differentiating"``     VII    ``(1/k) T p/(T p + 1)``
    ``"low-pass"``            VIII   ``(1/k)/(T p + 1)``
    ``"second-order"``        IX–XV  ``(1/k) (T1² p² + 2 ζ1 T1 p + sign)/(T2² p² + 2 ζ2 T2 p + 1)``
    ========================  =====  ======================================================================

    The partial gain ``c`` of the book (``T1/T2`` for II and III, ``k`` otherwise) restores unit gain; ``k > 1``
    adds the flat loss ``ln k`` that lets the book avoid ideal elements (9.525).  Whether a second-order link is
    passive (``|X(iω)| <= 1``) depends on ``k``; :func:`correcting_link` checks it.

    Parameters
    ----------
    kind : str
        One of :data:`CORRECTING_LINKS`.
    T1, T2, T : positive number or symbol
        Time constants (which ones depends on ``kind``).
    zeta1, zeta2 : number
        Damping ratios of the numerator (``>= 0``) and denominator (``> 0``) of a second-order link.
    k : number
        Flat attenuation factor ``>= 1`` (``> 1`` for the attenuator).
    sign : {1, -1}
        Sign of the constant term of a second-order numerator.
    p : sympy.Symbol, optional
        Operator variable of the transfer, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Returns
    -------
    sympy.Expr

    Examples
    --------
    >>> from symosc.networks import link_transfer
    >>> link_transfer("lag", T1=1, T2=4, k=2)
    (p + 1)/(8*p + 2)

    See Also
    --------
    correcting_link, CORRECTING_LINKS
    """
    p = as_symbol(p)
    if not isinstance(kind, str) or kind not in LINKS:
        raise ParameterError(f"kind must be one of {sorted(LINKS)}, got {kind!r}")
    k = positive(k, "k")
    if kind == "attenuator":
        require_less(sp.Integer(1), k, f"k = {k} must exceed 1 for the attenuator link (X = 1/k, a = ln k)")
        return 1 / k
    if (k - 1).is_negative:
        raise ParameterError(f"k = {k} < 1 would amplify: a passive link needs k >= 1 (Bulgakov (1954), (9.519))")
    if kind in ("lead", "lead-stabilizing", "lag", "lag-stabilizing"):
        T1, T2 = positive(T1, "T1"), positive(T2, "T2")
        s = 1 if kind in ("lead", "lag") else -1
        if kind.startswith("lead"):
            require_less(T2, T1, f"the lead links need T1 > T2, got T1 = {T1}, T2 = {T2}")
            return T2 / (k * T1) * (T1 * p + s) / (T2 * p + 1)
        require_less(T1, T2, f"the lag links need T1 < T2, got T1 = {T1}, T2 = {T2}")
        return (T1 * p + s) / (k * (T2 * p + 1))
    if kind == "second-order":
        T1, T2 = positive(T1, "T1"), positive(T2, "T2")
        z2 = positive(zeta2, "zeta2")
        z1 = sp.sympify(0 if zeta1 is None else zeta1)
        if not isinstance(z1, sp.Expr) or z1.is_extended_real is False or z1.is_negative:
            raise ParameterError(f"zeta1 must be a real number >= 0, got {zeta1!r}")
        if sign not in (1, -1):
            raise ParameterError(f"sign must be 1 or -1, got {sign!r}")
        return (T1**2 * p**2 + 2 * z1 * T1 * p + sign) / (k * (T2**2 * p**2 + 2 * z2 * T2 * p + 1))
    T = positive(T, "T")
    if kind == "all-pass":
        return (T * p - 1) / (k * (T * p + 1))
    if kind == "differentiating":
        return T * p / (k * (T * p + 1))
    return 1 / (k * (T * p + 1))


def _rational_cycle(Z: sp.Expr, p: sp.Symbol) -> bool:
    """True when the minimum real parts of ``Z`` and ``1/Z`` lie at rational points with rational values.

    Then a Bott–Duffin cycle keeps rational element values; otherwise its exact arithmetic in nested square roots
    is very slow and Brune's cycle (coupled coils) is used instead.
    """
    for F in (Z, sp.cancel(1 / Z)):
        try:
            value, x0 = minimum_real_part(F, p)
        except TypeError:  # a pole at p = 0 makes Re F(iω) undefined at ω = 0: let Brune's removals go first
            return False
        if not all(v == sp.oo or v.is_Rational for v in (value, x0)):
            return False
    return True


def _synthesize(Z: sp.Expr, p: sp.Symbol, method: str) -> OnePort:
    if not Z.has(p):
        return Resistor(Z)
    if method == "auto":
        method = "bott-duffin" if _rational_cycle(Z, p) else "brune"
    if method == "brune":
        from .brune import brune_synthesis

        return brune_synthesis(Z, p)
    from .bott_duffin import bott_duffin_synthesis

    return bott_duffin_synthesis(Z, p)


def _arms(Za: sp.Expr, W: sp.Expr, p: sp.Symbol, method: str) -> tuple[OnePort, OnePort]:
    net_a = _synthesize(Za, p, method)
    net_b = dual(net_a, W**2)
    if net_b is None:
        net_b = _synthesize(sp.cancel(W**2 / Za), p, method)
    return net_a, net_b


@dataclass(frozen=True)
class CorrectingLink(SymPyPrintable):
    """A constant-resistance symmetric lattice: series arms ``Za``, cross arms ``Zb`` with ``Za Zb = W²``.

    Built by :func:`correcting_link`; closed by ``W`` it transmits ``X = (W - Za)/(W + Za)`` and shows ``W`` at
    its input at every frequency (Bulgakov (1954), §9.34).

    Attributes
    ----------
    transfer : sympy.Expr
        The requested transfer ``X(p)``.
    W : sympy.Expr
        The constant image (and input) resistance.
    Za, Zb : OnePort
        Networks of the series and cross arms (element values exact).
    p : sympy.Symbol
        Operator variable of the transfer and of the arms' impedances.
    max_gain : float
        ``max |X(iω)|`` (at most 1).

    Examples
    --------
    >>> from symosc.networks import correcting_link, link_transfer
    >>> link = correcting_link(link_transfer("attenuator", k=3), W=600)
    >>> link
    CorrectingLink(X = 1/3, W = 600; Za = R(300), Zb = R(1200))
    >>> link.input_impedance()
    600

    See Also
    --------
    correcting_link, constant_resistance_bridged_t, lattice
    """

    transfer: sp.Expr
    W: sp.Expr
    Za: OnePort
    Zb: OnePort
    p: sp.Symbol = P
    max_gain: float = 1.0

    @functools.cached_property
    def four_pole(self) -> FourPole:
        """The symmetric lattice as a :class:`FourPole`, chain matrix from its arms by eqs. (8.360)–(8.364).

        ``A11 = A22 = (Zb + Za)/(Zb - Za)``, ``A12 = 2 Za Zb/(Zb - Za)``, ``A21 = 2/(Zb - Za)``.
        """
        p = self.p
        za, zb = self.Za.impedance(p), self.Zb.impedance(p)
        d = zb - za
        chain = [[sp.cancel((zb + za) / d), sp.cancel(2 * za * zb / d)], [sp.cancel(2 / d), sp.cancel((zb + za) / d)]]
        net = lattice(sp.Symbol("Z_a"), sp.Symbol("Z_b")).netlist
        arm = {sp.Symbol("Z_a"): za, sp.Symbol("Z_b"): zb}
        branches = tuple((pairs, sp.ImmutableMatrix([[arm[Zb[0, 0]]]])) for pairs, Zb in net.branches)
        return FourPole(chain, p, Netlist(branches, net.terminals), name="constant-resistance lattice")

    def realized_transfer(self) -> sp.Expr:
        """``Ey/Ex`` of the lattice closed by ``W``, computed from its chain matrix: ``1/(A11 + A12/W)``."""
        A = self.four_pole.chain
        return sp.cancel(1 / (A[0, 0] + A[0, 1] / self.W))

    def input_impedance(self) -> sp.Expr:
        """Input impedance with the output closed by ``W`` (equal to ``W`` at all frequencies)."""
        return self.four_pole.input_impedance(self.W)

    def attenuation_phase(self, omega: Any) -> tuple[float, float]:
        """Attenuation ``a = -ln|X(iω)|`` (nepers) and phase ``b = -arg X(iω)`` at ``omega`` (rad/s), eq. (9.511).

        Parameters
        ----------
        omega : float
            Angular frequency in rad/s, a finite real number.
        """
        value = complex(sp.lambdify(self.p, self.transfer, "mpmath")(mpmath.mpc(0, float(omega))))
        g = -mpmath.log(value)
        return float(g.real), float(g.imag)

    def plot(self, omega: Any = None, *, ax: Any = None) -> Any:
        """Attenuation (solid) and phase (dashed) against ``ω`` on a log axis, as in Bulgakov's Figs. 161–166.

        Parameters
        ----------
        omega : array_like, optional
            Angular frequencies in rad/s, finite positive numbers (a log axis); 200 points from 0.01 to 100 when
            omitted.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from ..._plotting import pyplot

        plt = pyplot()
        import numpy as np

        if ax is None:
            _, ax = plt.subplots()
        w = np.logspace(-2, 2, 200) if omega is None else np.asarray(omega, dtype=float)
        ab = np.array([self.attenuation_phase(x) for x in w])
        ax.semilogx(w, ab[:, 0], "-", label="attenuation a [Np]")
        ax.semilogx(w, ab[:, 1], "--", label="phase b [rad]")
        ax.set_xlabel("ω [rad/s]")
        ax.legend()
        return ax

    def __repr__(self) -> str:
        return f"CorrectingLink(X = {sp.sstr(self.transfer)}, W = {self.W}; Za = {self.Za!r}, Zb = {self.Zb!r})"

    def _sympystr(self, printer: Any) -> str:
        return repr(self)

    def _latex(self, printer: Any) -> str:
        return (
            rf"X(p) = {sp.latex(self.transfer)},\ W = {sp.latex(self.W)},\ "
            rf"Z_a = {sp.latex(self.Za.impedance(self.p))},\ Z_b = {sp.latex(self.Zb.impedance(self.p))}"
        )

    def _repr_latex_(self) -> str:
        return f"${self._latex(None)}$"


def _check_transfer(X: Any, p: sp.Symbol, max_degree: int | None = 2) -> tuple[sp.Poly, sp.Poly]:
    N, D = rational_function(X, p, "X")
    free = (N.as_expr().free_symbols | D.as_expr().free_symbols) - {p}
    if free:
        names = sorted(free, key=str)
        raise ParameterError(f"X must have numeric coefficients to be realised; substitute values for {names}")
    if N.is_zero:
        raise ParameterError("X = 0: the lattice would be a balanced bridge transmitting nothing")
    if N.degree() > D.degree():
        raise ParameterError(
            "X is not regular at p = oo (numerator degree above the denominator's): not realisable by a "
            "passive lattice, Bulgakov (1954), §9.36"
        )
    if max_degree is not None and D.degree() > max_degree:
        raise ParameterError(
            f"X has degree {D.degree()}: a single link realises first- and second-order transfers; factor X into "
            "first- and second-order factors and realise each as its own link with the same W (their cascade "
            "multiplies the transfers: correcting_cascade does this), Bulgakov (1954), §9.37"
        )
    if not is_strictly_hurwitz(D):
        poles = [z for z in map(complex, roots_numeric(D)) if z.real >= -1e-12]
        raise ParameterError(
            f"X has poles in the closed right half-plane Re p >= 0 (at {poles}): not realisable by a passive "
            "lattice, Bulgakov (1954), §9.36, (9.518)"
        )
    if max_degree is None:
        return N, D
    x = sp.Dummy("x")

    def sq(Pl: sp.Poly) -> sp.Expr:
        return sp.expand(Pl.as_expr().subs(p, sp.I * sp.sqrt(x)) * Pl.as_expr().subs(p, -sp.I * sp.sqrt(x)))

    if not nonnegative_on_half_line(sp.Poly(sq(D) - sq(N), x)):
        m = max_gain_on_axis(N, D)
        raise ParameterError(
            f"|X(iω)| exceeds 1 (max |X(iω)| = {m:.6g}): a passive lattice can only attenuate, Bulgakov (1954), "
            f"(9.518); divide X by a constant k >= {m:.6g} (a flat loss ln k, (9.519)–(9.520)) or raise k"
        )
    return N, D


def lattice_arm(X: sp.Expr, W: sp.Expr) -> sp.Expr:
    """The arm ``Za = W (1 - X)/(1 + X)`` of the symmetric constant-resistance lattice with transfer ``X`` and image
    resistance ``W`` (Bulgakov (1954), (9.513)); the other arm is ``W²/Za``."""
    return sp.cancel(W * (1 - X) / (1 + X))


@validated
def lattice_from_transmission(X: Any, W: Any, p: sp.Symbol = P) -> FourPole:
    """Symmetric lattice of image impedance ``W`` with transmission ``e^{-g} = X(p)`` (eqs. (9.493), (9.512)).

    ``Za = W (1 - X)/(1 + X)`` and ``Zb = W²/Za``.  Realisable (ideal elements allowed) iff ``Za`` is positive real,
    i.e. ``X`` is analytic in the closed right half-plane with ``|X(iω)| <= 1`` (§9.34).

    Parameters
    ----------
    X : SymPy expression
        Transmission ``e^{-g}`` as a rational function of ``p``, which must be analytic in the closed right half-plane
        with ``|X(iω)| <= 1`` and not identically 1.
    W : number or SymPy expression
        Image impedance of the lattice, which must be positive.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import lattice_from_transmission
    >>> p = sp.Symbol("p")
    >>> lat = lattice_from_transmission((1 - p) / (1 + p), 1, p)        # first-order all-pass
    >>> sp.simplify(lat.chain - lattice(p, 1 / p).chain)
    Matrix([
    [0, 0],
    [0, 0]])

    The arms are returned as impedances, for a transfer of any degree; :func:`correcting_link` realises the same
    lattice (the same arms) with networks of positive R, L, C (and coupled coils where needed) for transfers of degree
    up to 2.

    See Also
    --------
    lattice, lattice_phase_network, correcting_link
    """
    from .positive_real import require_positive_real

    X, W = as_expr(X, "X"), element_value(W, "W")
    Za = lattice_arm(X, W)
    if Za == 0:
        raise ParameterError("X = 1 gives a short-circuited lattice arm")
    require_positive_real(Za, p, "the lattice arm W(1 - X)/(1 + X)")
    return lattice(Za, sp.cancel(W**2 / Za), p=p)


@validated
def correcting_link(X: Any, W: Any = 1, p: sp.Symbol = P, *, method: str = "auto") -> CorrectingLink:
    """Constant-resistance lattice realising the transfer ``X(p)`` (Bulgakov (1954), §9.34–9.39).

    ``Za = W (1 - X)/(1 + X)`` (9.513) and ``Zb = W²/Za`` are positive real when ``X`` is regular in the closed
    right half-plane and ``|X(iω)| <= 1`` (9.518); both are realised as networks: ``Za`` by Bott–Duffin
    (or Brune) synthesis, which for first-order links gives the forms of Tables 8–9 (a resistor with an R–L or
    R–C pair), and ``Zb`` as its inverse (dual) network.

    Parameters
    ----------
    X : SymPy expression
        Desired transfer ``Ey/Ex``, rational in ``p`` with numeric coefficients (see :func:`link_transfer`).
    W : positive number
        The constant resistance between which the link works.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.
    method : {"auto", "bott-duffin", "brune"}
        One-port synthesis of ``Za``: "bott-duffin" uses R, L, C only, "brune" perfectly coupled coils where the
        real part of ``Za`` touches zero; "auto" takes Bott–Duffin when its element values stay rational and
        Brune otherwise (the book's aim of avoiding mutual inductances cannot always be met exactly).

    Returns
    -------
    CorrectingLink

    Raises
    ------
    ParameterError
        When ``X`` is not realisable (pole in ``Re p >= 0``, not regular at infinity, ``|X(iω)| > 1``), is 0 or
        ±1, is of degree above 2 (cascade first- and second-order links instead, §9.37), or ``W`` is not
        positive.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import correcting_link
    >>> p = sp.Symbol("p")
    >>> link = correcting_link((p + 1) / (2 * (4 * p + 1)), W=1)     # lag link IV, k = 2
    >>> sp.factor(link.Za.impedance(p))         # Table 8: (a0 p + a1)/(b0 p + b1), a0 = kT2 - T1, b0 = kT2 + T1
    (7*p + 1)/(3*(3*p + 1))
    >>> link.Za, link.Zb
    (R(1/3) + (L(4/3) | R(4/9)), R(3) | (C(4/3) + R(9/4)))
    >>> sp.cancel(link.realized_transfer() - link.transfer)
    0

    See Also
    --------
    link_transfer, constant_resistance_bridged_t, lattice_from_transmission
    """
    p = as_symbol(p)
    W = element_value(W, "W")
    if not W.is_number:
        raise ParameterError(f"W must be a positive number, got {W}")
    if method not in ("auto", "bott-duffin", "brune"):
        raise ParameterError(f"method must be 'auto', 'bott-duffin' or 'brune', got {method!r}")
    N, D = _check_transfer(X, p)
    Xe = sp.cancel(N.as_expr() / D.as_expr())
    if Xe in (1, -1):
        raise ParameterError(f"X = {Xe}: the arms would be a short and an open circuit; nothing to realise")
    Za = lattice_arm(Xe, W)
    net_a, net_b = _arms(Za, W, p, method)
    return CorrectingLink(Xe, W, net_a, net_b, p, max_gain_on_axis(N, D))


@dataclass(frozen=True)
class BridgedTLink(SymPyPrintable):
    """A symmetric bridged T equivalent to a constant-resistance lattice (Bulgakov (1954), §9.40, Fig. 187).

    Series arms ``R1`` (resistors), shunt arm ``shunt``, bridge ``bridge`` (``None``: no bridge).  With
    ``crossed=True`` the output terminals are interchanged (the network's chain matrix is minus that of the bridged
    T), which the book uses when ``Zb`` rather than ``Za`` holds the resistor.

    Attributes
    ----------
    R1 : SymPy expression
        Resistance of each of the two series arms.
    bridge : OnePort or None
        Network of the bridge from input to output; None when there is no bridge (``R1`` equal to the lattice's parallel
        resistance).
    shunt : OnePort
        Network of the shunt arm.
    W : SymPy expression
        The constant image (and input) resistance.
    crossed : bool
        Whether the output terminals are interchanged (the chain matrix is then minus that of the bridged T).
    p : sympy.Symbol
        Operator variable of the arms' impedances.

    Examples
    --------
    >>> from symosc.networks import constant_resistance_bridged_t, correcting_link, link_transfer
    >>> tee = constant_resistance_bridged_t(correcting_link(link_transfer("lead", T1=2, T2=1)))
    >>> tee
    BridgedTLink(R1 = 1, bridge = C(2) | R(1), shunt = L(2) + R(1), crossed = False)

    See Also
    --------
    constant_resistance_bridged_t, bridged_t_section
    """

    R1: sp.Expr
    bridge: OnePort | None
    shunt: OnePort
    W: sp.Expr
    crossed: bool = False
    p: sp.Symbol = P

    @functools.cached_property
    def four_pole(self) -> FourPole:
        """Chain matrix from the bridged-T's own Y-parameters (eq. (8.420)); negated when ``crossed``."""
        p = self.p
        zs = self.shunt.impedance(p)
        if self.bridge is None:
            fp = t_section(self.R1, zs, self.R1, p=p)
        else:
            fp = bridged_t_section(self.R1, zs, self.R1, self.bridge.impedance(p), p=p)
        if not self.crossed:
            return fp
        return FourPole(-fp.chain, p, None, name="crossed bridged-T")

    def __repr__(self) -> str:
        return (
            f"BridgedTLink(R1 = {self.R1}, bridge = {self.bridge!r}, shunt = {self.shunt!r}, crossed = {self.crossed})"
        )

    def _sympystr(self, printer: Any) -> str:
        return repr(self)

    def _latex(self, printer: Any) -> str:
        bridge = r"\infty" if self.bridge is None else sp.latex(self.bridge.impedance(self.p))
        shunt = sp.latex(self.shunt.impedance(self.p))
        return rf"R_1 = {sp.latex(self.R1)},\ Z_{{bridge}} = {bridge},\ Z_{{shunt}} = {shunt}"

    def _repr_latex_(self) -> str:
        return f"${self._latex(None)}$"


@validated
def constant_resistance_bridged_t(link: CorrectingLink, R1: Any = None, *, method: str = "auto") -> BridgedTLink:
    """Convert a constant-resistance lattice to a symmetric bridged T where realisable (Bulgakov (1954), §9.40).

    The bridged T with series resistors ``R1``, bridge ``Z3`` and shunt ``Z2`` equals the lattice with
    ``Za = R1 || (Z3/2)`` and ``Zb = R1 + 2 Z2`` (Bartlett's bisection).  With ``Zb = W²/Za`` this gives

    ``Z3 = 2/(1/Za - 1/R1)``,  ``Z2 = (W²/Za - R1)/2``,

    both positive real iff ``Za`` holds a parallel resistance ``R <= W``, i.e. ``g = min Re 1/Za(iω) >= 1/W``,
    and ``1/g <= R1 <= g W²`` (Guillemin's device, eqs. (9.575)–(9.578)); ``R1 = W`` (the default) gives the
    classical constant-resistance bridged T with ``Z2 Z3 = W²``.  When instead ``Zb`` holds the parallel
    resistor (``Za`` a series resistance ``>= W``) the arms are swapped and the output terminals crossed.

    Parameters
    ----------
    link : CorrectingLink
        The constant-resistance lattice to convert (from :func:`correcting_link`).
    R1 : positive number, optional
        Series resistors (default ``W``).
    method : {"auto", "bott-duffin", "brune"}
        Synthesis of the bridge and shunt arms (as in :func:`correcting_link`).

    Returns
    -------
    BridgedTLink

    Raises
    ------
    ParameterError
        When neither ``Za`` nor ``Zb`` contains a parallel resistance ``<= W`` (links III, V, VI of the book), or
        ``R1`` lies outside ``[1/g, g W²]``.

    Examples
    --------
    >>> from symosc.networks import constant_resistance_bridged_t, correcting_link, link_transfer
    >>> link = correcting_link(link_transfer("lag", T1=1, T2=4, k=2))
    >>> tee = constant_resistance_bridged_t(link)
    >>> tee.four_pole.chain == link.four_pole.chain
    True

    See Also
    --------
    correcting_link, bridged_t_section
    """
    if not isinstance(link, CorrectingLink):
        raise ParameterError(f"link must be a CorrectingLink (from correcting_link), got {type(link).__name__}")
    if method not in ("auto", "bott-duffin", "brune"):
        raise ParameterError(f"method must be 'auto', 'bott-duffin' or 'brune', got {method!r}")
    p, W = link.p, link.W
    Za = link.Za.impedance(p)
    crossed = False
    g = _min_conductance(Za, p)
    if g < 1 / W:
        Zb = link.Zb.impedance(p)
        g_b = _min_conductance(Zb, p)
        if g_b < 1 / W:
            raise ParameterError(
                "the lattice has no bridged-T equivalent by Guillemin's device (Bulgakov (1954), §9.40, (9.578)): "
                f"Za holds no parallel resistance R <= W (min Re 1/Za(iω) = {sp.N(g, 6)} < 1/W = {sp.N(1 / W, 6)}) "
                f"and Zb none either (min Re 1/Zb(iω) = {sp.N(g_b, 6)})"
            )
        Za, g, crossed = Zb, g_b, True
    R1 = W if R1 is None else element_value(R1, "R1")
    if sp.N(R1 - 1 / g, 30) < 0 or sp.N(g * W**2 - R1, 30) < 0:
        raise ParameterError(
            f"R1 = {R1} must lie in [1/g, g W²] = [{sp.N(1 / g, 6)}, {sp.N(g * W**2, 6)}] "
            "(g = min Re 1/Za(iω)), Bulgakov (1954), (9.577)"
        )
    Ya = sp.cancel(1 / Za)
    Y3 = sp.cancel((Ya - 1 / R1) / 2)
    Z2 = sp.cancel((W**2 * Ya - R1) / 2)
    if Z2 == 0:
        raise ParameterError(f"R1 = {R1} makes the shunt arm a short circuit; choose R1 inside (1/g, g W²), e.g. W")
    shunt = _synthesize(Z2, p, method)
    if Y3 == 0:
        bridge = None
    else:
        Z3 = sp.cancel(1 / Y3)
        bridge = dual(shunt, W**2) if R1 == W else None
        if bridge is None:
            bridge = _synthesize(Z3, p, method)
    return BridgedTLink(R1, bridge, shunt, W, crossed, p)


def _min_conductance(Z: sp.Expr, p: sp.Symbol) -> sp.Expr:
    Y = sp.cancel(1 / Z)
    if not Y.has(p):
        return Y
    if sp.Poly(sp.fraction(Y)[0], p).degree() > sp.Poly(sp.fraction(Y)[1], p).degree() + 1:
        raise ModelError("1/Za is not positive real")  # pragma: no cover - excluded by construction
    return minimum_real_part(Y, p)[0]
