"""Damped/gyroscopic modes of ``M q'' + D q' + K q = 0`` and Floquet analysis of ``K = K0 + K1 cos(p t)``.

The quadratic eigenproblem ``(M s**2 + D s + K) phi = 0`` is solved through its first companion
linearization, the ``2n x 2n`` pencil

    [[0, I], [-K, -D]] z = s [[I, 0], [0, M]] z,      z = (phi, s phi),

which needs no inverse of ``M`` (``scipy.linalg.eig`` of the pencil; QZ algorithm).  The periodic case
builds the first-order matrix ``A(t) = [[0, I], [-M^{-1} K(t), -M^{-1} D]]`` and hands it to
:func:`symosc.periodic.monodromy`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ModelError, ParameterError
from ..symbols import sort_symbols, t

if TYPE_CHECKING:
    from ..periodic.floquet import FloquetResult
    from .linear_model import LinearModel

__all__ = ["ComplexModes", "complex_modes", "periodic_monodromy"]


@dataclass(frozen=True)
class ComplexModes(SymPyPrintable):
    """Eigenvalues and mode shapes of the quadratic eigenproblem ``(M s**2 + D s + K) phi = 0``.

    Attributes
    ----------
    eigenvalues : ndarray, shape (2n,)
        The ``2n`` roots ``s`` of ``det(M s**2 + D s + K) = 0``, ordered by increasing ``|s|`` and, within a
        complex-conjugate pair, positive imaginary part first.
    vectors : ndarray, shape (n, 2n)
        Mode shapes ``phi`` (columns, complex), each normalised to unit Euclidean norm with its
        largest-magnitude component real and positive.
    residual : float
        Achieved accuracy: ``max_k ||(M s_k**2 + D s_k + K) phi_k|| / (||M|| |s_k|**2 + ||D|| |s_k| + ||K||)``.
    """

    eigenvalues: np.ndarray
    vectors: np.ndarray
    residual: float

    @property
    def frequencies(self) -> np.ndarray:
        """Damped angular frequencies ``Im s`` of the oscillatory roots (``Im s > 0``), ascending (rad/s)."""
        s = self.eigenvalues
        tol = 1e-12 * max(1.0, float(np.max(np.abs(s), initial=0.0)))
        return np.sort(s.imag[s.imag > tol])

    @property
    def natural_frequencies(self) -> np.ndarray:
        """``|s|`` of the oscillatory roots (``Im s > 0``), ascending: the undamped frequency of each mode."""
        s = self.eigenvalues
        tol = 1e-12 * max(1.0, float(np.max(np.abs(s), initial=0.0)))
        return np.sort(np.abs(s[s.imag > tol]))

    @property
    def damping_ratios(self) -> np.ndarray:
        """``-Re s / |s|`` for every root (negative for a growing mode), in the order of :attr:`eigenvalues`."""
        s = self.eigenvalues
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(np.abs(s) > 0, -s.real / np.abs(s), 0.0)

    @property
    def mode_shape_moduli(self) -> np.ndarray:
        """``sign(Re phi) |phi|`` per component, for every root: the real mode shape recovered from a complex one
        (stage 3 of the identification recipe of Belyakov (2005), Ch. III §4)."""
        return np.where(self.vectors.real < 0, -1.0, 1.0) * np.abs(self.vectors)

    @property
    def stability(self) -> str:
        """``"asymptotically stable"``, ``"marginally stable"`` (roots on the imaginary axis) or ``"unstable"``.

        Decided with the tolerance ``1e-9 * max|s|`` on ``Re s``; multiple roots on the axis (secular terms)
        are not distinguished from simple ones.
        """
        s = self.eigenvalues
        tol = 1e-9 * max(1.0, float(np.max(np.abs(s), initial=0.0)))
        if np.all(s.real < -tol):
            return "asymptotically stable"
        if np.all(s.real <= tol):
            return "marginally stable"
        return "unstable"

    def __repr__(self) -> str:
        shown = ", ".join(f"{z.real:.6g}{z.imag:+.6g}j" for z in self.eigenvalues[:6])
        more = ", ..." if self.eigenvalues.size > 6 else ""
        return f"ComplexModes(n={self.vectors.shape[0]}, s=[{shown}{more}], {self.stability})"

    def _repr_latex_(self) -> str:
        roots = ", ".join(sp.latex(sp.Float(z.real, 6) + sp.I * sp.Float(z.imag, 6)) for z in self.eigenvalues)
        return f"$$s = \\{{{roots}\\}}$$"

    def plot(self, *, ax: Any = None) -> Any:
        """Roots ``s`` in the complex plane; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        ax.plot(self.eigenvalues.real, self.eigenvalues.imag, "x")
        ax.axvline(0.0, color="0.6", lw=0.8)
        ax.set_xlabel("Re s")
        ax.set_ylabel("Im s")
        ax.set_title(f"roots of det(M s^2 + D s + K) ({self.stability})")
        return ax


