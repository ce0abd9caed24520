"""The contract between a periodic boundary-value formulation and the continuation driver (private).

A formulation (harmonic balance, shooting, collocation) holds a :class:`~._model.PeriodicModel` and fixed
parameter values, and maps an unknown vector ``u`` (Fourier coefficients, an initial state, collocation values;
with the frequency for autonomous problems) and the parameter vector ``p`` to the residual ``G(u, p)`` with its
exact Jacobians ``G_u`` and ``G_p``.  The continuation driver (``arclength``, ``follow``, ``bifurcations``,
``folds``, ``stability``) only uses this contract: the methods with a leading underscore.  What a user calls is
``solve``, ``with_values``, :attr:`parameters` and :attr:`equations`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Self

import numpy as np
import sympy as sp

from .._validate import check_int
from ..errors import ParameterError
from ._model import PeriodicModel


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

    @property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """Every parameter of the model (the forcing frequency included), in the order of :attr:`values`."""
        return self.model.params

    @property
    def equations(self) -> str:
        """The equations of motion as text."""
        return self.model.describe

    def with_values(self, values: Mapping[Any, Any]) -> Self:
        """A copy of the problem with some parameter values changed (the others kept).

        Parameters
        ----------
        values : mapping of Symbol or str to float
            New values of some of the model's parameters, keyed by Symbol or name: each a finite number (positive
            for a symbol declared positive), and every key a parameter of the model.

        Returns
        -------
        HarmonicBalance, Shooting or Collocation
            A problem of the same kind and truncation.

        Raises
        ------
        ParameterError
            ``values`` is not a mapping, names an unknown parameter or holds a value that is not a finite number.

        Examples
        --------
        >>> import sympy as sp
        >>> from symosc.continuation import harmonic_balance
        >>> x, v, t, w, F = sp.symbols("x v t w F")
        >>> hb = harmonic_balance(-0.1 * v - x - x**3 + F * sp.cos(w * t), x, v, t, forcing_frequency=w,
        ...                       values={"F": 1.0, "w": 2.0}, harmonics=5)
        >>> hb.with_values({"F": 0.5}).values
        array([0.5, 2. ])
        """
        if not isinstance(values, Mapping):
            raise ParameterError(
                f"values must be a mapping from parameter (Symbol or name) to number, got {type(values).__name__}"
            )
        given = self.model.values_vector(values, skip=self.model.params)
        return self._with_vector(np.where(np.isnan(given), self.values, given))

    # ------------------------------------------------------------------ the driver's protocol
    def _with_values(self, values: Mapping[Any, Any]) -> Self:
        """``with_values`` without the checks of the values (the continuation may cross a declared sign)."""
        p = self.values.copy()
        for k, v in values.items():
            p[self.model.param_index(k)] = float(v)
        return self._with_vector(p)

    def _with_vector(self, p: np.ndarray) -> Self:
        """The same problem at the parameter vector ``p``."""
        raise NotImplementedError

    def _evaluate(self, u: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, Any, np.ndarray]:
        """``G``, ``G_u`` (dense ndarray or sparse matrix) and ``G_p`` (dense, one column per parameter)."""
        raise NotImplementedError

    def _weights(self, u: np.ndarray) -> np.ndarray:
        """Weights of the unknowns in the arclength inner product."""
        return np.ones(len(u))

    def _begin_step(self, u: np.ndarray) -> None:
        """Called with the last accepted point before each corrector (reference of the phase condition)."""

    def _point(self, u: np.ndarray, p: np.ndarray, *, stability: bool = True) -> PointData:
        """What the converged point ``u`` reports (multipliers only with ``stability``)."""
        raise NotImplementedError

    def _adapt(self, u: np.ndarray, p: np.ndarray, data: PointData) -> tuple[Any, Any] | None:
        """A refined formulation and the unknowns transferred to it when the point's residual exceeds the
        tolerance (None: keep going).  ``transfer(v)`` maps any vector of this formulation to the new one."""
        return None

    def _frequency_of(self, u: np.ndarray, p: np.ndarray) -> float:
        raise NotImplementedError


def checked_arguments(model: Any, values: Any, period_multiple: Any) -> tuple[np.ndarray, int]:
    """The constructor checks the three formulations share: the model, the parameter vector, the period multiple."""
    if not isinstance(model, PeriodicModel):
        raise ParameterError(
            "model must be the model built by harmonic_balance(), shooting() or collocation() (build the problem "
            f"with one of them), got {type(model).__name__}"
        )
    n = len(model.params)
    try:
        p = np.array(values, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"values must be a vector of {n} parameter values, got {type(values).__name__}") from exc
    if p.shape != (n,):
        raise ParameterError(
            f"values must be a vector of {n} parameter values (in the order {[s.name for s in model.params]}), "
            f"got shape {p.shape}"
        )
    if np.any(np.isinf(p)):
        raise ParameterError(f"values must be finite (nan marks a value not given yet), got {p}")
    period_multiple = check_int("period_multiple", period_multiple, minimum=1)
    if model.autonomous and period_multiple != 1:
        raise ParameterError(
            f"period_multiple must be 1 for an autonomous problem (its period is an unknown), got {period_multiple}"
        )
    return p, period_multiple
