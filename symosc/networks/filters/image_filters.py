"""Image-parameter filters: constant-k and m-derived sections, reactance transformations, operating loss.

Bulgakov (1954), §9.28–9.33.  The low-pass prototype half-section has series ``L`` and shunt ``C`` with
``R = sqrt(L/C)`` and ``ω0 = 1/sqrt(LC)``; the symmetric T (series ``L``, shunt ``2C``, series ``L``) has image
impedance ``R sqrt(1 - x²)``, ``x = ω/ω0``, phase ``b = 2 arcsin x`` in the pass band and attenuation
``a = 2 arccosh x`` in the stop band.  High-, band-pass and band-stop sections follow by the reactance
transformations (9.461), (9.468) and their inverse.

>>> from symosc.networks import constant_k_section
>>> sec = constant_k_section("lowpass", R=1000, omega0=1000)
>>> sec.elements
{'L': 1, 'C': 1/1000000}
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mpmath
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_int, check_positive, validated
from ...errors import ParameterError
from .._util import P, as_expr, element_value
from ..ports.fourpoles import FourPole
from ..ports.sections import t_section

__all__ = [
    "FilterSection",
    "bandpass_attenuation_poles",
    "constant_k_section",
    "frequency_map",
    "image_operating_loss",
    "m_derived_section",
]

_KINDS = ("lowpass", "highpass", "bandpass", "bandstop")


@dataclass(frozen=True)
class FilterSection(SymPyPrintable):
    """A filter section: its four-pole, its element values (per half-section) and its design data.

    Attributes
    ----------
    kind : {"lowpass", "highpass", "bandpass", "bandstop"}
        The kind of filter.
    four_pole : FourPole
        The symmetric T section (half-section series arms on both sides, shunt arm doubled).
    elements : dict
        Element values of one half-section, keyed by name (``"L"``, ``"C"``, ``"L_series"``, ``"C_shunt"``, ...).
    R : SymPy expression
        Nominal impedance ``sqrt(L/C)`` of the low-pass prototype.
    band : tuple
        The band edges ``(omega1, omega2)`` of a band-pass or band-stop section, ``(omega0,)`` otherwise.
    """

    kind: str
    four_pole: FourPole
    elements: dict
    R: Any
    band: tuple

    def attenuation_phase(self, omega: Any) -> tuple[float, float]:
        """Image attenuation ``a`` (nepers) and phase ``b`` (rad) at angular frequency ``omega``.

        Parameters
        ----------
        omega : float
            Angular frequency in rad/s, a finite real number (avoid the cut-off frequencies, where the image parameters
            do not exist).
        """
        from ..ports.image import image_parameters

        ip = image_parameters(self.four_pole, at=1j * mpmath.mpf(omega))
        return float(ip.g.real), float(ip.g.imag)

    def plot(self, omega: Any = None, *, ax: Any = None) -> Any:
        """Plot image attenuation and phase against ``omega``; returns the Axes.

        Parameters
        ----------
        omega : array_like, optional
            Angular frequencies in rad/s, finite real numbers; 600 points up to three times the highest band edge when
            omitted.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from ..._plotting import pyplot

        plt = pyplot()
        import numpy as np

        if ax is None:
            _, ax = plt.subplots()
        hi = float(max(self.band)) * 3
        omega = np.linspace(hi * 1e-3, hi, 600) if omega is None else np.asarray(omega, dtype=float)
        ab = np.array([self.attenuation_phase(w) for w in omega])
        ax.plot(omega, ab[:, 0], label="attenuation a [Np]")
        ax.plot(omega, np.abs(ab[:, 1]), "--", label="phase |b| [rad]")
        ax.set_xlabel("ω [rad/s]")
        ax.legend()
        return ax

    def __repr__(self) -> str:
        return f"FilterSection({self.kind}, R={self.R}, band={self.band}, elements={self.elements})"

    def _repr_latex_(self) -> str:
        """The kind and band as text, then the chain matrix of the section."""
        from ..._printing import latex_value

        band = ", ".join(latex_value(b) for b in self.band)
        return (
            rf"$\text{{{self.kind}}},\ R = {latex_value(self.R)},\ \text{{band}}\ \left({band}\right):\ "
            f"{self.four_pole._latex(None)}$"
        )


