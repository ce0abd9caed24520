"""Floquet theory for linear periodic systems ``x' = A(t) x``: monodromy matrix, multipliers, exponents.

The fundamental matrix ``X(t)`` with ``X(0) = I`` satisfies ``X(t + T) = X(t) X(T)``; ``X(T)`` is the
monodromy matrix, its eigenvalues ``rho`` are the Floquet multipliers and ``zeta = ln(rho) / T`` the
characteristic exponents (defined modulo ``2*pi*i/T``).  Sources: Bulgakov (1954),
§§11.1–11.4, and Gribkov & Khokhlov (2015), eqs. (2)–(5).

The matrix ODE is integrated for all ``n`` columns at once (one ``n x n`` matrix product per
right-hand-side call) together with ``s' = tr A(t)``, so that the Liouville relation
``det X(T) = exp(integral of tr A over a period)`` is checked with no extra quadrature.

Reversible (Hill-type) systems.  If an involution ``R`` (``R @ R = I``) satisfies ``R A(-t) R = -A(t)``,
then ``z(t) = R x(-t)`` solves the same equation, hence ``X(-t) = R X(t) R`` and, from
``X(T/2) = X(-T/2) X(T)``,

    X(T) = R X(T/2)^{-1} R X(T/2),

so half a period of integration suffices.  The first-order form ``(q, q')`` of ``M q'' + K(t) q = 0``
with ``K`` even in ``t`` (e.g. ``K0 + K1*cos(p*t)``) has this property with ``R = diag(I, -I)``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any

import numpy as np
import sympy as sp

from .._plotting import plot_method
from .._printing import SymPyPrintable
from .._validate import check_finite_array, check_positive, validated
from ..errors import ConvergenceError, ModelError, ParameterError
from ..numeric import compile, resolve
from ..symbols import sort_symbols, t

__all__ = ["FloquetResult", "floquet_multipliers", "monodromy"]


@dataclass(frozen=True)
class FloquetResult(SymPyPrintable):
    """Monodromy matrix of ``x' = A(t) x`` over one period and what follows from it.

    Attributes
    ----------
    monodromy : ndarray, shape (n, n)
        ``X(T)`` with ``X(0) = I``.
    period : float
        The period ``T``.
    unit_tol : float
        Requested tolerance on ``|rho| = 1``; :attr:`stability` uses :attr:`effective_tol`.
    liouville_error : float
        Achieved accuracy: ``|det X - exp(S)| / exp(S)`` with ``S`` the integral of ``tr A`` over the
        integrated interval (the whole period, or half of it when a reversor was used).
    trace_integral : float
        ``S`` = integral of ``tr A`` over one period (Liouville: ``det X(T) = exp(S)``).
    nfev : int
        Right-hand-side evaluations used by the integrator.
    reversor_used : bool
        Whether the half-period construction ``X(T) = R X(T/2)^{-1} R X(T/2)`` was used.
    integration_rtol : float
        The integrator's relative tolerance.
    _mult : ndarray or None
        Internal cache of :attr:`floquet_multipliers` (the eigenvalues of ``monodromy`` by decreasing modulus);
        computed from ``monodromy`` when None.
    """

    monodromy: np.ndarray
    period: float
    unit_tol: float
    liouville_error: float
    trace_integral: float
    nfev: int
    reversor_used: bool = False
    integration_rtol: float = 0.0
    _mult: np.ndarray = field(default=None, repr=False, compare=False)

    def __post_init__(self) -> None:
        if self._mult is None:
            X = check_finite_array("monodromy", self.monodromy, ndim=2, complex_ok=True)
            if X.shape[0] != X.shape[1]:
                raise ParameterError(f"monodromy must be a square matrix, got shape {X.shape}")
            rho = np.linalg.eigvals(self.monodromy)
            order = np.lexsort((-rho.imag, -np.abs(rho)))
            object.__setattr__(self, "_mult", rho[order])

    # ------------------------------------------------------------------ derived quantities
    @property
    def floquet_multipliers(self) -> np.ndarray:
        """Eigenvalues ``rho`` of the monodromy matrix, by decreasing modulus."""
        return self._mult

    @property
    def characteristic_exponents(self) -> np.ndarray:
        """``zeta = ln(rho) / T`` (principal branch; defined modulo ``2*pi*i/T``)."""
        with np.errstate(divide="ignore"):
            return np.log(self._mult.astype(complex)) / self.period

    @property
    def spectral_radius(self) -> float:
        """``max |rho|``."""
        return float(np.max(np.abs(self._mult)))

    @property
    def effective_tol(self) -> float:
        """Tolerance actually used on ``|rho| = 1``: ``max(unit_tol, 10 sqrt(accuracy * max(1, ||X(T)||)))``.

        ``accuracy = max(liouville_error, integration_rtol)``, ``||X(T)||`` the spectral norm.  The square root
        is there because a double multiplier with a Jordan block (every boundary of a parametric-resonance
        tongue) is perturbed like the square root of the matrix error: with ``rtol = 1e-12`` the multipliers on
        a Mathieu boundary are split by ~1e-6.  Points classified differently than with an exact monodromy
        matrix therefore lie within ~``accuracy`` (in the parameters) of a boundary.
        """
        acc = max(self.liouville_error, self.integration_rtol) * max(1.0, float(np.linalg.norm(self.monodromy, 2)))
        return float(max(self.unit_tol, 10.0 * np.sqrt(acc)))

    @property
    def hamiltonian_indicator(self) -> float:
        """``max_k |rho_k + 1/rho_k| - 2``: <= 0 exactly when every multiplier lies on the unit circle.

        For Hamiltonian (symplectic) monodromy matrices ``rho + 1/rho`` is the trace of a 2x2 block and is
        smooth in the parameters even where the multipliers themselves split like a square root, so this
        is the function to bisect on when locating a stability boundary.  (Krein collisions of complex
        quadruplets are not detected by it; use :attr:`spectral_radius` there.)
        """
        rho = self._mult.astype(complex)
        with np.errstate(divide="ignore", invalid="ignore"):
            sigma = rho + 1.0 / rho
        return float(np.max(np.abs(sigma)) - 2.0)

    @property
    def stability(self) -> str:
        """Classification with the tolerance ``tol = effective_tol`` on ``|rho| = 1``.

        ``"unstable"`` (some ``|rho| > 1 + tol``), ``"asymptotically stable"`` (all ``|rho| < 1 - tol``),
        ``"stable"`` (the rest lie on the unit circle and are semisimple) or ``"critical"``: multipliers on the
        unit circle coincide within ``10 tol`` and the monodromy matrix is not diagonalisable there (a Jordan
        block, as on the boundary of a Mathieu instability tongue, where one solution grows linearly).
        """
        r = np.abs(self._mult)
        tol = self.effective_tol
        if np.any(r > 1 + tol):
            return "unstable"
        if np.all(r < 1 - tol):
            return "asymptotically stable"
        on = self._mult[np.abs(r - 1) <= tol]
        scale = max(1.0, float(np.max(np.abs(self.monodromy))))
        ctol = 10.0 * tol
        used = np.zeros(on.size, bool)
        for i in range(on.size):
            if used[i]:
                continue
            cluster = np.abs(on - on[i]) <= ctol
            used |= cluster
            k = int(cluster.sum())
            if k > 1:
                center = on[cluster].mean()
                sv = np.linalg.svd(self.monodromy - center * np.eye(self.monodromy.shape[0]), compute_uv=False)
                nullity = int(np.sum(sv <= ctol * scale))
                if nullity < k:
                    return "critical"
        return "stable"

    @property
    def is_stable(self) -> bool:
        """True for ``"stable"`` and ``"asymptotically stable"``."""
        return self.stability in ("stable", "asymptotically stable")

    def __repr__(self) -> str:
        rho = ", ".join(f"{z:.6g}" for z in self._mult[:6])
        more = ", ..." if self._mult.size > 6 else ""
        return (
            f"FloquetResult(n={self.monodromy.shape[0]}, T={self.period:.6g}, {self.stability}, "
            f"multipliers=[{rho}{more}], liouville_error={self.liouville_error:.2e})"
        )

    def _repr_latex_(self) -> str:
        rho = ", ".join(
            sp.latex(sp.Float(complex(z).real, 6) + sp.I * sp.Float(complex(z).imag, 6)) for z in self._mult
        )
        return f"$$\\rho = \\{{{rho}\\}},\\quad \\text{{{self.stability}}}$$"

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Multipliers in the complex plane with the unit circle.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
            The axes drawn on.
        """
        from .._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots(figsize=(4.5, 4.5))
        th = np.linspace(0, 2 * np.pi, 361)
        ax.plot(np.cos(th), np.sin(th), "k-", lw=0.8)
        ax.plot(self._mult.real, self._mult.imag, "o", color="C3")
        ax.set_aspect("equal")
        ax.set_xlabel(r"Re $\rho$")
        ax.set_ylabel(r"Im $\rho$")
        ax.set_title(f"Floquet multipliers ({self.stability})")
        return ax


