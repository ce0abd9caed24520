"""The steam engine with a centrifugal governor (Bulgakov (1954), §7.5-7.7; Vyshnegradsky (1876)).

- :func:`stodola_time_constant`: ``T = -J / K'(omega*)`` of ``J omega' = K(omega) - L`` (eq. (7.39)).
- :func:`governor_statics`: the characteristic ``omega^2 = E(z) / A(z)`` and the stability index
  ``E'(z) - A'(z) omega^2 = A(z) d(omega^2)/dz`` (eqs. (7.44)-(7.45)).
- :func:`vyshnegradsky_cubic`: with the governor's inertia, ``U V^2 l^3 + U W l^2 + (U delta + N) l + 1``
  (eqs. (7.55)-(7.57)) and its Hurwitz condition ``U W (U delta + N) > U V^2``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError

__all__ = ["GovernorStatics", "governor_statics", "stodola_time_constant", "vyshnegradsky_cubic"]


@validated
def stodola_time_constant(J: Any, K: Any, omega: sp.Symbol, steady: Any | None = None) -> sp.Expr:
    """Stodola's time constant ``T = -J / K'(omega)`` at the steady speed (Bulgakov (1954), eq. (7.39)).

    Raises :class:`ModelError` when ``K'(omega*) = 0`` (no restoring torque).

    Parameters
    ----------
    J : number or SymPy expression
        Moment of inertia of the rotating parts, reduced to the shaft (positive).
    K : SymPy expression
        Driving torque minus resistance as a function ``K(omega)`` of the angular speed; ``K'`` must not vanish at the
        steady speed.
    omega : sympy.Symbol
        The angular-speed symbol in ``K``.
    steady : number or SymPy expression, optional
        The steady speed ``omega*`` at which ``K'`` is taken; the result stays a function of ``omega`` when omitted.

    Examples
    --------
    >>> import sympy as sp
    >>> J, K0, c, w = sp.symbols("J K0 c omega", positive=True)
    >>> stodola_time_constant(J, K0 - c * w, w)
    J/c

    See Also
    --------
    governor_statics, vyshnegradsky_cubic
    """
    dK = sp.sympify(K).diff(omega)
    if steady is not None:
        dK = dK.xreplace({omega: sp.sympify(steady)})
    if sp.simplify(dK) == 0:
        raise ModelError("K'(omega) = 0 at the steady speed: the engine has no self-regulation (T is infinite)")
    return sp.simplify(-sp.sympify(J) / dK)


@dataclass(frozen=True)
class GovernorStatics(SymPyPrintable):
    """``omega^2(z) = E(z)/A(z)`` and the stability index ``E' - A' omega^2`` (positive: stable).

    Attributes
    ----------
    speed_squared : SymPy expression
        The static characteristic ``omega^2 = E(z)/A(z)``.
    stability_index : SymPy expression
        ``E'(z) - A'(z) omega^2 = A(z) d(omega^2)/dz``, positive for a stable governor (eq. (7.45)).
    coordinate : sympy.Symbol
        The sleeve coordinate ``z``.

    See Also
    --------
    governor_statics"""

    speed_squared: sp.Expr
    stability_index: sp.Expr
    coordinate: sp.Symbol

    def __repr__(self) -> str:
        return f"GovernorStatics(omega^2 = {self.speed_squared})"


@validated
def governor_statics(E: Any, A: Any, z: sp.Symbol) -> GovernorStatics:
    """Static characteristic of a centrifugal governor with generalized force ``Q = -E(z) + A(z) omega^2``
    (Bulgakov (1954), §7.6, eqs. (7.40)-(7.45)).

    Parameters
    ----------
    E : SymPy expression
        The part ``E(z)`` of the generalized force that does not depend on the speed (weight, springs).
    A : SymPy expression
        The coefficient ``A(z)`` of ``omega^2`` in the centrifugal force, which must not vanish identically.
    z : sympy.Symbol
        The sleeve coordinate in ``E`` and ``A``.

    Examples
    --------
    >>> import sympy as sp
    >>> z, e0, e1, a0 = sp.symbols("z e0 e1 a0", positive=True)
    >>> st = governor_statics(e0 + e1 * z, a0, z)
    >>> st.speed_squared, st.stability_index
    ((e0 + e1*z)/a0, e1)

    See Also
    --------
    stodola_time_constant, vyshnegradsky_cubic
    """
    E, A = sp.sympify(E), sp.sympify(A)
    if sp.simplify(A) == 0:
        raise ModelError("A(z) = 0: the flyballs exert no centrifugal force")
    w2 = sp.simplify(E / A)
    return GovernorStatics(speed_squared=w2, stability_index=sp.simplify(E.diff(z) - A.diff(z) * w2), coordinate=z)


@validated
def vyshnegradsky_cubic(U: Any, V2: Any, W: Any, delta: Any, N: Any = 0, symbol: sp.Symbol | None = None):
    """Vyshnegradsky's characteristic polynomial and its Hurwitz stability condition (Bulgakov (1954), §7.7).

    Returns ``(polynomial, condition)``: ``U V^2 l^3 + U W l^2 + (U delta + N) l + 1`` and
    ``U W (U delta + N) - U V^2 > 0`` (with positive coefficients, the cubic's Hurwitz condition).

    Parameters
    ----------
    U, V2, W, delta : Expr or float
        Vyshnegradsky's parameters of the machine and the governor (positive numbers or symbols).
    N : Expr or float
        The added damping term of the governor (default 0).
    symbol : Symbol, optional
        The variable ``l`` of the polynomial.

    Examples
    --------
    >>> import sympy as sp
    >>> U, V2, W, d = sp.symbols("U V2 W delta", positive=True)
    >>> poly, cond = vyshnegradsky_cubic(U, V2, W, d)
    >>> cond
    U**2*W*delta - U*V2 > 0

    See Also
    --------
    variational_equations, governor_statics
    """
    lam = symbol if symbol is not None else sp.Symbol("lambda")
    U, V2, W, delta, N = (sp.sympify(x) for x in (U, V2, W, delta, N))
    poly = U * V2 * lam**3 + U * W * lam**2 + (U * delta + N) * lam + 1
    cond = sp.expand(U * W * (U * delta + N) - U * V2) > 0
    return poly, cond
