"""Lines of equal degree of stability with delay (Bulgakov (1954), §4.16–4.17).

References: the book's closed forms (4.132), (4.134)–(4.136), (4.144)–(4.148) typed in here, and the certified
argument-principle root count of symosc.nonlinear (a different algorithm from the linear solve used by the code).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from symosc.errors import ParameterError
from symosc.linear import delay_equal_stability_lines
from symosc.nonlinear import callender_hartree_porter_optimum, count_roots


@pytest.mark.parametrize("s", [0.0, 0.2, 0.45])
def test_callender_hartree_porter_closed_forms(s):
    b = delay_equal_stability_lines("callender-hartree-porter", s, n_points=50)
    w = b.omega[1:]
    rho = np.exp(-s) * (2 * s * np.cos(w) + (w**2 - s**2) * np.sin(w) / w)  # (4.135); s = 0: (4.132)
    sig = np.exp(-s) * (s**2 + w**2) * (np.cos(w) - s * np.sin(w) / w)
    assert np.allclose(b.rho[1:], rho, atol=1e-12) and np.allclose(b.sigma[1:], sig, atol=1e-12)
    assert b.cusp == pytest.approx((np.exp(-s) * (2 * s - s**2), np.exp(-s) * s**2 * (1 - s)), abs=1e-14)  # (4.136)
    r, q = b.real_line
    assert np.allclose(q, r * s - s**2 * np.exp(-s), atol=1e-14)  # (4.134); s = 0: σ = 0 (4.131)


@pytest.mark.parametrize("s", [0.0, 0.3, 0.6])
def test_andronov_maier_closed_forms(s):
    b = delay_equal_stability_lines("andronov-maier", s, n_points=50)
    w = b.omega[1:]
    den = w * np.cos(w) - s * np.sin(w)
    rho = (2 * s * w * np.cos(w) + (w**2 - s**2) * np.sin(w)) / den  # (4.147); s = 0: (4.145)
    sig = np.exp(-s) * w * (w**2 + s**2) / den
    assert np.allclose(b.rho[1:], rho, rtol=1e-10) and np.allclose(b.sigma[1:], sig, rtol=1e-10)
    assert b.cusp == pytest.approx((s * (2 - s) / (1 - s), np.exp(-s) * s**2 / (1 - s)), abs=1e-13)  # (4.148)
    r, q = b.real_line
    assert np.allclose(q, np.exp(-s) * (r * s - s**2), atol=1e-13)  # (4.146)


def test_andronov_maier_boundary_with_lambda():
    """(4.144): ρ = (ω² - λ) tan ω/ω, σ = [ω² + λ(cos ω - 1)]/cos ω."""
    lam = -0.3
    b = delay_equal_stability_lines("andronov-maier", 0.0, lam=lam, omega_max=1.4, n_points=30)
    w = b.omega[1:]
    assert np.allclose(b.rho[1:], (w**2 - lam) * np.tan(w) / w, rtol=1e-10)
    assert np.allclose(b.sigma[1:], (w**2 + lam * (np.cos(w) - 1)) / np.cos(w), rtol=1e-10)


@pytest.mark.parametrize(("model", "s"), [("callender-hartree-porter", 0.3), ("andronov-maier", 0.2)])
def test_degree_of_stability_on_the_curve_by_root_counting(model, s):
    """At sampled points of the complex-root curve the rightmost roots are exactly -s ± iω: no root right of
    Re p = -s + 1e-4, and two roots in a thin strip around -s (certified counts)."""
    b = delay_equal_stability_lines(model, s, n_points=9)
    for j in (2, 4, 6):
        f = b.characteristic(b.rho[j], b.sigma[j])
        w = float(b.omega[j])
        assert count_roots(f, (-s + 1e-4, 4.0, -12.0, 12.0)) == 0
        assert count_roots(f, (-s - 1e-4, -s + 1e-4, w - 1e-2, w + 1e-2)) == 1
    # the real-root line: -s is a root
    r, q = b.real_line
    p = sp.Symbol("p")
    f = b.characteristic(r[5], q[5])
    assert abs(complex(f.subs(p, -s))) < 1e-12


def test_optimum_cusp_and_errors():
    """§4.16 (4.137)–(4.138): at s* = 2 - √2 the cusp is (ρ*, σ*) of the symbolic optimum."""
    opt = callender_hartree_porter_optimum()
    b = delay_equal_stability_lines("callender-hartree-porter", float(opt["s"]))
    assert b.cusp == pytest.approx((float(opt["rho"]), float(opt["sigma"])), abs=1e-14)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    assert b.plot(ax=ax) is ax
    plt.close(fig)
    with pytest.raises(ParameterError, match="model"):
        delay_equal_stability_lines("smith")
    with pytest.raises(ParameterError, match="degree of stability"):
        delay_equal_stability_lines(s=-1)
