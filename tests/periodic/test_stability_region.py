"""Classic/modified Ince–Strutt diagrams and the stability region of inverted N-link pendulums.

Source: Gribkov & Khokhlov 2015 (seed 000; research report seed-gribkov-khokhlov.md §2–§4, §6).
The reference for the modified diagram is always an independent computation: the Floquet multipliers of the
full coupled 2N-dimensional system (no modal decomposition), or direct numerical integration in the test.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp
from scipy.linalg import eigh

from symosc.errors import ModelError, ParameterError
from symosc.mechanics import LinearModel
from symosc.models import gribkov_khokhlov_table1, n_link_pendulum
from symosc.periodic import (
    ince_strutt_diagram,
    mathieu_a,
    mathieu_b,
    mathieu_stable,
    modified_ince_strutt,
    stability_region,
)
from symosc.symbols import t

G = 9.81
TABLE1 = gribkov_khokhlov_table1()  # Gribkov & Khokhlov 2015, Table 1, in SI units

_SYSTEMS: dict = {}


def pendulum(n: int, links: str, inverted: bool = True, pivot: str = "vertical"):
    key = (n, links, inverted, pivot)
    if key not in _SYSTEMS:
        _SYSTEMS[key] = n_link_pendulum(n, links=links, inverted=inverted, pivot=pivot)
    return _SYSTEMS[key]


def random_values(n: int, links: str, seed: int) -> dict:
    rng = np.random.default_rng(seed)
    vals = {"g": G}
    for i in range(1, n + 1):
        m, ll = rng.uniform(0.5, 2.0), rng.uniform(0.3, 1.5)
        vals[f"m{i}"], vals[f"l{i}"] = m, ll
        if links == "rigid":
            vals[f"lc{i}"] = ll * rng.uniform(0.3, 0.7)
            vals[f"I{i}"] = m * ll**2 * rng.uniform(0.02, 0.1)
    return vals


def scalar_mathieu_stable(a: float, q: float) -> bool:
    """Independent: Floquet multipliers of y'' + (a - 2q cos 2x) y = 0 by direct integration (test-local)."""
    sol = solve_ivp(
        lambda x, y: [y[1], -(a - 2 * q * np.cos(2 * x)) * y[0], y[3], -(a - 2 * q * np.cos(2 * x)) * y[2]],
        (0, np.pi),
        [1.0, 0.0, 0.0, 1.0],
        method="DOP853",
        rtol=1e-12,
        atol=1e-14,
    )
    return abs(sol.y[0, -1] + sol.y[3, -1]) < 2.0


# ------------------------------------------------------------------ classic diagram
def test_classic_diagram_classification_against_direct_integration():
    """Seed 000 §2 (Fig. 1): stable iff a_n(q) < a < b_{n+1}(q); checked against direct Floquet integration."""
    rng = np.random.default_rng(7)
    a = rng.uniform(-2, 14, 40)
    q = rng.uniform(0, 6, 40)
    got = mathieu_stable(a, q)
    for ai, qi, gi in zip(a, q, got, strict=True):
        assert gi == scalar_mathieu_stable(ai, qi), (ai, qi)
    assert np.array_equal(mathieu_stable(a, -q), got)  # even in q


def test_classic_diagram_curves_and_ordering():
    d = ince_strutt_diagram(n_max=3, q_max=8.0, num=41)
    assert d.n_max == 3
    q = d.q[1:]
    chain = [d.a_curves[0], d.b_curves[1], d.a_curves[1], d.b_curves[2], d.a_curves[2], d.b_curves[3]]
    for lo, hi in itertools.pairwise(chain):
        assert np.all(lo[1:] < hi[1:])
    assert np.allclose(d.a_curves[2][0], 4.0) and np.allclose(d.b_curves[3][0], 9.0)
    assert d.is_stable(-0.1, 0.5) and not d.is_stable(1.0, 0.5)
    assert "InceStruttDiagram" in repr(d)
    assert q.size == 40


# ------------------------------------------------------------------ single pendulum
def test_single_inverted_pendulum_reduces_to_a0_b1():
    """Seed 000 §2: a single inverted pendulum is stable iff a_0(q) < a < b_1(q), a = -4 g/(l p^2), q = 2a*/l."""
    vals = {"m1": 0.7, "l1": 0.4, "g": G}
    reg = stability_region(pendulum(1, "point"), vals)
    p1 = np.sqrt(G / 0.4)
    assert reg.natural_frequencies[0] == pytest.approx(p1, rel=1e-14)
    a1, q1 = reg.first_tone(p=[20.0, 80.0], a=[0.01, 0.05])
    assert np.allclose(a1, -4 * G / (0.4 * np.array([20.0, 80.0]) ** 2), rtol=1e-14)
    assert np.allclose(q1, 2 * np.array([0.01, 0.05]) / 0.4, rtol=1e-14)
    q = np.linspace(0.01, 2.0, 9)
    assert np.allclose(reg.lower(q), mathieu_a(0, q), rtol=1e-14)
    assert np.allclose(reg.upper(q), mathieu_b(1, q), rtol=1e-14)
    rng = np.random.default_rng(3)
    p = rng.uniform(5, 200, 30)
    amp = rng.uniform(0.001, 0.3, 30)
    got = reg.is_stable(p, amp)
    a1, q1 = reg.first_tone(p, amp)
    for k in range(30):
        assert got[k] == scalar_mathieu_stable(a1[k], q1[k])


@pytest.mark.parametrize("links", ["point", "rigid"])
def test_kapitza_limit(links):
    """Small amplitude: the minimum stabilising frequency tends to Kapitza's a p = sqrt(2 g l_red)."""
    vals = {"m1": 1.0, "l1": 0.5, "lc1": 0.2, "I1": 0.01, "g": G}
    reg = stability_region(pendulum(1, links), vals)
    l_red = 0.5 if links == "point" else (0.01 + 1.0 * 0.2**2) / (1.0 * 0.2)
    amp = np.array([1e-4, 1e-3]) * l_red
    pmin, pmax = reg.frequency_bounds(amp)
    kapitza = np.sqrt(2 * G * l_red) / amp
    q = 2 * amp / l_red
    assert np.allclose(pmin / kapitza - 1, 0, atol=1e-6)
    assert np.all(np.abs(pmin / kapitza - 1) < q**2)  # next correction is O(q^2) = 7 q^2 / 128
    assert np.all(np.isinf(pmax))  # upper boundary b_1 > 0 at small q: no upper frequency limit
    assert np.all(reg.is_stable(1.001 * kapitza, amp)) and not np.any(reg.is_stable(0.999 * kapitza, amp))


