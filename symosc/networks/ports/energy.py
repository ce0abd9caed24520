"""Energy functions of passive networks and Foster's reactance theorem (Bulgakov (1954), §9.19–9.21).

With loop currents ``I`` (complex amplitudes at the complex frequency ``p``) and the loop resistance, inductance and
elastance (1/C) matrices ``R``, ``L``, ``S`` of a passive network, the energy functions are the Hermitian forms

``F0 = Ī^T R I``,  ``T0 = Ī^T L I``,  ``V0 = Ī^T S I``

(dissipation, magnetic/kinetic and electric/potential; all ``>= 0``) and the driving-point impedance is

``Z(p) = (F0 + p T0 + V0/p) / |I1|²``

(Brune; Bulgakov (1954), eqs. (9.223)–(9.236)).  For a reactive (LC) one-port ``dX/dω = (T0 + V0/ω²)/|I1|² > 0``
(Foster's reactance theorem, eq. (9.250)).

>>> import sympy as sp
>>> from symosc.networks import Capacitor, Inductor, Resistor, energy_functions
>>> ef = energy_functions(Resistor(1) + (Inductor(2) | Capacitor(3)))
>>> values = ef.evaluate(sp.I)
>>> values.impedance == ef.impedance().subs(sp.Symbol("p"), sp.I)
True
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._exact.polynomial_tests import nonnegative_on_half_line
from .._util import P, as_expr, as_symbol, rational_function
from ._loops import _Names, expand_port, fundamental_loops, loop_matrices
from .oneports import OnePort

__all__ = ["EnergyFunctions", "EnergyValues", "ReactanceCheck", "check_reactance_theorem", "energy_functions"]


def _hermitian_form(M: sp.Matrix, x: Sequence) -> sp.Expr:
    n = M.shape[0]
    return sp.Add(*(M[j, k] * x[j] * sp.conjugate(x[k]) for j in range(n) for k in range(n) if M[j, k] != 0))


def _loop_currents(Zl: sp.Matrix, rhs: sp.Matrix, at: sp.Expr) -> tuple:
    """Solution of ``Zl x = rhs`` scaled to ``x[0] = 1``, exactly, in the smallest domain holding the entries
    (Gaussian rationals for a numeric ``p``: no expression swell; SymPy's expressions only for radicals or
    symbols)."""
    from sympy.polys.matrices import DomainMatrix
    from sympy.polys.matrices.exceptions import DMNonInvertibleMatrixError

    A, b = DomainMatrix.from_Matrix(Zl).to_field(), DomainMatrix.from_Matrix(rhs)
    A, b = A.unify(b.to_field())
    K = A.domain
    try:
        x = [row[0] for row in A.lu_solve(b).to_list()]
    except (DMNonInvertibleMatrixError, ValueError, ZeroDivisionError) as exc:
        raise ModelError(f"the loop equations are singular at p = {at} (a resonance of the network)") from exc
    if not x[0]:
        raise ModelError(f"no current enters the network at p = {at} (its impedance is infinite there)")
    currents = (K.to_sympy(K.quo(v, x[0])) for v in x)
    return tuple(sp.expand(sp.radsimp(v)) if K.is_EX or K.is_EXRAW else v for v in currents)


@dataclass(frozen=True)
class EnergyValues(SymPyPrintable):
    """The energy functions at one complex frequency ``at`` for the driving current ``I1 = 1``.

    Attributes
    ----------
    at : sympy.Expr
        The value of ``p``.
    F0, T0, V0 : sympy.Expr
        Dissipation, magnetic (kinetic) and electric (potential) functions, real and ``>= 0``.
    currents : tuple
        Loop currents (the driving loop first, ``I1 = 1``).
    impedance : sympy.Expr
        ``F0 + at T0 + V0/at``: the driving-point impedance ``Z(at)``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import Capacitor, Inductor, energy_functions
    >>> values = energy_functions(Inductor(1) + Capacitor(1)).evaluate(2 * sp.I)
    >>> values
    EnergyValues(at=2*I, F0=0, T0=1, V0=1, Z=3*I/2)

    See Also
    --------
    energy_functions
    """

    at: sp.Expr
    F0: sp.Expr
    T0: sp.Expr
    V0: sp.Expr
    currents: tuple
    impedance: sp.Expr

    def reactance_slope(self) -> sp.Expr:
        """``dX/dω = T0 + V0/ω²`` at ``at = iω`` (Foster; Bulgakov (1954), eq. (9.250)); for lossless networks."""
        omega = sp.im(self.at)
        if sp.re(self.at) != 0 or omega == 0:
            raise ParameterError(f"the reactance slope needs a point p = iω on the imaginary axis, got {self.at}")
        return self.T0 + self.V0 / omega**2

    def __repr__(self) -> str:
        return (
            f"EnergyValues(at={sp.sstr(self.at)}, F0={sp.sstr(self.F0)}, T0={sp.sstr(self.T0)}, "
            f"V0={sp.sstr(self.V0)}, Z={sp.sstr(self.impedance)})"
        )

    def _sympystr(self, printer: Any) -> str:
        return repr(self)

    def _latex(self, printer: Any) -> str:
        forms = rf"F_0 = {sp.latex(self.F0)},\ T_0 = {sp.latex(self.T0)},\ V_0 = {sp.latex(self.V0)}"
        return rf"{forms},\ Z = {sp.latex(self.impedance)}"

    def _repr_latex_(self) -> str:
        return f"${self._latex(None)}$"


@dataclass(frozen=True)
class EnergyFunctions(SymPyPrintable):
    """Loop matrices ``R``, ``L``, ``S`` of a passive network and its energy functions (Bulgakov (1954), §9.21).

    Built by :func:`energy_functions`.  The loop impedance matrix is ``R + p L + S/p``; loop 1 carries the driving
    current ``I1``.  :attr:`F0`, :attr:`T0`, :attr:`V0` are the Hermitian forms in the loop-current symbols
    :attr:`currents`; :meth:`evaluate` puts in the currents the network carries at a given ``p``.

    Attributes
    ----------
    R : sympy.ImmutableMatrix
        Loop resistance matrix (symmetric, driving loop first).
    L : sympy.ImmutableMatrix
        Loop inductance matrix, mutual inductances of Brune sections included.
    S : sympy.ImmutableMatrix
        Loop elastance matrix (inverse capacitances ``1/C``).
    loops : tuple of str
        Labels of the loops, in the order of the matrix rows ("driving loop" first).
    p : sympy.Symbol
        Operator variable of :meth:`loop_impedance` and :meth:`impedance`.

    Examples
    --------
    >>> from symosc.networks import Capacitor, Inductor, Resistor, energy_functions
    >>> ef = energy_functions(Resistor(2) + (Inductor(1) | Capacitor(1)))
    >>> ef.L, ef.S
    (Matrix([
    [ 1, -1],
    [-1,  1]]), Matrix([
    [0, 0],
    [0, 1]]))
    >>> ef.T0
    I_1*conjugate(I_1) - I_1*conjugate(I_2) - I_2*conjugate(I_1) + I_2*conjugate(I_2)

    See Also
    --------
    energy_functions, check_reactance_theorem
    """

    R: sp.ImmutableMatrix
    L: sp.ImmutableMatrix
    S: sp.ImmutableMatrix
    loops: tuple
    p: sp.Symbol = P

    @property
    def currents(self) -> tuple:
        """Symbols ``I_1, ..., I_n`` of the loop currents (``I_1``: the driving loop)."""
        return sp.symbols(f"I_1:{self.R.shape[0] + 1}")

    @property
    def F0(self) -> sp.Expr:
        """Dissipation function ``Σ R_jk I_j conj(I_k)``."""
        return _hermitian_form(self.R, self.currents)

    @property
    def T0(self) -> sp.Expr:
        """Magnetic (kinetic) energy function ``Σ L_jk I_j conj(I_k)``."""
        return _hermitian_form(self.L, self.currents)

    @property
    def V0(self) -> sp.Expr:
        """Electric (potential) energy function ``Σ S_jk I_j conj(I_k)`` (``S = 1/C``)."""
        return _hermitian_form(self.S, self.currents)

    def loop_impedance(self) -> sp.Matrix:
        """Loop impedance matrix ``R + p L + S/p``."""
        return (self.R + self.p * self.L + self.S / self.p).as_mutable()

    def impedance(self) -> sp.Expr:
        """Driving-point impedance ``E1/I1`` from the loop equations: ``det Z_loop / minor_11``."""
        Zl = self.loop_impedance()
        if Zl.shape[0] == 1:
            return sp.cancel(Zl[0, 0])
        minor = Zl[1:, 1:].det(method="berkowitz")
        return sp.cancel(Zl.det(method="berkowitz") / minor)

    def evaluate(self, at: Any) -> EnergyValues:
        """Loop currents for ``I1 = 1`` at ``p = at`` and the values of ``F0``, ``T0``, ``V0`` there.

        ``at`` may be an exact complex number (``3 + 2*sympy.I``): the result is then exact.

        Parameters
        ----------
        at : number or SymPy number
            The value of ``p``, a nonzero real or complex number free of symbols (exact values such as ``2*sympy.I``
            give exact results).
        """
        at = as_expr(at, "at")
        if at.free_symbols or at == 0:
            raise ParameterError(f"at must be a non-zero complex number (a value of p), got {at}")
        Zl = (self.R + at * self.L + self.S / at).as_mutable()
        rhs = sp.zeros(Zl.shape[0], 1)
        rhs[0] = 1
        currents = _loop_currents(Zl, rhs, at)

        def form(M: sp.ImmutableMatrix) -> sp.Expr:
            value = sp.expand(_hermitian_form(M, currents))
            return sp.re(value) if value.is_number else value

        F0, T0, V0 = form(self.R), form(self.L), form(self.S)
        return EnergyValues(at, F0, T0, V0, currents, sp.expand(F0 + at * T0 + V0 / at))

    def __repr__(self) -> str:
        return f"EnergyFunctions({len(self.loops)} loops: F0 = {self.F0}, T0 = {self.T0}, V0 = {self.V0})"

    def _sympystr(self, printer: Any) -> str:
        return repr(self)

    def _latex(self, printer: Any) -> str:
        return rf"F_0 = {sp.latex(self.F0)},\ T_0 = {sp.latex(self.T0)},\ V_0 = {sp.latex(self.V0)}"

    def _repr_latex_(self) -> str:
        return f"${self._latex(None)}$"


@validated
def energy_functions(network: Any, terminals: tuple | None = None, p: sp.Symbol = P) -> EnergyFunctions:
    """Energy functions ``F0``, ``T0``, ``V0`` of a passive network as forms in its loop currents (§9.19–9.21).

    Parameters
    ----------
    network : OnePort or sequence of (node, node, OnePort)
        A one-port tree of R, L, C (and Brune sections), or a list of branches ``(a, b, element)`` between named
        nodes (any topology, e.g. a bridge), each element itself a one-port tree.
    terminals : (node, node), optional
        The driving terminals of a branch list (required then; the current enters at the first).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Returns
    -------
    EnergyFunctions
        Loop matrices with the driving loop first; ``Z(p) |I1|² = F0 + p T0 + V0/p`` for the loop currents at
        any ``p`` (Bulgakov (1954), eqs. (9.223)–(9.236)).

    Raises
    ------
    ParameterError
        For elements with unknown structure (:class:`Impedance`) or a malformed branch list.
    ModelError
        When the terminals are not connected, or parts of the network float.

    Examples
    --------
    A bridge (not a series-parallel network): five resistors and a capacitor.

    >>> import sympy as sp
    >>> from symosc.networks import Capacitor, Resistor, energy_functions
    >>> branches = [("a", "c", Resistor(1)), ("a", "d", Resistor(2)), ("c", "b", Resistor(3)),
    ...             ("d", "b", Capacitor(1)), ("c", "d", Resistor(5))]
    >>> ef = energy_functions(branches, terminals=("a", "b"))
    >>> len(ef.loops)
    3
    >>> sp.factor(ef.impedance())
    (46*p + 31)/(39*p + 8)

    See Also
    --------
    EnergyFunctions, check_reactance_theorem
    """
    p = as_symbol(p)
    names = _Names()
    edges: list = []
    mutual: dict = {}
    if isinstance(network, OnePort):
        if terminals is not None:
            raise ParameterError("terminals are only used with a branch list; a one-port has its own two terminals")
        a, b = "+", "-"
        expand_port(network, a, b, names, edges, mutual)
    else:
        if isinstance(network, str) or not isinstance(network, Sequence) or not network:
            raise ParameterError(
                f"network must be a one-port or a non-empty list of (node, node, element) branches, got {network!r}"
            )
        if not isinstance(terminals, tuple) or len(terminals) != 2 or terminals[0] == terminals[1]:
            raise ParameterError(f"terminals must be two different nodes (a, b) of the branch list, got {terminals!r}")
        a, b = terminals
        for item in network:
            if not isinstance(item, tuple) or len(item) != 3 or not isinstance(item[2], OnePort):
                raise ParameterError(f"each branch must be (node, node, one-port element), got {item!r}")
            if item[0] == item[1]:
                raise ParameterError(f"branch {item!r} connects a node to itself")
            expand_port(item[2], item[0], item[1], names, edges, mutual)
    B, labels = fundamental_loops(edges, a, b)
    R, L, S = loop_matrices(edges, mutual, B)
    return EnergyFunctions(sp.ImmutableMatrix(R), sp.ImmutableMatrix(L), sp.ImmutableMatrix(S), tuple(labels), p)


@dataclass(frozen=True)
class ReactanceCheck(SymPyPrintable):
    """Foster's reactance theorem for ``Z(p)``: ``Z(iω) = i X(ω)`` with ``dX/dω > 0`` (Bulgakov (1954), (9.250)).

    ``bool(check)`` is True when the one-port is lossless (``Re Z(iω) = 0``) and its reactance increases on
    ``ω > 0`` (between poles), which makes the zeros and poles of ``X`` interlace (9.252)–(9.255).

    Attributes
    ----------
    Z : SymPy expression
        The impedance tested, cancelled.
    omega : sympy.Symbol
        The positive angular-frequency symbol in :attr:`reactance` and :attr:`slope`.
    reactance : SymPy expression or None
        ``X(ω)`` with ``Z(iω) = i X(ω)``; None when ``Z`` is not lossless.
    slope : SymPy expression or None
        ``dX/dω``; None when ``Z`` is not lossless.
    lossless : bool
        Whether ``Re Z(iω)`` vanishes identically.
    increasing : bool
        Whether ``dX/dω > 0`` on ``ω > 0``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import check_reactance_theorem
    >>> p = sp.Symbol("p")
    >>> check = check_reactance_theorem((p**2 + 1) / p, p)
    >>> bool(check), check.slope
    (True, (omega**2 + 1)/omega**2)

    See Also
    --------
    check_reactance_theorem, is_reactance_function
    """

    Z: sp.Expr
    omega: sp.Symbol
    reactance: sp.Expr | None
    slope: sp.Expr | None
    lossless: bool
    increasing: bool

    def __bool__(self) -> bool:
        return self.lossless and self.increasing

    def __repr__(self) -> str:
        return (
            f"ReactanceCheck(Z = {sp.sstr(self.Z)}, lossless = {self.lossless}, increasing = {self.increasing}, "
            f"dX/dω = {sp.sstr(self.slope)})"
        )

    def _sympystr(self, printer: Any) -> str:
        return repr(self)

    def _latex(self, printer: Any) -> str:
        slope = r"\text{--}" if self.slope is None else sp.latex(self.slope)
        return rf"Z(p) = {sp.latex(self.Z)},\ \frac{{dX}}{{d\omega}} = {slope}"

    def _repr_latex_(self) -> str:
        return f"${self._latex(None)}$"


@validated
def check_reactance_theorem(Z: Any, p: sp.Symbol = P) -> ReactanceCheck:
    """Check Foster's reactance theorem ``dX/dω > 0`` for a one-port (Bulgakov (1954), §9.21, (9.250)).

    Exact: ``Re Z(iω)`` must vanish identically (a reactive one-port) and the numerator ``X' B - X B'`` of the
    slope of ``X = A/B`` must have no zero on ``ω > 0``.

    Parameters
    ----------
    Z : SymPy expression or OnePort
        Rational impedance in ``p`` with numeric coefficients (or a network).
    p : sympy.Symbol, optional
        Operator variable of ``Z``, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Returns
    -------
    ReactanceCheck
        True-valued when the theorem holds.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import check_reactance_theorem
    >>> p = sp.Symbol("p")
    >>> bool(check_reactance_theorem(p / (p**2 + 1), p))
    True
    >>> bool(check_reactance_theorem(p - 1 / p, p))          # a negative capacitor: X = ω + 1/ω falls below ω = 1
    False

    See Also
    --------
    energy_functions, is_reactance_function, foster_first
    """
    p = as_symbol(p)
    if isinstance(Z, OnePort):
        Z = Z.impedance(p)
    N, D = rational_function(Z, p)
    free = (N.as_expr().free_symbols | D.as_expr().free_symbols) - {p}
    if free:
        raise ParameterError(f"Z must have numeric coefficients; substitute values for {sorted(free, key=str)}")
    if N.is_zero:
        raise ParameterError("Z is identically zero (a short circuit)")
    Ze = N.as_expr() / D.as_expr()
    w = sp.Symbol("omega", positive=True)
    Ziw = sp.cancel(Ze.subs(p, sp.I * w))
    re_part = sp.cancel(sp.expand((Ziw + Ze.subs(p, -sp.I * w)) / 2))
    if re_part != 0:
        return ReactanceCheck(Ze, w, None, None, False, False)
    X = sp.cancel(sp.expand(-sp.I * Ziw))
    A, B = sp.fraction(X)
    A, B = sp.Poly(A, w), sp.Poly(B, w)
    slope_num = sp.Poly(A.diff(w) * B - A * B.diff(w), w)
    slope = sp.cancel(slope_num.as_expr() / B.as_expr() ** 2)
    increasing = False
    if not slope_num.is_zero:
        # slope_num >= 0 on w >= 0 (exact) and no zero on w > 0
        nonneg = nonnegative_on_half_line(slope_num)
        roots = slope_num.count_roots(0, None) - (1 if slope_num.eval(0) == 0 else 0)
        increasing = bool(nonneg and roots == 0)
    return ReactanceCheck(Ze, w, X, slope, True, increasing)
