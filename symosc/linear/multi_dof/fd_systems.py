"""Systems ``f(D) y = e(D) x`` with constant coefficients (Bulgakov (1954), §8.2–8.12, 8.28, 8.54).

* :func:`compatibility` — rank and the compatibility operator from modified minors (§8.2–8.4).
* :func:`fundamental_solutions` — characteristic determinant, degree (the order of the system) and modal columns
  ``∂^k/∂λ^k [F(λ) e^{λt}]`` (``F = adj f``), polynomial in ``t`` for multiple roots, in real form for complex
  pairs (§8.5, 8.10–8.12).
* :func:`impulse_response` — direct term ``S(D)`` and kernel ``N(t)`` of the forced solution (§8.50–8.51).
* :func:`frequency_response` — ``X(iω) = f(iω)⁻¹ e(iω)`` with gain, phase, decibels and nepers (§8.28–8.30).
* :func:`worst_case_gain` — accumulation of disturbances ``A = |S| + ∫|N| dt`` (§8.54).
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations, pairwise
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import check_finite_array, validated
from ...errors import ConvergenceError, ModelError, ParameterError

__all__ = [
    "Compatibility",
    "FrequencyResponse",
    "FundamentalSolutions",
    "ImpulseResponse",
    "compatibility",
    "frequency_response",
    "fundamental_solutions",
    "impulse_response",
    "mean_power",
    "resonant_particular",
    "worst_case_gain",
]

NEPERS_PER_DECIBEL = float(np.log(10) / 20)


def _matrix(f: Any, var: sp.Symbol, what: str = "f") -> sp.Matrix:
    if not isinstance(var, sp.Symbol):
        raise ParameterError(f"var must be a SymPy Symbol (the operator D), got {var!r}")
    M = sp.Matrix(f)
    for e in M:
        if not sp.sympify(e).is_polynomial(var):
            raise ParameterError(f"{what} must be polynomial in {var}, got entry {e}")
    return M


@dataclass(frozen=True)
class Compatibility(SymPyPrintable):
    """Result of :func:`compatibility`.

    Attributes
    ----------
    rank : int
        Rank of ``f(D)`` over rational functions of ``D``.
    operator : sympy.Expr
        ``c(D)`` (monic): the input must satisfy ``c(D) x = 0`` (1 when any input is admissible).
    modified_minors : tuple
        The ``(r+1)``-minors of ``[f | e]`` divided by the gcd of the ``r``-minors of ``f`` in the same columns.
    """

    rank: int
    operator: sp.Expr
    modified_minors: tuple

    @property
    def always_compatible(self) -> bool:
        return self.operator == 1

    def __repr__(self) -> str:
        return f"Compatibility(rank={self.rank}, operator={self.operator})"


@validated
def compatibility(f: Any, e: Any, var: sp.Symbol) -> Compatibility:
    """Compatibility of ``f(D) y = e(D) x`` by modified minors (Bulgakov (1954), §8.2–8.4).

    For ``rank f = r``, each ``(r+1)``-minor of the augmented matrix ``[f | e]`` that uses the column ``e`` is
    divided by the gcd of the ``r``-minors of ``f`` in its columns; the gcd ``c(D)`` of these modified minors gives the
    condition ``c(D) x = 0``.  Using the unmodified minors would add spurious factors (the pitfall of §8.4).

    Parameters
    ----------
    f : matrix-like
        The operator ``f(D)``: an ``n x m`` matrix (nested sequence or sympy.Matrix) of polynomials in ``var``.
    e : matrix-like
        The input operator ``e(D)``: a single column of polynomials in ``var`` with as many rows as ``f``.
    var : sympy.Symbol
        The operator symbol ``D``; must be a SymPy Symbol.

    Returns
    -------
    Compatibility

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import compatibility
    >>> D = sp.Symbol("D")
    >>> f = [[D**2 - 2*D - 1, D - 1, D**2 - D - 4], [D - 2, 1, D - 2], [-1, -1, D - 4]]     # §8.4
    >>> compatibility(f, [2*D, 1, -1], D).operator
    D + 1

    See Also
    --------
    fundamental_solutions
    """
    f = _matrix(f, var)
    e = _matrix(e, var, "e")
    if e.cols != 1 or e.rows != f.rows:
        raise ParameterError(f"e must be a column of {f.rows} polynomials, got shape {e.shape}")
    r = f.rank(simplify=True)
    if r == f.rows:
        return Compatibility(r, sp.Integer(1), ())
    aug = f.row_join(e)
    mods = []
    for cols in combinations(range(f.cols), r):
        g = sp.Integer(0)
        for rows in combinations(range(f.rows), r):
            g = sp.gcd(g, sp.expand(f.extract(list(rows), list(cols)).det()))
        if g == 0:
            continue
        for rows in combinations(range(f.rows), r + 1):
            minor = sp.expand(aug.extract(list(rows), [*cols, f.cols]).det())
            if minor != 0:
                mods.append(sp.factor(sp.cancel(minor / g)))
    if not mods:
        return Compatibility(r, sp.Integer(1), ())
    c = sp.Integer(0)
    for m in mods:
        c = sp.gcd(c, sp.numer(sp.together(m)))
    c = sp.Poly(c, var).monic().as_expr() if sp.degree(c, var) > 0 else sp.Integer(1)
    return Compatibility(r, sp.factor(c), tuple(mods))


@dataclass(frozen=True)
class FundamentalSolutions(SymPyPrintable):
    """Result of :func:`fundamental_solutions`.

    Attributes
    ----------
    determinant : sympy.Expr
        ``Δ(D) = det f(D)`` (factored).
    degree : int
        ``deg Δ``: the number of arbitrary constants (the order of the system).
    roots : tuple of (root, multiplicity)
        The distinct roots of ``Δ`` (exact) with their multiplicities, by increasing real part.
    matrix : sympy.Matrix
        ``ϑ(t)``: its columns are independent solutions of ``f(D) y = 0``; the general solution is ``ϑ c``.
    """

    determinant: sp.Expr
    degree: int
    roots: tuple
    matrix: sp.Matrix

    def __repr__(self) -> str:
        return f"FundamentalSolutions(determinant={self.determinant}, degree={self.degree})"

    def _latex(self, printer) -> str:
        return printer._print(self.matrix)

    def _repr_latex_(self) -> str:
        return f"$${sp.latex(self)}$$"


@validated
def fundamental_solutions(
    f: Any, var: sp.Symbol, t: sp.Symbol | None = None, *, real: bool = True
) -> FundamentalSolutions:
    """Modal columns and the fundamental matrix of ``f(D) y = 0`` (Bulgakov (1954), §8.5, 8.10–8.12).

    For a root ``λ`` of multiplicity ``q`` the solutions are the columns of ``∂^k/∂λ^k [F(λ) e^{λt}]``,
    ``k < q``, ``F = adj f``; independent ones are kept (polynomial modal columns such as ``[t + 4, -t]`` of
    Bromwich's example).  With ``real=True`` a complex pair contributes the real and imaginary parts (the real modal
    matrix and the Cayley form of §8.12).

    Parameters
    ----------
    f : matrix-like
        Square ``n x n`` matrix (nested sequence or sympy.Matrix) of polynomials in ``var``: the operator ``f(D)``.
    var : sympy.Symbol
        The operator symbol ``D``; must be a SymPy Symbol.
    t : sympy.Symbol, optional
        Time symbol of the result (default ``Symbol("t")``).
    real : bool, optional
        Give each complex pair as the real and imaginary parts of its columns (default True); False keeps the
        complex exponentials.

    Returns
    -------
    FundamentalSolutions

    Raises
    ------
    ModelError
        When ``det f ≡ 0`` (use :func:`compatibility`) or the roots cannot be found exactly.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import fundamental_solutions
    >>> D, t = sp.symbols("D t")
    >>> fs = fundamental_solutions([[D**3, D**2 + D + 1], [D**3 + D, D**2 + D + 2]], D, t)     # §8.10 Ex. 1
    >>> fs.determinant, fs.matrix
    (-D*(D + 1), Matrix([
    [exp(-t), 1],
    [exp(-t), 0]]))

    See Also
    --------
    compatibility, frequency_response
    """
    f = _matrix(f, var)
    if f.rows != f.cols:
        raise ModelError(f"f must be square, got {f.shape}")
    t_out = sp.Symbol("t") if t is None else t
    t = sp.Dummy("t", real=True)
    det = sp.expand(f.det())
    if det == 0:
        raise ModelError("det f(D) ≡ 0: the system is degenerate; check it with compatibility(f, e, D)")
    F = f.adjugate()
    roots = sp.roots(sp.Poly(det, var))
    if sum(roots.values()) != sp.degree(det, var):
        raise ModelError("the characteristic determinant has roots SymPy cannot find exactly; pass exact numbers")
    lam = sp.Dummy("lambda")
    cols = []
    order = sorted(roots.items(), key=lambda kv: (float(sp.re(kv[0])), float(sp.im(kv[0]))))
    for r, q in order:
        if real and sp.im(r) < 0:
            continue
        G = F.subs(var, lam) * sp.exp(lam * t)
        found: list[sp.Matrix] = []
        k = 0
        while len(found) < q and k < 2 * q + f.rows:
            Gk = sp.diff(G, lam, k).subs(lam, r) if k else G.subs(lam, r)
            Gk = (Gk * sp.exp(-r * t)).applyfunc(sp.expand)
            for j in range(Gk.cols):
                c = Gk[:, j]
                if any(v != 0 for v in c) and sp.Matrix.hstack(*found, c).rank(simplify=True) > len(found):
                    found.append(c)
                    if len(found) == q:
                        break
            k += 1
        if len(found) < q:
            raise ModelError(f"could not find {q} independent modal columns at λ = {r}")
        for c in found:
            content = sp.gcd_list([v for v in c if v != 0])
            c = (c / content).applyfunc(sp.expand) if content.is_number and content != 0 else c
            col = (c * sp.exp(r * t)).applyfunc(sp.expand)
            if real and sp.im(r) != 0:
                cols.append(col.applyfunc(lambda v: sp.simplify(sp.re(sp.expand_complex(v)))))
                cols.append(col.applyfunc(lambda v: sp.simplify(sp.im(sp.expand_complex(v)))))
            else:
                cols.append(col)
    matrix = sp.Matrix.hstack(*cols).xreplace({t: t_out})
    return FundamentalSolutions(sp.factor(det), int(sp.degree(det, var)), tuple(order), matrix)


@dataclass(frozen=True)
class FrequencyResponse(SymPyPrintable):
    """Result of :func:`frequency_response`: ``X(iω)`` and its gain/phase in the book's units (§8.28–8.30).

    Attributes
    ----------
    omega : ndarray
        The angular frequencies ``ω``.
    values : ndarray
        ``X(iω)``, shape ``(len(omega), n, m)``.
    """

    omega: np.ndarray
    values: np.ndarray

    @property
    def gain(self) -> np.ndarray:
        return np.abs(self.values)

    @property
    def phase(self) -> np.ndarray:
        """Phase in radians, unwrapped along ``ω``."""
        return np.unwrap(np.angle(self.values), axis=0)

    @property
    def decibels(self) -> np.ndarray:
        return 20 * np.log10(self.gain)

    @property
    def nepers(self) -> np.ndarray:
        """``ln |X|`` (1 dB = 0.11513 Np)."""
        return np.log(self.gain)

    def __repr__(self) -> str:
        return f"FrequencyResponse({self.omega.size} frequencies, shape {self.values.shape[1:]})"

    def plot(self, *, ax=None, entry: tuple = (0, 0)):
        """Gain in decibels of one entry against ``ω`` (log axis); returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        entry : (int, int), optional
            Row (output) and column (input) indices of the entry of ``X`` to draw; within its shape (default (0, 0)).
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        ax.semilogx(self.omega, self.decibels[:, entry[0], entry[1]])
        ax.set_xlabel("ω")
        ax.set_ylabel("gain, dB")
        return ax


