"""Argument checks of compiled functions: a generic (slow, thorough) path and generated fast-path conditions."""

from __future__ import annotations

from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ..errors import ParameterError


def check_value(symbol: sp.Symbol, value: Any, backend: str) -> Any:
    """Validate one argument value against finiteness and the symbol's sign assumptions.

    Returns the value converted for the backend (a plain Python scalar for 0-d NumPy input).
    """
    if backend == "mpmath":
        try:
            v = mpmath.mpmathify(value)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"{symbol.name}: cannot convert {value!r} to an mpmath number") from exc
        finite = mpmath.isfinite(v)
        real = not isinstance(v, mpmath.mpc)
        arr_min = v if real else None
    else:
        if value is None:
            raise ParameterError(f"{symbol.name}: expected a number, got None")
        v = np.asarray(value)
        if v.dtype == object:
            try:
                v = v.astype(float)
            except (TypeError, ValueError) as exc:
                raise ParameterError(f"{symbol.name}: cannot convert {value!r} to a number") from exc
        if not np.issubdtype(v.dtype, np.number) and v.dtype != bool:
            raise ParameterError(f"{symbol.name}: expected a number, got {value!r}")
        finite = bool(np.all(np.isfinite(v)))
        real = not np.iscomplexobj(v)
        arr_min = (v.min() if v.size else None) if real else None
    if not finite:
        raise ParameterError(f"{symbol.name} must be finite, got {value!r}")
    if symbol.is_real and not real:
        raise ParameterError(f"{symbol.name} is declared real but got a complex value {value!r}")
    if arr_min is not None:
        if symbol.is_positive and not arr_min > 0:
            raise ParameterError(f"{symbol.name} must be positive (declared positive), got {value!r}")
        if symbol.is_nonnegative and not arr_min >= 0:
            raise ParameterError(f"{symbol.name} must be non-negative (declared nonnegative), got {value!r}")
    if backend != "mpmath" and v.ndim == 0:
        return v.item()  # a plain scalar keeps the generated code on its scalar fast path
    return v


def check_all(symbols: tuple[sp.Symbol, ...], values: tuple[Any, ...], backend: str) -> tuple[Any, ...]:
    """Check the argument count and every value; raise :class:`ParameterError` naming the first bad one."""
    if len(values) != len(symbols):
        names = ", ".join(s.name for s in symbols)
        raise ParameterError(f"expected {len(symbols)} arguments ({names}), got {len(values)}")
    return tuple(check_value(s, v, backend) for s, v in zip(symbols, values, strict=True))


def python_condition(symbol: sp.Symbol, name: str) -> str:
    """A Python boolean expression, true when the float ``name`` passes the checks of ``symbol``.

    ``v - v == 0.0`` is false exactly for NaN and infinities, and costs one subtraction.
    """
    if symbol.is_positive:
        return f"0.0 < {name} < _INF"
    if symbol.is_nonnegative:
        return f"0.0 <= {name} < _INF"
    return f"{name} - {name} == 0.0"


def c_condition(symbol: sp.Symbol, name: str) -> str:
    """The C99 test of ``python_condition`` (false for NaN through the comparisons)."""
    if symbol.is_positive:
        return f"(0.0 < {name} && {name} < INFINITY)"
    if symbol.is_nonnegative:
        return f"(0.0 <= {name} && {name} < INFINITY)"
    return f"isfinite({name})"


def nonfinite_message(name: str, symbols: tuple[sp.Symbol, ...], values: tuple[Any, ...]) -> str:
    """The warning text for an evaluation that gave inf/NaN from finite arguments (e.g. 1/x at x = 0)."""
    shown = ", ".join(f"{s.name}={_short(v)}" for s, v in zip(symbols, values, strict=False))
    return (
        f"{name}: evaluation gave non-finite values (a division by zero or a value outside a function's domain) "
        f"at {shown}"
    )


def _short(v: Any) -> str:
    if isinstance(v, float):
        return repr(v)
    arr = np.asarray(v)
    return repr(v) if arr.size <= 4 else f"<array of shape {arr.shape}>"
