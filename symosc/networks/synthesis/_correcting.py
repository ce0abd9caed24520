"""Helpers of the correcting-network module (private): realisability tests, duals, link catalogue."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import sympy as sp

from ...errors import ParameterError
from ..ports.oneports import Capacitor, Inductor, OnePort, Parallel, Resistor, Series


def dual(net: OnePort, W2: Any, scale: Callable[[Any, str], Any] | None = None) -> OnePort | None:
    """The inverse network with ``Z_dual = W2 / Z`` (series <-> parallel, L <-> C); None when it has no dual.

    ``scale(value, kind)`` computes the new values when given (``kind`` ``"R"``: the resistance ``W2/R``, ``"L"``:
    the capacitance ``L/W2``, ``"C"``: the inductance ``W2 C``), e.g. in exact field arithmetic; by default they
    are SymPy expressions."""
    if scale is None:
        scale = scale_expr(W2)
    if isinstance(net, Resistor):
        return Resistor(scale(net.R, "R"))
    if isinstance(net, Inductor):
        return Capacitor(scale(net.L, "L"))
    if isinstance(net, Capacitor):
        return Inductor(scale(net.C, "C"))
    if isinstance(net, Series | Parallel):
        parts = [dual(part, W2, scale) for part in net.parts]
        if any(part is None for part in parts):
            return None
        return Parallel(tuple(parts)) if isinstance(net, Series) else Series(tuple(parts))
    return None


def scale_expr(W2: sp.Expr) -> Callable[[sp.Expr, str], sp.Expr]:
    return lambda v, kind: W2 / v if kind == "R" else v / W2 if kind == "L" else W2 * v  # only the one needed


def positive(value: Any, name: str) -> sp.Expr:
    """A positive time constant or ratio (a number > 0 or a symbol not known to be non-positive)."""
    try:
        expr = sp.sympify(value)
    except (sp.SympifyError, TypeError) as exc:
        raise ParameterError(f"{name} must be a positive number, got {value!r}") from exc
    if not isinstance(expr, sp.Expr) or expr.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or expr.is_extended_real is False:
        raise ParameterError(f"{name} must be a positive real number, got {value!r}")
    if expr.is_positive is False:
        raise ParameterError(f"{name} = {expr} must be positive")
    return expr


def require_less(small: sp.Expr, large: sp.Expr, text: str) -> None:
    if (large - small).is_positive is False:
        raise ParameterError(text)


#: link name -> (Bulgakov's numeral, table, the transfer in words)
LINKS: dict[str, tuple[str, str, str]] = {
    "attenuator": ("I", "Table 8", "X = 1/k"),
    "lead": ("II", "Table 8", "X = (T2/(k T1)) (T1 p + 1)/(T2 p + 1), T1 > T2"),
    "lead-stabilizing": ("III", "Table 8", "X = (T2/(k T1)) (T1 p - 1)/(T2 p + 1), T1 > T2"),
    "lag": ("IV", "Table 8", "X = (1/k) (T1 p + 1)/(T2 p + 1), T1 < T2"),
    "lag-stabilizing": ("V", "Table 8", "X = (1/k) (T1 p - 1)/(T2 p + 1), T1 < T2"),
    "all-pass": ("VI", "Table 9", "X = (1/k) (T p - 1)/(T p + 1)"),
    "differentiating": ("VII", "Table 9", "X = (1/k) T p/(T p + 1)"),
    "low-pass": ("VIII", "Table 9", "X = (1/k) /(T p + 1)"),
    "second-order": ("IX-XV", "§9.39", "X = (1/k) (T1² p² + 2 ζ1 T1 p ± 1)/(T2² p² + 2 ζ2 T2 p + 1)"),
}