# ---------------------------------------------------------------------------------------- monodromy
def _as_matrix_function(
    A: Any, period: float, args: Sequence[Any] | None, values: Mapping[Any, Any] | None
) -> tuple[Callable[[float], np.ndarray], int, Any]:
    """Turn a SymPy Matrix or a callable into ``f(t) -> ndarray (n, n)``; also return n and the symbolic A."""
    if isinstance(A, sp.MatrixBase):
        if A.shape[0] != A.shape[1] or A.shape[0] == 0:
            raise ModelError(f"A must be a square matrix, got shape {A.shape}")
        params = sort_symbols(A.free_symbols - {t})
        if any(s.name == "t" for s in params):
            raise ParameterError(
                "A contains a symbol named 't' that is not symosc.symbols.t (different assumptions); "
                "build A with symosc.symbols.t as the time variable"
            )
        vals = resolve(params, values or {}) if params else []
        fn = _compiled(sp.ImmutableMatrix(A), tuple(params))
        fn(0.0, *vals)  # checks the parameter values once
        raw = fn.raw
        vals_f = [float(v) for v in vals]

        def f(tt: float) -> np.ndarray:
            return np.asarray(raw(tt, *vals_f), dtype=float)

        return f, A.shape[0], A
    if callable(A):
        extra = tuple(args or ())

        def f(tt: float) -> np.ndarray:
            return np.asarray(A(tt, *extra))

        a0 = f(0.0)
        if a0.ndim != 2 or a0.shape[0] != a0.shape[1]:
            raise ModelError(f"A(t) must return a square matrix, got shape {a0.shape}")
        return f, a0.shape[0], None
    raise ModelError(f"A must be a SymPy Matrix or a callable A(t) -> ndarray, got {type(A).__name__}")


