"""Linearized models ``M q'' + D q' + K(t) q = f(t)`` and their modal analysis."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np
import sympy as sp

from .._equality import ModelEquality
from .._printing import SymPyPrintable
from .._validate import check_complete_names
from ..errors import ModelError, ParameterError, warn
from ..numeric import compile
from ..symbols import sort_symbols, t
from . import _terms

if TYPE_CHECKING:
    from .lagrange import LagrangianSystem

__all__ = ["LinearModel"]

_S = sp.Symbol("s")


@dataclass(frozen=True, eq=False)
class LinearModel(ModelEquality, SymPyPrintable):
    """``M q'' + D q' + K q = f`` about an equilibrium; ``K`` and ``f`` may depend on time.

    Two models are equal (and hash alike) when coordinates, point and matrices agree (entries equal after
    expansion).

    Attributes
    ----------
    M, D, K : sympy.Matrix
        Mass, damping (including gyroscopic) and stiffness matrices.  For a rheonomic system the
        time-periodic part of ``K`` is kept explicit, e.g. ``K0 + K1*cos(p*t)``
        (see :meth:`stiffness_harmonics`).
    f : sympy.Matrix
        Excitation left at the equilibrium (zero for a true equilibrium of an unforced system).
    coordinates : tuple of Symbol
        The deviations q from the point (same symbols as the nonlinear system).
    point : dict
        The linearization point.

    Examples
    --------
    >>> from symosc.models import n_link_pendulum
    >>> lin = n_link_pendulum(1, inverted=True, pivot="vertical").linearize()
    >>> lin.K
    Matrix([[a*l1*m1*p**2*cos(p*t) - g*l1*m1]])
    >>> lin.periodic_stiffness()
    (Matrix([[-g*l1*m1]]), Matrix([[a*l1*m1*p**2]]), p)
    """

    M: sp.Matrix
    D: sp.Matrix
    K: sp.Matrix
    f: sp.Matrix
    coordinates: tuple[sp.Symbol, ...]
    point: dict = field(default_factory=dict)

    def _equality_data(self) -> tuple:
        point = tuple(sorted((str(k), sp.sympify(v)) for k, v in self.point.items()))
        return (tuple(self.coordinates), point), (self.M, self.D, self.K, self.f)

    def __repr__(self) -> str:
        n = len(self.coordinates)
        kind = "time-periodic" if t in self.K.free_symbols else "constant"
        names = ", ".join(s.name for s in self.parameters)
        return f"LinearModel({n} DOF, {kind} stiffness; parameters: {names})"

    def _repr_latex_(self) -> str:
        return f"$${self.latex()}$$"

    def latex(self, *, simplify: bool = False) -> str:
        """LaTeX of ``M q'' + D q' + K q = f``; ``simplify=True`` applies ``sympy.trigsimp`` first (display only).

        Parameters
        ----------
        simplify : bool, optional
            Whether to apply ``sympy.trigsimp`` to M, D and K before printing (display only; default False).

        Examples
        --------
        >>> from symosc.models import n_link_pendulum
        >>> tex = n_link_pendulum(1).linearize().latex(simplify=True)
        >>> tex.startswith(r"\\left[\\begin{matrix}l_{1}^{2} m_{1}\\end{matrix}\\right] \\ddot{q}")
        True

        See Also
        --------
        symosc.mechanics.LagrangianSystem.latex
        """
        M, D, K = self.M, self.D, self.K
        if simplify:
            M, D, K = (m.applyfunc(sp.trigsimp) for m in (M, D, K))
        q = sp.Matrix(self.coordinates)
        return (
            f"{sp.latex(M)} \\ddot{{q}} + {sp.latex(D)} \\dot{{q}} + {sp.latex(K)} {sp.latex(q)} = {sp.latex(self.f)}"
        )

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """Parameter symbols of M, D, K and f (time excluded), natural order."""
        syms = set().union(*(m.free_symbols for m in (self.M, self.D, self.K, self.f)))
        return sort_symbols(syms - {t} - set(self.coordinates))

    # ------------------------------------------------------------------ time structure of K
    def stiffness_harmonics(self) -> dict[sp.Expr, sp.Matrix]:
        """Split ``K(t) = sum_f f(t) K_f``; the constant part is keyed by ``S.One``.

        >>> from symosc.models import n_link_pendulum
        >>> parts = n_link_pendulum(1, pivot="vertical").linearize().stiffness_harmonics()
        >>> sorted(map(str, parts))
        ['1', 'cos(p*t)']
        """
        return {f: K.copy() for f, K in self._harmonics.items()}

    @cached_property
    def _harmonics(self) -> dict[sp.Expr, sp.Matrix]:
        n = self.K.shape[0]
        terms: dict[sp.Expr, dict[tuple[int, int], list]] = {}
        for i in range(n):
            for j in range(n):
                # term by term: expanding a long sum as a whole re-sorts all of its terms at every level
                for top in sp.Add.make_args(self.K[i, j]):
                    for term in sp.Add.make_args(sp.expand(top) if _expandable(top) else top):
                        if term == 0:  # a zero entry is no harmonic (it used to add a spurious key 0)
                            continue
                        coeff, tpart = _split_time(term)
                        terms.setdefault(tpart, {}).setdefault((i, j), []).append(coeff)
        parts: dict[sp.Expr, sp.Matrix] = {sp.S.One: sp.zeros(n, n)}
        for tpart, entries in terms.items():  # one Add per entry: summing term by term is quadratic
            sums = {ij: sp.Add(*coeffs) for ij, coeffs in entries.items()}
            if tpart == sp.S.One or any(v != 0 for v in sums.values()):  # terms that cancel leave no harmonic
                parts[tpart] = sp.zeros(n, n)
                for (i, j), v in sums.items():
                    parts[tpart][i, j] = v
        return parts

    @cached_property
    def K0(self) -> sp.Matrix:
        """The time-independent part of K."""
        return self.stiffness_harmonics()[sp.S.One]

    def periodic_stiffness(self) -> tuple[sp.Matrix, sp.Matrix, sp.Expr]:
        """``(K0, K1, p)`` such that ``K = K0 + K1*cos(p*t)``; :class:`ModelError` if K has another form."""
        parts = self.stiffness_harmonics()
        varying = {k: v for k, v in parts.items() if k != sp.S.One and v != sp.zeros(*v.shape)}
        if len(varying) != 1:
            raise ModelError(
                f"K(t) is not of the form K0 + K1*cos(p*t): its time-dependent factors are {list(varying) or 'none'}"
            )
        ((tf, K1),) = varying.items()
        if not (isinstance(tf, sp.cos) and (tf.args[0] / t).free_symbols.isdisjoint({t})):
            raise ModelError(f"K(t) is not of the form K0 + K1*cos(p*t): time factor {tf}")
        return parts[sp.S.One], K1, sp.simplify(tf.args[0] / t)

    # ------------------------------------------------------------------ numbers
    @cached_property
    def _compiled(self):
        n = self.M.shape[0]
        mats = self.M.row_join(self.D).row_join(self.K0)
        if t in mats.free_symbols:
            raise ModelError("M or D depends on time; evaluate them at a given time with sympy first")
        return n, compile(mats, list(sort_symbols(mats.free_symbols)), name="linear_matrices")

    def matrices(self, values: Mapping[Any, Any]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Numeric ``(M, D, K0)``; array-valued parameters give stacks of shape ``(..., n, n)``.

        Parameters
        ----------
        values : mapping of Symbol or str to float or array_like
            Numbers for every parameter of M, D and K0 (keys are symbols or their names); a missing or non-finite value
            raises ParameterError, and arrays of values (broadcast together) give stacked results.
        """
        if not isinstance(values, Mapping):
            raise ParameterError(
                f"values must be a mapping of parameter names to numbers, got {type(values).__name__}; "
                f"parameters: {[s.name for s in self.parameters]}"
            )
        check_complete_names("parameter value(s)", values, sort_symbols(self._compiled[1].args))
        n, fn = self._compiled
        out = fn.call(values)
        return out[..., :, :n], out[..., :, n : 2 * n], out[..., :, 2 * n :]

    def _whitened(self, values: Mapping[Any, Any]) -> tuple[np.ndarray, np.ndarray]:
        M, _, K = self.matrices(values)
        if not np.allclose(M, np.swapaxes(M, -1, -2), rtol=1e-12, atol=0):
            raise ModelError("mass matrix is not symmetric")
        if not np.allclose(K, np.swapaxes(K, -1, -2), rtol=1e-10, atol=1e-300):
            raise ModelError("stiffness matrix K0 is not symmetric (circulatory forces): use a state-space analysis")
        try:
            L = np.linalg.cholesky(M)
        except np.linalg.LinAlgError as exc:
            raise ModelError("mass matrix is singular or not positive definite at these parameter values") from exc
        cond = float(np.max(np.linalg.cond(M)))
        if cond * np.finfo(float).eps > 1e-8:
            from ..errors import AccuracyWarning

            warn(
                f"the mass matrix is ill-conditioned (cond = {cond:.3g}, e.g. a very short or light link): the "
                f"frequencies may carry relative errors up to about {min(1.0, cond * np.finfo(float).eps):.1g} (worst "
                "case; the low modes suffer most)",
                AccuracyWarning,
            )
        Linv = np.linalg.inv(L)
        A = Linv @ K @ np.swapaxes(Linv, -1, -2)
        return 0.5 * (A + np.swapaxes(A, -1, -2)), Linv

    def eigenvalues(self, values: Mapping[Any, Any]) -> np.ndarray:
        """Generalised eigenvalues ``lambda = omega**2`` of ``K0 phi = lambda M phi``, ascending (may be < 0).

        Parameters
        ----------
        values : mapping of Symbol or str to float or array_like
            Numbers for every parameter of M, D and K0 (keys are symbols or their names); a missing or non-finite value
            raises ParameterError, and arrays of values (broadcast together) give stacked results.
        """
        A, _ = self._whitened(values)
        return np.linalg.eigvalsh(A)

    def natural_frequencies(self, values: Mapping[Any, Any]) -> np.ndarray:
        """Undamped natural angular frequencies (rad/s), ascending, from M and the constant part K0.

        Raises :class:`ModelError` when M is not positive definite or when the equilibrium is
        statically unstable (K0 has negative eigenvalues relative to M; use :meth:`eigenvalues`).

        Parameters
        ----------
        values : mapping of Symbol or str to float or array_like
            Numbers for every parameter of M, D and K0 (keys are symbols or their names); a missing or non-finite value
            raises ParameterError, and arrays of values (broadcast together) give stacked results.

        Examples
        --------
        >>> from symosc.models import n_link_pendulum
        >>> lin = n_link_pendulum(2).linearize()
        >>> lin.natural_frequencies({"m1": 1, "m2": 1, "l1": 1, "l2": 1, "g": 1}).round(6).tolist()
        [0.765367, 1.847759]
        """
        lam = self.eigenvalues(values)
        return _frequencies(lam)

    def modes(self, values: Mapping[Any, Any]) -> tuple[np.ndarray, np.ndarray]:
        """``(omega, Phi)``: frequencies and mass-normalised mode shapes (columns), ``Phi.T M Phi = I``.

        Each mode is signed so that its largest-magnitude component is positive.

        Parameters
        ----------
        values : mapping of Symbol or str to float or array_like
            Numbers for every parameter of M, D and K0 (keys are symbols or their names); a missing or non-finite value
            raises ParameterError, and arrays of values (broadcast together) give stacked results.
        """
        A, Linv = self._whitened(values)
        lam, V = np.linalg.eigh(A)
        omega = _frequencies(lam)
        Phi = np.swapaxes(Linv, -1, -2) @ V
        idx = np.argmax(np.abs(Phi), axis=-2)[..., None, :]
        sign = np.sign(np.take_along_axis(Phi, idx, axis=-2))
        return omega, Phi * np.where(sign == 0, 1.0, sign)

    # ------------------------------------------------------------------ simulation
    def simulate(
        self,
        t: Any,
        initial: Mapping[Any, Any] | Sequence[float],
        values: Mapping[Any, Any],
        *,
        method: str = "LSODA",
        rtol: float = 1e-9,
        atol: float = 1e-11,
        geometry: Any = None,
    ) -> Any:
        """Integrate ``M q'' + D q' + K(t) q = f(t)`` (periodic stiffness and forcing included).

        Parameters
        ----------
        t : array_like or float
            Output times (increasing), or a duration ``T`` (0..T, 1001 points).
        initial : mapping or array_like
            Coordinate name -> initial deviation, ``"<name>_dot"`` -> initial rate (zero unless given), or the
            full state ``(q, q')``.
        values : mapping
            Parameter values keyed by Symbol or name.
        method : {"LSODA", "DOP853", "RK45", "Radau", "BDF"}
            Integrator (the Jacobian ``[[0, I], [-M^-1 K(t), -M^-1 D]]`` is exact).
        rtol, atol : float
            Tolerances.
        geometry : Geometry, optional
            Points and lines for :meth:`Trajectory.animate <symosc.mechanics.Trajectory.animate>`.

        Returns
        -------
        Trajectory
            With the energy ``(q'^T M q' + q^T K q) / 2``, conserved when ``D = 0``, ``f = 0`` and ``K`` is constant
            and symmetric.

        Examples
        --------
        >>> import numpy as np
        >>> from symosc.models import n_link_pendulum
        >>> lin = n_link_pendulum(1).linearize()
        >>> traj = lin.simulate(np.linspace(0, np.pi, 3), {"phi1": 0.1}, {"m1": 1.0, "l1": 1.0, "g": 4.0})
        >>> traj.q["phi1"].round(8).tolist()        # 0.1 cos(2 t)
        [0.1, -0.1, 0.1]

        See Also
        --------
        symosc.mechanics.LagrangianSystem.simulate
        """
        from .simulation import simulate_linear

        return simulate_linear(self, t, initial, values, method=method, rtol=rtol, atol=atol, geometry=geometry)

    # ------------------------------------------------------------------ control systems
    def transfer_function(
        self,
        inputs: Any = None,
        outputs: Any = None,
        *,
        values: Mapping[Any, Any] | None = None,
        velocities: bool = False,
        s: sp.Symbol = _S,
    ) -> sp.ImmutableMatrix:
        """The exact transfer matrix ``H(s) = C (M s**2 + D s + K)**-1 E`` from the inputs to the outputs.

        Formed in exact arithmetic over the rational functions of ``s`` and the parameters (damping and gyroscopic
        terms included): each entry is a cancelled ratio of polynomials, symbolic in the parameters left free.

        Parameters
        ----------
        inputs : coordinates, force symbols, indices or matrix (n, m), optional
            Where the inputs act: a unit generalized force ``Q_q`` on each listed coordinate (default: every
            coordinate), a symbol of the excitation ``f`` (its column ``df/du``), or a force-distribution matrix
            ``E`` in ``M q'' + D q' + K q = E u``.
        outputs : coordinates, indices or matrix (n, p), optional
            The measured coordinates (default: all), or a matrix ``C`` with ``y = C^T q``.
        values : mapping, optional
            Numbers for some or all parameters (keyed by Symbol or name); floats are read as the decimals they print
            as (``9.81 -> 981/100``), so the result is exact.
        velocities : bool
            Measure the rates of the outputs (``H`` times ``s``).
        s : Symbol
            The Laplace variable.

        Returns
        -------
        sympy.ImmutableMatrix
            ``p x m`` rational functions of ``s``.

        Raises
        ------
        ModelError
            ``K`` depends on time, or ``M s**2 + D s + K`` is singular for every ``s``.

        Examples
        --------
        Hanging double pendulum, unit masses and lengths: from the torque on the lower link to the upper angle
        (``det(M s**2 + K) = s**4 + 4 g s**2 + 2 g**2``):

        >>> import sympy as sp
        >>> from symosc.models import n_link_pendulum
        >>> lin = n_link_pendulum(2, links="point").linearize()
        >>> H = lin.transfer_function(inputs=["phi2"], outputs=["phi1"], values={"m1": 1, "m2": 1, "l1": 1, "l2": 1})
        >>> sp.factor(H[0, 0])
        -s**2/(2*g**2 + 4*g*s**2 + s**4)

        See Also
        --------
        to_transfer_function, to_state_space
        """
        from ._control import exact_transfer_matrix

        return exact_transfer_matrix(self, inputs=inputs, outputs=outputs, values=values, velocities=velocities, s=s)

    def to_state_space(
        self,
        *,
        inputs: Any = None,
        outputs: Any = None,
        values: Mapping[Any, Any] | None = None,
        velocities: bool = False,
        backend: str = "auto",
    ) -> Any:
        """The model as a state-space system ``x' = A x + B u``, ``y = C x`` with ``x = (q, q')``.

        With python-control the signals carry the model's names: inputs ``Q_q`` (generalized force on coordinate
        ``q``) or the force symbols given, outputs the coordinates (``q_dot`` with ``velocities=True``), states
        ``q..., q_dot...``.

        Parameters
        ----------
        inputs : coordinates, indices or array (n, m), optional
            Where the inputs act: a unit generalized force on each listed coordinate (default: every coordinate),
            or a force-distribution matrix ``E`` in ``M q'' + D q' + K q = E u``.
        outputs : coordinates, indices or array (n, p), optional
            The measured coordinates (default: all); ``velocities=True`` measures their rates instead.
        values : mapping
            Numbers for every parameter (keyed by Symbol or name).
        velocities : bool, optional
            Whether the outputs are the rates ``q'`` of the measured coordinates instead of the coordinates (default
            False).
        backend : {"auto", "control", "scipy"}
            ``control.StateSpace`` when python-control is installed (``"auto"``), else ``scipy.signal.StateSpace``.

        Examples
        --------
        >>> from symosc.models import n_link_pendulum
        >>> lin = n_link_pendulum(1).linearize()
        >>> sys = lin.to_state_space(values={"m1": 1.0, "l1": 1.0, "g": 9.81}, backend="scipy")
        >>> sys.A.tolist(), sys.B.ravel().tolist()
        ([[0.0, 1.0], [-9.81, 0.0]], [0.0, 1.0])

        With python-control, Bode, Nyquist and step plots are one line each, e.g.
        ``control.bode_plot(lin.to_transfer_function(values=...))``.

        See Also
        --------
        to_transfer_function, natural_frequencies
        """
        from ._control import state_space

        return state_space(self, inputs=inputs, outputs=outputs, values=values, velocities=velocities, backend=backend)

    def to_transfer_function(
        self,
        *,
        inputs: Any = None,
        outputs: Any = None,
        values: Mapping[Any, Any] | None = None,
        velocities: bool = False,
        backend: str = "auto",
    ) -> Any:
        """Transfer function(s) from the inputs to the outputs (arguments as :meth:`to_state_space`).

        ``control.TransferFunction`` (MIMO allowed, signals named as in :meth:`to_state_space`) with python-control,
        else ``scipy.signal.TransferFunction`` (one input).  The coefficients are those of the exact
        :meth:`transfer_function`, normalised to a monic denominator exactly and rounded once, at the end: no
        round-off coefficients where the exact answer has none.

        Parameters
        ----------
        inputs : coordinates, indices or array (n, m), optional
            Where the inputs act: a unit generalized force on each listed coordinate (given by Symbol, name or index;
            default every coordinate), or a force-distribution matrix ``E`` with one row per coordinate.
        outputs : coordinates, indices or array (n, p), optional
            The measured coordinates (default: all); ``velocities=True`` measures their rates instead.
        values : mapping of Symbol or str to float, optional
            Numbers for every parameter (keyed by Symbol or name); every parameter of M, D and K must get one, and K
            must not depend on time.
        velocities : bool, optional
            Whether the outputs are the rates ``q'`` of the measured coordinates instead of the coordinates (default
            False).
        backend : {"auto", "control", "scipy"}, optional
            ``control.TransferFunction`` when python-control is installed (``"auto"``) or asked for (``"control"``),
            else ``scipy.signal.TransferFunction`` (one input only); default "auto".

        Examples
        --------
        >>> from symosc.models import n_link_pendulum
        >>> lin = n_link_pendulum(1).linearize()
        >>> H = lin.to_transfer_function(values={"m1": 2.0, "l1": 1.0, "g": 9.81}, backend="scipy")
        >>> H.num.round(12).tolist(), H.den.round(12).tolist()      # 1 / (m l^2 s^2 + m g l)
        ([0.5], [1.0, 0.0, 9.81])

        See Also
        --------
        to_state_space, symosc.operational.to_transfer_function
        """
        from ._control import transfer_function

        return transfer_function(
            self, inputs=inputs, outputs=outputs, values=values, velocities=velocities, backend=backend
        )

    # ------------------------------------------------------------------ damped/gyroscopic and periodic analysis
    def complex_modes(self, values: Mapping[Any, Any]) -> Any:
        """Roots ``s`` and complex mode shapes of ``(M s**2 + D s + K0) phi = 0``, damping and gyroscopic terms kept.

        Returns a :class:`~symosc.mechanics._quadratic.ComplexModes`; see
        :func:`symosc.mechanics._quadratic.complex_modes` for the method (companion pencil, QZ).

        Parameters
        ----------
        values : mapping of Symbol or str to float
            Numbers for every parameter of the model (keys are symbols or their names), scalars only; a missing or
            non-finite value raises ParameterError.

        Examples
        --------
        >>> from symosc.models import n_link_pendulum
        >>> lin = n_link_pendulum(1).linearize()
        >>> lin.complex_modes({"m1": 1, "l1": 1, "g": 4}).frequencies.round(12).tolist()
        [2.0]
        """
        from ._quadratic import model_complex_modes

        return model_complex_modes(self, values)

    def monodromy(self, values: Mapping[Any, Any], **kwargs: Any) -> Any:
        """Floquet analysis of ``M q'' + D q' + (K0 + K1 cos(p t)) q = 0`` over one period ``2 pi / p``.

        Builds ``x' = A(t) x`` with ``x = (q, q')`` and calls :func:`symosc.periodic.monodromy` (keyword
        arguments are passed on; for ``D = 0`` the half-period reversor is used).  Returns its
        :class:`~symosc.periodic.FloquetResult`.

        Parameters
        ----------
        values : mapping of Symbol or str to float
            Numbers for every parameter of the model, the excitation frequency ``p`` included (keys are symbols or their
            names), scalars only; ``p`` must be positive.

        Examples
        --------
        >>> from symosc.models import n_link_pendulum
        >>> lin = n_link_pendulum(1, inverted=True, pivot="vertical").linearize()
        >>> lin.monodromy({"m1": 1, "l1": 1, "g": 9.81, "a": 0.02, "p": 300}).stability   # Kapitza
        'stable'
        """
        from ._quadratic import periodic_monodromy

        return periodic_monodromy(self, values, **kwargs)