@validated
def frequency_response(f: Any, e: Any, var: sp.Symbol, omega: Any) -> FrequencyResponse:
    """``X(iω) = f(iω)⁻¹ e(iω)`` of ``f(D) y = e(D) x`` (Bulgakov (1954), §8.28).

    Parameters
    ----------
    f : matrix-like
        Square ``n x n`` matrix (nested sequence or sympy.Matrix) of polynomials in ``var``: the operator ``f(D)``.
    e : matrix-like
        The input operator ``e(D)``: a column (or ``n x m`` matrix) of polynomials in ``var`` with as many rows as
        ``f``.
    var : sympy.Symbol
        The operator symbol ``D``; must be a SymPy Symbol.
    omega : float or array_like
        Angular frequencies ``ω``: finite real numbers, none at a resonance ``Δ(iω) = 0``.

    Returns
    -------
    FrequencyResponse

    Raises
    ------
    ModelError
        At a resonance, ``Δ(iω) = 0`` (use the resonant particular solution).

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import frequency_response
    >>> D = sp.Symbol("D")
    >>> r = frequency_response([[D + 1]], [[1]], D, [1.0])
    >>> round(float(r.decibels[0, 0, 0]), 4)
    -3.0103

    See Also
    --------
    fundamental_solutions, worst_case_gain
    """
    f = _matrix(f, var)
    e = _matrix(e, var, "e")
    ff = sp.lambdify(var, f, "numpy")
    ef = sp.lambdify(var, e, "numpy")
    w = np.atleast_1d(np.asarray(omega, dtype=float))
    out = []
    for wk in w:
        A = np.array(ff(1j * wk), dtype=complex).reshape(f.shape)
        B = np.array(ef(1j * wk), dtype=complex).reshape(e.shape)
        if abs(np.linalg.det(A)) <= 1e-13 * max(1.0, np.abs(A).max()) ** A.shape[0]:
            raise ModelError(f"Δ(iω) = 0 at ω = {wk}: resonance; the forced solution grows like t there")
        out.append(np.linalg.solve(A, B))
    return FrequencyResponse(w, np.array(out))


