"""Conversions between the four-pole parameter sets A (chain), Z, Y, H, G (Bulgakov (1954), §8.32), S and T.

Sign convention ``"book"`` (Bulgakov's): the output current ``Iy`` is counted *out of* the network, so

* chain:      ``[Ex, Ix] = A [Ey, Iy]``   (the same as the usual ABCD matrix),
* impedance:  ``[Ex, Ey] = Z [Ix, Iy]``,   admittance ``[Ix, Iy] = Y [Ex, Ey]``,
* hybrid:     ``[Ex, Iy] = H [Ix, Ey]``,   inverse hybrid ``[Ix, Ey] = G [Ex, Iy]``,

and a reciprocal network has ``Z12 = -Z21``, ``Y12 = -Y21``, ``det A = 1`` (eqs. (8.255), (8.260)–(8.261)).
Convention ``"ieee"`` counts both currents *into* the network (lcapy, scikit-rf, most textbooks): its Z and G
differ from the book's by the sign of the second column, its Y and H by the sign of the second row.
The scattering parameters S and the scattering-transfer parameters T (``[b1, a1] = T [a2, b2]``, as in scikit-rf)
need reference impedances ``z0`` and do not depend on the convention (see :mod:`.scattering`).

>>> import sympy as sp
>>> from symosc.networks import convert_parameters
>>> ZA, ZB, ZC = sp.symbols("Z_A Z_B Z_C")
>>> Z = sp.Matrix([[ZA + ZB, -ZB], [ZB, -(ZB + ZC)]])     # T section, eq. (8.408)
>>> convert_parameters(Z, "Z", "A").applyfunc(sp.factor)
Matrix([
[(Z_A + Z_B)/Z_B, (Z_A*Z_B + Z_A*Z_C + Z_B*Z_C)/Z_B],
[          1/Z_B,                   (Z_B + Z_C)/Z_B]])
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import validated
from ...errors import ModelError, ParameterError
from .scattering import chain_from_scattering, scattering_from_chain

__all__ = ["PARAMETER_KINDS", "convert_parameters"]

#: Names of the parameter sets understood by :func:`convert_parameters`.
PARAMETER_KINDS = ("A", "Z", "Y", "H", "G", "S", "T")

#: "T" is the scattering-transfer matrix (scikit-rf's); the chain matrix is "A", "ABCD" or "chain"
_ALIASES = {"A": "A", "ABCD": "A", "CHAIN": "A", "Z": "Z", "Y": "Y", "H": "H", "G": "G", "S": "S", "T": "T"}
_FLIP = sp.ImmutableMatrix([[1, 0], [0, -1]])


def _kind(kind: str, name: str) -> str:
    key = str(kind).upper()
    if key not in _ALIASES:
        raise ParameterError(f"{name} must be one of {PARAMETER_KINDS} (or 'ABCD'/'chain'), got {kind!r}")
    return _ALIASES[key]


def _as_2x2(M: Any) -> sp.Matrix:
    try:
        M = sp.Matrix(M)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"parameters must be a 2x2 matrix, got {M!r}") from exc
    if M.shape != (2, 2):
        raise ParameterError(f"parameters must be a 2x2 matrix, got shape {M.shape}")
    return M


def _pivot(value: sp.Expr, source: str, entry: str, target: str) -> sp.Expr:
    v = sp.cancel(value)
    if v == 0:
        raise ModelError(
            f"the {source} parameters have {entry} = 0, so the {target} parameters do not exist "
            f"(the network has no {target} description; use another parameter set)"
        )
    return v


def _to_book(M: sp.Matrix, kind: str, convention: str) -> sp.Matrix:
    if convention == "book" or kind in ("A", "S", "T"):
        return M
    return {"Z": lambda: M * _FLIP, "G": lambda: M * _FLIP, "Y": lambda: _FLIP * M, "H": lambda: _FLIP * M}[kind]()


def _chain_from(M: sp.Matrix, kind: str, z0: Any = 50) -> sp.Matrix:
    if kind == "A":
        return M
    if kind in ("S", "T"):
        return chain_from_scattering(M, kind, z0)
    d = M.det()
    if kind == "Z":
        return sp.Matrix([[M[0, 0], -d], [1, -M[1, 1]]]) / _pivot(M[1, 0], "Z", "Z21", "chain")
    if kind == "Y":
        return sp.Matrix([[-M[1, 1], 1], [-d, M[0, 0]]]) / _pivot(M[1, 0], "Y", "Y21", "chain")
    if kind == "H":
        return sp.Matrix([[-d, M[0, 0]], [-M[1, 1], 1]]) / _pivot(M[1, 0], "H", "H21", "chain")
    return sp.Matrix([[1, -M[1, 1]], [M[0, 0], -d]]) / _pivot(M[1, 0], "G", "G21", "chain")


def _from_chain(A: sp.Matrix, kind: str, z0: Any = 50) -> sp.Matrix:
    if kind == "A":
        return A
    if kind in ("S", "T"):
        return scattering_from_chain(A, kind, z0)
    d = A.det()
    if kind == "Z":
        return sp.Matrix([[A[0, 0], -d], [1, -A[1, 1]]]) / _pivot(A[1, 0], "chain", "A21", "Z")
    if kind == "Y":
        return sp.Matrix([[A[1, 1], -d], [1, -A[0, 0]]]) / _pivot(A[0, 1], "chain", "A12", "Y")
    if kind == "H":
        return sp.Matrix([[A[0, 1], d], [1, -A[1, 0]]]) / _pivot(A[1, 1], "chain", "A22", "H")
    return sp.Matrix([[A[1, 0], d], [1, -A[0, 1]]]) / _pivot(A[0, 0], "chain", "A11", "G")


@validated
def convert_parameters(M: Any, source: str, target: str, convention: str = "book", *, z0: Any = 50) -> sp.Matrix:
    """Convert a 2x2 four-pole parameter matrix between the sets A, Z, Y, H, G, S and T.

    Parameters
    ----------
    M : 2x2 matrix
        Parameters of kind ``source``, symbolic in ``p`` (or ``i*omega``) or numeric.
    source, target : {"A", "Z", "Y", "H", "G", "S", "T"}
        Parameter sets (``"ABCD"`` and ``"chain"`` are accepted for ``"A"``); ``"S"`` scattering and ``"T"``
        scattering-transfer parameters (``[b1, a1] = T [a2, b2]``, scikit-rf's definition).
    convention : {"book", "ieee"}
        ``"book"``: the output current flows out of the network (Bulgakov (1954), §8.32); ``"ieee"``: both port
        currents flow in (lcapy, scikit-rf).  Both ``M`` and the result use it (S and T do not depend on it).
    z0 : number, positive Symbol or pair
        Reference impedance(s) of S and T: one for both ports, or ``(Z01, Z02)``; real and positive.

    Returns
    -------
    sympy.Matrix
        The ``target`` parameters, entries cancelled.

    Raises
    ------
    ModelError
        When the target set does not exist (e.g. Z of a series impedance, where ``A21 = 0``).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import convert_parameters
    >>> Z = sp.symbols("Z")
    >>> convert_parameters([[1, Z], [0, 1]], "A", "Y")
    Matrix([
    [1/Z, -1/Z],
    [1/Z, -1/Z]])
    >>> convert_parameters([[1, Z], [0, 1]], "A", "Y", convention="ieee")
    Matrix([
    [ 1/Z, -1/Z],
    [-1/Z,  1/Z]])

    See Also
    --------
    FourPole, FourPole.parameters
    """
    source, target = _kind(source, "source"), _kind(target, "target")
    if convention not in ("book", "ieee"):
        raise ParameterError(f"convention must be 'book' or 'ieee', got {convention!r}")
    M = _to_book(_as_2x2(M), source, convention)
    result = _from_chain(_chain_from(M, source, z0), target, z0)
    result = _to_book(result, target, convention)  # the flips are involutions
    return sp.Matrix(result).applyfunc(sp.cancel)
