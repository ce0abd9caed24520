"""Reconstruction of the inertia matrix from identified modes (Belyakov 2005, seed 001, Ch. II §§1–2)."""

import warnings

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from symosc.errors import IdentificationError, ParameterError
from symosc.identification.reconstruction import (
    InertiaEstimate,
    assemble_tensor,
    central_identity,
    check_distinct,
    inertia_equal_springs,
    inertia_from_release,
    inertia_known_center,
    real_modes,
)
from symosc.models import body_on_springs

W_APPENDIX = [14.04726, 16.39794, 27.35160]
C_APPENDIX = np.array(
    [
        [-0.0006753510, 0.0006737952, -0.0006730062],
        [-0.0006753488, -0.0007192560, -0.0006304674],
        [-0.0006753497, -0.0006737934, 0.0006730067],
        [-0.0006753526, 0.0007192575, 0.0006304678],
    ]
)
F2 = [0, -2000, 0, 0]
TABLE12 = dict(
    m=15000, rx=2, rz=0.87, Izz=44000, Ixx=3000, Ixz=400, Lx=4, Lz=1.74, k1=7.4e5, k2=7.4e5, k3=7.4e5, k4=7.4e5
)


def test_golden_appendix_run():
    """Golden case: the dissertation's Maple run (Appendix 1, pp. 106–115; report §4.4), Ixz = +M23.

    Maple's printed estimates, to 1e-8 relative (Maple worked with 10-digit floats).
    """
    est = inertia_from_release(W_APPENDIX, C_APPENDIX, F2, (4, 1.74), product_of_inertia="dissertation")
    maple = dict(mass=15007.77822, rx=2.000005143, rz=0.8699994285, Izz=44031.41489, Ixx=3005.936169, Ixz=399.9900534)
    for key, value in maple.items():
        assert est.as_dict()[key] == pytest.approx(value, rel=1e-8), key
    # Table 4 (p. 80), rounded
    assert (round(est.mass), round(est.Izz), round(est.Ixx), round(est.Ixz, 1)) == (15008, 44031, 3006, 400.0)
    # report §4.4 [C]: modal stiffnesses and masses; M12 = M13 = 0 at the reconstructed center of mass
    np.testing.assert_allclose(est.modal_stiffness, [1.3506976, 1.4385120, 1.2609348], rtol=1e-7)
    np.testing.assert_allclose(est.modal_mass, [0.0068450226, 0.0053497674, 0.0016854938], rtol=1e-7)
    assert abs(est.M[0, 1]) < 1e-8 and abs(est.M[0, 2]) < 1e-8


def test_maple_g_matrix():
    """Maple's G = Y (Y^T Y)^-1 printed in the Appendix (re-sorted in report §4.4) equals (C'^+)^T."""
    maple_g = np.array(
        [
            [-370.1777506, 346.8408488, -395.6877211],
            [-370.1788100, -370.2442808, -370.6773229],
            [-370.1783343, -346.8421470, 395.6870886],
            [-370.1776585, 370.2428281, 370.6766316],
        ]
    )
    g = np.linalg.pinv(C_APPENDIX).T
    np.testing.assert_allclose(g, maple_g, rtol=2e-9)


def test_algorithm1_matches_symbolic_solve():
    """Algorithm 1 the Maple way: M(rx, rz) = C(rx, rz)^T G M' G^T C(rx, rz), solve M12 = M13 = 0 with SymPy."""
    rx, rz = sp.symbols("rx rz")
    C = sp.Matrix([[1, -rx, rz], [1, 4 - rx, rz], [1, 4 - rx, -1.74 + rz], [1, -rx, -1.74 + rz]])
    Y = sp.Matrix(C_APPENDIX.tolist())
    G = Y * (Y.T * Y).inv()
    MM = sp.diag(*[(Y[:, i].T * sp.Matrix(F2))[0] / W_APPENDIX[i] ** 2 for i in range(3)])
    M = (C.T * G * MM * G.T * C).applyfunc(sp.expand)
    sol = sp.solve([M[0, 1], M[0, 2]], [rx, rz], dict=True)[0]
    est = inertia_from_release(W_APPENDIX, C_APPENDIX, F2, (4, 1.74), product_of_inertia="dissertation")
    assert float(sol[rx]) == pytest.approx(est.rx, rel=1e-10)
    assert float(sol[rz]) == pytest.approx(est.rz, rel=1e-10)
    Mc = M.subs(sol)
    assert float(Mc[1, 1]) == pytest.approx(est.Izz, rel=1e-10)
    assert float(Mc[2, 2]) == pytest.approx(est.Ixx, rel=1e-10)
    assert float(Mc[1, 2]) == pytest.approx(est.Ixz, rel=1e-10)
    assert float(Mc[0, 0]) == pytest.approx(est.mass, rel=1e-10)


