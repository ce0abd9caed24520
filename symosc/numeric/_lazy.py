"""Picklable numeric functions of SymPy expressions (compiled on first use, again after unpickling)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy as sp


class LazyFunction:
    """``f(*x) = raw(*x, *bound)`` for ``raw = symosc.numeric.compile(expr, args).raw``, compiled when first called.

    Only the SymPy expression, the argument symbols and the bound trailing values are pickled, so results that
    hold one can be sent to a process pool or saved.

    Examples
    --------
    >>> import pickle, sympy as sp
    >>> x, a = sp.symbols("x a")
    >>> f = LazyFunction(a * x**2, [x, a], bound=(3.0,))
    >>> float(pickle.loads(pickle.dumps(f))(2.0))
    12.0
    """

    def __init__(
        self, expr: Any, args: Sequence[sp.Symbol], *, bound: Sequence[Any] = (), name: str | None = None
    ) -> None:
        self.expr = sp.sympify(expr)
        self.args = tuple(args)
        self.bound = tuple(bound)
        self.name = name
        self._raw: Any = None

    def _compiled(self) -> Any:
        if self._raw is None:
            from . import compile as _compile

            kw = {"name": self.name} if self.name else {}
            self._raw = _compile(self.expr, list(self.args), check=False, **kw).raw
        return self._raw

    def __call__(self, *x: Any) -> Any:
        return self._compiled()(*x, *self.bound)

    def __getstate__(self) -> dict[str, Any]:
        return {"expr": self.expr, "args": self.args, "bound": self.bound, "name": self.name}

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__dict__.update(state)
        self._raw = None

    def __repr__(self) -> str:
        return f"LazyFunction({self.expr}, args={list(self.args)})"
