"""One-call simulation of mechanical models: :class:`Trajectory` and the integrator behind ``simulate``.

``LagrangianSystem.simulate``, ``FirstOrderSystem.simulate`` and ``LinearModel.simulate`` integrate the compiled
equations of motion (generated C with the analytic Jacobian where a compiler exists, NumPy otherwise) from an
initial state given by coordinate name, and return a :class:`Trajectory`: times, coordinates and velocities by
name, the energy (or the Jacobi integral) and its drift where it is conserved, tables (xarray/pandas), a plot and an
animation.  The default integrator is LSODA (``scipy.integrate.odeint``: Adams or BDF chosen automatically, the
analytic Jacobian used when it switches to BDF), the integrator PyDy's ``System.integrate`` uses; ``DOP853``,
``RK45``, ``Radau`` and ``BDF`` go through ``scipy.integrate.solve_ivp``.
"""

from __future__ import annotations

import time as _time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from .._plotting import new_axes, plot_method, tex_name
from .._printing import SymPyPrintable
from .._validate import check_choice, check_finite_array, check_positive, validated
from ..errors import ConvergenceError, ModelError, ParameterError

__all__ = ["METHODS", "Geometry", "Trajectory", "integrate_state"]

#: integrators accepted by ``simulate(method=...)``
METHODS = ("LSODA", "DOP853", "RK45", "Radau", "BDF")


@dataclass(frozen=True)
class Geometry(SymPyPrintable):
    """Where a model's bodies are, for animations: named points in a plane and the lines between them.

    Attributes
    ----------
    points : dict
        Point name -> ``(horizontal, vertical)`` SymPy expressions in the coordinates, the parameters and time
        :data:`symosc.t` (a vibrating pivot moves with ``t``).
    lines : tuple of tuple of str
        Pairs of point names joined by a line (links, springs, edges of a body).
    masses : tuple of str
        Points drawn as bodies (filled circles); the others are drawn as hinges, except those whose name starts with
        an underscore (bends of a line, such as the coils of a spring).
    fixed : tuple of str
        Points drawn as supports (a short hatched ground line under them).

    Examples
    --------
    >>> import sympy as sp
    >>> phi, l = sp.symbols("phi l")
    >>> g = Geometry({"O": (0, 0), "bob": (l * sp.sin(phi), -l * sp.cos(phi))}, (("O", "bob"),), ("bob",), ("O",))
    >>> sorted(g.points)
    ['O', 'bob']

    See Also
    --------
    Trajectory.animate
    """

    points: dict
    lines: tuple = ()
    masses: tuple = ()
    fixed: tuple = ()

    def __post_init__(self) -> None:
        if not isinstance(self.points, Mapping) or not self.points:
            raise ParameterError(
                f"Geometry(): points must be a dict of point name -> (horizontal, vertical), got {self.points!r}"
            )
        for key, value in self.points.items():
            if isinstance(value, str | bytes) or not (isinstance(value, Sequence) and len(value) == 2):
                raise ParameterError(
                    f"Geometry(): point {key!r} must be a pair (horizontal, vertical) of expressions, got {value!r}"
                )
        for what in ("lines", "masses", "fixed"):
            value = getattr(self, what)
            if isinstance(value, str | bytes) or not isinstance(value, Sequence):
                raise ParameterError(f"Geometry(): {what} must be a tuple of point names, got {value!r}")
        for pair in self.lines:
            if isinstance(pair, str | bytes) or not (isinstance(pair, Sequence) and len(pair) == 2):
                raise ParameterError(f"Geometry(): each line must be a pair of point names, got {pair!r}")
        pts = {str(k): (sp.sympify(v[0]), sp.sympify(v[1])) for k, v in self.points.items()}
        for pair in self.lines:
            for name in pair:
                if name not in pts:
                    raise ParameterError(f"line {pair} names the point {name!r}, which is not in points {list(pts)}")
        for name in (*self.masses, *self.fixed):
            if name not in pts:
                raise ParameterError(f"{name!r} is not one of the points {list(pts)}")
        object.__setattr__(self, "points", pts)
        object.__setattr__(self, "lines", tuple(tuple(p) for p in self.lines))

    def __repr__(self) -> str:
        return f"Geometry(points: {', '.join(self.points)}; {len(self.lines)} lines)"

    def positions(self, times: np.ndarray, states: np.ndarray, coordinates: tuple, values: Mapping) -> dict:
        """Point name -> array ``(len(times), 2)`` of positions along a trajectory.

        Parameters
        ----------
        times : ndarray, shape (k,)
            Times (a moving pivot depends on them).
        states : ndarray, shape (k, >= n)
            The coordinates in the first ``n`` columns (velocities may follow).
        coordinates : tuple of str or Symbol
            Coordinate names, in the order of the columns.
        values : mapping
            Values of the parameters the points depend on.

        Returns
        -------
        dict of str to ndarray
        """
        from ..numeric import compile, resolve
        from ..symbols import t

        names = list(self.points)
        exprs = [e for name in names for e in self.points[name]]
        coords = [sp.Symbol(c) if isinstance(c, str) else c for c in coordinates]
        by_name = {c.name: c for c in coords}
        free = set().union(*(e.free_symbols for e in exprs)) - {t}
        # coordinates may be declared real in the model and plain here: match them by name
        exprs = [e.xreplace({s: by_name[s.name] for s in e.free_symbols if s.name in by_name}) for e in exprs]
        params = sorted((s for s in free if s.name not in by_name), key=lambda s: s.name)
        fn = compile(exprs, [t, *coords, *params], name="geometry", check=False)
        pvals = [float(v) for v in resolve(params, values)]
        k = len(times)
        cols = [np.asarray(times, float)] + [states[:, i] for i in range(len(coords))]
        out = np.asarray(fn.raw(*cols, *pvals), dtype=float)  # (k, points * 2) for k states
        out = np.broadcast_to(out.reshape(-1, len(exprs)), (k, len(exprs))).T
        return {name: np.stack([out[2 * i], out[2 * i + 1]], axis=1) for i, name in enumerate(names)}


