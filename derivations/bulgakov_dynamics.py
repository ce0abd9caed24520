"""Bulgakov (1954) ch. 3 and ch. 7: analytic dynamics and motion about a given state, on textbook systems.

The book's chapter 3 states the machinery without numerical examples, so each row takes a standard system
(Goldstein, Landau & Lifshitz) through the book's formula and prints "quantity | book | symosc | note", where
"book" is the closed form the book's formula gives by hand.  Run
``python derivations/bulgakov_dynamics.py [--section NAME ...] [--out DIR]``; the tables are also written to
``DIR/tables.txt`` (default ``derivations/out/bulgakov_dynamics/``).  Each section returns a dict of the symosc
values, which tests/derivations/test_bulgakov_dynamics_script.py checks independently.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import sys
from pathlib import Path

import sympy as sp

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from symosc import dot, t
from symosc.mechanics import (
    LagrangianSystem,
    action_variable,
    canonical_transformation,
    electromechanical_system,
    routh_reduction,
    separate_hamilton_jacobi,
    stodola_time_constant,
    variational_equations,
    vyshnegradsky_cubic,
)

x, y, r, th, ph, q, p, u, v = sp.symbols("x y r theta phi q p u v", real=True)
m, g, l, k, w, L, R, C, e, c, J = sp.symbols("m g l k omega L R C e c J", positive=True)
h = sp.Symbol("h", real=True)
E = sp.Symbol("E", negative=True)


def _fmt(val) -> str:
    if isinstance(val, sp.MatrixBase):
        return sp.sstr(val.tolist())
    return sp.sstr(val) if isinstance(val, sp.Basic) else str(val)


def _title(text: str) -> None:
    print(f"\n== {text}")
    print(f"{'quantity':<30} | {'book':<40} | {'symosc':<40} | note")


def _row(what: str, book, ours, note: str = "") -> None:
    print(f"{what:<30} | {_fmt(book):<40} | {_fmt(ours):<40} | {note}")


def section_3_3() -> dict:
    """§3.3, eq. (3.12): a pendulum as a particle on x^2 + y^2 - l^2 = 0; the multiplier is the tension."""
    s = LagrangianSystem(m / 2 * (dot(x) ** 2 + dot(y) ** 2), m * g * y, [x, y], constraints=[x**2 + y**2 - l**2])
    _, lam = s.constrained.solved()
    on = {x: l * sp.sin(th), y: -l * sp.cos(th), dot(x): l * sp.cos(th) * dot(th), dot(y): l * sp.sin(th) * dot(th)}
    kappa = sp.simplify(lam[0].xreplace(on))
    angle = s.reduce_coordinates({x: l * sp.sin(th), y: -l * sp.cos(th)}, [th])
    eq = sp.simplify(angle.equations()[0] / (m * l))
    _title("§3.3 Lagrange equations of the first kind (particle pendulum)")
    _row("multiplier kappa", "-m (l th'^2 + g cos th) / (2 l)", kappa, "tension = -2 l kappa")
    _row("reduced equation / (m l)", "l th'' + g sin th", eq, "second kind, eq. (3.47)")
    return {"kappa": kappa, "reduced": eq}


def section_3_7() -> dict:
    """§3.7, eqs. (3.83)-(3.88): Christoffel symbols of polar coordinates."""
    s = LagrangianSystem(m / 2 * (dot(r) ** 2 + r**2 * dot(ph) ** 2), 0, [r, ph])
    G = s.christoffel_symbols()
    _title("§3.7 Christoffel symbols, polar coordinates")
    _row("Gamma^r_phi,phi", "-r", G[0, 1, 1])
    _row("Gamma^phi_r,phi", "1/r", sp.simplify(G[1, 0, 1]))
    return {"G_r_phiphi": G[0, 1, 1], "G_phi_rphi": sp.simplify(G[1, 0, 1])}


def section_3_8() -> dict:
    """§3.8, eqs. (3.93)-(3.97): a series RLC loop and a solenoid plunger L(x) = L + c x."""
    rlc = electromechanical_system(
        m * dot(x) ** 2 / 2, k * x**2 / 2, [x], [q], inductance=sp.Matrix([[L]]),
        elastance=sp.Matrix([[1 / C]]), resistance=sp.Matrix([[R]]), emf=[e],
    )  # fmt: skip
    plunger = electromechanical_system(m * dot(x) ** 2 / 2, k * x**2 / 2, [x], [q], inductance=sp.Matrix([[L + c * x]]))
    voltage = rlc.equations()[1]
    force = sp.expand(plunger.forcing[0] + k * x)
    _title("§3.8 electromechanical systems")
    _row("loop equation", "L q'' + R q' + q/C - e", voltage, "voltage balance (3.97)")
    _row("ponderomotive force", "i^2 dL/dx / 2", force, "i = q'")
    return {"voltage": voltage, "force": force}


def section_3_9() -> dict:
    """§3.9, eqs. (3.98)-(3.107): bead on a hoop spinning at omega; the Jacobi integral T2 + V - T0."""
    R0 = sp.Symbol("R", positive=True)
    cart = LagrangianSystem(
        m / 2 * (dot(x) ** 2 + dot(y) ** 2 + dot(r) ** 2), m * g * r, [x, y, r],
        constraints=[x * sp.sin(w * t) - y * sp.cos(w * t), x**2 + y**2 + r**2 - R0**2],
    )  # fmt: skip
    hoop = cart.reduce_coordinates(
        {x: R0 * sp.sin(th) * sp.cos(w * t), y: R0 * sp.sin(th) * sp.sin(w * t), r: -R0 * sp.cos(th)}, [th]
    )
    _, T1, T0 = (sp.simplify(a) for a in hoop.kinetic_energy_parts)
    jac = sp.simplify(hoop.jacobi_integral)
    _title("§3.9 energy function of a rheonomic system (bead on a spinning hoop)")
    _row("T1", "0", T1)
    _row("T0", "m R^2 omega^2 sin^2 th / 2", T0)
    _row("Jacobi integral", "T2 + V - T0", jac, "conserved although T + V is not")
    return {"T1": T1, "T0": T0, "jacobi": jac}


def section_3_10() -> dict:
    """§3.10, eqs. (3.110)-(3.114): Routh function of a central force, book sign R = L - p phi'."""
    red = routh_reduction(LagrangianSystem(m / 2 * (dot(r) ** 2 + r**2 * dot(ph) ** 2), -k / r, [r, ph]), [ph])
    sph = routh_reduction(
        LagrangianSystem(
            m * l**2 / 2 * (dot(th) ** 2 + sp.sin(th) ** 2 * dot(ph) ** 2), -m * g * l * sp.cos(th), [th, ph]
        ),
        [ph],
    )
    th0 = sp.pi / 4
    p0 = sp.sqrt(m**2 * g * l**3 * sp.sin(th0) ** 4 / sp.cos(th0))
    lin = sph.small_oscillations({th: th0}, {sph.momenta[0]: p0})
    omega2 = sp.simplify(lin.K[0, 0] / lin.M[0, 0])
    _title("§3.10 Routh reduction")
    _row("Routh function", "m r'^2/2 + k/r - p^2/(2 m r^2)", red.routhian)
    _row("conical pendulum, Omega^2", "(g/(l cos th0))(1 + 3 cos^2 th0)", omega2, "th0 = pi/4 (Landau & Lifshitz)")
    return {"routhian": red.routhian, "omega2": omega2}


