"""Shared machinery of the signal estimators: input checks, the modal result, pole handling, amplitude fit.

Every estimator (:func:`~symosc.identification.prony`, :func:`~symosc.identification.era`,
:func:`~symosc.identification.matrix_pencil`, :func:`~symosc.identification.esprit`) finds the discrete poles
``z_k = exp(lambda_k dt)`` its own way and then hands them to :func:`_modal_estimate`, which checks them
(Nyquist, conjugate pairs, conditioning), fits the amplitudes and phases of every channel by linear least squares
over the whole record, and packs a :class:`ModalEstimate`.

Signal model (Belyakov 2005, eq. 39), per channel c and sample n at t_n = n dt::

    y_c(t_n) = A0_c + sum_k A_ck exp(-delta_k t_n) cos(omega_k t_n + phi_ck)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..._plotting import plot_method
from ..._printing import SymPyPrintable
from ...errors import AccuracyWarning, IdentificationError, ParameterError, warn

__all__ = ["ModalEstimate"]

_MIN_SAMPLES = 4
_RANK_TOL = 1e-11  # sigma_order / sigma_1 below this: the data do not support the requested order


@dataclass(frozen=True, repr=False, eq=False)
class ModalEstimate(SymPyPrintable):
    """Modal model identified from sampled free-decay signals.

    Attributes
    ----------
    method : str
        Name of the estimator that produced it.
    dt : float
        Sampling period of the input signals (s).
    poles : ndarray, shape (n_modes,)
        Continuous-time poles ``lambda_k = -delta_k + i omega_k`` (upper half plane, sorted by frequency).
    amplitudes : ndarray, shape (channels, n_modes)
        Real amplitudes ``A_ck >= 0`` (the full amplitude, i.e. twice the modulus of one exponential's coefficient).
    phases : ndarray, shape (channels, n_modes)
        Phases ``phi_ck`` in (-pi, pi] at t = 0 (the first sample).
    offset : ndarray, shape (channels,)
        Constant term ``A0_c`` (zeros when the model has no constant state).
    singular_values : ndarray
        Singular values of the data matrix the method decomposed (Hankel or linear-prediction matrix); the gap
        after ``n_poles`` values measures how well the model order is determined.
    residual : float
        Relative RMS misfit ``||y - y_model|| / ||y||`` over all channels and samples.
    n_poles : int
        Number of exponentials in the model, ``2 n_modes + (1 if constant)``.
    n_samples : int
        Number of samples per channel that were fitted.
    details : dict
        Method-specific extras (Hankel size, realisation matrices, decimation, ...).
    """

    method: str
    dt: float
    poles: np.ndarray
    amplitudes: np.ndarray
    phases: np.ndarray
    offset: np.ndarray
    singular_values: np.ndarray
    residual: float
    n_poles: int
    n_samples: int
    details: Mapping[str, Any] = field(default_factory=dict)

    # ----------------------------------------------------------------------------------------------- derived
    @property
    def order(self) -> int:
        """Deprecated alias of :attr:`n_poles`."""
        from ..._deprecation import warn_deprecated

        warn_deprecated("ModalEstimate.order", "ModalEstimate.n_poles")
        return self.n_poles

    @property
    def n_modes(self) -> int:
        """Number of oscillatory modes."""
        return int(self.poles.size)

    @property
    def n_channels(self) -> int:
        """Number of signal channels."""
        return int(self.amplitudes.shape[0])

    @property
    def frequencies(self) -> np.ndarray:
        """Damped angular frequencies ``omega_k = Im lambda_k`` (rad/s)."""
        return self.poles.imag.copy()

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Damped frequencies in Hz."""
        return self.poles.imag / (2 * np.pi)

    @property
    def damping(self) -> np.ndarray:
        """Decay rates ``delta_k = -Re lambda_k`` (1/s)."""
        return -self.poles.real

    @property
    def undamped_frequencies(self) -> np.ndarray:
        """``|lambda_k| = sqrt(omega_k**2 + delta_k**2)`` (rad/s): the undamped frequency for modal damping (eq. 97)."""
        return np.abs(self.poles)

    @property
    def damping_ratios(self) -> np.ndarray:
        """Damping ratios ``zeta_k = delta_k / |lambda_k|``."""
        return self.damping / np.abs(self.poles)

    @property
    def complex_amplitudes(self) -> np.ndarray:
        """Coefficients ``h_ck = (A_ck / 2) exp(i phi_ck)`` of ``exp(lambda_k t)`` (Belyakov's h_k, Kung's Q)."""
        return 0.5 * self.amplitudes * np.exp(1j * self.phases)

    @property
    def mode_shapes(self) -> np.ndarray:
        """Signed modal amplitudes ``sign(cos phi_ck) A_ck`` (channels, n_modes).

        This is the normal-coordinate observation matrix C' of Belyakov's recipe (stage 3: modulus with the sign
        of the real part) for a release from rest, where q0' = (1, ..., 1).
        """
        return np.where(np.cos(self.phases) < 0, -1.0, 1.0) * self.amplitudes

    # ----------------------------------------------------------------------------------------------- methods
    def reconstruct(self, n_samples: int | None = None, *, t: Any = None) -> np.ndarray:
        """Model signal, shape (channels, samples), at ``t`` (s) or at the first ``n_samples`` sample times.

        Parameters
        ----------
        n_samples : int, optional
            Number of sample times ``0, dt, 2 dt, ...`` to evaluate at (an integer >= 0); default: as many as were
            fitted.  Ignored when ``t`` is given.
        t : float or array_like, optional
            Times (s, from the first sample) at which to evaluate the model; finite numbers.
        """
        if t is None:
            t = np.arange(self.n_samples if n_samples is None else int(n_samples)) * self.dt
        t = np.asarray(t, dtype=float)
        h = self.complex_amplitudes  # (c, k)
        out = 2.0 * np.real(h @ np.exp(np.outer(self.poles, t)))
        return out + self.offset[:, None]

    def __repr__(self) -> str:
        lines = [
            f"ModalEstimate(method={self.method!r}, n_poles={self.n_poles}, n_modes={self.n_modes}, "
            f"channels={self.n_channels}, n_samples={self.n_samples}, dt={self.dt:g}, residual={self.residual:.3g})",
            f"  {'mode':>4} {'omega (rad/s)':>16} {'f (Hz)':>14} {'delta (1/s)':>14} {'zeta':>10}  amplitudes",
        ]
        for k in range(self.n_modes):
            amps = ", ".join(f"{a:.4g}" for a in self.amplitudes[:, k][:6])
            more = ", ..." if self.n_channels > 6 else ""
            lines.append(
                f"  {k + 1:>4} {self.frequencies[k]:>16.10g} {self.frequencies_hz[k]:>14.8g} "
                f"{self.damping[k]:>14.6g} {self.damping_ratios[k]:>10.4g}  [{amps}{more}]"
            )
        return "\n".join(lines)

    def _repr_latex_(self) -> str:
        terms = [
            rf"{a:.4g}\,e^{{-{d:.4g}t}}\cos({w:.6g}t{p:+.4f})"
            for a, d, w, p in zip(self.amplitudes[0], self.damping, self.frequencies, self.phases[0], strict=True)
        ]
        lead = f"{self.offset[0]:.4g} + " if self.offset[0] != 0 else ""
        return "$y_1(t) = " + lead + " + ".join(terms) + "$"

    @plot_method
    def plot(self, signals: Any = None, *, ax: Any = None, channel: int = 0) -> Any:
        """Plot the model signal of one channel (and the measured ``signals`` if given); returns the axes.

        Parameters
        ----------
        signals : array_like, shape (samples,) or (channels, samples), optional
            Measured record sampled at ``dt``, drawn as dots for comparison; not drawn when omitted.
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        channel : int, optional
            Index of the channel to draw; must be less than the number of channels (default 0).

        Returns
        -------
        matplotlib Axes
        """
        from ..._plotting import pyplot

        plt = pyplot()

        if ax is None:
            _, ax = plt.subplots()
        t = np.arange(self.n_samples) * self.dt
        if signals is not None:
            y = np.atleast_2d(np.asarray(signals, dtype=float))
            ax.plot(np.arange(y.shape[1]) * self.dt, y[channel], ".", ms=2, label="measured")
        ax.plot(t, self.reconstruct()[channel], "-", lw=1, label=f"{self.method} model")
        ax.set_xlabel("t (s)")
        ax.set_ylabel(f"channel {channel}")
        ax.legend()
        return ax


# --------------------------------------------------------------------------------------------------- input
def _as_signals(signals: Any, dt: Any, *, name: str = "signals") -> tuple[np.ndarray, float]:
    """Return signals as a float (channels, samples) array and dt as a positive float; raise on bad input."""
    try:
        dtf = float(dt)
    except (TypeError, ValueError):
        raise ParameterError(f"dt must be a positive number (the sampling period in s), got {dt!r}") from None
    if not np.isfinite(dtf) or dtf <= 0:
        raise ParameterError(f"dt must be a positive finite sampling period in s, got {dt!r}")
    y = np.asarray(signals)
    if np.iscomplexobj(y):
        raise ParameterError(f"{name} must be real-valued measurements, got a complex array")
    try:
        y = y.astype(float)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a numeric array of shape (samples,) or (channels, samples)") from None
    if y.ndim == 1:
        y = y[None, :]
    if y.ndim != 2:
        raise ParameterError(f"{name} must have shape (samples,) or (channels, samples), got shape {y.shape}")
    if y.shape[0] > y.shape[1]:
        raise ParameterError(
            f"{name} has shape {y.shape}: more channels than samples. Pass shape (channels, samples); "
            "if you have (samples, channels), transpose it (signals.T)"
        )
    if y.shape[1] < _MIN_SAMPLES:
        raise ParameterError(f"{name} is too short: {y.shape[1]} samples; at least {_MIN_SAMPLES} are needed")
    bad = ~np.isfinite(y)
    if bad.any():
        c, n = np.argwhere(bad)[0]
        raise ParameterError(
            f"{name} contains {int(bad.sum())} NaN/inf value(s) (first at channel {c}, sample {n}); "
            "remove or interpolate them before identification"
        )
    if not np.any(y):
        raise IdentificationError(f"{name} are identically zero: there is nothing to identify")
    return y, dtf


def _resolve_order(n_modes: int | None, order: int | None, constant: bool) -> int | None:
    """Total number of exponentials from ``n_modes`` or ``order`` (None: select from the data)."""
    c = int(bool(constant))
    if n_modes is not None:
        if int(n_modes) != n_modes or n_modes < 1:
            raise ParameterError(f"n_modes must be a positive integer, got {n_modes!r}")
        if order is not None and order != 2 * int(n_modes) + c:
            raise ParameterError(
                f"n_poles={order} contradicts n_modes={n_modes} (with constant={constant} it must be "
                f"{2 * int(n_modes) + c}); give only one of them"
            )
        return 2 * int(n_modes) + c
    if order is not None:
        if int(order) != order or order < 1 + c:
            raise ParameterError(f"n_poles must be an integer >= {1 + c}, got {order!r}")
        if (order - c) % 2:
            raise ParameterError(
                f"n_poles={order} with constant={constant} leaves a lone real exponential: n_poles must be "
                f"2*n_modes{' + 1' if c else ''}"
            )
        return int(order)
    return None


def _check_supported(order: int, n_samples: int, what: str) -> None:
    if 2 * order + 1 > n_samples:
        raise ParameterError(
            f"order {order} is larger than {n_samples} samples support ({what}): {order} exponentials need at least "
            f"{2 * order + 1} samples; lower n_modes or record longer"
        )


def _hankel(y: np.ndarray, rows: int) -> np.ndarray:
    """Block Hankel matrix of a (channels, N) record: ``rows`` block rows of ``channels`` rows each."""
    c, n = y.shape
    cols = n - rows + 1
    idx = np.arange(rows)[:, None] + np.arange(cols)[None, :]  # (rows, cols)
    return y[:, idx].transpose(1, 0, 2).reshape(rows * c, cols)


def _select_order(sv: np.ndarray, constant: bool, max_order: int) -> int:
    """Model order from the largest relative gap of the singular values (at most ``max_order``)."""
    s = np.asarray(sv, dtype=float)
    s = s[s > 0]
    if s.size < 2:
        raise IdentificationError("cannot select a model order: the data matrix has rank < 2")
    kmax = min(max_order, s.size - 1)
    floor = s[0] * 1e-300
    gaps = np.log(s[:kmax] + floor) - np.log(s[1 : kmax + 1] + floor)
    r = int(np.argmax(gaps)) + 1
    if constant and r % 2 == 0:
        return r  # no constant state visible in the data: an even rank means oscillatory pairs only
    if not constant and r % 2 == 1:
        r = max(r - 1, 2)
    return r


def _check_rank(sv: np.ndarray, order: int, hint: str = "", *, spare: bool = False) -> None:
    """Raise unless the data support ``order`` exponentials (``order - 1`` if ``spare``: an optional offset state)."""
    s = np.asarray(sv)
    if s.size < order:
        raise ParameterError(f"order {order} exceeds the rank the data matrix can have ({s.size}); lower n_modes")
    if s[order - 1 - int(spare)] <= _RANK_TOL * s[0]:
        r = int(np.sum(s > _RANK_TOL * s[0]))
        raise IdentificationError(
            f"the data support only {r} exponentials (singular values {s[: order + 1]!r} drop below "
            f"{_RANK_TOL:g} of the largest), but order {order} was requested. Lower n_modes, or pass "
            "constant=False if the signal has no constant offset" + hint
        )


def _prepare(
    signals: Any, dt: Any, n_modes: int | None, order: int | None, constant: bool, what: str
) -> tuple[np.ndarray, float, int | None]:
    """Checked ``(channels, samples)`` record, sampling period and requested order (None: select from the data)."""
    y, dtf = _as_signals(signals, dt)
    p = _resolve_order(n_modes, order, constant)
    if p is not None:
        _check_supported(p, y.shape[1], what)
    return y, dtf, p


# --------------------------------------------------------------------------------------------------- poles
def _offset_pole(z: np.ndarray) -> tuple[complex, bool]:
    """The real pole nearest z = 1 and whether it can be the constant (offset) state of an odd-order model.

    The offset is the exponential with root z = 1. In noise that root moves a little, but it stays real, positive
    and slower than every oscillation. Supported means: a real positive pole whose rate ``|ln z|`` is at most half
    that of the slowest oscillatory pole. Without an offset in the data, the spare state of an order ``2 n + 1``
    model fits noise instead, often as a real pole at z ~ -1, which would read as a mode at the Nyquist frequency.
    """
    z = np.asarray(z, dtype=complex).ravel()
    if not np.all(np.isfinite(z)) or np.any(z == 0):
        return complex(np.nan), True  # degenerate: let _modal_estimate report it
    ln = np.log(z)
    tol = 1e-9 * np.maximum(np.abs(ln), 1.0)
    real = np.abs(ln.imag) <= tol  # z < 0 has Im ln z = pi: never the offset
    if not real.any():
        return complex(np.nan), False
    i = np.flatnonzero(real)[np.argmin(np.abs(ln[real]))]
    osc = np.abs(ln[ln.imag > tol])
    return complex(z[i]), bool(osc.size == 0 or abs(ln[i]) <= 0.5 * osc.min())


def _subspace_estimate(
    y: np.ndarray,
    dt: float,
    order: int,
    constant: bool,
    poles_at: Callable[[int], tuple[np.ndarray, dict[str, Any]]],
    *,
    method: str,
    singular_values: np.ndarray,
    nyquist_margin: float,
) -> ModalEstimate:
    """Poles of a subspace estimator at ``order`` (``poles_at(order) -> (z, details)``), checked and fitted.

    With a constant term (odd ``order``) the spare state is kept only if the data support an offset
    (:func:`_offset_pole`); otherwise the poles are recomputed at ``order - 1`` from the same decomposition, and the
    offset is still estimated, linearly, in the amplitude fit (the same happens when exact data have rank
    ``order - 1``). A genuine mode near or above Nyquist is part of the signal subspace at either order, so it is
    still reported as aliasing.
    """
    use_const = bool(constant) and order % 2 == 1
    can_drop = use_const and order >= 3  # at least one oscillatory pair remains
    if can_drop and singular_values[order - 1] <= _RANK_TOL * singular_values[0]:
        z, details = poles_at(order - 1)  # exact data without an offset: no spare state at all
        details = {**details, "offset_pole": complex(np.nan), "offset_refit": True}
    else:
        z, details = poles_at(order)
        if use_const:
            pole, supported = _offset_pole(z)
            details = {**details, "offset_pole": pole, "offset_refit": not supported}
            if not supported and can_drop:
                z, more = poles_at(order - 1)
                details.update(more)
    return _modal_estimate(
        y,
        dt,
        z,
        constant=use_const,
        method=method,
        singular_values=singular_values,
        nyquist_margin=nyquist_margin,
        details=details,
    )


def _modal_estimate(
    y: np.ndarray,
    dt: float,
    z: np.ndarray,
    *,
    constant: bool,
    method: str,
    singular_values: np.ndarray,
    dt_poles: float | None = None,
    nyquist_margin: float = 0.95,
    details: Mapping[str, Any] | None = None,
) -> ModalEstimate:
    """Classify discrete poles ``z`` (sampled at ``dt_poles``), fit amplitudes on ``y`` (sampled at ``dt``)."""
    dtp = dt if dt_poles is None else dt_poles
    z = np.asarray(z, dtype=complex).ravel()
    if not np.all(np.isfinite(z)) or np.any(z == 0):
        raise IdentificationError(
            f"{method}: the identified poles are degenerate (zero or non-finite); lower the order"
        )
    # a real negative pole (z < 0) is an alternating sequence: on an oversampled noisy record the spare pole of an
    # odd order lands there to fit noise; it is not an aliased mode, so it is neither a Nyquist alarm nor a mode
    alternating = (np.abs(z.imag) <= 1e-9 * np.abs(z)) & (z.real < 0)
    if z.size >= 3 and z.size % 2 == 1 and alternating.sum() == 1:
        z = z[~alternating]
    ang = np.abs(np.angle(z))
    near = ang > nyquist_margin * np.pi
    if near.any():
        w = ang[near].max() / dtp
        raise IdentificationError(
            f"{method}: a mode at about {w:.6g} rad/s lies at {100 * ang[near].max() / np.pi:.1f} % of the Nyquist "
            f"frequency pi/dt = {np.pi / dtp:.6g} rad/s: the signal is undersampled and may be aliased (a mode above "
            f"Nyquist folds back to a lower frequency). Sample faster (dt < {np.pi / (w * 1.25):.3g} s), low-pass "
            "filter before decimating, or lower the decimation"
        )
    lam = np.log(z) / dtp
    osc = lam[lam.imag > 1e-9 * np.maximum(np.abs(lam), 1.0 / dtp)]
    n_real = int(np.sum(np.abs(lam.imag) <= 1e-9 * np.maximum(np.abs(lam), 1.0 / dtp)))
    n_pairs_wanted = z.size // 2  # one spare real pole (the offset) when the size is odd
    if osc.size < n_pairs_wanted:
        raise IdentificationError(
            f"{method}: only {osc.size} oscillatory mode(s) found but {n_pairs_wanted} requested; {n_real} pole(s) are "
            "real (non-oscillatory, e.g. noise or an overdamped component). Lower n_modes or improve the signal"
        )
    if osc.size == 0:
        raise IdentificationError(
            f"{method}: the record holds no oscillation (every identified pole is real: {n_real}); nothing to identify"
        )
    osc = osc[np.argsort(osc.imag)]
    samples_per_period = 2 * np.pi / (float(osc.imag.max()) * dt)
    if samples_per_period < _MIN_SAMPLES_PER_PERIOD:
        warn(
            f"{method}: the fastest mode found, {osc.imag.max():.6g} rad/s, has only {samples_per_period:.2g} samples "
            f"per period at dt = {dt:g} s: the record may be under-sampled, and a faster mode above the Nyquist "
            f"frequency pi/dt = {np.pi / dt:.6g} rad/s would fold to this frequency. Sample faster (at least "
            f"{_MIN_SAMPLES_PER_PERIOD} samples per period of the fastest mode) to rule aliasing out",
            AccuracyWarning,
        )
    estimate = _fit(y, dt, osc, constant=constant, method=method, singular_values=singular_values, details=details)
    _check_explains_more_than_noise(estimate, y.size, method)
    return estimate


#: fewer samples per period of the fastest identified mode than this, and the record may be aliased
_MIN_SAMPLES_PER_PERIOD = 5


def _check_explains_more_than_noise(estimate: ModalEstimate, n_values: int, method: str) -> None:
    """Model-order test: white noise fitted with ``p`` free poles and amplitudes has about ``2 p / N`` of its energy
    explained by chance; a model that explains less than three times that is no better than noise."""
    explained = 1.0 - estimate.residual**2
    chance = 2.0 * estimate.n_poles / n_values
    if explained < 3.0 * chance:
        warn(
            f"{method}: the {len(estimate.frequencies)} fitted mode(s) explain {100 * explained:.2g} % of the "
            f"record's energy, no more than {estimate.n_poles} free poles would fit in white noise "
            f"(about {100 * chance:.2g} %): the record may hold no identifiable oscillation; check the signal, "
            "its noise level, or lower n_modes",
            AccuracyWarning,
        )


def _basis(lam: np.ndarray, t: np.ndarray, constant: bool) -> np.ndarray:
    e = np.exp(np.outer(t, lam))  # (N, k)
    cols = [e.real, e.imag]
    if constant:
        cols.append(np.ones((t.size, 1)))
    return np.hstack(cols)


def _fit(
    y: np.ndarray,
    dt: float,
    lam: np.ndarray,
    *,
    constant: bool,
    method: str,
    singular_values: np.ndarray,
    details: Mapping[str, Any] | None = None,
) -> ModalEstimate:
    """Least-squares amplitudes/phases for fixed continuous poles ``lam`` (upper half plane)."""
    n = y.shape[1]
    k = lam.size
    t = np.arange(n) * dt
    v = _basis(lam, t, constant)
    colnorm = np.linalg.norm(v, axis=0)
    if np.any(colnorm == 0):
        raise IdentificationError(f"{method}: a mode has vanished from the record (zero basis column)")
    coef, _, rank, sv = np.linalg.lstsq(v / colnorm, y.T, rcond=None)
    if rank < v.shape[1] or sv[-1] < 1e-12 * sv[0]:
        w = np.sort(lam.imag)
        rel = np.min(np.diff(w) / w[1:]) if w.size > 1 else np.inf
        raise IdentificationError(
            f"{method}: the modal basis is ill-conditioned (condition {sv[0] / max(sv[-1], 1e-300):.3g}); "
            f"modes are nearly repeated (closest relative spacing {rel:.3g}) or a mode is not excited. "
            "Lower n_modes or record longer"
        )
    coef = coef / colnorm[:, None]
    a = coef[:k].T  # coefficients of exp(-delta t) cos(omega t)
    b = coef[k : 2 * k].T  # of exp(-delta t) sin(omega t)
    offset = coef[2 * k] if constant else np.zeros(y.shape[0])
    # A cos(wt + phi) = A cos(phi) cos(wt) - A sin(phi) sin(wt)
    amps = np.hypot(a, b)
    phases = np.arctan2(-b, a)
    model = v @ coef
    residual = float(np.linalg.norm(y.T - model) / np.linalg.norm(y))
    return ModalEstimate(
        method=method,
        dt=float(dt),
        poles=lam.copy(),
        amplitudes=amps,
        phases=phases,
        offset=np.asarray(offset, dtype=float),
        singular_values=np.asarray(singular_values, dtype=float),
        residual=residual,
        n_poles=2 * k + int(bool(constant)),
        n_samples=n,
        details=dict(details or {}),
    )