def test_central_identity_exact_symbolic():
    """Eq. (32) recovers M exactly (SymPy, rational) for SPD M, K, 4 sensors and known K' (feature 4).

    Built backwards from a rational modal matrix so that every quantity is exact: M = S^T M' S, K = S^T K' S.
    """
    S_inv = sp.Matrix([[1, 2, 0], [sp.Rational(1, 3), -1, 1], [0, 1, 4]])  # columns = mode shapes
    S = S_inv.inv()
    Mp, Kp = sp.diag(2, 3, 5), sp.diag(8, 27, 125)
    M, K = S.T * Mp * S, S.T * Kp * S
    assert M.is_symmetric() and M.is_positive_definite
    C = sp.Matrix([[1, 2, 0], [1, -1, 3], [0, 1, 1], [2, 0, -1]])
    omega = [sp.sqrt(Kp[i, i] / Mp[i, i]) for i in range(3)]
    assert (M.inv() * K * S_inv - S_inv * sp.diag(*[w**2 for w in omega])).is_zero_matrix
    Mrec = central_identity(C, C * S_inv, omega, [Kp[i, i] for i in range(3)])
    assert (Mrec - M).applyfunc(sp.simplify).is_zero_matrix
    # the numeric path agrees
    Mnum = central_identity(np.array(C, float), np.array(C * S_inv, float), np.array(omega, float), [8, 27, 125])
    np.testing.assert_allclose(Mnum, np.array(M, float), rtol=1e-12)


@settings(max_examples=25, deadline=None)
@given(
    seed=st.integers(0, 10_000),
    convention=st.sampled_from(["tensor", "dissertation"]),
)
def test_round_trip_random_bodies(seed, convention):
    """Forward modal solve -> Algorithms 1, 2.1 and 2.2 -> the same body (report §4.9, features 5–7)."""
    rng = np.random.default_rng(seed)
    lx, lz = rng.uniform(2, 6), rng.uniform(1, 3)
    vals = dict(
        m=rng.uniform(1e3, 3e4),
        rx=lx / 2 + rng.uniform(-0.4, 0.4) * lx,
        rz=lz / 2 + rng.uniform(-0.4, 0.4) * lz,
        Izz=rng.uniform(1e4, 6e4),
        Ixx=rng.uniform(1e3, 9e3),
        Lx=lx,
        Lz=lz,
    )
    vals["Ixz"] = rng.uniform(-0.3, 0.3) * np.sqrt(vals["Izz"] * vals["Ixx"])
    k = rng.uniform(5e5, 1e6)
    model = body_on_springs(product_of_inertia=convention)
    # Algorithm 1 (unequal springs, known release force)
    vals1 = {**vals, **{f"k{j}": k * rng.uniform(0.8, 1.2) for j in range(1, 5)}}
    force = np.zeros(4)
    force[rng.integers(4)] = -rng.uniform(500, 3000)
    data = model.modal(vals1, force=force)
    try:
        check_distinct(data.omega)
    except IdentificationError:
        return  # a (nearly) repeated frequency: reconstruction is undefined, tested separately
    est = inertia_from_release(data.omega, data.observation, force, (lx, lz), product_of_inertia=convention)
    for key in ("mass", "rx", "rz", "Izz", "Ixx", "Ixz"):
        assert est.as_dict()[key] == pytest.approx(
            vals["m" if key == "mass" else key], rel=1e-7, abs=1e-7 * vals["Izz"]
        ), key
    # Algorithm 2.2 on the same data (known m and center)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        try:
            est22 = inertia_known_center(
                data.omega, data.observation, vals["m"], (vals["rx"], vals["rz"]), (lx, lz),
                product_of_inertia=convention,
            )  # fmt: skip
        except IdentificationError as err:
            assert "ill-posed" in str(err)
        else:
            for key in ("Izz", "Ixx", "Ixz"):
                assert est22.as_dict()[key] == pytest.approx(vals[key], rel=1e-6, abs=1e-6 * vals["Izz"]), key
    # Algorithm 2.1 (equal springs), columns of C' scaled arbitrarily: scale invariant
    vals21 = {**vals, **{f"k{j}": k for j in range(1, 5)}}
    d21 = model.modal(vals21)
    cp = d21.observation * rng.uniform(0.1, 10, 3) * rng.choice([-1, 1], 3)
    est21 = inertia_equal_springs(d21.omega, cp, vals["m"], (lx, lz), product_of_inertia=convention)
    assert est21.spring_stiffness == pytest.approx(k, rel=1e-9)
    for key in ("rx", "rz", "Izz", "Ixx", "Ixz"):
        assert est21.as_dict()[key] == pytest.approx(vals[key], rel=1e-7, abs=1e-7 * vals["Izz"]), key