@lru_cache(maxsize=32)
def _compiled(A: sp.ImmutableMatrix, params: tuple) -> Any:
    """Compiled ``A(t, *params)``; cached so that sweeps over parameter values compile once."""
    return compile(A, [t, *params], name="floquet_A")


@lru_cache(maxsize=32)
def _auto_reversor_cached(A: sp.ImmutableMatrix) -> np.ndarray | None:
    return _auto_reversor(A, A.shape[0])


def _check_periodic(f: Callable[[float], np.ndarray], period: float) -> None:
    for tt in (0.123456789 * period, 0.618033988 * period):
        a, b = f(tt), f(tt + period)
        if not np.allclose(a, b, rtol=1e-9, atol=1e-12 * max(1.0, float(np.max(np.abs(a))))):
            raise ModelError(f"A(t) is not periodic with period {period:g}: A(t) != A(t + T) at t = {tt:.6g}")


def _auto_reversor(A_sym: Any, n: int) -> np.ndarray | None:
    """``diag(I, -I)`` if ``R A(-t) R = -A(t)`` holds symbolically, else None."""
    if A_sym is None or n % 2:
        return None
    h = n // 2
    R = sp.diag(*([1] * h + [-1] * h))
    diff = R * A_sym.xreplace({t: -t}) * R + A_sym
    if all(e == 0 or sp.expand(e) == 0 or sp.simplify(e) == 0 for e in diff):
        return np.diag([1.0] * h + [-1.0] * h)
    return None


