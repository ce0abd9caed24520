"""Four-poles (two-ports) described by their chain matrix (Bulgakov (1954), §8.32–8.36).

>>> import sympy as sp
>>> from symosc.networks import FourPole
>>> Z = sp.Symbol("Z")
>>> fp = FourPole([[1, Z], [0, 1]])          # series impedance
>>> fp.is_reciprocal(), fp.is_symmetric()
(True, True)
>>> fp.input_impedance(sp.Symbol("Z_H"))
Z + Z_H
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_finite_array, validated
from ...errors import AccuracyWarning, ModelError, ParameterError, warn
from .._util import P, as_expr, as_symbol, is_zero
from ._chain_product import Deferred, PendingChain, PendingNetlist, merge_runs, mpmath_product, numeric_product
from ._nodal import Netlist
from .conversions import _kind, convert_parameters

__all__ = ["FourPole", "cascade"]

#: the chain matrix and netlist fields: a cascade stores its factors and multiplies them out on first read
_CHAIN = Deferred()
_NETLIST = Deferred(None)


@dataclass(frozen=True)
class FourPole(SymPyPrintable):
    """A linear four-pole (two-port) given by its chain (A, ABCD) matrix ``[Ex, Ix] = A [Ey, Iy]``.

    Parameters
    ----------
    chain : 2x2 matrix
        Chain matrix, entries rational in ``p`` (or any SymPy expressions).
    p : sympy.Symbol
        Operator variable (``p = i*omega`` in the steady state).
    netlist : Netlist or None
        Terminal-level description used by the Brune validity test of non-cascade connections; the section
        library fills it in.  ``None`` means unknown.
    isolated : bool
        True when an ideal isolating transformer guarantees the port conditions, so every connection is valid.
    name : str
        Label used in ``repr``.

    Notes
    -----
    Output current counted out of the network (Bulgakov (1954), §8.32); :meth:`parameters` converts to Z, Y, H,
    G in this or in the "ieee" convention.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import FourPole
    >>> ZA, ZB = sp.symbols("Z_A Z_B")
    >>> FourPole.from_parameters([[ZA + ZB, -ZB], [ZB, -ZB]], "Z").chain
    Matrix([
    [(Z_A + Z_B)/Z_B, Z_A],
    [          1/Z_B,   1]])

    See Also
    --------
    convert_parameters, cascade, image_parameters
    """

    chain: Any = _CHAIN
    p: sp.Symbol = P
    netlist: Netlist | None = field(default=_NETLIST, compare=False)
    isolated: bool = field(default=False, compare=False)
    name: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        if self._runs() is not None:  # a cascade: the factors were checked, the product is formed on first read
            as_symbol(self.p)
            return
        try:
            A = sp.ImmutableMatrix(self.chain)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"chain must be a 2x2 matrix, got {self.chain!r}") from exc
        if A.shape != (2, 2):
            raise ParameterError(f"chain must be a 2x2 matrix, got shape {A.shape}")
        for entry in A:
            as_expr(entry, "chain entry")
        if is_zero(A.det()):
            raise ModelError(
                "the chain matrix is singular (det A = 0): such a network transmits nothing in one direction; "
                "check the section's element values"
            )
        object.__setattr__(self, "chain", A.applyfunc(sp.cancel))
        as_symbol(self.p)

    # -- parameter sets ------------------------------------------------------------------------------------
    @classmethod
    def from_parameters(
        cls, M: Any, kind: str, p: sp.Symbol = P, convention: str = "book", *, z0: Any = 50, **kw: Any
    ) -> FourPole:
        """Build a four-pole from Z, Y, H, G, S, T or A parameters (see :func:`convert_parameters`)."""
        return cls(convert_parameters(M, kind, "A", convention, z0=z0), p, **kw)

    def parameters(self, kind: str = "A", convention: str = "book", *, z0: Any = 50) -> sp.Matrix:
        """The parameter matrix of ``kind`` in ``convention``; S and T in the reference impedance(s) ``z0``.

        Parameters
        ----------
        kind : {"A", "Z", "Y", "H", "G", "S", "T"}
            Parameter set to return, one of "A" (chain; "ABCD" and "chain" are accepted too), "Z", "Y", "H", "G", "S",
            "T" (see :func:`convert_parameters`).
        convention : {"book", "ieee"}
            Sign convention of Z, Y, H, G: the output current counted out of (book) or into (ieee) the network.
        z0 : number, positive Symbol or pair
            Reference impedance(s) of S and T (default 50 ohm).
        """
        _kind(kind, "kind")
        return convert_parameters(self.chain, "A", kind, convention, z0=z0)

    def s_parameters(self, z0: Any = 50) -> sp.Matrix:
        """Scattering parameters ``[b1, b2] = S [a1, a2]`` in the reference impedance(s) ``z0``, symbolic in ``p``.

        Parameters
        ----------
        z0 : number, positive Symbol or pair
            Reference impedance of both ports (default 50 ohm), or ``(Z01, Z02)``; real and positive.

        Examples
        --------
        >>> import sympy as sp
        >>> from symosc.networks import series_element
        >>> Z0 = sp.Symbol("Z0", positive=True)
        >>> series_element(sp.Symbol("Z")).s_parameters(Z0)
        Matrix([
        [   Z/(Z + 2*Z0), 2*Z0/(Z + 2*Z0)],
        [2*Z0/(Z + 2*Z0),    Z/(Z + 2*Z0)]])

        See Also
        --------
        t_parameters, to_skrf, convert_parameters
        """
        return convert_parameters(self.chain, "A", "S", z0=z0)

    def t_parameters(self, z0: Any = 50) -> sp.Matrix:
        """Scattering-transfer parameters ``[b1, a1] = T [a2, b2]`` (scikit-rf's), so that cascades multiply.

        Parameters
        ----------
        z0 : number, positive Symbol or pair
            Reference impedance of both ports (default 50 ohm), or ``(Z01, Z02)``; real and positive.
        """
        return convert_parameters(self.chain, "A", "T", z0=z0)

    def to_skrf(self, frequencies: Any, z0: Any = 50, name: str | None = None) -> Any:
        """The four-pole as a ``skrf.Network`` (scikit-rf, an optional dependency) at ``p = 2 pi i f``.

        Parameters
        ----------
        frequencies : array_like
            Frequencies in hertz (>= 0).
        z0 : number or pair
            Reference impedance(s) of the S parameters (default 50 ohm).
        name : str, optional
            Name of the network (default: the four-pole's name).

        Raises
        ------
        ParameterError
            Free symbols other than ``p`` in the chain matrix (substitute values first).

        See Also
        --------
        s_parameters, symosc.networks.skrf_parameters
        """
        from .scattering import to_skrf

        return to_skrf(self, frequencies, z0, name)

    @property
    def A(self) -> sp.Matrix:
        """Chain matrix."""
        return sp.Matrix(self.chain)

    @property
    def Z(self) -> sp.Matrix:
        """Impedance matrix, book convention."""
        return self.parameters("Z")

    @property
    def Y(self) -> sp.Matrix:
        """Admittance matrix, book convention."""
        return self.parameters("Y")

    @property
    def H(self) -> sp.Matrix:
        """Hybrid matrix ``[Ex, Iy] = H [Ix, Ey]``, book convention."""
        return self.parameters("H")

    @property
    def G(self) -> sp.Matrix:
        """Inverse hybrid matrix ``[Ix, Ey] = G [Ex, Iy]``, book convention."""
        return self.parameters("G")

    # -- properties ----------------------------------------------------------------------------------------
    def is_reciprocal(self) -> bool:
        """``det A = 1`` (equivalently ``Z12 = -Z21``), Bulgakov (1954), eqs. (8.255), (8.261)."""
        return is_zero(self.chain.det() - 1)

    def is_symmetric(self) -> bool:
        """Reciprocal with ``A11 = A22``: the ports can be interchanged."""
        return self.is_reciprocal() and is_zero(self.chain[0, 0] - self.chain[1, 1])

    def reversed(self) -> FourPole:
        """The same network driven from the other side (ports interchanged)."""
        runs = self._runs()
        if runs is not None:  # rev(A B) = rev(B) rev(A): rev(A) = J A^-1 J with J = diag(1, -1)
            parts = [(f.reversed(), n) for f, n in reversed(runs)]
            return _product(parts, self.p, self.isolated, f"reversed({self.name})" if self.name else "")
        A = self.chain
        Ar = sp.Matrix([[A[1, 1], A[0, 1]], [A[1, 0], A[0, 0]]]) / A.det()
        net = None
        if self.netlist is not None:
            t = self.netlist.terminals
            net = Netlist(self.netlist.branches, (t[2], t[3], t[0], t[1]))
        return FourPole(Ar, self.p, net, self.isolated, f"reversed({self.name})" if self.name else "")

    def input_impedance(self, load: Any) -> sp.Expr:
        """``(A11 Zy + A12)/(A21 Zy + A22)`` with the output closed by ``load``, eq. (8.281).

        Parameters
        ----------
        load : number or SymPy expression
            Impedance ``Zy`` closing the output, an expression in ``p`` (or a number).
        """
        A, Zy = self.chain, as_expr(load, "load")
        return sp.cancel((A[0, 0] * Zy + A[0, 1]) / (A[1, 0] * Zy + A[1, 1]))

    def output_impedance(self, source: Any) -> sp.Expr:
        """``(A22 Zx + A12)/(A21 Zx + A11)`` seen from the output with the input closed by ``source``, (8.284).

        Parameters
        ----------
        source : number or SymPy expression
            Impedance ``Zx`` closing the input, an expression in ``p`` (or a number).
        """
        A, Zx = self.chain, as_expr(source, "source")
        return sp.cancel((A[1, 1] * Zx + A[0, 1]) / (A[1, 0] * Zx + A[0, 0]))

    def subs(self, *args: Any, **kwargs: Any) -> FourPole:
        """Substitute into the chain matrix (the netlist is dropped unless nothing structural changes).

        A cascade substitutes into each of its sections and stays a product (see :meth:`evaluate_numeric`).

        Parameters
        ----------
        args
            What to substitute, as for ``sympy.Matrix.subs``: ``old, new``, a dict or a list of ``(old, new)`` pairs.
        """
        runs = self._runs()
        if runs is not None:
            return _product([(f.subs(*args, **kwargs), n) for f, n in runs], self.p, self.isolated, self.name)
        return FourPole(self.chain.subs(*args, **kwargs), self.p, None, self.isolated, self.name)

    def evaluate(self, value: Any) -> Any:
        """Chain matrix at ``p = value`` as an mpmath matrix (``value`` may be complex, e.g. ``1j*omega``).

        A cascade is evaluated as the product of its sections' matrices at the working precision.

        Parameters
        ----------
        value : number or SymPy number
            Value of the operator variable ``p``, real or complex (``1j*omega`` for the steady state at ``omega``).
        """
        import mpmath

        runs = self._runs()
        if runs is not None:
            return mpmath_product(runs, value)
        f = sp.lambdify(self.p, self.chain, "mpmath")
        return mpmath.matrix(f(mpmath.mpmathify(value)).tolist())

    def evaluate_numeric(self, omega: Any = None, values: Mapping | None = None, *, p_values: Any = None) -> np.ndarray:
        """Chain (ABCD) matrices at many frequencies in double precision: an array of shape ``(..., 2, 2)``.

        The layout of scikit-rf's ``Network.a`` (frequency first).  A cascade is evaluated as the product of its
        sections' numeric chain matrices at every frequency (``numpy.matmul`` on the stacks, repeated squaring for
        runs of identical sections), never through its multiplied-out polynomials: those cancel catastrophically in
        a pass band (100 L-C sections: degree 200, coefficients of 1e60, values of order one).  So build long chains
        with :func:`cascade`, ``@``, ``**`` or :func:`chain_power` and evaluate them here.

        Parameters
        ----------
        omega : float or array_like of float, optional
            Angular frequencies in rad/s; the chain matrix is evaluated at ``p = i*omega``.
        values : mapping, optional
            Numbers for the other symbols of the chain matrix (element values), keyed by Symbol or name.
        p_values : complex or array_like of complex, optional
            Values of the operator variable ``p`` itself (instead of ``omega``), e.g. ``sigma + i*omega``.

        Returns
        -------
        ndarray
            Complex, shape ``shape(omega) + (2, 2)``.

        Raises
        ------
        ParameterError
            Neither or both of ``omega`` and ``p_values`` given, non-finite frequencies, or a value missing for a
            symbol of the chain matrix.

        Warns
        -----
        AccuracyWarning
            When an entry overflows double precision (a long chain far in its stop band grows like
            ``exp(n * attenuation)``).

        Examples
        --------
        >>> import numpy as np, sympy as sp
        >>> from symosc.networks import series_element, shunt_element
        >>> p = sp.Symbol("p")
        >>> lc = series_element(p) @ shunt_element(1 / p)            # one L-C low-pass section
        >>> A = (lc**100).evaluate_numeric(np.array([0.5, 1.0, 1.5]))  # pass band: omega < 2
        >>> A.shape
        (3, 2, 2)
        >>> np.allclose(np.linalg.det(A), 1.0)                        # reciprocal: det A = 1
        True

        See Also
        --------
        evaluate, cascade, chain_power
        """
        if (omega is None) == (p_values is None):
            raise ParameterError("evaluate_numeric needs exactly one of omega (rad/s) or p_values")
        if p_values is None:
            p_arr = 1j * check_finite_array("omega", omega)
        else:
            p_arr = check_finite_array("p_values", p_values, complex_ok=True)
        given = dict(values) if values is not None else {}
        with np.errstate(over="ignore", invalid="ignore"):
            out = self._numeric_chain(p_arr, given)
        if not np.all(np.isfinite(out)):
            warn(
                "the chain matrix is not finite at some frequencies (it overflows double precision far in a stop "
                "band, or p is at a pole of a section); evaluate there with evaluate() at higher precision",
                AccuracyWarning,
            )
        return out

    def _numeric_chain(self, p_arr: np.ndarray, values: dict) -> np.ndarray:
        runs = self._runs()
        if runs is not None:
            return numeric_product(runs, p_arr, values)
        fn, others = self._chain_function
        from ...numeric import resolve

        args = resolve(others, values) if others else []
        out = np.asarray(fn.raw(p_arr, *args), dtype=complex)
        shape = (*p_arr.shape, 2, 2)
        return out if out.shape == shape else np.broadcast_to(out, shape)

    @functools.cached_property
    def _chain_function(self) -> tuple[Any, list[sp.Symbol]]:
        """The chain matrix compiled once (NumPy backend), and its symbols other than ``p`` in call order."""
        from ...numeric import compile as compile_numeric

        others = sorted(self.chain.free_symbols - {self.p}, key=lambda s: s.name)
        return compile_numeric(self.chain, [self.p, *others], backend="numpy", check=False), others

    def _runs(self) -> tuple[tuple[FourPole, int], ...] | None:
        """The factors ``((four_pole, power), ...)`` of a cascade not yet multiplied out, else None."""
        stored = _CHAIN.stored(self)
        return stored.runs if isinstance(stored, PendingChain) else None

    def __matmul__(self, other: FourPole) -> FourPole:
        return cascade(self, other)

    def __pow__(self, n: int) -> FourPole:
        if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 1:
            raise ParameterError(
                f"a four-pole's power is the cascade of n >= 1 copies; n must be such an integer, got {n!r}"
            )
        if n == 1:
            return self
        name = f"({self.name})**{int(n)}" if self.name else ""
        return _product([(self, int(n))], self.p, self.isolated, name)

    # -- printing ------------------------------------------------------------------------------------------
    def __repr__(self) -> str:
        label = f"{self.name}: " if self.name else ""
        return f"FourPole({label}A = {sp.sstr(self.chain.tolist())})"

    def _sympystr(self, printer: Any) -> str:
        return repr(self)

    def _latex(self, printer: Any) -> str:
        return r"\mathbf{A} = " + (printer._print(self.chain) if printer is not None else sp.latex(self.chain))

    def _repr_latex_(self) -> str:
        return f"${self._latex(None)}$"


def _product(runs: list[tuple[FourPole, int]], p: sp.Symbol, isolated: bool, name: str) -> FourPole:
    """A four-pole whose chain matrix is the product of ``runs``, formed exactly on first read."""
    merged = merge_runs(runs)
    return FourPole(PendingChain(merged), p, PendingNetlist(merged), isolated, name)


@validated
def cascade(*four_poles: FourPole) -> FourPole:
    """Cascade (tandem) connection, chain matrix A = A_1 A_2 ⋯ A_n (Bulgakov (1954), eq. (8.270)).

    The result keeps its sections: its exact chain matrix is multiplied out (in the polynomial ring or rational
    function field of the entries) when first read, and :meth:`FourPole.evaluate_numeric` multiplies the sections'
    numeric matrices frequency by frequency, which stays accurate where the multiplied-out polynomials cancel.
    ``a @ b`` is ``cascade(a, b)``; ``a**n`` is the cascade of ``n`` copies.

    Parameters
    ----------
    *four_poles : FourPole
        The sections, from input to output (at least one).

    Returns
    -------
    FourPole

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import cascade, series_element
    >>> cascade(series_element(1), series_element(2)).chain
    Matrix([
    [1, 3],
    [0, 1]])

    See Also
    --------
    chain_power, series, parallel, FourPole.evaluate_numeric
    """
    if not four_poles:
        raise ParameterError("cascade needs at least one four-pole")
    for i, f in enumerate(four_poles):
        if not isinstance(f, FourPole):
            raise ParameterError(f"four_poles[{i}] must be a FourPole, got {type(f).__name__}")
    fps = list(four_poles)
    if len(fps) == 1:
        return fps[0]
    isolated = any(f.isolated for f in fps)
    return _product([(f, 1) for f in fps], fps[0].p, isolated, " * ".join(f.name for f in fps if f.name))
