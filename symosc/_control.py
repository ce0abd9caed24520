"""Bridge to python-control (optional) and SciPy's LTI objects.

``python-control`` is imported inside the functions; without it SciPy's ``StateSpace`` / ``TransferFunction`` are
returned (SciPy's transfer functions are single-input).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import sympy as sp

from .errors import ModelError, ParameterError

__all__ = ["control_module", "lti_state_space", "transfer_function_from_expr", "transfer_function_from_matrix"]


def control_module(required: bool = False) -> Any:
    """The ``control`` package, or None when it is not installed (an ImportError naming the extra if required)."""
    try:
        import control
    except ImportError as err:
        if required:
            raise ImportError(
                "this needs python-control: pip install 'symosc[control]' (or pip install control)"
            ) from err
        return None
    return control


def lti_state_space(A: Any, B: Any, C: Any, D: Any, *, backend: str = "auto", names: Mapping | None = None) -> Any:
    """``control.StateSpace`` (backend ``"control"`` or ``"auto"`` with control installed) or SciPy's.

    ``names`` (``{"inputs": [...], "outputs": [...], "states": [...]}``) labels the signals of the python-control
    system (SciPy's systems have no labels).
    """
    if backend not in ("auto", "control", "scipy"):
        raise ParameterError(f"backend must be 'auto', 'control' or 'scipy', got {backend!r}")
    ct = None if backend == "scipy" else control_module(required=backend == "control")
    if ct is not None:
        return ct.ss(A, B, C, D, **dict(names or {}))
    from scipy import signal

    return signal.StateSpace(A, B, C, D)


def _coefficients(poly_expr: sp.Expr, s: sp.Symbol) -> list[sp.Expr]:
    """Exact coefficients of a polynomial in ``s``, highest power first (a ParameterError for free symbols)."""
    poly = sp.Poly(sp.expand(poly_expr), s)
    coeffs = poly.all_coeffs()
    free = sorted({str(x) for c in coeffs for x in sp.sympify(c).free_symbols})
    if free:
        raise ParameterError(f"the transfer function still has free symbols {free}; pass values= for them")
    return coeffs


def _rounded(coeffs: list[sp.Expr], what: str) -> np.ndarray:
    values = [complex(sp.N(c, 20)) for c in coeffs]
    if any(v.imag for v in values):
        raise ModelError(f"complex coefficients in the {what}: the transfer function is not real")
    return np.array([v.real for v in values])


def _ratio(expr: Any, s: sp.Symbol) -> tuple[np.ndarray, np.ndarray]:
    """Numerator and denominator coefficients of a rational function of ``s``, normalised exactly to a monic
    denominator and rounded once, at the end."""
    num, den = sp.fraction(sp.cancel(sp.together(sp.sympify(expr))))
    if not (num.is_polynomial(s) and den.is_polynomial(s)):
        raise ModelError(f"{expr} is not rational in {s}: only rational transfer functions convert (no delays)")
    n, d = _coefficients(num, s), _coefficients(den, s)
    lead = d[0]
    return _rounded([c / lead for c in n], "numerator"), _rounded([c / lead for c in d], "denominator")


def transfer_function_from_matrix(H: Any, s: sp.Symbol, *, backend: str = "auto", names: Mapping | None = None) -> Any:
    """A rational transfer matrix ``H(s)`` (SymPy) as ``control.TransferFunction`` (MIMO, named signals with
    ``names = {"inputs": [...], "outputs": [...]}``) or, for one input and one output, SciPy's."""
    if backend not in ("auto", "control", "scipy"):
        raise ParameterError(f"backend must be 'auto', 'control' or 'scipy', got {backend!r}")
    H = sp.Matrix(H)
    parts = [[_ratio(H[i, j], s) for j in range(H.shape[1])] for i in range(H.shape[0])]
    ct = None if backend == "scipy" else control_module(required=backend == "control")
    if ct is not None:
        num = [[n for n, _ in row] for row in parts]
        den = [[d for _, d in row] for row in parts]
        return ct.tf(num, den, **dict(names or {}))
    from scipy import signal

    if H.shape[1] != 1:
        raise ParameterError("SciPy transfer functions have one input: pass a single input, or install python-control")
    if H.shape[0] == 1:
        return signal.TransferFunction(*parts[0][0])
    # one input, several outputs: SciPy wants a common denominator
    common = sp.lcm([sp.fraction(sp.cancel(h))[1] for h in H])
    rows = [sp.cancel(h * common) for h in H]
    den = _coefficients(common, s)
    nums = [_coefficients(r, s) for r in rows]
    width = max(len(c) for c in nums)
    nums = [[sp.S.Zero] * (width - len(c)) + list(c) for c in nums]
    lead = den[0]
    return signal.TransferFunction(
        np.array([_rounded([c / lead for c in row], "numerator") for row in nums]),
        _rounded([c / lead for c in den], "denominator"),
    )


def transfer_function_from_expr(
    expr: Any, s: sp.Symbol, values: Mapping[Any, Any] | None = None, *, backend: str = "auto"
) -> Any:
    """A SISO transfer function ``expr(s)`` (rational in ``s``) as a ``control.TransferFunction`` (or SciPy's).

    ``s`` is the Laplace variable; a ratio of Carson images ``Y(p)/U(p)`` is the same function of ``p``.
    """
    from .numeric import bind

    e = bind(expr, values) if values else sp.sympify(expr)
    return transfer_function_from_matrix(sp.Matrix([[e]]), s, backend=backend)