@dataclass(frozen=True)
class Trajectory(SymPyPrintable):
    """A simulated motion: states at the output times, energy and how the integration went.

    Attributes
    ----------
    t : ndarray, shape (k,)
        Output times (s).
    states : ndarray, shape (k, 2n)
        ``(q, q')`` at each output time.
    coordinates : tuple of str
        Coordinate names, in the order of the state.
    values : dict
        Parameter values used (name -> float).
    energy : ndarray or None, shape (k,)
        The model's energy ``T + V`` (or its Jacobi integral ``T2 - T0 + V``) along the motion, None when the model
        has no energy function.
    energy_name : str
        What :attr:`energy` is: ``"energy"``, ``"Jacobi integral"`` or ``"energy (not conserved)"``.
    conserved : bool
        True when :attr:`energy` is a first integral of the equations (no dissipation, forces or explicit time).
    method : str
        Integrator used.
    rtol, atol : float
        Its tolerances.
    nfev : int
        Number of right-hand-side evaluations.
    seconds : float
        Wall-clock time of the integration (evaluator build included).
    geometry : Geometry or None
        Points and lines for :meth:`animate` (catalogue models carry one).

    Examples
    --------
    >>> import numpy as np
    >>> from symosc.models import n_link_pendulum
    >>> pend = n_link_pendulum(1)
    >>> traj = pend.simulate(np.linspace(0, 2, 5), {"phi1": 0.1}, {"m1": 1.0, "l1": 1.0, "g": 9.81})
    >>> traj.q["phi1"].shape, bool(traj.energy_drift < 1e-8)
    ((5,), True)

    See Also
    --------
    symosc.mechanics.LagrangianSystem.simulate
    """

    t: np.ndarray
    states: np.ndarray = field(repr=False)
    coordinates: tuple
    values: dict = field(repr=False)
    energy: np.ndarray | None = field(repr=False)
    energy_name: str = "energy"
    conserved: bool = False
    method: str = "LSODA"
    rtol: float = 1e-9
    atol: float = 1e-11
    nfev: int = 0
    seconds: float = 0.0
    geometry: Geometry | None = field(default=None, repr=False)

    def __repr__(self) -> str:
        drift = f", {self.energy_name} drift {self.energy_drift:.2g}" if self.energy_drift is not None else ""
        return (
            f"Trajectory({', '.join(self.coordinates)}; t = {self.t[0]:.6g} .. {self.t[-1]:.6g} s, {self.t.size} "
            f"points; {self.method}, rtol={self.rtol:g}, {self.nfev} evaluations{drift})"
        )

    @property
    def q(self) -> dict[str, np.ndarray]:
        """Coordinate name -> values over :attr:`t`."""
        return {c: self.states[:, i] for i, c in enumerate(self.coordinates)}

    @property
    def qd(self) -> dict[str, np.ndarray]:
        """Coordinate name -> velocity over :attr:`t` (also reachable as ``traj["<name>_dot"]``)."""
        n = len(self.coordinates)
        return {c: self.states[:, n + i] for i, c in enumerate(self.coordinates)}

    def __getitem__(self, name: str) -> np.ndarray:
        """A coordinate, a velocity (``"<name>_dot"``) or ``"energy"`` by name."""
        if name in self.q:
            return self.q[name]
        if name.endswith("_dot") and name[:-4] in self.qd:
            return self.qd[name[:-4]]
        if name == "energy" and self.energy is not None:
            return self.energy
        valid = [*self.coordinates, *(f"{c}_dot" for c in self.coordinates)]
        valid += ["energy"] if self.energy is not None else []
        raise KeyError(f"{name!r} is not an output of this trajectory; outputs: {', '.join(valid)}")

    @property
    def energy_drift(self) -> float | None:
        """``max |E(t) - E(t0)| / max(|E(t0)|, max |E(t) - E_min|)`` when the energy is conserved, else None.

        The denominator falls back to the energy's range along the motion when ``E(t0)`` is zero (a potential
        measured from the initial position).
        """
        if not self.conserved or self.energy is None:
            return None
        e = self.energy
        scale = max(abs(float(e[0])), float(np.ptp(e)), np.finfo(float).tiny)
        return float(np.max(np.abs(e - e[0])) / scale)

    def to_pandas(self) -> Any:
        """A ``pandas.DataFrame`` indexed by time: coordinates, velocities (``<name>_dot``) and the energy."""
        import pandas as pd

        return pd.DataFrame(self._columns(), index=pd.Index(self.t, name="t"))

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset`` over the dimension ``t`` (units in the attributes)."""
        import xarray as xr

        data = {k: ("t", v) for k, v in self._columns().items()}
        ds = xr.Dataset(data, coords={"t": ("t", self.t, {"units": "s"})})
        ds.attrs.update({"method": self.method, "rtol": self.rtol, "atol": self.atol})
        return ds

    def _columns(self) -> dict[str, np.ndarray]:
        cols = dict(self.q)
        cols.update({f"{c}_dot": v for c, v in self.qd.items()})
        if self.energy is not None:
            cols["energy"] = self.energy
        return cols

    @plot_method
    def plot(self, what: str = "coordinates", *, ax: Any = None) -> Any:
        """Coordinates (default), velocities or the energy against time, one labelled line each.

        Parameters
        ----------
        what : {"coordinates", "velocities", "energy"}
            What to draw.  ``"energy"`` draws ``E(t) - E(t0)`` when the energy is conserved (its drift).
        ax : matplotlib Axes, optional
            Draw here; a new figure otherwise.

        Returns
        -------
        matplotlib Axes
        """
        check_choice("what", what, ("coordinates", "velocities", "energy"))
        ax = new_axes(ax, figsize=(6.5, 3.8))
        if what == "energy":
            if self.energy is None:
                raise ParameterError("this trajectory has no energy to plot")
            e = self.energy - self.energy[0] if self.conserved else self.energy
            label = f"{self.energy_name} - initial" if self.conserved else self.energy_name
            ax.plot(self.t, e, label=label)
            ax.set_ylabel(label)
        else:
            series = self.q if what == "coordinates" else self.qd
            for name, v in series.items():
                ax.plot(self.t, v, label=tex_name(name, dot=what == "velocities"))
            ax.set_ylabel("coordinates" if what == "coordinates" else "velocities")
        ax.set_xlabel("time $t$, s")
        ax.grid(True, lw=0.4, alpha=0.5)
        ax.legend(loc="best", fontsize=9)
        return ax

    def animate(
        self,
        path: str | None = None,
        *,
        fps: float = 25.0,
        speed: float = 1.0,
        max_frames: int = 400,
        trail: float = 0.0,
        geometry: Geometry | None = None,
        dpi: int = 80,
        size: float = 4.0,
    ) -> Any:
        """Animate the motion with matplotlib (frame times follow simulated time).

        Parameters
        ----------
        path : str, optional
            Write the animation: ``.gif`` through Pillow, ``.mp4`` through ffmpeg (when installed), ``.html``
            as a self-contained JavaScript player.
        fps : float
            Frames per second of the animation.
        speed : float
            Simulated seconds per second of animation (``0.1``: ten times slower than real time).
        max_frames : int
            Upper bound on the number of frames; a longer motion is shown with a lower frame rate, its frame
            interval still equal to the simulated time step divided by ``speed``.
        trail : float
            Draw the path of the last mass point over this many simulated seconds (0: none).
        geometry : Geometry, optional
            Points and lines to draw, when the model carries none (any :class:`LagrangianSystem`).
        dpi : int
            Resolution of written frames.
        size : float
            Figure size in inches (square).

        Returns
        -------
        symosc.visual.Animation
            Shown as a JavaScript player in notebooks (``_repr_html_``); ``.save(path)`` writes it.

        Examples
        --------
        >>> import numpy as np
        >>> from symosc.models import n_link_pendulum
        >>> traj = n_link_pendulum(2).simulate(np.linspace(0, 1, 11), {"phi1": 0.5},
        ...                                    {"m1": 1, "m2": 1, "l1": 1, "l2": 1, "g": 9.81})
        >>> anim = traj.animate(fps=10)
        >>> anim.frames
        11

        See Also
        --------
        Geometry, plot
        """
        from ..visual.animation import animate_trajectory

        return animate_trajectory(
            self, path, fps=fps, speed=speed, max_frames=max_frames, trail=trail, geometry=geometry, dpi=dpi, size=size
        )


# ---------------------------------------------------------------------------------------- integration
def initial_state(coordinates: tuple, initial: Mapping[Any, Any] | np.ndarray) -> np.ndarray:
    """The state ``(q, q')`` from a mapping (coordinate name -> value, ``"<name>_dot"`` -> velocity) or an array
    (the full state, or the coordinates alone with zero velocities)."""
    n = len(coordinates)
    if not isinstance(initial, Mapping):
        y0 = check_finite_array("initial", initial, ndim=1)
        if y0.shape == (n,):  # coordinates only: at rest
            return np.concatenate([y0.astype(float), np.zeros(n)])
        if y0.shape != (2 * n,):
            raise ParameterError(
                f"initial must be a mapping by name, the coordinates ({n},) or a state ({2 * n},), got {y0.shape}"
            )
        return y0.astype(float)
    names = [c if isinstance(c, str) else c.name for c in coordinates]
    slots = {name: i for i, name in enumerate(names)}
    slots.update({f"{name}_dot": n + i for i, name in enumerate(names)})
    y0 = np.zeros(2 * n)
    for key, value in initial.items():
        name = key.name if isinstance(key, sp.Symbol) else str(key)
        if name not in slots:
            raise ParameterError(
                f"initial names {name!r}, which is neither a coordinate nor a velocity; valid: {', '.join(slots)}"
            )
        try:
            v = float(value)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"initial[{name!r}] must be a number, got {value!r}") from exc
        if not np.isfinite(v):
            raise ParameterError(f"initial[{name!r}] must be finite, got {v}")
        y0[slots[name]] = v
    return y0


def output_times(t: Any) -> np.ndarray:
    """``t`` as an increasing array of output times (a positive scalar ``T`` means 0..T with 1001 points)."""
    if np.ndim(t) == 0:
        T = check_positive("t", t)
        return np.linspace(0.0, T, 1001)
    times = check_finite_array("t", t, ndim=1)
    if times.size < 2 or np.any(np.diff(times) <= 0):
        raise ParameterError(f"t must hold at least two strictly increasing output times, got {times.size} values")
    return times.astype(float)


@validated
def integrate_state(
    rhs: Callable,
    jac: Callable | None,
    times: np.ndarray,
    y0: np.ndarray,
    *,
    method: str = "LSODA",
    rtol: float = 1e-9,
    atol: float = 1e-11,
) -> tuple[np.ndarray, int]:
    """Integrate ``y' = rhs(t, y)`` from ``y0`` at ``times[0]``; returns the states at ``times`` and the count of
    right-hand-side evaluations.

    Parameters
    ----------
    rhs : callable
        ``rhs(t, y)``.
    jac : callable or None
        ``jac(t, y)``, the analytic Jacobian (LSODA when stiff, Radau, BDF).
    times : ndarray
        Increasing output times.
    y0 : ndarray
        Initial state.
    method : {"LSODA", "DOP853", "RK45", "Radau", "BDF"}
        Integrator (LSODA through ``scipy.integrate.odeint``, the others through ``solve_ivp``).
    rtol, atol : float
        Relative and absolute tolerances.

    Returns
    -------
    states : ndarray, shape (len(times), len(y0))
    nfev : int

    Raises
    ------
    ConvergenceError
        When the integrator stops before the last time (too much work, step size underflow).

    Examples
    --------
    >>> import numpy as np
    >>> y, nfev = integrate_state(lambda t, y: -y, None, np.array([0.0, 1.0]), np.array([1.0]))
    >>> bool(abs(y[-1, 0] - np.exp(-1)) < 1e-8)
    True
    """
    check_choice("method", method, METHODS)
    rtol, atol = check_positive("rtol", rtol), check_positive("atol", atol)
    if method == "LSODA":
        import warnings

        from scipy.integrate import ODEintWarning, odeint

        with warnings.catch_warnings():  # a failure is raised below as ConvergenceError, with the reason
            warnings.simplefilter("ignore", ODEintWarning)
            y, info = odeint(
                rhs, y0, times, Dfun=jac, rtol=rtol, atol=atol, tfirst=True, full_output=True, mxstep=200_000
            )
        if info["message"] != "Integration successful.":
            reached = float(info["tcur"][info["tcur"] > 0].max()) if np.any(info["tcur"] > 0) else float(times[0])
            raise ConvergenceError(
                f"LSODA stopped near t = {reached:g} before t = {times[-1]:g}: {info['message']}; loosen rtol/atol, "
                "shorten t, or try method='Radau'"
            )
        return y, int(info["nfe"][-1])
    from scipy.integrate import solve_ivp

    kwargs = {"jac": jac} if method in ("Radau", "BDF") and jac is not None else {}
    sol = solve_ivp(rhs, (times[0], times[-1]), y0, method=method, t_eval=times, rtol=rtol, atol=atol, **kwargs)
    if not sol.success:
        raise ConvergenceError(
            f"{method} stopped at t = {sol.t[-1] if sol.t.size else times[0]:g} before t = {times[-1]:g}: "
            f"{sol.message}; loosen rtol/atol or try another method"
        )
    return sol.y.T.copy(), int(sol.nfev)


def simulate_lagrangian(
    system: Any,
    t: Any,
    initial: Any,
    values: Mapping[Any, Any],
    *,
    method: str,
    rtol: float,
    atol: float,
    backend: str,
    geometry: Geometry | None = None,
) -> Trajectory:
    """Implementation of :meth:`LagrangianSystem.simulate` and :meth:`FirstOrderSystem.simulate`."""
    start = _time.perf_counter()
    times = output_times(t)
    cache = system._simulation_cache  # the first-order form and the energy, compiled once per system
    fo = cache.get("first_order") or cache.setdefault("first_order", system.first_order())
    y0 = initial_state(system.coordinates, initial)
    if not isinstance(values, Mapping):
        raise ParameterError(f"values must be a mapping of parameter names to numbers, got {type(values).__name__}")
    rhs = fo.rhs(values, backend=backend)
    jac = fo.jacobian(values, backend=backend) if method in ("LSODA", "Radau", "BDF") else None
    states, nfev = integrate_state(rhs, jac, times, y0, method=method, rtol=rtol, atol=atol)
    energy, name, conserved = _energy_along(system, cache, values, times, states)
    used = _used_values(system.parameters, values)
    return Trajectory(
        t=times,
        states=states,
        coordinates=tuple(c.name for c in system.coordinates),
        values=used,
        energy=energy,
        energy_name=name,
        conserved=conserved,
        method=method,
        rtol=float(rtol),
        atol=float(atol),
        nfev=nfev,
        seconds=_time.perf_counter() - start,
        geometry=geometry if geometry is not None else getattr(system, "geometry", None),
    )


def _used_values(parameters: tuple, values: Mapping[Any, Any]) -> dict[str, float]:
    from ..numeric import resolve

    return {p.name: float(v) for p, v in zip(parameters, resolve(parameters, values), strict=True)}


def _energy_along(system: Any, cache: dict, values: Mapping, times: np.ndarray, states: np.ndarray):
    """``(E over t, its name, conserved)`` for a Lagrangian system (the compiled energy kept in ``cache``)."""
    from ..numeric import compile, resolve
    from ..symbols import t

    if "energy" not in cache:
        conserved_forces = system.dissipation == 0 and all(f == 0 for f in system.forces)
        _, T1, T0 = system.kinetic_energy_parts
        if not system.is_rheonomic and conserved_forces:
            expr, name, conserved = (
                (system.energy, "energy", True)
                if T1 == 0 and T0 == 0
                else (system.energy_function, "Jacobi integral", True)
            )
        else:
            expr, name, conserved = system.energy, "energy (not conserved)", False
        args = [t, *system.coordinates, *system.velocities, *system.parameters]
        cache["energy"] = (compile(expr, args, name="energy", check=False), name, conserved)
    fn, name, conserved = cache["energy"]
    p = [float(v) for v in resolve(system.parameters, values)]
    cols = [states[:, i] for i in range(states.shape[1])]
    e = np.broadcast_to(np.asarray(fn.raw(times, *cols, *p), dtype=float), times.shape).copy()
    return e, name, conserved


def simulate_linear(
    model: Any,
    t: Any,
    initial: Any,
    values: Mapping[Any, Any],
    *,
    method: str,
    rtol: float,
    atol: float,
    geometry: Geometry | None = None,
) -> Trajectory:
    """Implementation of :meth:`LinearModel.simulate`: ``M q'' + D q' + K(t) q = f(t)``."""
    from ..numeric import compile, resolve
    from ..symbols import t as time_symbol

    start = _time.perf_counter()
    times = output_times(t)
    y0 = initial_state(model.coordinates, initial)
    n = len(model.coordinates)
    if time_symbol in (model.M.free_symbols | model.D.free_symbols):
        raise ModelError("simulate() needs M and D independent of time (K and f may depend on t)")
    params = model.parameters
    pv = [float(v) for v in resolve(params, values)]
    args = [time_symbol, *params]
    const = compile(model.M.row_join(model.D), args, name="linear_MD")
    M, D = np.split(np.asarray(const(0.0, *pv), dtype=float).reshape(n, 2 * n), 2, axis=1)
    try:
        Minv = np.linalg.inv(M)
    except np.linalg.LinAlgError as exc:
        raise ModelError("the mass matrix is singular at these parameter values") from exc
    varying = time_symbol in (model.K.free_symbols | model.f.free_symbols)
    Kf = compile(model.K.row_join(model.f), args, name="linear_Kf")
    rhs = _LinearRhs(Minv, D, Kf.raw, pv, n, varying)
    states, nfev = integrate_state(rhs, rhs.jacobian, times, y0, method=method, rtol=rtol, atol=atol)
    qs, vs = states[:, :n], states[:, n:]
    K0 = rhs.K(0.0)
    conserved = not varying and not np.any(D) and np.allclose(K0, K0.T) and not np.any(rhs.f(0.0))
    energy = 0.5 * (np.einsum("ki,ij,kj->k", vs, M, vs) + np.einsum("ki,ij,kj->k", qs, K0, qs))
    return Trajectory(
        t=times,
        states=states,
        coordinates=tuple(c.name for c in model.coordinates),
        values={p.name: v for p, v in zip(params, pv, strict=True)},
        energy=energy,
        energy_name="energy" if conserved else "energy (not conserved)",
        conserved=bool(conserved),
        method=method,
        rtol=float(rtol),
        atol=float(atol),
        nfev=nfev,
        seconds=_time.perf_counter() - start,
        geometry=geometry,
    )


class _LinearRhs:
    """``y' = [[0, I], [-M^-1 K(t), -M^-1 D]] y + [0, M^-1 f(t)]`` with K(t), f(t) compiled (no closures)."""

    def __init__(self, Minv: np.ndarray, D: np.ndarray, Kf: Callable, pv: list, n: int, varying: bool) -> None:
        self.Minv, self.MinvD, self.Kf, self.pv, self.n, self.varying = Minv, Minv @ D, Kf, pv, n, varying
        self._const = None if varying else self._at(0.0)

    def _at(self, time: float) -> tuple[np.ndarray, np.ndarray]:
        n = self.n
        out = np.asarray(self.Kf(float(time), *self.pv), dtype=float).reshape(n, n + 1)
        return out[:, :n], out[:, n]

    def K(self, time: float) -> np.ndarray:
        return self._at(time)[0]

    def f(self, time: float) -> np.ndarray:
        return self._at(time)[1]

    def __call__(self, time: float, y: np.ndarray) -> np.ndarray:
        K, f = self._const if self._const is not None else self._at(time)
        n = self.n
        return np.concatenate([y[n:], self.Minv @ (f - K @ y[:n]) - self.MinvD @ y[n:]])

    def jacobian(self, time: float, y: np.ndarray) -> np.ndarray:
        K, _ = self._const if self._const is not None else self._at(time)
        n = self.n
        J = np.zeros((2 * n, 2 * n))
        J[:n, n:] = np.eye(n)
        J[n:, :n] = -self.Minv @ K
        J[n:, n:] = -self.MinvD
        return J
