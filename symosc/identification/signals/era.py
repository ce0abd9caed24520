"""Kung's Hankel-SVD realisation (the eigensystem realisation algorithm, ERA) for multichannel free decays.

Belyakov 2005, Ch. II §3.2 (d), after S. Y. Kung, "A new identification and model reduction algorithm via singular
value decomposition" (1978); J.-N. Juang & R. S. Pappa, J. Guidance 8 (1985) 620 (ERA)::

    H = [y_{i+j}]  (block Hankel, rows*l x cols)   = U diag(sigma) V^T
    Gamma = U_1 sqrt(Sigma_1)          (observability, first `order` singular triplets)
    A = Gamma_up^+ Gamma_down          (shift invariance, eq. 57, least squares)
    C = first block row of Gamma,      x0 = first column of sqrt(Sigma_1) V_1^T

The eigenvalues of A are the discrete poles; the modal amplitudes Q = C T diag(T^-1 x0) of the recipe (pp. 51–54)
are kept in ``details["Q"]``, while the reported amplitudes are a least-squares fit over the whole record (equal
for exact data, better in noise).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._deprecation import renamed_keyword
from ..._validate import validated
from ...errors import ParameterError
from ._signals import (
    ModalEstimate,
    _check_rank,
    _hankel,
    _prepare,
    _select_order,
    _subspace_estimate,
)

__all__ = ["era", "realize"]


def _default_rows(n: int, nch: int, order: int | None) -> int:
    rows = max(2, min((n + 1) // (nch + 1), max(2, 300 // nch)))
    if order is not None:
        rows = max(rows, -(-(order + 1) // nch) + 1)
    return min(rows, n - 1)


@validated
@renamed_keyword({"order": "n_poles", "rows": "hankel_size"})
def realize(
    y: np.ndarray, n_poles: int | None, *, hankel_size: int | None = None, constant: bool = True
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, int, int]:
    """Kung realization ``(A, C, x0, singular_values, n_poles, hankel_size)`` of a sequence ``y[:, j] = C A^j x0``.

    Parameters
    ----------
    y : ndarray, shape (channels, N)
        The sequence, one row per channel: a 2-D array of finite real numbers with at least 3 samples.
    n_poles : int or None
        State dimension of the realization, an integer >= 1 (odd with ``constant``: ``2 n_modes + 1``); None
        selects the order from the largest singular-value gap.
    hankel_size : int, optional
        Number of block rows of the Hankel matrix, an integer in ``[2, N - 1]`` (default: about
        N/(channels+1), at most 300/channels).
    constant : bool, optional
        Whether the sequence may contain a constant (offset) state; it affects the order selection and the rank
        check (default True).

    Returns
    -------
    A : ndarray, shape (n_poles, n_poles)
        Discrete state matrix.
    C : ndarray, shape (channels, n_poles)
        Output matrix.
    x0 : ndarray, shape (n_poles,)
        Initial state.
    singular_values : ndarray
        Singular values of the block Hankel matrix.
    n_poles : int
        The state dimension used.
    hankel_size : int
        The number of block rows used.

    Examples
    --------
    >>> import numpy as np
    >>> a = np.array([[0.9, 0.2], [-0.2, 0.9]])
    >>> seq = np.array([[np.linalg.matrix_power(a, j)[0] @ [1.0, 0.0] for j in range(20)]])
    >>> A, C, x0, sv, n, rows = realize(seq, 2, constant=False)
    >>> np.allclose(np.sort_complex(np.linalg.eigvals(A)), np.sort_complex(np.linalg.eigvals(a)))
    True
    """
    u, s, vt, order, r = _hankel_svd(y, n_poles, hankel_size, constant)
    a, c, x0 = _realization(u, s, vt, order, y.shape[0])
    return a, c, x0, s, order, r


def _hankel_svd(y: np.ndarray, order: int | None, rows: int | None, constant: bool):
    """SVD of the block Hankel matrix, the (checked or selected) order and the number of block rows."""
    nch, n = y.shape
    r = _default_rows(n, nch, order) if rows is None else int(rows)
    if r < 2 or r > n - 1:
        raise ParameterError(f"hankel_size (block rows) must be in [2, {n - 1}] for {n} samples, got {rows!r}")
    h = _hankel(y, r)
    u, s, vt = np.linalg.svd(h, full_matrices=False)
    if order is None:
        order = _select_order(s, constant, max_order=min((r - 1) * nch, h.shape[1]) // 2 * 2)
    if order > min((r - 1) * nch, h.shape[1]):
        raise ParameterError(
            f"order {order} is larger than the Hankel matrix ({r} block rows x {h.shape[1]} columns) supports; "
            "lower n_modes or pass more rows / a longer record"
        )
    _check_rank(s, order, spare=bool(constant) and order % 2 == 1)
    return u, s, vt, order, r


def _realization(u: np.ndarray, s: np.ndarray, vt: np.ndarray, order: int, nch: int):
    """Kung's balanced realisation ``(A, C, x0)`` from the first ``order`` singular triplets."""
    sq = np.sqrt(s[:order])
    gamma = u[:, :order] * sq
    a, *_ = np.linalg.lstsq(gamma[:-nch], gamma[nch:], rcond=None)
    return a, gamma[:nch], sq * vt[:order, 0]


