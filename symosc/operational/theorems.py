"""Theorems of Carson's operational calculus (Bulgakov §2.4–§2.17), as operations on images.

Every function takes a Carson image ``X(p)`` and returns the image of the transformed original, so that
``inverse_carson(theorem(carson(x)))`` is the transformed ``x``.  The validity conditions of the limit theorems are
checked, not assumed.
"""

from __future__ import annotations

from collections.abc import Sequence

import sympy as sp

from .._deprecation import renamed_keyword
from .._validate import validated
from ..errors import ModelError, ParameterError
from ._rational import as_rational, check_expression, check_symbol, distinct_roots

__all__ = [
    "advance",
    "convolution",
    "delay",
    "differentiate_image",
    "differentiate_original",
    "differentiate_parameter",
    "duhamel",
    "final_value",
    "finite_difference",
    "finite_sum",
    "higher_difference",
    "initial_value",
    "integral_to_infinity",
    "integrate_original",
    "integrate_parameter",
    "multiple_advance",
    "product_of_originals",
    "shift",
    "similarity",
]


@validated
def shift(image, p: sp.Symbol, lam) -> sp.Expr:
    """Damping theorem (2.38): ``p/(p + lam) X(p + lam) <-> exp(-lam t) x(t)``.

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.
    lam : number or Expr
        The damping exponent λ of ``exp(-λ t)`` (any sign; complex for a modulation ``exp(-i ω t)``).

    Examples
    --------
    >>> import sympy as sp
    >>> p, a = sp.symbols("p a")
    >>> sp.factor(shift(1 / p, p, a))     # t  ->  t exp(-a t)
    p/(a + p)**2
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    lam = check_expression(lam, "lam")
    return sp.cancel(p / (p + lam) * image.subs(p, p + lam))


@validated
def delay(image, p: sp.Symbol, tau) -> sp.Expr:
    """Delay theorem (2.26a): ``exp(-p tau) X(p) <-> x(t - tau) 1(t - tau)`` for ``tau >= 0``.

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.
    tau : number or Expr
        The delay, which must be >= 0 (a symbol not known to be negative is accepted).

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> delay(1 / p, p, 2)
    exp(-2*p)/p
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    tau = check_expression(tau, "tau")
    if tau.is_negative:
        raise ParameterError(f"delay tau must be >= 0, got {tau}; for an advance use advance()")
    return sp.exp(-p * tau) * image


@validated
def advance(image, p: sp.Symbol, tau, head) -> sp.Expr:
    """Advance theorem (2.27–2.28): ``exp(p tau) [X(p) - alpha(p)] <-> x(t + tau)``.

    ``head`` is ``alpha(p) = p Integral(x(t) exp(-p t), (t, 0, tau))``, the Carson image of the piece of ``x`` on
    ``(0, tau)`` that the advance removes; pass it as an expression in ``p``, or pass ``(x, t)`` to have it integrated.

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.
    tau : number or Expr
        The advance, which must be >= 0.
    head : Expr or tuple (x, t)
        ``alpha(p)`` as an expression in ``p``, or the original ``x`` with its time symbol ``t`` (then integrated).

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t", positive=True)
    >>> sp.simplify(advance(p / (p + 1), p, 1, (sp.exp(-t), t)))    # exp(-(t+1))
    p*exp(-1)/(p + 1)
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    tau = check_expression(tau, "tau")
    if tau.is_negative:
        raise ParameterError(f"advance tau must be >= 0, got {tau}")
    if isinstance(head, tuple):
        head = _head_image(*head, p, tau)
    return sp.exp(p * tau) * (image - head)


@validated
def finite_sum(image, p: sp.Symbol, tau) -> sp.Expr:
    """Image of ``sum_{j=1}^{floor(t/tau)} x(t - j tau)`` (2.31): ``X(p)/(exp(p tau) - 1)``.

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.
    tau : number or Expr
        The step, which must be > 0.

    Examples
    --------
    >>> import sympy as sp
    >>> p, tau = sp.symbols("p tau", positive=True)
    >>> finite_sum(sp.Integer(1), p, tau)       # floor(t/tau), (2.62)
    1/(exp(p*tau) - 1)
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    tau = check_expression(tau, "tau")
    if tau.is_positive is False:
        raise ParameterError(f"finite_sum needs tau > 0, got {tau}")
    return image / (sp.exp(p * tau) - 1)


