"""Bulgakov (1954), §12.13, 5° (T17): stability of the relay regulator's cycles and the regions of Table 14.

References, all independent of the code under test:
- the book's model (12.226)–(12.227), ``x'' + beta x' + x = y``, ``x''' + M x'' + alpha x' + gamma H(y) = 0``,
  integrated with SciPy (LSODA) for a relay with a dead zone whose switch is a steep ramp (width 1 % of the dead
  zone; the ideal switch would make the regulator input slide on the switching surfaces, the ramp turns sliding into
  a thin boundary layer): stable cycles are approached, unstable ones are left;
- the shortened equations' Jacobian by finite differences of the averages ``A(a, b)``, ``B(a, b)`` computed by
  quadrature from the modal form (partial fractions of ``N(E) / Delta(E)`` by numpy roots);
- the book's qualitative conclusions of 5° (cases I–III) and the sign pattern of Table 14 (sampled by numpy roots of
  the quadratic (12.185)).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

from symosc import ParameterError
from symosc.nonlinear import relay_regulator_cycles, relay_regulator_region


def _simulate(alpha, beta, gamma, M, dead_zone, cycle, factor, periods=40):
    """Start on the linear mode of ``cycle`` with input amplitude ``factor * b*``; over the last third of the run:
    (max |y|, period from the zero crossings of y, fraction of the time the relay is switching (sliding)).
    (inf, nan, nan) when |y| exceeds 20 b*."""
    ramp = 0.01 * dead_zone

    def H(y):
        return math.copysign(min(max((abs(y) - dead_zone) / ramp, 0.0), 1.0), y)

    def rhs(_t, z):
        x, x1, x2 = z
        return [x1, x2, -M * x2 - alpha * x1 - gamma * H(x2 + beta * x1 + x)]

    lam = 1j * cycle.omega
    c = factor * cycle.amplitude / (2 * (lam**2 + beta * lam + 1))  # y = b cos(u), the real mode not excited
    z0 = [2 * c.real, 2 * (lam * c).real, 2 * (lam**2 * c).real]
    period = 2 * math.pi / cycle.omega

    def blow_up(_t, z):
        return abs(z[2] + beta * z[1] + z[0]) - 20 * cycle.amplitude

    blow_up.terminal = True
    sol = solve_ivp(rhs, (0, periods * period), z0, method="LSODA", rtol=1e-8, atol=1e-10, max_step=period / 200,
                    dense_output=True, events=blow_up)  # fmt: skip
    if sol.status == 1:
        return math.inf, math.nan, math.nan
    tt = np.linspace(sol.t[-1] * 2 / 3, sol.t[-1], 20000)
    x, x1, x2 = sol.sol(tt)
    y = x2 + beta * x1 + x
    crossings = tt[1:][np.sign(y[1:]) != np.sign(y[:-1])]
    true_period = 2 * float(np.median(np.diff(crossings))) if len(crossings) > 2 else math.inf
    sliding = float(np.mean((np.abs(y) > dead_zone) & (np.abs(y) < dead_zone + ramp)))
    return float(np.max(np.abs(y))), true_period, sliding


def test_region7_large_stable_cycle_attracts():
    """Case III of 5° (alpha small positive, M beta < M/(M + gamma h*), region 7): b1 unstable, b1' stable.

    The large cycle is a true relay oscillation (it crosses the switching surfaces, no sliding): the simulation
    settles on it from either side, with amplitude and period close to the first approximation (3.3 % and 0.5 %)."""
    alpha, beta, gamma, M, d = 0.02, 0.3, 1.0, 1.0, 1.0
    assert relay_regulator_region(alpha, beta, gamma, M, dead_zone=d).number == 7
    small, large = relay_regulator_cycles(alpha, beta, gamma, M, dead_zone=d)
    assert not small.stable and large.stable
    for factor in (0.8, 1.25):
        amplitude, period, sliding = _simulate(alpha, beta, gamma, M, d, large, factor)
        assert amplitude == pytest.approx(large.amplitude, rel=0.05)
        assert period == pytest.approx(2 * math.pi / large.omega, rel=0.02)
        assert sliding < 1e-3
    # just below the unstable small cycle the motion comes to rest inside the dead zone (|y| < d)
    assert _simulate(alpha, beta, gamma, M, d, small, 0.8)[0] < d


def test_region9_small_stable_cycle_attracts_large_unstable_one_repels():
    """Case I of 5° (|alpha| small, M beta > 1, region 9): b2 stable (self-oscillation), b2' unstable.

    In the book's model the relay acts on y through a first-order path, so the motion slides on the switching
    surfaces: the small "cycle" is in fact a sliding relaxation oscillation (the relay only partly on, then a slow
    drift across the dead zone).  Its amplitude is close to b2 (3 %), but its period is several times the
    predicted 2 pi / omega: the first approximation gets existence, stability and amplitude, not the period."""
    alpha, beta, gamma, M, d = -0.02, 1.5, 1.0, 1.0, 8.53
    assert relay_regulator_region(alpha, beta, gamma, M, dead_zone=d).number == 9
    small, large = relay_regulator_cycles(alpha, beta, gamma, M, dead_zone=d)
    assert small.stable and not large.stable
    assert small.slope > small.gain > large.slope  # J'(b2) > h2 > J'(b2'), as in the book
    for factor in (0.8, 1.25):  # from either side of the small cycle
        amplitude, period, sliding = _simulate(alpha, beta, gamma, M, d, small, factor, periods=60)
        assert amplitude == pytest.approx(small.amplitude, rel=0.05)
        assert period > 3 * 2 * math.pi / small.omega and sliding > 0.01
    # below the unstable cycle: drawn down to the small one; above it: diverges
    assert _simulate(alpha, beta, gamma, M, d, large, 0.8, periods=60)[0] == pytest.approx(small.amplitude, rel=0.05)
    assert _simulate(alpha, beta, gamma, M, d, large, 1.25)[0] == math.inf


def test_region6_two_pairs_as_in_case_II():
    """Case II of 5° (region 6): b1 unstable, b1' stable, b2 stable, b2' unstable (two possible self-oscillations)."""
    cycles = relay_regulator_cycles(0.02, 0.7, 1.0, 1.0, dead_zone=1.0)
    by_gain = {}
    for c in cycles:
        by_gain.setdefault(c.gain, []).append(c)
    (h1, (b1, b1p)), (h2, (b2, b2p)) = sorted((h, sorted(cs, key=lambda c: c.amplitude)) for h, cs in by_gain.items())
    assert h1 < h2
    assert (b1.stable, b1p.stable, b2.stable, b2p.stable) == (False, True, True, False)


def _averages_jacobian(alpha, beta, gamma, M, d, cycle, step=1e-5):
    """(dA/da, dB/db, dA/db, dB/da) at (0, b*) by central differences of quadrature averages (modal form)."""
    h = cycle.gain
    roots = np.roots([1.0, gamma * h + M, beta * gamma * h + alpha, gamma * h])
    real = roots[np.argmin(np.abs(roots.imag))].real
    osc = roots[np.argmax(roots.imag)]
    dprime = np.polyder(np.poly1d([1.0, gamma * h + M, beta * gamma * h + alpha, gamma * h]))

    def weight(lam):
        return (lam**2 + beta * lam + 1) / dprime(lam)

    H = lambda y: math.copysign(1.0, y) if abs(y) > d else 0.0  # noqa: E731

    def g_avg(a, b, kernel):
        f = lambda u: kernel(u) * (-gamma) * (H(a + b * math.cos(u)) - h * (a + b * math.cos(u)))  # noqa: E731
        # split at the switching angles, where a + b cos(u) = +-d
        cuts = [math.acos(c) for c in ((d - a) / b, (-d - a) / b) if -1 < c < 1]
        pts = sorted({0.0, math.pi, 2 * math.pi, *cuts, *(2 * math.pi - u for u in cuts)})
        return sum(quad(f, u0, u1, epsabs=1e-14, epsrel=1e-13)[0] for u0, u1 in itertools.pairwise(pts)) / (2 * math.pi)

    def A(a, b):
        return real * a + (weight(real) * g_avg(a, b, lambda u: 1.0)).real

    def B(a, b):
        re = g_avg(a, b, math.cos)
        im = -g_avg(a, b, math.sin)
        return (2 * weight(osc) * (re + 1j * im)).real

    b = cycle.amplitude
    e = step * b
    return (
        (A(e, b) - A(-e, b)) / (2 * e),
        (B(0, b + e) - B(0, b - e)) / (2 * e),
        (A(0, b + e) - A(0, b - e)) / (2 * e),
        (B(e, b) - B(-e, b)) / (2 * e),
    )


def test_jacobian_is_diagonal_and_matches_the_averages():
    """(12.218)–(12.221): the Jacobian of the averaged equations, by quadrature and finite differences."""
    alpha, beta, gamma, M, d = 0.02, 0.7, 1.0, 1.0, 1.0
    for cycle in relay_regulator_cycles(alpha, beta, gamma, M, dead_zone=d):
        daa, dbb, dab, dba = _averages_jacobian(alpha, beta, gamma, M, d, cycle)
        scale = abs(daa) + abs(dbb)
        assert abs(dab) < 1e-6 * scale and abs(dba) < 1e-6 * scale
        np.testing.assert_allclose([daa, dbb], cycle.jacobian, rtol=2e-4, atol=1e-7 * scale)
        # trace (12.222): -M - (gamma/2)(h + J'(b*))
        assert sum(cycle.jacobian) == pytest.approx(-M - gamma / 2 * (cycle.gain + cycle.slope), rel=1e-12)


def test_ideal_relay_one_cycle_per_gain():
    """dead_zone = 0: b* = 4/(pi h), J' = 0; the h2 cycle is unstable ((dB/db)* = gamma R h / (2(kappa^2+omega^2)))."""
    cycles = relay_regulator_cycles(0.02, 0.3, 1.0, 1.0)
    assert len(cycles) == 2
    for c in cycles:
        assert c.amplitude == pytest.approx(4 / (math.pi * c.gain), rel=1e-14) and c.slope == 0.0
    assert [c.stable for c in sorted(cycles, key=lambda c: c.gain)][1] is False