def _square(name: str, a: Any, n: int | None) -> np.ndarray:
    try:
        arr = np.asarray(a, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a real square matrix, got {type(a).__name__}") from exc
    if arr.ndim != 2 or arr.shape[0] != arr.shape[1] or (n is not None and arr.shape[0] != n):
        raise ParameterError(f"{name} must be a square matrix of the size of M, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{name} has non-finite entries")
    return arr


@validated
def complex_modes(M: Any, D: Any, K: Any) -> ComplexModes:
    """Roots and mode shapes of ``(M s**2 + D s + K) phi = 0`` with damping and gyroscopic terms.

    Parameters
    ----------
    M, D, K : array_like, shape (n, n)
        Mass (nonsingular), damping-plus-gyroscopic and stiffness matrices (real; no symmetry needed).

    Returns
    -------
    ComplexModes

    Raises
    ------
    ParameterError
        Non-square, mismatched or non-finite matrices.
    ModelError
        Singular ``M`` (infinite roots).

    See Also
    --------
    symosc.mechanics.LinearModel.complex_modes : the same from a linearised model and parameter values.
    symosc.mechanics.LinearModel.modes : undamped modes of a symmetric ``M``, ``K``.
    symosc.identification.quadratic_modes : symmetric ``M``, ``D``, ``K`` with oscillatory modes only
        (Belyakov (2005), eq. (97)); this function also takes gyroscopic (skew) ``D``, circulatory ``K``,
        overdamped and growing modes.

    Notes
    -----
    Solved through the companion pencil ``[[0, I], [-K, -D]] z = s [[I, 0], [0, M]] z`` (QZ).  For a
    spinning system written in a rotating frame, ``D`` is skew (Coriolis) and the roots of an isotropic
    oscillator ``M = m I``, ``K = (k - m Omega**2) I``, ``D = 2 m Omega J`` are ``s = +-i (omega0 +- Omega)``,
    ``omega0 = sqrt(k/m)``.

    Examples
    --------
    Isotropic oscillator seen from a frame rotating at ``Omega = 0.5`` (``omega0 = 2``):

    >>> import numpy as np
    >>> W = 0.5
    >>> res = complex_modes(np.eye(2), [[0, -2 * W], [2 * W, 0]], (4 - W**2) * np.eye(2))
    >>> res.frequencies.round(10).tolist()
    [1.5, 2.5]
    >>> res.stability
    'marginally stable'
    """
    from scipy.linalg import eig

    Mn = _square("M", M, None)
    n = Mn.shape[0]
    Dn, Kn = _square("D", D, n), _square("K", K, n)
    if n == 0:
        raise ParameterError("M must have at least one row")
    if np.linalg.cond(Mn) * np.finfo(float).eps > 1e-2:
        raise ModelError("the mass matrix M is singular: the quadratic eigenproblem has infinite roots")
    eye, zero = np.eye(n), np.zeros((n, n))
    A = np.block([[zero, eye], [-Kn, -Dn]])
    B = np.block([[eye, zero], [zero, Mn]])
    s, Z = eig(A, B)
    order = np.lexsort((-s.imag, np.round(np.abs(s), 12)))
    s, Z = s[order], Z[:n, order]
    big = np.argmax(np.abs(Z), axis=0)
    phase = Z[big, np.arange(2 * n)]
    Z = Z / (phase / np.abs(phase))
    Z = Z / np.linalg.norm(Z, axis=0)
    scale = np.linalg.norm(Mn, 2) * np.abs(s) ** 2 + np.linalg.norm(Dn, 2) * np.abs(s) + np.linalg.norm(Kn, 2)
    res = [
        np.linalg.norm((Mn * sk**2 + Dn * sk + Kn) @ Z[:, k]) / sc
        for k, (sk, sc) in enumerate(zip(s, scale, strict=True))
    ]
    return ComplexModes(eigenvalues=s, vectors=Z, residual=float(max(res)))


def model_complex_modes(lin: LinearModel, values: Mapping[Any, Any]) -> ComplexModes:
    """Implementation of :meth:`LinearModel.complex_modes`."""
    M, D, K = lin.matrices(values)
    if M.ndim != 2:
        raise ParameterError("complex_modes takes scalar parameter values (no arrays)")
    return complex_modes(M, D, K)


def periodic_monodromy(lin: LinearModel, values: Mapping[Any, Any], **kwargs: Any) -> FloquetResult:
    """Implementation of :meth:`LinearModel.monodromy` (see there)."""
    from ..numeric import compile, resolve
    from ..periodic.floquet import monodromy

    if not isinstance(values, Mapping):
        raise ParameterError(f"values must be a mapping of parameter names to numbers, got {type(values).__name__}")
    K0, K1, p = lin.periodic_stiffness()
    M, D, _ = lin.matrices(values)
    if M.ndim != 2:
        raise ParameterError("monodromy takes scalar parameter values (no arrays)")
    n = M.shape[0]
    syms = sort_symbols((K0.free_symbols | K1.free_symbols | p.free_symbols) - {t})
    k_fn = compile(K0.row_join(K1).col_join(sp.Matrix([[p] + [0] * (2 * n - 1)])), list(syms), name="periodic_K")
    vals = np.asarray(k_fn(*[float(v) for v in resolve(syms, values)]), dtype=float)
    K0n, K1n, pn = vals[:n, :n], vals[:n, n:], float(vals[n, 0])
    if not np.isfinite(pn) or pn <= 0:
        raise ParameterError(f"the excitation frequency p = {pn} must be positive")
    try:
        Minv = np.linalg.inv(M)
    except np.linalg.LinAlgError as exc:
        raise ModelError("the mass matrix is singular at these parameter values") from exc
    S0, S1, C = -Minv @ K0n, -Minv @ K1n, -Minv @ D
    eye, zero = np.eye(n), np.zeros((n, n))

    def A(tt: float) -> np.ndarray:
        return np.block([[zero, eye], [S0 + S1 * np.cos(pn * tt), C]])

    kwargs.setdefault("reversor", np.diag([1.0] * n + [-1.0] * n) if not np.any(D) else None)
    return monodromy(A, 2.0 * np.pi / pn, **kwargs)
