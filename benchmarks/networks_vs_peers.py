"""symosc.networks vs lcapy (symbolic) and scikit-rf (numeric) where they overlap.

Run ``python benchmarks/networks_vs_peers.py``.  Three tasks, each timed in one run on the same machine:

1. parameter conversions: symbolic A -> Z of a T section (lcapy ``TSection.Zparams``); numeric ABCD -> Z on
   1001 frequencies (scikit-rf ``a2z``) against symosc's symbolic conversion compiled once with lambdify;
2. cascades: chain matrix of n identical L-C sections, symbolic (lcapy ``chain``) and closed form
   (``chain_power``), and numerically at 1001 frequencies (scikit-rf ``cascade`` of ABCD via ``a2s``/``s2a``);
3. ladder impedance: input impedance of an n-element L-C ladder (n = 12, 40) (lcapy ``Z`` of nested Series/Par).

Agreement is reported as the largest relative difference.  lcapy and scikit-rf are benchmark-only dependencies.
"""

from __future__ import annotations

import time

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
    Z_fun = sp.lambdify(p, convert_parameters(A_expr, "A", "Z", "ieee").tolist(), "numpy")
    A_fun = sp.lambdify(p, A_expr.tolist(), "numpy")
    A_num = abcd(A_fun, w)
    t1, z_ours = timed(lambda: abcd(Z_fun, w))
    t2, z_skrf = timed(lambda: skrf.network.a2z(A_num))
    agree = float(np.max(np.abs(z_ours - z_skrf) / np.abs(z_skrf)))
    rows.append(("A->Z numeric, 1001 freqs", t1, "scikit-rf", t2, agree))

    # 2. cascade of n identical L-C sections, symbolic
    n = 8
    sec = cascade(series_element(p), shunt_element(1 / p))
    t1, A_ours = timed(lambda: chain_power(sec, n), repeat=1)
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

    # 2b. numeric cascade of 100 sections at 1001 frequencies
    m = 100
    S_one = skrf.network.a2s(abcd(sp.lambdify(p, sec.chain.tolist(), "numpy"), w))
    net_one = skrf.Network(frequency=skrf.Frequency.from_f(w / (2 * np.pi), unit="hz"), s=S_one, z0=50)
    closed = sp.lambdify((p, sp.Symbol("n")), chain_power(sec, sp.Symbol("n", integer=True, positive=True)), "mpmath")

    def skrf_cascade():
        out = net_one
        for _ in range(m - 1):
            out = out**net_one
        return skrf.network.s2a(out.s)

    t2, A_sk = timed(skrf_cascade, repeat=1)
    A_fun = sp.lambdify(p, sec.chain.tolist(), "numpy")
    t1, A_np = timed(lambda: np.linalg.matrix_power(abcd(A_fun, w), m))
    idx = [10, 500, 990]
    ref = [np.array(closed(1j * w[i], m).tolist(), dtype=complex) for i in idx]
    agree = max(float(np.max(np.abs(A_sk[i] - r) / np.max(np.abs(r)))) for i, r in zip(idx, ref, strict=True))
    agree_ours = max(float(np.max(np.abs(A_np[i] - r) / np.max(np.abs(r)))) for i, r in zip(idx, ref, strict=True))
    rows.append(
        (f"numeric cascade {m} sections x 1001 freqs (ABCD power)", t1, "scikit-rf", t2, max(agree, agree_ours))
    )

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
