"""Method "auto" of :func:`symosc.periodic.mathieu_characteristic`: own seeds, verified and refined (private).

Raw values (q >= 0, no ordering clamp): the seed of :mod:`symosc.periodic._mathieu_seed` (piecewise Chebyshev in
sqrt(q), asymptotic expansion beyond), refined and verified by the kernel (C, or NumPy without a compiler); a point
the kernel does not accept (wrong index, error above target) is recomputed by the LAPACK/mpmath solvers.
The value of kind_n is then clamped into [raw lower neighbour, raw upper neighbour] inside the clamp regions of
:func:`symosc.periodic._mathieu_seed.neighbours`.  The raw value of each (kind, n, q) is a function of (kind, n, q)
only, so a_n <= b_{n+1} etc. hold exactly however the values are called, and scalar calls give the same bits as
vectorised ones (the same kernel code per point).
"""

from __future__ import annotations

import ctypes

import numpy as np

from . import _hill_c, _mathieu_seed

DEFAULT_TOL = 1e-13


def mathieu_kernel() -> str:
    """``"c"`` when the compiled kernel runs, ``"numpy"`` for the fallback (no C compiler, or
    ``SYMOSC_MATHIEU_KERNEL=numpy`` in the environment)."""
    return "numpy" if _hill_c.kernel() is None else "c"


def auto_scalar(kind: str, n: int, q: float, tol) -> tuple[float, float]:
    """kind_n(q) for one q >= 0 with the ordering clamp: the compiled common case, else :func:`general_array`."""
    lib = _hill_c.kernel()
    if lib is not None:
        err = ctypes.c_double()
        plan = _mathieu_seed.plan(kind, n)
        _hill_c.FAST.register(int(kind == "b"), n, plan)
        value = lib.symosc_mathieu_auto1(plan.ctypes.data, q, tol or DEFAULT_TOL, ctypes.byref(err))
        if value == value:
            return value, err.value
    values, errors = general_array(kind, n, np.array([q]), tol)
    return float(values[0]), float(errors[0])


def auto_array(kind: str, n: int, q: np.ndarray, tol) -> tuple[np.ndarray, np.ndarray]:
    """Vectorised :func:`auto_scalar` over a 1-d array q >= 0 (the same bits per point)."""
    lib = _hill_c.kernel()
    if lib is None:
        return general_array(kind, n, q, tol)
    values, errors, done = _hill_c.auto(lib, _mathieu_seed.plan(kind, n), q, tol or DEFAULT_TOL)
    rest = np.nonzero(~done)[0]
    if rest.size:
        values[rest], errors[rest] = general_array(kind, n, q[rest], tol)
    return values, errors


def general_array(kind: str, n: int, q: np.ndarray, tol) -> tuple[np.ndarray, np.ndarray]:
    """Raw values by the kernel and the solvers, clamped against the neighbours' raw values (the same bits per point
    as the compiled common case where that accepts a point)."""
    t = tol or DEFAULT_TOL
    values, errors = _mathieu_seed.raw(kind, n, q, t)
    lower, upper = _mathieu_seed.neighbours(kind, n)
    for nb, op in ((lower, np.maximum), (upper, np.minimum)):
        if nb is None:
            continue
        idx = np.nonzero(nb.covers(q))[0]
        if idx.size:
            values[idx] = op(values[idx], _mathieu_seed.raw(nb.kind, nb.n, q[idx], t)[0])
    return values, errors
