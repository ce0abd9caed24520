"""Accurate divided differences for clustered floating-point nodes (private).

Within a cluster of nearly equal nodes ``x_i = μ + y_i`` the divided difference is computed from the Taylor
expansion of f about the cluster center,

    f[x_i, ..., x_j] = Σ_{m >= k} c_m h_{m-k}(y_i, ..., y_j),   c_m = f^(m)(μ)/m!,  k = j - i,

where ``h_r`` is the complete homogeneous symmetric polynomial of degree r.  Every term is a product of small
numbers, so nothing cancels; the simple recursion ``(f[x_(i+1)..x_j] - f[x_i..x_(j-1)])/(x_j - x_i)`` is used
only between clusters, where the denominator is not small.  Arithmetic is done in mpmath.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence

import mpmath
import sympy as sp

from ...errors import ConvergenceError, ModelError
from ...numeric import compile as _compile


class TaylorSource:
    """Lazily compiled derivatives of ``expr`` in ``x`` (mpmath backend), with a singularity check."""

    def __init__(self, expr: sp.Expr, x: sp.Symbol):
        self.expr = expr
        self.x = x
        self._derivs: list[sp.Expr] = [expr]
        self._funcs: list[Callable] = []

    def _func(self, m: int) -> Callable:
        while len(self._funcs) <= m:
            k = len(self._funcs)
            while len(self._derivs) <= k:
                self._derivs.append(sp.diff(self._derivs[-1], self.x))
            self._funcs.append(_compile(self._derivs[k], [self.x], backend="mpmath", check=False).raw)
        return self._funcs[m]

    @functools.cached_property
    def degree(self) -> int | None:
        """Polynomial degree of f (None when f is not a polynomial)."""
        return int(sp.degree(self.expr, self.x)) if self.expr.is_polynomial(self.x) else None

    def coefficient(self, m: int, at: mpmath.mpc, cluster: int = -1) -> mpmath.mpc:
        """``f^(m)(at)/m!`` ; ModelError if f is not analytic there."""
        if self.degree is not None and m > self.degree:
            return mpmath.mpf(0)
        try:
            v = mpmath.mpmathify(self._func(m)(at))
        except (ZeroDivisionError, ValueError) as exc:
            raise ModelError(
                f"f is not analytic at the eigenvalue {_fmt(at)} (its derivative of order {m} fails: "
                f"{exc or type(exc).__name__}); a matrix function needs f analytic at every eigenvalue"
            ) from exc
        if not mpmath.isfinite(v):
            raise ModelError(
                f"f is not analytic at the eigenvalue {_fmt(at)} (its derivative of order {m} is "
                f"{v}); a matrix function needs f analytic at every eigenvalue"
            )
        return v / mpmath.factorial(m)


def _fmt(z) -> str:
    z = complex(z)
    return f"{z.real:.8g}" if z.imag == 0 else f"{z.real:.8g}{z.imag:+.8g}j"


class IndicatorSource:
    """Taylor data of the function that is 1 near one cluster center and 0 near the others (for projectors)."""

    degree = 0

    def __init__(self, cluster: int):
        self.cluster = cluster

    def coefficient(self, m: int, at: mpmath.mpc, cluster: int = -1) -> mpmath.mpc:
        return mpmath.mpf(1) if (cluster == self.cluster and m == 0) else mpmath.mpf(0)


def divided_differences(
    nodes: Sequence[complex],
    clusters: Sequence[Sequence[int]],
    source,
    *,
    tol: float = 1e-17,
    max_terms: int = 200,
) -> list[mpmath.mpc]:
    """Newton coefficients ``f[x_0], f[x_0,x_1], ..., f[x_0..x_(n-1)]``.

    ``nodes`` must be ordered so that each cluster's members are contiguous; ``clusters`` lists their index
    ranges.  ``source.coefficient(m, μ)`` returns ``f^(m)(μ)/m!``.
    """
    n = len(nodes)
    # Extra digits: between clusters the recursion divides by gaps >= cluster_tol, losing a few digits per level.
    with mpmath.workdps(max(50, 30 + 3 * n)):
        return _divided_differences(nodes, clusters, source, tol, max_terms)


def _divided_differences(nodes, clusters, source, tol: float, max_terms: int) -> list[mpmath.mpc]:
    n = len(nodes)
    x = [mpmath.mpmathify(complex(v)) for v in nodes]
    D: list[list[mpmath.mpc | None]] = [[None] * n for _ in range(n)]
    degree = getattr(source, "degree", None)
    for ci, members in enumerate(clusters):
        lo, hi = members[0], members[-1]
        center = mpmath.fsum(x[lo : hi + 1]) / (hi - lo + 1)
        if hi == lo:
            D[lo][lo] = source.coefficient(0, x[lo], ci)
            continue
        y = [xi - center for xi in x[lo : hi + 1]]
        s = len(y)
        rho = max(abs(v) for v in y)
        coeff = functools.lru_cache(maxsize=None)(lambda m, c=center, q=ci: source.coefficient(m, c, q))
        for i in range(s):
            # h[r] = h_r(y_i..y_j), updated as j grows
            h = [mpmath.mpf(1)] + [mpmath.mpf(0)] * max_terms
            for j in range(i, s):
                for r in range(1, max_terms + 1):
                    h[r] = h[r] + y[j] * h[r - 1]
                k = j - i
                total = mpmath.mpf(0)
                scale = mpmath.mpf(0)
                small = 0
                converged = rho == 0 or degree is not None
                last = k + max_terms if degree is None else min(k + max_terms, max(degree + 1, k + 1))
                term = mpmath.mpf(0)
                for m in range(k, last):
                    term = coeff(m) * h[m - k]
                    total += term
                    scale = max(scale, abs(term))
                    if degree is None and m - k >= 1 and abs(term) <= tol * scale:
                        small += 1
                        if small >= 3 or rho == 0:
                            converged = True
                            break
                    else:
                        small = 0
                if not converged:
                    raise ConvergenceError(
                        f"the Taylor series of f about the cluster center {_fmt(center)} (cluster radius "
                        f"{mpmath.nstr(rho, 3)}) did not converge in {max_terms} terms; f may have a singularity "
                        "near this cluster. Use a smaller cluster_tol.",
                        achieved=float(abs(term) / scale) if scale else None,
                    )
                D[lo + i][lo + j] = total
    for width in range(1, n):
        for i in range(n - width):
            j = i + width
            if D[i][j] is None:
                D[i][j] = (D[i + 1][j] - D[i][j - 1]) / (x[j] - x[i])
    return [D[0][k] for k in range(n)]
