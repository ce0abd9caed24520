"""Motor spin-up/brake inertia formula and the Huygens–Steiner transfer to the center of mass (Belyakov (2005), §3.12).

* :func:`motor_spin_up_brake` — the body sits on a motor shaft; the motor's work ``A1`` spinning it up from
  ``omega0`` to ``omega1`` and its work ``A2`` braking it back to ``omega0`` give
  ``I = (A1 - A2) / (omega1**2 - omega0**2) - J`` (Belyakov (2005), Ch. I §1, ref. [7]); the friction work, the same
  in both runs, cancels.
* :func:`central_gyration` — Huygens–Steiner ``rho_m**2 = rho**2 - r**2`` and how the relative errors of ``rho``
  and ``r`` are amplified when the rotation axis is far from the center of mass (Belyakov (2005), Ch. I §1).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ModelError, ParameterError
from .classical import InertiaFormula, _solve

__all__ = ["CentralGyration", "central_gyration", "motor_spin_up_brake"]


@validated
def motor_spin_up_brake() -> InertiaFormula:
    """Moment of inertia from the motor's work in a spin-up and a brake run (Belyakov (2005), §3.12).

    The body (moment of inertia ``I`` about the shaft) is mounted on a motor whose rotating parts have the reduced
    moment of inertia ``J``.  Spinning up from ``omega0`` to ``omega1`` the motor does the work ``A1``; braking from
    ``omega1`` back to ``omega0`` it does the work ``A2`` (negative: the motor absorbs energy).  The friction work
    ``W`` is assumed equal in both runs (the same speed profile, e.g. equal acceleration and deceleration under a
    constant friction moment).  Energy balances

        A1 = (I + J) (omega1**2 - omega0**2) / 2 + W,     A2 = -(I + J) (omega1**2 - omega0**2) / 2 + W

    give ``I = (A1 - A2) / (omega1**2 - omega0**2) - J``.

    Returns
    -------
    InertiaFormula
        Call it with values for ``A1, A2, omega0, omega1, J``.

    See Also
    --------
    flywheel : falling-weight flywheel, two runs eliminating a constant friction moment.
    central_gyration : transfer of a measured moment to the center of mass (Huygens–Steiner).

    Notes
    -----
    If the friction works differ (e.g. viscous friction with unequal speed profiles), the formula is biased by
    ``(W1 - W2) / (omega1**2 - omega0**2)``.

    Examples
    --------
    >>> f = motor_spin_up_brake()
    >>> f.expr
    -J + (A1 - A2)/(-omega0**2 + omega1**2)
    >>> float(f({"A1": 130.0, "A2": -70.0, "omega0": 0.0, "omega1": 10.0, "J": 0.5}))
    1.5
    """
    I, J, W = sp.symbols("I J W")
    A1, A2 = sp.symbols("A1 A2")
    w0, w1 = sp.symbols("omega0 omega1", nonnegative=True)
    half = (I + J) * (w1**2 - w0**2) / 2
    eqs = [sp.Eq(A1, half + W), sp.Eq(A2, -half + W)]
    expr = _solve(eqs, [I, W], I)
    form = (A1 - A2) / (w1**2 - w0**2) - J  # the book's arrangement; verified equal to the solution
    if sp.simplify(expr - form) != 0:  # pragma: no cover
        raise ModelError(f"derivation mismatch: {expr}")
    return InertiaFormula("motor_spin_up_brake", form, tuple(eqs))


@dataclass(frozen=True)
class CentralGyration(SymPyPrintable):
    """Radius of gyration about the parallel axis through the center of mass (Huygens–Steiner).

    Attributes
    ----------
    radius : float
        ``rho_m = sqrt(rho**2 - r**2)``.
    amplification : float
        ``(rho**2 + r**2) / (rho**2 - r**2)``: worst-case relative error of ``rho_m**2`` per unit relative error
        of ``rho`` and ``r`` (both ``delta``): ``|d(rho_m**2)| / rho_m**2 <= 2 * amplification * delta``.
    relative_error : float
        First-order worst-case relative error of ``radius`` for the given relative errors of ``rho`` and ``r``:
        ``(rho**2 delta_rho + r**2 delta_r) / (rho**2 - r**2)``.
    """

    radius: float
    amplification: float
    relative_error: float

    def __repr__(self) -> str:
        return (
            f"CentralGyration(radius={self.radius:.6g}, amplification={self.amplification:.3g}, "
            f"relative_error={self.relative_error:.3g})"
        )

    def _repr_latex_(self) -> str:
        return f"$\\rho_m = {self.radius:.6g}\\ (\\pm {100 * self.relative_error:.3g}\\,\\%)$"


@validated
def central_gyration(rho: float, r: float, *, rel_error_rho: float = 0.0, rel_error_r: float = 0.0) -> CentralGyration:
    """Radius of gyration about the center of mass from the one about a parallel axis (Belyakov (2005), §3.12).

    Huygens–Steiner: ``rho_m**2 = rho**2 - r**2``, with ``rho`` the radius of gyration about the rotation axis and
    ``r`` the distance from the center of mass to that axis.  For large ``r`` this is a difference of large
    numbers: the relative error of ``rho_m`` is ``(rho**2 delta_rho + r**2 delta_r) / (rho**2 - r**2)`` to first
    order, however small ``delta_rho`` and ``delta_r`` are — the reason rigs should rotate the body about axes
    passing near its center of mass.

    Parameters
    ----------
    rho : float
        Radius of gyration about the rotation axis (``rho**2 = I_axis / m``), > 0.
    r : float
        Distance from the center of mass to the rotation axis, ``0 <= r < rho``.
    rel_error_rho, rel_error_r : float, optional
        Relative measurement errors (bounds) of ``rho`` and ``r``.

    Returns
    -------
    CentralGyration

    Raises
    ------
    ParameterError
        Non-finite or negative input.
    ModelError
        ``r >= rho`` (no real radius of gyration: inconsistent measurements).

    See Also
    --------
    motor_spin_up_brake, symosc.identification.physical_pendulum

    Examples
    --------
    A body with ``rho_m = 0.1`` m swung about an axis 1 m away: 1 ppm errors in ``rho`` and ``r`` become ~200 ppm.

    >>> res = central_gyration(math.sqrt(1.01), 1.0, rel_error_rho=1e-6, rel_error_r=1e-6)
    >>> round(res.radius, 12), round(res.relative_error * 1e6, 3)
    (0.1, 201.0)
    """
    vals = {}
    for name, v in (("rho", rho), ("r", r), ("rel_error_rho", rel_error_rho), ("rel_error_r", rel_error_r)):
        try:
            x = float(v)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"{name} must be a real number, got {v!r}") from exc
        if not math.isfinite(x) or x < 0:
            raise ParameterError(f"{name} must be finite and non-negative, got {v!r}")
        vals[name] = x
    p, d = vals["rho"], vals["r"]
    if p == 0:
        raise ParameterError("rho must be positive")
    diff = (p - d) * (p + d)
    if diff <= 0:
        raise ModelError(
            f"r = {d} is not smaller than rho = {p}: the moment about the axis is less than m r**2, so the "
            "measurements are inconsistent"
        )
    rel = (p**2 * vals["rel_error_rho"] + d**2 * vals["rel_error_r"]) / diff
    return CentralGyration(radius=math.sqrt(diff), amplification=(p**2 + d**2) / diff, relative_error=rel)
