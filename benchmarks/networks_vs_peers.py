"""symosc.networks vs lcapy (symbolic) and scikit-rf (numeric) where they overlap.

Run ``python benchmarks/networks_vs_peers.py``.  Three tasks, each timed in one run on the same machine:

1. parameter conversions: symbolic A -> Z of a T section (lcapy ``TSection.Zparams``); numeric ABCD -> Z on
   1001 frequencies (scikit-rf ``a2z``) against symosc's symbolic conversion compiled once by
   ``symosc.numeric.compile`` (the call is timed);
2. cascades: exact chain matrix of n identical L-C sections (lcapy ``chain``), by ``chain_power`` and by
   ``cascade``; and 100 sections at 1001 frequencies, numerically: symosc ``cascade(...).evaluate_numeric`` and
   ``chain_power(...).evaluate_numeric`` (products of the sections' numeric chain matrices) against scikit-rf's
   ``cascade`` of S-parameter networks (``Network ** Network``, ABCD via ``a2s``/``s2a``), both timed from the
   section's symbolic chain matrix (symosc: first call, which compiles the section, and warm; scikit-rf: the
   evaluated section wrapped in a ``Network``), and both checked against a 50-digit mpmath product;
3. ladder impedance: input impedance of an n-element L-C ladder (n = 12, 40) (lcapy ``Z`` of nested Series/Par).

Agreement is reported as the largest relative difference (numeric cascades: normwise error against the 50-digit
product, largest over 41 frequencies from 0.1 to 10 rad/s, cut-off 2 rad/s).  lcapy and scikit-rf are
benchmark-only dependencies.
"""

from __future__ import annotations

import time

import mpmath
import numpy as np
import sympy as sp

from symosc.networks import (
    Capacitor,
    Inductor,
    cascade,
    chain_power,
    convert_parameters,
    series_element,
    shunt_element,
    t_section,
)
from symosc.numeric import compile as compile_numeric

p = sp.Symbol("p")


def abcd(fun, w):
    """Evaluate a lambdified 2x2 matrix on a frequency grid, broadcasting constant entries: shape (len(w), 2, 2)."""
    M = fun(1j * w)
    out = np.array([[np.broadcast_to(np.asarray(e, dtype=complex), w.shape) for e in row] for row in M])
    return np.moveaxis(out, -1, 0)