def test_algorithm21_dissertation_data():
    """Report §4.9: Algorithm 2.1 (diag variant) on the §4.3 data with m = 15000."""
    est = inertia_equal_springs(W_APPENDIX, C_APPENDIX, 15000.0, (4, 1.74), product_of_inertia="dissertation")
    assert est.spring_stiffness == pytest.approx(739970.676, rel=1e-8)
    assert est.rx == pytest.approx(2.0000051, abs=1e-7)
    assert est.rz == pytest.approx(0.8699994, abs=1e-7)
    assert est.Izz == pytest.approx(44000.725, abs=1e-3)
    assert est.Ixx == pytest.approx(3000.338, abs=1e-3)
    assert est.Ixz == pytest.approx(399.974, abs=1e-3)
    full = inertia_equal_springs(
        W_APPENDIX, C_APPENDIX, 15000.0, (4, 1.74), variant="full", product_of_inertia="dissertation"
    )
    assert full.spring_stiffness == pytest.approx(739970.676, rel=1e-8)
    assert full.Izz == pytest.approx(est.Izz, rel=1e-5)
    with pytest.raises(ParameterError, match="variant"):
        inertia_equal_springs(W_APPENDIX, C_APPENDIX, 15000.0, (4, 1.74), variant="both")


@pytest.mark.parametrize("ks", [(7e5, 7.6e5, 7.3e5, 7.8e5), (7.4e5,) * 4], ids=["case B", "case C"])
def test_algorithm22_cases_b_c(ks):
    """Report §4.9 cases B and C: Algorithm 2.2 is exact with the CM offset to (2.3, 0.8); cond about 30."""
    vals = {**TABLE12, "rx": 2.3, "rz": 0.8, **{f"k{i + 1}": k for i, k in enumerate(ks)}}
    data = body_on_springs(product_of_inertia="dissertation").modal(vals)
    est = inertia_known_center(
        data.omega, data.observation, 15000, (2.3, 0.8), (4, 1.74), product_of_inertia="dissertation"
    )
    assert (est.Izz, est.Ixx, est.Ixz) == pytest.approx((44000, 3000, 400), rel=1e-9)
    assert 5 < est.condition < 100


