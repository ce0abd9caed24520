"""Body on springs: symbolic 6-DOF/3-DOF model and forward modal solver (Belyakov 2005, seed 001, Ch. I §3)."""

import numpy as np
import pytest
import scipy.linalg
import sympy as sp

from symosc.errors import ModelError, ParameterError
from symosc.models import body_on_springs

TABLE12 = dict(
    m=15000, rx=2, rz=0.87, Izz=44000, Ixx=3000, Ixz=400, Lx=4, Lz=1.74, k1=7.4e5, k2=7.4e5, k3=7.4e5, k4=7.4e5
)
F2 = [0, -2000, 0, 0]


def test_k6_symmetric_and_eq18():
    """K6 = C^T G C is symmetric and sum R_i G_i = -(sum G_i R_i)^T (eq. 18; report §2.3, feature 1)."""
    model = body_on_springs()
    assert (model.K6 - model.K6.T).applyfunc(sp.expand) == sp.zeros(6, 6)
    lhs = sum((model.R(j) * model.G(j) for j in range(1, 5)), sp.zeros(3, 3))
    rhs = -sum((model.G(j) * model.R(j) for j in range(1, 5)), sp.zeros(3, 3)).T
    assert (lhs - rhs).applyfunc(sp.expand) == sp.zeros(3, 3)
    # the off-diagonal block of K6 is -sum G_i R_i (eq. 17)
    assert (model.K6[:3, 3:] + sum((model.G(j) * model.R(j) for j in range(1, 5)), sp.zeros(3, 3))).applyfunc(
        sp.expand
    ) == sp.zeros(3, 3)


def test_equal_springs_centered_block():
    """Equal springs, CM at the rectangle center: (y, theta_z, theta_x) block of K6 = k diag(4, Lx^2, Lz^2) (§2.4)."""
    model = body_on_springs()
    k, c = sp.symbols("k c", positive=True)
    sub = {**{s: k for s in model.k}, **{s: c for s in model.c}, model.rx: model.Lx / 2, model.rz: model.Lz / 2}
    sub[model.ry] = 0
    block = model.K6.extract([1, 5, 3], [1, 5, 3]).subs(sub).applyfunc(sp.expand)
    assert block == sp.diag(4 * k, k * model.Lx**2, k * model.Lz**2)


def test_c_matches_eq23_and_ry_drops_out():
    """Vertical rows of C6, columns (y, theta_z, theta_x), reproduce eq. (23); ry does not appear (feature 2)."""
    model = body_on_springs()
    Lx, Lz, rx, rz = model.Lx, model.Lz, model.rx, model.rz
    eq23 = sp.Matrix([[1, -rx, rz], [1, Lx - rx, rz], [1, Lx - rx, -Lz + rz], [1, -rx, -Lz + rz]])
    assert model.C == eq23
    assert model.ry not in model.C.free_symbols
    # rows are (1, x_j - rx, -(z_j - rz)) also for a general layout
    gen = body_on_springs(5)
    for j, (x, z) in enumerate(gen.positions):
        assert list(gen.C.row(j)) == [1, x - gen.rx, -(z - gen.rz)]


def test_reduced_stiffness_is_selection_of_k6_when_ry_zero():
    """K = C^T diag(k) C (eq. 25) equals the (y, theta_z, theta_x) block of K6 when the CM is at spring level."""
    model = body_on_springs()
    block = model.K6.extract([1, 5, 3], [1, 5, 3]).subs(model.ry, 0).applyfunc(sp.expand)
    assert (block - model.K).applyfunc(sp.expand) == sp.zeros(3, 3)


def test_stiffness_center():
    """Center of stiffness: sum R G = 0 at (Lx/2, 0, Lz/2) for equal springs; none for unequal c/k ratios."""
    model = body_on_springs()
    eq = {"k1": 3, "k2": 3, "k3": 3, "k4": 3, "c1": 1, "c2": 1, "c3": 1, "c4": 1}
    center = model.stiffness_center(eq)
    assert center == {model.rx: model.Lx / 2, model.ry: 0, model.rz: model.Lz / 2}
    coupling = model.coupling().subs({sp.Symbol(k, positive=True): v for k, v in eq.items()}).subs(center)
    assert coupling.applyfunc(sp.simplify) == sp.zeros(3, 3)
    with pytest.raises(ModelError, match="no center of stiffness"):
        model.stiffness_center({"k1": 1, "k2": 2, "k3": 3, "k4": 4, "c1": 1, "c2": 1, "c3": 1, "c4": 1})
    # vertical center of stiffness decouples the 3-DOF stiffness for unequal springs
    xs, zs = model.vertical_stiffness_center()
    K = model.K.subs({model.rx: xs, model.rz: zs}).applyfunc(sp.simplify)
    assert K[0, 1] == 0 and K[0, 2] == 0


