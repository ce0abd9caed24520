"""Quick instances of public classes whose documented examples are slow or do not build them.

The generic API tests take instances from here first and otherwise from the docstring examples
(:func:`tests.api.public.example_instances`), so a new public class is covered through its own examples.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import sympy as sp


def _averaged():
    from symosc.nonlinear import averaged_equations

    x, v = sp.symbols("x v", real=True)
    return averaged_equations(x + sp.Rational(1, 10) * x**3 + sp.Rational(1, 20) * v, forcing=sp.Rational(1, 10))


def _frequency_response():
    return _averaged().frequency_response({}, (0.8, 1.4), n=60)


def _fold():
    return _frequency_response().folds[0]


def _steady_state():
    return _averaged().steady_states({}, nu=1.0)[0]


def _stationary():
    from symosc.nonlinear import averaged_equations

    x, v = sp.symbols("x v", real=True)
    return averaged_equations(x - sp.Rational(1, 10) * (1 - x**2) * v).stationary()[0]


def _matrix_function():
    from symosc.algebra import matrix_function

    return matrix_function(sp.Matrix([[2, 1], [0, 3]]), sp.exp, spectral=True)


def _matrizant():
    from symosc.algebra import matrizant

    t = sp.Symbol("t")
    return matrizant(sp.Matrix([[0, 1], [-1, 0]]), t, order=3)


def _flywheel():
    from symosc.nonlinear import radinger_flywheel

    s = sp.Symbol("s")
    return radinger_flywheel(sp.sin(s), s, 0.05, 1.0, samples=201)


def _radius():
    from symosc.nonlinear import limit_cycle

    x, v = sp.symbols("x v")
    return limit_cycle((1 - x**2) * v, 14, arithmetic="float").frequency.radius_of_convergence()


def _step_generator():
    from symosc.nonlinear import step_valve_generator

    return step_valve_generator(1, sp.Rational(1, 10), 1)


def _difference():
    from symosc.operational import solve_difference

    T, n = sp.symbols("T n")
    return solve_difference(T**2 - T - 1, 1, None, [[0, 1]], T=T, n=n)


def _table_entry():
    from symosc.operational import CARSON_TABLE

    return CARSON_TABLE[0]


def _numeric_inversion():
    from symosc.operational import invert_numeric

    p = sp.Symbol("p")
    return invert_numeric(p / (p + 1), p, [0.5, 1.0], dps=15)


def _spectral_component():
    from symosc.algebra import spectral_decomposition

    return spectral_decomposition(sp.Matrix([[2, 1], [0, 3]])).components[0]


def _error_map():
    from symosc.identification import error_map

    return error_map([0.0, 0.2], [0.0, 0.1], noise=0.0, runs=1, n_samples=120)  # 2x2: contour plots need it


def _compatibility():
    from symosc.linear import compatibility

    D = sp.Symbol("D")
    f = [[D**2 - 2 * D - 1, D - 1, D**2 - D - 4], [D - 2, 1, D - 2], [-1, -1, D - 4]]
    return compatibility(f, [2 * D, 1, -1], D)


def _cubic_optimum():
    from symosc.linear import max_stability_degree_cubic

    return max_stability_degree_cubic(1.0, k1_max=3.0, k2_max=3.0, k3_max=1.0)


def _modal_analysis():
    from symosc.linear import conservative_modes

    return conservative_modes(sp.Matrix([[2, 0], [0, 1]]), sp.Matrix([[3, -1], [-1, 1]]))


def _routh_array():
    from symosc.linear import routh_array

    return routh_array([1, 1, 2, 8])


def _servo_optimum():
    from symosc.linear import servo_optimum

    return servo_optimum(8.0, k=1.0)


def _stability_degree():
    from symosc.linear import stability_degree

    return stability_degree([1, 6, 11, 6])


def _linear_verdict():
    from symosc.linear import hurwitz

    return hurwitz([1, 3, 3, 1])


def _mechanics_verdict():
    from symosc.mechanics import decompose_forces

    g = sp.Symbol("g", positive=True)
    return decompose_forces(sp.eye(2), sp.Matrix([[0, -g], [g, 0]]), sp.diag(-1, -1)).stability({"g": 3})


def _minimal_form():
    from symosc import dot
    from symosc.mechanics import LagrangianSystem

    x, y = sp.symbols("x y", real=True)
    m, g, l = sp.symbols("m g l", positive=True)
    s = LagrangianSystem(m / 2 * (dot(x) ** 2 + dot(y) ** 2), m * g * y, [x, y], constraints=[x**2 + y**2 - l**2])
    return s.constrained.minimal_form()


def _steady_motion():
    from symosc import dot
    from symosc.mechanics import LagrangianSystem, routh_reduction

    r, phi = sp.symbols("r phi", real=True)
    red = routh_reduction(LagrangianSystem((dot(r) ** 2 + r**2 * dot(phi) ** 2) / 2, -1 / r, [r, phi]), [phi])
    return red.steady_motion({r: 1}, {red.momenta[0]: 1}) if hasattr(red, "momenta") else red.steady_motion({r: 1})


def _equilibrium():
    from symosc.nonlinear import classify_equilibrium

    q = sp.Symbol("q")
    return classify_equilibrium(-sp.cos(q), q, 0)


def _scene_table():
    from symosc.scene import Table

    return Table(("mode", "f, Hz"), (("1", "2.3276"),))


def _scene_figure():
    from symosc.scene import Figure

    return Figure("ince.png", "Ince–Strutt diagram", "ince_strutt", {"orders": 2, "q_max": 5.0})


def _scene():
    from symosc.scene import loads

    return loads('[system]\nmodel = "mathieu"\n[[questions]]\nkind = "mathieu_values"\nn = 0\nq = 0\n')


def arctan_spring(q, v):
    """Module-level force ``f(q, v) = arctan(q)`` (Bulgakov (1954), §5.29): picklable, unlike a lambda."""
    return np.arctan(q)


def _design_linearization():
    from symosc.nonlinear import design_amplitude_linearization

    return design_amplitude_linearization(arctan_spring, 2.0)


def _implicit_map_cycle():
    import sympy as sp

    from symosc.nonlinear import implicit_map_cycle

    a, b = sp.symbols("a b")
    return implicit_map_cycle(a**2 / 2 - b**2 / 2 - sp.Rational(1, 10) * (a + b) + sp.Rational(1, 5), (a, b), 1.0)


def _operator_cycle():
    import sympy as sp

    from symosc.nonlinear import poincare_operator_system

    D, y, v = sp.symbols("D y v")
    system = poincare_operator_system(sp.Matrix([[D**2 + 1]]), [(1 - y**2) * v], [y], [v], D)
    return system.cycles(5.0)


def _one_ports():
    import sympy as sp

    from symosc.networks import BruneSection, Capacitor, Impedance, Inductor, Resistor

    R = Resistor(1)
    return (R, Inductor(2), Capacitor(3), Impedance(sp.Symbol("Z_A")), BruneSection(1, 4, 2, 1, load=R), R + R, R | R)


FACTORIES: dict[str, Callable[[], Any]] = {
    "DesignLinearization": _design_linearization,
    "ImplicitMapCycle": _implicit_map_cycle,
    "OperatorCycle": _operator_cycle,
    "Compatibility": _compatibility,
    "CubicOptimum": _cubic_optimum,
    "Equilibrium": _equilibrium,
    "Figure": _scene_figure,
    "MinimalForm": _minimal_form,
    "ModalAnalysis": _modal_analysis,
    "RouthArray": _routh_array,
    "Scene": _scene,
    "ServoOptimum": _servo_optimum,
    "StabilityDegree": _stability_degree,
    "StabilityVerdict": lambda: (_linear_verdict(), _mechanics_verdict()),  # symosc.linear and symosc.mechanics
    "SteadyMotion": _steady_motion,
    "Table": _scene_table,
    "DifferenceSolution": _difference,
    "ErrorMap": _error_map,
    "FlywheelDesign": _flywheel,
    "Fold": _fold,
    "FrequencyResponse": _frequency_response,
    "MatrixFunction": _matrix_function,
    "Matrizant": _matrizant,
    "NumericInversion": _numeric_inversion,
    "RadiusEstimate": _radius,
    "StationaryRegime": _stationary,
    "SteadyState": _steady_state,
    "SpectralComponent": _spectral_component,
    "StepGenerator": _step_generator,
    "TableEntry": _table_entry,
    "OnePort": _one_ports,  # symosc.networks: every element kind (other examples may find a OnePort first)
}

__all__ = ["FACTORIES", "np"]


# Arguments a plot method needs besides ``ax`` (keyed by class name); and smaller sampling where the default
# drawing is long and the same code draws fewer points (DPartition: root counts on an 8 x 8 grid instead of 60 x 60,
# 401 boundary samples instead of 4001; tests/linear/test_dpartition.py checks the drawing itself).
PLOT_ARGS: dict[str, dict[str, Any]] = {
    "LimitCycleSeries": {"eps": 0.3, "numeric": False},
    "DPartition": {"grid": 8, "n_omega": 401, "hatch_every": 40},
}
