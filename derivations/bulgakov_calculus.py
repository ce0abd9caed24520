"""Bulgakov (1954) Part I, ch. 1-2: the legible worked examples of matrix and Carson operational calculus.

Source: B. V. Bulgakov, "Oscillations" (Kolebaniya), Moscow, 1954, ch. 1-2 (worked examples, Sylvester's and the
confluent formula, the expansion theorems, integral squares).
Run ``python derivations/bulgakov_calculus.py [--section NAME ...]``.

Each section prints a table "quantity | book | symosc | note" and returns a dict of the symosc values, so that
tests/derivations/test_bulgakov_calculus_script.py can check them against independent computations.  Exact values
are printed exactly.  Most displayed matrices are illegible in the available copy of the book: where an example had to
be reconstructed the note says so, where the print is illegible the book column says so; nothing is tuned to match.
"""

from __future__ import annotations

import argparse
import sys

import sympy as sp

from symosc.algebra import (
    adjugate_poly,
    determinantal_divisors,
    elementary_divisors,
    function_elementary_divisors,
    invariant_factors,
    luzin_form,
    matrix_function,
    polymatrix_divmod,
    smith_form,
)
from symosc.operational import heaviside_expand, integral_square, inverse_carson, solve_operational

l, x, t, p, D = sp.symbols("l x t p D")
R = sp.Rational


def _fmt(v) -> str:
    if isinstance(v, sp.MatrixBase):
        return sp.sstr(v.tolist())
    if isinstance(v, tuple | list):
        return "(" + ", ".join(_fmt(e) for e in v) + ")"
    return sp.sstr(v) if isinstance(v, sp.Basic) else str(v)


def _title(text: str) -> None:
    print(f"\n== {text}")
    print(f"{'quantity':<34} | {'book':<34} | {'symosc':<44} | note")


def _row(what: str, book, ours, note: str = "") -> None:
    print(f"{what:<34} | {_fmt(book):<34} | {_fmt(ours):<44} | {note}")


# ------------------------------------------------------------------------------------------------ chapter 1
def section_1_18() -> dict:
    """§1.18: divisors of f = [[l^2-2l+1, l-1, l-1], [l-1, l^2-2l+1, l-1]] (2x3)."""
    f = sp.Matrix([[l**2 - 2 * l + 1, l - 1, l - 1], [l - 1, l**2 - 2 * l + 1, l - 1]])
    dd = [sp.factor(d) for d in determinantal_divisors(f, l)]
    inv = [sp.factor(e) for e in invariant_factors(f, l)]
    ed = elementary_divisors(f, l)
    sf = smith_form(f, l)
    _title("§1.18 determinantal divisors, invariant factors, elementary divisors (Smith form)")
    _row("D1", "l - 1", dd[0])
    _row("D2", "(l-1)^2 (l-2)", dd[1])
    _row("E1", "l - 1", inv[0])
    _row("E2", "(l-1)(l-2)", inv[1])
    _row("elementary divisors {root: exps}", "l-1, l-1, l-2 (all linear)", ed)
    _row("Smith form S = U f V", "diag(E1, E2)", sf.S, "not printed; follows from E1, E2")
    _row("det U, det V", "non-zero constants", (sf.U.det(), sf.V.det()), "unimodular (1.167)")
    return {"f": f, "D": dd, "E": inv, "elementary_divisors": ed, "S": sf.S, "U": sf.U, "V": sf.V}


def section_1_21() -> dict:
    """§1.21 Ex. 5 (reconstructed): left division g = f S + T."""
    f = sp.Matrix([[2 * l - 2, l + 2], [3 * l - 1, l]])
    g = sp.Matrix([[l**2 + 1, l], [3, 1]])
    S, T = polymatrix_divmod(f, g, l, side="left")
    det_f = sp.expand(f.det())
    _title("§1.21 Ex. 5 left division of polynomial matrices, g = f S + T")
    _row("det f", "-l^2 - 7l + 2", det_f)
    _row("S", "[[-l+7, -1], [3l-22, 3]]", S, "reconstructed (print illegible)")
    _row("T", "[[59, -8], [10, 0]]", T, "deg T = 0 since a0 is nonsingular")
    return {"f": f, "g": g, "S": S, "T": T, "det_f": det_f}