# ------------------------------------------------------------------ Table 1
def test_table1_natural_frequencies_recomputed():
    """Seed 000 §4, Table 1: the paper prints 2.289 / 5.094 Hz and r = 0.2019; the standard model with Table 1
    gives 2.3276 / 5.0460 Hz and r = 0.2128 (research report §4 [C]) - tested against the recomputed values."""
    v = TABLE1
    M = np.array(
        [
            [v["I1"] + v["m1"] * v["lc1"] ** 2 + v["m2"] * v["l1"] ** 2, v["m2"] * v["l1"] * v["lc2"]],
            [v["m2"] * v["l1"] * v["lc2"], v["I2"] + v["m2"] * v["lc2"] ** 2],
        ]
    )
    C = np.diag([(v["m1"] * v["lc1"] + v["m2"] * v["l1"]) * G, v["m2"] * v["lc2"] * G])
    ref = np.sqrt(eigh(C, M, eigvals_only=True))
    reg = stability_region(pendulum(2, "rigid"), TABLE1)
    assert np.allclose(reg.natural_frequencies, ref, rtol=1e-12)
    assert np.allclose(reg.natural_frequencies / (2 * np.pi), [2.3276, 5.0460], atol=5e-5)
    assert reg.ratios[1] == pytest.approx(0.2128, abs=5e-5)
    assert abs(reg.ratios[1] - 0.2019) > 0.01  # the printed ratio is not reproduced by Table 1