@validated
def frequency_map(kind: str, omega0: Any, band: tuple | None = None, p: sp.Symbol = P) -> sp.Expr:
    """The reactance transformation ``p/ω0 -> F(p)`` from the low-pass prototype (eqs. (9.461), (9.468)).

    Parameters
    ----------
    kind : {"lowpass", "highpass", "bandpass", "bandstop"}
        Kind of filter, one of "lowpass", "highpass", "bandpass", "bandstop" (the last two need ``band``).
    omega0 : number or SymPy expression
        Normalising frequency of the low-pass prototype ``p/ω0``, which must be positive.
    band : (omega1, omega2), optional
        Band edges ``0 < omega1 < omega2``, required for band-pass and band-stop maps and ignored otherwise.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol (Carson/Laplace ``p``; put ``p = iω`` for the steady state); the
        standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import frequency_map
    >>> frequency_map("bandpass", 1, (1, 4))
    (p**2 + 4)/(3*p)

    See Also
    --------
    constant_k_section
    """
    w0 = element_value(omega0, "omega0")
    if kind == "lowpass":
        return p / w0
    if kind == "highpass":
        return w0 / p
    if band is None or len(band) != 2:
        raise ParameterError(f"a {kind} section needs band=(omega1, omega2)")
    w1, w2 = element_value(band[0], "omega1"), element_value(band[1], "omega2")
    if not (w2 - w1).is_positive:
        raise ParameterError("band must satisfy omega1 < omega2")
    if kind == "bandpass":
        return (p**2 + w1 * w2) / ((w2 - w1) * p)
    if kind == "bandstop":
        return (w2 - w1) * p / (p**2 + w1 * w2)
    raise ParameterError(f"kind must be one of {_KINDS}, got {kind!r}")


def _elements(kind: str, L: sp.Expr, C: sp.Expr, w0: sp.Expr, band: tuple | None) -> dict:
    """Element values per half-section after the transformation (§9.30–9.32)."""
    if kind == "lowpass":
        return {"L": L, "C": C}
    if kind == "highpass":  # L <-> C: series C' = 1/(L w0²), shunt L' = 1/(C w0²)
        return {"C_series": 1 / (L * w0**2), "L_shunt": 1 / (C * w0**2)}
    w1, w2 = (sp.sympify(v) for v in band)
    bw = w2 - w1
    if kind == "bandpass":
        return {
            "L_series": L * w0 / bw,
            "C_series": bw / (L * w0 * w1 * w2),
            "L_shunt": bw / (C * w0 * w1 * w2),
            "C_shunt": C * w0 / bw,
        }
    return {  # band-stop: series tank, shunt series-LC
        "L_series": L * w0 * bw / (w1 * w2),
        "C_series": 1 / (L * w0 * bw),
        "L_shunt": 1 / (C * w0 * bw),
        "C_shunt": C * w0 * bw / (w1 * w2),
    }


@validated
def constant_k_section(kind: str, R: Any, omega0: Any, band: tuple | None = None, p: sp.Symbol = P) -> FilterSection:
    """Constant-k symmetric T section (Bulgakov (1954), §9.29–9.32).

    Parameters
    ----------
    kind : {"lowpass", "highpass", "bandpass", "bandstop"}
        Kind of filter, one of "lowpass", "highpass", "bandpass", "bandstop" (the last two need ``band``).
    R : number
        Nominal impedance ``sqrt(L/C)``, which must be positive.
    omega0 : number
        Cut-off of the low-pass prototype (``1/sqrt(LC)``), which must be positive; for band filters the normalising
        frequency of the map.
    band : (omega1, omega2), optional
        Band edges ``0 < omega1 < omega2`` for band-pass and band-stop sections.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol (Carson/Laplace ``p``; put ``p = iω`` for the steady state); the
        standard symbol ``p`` when omitted.

    Returns
    -------
    FilterSection
        ``four_pole`` is the T section (half-section series arms on both sides, shunt arm doubled).

    Examples
    --------
    >>> from symosc.networks import constant_k_section
    >>> sec = constant_k_section("lowpass", 1000, 1000)
    >>> a, b = sec.attenuation_phase(500)
    >>> abs(a) < 1e-12, round(b, 12)                       # b = 2 arcsin(1/2) = pi/3
    (True, 1.047197551197)

    See Also
    --------
    m_derived_section, image_operating_loss
    """
    R, w0 = element_value(R, "R"), element_value(omega0, "omega0")
    L, C = R / w0, 1 / (R * w0)
    s = frequency_map(kind, w0, band, p)  # p/w0 of the prototype
    za = R * s  # series arm L p = R (p/w0)
    zb = R / (2 * s)  # shunt 2C: 1/(2 C p) = R/(2 p/w0)
    fp = t_section(za, zb, za, p=p)
    fp = FourPole(fp.chain, p, fp.netlist, name=f"constant-k {kind}")
    return FilterSection(kind, fp, _elements(kind, L, C, w0, band), R, tuple(band) if band else (w0,))


