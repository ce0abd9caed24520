"""Sensitivity of identified parameters: Jacobian, elasticities and first-order error bounds (Belyakov Ch. III §3.1).

Generic over a user function ``Phi(xi)``: the Jacobian is computed by the complex step ``Im f(x + i h e_j) / h``
(exact to rounding when ``f`` is complex-analytic) or by Richardson-extrapolated central differences, and the step
is checked: with ``method="auto"`` the complex step is compared against central differences and abandoned (with a
warning) when they disagree, e.g. because ``f`` takes moduli or casts to float.

Elasticities ``E_ij = (dPhi_i/dxi_j) xi_j / Phi_i`` are relative sensitivities; the first-order relative error
bound for relative input errors <= eps is ``sum_j |E_ij| eps`` (Belyakov's bound).  Note that the
thesis's "<= 2 eps" holds per argument (max_j |E_ij| = 2 at its data point), not for the sum.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, fields, is_dataclass
from typing import Any

import numpy as np

from .._printing import SymPyPrintable
from .._validate import validated
from ..errors import ParameterError, warn

__all__ = ["JacobianResult", "jacobian", "sensitivity"]


@dataclass(frozen=True, repr=False, eq=False)
class JacobianResult(SymPyPrintable):
    """Jacobian of ``f`` at ``x`` with elasticities and a numerical error estimate.

    Attributes
    ----------
    x, value : ndarray
        Point (n,) and function value (m,).
    jacobian : ndarray, shape (m, n)
    method : str
        ``"complex"`` or ``"central"``.
    step : ndarray
        Steps used per argument.
    error_estimate : float
        Largest absolute discrepancy found by the step check (complex vs central, or h vs 2h).
    input_names, output_names : tuple of str
    """

    x: np.ndarray
    value: np.ndarray
    jacobian: np.ndarray
    method: str
    step: np.ndarray
    error_estimate: float
    input_names: tuple[str, ...]
    output_names: tuple[str, ...]

    @property
    def elasticities(self) -> np.ndarray:
        """``E_ij = J_ij x_j / f_i`` (NaN where f_i = 0)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            e = self.jacobian * self.x[None, :] / self.value[:, None]
        return np.where(self.value[:, None] == 0, np.nan, e)

    @property
    def sum_elasticities(self) -> np.ndarray:
        """``sum_j |E_ij|``: first-order relative error of f_i per unit relative error of every input."""
        return np.nansum(np.abs(self.elasticities), axis=1)

    @property
    def max_elasticities(self) -> np.ndarray:
        """``max_j |E_ij|``: worst single-argument relative sensitivity."""
        return np.nanmax(np.abs(self.elasticities), axis=1)

    def error_bound(self, relative_error: float | Sequence[float]) -> np.ndarray:
        """First-order relative error bound of each output for relative input errors ``relative_error``.

        Parameters
        ----------
        relative_error : float or sequence of float, shape (n,)
            Bound(s) on the relative error of the inputs: one non-negative number for all inputs, or one per input.

        Returns
        -------
        ndarray, shape (m,)
            ``sum_j |E_ij| eps_j`` per output.
        """
        eps = np.broadcast_to(np.asarray(relative_error, dtype=float), self.x.shape)
        return np.nansum(np.abs(self.elasticities) * eps[None, :], axis=1)

    def __repr__(self) -> str:
        head = (
            f"JacobianResult(method={self.method!r}, shape={self.jacobian.shape}, "
            f"error_estimate={self.error_estimate:.2g})"
        )
        rows = [f"  {'output':>10} {'value':>14} {'sum|E|':>9} {'max|E|':>9}  most sensitive to"]
        el = self.elasticities
        for i, name in enumerate(self.output_names):
            j = int(np.nanargmax(np.abs(el[i]))) if np.any(np.isfinite(el[i])) else 0
            rows.append(
                f"  {name:>10} {self.value[i]:>14.8g} {self.sum_elasticities[i]:>9.4g} {self.max_elasticities[i]:>9.4g}"
                f"  {self.input_names[j]} ({el[i, j]:+.4g})"
            )
        return "\n".join([head, *rows])


def _flatten_output(out: Any) -> tuple[np.ndarray, tuple[str, ...] | None]:
    if isinstance(out, Mapping):
        names = tuple(str(k) for k in out)
        return np.array([out[k] for k in out]).ravel(), names
    if is_dataclass(out) and not isinstance(out, type):
        names, vals = [], []
        for f in fields(out):
            v = getattr(out, f.name)
            if isinstance(v, (int, float, complex, np.number)) and not isinstance(v, bool):
                names.append(f.name)
                vals.append(v)
        if not vals:
            raise ParameterError(f"{type(out).__name__} has no scalar numeric fields to differentiate")
        return np.array(vals).ravel(), tuple(names)
    return np.atleast_1d(np.asarray(out)).ravel(), None


