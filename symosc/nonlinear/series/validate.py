"""Numerical reference solutions for the series methods: limit cycles by shooting, periods by integration.

The original equation ``x'' + x = eps*f(x, x')`` is compiled with :func:`symosc.numeric.compile` (right-hand side
and Jacobian) and integrated with SciPy (``DOP853`` for moderate ``eps``, ``LSODA``/``Radau`` with the analytic
Jacobian in the stiff relaxation regime) or, for reference values to many digits, with :func:`mpmath.odefun` (Taylor
series).  The cycle is found on the Poincaré section ``v = 0, x > 0``: the return map ``x0 -> P(x0)`` is composed of
two event-located half-swings, and ``P(x0) = x0`` is solved by a Newton/secant iteration (the Floquet multiplier
gives the slope), or by the secant method in mpmath.  The nontrivial
Floquet multiplier comes from integrating the divergence ``eps*f_v`` along the orbit.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ..._plotting import plot_method
from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_positive, validated
from ...errors import ConvergenceError, ParameterError, SeriesWarning
from ...numeric import compile as _compile
from .. import _checks

__all__ = [
    "NumericCycle",
    "SeriesValidation",
    "numeric_limit_cycle",
    "numeric_orbit",
    "numeric_period",
    "validate_limit_cycle",
    "validate_lindstedt",
]

_X, _V = sp.Symbol("x"), sp.Symbol("v")
_EPS = sp.Symbol("eps")


@dataclass(frozen=True)
class NumericCycle(SymPyPrintable):
    """A limit cycle located numerically on the section ``v = 0, x > 0``.

    Attributes
    ----------
    eps : float
        The value of the small parameter at which the cycle was located.
    amplitude : float or mpf
        ``x`` at the section (the turning point).
    period, frequency : float or mpf
        Period and ``2 pi/period``.
    multiplier : float or None
        Nontrivial Floquet multiplier ``exp(int eps f_v dt)`` (stable when < 1).
    residual : float
        ``|P(x0) - x0|`` at the solution.
    method : str
        Integrator used.
    stiff : bool
        Whether the stiff integrator was chosen.
    """

    eps: float
    amplitude: Any
    period: Any
    frequency: Any
    multiplier: float | None
    residual: float
    method: str
    stiff: bool


def _rhs_functions(f: Any, x: sp.Symbol, v: sp.Symbol, eps: sp.Symbol, backend: str, dps: int | None = None) -> Any:
    f = _checks.expression("f", f)
    x, v, eps = _checks.symbol("x", x), _checks.symbol("v", v), _checks.symbol("eps_symbol", eps)
    extra = f.free_symbols - {x, v, eps}
    if extra:
        raise ParameterError(f"f depends on {', '.join(sorted(s.name for s in extra))}: substitute numbers first")
    fv = sp.diff(f, v)
    field = [v, -x + eps * f, eps * fv]
    rhs = _compile(field, [x, v, eps], backend=backend, dps=dps, check=False, name="_cycle_rhs")
    jac = None
    if backend == "numpy":
        J = sp.Matrix(field[:2]).jacobian([x, v])
        jac = _compile(J, [x, v, eps], check=False, name="_cycle_jac")
    return rhs, jac


def _half_swings(rhs: Any, jac: Any, eps: float, x0: float, method: str, rtol: float, tmax: float) -> tuple:
    """Integrate from (x0, 0) to the next crossing of v = 0 from above (two event-located half swings)."""

    def fun(t: float, y: np.ndarray) -> np.ndarray:
        return np.asarray(rhs.raw(y[0], y[1], eps), dtype=float)

    kwargs: dict[str, Any] = {"method": method, "rtol": rtol, "atol": rtol * 1e-2}
    if method in ("Radau", "BDF", "LSODA"):

        def jfun(t: float, y: np.ndarray) -> np.ndarray:
            out = np.zeros((3, 3))
            out[:2, :2] = jac.raw(y[0], y[1], eps)
            return out

        kwargs["jac"] = jfun

    def ev_up(t: float, y: np.ndarray) -> float:
        return y[1]

    ev_up.terminal = True  # type: ignore[attr-defined]
    ev_up.direction = 1  # type: ignore[attr-defined]

    def ev_down(t: float, y: np.ndarray) -> float:
        return y[1]

    ev_down.terminal = True  # type: ignore[attr-defined]
    ev_down.direction = -1  # type: ignore[attr-defined]
    from scipy.integrate import solve_ivp

    s1 = solve_ivp(fun, (0.0, tmax), [x0, 0.0, 0.0], events=ev_up, **kwargs)
    if s1.status != 1:
        raise ConvergenceError(
            f"no turning point within t = {tmax} (eps = {eps}, x0 = {x0}): the orbit does not oscillate"
        )
    t1, y1 = s1.t_events[0][0], s1.y_events[0][0]
    s2 = solve_ivp(fun, (t1, t1 + tmax), [y1[0], 0.0, y1[2]], events=ev_down, **kwargs)
    if s2.status != 1:
        raise ConvergenceError(f"no second turning point within t = {tmax} (eps = {eps})")
    t2, y2 = s2.t_events[0][0], s2.y_events[0][0]
    return t2, y2[0], y2[2]


@validated
def numeric_limit_cycle(
    f: Any,
    eps: float,
    *,
    x: sp.Symbol = _X,
    v: sp.Symbol = _V,
    eps_symbol: sp.Symbol = _EPS,
    guess: float = 2.0,
    method: str = "auto",
    rtol: float = 1e-12,
    dps: int | None = None,
) -> NumericCycle:
    """Locate the limit cycle of ``x'' + x = eps*f(x, v)`` by shooting on the section ``v = 0, x > 0``.

    Parameters
    ----------
    f : Expr
        Right-hand side ``f(x, v)`` of ``x'' + x = eps*f``, an expression in ``x``, ``v`` (and ``eps``) with no other
        free symbols (substitute numbers for parameters first).
    eps : float
        Value of the small parameter ``eps``; a finite real number (``|eps| >= 3`` selects the stiff integrator).
    x : Symbol, optional
        Symbol of the coordinate in ``f`` (default ``x``).
    v : Symbol, optional
        Symbol of the velocity ``x'`` in ``f`` (default ``v``).
    eps_symbol : Symbol, optional
        Symbol of the small parameter when ``f`` contains it (default ``eps``).
    guess : float
        Amplitude guess (the generating amplitude or the series value); a positive number.
    method : str
        ``"auto"`` (``DOP853`` for ``|eps| < 3``, ``LSODA`` with the analytic Jacobian otherwise: the relaxation
        regime is stiff; ``"Radau"`` also works but is about 10x slower here), or any
        :func:`scipy.integrate.solve_ivp` method.
    rtol : float
        Integration tolerance (the cycle is then accurate to about ``10*rtol``).
    dps : int, optional
        If given, polish the result with :func:`mpmath.odefun` at ``dps`` digits (slow; for reference values at
        moderate ``eps``).  Amplitude and period are then ``mpf``.

    See Also
    --------
    limit_cycle
    numeric_orbit
    numeric_period

    Examples
    --------
    >>> import sympy as sp
    >>> x, v = sp.symbols("x v")
    >>> cyc = numeric_limit_cycle((1 - x**2) * v, 0.1)
    >>> round(cyc.amplitude, 6), round(cyc.period, 5)
    (2.000104, 6.28711)
    """
    eps = float(eps)
    if not np.isfinite(eps):
        raise ParameterError(f"eps must be finite, got {eps}")
    stiff = abs(eps) >= 3.0
    if method == "auto":
        method = "LSODA" if stiff else "DOP853"
    rtol = max(rtol, 1e-10) if method in ("Radau", "BDF", "LSODA") else rtol
    rhs, jac = _rhs_functions(f, x, v, eps_symbol, "numpy")
    tmax = 50.0 + 10.0 * abs(eps)

    def ret(x0: float) -> tuple[float, float, float]:
        T, xr, integral = _half_swings(rhs, jac, eps, x0, method, rtol, tmax)
        return T, xr, integral

    # Newton-like iteration on P(x0) = x0 with the Floquet multiplier as the slope estimate; a strongly
    # contracting map (relaxation regime) converges in a couple of steps, a weakly contracting one needs the slope
    a = check_positive("guess (the amplitude guess, e.g. the series value)", guess)
    T, xr, integral = ret(a)
    prev = None
    for _ in range(60):
        m = float(np.exp(integral)) if integral < 700 else np.inf
        step = (xr - a) / (1.0 - m) if abs(1.0 - m) > 1e-12 else xr - a
        if prev is not None and abs(prev[0] - a) > 0 and abs(xr - a) > 1e-3 * abs(a) * rtol:
            # secant slope from the last two iterates is better than the multiplier off the cycle
            slope = ((xr - a) - prev[1]) / (a - prev[0])
            if np.isfinite(slope) and slope != 0:
                step = -(xr - a) / slope
        prev = (a, xr - a)
        a_new = a + step
        if not np.isfinite(a_new) or a_new <= 0:
            raise ConvergenceError(f"shooting for the limit cycle diverged (eps = {eps}, guess = {guess})")
        if abs(a_new - a) <= 10 * rtol * abs(a):
            a = a_new
            T, xr, integral = ret(a)
            break
        a = a_new
        T, xr, integral = ret(a)
    else:
        raise ConvergenceError(f"shooting for the limit cycle did not converge (eps = {eps})", achieved=abs(xr - a))
    res = abs(xr - a)
    if dps is None:
        return NumericCycle(
            eps, float(a), float(T), float(2 * np.pi / T), float(np.exp(integral)), float(res), method, stiff
        )
    return _polish_mpmath(f, x, v, eps_symbol, eps, a, T, dps, method, stiff)


def _polish_mpmath(f, x, v, eps_symbol, eps, a0, T0, dps, method, stiff) -> NumericCycle:
    rhs, _ = _rhs_functions(f, x, v, eps_symbol, "mpmath", dps=dps + 10)
    with mpmath.workdps(dps + 10):
        e = mpmath.mpf(eps)

        def flow(x0: Any) -> Any:
            return mpmath.odefun(lambda t, y: list(rhs.raw(y[0], y[1], e))[:2], 0, [x0, mpmath.mpf(0)])

        found: dict = {}  # findroot checks its root by one more evaluation: the final crossing is that one

        def crossing(x0: Any) -> tuple[Any, Any]:
            if x0 not in found:
                sol = flow(x0)
                T = mpmath.findroot(lambda t: sol(t)[1], mpmath.mpf(T0))
                found[x0] = T, sol(T)[0]
            return found[x0]

        a = mpmath.findroot(
            lambda x0: crossing(x0)[1] - x0, (mpmath.mpf(a0), mpmath.mpf(a0) * (1 + 1e-9)), tol=mpmath.mpf(10) ** (-dps)
        )
        T, xr = crossing(a)
        res = float(abs(xr - a))
        return NumericCycle(eps, +a, +T, 2 * mpmath.pi / T, None, res, f"mpmath.odefun(dps={dps})", stiff)


@validated
def numeric_orbit(
    f: Any,
    eps: float,
    *,
    x: sp.Symbol = _X,
    v: sp.Symbol = _V,
    eps_symbol: sp.Symbol = _EPS,
    guess: float = 2.0,
    samples: int = 400,
) -> tuple[np.ndarray, np.ndarray]:
    """Samples ``(x(t), v(t))`` over one period of the numerically located limit cycle (for plots).

    Parameters
    ----------
    f : Expr
        Right-hand side ``f(x, v)`` of ``x'' + x = eps*f``, an expression in ``x``, ``v`` (and ``eps``) with no other
        free symbols.
    eps : float
        Value of the small parameter ``eps``; a finite real number.
    x : Symbol, optional
        Symbol of the coordinate in ``f`` (default ``x``).
    v : Symbol, optional
        Symbol of the velocity ``x'`` in ``f`` (default ``v``).
    eps_symbol : Symbol, optional
        Symbol of the small parameter when ``f`` contains it (default ``eps``).
    guess : float, optional
        Amplitude guess for the shooting on the section ``v = 0, x > 0``; a positive number (default 2, the van der
        Pol generating amplitude).
    samples : int, optional
        Number of equally spaced time samples over the period, an integer >= 2 (default 400).

    Returns
    -------
    x, v : ndarray
        The coordinate and the velocity at the samples, starting at the turning point ``x = amplitude, v = 0``.

    See Also
    --------
    numeric_limit_cycle
    LimitCycleSeries.plot

    Examples
    --------
    >>> import sympy as sp
    >>> x, v = sp.symbols("x v")
    >>> xs, vs = numeric_orbit((1 - x**2) * v, 0.1, samples=50)
    >>> xs.shape, round(float(xs.max()), 4)
    ((50,), 2.0001)
    """
    cyc = numeric_limit_cycle(f, eps, x=x, v=v, eps_symbol=eps_symbol, guess=guess)
    rhs, jac = _rhs_functions(f, x, v, eps_symbol, "numpy")
    method = "LSODA" if cyc.stiff else "DOP853"
    kw: dict[str, Any] = {}
    if cyc.stiff:
        kw["jac"] = lambda t, y: np.pad(np.asarray(jac.raw(y[0], y[1], float(eps)), dtype=float), ((0, 1), (0, 1)))
    ts = np.linspace(0.0, cyc.period, samples)
    from scipy.integrate import solve_ivp

    sol = solve_ivp(
        lambda t, y: np.asarray(rhs.raw(y[0], y[1], float(eps)), dtype=float),
        (0.0, cyc.period),
        [cyc.amplitude, 0.0, 0.0],
        t_eval=ts,
        method=method,
        rtol=1e-10,
        atol=1e-12,
        **kw,
    )
    return sol.y[0], sol.y[1]


@validated
def numeric_period(
    f: Any, eps: float, A: float, *, x: sp.Symbol = _X, eps_symbol: sp.Symbol = _EPS, rtol: float = 1e-12
) -> float:
    """Period of ``x'' + x = eps*f(x)`` started at rest at ``x = A`` (two event-located half swings, DOP853).

    Parameters
    ----------
    f : Expr
        Restoring force ``f(x)`` of ``x'' + x = eps*f``, an expression in ``x`` (and ``eps``) with no other free
        symbols.
    eps : float
        Value of the small parameter ``eps``; a finite real number.
    A : float
        Starting displacement (the motion starts at rest at ``x = A``); a finite real number for which the orbit
        oscillates (otherwise ConvergenceError).
    x : Symbol, optional
        Symbol of the coordinate in ``f`` (default ``x``).
    eps_symbol : Symbol, optional
        Symbol of the small parameter when ``f`` contains it (default ``eps``).
    rtol : float, optional
        Relative tolerance of the integration, a positive number (default 1e-12).

    Returns
    -------
    float
        The period (time between two successive turning points on the same side).

    Examples
    --------
    >>> import sympy as sp
    >>> round(numeric_period(sp.Integer(0) * sp.Symbol("x"), 0.3, 1.0), 10)
    6.2831853072
    """
    eps, A, rtol = check_finite("eps", eps), check_finite("A", A), check_positive("rtol", rtol)
    rhs, jac = _rhs_functions(sp.sympify(f), x, sp.Symbol("_v_unused"), eps_symbol, "numpy")
    T, _, _ = _half_swings(rhs, jac, float(eps), float(A), "DOP853", rtol, 1e3)
    return float(T)


@dataclass(frozen=True)
class SeriesValidation(SymPyPrintable):
    """Truncated series against the numerical cycle/period.

    Attributes
    ----------
    rows : tuple of dict
        One dict per (eps, order) with the series and numeric values, the errors, the size of the last term included
        (a proxy for the truncation error while the series converges) and ``in_validity`` (False when ``|eps|``
        exceeds the estimated radius of convergence: the series is then not meaningful and only the numeric value
        stands).
    radius : float or None
        Estimated radius of convergence of the frequency series (None when it could not be estimated or was not
        computed).
    """

    rows: tuple
    radius: float | None

    def table(self) -> str:
        """A plain-text table."""
        head = (
            f"{'eps':>6} {'order':>5} {'amp series':>14} {'amp numeric':>14} {'amp err':>9} "
            f"{'omega err':>9} {'Pade err':>9} {'last term':>9}  note"
        )
        lines = [head]
        for r in self.rows:
            note = "" if r["in_validity"] else "outside series validity (|eps| > radius)"
            lines.append(
                f"{r['eps']:>6g} {r['order']:>5d} {r['amplitude_series']:>14.10f} {r['amplitude_numeric']:>14.10f} "
                f"{r['amplitude_error']:>9.2e} {r['frequency_error']:>9.2e} "
                f"{r.get('frequency_pade_error', float('nan')):>9.2e} "
                f"{r['last_term']:>9.2e}  {note}"
            )
        return "\n".join(lines)

    def __repr__(self) -> str:
        return "SeriesValidation(\n" + self.table() + f"\n radius of convergence estimate: {self.radius})"

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Frequency error vs order for each eps (log scale).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from ..._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        for e in sorted({r["eps"] for r in self.rows}):
            rs = [r for r in self.rows if r["eps"] == e]
            ax.semilogy(
                [r["order"] for r in rs], [max(r["frequency_error"], 1e-17) for r in rs], "o-", label=f"eps={e}"
            )
        ax.set_xlabel("truncation order")
        ax.set_ylabel("|omega_series - omega_numeric|")
        ax.legend()
        return ax


@validated
def validate_limit_cycle(
    lc: Any, eps_values: Any, *, orders: Any = None, rtol: float = 1e-12, dps: int | None = None
) -> SeriesValidation:
    """Compare a :class:`~symosc.nonlinear.LimitCycleSeries` with the numerical limit cycle at each ``eps``.

    Parameters
    ----------
    lc : LimitCycleSeries
        The series to check, as returned by :func:`limit_cycle`.
    eps_values : float or sequence of float
        Values of the small parameter at which to compare; finite real numbers.
    orders : sequence of int, optional
        Truncation orders to tabulate (default: ``lc.order`` only).
    rtol : float
        Integration tolerance.
    dps : int, optional
        Use the mpmath reference (see :func:`numeric_limit_cycle`).

    See Also
    --------
    limit_cycle
    numeric_limit_cycle

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.nonlinear import limit_cycle
    >>> x, v = sp.symbols("x v")
    >>> val = validate_limit_cycle(limit_cycle((1 - x**2) * v, 8), [0.1])
    >>> val.rows[0]["frequency_error"] < 1e-12
    True
    """
    eps_list = np.atleast_1d(np.asarray(eps_values, dtype=float)).tolist()
    orders = [lc.order] if orders is None else [int(o) for o in orders]
    try:
        radius = float(lc.frequency.radius_of_convergence().radius)
    except (ValueError, ConvergenceError):
        radius = None
    f_num = lc.f
    rows = []
    for e in eps_list:
        t0 = time.perf_counter()
        cyc = numeric_limit_cycle(
            f_num, e, x=lc.x, v=lc.v, eps_symbol=lc.eps_symbol, guess=float(lc.generating_amplitude), rtol=rtol, dps=dps
        )
        tnum = time.perf_counter() - t0
        # the table reports the validity itself (in_validity), so the SeriesWarning of each evaluation is not repeated
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SeriesWarning)
            rows.extend(_limit_cycle_rows(lc, e, orders, cyc, radius, tnum))
    return SeriesValidation(tuple(rows), radius)


def _limit_cycle_rows(lc: Any, e: float, orders: list, cyc: Any, radius: float | None, tnum: float) -> list:
    rows = []
    for n in orders:
        amp = lc.amplitude.evaluate(e, n)
        om = lc.frequency.evaluate(e, n)
        last = abs(float(lc.frequency.coefficients[n]) * e**n) if n > 0 else float("nan")
        rows.append(
            {
                "eps": e,
                "order": n,
                "amplitude_series": amp,
                "amplitude_numeric": float(cyc.amplitude),
                "amplitude_error": abs(amp - float(cyc.amplitude)),
                "frequency_series": om,
                "frequency_numeric": float(cyc.frequency),
                "frequency_error": abs(om - float(cyc.frequency)),
                "frequency_pade_error": _pade_error(lc.frequency, e, n, float(cyc.frequency)),
                "last_term": last,
                "multiplier_numeric": cyc.multiplier,
                "multiplier_series": float(np.exp(lc.floquet_exponent.evaluate(e, n + 1) * 2 * np.pi / om)),
                "in_validity": radius is None or abs(e) < radius,
                "method": cyc.method,
                "stiff": cyc.stiff,
                "numeric_time": tnum,
            }
        )
    return rows


def _pade_error(series: Any, e: float, n: int, ref: float) -> float:
    """Error of the diagonal Padé approximant built from the coefficients up to order n (nan if too few)."""
    from ._series import EpsSeries

    sub = EpsSeries(series.coefficients[: n + 1], series.symbol, n, series.factor, series.name)
    try:
        return abs(sub.evaluate_pade(e) - ref)
    except (ValueError, ZeroDivisionError):
        return float("nan")


@validated
def validate_lindstedt(ls: Any, eps: float, A: float, *, orders: Any = None, rtol: float = 1e-12) -> SeriesValidation:
    """Compare a :class:`~symosc.nonlinear.LindstedtSeries` frequency with the numerically integrated period.

    Parameters
    ----------
    ls : LindstedtSeries
        The series to check, as returned by :func:`lindstedt`.
    eps : float
        Value of the small parameter at which to compare; a finite real number.
    A : float
        Amplitude (starting displacement at rest) at which to compare; a finite real number.
    orders : sequence of int, optional
        Truncation orders to tabulate, integers from 0 to ``ls.order`` (default: ``ls.order`` only).
    rtol : float, optional
        Relative tolerance of the integration of the period, a positive number (default 1e-12).

    Returns
    -------
    SeriesValidation
        One row per order (the amplitude columns hold ``A``, the radius is None).

    See Also
    --------
    lindstedt
    numeric_period

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.nonlinear import lindstedt
    >>> x = sp.Symbol("x")
    >>> val = validate_lindstedt(lindstedt(-(x**3), 8), 0.1, 1.0)
    >>> val.rows[0]["frequency_error"] < 1e-9
    True
    """
    eps, A = check_finite("eps", eps), check_finite("A", A)
    T = numeric_period(ls.f, eps, A, x=ls.x, eps_symbol=ls.eps_symbol, rtol=rtol)
    om_num = 2 * np.pi / T
    orders = [ls.order] if orders is None else [int(o) for o in orders]
    rows = []
    for n in orders:
        om = float(ls.omega(eps, A, order=n))
        coeff = ls.frequency.coefficients[n].subs(ls.amplitude, A) if n > 0 else 0
        rows.append(
            {
                "eps": float(eps),
                "order": n,
                "amplitude_series": float(A),
                "amplitude_numeric": float(A),
                "amplitude_error": 0.0,
                "frequency_series": om,
                "frequency_numeric": om_num,
                "frequency_error": abs(om - om_num),
                "last_term": abs(float(coeff) * eps**n),
                "in_validity": True,
            }
        )
    return SeriesValidation(tuple(rows), None)
