"""Nonlinear 6-DOF stand simulator, the virtual experiment (Belyakov 2005, seed 001, Ch. III §1; report §3.7)."""

import numpy as np
import pytest
import scipy.optimize
import sympy as sp
from scipy.spatial.transform import Rotation

from symosc.errors import ModelError, ParameterError
from symosc.identification.reconstruction import inertia_from_release
from symosc.identification.simulator import krylov_rate_matrix, krylov_rotation, simulate_stand
from symosc.models import body_on_springs

VALS = dict(m=15000, rx=2, rz=0.87, Ixx=3000, Iyy=43000, Izz=44000, Ixz=400, Lx=4, Lz=1.74)
VALS.update({f"k{i}": 7.4e5 for i in range(1, 5)})
VALS.update({f"c{i}": 3.1e5 for i in range(1, 5)})
F2 = [0, -2000, 0, 0]
TABLE3 = [14.04726, 16.39794, 27.35160]


def fit_modes(signals, dt, n_modes=3):
    """Independent estimator for the tests: variable-projection least squares (shared frequencies, per-channel
    offset, cosine and sine amplitudes), started from the peaks of the zero-padded spectrum."""
    y = np.asarray(signals)
    t = np.arange(y.shape[1]) * dt
    spec = np.abs(np.fft.rfft(y - y.mean(axis=1, keepdims=True), n=16 * y.shape[1], axis=1)).sum(axis=0)
    freqs = 2 * np.pi * np.fft.rfftfreq(16 * y.shape[1], dt)
    peaks = [i for i in range(1, len(spec) - 1) if spec[i] >= spec[i - 1] and spec[i] >= spec[i + 1]]
    w0 = np.sort(freqs[sorted(peaks, key=lambda i: -spec[i])[:n_modes]])

    def basis(w):
        return np.column_stack([np.ones_like(t), np.cos(np.outer(t, w)), np.sin(np.outer(t, w))])

    def resid(w):
        B = basis(w)
        coef, *_ = np.linalg.lstsq(B, y.T, rcond=None)
        return (B @ coef - y.T).ravel()

    w = scipy.optimize.least_squares(resid, w0, x_scale=1e-3, xtol=1e-15, ftol=1e-15, gtol=1e-15).x
    coef, *_ = np.linalg.lstsq(basis(w), y.T, rcond=None)
    b, s = coef[1 : 1 + n_modes].T, coef[1 + n_modes :].T
    return w, np.sign(b) * np.hypot(b, s)


@pytest.fixture(scope="module")
def record():
    model = body_on_springs(product_of_inertia="dissertation")
    return simulate_stand(model, VALS, force=F2, dt=4 * 0.002212, n_samples=1400, noise=0.01, seed=5)


def test_small_amplitude_limit_matches_linear_model(record):
    """The 2000 N release is a small motion: the nonlinear signals follow the linear 3-DOF model (eqs 23–26)."""
    linear = record.linear.response(record.t).T
    assert np.max(np.abs(record.clean - linear)) < 1e-3 * np.max(np.abs(linear))
    np.testing.assert_allclose(record.clean[:, 0], record.linear.y0, rtol=1e-6)  # static release point


def test_frequencies_close_to_table3(record):
    """Frequencies of the simulated stand agree with Table 3 (p. 79) to 0.02 % (the spring geometry is unknown)."""
    w, _ = fit_modes(record.clean, record.dt)
    np.testing.assert_allclose(w, TABLE3, rtol=2e-4)
    np.testing.assert_allclose(w, record.linear.omega, rtol=2e-5)


def test_noise_level_and_seed(record):
    """White noise with sigma = 1 % of the mean modal amplitude (about 0.00067 m, report §3.9), reproducible."""
    sigma = 0.01 * np.mean(np.abs(record.linear.observation))
    assert record.noise_sigma == pytest.approx(sigma, rel=1e-12)
    assert sigma == pytest.approx(6.74e-6, rel=1e-2)
    assert np.std(record.signals - record.clean) == pytest.approx(sigma, rel=0.05)


