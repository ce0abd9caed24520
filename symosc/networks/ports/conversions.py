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

import numpy as np
import sympy as sp

from ..._validate import validated
from ...errors import ModelError, ParameterError

__all__ = ["PARAMETER_KINDS", "convert_parameters"]

#: Names of the parameter sets understood by :func:`convert_parameters`.
PARAMETER_KINDS = ("A", "Z", "Y", "H", "G", "S", "T")

#: "T" is the scattering-transfer matrix (scikit-rf's); the chain matrix is "A", "ABCD" or "chain"
_ALIASES = {"A": "A", "ABCD": "A", "CHAIN": "A", "Z": "Z", "Y": "Y", "H": "H", "G": "G", "S": "S", "T": "T"}
_FLIP = sp.ImmutableMatrix([[1, 0], [0, -1]])


def scattering_references(z0: Any) -> tuple[Any, Any]:
    """``(Z01, Z02)`` from one reference impedance or a pair (numbers > 0 or positive symbols)."""
    pair = tuple(z0) if isinstance(z0, tuple | list | np.ndarray) else (z0, z0)
    if len(pair) != 2:
        raise ParameterError(f"z0 must be one reference impedance or a pair (Z01, Z02), got {z0!r}")
    out = []
    for z in pair:
        v = sp.sympify(z)
        if v.is_number and not (v.is_real and v > 0):
            raise ParameterError(f"z0 must be real and positive (power waves with real references), got {z}")
        if not v.is_number and v.is_positive is not True:
            raise ParameterError(f"a symbolic z0 must be declared positive (Symbol(..., positive=True)), got {z}")
        out.append(v)
    return out[0], out[1]


def s_from_abcd(a: Any, b: Any, c: Any, d: Any, z1: Any, z2: Any, sqrt: Any) -> tuple:
    delta = a * z2 + b + c * z1 * z2 + d * z1
    root = sqrt(z1 * z2)
    return (
        (a * z2 + b - c * z1 * z2 - d * z1) / delta,
        2 * (a * d - b * c) * root / delta,
        2 * root / delta,
        (-a * z2 + b - c * z1 * z2 + d * z1) / delta,
    )


def abcd_from_s(s11: Any, s12: Any, s21: Any, s22: Any, z1: Any, z2: Any, sqrt: Any) -> tuple:
    den = 2 * s21 * sqrt(z1 * z2)
    return (
        ((z1 + s11 * z1) * (1 - s22) + s12 * s21 * z1) / den,
        ((z1 + s11 * z1) * (z2 + s22 * z2) - s12 * s21 * z1 * z2) / den,
        ((1 - s11) * (1 - s22) - s12 * s21) / den,
        ((1 - s11) * (z2 + s22 * z2) + s12 * s21 * z2) / den,
    )


def t_from_s(s11: Any, s12: Any, s21: Any, s22: Any) -> tuple:
    return (-(s11 * s22 - s12 * s21) / s21, s11 / s21, -s22 / s21, 1 / s21)


def s_from_t(t11: Any, t12: Any, t21: Any, t22: Any) -> tuple:
    return (t12 / t22, (t11 * t22 - t12 * t21) / t22, 1 / t22, -t21 / t22)


def scattering_from_chain(A: Any, kind: str, z0: Any) -> sp.Matrix:
    """S (``kind="S"``) or T (``kind="T"``) parameters of the chain matrix ``A`` (SymPy, entries cancelled)."""
    z1, z2 = scattering_references(z0)
    a, b, c, d = sp.Matrix(A)
    if sp.cancel(a * z2 + b + c * z1 * z2 + d * z1) == 0:
        raise ModelError("A Z02 + B + C Z01 Z02 + D Z01 = 0: the network has no scattering matrix")
    s = s_from_abcd(a, b, c, d, z1, z2, sp.sqrt)
    if kind == "T":
        if sp.cancel(s[2]) == 0:
            raise ModelError("S21 = 0: the network transmits nothing, so its T parameters do not exist")
        s = t_from_s(*s)
    return sp.Matrix(2, 2, [sp.cancel(x) for x in s])


def chain_from_scattering(M: Any, kind: str, z0: Any) -> sp.Matrix:
    """The chain matrix of S (``kind="S"``) or T (``kind="T"``) parameters ``M``."""
    z1, z2 = scattering_references(z0)
    m = sp.Matrix(M)
    s = tuple(m) if kind == "S" else s_from_t(*m)
    if sp.cancel(s[2]) == 0:
        raise ModelError("S21 = 0: the network transmits nothing, so it has no chain matrix")
    return sp.Matrix(2, 2, [sp.cancel(x) for x in abcd_from_s(*s, z1, z2, sp.sqrt)])


def parameter_kind(kind: str, name: str) -> str:
    """The canonical name ("A", "Z", ...) of a parameter set, or a ParameterError naming ``name``."""
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
    source, target = parameter_kind(source, "source"), parameter_kind(target, "target")
    if convention not in ("book", "ieee"):
        raise ParameterError(f"convention must be 'book' or 'ieee', got {convention!r}")
    M = _to_book(_as_2x2(M), source, convention)
    result = _from_chain(_chain_from(M, source, z0), target, z0)
    result = _to_book(result, target, convention)  # the flips are involutions
    return sp.Matrix(result).applyfunc(sp.cancel)


_kind = parameter_kind  # the name the four-poles use
