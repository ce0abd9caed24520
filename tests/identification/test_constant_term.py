"""Constant-term (offset) handling of the subspace estimators with their default ``constant=True``.

Belyakov 2005, Ch. II §3.1–3.2 (seed 001, report §3.5): the model order 7 = 1 + 2·3 carries one spare state for
the constant offset A0 (root z = 1).  On a record without an offset that state fits noise; these tests check it
can no longer masquerade as a Nyquist-frequency mode, while genuine near-Nyquist modes are still reported.
"""

import numpy as np
import pytest

from symosc.errors import IdentificationError
from symosc.identification import era, esprit, matrix_pencil

ESTIMATORS = [era, matrix_pencil, esprit]
DT = 0.02
MODES = [(14.05, 0.10, 1.0), (16.40, 0.15, 0.8), (27.35, 0.30, 0.6)]  # (omega, delta, amplitude), report §4.4-like


def _record(n=500, offset=0.0, sigma=0.0, seed=0):
    t = np.arange(n) * DT
    y = offset + sum(a * np.exp(-d * t) * np.cos(w * t + 0.3 * k) for k, (w, d, a) in enumerate(MODES))
    return y + sigma * np.random.default_rng(seed).standard_normal(n)


@pytest.mark.parametrize("estimator", ESTIMATORS)
def test_default_call_on_offset_free_noisy_record(estimator):
    """Offset-free record, 2 % noise: with the defaults (constant=True) every seed gives the three frequencies.

    Before the fix seeds 1, 2 and 4 raised a spurious aliasing error (the spare pole at z = -1)."""
    true_w = np.array([w for w, _, _ in MODES])
    for seed in range(12):
        est = estimator(_record(sigma=0.02, seed=seed), DT, 3)
        assert est.n_modes == 3 and est.n_poles == 7
        # the 2 % noise gives frequency standard deviations of a few 1e-3 rad/s (Cramér–Rao, see test_pencil)
        np.testing.assert_allclose(est.frequencies, true_w, atol=0.02)
        np.testing.assert_allclose(est.damping, [d for _, d, _ in MODES], atol=0.02)
        # the offset is still estimated (linearly) and is zero within the noise: sigma / sqrt(N) ~ 1e-3
        assert abs(est.offset[0]) < 5e-3


@pytest.mark.parametrize("estimator", ESTIMATORS)
def test_default_call_order_selection_and_two_channels(estimator):
    """Order selected from the singular values, and two channels (one offset-free, one not)."""
    rng = np.random.default_rng(7)
    t = np.arange(500) * DT
    y1 = sum(a * np.exp(-d * t) * np.cos(w * t) for w, d, a in MODES)
    y2 = sum(s * a * np.exp(-d * t) * np.cos(w * t) for (w, d, a), s in zip(MODES, [1, -1, 1], strict=True))
    y = np.vstack([y1, y2 + 0.1]) + 0.01 * rng.standard_normal((2, 500))
    est = estimator(y, DT)
    np.testing.assert_allclose(est.frequencies, [w for w, _, _ in MODES], atol=0.01)
    np.testing.assert_allclose(est.offset, [0.0, 0.1], atol=3e-3)
    assert est.details["offset_refit"] is False  # the offset of channel 2 is a genuine state near z = 1


@pytest.mark.parametrize("estimator", ESTIMATORS)
def test_noise_free_offset_free_record_with_defaults(estimator):
    """Exact data without offset have rank 6, not 7: the spare state is dropped instead of raising."""
    est = estimator(_record(), DT, 3)
    np.testing.assert_allclose(est.frequencies, [w for w, _, _ in MODES], rtol=1e-9)
    np.testing.assert_allclose(est.amplitudes[0], [a for _, _, a in MODES], rtol=1e-8)
    assert abs(est.offset[0]) < 1e-10
    assert est.details["offset_refit"] is True
    with pytest.raises(IdentificationError, match="support only 6"):
        estimator(_record(), DT, 4)  # one mode too many is still an error


@pytest.mark.parametrize("estimator", ESTIMATORS)
def test_genuine_offset_is_kept(estimator):
    """A real offset (5x the noise) is identified as the state at z ~ 1 and estimated to noise accuracy."""
    est = estimator(_record(offset=0.1, sigma=0.02, seed=3), DT, 3)
    assert est.details["offset_refit"] is False
    assert abs(est.details["offset_pole"] - 1.0) < 1e-3
    assert abs(est.offset[0] - 0.1) < 5e-3
    np.testing.assert_allclose(est.frequencies, [w for w, _, _ in MODES], atol=0.02)


@pytest.mark.parametrize("estimator", ESTIMATORS)
@pytest.mark.parametrize(
    ("omega_fraction", "offset", "sigma"), [(0.97, 0.0, 0.0), (0.97, 0.0, 0.01), (0.97, 0.3, 0.01), (1.03, 0.0, 0.01)]
)
def test_genuine_near_nyquist_mode_still_raises(estimator, omega_fraction, offset, sigma):
    """A real mode at 97 % of Nyquist, or one at 103 % that folds back to 97 %, is still reported as aliasing,
    with and without offset and noise, with the defaults and with order selection."""
    t = np.arange(400) * DT
    w_fast = omega_fraction * np.pi / DT
    y = offset + np.exp(-0.1 * t) * np.cos(14.0 * t) + 0.5 * np.exp(-0.2 * t) * np.cos(w_fast * t + 0.3)
    y = y + sigma * np.random.default_rng(1).standard_normal(t.size)
    for n_modes in (2, None):
        with pytest.raises(IdentificationError, match="Nyquist"):
            estimator(y, DT, n_modes)


@pytest.mark.parametrize("estimator", ESTIMATORS)
def test_pure_nyquist_sequence_with_order_selection_still_raises(estimator):
    """Extreme: (-1)^n plus a little noise selects order 1 (one real pole at z = -1); with nothing left to drop
    it must still be reported as aliasing, not taken for the offset."""
    y = (-1.0) ** np.arange(100) + 0.01 * np.random.default_rng(0).standard_normal(100)
    with pytest.raises(IdentificationError, match="Nyquist"):
        estimator(y, 0.1)
