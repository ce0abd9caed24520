"""Linearization at a design amplitude and the shortened equations (Bulgakov (1954), §5.26–5.27).

For ``q'' + f(q, q') = 0`` the comparison system ``q'' + 2 eps q' + (omega**2 + eps**2)(q - q*) = 0`` is chosen so that
the first Fourier harmonics of ``f(q* + a cos u, -a (omega sin u + eps cos u))`` match it at the design amplitude
``a = a*`` (5.333)–(5.334):

    Integral(f, u) = 0,   2 eps = -(1/(pi a* omega)) Integral(f sin u, u),
    omega**2 - eps**2 = (1/(pi a*)) Integral(f cos u, u)

(integrals over one period), i.e. ``eps = Phi(a*)``, ``omega = Psi(a*)`` (5.335), with the instantaneous damping and
frequency of the shortened equations (5.330)

    a' = -a Phi(a),   u' = Psi(a),
    Phi = -(1/(2 pi omega a)) Integral(f sin u, u),
    Psi = (omega**2 + eps**2)/(2 omega) + (1/(2 pi omega a)) Integral(f cos u, u).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import check_positive, validated
from ...errors import ConvergenceError, ParameterError

__all__ = ["DesignLinearization", "design_amplitude_linearization"]

_N = 512


def _harmonics(f: Callable, q_star: float, a: float, omega: float, eps: float) -> tuple[float, float, float]:
    u = 2 * np.pi * np.arange(_N) / _N
    vals = np.broadcast_to(
        np.asarray(f(q_star + a * np.cos(u), -a * (omega * np.sin(u) + eps * np.cos(u))), dtype=float), u.shape
    )
    w = 2 * np.pi / _N
    return float(vals.sum() * w), float((vals * np.sin(u)).sum() * w), float((vals * np.cos(u)).sum() * w)


class _ExpressionForce:
    """``f(q, v)`` given as a SymPy expression: picklable (the compiled NumPy function is rebuilt after loading)."""

    def __init__(self, expr: Any, q: Any, v: Any) -> None:
        self.expr, self.q, self.v = expr, q, v
        self._fn: Callable[..., Any] | None = None

    def __call__(self, q: Any, v: Any) -> Any:
        if self._fn is None:
            import sympy as sp

            self._fn = sp.lambdify((self.q, self.v), self.expr, "numpy")
        return self._fn(q, v)

    def __getstate__(self) -> dict[str, Any]:
        return {"expr": self.expr, "q": self.q, "v": self.v, "_fn": None}

    def __repr__(self) -> str:
        return f"f({self.q}, {self.v}) = {self.expr}"


def _as_force(f: Any, variables: Any) -> Callable[..., Any]:
    import sympy as sp

    if not isinstance(f, sp.Basic):
        if not callable(f):
            raise ParameterError(f"f must be a callable f(q, v) or a SymPy expression, got {type(f).__name__}")
        return f
    if variables is None:
        names = {s.name: s for s in f.free_symbols}
        extra = set(names) - {"q", "v"}
        if extra:
            raise ParameterError(
                f"f has symbols {sorted(extra)} besides q and v: pass variables=(q, v) naming the coordinate and "
                "the velocity (and substitute numbers for the parameters)"
            )
        variables = (names.get("q", sp.Symbol("q")), names.get("v", sp.Symbol("v")))
    try:
        q, v = variables
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"variables must be a pair (q, v) of SymPy symbols, got {variables!r}") from exc
    extra = f.free_symbols - {q, v}
    if extra:
        raise ParameterError(f"f has free symbols {sorted(map(str, extra))} besides {q}, {v}: substitute numbers")
    return _ExpressionForce(f, q, v)


@dataclass(frozen=True)
class DesignLinearization(SymPyPrintable):
    """The linear comparison system chosen at the design amplitude (Bulgakov (1954), §5.27).

    Attributes
    ----------
    a_star : float
        Design amplitude.
    q_star : float
        Centre of the oscillation (5.333).
    eps, omega : float
        Damping and frequency of the comparison system: roots ``-eps +- i omega``.
    f : callable
        The force ``f(q, v)``.

    Notes
    -----
    The instance keeps ``f`` to evaluate :meth:`damping` and :meth:`frequency`, so it pickles exactly when ``f``
    does: a SymPy expression or a module-level function (or a picklable callable object) works, a lambda or a
    closure does not.
    """

    a_star: float
    q_star: float
    eps: float
    omega: float
    f: Callable[..., Any] = field(repr=False, compare=False)  # the user's force (picklable if it is)

    def __repr__(self) -> str:
        return (
            f"DesignLinearization(a*={self.a_star:.6g}: q*={self.q_star:.6g}, eps={self.eps:.6g}, "
            f"omega={self.omega:.6g})"
        )

    def damping(self, a: float) -> float:
        """Instantaneous damping ``Phi(a)`` of the shortened equations (5.330): ``a' = -a Phi(a)``.

        Parameters
        ----------
        a : float
            Amplitude of the oscillation about the centre ``q*``; a positive number.
        """
        _, s, _ = _harmonics(self.f, self.q_star, a, self.omega, self.eps)
        return -s / (2 * np.pi * self.omega * a)

    def frequency(self, a: float) -> float:
        """Instantaneous frequency ``Psi(a)`` of the shortened equations (5.330): ``u' = Psi(a)``.

        Parameters
        ----------
        a : float
            Amplitude of the oscillation about the centre ``q*``; a positive number.
        """
        _, _, c = _harmonics(self.f, self.q_star, a, self.omega, self.eps)
        return (self.omega**2 + self.eps**2) / (2 * self.omega) + c / (2 * np.pi * self.omega * a)


@validated
def design_amplitude_linearization(
    f: Callable[..., Any] | Any,
    a_star: float,
    *,
    omega0: float = 1.0,
    tol: float = 1e-12,
    variables: Any = None,
) -> DesignLinearization:
    """Linear comparison system of ``q'' + f(q, q') = 0`` at the design amplitude ``a*`` (Bulgakov (1954), §5.27).

    Parameters
    ----------
    f : callable or SymPy expression
        ``f(q, v)`` (vectorized over NumPy arrays), the force per unit mass; ``q`` the coordinate, ``v = q'``.
        A SymPy expression in ``q`` and ``v`` is evaluated through NumPy and keeps the result picklable; a callable
        should be defined at module level (not as a lambda) if the result is to be pickled.
    a_star : float
        Design amplitude ``a* > 0``.
    omega0 : float
        Starting guess for ``omega``.
    tol : float
        Tolerance on the residuals of (5.333)–(5.334).
    variables : pair of Symbol, optional
        ``(q, v)`` when ``f`` is a SymPy expression in other symbols than ``q`` and ``v``.

    Returns
    -------
    DesignLinearization
        ``q*``, ``eps``, ``omega`` and the shortened equations' ``Phi(a)``, ``Psi(a)``.

    Raises
    ------
    ConvergenceError
        If the three conditions cannot be met (e.g. no oscillatory comparison system, ``omega**2 <= 0``).

    See Also
    --------
    symosc.nonlinear.averaged_equations : symbolic shortened equations of one oscillator.
    symosc.nonlinear.harmonic_linearization : ``J(A)/A`` for a single nonlinearity.

    Examples
    --------
    The arctan spring ``q'' + arctan(q) = 0`` (Bulgakov (1954), §5.29): ``omega**2 = 2 (sqrt(1 + a**2) - 1) / a**2``.

    >>> import numpy as np
    >>> lin = design_amplitude_linearization(lambda q, v: np.arctan(q), 2.0)
    >>> round(lin.omega, 12), round(float(np.sqrt(2 * (np.sqrt(5) - 1) / 4)), 12), abs(lin.eps) < 1e-12
    (0.786151377757, 0.786151377757, True)

    The same force as a SymPy expression (then the result can be pickled):

    >>> import pickle
    >>> import sympy as sp
    >>> q = sp.Symbol("q")
    >>> symbolic = design_amplitude_linearization(sp.atan(q), 2.0)
    >>> round(pickle.loads(pickle.dumps(symbolic)).frequency(2.0), 12) == round(symbolic.frequency(2.0), 12)
    True
    """
    from scipy.optimize import fsolve

    try:
        a = float(a_star)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"a_star must be a positive number, got {a_star!r}") from exc
    if not np.isfinite(a) or a <= 0:
        raise ParameterError(f"a_star must be a positive finite number, got {a_star!r}")
    omega0 = check_positive("omega0 (the starting guess for the frequency)", omega0)
    f = _as_force(f, variables)

    def residual(x: np.ndarray) -> np.ndarray:
        q_star, eps, omega = x
        i0, s, c = _harmonics(f, q_star, a, omega, eps)
        return np.array(
            [
                i0 / (2 * np.pi),
                2 * eps + s / (np.pi * a * omega),
                omega**2 - eps**2 - c / (np.pi * a),
            ]
        )

    x, _info, ier, msg = fsolve(residual, [0.0, 0.0, float(omega0)], full_output=True, xtol=1e-14)
    res = float(np.max(np.abs(residual(x))))
    if (ier != 1 and res > tol) or res > tol * max(1.0, abs(x[2]) ** 2) or not np.all(np.isfinite(x)) or x[2] == 0:
        raise ConvergenceError(
            f"no linear comparison system at a* = {a}: residual {res:.3g} ({msg.strip()})", achieved=res
        )
    q_star, eps, omega = (float(v) for v in x)
    return DesignLinearization(a_star=a, q_star=q_star, eps=eps, omega=abs(omega), f=f)
