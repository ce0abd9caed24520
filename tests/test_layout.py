"""The package's layout: old import paths keep working, folders stay small, subpackages do not import in circles.

The split of the larger subpackages into method families moved modules; the table below is the
public API of every module of the previous release (each module's ``__all__``), so that code written against those
paths keeps importing (with a ``DeprecationWarning`` for moved modules).
"""

from __future__ import annotations

import ast
import importlib
import sys
import warnings
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "symosc"

#: module path -> its __all__ in the release before the split
OLD_MODULES = {
    "symosc.mechanics.circuits": ("LoopEquations", "loop_equations"),
    "symosc.mechanics.electromechanical": ("electromechanical_system",),
    "symosc.mechanics.governor": (
        "GovernorStatics",
        "governor_statics",
        "stodola_time_constant",
        "vyshnegradsky_cubic",
    ),
    "symosc.algebra.adjugate": ("adjugate_derivative_at_root", "adjugate_derivatives"),
    "symosc.algebra.block": (
        "BorderingInverse",
        "block_determinant",
        "block_inverse",
        "bordering_inverse",
        "cyclic_block_determinant",
        "triangular_adjugate_series",
        "triangular_inverse_series",
    ),
    "symosc.algebra.cayley": ("cayley_real_form", "real_matrix_function"),
    "symosc.algebra.charpoly": ("adjugate_poly", "charpoly", "danilevsky", "krylov", "leverrier"),
    "symosc.algebra.continuation": ("AnalyticContinuation", "analytic_continuation"),
    "symosc.algebra.interpolation": ("function_elementary_divisors", "interpolation_basis", "interpolation_polynomial"),
    "symosc.algebra.matrix_coefficient_series": ("matrix_coefficient_function",),
    "symosc.algebra.matrix_functions": ("MatrixFunction", "matrix_function", "series_converges"),
    "symosc.algebra.matrizant": ("Matrizant", "matrizant", "matrizant_numeric"),
    "symosc.algebra.matrizant_product": ("MatrizantProduct", "matrizant_product"),
    "symosc.algebra.modal": ("ModalMatrix", "TriangularForm", "luzin_form", "modal_matrix", "pencil_modal_matrix"),
    "symosc.algebra.pencils": (
        "PencilCanonicalForm",
        "PencilEquivalence",
        "pencil_canonical_form",
        "pencil_equivalence",
    ),
    "symosc.algebra.polynomial_matrices": (
        "PencilDivisors",
        "SmithForm",
        "determinantal_divisors",
        "elementary_divisors",
        "invariant_factors",
        "minimal_polynomial",
        "pencil_divisors",
        "polymatrix_divmod",
        "smith_form",
    ),
    "symosc.algebra.power_series": ("matrix_power_series",),
    "symosc.algebra.spectral": ("SpectralComponent", "SpectralDecomposition", "spectral_decomposition"),
    "symosc.identification.era": ("era", "realize"),
    "symosc.identification.noise": (
        "ApplicabilityCheck",
        "CramerRaoBound",
        "ErrorVsNoise",
        "MonteCarloResult",
        "add_noise",
        "applicability",
        "cramer_rao_bound",
        "error_vs_noise",
        "monte_carlo",
        "noise_sigma",
    ),
    "symosc.identification.pencil": ("esprit", "matrix_pencil"),
    "symosc.identification.prony": ("SamplingAdvice", "prony", "sampling_advice"),
    "symosc.identification.refine": ("refine",),
    "symosc.identification.two_stage": ("SecondOrderModel", "two_stage"),
    "symosc.linear.bounds": (
        "FrequencyBounds",
        "PowerIteration",
        "constrained_eigenvalues",
        "dunkerley",
        "dunkerley_bounds",
        "power_iteration",
        "rayleigh_quotient",
    ),
    "symosc.linear.conservative": ("ModalAnalysis", "a_orthonormalize", "conservative_modes"),
    "symosc.linear.criteria": ("StabilityVerdict", "hurwitz", "hurwitz_matrix", "lienard_chipart"),
    "symosc.linear.degree": ("StabilityDegree", "hurwitz_at_degree", "shifted_coefficients", "stability_degree"),
    "symosc.linear.delay_lines": ("DelayStabilityLines", "delay_equal_stability_lines"),
    "symosc.linear.delay_response": ("DelayResponseSeries", "delay_response_series"),
    "symosc.linear.dpartition": (
        "DPartition",
        "DiscriminantCurve",
        "d_partition",
        "discriminant_curve",
        "vyshnegradsky_diagram",
    ),
    "symosc.linear.fd_systems": (
        "Compatibility",
        "FrequencyResponse",
        "FundamentalSolutions",
        "ImpulseResponse",
        "compatibility",
        "frequency_response",
        "fundamental_solutions",
        "impulse_response",
        "mean_power",
        "resonant_particular",
        "worst_case_gain",
    ),
    "symosc.linear.loops": ("chain_transmittance", "closed_loop_characteristic", "return_difference"),
    "symosc.linear.normal_form": ("NormalForm", "modal_normal_form"),
    "symosc.linear.nyquist": ("NyquistResult", "StabilityMargins", "nyquist", "stability_margins"),
    "symosc.linear.one_dof": (
        "LinearFilter",
        "StabilityCoefficients",
        "classify_equilibrium",
        "linear_filter",
        "periodic_forced_response",
        "stability_coefficients",
        "volterra_march",
    ),
    "symosc.linear.phase_plane": ("PhasePortrait", "phase_portrait"),
    "symosc.linear.quadratic_forms": ("QuadraticFormVerdict", "routh_form_criteria"),
    "symosc.linear.regions": ("StabilityRegion", "robust_boundary", "stability_region"),
    "symosc.linear.regulator": (
        "EqualStabilityLines",
        "RegulatorOptimum",
        "equal_stability_lines",
        "optimize_regulator",
    ),
    "symosc.linear.routh": ("RouthArray", "routh_array"),
    "symosc.linear.servo": ("ServoOptimum", "ServoStabilityLines", "servo_optimum", "servo_stability_lines"),
    "symosc.linear.strings": ("chain_matrices", "influence_matrix", "string_frequencies", "string_modes"),
    "symosc.linear.two_dof": (
        "TuningCurves",
        "TwoDOFBeats",
        "TwoDOFSystem",
        "tuning_curves",
        "two_dof_beats",
        "two_dof_system",
    ),
    "symosc.mechanics.canonical": ("CanonicalTransformation", "canonical_transformation", "is_canonical"),
    "symosc.mechanics.hamilton_jacobi": (
        "ActionVariable",
        "HamiltonJacobiSeparation",
        "action_variable",
        "action_variable_numeric",
        "separate_hamilton_jacobi",
    ),
    "symosc.mechanics.hamiltonian": ("HamiltonianSystem", "poisson_bracket"),
    "symosc.mechanics.routh": ("RouthReduction", "SteadyMotion", "routh_reduction"),
    "symosc.networks.absorber": (
        "Absorber",
        "HInfinityOptimum",
        "absorber_fixed_points",
        "absorber_hinf_optimum",
        "absorber_optimum",
        "amplification_squared",
    ),
    "symosc.networks.analogues": (
        "Damper",
        "Mass",
        "MechanicalElement",
        "MechanicalParallel",
        "MechanicalSeries",
        "Spring",
        "chain_driving_point",
        "to_electrical",
        "to_mechanical",
    ),
    "symosc.networks.bott_duffin": ("bott_duffin_synthesis",),
    "symosc.networks.brune": ("brune_synthesis", "minimum_real_part"),
    "symosc.networks.connections": (
        "brune_test",
        "cascade",
        "chain_power",
        "parallel",
        "parallel_series",
        "series",
        "series_parallel",
    ),
    "symosc.networks.conversions": ("PARAMETER_KINDS", "convert_parameters"),
    "symosc.networks.correcting": (
        "BridgedTLink",
        "CORRECTING_LINKS",
        "CorrectingLink",
        "constant_resistance_bridged_t",
        "correcting_link",
        "link_transfer",
    ),
    "symosc.networks.correcting_cascade": ("CorrectingCascade", "correcting_cascade"),
    "symosc.networks.energy": (
        "EnergyFunctions",
        "EnergyValues",
        "ReactanceCheck",
        "check_reactance_theorem",
        "energy_functions",
    ),
    "symosc.networks.filters": (
        "FilterSection",
        "bandpass_attenuation_poles",
        "constant_k_section",
        "frequency_map",
        "image_operating_loss",
        "lattice_from_transmission",
        "m_derived_section",
    ),
    "symosc.networks.foster_cauer": (
        "cauer_first",
        "cauer_second",
        "foster_first",
        "foster_second",
        "is_reactance_function",
    ),
    "symosc.networks.fourpoles": ("FourPole",),
    "symosc.networks.image": (
        "ImageParameters",
        "IterativeParameters",
        "TerminatedResponse",
        "image_parameters",
        "insertion_loss",
        "iterative_parameters",
        "terminated_response",
        "working_loss",
    ),
    "symosc.networks.junctions": ("CascadeJunctions", "cascade_junctions"),
    "symosc.networks.m_functions": ("m_abscissa", "m_function_synthesis", "richards_function"),
    "symosc.networks.oneports": (
        "BruneSection",
        "Capacitor",
        "Impedance",
        "Inductor",
        "OnePort",
        "Parallel",
        "Resistor",
        "Series",
        "equivalent_two_pole",
    ),
    "symosc.networks.pads": ("MatchingPad", "matching_l_pad"),
    "symosc.networks.positive_real": (
        "PositiveRealReport",
        "biquadratic_is_positive_real",
        "is_m_function",
        "is_positive_real",
        "positive_real_report",
        "real_part_on_axis",
    ),
    "symosc.networks.sections": (
        "bridged_t_section",
        "ideal_transformer",
        "l_section",
        "lattice",
        "lattice_phase_network",
        "pi_section",
        "series_element",
        "shunt_element",
        "t_section",
        "transformer",
        "twin_t_notch",
        "twin_t_section",
    ),
    "symosc.nonlinear.averaging": (
        "AveragedEquations",
        "StationaryRegime",
        "averaged_equations",
        "describing_function",
    ),
    "symosc.nonlinear.averaging_ndof": (
        "MultiAveragedEquations",
        "averaged_equations_ndof",
        "dry_friction_ratio",
        "dry_friction_torus_average",
    ),
    "symosc.nonlinear.averaging_normal_form": (
        "AveragingNormalForm",
        "QuasiPeriodicRegime",
        "ShortenedEquations",
        "averaging_normal_form",
    ),
    "symosc.nonlinear.backlash_servo": ("BacklashServoRun", "simulate_backlash_servo"),
    "symosc.nonlinear.conservative": ("Equilibrium", "classify_equilibrium", "libration_period", "rotation_period"),
    "symosc.nonlinear.delay": (
        "DelayRoots",
        "QuasiPolynomial",
        "andronov_maier_optimum",
        "callender_hartree_porter_optimum",
        "characteristic_quasipolynomial",
        "count_roots",
        "quasi_polynomial",
        "quasi_polynomial_roots",
    ),
    "symosc.nonlinear.design_linearization": ("DesignLinearization", "design_amplitude_linearization"),
    "symosc.nonlinear.flywheel_series": ("FlywheelSpeedSeries", "flywheel_speed_series"),
    "symosc.nonlinear.forced_nonresonant": ("NonResonantForcedSolution", "nonresonant_forced_solution"),
    "symosc.nonlinear.forced_poincare": ("ForcedPeriodicSolution", "forced_periodic_solution"),
    "symosc.nonlinear.gyro_pendulum": ("GyroPendulumModes", "gyro_pendulum_modes"),
    "symosc.nonlinear.harmonic_linearization": (
        "HarmonicCycle",
        "HarmonicLinearization",
        "LinearizationBoundary",
        "TwoNonlinearityCycle",
        "harmonic_linearization",
        "linearization_boundary",
        "neimark_curve",
        "self_oscillations",
        "servo_characteristic",
        "servo_equations",
        "servo_region",
        "two_nonlinearity_cycles",
    ),
    "symosc.nonlinear.high_frequency": (
        "FastAveragedSystem",
        "VibrationalAveraging",
        "fast_averaged_system",
        "vibrational_averaging",
        "vibrational_averaging_of",
        "vibrational_stiffness",
    ),
    "symosc.nonlinear.implicit_point_map": ("ImplicitMapCycle", "implicit_map_cycle"),
    "symosc.nonlinear.lindstedt": ("LindstedtSeries", "lindstedt"),
    "symosc.nonlinear.piecewise": (
        "CoulombMotion",
        "HalfSwingMap",
        "coulomb_oscillator",
        "half_swing_map",
        "quadratic_drag_eta",
        "quadratic_drag_eta_series",
        "quadratic_drag_half_swing_times",
    ),
    "symosc.nonlinear.poincare": ("LimitCycleSeries", "limit_cycle"),
    "symosc.nonlinear.poincare_fd": ("OperatorCycle", "PoincareOperatorSystem", "poincare_operator_system"),
    "symosc.nonlinear.poincare_ndof": ("NDofPeriodicSolution", "periodic_solution_ndof"),
    "symosc.nonlinear.poincare_second": ("SecondApproximation", "poincare_second_approximation"),
    "symosc.nonlinear.point_map": ("PointMapFixedPoint", "point_map_fixed_point"),
    "symosc.nonlinear.relay_regulator": (
        "RelayCycle",
        "RelayRegulatorBoundary",
        "RelayRegulatorRegion",
        "relay_regulator_boundary",
        "relay_regulator_cycles",
        "relay_regulator_region",
    ),
    "symosc.nonlinear.special_systems": (
        "ClockEscapement",
        "FlywheelDesign",
        "StepGenerator",
        "backlash_critical_gap",
        "clock_escapement",
        "radinger_flywheel",
        "step_valve_generator",
    ),
    "symosc.nonlinear.validate": (
        "NumericCycle",
        "SeriesValidation",
        "numeric_limit_cycle",
        "numeric_orbit",
        "numeric_period",
        "validate_limit_cycle",
        "validate_lindstedt",
    ),
}