@validated
def jacobian(
    func: Callable[..., Any],
    x: Any,
    *,
    method: str = "auto",
    step: float | None = None,
    args: Sequence[Any] = (),
    kwargs: Mapping[str, Any] | None = None,
    input_names: Sequence[str] | None = None,
    output_names: Sequence[str] | None = None,
    rtol: float = 1e-6,
) -> JacobianResult:
    """Jacobian of ``func(x, *args, **kwargs)`` at ``x`` with a step check.

    Parameters
    ----------
    func : callable
        ``func(x, *args, **kwargs)``: the function to differentiate; must return a scalar, a 1-D array, a mapping
        name -> number, or a dataclass (its scalar fields).
    x : array_like, shape (n,)
        Point of differentiation: finite real numbers (flattened to a 1-D array).
    method : {"auto", "complex", "central"}
        ``"complex"``: complex step (needs a complex-analytic ``func``), verified against central differences;
        raises if they disagree.  ``"central"``: Richardson-extrapolated central differences with error estimate
        from steps h and 2h.  ``"auto"``: complex step if it passes the check, else central (with a warning).
    step : float, optional
        Relative step (default 1e-20 for the complex step, 1e-4 for central differences) times ``max(|x_j|, 1e-8)``.
    args : sequence, optional
        Extra positional arguments passed to ``func`` after ``x``.
    kwargs : mapping of str to object, optional
        Extra keyword arguments passed to ``func``.
    input_names : sequence of str, optional
        Names of the ``n`` inputs, one per entry of ``x`` (default ``"x0", "x1", ...``).
    output_names : sequence of str, optional
        Names of the ``m`` outputs, one per value of ``func`` (default: the keys or field names ``func`` returns,
        else ``"f0", "f1", ...``).
    rtol : float
        Agreement required between complex step and central differences, relative to ``max |J|``.

    Examples
    --------
    >>> import numpy as np
    >>> res = jacobian(lambda v: [v[0] ** 2 * v[1], np.sin(v[1])], [3.0, 0.5])
    >>> res.method, np.round(res.jacobian, 12).tolist()
    ('complex', [[3.0, 9.0], [0.0, 0.87758256189]])
    >>> np.round(res.elasticities[0], 12).tolist()  # f = x0^2 x1: elasticities 2 and 1
    [2.0, 1.0]
    """
    if method not in {"auto", "complex", "central"}:
        raise ParameterError(f"method must be 'auto', 'complex' or 'central', got {method!r}")
    x = np.atleast_1d(np.asarray(x, dtype=float)).ravel()
    if not np.all(np.isfinite(x)):
        raise ParameterError("jacobian: x must be finite")
    kw = dict(kwargs or {})

    def f(v: np.ndarray) -> tuple[np.ndarray, tuple[str, ...] | None]:
        return _flatten_output(func(v, *args, **kw))

    f0, names = f(x)
    if np.iscomplexobj(f0):
        if np.any(f0.imag != 0):
            raise ParameterError("jacobian: func returned complex values at a real point")
        f0 = f0.real
    f0 = f0.astype(float)
    n, m = x.size, f0.size
    scale = np.maximum(np.abs(x), 1e-8)

    def central(h: np.ndarray) -> np.ndarray:
        jac = np.empty((m, n))
        for j in range(n):
            e = np.zeros(n)
            e[j] = h[j]
            jac[:, j] = (f(x + e)[0].real - f(x - e)[0].real) / (2 * h[j])
        return jac

    hc = (1e-4 if step is None or method == "complex" else float(step)) * scale
    j1, j2 = central(hc), central(2 * hc)
    jc = (4 * j1 - j2) / 3
    err_c = float(np.max(np.abs(j1 - j2))) if j1.size else 0.0
    used, jac, err, hs = "central", jc, err_c, hc
    if method in {"auto", "complex"}:
        hx = (1e-20 if step is None or method == "central" else float(step)) * scale
        jx = np.empty((m, n))
        ok = True
        try:
            for j in range(n):
                e = np.zeros(n, dtype=complex)
                e[j] = 1j * hx[j]
                with warnings.catch_warnings():
                    warnings.simplefilter("error", np.exceptions.ComplexWarning)
                    val, _ = f(x + e)
                if not np.iscomplexobj(val):
                    ok = False
                    break
                jx[:, j] = val.imag / hx[j]
        except (TypeError, ValueError, np.exceptions.ComplexWarning):
            ok = False
        floor = 1e-12 * float(np.max(np.abs(f0), initial=0.0)) / float(np.max(scale))
        tol = rtol * float(np.max(np.abs(jc), initial=0.0)) + 10 * err_c + floor
        diff = float(np.max(np.abs(jx - jc))) if ok else np.inf
        if ok and diff <= tol:
            used, jac, err, hs = "complex", jx, diff, hx
        elif method == "complex":
            raise ParameterError(
                "jacobian: the complex step disagrees with central differences "
                f"(max difference {diff:.3g}); func is not complex-analytic (abs, float casts, branches?). "
                "Use method='central'"
            )
        else:
            warn(f"jacobian: complex step unusable (difference {diff:.3g}); using central differences", RuntimeWarning)
    in_names = tuple(input_names) if input_names is not None else tuple(f"x{j}" for j in range(n))
    out_names = tuple(output_names) if output_names is not None else (names or tuple(f"f{i}" for i in range(m)))
    if len(in_names) != n or len(out_names) != m:
        raise ParameterError(f"expected {n} input names and {m} output names")
    return JacobianResult(
        x=x,
        value=f0,
        jacobian=jac,
        method=used,
        step=hs,
        error_estimate=err,
        input_names=in_names,
        output_names=out_names,
    )


