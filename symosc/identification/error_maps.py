"""Error maps: identification error of the inertia parameters against the center-of-mass offset (Belyakov Figs 21–24).

Belyakov (2005), Ch. III §3.2: the body of Tables 1–2 is moved so that its center of mass sits at an
offset ``(dx, dz)`` from the center of stiffness of the stand; its free response after the release of a static force
(the linear 3-DOF modal model) gets white noise of a given level, a signal estimator identifies the modes, and a
reconstruction algorithm returns the inertia parameters.  The Monte Carlo mean of the relative errors over a grid of
offsets is the error map (Figs 21–22); the smallest modal energy of the release over the same grid is the
applicability map (Figs 23–24: "a low-energy mode drowns in noise"; criterion min energy > half the mean).

The noise runs go through :func:`symosc.sweep` (``executor=`` chooses serial, a process pool or a Dask cluster; the
default ``"auto"`` measures the first runs and decides); every run has its own seed, so the map does not depend on
the executor.
"""

from __future__ import annotations

import functools
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._plotting import plot_method
from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ParameterError, SymoscError
from ..numeric import bind
from ._sweeping import raise_first_failure
from .reconstruction import inertia_equal_springs, inertia_from_release, inertia_known_center
from .signals.era import era
from .signals.noise import add_noise

__all__ = ["ErrorMap", "error_map"]

#: The body and stand of Belyakov's Tables 1–2 (rx, rz are set from the offsets).
STAND = dict(m=15000.0, Izz=44000.0, Ixx=3000.0, Ixz=400.0, Lx=4.0, Lz=1.74, k1=7.4e5, k2=7.4e5, k3=7.4e5, k4=7.4e5)
_PARAMS = ("m", "rx", "rz", "Izz", "Ixx", "Ixz")
_ALGORITHMS = ("1", "2.1", "2.2")


@dataclass(frozen=True, repr=False, eq=False)
class ErrorMap(SymPyPrintable):
    """Relative errors of identified inertia parameters over a grid of center-of-mass offsets and noise levels.

    Attributes
    ----------
    dx, dz : ndarray
        Offsets (m) of the center of mass from the center of stiffness along x and z.
    noise : ndarray
        Noise levels (standard deviation as a fraction of ``reference``).
    names : tuple of str
        Parameters whose errors are mapped.
    errors : ndarray, shape (noise, dx, dz, runs, names)
        ``|estimate - truth| / |truth|`` per run; NaN where the pipeline failed.
    failures : ndarray, shape (noise, dx, dz)
        Number of failed runs (identification or reconstruction errors).
    energies : ndarray, shape (dx, dz, 3)
        Modal energies ``K'_ii / 2`` (J) stored by the released force.
    condition : ndarray, shape (dx, dz)
        Condition number of Algorithm 2.2 on exact data (``inf`` where it is ill-posed); 1 for the others.
    algorithm : str
        ``"1"``, ``"2.1"`` or ``"2.2"``.
    """

    dx: np.ndarray
    dz: np.ndarray
    noise: np.ndarray
    names: tuple[str, ...]
    errors: np.ndarray
    failures: np.ndarray
    energies: np.ndarray
    condition: np.ndarray
    algorithm: str

    @property
    def mean(self) -> np.ndarray:
        """Mean relative error, shape (noise, dx, dz, names); failed runs are ignored (NaN if all failed)."""
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            return np.nanmean(self.errors, axis=3)

    @property
    def min_energy(self) -> np.ndarray:
        """Smallest modal energy of the release (J), shape (dx, dz) (Figs 23–24)."""
        return self.energies.min(axis=-1)

    @property
    def applicable(self) -> np.ndarray:
        """Belyakov's criterion for Algorithm 1: min modal energy > half the mean modal energy, shape (dx, dz)."""
        return self.min_energy > 0.5 * self.energies.mean(axis=-1)

    @plot_method
    def plot(self, name: str | None = None, *, noise_index: int = -1, energy: bool = False, ax: Any = None) -> Any:
        """Contour map in 1 % bands up to 10 % (Figs 21–22), or of the min modal energy (``energy=True``, Figs 23–24).

        The energy map draws the applicability level (half the mean modal energy) as a dashed line.

        Parameters
        ----------
        name : str, optional
            Parameter whose mean error is drawn; must be one of ``names`` (default: the first of them).
        noise_index : int, optional
            Index into ``noise`` of the level to draw (default -1: the highest level given).
        energy : bool, optional
            Draw the minimum modal energy of the release (Figs 23–24) instead of the error (default False).
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
        """
        from .._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        if energy:
            cs = ax.contourf(self.dx, self.dz, self.min_energy.T, levels=12, cmap="viridis")
            level = 0.5 * float(self.energies.mean())
            if self.min_energy.min() < level < self.min_energy.max():
                ax.contour(self.dx, self.dz, self.min_energy.T, levels=[level], colors="w", linestyles="--")
            ax.figure.colorbar(cs, ax=ax, label="min modal energy (J)")
            ax.set_title("minimum modal energy of the release")
        else:
            n = self.names[0] if name is None else name
            e = 100 * self.mean[noise_index, :, :, self.names.index(n)]
            cs = ax.contourf(self.dx, self.dz, e.T, levels=np.arange(11), extend="max", cmap="RdYlGn_r")
            ax.figure.colorbar(cs, ax=ax, label=f"mean |error| of {n} (%)")
            ax.set_title(f"Algorithm {self.algorithm}, noise {100 * self.noise[noise_index]:.3g} %")
        ax.plot(0, 0, "k+", ms=10)
        ax.set_xlabel("CM offset along x (m)")
        ax.set_ylabel("CM offset along z (m)")
        return ax

    def __repr__(self) -> str:
        head = (
            f"ErrorMap(algorithm={self.algorithm!r}, grid={self.dx.size}x{self.dz.size}, "
            f"runs={self.errors.shape[3]}, noise={np.round(100 * self.noise, 4).tolist()} %, "
            f"failures={int(self.failures.sum())})"
        )
        rows = [f"  mean |error| % of {self.names[0]} at noise {100 * self.noise[-1]:.3g} % (rows dx, columns dz)"]
        rows.append("  " + " " * 9 + " ".join(f"{z:>9.3g}" for z in self.dz))
        e = 100 * self.mean[-1, :, :, 0]
        rows += [f"  {x:>8.3g} " + " ".join(f"{v:>9.3g}" for v in row) for x, row in zip(self.dx, e, strict=True)]
        return "\n".join([head, *rows])