def test_table12_frequencies_and_modes():
    """Table 1–2 body, M23 = +400 (report §4.2/§4.3, feature 3): linear-model frequencies and C'.

    The linear 3-DOF values were recomputed in the research report ([C]); they lie within 0.01 % of Table 3
    (the dissertation's nonlinear simulation).  C' agrees with the dissertation's identified C' to 0.2 %.
    """
    model = body_on_springs(product_of_inertia="dissertation")
    data = model.modal(TABLE12, force=F2)
    np.testing.assert_allclose(data.omega, [14.0475383, 16.3983994, 27.3536888], rtol=3e-9)
    np.testing.assert_allclose(data.omega, [14.04726, 16.39794, 27.35160], rtol=1e-4)
    report_c = np.array(
        [
            [-6.756757e-4, 6.742379e-4, -6.742379e-4],
            [-6.756757e-4, -7.197311e-4, -6.316203e-4],
            [-6.756757e-4, -6.742379e-4, 6.742379e-4],
            [-6.756757e-4, 7.197311e-4, 6.316203e-4],
        ]
    )
    np.testing.assert_allclose(data.observation, report_c, rtol=2e-6)
    thesis_c = np.array(
        [
            [-0.0006753510, 0.0006737952, -0.0006730062],
            [-0.0006753488, -0.0007192560, -0.0006304674],
            [-0.0006753497, -0.0006737934, 0.0006730067],
            [-0.0006753526, 0.0007192575, 0.0006304678],
        ]
    )
    np.testing.assert_allclose(data.observation, thesis_c, rtol=2e-3)
    assert data.y0[1] == pytest.approx(-2.027e-3, abs=1e-6)
    # p/(4k) is the vertical-mode amplitude; row sums give the initial deflections
    np.testing.assert_allclose(data.observation[:, 0], -2000 / (4 * 7.4e5), rtol=1e-12)
    np.testing.assert_allclose(data.observation.sum(axis=1), data.y0, rtol=1e-12)
    # modal energies: total 1/2 p |y2| (report §3.9)
    assert data.modal_energy().sum() == pytest.approx(0.5 * 2000 * 2.027027027e-3, rel=1e-8)


def test_sign_convention_swaps_modes():
    """§2.7: with M23 = -400 the entries 0.000719 and 0.000630 of rows 2 and 4 of C' swap places."""
    plus = body_on_springs(product_of_inertia="dissertation").modal(TABLE12, force=F2).observation
    minus = body_on_springs(product_of_inertia="tensor").modal(TABLE12, force=F2).observation
    assert abs(plus[1, 1]) == pytest.approx(7.197311e-4, rel=1e-6)
    assert abs(minus[1, 2]) == pytest.approx(7.197311e-4, rel=1e-6)
    # the two conventions describe the same body when the sign of Ixz is flipped
    flipped = body_on_springs(product_of_inertia="tensor").modal({**TABLE12, "Ixz": -400}, force=F2).observation
    np.testing.assert_allclose(flipped, plus, rtol=1e-12)
    with pytest.raises(ParameterError, match="product_of_inertia"):
        body_on_springs(product_of_inertia="maple")


@pytest.mark.parametrize(
    ("ks", "omega"),
    [
        ((7e5, 7.6e5, 7.3e5, 7.8e5), (13.5567403, 16.9455561, 27.5448558)),  # report §4.9 case B
        ((7.4e5,) * 4, (13.5164510, 16.9761145, 27.4610171)),  # case C
    ],
)
def test_offset_cases(ks, omega):
    """Report §4.9 cases B and C (CM at (2.3, 0.8), M23 = +400)."""
    vals = {**TABLE12, "rx": 2.3, "rz": 0.8, **{f"k{i + 1}": k for i, k in enumerate(ks)}}
    data = body_on_springs(product_of_inertia="dissertation").modal(vals, force=F2)
    np.testing.assert_allclose(data.omega, omega, rtol=1e-8)


