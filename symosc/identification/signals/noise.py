"""Noise studies: white-noise injection, the Cramér–Rao bound for damped sinusoids, Monte Carlo runs, and
Belyakov's applicability criterion (Ch. III §3.2).

The Monte Carlo runs go through :func:`symosc.sweep` (``executor=``: serial, a process pool or a Dask cluster);
each run has its own seed, so results do not depend on the executor.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._plotting import plot_method
from ..._printing import SymPyPrintable
from ..._validate import check_finite, check_finite_array, check_int, check_memory, check_positive, validated
from ...errors import IdentificationError, ParameterError
from ._signals import ModalEstimate, _as_signals

__all__ = [
    "ApplicabilityCheck",
    "CramerRaoBound",
    "ErrorVsNoise",
    "MonteCarloResult",
    "add_noise",
    "applicability",
    "cramer_rao_bound",
    "error_vs_noise",
    "monte_carlo",
    "noise_sigma",
]


@validated
def noise_sigma(signals: Any, snr_db: float) -> float:
    """Standard deviation of white noise giving ``snr_db`` = 10 log10(mean(s**2) / sigma**2) on clean ``signals``.

    Parameters
    ----------
    signals : array_like, shape (samples,) or (channels, samples)
        Clean sampled record; finite real numbers.
    snr_db : float
        Signal-to-noise power ratio in decibels over all channels; a finite number (may be negative).

    Returns
    -------
    float

    Examples
    --------
    >>> noise_sigma([1.0, -1.0, 1.0, -1.0], 20.0)
    0.1
    """
    s = check_finite_array("signals", signals)
    if s.size == 0:
        raise ParameterError("signals must hold at least one sample")
    return float(np.sqrt(np.mean(s**2) / 10 ** (check_finite("snr_db", snr_db) / 10)))


@validated
def add_noise(
    signals: Any,
    *,
    snr_db: float | None = None,
    level: float | None = None,
    reference: float | None = None,
    rng: Any = None,
) -> np.ndarray:
    """Add white Gaussian noise to clean signals.

    Give either ``snr_db`` (power ratio over all channels) or ``level`` (noise standard deviation as a fraction of
    ``reference``; Belyakov uses a percentage of the modal amplitude 0.00067 m; default reference is the RMS of
    the signal).

    Parameters
    ----------
    signals : array_like, any shape
        Clean signals; finite real numbers.
    snr_db : float, optional
        Signal-to-noise power ratio in decibels over all channels; give exactly one of ``snr_db`` and ``level``.
    level : float, optional
        Noise standard deviation as a fraction of ``reference``; a number >= 0 (give exactly one of ``snr_db`` and
        ``level``).
    reference : float, optional
        Reference amplitude that ``level`` multiplies; a number >= 0 (default: the RMS of ``signals``).
    rng : int, numpy.random.Generator or None, optional
        Seed (an integer >= 0) or generator of the noise; None draws fresh entropy.

    Returns
    -------
    ndarray
        ``signals`` plus the noise, same shape.

    Examples
    --------
    >>> y = add_noise(np.ones(4), level=0.0, rng=0)
    >>> y.tolist()
    [1.0, 1.0, 1.0, 1.0]
    """
    s = np.asarray(signals, dtype=float)
    if (snr_db is None) == (level is None):
        raise ParameterError("add_noise needs exactly one of snr_db= or level=")
    if snr_db is not None:
        sigma = noise_sigma(s, snr_db)
    else:
        ref = float(np.sqrt(np.mean(s**2))) if reference is None else float(reference)
        if level < 0 or ref < 0:
            raise ParameterError(f"level and reference must be non-negative, got {level!r}, {reference!r}")
        sigma = float(level) * ref
    gen = rng if isinstance(rng, np.random.Generator) else np.random.default_rng(rng)
    return s + sigma * gen.standard_normal(s.shape)


@dataclass(frozen=True, eq=False)
class CramerRaoBound(SymPyPrintable):
    """Cramér–Rao lower bounds (variances) for damped sinusoids in white Gaussian noise.

    Attributes
    ----------
    frequency : ndarray, shape (n_modes,)
        Variance bound of each angular frequency ``omega_k`` ((rad/s)**2).
    damping : ndarray, shape (n_modes,)
        Variance bound of each decay rate ``delta_k`` ((1/s)**2).
    amplitude : ndarray, shape (channels, n_modes)
        Variance bound of each amplitude ``A_ck``.
    phase : ndarray, shape (channels, n_modes)
        Variance bound of each phase ``phi_ck`` (rad**2).
    fisher : ndarray, shape (p, p)
        Fisher information matrix for the parameter vector
        ``(delta_1..delta_K, omega_1..omega_K, then per channel A_c1, phi_c1, ..., [offset_c])``.
    """

    frequency: np.ndarray
    damping: np.ndarray
    amplitude: np.ndarray
    phase: np.ndarray
    fisher: np.ndarray

    @property
    def frequency_std(self) -> np.ndarray:
        """Standard deviation bound of the frequencies (rad/s)."""
        return np.sqrt(self.frequency)


@validated
def cramer_rao_bound(
    frequencies: Any,
    damping: Any,
    amplitudes: Any,
    phases: Any,
    dt: float,
    n_samples: int,
    sigma: float,
    *,
    offset: bool = False,
) -> CramerRaoBound:
    """Cramér–Rao bound for ``y_c(t_n) = [A0_c +] sum_k A_ck exp(-delta_k t_n) cos(omega_k t_n + phi_ck) + noise``.

    The Fisher information is ``J^T J / sigma**2`` with the analytic Jacobian ``J`` of the noise-free samples
    with respect to all parameters (poles shared by the channels); the bound is the diagonal of its inverse.

    Parameters
    ----------
    frequencies : array_like, shape (n_modes,)
        Angular frequencies ``omega_k`` (rad/s) of the true signal; finite numbers.
    damping : array_like, shape (n_modes,)
        Decay rates ``delta_k`` (1/s), one per frequency; finite numbers (0 for undamped sinusoids).
    amplitudes : array_like, shape (n_modes,) or (channels, n_modes)
        Amplitudes ``A_ck``, one column per frequency; finite, not all zero in a mode (else the information is
        singular).
    phases : array_like, same shape as amplitudes
        Phases ``phi_ck`` (rad) at the first sample.
    dt : float
        Sampling period (s); must be positive.
    n_samples : int
        Number of samples per channel; must exceed ``2 n_modes``.
    sigma : float
        Standard deviation of the white Gaussian noise; must be positive.
    offset : bool, optional
        Whether the model has a constant offset ``A0_c`` per channel (estimated too; default False).

    Returns
    -------
    CramerRaoBound

    Raises
    ------
    IdentificationError
        When the Fisher information is singular to working precision (coincident modes, a mode without amplitude, a
        mode at zero frequency): those parameters cannot be estimated from such a record and have no finite bound.

    Examples
    --------
    One undamped real sinusoid, N samples, dt = 1: Kay's bound 12 / (eta N (N^2 - 1)) with eta = A^2 / (2 sigma^2)
    (S. M. Kay, *Fundamentals of Statistical Signal Processing I*, 1993, example 3.14):

    >>> b = cramer_rao_bound([1.0], [0.0], [1.0], [0.3], 1.0, 1000, 0.1)
    >>> round(float(b.frequency[0] / (12 / (50.0 * 1000 * (1000**2 - 1)))), 2)
    1.0
    """
    w = np.atleast_1d(check_finite_array("frequencies", frequencies))
    d = np.atleast_1d(check_finite_array("damping", damping))
    a = np.atleast_2d(check_finite_array("amplitudes", amplitudes))
    ph = np.atleast_2d(check_finite_array("phases", phases))
    k = w.size
    if w.ndim != 1 or d.shape != (k,) or a.ndim != 2 or a.shape[1] != k or ph.shape != a.shape:
        raise ParameterError(
            f"inconsistent shapes: frequencies {w.shape}, damping {d.shape}, amplitudes {a.shape}, phases {ph.shape}"
        )
    dt, sigma = check_positive("dt", dt), check_positive("sigma", sigma)
    n_samples = check_int("n_samples", n_samples, minimum=2 * k + 1)
    nch, npc = a.shape[0], 2 * k + int(offset)
    n_par = 2 * k + npc * nch
    check_memory(
        f"cramer_rao_bound(): a Jacobian of {n_samples * nch} samples by {n_par} parameters (n_samples = {n_samples})",
        8.0 * n_samples * nch * (n_par + 8 * k),
    )
    _identifiable(w, d, a)
    t = np.arange(n_samples) * dt
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow is reported below
        jac = _jacobian(t, w, d, a, ph, npc, offset)
        fisher = jac.T @ jac / sigma**2
    if not np.all(np.isfinite(fisher)):
        raise ParameterError(
            f"the signal overflows over the record (damping {d.min():.3g} 1/s over n_samples * dt = "
            f"{n_samples * dt:.3g} s): the record must be shorter or the damping larger (a decay rate > 0)"
        )
    cov = _inverse_information(fisher)
    var = np.diag(cov)
    per = var[2 * k :].reshape(nch, npc)
    return CramerRaoBound(
        frequency=var[k : 2 * k],
        damping=var[:k],
        amplitude=per[:, 0 : 2 * k : 2],
        phase=per[:, 1 : 2 * k : 2],
        fisher=fisher,
    )


def _jacobian(t, w, d, a, ph, npc: int, offset: bool) -> np.ndarray:
    """Jacobian of the noise-free samples of every channel with respect to (delta, omega, then per channel A, phi,
    [offset])."""
    k, nch = w.size, a.shape[0]
    e = np.exp(-np.outer(t, d))  # (N, k)
    blocks = []
    for c in range(nch):
        arg = np.outer(t, w) + ph[c]
        cos, sin = np.cos(arg), np.sin(arg)
        dd = -a[c] * t[:, None] * e * cos  # d/d delta
        dw = -a[c] * t[:, None] * e * sin  # d/d omega
        da = e * cos
        dp = -a[c] * e * sin
        local = np.zeros((t.size, npc * nch))
        local[:, c * npc : c * npc + 2 * k : 2] = da
        local[:, c * npc + 1 : c * npc + 2 * k : 2] = dp
        if offset:
            local[:, c * npc + 2 * k] = 1.0
        blocks.append(np.hstack([dd, dw, local]))
    return np.vstack(blocks)


def _identifiable(w: np.ndarray, d: np.ndarray, a: np.ndarray) -> None:
    """IdentificationError for modes whose parameters no record can tell apart (the information is singular)."""
    for i in range(w.size):
        if not np.any(a[:, i]):
            raise IdentificationError(
                f"mode {i} (omega = {w[i]:.6g}) has zero amplitude in every channel: its frequency and damping do not "
                "enter the signal and have no finite bound; drop the mode or give its amplitudes"
            )
        for j in range(i + 1, w.size):
            if w[i] == w[j] and d[i] == d[j]:
                raise IdentificationError(
                    f"modes {i} and {j} coincide (frequencies {w[i]:.6g}, damping {d[i]:.6g}): a record cannot "
                    "tell their parameters apart and the Fisher information is singular; give each pole (frequency "
                    "and damping) only once, its amplitudes add"
                )


def _inverse_information(fisher: np.ndarray) -> np.ndarray:
    """The inverse of a Fisher matrix, equilibrated by its diagonal; IdentificationError when it is singular to
    working precision (the diagonal of the inverse would have no correct digit)."""
    scale = np.sqrt(np.diag(fisher))
    if not np.all(scale > 0):
        raise IdentificationError(
            "a parameter does not enter the signal (zero Fisher information) and has no bound: each mode needs "
            "nonzero amplitudes and each channel a nonzero signal"
        )
    lam, vec = np.linalg.eigh(fisher / np.outer(scale, scale))
    cond = lam[-1] / lam[0] if lam[0] > 0 else np.inf
    if not cond * np.finfo(float).eps < 1e-3:
        raise IdentificationError(
            f"the Fisher information is singular to working precision (condition number {cond:.3g} after "
            "equilibration): some parameters cannot be identified from this record (nearly coincident modes, a "
            "mode at zero frequency, or too short a record); the bounds would have no correct digit"
        )
    return (vec / lam) @ vec.T / np.outer(scale, scale)


@dataclass(frozen=True, repr=False, eq=False)
class MonteCarloResult(SymPyPrintable):
    """Estimates over noise realisations: arrays of shape (runs, n_modes) (NaN rows for failed runs).

    Attributes
    ----------
    frequencies : ndarray, shape (runs, n_modes)
        Damped angular frequencies (rad/s) estimated in each run.
    damping : ndarray, shape (runs, n_modes)
        Decay rates (1/s) estimated in each run.
    amplitudes : ndarray, shape (runs, channels, n_modes)
        Amplitudes estimated in each run.
    failures : int
        Number of runs in which the estimator failed.
    snr_db : float or None
        Signal-to-noise ratio (dB) of the runs; None when the noise was given by ``level``.
    """

    frequencies: np.ndarray
    damping: np.ndarray
    amplitudes: np.ndarray
    failures: int
    snr_db: float | None

    @property
    def frequency_mean(self) -> np.ndarray:
        """Mean frequency per mode over successful runs."""
        return np.nanmean(self.frequencies, axis=0)

    @property
    def frequency_var(self) -> np.ndarray:
        """Frequency variance per mode over successful runs (ddof=1)."""
        return np.nanvar(self.frequencies, axis=0, ddof=1)

    def __repr__(self) -> str:
        n = self.frequencies.shape[0]
        return (
            f"MonteCarloResult(runs={n}, failures={self.failures}, snr_db={self.snr_db}, "
            f"frequency_mean={np.array2string(self.frequency_mean, precision=6)}, "
            f"frequency_std={np.array2string(np.sqrt(self.frequency_var), precision=3)})"
        )


def _monte_carlo_run(run: int, *, estimator, y, dt, noise, seed, kwargs) -> Any:
    """One noisy copy through ``estimator``; None when it fails with an identification error (counted)."""
    from ...errors import SymoscError

    snr_db, level, reference = noise
    noisy = add_noise(y, snr_db=snr_db, level=level, reference=reference, rng=np.random.default_rng([seed, run]))
    try:
        return estimator(noisy if y.shape[0] > 1 else noisy[0], dt, **kwargs)
    except (SymoscError, np.linalg.LinAlgError):
        return None


@validated
def monte_carlo(
    estimator: Callable[..., ModalEstimate],
    signals: Any,
    dt: float,
    *,
    snr_db: float | None = None,
    level: float | None = None,
    reference: float | None = None,
    runs: int = 200,
    seed: int = 0,
    executor: Any = "auto",
    progress: bool | None = None,
    **kwargs: Any,
) -> MonteCarloResult:
    """Run ``estimator(noisy, dt, **kwargs)`` on ``runs`` noisy copies of clean ``signals``.

    Runs whose estimator raises an identification/parameter/convergence error are counted in ``failures`` and
    stored as NaN.  Run ``i`` uses seed ``(seed, i)``, so results are reproducible and independent of order and
    of ``executor``.

    Parameters
    ----------
    estimator : callable
        ``estimator(noisy, dt, **kwargs) -> ModalEstimate``, e.g. :func:`matrix_pencil`; picklable for parallel
        executors.
    signals : array_like, shape (samples,) or (channels, samples)
        Clean sampled record: finite real numbers, at least 4 samples, not all zero.
    dt : float
        Sampling period (s); must be positive and finite.
    snr_db : float, optional
        Signal-to-noise power ratio (dB); give exactly one of ``snr_db`` and ``level``.
    level : float, optional
        Noise standard deviation as a fraction of ``reference``; a number >= 0 (give exactly one of ``snr_db`` and
        ``level``).
    reference : float, optional
        Reference amplitude that ``level`` multiplies; a number >= 0 (default: the RMS of ``signals``).
    runs : int, optional
        Number of noise realisations; an integer >= 1 (default 200).
    seed : int, optional
        Base seed (an integer >= 0); run ``i`` uses ``(seed, i)``.
    executor : {"auto", "serial", "processes"}, Executor or distributed.Client, optional
        Where the runs go (see :func:`symosc.sweep`); the result does not depend on it.
    progress : bool, optional
        Show a progress bar (default: when stderr is a terminal).
    **kwargs
        Passed to ``estimator`` (e.g. ``n_modes=1``).

    Returns
    -------
    MonteCarloResult

    See Also
    --------
    symosc.sweep, error_vs_noise, cramer_rao_bound

    Examples
    --------
    >>> import numpy as np
    >>> from symosc.identification import matrix_pencil
    >>> t = np.arange(64) * 0.1
    >>> mc = monte_carlo(matrix_pencil, np.cos(2 * t), 0.1, snr_db=30, runs=20, n_modes=1, constant=False)
    >>> mc.failures, bool(abs(mc.frequency_mean[0] - 2.0) < 1e-2)
    (0, True)
    """

    from ...sweep import sweep
    from .._sweeping import raise_first_failure

    y, dt = _as_signals(signals, dt)
    trial = functools.partial(
        _monte_carlo_run,
        estimator=estimator,
        y=y,
        dt=dt,
        noise=(snr_db, level, reference),
        seed=seed,
        kwargs=kwargs,
    )
    res = sweep(trial, {"run": np.arange(int(runs))}, executor=executor, progress=progress)
    raise_first_failure(res, "monte_carlo")
    ests = list(res.values.reshape(-1)) if res.values.dtype == object else [None] * int(runs)
    fails = sum(e is None for e in ests)
    rows_w = [None if e is None else e.frequencies for e in ests]
    rows_d = [None if e is None else e.damping for e in ests]
    rows_a = [None if e is None else e.amplitudes for e in ests]
    k = next((r.size for r in rows_w if r is not None), 0)

    def stack(rows, shape):
        return np.array([np.full(shape, np.nan) if r is None else r for r in rows])

    return MonteCarloResult(
        frequencies=stack(rows_w, (k,)),
        damping=stack(rows_d, (k,)),
        amplitudes=stack(rows_a, (y.shape[0], k)),
        failures=fails,
        snr_db=snr_db,
    )


@dataclass(frozen=True, eq=False)
class ApplicabilityCheck(SymPyPrintable):
    """Belyakov's criterion for Algorithm 1: the weakest mode carries more than half the mean modal energy.

    Attributes
    ----------
    ok : bool
        Whether the criterion ``min E_i > threshold`` holds.
    energies : ndarray, shape (modes,)
        Modal energies ``E_i`` (J when forces are in N and amplitudes in m).
    threshold : float
        Half the mean modal energy.
    weakest_mode : int
        Index of the mode with the smallest energy.
    margin : float
        ``min E_i / threshold`` (> 1 when the criterion holds).
    """

    ok: bool
    energies: np.ndarray
    threshold: float
    weakest_mode: int
    margin: float


@validated
def applicability(energies: Any = None, *, mode_shapes: Any = None, force: Any = None) -> ApplicabilityCheck:
    """Applicability criterion (Belyakov Ch. III §3.2): ``min E_i > 0.5 mean E_i``.

    Give the modal energies directly, or the normal-coordinate observation matrix C' (``mode_shapes``, sensors x
    modes, with q0' = 1) and the released static ``force`` on the sensors: then ``E_i = (C'^T f)_i / 2``
    (half the modal stiffness of Algorithm 1, eq. 34).

    Parameters
    ----------
    energies : array_like, shape (modes,), optional
        Modal energies ``E_i``; a finite 1-D array.  Give either ``energies`` or both ``mode_shapes`` and ``force``.
    mode_shapes : array_like, shape (sensors, modes), optional
        Normal-coordinate observation matrix ``C'`` scaled so that ``q0' = 1`` (used when ``energies`` is omitted).
    force : array_like, shape (sensors,), optional
        Static vertical forces (N) released at the sensors (used with ``mode_shapes``).

    Returns
    -------
    ApplicabilityCheck

    Examples
    --------
    The dissertation's C' and the 2000 N release at spring 2 (recomputed: 0.675, 0.719, 0.630 J):

    >>> C = [[-6.753510e-4, 6.737952e-4, -6.730062e-4], [-6.753488e-4, -7.192560e-4, -6.304674e-4],
    ...      [-6.753497e-4, -6.737934e-4, 6.730067e-4], [-6.753526e-4, 7.192575e-4, 6.304678e-4]]
    >>> chk = applicability(mode_shapes=C, force=[0, -2000, 0, 0])
    >>> chk.ok, np.round(chk.energies, 3).tolist()
    (True, [0.675, 0.719, 0.63])
    """
    if energies is None:
        if mode_shapes is None or force is None:
            raise ParameterError("applicability() needs energies, or mode_shapes and force")
        cp = np.asarray(mode_shapes, dtype=float)
        f = np.asarray(force, dtype=float)
        energies = 0.5 * (cp.T @ f)
    e = np.asarray(energies, dtype=float)
    if e.ndim != 1 or e.size < 1 or not np.all(np.isfinite(e)):
        raise ParameterError(f"energies must be a finite 1-D array, got {energies!r}")
    thr = 0.5 * float(np.mean(e))
    i = int(np.argmin(e))
    return ApplicabilityCheck(ok=bool(e[i] > thr), energies=e, threshold=thr, weakest_mode=i, margin=float(e[i] / thr))


@dataclass(frozen=True, repr=False, eq=False)
class ErrorVsNoise(SymPyPrintable):
    """Relative parameter errors of an identification pipeline against the noise level (Belyakov Fig. 20).

    Attributes
    ----------
    levels : ndarray, shape (levels,)
        Noise levels (standard deviation as a fraction of the reference amplitude).
    names : tuple of str
        Names of the parameters compared with the truth.
    errors : ndarray, shape (levels, runs, parameters)
        Relative errors ``|estimate - truth| / |truth|`` per run (NaN for failed runs).
    failures : ndarray of int, shape (levels,)
        Number of failed runs per level.
    """

    levels: np.ndarray
    names: tuple[str, ...]
    errors: np.ndarray
    failures: np.ndarray

    @property
    def mean(self) -> np.ndarray:
        """Mean relative error per level and parameter (failed runs ignored)."""
        with np.errstate(invalid="ignore"):
            return np.nanmean(self.errors, axis=1)

    def threshold(self, name: str, max_error: float) -> float:
        """Largest noise level (linearly interpolated) at which the mean error of ``name`` stays <= ``max_error``.

        Parameters
        ----------
        name : str
            Parameter whose error is tested; must be one of ``names``.
        max_error : float
            Admissible mean relative error (a fraction, e.g. 0.005 for 0.5 %); a non-negative number.

        Returns
        -------
        float
            The noise level (0 when even the lowest level exceeds ``max_error``, the highest level when none does).
        """
        j = self.names.index(name)
        e = self.mean[:, j]
        above = np.nonzero(e > max_error)[0]
        if above.size == 0:
            return float(self.levels[-1])
        i = int(above[0])
        if i == 0:
            return 0.0
        return float(np.interp(max_error, [e[i - 1], e[i]], [self.levels[i - 1], self.levels[i]]))

    @plot_method
    def plot(self, names: Any = None, *, ax: Any = None) -> Any:
        """Mean relative error (%) vs noise level (%) per parameter; returns the axes.

        Parameters
        ----------
        names : sequence of str, optional
            Parameters to draw, each one of ``names``; all of them when omitted.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
        """
        from ..._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        for n in names or self.names:
            ax.plot(100 * self.levels, 100 * self.mean[:, self.names.index(n)], "o-", ms=3, label=n)
        ax.set_xlabel("noise (% of reference amplitude)")
        ax.set_ylabel("mean relative error (%)")
        ax.legend()
        return ax

    def __repr__(self) -> str:
        head = "  level  " + " ".join(f"{n:>10}" for n in self.names) + "  failed"
        rows = [
            f"  {lv:5.3g}  " + " ".join(f"{100 * v:9.3g}%" for v in m) + f"  {int(f)}"
            for lv, m, f in zip(self.levels, self.mean, self.failures, strict=True)
        ]
        return "\n".join([f"ErrorVsNoise(runs={self.errors.shape[1]})", head, *rows])


def _error_vs_noise_run(level_index: int, run: int, *, pipeline, y, dt, levels, reference, seed, truth) -> np.ndarray:
    """Relative errors of one run, then a failure flag (1.0 when the pipeline failed, errors NaN)."""
    from ...errors import SymoscError

    names, true = truth
    out = np.full(len(names) + 1, np.nan)
    rng = np.random.default_rng([seed, level_index, run])
    noisy = add_noise(y, level=levels[level_index], reference=reference, rng=rng)
    try:
        res = pipeline(noisy if y.shape[0] > 1 else noisy[0], dt)
    except (SymoscError, np.linalg.LinAlgError):
        out[-1] = 1.0
        return out
    if hasattr(res, "as_dict"):
        res = res.as_dict()
    est = np.array([float(res[n]) for n in names])
    out[:-1] = np.abs(est - true) / np.abs(true)
    out[-1] = 0.0
    return out


@validated
def error_vs_noise(
    pipeline: Callable[[np.ndarray, float], Any],
    signals: Any,
    dt: float,
    truth: Any,
    levels: Any,
    *,
    reference: float | None = None,
    runs: int = 10,
    seed: int = 0,
    executor: Any = "auto",
    progress: bool | None = None,
) -> ErrorVsNoise:
    """Monte Carlo of ``pipeline(noisy_signals, dt)`` at each noise ``level`` (fraction of ``reference``).

    ``pipeline`` returns the identified parameters as a mapping (or a dataclass with ``as_dict()``) whose keys
    include those of ``truth`` (a mapping name -> true value).  Run i at level index l uses seed (seed, l, i).
    Errors raised by the pipeline (symosc errors, LinAlgError) count as failures.  The runs go through
    :func:`symosc.sweep` with ``executor`` (parallel executors need a picklable ``pipeline``); results do not
    depend on it.

    Parameters
    ----------
    pipeline : callable
        ``pipeline(noisy_signals, dt)`` returning the identified parameters as a mapping (or an object with
        ``as_dict()``) whose keys include those of ``truth``; picklable for parallel executors.
    signals : array_like, shape (samples,) or (channels, samples)
        Clean sampled record: finite real numbers, at least 4 samples, not all zero.
    dt : float
        Sampling period (s); must be positive and finite.
    truth : mapping of str to float
        True values of the parameters to compare, by name; nonzero finite numbers (errors are relative).
    levels : float or array_like
        Noise level(s): standard deviation as a fraction of ``reference``; numbers >= 0.
    reference : float, optional
        Reference amplitude the levels multiply; a number >= 0 (default: the RMS of ``signals``).
    runs : int, optional
        Noise realisations per level; an integer >= 1 (default 10).
    seed : int, optional
        Base seed (an integer >= 0); run ``i`` at level index ``l`` uses ``(seed, l, i)``.
    executor : {"auto", "serial", "processes"}, Executor or distributed.Client, optional
        Where the runs go (see :func:`symosc.sweep`); the result does not depend on it.
    progress : bool, optional
        Show a progress bar (default: when stderr is a terminal).

    Returns
    -------
    ErrorVsNoise

    See Also
    --------
    symosc.sweep, monte_carlo

    Examples
    --------
    >>> import numpy as np
    >>> from symosc.identification import matrix_pencil
    >>> t = np.arange(100) * 0.1
    >>> def pipe(y, dt):
    ...     return {"w": matrix_pencil(y, dt, 1, constant=False).frequencies[0]}
    >>> ev = error_vs_noise(pipe, np.cos(2.0 * t), 0.1, {"w": 2.0}, [0.01, 0.1], runs=5)
    >>> bool(ev.mean[0, 0] < ev.mean[1, 0] < 1e-2)
    True
    """

    y, dt = _as_signals(signals, dt)
    names = tuple(truth)
    true = np.array([float(truth[n]) for n in names])
    lv = np.atleast_1d(np.asarray(levels, dtype=float))
    from ...sweep import sweep
    from .._sweeping import raise_first_failure

    trial = functools.partial(
        _error_vs_noise_run,
        pipeline=pipeline,
        y=y,
        dt=dt,
        levels=lv,
        reference=reference,
        seed=seed,
        truth=(names, true),
    )
    res = sweep(
        trial, {"level_index": np.arange(lv.size), "run": np.arange(int(runs))}, executor=executor, progress=progress
    )
    raise_first_failure(res, "error_vs_noise")
    errs = res.values[..., :-1]
    fails = res.values[..., -1].sum(axis=-1).astype(int)
    return ErrorVsNoise(levels=lv, names=names, errors=errs, failures=fails)