@pytest.mark.parametrize("path", sorted(OLD_MODULES))
def test_every_old_module_path_still_imports(path):
    cached = sys.modules.get(path)
    if cached is not None and cached.__name__ != path:  # an alias an earlier test imported: import it afresh
        del sys.modules[path]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        module = importlib.import_module(path)
    moved = module.__name__ != path
    assert moved == any(issubclass(w.category, DeprecationWarning) for w in caught)
    package = importlib.import_module(path.rsplit(".", 1)[0])
    for name in OLD_MODULES[path]:
        assert getattr(module, name) is getattr(package, name), name


def _modules() -> dict[str, tuple[Path, bool]]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        package = parts[-1] == "__init__"
        out[".".join(parts[:-1] if package else parts)] = (path, package)
    return out


def test_every_folder_holds_at_most_15_modules():
    sizes = {str(d.relative_to(PACKAGE.parent)): len(list(d.glob("*.py"))) for d in [PACKAGE, *PACKAGE.rglob("*/")]}
    assert {d: n for d, n in sizes.items() if n > 15} == {}


def _runtime_imports(tree: ast.AST) -> list[ast.ImportFrom | ast.Import]:
    """Import statements outside ``if TYPE_CHECKING:`` blocks (those run only under a type checker)."""
    skip = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            skip |= {id(n) for n in ast.walk(node)}
    return [n for n in ast.walk(tree) if isinstance(n, ast.Import | ast.ImportFrom) and id(n) not in skip]


