"""Series against numerically integrated limit cycles (the accuracy targets of the series methods)."""

from __future__ import annotations

import math

import matplotlib
import pytest
import sympy as sp

from symosc.errors import ConvergenceError
from symosc.nonlinear import limit_cycle, numeric_limit_cycle, numeric_period

matplotlib.use("Agg")

x, v = sp.symbols("x v")
VDP = (1 - x**2) * v


@pytest.fixture(scope="module")
def vdp24():
    return limit_cycle(VDP, 24)


def test_numeric_cycle_matches_report_numbers():
    """Report part 2 §3 item 10 (Radau, rtol 1e-10): mu = 0.1: (2.00010, 6.28711); mu = 1: (2.00862, 6.66329)."""
    c = numeric_limit_cycle(VDP, 0.1)
    assert abs(c.amplitude - 2.00010) < 1e-5 and abs(c.period - 6.28711) < 1e-5
    c = numeric_limit_cycle(VDP, 1.0)
    assert abs(c.amplitude - 2.00862) < 1e-5 and abs(c.period - 6.66329) < 1e-5
    assert c.residual < 1e-12 and not c.stiff


def test_truncation_table_eps_01_05_1(vdp24):
    """Errors fall with the order as the next terms predict, at eps = 0.1, 0.5, 1 (all inside the radius ~1.85)."""
    val = vdp24.validate([0.1, 0.5, 1.0], orders=[2, 4, 8, 16, 24])
    assert 1.7 < val.radius < 2.0
    floor = 1e-11  # accuracy of the DOP853 reference at rtol 1e-12
    for r in val.rows:
        assert r["in_validity"]
        # the error of the order-N truncation is of the size of the first omitted terms (a few times the last one)
        assert r["frequency_error"] < 5 * r["last_term"] + floor
    by = {(r["eps"], r["order"]): r for r in val.rows}
    assert by[(1.0, 24)]["frequency_error"] < 1e-9
    assert by[(1.0, 24)]["amplitude_error"] < 1e-9
    assert by[(0.5, 16)]["frequency_error"] < 1e-11
    assert by[(1.0, 2)]["frequency_error"] > 1e-3  # the book's 2nd-order period: 2e-3 error at mu = 1
    assert "eps" in val.table()


def test_floquet_multiplier_series_vs_numeric(vdp24):
    val = vdp24.validate([0.3], orders=[12])
    r = val.rows[0]
    assert abs(r["multiplier_series"] - r["multiplier_numeric"]) < 1e-9


def test_stiff_relaxation_regime_outside_series_validity(vdp24):
    """eps = 10, 100: the stiff solver finds the relaxation cycle; the series is flagged as outside its validity.

    References: report part 2 §3 item 10 (mu = 10: amplitude 2.01429, period 19.07837) and the asymptotic period
    (3 - 2 ln 2) mu + 7.014 mu^(-1/3) (§5 item 5), which is accurate to O(ln(mu)/mu).
    """
    val = vdp24.validate([10.0], rtol=1e-8)
    r = val.rows[0]
    assert r["stiff"] and r["method"] == "LSODA"
    assert not r["in_validity"]
    assert abs(r["amplitude_numeric"] - 2.01429) < 1e-4
    assert abs(2 * math.pi / r["frequency_numeric"] - 19.07837) < 1e-3
    assert r["frequency_error"] > 1.0  # the divergent series is useless there, as reported
    assert "outside series validity" in val.table()
    c = numeric_limit_cycle(VDP, 100.0, rtol=1e-8)
    asym = (3 - 2 * math.log(2)) * 100 + 7.014 * 100 ** (-1 / 3)
    assert abs(c.period - asym) / asym < 1e-3
    assert abs(c.amplitude - 2.0) < 2e-3


def test_validation_plot(vdp24):
    val = vdp24.validate([0.5], orders=[2, 6, 10])
    ax = val.plot()
    assert ax.get_xlabel() == "truncation order"
    ax2 = vdp24.plot(0.5, order=6)
    lines = ax2.get_lines()
    assert len(lines) == 2
    # series and numeric orbits overlap: same maximum of x to 1e-6
    assert abs(max(lines[0].get_xdata()) - max(lines[1].get_xdata())) < 1e-5


def test_numeric_period_harmonic_and_no_oscillation():
    assert abs(numeric_period(sp.Integer(0) * x, 0.1, 1.0) - 2 * math.pi) < 1e-10
    with pytest.raises(ConvergenceError, match="turning point"):
        # x'' + x = eps*x^2 with eps large: starting at x = 1 the orbit escapes, never turns back
        numeric_period(x**2, 2.0, 1.0)


@pytest.mark.slow
def test_mpmath_reference_cycle(vdp24):
    """High-precision reference (mpmath.odefun at 26 digits, the cycle located to 1e-16, a hundredth of the
    tolerance): the order-24 series at eps = 0.5 agrees to about 1e-14."""
    c = numeric_limit_cycle(VDP, 0.5, dps=16)
    import mpmath

    with mpmath.workdps(30):
        amp = vdp24.amplitude.evaluate(0.5, dps=30)
        om = vdp24.frequency.evaluate(0.5, dps=30)
        assert abs(amp - c.amplitude) < 1e-14
        assert abs(om - c.frequency) < 1e-14


def test_pade_continues_beyond_the_radius(vdp24):
    """Report part 2 §5 item 1(c): Padé resummation in eps^2 recovers the frequency at eps = 3 > radius ~1.85,
    where the truncated series diverges; checked against the numeric (LSODA) cycle."""
    val = vdp24.validate([3.0], orders=[24], rtol=1e-10)
    r = val.rows[0]
    assert not r["in_validity"]
    assert r["frequency_error"] > 1.0
    assert r["frequency_pade_error"] < 1e-3
    assert "Pade err" in val.table()
    with pytest.raises(ValueError, match="Padé"):
        vdp24.frequency.evaluate_pade(1.0, 10, 10)  # 13 coefficients in eps^2 only
