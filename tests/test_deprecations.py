"""Old names stay usable for one release: each warns once (DeprecationWarning) and gives the new object/result."""

from __future__ import annotations

import importlib
import warnings

import numpy as np
import pytest
import sympy as sp

from symosc import _deprecation
from symosc.errors import ParameterError


@pytest.fixture(autouse=True)
def _fresh_registry():
    _deprecation.reset_warnings()
    yield
    _deprecation.reset_warnings()


@pytest.mark.parametrize(
    ("module", "old", "new"),
    [
        ("symosc.nonlinear", "harmonic_linearisation", "harmonic_linearization"),
        ("symosc.nonlinear", "HarmonicLinearisation", "HarmonicLinearization"),
        ("symosc.nonlinear", "LinearisationBoundary", "LinearizationBoundary"),
        ("symosc.nonlinear", "linearisation_boundary", "linearization_boundary"),
        ("symosc.nonlinear.harmonic_linearisation", "harmonic_linearisation", "harmonic_linearization"),
        ("symosc.identification", "algorithm1", "inertia_from_release"),
        ("symosc.identification", "algorithm21", "inertia_equal_springs"),
        ("symosc.identification", "algorithm22", "inertia_known_center"),
    ],
)
def test_renamed_module_attributes(module, old, new):
    mod = importlib.import_module(module)
    with pytest.warns(DeprecationWarning, match=new):
        obj = getattr(mod, old)
    assert obj is getattr(mod, new)
    assert old not in mod.__all__ if hasattr(mod, "__all__") else True


def test_warns_once_per_name():
    import symosc.nonlinear as nl

    with pytest.warns(DeprecationWarning):
        nl.harmonic_linearisation  # noqa: B018
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert nl.harmonic_linearisation is nl.harmonic_linearization


def test_unknown_attribute_still_raises():
    import symosc.nonlinear as nl

    with pytest.raises(AttributeError, match="no_such_name"):
        nl.no_such_name  # noqa: B018


def test_old_module_path_imports():
    with pytest.warns(DeprecationWarning):
        from symosc.nonlinear.harmonic_linearisation import HarmonicLinearisation
    from symosc.nonlinear.harmonic_linearization import HarmonicLinearization

    assert HarmonicLinearisation is HarmonicLinearization


def _two_mode_record():
    t = np.arange(400) * 0.02
    return np.vstack([np.exp(-0.1 * t) * np.cos(9 * t) + 0.5 * np.exp(-0.2 * t) * np.cos(23 * t) + 0.1] * 2)


@pytest.mark.parametrize(
    ("name", "old", "new"),
    [("era", "rows", "hankel_size"), ("matrix_pencil", "pencil", "hankel_size"), ("esprit", "pencil", "hankel_size")],
)
def test_hankel_size_keyword(name, old, new):
    from symosc import identification

    fn = getattr(identification, name)
    y = _two_mode_record()
    ref = fn(y, 0.02, 2, **{new: 40})
    with pytest.warns(DeprecationWarning, match=new):
        est = fn(y, 0.02, 2, **{old: 40})
    np.testing.assert_array_equal(est.poles, ref.poles)
    assert est.details["hankel_size"] == 40
    with pytest.raises(ParameterError, match=f"{new}= only"):
        fn(y, 0.02, 2, **{old: 40, new: 40})


def test_n_poles_keyword_and_attribute():
    from symosc.identification import prony

    y = _two_mode_record()
    with pytest.warns(DeprecationWarning, match="n_poles"):
        est = prony(y, 0.02, order=5)
    assert est.n_poles == 5 and est.n_modes == 2
    with pytest.warns(DeprecationWarning, match="ModalEstimate.n_poles"):
        assert est.order == 5


def test_inertia_as_dict_keys_are_attribute_names():
    from symosc.identification import inertia_from_release

    modes = np.array(
        [[-0.0006753510, 0.0006737952, -0.0006730062], [-0.0006753488, -0.0007192560, -0.0006304674],
         [-0.0006753497, -0.0006737934, 0.0006730067], [-0.0006753526, 0.0007192575, 0.0006304678]]
    )  # fmt: skip
    est = inertia_from_release([14.04726, 16.39794, 27.35160], modes, [0, -2000, 0, 0], (4, 1.74))
    d = est.as_dict()
    assert set(d) == {"mass", "rx", "rz", "Izz", "Ixx", "Ixz"}
    assert all(d[k] == getattr(est, k) for k in d)


def test_center_spelling():
    from symosc.models import body_on_springs
    from symosc.nonlinear import averaged_equations

    x = sp.Symbol("x")
    k = sp.Symbol("k", positive=True)
    eqs = averaged_equations(k**2 * (sp.exp(x) - 1), center=True)
    with pytest.warns(DeprecationWarning, match="AveragedEquations.center"):
        assert eqs.centre == eqs.center
    model = body_on_springs(product_of_inertia="dissertation")
    with pytest.warns(DeprecationWarning, match="vertical_stiffness_center"):
        assert model.vertical_stiffness_centre() == model.vertical_stiffness_center()


def test_eps_symbol_keyword_and_attribute():
    from symosc.nonlinear import limit_cycle, lindstedt

    x, v, mu = sp.symbols("x v mu")
    with pytest.warns(DeprecationWarning, match="eps_symbol"):
        lc = limit_cycle((1 - x**2) * v, 2, x=x, v=v, eps=mu)
    assert lc.eps_symbol == mu
    assert lc.frequency.expr == 1 - mu**2 / 16  # van der Pol, omega = 1 - eps^2/16 + O(eps^4)
    with pytest.warns(DeprecationWarning, match="LimitCycleSeries.eps_symbol"):
        assert lc.eps == mu
    ls = lindstedt(-(x**3), 1, x=x, eps_symbol=mu)
    assert ls.eps_symbol == mu and mu in ls.frequency.expr.free_symbols


def test_series_and_derivative_orders():
    from symosc.operational import differentiate_parameter
    from symosc.periodic import ince_strutt_diagram

    s, p = sp.symbols("s p")
    with pytest.warns(DeprecationWarning, match=r"differentiate_parameter\(n="):
        assert differentiate_parameter(p / (p - s), s, order=2) == sp.diff(p / (p - s), s, 2)
    with pytest.warns(DeprecationWarning, match="n_max"):
        d = ince_strutt_diagram(orders=2, q_max=1.0, num=3)
    assert sorted(d.a_curves) == [0, 1, 2]
    with pytest.warns(DeprecationWarning, match="InceStruttDiagram.n_max"):
        assert d.orders == d.n_max == 2


def test_dir_lists_installed_subpackages_only():
    import symosc

    names = dir(symosc)
    for sub in ("algebra", "identification", "mechanics", "models", "nonlinear", "operational", "periodic"):
        assert sub in names
        assert importlib.import_module(f"symosc.{sub}") is getattr(symosc, sub)
    assert "plotting" not in names
    with pytest.raises(AttributeError):
        symosc.plotting  # noqa: B018
    for sub in ("linear", "networks", "scene", "codegen"):
        assert (sub in names) == (sub in symosc._installed_subpackages())
    assert set(symosc._installed_subpackages()) >= {"algebra", "mechanics", "nonlinear", "periodic"}
