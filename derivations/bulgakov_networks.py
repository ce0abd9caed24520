"""Bulgakov (1954) §8.31-8.49 and ch. 9 B-D: two-poles, four-poles, synthesis, filters, vibration absorbers.

Run ``python derivations/bulgakov_networks.py [--out DIR]``.  Prints one table "quantity | book | symosc | note"
per worked example (E15, E16, E18, T9, T10, T11 and the legible formulas of §8.34, §8.41, §8.46, §9.21, §9.23,
§9.26, §9.38–9.40) and
saves the absorber response curves to ``DIR/absorber.png`` (default ``derivations/out/bulgakov_networks/``).
Where the printed value cannot be read the book column says so; nothing is tuned to match.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import mpmath
import sympy as sp

from symosc.errors import ParameterError
from symosc.networks import (
    Absorber,
    Capacitor,
    Impedance,
    Inductor,
    absorber_fixed_points,
    absorber_hinf_optimum,
    absorber_optimum,
    biquadratic_is_positive_real,
    brune_synthesis,
    cascade,
    cascade_junctions,
    check_reactance_theorem,
    constant_k_section,
    constant_resistance_bridged_t,
    correcting_cascade,
    correcting_link,
    energy_functions,
    equivalent_two_pole,
    image_parameters,
    is_positive_real,
    l_section,
    lattice_phase_network,
    link_transfer,
    matching_l_pad,
    t_section,
    twin_t_notch,
    working_loss,
)

p = sp.Symbol("p")
ROWS: list[tuple[str, str, str, str]] = []


def row(quantity: str, book: object, value: object, note: str = "") -> None:
    ROWS.append((quantity, str(book), str(value), note))


def e15() -> dict:
    """§8.31 (8.248)-(8.252): the equivalent two-pole."""
    out = {}
    for a, b, book in ((1, 2, "(4-2√2, 4, 4+2√2, 4)"), (2, sp.Rational(1, 2), "(3.4069, 0.53465, 4.8431, 7.7154)")):
        c, d, e, f = equivalent_two_pole(a, b)
        Z1, Z2 = sp.symbols("Z1 Z2")
        lhs = ((Impedance(Z1) | Impedance(Z2)) + Impedance(a * Z1) + Impedance(b * Z2)).impedance()
        rhs = ((Impedance(c * Z1) + Impedance(d * Z2)) | (Impedance(e * Z1) + Impedance(f * Z2))).impedance()
        ok = sp.simplify(lhs - rhs) == 0
        vals = tuple(round(float(v), 5) for v in (c, d, e, f))
        row(f"E15 (c,d,e,f) a={a}, b={b}", book, vals, f"identity holds: {ok}; branches may be swapped")
        out[(a, b)] = (c, d, e, f)
    return out


def e16() -> dict:
    """Twin-T null network (Fig. 110)."""
    R, C, s = sp.symbols("R C s", positive=True)
    Y = twin_t_notch(R, C, s).Y
    y11 = sp.factor(Y[0, 0])
    row("E16 Y11 twin T", "(s²R²C²D²+2(1+s²)RCD+1)/(2R(RCD+1))", y11, "the printed denominator (s²RCD+1) is doubtful")
    row(
        "E16 null at",
        "ω = 1/(sRC)",
        sp.solve(sp.numer(sp.factor(Y[1, 0])).subs(p, sp.I * sp.Symbol("w")), sp.Symbol("w"))[-1],
        "",
    )
    return {"Y11": y11}


def e18() -> dict:
    """Lattice phase network (8.365)-(8.368)."""
    net = lattice_phase_network(2, sp.Rational(1, 2))
    ip = image_parameters(net, at=0.8j)
    row("E18 W (L=2, C=1/2)", "sqrt(L/C) = 2", mpmath.nstr(ip.W.real, 12), "")
    row(
        "E18 b at ω = 0.8",
        "2 arctan(sqrt(LC) ω) = 1.349482",
        mpmath.nstr(ip.g.imag, 7),
        f"a = {mpmath.nstr(ip.g.real, 3)}",
    )
    return {"g": ip.g}


def image_formulas() -> dict:
    """§8.34 and §8.41 on a T section."""
    za, zb, zc = 1 + 0.5j, 2 - 0.3j, 0.7 + 1.1j
    ip = image_parameters(t_section(za, zb, zc), at=0)
    s2 = za * zb + zb * zc + zc * za
    row(
        "(8.410) W² of the T",
        "Σ2",
        f"{mpmath.nstr(ip.W**2, 10)} vs {mpmath.nstr(mpmath.mpc(s2), 10)}",
        "coupled radicals",
    )
    return {}


def synthesis() -> dict:
    Z = (p**2 + p + 1) / (p**2 + p + 4)
    net = brune_synthesis(Z, p)
    row(
        "§9.26 biquadratic test (1,1,1,1,1,4)",
        "a1b1 ≥ (√(a0b2)-√(a2b0))²",
        biquadratic_is_positive_real(1, 1, 1, 1, 1, 4),
        "",
    )
    row("§9.23 Theorem V on (p²+p+1)/(p²+p+4)", "positive real", is_positive_real(Z, p), "")
    row("Brune network of (p²+p+1)/(p²+p+4)", "—", net, f"impedance error: {sp.cancel(net.impedance(p) - Z)}")
    return {"brune": net}


def t9(out: Path | None) -> dict:
    xs = [float(v) for v in absorber_fixed_points(0.1, 0.9)]
    row("T9 fixed points ν² (ω_m=0.9, μ=0.1)", "0.701909, 1.099043", ", ".join(f"{x:.6f}" for x in xs), "(9.600)")
    a = Absorber(0.1, 0.9, 0.2)
    heights = [float(a.amplification(x**0.5)) for x in xs]
    row("T9 R1 at the fixed points", "4.38789, 4.78589", ", ".join(f"{h:.5f}" for h in heights), "independent of β")
    mu = sp.Symbol("mu", positive=True)
    f, z = absorber_optimum(mu)
    row("Den Hartog tuning", "1/(1+μ)", f, "derived: equal fixed-point heights")
    row("Den Hartog damping", "√(3μ/(8(1+μ)³))", z, "derived: mean of the horizontal-tangent dampings")
    results = {}
    for m, beta_book, beta_num in ((0.05, 0.127267, 0.12743), (0.1, 0.167852, 0.16828), (0.25, 0.219089, 0.22041)):
        r = absorber_hinf_optimum(m, tune=False)
        row(
            f"T9 β, μ={m}",
            f"{beta_book} (formula), {beta_num} (min-max)",
            f"{float(z.subs(mu, m)):.6f}, {r.damping_ratio:.5f}",
            f"peaks {r.fixed_point_peak:.5f} → {r.peak:.5f}",
        )
        results[m] = r
    if out is not None:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots()
        f0, z0 = (float(v) for v in absorber_optimum(sp.Float(0.1, 30)))
        Absorber(0.1, f0, z0).plot(ax=ax)
        Absorber(0.1, f0, 0.0).plot(ax=ax)
        ax.set_title("Absorber, μ = 0.1, Den Hartog tuning")
        out.mkdir(parents=True, exist_ok=True)
        fig.savefig(out / "absorber.png", dpi=100)
        plt.close(fig)
    return results


def t10() -> dict:
    L, C = 1 / (2 * sp.pi), sp.Rational(1, 10**6) / (2 * sp.pi)
    sec = constant_k_section("lowpass", sp.sqrt(L / C), 1 / sp.sqrt(L * C))
    four = cascade(*[sec.four_pole] * 4)
    values = {}
    for x, book in ((0.1, 1.171360), (0.5, 1.083333), (0.9, 1.377219), (1.2, 7423.73), (2.0, 6.71276e8)):
        v = mpmath.exp(2 * working_loss(four, 1500, 500, at=2j * mpmath.pi * 1000 * x).real)
        row(
            f"T10 e^(2a_op), x={x}",
            book,
            mpmath.nstr(v, 7),
            "recomputed by (9.430)-(9.435); the printed closed form is garbled",
        )
        values[x] = v
    return values


def t11() -> dict:
    pad = matching_l_pad(1500, 500)
    row("T11 Ra, Rb", "1224.74, 612.37", f"{float(pad.Ra):.2f}, {float(pad.Rb):.2f}", "(9.514)-(9.517)")
    row("T11 a0 [Np]", "1.14622", f"{float(pad.loss):.5f}", "")
    return {"pad": pad}


def correcting() -> dict:
    """§9.38–9.40, Tables 8–9: constant-resistance links, their element values and the bridged-T conversion."""
    T1, T2, k, W = 1, 4, 2, 1
    link = correcting_link(link_transfer("lag", T1=T1, T2=T2, k=k), W=W)
    a0, a1, b0, b1 = k * T2 - T1, k - 1, k * T2 + T1, k + 1
    book = sp.factor((a0 * p + a1) * W / (b0 * p + b1))
    row("§9.38 link IV Za (T1=1, T2=4, k=2)", book, sp.factor(link.Za.impedance(p)), "Table 8: a0=kT2-T1, b0=kT2+T1")
    row("§9.38 link IV lattice arms", "R + (R||L), R || (R+C)", f"{link.Za!r}; {link.Zb!r}", "")
    row(
        "  transfer error, input impedance",
        "0, W",
        f"{sp.cancel(link.realized_transfer() - link.transfer)}, {link.input_impedance()}",
        "from the chain matrix (8.360)",
    )
    vi = correcting_link(link_transfer("all-pass", T=2, k=3), W=10)
    caps = [e.C for e in vi.Za.elements() if isinstance(e, Capacitor)]
    row("Table 9 link VI C = (k+1)²T/(4kW), T=2, k=3, W=10", sp.Rational(16 * 2, 4 * 3 * 10), caps[0], "")
    vii = correcting_link(link_transfer("differentiating", T=2), W=10)
    Ls = [e.L for e in vii.Zb.elements() if isinstance(e, Inductor)]
    Cs = [e.C for e in vii.Za.elements() if isinstance(e, Capacitor)]
    row("Table 9 link VII L = 2TW, C = 2T/W (T=2, W=10)", "40, 2/5", f"{Ls[0]}, {Cs[0]}", "")
    kinds = {
        "I": ("attenuator", {"k": 3}),
        "II": ("lead", {"T1": 2, "T2": 1}),
        "III": ("lead-stabilizing", {"T1": 2, "T2": 1}),
        "IV": ("lag", {"T1": 1, "T2": 4, "k": 2}),
        "V": ("lag-stabilizing", {"T1": 1, "T2": 4, "k": 2}),
        "VI": ("all-pass", {"T": 1}),
        "VII": ("differentiating", {"T": 1}),
        "VIII": ("low-pass", {"T": 1, "k": 2}),
    }
    convertible = []
    for numeral, (kind, params) in kinds.items():
        try:
            tee = constant_resistance_bridged_t(correcting_link(link_transfer(kind, **params)))
        except ParameterError:  # the conversion is refused, naming the failed condition (9.578)
            continue
        convertible.append(numeral)
        assert tee.four_pole.chain == correcting_link(link_transfer(kind, **params)).four_pole.chain
    row("§9.40 links with a bridged-T form", "I, II, IV, VII, VIII", ", ".join(convertible), "same chain matrix")
    net = correcting_cascade(1 / ((p + 1) * (p + 2) * (p + 3)), W=1)
    row(
        "§9.37 1/((p+1)(p+2)(p+3)) as a cascade",
        "3 first-order links",
        f"{len(net.links)} links, gain {net.gain}",
        f"transfer error {sp.cancel(net.realized_transfer() - net.transfer)}",
    )
    return {"link": link, "convertible": convertible}


def energy() -> dict:
    """§9.21: Z|I1|² = F0 + p T0 + V0/p; Foster's theorem dX/dω = (T0 + V0/ω²)/|I1|² (9.250)."""
    net = (Inductor(1) | Capacitor(2)) + Inductor(3) + ((Inductor(1) + Capacitor(1)) | Capacitor(1))
    at = sp.I * sp.Rational(1, 2)
    values = energy_functions(net).evaluate(at)
    w = sp.Symbol("w", positive=True)
    X = sp.cancel(-sp.I * net.impedance(p).subs(p, sp.I * w))
    slope = sp.diff(X, w).subs(w, sp.Rational(1, 2))
    row(
        "(9.250) dX/dω at ω = 1/2", sp.nsimplify(slope), values.reactance_slope(), "book: d/dω of X; symosc: T0 + V0/ω²"
    )
    row("(9.250) Foster's theorem on the same network", "dX/dω > 0", bool(check_reactance_theorem(net)), "")
    return {"slope": slope, "energy": values.reactance_slope()}