def section_3_14() -> dict:
    """§3.14, eqs. (3.135)-(3.139): generating functions."""
    ex = canonical_transformation(q * u, [q], [p], [u], [v], kind=1)
    qq, pp, uu, vv = sp.symbols("q p u v", positive=True)
    ho = canonical_transformation(w * qq**2 / 2 * sp.cot(uu), [qq], [pp], [uu], [vv], kind=1)
    Hn = sp.simplify(ho.new_hamiltonian((pp**2 + w**2 * qq**2) / 2))
    _title("§3.14 canonical transformations")
    _row("S = q u: (u, v)", "(p, -q)", (ex.forward[u], ex.forward[v]), "exchange of coordinates and momenta")
    _row("S = (w q^2/2) cot u: H'", "omega v", Hn, "action-angle variables of the oscillator")
    return {"exchange": (ex.forward[u], ex.forward[v]), "H_new": Hn, "canonical": ho.is_canonical()}


def section_3_16() -> dict:
    """§3.16, eqs. (3.145)-(3.151): action variables and Poincaré frequencies."""
    ho = action_variable(p**2 / 2 + w**2 * q**2 / 2, q, p, h)
    Lz = sp.Symbol("L_z", positive=True)
    kep = action_variable(p**2 / (2 * m) + Lz**2 / (2 * m * r**2) - k / r, r, p, E)
    _title("§3.16 Hamilton-Jacobi: action variables")
    _row("oscillator J(h)", "h / omega", ho.action)
    _row("oscillator nu = dh/dJ", "omega", ho.frequency)
    _row("Kepler radial J_r", "k sqrt(m/(-2E)) - L_z", kep.action, "Goldstein eq. (10.137)")
    _row("Kepler period", "2 pi k sqrt(m) / (-2E)^(3/2)", kep.period, "Kepler's third law")
    pr, pth = sp.symbols("p_r p_theta", real=True)
    Hn = pr**2 / (2 * m) + pth**2 / (2 * m * r**2) - k / r + c * sp.cos(th) / r**2
    sep = separate_hamilton_jacobi(Hn, [r, th], [pr, pth], h)
    beta = sep.constants[th]
    _row("-k/r + c cos(th)/r^2: factor", "2 m r^2", sep.factors[0], "Landau & Lifshitz §48 (Stäckel separation)")
    _row("  p_theta^2", "beta - 2 m c cos(theta)", sep.momenta[pth] ** 2)
    _row("  p_r^2", "2 m (h + k/r) - beta / r^2", sp.expand(sep.momenta[pr] ** 2), f"beta = {beta}")
    return {
        "J_ho": ho.action,
        "nu_ho": ho.frequency,
        "J_kepler": kep.action,
        "T_kepler": kep.period,
        "separation": (sep.factors[0], sep.momenta[pth] ** 2, sep.momenta[pr] ** 2, beta),
    }


