"""Figure drawers of scene reports (matplotlib is imported by the caller, only when figures are written)."""

from __future__ import annotations

from typing import Any

import numpy as np

from ._questions.mathieu import draw as mathieu_functions  # noqa: F401 - the drawer of the mathieu_functions question
from ._questions.time_response import animation, time_series  # noqa: F401 - drawers of time_response figures


def modified_ince_strutt(ax: Any, *, ratios: list, point: Any = None, q_max: float = 1.0) -> Any:
    """The modified Ince–Strutt diagram (Gribkov & Khokhlov 2015, Fig. 3), with the excitation point marked."""
    from ..periodic import modified_ince_strutt as build

    lo = min(-0.05, 2.0 * point[0]) if point is not None else -0.05
    build(ratios[1:] or ratios).plot(ax=ax, q_max=q_max, a_range=(lo, 1.2 * min(ratios)), point=point)
    ax.axvline(0.0, color="0.5", lw=0.6)
    return ax


def ince_strutt(ax: Any, *, orders: int, q_max: float) -> Any:
    from ..periodic import ince_strutt_diagram

    return ince_strutt_diagram(orders, q_max).plot(ax=ax)


def resonance(ax: Any, *, nu: list, amplitudes: list, stable: list, folds: list = ()) -> Any:
    """The resonance curve as continuous branches (stable solid, unstable dashed), the jumps circled."""
    from ..nonlinear.averaging import Fold, FrequencyResponse

    fr = FrequencyResponse(
        np.asarray(nu, dtype=float),
        np.asarray(amplitudes, dtype=float),
        np.asarray(stable, dtype=bool),
        tuple(Fold(float(x), float(a), True) for x, a in folds),
    )
    return fr.plot(ax=ax)


def branch(ax: Any, **data: Any) -> Any:
    """A branch of periodic solutions (the ``continuation`` question)."""
    from ._questions.continuation import draw_branch

    return draw_branch(ax, **data)
