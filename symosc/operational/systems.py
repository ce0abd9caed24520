"""Operational solution of linear constant-coefficient systems ``f(D) y = e(D) x(t)`` (Bulgakov §2.20–2.21).

With ``Delta(p) = det f(p)``, ``F = adj f``, the initial-value polynomials (2.77)

    P(p) = (e(p) - e(D0))/(p - D0) x(0),     Q(p) = (f(p) - f(D0))/(p - D0) y(0)

and the splittings (2.78) ``F (Q - P)/Delta = -R + mu`` and ``F e/Delta = S + nu`` (polynomial + proper parts),
the solution (2.87) is

    y(t) = M(t) + S(D) x(t) + Integral(N(t - u) x(u), (u, 0, t)),

``M`` the original of ``p mu`` (free motion), ``N`` the original of ``p nu`` (impulse-response matrix).  When the
system is not in normal form (``s = deg Delta`` below ``m``, the number of initial values), only ``s`` initial
values are free: the operational solution silently satisfies ``m - s`` relations at ``t = 0+``, which are
returned as :attr:`OperationalSolution.constraints`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp

from .._plotting import new_axes, plot_method
from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ModelError, ParameterError
from ..symbols import t as _t
from ._rational import check_expression
from .heaviside import heaviside_expand
from .table import _Unsupported, carson_by_table
from .transform import inverse_carson

__all__ = ["OperationalSolution", "solve_operational"]


@dataclass(frozen=True)
class OperationalSolution(SymPyPrintable):
    """Result of :func:`solve_operational`.

    Attributes
    ----------
    response : Matrix
        ``y(t)`` for ``t > 0`` (column), in terms of the initial values and inputs.
    free : Matrix
        ``M(t)``, the part due to the initial values (2.82–2.83).
    feedthrough : Matrix
        ``S(p)``, the polynomial part of ``F e/Delta`` (acts as ``S(D) x``).
    impulse : Matrix
        ``N(t)``, the regular part of the impulse-response matrix (2.85).
    step : Matrix
        Transition (step-response) matrix ``S(0) + Integral(N, (u, 0, t))``: the response to ``x = 1(t)`` with
        zero initial values, without the delta functions of ``S(D)`` when ``deg S > 0``.
    transfer : Matrix
        ``F(p) e(p)/Delta(p)``, the Carson image of ``step`` (including the polynomial part).
    delta : Expr
        ``Delta(p) = det f(p)``.
    adjugate : Matrix
        ``F(p) = adj f(p)``.
    orders : tuple of int
        ``m_k``, the highest derivative of each unknown; ``m = sum(orders)``.
    degree : int
        ``s = deg Delta``, the number of free initial values.
    initial_symbols : tuple
        The symbols used for ``y_k^(j)(0)`` (and ``x_l^(j)(0)`` for symbolic inputs).
    constraints : tuple of Eq
        ``m - s`` independent relations the initial data must satisfy (empty in normal form), in the symbols
        ``y1_0, y1_1, ...`` (``y_k^(j)(0)``), solved for the highest derivatives.
    initial_values : dict
        The numbers given for those symbols (substituted into ``response`` and ``free``).
    p : Symbol
        The image variable of ``feedthrough``, ``transfer``, ``delta`` and ``adjugate``.
    t : Symbol
        Time, the variable of ``response``, ``free``, ``impulse`` and ``step``.
    """

    response: sp.Matrix
    free: sp.Matrix
    feedthrough: sp.Matrix
    impulse: sp.Matrix
    step: sp.Matrix
    transfer: sp.Matrix
    delta: sp.Expr
    adjugate: sp.Matrix
    orders: tuple[int, ...]
    degree: int
    initial_symbols: tuple
    constraints: tuple
    initial_values: dict
    p: sp.Symbol
    t: sp.Symbol

    def __repr__(self) -> str:
        return (
            f"OperationalSolution(delta={self.delta}, orders={self.orders}, degree={self.degree}, "
            f"constraints={len(self.constraints)}, response={list(self.response)})"
        )

    def _repr_latex_(self) -> str:
        return f"$$y(t) = {sp.latex(self.response)}$$"

    @property
    def normal_form(self) -> bool:
        """True if all ``m`` initial values are free (leading-coefficient determinant nonzero)."""
        return self.degree == sum(self.orders)

    def is_consistent(self, values: dict | None = None) -> bool:
        """True if the given initial data (plus ``values``, keyed by symbol or name) satisfy every constraint.

        Parameters
        ----------
        values : mapping of Symbol or name to number, optional
            Values of initial-value symbols (``y1_0``, ...) or parameters, added to the given initial data.

        Returns
        -------
        bool
            True when every relation in :attr:`constraints` holds (always True in normal form).
        """
        sub = dict(self.initial_values)
        for k, v in (values or {}).items():
            sub[k if isinstance(k, sp.Basic) else sp.Symbol(str(k))] = v
        return all(sp.simplify((c.lhs - c.rhs).subs(sub)) == 0 for c in self.constraints)

    @plot_method
    def plot(self, values: dict | None = None, t_max: float = 10.0, *, ax: Any = None) -> Any:
        """Plot the response components for numeric ``values`` of the symbols in it.

        Parameters
        ----------
        values : mapping of Symbol or name to number, optional
            Values of every symbol in ``response`` other than ``t`` (initial values, parameters).
        t_max : float
            End of the plotted time interval ``(0, t_max]``; a positive number.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
            The axes drawn on.
        """
        import numpy as np

        from .. import numeric

        ax = new_axes(ax)
        expr = numeric.bind(self.response, values or {})
        fn = numeric.compile(expr, [self.t])
        ts = np.linspace(1e-9, t_max, 400)
        ys = fn(ts)
        for k in range(ys.shape[-2]):
            ax.plot(ts, ys[:, k, 0], label=f"y{k + 1}")
        ax.set_xlabel("t")
        ax.legend()
        return ax


def _as_matrix(a, name: str) -> sp.Matrix:
    """``a`` (a matrix, nested list or scalar expression) as a Matrix of finite expressions."""
    if isinstance(a, sp.MatrixBase | list | tuple):
        try:
            out = sp.Matrix(a)
        except (TypeError, ValueError, sp.SympifyError) as exc:
            raise ParameterError(f"{name} must be a matrix of expressions: {exc}") from None
        for entry in out:
            check_expression(entry, f"an entry of {name}")
        return out
    return sp.Matrix([[check_expression(a, name)]])


def _coeffs(poly_expr, var) -> list:
    """Coefficients c_r of sum c_r var**r (index = power)."""
    poly = sp.Poly(poly_expr, var)
    return list(reversed(poly.all_coeffs())) if not poly.is_zero else [0]


def _initial_poly(mat: sp.Matrix, var, p, derivs: list[list]) -> sp.Matrix:
    """(mat(p) - mat(D0))/(p - D0) applied to the initial values: sum_r c_r sum_{j<r} p**(r-1-j) z^(j)(0)."""
    rows = []
    for i in range(mat.rows):
        total = sp.S.Zero
        for k in range(mat.cols):
            for r, c in enumerate(_coeffs(mat[i, k], var)):
                for j in range(r):
                    if c != 0:
                        total += c * p ** (r - 1 - j) * derivs[k][j]
        rows.append(sp.expand(total))
    return sp.Matrix(rows)


def _split(expr, p) -> tuple[sp.Expr, sp.Expr]:
    """Polynomial part and proper remainder of a rational function of p."""
    num, den = sp.fraction(sp.cancel(sp.together(expr)))
    q, r = sp.div(sp.Poly(num, p), sp.Poly(den, p))
    return q.as_expr(), sp.cancel(r.as_expr() / den)


def _apply_poly(poly_expr, p, x, t):
    return sp.Add(*[c * sp.diff(x, t, r) for r, c in enumerate(_coeffs(poly_expr, p))])


@validated
def solve_operational(
    f,
    e,
    inputs=None,
    initial=None,
    *,
    D: sp.Symbol | None = None,
    t: sp.Symbol = _t,
    p: sp.Symbol | None = None,
    roots: str = "exact",
) -> OperationalSolution:
    """Solve ``f(D) y = e(D) x(t)`` operationally (Bulgakov 2.75–2.99).

    Parameters
    ----------
    f : Matrix or Expr
        ``n x n`` matrix (or scalar) of polynomials in the operator symbol ``D`` (``D = d/dt``).
    e : Matrix or Expr
        ``n x r`` matrix (or scalar / column) of polynomials in ``D``.
    inputs : sequence of Expr, optional
        ``x_1(t) .. x_r(t)``.  Default: undefined functions ``x1(t), ...``; their initial derivatives then appear
        as symbols ``x1_0, x1_1, ...``.
    initial : sequence of sequences, optional
        ``initial[k] = [y_k(0), y_k'(0), ..., y_k^(m_k - 1)(0)]``.  Default: symbols ``y1_0, y1_1, ...``.
    D, t, p : Symbol
        Operator symbol (default ``Symbol("D")``), time, image variable (default ``Symbol("p")``).
    roots : {"exact", "numeric"}
        Poles of ``1/Delta`` exact (radicals/``CRootOf``) or as 30-digit numbers (real form, compilable).

    Returns
    -------
    OperationalSolution

    Raises
    ------
    ModelError
        If ``det f`` vanishes identically or shapes do not match.

    See Also
    --------
    carson
    inverse_carson
    to_transfer_function

    Examples
    --------
    A damped oscillator ``y'' + 3 y' + 2 y = x`` under a unit step, at rest:

    >>> import sympy as sp
    >>> D, t = sp.symbols("D t")
    >>> sol = solve_operational(D**2 + 3 * D + 2, 1, [sp.Integer(1)], [[0, 0]], D=D, t=t)
    >>> sol.response[0]
    1/2 - exp(-t) + exp(-2*t)/2
    >>> sol.impulse[0]
    exp(-t) - exp(-2*t)
    """
    D = sp.Symbol("D") if D is None else D
    p = sp.Symbol("p") if p is None else p
    fm, em = _as_matrix(f, "f"), _as_matrix(e, "e")
    if em.rows == 1 and em.cols > 1 and fm.rows > 1:
        em = em.T
    n = fm.rows
    if not fm.is_square:
        raise ModelError(f"f(D) must be square, got shape {fm.shape}")
    if em.rows != n:
        raise ModelError(f"e(D) must have {n} rows (one per equation), got shape {em.shape}")
    for entry in list(fm) + list(em):
        if not sp.sympify(entry).is_polynomial(D):
            raise ModelError(f"entries of f(D), e(D) must be polynomials in {D}; got {entry}")
    r = em.cols
    fp, ep = fm.subs(D, p), em.subs(D, p)
    delta = sp.expand(fp.det(method="berkowitz"))
    if delta == 0:
        raise ModelError("det f(D) vanishes identically: the system is singular (dependent equations)")
    s = sp.degree(delta, p)
    adj = fp.adjugate(method="berkowitz").applyfunc(sp.expand)
    orders = tuple(max(sp.degree(fm[i, k], D) if fm[i, k] != 0 else 0 for i in range(n)) for k in range(n))

    # inputs and their initial derivatives
    e_orders = [max(sp.degree(em[i, j], D) if em[i, j] != 0 else 0 for i in range(n)) for j in range(r)]
    x_syms: list = []
    if inputs is None:
        xs = [sp.Function(f"x{j + 1}")(t) for j in range(r)]
    else:
        xs = [sp.sympify(x) for x in (inputs if isinstance(inputs, (list, tuple, sp.MatrixBase)) else [inputs])]
        if len(xs) != r:
            raise ParameterError(f"expected {r} inputs (columns of e), got {len(xs)}")
    # deg S <= deg F + deg e - s, and constraints need S(D) x up to derivative m_k - 1
    max_x_order = n * max(orders) + max(e_orders) + 1
    x_derivs = []
    for x in xs:
        row = []
        for q in range(max_x_order):
            if isinstance(x, sp.core.function.AppliedUndef):
                sym = sp.Symbol(f"{x.func.__name__}_{q}")
                x_syms.append(sym)
                row.append(sym)
            else:
                row.append(_value_at_zero(sp.diff(x, t, q), t))
        x_derivs.append(row)
    # initial values of y: always symbols y1_0, y1_1, ...; given numbers are substituted at the end
    y_derivs = [[sp.Symbol(f"y{k + 1}_{j}") for j in range(orders[k])] for k in range(n)]
    given: dict = {}
    if initial is not None:
        if len(initial) != n:
            raise ParameterError(f"initial must hold one list per unknown ({n}), got {len(initial)}")
        for k, vals in enumerate(initial):
            vals = list(vals)
            if len(vals) != orders[k]:
                raise ParameterError(f"y{k + 1} has derivative order {orders[k]}: give {orders[k]} initial values")
            for j, v in enumerate(vals):
                v = sp.sympify(v)
                if v != y_derivs[k][j]:
                    given[y_derivs[k][j]] = v
    y_syms = [v for row in y_derivs for v in row]
    # pivot order for the constraints: highest derivatives first (they are the ones fixed by lower ones)
    pivot_order = [y_derivs[k][j] for j in reversed(range(max(orders))) for k in reversed(range(n)) if j < orders[k]]
    qv = _initial_poly(fm, D, p, y_derivs)
    pv = _initial_poly(em, D, p, x_derivs)
    w = (adj * (qv - pv)) / delta
    mu = sp.Matrix([_split(w[i], p)[1] for i in range(n)])
    transfer = (adj * ep / delta).applyfunc(sp.cancel)
    split = [[_split(transfer[i, j], p) for j in range(r)] for i in range(n)]
    smat = sp.Matrix(n, r, lambda i, j: sp.expand(split[i][j][0]))
    nu = sp.Matrix(n, r, lambda i, j: split[i][j][1])

    free = heaviside_expand(mu * p, p, t, roots=roots).applyfunc(sp.expand)
    impulse = heaviside_expand(nu * p, p, t, roots=roots).applyfunc(sp.expand)
    step = (smat.subs(p, 0) + heaviside_expand(nu, p, t, roots=roots)).applyfunc(sp.expand)

    response = []
    for i in range(n):
        yi = free[i]
        for j in range(r):
            yi += _apply_poly(smat[i, j], p, xs[j], t)
            yi += _convolve(nu[i, j], impulse[i, j], xs[j], p, t, roots)
        response.append(yi)
    response = sp.Matrix(response)

    constraints: tuple = ()
    m = sum(orders)
    if s < m:
        constraints = _constraints(free, impulse, smat, x_derivs, y_derivs, orders, p, t, pivot_order + x_syms)
    return OperationalSolution(
        response=response.subs(given),
        free=free.subs(given),
        feedthrough=smat,
        impulse=impulse,
        step=step,
        transfer=transfer,
        delta=delta,
        adjugate=adj,
        orders=orders,
        degree=s,
        initial_symbols=tuple(y_syms + x_syms),
        constraints=constraints,
        initial_values=given,
        p=p,
        t=t,
    )


def _value_at_zero(expr, t):
    val = expr.subs(t, 0)
    if val.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        val = sp.limit(expr, t, 0, "+")
    return val


def _convolve(nu_ij, n_ij, x, p, t, roots="exact"):
    """Integral(N(t-u) x(u), (u, 0, t)) via the image nu * X when x has a table image, else as an Integral."""
    if nu_ij == 0 or x == 0:
        return sp.S.Zero
    if not isinstance(x, sp.core.function.AppliedUndef):
        try:
            image = carson_by_table(x, t, p)
        except _Unsupported:
            image = None
        if image is not None:
            prod = sp.cancel(nu_ij * image) if image.is_rational_function(p) else nu_ij * image
            return sp.expand(inverse_carson(prod, p, t, roots=roots))
    u = sp.Dummy("u")
    return sp.Integral(n_ij.subs(t, t - u) * x.subs(t, u), (u, 0, t))


def _constraints(free, impulse, smat, x_derivs, y_derivs, orders, p, t, unknowns) -> tuple:
    """Relations y_k^(j)(0) = y_k^(j)(0+) among the initial data, reduced to an independent set."""
    n, r = smat.shape
    eqs = []
    for k in range(n):
        for j in range(orders[k]):
            at0 = sp.diff(free[k], t, j).subs(t, 0)
            for l in range(r):
                for q, c in enumerate(_coeffs(smat[k, l], p)):
                    at0 += c * x_derivs[l][q + j]
                for i in range(j):
                    at0 += sp.diff(impulse[k, l], t, i).subs(t, 0) * x_derivs[l][j - 1 - i]
            eqs.append(sp.expand(y_derivs[k][j] - at0))
    syms = [s for s in unknowns if any(eq.has(s) for eq in eqs)]
    if not syms:
        return tuple(sp.Eq(eq, 0) for eq in eqs if eq != 0)
    a, b = sp.linear_eq_to_matrix(eqs, syms)
    aug = a.row_join(b)
    rref, pivots = aug.rref(simplify=True)
    out = []
    for row in range(len(pivots)):
        if pivots[row] >= len(syms):
            raise ModelError("the initial-value relations are contradictory for these inputs")
        lhs = syms[pivots[row]]
        rhs = rref[row, -1] - sum(rref[row, c] * syms[c] for c in range(len(syms)) if c != pivots[row])
        out.append(sp.Eq(lhs, sp.expand(rhs)))
    return tuple(out)
