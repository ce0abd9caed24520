"""Eigenvalue bounds and iterations for conservative systems (Bulgakov (1954), §9.8–9.9, 9.17–9.18).

* :func:`rayleigh_quotient` — ``λ(u) = H(u, u)/A(u, u)``, an upper bound of ``ω1²`` (9.97)–(9.105).
* :func:`constrained_eigenvalues` — eigenvalues under added linear constraints (Rayleigh's theorem I, interlacing).
* :func:`dunkerley` — Dunkerley's lower bound of the fundamental angular frequency, ``ω1 ≥ (Σ m_j Φ_jj)^(-1/2)``.
* :func:`dunkerley_bounds` — van den Dungen / Papkovich brackets from traces of powers of ``L = ΦA`` (9.192)–(9.198).
* :func:`power_iteration` — successive multiplications (Vianello) with deflation for higher modes (§9.18).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ModelError, ParameterError
from .._util import as_real_array, as_spd_pair

__all__ = [
    "FrequencyBounds",
    "PowerIteration",
    "constrained_eigenvalues",
    "dunkerley",
    "dunkerley_bounds",
    "power_iteration",
    "rayleigh_quotient",
]


@validated
def rayleigh_quotient(M: Any, K: Any, u: Any) -> float:
    """Rayleigh quotient ``λ(u) = uᵀKu / uᵀMu`` (Bulgakov (1954), eq. (9.97)); ``λ1 ≤ λ(u) ≤ λn``.

    Parameters
    ----------
    M : array_like, shape (n, n)
        Mass (inertia) matrix: finite, symmetric positive definite.
    K : array_like, shape (n, n)
        Stiffness matrix: finite, symmetric, the same size as ``M``.
    u : array_like, shape (n,)
        Trial vector (an approximate mode shape); a nonzero finite vector of length ``n``.

    Returns
    -------
    float

    Examples
    --------
    >>> from symosc.linear import rayleigh_quotient
    >>> rayleigh_quotient([[1, 0], [0, 1]], [[2, -1], [-1, 2]], [1, 1])
    1.0

    See Also
    --------
    dunkerley, constrained_eigenvalues
    """
    M, K = as_spd_pair(M, K)
    u = as_real_array(u, "u", 1)
    if u.size != M.shape[0] or not np.any(u):
        raise ParameterError(f"u must be a nonzero vector of length {M.shape[0]}")
    return float(u @ K @ u / (u @ M @ u))


@validated
def constrained_eigenvalues(M: Any, K: Any, C: Any) -> np.ndarray:
    """Eigenvalues ``λ'`` of the pencil restricted to ``C u = 0`` (Bulgakov (1954), §9.9, Rayleigh's theorem I).

    With ``c`` independent constraints, ``λ_j ≤ λ'_j ≤ λ_(c+j)``.

    Parameters
    ----------
    M : array_like, shape (n, n)
        Mass (inertia) matrix: finite, symmetric positive definite.
    K : array_like, shape (n, n)
        Stiffness matrix: finite, symmetric, the same size as ``M``.
    C : array_like, shape (c, n) or (n,)
        Constraint matrix (one row per constraint ``c_i · u = 0``); finite, ``n`` columns, leaving some motion free.

    Returns
    -------
    ndarray
        The ``n - rank(C)`` constrained eigenvalues, ascending.

    Examples
    --------
    >>> from symosc.linear import constrained_eigenvalues
    >>> constrained_eigenvalues([[1, 0], [0, 1]], [[2, -1], [-1, 2]], [[1, -1]]).tolist()  # y1 = y2
    [1.0]

    See Also
    --------
    rayleigh_quotient
    """
    from scipy.linalg import eigh, null_space

    M, K = as_spd_pair(M, K)
    C = np.atleast_2d(as_real_array(C, "C", 2 if np.ndim(C) == 2 else 1))
    if C.shape[1] != M.shape[0]:
        raise ParameterError(f"C must have {M.shape[0]} columns, got {C.shape[1]}")
    Z = null_space(C)
    if Z.shape[1] == 0:
        raise ModelError("the constraints C u = 0 leave no motion")
    return eigh(Z.T @ K @ Z, Z.T @ M @ Z, eigvals_only=True)


@validated
def dunkerley(M: Any, K: Any) -> float:
    """Dunkerley's lower bound of the fundamental angular frequency (Bulgakov (1954), §9.17).

    ``1/ω1² < Σ_k 1/ω_k² = tr(K⁻¹ M)``, so ``ω1 > tr(K⁻¹M)^(-1/2)`` (for a diagonal ``M``: ``Σ m_j Φ_jj``).

    Parameters
    ----------
    M : array_like
        Symmetric positive definite mass matrix.
    K : array_like
        Symmetric positive definite stiffness matrix.

    Returns
    -------
    float
        A lower bound of ``ω1`` (rad/s for SI input).

    Examples
    --------
    >>> from symosc.linear import dunkerley
    >>> round(dunkerley([[1, 0], [0, 1]], [[2, -1], [-1, 2]]), 6)        # exact ω1 = 1
    0.866025

    See Also
    --------
    dunkerley_bounds, rayleigh_quotient, power_iteration
    """
    from scipy.linalg import cho_factor, cho_solve

    M, K = as_spd_pair(M, K, allow_singular_k=False)
    trace = float(np.trace(cho_solve(cho_factor(K), M)))
    return trace**-0.5


@dataclass(frozen=True)
class FrequencyBounds(SymPyPrintable):
    """Result of :func:`dunkerley_bounds`: brackets of the dominant ``z1 = 1/ω1²`` of ``L = ΦA``.

    Attributes
    ----------
    powers : tuple of int
        The exponents ``m`` used.
    traces : tuple
        ``s_m = tr L^m`` (exact for exact input).
    z_lower, z_upper : tuple of float
        ``(s_m'/s_m)^(1/(m'-m))`` for consecutive powers (the first entry None) and ``s_m^(1/m)`` (9.194)–(9.198).
    omega_lower, omega_upper : tuple of float
        The same as brackets of ``ω1 = z1^(-1/2)`` (in units of the scaling of ``L``).
    """

    powers: tuple
    traces: tuple
    z_lower: tuple
    z_upper: tuple

    @property
    def omega_lower(self) -> tuple:
        return tuple(z**-0.5 for z in self.z_upper)

    @property
    def omega_upper(self) -> tuple:
        return tuple(None if z is None else z**-0.5 for z in self.z_lower)

    def __repr__(self) -> str:
        rows = ", ".join(
            f"m={m}: {'-' if lo is None else f'{lo:.6g}'} < z1 < {hi:.6g}"
            for m, lo, hi in zip(self.powers, self.z_lower, self.z_upper, strict=True)
        )
        return f"FrequencyBounds({rows})"

    def plot(self, *, ax=None):
        """Upper and lower bounds of ``z1`` against the power ``m``; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        ax.plot(self.powers, self.z_upper, "v-", label=r"upper $s_m^{1/m}$")
        lo = [(m, z) for m, z in zip(self.powers, self.z_lower, strict=True) if z is not None]
        ax.plot([m for m, _ in lo], [z for _, z in lo], "^-", label="lower (trace ratio)")
        ax.set_xlabel("power m")
        ax.set_ylabel("z1 = 1/ω1²")
        ax.legend()
        return ax


