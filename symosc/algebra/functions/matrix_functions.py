"""Functions of a matrix by Sylvester's formula (Bulgakov §1.29–1.35).

``f(A) = Σ_σ [f(λ_σ) ε_σ + Σ_(p=1)^(e_σ-1) f^(p)(λ_σ)/p! η_σ^p]`` (1.287): simple roots give the plain Sylvester
formula with projectors ``ε_σ = Π_(τ≠σ) (A - λ_τE)/(λ_σ - λ_τ)`` (1.278); multiple roots (non-linear elementary
divisors) the confluent form.  For floating-point matrices the blocked Schur–Parlett algorithm (Davies & Higham,
2003) is used: eigenvalues close relative to their own size form clusters, f on a cluster is the Newton
interpolation polynomial with divided differences computed from the Taylor series of f about the cluster center
(so no ``1/(λ_σ - λ_τ)`` with a small difference is ever formed), and the clusters are coupled through triangular
Sylvester equations, which keeps the accuracy on spectra spanning many decades.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError, warn
from .._util import as_scalar_function, as_square_matrix, is_float_matrix
from . import _taylor
from ._schur_parlett import float_matrix_function
from .spectral import SpectralDecomposition, _float_decomposition, spectral_decomposition

__all__ = ["MatrixFunction", "matrix_function", "series_converges"]

_METHODS = ("auto", "sylvester", "confluent")


@dataclass(frozen=True)
class MatrixFunction(SymPyPrintable):
    """``f(A)`` together with the spectral data it was built from (returned when ``spectral=True``).

    Attributes
    ----------
    value : Matrix or ndarray
        ``f(A)`` (an ndarray when ``A`` was given as an ndarray).
    spectral : SpectralDecomposition
        The roots, projectors and nilpotents of ``A`` used (clusters in floating point).
    method : str
        The method requested: ``"auto"``, ``"sylvester"`` or ``"confluent"``.
    f : Expr
        The scalar function as an expression in a dummy variable.
    """

    value: sp.Matrix
    spectral: SpectralDecomposition
    method: str
    f: sp.Expr = field(repr=False)

    def __repr__(self) -> str:
        return f"MatrixFunction(method={self.method!r}, roots={self.spectral.roots}, value={self.value!r})"

    def _repr_latex_(self) -> str:
        return f"${sp.latex(self.value)}$"


@validated
def matrix_function(
    A: Any,
    f: Any,
    *,
    var: sp.Symbol | None = None,
    method: str = "auto",
    spectral: bool = False,
    tol: float = 1e-17,
    cluster_tol: float = 1e-2,
) -> sp.Matrix | np.ndarray | MatrixFunction:
    """The matrix function ``f(A)`` for a square matrix and f analytic at its eigenvalues.

    Parameters
    ----------
    A : Matrix or ndarray
        Square matrix.  Exact (Integer, Rational, radicals) or symbolic entries give an exact result; float
        entries (or a NumPy array) a floating-point one (an ndarray in, an ndarray out).
    f : Lambda, function class, callable or Expr
        The scalar function: ``sympy.Lambda(x, ...)``, ``sympy.exp``, ``lambda x: ...`` or an expression in
        ``var``.  Polynomials, rational functions, power and Laurent series (closed form), ``exp(x*t)``,
        ``sqrt``, ``log`` ... anything SymPy can differentiate.
    var : Symbol, optional
        The variable of f when f is an expression with more than one free symbol.
    method : {"auto", "sylvester", "confluent"}
        ``"sylvester"``: projector formula for simple roots only (raises on repeated exact roots; in floating
        point it shows the 1e-16/δ loss for roots δ apart).  ``"confluent"``: (1.287) with the principal
        idempotents and nilpotents.  ``"auto"``: confluent where roots repeat; in floating point, clusters of
        nearly equal roots are treated through accurate divided differences.
    spectral : bool
        Return a :class:`MatrixFunction` holding ``value`` and the :class:`SpectralDecomposition`.
    tol : float
        Floating point: relative size of the last Taylor terms kept in a cluster's divided differences.
    cluster_tol : float
        Floating point: eigenvalues with ``|λ_i - λ_j| <= cluster_tol * max(|λ_i|, |λ_j|)`` (relative to their
        own size, so a spectrum spanning many decades is not lumped together) are linked into a cluster.

    Returns
    -------
    Matrix, ndarray or MatrixFunction

    Raises
    ------
    ModelError
        A is not square, or f (or a derivative that the Jordan structure needs) is not defined at an eigenvalue
        (``log`` at 0, ``sqrt`` at 0 with a Jordan block, a pole of a rational f).
    ConvergenceError
        Floating point: the Taylor series of f about a cluster center does not converge (a singularity is near).

    See Also
    --------
    spectral_decomposition
    interpolation_polynomial
    series_converges

    Examples
    --------
    Bulgakov §1.35: ``R(λ) = (λ+1)/(4λ)`` of ``z = [[4,-3],[2,-1]]``:

    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> matrix_function(sp.Matrix([[4, -3], [2, -1]]), (x + 1) / (4 * x))
    Matrix([
    [ 1/8, 3/8],
    [-1/4, 3/4]])

    A Jordan block (confluent case) and exp(At):

    >>> t = sp.Symbol("t")
    >>> matrix_function(sp.Matrix([[-1, 1], [0, -1]]), sp.Lambda(x, sp.exp(x * t)))
    Matrix([
    [exp(-t), t*exp(-t)],
    [      0,   exp(-t)]])

    Floating point with roots 1e-12 apart (the plain formula would lose 4 digits):

    >>> F = matrix_function(sp.Matrix([[1.0, 1.0], [0.0, 1.0 + 1e-12]]), sp.exp)
    >>> [round(float(v), 12) for v in F]
    [2.718281828459, 2.71828182846, 0.0, 2.718281828462]
    """
    if method not in _METHODS:
        raise ParameterError(f"unknown method {method!r}; choose one of {_METHODS}")
    as_numpy = isinstance(A, np.ndarray)
    M = as_square_matrix(A)
    expr, x = as_scalar_function(f, var)
    if as_numpy or is_float_matrix(M):
        if expr.free_symbols - {x}:
            names = sorted(str(s) for s in expr.free_symbols - {x})
            raise ParameterError(
                f"f has free parameters {names} but A has float entries; substitute numbers for them, or pass an "
                "exact matrix (e.g. sympy.nsimplify(A)) for a symbolic result"
            )
        arr, decomp = _float_function(M, expr, x, method, tol, cluster_tol, spectral)
        value = arr if as_numpy else _to_sympy(arr)
    else:
        decomp = spectral_decomposition(M)
        if method == "sylvester" and any(c.multiplicity > 1 for c in decomp.components):
            rep = [c.root for c in decomp.components if c.multiplicity > 1]
            raise ModelError(
                f"Sylvester's formula for simple roots does not apply: repeated roots {rep}; use method='confluent' "
                "or 'auto'"
            )
        value = decomp.apply(sp.Lambda(x, expr))
    if spectral:
        return MatrixFunction(value=value, spectral=decomp, method=method, f=expr)
    return value


def _is_real_function(expr: sp.Expr, x: sp.Symbol) -> bool:
    r = sp.Dummy("r", real=True)
    return bool(expr.xreplace({x: r}).is_real)


def _float_function(
    M: sp.Matrix, expr: sp.Expr, x: sp.Symbol, method: str, tol: float, cluster_tol: float, want_spectral: bool
) -> tuple[np.ndarray, SpectralDecomposition | None]:
    An = np.array(M.evalf(), dtype=complex)
    if not np.all(np.isfinite(An)):
        raise ParameterError("A has non-finite entries (nan or inf); a matrix function needs finite entries")
    n = An.shape[0]
    source = _taylor.TaylorSource(expr, x)
    if method == "sylvester":
        nodes = np.linalg.eigvals(An)
        if len(set(nodes.tolist())) < n:
            raise ModelError("Sylvester's formula for simple roots: computed eigenvalues repeat exactly; use 'auto'")
        val = np.zeros((n, n), dtype=complex)
        E = np.eye(n)
        for s, ls in enumerate(nodes):
            P = E.astype(complex)
            for tau, lt in enumerate(nodes):
                if tau != s:
                    P = P @ (An - lt * E) / (ls - lt)
            val += complex(source.coefficient(0, mpmath.mpmathify(complex(ls)))) * P
    else:
        val = float_matrix_function(An, source, tol, cluster_tol)
    bad = ~np.isfinite(val)
    if np.any(bad):
        where = [(int(i), int(j)) for i, j in zip(*np.nonzero(bad), strict=False)]
        warn(
            f"f(A) overflows: entries {where[:10]}{' ...' if len(where) > 10 else ''} are not finite in double "
            "precision (the other entries are accurate); pass an exact matrix for a symbolic result",
            RuntimeWarning,
        )
    real_in = not np.any(An.imag)
    finite = val[~bad]
    scale = max(float(np.max(np.abs(finite))) if finite.size else 0.0, np.finfo(float).tiny)
    with np.errstate(invalid="ignore"):
        small_imag = float(np.max(np.abs(np.where(bad, 0, val.imag)))) <= 1e-13 * scale
    if real_in and (_is_real_function(expr, x) or small_imag):
        val = val.real.copy()
    elif not np.any(np.where(bad, 0, val.imag)):
        val = val.real.copy()
    decomp = _float_decomposition(M, cluster_tol) if want_spectral else None
    return val, decomp


def _to_sympy(val: np.ndarray) -> sp.Matrix:
    n = val.shape[0]
    if not np.iscomplexobj(val):
        return sp.Matrix(n, n, lambda i, j: sp.Float(val[i, j]))
    return sp.Matrix(n, n, lambda i, j: sp.Float(val[i, j].real) + sp.I * sp.Float(val[i, j].imag))


@validated
def series_converges(A: Any, radius: Any, *, center: Any = 0, inner_radius: Any = 0) -> bool | None:
    """Eigenvalue test for a matrix power (or Laurent) series about ``center`` (Bulgakov §1.30, §1.33).

    A scalar-coefficient series ``Σ c_k (A - center E)^k`` converges iff every eigenvalue lies inside the
    scalar disk ``|λ - center| < radius`` (for a Laurent series, inside the annulus
    ``inner_radius < |λ - center| < radius``) and diverges if one lies outside.  On the boundary the test says
    nothing: ``None`` is returned.

    Parameters
    ----------
    A : Matrix, nested list or ndarray
        Square, non-empty matrix (exact, symbolic or float entries).
    radius : number or Expr
        Radius of convergence R > 0 of the scalar series (``sympy.oo`` for an entire function).
    center : number or Expr
        Center β of the expansion (the series is in ``A - βE``).
    inner_radius : number or Expr
        Inner radius (>= 0) of the annulus of a Laurent series; 0 for a power series.

    Returns
    -------
    bool or None
        True when the series converges, False when it diverges, None when an eigenvalue lies on the boundary (or
        the test cannot decide for symbolic entries).

    See Also
    --------
    matrix_function, matrix_power_series

    Examples
    --------
    >>> import sympy as sp
    >>> series_converges(sp.Matrix([[0, 5], [0, sp.Rational(1, 2)]]), 1)   # log(E + z): radius 1
    True
    >>> series_converges(sp.Matrix([[0, 1], [-sp.Rational(3, 2), 0]]), 1)
    False
    """
    M = as_square_matrix(A)
    radius, center, inner = sp.sympify(radius), sp.sympify(center), sp.sympify(inner_radius)
    if is_float_matrix(M):
        eigs = np.linalg.eigvals(np.array(M.evalf(), dtype=complex))
        dist = np.abs(eigs - complex(center))
        r, ri = float(radius), float(inner)
        if np.any(dist > r * (1 + 1e-12)) or np.any(dist < ri * (1 - 1e-12)):
            return False
        if np.all(dist < r * (1 - 1e-12)) and np.all(dist > ri * (1 + 1e-12)):
            return True
        return None
    verdict: bool | None = True
    for root in M.eigenvals():
        d = sp.Abs(sp.sympify(root) - center)
        outer = sp.simplify(d - radius)
        inn = sp.simplify(d - inner) if inner != 0 else sp.Integer(1)
        if outer.is_positive or (inner != 0 and inn.is_negative):
            return False
        if outer.is_negative is not True or (inner != 0 and inn.is_positive is not True):
            verdict = None
    return verdict
