"""Bott–Duffin synthesis: a positive-real impedance without transformers (Bott & Duffin 1949; Bulgakov (1954),
§9.27, eqs. (9.408)–(9.423)).

Where Brune's cycle needs unit-coupled coils, Bott and Duffin use Richards' function
``R(p) = (k Z(p) - p Z(k)) / (k Z(k) - p Z(p))`` with ``k > 0`` chosen so that ``Z(k)/k = L`` (``Z(iω0) = iω0 L``):

``Z = [1/(Z(k) R) + p/(k Z(k))]^-1 + [k/(p Z(k)) + R/Z(k)]^-1``,

two parallel pairs in series, each holding a remainder of lower degree after the imaginary-axis removals.  The
remainders ``Z(k) R`` and ``Z(k)/R = Z(k)²/(Z(k) R)`` are duals of each other, so the second network is the first
one's dual (series and parallel exchanged, ``L`` and ``C`` exchanged, values scaled by ``Z(k)²``): one synthesis per
cycle, and one number field for both branches.  The dual step (on ``1/Z``) handles ``Z(iω0) = -i|X|``.  The
result uses only R, L and C (more of them than Brune).

>>> import sympy as sp
>>> from symosc.networks import bott_duffin_synthesis
>>> p = sp.Symbol("p")
>>> Z = (p**2 + p + 1) / (p**2 + p + 4)
>>> net = bott_duffin_synthesis(Z, p)
>>> sp.cancel(net.impedance(p) - Z)
0
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import check_int, validated
from .._exact.fields import Nested
from .._util import P, synthesis_target
from ..ports.oneports import OnePort
from ._synthesis import synthesize
from .positive_real import require_positive_real

__all__ = ["bott_duffin_synthesis"]


@validated
def bott_duffin_synthesis(Z: Any, p: sp.Symbol = P, *, max_degree: int | None = None) -> OnePort:
    """Realise a positive-real impedance with resistors, inductors and capacitors only (Bott–Duffin).

    Parameters
    ----------
    Z : SymPy expression
        Rational positive-real function of ``p`` with numeric coefficients.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.
    max_degree : int, optional
        Largest degree over the rationals of the number field holding the exact element values, as in
        :func:`brune_synthesis` (default 64 with python-flint, 8 without; fields of degree 32–40 take seconds,
        degree 64 up to a few minutes, degree 128 a quarter of an hour or more).

    Returns
    -------
    OnePort
        A series/parallel tree of positive R, L, C whose impedance equals ``Z`` exactly.

    Raises
    ------
    ParameterError
        When ``Z`` is not positive real (naming the failed condition).
    ModelError
        When the exact element values would need a number field of degree above ``max_degree`` over the
        rationals, e.g. an irrational ``ω0`` of degree 6 followed by a Richards' ``k`` of degree 3 over it,
        whichever of the minima of ``Re Z`` and ``Re 1/Z`` a step subtracts (as in :func:`brune_synthesis`).  The
        message names the degree needed and suggests :func:`brune_synthesis`, which needs no Richards' ``k``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import bott_duffin_synthesis
    >>> p = sp.Symbol("p")
    >>> bott_duffin_synthesis((p**2 + p + 1) / (p**2 + p + 4), p)
    (C(2) | (L(1/6) + C(3)) | R(1/4)) + (L(1/2) | ((C(2/3) | L(3/4)) + R(1)))

    See Also
    --------
    brune_synthesis, is_positive_real
    """
    if max_degree is not None:
        max_degree = check_int("max_degree", max_degree, minimum=1)
    p, N, D = synthesis_target(Z, p)
    Z = N.as_expr() / D.as_expr()
    require_positive_real(Z, p)
    try:
        return synthesize(Z, p, "bott_duffin", max_degree)
    except Nested as exc:
        raise Nested(f"{exc}. {_BRUNE_HINT}", exc.degree) from None


#: the advice added to a refusal: Bott–Duffin's fields grow through Richards' ``k`` on top of each ``ω0``
_BRUNE_HINT = (
    "Bott–Duffin's values need Richards' k on top of each frequency ω0 of a minimum; brune_synthesis needs no k "
    "(it uses unit-coupled coils instead) and so usually a much smaller field"
)
