"""derivations/bulgakov_linear.py reproduces the worked examples of Bulgakov (1954) ch. 4, 8, 9 A and 10.

Every expected value is computed here independently: numpy eigenvalues and roots, the book's closed forms
evaluated directly, SymPy's solve for the Rayleigh-quotient extremum.
"""

from __future__ import annotations

import importlib.util
from functools import cache
from pathlib import Path

import numpy as np
import sympy as sp

SCRIPT = Path(__file__).resolve().parents[2] / "derivations" / "bulgakov_linear.py"


@cache
def _load():
    spec = importlib.util.spec_from_file_location("bulgakov_linear", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@cache
def _run(out: str):
    return _load().main(["--out", out])


def test_script_runs_and_reproduces(tmp_path_factory):
    out = tmp_path_factory.mktemp("bulgakov_linear")
    res = _run(str(out))
    # figures written to --out
    for name in (
        "vyshnegradsky.png",
        "neimark.png",
        "nyquist_unstable_link.png",
        "t8_power_iteration.png",
        "phase_portraits.png",
        "delay_equal_stability.png",
    ):
        assert (out / name).stat().st_size > 1000
    # §4.10 Raushenbakh integral, the book's closed form evaluated here
    k0, k1, k2 = 1.3, 0.7, 2.1
    delta = np.exp(-np.pi * k1 / np.sqrt(4 * k0 * k2 - k1**2))
    assert abs(res["ch4"]["inv_beta"] - (1 + delta) / (1 - delta) / k2) < 1e-12
    assert abs(res["ch4"]["inv_gamma1"] - (0.8 * k0 + 0.5 * k2) / (2 * k0 * k1 * k2)) < 1e-12
    assert abs(res["ch4"]["alpha_opt_k1"] - 2 * np.sqrt(2)) < 2e-3
    assert abs(res["ch4"]["opt_alpha_k1"] - 2 * np.sqrt(2)) < 1e-12
    assert np.allclose(res["ch4"]["opt_gamma0"], (np.sqrt(2), np.sqrt(2)), atol=1e-12)
    s_star = 2 - np.sqrt(2)  # (4.136) at s*: the book's closed form
    assert np.allclose(
        res["ch4"]["chp_cusp"],
        (np.exp(-s_star) * (2 * s_star - s_star**2), np.exp(-s_star) * s_star**2 * (1 - s_star)),
        atol=1e-14,
    )
    # E1
    assert res["fd_systems"]["E1_operator"] == sp.Symbol("D") + 1
    # E12 Ex. 2 (§8.52): the book's S(D) and e^{3t} v b, v = [1, -1], b = [1, -2]
    Ds, ts = sp.symbols("D t")
    e12 = res["fd_systems"]["E12"]
    assert sp.simplify(e12.direct - sp.Matrix([[0, -1], [-1, Ds + 1]])) == sp.zeros(2, 2)
    assert sp.simplify(e12.kernel - sp.exp(3 * ts) * sp.Matrix([[1, -2], [-1, 2]])) == sp.zeros(2, 2)
    # Vyshnegradsky cusp: λ³ + 3λ² + 3λ + 1 has the triple root -1
    assert res["stability_regions"]["cusp"] == (3, 3)
    # E10 §8.24: the servo optimum is the triple root -2 of λ³ + (8x + 1)λ² + (8y + 1)λ + 8
    d, x, y = res["stability_regions"]["servo"]
    assert np.allclose(np.poly([-d, -d, -d]), [1, 8 * x + 1, 8 * y + 1, 8], atol=1e-12) and d == 2.0
    assert np.allclose(np.poly([-1, -1, -1]), [1, 3, 3, 1])
    # T7: roots of the integer matrix and the product 56
    L7 = np.array([[9, 22, 7], [11, 32, 11], [7, 22, 9]], dtype=float)
    z = np.sort(np.linalg.eigvals(L7).real)[::-1]
    assert np.allclose(res["bounds"]["T7_roots"], z, rtol=1e-12) and abs(np.prod(z) - 56) < 1e-9
    assert abs(z[2] - 0.590600) < 5e-7
    # T8: L_jk = 1 + min(j, k) (1-based), numpy eigenvalues, bounds bracket z1
    L8 = np.fromfunction(lambda j, k: 2 + np.minimum(j, k), (6, 6))
    z8 = np.linalg.eigvalsh(L8)[-1]
    p8 = res["bounds"]["T8_power"]
    assert abs(p8.eigenvalues[0] - z8) < 1e-10
    b8 = res["bounds"]["T8_bounds"]
    assert all(lo < z8 for lo in b8.z_lower[1:]) and all(z8 < hi for hi in b8.z_upper)
    assert abs(b8.z_upper[1] - np.sqrt(519)) < 1e-12
    # T5: extremum of λ(α) = ½(3 - 18α + 35α²)/(7 - 36α + 49α²) from its derivative
    a = sp.Symbol("a")
    lam = sp.Rational(1, 2) * (3 - 18 * a + 35 * a**2) / (7 - 36 * a + 49 * a**2)
    crit = [r for r in sp.solve(sp.diff(lam, a), a) if r.is_real]
    assert abs(res["conservative"]["T5_max"] - max(float(lam.subs(a, r)) for r in crit)) < 1e-8
    # E20: the closed form of the accumulation coefficient
    zeta, w = 0.15, 2.0
    assert abs(res["forced"]["E20"] - 1 / np.tanh(np.pi * zeta / (2 * np.sqrt(1 - zeta**2))) / w**2) < 1e-8
    # E9: generalized eigenvalues of the 2x2 pencil by the quadratic formula
    M = np.array([[2, 0.3], [0.3, 1]])
    K = np.array([[5, -0.8], [-0.8, 3]])
    c2, c1, c0 = np.linalg.det(M), -(M[0, 0] * K[1, 1] + M[1, 1] * K[0, 0] - 2 * M[0, 1] * K[0, 1]), np.linalg.det(K)
    lam2 = np.sort(np.roots([c2, c1, c0]).real)
    assert np.allclose(res["two_dof"]["omega"], np.sqrt(lam2), rtol=1e-12)
    assert np.allclose(res["two_dof"]["omega_8_79"], np.sqrt(lam2), rtol=1e-12)
    assert np.allclose(res["two_dof"]["tuned_limits"], (0.0, 1.0), atol=1e-12)  # equal pendulums: full exchange
    # T12 scaling computed from the printed data
    assert abs(res["regulated"]["T12"][1] - 1.295 * 2.007 / 0.6601) < 1e-12
    assert res["regulated"]["nyquist"].closed_loop_roots == 0
