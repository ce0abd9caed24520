"""Port algebra: one-ports, four-poles and their connections (Bulgakov 1954, §8.31–8.46, §9.19–9.21).

Element trees and their impedances, four-pole parameter sets (A, Z, Y, H, G, S, T) and conversions, scikit-rf
networks, SPICE-like netlists, series/parallel/cascade connections
with the Brune test, a library of sections with closed-form chain matrices, image and iterative parameters,
junction voltages of cascades, mechanical analogues and the energy functions of passive networks.
"""

from __future__ import annotations

from .analogues import (
    Damper,
    Mass,
    MechanicalElement,
    MechanicalParallel,
    MechanicalSeries,
    Spring,
    chain_driving_point,
    to_electrical,
    to_mechanical,
)
from .connections import brune_test, cascade, chain_power, parallel, parallel_series, series, series_parallel
from .conversions import PARAMETER_KINDS, convert_parameters
from .energy import EnergyFunctions, EnergyValues, ReactanceCheck, check_reactance_theorem, energy_functions
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
from .junctions import CascadeJunctions, cascade_junctions
from .netlist import Circuit, CircuitElement, parse_netlist
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
from .scattering import skrf_parameters
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
    "CascadeJunctions",
    "Circuit",
    "CircuitElement",
    "Damper",
    "EnergyFunctions",
    "EnergyValues",
    "FourPole",
    "ImageParameters",
    "Impedance",
    "Inductor",
    "IterativeParameters",
    "Mass",
    "MechanicalElement",
    "MechanicalParallel",
    "MechanicalSeries",
    "OnePort",
    "Parallel",
    "ReactanceCheck",
    "Resistor",
    "Series",
    "Spring",
    "TerminatedResponse",
    "bridged_t_section",
    "brune_test",
    "cascade",
    "cascade_junctions",
    "chain_driving_point",
    "chain_power",
    "check_reactance_theorem",
    "convert_parameters",
    "energy_functions",
    "equivalent_two_pole",
    "ideal_transformer",
    "image_parameters",
    "insertion_loss",
    "iterative_parameters",
    "l_section",
    "lattice",
    "lattice_phase_network",
    "parallel",
    "parallel_series",
    "parse_netlist",
    "pi_section",
    "series",
    "series_element",
    "series_parallel",
    "shunt_element",
    "skrf_parameters",
    "t_section",
    "terminated_response",
    "to_electrical",
    "to_mechanical",
    "transformer",
    "twin_t_notch",
    "twin_t_section",
    "working_loss",
]
