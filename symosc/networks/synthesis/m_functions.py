"""Richards' function and Min Nai-da's M-function realisation (Bulgakov (1954), §9.24 and §9.27, eq. (9.408)).

Richards' theorem: for a positive-real ``Z`` and ``k > 0`` the function
``R(p) = (k Z(p) - p Z(k)) / (k Z(k) - p Z(p))`` is positive real and its rank (sum of the degrees of numerator and
denominator) does not exceed that of ``Z``.  It is the step on which the Bott–Duffin synthesis is built.

An M-function is a rational ``Z`` with ``Re Z > 0`` for ``Re p > -rho``; ``Z*(p*) = Z(p* - rho)`` is then positive
real (eqs. (9.274)–(9.276)).  Realising ``Z*`` without mutual inductance (Bott–Duffin) and substituting
``p* = p + rho`` turns every inductor ``L`` into ``L`` in series with ``rho L`` and every capacitor ``C`` into ``C``
in parallel with ``1/(rho C)``: a network without ideal (lossless) elements whose impedance is ``Z`` (the theorem
of §9.24).

>>> import sympy as sp
>>> from symosc.networks import m_function_synthesis
>>> p = sp.Symbol("p")
>>> net = m_function_synthesis((p + 3) / (p + 2), 1, p)
>>> net
R(1) + (C(1) | R(1) | R(1))
>>> sp.cancel(net.impedance(p) - (p + 3) / (p + 2))
0
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import check_int, validated
from ...errors import ConvergenceError, ParameterError
from ...operational._rational import exactify
from .._util import P, as_expr, as_symbol, rational_function, synthesis_target
from ..ports.oneports import BruneSection, Capacitor, Impedance, Inductor, OnePort, Parallel, Resistor, Series
from ._synthesis import _clean, exact_polys
from .positive_real import is_positive_real, positive_real_report, require_positive_real

__all__ = ["m_abscissa", "m_function_synthesis", "richards_function"]

_DIGITS = 50


@validated
def richards_function(Z: Any, k: Any, p: sp.Symbol = P) -> sp.Expr:
    """Richards' function ``R(p) = (k Z(p) - p Z(k)) / (k Z(k) - p Z(p))``, Bulgakov (1954), §9.27, eq. (9.408).

    For a positive-real ``Z`` and ``k > 0`` it is positive real of rank not above the rank of ``Z``; when
    ``Z(k)/k = L`` and ``Z(iω0) = iω0 L`` it vanishes at ``p = iω0`` (eq. (9.410)), which lets the Bott–Duffin
    procedure lower the rank without transformers.

    Parameters
    ----------
    Z : SymPy expression
        Positive-real rational function of ``p`` with numeric coefficients.
    k : number or SymPy expression
        A positive real number (exact values keep the result exact).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Returns
    -------
    sympy.Expr
        ``R(p)`` as a cancelled rational function.

    Raises
    ------
    ParameterError
        When ``Z`` is not positive real, ``k`` is not a positive number, or ``k Z(k) - p Z(p)`` vanishes
        identically (``Z = c/p``, a pure capacitor).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import richards_function
    >>> p = sp.Symbol("p")
    >>> Z = (p**2 + p + 1) / (p**2 + p + 4)
    >>> richards_function(Z, 1, p)
    (p**2 + 2)/(2*p**2 + 3*p + 4)

    See Also
    --------
    bott_duffin_synthesis, is_positive_real
    """
    p = as_symbol(p)
    N, D = rational_function(Z, p)
    k = as_expr(k, "k")
    if k.free_symbols or not k.is_extended_real or not k.is_positive:
        raise ParameterError(f"k must be a positive real number, got {k}")
    Z = N.as_expr() / D.as_expr()
    require_positive_real(Z, p)
    Zk = N.as_expr().subs(p, k) / D.as_expr().subs(p, k)
    den = sp.cancel(k * Zk - p * Z)
    if den == 0:
        raise ParameterError(
            "Richards' function is undefined for Z = c/p, a pure capacitor (k Z(k) - p Z(p) vanishes identically)"
        )
    return sp.cancel((k * Z - p * Zk) / den)


@validated
def m_abscissa(Z: Any, p: sp.Symbol = P) -> sp.Expr:
    """The largest ``rho`` for which ``Z(p - rho)`` is positive real: Min Nai-da's abscissa (Bulgakov (1954), §9.24).

    ``Z`` is an M-function for every ``0 < rho <= m_abscissa(Z)`` (shifting a positive-real function to the right
    keeps it positive real, so these ``rho`` form an interval); an inductor of the realisation may then carry a
    series resistance ``rho L`` and a capacitor a parallel one ``1/(rho C)`` (:func:`m_function_synthesis`).

    The result is exact.  At the largest ``rho`` either a pole or zero of ``Z`` reaches the line ``Re p = -rho``,
    or the minimum of ``Re Z(-rho + iω)`` over ``ω`` (at a finite ``ω``, at 0 or at infinity) reaches zero.  Every
    such ``rho`` is a positive real root of one of these polynomials: the resultants
    ``res_y(F(y), F(-2 rho - y))`` for ``F = N, D`` (their roots include minus the real part of every pole and
    zero), and the discriminant, the leading coefficient and the constant term in ``x = ω²`` of the numerator of
    ``Re Z(-rho + iω)`` (with algebraic coefficients: their norms over the rationals, whose roots include those
    of the conjugate functions as harmless extra candidates).  The roots are ordered and ``Z(p - t)`` is tested
    exactly (Sturm counts) at a rational ``t`` between each pair of consecutive roots; the last root below the
    first failing ``t`` is the answer.

    Parameters
    ----------
    Z : SymPy expression
        Positive-real rational function of ``p`` with rational or algebraic (e.g. ``sqrt(2)``) coefficients
        (floating-point ones are taken exactly).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Returns
    -------
    sympy.Expr
        ``rho`` >= 0: a rational, a radical or a ``CRootOf`` number; ``0`` when ``Z`` has a pole or a zero on the
        imaginary axis or ``Re Z(iω)`` reaches zero (no positive ``rho`` works), ``oo`` for a constant ``Z``.

    Raises
    ------
    ParameterError
        When ``Z`` is not positive real (the message names the failed condition) or has coefficients that are
        not algebraic numbers (symbols, ``pi``).
    ConvergenceError
        When two candidate roots agree to 40 digits, so that no rational point is placed between them (not
        seen in practice).

    Examples
    --------
    Bulgakov (1954), §9.24, Ex. 1: ``(a0 p + a1)/(b0 p + b1)`` is an M-function up to ``min(b1/b0, a1/a0)``.

    >>> import sympy as sp
    >>> from symosc.networks import m_abscissa
    >>> p = sp.Symbol("p")
    >>> m_abscissa((2*p + 3) / (p + 4), p)
    3/2
    >>> m_abscissa((p**2 + p + 1) / (p**2 + p + 4), p)     # Re Z(iω) = 0 at ω² = 2
    0

    See Also
    --------
    is_m_function, m_function_synthesis, minimum_real_part
    """
    p = as_symbol(p)
    N, D = rational_function(exactify(Z), p)
    exact_polys(N, D)  # ParameterError unless the coefficients are rational or algebraic
    require_positive_real(N.as_expr() / D.as_expr(), p)
    if N.degree() <= 0 and D.degree() <= 0:
        return sp.oo
    below, low = sp.Integer(0), sp.Integer(0)  # the last candidate passed, exact and as a 50-digit rational
    for c, value in _ordered_candidates(N, D, p):
        if not is_positive_real(_shifted(N, D, p, _between(low, value)), p):
            return below
        below, low = c, value
    return sp.oo if is_positive_real(_shifted(N, D, p, 2 * low + 1), p) else below


def _shifted(N: sp.Poly, D: sp.Poly, p: sp.Symbol, t: sp.Expr) -> sp.Expr:
    return N.as_expr().subs(p, p - t) / D.as_expr().subs(p, p - t)


def _value(c: sp.Expr) -> sp.Rational:
    return sp.Rational(str(sp.N(c, _DIGITS)))


def _between(lo: sp.Rational, hi: sp.Rational) -> sp.Rational:
    """A rational strictly between the 50-digit values of two consecutive candidates."""
    if hi - lo <= abs(hi) * sp.Rational(1, 10 ** (_DIGITS - 10)):
        raise ConvergenceError(f"two candidate abscissae agree to {_DIGITS - 10} digits ({sp.N(hi, 20)})")
    return (lo + hi) / 2


def _ordered_candidates(N: sp.Poly, D: sp.Poly, p: sp.Symbol) -> list:
    """``(root, value)`` of the distinct positive roots (exact, with their 50-digit rational values, ascending) of
    the polynomials that vanish at every boundary ``rho``."""
    r, y, x = sp.Dummy("rho"), sp.Dummy("y"), sp.Dummy("x")
    polys = []
    for F in (N, D):
        if F.degree() > 0:
            f = F.as_expr()
            polys.append(sp.Poly(sp.resultant(f.subs(p, y), f.subs(p, -2 * r - y), y), r))
    n, d = N.as_expr().subs(p, p - r), D.as_expr().subs(p, p - r)
    even = sp.expand(n * d.subs(p, -p) + n.subs(p, -p) * d)  # 2 Re(N D*) at p = iω: even in p
    E = sp.Poly(sp.expand(even.subs(p, sp.sqrt(-x))), x)
    E = sp.Poly(sp.sqf_part(E.as_expr(), x, r), x)
    polys += [sp.Poly(E.LC(), r), sp.Poly(E.as_expr().subs(x, 0), r)]
    if E.degree() > 1:
        polys.append(sp.Poly(sp.discriminant(E.as_expr(), x), r))
    polys = [_rational_multiple(P_, r) for P_ in polys]
    factors = {f.monic() for P_ in polys if not P_.is_zero and P_.degree() > 0 for f, _ in P_.factor_list()[1]}
    roots = [(c, _value(c)) for f in factors for c in f.real_roots() if c.is_positive]
    return sorted(roots, key=lambda rv: rv[1])


def _rational_multiple(P_: sp.Poly, r: sp.Symbol) -> sp.Poly:
    """``P_`` itself over the rationals; over an algebraic field its norm, a rational polynomial holding every
    root of ``P_`` (and those of its conjugates, harmless extra candidates)."""
    P_ = sp.Poly(P_.as_expr(), r, extension=True)
    return P_.norm() if P_.domain.is_AlgebraicField else P_


def _shift_elements(net: OnePort, rho: sp.Expr) -> OnePort:
    """Replace ``p*`` by ``p + rho``: L -> L + R(rho L), C -> C | R(1/(rho C)), R unchanged."""
    if isinstance(net, Resistor):
        return net
    if isinstance(net, Inductor):
        return Series((net, Resistor(_clean(rho * net.L))))
    if isinstance(net, Capacitor):
        return Parallel((net, Resistor(_clean(1 / (rho * net.C)))))
    if isinstance(net, Series):
        return Series(tuple(_shift_elements(part, rho) for part in net.parts))
    if isinstance(net, Parallel):
        return Parallel(tuple(_shift_elements(part, rho) for part in net.parts))
    kind = "a Brune section" if isinstance(net, BruneSection) else type(net).__name__
    if isinstance(net, Impedance | BruneSection):  # pragma: no cover - Bott–Duffin emits R, L, C only
        raise ParameterError(f"cannot shift {kind}: the M-function realisation needs R, L, C only")
    raise ParameterError(f"unknown network element {kind}")  # pragma: no cover


@validated
def m_function_synthesis(Z: Any, rho: Any = None, p: sp.Symbol = P, *, max_degree: int | None = None) -> OnePort:
    """Realise an M-function (Min Nai-da) without mutual inductance and without lossless L or C.

    Bulgakov (1954), §9.24, eqs. (9.274)–(9.276): ``Z*(p*) = Z(p* - rho)`` is positive real; its Bott–Duffin
    realisation with ``p* = p + rho`` gives every inductor ``L`` a series resistance ``rho L`` and every capacitor
    ``C`` a parallel resistance ``1/(rho C)``, so ``R_L/L = 1/(R_C C) = rho``.

    Parameters
    ----------
    Z : SymPy expression
        Rational function of ``p`` with numeric coefficients.
    rho : number or SymPy expression, optional
        Positive abscissa: ``Re Z(p) >= 0`` must hold for ``Re p >= -rho`` (test it with :func:`is_m_function`).
        Default: the largest such ``rho``, :func:`m_abscissa` (exact; an irrational one makes the element values
        algebraic numbers).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.
    max_degree : int, optional
        Largest degree over the rationals of the number field holding the exact element values, as in
        :func:`bott_duffin_synthesis` (default 64 with python-flint, 8 without).

    Returns
    -------
    OnePort
        A series/parallel tree of positive R, L, C whose impedance equals ``Z`` exactly.

    Raises
    ------
    ParameterError
        When ``rho`` is not a positive number or ``Z(p - rho)`` is not positive real (the message names the
        failed condition, so ``rho`` is too large or ``Z`` is no M-function).
    ModelError
        When the Bott–Duffin realisation of ``Z(p - rho)`` needs a number field of degree above ``max_degree``.

    Examples
    --------
    Bulgakov (1954), §9.24, Ex. 1: ``(a0 p + a1)/(b0 p + b1)`` is an M-function for ``rho < min(b1/b0, a1/a0)``.

    >>> import sympy as sp
    >>> from symosc.networks import m_function_synthesis
    >>> p = sp.Symbol("p")
    >>> m_function_synthesis((2*p + 3) / (p + 4), 1, p)
    R(1/3) + ((L(5/9) + R(5/9)) | R(5/3))

    Without ``rho`` the largest one is used, here ``m_abscissa = 3/2``:

    >>> m_function_synthesis((2*p + 3) / (p + 4), p=p)
    (L(4/5) + R(6/5)) | R(2)

    See Also
    --------
    m_abscissa, is_m_function, bott_duffin_synthesis, richards_function
    """
    from ._synthesis import synthesize

    if max_degree is not None:
        max_degree = check_int("max_degree", max_degree, minimum=1)
    p, N, D = synthesis_target(Z, p)
    if rho is None:
        rho = m_abscissa(N.as_expr() / D.as_expr(), p)
        if rho == 0:
            raise ParameterError(
                "Z is an M-function for no rho > 0 (m_abscissa(Z) = 0: a pole or zero on the imaginary axis, or "
                "Re Z(iω) reaches zero); realise it with bott_duffin_synthesis (Bulgakov (1954), §9.24)"
            )
        if rho == sp.oo:  # a constant: a resistor, whatever rho
            rho = sp.Integer(1)
    rho = as_expr(rho, "rho")
    if rho.free_symbols or not rho.is_extended_real or not rho.is_positive:
        raise ParameterError(f"rho must be a positive real number, got {rho}")
    rho = sp.nsimplify(rho) if isinstance(rho, sp.Float) else rho
    shifted = sp.cancel(N.as_expr().subs(p, p - rho) / D.as_expr().subs(p, p - rho))
    verdict = positive_real_report(shifted, p)
    if not verdict:
        raise ParameterError(
            f"Z(p - rho) is not positive real for rho = {rho} ({verdict.failed}: {verdict.detail}); Z is not an "
            "M-function with this rho (Bulgakov (1954), §9.24): try a smaller rho, see is_m_function"
        )
    return _shift_elements(synthesize(shifted, p, "bott_duffin", max_degree), rho)  # PR already checked above
