"""Effect of damping on the identified model (Belyakov Ch. III §4, eqs 90–106).

``M q'' + D q' + K q = 0``.  The quadratic eigenproblem ``(lambda^2 M + lambda D + K) u = 0`` is solved by
:func:`symosc.mechanics.complex_modes` (its ``natural_frequencies`` are the undamped-frequency estimates
``|lambda|`` of eq. (97), its ``mode_shape_moduli`` the moduli of stage 3; ``quadratic_modes``, which did the same
for symmetric matrices, is a deprecated alias).  :func:`damping_perturbation` gives the
first-order theory for small damping ``eps D``: ``lambda = i omega + eps lambda_1 + O(eps^2)`` with
``lambda_1 = -u0^T D u0 / (2 u0^T M u0)`` (real), and ``u = u0 + eps u1`` with ``u1`` purely imaginary (eq. 106),
so frequencies and mode-shape moduli change only at O(eps^2).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ModelError, ParameterError

__all__ = ["DampingPerturbation", "damping_perturbation"]


def _mats(m: Any, d: Any, k: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    mats = [np.atleast_2d(np.asarray(a, dtype=float)) for a in (m, d, k)]
    n = mats[0].shape[0]
    for name, a in zip("MDK", mats, strict=True):
        if a.shape != (n, n) or not np.all(np.isfinite(a)):
            raise ParameterError(f"{name} must be a finite {n}x{n} matrix, got shape {a.shape}")
        if not np.allclose(a, a.T, rtol=1e-12, atol=0):
            raise ParameterError(f"{name} must be symmetric")
    try:
        np.linalg.cholesky(mats[0])
    except np.linalg.LinAlgError:
        raise ModelError("the mass matrix M is not positive definite") from None
    return mats[0], mats[1], mats[2]


@dataclass(frozen=True, eq=False)
class QuadraticModes(SymPyPrintable):
    """Eigenpairs of ``lambda^2 M + lambda D + K`` with Im(lambda) >= 0, sorted by ``|lambda|``.

    ``vectors[:, j]`` is normalised to unit Euclidean norm with its largest component real and positive.
    ``undamped_frequencies`` = ``|lambda|`` (eq. 97), ``mode_shape_moduli`` = signed moduli
    ``sign(Re u) |u|`` scaled like the vectors (stage 3 of Belyakov's recipe).

    Attributes
    ----------
    eigenvalues : ndarray of complex, shape (n,)
        Eigenvalues ``lambda_j`` with positive imaginary part, sorted by ``|lambda|``.
    vectors : ndarray of complex, shape (n, n)
        Eigenvectors ``u_j`` as columns (unit Euclidean norm, largest component real and positive).
    """

    eigenvalues: np.ndarray
    vectors: np.ndarray

    @property
    def undamped_frequencies(self) -> np.ndarray:
        """``|lambda_j|`` (rad/s)."""
        return np.abs(self.eigenvalues)

    @property
    def damping_ratios(self) -> np.ndarray:
        """``-Re lambda / |lambda|``."""
        return -self.eigenvalues.real / np.abs(self.eigenvalues)

    @property
    def mode_shape_moduli(self) -> np.ndarray:
        """``sign(Re u) |u|`` per component (the real mode shape recovered from a complex one)."""
        return np.where(self.vectors.real < 0, -1.0, 1.0) * np.abs(self.vectors)


def quadratic_modes(mass: Any, damping: Any, stiffness: Any) -> QuadraticModes:
    """Deprecated: use :func:`symosc.mechanics.complex_modes` (the same eigenproblem, also for gyroscopic,
    circulatory, overdamped and growing systems).

    The oscillatory half of ``complex_modes``' roots (``Im lambda > 0``), for symmetric ``M``, ``D``, ``K`` with
    ``M`` positive definite; an overdamped mode raises ModelError.

    Parameters
    ----------
    mass : array_like, shape (n, n)
        Mass matrix ``M``: a finite symmetric positive definite matrix (a scalar means a 1x1 matrix).
    damping : array_like, shape (n, n)
        Damping matrix ``D``: a finite symmetric matrix of the same size as ``mass``.
    stiffness : array_like, shape (n, n)
        Stiffness matrix ``K``: a finite symmetric matrix of the same size as ``mass``.

    Returns
    -------
    QuadraticModes
    """
    from .._deprecation import warn_deprecated
    from ..mechanics import complex_modes

    warn_deprecated("symosc.identification.quadratic_modes", "symosc.mechanics.complex_modes")
    m, d, k = _mats(mass, damping, stiffness)
    modes = complex_modes(m, d, k)
    lam = modes.eigenvalues
    sel = lam.imag > 1e-12 * np.maximum(np.abs(lam), 1e-300)
    n = m.shape[0]
    if sel.sum() != n:
        raise ModelError(
            f"{n - int(sel.sum())} mode(s) are overdamped (real eigenvalues); |lambda| is no longer a frequency"
        )
    return QuadraticModes(eigenvalues=lam[sel], vectors=modes.vectors[:, sel])


@dataclass(frozen=True, eq=False)
class DampingPerturbation(SymPyPrintable):
    """First-order small-damping theory (eqs 99–106).

    Attributes
    ----------
    frequencies : ndarray
        Undamped ``omega_j`` (rad/s).
    modes : ndarray
        Undamped modes ``U0``, mass-normalised (``U0^T M U0 = I``).
    lambda1 : ndarray
        ``-u0^T D u0 / (2 u0^T M u0)`` per mode (real): the first-order change of the eigenvalue.
    u1 : ndarray (complex)
        First-order eigenvector corrections (purely imaginary), normalised by ``u0_j^T u1_j = 0``.
    """

    frequencies: np.ndarray
    modes: np.ndarray
    lambda1: np.ndarray
    u1: np.ndarray

    def eigenvalues(self, eps: float = 1.0) -> np.ndarray:
        """First-order eigenvalues ``i omega + eps lambda1``.

        Parameters
        ----------
        eps : float, optional
            Scale of the damping matrix (the system's damping is ``eps D``); a finite number, small for the
            first-order theory to hold (default 1: the ``D`` given).
        """
        return 1j * self.frequencies + eps * self.lambda1

    def vectors(self, eps: float = 1.0) -> np.ndarray:
        """First-order eigenvectors ``u0 + eps u1``.

        Parameters
        ----------
        eps : float, optional
            Scale of the damping matrix (the system's damping is ``eps D``); a finite number, small for the
            first-order theory to hold (default 1: the ``D`` given).
        """
        return self.modes + eps * self.u1


@validated
def damping_perturbation(mass: Any, damping: Any, stiffness: Any) -> DampingPerturbation:
    """First-order perturbation of the undamped modes by damping ``D`` (Vishik–Lyusternik; Belyakov eq. 100–106).

    Off-diagonal Sylvester solution (eq. 106) in the mass-normalised basis ``X = U0^{-1} U1``:
    ``X_jk = -i omega_k Dt_jk / (omega_j^2 - omega_k^2)``, ``Dt = U0^T D U0``; the diagonal follows from
    ``u0_k^T u1_k = 0``.  Requires distinct undamped frequencies.

    Parameters
    ----------
    mass : array_like, shape (n, n)
        Mass matrix ``M``: a finite symmetric positive definite matrix (a scalar means a 1x1 matrix).
    damping : array_like, shape (n, n)
        Damping matrix ``D``: a finite symmetric matrix of the same size as ``mass``.
    stiffness : array_like, shape (n, n)
        Stiffness matrix ``K``: a finite symmetric matrix of the same size as ``mass``; positive definite, with
        distinct undamped frequencies.

    Returns
    -------
    DampingPerturbation

    Examples
    --------
    >>> p = damping_perturbation(np.eye(2), 0.01 * np.eye(2), np.diag([1.0, 4.0]))
    >>> p.lambda1.tolist(), np.abs(p.u1).max()
    ([-0.005, -0.005], np.float64(0.0))
    """
    m, d, k = _mats(mass, damping, stiffness)
    import scipy.linalg as sla

    w2, u0 = sla.eigh(k, m)
    if np.any(w2 <= 0):
        raise ModelError("the stiffness matrix must be positive definite for oscillatory modes")
    w = np.sqrt(w2)
    gaps = np.abs(np.subtract.outer(w2, w2)) + np.eye(w.size) * np.max(w2)
    if np.min(gaps) <= 1e-9 * np.max(w2):
        raise ModelError("repeated undamped frequencies: first-order perturbation needs distinct frequencies")
    dt = u0.T @ d @ u0
    lam1 = -np.diag(dt) / 2.0  # u0^T M u0 = 1
    with np.errstate(divide="ignore", invalid="ignore"):
        x = -1j * dt * w[None, :] / np.subtract.outer(w2, w2)
    np.fill_diagonal(x, 0.0)
    g = u0.T @ u0
    diag = -np.einsum("kj,jk->k", g, x) / np.diag(g)
    x[np.diag_indices_from(x)] = diag
    return DampingPerturbation(frequencies=w, modes=u0, lambda1=lam1, u1=u0 @ x)