@validated
def finite_difference(image, p: sp.Symbol, tau, head) -> sp.Expr:
    """Image of ``Delta x(t) = x(t + tau) - x(t)`` (2.34): ``(exp(p tau) - 1) X(p) - exp(p tau) alpha(p)``.

    ``head`` is ``alpha(p) = p Integral(x exp(-p t), (t, 0, tau))`` or ``(x, t)`` to have it integrated (as in
    :func:`advance`).

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.
    tau : number or Expr
        The step, which must be > 0.
    head : Expr or tuple (x, t)
        ``alpha(p)`` as an expression in ``p``, or the original ``x`` with its time symbol ``t`` (then integrated).

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t", positive=True)
    >>> sp.simplify(finite_difference(1 / p, p, 1, (t, t)))     # Delta t = 1
    1
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    tau = check_expression(tau, "tau")
    if tau.is_positive is False:
        raise ParameterError(f"finite_difference needs tau > 0, got {tau}")
    if isinstance(head, tuple):
        head = _head_image(*head, p, tau)
    return (sp.exp(p * tau) - 1) * image - sp.exp(p * tau) * head


def _heads(p, tau, m: int, heads, original, transform, what: str) -> list[sp.Expr]:
    """The ``m`` head images of :func:`multiple_advance` / :func:`higher_difference` (given or integrated)."""
    if (heads is None) == (original is None):
        raise ParameterError(f"{what}: give exactly one of heads=[...] (m expressions in p) or original=(x, t)")
    if heads is not None:
        heads = [sp.sympify(h) for h in heads]
        if len(heads) != m:
            raise ParameterError(f"{what}: m = {m} needs {m} head images, got {len(heads)}")
        return heads
    x, t = original
    x = sp.sympify(x)
    return [sp.simplify(_head_image(transform(x, t, j), t, p, tau)) for j in range(m)]


def _head_image(x, t, p, tau) -> sp.Expr:
    """``p Integral(x(t) exp(-p t), (t, 0, tau))``, the Carson image of the piece of ``x`` on ``(0, tau)``.

    The integral over a finite interval is entire in p: integrate for p > 0 (no ``Piecewise`` for p = 0) and
    continue analytically, so the result is the same whatever assumptions the caller's ``p`` carries.  The
    integrand is expanded first: SymPy integrates the sum of its terms 2-4x faster than a product of shifted factors
    (``exp(-(t + tau)) cos(t + tau)``), which it sends to its heuristic Risch algorithm.
    """
    pp = sp.Dummy("p", positive=True)
    return p * sp.integrate(sp.expand(sp.sympify(x) * sp.exp(-pp * t)), (t, 0, tau)).subs(pp, p)


def _check_order(m, what: str) -> int:
    if int(m) != m or m < 0:
        raise ParameterError(f"{what}: m must be an integer >= 0, got {m}")
    return int(m)


@validated
def multiple_advance(image, p: sp.Symbol, tau, m: int, heads: Sequence | None = None, *, original=None) -> sp.Expr:
    """m-fold advance theorem (2.29–2.30): image of ``T**m x(t) = x(t + m tau)``,

        exp(p m tau) X(p) - sum_{j=0}^{m-1} exp(p (m - j) tau) alpha_j(p),

    with ``alpha_j(p) = p Integral(x(t + j tau) exp(-p t), (t, 0, tau))`` (2.29) the Carson image of the piece of
    ``T**j x`` on ``(0, tau)``; ``alpha_0`` is the ``alpha`` of :func:`advance`.

    Parameters
    ----------
    image : Expr
        ``X(p)``.
    p : Symbol
        The image variable.
    tau : Expr
        Step, ``tau >= 0``.
    m : int
        Number of advances, ``m >= 0`` (``m = 0`` returns ``X``).
    heads : sequence of Expr, optional
        ``[alpha_0, ..., alpha_{m-1}]`` as expressions in ``p``.
    original : tuple (x, t), optional
        The original instead of ``heads``: the ``alpha_j`` are then integrated.

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t", positive=True)
    >>> sp.simplify(multiple_advance(1 / p, p, 1, 2, original=(t, t)))     # t -> t + 2
    2 + 1/p
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    tau = check_expression(tau, "tau")
    m = _check_order(m, "multiple_advance")
    tau = sp.sympify(tau)
    if tau.is_negative:
        raise ParameterError(f"multiple_advance needs tau >= 0, got {tau}")
    alphas = _heads(p, tau, m, heads, original, lambda x, t, j: x.subs(t, t + j * tau), "multiple_advance")
    return sp.exp(p * m * tau) * image - sp.Add(*[sp.exp(p * (m - j) * tau) * alphas[j] for j in range(m)])