@validated
def m_derived_section(
    kind: str, R: Any, omega0: Any, m: Any, band: tuple | None = None, p: sp.Symbol = P
) -> FilterSection:
    """m-derived T section: series ``m Z1/2``, shunt ``Z2/m + (1 - m²) Z1/(4m)`` (§9.29, standard forms).

    Its image impedance equals the constant-k T's; the low-pass prototype has infinite attenuation at
    ``ω∞ = ω0/sqrt(1 - m²)`` (``m = sqrt(1 - ω0²/ω∞²)``).  High-pass, band-pass and band-stop sections are the
    low-pass one under ``p/ω0 -> F(p)`` (:func:`frequency_map`, Bulgakov (1954), §9.30–9.32).

    ``elements`` holds the element values of one half-section (series arm ``m Z1/2``, shunt arm of the T):

    * low-pass: series ``L_series``; shunt ``C_shunt`` in series with ``L_shunt``;
    * high-pass: series ``C_series``; shunt ``L_shunt`` in series with ``C_shunt``;
    * band-pass: series ``L_series`` + ``C_series`` in series; shunt: the tank ``L_shunt_tank`` ‖
      ``C_shunt_tank`` in series with ``L_shunt`` + ``C_shunt``;
    * band-stop: series tank ``L_series`` ‖ ``C_series``; shunt: ``L_shunt`` + ``C_shunt`` in series with the
      tank ``L_shunt_tank`` ‖ ``C_shunt_tank``.

    Parameters
    ----------
    kind : {"lowpass", "highpass", "bandpass", "bandstop"}
        Kind of filter, one of "lowpass", "highpass", "bandpass", "bandstop" (the last two need ``band``).
    R : number or SymPy expression
        Nominal impedance ``sqrt(L/C)`` of the constant-k prototype, which must be positive.
    omega0 : number or SymPy expression
        Cut-off of the low-pass prototype, which must be positive; for band filters the normalising frequency of the
        map.
    m : number or SymPy expression
        The m of the section, which must satisfy ``0 < m <= 1`` (``m = 1`` gives the constant-k section).
    band : (omega1, omega2), optional
        Band edges ``0 < omega1 < omega2``, required for band-pass and band-stop sections.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol (Carson/Laplace ``p``; put ``p = iω`` for the steady state); the
        standard symbol ``p`` when omitted.

    Examples
    --------
    >>> from symosc.networks import m_derived_section
    >>> sec = m_derived_section("lowpass", 1, 1, 0.6)
    >>> sec.attenuation_phase(1.24)[0] > 4                  # near the pole of attenuation 1/sqrt(1 - 0.36)
    True
    >>> m_derived_section("highpass", 1, 1, 0.5).elements["C_series"]
    2.00000000000000

    See Also
    --------
    constant_k_section, frequency_map, bandpass_attenuation_poles
    """
    R, w0 = element_value(R, "R"), element_value(omega0, "omega0")
    m = as_expr(m, "m")
    if not (m.is_positive and (1 - m).is_nonnegative):
        raise ParameterError(f"m must satisfy 0 < m <= 1, got {m}")
    s = frequency_map(kind, w0, band, p)
    z1 = 2 * R * s
    z2 = R / (2 * s)
    za = m * z1 / 2
    zb = z2 / m + (1 - m**2) / (4 * m) * z1
    fp = t_section(za, zb, za, p=p)
    elements = _m_derived_elements(kind, R, w0, m, band)
    return FilterSection(
        kind, FourPole(fp.chain, p, fp.netlist, name=f"m-derived {kind}"), elements, R, tuple(band) if band else (w0,)
    )


def _m_derived_elements(kind: str, R: sp.Expr, w0: sp.Expr, m: sp.Expr, band: tuple | None) -> dict:
    """Element values of the m-derived half-section: each reactance of the low-pass one mapped by F(p)."""
    k = (1 - m**2) / (2 * m)  # shunt-arm inductance factor of the low-pass prototype
    if kind == "lowpass":
        return {"L_series": m * R / w0, "C_shunt": 2 * m / (R * w0), "L_shunt": k * R / w0}
    if kind == "highpass":  # s = w0/p: every L -> C and C -> L
        return {"C_series": 1 / (m * R * w0), "L_shunt": R / (2 * m * w0), "C_shunt": 1 / (k * R * w0)}
    w1, w2 = (sp.sympify(v) for v in band)
    bw, w12 = w2 - w1, w1 * w2
    if kind == "bandpass":  # s = p/bw + w1 w2/(bw p): L -> series LC, C -> parallel LC
        return {
            "L_series": m * R / bw,
            "C_series": bw / (m * R * w12),
            "L_shunt_tank": R * bw / (2 * m * w12),
            "C_shunt_tank": 2 * m / (R * bw),
            "L_shunt": k * R / bw,
            "C_shunt": bw / (k * R * w12),
        }
    # band-stop: s = bw p/(p² + w1 w2): L -> parallel LC, C -> series LC
    return {
        "L_series": m * R * bw / w12,
        "C_series": 1 / (m * R * bw),
        "L_shunt": R / (2 * m * bw),
        "C_shunt": 2 * m * bw / (R * w12),
        "L_shunt_tank": k * R * bw / w12,
        "C_shunt_tank": 1 / (k * R * bw),
    }


