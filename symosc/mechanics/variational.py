"""Small oscillations about a given motion (Bulgakov (1954), ch. 7).

- :func:`variational_equations`: the equations in variations ``f(D) y = w(t)`` about a known motion
  ``q_bar(t)`` (§7.1, eqs. (7.11)-(7.14)); coefficients depend on time unless the motion is an equilibrium.
- :meth:`VariationalEquations.first_order`: the reduction ``[A D + H] Y = W`` (§7.2, eqs. (7.25)-(7.26)).
- :func:`decompose_forces`: ``A y'' + (N + G) y' + (H + J) y = 0`` with inertia, dissipative, gyroscopic,
  potential and non-conservative positional parts, the energy identity and the classical stability theorems
  (§7.9, eqs. (7.75)-(7.81)).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from .._printing import SymPyPrintable
from .._validate import check_sympy_matrix, validated
from ..errors import ModelError
from ..numeric import bind
from ..symbols import ddot, dot, t

__all__ = [
    "FirstOrderReduction",
    "ForceDecomposition",
    "StabilityVerdict",
    "VariationalEquations",
    "decompose_forces",
    "variational_equations",
]

D = sp.Symbol("D")
LAMBDA = sp.Symbol("lambda")


@dataclass(frozen=True)
class VariationalEquations(SymPyPrintable):
    """``a0 y'' + a1 y' + a2 y = w(t)`` about a known motion (Bulgakov (1954), eq. (7.12)).

    Attributes
    ----------
    coefficients : tuple of Matrix
        ``(a0, a1, a2)``: Jacobians of the equations with respect to ``q''``, ``q'``, ``q`` along the motion.
    w : Matrix
        ``-phi(q_bar, q_bar', q_bar'', t)``; zero when the motion solves the equations (eq. (7.14)).
    coordinates : tuple of Symbol
        The variations ``y`` (named as the coordinates).

    See Also
    --------
    variational_equations, decompose_forces
    """

    coefficients: tuple[sp.Matrix, sp.Matrix, sp.Matrix]
    w: sp.Matrix
    coordinates: tuple[sp.Symbol, ...]

    def __repr__(self) -> str:
        kind = "time-varying" if any(t in a.free_symbols for a in self.coefficients) else "constant"
        return f"VariationalEquations({len(self.coordinates)} equations, {kind} coefficients)"

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(self.operator_matrix())} y = {sp.latex(self.w)}$$"

    def operator_matrix(self, symbol: sp.Symbol = D) -> sp.Matrix:
        """``f(D) = a0 D^2 + a1 D + a2`` (eq. (7.11)); ``D`` stands for d/dt acting on y.

        Parameters
        ----------
        symbol : sympy.Symbol, optional
            Symbol standing for the operator d/dt (default ``D``).
        """
        a0, a1, a2 = self.coefficients
        return a0 * symbol**2 + a1 * symbol + a2

    def characteristic_polynomial(self, symbol: sp.Symbol = LAMBDA) -> sp.Expr:
        """``det f(lambda)`` (meaningful for constant coefficients).

        Parameters
        ----------
        symbol : sympy.Symbol, optional
            Symbol of the characteristic polynomial (default ``lambda``).
        """
        return sp.factor(self.operator_matrix(symbol).det(method="berkowitz"))

    def coordinate_orders(self) -> tuple[int, ...]:
        """Highest derivative order ``m_k`` of each coordinate in ``f(D)`` (over all equations; Bulgakov (1954),
        §7.2)."""
        a0, a1, _ = self.coefficients
        out = []
        for k in range(len(self.coordinates)):
            if any(sp.simplify(e) != 0 for e in a0[:, k]):
                out.append(2)
            elif any(sp.simplify(e) != 0 for e in a1[:, k]):
                out.append(1)
            else:
                out.append(0)
        return tuple(out)

    def first_order(self, method: int = 1) -> FirstOrderReduction:
        """Reduction to ``A Y' + H Y = W`` (Bulgakov (1954), §7.2, eqs. (7.25)-(7.26)).

        Parameters
        ----------
        method : {1, 2}
            1: all coordinates and their first derivatives are unknowns, ``Y = (y, y')``: ``A = [[I, 0], [0, a0]]``,
            ``H = [[0, -I], [a2, a1]]``, ``W = [0; w]`` (``2 n`` unknowns; ``A`` is singular when ``a0`` is).
            2: orders per coordinate: with ``m_k`` the highest derivative of ``y_k`` in ``f(D)`` the unknowns are
            ``y_k, ..., y_k^(m_k - 1)`` (``y_k`` itself when ``m_k = 0``), one trivial equation
            ``D y_k^(i) - y_k^(i+1) = 0`` per extra unknown, then the original equations; ``sum max(1, m_k)``
            unknowns.  For constant coefficients ``det(A lambda + H) = +-det f(lambda)`` for both methods.

        Returns
        -------
        FirstOrderReduction
            Unpacks as ``A, H, W``; ``.state`` names the unknowns.

        Examples
        --------
        A mass on a spring driven through a first-order lag ``T z' + z = x`` (orders 2 and 1):

        >>> import sympy as sp
        >>> from symosc import ddot, dot
        >>> x, z = sp.symbols("x z")
        >>> T, k = sp.symbols("T k", positive=True)
        >>> ve = variational_equations([ddot(x) + k * x - z, T * dot(z) + z - x], [x, z])
        >>> red = ve.first_order(method=2)
        >>> red.state
        (x, z, x_dot)
        >>> red.A
        Matrix([
        [1, 0, 0],
        [0, 0, 1],
        [0, T, 0]])
        """
        a0, a1, a2 = self.coefficients
        n = a0.rows
        if method == 1:
            A = sp.diag(sp.eye(n), a0)
            H = sp.zeros(n, n).row_join(-sp.eye(n)).col_join(a2.row_join(a1))
            state = (*self.coordinates, *(dot(y) for y in self.coordinates))
            return FirstOrderReduction(A, H, sp.zeros(n, 1).col_join(self.w), state, 1)
        if method != 2:
            raise ModelError(f"method must be 1 or 2 (Bulgakov (1954), §7.2), got {method!r}")
        orders = self.coordinate_orders()
        coeffs = (a2, a1, a0)  # coefficient of D^r is coeffs[r]
        q = self.coordinates
        # unknowns: all y_k, then y_k' for m_k = 2 (derivative r of coordinate k at column col[(k, r)])
        col = {(k, 0): k for k in range(n)}
        state: list[sp.Expr] = list(q)
        for k in range(n):
            for r in range(1, orders[k]):
                col[(k, r)] = len(state)
                state.append(dot(q[k]) if r == 1 else ddot(q[k]))
        size = len(state)
        trivial = size - n
        A = sp.zeros(trivial + n, size)
        H = sp.zeros(trivial + n, size)
        row = 0
        for k in range(n):
            for r in range(orders[k] - 1):
                A[row, col[(k, r)]] = 1
                H[row, col[(k, r + 1)]] = -1
                row += 1
        for j in range(a0.rows):
            for k in range(n):
                mk = orders[k]
                for r in range(mk + 1):
                    c = coeffs[r][j, k]
                    if c == 0:
                        continue
                    if r == mk and mk > 0:
                        A[trivial + j, col[(k, mk - 1)]] += c
                    else:
                        H[trivial + j, col[(k, r)]] += c
        W = sp.zeros(trivial, 1).col_join(self.w)
        return FirstOrderReduction(A, H, W, tuple(state), 2)


@dataclass(frozen=True)
class FirstOrderReduction(SymPyPrintable):
    """``A Y' + H Y = W`` from ``f(D) y = w`` (Bulgakov (1954), §7.2, eqs. (7.25)-(7.26)); unpacks as
    ``A, H, W``.

    Attributes
    ----------
    A, H, W : Matrix
        Coefficients (``A`` may be singular: a descriptor system when some equations are algebraic).
    state : tuple of Expr
        The unknowns ``Y`` (coordinates, then ``dot(q)``).
    method : int
        1 or 2, as in §7.2.

    See Also
    --------
    VariationalEquations.first_order
    """

    A: sp.Matrix
    H: sp.Matrix
    W: sp.Matrix
    state: tuple
    method: int

    def __iter__(self):
        return iter((self.A, self.H, self.W))

    def __repr__(self) -> str:
        return f"FirstOrderReduction(method {self.method}, {len(self.state)} unknowns, {self.A.rows} equations)"

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(self.A)} \\dot{{Y}} + {sp.latex(self.H)} Y = {sp.latex(self.W)}$$"

    def characteristic_polynomial(self, symbol: sp.Symbol = LAMBDA) -> sp.Expr:
        """``det(A lambda + H)`` (constant coefficients).

        Parameters
        ----------
        symbol : sympy.Symbol, optional
            Symbol of the characteristic polynomial (default ``lambda``).
        """
        return sp.factor((self.A * symbol + self.H).det(method="berkowitz"))


@validated
def variational_equations(
    equations: Any, coordinates: Sequence[sp.Symbol] | None = None, reference: Mapping[Any, Any] | None = None
) -> VariationalEquations:
    """Equations in variations about the motion ``q = reference(t)`` (Bulgakov (1954), §7.1).

    Parameters
    ----------
    equations : LagrangianSystem or sequence of Expr
        Expressions ``phi(q, q', q'', t)`` (in the plain symbols ``q``, ``dot(q)``, ``ddot(q)``) equal to zero,
        or a system (its ``equations()`` are used).
    coordinates : sequence of Symbol
        Needed when ``equations`` are expressions.
    reference : mapping
        Coordinate -> its known motion, an expression of :data:`symosc.t` (default: all zero).

    Examples
    --------
    A pendulum about its uniform rotation ``phi = w t`` on a spinning shaft gives constant coefficients:

    >>> import sympy as sp
    >>> from symosc import ddot, dot, t
    >>> phi = sp.Symbol("phi", real=True)
    >>> k = sp.Symbol("k", positive=True)
    >>> ve = variational_equations([ddot(phi) + k * sp.sin(phi)], [phi], {phi: sp.pi})
    >>> ve.operator_matrix()
    Matrix([[D**2 - k]])

    See Also
    --------
    decompose_forces, LagrangianSystem.linearize
    """
    from .lagrange import LagrangianSystem

    if isinstance(equations, LagrangianSystem):
        coordinates = equations.coordinates
        phis = list(equations.equations())
    else:
        if coordinates is None:
            raise ModelError("coordinates= is needed when the equations are given as expressions")
        phis = [sp.sympify(e) for e in equations]
    q = tuple(coordinates)
    if len(phis) != len(q):
        raise ModelError(f"{len(phis)} equations for {len(q)} coordinates: a square system is needed")
    ref = {x: sp.S.Zero for x in q}
    names = {x.name: x for x in q}
    for key, val in (reference or {}).items():
        nm = key.name if isinstance(key, sp.Symbol) else str(key)
        if nm not in names:
            raise ModelError(f"reference names {nm!r}, which is not a coordinate")
        ref[names[nm]] = sp.sympify(val)
    at: dict[sp.Symbol, sp.Expr] = {}
    for x in q:
        at[x] = ref[x]
        at[dot(x)] = ref[x].diff(t)
        at[ddot(x)] = ref[x].diff(t, 2)
    F = sp.Matrix(phis)
    coeffs = tuple(
        F.jacobian([f(x) if f else x for x in q]).xreplace(at).applyfunc(sp.simplify) for f in (ddot, dot, None)
    )
    w = (-F.xreplace(at)).applyfunc(sp.simplify)
    return VariationalEquations(coefficients=coeffs, w=w, coordinates=q)


@dataclass(frozen=True)
class StabilityVerdict(SymPyPrintable):
    """What the classical theorems say about ``A y'' + (N + G) y' + (H + J) y = 0``.

    Attributes
    ----------
    stable : bool or None
        True when a theorem proves stability, False when one proves instability, None when none decides.
    asymptotically : bool
        Whether the stability is asymptotic (positive-definite ``H`` under complete dissipation).
    reason : str
        The theorem applied, or why none applies.

    See Also
    --------
    ForceDecomposition.stability
    """

    stable: bool | None
    asymptotically: bool
    reason: str

    def __repr__(self) -> str:
        word = {True: "stable", False: "unstable", None: "undecided"}[self.stable]
        return f"StabilityVerdict({word}{' (asymptotically)' if self.asymptotically else ''}: {self.reason})"


@dataclass(frozen=True)
class ForceDecomposition(SymPyPrintable):
    """``A`` inertia, ``N`` dissipative, ``G`` gyroscopic, ``H`` potential, ``J`` non-conservative positional
    (circulatory) matrices: ``N, H`` symmetric, ``G, J`` skew (Bulgakov (1954), eqs. (7.75), (7.81)).

    Attributes
    ----------
    A : sympy.Matrix
        Inertia matrix (symmetric).
    N : sympy.Matrix
        Dissipative matrix, the symmetric part of the velocity coefficients.
    G : sympy.Matrix
        Gyroscopic matrix, their skew part.
    H : sympy.Matrix
        Potential (stiffness) matrix, the symmetric part of the position coefficients.
    J : sympy.Matrix
        Non-conservative positional (circulatory) matrix, their skew part.

    See Also
    --------
    decompose_forces"""

    A: sp.Matrix
    N: sp.Matrix
    G: sp.Matrix
    H: sp.Matrix
    J: sp.Matrix

    def __repr__(self) -> str:
        return f"ForceDecomposition({self.A.rows} DOF)"

    def energy_rate(self, y: Sequence[sp.Symbol], ydot: Sequence[sp.Symbol]) -> sp.Expr:
        """``d/dt [y'^T A y' + y^T H y] = -2 [y'^T N y' + y'^T J y]`` along the motion (eq. (7.79)).

        Parameters
        ----------
        y : sequence of Symbol
            Symbols of the coordinates ``y``, one per row of the matrices.
        ydot : sequence of Symbol
            Symbols of the velocities ``y'``, as many as ``y``.
        """
        Y, Yd = sp.Matrix(y), sp.Matrix(ydot)
        return sp.expand(-2 * ((Yd.T * self.N * Yd)[0] + (Yd.T * self.J * Y)[0]))

    def stability(self, values: Mapping[Any, Any] | None = None, *, tol: float = 1e-12) -> StabilityVerdict:
        """Thomson-Tait-Chetaev theorems (Bulgakov (1954), §7.9; Merkin, Introduction to the Theory of Stability,
        ch. 6), applied with numeric values of the parameters.

        - ``J = 0, N = 0``: ``H > 0`` stable whatever ``G``; an odd number of negative eigenvalues of ``H``:
          unstable whatever ``G``; an even number: gyroscopic stabilization is possible (undecided).
        - ``J = 0, N > 0`` (complete dissipation): ``H > 0`` asymptotically stable; ``H`` with a negative
          eigenvalue unstable (dissipation destroys gyroscopic stabilization).
        - ``J = 0, N >= 0``: ``H > 0`` stable.
        - ``J != 0``: no classical theorem applies (undecided; use the eigenvalues).

        Parameters
        ----------
        values : mapping of Symbol or str to float, optional
            Numbers for every parameter of the matrices (keys are symbols or their names); none needed when the matrices
            are numeric.
        tol : float, optional
            Relative tolerance, which must be positive, below which an entry or eigenvalue counts as zero (scaled by the
            largest entry; default 1e-12).
        """
        mats = [np.array(bind(m, values or {}).evalf(), dtype=float) for m in (self.A, self.N, self.G, self.H, self.J)]
        _, N, G, H, J = mats
        scale = max(1.0, *(float(np.abs(m).max()) for m in mats))
        if np.abs(J).max() > tol * scale:
            return StabilityVerdict(None, False, "circulatory forces J != 0: no classical theorem applies")
        hev = np.linalg.eigvalsh(H)
        nev = np.linalg.eigvalsh(N)
        neg = int(np.sum(hev < -tol * scale))
        pos_def = bool(np.all(hev > tol * scale))
        no_damping = bool(np.abs(N).max() <= tol * scale)
        full_damping = bool(np.all(nev > tol * scale))
        gyro = bool(np.abs(G).max() > tol * scale)
        if no_damping:
            if pos_def:
                return StabilityVerdict(True, False, "H > 0 (Lagrange-Dirichlet; gyroscopic forces keep it stable)")
            if neg % 2 == 1:
                return StabilityVerdict(False, False, f"H has {neg} negative eigenvalues, an odd number (Kelvin-Tait)")
            if not gyro:
                return StabilityVerdict(False, False, "H has a negative eigenvalue and there are no gyroscopic forces")
            return StabilityVerdict(None, False, "even degree of instability: gyroscopic stabilization is possible")
        if bool(np.any(nev < -tol * scale)):
            return StabilityVerdict(None, False, "N is not positive semidefinite (energy is fed in)")
        if pos_def:
            if full_damping:
                return StabilityVerdict(True, True, "H > 0 and complete dissipation N > 0 (Kelvin-Tait-Chetaev)")
            return StabilityVerdict(True, False, "H > 0 and N >= 0")
        if full_damping:
            return StabilityVerdict(False, False, "H has a negative eigenvalue under complete dissipation (Chetaev)")
        return StabilityVerdict(None, False, "H indefinite with partial dissipation")


@validated
def decompose_forces(M: Any, C: Any, K: Any) -> ForceDecomposition:
    """Split ``M y'' + C y' + K y = 0`` into ``A = M``, ``N = (C + C^T)/2``, ``G = (C - C^T)/2``,
    ``H = (K + K^T)/2``, ``J = (K - K^T)/2`` (Bulgakov (1954), §7.9).

    Parameters
    ----------
    M : matrix
        Inertia matrix: a square, symmetric SymPy Matrix, nested list or NumPy array.
    C : matrix
        Coefficients of the velocities, square of the size of ``M`` (split into dissipative and gyroscopic parts).
    K : matrix
        Coefficients of the coordinates, square of the size of ``M`` (split into potential and circulatory parts).

    Examples
    --------
    >>> import sympy as sp
    >>> g = sp.Symbol("g", positive=True)
    >>> fd = decompose_forces(sp.eye(2), sp.Matrix([[0, -g], [g, 0]]), sp.diag(-1, -1))
    >>> fd.G
    Matrix([
    [0, -g],
    [g,  0]])
    >>> fd.stability({"g": 3})
    StabilityVerdict(undecided: even degree of instability: gyroscopic stabilization is possible)

    See Also
    --------
    variational_equations, LinearModel
    """
    M, C, K = (check_sympy_matrix(n, x) for n, x in (("M", M), ("C", C), ("K", K)))
    if not (M.is_square and M.shape == C.shape == K.shape):
        raise ModelError(f"M, C, K must be square of one size, got {M.shape}, {C.shape}, {K.shape}")
    if (M - M.T).applyfunc(sp.simplify) != sp.zeros(*M.shape):
        raise ModelError("the inertia matrix M must be symmetric")
    return ForceDecomposition(A=M, N=(C + C.T) / 2, G=(C - C.T) / 2, H=(K + K.T) / 2, J=(K - K.T) / 2)
