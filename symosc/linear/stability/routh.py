"""The fraction-free Routh array (Bulgakov (1954), §8.18; Routh 1877).

Rows ``r_0 = (k0, k2, k4, ...)``, ``r_1 = (k1, k3, ...)`` and, for ``i >= 2``,
``r_i[j] = (r_{i-1}[0] r_{i-2}[j+1] - r_{i-2}[0] r_{i-1}[j+1]) / d_i`` with ``d_2 = d_3 = 1`` and
``d_i = r_{i-3}[0]`` otherwise.  The division is exact (a Sylvester/Bareiss identity), so integer, rational and
polynomial coefficients stay polynomial, and the first column is ``(k0, Δ1, Δ2, ..., Δs)`` — the Hurwitz minors.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from .._util import as_coefficients, is_numeric, to_fraction

__all__ = ["RouthArray", "routh_array"]


@dataclass(frozen=True)
class RouthArray(SymPyPrintable):
    """Result of :func:`routh_array`.

    Attributes
    ----------
    coefficients : tuple
        ``k0, ..., ks`` (highest power first).
    rows : tuple of tuples
        The fraction-free rows ``r_0 ... r_s``; row ``i`` stops at the first structural zero.
    first_column : tuple
        ``(k0, Δ1, ..., Δs)``: the leading coefficient and the Hurwitz minors.
    regular : bool
        False when a pivot vanished (numeric input); the array is then truncated at that row and
        ``sign_changes`` is None (the roots lie on both sides of, or on, the imaginary axis).
    sign_changes : int or None
        Sign changes in the first column = number of roots with positive real part (Routh's theorem), for a
        regular numeric array.
    """

    coefficients: tuple
    rows: tuple
    first_column: tuple
    regular: bool
    sign_changes: int | None

    @property
    def stable(self) -> Any:
        """All roots in the open left half-plane; for symbolic input the conditions ``k0 > 0, Δ_i > 0``."""
        if self.sign_changes is not None:
            return self.sign_changes == 0 and all(c != 0 for c in self.first_column)
        if not self.regular:
            return False
        return sp.And(*[sp.StrictGreaterThan(c, 0) for c in self.first_column])

    def __repr__(self) -> str:
        return f"RouthArray(first_column={[sp.sstr(c) for c in self.first_column]}, sign_changes={self.sign_changes})"

    def _latex(self, printer) -> str:
        return printer._print(sp.Matrix(_padded(self.rows)))

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(sp.Matrix(_padded(self.rows)))}$$"


def _padded(rows: tuple) -> list[list]:
    w = max(len(r) for r in rows)
    return [list(r) + [0] * (w - len(r)) for r in rows]


def _array(k: list, exact_div) -> tuple[list[list], bool]:
    s = len(k) - 1
    w = s // 2 + 2
    rows = [list(k[0::2]) + [0] * (w - len(k[0::2])), list(k[1::2]) + [0] * (w - len(k[1::2]))]
    regular = True
    for i in range(2, s + 1):
        a, b = rows[i - 2], rows[i - 1]
        if b[0] == 0:
            regular = False
            break
        d = 1 if i <= 3 else rows[i - 3][0]
        rows.append([exact_div(b[0] * a[j + 1] - a[0] * b[j + 1], d) for j in range(w - 1)] + [0])
    return rows, regular


def _trim(row: list, n: int) -> tuple:
    return tuple(row[:n])


@validated
def routh_array(coefficients: Any) -> RouthArray:
    """Fraction-free Routh array of ``k0 λ^s + k1 λ^(s-1) + … + ks`` (Bulgakov (1954), §8.18).

    Parameters
    ----------
    coefficients : sequence or sympy.Poly
        ``k0, ..., ks``, highest power first; numbers (floats are used exactly) or SymPy expressions.

    Returns
    -------
    RouthArray
        Rows, the first column ``(k0, Δ1, ..., Δs)`` (Hurwitz minors) and, for numbers, the sign changes.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import routh_array
    >>> k0, k1, k2, k3 = sp.symbols("k0:4")
    >>> routh_array([k0, k1, k2, k3]).first_column
    (k0, k1, -k0*k3 + k1*k2, -k3*(k0*k3 - k1*k2))
    >>> routh_array([1, 1, 2, 8]).sign_changes  # two roots right of the axis
    2

    See Also
    --------
    hurwitz, lienard_chipart
    """
    coeffs = as_coefficients(coefficients)
    numeric = is_numeric(coeffs)
    s = len(coeffs) - 1
    if numeric:
        k = [to_fraction(c) for c in coeffs]
        rows, regular = _array(k, lambda x, d: x / d)
        rows_out = tuple(
            _trim([sp.Rational(v.numerator, v.denominator) for v in r], (s - i) // 2 + 1) for i, r in enumerate(rows)
        )
        first = tuple(r[0] for r in rows_out)
        col = [r[0] for r in rows]
        changes = None
        if regular and all(c != 0 for c in col):
            # Routh's own first column is c_0 = k0, c_1 = Δ1, c_i = Δ_i / Δ_(i-1)
            signs = [col[0] > 0, col[1] > 0] + [(col[i] > 0) == (col[i - 1] > 0) for i in range(2, len(col))]
            changes = sum(1 for x, y in itertools.pairwise(signs) if x != y)
        return RouthArray(coeffs, rows_out, first, regular and changes is not None, changes)
    rows, _ = _array(list(coeffs), lambda x, d: sp.expand(sp.cancel(x / d)) if d != 1 else sp.expand(x))
    rows_out = tuple(_trim([sp.factor(v) for v in r], (s - i) // 2 + 1) for i, r in enumerate(rows))
    return RouthArray(coeffs, rows_out, tuple(r[0] for r in rows_out), True, None)
