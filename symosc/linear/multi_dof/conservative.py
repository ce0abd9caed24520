"""Conservative systems ``A ÿ + H y = x(t)`` (Bulgakov (1954), §9.1–9.5).

:func:`conservative_modes` solves the pencil ``det(H - λA) = 0`` exactly (SymPy, for exact input) or with
``scipy.linalg.eigh``, returns A-orthonormal modes (Gram–Schmidt in the A-metric for repeated roots, (9.37)–(9.39)),
flags rigid-body (secular, ``c t + c'``) motions when ``H`` is singular and decouples forcing (9.42)–(9.43).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_sympy_matrix, validated
from ...errors import ModelError, ParameterError
from .._util import as_spd_pair

__all__ = ["ModalAnalysis", "a_orthonormalize", "conservative_modes"]


@dataclass(frozen=True)
class ModalAnalysis(SymPyPrintable):
    """Result of :func:`conservative_modes`.

    Attributes
    ----------
    eigenvalues : tuple
        ``λ_k = ω_k²`` ascending (exact SymPy numbers for exact input), repeated by multiplicity.
    modes : Matrix or ndarray
        Columns ``v_k`` with ``vᵀ A v = E`` and ``vᵀ H v = diag(λ)`` (9.35)–(9.36).
    exact : bool
        True when computed in exact arithmetic.
    rigid_body_modes : int
        Number of zero eigenvalues (``H`` singular): each adds a secular motion ``c t + c'`` (§9.2, §9.5 Ex. 2).
    """

    eigenvalues: tuple
    modes: Any
    exact: bool
    rigid_body_modes: int

    @property
    def frequencies(self) -> tuple:
        """Angular frequencies ``ω_k = sqrt(λ_k)`` (imaginary for ``λ < 0``: unstable, hyperbolic motion)."""
        if self.exact:
            return tuple(sp.sqrt(lam) for lam in self.eigenvalues)
        return tuple(np.sqrt(complex(lam)) if lam < 0 else float(np.sqrt(lam)) for lam in self.eigenvalues)

    def modal_forces(self, forces: Any) -> Any:
        """Generalised forces of the normal coordinates, ``vᵀ x`` (9.42): ``η_l'' + λ_l η_l = (vᵀ x)_l``.

        Parameters
        ----------
        forces : sequence, sympy.Matrix or array_like, shape (n,)
            Generalised forces ``x`` on the original coordinates, one per coordinate (numbers or SymPy expressions
            for an exact analysis, finite numbers otherwise).
        """
        if self.exact:
            return self.modes.T * sp.Matrix(forces)
        return np.asarray(self.modes).T @ np.asarray(forces, dtype=float)

    def __repr__(self) -> str:
        return f"ModalAnalysis(eigenvalues={[sp.sstr(e) if self.exact else float(e) for e in self.eigenvalues]})"

    def _latex(self, printer) -> str:
        return (
            r"\Lambda = "
            + printer._print(sp.diag(*self.eigenvalues))
            + r",\ v = "
            + printer._print(sp.Matrix(self.modes))
        )

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(self)}$$"

    def plot(self, *, ax=None, n_modes: int | None = None):
        """Mode shapes against the coordinate index; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        n_modes : int, optional
            Number of modes drawn, lowest first (an integer >= 1); all when omitted.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        V = np.array(sp.Matrix(self.modes).evalf(), dtype=float) if self.exact else np.asarray(self.modes)
        for k in range(V.shape[1] if n_modes is None else min(n_modes, V.shape[1])):
            ax.plot(np.arange(1, V.shape[0] + 1), V[:, k], "o-", label=f"mode {k + 1}")
        ax.set_xlabel("coordinate")
        ax.set_ylabel("amplitude (A-normalized)")
        ax.legend()
        return ax


