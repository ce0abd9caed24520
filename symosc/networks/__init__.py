"""Networks and passive systems: one-ports, four-poles, synthesis, filters, vibration absorbers.

After Bulgakov (1954), §8.31–8.49 and ch. 9 B–D.
"""

from .connections import brune_test, cascade, chain_power, parallel, parallel_series, series, series_parallel
from .conversions import PARAMETER_KINDS, convert_parameters
from .fourpoles import FourPole
from .image import (
    ImageParameters,
    IterativeParameters,
    TerminatedResponse,
    image_parameters,
    insertion_loss,
    iterative_parameters,
    terminated_response,
    working_loss,
)
from .oneports import (
    BruneSection,
    Capacitor,
    Impedance,
    Inductor,
    OnePort,
    Parallel,
    Resistor,
    Series,
    equivalent_two_pole,
)
from .sections import (
    bridged_t_section,
    ideal_transformer,
    l_section,
    lattice,
    lattice_phase_network,
    pi_section,
    series_element,
    shunt_element,
    t_section,
    transformer,
    twin_t_notch,
    twin_t_section,
)

__all__ = [
    "PARAMETER_KINDS",
    "BruneSection",
    "Capacitor",
    "FourPole",
    "ImageParameters",
    "IterativeParameters",
    "TerminatedResponse",
    "Impedance",
    "Inductor",
    "OnePort",
    "Parallel",
    "Resistor",
    "Series",
    "bridged_t_section",
    "brune_test",
    "cascade",
    "chain_power",
    "convert_parameters",
    "equivalent_two_pole",
    "image_parameters",
    "insertion_loss",
    "iterative_parameters",
    "terminated_response",
    "working_loss",
    "ideal_transformer",
    "l_section",
    "lattice",
    "lattice_phase_network",
    "parallel",
    "parallel_series",
    "pi_section",
    "series",
    "series_element",
    "series_parallel",
    "shunt_element",
    "t_section",
    "transformer",
    "twin_t_notch",
    "twin_t_section",
]