def section_7_2() -> dict:
    """§7.2: reduction of f(D) y = w to first order, method 2, on the book's system of §8.52, Example 2."""
    y1, y2 = sp.symbols("y1 y2", real=True)
    D = sp.Symbol("D")
    from symosc import ddot

    ve = variational_equations(
        [ddot(y1) - 2 * dot(y1) - y1 + dot(y2) - y2, dot(y1) - 2 * y1 + y2], [y1, y2]
    )  # the book's f(D) = [[D^2 - 2D - 1, D - 1], [D - 2, 1]]
    red1, red2 = ve.first_order(method=1), ve.first_order(method=2)
    lam = sp.Symbol("lambda")
    _title("§7.2 reduction to first order (system of §8.52, Example 2)")
    _row("orders m_k", "(2, 1)", ve.coordinate_orders())
    _row("unknowns, method 1 / method 2", "4 / 3", f"{len(red1.state)} / {len(red2.state)}", "sum max(1, m_k) = 3")
    _row("det f(D)", "D - 3", sp.factor(ve.operator_matrix(D).det()), "§8.52")
    _row("det(A lambda + H), method 2", "+-(lambda - 3)", red2.characteristic_polynomial(lam))
    return {
        "orders": ve.coordinate_orders(),
        "sizes": (len(red1.state), len(red2.state)),
        "char2": red2.characteristic_polynomial(lam),
        "char1": red1.characteristic_polynomial(lam),
    }


def section_7() -> dict:
    """§7.5-7.7: Stodola's time constant and Vyshnegradsky's cubic from the Lagrangian (7.51)."""
    K0 = sp.Symbol("K0", positive=True)
    T = stodola_time_constant(J, K0 - c * w, w)
    vt, z, zs, gam, kf, a1, cz, e1 = sp.symbols("vartheta z z_s gamma k_f a1 c_z e1", positive=True)
    alpha = a1 * z**2
    A = alpha.diff(z) / 2
    e0 = (A * w**2).xreplace({z: zs}) - e1 * zs
    s = LagrangianSystem(
        (J + alpha) * dot(vt) ** 2 / 2 + gam * dot(z) ** 2 / 2, e0 * z + e1 * z**2 / 2, [vt, z],
        forces=[-cz * (z - zs), -kf * dot(z)],
    )  # fmt: skip
    lam = sp.Symbol("lambda")
    det = variational_equations(s, reference={vt: w * t, z: zs}).characteristic_polynomial(lam)
    Az = A.xreplace({z: zs})
    U, N = (J + alpha.xreplace({z: zs})) / cz, 2 * Az * w / cz
    cubic, cond = vyshnegradsky_cubic(
        U, gam / (2 * Az * w), kf / (2 * Az * w), (e1 - A.diff(z) * w**2) / (2 * Az * w), N, lam
    )
    ratio = sp.simplify(det / (lam * cubic))
    _title("§7.5-7.7 engine with a centrifugal governor")
    _row("Stodola T for K = K0 - c omega", "J / c", T, "eq. (7.39)")
    _row("det f(lambda) / (lambda * cubic)", "independent of lambda", ratio, "eqs. (7.55)-(7.57)")
    _row("Hurwitz condition", "U W (U delta + N) > U V^2", cond, "Vyshnegradsky's inequality")
    return {"T": T, "ratio": ratio, "condition": cond}


SECTIONS = {
    "3.3": section_3_3,
    "3.7": section_3_7,
    "3.8": section_3_8,
    "3.9": section_3_9,
    "3.10": section_3_10,
    "3.14": section_3_14,
    "3.16": section_3_16,
    "7.2": section_7_2,
    "7": section_7,
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--section", action="append", choices=sorted(SECTIONS), help="run only these sections")
    parser.add_argument("--out", default=str(Path(__file__).resolve().parent / "out" / "bulgakov_dynamics"))
    args = parser.parse_args(argv)
    buf = io.StringIO()
    for name in args.section or list(SECTIONS):
        with contextlib.redirect_stdout(buf):
            SECTIONS[name]()
    text = buf.getvalue()
    print(text, end="")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "tables.txt").write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
