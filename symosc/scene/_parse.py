"""Small validators for scene values: each raises :class:`SceneError` naming the key, expectation and fix."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import sympy as sp

from .._parsing import ExpressionError, parse_expression
from ._errors import SceneError, closest
from ._units import UnitError, parse_quantity

__all__ = ["Ctx", "parse_sympy"]


class Ctx:
    """Where values come from (file path, text for line numbers) and how to report a bad one."""

    def __init__(self, path: str, text: str) -> None:
        self.path, self.text = path, text

    def error(self, key: str, message: str, fix: str = "") -> SceneError:
        from ._errors import locate

        return SceneError(self.path, key, message, line=locate(self.text, key) if key else None, fix=fix)

    # ---------------------------------------------------------------- tables and keys
    def table(self, value: Any, key: str) -> Mapping[str, Any]:
        if not isinstance(value, Mapping):
            raise self.error(key, f"expected a table, got {type(value).__name__} {value!r}", f"write [{key}] ...")
        return value

    def check_keys(self, table: Mapping[str, Any], valid: Sequence[str], where: str, what: str = "key") -> None:
        for k in table:
            if k not in valid:
                key = f"{where}.{k}" if where else k
                raise self.error(
                    key,
                    f"unknown {what} '{k}'.{closest(k, valid)} Valid {what}s here: {', '.join(valid) or 'none'}",
                    f"rename or remove '{k}'",
                )

    def require(self, table: Mapping[str, Any], name: str, where: str, hint: str) -> Any:
        if name not in table:
            raise self.error(where, f"missing required key '{name}'", f"add {name} = {hint}")
        return table[name]

    # ---------------------------------------------------------------- scalars
    def integer(self, value: Any, key: str, *, minimum: int = 1) -> int:
        if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
            raise self.error(
                key, f"expected an integer >= {minimum}, got {value!r}", f"write {key.split('.')[-1]} = {minimum}"
            )
        return value

    def boolean(self, value: Any, key: str) -> bool:
        if not isinstance(value, bool):
            raise self.error(
                key, f"expected true or false, got {value!r}", "write true or false (lower case, no quotes)"
            )
        return value

    def choice(self, value: Any, key: str, choices: Sequence[str]) -> str:
        if not isinstance(value, str) or value not in choices:
            hint = closest(str(value), choices)
            raise self.error(
                key,
                f"expected one of {', '.join(map(repr, choices))}, got {value!r}.{hint}",
                f"use one of {', '.join(choices)}",
            )
        return value

    def string(self, value: Any, key: str) -> str:
        if not isinstance(value, str):
            raise self.error(key, f"expected a string, got {value!r}", "put the text in double quotes")
        return value

    def quantity(self, value: Any, key: str, dimension: str | None, *, positive: bool = False) -> float:
        try:
            x = parse_quantity(value, dimension)
        except UnitError as exc:
            raise self.error(key, str(exc), 'give a number in SI units or a string such as "45 mm"') from None
        if positive and not x > 0:
            raise self.error(key, f"expected a positive value, got {value!r}", "give a value > 0")
        return x

    def quantities(self, value: Any, key: str, dimension: str | None, *, positive: bool = False) -> list[float]:
        if isinstance(value, str | int | float) and not isinstance(value, bool):
            value = [value]
        if not isinstance(value, list) or not value:
            raise self.error(
                key, f"expected a non-empty list of values, got {value!r}", f"write {key.split('.')[-1]} = [1.0, 2.0]"
            )
        return [self.quantity(v, f"{key}", dimension, positive=positive) for v in value]

    def span(self, value: Any, key: str, dimension: str | None) -> tuple[float, float]:
        vals = self.quantities(value, key, dimension)
        if len(vals) != 2 or not vals[0] < vals[1]:
            raise self.error(
                key, f"expected [low, high] with low < high, got {value!r}", f"write {key.split('.')[-1]} = [0.5, 1.5]"
            )
        return vals[0], vals[1]


def parse_sympy(
    ctx: Ctx, text: Any, key: str, symbols: Mapping[str, Any], functions: Mapping[str, Any] | None = None
) -> sp.Expr:
    """The expression written at ``key``: numbers as exact numbers, text parsed (never evaluated) by
    :func:`symosc._parsing.parse_expression`; a name not in ``symbols`` is a positive Symbol (so ``I``, ``E``, ``N``,
    ``gamma`` are symbols too)."""
    if isinstance(text, int | float) and not isinstance(text, bool):
        if not math.isfinite(text):
            raise ctx.error(key, f"expected a finite number, got {text!r}", "give a finite number")
        return sp.nsimplify(text)
    text = ctx.string(text, key)
    try:
        return parse_expression(
            text,
            names=symbols,
            functions=functions,
            unknown=lambda name: sp.Symbol(name, positive=True),
            what=repr(text) if len(text) <= 60 else "the text",
        )
    except ExpressionError as exc:
        raise ctx.error(
            key, str(exc), 'write arithmetic of names, numbers and functions, e.g. "m*l**2*phi_dot**2/2"'
        ) from None
