"""Argument checks shared by the public functions (private).

Each helper raises :class:`~symosc.errors.ParameterError` naming the argument, what was given and what is
expected, so bad input never surfaces as a NumPy/SymPy exception from deep inside.
"""

from __future__ import annotations

import difflib
import numbers
from collections.abc import Iterable
from typing import Any

import numpy as np

from .errors import ParameterError

__all__ = [
    "check_bool",
    "check_choice",
    "check_complete_names",
    "check_finite",
    "check_finite_array",
    "check_int",
    "check_known_names",
    "check_positive",
]


def _show(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def check_finite(name: str, value: Any) -> float:
    """``value`` as a finite float (bool, None, strings and nan/inf are refused)."""
    if isinstance(value, bool) or value is None or isinstance(value, str | bytes):
        raise ParameterError(f"{name} must be a finite real number, got {_show(value)}")
    try:
        out = float(value)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a finite real number, got {_show(value)}") from exc
    if not np.isfinite(out):
        raise ParameterError(f"{name} must be finite, got {out}")
    return out


def check_positive(name: str, value: Any, *, allow_zero: bool = False) -> float:
    """``value`` as a finite float that is > 0 (or >= 0 with ``allow_zero``)."""
    out = check_finite(name, value)
    if out < 0 or (out == 0 and not allow_zero):
        raise ParameterError(f"{name} must be {'>= 0' if allow_zero else 'positive'}, got {out}")
    return out


def check_int(name: str, value: Any, *, minimum: int | None = None, maximum: int | None = None) -> int:
    """``value`` as an int (integral floats such as ``3.0`` pass; ``1.5``, nan, strings, bools do not)."""
    if isinstance(value, bool) or value is None or isinstance(value, str | bytes):
        raise ParameterError(f"{name} must be an integer, got {_show(value)}")
    if isinstance(value, numbers.Integral):
        out = int(value)
    else:
        try:
            f = float(value)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"{name} must be an integer, got {_show(value)}") from exc
        if not np.isfinite(f) or f != int(f):
            raise ParameterError(f"{name} must be an integer, got {_show(value)}")
        out = int(f)
    if minimum is not None and out < minimum:
        raise ParameterError(f"{name} must be >= {minimum}, got {out}")
    if maximum is not None and out > maximum:
        raise ParameterError(f"{name} must be <= {maximum}, got {out}")
    return out


def check_bool(name: str, value: Any) -> bool:
    """``value`` as a bool; only True/False (and NumPy bools) are accepted, not strings such as ``"yes"``."""
    if isinstance(value, bool | np.bool_):
        return bool(value)
    raise ParameterError(f"{name} must be True or False, got {_show(value)}")


def _suggest(value: Any, choices: Iterable[Any]) -> str:
    names = [str(c) for c in choices]
    close = difflib.get_close_matches(str(value), names, n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def check_choice(name: str, value: Any, choices: Iterable[Any]) -> Any:
    """``value`` if it is one of ``choices``; otherwise an error listing them with the closest match."""
    choices = tuple(choices)
    try:
        ok = value in choices
    except TypeError:
        ok = False
    if not ok:
        raise ParameterError(
            f"unknown {name} {_show(value)}{_suggest(value, choices)}; choose one of {', '.join(map(repr, choices))}"
        )
    return value


def check_known_names(what: str, given: Iterable[Any], valid: Iterable[Any]) -> None:
    """Raise when ``given`` holds names that are not in ``valid`` (misspelt parameters go unnoticed otherwise)."""
    valid_names = {str(v): v for v in valid}
    unknown = [g for g in given if str(g) not in valid_names]
    if unknown:
        hints = "".join(_suggest(u, valid_names) for u in unknown[:1])
        raise ParameterError(f"unknown {what} {sorted(map(str, unknown))}{hints}; valid names: {sorted(valid_names)}")


def check_complete_names(what: str, given: Iterable[Any], needed: Iterable[Any]) -> None:
    """Raise when a needed name is missing, listing the unknown names given (with the closest match).

    Extra names are harmless when every needed name is present (a shared dict of values); when one is missing, an
    unknown name given instead is most likely a misspelling, and the error says so.
    """
    given_names = [str(getattr(g, "name", g)) for g in given]
    needed_names = [str(getattr(v, "name", v)) for v in needed]
    missing = sorted(set(needed_names) - set(given_names))
    if not missing:
        return
    unknown = [g for g in given_names if g not in needed_names]
    hints = [f"{u!r} -> {close[0]!r}" for u in unknown if (close := difflib.get_close_matches(u, missing, n=1))]
    extra = f"; unknown {what} given: {', '.join(sorted(unknown))}" if unknown else ""
    hint = f" (misspelt? {', '.join(hints)})" if hints else ""
    raise ParameterError(f"missing values for: {', '.join(missing)}{extra}{hint}; valid names: {sorted(needed_names)}")


def check_finite_array(name: str, value: Any, *, ndim: int | None = None, complex_ok: bool = False) -> np.ndarray:
    """``value`` as a finite float (or complex) ndarray, optionally of a given number of dimensions."""
    if value is None or isinstance(value, str | bytes):
        raise ParameterError(f"{name} must be an array of numbers, got {_show(value)}")
    try:
        arr = np.asarray(value, dtype=complex if complex_ok else float)
    except (TypeError, ValueError) as exc:
        raise ParameterError(
            f"{name} must be an array of {'complex' if complex_ok else 'real'} numbers: {exc}"
        ) from exc
    if ndim is not None and arr.ndim != ndim:
        raise ParameterError(f"{name} must have {ndim} dimension(s), got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{name} must contain only finite numbers (found nan or inf)")
    return arr
