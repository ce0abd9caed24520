"""Nonlinear 6-DOF simulation of the inertia stand: the virtual experiment (Belyakov 2005, Ch. III §1).

State (eq. 89): angular momentum ``K`` about the center of mass in the König frame (axes parallel to the fixed
frame), Krylov angles ``theta`` of the body (``S = Sx Sy Sz``), center-of-mass velocity ``v`` and displacement
``x`` from its nominal position::

    dK/dt = sum r_i x f_i,   dtheta/dt = W(theta) S J^{-1} S^T K,   dv/dt = F/m,   dx/dt = v.

Spring i runs from its base point to the attachment point: ``l_i = x + S rho_i - rho_i + l0`` with ``l0 = (0, h, 0)``
the undeformed spring (length ``h``); the base sits at ``rho_i - l0``.  Spring law (step 5 of the dissertation)::

    f_i = -k_i l_i (1 - l0.l_i / |l_i|^2) - c_i ((l0.l_i) l_i / |l_i|^2 - l0)

(axial stiffness ``k_i``, transverse ``c_i``; ``spring_law="linear"`` uses ``-diag(c, k, c)(l_i - l0)``, which is
conservative).  Gravity ``-m g`` acts on the center of mass; optional viscous damping ``-d diag(c/k, 1, c/k) v_i``
at each attachment point (stiffness-proportional, so it leaves the mode shapes real).  The right-hand side is
derived with SymPy and compiled with :func:`symosc.numeric.compile`; scipy's DOP853 integrates it.

The experiment: a vertical force is applied at the attachment points, the body rests in static equilibrium, the
force is released at ``t = 0``; sensors sample the vertical displacement of the attachment points relative to the
equilibrium under gravity alone, with optional white noise.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cache, cached_property
from typing import Any

import numpy as np
import sympy as sp

from .._plotting import new_axes, plot_method
from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ConvergenceError, ModelError, ParameterError
from ..numeric import CompiledFunction, resolve
from ..numeric import compile as _compile

__all__ = [
    "StandRecord",
    "krylov_rate_matrix",
    "krylov_rotation",
    "simulate_stand",
    "spring_force",
    "stand_system",
]


def krylov_rotation(tx: Any, ty: Any, tz: Any) -> sp.Matrix:
    """Rotation ``S = Sx Sy Sz`` of the body frame for Krylov angles (eq. 8).

    >>> import sympy as sp
    >>> a = sp.Symbol("a")
    >>> krylov_rotation(0, 0, a)
    Matrix([
    [cos(a), -sin(a), 0],
    [sin(a),  cos(a), 0],
    [     0,       0, 1]])
    """
    cx, sx, cy, sy, cz, sz = sp.cos(tx), sp.sin(tx), sp.cos(ty), sp.sin(ty), sp.cos(tz), sp.sin(tz)
    Sx = sp.Matrix([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    Sy = sp.Matrix([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    Sz = sp.Matrix([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return Sx * Sy * Sz


def krylov_rate_matrix(tx: Any, ty: Any, tz: Any) -> sp.Matrix:
    """``W`` with ``dtheta/dt = W omega`` (omega in the fixed frame; eq. 89).

    >>> import sympy as sp
    >>> krylov_rate_matrix(0, 0, 0) == sp.eye(3)
    True
    """
    cx, sx, cy, sy = sp.cos(tx), sp.sin(tx), sp.cos(ty), sp.sin(ty)
    return sp.Matrix([[1, sx * sy / cy, -cx * sy / cy], [0, cx, sx], [0, -sx / cy, cx / cy]])


def spring_force(law: str = "belyakov") -> tuple[sp.Matrix, tuple[sp.Symbol, ...]]:
    """Symbolic force of one spring on the body and its arguments ``(l_x, l_y, l_z, k, c, h)``.

    ``l`` is the spring vector (base to attachment point), ``l0 = (0, h, 0)`` the undeformed one.

    >>> f, args = spring_force()
    >>> f.subs({args[0]: 0, args[1]: args[5], args[2]: 0}).T  # undeformed spring: no force
    Matrix([[0, 0, 0]])
    """
    lx, ly, lz = sp.symbols("l_x l_y l_z", real=True)
    k, c, h = sp.symbols("k c h", positive=True)
    ell, l0 = sp.Matrix([lx, ly, lz]), sp.Matrix([0, h, 0])
    if law == "linear":
        f = -sp.diag(c, k, c) * (ell - l0)
    elif law == "belyakov":
        dot, nn = h * ly, lx**2 + ly**2 + lz**2
        f = -k * ell * (1 - dot / nn) - c * (dot * ell / nn - l0)
    else:
        raise ParameterError(f"spring_law must be 'belyakov' or 'linear', got {law!r}")
    return f, (lx, ly, lz, k, c, h)


@cache
def _compiled(law: str) -> tuple[CompiledFunction, CompiledFunction]:
    """Compiled rotation/Krylov-rate matrices ``[S | W](theta)`` and spring force (broadcasts over springs)."""
    th = sp.symbols("theta_x theta_y theta_z", real=True)
    rot = _compile(sp.Matrix.hstack(krylov_rotation(*th), krylov_rate_matrix(*th)), list(th), name="krylov")
    f, args = spring_force(law)
    return rot, _compile(f, list(args), name=f"spring_{law}")


class _Stand:
    """Numeric right-hand side of the 6-DOF stand; state ``(K, theta, v, x)``."""

    def __init__(self, law: str, m: float, J: np.ndarray, rho: np.ndarray, k, c, d, h: float, g: float):
        self.law = law
        self.rot, self.spring = (f.raw for f in _compiled(law))
        self.m, self.Jinv, self.rho, self.h, self.g = m, np.linalg.inv(J), rho, h, g
        self.k, self.c, self.d = (np.asarray(a, dtype=float) for a in (k, c, d))
        self.l0 = np.array([0.0, h, 0.0])
        self.dtensor = np.stack([self.d * self.c / self.k, self.d, self.d * self.c / self.k], axis=1)

    def _pose(self, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        sw = np.asarray(self.rot(*theta), dtype=float)
        return sw[:, :3], sw[:, 3:]

    def rhs(self, y: np.ndarray, P: np.ndarray) -> np.ndarray:
        K, theta, v, x = y[0:3], y[3:6], y[6:9], y[9:12]
        S, W = self._pose(theta)
        omega = S @ (self.Jinv @ (S.T @ K))
        r = self.rho @ S.T  # (N, 3) attachment radius vectors in the König frame
        ell = x + r - self.rho + self.l0
        f = np.asarray(self.spring(ell[:, 0], ell[:, 1], ell[:, 2], self.k, self.c, self.h), dtype=float)
        f = f.reshape(len(self.k), 3)
        vel = v + np.cross(omega, r)
        f = f - self.dtensor * vel
        f[:, 1] += P
        F = f.sum(axis=0) + np.array([0.0, -self.m * self.g, 0.0])
        Mom = np.cross(r, f).sum(axis=0)
        return np.concatenate([Mom, W @ omega, F / self.m, v])

    def rhs_expression(self) -> tuple[sp.Matrix, tuple[sp.Symbol, ...]]:
        """The whole right-hand side as one SymPy matrix (numbers substituted) and its state symbols."""
        K = sp.Matrix(sp.symbols("K_x K_y K_z", real=True))
        th = sp.symbols("theta_x theta_y theta_z", real=True)
        v = sp.Matrix(sp.symbols("v_x v_y v_z", real=True))
        x = sp.Matrix(sp.symbols("x y z", real=True))
        S = krylov_rotation(*th)
        omega = S * sp.Matrix(self.Jinv) * S.T * K
        f_sym, (lx, ly, lz, k, c, h) = spring_force(self.law)
        F = sp.Matrix([0, -self.m * self.g, 0])
        Mom = sp.zeros(3, 1)
        for i in range(len(self.k)):
            rho = sp.Matrix(self.rho[i])
            r = S * rho
            ell = x + r - rho + sp.Matrix([0, self.h, 0])
            f = f_sym.xreplace({lx: ell[0], ly: ell[1], lz: ell[2], k: self.k[i], c: self.c[i], h: self.h})
            if self.d[i] > 0:
                f = f - sp.diag(*(float(q) for q in self.dtensor[i])) * (v + omega.cross(r))
            F += f
            Mom += r.cross(f)
        rhs = sp.Matrix([*Mom, *(krylov_rate_matrix(*th) * omega), *(F / self.m), *v])
        return rhs, (*K, *th, *v, *x)

    @cached_property
    def compiled_rhs(self) -> CompiledFunction:
        """:meth:`rhs_expression` compiled with :func:`symosc.numeric.compile` (free motion, no applied force)."""
        expr, state = self.rhs_expression()
        return _compile(expr, list(state), name="stand_rhs")

    def heights(self, states: np.ndarray) -> np.ndarray:
        """Vertical displacement of the attachment points, shape (N, samples)."""
        S = np.asarray(self.rot(*states[3:6]), dtype=float).reshape(-1, 3, 6)[:, :, :3]  # (samples, 3, 3)
        r_y = np.einsum("sb,nb->ns", S[:, 1, :], self.rho)  # vertical component of S rho_n
        return states[10][None, :] + r_y - self.rho[:, 1:2]

    def energy(self, y: np.ndarray) -> float:
        """Kinetic + gravity + spring energy (exact only for the conservative 'linear' law)."""
        K, theta, v, x = y[0:3], y[3:6], y[6:9], y[9:12]
        S, _ = self._pose(theta)
        omega = S @ (self.Jinv @ (S.T @ K))
        ell = x + self.rho @ S.T - self.rho + self.l0
        dl = ell - self.l0
        stiff = np.stack([self.c, self.k, self.c], axis=1)
        return float(0.5 * self.m * v @ v + 0.5 * K @ omega + self.m * self.g * x[1] + 0.5 * np.sum(stiff * dl**2))


@dataclass(frozen=True)
class StandRecord(SymPyPrintable):
    """Sampled sensor signals of a virtual experiment.

    Attributes
    ----------
    t : ndarray (samples,)
    signals : ndarray (channels, samples)
        Vertical displacements of the attachment points from their equilibrium under gravity (m), with noise.
    clean : ndarray (channels, samples)
        The same without noise.
    dt : float
    noise_sigma : float
        Standard deviation of the added white noise (m).
    linear : ModalData
        The linear 3-DOF model of the same stand and release (frequencies, ``C'``), for reference.
    states : ndarray (12, samples)
        ``(K, theta, v, x)`` at the samples.
    """

    t: np.ndarray = field(repr=False)
    signals: np.ndarray = field(repr=False)
    clean: np.ndarray = field(repr=False)
    dt: float
    noise_sigma: float
    linear: Any = field(repr=False)
    states: np.ndarray = field(repr=False)

    def __repr__(self) -> str:
        ch, ns = self.signals.shape
        return f"StandRecord(channels={ch}, samples={ns}, dt={self.dt:g}, noise_sigma={self.noise_sigma:.3g})"

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Plot the sensor signals (mm) against time.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; a new figure when omitted.

        Returns
        -------
        matplotlib Axes
        """

        ax = new_axes(ax)
        for j, y in enumerate(self.signals, start=1):
            ax.plot(self.t, 1e3 * y, lw=0.7, label=f"sensor {j}")
        ax.set_xlabel("t, s")
        ax.set_ylabel("displacement, mm")
        ax.legend()
        return ax


@validated
def stand_system(
    model: Any,
    values: Mapping[Any, Any],
    *,
    damping: Any = 0.0,
    spring_length: float = 0.5,
    g: float = 9.81,
    spring_law: str = "belyakov",
) -> _Stand:
    """Numeric 6-DOF stand: ``.rhs(y, P)``, ``.heights(states)``, ``.energy(y)``; state ``(K, theta, v, x)``.

    ``P`` are vertical forces at the attachment points.

    Parameters
    ----------
    model : BodyOnSprings
        The stand model; must come from :func:`symosc.models.body_on_springs`.
    values : dict
        Parameter values of the model (by symbol or name).
    damping : float or sequence of float
        Viscous damping of the springs (>= 0; one value or one per spring).
    spring_length : float
        Free length of the springs (m, > 0).
    g : float
        Gravity (m/s**2).
    spring_law : {"belyakov", "linear"}
        Spring force law.

    At rest in the undeformed pose only gravity acts:

    >>> import numpy as np
    >>> from symosc.models import body_on_springs
    >>> vals = dict(m=15000, rx=2, rz=0.87, Ixx=3000, Iyy=43000, Izz=44000, Ixz=400, Lx=4, Lz=1.74,
    ...             **{f"k{i}": 7.4e5 for i in range(1, 5)}, **{f"c{i}": 3.1e5 for i in range(1, 5)})
    >>> stand = stand_system(body_on_springs(), vals)
    >>> stand.rhs(np.zeros(12), np.zeros(4))[6:9].tolist()  # dv/dt
    [0.0, -9.81, 0.0]
    """
    from ..models.body_on_springs import BodyOnSprings

    if not isinstance(model, BodyOnSprings):
        raise ParameterError("model must come from symosc.models.body_on_springs(...)")
    if spring_law not in ("belyakov", "linear"):
        raise ParameterError(f"spring_law must be 'belyakov' or 'linear', got {spring_law!r}")
    by_name = {(k.name if isinstance(k, sp.Symbol) else str(k)): v for k, v in values.items()}
    for name, default in (("ry", 0.0), ("Ixy", 0.0), ("Iyz", 0.0)):
        by_name.setdefault(name, default)
    tensor = model.inertia_tensor
    syms = sorted(tensor.free_symbols, key=lambda q: q.name)
    J = np.asarray(_compile(tensor, syms).call(by_name), dtype=float)
    try:
        np.linalg.cholesky(J)
    except np.linalg.LinAlgError as exc:
        raise ModelError(f"inertia tensor {J.tolist()} is not positive definite") from exc
    pos = model.sensor_positions(by_name)
    r = np.array(resolve([model.rx, model.ry, model.rz], by_name), dtype=float)
    rho = np.column_stack([pos[:, 0] - r[0], np.full(len(pos), -r[1]), pos[:, 1] - r[2]])
    n = model.n_springs
    k = np.array(resolve(model.k, by_name), dtype=float)
    c = np.array(resolve(model.c, by_name), dtype=float)
    d = np.broadcast_to(np.asarray(damping, dtype=float), (n,))
    m = float(resolve([model.m], by_name)[0])
    if min(m, *k, *c) <= 0 or np.any(d < 0) or not np.all(np.isfinite(d)):
        raise ParameterError("mass and spring stiffnesses must be positive and damping non-negative")
    if not (spring_length > 0 and g >= 0):
        raise ParameterError(f"spring_length must be positive and g non-negative, got {spring_length!r}, {g!r}")
    return _Stand(spring_law, m, J, rho, k, c, d, float(spring_length), float(g))


def _equilibrium(stand: _Stand, P: np.ndarray, guess: np.ndarray) -> np.ndarray:
    """Static pose (x, theta) where forces and moments vanish (residuals scaled to units of g)."""
    m, g = stand.m, max(stand.g, 1.0)

    def resid(p: np.ndarray) -> np.ndarray:
        out = stand.rhs(np.concatenate([np.zeros(3), p[3:6], np.zeros(3), p[0:3]]), P)
        return np.concatenate([out[6:9] / g, out[0:3] / (m * g)])

    p = np.asarray(guess, dtype=float).copy()
    eye = np.eye(6) * 1e-7
    err = np.inf
    for _ in range(60):  # Newton with a central-difference Jacobian (6 x 6)
        res = resid(p)
        err = float(np.max(np.abs(res)))
        if err < 1e-13:
            return p
        jac = np.column_stack([(resid(p + e) - resid(p - e)) / 2e-7 for e in eye])
        p = p - np.linalg.solve(jac, res)
    if err > 1e-10:
        raise ConvergenceError(f"static equilibrium not found (scaled residual {err:.3g})", achieved=err)
    return p


@validated
def simulate_stand(
    model: Any,
    values: Mapping[Any, Any],
    *,
    force: Sequence[float],
    dt: float = 0.002212,
    n_samples: int = 12544,
    noise: float = 0.0,
    noise_reference: float | None = None,
    seed: int | None = None,
    damping: Any = 0.0,
    spring_length: float = 0.5,
    g: float = 9.81,
    spring_law: str = "belyakov",
    rtol: float = 1e-10,
    atol: float = 1e-14,
) -> StandRecord:
    """Virtual experiment: release a static force and sample the sensors of the nonlinear 6-DOF stand.

    Parameters
    ----------
    model : BodyOnSprings
        The stand model; must come from :func:`symosc.models.body_on_springs` (it fixes the layout and the
        product-of-inertia convention).
    values : mapping
        ``m, rx, rz, Ixx, Iyy, Izz, Ixz, k1..kN, c1..cN`` and the layout (``Lx, Lz`` or ``x_j, z_j``);
        ``ry, Ixy, Iyz`` default to 0.
    force : sequence of N floats
        Vertical forces (N, positive up) applied at the attachment points before ``t = 0``.
    dt : float
        Sampling period (s); must be positive and finite (the dissertation: 0.002212 s).
    n_samples : int
        Number of samples; an integer >= 2 (the dissertation: 12544).
    noise : float
        White-noise standard deviation as a fraction of ``noise_reference``; a finite number >= 0 (default 0: no
        noise).
    noise_reference : float, optional
        Reference amplitude (m) that ``noise`` multiplies; a positive number.  Default: the mean absolute modal
        amplitude ``mean |C'|`` of the linear model, about 0.00067 m for the dissertation's stand; if the force
        leaves a mode unexcited, sqrt(2) times the mean standard deviation of the clean signals.
    seed : int, optional
        Seed of the noise generator.
    damping : float or (N,) array
        Viscous damping of each spring along its axis (N s/m), stiffness-proportional transversally.
    spring_length : float
        Undeformed spring length ``h`` (m); not given in the dissertation.
    g : float
        Gravity (m/s^2).
    spring_law : {"belyakov", "linear"}
    rtol, atol : float
        Integrator tolerances; ``atol`` is in metres and radians (velocities and angular momenta use it scaled by
        a 100 rad/s reference rate and the largest principal moment of inertia).

    Returns
    -------
    StandRecord

    See Also
    --------
    stand_system
    matrix_pencil
    inertia_from_release

    Examples
    --------
    >>> from symosc.models import body_on_springs
    >>> model = body_on_springs(product_of_inertia="dissertation")
    >>> vals = dict(m=15000, rx=2, rz=0.87, Ixx=3000, Iyy=43000, Izz=44000, Ixz=400, Lx=4, Lz=1.74,
    ...             **{f"k{i}": 7.4e5 for i in range(1, 5)}, **{f"c{i}": 3.1e5 for i in range(1, 5)})
    >>> rec = simulate_stand(model, vals, force=[0, -2000, 0, 0], n_samples=50)
    >>> rec.signals.shape
    (4, 50)
    >>> round(float(rec.signals[1, 0]) * 1e3, 2)  # sensor 2 starts about 2 mm down
    -2.03
    """
    if not (dt > 0 and np.isfinite(dt)) or int(n_samples) < 2:
        raise ParameterError(f"need dt > 0 and n_samples >= 2, got dt={dt!r}, n_samples={n_samples!r}")
    if not (noise >= 0 and np.isfinite(noise)):
        raise ParameterError(f"noise must be a non-negative fraction, got {noise!r}")
    if not hasattr(model, "n_springs"):
        raise ParameterError("model must come from symosc.models.body_on_springs(...)")
    n = model.n_springs
    P = np.asarray(force, dtype=float)
    if P.shape != (n,) or not np.all(np.isfinite(P)):
        raise ParameterError(f"force must have {n} finite entries (one per spring), got {force!r}")
    stand = stand_system(model, values, damping=damping, spring_length=spring_length, g=g, spring_law=spring_law)
    zeros = np.zeros(n)
    eq0 = _equilibrium(stand, zeros, np.zeros(6))
    eq1 = _equilibrium(stand, P, eq0)
    y0 = np.concatenate([np.zeros(3), eq1[3:6], np.zeros(3), eq1[0:3]])

    raw = stand.compiled_rhs.raw

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        return np.asarray(raw(*y), dtype=float).ravel()

    t = np.arange(int(n_samples)) * float(dt)
    # absolute tolerances per state: atol (m, rad) for positions and angles; rates and angular momenta scaled by a
    # 100 rad/s reference rate and the largest principal inertia (else a decayed, damped record stalls on roundoff)
    jmax = float(np.max(np.linalg.eigvalsh(np.linalg.inv(stand.Jinv))))
    scale = np.concatenate([np.full(3, 100.0 * jmax), np.ones(3), np.full(3, 100.0), np.ones(3)])
    import scipy.integrate

    sol = scipy.integrate.solve_ivp(rhs, (0.0, t[-1]), y0, method="DOP853", t_eval=t, rtol=rtol, atol=atol * scale)
    if not sol.success:
        raise ConvergenceError(f"integration failed: {sol.message}")
    ref = stand.heights(np.concatenate([np.zeros(3), eq0[3:6], np.zeros(3), eq0[0:3]])[:, None])
    clean = stand.heights(sol.y) - ref

    try:
        linear = model.modal(values, force=P)
    except ModelError:  # the force leaves some mode unexcited: keep the unscaled modal data
        linear = model.modal(values)
        if noise_reference is None:
            noise_reference = float(np.sqrt(2) * np.mean(np.std(clean, axis=1)))
    if noise_reference is None:
        noise_reference = float(np.mean(np.abs(linear.observation)))
    sigma = float(noise) * float(noise_reference)
    rng = np.random.default_rng(seed)
    noisy = clean + sigma * rng.standard_normal(clean.shape) if sigma > 0 else clean.copy()
    return StandRecord(t, noisy, clean, float(dt), sigma, linear, sol.y)
