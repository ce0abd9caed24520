"""Brune's synthesis of a positive-real impedance (Brune 1931; Bulgakov (1954), §9.23–9.27).

Each cycle removes the imaginary-axis poles of ``Z`` and of ``1/Z`` (Foster, Theorem IV), subtracts the minimum
resistance ``R = min Re Z(iω)`` (Theorem III) and, when ``Re Z(iω0) = 0`` at a finite ``ω0 > 0``, extracts a
Brune section (perfectly coupled coils and a capacitor) that lowers the degree by two.  The result is a network
whose impedance equals the target exactly.

>>> import sympy as sp
>>> from symosc.networks import brune_synthesis
>>> p = sp.Symbol("p")
>>> Z = (p**2 + p + 1) / (p**2 + p + 4)
>>> net = brune_synthesis(Z, p)
>>> sp.cancel(net.impedance(p) - Z)
0
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import check_int, validated
from .._util import P, synthesis_target
from ..ports.oneports import OnePort
from ._synthesis import minimum_real_part, synthesize
from .positive_real import require_positive_real

__all__ = ["brune_synthesis", "minimum_real_part"]


@validated
def brune_synthesis(Z: Any, p: sp.Symbol = P, *, max_degree: int | None = None) -> OnePort:
    """Realise a positive-real impedance by Brune's procedure; the network's impedance equals ``Z`` exactly.

    Parameters
    ----------
    Z : SymPy expression
        Rational positive-real function of ``p`` with numeric coefficients.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.
    max_degree : int, optional
        Largest degree over the rationals of the number field holding the exact element values; default 64 with
        python-flint (the ``exact`` extra), 8 without, for nested extensions (the first one, of degree at most
        ``2n - 2``, is bounded only by a given value).  Random degree-6 targets occasionally need 32 or more (a
        Brune chain of degree 6 can need up to 10·6·2 = 120); with python-flint fields of degree 32–40 take
        seconds, degree 64 up to a few minutes, and the exact values then have coefficients of thousands of digits
        (the network prints them by 15 digits after ``≈``).  A smaller limit makes such targets fail fast.

    Returns
    -------
    OnePort
        A tree of resistors, inductors, capacitors and :class:`BruneSection` objects (unit-coupled coils), all
        element values positive.

    Raises
    ------
    ParameterError
        When ``Z`` is not positive real (the message names the failed condition), or is identically zero.
    ModelError
        When the exact element values would need a number field of degree above ``max_degree`` over the
        rationals (whichever of the minima of ``Re Z`` and ``Re 1/Z`` a step subtracts: when the one in the
        smaller field leads above the limit, the step is undone and the other one taken).  Element values are
        exact numbers: rationals, square roots, polynomials in a ``CRootOf`` number (in fields of degree above 24,
        polynomials in one ``CRootOf`` per level of the field tower).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import brune_synthesis
    >>> p = sp.Symbol("p")
    >>> brune_synthesis((p**2 + p + 1) / (p**2 + p + 4), p)
    Brune(Lp=1, Ls=1/4, M=1/2, C=1; load=R(1/4))

    See Also
    --------
    bott_duffin_synthesis, is_positive_real, foster_first
    """
    if max_degree is not None:
        max_degree = check_int("max_degree", max_degree, minimum=1)
    p, N, D = synthesis_target(Z, p)
    Z = N.as_expr() / D.as_expr()
    require_positive_real(Z, p)
    return synthesize(Z, p, "brune", max_degree)
