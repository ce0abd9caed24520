"""Canonical form and phase portrait of ``k0 y'' + k1 y' + k2 y = 0`` (Bulgakov (1954), §4.1–4.2, §4.9).

The canonical equations of a natural system with constant mass ``m = k0`` are ``q' = p/k0``,
``p' = -k2 q - (k1/k0) p`` ((4.8)–(4.11) with ``V = k2 q²/2``, ``Q = -k1 q'``).  Dividing by ``k0`` gives
``y'' + 2h y' + k² y = 0`` with ``h = k1/(2 k0)``, ``k² = k2/k0``.  Trajectories are evaluated in closed form
(the free motion ``M(t)`` of (4.62)–(4.70) and its derivative), continuous through critical damping.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ParameterError
from .one_dof import _check, _cs, classify_equilibrium

__all__ = ["PhasePortrait", "phase_portrait"]


def _free_motion(h: float, k2: float, y0: float, v0: float, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``y(t)`` and ``y'(t)`` of ``y'' + 2h y' + k2 y = 0`` from ``(y0, v0)``; ``C' = -d S``, ``S' = C``."""
    d = k2 - h * h
    C, S = _cs(d, t)
    e = np.exp(-h * t)
    a = v0 + h * y0
    y = e * (y0 * C + a * S)
    v = e * (v0 * C - (k2 * y0 + h * v0) * S)
    return y, v


@dataclass(frozen=True)
class PhasePortrait(SymPyPrintable):
    """Result of :func:`phase_portrait`: trajectories of ``y'' + 2h y' + k² y = 0`` in the ``(y, y')`` plane.

    Attributes
    ----------
    h, k_squared : float
        The canonical coefficients ``h = k1/(2 k0)``, ``k² = k2/k0``.
    kind : str
        Type of the singular point at the origin (``classify_equilibrium``).
    eigenvalues : tuple of complex
        Roots of ``λ² + 2h λ + k² = 0``.
    directions : tuple of tuple
        Slopes ``y'/y = λ`` of the invariant straight lines (real roots only: nodes and saddles), else empty.
    t : ndarray
        Time grid of the trajectories.
    initial_states : ndarray, shape (n, 2)
        ``(y0, y0')`` of each trajectory.
    y, v : ndarray, shape (n, len(t))
        Displacement and velocity along each trajectory.
    """

    h: float
    k_squared: float
    kind: str
    eigenvalues: tuple
    directions: tuple
    t: np.ndarray
    initial_states: np.ndarray
    y: np.ndarray
    v: np.ndarray

    def __repr__(self) -> str:
        return (
            f"PhasePortrait(y'' + {2 * self.h:.6g} y' + {self.k_squared:.6g} y = 0: {self.kind}, "
            f"{len(self.initial_states)} trajectories)"
        )

    def _repr_latex_(self) -> str:
        return rf"$\ddot y + {2 * self.h:.6g}\,\dot y + {self.k_squared:.6g}\,y = 0\quad \text{{({self.kind})}}$"

    def plot(self, *, ax=None, arrows: bool = True):
        """Draw the trajectories (arrows in the direction of motion) and the invariant lines; returns the Axes.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.
        arrows : bool, optional
            Mark the direction of motion on each trajectory (default True).
        """
        from .._util import figure_axes

        ax = figure_axes(ax)
        for y, v in zip(self.y, self.v, strict=True):
            (line,) = ax.plot(y, v, lw=1)
            if arrows and y.size > 2:
                j = max(1, y.size // 8)
                ax.annotate(
                    "",
                    xy=(y[j + 1], v[j + 1]),
                    xytext=(y[j], v[j]),
                    arrowprops={"arrowstyle": "->", "color": line.get_color()},
                )
        lim = np.abs(self.initial_states).max() * 1.2 or 1.0
        for slope in self.directions:
            ax.plot([-lim, lim], [-slope * lim, slope * lim], "k--", lw=0.7)
        ax.plot([0], [0], "ko", ms=4)
        ax.set_xlabel("y")
        ax.set_ylabel("y'")
        ax.set_title(f"{self.kind} (Bulgakov (1954), §4.2)")
        return ax


@validated
def phase_portrait(
    k0: float,
    k1: float,
    k2: float,
    initial_states: Any = None,
    *,
    t_max: float | None = None,
    n_points: int = 400,
) -> PhasePortrait:
    """Canonical form and phase trajectories of ``k0 y'' + k1 y' + k2 y = 0`` (Bulgakov (1954), §4.1–4.2).

    Parameters
    ----------
    k0, k1, k2 : float
        Mass (positive), damping and stiffness (any sign: negative damping or stiffness give unstable foci,
        nodes and saddles).
    initial_states : array_like, shape (n, 2), optional
        Starting points ``(y0, y0')``; default eight points on the unit circle.
    t_max : float, optional
        Length of each trajectory; default ``6`` time constants or periods of the slowest motion.
    n_points : int
        Samples per trajectory (an integer >= 2).

    Returns
    -------
    PhasePortrait

    Examples
    --------
    >>> from symosc.linear import phase_portrait
    >>> pp = phase_portrait(2.0, 0.8, 8.0, [[1.0, 0.0]], t_max=3.0)
    >>> pp.h, pp.k_squared, pp.kind
    (0.2, 4.0, 'stable focus')
    >>> pp.eigenvalues
    ((-0.2+1.98997487421324j), (-0.2-1.98997487421324j))

    See Also
    --------
    classify_equilibrium, linear_filter
    """
    k0, k1, k2 = _check(k0, k1, k2)
    h, ksq = k1 / (2 * k0), k2 / k0
    if initial_states is None:
        ang = np.linspace(0, 2 * np.pi, 9)[:-1]
        initial_states = np.column_stack([np.cos(ang), np.sin(ang)])
    x0 = np.atleast_2d(np.asarray(initial_states, dtype=float))
    if x0.ndim != 2 or x0.shape[1] != 2 or not np.all(np.isfinite(x0)):
        raise ParameterError("initial_states must be finite pairs (y0, y0'), shape (n, 2)")
    if int(n_points) < 2:
        raise ParameterError("n_points must be at least 2")
    disc = h * h - ksq
    roots = (complex(-h + np.sqrt(complex(disc))), complex(-h - np.sqrt(complex(disc))))
    if t_max is None:
        re_max = max(r.real for r in roots)
        if re_max > 1e-12:  # unstable: until the state grows by about e³
            t_max = 3.0 / re_max
        elif re_max < -1e-12:  # stable: five time constants of the slowest motion
            t_max = 5.0 / -re_max
        else:  # center or a zero root: one period (or unit time)
            t_max = 2 * np.pi / abs(roots[0].imag) if abs(roots[0].imag) > 1e-12 else 1.0
        t_max = min(t_max, 100.0)
    t_max = float(t_max)
    if not t_max > 0:
        raise ParameterError(f"t_max must be positive, got {t_max}")
    t = np.linspace(0.0, t_max, int(n_points))
    ys, vs = zip(*(_free_motion(h, ksq, a, b, t) for a, b in x0), strict=True)
    directions = tuple(r.real for r in roots) if disc > 0 else ((-h,) if disc == 0 else ())
    return PhasePortrait(
        h=h,
        k_squared=ksq,
        kind=classify_equilibrium(k0, k1, k2),
        eigenvalues=roots,
        directions=directions,
        t=t,
        initial_states=x0,
        y=np.array(ys),
        v=np.array(vs),
    )
