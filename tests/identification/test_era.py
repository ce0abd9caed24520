"""Kung / ERA realisation and the two-stage structure-preserving variant.

Source: Belyakov 2005 (seed 001_b22cdb6b21550ad5.txt), Ch. II §3.2 (report §3.5) and the worked example of
Ch. III §2 (report §4.1–§4.6, §4.9).  The body-on-springs forward model used here is an independent few-line
reimplementation of eqs (23)–(26) (scipy eigh), not the package's model.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla

from symosc.errors import IdentificationError, ParameterError
from symosc.identification import era, esprit, matrix_pencil, prony, realize, two_stage

LX, LZ, RX, RZ, K_SPRING = 4.0, 1.74, 2.0, 0.87, 740000.0
MASS = np.array([[15000.0, 0.0, 0.0], [0.0, 44000.0, 400.0], [0.0, 400.0, 3000.0]])  # M23 = +400 (report §2.7)
FORCE = np.array([0.0, -2000.0, 0.0, 0.0])  # 2000 N released at spring 2 (Appendix: P = -2000)


def _stand():
    """3-DOF stand of report §2.4: C rows (1, x_j - rx, -(z_j - rz)), K = k C^T C; release from the static load."""
    xs = np.array([0.0, LX, LX, 0.0])
    zs = np.array([0.0, 0.0, LZ, LZ])
    c = np.column_stack([np.ones(4), xs - RX, -(zs - RZ)])
    k = K_SPRING * c.T @ c
    w2, u = sla.eigh(k, MASS)
    q0 = np.linalg.solve(k, c.T @ FORCE)
    a = np.linalg.solve(u, q0)  # normal-coordinate initial displacements
    return c, k, np.sqrt(w2), u, q0, c @ u * a[None, :]  # last: C' with q0' = 1


def _signals(dt, n, *, damping=None):
    _c, _k, w, _u, _q0, cprime = _stand()
    t = np.arange(n) * dt
    if damping is None:
        y = cprime @ np.cos(np.outer(w, t))
    else:
        lam = -damping + 1j * np.sqrt(w**2 - damping**2)
        y = np.real(cprime @ np.exp(np.outer(lam, t)))
    return y, w, cprime


def test_forward_model_reproduces_report_values():
    """Report §4.2/§4.3 [C]: linear-model frequencies 14.0475383, 16.3983994, 27.3536888 rad/s and C' entries."""
    _, _, w, _, _, cprime = _stand()
    np.testing.assert_allclose(w, [14.0475383, 16.3983994, 27.3536888], rtol=1e-8)
    np.testing.assert_allclose(np.abs(cprime[1]), [6.756757e-4, 7.197311e-4, 6.316203e-4], rtol=1e-6)


