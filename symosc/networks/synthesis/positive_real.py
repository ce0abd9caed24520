"""Positive-real (Brune) functions: the test of Bulgakov (1954), §9.22–9.24, Theorem V.

``Z(p)`` is positive real when it is real for real ``p`` and ``Re Z > 0`` for ``Re p > 0``.  For a rational ``Z``
this holds iff (a) ``Z`` has no poles in ``Re p > 0``, (b) its poles on the imaginary axis (including 0 and
infinity) are simple with real positive residues, and (c) ``Re Z(iω) >= 0`` for all real ``ω``.  Condition (c) is
decided exactly by counting the real roots of the numerator of ``Re Z(iω)`` (a polynomial in ``ω²``) with Sturm
sequences.

>>> import sympy as sp
>>> from symosc.networks import is_positive_real
>>> p = sp.Symbol("p")
>>> is_positive_real((p**2 + p + 1) / (p**2 + p + 4), p), is_positive_real((p**2 + 1) / (p**2 + p + 4), p)
(True, False)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from ...linear import hurwitz
from ...operational._rational import exactify
from .._util import P, as_expr, as_symbol, rational_function

__all__ = [
    "PositiveRealReport",
    "biquadratic_is_positive_real",
    "is_m_function",
    "is_positive_real",
    "positive_real_report",
    "real_part_on_axis",
]

_DIGITS = 60


@dataclass(frozen=True)
class PositiveRealReport(SymPyPrintable):
    """Outcome of the positive-real test: ``failed`` names the violated condition (``None`` when PR).

    The conditions are those of Bulgakov (1954), §9.23, Theorem V.

    Attributes
    ----------
    is_positive_real : bool
        The verdict.
    failed : str or None
        The violated condition ("real coefficients", "pole in the right half-plane", "residue at an imaginary-axis
        pole", ...); None when ``Z`` is positive real.
    detail : str
        What was found (a pole, a residue, a frequency where ``Re Z(iω) < 0``); empty when positive real.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import positive_real_report
    >>> p = sp.Symbol("p")
    >>> passive = positive_real_report((p + 2) / (p + 1), p)
    >>> passive
    PositiveRealReport(positive real)
    >>> print(sp.latex(passive))
    \\text{positive real}

    See Also
    --------
    positive_real_report, is_positive_real
    """

    is_positive_real: bool
    failed: str | None = None
    detail: str = ""

    def __bool__(self) -> bool:
        return self.is_positive_real

    def __repr__(self) -> str:
        if self.is_positive_real:
            return "PositiveRealReport(positive real)"
        return f"PositiveRealReport(not positive real: {self.failed}; {self.detail})"

    def _repr_latex_(self) -> str:
        """The verdict as text; the violated condition and its detail when not positive real."""
        from ..._printing import latex_value

        if self.is_positive_real:
            return f"${latex_value('positive real')}$"
        return f"${latex_value('not positive real')}:\\ {latex_value(f'{self.failed}; {self.detail}')}$"


@validated
def real_part_on_axis(Z: Any, p: sp.Symbol = P) -> tuple[sp.Poly, sp.Poly]:
    """``Re Z(iω) = E(x)/Q(x)`` with ``x = ω²``: returns the polynomials ``(E, Q)`` in a dummy ``x``.

    ``E`` is the even part ``(N(p)D(-p) + N(-p)D(p))/2`` and ``Q = D(p)D(-p)``, both at ``p² = -x``.

    Parameters
    ----------
    Z : SymPy expression
        Rational function of ``p`` with real numeric coefficients (symbols other than ``p`` must be substituted).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import real_part_on_axis
    >>> p = sp.Symbol("p")
    >>> E, Q = real_part_on_axis((p + 2) / (p + 1), p)
    >>> E.as_expr(), Q.as_expr()
    (_x + 2, _x + 1)

    See Also
    --------
    is_positive_real
    """
    N, D = rational_function(Z, as_symbol(p))
    x = sp.Dummy("x")
    ev = sp.expand((N.as_expr() * D.as_expr().subs(p, -p) + N.as_expr().subs(p, -p) * D.as_expr()) / 2)
    q = sp.expand(D.as_expr() * D.as_expr().subs(p, -p))
    E = sp.Poly(sp.expand(ev.subs(p, sp.sqrt(-x))), x, extension=True)
    Q = sp.Poly(sp.expand(q.subs(p, sp.sqrt(-x))), x, extension=True)
    return E, Q


def _fail(name: str, detail: str) -> PositiveRealReport:
    return PositiveRealReport(False, name, detail)


@validated
def positive_real_report(Z: Any, p: sp.Symbol = P) -> PositiveRealReport:
    """Test ``Z`` for positive realness and say which condition fails (Bulgakov (1954), §9.23, Theorem V).

    Parameters
    ----------
    Z : SymPy expression
        Rational function of ``p`` with real (numeric) coefficients.
    p : sympy.Symbol, optional
        Operator variable of ``Z``, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Returns
    -------
    PositiveRealReport
        Truthy when ``Z`` is positive real; otherwise ``failed`` is one of ``"real coefficients"``,
        ``"degree difference"``, ``"pole in the right half-plane"``, ``"multiple pole on the imaginary axis"``,
        ``"residue at an imaginary-axis pole"``, ``"negative real part on the imaginary axis"``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import positive_real_report
    >>> p = sp.Symbol("p")
    >>> positive_real_report((p**2 + 1) / (p**2 + p + 4), p).failed
    'negative real part on the imaginary axis'
    >>> positive_real_report(1 / (p**2 + 1), p).failed
    'degree difference'

    See Also
    --------
    is_positive_real, real_part_on_axis
    """
    p = as_symbol(p)
    N, D = rational_function(exactify(Z), p)  # floats taken at their exact binary values: Sturm counts stay exact
    free = (N.free_symbols | D.free_symbols) - {p}
    if free:
        raise ParameterError(f"Z must have numeric coefficients for the positive-real test; free symbols: {free}")
    if any(c.is_extended_real is False for c in N.all_coeffs() + D.all_coeffs()):
        return _fail("real coefficients", "Z(p) is not real for real p")
    if N.is_zero:
        return PositiveRealReport(True)
    dn, dd = N.degree(), D.degree()
    if abs(dn - dd) > 1:
        return _fail("degree difference", f"degrees of numerator and denominator are {dn} and {dd} (differ by > 1)")
    if dn == dd + 1 and not (N.LC() / D.LC()).is_positive:
        return _fail("residue at an imaginary-axis pole", "the residue at infinity (leading ratio) is not positive")
    if dd == dn + 1 and not (N.LC() / D.LC()).is_positive:
        return _fail("degree difference", "the zero at infinity has a negative derivative")
    # poles: split D into the part with roots symmetric about the imaginary axis and a strictly Hurwitz rest
    Dm = sp.Poly(D.as_expr().subs(p, -p), p)
    G = sp.gcd(D, Dm)
    rest = sp.div(D, G)[0]
    if rest.degree() > 0 and hurwitz(rest).stable is not True:
        return _fail("pole in the right half-plane", f"the denominator factor {rest.as_expr()} is not Hurwitz")
    if G.degree() > 0:
        report = _axis_poles(N, D, G, p)
        if report is not None:
            return report
    E, _ = real_part_on_axis(N.as_expr() / D.as_expr(), p)
    bad = _negative_point(E)
    if bad is not None:
        return _fail("negative real part on the imaginary axis", f"Re Z(iω) < 0 at ω² = {bad}")
    return PositiveRealReport(True)


def _axis_poles(N: sp.Poly, D: sp.Poly, G: sp.Poly, p: sp.Symbol) -> PositiveRealReport | None:
    if not G.is_sqf or sp.gcd(G, sp.div(D, G)[0]).degree() > 0:
        return _fail("multiple pole on the imaginary axis", f"the factor {G.as_expr()} of the denominator repeats")
    x = sp.Dummy("x")
    g = G.as_expr()
    k = 0
    while sp.Poly(g, p).eval(0) == 0:
        g, k = sp.cancel(g / p), k + 1
    H = sp.Poly(sp.expand(g.subs(p, sp.sqrt(-x))), x, extension=True)  # roots x = ω² > 0 expected
    if H.degree() > 0 and H.count_roots(0, None) - (1 if H.eval(0) == 0 else 0) != H.degree():
        return _fail("pole in the right half-plane", f"the denominator factor {G.as_expr()} has roots off the axis")
    dD = D.diff(p)
    if k:
        res = N.eval(0) / dD.eval(0)
        if not res.is_positive:
            return _fail("residue at an imaginary-axis pole", f"residue {res} at p = 0 is not positive")
    if H.degree() > 0:
        for root in sp.Poly(H, x).all_roots():
            w = sp.sqrt(root)
            res = sp.N(N.as_expr().subs(p, sp.I * w) / dD.as_expr().subs(p, sp.I * w), _DIGITS)
            re, im = sp.re(res), sp.im(res)
            if re <= 0 or abs(im) > sp.Float(10) ** (-_DIGITS // 2) * abs(res):
                return _fail(
                    "residue at an imaginary-axis pole", f"residue {sp.N(res, 8)} at p = ±i·{sp.N(w, 8)} not real > 0"
                )
    return None


def _negative_point(E: sp.Poly) -> Any:
    """A point ``x > 0`` with ``E(x) < 0``, or None when ``E >= 0`` on ``x >= 0`` (exact Sturm counting)."""
    if E.is_zero:
        return None
    for factor, mult in E.sqf_list()[1]:
        if mult % 2 == 0:
            continue
        n_pos = factor.count_roots(0, None) - (1 if factor.eval(0) == 0 else 0)
        if n_pos:
            # the sign changes at a positive root: find a negative point next to one of them
            roots = [r for r in factor.real_roots() if r > 0]
            for r in roots:
                for delta in (sp.Rational(1, 10**3), sp.Rational(1, 10**6), sp.Rational(1, 10**9)):
                    for cand in (sp.nsimplify(sp.N(r, 30)) - delta, sp.nsimplify(sp.N(r, 30)) + delta):
                        if cand > 0 and E.eval(cand) < 0:
                            return cand
            return roots[0]
    # no sign change on (0, oo): check the sign at a point that is not a root
    probe = sp.Integer(1)
    while E.eval(probe) == 0:
        probe += 1
    return None if E.eval(probe) > 0 else probe


@validated
def is_positive_real(Z: Any, p: sp.Symbol = P) -> bool:
    """True when the rational function ``Z(p)`` is positive real (a Brune function), Bulgakov (1954), §9.22–9.23.

    Parameters
    ----------
    Z : SymPy expression
        Rational function of ``p`` with real numeric coefficients (symbols other than ``p`` must be substituted).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import is_positive_real
    >>> p = sp.Symbol("p")
    >>> is_positive_real(p + 1 / p, p), is_positive_real(p - 1, p)
    (True, False)

    See Also
    --------
    positive_real_report, brune_synthesis
    """
    return bool(positive_real_report(Z, p))


def require_positive_real(Z: Any, p: sp.Symbol, what: str = "Z") -> None:
    """Raise ParameterError naming the failed condition unless ``Z`` is positive real."""
    verdict = positive_real_report(Z, p)
    if not verdict:
        raise ParameterError(
            f"{what} is not positive real ({verdict.failed}: {verdict.detail}); no passive network realises it "
            "(Bulgakov (1954), §9.23, Theorem V)"
        )


@validated
def biquadratic_is_positive_real(a0: Any, a1: Any, a2: Any, b0: Any, b1: Any, b2: Any) -> bool:
    """Test of ``(a0 p² + a1 p + a2)/(b0 p² + b1 p + b2)``: coefficients >= 0 and
    ``a1 b1 >= (sqrt(a0 b2) - sqrt(a2 b0))²`` (Bulgakov (1954), §9.26, eqs. (9.395), (9.530)).

    Parameters
    ----------
    a0 : number or SymPy expression
        Coefficient of ``p²`` in the numerator; a negative coefficient makes the function not positive real.
    a1 : number or SymPy expression
        Coefficient of ``p`` in the numerator; a negative coefficient makes the function not positive real.
    a2 : number or SymPy expression
        Constant term of the numerator; a negative coefficient makes the function not positive real.
    b0 : number or SymPy expression
        Coefficient of ``p²`` in the denominator; a negative coefficient makes the function not positive real.
    b1 : number or SymPy expression
        Coefficient of ``p`` in the denominator; a negative coefficient makes the function not positive real.
    b2 : number or SymPy expression
        Constant term of the denominator; a negative coefficient makes the function not positive real.

    Examples
    --------
    >>> from symosc.networks import biquadratic_is_positive_real
    >>> biquadratic_is_positive_real(1, 1, 1, 1, 1, 4), biquadratic_is_positive_real(1, 0, 1, 1, 1, 4)
    (True, False)

    See Also
    --------
    is_positive_real
    """
    names = ("a0", "a1", "a2", "b0", "b1", "b2")
    a = [as_expr(v, n) for v, n in zip((a0, a1, a2, b0, b1, b2), names, strict=True)]
    for v, n in zip(a, names, strict=True):
        if v.is_extended_real is False:
            raise ParameterError(f"{n} must be a real coefficient, got {v}")
    if all(v.is_zero for v in a[3:]):
        raise ParameterError("b0, b1 and b2 are all zero: the denominator must not vanish identically")
    if any(v.is_negative for v in a):
        return False
    a0, a1, a2, b0, b1, b2 = a
    verdict = sp.simplify(a1 * b1 - (sp.sqrt(a0 * b2) - sp.sqrt(a2 * b0)) ** 2) >= 0
    undecided = [n for v, n in zip(a, names, strict=True) if v.is_nonnegative is None]
    if undecided or verdict not in (sp.true, sp.false):
        raise ParameterError(
            f"{', '.join(names)} must be numbers, or symbols declared nonnegative for which the condition "
            f"simplifies: {verdict} is undecided"
            + (f" and the signs of {', '.join(undecided)} are unknown" if undecided else "")
        )
    return bool(verdict)


@validated
def is_m_function(Z: Any, rho: Any, p: sp.Symbol = P) -> bool:
    """Min Nai-da's M-function test: ``Z(p - rho)`` is positive real (Bulgakov (1954), §9.24, eqs. (9.274)–(9.276)).

    Such ``Z`` is realisable without mutual inductance, with every inductor ``L`` carrying a series resistance
    ``R_L`` and every capacitor ``C`` a parallel conductance, provided ``rho < min(R_L/L, 1/(R_C C))``.

    Parameters
    ----------
    Z : SymPy expression
        Rational function of ``p`` with real numeric coefficients (symbols other than ``p`` must be substituted).
    rho : number or SymPy expression
        The abscissa shift, which must be a non-negative number: the test is whether ``Z(p - rho)`` is positive real.
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import is_m_function
    >>> p = sp.Symbol("p")
    >>> Z = (p + 3) / (p + 2)                      # Ex. 1: rho < min(b1/b0, a1/a0) = 2
    >>> is_m_function(Z, 1, p), is_m_function(Z, 2.5, p)
    (True, False)

    See Also
    --------
    is_positive_real
    """
    rho = as_expr(rho, "rho")
    if not rho.is_nonnegative:
        raise ParameterError(f"rho must be a non-negative number, got {rho}")
    return is_positive_real(sp.cancel(as_expr(Z, "Z").subs(p, p - sp.nsimplify(rho))), p)
