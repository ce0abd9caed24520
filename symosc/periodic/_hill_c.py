"""The per-point Mathieu kernel of :mod:`symosc.periodic._hill_batch` in C (private).

One C function refines a whole batch of seeds (matrix size choice, twisted factorisation, Rayleigh-quotient steps,
pivot count, error bounds -- the operations of :func:`symosc.periodic._hill_batch.refine_scalar`), one evaluates the
initial approximations of :mod:`symosc.periodic._mathieu_seed`, and one runs the whole common case of method "auto"
(own value, nearly degenerate neighbours, ordering clamp) for a plan.  Scalar calls go through the
same C code, so scalar and vectorised results have the same bits.  The library is compiled once with the C
backend's build cache (:mod:`symosc.numeric._build`); without a C compiler (or with ``SYMOSC_MATHIEU_KERNEL=numpy``)
:func:`kernel` returns None and the NumPy implementation runs instead.
"""

from __future__ import annotations

import ctypes
import math
import os

import numpy as np

from ._hill_c_fourier import FOURIER_SOURCE
from ._hill_c_source import EXTENSION, SOURCE

_PTR = ctypes.POINTER(ctypes.c_double)
_state: dict = {}


class _Fast:
    """The scalar fast path of ``mathieu_a/b``: ``value(is_b, n, q)`` is kind_n(q) for a plan registered by
    ``register(is_b, n, plan)``, nan otherwise (None without the C kernel).  A CPython extension where the
    interpreter's headers are found, else a ctypes call (about 0.6 us more)."""

    value = None
    register = None


FAST = _Fast()


def kernel():
    """The loaded C library, or None (no C compiler, or ``SYMOSC_MATHIEU_KERNEL=numpy``); decided once."""
    try:
        return _state["lib"]
    except KeyError:
        pass
    lib = None
    if os.environ.get("SYMOSC_MATHIEU_KERNEL", "").lower() != "numpy":
        from ..numeric._build import CompilerError, load

        try:
            lib = load(SOURCE + FOURIER_SOURCE)
        except CompilerError:
            lib = None
    if lib is not None:
        lib.symosc_mathieu_refine.restype = ctypes.c_int
        lib.symosc_mathieu_refine.argtypes = (
            [ctypes.c_int] * 4 + [ctypes.c_long] + [ctypes.c_void_p] * 2 + [ctypes.c_double] + [ctypes.c_void_p] * 3
        )
        lib.symosc_mathieu_refine1.restype = ctypes.c_double
        lib.symosc_mathieu_refine1.argtypes = [ctypes.c_int] * 4 + [ctypes.c_double] * 3 + [_PTR]
        lib.symosc_mathieu_seeds.restype = None
        lib.symosc_mathieu_seeds.argtypes = [ctypes.c_void_p, ctypes.c_long, ctypes.c_void_p, ctypes.c_void_p]
        lib.symosc_mathieu_auto.restype = ctypes.c_int
        lib.symosc_mathieu_auto.argtypes = [ctypes.c_void_p, ctypes.c_long, ctypes.c_void_p, ctypes.c_double] + [
            ctypes.c_void_p
        ] * 3
        lib.symosc_mathieu_auto1.restype = ctypes.c_double
        lib.symosc_mathieu_auto1.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_void_p]
        lib.symosc_mathieu_coefficients.restype = ctypes.c_int
        lib.symosc_mathieu_coefficients.argtypes = (
            [ctypes.c_int] * 4 + [ctypes.c_long] + [ctypes.c_void_p] * 3 + [ctypes.c_double] + [ctypes.c_int] * 2
            + [ctypes.c_void_p] * 8
        )  # fmt: skip
        lib.symosc_mathieu_hill_sc.restype = None
        lib.symosc_mathieu_hill_sc.argtypes = [ctypes.c_long] + [ctypes.c_void_p] * 8
        lib.symosc_mathieu_sum_eps.restype = ctypes.c_double
        lib.symosc_mathieu_sum_eps.argtypes = []
        lib.symosc_mathieu_fourier_sum.restype = None
        lib.symosc_mathieu_fourier_sum.argtypes = (
            [ctypes.c_int] * 3 + [ctypes.c_long] + [ctypes.c_void_p] * 3 + [ctypes.c_int] + [ctypes.c_void_p] * 2
        )
        _fast_path(lib)
    _state["lib"] = lib
    return lib


