"""Exact transfer matrices, state-space and transfer-function export of linear models (python-control or SciPy).

The transfer matrix ``H(s) = C (M s**2 + D s + K)**-1 E`` is formed exactly (SymPy's ``DomainMatrix`` over the
field of rational functions of ``s`` and the parameters; numeric values enter as the exact rationals of the floats
given), so structurally zero coefficients stay zero; ``to_transfer_function`` rounds each coefficient once, at the
end.  Signals are named after the model: inputs ``Q_q`` (the generalized force on coordinate ``q``) or the force
symbols of the excitation, outputs and states after the coordinates and their rates.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import sympy as sp
from sympy.polys.matrices import DomainMatrix
from sympy.polys.matrices.exceptions import DMNonInvertibleMatrixError

from .._control import control_module, lti_state_space, transfer_function_from_matrix
from ..errors import ModelError, ParameterError
from ..numeric import bind
from ..symbols import dot, t

__all__ = ["exact_transfer_matrix", "state_space", "state_space_matrices", "transfer_function"]

S = sp.Symbol("s")


def _design(model: Any, spec: Any, what: str) -> tuple[sp.Matrix, list[str]]:
    """``n x k`` matrix (SymPy) selecting coordinates (by Symbol, name or index) or the force symbols of the
    excitation ``f`` (inputs only), or a matrix given as is; with the names of the ``k`` signals."""
    q = model.coordinates
    n = len(q)
    prefix = "Q_" if what == "inputs" else ""
    if spec is None:
        return sp.eye(n), [f"{prefix}{s.name}" for s in q]
    if isinstance(spec, np.ndarray | sp.MatrixBase) and len(getattr(spec, "shape", ())) == 2:
        if spec.shape[0] != n:
            raise ParameterError(f"{what} matrix must have {n} rows (one per coordinate), got shape {spec.shape}")
        letter = "u" if what == "inputs" else "y"
        return sp.Matrix(spec), [f"{letter}{j}" for j in range(spec.shape[1])]
    items = [spec] if isinstance(spec, str | int | sp.Symbol) else list(spec)
    names = [s.name for s in q]
    forces = {s.name: s for s in model.f.free_symbols - {t}} if what == "inputs" else {}
    cols, labels = [], []
    for it in items:
        if isinstance(it, int | np.integer) and not isinstance(it, bool):
            idx = int(it)
            if not 0 <= idx < n:
                raise ParameterError(f"{what}: index {idx} out of range for {n} coordinates")
        else:
            name = it.name if isinstance(it, sp.Symbol) else str(it)
            if name in forces and name not in names:  # a force symbol: its column of the excitation
                cols.append(model.f.diff(forces[name]))
                labels.append(name)
                continue
            if name not in names:
                extra = f", or a force symbol of the excitation: {sorted(forces)}" if forces else ""
                raise ParameterError(f"{what}: {name!r} is not a coordinate of the model; choose from {names}{extra}")
            idx = names.index(name)
        cols.append(sp.Matrix([int(i == idx) for i in range(n)]))
        labels.append(f"{prefix}{names[idx]}")
    return sp.Matrix.hstack(*cols), labels


def _output_names(model: Any, outputs: Any, velocities: bool) -> tuple[sp.Matrix, list[str]]:
    S_, names = _design(model, outputs, "outputs")
    if velocities:
        by_name = {q.name: dot(q).name for q in model.coordinates}
        names = [by_name.get(nm, f"{nm}_dot") for nm in names]
    return S_, names


def _state_names(model: Any) -> list[str]:
    return [q.name for q in model.coordinates] + [dot(q).name for q in model.coordinates]


def _time_free(model: Any, mats: list) -> None:
    if any(t in m.free_symbols for m in mats):
        raise ModelError(
            "the stiffness depends on time (a vibrating pivot): the model is not time-invariant; set the "
            "excitation amplitude to 0 in values, or analyse it with symosc.periodic"
        )


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
    E_sym, _ = _design(model, inputs, "inputs")
    S_sym, _ = _output_names(model, outputs, velocities)
    mats = [bind(m, values) for m in (model.M, model.D, model.K, E_sym, S_sym)]
    _time_free(model, mats)
    free = sorted({str(s) for m in mats for s in m.free_symbols})
    if free:
        raise ParameterError(f"missing values for: {', '.join(free)}")
    M, Dm, K, E, S_ = (np.array(m.evalf(), dtype=float) for m in mats)
    n = M.shape[0]
    try:
        Minv = np.linalg.inv(M)
    except np.linalg.LinAlgError as err:
        raise ModelError("the mass matrix is singular at these values") from err
    S_ = S_.T
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ Dm]])
    B = np.vstack([np.zeros((n, E.shape[1])), Minv @ E])
    C = np.hstack([np.zeros_like(S_), S_]) if velocities else np.hstack([S_, np.zeros_like(S_)])
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
    """``control.StateSpace`` with named signals (SciPy ``StateSpace`` without python-control) of a linear model."""
    A, B, C, D = state_space_matrices(model, inputs=inputs, outputs=outputs, values=values, velocities=velocities)
    names = {
        "inputs": _design(model, inputs, "inputs")[1],
        "outputs": _output_names(model, outputs, velocities)[1],
        "states": _state_names(model),
    }
    return lti_state_space(A, B, C, D, backend=backend, names=names)


def _exact_values(values: Mapping[Any, Any] | None) -> dict[str, sp.Expr]:
    """Values as exact SymPy numbers: a float becomes the shortest decimal that rounds to it (``9.81 -> 981/100``,
    what was typed), integers and SymPy numbers stay as they are."""
    out = {}
    for key, val in (values or {}).items():
        name = key.name if isinstance(key, sp.Symbol) else str(key)
        if isinstance(val, float | np.floating):
            v = sp.Rational(repr(float(val))) if np.isfinite(val) else sp.sympify(float(val))
        else:
            v = sp.sympify(val)
            v = sp.Rational(repr(float(v))) if isinstance(v, sp.Float) and v.is_finite else v
        out[name] = v
    return out


def _rational(m: sp.Matrix) -> sp.Matrix:
    """``m`` with its floats replaced by the decimals they print as (exact arithmetic from here on)."""
    floats = m.atoms(sp.Float)
    return m.xreplace({f: sp.Rational(repr(float(f))) for f in floats if f.is_finite}) if floats else m


def exact_transfer_matrix(
    model: Any,
    *,
    inputs: Any = None,
    outputs: Any = None,
    values: Mapping[Any, Any] | None = None,
    velocities: bool = False,
    s: sp.Symbol = S,
) -> sp.ImmutableMatrix:
    """``H(s) = C (M s**2 + D s + K)**-1 E`` exactly (entries cancelled rational functions of ``s``)."""
    exact = _exact_values(values)
    E, _ = _design(model, inputs, "inputs")
    S_, _ = _output_names(model, outputs, velocities)
    mats = [_rational(bind(m, exact)) for m in (model.M, model.D, model.K, E, S_)]
    _time_free(model, mats)
    M, Dm, K, E, S_ = mats
    if s in set().union(*(m.free_symbols for m in mats)):
        raise ParameterError(f"the Laplace variable {s} is also a parameter of the model; pass another s=")
    P = M * s**2 + Dm * s + K
    n = P.shape[0]
    whole = DomainMatrix.from_Matrix(P.row_join(E))
    if whole.domain.is_EX or whole.domain.is_EXRAW:
        X = P.LUsolve(E)
    else:
        field = whole.to_field()
        try:
            X = field[:, :n].lu_solve(field[:, n:]).to_Matrix()
        except DMNonInvertibleMatrixError as exc:
            raise ModelError("M s**2 + D s + K is singular for every s: the model has no transfer matrix") from exc
    H = S_.T * X
    if velocities:
        H = H * s
    return sp.ImmutableMatrix(H.applyfunc(sp.cancel))


def transfer_function(
    model: Any,
    *,
    inputs: Any = None,
    outputs: Any = None,
    values: Mapping[Any, Any] | None = None,
    velocities: bool = False,
    backend: str = "auto",
) -> Any:
    """``control.TransferFunction`` (MIMO allowed, named signals) or SciPy's (single input) of a linear model, from
    the exact transfer matrix (coefficients rounded once, at the end)."""
    if backend not in ("auto", "control", "scipy"):
        raise ParameterError(f"backend must be 'auto', 'control' or 'scipy', got {backend!r}")
    H = exact_transfer_matrix(model, inputs=inputs, outputs=outputs, values=values, velocities=velocities)
    free = sorted({str(x) for x in H.free_symbols} - {S.name})
    if free:
        raise ParameterError(f"missing values for: {', '.join(free)}")
    ct = None if backend == "scipy" else control_module(required=backend == "control")
    if ct is None and H.shape[1] != 1:
        raise ParameterError(
            "SciPy transfer functions have one input: pass a single input, or install python-control for MIMO"
        )
    names = {"inputs": _design(model, inputs, "inputs")[1], "outputs": _output_names(model, outputs, velocities)[1]}
    return transfer_function_from_matrix(H, S, backend="scipy" if ct is None else "control", names=names)