@validated
def monodromy(
    A: Any,
    period: float,
    *,
    args: Sequence[Any] | None = None,
    values: Mapping[Any, Any] | None = None,
    rtol: float = 1e-12,
    atol: float = 1e-14,
    method: str = "DOP853",
    reversor: Any = "auto",
    unit_tol: float = 1e-9,
    check_periodic: bool = True,
) -> FloquetResult:
    """Monodromy matrix ``X(T)`` of ``x' = A(t) x`` with a ``T``-periodic ``A``.

    Parameters
    ----------
    A : sympy.Matrix or callable
        ``n x n`` matrix in ``symosc.symbols.t`` and parameters (compiled with :func:`symosc.numeric.compile`;
        parameter values come from ``values``), or a function ``A(t, *args) -> ndarray (n, n)``.
    period : float
        The period ``T > 0``.
    args : sequence, optional
        Extra positional arguments of a callable ``A``.
    values : mapping, optional
        Parameter values for a symbolic ``A`` (keyed by Symbol or name).
    rtol, atol : float
        Integrator tolerances (``scipy.integrate.solve_ivp``).
    method : str
        ``solve_ivp`` method (``"DOP853"``, ``"RK45"``, ``"Radau"``, ...).
    reversor : "auto", None or array
        Involution ``R`` with ``R A(-t) R = -A(t)``; then only half a period is integrated (see the module
        docstring).  ``"auto"`` tests ``R = diag(I, -I)`` symbolically for a SymPy ``A``; for a callable pass
        ``R`` explicitly (it is verified numerically at two instants).
    unit_tol : float
        Tolerance on ``|rho| = 1`` for :attr:`FloquetResult.stability` (raised to ``10 sqrt(accuracy)``, see
        :attr:`FloquetResult.effective_tol`).
    check_periodic : bool
        Verify ``A(t + T) = A(t)`` numerically at two instants.

    Returns
    -------
    FloquetResult

    Raises
    ------
    ModelError
        Non-square or non-periodic ``A``, or an invalid reversor.
    ConvergenceError
        If the integrator fails or the Liouville check is worse than ``max(1e-6, 1e4 * rtol)``.

    See Also
    --------
    floquet_multipliers

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.symbols import t
    >>> a, q = sp.symbols("a q", real=True)
    >>> A = sp.Matrix([[0, 1], [-(a - 2 * q * sp.cos(2 * t)), 0]])   # Mathieu equation
    >>> res = monodromy(A, sp.pi, values={"a": 2.0, "q": 0.2})
    >>> res.stability, res.reversor_used
    ('stable', True)
    >>> monodromy(A, sp.pi, values={"a": 1.0, "q": 0.2}).stability   # inside the b1..a1 tongue
    'unstable'
    """
    from scipy.integrate import solve_ivp

    try:
        T = float(period)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"period must be a positive number, got {period!r}") from exc
    if not np.isfinite(T) or T <= 0:
        raise ParameterError(f"period must be a positive finite number, got {period!r}")
    rtol, atol = check_positive("rtol", rtol), check_positive("atol", atol)
    unit_tol = check_positive("unit_tol", unit_tol)
    f, n, A_sym = _as_matrix_function(A, T, args, values)
    if check_periodic:
        _check_periodic(f, T)

    R = None
    if isinstance(reversor, str):
        if reversor != "auto":
            raise ParameterError(f"reversor must be 'auto', None or a matrix, got {reversor!r}")
        R = _auto_reversor_cached(sp.ImmutableMatrix(A_sym)) if A_sym is not None else None
    elif reversor is not None:
        R = np.asarray(reversor, dtype=float)
        if R.shape != (n, n) or not np.allclose(R @ R, np.eye(n)):
            raise ModelError("reversor must be an n x n involution (R @ R = I)")
        for tt in (0.1234 * T, 0.377 * T):
            if not np.allclose(R @ f(-tt) @ R, -f(tt), rtol=1e-9, atol=1e-12):
                raise ModelError("reversor R does not satisfy R A(-t) R = -A(t)")

    t_end = T / 2 if R is not None else T
    nn = n * n

    def rhs(tt: float, y: np.ndarray) -> np.ndarray:
        a = f(tt)
        out = np.empty(nn + 1)
        out[:nn] = (a @ y[:nn].reshape(n, n)).ravel()
        out[nn] = np.trace(a)
        return out

    y0 = np.concatenate([np.eye(n).ravel(), [0.0]])
    sol = solve_ivp(rhs, (0.0, t_end), y0, method=method, rtol=rtol, atol=atol)
    if not sol.success:
        raise ConvergenceError(f"integration of the monodromy matrix failed: {sol.message}")
    X = sol.y[:nn, -1].reshape(n, n)
    s = float(sol.y[nn, -1])
    with np.errstate(over="ignore"):
        detX = np.linalg.det(X)
        err = float(abs(detX * np.exp(-s) - 1.0))
    if R is not None:
        try:
            XT = R @ np.linalg.solve(X, R @ X)
        except np.linalg.LinAlgError as exc:
            raise ConvergenceError("X(T/2) is numerically singular; use reversor=None") from exc
        trace_int = 0.0  # tr A is odd about t = 0 for a reversible system
    else:
        XT = X
        trace_int = s
    limit = max(1e-6, 1e4 * rtol)
    if not np.isfinite(err) or err > limit:
        raise ConvergenceError(
            f"Liouville check failed: |det X e^(-int tr A) - 1| = {err:.3g} > {limit:.1g}; "
            "tighten rtol/atol or use a stiff method",
            achieved=err,
        )
    return FloquetResult(
        monodromy=XT,
        period=T,
        unit_tol=float(unit_tol),
        liouville_error=err,
        trace_integral=trace_int,
        nfev=int(sol.nfev),
        reversor_used=R is not None,
        integration_rtol=float(rtol),
    )


@validated
def floquet_multipliers(A: Any, period: float, **kwargs: Any) -> np.ndarray:
    """Floquet multipliers of ``x' = A(t) x`` (shortcut for ``monodromy(...).floquet_multipliers``).

    Parameters
    ----------
    A : sympy.Matrix or callable
        ``n x n`` matrix in ``symosc.symbols.t`` and parameters, or a function ``A(t, *args) -> ndarray (n, n)``;
        it must be square and ``period``-periodic (as for :func:`monodromy`).
    period : float
        The period ``T > 0``.
    **kwargs
        Options of :func:`monodromy` (``args``, ``values``, ``rtol``, ``atol``, ``method``, ``reversor``,
        ``unit_tol``, ``check_periodic``).

    Returns
    -------
    ndarray
        The eigenvalues ``rho`` of ``X(T)``, by decreasing modulus.

    See Also
    --------
    monodromy
    stability_region

    Examples
    --------
    >>> import numpy as np
    >>> rho = floquet_multipliers(lambda t: np.array([[-1.0, 0.0], [0.0, -2.0]]), 1.0)
    >>> np.allclose(rho, [np.exp(-1), np.exp(-2)])
    True
    """
    return monodromy(A, period, **kwargs).floquet_multipliers
