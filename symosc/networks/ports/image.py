"""Image (wave) and iterative parameters, terminated four-poles, insertion and working loss.

Bulgakov (1954), §8.34, §8.39, §8.41, §8.47–8.48.  The square roots are *coupled*: with ``q = sqrt(A22/A11)``
and ``W = sqrt(A12/A21)`` one takes ``sqrt(A11 A22) := A11 q`` and ``sqrt(A12 A21) := A21 W`` and flips the sign
of ``W`` when ``Re g_x < 0`` (the book's footnote rule).  Independent principal square roots give wrong
reconstructions.

>>> from symosc.networks import t_section, image_parameters
>>> ip = image_parameters(t_section(1, 2, 1), at=0)
>>> ip.W, ip.q
(mpc(real='2.2360679774997898', imag='0.0'), mpc(real='1.0', imag='0.0'))
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import as_expr
from .fourpoles import FourPole

__all__ = [
    "ImageParameters",
    "IterativeParameters",
    "TerminatedResponse",
    "image_parameters",
    "insertion_loss",
    "iterative_parameters",
    "terminated_response",
    "working_loss",
]


def _chain_at(fp: FourPole, at: Any) -> list:
    if not isinstance(fp, FourPole):
        raise ParameterError(f"four_pole must be a FourPole, got {type(fp).__name__}")
    M = fp.evaluate(at)
    return [[mpmath.mpc(M[0, 0]), mpmath.mpc(M[0, 1])], [mpmath.mpc(M[1, 0]), mpmath.mpc(M[1, 1])]]


def _latex_values(values: dict) -> str:
    """``$name = value, ...$`` with mpmath/SymPy numbers typeset to six significant digits."""
    parts = []
    for name, v in values.items():
        try:
            e = sp.N(sp.sympify(v), 6)
        except (sp.SympifyError, TypeError):
            e = sp.Symbol(str(v))
        parts.append(f"{name} = {sp.latex(e)}")
    return "$" + r",\ ".join(parts) + "$"


@dataclass(frozen=True)
class ImageParameters(SymPyPrintable):
    """Image parameters at one point ``p``: ``Zx = W/q``, ``Zy = W q``, ``e^{gx}``, ``e^{-gy}``, ``g``, ``delta``.

    ``g = (gx + gy)/2`` is the image propagation (attenuation ``Re g`` in nepers, phase ``Im g``) and
    ``delta = (gx - gy)/2`` (zero for a reciprocal network), eqs. (8.286)–(8.299).

    Attributes
    ----------
    W : mpmath.mpc
        Characteristic (image) impedance ``W = sqrt(A12/A21)``, sign coupled so that ``Re gx >= 0``.
    q : mpmath.mpc
        Transformation ratio ``q = sqrt(A22/A11)``.
    Zx : mpmath.mpc
        Input image impedance ``W/q``.
    Zy : mpmath.mpc
        Output image impedance ``W q``.
    gx : mpmath.mpc
        Input propagation constant, ``e^{gx} = A11 q + A21 W`` (``Re gx >= 0``).
    gy : mpmath.mpc
        Output propagation constant ``g - delta``.
    g : mpmath.mpc
        Image propagation ``(gx + gy)/2``: attenuation ``Re g`` in nepers, phase ``Im g`` in radians.
    delta : mpmath.mpc
        Asymmetry ``(gx - gy)/2`` with ``e^{2 delta} = det A`` (zero for a reciprocal network), eq. (8.299).
    """

    W: Any
    q: Any
    Zx: Any
    Zy: Any
    gx: Any
    gy: Any
    g: Any
    delta: Any

    def chain(self) -> Any:
        """Rebuild ``A = e^delta [[ch g / q, W sh g], [sh g / W, q ch g]]`` (8.303)."""
        e = mpmath.exp(self.delta)
        g = self.g
        return mpmath.matrix(
            [
                [e * mpmath.cosh(g) / self.q, e * self.W * mpmath.sinh(g)],
                [e * mpmath.sinh(g) / self.W, e * self.q * mpmath.cosh(g)],
            ]
        )

    def __repr__(self) -> str:
        return f"ImageParameters(W={self.W}, q={self.q}, g={self.g}, delta={self.delta})"

    def _repr_latex_(self) -> str:
        """``W``, ``q``, ``g``, ``delta`` to six digits (Bulgakov (1954), eqs. (8.286)–(8.299))."""
        return _latex_values({"W": self.W, "q": self.q, "g": self.g, r"\delta": self.delta})


@validated
def image_parameters(four_pole: FourPole, at: Any) -> ImageParameters:
    """Image (wave) parameters of a four-pole at ``p = at`` with the coupled choice of square roots.

    Parameters
    ----------
    four_pole : FourPole
        The four-pole, its chain matrix a function of its operator variable ``p``.
    at : complex
        Value of ``p`` at which to evaluate, a finite real or complex number (``1j*omega`` for the steady state at
        angular frequency ``omega``).

    Returns
    -------
    ImageParameters
        mpmath numbers at the working precision; ``Re gx >= 0`` (Bulgakov (1954), §8.34, footnote).

    Raises
    ------
    ModelError
        When ``A11``, ``A21`` or ``A12 A22`` vanish there (no image parameters exist).

    Examples
    --------
    >>> from symosc.networks import lattice_phase_network, image_parameters
    >>> ip = image_parameters(lattice_phase_network(1, 1), at=0.5j)    # E18: all-pass
    >>> abs(ip.g.real) < 1e-15, round(float(ip.g.imag), 12)    # b = 2 arctan(0.5)
    (True, 0.927295218002)

    See Also
    --------
    iterative_parameters, insertion_loss
    """
    (A11, A12), (A21, A22) = _chain_at(four_pole, at)
    if A11 == 0 or A21 == 0 or A12 == 0 or A22 == 0:
        raise ModelError(
            f"image parameters do not exist at p = {at}: an entry of the chain matrix vanishes "
            "(e.g. a single series or shunt element); use iterative parameters or the chain matrix directly"
        )
    q = mpmath.sqrt(A22 / A11)
    W = mpmath.sqrt(A12 / A21)
    egx = A11 * q + A21 * W
    a = mpmath.log(egx).real
    tol = mpmath.mpf(2) ** (-mpmath.mp.prec + 12) * (1 + abs(egx))
    # Re gx > 0 (the book's rule); on a passband (Re gx = 0 up to rounding) take Re W >= 0 instead
    if a < -tol or (abs(a) <= tol and W.real < 0):
        W = -W
        egx = A11 * q + A21 * W
    gx = mpmath.log(egx)
    # e^{2 delta} = det A (8.299): take delta from the principal logarithm, so that a reciprocal network has
    # delta = 0 and the phase of a stop band (b = pi) stays in g, not in delta
    delta = mpmath.log(A11 * A22 - A12 * A21) / 2
    g = gx - delta
    return ImageParameters(W, q, W / q, W * q, gx, g - delta, g, delta)


@dataclass(frozen=True)
class IterativeParameters(SymPyPrintable):
    """Iterative parameters at one point: ``Z1 = Z'``, ``Z2 = Z''``, ``s1 = s'``, ``s2 = s''``, ``s``, ``delta``.

    A chain of sections closed by ``Z'`` at the output shows ``Z'`` at the input (eqs. (8.389)–(8.400)).

    Attributes
    ----------
    Z1 : mpmath.mpc
        Iterative impedance ``Z'`` (seen at the input of a chain closed by ``Z'``).
    Z2 : mpmath.mpc
        Iterative impedance ``Z''`` (the same from the output side).
    s1 : mpmath.mpc
        Propagation ``s'`` from input to output, ``Re s' > 0``.
    s2 : mpmath.mpc
        Propagation ``s''`` in the opposite direction.
    s : mpmath.mpc
        Mean propagation ``(s' + s'')/2``.
    delta : mpmath.mpc
        Half-difference ``(s' - s'')/2``.
    """

    Z1: Any
    Z2: Any
    s1: Any
    s2: Any
    s: Any
    delta: Any

    def chain(self) -> Any:
        """Rebuild the chain matrix from (8.401)."""
        e, s = mpmath.exp(self.delta), self.s
        Z1, Z2 = self.Z1, self.Z2
        rho = (Z1 - Z2) / (Z1 + Z2)
        return mpmath.matrix(
            [
                [e * (mpmath.cosh(s) + rho * mpmath.sinh(s)), e * 2 * Z1 * Z2 / (Z1 + Z2) * mpmath.sinh(s)],
                [e * 2 / (Z1 + Z2) * mpmath.sinh(s), e * (mpmath.cosh(s) - rho * mpmath.sinh(s))],
            ]
        )

    def _repr_latex_(self) -> str:
        """``Z'``, ``Z''``, ``s'``, ``s''``, ``s``, ``delta`` to six digits (Bulgakov (1954), §8.41)."""
        return _latex_values(
            {"Z'": self.Z1, "Z''": self.Z2, "s'": self.s1, "s''": self.s2, "s": self.s, r"\delta": self.delta}
        )


@validated
def iterative_parameters(four_pole: FourPole, at: Any) -> IterativeParameters:
    """Iterative parameters at ``p = at`` (Bulgakov (1954), §8.41), radical chosen so that ``Re s' > 0``.

    ``Z', Z'' = [±(A11 - A22) + r]/(2 A21)``, ``e^{s'} = (A11 + A22 + r)/2``, ``e^{-s''} = (A11 + A22 - r)/2`` with
    ``r = sqrt((A11 - A22)**2 + 4 A12 A21)``.

    Parameters
    ----------
    four_pole : FourPole
        The four-pole, its chain matrix a function of its operator variable ``p``.
    at : complex
        Value of ``p`` at which to evaluate, a finite real or complex number (``1j*omega`` for the steady state at
        angular frequency ``omega``).

    Examples
    --------
    >>> from symosc.networks import l_section, iterative_parameters, FourPole
    >>> it = iterative_parameters(l_section(1, 2, shunt_first=True), at=0)
    >>> it.Z1, it.Z2
    (mpc(real='1.0', imag='0.0'), mpc(real='2.0', imag='0.0'))

    See Also
    --------
    image_parameters
    """
    (A11, A12), (A21, A22) = _chain_at(four_pole, at)
    if A21 == 0:
        raise ModelError(f"iterative impedances do not exist at p = {at}: A21 = 0 (no shunt path)")
    r = mpmath.sqrt((A11 - A22) ** 2 + 4 * A12 * A21)
    if mpmath.log((A11 + A22 + r) / 2).real < 0:
        r = -r
    Z1 = ((A11 - A22) + r) / (2 * A21)
    Z2 = (-(A11 - A22) + r) / (2 * A21)
    s1 = mpmath.log((A11 + A22 + r) / 2)
    s2 = -mpmath.log((A11 + A22 - r) / 2)
    return IterativeParameters(Z1, Z2, s1, s2, (s1 + s2) / 2, (s1 - s2) / 2)


@dataclass(frozen=True)
class TerminatedResponse(SymPyPrintable):
    """Currents and voltages of a four-pole between a generator ``E`` (internal ``Zr``) and a load ``ZH``.

    Attributes
    ----------
    Ex : SymPy expression
        Input voltage ``E - Zr Ix``.
    Ix : SymPy expression
        Input current.
    Ey : SymPy expression
        Output voltage ``ZH Iy``.
    Iy : SymPy expression
        Output (load) current, counted out of the network.

    Examples
    --------
    A series resistor 3 between a source 10 with internal resistance 1 and a load 1: ``I = 10/(1 + 3 + 1) = 2``.

    >>> from symosc.networks import series_element, terminated_response
    >>> response = terminated_response(series_element(3), 10, 1, 1)
    >>> response.Iy, response.Ey
    (2, 2)

    See Also
    --------
    terminated_response, image_parameters
    """

    Ex: Any
    Ix: Any
    Ey: Any
    Iy: Any

    def __repr__(self) -> str:
        return f"TerminatedResponse(Ex={self.Ex}, Ix={self.Ix}, Ey={self.Ey}, Iy={self.Iy})"

    def _repr_latex_(self) -> str:
        """Input and output voltages and currents."""
        return _latex_values({"E_x": self.Ex, "I_x": self.Ix, "E_y": self.Ey, "I_y": self.Iy})


@validated
def terminated_response(four_pole: FourPole, E: Any, Zr: Any, ZH: Any) -> TerminatedResponse:
    """Boundary problem of §8.39: ``Ex = E - Zr Ix``, ``Ey = ZH Iy``, solved exactly in ``p``.

    ``E = A'12 Iy`` with ``A' = [[1, Zr], [0, 1]] A [[1, ZH], [0, 1]]`` (8.369)–(8.375).

    Parameters
    ----------
    four_pole : FourPole
        The four-pole, its chain matrix a function of its operator variable ``p``.
    E : number or SymPy expression
        Electromotive force of the generator (an expression in ``p`` for a Carson image, or a constant).
    Zr : number or SymPy expression
        Internal impedance of the generator, an expression in ``p`` (or a number).
    ZH : number or SymPy expression
        Load impedance closing the output, an expression in ``p`` (or a number).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import series_element, terminated_response
    >>> terminated_response(series_element(3), 10, 1, 1).Iy
    2

    See Also
    --------
    insertion_loss, working_loss
    """
    A = four_pole.chain
    E, Zr, ZH = as_expr(E, "E"), as_expr(Zr, "Zr"), as_expr(ZH, "ZH")
    a12 = sp.cancel(A[0, 0] * ZH + A[0, 1] + Zr * (A[1, 0] * ZH + A[1, 1]))
    if a12 == 0:
        raise ModelError("the terminated network carries no output current for any E (A'12 = 0)")
    Iy = sp.cancel(E / a12)
    Ey = sp.cancel(ZH * Iy)
    Ex = sp.cancel(A[0, 0] * Ey + A[0, 1] * Iy)
    Ix = sp.cancel(A[1, 0] * Ey + A[1, 1] * Iy)
    return TerminatedResponse(Ex, Ix, Ey, Iy)


def _a12_prime(four_pole: FourPole, Zr: Any, ZH: Any) -> sp.Expr:
    A = four_pole.chain
    Zr, ZH = as_expr(Zr, "Zr"), as_expr(ZH, "ZH")
    return A[0, 0] * ZH + A[0, 1] + Zr * (A[1, 0] * ZH + A[1, 1])


@validated
def insertion_loss(four_pole: FourPole, Zr: Any, ZH: Any, at: Any) -> Any:
    """Insertion propagation ``g_ins`` at ``p = at``: ``Iy = E e^{-g_ins}/(Zr + ZH)`` (Bulgakov (1954), §8.47).

    ``Re g_ins`` is the insertion loss in nepers (it may be negative for a passive network that improves the
    match), ``Im g_ins`` the insertion phase.

    Parameters
    ----------
    four_pole : FourPole
        The four-pole, its chain matrix a function of its operator variable ``p``.
    Zr : number or SymPy expression
        Internal impedance of the generator, an expression in ``p`` (or a number); ``Zr + ZH`` must not vanish at
        ``at``.
    ZH : number or SymPy expression
        Load impedance, an expression in ``p`` (or a number).
    at : complex
        Value of ``p`` at which to evaluate, a finite real or complex number (``1j*omega`` for the steady state at
        angular frequency ``omega``).

    Examples
    --------
    >>> from symosc.networks import series_element, insertion_loss
    >>> insertion_loss(series_element(2), 1, 1, at=0)     # ln 2
    mpc(real='0.69314718055994529', imag='0.0')

    See Also
    --------
    working_loss, image_parameters
    """
    Zr, ZH = as_expr(Zr, "Zr"), as_expr(ZH, "ZH")
    val = sp.lambdify(four_pole.p, _a12_prime(four_pole, Zr, ZH) / (Zr + ZH), "mpmath")(mpmath.mpmathify(at))
    return mpmath.log(mpmath.mpc(val))


@validated
def working_loss(four_pole: FourPole, Zr: Any, ZH: Any, at: Any) -> Any:
    """Working (operating) propagation constant between given terminations (Bulgakov (1954), §8.48).

    ``exp(g_work) = A'12 / (2 sqrt(Rr RH))``.

    ``Re g_work = ½ ln(P_max/P) >= 0`` for a passive network; ``Rr``, ``RH`` are the real parts of ``Zr``, ``ZH``
    at ``p = at``.

    Parameters
    ----------
    four_pole : FourPole
        The four-pole, its chain matrix a function of its operator variable ``p``.
    Zr : number or SymPy expression
        Internal impedance of the generator, an expression in ``p`` whose real part at ``at`` must be positive.
    ZH : number or SymPy expression
        Load impedance, an expression in ``p`` whose real part at ``at`` must be positive.
    at : complex
        Value of ``p`` at which to evaluate, a finite real or complex number (``1j*omega`` for the steady state at
        angular frequency ``omega``).

    Examples
    --------
    >>> from symosc.networks import series_element, working_loss
    >>> working_loss(series_element(2), 1, 1, at=0)
    mpc(real='0.69314718055994529', imag='0.0')

    See Also
    --------
    insertion_loss
    """
    p, x = four_pole.p, mpmath.mpmathify(at)
    Zr, ZH = as_expr(Zr, "Zr"), as_expr(ZH, "ZH")
    zr = mpmath.mpc(sp.lambdify(p, Zr, "mpmath")(x))
    zh = mpmath.mpc(sp.lambdify(p, ZH, "mpmath")(x))
    if zr.real <= 0 or zh.real <= 0:
        raise ParameterError("the working loss needs terminations with positive resistance (Re Zr, Re ZH > 0)")
    val = mpmath.mpc(sp.lambdify(p, _a12_prime(four_pole, Zr, ZH), "mpmath")(x))
    return mpmath.log(val / (2 * mpmath.sqrt(zr.real * zh.real)))
