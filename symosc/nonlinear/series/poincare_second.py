"""Poincaré's second approximation for ``f(D) y = mu psi(y, Dy)`` (Bulgakov (1954), §12.4, eqs. (12.36)–(12.41)).

With ``u = Omega t`` and ``Omega = omega (1 + b mu + c mu**2 / 2 + ...)`` (12.20)–(12.23), ``y = y0 + mu y1 + ...``
and ``D = Omega d/du``, harmonic ``k`` of each order solves ``f(i k omega) Y_k = R_k``.  For ``k != +-1`` the matrix is
regular (no root ``+- i k omega`` of ``Delta``); at ``k = 1`` it has rank ``n - 1`` and the right-hand side must be
orthogonal to the left null row ``L`` of ``f(i omega)`` (12.30):

* order 1: ``L [-i Omega1 f'(i omega) Y0 + Psi0] = 0`` gives the generating amplitude ``A*`` (``G(A*) = 0``) and ``b``
  (12.35);
* order 2: ``L [-i Omega1 f' Y1 - (i Omega2 f' + (i Omega1)**2 f''/2) Y0 + Psi1] = 0`` with ``Psi1 = psi_y y1 +
  psi_v (Omega1 y0_u + omega y1_u)`` is linear in the amplitude correction ``B`` of ``y1`` and in ``Omega2``; it is
  solvable exactly when ``G'(A*) != 0`` (12.39)–(12.40) and gives ``B`` and ``c``.

The phase is fixed by the reference coordinate ``y_m`` (``V_m = 1``): its first harmonic is a pure cosine at every
order (the book's ``B1 = 0``), so ``y_m = (A + mu B) cos u + (higher harmonics) + O(mu**2)``.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_int, check_positive, validated
from ...errors import ModelError, ParameterError
from ...numeric import compile as _compile

__all__ = ["SecondApproximation", "poincare_second_approximation"]


@dataclass(frozen=True)
class SecondApproximation(SymPyPrintable):
    """Periodic solution of ``f(D) y = mu psi`` to the second approximation (Bulgakov (1954), §12.4).

    Attributes
    ----------
    omega : float
        The critical frequency (``Delta(+- i omega) = 0``).
    amplitude : float
        Generating amplitude ``A*`` of the reference coordinate ``y_m`` (12.35).
    B : float
        First correction of that amplitude: ``A* + mu B`` (12.36), (12.39).
    b, c : float
        Frequency ``omega (1 + b mu + c mu**2 / 2)`` (12.23), (12.37), (12.41).
    slope : float
        ``G'(A*)`` in the normalisation ``Omega1 = Re Q(A) / A``-free form used here; nonzero by (12.40).
    reference : int
        The index ``m`` of the reference coordinate.
    V : ndarray (complex)
        Generating mode with ``V_m = 1``: ``y0 = A* Re(V e^{iu})``.
    harmonics : ndarray, shape (2, n, n_harmonics + 1), complex
        One-sided Fourier coefficients of ``y0`` and ``y1`` (``y = Re sum_k Y_k e^{i k u}``, ``Y_0`` real).
    _operator : tuple of ndarray
        Internal: the coefficient matrices of ``f(D)`` in ascending powers of ``D``, used by :meth:`r_matrix`.
    _jacobian : tuple
        Internal: the rows of the Jacobian of ``psi`` (expressions) and the symbols they are written in.
    """

    omega: float
    amplitude: float
    B: float
    b: float
    c: float
    slope: float
    reference: int
    V: np.ndarray = field(repr=False)
    harmonics: np.ndarray = field(repr=False)
    _operator: tuple = field(default=(), repr=False, compare=False)  # coefficient matrices of f(D), ascending powers
    _jacobian: tuple = field(default=(), repr=False, compare=False)  # (psi Jacobian rows as Exprs, argument symbols)

    def frequency(self, mu: float, order: int = 2) -> float:
        """``omega (1 + b mu)`` (``order=1``) or ``omega (1 + b mu + c mu**2 / 2)`` (``order=2``), rad/s.

        Parameters
        ----------
        mu : float
            Value of the small parameter ``mu``; a finite real number.
        order : int, optional
            Number of corrections kept, an integer 0, 1 or 2 (default 2; 0 gives ``omega``).
        """
        m = check_finite("mu", mu)
        k = check_int("order", order, minimum=0, maximum=2)
        return self.omega * (1 + (self.b * m if k >= 1 else 0.0) + (self.c * m * m / 2 if k >= 2 else 0.0))

    def reference_amplitude(self, mu: float, order: int = 1) -> float:
        """First-harmonic amplitude of ``y_m``: ``A*`` (``order=0``) or ``A* + mu B`` (``order=1``).

        Parameters
        ----------
        mu : float
            Value of the small parameter ``mu``; a finite real number.
        order : int, optional
            Number of corrections kept, an integer 0 or 1 (default 1).
        """
        m = check_finite("mu", mu)
        k = check_int("order", order, minimum=0, maximum=1)
        return self.amplitude + (self.B * m if k == 1 else 0.0)

    def solution(self, u: Any, mu: float) -> np.ndarray:
        """``y0(u) + mu y1(u)`` (shape ``(n, len(u))``), ``u = Omega t``; error ``O(mu**2)``.

        Parameters
        ----------
        u : float or array_like of float
            Phase(s) ``u = Omega t`` at which to evaluate, in radians; real numbers.
        mu : float
            Value of the small parameter ``mu``; a finite real number.
        """
        m = check_finite("mu", mu)
        uu = np.atleast_1d(np.asarray(u, dtype=float))
        Y = self.harmonics[0] + m * self.harmonics[1]
        k = np.arange(Y.shape[1])
        return (Y @ np.exp(1j * np.outer(k, uu))).real

    def r_matrix(self, n_nodes: int = 256) -> np.ndarray:
        """Bulgakov's matrix ``R`` of the monodromy ``e^{QP} + mu R + O(mu**2)`` (§12.6, eqs. (12.56), (12.65)).

        Only for first-order systems ``f(D) = A D + H`` (the case the book treats): with ``L = -A^-1 H``,
        ``R = e^{LP} [-b L P + Integral(e^{-L tau} A^-1 Psi(y*(tau)) e^{L tau}, (tau, 0, P))]``, ``Psi = dpsi/dy``,
        in the original coordinates (the book's (12.65) in the modal basis ``v``, ``H1 = -Psi``).  The integral uses
        Gauss–Legendre quadrature on ``n_nodes`` points.

        Parameters
        ----------
        n_nodes : int, optional
            Number of quadrature nodes over the period, an integer from 16 to 100000 (default 256; used in panels
            of 16 Gauss–Legendre points).
        """
        import scipy.linalg as sl

        F = self._operator
        if len(F) != 2:
            raise ModelError("the R-matrix (12.65) is formed for first-order systems f(D) = A D + H only")
        nn = check_int("n_nodes", n_nodes, minimum=16, maximum=100000)
        H, A = F
        Ai = np.linalg.inv(A)
        L = (-Ai @ H).real
        P = 2 * np.pi / self.omega
        exprs, args = self._jacobian
        jac = _compile(list(exprs), list(args), check=False).raw
        n = A.shape[0]
        x, wq = np.polynomial.legendre.leggauss(16)
        panels = max(1, nn // 16)
        edges = np.linspace(0, P, panels + 1)
        K = -self.b * L * P
        k = np.arange(self.harmonics.shape[2])
        for lo, hi in itertools.pairwise(edges):
            taus = (hi - lo) / 2 * x + (hi + lo) / 2
            for tau, wt in zip(taus, wq * (hi - lo) / 2, strict=True):
                y0 = (self.harmonics[0] @ np.exp(1j * k * self.omega * tau)).real
                Psi = np.asarray(jac(*y0, *np.zeros(len(args) - n)), dtype=float).reshape(n, len(args))[:, :n]
                E = sl.expm(L * tau)
                K = K + wt * np.linalg.solve(E, Ai.real @ Psi @ E)
        return sl.expm(L * P) @ K

    def critical_multipliers(self, mu: float) -> np.ndarray:
        """``1 + mu eta`` for the two roots ``eta`` of the critical block of :meth:`r_matrix` (12.61)–(12.64).

        One ``eta`` is 0 (autonomy); the other decides orbital stability (stable if negative, with the other roots
        of ``Delta`` in the left half-plane).

        Parameters
        ----------
        mu : float
            Value of the small parameter ``mu``; a finite real number.
        """
        m = check_finite("mu", mu)
        R = self.r_matrix()
        H, A = self._operator
        lam, U = np.linalg.eig(-np.linalg.inv(A) @ H)
        crit = np.argsort(np.abs(np.abs(lam.imag) - self.omega) + np.abs(lam.real))[:2]
        W = np.linalg.inv(U)[crit]
        eta = np.linalg.eigvals(W @ R @ U[:, crit])
        return np.real_if_close(1 + m * eta[np.argsort(np.abs(eta))], tol=1e6)

    def _repr_latex_(self) -> str:
        return (
            rf"$A^* = {self.amplitude:.8g},\ B = {self.B:.8g},\ \Omega = {self.omega:.8g}"
            rf"\left(1 + {self.b:.8g}\,\mu + \frac{{{self.c:.8g}}}{{2}}\mu^2\right)$"
        )

    def __repr__(self) -> str:
        return (
            f"SecondApproximation(omega={self.omega:.8g}, A*={self.amplitude:.10g}, B={self.B:.8g}, "
            f"b={self.b:.8g}, c={self.c:.8g}, reference=y[{self.reference}])"
        )


def _poly_coeffs(f: sp.Matrix, D: sp.Symbol) -> list[np.ndarray]:
    n = f.shape[0]
    deg = max(sp.Poly(e, D).degree() for e in f)
    out = [np.zeros((n, n), dtype=complex) for _ in range(deg + 1)]
    for i in range(n):
        for j in range(n):
            for (p,), c in sp.Poly(f[i, j], D).terms():
                out[p][i, j] = complex(c)
    return out


def _fval(F: list[np.ndarray], s: complex, der: int = 0) -> np.ndarray:
    out = np.zeros_like(F[0])
    for p in range(der, len(F)):
        fac = 1.0
        for r in range(der):
            fac *= p - r
        out = out + fac * F[p] * s ** (p - der)
    return out


@validated
def poincare_second_approximation(
    fD: Any,
    psi: Sequence[Any],
    y: Sequence[sp.Symbol],
    dy: Sequence[sp.Symbol],
    D: sp.Symbol,
    A_max: float,
    *,
    amplitude0: float | None = None,
    n_harmonics: int = 32,
) -> SecondApproximation:
    """Amplitude and frequency of the periodic solution of ``f(D) y = mu psi(y, Dy)`` to second order in ``mu``.

    Bulgakov (1954), §12.3–12.4, eqs. (12.26)–(12.41).

    Parameters
    ----------
    fD : Matrix
        ``n x n`` matrix of polynomials in ``D`` (numeric coefficients) whose determinant has one simple pair
        ``+- i omega`` and no root ``+- i k omega`` (``k = 0, 2, 3, ...``).
    psi : sequence of expressions
        ``psi_j`` in ``y`` and ``dy`` (smooth; derivatives must be polynomial-free of singularities on the cycle).
    y, dy : sequences of Symbol
        Coordinates and their first derivatives.
    D : Symbol
        The differentiation symbol.
    A_max : float
        Generating amplitudes ``A*`` (of the reference coordinate) are searched in ``(0, A_max]``.
    amplitude0 : float, optional
        Choose the root nearest to it when there are several.
    n_harmonics : int
        Harmonics kept (the grid has ``4 n_harmonics`` points; exact for polynomial ``psi`` of degree below 4).

    Returns
    -------
    SecondApproximation

    Raises
    ------
    ModelError
        No or several generating amplitudes (without ``amplitude0``), a resonant root ``+- i k omega``, or
        ``G'(A*) = 0`` (12.40): the second approximation does not exist.

    See Also
    --------
    poincare_operator_system : the first approximation and the stability of the cycle.
    periodic_solution_ndof : any order for ``M q'' + K q = eps f``.

    Examples
    --------
    Van der Pol, ``(D**2 + 1) y = mu (1 - y**2) Dy``: ``A* = 2``, ``B = 0``, ``b = 0``, ``c / 2 = -1/16``.

    >>> import sympy as sp
    >>> D, y, v = sp.symbols("D y v")
    >>> sa = poincare_second_approximation(sp.Matrix([[D**2 + 1]]), [(1 - y**2) * v], [y], [v], D, 5.0)
    >>> [round(x, 12) + 0.0 for x in (sa.amplitude, sa.B, sa.b, sa.c / 2)]
    [2.0, 0.0, 0.0, -0.0625]
    """
    from scipy.optimize import brentq

    from ..averaging._normal_form_support import _operator

    f = _operator(fD, D)
    n = f.shape[0]
    ys, dys = tuple(y), tuple(dy)
    if len(psi) != n or len(ys) != n or len(dys) != n:
        raise ParameterError(f"psi, y and dy must each have {n} entries (the size of fD)")
    Amax = check_positive("A_max", A_max)
    H = check_int("n_harmonics", n_harmonics, minimum=4, maximum=1024)
    psis = [sp.sympify(e) for e in psi]
    extra = set().union(*(e.free_symbols for e in psis)) - set(ys) - set(dys)
    if extra:
        raise ParameterError("psi: substitute values for " + ", ".join(sorted(s.name for s in extra)))
    delta = sp.Poly(sp.expand(f.det(method="berkowitz")), D)
    roots = np.roots([complex(c) for c in delta.all_coeffs()])
    scale = max(1.0, float(np.max(np.abs(roots), initial=1.0)))
    imag = roots[(np.abs(roots.real) < 1e-9 * scale) & (roots.imag > 1e-9 * scale)]
    if imag.size != 1:
        raise ModelError(f"Delta(D) must have exactly one simple imaginary pair +-i omega; its roots are {roots}")
    w = float(imag[0].imag)
    if np.sum(np.abs(roots - 1j * w) < 1e-7 * scale) > 1:
        raise ModelError("the imaginary pair is a multiple root of Delta(D)")
    F = _poly_coeffs(f, D)
    for k in [0, *range(2, H + 1)]:
        if np.any(np.abs(roots - 1j * k * w) < 1e-9 * scale):
            raise ModelError(f"Delta(D) has the resonant root {k}i*omega (12.17): the series does not exist")
    adj = np.array(f.adjugate(method="berkowitz").subs(D, sp.I * w).evalf(), dtype=complex)
    col = int(np.argmax(np.max(np.abs(adj), axis=0)))
    m = int(np.argmax(np.abs(adj[:, col])))
    V = adj[:, col] / adj[m, col]
    row = int(np.argmax(np.max(np.abs(adj), axis=1)))
    L = adj[row, :]
    f1 = _fval(F, 1j * w)
    fp = _fval(F, 1j * w, 1)
    fpp = _fval(F, 1j * w, 2)
    Nt = 4 * H
    u = 2 * np.pi * np.arange(Nt) / Nt
    args = [*ys, *dys]
    psi_f = _compile(psis, args, check=False).raw
    jac = sp.Matrix(psis).jacobian(sp.Matrix(args))
    jac_f = _compile(jac, args, check=False).raw

    def synth(Y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """values and u-derivatives on the grid of y = Re sum_k Y_k e^{iku} (Y: (n, H+1))."""
        k = np.arange(Y.shape[1])
        E = np.exp(1j * np.outer(k, u))
        return (Y @ E).real, ((1j * k * Y) @ E).real

    def analyse(x: np.ndarray) -> np.ndarray:
        """one-sided harmonics (n, H+1) of real samples x (n, Nt)."""
        X = np.fft.rfft(x, axis=-1) / Nt
        out = np.zeros((x.shape[0], H + 1), dtype=complex)
        out[:, 0] = X[:, 0]
        out[:, 1:] = 2 * X[:, 1 : H + 1]
        return out

    def psi_grid(yv: np.ndarray, vv: np.ndarray) -> np.ndarray:
        return np.broadcast_to(np.asarray(psi_f(*yv, *vv), dtype=float), (Nt, n)).T

    def Y0(A: float) -> np.ndarray:
        Y = np.zeros((n, H + 1), dtype=complex)
        Y[:, 1] = A * V
        return Y

    den = complex(L @ fp @ V)  # = Delta'(i omega) up to the normalisation of L and V (Jacobi's formula)

    def first(A: float) -> complex:
        """Omega1 from L[-i Omega1 f' A V + Psi0_1] = 0 (halved harmonic convention cancels): complex, real at A*."""
        yv, yu = synth(Y0(A))
        P1 = analyse(psi_grid(yv, w * yu))[:, 1]
        return complex(L @ P1) / (1j * A * den)

    def G(A: float) -> float:
        return first(A).imag

    grid = np.linspace(Amax / 400, Amax, 400)
    g = np.array([G(a) for a in grid])
    roots_A = []
    for a0, a1, g0, g1 in zip(grid[:-1], grid[1:], g[:-1], g[1:], strict=True):
        if g0 == 0 or g0 * g1 < 0:
            roots_A.append(a0 if g0 == 0 else brentq(G, a0, a1, xtol=1e-14 * max(1.0, a1)))
    if not roots_A:
        raise ModelError(f"no generating amplitude in (0, {Amax}]: G(A) = 0 (12.35) has no root there")
    if amplitude0 is not None:
        A = min(roots_A, key=lambda r: abs(r - float(amplitude0)))
    elif len(roots_A) > 1:
        raise ModelError(f"several generating amplitudes {roots_A}; pass amplitude0= to choose one")
    else:
        A = roots_A[0]
    hA = 1e-6 * max(1.0, A)
    slope = (G(A + hA) - G(A - hA)) / (2 * hA)
    Om1 = first(A).real
    # order 1: y1 harmonics; k = 1 particular solution with component m zero, plus B * V (B real, phase fixed)
    Y0A = Y0(A)
    y0v, y0u = synth(Y0A)
    P0 = analyse(psi_grid(y0v, w * y0u))
    R1 = P0.copy()
    R1[:, 1] += -1j * Om1 * fp @ Y0A[:, 1]
    Y1p = np.zeros((n, H + 1), dtype=complex)
    for k in [0, *range(2, H + 1)]:
        Y1p[:, k] = np.linalg.solve(_fval(F, 1j * k * w) if k else F[0], R1[:, k])
    keep = [j for j in range(n) if j != m]
    sol = np.linalg.lstsq(f1[:, keep], R1[:, 1], rcond=None)[0]
    resid = f1[:, keep] @ sol - R1[:, 1]
    if np.max(np.abs(resid), initial=0.0) > 1e-8 * max(1.0, float(np.max(np.abs(R1[:, 1])))):
        raise ModelError("the first-order periodicity condition is not met at A*")  # pragma: no cover
    Y1p[keep, 1] = sol
    if not np.all(np.isfinite(Y1p)):
        raise ModelError("f(i k omega) is singular for some harmonic k: resonance")  # pragma: no cover

    def second_residual(B: float, Om2: float) -> complex:
        Y1 = Y1p.copy()
        Y1[:, 1] += B * V
        y1v, y1u = synth(Y1)
        J = np.asarray(jac_f(*y0v, *(w * y0u)), dtype=float)  # (Nt, n, 2n)
        J = np.broadcast_to(J, (Nt, n, 2 * n))
        dv = Om1 * y0u + w * y1u
        lin = np.einsum("tij,jt->it", J[:, :, :n], y1v) + np.einsum("tij,jt->it", J[:, :, n:], dv)
        P1 = analyse(lin)[:, 1]
        R2 = -1j * Om1 * fp @ Y1[:, 1] - (1j * Om2 * fp + (1j * Om1) ** 2 / 2 * fpp) @ Y0A[:, 1] + P1
        return complex(L @ R2)

    e0 = second_residual(0.0, 0.0)
    eB = second_residual(1.0, 0.0) - e0
    eO = second_residual(0.0, 1.0) - e0
    Mx = np.array([[eB.real, eO.real], [eB.imag, eO.imag]])
    if abs(np.linalg.det(Mx)) < 1e-12 * max(1.0, float(np.max(np.abs(Mx)))) ** 2:
        raise ModelError("G'(A*) = 0 (12.40): the curve G(A) touches the axis, the second approximation does not exist")
    B, Om2 = np.linalg.solve(Mx, -np.array([e0.real, e0.imag]))
    Y1 = Y1p.copy()
    Y1[:, 1] += B * V
    return SecondApproximation(
        omega=w,
        amplitude=float(A),
        B=float(B),
        b=float(Om1 / w),
        c=float(2 * Om2 / w),
        slope=float(slope),
        reference=m,
        V=V,
        harmonics=np.array([Y0A, Y1]),
        _operator=tuple(c.real if np.all(c.imag == 0) else c for c in F),
        _jacobian=(tuple(jac), tuple(args)),
    )
