"""Loaded strings, torsional shafts and beams with point masses (Bulgakov (1954), §9.6–9.7, 9.10–9.13)."""

from __future__ import annotations

from typing import Any

import numpy as np
import sympy as sp

from ..._validate import check_int, check_memory, check_positive, validated
from ...errors import ParameterError
from .._util import as_real_array

__all__ = ["chain_matrices", "influence_matrix", "string_frequencies", "string_modes"]

_BOUNDARIES = ("fixed-fixed", "fixed-free")


def _check_boundary(boundary: str) -> None:
    if boundary not in _BOUNDARIES:
        raise ParameterError(f"boundary must be one of {_BOUNDARIES}, got {boundary!r}")


def _check_count(n: Any, fname: str, columns: int) -> int:
    """``n`` (the number of masses) as an int >= 1 whose result of ``n`` by ``columns`` floats fits in memory."""
    n = check_int("n (number of point masses)", n, minimum=1)
    check_memory(f"{fname}(): n = {n} masses ({n} x {columns} values)", 8.0 * 4 * n * columns)
    return n


@validated
def chain_matrices(masses: Any, stiffnesses: Any, *, boundary: str = "fixed-fixed") -> tuple[np.ndarray, np.ndarray]:
    """Mass and stiffness matrices of a chain: a string with point masses or a shaft with disks (§9.6–9.7, 9.12).

    Parameters
    ----------
    masses : array_like, shape (n,)
        Point masses ``m_j`` (string) or disk moments of inertia ``J_j`` (shaft); positive numbers.
    stiffnesses : array_like
        Positive segment stiffnesses ``P/h_j`` (string, tension over segment length) or ``c_j`` (shaft): ``n + 1``
        values for ``"fixed-fixed"`` (segment 0 joins the left support), ``n`` for ``"fixed-free"``.
    boundary : {"fixed-fixed", "fixed-free"}
        Both ends fixed (default) or the left end fixed and the right end free.

    Returns
    -------
    M, K : ndarray
        Diagonal mass matrix and tridiagonal stiffness matrix (9.45)–(9.46), (9.80)–(9.85).

    Examples
    --------
    >>> from symosc.linear import chain_matrices
    >>> M, K = chain_matrices([1, 1], [1, 1, 1])
    >>> K.tolist()
    [[2.0, -1.0], [-1.0, 2.0]]

    See Also
    --------
    string_frequencies, influence_matrix
    """
    _check_boundary(boundary)
    m = as_real_array(masses, "masses", 1)
    c = as_real_array(stiffnesses, "stiffnesses", 1)
    n = m.size
    need = n + 1 if boundary == "fixed-fixed" else n
    if n == 0 or c.size != need:
        raise ParameterError(f"{boundary} chain of {n} masses needs {need} stiffnesses, got {c.size}")
    if np.any(m <= 0) or np.any(c <= 0):
        raise ParameterError("masses and stiffnesses must be positive")
    K = np.zeros((n, n))
    for j in range(n):
        K[j, j] = c[j] + (c[j + 1] if j + 1 < c.size else 0.0)
        if j + 1 < n:
            K[j, j + 1] = K[j + 1, j] = -c[j + 1]
    return np.diag(m), K


@validated
def string_frequencies(
    n: int, *, boundary: str = "fixed-fixed", tension: float = 1.0, mass: float = 1.0, spacing: float = 1.0
) -> np.ndarray:
    """Closed-form angular frequencies of a uniform loaded string (Bulgakov (1954), eqs. (9.65), (9.90)).

    Fixed–fixed: ``ω_k = 2 sqrt(P/(m h)) sin(kπ / (2(n+1)))``; fixed–free: ``ω_k = 2 sqrt(P/(m h))
    sin((2k-1)π / (2(2n+1)))``, ``k = 1..n``.  The same formulas hold for a uniform shaft with ``P/h → c``,
    ``m → J``.  Written with ``sin`` (not ``1 - cos``) so that the fundamental keeps full precision for long chains.

    Parameters
    ----------
    n : int
        Number of point masses; a positive integer.
    boundary : {"fixed-fixed", "fixed-free"}, optional
        Both ends fixed (default) or the left end fixed and the right end free.
    tension : float, optional
        String tension ``P`` (or shaft stiffness ``c`` with ``spacing = 1``); must be positive (default 1).
    mass : float, optional
        Each point mass ``m`` (or disk moment of inertia ``J``); must be positive (default 1).
    spacing : float, optional
        Segment length ``h`` between the masses; must be positive (default 1).

    Returns
    -------
    ndarray, shape (n,)
        ``ω_1 < ... < ω_n``.

    Examples
    --------
    >>> from symosc.linear import string_frequencies
    >>> string_frequencies(3).round(6).tolist()          # §9.6, n = 3
    [0.765367, 1.414214, 1.847759]

    See Also
    --------
    chain_matrices, string_modes
    """
    _check_boundary(boundary)
    n = _check_count(n, "string_frequencies", 1)
    tension, mass, spacing = (check_positive(name, value) for name, value in
                              (("tension", tension), ("mass", mass), ("spacing", spacing)))  # fmt: skip
    k = np.arange(1, n + 1)
    scale = 2.0 * np.sqrt(tension / (mass * spacing))
    if boundary == "fixed-fixed":
        return scale * np.sin(k * np.pi / (2 * (n + 1)))
    return scale * np.sin((2 * k - 1) * np.pi / (2 * (2 * n + 1)))