def section_1_22() -> dict:
    """§1.22 Ex. 1 (reconstructed): Luzin's triangular canonical form by row operations."""
    f = sp.Matrix([[2 * l**2 + 3, 2 * l + 1], [l**2 - 2, l + 2]])
    res = luzin_form(f, l)
    det_u = sp.simplify(res.U.det())
    _title("§1.22 Ex. 1 triangular (Luzin) canonical form u f")
    _row("det f", "3l^2 + 7l + 8", sp.expand(f.det()))
    _row("u f", "[[1, -3/7], [0, l^2 + 7l/3 + 8/3]]", res.H, "reconstructed (print illegible)")
    _row("det u", "illegible (recomputed: 1/3)", det_u)
    return {"f": f, "H": res.H, "U": res.U, "det_U": det_u}


def section_1_35() -> dict:
    """§1.35: Sylvester's formula for R(l) = (l+1)/(4l) of z = [[4,-3],[2,-1]]."""
    z = sp.Matrix([[4, -3], [2, -1]])
    Rz = matrix_function(z, (x + 1) / (4 * x), var=x)
    eig = sorted(Rz.eigenvals())
    _title("§1.35 rational function of a matrix by Sylvester's formula")
    _row("R(z), R(l) = (l+1)/(4l)", "illegible; recomputed (1/8)[[1,3],[-2,6]]", Rz, "R(l) reconstructed")
    _row("eigenvalues of R(z)", "R(1) = 1/2, R(2) = 3/8", eig)
    _row("z recovered as 5E - 8R(z)", z, 5 * sp.eye(2) - 8 * Rz)
    return {"z": z, "R": Rz, "eigenvalues": eig}


def section_1_36() -> dict:
    """§1.36 (reconstructed): S(l) = l/(1+l^2) with S'(1) = 0 splits the divisor of J_2(1)."""
    S = sp.Lambda(x, x / (1 + x**2))
    z = sp.Matrix([[1, 1], [0, 1]])
    Sz = matrix_function(z, S)
    split = function_elementary_divisors(z, S)
    z2 = sp.Matrix([[2, 1], [0, 2]])
    Sz2 = matrix_function(z2, S)
    kept = function_elementary_divisors(z2, S)
    _title("§1.36 elementary divisors of a function of a matrix")
    _row("S(z), z = J_2(1)", "S(1) E = (1/2) E", Sz, "S'(1) = 0")
    _row("divisors of S(z)", "two linear at 1/2", split, "splitting")
    _row("S(J_2(2))", "quadratic divisor kept", Sz2, "S'(2) = -3/25 != 0")
    _row("divisors of S(J_2(2))", "one quadratic", kept, "Lappo-Danilevsky (1.307)")
    return {"Sz": Sz, "divisors": split, "Sz2": Sz2, "divisors2": kept}


