"""The matrizant over a long interval as a product of short Peano–Baker series (Bulgakov §1.38).

The series ``Ω = E + ΓA + ΓAΓA + …`` (1.319) converges everywhere, but the number of terms it needs grows with
``n U |t1 - t0|``.  Since ``Ω' = A Ω``, the matrizant composes: ``Ω(t2, t0) = Ω(t2, t1) Ω(t1, t0)``.  One symbolic
series ``Ω(t, τ)`` with a symbolic start τ is derived once and evaluated on pieces short enough for its a-priori bound;
the determinant is checked against Liouville's formula ``det Ω = exp ∫ tr A dt`` (1.321).
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_int, check_positive, validated
from ...errors import ConvergenceError, ParameterError
from ...numeric import bind
from ...numeric import compile as _compile
from .._util import as_square_matrix
from .matrizant import matrizant

__all__ = ["MatrizantProduct", "matrizant_product"]


@dataclass(frozen=True)
class MatrizantProduct(SymPyPrintable):
    """Result of :func:`matrizant_product`.

    Attributes
    ----------
    value : ndarray
        ``Ω(t1, t0)``.
    pieces : int
        Number of sub-intervals.
    order : int
        Series order on each piece.
    bound : float
        Sum over the pieces of the a-priori truncation bound of each piece (local error; it is carried forward
        multiplied by the matrizant of the rest of the interval).
    det_error : float
        ``|det Ω - exp ∫ tr A| / |exp ∫ tr A|`` (Liouville, eq. (1.321)), an a-posteriori check.
    """

    value: np.ndarray
    pieces: int
    order: int
    bound: float
    det_error: float

    def __repr__(self) -> str:
        return (
            f"MatrizantProduct(pieces={self.pieces}, order={self.order}, bound={self.bound:.3g}, "
            f"det_error={self.det_error:.3g})"
        )

    def _repr_latex_(self) -> str:
        body = sp.latex(sp.Matrix(np.round(self.value, 12).tolist())) if self.value.size <= 36 else r"\dots"
        return rf"$\Omega = {body},\quad \text{{{self.pieces} pieces, bound}}\ {self.bound:.2g}$"


@validated
def matrizant_product(
    A: Any,
    t: sp.Symbol,
    t0: float,
    t1: float,
    *,
    order: int = 10,
    tol: float = 1e-10,
    values: Mapping | None = None,
    max_pieces: int = 100000,
) -> MatrizantProduct:
    """``Ω(t1, t0)`` of ``X' = A(t) X`` as a product of order-``order`` Peano–Baker series on short pieces.

    Bulgakov (1954), §1.38, eqs. (1.319)–(1.321): each piece ``[τ_i, τ_(i+1)]`` uses the truncated series whose
    a-priori bound ``Σ_(k>order) U^k n^(k-1) h^k / k!`` (``U ≥ max|a_jk|``) is at most ``tol / pieces``; the
    pieces are multiplied, later ones on the left.  ``det Ω`` is compared with ``exp ∫ tr A dt``.

    Parameters
    ----------
    A : Matrix
        ``A(t)``, square, entries that SymPy integrates in closed form (polynomials, exponentials, sines, ...).
    t : Symbol
        Time variable.
    t0 : float
        Start of the interval, where ``Ω(t0) = E``; a finite real number.
    t1 : float
        End of the interval, at which ``Ω`` is returned; a finite real number.
    order : int
        Series order on each piece.
    tol : float
        Bound on the sum of the local truncation errors.
    values : mapping, optional
        Values of other parameters in ``A``.
    max_pieces : int
        Refuse (ConvergenceError) when more pieces would be needed.

    Returns
    -------
    MatrizantProduct

    Raises
    ------
    ConvergenceError
        More than ``max_pieces`` pieces would be needed.
    ModelError
        ``A`` cannot be integrated in closed form (use :func:`matrizant_numeric`).

    See Also
    --------
    matrizant, matrizant_numeric

    Examples
    --------
    ``x'' + x = 0`` over 20 time units, against the rotation ``[[cos 20, sin 20], [-sin 20, cos 20]]``:

    >>> import numpy as np, sympy as sp
    >>> t = sp.Symbol("t")
    >>> res = matrizant_product(sp.Matrix([[0, 1], [-1, 0]]), t, 0.0, 20.0, order=12, tol=1e-12)
    >>> bool(np.allclose(res.value, [[np.cos(20), np.sin(20)], [-np.sin(20), np.cos(20)]], atol=1e-10))
    True
    >>> res.pieces, res.det_error < 1e-12
    (83, True)
    """
    if not isinstance(t, sp.Symbol):
        raise ParameterError(f"t must be a SymPy Symbol, got {t!r}")
    t0, t1 = check_finite("t0", t0), check_finite("t1", t1)
    order = check_int("order", order, minimum=1, maximum=60)
    tol = check_positive("tol", tol)
    max_pieces = check_int("max_pieces", max_pieces, minimum=1)
    M = as_square_matrix(A)
    Ab = bind(M, values or {})
    free = Ab.free_symbols - {t}
    if free:
        raise ParameterError("missing values for: " + ", ".join(sorted(map(str, free))))
    n = Ab.rows
    if t1 == t0:
        return MatrizantProduct(np.eye(n), 0, order, 0.0, 0.0)
    fA = _compile(Ab, [t])
    grid = np.linspace(t0, t1, 4097)
    avals = np.asarray(fA(grid), dtype=float)
    if not np.all(np.isfinite(avals)):
        raise ParameterError("A(t) is not finite on [t0, t1]; check the parameter values")
    U = 1.05 * float(np.max(np.abs(avals))) or 1e-300
    tau = sp.Dummy("tau")
    series = matrizant(Ab, t, tau, order)
    probe = dataclasses.replace(series, t0=sp.Integer(0))
    length = abs(t1 - t0)
    pieces = max(1, int(np.ceil(n * U * length / 2)))
    while probe.bound(length / pieces, U=U) * pieces > tol:
        pieces *= 2
        if pieces > max_pieces:
            raise ConvergenceError(
                f"more than max_pieces={max_pieces} pieces of order {order} would be needed for tol={tol:g} "
                f"(n U |t1 - t0| = {n * U * length:.3g}); raise order or max_pieces, or use matrizant_numeric()",
            )
    # fewest pieces that still meet tol (bisection between pieces/2 and pieces)
    lo, hi = max(1, pieces // 2), pieces
    while lo < hi:
        mid = (lo + hi) // 2
        if probe.bound(length / mid, U=U) * mid <= tol:
            hi = mid
        else:
            lo = mid + 1
    pieces = hi
    # in the step h = t - τ: the expanded powers of t and τ separately would cancel badly far from t = 0
    h = sp.Dummy("h")
    f = _compile(series.series.subs(t, tau + h).applyfunc(sp.expand), [h, tau])
    nodes = np.linspace(t0, t1, pieces + 1)
    value = np.eye(n)
    for a, b in itertools.pairwise(nodes):
        value = np.asarray(f(b - a, a), dtype=float) @ value
    from scipy.integrate import quad

    ftr = _compile(Ab.trace(), [t])
    integral, _ = quad(lambda s: float(ftr(s)), t0, t1, limit=200, epsabs=1e-14, epsrel=1e-13)
    liouville = float(np.exp(integral))
    det_error = abs(float(np.linalg.det(value)) - liouville) / max(abs(liouville), 1e-300)
    return MatrizantProduct(value, pieces, order, probe.bound(length / pieces, U=U) * pieces, det_error)
