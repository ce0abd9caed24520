"""Argument checks shared by the nonlinear modules (private)."""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..errors import ParameterError


def expression(name: str, value: Any, *, real: bool = False) -> sp.Expr:
    """``value`` as a SymPy expression without nan or infinities (numbers, symbols, expressions; text and None
    refused); with ``real`` a number or symbol known to be non-real is refused too."""
    what = "a finite real number or a real SymPy expression" if real else "a finite SymPy expression"
    if value is None or isinstance(value, str | bytes | bool):
        raise ParameterError(f"{name} must be {what}, got {value!r}")
    try:
        out = sp.sympify(value)
    except (sp.SympifyError, TypeError) as exc:
        raise ParameterError(f"{name} must be {what}, got {value!r}") from exc
    if not isinstance(out, sp.Expr) or out.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise ParameterError(f"{name} must be {what}, got {value!r}")
    if real and out.is_extended_real is False:
        raise ParameterError(f"{name} must be {what}, got {value!r}")
    return out


def symbol(name: str, value: Any) -> sp.Symbol:
    """``value`` if it is a SymPy Symbol."""
    if not isinstance(value, sp.Symbol):
        raise ParameterError(f"{name} must be a SymPy Symbol, got {value!r}")
    return value
