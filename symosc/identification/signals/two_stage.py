"""Two-stage structure-preserving identification (Belyakov 2005, Ch. II §3.2 (b)–(c), eqs 48–54).

A first realisation of the sampled record gives the continuous poles ``lambda_k`` and complex amplitudes ``h_ck``
(``y = A0 + sum 2 Re h_k exp(lambda_k t)``).  The continuous Markov parameters of the free response are the
derivatives at t = 0, ``S_j = sum_k 2 Re(h_k lambda_k^(j-1))`` (eq. 48).  For ``q'' = A q``, ``y = C q`` they split
into ``S_(2k-1) = C A^(k-1) q0`` (eq. 52) and ``S_(2k) = C A^(k-1) v0`` (eq. 53); Kung's algorithm on the odd
subsequence returns ``(A, C, q0)`` directly in second-order form, with ``A ~ -M^-1 K`` up to a similarity.
"Identification is thus done twice."  Time is rescaled by the largest ``|lambda|`` so that the Markov parameters
stay O(1).

The trick is exact for conservative systems (no damping, A_d = 0 in eq. 46).  With damping the poles
``lambda_k`` are replaced by ``i |lambda_k|`` before the Markov parameters are formed (stage 3 of Belyakov's
recipe, justified by Ch. III §4: for modal damping ``|lambda|`` is the undamped frequency and for small damping it
is correct to O(eps^2)); the decay rates stay available in ``first_stage``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import IdentificationError, ParameterError
from ._signals import ModalEstimate
from .era import era, realize

__all__ = ["SecondOrderModel", "two_stage"]


@dataclass(frozen=True, repr=False, eq=False)
class SecondOrderModel(SymPyPrintable):
    """Second-order model ``q'' = A q``, ``y = C q``, ``q(0) = q0``, ``q'(0) = v0`` in an identified basis.

    Attributes
    ----------
    A, C, q0, v0 : ndarray
        Real realisation (A is similar to ``-M^-1 K`` for an undamped system).
    markov_odd, markov_even : ndarray, shape (channels, L)
        The continuous Markov parameters S_1, S_3, ... and S_2, S_4, ... (in units of the time scale).
    time_scale : float
        The Markov parameters were computed for time measured in units of ``1/time_scale`` s.
    singular_values : ndarray
        Hankel singular values of the second realisation.
    first_stage : ModalEstimate
        The first identification.
    """

    A: np.ndarray
    C: np.ndarray
    q0: np.ndarray
    v0: np.ndarray
    markov_odd: np.ndarray
    markov_even: np.ndarray
    time_scale: float
    singular_values: np.ndarray
    first_stage: ModalEstimate

    @property
    def eigenvalues(self) -> np.ndarray:
        """Eigenvalues of A sorted by modulus (``-omega^2`` for an undamped system)."""
        mu = np.linalg.eigvals(self.A)
        return mu[np.argsort(np.abs(mu))]

    @property
    def frequencies(self) -> np.ndarray:
        """``sqrt|mu|`` (rad/s): the undamped frequencies (``|lambda|`` of the first stage)."""
        return np.sqrt(np.abs(self.eigenvalues))

    @property
    def mode_shapes(self) -> np.ndarray:
        """Normal-coordinate observation matrix C' with q0' = (1, ..., 1): ``sign(Re Q) |Q|``,
        ``Q = C T diag(T^-1 q0)`` where ``A = T diag(mu) T^-1`` (stage 3 of Belyakov's recipe)."""
        mu, t = np.linalg.eig(self.A)
        order = np.argsort(np.abs(mu))
        t = t[:, order]
        q = (self.C @ t) * np.linalg.solve(t, self.q0.astype(complex))[None, :]
        return np.where(q.real < 0, -1.0, 1.0) * np.abs(q)

    def __repr__(self) -> str:
        return (
            f"SecondOrderModel(n={self.A.shape[0]}, channels={self.C.shape[0]}, "
            f"frequencies={np.array2string(self.frequencies, precision=8)}, "
            f"|v0|/|q0|={np.linalg.norm(self.v0) / max(np.linalg.norm(self.q0), 1e-300):.3g})"
        )


@validated
def two_stage(
    signals: Any,
    dt: float,
    n_modes: int | None = None,
    *,
    first: Callable[..., ModalEstimate] = era,
    markov_terms: int | None = None,
    **kwargs: Any,
) -> SecondOrderModel:
    """Identify ``(A, C, q0, v0)`` of ``q'' = A q, y = C q`` from a free-decay record (Belyakov's two-stage variant).

    Parameters
    ----------
    signals : array_like, shape (samples,) or (channels, samples)
        Real samples at t = 0, dt, 2 dt, ...: finite, at least 4 per channel, not all zero (as for
        :func:`~symosc.identification.era`).
    dt : float
        Sampling period (s); must be positive and finite.
    n_modes : int, optional
        Number of oscillatory modes, an integer >= 1; None lets the first stage select the order.
    first : callable
        First-stage estimator (``era`` by default; any estimator of this package, or a refined one).
    markov_terms : int, optional
        Number of odd Markov parameters used in the second realisation (default ``2 n_modes + 4``).
    **kwargs
        Passed to ``first``.

    Examples
    --------
    Two uncoupled modes seen by two sensors, released from rest:

    >>> import numpy as np
    >>> t = np.arange(400) * 0.01
    >>> q = np.vstack([0.002 * np.cos(5.0 * t), 0.001 * np.cos(9.0 * t)])
    >>> y = np.array([[1.0, 1.0], [1.0, -2.0]]) @ q
    >>> model = two_stage(y, 0.01, 2, constant=False)
    >>> np.round(model.frequencies, 9).tolist(), np.round(model.eigenvalues.real, 6).tolist()
    ([5.0, 9.0], [-25.0, -81.0])
    >>> np.round(model.mode_shapes * 1e3, 9).tolist(), bool(np.abs(model.v0).max() < 1e-9)
    ([[2.0, 1.0], [2.0, -2.0]], True)
    """
    est = first(signals, dt, n_modes, **kwargs)
    if not isinstance(est, ModalEstimate):
        raise ParameterError(f"the first stage must return a ModalEstimate, got {type(est).__name__}")
    n = est.n_modes
    terms = 2 * n + 4 if markov_terms is None else int(markov_terms)
    if terms < 2 * n + 1:
        raise ParameterError(f"markov_terms must be at least 2 n_modes + 1 = {2 * n + 1}, got {markov_terms!r}")
    scale = float(np.max(np.abs(est.poles)))
    lam = 1j * np.abs(est.poles) / scale  # conservative projection (exact when undamped)
    h = est.complex_amplitudes  # (c, n)
    j = np.arange(2 * terms)
    markov = 2.0 * np.real(h @ (lam[:, None] ** j[None, :]))  # S_{j+1}, (c, 2*terms)
    odd, even = markov[:, 0::2], markov[:, 1::2]
    a, c, q0, sv, _, _ = realize(odd, n, hankel_size=terms // 2 + 1, constant=False)
    # v0 from S_{2k} = C A^{k-1} v0 (least squares over the observability matrix)
    obs = np.vstack([c @ np.linalg.matrix_power(a, k) for k in range(terms)])
    v0, *_ = np.linalg.lstsq(obs, even.T.reshape(-1), rcond=None)
    if not np.all(np.isfinite(a)):
        raise IdentificationError("two_stage: the second realisation failed (non-finite A)")
    return SecondOrderModel(
        A=a * scale**2,
        C=c,
        q0=q0,
        v0=v0 * scale,
        markov_odd=odd,
        markov_even=even,
        time_scale=scale,
        singular_values=sv,
        first_stage=est,
    )
