"""Four-poles: conversions, sections, connections, image/iterative parameters (Bulgakov (1954), §8.31–8.49).

References are independent of the code under test: scikit-rf's conversions (IEEE convention), modified nodal
analysis of the terminal-level netlist, the closed forms printed in the book, direct loop equations solved by
SymPy, and repeated matrix multiplication in 50-digit mpmath.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.errors import ModelError, ParameterError
from symosc.networks import (
    Impedance,
    Resistor,
    brune_test,
    cascade,
    chain_power,
    convert_parameters,
    equivalent_two_pole,
    ideal_transformer,
    image_parameters,
    insertion_loss,
    iterative_parameters,
    l_section,
    lattice,
    lattice_phase_network,
    parallel,
    pi_section,
    series,
    series_element,
    shunt_element,
    t_section,
    terminated_response,
    transformer,
    twin_t_notch,
    working_loss,
)
from symosc.networks.ports._nodal import chain_from_netlist

p = sp.Symbol("p")
ZA, ZB, ZC, ZD = sp.symbols("Z_A Z_B Z_C Z_D")
Z1, Z2 = sp.symbols("Z1 Z2")


def _zero(M) -> bool:
    if not isinstance(M, (sp.MatrixBase, list)):
        return sp.cancel(sp.together(M)) == 0
    return sp.Matrix(M).applyfunc(lambda e: sp.cancel(sp.together(e))).is_zero_matrix


@pytest.mark.parametrize(
    ("a", "b", "book"),
    [
        (1, 2, None),
        (2, sp.Rational(1, 2), (3.4069, 0.53465, 4.8431, 7.7154)),
        (sp.Rational(1, 3), 5, (33.108, 27.325, 0.33672, 6.1198)),
    ],
)
def test_e15_two_pole_equivalence(a, b, book):
    """Bulgakov (1954), §8.31, eqs. (8.248)-(8.252): (Z1 || Z2) + aZ1 + bZ2 = (cZ1 + dZ2) || (eZ1 + fZ2)."""
    c, d, e, f = equivalent_two_pole(a, b)
    net_a = (Impedance(Z1) | Impedance(Z2)) + Impedance(a * Z1) + Impedance(b * Z2)
    net_b = (Impedance(c * Z1) + Impedance(d * Z2)) | (Impedance(e * Z1) + Impedance(f * Z2))
    assert sp.simplify(net_a.impedance() - net_b.impedance()) == 0
    if book is not None:  # the book lists (c, d, e, f) up to swapping the two parallel branches
        got = sorted([(float(c), float(d)), (float(e), float(f))])
        want = sorted([book[:2], book[2:]])
        assert np.allclose(got, want, rtol=2e-4)
    if 1 + a - b == 0:
        return  # d = f: both sign choices coincide
    # the uncoupled sign choice fails (the book's remark)
    B = sp.sqrt((1 + a + b) ** 2 - 4 * a * b)
    d_bad, f_bad = B / 2 * (B - (1 + a - b)), B / 2 * (B + (1 + a - b))
    net_bad = (Impedance(c * Z1) + Impedance(d_bad * Z2)) | (Impedance(e * Z1) + Impedance(f_bad * Z2))
    assert sp.simplify(net_a.impedance() - net_bad.impedance()) != 0


finite = st.floats(min_value=-5, max_value=5, allow_nan=False).filter(lambda x: abs(x) > 0.05)


@settings(max_examples=15, deadline=None)
@given(st.lists(finite, min_size=8, max_size=8))
def test_conversions_match_scikit_rf(v):
    """IEEE-convention conversions agree with scikit-rf's a2z, z2y, ... on random complex ABCD matrices."""
    import skrf

    A = np.array([[v[0] + 1j * v[1], v[2] + 1j * v[3]], [v[4] + 1j * v[5], v[6] + 1j * v[7]]])
    if min(abs(A[1, 0]), abs(A[0, 1]), abs(A[0, 0]), abs(A[1, 1]), abs(np.linalg.det(A))) < 0.05:
        return
    z_ref = skrf.network.a2z(A[None])[0]
    y_ref = skrf.network.z2y(z_ref[None])[0]
    h_ref = skrf.network.z2h(z_ref[None])[0]
    z = np.array(convert_parameters(sp.Matrix(A), "A", "Z", "ieee").evalf(), dtype=complex)
    y = np.array(convert_parameters(sp.Matrix(A), "A", "Y", "ieee").evalf(), dtype=complex)
    h = np.array(convert_parameters(sp.Matrix(A), "A", "H", "ieee").evalf(), dtype=complex)
    g = np.array(convert_parameters(sp.Matrix(A), "A", "G", "ieee").evalf(), dtype=complex)
    assert np.allclose(z, z_ref, rtol=1e-9, atol=1e-12)
    assert np.allclose(y, y_ref, rtol=1e-9, atol=1e-12)
    assert np.allclose(h, h_ref, rtol=1e-9, atol=1e-12)
    assert np.allclose(g, np.linalg.inv(h_ref), rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("kind", ["Z", "Y", "H", "G"])
@pytest.mark.parametrize("convention", ["book", "ieee"])
def test_conversion_round_trip_symbolic(kind, convention):
    A = sp.Matrix(2, 2, sp.symbols("a b c d"))
    M = convert_parameters(A, "A", kind, convention)
    assert _zero(convert_parameters(M, kind, "A", convention) - A)
    for other in "ZYHG":
        assert _zero(convert_parameters(convert_parameters(M, kind, other, convention), other, kind, convention) - M)


def test_book_sign_convention_t_section():
    """Eq. (8.408): Z of the T section in the book's convention, and the book's formulas A from Z, A from Y."""
    T = t_section(ZA, ZB, ZC)
    assert _zero(T.Z - sp.Matrix([[ZA + ZB, -ZB], [ZB, -(ZB + ZC)]]))
    Z = T.Z
    A_book = sp.Matrix([[Z[0, 0] / Z[1, 0], -Z.det() / Z[1, 0]], [1 / Z[1, 0], -Z[1, 1] / Z[1, 0]]])
    Y = T.Y
    A_from_y = sp.Matrix([[-Y[1, 1] / Y[1, 0], 1 / Y[1, 0]], [-Y.det() / Y[1, 0], Y[0, 0] / Y[1, 0]]])
    assert _zero(A_book - T.A) and _zero(A_from_y - T.A)
    assert T.is_reciprocal() and not T.is_symmetric() and t_section(ZA, ZB, ZA).is_symmetric()


SECTIONS = [
    t_section(ZA, ZB, ZC),
    pi_section(ZA, ZB, ZC),
    l_section(ZA, ZB),
    l_section(ZA, ZB, shunt_first=True),
    lattice(ZA, ZB, ZC, ZD),
    lattice(ZA, ZB),
]


@pytest.mark.parametrize("section", SECTIONS, ids=lambda s: s.name)
def test_sections_against_nodal_analysis(section):
    """The closed-form chain matrices equal modified nodal analysis of the section's netlist; all reciprocal."""
    values = {ZA: sp.Rational(2, 3), ZB: 5, ZC: sp.Rational(7, 2), ZD: 11, p: sp.Rational(3, 7)}
    assert _zero(chain_from_netlist(section.netlist, values) - section.chain.xreplace(values))
    assert section.is_reciprocal()


def test_pi_and_lattice_book_forms():
    """Eqs. (8.416) and (8.356)-(8.357)."""
    Pi = pi_section(ZA, ZB, ZC).chain
    assert _zero(Pi - sp.Matrix([[(ZB + ZC) / ZC, ZB], [(ZA + ZB + ZC) / (ZA * ZC), (ZA + ZB) / ZA]]))
    Zl = lattice(ZA, ZB, ZC, ZD).Z
    S = ZA + ZB + ZC + ZD
    assert _zero(
        Zl - sp.Matrix([[(ZA + ZD) * (ZB + ZC), ZA * ZB - ZC * ZD], [ZC * ZD - ZA * ZB, -(ZA + ZC) * (ZB + ZD)]]) / S
    )


def test_bridged_t_book_form():
    """Eq. (8.420): Y11 of the bridged T."""
    from symosc.networks import bridged_t_section

    Y = bridged_t_section(ZA, ZB, ZC, ZD).Y
    s2 = ZA * ZB + ZB * ZC + ZC * ZA
    assert _zero(Y[0, 0] - (ZA * ZB + ZA * ZC + ZB * ZC + ZB * ZD + ZC * ZD) / (ZD * s2))
    assert _zero(Y[1, 1] + (ZA * ZB + ZA * ZC + ZA * ZD + ZB * ZC + ZB * ZD) / (ZD * s2))
    net = bridged_t_section(ZA, ZB, ZC, ZD)
    values = {ZA: sp.Rational(2, 3), ZB: 5, ZC: sp.Rational(7, 2), ZD: 11}
    assert _zero(chain_from_netlist(net.netlist, values) - net.chain.xreplace(values))


def test_e16_twin_t_notch():
    """Example E16 (Fig. 110): Y11 = -Y22 and Y12 = -Y21 in closed form, null at omega = 1/(s R C)."""
    R, C, s = sp.symbols("R C s", positive=True)
    Y = twin_t_notch(R, C, s).Y
    den = 2 * R * (R * C * p + 1)
    assert sp.cancel(Y[0, 0] - (s**2 * R**2 * C**2 * p**2 + 2 * (1 + s**2) * R * C * p + 1) / den) == 0
    assert sp.cancel(Y[1, 1] + Y[0, 0]) == 0
    assert sp.cancel(Y[0, 1] + (s**2 * R**2 * C**2 * p**2 + 1) / den) == 0
    # transmission null: open-circuit voltage ratio Ey/Ex = 1/A11 vanishes at p = i/(sRC)
    A = twin_t_notch(2, 3, 5).chain
    assert sp.simplify(1 / A[0, 0].subs(p, sp.I / (5 * 2 * 3))) == 0


def test_e18_lattice_phase_network():
    """Eqs. (8.365)-(8.368): W = sqrt(L/C), no attenuation, b = 2 arctan(sqrt(LC) omega)."""
    L, C = sp.Rational(3, 2), sp.Rational(2, 7)
    net = lattice_phase_network(L, C)
    for omega in (0.1, 0.7, 1.9, 8.0):
        ip = image_parameters(net, at=1j * omega)
        assert abs(ip.g.real) < 1e-14
        assert abs(ip.g.imag - 2 * mpmath.atan(mpmath.sqrt(L * C) * omega)) < 1e-14
        assert abs(ip.W - mpmath.sqrt(L / C)) < 1e-14


@pytest.mark.parametrize(
    "section",
    [t_section(1 + p, 2 / p, 3 * p), pi_section(2 * p, 1 + 1 / p, 3), lattice(p, 1 / p), l_section(p, 1 / p + 2)],
    ids=["T", "Pi", "lattice", "L"],
)
def test_image_parameters_reconstruct_chain(section):
    """Coupled radicals: (8.303) rebuilds A at random points; Re gx >= 0; delta = 0 for reciprocal networks."""
    rng = np.random.default_rng(3)
    for _ in range(6):
        z = complex(rng.uniform(0.01, 2), rng.uniform(-3, 3))
        ip = image_parameters(section, at=z)
        A = section.evaluate(z)
        assert mpmath.mnorm(ip.chain() - A, 1) < 1e-12 * mpmath.mnorm(A, 1)
        assert ip.gx.real >= 0 and abs(ip.delta) < 1e-12
        it = iterative_parameters(section, at=z)
        assert mpmath.mnorm(it.chain() - A, 1) < 1e-12 * mpmath.mnorm(A, 1)
        # Z' closes the section iteratively: input impedance with load Z' is Z'
        zin = (A[0, 0] * it.Z1 + A[0, 1]) / (A[1, 0] * it.Z1 + A[1, 1])
        assert abs(zin - it.Z1) < 1e-12 * abs(it.Z1)


def test_t_section_book_image_and_iterative_forms():
    """Eqs. (8.410)-(8.412): W = sqrt(Σ2), q, cth g and the iterative impedances of the T."""
    za, zb, zc = 1 + 0.5j, 2 - 0.3j, 0.7 + 1.1j
    ip = image_parameters(t_section(za, zb, zc), at=0)
    s2 = za * zb + zb * zc + zc * za
    assert abs(ip.W**2 - s2) < 1e-14 and abs(ip.q**2 - (zb + zc) / (za + zb)) < 1e-14
    assert abs(mpmath.coth(ip.g) ** 2 - (za + zb) * (zb + zc) / s2) < 1e-13
    it = iterative_parameters(t_section(za, zb, zc), at=0)
    root = mpmath.sqrt((za + zc) * (za + zc + 4 * zb))
    assert {complex(round(complex(x).real, 12), round(complex(x).imag, 12)) for x in (it.Z1, it.Z2)} == {
        complex(round(v.real, 12), round(v.imag, 12))
        for v in (complex(((za - zc) + root) / 2), complex((-(za - zc) + root) / 2))
    }


def test_terminated_response_against_loop_equations():
    """§8.39: a T section between generator (E, Zr) and load ZH, solved from three loop equations."""
    E, Zr, ZH = sp.symbols("E Z_r Z_H")
    i1, i2 = sp.symbols("i1 i2")
    sol = sp.solve([E - Zr * i1 - ZA * i1 - ZB * (i1 - i2), ZB * (i1 - i2) - ZC * i2 - ZH * i2], [i1, i2])
    r = terminated_response(t_section(ZA, ZB, ZC), E, Zr, ZH)
    assert sp.cancel(r.Iy - sol[i2]) == 0 and sp.cancel(r.Ix - sol[i1]) == 0
    assert sp.cancel(r.Ex - (E - Zr * sol[i1])) == 0


def test_insertion_loss_book_decomposition():
    """Eq. (8.434): g_ins = g + two reflection terms + interaction - mismatch, from image parameters."""
    sec = pi_section(1 + 2 * p, 3 / p, 2 + p)
    Zr, ZH = 0.8 + 0.2j, 1.7 - 0.4j
    for omega in (0.3, 1.1, 2.5):
        z = 1j * omega
        ip = image_parameters(sec, at=z)
        rx, ry = (Zr - ip.Zx) / (Zr + ip.Zx), (ZH - ip.Zy) / (ZH + ip.Zy)
        g_book = (
            ip.g
            + mpmath.log((Zr + ip.Zx) / (2 * mpmath.sqrt(Zr * ip.Zx)))
            + mpmath.log((ZH + ip.Zy) / (2 * mpmath.sqrt(ZH * ip.Zy)))
            + mpmath.log(1 - rx * ry * mpmath.exp(-2 * ip.g))
            - mpmath.log((Zr + ZH) / (2 * mpmath.sqrt(Zr * ZH)))
        )
        g = insertion_loss(sec, Zr, ZH, at=z)
        assert abs(mpmath.exp(g - g_book) - 1) < 1e-12
        a_work = working_loss(sec, Zr, ZH, at=z).real
        a_refl = mpmath.log(abs(Zr + ZH) / (2 * mpmath.sqrt(Zr.real * ZH.real)))
        assert a_work >= 0 and abs(a_work - (g.real + a_refl)) < 1e-12  # (8.452)


def test_chain_power_1000_sections_closed_form():
    """Chain of 1000 identical sections: Chebyshev closed form vs repeated multiplication at 50 digits."""
    n = sp.Symbol("n", integer=True, positive=True)
    section = cascade(series_element(sp.Rational(1, 2) * p), shunt_element(1 / (2 * p)))  # LP half-sections
    formula = sp.lambdify((p, n), chain_power(section, n), "mpmath")
    with mpmath.workdps(50):
        for z in (0.7j, 1.3j, mpmath.mpc(0.01, 0.9)):
            A = section.evaluate(z)
            ref = mpmath.eye(2)
            for _ in range(1000):
                ref = ref * A
            got = mpmath.matrix(formula(z, 1000))
            assert mpmath.mnorm(got - ref, 1) <= 1e-12 * mpmath.mnorm(ref, 1)
    # non-reciprocal section (det != 1): Sylvester's form with sqrt(det)
    M = sp.Matrix([[2, 1], [3, 5]])
    assert chain_power(M, 7) == M**7


def test_brune_test_and_connections():
    """§8.33: parallel T's with common ground are valid; series T's short a shunt arm; an ideal transformer cures it."""
    T1, T2 = t_section(1, 2 * p, 3), t_section(1 / p, 5, 2)
    assert brune_test(T1, T2, "parallel")
    assert not brune_test(T1, T2, "series")
    with pytest.raises(ModelError, match="Brune test"):
        series(T1, T2)
    fixed = series(cascade(T1, ideal_transformer(1)), T2)
    assert _zero(fixed.Z - (T1.Z + T2.Z))
    # a valid parallel connection: the sum equals nodal analysis of the connected netlist (Brune test checks this)
    par = parallel(T1, T2)
    assert _zero(chain_from_netlist(par.netlist) - par.chain)
    # lattices in series-series are invalid too (the cross arms short)
    assert not brune_test(lattice(1, p), lattice(2, 3 * p), "series")


def test_transformer_unit_coupling():
    """Eqs. (8.340)-(8.342): lossless, k = 1: A = [[1/q, 0], [1/(sqrt(LA LB) p), q]], q = sqrt(LB/LA)."""
    LA, LB = sp.Rational(4), sp.Rational(9)
    A = transformer(LA, LB, 6).chain
    assert _zero(A - sp.Matrix([[sp.Rational(2, 3), 0], [1 / (6 * p), sp.Rational(3, 2)]]))
    ZH = sp.Symbol("Z_H")
    Ix_over_Iy = A[1, 0] * ZH + A[1, 1]
    assert sp.cancel(Ix_over_Iy - (ZH + LB * p) / (6 * p)) == 0


def test_bad_input():
    with pytest.raises(ParameterError, match="positive"):
        Resistor(-1)
    with pytest.raises(ModelError, match="do not exist"):
        convert_parameters([[1, 5], [0, 1]], "A", "Z")  # a series impedance has no Z parameters
    with pytest.raises(ModelError, match="singular"):
        from symosc.networks import FourPole

        FourPole([[1, 2], [2, 4]])
    with pytest.raises(ParameterError, match="one of"):
        convert_parameters(sp.eye(2), "Q", "Z")  # (S and T are parameter sets now)
    with pytest.raises(ParameterError, match="positive integer"):
        chain_power(sp.eye(2), 0)


def test_boundary_problem_iterative_form():
    """Eq. (8.407): Iy = (Z'+Z'') E e^{-delta} / [(Zr+Z')(ZH+Z'')(e^s - r'r'' e^{-s})] for a cascade of 5 Π sections."""
    sec = pi_section(2 + p, 1 + 3 * p, 1 / p)
    Zr, ZH, E = sp.Rational(13, 10), sp.Rational(3, 5), 2
    for omega in (sp.Rational(2, 5), sp.Rational(17, 10)):
        z = 1j * float(omega)
        it = iterative_parameters(sec, at=z)
        s5, d5 = 5 * it.s, 5 * it.delta  # iterative parameters add along a cascade (8.403)-(8.405)
        r1 = (Zr - it.Z2) / (Zr + it.Z1)
        r2 = (ZH - it.Z1) / (ZH + it.Z2)
        iy_book = (
            (it.Z1 + it.Z2)
            * E
            * mpmath.exp(-d5)
            / ((Zr + it.Z1) * (ZH + it.Z2) * (mpmath.exp(s5) - r1 * r2 * mpmath.exp(-s5)))
        )
        chain = cascade(*[sec.subs(p, sp.I * omega)] * 5)
        iy = complex(sp.N(terminated_response(chain, E, Zr, ZH).Iy))
        assert abs(iy - complex(iy_book)) < 1e-12 * abs(iy)


@pytest.mark.parametrize(
    "arms",
    [
        [(p, 1 / p)] * 8,  # L-C half-sections: polynomial entries
        [(sp.Symbol("R", positive=True) + sp.Symbol("L", positive=True) * p, 1 / (sp.Symbol("C", positive=True) * p))]
        * 3,  # symbolic values: a polynomial ring in p, R, L, C
        [(1 / (3 * p), 2 * p + 1), (sp.Rational(1, 2) * p, 1 / (p + 4)), (5, 1 / (7 * p))],  # rational functions
        [(sp.sqrt(2) * p, 1 / (sp.sqrt(3) * p)), (p + sp.pi, 1 / p)],  # radicals and pi: SymPy's expressions
    ],
    ids=["lc", "symbolic", "rational", "radicals"],
)
def test_cascade_chain_is_the_product_in_lowest_terms(arms):
    """The cascade's chain matrix (Bulgakov (1954), eq. (8.270)) equals the product of the sections' chain matrices
    evaluated one by one at a complex point in 40-digit mpmath, and every entry is in SymPy's ``cancel`` form."""
    sections = [cascade(series_element(z), shunt_element(y)) for z, y in arms]
    A = cascade(*sections).chain
    assert all(sp.cancel(a) == a for a in A)
    values = {s: sp.Rational(3, 2) + k for k, s in enumerate(sorted(A.free_symbols - {p}, key=str))}
    at = sp.Rational(3, 10) + sp.Rational(17, 10) * sp.I
    with mpmath.workdps(40):
        product = mpmath.eye(2)
        for sec in sections:
            product = product * mpmath.matrix(
                [[sp.N(e.subs(values).subs(p, at), 50) for e in row] for row in sec.chain.tolist()]
            )
        for i in range(2):
            for j in range(2):
                got = mpmath.mpmathify(sp.N(A[i, j].subs(values).subs(p, at), 50))
                assert abs(got - product[i, j]) <= mpmath.mpf(10) ** -35 * (1 + abs(product[i, j]))
