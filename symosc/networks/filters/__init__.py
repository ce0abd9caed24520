"""Frequency-selective networks: image-parameter filters, matching pads and dynamic vibration absorbers.

Constant-k and m-derived sections and reactance transformations (Bulgakov 1954, §9.28–9.33), matching pads
(§9.35) and the vibration absorber with its fixed points and H-infinity optimum (Frahm 1909; Den Hartog 1928;
§9.41–9.42).
"""

from __future__ import annotations

from ..synthesis.correcting import lattice_from_transmission  # noqa: F401 (its path before it moved to synthesis)
from .absorber import (
    Absorber,
    HInfinityOptimum,
    absorber_fixed_points,
    absorber_hinf_optimum,
    absorber_optimum,
    amplification_squared,
)
from .image_filters import (
    FilterSection,
    bandpass_attenuation_poles,
    constant_k_section,
    frequency_map,
    image_operating_loss,
    m_derived_section,
)
from .pads import MatchingPad, matching_l_pad

__all__ = [
    "Absorber",
    "FilterSection",
    "HInfinityOptimum",
    "MatchingPad",
    "absorber_fixed_points",
    "absorber_hinf_optimum",
    "absorber_optimum",
    "amplification_squared",
    "bandpass_attenuation_poles",
    "constant_k_section",
    "frequency_map",
    "image_operating_loss",
    "m_derived_section",
    "matching_l_pad",
]
