"""Filters and pads: Bulgakov (1954), §9.28-9.35, examples T10 (Guillemin low-pass) and T11 (L pad).

References: the printed/recomputed T10 values, the closed forms Z_T = R sqrt(1 - x^2), b = 2 arcsin x,
a = 2 arccosh x, the element maps of §9.30-9.32 built as explicit element networks, and the T11 numbers.
"""

from __future__ import annotations

import mpmath
import pytest
import sympy as sp

from symosc.errors import ParameterError
from symosc.networks import (
    Capacitor,
    Inductor,
    bandpass_attenuation_poles,
    cascade,
    constant_k_section,
    image_operating_loss,
    image_parameters,
    lattice_from_transmission,
    m_derived_section,
    matching_l_pad,
    series_element,
    shunt_element,
    working_loss,
)

p = sp.Symbol("p")


@pytest.mark.parametrize(
    ("x", "book"), [(0.1, 1.171360), (0.5, 1.083333), (0.9, 1.377219), (1.2, 7423.73), (2.0, 6.71276e8)]
)
def test_t10_guillemin_lowpass(x, book):
    """T10: four constant-k T sections, R = 1000, w0 = 2 pi 1000, between 1500 and 500 ohm: e^{2 a_op}."""
    L, C = 1 / (2 * sp.pi), sp.Rational(1, 10**6) / (2 * sp.pi)
    R, w0 = sp.sqrt(L / C), 1 / sp.sqrt(L * C)
    sec = constant_k_section("lowpass", R, w0)
    four = cascade(*[sec.four_pole] * 4)
    omega = x * float(w0)
    a_work = working_loss(four, 1500, 500, at=1j * omega).real
    assert abs(mpmath.exp(2 * a_work) / book - 1) < 2e-6
    ip = image_parameters(sec.four_pole, at=1j * omega)
    assert abs(image_operating_loss(ip.W, ip.g, 4, 1500, 500) / book - 1) < 2e-6
    if x < 1:  # pass band: W = R sqrt(1 - x^2), b = 2 arcsin x, no attenuation
        assert abs(ip.W - 1000 * mpmath.sqrt(1 - x**2)) < 1e-9 and abs(ip.g.real) < 1e-12
        assert abs(ip.g.imag - 2 * mpmath.asin(x)) < 1e-12
    else:  # stop band: a = 2 arccosh x, b = pi
        assert abs(ip.g.real - 2 * mpmath.acosh(x)) < 1e-10 and abs(abs(ip.g.imag) - mpmath.pi) < 1e-10


def test_element_maps_high_band_pass_band_stop():
    """§9.30-9.32: the printed element formulas, built as element networks, give the transformed arms."""
    R, w0, w1, w2 = 600, 1000, 800, 1250
    hp = constant_k_section("highpass", R, w0)
    e = hp.elements
    arm = Capacitor(e["C_series"]).impedance(p)
    assert (
        sp.cancel(
            hp.four_pole.chain[0, 1]
            - cascade(
                series_element(arm), shunt_element(Inductor(e["L_shunt"]).impedance(p) / 2), series_element(arm)
            ).chain[0, 1]
        )
        == 0
    )
    bp = constant_k_section("bandpass", R, w0, (w1, w2))
    e = bp.elements
    series_arm = (Inductor(e["L_series"]) + Capacitor(e["C_series"])).impedance(p)
    shunt_arm = (Inductor(e["L_shunt"]) | Capacitor(e["C_shunt"])).impedance(p) / 2
    ref = cascade(series_element(series_arm), shunt_element(shunt_arm), series_element(series_arm))
    assert (bp.four_pole.chain - ref.chain).applyfunc(sp.cancel).is_zero_matrix
    bs = constant_k_section("bandstop", R, w0, (w1, w2))
    e = bs.elements
    series_arm = (Inductor(e["L_series"]) | Capacitor(e["C_series"])).impedance(p)
    shunt_arm = (Inductor(e["L_shunt"]) + Capacitor(e["C_shunt"])).impedance(p) / 2
    ref = cascade(series_element(series_arm), shunt_element(shunt_arm), series_element(series_arm))
    assert (bs.four_pole.chain - ref.chain).applyfunc(sp.cancel).is_zero_matrix
    # band-pass: pass band between w1 and w2 (a = 0), attenuation outside
    assert abs(bp.attenuation_phase(1100)[0]) < 1e-12 and bp.attenuation_phase(500)[0] > 0.5


def test_m_derived_same_image_impedance_and_pole():
    """m-derived T: image impedance equals the constant-k T's; infinite attenuation at w0/sqrt(1 - m^2)."""
    k = constant_k_section("lowpass", 50, 2)
    m = m_derived_section("lowpass", 50, 2, sp.Rational(3, 5))
    for w in (0.3, 1.1, 1.9):
        assert abs(image_parameters(k.four_pole, 1j * w).W - image_parameters(m.four_pole, 1j * w).W) < 1e-10
    shunt = m.four_pole.chain[1, 0]  # 1/Z_shunt -> infinite at the pole
    assert sp.simplify(1 / shunt.subs(p, sp.I * 2 / sp.sqrt(1 - sp.Rational(9, 25)))) == 0


def test_t11_l_pad():
    """T11: Rx = 1500, Ry = 500 gives Ra = 1224.74, Rb = 612.37, a0 = 1.14622 Np; image impedances Rx, Ry."""
    pad = matching_l_pad(1500, 500)
    assert abs(float(pad.Ra) - 1224.74) < 0.01 and abs(float(pad.Rb) - 612.37) < 0.01
    assert abs(float(pad.loss) - 1.14622) < 1e-5
    ip = image_parameters(pad.four_pole, at=0)
    assert abs(ip.Zx - 1500) < 1e-9 and abs(ip.Zy - 500) < 1e-9 and abs(ip.g - float(pad.loss)) < 1e-12
    with pytest.raises(ParameterError, match="Rx > Ry"):
        matching_l_pad(500, 1500)


