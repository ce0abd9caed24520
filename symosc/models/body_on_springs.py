"""Rigid body on N vertical springs: the inertia-measurement stand of Belyakov (2005).

A rigid body (mass ``m``, center of mass ``r = (rx, ry, rz)`` in the body frame ``Oxyz`` whose origin is the
attachment point of spring 1, inertia tensor about the center of mass) rests on N vertical springs attached at
points ``(x_j, 0, z_j)`` of ``Oxyz``.  Spring j has longitudinal (vertical) stiffness ``k_j`` and transverse
stiffness ``c_j``, i.e. the stiffness tensor ``G_j = diag(c_j, k_j, c_j)`` (``y`` points up).  Displacement
sensors at the attachment points measure vertical displacements.

Linear 6-DOF model (Belyakov 2005, eqs 17–21), coordinates ``(x, y, z, theta_x, theta_y, theta_z)`` = center-of-mass
displacement and small Krylov angles::

    blockdiag(m E, J) q'' + K6 q = 0,   K6 = C6^T G C6,   C6 = [[E, -R_1], ..., [E, -R_N]]

with ``R_j`` the cross-product matrix of ``rho_j = a_j - r``.  Keeping the vertical rows and the coordinates
``(y, theta_z, theta_x)`` gives the 3-DOF model (eqs 23–26) used for identification::

    M q'' + K q = 0,  y = C q,  C_j = (1, x_j - rx, -(z_j - rz)),  K = C^T diag(k) C,
    M = [[m, 0, 0], [0, Izz, s*Ixz], [0, s*Ixz, Ixx]].

Product-of-inertia sign convention
----------------------------------
``product_of_inertia="tensor"`` (default): ``Ixy, Ixz, Iyz`` are the products ``∫xy dm, ...`` and the inertia
tensor is ``[[Ixx, -Ixy, -Ixz], [-Ixy, Iyy, -Iyz], [-Ixz, -Iyz, Izz]]`` (the dissertation's Table 2 and eq. 26),
so ``M23 = -Ixz``.  ``product_of_inertia="dissertation"``: the off-diagonal entries are ``+Ixy, +Ixz, +Iyz``, so
``M23 = +Ixz``.  This is what the dissertation's numeric run (Appendix, ``Izx := M[2,3]``) and Table 4 actually
use; choose it to reproduce their numbers.  The same flag must be given to the reconstruction algorithms.
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
import sympy as sp

from .._deprecation import deprecated_attribute as _deprecated_attribute
from .._equality import ModelEquality
from .._plotting import new_axes, plot_method
from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ModelError, ParameterError
from ..mechanics import LinearModel
from ..numeric import bind, resolve
from ..numeric import compile as _compile

__all__ = ["BodyOnSprings", "ModalData", "body_on_springs", "product_sign"]

_CONVENTIONS = ("tensor", "dissertation")


def product_sign(convention: str) -> int:
    """Sign ``s`` with which a product of inertia enters the inertia matrix (``M23 = s * Ixz``).

    >>> product_sign("tensor"), product_sign("dissertation")
    (-1, 1)
    """
    if convention not in _CONVENTIONS:
        raise ParameterError(
            f"product_of_inertia must be one of {_CONVENTIONS}, got {convention!r}: 'tensor' means M23 = -Ixz "
            "(standard inertia tensor, eq. 26), 'dissertation' means M23 = +Ixz (the dissertation's numeric run)"
        )
    return -1 if convention == "tensor" else 1


def _cross_matrix(v: Sequence[Any]) -> sp.Matrix:
    """Cross-product matrix R with R w = v x w (eq. 13)."""
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


@dataclass(frozen=True)
class ModalData:
    """Forward modal solution of the 3-DOF stand model.

    Attributes
    ----------
    omega : ndarray, shape (k,)
        Natural angular frequencies, ascending (rad/s).
    shapes : ndarray, shape (3, k)
        Mass-normalised mode shapes ``Phi`` (``Phi.T @ M @ Phi = E``) in the coordinates ``(y, theta_z, theta_x)``.
    observation : ndarray, shape (N, k)
        Normal-coordinate observation matrix ``C'`` (sensor j, mode k).  With a released ``force`` the columns are
        scaled so that the normal-coordinate initial displacement is ``q0' = (1, ..., 1)``: ``C'_jk`` is then the
        full amplitude of mode k on sensor j (metres).  Without a force ``C' = C Phi``.
    modal_stiffness, modal_mass : ndarray, shape (k,)
        Diagonals of ``K'`` and ``M'`` in the same scaling (``K' = M' omega**2``).
    q0 : ndarray or None
        Static deflection ``K^{-1} C^T f`` of the generalised coordinates under the force (None without force).
    y0 : ndarray or None
        Static sensor deflections ``C q0``.
    M, K, C : ndarray
        The numeric 3-DOF matrices.
    """

    omega: np.ndarray
    shapes: np.ndarray
    observation: np.ndarray
    modal_stiffness: np.ndarray
    modal_mass: np.ndarray
    q0: np.ndarray | None
    y0: np.ndarray | None
    M: np.ndarray = field(repr=False)
    K: np.ndarray = field(repr=False)
    C: np.ndarray = field(repr=False)

    def __repr__(self) -> str:
        w = ", ".join(f"{v:.8g}" for v in self.omega)
        return f"ModalData(omega=[{w}] rad/s, sensors={self.observation.shape[0]})"

    def response(self, times: Any) -> np.ndarray:
        """Free undamped sensor response ``y(t) = C' cos(omega t) q0'`` after the release, shape ``(len(t), N)``.

        Only meaningful when the data were computed with a force (``q0' = 1``, ``v0' = 0``).
        """
        if self.q0 is None:
            raise ParameterError("response() needs the modal data of a released force: call modal(values, force=f)")
        times = np.asarray(times, dtype=float)
        return np.cos(np.multiply.outer(times, self.omega)) @ self.observation.T

    @plot_method
    def plot(self, *, ax: Any = None) -> Any:
        """Bar chart of the modal amplitudes ``C'`` per sensor (one group of bars per mode)."""

        ax = new_axes(ax)
        n, k = self.observation.shape
        width = 0.8 / n
        for j in range(n):
            ax.bar(np.arange(k) + j * width, self.observation[j], width, label=f"sensor {j + 1}")
        ax.set_xticks(np.arange(k) + 0.4 - width / 2, [f"{w:.4g} rad/s" for w in self.omega])
        ax.set_ylabel("modal amplitude C'")
        ax.legend()
        return ax

    def modal_energy(self) -> np.ndarray:
        """Energy ``K'_ii / 2`` stored in each mode by the release (J).

        The applicability measure of Belyakov (2005), Ch. III §3.
        """
        return 0.5 * self.modal_stiffness