def test_end_to_end_one_percent_noise(record):
    """Virtual experiment -> modal estimate -> Algorithm 1 at 1 % noise: Izz and Ixx within 0.5 % (issue target; the
    dissertation's Table 4 reports 0.2 %).

    Two estimators: the package's matrix pencil (no constant state: the sensors are referenced to the gravity
    equilibrium) and, as an independent cross-check, the test's own least-squares fit.
    """
    from symosc.identification import matrix_pencil

    estimate = matrix_pencil(record.signals, record.dt, 3, constant=False, hankel_size=200)
    estimates = {
        "matrix_pencil": (estimate.undamped_frequencies, estimate.mode_shapes),
        "least squares": fit_modes(record.signals, record.dt),
    }
    for name, (w, cp) in estimates.items():
        est = inertia_from_release(w, cp, F2, (4, 1.74), product_of_inertia="dissertation")
        assert est.Izz == pytest.approx(44000, rel=5e-3), name
        assert est.Ixx == pytest.approx(3000, rel=5e-3), name
        assert est.mass == pytest.approx(15000, rel=5e-3), name
        assert (est.rx, est.rz) == pytest.approx((2.0, 0.87), abs=5e-3), name
        assert est.Ixz == pytest.approx(400, rel=0.05), name
    # noise-free: the 6-DOF simulation and the 3-DOF model agree to within the model error (report §4.5)
    w, cp = fit_modes(record.clean, record.dt)
    est = inertia_from_release(w, cp, F2, (4, 1.74), product_of_inertia="dissertation")
    assert (est.Izz, est.Ixx, est.mass) == pytest.approx((44000, 3000, 15000), rel=1e-4)


def test_krylov_rate_matrix_against_sympy():
    """W of eq. (89) inverts the map theta' -> omega derived with SymPy from S' S^T for S = Sx Sy Sz."""
    tx, ty, tz = sp.symbols("tx ty tz", real=True)
    d = sp.symbols("dx dy dz", real=True)
    S = krylov_rotation(tx, ty, tz)
    Sdot = sum((S.diff(q) * dq for q, dq in zip((tx, ty, tz), d, strict=True)), sp.zeros(3, 3))
    Om = Sdot * S.T
    omega = sp.Matrix([Om[2, 1], Om[0, 2], Om[1, 0]])
    E = omega.jacobian(d)
    f = sp.lambdify((tx, ty, tz), krylov_rate_matrix(tx, ty, tz) * E)
    rng = np.random.default_rng(0)
    for angles in rng.uniform(-1.2, 1.2, (5, 3)):
        np.testing.assert_allclose(np.array(f(*angles), float), np.eye(3), atol=1e-12)
    # S is the intrinsic x-y-z rotation
    ang = [0.3, -0.2, 0.5]
    S_num = np.array(S.subs(dict(zip((tx, ty, tz), ang, strict=True))), float)
    np.testing.assert_allclose(S_num, Rotation.from_euler("XYZ", ang).as_matrix(), atol=1e-14)


def test_energy_conserved_linear_springs():
    """Without damping and with conservative linear springs the total energy is constant (6-DOF, large motion)."""
    vals = {**VALS, "ry": 0.3, "Ixy": 150.0}
    rec = simulate_stand(body_on_springs(), vals, force=[0, -2e5, 0, 3e4], dt=0.01, n_samples=150, spring_law="linear")
    m, g = 15000.0, 9.81
    J = np.array([[3000.0, -150, -400], [-150, 43000, 0], [-400, 0, 44000]])  # tensor convention
    pts = np.array([[0, 0], [4, 0], [4, 1.74], [0, 1.74]])
    rho = np.column_stack([pts[:, 0] - 2, np.full(4, -0.3), pts[:, 1] - 0.87])
    stiff = np.array([3.1e5, 7.4e5, 3.1e5])
    energies, kinetic = [], []
    for y in rec.states.T:
        K, th, v, x = y[:3], y[3:6], y[6:9], y[9:]
        S = Rotation.from_euler("XYZ", th).as_matrix()
        omega = S @ np.linalg.solve(J, S.T @ K)
        dl = x + rho @ S.T - rho  # spring deformation
        kinetic.append(0.5 * m * v @ v + 0.5 * K @ omega)
        energies.append(kinetic[-1] + m * g * x[1] + 0.5 * np.sum(stiff * dl**2))
    assert np.ptp(rec.states[3:6]) > 1e-3  # the body really rotates
    assert max(kinetic) > 100.0
    assert np.ptp(energies) < 1e-7 * max(kinetic)