def test_table1_modified_equals_floquet():
    """Seed 000 §6 claim 1: the modified diagram coincides with Floquet (to numerical precision)."""
    mod = stability_region(pendulum(2, "rigid"), TABLE1)
    flo = stability_region(pendulum(2, "rigid"), TABLE1, method="floquet")
    q = np.array([0.05, 0.15, 0.2])
    assert np.allclose(flo.lower(q), mod.lower(q), rtol=1e-9, atol=0)
    assert np.allclose(flo.upper(q), mod.upper(q), rtol=1e-9, atol=0)
    p = np.array([150.0, 250.0])  # at 150 rad/s the region is empty (a^1 = -0.038, it closes near -0.022)
    lo_m, hi_m = mod.amplitude_bounds(p)
    lo_f, hi_f = flo.amplitude_bounds(p)
    assert np.isnan(lo_m[0]) and np.isnan(hi_m[0])
    assert np.allclose(lo_f, lo_m, rtol=1e-8, equal_nan=True) and np.allclose(hi_f, hi_m, rtol=1e-8, equal_nan=True)


# ------------------------------------------------------------------ random 2- and 3-link pendulums
CASES = [(2, "point", 11), (2, "rigid", 12), (3, "point", 13), (3, "rigid", 14)]


@pytest.mark.parametrize(("n", "links", "seed"), CASES)
def test_random_pendulums_modified_vs_floquet(n, links, seed):
    """Modified diagram vs Floquet of the full coupled system: boundaries to 1e-6 relative, and the same
    classification at random (p, a) points farther than 1e-6 from every boundary curve."""
    vals = random_values(n, links, seed)
    sysn = pendulum(n, links)
    mod = stability_region(sysn, vals)
    flo = stability_region(sysn, vals, method="floquet")
    rN = mod.ratios[-1]
    q0 = 0.9 * rN  # upper boundary crosses a = 0 near here
    qg = np.linspace(0.01, 3, 3000) * q0
    q_close = qg[np.argmax(mod.lower(qg) >= mod.upper(qg))]  # the principal region closes here
    qs = np.array([0.2, 0.6, 0.97]) * q_close
    assert np.allclose(flo.lower(qs), mod.lower(qs), rtol=1e-6, atol=0)
    assert np.allclose(flo.upper(qs), mod.upper(qs), rtol=1e-6, atol=0)

    rng = np.random.default_rng(seed + 100)
    q1 = rng.uniform(0.05, 1.3, 14) * q0
    lo, hi = mod.lower(q1), mod.upper(q1)
    a1 = rng.uniform(2.0 * lo - 0.01 * rN, np.minimum(hi + 0.3 * rN, -1e-4))
    a1 = np.minimum(a1, -1e-4)
    # keep only points farther than 1e-6 from every boundary curve of every mode
    d = np.full(a1.shape, np.inf)
    for mode in range(1, n + 1):
        for kind, orders in (("a", range(0, 3)), ("b", range(1, 4))):
            for k in orders:
                d = np.minimum(d, np.abs(a1 - mod.diagram.curve(kind, k, mode, q1)))
    keep = d > 1e-6
    p1 = mod.natural_frequencies[0]
    p = 2 * p1 / np.sqrt(-a1[keep])
    amp = q1[keep] * G / (2 * p1**2)
    got_mod = mod.is_stable(p, amp)
    got_flo = flo.is_stable(p, amp)
    assert np.array_equal(got_mod, got_flo)
    assert got_mod.any() and not got_mod.all()


def test_only_two_curves_needed():
    """Seed 000 §3: the lower boundary is always mode 1's a_0 curve, the upper one mode N's b_1 curve."""
    q = np.linspace(0.001, 5.0, 300)
    for ratios in ([1.0], [0.7], [0.2019], [0.05], [0.5, 0.1, 0.02]):
        d = modified_ince_strutt(ratios)
        assert np.all(d.lower_mode(q) == 1)
        assert np.all(d.upper_mode(q) == len(d.ratios))


