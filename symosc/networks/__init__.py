"""Networks and passive systems: one-ports, four-poles, synthesis, filters, vibration absorbers.

After Bulgakov (1954), §8.31–8.49 and ch. 9 B–D.
"""

from .absorber import (
    Absorber,
    HInfinityOptimum,
    absorber_fixed_points,
    absorber_hinf_optimum,
    absorber_optimum,
    amplification_squared,
)
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
from .bott_duffin import bott_duffin_synthesis
from .brune import brune_synthesis, minimum_real_part
from .connections import brune_test, cascade, chain_power, parallel, parallel_series, series, series_parallel
from .conversions import PARAMETER_KINDS, convert_parameters
from .correcting import (
    CORRECTING_LINKS,
    BridgedTLink,
    CorrectingLink,
    constant_resistance_bridged_t,
    correcting_link,
    link_transfer,
)
from .correcting_cascade import CorrectingCascade, correcting_cascade
from .energy import EnergyFunctions, EnergyValues, ReactanceCheck, check_reactance_theorem, energy_functions
from .filters import (
    FilterSection,
    bandpass_attenuation_poles,
    constant_k_section,
    frequency_map,
    image_operating_loss,
    lattice_from_transmission,
    m_derived_section,
)
from .foster_cauer import cauer_first, cauer_second, foster_first, foster_second, is_reactance_function
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
from .m_functions import m_abscissa, m_function_synthesis, richards_function
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
from .pads import MatchingPad, matching_l_pad
from .positive_real import (
    PositiveRealReport,
    biquadratic_is_positive_real,
    is_m_function,
    is_positive_real,
    positive_real_report,
    real_part_on_axis,
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
    "CORRECTING_LINKS",
    "PARAMETER_KINDS",
    "Absorber",
    "BridgedTLink",
    "BruneSection",
    "Capacitor",
    "CascadeJunctions",
    "CorrectingCascade",
    "CorrectingLink",
    "Damper",
    "EnergyFunctions",
    "EnergyValues",
    "FilterSection",
    "FourPole",
    "HInfinityOptimum",
    "ImageParameters",
    "Impedance",
    "Inductor",
    "IterativeParameters",
    "Mass",
    "MatchingPad",
    "MechanicalElement",
    "MechanicalParallel",
    "MechanicalSeries",
    "OnePort",
    "Parallel",
    "PositiveRealReport",
    "ReactanceCheck",
    "Resistor",
    "Series",
    "Spring",
    "TerminatedResponse",
    "absorber_fixed_points",
    "absorber_hinf_optimum",
    "absorber_optimum",
    "amplification_squared",
    "bandpass_attenuation_poles",
    "biquadratic_is_positive_real",
    "bott_duffin_synthesis",
    "bridged_t_section",
    "brune_synthesis",
    "brune_test",
    "cascade",
    "cascade_junctions",
    "cauer_first",
    "cauer_second",
    "chain_driving_point",
    "chain_power",
    "check_reactance_theorem",
    "constant_k_section",
    "constant_resistance_bridged_t",
    "convert_parameters",
    "correcting_cascade",
    "correcting_link",
    "energy_functions",
    "equivalent_two_pole",
    "foster_first",
    "foster_second",
    "frequency_map",
    "ideal_transformer",
    "image_operating_loss",
    "image_parameters",
    "insertion_loss",
    "is_m_function",
    "is_positive_real",
    "is_reactance_function",
    "iterative_parameters",
    "l_section",
    "lattice",
    "lattice_from_transmission",
    "lattice_phase_network",
    "link_transfer",
    "m_abscissa",
    "m_derived_section",
    "m_function_synthesis",
    "matching_l_pad",
    "minimum_real_part",
    "parallel",
    "parallel_series",
    "pi_section",
    "positive_real_report",
    "real_part_on_axis",
    "richards_function",
    "series",
    "series_element",
    "series_parallel",
    "shunt_element",
    "t_section",
    "terminated_response",
    "to_electrical",
    "to_mechanical",
    "transformer",
    "twin_t_notch",
    "twin_t_section",
    "working_loss",
]

# public functions refuse invalid arguments with ParameterError (symosc/_validate.py)
from .._validate import guard_public_api as _guard_public_api

_guard_public_api(__name__)

# SymPy printer hooks (sympy.latex, sstr, pretty) and pickling support on every public model and result
from .._printing import add_printing_hooks_to_public as _add_printing_hooks_to_public  # noqa: E402

_add_printing_hooks_to_public(__name__)
