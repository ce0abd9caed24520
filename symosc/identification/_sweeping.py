"""Helpers shared by the Monte Carlo studies that run through :func:`symosc.sweep` (private)."""

from __future__ import annotations

from typing import Any

from ..errors import SymoscError


def raise_first_failure(res: Any, what: str) -> None:
    """Errors other than the counted identification failures stop the study, as they would in a plain loop."""
    if res.failures:
        f = res.failures[0]
        raise SymoscError(f"{what} failed at {f.params}: {f.error}\n{f.traceback}")
