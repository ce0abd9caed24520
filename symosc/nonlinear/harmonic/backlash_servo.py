"""Relay servo with backlash (Krautwig) by direct simulation of the piecewise ODE (Bulgakov (1954), §5.14).

Dimensionless model (5.167)–(5.174): motor velocity ``x`` and position ``y`` obey ``x' = -x + p``, ``y' = x``.  The
follower ``s`` (massless) is coupled to the motor through a backlash of total width ``z``: ``|y - s| <= z/2``, and
moves with the motor only when the motor pushes it.  The contact rollers ride on the follower: the voltage is ``-1``
for ``s > k/2``, ``+1`` for ``s < -k/2`` and ``0`` on the insulating gap ``|s| < k/2``.  Coulomb friction ``f``
acts on the follower (``variant="follower"``: felt by the motor only while it pushes) or on the motor
(``variant="motor"``).  So ``p`` = voltage ``- f sign(x)`` when friction acts, else the voltage.

A half-swing starts with the motor at rest, pressed against the follower at ``s = xi``, and ends when the motor stops
again at ``s = -eta``; self-oscillation needs ``eta = Phi(xi)`` to have a fixed point outside the gap.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError

__all__ = ["BacklashServoRun", "simulate_backlash_servo"]


@dataclass(frozen=True)
class BacklashServoRun(SymPyPrintable):
    """Result of :func:`simulate_backlash_servo`.

    Attributes
    ----------
    amplitudes : ndarray
        ``|s|`` of the follower at each stop of the motor (successive half-swing amplitudes, starting with ``xi0``).
    stopped : bool
        The motion ended: the motor stopped with the follower on the insulating gap, or still driven forward but
        held by the follower's friction (``f >= 1``).
    """

    amplitudes: np.ndarray
    stopped: bool

    def __repr__(self) -> str:
        last = ", ".join(f"{a:.6g}" for a in self.amplitudes[-3:])
        return (
            f"BacklashServoRun({self.amplitudes.size} stops, last [{last}], {'stopped' if self.stopped else 'running'})"
        )


def _advance(y: float, v: float, p: float, tau: float) -> tuple[float, float]:
    e = math.exp(-tau)
    return y + p * tau + (v - p) * (1 - e), p + (v - p) * e


def _first_event(y, v, p, funcs, tmax=60.0):
    """Earliest tau in (0, tmax] at which any g(y(tau), v(tau)) crosses zero (dense scan plus bisection)."""
    grid = np.concatenate([np.linspace(0, 1, 201)[1:], np.linspace(1, tmax, 600)[1:]])
    prev = 1e-13
    g_prev = [g(*_advance(y, v, p, prev)) for g in funcs]
    for tau in grid:
        g_now = [g(*_advance(y, v, p, tau)) for g in funcs]
        hits = [i for i, (a, b) in enumerate(zip(g_prev, g_now, strict=True)) if a * b <= 0 and a != b]
        if hits:
            best = None
            for i in hits:
                lo, hi = prev, tau
                for _ in range(80):
                    mid = 0.5 * (lo + hi)
                    if funcs[i](*_advance(y, v, p, mid)) * g_prev[i] > 0:
                        lo = mid
                    else:
                        hi = mid
                if best is None or hi < best[0]:
                    best = (hi, i)
            return best
        prev, g_prev = tau, g_now
    return None


@validated
def simulate_backlash_servo(
    z: float, k: float, f: float, xi0: float, *, variant: str = "follower", max_half_swings: int = 60
) -> BacklashServoRun:
    """Simulate the relay servo with backlash half-swing by half-swing (Bulgakov (1954), §5.14).

    Parameters
    ----------
    z : float
        Reduced backlash (total play), ``z > 0``.
    k : float
        Reduced width of the insulating gap, ``k >= 0``.
    f : float
        Reduced Coulomb friction, ``f >= 0`` (``f < 1`` for ``variant="motor"``).
    xi0 : float
        Initial amplitude: the follower at ``s = xi0 > k/2``, the motor at rest pressing it (``y = xi0 + z/2``).
    variant : {"follower", "motor"}
        Where the friction acts.
    max_half_swings : int
        Number of half-swings simulated at most.

    Returns
    -------
    BacklashServoRun

    See Also
    --------
    symosc.nonlinear.backlash_critical_gap : the critical gap ``k_c`` (5.186), (5.189).
    implicit_map_cycle : stationary amplitudes of a point map and their stability (§5.12).

    Examples
    --------
    >>> run = simulate_backlash_servo(1.0, 0.2, 0.3, 1.0)
    >>> run.stopped, round(float(run.amplitudes[-1]), 3) > 0.1
    (False, True)
    """
    for name, val in (("z", z), ("k", k), ("f", f), ("xi0", xi0)):
        if not isinstance(val, int | float) or not math.isfinite(val) or val < 0:
            raise ParameterError(f"{name} must be a non-negative finite number, got {val!r}")
    if z <= 0:
        raise ParameterError("z must be positive (no backlash: no self-oscillation, see (5.186))")
    if variant not in ("follower", "motor"):
        raise ParameterError(f"variant must be 'follower' or 'motor', got {variant!r}")
    if variant == "motor" and f >= 1:
        raise ParameterError("with friction on the motor f must be < 1 (the motor cannot start otherwise)")
    if xi0 <= k / 2:
        raise ParameterError(f"xi0 must exceed k/2 = {k / 2} (the rollers must be on a lamella)")
    if not isinstance(max_half_swings, int) or max_half_swings < 1:
        raise ParameterError(f"max_half_swings must be a positive integer, got {max_half_swings!r}")

    def voltage(s: float) -> float:
        return -1.0 if s > k / 2 else (1.0 if s < -k / 2 else 0.0)

    s, y, v = xi0, xi0 + z / 2, 0.0
    amps = [xi0]
    for _ in range(max_half_swings):
        d = -1.0 if s > 0 else 1.0  # direction of this half-swing
        # free run across the backlash (voltage fixed by the resting follower)
        p = voltage(s) - (f * d if variant == "motor" else 0.0)
        ev = _first_event(y, v, p, [lambda yy, vv, s=s, d=d: (yy - s) - d * z / 2])
        if ev is None:  # pragma: no cover - the voltage always drives the motor across the play
            return BacklashServoRun(np.array(amps), True)
        y, v = _advance(y, v, p, ev[0])
        # engaged: follower s = y - d z/2, pieces with constant voltage until the motor stops
        while True:
            sv = (y - d * z / 2) + d * 1e-12
            p = voltage(sv) - f * d
            funcs = [lambda yy, vv: vv]
            for edge in (k / 2, -k / 2):
                funcs.append(lambda yy, vv, edge=edge, d=d: (yy - d * z / 2) - edge)
            ev = _first_event(y, v, p, funcs)
            if ev is None:  # pragma: no cover
                return BacklashServoRun(np.array(amps), True)
            y, v = _advance(y, v, p, ev[0])
            if ev[1] == 0:
                break
        s = y - d * z / 2
        v = 0.0
        amps.append(abs(s))
        if abs(s) <= k / 2 or voltage(s) * d > 0:
            # on the gap, or still driven forward but held by friction (f >= 1): the motion ends
            return BacklashServoRun(np.array(amps), True)
    return BacklashServoRun(np.array(amps), False)
