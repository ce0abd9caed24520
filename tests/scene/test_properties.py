"""Properties of the scene reader: unit conversion and typo suggestions (hypothesis)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.scene import SceneError, loads
from symosc.scene._units import UnitError, parse_quantity

# SI factors written out by hand (independent of the module's table)
LENGTH = {"m": 1.0, "km": 1000.0, "cm": 0.01, "mm": 0.001, "um": 1e-6, "in": 0.0254, "ft": 0.3048}
MASS = {"kg": 1.0, "g": 0.001, "mg": 1e-6, "t": 1000.0}
TIME = {"s": 1.0, "ms": 0.001, "min": 60.0, "h": 3600.0}

values = st.floats(min_value=1e-6, max_value=1e6, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(x=values, lu=st.sampled_from(sorted(LENGTH)), mu=st.sampled_from(sorted(MASS)), tu=st.sampled_from(sorted(TIME)))
def test_compound_units_convert_like_the_hand_table(x, lu, mu, tu):
    """A stiffness written as mass/time^2 and a moment of inertia as mass*length^2."""
    assert parse_quantity(f"{x!r} {mu}/{tu}^2", "stiffness") == pytest.approx(x * MASS[mu] / TIME[tu] ** 2, rel=1e-13)
    assert parse_quantity(f"{x!r} {mu}*{lu}**2", "moment of inertia") == pytest.approx(
        x * MASS[mu] * LENGTH[lu] ** 2, rel=1e-13
    )
    with pytest.raises(UnitError, match="expected a length"):
        parse_quantity(f"{x!r} {mu}", "length")


@settings(max_examples=40, deadline=None)
@given(key=st.sampled_from(["parameters", "questions", "excitation", "system", "source"]), data=st.data())
def test_a_one_letter_typo_in_a_top_level_key_is_named_and_corrected(key, data):
    i = data.draw(st.integers(0, len(key) - 1))
    typo = key[:i] + key[i + 1 :]
    text = f'{typo} = 1\n[system]\nmodel = "mathieu"\n[[questions]]\nkind = "ince_strutt"\n'
    with pytest.raises(SceneError) as info:
        loads(text)
    assert info.value.key == typo and f"Did you mean '{key}'?" in str(info.value)


@settings(max_examples=40, deadline=None)
@given(freq=st.floats(min_value=0.01, max_value=1e4, allow_nan=False))
def test_hz_is_cycles_per_second(freq):
    assert parse_quantity(f"{freq!r} Hz", "angular frequency") == pytest.approx(2 * math.pi * freq, rel=1e-14)
    assert parse_quantity(f"{freq * 60!r} rpm", "angular frequency") == pytest.approx(2 * math.pi * freq, rel=1e-12)