def section_sylvester() -> dict:
    """§1.30: Sylvester (simple roots) and confluent (1.284)-(1.287) forms of exp(zt).

    The book prints the formulas, not numbers; the matrices are our examples (simple roots
    1, 2; derogatory double root 2 with linear divisors) and a Jordan block (non-linear divisor).
    """
    z1 = sp.Matrix([[4, -3], [2, -1]])
    simple = matrix_function(z1, sp.Lambda(x, sp.exp(x * t)), method="sylvester")
    F1 = adjugate_poly(z1, l)
    dDelta1 = sp.diff((l * sp.eye(2) - z1).det(), l).subs(l, 1)
    z2 = sp.Matrix([[2, 0, 0], [0, 2, 0], [1, 1, 3]])
    derog = matrix_function(z2, sp.Lambda(x, sp.exp(x * t)), spectral=True)
    F2p = sp.diff(adjugate_poly(z2, l), l).subs(l, 2)
    z3 = sp.Matrix([[2, 1, 0], [0, 2, 0], [0, 0, 3]])
    jordan = matrix_function(z3, sp.Lambda(x, sp.exp(x * t)), method="confluent", spectral=True)
    comp = {c.root: c for c in jordan.spectral.components}
    _title("§1.30 Sylvester / confluent matrix functions, exp(z t)")
    _row("exp(z t), z = [[4,-3],[2,-1]]", "e^t eps_1 + e^(2t) eps_2 (1.279)", simple.applyfunc(sp.expand))
    _row("F(1)^2 = Delta'(1) F(1)", "Delta'(1) = -1 (1.311)", dDelta1, f"holds: {F1.subs(l, 1) ** 2 == -F1.subs(l, 1)}")
    _row("F'(2), z derogatory", "[[-1,0,0],[0,-1,0],[1,1,0]], rank 2", F2p, f"rank {F2p.rank()} = q (1.216)")
    _row("spectral data (q, e)", "e_2 = 1 < q_2 = 2", derog.spectral, "derogatory: eta_2 = 0 (1.286)")
    _row("exp(z t), z derogatory", "(1.287)", derog.value)
    _row("eps_2, eta_2 for J_2(2) + (3)", "(1.284), (1.285)", (comp[2].projector, comp[2].nilpotents[0]))
    _row("exp(z t), z = J_2(2) + (3)", "(1.287): t e^(2t) eta_2 term", jordan.value)
    return {
        "z_simple": z1,
        "exp_simple": simple,
        "dDelta_1": dDelta1,
        "z_derogatory": z2,
        "exp_derogatory": derog.value,
        "F_prime_2": F2p,
        "index_derogatory": {c.root: (c.multiplicity, c.index) for c in derog.spectral.components},
        "z_jordan": z3,
        "exp_jordan": jordan.value,
        "eps_jordan": comp[2].projector,
        "eta_jordan": comp[2].nilpotents[0],
    }


# ------------------------------------------------------------------------------------------------ chapter 2
def section_2_19() -> dict:
    """§2.19 second expansion theorem and the real form (2.89)-(2.91)."""
    X1 = p * (3 * p + 1) / ((p - 1) ** 2 * (p + 2))
    x1 = heaviside_expand(X1, p, t)
    X2 = p * (p + 3) / (p**2 + 2 * p + 10)
    x2 = inverse_carson(X2, p, t)
    book1 = ((12 * t + 5) * sp.exp(3 * t) - 5) * sp.exp(-2 * t) / 9
    _title("§2.19 Heaviside expansion (Carson images)")
    _row("p(3p+1)/((p-1)^2 (p+2))", "((12t+5)e^(3t) - 5) e^(-2t)/9", x1, f"diff {sp.simplify(x1 - book1)}")
    _row("p(p+3)/(p^2+2p+10), real form", "(2.89)-(2.91): cos/sin pair", x2, "not a book example")
    return {"X1": X1, "x1": x1, "X2": X2, "x2": x2}


