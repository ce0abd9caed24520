"""Cycles of the relay position regulator: amplitudes, shortened-equation Jacobian, Table 14 regions (private).

Bulgakov (1954), §12.13.  Modal form of the simplified equations ``Delta(E) x = -gamma (H(y) - h y)``,
``y = N(E) x`` with ``N(E) = E**2 + beta E + 1`` and ``Delta = (E + kappa)(E**2 + omega**2)``: the mode ``lambda`` of
``Delta`` carries ``N(lambda) / Delta'(lambda)`` of the forcing into ``y``.  With ``y = a + b cos u`` (``a`` the real
mode, ``b`` the oscillation) the averaged right-hand sides (12.207)–(12.209) give at ``(0, b*)``

    (dA/da)* = -kappa - (gamma/2) c1 (J'(b*) - h),     (dB/db)* = -gamma c2 (J'(b*) - h),

    c1 = N(-kappa) / Delta'(-kappa) = (kappa**2 - beta kappa + 1) / (kappa**2 + omega**2),
    c2 = Re N(i omega) / Delta'(i omega) = (omega**2 - 1 + beta kappa) / (2 (kappa**2 + omega**2)),

using ``(1/pi) Integral(H'(b cos u), u, -pi, pi) = J'(b) + h`` at ``J(b) = h b`` (12.220); ``c1 + 2 c2 = 1`` gives
the trace (12.222), and ``omega**2 - 1 + beta kappa = -+R`` recovers the book's form of (12.220).
"""

from __future__ import annotations

import math

__all__ = ["relay_amplitudes_and_slopes", "shortened_jacobian", "table14_region"]


def relay_amplitudes_and_slopes(h: float, level: float, dead_zone: float) -> list[tuple[float, float]]:
    """``[(b*, J'(b*)), ...]`` with ``J(b*) = h b*`` for a relay of ``level`` with a dead zone (12.210)–(12.211).

    ``J(b) = k0 sqrt(1 - d**2/b**2)``, ``k0 = 4 level / pi``; ``J(b) = h b`` gives ``b**4 - k**2 b**2 + k**2 d**2 = 0``
    with ``k = k0 / h``, two roots when ``k > 2 d`` (``h < h* = 2 level / (pi d)``), one (``b = k``) when ``d = 0``.
    """
    k0 = 4.0 * level / math.pi
    k = k0 / h
    d = dead_zone
    if d == 0:
        return [(k, 0.0)]
    disc = k**4 - 4 * k**2 * d**2
    if disc <= 0:
        return []
    out = []
    for b2 in ((k**2 - math.sqrt(disc)) / 2, (k**2 + math.sqrt(disc)) / 2):
        b = math.sqrt(b2)
        slope = k0 * d**2 / (b**2 * math.sqrt(b**2 - d**2))
        out.append((b, slope))
    return out


def shortened_jacobian(
    h: float, omega: float, kappa: float, beta: float, gamma: float, slope: float
) -> tuple[float, float]:
    """The diagonal ``((dA/da)*, (dB/db)*)`` of the shortened equations' Jacobian (12.218)–(12.221)."""
    denom = kappa**2 + omega**2
    c1 = (kappa**2 - beta * kappa + 1) / denom
    c2 = (omega**2 - 1 + beta * kappa) / (2 * denom)
    return -kappa - 0.5 * gamma * c1 * (slope - h), -gamma * c2 * (slope - h)


def _real_roots(e0: float, e1: float, e2: float) -> tuple[float, ...]:
    disc = e1 * e1 - 4 * e0 * e2
    if disc < 0:
        return ()
    r = math.sqrt(disc)
    q = -0.5 * (e1 + math.copysign(r, e1))  # stable quadratic formula
    roots = [q / e0, e2 / q] if q != 0 else [0.0, 0.0]
    return tuple(sorted(roots))


def table14_region(
    alpha: float, beta: float, gamma: float, M: float, h_star: float, *, rtol: float = 1e-12
) -> tuple[int | None, tuple[float, ...]]:
    """Region number of Table 14 (``None`` on a dividing curve) and the real roots ``h``.

    ``xi = alpha``, ``eta = M beta``; ``e0 = beta gamma**2``, ``e1 = gamma (xi + eta - 1)``, ``e2 = M xi`` (12.189).
    First quadrant: inside the parabola 2; beyond the line ``xi + eta = 1`` both roots are negative (1 on the ``eta``
    side, 4 on the ``xi`` side); below it ``0 < h1 < h2`` and the tangent (12.215) separates 6 (``h2 < h*``),
    7 (``h1 < h* < h2``) and 3 (``h* < h1``).  Second quadrant ``h1 < 0 < h2``: 9 (``h2 < h*``), 10.  Fourth quadrant
    one positive root: 8 (``< h*``), 5.  Third quadrant (both roots negative): 11.
    """
    xi, eta = alpha, M * beta
    tol = rtol * max(1.0, abs(xi), abs(eta))
    R2 = (eta - xi) ** 2 - 2 * (xi + eta) + 1  # (12.213)
    roots = _real_roots(beta * gamma**2, gamma * (xi + eta - 1), M * xi) if beta != 0 else ()
    if abs(xi) <= tol or abs(eta) <= tol or abs(R2) <= tol:
        return None, roots
    positive = [h for h in roots if h > 0]
    if any(abs(h - h_star) <= rtol * h_star for h in positive):
        return None, roots  # on the tangent (12.215)
    if xi > 0 and eta > 0:
        if R2 < 0:
            return 2, roots
        if abs(xi + eta - 1) <= tol:
            return None, roots
        if xi + eta > 1:
            return (1 if eta > xi else 4), roots
        below = sum(h < h_star for h in positive)
        return {2: 6, 1: 7, 0: 3}[below], roots
    if xi < 0 and eta > 0:
        return (9 if positive and positive[-1] < h_star else 10), roots
    if xi > 0 and eta < 0:
        return (8 if positive and positive[-1] < h_star else 5), roots
    return 11, roots
