"""Step functions and linear difference equations (Bulgakov §2.22–2.26).

A step function ``x(t) = h(floor(t/tau) tau)`` is described by its sequence ``x_n = h(n tau)``.  With
``gamma = exp(p tau)`` its Carson image is (2.104)

    X = (gamma - 1) sum_{n>=0} x_n gamma**(-n-1) = (1 - 1/gamma) Z{x}(gamma),

``Z`` the unilateral z-transform (the factor ``1 - 1/gamma`` is the discrete analogue of Carson's ``p``).  The advance
``T x(t) = x(t + tau)`` has image ``gamma X - (gamma - 1) x_0`` (2.106), and the pairs (2.117–2.118)

    (gamma - 1)/(gamma - l)**(m+1)  <->  binomial(n, m) l**(n-m)

invert any rational image of ``gamma`` with ``deg numerator <= deg denominator``.

What is reconstructed: parts of §§2.22–2.26 are illegible in the available copy of the book; the formulas above
were rebuilt from the legible fragments (the identification with the z-transform is ours, not the book's).
Here everything is verified against direct recursion in the tests.  The consistency relations of degenerate
systems are carried over from §2.21b by analogy (the solution evaluated at ``n < m_k`` must reproduce the data).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ModelError, ParameterError
from ._rational import as_rational, check_expression, check_symbol, distinct_roots

__all__ = [
    "DifferenceSolution",
    "IndefiniteSum",
    "indefinite_sum",
    "inverse_step_image",
    "solve_difference",
    "step_image",
]

_n = sp.Symbol("n", integer=True, nonnegative=True)
_gamma = sp.Symbol("gamma")


@validated
def step_image(h, n: sp.Symbol = _n, gamma: sp.Symbol = _gamma) -> sp.Expr:
    """Carson image, as a function of ``gamma = exp(p tau)``, of the step function with values ``x_n = h(n)``.

    ``(1 - 1/gamma) sum_{n>=0} h(n) gamma**(-n)`` (Bulgakov 2.104), summed in closed form by SymPy (valid for
    ``|gamma|`` beyond the radius of convergence).

    Parameters
    ----------
    h : Expr
        The values ``x_n = h(n)``: an expression in the index ``n`` whose z-transform SymPy sums in closed form.
    n : Symbol
        The integer index of the sequence (default: a nonnegative integer symbol ``n``).
    gamma : Symbol
        The image variable ``gamma = exp(p tau)`` (default ``Symbol("gamma")``).

    Returns
    -------
    Expr
        The image as a factored function of ``gamma``.

    Raises
    ------
    ModelError
        If a term of ``h`` has no closed-form z-transform.

    See Also
    --------
    inverse_step_image

    Examples
    --------
    >>> import sympy as sp
    >>> n, g, l = sp.symbols("n gamma lambda")
    >>> sp.factor(step_image(l**n, n, g))
    (gamma - 1)/(gamma - lambda)
    >>> sp.factor(step_image(n, n, g))          # floor(t/tau)  <->  1/(exp(p tau) - 1)
    1/(gamma - 1)
    """
    h, n, gamma = check_expression(h, "h"), check_symbol(n, "n"), check_symbol(gamma, "gamma")
    total = sp.S.Zero
    for term in sp.Add.make_args(sp.expand(h)):  # linearity: SymPy sums simple terms more reliably
        part = sp.summation(term * gamma ** (-n), (n, 0, sp.oo))
        if isinstance(part, sp.Piecewise):
            part = part.args[0][0]
        if part.has(sp.Sum):
            raise ModelError(f"no closed form for the z-transform of {term}")
        total += part
    return sp.factor(sp.simplify((1 - 1 / gamma) * total))


@validated
def inverse_step_image(image, gamma: sp.Symbol = _gamma, n: sp.Symbol = _n) -> sp.Expr:
    """Sequence ``x_n`` of the step function whose Carson image is the rational function ``image`` of ``gamma``.

    Writes ``image = (gamma - 1) H(gamma)``, expands ``H`` in partial fractions and inverts term by term with
    ``(gamma - 1)/(gamma - l)**(m+1) <-> binomial(n, m) l**(n-m)`` (Bulgakov 2.117–2.118, §2.25).

    Parameters
    ----------
    image : Expr
        The image: a rational function of ``gamma`` with ``deg numerator <= deg denominator``.
    gamma : Symbol
        The image variable ``gamma = exp(p tau)`` (default ``Symbol("gamma")``).
    n : Symbol
        The integer index of the returned sequence (default: a nonnegative integer symbol ``n``).

    Returns
    -------
    Expr
        ``x_n`` as an expression in ``n``.

    Raises
    ------
    ModelError
        If the image is not rational in ``gamma`` or ``deg numerator > deg denominator``.

    Examples
    --------
    >>> import sympy as sp
    >>> g, n = sp.symbols("gamma n")
    >>> inverse_step_image((g - 1) / (g - 2) ** 2, g, n)
    2**(n - 1)*n
    >>> inverse_step_image(1 / (g - 1) ** 2, g, n)      # binomial(n, 2) (2.118)
    n*(n - 1)/2
    """
    num, den = as_rational(image, gamma)
    if num.is_zero:
        return sp.S.Zero
    if num.degree() > den.degree():
        raise ModelError(
            f"improper step image: deg numerator {num.degree()} > deg denominator {den.degree()} in {gamma}"
        )
    h_num, h_den = num, den * sp.Poly(gamma - 1, gamma)
    g = h_num.gcd(h_den)
    h_num, h_den = h_num.quo(g), h_den.quo(g)
    roots = distinct_roots(h_den)
    lead = h_den.LC()
    z = sp.Dummy("z")
    total = sp.S.Zero
    for i, (root, q) in enumerate(roots):
        others = sp.Mul(*[(z - r) ** m for j, (r, m) in enumerate(roots) if j != i])
        phi = h_num.as_expr().subs(gamma, z) / (lead * others)
        deriv = phi
        for j in range(q, 0, -1):  # coefficient of 1/(gamma - root)**j
            c = deriv.subs(z, root) / sp.factorial(q - j)
            deriv = sp.diff(deriv, z)
            c = sp.simplify(c) if not c.is_Rational else c
            if root == 0:
                total += c * sp.KroneckerDelta(n, j - 1)
            else:
                total += c * sp.binomial(n, j - 1) * root ** (n - j + 1)
    return sp.simplify(sp.expand_func(total)) if not total.has(sp.CRootOf) else total


@dataclass(frozen=True)
class DifferenceSolution(SymPyPrintable):
    """Result of :func:`solve_difference`: ``y_n = M_n + S(T) x_n + sum_{j<n} N_{n-j-1} x_j`` (2.130).

    Attributes
    ----------
    response : Matrix
        ``y_n`` (may contain an unevaluated ``Sum``; :meth:`values` evaluates it for concrete ``n``).
    free : Matrix
        ``M_n``, the response to the initial values (free motion).
    impulse : Matrix
        ``N_n``, the response to a unit input pulse (its entries convolve with the inputs).
    feedthrough : Matrix
        ``S(gamma)``, acting as ``S(T)``.
    delta : Expr
        ``det f(gamma)``.
    constraints : tuple of Eq
        When ``deg delta`` is below the number of initial values (leading matrix singular), the relations that the
        initial values ``y1_0, y1_1, ...`` (``y_k(j)``) must satisfy, solved for the highest ones; the solution
        satisfies them whatever is given (as in §2.21b for differential systems).
    n : Symbol
        The integer index of the sequences.
    initial_values : dict
        The given values of those symbols (substituted into ``response`` and ``free``).
    """

    response: sp.Matrix
    free: sp.Matrix
    impulse: sp.Matrix
    feedthrough: sp.Matrix
    delta: sp.Expr
    n: sp.Symbol
    constraints: tuple = ()
    initial_values: dict | None = None

    def __repr__(self) -> str:
        return f"DifferenceSolution(delta={self.delta}, response={list(self.response)})"

    def _repr_latex_(self) -> str:
        return f"$$y_n = {sp.latex(self.response)}$$"

    def values(self, count: int) -> list[sp.Matrix]:
        """Exact values ``y_k`` for ``k < count`` (needs numeric initial values).

        Parameters
        ----------
        count : int
            Number of values wanted (>= 0): ``y_0, ..., y_(count-1)``.

        Returns
        -------
        list of Matrix
            The column vectors ``y_k``, simplified.
        """
        return [self.response.subs(self.n, k).doit().applyfunc(sp.simplify) for k in range(count)]


@validated
def solve_difference(f, e, inputs=None, initial=None, *, T: sp.Symbol | None = None, n: sp.Symbol = _n):
    """Solve ``f(T) y = e(T) x`` with the advance operator ``T y_n = y_{n+1}`` (Bulgakov 2.119–2.130).

    Parameters
    ----------
    f, e : Matrix or Expr
        Polynomial matrices (or scalars) in ``T``; ``f`` square with ``det f`` not identically 0.
    inputs : sequence of Expr, optional
        ``x_n`` as expressions in ``n`` (default: zero input).
    initial : sequence of sequences, optional
        ``initial[k] = [y_k(0), y_k(1), ..., y_k(m_k - 1)]`` (``m_k`` the highest advance of ``y_k``); default:
        symbols ``y1_0, y1_1, ...``.
    T : Symbol, optional
        The advance operator's symbol in ``f`` and ``e`` (default ``Symbol("T")``).
    n : Symbol
        The integer index of the sequences (default: a nonnegative integer symbol ``n``); ``inputs`` are
        expressions in it.

    Returns
    -------
    DifferenceSolution

    Examples
    --------
    Fibonacci, ``y_{n+2} = y_{n+1} + y_n``:

    >>> import sympy as sp
    >>> T, n = sp.symbols("T n")
    >>> sol = solve_difference(T**2 - T - 1, 1, None, [[0, 1]], T=T, n=n)
    >>> [v[0] for v in sol.values(8)]
    [0, 1, 1, 2, 3, 5, 8, 13]
    """
    from .systems import _as_matrix, _initial_poly, _split

    T = sp.Symbol("T") if T is None else T
    g = sp.Dummy("gamma")
    fm, em = _as_matrix(f, "f"), _as_matrix(e, "e")
    nn = fm.rows
    if not fm.is_square:
        raise ModelError(f"f(T) must be square, got shape {fm.shape}")
    if em.rows != nn:
        raise ModelError(f"e(T) must have {nn} rows, got shape {em.shape}")
    r = em.cols
    fg, eg = fm.subs(T, g), em.subs(T, g)
    delta = sp.expand(fg.det(method="berkowitz"))
    if delta == 0:
        raise ModelError("det f(T) vanishes identically: the system is singular")
    adj = fg.adjugate(method="berkowitz").applyfunc(sp.expand)
    orders = [max(sp.degree(fm[i, k], T) if fm[i, k] != 0 else 0 for i in range(nn)) for k in range(nn)]
    xs = [sp.S.Zero] * r if inputs is None else [sp.sympify(x) for x in inputs]
    if len(xs) != r:
        raise ParameterError(f"expected {r} inputs, got {len(xs)}")
    if initial is not None and len(initial) != nn:
        raise ParameterError(f"initial must hold one list of values per unknown ({nn})")
    y0 = [[sp.Symbol(f"y{k + 1}_{j}") for j in range(orders[k])] for k in range(nn)]
    given = {}
    for k, vals in enumerate(initial or []):
        if len(vals) != orders[k]:
            raise ParameterError(f"y{k + 1} has advance order {orders[k]}: give {orders[k]} initial values")
        given.update({y0[k][j]: sp.sympify(v) for j, v in enumerate(vals)})
    e_order = max([sp.degree(em[i, j], T) if em[i, j] != 0 else 0 for i in range(nn) for j in range(r)] or [0])
    x0 = [[x.subs(n, k) for k in range(max(e_order, 1))] for x in xs]
    qv = _initial_poly(fm, T, g, y0)
    pv = _initial_poly(em, T, g, x0)
    w = adj * (qv - pv) / delta
    mu = sp.Matrix([_split(w[i], g)[1] for i in range(nn)])
    transfer = (adj * eg / delta).applyfunc(sp.cancel)
    parts = [[_split(transfer[i, j], g) for j in range(r)] for i in range(nn)]
    smat = sp.Matrix(nn, r, lambda i, j: sp.expand(parts[i][j][0]))
    nu = sp.Matrix(nn, r, lambda i, j: parts[i][j][1])
    free = mu.applyfunc(lambda v: inverse_step_image(sp.cancel((g - 1) * v), g, n))
    impulse = nu.applyfunc(lambda v: inverse_step_image(sp.cancel((g - 1) * v), g, n))
    j = sp.Dummy("j", integer=True, nonnegative=True)
    response = []
    for i in range(nn):
        yi = free[i]
        for col in range(r):
            if xs[col] == 0:
                continue
            poly = sp.Poly(smat[i, col], g)
            for (deg,), c in poly.terms():
                yi += c * xs[col].subs(n, n + deg)
            if nu[i, col] != 0:
                yi += sp.Sum(impulse[i, col].subs(n, n - j - 1) * xs[col].subs(n, j), (j, 0, n - 1))
        response.append(yi)
    response = sp.Matrix(response)
    constraints: tuple = ()
    if sp.degree(delta, g) < sum(orders):  # not in normal form: y_k(j) must equal the solution at n = j
        eqs = []
        for k in range(nn):
            for jj in range(orders[k]):
                eqs.append(sp.expand(y0[k][jj] - response[k].subs(n, jj).doit()))
        syms = [v for jj in reversed(range(max(orders))) for k in reversed(range(nn)) if jj < orders[k]
                for v in [y0[k][jj]]]  # fmt: skip
        a, b = sp.linear_eq_to_matrix(eqs, syms)
        rref, pivots = a.row_join(b).rref(simplify=True)
        out = []
        for row, piv in enumerate(pivots):
            if piv >= len(syms):
                raise ModelError("the initial-value relations of the difference system are contradictory")
            rhs = rref[row, -1] - sum(rref[row, c] * syms[c] for c in range(len(syms)) if c != piv)
            out.append(sp.Eq(syms[piv], sp.expand(rhs)))
        constraints = tuple(out)
    return DifferenceSolution(
        response=response.subs(given),
        constraints=constraints,
        initial_values=given,
        free=free.subs(given),
        impulse=impulse,
        feedthrough=smat.subs(g, sp.Symbol("gamma")),
        delta=delta.subs(g, sp.Symbol("gamma")),
        n=n,
    )


@dataclass(frozen=True)
class IndefiniteSum(SymPyPrintable):
    """Result of :func:`indefinite_sum`: the general solution ``y`` of ``Delta y = y(t + tau) - y(t) = x(t)`` (2.68),

        y(t) = sum_{j=1}^{floor(t/tau)} x(t - j tau) + A(t),     A(t) = a(t - tau floor(t/tau)),

    ``A`` the arbitrary ``tau``-periodic function that replaces the constant of an indefinite integral; ``a`` is
    ``y`` on ``(0, tau)``.

    Attributes
    ----------
    definite : Expr
        The definite sum (2.31), the solution that vanishes on ``0 <= t < tau`` (an unevaluated ``Sum``).
    periodic : Expr
        ``A(t)``.
    piece : Expr
        ``a(t)``, the values on ``(0, tau)``.
    x : Expr
        The given difference ``x(t)``.
    t : Symbol
        The independent variable.
    tau : Expr
        The step, ``tau > 0``.
    p : Symbol
        The variable of the images.
    given_image : Expr or None
        The Carson image of ``x`` when it was given to :func:`indefinite_sum`; None to compute it lazily.
    """

    x: sp.Expr
    piece: sp.Expr
    t: sp.Symbol
    tau: sp.Expr
    p: sp.Symbol
    given_image: sp.Expr | None = None

    @property
    def definite(self) -> sp.Expr:
        j = sp.Dummy("j", integer=True, positive=True)
        return sp.Sum(self.x.subs(self.t, self.t - j * self.tau), (j, 1, sp.floor(self.t / self.tau)))

    @property
    def periodic(self) -> sp.Expr:
        return self.piece.subs(self.t, self.t - self.tau * sp.floor(self.t / self.tau))

    @property
    def original(self) -> sp.Expr:
        """``y(t)`` (2.68)."""
        return self.definite + self.periodic

    @cached_property
    def head(self) -> sp.Expr:
        """``alpha(p) = p Integral(a(t) exp(-p t), (t, 0, tau))`` (2.64)."""
        return _p_integral(self.piece, self.t, self.p, self.tau)

    @cached_property
    def image(self) -> sp.Expr:
        """``eta(p) = X(p)/(exp(p tau) - 1) + exp(p tau) alpha(p)/(exp(p tau) - 1)``: (2.34) solved for ``eta``."""
        from .transform import carson

        xi = self.given_image if self.given_image is not None else carson(self.x, self.t, self.p)
        g = sp.exp(self.p * self.tau)
        return xi / (g - 1) + g * self.head / (g - 1)

    def __call__(self, value) -> sp.Expr:
        """``y`` at a numeric ``t = value >= 0`` (the finite sum written out)."""
        value = sp.sympify(value)
        ratio = value / self.tau
        if not ratio.is_number or ratio.is_negative:
            raise ParameterError(f"evaluate y at a numeric t >= 0 with numeric tau; got t = {value}, tau = {self.tau}")
        n = int(sp.floor(ratio))
        head = self.piece.subs(self.t, value - n * self.tau)
        return sp.Add(*[self.x.subs(self.t, value - j * self.tau) for j in range(1, n + 1)]) + head

    def __repr__(self) -> str:
        return f"IndefiniteSum(Delta y = {self.x}, tau = {self.tau}, y = {self.piece} on (0, tau))"

    def _repr_latex_(self) -> str:
        return f"$$y(t) = {sp.latex(self.original)}$$"


def _p_integral(a, t: sp.Symbol, p: sp.Symbol, tau) -> sp.Expr:
    """Carson image ``p Integral(a(t) exp(-p t), (t, 0, tau))`` of ``a`` cut to ``(0, tau)`` (2.64)."""
    pp = sp.Dummy("p", positive=True)  # entire in p: integrate for p > 0 (no Piecewise at p = 0) and continue
    return sp.simplify(p * sp.integrate(sp.sympify(a) * sp.exp(-pp * t), (t, 0, tau)).subs(pp, p))


@validated
def indefinite_sum(x, t: sp.Symbol, tau, piece=None, *, p: sp.Symbol | None = None, image=None) -> IndefiniteSum:
    """Indefinite sum: every ``y`` with first difference ``Delta y = y(t + tau) - y(t) = x(t)`` (Bulgakov 2.67–2.68).

    By (2.34) the images satisfy ``(exp(p tau) - 1) eta - exp(p tau) alpha = X``, where ``alpha`` is the image of
    ``y`` cut to ``(0, tau)``; solving for ``eta`` and inverting with (2.31) and (2.66) gives

        y(t) = sum_{j=1}^{floor(t/tau)} x(t - j tau) + A(t),

    with ``A`` periodic (period ``tau``) and equal to ``y`` on ``(0, tau)``: an arbitrary periodic function takes the
    place of the constant of integration.  The first term is the definite sum, the solution vanishing on
    ``0 <= t < tau``.

    What is reconstructed: (2.67), the image equation and (2.68) are legible in the book; the closed form of the
    image ``eta`` above is the book's intermediate step, rebuilt where the print is illegible.  The tests check
    ``Delta y = x`` pointwise and ``eta`` against numeric quadrature of ``p Integral(y exp(-p t))``.

    Parameters
    ----------
    x : Expr
        The given difference, an expression in ``t``.
    t : Symbol
        The independent variable; it must be a SymPy Symbol.
    tau : Expr
        Step, ``tau > 0``.
    piece : Expr, optional
        ``a(t)``: the values of ``y`` on ``(0, tau)``, which fix the periodic function.  Default: an undefined
        function ``a(t)`` (the general solution).
    p : Symbol, optional
        Variable of the image (default ``Symbol("p")``).
    image : Expr, optional
        The Carson image of ``x``, if known (else computed lazily with :func:`~symosc.operational.carson`).

    Examples
    --------
    >>> import sympy as sp
    >>> t = sp.Symbol("t", nonnegative=True)
    >>> y = indefinite_sum(t, t, 1, piece=sp.Integer(0))      # Delta y = t, y = 0 on (0, 1)
    >>> [y(k) for k in range(5)]                              # 0, 0, 1, 3, 6: binomial(t, 2) at integers
    [0, 0, 1, 3, 6]
    >>> y.image                                               # (1/p)/(exp(p) - 1) by (2.31)
    1/(p*(exp(p) - 1))
    """
    tau = sp.sympify(tau)
    if tau.is_positive is False:
        raise ParameterError(f"indefinite_sum needs tau > 0, got {tau}")
    if not isinstance(t, sp.Symbol):
        raise ParameterError(f"t must be a SymPy Symbol, got {t!r}")
    piece = sp.Function("a")(t) if piece is None else sp.sympify(piece)
    p = sp.Symbol("p") if p is None else p
    return IndefiniteSum(
        x=sp.sympify(x), piece=piece, t=t, tau=tau, p=p, given_image=None if image is None else sp.sympify(image)
    )
