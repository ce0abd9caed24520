"""Theorems of Carson's operational calculus (Bulgakov §2.4–§2.17), as operations on images.

Every function takes a Carson image ``X(p)`` and returns the image of the transformed original, so that
``inverse_carson(theorem(carson(x)))`` is the transformed ``x``.  The validity conditions of the limit theorems are
checked, not assumed.
"""

from __future__ import annotations

from collections.abc import Sequence

import sympy as sp

from ..errors import ModelError, ParameterError
from ._rational import as_rational, distinct_roots

__all__ = [
    "advance",
    "convolution",
    "delay",
    "differentiate_image",
    "differentiate_original",
    "duhamel",
    "final_value",
    "finite_difference",
    "finite_sum",
    "initial_value",
    "integral_to_infinity",
    "integrate_original",
    "product_of_originals",
    "shift",
    "similarity",
]


def shift(image, p: sp.Symbol, lam) -> sp.Expr:
    """Damping theorem (2.38): ``p/(p + lam) X(p + lam) <-> exp(-lam t) x(t)``.

    >>> import sympy as sp
    >>> p, a = sp.symbols("p a")
    >>> sp.factor(shift(1 / p, p, a))     # t  ->  t exp(-a t)
    p/(a + p)**2
    """
    return sp.cancel(p / (p + lam) * sp.sympify(image).subs(p, p + lam))


def delay(image, p: sp.Symbol, tau) -> sp.Expr:
    """Delay theorem (2.26a): ``exp(-p tau) X(p) <-> x(t - tau) 1(t - tau)`` for ``tau >= 0``.

    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> delay(1 / p, p, 2)
    exp(-2*p)/p
    """
    tau = sp.sympify(tau)
    if tau.is_negative:
        raise ParameterError(f"delay tau must be >= 0, got {tau}; for an advance use advance()")
    return sp.exp(-p * tau) * sp.sympify(image)


def advance(image, p: sp.Symbol, tau, head) -> sp.Expr:
    """Advance theorem (2.27–2.28): ``exp(p tau) [X(p) - alpha(p)] <-> x(t + tau)``.

    ``head`` is ``alpha(p) = p Integral(x(t) exp(-p t), (t, 0, tau))``, the Carson image of the piece of ``x`` on
    ``(0, tau)`` that the advance removes; pass it as an expression in ``p``, or pass ``(x, t)`` to have it integrated.

    >>> import sympy as sp
    >>> p, t = sp.symbols("p t", positive=True)
    >>> sp.simplify(advance(p / (p + 1), p, 1, (sp.exp(-t), t)))    # exp(-(t+1))
    p*exp(-1)/(p + 1)
    """
    tau = sp.sympify(tau)
    if tau.is_negative:
        raise ParameterError(f"advance tau must be >= 0, got {tau}")
    if isinstance(head, tuple):
        x, t = head
        head = p * sp.integrate(x * sp.exp(-p * t), (t, 0, tau))
    return sp.exp(p * tau) * (sp.sympify(image) - head)


def finite_sum(image, p: sp.Symbol, tau) -> sp.Expr:
    """Image of ``sum_{j=1}^{floor(t/tau)} x(t - j tau)`` (2.31): ``X(p)/(exp(p tau) - 1)``.

    >>> import sympy as sp
    >>> p, tau = sp.symbols("p tau", positive=True)
    >>> finite_sum(sp.Integer(1), p, tau)       # floor(t/tau), (2.62)
    1/(exp(p*tau) - 1)
    """
    tau = sp.sympify(tau)
    if tau.is_positive is False:
        raise ParameterError(f"finite_sum needs tau > 0, got {tau}")
    return sp.sympify(image) / (sp.exp(p * tau) - 1)


def finite_difference(image, p: sp.Symbol, tau, head) -> sp.Expr:
    """Image of ``Delta x(t) = x(t + tau) - x(t)`` (2.34): ``(exp(p tau) - 1) X(p) - exp(p tau) alpha(p)``.

    ``head`` is ``alpha(p) = p Integral(x exp(-p t), (t, 0, tau))`` or ``(x, t)`` to have it integrated (as in
    :func:`advance`).

    >>> import sympy as sp
    >>> p, t = sp.symbols("p t", positive=True)
    >>> sp.simplify(finite_difference(1 / p, p, 1, (t, t)))     # Delta t = 1
    1
    """
    tau = sp.sympify(tau)
    if tau.is_positive is False:
        raise ParameterError(f"finite_difference needs tau > 0, got {tau}")
    if isinstance(head, tuple):
        x, t = head
        head = p * sp.integrate(x * sp.exp(-p * t), (t, 0, tau))
    return (sp.exp(p * tau) - 1) * sp.sympify(image) - sp.exp(p * tau) * head