@validated
def worst_case_gain(numerator: Any, denominator: Any, *, t_max: float | None = None, tol: float = 1e-10) -> float:
    """Largest steady deviation per unit bound of a persistent disturbance, ``A = |S| + ∫₀^∞ |N(t)| dt`` (§8.54).

    ``N`` is the impulse response of ``numerator/denominator`` (denominator Hurwitz, degrees equal or proper),
    ``S`` the direct term; ``∫|N|`` is summed between the zeros of ``N`` (sign scan + brentq), cf. (8.567)–(8.570).

    Parameters
    ----------
    numerator : sequence of float
        Coefficients of the numerator, highest power first; finite numbers, degree at most the denominator's.
    denominator : sequence of float
        Coefficients of the denominator, highest power first; finite numbers forming a Hurwitz polynomial (every
        root with ``Re < 0``).
    t_max : float, optional
        End of the integration of ``|N|`` (positive); default ``(ln(1/tol) + 10)`` slowest time constants.
    tol : float, optional
        Absolute tolerance (> 0) of the integral; also sets the default ``t_max``.

    Returns
    -------
    float

    Examples
    --------
    >>> from symosc.linear import worst_case_gain
    >>> round(worst_case_gain([1], [1, 1]), 10)        # (D + 1) y = x: A = 1
    1.0

    See Also
    --------
    frequency_response
    """
    from scipy.integrate import quad
    from scipy.signal import residue

    num = np.atleast_1d(np.asarray(numerator, dtype=float))
    den = np.atleast_1d(np.asarray(denominator, dtype=float))
    if num.size > den.size:
        raise ModelError("numerator degree exceeds the denominator's: the response is not bounded")
    poles = np.roots(den)
    if poles.size == 0 or np.any(poles.real >= 0):
        raise ModelError("the denominator must be Hurwitz (every root with Re < 0) for a bounded accumulation")
    res, p, k = residue(num, den)
    S = float(k[0].real) if np.size(k) else 0.0

    def N(t):
        return float(np.real(np.sum(res * np.exp(p * t))))

    decay = -poles.real.max()
    t_end = t_max if t_max is not None else (np.log(1 / tol) + 10) / decay
    grid = np.linspace(0, t_end, 20001)
    vals = np.real(np.exp(np.outer(grid, p)) @ res)
    from scipy.optimize import brentq

    cuts = [0.0]
    for i in np.flatnonzero(np.sign(vals[1:]) * np.sign(vals[:-1]) < 0):
        cuts.append(brentq(N, grid[i], grid[i + 1], xtol=1e-14))
    cuts.append(t_end)
    total = 0.0
    for a, b in pairwise(cuts):
        val, _err = quad(N, a, b, epsabs=tol * 1e-2, limit=200)
        total += abs(val)
    if not np.isfinite(total):
        raise ConvergenceError("the integral of |N| did not converge")
    return abs(S) + total


