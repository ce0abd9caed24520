"""Scenes: the Gribkov & Khokhlov examples against independent computations; units; the derivation log."""

from __future__ import annotations

import json
import pickle
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg
from scipy.integrate import solve_ivp

from symosc.scene import SceneError, load, loads
from symosc.scene._builtin import TABLE1_SCENE
from symosc.scene._units import parse_quantity

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

# Table 1 of Gribkov & Khokhlov (2015), converted by hand to SI
T1 = dict(m1=1.032e-3, m2=0.424e-3, l1=45.0e-3, lc1=24.917e-3, lc2=12.838e-3, I1=146.804e-9, I2=32.871e-9, g=9.81)


def _textbook_double_pendulum(v):
    """M, C of the double physical pendulum written out by hand: M q'' + g C q = 0 (hanging), C diagonal."""
    M = np.array(
        [
            [v["I1"] + v["m1"] * v["lc1"] ** 2 + v["m2"] * v["l1"] ** 2, v["m2"] * v["l1"] * v["lc2"]],
            [v["m2"] * v["l1"] * v["lc2"], v["I2"] + v["m2"] * v["lc2"] ** 2],
        ]
    )
    C = np.diag([v["m1"] * v["lc1"] + v["m2"] * v["l1"], v["m2"] * v["lc2"]])
    return M, C


def test_double_pendulum_frequencies_against_the_textbook_model():
    scene = load(EXAMPLES / "double_pendulum_frequencies.toml")
    for k, v in T1.items():  # the units in the file were converted to SI
        assert scene.values[k] == pytest.approx(v, rel=1e-12)
    res = scene.run()
    M, C = _textbook_double_pendulum(T1)
    lam, vec = scipy.linalg.eigh(T1["g"] * C, M)
    data = res["natural_frequencies"].data
    np.testing.assert_allclose(data["omega_rad_s"], np.sqrt(lam), rtol=1e-10)
    np.testing.assert_allclose(data["frequency_hz"], [2.3276, 5.0460], atol=5e-5)
    Phi = np.array(data["modes"])
    np.testing.assert_allclose(Phi.T @ M @ Phi, np.eye(2), atol=1e-9)  # mass-normalised
    np.testing.assert_allclose(np.abs(Phi), np.abs(vec), rtol=1e-8)
    # the comparison with the paper is in the report, with its reason in one line
    text = res.report()
    assert "2.289" in text and "+1.686%" in text and "lc2 = 15.16 mm" in text


def test_the_paper_values_follow_from_lc2_15_16mm():
    """The report's explanation, checked: with lc2 = 15.16 mm the textbook model gives the printed 2.289/5.094 Hz."""
    M, C = _textbook_double_pendulum({**T1, "lc2": 15.16e-3})
    f = np.sqrt(scipy.linalg.eigh(T1["g"] * C, M, eigvals_only=True)) / (2 * np.pi)
    np.testing.assert_allclose(f, [2.289, 5.094], atol=1.5e-3)


def test_frequency_question_derives_no_nonlinear_equations():
    scene = load(EXAMPLES / "double_pendulum_frequencies.toml")
    res = scene.run()
    steps = [e.step for e in res.log]
    assert steps == [
        "build the Lagrangian system",
        "linearize at q = 0",
        "evaluate M, K0 and solve K0 phi = omega^2 M phi",
    ]
    assert "forcing" not in scene.model.system.__dict__  # the cached nonlinear right-hand side was never formed
    assert all(e.seconds >= 0 for e in res.log)
    assert "Derivation log" in res.report() and "linearize at q = 0" in res.markdown()


