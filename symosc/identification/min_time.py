"""Minimum time to excite oscillations with a bounded control (Belyakov 2005, Ch. II §4).

One degree of freedom ``x1'' + omega**2 x1 = u_bar / m``, ``|u_bar| <= u_bar_max``.  In the scaled phase plane
``x = (x1, x1' / omega)`` with ``u = u_bar / (m omega**2)`` (bound ``u_m``) the motion under constant ``u`` is a
clockwise rotation about ``(u, 0)`` at rate ``omega``; the target is the circle ``|x| = a`` (an energy level).

* :func:`min_time_1dof` — the exact minimum time to reach the circle from any state (from inside or outside),
  computed from the support function of the reachable set (the maximum principle's bang-bang structure:
  ``u = u_m sign(sin(omega (T - t) + alpha))``, switches every half period);
* :func:`quasi_optimal_control` and :func:`simulate_quasi_optimal` — the quasi-optimal feedback (eq. 75): push in
  the direction of the velocity inside the circle, brake outside, simulated exactly arc by arc;
* :func:`excitation_time` — ``T = pi a m omega / (2 u_bar_max)`` (eq. 76), the time from rest at large ``a/u_m``,
  and :func:`sine_forcing_time` — resonant sine forcing, ``4/pi`` times slower;
* :func:`excitation_time_bound` — the multi-DOF lower bound (eq. 84)
  ``T_min >= max_i pi a_i omega_i / (2 sum_j |B'_ij| U_j)`` in normal coordinates.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._plotting import new_axes, plot_method
from .._printing import SymPyPrintable
from .._validate import check_finite, check_finite_array, check_memory, validated
from ..errors import ConvergenceError, ModelError, ParameterError

__all__ = [
    "ExcitationBound",
    "MinTimeResult",
    "QuasiOptimalRun",
    "excitation_time",
    "excitation_time_bound",
    "min_time_1dof",
    "quasi_optimal_control",
    "simulate_quasi_optimal",
    "sine_forcing_time",
    "switching_curves",
]


def _positive(name: str, value: Any) -> float:
    v = check_finite(name, value)
    if not v > 0:
        raise ParameterError(f"{name} must be positive and finite, got {value!r}")
    return v


@validated
def excitation_time(amplitude: float, omega: float, force_max: float, mass: float = 1.0) -> float:
    """Time ``pi a m omega / (2 u_bar_max)`` to pump a 1-DOF oscillator from rest to amplitude ``a`` (eq. 76).

    The bang-bang law adds ``4 u_m`` to the amplitude per period; the minimum time differs from this by
    ``O(u_m / a) / omega``.

    Parameters
    ----------
    amplitude : float
        Target amplitude ``a`` of the displacement (same length unit as the force over stiffness); must be positive
        and finite.
    omega : float
        Natural frequency (rad/s); must be positive and finite.
    force_max : float
        Bound ``u_bar_max`` on the force (N); must be positive and finite.
    mass : float, optional
        Mass ``m`` of the oscillator (kg); must be positive and finite (default 1: ``force_max`` is then a force per
        unit mass).

    Returns
    -------
    float
        The time (s).

    Examples
    --------
    >>> round(excitation_time(2e-3, 2 * (7.4e5 / 15000) ** 0.5, 20.0, 15000.0), 4)  # stand, vertical mode
    33.0987
    """
    a, w, u, m = (_positive(n, v) for n, v in zip(("amplitude", "omega", "force_max", "mass"),
                                                   (amplitude, omega, force_max, mass), strict=True))  # fmt: skip
    return np.pi * a * m * w / (2 * u)


@validated
def sine_forcing_time(amplitude: float, omega: float, force_max: float, mass: float = 1.0) -> float:
    """Time ``2 a m omega / u_bar_max`` for resonant forcing ``u_bar_max sin(omega t)`` from rest (eq. 78).

    Parameters
    ----------
    amplitude : float
        Target amplitude ``a`` of the displacement (same length unit as the force over stiffness); must be positive
        and finite.
    omega : float
        Natural frequency (rad/s); must be positive and finite.
    force_max : float
        Bound ``u_bar_max`` on the force (N); must be positive and finite.
    mass : float, optional
        Mass ``m`` of the oscillator (kg); must be positive and finite (default 1: ``force_max`` is then a force per
        unit mass).

    Returns
    -------
    float
        The time (s).

    Examples
    --------
    >>> round(sine_forcing_time(1, 1, 1) / excitation_time(1, 1, 1), 5)
    1.27324
    """
    a, w, u, m = (_positive(n, v) for n, v in zip(("amplitude", "omega", "force_max", "mass"),
                                                   (amplitude, omega, force_max, mass), strict=True))  # fmt: skip
    return 2 * a * m * w / u


# ---------------------------------------------------------------------------------------------------- exact 1-DOF
def _abs_sin_integral(x: np.ndarray) -> np.ndarray:
    """F(x) = int_0^x |sin s| ds for x >= 0."""
    k = np.floor(x / np.pi)
    return 2 * k + 1 - np.cos(x - k * np.pi)


def _support(alpha: np.ndarray, T: float, x0: np.ndarray, u_m: float, omega: float) -> np.ndarray:
    """Support function h(alpha) of the reachable set at time T (scaled coordinates)."""
    th = omega * T
    rot = np.array([[np.cos(th), np.sin(th)], [-np.sin(th), np.cos(th)]])  # clockwise rotation
    xf = rot @ x0
    a0 = np.mod(alpha, 2 * np.pi)
    return np.cos(a0) * xf[0] + np.sin(a0) * xf[1] + u_m * (_abs_sin_integral(a0 + th) - _abs_sin_integral(a0))


def _extreme(T: float, x0: np.ndarray, u_m: float, omega: float, sign: float) -> tuple[float, float]:
    """max over alpha of sign*h(alpha): returns (value, alpha)."""
    grid = np.linspace(0, 2 * np.pi, 721)
    vals = sign * _support(grid, T, x0, u_m, omega)
    i = int(np.argmax(vals))
    import scipy.optimize

    res = scipy.optimize.minimize_scalar(
        lambda a: -sign * float(_support(np.array(a), T, x0, u_m, omega)),
        bounds=(grid[max(i - 1, 0)], grid[min(i + 1, 720)]),
        method="bounded",
        options={"xatol": 1e-12},
    )
    best = -res.fun
    return (best, float(res.x)) if best > vals[i] else (float(vals[i]), float(grid[i]))


@dataclass(frozen=True)
class MinTimeResult(SymPyPrintable):
    """Minimum time to reach the circle ``|x| = a`` (scaled phase plane) and the optimal open-loop control.

    ``control(t)`` returns ``u_m sign(sin(omega (time - t) + alpha))`` (scaled control), the bang-bang law of the
    maximum principle; ``switching_times`` are its sign changes in ``(0, time)``.

    Attributes
    ----------
    time : float
        Minimum time to reach the circle (s when ``omega`` is in rad/s); 0 when the start lies on it.
    alpha : float
        Phase (rad) of the optimal bang-bang law ``u_m sign(sin(omega (time - t) + alpha))``.
    inside : bool
        Whether the initial state lies inside the circle (the motion pumps energy in rather than out).
    u_m : float
        Scaled control bound ``u_bar_max / (m omega**2)`` (units of ``x1``).
    omega : float
        Natural frequency (rad/s).
    switching_times : ndarray
        Times in ``(0, time)`` at which the optimal control changes sign, ascending.
    """

    time: float
    alpha: float
    inside: bool
    u_m: float
    omega: float
    switching_times: np.ndarray = field(repr=False)

    def control(self, t: Any) -> np.ndarray:
        """Optimal scaled control at times ``t`` in ``[0, time]``.

        Parameters
        ----------
        t : float or array_like
            Time(s) at which to evaluate the control; finite, meaningful in ``[0, time]``.
        """
        s = np.sin(self.omega * (self.time - np.asarray(t, dtype=float)) + self.alpha)
        return self.u_m * np.where(s >= 0, 1.0, -1.0)


@validated
def min_time_1dof(
    x0: Sequence[float], a: float, u_m: float, omega: float = 1.0, *, tol: float = 1e-10
) -> MinTimeResult:
    """Exact minimum time to bring the scaled 1-DOF oscillator from ``x0`` to the circle ``|x| = a``.

    Scaled coordinates: ``x = (x1, x1'/omega)``, scaled control bound ``u_m = u_bar_max / (m omega**2)``.  From
    inside the circle the time is the first ``T`` at which the reachable set touches the circle from inside
    (``max_alpha h(alpha, T) = a``, ``h`` its support function); from outside the first ``T`` at which its
    distance from the origin falls to ``a``.

    Parameters
    ----------
    x0 : (x1, x2)
        Initial scaled state ``(x1, x1'/omega)``: a pair of finite numbers.
    a, u_m, omega : float
        Target amplitude, control bound (both in units of ``x1``) and natural frequency; all positive and finite.
    tol : float
        Absolute tolerance on the time (> 0).

    Returns
    -------
    MinTimeResult

    Examples
    --------
    From rest with ``a = 4 u_m`` (one full period of pumping, eq. 76):

    >>> res = min_time_1dof((0.0, 0.0), 4.0, 1.0)
    >>> round(res.time / (2 * 3.141592653589793), 9)
    1.0
    """
    x0 = np.asarray(x0, dtype=float)
    a, u_m, omega = _positive("a", a), _positive("u_m", u_m), _positive("omega", omega)
    if x0.shape != (2,) or not np.all(np.isfinite(x0)):
        raise ParameterError(f"x0 must be a finite pair (x1, x2), got {x0!r}")
    r0 = float(np.hypot(*x0))
    # the optimal control switches once per half period and |x| changes by at most 2 u_m per half period
    switches = abs(r0 - a) / (2 * u_m) + 2
    check_memory(
        f"min_time_1dof(): the optimal control with about {switches:.3g} switches (|x0| - a = {r0 - a:.3g} with "
        f"u_m = {u_m:.3g})",
        40.0 * switches,
        "u_m must not be so small against the distance |x0| - a (excitation_time gives the time from rest in closed "
        "form)",
    )
    if abs(r0 - a) <= tol * max(a, 1.0):
        return MinTimeResult(0.0, 0.0, r0 <= a, u_m, omega, np.empty(0))
    inside = r0 < a
    sign = 1.0 if inside else -1.0

    def gap(T: float) -> float:
        val, _ = _extreme(T, x0, u_m, omega, sign)
        return val - a if inside else a - val  # >= 0 once the circle is reachable

    half = np.pi / omega
    # |x| changes by at most 2 u_m per half period (plus one partial arc): a safe lower bound to start from
    lo = max(0.0, half * (abs(r0 - a) / (2 * u_m) - 1.0) * (1 - 1e-12))
    T_hi = lo + half / 8
    n_max = 8 * 8 + 64
    for _ in range(n_max):
        if gap(T_hi) >= 0:
            break
        lo, T_hi = T_hi, T_hi + half / 8
    else:  # pragma: no cover - defensive
        raise ConvergenceError("min_time_1dof: target not reached; check a and u_m", achieved=T_hi)
    import scipy.optimize

    T = scipy.optimize.brentq(gap, lo, T_hi, xtol=tol) if lo > 0 or gap(lo) < 0 else 0.0
    _, alpha = _extreme(T, x0, u_m, omega, sign)
    # switches where sin(omega (T - t) + alpha) changes sign
    ks = np.arange(np.ceil(alpha / np.pi - 1e-12), np.floor((omega * T + alpha) / np.pi + 1e-12) + 1)
    sw = T - (ks * np.pi - alpha) / omega
    sw = np.sort(sw[(sw > tol) & (sw < T - tol)])
    return MinTimeResult(float(T), alpha, inside, u_m, omega, sw)


@validated
def switching_curves(
    a: float,
    u_m: float,
    omega: float = 1.0,
    *,
    n_switches: int = 3,
    inside: bool = True,
    points: int = 361,
    optimal_only: bool = False,
) -> list[np.ndarray]:
    """Switching curves of the time-optimal synthesis for reaching the circle ``|x| = a`` (Ch. II §4.1, Figs 13–17).

    Extremals are traced backwards from every terminal point ``a (cos phi, sin phi)`` with the adjoint given by
    transversality (``psi(T) ∝ ±x(T)``: outward when reaching the circle from inside, inward from outside).
    Backwards, the first switch comes after the angle ``pi - (phi mod pi)`` (eq. 74) and the others every ``pi``
    (arcs about ``(±u_m, 0)``).  Curve ``k`` is the locus of the k-th switch (scaled phase plane).

    These are loci of extremals (necessary conditions only): backwards, extremals from different terminal points
    overlap and an earlier switch may belong to a non-optimal extremal.  With ``optimal_only=True`` such points
    (backward time above the exact :func:`min_time_1dof` from that point) are replaced by ``nan``, leaving the
    switching curves of the optimal synthesis; this costs one minimum-time solve per point.

    Parameters
    ----------
    a : float
        Radius of the target circle (scaled amplitude, units of ``x1``); must be positive and finite.
    u_m : float
        Scaled control bound ``u_bar_max / (m omega**2)`` (units of ``x1``); must be positive and finite.
    omega : float, optional
        Natural frequency (rad/s); must be positive and finite (default 1).
    n_switches : int, optional
        Number of switching curves traced (the first ``n_switches`` switches backwards in time); an integer >= 1.
    inside : bool, optional
        Reach the circle from inside (True, default: excitation) or from outside (False: damping).
    points : int, optional
        Number of terminal points on the circle, i.e. of points per curve; an integer >= 1 (default 361).
    optimal_only : bool, optional
        Replace points of non-optimal extremals by ``nan`` (default False: all extremals).

    Returns
    -------
    list of ndarray, each of shape (points, 2)
        Curve ``k`` holds the ``k``-th switching point of the extremal through each terminal point (``nan`` where
        the extremal left its side of the circle, or was discarded as non-optimal).

    Examples
    --------
    >>> curves = switching_curves(3.0, 1.0, n_switches=2, points=5)
    >>> [c.shape for c in curves]
    [(5, 2), (5, 2)]
    """
    a, u_m, omega = _positive("a", a), _positive("u_m", u_m), _positive("omega", omega)
    phis = np.linspace(0, 2 * np.pi, int(points), endpoint=False) + np.pi / (2 * int(points))
    curves = np.full((int(n_switches), len(phis), 2), np.nan)
    for i, phi in enumerate(phis):
        alpha = phi if inside else phi + np.pi
        x = a * np.array([np.cos(phi), np.sin(phi)])
        tau = 0.0
        edges = (np.ceil(alpha / np.pi) * np.pi - alpha) / omega + np.arange(int(n_switches)) * np.pi / omega
        for k, t_sw in enumerate(edges):
            mid = 0.5 * (tau + t_sw)
            u = u_m * (1.0 if np.sin(omega * mid + alpha) >= 0 else -1.0)
            d = x - np.array([u, 0.0])
            th = omega * (t_sw - tau)  # counter-clockwise backwards
            x = np.array([u + d[0] * np.cos(th) - d[1] * np.sin(th), d[0] * np.sin(th) + d[1] * np.cos(th)])
            tau = t_sw
            if (np.hypot(*x) < a) != inside:  # the extremal left the side of the circle it must start from
                break
            if optimal_only:
                exact = min_time_1dof(x, a, u_m, omega).time
                if not exact > tau - 1e-6 / omega:
                    break
            curves[k, i] = x
    return list(curves)


# ---------------------------------------------------------------------------------------------------- quasi-optimal
@validated
def quasi_optimal_control(x1: Any, x2: Any, a: float, u_m: float) -> np.ndarray:
    """Quasi-optimal feedback (eq. 75): ``+u_m sign(x2)`` inside the circle, ``0`` on it, ``-u_m sign(x2)`` outside.

    On the switching line ``x2 = 0`` the sign is chosen so that the motion leaves it consistently (``+1`` for
    ``x1 < u_m`` inside, so the law starts from rest).

    Parameters
    ----------
    x1 : float or array_like
        Scaled displacement(s) ``x1``; finite, broadcastable against ``x2``.
    x2 : float or array_like
        Scaled velocity(ies) ``x1'/omega``; finite, broadcastable against ``x1``.
    a : float
        Radius of the target circle (units of ``x1``); must be positive.
    u_m : float
        Scaled control bound (units of ``x1``); must be positive.

    Returns
    -------
    ndarray
        The scaled control ``-u_m``, ``0`` or ``u_m`` at each state.

    Examples
    --------
    >>> quasi_optimal_control([0.0, 0.5, 3.0, 3.0], [0.0, -0.2, 1.0, 0.0], 2.0, 0.1).tolist()
    [0.1, -0.1, -0.1, 0.1]
    """
    a, u_m = _positive("a", a), _positive("u_m", u_m)
    x1, x2 = check_finite_array("x1", x1), check_finite_array("x2", x2)
    try:
        x1, x2 = np.broadcast_arrays(x1, x2)
    except ValueError:
        raise ParameterError(f"x1 and x2 must be broadcastable, got shapes {x1.shape} and {x2.shape}") from None
    r2 = x1**2 + x2**2
    s = np.where(x2 > 0, 1.0, np.where(x2 < 0, -1.0, np.where(x1 < u_m, 1.0, -1.0)))
    inside = r2 < a * a
    s_out = np.where(x2 > 0, 1.0, np.where(x2 < 0, -1.0, np.where(x1 < 0, 1.0, -1.0)))
    return np.where(np.isclose(r2, a * a, rtol=1e-12, atol=0), 0.0, np.where(inside, u_m * s, -u_m * s_out))


@dataclass(frozen=True)
class QuasiOptimalRun(SymPyPrintable):
    """Closed-loop run of the quasi-optimal law: event times, states at the events and the control on each arc.

    Attributes
    ----------
    time : float
        Time at which the circle ``|x| = a`` was reached.
    events_t : ndarray, shape (n + 1,)
        Times of the events (start, switches on ``x2 = 0`` and the final crossing of the circle), from 0.
    events_x : ndarray, shape (n + 1, 2)
        Scaled states ``(x1, x1'/omega)`` at the events.
    controls : ndarray, shape (n,)
        Scaled control on each of the ``n`` arcs between events.
    """

    time: float
    events_t: np.ndarray = field(repr=False)
    events_x: np.ndarray = field(repr=False)
    controls: np.ndarray = field(repr=False)

    @plot_method
    def plot(self, *, ax: Any = None, points: int = 40) -> Any:
        """Draw the phase-plane trajectory (arcs about ``(±u_m, 0)``).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        points : int, optional
            Number of points drawn per arc (an integer >= 2; default 40).

        Returns
        -------
        matplotlib Axes
        """

        ax = new_axes(ax)
        for k, (x, u, t0, t1) in enumerate(
            zip(self.events_x[:-1], self.controls, self.events_t[:-1], self.events_t[1:], strict=True)
        ):
            th = np.linspace(0, 1, points) * (t1 - t0)
            d = x - np.array([u, 0.0])
            label = "trajectory (arcs about (±u_m, 0))" if k == 0 else None
            ax.plot(
                u + d[0] * np.cos(th) + d[1] * np.sin(th), -d[0] * np.sin(th) + d[1] * np.cos(th), "b-", label=label
            )
        ax.legend(loc="best", fontsize="small")
        ax.set_xlabel("x1")
        ax.set_ylabel("x1'/omega")
        ax.set_aspect("equal")
        return ax


@validated
def simulate_quasi_optimal(
    x0: Sequence[float], a: float, u_m: float, omega: float = 1.0, *, max_arcs: int = 100000
) -> QuasiOptimalRun:
    """Run the quasi-optimal feedback exactly (arc by arc) until the circle ``|x| = a`` is reached.

    Returns the reaching time; from rest it is about ``pi a / (2 omega u_m)`` (eq. 76).

    Parameters
    ----------
    x0 : (x1, x2)
        Initial scaled state ``(x1, x1'/omega)``: a pair of finite numbers.
    a : float
        Radius of the target circle (units of ``x1``); must be positive and finite.
    u_m : float
        Scaled control bound ``u_bar_max / (m omega**2)`` (units of ``x1``); must be positive and finite.
    omega : float, optional
        Natural frequency (rad/s); must be positive and finite (default 1).
    max_arcs : int, optional
        Largest number of arcs simulated (an integer >= 1); more raises ConvergenceError.

    Returns
    -------
    QuasiOptimalRun

    Examples
    --------
    >>> run = simulate_quasi_optimal((0.0, 0.0), 4.0, 1.0)
    >>> round(run.time / (2 * 3.141592653589793), 6)
    1.0
    """
    a, u_m, omega = _positive("a", a), _positive("u_m", u_m), _positive("omega", omega)
    x = np.asarray(x0, dtype=float).copy()
    if x.shape != (2,) or not np.all(np.isfinite(x)):
        raise ParameterError(f"x0 must be a finite pair (x1, x2), got {x0!r}")
    inside = np.hypot(*x) < a
    t, ts, xs, us = 0.0, [0.0], [x.copy()], []
    for _ in range(max_arcs):
        if np.isclose(np.hypot(*x), a, rtol=1e-12) or (np.hypot(*x) < a) != inside:
            return QuasiOptimalRun(t, np.array(ts), np.array(xs), np.array(us))
        u = float(quasi_optimal_control(x[0], x[1], a, u_m))
        d = x - np.array([u, 0.0])
        rd = np.hypot(*d)
        delta = np.arctan2(d[1], d[0])
        th_sw = np.mod(delta, np.pi)
        th_sw = np.pi if th_sw < 1e-13 else th_sw
        # circle crossing: |c + Rot(-th) d|^2 = a^2  <=>  u (d1 cos th + d2 sin th) = (a^2 - u^2 - rd^2) / 2
        rhs = (a * a - u * u - rd * rd) / 2
        th_hit = np.inf
        if u != 0 and abs(rhs) <= abs(u) * rd:
            base = np.arccos(np.clip(rhs / (u * rd), -1, 1))
            for cand in (delta + base, delta - base):
                c = np.mod(cand, 2 * np.pi)
                if 1e-13 < c <= th_sw + 1e-13:
                    th_hit = min(th_hit, c)
        th = min(th_sw, th_hit)
        cth, sth = np.cos(th), np.sin(th)
        x = np.array([u + d[0] * cth + d[1] * sth, -d[0] * sth + d[1] * cth])
        if th == th_hit:
            x *= a / np.hypot(*x)
        else:
            x[1] = 0.0
        t += th / omega
        ts.append(t)
        xs.append(x.copy())
        us.append(u)
    raise ConvergenceError(f"quasi-optimal run did not reach the circle in {max_arcs} arcs", achieved=float(t))


# ---------------------------------------------------------------------------------------------------- multi-DOF
@dataclass(frozen=True)
class ExcitationBound(SymPyPrintable):
    """Multi-DOF excitation-time bound.

    ``times[i] = pi a_i omega_i / (2 b_i)`` is the dissertation's eq. (84) per mode and ``bound = max(times)``.  From
    rest the exact 1-DOF minimum time can be shorter than (76) by less than half a period (the last arc need not be
    a full half turn), so the rigorous lower bound is ``exact_bound = max(exact_times)`` with ``exact_times`` the
    exact minimum times of each normal coordinate under its bound ``b_i`` (:func:`min_time_1dof`).

    Attributes
    ----------
    bound : float
        ``max(times)``: the bound of eq. 84 (s).
    times : ndarray, shape (n,)
        Time ``pi a_i omega_i / (2 b_i)`` of eq. 84 per mode, ascending frequency order.
    omega : ndarray, shape (n,)
        Natural frequencies ``omega_i`` (rad/s), ascending.
    control_bounds : ndarray, shape (n,)
        Bounds ``b_i = sum_j |B'_ij| U_j`` on the modal forces.
    exact_times : ndarray, shape (n,)
        Exact minimum time from rest of each normal coordinate under its bound ``b_i``.
    exact_bound : float
        ``max(exact_times)``: the rigorous lower bound.
    """

    bound: float
    times: np.ndarray
    omega: np.ndarray
    control_bounds: np.ndarray = field(repr=False)
    exact_times: np.ndarray = field(repr=False)
    exact_bound: float = field(repr=False)

    def __repr__(self) -> str:
        ts = ", ".join(f"{v:.6g}" for v in self.times)
        return f"ExcitationBound(bound={self.bound:.6g} s, times=[{ts}] s, exact_bound={self.exact_bound:.6g} s)"


@validated
def excitation_time_bound(
    M: Any,
    K: Any,
    B: Any,
    force_max: Any,
    amplitudes: Sequence[float],
    *,
    normalization: str = "max",
) -> ExcitationBound:
    """Lower bound on the time any control ``|u_j| <= U_j`` needs to excite every mode of ``M q'' + K q = B u``.

    In mass-normalised normal coordinates ``z_i'' + omega_i**2 z_i = (B' u)_i`` with ``|(B' u)_i| <= b_i =
    sum_j |B'_ij| U_j`` and ``T_i = pi a_i omega_i / (2 b_i)`` (eqs 79–84).

    Parameters
    ----------
    M, K : (n, n) arrays
        Inertia and stiffness matrices: symmetric, ``M`` and ``K`` positive definite.
    B : (n, r) array
        Control matrix with ``n`` rows (``C^T`` for actuators collocated with the sensors).
    force_max : float or (r,) array
        Bounds ``U_j`` on the ``r`` controls; positive and finite (a scalar applies to every control).
    amplitudes : (n,) floats
        Target amplitude of each mode (ascending frequency order); ``n`` positive numbers, read according to
        ``normalization``.
    normalization : {"max", "mass"}
        What ``amplitudes`` measure: ``"max"`` (default) the amplitude of the largest generalised coordinate in that
        mode, ``"mass"`` the amplitude of the mass-normalised coordinate.

    Returns
    -------
    ExcitationBound

    Examples
    --------
    The stand of Ch. II §4.5 (equal springs, centered CM, ±5 N actuators, 2 mm amplitudes):

    >>> import numpy as np
    >>> Lx, Lz, k, am = 4.0, 1.74, 7.4e5, 2e-3
    >>> C = np.array([[1, -Lx/2, Lz/2], [1, Lx/2, Lz/2], [1, Lx/2, -Lz/2], [1, -Lx/2, -Lz/2]])
    >>> res = excitation_time_bound(np.diag([15000, 44000, 3000]), k * C.T @ C, C.T, 5.0, [am, am / Lx, am / Lz])
    >>> res.times.round(4).tolist()
    [33.0987, 14.172, 8.507]
    """
    M, K, B = (np.atleast_2d(np.asarray(v, dtype=float)) for v in (M, K, B))
    n = M.shape[0]
    if M.shape != (n, n) or K.shape != (n, n) or B.shape[0] != n:
        raise ParameterError(f"shapes do not match: M {M.shape}, K {K.shape}, B {B.shape}")
    U = np.broadcast_to(np.asarray(force_max, dtype=float), (B.shape[1],))
    if np.any(~np.isfinite(U)) or np.any(U <= 0):
        raise ParameterError(f"force_max must be positive, got {force_max!r}")
    amp = np.asarray(amplitudes, dtype=float)
    if amp.shape != (n,) or np.any(amp <= 0):
        raise ParameterError(f"amplitudes must be {n} positive numbers, got {amplitudes!r}")
    try:
        import scipy.linalg

        lam, phi = scipy.linalg.eigh(K, M)
    except np.linalg.LinAlgError as exc:
        raise ModelError("M must be symmetric positive definite") from exc
    if np.any(lam <= 0):
        raise ModelError(f"K must be positive definite (eigenvalues {lam})")
    omega = np.sqrt(lam)
    if normalization == "max":
        za = amp / np.abs(phi).max(axis=0)
    elif normalization == "mass":
        za = amp
    else:
        raise ParameterError(f"normalization must be 'max' or 'mass', got {normalization!r}")
    b = np.abs(phi.T @ B) @ U
    if np.any(b == 0):
        raise ModelError(f"mode(s) {np.flatnonzero(b == 0).tolist()} are not controllable by B")
    times = np.pi * za * omega / (2 * b)
    exact = np.array([min_time_1dof((0.0, 0.0), za[i], b[i] / omega[i] ** 2, omega[i]).time for i in range(n)])
    return ExcitationBound(float(times.max()), times, omega, b, exact, float(exact.max()))
