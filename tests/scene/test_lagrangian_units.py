"""Units of a user Lagrangian's parameters are checked against the dimensions their places in T, V, R and the
forces imply (as the catalogue models' are)."""

from __future__ import annotations

import math

import pytest

from symosc.scene import SceneError, loads

HEAD = (
    '[system]\nmodel = "lagrangian"\ncoordinates = ["x", "phi"]\n'
    'T = "m*x_dot**2/2 + J*phi_dot**2/2"\nV = "k*x**2/2 + m*g*l*(1 - cos(phi))"\nR = "c*x_dot**2/2"\n'
    'forces = ["F*cos(w*t)", "0"]\n'
)
GOOD = {"m": "2 kg", "k": "200 N/m", "J": "0.1 kg*m^2", "g": "9.81 m/s^2", "l": "0.5 m", "c": "3 N*s/m", "F": "1 N",
        "w": "2 rad/s"}  # fmt: skip


def _scene(**changed: str) -> str:
    values = {**GOOD, **changed}
    text = HEAD + "[parameters]\n" + "".join(f'{k} = "{v}"\n' for k, v in values.items())
    return text + '[[questions]]\nkind = "natural_frequencies"\n'


def test_consistent_units_are_accepted_and_converted():
    omega = loads(_scene(J="100000 g*cm^2")).run()["natural_frequencies"].data["omega_rad_s"]
    # independent: x decouples (k/m), phi has m g l / J (J = 0.01 kg m^2 here)
    assert sorted(omega) == pytest.approx(sorted([math.sqrt(200 / 2), math.sqrt(2 * 9.81 * 0.5 / 0.01)]), rel=1e-12)


@pytest.mark.parametrize(
    ("name", "unit", "implied"),
    [
        ("k", "200 N/s", "stiffness"),
        ("c", "3 N/m", "damping"),
        ("J", "0.1 kg", "moment of inertia"),
        ("F", "1 N*m", "force"),  # a force on x (a length, fixed by m and k)
        ("w", "2 m", "angular frequency"),  # the argument of cos must be dimensionless
    ],
)
def test_a_unit_that_contradicts_its_place_names_the_parameter(name, unit, implied):
    with pytest.raises(SceneError) as info:
        loads(_scene(**{name: unit}))
    assert info.value.key == f"parameters.{name}"
    assert implied in str(info.value) and repr(unit) in str(info.value)


def test_two_parameters_that_could_each_be_wrong_are_both_named():
    with pytest.raises(SceneError) as info:
        loads(_scene(l="0.5 kg"))
    assert "contradict each other" in str(info.value) and "l = '0.5 kg'" in str(info.value)


def test_bare_numbers_are_si_and_not_checked():
    assert loads(_scene(k="200", c="3")).values["k"] == 200.0