def timed(fn, repeat=3):
    best, out = np.inf, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def main() -> None:
    import lcapy
    import skrf

    s = lcapy.s
    rows = []

    # 1. symbolic conversion A -> Z (IEEE convention) of a T section
    def ours_conv():
        return convert_parameters(t_section(1 + 2 * p, 1 / (3 * p), 4).chain, "A", "Z", "ieee")

    def lcapy_conv():
        return lcapy.TSection(lcapy.R(1) + lcapy.L(2), lcapy.C(3), lcapy.R(4)).Zparams

    t1, z1 = timed(ours_conv)
    t2, z2 = timed(lcapy_conv)
    z2s = sp.Matrix(z2.sympy if hasattr(z2, "sympy") else z2).subs(sp.Symbol("s"), p)
    z2s = sp.Matrix(2, 2, [sp.sympify(str(e)).subs(sp.Symbol("s"), p) for e in z2])
    agree = max(abs(complex((z1[i] - z2s[i]).subs(p, 0.3 + 1.7j))) for i in range(4))
    rows.append(("A->Z symbolic, T section", t1, "lcapy", t2, agree))

    # 1b. numeric conversion on 1001 frequencies
    w = np.linspace(0.1, 10, 1001)
    A_expr = t_section(1 + 2 * p, 1 / (3 * p), 4).chain
    Z_fun = compile_numeric(convert_parameters(A_expr, "A", "Z", "ieee"), [p])  # symosc.numeric, compiled once
    A_fun = sp.lambdify(p, A_expr.tolist(), "numpy")
    A_num = abcd(A_fun, w)
    t1, z_ours = timed(lambda: Z_fun(1j * w))
    t2, z_skrf = timed(lambda: skrf.network.a2z(A_num))
    agree = float(np.max(np.abs(z_ours - z_skrf) / np.abs(z_skrf)))
    rows.append(("A->Z numeric, 1001 freqs", t1, "scikit-rf", t2, agree))

    # 2. cascade of n identical L-C sections, symbolic
    n = 8
    sec = cascade(series_element(p), shunt_element(1 / p))
    t1, A_ours = timed(lambda: chain_power(sec, n).chain, repeat=1)
    t1b, _ = timed(lambda: cascade(*[sec] * n).chain, repeat=1)

    def lcapy_chain():
        one = lcapy.Series(lcapy.L(1)).chain(lcapy.Shunt(lcapy.C(1)))
        out = one
        for _ in range(n - 1):
            out = out.chain(one)
        return out.Aparams

    t2, A_l = timed(lcapy_chain, repeat=1)
    A_ls = sp.Matrix(2, 2, [sp.sympify(str(e)).subs(sp.Symbol("s"), p) for e in A_l])
    agree = max(
        abs(complex((A_ours[i] - A_ls[i]).subs(p, 0.2 + 0.9j))) / abs(complex(A_ls[i].subs(p, 0.2 + 0.9j)))
        for i in range(4)
    )
    rows.append((f"cascade of {n} L-C sections (chain_power)", t1, "lcapy", t2, agree))
    rows.append((f"cascade of {n} L-C sections (product)", t1b, "lcapy", t2, agree))

    # 2b. numeric cascade of 100 sections at 1001 frequencies (symosc code in the symosc column)
    m = 100
    idx = range(0, 1001, 25)
    with mpmath.workdps(50):
        refs = {}
        for i in idx:
            z = mpmath.mpc(0, w[i])
            S = mpmath.matrix([[1, z], [0, 1]]) * mpmath.matrix([[1, 0], [z, 1]])
            R = mpmath.eye(2)
            for _ in range(m):
                R = R * S
            refs[i] = np.array(R.tolist(), dtype=complex)

    def error(A):
        """Largest normwise relative error over the reference frequencies (pass band w < 2 and stop band)."""
        return max(float(np.max(np.abs(A[i] - r)) / np.max(np.abs(r))) for i, r in refs.items())

    def skrf_cascade():
        A_one = abcd(sp.lambdify(p, sec.chain.tolist(), "numpy"), w)
        net_one = skrf.Network(frequency=skrf.Frequency.from_f(w / (2 * np.pi), unit="hz"), s=skrf.network.a2s(A_one))
        out = net_one
        for _ in range(m - 1):
            out = out**net_one
        return skrf.network.s2a(out.s)

    def fresh_section():
        return cascade(series_element(p), shunt_element(1 / p))

    t2, A_sk = timed(skrf_cascade)
    err_sk = error(A_sk)
    t_cold, A_c = timed(lambda: cascade(*[fresh_section()] * m).evaluate_numeric(w))
    t_warm, A_w = timed(lambda: cascade(*[sec] * m).evaluate_numeric(w))
    rows.append((f"numeric cascade({m} sections) x 1001 freqs, first call", t_cold, "scikit-rf", t2, error(A_c)))
    rows.append((f"numeric cascade({m} sections) x 1001 freqs, warm", t_warm, "scikit-rf", t2, error(A_w)))
    t_cold, A_c = timed(lambda: chain_power(fresh_section(), m).evaluate_numeric(w))
    t_warm, A_w = timed(lambda: chain_power(sec, m).evaluate_numeric(w))
    rows.append((f"numeric chain_power(section, {m}) x 1001, first call", t_cold, "scikit-rf", t2, error(A_c)))
    rows.append((f"numeric chain_power(section, {m}) x 1001, warm", t_warm, "scikit-rf", t2, error(A_w)))
    # what the expanded exact chain gives in floating point (the reason the product is evaluated)
    expanded = sp.lambdify(p, chain_power(sec, m).chain.tolist(), "numpy")
    t_exp, A_e = timed(lambda: abcd(expanded, w), repeat=1)
    rows.append((f"lambdify of the expanded {m}-section chain", t_exp, "scikit-rf", t2, error(A_e)))
    print(f"scikit-rf error against the 50-digit product: {err_sk:.1e}")

    # 3. ladder input impedance, 12 and 40 elements
    for k in (12, 40):

        def ours_ladder(k=k):
            net = None
            for i in reversed(range(k)):
                e = Inductor(i + 1) if i % 2 == 0 else Capacitor(i + 1)
                net = e if net is None else ((e + net) if i % 2 == 0 else (e | net))
            return net.impedance(p)

        def lcapy_ladder(k=k):
            net = None
            for i in reversed(range(k)):
                e = lcapy.L(i + 1) if i % 2 == 0 else lcapy.C(i + 1)
                net = e if net is None else ((e + net) if i % 2 == 0 else (e | net))
            return net.Z

        t1, Z1 = timed(ours_ladder, repeat=1)
        t2, Z2 = timed(lcapy_ladder, repeat=1)
        Z2s = sp.sympify(str(Z2)).subs(sp.Symbol("s"), p)
        agree = abs(complex((Z1 - Z2s).subs(p, 0.3 + 1.1j))) / abs(complex(Z2s.subs(p, 0.3 + 1.1j)))
        rows.append((f"ladder impedance, {k} elements", t1, "lcapy", t2, agree))

    print(f"{'task':58s} | {'symosc [s]':>10s} | {'peer':9s} | {'peer [s]':>9s} | {'peer/symosc':>11s} | agreement")
    for task, a, peer, b, agree in rows:
        print(f"{task:58s} | {a:10.4f} | {peer:9s} | {b:9.4f} | {b / a:11.2f} | {agree:.1e}")
    del s


if __name__ == "__main__":
    main()