@dataclass(frozen=True)
class ImpulseResponse(SymPyPrintable):
    """Result of :func:`impulse_response`: ``y = S(D) x + ∫₀ᵗ N(t - τ) x(τ) dτ`` for zero initial data (§8.50–8.51).

    Attributes
    ----------
    direct : sympy.Matrix
        ``S(D)``: the polynomial part of ``F(D) e(D)/Δ(D)`` (acts on ``x`` directly).
    kernel : sympy.Matrix
        ``N(t)``, the original of the proper part (residues at the roots of ``Δ``).
    """

    direct: sp.Matrix
    kernel: sp.Matrix

    def __repr__(self) -> str:
        return f"ImpulseResponse(direct={self.direct.tolist()}, kernel={self.kernel.tolist()})"


@validated
def impulse_response(f: Any, e: Any, var: sp.Symbol, t: sp.Symbol | None = None) -> ImpulseResponse:
    """Direct term ``S(D)`` and kernel ``N(t)`` of ``f(D) y = e(D) x`` (Bulgakov (1954), §8.50–8.51).

    ``F(D) e(D)/Δ(D) = S(D) + v(D)`` with ``F = adj f``; ``N(t)`` is the original of the proper part ``v``, found by
    the Heaviside expansion (residues), so that ``y = S(D) x + ∫₀ᵗ N(t - τ) x(τ) dτ`` from rest.

    Parameters
    ----------
    f : matrix-like
        Square ``n x n`` matrix (nested sequence or sympy.Matrix) of polynomials in ``var``: the operator ``f(D)``.
    e : matrix-like
        The input operator ``e(D)``: a column (or ``n x m`` matrix) of polynomials in ``var`` with as many rows as
        ``f``.
    var : sympy.Symbol
        The operator symbol ``D``; must be a SymPy Symbol.
    t : sympy.Symbol, optional
        Time symbol of the result (default ``Symbol("t")``).

    Returns
    -------
    ImpulseResponse

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import impulse_response
    >>> D, t = sp.symbols("D t")
    >>> r = impulse_response([[D**3 + 2*D**2 + 10*D, -1], [2*D**2 + 6*D + 64, 1]], [0, 10*D], D, t)   # §8.51
    >>> r.direct.T
    Matrix([[0, 10*D - 20]])

    See Also
    --------
    fundamental_solutions, frequency_response
    """
    from ...operational import inverse_carson

    f = _matrix(f, var)
    e = _matrix(e, var, "e")
    if e.rows != f.rows:
        raise ParameterError(f"e must have {f.rows} rows, got {e.rows}")
    t = sp.Symbol("t") if t is None else t
    det = sp.expand(f.det())
    if det == 0:
        raise ModelError("det f(D) ≡ 0: the system is degenerate; check it with compatibility(f, e, D)")
    G = (f.adjugate() * e).applyfunc(sp.expand)
    S = sp.zeros(*G.shape)
    N = sp.zeros(*G.shape)
    for i in range(G.rows):
        for j in range(G.cols):
            q, r = sp.div(sp.Poly(G[i, j], var), sp.Poly(det, var))
            S[i, j] = q.as_expr()
            if not r.is_zero:
                N[i, j] = sp.simplify(inverse_carson(var * r.as_expr() / det, var, t))
    return ImpulseResponse(S, N)


