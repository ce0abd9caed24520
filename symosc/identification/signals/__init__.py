"""Modal models from sampled free oscillations: the signal estimators (Belyakov 2005, Ch. II §3, Ch. III §2).

Prony's method with its sampling advisor, Kung's Hankel-SVD realisation (ERA), the matrix pencil and TLS-ESPRIT,
maximum-likelihood refinement, the two-stage structure-preserving identification, and the noise studies (the
Cramér–Rao bound, Monte Carlo runs).
"""

from __future__ import annotations

from ._signals import ModalEstimate
from .era import era, realize
from .noise import (
    ApplicabilityCheck,
    CramerRaoBound,
    ErrorVsNoise,
    MonteCarloResult,
    add_noise,
    applicability,
    cramer_rao_bound,
    error_vs_noise,
    monte_carlo,
    noise_sigma,
)
from .pencil import esprit, matrix_pencil
from .prony import SamplingAdvice, prony, sampling_advice
from .refine import refine
from .two_stage import SecondOrderModel, two_stage

__all__ = [
    "ApplicabilityCheck",
    "CramerRaoBound",
    "ErrorVsNoise",
    "ModalEstimate",
    "MonteCarloResult",
    "SamplingAdvice",
    "SecondOrderModel",
    "add_noise",
    "applicability",
    "cramer_rao_bound",
    "era",
    "error_vs_noise",
    "esprit",
    "matrix_pencil",
    "monte_carlo",
    "noise_sigma",
    "prony",
    "realize",
    "refine",
    "sampling_advice",
    "two_stage",
]
