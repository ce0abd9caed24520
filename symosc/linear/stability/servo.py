"""Equal degree of stability of the third-order servo and its optimum (Bulgakov (1954), §8.23–8.24).

For ``λ³ + k1 λ² + k2 λ + z`` (the servo (8.145)–(8.147) with ``V = 0``, ``z`` fixed) the set ``C_δ`` of
``(k1, k2)`` whose roots all lie in ``Re λ ≤ -δ`` is bounded by the line of the real root ``-δ``,
``δ² k1 - δ k2 - δ³ + z = 0``, and the hyperbola of a pair on ``Re λ = -δ``,
``k1(k2 - 2δ k1) + 8δ² k1 - 2δ k2 - 8δ³ - z = 0`` (the Hurwitz minor of the shifted polynomial), between the corners
``A = (3δ, 2δ² + z/δ)`` and ``B = (2δ + z/δ², δ² + 2z/δ)``.  It is not empty iff ``δ³ ≤ z``; the optimum
``δ = z^{1/3}`` is the triple root ``k1 = 3z^{1/3}``, ``k2 = 3z^{2/3}``, i.e. ``x_M = (3δ - 1)/δ³``,
``y_M = (3δ² - k)/δ³`` in the servo's parameters ``k1 = x z + 1``, ``k2 = y z + k``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError

__all__ = ["ServoOptimum", "ServoStabilityLines", "servo_optimum", "servo_stability_lines"]


def _positive(v, name: str) -> float:
    try:
        v = float(v)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a positive number") from exc
    if not (v > 0 and np.isfinite(v)):
        raise ParameterError(f"{name} must be positive and finite, got {v}")
    return v


@dataclass(frozen=True)
class ServoStabilityLines(SymPyPrintable):
    """Result of :func:`servo_stability_lines`: the boundary of ``C_δ`` in the ``(k1, k2)`` plane.

    Attributes
    ----------
    z, delta : float
        The constant term ``z`` and the degree of stability ``δ``.
    line : (ndarray, ndarray)
        The real-root line from ``A`` to ``B``.
    hyperbola : (ndarray, ndarray)
        The complex-pair hyperbola from ``A`` to ``B``.
    corner_a, corner_b : (float, float)
        The corners ``A = (3δ, 2δ² + z/δ)`` and ``B = (2δ + z/δ², δ² + 2z/δ)`` where line and hyperbola meet.
    """

    z: float
    delta: float
    line: tuple
    hyperbola: tuple
    corner_a: tuple[float, float]
    corner_b: tuple[float, float]

    def __repr__(self) -> str:
        return (
            f"ServoStabilityLines(z = {self.z:.6g}, δ = {self.delta:.6g}: A = {np.round(self.corner_a, 6).tolist()}, "
            f"B = {np.round(self.corner_b, 6).tolist()})"
        )

    def plot(self, *, ax=None):
        """Draw the boundary of ``C_δ`` and its corners; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        (ln,) = ax.plot(*self.line, label=f"δ = {self.delta:.4g}: real root -δ")
        ax.plot(*self.hyperbola, "--", color=ln.get_color(), label="pair on Re λ = -δ")
        ax.plot(*zip(self.corner_a, self.corner_b, strict=True), "o", color=ln.get_color())
        ax.set_xlabel("k1")
        ax.set_ylabel("k2")
        ax.legend(fontsize="small")
        return ax


@validated
def servo_stability_lines(z: float, delta: float, *, n_points: int = 100) -> ServoStabilityLines:
    """Boundary of the region of degree of stability ``≥ δ`` of ``λ³ + k1λ² + k2λ + z`` (Bulgakov (1954), §8.24).

    Parameters
    ----------
    z : float
        Constant term ``z`` of the characteristic polynomial; must be positive and finite.
    delta : float
        Required degree of stability ``δ``; must be positive with ``δ³ <= z`` (else the region is empty).
    n_points : int, optional
        Number of points on each boundary curve (an integer >= 2; default 100).

    Returns
    -------
    ServoStabilityLines

    Examples
    --------
    >>> from symosc.linear import servo_stability_lines
    >>> c = servo_stability_lines(8.0, 1.0, n_points=3)
    >>> c.corner_a, c.corner_b
    ((3.0, 10.0), (10.0, 17.0))

    See Also
    --------
    servo_optimum, max_stability_degree_cubic, d_partition
    """
    z, d = _positive(z, "z"), _positive(delta, "delta")
    if d**3 > z:
        raise ParameterError(f"δ³ = {d**3:.6g} > z = {z:.6g}: no (k1, k2) reaches this degree of stability")
    n = int(n_points)
    if n < 2:
        raise ParameterError("n_points must be at least 2")
    a = (3 * d, 2 * d * d + z / d)
    b = (2 * d + z / d**2, d * d + 2 * z / d)
    k1 = np.linspace(a[0], b[0], n)
    line = (k1, (d * d * k1 - d**3 + z) / d)
    hyp = (k1, (2 * d * k1**2 - 8 * d * d * k1 + 8 * d**3 + z) / (k1 - 2 * d))
    return ServoStabilityLines(z, d, line, hyp, a, b)


@dataclass(frozen=True)
class ServoOptimum(SymPyPrintable):
    """Result of :func:`servo_optimum`.

    Attributes
    ----------
    z : float
        The servo's constant term ``z``.
    k : float
        The servo's parameter ``k`` (in ``k2 = y z + k``).
    delta : float
        The largest degree of stability, ``z^{1/3}``.
    k1, k2 : float
        ``3δ`` and ``3δ²`` (triple root ``-δ``).
    x, y : float
        ``x_M = (3δ - 1)/δ³`` and ``y_M = (3δ² - k)/δ³`` of the servo (8.145)–(8.147).
    """

    z: float
    k: float
    delta: float
    k1: float
    k2: float
    x: float
    y: float


@validated
def servo_optimum(z: float, k: float = 0.0) -> ServoOptimum:
    """Best degree of stability of the servo ``λ³ + (xz + 1)λ² + (yz + k)λ + z`` (Bulgakov (1954), §8.24).

    Parameters
    ----------
    z : float
        Constant term ``z`` of the characteristic polynomial; must be positive and finite.
    k : float, optional
        The servo's parameter ``k`` in ``k2 = y z + k``; a finite number (default 0).

    Returns
    -------
    ServoOptimum

    Examples
    --------
    >>> from symosc.linear import servo_optimum
    >>> servo_optimum(8.0, k=1.0)
    ServoOptimum(z=8.0, k=1.0, delta=2.0, k1=6.0, k2=12.0, x=0.625, y=1.375)

    See Also
    --------
    servo_stability_lines, max_stability_degree_cubic
    """
    z = _positive(z, "z")
    k = float(k)
    d = z ** (1 / 3)
    return ServoOptimum(z, k, d, 3 * d, 3 * d * d, (3 * d - 1) / d**3, (3 * d * d - k) / d**3)
