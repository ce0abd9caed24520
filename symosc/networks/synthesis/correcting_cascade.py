"""A correcting network as a cascade of first- and second-order constant-resistance links (Bulgakov (1954), §9.37).

``X = P/Q`` regular in the closed right half-plane is factored into first- and second-order fractions
``P_j/Q_j``; each, divided by a flat factor ``k_j >= max |P_j/Q_j(iω)|``, is one lattice link with the common
resistance ``W``, and an amplifier of gain ``Π k_j`` (times the leading constant) restores ``X`` (9.521)–(9.524).

>>> import sympy as sp
>>> from symosc.networks import correcting_cascade
>>> p = sp.Symbol("p")
>>> net = correcting_cascade(1 / ((p + 1) * (p + 2) * (p + 3)), W=1)
>>> len(net.links), net.gain
(3, 1/6)
>>> sp.cancel(net.realized_transfer() - net.transfer)
0
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from .._exact.polynomial_tests import flat_factor
from .._util import P, as_symbol, element_value
from ..ports.fourpoles import FourPole
from .correcting import CorrectingLink, _check_transfer, correcting_link

__all__ = ["CorrectingCascade", "correcting_cascade"]


@dataclass(frozen=True)
class CorrectingCascade(SymPyPrintable):
    """Constant-resistance links in cascade and the gain that restores the requested transfer.

    ``transfer = gain * Π link.transfer``; ``gain > 1`` needs an amplifier (the book's compensating amplifier of
    gain ``exp(a0 + Σ a_rj)``), ``gain < 1`` an attenuator.

    Attributes
    ----------
    transfer : SymPy expression
        The requested transfer ``X(p)``.
    W : SymPy expression
        The common constant resistance of the links.
    links : tuple of CorrectingLink
        The links in cascade order, each of first or second order.
    gain : SymPy expression
        The flat factor ``X / Π X_j`` an amplifier (above 1) or attenuator (below 1) must supply.
    p : sympy.Symbol
        Operator variable of the transfers.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import correcting_cascade
    >>> p = sp.Symbol("p")
    >>> net = correcting_cascade((p**2 + 1) / ((p + 1) * (p + 2)), W=1)
    >>> net.links[0].transfer, net.gain
    ((p**2 + 1)/(p**2 + 3*p + 2), 1)

    See Also
    --------
    correcting_cascade, correcting_link
    """

    transfer: sp.Expr
    W: sp.Expr
    links: tuple
    gain: sp.Expr
    p: sp.Symbol = P

    @functools.cached_property
    def four_pole(self) -> FourPole:
        """The cascade's chain matrix (the product of the links' chain matrices)."""
        A = sp.eye(2)
        for link in self.links:
            A = (A * link.four_pole.chain).applyfunc(sp.cancel)
        return FourPole(A, self.p, name="correcting cascade")

    def realized_transfer(self) -> sp.Expr:
        """``gain * Ey/Ex`` of the cascade closed by ``W``, from its chain matrix."""
        A = self.four_pole.chain
        return sp.cancel(self.gain / (A[0, 0] + A[0, 1] / self.W))

    def __repr__(self) -> str:
        links = ", ".join(sp.sstr(link.transfer) for link in self.links)
        return f"CorrectingCascade(X = {sp.sstr(self.transfer)}, W = {self.W}; links: {links}; gain = {self.gain})"

    def _sympystr(self, printer: Any) -> str:
        return repr(self)

    def _latex(self, printer: Any) -> str:
        factors = r" \cdot ".join(r"\left(" + sp.latex(link.transfer) + r"\right)" for link in self.links)
        return rf"X(p) = {sp.latex(self.gain)} \cdot {factors}"

    def _repr_latex_(self) -> str:
        return f"${self._latex(None)}$"


def _factors(poly: sp.Poly, p: sp.Symbol, name: str) -> tuple[sp.Expr, list[sp.Expr]]:
    const, pairs = sp.factor_list(poly.as_expr(), p)
    out = []
    for factor, mult in pairs:
        d = sp.Poly(factor, p).degree()
        if d > 2:
            raise ParameterError(
                f"the {name} of X has an irreducible factor of degree {d} over the rationals ({factor}): its roots "
                "are irrational and the links of §9.38–9.39 would need them exactly; give X with a factored "
                f"{name} (first- and second-order factors with rational coefficients)"
            )
        out += [factor] * mult
    return const, out


def _pair(num: list, den: list, p: sp.Symbol) -> list[tuple[sp.Expr, sp.Expr]]:
    """Distribute numerator factors over denominator slots so that no section has more zeros than poles."""
    deg = {f: sp.Poly(f, p).degree() for f in num + den}
    slots = [[d, [], deg[d]] for d in sorted(den, key=lambda f: -deg[f])]  # [denominator, numerators, room]
    for f in sorted(num, key=lambda f: -deg[f]):
        target = next((s for s in slots if s[2] == deg[f] and not s[1]), None) or next(
            (s for s in slots if s[2] >= deg[f]), None
        )
        if target is None:  # an irreducible quadratic over two linear denominators: merge them
            lin = [s for s in slots if deg[s[0]] == 1 and not s[1]][:2]
            merged = [sp.expand(lin[0][0] * lin[1][0]), [], 2]
            slots = [s for s in slots if s not in lin] + [merged]
            target = merged
        target[1].append(f)
        target[2] -= deg[f]
    return [(sp.Mul(*nums), d) for d, nums, _ in slots]


@validated
def correcting_cascade(X: Any, W: Any = 1, p: sp.Symbol = P, *, method: str = "auto") -> CorrectingCascade:
    """Realise ``X(p)`` as a cascade of first- and second-order constant-resistance links (Bulgakov (1954), §9.37).

    Parameters
    ----------
    X : SymPy expression
        Rational transfer with numeric coefficients, regular in ``Re p >= 0`` and at infinity; its numerator and
        denominator must split into factors of degree at most 2 over the rationals.
    W : positive number
        The common constant resistance of the links, which must be positive (default 1).
    p : sympy.Symbol, optional
        Operator variable, which must be a SymPy Symbol; the standard symbol ``p`` when omitted.
    method : {"auto", "bott-duffin", "brune"}
        One-port synthesis of the link arms (see :func:`correcting_link`).

    Returns
    -------
    CorrectingCascade
        Links whose transfers ``P_j/(k_j Q_j)`` have ``max |X_j(iω)| <= 1``, with ``k_j = max |P_j/Q_j(iω)|``
        when that is rational (else the six-digit decimal above it), and the gain ``X / Π X_j``.

    Raises
    ------
    ParameterError
        For a pole in ``Re p >= 0``, a transfer not regular at infinity, an irreducible factor of degree above 2.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.networks import correcting_cascade
    >>> p = sp.Symbol("p")
    >>> net = correcting_cascade((p - 1) * (p**2 + 4) / ((p + 1) * (p**2 + 2 * p + 2)), W=600)
    >>> [link.transfer for link in net.links], net.gain
    ([(p**2 + 4)/(2*p**2 + 4*p + 4), (p - 1)/(p + 1)], 2)

    See Also
    --------
    correcting_link, cascade_junctions
    """
    p = as_symbol(p)
    W = element_value(W, "W")
    if not W.is_number:
        raise ParameterError(f"W must be a positive number, got {W}")
    N, D = _check_transfer(X, p, max_degree=None)
    Xe = sp.cancel(N.as_expr() / D.as_expr())
    cN, num = _factors(N, p, "numerator")
    cD, den = _factors(D, p, "denominator")
    links: list[CorrectingLink] = []
    gain = cN / cD
    for n_j, d_j in _pair(num, den, p):
        k = flat_factor(sp.Poly(n_j, p), sp.Poly(d_j, p))
        links.append(correcting_link(n_j / (k * d_j), W, p, method=method))
        gain *= k
    return CorrectingCascade(Xe, W, tuple(links), sp.nsimplify(gain), p)
