"""Cascades kept as products of their sections (private; used by :mod:`.fourpoles`).

A cascade multiplied out symbolically is a matrix of high-degree polynomials: 100 identical L-C sections give
degree 200, with coefficients of 1e60 whose sum, at a pass-band frequency, is of order one.  Evaluated in floating
point, that expanded form loses every digit; evaluated as the product of the sections' own chain matrices it loses
almost none (each factor is well conditioned, and the rounding errors of a product of 2x2 matrices grow like the
number of factors times the condition of the partial products).  So a cascade stores its factors and

* multiplies them exactly, once, when its chain matrix is first read (SymPy's ``DomainMatrix`` over the
  polynomial ring or rational function field of the entries, repeated squaring for powers);
* evaluates numerically as a product of the factors' numeric chain matrices, vectorised over frequency
  (:func:`numpy.matmul` on ``(..., 2, 2)`` stacks, :func:`numpy.linalg.matrix_power` for runs of identical
  sections), never through the expanded polynomials;
* evaluates in mpmath the same way (:meth:`FourPole.evaluate`).

:class:`Deferred` is the data descriptor behind ``FourPole.chain`` and ``FourPole.netlist``: the stored value may be
a :class:`Pending` product, resolved on first read and then kept.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import sympy as sp
from sympy.polys.matrices import DomainMatrix

_MISSING = object()


class Pending:
    """A value computed on first read (see :class:`Deferred`)."""

    def resolve(self) -> Any:  # pragma: no cover - abstract
        raise NotImplementedError


class Deferred:
    """Data descriptor of a dataclass field whose stored value may be :class:`Pending`.

    Reading the field resolves a pending value once and stores the result; writing stores the value as given.  The
    descriptor itself passed as a value (the dataclass default when the field is omitted) stands for ``default``.
    """

    def __init__(self, default: Any = _MISSING):
        self.default = default

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name
        self.key = f"_{name}_stored"

    def __get__(self, obj: Any, objtype: Any = None) -> Any:
        if obj is None:
            if self.default is _MISSING:
                raise AttributeError(self.name)  # no default value for the dataclass field
            return self.default
        try:
            value = obj.__dict__[self.key]
        except KeyError:
            raise AttributeError(self.name) from None
        if isinstance(value, Pending):
            value = value.resolve()
            obj.__dict__[self.key] = value
        return value

    def __set__(self, obj: Any, value: Any) -> None:
        obj.__dict__[self.key] = self.default if value is self else value

    def stored(self, obj: Any) -> Any:
        """The stored value without resolving it (a :class:`Pending` or the value)."""
        return obj.__dict__.get(self.key)


def merge_runs(factors: list[tuple[Any, int]]) -> tuple[tuple[Any, int], ...]:
    """Adjacent runs of the same object joined: ``[(a, 1), (a, 2), (b, 1)] -> ((a, 3), (b, 1))``."""
    out: list[list] = []
    for f, n in factors:
        if out and out[-1][0] is f:
            out[-1][1] += n
        else:
            out.append([f, n])
    return tuple((f, n) for f, n in out)


class PendingChain(Pending):
    """The chain matrix ``A_1**n_1 A_2**n_2 ...`` of a cascade: ``runs`` is ``((four_pole, n), ...)``."""

    def __init__(self, runs: tuple[tuple[Any, int], ...]):
        self.runs = runs

    def resolve(self) -> sp.ImmutableMatrix:
        return sp.ImmutableMatrix(exact_product(self.runs))

    def __getstate__(self) -> tuple:
        return self.runs

    def __setstate__(self, runs: tuple) -> None:
        self.runs = runs


class PendingNetlist(Pending):
    """The terminal-level netlist of a cascade, built from its factors' netlists on first read."""

    def __init__(self, runs: tuple[tuple[Any, int], ...]):
        self.runs = runs

    def resolve(self) -> Any:
        from ._nodal import cascade_netlists

        return cascade_netlists([f.netlist for f, n in self.runs for _ in range(n)])

    def __getstate__(self) -> tuple:
        return self.runs

    def __setstate__(self, runs: tuple) -> None:
        self.runs = runs


def exact_product(runs: tuple[tuple[Any, int], ...]) -> sp.Matrix:
    """``Π A_i**n_i`` exactly: in the polynomial ring / fraction field of the entries (``DomainMatrix``), or with
    SymPy expressions (and ``cancel``) when the entries need the ``EX`` domain."""
    distinct: list[Any] = []
    for f, _ in runs:
        if not any(f is g for g in distinct):
            distinct.append(f)
    chains = [sp.Matrix(f.chain) for f in distinct]
    whole = DomainMatrix.from_Matrix(sp.Matrix.hstack(*chains))
    if whole.domain.is_EX or whole.domain.is_EXRAW:
        A = sp.eye(2)
        for f, n in runs:
            M = chains[_index(distinct, f)]
            A = A * (M**n if n > 1 else M)
        return A.applyfunc(sp.cancel)
    A = None
    for f, n in runs:
        i = _index(distinct, f)
        M = whole[:, 2 * i : 2 * i + 2]
        M = M**n if n > 1 else M
        A = M if A is None else A * M
    out = A.to_Matrix()
    ground = whole.domain.dom if (whole.domain.is_PolynomialRing or whole.domain.is_FractionField) else whole.domain
    if ground.is_ZZ or ground.is_QQ:
        return out  # already in lowest terms, expanded: the form ``cancel`` gives
    return out.applyfunc(sp.cancel)


def _index(items: list, obj: Any) -> int:
    return next(i for i, x in enumerate(items) if x is obj)


def numeric_product(runs: tuple[tuple[Any, int], ...], p_values: np.ndarray, values: dict) -> np.ndarray:
    """``Π A_i(p)**n_i`` at every ``p`` in ``p_values``: complex array of shape ``p_values.shape + (2, 2)``."""
    out = None
    for f, n in runs:
        M = f._numeric_chain(p_values, values)
        if n > 1:
            M = np.linalg.matrix_power(M, n)
        out = M if out is None else np.matmul(out, M)
    return out


def mpmath_product(runs: tuple[tuple[Any, int], ...], value: Any) -> Any:
    """``Π A_i(p)**n_i`` at one point in mpmath (at the working precision)."""
    import mpmath

    out = mpmath.eye(2)
    for f, n in runs:
        M = f.evaluate(value)
        out = out * (M**n if n > 1 else M)
    return out
