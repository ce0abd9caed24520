"""Prony's method with a constant term and Belyakov's sampling advisor (Belyakov 2005, Ch. II §3.1, eqs 39–45).

Linear prediction (eq. 40): every sample is a fixed linear combination of the ``p`` previous ones,
``x[n] = -sum_{k=1..p} a_k x[n-k]``, with ``p = 2 n_modes + 1`` (the extra exponential is the constant offset,
root z = 1).  The coefficients are found by least squares over all channels at once (common poles), the poles are
the roots of ``F(z) = z**p + a_1 z**(p-1) + ... + a_p`` (eq. 41), and amplitudes and phases come from a
least-squares fit of the exponentials (the Vandermonde system).

References: R. Prony (1795); S. L. Marple, *Digital Spectral Analysis* (1987), ch. 11; Belyakov (2005) §3.1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._deprecation import renamed_keyword
from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from ._signals import (
    ModalEstimate,
    _as_signals,
    _check_rank,
    _check_supported,
    _hankel,
    _modal_estimate,
    _resolve_order,
    _select_order,
)

__all__ = ["SamplingAdvice", "prony", "sampling_advice"]


@dataclass(frozen=True)
class SamplingAdvice(SymPyPrintable):
    """Belyakov's sampling rules (eqs 43–45) for a record of ``n_samples`` at period ``dt``.

    Attributes
    ----------
    ratio : float
        ``omega_d / omega_max`` with ``omega_d = 2 pi / dt`` the angular sampling frequency.
    frequency_range_ok : bool
        Rule (43): ``2 <= ratio < 10`` gives the most accurate frequencies and decrements.
    ratio_for_amplitudes : float
        Rule (44): ``sqrt(n_samples)``; amplitudes are best when ``ratio`` is close to it.
    dt_for_amplitudes : float
        The sampling period that satisfies rule (44): ``2 pi / (omega_max sqrt(N))``.
    decimation : int
        Rule (45) as printed: use every m-th sample for the frequencies, ``m = round(ratio / 2)`` (at least 1), so
        that the decimated ratio is close to 2.  Rounding can push it just below 2 (aliasing), so prefer
        ``safe_decimation``.
    safe_decimation : int
        ``floor(ratio / 2.2)`` (at least 1): the decimated ratio stays >= 2.2, where Prony is still most accurate
        and the fastest mode keeps clear of the Nyquist frequency.
    aliased : bool
        ``ratio < 2``: the fastest mode is above the Nyquist frequency.
    message : str
        A one-line verdict.
    """

    ratio: float
    frequency_range_ok: bool
    ratio_for_amplitudes: float
    dt_for_amplitudes: float
    decimation: int
    safe_decimation: int
    aliased: bool
    message: str


@validated
def sampling_advice(dt: float, n_samples: int, omega_max: float) -> SamplingAdvice:
    """Check a sampling period against Belyakov's rules (43)–(45) for the fastest mode ``omega_max`` (rad/s).

    Parameters
    ----------
    dt : float
        Sampling period (s); must be positive and finite.
    n_samples : int
        Number of samples in the record; an integer >= 1.
    omega_max : float
        Angular frequency (rad/s) of the fastest mode of interest; must be positive and finite.

    Returns
    -------
    SamplingAdvice

    Examples
    --------
    The dissertation's record (§4.6: 12544 samples at 0.002212 s, fastest mode 27.35160 rad/s):

    >>> adv = sampling_advice(0.002212, 12544, 27.35160)
    >>> round(adv.ratio, 1), round(adv.ratio_for_amplitudes, 1), adv.decimation, adv.safe_decimation
    (103.9, 112.0, 52, 47)
    """
    dt = float(dt)
    n = int(n_samples)
    w = float(omega_max)
    if not (dt > 0 and math.isfinite(dt)) or n < 1 or not (w > 0 and math.isfinite(w)):
        raise ParameterError(
            f"sampling_advice needs dt > 0, n_samples >= 1, omega_max > 0; got {dt!r}, {n_samples!r}, {omega_max!r}"
        )
    ratio = 2 * math.pi / dt / w
    m = max(1, round(ratio / 2))
    safe = max(1, math.floor(ratio / 2.2))
    aliased = ratio < 2
    ok = 2 <= ratio < 10
    if aliased:
        msg = (
            f"aliased: omega_d/omega_max = {ratio:.3g} < 2, the mode at {w:g} rad/s is above the Nyquist frequency "
            f"{math.pi / dt:.6g} rad/s; sample with dt < {2 * math.pi / (2 * w):.3g} s"
        )
    elif ok:
        msg = f"ratio {ratio:.3g} in [2, 10): good for frequencies (rule 43)"
    else:
        msg = f"ratio {ratio:.3g} >= 10: decimate by about {m} for the frequencies (rule 45; {safe} keeps it >= 2.2)"
    return SamplingAdvice(
        ratio=ratio,
        frequency_range_ok=ok,
        ratio_for_amplitudes=math.sqrt(n),
        dt_for_amplitudes=2 * math.pi / (w * math.sqrt(n)),
        decimation=m,
        safe_decimation=safe,
        aliased=aliased,
        message=msg,
    )


def _fastest_frequency(y: np.ndarray, dt: float) -> float | None:
    """Highest angular frequency carrying signal power in the record (periodogram over the noise floor)."""
    n = y.shape[1]
    if n < 16:
        return None
    win = np.hanning(n)
    power = np.zeros(n // 2 + 1)
    for ch in y:
        power += np.abs(np.fft.rfft((ch - ch.mean()) * win)) ** 2
    if not np.any(power[1:] > 0):
        return None
    floor = float(np.median(power[len(power) // 2 :]))
    threshold = max(100.0 * floor, 1e-14 * float(power[1:].max()))
    # spectral peaks (local maxima) above the noise floor: the window's leakage around a strong mode falls off
    # monotonically, while a weak mode far below the strong one (80 dB and more) still stands out as a peak, and
    # decimating past it would fold it to a wrong frequency
    inner = power[1:-1]
    peaks = np.nonzero((inner > power[:-2]) & (inner >= power[2:]) & (inner > threshold))[0] + 1
    if peaks.size == 0:
        return None
    return 2 * np.pi * (peaks[-1] + 1) / (n * dt)


def _auto_decimation(y: np.ndarray, dt: float, n_poles: int | None) -> int:
    """Decimation factor from rule (45) when the record is oversampled (rule 43), else 1."""
    w = _fastest_frequency(y, dt)
    if w is None or w <= 0:
        return 1
    adv = sampling_advice(dt, y.shape[1], w)
    if adv.ratio < 10:
        return 1
    keep = 4 * (n_poles or 10) + 20
    return max(1, min(adv.safe_decimation, y.shape[1] // keep))


@validated
@renamed_keyword({"order": "n_poles"})
def prony(
    signals: Any,
    dt: float,
    n_modes: int | None = None,
    *,
    n_poles: int | None = None,
    constant: bool = True,
    decimate: int | str = "auto",
    dps: int | None = None,
    nyquist_margin: float = 0.95,
) -> ModalEstimate:
    """Least-squares Prony estimate of damped modes (with a constant term) from free-decay signals.

    Parameters
    ----------
    signals : array_like, shape (samples,) or (channels, samples)
        Real samples at t = 0, dt, 2 dt, ...; all channels share the poles (multichannel linear prediction).
    dt : float
        Sampling period (s); must be positive and finite.
    n_modes : int, optional
        Number of oscillatory modes.  If neither it nor ``n_poles`` is given, the order is selected from the
        largest gap of the singular values of the data Hankel matrix.
    n_poles : int, optional
        Total number of exponentials, ``2 n_modes + 1`` with a constant term (``2 n_modes`` without).
    constant : bool
        Include the constant offset (Belyakov's A0, root z = 1).
    decimate : int or "auto"
        Use every ``decimate``-th sample to find the poles (rule 45; see :func:`sampling_advice`); amplitudes and
        phases are still fitted on the full record.  ``"auto"`` (default) estimates the fastest mode from the
        record's periodogram and, when the record is oversampled (``omega_d/omega_max >= 10``, rule 43), decimates
        by the safe factor of :func:`sampling_advice` (limited so that at least ``4*n_poles + 20`` samples remain);
        on an oversampled noisy record the prediction otherwise fits the noise.  ``details["decimate"]`` tells
        the factor used.
    dps : int, optional
        Root the prediction polynomial with mpmath at this many digits (for ill-conditioned high orders).
    nyquist_margin : float
        A pole above this fraction of the Nyquist frequency is reported as aliasing (IdentificationError).

    Returns
    -------
    ModalEstimate
        ``singular_values`` are those of the linear-prediction matrix.

    Raises
    ------
    ParameterError
        Too-short or non-finite signals, bad dt, an order larger than the record supports.
    IdentificationError
        Rank-deficient data for the requested order, a mode at/above Nyquist, nearly repeated modes.

    See Also
    --------
    era
    matrix_pencil
    sampling_advice

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(200) * 0.05
    >>> y = 0.3 + np.exp(-0.1 * t) * np.cos(3.0 * t + 0.2) + 0.5 * np.exp(-0.2 * t) * np.cos(7.0 * t)
    >>> est = prony(y, 0.05, n_modes=2)
    >>> np.round(est.frequencies, 9).tolist(), np.round(est.damping, 9).tolist()
    ([3.0, 7.0], [0.1, 0.2])
    >>> np.round(est.amplitudes, 9).tolist(), round(float(est.offset[0]), 9)
    ([[1.0, 0.5]], 0.3)
    """
    y, dt = _as_signals(signals, dt)
    if isinstance(decimate, str) and decimate == "auto":
        guess = _resolve_order(n_modes, n_poles, constant)
        m = _auto_decimation(y, dt, guess)
    else:
        if (
            isinstance(decimate, bool | str)
            or not isinstance(decimate, int | np.integer | float)
            or decimate != int(decimate)
        ):
            raise ParameterError(f"decimate must be a positive integer or 'auto', got {decimate!r}")
        m = int(decimate)
        if m < 1:
            raise ParameterError(f"decimate must be a positive integer or 'auto', got {decimate!r}")
    yd = y[:, ::m]
    dtd = dt * m
    nch, n = yd.shape
    p = _resolve_order(n_modes, n_poles, constant)
    use_const = bool(constant)
    if p is None:
        rows = max(2, min(n // 2, max(2, 200 // nch)))
        sv_sel = np.linalg.svd(_hankel(yd, rows), compute_uv=False)
        p = _select_order(sv_sel, constant, max_order=min(rows * nch, n - rows) // 2)
        use_const = bool(constant) and p % 2 == 1
    _check_supported(p, n, "Prony linear prediction" + (f" after decimation by {m}" if m > 1 else ""))
    # rows: channel c, sample j >= p:  sum_{k=1..p} a_k y[j-k] = -y[j]
    idx = np.arange(p, n)[:, None] - np.arange(1, p + 1)[None, :]
    x = yd[:, idx].reshape(-1, p)
    rhs = -yd[:, p:].reshape(-1)
    if x.shape[0] < p:
        raise ParameterError(
            f"order {p} is larger than the data support: {x.shape[0]} prediction equations for {p} unknowns"
        )
    sv = np.linalg.svd(x, compute_uv=False)
    _check_rank(sv, p, hint="; if the record is heavily oversampled, decimate it (rule 45, see sampling_advice)")
    a, *_ = np.linalg.lstsq(x, rhs, rcond=None)
    coeffs = np.concatenate([[1.0], a])
    if dps is None:
        z = np.roots(coeffs)
    else:
        import mpmath

        with mpmath.workdps(int(dps)):
            roots = mpmath.polyroots([mpmath.mpf(c) for c in coeffs], maxsteps=200, extraprec=4 * int(dps))
        z = np.array([complex(r) for r in roots])
    return _modal_estimate(
        y,
        dt,
        z,
        constant=use_const,
        method="prony",
        singular_values=sv,
        dt_poles=dtd,
        nyquist_margin=nyquist_margin,
        details={"decimate": m, "prediction_coefficients": a},
    )