class BodyOnSprings(ModelEquality, SymPyPrintable):
    """Symbolic model of a rigid body on N vertical springs (see the module docstring).

    Build it with :func:`body_on_springs`.  Every matrix is a SymPy object computed on first access.

    Parameters
    ----------
    n_springs : int
        Number of springs, an integer >= 3 (checked by :func:`body_on_springs`).
    layout : {"rectangle", "general"}
        ``"rectangle"``: four springs at ``(0, 0), (Lx, 0), (Lx, Lz), (0, Lz)``; ``"general"`` (any other value is
        treated so): spring ``j`` at ``(x_j, z_j)``.
    convention : {"tensor", "dissertation"}
        Product-of-inertia sign convention, ``"tensor"`` (``M23 = -Ixz``) or ``"dissertation"`` (``M23 = +Ixz``).

    Attributes
    ----------
    n_springs : int
        Number of springs.
    layout : str
        ``"rectangle"`` or ``"general"``.
    convention : str
        Product-of-inertia sign convention, ``"tensor"`` or ``"dissertation"``.
    positions : tuple of (x_j, z_j)
        Attachment (= sensor) points in ``Oxyz`` (``y = 0``), symbolic.
    """

    def _equality_data(self) -> tuple:
        return (self.n_springs, self.layout, self.convention), ()

    def __init__(self, n_springs: int, layout: str, convention: str):
        if not isinstance(n_springs, int | np.integer) or isinstance(n_springs, bool) or n_springs < 3:
            raise ParameterError(f"n_springs must be an integer >= 3 (three non-collinear supports), got {n_springs!r}")
        n_springs = int(n_springs)
        if layout not in ("rectangle", "general"):
            raise ParameterError(f"layout must be 'rectangle' or 'general', got {layout!r}")
        if layout == "rectangle" and n_springs != 4:
            raise ParameterError(f"the rectangle layout has 4 springs, got n_springs={n_springs}; use layout='general'")
        self.n_springs = n_springs
        self.layout = layout
        self.convention = convention
        self._s = product_sign(convention)
        pos = {"positive": True}
        self.m = sp.Symbol("m", **pos)
        self.rx, self.ry, self.rz = sp.symbols("rx ry rz", real=True)
        self.Ixx, self.Iyy, self.Izz = sp.symbols("Ixx Iyy Izz", **pos)
        self.Ixy, self.Ixz, self.Iyz = sp.symbols("Ixy Ixz Iyz", real=True)
        self.k = sp.symbols(f"k1:{n_springs + 1}", **pos)
        self.c = sp.symbols(f"c1:{n_springs + 1}", **pos)
        if layout == "rectangle":
            self.Lx, self.Lz = sp.symbols("Lx Lz", **pos)
            self.positions = ((0, 0), (self.Lx, 0), (self.Lx, self.Lz), (0, self.Lz))
        else:
            xs = sp.symbols(f"x1:{n_springs + 1}", real=True)
            zs = sp.symbols(f"z1:{n_springs + 1}", real=True)
            self.positions = tuple(zip(xs, zs, strict=True))
        self.coordinates6 = sp.symbols("x y z theta_x theta_y theta_z", real=True)
        self.coordinates = (self.coordinates6[1], self.coordinates6[5], self.coordinates6[3])

    def __repr__(self) -> str:
        return (
            f"BodyOnSprings(n_springs={self.n_springs}, layout={self.layout!r}, product_of_inertia={self.convention!r})"
        )

    def _repr_latex_(self) -> str:
        q = sp.Matrix(self.coordinates)
        lhs = sp.latex(self.M) + r"\ddot{q} + " + sp.latex(self.K) + r"q = 0"
        return rf"$ {lhs},\quad y = {sp.latex(self.C)}\,q,\quad q = {sp.latex(q.T)}^T $"

    # ------------------------------------------------------------------ symbolic 6-DOF model
    @property
    def r(self) -> sp.Matrix:
        """Center of mass in ``Oxyz``."""
        return sp.Matrix([self.rx, self.ry, self.rz])

    def rho(self, j: int) -> sp.Matrix:
        """Radius vector of attachment point ``j`` (1-based) relative to the center of mass.

        Parameters
        ----------
        j : int
            Number of the spring, from 1 to ``n_springs`` (1-based, as in Belyakov (2005)).
        """
        x, z = self.positions[j - 1]
        return sp.Matrix([x, 0, z]) - self.r

    def R(self, j: int) -> sp.Matrix:
        """Cross-product matrix of ``rho_j`` (eq. 13).

        Parameters
        ----------
        j : int
            Number of the spring, from 1 to ``n_springs`` (1-based, as in Belyakov (2005)).
        """
        return _cross_matrix(self.rho(j))

    def G(self, j: int) -> sp.Matrix:
        """Stiffness tensor ``diag(c_j, k_j, c_j)`` of spring ``j`` (eq. 4).

        Parameters
        ----------
        j : int
            Number of the spring, from 1 to ``n_springs`` (1-based, as in Belyakov (2005)).
        """
        return sp.diag(self.c[j - 1], self.k[j - 1], self.c[j - 1])

    @cached_property
    def inertia_tensor(self) -> sp.Matrix:
        """Inertia tensor about the center of mass in ``Cxyz``, in the chosen product-of-inertia convention."""
        s = self._s
        return sp.Matrix(
            [
                [self.Ixx, s * self.Ixy, s * self.Ixz],
                [s * self.Ixy, self.Iyy, s * self.Iyz],
                [s * self.Ixz, s * self.Iyz, self.Izz],
            ]
        )

    @cached_property
    def C6(self) -> sp.Matrix:
        """``3N x 6`` matrix ``[[E, -R_j]]`` mapping ``(x, theta)`` to attachment displacements (eqs 14, 21)."""
        return sp.Matrix.vstack(*[sp.Matrix.hstack(sp.eye(3), -self.R(j)) for j in range(1, self.n_springs + 1)])

    @cached_property
    def G_all(self) -> sp.Matrix:
        """Block-diagonal ``blockdiag(G_1, ..., G_N)``."""
        return sp.diag(*[self.G(j) for j in range(1, self.n_springs + 1)])

    @cached_property
    def M6(self) -> sp.Matrix:
        """6-DOF inertia matrix ``blockdiag(m E, J)``."""
        return sp.diag(self.m, self.m, self.m, self.inertia_tensor)

    @cached_property
    def K6(self) -> sp.Matrix:
        """6-DOF stiffness matrix ``C6^T G C6`` (eq. 19), expanded."""
        return (self.C6.T * self.G_all * self.C6).applyfunc(sp.expand)

    def coupling(self) -> sp.Matrix:
        """``sum_j R_j G_j`` (eq. 18): zero exactly when the center of mass is the center of stiffness."""
        return sp.Matrix(sum((self.R(j) * self.G(j) for j in range(1, self.n_springs + 1)), sp.zeros(3, 3)))

    def stiffness_center(self, values: Mapping[Any, Any] | None = None) -> dict[sp.Symbol, sp.Expr]:
        """Center of stiffness ``{rx: ..., ry: ..., rz: ...}``: the point where ``sum R_j G_j = 0`` (eq. 18).

        ``values`` (optional, keyed by symbol or name) are substituted exactly first, e.g. equal springs.
        Raises :class:`ModelError` if no such point exists (unequal ratios ``c_j/k_j`` make the conditions
        incompatible); :meth:`vertical_stiffness_center` always exists.

        Parameters
        ----------
        values : mapping of Symbol or str to number, optional
            Values substituted exactly before solving (keys are symbols or their names), for instance equal springs; the
            center stays symbolic in the parameters left out.

        Examples
        --------
        >>> model = body_on_springs()
        >>> model.stiffness_center({"k1": 1, "k2": 1, "k3": 1, "k4": 1, "c1": 2, "c2": 2, "c3": 2, "c4": 2})
        {rx: Lx/2, ry: 0, rz: Lz/2}
        """
        coupling = self.coupling()
        if values:
            coupling = coupling.applyfunc(lambda e: bind(e, values))
        eqs = [e for e in coupling if e != 0]
        sol = sp.solve(eqs, [self.rx, self.ry, self.rz], dict=True)
        if not sol or len(sol[0]) < 3:
            raise ModelError(
                "no center of stiffness: sum R_j G_j = 0 has no solution for these springs (the longitudinal and "
                "transverse stiffness ratios c_j/k_j differ); use vertical_stiffness_center() for the 3-DOF model"
            )
        return {s: sp.simplify(sol[0][s]) for s in (self.rx, self.ry, self.rz)}

    def vertical_stiffness_center(self) -> tuple[sp.Expr, sp.Expr]:
        """``(sum k_j x_j / sum k_j, sum k_j z_j / sum k_j)``: where the 3-DOF stiffness matrix decouples."""
        ks = sum(self.k)
        return (
            sp.simplify(sum(k * p[0] for k, p in zip(self.k, self.positions, strict=True)) / ks),
            sp.simplify(sum(k * p[1] for k, p in zip(self.k, self.positions, strict=True)) / ks),
        )

    # ------------------------------------------------------------------ 3-DOF reduction

    stiffness_centre = _deprecated_attribute("stiffness_center")
    vertical_stiffness_centre = _deprecated_attribute("vertical_stiffness_center")

    @cached_property
    def C(self) -> sp.Matrix:
        """``N x 3`` observation matrix (eq. 23): vertical rows of ``C6``, columns ``(y, theta_z, theta_x)``."""
        rows = [3 * j + 1 for j in range(self.n_springs)]
        return self.C6.extract(rows, [1, 5, 3])

    @cached_property
    def K(self) -> sp.Matrix:
        """3-DOF stiffness ``C^T diag(k) C`` (eq. 25)."""
        return (self.C.T * sp.diag(*self.k) * self.C).applyfunc(sp.expand)

    @cached_property
    def M(self) -> sp.Matrix:
        """3-DOF inertia matrix ``[[m, 0, 0], [0, Izz, s Ixz], [0, s Ixz, Ixx]]`` (eq. 26, ``s`` = convention)."""
        return self.M6.extract([1, 5, 3], [1, 5, 3])

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """Parameters of the 3-DOF model, in a fixed order."""
        geo = [self.Lx, self.Lz] if self.layout == "rectangle" else [s for p in self.positions for s in p]
        return (self.m, self.rx, self.rz, self.Izz, self.Ixx, self.Ixz, *self.k, *geo)

    @cached_property
    def parameters6(self) -> tuple[sp.Symbol, ...]:
        """Parameters of the 6-DOF model, in a fixed order."""
        geo = [self.Lx, self.Lz] if self.layout == "rectangle" else [s for p in self.positions for s in p]
        return (
            self.m, self.rx, self.ry, self.rz, self.Ixx, self.Iyy, self.Izz, self.Ixy, self.Ixz, self.Iyz,
            *self.k, *self.c, *geo,
        )  # fmt: skip

    @cached_property
    def _numeric3(self):
        return _compile(sp.Matrix.hstack(self.M, self.K, self.C.T), list(self.parameters), name="stand3")

    def sensor_positions(self, values: Mapping[Any, Any]) -> np.ndarray:
        """Numeric attachment/sensor points ``(x_j, z_j)``, shape ``(N, 2)``.

        Parameters
        ----------
        values : mapping of Symbol or str to float
            Numbers for the geometric parameters (``Lx, Lz`` or ``x1..xN, z1..zN``; keys are symbols or their names); a
            missing or non-finite value raises ParameterError.
        """
        flat = [sp.sympify(c) for p in self.positions for c in p]
        syms = sorted(set().union(*(e.free_symbols for e in flat)), key=lambda s: s.name)
        f = _compile(flat, syms) if syms else None
        out = np.asarray(f(*resolve(syms, values)) if f else [float(e) for e in flat], dtype=float)
        return out.reshape(self.n_springs, 2)

    def matrices(self, values: Mapping[Any, Any]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Numeric ``(M, K, C)`` of the 3-DOF model for ``values`` keyed by symbol or name.

        Parameters
        ----------
        values : mapping of Symbol or str to float
            Numbers for every parameter of the 3-DOF model (:attr:`parameters`; keys are symbols or their names); a
            missing or non-finite value raises ParameterError.
        """
        out = np.asarray(self._numeric3(*resolve(self.parameters, values)), dtype=float)
        return out[:, :3], out[:, 3:6], out[:, 6:].T

    def matrices6(self, values: Mapping[Any, Any]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Numeric ``(M6, K6, C6)`` of the 6-DOF model.

        Parameters
        ----------
        values : mapping of Symbol or str to float
            Numbers for every parameter of the 6-DOF model (:attr:`parameters6`; keys are symbols or their names); a
            missing or non-finite value raises ParameterError.
        """
        f = self.__dict__.get("_numeric6")
        if f is None:
            f = self.__dict__["_numeric6"] = _compile(
                sp.Matrix.hstack(self.M6, self.K6, self.C6.T), list(self.parameters6), name="stand6"
            )
        out = np.asarray(f(*resolve(self.parameters6, values)), dtype=float)
        return out[:, :6], out[:, 6:12], out[:, 12:].T

    # ------------------------------------------------------------------ simulation
    def linear_model(self) -> LinearModel:
        """The 3-DOF model as a :class:`~symosc.mechanics.LinearModel` ``M q'' + K q = 0`` in ``(y, theta_z, theta_x)``.

        >>> body_on_springs().linear_model().coordinates
        (y, theta_z, theta_x)
        """
        n = len(self.coordinates)
        return LinearModel(
            M=self.M, D=sp.zeros(n, n), K=self.K, f=sp.zeros(n, 1), coordinates=tuple(self.coordinates), point={}
        )

    def simulate(
        self,
        t: Any,
        initial: Mapping[Any, Any] | Sequence[float],
        values: Mapping[Any, Any],
        *,
        projection: str = "front",
        exaggeration: float | None = None,
        method: str = "LSODA",
        rtol: float = 1e-9,
        atol: float = 1e-12,
    ) -> Any:
        """Free oscillations of the 3-DOF model, with a drawing of the stand for ``Trajectory.animate``.

        Parameters
        ----------
        t : array_like or float
            Output times, or a duration.
        initial : mapping or array_like
            ``y``, ``theta_z``, ``theta_x`` (and ``"<name>_dot"``) at the start, e.g. the static deflection
            ``ModalData.q0`` of a released force.
        values : mapping
            Numbers for :attr:`parameters`.
        projection : {"front", "side"}
            The plane drawn: ``"front"`` looks along ``z`` (springs spread over ``x``, rotation ``theta_z``
            visible), ``"side"`` looks along ``x`` (spread over ``z``, rotation ``theta_x``).
        exaggeration : float, optional
            Factor applied to the drawn displacements (default: the largest displacement is drawn as 8 % of the
            stand's span).  The trajectory itself is unscaled.
        method : {"LSODA", "DOP853", "RK45", "Radau", "BDF"}
            Integrator.
        rtol, atol : float
            Tolerances.

        Returns
        -------
        Trajectory

        Examples
        --------
        >>> import numpy as np
        >>> model = body_on_springs(product_of_inertia="dissertation")
        >>> vals = dict(m=15000, rx=2, rz=0.87, Izz=44000, Ixx=3000, Ixz=400, Lx=4, Lz=1.74,
        ...             k1=7.4e5, k2=7.4e5, k3=7.4e5, k4=7.4e5)
        >>> q0 = model.modal(vals, force=[0, -2000, 0, 0]).q0
        >>> traj = model.simulate(np.linspace(0, 1, 101), q0, vals)
        >>> bool(traj.energy_drift < 1e-6)
        True
        """
        from .._validate import check_choice, check_positive

        check_choice("projection", projection, ("front", "side"))
        traj = self.linear_model().simulate(t, initial, values, method=method, rtol=rtol, atol=atol)
        pos = self.sensor_positions(values)
        span = float(max(np.ptp(pos[:, 0 if projection == "front" else 1]), 1e-9))
        C = self.matrices(values)[2]
        largest = float(np.max(np.abs(traj.states[:, :3] @ C.T))) or 1.0
        scale = check_positive("exaggeration", exaggeration) if exaggeration is not None else 0.08 * span / largest
        geometry = self._geometry(projection, scale, span)
        return dataclasses.replace(traj, geometry=geometry)

    def _geometry(self, projection: str, scale: float, span: float) -> Any:
        """Springs and the body's outline in the chosen plane; displacements multiplied by ``scale``."""
        from ..mechanics import Geometry

        y, tz, tx = self.coordinates
        axis = 0 if projection == "front" else 1
        height, ground = 0.25 * span, -0.4 * span
        points: dict[str, tuple] = {}
        lines = []
        for j, pnt in enumerate(self.positions, start=1):
            x, z = pnt
            disp = y + (x - self.rx) * tz - (z - self.rz) * tx
            points[f"ground{j}"] = (pnt[axis], ground)
            points[f"spring{j}"] = (pnt[axis], scale * disp)
            chain = [f"ground{j}"]
            for k in range(1, 9):  # a zigzag between the ground and the attachment point
                frac = sp.Rational(k, 9)
                side = 0.03 * span * (1 if k % 2 else -1)
                points[f"_coil{j}_{k}"] = (pnt[axis] + side, ground + frac * (scale * disp - ground))
                chain.append(f"_coil{j}_{k}")
            chain.append(f"spring{j}")
            lines += list(itertools.pairwise(chain))
        along = [p[axis] for p in self.positions]
        lo, hi = sp.Min(*along), sp.Max(*along)
        center = self.rz if projection == "front" else self.rx
        for name, u in (("left", lo), ("right", hi)):  # the body's outline through the center of mass
            x, z = (u, center) if projection == "front" else (center, u)
            disp = scale * (y + (x - self.rx) * tz - (z - self.rz) * tx)
            points[f"{name}_bottom"] = (u, disp)
            points[f"{name}_top"] = (u, disp + height)
        lines += [("left_bottom", "right_bottom"), ("right_bottom", "right_top"), ("right_top", "left_top")]
        lines += [("left_top", "left_bottom")]
        return Geometry(points, tuple(lines), (), tuple(f"ground{j}" for j in range(1, self.n_springs + 1)))

    # ------------------------------------------------------------------ forward modal solver
    def modal(self, values: Mapping[Any, Any], force: Sequence[float] | None = None) -> ModalData:
        """Forward modal solution of the 3-DOF model.

        Parameters
        ----------
        values : mapping
            Numbers for :attr:`parameters` (keyed by symbol or name).
        force : sequence of N floats, optional
            Vertical forces (N, positive up) applied at the attachment points and released at ``t = 0``
            from static equilibrium.  Then ``C'`` is scaled so that ``q0' = (1, ..., 1)`` (eq. 34).

        Returns
        -------
        ModalData

        Raises
        ------
        ModelError
            If ``M`` is not positive definite or ``K`` is singular.

        Examples
        --------
        Table 1–2 body of Belyakov (2005), released by 2000 N pushing down on spring 2:

        >>> model = body_on_springs(product_of_inertia="dissertation")
        >>> vals = dict(m=15000, rx=2, rz=0.87, Izz=44000, Ixx=3000, Ixz=400, Lx=4, Lz=1.74,
        ...             k1=7.4e5, k2=7.4e5, k3=7.4e5, k4=7.4e5)
        >>> data = model.modal(vals, force=[0, -2000, 0, 0])
        >>> data.omega.round(6).tolist()
        [14.047538, 16.398399, 27.353689]
        """
        M, K, C = self.matrices(values)
        try:
            np.linalg.cholesky(M)
        except np.linalg.LinAlgError as exc:
            raise ModelError(f"inertia matrix is not positive definite: {M.tolist()}; check Izz, Ixx, Ixz") from exc
        import scipy.linalg

        lam, phi = scipy.linalg.eigh(K, M)
        if lam.min() <= 0:
            raise ModelError(f"stiffness matrix is not positive definite (eigenvalues {lam}); check springs/sensors")
        omega = np.sqrt(lam)
        # deterministic sign: largest-magnitude component of each mode shape positive
        idx = np.argmax(np.abs(phi), axis=0)
        phi = phi * np.sign(phi[idx, np.arange(phi.shape[1])])
        if force is None:
            obs = C @ phi
            return ModalData(omega, phi, obs, lam.copy(), np.ones_like(lam), None, None, M, K, C)
        f = np.asarray(force, dtype=float)
        if f.shape != (self.n_springs,):
            raise ParameterError(f"force must have {self.n_springs} entries (one per spring), got shape {f.shape}")
        q0 = np.linalg.solve(K, C.T @ f)
        z0 = phi.T @ M @ q0
        if np.any(np.abs(z0) < 1e-12 * np.abs(z0).max()):
            raise ModelError(f"the force does not excite every mode (modal initial displacements {z0}); move it")
        obs = C @ phi * z0
        return ModalData(omega, phi, obs, lam * z0**2, z0**2, q0, C @ q0, M, K, C)


@validated
def body_on_springs(
    n_springs: int = 4, *, layout: str | None = None, product_of_inertia: str = "tensor"
) -> BodyOnSprings:
    """Rigid body on ``n_springs`` vertical springs with collocated vertical displacement sensors.

    Parameters
    ----------
    n_springs : int
        Number of springs (at least 3).
    layout : {"rectangle", "general"}, optional
        ``"rectangle"`` (default for 4 springs): the dissertation's stand, springs at ``(0, 0), (Lx, 0), (Lx, Lz),
        (0, Lz)`` with parameters ``Lx, Lz``.  ``"general"``: spring ``j`` at ``(x_j, z_j)``.
    product_of_inertia : {"tensor", "dissertation"}
        Sign convention of the products of inertia (``M23 = -Ixz`` or ``+Ixz``); see the module docstring.

    Returns
    -------
    BodyOnSprings
        Symbolic model: ``C6``, ``K6``, ``M6`` (6-DOF), ``C``, ``K``, ``M`` (3-DOF), center of stiffness,
        ``modal(values, force)``.  Parameter names: ``m, rx, ry, rz, Ixx, Iyy, Izz, Ixy, Ixz, Iyz, k1..kN,
        c1..cN`` and ``Lx, Lz`` or ``x1..xN, z1..zN``.

    See Also
    --------
    symosc.identification.simulate_stand
    symosc.identification.inertia_from_release

    Examples
    --------
    >>> model = body_on_springs()
    >>> model.C
    Matrix([
    [1,     -rx,       rz],
    [1, Lx - rx,       rz],
    [1, Lx - rx, -Lz + rz],
    [1,     -rx, -Lz + rz]])
    >>> model.M
    Matrix([
    [m,    0,    0],
    [0,  Izz, -Ixz],
    [0, -Ixz,  Ixx]])
    """
    if layout is None and isinstance(n_springs, int | np.integer):
        layout = "rectangle" if n_springs == 4 else "general"
    return BodyOnSprings(n_springs, layout, product_of_inertia)
