"""The table of Carson images of Bulgakov §2.18 and a rewrite engine for quasi-polynomials.

Every entry of :data:`CARSON_TABLE` is checked in ``tests/operational/test_table.py`` against
``p * sympy.laplace_transform`` or, for the step functions, against direct integration.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from .._printing import SymPyPrintable
from .._validate import validated
from ..symbols import t as _t
from ._rational import check_expression, check_symbol

__all__ = ["CARSON_TABLE", "TableEntry", "carson_by_table", "carson_matrix_exp", "table_entry"]

# Symbols of the table (positive where the book assumes them so; m is a non-negative integer).
_p = sp.Symbol("p")
_m = sp.Symbol("m", integer=True, nonnegative=True)
_l = sp.Symbol("lambda", real=True)
_eps = sp.Symbol("epsilon", real=True)
_w = sp.Symbol("omega", positive=True)
_tau = sp.Symbol("tau", positive=True)
_a = sp.Symbol("a", positive=True)
_b = sp.Symbol("b", positive=True)
_tau0 = sp.Symbol("tau0", positive=True)


@dataclass(frozen=True)
class TableEntry(SymPyPrintable):
    """One row of the table of images: ``original(t) <-> image(p)`` (Carson: image = p * Laplace[original]).

    Attributes
    ----------
    name : str
        Short name of the pair, such as ``"damped sine"``.
    equation : str
        Equation number in Bulgakov (1954), ch. 2, such as ``"(2.55)"``.
    original : Expr
        The original ``x(t)``, valid for ``t > 0`` (in ``symosc.t``).
    image : Expr
        Its Carson image ``X(p)``.
    params : tuple of Symbol
        The parameters of the pair (``m``, ``lambda``, ``omega``, ``tau``, ...), with the assumptions the book
        makes (positive, real, non-negative integer).
    note : str
        Conditions or remarks (empty when none).
    """

    name: str
    equation: str
    original: sp.Expr
    image: sp.Expr
    params: tuple[sp.Symbol, ...] = field(default=())
    note: str = ""

    def __repr__(self) -> str:
        return f"TableEntry({self.name!r}, {self.equation}: {self.original} <-> {self.image})"

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(self.original)} \\;\\risingdotseq\\; {sp.latex(self.image)}$$"

    def substitute(self, values: dict) -> tuple[sp.Expr, sp.Expr]:
        """``(original, image)`` with parameter values substituted (keys: Symbol or name).

        Parameters
        ----------
        values : mapping of Symbol or name to number or Expr
            Values of some or all of :attr:`params` (keys are the symbols or their names; other keys are ignored).

        Returns
        -------
        (original, image) : tuple of Expr
            The pair with the values substituted.
        """
        sub = {}
        for k, v in values.items():
            name = k.name if isinstance(k, sp.Symbol) else str(k)
            for s in self.params:
                if s.name == name:
                    sub[s] = sp.sympify(v)
        return self.original.xreplace(sub).doit(), self.image.xreplace(sub).doit()


_floor_n = sp.floor(_t / _tau)
_gamma = sp.exp(_p * _tau)

#: The table of §2.18 (and the general-m rows 2.146–2.149 of §2.31).  Originals hold for ``t > 0``.
CARSON_TABLE: tuple[TableEntry, ...] = (
    TableEntry("unit step", "(2.7)", sp.S.One, sp.S.One),
    TableEntry("power", "(2.50)", _t**_m / sp.factorial(_m), 1 / _p**_m, (_m,)),
    TableEntry("exponential", "(2.51)", sp.exp(_l * _t), _p / (_p - _l), (_l,)),
    TableEntry(
        "power times exponential",
        "(2.52)",
        _t**_m * sp.exp(_l * _t) / sp.factorial(_m),
        _p / (_p - _l) ** (_m + 1),
        (_m, _l),
    ),
    TableEntry(
        "damped cosh",
        "(2.54)",
        sp.exp(_eps * _t) * sp.cosh(_l * _t),
        _p * (_p - _eps) / ((_p - _eps) ** 2 - _l**2),
        (_eps, _l),
    ),
    TableEntry(
        "damped sinh", "(2.54)", sp.exp(_eps * _t) * sp.sinh(_l * _t), _p * _l / ((_p - _eps) ** 2 - _l**2), (_eps, _l)
    ),
    TableEntry(
        "damped cosine",
        "(2.55)",
        sp.exp(_eps * _t) * sp.cos(_w * _t),
        _p * (_p - _eps) / ((_p - _eps) ** 2 + _w**2),
        (_eps, _w),
    ),
    TableEntry(
        "damped sine", "(2.55)", sp.exp(_eps * _t) * sp.sin(_w * _t), _p * _w / ((_p - _eps) ** 2 + _w**2), (_eps, _w)
    ),
    TableEntry("cosh", "(2.56)", sp.cosh(_l * _t), _p**2 / (_p**2 - _l**2), (_l,)),
    TableEntry("sinh", "(2.56)", sp.sinh(_l * _t), _p * _l / (_p**2 - _l**2), (_l,)),
    TableEntry("cosine", "(2.57)", sp.cos(_w * _t), _p**2 / (_p**2 + _w**2), (_w,)),
    TableEntry("sine", "(2.57)", sp.sin(_w * _t), _p * _w / (_p**2 + _w**2), (_w,)),
    TableEntry("delayed step", "(2.58)", sp.Heaviside(_t - _tau), sp.exp(-_p * _tau), (_tau,)),
    TableEntry(
        "rectangular pulse",
        "(2.59)",
        sp.Heaviside(_t - _a) - sp.Heaviside(_t - _b),
        sp.exp(-_p * _a) - sp.exp(-_p * _b),
        (_a, _b),
        "a < b",
    ),
    TableEntry(
        "step train",
        "(2.61)",
        sp.Heaviside(_t - _tau0) * (sp.floor((_t - _tau0) / _tau) + 1),
        sp.exp(-_p * _tau0) / (1 - sp.exp(-_p * _tau)),
        (_tau0, _tau),
        "sum_j 1(t - tau0 - j tau)",
    ),
    TableEntry("staircase", "(2.62)", _floor_n, 1 / (_gamma - 1), (_tau,)),
    TableEntry(
        "sawtooth",
        "(2.63)",
        _t - _tau * _floor_n,
        1 / _p - _tau / (_gamma - 1),
        (_tau,),
        "reconstructed: the printed formula is illegible",
    ),
    TableEntry(
        "geometric steps", "(2.69)", _l**_floor_n, (_gamma - 1) / (_gamma - _l), (_l, _tau), "A(t) = 1 in (2.69)"
    ),
    TableEntry(
        "binomial steps",
        "(2.71)",
        sp.binomial(_floor_n, _m) * _l ** (_floor_n - _m),
        (_gamma - 1) / (_gamma - _l) ** (_m + 1),
        (_m, _l, _tau),
        "A(t) = 1 in (2.71); also (2.117)",
    ),
    TableEntry(
        "power times damped cosh",
        "(2.146)",
        _t**_m * sp.exp(_eps * _t) * sp.cosh(_l * _t) / sp.factorial(_m),
        _p / 2 * (1 / (_p - _eps + _l) ** (_m + 1) + 1 / (_p - _eps - _l) ** (_m + 1)),
        (_m, _eps, _l),
    ),
    TableEntry(
        "power times damped sinh",
        "(2.147)",
        _t**_m * sp.exp(_eps * _t) * sp.sinh(_l * _t) / sp.factorial(_m),
        _p / 2 * (1 / (_p - _eps - _l) ** (_m + 1) - 1 / (_p - _eps + _l) ** (_m + 1)),
        (_m, _eps, _l),
    ),
    TableEntry(
        "power times damped cosine",
        "(2.148)",
        _t**_m * sp.exp(_eps * _t) * sp.cos(_w * _t) / sp.factorial(_m),
        _p / 2 * (1 / (_p - _eps - sp.I * _w) ** (_m + 1) + 1 / (_p - _eps + sp.I * _w) ** (_m + 1)),
        (_m, _eps, _w),
        "= p Re[(p - eps + i w)**(m+1)] / ((p - eps)**2 + w**2)**(m+1) for real p",
    ),
    TableEntry(
        "power times damped sine",
        "(2.149)",
        _t**_m * sp.exp(_eps * _t) * sp.sin(_w * _t) / sp.factorial(_m),
        _p / (2 * sp.I) * (1 / (_p - _eps - sp.I * _w) ** (_m + 1) - 1 / (_p - _eps + sp.I * _w) ** (_m + 1)),
        (_m, _eps, _w),
        "= p Im[(p - eps + i w)**(m+1)] / ((p - eps)**2 + w**2)**(m+1) for real p",
    ),
)


@validated
def table_entry(name: str) -> TableEntry:
    """The entry of :data:`CARSON_TABLE` called ``name`` (or with equation number ``name``, e.g. ``"(2.52)"``).

    Parameters
    ----------
    name : str
        Name of an entry of CARSON_TABLE (such as ``"sine"`` or ``"damped cosine"``) or its equation number
        (such as ``"(2.52)"``); it must be one of them.

    Returns
    -------
    TableEntry

    Examples
    --------
    >>> table_entry("sine").image
    omega*p/(omega**2 + p**2)
    """
    for entry in CARSON_TABLE:
        if name in (entry.name, entry.equation):
            return entry
    names = ", ".join(e.name for e in CARSON_TABLE)
    raise KeyError(f"no table entry {name!r}; entries: {names}")


class _Unsupported(Exception):
    """The rewrite engine cannot transform this term (the caller falls back to SymPy)."""


@validated
def carson_by_table(x, t: sp.Symbol = _t, p: sp.Symbol = _p):
    """Carson image of a quasi-polynomial with delayed steps, by the rules (2.52), (2.26a) and linearity.

    ``x`` may be any sum of terms ``c * t**k * exp(l t) * {cos, sin, cosh, sinh}(w t) * Heaviside(t - tau)``
    (products and powers of the trigonometric factors included).  Trigonometric and hyperbolic functions are
    written as exponentials, each term is mapped by ``t**k exp(l t) <-> k! p/(p - l)**(k+1)``, delayed terms by
    ``x(t - tau) 1(t - tau) <-> exp(-p tau) X(p)``, and the rational part is put over a common denominator.

    Raises ``_Unsupported`` (private) for anything else; :func:`symosc.operational.carson` then asks SymPy.

    Parameters
    ----------
    x : Expr or Matrix
        Original: a quasi-polynomial in ``t``, possibly with delayed steps ``Heaviside(t - tau)``, ``tau >= 0`` (a
        Matrix is transformed entry by entry).
    t : Symbol
        Time, the variable of ``x`` (default ``symosc.t``).
    p : Symbol
        The image variable (default ``Symbol("p")``).

    Returns
    -------
    Expr or Matrix
        The Carson image.

    Examples
    --------
    >>> import sympy as sp
    >>> p, t = sp.symbols("p t")
    >>> carson_by_table(t * sp.exp(-t) + sp.sin(2 * t), t, p)
    p*(3*p**2 + 4*p + 6)/((p + 1)**2*(p**2 + 4))
    """
    t, p = check_symbol(t, "t"), check_symbol(p, "p")
    if isinstance(x, sp.MatrixBase):
        return x.applyfunc(lambda e: carson_by_table(e, t, p))
    x = check_expression(x, "x")
    if not x.has(t):
        return x
    delayed: dict[sp.Expr, sp.Expr] = {}
    for term in sp.Add.make_args(sp.expand(x)):
        steps = [f for f in sp.Mul.make_args(term) if isinstance(f, sp.Heaviside)]
        if len(steps) > 1:
            raise _Unsupported("products of steps")
        if steps:
            arg = steps[0].args[0]
            tau = -(arg - t)
            if tau.has(t) or sp.expand(arg - (t - tau)) != 0 or tau.is_negative:
                raise _Unsupported("step argument must be t - tau with tau >= 0")
            rest = term / steps[0]
            delayed[tau] = delayed.get(tau, 0) + rest.subs(t, t + tau)
        else:
            delayed[sp.S.Zero] = delayed.get(sp.S.Zero, 0) + term
    out = sp.S.Zero
    for tau, part in delayed.items():
        out += sp.exp(-p * tau) * _quasi_polynomial_image(part, t, p)
    return out


def _quasi_polynomial_image(x, t, p):
    expr = sp.expand(sp.sympify(x).rewrite(sp.exp), power_base=False, mul=True, multinomial=True)
    total = sp.S.Zero
    for term in sp.Add.make_args(expr):
        coeff, rest = term.as_independent(t, as_Add=False)
        rest = sp.powsimp(rest, combine="exp")
        k, lam = 0, sp.S.Zero
        for f in sp.Mul.make_args(rest):
            if f == t:
                k += 1
            elif f.is_Pow and f.base == t and f.exp.is_Integer and f.exp > 0:
                k += int(f.exp)
            elif isinstance(f, sp.exp) or (f.is_Pow and f.base == sp.E):
                arg = sp.expand(f.exp if f.is_Pow else f.args[0])
                lin = sp.Poly(arg, t) if arg.is_polynomial(t) else None
                if lin is None or lin.degree() > 1:
                    raise _Unsupported(f"exponent {arg} not linear in t")
                c1, c0 = lin.all_coeffs() if lin.degree() == 1 else (0, lin.as_expr())
                lam += c1
                coeff *= sp.exp(c0)
            elif f == 1:
                continue
            else:
                raise _Unsupported(f"factor {f}")
        total += coeff * sp.factorial(k) * p / (p - lam) ** (k + 1)
    result = sp.factor(sp.cancel(total), p) if total.is_rational_function(p) else total
    if result.has(sp.I):
        result = _clear_imaginary_unit(result, p)
    return result


def _clear_imaginary_unit(result, p):
    """Real form of an image that is real for real p and real parameters (I left over from cos/sin phases)."""
    real = {s: sp.Dummy(s.name, real=True) for s in result.free_symbols}
    back = {v: k for k, v in real.items()}
    re_part, im_part = sp.expand_complex(result.xreplace(real)).as_real_imag()
    for trial in (0.37, 1.91):
        probe = {d: trial + 0.1 * i for i, d in enumerate(real.values())}
        if abs(complex(im_part.subs(probe))) > 1e-12 * (1 + abs(complex(re_part.subs(probe)))):
            return result
    if sp.simplify(im_part) != 0:
        return result
    num, den = sp.fraction(sp.cancel(re_part.xreplace(back)))
    num = sp.Poly(num, p)
    num = sum(sp.simplify(c) * p**k for (k,), c in num.terms())  # trig identities of the phases
    return sp.factor(num, p) / sp.factor(den, p)


@validated
def carson_matrix_exp(a, p: sp.Symbol = _p):
    """Carson image of the matrix exponential, ``exp(a t) <-> p (E p - a)**-1`` (Bulgakov 2.53).

    Parameters
    ----------
    a : Matrix or nested list
        Square constant matrix (exact or symbolic entries).
    p : Symbol
        The image variable (default ``Symbol("p")``).

    Returns
    -------
    Matrix
        ``p (E p - a)**-1`` with each entry factored in ``p``.

    Examples
    --------
    >>> import sympy as sp
    >>> p = sp.Symbol("p")
    >>> carson_matrix_exp(sp.Matrix([[0, 1], [-1, 0]]), p).tolist()
    [[p**2/(p**2 + 1), p/(p**2 + 1)], [-p/(p**2 + 1), p**2/(p**2 + 1)]]
    """
    a = sp.Matrix(a)
    if not a.is_square:
        from ..errors import ModelError

        raise ModelError(f"exp(a t) needs a square matrix, got shape {a.shape}")
    n = a.shape[0]
    res = (sp.eye(n) * p - a).adjugate() * p / (sp.eye(n) * p - a).det()
    return res.applyfunc(lambda e: sp.factor(sp.cancel(e), p))