def test_uncoupled_formulas_eq86():
    """Equal springs, centered CM, no product: omega = 2 sqrt(k/m), Lx sqrt(k/Izz), Lz sqrt(k/Ixx) (eq. 86)."""
    vals = {**TABLE12, "Ixz": 0.0}
    data = body_on_springs().modal(vals)
    k = 7.4e5
    expected = sorted([2 * np.sqrt(k / 15000), 4 * np.sqrt(k / 44000), 1.74 * np.sqrt(k / 3000)])
    np.testing.assert_allclose(data.omega, expected, rtol=1e-12)
    # report's rounded values of (86)
    np.testing.assert_allclose(expected, [14.04754, 16.40399, 27.32779], rtol=1e-6)


def test_modal_data_consistency():
    """Eq. (34): C'^T f = K' q0' with q0' = 1, modal mass normalisation and the free response at t = 0."""
    model = body_on_springs(7, product_of_inertia="tensor")
    rng = np.random.default_rng(3)
    vals = dict(m=900.0, rx=0.4, rz=0.3, Izz=300.0, Ixx=120.0, Ixz=15.0)
    vals.update({f"k{j}": rng.uniform(1e5, 3e5) for j in range(1, 8)})
    vals.update({f"x{j}": x for j, x in enumerate(rng.uniform(-1, 1.5, 7), 1)})
    vals.update({f"z{j}": z for j, z in enumerate(rng.uniform(-0.5, 1, 7), 1)})
    f = rng.normal(size=7) * 100
    data = model.modal(vals, force=f)
    np.testing.assert_allclose(data.observation.T @ f, data.modal_stiffness, rtol=1e-10)
    np.testing.assert_allclose(data.modal_stiffness / data.modal_mass, data.omega**2, rtol=1e-12)
    np.testing.assert_allclose(data.response([0.0])[0], data.y0, rtol=1e-10, atol=1e-15)
    # independent: frequencies from det(K - w^2 M) = 0 via scipy.linalg.eigvals of M^-1 K
    lam = np.sort(scipy.linalg.eigvals(np.linalg.solve(data.M, data.K)).real)
    np.testing.assert_allclose(data.omega, np.sqrt(lam), rtol=1e-10)


def test_six_dof_contains_three_dof_frequencies():
    """With ry = 0 and no Ixy, Iyz the 6-DOF model decouples: its spectrum contains the 3-DOF frequencies."""
    model = body_on_springs(product_of_inertia="dissertation")
    vals = {**TABLE12, "ry": 0.0, "Iyy": 43000, "Ixy": 0.0, "Iyz": 0.0, **{f"c{i}": 3.1e5 for i in range(1, 5)}}
    M6, K6, C6 = model.matrices6(vals)
    w6 = np.sqrt(scipy.linalg.eigh(K6, M6, eigvals_only=True))
    w3 = model.modal(TABLE12).omega
    for w in w3:
        assert np.min(np.abs(w6 - w)) < 1e-9 * w
    assert C6.shape == (12, 6)


def test_bad_input():
    """Clear errors for impossible models and missing numbers."""
    with pytest.raises(ParameterError, match="n_springs"):
        body_on_springs(2)
    with pytest.raises(ParameterError, match="rectangle"):
        body_on_springs(5, layout="rectangle")
    model = body_on_springs()
    with pytest.raises(ParameterError, match="missing values for: Lz"):
        model.modal({k: v for k, v in TABLE12.items() if k != "Lz"})
    with pytest.raises(ParameterError, match="one per spring"):
        model.modal(TABLE12, force=[1.0, 2.0])
    with pytest.raises(ModelError, match="not positive definite"):
        model.modal({**TABLE12, "Ixz": 1e6})
    with pytest.raises(ParameterError, match="positive"):
        model.modal({**TABLE12, "m": -1.0})


def test_latex_and_plot():
    """Notebook display and the mode-shape picture."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    model = body_on_springs(product_of_inertia="dissertation")
    assert r"\ddot{q}" in model._repr_latex_()
    fig, ax = plt.subplots()
    model.modal(TABLE12, force=F2).plot(ax=ax)
    assert len(ax.patches) == 12  # 4 sensors x 3 modes
    plt.close(fig)