@validated
@renamed_keyword({"order": "n_poles", "rows": "hankel_size"})
def era(
    signals: Any,
    dt: float,
    n_modes: int | None = None,
    *,
    n_poles: int | None = None,
    constant: bool = True,
    hankel_size: int | None = None,
    nyquist_margin: float = 0.95,
) -> ModalEstimate:
    """Kung / ERA estimate of damped modes shared by all channels of a free-decay record.

    Parameters
    ----------
    signals : array_like, shape (samples,) or (channels, samples)
        Real samples at t = 0, dt, 2 dt, ...: finite, at least 4 per channel, not all zero.
    dt : float
        Sampling period (s); must be positive and finite.
    n_modes : int, optional
        Number of oscillatory modes, an integer >= 1.  If neither it nor ``n_poles`` is given, the order is selected
        from the largest gap of the Hankel singular values (returned in ``singular_values``).
    n_poles : int, optional
        State dimension, ``2 n_modes + 1`` with the constant (offset) state, e.g. 7 = 1 + 2*3 in the dissertation.
    constant : bool
        Include a constant (offset) state.
    hankel_size : int, optional
        Number of block rows of the Hankel matrix (default: about N/(channels+1), at most 300/channels).
    nyquist_margin : float
        A pole above this fraction of the Nyquist frequency is reported as aliasing (IdentificationError).

    Returns
    -------
    ModalEstimate
        ``details`` holds the realisation ``A`` (discrete), ``C``, ``x0``, the recipe's ``Q`` and ``hankel_size``.

    See Also
    --------
    matrix_pencil
    esprit
    prony
    two_stage
    refine

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(300) * 0.01
    >>> y = np.vstack([np.cos(20 * t) + np.cos(31 * t), np.cos(20 * t) - 0.5 * np.cos(31 * t)]) + 0.1
    >>> est = era(y, 0.01)
    >>> est.n_poles, np.round(est.frequencies, 8).tolist()
    (5, [20.0, 31.0])
    >>> np.round(est.mode_shapes, 8).tolist()
    [[1.0, 1.0], [1.0, -0.5]]
    """
    y, dt, p = _prepare(signals, dt, n_modes, n_poles, constant, "Hankel realization")
    u, s, vt, p, r = _hankel_svd(y, p, hankel_size, constant)

    def poles_at(k: int) -> tuple[np.ndarray, dict[str, Any]]:
        a, c, x0 = _realization(u, s, vt, k, y.shape[0])
        z, t = np.linalg.eig(a)
        try:
            q = (c @ t) * np.linalg.solve(t, x0)[None, :]
        except np.linalg.LinAlgError:  # defective realisation: keep going, Q is only informative
            q = np.full((c.shape[0], z.size), np.nan + 0j)
        return z, {"A": a, "C": c, "x0": x0, "Q": q, "discrete_poles": z, "hankel_size": r}

    return _subspace_estimate(
        y, dt, p, constant, poles_at, method="era", singular_values=s, nyquist_margin=nyquist_margin
    )
