"""Maximum-likelihood refinement of a modal estimate by variable projection (Golub & Pereyra 1973).

In white Gaussian noise the maximum-likelihood estimate minimises ``||y - V(lambda) h||``.  For fixed poles the
amplitudes ``h`` are a linear least-squares problem, so only the poles are iterated: the residual
``(I - V V^+) y`` is minimised over ``(delta_k, omega_k)`` with scipy's trust-region least squares, starting from
a subspace estimate (matrix pencil, ESPRIT or ERA).  Near the solution this attains the Cramér–Rao bound
(see :func:`~symosc.identification.cramer_rao_bound` and ``benchmarks/identification_crlb.py``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..._validate import validated
from ...errors import ConvergenceError, ParameterError
from ._signals import ModalEstimate, _as_signals, _basis, _fit

__all__ = ["refine"]


@validated
def refine(estimate: ModalEstimate, signals: Any, *, max_nfev: int = 200, xtol: float = 1e-12) -> ModalEstimate:
    """Refine the poles of ``estimate`` on ``signals`` by nonlinear least squares (variable projection).

    Parameters
    ----------
    estimate : ModalEstimate
        Starting point, e.g. from :func:`~symosc.identification.matrix_pencil` on the same signals.
    signals : array_like
        The record the estimate was made from (same ``dt``, same channels).
    max_nfev : int, optional
        Largest number of function evaluations per fitted pole parameter (an integer >= 1); times the number of
        parameters, it is passed to :func:`scipy.optimize.least_squares`.
    xtol : float, optional
        Tolerance (> 0) for termination by the change of the pole parameters, passed to
        :func:`scipy.optimize.least_squares`.

    Returns
    -------
    ModalEstimate
        ``method`` is the original name with ``"+ml"``; ``details["nfev"]`` and ``details["cost"]`` report the
        optimisation.

    Raises
    ------
    ConvergenceError
        When the optimiser stops without meeting its tolerances.

    Examples
    --------
    >>> import numpy as np
    >>> from symosc.identification import matrix_pencil
    >>> t = np.arange(100) * 0.1
    >>> rng = np.random.default_rng(1)
    >>> y = np.exp(-0.05 * t) * np.cos(2.0 * t) + 0.01 * rng.standard_normal(100)
    >>> est = refine(matrix_pencil(y, 0.1, 1, constant=False), y)
    >>> est.method, abs(float(est.frequencies[0]) - 2.0) < 1e-3
    ('matrix_pencil+ml', True)
    """
    from scipy.optimize import least_squares

    if not isinstance(estimate, ModalEstimate):
        raise ParameterError(f"refine() needs a ModalEstimate, got {type(estimate).__name__}")
    y, dt = _as_signals(signals, estimate.dt)
    if y.shape[0] != estimate.n_channels:
        raise ParameterError(f"signals have {y.shape[0]} channels but the estimate has {estimate.n_channels}")
    constant = estimate.n_poles % 2 == 1
    t = np.arange(y.shape[1]) * dt
    k = estimate.n_modes
    scale = np.abs(estimate.poles).max()

    def residual(theta: np.ndarray) -> np.ndarray:
        lam = scale * (-theta[:k] + 1j * theta[k:])
        v = _basis(lam, t, constant)
        coef, *_ = np.linalg.lstsq(v, y.T, rcond=None)
        return (y.T - v @ coef).ravel()

    theta0 = np.concatenate([estimate.damping, estimate.frequencies]) / scale
    sol = least_squares(
        residual, theta0, method="lm", xtol=xtol, ftol=1e-14, gtol=1e-14, max_nfev=max_nfev * theta0.size
    )
    if sol.status <= 0:
        raise ConvergenceError(f"refine: least squares did not converge ({sol.message})", achieved=float(sol.cost))
    lam = scale * (-sol.x[:k] + 1j * sol.x[k:])
    order = np.argsort(lam.imag)
    details = dict(estimate.details)
    details.update(nfev=int(sol.nfev), cost=float(sol.cost), start=estimate.poles)
    return _fit(
        y,
        dt,
        lam[order],
        constant=constant,
        method=estimate.method + "+ml",
        singular_values=estimate.singular_values,
        details=details,
    )
