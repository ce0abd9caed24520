"""The methods Gribkov & Khokhlov (2015) compare with: Otterbein, Acheson, Chelomei (Kapitza averaging), Floquet.

Source: seed 000, introduction, Fig. 5 and research report seed-gribkov-khokhlov.md §5–§6.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import eigh

from symosc.errors import ParameterError
from symosc.models import gribkov_khokhlov_table1, n_link_pendulum
from symosc.periodic import compare_methods, mathieu_a, mathieu_b, stability_region
from symosc.periodic.comparison import ACHESON_BETA

G = 9.81
TABLE1 = gribkov_khokhlov_table1()  # Gribkov & Khokhlov 2015, Table 1, in SI units
_S: dict = {}


def system(n: int, links: str = "point"):
    if (n, links) not in _S:
        _S[(n, links)] = n_link_pendulum(n, links=links, inverted=True, pivot="vertical")
    return _S[(n, links)]


def test_chelomei_first_approximation_is_averaged_equations():
    """Kapitza/Chelomei first approximation: the averaged equations M phi'' + (-g C + a^2 p^2/2 C M^-1 C) phi = 0
    are stable iff the effective stiffness is positive definite - computed here directly from M and C."""
    vals = {"m1": 1.3, "m2": 0.6, "m3": 0.9, "l1": 0.8, "l2": 0.5, "l3": 0.35, "g": G}
    reg = stability_region(system(3), vals, method="chelomei")
    m, ll = [vals[f"m{i}"] for i in (1, 2, 3)], [vals[f"l{i}"] for i in (1, 2, 3)]
    M = np.array([[sum(m[max(i, j) :]) * ll[i] * ll[j] for j in range(3)] for i in range(3)])
    C = np.diag([sum(m[i:]) * ll[i] for i in range(3)])
    rng = np.random.default_rng(2)
    p = rng.uniform(20, 400, 40)
    amp = rng.uniform(1e-3, 0.2, 40)
    Minv = np.linalg.inv(M)
    ref = [
        eigh(-G * C + 0.5 * (x * w) ** 2 * C @ Minv @ C, M, eigvals_only=True).min() > 0
        for w, x in zip(p, amp, strict=True)
    ]
    assert np.array_equal(reg.is_stable(p, amp), ref)
    assert np.all(np.isinf(reg.upper([0.1, 1.0])))


def test_chelomei_single_pendulum_is_kapitza():
    reg = stability_region(system(1), {"m1": 1.0, "l1": 0.3, "g": G}, method="chelomei")
    amp = np.array([0.001, 0.01])
    kap = np.sqrt(2 * G * 0.3) / amp
    assert np.all(reg.is_stable(kap * 1.0001, amp)) and not np.any(reg.is_stable(kap * 0.9999, amp))
    pmin, pmax = reg.frequency_bounds(amp)
    assert np.allclose(pmin, kap, rtol=1e-12) and np.all(np.isinf(pmax))


def test_chelomei_second_approximation_closer_to_exact():
    vals = {"m1": 1.0, "l1": 0.3, "g": G}
    q = np.array([0.05, 0.2, 0.5])
    exact = mathieu_a(0, q)
    e1 = np.abs(stability_region(system(1), vals, method="chelomei", order=1).lower(q) - exact)
    e2 = np.abs(stability_region(system(1), vals, method="chelomei", order=2).lower(q) - exact)
    assert np.all(e2 < e1 / 10)
    # the order-2 boundary is -q^2/2 + 7 q^4/128 (seed 000 eq. (8), two terms)
    reg2 = stability_region(system(1), vals, method="chelomei", order=2)
    assert np.allclose(reg2.lower(q), -(q**2) / 2 + 7 * q**4 / 128, rtol=1e-14)
    amin, _ = reg2.amplitude_bounds(np.array([100.0]))
    a1, q1 = reg2.first_tone(100.0, amin)
    assert a1 == pytest.approx(float(reg2.lower(q1)[0]), rel=1e-12)
    with pytest.raises(ParameterError, match="order"):
        stability_region(system(1), vals, method="chelomei", order=3)


def test_otterbein_overestimates_table1_region():
    """Seed 000 §6 claim 3 (Fig. 5): the Otterbein upper boundary lies above the true one (it adds a
    non-existent sub-region on top), and its lower boundary -q^2/2 lies below a_0."""
    ott = stability_region(system(2, "rigid"), TABLE1, method="otterbein")
    mod = stability_region(system(2, "rigid"), TABLE1)
    q = np.linspace(0.02, 0.25, 12)
    rN = mod.ratios[-1]
    assert np.allclose(ott.upper(q), rN - q, rtol=1e-13)
    assert np.all(ott.upper(q) > mod.upper(q))
    assert np.all(ott.lower(q) < mod.lower(q))
    # a point the Otterbein region calls stable but the exact (and Floquet) analysis does not
    qx = 0.21
    ax = 0.5 * (mod.upper(qx) + ott.upper(qx))
    assert ott.contains(ax, qx) and not mod.contains(ax, qx)
    flo = stability_region(system(2, "rigid"), TABLE1, method="floquet")
    assert not flo.contains(ax, qx)


def test_acheson_reconstruction():
    """Acheson's theorem: q^1 > sqrt(-2 a^1) and q_N < 2 * 0.450.  As reconstructed, its upper bound lies slightly
    BELOW the exact one near a^1 = 0 (q_N = 0.900 vs the root 0.9081 of b_1), i.e. it does not enlarge the region
    there - the paper's Fig. 5 statement for Acheson is not reproduced (see docs/periodic-stability.md)."""
    ach = stability_region(system(2, "rigid"), TABLE1, method="acheson")
    mod = stability_region(system(2, "rigid"), TABLE1)
    rN = ach.ratios[-1]
    cap = 2 * ACHESON_BETA * rN
    assert ach.contains(-1e-4, 0.99 * cap) and not ach.contains(-1e-4, 1.01 * cap)
    q_b1_zero = 0.9080463337  # b_1(q) = 0 (checked below)
    assert abs(mathieu_b(1, q_b1_zero)) < 1e-9
    assert cap < q_b1_zero * rN
    p = np.array([300.0, 1000.0])
    amin_a, amax_a = ach.amplitude_bounds(p)
    amin_m, amax_m = mod.amplitude_bounds(p)
    assert np.all(amax_a < amax_m) and np.all(amin_a < amin_m)


def test_compare_methods_table_and_plot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cmp = compare_methods(system(2, "rigid"), TABLE1, q=np.array([0.05, 0.15]))
    assert set(cmp.regions) == {"modified-ince-strutt", "floquet", "otterbein", "acheson", "chelomei"}
    assert np.allclose(cmp.lower["floquet"], cmp.lower["modified-ince-strutt"], rtol=1e-9)
    text = cmp.table()
    assert "max |floquet - modified-ince-strutt|" in text
    assert "MethodComparison" in repr(cmp)
    ax = cmp.plot(a_range=(-0.03, 0.0))
    assert ax.get_xlim() == (-0.03, 0.0)
    plt.close("all")