@validated
def higher_difference(image, p: sp.Symbol, tau, m: int, heads: Sequence | None = None, *, original=None) -> sp.Expr:
    """Image of the m-th finite difference ``Delta**m x(t)``, ``Delta = T - 1`` (2.35–2.37):

        (exp(p tau) - 1)**m X(p) - exp(p tau) sum_{j=0}^{m-1} (exp(p tau) - 1)**(m - j - 1) beta_j(p),

    with ``beta_j(p) = p Integral(Delta**j x(t) exp(-p t), (t, 0, tau))`` (2.37), ``beta_0 = alpha``; ``m = 1`` is
    :func:`finite_difference` (2.34).

    Parameters
    ----------
    image : Expr
        ``X(p)``, as in :func:`multiple_advance`.
    p : Symbol
        The image variable.
    tau : Expr
        Step, ``tau > 0``.
    m : int
        Order of the difference, ``m >= 0`` (``m = 0`` returns ``X``).
    heads : sequence of Expr, optional
        ``[beta_0, ..., beta_{m-1}]``.
    original : tuple (x, t), optional
        The original instead of ``heads``; ``Delta**j x = sum_k (-1)**(j-k) binomial(j, k) x(t + k tau)`` (2.35) is
        integrated.

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t", positive=True)
    >>> sp.simplify(higher_difference(2 / p**2, p, 1, 2, original=(t**2, t)))     # Delta**2 t**2 = 2
    2
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    tau = check_expression(tau, "tau")
    m = _check_order(m, "higher_difference")
    tau = sp.sympify(tau)
    if tau.is_positive is False:
        raise ParameterError(f"higher_difference needs tau > 0, got {tau}")

    def delta_power(x, t, j):
        return sp.Add(*[(-1) ** (j - k) * sp.binomial(j, k) * x.subs(t, t + k * tau) for k in range(j + 1)])

    betas = _heads(p, tau, m, heads, original, delta_power, "higher_difference")
    g = sp.exp(p * tau)
    return (g - 1) ** m * image - g * sp.Add(*[(g - 1) ** (m - j - 1) * betas[j] for j in range(m)])


@validated
@renamed_keyword({"order": "n"})
def differentiate_parameter(image, s: sp.Symbol, n: int = 1) -> sp.Expr:
    """Differentiation with respect to a parameter (2.42): ``d^k X(p, s)/ds^k <-> d^k x(t, s)/ds^k``.

    The Carson transform commutes with differentiation in a parameter ``s`` independent of ``t`` and ``p`` (for
    ``Re p`` beyond the abscissa of convergence, uniformly in ``s``); this is what lets operational calculus treat
    partial differential equations.

    Parameters
    ----------
    image : Expr
        Carson image ``X(p, s)`` depending on the parameter ``s``.
    s : Symbol
        The parameter, independent of ``t`` and ``p``; it must be a SymPy Symbol.
    n : int
        Order of the derivative, an integer >= 0 (``0`` returns the image unchanged).

    Examples
    --------
    >>> import sympy as sp
    >>> p, s = sp.symbols("p s")
    >>> sp.factor(differentiate_parameter(p / (p - s), s))      # d/ds exp(s t) = t exp(s t)
    p/(p - s)**2
    """
    image = check_expression(image, "image")
    s = check_symbol(s, "s")
    if not isinstance(s, sp.Symbol):
        raise ParameterError(f"the parameter must be a SymPy Symbol, got {s!r}")
    if int(n) != n or n < 0:
        raise ParameterError(f"n (the derivative order) must be an integer >= 0, got {n}")
    return sp.diff(image, s, int(n))


@validated
def integrate_parameter(image, s: sp.Symbol, s0, s1=None) -> sp.Expr:
    """Integration with respect to a parameter (2.41): ``Integral(X(p, s), (s, s0, s1)) <-> Integral(x(t, s), (s, s0,
    s1))``; ``s1`` defaults to ``s`` itself (the book's variable upper limit).

    Parameters
    ----------
    image : Expr
        Carson image ``X(p, s)`` depending on the parameter ``s``.
    s : Symbol
        The parameter of integration, independent of ``t`` and ``p``; it must be a SymPy Symbol.
    s0 : number or Expr
        Lower limit of the integral.
    s1 : number or Expr, optional
        Upper limit of the integral; ``s`` itself (a variable upper limit) when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> p, s, u = sp.symbols("p s u", positive=True)
    >>> integrate_parameter(p / (p + u), u, 0, s)     # Integral(exp(-u t), (u, 0, s)) = (1 - exp(-s t))/t
    -p*log(p) + p*log(p + s)
    """
    image = check_expression(image, "image")  # the limits s0, s1 may be infinite
    if not isinstance(s, sp.Symbol):
        raise ParameterError(f"the parameter must be a SymPy Symbol, got {s!r}")
    upper = s if s1 is None else sp.sympify(s1)
    if upper == s:
        u = sp.Dummy(s.name)
        return sp.integrate(image.subs(s, u), (u, s0, s))
    return sp.integrate(image, (s, s0, upper))


@validated
def similarity(image, p: sp.Symbol, a) -> sp.Expr:
    """Similarity theorem (2.46): ``X(p/a) <-> x(a t)``, ``a > 0``.

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.
    a : number or Expr
        The time scale factor, which must be > 0.

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> similarity(p / (p**2 + 1), p, 3)     # sin t -> sin 3t
    p/(3*(p**2/9 + 1))
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    a = check_expression(a, "a")
    a = sp.sympify(a)
    if a.is_positive is False:
        raise ParameterError(f"similarity needs a > 0, got {a}")
    return image.subs(p, p / a)


@validated
@renamed_keyword({"order": "n"})
def differentiate_original(image, p: sp.Symbol, initial: Sequence = (), n: int | None = None) -> sp.Expr:
    """Image of the ``m``-th derivative (2.18): ``p**m X - p**m x(0) - p**(m-1) x'(0) - … - p x^(m-1)(0)``.

    ``initial`` holds ``x(0+), x'(0+), ..., x^(m-1)(0+)``; ``n`` defaults to ``len(initial)`` (with zero data
    pass ``n`` alone, giving (2.20)).

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.
    initial : sequence of number or Expr
        Initial values ``[x(0+), x'(0+), ..., x^(k-1)(0+)]`` with ``k <= n`` (missing ones are zero).
    n : int, optional
        Order m of the derivative, an integer >= 0; ``len(initial)`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> sp.cancel(differentiate_original(p**2 / (p**2 + 1), p, [1]))   # (cos t)' = -sin t
    -p/(p**2 + 1)
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    m = len(initial) if n is None else int(n)
    if m < 0:
        raise ParameterError("n (the derivative order) must be >= 0")
    if len(initial) > m:
        raise ParameterError(f"{len(initial)} initial values given for a derivative of order {m}")
    init = list(initial) + [0] * (m - len(initial))
    return p**m * image - sp.Add(*[p ** (m - k) * init[k] for k in range(m)])


@validated
def integrate_original(image, p: sp.Symbol, times: int = 1, constant=0) -> sp.Expr:
    """Image of the ``m``-fold integral from 0 (2.11–2.12): ``X(p)/p**m``; with ``constant`` = value at 0 of an
    indefinite (single) integral, ``X/p + constant`` (2.14).

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.
    times : int
        Number m of integrations, an integer >= 1.
    constant : number or Expr
        Value at ``t = 0`` of an indefinite integral; only with ``times=1`` (0: the integral from 0).

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> integrate_original(sp.Integer(1), p, 2)    # 1 -> t**2/2
    p**(-2)
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    constant = constant if constant is None else check_expression(constant, "constant")
    if times < 1:
        raise ParameterError("times must be >= 1")
    if constant != 0 and times != 1:
        raise ParameterError("an integration constant is supported for a single integration only")
    return image / p**times + constant


@validated
@renamed_keyword({"order": "n"})
def differentiate_image(image, p: sp.Symbol, n: int = 1) -> sp.Expr:
    """Image of ``t**m x(t)`` (2.23): ``(-1)**m p d^m/dp^m [X(p)/p]``.

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.
    n : int
        The power m of ``t``, an integer >= 0.

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> sp.factor(differentiate_image(p / (p + 1), p, 2))    # t**2 exp(-t)
    2*p/(p + 1)**3
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    if n < 0:
        raise ParameterError("n (the derivative order) must be >= 0")
    return sp.cancel((-1) ** n * p * sp.diff(image / p, p, n))


@validated
def convolution(image_x, image_y, p: sp.Symbol) -> sp.Expr:
    """Image of ``Integral(x(u) y(t - u), (u, 0, t))`` (2.43): ``X(p) Y(p)/p``.

    Parameters
    ----------
    image_x : Expr
        Carson image ``X(p)`` of the first original.
    image_y : Expr
        Carson image ``Y(p)`` of the second original.
    p : Symbol
        The image variable.

    See Also
    --------
    duhamel, product_of_originals

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> convolution(sp.Integer(1), sp.Integer(1), p)      # 1 * 1 = t
    1/p
    """
    image_x = check_expression(image_x, "image_x")
    image_y = check_expression(image_y, "image_y")
    p = check_symbol(p, "p")
    return sp.sympify(image_x) * sp.sympify(image_y) / p


@validated
def duhamel(image_x, image_y, p: sp.Symbol) -> sp.Expr:
    """Image of ``d/dt Integral(x(u) y(t - u), (u, 0, t))`` (2.45, Duhamel): ``X(p) Y(p)``.

    Parameters
    ----------
    image_x, image_y : Expr
        Carson images ``X(p)`` and ``Y(p)`` of the two originals.
    p : Symbol
        The image variable.

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> duhamel(p / (p + 1), sp.Integer(1), p)      # x = exp(-t), y = 1: d/dt of the convolution is exp(-t)
    p/(p + 1)
    """
    image_x = check_expression(image_x, "image_x")
    image_y = check_expression(image_y, "image_y")
    p = check_symbol(p, "p")
    return sp.sympify(image_x) * sp.sympify(image_y)


@validated
def initial_value(image, p: sp.Symbol) -> sp.Expr:
    """``x(0+) = lim_{p -> oo} X(p)`` (2.47).

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, an expression in ``p``.
    p : Symbol
        The image variable.

    Returns
    -------
    Expr
        The finite limit.

    Raises
    ------
    ModelError
        If ``X(p)`` has no finite limit at ``p -> oo``.

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> initial_value(p**2 / (p**2 + 4), p)
    1
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    value = sp.limit(image, p, sp.oo)
    if value.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or isinstance(value, sp.AccumBounds):
        raise ModelError(f"X(p) has no finite limit at p -> oo ({value}): the original is not a function at t = 0+")
    return value


def _poles_checked(expr, p, what: str) -> list[tuple[sp.Expr, int]]:
    if not sp.sympify(expr).is_rational_function(p):
        raise ModelError(f"{what}: the pole locations of a non-rational image cannot be checked; invert it instead")
    _, den = as_rational(expr, p)
    return distinct_roots(den)


@validated
def final_value(image, p: sp.Symbol) -> sp.Expr:
    """``x(oo) = X(0)`` (2.49), *only* when the limit exists.

    The theorem holds when every pole of ``X(p)/p`` lies in the open left half-plane except a simple pole at
    ``p = 0``.  Otherwise (a pole with ``Re >= 0`` other than a simple one at 0: growth, undamped oscillation, a
    ramp) :class:`ModelError` is raised instead of returning the meaningless ``X(0)``.

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, a rational function of ``p``.
    p : Symbol
        The image variable.

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
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    image = image
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


@validated
def integral_to_infinity(image, p: sp.Symbol) -> sp.Expr:
    """``Integral(x, (t, 0, oo)) = [X(p)/p]_{p=0}`` (2.48), when every pole of ``X/p`` is in ``Re p < 0``.

    Parameters
    ----------
    image : Expr
        Carson image ``X(p)``, a rational function of ``p``.
    p : Symbol
        The image variable.

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> integral_to_infinity(p / (p + 2), p)     # exp(-2 t)
    1/2
    """
    image = check_expression(image, "image")
    p = check_symbol(p, "p")
    image = image
    for root, _ in _poles_checked(image / p, p, "integral_to_infinity"):
        re = sp.re(sp.N(root)) if root.is_number else sp.re(root)
        if not re.is_negative:
            raise ModelError(
                f"integral_to_infinity: X(p)/p has the pole {root} with Re >= 0 (or undecidable sign); "
                "the integral does not converge (abscissa of convergence sigma_c >= 0)"
            )
    return sp.cancel(image / p).subs(p, 0)


@validated
def product_of_originals(image_x, image_y, p: sp.Symbol) -> sp.Expr:
    """Image of the product ``x(t) y(t)`` (Bulgakov 2.143–2.144) for a rational ``Y``:

        p * sum Res_q [X(p - q) Y(q) / ((p - q) q)]   over the poles of Y(q)/q.

    ``X`` may be any image analytic for ``Re p`` large enough.

    Parameters
    ----------
    image_x : Expr
        Carson image ``X(p)`` of ``x``, analytic for ``Re p`` large enough.
    image_y : Expr
        Carson image ``Y(p)`` of ``y``, which must be a rational function of ``p``.
    p : Symbol
        The image variable.

    See Also
    --------
    convolution

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> sp.factor(product_of_originals(1 / p, p / (p + 1), p))     # t * exp(-t)
    p/(p + 1)**2
    """
    image_x = check_expression(image_x, "image_x")
    image_y = check_expression(image_y, "image_y")
    p = check_symbol(p, "p")
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
