"""Hurwitz and Liénard–Chipart stability criteria (Bulgakov (1954), §8.18, eqs. (8.117)–(8.118)).

Numeric coefficients are used exactly (a float is the rational number it stores), so the verdict is the exact
verdict for the polynomial as given; :attr:`StabilityVerdict.margin` says how close to the boundary it is and
``near_boundary`` flags a verdict that a relative change of the coefficients of about ``tol`` could flip.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_int, validated
from ...errors import ParameterError
from .._util import as_coefficients, is_numeric, to_fraction
from .routh import _array

__all__ = ["StabilityVerdict", "hurwitz", "hurwitz_matrix", "lienard_chipart"]


@dataclass(frozen=True)
class StabilityVerdict(SymPyPrintable):
    """Result of :func:`hurwitz` and :func:`lienard_chipart`.

    Attributes
    ----------
    criterion : str
        ``"Hurwitz"`` or ``"Liénard–Chipart (form n)"``.
    coefficients : tuple
        ``k0, ..., ks`` highest power first (multiplied by -1 when a numeric ``k0`` was negative).
    minors : tuple
        The Hurwitz minors ``Δ1, ..., Δs`` (leading principal minors of :func:`hurwitz_matrix`).
    conditions : tuple
        The expressions that must all be positive; for numbers, their exact values.
    stable : bool or sympy Boolean
        All roots in the open left half-plane; symbolic input gives the inequalities (``k0 > 0`` assumed
        unless it is a number).
    margin : float or None
        Smallest pivot of the ordinary Routh array of the polynomial scaled to unit leading and trailing
        coefficients, each divided by the size of the rows it came from (0 on the boundary); None if symbolic.
    tol : float
        The relative tolerance against which ``near_boundary`` is judged.
    near_boundary : bool or None
        ``margin < tol``: the verdict is exact for these coefficients but not robust to perturbations of ~tol.
    """

    criterion: str
    coefficients: tuple
    minors: tuple
    conditions: tuple
    stable: Any
    margin: float | None
    tol: float
    near_boundary: bool | None

    def __bool__(self) -> bool:
        if isinstance(self.stable, bool):
            return self.stable
        raise TypeError("the verdict is symbolic; use .stable (a SymPy Boolean) or substitute numbers")

    def __repr__(self) -> str:
        if self.margin is None:
            return f"StabilityVerdict({self.criterion}: {sp.sstr(self.stable)})"
        return (
            f"StabilityVerdict({self.criterion}: stable={self.stable}, margin={self.margin:.3g}, tol={self.tol:g}, "
            f"near_boundary={self.near_boundary})"
        )

    def _sympystr(self, printer) -> str:
        return printer._print(self.stable) if not isinstance(self.stable, bool) else repr(self)

    def _latex(self, printer) -> str:
        if isinstance(self.stable, bool):
            return r"\text{%s}" % ("stable" if self.stable else "not stable")
        return r",\ ".join(printer._print(sp.StrictGreaterThan(c, 0)) for c in self.conditions)

    def _repr_latex_(self) -> str:
        from sympy.printing.latex import LatexPrinter

        return f"$${self._latex(LatexPrinter())}$$"


@validated
def hurwitz_matrix(coefficients: Any) -> sp.ImmutableMatrix:
    """The ``s x s`` Hurwitz matrix, entry ``(i, j) = k_(2i-j)`` (1-based) (Bulgakov (1954), eq. (8.117)).

    Parameters
    ----------
    coefficients : sequence or sympy.Poly
        Coefficients ``k0, ..., ks`` highest power first (numbers or SymPy expressions, ``k0 != 0``, at least two).

    Returns
    -------
    sympy.ImmutableMatrix

    Examples
    --------
    >>> from symosc.linear import hurwitz_matrix
    >>> hurwitz_matrix([1, 2, 3, 4])
    Matrix([
    [2, 1, 0],
    [4, 3, 2],
    [0, 0, 4]])

    See Also
    --------
    hurwitz, routh_array
    """
    k = as_coefficients(coefficients)
    s = len(k) - 1
    return sp.ImmutableMatrix(s, s, lambda i, j: k[2 * (i + 1) - (j + 1)] if 0 <= 2 * (i + 1) - (j + 1) <= s else 0)


def _numeric_minors(k: list[Fraction]) -> tuple[list[Fraction], list[list[Fraction]] | None]:
    rows, regular = _array(k, lambda x, d: x / d)
    s = len(k) - 1
    col = [r[0] for r in rows]
    if regular and len(col) == s + 1:
        return col[1:], rows
    # a zero pivot: the remaining minors by exact determinants
    H = hurwitz_matrix([sp.Rational(v.numerator, v.denominator) for v in k])
    minors = [Fraction(int(m.p), int(m.q)) for m in (H[:i, :i].det(method="bareiss") for i in range(1, s + 1))]
    return minors, None


def _margin(k: list[Fraction]) -> float:
    """Smallest normalised pivot of the ordinary Routh array of the polynomial scaled to k0 = |ks| = 1."""
    s = len(k) - 1
    kf = [float(v) for v in k]
    if kf[-1] == 0:
        return 0.0
    rho = abs(kf[-1] / kf[0]) ** (1.0 / s)
    scaled = [kf[j] / (kf[0] * rho**j) for j in range(s + 1)]
    w = s // 2 + 2
    rows = [scaled[0::2] + [0.0] * (w - len(scaled[0::2])), scaled[1::2] + [0.0] * (w - len(scaled[1::2]))]
    margin = rows[1][0] / max(max(abs(x) for x in rows[0]), max(abs(x) for x in rows[1]), 1e-300)
    for _ in range(2, s + 1):
        a, b = rows[-2], rows[-1]
        if b[0] == 0:
            return 0.0
        new = [(b[0] * a[j + 1] - a[0] * b[j + 1]) / b[0] for j in range(w - 1)] + [0.0]
        scale = max(max(abs(x) for x in a), max(abs(x) for x in b), 1e-300)
        margin = min(margin, new[0] / scale)
        rows.append(new)
    return float(margin)


def _prepare(coefficients: Any):
    coeffs = as_coefficients(coefficients)
    if any(c.is_number and c.is_real is False for c in coeffs):
        raise ParameterError(
            "the Hurwitz criterion needs real coefficients; for complex ones count roots with d_partition or nyquist"
        )
    numeric = is_numeric(coeffs)
    if numeric and coeffs[0] < 0:
        coeffs = tuple(-c for c in coeffs)
    return coeffs, numeric


def _verdict(criterion, coeffs, numeric, minors, conds, tol, k=None) -> StabilityVerdict:
    if numeric:
        vals = tuple(sp.Rational(v.numerator, v.denominator) for v in conds)
        stable = all(v > 0 for v in conds)
        margin = _margin(k)
        if not stable and all(v >= 0 for v in conds):  # a zero condition, none negative: exactly on the boundary
            margin = 0.0  # (the float Routh pivots of such a polynomial are rounding errors of either sign)
        mins = tuple(sp.Rational(v.numerator, v.denominator) for v in minors)
        return StabilityVerdict(criterion, coeffs, mins, vals, stable, margin, tol, bool(abs(margin) < tol))
    exprs = tuple(c for c in conds if sp.StrictGreaterThan(c, 0) is not sp.true)
    return StabilityVerdict(criterion, coeffs, tuple(minors), exprs, sp.And(*[e > 0 for e in exprs]), None, tol, None)


def _check_tol(tol: float) -> float:
    if not (0 < tol < 1):
        raise ParameterError(f"tol must lie in (0, 1), got {tol}")
    return float(tol)


@validated
def hurwitz(coefficients: Any, *, tol: float = 1e-9) -> StabilityVerdict:
    """Hurwitz criterion: all roots of ``k0 λ^s + … + ks`` have negative real parts (Bulgakov (1954), §8.18).

    Conditions: ``k0 > 0``, ``Δ1 > 0, ..., Δ_(s-1) > 0`` and ``ks > 0`` (which replaces ``Δs = ks Δ_(s-1)``), with
    ``Δi`` the leading minors of :func:`hurwitz_matrix`, computed from the fraction-free Routh array.

    Parameters
    ----------
    coefficients : sequence or sympy.Poly
        Coefficients ``k0, ..., ks`` highest power first (real, ``k0 != 0``, at least two).  Numbers give a verdict
        (floats are taken exactly); expressions give inequalities.
    tol : float
        Relative tolerance (> 0 and < 1) for flagging a numeric verdict as ``near_boundary``.

    Returns
    -------
    StabilityVerdict

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import hurwitz
    >>> k0, k1, k2, k3 = sp.symbols("k0:4", positive=True)
    >>> hurwitz([k0, k1, k2, k3]).stable
    -k0*k3 + k1*k2 > 0
    >>> v = hurwitz([1, 4, 16, 64])       # Bulgakov §8.12 Ex. 2: (D + 4)(D^2 + 16), on the boundary
    >>> v.stable, v.minors[1], v.near_boundary
    (False, 0, True)

    See Also
    --------
    routh_array, lienard_chipart, stability_degree
    """
    tol = _check_tol(tol)
    coeffs, numeric = _prepare(coefficients)
    s = len(coeffs) - 1
    if numeric:
        k = [to_fraction(c) for c in coeffs]
        minors, _ = _numeric_minors(k)
        conds = [minors[i] for i in range(s - 1)] + [k[-1]]
        return _verdict("Hurwitz", coeffs, True, minors, conds, tol, k)
    rows, _ = _array(list(coeffs), lambda x, d: sp.expand(sp.cancel(x / d)) if d != 1 else sp.expand(x))
    minors = [sp.factor(r[0]) for r in rows[1:]]
    conds = [coeffs[0], *minors[: s - 1], coeffs[-1]]
    return _verdict("Hurwitz", coeffs, False, minors, conds, tol)


@validated
def lienard_chipart(coefficients: Any, *, form: int = 1, tol: float = 1e-9) -> StabilityVerdict:
    """Liénard–Chipart criterion: half the Hurwitz minors plus sign conditions on the coefficients.

    With ``k0 > 0`` (Gantmacher's four equivalent forms):

    1. ``ks, k_(s-2), k_(s-4), ... > 0`` and ``Δ1, Δ3, ... > 0``;
    2. ``ks, k_(s-2), ... > 0`` and ``Δ2, Δ4, ... > 0``;
    3. ``ks, k_(s-1), k_(s-3), ... > 0`` and ``Δ1, Δ3, ... > 0``;
    4. ``ks, k_(s-1), k_(s-3), ... > 0`` and ``Δ2, Δ4, ... > 0``.

    Parameters
    ----------
    coefficients : sequence or sympy.Poly
        Coefficients ``k0, ..., ks`` highest power first (real, ``k0 != 0``, at least two).
    form : {1, 2, 3, 4}
        Which of the four equivalent forms.
    tol : float
        Relative tolerance (> 0 and < 1) for flagging a numeric verdict as ``near_boundary`` (as in
        :func:`hurwitz`).

    Returns
    -------
    StabilityVerdict

    Examples
    --------
    >>> from symosc.linear import lienard_chipart
    >>> lienard_chipart([1, 3, 3, 1]).stable     # (λ + 1)^3
    True
    >>> [str(c) for c in lienard_chipart([1, 3, 3, 1], form=2).conditions]
    ['1', '3', '8']

    See Also
    --------
    hurwitz, routh_array
    """
    tol = _check_tol(tol)
    form = check_int("form (which of the four Liénard–Chipart forms)", form, minimum=1, maximum=4)
    coeffs, numeric = _prepare(coefficients)
    s = len(coeffs) - 1
    kidx = list(range(s, -1, -2)) if form in (1, 2) else [s, *list(range(s - 1, -1, -2))]
    kidx = [j for j in kidx if j >= 1 or j == s]
    didx = list(range(1, s + 1, 2)) if form in (1, 3) else list(range(2, s + 1, 2))
    if numeric:
        k = [to_fraction(c) for c in coeffs]
        minors, _ = _numeric_minors(k)
        conds = [k[j] for j in kidx] + [minors[i - 1] for i in didx]
        return _verdict(f"Liénard–Chipart (form {form})", coeffs, True, minors, conds, tol, k)
    rows, _ = _array(list(coeffs), lambda x, d: sp.expand(sp.cancel(x / d)) if d != 1 else sp.expand(x))
    minors = [sp.factor(r[0]) for r in rows[1:]]
    conds = [coeffs[0]] + [coeffs[j] for j in kidx] + [minors[i - 1] for i in didx]
    return _verdict(f"Liénard–Chipart (form {form})", coeffs, False, minors, conds, tol)
