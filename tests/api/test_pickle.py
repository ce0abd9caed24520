"""Every public result pickles: a round trip gives an equal object (for process pools, caches and files)."""

from __future__ import annotations

import pickle

import pytest
import sympy as sp

from .public import public_classes

CLASSES = public_classes()


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_pickle_round_trip(cls, examples):
    obj = examples.get(cls)
    assert obj is not None, f"no documented example builds a {cls.__name__}"
    back = pickle.loads(pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL))
    assert type(back) is type(obj)
    if " at 0x" not in repr(obj):  # a readable repr shows the defining data
        assert repr(back) == repr(obj)
    assert sp.latex(back) == sp.latex(obj)


@pytest.mark.parametrize("method", ["modified-ince-strutt", "otterbein", "chelomei"])
def test_stability_region_round_trip_classifies_the_same(method):
    """The boundary functions are rebuilt after loading: the region answers exactly as before."""
    import numpy as np

    from symosc.models import n_link_pendulum
    from symosc.periodic import stability_region

    system = n_link_pendulum(2, inverted=True, pivot="vertical")
    region = stability_region(system, {"m1": 1.0, "l1": 1.0, "m2": 1.0, "l2": 1.0, "g": 9.81}, method=method)
    back = pickle.loads(pickle.dumps(region))
    q = np.linspace(0.05, 3.0, 25)
    np.testing.assert_array_equal(back.lower(q), region.lower(q))
    p = np.linspace(20.0, 400.0, 9)
    a = np.full_like(p, 0.05)
    np.testing.assert_array_equal(back.is_stable(p=p, a=a), region.is_stable(p=p, a=a))


def test_lazy_function_in_results_survives_pickling():
    """HalfSwingMap holds numeric functions of its expressions; after loading it maps amplitudes the same."""
    from symosc.nonlinear import half_swing_map

    x = sp.Symbol("x")
    hs = half_swing_map(x**2 / 2 + x**4 / 40, x, friction=sp.Rational(1, 20))
    back = pickle.loads(pickle.dumps(hs))
    assert back(1.3) == hs(1.3) and hs(1.3) is not None
