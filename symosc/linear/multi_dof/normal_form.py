"""Normal coordinates of first-order systems ``(A D + H) y = x`` (Bulgakov (1954), §8.52–8.53)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError
from .._util import as_real_array

__all__ = ["NormalForm", "modal_normal_form"]


@dataclass(frozen=True)
class NormalForm(SymPyPrintable):
    """Result of :func:`modal_normal_form`.

    Attributes
    ----------
    eigenvalues : ndarray
        Roots ``λ_k`` of ``det(A λ + H) = 0``.
    v : ndarray
        Right modal matrix, ``(A λ_k + H) v_k = 0``.
    z : ndarray
        Left modal matrix with ``z A v = E`` and ``z H v = -diag(λ)``; ``y = v ξ`` gives the decoupled normal
        equations ``ξ' = diag(λ) ξ + z x`` (8.53).
    condition : float
        ``cond(v)``: large for nearly defective pencils, where the normal form loses accuracy.
    """

    eigenvalues: np.ndarray
    v: np.ndarray
    z: np.ndarray
    condition: float

    def __repr__(self) -> str:
        return f"NormalForm(eigenvalues={np.round(self.eigenvalues, 12).tolist()}, condition={self.condition:.3g})"


@validated
def modal_normal_form(A: Any, H: Any, *, max_condition: float = 1e12) -> NormalForm:
    """Normal form ``z A v = E``, ``z H v = -Λ`` of ``(A D + H) y = x`` with nonsingular ``A`` (§8.53).

    A second-order system ``M ÿ + C ẏ + K y = x`` is first brought to this form with ``A = [[C, M], [M, 0]]``,
    ``H = [[K, 0], [0, -M]]`` on ``(y, ẏ)``.

    Parameters
    ----------
    A : array_like, shape (n, n)
        Coefficient of ``D``: a finite real nonsingular square matrix.
    H : array_like, shape (n, n)
        Coefficient of ``y``: a finite real square matrix of the same size as ``A``.
    max_condition : float, optional
        Largest acceptable ``cond(v)`` (> 0); a larger one means a (nearly) defective pencil and raises ModelError.

    Returns
    -------
    NormalForm

    Raises
    ------
    ModelError
        Singular ``A`` (the system is not in normal form; constraints must be eliminated first) or a defective
        pencil (``cond(v) > max_condition``).

    Examples
    --------
    >>> import numpy as np
    >>> from symosc.linear import modal_normal_form
    >>> nf = modal_normal_form(np.eye(2), [[0, -1], [4, 0]])      # y1' = y2, y2' = -4 y1
    >>> np.sort_complex(nf.eigenvalues).round(12).tolist()
    [-2j, 2j]

    See Also
    --------
    fundamental_solutions, conservative_modes
    """
    from scipy.linalg import eig

    A = as_real_array(A, "A", 2)
    H = as_real_array(H, "H", 2)
    n = A.shape[0]
    if A.shape != (n, n) or H.shape != (n, n):
        raise ModelError(f"A and H must be square of one size, got {A.shape} and {H.shape}")
    s = np.linalg.svd(A, compute_uv=False)
    if s[-1] <= 1e-13 * max(s[0], 1e-300):
        raise ModelError(
            "A is singular: the system is not in normal form (the degree of det(Aλ + H) is below n); eliminate the "
            "algebraic constraints first"
        )
    lam, v = eig(-H, A)
    cond = float(np.linalg.cond(v))
    if not np.isfinite(cond) or cond > max_condition:
        raise ModelError(f"the pencil is (nearly) defective: cond(v) = {cond:.3g}; normal coordinates do not exist")
    z = np.linalg.inv(A @ v)
    return NormalForm(lam, v, z, cond)
