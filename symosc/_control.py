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

__all__ = ["control_module", "lti_state_space", "transfer_function_from_expr"]


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


def lti_state_space(A: Any, B: Any, C: Any, D: Any, *, backend: str = "auto") -> Any:
    """``control.StateSpace`` (backend ``"control"`` or ``"auto"`` with control installed) or SciPy's."""
    if backend not in ("auto", "control", "scipy"):
        raise ParameterError(f"backend must be 'auto', 'control' or 'scipy', got {backend!r}")
    ct = None if backend == "scipy" else control_module(required=backend == "control")
    if ct is not None:
        return ct.ss(A, B, C, D)
    from scipy import signal

    return signal.StateSpace(A, B, C, D)


def _coefficients(poly_expr: sp.Expr, s: sp.Symbol) -> np.ndarray:
    poly = sp.Poly(sp.expand(poly_expr), s)
    coeffs = poly.all_coeffs()
    try:
        return np.array([complex(c) for c in coeffs]).real if all(sp.im(c) == 0 for c in coeffs) else None
    except TypeError as err:
        free = sorted(str(x) for x in poly_expr.free_symbols - {s})
        raise ParameterError(f"the transfer function still has free symbols {free}; pass values= for them") from err


def transfer_function_from_expr(
    expr: Any, s: sp.Symbol, values: Mapping[Any, Any] | None = None, *, backend: str = "auto"
) -> Any:
    """A SISO transfer function ``expr(s)`` (rational in ``s``) as a ``control.TransferFunction`` (or SciPy's).

    ``s`` is the Laplace variable; a ratio of Carson images ``Y(p)/U(p)`` is the same function of ``p``.
    """
    from .numeric import bind

    e = bind(expr, values) if values else sp.sympify(expr)
    num, den = sp.fraction(sp.cancel(sp.together(e)))
    if not (num.is_polynomial(s) and den.is_polynomial(s)):
        raise ModelError(f"{expr} is not rational in {s}: only rational transfer functions convert (no delays)")
    n, d = _coefficients(num, s), _coefficients(den, s)
    if n is None or d is None:
        raise ModelError("complex coefficients: the transfer function is not real")
    lead = d[0]
    n, d = n / lead, d / lead
    if backend not in ("auto", "control", "scipy"):
        raise ParameterError(f"backend must be 'auto', 'control' or 'scipy', got {backend!r}")
    ct = None if backend == "scipy" else control_module(required=backend == "control")
    if ct is not None:
        return ct.tf(n, d)
    from scipy import signal

    return signal.TransferFunction(n, d)