def similarity(image, p: sp.Symbol, a) -> sp.Expr:
    """Similarity theorem (2.46): ``X(p/a) <-> x(a t)``, ``a > 0``.

    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> similarity(p / (p**2 + 1), p, 3)     # sin t -> sin 3t
    p/(3*(p**2/9 + 1))
    """
    a = sp.sympify(a)
    if a.is_positive is False:
        raise ParameterError(f"similarity needs a > 0, got {a}")
    return sp.sympify(image).subs(p, p / a)


def differentiate_original(image, p: sp.Symbol, initial: Sequence = (), order: int | None = None) -> sp.Expr:
    """Image of the ``m``-th derivative (2.18): ``p**m X - p**m x(0) - p**(m-1) x'(0) - ... - p x^(m-1)(0)``.

    ``initial`` holds ``x(0+), x'(0+), ..., x^(m-1)(0+)``; ``order`` defaults to ``len(initial)`` (with zero data
    pass ``order`` alone, giving (2.20)).

    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> sp.cancel(differentiate_original(p**2 / (p**2 + 1), p, [1]))   # (cos t)' = -sin t
    -p/(p**2 + 1)
    """
    m = len(initial) if order is None else int(order)
    if m < 0:
        raise ParameterError("order must be >= 0")
    if len(initial) > m:
        raise ParameterError(f"{len(initial)} initial values given for a derivative of order {m}")
    init = list(initial) + [0] * (m - len(initial))
    return p**m * sp.sympify(image) - sp.Add(*[p ** (m - k) * init[k] for k in range(m)])


def integrate_original(image, p: sp.Symbol, times: int = 1, constant=0) -> sp.Expr:
    """Image of the ``m``-fold integral from 0 (2.11–2.12): ``X(p)/p**m``; with ``constant`` = value at 0 of an
    indefinite (single) integral, ``X/p + constant`` (2.14).

    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> integrate_original(sp.Integer(1), p, 2)    # 1 -> t**2/2
    p**(-2)
    """
    if times < 1:
        raise ParameterError("times must be >= 1")
    if constant != 0 and times != 1:
        raise ParameterError("an integration constant is supported for a single integration only")
    return sp.sympify(image) / p**times + constant


def differentiate_image(image, p: sp.Symbol, order: int = 1) -> sp.Expr:
    """Image of ``t**m x(t)`` (2.23): ``(-1)**m p d^m/dp^m [X(p)/p]``.

    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> sp.factor(differentiate_image(p / (p + 1), p, 2))    # t**2 exp(-t)
    2*p/(p + 1)**3
    """
    if order < 0:
        raise ParameterError("order must be >= 0")
    return sp.cancel((-1) ** order * p * sp.diff(sp.sympify(image) / p, p, order))


def convolution(image_x, image_y, p: sp.Symbol) -> sp.Expr:
    """Image of ``Integral(x(u) y(t - u), (u, 0, t))`` (2.43): ``X(p) Y(p)/p``.

    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> convolution(sp.Integer(1), sp.Integer(1), p)      # 1 * 1 = t
    1/p
    """
    return sp.sympify(image_x) * sp.sympify(image_y) / p


def duhamel(image_x, image_y, p: sp.Symbol) -> sp.Expr:
    """Image of ``d/dt Integral(x(u) y(t - u), (u, 0, t))`` (2.45, Duhamel): ``X(p) Y(p)``."""
    return sp.sympify(image_x) * sp.sympify(image_y)


def initial_value(image, p: sp.Symbol) -> sp.Expr:
    """``x(0+) = lim_{p -> oo} X(p)`` (2.47).

    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> initial_value(p**2 / (p**2 + 4), p)
    1
    """
    value = sp.limit(sp.sympify(image), p, sp.oo)
    if value.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or isinstance(value, sp.AccumBounds):
        raise ModelError(f"X(p) has no finite limit at p -> oo ({value}): the original is not a function at t = 0+")
    return value