def test_algorithm22_ill_posed_at_center_of_stiffness():
    """Algorithm 2.2 with the CM at the center of stiffness: the §4.3 data (report §3.3) and exact data raise."""
    with pytest.raises(IdentificationError, match="center of stiffness"):
        inertia_known_center(W_APPENDIX, C_APPENDIX, 15000, (2.0, 0.87), (4, 1.74))
    data = body_on_springs().modal(TABLE12)
    with pytest.raises(IdentificationError, match="ill-posed"):
        inertia_known_center(data.omega, data.observation, 15000, (2.0, 0.87), (4, 1.74))
    # 10 cm away: solvable but amplified errors -> warning, still exact on exact data
    vals = {**TABLE12, "rx": 2.1}
    data = body_on_springs().modal(vals)
    with pytest.warns(RuntimeWarning, match="condition number"):
        est = inertia_known_center(data.omega, data.observation, 15000, (2.1, 0.87), (4, 1.74))
    assert est.Izz == pytest.approx(44000, rel=1e-7)


def test_repeated_frequencies_raise():
    """Stage 4: repeated (and near-repeated) frequencies stop the algorithm (report §3.0, feature 8)."""
    # an equal-spring stand with Lx sqrt(k/Izz) = Lz sqrt(k/Ixx): two rotational modes coincide
    vals = {**TABLE12, "Ixz": 0.0, "Ixx": 44000 * (1.74 / 4) ** 2}
    data = body_on_springs().modal(vals, force=F2)
    with pytest.raises(IdentificationError, match="repeated frequencies"):
        inertia_from_release(data.omega, data.observation, F2, (4, 1.74))
    with pytest.raises(IdentificationError, match="repeated"):
        inertia_equal_springs(data.omega, data.observation, 15000, (4, 1.74))
    with pytest.raises(IdentificationError, match=r"rtol=0\.01"):
        check_distinct([10.0, 10.05, 20.0], rtol=0.01)
    assert check_distinct([10.0, 10.05, 20.0]).tolist() == [10.0, 10.05, 20.0]


def test_near_repeated_but_distinct_is_exact():
    """Extreme: modes 0.5 % apart are still reconstructed exactly from exact data."""
    vals = {**TABLE12, "Ixz": 0.0, "Ixx": 44000 * (1.74 / 4) ** 2 * 1.01, "rx": 2.05}
    data = body_on_springs().modal(vals, force=F2)
    assert np.min(np.diff(data.omega) / data.omega[1:]) < 0.01
    est = inertia_from_release(data.omega, data.observation, F2, (4, 1.74))
    assert (est.Izz, est.Ixx) == pytest.approx((44000, vals["Ixx"]), rel=1e-8)


def test_stage3_complex_modes():
    """Stage 3: complex identified values -> sign(Re) |.|; with small modal phase errors the result is O(eps^2)."""
    data = body_on_springs(product_of_inertia="dissertation").modal(TABLE12, force=F2)
    eps = 1e-3
    noisy = data.observation * np.exp(1j * eps * np.array([[1, -1, 2], [0.5, 1, -2], [-1, 0, 1], [2, 1, 1]]))
    np.testing.assert_allclose(real_modes(noisy), data.observation, rtol=1e-15)
    est = inertia_from_release(
        data.omega * (1 + 0j), noisy, F2, (4, 1.74), product_of_inertia="dissertation", complex_modes="modulus"
    )
    assert est.Izz == pytest.approx(44000, rel=1e-9)
    est = inertia_from_release(
        data.omega, noisy, F2, (4, 1.74), product_of_inertia="dissertation"
    )  # real part: O(eps^2)
    assert est.Izz == pytest.approx(44000, rel=1e-5)
    with pytest.raises(ParameterError, match="how must be"):
        real_modes(noisy, how="phase")