@pytest.mark.parametrize("seed", range(4))
def test_table14_sign_pattern(seed):
    """Each region's defining signs (Table 14) hold at random points classified into it."""
    rng = np.random.default_rng(seed)
    gamma, M, d = 1.0, rng.uniform(0.3, 2.0), rng.uniform(0.2, 3.0)
    h_star = 2 / (math.pi * d)
    seen = set()
    for xi, eta in rng.uniform(-1.5, 2.5, size=(400, 2)):
        beta = eta / M
        reg = relay_regulator_region(xi, beta, gamma, M, dead_zone=d)
        if reg.number is None:
            continue
        seen.add(reg.number)
        e0, e1, e2 = beta * gamma**2, gamma * (xi + eta - 1), M * xi
        r = np.roots([e0, e1, e2])
        real = np.all(np.abs(r.imag) < 1e-12)
        hs = np.sort(r.real)
        n = reg.number
        assert (n == 2) == (not real)
        if n in (1, 4, 11):
            assert np.all(hs < 0)
        if n == 3:
            assert h_star < hs[0]
        if n == 6:
            assert 0 < hs[0] and hs[1] < h_star
        if n == 7:
            assert 0 < hs[0] < h_star < hs[1]
        if n in (8, 9):
            assert hs[0] < 0 < hs[1] < h_star
        if n in (5, 10):
            assert hs[0] < 0 and hs[1] > h_star
        if n <= 5:
            assert xi > 0  # damped: k > 0
        if n >= 10:
            assert xi < 0  # divergent: k < 0
        assert (n == 11) == (xi < 0 and eta < 0)
        assert (n in (5, 8)) == (xi > 0 and eta < 0)
    assert {1, 2, 4, 7, 9, 10, 11} <= seen


def test_bad_arguments():
    with pytest.raises(ParameterError, match="dead_zone must be >= 0"):
        relay_regulator_cycles(0.02, 0.3, 1.0, 1.0, dead_zone=-1)
    with pytest.raises(ParameterError, match="M must be positive"):
        relay_regulator_region(0.02, 0.3, 1.0, 0.0)
    with pytest.raises(ParameterError, match="level must be positive"):
        relay_regulator_cycles(0.02, 0.3, 1.0, 1.0, level=0)
