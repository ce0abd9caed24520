"""Poincaré's first approximation for ``f(D) y = mu psi(y, Dy)`` with a general polynomial operator matrix.

Bulgakov (1954), §12.2–12.6 and §12.12.  ``f(D)`` is an ``n x n`` matrix of polynomials in ``D = d/dt`` whose
determinant ``Delta(D)`` has one simple pair of roots ``+-i omega``.  With ``F(D)`` the adjugate of ``f(D)``,
``Delta1(D) = Delta(D) / (D**2 + omega**2)`` and a column ``m``, row ``l`` with ``F_lm(i omega) != 0``, the
generating solution is ``y* = A Re(V e^{iu})``, ``V_j = F_jm(i omega)`` (12.17), and with

    Q(A) = (1 / Delta1(i omega)) sum_j (F_lj(i omega) / F_lm(i omega)) (1/pi) Int(psi_j(y*) e^{-iu} du over 2 pi)

the amplitudes of periodic solutions solve ``G(A) = Im Q(A) = 0`` and the frequency is ``omega (1 + b mu)`` with
``2 A b omega**2 = -Re Q(A)`` (12.35).  The same projection gives the averaged (shortened) amplitude equation of the
active pair, ``dA/dt = mu G(A) / (2 omega)`` (12.152 with one active pair), so the cycle at ``A*`` is orbitally
stable when ``G'(A*) < 0`` and the other roots of ``Delta1`` have negative real parts; the perturbed Floquet
multiplier is ``1 + mu pi G'(A*) / omega**2 + O(mu**2)`` — the nonzero root ``eta`` of the critical block of
Bulgakov's R-matrix (12.61)–(12.64).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError

__all__ = ["OperatorCycle", "PoincareOperatorSystem", "poincare_operator_system"]


@dataclass(frozen=True)
class OperatorCycle(SymPyPrintable):
    """A periodic solution of ``f(D) y = mu psi`` to first order in ``mu``.

    Attributes
    ----------
    amplitude : float
        ``A*`` (root of ``G``); the first-harmonic amplitude of ``y_j`` is ``A* |V_j|``.
    b : float
        Frequency correction: the frequency is ``omega (1 + b mu)``.
    slope : float
        ``G'(A*)``; negative for an orbitally stable cycle.
    stable : bool
        ``slope < 0`` and the non-critical roots of ``Delta`` in the open left half-plane.
    """

    amplitude: float
    b: float
    slope: float
    stable: bool

    def _repr_latex_(self) -> str:
        """Amplitude, frequency correction, slope and the verdict."""
        from ..._printing import latex_value

        verdict = r"\text{stable}" if self.stable else r"\text{unstable}"
        return (
            rf"$A^* = {latex_value(self.amplitude)},\ b = {latex_value(self.b)},\ "
            rf"G'(A^*) = {latex_value(self.slope)}\ \left({verdict}\right)$"
        )

    def multiplier(self, mu: float, omega: float) -> float:
        """First-order nontrivial Floquet multiplier ``1 + mu pi G'(A*) / omega**2``.

        Parameters
        ----------
        mu : float
            Value of the small parameter ``mu``; a real number.
        omega : float
            The critical frequency of the system (``PoincareOperatorSystem.omega``); a nonzero number, rad/s.
        """
        return 1.0 + mu * np.pi * self.slope / omega**2


@dataclass(frozen=True)
class PoincareOperatorSystem(SymPyPrintable):
    """First-approximation data of ``f(D) y = mu psi`` (see :func:`poincare_operator_system`).

    Attributes
    ----------
    psi, variables : tuple
        The right-hand sides and the symbols ``(*y, *dy)`` they are written in.
    omega : float
        The critical frequency (``Delta(+-i omega) = 0``).
    V : ndarray (complex)
        Generating mode ``V_j = F_jm(i omega)`` (12.17).
    W : ndarray (complex)
        ``F_lj(i omega) / (F_lm(i omega) Delta1(i omega))``: the projection row.
    other_roots : ndarray (complex)
        Roots of ``Delta1``.
    n_samples : int
        Points of the periodic trapezoidal rule used for the first harmonic of ``psi``.
    """

    omega: float
    V: np.ndarray
    W: np.ndarray
    other_roots: np.ndarray
    n_samples: int
    psi: tuple[sp.Expr, ...]
    variables: tuple[sp.Symbol, ...]

    def Q(self, A: float) -> complex:
        """``Q(A)``: ``G = Im Q``, ``2 A b omega**2 = -Re Q`` (Bulgakov (1954), eq. (12.35)).

        Parameters
        ----------
        A : float
            Amplitude of the generating solution ``y* = A Re(V e^{iu})``; a finite real number.
        """
        N = self.n_samples
        u = 2 * np.pi * np.arange(N) / N
        e = np.exp(1j * u)
        y = A * (self.V[:, None] * e[None, :]).real
        dy = A * (1j * self.omega * self.V[:, None] * e[None, :]).real
        fns = _lambdified(self.psi, self.variables)
        psi = np.array([np.broadcast_to(np.asarray(f(*y, *dy), dtype=float), u.shape) for f in fns])
        first = 2.0 / N * (psi @ np.conj(e))  # (1/pi) Integral(psi e^{-iu})
        return complex(self.W @ first)

    def G(self, A: float) -> float:
        """The amplitude function ``G(A) = Im Q(A)`` (12.35).

        Parameters
        ----------
        A : float
            Amplitude of the generating solution ``y* = A Re(V e^{iu})``; a finite real number.
        """
        return self.Q(A).imag

    def b(self, A: float) -> float:
        """First frequency correction ``b(A) = -Re Q(A) / (2 A omega**2)``.

        Parameters
        ----------
        A : float
            Amplitude of the generating solution ``y* = A Re(V e^{iu})``; a nonzero finite real number.
        """
        return -self.Q(A).real / (2 * A * self.omega**2)

    def amplitude_rate(self, A: float) -> float:
        """Shortened amplitude equation per unit ``mu``: ``dA/dt = mu G(A) / (2 omega)`` (12.152, one active pair).

        Parameters
        ----------
        A : float
            Amplitude of the generating solution ``y* = A Re(V e^{iu})``; a finite real number.
        """
        return self.G(A) / (2 * self.omega)

    def cycles(self, A_max: float, *, n_grid: int = 400, tol: float = 1e-12) -> list[OperatorCycle]:
        """All roots ``A*`` of ``G`` in ``(0, A_max]`` (sign changes on a grid, then Brent), with stability.

        Parameters
        ----------
        A_max : float
            Upper end of the amplitude interval searched; a positive finite number.
        n_grid : int, optional
            Number of grid points on which sign changes of ``G`` are sought, an integer >= 2 (default 400); two
            roots closer than the grid spacing can be missed.
        tol : float, optional
            Relative tolerance of Brent's method on each root, a positive number (default 1e-12).
        """
        from scipy.optimize import brentq

        if not np.isfinite(A_max) or A_max <= 0:
            raise ParameterError(f"A_max must be positive, got {A_max}")
        grid = np.linspace(A_max / n_grid, A_max, n_grid)
        g = np.array([self.G(a) for a in grid])
        out = []
        others_ok = bool(np.all(self.other_roots.real < 0))
        for a0, a1, g0, g1 in zip(grid[:-1], grid[1:], g[:-1], g[1:], strict=True):
            if g0 == 0 or g0 * g1 < 0:
                root = a0 if g0 == 0 else brentq(self.G, a0, a1, xtol=tol * max(1.0, a1))
                h = 1e-5 * root
                slope = (self.G(root + h) - self.G(root - h)) / (2 * h)
                out.append(OperatorCycle(float(root), self.b(root), float(slope), bool(slope < 0 and others_ok)))
        return out


@validated
def poincare_operator_system(
    fD: Any, psi: Sequence[Any], y: Sequence[sp.Symbol], dy: Sequence[sp.Symbol], D: sp.Symbol, *, n_samples: int = 512
) -> PoincareOperatorSystem:
    """Set up Poincaré's first approximation for ``f(D) y = mu psi(y, Dy)`` (Bulgakov (1954), §12.2–12.6).

    Parameters
    ----------
    fD : sympy.Matrix
        ``n x n`` matrix of polynomials in ``D`` with numeric coefficients.
    psi : sequence of expressions
        Right-hand sides ``psi_j`` in the symbols ``y`` and ``dy`` (first derivatives).
    y, dy : sequences of Symbol
        Coordinates and their derivatives as they appear in ``psi``.
    D : Symbol
        The differentiation symbol in ``fD``.
    n_samples : int
        Points of the periodic trapezoidal rule for the first harmonic of ``psi`` (spectrally accurate for smooth
        ``psi``; first order for relays).

    Returns
    -------
    PoincareOperatorSystem

    Raises
    ------
    ModelError
        ``Delta(D)`` has no simple imaginary pair, several pairs, or a resonant multiple ``+-i k omega``.

    See Also
    --------
    symosc.nonlinear.periodic_solution_ndof : higher orders for ``M q'' + K q = eps f``.
    symosc.nonlinear.harmonic_linearization : the one-nonlinearity case (§12.7).

    Examples
    --------
    Van der Pol, ``(D**2 + 1) y = mu (1 - y**2) Dy``: ``A* = 2``, ``b = 0``, stable.

    >>> import sympy as sp
    >>> D, y, v = sp.symbols("D y v")
    >>> sys = poincare_operator_system(sp.Matrix([[D**2 + 1]]), [(1 - y**2) * v], [y], [v], D)
    >>> [(round(c.amplitude, 10), round(c.b, 10), c.stable) for c in sys.cycles(5.0)]
    [(2.0, 0.0, True)]
    """
    try:
        f = sp.Matrix(fD)
    except (TypeError, ValueError, sp.SympifyError) as exc:
        raise ParameterError(f"fD must be a square SymPy matrix, got {type(fD).__name__}") from exc
    n = f.shape[0]
    if f.shape != (n, n) or n == 0:
        raise ParameterError(f"fD must be square, got shape {f.shape}")
    if len(psi) != n or len(y) != n or len(dy) != n:
        raise ParameterError(f"psi, y and dy must each have {n} entries (the size of fD)")
    if f.free_symbols - {D}:
        raise ModelError(f"fD must be numeric apart from {D}; substitute {sorted(map(str, f.free_symbols - {D}))}")
    if not isinstance(n_samples, int | np.integer) or n_samples < 16:
        raise ParameterError(f"n_samples must be an integer >= 16, got {n_samples!r}")
    delta = sp.Poly(sp.expand(f.det(method="berkowitz")), D)
    coeffs = [complex(c) for c in delta.all_coeffs()]
    roots = np.roots(coeffs)
    scale = max(1.0, float(np.max(np.abs(roots), initial=1.0)))
    imag = roots[(np.abs(roots.real) < 1e-9 * scale) & (roots.imag > 1e-9 * scale)]
    if imag.size != 1:
        raise ModelError(
            f"Delta(D) must have exactly one simple pair of imaginary roots +-i omega; its roots are {roots.tolist()}"
        )
    omega = float(imag[0].imag)
    others = roots[np.abs(roots - 1j * omega) > 1e-7 * scale]
    others = others[np.abs(others + 1j * omega) > 1e-7 * scale]
    if others.size != roots.size - 2:
        raise ModelError("the imaginary pair is a multiple root of Delta(D)")
    for k in range(2, 8):
        if np.any(np.abs(others - 1j * k * omega) < 1e-9 * scale):
            raise ModelError(f"Delta(D) has the resonant root {k}i*omega; the first approximation does not apply")
    adj = f.adjugate(method="berkowitz")
    Fi = np.array(adj.subs(D, sp.I * omega).evalf(), dtype=complex)
    l, m = np.unravel_index(np.argmax(np.abs(Fi)), Fi.shape)
    if abs(Fi[l, m]) == 0:
        raise ModelError("the adjugate vanishes at i*omega (non-simple root)")  # pragma: no cover
    d1 = complex(np.polyval(np.poly(others), 1j * omega) * coeffs[0]) if others.size else complex(coeffs[0])
    V = Fi[:, m]
    W = Fi[l, :] / (Fi[l, m] * d1)
    return PoincareOperatorSystem(
        omega=omega,
        V=V,
        W=W,
        other_roots=others,
        n_samples=int(n_samples),
        psi=tuple(sp.sympify(e) for e in psi),
        variables=(*y, *dy),
    )


@lru_cache(maxsize=64)
def _lambdified(psi: tuple, variables: tuple) -> tuple:
    return tuple(sp.lambdify(list(variables), e, modules="numpy") for e in psi)