@validated
def resonant_particular(f: Any, e: Any, var: sp.Symbol, xi: Any, lam: Any, t: sp.Symbol | None = None) -> sp.Matrix:
    """Particular solution of ``f(D) y = e(D) ξ e^{λt}``, also at resonance (Bulgakov (1954), eqs. (8.185), (8.209)).

    If ``λ`` is a root of ``Δ`` of multiplicity ``q``, ``y = ∂^q/∂λ^q [e^{λt} F(λ)] e(λ) ξ / Δ^(q)(λ)`` (growing
    like ``t^q``); ``q = 0`` gives the steady state ``X(λ) ξ e^{λt}``.

    Parameters
    ----------
    f : matrix-like
        Square ``n x n`` matrix (nested sequence or sympy.Matrix) of polynomials in ``var``: the operator ``f(D)``.
    e : matrix-like
        The input operator ``e(D)``: a column (or ``n x m`` matrix) of polynomials in ``var`` with as many rows as
        ``f``.
    var : sympy.Symbol
        The operator symbol ``D``; must be a SymPy Symbol.
    xi : sequence or sympy.Matrix
        Amplitude vector ``ξ`` of the input, one entry per column of ``e`` (numbers or expressions).
    lam : number or sympy.Expr
        Exponent ``λ`` of the input ``e^{λt}`` (complex allowed, e.g. ``I*omega``).
    t : sympy.Symbol, optional
        Time symbol of the result (default ``Symbol("t")``).

    Returns
    -------
    sympy.Matrix
        The particular solution ``y(t)``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.linear import resonant_particular
    >>> D, t = sp.symbols("D t")
    >>> resonant_particular([[D**2 + 1]], [1], D, [1], sp.I, t)       # y'' + y = e^{it}
    Matrix([[-I*t*exp(I*t)/2]])

    See Also
    --------
    frequency_response, impulse_response
    """
    f = _matrix(f, var)
    e = _matrix(e, var, "e")
    t = sp.Symbol("t") if t is None else t
    xi = sp.Matrix(xi)
    lam = sp.sympify(lam)
    det = sp.expand(f.det())
    if det == 0:
        raise ModelError("det f(D) ≡ 0: the system is degenerate; check it with compatibility(f, e, D)")
    q = 0
    while sp.simplify(sp.diff(det, var, q).subs(var, lam)) == 0:
        q += 1
    s = sp.Dummy("s")
    G = sp.exp(s * t) * f.adjugate().subs(var, s)
    Gq = sp.diff(G, s, q) if q else G
    y = Gq.subs(s, lam) * e.subs(var, lam) * xi / sp.diff(det, var, q).subs(var, lam)
    return y.applyfunc(lambda v: sp.simplify(sp.expand(v)))


