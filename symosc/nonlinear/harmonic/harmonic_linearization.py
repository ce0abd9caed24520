"""Harmonic linearization of multi-DOF systems with one nonlinear element (Bulgakov §12.7, §12.9–12.10).

After Bulgakov (1954), eqs. (12.66)–(12.80), (12.89)–(12.124):

* §12.7: the nonlinear term ``g(y_l)`` of the m-th equation is replaced by ``h y_l`` (coefficient of harmonic
  linearization ``h``).  The characteristic determinant is then linear in ``h``, ``Delta(D) = Delta_0(D) + h F(D)``
  (12.71).  A generating periodic solution exists where ``Delta(i w) = 0`` for real ``h`` and ``w > 0`` (the real-axis
  crossing of the Nyquist plot of ``K = F/Delta_0``, ``h = -1/K(i w)``, or the penultimate Hurwitz determinant =
  0), and its amplitude ``A`` solves ``h A = J(A)`` with ``J(A) = (1/pi) Integral(g(A cos u) cos u, (u, -pi, pi))``
  (12.78, 12.80); the first frequency correction ``b`` vanishes (12.79).
* §12.10 (stability of the cycles): the cycle is orbitally stable when an increase of amplitude moves the
  linearized system into its stable side, ``Re(d lambda/dh) * dh/dA < 0`` at the crossing (``lambda`` the critical
  root, ``h(A) = J(A)/A``), and the other roots of ``Delta`` have negative real parts.  For the servo this is the
  book's rule "stable iff ``J'(C*) > z`` for ``x > 0``, the reverse for ``x < 0``".
* §12.9 servo (12.89): ``T D(UD+1) phi = v``, ``rho = -(L^2 D^2 + M D + 1) phi``, ``sigma = rho - n v``,
  ``D(VD+1) v = g(sigma)``; eliminating ``rho, v``:
  ``T D^2 (UD+1)(VD+1) phi = g(sigma)``, ``sigma = -(x D^2 + y D + 1) phi`` with ``x = L^2 + T U n``,
  ``y = M + T n`` (12.93).  With ``g(sigma) -> z sigma`` the determinant is
  ``TUV D^4 + T(U+V) D^3 + (x z + T) D^2 + y z D + z`` (12.94–12.95), so ``z`` is the linearization coefficient
  (from (12.89) with ``g = sigma/W - psi`` it is ``z = 1/W``; ``z = T/W`` would be a misreading of the print).

* §12.8 two nonlinearities: ``Delta`` is bilinear in ``h1, h2``; :func:`neimark_curve` gives the curve C1
  ``(h1(w), h2(w))`` (two branches) by the book's device (``h = h1 h2`` as a third unknown, then a quadratic), and
  :func:`two_nonlinearity_cycles` intersects it with ``h_i = J_i(A_i)/A_i`` and ``A_2 = k(w) A_1``,
  ``k = |R(i w)|`` for a user-given transfer ``sigma_2 = R(D) sigma_1`` (the curves C2, C3 of 12.86–12.87), by
  solving the two real equations directly instead of graphically.  The book gives no stability rule here and none is
  claimed.

Not reconstructed: figures 207–209 (no numbers are legible); the servo's Table 13 regions are given as a classifier
:func:`servo_region`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._deprecation import module_getattr as _module_getattr
from ..._plotting import plot_method
from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_positive, validated
from ...errors import ModelError, ParameterError
from ...numeric import compile as _compile
from .. import _checks
from ..averaging.shortened import describing_function

__all__ = [
    "HarmonicCycle",
    "HarmonicLinearization",
    "LinearizationBoundary",
    "TwoNonlinearityCycle",
    "harmonic_linearization",
    "linearization_boundary",
    "neimark_curve",
    "self_oscillations",
    "servo_characteristic",
    "servo_equations",
    "servo_region",
    "two_nonlinearity_cycles",
]

D_ = sp.Symbol("D")
W2 = sp.Symbol("omega2", positive=True)


@validated
def harmonic_linearization(g: Any, sigma: sp.Symbol, amplitude: sp.Symbol | None = None) -> sp.Expr:
    """Coefficient of harmonic linearization ``h(A) = J(A)/A`` of an odd nonlinearity ``g(sigma)`` (12.78, 12.80).

    Parameters
    ----------
    g : Expr
        The nonlinear characteristic ``g(sigma)``, odd in ``sigma`` (condition (12.67)); a polynomial, or built with
        ``sign``/``Abs`` (relays).
    sigma : Symbol
        The input of the nonlinear element, the variable of ``g``.
    amplitude : Symbol, optional
        Symbol of the amplitude ``A`` in the result (default: a positive symbol ``A``).

    Returns
    -------
    Expr
        ``h(A) = J(A)/A`` with ``J(A) = (1/pi) Integral(g(A cos u) cos u, (u, -pi, pi))``.

    See Also
    --------
    describing_function
    self_oscillations
    linearization_boundary

    Examples
    --------
    >>> import sympy as sp
    >>> s = sp.Symbol("sigma")
    >>> A = sp.Symbol("A", positive=True)
    >>> harmonic_linearization(sp.sign(s), s, A)  # ideal relay: 4/(pi A)
    4/(pi*A)
    >>> harmonic_linearization(4 * s**3 - s**5, s, A)
    -5*A**4/8 + 3*A**2
    """
    A = amplitude if amplitude is not None else sp.Symbol("A", positive=True)
    g = sp.sympify(g)
    if g.subs(sigma, -sigma).simplify() != (-g).simplify():
        raise ModelError(f"g = {g} is not odd in {sigma}: condition (12.67) fails, add the bias to the linear part")
    J = describing_function(g, sigma, amplitude=A)
    return sp.expand(sp.simplify(J / A))


@dataclass(frozen=True)
class LinearizationBoundary(SymPyPrintable):
    """A value ``h`` of the linearization coefficient at which ``Delta(D)`` has the roots ``±i omega`` (§12.7).

    Attributes
    ----------
    h : Expr or float
        The boundary value ``h*`` of the linearization coefficient (symbolic when the determinant has parameters).
    omega2 : Expr or float
        The squared frequency ``omega**2`` of the imaginary roots at ``h*``.
    """

    h: Any
    omega2: Any

    @property
    def omega(self) -> Any:
        return sp.sqrt(self.omega2) if isinstance(self.omega2, sp.Basic) else float(np.sqrt(self.omega2))

    def __repr__(self) -> str:
        return f"LinearizationBoundary(h = {self.h}, omega**2 = {self.omega2})"


@validated
def linearization_boundary(delta: Any, h: sp.Symbol, D: sp.Symbol = D_) -> tuple[LinearizationBoundary, ...]:
    """Solve ``Delta(i w; h) = 0`` for real ``h`` and ``w**2`` when ``Delta`` is linear in ``h`` (12.70–12.71).

    Writing ``Delta(D) = E(D**2) + D O(D**2)``, both ``E(-w**2) = 0`` and ``O(-w**2) = 0`` are linear in ``h``;
    eliminating ``h`` leaves a polynomial in ``w**2``.  Symbolic parameters are kept (the result is the book's
    "periodic boundary"); with numbers only the roots with ``w**2 > 0`` and real ``h`` are returned.

    Parameters
    ----------
    delta : Expr
        The characteristic determinant ``Delta(D) = Delta_0(D) + h F(D)``, a polynomial in ``D`` of degree exactly 1
        in ``h`` (one nonlinear element, (12.71)); other symbols are kept as parameters.
    h : Symbol
        The linearization coefficient in ``delta``.
    D : Symbol, optional
        The differentiation symbol in ``delta`` (default ``D``).

    Returns
    -------
    tuple of LinearizationBoundary

    Examples
    --------
    Servo of §12.9 with ``V = 0`` (12.96–12.103):

    >>> import sympy as sp
    >>> T, U, x, y, z = sp.symbols("T U x y z", positive=True)
    >>> (b,) = linearization_boundary(servo_characteristic(T, U, 0, x, y, z), z)
    >>> sp.simplify(b.h - T * (U - y) / (x * y)), sp.simplify(b.omega2 - (U - y) / (U * x))
    (0, 0)
    """
    delta = sp.expand(sp.sympify(delta))
    if sp.degree(delta, h) != 1:
        raise ModelError(
            f"Delta must be linear in {h} (one nonlinear element, 12.71); got degree {sp.degree(delta, h)}"
        )
    P = sp.Poly(delta, D)
    E = sp.Integer(0)
    O = sp.Integer(0)
    for (k,), c in P.terms():
        # D**k at D = i w: (i w)**k = (-w2)**(k//2) * (i w if k odd)
        if k % 2 == 0:
            E += c * (-W2) ** (k // 2)
        else:
            O += c * (-W2) ** (k // 2)
    E, O = sp.expand(E), sp.expand(O)
    e1, e0 = E.coeff(h, 1), E.coeff(h, 0)
    o1, o0 = O.coeff(h, 1), O.coeff(h, 0)
    res = sp.factor(sp.expand(e0 * o1 - e1 * o0))
    numeric = not (delta.free_symbols - {h, D})
    out = []
    sols = sp.solve(res, W2) if not numeric else _real_positive_roots(res)
    for w2 in sols:
        den = e1.subs(W2, w2)
        hv = -e0.subs(W2, w2) / den if den != 0 else -o0.subs(W2, w2) / o1.subs(W2, w2)
        hv = sp.factor(sp.simplify(hv)) if not numeric else complex(sp.N(hv))
        if numeric:
            if abs(hv.imag) > 1e-9 * max(1.0, abs(hv)):
                continue
            out.append(LinearizationBoundary(float(hv.real), float(w2)))
        else:
            out.append(LinearizationBoundary(hv, sp.factor(w2)))
    return tuple(out)


def _real_positive_roots(poly: sp.Expr) -> list[float]:
    if poly == 0:
        raise ModelError("Delta(i w) vanishes for every h: the family is degenerate")
    c = [complex(v) for v in sp.Poly(poly, W2).all_coeffs()]
    roots = np.roots(c) if len(c) > 1 else []
    return sorted(float(r.real) for r in roots if abs(r.imag) < 1e-9 * max(1, abs(r)) and r.real > 0)


@dataclass(frozen=True)
class HarmonicCycle(SymPyPrintable):
    """A generating periodic motion: ``sigma ≈ amplitude * cos(omega t)`` at the nonlinear element's input.

    Attributes
    ----------
    amplitude : float
        Amplitude ``A*`` of ``sigma``: the root of ``h(A) = h*``.
    omega : float
        Frequency of the cycle (rad/s), that of the imaginary roots at ``h*``.
    h : float
        The boundary value ``h*`` of the linearization coefficient.
    dh_dA : float
        Slope ``h'(A*)`` of the linearization coefficient at the cycle.
    root_sensitivity : complex
        ``d lambda/dh`` of the critical root ``lambda = i omega`` at ``h*``.
    other_roots_stable : bool
        Whether the other roots of ``Delta`` at ``h*`` have negative real parts.
    stable : bool
        Orbital stability by §12.10: ``Re(d lambda/dh) * h'(A*) < 0`` and the other roots stable.
    """

    amplitude: float
    omega: float
    h: float
    dh_dA: float
    root_sensitivity: complex
    other_roots_stable: bool
    stable: bool

    def __repr__(self) -> str:
        word = "stable" if self.stable else "unstable"
        return f"HarmonicCycle(A = {self.amplitude:.8g}, omega = {self.omega:.8g}, h = {self.h:.8g}, {word})"


@dataclass(frozen=True)
class HarmonicLinearization(SymPyPrintable):
    """All generating cycles of ``Delta_0(D) + h F(D)`` with ``h = J(A)/A``, and the pieces used to find them.

    Attributes
    ----------
    delta : Expr
        The characteristic determinant, linear in the linearization coefficient.
    h_symbol : Symbol
        The linearization coefficient in ``delta``.
    gain : Expr
        The coefficient of harmonic linearization ``h(A) = J(A)/A`` of the nonlinearity.
    amplitude_symbol : Symbol
        The amplitude symbol ``A`` in ``gain``.
    boundaries : tuple of LinearizationBoundary
        The values ``h*`` at which ``Delta`` has imaginary roots.
    cycles : tuple of HarmonicCycle
        The generating cycles, ascending in frequency, then amplitude.
    """

    delta: sp.Expr
    h_symbol: sp.Symbol
    gain: sp.Expr
    amplitude_symbol: sp.Symbol
    boundaries: tuple
    cycles: tuple

    def __repr__(self) -> str:
        cyc = "\n  ".join(repr(c) for c in self.cycles) or "(none)"
        return f"HarmonicLinearization(h(A) = {self.gain}, boundaries = {self.boundaries},\n  {cyc})"

    def _repr_latex_(self) -> str:
        return f"$h(A) = {sp.latex(self.gain)},\\quad \\Delta(D) = {sp.latex(self.delta)}$"

    @plot_method
    def plot(self, *, ax: Any = None, amax: float | None = None) -> Any:
        """``h(A)`` with the boundary values ``h*`` and the cycles marked.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        amax : float, optional
            Largest amplitude drawn, a positive number (default: 1.5 times the largest cycle amplitude, at least
            1.5).
        """
        from ..._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        amax = amax or 1.5 * max([c.amplitude for c in self.cycles] + [1.0])
        fn = _compile(self.gain, [self.amplitude_symbol], check=False)
        A = np.linspace(amax * 1e-3, amax, 400)
        ax.plot(A, np.broadcast_to(np.asarray(fn.raw(A), dtype=float), A.shape), label="h(A) = J(A)/A")
        for b in self.boundaries:
            ax.axhline(float(b.h), ls="--", color="gray")
        for c in self.cycles:
            ax.plot([c.amplitude], [c.h], "o" if c.stable else "x", color="k")
        ax.set_xlabel("A")
        ax.set_ylabel("h")
        ax.legend()
        return ax


@validated
def self_oscillations(
    delta: Any,
    h: sp.Symbol,
    g: Any,
    sigma: sp.Symbol,
    *,
    D: sp.Symbol = D_,
    amplitude_max: float = 100.0,
    samples: int = 2000,
) -> HarmonicLinearization:
    """Generating cycles of a linear system closed by one odd nonlinearity (§12.7, stability §12.10).

    Parameters
    ----------
    delta : Expr
        Characteristic determinant with ``g(sigma)`` replaced by ``h*sigma``, numeric apart from ``h`` and ``D``.
    h, sigma : Symbol
        Linearization coefficient and the nonlinear element's input.
    g : Expr
        The odd nonlinearity ``g(sigma)`` (polynomial, ``sign``, ``Abs``).
    D : Symbol, optional
        The differentiation symbol in ``delta`` (default ``D``).
    amplitude_max, samples : float, int
        Amplitudes ``0 < A <= amplitude_max`` are scanned on a geometric grid for sign changes of ``h(A) - h*``.

    Examples
    --------
    >>> import sympy as sp
    >>> s, z = sp.symbols("sigma z")
    >>> delta = servo_characteristic(1, 1, 0, 1, sp.Rational(1, 2), z)
    >>> res = self_oscillations(delta, z, 4 * s**3 - s**5, s)
    >>> [(round(c.amplitude, 10), round(c.omega**2, 10), c.stable) for c in res.cycles]
    [(0.6003267398, 0.5, True), (2.1070376849, 0.5, False)]
    """
    A = sp.Symbol("A", positive=True)
    gain = harmonic_linearization(g, sigma, A)
    bounds = linearization_boundary(delta, h, D)
    hf = _compile(gain, [A], check=False)
    dhf = _compile(sp.diff(gain, A), [A], check=False)
    grid = np.geomspace(amplitude_max * 1e-6, amplitude_max, samples)
    hv = np.broadcast_to(np.asarray(hf.raw(grid), dtype=float), grid.shape)
    dd = sp.diff(delta, D)
    cycles = []
    for b in bounds:
        hs = float(b.h)
        w = float(np.sqrt(b.omega2))
        lam = 1j * w
        dlam = complex(-sp.diff(delta, h).subs(D, lam) / dd.subs({h: hs, D: lam}))
        coeffs = [complex(c) for c in sp.Poly(delta.subs(h, hs), D).all_coeffs()]
        roots = np.roots(coeffs)
        others = [r for r in roots if abs(r - lam) > 1e-6 * max(1, w) and abs(r + lam) > 1e-6 * max(1, w)]
        others_ok = all(r.real < 0 for r in others)
        f = hv - hs
        from scipy.optimize import brentq

        for i in np.nonzero(np.sign(f[:-1]) * np.sign(f[1:]) < 0)[0]:
            Ac = brentq(lambda x, hs=hs: float(hf.raw(x)) - hs, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-14)
            slope = float(dhf.raw(Ac))
            stable = bool(others_ok and dlam.real * slope < 0)
            cycles.append(HarmonicCycle(float(Ac), w, hs, slope, dlam, others_ok, stable))
    return HarmonicLinearization(
        delta=sp.sympify(delta),
        h_symbol=h,
        gain=gain,
        amplitude_symbol=A,
        boundaries=bounds,
        cycles=tuple(sorted(cycles, key=lambda c: (c.omega, c.amplitude))),
    )


@validated
def servo_characteristic(T: Any, U: Any, V: Any, x: Any, y: Any, z: Any, D: sp.Symbol = D_) -> sp.Expr:
    """Characteristic polynomial (12.94–12.95) of the servo of §12.9 with ``g(sigma) -> z sigma``.

    ``TUV D^4 + T(U+V) D^3 + (x z + T) D^2 + y z D + z`` with ``x = L^2 + TUn``, ``y = M + Tn``; derived from
    (12.89) as ``T D^2 (UD+1)(VD+1) + z (x D^2 + y D + 1)``.

    Parameters
    ----------
    T : Expr or float
        Time constant ``T`` of (12.89); a positive number or symbol.
    U : Expr or float
        Time constant ``U`` of (12.89); a positive number or symbol.
    V : Expr or float
        Time constant ``V`` of (12.89); a non-negative number or symbol (0 gives the third-order case).
    x : Expr or float
        Feedback parameter ``x = L**2 + T U n`` (12.93); a real number or symbol, of either sign.
    y : Expr or float
        Feedback parameter ``y = M + T n`` (12.93); a real number or symbol.
    z : Expr or float
        The linearization coefficient replacing ``g(sigma)`` by ``z sigma``; usually a symbol.
    D : Symbol, optional
        The differentiation symbol of the result (default ``D``).

    Returns
    -------
    Expr
        The characteristic polynomial in ``D``.

    Examples
    --------
    >>> import sympy as sp
    >>> T, U, V, x, y, z = sp.symbols("T U V x y z")
    >>> sp.Poly(servo_characteristic(T, U, V, x, y, z), sp.Symbol("D")).all_coeffs()
    [T*U*V, T*U + T*V, T + x*z, y*z, z]
    """
    T, U, V, x, y, z = (_checks.expression(n, v, real=True) for n, v in zip("TUVxyz", (T, U, V, x, y, z), strict=True))
    D = _checks.symbol("D", D)
    return sp.expand(T * D**2 * (U * D + 1) * (V * D + 1) + z * (x * D**2 + y * D + 1))


@validated
def servo_equations(
    T: float, U: float, V: float, L: float, M: float, n: float, g: Any, sigma: sp.Symbol
) -> tuple[sp.Matrix, tuple, sp.Expr]:
    """First-order form of the servo (12.89) for direct integration.

    Returns ``(rhs, state, sigma_expr)``: ``state = (phi, phi', phi'' [, phi'''])`` (three states when ``V = 0``),
    ``rhs`` its derivative and ``sigma_expr = -(x phi'' + y phi' + phi)``.

    Parameters
    ----------
    T, U, V : float
        Time constants of (12.89): ``T > 0``, ``U > 0``, ``V >= 0``.
    L, M, n : float
        Feedback parameters: ``x = L**2 + T U n`` and ``y = M + T n``.
    g : Expr
        The nonlinear characteristic, a SymPy expression in ``sigma``.
    sigma : Symbol
        The characteristic's argument.
    """
    T, U, V, L, M, n = (check_finite(k, v) for k, v in zip("TUVLMn", (T, U, V, L, M, n), strict=True))
    g, sigma = _checks.expression("g", g), _checks.symbol("sigma", sigma)
    if T <= 0 or U <= 0 or V < 0:
        raise ParameterError("the servo needs T > 0, U > 0 and V >= 0 (time constants)")
    x = L**2 + T * U * n
    y = M + T * n
    p = sp.symbols("phi0:4")
    s_expr = -(x * p[2] + y * p[1] + p[0])
    gs = sp.sympify(g).subs(sigma, s_expr)
    if V == 0:
        # T U phi''' + T phi'' = g
        return sp.Matrix([p[1], p[2], (gs - T * p[2]) / (T * U)]), p[:3], s_expr
    # T U V phi'''' + T (U+V) phi''' + T phi'' = g
    return sp.Matrix([p[1], p[2], p[3], (gs - T * (U + V) * p[3] - T * p[2]) / (T * U * V)]), p, s_expr


@validated
def servo_region(x: float, y: float, T: float, U: float, z0: float) -> int:
    """Region of Table 13 (§12.10, V = 0) in the ``(x, y)`` plane for a characteristic with maximal gain ``z0``.

    1: robust stability; 2: small-amplitude self-oscillation C1; 3: large-amplitude self-oscillation C2;
    4: instability.  ``z0`` is the slope of the tangent from the origin to ``J(C)`` (the maximum of ``J(C)/C``).

    Parameters
    ----------
    x : float
        Feedback parameter ``x = L**2 + T U n`` (12.93); a finite real number.
    y : float
        Feedback parameter ``y = M + T n`` (12.93); a finite real number.
    T : float
        Time constant ``T`` of (12.89); a positive number.
    U : float
        Time constant ``U`` of (12.89); a positive number.
    z0 : float
        Maximal gain of the characteristic: the largest value of ``J(C)/C``; a positive number.

    Returns
    -------
    int
        The region 1, 2, 3 or 4 of Table 13.

    Examples
    --------
    >>> servo_region(1.0, 0.5, 1.0, 1.0, 3.6), servo_region(1.0, 2.0, 1.0, 1.0, 3.6)
    (2, 1)
    """
    x, y = check_finite("x", x), check_finite("y", y)
    T, U, z0 = check_positive("T", T), check_positive("U", U), check_positive("z0", z0)
    if (x < 0 and (x * z0 + T) * y > T * U) or (x > 0 and y > U):
        return 1
    if (x * z0 + T) * y > T * U and y < U:
        return 2
    if (x * z0 + T) * y < T * U and y > U:
        return 3
    return 4


@validated
def neimark_curve(delta: Any, h1: sp.Symbol, h2: sp.Symbol, omega: Any, D: sp.Symbol = D_) -> np.ndarray:
    """Curve C1 of §12.8: the pairs ``(h1, h2)`` for which ``Delta(i w) = 0``, ``Delta`` bilinear in ``h1, h2``.

    Returns an array of shape ``(len(omega), 2, 2)``: ``[k, branch] = (h1, h2)``, NaN where the branch is complex.

    Parameters
    ----------
    delta : Expr
        The characteristic determinant, a polynomial in ``D`` of degree at most 1 in each of ``h1`` and ``h2``
        (12.81)–(12.83), numeric apart from ``h1``, ``h2`` and ``D``.
    h1 : Symbol
        Linearization coefficient of the first nonlinear element in ``delta``.
    h2 : Symbol
        Linearization coefficient of the second nonlinear element in ``delta``.
    omega : float or array_like of float
        Frequencies ``w`` (rad/s) at which to compute the curve; real numbers.
    D : Symbol, optional
        The differentiation symbol in ``delta`` (default ``D``).

    Examples
    --------
    >>> import sympy as sp
    >>> h1, h2, D = sp.symbols("h1 h2 D")
    >>> neimark_curve(D**3 + D**2 + h2 * D + h1, h1, h2, [1.0, 2.0])[:, 0]   # h2 = w^2, h1 = w^2
    array([[1., 1.],
           [4., 4.]])
    """
    delta = sp.expand(sp.sympify(delta))
    if sp.Poly(delta, h1, h2).degree(h1) > 1 or sp.Poly(delta, h1, h2).degree(h2) > 1:
        raise ModelError("Delta must be of degree <= 1 in each of h1 and h2 (12.81-12.83)")
    W = sp.Symbol("w", real=True)
    P = sp.Poly(sp.expand(delta.subs(D, sp.I * W)), h1, h2)
    cs = [sp.expand(P.coeff_monomial(m)) for m in (1, h1, h2, h1 * h2)]
    coef = [[sp.re(c) for c in cs], [sp.im(c) for c in cs]]
    fn = _compile([c for row in coef for c in row], [W], check=False)
    om = np.atleast_1d(np.asarray(omega, dtype=float))
    out = np.full((om.size, 2, 2), np.nan)
    for k, wv in enumerate(om):
        (a0, a1, a2, a3), (b0, b1, b2, b3) = np.asarray(fn.raw(wv), dtype=float).reshape(2, 4)
        Mx = np.array([[a1, a2], [b1, b2]])
        if abs(np.linalg.det(Mx)) < 1e-300:
            continue
        Mi = np.linalg.inv(Mx)
        # (h1, h2) = u + p v with p = h1*h2
        u = Mi @ np.array([-a0, -b0])
        v = Mi @ np.array([-a3, -b3])
        roots = np.roots([v[0] * v[1], u[0] * v[1] + u[1] * v[0] - 1, u[0] * u[1]])
        roots = sorted(r.real for r in np.atleast_1d(roots) if abs(r.imag) < 1e-12 * max(1, abs(r)))
        for j, p in enumerate(roots[:2]):
            out[k, j] = u + p * v
    return out


@dataclass(frozen=True)
class TwoNonlinearityCycle(SymPyPrintable):
    """Generating cycle with two nonlinear elements: input amplitudes ``A1``, ``A2 = k(w) A1``, frequency ``w``.

    Attributes
    ----------
    amplitude1 : float
        Amplitude ``A1`` at the input of the first nonlinear element.
    amplitude2 : float
        Amplitude ``A2 = |R(i w)| A1`` at the input of the second.
    omega : float
        Frequency ``w`` of the cycle (rad/s).
    h1 : float
        Linearization coefficient ``h1(A1)`` of the first element at the cycle.
    h2 : float
        Linearization coefficient ``h2(A2)`` of the second element at the cycle.
    """

    amplitude1: float
    amplitude2: float
    omega: float
    h1: float
    h2: float

    def __repr__(self) -> str:
        return (
            f"TwoNonlinearityCycle(A1 = {self.amplitude1:.8g}, A2 = {self.amplitude2:.8g}, omega = {self.omega:.8g}, "
            f"h1 = {self.h1:.8g}, h2 = {self.h2:.8g})"
        )


@validated
def two_nonlinearity_cycles(
    delta: Any,
    h1: sp.Symbol,
    h2: sp.Symbol,
    g1: Any,
    sigma1: sp.Symbol,
    g2: Any,
    sigma2: sp.Symbol,
    ratio: Any,
    *,
    D: sp.Symbol = D_,
    omega_max: float = 10.0,
    amplitude_max: float = 10.0,
    starts: int = 12,
) -> tuple[TwoNonlinearityCycle, ...]:
    """Generating cycles of a system with two odd nonlinearities (§12.8, 12.81–12.88).

    Solves ``Delta(i w; h1(A1), h2(|R(i w)| A1)) = 0`` for ``w > 0``, ``A1 > 0`` with ``h_i(A) = J_i(A)/A`` and
    ``sigma_2 = R(D) sigma_1`` (``ratio = R(D)``, a rational function of ``D``), from a grid of starting points.

    Parameters
    ----------
    delta : Expr
        The characteristic determinant, a polynomial in ``D`` bilinear in ``h1`` and ``h2``, numeric apart from
        ``h1``, ``h2`` and ``D``.
    h1 : Symbol
        Linearization coefficient of the first nonlinear element in ``delta``.
    h2 : Symbol
        Linearization coefficient of the second nonlinear element in ``delta``.
    g1 : Expr
        The first nonlinearity ``g1(sigma1)``, odd in ``sigma1``.
    sigma1 : Symbol
        Input of the first nonlinear element, the variable of ``g1``.
    g2 : Expr
        The second nonlinearity ``g2(sigma2)``, odd in ``sigma2``.
    sigma2 : Symbol
        Input of the second nonlinear element, the variable of ``g2``.
    ratio : Expr
        The transfer ``R(D)`` with ``sigma2 = R(D) sigma1``, a rational function of ``D`` with numeric coefficients.
    D : Symbol, optional
        The differentiation symbol in ``delta`` and ``ratio`` (default ``D``).
    omega_max : float, optional
        Largest starting frequency of the grid, a positive number (default 10); starts lie in
        ``(0, omega_max]``.
    amplitude_max : float, optional
        Largest starting amplitude ``A1`` of the grid, a positive number (default 10).
    starts : int, optional
        Number of starting values per axis of the grid, a positive integer (default 12, so 144 starts).

    Returns
    -------
    tuple of TwoNonlinearityCycle
        The distinct cycles found, ascending in frequency, then amplitude.

    Examples
    --------
    >>> import sympy as sp
    >>> h1, h2, D, x, v = sp.symbols("h1 h2 D x v")
    >>> cyc = two_nonlinearity_cycles(D**3 + D**2 + h2 * D + h1, h1, h2, x + x**3 / 10, x, -v + v**3, v, D)
    >>> [(round(c.amplitude1, 8), round(c.omega, 8)) for c in cyc]
    [(1.56813638, 1.0883147)]
    """
    from scipy.optimize import fsolve

    A = sp.Symbol("A", positive=True)
    W = sp.Symbol("w", positive=True)
    G1 = harmonic_linearization(g1, sigma1, A)
    G2 = harmonic_linearization(g2, sigma2, A)
    kw = sp.Abs(sp.sympify(ratio).subs(D, sp.I * W))
    val = sp.expand(sp.sympify(delta).subs({h1: G1, h2: G2.subs(A, kw * A)}).subs(D, sp.I * W))
    fn = _compile([sp.re(val), sp.im(val)], [W, A], check=False)
    h1f = _compile(G1, [A], check=False)
    h2f = _compile(G2, [A], check=False)
    kf = _compile(kw, [W], check=False)
    found: list[TwoNonlinearityCycle] = []
    for w0 in np.linspace(omega_max / starts, omega_max, starts):
        for a0 in np.linspace(amplitude_max / starts, amplitude_max, starts):
            sol, _info, ier, _msg = fsolve(
                lambda p: np.asarray(fn.raw(*p), dtype=float).ravel(), [w0, a0], full_output=True, xtol=1e-13
            )
            wv, av = float(sol[0]), float(sol[1])
            if ier != 1 or wv <= 0 or av <= 0 or np.max(np.abs(fn.raw(wv, av))) > 1e-9:
                continue
            if any(abs(c.omega - wv) < 1e-7 and abs(c.amplitude1 - av) < 1e-7 for c in found):
                continue
            a2 = float(kf.raw(wv)) * av
            found.append(TwoNonlinearityCycle(av, a2, wv, float(h1f.raw(av)), float(h2f.raw(a2))))
    return tuple(sorted(found, key=lambda c: (c.omega, c.amplitude1)))


_DEPRECATED_NAMES = {
    "harmonic_linearisation": "harmonic_linearization",
    "HarmonicLinearisation": "HarmonicLinearization",
    "LinearisationBoundary": "LinearizationBoundary",
    "linearisation_boundary": "linearization_boundary",
}
__getattr__ = _module_getattr(__name__, _DEPRECATED_NAMES, globals())
