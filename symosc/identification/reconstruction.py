"""Inertia of a body on springs from its identified modes (Belyakov 2005, Ch. II).

Inputs are what a modal identification delivers: natural frequencies ``omega`` (rad/s, shape ``(k,)``) and the
normal-coordinate observation matrix ``C'`` (``modes``, shape ``(N, k)``: amplitude of mode k on sensor j,
``q0' = 1``).  Everything rests on the central identity (eq. 32)::

    M = C^T (C'^+)^T K' A'^{-1} C'^+ C,    A' = diag(omega**2),  C'^+ = (C'^T C')^{-1} C'^T

and three ways to close it:

* :func:`inertia_from_release` (the thesis' Algorithm 1) — the motion starts from the release of a known static
  force (``K' = diag(C'^T f)``);
* :func:`inertia_equal_springs` (Algorithm 2.1) — equal (unknown) springs and known mass (``K' = k C'^T C'``);
* :func:`inertia_known_center` (Algorithm 2.2) — known mass and center of mass, arbitrary springs; ill-posed when
  the center of mass sits at the center of stiffness (detected from the condition number).

Stage 3/4 of the common algorithm are :func:`real_modes` (complex -> sign(Re)·modulus) and
:func:`check_distinct` (repeated frequencies -> :class:`~symosc.errors.IdentificationError`).
:func:`assemble_tensor` combines two orientations into 5 of the 6 inertia-tensor components.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import sympy as sp

from .._deprecation import module_getattr as _module_getattr
from .._printing import SymPyPrintable
from .._validate import check_finite_array, validated
from ..errors import IdentificationError, ParameterError, warn

__all__ = [
    "InertiaEstimate",
    "InertiaTensor",
    "assemble_tensor",
    "central_identity",
    "check_distinct",
    "inertia_equal_springs",
    "inertia_from_release",
    "inertia_known_center",
    "real_modes",
    "sensor_layout",
]


def _product_sign(convention: str) -> int:
    from ..models.body_on_springs import product_sign

    return product_sign(convention)


# ---------------------------------------------------------------------------------------------------- utilities
def sensor_layout(positions: Any) -> np.ndarray:
    """Sensor points ``(x_j, z_j)`` as an ``(N, 2)`` array; a pair ``(Lx, Lz)`` means the 4-spring rectangle.

    >>> sensor_layout((4, 1.74)).tolist()
    [[0.0, 0.0], [4.0, 0.0], [4.0, 1.74], [0.0, 1.74]]
    """
    p = np.asarray(positions, dtype=float)
    if p.shape == (2,):
        lx, lz = p
        p = np.array([[0.0, 0.0], [lx, 0.0], [lx, lz], [0.0, lz]])
    if p.ndim != 2 or p.shape[1] != 2 or p.shape[0] < 3:
        raise ParameterError(f"positions must be (Lx, Lz) or an (N, 2) array of sensor points, N >= 3; got {p.shape}")
    if not np.all(np.isfinite(p)):
        raise ParameterError("sensor positions must be finite")
    c0 = np.column_stack([np.ones(len(p)), p[:, 0], -p[:, 1]])
    if np.linalg.matrix_rank(c0) < 3:
        raise ParameterError("sensor points are collinear: pitch and roll cannot both be observed")
    return p


@validated
def real_modes(values: Any, how: str = "modulus") -> np.ndarray:
    """Stage 3: make complex identified quantities real (real input is returned as float).

    ``how="modulus"`` (the dissertation): ``sign(Re) * |.|``, justified by the damping analysis (with small damping
    the moduli of complex mode shapes equal the undamped ones up to O(eps^2)).  ``how="real"``: the real part.
    For complex *amplitudes* ``A exp(i phi)`` of a release from rest the real part is the displacement at
    ``t = 0``, which is exactly the ``q0' = 1`` scaling Algorithm 1 needs; the modulus is larger by
    ``|lambda| / omega_d`` per mode (0.45 % on the stand's vertical mode at 10000 N s/m per spring).

    Parameters
    ----------
    values : array_like of float or complex
        Identified frequencies, mode shapes or modal amplitudes, any shape; must be numeric (real input is only
        converted to float).
    how : {"modulus", "real"}, optional
        How complex values are made real: ``"modulus"`` (default, Belyakov's stage 3) gives ``sign(Re) * |.|``,
        ``"real"`` the real part.

    Returns
    -------
    ndarray of float
        Same shape as ``values``.

    Examples
    --------
    >>> real_modes([1 + 0.01j, -2 - 0.1j]).round(4).tolist()
    [1.0, -2.0025]
    >>> real_modes([1 + 0.01j, -2 - 0.1j], how="real").tolist()
    [1.0, -2.0]
    """
    if how not in ("modulus", "real"):
        raise ParameterError(f"how must be 'modulus' or 'real', got {how!r}")
    a = check_finite_array("values (identified frequencies, mode shapes or amplitudes)", values, complex_ok=True)
    if how == "real" or not np.any(a.imag):
        return a.real.copy()
    return np.where(a.real < 0, -1.0, 1.0) * np.abs(a)


@validated
def check_distinct(omega: Sequence[float], rtol: float = 1e-3) -> np.ndarray:
    """Stage 4: raise :class:`IdentificationError` if two frequencies agree within relative tolerance ``rtol``.

    With a repeated eigenvalue ``A'`` is diagonal in a non-normal basis and the reconstruction is undefined.

    Parameters
    ----------
    omega : sequence of float, shape (k,)
        Identified natural frequencies (rad/s): a 1-D sequence of positive finite numbers.  Complex values are
        replaced by their modulus ``|lambda|`` (Belyakov (2005), eq. 97).
    rtol : float, optional
        Relative tolerance (> 0): two frequencies with ``|w_i - w_j| <= rtol * max(w_i, w_j)`` count as repeated.

    Returns
    -------
    ndarray of float, shape (k,)
        The (real) frequencies.

    Raises
    ------
    IdentificationError
        If two frequencies agree within ``rtol``.

    Examples
    --------
    >>> check_distinct([14.0, 16.4, 27.4]).tolist()
    [14.0, 16.4, 27.4]
    >>> check_distinct([14.0, 14.001, 27.4])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    symosc.errors.IdentificationError: repeated frequencies: omega[0] = 14 and omega[1] = 14.001 agree within ...
    """
    w = np.abs(np.asarray(omega)) if np.iscomplexobj(omega) else np.asarray(omega, dtype=float)
    if w.ndim != 1 or not np.all(np.isfinite(w)) or np.any(w <= 0):
        raise ParameterError(f"frequencies must be a 1-D array of positive finite numbers, got {omega!r}")
    for i in range(len(w)):
        for j in range(i + 1, len(w)):
            if abs(w[i] - w[j]) <= rtol * max(w[i], w[j]):
                raise IdentificationError(
                    f"repeated frequencies: omega[{i}] = {w[i]:.8g} and omega[{j}] = {w[j]:.8g} agree within "
                    f"rtol={rtol:g}; the modal reconstruction needs distinct frequencies (excite differently or "
                    "change the stand)"
                )
    return w


def _prepare(omega: Any, modes: Any, rtol: float, how: str = "modulus") -> tuple[np.ndarray, np.ndarray]:
    w = check_distinct(np.abs(omega) if np.iscomplexobj(omega) else omega, rtol)
    cp = np.asarray(modes)
    if cp.dtype.kind in "fc" and not np.all(np.isfinite(cp)):
        raise ParameterError("modes contain NaN or inf")
    cp = real_modes(modes, how)
    if cp.ndim != 2 or cp.shape[1] != len(w):
        raise ParameterError(f"modes must have shape (sensors, {len(w)}) to match omega, got {cp.shape}")
    if len(w) != 3:
        raise ParameterError(
            f"the stand model has 3 degrees of freedom (vertical, pitch, roll): give exactly 3 modes, got {len(w)}"
        )
    if not np.all(np.isfinite(cp)):
        raise ParameterError("modes contain NaN or inf")
    if cp.shape[0] < cp.shape[1] or np.linalg.matrix_rank(cp) < cp.shape[1]:
        raise IdentificationError(
            f"the modal observation matrix C' ({cp.shape[0]} x {cp.shape[1]}) does not have full column rank: "
            "some mode is not seen by the sensors"
        )
    return w, cp


@validated
def central_identity(C: Any, modes: Any, omega: Any, modal_stiffness: Any) -> Any:
    """Inertia matrix ``M = C^T (C'^+)^T K' A'^{-1} C'^+ C`` (eq. 32).

    Works on NumPy arrays and on SymPy matrices (then the result is symbolic).

    Parameters
    ----------
    C : array_like or sympy.Matrix, shape (N, n)
        Observation matrix of the physical coordinates: a 2-D array or Matrix, row j maps the coordinates to sensor
        j (for the stand, ``(1, x_j - rx, -(z_j - rz))``, eq. 23).
    modes : array_like or sympy.Matrix, shape (N, k)
        Normal-coordinate observation matrix ``C'`` (amplitude of mode i on sensor j): a 2-D array or Matrix of
        full column rank (``N >= k``).
    omega : sequence of float or sympy expressions, shape (k,)
        Natural frequencies (rad/s) of the columns of ``modes``; must be nonzero (``A' = diag(omega**2)`` is
        inverted).
    modal_stiffness : array_like or sympy.Matrix, shape (k,) or (k, k)
        Modal stiffness ``K'``: the vector of its diagonal ``K'_ii`` or the full matrix, consistent with the
        scaling of ``modes``.

    Returns
    -------
    ndarray or sympy.Matrix, shape (n, n)
        The inertia matrix ``M`` (symbolic when ``C`` or ``modes`` is a SymPy matrix).

    Examples
    --------
    >>> import numpy as np
    >>> M = np.diag([2.0, 3.0]); phi = np.eye(2); C = np.array([[1.0, 0.0], [0.0, 1.0], [1.0, 1.0]])
    >>> central_identity(C, C @ phi, np.array([1.0, 2.0]), np.array([2.0, 12.0])).round(12).tolist()
    [[2.0, 0.0], [0.0, 3.0]]
    """
    for name, v in (("C", C), ("modes", modes)):
        if not isinstance(v, sp.MatrixBase) and np.ndim(v) != 2:
            raise ParameterError(f"{name} must be a 2-D array or Matrix, got {type(v).__name__} with ndim {np.ndim(v)}")
    if isinstance(C, sp.MatrixBase) or isinstance(modes, sp.MatrixBase):
        C, Cp = sp.Matrix(C), sp.Matrix(modes)
        Kp = sp.Matrix(modal_stiffness)
        Kp = sp.diag(*Kp) if 1 in Kp.shape else Kp
        Ainv = sp.diag(*[1 / sp.sympify(w) ** 2 for w in omega])
        pinv = (Cp.T * Cp).inv() * Cp.T
        return C.T * pinv.T * Kp * Ainv * pinv * C
    C, Cp = np.asarray(C, dtype=float), np.asarray(modes, dtype=float)
    Kp = np.asarray(modal_stiffness, dtype=float)
    Kp = np.diag(Kp) if Kp.ndim == 1 else Kp
    w = np.asarray(omega, dtype=float)
    pinv = np.linalg.solve(Cp.T @ Cp, Cp.T)
    return C.T @ pinv.T @ Kp @ np.diag(1.0 / w**2) @ pinv @ C


# ---------------------------------------------------------------------------------------------------- results
@dataclass(frozen=True)
class InertiaEstimate(SymPyPrintable):
    """Dynamic parameters reconstructed from identified modes.

    ``Ixz`` follows ``convention`` (``"tensor"``: ``Ixz = -M23``; ``"dissertation"``: ``Ixz = +M23``).
    ``spring_stiffness`` is set by Algorithm 2.1, ``condition`` is the condition number of the linear system that
    closed the problem (Algorithm 2.2; 1.0 for the closed forms of Algorithms 1 and 2.1).

    Attributes
    ----------
    mass : float
        Reconstructed mass ``m`` (kg, in the units of the force and the modes), positive.
    rx, rz : float
        Center of mass in the body frame (same length unit as the sensor positions).
    Izz, Ixx : float
        Moments of inertia about the axes through the center of mass (pitch ``theta_z`` and roll ``theta_x``).
    Ixz : float
        Product of inertia, signed according to ``convention``.
    M : ndarray, shape (3, 3)
        Inertia matrix about the center of mass in the coordinates ``(y, theta_z, theta_x)`` (Belyakov (2005),
        eq. 26).
    modal_stiffness : ndarray, shape (3,)
        Modal stiffnesses ``K'_ii`` in the scaling of the given ``modes``.
    modal_mass : ndarray, shape (3,)
        Modal masses ``K'_ii / omega_i**2``.
    algorithm : str
        Which reconstruction produced the estimate: ``"1"``, ``"2.1 (diag)"``, ``"2.1 (full)"`` or ``"2.2"``.
    convention : {"tensor", "dissertation"}
        Product-of-inertia sign convention of ``Ixz``.
    spring_stiffness : float or None
        Common spring stiffness ``k`` found by Algorithm 2.1; None for the other algorithms.
    condition : float
        Condition number of the closing linear system (Algorithm 2.2); 1.0 for Algorithms 1 and 2.1.
    """

    mass: float
    rx: float
    rz: float
    Izz: float
    Ixx: float
    Ixz: float
    M: np.ndarray = field(repr=False)
    modal_stiffness: np.ndarray = field(repr=False)
    modal_mass: np.ndarray = field(repr=False)
    algorithm: str
    convention: str
    spring_stiffness: float | None = None
    condition: float = 1.0

    def __repr__(self) -> str:
        extra = f", k={self.spring_stiffness:.8g}" if self.spring_stiffness is not None else ""
        return (
            f"InertiaEstimate(algorithm={self.algorithm!r}, mass={self.mass:.10g}, rx={self.rx:.10g}, "
            f"rz={self.rz:.10g}, Izz={self.Izz:.10g}, Ixx={self.Ixx:.10g}, Ixz={self.Ixz:.10g}{extra})"
        )

    def as_dict(self) -> dict[str, float]:
        """``{"mass", "rx", "rz", "Izz", "Ixx", "Ixz"}`` (the attribute names) as plain floats."""
        return {"mass": self.mass, "rx": self.rx, "rz": self.rz, "Izz": self.Izz, "Ixx": self.Ixx, "Ixz": self.Ixz}

    def _repr_latex_(self) -> str:
        rows = r" \\ ".join(" & ".join(f"{v:.6g}" for v in row) for row in self.M)
        return rf"$M = \begin{{pmatrix}} {rows} \end{{pmatrix}},\ r_x = {self.rx:.6g},\ r_z = {self.rz:.6g}$"


def _c0(positions: np.ndarray) -> np.ndarray:
    return np.column_stack([np.ones(len(positions)), positions[:, 0], -positions[:, 1]])


def _from_point_o(M0: np.ndarray, **kw: Any) -> InertiaEstimate:
    """Move the inertia matrix from point O to the center of mass (M12 = M13 = 0): Schur complements."""
    conv = kw.pop("convention")
    m = M0[0, 0]
    if not m > 0:
        raise IdentificationError(f"reconstructed mass is not positive ({m:g}): the modal data are inconsistent")
    rx, rz = M0[0, 1] / m, -M0[0, 2] / m
    T = np.array([[1.0, -rx, rz], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    M = T.T @ M0 @ T
    return InertiaEstimate(
        mass=float(m),
        rx=float(rx),
        rz=float(rz),
        Izz=float(M0[1, 1] - M0[0, 1] ** 2 / m),
        Ixx=float(M0[2, 2] - M0[0, 2] ** 2 / m),
        Ixz=float(_product_sign(conv) * (M0[1, 2] - M0[0, 1] * M0[0, 2] / m)),
        M=M,
        convention=conv,
        **kw,
    )


# ---------------------------------------------------------------------------------------------------- algorithms
@validated
def inertia_from_release(
    omega: Any,
    modes: Any,
    force: Sequence[float],
    positions: Any,
    *,
    product_of_inertia: str = "tensor",
    rtol: float = 1e-3,
    complex_modes: str = "real",
) -> InertiaEstimate:
    """Inertia from free motion after the release of a known static force (Belyakov (2005), Algorithm 1).

    Ch. II §1, eqs 34–35.  The thesis calls this Algorithm 1; ``algorithm1`` is a deprecated alias.

    Static equilibrium in normal coordinates ``C'^T f = K' q0'`` with ``q0' = 1`` gives ``K'_ii = (C'^T f)_i``;
    the central identity with ``C = C(rx=0, rz=0)`` gives the inertia matrix about the origin O, and the
    conditions ``M12 = M13 = 0`` (Schur complements, the parallel-axis theorem) give ``m, rx, rz, Izz, Ixx, Ixz``.
    No spring stiffness is needed.

    Parameters
    ----------
    omega : array, shape (k,)
        Identified natural frequencies (rad/s): exactly three distinct positive finite numbers.  Complex values are
        replaced by ``|.|`` (stage 3).
    modes : array, shape (N, k)
        Normal-coordinate observation matrix ``C'`` with ``q0' = 1`` (full modal amplitudes with sign, metres); must
        have full column rank, ``N >= 3`` sensors.  Complex full amplitudes ``A exp(i phi)`` (phase at the release)
        are made real by ``complex_modes``.
    force : sequence of N floats
        Vertical forces (N, positive up) at the sensors before the release, one per sensor, e.g.
        ``(0, -2000, 0, 0)``.
    positions : (Lx, Lz) or array (N, 2)
        Sensor points ``(x_j, z_j)`` in the body frame: a pair ``(Lx, Lz)`` for the 4-spring rectangle or at least
        three non-collinear points (see :func:`sensor_layout`).
    product_of_inertia : {"tensor", "dissertation"}
        Sign convention of the product of inertia: ``Ixz = -M23`` (default) or ``+M23``.
    rtol : float
        Relative tolerance (> 0) of the repeated-frequency check (stage 4).
    complex_modes : {"real", "modulus"}
        Stage 3 for complex ``modes`` (see :func:`real_modes`).  ``"real"`` (default) takes the displacement at
        the release and stays exact with damping; ``"modulus"`` is the dissertation's recipe, biased by
        ``|lambda|/omega_d`` per mode when the record is damped.

    See Also
    --------
    inertia_equal_springs
    inertia_known_center
    assemble_tensor

    Examples
    --------
    The dissertation's Appendix 1 run (Belyakov (2005), pp. 106–115):

    >>> import numpy as np
    >>> modes = np.array([[-0.0006753510, 0.0006737952, -0.0006730062], [-0.0006753488, -0.0007192560, -0.0006304674],
    ...                   [-0.0006753497, -0.0006737934, 0.0006730067], [-0.0006753526, 0.0007192575, 0.0006304678]])
    >>> est = inertia_from_release([14.04726, 16.39794, 27.35160], modes, [0, -2000, 0, 0], (4, 1.74),
    ...                  product_of_inertia="dissertation")
    >>> print(f"{est.mass:.5f} {est.Izz:.5f} {est.Ixx:.6f} {est.Ixz:.7f}")
    15007.77821 44031.41487 3005.936169 399.9900541
    """
    w, cp = _prepare(omega, modes, rtol, complex_modes)
    pos = sensor_layout(positions)
    f = np.asarray(force, dtype=float)
    if f.shape != (cp.shape[0],):
        raise ParameterError(f"force must have one entry per sensor ({cp.shape[0]}), got shape {f.shape}")
    kp = cp.T @ f
    if np.any(kp <= 0):
        raise IdentificationError(
            f"modal stiffnesses C'^T f = {kp} are not all positive: the columns of C' must be scaled so that "
            "q0' = (1, ..., 1) for the released force (sign and factor of the modal amplitudes), or the force sign "
            "is wrong"
        )
    M0 = central_identity(_c0(pos), cp, w, kp)
    M0 = 0.5 * (M0 + M0.T)
    return _from_point_o(M0, modal_stiffness=kp, modal_mass=kp / w**2, algorithm="1", convention=product_of_inertia)


@validated
def inertia_equal_springs(
    omega: Any,
    modes: Any,
    mass: float,
    positions: Any,
    *,
    variant: str = "diag",
    product_of_inertia: str = "tensor",
    rtol: float = 1e-3,
) -> InertiaEstimate:
    """Inertia with equal unknown springs and known mass, any excitation (Belyakov (2005), Algorithm 2.1).

    Ch. II §2.1, eq. 36.  The thesis calls this Algorithm 2.1; ``algorithm21`` is a deprecated alias.

    With equal springs ``K' = k C'^T C'``; ``M11 = m`` gives ``k``.  Invariant to the column scaling of ``C'``.
    ``variant="diag"`` (default) keeps only the diagonal of ``C'^T C'`` (exactly diagonal for exact data, so the
    reconstructed ``M`` stays symmetric); ``"full"`` uses the whole matrix and symmetrises ``M``.  On the
    dissertation's data the two agree to 1e-5 (the full-variant values, computed without
    symmetrising, differ from both at the 1e-6 level in Izz and Ixx).

    Parameters
    ----------
    omega : array, shape (3,)
        Identified natural frequencies (rad/s): exactly three distinct positive finite numbers.  Complex values are
        replaced by ``|.|`` (stage 3).
    modes : array, shape (N, 3)
        Normal-coordinate observation matrix ``C'`` (modal amplitudes with sign, any column scaling); must have full
        column rank, ``N >= 3`` sensors.  Complex values are made real by ``sign(Re) * |.|``.
    mass : float
        Known mass of the body (kg); must be positive and finite.
    positions : (Lx, Lz) or array (N, 2)
        Sensor points ``(x_j, z_j)`` in the body frame: a pair ``(Lx, Lz)`` for the 4-spring rectangle or at least
        three non-collinear points (see :func:`sensor_layout`).
    variant : {"diag", "full"}
        Which part of ``C'^T C'`` is taken as ``K' / k``: its diagonal (default) or the whole matrix.
    product_of_inertia : {"tensor", "dissertation"}
        Sign convention of the product of inertia: ``Ixz = -M23`` (default) or ``+M23``.
    rtol : float
        Relative tolerance (> 0) of the repeated-frequency check (stage 4).

    Returns
    -------
    InertiaEstimate
        With ``spring_stiffness`` set to the identified ``k``.

    See Also
    --------
    inertia_from_release
    inertia_known_center

    Examples
    --------
    >>> import numpy as np
    >>> modes = np.array([[-0.0006753510, 0.0006737952, -0.0006730062], [-0.0006753488, -0.0007192560, -0.0006304674],
    ...                   [-0.0006753497, -0.0006737934, 0.0006730067], [-0.0006753526, 0.0007192575, 0.0006304678]])
    >>> est = inertia_equal_springs([14.04726, 16.39794, 27.35160], modes, 15000.0, (4, 1.74),
    ...                             product_of_inertia="dissertation")
    >>> print(f"{est.spring_stiffness:.1f} {est.Izz:.1f} {est.Ixx:.2f}")
    739970.7 44000.7 3000.34
    """
    w, cp = _prepare(omega, modes, rtol)
    pos = sensor_layout(positions)
    if not (np.isfinite(mass) and mass > 0):
        raise ParameterError(f"mass must be positive and finite, got {mass!r}")
    gram = cp.T @ cp
    if variant == "diag":
        kp = np.diag(np.diag(gram))
    elif variant == "full":
        kp = gram
    else:
        raise ParameterError(f"variant must be 'diag' or 'full', got {variant!r}")
    M0 = central_identity(_c0(pos), cp, w, kp)
    M0 = 0.5 * (M0 + M0.T)
    k = mass / M0[0, 0]
    M0 = k * M0
    kp_vec = k * np.diag(gram)
    return _from_point_o(
        M0,
        modal_stiffness=kp_vec,
        modal_mass=kp_vec / w**2,
        algorithm=f"2.1 ({variant})",
        convention=product_of_inertia,
        spring_stiffness=float(k),
    )


@validated
def inertia_known_center(
    omega: Any,
    modes: Any,
    mass: float,
    center: Sequence[float],
    positions: Any,
    *,
    product_of_inertia: str = "tensor",
    rtol: float = 1e-3,
    cond_max: float = 1e4,
    cond_warn: float = 1e2,
) -> InertiaEstimate:
    """Inertia with known mass and center of mass, arbitrary springs (Belyakov (2005), Algorithm 2.2).

    Ch. II §2.2, eq. 37.  The thesis calls this Algorithm 2.2; ``algorithm22`` is a deprecated alias.

    With ``C`` known, ``M = sum_i kappa_i g_i g_i^T`` (``g_i`` = column i of ``C^T (C'^+)^T``, ``kappa_i`` the
    modal masses) and ``{M11 = m, M12 = 0, M13 = 0}`` is a 3x3 linear system for ``kappa``.

    It is singular when the center of mass is at the center of stiffness (the translational mode decouples and
    ``M12, M13`` stop depending on the rotational modal masses).  The equilibrated condition number of the system is
    checked (computed with unit-norm mode shapes and lengths scaled by the rms sensor lever arm, so it does not
    depend on units or on the scaling of ``C'``): above ``cond_max`` an :class:`IdentificationError` says so, above
    ``cond_warn`` a ``RuntimeWarning``.  At the center of stiffness it is infinite; 1 cm away on the dissertation's
    stand it is about 8e3, 30 cm away about 12.

    Parameters
    ----------
    omega : array, shape (3,)
        Identified natural frequencies (rad/s): exactly three distinct positive finite numbers.  Complex values are
        replaced by ``|.|`` (stage 3).
    modes : array, shape (N, 3)
        Normal-coordinate observation matrix ``C'`` (modal amplitudes with sign, any column scaling); must have full
        column rank, ``N >= 3`` sensors.  Complex values are made real by ``sign(Re) * |.|``.
    mass : float
        Known mass of the body (kg); must be positive and finite.
    center : (rx, rz)
        Known center of mass in the body frame: a pair of finite numbers (same length unit as ``positions``).
    positions : (Lx, Lz) or array (N, 2)
        Sensor points ``(x_j, z_j)`` in the body frame: a pair ``(Lx, Lz)`` for the 4-spring rectangle or at least
        three non-collinear points (see :func:`sensor_layout`).
    product_of_inertia : {"tensor", "dissertation"}
        Sign convention of the product of inertia: ``Ixz = -M23`` (default) or ``+M23``.
    rtol : float
        Relative tolerance (> 0) of the repeated-frequency check (stage 4).
    cond_max, cond_warn : float
        Condition number above which to raise / to warn (positive, ``cond_warn <= cond_max``).

    Returns
    -------
    InertiaEstimate
        With ``condition`` set to the scale-free condition number of the 3x3 system.

    See Also
    --------
    inertia_from_release
    inertia_equal_springs

    Examples
    --------
    >>> import numpy as np
    >>> from symosc.models import body_on_springs
    >>> vals = dict(m=15000, rx=2.3, rz=0.8, Izz=44000, Ixx=3000, Ixz=400, Lx=4, Lz=1.74,
    ...             k1=7.0e5, k2=7.6e5, k3=7.3e5, k4=7.8e5)
    >>> data = body_on_springs().modal(vals)
    >>> est = inertia_known_center(data.omega, data.observation, 15000, (2.3, 0.8), (4, 1.74))
    >>> print(f"{est.Izz:.6f} {est.Ixx:.6f} {est.Ixz:.6f}")
    44000.000000 3000.000000 400.000000
    """
    w, cp = _prepare(omega, modes, rtol)
    pos = sensor_layout(positions)
    if not (np.isfinite(mass) and mass > 0):
        raise ParameterError(f"mass must be positive and finite, got {mass!r}")
    rx, rz = (float(v) for v in center)
    C = np.column_stack([np.ones(len(pos)), pos[:, 0] - rx, -(pos[:, 1] - rz)])
    g = C.T @ np.linalg.solve(cp.T @ cp, cp.T).T  # column i is g_i
    A = g[0][None, :] * g  # A[r, i] = g_i[0] * g_i[r]
    cond = _condition_22(cp, C)
    if not cond < cond_max:
        raise IdentificationError(
            f"Algorithm 2.2 is ill-posed here: condition number {cond:.3g} > cond_max={cond_max:g}. The center of "
            f"mass ({rx:g}, {rz:g}) is (nearly) at the center of stiffness, so the translational mode decouples and "
            "M12 = M13 = 0 do not determine the modal masses. Use Algorithm 1 (known released force) or 2.1 (equal "
            "springs) instead."
        )
    if cond > cond_warn:
        warn(
            f"Algorithm 2.2: condition number {cond:.3g}; errors in the modes are amplified about that much (the "
            "center of mass is close to the center of stiffness)",
            RuntimeWarning,
        )
    kappa = np.linalg.solve(A, np.array([mass, 0.0, 0.0]))
    if np.any(kappa <= 0):
        raise IdentificationError(f"Algorithm 2.2 gave non-positive modal masses {kappa}: the data are inconsistent")
    M = (g * kappa) @ g.T
    s = _product_sign(product_of_inertia)
    return InertiaEstimate(
        mass=float(M[0, 0]),
        rx=rx,
        rz=rz,
        Izz=float(M[1, 1]),
        Ixx=float(M[2, 2]),
        Ixz=float(s * M[1, 2]),
        M=M,
        modal_stiffness=kappa * w**2,
        modal_mass=kappa,
        algorithm="2.2",
        convention=product_of_inertia,
        condition=cond,
    )


def _condition_22(cp: np.ndarray, C: np.ndarray) -> float:
    """Scale-free condition number of the Algorithm 2.2 system."""
    cpn = cp / np.linalg.norm(cp, axis=0)
    lever = np.sqrt(np.mean(C[:, 1:] ** 2))
    Cs = C * np.array([1.0, 1.0 / lever, 1.0 / lever])
    g = Cs.T @ np.linalg.solve(cpn.T @ cpn, cpn.T).T
    with np.errstate(all="ignore"):
        c = np.linalg.cond(g[0][None, :] * g)
    return float(c) if np.isfinite(c) else float("inf")


# ---------------------------------------------------------------------------------------------------- two orientations
@dataclass(frozen=True)
class InertiaTensor(SymPyPrintable):
    """Five of the six inertia-tensor components from two orientations (``Iyz`` is never measured).

    Products follow ``convention``; ``Iyz`` is ``nan`` unless given.  ``source_Ixx`` says which run gave ``Ixx``.

    Attributes
    ----------
    Ixx, Iyy, Izz : float
        Moments of inertia about the body axes through the center of mass.
    Ixy, Ixz : float
        Products of inertia, signed according to ``convention``.
    Iyz : float
        Product of inertia ``Iyz``: ``nan`` (not measured by the two-orientation procedure) unless given.
    mass : float
        Mean of the two runs' masses (``nan`` when not given).
    convention : {"tensor", "dissertation"}
        Product-of-inertia sign convention (``"tensor"``: off-diagonal entries ``-Ixy, -Ixz, -Iyz``).
    source_Ixx : {1, 2}
        The run (1 or 2) whose ``Ixx`` was taken.
    """

    Ixx: float
    Iyy: float
    Izz: float
    Ixy: float
    Ixz: float
    Iyz: float = float("nan")
    mass: float = float("nan")
    convention: str = "tensor"
    source_Ixx: int = 1

    @property
    def known(self) -> dict[str, bool]:
        """Which components were measured."""
        return {k: bool(np.isfinite(getattr(self, k))) for k in ("Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz")}

    def matrix(self) -> np.ndarray:
        """Inertia tensor about the center of mass (``nan`` where ``Iyz`` is unknown)."""
        s = _product_sign(self.convention)
        return np.array(
            [
                [self.Ixx, s * self.Ixy, s * self.Ixz],
                [s * self.Ixy, self.Iyy, s * self.Iyz],
                [s * self.Ixz, s * self.Iyz, self.Izz],
            ]
        )

    def axis_moment(self, direction: Sequence[float]) -> float:
        """Moment of inertia about the axis through the center of mass with the given direction.

        ``I_u = u^T J u`` (= ``Ix a^2 + Iy b^2 + Iz c^2 - 2 Ixy ab - 2 Ixz ac - 2 Iyz bc`` in the tensor
        convention).  Raises :class:`IdentificationError` if the axis needs the unknown ``Iyz``.

        Parameters
        ----------
        direction : sequence of 3 floats
            Direction ``(a, b, c)`` of the axis in the body frame ``(x, y, z)``: a nonzero finite vector (normalised
            here).
        """
        u = np.asarray(direction, dtype=float)
        u = u / np.linalg.norm(u)
        J = self.matrix()
        if not np.isfinite(self.Iyz):
            if abs(u[1] * u[2]) > 0:
                raise IdentificationError("this axis needs Iyz, which the two-orientation procedure does not measure")
            J = np.nan_to_num(J)
        return float(u @ J @ u)


@validated
def assemble_tensor(run1: InertiaEstimate, run2: InertiaEstimate, *, Iyz: float | None = None) -> InertiaTensor:
    """Combine two runs into ``Ixx, Iyy, Izz, Ixy, Ixz`` (Ch. I §2, p. 81).

    ``run2`` is measured after turning the body 90° about its long axis Cx so that the body's ``+y`` axis lies
    along the stand's ``+z`` axis: its ``Izz`` is the body's ``Iyy`` and its ``Ixz`` the body's ``Ixy``.  ``Ixx``
    is taken from the run with the larger ``|Ixz|`` (where the out-of-model product is smaller).

    Parameters
    ----------
    run1 : InertiaEstimate
        Estimate in the first orientation (gives ``Izz`` and ``Ixz``).
    run2 : InertiaEstimate
        Estimate after turning the body 90° about Cx (gives ``Iyy`` and ``Ixy``); must use the same ``convention``
        as ``run1``.
    Iyz : float, optional
        Product of inertia ``Iyz`` if known from elsewhere; when omitted it stays ``nan`` (unknown).

    Returns
    -------
    InertiaTensor

    Examples
    --------
    >>> import numpy as np
    >>> r1 = InertiaEstimate(1.0, 0, 0, 44000.0, 3001.0, 400.0, np.eye(3), np.ones(3), np.ones(3), "1", "tensor")
    >>> r2 = InertiaEstimate(1.0, 0, 0, 43000.0, 3003.0, 20.0, np.eye(3), np.ones(3), np.ones(3), "1", "tensor")
    >>> tensor = assemble_tensor(r1, r2)
    >>> tensor.Ixx, tensor.Iyy, tensor.Izz, tensor.Ixy, tensor.Ixz, tensor.Iyz, tensor.source_Ixx
    (3001.0, 43000.0, 44000.0, 20.0, 400.0, nan, 1)
    """
    if run1.convention != run2.convention:
        raise ParameterError("both runs must use the same product-of-inertia convention")
    first = abs(run1.Ixz) >= abs(run2.Ixz)
    return InertiaTensor(
        Ixx=run1.Ixx if first else run2.Ixx,
        Iyy=run2.Izz,
        Izz=run1.Izz,
        Ixy=run2.Ixz,
        Ixz=run1.Ixz,
        Iyz=float("nan") if Iyz is None else float(Iyz),
        mass=0.5 * (run1.mass + run2.mass),
        convention=run1.convention,
        source_Ixx=1 if first else 2,
    )


_DEPRECATED_NAMES = {
    "algorithm1": "inertia_from_release",
    "algorithm21": "inertia_equal_springs",
    "algorithm22": "inertia_known_center",
}
__getattr__ = _module_getattr(__name__, _DEPRECATED_NAMES, globals())
