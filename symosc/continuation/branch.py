"""Results of :mod:`symosc.continuation`: one periodic solution, a bifurcation point, a branch."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._plotting import new_axes, plot_method
from .._printing import SymPyPrintable
from .._validate import check_choice, check_int
from ..errors import ParameterError

__all__ = ["Bifurcation", "Branch", "PeriodicSolution"]

KINDS = ("fold", "period_doubling", "neimark_sacker", "branch_point")
_SHORT = {"fold": "LP", "period_doubling": "PD", "neimark_sacker": "NS", "branch_point": "BP"}


def _fmt_mult(rho: np.ndarray) -> str:
    items = []
    for r in np.asarray(rho)[:4]:
        items.append(f"{r.real:.6g}" if abs(r.imag) < 1e-12 * max(1, abs(r)) else f"{r.real:.4g}{r.imag:+.4g}j")
    return "[" + ", ".join(items) + (", ..." if len(rho) > 4 else "") + "]"


@dataclass(frozen=True)
class PeriodicSolution(SymPyPrintable):
    """One periodic solution with its residual and stability.

    Attributes
    ----------
    method : str
        ``"harmonic balance"``, ``"shooting"`` or ``"collocation"``.
    frequency : float
        Base angular frequency (rad/s) of the solution; the period is ``2 pi / frequency``.
    amplitudes : tuple of float
        ``max |q_i(t)|`` over a period, one per coordinate.
    residual : float
        What was achieved: the relative residual of the truncated solution in the equations of motion (harmonic
        balance, collocation) or the relative periodicity defect ``|y(T) - y(0)|`` (shooting).
    multipliers : ndarray
        Floquet multipliers (2n), largest modulus first.
    stable : bool
        All multipliers inside the unit circle (the trivial multiplier 1 of an autonomous system excepted).
    values : dict
        Parameter values (name -> value).
    coefficients : ndarray or None
        Fourier coefficients ``[a0, a1, b1, ...]`` per coordinate in the phase ``tau = frequency * t`` (harmonic
        balance).
    initial_state : ndarray
        ``(q, q')`` at ``t = 0`` (forced problems: the forcing phase of ``t = 0``).
    size : int
        Harmonics (harmonic balance), mesh intervals (collocation) or integration steps (shooting).
    coordinates : tuple of str
        Coordinate names.
    tolerance : float
        The requested residual.
    """

    method: str
    frequency: float
    amplitudes: tuple
    residual: float
    multipliers: np.ndarray = field(repr=False)
    stable: bool
    values: dict
    coefficients: np.ndarray | None = field(default=None, repr=False)
    initial_state: np.ndarray = field(default=None, repr=False)
    size: int = 0
    coordinates: tuple = ()
    tolerance: float = float("nan")

    @property
    def amplitude(self) -> float:
        """``max |q_1(t)|`` (first coordinate)."""
        return float(self.amplitudes[0])

    @property
    def period(self) -> float:
        return float(2 * np.pi / self.frequency)

    @property
    def harmonics(self) -> int | None:
        """Number of harmonics (harmonic balance), else None."""
        return self.size if self.method == "harmonic balance" else None

    def __repr__(self) -> str:
        amp = ", ".join(f"{a:.10g}" for a in self.amplitudes)
        vals = ", ".join(f"{k}={v:g}" for k, v in self.values.items())
        what = {"harmonic balance": "harmonics", "collocation": "intervals", "shooting": "steps"}.get(self.method, "")
        return (
            f"PeriodicSolution({self.method}, frequency={self.frequency:.12g}, amplitude=({amp}), "
            f"{'stable' if self.stable else 'unstable'}, multipliers={_fmt_mult(self.multipliers)}, "
            f"residual={self.residual:.2e}, {what}={self.size}; {vals})"
        )

    def orbit(self, samples: int = 256) -> tuple[np.ndarray, np.ndarray]:
        """Times (samples + 1 points over one period) and states ``(q, q')`` of the orbit.

        Parameters
        ----------
        samples : int, optional
            Number of intervals of the uniform time grid: an integer >= 4 (default 256).

        Returns
        -------
        t : ndarray, shape (samples + 1,)
        y : ndarray, shape (samples + 1, 2n)
        """
        from . import _fourier

        samples = check_int("samples", samples, minimum=4)
        T = self.period
        tt = np.linspace(0.0, T, samples + 1)
        if self.coefficients is None:
            raise ParameterError(f"orbit() needs Fourier coefficients; a {self.method} solution integrates instead")
        tau = self.frequency * tt
        q = _fourier.evaluate(self.coefficients, tau)
        qd = _fourier.evaluate(_fourier.derivative(self.coefficients), tau) * self.frequency
        return tt, np.hstack([q, qd])

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Phase portrait ``(q_1, q_1')`` of the solution (Fourier series), or its initial state.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
        """
        ax = new_axes(ax)
        if self.coefficients is not None:
            _, y = self.orbit(512)
            n = len(self.coordinates) or 1
            ax.plot(y[:, 0], y[:, n], "-" if self.stable else "--")
        else:
            n = len(self.initial_state) // 2
            ax.plot([self.initial_state[0]], [self.initial_state[n]], "o")
        name = self.coordinates[0] if self.coordinates else "q"
        ax.set_xlabel(name)
        ax.set_ylabel(f"d{name}/dt")
        ax.set_title(f"periodic solution, {self.method}")
        return ax


@dataclass(frozen=True)
class Bifurcation(SymPyPrintable):
    """A bifurcation located on a branch.

    Attributes
    ----------
    kind : str
        ``"fold"`` (saddle-node, limit point), ``"period_doubling"`` (a multiplier through -1),
        ``"neimark_sacker"`` (a complex pair through the unit circle) or ``"branch_point"`` (a simple branch point:
        pitchfork or transcritical, a multiplier through +1 with the branch crossing another).
    parameter : float
        Value of the continuation parameter.
    amplitude : float
        ``max |q_1|`` of the solution there.
    frequency : float
        Base angular frequency there (rad/s).
    multipliers : ndarray
        Floquet multipliers at the located point.
    located : bool
        Whether the test function was driven to zero (otherwise the point is the interpolated crossing).
    test : float
        Value of the test function at the returned point (about 0 when located).
    index : int
        Index of the branch point just before the bifurcation.
    state : ndarray
        The formulation's unknowns and the parameter, ``(u, lambda)``, at the bifurcation (for branch switching).
    tangent : ndarray
        The unit tangent of the branch there, in the same layout as ``state`` (for branch switching).
    size : int
        Harmonics (harmonic balance), mesh intervals (collocation) or integration steps (shooting) at the point.
    initial_state : ndarray
        ``(q, q')`` at ``t = 0`` of the solution at the bifurcation (forced problems: the forcing phase of
        ``t = 0``), for a simulation started there.
    """

    kind: str
    parameter: float
    amplitude: float
    frequency: float
    multipliers: np.ndarray = field(repr=False)
    located: bool = True
    test: float = 0.0
    index: int = 0
    state: np.ndarray = field(default=None, repr=False, compare=False)
    tangent: np.ndarray = field(default=None, repr=False, compare=False)
    size: int = 0
    initial_state: np.ndarray = field(default=None, repr=False, compare=False)

    def __repr__(self) -> str:
        return (
            f"Bifurcation({self.kind} at parameter={self.parameter:.12g}, amplitude={self.amplitude:.8g}, "
            f"frequency={self.frequency:.8g}, multipliers={_fmt_mult(self.multipliers)}, "
            f"{'located' if self.located else 'bracketed'}, test={self.test:.1e})"
        )


@dataclass(frozen=True)
class Branch(SymPyPrintable):
    """A branch of periodic solutions followed in one parameter, with stability and bifurcations.

    Attributes
    ----------
    method : str
        The formulation (harmonic balance, shooting, collocation).
    name : str
        The continuation parameter's name.
    parameter : ndarray
        Its value at each point.
    amplitude : ndarray
        ``max |q_1(t)|`` over a period at each point.
    frequency : ndarray
        Base angular frequency (rad/s) at each point.
    stable : ndarray of bool
        Stability of each point (Floquet multipliers).
    residual : ndarray
        Achieved relative residual at each point (see :class:`PeriodicSolution`).
    size : ndarray of int
        Harmonics (harmonic balance), mesh intervals or integration steps used at each point.
    multipliers : ndarray, shape (points, 2n)
        Floquet multipliers at each point, largest modulus first.
    amplitudes : ndarray, shape (points, n)
        ``max |q_i|`` for every coordinate.
    bifurcations : list of Bifurcation
        Folds, period doublings, Neimark–Sacker and branch points, in the order met.
    values : dict
        The fixed parameter values.
    coordinates : tuple of str
        The coordinate names.
    states : tuple of ndarray
        The formulation's unknowns at each point (Fourier coefficients and frequency, initial state, ...).
    initial_states : ndarray, shape (points, 2n)
        ``(q, q')`` at ``t = 0``.
    stopped : str
        Why the continuation ended.
    tolerance : float
        Requested residual.
    autonomous : bool
        Whether the oscillations are self-excited (then one multiplier is the trivial 1, left out of the stability).
    """

    method: str
    name: str
    parameter: np.ndarray
    amplitude: np.ndarray
    frequency: np.ndarray
    stable: np.ndarray
    residual: np.ndarray
    size: np.ndarray
    multipliers: np.ndarray = field(repr=False)
    amplitudes: np.ndarray = field(repr=False)
    bifurcations: list = field(repr=False)
    values: dict = field(repr=False)
    coordinates: tuple = field(repr=False)
    states: tuple = field(repr=False, compare=False)
    initial_states: np.ndarray = field(repr=False)
    stopped: str = ""
    tolerance: float = float("nan")
    autonomous: bool = False

    def __len__(self) -> int:
        return len(self.parameter)

    def __repr__(self) -> str:
        kinds = ", ".join(f"{_SHORT[b.kind]} at {b.parameter:.8g}" for b in self.bifurcations) or "none"
        lo, hi = (float(self.parameter.min()), float(self.parameter.max())) if len(self) else (np.nan, np.nan)
        return (
            f"Branch({self.method}, {self.name} in [{lo:.6g}, {hi:.6g}], {len(self)} points, "
            f"{int(np.sum(self.stable))} stable, max residual {float(np.max(self.residual)):.1e}, "
            f"size {int(np.min(self.size))}..{int(np.max(self.size))}; bifurcations: {kinds}; {self.stopped})"
        )

    def of_kind(self, kind: str) -> list[Bifurcation]:
        """The bifurcations of one kind.

        Parameters
        ----------
        kind : {"fold", "period_doubling", "neimark_sacker", "branch_point"}
            The kind of bifurcation: one of these names.
        """
        check_choice("kind", kind, KINDS)
        return [b for b in self.bifurcations if b.kind == kind]

    def solution(self, index: int) -> PeriodicSolution:
        """The :class:`PeriodicSolution` at point ``index``.

        Parameters
        ----------
        index : int
            Index of the point: an integer from ``-len(branch)`` to ``len(branch) - 1`` (negative counts from the
            end).
        """
        k = check_int("index", index, minimum=-len(self), maximum=len(self) - 1)
        vals = dict(self.values)
        vals[self.name] = float(self.parameter[k])
        coeffs = None
        if self.method == "harmonic balance":
            st = self.states[k]
            n = len(self.coordinates)
            m = 2 * int(self.size[k]) + 1
            coeffs = np.asarray(st[: n * m]).reshape(n, m)
        return PeriodicSolution(
            method=self.method,
            frequency=float(self.frequency[k]),
            amplitudes=tuple(float(a) for a in self.amplitudes[k]),
            residual=float(self.residual[k]),
            multipliers=self.multipliers[k],
            stable=bool(self.stable[k]),
            values=vals,
            coefficients=coeffs,
            initial_state=self.initial_states[k],
            size=int(self.size[k]),
            coordinates=self.coordinates,
            tolerance=self.tolerance,
        )

    @plot_method
    def plot(self, *, y: str = "amplitude", ax: Any = None) -> Any:
        """Draw the branch: stable parts solid, unstable parts dashed, bifurcations marked.

        Parameters
        ----------
        y : {"amplitude", "frequency", "period"}, optional
            What to draw against the parameter: one of these names (default "amplitude").
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
        """
        check_choice("y", y, ("amplitude", "frequency", "period"))
        ax = new_axes(ax)
        ys = {"amplitude": self.amplitude, "frequency": self.frequency, "period": 2 * np.pi / self.frequency}[y]
        x = self.parameter
        color = None
        start = 0
        for k in range(1, len(x) + 1):
            if k == len(x) or self.stable[k] != self.stable[start]:
                stop = min(k + 1, len(x))
                style = "-" if self.stable[start] else "--"
                (line,) = ax.plot(x[start:stop], ys[start:stop], style, color=color, lw=1.6)
                color = line.get_color()
                start = k
        for b in self.bifurcations:
            yb = {"amplitude": b.amplitude, "frequency": b.frequency, "period": 2 * np.pi / b.frequency}[y]
            ax.plot([b.parameter], [yb], "o", mfc="none", color="k")
            ax.annotate(_SHORT[b.kind], (b.parameter, yb), textcoords="offset points", xytext=(4, 4), fontsize=8)
        ax.set_xlabel(self.name)
        ax.set_ylabel(
            {
                "amplitude": f"max |{self.coordinates[0] if self.coordinates else 'q'}|",
                "frequency": "angular frequency (rad/s)",
                "period": "period (s)",
            }[y]
        )
        ax.set_title(f"{self.method}: solid stable, dashed unstable")
        return ax

    def to_xarray(self) -> Any:
        """The branch as an ``xarray.Dataset`` over the point index (extra ``symosc[labelled]``)."""
        try:
            import xarray as xr
        except ImportError as err:  # pragma: no cover - depends on the environment
            raise ImportError("to_xarray() needs xarray: pip install 'symosc[labelled]'") from err
        n_mult = self.multipliers.shape[1] if self.multipliers.ndim == 2 else 0
        ds = xr.Dataset(
            {
                "amplitude": ("point", self.amplitude),
                "frequency": ("point", self.frequency),
                "stable": ("point", self.stable),
                "residual": ("point", self.residual),
                "size": ("point", self.size),
                "amplitudes": (("point", "coordinate"), self.amplitudes),
                "multipliers": (("point", "multiplier"), self.multipliers),
            },
            coords={
                self.name: ("point", self.parameter),
                "point": np.arange(len(self)),
                "coordinate": list(self.coordinates),
                "multiplier": np.arange(n_mult),
            },
            attrs={
                "method": self.method,
                "parameter": self.name,
                "stopped": self.stopped,
                "bifurcations": [f"{b.kind} at {self.name}={b.parameter!r}" for b in self.bifurcations],
            },
        )
        return ds