def _reconstruct(algorithm: str, omega, modes, truth, force, positions, poi):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # Algorithm 2.2's conditioning warning
        if algorithm == "1":
            return inertia_from_release(omega, modes, force, positions, product_of_inertia=poi)
        if algorithm == "2.1":
            return inertia_equal_springs(omega, modes, truth["m"], positions, product_of_inertia=poi)
        center = (truth["rx"], truth["rz"])
        return inertia_known_center(omega, modes, truth["m"], center, positions, product_of_inertia=poi)


def _default_estimator(y: np.ndarray, step: float, rows: int) -> Any:
    return era(y, step, 3, constant=False, hankel_size=rows)


@dataclass(frozen=True, eq=False)
class _MapRuns:
    """Everything one noise run of :func:`error_map` needs (picklable: sent once per chunk to a worker)."""

    levels: np.ndarray
    clean: np.ndarray  # (dx, dz, channels, samples)
    points: list  # [a][b] -> parameter dict
    names: tuple[str, ...]
    algorithm: str
    force: tuple
    positions: tuple
    poi: str
    reference: float
    dt: float
    seed: int
    estimator: Callable[[np.ndarray, float], Any]


def _error_map_run(level_index: int, a: int, b: int, run: int, *, ctx: _MapRuns) -> np.ndarray:
    """Relative errors of one noise run, then a failure flag (1.0 when the pipeline failed, errors NaN)."""
    level = ctx.levels[level_index]
    clean = ctx.clean[a, b]
    point = ctx.points[a][b]
    rng = np.random.default_rng([ctx.seed, level_index, a, b, run])
    y = add_noise(clean, level=level, reference=ctx.reference, rng=rng) if level > 0 else clean
    out = np.full(len(ctx.names) + 1, np.nan)
    try:
        est = ctx.estimator(y, ctx.dt)
        omega, modes = est.undamped_frequencies, est.mode_shapes
        res = _reconstruct(ctx.algorithm, omega, modes, point, ctx.force, ctx.positions, ctx.poi).as_dict()
        res["m"] = res["mass"]
    except (SymoscError, np.linalg.LinAlgError):
        out[-1] = 1.0
        return out
    truth = np.array([point[n] for n in ctx.names])
    out[:-1] = np.abs(np.array([res[n] for n in ctx.names]) - truth) / np.abs(truth)
    out[-1] = 0.0
    return out