@validated
def dunkerley_bounds(L: Any, *, powers: Any = (1, 2, 4, 8)) -> FrequencyBounds:
    """Van den Dungen / Papkovich brackets of the dominant eigenvalue of ``L = ΦA`` (Bulgakov (1954), §9.17).

    ``(s_m'/s_m)^(1/(m'-m)) < z1 < s_m'^(1/m')`` with ``s_m = tr L^m``; ``m = 1`` is Dunkerley's bound.  The default
    squaring schedule ``1, 2, 4, 8`` needs only ``L², L⁴ = L²L², L⁸ = L⁴L⁴``.  Exact integer/rational matrices keep
    exact traces.

    Parameters
    ----------
    L : array_like or sympy.Matrix
        Dynamic matrix ``ΦA`` with positive eigenvalues ``z_k = 1/ω_k²``.
    powers : sequence of int
        Exponents ``m``: strictly increasing positive integers.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import dunkerley_bounds
    >>> L = sp.Matrix([[9, 22, 7], [11, 32, 11], [7, 22, 9]])             # beam of §9.13
    >>> b = dunkerley_bounds(L, powers=(1, 2, 3))
    >>> b.traces, round(b.z_upper[1], 2), round(b.z_lower[1], 3)
    ((50, 2252, 106568), 47.46, 45.04)

    See Also
    --------
    dunkerley, power_iteration
    """
    powers = tuple(int(m) for m in powers)
    if not powers or any(m < 1 for m in powers) or any(b <= a for a, b in itertools.pairwise(powers)):
        raise ParameterError(f"powers must be increasing positive integers, got {powers}")
    exact = isinstance(L, sp.MatrixBase) and not any(e.has(sp.Float) for e in L) and not L.free_symbols
    Lm = sp.Matrix(L) if exact else as_real_array(L, "L", 2)
    if Lm.shape[0] != Lm.shape[1]:
        raise ParameterError(f"L must be square, got {Lm.shape}")
    traces, cache = [], {1: Lm}
    for m in powers:
        # binary powering reuses the squarings L^2, L^4, ... (Papkovich's schedule)
        P, e, base, b = None, m, 1, Lm
        while e:
            if e & 1:
                P = b if P is None else P @ b if not exact else P * b
            e >>= 1
            if e:
                base *= 2
                if base not in cache:
                    cache[base] = cache[base // 2] * cache[base // 2] if exact else cache[base // 2] @ cache[base // 2]
                b = cache[base]
        traces.append(P.trace() if exact else float(np.trace(P)))
    if any(float(s) <= 0 for s in traces):
        raise ModelError("tr L^m must be positive: L = ΦA must have positive eigenvalues (positive definite A, Φ)")
    upper = tuple(float(s) ** (1.0 / m) for s, m in zip(traces, powers, strict=True))
    lower = (
        None,
        *tuple(
            (float(traces[i + 1]) / float(traces[i])) ** (1.0 / (powers[i + 1] - powers[i]))
            for i in range(len(powers) - 1)
        ),
    )
    return FrequencyBounds(powers, tuple(traces), lower, upper)


@dataclass(frozen=True)
class PowerIteration(SymPyPrintable):
    """Result of :func:`power_iteration`.

    Attributes
    ----------
    eigenvalues : tuple of float
        Dominant ``z_1 > z_2 > ...`` of ``L`` (``z = 1/ω²`` for ``L = ΦA``).
    vectors : ndarray
        Columns, normalized to a largest element of 1 (the book's normalization).
    iterations : tuple of int
        Multiplications used for each eigenvalue.
    history : tuple of ndarray
        Successive normalized vectors of the first eigenvalue (Tables 6–7 of the book).
    achieved : tuple of float
        Final change of the normalized vector (max norm) for each eigenvalue.
    """

    eigenvalues: tuple
    vectors: np.ndarray
    iterations: tuple
    history: tuple
    achieved: tuple

    @property
    def frequencies(self) -> tuple:
        """``ω_k = z_k^(-1/2)``."""
        return tuple(z**-0.5 for z in self.eigenvalues)

    def __repr__(self) -> str:
        return f"PowerIteration(eigenvalues={list(self.eigenvalues)}, iterations={list(self.iterations)})"

    def plot(self, *, ax=None):
        """Convergence of the normalized vector of the first eigenvalue; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        h = np.array(self.history)
        ax.semilogy(np.arange(1, len(h)), np.abs(np.diff(h, axis=0)).max(axis=1) + 1e-300, "o-")
        ax.set_xlabel("iteration")
        ax.set_ylabel("change of normalized vector")
        return ax


@validated
def power_iteration(
    L: Any, *, start: Any = None, mass: Any = None, n_modes: int = 1, tol: float = 1e-12, max_iterations: int = 10_000
) -> PowerIteration:
    """Successive multiplications ``u ← L u`` (Vianello; Bulgakov (1954), §9.18) with deflation.

    Each step normalizes the largest element to 1; the ratio ``(Lu)_j/u_j`` at that element tends to ``z1`` and
    ``u`` to the first mode, at the rate ``|z2/z1|``.  Higher modes by deflation
    ``L ← L - z v (vᵀ A) / (vᵀ A v)`` with the mass matrix ``A`` (``mass``, default identity; ``L = ΦA`` is then
    A-self-adjoint).

    Parameters
    ----------
    L : array_like
        Dynamic matrix ``L = ΦA``: a finite real square matrix.
    start : array_like, optional
        Starting vector: finite, nonzero, of length ``n`` (default all ones).  A start orthogonal to a mode never finds
        it (e.g. a symmetric start for an antisymmetric mode); deflation uses a generic start.
    mass : array_like, optional
        Mass matrix ``A`` for the deflation: finite, symmetric positive definite, ``n x n`` (default identity).
    n_modes : int
        Number of dominant eigenvalues, an integer from 1 to ``n``.
    tol : float
        Stop when the normalized vector changes by less than ``tol`` (max norm).
    max_iterations : int
        Largest number of multiplications per eigenvalue (an integer >= 1); more raises ConvergenceError.

    Returns
    -------
    PowerIteration

    Raises
    ------
    ConvergenceError
        When ``tol`` is not reached (e.g. ``|z2| = |z1|``).

    Examples
    --------
    >>> from symosc.linear import power_iteration
    >>> L = [[9, 22, 7], [11, 32, 11], [7, 22, 9]]                           # beam of §9.13
    >>> r = power_iteration(L, start=[0.5, 1, 0.5])
    >>> round(r.eigenvalues[0], 4), r.iterations[0] < 20
    (47.4094, True)

    See Also
    --------
    dunkerley_bounds, dunkerley
    """
    L = as_real_array(L, "L", 2).copy()
    n = L.shape[0]
    if L.shape != (n, n):
        raise ParameterError(f"L must be square, got {L.shape}")
    A = np.eye(n) if mass is None else as_real_array(mass, "mass", 2)
    if not (1 <= n_modes <= n):
        raise ParameterError(f"n_modes must be in 1..{n}, got {n_modes}")
    u0 = np.ones(n) if start is None else as_real_array(start, "start", 1)
    eigs, vecs, its, ach, history = [], [], [], [], []
    rng = np.random.default_rng(12345)
    for mode in range(n_modes):
        u = u0.copy() if mode == 0 else u0 + 0.1 * rng.standard_normal(n)
        u = u / u[np.argmax(np.abs(u))]
        change = np.inf
        for it in range(1, max_iterations + 1):  # noqa: B007 (the count is reported)
            w = L @ u
            j = int(np.argmax(np.abs(w)))
            if w[j] == 0:
                raise ConvergenceError("L u = 0: the start lies in the null space of L")
            z = w[j] / u[j] if u[j] != 0 else w[j]
            w = w / w[j]
            change = float(np.abs(w - u).max())
            u = w
            if mode == 0:
                history.append(u.copy())
            if change <= tol:
                break
        else:
            raise ConvergenceError(
                f"power iteration for eigenvalue {mode + 1} reached {change:.3g} > tol={tol:g} after {max_iterations} "
                "multiplications (|z2/z1| close to 1, or equal moduli)",
                achieved=change,
            )
        z = float(u @ A @ (L @ u) / (u @ A @ u))
        eigs.append(z)
        vecs.append(u.copy())
        its.append(it)
        ach.append(change)
        L = L - z * np.outer(u, u @ A) / (u @ A @ u)
    return PowerIteration(tuple(eigs), np.array(vecs).T, tuple(its), tuple(history), tuple(ach))