@validated
def a_orthonormalize(V: Any, A: Any) -> sp.Matrix:
    """Gram–Schmidt in the metric ``A(x, y) = xᵀ A y`` (Bulgakov (1954), eqs. (9.37)–(9.39)), exact.

    Parameters
    ----------
    V : sympy.Matrix, shape (n, k)
        Columns to orthonormalize; must be a SymPy matrix with linearly independent columns.
    A : sympy.Matrix, shape (n, n)
        The metric (inertia matrix); must be a symmetric SymPy matrix, positive definite on the columns of ``V``.

    Returns
    -------
    sympy.Matrix, shape (n, k)
        Columns ``v`` with ``vᵀ A v = E``, spanning the same nested subspaces as ``V``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import a_orthonormalize
    >>> A = sp.Matrix([[32, -16, 4], [-16, 32, 4], [4, 4, 11]])
    >>> v = a_orthonormalize(sp.Matrix([[5, -4], [-4, 5], [4, 4]]), A)    # §9.5 Ex. 3
    >>> v[:, 1].T * 4 * sp.sqrt(15)
    Matrix([[0, 1, 4]])

    See Also
    --------
    conservative_modes
    """
    V, A = check_sympy_matrix("V", V), check_sympy_matrix("A", A)
    out: list[sp.Matrix] = []
    for j in range(V.cols):
        u = V[:, j]
        for v in out:
            u = u - (u.T * A * v)[0] * v
        norm2 = sp.nsimplify(sp.simplify((u.T * A * u)[0]))
        if norm2 == 0:
            raise ModelError("the columns are linearly dependent (or A is not positive definite on them)")
        out.append((u / sp.sqrt(norm2)).applyfunc(sp.radsimp))
    return sp.Matrix.hstack(*out)


def _exact_modes(A: sp.Matrix, H: sp.Matrix) -> ModalAnalysis:
    n = A.rows
    if A != A.T or H != H.T:
        raise ModelError("A (inertia) and H (stiffness) must be symmetric")
    if not all(A[:k, :k].det() > 0 for k in range(1, n + 1)):
        raise ModelError(
            "the inertia matrix A must be positive definite (kinetic energy > 0); got a singular or indefinite A"
        )
    lam = sp.Symbol("lambda")
    roots = sp.roots(sp.Poly((H - lam * A).det(), lam))
    if sum(roots.values()) != n:
        raise ParameterError("det(H - λA) has roots SymPy cannot write in radicals; pass floats for a numeric solve")
    eig, cols = [], []
    for r in sorted(roots, key=lambda z: float(sp.re(z))):
        basis = (H - r * A).nullspace()
        if len(basis) != roots[r]:
            raise ModelError(f"the pencil is defective at λ = {r}: A is not positive definite")
        cols.append(a_orthonormalize(sp.Matrix.hstack(*basis), A))
        eig += [r] * roots[r]
    V = sp.Matrix.hstack(*cols)
    return ModalAnalysis(tuple(eig), sp.ImmutableMatrix(V), True, sum(1 for e in eig if e == 0))


@validated
def conservative_modes(A: Any, H: Any) -> ModalAnalysis:
    """Natural modes of ``A ÿ + H y = 0`` (Bulgakov (1954), §9.2–9.5).

    Parameters
    ----------
    A : array_like or sympy.Matrix
        Symmetric positive definite inertia (mass) matrix.
    H : array_like or sympy.Matrix
        Symmetric stiffness matrix (may be singular: rigid-body modes; or indefinite: unstable modes).

    Returns
    -------
    ModalAnalysis
        Exact for SymPy matrices of exact numbers, else from ``scipy.linalg.eigh``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import conservative_modes
    >>> A = sp.Matrix([[6, 6, 11], [6, 11, 14], [11, 14, 22]])                  # Krylov's example, §9.4
    >>> H = sp.Matrix([[9, 15, 20], [15, 38, 41], [20, 41, 49]])
    >>> conservative_modes(A, H).eigenvalues
    (1, 1, 4)

    See Also
    --------
    a_orthonormalize, dunkerley, rayleigh_quotient
    """
    if isinstance(A, sp.MatrixBase) and isinstance(H, sp.MatrixBase):
        A, H = sp.Matrix(A), sp.Matrix(H)
        if A.shape != H.shape or A.rows != A.cols:
            raise ModelError(f"A and H must be square of one size, got {A.shape} and {H.shape}")
        if not (A.free_symbols or H.free_symbols or any(e.has(sp.Float) for e in list(A) + list(H))):
            return _exact_modes(A, H)
        A = np.array(A.evalf(), dtype=float)
        H = np.array(H.evalf(), dtype=float)
    from scipy.linalg import eigh

    for name, X in (("A", A), ("H", H)):
        if np.ndim(X) != 2:
            raise ParameterError(f"{name} must be a square matrix (array_like or sympy.Matrix), got {X!r:.60}")
    M, K = as_spd_pair(A, H)
    w, V = eigh(K, M)
    scale = max(abs(w).max(), 1e-300)
    return ModalAnalysis(tuple(float(x) for x in w), V, False, int(np.sum(np.abs(w) <= 1e-12 * scale)))