@validated
def bandpass_attenuation_poles(m: Any, band: tuple) -> tuple[sp.Expr, sp.Expr]:
    """Frequencies of infinite attenuation of the m-derived band-pass section (Bulgakov (1954), eq. (9.477)).

    The low-pass prototype's pole ``x∞ = 1/sqrt(1 - m²)`` maps through ``ω² - ω1 ω2 = ± x∞ (ω2 - ω1) ω`` to

    ``ω∞± = sqrt(ω1 ω2 + x∞² (ω2 - ω1)²/4) ± x∞ (ω2 - ω1)/2``,

    one below and one above the pass band, with ``ω∞- ω∞+ = ω1 ω2``.

    Parameters
    ----------
    m : number or SymPy expression
        The m of the section, ``0 < m < 1``.
    band : (omega1, omega2)
        Pass-band edges.

    Returns
    -------
    (omega_low, omega_high) : tuple of SymPy expressions

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import bandpass_attenuation_poles
    >>> lo, hi = bandpass_attenuation_poles(sp.Rational(3, 5), (1, 4))
    >>> lo, hi, sp.simplify(lo * hi)
    (-15/8 + sqrt(481)/8, 15/8 + sqrt(481)/8, 4)

    See Also
    --------
    m_derived_section, frequency_map
    """
    m = as_expr(m, "m")
    if not (m.is_positive and (1 - m).is_positive):
        raise ParameterError(f"m must satisfy 0 < m < 1 for finite attenuation poles, got {m}")
    if band is None or len(band) != 2:
        raise ParameterError("band must be (omega1, omega2)")
    w1, w2 = element_value(band[0], "omega1"), element_value(band[1], "omega2")
    if not (w2 - w1).is_positive:
        raise ParameterError("band must satisfy omega1 < omega2")
    half = (w2 - w1) / (2 * sp.sqrt(1 - m**2))
    root = sp.sqrt(w1 * w2 + half**2)
    return sp.simplify(root - half), sp.simplify(root + half)


def _finite_complex(name: str, value: Any) -> mpmath.mpc:
    """``value`` (a number, an mpmath or a numeric SymPy number) as a finite mpmath number."""
    try:
        out = mpmath.mpmathify(complex(value) if isinstance(value, sp.Basic) else value)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a finite number, got {value!r}") from exc
    if not mpmath.isfinite(out):
        raise ParameterError(f"{name} must be a finite number, got {value!r}")
    return out


@validated
def image_operating_loss(W: Any, g: Any, n: int, Rg: Any, Rl: Any) -> Any:
    """``e^{2 a_op}`` of ``n`` identical symmetric sections (image ``W``, ``g``) between resistances (§9.28).

    ``e^{2a_op} = (Rg + Rl)²/(4 Rg Rl) · |ch(n g) + (W² + Rg Rl)/(W (Rg + Rl)) sh(n g)|²`` (the general form that
    replaces the damaged printed closed form of Guillemin's example).

    Parameters
    ----------
    W : complex
        Image impedance of one section at the frequency considered (a finite nonzero real or complex number).
    g : complex
        Image propagation of one section there (attenuation + i·phase, nepers and radians).
    n : int
        Number of identical sections in the chain, a positive integer.
    Rg : float
        Resistance of the generator, which must be positive.
    Rl : float
        Resistance of the load, which must be positive.

    Examples
    --------
    >>> import mpmath
    >>> from symosc.networks import image_operating_loss
    >>> x = 0.5
    >>> W, g = 1000 * mpmath.sqrt(1 - x**2), 2j * mpmath.asin(x)
    >>> round(float(image_operating_loss(W, g, 4, 1500, 500)), 6)          # T10
    1.083333

    See Also
    --------
    working_loss
    """
    W, g = (_finite_complex(name, v) for name, v in (("W", W), ("g", g)))
    Rg, Rl = (check_positive(name, v) for name, v in (("Rg", Rg), ("Rl", Rl)))
    n = check_int("n (number of sections)", n, minimum=1)
    if W == 0:
        raise ParameterError("W (the image impedance) must be nonzero")
    term = mpmath.cosh(n * g) + (W**2 + Rg * Rl) / (W * (Rg + Rl)) * mpmath.sinh(n * g)
    return (Rg + Rl) ** 2 / (4 * Rg * Rl) * abs(term) ** 2