def test_dimensional_bounds_consistent_with_is_stable():
    reg = stability_region(pendulum(2, "point"), random_values(2, "point", 5))
    p = np.array([60.0, 120.0, 240.0])
    amin, amax = reg.amplitude_bounds(p)
    assert np.all(amin < amax)
    assert np.all(reg.is_stable(p, amin * (1 + 1e-7))) and not np.any(reg.is_stable(p, amin * (1 - 1e-7)))
    assert np.all(reg.is_stable(p, amax * (1 - 1e-7))) and not np.any(reg.is_stable(p, amax * (1 + 1e-7)))
    assert np.allclose(reg.lower_dimensional(p), amin) and np.allclose(reg.upper_dimensional(p), amax)
    a = np.array([0.5, 1.0]) * amin[-1]
    pmin, _ = reg.frequency_bounds(a)
    assert np.all(reg.is_stable(pmin * (1 + 1e-7), a)) and not np.any(reg.is_stable(pmin * (1 - 1e-7), a))


# ------------------------------------------------------------------ series boundaries (Fig. 4)
def test_series_boundaries_fig4():
    """Seed 000 §6 claim 2 (Fig. 4): the lower boundary hardly depends on the number of terms of (8), the upper
    one does on the terms of (9).  Quantified up to the point where the region closes."""
    for r in (1.0, 0.7, 0.2019, 0.2, 0.05):
        exact = modified_ince_strutt(r)
        q = np.linspace(1e-3, 1.5 * r, 600)
        lo, up = exact.lower(q), exact.upper(q)
        qc = q[np.argmax(lo >= up)] if np.any(lo >= up) else q[-1]
        qq = np.linspace(1e-3, qc, 300)
        el = [np.max(np.abs(modified_ince_strutt(r, lower_terms=k).lower(qq) - exact.lower(qq))) for k in (1, 2, 3, 4)]
        eu = [np.max(np.abs(modified_ince_strutt(r, upper_terms=k).upper(qq) - exact.upper(qq))) for k in (2, 3, 5)]
        assert el == sorted(el, reverse=True) and eu == sorted(eu, reverse=True)
        if r <= 0.2019:
            assert el[0] < 1e-4 and eu[0] > 100 * el[0]


# ------------------------------------------------------------------ bad input
def test_bad_input():
    vals = {"m1": 1.0, "l1": 1.0, "g": G}
    with pytest.raises(ModelError, match="no pivot excitation"):
        stability_region(pendulum(1, "point", pivot="fixed"), vals)
    with pytest.raises(ModelError, match="statically unstable"):
        stability_region(pendulum(1, "point", inverted=False), vals)
    with pytest.raises(ParameterError, match="unknown method"):
        stability_region(pendulum(1, "point"), vals, method="magic")
    with pytest.raises(ParameterError, match="missing values for: g"):
        stability_region(pendulum(1, "point"), {"m1": 1.0, "l1": 1.0})
    with pytest.raises(ModelError, match="LagrangianSystem or a LinearModel"):
        stability_region(np.eye(2), vals)
    with pytest.raises(ParameterError, match="ratios"):
        modified_ince_strutt([0.5, 1.5])
    with pytest.raises(ParameterError, match="lower_terms"):
        modified_ince_strutt(0.5, lower_terms=0)
    with pytest.raises(ParameterError, match="finite"):
        mathieu_stable(0.0, np.inf)
    reg = stability_region(pendulum(1, "point"), vals)
    with pytest.raises(ParameterError, match="positive"):
        reg.is_stable(-1.0, 0.1)
    with pytest.raises(ParameterError, match="coords"):
        reg.plot(coords="polar")


def test_not_proportional_and_damped_models_rejected():
    x, y, g, a, p, c = sp.symbols("x y g a p c", positive=True)
    M = sp.eye(2)
    K0 = sp.Matrix([[-g, 0], [0, -2 * g]])
    K1 = a * p**2 * sp.eye(2)  # pivot acceleration does not multiply the gravity matrix
    lin = LinearModel(M=M, D=sp.zeros(2), K=K0 + K1 * sp.cos(p * t), f=sp.zeros(2, 1), coordinates=(x, y))
    with pytest.raises(ModelError, match="same matrix"):
        stability_region(lin, {"g": G})
    ok = LinearModel(
        M=M, D=sp.zeros(2), K=K0 * (1 - a * p**2 / g * sp.cos(p * t)), f=sp.zeros(2, 1), coordinates=(x, y)
    )
    reg = stability_region(ok, {"g": G})
    assert np.allclose(reg.ratios, [1.0, 0.5])
    damped = LinearModel(M=M, D=c * sp.eye(2), K=ok.K, f=sp.zeros(2, 1), coordinates=(x, y))
    with pytest.raises(ModelError, match="damping"):
        stability_region(damped, {"g": G, "c": 0.1})