def test_equations_question_is_logged_and_matches_the_textbook_mass_matrix():
    text = TABLE1_SCENE.split("[[questions]]")[0] + '[[questions]]\nkind = "equations_of_motion"\n'
    scene = loads(text)
    res = scene.run()
    assert [e.step for e in res.log] == ["build the Lagrangian system", "derive the nonlinear equations of motion"]
    import sympy as sp

    M, _ = scene.model.equations
    at_rest = {s: 0 for s in scene.model.system.coordinates}
    num = {sp.Symbol(k, positive=True): v for k, v in T1.items()}
    np.testing.assert_allclose(
        np.array(M.subs(at_rest).subs(num), dtype=float), _textbook_double_pendulum(T1)[0], rtol=1e-12
    )
    assert res["equations_of_motion"]._repr_latex_().startswith("$$\\left[")
    assert res["equations_of_motion"]._repr_latex_().count("=") == 1


def test_builtin_table1_scene_is_the_example_file():
    assert TABLE1_SCENE == (EXAMPLES / "double_pendulum_frequencies.toml").read_text()


def _floquet_radius(v, a, p):
    """Largest |multiplier| of the inverted pendulum M q'' + (-g + a p^2 cos pt) C q = 0 over one period (SciPy)."""
    M, C = _textbook_double_pendulum(v)
    Minv_C = np.linalg.solve(M, C)

    def rhs(t, y):
        Y = y.reshape(4, 4)
        q, qd = Y[:2], Y[2:]
        return np.vstack([qd, -(-v["g"] + a * p**2 * np.cos(p * t)) * Minv_C @ q]).ravel()

    sol = solve_ivp(rhs, (0, 2 * np.pi / p), np.eye(4).ravel(), rtol=1e-11, atol=1e-13, method="DOP853")
    return np.max(np.abs(np.linalg.eigvals(sol.y[:, -1].reshape(4, 4))))


def test_gribkov2015_stability_interval_against_floquet(tmp_path):
    scene = load(EXAMPLES / "gribkov2015.toml")
    assert scene.excitation["frequency"] == pytest.approx(200 * np.pi)  # "100 Hz" -> rad/s
    res = scene.run()
    d = res["stability_region"].data
    p, amin, amax = d["frequency_rad_s"], d["amplitude_min"], d["amplitude_max"]
    assert d["stable"] is True and amin < d["amplitude"] < amax
    # independent check of both ends of the interval by Floquet multipliers of the hand-written linear model
    assert _floquet_radius(T1, amin * 1.03, p) < 1 + 1e-6
    assert _floquet_radius(T1, amin * 0.97, p) > 1 + 1e-4
    assert _floquet_radius(T1, amax * 0.98, p) < 1 + 1e-6
    assert _floquet_radius(T1, amax * 1.03, p) > 1 + 1e-4
    steps = [e.step for e in res.log]
    assert "derive the nonlinear equations of motion" not in steps and "split K(t) = K0 + K1 cos(p t)" in steps
    paths = res.write(tmp_path / "out", "md")
    names = sorted(x.name for x in paths)
    motion = [f"gribkov2015-motion-{i}.{ext}" for i in (3, 4) for ext in ("gif", "png")]  # the two time responses
    assert names == ["gribkov2015-ince-strutt.png", *motion, "report.md", "results.json", "timings.json"]
    assert (tmp_path / "out" / "gribkov2015-ince-strutt.png").read_bytes()[:4] == b"\x89PNG"
    js = json.loads((tmp_path / "out" / "results.json").read_text())
    assert js["questions"][1]["amplitude_min"] == pytest.approx(amin)
    assert "![" in (tmp_path / "out" / "report.md").read_text()
    pickle.loads(pickle.dumps(res))


@pytest.mark.parametrize(
    ("text", "dimension", "si"),
    [
        ("45 mm", "length", 0.045),
        ("1.032 g", "mass", 1.032e-3),
        ("146.804 g*mm^2", "moment of inertia", 146.804e-9),
        ("2 kg*m**2", "moment of inertia", 2.0),
        ("100 Hz", "angular frequency", 200 * np.pi),
        ("60 rpm", "angular frequency", 2 * np.pi),
        ("3 rad/s", "angular frequency", 3.0),
        ("1 g0", "acceleration", 9.80665),
        ("9.81 m/s^2", "acceleration", 9.81),
        ("2 N/mm", "stiffness", 2000.0),
        ("5 N*s/m", "damping", 5.0),
        ("90 deg", "dimensionless", np.pi / 2),
        (7, "length", 7.0),
    ],
)
def test_units_convert_to_si(text, dimension, si):
    assert parse_quantity(text, dimension) == pytest.approx(si, rel=1e-14)