@validated
def error_map(
    dx: Any,
    dz: Any,
    *,
    noise: Any = 0.06,
    algorithm: str = "1",
    runs: int = 5,
    values: Mapping[str, float] | None = None,
    force: Sequence[float] = (0.0, -2000.0, 0.0, 0.0),
    dt: float = 3 * 0.02212,
    n_samples: int = 418,
    reference: float = 0.00067,
    estimator: Callable[[np.ndarray, float], Any] | None = None,
    names: Sequence[str] = ("Izz", "Ixx"),
    product_of_inertia: str = "dissertation",
    seed: int = 0,
    executor: Any = "auto",
    progress: bool | None = None,
) -> ErrorMap:
    """Monte Carlo error map of an identification pipeline over center-of-mass offsets (Belyakov Figs 21–24).

    Parameters
    ----------
    dx, dz : array_like
        Offsets (m) of the center of mass from the center of stiffness along x and z (the dissertation maps
        ±0.4 m by ±0.3 m).
    noise : float or array_like
        White-noise standard deviation(s) as a fraction of ``reference`` (6 % is the dissertation's admissible level).
    algorithm : {"1", "2.1", "2.2"}
        Reconstruction: known released force, equal springs and known mass, or known mass and center of mass.
    runs : int
        Noise realisations per grid point; run i at noise index l and point (a, b) uses seed (seed, l, a, b, i).
    values : mapping, optional
        Body and stand (``m, Izz, Ixx, Ixz, Lx, Lz, k1..k4``; rx, rz are set from the offsets). Default: Tables 1–2.
    force : sequence of 4 floats
        Vertical forces (N) released at t = 0 (default 2000 N pressing spring 2 down).
    dt : float
        Sampling period of the record (s); must be positive (default: the dissertation's 0.02212 s decimated by 3).
    n_samples : int
        Number of samples per record; a positive integer (default 418: 27.7 s at the default ``dt``).
    reference : float
        Noise reference amplitude (m); Belyakov uses the modal amplitude 0.00067 m.
    estimator : callable, optional
        ``estimator(signals, dt) -> ModalEstimate``; default Kung/ERA with 3 modes, no offset,
        ``n_samples / 10`` block rows (10 to 40).
    names : sequence of str
        Parameters to map, from ``m, rx, rz, Izz, Ixx, Ixz``.
    product_of_inertia : str
        Sign convention of Ixz (see ``body_on_springs``).
    seed : int
        Base seed.
    executor : "auto", "serial", "processes", Executor or distributed.Client
        Where the noise runs go (see :func:`symosc.sweep`); the result does not depend on it.
    progress : bool, optional
        Progress bar (default: when stderr is a terminal).

    Returns
    -------
    ErrorMap

    See Also
    --------
    symosc.sweep, error_vs_noise

    Examples
    --------
    >>> em = error_map([-0.4, 0.0], [0.0], noise=0.06, runs=2, n_samples=200)
    >>> em.errors.shape, em.min_energy.round(3).tolist()
    ((1, 2, 1, 2, 2), [[0.083], [0.632]])
    """
    from ..models import body_on_springs

    if algorithm not in _ALGORITHMS:
        raise ParameterError(f"algorithm must be one of {_ALGORITHMS}, got {algorithm!r}")
    bad = [n for n in names if n not in _PARAMS]
    if bad or not names:
        raise ParameterError(f"names must be taken from {_PARAMS}, got {tuple(names)!r}")
    if int(runs) != runs or runs < 1:
        raise ParameterError(f"runs must be a positive integer, got {runs!r}")
    gx, gz = (np.atleast_1d(np.asarray(g, dtype=float)) for g in (dx, dz))
    lv = np.atleast_1d(np.asarray(noise, dtype=float))
    for label, g in (("dx", gx), ("dz", gz), ("noise", lv)):
        if g.ndim != 1 or not np.all(np.isfinite(g)):
            raise ParameterError(f"{label} must be a finite scalar or 1-D array, got {g!r}")
    if np.any(lv < 0):
        raise ParameterError(f"noise levels must be >= 0, got {lv.tolist()}")
    poi = product_of_inertia
    model = body_on_springs(product_of_inertia=poi)
    vals = {str(k): float(v) for k, v in (STAND if values is None else values).items() if str(k) not in ("rx", "rz")}
    xs, zs = (float(bind(e, vals)) for e in model.vertical_stiffness_center())
    positions = (vals["Lx"], vals["Lz"])
    if estimator is None:
        estimator = functools.partial(_default_estimator, rows=max(10, min(40, int(n_samples) // 10)))
    t = np.arange(int(n_samples)) * float(dt)
    energies = np.empty((gx.size, gz.size, 3))
    cond = np.ones((gx.size, gz.size))
    points = [[None] * gz.size for _ in range(gx.size)]
    clean = None
    for a, ox in enumerate(gx):
        for b, oz in enumerate(gz):
            point = dict(vals, rx=xs + ox, rz=zs + oz)
            points[a][b] = point
            data = model.modal(point, force=force)
            energies[a, b] = data.modal_energy()
            if algorithm == "2.2":
                try:
                    exact = _reconstruct("2.2", data.omega, data.observation, point, force, positions, poi)
                    cond[a, b] = exact.condition
                except SymoscError:
                    cond[a, b] = np.inf
            response = data.response(t).T
            if clean is None:
                clean = np.empty((gx.size, gz.size, *response.shape))
            clean[a, b] = response
    from ..sweep import sweep

    ctx = _MapRuns(
        lv,
        clean,
        points,
        tuple(names),
        algorithm,
        tuple(force),
        positions,
        poi,
        float(reference),
        float(dt),
        int(seed),
        estimator,
    )
    grid = {
        "level_index": np.arange(lv.size),
        "a": np.arange(gx.size),
        "b": np.arange(gz.size),
        "run": np.arange(int(runs)),
    }
    res = sweep(_error_map_run, grid, executor=executor, constants={"ctx": ctx}, progress=progress)
    raise_first_failure(res, "error_map")
    errs = res.values[..., :-1]
    fails = res.values[..., -1].sum(axis=-1).astype(int)
    return ErrorMap(gx, gz, lv, tuple(names), errs, fails, energies, cond, algorithm)