def test_plots_and_reprs():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    reg = stability_region(pendulum(2, "rigid"), TABLE1)
    assert "modified-ince-strutt" in repr(reg) and "a_0" in reg._repr_latex_()
    reg.plot()
    reg.plot(coords="dimensional", num=20)
    modified_ince_strutt(0.7).plot(n_max=3, q_max=2.0, num=40)
    ince_strutt_diagram(n_max=2, q_max=3.0, num=21).plot()
    assert "0.7" in repr(modified_ince_strutt(0.7))
    plt.close("all")


def test_large_q_higher_bands_against_floquet():
    """Extreme: at large q the second stability band a_1(q) < a < b_2(q) lies at a < 0, i.e. an inverted pendulum
    is also stabilised there.  The exact band test must agree with Floquet of the same system; the principal
    region a_0 < a < b_1 misses these points."""
    vals = {"m1": 1.0, "l1": 0.5, "g": G}
    mod = stability_region(pendulum(1, "point"), vals)
    flo = stability_region(pendulum(1, "point"), vals, method="floquet")
    rng = np.random.default_rng(4)
    q1 = rng.uniform(8.0, 14.0, 30)
    lo, hi = mathieu_a(1, q1), mathieu_b(2, q1)  # the band is thin (~1e-2): sample around it
    a1 = rng.uniform(lo - 0.3 * (hi - lo), hi + 0.3 * (hi - lo))
    assert np.all(a1 < 0)
    d = np.minimum(np.abs(a1 - mathieu_a(1, q1)), np.abs(a1 - mathieu_b(2, q1)))
    keep = d > 1e-6
    got = mod.contains(a1[keep], q1[keep])
    assert np.array_equal(got, flo.contains(a1[keep], q1[keep]))
    assert got.sum() >= 5 and not got.all()
    assert not np.any(mod.diagram.is_stable(a1[keep], q1[keep], principal=True))


def test_long_chain_boundaries():
    """Extreme: a 6-link chain (r_N ~ 0.02): two Mathieu curves vs Floquet of the 12-dimensional system."""
    vals = random_values(6, "point", 31)
    mod = stability_region(pendulum(6, "point"), vals)
    flo = stability_region(pendulum(6, "point"), vals, method="floquet")
    q = np.array([0.5]) * mod.ratios[-1]
    assert np.allclose(flo.lower(q), mod.lower(q), rtol=1e-6, atol=0)
    assert np.allclose(flo.upper(q), mod.upper(q), rtol=1e-6, atol=0)


@settings(max_examples=25, deadline=None)
@given(st.floats(0.01, 1.0), st.floats(0.0, 10.0))
def test_property_scaled_curves_monotone_in_ratio(r, q):
    """The reason two curves suffice (seed 000 §3): r a_0(q/r) and r b_1(q/r) increase with r (concavity of the
    lowest eigenvalues a_0, b_1 in q), so mode 1 gives the highest a_0 curve and mode N the lowest b_1 curve."""
    assert r * mathieu_a(0, q / r) <= mathieu_a(0, q) + 1e-12 * (1 + abs(q))
    assert r * mathieu_b(1, q / r) <= mathieu_b(1, q) + 1e-12 * (1 + abs(q))


def test_scalar_point_gives_a_scalar_verdict():
    """A scalar (a, q) gives a scalar answer, as NumPy ufuncs do; for one mode (ratio 1) it is the Mathieu chart:
    at q = 0.1, a0 = -0.0050, b1 = 0.8988, a1 = 1.0987 (DLMF 28.6), so a = 0.5 is stable and a = 1.0 is not."""
    d = modified_ince_strutt([1.0])
    inside, outside = d.is_stable(0.5, 0.1), d.is_stable(1.0, 0.1)
    assert not isinstance(inside, np.ndarray) and not isinstance(outside, np.ndarray)  # a NumPy bool, not array(True)
    assert bool(inside) and not bool(outside)
    assert d.is_stable(np.array([0.5, 1.0]), 0.1).tolist() == [True, False]