def _import_graph() -> dict[str, set[str]]:
    modules = _modules()
    graph: dict[str, set[str]] = {m: set() for m in modules}
    for name, (path, package) in modules.items():
        for node in _runtime_imports(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level:
                base = name.split(".") if package else name.split(".")[:-1]
                base = base[: len(base) - node.level + 1]
                stem = ".".join(base + ([node.module] if node.module else []))
                targets = [f"{stem}.{a.name}" if f"{stem}.{a.name}" in modules else stem for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                targets = [node.module or ""]
            else:
                targets = [a.name for a in node.names]
            for target in targets:
                while target and target not in modules:
                    target = target.rpartition(".")[0]
                if target and target != name and not name.startswith(target + "."):
                    graph[name].add(target)
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[set[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    out: list[set[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = set()
            while True:
                w = stack.pop()
                component.add(w)
                if w == v:
                    break
            if len(component) > 1:
                out.append(component)

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def _private_core(component: set[str]) -> bool:
    """All modules of the circle are in one subpackage and private to it: below the subpackage each path holds a
    ``_name`` (a private module, or a module of a private subpackage such as ``networks._exact``)."""
    parts = [m.split(".") for m in component]
    packages = {tuple(p[:2]) if len(p) > 2 else tuple(p[:1]) for p in parts}
    return len(packages) == 1 and all(any(x.startswith("_") for x in p[1:]) for p in parts)


def test_no_import_circle_outside_a_private_core():
    cycles = [sorted(c) for c in _cycles(_import_graph()) if not _private_core(c)]
    assert cycles == []


def test_the_circle_check_can_fail():
    graph = {"p.a": {"p.b"}, "p.b": {"p.a"}, "p._c": {"p._d"}, "p._d": {"p._c"}}
    found = _cycles(graph)
    assert sorted(map(sorted, found)) == [["p._c", "p._d"], ["p.a", "p.b"]]
    assert [_private_core(c) for c in sorted(found, key=sorted)] == [True, False]


def test_a_function_pickled_under_the_old_lazy_module_path_loads():
    """``symosc._lazy`` moved into ``symosc.numeric``: a LazyFunction pickled before names the old module, and
    loading it finds the class (with a deprecation warning)."""
    import pickle

    import sympy as sp

    from symosc.numeric._lazy import LazyFunction

    x = sp.Symbol("x")
    blob = pickle.dumps(LazyFunction(3 * x, [x]), protocol=2).replace(b"symosc.numeric._lazy", b"symosc._lazy")
    assert b"symosc._lazy" in blob
    sys.modules.pop("symosc._lazy", None)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        back = pickle.loads(blob)
    assert type(back) is LazyFunction and float(back(2.0)) == 6.0
    assert any(issubclass(w.category, DeprecationWarning) for w in caught)
