"""symosc objects in the SymPy / python-control / scikit-rf ecosystem: cost and accuracy against the peer route.

Run ``PYTHONPATH=. python benchmarks/sympy_native.py`` (this checkout's symosc first on the path).  Three tasks,
each timed in one run on the same machine:

1. series arithmetic on the van der Pol frequency (exact, orders 24 and 48): ``omega * omega``, ``1/omega`` and
   ``sqrt(omega)`` as :class:`EpsSeries` against SymPy on the sympified series (``expand`` of the product with its
   order term; ``sympy.series`` of the quotient and the root of the truncated sum);
2. transfer functions of the hanging n-link pendulum (point masses, unit values, g = 9.81, n = 2, 3, 4), all inputs
   to all outputs: ``to_transfer_function()`` from the exact transfer matrix against python-control's ``ss2tf``
   of the same state space; reported: time, the largest relative coefficient error against the exact rational
   answer, and the number of coefficients that should be exactly zero but are not;
3. a ladder of n L-C sections (n = 4, 8) read from a netlist and solved by nodal analysis (``parse_netlist`` +
   ``Circuit.four_pole``) against the cascade of the same sections (``cascade``), with the agreement.
"""

from __future__ import annotations

import time
import warnings

import numpy as np
import sympy as sp


def timed(fn, repeat=3):
    best, out = np.inf, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def _series_tasks(w, order):
    eps = w.symbol
    W = sp.sympify(w)
    poly = w.removeO()
    return [
        ("omega*omega", lambda: w * w, lambda: sp.expand(W * W)),
        ("1/omega", lambda: 1 / w, lambda: sp.series(1 / poly, eps, 0, order + 1)),
        ("sqrt(omega)", lambda: w ** sp.Rational(1, 2), lambda: sp.series(sp.sqrt(poly), eps, 0, order + 1)),
    ]


def series_rows():
    from symosc.nonlinear import limit_cycle

    x, v = sp.symbols("x v")
    rows = []
    for order in (24, 48):
        w = limit_cycle((1 - x**2) * v, order).frequency
        for label, ours, theirs in _series_tasks(w, order):
            t_ours, a = timed(ours)
            t_theirs, b = timed(theirs, repeat=1)
            same = sp.sympify(a) == b
            rows.append((f"{label}, order {order}", t_ours, t_theirs, "identical" if same else "DIFFERENT"))
    return rows


def transfer_rows():
    import control as ct

    from symosc.models import n_link_pendulum

    rows = []
    for n in (2, 3, 4):
        lin = n_link_pendulum(n).linearize()
        values = {"g": 9.81, **{f"m{i}": 1 for i in range(1, n + 1)}, **{f"l{i}": 1 for i in range(1, n + 1)}}
        exact = lin.transfer_function(values={k: sp.Rational(str(v)) for k, v in values.items()})
        t_ours, H = timed(lambda lin=lin, values=values: lin.to_transfer_function(values=values))
        sys_ = lin.to_state_space(values=values)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            t_theirs, G = timed(lambda sys_=sys_: ct.ss2tf(sys_))
        spurious = {"symosc": 0, "ss2tf": 0}
        worst = {"symosc": 0.0, "ss2tf": 0.0}
        s = sp.Symbol("s")
        for i in range(n):
            for j in range(n):
                num, den = sp.fraction(sp.cancel(exact[i, j]))
                lead = sp.Poly(den, s).LC()
                want = [float(c / lead) for c in sp.Poly(num, s).all_coeffs()]
                want_d = [float(c / lead) for c in sp.Poly(den, s).all_coeffs()]
                for name, tf in (("symosc", H), ("ss2tf", G)):
                    got_n = np.trim_zeros(np.asarray(tf.num[i][j], dtype=float), "f")
                    got_d = np.asarray(tf.den[i][j], dtype=float) / tf.den[i][j][0]
                    got_n = got_n / tf.den[i][j][0]
                    got_n = np.concatenate([np.zeros(max(0, len(want) - len(got_n))), got_n])[-max(len(want), 1) :]
                    full_n = np.concatenate([np.zeros(max(0, len(got_n) - len(want))), want])
                    for got, ref in ((got_n, full_n), (got_d, np.array(want_d))):
                        scale = np.max(np.abs(ref))
                        for g_, r_ in zip(got, ref, strict=False):
                            if r_ == 0:
                                spurious[name] += g_ != 0
                            else:
                                worst[name] = max(worst[name], abs(g_ - r_) / scale)
        rows.append((n, t_ours, t_theirs, worst, spurious, len(caught)))
    return rows


def ladder_rows():
    from symosc.networks import cascade, parse_netlist, series_element, shunt_element

    p = sp.Symbol("p")
    rows = []
    for n in (4, 8):
        lines = ["P1 n0 0"]
        for k in range(n):
            lines += [f"L{k} n{k} n{k + 1} {k + 1}m", f"C{k} n{k + 1} 0 {k + 2}u"]
        lines.append(f"P2 n{n} 0")
        text = "\n".join(lines)
        t_ours, fp = timed(lambda text=text: parse_netlist(text).four_pole(), repeat=1)
        sections = []
        for k in range(n):
            sections += [
                series_element(p * sp.Rational(k + 1, 1000)),
                shunt_element(1 / (p * sp.Rational(k + 2, 10**6))),
            ]
        t_ref, ref = timed(lambda sections=sections: cascade(*sections), repeat=1)
        same = (fp.chain - ref.chain).applyfunc(sp.cancel) == sp.zeros(2, 2)
        rows.append((n, t_ours, t_ref, "identical" if same else "DIFFERENT"))
    return rows


def main() -> None:
    print("1. series arithmetic, van der Pol frequency (exact)")
    print(f"{'operation':<24}{'symosc [ms]':>14}{'SymPy [ms]':>14}{'ratio':>9}  result")
    for label, a, b, same in series_rows():
        print(f"{label:<24}{1e3 * a:>14.2f}{1e3 * b:>14.1f}{b / a:>9.0f}  {same}")
    print()
    print("2. transfer functions of the hanging n-link pendulum, all inputs to all outputs")
    print(
        f"{'n':>3}{'symosc [ms]':>13}{'ss2tf [ms]':>12}{'max rel err symosc':>20}{'ss2tf':>10}"
        f"{'spurious symosc':>17}{'ss2tf':>7}{'warnings (ss2tf)':>18}"
    )
    for n, a, b, worst, spurious, caught in transfer_rows():
        print(
            f"{n:>3}{1e3 * a:>13.1f}{1e3 * b:>12.1f}{worst['symosc']:>20.1e}{worst['ss2tf']:>10.1e}"
            f"{spurious['symosc']:>17}{spurious['ss2tf']:>7}{caught:>18}"
        )
    print()
    print("3. L-C ladder: netlist + nodal analysis vs cascade of sections")
    print(f"{'sections':>9}{'netlist [ms]':>14}{'cascade [ms]':>14}  chain matrices")
    for n, a, b, same in ladder_rows():
        print(f"{n:>9}{1e3 * a:>14.1f}{1e3 * b:>14.1f}  {same}")


if __name__ == "__main__":
    main()
