"""State-space and transfer-function export of linear models (python-control, or SciPy without it)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import sympy as sp

from .._control import control_module, lti_state_space
from ..errors import ModelError, ParameterError
from ..numeric import bind
from ..symbols import t

__all__ = ["state_space", "state_space_matrices", "transfer_function"]


def _selection(model: Any, spec: Any, what: str) -> np.ndarray:
    """``n x k`` matrix selecting coordinates (by Symbol, name or index), or a numeric matrix given as is."""
    q = model.coordinates
    n = len(q)
    if spec is None:
        return np.eye(n)
    if isinstance(spec, np.ndarray) and spec.ndim == 2:
        if spec.shape[0] != n:
            raise ParameterError(f"{what} matrix must have {n} rows (one per coordinate), got shape {spec.shape}")
        return spec.astype(float)
    items = [spec] if isinstance(spec, str | int | sp.Symbol) else list(spec)
    names = [s.name for s in q]
    cols = []
    for it in items:
        if isinstance(it, int | np.integer) and not isinstance(it, bool):
            idx = int(it)
        else:
            name = it.name if isinstance(it, sp.Symbol) else str(it)
            if name not in names:
                raise ParameterError(f"{what}: {name!r} is not a coordinate of the model; choose from {names}")
            idx = names.index(name)
        if not 0 <= idx < n:
            raise ParameterError(f"{what}: index {idx} out of range for {n} coordinates")
        e = np.zeros(n)
        e[idx] = 1.0
        cols.append(e)
    return np.column_stack(cols)


def state_space_matrices(
    model: Any,
    *,
    inputs: Any = None,
    outputs: Any = None,
    values: Mapping[Any, Any] | None = None,
    velocities: bool = False,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Numeric ``(A, B, C, D)`` of ``M q'' + D q' + K q = E u``, ``y = q_out`` with state ``x = (q, q')``."""
    values = values or {}
    mats = [bind(m, values) for m in (model.M, model.D, model.K)]
    if any(t in m.free_symbols for m in mats):
        raise ModelError(
            "the stiffness depends on time (a vibrating pivot): the model is not time-invariant; set the "
            "excitation amplitude to 0 in values, or analyse it with symosc.periodic"
        )
    free = sorted({str(s) for m in mats for s in m.free_symbols})
    if free:
        raise ParameterError(f"missing values for: {', '.join(free)}")
    M, Dm, K = (np.array(m.evalf(), dtype=float) for m in mats)
    n = M.shape[0]
    try:
        Minv = np.linalg.inv(M)
    except np.linalg.LinAlgError as err:
        raise ModelError("the mass matrix is singular at these values") from err
    E = _selection(model, inputs, "inputs")
    S = _selection(model, outputs, "outputs").T
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ Dm]])
    B = np.vstack([np.zeros((n, E.shape[1])), Minv @ E])
    C = np.hstack([np.zeros_like(S), S]) if velocities else np.hstack([S, np.zeros_like(S)])
    D = np.zeros((C.shape[0], B.shape[1]))
    return A, B, C, D


def state_space(
    model: Any,
    *,
    inputs: Any = None,
    outputs: Any = None,
    values: Mapping[Any, Any] | None = None,
    velocities: bool = False,
    backend: str = "auto",
) -> Any:
    """``control.StateSpace`` (SciPy ``StateSpace`` without python-control) of a linear model."""
    A, B, C, D = state_space_matrices(model, inputs=inputs, outputs=outputs, values=values, velocities=velocities)
    return lti_state_space(A, B, C, D, backend=backend)


def transfer_function(
    model: Any,
    *,
    inputs: Any = None,
    outputs: Any = None,
    values: Mapping[Any, Any] | None = None,
    velocities: bool = False,
    backend: str = "auto",
) -> Any:
    """``control.TransferFunction`` (MIMO allowed) or SciPy's (single input only) of a linear model."""
    A, B, C, D = state_space_matrices(model, inputs=inputs, outputs=outputs, values=values, velocities=velocities)
    ct = None if backend == "scipy" else control_module(required=backend == "control")
    if backend not in ("auto", "control", "scipy"):
        raise ParameterError(f"backend must be 'auto', 'control' or 'scipy', got {backend!r}")
    if ct is not None:
        return ct.ss2tf(ct.ss(A, B, C, D))
    if B.shape[1] != 1:
        raise ParameterError(
            "SciPy transfer functions have one input: pass a single input, or install python-control for MIMO"
        )
    from scipy import signal

    num, den = signal.ss2tf(A, B, C, D)
    scale = np.max(np.abs(num)) if num.size else 0.0
    num = np.where(np.abs(num) <= 1e-12 * scale, 0.0, num)  # round-off in the structurally zero leading terms
    if num.shape[0] == 1:
        num = np.trim_zeros(num[0], "f")
    return signal.TransferFunction(num, den)
