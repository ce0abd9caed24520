"""Matching pads (Bulgakov (1954), §9.35, example T11)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from .._util import element_value
from ..ports.fourpoles import FourPole
from ..ports.sections import l_section

__all__ = ["MatchingPad", "matching_l_pad"]


@dataclass(frozen=True)
class MatchingPad(SymPyPrintable):
    """A resistive L pad: series ``Ra`` on the high side, shunt ``Rb`` on the low side, and its loss ``a0``.

    Attributes
    ----------
    Ra : SymPy expression
        Series resistance on the high-impedance (input) side, ``sqrt(Rx (Rx - Ry))``.
    Rb : SymPy expression
        Shunt resistance on the low-impedance (output) side, ``Ry sqrt(Rx/(Rx - Ry))``.
    loss : SymPy expression
        Image attenuation ``a0`` in nepers, ``ch a0 = sqrt(Rx/Ry)``.
    four_pole : FourPole
        The pad as an L section (series ``Ra``, then shunt ``Rb``).
    """

    Ra: sp.Expr
    Rb: sp.Expr
    loss: sp.Expr
    four_pole: FourPole

    def __repr__(self) -> str:
        return f"MatchingPad(Ra={self.Ra}, Rb={self.Rb}, loss={self.loss})"

    def _repr_latex_(self) -> str:
        """``R_a``, ``R_b``, the loss ``a_0`` and the chain matrix (Bulgakov (1954), eqs. (9.514)–(9.517))."""
        return (
            f"$R_a = {sp.latex(self.Ra)},\\ R_b = {sp.latex(self.Rb)},\\ a_0 = {sp.latex(self.loss)},\\ "
            f"{self.four_pole._latex(None)}$"
        )


@validated
def matching_l_pad(Rx: Any, Ry: Any) -> MatchingPad:
    """L pad with image impedances ``Rx`` (input) and ``Ry`` (output), ``Rx > Ry`` (eqs. (9.514)–(9.517)).

    ``Ra = sqrt(Rx (Rx - Ry))``, ``Rb = Ry sqrt(Rx/(Rx - Ry))``, loss ``ch a0 = sqrt(Rx/Ry)`` nepers.

    Parameters
    ----------
    Rx : number or SymPy expression
        Image impedance at the input, which must be positive and larger than ``Ry``.
    Ry : number or SymPy expression
        Image impedance at the output, which must be positive and smaller than ``Rx``.

    Examples
    --------
    >>> from symosc.networks import matching_l_pad
    >>> pad = matching_l_pad(1500, 500)                     # T11
    >>> [round(float(v), 5) for v in (pad.Ra, pad.Rb, pad.loss)]
    [1224.74487, 612.37244, 1.14622]

    See Also
    --------
    image_parameters, l_section
    """
    Rx, Ry = element_value(Rx, "Rx"), element_value(Ry, "Ry")
    if not (Rx - Ry).is_positive:
        raise ParameterError("the L pad needs Rx > Ry (drive it from the high-impedance side; reverse otherwise)")
    Ra = sp.sqrt(Rx * (Rx - Ry))
    Rb = Ry * sp.sqrt(Rx / (Rx - Ry))
    return MatchingPad(Ra, Rb, sp.acosh(sp.sqrt(Rx / Ry)), l_section(Ra, Rb))