def junctions() -> dict:
    """§8.46, (8.427): junction currents of four identical Γ sections against the direct chain solution."""
    sections = [l_section(p + 2, 3 / p + 1, shunt_first=True)] * 4
    at = mpmath.mpc(0.3, 1.7)
    result = cascade_junctions(sections, 1, 2, 1, at)
    total = mpmath.eye(2)
    for fp in sections:
        total = total * fp.evaluate(at)
    z_in = (total[0, 0] + total[0, 1]) / (total[1, 0] + total[1, 1])
    ix = 1 / (2 + z_in)
    row(
        "(8.427) I_0 of 4 Γ sections at p = 0.3+1.7i",
        mpmath.nstr(ix, 10),
        mpmath.nstr(result.I[0], 10),
        "book column: direct chain solution (no iterative parameters)",
    )
    state = mpmath.matrix([1 - 2 * ix, ix])
    for fp in sections:
        state = mpmath.inverse(fp.evaluate(at)) * state
    row("(8.427) I_4 (load current)", mpmath.nstr(state[1], 10), mpmath.nstr(result.I[-1], 10), "")
    return {"direct": state[1], "formula": result.I[-1]}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path(__file__).parent / "out" / "bulgakov_networks")
    args = parser.parse_args(argv)
    ROWS.clear()
    e15()
    e16()
    e18()
    image_formulas()
    synthesis()
    t9(args.out)
    t10()
    t11()
    correcting()
    energy()
    junctions()
    width = [max(len(r[i]) for r in ROWS) for i in range(4)]
    header = ("quantity", "book", "symosc", "note")
    print(" | ".join(h.ljust(min(w, 60)) for h, w in zip(header, width, strict=True)))
    for r in ROWS:
        print(" | ".join(c.ljust(min(w, 60)) for c, w in zip(r, width, strict=True)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