def test_bad_inputs():
    """NaN, wrong shapes, wrong force sign and collinear sensors give clear errors."""
    bad = C_APPENDIX.copy()
    bad[0, 0] = np.nan
    with pytest.raises(ParameterError, match="NaN"):
        inertia_from_release(W_APPENDIX, bad, F2, (4, 1.74))
    with pytest.raises(ParameterError, match="shape"):
        inertia_from_release(W_APPENDIX, C_APPENDIX[:, :2], F2, (4, 1.74))
    with pytest.raises(ParameterError, match="exactly 3 modes"):
        inertia_known_center(W_APPENDIX[:2], C_APPENDIX[:, :2], 15000, (2.3, 0.8), (4, 1.74))
    with pytest.raises(IdentificationError, match="not all positive"):
        inertia_from_release(W_APPENDIX, C_APPENDIX, [0, 2000, 0, 0], (4, 1.74))
    with pytest.raises(ParameterError, match="collinear"):
        inertia_from_release(W_APPENDIX, C_APPENDIX, F2, [[0, 0], [1, 0], [2, 0], [3, 0]])
    with pytest.raises(ParameterError, match="positive"):
        check_distinct([1.0, -2.0, 3.0])
    with pytest.raises(ParameterError, match="mass"):
        inertia_equal_springs(W_APPENDIX, C_APPENDIX, -1.0, (4, 1.74))
    rank_deficient = np.column_stack([C_APPENDIX[:, 0], C_APPENDIX[:, 0], C_APPENDIX[:, 2]])
    with pytest.raises(IdentificationError, match="full column rank"):
        inertia_from_release(W_APPENDIX, rank_deficient, F2, (4, 1.74))


def _rotated_run(J_body, convention, rng):
    """Run Algorithm 1 on a stand carrying a body with inertia tensor J (stand axes)."""
    s = -1 if convention == "tensor" else 1
    vals = {**TABLE12, "rx": 2.2, "rz": 0.8, "Izz": J_body[2, 2], "Ixx": J_body[0, 0], "Ixz": s * J_body[0, 2]}
    vals.update({f"k{j}": 7.4e5 * rng.uniform(0.9, 1.1) for j in range(1, 5)})
    data = body_on_springs(product_of_inertia=convention).modal(vals, force=F2)
    return inertia_from_release(data.omega, data.observation, F2, (4, 1.74), product_of_inertia=convention)


@pytest.mark.parametrize("convention", ["tensor", "dissertation"])
def test_two_orientation_assembly(convention):
    """Feature 17: a synthetic tensor measured in two orientations (90° about Cx) -> 5 components; Iyz unknown."""
    rng = np.random.default_rng(7)
    s = -1 if convention == "tensor" else 1
    Ixx, Iyy, Izz, Ixy, Ixz, Iyz = 3000.0, 43000.0, 44000.0, 120.0, 400.0, 55.0
    J = np.array([[Ixx, s * Ixy, s * Ixz], [s * Ixy, Iyy, s * Iyz], [s * Ixz, s * Iyz, Izz]])
    run1 = _rotated_run(J, convention, rng)
    R = np.array([[1.0, 0, 0], [0, 0, -1], [0, 1, 0]])  # body +y -> stand +z
    run2 = _rotated_run(R @ J @ R.T, convention, rng)
    tensor = assemble_tensor(run1, run2)
    got = (tensor.Ixx, tensor.Iyy, tensor.Izz, tensor.Ixy, tensor.Ixz)
    assert got == pytest.approx((Ixx, Iyy, Izz, Ixy, Ixz), rel=1e-7)
    assert tensor.known == {"Ixx": True, "Iyy": True, "Izz": True, "Ixy": True, "Ixz": True, "Iyz": False}
    assert tensor.source_Ixx == 1  # |Ixz| = 400 > |Ixy| = 120
    # axis moment I_u = Ix a^2 + Iy b^2 + Iz c^2 - 2 Ixy ab - 2 Ixz ac - 2 Iyz bc (tensor convention form)
    u = np.array([0.6, 0.0, 0.8])
    expected = Ixx * 0.36 + Izz * 0.64 + 2 * s * Ixz * 0.48
    assert tensor.axis_moment(u) == pytest.approx(expected, rel=1e-7)
    with pytest.raises(IdentificationError, match="Iyz"):
        tensor.axis_moment([0.0, 0.6, 0.8])


def test_estimate_repr():
    """Readable repr and LaTeX."""
    est = inertia_from_release(W_APPENDIX, C_APPENDIX, F2, (4, 1.74), product_of_inertia="dissertation")
    assert "Izz=44031.41" in repr(est)
    assert est._repr_latex_().startswith("$M =")
    assert isinstance(est, InertiaEstimate)
