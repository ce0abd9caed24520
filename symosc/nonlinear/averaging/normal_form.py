"""Averaging in normal coordinates for ``f(D) y = psi(y, Dy, ..., t)`` with several oscillating pairs.

Bulgakov (1954), §12.11–12.12.  ``f(D)`` is an ``n x n`` matrix of polynomials in ``D = d/dt`` whose determinant
``Delta(D)`` has simple roots: real roots ``kappa_s`` and complex pairs ``eps_h +- i omega_h``.  At a simple root the
adjugate ``F(kappa)`` has rank one and splits as ``F(kappa) = v w`` (12.146)–(12.150), with the column
``v_j = F_jl(kappa) / F_ml(kappa)`` (so ``v_m = 1``) and the row ``w_k = F_mk(kappa)``.  Partial fractions
``f(D)^-1 = sum F(kappa) / (Delta'(kappa) (D - kappa))`` give the normal coordinates (12.144)

    D^nu y_j = sum_s kappa_s^nu v_js xi_s + sum_h a_h |kappa_h^nu V_jh| cos(u_h + arg(kappa_h^nu V_jh))

and the exact equations (12.151)–(12.153)

    xi_s' = kappa_s xi_s + (1/Delta'(kappa_s)) sum_k w_sk psi_k
    a_h'  = eps_h a_h + Re[(2/Delta'(kappa_h)) e^{-i u_h} sum_k W_hk psi_k]
    u_h'  = omega_h + (1/a_h) Im[(2/Delta'(kappa_h)) e^{-i u_h} sum_k W_hk psi_k]

Averaging the right-hand sides over the torus of the phases ``u_h`` (frequencies without integer relations,
assumption (e) of §12.12) gives the shortened equations (12.154); their constant solutions are the quasi-periodic
regimes (12.155)–(12.156), and the Jacobian of the shortened amplitude equations at a regime decides its stability
(the matrix of the variational equations of (12.207), (12.219)–(12.223)).  With one oscillating pair and
``eps_h = 0`` the shortened equations are Poincaré's first approximation (12.159)–(12.160) = (12.34).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ModelError, ParameterError
from . import _trig
from ._normal_form_support import _DPS, _clean, _is_real, _jacobian_values, _operator, _rates, _roots, _tidy

__all__ = ["AveragingNormalForm", "QuasiPeriodicRegime", "ShortenedEquations", "averaging_normal_form"]


@dataclass(frozen=True)
class QuasiPeriodicRegime(SymPyPrintable):
    """A constant solution of the shortened equations (Bulgakov (1954), eqs. (12.155)–(12.156)).

    Attributes
    ----------
    variables : tuple of Symbol
        The slow variables: real-root coordinates ``xi_s``, then the amplitudes ``a_h`` of the averaged pairs.
    values : ndarray
        Their stationary values.
    frequencies : ndarray
        ``u_h'`` of the averaged pairs at the regime (rad/s): ``omega_h (1 + b_h)`` of (12.155).
    jacobian : ndarray
        Jacobian of the shortened equations for ``variables`` at the regime (the matrix of the variational
        equations, Bulgakov (1954), eqs. (12.219)–(12.223)).
    eigenvalues : ndarray
        Its eigenvalues (rad/s): the first-order decay/growth rates of perturbations of the regime.
    stable : bool
        All eigenvalues in the open left half-plane and every pair left out of the averaging decays (``eps_h < 0``).
    residual : float
        Largest absolute rate at :attr:`values`.
    """

    variables: tuple
    values: np.ndarray
    frequencies: np.ndarray
    jacobian: np.ndarray
    eigenvalues: np.ndarray
    stable: bool
    residual: float

    def _repr_latex_(self) -> str:
        from ..._printing import latex_value

        vals = r",\ ".join(
            f"{sp.latex(s)} = {latex_value(float(x))}" for s, x in zip(self.variables, self.values, strict=True)
        )
        verdict = r"\text{stable}" if self.stable else r"\text{unstable}"
        return rf"${vals}\ \left({verdict}\right)$"

    def __repr__(self) -> str:
        vals = ", ".join(f"{s}={x:.8g}" for s, x in zip(self.variables, self.values, strict=True))
        freqs = ", ".join(f"{w:.8g}" for w in self.frequencies)
        return f"QuasiPeriodicRegime({vals}; frequencies=({freqs}); {'stable' if self.stable else 'unstable'})"


@dataclass(frozen=True)
class AveragingNormalForm(SymPyPrintable):
    """Normal coordinates and exact equations (12.144), (12.151)–(12.153) of ``f(D) y = psi``.

    Attributes
    ----------
    D : Symbol
        The differentiation symbol of ``f(D)``.
    coordinates : tuple of Symbol
        The coordinates ``y_j``.
    psi : tuple of Expr
        The right-hand sides ``psi_j`` as given.
    real_roots : tuple of Expr
        The real roots ``kappa_s`` of ``Delta(D)`` (coordinates ``xi_s``).
    complex_roots : tuple of Expr
        ``eps_h + i omega_h`` with ``omega_h > 0``, ascending ``omega_h`` (amplitudes ``a_h``, phases ``u_h``).
    modal_columns, modal_rows : tuple of tuple of Expr
        ``v`` (with ``v_m = 1``) and ``w`` of ``F(kappa) = v w`` at every root, real roots first (12.147)–(12.150).
    reference : tuple of int
        The index ``m`` with ``v_m = 1`` for each root: ``a_h`` is the amplitude of ``y_m`` in pair ``h``.
    delta_prime : tuple of Expr
        ``Delta'(kappa)`` at every root.
    xi, amplitudes, phases : tuple of Symbol
        The new unknowns.
    substitution : dict
        ``y_j`` and every derivative symbol used in ``psi`` in terms of the new unknowns (12.144).
    xi_dot, a_dot, u_dot : tuple of Expr
        The exact right-hand sides (12.151)–(12.153).
    state_symbols : tuple of (int, int)
        The order of the entries of a state vector (:meth:`from_state`, :meth:`to_state`): one pair
        ``(j, nu)`` (coordinate index, derivative order) per entry, for ``D**nu y_j``; all ``y_j`` first, then the
        first derivatives of the coordinates that have them, and so on.
    time : Symbol or None
        The slow explicit time in ``psi`` (a parameter of the shortened equations), if any.
    """

    D: sp.Symbol
    coordinates: tuple
    psi: tuple
    real_roots: tuple
    complex_roots: tuple
    modal_columns: tuple = field(repr=False)
    modal_rows: tuple = field(repr=False)
    reference: tuple = field(repr=False)
    delta_prime: tuple = field(repr=False)
    xi: tuple = ()
    amplitudes: tuple = ()
    phases: tuple = ()
    substitution: dict = field(default_factory=dict, repr=False)
    xi_dot: tuple = field(default=(), repr=False)
    a_dot: tuple = field(default=(), repr=False)
    u_dot: tuple = field(default=(), repr=False)
    state_symbols: tuple = field(default=(), repr=False)  # (coordinate index, derivative order) per state entry
    time: sp.Symbol | None = None

    def __repr__(self) -> str:
        kr = ", ".join(f"{complex(r):.6g}" for r in self.real_roots)
        kc = ", ".join(f"{complex(r):.6g}" for r in self.complex_roots)
        return f"AveragingNormalForm(n={len(self.coordinates)}, real roots=[{kr}], oscillating pairs=[{kc}])"

    def _repr_latex_(self) -> str:
        lines = [rf"\dot {{{sp.latex(x)}}} = {sp.latex(e)}" for x, e in zip(self.xi, self.xi_dot, strict=True)]
        for a, u, ea, eu in zip(self.amplitudes, self.phases, self.a_dot, self.u_dot, strict=True):
            lines += [rf"\dot {{{sp.latex(a)}}} = {sp.latex(ea)}", rf"\dot {{{sp.latex(u)}}} = {sp.latex(eu)}"]
        return r"$\begin{array}{l}" + r" \\ ".join(lines) + r"\end{array}$"

    def _state_matrix(self, values: Mapping | None = None) -> np.ndarray:
        """Columns ``kappa^nu v_j`` of every root (conjugate pairs as two columns) over the state entries."""
        roots = list(self.real_roots) + [r for c in self.complex_roots for r in (c, sp.conjugate(c))]
        cols = list(self.modal_columns[: len(self.real_roots)])
        for col in self.modal_columns[len(self.real_roots) :]:
            cols += [col, tuple(sp.conjugate(e) for e in col)]
        T = np.zeros((len(self.state_symbols), len(roots)), dtype=complex)
        for i, (j, nu) in enumerate(self.state_symbols):
            for r, (kap, col) in enumerate(zip(roots, cols, strict=True)):
                T[i, r] = complex(sp.N(kap**nu * col[j], _DPS))
        return T

    def from_state(self, state: Sequence[float]) -> dict:
        """Normal coordinates ``{xi_s, a_h, u_h: value}`` of a state ``(y_j, Dy_j, ..., D^(m_j - 1) y_j)``.

        The state is ordered as :attr:`state_symbols`: all ``y_j`` first, then the first derivatives of the
        coordinates that have them, and so on (inverse of (12.144)).

        Parameters
        ----------
        state : sequence of float
            The state ``(y_j, Dy_j, ...)``, one finite number per entry of :attr:`state_symbols`, in that order.
        """
        x = np.asarray(state, dtype=float)
        if x.shape != (len(self.state_symbols),) or not np.all(np.isfinite(x)):
            raise ParameterError(f"state must be {len(self.state_symbols)} finite numbers ordered as state_symbols")
        z = np.linalg.solve(self._state_matrix(), x.astype(complex))
        s = len(self.real_roots)
        out: dict = {xi: float(z[i].real) for i, xi in enumerate(self.xi)}
        for h, (a, u) in enumerate(zip(self.amplitudes, self.phases, strict=True)):
            zh = z[s + 2 * h]
            out[a] = float(2 * abs(zh))
            out[u] = float(np.angle(zh))
        return out

    def to_state(self, coordinates: Mapping) -> np.ndarray:
        """The state ``(y_j, Dy_j, ...)`` (ordered as :attr:`state_symbols`) of given normal coordinates (12.144).

        Parameters
        ----------
        coordinates : mapping of Symbol or symbol name to float
            Values of the normal coordinates ``xi_s``, ``a_h`` and ``u_h`` (keys are the symbols or their names);
            finite numbers, a missing one counts as 0.
        """
        vals = {}
        for s in (*self.xi, *self.amplitudes, *self.phases):
            v = coordinates.get(s, coordinates.get(s.name, 0.0))
            vals[s] = float(v)
        T = self._state_matrix()
        s = len(self.real_roots)
        z = np.zeros(T.shape[1], dtype=complex)
        for i, xi in enumerate(self.xi):
            z[i] = vals[xi]
        for h, (a, u) in enumerate(zip(self.amplitudes, self.phases, strict=True)):
            zh = vals[a] / 2 * np.exp(1j * vals[u])
            z[s + 2 * h], z[s + 2 * h + 1] = zh, np.conj(zh)
        return (T @ z).real

    def shortened(self, active: Sequence[int] | None = None, *, n_samples: int = 64) -> ShortenedEquations:
        """Shortened equations (12.154): the right-hand sides averaged over the phases of the ``active`` pairs.

        Parameters
        ----------
        active : sequence of int, optional
            Indices of the oscillating pairs kept (default: all).  The others are set to zero amplitude (pairs
            strongly damped by the linear part, for which assumption (f) of §12.12 fails); a regime is then stable
            only if they decay (``eps_h < 0``).
        n_samples : int
            Points per phase of the torus quadrature used when ``psi`` is not a polynomial (relays, dry friction).

        Returns
        -------
        ShortenedEquations
        """
        return _shortened(self, active, n_samples)


@dataclass(frozen=True)
class ShortenedEquations(SymPyPrintable):
    """Shortened (averaged) equations of :class:`AveragingNormalForm` (Bulgakov (1954), eq. (12.154)).

    Attributes
    ----------
    variables : tuple of Symbol
        Slow variables: the real-root coordinates ``xi_s``, then the amplitudes of the active pairs.
    rates : tuple of Expr or None
        Their averaged right-hand sides (exact torus averages; ``None`` when ``psi`` is not a polynomial and the
        averages are evaluated by quadrature).
    phase_rates : tuple of Expr or None
        Averaged ``u_h'`` of the active pairs (``omega_h (1 + b_h)`` at a regime).
    active : tuple of int
        Indices of the averaged pairs.
    parameters : tuple of Symbol
        Other free symbols (values are passed to the numeric methods).
    normal_form : AveragingNormalForm
        The normal form the equations were averaged from.
    n_samples : int
        Points per phase of the torus quadrature used when ``psi`` is not a polynomial.
    """

    normal_form: AveragingNormalForm = field(repr=False)
    variables: tuple
    rates: tuple | None
    phase_rates: tuple | None
    active: tuple
    parameters: tuple
    n_samples: int = 64

    def __repr__(self) -> str:
        if self.rates is None:
            return f"ShortenedEquations(variables={self.variables}, averaged by quadrature)"
        eqs = ", ".join(f"{x}' = {e}" for x, e in zip(self.variables, self.rates, strict=True))
        return f"ShortenedEquations({eqs})"

    def _repr_latex_(self) -> str:
        if self.rates is None:
            return rf"$\text{{shortened equations in }} {sp.latex(self.variables)}$"
        rows = [rf"\dot {{{sp.latex(x)}}} = {sp.latex(e)}" for x, e in zip(self.variables, self.rates, strict=True)]
        return r"$\begin{array}{l}" + r" \\ ".join(rows) + r"\end{array}$"

    def jacobian(self) -> sp.Matrix:
        """Symbolic Jacobian of :attr:`rates` with respect to :attr:`variables` (the matrix of (12.219)–(12.223))."""
        if self.rates is None:
            raise ModelError("psi is not a polynomial: the averages are numeric; use regime(...).jacobian")
        return sp.Matrix(self.rates).jacobian(sp.Matrix(self.variables))

    def _param_values(self, values: Mapping | None) -> list[float]:
        from ..._validate import check_finite

        values = {} if values is None else dict(values)
        out = []
        missing = []
        for p in self.parameters:
            v = values.get(p, values.get(p.name))
            if v is None:
                missing.append(p.name)
            else:
                out.append(check_finite(f"values[{p.name!r}]", v))
        if missing:
            raise ParameterError("missing values for: " + ", ".join(missing))
        return out

    def _rates_at(self, state: Sequence[float], values: Mapping | None) -> tuple[np.ndarray, np.ndarray]:
        x = np.asarray(state, dtype=float)
        if x.shape != (len(self.variables),) or not np.all(np.isfinite(x)):
            raise ParameterError(f"state must be {len(self.variables)} finite numbers (for {self.variables})")
        return _rates(self, x, self._param_values(values))

    def rate_values(self, state: Sequence[float], values: Mapping | None = None) -> np.ndarray:
        """Averaged rates of :attr:`variables` at ``state`` (exact averages compiled, or torus quadrature).

        Parameters
        ----------
        state : sequence of float
            Values of the slow :attr:`variables`, one finite number each, in that order.
        values : mapping of Symbol or symbol name to float, optional
            Values of every symbol in :attr:`parameters` (keys are symbols or their names); a missing or non-finite
            value raises ParameterError.
        """
        return self._rates_at(state, values)[0]

    def phase_rate_values(self, state: Sequence[float], values: Mapping | None = None) -> np.ndarray:
        """Averaged phase rates ``u_h'`` of the active pairs at ``state`` (rad/s).

        Parameters
        ----------
        state : sequence of float
            Values of the slow :attr:`variables`, one finite number each, in that order.
        values : mapping of Symbol or symbol name to float, optional
            Values of every symbol in :attr:`parameters` (keys are symbols or their names); a missing or non-finite
            value raises ParameterError.
        """
        return self._rates_at(state, values)[1]

    def regime(
        self, guess: Sequence[float], values: Mapping | None = None, *, tol: float = 1e-10
    ) -> QuasiPeriodicRegime:
        """The quasi-periodic regime (constant slow variables, (12.155)) nearest to ``guess``, with its stability.

        Amplitudes given as exactly 0 in ``guess`` stay 0 (a suppressed pair: ``a_h = 0`` solves its averaged
        equation); their rows of the Jacobian give the growth rate of a small oscillation in that pair.

        Parameters
        ----------
        guess : sequence of float
            Starting values of the slow :attr:`variables`, one finite number each, in that order.
        values : mapping of Symbol or symbol name to float, optional
            Values of every symbol in :attr:`parameters` (keys are symbols or their names); a missing or non-finite
            value raises ParameterError.
        tol : float, optional
            Largest accepted residual of the rates, relative to the largest variable (and at least absolute); a
            positive number (default 1e-10).

        Raises
        ------
        ConvergenceError
            Newton's method did not reach ``tol`` (relative).
        """
        from scipy.optimize import fsolve

        x0 = np.asarray(guess, dtype=float)
        nv = len(self.variables)
        if x0.shape != (nv,) or not np.all(np.isfinite(x0)):
            raise ParameterError(f"guess must be {nv} finite numbers (for {self.variables})")
        p = self._param_values(values)
        ns = len(self.normal_form.xi)
        free = [i for i in range(nv) if not (i >= ns and x0[i] == 0.0)]

        def residual(xf: np.ndarray) -> np.ndarray:
            # amplitude equations are a_h * g_h(...): solve g_h = 0 so that Newton does not fall to a_h = 0
            x = x0.copy()
            x[free] = xf
            r = _rates(self, x, p)[0]
            amp = np.arange(nv) >= ns
            with np.errstate(divide="ignore", invalid="ignore"):
                r = np.where(amp, r / np.where(x == 0, np.nan, x), r)
            return r[free]

        x = x0.copy()
        if free:
            xf, _info, _ier, msg = fsolve(residual, x0[free], full_output=True, xtol=1e-14)
            x[free] = xf
        else:
            msg = ""
        res_vec, om = _rates(self, x, p)
        scale = max(1.0, float(np.max(np.abs(x))))
        res = float(np.max(np.abs(res_vec), initial=0.0))
        if not np.isfinite(res) or res > tol * scale:
            raise ConvergenceError(
                f"no regime of the shortened equations near {tuple(x0)}: residual {res:.3g} ({str(msg).strip()})"
            )
        # (a_h, u_h) -> (-a_h, u_h + pi) is the same motion: the averaged rates are odd in a_h
        x[ns:] = np.abs(x[ns:])
        J = _jacobian_values(self, x, p)
        eig = np.linalg.eigvals(J) if J.size else np.zeros(0, dtype=complex)
        nf = self.normal_form
        dropped_ok = all(
            float(sp.re(sp.N(nf.complex_roots[h], _DPS))) < 0
            for h in range(len(nf.complex_roots))
            if h not in self.active
        )
        stable = bool(np.all(eig.real < 0) and dropped_ok)
        return QuasiPeriodicRegime(
            variables=self.variables,
            values=x,
            frequencies=np.asarray(om, dtype=float),
            jacobian=J,
            eigenvalues=eig,
            stable=stable,
            residual=res,
        )

    def integrate(
        self,
        t_span: tuple[float, float],
        initial: Sequence[float],
        values: Mapping | None = None,
        *,
        t_eval: Any = None,
    ) -> tuple[np.ndarray, np.ndarray]:
        """Solve the shortened equations for the slow variables; returns ``(t, states)`` with states ``(n_var, n_t)``.

        The phases follow by quadrature of :meth:`phase_rate_values` (§12.12).

        Parameters
        ----------
        t_span : tuple of float
            ``(t0, t1)``: the interval of integration.
        initial : sequence of float
            Values of the slow :attr:`variables` at ``t0``, one finite number each, in that order.
        values : mapping of Symbol or symbol name to float, optional
            Values of every symbol in :attr:`parameters` (keys are symbols or their names); a missing or non-finite
            value raises ParameterError.
        t_eval : array_like of float, optional
            Times at which to return the solution, inside ``t_span``; the solver's own steps when omitted.
        """
        from scipy.integrate import solve_ivp

        x0 = np.asarray(initial, dtype=float)
        if x0.shape != (len(self.variables),) or not np.all(np.isfinite(x0)):
            raise ParameterError(f"initial must be {len(self.variables)} finite numbers (for {self.variables})")
        p = self._param_values(values)
        sol = solve_ivp(
            lambda _t, x: _rates(self, x, p)[0], t_span, x0, t_eval=t_eval, method="DOP853", rtol=1e-10, atol=1e-12
        )
        if not sol.success:
            raise ConvergenceError(f"integration of the shortened equations failed: {sol.message}")
        return sol.t, sol.y


# ----------------------------------------------------------------------------------------------------------------
# construction


@validated
def averaging_normal_form(
    fD: Any,
    psi: Sequence[Any],
    y: Sequence[sp.Symbol],
    D: sp.Symbol,
    *,
    derivatives: Mapping[sp.Symbol, tuple[sp.Symbol, int]] | None = None,
    time: sp.Symbol | None = None,
) -> AveragingNormalForm:
    """Normal coordinates and exact equations of ``f(D) y = psi`` (Bulgakov (1954), §12.11, (12.143)–(12.153)).

    Parameters
    ----------
    fD : Matrix
        ``n x n`` matrix of polynomials in ``D`` with numeric coefficients; ``Delta = det f`` with simple roots and
        nonzero leading coefficient (assumptions (a)–(c) of §12.11).
    psi : sequence of expressions
        ``psi_j`` in the symbols ``y`` and the derivative symbols (any other symbols are parameters).
    y : sequence of Symbol
        The coordinates.
    D : Symbol
        The differentiation symbol in ``fD``.
    derivatives : dict, optional
        ``{symbol: (y_k, nu)}``: symbols in ``psi`` that stand for ``D**nu y_k``, with ``nu`` below the highest
        power of ``D`` in column ``k`` of ``fD`` (assumption (d)).
    time : Symbol, optional
        Slow explicit time in ``psi`` (assumption (h)); kept as a parameter of the shortened equations.

    Returns
    -------
    AveragingNormalForm

    Raises
    ------
    ModelError
        Singular or improper operator, multiple roots, or a derivative of too high an order in ``psi``.

    See Also
    --------
    AveragingNormalForm.shortened : the averaged equations (12.154) and their regimes.
    symosc.nonlinear.poincare_operator_system : Poincaré's first approximation with one pair (12.34).
    symosc.nonlinear.averaged_equations_ndof : the mechanical case ``x_i'' + f_i = 0`` with diagonal linear part.

    Examples
    --------
    Van der Pol ``(D**2 + 1) y = mu (1 - y**2) Dy``: ``a' = mu a (1 - a**2/4) / 2``, stable at ``a = 2``.

    >>> import sympy as sp
    >>> D, y, v, mu = sp.symbols("D y v mu")
    >>> nf = averaging_normal_form(sp.Matrix([[D**2 + 1]]), [mu * (1 - y**2) * v], [y], D, derivatives={v: (y, 1)})
    >>> sh = nf.shortened()
    >>> sh.rates[0]
    -a1**3*mu/8 + a1*mu/2
    >>> regime = sh.regime([1.5], {"mu": 0.1})
    >>> regime
    QuasiPeriodicRegime(a1=2; frequencies=(1); stable)
    """
    f = _operator(fD, D)
    n = f.shape[0]
    ys = tuple(y)
    if len(ys) != n or not all(isinstance(s, sp.Symbol) for s in ys):
        raise ParameterError(f"y must be {n} Symbols (the size of fD)")
    try:
        psis = tuple(sp.sympify(e) for e in psi)
    except (TypeError, sp.SympifyError) as exc:
        raise ParameterError(f"psi must be {n} SymPy expressions") from exc
    if len(psis) != n:
        raise ParameterError(f"psi must have {n} entries (the size of fD), got {len(psis)}")
    degs = [max(sp.Poly(f[i, k], D).degree() for i in range(n)) for k in range(n)]
    delta = sp.Poly(sp.expand(f.det(method="berkowitz")), D)
    if delta.is_zero or delta.degree() < 1:
        raise ModelError("det f(D) is constant or identically zero: no oscillating normal coordinates")
    if delta.degree() != sum(degs):
        raise ModelError(
            f"the leading-coefficient determinant of f(D) vanishes (deg Delta = {delta.degree()} < {sum(degs)}): "
            "assumption (c) of Bulgakov (1954), §12.11 fails; reduce the system to one with independent highest "
            "derivatives"
        )
    ders: dict = {}
    for s, spec in (derivatives or {}).items():
        try:
            yk, nu = spec
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"derivatives[{s}] must be a pair (coordinate, order), got {spec!r}") from exc
        if yk not in ys:
            raise ParameterError(f"derivatives[{s}]: {yk} is not one of the coordinates {ys}")
        k = ys.index(yk)
        if isinstance(nu, bool) or not isinstance(nu, int | np.integer) or nu < 1:
            raise ParameterError(f"derivatives[{s}]: the order must be an integer >= 1, got {nu!r}")
        if nu >= degs[k]:
            raise ModelError(
                f"{s} = D**{nu} {yk} but column {k} of f(D) has degree {degs[k]}: psi may contain derivatives of "
                f"{yk} up to order {degs[k] - 1} only (assumption (d) of Bulgakov (1954), §12.11)"
            )
        ders[s] = (k, int(nu))
    exact = not any(e.has(sp.Float) for e in f)
    roots = _roots(delta)
    real = sorted([r for r in roots if _is_real(r)], key=lambda r: float(sp.re(sp.N(r, _DPS))))
    cplx = [r for r in roots if not _is_real(r) and float(sp.im(sp.N(r, _DPS))) > 0]
    cplx.sort(key=lambda r: float(sp.im(sp.N(r, _DPS))))
    real = [sp.re(r) if sp.im(r).is_zero is not False else sp.re(sp.N(r, _DPS)) for r in real]
    adj = f.adjugate(method="berkowitz")
    dprime = delta.diff(D)
    cols, rows, refs, dps_ = [], [], [], []
    for kap in [*real, *cplx]:
        F = adj.subs(D, kap)
        Fn = np.array(F.evalf(_DPS), dtype=complex)
        m, l = np.unravel_index(np.argmax(np.abs(Fn)), Fn.shape)
        if abs(Fn[m, l]) == 0:  # pragma: no cover - excluded by the simple-root check
            raise ModelError(f"the adjugate vanishes at the root {kap}")
        cols.append(tuple(_clean(F[j, l] / F[m, l], exact) for j in range(n)))
        rows.append(tuple(_clean(F[m, k], exact) for k in range(n)))
        refs.append(int(m))
        dps_.append(_clean(dprime.as_expr().subs(D, kap), exact))
    s1 = len(real)
    xi = tuple(sp.Symbol(f"xi{i + 1}", real=True) for i in range(s1))
    amps = tuple(sp.Symbol(f"a{h + 1}", nonnegative=True) for h in range(len(cplx)))
    phs = tuple(sp.Symbol(f"u{h + 1}", real=True) for h in range(len(cplx)))
    clash = {s.name for s in (*xi, *amps, *phs)} & {s.name for e in psis for s in e.free_symbols}
    if clash:
        raise ParameterError(f"psi uses the names {sorted(clash)} reserved for the normal coordinates; rename them")

    def state_expr(k: int, nu: int) -> sp.Expr:
        e = sp.S.Zero
        for kap, col, x in zip(real, cols[:s1], xi, strict=True):
            e += _clean(kap**nu * col[k], exact) * x
        for kap, col, a, u in zip(cplx, cols[s1:], amps, phs, strict=True):
            c = _clean(kap**nu * col[k], exact)
            e += a * (sp.re(c) * sp.cos(u) - sp.im(c) * sp.sin(u))
        return e

    sub = {ys[k]: state_expr(k, 0) for k in range(n)}
    for s, (k, nu) in ders.items():
        sub[s] = state_expr(k, nu)
    psub = [sp.expand(e.xreplace(sub)) for e in psis]
    xi_dot = []
    for i, x in enumerate(xi):
        xi_dot.append(sp.expand(real[i] * x + sum(rows[i][k] / dps_[i] * psub[k] for k in range(n))))
    a_dot, u_dot = [], []
    for h, (a, u) in enumerate(zip(amps, phs, strict=True)):
        kap, row, dp = cplx[h], rows[s1 + h], dps_[s1 + h]
        eps_h, om_h = sp.re(kap), sp.im(kap)
        ca = sp.S.Zero
        cu = sp.S.Zero
        for k in range(n):
            c = _clean(2 * row[k] / dp, exact)
            al, be = sp.re(c), sp.im(c)
            ca += psub[k] * (al * sp.cos(u) + be * sp.sin(u))
            cu += psub[k] * (be * sp.cos(u) - al * sp.sin(u))
        a_dot.append(eps_h * a + sp.expand(ca))
        u_dot.append(om_h + sp.expand(cu) / a)
    states = tuple((k, nu) for nu in range(max(degs)) for k in range(n) if nu < degs[k])
    return AveragingNormalForm(
        D=D,
        coordinates=ys,
        psi=psis,
        real_roots=tuple(real),
        complex_roots=tuple(cplx),
        modal_columns=tuple(cols),
        modal_rows=tuple(rows),
        reference=tuple(refs),
        delta_prime=tuple(dps_),
        xi=xi,
        amplitudes=amps,
        phases=phs,
        substitution=sub,
        xi_dot=tuple(xi_dot),
        a_dot=tuple(a_dot),
        u_dot=tuple(u_dot),
        state_symbols=states,
        time=time,
    )


# ----------------------------------------------------------------------------------------------------------------
# averaging and numerics


def _shortened(nf: AveragingNormalForm, active: Sequence[int] | None, n_samples: int) -> ShortenedEquations:
    npairs = len(nf.complex_roots)
    if active is None:
        act = tuple(range(npairs))
    else:
        try:
            act = tuple(sorted({int(h) for h in active}))
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"active must be a sequence of pair indices, got {active!r}") from exc
        if any(isinstance(h, bool) for h in active) or any(not 0 <= h < npairs for h in act):
            raise ParameterError(f"active must hold pair indices in 0..{npairs - 1}, got {active!r}")
    if isinstance(n_samples, bool) or not isinstance(n_samples, int | np.integer) or n_samples < 8:
        raise ParameterError(f"n_samples must be an integer >= 8, got {n_samples!r}")
    zero = {nf.amplitudes[h]: 0 for h in range(npairs) if h not in act}
    variables = (*nf.xi, *(nf.amplitudes[h] for h in act))
    slow = [e.xreplace(zero) for e in nf.xi_dot] + [nf.a_dot[h].xreplace(zero) for h in act]
    fast = [sp.expand(nf.u_dot[h].xreplace(zero)) for h in act]
    phases = [nf.phases[h] for h in act]
    rates: tuple | None
    prates: tuple | None
    try:
        r_out, p_out = [], []
        for e in slow:
            for u in phases:
                e = _trig.average(e, u)
            r_out.append(_tidy(e, variables))
        for h, e in zip(act, fast, strict=True):
            a = nf.amplitudes[h]
            e = sp.expand(e * a)
            for u in phases:
                e = _trig.average(e, u)
            p_out.append(_tidy(sp.cancel(e / a), variables))
        rates, prates = tuple(r_out), tuple(p_out)
        leftover = set().union(*(e.free_symbols for e in (*r_out, *p_out))) & (set(nf.phases))
        if leftover:  # pragma: no cover - the averages remove every phase
            rates = prates = None
    except ModelError:
        rates = prates = None
    params = set().union(*(e.free_symbols for e in (*slow, *fast))) - set(variables) - set(nf.phases) - set(zero)
    return ShortenedEquations(
        normal_form=nf,
        variables=variables,
        rates=rates,
        phase_rates=prates,
        active=act,
        parameters=tuple(sorted(params, key=lambda s: s.name)),
        n_samples=int(n_samples),
    )
