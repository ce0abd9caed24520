"""Routh's reduction of cyclic coordinates and steady motions (Bulgakov (1954), §3.10, §7.9).

With ``L = 1/2 q'^T M q' + b^T q' + T0 - V`` partitioned into non-cyclic (``n``) and cyclic (``c``) velocities,
``A = M_cc``, ``B = M_cn`` and the constant cyclic momenta ``p = dL/dq'_c``, the Routh function in the book's
sign convention ``R = L - p^T q'_c`` (eq. (3.110)) is

    R = 1/2 q'_n^T (M_nn - B^T A^-1 B) q'_n + q'_n^T (b_n + B^T A^-1 (p - b_c)) - V_R,
    V_R = V - T0 + 1/2 (p - b_c)^T A^-1 (p - b_c)          (the reduced, or amended, potential),

a Lagrangian of the non-cyclic coordinates alone (eq. (3.114)).  The kinetic energy of the hidden cyclic
motions enters V_R with a plus sign (Helmholtz's cyclic systems): a steady motion is an equilibrium of V_R and is
stable when V_R has a strict minimum there (Routh's theorem).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any

import sympy as sp

from ..._equality import ModelEquality
from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from .hamiltonian import momentum_symbol

if TYPE_CHECKING:
    from ..lagrange import LagrangianSystem
    from ..linear_model import LinearModel

__all__ = ["RouthReduction", "SteadyMotion", "routh_reduction"]


@dataclass(frozen=True)
class SteadyMotion(SymPyPrintable):
    """A steady motion: non-cyclic coordinates at rest at ``point``, cyclic momenta ``momenta``.

    Attributes
    ----------
    point, momenta : dict
        The values of the non-cyclic coordinates and of the cyclic momenta at the steady motion.
    hessian : sympy.Matrix
        Hessian of the reduced potential at the point.
    stable : bool or None
        True when the Hessian is positive definite (Routh's theorem: stable), False when it has a negative
        eigenvalue and no gyroscopic coupling can help (an odd number of them: Kelvin-Tait), None otherwise.

    See Also
    --------
    RouthReduction.steady_motion, routh_reduction
    """

    point: dict
    momenta: dict
    hessian: sp.Matrix
    stable: bool | None

    def __repr__(self) -> str:
        verdict = {True: "stable", False: "unstable", None: "undecided by the reduced potential"}[self.stable]
        return f"SteadyMotion({self.point}, momenta {self.momenta}: {verdict})"


class RouthReduction(ModelEquality, SymPyPrintable):
    """The Routh function of a system with cyclic coordinates; build with :func:`routh_reduction`.

    Attributes ``routhian``, ``reduced_potential``, ``reduced_system`` and ``cyclic_velocities`` are computed on
    first access; ``momenta`` are the symbols ``p_<q>`` of the cyclic momenta.

    Parameters
    ----------
    system : LagrangianSystem
        The unconstrained system whose cyclic coordinates are reduced.
    cyclic : sequence of Symbol
        The cyclic coordinates, each a coordinate of ``system`` (not checked here: :func:`routh_reduction` checks
        that the Lagrangian, the dissipation and the forces do not depend on them).

    See Also
    --------
    routh_reduction, SteadyMotion
    """

    def __init__(self, system: LagrangianSystem, cyclic: Sequence[sp.Symbol]):
        from ..lagrange import LagrangianSystem

        if not isinstance(system, LagrangianSystem):
            raise ParameterError(f"system must be a LagrangianSystem, got {type(system).__name__}")
        if isinstance(cyclic, sp.Symbol):
            cyclic = (cyclic,)
        if isinstance(cyclic, str | bytes) or not hasattr(cyclic, "__iter__"):
            raise ParameterError(f"cyclic must be a sequence of coordinates of the system, got {cyclic!r}")
        self.system = system
        self.cyclic = tuple(cyclic)
        if not self.cyclic or not set(self.cyclic) <= set(system.coordinates):
            raise ParameterError(
                f"cyclic must name coordinates of the system ({', '.join(map(str, system.coordinates))}), got "
                f"{cyclic!r}; routh_reduction checks that they are cyclic"
            )
        q = system.coordinates
        self.noncyclic = tuple(x for x in q if x not in self.cyclic)
        self.momenta = tuple(momentum_symbol(x) for x in self.cyclic)

    def _equality_data(self) -> tuple:
        key, exprs = self.system._equality_data()
        return (self.cyclic, key), exprs

    def __repr__(self) -> str:
        return (
            f"RouthReduction(cyclic: {', '.join(map(str, self.cyclic))}; "
            f"remaining: {', '.join(map(str, self.noncyclic))})"
        )

    @cached_property
    def _blocks(self):
        s = self.system
        q, qd = s.coordinates, s.velocities
        ic = [q.index(x) for x in self.cyclic]
        inn = [q.index(x) for x in self.noncyclic]
        M = s.mass_matrix
        _, T1, T0 = s.kinetic_energy_parts
        b = sp.Matrix([T1.diff(v) for v in qd])
        A = M.extract(ic, ic)
        B = M.extract(ic, inn)
        Ainv = A.inv(method="LU").applyfunc(sp.simplify) if len(ic) <= 2 else A.inv(method="LU")
        w = sp.Matrix(self.momenta) - b.extract(ic, [0])
        return ic, inn, M, b, T0, A, B, Ainv, w

    @cached_property
    def reduced_potential(self) -> sp.Expr:
        """``V_R = V - T0 + 1/2 (p - b_c)^T A^-1 (p - b_c)``."""
        *_, T0, _, _, Ainv, w = self._blocks
        return sp.simplify(self.system.potential_energy - T0 + (w.T * Ainv * w)[0] / 2)

    @cached_property
    def routhian(self) -> sp.Expr:
        """The Routh function ``R = L - sum p q'_c`` in the book's sign convention (Bulgakov (1954), eq. (3.110))."""
        _, inn, M, b, _, _, B, Ainv, w = self._blocks
        vn = sp.Matrix([self.system.velocities[i] for i in inn])
        Mr = M.extract(inn, inn) - B.T * Ainv * B
        gyro = b.extract(inn, [0]) + B.T * Ainv * w
        return (vn.T * Mr * vn)[0] / 2 + (vn.T * gyro)[0] - self.reduced_potential

    @cached_property
    def cyclic_velocities(self) -> dict:
        """The cyclic velocities in terms of the momenta and the remaining coordinates and velocities."""
        ic, inn, *_, B, Ainv, w = self._blocks
        vn = sp.Matrix([self.system.velocities[i] for i in inn])
        vc = Ainv * (w - B * vn)
        return {self.system.velocities[i]: sp.simplify(e) for i, e in zip(ic, vc, strict=True)}

    @cached_property
    def reduced_system(self) -> LagrangianSystem:
        """The Routh function as a :class:`LagrangianSystem` in the non-cyclic coordinates, the momenta
        ``p_<q>`` being parameters (eq. (3.114)); ``V`` is the reduced potential."""
        from ..lagrange import LagrangianSystem

        if not self.noncyclic:
            raise ModelError("every coordinate is cyclic: nothing is left to reduce to")
        kin = sp.expand(self.routhian + self.reduced_potential)
        s = self.system
        inn = self._blocks[1]
        forces = [s.forces[i] for i in inn]
        return LagrangianSystem(kin, self.reduced_potential, list(self.noncyclic), forces=forces)

    def _point(self, point: Mapping[Any, Any], momenta: Mapping[Any, Any] | None) -> tuple[dict, dict]:
        for what, given in (("point", point), ("momenta", momenta or {})):
            if not isinstance(given, Mapping):
                raise ParameterError(f"{what} must be a mapping (coordinate or name -> value), got {given!r}")
            for key, val in given.items():
                if val is None or isinstance(val, str | bytes):
                    raise ParameterError(f"{what}[{key!r}] must be a number or SymPy expression, got {val!r}")
        names = {x.name: x for x in self.noncyclic}
        pt = {}
        for k, val in point.items():
            nm = k.name if isinstance(k, sp.Symbol) else str(k)
            if nm not in names:
                raise ModelError(f"the point names {nm!r}, which is not a non-cyclic coordinate")
            pt[names[nm]] = sp.sympify(val)
        missing = [x.name for x in self.noncyclic if x not in pt]
        if missing:
            raise ModelError(f"the point must give every non-cyclic coordinate; missing {missing}")
        pn = {p.name: p for p in self.momenta}
        mom = {}
        for k, val in (momenta or {}).items():
            nm = k.name if isinstance(k, sp.Symbol) else str(k)
            if nm not in pn:
                raise ModelError(f"momenta names {nm!r}; the cyclic momenta are {sorted(pn)}")
            mom[pn[nm]] = sp.sympify(val)
        return pt, mom

    @staticmethod
    def _at(expr: sp.Expr, pt: dict) -> sp.Expr:
        val = sp.simplify(expr.xreplace(pt))
        if val.has(sp.nan, sp.zoo, sp.oo, -sp.oo):  # a coordinate singularity (e.g. a sleeping top at theta = 0)
            val = expr
            for x, x0 in pt.items():
                val = sp.limit(val, x, x0)
            val = sp.simplify(val)
        return val

    def steady_motion(
        self, point: Mapping[Any, Any], momenta: Mapping[Any, Any] | None = None, *, rtol: float = 1e-10
    ) -> SteadyMotion:
        """Check that ``point`` (non-cyclic coordinates at rest) with the cyclic ``momenta`` is a steady motion,
        and judge its stability from the Hessian of the reduced potential.

        Raises :class:`ModelError` naming the unbalanced generalized force when it is not a solution.

        Parameters
        ----------
        point : mapping of Symbol or str to number or expression
            Values of every non-cyclic coordinate at the steady motion (keys are coordinates or their names); a
            missing or unknown coordinate raises ModelError.
        momenta : mapping of Symbol or str to number or expression, optional
            Values of the cyclic momenta (keys are the symbols ``p_<q>`` of :attr:`momenta` or their names);
            momenta left out stay symbolic.
        rtol : float, optional
            Relative tolerance (> 0) on the balance ``dV_R/dq = 0`` when the data hold floats: the residual is
            compared with the size of the terms that cancel in it (each evaluated in absolute value), so that a
            steady motion computed in floating point is accepted; exact data must balance exactly.
        """
        if not (isinstance(rtol, int | float) and 0 < rtol < 1):
            raise ParameterError(f"rtol must be a number in (0, 1), got {rtol!r}")
        pt, mom = self._point(point, momenta)
        VR = self.reduced_potential.xreplace(mom)
        inexact = VR.has(sp.Float) or any(sp.sympify(v).has(sp.Float) for v in pt.values())
        for x in self.noncyclic:
            dV = VR.diff(x)
            resid = self._at(dV, pt)
            if resid != 0 and not (inexact and _balanced(dV, pt, resid, rtol)):
                raise ModelError(
                    f"not a steady motion: dV_R/d{x.name} = {resid} at {pt} (it must vanish"
                    + (f" to rtol = {rtol:g} of its terms" if inexact else "")
                    + "); adjust the point or the cyclic momenta"
                )
        hess = sp.Matrix(
            len(self.noncyclic),
            len(self.noncyclic),
            lambda i, j: self._at(VR.diff(self.noncyclic[i], self.noncyclic[j]), pt),
        )
        hess = hess.applyfunc(sp.simplify)
        stable: bool | None = None
        if hess.is_positive_definite:
            stable = True
        elif not hess.free_symbols or hess.rows == 1:
            if hess.rows == 1:
                neg = 1 if hess[0, 0].is_negative else (0 if hess[0, 0].is_nonnegative else None)
            else:
                neg = sum(mult for ev, mult in hess.eigenvals().items() if ev < 0)
            vn = [self.system.velocities[self.system.coordinates.index(x)] for x in self.noncyclic]
            gyroscopic = any(sp.simplify(self.routhian.diff(v).xreplace({w: 0 for w in vn})) != 0 for v in vn)
            if neg is not None and (neg % 2 == 1 or (neg > 0 and not gyroscopic)):
                stable = False
        return SteadyMotion(point=pt, momenta=mom, hessian=hess, stable=stable)

    def small_oscillations(
        self, point: Mapping[Any, Any], momenta: Mapping[Any, Any], *, rtol: float = 1e-10
    ) -> LinearModel:
        """Linearized motion about a steady motion, with the gyroscopic terms of the Routh function
        (Bulgakov (1954), §7.9): a :class:`LinearModel` ``M y'' + G y' + K y = 0``.

        Parameters
        ----------
        point : mapping of Symbol or str to number or expression
            Values of every non-cyclic coordinate at the steady motion (keys are coordinates or their names); a missing
            or unknown coordinate raises ModelError.
        momenta : mapping of Symbol or str to number or expression
            Values of the cyclic momenta (keys are the symbols ``p_<q>`` of :attr:`momenta` or their names); momenta
            left out stay symbolic.
        rtol : float, optional
            Relative tolerance of the steady-motion check for floating-point data (see :meth:`steady_motion`).
        """
        from ..lagrange import LagrangianSystem

        self.steady_motion(point, momenta, rtol=rtol)
        pt, mom = self._point(point, momenta)
        r = self.reduced_system
        fixed = LagrangianSystem(
            r.kinetic_energy.xreplace(mom), r.potential_energy.xreplace(mom), list(self.noncyclic), forces=r.forces
        )
        return fixed.linearize(pt, check_equilibrium=False)


def _balanced(expr: sp.Expr, point: dict, residual: sp.Expr, rtol: float) -> bool:
    """Whether the numeric ``residual`` of ``expr`` at ``point`` is within ``rtol`` of the size of the terms that
    cancel in it: ``expr`` evaluated with every sum and product taken in absolute value (the scale of its rounding
    and of the rounding of floating-point data)."""
    try:
        value = complex(residual)
        scale = _magnitude(expr, point)
    except (TypeError, ValueError, ZeroDivisionError, OverflowError):
        return False
    return bool(abs(value) <= rtol * scale) and scale < float("inf")


def _magnitude(expr: sp.Expr, point: dict) -> float:
    if expr.is_Add:
        return sum(_magnitude(a, point) for a in expr.args)
    if expr.is_Mul:
        out = 1.0
        for a in expr.args:
            out *= _magnitude(a, point)
        return out
    if expr.is_Pow and expr.exp.is_number and expr.exp.is_positive:
        return _magnitude(expr.base, point) ** float(expr.exp)
    return abs(complex(sp.N(expr.xreplace(point))))


@validated
def routh_reduction(system: LagrangianSystem, cyclic: Sequence[Any]) -> RouthReduction:
    """Routh's reduction of the cyclic coordinates ``cyclic`` (Bulgakov (1954), §3.10, eqs. (3.109)-(3.114)).

    A coordinate is cyclic when L, the dissipation and its generalized force do not depend on it and its
    generalized force vanishes; otherwise :class:`ModelError` names the dependence.

    Parameters
    ----------
    system : LagrangianSystem
        The system, which must be unconstrained (reduce constrained coordinates first).
    cyclic : Symbol or sequence of Symbol
        The coordinates to reduce (Symbols, ``dynamicsymbols`` or names inside a list); each must be cyclic: the
        Lagrangian, the dissipation and the forces must not depend on it, and its generalized force must vanish.

    Examples
    --------
    A central force (Bulgakov's sign convention ``R = L - p phi'``):

    >>> import sympy as sp
    >>> from symosc import dot
    >>> from symosc.mechanics import LagrangianSystem, routh_reduction
    >>> r, phi = sp.symbols("r phi", real=True)
    >>> m, k = sp.symbols("m k", positive=True)
    >>> red = routh_reduction(LagrangianSystem(m / 2 * (dot(r) ** 2 + r**2 * dot(phi) ** 2), -k / r, [r, phi]), [phi])
    >>> red.routhian
    k/r + m*r_dot**2/2 - p_phi**2/(2*m*r**2)
    >>> red.reduced_potential
    -k/r + p_phi**2/(2*m*r**2)

    See Also
    --------
    RouthReduction.steady_motion, RouthReduction.small_oscillations, HamiltonianSystem
    """
    if system.is_constrained:
        raise ModelError("routh_reduction needs an unconstrained system: call reduce_coordinates first")
    names = {x.name: x for x in system.coordinates}
    cyc = []
    for c in cyclic if isinstance(cyclic, (list, tuple)) else [cyclic]:
        nm = c.name if isinstance(c, sp.Symbol) else getattr(getattr(c, "func", None), "__name__", str(c))
        if nm not in names:
            raise ModelError(f"cyclic coordinate {nm!r} is not a coordinate of the system")
        cyc.append(names[nm])
    if not cyc:
        raise ModelError("give at least one cyclic coordinate")
    L = system.kinetic_energy - system.potential_energy
    for x in cyc:
        i = system.coordinates.index(x)
        if x in L.free_symbols and sp.simplify(L.diff(x)) != 0:
            raise ModelError(f"{x.name} is not cyclic: the Lagrangian depends on it (dL/d{x.name} = {L.diff(x)})")
        if system.forces[i] != 0:
            raise ModelError(f"{x.name} is not cyclic: its generalized force {system.forces[i]} does not vanish")
        if system.dissipation != 0 and system.dissipation.diff(system.velocities[i]) != 0:
            raise ModelError(f"{x.name} is not cyclic: the dissipation acts on its velocity")
        if any(x in f.free_symbols for f in system.forces) or x in system.dissipation.free_symbols:
            raise ModelError(f"{x.name} is not cyclic: the forces depend on it")
    return RouthReduction(system, cyc)