def test_lagrangian_scene_with_units():
    """A mass on a spring written as T, V: omega = sqrt(k/m) = 5 rad/s; the sweep follows sqrt(k/m)."""
    scene = loads(
        """
[system]
model = "lagrangian"
coordinates = ["x"]
T = "m*x_dot**2/2"
V = "k*x**2/2"
[parameters]
m = "2000 g"
k = "50 N/m"
[[questions]]
kind = "natural_frequencies"
[[questions]]
kind = "sweep"
parameter = "k"
values = ["8 N/m", "18 N/m", "32 N/m"]
"""
    )
    res = scene.run()
    assert res["natural_frequencies"].data["omega_rad_s"] == pytest.approx([5.0], rel=1e-12)
    np.testing.assert_allclose(np.array(res["sweep"].data["frequency_hz"])[:, 0] * 2 * np.pi, [2, 3, 4], rtol=1e-12)


def test_overrides_are_validated_like_the_file():
    with pytest.raises(SceneError, match=r"parameters\.m1"):
        loads(TABLE1_SCENE, overrides={"m1": "3 mm"})


def test_lagrangian_with_dissipation_and_forces():
    """Damped, forced oscillator from T, V, R, Q: D = c, K = k, f = F0 cos(w t) (read off the energies by hand)."""
    scene = loads(
        """
[system]
model = "lagrangian"
coordinates = ["x"]
T = "m*x_dot**2/2"
V = "k*x**2/2"
R = "c*x_dot**2/2"
forces = ["F0*cos(w*t)"]
[parameters]
m = 2.0
k = 50.0
c = 0.3
F0 = 1.0
w = 3.0
[[questions]]
kind = "linear_matrices"
"""
    )
    res = scene.run()
    num = res["linear_matrices"].data["numeric"]
    np.testing.assert_allclose([num["M"][0][0], num["D"][0][0], num["K0"][0][0]], [2.0, 0.3, 50.0], rtol=1e-14)
    import sympy as sp

    f = scene.model.linear.f[0]
    t = sp.Symbol("t")
    F0, w = sp.Symbol("F0", positive=True), sp.Symbol("w", positive=True)
    assert sp.simplify(f - F0 * sp.cos(w * t)) == 0


def test_figures_without_matplotlib_say_so(tmp_path, monkeypatch, capsys):
    import sys

    res = load(EXAMPLES / "gribkov2015.toml").run()
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib now raises ImportError
    paths = res.write(tmp_path, "md")
    assert sorted(p.name for p in paths) == ["report.md", "results.json", "timings.json"]
    msg = "figures skipped: matplotlib is not installed (pip install 'symosc[plot]')"
    report = (tmp_path / "report.md").read_text()
    assert msg in capsys.readouterr().out and msg in report
    assert ".png" not in report and ".png" not in res.report()  # no figure is named that was not written


def test_sign_rules_of_parameters():
    """Pendulum masses and lengths are positive; a product of inertia or a centre-of-mass offset may be negative."""
    body = (EXAMPLES / "belyakov_stand.toml").read_text()
    scene = loads(body, overrides={"Ixz": "-400 kg*m^2", "rx": -0.5})
    assert scene.values["Ixz"] == -400.0 and scene.values["rx"] == -0.5
    with pytest.raises(SceneError, match=r"parameters\.m1.*positive"):
        loads(TABLE1_SCENE, overrides={"m1": 0})
    lagr = '[system]\nmodel = "lagrangian"\ncoordinates = ["x"]\nT = "m*x_dot**2/2"\nV = "k*x**2/2"\n'
    lagr += '[parameters]\nm = 1\nk = -4\n[[questions]]\nkind = "natural_frequencies"\n'
    with pytest.raises(SceneError, match=r"parameters\.k.*positive"):
        loads(lagr)
