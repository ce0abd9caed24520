"""Figure drawers of scene reports (matplotlib is imported by the caller, only when figures are written)."""

from __future__ import annotations

from typing import Any

import numpy as np

from ._questions_mathieu import draw as mathieu_functions  # noqa: F401 - the drawer of the mathieu_functions question


def modified_ince_strutt(ax: Any, *, ratios: list, point: Any = None, q_max: float = 1.0) -> Any:
    """The modified Ince–Strutt diagram (Gribkov & Khokhlov 2015, Fig. 3), with the excitation point marked."""
    from ..periodic import modified_ince_strutt as build

    lo = min(-0.05, 2.0 * point[0]) if point is not None else -0.05
    build(ratios[1:] or ratios).plot(ax=ax, q_max=q_max, a_range=(lo, 1.2 * min(ratios)))
    ax.axvline(0.0, color="0.5", lw=0.6)
    if point is not None:
        ax.plot([point[0]], [point[1]], "o", color="C3", label="excitation point")
        ax.legend(loc="upper left")
    return ax


def ince_strutt(ax: Any, *, orders: int, q_max: float) -> Any:
    from ..periodic import ince_strutt_diagram

    return ince_strutt_diagram(orders, q_max).plot(ax=ax)


def resonance(ax: Any, *, nu: list, amplitudes: list, stable: list) -> Any:
    nu_a = np.repeat(np.asarray(nu)[:, None], np.asarray(amplitudes).shape[1], axis=1)
    amp, st = np.asarray(amplitudes, dtype=float), np.asarray(stable, dtype=bool)
    ok = np.isfinite(amp)
    ax.plot(nu_a[ok & st], amp[ok & st], ".", ms=2, label="stable")
    ax.plot(nu_a[ok & ~st], amp[ok & ~st], "x", ms=2, label="unstable")
    ax.set_xlabel(r"forcing frequency $\nu$, rad/s")
    ax.set_ylabel("amplitude $a$")
    ax.legend()
    return ax
