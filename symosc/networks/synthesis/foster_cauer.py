"""Foster and Cauer canonical forms of reactance (LC) one-ports (Bulgakov (1954), §9.21, §9.23).

Element values are exact: rational, radicals, or polynomials in a ``CRootOf`` when the resonances are roots of
an irreducible polynomial of degree three or more in ``p²`` (one tank per root).

A reactance function is positive real with ``Re Z(iω) = 0``: Foster's theorem gives
``Z = L p + 1/(C0 p) + Σ 2k p/(p² + ω²)`` (first form: a series chain of tanks) and the same for ``Y = 1/Z``
(second form: parallel series-LC branches); Cauer's continued fractions at infinity (first form) and at zero
(second form) give ladders.

>>> import sympy as sp
>>> from symosc.networks import foster_first, cauer_first
>>> p = sp.Symbol("p")
>>> Z = (p**4 + 4*p**2 + 3) / (p**3 + 2*p)
>>> foster_first(Z, p)
L(1) + C(2/3) + (C(2) | L(1/4))
>>> cauer_first(Z, p)
L(1) + (C(1/2) | (L(4) + C(1/6)))
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import validated
from ...errors import ParameterError
from .._exact import fields as ex
from .._util import P, synthesis_target
from ..ports.oneports import OnePort, Parallel, Series
from ._synthesis import cauer_ladder, exact_polys, remove_axis_poles
from .positive_real import real_part_on_axis, require_positive_real

__all__ = ["cauer_first", "cauer_second", "foster_first", "foster_second", "is_reactance_function"]


@validated
def is_reactance_function(Z: Any, p: sp.Symbol = P) -> bool:
    """True when ``Z`` is positive real with ``Re Z(iω) ≡ 0`` (a lossless LC one-port, Foster's theorem).

    Parameters
    ----------
    Z : SymPy expression
        Rational function of ``p`` with real numeric coefficients to test.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import is_reactance_function
    >>> p = sp.Symbol("p")
    >>> is_reactance_function((p**2 + 1) / p, p), is_reactance_function((p + 1) / p, p)
    (True, False)

    See Also
    --------
    foster_first, cauer_first, is_positive_real
    """
    from .positive_real import is_positive_real

    return is_positive_real(Z, p) and real_part_on_axis(Z, p)[0].is_zero


def _reactance(Z: Any, p: sp.Symbol) -> tuple[list, list, Any]:
    """Exact coefficient lists ``(N, D, K)`` of a reactance function, or ParameterError saying why not."""
    p, N, D = synthesis_target(Z, p)
    require_positive_real(N.as_expr() / D.as_expr(), p)
    Ne, De, K = exact_polys(N, D)
    if ex.real_part_x(Ne, De, K)[0]:
        raise ParameterError(
            "Z is not a reactance function (Re Z(iω) is not identically zero): Foster and Cauer forms realise "
            "lossless LC one-ports only; use brune_synthesis or bott_duffin_synthesis for RLC targets"
        )
    return Ne, De, K


def _join(parts: list[OnePort], cls: type) -> OnePort:
    return parts[0] if len(parts) == 1 else cls(tuple(parts))


@validated
def foster_first(Z: Any, p: sp.Symbol = P) -> OnePort:
    """Foster's first form: series inductor, series capacitor and parallel LC tanks (poles of ``Z``).

    Parameters
    ----------
    Z : SymPy expression
        Reactance function to realise: a positive-real rational function of ``p`` with numeric coefficients and ``Re
        Z(iω) = 0`` (an LC one-port).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import foster_first
    >>> p = sp.Symbol("p")
    >>> foster_first(p / (p**2 + 1), p)
    C(1) | L(1)

    See Also
    --------
    foster_second, cauer_first
    """
    N, D, K = _reactance(Z, p)
    parts, rest, _ = remove_axis_poles(N, D, K, "Z")
    if rest:  # pragma: no cover - a reactance function is exhausted by its poles
        raise ParameterError("Foster expansion left a remainder: Z is not a reactance function")
    return _join(parts, Series)


@validated
def foster_second(Z: Any, p: sp.Symbol = P) -> OnePort:
    """Foster's second form: shunt capacitor, shunt inductor and parallel series-LC branches (poles of ``1/Z``).

    Parameters
    ----------
    Z : SymPy expression
        Reactance function to realise: a positive-real rational function of ``p`` with numeric coefficients and ``Re
        Z(iω) = 0`` (an LC one-port).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import foster_second
    >>> p = sp.Symbol("p")
    >>> foster_second((p**2 + 1) / p, p)
    L(1) + C(1)

    See Also
    --------
    foster_first, cauer_second
    """
    N, D, K = _reactance(Z, p)
    parts, rest, _ = remove_axis_poles(D, N, K, "Y")
    if rest:  # pragma: no cover
        raise ParameterError("Foster expansion left a remainder: Z is not a reactance function")
    return _join(parts, Parallel)


@validated
def cauer_first(Z: Any, p: sp.Symbol = P) -> OnePort:
    """Cauer's first form: ladder of series inductors and shunt capacitors (continued fraction at infinity).

    Parameters
    ----------
    Z : SymPy expression
        Reactance function to realise: a positive-real rational function of ``p`` with numeric coefficients and ``Re
        Z(iω) = 0`` (an LC one-port).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import cauer_first
    >>> p = sp.Symbol("p")
    >>> cauer_first(p / (p**2 + 1), p)
    C(1) | L(1)

    See Also
    --------
    cauer_second, foster_first
    """
    N, D, K = _reactance(Z, p)
    if ex.dup_degree(N) == ex.dup_degree(D) + 1:
        return cauer_ladder(N, D, K, "Z", True)
    return cauer_ladder(*ex.normalize(D, N, K), K, "Y", True)


@validated
def cauer_second(Z: Any, p: sp.Symbol = P) -> OnePort:
    """Cauer's second form: ladder of series capacitors and shunt inductors (continued fraction at zero).

    Parameters
    ----------
    Z : SymPy expression
        Reactance function to realise: a positive-real rational function of ``p`` with numeric coefficients and ``Re
        Z(iω) = 0`` (an LC one-port).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import cauer_second
    >>> p = sp.Symbol("p")
    >>> cauer_second((p**2 + 1) / p, p)
    C(1) + L(1)

    See Also
    --------
    cauer_first, foster_second
    """
    N, D, K = _reactance(Z, p)
    if D and not D[-1]:
        return cauer_ladder(N, D, K, "Z", False)
    return cauer_ladder(*ex.normalize(D, N, K), K, "Y", False)