def _poles_checked(expr, p, what: str) -> list[tuple[sp.Expr, int]]:
    if not sp.sympify(expr).is_rational_function(p):
        raise ModelError(f"{what}: the pole locations of a non-rational image cannot be checked; invert it instead")
    _, den = as_rational(expr, p)
    return distinct_roots(den)


def final_value(image, p: sp.Symbol) -> sp.Expr:
    """``x(oo) = X(0)`` (2.49), *only* when the limit exists.

    The theorem holds when every pole of ``X(p)/p`` lies in the open left half-plane except a simple pole at
    ``p = 0``.  Otherwise (a pole with ``Re >= 0`` other than a simple one at 0: growth, undamped oscillation, a
    ramp) :class:`ModelError` is raised instead of returning the meaningless ``X(0)``.

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> final_value(2 / (p + 1), p)      # 2 (1 - exp(-t))
    2
    >>> final_value(p**2 / (p**2 + 1), p)
    Traceback (most recent call last):
    ...
    symosc.errors.ModelError: final value theorem not applicable: poles -I, I of X(p)/p in Re p >= 0 (x(t) has no limit)
    """
    image = sp.sympify(image)
    bad = []
    for root, mult in _poles_checked(image / p, p, "final_value"):
        re = sp.re(sp.N(root)) if root.is_number else sp.re(root)
        if root == 0 and mult == 1:
            continue
        if re.is_negative:
            continue
        if re.is_number or re.is_nonnegative:
            bad.append(root if mult == 1 else sp.Symbol(f"{root} (multiplicity {mult})"))
        else:
            raise ModelError(f"final_value: cannot decide the sign of Re({root}); substitute numbers")
    if bad:
        raise ModelError(
            "final value theorem not applicable: poles "
            + ", ".join(str(b) for b in bad)
            + " of X(p)/p in Re p >= 0 (x(t) has no limit)"
        )
    return sp.cancel(image).subs(p, 0)


def integral_to_infinity(image, p: sp.Symbol) -> sp.Expr:
    """``Integral(x, (t, 0, oo)) = [X(p)/p]_{p=0}`` (2.48), when every pole of ``X/p`` is in ``Re p < 0``.

    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> integral_to_infinity(p / (p + 2), p)     # exp(-2 t)
    1/2
    """
    image = sp.sympify(image)
    for root, _ in _poles_checked(image / p, p, "integral_to_infinity"):
        re = sp.re(sp.N(root)) if root.is_number else sp.re(root)
        if not re.is_negative:
            raise ModelError(
                f"integral_to_infinity: X(p)/p has the pole {root} with Re >= 0 (or undecidable sign); "
                "the integral does not converge (abscissa of convergence sigma_c >= 0)"
            )
    return sp.cancel(image / p).subs(p, 0)


def product_of_originals(image_x, image_y, p: sp.Symbol) -> sp.Expr:
    """Image of the product ``x(t) y(t)`` (Bulgakov 2.143–2.144) for a rational ``Y``:

        p * sum Res_q [X(p - q) Y(q) / ((p - q) q)]   over the poles of Y(q)/q.

    ``X`` may be any image analytic for ``Re p`` large enough.

    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> sp.factor(product_of_originals(1 / p, p / (p + 1), p))     # t * exp(-t)
    p/(p + 1)**2
    """
    q = sp.Dummy("q")
    y_over_q = sp.sympify(image_y).subs(p, q) / q
    if not y_over_q.is_rational_function(q):
        raise ModelError("product_of_originals needs a rational image Y (its poles are summed)")
    num, den = as_rational(y_over_q, q)
    g_x = sp.sympify(image_x).subs(p, p - q) / (p - q)
    lead = den.LC()
    roots = distinct_roots(den)
    total = sp.S.Zero
    for i, (root, mult) in enumerate(roots):
        others = sp.Mul(*[(q - r) ** m for j, (r, m) in enumerate(roots) if j != i])
        g = g_x * num.as_expr() / (lead * others)
        total += sp.diff(g, q, mult - 1).subs(q, root) / sp.factorial(mult - 1)
    out = p * total
    return sp.factor(sp.cancel(out), p) if out.is_rational_function(p) else sp.simplify(out)
