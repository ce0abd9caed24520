"""Analytic continuation of a function of a matrix through expansions about scalar matrices (Bulgakov §1.31).

A scalar element ``φ(λ) = Σ a_k (λ - β0)^k`` is continued along a path of centers ``β0 → β1 → ...``: each new
element ``χ(λ - β) = Σ b_k (λ - β)^k`` is the re-expansion of the previous one about a point inside its disk of
convergence (Bulgakov (1954), §1.31).  The matrix series ``Σ b_k (z - Eβ)^k`` converges iff every eigenvalue of
``z`` lies in the element's disk ``|λ - β| < R`` (§1.30), and agrees with Sylvester's formula there.

Two evaluations are offered.  ``method="single"`` is the book's: one element about ``E β`` whose disk holds the
whole spectrum.  ``method="disks"`` (default) splits the spectrum into clusters of nearby eigenvalues (the
reordered Schur form, Davies & Higham (2003)), continues the element to the center of each cluster and sums the
series there; Parlett's recurrence joins the blocks.  This works for spectra spanning many decades, where no single
disk avoiding the singularities of f contains the spectrum.

The elements are the Taylor series of a given f (exact derivatives in mpmath).  Along the path the branch is
tracked: the continued element is ``c·P + d`` with ``P`` the principal-branch element of f at the new center, and
``c``, ``d`` are fixed by matching the continued value and first derivative (checked on the second), so going
round a branch point of ``log`` adds ``2πi`` and of ``sqrt`` changes the sign, as analytic continuation must.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ConvergenceError, ModelError, ParameterError
from .._util import as_scalar_function, as_square_matrix
from . import _schur_parlett, _taylor

__all__ = ["AnalyticContinuation", "analytic_continuation"]

#: orders used to estimate the radius of an element
_RADIUS_ORDERS = range(12, 25)
#: terms summed when moving the element one step (step 0.25 R: 0.25**44 ~ 3e-27, leaving room for an
#: overestimated radius; a step whose tail is not negligible is halved)
_STEP_TERMS = 44


@dataclass(frozen=True)
class AnalyticContinuation(SymPyPrintable):
    """Result of :func:`analytic_continuation`.

    Attributes
    ----------
    value : ndarray
        ``f(A)`` on the continued branch.
    disks : tuple of (complex, float, float)
        One ``(β, R, ρ)`` per expansion used: center ``β``, estimated radius of convergence ``R`` of the element
        there, and the largest ``|λ - β|`` over the eigenvalues summed in it (``ρ < R``, §1.30).
    branches : tuple of (complex, complex)
        ``(c, d)`` per disk: the element used is ``c·f + d`` with ``f`` the principal branch (``(1, 0)``: principal).
    path : tuple of complex
        All centers visited, in order (the steps of the continuation).
    terms : int
        Largest number of series terms summed on a block.
    error_estimate : float
        Estimated relative truncation error of the series (geometric tail bound).
    converged : bool
        ``error_estimate <= tol``.
    method : str
        ``"disks"`` or ``"single"``.
    """

    value: np.ndarray
    disks: tuple
    branches: tuple
    path: tuple
    terms: int
    error_estimate: float
    converged: bool
    method: str

    def __repr__(self) -> str:
        return (
            f"AnalyticContinuation(method={self.method!r}, disks={len(self.disks)}, steps={len(self.path)}, "
            f"terms={self.terms}, error_estimate={self.error_estimate:.3g}, converged={self.converged})"
        )

    def _repr_latex_(self) -> str:
        body = sp.latex(sp.Matrix(np.round(self.value, 12).tolist())) if self.value.size <= 36 else r"\dots"
        return rf"$f(A) = {body},\quad \text{{{len(self.disks)} disk(s), error}} \approx {self.error_estimate:.2g}$"

    def plot(self, *, ax: Any = None) -> Any:
        """Draw the path of centers, the disks of convergence used and the eigenvalues in the complex plane.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
            The axes drawn on.
        """
        from ..._plotting import pyplot

        plt = pyplot()
        from matplotlib.patches import Circle

        if ax is None:
            _, ax = plt.subplots()
        pts = np.array(self.path, dtype=complex)
        ax.plot(pts.real, pts.imag, ".-", color="0.5", label="continuation path")
        for beta, R, rho in self.disks:
            beta = complex(beta)
            if np.isfinite(R):
                ax.add_patch(Circle((beta.real, beta.imag), R, fill=False, ls="--", color="C0"))
            ax.add_patch(Circle((beta.real, beta.imag), max(rho, 1e-300), fill=False, color="C1"))
        ax.set_xlabel("Re λ")
        ax.set_ylabel("Im λ")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title("analytic continuation (Bulgakov 1954, §1.31)")
        ax.legend()
        return ax


class _StepTooLong(Exception):
    """The re-expansion did not converge to working accuracy within the terms used: take a shorter step."""


class _Element:
    """Taylor element ``c·P_β + d`` of f at β (``P_β``: principal-branch coefficients from exact derivatives)."""

    def __init__(self, source: _taylor.TaylorSource, beta: complex, c: Any = 1, d: Any = 0):
        self.source, self.beta, self.c, self.d = source, mpmath.mpc(beta), mpmath.mpc(c), mpmath.mpc(d)
        self._p: list = []

    def principal(self, k: int) -> Any:
        while len(self._p) <= k:
            self._p.append(self.source.coefficient(len(self._p), self.beta))
        return self._p[k]

    def coefficient(self, k: int) -> Any:
        return self.c * self.principal(k) + (self.d if k == 0 else 0)

    def radius(self) -> float:
        """Radius of convergence estimated from the coefficients of orders 12..24 (§1.30): the smallest ratio
        ``|c_k/c_(k+1)|`` (the root test ``|c_k|^(-1/k)`` where coefficients vanish); inf for a polynomial, or when
        the ratios keep growing with k (an entire function)."""
        if self.source.degree is not None:
            return float("inf")
        est: list[float] = []
        for k in _RADIUS_ORDERS:
            a, b = self.principal(k), self.principal(k + 1)
            if a != 0 and b != 0:
                est.append(float(abs(a / b)))
            elif b != 0:
                est.append(float(abs(b) ** (-1.0 / (k + 1))))
        if not est:
            return float("inf")
        if est[-1] > 1.5 * est[0]:
            return float("inf")  # ratios ~ k: entire function
        return min(est)

    def moved(self, new: complex) -> _Element:
        """The element re-expanded about ``new`` (inside the disk), on the continued branch."""
        h = mpmath.mpc(new) - self.beta
        v = [mpmath.mpc(0)] * 3
        hp = [mpmath.mpc(1)]
        for _ in range(_STEP_TERMS):
            hp.append(hp[-1] * h)
        tail = mpmath.mpf(0)
        for k in range(_STEP_TERMS):
            a = self.coefficient(k)
            if k >= _STEP_TERMS - 4:
                tail = max(tail, abs(a * hp[k - 2]) * k * k)
            v[0] += a * hp[k]
            if k >= 1:
                v[1] += k * a * hp[k - 1]
            if k >= 2:
                v[2] += (k * (k - 1) // 2) * a * hp[k - 2]
        if tail > 1e-18 * max(abs(v[0]), abs(v[1]), abs(v[2]), mpmath.mpf(1e-300)):
            raise _StepTooLong
        nxt = _Element(self.source, complex(new))
        p0, p1, p2 = nxt.principal(0), nxt.principal(1), nxt.principal(2)
        if p1 != 0:
            c = v[1] / p1
        elif p2 != 0:
            c = v[2] / p2
        else:
            raise ModelError(
                f"cannot follow the branch of f at the critical point {complex(new):.6g} (f' = f'' = 0 there); "
                "move the path slightly"
            )
        scale = max(abs(v[2]), abs(c * p2), mpmath.mpf(1e-300))
        if abs(v[2] - c * p2) > 1e-12 * scale + 1e-14 * abs(v[1]):
            raise ModelError(
                f"the continued element of f at {complex(new):.6g} is not c·f + d for the principal branch f; "
                "analytic continuation of this f is supported for branches related by such maps (log, powers, "
                "inverse trigonometric functions)"
            )
        nxt.c, nxt.d = c, v[0] - c * p0
        return nxt


def _walk(
    element: _Element, targets: list[complex], step: float, path: list[complex], max_steps: int = 2000
) -> _Element:
    """Continue ``element`` through ``targets`` in straight segments, each step at most ``step·R``.

    A segment through a singularity of f never gets past it: the steps shrink with the distance to it.  Once the
    radius has stayed below ``1e-15`` of the remaining distance for three steps (the singularity lies on the
    segment to the precision of its end points), the walk stops with a ConvergenceError, as after ``max_steps``."""
    for target in targets:
        stalled = 0
        for _ in range(max_steps):
            here = complex(element.beta)
            gap = target - here
            if abs(gap) <= 1e-15 * max(abs(target), 1.0):
                break
            R = element.radius()
            if not R > 0:  # pragma: no cover - f is checked for analyticity at the centers first
                raise ModelError(f"f has a singularity at the center {here:.6g} of the continuation")
            stalled = stalled + 1 if R <= 1e-15 * abs(gap) else 0
            if stalled >= 3:
                raise ConvergenceError(
                    f"the continuation from {here:.6g} to {target:.6g} stalls at a radius of convergence of "
                    f"{R:.3g}: the path passes too close to a singularity of f; choose a path (or center) around it"
                )
            move = gap if abs(gap) <= step * R else gap / abs(gap) * step * R
            for _ in range(60):
                try:
                    element = element.moved(here + move)
                    break
                except _StepTooLong:
                    move = move / 2
            else:  # pragma: no cover - a tiny step always converges unless f is singular at `here`
                raise ConvergenceError(f"the continuation cannot leave {here:.6g}: f looks singular there")
            path.append(complex(element.beta))
        else:
            raise ConvergenceError(
                f"the continuation from {complex(element.beta):.6g} to {target:.6g} needed more than {max_steps} "
                "steps: the path passes too close to a singularity of f"
            )
    return element


def _block_series(
    element: _Element, T: np.ndarray, eigs: np.ndarray, beta: complex, R: float, order: int, tol: float
) -> tuple[np.ndarray, int, float, float]:
    """``Σ b_k (T - βE)^k`` (eigenvalues ``eigs`` of T); returns value, terms, relative tail estimate, ρ."""
    s = T.shape[0]
    N = T - beta * np.eye(s)
    rho = float(np.max(np.abs(eigs - beta)))
    if s == 1 and rho == 0.0:
        return np.array([[complex(element.coefficient(0))]]), 1, 0.0, 0.0
    if not rho < R:
        raise ConvergenceError(
            f"an eigenvalue lies outside the disk of convergence about β = {beta:.6g}: max|λ - β| = {rho:.6g} is not "
            f"below the radius R = {R:.6g} (Bulgakov (1954), §1.30); choose another center or method='disks'"
        )
    F = np.zeros((s, s), dtype=complex)
    P = np.eye(s, dtype=complex)
    small, rel, q = 0, np.inf, rho / R if np.isfinite(R) else 0.0
    for k in range(order):
        term = complex(element.coefficient(k)) * P
        F = F + term
        nf = float(np.linalg.norm(F)) or 1.0
        rel = float(np.linalg.norm(term)) / nf
        small = small + 1 if rel <= tol else 0
        if small >= 3 and k >= s:
            tail = rel * q / (1 - q) if q < 1 else rel
            return F, k + 1, tail, rho
        P = P @ N
    raise ConvergenceError(
        f"the series about β = {beta:.6g} did not reach tol={tol:g} in order={order} terms (last relative term "
        f"{rel:.3g}; max|λ - β|/R = {q:.3g}); raise order= or use method='disks'",
        achieved=float(rel),
    )


@validated
def analytic_continuation(
    A: Any,
    f: Any,
    *,
    center: complex = 1,
    path: Any = (),
    var: sp.Symbol | None = None,
    method: str = "disks",
    order: int = 400,
    tol: float = 1e-15,
    step: float = 0.25,
    cluster_tol: float = 1e-2,
) -> AnalyticContinuation:
    """``f(A)`` by analytic continuation of f's Taylor element about ``center`` (Bulgakov (1954), §1.31).

    The element of f about ``center`` (principal branch there) is re-expanded about scalar matrices ``E β`` along
    ``path`` and then to each expansion point; the branch follows the path, so ``log`` continued once round the
    origin gains ``2πi E``.  Each matrix series ``Σ b_k (A - Eβ)^k`` is summed only where the eigenvalue criterion
    of §1.30 holds (all ``|λ - β| < R``).

    Parameters
    ----------
    A : ndarray or Matrix
        Square matrix with finite numeric entries (evaluated in double precision).
    f : callable, Lambda or Expr
        Analytic function, as for :func:`matrix_function` (``sympy.log``, ``sympy.sqrt``, ``Lambda(x, ...)``).
    center : complex
        Center ``β0`` of the initial element (principal branch of f there).
    path : sequence of complex
        Intermediate points the continuation passes through, in order (straight segments between them).
    var : Symbol, optional
        Variable of an expression ``f``.
    method : {"disks", "single"}
        ``"disks"``: one expansion per cluster of eigenvalues (any spread of the spectrum); ``"single"``: the
        book's single expansion about ``E β`` with ``β`` the last point of ``path`` (or ``center``).
    order : int
        Largest number of series terms summed for one block (the series order).
    tol : float
        Relative size of the last terms at which a series is stopped.
    step : float
        Each continuation step moves at most ``step`` times the current radius of convergence (0 < step ≤ 0.5).
    cluster_tol : float
        Relative distance below which eigenvalues share a disk (``"disks"``).

    Returns
    -------
    AnalyticContinuation
        ``value``, the ``disks`` used, the ``branches``, the ``path`` of centers, ``terms``, ``error_estimate``.

    Raises
    ------
    ConvergenceError
        An eigenvalue lies outside the disk of its element (§1.30), the series did not reach ``tol`` within
        ``order`` terms, or the path runs into a singularity.
    ModelError
        f is singular at a center or eigenvalue, or its branches are not affine images of one another.
    ParameterError
        Non-finite entries, an f with free parameters, bad options.

    See Also
    --------
    matrix_function, matrix_power_series, series_converges

    Examples
    --------
    The series of ``log`` about 1 converges only for ``|λ - 1| < 1``; continued about the eigenvalues it gives
    ``log A`` for the spectrum ``{0.001, 50}``:

    >>> import numpy as np, sympy as sp
    >>> A = np.array([[0.001, 1.0], [0.0, 50.0]])
    >>> res = analytic_continuation(A, sp.log)
    >>> np.round(res.value.real, 10)
    array([[-6.90775528,  0.21639989],
           [ 0.        ,  3.91202301]])
    >>> len(res.disks), res.converged
    (2, True)

    Going once round the origin adds ``2πi`` (the continuation of log is multivalued):

    >>> res = analytic_continuation(np.diag([2.0, 3.0]), sp.log, path=[1j, -1, -1j, 1])
    >>> np.round(res.value.imag / (2 * np.pi), 12)
    array([[1., 0.],
           [0., 1.]])
    """
    if method not in ("disks", "single"):
        raise ParameterError(f"method must be 'disks' or 'single', got {method!r}")
    if isinstance(order, bool) or not isinstance(order, int | np.integer) or order < 1:
        raise ParameterError(f"order must be a positive integer (the number of series terms), got {order!r}")
    for name, val in (("tol", tol), ("step", step), ("cluster_tol", cluster_tol)):
        if isinstance(val, bool) or not isinstance(val, int | float | np.floating) or not np.isfinite(val) or val <= 0:
            raise ParameterError(f"{name} must be a positive finite number, got {val!r}")
    if step > 0.5:
        raise ParameterError(f"step must be at most 0.5 (a fraction of the radius of convergence), got {step}")
    try:
        beta0 = complex(center)
        points = [complex(p) for p in path]
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"center and path must be complex numbers: {exc}") from exc
    if not all(np.isfinite(p) for p in [beta0, *points]):
        raise ParameterError("center and path must be finite complex numbers")
    M = np.array(as_square_matrix(A).evalf().tolist(), dtype=complex) if not isinstance(A, np.ndarray) else A
    if M.ndim != 2 or M.shape[0] != M.shape[1] or M.size == 0:
        raise ModelError(f"A must be a non-empty square matrix, got shape {M.shape}")
    try:
        M = M.astype(complex)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"A must have numeric entries: {exc}") from exc
    if not np.all(np.isfinite(M)):
        raise ParameterError("A has non-finite entries (nan or inf); analytic continuation needs finite entries")
    expr, x = as_scalar_function(f, var)
    if expr.free_symbols - {x}:
        raise ParameterError(f"f has free parameters {sorted(map(str, expr.free_symbols - {x}))}; substitute numbers")
    source = _taylor.TaylorSource(expr, x)
    visited = [beta0]
    with mpmath.workdps(30):
        start = _walk(_Element(source, beta0), points, step, visited)
        disks, branches, info = [], [], {"terms": 0, "err": 0.0}

        def block(element: _Element, T: np.ndarray, eigs: np.ndarray, beta: complex) -> np.ndarray:
            R = element.radius()
            F, terms, err, rho = _block_series(element, T, eigs, beta, R, order, tol)
            disks.append((beta, R, rho))
            branches.append((complex(element.c), complex(element.d)))
            info["terms"], info["err"] = max(info["terms"], terms), max(info["err"], err)
            return F

        if method == "single":
            for lam in np.linalg.eigvals(M):
                source.coefficient(1, mpmath.mpc(complex(lam)))  # ModelError where f is not analytic
            value = block(start, M, np.linalg.eigvals(M), complex(start.beta))
        else:

            def block_f(k: int, Tk: np.ndarray) -> np.ndarray:
                beta = complex(np.mean(np.diag(Tk)))
                for lam in {beta, *np.diag(Tk).tolist()}:
                    source.coefficient(1, mpmath.mpc(lam))  # ModelError where f is not analytic
                element = _walk(start, [beta], step, visited)
                return block(element, Tk, np.diag(Tk), beta)

            value = _schur_parlett.schur_parlett(M, block_f, cluster_tol)
    if not np.any(M.imag) and float(np.max(np.abs(value.imag))) <= 1e-13 * max(float(np.max(np.abs(value))), 1e-300):
        value = value.real.copy()
    err = float(info["err"])
    return AnalyticContinuation(
        value=value,
        disks=tuple(disks),
        branches=tuple(branches),
        path=tuple(visited),
        terms=int(info["terms"]),
        error_estimate=err,
        converged=err <= tol,
        method=method,
    )
