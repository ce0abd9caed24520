"""Special self-oscillating and regulated systems of Bulgakov ch. 5 C and §5.24, as far as they could be read.

* :func:`clock_escapement` — balance wheel with Coulomb friction and an instantaneous escapement kick (§5.11):
  point map ``b = sqrt((a - B)^2 + h) - B`` (5.135), stationary amplitude ``A = h/(4B)`` (5.138), existence and start
  conditions (5.132), (5.139)–(5.140), half-swing time (5.137) and Airy's theorem.
* :func:`step_valve_generator` — valve generator with a step characteristic ``x'' + 2 eps x' + k^2 x = k^2 S H(x')``
  (§5.13, reconstructed): half-maps ``b = delta a``, ``c = delta b + S(1 + delta)``, cycle ``A = S/(1 - delta)``.
* :func:`backlash_critical_gap` — relay servo with backlash (§5.14, Krautwig): critical gap ``k_c``.  The printed
  formulas are damaged; the two variants (5.186), (5.189) are reconstructions that satisfy the stated limits.
* :func:`radinger_flywheel` — flywheel mass for a given cyclic irregularity (§5.24, leading term = Radinger (5.319)).

The steam-engine governor of §5.15 is an existence/uniqueness argument with no computable formula; it is not
implemented.  The second-order flywheel terms (5.312)–(5.316) are illegible and are not implemented either.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from ...numeric import compile

__all__ = [
    "ClockEscapement",
    "FlywheelDesign",
    "StepGenerator",
    "backlash_critical_gap",
    "clock_escapement",
    "radinger_flywheel",
    "step_valve_generator",
]

_a = sp.Symbol("a", positive=True)


def _pos(x: Any, name: str, allow_zero: bool = False) -> sp.Expr:
    v = sp.sympify(x)
    if not v.is_number or not v.is_real or not (v > 0 or (allow_zero and v == 0)):
        raise ParameterError(f"{name} must be a {'non-negative' if allow_zero else 'positive'} number, got {x!r}")
    return v


@dataclass(frozen=True)
class ClockEscapement(SymPyPrintable):
    """Balance wheel ``x'' + x = -B sign(x')`` (time in units ``sqrt(m/sigma)``) kicked by ``h/2`` energy units at
    ``x = +f`` on the leftward swing and ``x = -f`` on the rightward swing.

    Attributes
    ----------
    B, h, f : Expr
        Dead zone ``F/sigma``, kick ``h = 2 dH/sigma``, kick position.
    map : Expr
        Next amplitude ``b(a)`` (symbol ``a``).
    amplitude : Expr
        Stationary amplitude ``A = h/(4B)`` (the solution of ``b(A) = A``).
    multiplier : Expr
        ``db/da`` at ``A``: ``(A - B)/(A + B)``; the cycle is stable since it is in (-1, 1) (5.153).
    start_threshold : Expr
        Smallest starting amplitude for which the escapement is reached: ``f`` if ``B <= f``, else ``2B - f``.
    exists : bool
        The cycle exists (it is reached by its own swing): ``A`` above the start threshold (5.139)–(5.140).
    """

    B: sp.Expr
    h: sp.Expr
    f: sp.Expr
    map: sp.Expr
    amplitude: sp.Expr
    multiplier: sp.Expr
    start_threshold: sp.Expr
    exists: bool

    def next_amplitude(self, a: float) -> float:
        """``b(a)``; for ``a`` below the start threshold the kick is missed and the Coulomb law ``a - 2B`` applies.

        Parameters
        ----------
        a : float
            Amplitude of the current swing (a turning point), in the units of ``B``; a positive number.
        """
        if a <= float(self.start_threshold):
            return a - 2 * float(self.B)
        return float(self.map.subs(_a, a))

    def sequence(self, a0: float, n: int) -> list[float]:
        """Successive swing amplitudes ``a0, b(a0), b(b(a0)), ...`` of the point map.

        The sequence stops early when an amplitude falls to ``B`` or below (the balance stops in the dead zone).

        Parameters
        ----------
        a0 : float
            Starting amplitude (a turning point), in the units of ``B``; a positive number.
        n : int
            Number of map steps, an integer >= 0.

        Returns
        -------
        list of float
            At most ``n + 1`` amplitudes, starting with ``a0``.
        """
        out = [float(a0)]
        for _ in range(n):
            nxt = self.next_amplitude(out[-1])
            if nxt <= float(self.B):
                out.append(nxt)
                break
            out.append(nxt)
        return out

    def half_swing_time(self, a: Any) -> sp.Expr:
        """Duration of a kicked half-swing from amplitude ``a`` (5.137), units ``sqrt(m/sigma)``.

        ``pi - asin((f - B)/(a - B)) + asin((f - B)/sqrt((a - B)^2 + h))``: shorter than ``pi`` when ``f > B`` (kick
        before the dead-zone edge is passed), longer when ``f < B`` and exactly ``pi`` when ``f = B`` (Airy).

        Parameters
        ----------
        a : Expr or float
            Amplitude at the start of the half-swing, above the start threshold (the kick is reached); a number or a
            symbol.
        """
        a = sp.sympify(a)
        B, h, f = self.B, self.h, self.f
        return sp.pi - sp.asin((f - B) / (a - B)) + sp.asin((f - B) / sp.sqrt((a - B) ** 2 + h))

    def __repr__(self) -> str:
        return (
            f"ClockEscapement(B={self.B}, h={self.h}, f={self.f}: A = {self.amplitude}, "
            f"multiplier = {self.multiplier}, exists={self.exists})"
        )


@validated
def clock_escapement(B: Any, h: Any, f: Any = 0) -> ClockEscapement:
    """Clock with Coulomb friction and an instantaneous escapement impulse (Bulgakov §5.11).

    The map is derived from energy conservation about the friction center ``+B`` of the leftward swing:
    ``(b + B)^2 = (a - B)^2 + h``.

    Parameters
    ----------
    B : Expr or float
        Dead zone ``F/sigma`` of the Coulomb friction (friction force over spring stiffness); a positive number.
    h : Expr or float
        Kick ``h = 2 dH/sigma``: twice the escapement energy per swing over the stiffness; a positive number.
    f : Expr or float, optional
        Position ``|x|`` at which the kick is given; a non-negative number (default 0).

    Returns
    -------
    ClockEscapement

    Examples
    --------
    >>> c = clock_escapement(sp.Rational(1, 100), sp.Rational(1, 50), sp.Rational(1, 20))
    >>> c.amplitude, c.multiplier, c.exists
    (1/2, 49/51, True)
    """
    B, h, f = _pos(B, "B"), _pos(h, "h"), _pos(f, "f", allow_zero=True)
    b = sp.Symbol("b", positive=True)
    sols = sp.solve(sp.Eq((b + B) ** 2, (_a - B) ** 2 + h), b)
    bmap = next(s for s in sols if s.subs(_a, 10 * (B + 1) + f).is_positive)
    fixed = [r for r in sp.solve(sp.Eq(bmap, _a), _a) if r.is_positive]
    if len(fixed) != 1:  # pragma: no cover - fixed algebra
        raise ModelError(f"unexpected fixed points {fixed}")
    A = sp.simplify(fixed[0])
    mult = sp.simplify(sp.diff(bmap, _a).subs(_a, A))
    thr = f if B <= f else 2 * B - f
    return ClockEscapement(
        B=B, h=h, f=f, map=bmap, amplitude=A, multiplier=mult, start_threshold=thr, exists=bool(A > thr)
    )


@dataclass(frozen=True)
class StepGenerator(SymPyPrintable):
    """Cycle of ``x'' + 2 eps x' + k^2 x = k^2 S H(x')``: turning points ``+A`` and ``-B`` (5.166).

    Attributes
    ----------
    S : Expr
        Height of the step characteristic (the switched force per unit ``k^2``).
    eps : Expr
        Damping coefficient ``eps`` of the circuit.
    k : Expr
        Undamped natural frequency ``k``.
    delta : Expr
        Half-swing decrement ``exp(-pi eps/omega)``, ``omega = sqrt(k^2 - eps^2)`` (5.162)–(5.163).
    A : Expr
        Upper turning point of the cycle, ``S/(1 - delta)`` (5.166).
    B : Expr
        Magnitude of the lower turning point, ``S delta/(1 - delta)`` (5.166).
    multiplier : Expr
        Slope ``delta**2`` of the composed half-maps at the cycle (stable, since below 1).
    period : Expr
        Period ``2 pi/omega`` of the cycle.
    """

    S: sp.Expr
    eps: sp.Expr
    k: sp.Expr
    delta: sp.Expr
    A: sp.Expr
    B: sp.Expr
    multiplier: sp.Expr
    period: sp.Expr

    def sequence(self, a0: float, n: int) -> list[float]:
        """Signed turning points ``a0, -b1, c2, ...`` of the half-maps (5.161), (5.164).

        Parameters
        ----------
        a0 : float
            Starting upper turning point; a real number.
        n : int
            Number of half-swings, an integer >= 0.

        Returns
        -------
        list of float
            ``n + 1`` signed turning points, starting with ``a0``.
        """
        d, S = float(self.delta), float(self.S)
        out = [float(a0)]
        for j in range(n):
            out.append(-d * out[-1] if j % 2 == 0 else -d * out[-1] + S * (1 + d))
        return out


@validated
def step_valve_generator(S: Any, eps: Any, k: Any = 1) -> StepGenerator:
    """Valve generator with an ideal step characteristic (Bulgakov (1954), §5.13; the model is
    reconstructed where the print is illegible).

    Parameters
    ----------
    S : Expr or float
        Height of the step characteristic ``i_a = S H(x')`` (rescaled, (5.158)–(5.160)); a positive number.
    eps : Expr or float
        Damping coefficient ``eps = R/(2L)``; a positive number below ``k``.
    k : Expr or float, optional
        Undamped natural frequency ``k = 1/sqrt(LC)``; a positive number above ``eps`` (default 1).

    Returns
    -------
    StepGenerator

    Examples
    --------
    >>> g = step_valve_generator(1, 0)
    Traceback (most recent call last):
    ...
    symosc.errors.ParameterError: eps must be a positive number, got 0
    """
    S, eps, k = _pos(S, "S"), _pos(eps, "eps"), _pos(k, "k")
    if not eps < k:
        raise ParameterError(f"need eps < k for oscillatory half-swings, got eps = {eps}, k = {k}")
    omega = sp.sqrt(k**2 - eps**2)
    delta = sp.exp(-sp.pi * eps / omega)
    a = sp.Symbol("a", positive=True)
    # half-maps: down-swing about 0, up-swing about S; fixed point of the composition
    down = delta * a
    up = lambda x: delta * x + S * (1 + delta)  # noqa: E731
    A = sp.simplify(sp.solve(sp.Eq(up(down), a), a)[0])
    mult = sp.simplify(sp.diff(up(down), a))
    return StepGenerator(
        S=S, eps=eps, k=k, delta=delta, A=A, B=sp.simplify(delta * A), multiplier=mult, period=2 * sp.pi / omega
    )


def _L(x: float) -> float:
    return x + math.log(abs(1 - x))


def _M2(y: float) -> float:
    """Inverse of ``L(x) = x + ln(1 - x)`` on ``0 < x < 1`` (``y < 0``)."""
    from scipy.optimize import brentq

    if y >= 0:
        return 0.0
    hi = 1 - 1e-16
    if _L(hi) > y:
        return hi
    return brentq(lambda x: _L(x) - y, 0.0, hi, xtol=1e-15)


@validated
def backlash_critical_gap(z: float, f: float, variant: str = "follower") -> float:
    """Critical insulating gap of the relay servo with backlash (Bulgakov §5.14, RECONSTRUCTED formulas).

    ``variant="follower"``: friction on the follower, ``k_c = -f L(-M2(-z)/f)`` (5.186);
    ``variant="motor"``: friction on the motor, ``k_c = -f L(-(1 - f) M2(-z/(1 - f))/f)`` (5.189), zero for f >= 1.
    ``L(x) = x + ln|1 - x|`` and ``M2`` is its inverse on (0, 1).  ``f = 0`` gives ``M2(-z)`` (5.187).  A gap above
    ``k_c`` suppresses the self-oscillation.  The printed formulas are damaged; these satisfy every limit the text
    states and agree with a simulation of the piecewise equations (:func:`simulate_backlash_servo`: at 0.9 k_c a
    self-oscillation persists, at 1.1 k_c every start comes to rest, for both variants).

    Parameters
    ----------
    z : float
        Reduced (dimensionless) backlash ``z`` of (5.186)–(5.189); a non-negative finite number.
    f : float
        Reduced Coulomb friction (friction force over the motor's driving force); a non-negative finite number.
    variant : {"follower", "motor"}, optional
        Where the friction acts: on the follower (5.186, default) or on the motor (5.189).

    Returns
    -------
    float
        The critical gap ``k_c`` (0 when ``z = 0``, or ``f >= 1`` for the motor variant).

    Examples
    --------
    >>> round(backlash_critical_gap(1.0, 0.0), 6) == round(backlash_critical_gap(1.0, 1e-12), 6)
    True
    """
    if not (z >= 0 and f >= 0) or not (math.isfinite(z) and math.isfinite(f)):
        raise ParameterError(f"z and f must be non-negative and finite, got z={z}, f={f}")
    if variant not in ("follower", "motor"):
        raise ParameterError(f"variant must be 'follower' or 'motor', got {variant!r}")
    if z == 0:
        return 0.0
    if variant == "follower":
        m = _M2(-z)
        return m if f == 0 else -f * _L(-m / f)
    if f >= 1:
        return 0.0
    m = (1 - f) * _M2(-z / (1 - f))
    return m if f == 0 else -f * _L(-m / f)


@dataclass(frozen=True)
class FlywheelDesign(SymPyPrintable):
    """Flywheel from Radinger's formula: ``M r_m^2 delta = Delta E`` (leading term of §5.24).

    Attributes
    ----------
    energy_swing : float
        ``Delta E = max E - min E`` of ``E(s) = Integral(torque - r_m^2 a'(s)/2)``.
    extremes : tuple of float
        The crank positions ``s`` (reduced to one period) of the smallest and the largest speed.
    mass : float
        The total reduced mass needed, ``Delta E/(delta r_m^2)``.
    flywheel_mass : float
        ``mass`` minus ``other_mass`` (m2 + m3 of (5.319)): the flywheel's share.
    """

    energy_swing: float
    extremes: tuple[float, float]
    mass: float
    flywheel_mass: float


@validated
def radinger_flywheel(
    torque: Any,
    s: sp.Symbol,
    delta: float,
    r_m: float,
    *,
    mass_variation: Any = 0,
    other_mass: float = 0.0,
    period: float = 2 * math.pi,
    samples: int = 4001,
) -> FlywheelDesign:
    """Reduced flywheel mass for a cyclic irregularity ``delta`` at mean speed ``r_m`` (Bulgakov (5.317)–(5.319)).

    Parameters
    ----------
    torque : expression in ``s``
        Excess driving force ``F(s) - G(s)`` along the path ``s`` (zero mean over a period).
    s : Symbol
        The path coordinate (crank-pin path) in ``torque`` and ``mass_variation``.
    delta : float
        Coefficient of cyclic irregularity ``(r_max - r_min)/r_m``.
    r_m : float
        Mean speed.
    mass_variation : expression in ``s``
        The zero-mean variable part ``a(s)`` of the reduced mass.
    other_mass : float, optional
        The constant reduced masses already present (m2 + m3 of (5.319)), subtracted to give ``flywheel_mass``; a
        finite number (default 0).
    period : float, optional
        Period of the torque in ``s``; a positive number (default ``2 pi``).
    samples : int, optional
        Number of grid points over one period on which sign changes of the torque are located, an integer >= 2
        (default 4001).

    Returns
    -------
    FlywheelDesign

    Examples
    --------
    >>> s = sp.Symbol("s")
    >>> round(radinger_flywheel(sp.sin(s), s, 0.02, 10.0).mass, 10)   # Delta E = 2
    1.0
    """
    torque, av = sp.sympify(torque), sp.sympify(mass_variation)
    for e, n in ((torque, "torque"), (av, "mass_variation")):
        if e.free_symbols - {s}:
            raise ParameterError(
                f"{n}: substitute values for " + ", ".join(sorted(x.name for x in e.free_symbols - {s}))
            )
    if not (0 < delta < 1) or not r_m > 0:
        raise ParameterError(f"need 0 < delta < 1 and r_m > 0, got delta={delta}, r_m={r_m}")
    integrand = torque - r_m**2 * sp.diff(av, s) / 2
    fn = compile(integrand, [s], check=False).raw
    s0 = 0.0123456789 * period  # start off any symmetric zero of the torque
    grid = np.linspace(s0, s0 + period, samples)
    vals = np.asarray(fn(grid), dtype=float)
    mean = float(np.trapezoid(vals, grid) / period)
    scale = float(np.max(np.abs(vals))) or 1.0
    if abs(mean) > 1e-6 * scale:
        raise ModelError(
            f"the excess torque must have zero mean over a period (steady running); its mean is {mean:.3g}"
        )
    from scipy.integrate import quad
    from scipy.optimize import brentq

    # extremes of E(s): zeros of the integrand, refined
    zs = [
        brentq(fn, grid[i], grid[i + 1], xtol=1e-14)
        for i in range(samples - 1)
        if np.sign(vals[i]) * np.sign(vals[i + 1]) < 0
    ]
    if not zs:
        raise ModelError("the excess torque never changes sign: no speed fluctuation")
    pts = [s0, *zs]
    E = [0.0]
    for lo, hi in itertools.pairwise(pts):
        E.append(E[-1] + quad(fn, lo, hi, epsabs=1e-13, epsrel=1e-12)[0])
    E = np.array(E[1:])
    zs = [z % period for z in zs]
    i_min, i_max = int(np.argmin(E)), int(np.argmax(E))
    dE = float(E[i_max] - E[i_min])
    M = dE / (delta * r_m**2)
    return FlywheelDesign(energy_swing=dE, extremes=(zs[i_min], zs[i_max]), mass=M, flywheel_mass=M - other_mass)
