"""Subspace estimators that beat Prony in noise: the matrix pencil (Hua & Sarkar 1990) and TLS-ESPRIT.

Both stack one Hankel matrix per channel, ``Y_c[n, k] = y_c[n + k]`` (``N - L`` rows, ``L + 1`` columns, pencil
parameter ``L`` about N/3), take its SVD, keep the ``order`` dominant right singular vectors ``V`` and use the
shift invariance of the signal subspace in time, ``V_down ~ V_up Psi``; the eigenvalues of ``Psi`` are the discrete
poles.  The matrix pencil solves the shift equation by least squares, ESPRIT by total least squares (errors on both
sides, Roy & Kailath 1989), which is slightly better at low SNR.  Truncating the SVD removes most of the noise before
the poles are formed; plain Prony roots a polynomial fitted to the raw noisy samples and is biased.

References: Y. Hua, T. K. Sarkar, IEEE Trans. ASSP 38 (1990) 814; R. Roy, T. Kailath, IEEE Trans. ASSP 37 (1989)
984; T. K. Sarkar, O. Pereira, IEEE Antennas Prop. Mag. 37 (1995) 48.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._deprecation import renamed_keyword
from ..._validate import validated
from ...errors import IdentificationError, ParameterError
from ._signals import (
    ModalEstimate,
    _check_rank,
    _prepare,
    _select_order,
    _subspace_estimate,
)

__all__ = ["esprit", "matrix_pencil"]


def _subspace(y: np.ndarray, order: int | None, pencil: int | None, constant: bool):
    n = y.shape[1]
    cap = 300
    lpar = max(2, min(n // 3, cap)) if pencil is None else int(pencil)
    if not 1 <= lpar <= n - 2:
        raise ParameterError(
            f"hankel_size (the pencil parameter L) must be in [1, {n - 2}] for {n} samples, got {pencil!r}"
        )
    if order is not None and lpar < order + 1:
        if pencil is not None:
            raise ParameterError(f"hankel_size (pencil parameter) {lpar} must exceed n_poles = {order}; raise it")
        lpar = min(order + 1, n - 2)
    idx = np.arange(n - lpar)[:, None] + np.arange(lpar + 1)[None, :]
    h = y[:, idx].reshape(-1, lpar + 1)  # channels stacked vertically
    _, s, vt = np.linalg.svd(h, full_matrices=False)
    if order is None:
        order = _select_order(s, constant, max_order=min(lpar, h.shape[0]) // 2 * 2)
    if order > min(lpar, h.shape[0]):
        raise ParameterError(
            f"order {order} is larger than the data support (pencil {lpar}, {h.shape[0]} Hankel rows); lower n_modes"
        )
    _check_rank(s, order, spare=bool(constant) and order % 2 == 1)
    return vt, s, order, lpar


def _shift_poles(vt: np.ndarray, order: int, tls: bool) -> np.ndarray:
    """Discrete poles from the shift invariance of the first ``order`` right singular vectors (LS or TLS)."""
    v = vt[:order].conj().T  # (L+1, order)
    v1, v2 = v[:-1], v[1:]
    if tls:
        _, _, wt = np.linalg.svd(np.hstack([v1, v2]), full_matrices=True)
        w = wt.conj().T
        w12, w22 = w[:order, order:], w[order:, order:]
        try:
            psi = -w12 @ np.linalg.inv(w22)
        except np.linalg.LinAlgError:
            raise IdentificationError("esprit: the total-least-squares shift equation is singular") from None
    else:
        psi, *_ = np.linalg.lstsq(v1, v2, rcond=None)
    return np.linalg.eigvals(psi)


def _run(signals, dt, n_modes, order, constant, pencil, nyquist_margin, tls: bool) -> ModalEstimate:
    y, dt, p = _prepare(signals, dt, n_modes, order, constant, "matrix pencil")
    vt, s, p, lpar = _subspace(y, p, pencil, constant)

    def poles_at(k: int) -> tuple[np.ndarray, dict[str, Any]]:
        z = _shift_poles(vt, k, tls)
        return z, {"hankel_size": lpar, "discrete_poles": z}

    name = "esprit" if tls else "matrix_pencil"
    return _subspace_estimate(
        y, dt, p, constant, poles_at, method=name, singular_values=s, nyquist_margin=nyquist_margin
    )


@validated
@renamed_keyword({"order": "n_poles", "pencil": "hankel_size"})
def matrix_pencil(
    signals: Any,
    dt: float,
    n_modes: int | None = None,
    *,
    n_poles: int | None = None,
    constant: bool = True,
    hankel_size: int | None = None,
    nyquist_margin: float = 0.95,
) -> ModalEstimate:
    """Matrix-pencil estimate of damped modes (SVD-truncated, least-squares shift invariance).

    Parameters
    ----------
    signals : array_like, shape (samples,) or (channels, samples)
        Real samples at t = 0, dt, 2 dt, ...: finite, at least 4 per channel, not all zero.
    dt : float
        Sampling period (s); must be positive and finite.
    n_modes : int, optional
        Number of oscillatory modes, an integer >= 1.  If neither it nor ``n_poles`` is given, the order is selected
        from the largest gap of the singular values.
    n_poles : int, optional
        Number of exponentials, ``2 n_modes + 1`` with the constant (offset) state, ``2 n_modes`` without; give at
        most one of ``n_modes`` and ``n_poles``.
    constant : bool
        Include a constant (offset) state (default True; it is dropped again when the data do not support it).
    hankel_size : int, optional
        Pencil parameter L (default N/3, at most 300); the Hankel matrix has L + 1 columns.
    nyquist_margin : float
        A pole above this fraction of the Nyquist frequency is reported as aliasing (IdentificationError).

    See Also
    --------
    esprit
    era
    prony
    refine

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(120) * 0.02
    >>> y = 2.0 * np.exp(-0.5 * t) * np.cos(9.0 * t - 1.0) + np.exp(-t) * np.cos(23.0 * t + 0.5)
    >>> est = matrix_pencil(y, 0.02, 2, constant=False)
    >>> np.round(est.poles, 9).tolist()
    [(-0.5+9j), (-1+23j)]
    >>> np.round(est.phases, 9).tolist()
    [[-1.0, 0.5]]
    """
    return _run(signals, dt, n_modes, n_poles, constant, hankel_size, nyquist_margin, tls=False)


@validated
@renamed_keyword({"order": "n_poles", "pencil": "hankel_size"})
def esprit(
    signals: Any,
    dt: float,
    n_modes: int | None = None,
    *,
    n_poles: int | None = None,
    constant: bool = True,
    hankel_size: int | None = None,
    nyquist_margin: float = 0.95,
) -> ModalEstimate:
    """TLS-ESPRIT estimate of damped modes (same subspace as :func:`matrix_pencil`, total-least-squares shift).

    Parameters
    ----------
    signals : array_like, shape (samples,) or (channels, samples)
        Real samples at t = 0, dt, 2 dt, ...: finite, at least 4 per channel, not all zero.
    dt : float
        Sampling period (s); must be positive and finite.
    n_modes : int, optional
        Number of oscillatory modes, an integer >= 1.  If neither it nor ``n_poles`` is given, the order is selected
        from the largest gap of the singular values.
    n_poles : int, optional
        Number of exponentials, ``2 n_modes + 1`` with the constant (offset) state, ``2 n_modes`` without; give at
        most one of ``n_modes`` and ``n_poles``.
    constant : bool
        Include a constant (offset) state (default True; it is dropped again when the data do not support it).
    hankel_size : int, optional
        Pencil parameter L, an integer in ``[1, N - 2]`` larger than ``n_poles`` (default N/3, at most 300); the
        Hankel matrix has L + 1 columns.
    nyquist_margin : float
        A pole above this fraction (in (0, 1]) of the Nyquist frequency is reported as aliasing
        (IdentificationError).

    Returns
    -------
    ModalEstimate
        ``details`` holds ``hankel_size`` and the discrete poles.

    See Also
    --------
    matrix_pencil
    era
    prony

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(120) * 0.02
    >>> y = 1.5 + np.exp(-0.3 * t) * np.cos(12.0 * t)
    >>> est = esprit(y, 0.02, 1)
    >>> round(float(est.frequencies[0]), 9), round(float(est.damping[0]), 9), round(float(est.offset[0]), 9)
    (12.0, 0.3, 1.5)
    """
    return _run(signals, dt, n_modes, n_poles, constant, hankel_size, nyquist_margin, tls=True)