def test_era_noise_free_stand_is_exact():
    """Report §4.6 sampling (dt = 0.002212 s) decimated x10 as in the §4.9 pipeline, 4 channels, static release
    plus the equilibrium offset (gravity sag, report §4.1): frequencies and C' to ~1e-9."""
    y, w, cprime = _signals(0.02212, 1254)
    sag = np.array([-0.0497, -0.0497, -0.0497, -0.0497])
    est = era(y + sag[:, None], 0.02212, hankel_size=30)
    assert est.n_poles == 7  # 1 + 2*3 as in the dissertation
    np.testing.assert_allclose(est.frequencies, w, rtol=1e-10)
    np.testing.assert_allclose(est.damping, 0.0, atol=1e-8)
    np.testing.assert_allclose(est.mode_shapes, cprime, rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(est.offset, sag, rtol=1e-9)
    # the recipe's Q: one exponential of a conjugate pair carries half the amplitude (report §3.5 factor-2 caveat)
    q = est.details["Q"]
    zq = est.details["discrete_poles"]
    upper = zq.imag > 0
    amps = 2 * np.abs(q[:, upper][:, np.argsort(np.angle(zq[upper]))])
    np.testing.assert_allclose(amps, np.abs(cprime), rtol=1e-7)
    assert est.singular_values[7] < 1e-10 * est.singular_values[0]


def test_era_one_percent_noise_stand():
    """Report §4.5/§4.9: 1 % white noise of the 0.00067 m modal amplitude; frequencies to 1e-4 and C' within
    0.5 % (the report's Kung gives 0.1–0.3 %); order 7 selected from the singular-value gap."""
    y, w, cprime = _signals(0.02212, 1254)
    rng = np.random.default_rng(7)
    noisy = y + 0.01 * 0.00067 * rng.standard_normal(y.shape) + 0.01
    est = era(noisy, 0.02212, hankel_size=40)
    assert est.n_poles == 7
    np.testing.assert_allclose(est.frequencies, w, rtol=1e-4)
    np.testing.assert_allclose(est.mode_shapes, cprime, rtol=5e-3)


def test_era_damped_modes_and_undamped_frequency():
    """Proportional-like modal damping: |lambda| is the undamped frequency (Belyakov eq. 97, report §3.10)."""
    delta = np.array([0.05, 0.08, 0.2])
    y, w, _cprime = _signals(0.02212, 1254, damping=delta)
    est = era(y, 0.02212, 3, constant=False, hankel_size=30)
    np.testing.assert_allclose(est.damping, delta, rtol=1e-8)
    np.testing.assert_allclose(est.undamped_frequencies, w, rtol=1e-10)
    np.testing.assert_allclose(est.damping_ratios, delta / w, rtol=1e-8)


def test_methods_agree_on_multichannel_signal():
    """Prony, ERA, matrix pencil and ESPRIT give the same model on exact 4-channel data."""
    y, w, cprime = _signals(0.05, 400)
    y = y + 1e-3
    ests = [f(y, 0.05, 3) for f in (prony, era, matrix_pencil, esprit)]
    for est in ests:
        np.testing.assert_allclose(est.frequencies, w, rtol=1e-9)
        np.testing.assert_allclose(est.mode_shapes, cprime, rtol=1e-7, atol=1e-12)
        np.testing.assert_allclose(est.offset, 1e-3, rtol=1e-7)
        assert est.residual < 1e-9


def test_era_beats_prony_in_noise():
    """Belyakov §3.2 (Fig. 12): Kung is much less noise-sensitive than Prony.  At 10 % noise on the dissertation's
    sampling rule ratio ~ sqrt(N) record, ERA's frequencies stay within 0.1 % while Prony's are far off or fail."""
    y, w, _ = _signals(0.02212, 1254)
    rng = np.random.default_rng(3)
    noisy = y + 0.1 * 0.00067 * rng.standard_normal(y.shape)
    est = era(noisy, 0.02212, 3, constant=False)
    assert np.abs(est.frequencies / w - 1).max() < 1e-3
    try:
        bad = prony(noisy, 0.02212, 3, constant=False)
        err_prony = np.abs(bad.frequencies / w - 1).max()
    except IdentificationError:
        err_prony = np.inf
    assert err_prony > 10 * np.abs(est.frequencies / w - 1).max()


def test_two_stage_recovers_second_order_structure():
    """Belyakov §3.2 (b)-(c), report §6 item 11: A similar to -M^-1 K (same C basis), S_2k = C A^(k-1) v0 = 0 for
    a static release, and q0 the static deflection."""
    c, k, w, _u, q0, cprime = _stand()
    y, _, _ = _signals(0.02212, 1254)
    model = two_stage(y + 0.01, 0.02212, 3, hankel_size=30)
    a_true = -np.linalg.solve(MASS, k)
    t = np.linalg.lstsq(c, model.C, rcond=None)[0]  # C_identified = C_true T
    np.testing.assert_allclose(c @ t, model.C, atol=1e-9 * np.abs(model.C).max())
    np.testing.assert_allclose(t @ model.A @ np.linalg.inv(t), a_true, rtol=1e-6, atol=1e-6 * np.abs(a_true).max())
    np.testing.assert_allclose(t @ model.q0, q0, rtol=1e-7)
    assert np.abs(model.markov_even).max() < 1e-8 * np.abs(model.markov_odd).max()
    np.testing.assert_allclose(model.frequencies, w, rtol=1e-10)
    np.testing.assert_allclose(model.mode_shapes, cprime, rtol=1e-8)
    assert "SecondOrderModel" in repr(model)


def test_two_stage_with_initial_velocity():
    """S_2k carry v0 when the motion starts with a velocity (eq. 53)."""
    c, _k, w, u, q0, _ = _stand()
    v0 = np.array([0.0, 0.001, -0.002])
    t = np.arange(1254) * 0.02212
    a = np.linalg.solve(u, q0)
    b = np.linalg.solve(u, v0) / w
    y = c @ u @ (a[:, None] * np.cos(np.outer(w, t)) + b[:, None] * np.sin(np.outer(w, t)))
    model = two_stage(y, 0.02212, 3, constant=False, hankel_size=30)
    tt = np.linalg.lstsq(c, model.C, rcond=None)[0]
    np.testing.assert_allclose(tt @ model.v0, v0, rtol=1e-6, atol=1e-9)


def test_two_stage_damped_uses_undamped_frequencies():
    """With modal damping the second stage works on |lambda| (Belyakov eq. 97): A ~ -M^-1 K exactly."""
    _c, _k, w, _u, _q0, _cprime = _stand()
    y, _, _ = _signals(0.02212, 1254, damping=np.array([0.05, 0.08, 0.2]))
    model = two_stage(y, 0.02212, 3, constant=False, hankel_size=30)
    np.testing.assert_allclose(model.frequencies, w, rtol=1e-9)
    np.testing.assert_allclose(np.sort(-model.eigenvalues.real), w**2, rtol=1e-9)


def test_realize_order_selection_and_rows():
    """Order from the singular-value gap; explicit rows are honoured; python-control-like signature."""
    y, w, _ = _signals(0.05, 300)
    a, c, _x0, _sv, n, rows = realize(y, None, hankel_size=20, constant=False)
    assert n == 6 and rows == 20 and a.shape == (6, 6) and c.shape == (4, 6)
    z = np.sort(np.angle(np.linalg.eigvals(a)))[3:] / 0.05
    np.testing.assert_allclose(z, w, rtol=1e-10)


def test_era_bad_input():
    y, _, _ = _signals(0.05, 300)
    with pytest.raises(ParameterError, match="NaN"):
        bad = y.copy()
        bad[2, 17] = np.nan
        era(bad, 0.05)
    with pytest.raises(ParameterError, match="too short"):
        era(y[0, :3], 0.05)
    with pytest.raises(ParameterError, match="transpose"):
        era(y.T, 0.05)
    with pytest.raises(IdentificationError, match="support only 6 exponentials"):
        era(y, 0.05, 4, constant=False)
    with pytest.raises(IdentificationError, match="constant=False"):
        era(y, 0.05, 4)  # more exponentials than the data support, even allowing for an unused offset state
    with pytest.raises(ParameterError, match="larger than"):
        era(y[:, :20], 0.05, 6)
    with pytest.raises(ParameterError, match="rows"):
        era(y, 0.05, 3, constant=False, hankel_size=1000)
    with pytest.raises(ParameterError, match="dt"):
        era(y, 0.0)
    with pytest.raises(ParameterError, match="contradicts"):
        era(y, 0.05, 3, n_poles=5)