def _frequencies(lam: np.ndarray) -> np.ndarray:
    scale = np.max(np.abs(lam), axis=-1, keepdims=True)
    tiny = 1e-12 * np.where(scale == 0, 1.0, scale)
    if np.any(lam < -tiny):
        raise ModelError(
            "the equilibrium is statically unstable (negative stiffness eigenvalues "
            f"{lam[lam < -tiny].tolist()}): natural frequencies are imaginary; use eigenvalues()"
        )
    return np.sqrt(np.clip(lam, 0.0, None))


def _point_map(system: LagrangianSystem, point: Mapping[Any, Any] | None) -> dict[sp.Symbol, sp.Expr]:
    q0 = {q: sp.S.Zero for q in system.coordinates}
    by_name = {q.name: q for q in system.coordinates}
    for key, val in (point or {}).items():
        name = key.name if isinstance(key, sp.Symbol) else str(key)
        if name not in by_name:
            raise ModelError(f"linearization point names {name!r}, which is not a coordinate")
        q0[by_name[name]] = sp.sympify(val)
    return q0


def linearize_system(
    system: LagrangianSystem, point: Mapping[Any, Any] | None, *, check_equilibrium: bool = True
) -> LinearModel:
    """Implementation of :meth:`LagrangianSystem.linearize` (see there)."""
    q, qd = system.coordinates, system.velocities
    n = len(q)
    q0 = _point_map(system, point)
    at = {**q0, **{v: sp.S.Zero for v in qd}}

    parts = system._parts
    dep = system._dependent
    qt = [*q, t]

    # Damping: gyroscopic part of b (T = 1/2 q'Mq' + b.q' + T0), dM/dt, Rayleigh, velocity-dependent forces.
    D = sp.zeros(n, n)
    db_dt: list[list[sp.Expr]] = [[] for _ in range(n)]
    for i in range(n):
        grads = _terms.grouped_gradient(parts.get((i,), []), qt)
        db_dt[i] = grads[n]
        for j in range(n):
            if grads[j]:
                c = sp.Add(*grads[j])
                D[i, j] += c
                D[j, i] -= c
    M = system.mass_matrix
    R, Q = system.dissipation, system.forces
    for i in range(n):
        for j in range(n):
            extra = M[i, j].diff(t) if t in M[i, j].free_symbols else 0
            if R != 0:
                extra += R.diff(qd[i], qd[j])
            if Q[i] != 0:
                extra -= Q[i].diff(qd[j])
            D[i, j] += extra

    # Stiffness: K = dW/dq at the point with W = dV/dq - dT0/dq + db/dt - Q; f = -W at the point.
    dV = _terms.grouped_gradient(system._potential_groups, q)
    dT0 = _terms.grouped_gradient(parts.get((), []), q)
    K = sp.zeros(n, n)
    f = sp.zeros(n, 1)
    for i in range(n):
        W = sp.Add(*dV[i]) - sp.Add(*dT0[i]) + sp.Add(*db_dt[i]) - Q[i]
        grads = _terms.grouped_gradient(_terms.group_terms(_terms.expand_terms(W, dep), dep), q)
        for j in range(n):
            if grads[j]:
                K[i, j] = sp.Add(*grads[j]).xreplace(at)
        f[i] = -W.xreplace(at)

    lin = LinearModel(M=M.xreplace(at), D=D.xreplace(at), K=K, f=f, coordinates=tuple(q), point=dict(q0))
    if check_equilibrium:
        for i in range(n):
            fi = f[i]
            if fi != 0 and t not in fi.free_symbols and sp.simplify(fi) != 0:
                raise ModelError(
                    f"the point {q0} is not an equilibrium: the generalised force on {q[i].name} is {fi}; "
                    "pass check_equilibrium=False to linearize anyway"
                )
    return lin


def _expandable(term: sp.Expr) -> bool:
    """False when ``sp.expand(term)`` would return ``term`` unchanged: no sum, no power of a compound base and no
    logarithm anywhere in it (most terms of a large stiffness matrix are plain products)."""
    return any(
        node.is_Add or isinstance(node, sp.log) or (node.is_Pow and not node.base.is_Atom)
        for node in sp.preorder_traversal(term)
    )


def _split_time(term: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``term.as_independent(t, as_Add=False)`` without re-sorting: the factors of a product are already in order,
    so each group is built from them directly."""
    if not term.is_Mul:
        return (sp.S.One, term) if t in term.free_symbols else (term, sp.S.One)
    groups: tuple[list, list] = ([], [])
    for factor in term.args:
        groups[t in factor.free_symbols].append(factor)
    return tuple(g[0] if len(g) == 1 else sp.Mul._from_args(g) if g else sp.S.One for g in groups)
