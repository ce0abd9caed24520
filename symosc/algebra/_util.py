"""Input checking shared by the algebra modules (private)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import sympy as sp

from ..errors import ModelError, ParameterError


def as_square_matrix(A: Any, what: str = "A") -> sp.Matrix:
    """Return ``A`` as a mutable SymPy Matrix, raising ModelError unless it is square and non-empty."""
    if isinstance(A, np.ndarray):
        A = sp.Matrix(A.tolist())
    elif not isinstance(A, sp.MatrixBase):
        try:
            A = sp.Matrix(A)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"{what} must be a square SymPy Matrix, got {type(A).__name__}") from exc
    A = sp.Matrix(A)
    r, c = A.shape
    if r != c or r == 0:
        raise ModelError(f"{what} must be a non-empty square matrix, got shape {r}x{c}")
    return A


def is_float_matrix(A: sp.Matrix) -> bool:
    """True when every entry is a number and at least one is a floating-point number."""
    if A.free_symbols:
        return False
    return any(e.has(sp.Float) for e in A)


def as_scalar_function(f: Any, var: sp.Symbol | None = None) -> tuple[sp.Expr, sp.Symbol]:
    """Normalise ``f`` to ``(expr, x)`` with ``expr`` a SymPy expression in the dummy ``x``.

    ``f`` may be a one-argument :class:`~sympy.Lambda`, a SymPy function class such as ``sympy.exp``, a
    Python callable that accepts a SymPy symbol, or an expression in ``var``.
    """
    x = sp.Dummy("x")
    if isinstance(f, sp.Lambda):
        if len(f.variables) != 1:
            raise ParameterError(f"f must be a Lambda of one variable, got {len(f.variables)} variables")
        return sp.sympify(f(x)), x
    if isinstance(f, sp.FunctionClass) or (callable(f) and not isinstance(f, sp.Basic)):
        try:
            expr = sp.sympify(_call(f, x))
        except (TypeError, ValueError, sp.SympifyError) as exc:
            raise ParameterError(f"cannot apply f={f!r} to a SymPy symbol: {exc}") from exc
        return expr, x
    expr = sp.sympify(f)
    if var is None:
        free = expr.free_symbols
        if len(free) != 1:
            raise ParameterError(
                "f is an expression; say which symbol is the variable with var=..., or pass a sympy.Lambda "
                f"(free symbols: {sorted(map(str, free))})"
            )
        var = next(iter(free))
    if not isinstance(var, sp.Symbol):
        raise ParameterError(f"var must be a SymPy Symbol, got {var!r}")
    return expr.xreplace({var: x}), x


def _call(f: Callable, x: sp.Symbol) -> Any:
    return f(x)


def has_singular_value(value: sp.Expr) -> bool:
    """True when a SymPy value is infinite or undefined (zoo, oo, nan)."""
    value = sp.sympify(value)
    return bool(value.has(sp.zoo, sp.oo, -sp.oo, sp.nan))
