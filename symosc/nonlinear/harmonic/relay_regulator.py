"""Position regulator with a relay servomotor: boundary, cycles and their stability (Bulgakov (1954), §12.13).

Self-braking servomotor (``V = 0``, ``rho = 0``), scaled parameters ``alpha, beta, gamma, M`` of (12.174).  The model
(12.226)–(12.227) at constant load, in the dimensionless time ``tau``, is

    x'' + beta x' + x - y = 0,        x''' + M x'' + alpha x' + gamma H(y) = 0,

with the relay characteristic ``H`` acting on the regulator input ``y``.  With ``H(y)`` replaced by the secant ``h y``
the simplified equations have the characteristic polynomial

    Delta(E) = E**3 + (gamma h + M) E**2 + (beta gamma h + alpha) E + gamma h        (12.179), (12.188)

which has a pair ``+-i omega`` when ``Delta = (E + kappa)(E**2 + omega**2)``, i.e. for the two gains (12.190)

    h_{1,2} = (1 - alpha - M beta -+ R) / (2 beta gamma),   R**2 = (alpha - 1)**2 - 2 (alpha + 1) M beta + (M beta)**2

with ``omega**2 = (1 + alpha - M beta -+ R) / 2`` (12.192) and ``kappa = gamma h + M`` (12.193).  A cycle of amplitude
``b*`` at the regulator input needs ``h b* = J(b*)``, ``J(b) = (1/pi) Integral(H(b cos u) cos u, u, -pi, pi)``
(12.210)–(12.211): ``b* = 4 c / (pi h)`` for an ideal relay of level ``c``.

Stability (§12.13, 5°): the shortened equations for the amplitude ``a`` of the real mode and the amplitude ``b`` of
the oscillation have a diagonal Jacobian at ``(0, b*)`` (12.218)–(12.221); its trace ``-M - (gamma/2)(h + J'(b*))``
(12.222) is negative, so a cycle is stable iff the product of the two diagonal entries is positive (12.223).  The
boundary curves cut the plane ``xi = alpha``, ``eta = M beta`` (12.212) into the eleven regions of Table 14.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from ._relay_cycles import relay_amplitudes_and_slopes, shortened_jacobian, table14_region

__all__ = [
    "RelayCycle",
    "RelayRegulatorBoundary",
    "RelayRegulatorRegion",
    "relay_regulator_boundary",
    "relay_regulator_cycles",
    "relay_regulator_region",
]


@dataclass(frozen=True)
class RelayRegulatorBoundary(SymPyPrintable):
    """Secant gains ``h`` on the periodic boundary of the relay position regulator, with ``omega`` and ``kappa``.

    Attributes
    ----------
    gains : tuple of float
        The real positive roots ``h_1 <= h_2`` of ``beta gamma**2 h**2 + gamma (alpha + M beta - 1) h + M alpha = 0``.
    omegas : tuple of float
        Angular frequencies (dimensionless time) of the periodic solutions, one per gain.
    kappas : tuple of float
        The third root ``-kappa`` of ``Delta`` at each gain.
    """

    gains: tuple[float, ...]
    omegas: tuple[float, ...]
    kappas: tuple[float, ...]

    def relay_amplitudes(self, level: float = 1.0) -> tuple[float, ...]:
        """Ideal relay ``H = level * sign(y)``: ``b* = 4 level / (pi h)`` for each gain (12.210).

        Parameters
        ----------
        level : float, optional
            Output level of the relay ``H = level * sign(y)``; a positive number (default 1).
        """
        return tuple(4.0 * level / (math.pi * h) for h in self.gains)


@validated
def relay_regulator_boundary(alpha: float, beta: float, gamma: float, M: float) -> RelayRegulatorBoundary:
    """Gains, frequencies and real roots on the periodic boundary of the relay regulator (Bulgakov (1954), §12.13).

    Parameters
    ----------
    alpha, beta, gamma, M : float
        Scaled parameters of (12.174): finite, ``gamma > 0`` and ``beta != 0`` (a negative ``beta`` is allowed, as
        in the regions 5, 8 and 11 of Table 14).

    Returns
    -------
    RelayRegulatorBoundary
        Only gains that are real and positive and give ``omega**2 > 0`` are kept (possibly none), ascending.

    Raises
    ------
    ParameterError
        Non-finite input, ``gamma <= 0`` or ``beta == 0``.

    See Also
    --------
    relay_regulator_cycles : the amplitudes and stability of the cycles.
    symosc.nonlinear.harmonic_linearization : ``J(b)/b`` for other characteristics.
    poincare_operator_system : the first approximation for a general ``f(D)`` system.

    Examples
    --------
    >>> res = relay_regulator_boundary(alpha=0.2, beta=0.5, gamma=1.0, M=0.3)
    >>> [round(h, 6) for h in res.gains], [round(w, 6) for w in res.omegas]
    ([0.1, 1.2], [0.5, 0.894427])
    """
    vals = _finite_inputs(alpha=alpha, beta=beta, gamma=gamma, M=M)
    a, b, g, m = vals["alpha"], vals["beta"], vals["gamma"], vals["M"]
    if g <= 0:
        raise ParameterError(f"gamma must be positive (the relay's scaled gain, (12.174)), got gamma={g}")
    if b == 0:
        raise ParameterError("beta must be nonzero (the boundary (12.190) divides by beta), got beta=0")
    R2 = (a - 1) ** 2 - 2 * (a + 1) * m * b + (m * b) ** 2  # (12.191)
    if R2 < 0:
        return RelayRegulatorBoundary((), (), ())
    R = math.sqrt(R2)
    found = []
    for sgn in (-1.0, 1.0):
        h = (1 - a - m * b + sgn * R) / (2 * b * g)
        w2 = b * g * h + a
        if h > 0 and w2 > 0:
            found.append((h, math.sqrt(w2), g * h + m))
    if any(k <= 0 for _, _, k in found):  # pragma: no cover - kappa * omega^2 = gamma h > 0 forces kappa > 0
        raise ModelError("inconsistent boundary: kappa <= 0")
    found.sort()
    return RelayRegulatorBoundary(*(tuple(row[i] for row in found) for i in range(3)))


@dataclass(frozen=True)
class RelayCycle(SymPyPrintable):
    """One self-oscillation of the relay regulator in the first approximation (Bulgakov (1954), §12.13).

    Attributes
    ----------
    gain : float
        The boundary gain ``h`` (12.190) whose secant ``c = h b`` meets ``c = J(b)`` at the amplitude (Fig. 212).
    amplitude : float
        ``b*`` with ``J(b*) = h b*`` (12.210): amplitude of the regulator input ``y``.
    omega : float
        Angular frequency in the dimensionless time ``tau`` (12.192).
    kappa : float
        The real root ``-kappa`` of the simplified characteristic polynomial (12.193).
    slope : float
        ``J'(b*)``.
    jacobian : tuple of float
        The diagonal entries ``((dA/da)*, (dB/db)*)`` of the shortened equations' Jacobian (12.220)–(12.221).
    stable : bool
        Both entries negative; as the trace (12.222) is always negative, this is the product rule (12.223).
    """

    gain: float
    amplitude: float
    omega: float
    kappa: float
    slope: float
    jacobian: tuple[float, float]
    stable: bool

    def __repr__(self) -> str:
        kind = "stable" if self.stable else "unstable"
        return (
            f"RelayCycle({kind}: amplitude={self.amplitude:.6g}, omega={self.omega:.6g}, gain h={self.gain:.6g}, "
            f"jacobian=({self.jacobian[0]:.4g}, {self.jacobian[1]:.4g}))"
        )


@validated
def relay_regulator_cycles(
    alpha: float, beta: float, gamma: float, M: float, *, level: float = 1.0, dead_zone: float = 0.0
) -> tuple[RelayCycle, ...]:
    """Self-oscillations of the relay position regulator and their stability (Bulgakov (1954), §12.13, 3°–5°).

    The relay ``H(y) = level * sign(y)`` for ``|y| > dead_zone`` (zero inside) has the first harmonic
    ``J(b) = (4 level / pi) sqrt(1 - dead_zone**2 / b**2)``.  Each boundary gain ``h`` of (12.190) with
    ``0 < h < h* = 2 level / (pi dead_zone)`` gives two amplitudes ``b*`` (one for an ideal relay, ``dead_zone = 0``,
    where ``h* = inf``): the intersections of ``c = h b`` with ``c = J(b)`` (Fig. 212).  Each cycle's stability
    follows from the diagonal Jacobian of the shortened equations (12.218)–(12.223).

    Parameters
    ----------
    alpha, beta, gamma, M : float
        Scaled parameters of (12.174), as in :func:`relay_regulator_boundary`; ``M >= 0``.
    level : float
        Relay output level (``> 0``).
    dead_zone : float
        Half-width of the relay's dead zone (``>= 0``).

    Returns
    -------
    tuple of RelayCycle
        Ordered by amplitude; empty when no boundary gain lies in ``(0, h*)``.

    See Also
    --------
    relay_regulator_boundary : the gains ``h_1, h_2``.
    relay_regulator_region : the region of Table 14 that a parameter point lies in.

    Examples
    --------
    Region 9 of Table 14 (``alpha`` slightly negative, ``M beta > 1``): a small stable cycle and a larger unstable
    one, the case I of §12.13, 5°:

    >>> small, large = relay_regulator_cycles(-0.02, 1.5, 1.0, 1.0, level=0.1, dead_zone=1.0)
    >>> small
    RelayCycle(stable: amplitude=1.05112, omega=0.189665, gain h=0.0373153, jacobian=(-1.112, -0.0848))
    >>> large.stable, round(large.amplitude, 4)
    (False, 3.2462)

    Notes
    -----
    This is the book's first approximation.  A simulation of (12.226)–(12.227) confirms the stability of the
    cycles it was checked on (regions 7 and 9), and the amplitudes to a few per cent; but the relay acts on ``y``
    through a first-order path, so the motion can slide on the switching surfaces: the small cycle of region 9 is
    in fact a sliding relaxation oscillation whose period is several times ``2 pi / omega``.  It can also fail
    outright: in region 6 at ``alpha = 0.02``, ``beta = 0.7``, ``gamma = M = level = dead_zone = 1`` none of the
    four predicted cycles is seen, the simulated motion comes to rest in the dead zone from each of them.  Check a
    prediction by simulation before relying on it.
    """
    vals = _finite_inputs(alpha=alpha, beta=beta, gamma=gamma, M=M, level=level, dead_zone=dead_zone)
    _check_relay(vals)
    if vals["M"] < 0:
        raise ParameterError(f"M must be >= 0 (the object's scaled damping, (12.174)), got M={vals['M']}")
    boundary = relay_regulator_boundary(alpha, beta, gamma, M)
    cycles = []
    for h, w, k in zip(boundary.gains, boundary.omegas, boundary.kappas, strict=True):
        for b, slope in relay_amplitudes_and_slopes(h, vals["level"], vals["dead_zone"]):
            da, db = shortened_jacobian(h, w, k, vals["beta"], vals["gamma"], slope)
            cycles.append(RelayCycle(h, b, w, k, slope, (da, db), bool(da < 0 and db < 0)))
    return tuple(sorted(cycles, key=lambda c: c.amplitude))


@dataclass(frozen=True)
class RelayRegulatorRegion(SymPyPrintable):
    """The region of Table 14 (Bulgakov (1954), §12.13, 4°, Fig. 213) that a point ``(xi, eta)`` lies in.

    Attributes
    ----------
    number : int or None
        1..11 as in Fig. 213 and Table 14; ``None`` on a dividing curve (an axis, the parabola, the line or the
        tangent).
    behaviour : str
        ``"damped oscillations"`` (1–5), ``"steady oscillations"`` (6–9), ``"divergent oscillations"`` (10–11) or
        ``"boundary"``.
    xi, eta : float
        ``xi = alpha`` and ``eta = M beta`` (12.212).
    gains : tuple of float
        The real roots ``h`` of ``beta gamma**2 h**2 + gamma (xi + eta - 1) h + M xi`` (empty when complex).
    """

    number: int | None
    behaviour: str
    xi: float
    eta: float
    gains: tuple[float, ...]

    def __repr__(self) -> str:
        return f"RelayRegulatorRegion({self.number}: {self.behaviour}; xi={self.xi:.6g}, eta={self.eta:.6g})"


@validated
def relay_regulator_region(
    alpha: float, beta: float, gamma: float, M: float, *, level: float = 1.0, dead_zone: float = 0.0
) -> RelayRegulatorRegion:
    """Classify a parameter point into the eleven regions of Table 14 (Bulgakov (1954), §12.13, 4°, Fig. 213).

    The plane ``xi = alpha``, ``eta = M beta`` (12.212) is cut by the axes, the parabola ``R**2 = 0`` (12.213), the
    line ``xi + eta = 1`` (12.214) and the tangent (12.215) on which a root equals ``h* = max J(b)/b``
    (``2 level / (pi dead_zone)`` for a relay with a dead zone; infinite for an ideal relay, when the tangent is
    the ``xi`` axis and the regions 3 and 5 are empty).  Regions 1–5: no cycles, damped (``alpha > 0``); 6–9:
    steady oscillations (:func:`relay_regulator_cycles` gives their stability); 10–11: divergent (``alpha < 0``).

    Parameters
    ----------
    alpha, beta, gamma, M : float
        Scaled parameters of (12.174); ``gamma > 0`` and ``M > 0`` (Fig. 213 is drawn for fixed ``gamma, M``).
    level : float
        Relay output level (``> 0``).
    dead_zone : float
        Half-width of the relay's dead zone (``>= 0``).

    Returns
    -------
    RelayRegulatorRegion

    See Also
    --------
    relay_regulator_cycles
    relay_regulator_boundary

    Examples
    --------
    >>> region = relay_regulator_region(-0.02, 1.5, 1.0, 1.0, level=0.1, dead_zone=1.0)
    >>> region
    RelayRegulatorRegion(9: steady oscillations; xi=-0.02, eta=1.5)
    >>> relay_regulator_region(0.5, 0.4, 1.0, 1.0, dead_zone=0.1).number  # inside the parabola
    2
    """
    vals = _finite_inputs(alpha=alpha, beta=beta, gamma=gamma, M=M, level=level, dead_zone=dead_zone)
    _check_relay(vals)
    for name in ("gamma", "M"):
        if vals[name] <= 0:
            raise ParameterError(f"{name} must be positive for the (xi, eta) plane of Table 14, got {vals[name]}")
    h_star = math.inf if vals["dead_zone"] == 0 else 2 * vals["level"] / (math.pi * vals["dead_zone"])
    number, gains = table14_region(vals["alpha"], vals["beta"], vals["gamma"], vals["M"], h_star)
    behaviour = "boundary" if number is None else _BEHAVIOUR[number]
    return RelayRegulatorRegion(number, behaviour, vals["alpha"], vals["M"] * vals["beta"], gains)


_BEHAVIOUR = {
    **dict.fromkeys(range(1, 6), "damped oscillations"),
    **dict.fromkeys(range(6, 10), "steady oscillations"),
    **dict.fromkeys((10, 11), "divergent oscillations"),
}


def _check_relay(vals: dict[str, float]) -> None:
    if vals["level"] <= 0:
        raise ParameterError(f"level must be positive (the relay's output level), got level={vals['level']}")
    if vals["dead_zone"] < 0:
        raise ParameterError(
            f"dead_zone must be >= 0 (half-width of the relay's dead zone), got dead_zone={vals['dead_zone']}"
        )


def _finite_inputs(**given: float) -> dict[str, float]:
    out = {}
    for name, v in given.items():
        try:
            out[name] = float(v)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"{name} must be a finite real number, got {v!r}") from exc
        if isinstance(v, bool) or not math.isfinite(out[name]):
            raise ParameterError(f"{name} must be a finite real number, got {v!r}")
    return out