@validated
def sensitivity(
    func: Callable[..., Any],
    frequencies: Any,
    amplitudes: Any,
    *,
    args: Sequence[Any] = (),
    kwargs: Mapping[str, Any] | None = None,
    method: str = "auto",
    output_names: Sequence[str] | None = None,
) -> JacobianResult:
    """Jacobian and elasticities of ``func(frequencies, amplitudes, *args, **kwargs)`` with respect to the
    identified frequencies (n,) and modal amplitudes C' (sensors x n), in the order
    ``omega_1..omega_n, C'_11, C'_12, ..., C'_ln`` (row by row, as in Belyakov's 18-vector without p, Lx, Lz).

    Parameters
    ----------
    func : callable
        ``func(frequencies, amplitudes, *args, **kwargs)``: the reconstruction to differentiate; must return a
        scalar, a 1-D array, a mapping name -> number, or a dataclass (its scalar fields), e.g. an
        :class:`InertiaEstimate`.
    frequencies : array_like, shape (n,)
        Identified natural frequencies (rad/s) at which to differentiate; finite real numbers.
    amplitudes : array_like, shape (sensors, n)
        Modal amplitudes ``C'`` (one column per frequency); finite real numbers.
    args : sequence, optional
        Extra positional arguments passed to ``func`` after the amplitudes (e.g. force and positions).
    kwargs : mapping of str to object, optional
        Extra keyword arguments passed to ``func``.
    method : {"auto", "complex", "central"}
        Differentiation method (see :func:`jacobian`); ``"auto"`` (default) tries the complex step first.
    output_names : sequence of str, optional
        Names of the outputs, one per value of ``func`` (default: the keys or field names ``func`` returns).

    Returns
    -------
    JacobianResult
        Inputs named ``omega1, ..., C'11, C'12, ...``.

    See Also
    --------
    jacobian

    Examples
    --------
    Uncoupled body on equal springs: m = 4 k / omega_1**2 has elasticity -2 with respect to omega_1.

    >>> import numpy as np
    >>> res = sensitivity(lambda w, c: {"m": 4 * 740000.0 / w[0] ** 2}, [14.0, 16.0], np.ones((4, 2)))
    >>> np.round(res.elasticities[0, :2], 12).tolist(), res.input_names[:3]
    ([-2.0, 0.0], ('omega1', 'omega2', "C'11"))
    """
    w = np.atleast_1d(np.asarray(frequencies, dtype=float))
    c = np.atleast_2d(np.asarray(amplitudes, dtype=float))
    if c.shape[1] != w.size:
        raise ParameterError(f"amplitudes must have shape (sensors, {w.size}), got {c.shape}")
    k = w.size

    def wrapped(v: np.ndarray, *a: Any, **kw: Any) -> Any:
        return func(v[:k], v[k:].reshape(c.shape), *a, **kw)

    names = [f"omega{i + 1}" for i in range(k)] + [f"C'{i + 1}{j + 1}" for i in range(c.shape[0]) for j in range(k)]
    return jacobian(
        wrapped,
        np.concatenate([w, c.ravel()]),
        method=method,
        args=args,
        kwargs=kwargs,
        input_names=names,
        output_names=output_names,
    )
