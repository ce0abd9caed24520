"""Characteristic exponents of an n-DOF Poincaré periodic solution as power series in ``eps`` (Bulgakov §12.5–12.6).

The variational equation of ``M q'' + K q = eps f(q, q', eps)`` about the periodic solution is written in the
scaled time ``tau = omega(eps) t`` (period ``2 pi``) as ``z_tau = B(tau, eps) z`` with
``B = J(t = tau/omega)/omega`` and ``J = [[0, I], [M^-1(-K + eps f_q), eps M^-1 f_v]]``.  ``B`` is a trigonometric
polynomial in ``tau`` and (with the truncated series inserted) a polynomial in ``eps``; its Taylor/Fourier
coefficients ``B_k(h)`` are extracted exactly (to rounding) by a two-dimensional FFT, on a circle in the complex
``eps`` plane and on a grid in ``tau``, whose sizes exceed the polynomial degrees (no aliasing).

A Floquet exponent ``kappa`` (in ``tau``) is an eigenvalue of the operator ``p -> B p - p_tau`` on ``2 pi``-periodic
``p``.  At ``eps = 0`` the operator is diagonal in Fourier space with eigenvalues ``lambda_l - i h``
(``lambda_l = ±i w_l/w_m`` the eigenvalues of ``B_0``).  For every non-critical mode ``j`` the eigenvalue
``i w_j/w_m`` is simple under the non-resonance conditions ``w_j/w_m ± w_k/w_m``, ``2 w_j/w_m``, ``w_j/w_m`` not
integers, and non-degenerate Rayleigh–Schrödinger perturbation theory (for a non-symmetric operator, normalisation
``v^T c_k(0) = 0``) gives its series to any order.  The critical pair (double eigenvalue 0 at ``eps = 0``) is not
expanded directly: one exponent is exactly 0 (autonomy) and the other follows from Liouville's formula, sum of all
exponents = mean of ``tr B`` over a period, itself a series.  The exponents in rad/s are ``mu = omega(eps) kappa``.

Order ``N`` means: every coefficient of ``eps**k``, ``k <= N``, of each exponent is exact (to rounding); the error
of the truncated sum is ``O(eps**(N+1))``.  This needs the periodic solution to order ``N - 1`` and the frequency to
order ``N``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._deprecation import deprecated_attribute as _deprecated_attribute
from ..._printing import SymPyPrintable
from ...errors import ModelError, ParameterError
from ._series import EpsSeries, SeriesResult

__all__ = ["CharacteristicExponentSeries"]


@dataclass(frozen=True)
class CharacteristicExponentSeries(SeriesResult, SymPyPrintable):
    """Characteristic (Floquet) exponents ``mu_i(eps) = sum_k c_ik eps**k + O(eps**(order+1))`` in rad/s.

    Attributes
    ----------
    coefficients : ndarray, shape (2n, order+1), complex
        Row ``i`` holds ``c_i0 .. c_i,order`` of exponent ``i``.  Rows: the critical pair first (``0`` exactly, then
        the exponent that decides orbital stability), then ``+``/``-`` pairs of the other modes in ascending
        frequency.  Imaginary parts are defined modulo the frequency ``omega(eps)`` (the multipliers are not).
    order : int
        Highest power of ``eps`` included; every included coefficient is exact to rounding.
    eps_symbol : Symbol
        The expansion variable.
    labels : tuple of str
        What each row is.
    """

    coefficients: np.ndarray
    order: int
    eps_symbol: sp.Symbol
    labels: tuple
    eps = _deprecated_attribute("eps_symbol")  # the old name of the small-parameter symbol

    def evaluate(self, eps: float, order: int | None = None) -> np.ndarray:
        """The truncated sums at ``eps`` (complex array, rad/s).

        Parameters
        ----------
        eps : float
            Value of the small parameter at which to sum the series; a real number.
        order : int, optional
            Highest power of ``eps`` kept, an integer from 0 to ``self.order``; all included orders when omitted.
        """
        n = self.order if order is None else int(order)
        if not 0 <= n <= self.order:
            raise ParameterError(f"exponents are known to order {self.order}; asked for {order}")
        powers = float(eps) ** np.arange(n + 1)
        return self.coefficients[:, : n + 1] @ powers

    def error_estimate(self, eps: float) -> np.ndarray:
        """Size of the last included term, per exponent (a heuristic for the truncation error).

        Parameters
        ----------
        eps : float
            Value of the small parameter at which to estimate; a real number.
        """
        return np.abs(self.coefficients[:, -1]) * abs(float(eps)) ** self.order

    def series(self, i: int, digits: int = 12) -> sp.Expr:
        """Exponent ``i`` as a SymPy polynomial in ``eps`` (Float coefficients).

        Parameters
        ----------
        i : int
            Row of the exponent (see ``labels``), an integer from 0 to ``2n - 1``.
        digits : int, optional
            Significant digits of the Float coefficients, a positive integer (default 12).
        """
        c = self.coefficients[i]
        return sp.Add(
            *[
                (sp.Float(z.real, digits) + sp.I * sp.Float(z.imag, digits)) * self.eps_symbol**k
                for k, z in enumerate(c)
                if abs(z) > 0
            ]
        )

    def series_expression(self) -> tuple[EpsSeries, ...]:
        """Every exponent as an :class:`EpsSeries` (complex ``Float`` coefficients, 15 digits): ``sympy.sympify``
        gives their column (an ``ImmutableMatrix``)."""
        out = []
        for label, row in zip(self.labels, self.coefficients, strict=True):
            cs = tuple(
                sp.Float(z.real, 15) + sp.I * sp.Float(z.imag, 15) if z.imag else sp.Float(z.real, 15) for z in row
            )
            out.append(EpsSeries(cs, self.eps_symbol, self.order, name=str(label)))
        return tuple(out)

    def _pretty_items(self) -> list:
        return [
            (str(label), self.series(i, 8) + sp.O(self.eps_symbol ** (self.order + 1)))
            for i, label in enumerate(self.labels)
        ]

    def _repr_latex_(self) -> str:
        rows = r" \\ ".join(sp.latex(self.series(i, 8)) for i in range(len(self.labels)))
        return rf"$\begin{{array}}{{l}}{rows}\end{{array}} + O({sp.latex(self.eps_symbol ** (self.order + 1))})$"

    def __repr__(self) -> str:
        lines = [f"CharacteristicExponentSeries(order={self.order}, rad/s;"]
        for lab, c in zip(self.labels, self.coefficients, strict=True):
            c = np.asarray(c, dtype=complex)
            tol = 1e-12 * float(np.max(np.abs(c), initial=0.0))  # rounding noise of the recurrence shown as 0
            c = np.where(np.abs(c.real) > tol, c.real, 0.0) + 1j * np.where(np.abs(c.imag) > tol, c.imag, 0.0)
            head = ", ".join(f"{z.real:.8g}{z.imag:+.8g}j" for z in c[:4])
            lines.append(f"  {lab}: [{head}{', ...' if len(c) > 4 else ''}]")
        return "\n".join(lines) + ")"


def _poly_degree(expr: sp.Expr, gens: tuple) -> int:
    if expr == 0:
        return 0
    return int(sp.Poly(expr, *gens).total_degree())


def exponent_series(sol: Any, order: int) -> CharacteristicExponentSeries:
    """Series of the characteristic exponents of ``sol`` (an ``NDofPeriodicSolution``) to ``order``."""
    if isinstance(order, bool) or not isinstance(order, int | np.integer) or order < 0:
        raise ParameterError(f"order must be an integer >= 0, got {order!r}")
    N = int(order)
    if N > sol.order:
        raise ParameterError(
            f"exponents to order {N} need the periodic solution to order {N}; it is known to order {sol.order}"
        )
    M, K, f, q, qdot, eps = sol._numeric
    n, m = sol.n, sol.mode
    Mi = np.linalg.inv(np.array(M.tolist(), dtype=float))
    Kn = np.array(K.tolist(), dtype=float)
    w = np.array(sol.mode_frequencies, dtype=float)
    wm = w[m]
    nu = w / wm
    # resonances that make i*nu_j a multiple eigenvalue of the unperturbed Floquet operator
    for j in range(n):
        if j == m:
            continue
        for k in range(n):
            for sgn in (1, -1):
                if k == j and sgn == 1:
                    continue
                d = nu[j] - sgn * nu[k]
                if abs(d - round(d)) < 1e-8:
                    kind = "parametric" if k == j else ("internal" if k == m else "combination")
                    raise ModelError(
                        f"{kind} resonance w_{j}/w_{m} {'-' if sgn == 1 else '+'} w_{k}/w_{m} = {d:.10g} is an "
                        "integer: the exponent series of this mode is degenerate (needs a block perturbation)"
                    )
    # Jacobian of f in (q, v) and its polynomial degree
    fm = sp.Matrix([sp.sympify(e) for e in f])
    gens = (*q, *qdot)
    Jf = fm.jacobian(list(gens))
    dF = max([_poly_degree(e, gens) for e in Jf] + [0])
    # series data: q_k(tau) (cos, sin) coefficients, omega and 1/omega coefficients
    A0 = sol.generating_amplitude
    Hq = max(len(cs) - 1 for k in range(N + 1) for (cs, _ss) in sol._coords[k])
    om_c = np.array([float(c) for c in sol.frequency.coefficients[: N + 1]]) * wm
    inv_c = np.array([float(c) for c in sol.period.coefficients[: N + 1]]) / wm
    HB = max(1, dF * Hq)
    Nt = 1 << max(4, int(np.ceil(np.log2(2 * HB + 2))))
    tau = 2 * np.pi * np.arange(Nt) / Nt
    hh = np.arange(Hq + 1)
    cosm, sinm = np.cos(np.outer(hh, tau)), np.sin(np.outer(hh, tau))
    qs, vs = [], []
    for i in range(n):
        qk = np.zeros((N + 1, Nt))
        dqk = np.zeros((N + 1, Nt))
        for k in range(N + 1):
            cs, ss = sol._coords[k][i]
            c = np.array([float(x) for x in cs] + [0.0] * (Hq + 1 - len(cs)))
            s = np.array([float(x) for x in ss] + [0.0] * (Hq + 1 - len(ss)))
            qk[k] = A0 * (c @ cosm + s @ sinm)
            dqk[k] = A0 * ((s * hh) @ cosm - (c * hh) @ sinm)
        qs.append(qk)
        vs.append(_cauchy(om_c[:, None], dqk))
    # Jacobian entries as truncated series in eps (exact Cauchy products, no aliasing)
    powers: dict = {}

    def power(var: int, p: int) -> np.ndarray:
        if (var, p) not in powers:
            base = (qs + vs)[var]
            powers[(var, p)] = base if p == 1 else _cauchy(power(var, p - 1), base)
        return powers[(var, p)]

    nv = 2 * n
    J = np.zeros((N + 1, Nt, n, nv))
    for idx, entry in enumerate(Jf):
        if entry == 0:
            continue
        a, b = divmod(idx, nv)
        for expo, coef in sp.Poly(entry, *gens, eps).terms():
            term = np.zeros((N + 1, Nt))
            shift = expo[-1]
            if shift > N:
                continue
            term[shift] = float(coef)
            for var, p in enumerate(expo[:-1]):
                if p:
                    term = _cauchy(term, power(var, p))
            J[:, :, a, b] += term
    Fq = np.einsum("ab,ksbc->ksac", Mi, J[..., :n])
    Fv = np.einsum("ab,ksbc->ksac", Mi, J[..., n:])
    B = np.zeros((N + 1, Nt, 2 * n, 2 * n))
    B[0, :, :n, n:] = np.eye(n)
    B[0, :, n:, :n] = -Mi @ Kn
    B[1:, :, n:, :n] += Fq[:-1]
    B[1:, :, n:, n:] += Fv[:-1]
    B = _cauchy(inv_c[:, None, None, None], B)
    Bh = np.fft.fft(B, axis=1) / Nt  # [k, h]
    Bk = np.zeros((N + 1, 2 * HB + 1, 2 * n, 2 * n), dtype=complex)
    for h in range(-HB, HB + 1):
        Bk[:, h + HB] = Bh[: N + 1, h % Nt]
    B0 = Bk[0, HB].real
    lam, U = np.linalg.eig(B0)
    Ui = np.linalg.inv(U)
    # critical exponent from Liouville: mean trace
    trace = np.array([np.trace(Bk[k, HB]) for k in range(N + 1)])
    kappas = []
    Hc = N * HB
    size = 2 * Hc + 1
    harm = np.arange(-Hc, Hc + 1)
    for j in range(n):
        if j == m:
            continue
        idx = int(np.argmin(np.abs(lam - 1j * nu[j])))
        u, v = U[:, idx], Ui[idx, :]
        k0 = lam[idx]
        den = lam[None, :] - 1j * harm[:, None] - k0  # (size, 2n)
        den[Hc, idx] = np.inf
        if np.min(np.abs(den)) < 1e-9:
            raise ModelError(
                f"small divisor in the exponent series of mode {j}: near-resonance of the Floquet spectrum"
            )
        c = [np.zeros((size, 2 * n), dtype=complex)]
        c[0][Hc] = u
        kap = [k0]
        for k in range(1, N + 1):
            S = np.zeros((size, 2 * n), dtype=complex)
            for i in range(1, k + 1):
                S += _conv(Bk[i], c[k - i], HB, Hc)
            kk = complex(v @ S[Hc])
            rhs = -S
            for i in range(1, k + 1):
                rhs += (kk if i == k else kap[i]) * c[k - i]
            ck = ((rhs @ Ui.T) / den) @ U.T
            kap.append(kk)
            c.append(ck)
        kappas.append(np.array(kap))
    crit = trace.copy()
    for kap in kappas:
        crit = crit - kap - np.conj(kap)
    crit[0] = 0.0
    rows = [np.zeros(N + 1, dtype=complex), crit]
    labels = ["critical 0", f"critical (mode {m})"]
    for jj, kap in zip([j for j in range(n) if j != m], kappas, strict=True):
        rows += [kap, np.conj(kap)]
        labels += [f"mode {jj} +", f"mode {jj} -"]
    out = np.array([np.convolve(om_c, r)[: N + 1] for r in rows])
    out[0] = 0.0
    return CharacteristicExponentSeries(coefficients=out, order=N, eps_symbol=eps, labels=tuple(labels))


def _cauchy(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Truncated Cauchy product along axis 0 (power series in eps), broadcasting the other axes."""
    N = max(a.shape[0], b.shape[0])
    out = np.zeros((N, *np.broadcast_shapes(a.shape[1:], b.shape[1:])), dtype=np.result_type(a, b))
    for i in range(a.shape[0]):
        for j in range(min(b.shape[0], N - i)):
            out[i + j] += a[i] * b[j]
    return out


def _conv(Bi: np.ndarray, c: np.ndarray, HB: int, Hc: int) -> np.ndarray:
    """Fourier convolution ``(B * c)_h = sum_g B_g c_{h-g}`` truncated to ``|h| <= Hc``."""
    out = np.zeros_like(c)
    size = 2 * Hc + 1
    scale = max(np.max(np.abs(Bi)), 1e-300)
    for g in range(-HB, HB + 1):
        Bg = Bi[g + HB]
        if np.max(np.abs(Bg)) <= 1e-15 * scale:
            continue
        lo, hi = max(0, g), min(size, size + g)  # target indices whose source h-g is in range
        out[lo:hi] += c[lo - g : hi - g] @ Bg.T
    return out
