"""Voltages and currents at the junctions of a cascade with equal iterative impedances (Bulgakov (1954), §8.46).

For ``n`` four-poles with the same iterative impedances ``Z'``, ``Z''`` (e.g. identical sections, or
constant-resistance links with one ``W``) between a generator ``E`` with internal impedance ``Zr`` and a load
``ZH``, the voltage and current at junction ``j`` (output of link ``j``, input of link ``j + 1``) are, eq. (8.427),

``E_j = [ZH (Z'+Z'') ch S* + (ZH (Z'-Z'') + 2 Z'Z'') sh S*] E e^{-(Δ-Δ*)} / N``

``I_j = [(Z'+Z'') ch S* + (2 ZH - Z' + Z'') sh S*] E e^{-(Δ-Δ*)} / N``

``N = (Zr + Z')(ZH + Z'')(e^S - r' r'' e^{-S})``,  ``r' = (Zr - Z'')/(Zr + Z')``,  ``r'' = (ZH - Z')/(ZH + Z'')``,

with ``S = Σ s_k``, ``Δ = Σ δ_k`` over all links and ``S* = Σ_{k>j} s_k``, ``Δ* = Σ_{k>j} δ_k`` (8.424)–(8.427).

>>> from symosc.networks import cascade_junctions, l_section
>>> out = cascade_junctions([l_section(1, 2, shunt_first=True)] * 3, E=1, Zr=1, ZH=1, at=0)
>>> [round(float(abs(v)), 12) for v in out.I]
[0.5, 0.25, 0.125, 0.0625]
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from .._util import as_expr
from .fourpoles import FourPole
from .image import _latex_values, iterative_parameters

__all__ = ["CascadeJunctions", "cascade_junctions"]


@dataclass(frozen=True)
class CascadeJunctions(SymPyPrintable):
    """Voltages ``E[j]`` and currents ``I[j]`` at the junctions ``j = 0..n`` of a cascade (``0``: its input).

    Attributes
    ----------
    at : complex
        The value of ``p``.
    E, I : tuple of mpmath.mpc
        Junction voltages and currents from eq. (8.427).
    Z1, Z2 : mpmath.mpc
        The common iterative impedances ``Z'``, ``Z''``.
    s, delta : tuple of mpmath.mpc
        Iterative propagation ``s_k`` and asymmetry ``δ_k`` of each link.

    Examples
    --------
    >>> from symosc.networks import cascade_junctions, series_element, shunt_element
    >>> from symosc.networks import cascade
    >>> half = cascade(series_element(1), shunt_element(2))
    >>> out = cascade_junctions([half, half], E=2, Zr=1, ZH=2, at=0)
    >>> round(float(out.E[-1].real), 12)       # 2 * (2/3) * (1/2) * (1/2): the ladder halves twice
    0.333333333333

    See Also
    --------
    cascade_junctions, iterative_parameters, terminated_response
    """

    at: Any
    E: tuple
    I: tuple
    Z1: Any
    Z2: Any
    s: tuple
    delta: tuple

    def plot(self, *, ax: Any = None) -> Any:
        """``|E_j|`` and ``|I_j|`` against the junction number ``j``.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from ..._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        j = list(range(len(self.E)))
        ax.plot(j, [float(abs(v)) for v in self.E], "o-", label="|E_j|")
        ax.plot(j, [float(abs(v)) for v in self.I], "s--", label="|I_j|")
        ax.set_xlabel("junction j")
        ax.legend()
        return ax

    def __repr__(self) -> str:
        def show(values: tuple) -> str:
            return "[" + ", ".join(mpmath.nstr(v, 6) for v in values) + "]"

        return f"CascadeJunctions(at={self.at}, E={show(self.E)}, I={show(self.I)})"

    def _repr_latex_(self) -> str:
        """Common iterative impedances and the input/output values (Bulgakov (1954), eq. (8.427))."""
        return _latex_values({"Z'": self.Z1, "Z''": self.Z2, "E_0": self.E[0], "I_0": self.I[0]})


def _value(expr: Any, name: str, p: sp.Symbol, at: Any) -> Any:
    e = as_expr(expr, name)
    return mpmath.mpc(sp.lambdify(p, e, "mpmath")(at)) if e.has(p) else mpmath.mpc(sp.N(e, mpmath.mp.dps + 5))


