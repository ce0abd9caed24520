"""Equality of models by their defining data (private): the same class, the same coordinates and parameters, and
the same expressions after expansion.

Models hold SymPy expressions that can be written in several ways (``m*(a + b)`` or ``m*a + m*b``); two models are
equal when the difference of each pair of defining expressions expands to zero.  Forms that only trigonometric or
other simplification identifies (``sin(x)**2 + cos(x)**2`` against ``1``) compare unequal.  The hash is taken from
the exact part of the data (coordinates, names, sizes), so that equal models hash alike.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

__all__ = ["ModelEquality", "same_expression"]


def same_expression(a: Any, b: Any) -> bool:
    """Whether two SymPy expressions, matrices or sequences of them are equal after expansion."""
    if a is b:
        return True
    if isinstance(a, tuple | list) or isinstance(b, tuple | list):
        return (
            isinstance(a, tuple | list)
            and isinstance(b, tuple | list)
            and len(a) == len(b)
            and all(same_expression(x, y) for x, y in zip(a, b, strict=True))
        )
    if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
        if not (isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase)) or a.shape != b.shape:
            return False
        return all(same_expression(x, y) for x, y in zip(a, b, strict=True))
    try:
        a, b = sp.sympify(a), sp.sympify(b)
    except sp.SympifyError:
        return a == b
    return bool(a == b or sp.expand(a - b) == 0)


class ModelEquality:
    """Mixin: ``==`` and ``hash`` from :meth:`_equality_data` (``(key, expressions)``).

    ``key`` is hashable and compared exactly (coordinates, names, sizes); ``expressions`` are compared with
    :func:`same_expression`.  Dataclasses using it are declared with ``eq=False`` so that the dataclass machinery
    keeps these methods.
    """

    __slots__ = ()

    def _equality_data(self) -> tuple[Any, tuple]:  # pragma: no cover - abstract
        raise NotImplementedError

    def __eq__(self, other: Any) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        if other is self:
            return True
        k1, e1 = self._equality_data()
        k2, e2 = other._equality_data()
        return k1 == k2 and same_expression(tuple(e1), tuple(e2))

    def __hash__(self) -> int:
        return hash((type(self).__name__, self._equality_data()[0]))
