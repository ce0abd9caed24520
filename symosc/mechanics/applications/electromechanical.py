"""Electromechanical systems in Maxwell's form (Bulgakov (1954), §3.8, eqs. (3.93)-(3.97)).

Charges are coordinates (currents ``i = q'``); the magnetic energy ``1/2 i^T L(x) i`` acts as kinetic energy, the
electrostatic energy ``1/2 q^T B(x) q`` (``B`` = inverse capacitances) as potential energy, resistances enter
through the dissipation function ``1/2 i^T R i`` and electromotive forces as generalized forces.  The mechanical
coordinates ``x`` feel the ponderomotive forces ``1/2 i^T dL/dx i - 1/2 q^T dB/dx q``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy as sp

from ..._validate import validated
from ...errors import ModelError
from ...symbols import dot

__all__ = ["electromechanical_system"]


@validated
def electromechanical_system(
    mechanical_T: Any,
    mechanical_V: Any,
    mechanical_coordinates: Sequence[sp.Symbol],
    charges: Sequence[sp.Symbol],
    *,
    inductance: Any,
    elastance: Any = None,
    resistance: Any = None,
    emf: Sequence[Any] | None = None,
    mechanical_dissipation: Any = 0,
    mechanical_forces: Sequence[Any] | None = None,
):
    """A :class:`LagrangianSystem` with mechanical coordinates and loop charges (Bulgakov (1954), §3.8).

    Parameters
    ----------
    mechanical_T, mechanical_V : Expr
        Mechanical kinetic and potential energies.
    mechanical_coordinates, charges : sequence of Symbol
        The mechanical coordinates ``x`` and the loop charges ``q`` (their rates ``q'`` are the loop currents).
    inductance : Matrix
        ``L(x)`` (symmetric), the loops' self- and mutual inductances.
    elastance : Matrix, optional
        ``B(x)``: inverse capacitances (eq. (3.93)); default none.
    resistance : Matrix, optional
        Loop resistances ``R`` (symmetric).
    emf : sequence, optional
        Electromotive forces ``e_j`` of the loops.
    mechanical_dissipation : SymPy expression, optional
        Rayleigh dissipation function of the mechanical coordinates, a function of their velocities (default 0).
    mechanical_forces : sequence of SymPy expressions, optional
        Generalized forces on the mechanical coordinates, one per coordinate (default none).

    Examples
    --------
    A series RLC loop gives ``L i' + R i + q / C = e`` (eq. (3.97)):

    >>> import sympy as sp
    >>> x, q = sp.symbols("x q", real=True)
    >>> m, k, L, R, C, e = sp.symbols("m k L R C e", positive=True)
    >>> from symosc import dot
    >>> s = electromechanical_system(m * dot(x)**2 / 2, k * x**2 / 2, [x], [q], inductance=sp.Matrix([[L]]),
    ...     elastance=sp.Matrix([[1 / C]]), resistance=sp.Matrix([[R]]), emf=[e])
    >>> s.equations()[1]
    L*q_ddot + R*q_dot - e + q/C

    See Also
    --------
    LagrangianSystem, loop_equations
    """
    from ..lagrange import LagrangianSystem

    x, qs = list(mechanical_coordinates), list(charges)
    nq = len(qs)
    Lm = sp.Matrix(inductance)
    if Lm.shape != (nq, nq):
        raise ModelError(f"inductance must be {nq}x{nq} (one row per charge), got {Lm.shape}")
    if (Lm - Lm.T).applyfunc(sp.simplify) != sp.zeros(nq, nq):
        raise ModelError("the inductance matrix must be symmetric (reciprocity)")
    i = sp.Matrix([dot(c) for c in qs])
    Q = sp.Matrix(qs)
    T = sp.sympify(mechanical_T) + (i.T * Lm * i)[0] / 2
    V = sp.sympify(mechanical_V)
    if elastance is not None:
        B = sp.Matrix(elastance)
        if B.shape != (nq, nq):
            raise ModelError(f"elastance must be {nq}x{nq}, got {B.shape}")
        V += (Q.T * B * Q)[0] / 2
    Rdiss = sp.sympify(mechanical_dissipation)
    if resistance is not None:
        Rm = sp.Matrix(resistance)
        if Rm.shape != (nq, nq):
            raise ModelError(f"resistance must be {nq}x{nq}, got {Rm.shape}")
        Rdiss += (i.T * Rm * i)[0] / 2
    mech_f = list(mechanical_forces) if mechanical_forces is not None else [0] * len(x)
    el_f = list(emf) if emf is not None else [0] * nq
    if len(mech_f) != len(x) or len(el_f) != nq:
        raise ModelError("give one mechanical force per mechanical coordinate and one emf per charge")
    return LagrangianSystem(T, V, [*x, *qs], dissipation=Rdiss, forces=[*mech_f, *el_f])
