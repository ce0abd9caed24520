"""Routh's criteria from quadratic forms (Bulgakov (1954), §8.16, statements 1°–7°).

For ``[A D² + (N + G) D + (H + J)] y = 0`` with symmetric ``A, N, H`` (inertia, dissipation, potential) and
skew-symmetric ``G, J`` (gyroscopic, non-conservative positional), the signs of the forms decide where the roots
can lie without computing them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError
from .._util import as_real_array

__all__ = ["QuadraticFormVerdict", "routh_form_criteria"]


@dataclass(frozen=True)
class QuadraticFormVerdict(SymPyPrintable):
    """Result of :func:`routh_form_criteria`.

    Attributes
    ----------
    signs : dict
        ``"A"``, ``"N"``, ``"H"`` → one of ``"positive definite"``, ``"positive semidefinite"``, ``"zero"``,
        ``"negative definite"``, ``"negative semidefinite"``, ``"indefinite"``.
    real_roots : str
        What 1°–3° say about real roots.
    complex_roots : str
        What 4°–7° say about complex roots.
    asymptotically_stable : bool or None
        True when ``A, N, H > 0`` and ``J = 0`` (1° + 4°); None when the criteria do not decide.
    """

    signs: dict
    real_roots: str
    complex_roots: str
    asymptotically_stable: bool | None

    def __repr__(self) -> str:
        return (
            f"QuadraticFormVerdict(real roots: {self.real_roots}; complex roots: {self.complex_roots}; "
            f"asymptotically_stable={self.asymptotically_stable})"
        )


def _sign(X: np.ndarray, tol: float) -> str:
    if np.abs(X).max() == 0:
        return "zero"
    w = np.linalg.eigvalsh(X)
    s = tol * np.abs(w).max()
    if w[0] > s:
        return "positive definite"
    if w[-1] < -s:
        return "negative definite"
    if w[0] >= -s:
        return "positive semidefinite"
    if w[-1] <= s:
        return "negative semidefinite"
    return "indefinite"


@validated
def routh_form_criteria(
    A: Any, N: Any = None, G: Any = None, H: Any = None, J: Any = None, *, tol: float = 1e-12
) -> QuadraticFormVerdict:
    """Apply Routh's quadratic-form statements 1°–7° (Bulgakov (1954), §8.16, eqs. (8.104)–(8.116)).

    Parameters
    ----------
    A, N, H : array_like
        Symmetric inertia, dissipation and potential matrices (``N``, ``H`` default to zero).
    G, J : array_like
        Skew-symmetric gyroscopic and circulatory matrices (default zero).
    tol : float
        Relative eigenvalue tolerance for definiteness.

    Returns
    -------
    QuadraticFormVerdict

    Examples
    --------
    >>> from symosc.linear import routh_form_criteria
    >>> v = routh_form_criteria([[1, 0], [0, 1]], H=[[2, 0], [0, 3]], G=[[0, 1], [-1, 0]])
    >>> v.complex_roots
    'purely imaginary (5°)'

    See Also
    --------
    hurwitz
    """
    A = as_real_array(A, "A", 2)
    n = A.shape[0]
    Z = np.zeros((n, n))
    mats = {"A": A}
    for name, X in (("N", N), ("G", G), ("H", H), ("J", J)):
        mats[name] = Z if X is None else as_real_array(X, name, 2)
        if mats[name].shape != (n, n):
            raise ModelError(f"{name} must be {n}x{n} like A, got {mats[name].shape}")
    for name in "ANH":
        if not np.allclose(mats[name], mats[name].T):
            raise ModelError(f"{name} must be symmetric (the skew part belongs in G or J)")
    for name in "GJ":
        if not np.allclose(mats[name], -mats[name].T):
            raise ModelError(f"{name} must be skew-symmetric")
    signs = {name: _sign(mats[name], tol) for name in "ANH"}
    pos = {k: v.startswith("positive") or v == "zero" for k, v in signs.items()}
    neg = {k: v.startswith("negative") or v == "zero" for k, v in signs.items()}
    same = all(pos.values()) or all(neg.values())
    j_zero = not np.any(mats["J"])
    g_zero = not np.any(mats["G"])
    definite = {k: v.endswith("definite") and "semi" not in v for k, v in signs.items()}
    real = "not decided"
    if same and signs["N"] != "zero" and definite["H"]:
        real = "negative (1°)"
    elif signs["N"] == "zero" and (all(pos[k] for k in "AH") or all(neg[k] for k in "AH")) and definite["H"]:
        real = "none (2°)"
    elif same and definite["H"]:
        real = "negative (1°)"
    comp = "not decided"
    if same and definite["N"] and j_zero:
        comp = "negative real parts (4°)"
    elif (
        signs["N"] == "zero"
        and j_zero
        and (all(pos[k] for k in "AH") or all(neg[k] for k in "AH"))
        and (definite["A"] or definite["H"])
    ):
        comp = "purely imaginary (5°)"
    elif g_zero and j_zero and definite["N"] and (pos["A"] == pos["N"] or neg["A"] == neg["N"]):
        comp = "negative real parts (6°)"
    elif (
        g_zero and j_zero and ((pos["A"] and neg["H"]) or (neg["A"] and pos["H"])) and (definite["A"] or definite["H"])
    ):
        comp = "none (7°)"
    stable = None
    if all(definite.values()) and same and j_zero:
        stable = True
    elif comp == "purely imaginary (5°)" or real == "none (2°)":
        stable = False
    return QuadraticFormVerdict(signs, real, comp, stable)
