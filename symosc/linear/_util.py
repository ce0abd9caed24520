"""Input checking shared by the linear-systems modules (private)."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np
import sympy as sp

from ..errors import ModelError, ParameterError


def as_coefficients(coefficients: Any, what: str = "coefficients") -> tuple[sp.Expr, ...]:
    """Return polynomial coefficients (highest power first) as a tuple of SymPy expressions.

    Accepts a sequence of numbers/expressions or a :class:`sympy.Poly`.  Raises ParameterError for a zero
    leading coefficient, fewer than two coefficients or non-finite numbers.
    """
    if isinstance(coefficients, sp.Poly):
        coefficients = coefficients.all_coeffs()
    if isinstance(coefficients, np.ndarray):
        coefficients = coefficients.tolist()
    try:
        coeffs = tuple(sp.sympify(c) for c in coefficients)
    except (TypeError, sp.SympifyError) as exc:
        raise ParameterError(f"{what} must be a sequence of numbers or SymPy expressions, highest power first") from exc
    if len(coeffs) < 2:
        raise ParameterError(f"{what} must hold at least two numbers (degree >= 1), got {len(coeffs)}")
    for c in coeffs:
        if c.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
            raise ParameterError(f"{what} must be finite, got {c}")
    if coeffs[0].is_zero:
        raise ParameterError(
            f"the leading coefficient of {what} is zero; pass the coefficients highest power first and drop "
            "leading zeros (the degree is len(coefficients) - 1)"
        )
    return coeffs


def is_numeric(coeffs: tuple[sp.Expr, ...]) -> bool:
    """True when every coefficient is a real number (no free symbols)."""
    return all(c.is_number and c.is_real is not False for c in coeffs) and not any(c.free_symbols for c in coeffs)


def to_fraction(c: sp.Expr) -> Fraction:
    """Exact rational value of a real SymPy number (floats are converted exactly, irrationals to 60 digits)."""
    if c.is_Integer:
        return Fraction(int(c))
    if c.is_Rational:
        return Fraction(int(c.p), int(c.q))
    if c.is_Float:
        return Fraction(float(c)) if c._prec <= 53 else Fraction(str(c))
    value = sp.N(c, 60)
    if not value.is_real:
        raise ParameterError(f"coefficient {c} is not real; use the D-partition tools for complex coefficients")
    return Fraction(str(value))


def as_real_array(a: Any, what: str, ndim: int) -> np.ndarray:
    """A finite float array of the given number of dimensions."""
    try:
        arr = np.asarray(a, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{what} must be a real numeric array") from exc
    if arr.ndim != ndim:
        raise ParameterError(f"{what} must have {ndim} dimension(s), got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{what} must be finite")
    return arr


def as_spd_pair(M: Any, K: Any, *, allow_singular_k: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Check a mass matrix ``M`` (symmetric positive definite) and stiffness ``K`` (symmetric) of one size."""
    M = as_real_array(M, "M (mass matrix)", 2)
    K = as_real_array(K, "K (stiffness matrix)", 2)
    n = M.shape[0]
    if M.shape != (n, n) or K.shape != (n, n) or n == 0:
        raise ModelError(f"M and K must be square matrices of one size, got {M.shape} and {K.shape}")
    scale = max(np.abs(M).max(), np.abs(K).max(), 1e-300)
    for name, X in (("M (mass matrix)", M), ("K (stiffness matrix)", K)):
        if not np.allclose(X, X.T, rtol=1e-12, atol=1e-12 * scale):
            raise ModelError(f"{name} must be symmetric")
    w = np.linalg.eigvalsh(M)
    if w[0] <= 1e-13 * max(abs(w[-1]), 1e-300):
        kind = "singular" if abs(w[0]) <= 1e-13 * max(abs(w[-1]), 1e-300) else "indefinite"
        raise ModelError(
            f"the mass matrix M is {kind} (smallest eigenvalue {w[0]:.3g}); kinetic energy must be positive "
            "definite: remove massless coordinates by static condensation first"
        )
    if not allow_singular_k:
        wk = np.linalg.eigvalsh(K)
        if wk[0] <= 1e-13 * max(abs(wk[-1]), 1e-300):
            raise ModelError(
                f"the stiffness matrix K must be positive definite here (smallest eigenvalue {wk[0]:.3g}): a rigid-"
                "body mode has zero frequency; constrain it or use the stiffness form"
            )
    return 0.5 * (M + M.T), 0.5 * (K + K.T)


def figure_axes(ax: Any):
    """Return ``ax`` or a new Axes (matplotlib imported here only)."""
    if ax is not None:
        return ax
    from .._plotting import pyplot

    plt = pyplot()

    _, ax = plt.subplots()
    return ax