@validated
def string_modes(n: int, *, boundary: str = "fixed-fixed") -> np.ndarray:
    """Closed-form mode shapes (columns) ``sin(jkπ/(n+1))`` (9.68) or ``sin(j(2k-1)π/(2n+1))`` (9.91).

    Parameters
    ----------
    n : int
        Number of point masses; a positive integer.
    boundary : {"fixed-fixed", "fixed-free"}, optional
        Both ends fixed (default) or the left end fixed and the right end free.

    Returns
    -------
    ndarray, shape (n, n)
        Column ``k`` is mode ``k`` (unnormalized), row ``j`` the mass ``j``.

    Examples
    --------
    >>> from symosc.linear import string_modes
    >>> string_modes(2).round(4).tolist()
    [[0.866, 0.866], [0.866, -0.866]]

    See Also
    --------
    string_frequencies
    """
    _check_boundary(boundary)
    n = _check_count(n, "string_modes", n)
    j = np.arange(1, n + 1)[:, None]
    k = np.arange(1, n + 1)[None, :]
    if boundary == "fixed-fixed":
        return np.sin(j * k * np.pi / (n + 1))
    return np.sin(j * (2 * k - 1) * np.pi / (2 * n + 1))


@validated
def influence_matrix(
    kind: str, positions: Any, *, length: Any = None, rigidity: Any = 1, compliances: Any = None
) -> sp.Matrix:
    """Influence (flexibility) matrix ``Φ = H⁻¹`` (Bulgakov (1954), §9.11–9.13), exact for exact input.

    Parameters
    ----------
    kind : {"string fixed-fixed", "string fixed-free", "shaft fixed-fixed", "shaft fixed-free", "beam"}
        String with tension ``rigidity`` (9.146)–(9.149); shaft given by cumulative compliances (9.152)–(9.153);
        simply supported beam with flexural rigidity ``rigidity`` (9.155)–(9.156).
    positions : sequence
        Abscissae of the masses (string, beam); ignored for the shaft.
    length : number
        Span ``l`` (string, beam; for ``"shaft fixed-fixed"`` the total compliance).
    rigidity : number
        Tension ``P`` (string) or flexural rigidity ``B`` (beam).
    compliances : sequence
        Shaft: compliance ``a_j`` from the fixed end to disk ``j``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import influence_matrix
    >>> l = sp.Integer(4)
    >>> influence_matrix("beam", [1, 2, 3], length=l) * 768 / l**3          # §9.13, masses at quarter points
    Matrix([
    [ 9, 11,  7],
    [11, 16, 11],
    [ 7, 11,  9]])

    See Also
    --------
    dunkerley_bounds, power_iteration
    """
    kinds = ("string fixed-fixed", "string fixed-free", "shaft fixed-fixed", "shaft fixed-free", "beam")
    if kind not in kinds:
        raise ParameterError(f"kind must be one of {kinds}, got {kind!r}")
    if kind.startswith("shaft"):
        if compliances is None:
            raise ParameterError("a shaft needs compliances= (cumulative compliance from the fixed end to each disk)")
        a = [sp.sympify(v) for v in compliances]
        n = len(a)
        if kind == "shaft fixed-free":
            return sp.Matrix(n, n, lambda j, k: a[min(j, k)])
        total = sp.sympify(length) if length is not None else None
        if total is None:
            raise ParameterError("shaft fixed-fixed needs length= (the total compliance between the supports)")
        return sp.Matrix(n, n, lambda j, k: a[min(j, k)] * (total - a[max(j, k)]) / total)
    s = [sp.sympify(v) for v in positions]
    n = len(s)
    R = sp.sympify(rigidity)
    if kind == "string fixed-free":
        return sp.Matrix(n, n, lambda j, k: sp.Min(s[j], s[k]) / R)
    if length is None:
        raise ParameterError(f"{kind} needs length= (the span)")
    L = sp.sympify(length)

    def phi(x, y):
        lo, hi = (x, y) if bool(x <= y) else (y, x)
        if kind == "string fixed-fixed":
            return lo * (L - hi) / (R * L)
        return lo * (L - hi) * (2 * L * hi - hi**2 - lo**2) / (6 * L * R)

    return sp.Matrix(n, n, lambda j, k: sp.simplify(phi(s[j], s[k])))