def section_2_21() -> dict:
    """§2.21: (D^2-2) y1 + D y2 = x, (D^2+D-3) y1 + (D+1) y2 = 0."""
    f = sp.Matrix([[D**2 - 2, D], [D**2 + D - 3, D + 1]])
    e = sp.Matrix([1, 0])
    sol = solve_operational(f, e, D=D, t=t)
    pp = sol.p
    xin = sp.sin(t) + t**2
    sol_x = solve_operational(f, e, [xin], D=D, t=t)
    y10, y11, y20 = sp.symbols("y1_0 y1_1 y2_0")
    rel = sp.solve(sol_x.constraints, [y11, y20], dict=True)[0]
    y = sol_x.response.subs(rel).applyfunc(sp.simplify)
    u = sp.Symbol("u")
    conv = sp.integrate(sp.exp(2 * (t - u)) * xin.subs(t, u), (u, 0, t))
    book_y = sp.Matrix([(y10 - xin.subs(t, 0)) * sp.exp(2 * t) + xin + 3 * conv, -sp.diff(xin, t) - 3 * xin - 3 * conv])
    book_y[1] += (xin.subs(t, 0) - y10) * sp.exp(2 * t)
    dy = (y - book_y).applyfunc(sp.simplify)
    _title("§2.21 operational solution of a degenerate system")
    _row("Delta(D) = det f", "D - 2", sol.delta.subs(pp, D), "s = 1, l1 = 2")
    _row("F = adj f", "[[D+1, -D], [-(D^2+D-3), D^2-2]]", sol.adjugate.subs(pp, D))
    _row("S(D)", "[[1], [-D-3]]", sol.feedthrough.subs(pp, D))
    _row("N(t)", "e^(2t) [[3], [-3]]", sol.impulse)
    _row("M(t)", "e^(2t)[[y1'(0)+y2(0)], [-y1'(0)-y2(0)]]", sol.free.applyfunc(sp.factor))
    _row("m = m1 + m2, s", "m = 3, s = 1", (sum(sol.orders), sol.degree), "m - s = 2 constraints")
    _row("constraints (xk_j = x^(j)(0))", "y1'(0)+y2(0) = y1(0)-x(0), ...", sol.constraints)
    _row("y1 for x = sin t + t^2", "[y1(0)-x(0)]e^(2t) + x + 3 e^(2t)*x", y[0], f"diff {dy[0]}; free y1(0)")
    _row("y2 for x = sin t + t^2", "[x(0)-y1(0)]e^(2t) - x' - 3x - 3 e^(2t)*x", y[1], f"diff {dy[1]}")
    return {
        "f": f,
        "delta": sol.delta,
        "p": pp,
        "adjugate": sol.adjugate,
        "feedthrough": sol.feedthrough,
        "impulse": sol.impulse,
        "free": sol.free,
        "orders": sol.orders,
        "degree": sol.degree,
        "constraints": sol.constraints,
        "x": xin,
        "y": y,
    }


def section_2_32() -> dict:
    """§2.32: integral square estimates, (2.153), I3 = 3/16, the I4 denominator."""
    a, b, k0, w, z = sp.symbols("a b k0 omega zeta", positive=True)
    I2 = integral_square(a * p + b, k0 * (p**2 + 2 * z * w * p + w**2), p)
    spots = {}
    _title("§2.32 integral square estimates I = Integral(x^2, (t, 0, oo)), x <- Laplace U/H")
    _row("(2.153) I2", "(a^2 w^2 + b^2)/(4 k0^2 w^3 zeta)", I2)
    for zv, ref in ((R(3, 10), 0.0470679), (R(1), 0.0141204), (R(5, 2), 0.0056481)):
        vals = {a: R(7, 10), b: R(13, 10), k0: 2, w: 3, z: zv}
        num = integral_square(vals[a] * p + vals[b], 2 * (p**2 + 2 * zv * 3 * p + 9), p)
        spots[zv] = num
        _row(f"  a=.7 b=1.3 k0=2 w=3 zeta={zv}", ref, f"{num} = {float(num):.7f}", "independent spot value")
    I3 = integral_square(1, (p + 1) ** 3, p)
    _row("I3, H = (p+1)^3, U = 1", "illegible; recomputed 3/16", I3, "x = t^2 e^-t / 2")
    k = sp.symbols("k0:5", positive=True)
    u = sp.symbols("u0:4")
    I4 = integral_square(sum(u[i] * p ** (3 - i) for i in range(4)), sum(k[i] * p ** (4 - i) for i in range(5)), p)
    den = sp.factor(sp.denom(sp.together(I4)) / (-k[0]))
    _row("I4 denominator / (-k0)", "2 k4 (k1k2k3 - k0k3^2 - k1^2k4)", den, "book divides num/den by -k0")
    return {"I2": I2, "I2_spots": spots, "I3": I3, "I4": I4, "I4_den": den, "symbols": (a, b, k0, w, z, k, u)}


SECTIONS = {
    "1.18": section_1_18,
    "1.21": section_1_21,
    "1.22": section_1_22,
    "1.35": section_1_35,
    "1.36": section_1_36,
    "sylvester": section_sylvester,
    "2.19": section_2_19,
    "2.21": section_2_21,
    "2.32": section_2_32,
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--section", action="append", choices=sorted(SECTIONS), help="run only these sections")
    args = parser.parse_args(argv)
    for name in args.section or list(SECTIONS):
        SECTIONS[name]()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
