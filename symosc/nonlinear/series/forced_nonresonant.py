"""Poincaré's method with an explicitly periodic right-hand side, non-resonant case (Bulgakov (1954), §5.23).

``q'' + omega0**2 q = Phi(q, q', t, mu)`` with ``Phi`` of period ``P = 2 pi / Omega`` in ``t`` and ``Phi(q, v, t, 0)
= f0(t)`` (the forcing of the generating system).  When no multiple ``n Omega`` equals ``omega0`` the generating
system has exactly one ``P``-periodic solution ``q*(t)`` (the forced response) and the periodicity conditions (5.288)
have a nonsingular Jacobian (the multipliers ``exp(+- i omega0 P)`` differ from 1), so the periodic solution
continues analytically in ``mu``, with initial values ``C1(mu) = q(0)``, ``C2(mu) = q'(0)`` (5.289).

The series ``q = q0 + mu q1 + mu**2 q2 + ...`` is computed order by order: ``q_k'' + omega0**2 q_k = [mu**k] Phi``,
whose right-hand side involves only ``q_0 .. q_(k-1)``, is solved harmonic by harmonic, ``c_n(q_k) = c_n(rhs) /
(omega0**2 - n**2 Omega**2)``.  The ``mu``-Taylor coefficients of ``Phi`` are taken exactly (to rounding) by an FFT over
a circle in the complex ``mu`` plane, on a time grid fine enough that no harmonic aliases (``Phi`` polynomial in
``q``, ``v`` and ``mu``; any dependence on ``t``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_int, check_positive, validated
from ...errors import ConvergenceError, ModelError, ParameterError
from ...numeric import compile as _compile
from ...symbols import t as _t
from ._series import EpsSeries, SeriesResult

__all__ = ["NonResonantForcedSolution", "nonresonant_forced_solution"]


@dataclass(frozen=True)
class NonResonantForcedSolution(SeriesResult, SymPyPrintable):
    """Series ``q(t) = sum_k mu**k q_k(t)`` of the forced periodic solution (Bulgakov (1954), §5.23).

    Attributes
    ----------
    C1, C2 : EpsSeries
        ``q(0)`` and ``q'(0)`` as series in ``mu`` (5.289).
    omega0, Omega : float
        Natural and forcing frequencies (rad/s).
    order : int
        Highest power of ``mu``.
    harmonics : ndarray, shape (order + 1, n_harmonics + 1), complex
        One-sided Fourier coefficients of ``q_k``: ``q_k(t) = Re sum_n c_kn e^{i n Omega t}`` (``c_k0`` real).
    tail : float
        Largest absolute coefficient in the upper quarter of the harmonics kept (the truncation of the Fourier grid).
    """

    C1: EpsSeries
    C2: EpsSeries
    omega0: float
    Omega: float
    order: int
    harmonics: np.ndarray = field(repr=False)
    tail: float = 0.0

    @property
    def period(self) -> float:
        """The forcing period ``P = 2 pi / Omega``."""
        return 2 * np.pi / self.Omega

    def evaluate(self, t: Any, mu: float, order: int | None = None) -> np.ndarray:
        """``q(t)`` of the series truncated at ``order`` (default: all terms).

        Parameters
        ----------
        t : float or array_like of float
            Time(s) at which to evaluate; real numbers (the solution has period ``2 pi / Omega``).
        mu : float
            Value of the small parameter ``mu``; a finite real number.
        order : int, optional
            Highest power of ``mu`` kept, an integer from 0 to ``self.order``; all computed orders when omitted.
        """
        n = self.order if order is None else check_int("order", order, minimum=0, maximum=self.order)
        m = check_finite("mu", mu)
        tt = np.asarray(t, dtype=float)
        h = np.arange(self.harmonics.shape[1])
        coeff = sum(m**k * self.harmonics[k] for k in range(n + 1))
        return (np.exp(1j * self.Omega * np.multiply.outer(tt, h)) @ coeff).real

    def solution_series(self, order: int | None = None, t: sp.Symbol = _t) -> EpsSeries:
        """``q(t) = sum_k mu**k q_k(t) + O(mu**(order+1))`` with ``q_k(t) = Re sum_n c_kn exp(i n Omega t)`` written
        out in cosines and sines (``Float`` coefficients): what ``sympy.sympify`` gives.

        Parameters
        ----------
        order : int, optional
            Highest power of ``mu`` kept (default: all, ``self.order``).
        t : Symbol
            The time variable (default :data:`symosc.t`).
        """
        n = self.order if order is None else check_int("order", order, minimum=0, maximum=self.order)
        W = sp.Float(self.Omega, 17)
        coefficients = []
        for row in self.harmonics[: n + 1]:
            terms = [sp.Float(float(row[0].real), 17)]
            for h, c in enumerate(row[1:], start=1):
                if c.real:
                    terms.append(sp.Float(float(c.real), 17) * sp.cos(h * W * t))
                if c.imag:
                    terms.append(-sp.Float(float(c.imag), 17) * sp.sin(h * W * t))
            coefficients.append(sp.Add(*terms))
        return EpsSeries(tuple(coefficients), self.C1.symbol, n, name="q")

    def series_expression(self) -> EpsSeries:
        """The solution ``q(t)`` with its order term (:meth:`solution_series`)."""
        return self.solution_series()

    def _pretty_items(self) -> list:
        return [("C1", self.C1), ("C2", self.C2)]

    def initial_state(self, mu: float, order: int | None = None) -> np.ndarray:
        """``(C1(mu), C2(mu))``: the initial state of the periodic solution, series truncated at ``order``.

        Parameters
        ----------
        mu : float
            Value of the small parameter ``mu``; a real number.
        order : int, optional
            Highest power of ``mu`` kept, an integer >= 0; all computed orders when omitted (larger values are
            clipped to ``self.order``).
        """
        return np.array([self.C1.evaluate(mu, order), self.C2.evaluate(mu, order)])

    def _repr_latex_(self) -> str:
        return rf"$C_1 = {sp.latex(self.C1.expr)},\ C_2 = {sp.latex(self.C2.expr)}$"

    def __repr__(self) -> str:
        c1 = ", ".join(f"{float(c):.8g}" for c in self.C1.coefficients[:4])
        c2 = ", ".join(f"{float(c):.8g}" for c in self.C2.coefficients[:4])
        return (
            f"NonResonantForcedSolution(omega0={self.omega0:.6g}, Omega={self.Omega:.6g}, order={self.order},\n"
            f"  C1 = [{c1}{', ...' if self.order > 3 else ''}], C2 = [{c2}{', ...' if self.order > 3 else ''}])"
        )


@validated
def nonresonant_forced_solution(
    Phi: Any,
    q: sp.Symbol,
    v: sp.Symbol,
    t: sp.Symbol,
    omega0: float,
    Omega: float,
    order: int,
    *,
    mu: sp.Symbol | None = None,
    n_harmonics: int = 64,
) -> NonResonantForcedSolution:
    """Periodic solution of ``q'' + omega0**2 q = Phi(q, q', t, mu)`` as a series in ``mu``, non-resonant forcing.

    Bulgakov (1954), §5.23, eqs. (5.285)–(5.289): the period ``2 pi / Omega`` is imposed by the forcing, there is no
    frequency correction and no free phase; ``C1(mu) = q(0)``, ``C2(mu) = q'(0)``.

    Parameters
    ----------
    Phi : expression
        Polynomial in ``q``, ``v`` and ``mu`` with coefficients depending on ``t`` (period ``2 pi / Omega``), such
        that ``Phi(q, v, t, 0)`` depends on ``t`` only (the generating system is linear with forcing).
    q, v, t : Symbol
        Coordinate, velocity and time in ``Phi``.
    omega0, Omega : float
        Natural and forcing frequencies; ``n Omega != omega0`` for every integer ``n`` in the harmonics kept.
    order : int
        Highest power of ``mu`` (>= 0).
    mu : Symbol, optional
        The small parameter in ``Phi`` (default: the symbol named ``mu``).
    n_harmonics : int
        Harmonics of ``Omega`` kept (the time grid has ``4 n_harmonics`` points).

    Returns
    -------
    NonResonantForcedSolution

    Raises
    ------
    ModelError
        A harmonic ``n Omega`` within ``1e-8`` (relative) of ``omega0`` (resonance: use
        :func:`forced_periodic_solution`), or ``Phi`` at ``mu = 0`` depends on ``q`` or ``v``.
    ConvergenceError
        The harmonics of the highest order do not decay within ``n_harmonics`` (raise it).

    See Also
    --------
    forced_periodic_solution : the resonant case ``Omega = omega0`` (first approximation).
    symosc.nonlinear.averaged_equations : frequency response near resonance.

    Examples
    --------
    Forced Duffing oscillator away from resonance, ``q'' + q = cos(2 t) - mu q**3``: the generating response is
    ``-cos(2 t)/3`` and ``q1 = -(cos(2 t) + cos(6 t)/35)/108``, so ``C1 = -1/3 - mu/105 + O(mu**2)``.

    >>> import sympy as sp
    >>> q, v, t, mu = sp.symbols("q v t mu")
    >>> sol = nonresonant_forced_solution(sp.cos(2 * t) - mu * q**3, q, v, t, 1.0, 2.0, 3)
    >>> [round(float(c), 12) for c in sol.C1.coefficients[:2]]
    [-0.333333333333, -0.009523809524]
    """
    try:
        Phi = sp.sympify(Phi)
    except (TypeError, sp.SympifyError) as exc:
        raise ParameterError(f"Phi must be a SymPy expression, got {type(Phi).__name__}") from exc
    for name, s in (("q", q), ("v", v), ("t", t)):
        if not isinstance(s, sp.Symbol):
            raise ParameterError(f"{name} must be a Symbol, got {type(s).__name__}")
    if mu is None:
        cands = [s for s in Phi.free_symbols if s.name == "mu"]
        mu = cands[0] if cands else sp.Symbol("mu")
    w0 = check_positive("omega0", omega0)
    W = check_positive("Omega", Omega)
    N = check_int("order", order, minimum=0, maximum=60)
    H = check_int("n_harmonics", n_harmonics, minimum=4, maximum=4096)
    extra = Phi.free_symbols - {q, v, t, mu}
    if extra:
        raise ParameterError("Phi: substitute values for " + ", ".join(sorted(s.name for s in extra)))
    if not Phi.is_polynomial(q, v, mu):
        raise ModelError("Phi must be a polynomial in q, v and mu (coefficients may depend on t)")
    if Phi.subs(mu, 0).has(q, v):
        raise ModelError(
            "Phi at mu = 0 depends on q or v: move the linear part to the left-hand side (omega0) so that the "
            "generating system is q'' + omega0**2 q = f0(t)"
        )
    n = np.arange(H + 1)
    den = w0**2 - (n * W) ** 2
    if np.min(np.abs(den)) < 1e-8 * max(w0**2, 1.0):
        k = int(np.argmin(np.abs(den)))
        raise ModelError(
            f"resonance: {k} * Omega = {k * W:.10g} equals omega0 = {w0:.10g}; the generating system has a family "
            "of periodic solutions (use forced_periodic_solution for the resonant case)"
        )
    deg_mu = sp.Poly(Phi, q, v, mu).degree(mu)
    deg_qv = sp.Poly(Phi, q, v).total_degree()
    M = 1 << int(np.ceil(np.log2(max(8, deg_qv * N + deg_mu + 2))))  # points on the mu circle (no aliasing)
    Nt = 4 * H
    tt = 2 * np.pi / W * np.arange(Nt) / Nt
    zs = np.exp(2j * np.pi * np.arange(M) / M)  # |mu| = 1: exact for the polynomial composition
    f = _compile(Phi, [q, v, t, mu], check=False).raw
    coef = np.zeros((N + 1, H + 1), dtype=complex)  # one-sided harmonics: q_k = Re sum c_n e^{i n W t}
    ik = 1j * n * W
    e = np.exp(1j * W * np.outer(tt, n))  # (Nt, H+1)
    for k in range(N + 1):
        # q(mu) and v(mu) truncated at mu^(k-1) on the circle, at every grid time
        Q = np.zeros((M, Nt), dtype=complex)
        V = np.zeros((M, Nt), dtype=complex)
        for j in range(k):
            qj = (e @ coef[j]).real
            vj = (e @ (ik * coef[j])).real
            Q += np.multiply.outer(zs**j, qj)
            V += np.multiply.outer(zs**j, vj)
        vals = np.broadcast_to(np.asarray(f(Q, V, tt[None, :], zs[:, None]), dtype=complex), (M, Nt))
        rhs = (np.fft.fft(vals, axis=0) / M)[k].real  # [mu^k] Phi(t)
        ch = np.fft.rfft(rhs) / Nt
        c = np.zeros(H + 1, dtype=complex)
        c[0] = ch[0]
        c[1:] = 2 * ch[1 : H + 1]
        coef[k] = c / den
    quarter = max(1, (H + 1) // 4)
    scale = max(float(np.max(np.abs(coef))), 1e-300)
    tail = float(np.max(np.abs(coef[:, -quarter:])))
    if tail > 1e-10 * scale:
        raise ConvergenceError(
            f"the harmonics of the series do not decay within n_harmonics = {H} (tail {tail:.3g} of {scale:.3g}); "
            "increase n_harmonics"
        )
    c1 = tuple(sp.Float(float(np.sum(coef[k]).real), 17) for k in range(N + 1))
    c2 = tuple(sp.Float(float(np.sum(ik * coef[k]).real), 17) for k in range(N + 1))
    return NonResonantForcedSolution(
        C1=EpsSeries(coefficients=c1, symbol=mu, order=N, name="C1 = q(0)"),
        C2=EpsSeries(coefficients=c2, symbol=mu, order=N, name="C2 = q'(0)"),
        omega0=w0,
        Omega=W,
        order=N,
        harmonics=coef,
        tail=tail,
    )
