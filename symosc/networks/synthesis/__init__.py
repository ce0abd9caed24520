"""Synthesis of passive one-ports and correcting networks (Bulgakov 1954, ch. 9 B–D).

The positive-real test, Foster and Cauer forms, Brune, Bott–Duffin and M-function realisations, and
constant-resistance correcting links and cascades.  Element values stay exact: when they are algebraic numbers the
procedures work in nested number fields (the private exact-arithmetic core :mod:`symosc.networks._exact`).
"""

from __future__ import annotations

from .bott_duffin import bott_duffin_synthesis
from .brune import brune_synthesis, minimum_real_part
from .correcting import (
    CORRECTING_LINKS,
    BridgedTLink,
    CorrectingLink,
    constant_resistance_bridged_t,
    correcting_link,
    lattice_from_transmission,
    link_transfer,
)
from .correcting_cascade import CorrectingCascade, correcting_cascade
from .foster_cauer import cauer_first, cauer_second, foster_first, foster_second, is_reactance_function
from .m_functions import m_abscissa, m_function_synthesis, richards_function
from .positive_real import (
    PositiveRealReport,
    biquadratic_is_positive_real,
    is_m_function,
    is_positive_real,
    positive_real_report,
    real_part_on_axis,
)

__all__ = [
    "CORRECTING_LINKS",
    "BridgedTLink",
    "CorrectingCascade",
    "CorrectingLink",
    "PositiveRealReport",
    "biquadratic_is_positive_real",
    "bott_duffin_synthesis",
    "brune_synthesis",
    "cauer_first",
    "cauer_second",
    "constant_resistance_bridged_t",
    "correcting_cascade",
    "correcting_link",
    "foster_first",
    "foster_second",
    "is_m_function",
    "is_positive_real",
    "is_reactance_function",
    "lattice_from_transmission",
    "link_transfer",
    "m_abscissa",
    "m_function_synthesis",
    "minimum_real_part",
    "positive_real_report",
    "real_part_on_axis",
    "richards_function",
]
