"""Stability region in coefficient (parameter) space (Bulgakov (1954), §8.19–8.20).

The region is bounded by ``T1`` (part of ``ks = 0``: a zero root) and ``T2`` (part of ``Δ_(s-1) = 0``: a pair
``±iω``); the rest of ``Δ_(s-1) = 0`` (``T3``: pairs ``±a`` or ``±(α ± iω)``) is not a boundary.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from .._util import as_coefficients
from ._root_counts import count_roots_right
from .criteria import hurwitz

__all__ = ["StabilityRegion", "robust_boundary", "stability_region"]


@dataclass(frozen=True)
class StabilityRegion(SymPyPrintable):
    """Result of :func:`stability_region`.

    Attributes
    ----------
    coefficients : tuple
        ``k0 ... ks`` as expressions in the parameters.
    params : tuple of Symbol
        The parameter symbols spanning the space.
    conditions : tuple
        Expressions that must all be positive (Hurwitz, with ``ks`` for the last minor).
    zero_root_boundary : sympy.Expr
        ``ks`` (``T1``).
    imaginary_pair_boundary : sympy.Expr
        ``Δ_(s-1)`` (contains ``T2`` and the non-boundary part ``T3``).
    """

    coefficients: tuple
    params: tuple
    conditions: tuple
    zero_root_boundary: sp.Expr
    imaginary_pair_boundary: sp.Expr

    @property
    def inequalities(self) -> sp.Basic:
        return sp.And(*[c > 0 for c in self.conditions])

    def contains(self, values: dict) -> bool:
        """Hurwitz verdict at a parameter point (exact on the given numbers).

        Parameters
        ----------
        values : mapping of Symbol or str to number
            Value of every parameter (keys are the symbols or their names); a missing parameter raises
            ParameterError.
        """
        vals = {sp.Symbol(k) if isinstance(k, str) else k: v for k, v in values.items()}
        missing = [p for p in self.params if p not in vals]
        if missing:
            raise ParameterError(f"missing values for {missing}")
        return bool(hurwitz([sp.sympify(c).subs(vals) for c in self.coefficients]).stable)

    def roots_right(self, values: Mapping) -> Any:
        """Number of roots with ``Re λ > 0`` at parameter points (0 inside the region), in floating point.

        The coefficients are compiled once per region (:func:`symosc.numeric.compile`) and the roots of a whole
        grid are the eigenvalues of a stack of companion matrices (as :func:`numpy.roots`, one LAPACK call per
        degree).  Points on the boundary get either label; :meth:`contains` decides one point exactly.

        Parameters
        ----------
        values : mapping
            A number or an array for each parameter (keyed by Symbol or name); arrays are broadcast together.

        Returns
        -------
        int or ndarray of int
            An int when every value is a scalar, else an array of the broadcast shape.

        Examples
        --------
        >>> import numpy as np, sympy as sp
        >>> from symosc.linear import stability_region
        >>> x, y = sp.symbols("x y")
        >>> r = stability_region([1, x, y, 1], (x, y))
        >>> r.roots_right({x: np.array([2.0, 2.0, -1.0]), "y": np.array([1.0, 0.4, 1.0])})
        array([0, 2, 2])
        """
        from ...numeric import resolve

        given = resolve(self.params, values)
        arrays = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in given))
        c = np.asarray(self._coefficient_function.raw(*arrays), dtype=complex)
        counts = count_roots_right(c.reshape(-1, len(self.coefficients)), 0.0)
        return int(counts[0]) if arrays[0].ndim == 0 else counts.reshape(arrays[0].shape)

    @functools.cached_property
    def _coefficient_function(self) -> Any:
        from ...numeric import compile as compile_numeric

        return compile_numeric(list(self.coefficients), list(self.params), backend="numpy", check=False)

    def __repr__(self) -> str:
        return f"StabilityRegion({sp.sstr(self.inequalities)})"

    def _latex(self, printer) -> str:
        return printer._print(self.inequalities)

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(self)}$$"

    def plot(self, *, ax=None, xlim=(-1.0, 5.0), ylim=(-1.0, 5.0), grid: int = 200):
        """Shade the region in the plane of two parameters; draw ``T1`` and ``Δ_(s-1) = 0``; returns the Axes.

        Needs exactly two parameters.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        xlim, ylim : pair of float, optional
            Range ``(low, high)`` of the first and second parameter shown, ``low < high`` (default (-1, 5)).
        grid : int, optional
            Number of grid points per axis (an integer >= 2; default 200).
        """
        from .._util import figure_axes

        if len(self.params) != 2:
            raise ParameterError("plot needs exactly two parameters")
        ax = figure_axes(ax)
        x, y = np.meshgrid(np.linspace(*xlim, grid), np.linspace(*ylim, grid))
        ok = np.ones_like(x, dtype=bool)
        for c in self.conditions:
            f = sp.lambdify(self.params, c, "numpy")
            ok &= np.broadcast_to(np.asarray(f(x, y), dtype=float), x.shape) > 0
        ax.contourf(x, y, ok.astype(float), levels=[0.5, 1.5], colors=["C2"], alpha=0.3)
        for expr, style, label in (
            (self.zero_root_boundary, "C0", "ks = 0"),
            (self.imaginary_pair_boundary, "C3", "Δ(s-1) = 0"),
        ):
            f = sp.lambdify(self.params, expr, "numpy")
            cs = ax.contour(x, y, np.broadcast_to(np.asarray(f(x, y), dtype=float), x.shape), levels=[0], colors=style)
            cs.set_label(label)
        ax.set_xlabel(str(self.params[0]))
        ax.set_ylabel(str(self.params[1]))
        return ax


@validated
def stability_region(coefficients: Any, params: Any) -> StabilityRegion:
    """Stability region of ``k0 λ^s + … + ks`` in the space of the parameters (Bulgakov (1954), §8.19).

    Parameters
    ----------
    coefficients : sequence or sympy.Poly
        Coefficients ``k0, ..., ks`` highest power first, expressions in ``params`` only (``k0 != 0``, at least
        two).
    params : Symbol or sequence of Symbols
        The parameters spanning the space; every free symbol of the coefficients must be among them.

    Returns
    -------
    StabilityRegion

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import stability_region
    >>> x, y = sp.symbols("x y")
    >>> r = stability_region([1, x, y, 1], (x, y))        # Vyshnegradsky: x > 0, xy > 1
    >>> r.imaginary_pair_boundary
    x*y - 1
    >>> r.contains({x: 2, y: 1}), r.contains({x: 2, y: 0.4})
    (True, False)

    See Also
    --------
    hurwitz, d_partition, vyshnegradsky_diagram
    """
    params = (params,) if isinstance(params, sp.Symbol) else tuple(params)
    coeffs = as_coefficients(coefficients)
    extra = set().union(*(c.free_symbols for c in coeffs)) - set(params)
    if extra:
        raise ParameterError(f"symbols {sorted(map(str, extra))} are not parameters; substitute values first")
    v = hurwitz(coeffs)
    s = len(coeffs) - 1
    conds = tuple(sp.factor(c) for c in v.conditions)
    return StabilityRegion(coeffs, params, conds, coeffs[-1], sp.factor(v.minors[s - 2]) if s >= 2 else sp.Integer(1))


@validated
def robust_boundary(boundary: Any, params: Any, unreliable: sp.Symbol) -> tuple:
    """Envelope of a family of stability boundaries over an unreliable parameter (Bulgakov (1954), §8.21, §8.23).

    The boundary ``F(x, y, z) = 0`` moves with the unreliable ``z``; regions of *reliable* stability (or instability)
    are bounded by its envelope ``F = ∂F/∂z = 0``, found here as the resultant in ``z`` (factors free of the
    parameters and monomial factors dropped).

    Parameters
    ----------
    boundary : sympy.Expr
        The boundary ``F(x, y, z)`` (the curve is ``F = 0``); must be polynomial in ``unreliable`` and depend on it.
    params : sequence of Symbols
        The reliable parameters (the plane of the diagram); factors free of them are dropped.
    unreliable : sympy.Symbol
        The unreliable parameter ``z`` the envelope is taken over; must be a SymPy Symbol.

    Returns
    -------
    tuple of sympy.Expr
        The factors of the envelope (each ``= 0`` is a branch).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import robust_boundary
    >>> x, y, z, k = sp.symbols("x y z k")
    >>> robust_boundary((x*z + 1)*(y*z + k) - z, (x, y), z)       # servo of §8.23: the parabola
    (k**2*x**2 - 2*k*x*y - 2*k*x + y**2 - 2*y + 1,)

    See Also
    --------
    stability_region, d_partition
    """
    params = tuple(params)
    F = sp.expand(sp.sympify(boundary))
    if not F.has(unreliable):
        raise ParameterError(f"the boundary does not depend on the unreliable parameter {unreliable}")
    if not F.is_polynomial(unreliable):
        raise ParameterError(f"the boundary must be polynomial in {unreliable}")
    R = sp.resultant(F, sp.diff(F, unreliable), unreliable)
    factors = []
    for fac, _ in sp.factor_list(R)[1]:
        if not (fac.free_symbols & set(params)):
            continue
        if fac.is_Symbol or (fac.is_Pow and fac.base.is_Symbol):
            continue
        factors.append(fac)
    return tuple(factors)