def test_damping_dissipates_and_signals_decay():
    """Spring damping of 10000 N s/m (Fig. 25): energy decreases monotonically, signals decay at ~ sum d / 2m."""
    rec = simulate_stand(body_on_springs(), {**VALS, "Ixz": 0.0}, force=[-1000.0] * 4, dt=0.02, n_samples=200,
                         damping=1e4, spring_law="linear")  # fmt: skip
    # a symmetric push excites only the vertical mode: y = y0 exp(-delta t)(cos + ...) with delta = 4 d / (2 m)
    delta = 4e4 / (2 * 15000)
    env = np.abs(rec.clean[0])
    t = rec.t
    peaks = [i for i in range(1, len(t) - 1) if env[i] >= env[i - 1] and env[i] >= env[i + 1] and env[i] > 1e-6]
    slope = np.polyfit(t[peaks], np.log(env[peaks]), 1)[0]
    assert slope == pytest.approx(-delta, rel=0.05)


def test_damped_release_algorithm1():
    """10000 N s/m per spring (Ch. III §4, Fig. 25): |lambda| gives the undamped frequencies exactly (eq. 97), and
    Algorithm 1 stays exact when C' is the displacement at the release (real part of the complex amplitudes).

    The dissertation's stage 3 (modulus of the complex amplitudes) overestimates each mode by |lambda|/omega_d
    and so biases Algorithm 1 by several tenths of a percent here; the thesis's "no loss of accuracy" holds for
    the frequencies and for the scale-invariant Algorithms 2.1/2.2, not for the modulus in Algorithm 1.
    """
    from symosc.identification import inertia_equal_springs, matrix_pencil

    model = body_on_springs(product_of_inertia="dissertation")
    rec = simulate_stand(model, VALS, force=F2, dt=4 * 0.002212, n_samples=1400, damping=1e4)
    est = matrix_pencil(rec.clean, rec.dt, 3, constant=False, hankel_size=200)
    lin = model.modal(VALS)
    np.testing.assert_allclose(est.undamped_frequencies, lin.omega, rtol=2e-5)
    assert est.damping[0] == pytest.approx(4e4 / (2 * 15000), rel=1e-3)  # vertical mode: sum d / 2m
    amps = 2 * est.complex_amplitudes
    exact = inertia_from_release(est.undamped_frequencies, amps, F2, (4, 1.74), product_of_inertia="dissertation")
    assert (exact.Izz, exact.Ixx, exact.mass) == pytest.approx((44000, 3000, 15000), rel=1e-4)
    biased = inertia_from_release(est.undamped_frequencies, amps, F2, (4, 1.74), product_of_inertia="dissertation",
                        complex_modes="modulus")  # fmt: skip
    assert biased.Ixx / 3000 - 1 < -0.01
    assert biased.mass / 15000 - 1 == pytest.approx(-(1 - np.sqrt(1 - (4e4 / 30000 / lin.omega[0]) ** 2)), rel=0.05)
    e21 = inertia_equal_springs(est.undamped_frequencies, amps, 15000, (4, 1.74), product_of_inertia="dissertation")
    assert (e21.Izz, e21.Ixx) == pytest.approx((44000, 3000), rel=1e-4)


def test_static_sag():
    """Without a release the body rests at the gravity equilibrium: sag mg/(4k) = 0.0497 m (report §4.1)."""
    rec = simulate_stand(body_on_springs(), VALS, force=[0.0] * 4, n_samples=3)
    assert rec.states[10, 0] == pytest.approx(-15000 * 9.81 / (4 * 7.4e5), rel=1e-9)
    assert np.max(np.abs(rec.signals)) < 1e-12


def test_bad_input():
    """Clear errors."""
    model = body_on_springs()
    with pytest.raises(ParameterError, match="one per spring"):
        simulate_stand(model, VALS, force=[1.0, 2.0])
    with pytest.raises(ParameterError, match="noise"):
        simulate_stand(model, VALS, force=F2, noise=-0.1)
    with pytest.raises(ParameterError, match="missing values for: c1"):
        simulate_stand(model, {k: v for k, v in VALS.items() if k != "c1"}, force=F2)
    with pytest.raises(ParameterError, match="body_on_springs"):
        simulate_stand(object(), VALS, force=F2)
    with pytest.raises(ModelError, match="not positive definite"):
        simulate_stand(model, {**VALS, "Ixz": 1e5}, force=F2)
    with pytest.raises(ParameterError, match="spring_law"):
        simulate_stand(model, VALS, force=F2, spring_law="cubic")


def test_record_plot(record):
    """Fig. 18-style picture of the sensor signals."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    record.plot(ax=ax)
    assert len(ax.lines) == 4
    plt.close(fig)
    assert repr(record) == "StandRecord(channels=4, samples=1400, dt=0.008848, noise_sigma=6.75e-06)"