@validated
def cascade_junctions(
    sections: Sequence[FourPole], E: Any, Zr: Any, ZH: Any, at: Any, *, rtol: float = 1e-10
) -> CascadeJunctions:
    """Junction voltages and currents of a cascade with equal iterative impedances, eq. (8.427) (§8.46).

    Parameters
    ----------
    sections : sequence of FourPole
        The links in order from the generator to the load; all with the same iterative impedances ``Z'``, ``Z''``
        at ``p = at``.
    E : number or expression in p
        Generator voltage.
    Zr, ZH : number or expression in p
        Internal impedance of the generator and the load impedance.
    at : complex
        Value of ``p`` (``1j*omega`` in the steady state).
    rtol : float
        Relative tolerance of the check that the iterative impedances agree.

    Returns
    -------
    CascadeJunctions
        ``E[j]``, ``I[j]`` for ``j = 0..n`` (``E[0] = Ex``, ``I[0] = Ix``; ``E[n] = ZH I[n]``).

    Raises
    ------
    ParameterError
        When the sections' iterative impedances differ (name the first that does), or the cascade is empty.

    Examples
    --------
    >>> from symosc.networks import cascade_junctions, correcting_link, link_transfer
    >>> links = [correcting_link(link_transfer("lag", T1=1, T2=4, k=2)).four_pole,
    ...          correcting_link(link_transfer("attenuator", k=3)).four_pole]
    >>> out = cascade_junctions(links, E=2, Zr=1, ZH=1, at=0)     # all links have Z' = Z'' = W = 1
    >>> [round(float(v.real), 12) for v in out.E]
    [1.0, 0.5, 0.166666666667]

    See Also
    --------
    iterative_parameters, terminated_response, chain_power
    """
    if isinstance(sections, FourPole) or not isinstance(sections, Sequence) or len(sections) == 0:
        raise ParameterError("sections must be a non-empty sequence of FourPole links")
    for k, fp in enumerate(sections):
        if not isinstance(fp, FourPole):
            raise ParameterError(f"sections[{k}] must be a FourPole, got {type(fp).__name__}")
    x = mpmath.mpmathify(at)
    its = [iterative_parameters(fp, x) for fp in sections]
    Z1, Z2 = its[0].Z1, its[0].Z2
    for k, it in enumerate(its[1:], start=1):
        scale = abs(Z1) + abs(Z2)
        if abs(it.Z1 - Z1) > rtol * scale or abs(it.Z2 - Z2) > rtol * scale:
            raise ParameterError(
                f"sections[{k}] has iterative impedances Z' = {mpmath.nstr(it.Z1, 8)}, Z'' = {mpmath.nstr(it.Z2, 8)} "
                f"unlike those of sections[0] ({mpmath.nstr(Z1, 8)}, {mpmath.nstr(Z2, 8)}); eq. (8.427) needs equal "
                "iterative impedances (use terminated_response on the cascade instead)"
            )
    p = sections[0].p
    e, zr, zh = _value(E, "E", p, x), _value(Zr, "Zr", p, x), _value(ZH, "ZH", p, x)
    s = [it.s for it in its]
    d = [it.delta for it in its]
    S, Delta = mpmath.fsum(s), mpmath.fsum(d)
    r1 = (zr - Z2) / (zr + Z1)
    r2 = (zh - Z1) / (zh + Z2)
    den = (zr + Z1) * (zh + Z2) * (mpmath.exp(S) - r1 * r2 * mpmath.exp(-S))
    if den == 0:
        raise ParameterError(f"the terminated cascade is at resonance at p = {at} (the denominator of (8.427) is 0)")
    Es, Is = [], []
    n = len(sections)
    for j in range(n + 1):
        Sj, Dj = mpmath.fsum(s[j:]), mpmath.fsum(d[j:])
        ch, sh = mpmath.cosh(Sj), mpmath.sinh(Sj)
        f = e * mpmath.exp(-(Delta - Dj)) / den
        Es.append((zh * (Z1 + Z2) * ch + (zh * (Z1 - Z2) + 2 * Z1 * Z2) * sh) * f)
        Is.append(((Z1 + Z2) * ch + (2 * zh - Z1 + Z2) * sh) * f)
    return CascadeJunctions(at, tuple(Es), tuple(Is), Z1, Z2, tuple(s), tuple(d))
