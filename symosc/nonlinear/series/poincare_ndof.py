"""Poincaré's method for near-linear systems with n degrees of freedom (Bulgakov §§12.1–12.6).

System ``M q'' + K q = eps*f(q, q', eps)`` with ``M`` symmetric positive definite, ``K`` symmetric and ``f`` a
polynomial.  The periodic solution is continued from the linear mode ``m`` (frequency ``w_m``): in mass-normalised
modal coordinates ``eta = Phi^T M q`` the mode ``m`` plays the role of the one-degree-of-freedom oscillator of
:func:`symosc.nonlinear.limit_cycle` (amplitude equation, periodicity conditions, phase ``eta_m'(0) = 0``) and the
other modes are forced linear oscillators, solvable harmonic by harmonic when no ``w_j`` is an integer multiple of
``w_m`` (no internal resonance; Bulgakov's hypothesis that ``±i n w`` are not roots of ``Delta(D)``).  The series in
``eps`` are computed to any order on vector Fourier series, in float or mpmath (fixed-point) arithmetic.

Characteristic exponents of the variational equation (§12.5–12.6) are given to first order in ``eps``: for the
critical pair ``0`` and ``-eps H'(A*)/2`` (scaled time), for the other modes ``eps <D_jj>/2 ± i (nu_j - eps <S_jj>/(2
nu_j))`` with ``S = phi_j^T f_q phi_j`` and ``D = phi_j^T f_v phi_j`` averaged over the generating solution (valid
away from parametric resonances ``2 nu_j`` integer).  :meth:`NDofPeriodicSolution.validate` computes the periodic
orbit and its Floquet exponents numerically (shooting with the monodromy matrix) for comparison.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ..._deprecation import deprecated_attribute as _deprecated_attribute
from ..._deprecation import renamed_keyword
from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ModelError, ParameterError
from ...numeric import compile as _compile
from ._arith.trig import FixedArith, Trig, _Arith, make_arith
from ._ndof_exponents import CharacteristicExponentSeries
from ._ndof_exponents import exponent_series as _exponent_series
from ._poincare_core import _polynomial_terms, _trig_power_coefficients
from ._series import EpsSeries, SeriesResult, to_sympy_number

__all__ = ["NDofPeriodicSolution", "periodic_solution_ndof"]

EPS = sp.Symbol("eps")
TAU = sp.Symbol("tau")


def _to_scalar(ar: _Arith, value: Any) -> Any:
    if isinstance(ar, FixedArith):
        with mpmath.workprec(ar.prec + 64):
            return int(mpmath.nint(mpmath.mpf(value) * mpmath.mpf(2) ** ar.prec))
    return float(value)


def _modes(M: sp.Matrix, K: sp.Matrix, dps: int) -> tuple[list, mpmath.matrix]:
    """Eigenvalues (ascending) and mass-normalised mode shapes (columns) of ``K phi = lam M phi`` in mpmath."""
    with mpmath.workdps(dps):
        Mm = mpmath.matrix([[mpmath.mpf(sp.N(e, dps)) for e in row] for row in M.tolist()])
        Km = mpmath.matrix([[mpmath.mpf(sp.N(e, dps)) for e in row] for row in K.tolist()])
        try:
            L = mpmath.cholesky(Mm)
        except ValueError as exc:
            raise ModelError("M must be symmetric positive definite") from exc
        Li = mpmath.inverse(L)
        C = Li * Km * Li.T
        C = (C + C.T) / 2
        E, Q = mpmath.eigsy(C)
        order = sorted(range(len(E)), key=lambda i: E[i])
        Phi = Li.T * Q
        Phi = mpmath.matrix([[Phi[i, j] for j in order] for i in range(Phi.rows)])
        return [E[i] for i in order], Phi


@dataclass(frozen=True)
class NDofPeriodicSolution(SeriesResult, SymPyPrintable):
    """Periodic solution of ``M q'' + K q = eps*f(q, q')`` continued from one linear mode.

    As a SymPy object the result is the column ``q(tau)`` of coordinate series (``sympy.sympify`` gives an
    ``ImmutableMatrix`` whose entries carry ``O(eps**(order+1))``; :meth:`solution_series`), ``tau = omega*t``.

    Attributes
    ----------
    n : int
        Number of degrees of freedom.
    mode : int
        Index of the linear mode continued (modes in ascending frequency, from 0).
    order : int
        Highest power of ``eps`` reached.
    arithmetic : str
        ``"float"`` or ``"mpmath"``: the arithmetic of the series coefficients.
    q : tuple of Symbol
        The coordinates, in the order of the rows of ``M``, ``K`` and ``f``.
    eps_symbol : Symbol
        Symbol of the small parameter (the expansion variable of the series).
    mode_frequencies : tuple of float
        The linear frequencies ``w_j`` (rad/s), ascending.
    mode_shapes : ndarray, shape (n, n)
        Mass-normalised mode shapes ``Phi`` (``Phi^T M Phi = I``) as columns, in ascending frequency.
    generating_amplitude : float
        Root ``A*`` of the amplitude equation ``H(A) = 0``.
    amplitude_equation : Expr
        ``H(A)`` of the continued mode (a polynomial in ``A`` with float coefficients, in the time scaled by
        ``w_m``).
    frequency, period : EpsSeries
        ``omega(eps)`` in rad/s (``factor = w_m``) and ``2 pi/omega``.
    amplitude : EpsSeries
        Modal amplitude ``eta_m(0)`` (``eta = Phi^T M q``, mass-normalised modes) at the turning point of the mode.
    exponents : tuple of (complex, complex)
        First-order characteristic exponents ``(lambda_0, lambda_1)`` with ``lambda = lambda_0 + eps*lambda_1``
        (rad/s), two per mode; the critical pair first.
    stable : bool
        Orbital stability for small ``eps > 0`` (all non-zero ``Re lambda_1 < 0``).
    _coords : tuple
        Internal: per order, per coordinate, the cosine and sine coefficients of ``q_i`` divided by ``A*``.
    _numeric : tuple
        Internal: ``(M, K, f, q, qdot, eps_symbol)`` as given, for the numeric checks and the exponent series.
    _exponent_cache : dict
        Internal: the exponent series already computed, keyed by order.
    """

    n: int
    mode: int
    order: int
    arithmetic: str
    q: tuple
    eps_symbol: sp.Symbol
    mode_frequencies: tuple
    mode_shapes: np.ndarray = field(repr=False)
    generating_amplitude: float = 0.0
    amplitude_equation: sp.Expr = field(default=sp.Integer(0), repr=False)
    frequency: EpsSeries | None = None
    period: EpsSeries | None = None
    amplitude: EpsSeries | None = None
    exponents: tuple = ()
    stable: bool = False
    _coords: tuple = field(default=(), repr=False, compare=False)  # per order: per coordinate (cos, sin) lists
    _numeric: Any = field(default=None, repr=False, compare=False)
    _exponent_cache: dict = field(default_factory=dict, repr=False, compare=False)
    eps = _deprecated_attribute("eps_symbol")  # the old name of the small-parameter symbol

    def solution(self, order: int | None = None, tau: sp.Symbol = TAU) -> sp.Matrix:
        """``q(tau)`` (column Matrix) truncated at ``order``; ``tau = omega*t``.

        Parameters
        ----------
        order : int, optional
            Highest power of ``eps`` kept, an integer from 0 to ``self.order``; all computed orders when omitted.
        tau : Symbol, optional
            Symbol of the phase ``tau = omega*t`` in the result (default ``tau``).
        """
        return sp.Matrix([sp.expand(s.removeO()) for s in self.solution_series(order, tau)])

    def solution_series(self, order: int | None = None, tau: sp.Symbol = TAU) -> tuple[EpsSeries, ...]:
        """``q_i(tau) = sum_k eps**k q_ik(tau) + O(eps**(order+1))``, one :class:`EpsSeries` per coordinate.

        Parameters
        ----------
        order : int, optional
            Highest power of ``eps`` kept (default: all, ``self.order``).
        tau : Symbol
            The phase variable ``tau = omega*t``.
        """
        n = self.order if order is None else int(order)
        if n < 0 or n > self.order:
            raise ParameterError(f"solution is known to order {self.order}; asked for {order}")
        A0 = self.generating_amplitude
        out = []
        for i in range(self.n):
            cs_k = []
            for k in range(n + 1):
                cs, ss = self._coords[k][i]
                terms = [A0 * c * sp.cos(h * tau) for h, c in enumerate(cs) if c != 0]
                terms += [A0 * s * sp.sin(h * tau) for h, s in enumerate(ss) if s != 0]
                cs_k.append(sp.Add(*terms))
            out.append(EpsSeries(tuple(cs_k), self.eps_symbol, n, name=str(self.q[i])))
        return tuple(out)

    def series_expression(self) -> tuple[EpsSeries, ...]:
        """The coordinates ``q(tau)`` with their order terms (:meth:`solution_series`)."""
        return self.solution_series()

    def _pretty_items(self) -> list:
        return [(sp.Symbol("omega"), self.frequency)]

    def initial_state(self, eps: float, order: int | None = None) -> np.ndarray:
        """``(q(0), q'(0))`` of the truncated series (the phase where ``eta_m' = 0``).

        Parameters
        ----------
        eps : float
            Value of the small parameter at which to sum the series; a real number.
        order : int, optional
            Highest power of ``eps`` kept, an integer from 0 to ``self.order``; all computed orders when omitted.

        Returns
        -------
        ndarray, shape (2n,)
            ``q(0)`` followed by ``dq/dt(0)`` (in the original time).
        """
        n = self.order if order is None else int(order)
        om = self.frequency.evaluate(eps, n)
        q0 = np.zeros(self.n)
        v0 = np.zeros(self.n)
        for k in range(n + 1):
            for i in range(self.n):
                cs, ss = self._coords[k][i]
                q0[i] += eps**k * sum(float(c) for c in cs)
                v0[i] += eps**k * sum(h * float(s) for h, s in enumerate(ss))
        return np.concatenate([self.generating_amplitude * q0, self.generating_amplitude * om * v0])

    def exponents_at(self, eps: float) -> np.ndarray:
        """First-order characteristic exponents at ``eps`` (complex array, rad/s).

        Parameters
        ----------
        eps : float
            Value of the small parameter; a real number (the exponents are ``lambda_0 + eps*lambda_1``).
        """
        return np.array([complex(a) + eps * complex(b) for a, b in self.exponents])

    def exponent_series(self, order: int | None = None) -> CharacteristicExponentSeries:
        """Characteristic exponents of the variational equation as series in ``eps`` to ``order`` (§12.5–12.6).

        Every coefficient up to ``eps**order`` is exact to rounding (``order`` defaults to the order of the
        solution and cannot exceed it), so the truncated sums have error ``O(eps**(order+1))``.  Non-critical modes by
        Rayleigh–Schrödinger perturbation of the Floquet operator in Fourier space, the critical exponent by
        Liouville's formula (:class:`symosc.nonlinear.CharacteristicExponentSeries`).  The order-1 coefficients agree
        with the averaged first-order ``exponents``.

        Parameters
        ----------
        order : int, optional
            Highest power of ``eps`` in the exponent series, an integer from 0 to ``self.order`` (default
            ``self.order``).

        Examples
        --------
        >>> import sympy as sp
        >>> q1, q2, v1, v2 = sp.symbols("q1 q2 v1 v2")
        >>> f = [(1 - q1**2) * v1, (1 - q2**2) * v2]
        >>> sol = periodic_solution_ndof([[1, 0], [0, 1]], [[2, -1], [-1, 2]], f, [q1, q2], [v1, v2], 4)
        >>> ex = sol.exponent_series(4)
        >>> bool(abs(ex.coefficients[1, 1] + 1) < 1e-12)  # critical exponent -eps + O(eps^2) (van der Pol)
        True
        """
        key = self.order if order is None else order
        if key not in self._exponent_cache:
            self._exponent_cache[key] = _exponent_series(self, key)
        return self._exponent_cache[key]

    def characteristic_exponents(self, eps: float, order: int | None = None) -> np.ndarray:
        """Characteristic exponents (rad/s) at ``eps`` from :meth:`exponent_series` truncated at ``order``.

        Parameters
        ----------
        eps : float
            Value of the small parameter at which to sum the series; a real number.
        order : int, optional
            Order of the exponent series, an integer from 0 to ``self.order`` (default ``self.order``).
        """
        ser = self.exponent_series(order)
        return ser.evaluate(eps)

    def validate(self, eps: float, *, rtol: float = 1e-11, exponent_order: int | None = None) -> dict:
        """Numerical periodic orbit (shooting with the monodromy matrix) and its Floquet exponents vs the series.

        ``exponents_series_real`` uses the first-order exponents, or :meth:`exponent_series` truncated at
        ``exponent_order`` when it is given.

        Parameters
        ----------
        eps : float
            Value of the small parameter at which to compare; a finite real number.
        rtol : float, optional
            Relative tolerance of the integration of the orbit and its monodromy matrix, a positive number
            (default 1e-11).
        exponent_order : int, optional
            Order of the exponent series compared, an integer from 0 to ``self.order``; the first-order exponents
            when omitted.

        Returns
        -------
        dict
            Numeric and series period, amplitude and their errors, the multipliers, and the real parts of the
            numeric (``exponents_numeric_real``) and series (``exponents_series_real``) exponents, sorted.
        """
        return _validate_ndof(self, float(eps), rtol, exponent_order)

    def _repr_latex_(self) -> str:
        return f"$\\omega = {sp.latex(self.frequency.expr)} + O({sp.latex(self.eps_symbol ** (self.order + 1))})$"

    def __repr__(self) -> str:
        w = ", ".join(f"{x:.6g}" for x in self.mode_frequencies)
        return (
            f"NDofPeriodicSolution(n={self.n}, mode={self.mode} (w = {w}), order={self.order}, "
            f"A* = {self.generating_amplitude:.10g}, {'stable' if self.stable else 'unstable'},\n"
            f"  omega = {_head(self.frequency)})"
        )


def _head(series: EpsSeries, terms: int = 4) -> str:
    cs = ", ".join(f"{float(c):.10g}" for c in series.coefficients[:terms])
    return f"{float(series.factor):.10g} * sum_k c_k eps**k, c = [{cs}, ...] (to order {series.order})"


@validated
@renamed_keyword({"eps": "eps_symbol"})
def periodic_solution_ndof(
    M: Any,
    K: Any,
    f: Any,
    q: Any,
    qdot: Any,
    order: int,
    *,
    mode: int = 0,
    eps_symbol: sp.Symbol = EPS,
    arithmetic: str = "float",
    dps: int | None = None,
    amplitude0: float | None = None,
) -> NDofPeriodicSolution:
    """Poincaré series for ``M q'' + K q = eps*f(q, q', eps)`` from linear mode ``mode`` (ascending frequency).

    Parameters
    ----------
    M, K : Matrix or nested lists
        Numeric symmetric matrices, ``M`` positive definite; mode ``mode`` must have ``w_m**2 > 0``.
    f : Matrix or list
        ``n`` polynomials in ``q``, ``qdot`` (and ``eps``) with numeric coefficients.
    q, qdot : sequence of Symbol
        Coordinates and velocities used in ``f``.
    order : int
        Highest power of ``eps`` (>= 1).
    mode : int, optional
        Index of the linear mode to continue, an integer from 0 to ``n - 1`` in ascending frequency (default 0); no
        other mode frequency may be an integer multiple of it (internal resonance).
    eps_symbol : Symbol, optional
        Symbol of the small parameter in ``f`` and in the series (default ``eps``). The old keyword ``eps=`` is still
        accepted, with a deprecation warning.
    arithmetic : {"float", "mpmath"}
        Mode shapes are irrational in general, so the series are computed in floating point or in mpmath fixed
        point at ``dps`` digits.
    dps : int, optional
        Decimal digits of the mpmath arithmetic, a positive integer (default ``mpmath.mp.dps``; the modes are
        computed with 20 digits more). Ignored by ``arithmetic="float"``.
    amplitude0 : float, optional
        Which generating amplitude to continue when the amplitude equation has several positive roots (the root
        closest to this value is used); required then.

    Examples
    --------
    Two coupled van der Pol oscillators, in-phase mode:

    >>> import sympy as sp
    >>> q1, q2, v1, v2 = sp.symbols("q1 q2 v1 v2")
    >>> K = [[2, -1], [-1, 2]]
    >>> f = [(1 - q1**2) * v1, (1 - q2**2) * v2]
    >>> sol = periodic_solution_ndof([[1, 0], [0, 1]], K, f, [q1, q2], [v1, v2], 2)
    >>> round(sol.generating_amplitude, 12), sol.stable
    (2.828427124746, True)
    """
    eps = eps_symbol
    if isinstance(order, bool) or not isinstance(order, int | np.integer) or order < 1:
        raise ParameterError(f"order must be an integer >= 1, got {order!r}")
    if arithmetic not in ("float", "mpmath"):
        raise ParameterError(
            "arithmetic must be 'float' or 'mpmath' for n degrees of freedom (mode shapes are irrational)"
        )
    order = int(order)
    q, qdot = tuple(q), tuple(qdot)
    M, K = sp.Matrix(M), sp.Matrix(K)
    n = len(q)
    f = list(sp.Matrix(f)) if not isinstance(f, list | tuple) else [sp.sympify(e) for e in f]
    if M.shape != (n, n) or K.shape != (n, n) or len(f) != n or len(qdot) != n:
        raise ParameterError(f"shapes do not match: n = {n}, M {M.shape}, K {K.shape}, {len(f)} forces")
    if M.free_symbols or K.free_symbols:
        raise ParameterError("M and K must be numeric; substitute parameter values first")
    if M != M.T or K != K.T:
        raise ModelError("M and K must be symmetric")
    if not 0 <= mode < n:
        raise ParameterError(f"mode must be in 0..{n - 1}")
    wdps = (dps or 15) + 20
    lams, Phi = _modes(M, K, wdps)
    lam_m = lams[mode]
    if lam_m <= 0:
        raise ModelError(f"mode {mode} has w^2 = {mpmath.nstr(lam_m, 8)} <= 0: it does not oscillate")
    for j, lj in enumerate(lams):
        if j == mode:
            continue
        nu = mpmath.sqrt(lj / lam_m) if lj > 0 else mpmath.mpf(-1)
        if lj > 0 and abs(nu - mpmath.nint(nu)) < 1e-8:
            raise ModelError(
                f"internal resonance: w_{j}/w_{mode} = {mpmath.nstr(nu, 10)} is an integer; the mode-{mode} family "
                "is not continued by this series (the other mode must be included in the generating solution)"
            )
        if lj <= 0:
            raise ModelError(f"mode {j} has w^2 <= 0 (unstable linear mode): no periodic solution near the linear one")
    wm = mpmath.sqrt(lam_m)
    nu2 = [lj / lam_m for lj in lams]
    gens = (*q, *qdot)
    comps = [_polynomial_terms(fi, gens, eps, f"f[{i}]") for i, fi in enumerate(f)]
    # scaled time t' = wm t: M q'' + (K/lam_m) q = eps g(q, q'), g = f(q, wm q')/lam_m
    phim = [Phi[i, mode] for i in range(n)]
    A = sp.Symbol("A")
    Hc: dict[int, Any] = {}
    for i, terms in enumerate(comps):
        for expo, c in terms.items():
            if expo[-1] != 0:
                continue
            P, Rv = sum(expo[:n]), sum(expo[n : 2 * n])
            _, hs = _trig_power_coefficients(P, Rv)
            coef = mpmath.mpf(sp.N(c, wdps)) * phim[i] * wm**Rv / lam_m * mpmath.mpf(hs.numerator) / hs.denominator
            for k in range(n):
                coef *= phim[k] ** (expo[k] + expo[n + k])
            Hc[P + Rv] = Hc.get(P + Rv, 0) + coef
    if not Hc or all(abs(v) < mpmath.mpf(10) ** (-wdps + 10) for v in Hc.values()):
        raise ModelError("the amplitude equation vanishes identically (conservative in this mode): no isolated cycle")
    deg = max(Hc)
    coeffs_np = [float(Hc.get(d, 0)) for d in range(deg, -1, -1)]
    roots = [r.real for r in np.roots(coeffs_np) if abs(r.imag) < 1e-9 * max(1, abs(r)) and r.real > 1e-12]
    H_expr = sp.Add(*[sp.Float(float(v), 15) * A**d for d, v in Hc.items()])
    if not roots:
        raise ModelError(
            f"no periodic solution from mode {mode}: the amplitude equation H(A) = {H_expr} has no positive root"
        )
    if amplitude0 is not None:
        r0 = min(roots, key=lambda r: abs(r - amplitude0))
    elif len(roots) > 1:
        raise ModelError(f"several generating amplitudes {sorted(roots)}; pass amplitude0= to choose one")
    else:
        r0 = roots[0]
    with mpmath.workdps(wdps):
        Hf = lambda a: sum(v * a**d for d, v in Hc.items())  # noqa: E731
        A0 = mpmath.findroot(Hf, mpmath.mpf(r0))
        dH = mpmath.diff(Hf, A0)
    if abs(dH) < 1e-10:
        raise ModelError(f"H'(A*) = 0 at A* = {mpmath.nstr(A0, 10)}: multiple root, the series does not exist")
    ar = make_arith(arithmetic, dps, order)
    coeffs: list[dict] = []
    for terms in comps:
        ci = {}
        for expo, c in terms.items():
            Rv = sum(expo[n : 2 * n])
            d = sum(expo[: 2 * n])
            ci[expo] = _to_scalar(ar, mpmath.mpf(sp.N(c, wdps)) * A0 ** (d - 1) * wm**Rv / lam_m)
        coeffs.append(ci)
    raw = _ndof_raw(
        ar,
        coeffs,
        [[_to_scalar(ar, Phi[i, j]) for j in range(n)] for i in range(n)],
        [_to_scalar(ar, v) for v in nu2],
        mode,
        n,
        order,
    )
    _s, w, coords = raw
    digits = dps or 17

    def num(c: Any) -> sp.Expr:
        return to_sympy_number(ar.output(c), digits)

    inv = [ar.scalar(1)]
    for k in range(1, order + 1):
        acc = 0
        for i in range(1, k + 1):
            acc = acc - ar.smul(w[i], inv[k - i])
        inv.append(acc)
    wm_s = sp.Float(wm, digits)
    coords_out = []
    amp = []
    for k in range(order + 1):
        per = []
        for i in range(n):
            cs, ss = ar.values(coords[k][i])
            per.append(([to_sympy_number(c, digits) for c in cs], [to_sympy_number(c, digits) for c in ss]))
        coords_out.append(tuple(per))
        # eta_m(0) = sum_i phi_i (M q)_i (0)
        Mq = [sum(float(M[a, b]) * sum(float(c) for c in per[b][0]) for b in range(n)) for a in range(n)]
        amp.append(sp.Float(sum(float(Phi[a, mode]) * Mq[a] for a in range(n)), 17))
    exps, stable = _first_order_exponents(comps, q, qdot, eps, Phi, lams, mode, float(A0), n, float(dH), wdps)
    return NDofPeriodicSolution(
        n=n,
        mode=mode,
        order=order,
        arithmetic=arithmetic,
        q=q,
        eps_symbol=eps,
        mode_frequencies=tuple(float(mpmath.sqrt(lj)) if lj > 0 else float("nan") for lj in lams),
        mode_shapes=np.array([[float(Phi[i, j]) for j in range(n)] for i in range(n)]),
        generating_amplitude=float(A0),
        amplitude_equation=H_expr,
        frequency=EpsSeries(tuple(num(c) for c in w[: order + 1]), eps, order, wm_s, name="omega"),
        period=EpsSeries(tuple(num(c) for c in inv), eps, order, 2 * sp.pi / wm_s, name="period"),
        amplitude=EpsSeries(tuple(amp), eps, order, sp.Float(A0, digits), name="modal amplitude"),
        exponents=exps,
        stable=stable,
        _coords=tuple(coords_out),
        _numeric=(M, K, f, q, qdot, eps),
    )


def _ndof_raw(ar: _Arith, coeffs: list[dict], Phi: list[list], nu2: list, m: int, n: int, order: int) -> tuple:
    """The vector recurrence (scaled problem, generating amplitude 1 in mode m)."""
    one = ar.scalar(1)
    nv = 2 * n
    # monomial trie: parent = remove one unit from the highest-index variable
    nodes: dict[tuple, tuple[tuple, int]] = {}

    def add(e: tuple) -> None:
        if sum(e) == 0 or e in nodes:
            return
        var = max(i for i in range(nv) if e[i] > 0)
        parent = tuple(e[i] - (1 if i == var else 0) for i in range(nv))
        add(parent)
        nodes[e] = (parent, var)

    for ci in coeffs:
        for expo in ci:
            add(tuple(expo[:nv]))
    order_nodes = sorted(nodes, key=sum)
    T: dict[tuple, list[Trig]] = {e: [] for e in order_nodes}
    Y: list[list[Trig]] = [[] for _ in range(nv)]  # y_i (i < n), w_i (i >= n) coefficients per order
    const = ar.monomial("c", 0, one)
    eta = [[] for _ in range(n)]  # modal series
    eta[m].append(ar.monomial("c", 1, one))
    for j in range(n):
        if j != m:
            eta[j].append(ar.new(0))
    x0 = [ar.scale(eta[m][0], Phi[i][m]) for i in range(n)]
    xs = [x0]
    s = [one]
    w = [one]
    cos1 = ar.monomial("c", 1, one)
    msin1 = ar.monomial("s", 1, -one)
    dT: dict[tuple, Trig] = {}
    Lmodal = None
    for k in range(1, order + 2):
        mm = k - 1
        for i in range(n):
            Y[i].append(xs[mm][i])
            acc = ar.new(0)
            for r in range(mm + 1):
                acc = ar.add(acc, ar.scale(ar.deriv(xs[mm - r][i]), w[r]))
            Y[n + i].append(acc)
        for e in order_nodes:
            parent, var = nodes[e]
            if sum(parent) == 0:
                T[e].append(Y[var][mm])
            else:
                acc = ar.mul(T[parent][0], Y[var][mm])
                for r in range(1, mm + 1):
                    acc = ar.add(acc, ar.mul(T[parent][r], Y[var][mm - r]))
                T[e].append(acc)

        def force(mi: int, table: Any) -> list[Trig]:
            out = []
            for ci in coeffs:
                acc = ar.new(0)
                for expo, c in ci.items():
                    j = expo[-1]
                    if j > mi:
                        continue
                    key = tuple(expo[:nv])
                    t = (const if mi - j == 0 else None) if sum(key) == 0 else table(key, mi - j)
                    if t is not None:
                        acc = ar.add(acc, ar.scale(t, c))
                out.append(acc)
            return out

        G = force(mm, lambda key, r: T[key][r])
        r_modal = []
        for j in range(n):
            acc = ar.new(0)
            for i in range(n):
                acc = ar.add(acc, ar.scale(G[i], Phi[i][j]))
            for i in range(1, k):
                acc = ar.sub(acc, ar.scale(ar.deriv(ar.deriv(eta[j][k - i])), s[i]))
            r_modal.append(acc)
        if k == 1:
            dY = [ar.scale(cos1, Phi[i][m]) for i in range(n)] + [ar.scale(msin1, Phi[i][m]) for i in range(n)]
            for e in order_nodes:
                parent, var = nodes[e]
                if sum(parent) == 0:
                    dT[e] = dY[var]
                else:
                    dT[e] = ar.add(ar.mul(dT[parent], Y[var][0]), ar.mul(T[parent][0], dY[var]))
            dG = []
            for ci in coeffs:
                acc = ar.new(0)
                for expo, c in ci.items():
                    key = tuple(expo[:nv])
                    if expo[-1] == 0 and sum(key) > 0:
                        acc = ar.add(acc, ar.scale(dT[key], c))
                dG.append(acc)
            sk = -ar.coeff(r_modal[m], "c", 1)
            Lmodal = []
            for j in range(n):
                acc = ar.new(0)
                for i in range(n):
                    acc = ar.add(acc, ar.scale(dG[i], Phi[i][j]))
                Lmodal.append(acc)
            Lmodal[m] = ar.add_coeff(Lmodal[m], "c", 1, sk)
            if ar.is_zero(ar.coeff(Lmodal[m], "s", 1)):
                raise ModelError("H'(A*) = 0: the periodicity conditions cannot be solved")
        else:
            a = -ar.sdiv(ar.coeff(r_modal[m], "s", 1), ar.coeff(Lmodal[m], "s", 1))
            sk = -(ar.coeff(r_modal[m], "c", 1) + ar.smul(a, ar.coeff(Lmodal[m], "c", 1)))
            eta[m][mm] = ar.add_coeff(eta[m][mm], "c", 1, a)
            for i in range(n):
                xs[mm][i] = ar.add(xs[mm][i], ar.scale(cos1, ar.smul(a, Phi[i][m])))
                Y[i][mm] = xs[mm][i]
                Y[n + i][mm] = ar.add(Y[n + i][mm], ar.scale(msin1, ar.smul(a, Phi[i][m])))
            for e in order_nodes:
                T[e][mm] = ar.add(T[e][mm], ar.scale(dT[e], a))
            for j in range(n):
                r_modal[j] = ar.add(r_modal[j], ar.scale(Lmodal[j], a))
        r_modal[m] = ar.add_coeff(r_modal[m], "c", 1, sk)
        s.append(sk)
        acc = sk
        for i in range(1, k):
            acc = acc - ar.smul(w[i], w[k - i])
        w.append(ar.sdiv(acc, ar.scalar(2)))
        if k == order + 1:
            break
        new_x = [ar.new(0) for _ in range(n)]
        for j in range(n):
            if j == m:
                ej = ar.solve_forced(r_modal[j])
                D = ar.scalar(0)
                for h in range(2, len(ej.cos)):
                    D = D + ar.smul(ar.scalar(h), ar.coeff(ej, "s", h))
                ej = ar.add_coeff(ej, "s", 1, -D)
            else:
                ej = ar.solve_detuned(r_modal[j], nu2[j])
            eta[j].append(ej)
            for i in range(n):
                new_x[i] = ar.add(new_x[i], ar.scale(ej, Phi[i][j]))
        xs.append(new_x)
    return s, w, xs


def _first_order_exponents(comps, q, qdot, eps, Phi, lams, m, A0, n, dH, dps) -> tuple[tuple, bool]:
    """First-order characteristic exponents (rad/s) by averaging the variational equation over the generating cycle."""
    wm = float(mpmath.sqrt(lams[m]))
    Ph = np.array([[float(Phi[i, j]) for j in range(n)] for i in range(n)])
    f0 = [
        sp.Add(
            *[
                c * sp.Mul(*[g**e for g, e in zip((*q, *qdot), expo[:-1], strict=True)])
                for expo, c in t.items()
                if expo[-1] == 0
            ]
        )
        for t in comps
    ]
    Fq = sp.Matrix(f0).jacobian(q)
    Fv = sp.Matrix(f0).jacobian(qdot)
    fn = _compile([*Fq, *Fv], [*q, *qdot], check=False)
    N = 256
    u = 2 * np.pi * np.arange(N) / N
    qs = [A0 * Ph[i, m] * np.cos(u) for i in range(n)]
    vs = [-A0 * wm * Ph[i, m] * np.sin(u) for i in range(n)]
    vals = np.asarray(fn.raw(*qs, *vs), dtype=float).reshape(N, 2, n, n) if n else None
    Sq = vals[:, 0].mean(axis=0)
    Sv = vals[:, 1].mean(axis=0)
    # critical pair (scaled time exponent -eps H'/2 -> times wm; H computed for g = f(q, wm v)/lam_m)
    crit = -0.5 * dH * wm
    exps: list[tuple[complex, complex]] = [(0j, 0j), (0j, complex(crit))]
    stable = crit < 0
    for j in range(n):
        if j == m:
            continue
        wj = float(mpmath.sqrt(lams[j]))
        if abs(2 * wj / wm - round(2 * wj / wm)) < 1e-6:
            raise ModelError(f"parametric resonance 2 w_{j}/w_{m} integer: first-order exponents need the full block")
        phi = Ph[:, j]
        D = float(phi @ Sv @ phi)
        S = float(phi @ Sq @ phi)
        re = 0.5 * D
        im = -S / (2 * wj)
        exps.append((complex(0, wj), complex(re, im)))
        exps.append((complex(0, -wj), complex(re, -im)))
        stable = stable and re < 0
    return tuple(exps), bool(stable)


def _validate_ndof(sol: NDofPeriodicSolution, e: float, rtol: float, exponent_order: int | None = None) -> dict:
    M, K, f, q, qdot, eps = sol._numeric
    n = sol.n
    Mi = np.linalg.inv(np.array(M.tolist(), dtype=float))
    Kn = np.array(K.tolist(), dtype=float)
    fexpr = [sp.sympify(fi).subs(eps, e) for fi in f]
    fj = sp.Matrix(fexpr).jacobian([*q, *qdot])
    fn = _compile(fexpr, [*q, *qdot], check=False)
    jn = _compile(fj, [*q, *qdot], check=False)

    def rhs(t: float, z: np.ndarray) -> np.ndarray:
        y = z[: 2 * n]
        Phi_ = z[2 * n :].reshape(2 * n, 2 * n)
        qq, vv = y[:n], y[n:]
        acc = Mi @ (-Kn @ qq + e * np.asarray(fn.raw(*qq, *vv), dtype=float))
        J = np.zeros((2 * n, 2 * n))
        J[:n, n:] = np.eye(n)
        J[n:, :n] = Mi @ (-Kn + e * np.asarray(jn.raw(*qq, *vv), dtype=float)[:, :n])
        J[n:, n:] = Mi @ (e * np.asarray(jn.raw(*qq, *vv), dtype=float)[:, n:])
        return np.concatenate([vv, acc, (J @ Phi_).ravel()])

    y0 = sol.initial_state(e)
    T = float(sol.period.evaluate(e))
    phase_row = np.concatenate([np.zeros(n), sol.mode_shapes[:, sol.mode] @ np.array(M.tolist(), dtype=float)])
    for _ in range(30):
        z0 = np.concatenate([y0, np.eye(2 * n).ravel()])
        from scipy.integrate import solve_ivp

        r = solve_ivp(rhs, (0, T), z0, method="DOP853", rtol=rtol, atol=rtol * 1e-2)
        yT = r.y[: 2 * n, -1]
        Mono = r.y[2 * n :, -1].reshape(2 * n, 2 * n)
        F = np.concatenate([yT - y0, [phase_row @ y0]])
        if np.max(np.abs(F)) < 1e-10 * max(1.0, np.max(np.abs(y0))):
            break
        J = np.zeros((2 * n + 1, 2 * n + 1))
        J[: 2 * n, : 2 * n] = Mono - np.eye(2 * n)
        J[: 2 * n, 2 * n] = rhs(T, np.concatenate([yT, np.eye(2 * n).ravel()]))[: 2 * n]
        J[2 * n, : 2 * n] = phase_row
        d = np.linalg.lstsq(J, -F, rcond=None)[0]
        y0 = y0 + d[: 2 * n]
        T = T + d[2 * n]
    else:
        raise ConvergenceError(f"shooting for the n-DOF periodic orbit did not converge at eps = {e}")
    mult = np.linalg.eigvals(Mono)
    num_exp = np.log(mult.astype(complex)) / T
    eta0 = sol.mode_shapes[:, sol.mode] @ np.array(M.tolist(), dtype=float) @ y0[:n]
    return {
        "eps": e,
        "period_numeric": float(T),
        "period_series": float(sol.period.evaluate(e)),
        "frequency_error": float(abs(2 * np.pi / T - float(sol.frequency.evaluate(e)))),
        "amplitude_numeric": float(eta0),
        "amplitude_series": float(sol.amplitude.evaluate(e)),
        "amplitude_error": abs(float(eta0) - float(sol.amplitude.evaluate(e))),
        "multipliers": mult,
        "exponents_numeric_real": np.sort(num_exp.real),
        "exponents_series_real": np.sort(
            (sol.exponents_at(e) if exponent_order is None else sol.characteristic_exponents(e, exponent_order)).real
        ),
    }