@validated
def mean_power(A: Any, N: Any, G: Any, H: Any, J: Any, xi: Any, omega: float) -> float:
    """Mean power of a harmonic force ``w = Re(ξ e^{iωt})`` on ``A ÿ + (N + G) ẏ + (H + J) y = w`` (§8.29, (8.220)).

    ``P̄ = ½ Re ζ̄'ᵀ (N - iJ/ω) ζ'`` with ``ζ' = iω ζ``, ``ζ = f(iω)⁻¹ ξ``; gyroscopic forces ``G`` do no work.

    Parameters
    ----------
    A : array_like, shape (n, n)
        Inertia matrix (symmetric); finite, square, the same size as the others.
    N : array_like, shape (n, n)
        Dissipation matrix (symmetric); finite, square, the same size as ``A``.
    G : array_like, shape (n, n)
        Gyroscopic matrix (antisymmetric); finite, square, the same size as ``A``.
    H : array_like, shape (n, n)
        Potential (stiffness) matrix (symmetric); finite, square, the same size as ``A``.
    J : array_like, shape (n, n)
        Circulatory (non-conservative positional) matrix (antisymmetric); finite, square, the same size as ``A``.
    xi : array_like, shape (n,)
        Complex amplitude ``ξ`` of the force; a vector of length ``n``.
    omega : float
        Angular frequency ``ω`` of the force; must be positive and not a resonance.

    Returns
    -------
    float
        The mean power ``P̄`` delivered by the force.

    Examples
    --------
    >>> from symosc.linear import mean_power
    >>> round(mean_power([[1]], [[0.5]], [[0]], [[4]], [[0]], [1.0], 2.0), 12)   # resonance: |ζ'| = 1/N
    1.0

    See Also
    --------
    frequency_response
    """
    mats = [check_finite_array(name, m) for name, m in zip("ANGHJ", (A, N, G, H, J), strict=True)]
    if any(m.ndim != 2 or m.shape[0] != m.shape[1] for m in mats) or len({m.shape for m in mats}) != 1:
        shapes = [m.shape for m in mats]
        raise ParameterError(f"A, N, G, H, J must be square matrices of one size, got shapes {shapes}")
    if np.shape(xi) != (mats[0].shape[0],):
        raise ParameterError(f"xi must be a vector of length {mats[0].shape[0]}, got shape {np.shape(xi)}")
    A_, N_, G_, H_, J_ = mats
    if omega <= 0:
        raise ParameterError(f"omega must be positive, got {omega}")
    fw = -(omega**2) * A_ + 1j * omega * (N_ + G_) + H_ + J_
    zeta = np.linalg.solve(fw, np.asarray(xi, dtype=complex))
    v = 1j * omega * zeta
    return float(0.5 * np.real(np.conj(v) @ (N_ - 1j * J_ / omega) @ v))