def test_lattice_from_transmission():
    """§9.33-9.34: the lattice with Za = W(1-X)/(1+X), Zb = W^2/Za has image W and e^{-g} = X."""
    X = (1 - p) * (2 - p) / ((1 + p) * (2 + p))
    lat = lattice_from_transmission(X, 3, p)
    for w in (0.2, 1.0, 4.0):
        ip = image_parameters(lat, at=1j * w)
        assert abs(ip.W - 3) < 1e-12
        assert abs(mpmath.exp(-ip.g) - complex(X.subs(p, 1j * w))) < 1e-12
    with pytest.raises(ParameterError, match="not positive real"):
        lattice_from_transmission(2 * (1 - p) / (1 + p), 1, p)  # |X| = 2 > 1: needs an amplifier


def _arm(*parts):
    """Impedance of elements in series; a part is ("L", v), ("C", v) or ("tank", L, C) (parallel LC)."""
    z = 0
    for part in parts:
        if part[0] == "L":
            z += part[1] * p
        elif part[0] == "C":
            z += 1 / (part[1] * p)
        else:
            z += 1 / (1 / (part[1] * p) + part[2] * p)
    return z


def _arms_from_elements(kind, e):
    """Series half-arm and shunt arm built by hand from the element values (the topology in the docstring)."""
    if kind == "lowpass":
        return _arm(("L", e["L_series"])), _arm(("C", e["C_shunt"]), ("L", e["L_shunt"]))
    if kind == "highpass":
        return _arm(("C", e["C_series"])), _arm(("L", e["L_shunt"]), ("C", e["C_shunt"]))
    tank = ("tank", e["L_shunt_tank"], e["C_shunt_tank"])
    if kind == "bandpass":
        return _arm(("L", e["L_series"]), ("C", e["C_series"])), _arm(tank, ("L", e["L_shunt"]), ("C", e["C_shunt"]))
    return _arm(("tank", e["L_series"], e["C_series"])), _arm(("L", e["L_shunt"]), ("C", e["C_shunt"]), tank)


@pytest.mark.parametrize("kind", ["lowpass", "highpass", "bandpass", "bandstop"])
def test_m_derived_elements_and_prototype_mapping(kind):
    """§9.29-9.32: the element values rebuild the designed chain matrix (cascade of element four-poles); the
    section is the low-pass m-derived prototype under p/w0 -> F(p); image impedance equals the constant-k one."""
    R, w0, m, band = 600, 3, sp.Rational(2, 5), (2, 5)
    sec = m_derived_section(kind, R, w0, m, band)
    za, zb = _arms_from_elements(kind, sec.elements)
    built = cascade(series_element(za, p=p), shunt_element(zb, p=p), series_element(za, p=p)).chain
    assert (built - sec.four_pole.chain).applyfunc(sp.cancel) == sp.zeros(2, 2)
    # prototype mapping, evaluated directly on the hand-written low-pass T
    F = {"lowpass": p / w0, "highpass": w0 / p}.get(kind) or (
        (p**2 + 10) / (3 * p) if kind == "bandpass" else 3 * p / (p**2 + 10)
    )
    s = sp.Symbol("s")
    za0, zb0 = m * R * s, R / (2 * m * s) + (1 - m**2) / (2 * m) * R * s
    proto = sp.Matrix([[1 + za0 / zb0, 2 * za0 + za0**2 / zb0], [1 / zb0, 1 + za0 / zb0]])
    assert (proto.subs(s, F) - sec.four_pole.chain).applyfunc(sp.cancel) == sp.zeros(2, 2)
    k = constant_k_section(kind, R, w0, band)
    for w in (0.7, 2.9, 4.1, 8.0):
        Wm = image_parameters(sec.four_pole, 1j * w).W
        Wk = image_parameters(k.four_pole, 1j * w).W
        assert abs(Wm - Wk) < 1e-9 * abs(Wk)
        # image attenuation of the mapped prototype: closed form a + ib = 2 asinh sqrt(za0/zb0 ... ) at s = F(iw)
        sv = complex(F.subs(p, 1j * w)) if F.has(p) else F
        z_a, z_b = complex(za0.subs(s, sv)), complex(zb0.subs(s, sv))
        g = 2 * mpmath.asinh(mpmath.sqrt(z_a / (2 * z_b)))
        a = sec.attenuation_phase(w)[0]
        assert abs(a - abs(float(mpmath.re(g)))) < 1e-8


def test_bandpass_attenuation_poles_are_transmission_zeros():
    """Eq. (9.477): the closed-form poles are the imaginary-axis zeros of 1/A of the m-derived band-pass T."""
    m, band = sp.Rational(3, 5), (2, 7)
    sec = m_derived_section("bandpass", 75, 1, m, band)
    num = sp.numer(sp.cancel(1 / sec.four_pole.chain[0, 0]))
    roots = [complex(r) for r in sp.Poly(num, p).nroots(n=30)]
    zeros = sorted(r.imag for r in roots if abs(r.real) < 1e-20 and r.imag > 0)
    lo, hi = bandpass_attenuation_poles(m, band)
    assert len(zeros) == 2
    assert abs(zeros[0] - float(lo)) < 1e-12 and abs(zeros[1] - float(hi)) < 1e-12
    assert float(lo) < 2 < 7 < float(hi)
    with pytest.raises(ParameterError, match="0 < m < 1"):
        bandpass_attenuation_poles(1, band)
    with pytest.raises(ParameterError, match="omega1 < omega2"):
        bandpass_attenuation_poles(m, (7, 2))
