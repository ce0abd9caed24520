"""Periodic systems: Mathieu characteristic values and functions, Floquet theory, Ince–Strutt stability diagrams."""

from .comparison import MethodComparison, compare_methods
from .floquet import FloquetResult, floquet_multipliers, monodromy
from .ince_strutt import (
    InceStruttDiagram,
    ModifiedInceStruttDiagram,
    ince_strutt_diagram,
    mathieu_stable,
    modified_ince_strutt,
    series_boundary,
)
from .mathieu import MathieuValues, mathieu_a, mathieu_b, mathieu_characteristic, mathieu_kernel
from .mathieu_functions import *  # noqa: F403  (ce/se, modified functions, Floquet exponent and solutions)
from .mathieu_functions import __all__ as _mathieu_functions_all
from .mathieu_series import (
    SeriesValue,
    mathieu_series_a,
    mathieu_series_b,
    mathieu_series_radius,
    mathieu_series_value,
)
from .stability import StabilityRegion, stability_region

__all__ = [
    "FloquetResult",
    "InceStruttDiagram",
    "MathieuValues",
    "MethodComparison",
    "ModifiedInceStruttDiagram",
    "SeriesValue",
    "StabilityRegion",
    "compare_methods",
    "floquet_multipliers",
    "ince_strutt_diagram",
    "mathieu_a",
    "mathieu_b",
    "mathieu_characteristic",
    "mathieu_kernel",
    "mathieu_series_a",
    "mathieu_series_b",
    "mathieu_series_radius",
    "mathieu_series_value",
    "mathieu_stable",
    "modified_ince_strutt",
    "monodromy",
    "series_boundary",
    "stability_region",
    *_mathieu_functions_all,
]