def _extension(lib):
    """The extension module of ``EXTENSION`` wired to ``lib``, or None (no Python headers, or it does not build)."""
    import importlib.machinery
    import importlib.util
    import sysconfig

    from ..numeric._build import CompilerError, load

    header = os.path.join(sysconfig.get_paths()["include"], "Python.h")
    if not os.path.isfile(header) or '"' in header:
        return None
    try:
        path = load(EXTENSION.replace("{python_h}", header))._name
        loader = importlib.machinery.ExtensionFileLoader("_symosc_mathieu", path)
        spec = importlib.util.spec_from_file_location("_symosc_mathieu", path, loader=loader)
        module = importlib.util.module_from_spec(spec)
        loader.exec_module(module)
    except (CompilerError, ImportError, OSError):
        return None
    module.set_kernel(ctypes.cast(lib.symosc_mathieu_auto1, ctypes.c_void_p).value)
    return module


def _fast_path(lib) -> None:
    ext = _extension(lib)
    if ext is not None:
        FAST.value = ext.value
        FAST.register = lambda is_b, n, plan: ext.register(is_b, n, plan.ctypes.data)
        return
    plans: dict[tuple[int, int], int] = {}
    call = lib.symosc_mathieu_auto1

    def value(is_b: int, n: int, q: float) -> float:
        if q < 0.0:
            q = -q
            if n % 2:
                is_b = 1 - is_b
        address = plans.get((is_b, n))
        if address is None or not q < math.inf:
            return math.nan
        return call(address, q, 1e-13, None)

    def register(is_b: int, n: int, plan: np.ndarray) -> None:
        plans[is_b, n] = plan.ctypes.data

    FAST.value = value
    FAST.register = register


def reset() -> None:
    """Forget the decision of :func:`kernel` (the tests switch between the C and NumPy kernels)."""
    _state.clear()
    FAST.value = FAST.register = None


def refine(lib, fam, k: int, q: np.ndarray, x: np.ndarray, tol: float):
    """(values, errors, accepted) for contiguous float64 arrays q, x."""
    q = np.ascontiguousarray(q, dtype=float)
    x = np.ascontiguousarray(x, dtype=float)
    value = np.empty(q.shape)
    err = np.empty(q.shape)
    ok = np.empty(q.shape, dtype=np.uint8)
    status = lib.symosc_mathieu_refine(
        fam.offset, fam.q_sign, int(fam.sqrt2), k, q.size, q.ctypes.data, x.ctypes.data, tol,
        value.ctypes.data, err.ctypes.data, ok.ctypes.data,
    )  # fmt: skip
    if status:
        raise MemoryError("the Mathieu kernel could not allocate its work array")
    return value, err, ok.view(bool)


def refine1(lib, fam, k: int, q: float, x: float, tol: float) -> tuple[float, float, bool]:
    err = ctypes.c_double()
    value = lib.symosc_mathieu_refine1(fam.offset, fam.q_sign, fam.sqrt2, k, q, x, tol, err)
    return value, err.value, value == value


def seeds(lib, table: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Initial approximations from a seed table (see :mod:`symosc.periodic._mathieu_seed`) at a 1-d float64 q."""
    q = np.ascontiguousarray(q, dtype=float)
    out = np.empty(q.shape)
    lib.symosc_mathieu_seeds(table.ctypes.data, q.size, q.ctypes.data, out.ctypes.data)
    return out


def auto(lib, plan: np.ndarray, q: np.ndarray, tol: float):
    """(values, errors, done) of the whole "auto" method for one plan; ``done`` False: use the general path."""
    q = np.ascontiguousarray(q, dtype=float)
    value = np.empty(q.shape)
    err = np.empty(q.shape)
    ok = np.empty(q.shape, dtype=np.uint8)
    status = lib.symosc_mathieu_auto(plan.ctypes.data, q.size, q.ctypes.data, tol, value.ctypes.data,
                                     err.ctypes.data, ok.ctypes.data)  # fmt: skip
    if status:
        raise MemoryError("the Mathieu kernel could not allocate its work array")
    return value, err, ok.view(bool)
