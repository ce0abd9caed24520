"""The contract between a periodic boundary-value formulation and the continuation driver (private).

A formulation (harmonic balance, shooting, collocation) holds a :class:`~._model.PeriodicModel` and fixed
parameter values, and maps an unknown vector ``u`` (Fourier coefficients, an initial state, collocation values;
with the frequency for autonomous problems) and the parameter vector ``p`` to the residual ``G(u, p)`` with its
exact Jacobians ``G_u`` and ``G_p``.  The continuation driver only uses this contract.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np


@dataclass
class PointData:
    """What a converged point reports: amplitudes (max |q_i|), base angular frequency, relative residual,
    Floquet multipliers, and the formulation's own data (Fourier coefficients or the orbit's initial state)."""

    amplitudes: np.ndarray
    frequency: float
    residual: float
    multipliers: np.ndarray
    coefficients: np.ndarray | None
    initial_state: np.ndarray
    size: int


class Formulation:
    """Base class of the periodic formulations (see the module docstring)."""

    #: name shown in results
    method: str = ""
    model: Any
    values: np.ndarray
    autonomous: bool

    def evaluate(self, u: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, Any, np.ndarray]:
        """``G``, ``G_u`` (dense ndarray or sparse matrix) and ``G_p`` (dense, one column per parameter)."""
        raise NotImplementedError

    def weights(self, u: np.ndarray) -> np.ndarray:
        """Weights of the unknowns in the arclength inner product."""
        return np.ones(len(u))

    def begin_step(self, u: np.ndarray) -> None:
        """Called with the last accepted point before each corrector (reference of the phase condition)."""

    def point(self, u: np.ndarray, p: np.ndarray, *, stability: bool = True) -> PointData:
        raise NotImplementedError

    def adapt(self, u: np.ndarray, p: np.ndarray, data: PointData) -> tuple[Any, Any] | None:
        """A refined formulation and the unknowns transferred to it when the point's residual exceeds the
        tolerance (None: keep going).  ``transfer(v)`` maps any vector of this formulation to the new one."""
        return None

    def frequency_of(self, u: np.ndarray, p: np.ndarray) -> float:
        raise NotImplementedError
