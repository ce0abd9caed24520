"""Position regulator with a relay servomotor: periodic boundary and cycle amplitudes (Bulgakov (1954), §12.13).

Self-braking servomotor (``V = 0``, ``rho = 0``), scaled parameters ``alpha, beta, gamma, M`` of (12.174).  With the
relay characteristic ``H(y)`` replaced by the secant ``h y`` the simplified equations have the characteristic
polynomial

    Delta(E) = E**3 + (gamma h + M) E**2 + (beta gamma h + alpha) E + gamma h        (12.179), (12.188)

which has a pair ``+-i omega`` when ``Delta = (E + kappa)(E**2 + omega**2)``, i.e. for the two gains (12.190)

    h_{1,2} = (1 - alpha - M beta -+ R) / (2 beta gamma),   R**2 = (alpha - 1)**2 - 2 (alpha + 1) M beta + (M beta)**2

with ``omega**2 = (1 + alpha - M beta -+ R) / 2`` (12.192) and ``kappa = gamma h + M`` (12.193).  A cycle of amplitude
``b*`` at the regulator input needs ``h b* = J(b*)``, ``J(b) = (1/pi) Integral(H(b cos u) cos u, u, -pi, pi)``
(12.210)–(12.211): ``b* = 4 c / (pi h)`` for an ideal relay of level ``c``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import ModelError, ParameterError

__all__ = ["RelayRegulatorBoundary", "relay_regulator_boundary"]


@dataclass(frozen=True)
class RelayRegulatorBoundary:
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
        """Ideal relay ``H = level * sign(y)``: ``b* = 4 level / (pi h)`` for each gain (12.210)."""
        return tuple(4.0 * level / (math.pi * h) for h in self.gains)


def relay_regulator_boundary(alpha: float, beta: float, gamma: float, M: float) -> RelayRegulatorBoundary:
    """Gains, frequencies and real roots on the periodic boundary of the relay regulator (Bulgakov (1954), §12.13).

    Parameters
    ----------
    alpha, beta, gamma, M : float
        Scaled parameters of (12.174) (``beta, gamma > 0``).

    Returns
    -------
    RelayRegulatorBoundary
        Only gains that are real and positive and give ``omega**2 > 0`` are kept (possibly none).

    Raises
    ------
    ParameterError
        Non-finite input or ``beta * gamma <= 0``.

    See Also
    --------
    symosc.nonlinear.harmonic_linearization : ``J(b)/b`` for other characteristics.
    poincare_operator_system : the first approximation for a general ``f(D)`` system.

    Examples
    --------
    >>> res = relay_regulator_boundary(alpha=0.2, beta=0.5, gamma=1.0, M=0.3)
    >>> [round(h, 6) for h in res.gains], [round(w, 6) for w in res.omegas]
    ([0.1, 1.2], [0.5, 0.894427])
    """
    vals = {}
    for name, v in (("alpha", alpha), ("beta", beta), ("gamma", gamma), ("M", M)):
        try:
            vals[name] = float(v)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"{name} must be a real number, got {v!r}") from exc
        if not math.isfinite(vals[name]):
            raise ParameterError(f"{name} must be finite, got {v!r}")
    a, b, g, m = vals["alpha"], vals["beta"], vals["gamma"], vals["M"]
    if b * g <= 0:
        raise ParameterError(f"beta * gamma must be positive, got beta={b}, gamma={g}")
    R2 = (a - 1) ** 2 - 2 * (a + 1) * m * b + (m * b) ** 2  # (12.191)
    if R2 < 0:
        return RelayRegulatorBoundary((), (), ())
    R = math.sqrt(R2)
    gains, omegas, kappas = [], [], []
    for sgn in (-1.0, 1.0):
        h = (1 - a - m * b + sgn * R) / (2 * b * g)
        w2 = b * g * h + a
        if h > 0 and w2 > 0:
            gains.append(h)
            omegas.append(math.sqrt(w2))
            kappas.append(g * h + m)
    if any(k <= 0 for k in kappas):  # pragma: no cover - kappa * omega^2 = gamma h > 0 forces kappa > 0
        raise ModelError("inconsistent boundary: kappa <= 0")
    return RelayRegulatorBoundary(tuple(gains), tuple(omegas), tuple(kappas))
