"""Right-hand side and Jacobian of ``M(q, t) q'' = F(q, q', t)`` in first-order form, for NumPy and C.

The state is ``y = (q, u)`` with ``u = q'``; ``f(t, y) = (u, M^{-1} F)`` and its Jacobian is
``[[0, I], [M^{-1} (dF/dy - (dM/dy) M^{-1} F)]]``.  The C backend evaluates M and F (and the derivatives) from
CSE'd expressions and solves with Gaussian elimination with partial pivoting in the same call.
"""

from __future__ import annotations

import ctypes
from typing import Any

import numpy as np
import sympy as sp

from ..errors import ModelError
from . import _build, _c
from ._core import _argument_names, compile


def _pieces(M: sp.Matrix, F: sp.Matrix, y: list[sp.Symbol], jacobian: bool):
    """Flat expression list [M, F, (dF/dy, nonzero dM/dy)] and the index list of the nonzero dM/dy_j entries."""
    n = M.shape[0]
    items = list(M) + list(F)
    dm_index: list[tuple[int, int, int]] = []
    if jacobian:
        items += [sp.diff(F[i], v) for i in range(n) for v in y]
        for j, v in enumerate(y):
            for r in range(n):
                for c in range(n):
                    d = sp.diff(M[r, c], v)
                    if d != 0:
                        dm_index.append((j, r, c))
                        items.append(d)
    return items, dm_index


def numpy_parts(M, F, t, q, u, params, jacobian: bool) -> tuple[Any, list]:
    """The compiled NumPy function of the flat pieces, and the dM/dy index list (see :func:`_pieces`)."""
    y = [*q, *u]
    items, dm_index = _pieces(M, F, y, jacobian)
    name = "first_order_jacobian" if jacobian else "first_order_rhs"
    return compile(items, [t, *y, *params], check=False, name=name), dm_index


class NumpyFirstOrder:
    """f(t, y) and df/dy with NumPy: compiled M, F (and derivatives), LAPACK solves; batched over y's columns."""

    def __init__(self, parts: tuple[Any, list], n: int, values: list[float]) -> None:
        self.fn, self.dm_index = parts
        self.n, self.nm = n, n * n
        self.raw = self.fn.raw
        self.params = list(values)

    def _eval(self, t: float, y: np.ndarray) -> np.ndarray:
        return self.raw(float(t), *y, *self.params)

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        n, nm = self.n, self.nm
        vals = self._eval(t, y)
        if y.ndim == 1:
            M, F = vals[:nm].reshape(n, n), vals[nm : nm + n]
            try:
                qdd = np.linalg.solve(M, F)
            except np.linalg.LinAlgError as exc:
                raise ModelError(f"mass matrix is singular at t={t}, state={y.tolist()}") from exc
            return np.concatenate([y[n:], qdd])
        M, F = vals[:, :nm].reshape(-1, n, n), vals[:, nm : nm + n]
        try:
            qdd = np.linalg.solve(M, F[..., None])[..., 0]
        except np.linalg.LinAlgError as exc:
            raise ModelError(f"mass matrix is singular at t={t} for one of the states") from exc
        return np.concatenate([y[n:], qdd.T])

    def jacobian(self, t: float, y: np.ndarray) -> np.ndarray:
        n, nm = self.n, self.nm
        vals = self._eval(t, y)
        M, F = vals[:nm].reshape(n, n), vals[nm : nm + n]
        dF = vals[nm + n : nm + n + 2 * n * n].reshape(n, 2 * n)
        dM = np.zeros((2 * n, n, n))
        for (j, r, c), v in zip(self.dm_index, vals[nm + n + 2 * n * n :], strict=True):
            dM[j, r, c] = v
        try:
            qdd = np.linalg.solve(M, F)
            X = np.linalg.solve(M, dF - np.einsum("jrc,c->rj", dM, qdd))
        except np.linalg.LinAlgError as exc:
            raise ModelError(f"mass matrix is singular at t={t}, state={y.tolist()}") from exc
        J = np.zeros((2 * n, 2 * n))
        J[:n, n:] = np.eye(n)
        J[n:] = X
        return J


_SOLVE = """\
/* Solve A X = B in place (A n x n, B n x nrhs, both row-major) by Gaussian elimination with partial
   pivoting; returns 1 when A is singular (or not finite), 0 otherwise. */
static int symosc_solve(int n, double *A, double *B, int nrhs)
{
    for (int c = 0; c < n; c++) {
        int piv = c;
        double best = fabs(A[c * n + c]);
        for (int r = c + 1; r < n; r++) {
            double v = fabs(A[r * n + c]);
            if (v > best) { best = v; piv = r; }
        }
        if (!(best > 0.0) || !isfinite(best)) return 1;
        if (piv != c) {
            for (int k = 0; k < n; k++) { double s = A[c * n + k]; A[c * n + k] = A[piv * n + k]; A[piv * n + k] = s; }
            for (int k = 0; k < nrhs; k++) {
                double s = B[c * nrhs + k]; B[c * nrhs + k] = B[piv * nrhs + k]; B[piv * nrhs + k] = s;
            }
        }
        for (int r = c + 1; r < n; r++) {
            double f = A[r * n + c] / A[c * n + c];
            if (f != 0.0) {
                for (int k = c + 1; k < n; k++) A[r * n + k] -= f * A[c * n + k];
                for (int k = 0; k < nrhs; k++) B[r * nrhs + k] -= f * B[c * nrhs + k];
            }
        }
    }
    for (int r = n - 1; r >= 0; r--) {
        for (int k = 0; k < nrhs; k++) {
            double s = B[r * nrhs + k];
            for (int j = r + 1; j < n; j++) s -= A[r * n + j] * B[j * nrhs + k];
            B[r * nrhs + k] = s / A[r * n + r];
        }
    }
    return 0;
}
"""

_RESERVED = frozenset({"symosc_solve"})


def c_first_order_source(M, F, t, q, u, params, *, jacobian: bool = False, name: str = "symosc_ode") -> str:
    """C99 source with ``{name}_rhs`` and ``{name}_rhs_batch``, or ``{name}_jac`` (see the header comment)."""
    n = M.shape[0]
    y = [*q, *u]
    syms = [t, *y, *params]
    py_names = _argument_names(syms)
    names = _c.c_names(py_names, _RESERVED)
    rename = {s: sp.Symbol(c, **s.assumptions0) for s, c in zip(syms, names, strict=True)}
    printer = _c.C99CodePrinter()

    def body(items: list[sp.Expr], targets: list[str]) -> list[str]:
        items = [e.xreplace(rename) for e in items]
        repl, reduced = sp.cse(items, symbols=sp.numbered_symbols("_c"), optimizations=None, order="none")
        lines = ["    const double " + f"{names[0]} = _t;"]
        lines += [f"    const double {c} = _y[{i}];" for i, c in enumerate(names[1 : 1 + 2 * n])]
        lines += [f"    const double {c} = _p[{i}];" for i, c in enumerate(names[1 + 2 * n :])]
        lines += [f"    const double {s} = {_c.printed(printer, e)};" for s, e in repl]
        lines += [f"    {tg} = {_c.printed(printer, e)};" for tg, e in zip(targets, reduced, strict=True)]
        return lines

    mf_targets = [f"_M[{i}]" for i in range(n * n)] + [f"_F[{i}]" for i in range(n)]
    if jacobian:
        items, dm_index = _pieces(M, F, y, True)
        jac_targets = mf_targets + [f"_R[{i}]" for i in range(2 * n * n)]
        jac_targets += [f"_dM[{j * n * n + r * n + c}]" for j, r, c in dm_index]
        jac_body, rhs_body = body(items, jac_targets), []
    else:
        # M is symmetric for a Lagrangian system: generate the upper triangle only and mirror it in C.
        upper = [(i, j) for i in range(n) for j in range(i, n)]
        if all(M[i, j] == M[j, i] for i, j in upper):
            targets = [f"_M[{i * n + j}]" for i, j in upper] + [f"_F[{i}]" for i in range(n)]
            rhs_body = body([M[i, j] for i, j in upper] + list(F), targets)
            rhs_body += [f"    _M[{j * n + i}] = _M[{i * n + j}];" for i, j in upper if i != j]
        else:
            rhs_body = body(list(M) + list(F), mf_targets)
        jac_body = []
    listing = ", ".join(s.name for s in params) or "none"
    header = [
        "/* Generated by symosc (FirstOrderSystem, backend 'c'): y' = f(t, y) for M(q, t) q'' = F(q, q', t).",
        f"   State y = ({', '.join(s.name for s in y)}); parameters p = ({listing}).",
        f"   int {name}_rhs(double t, const double *y, const double *p, double *dy)      dy = f(t, y), 2n = {2 * n}",
        f"   int {name}_rhs_batch(long count, double t, const double *Y, const double *p, double *dY)",
        "       Y and dY are count x 2n, row-major (one state per row).",
        f"   int {name}_jac(double t, const double *y, const double *p, double *J)       J = df/dy, 2n x 2n row-major",
        "   Each returns 0, or 1 (+ row index for the batch) when the mass matrix is singular.",
        f"   Build: cc -O2 -std=c99 -fPIC -shared -o {name}.so {name}.c -lm */",
    ]
    text = "\n".join(rhs_body + jac_body)
    rhs_src = [
        f"int {name}_rhs(double _t, const double *_y, const double *_p, double *_dy)",
        "{",
        f"    double _M[{n * n}], _F[{n}];",
        *rhs_body,
        f"    for (int i = 0; i < {n}; i++) _dy[i] = _y[{n} + i];",
        f"    if (symosc_solve({n}, _M, _F, 1)) return 1;",
        f"    for (int i = 0; i < {n}; i++) _dy[{n} + i] = _F[i];",
        "    return 0;",
        "}",
        "",
        f"int {name}_rhs_batch(long count, double _t, const double *_Y, const double *_p, double *_dY)",
        "{",
        "    for (long k = 0; k < count; k++)",
        f"        if ({name}_rhs(_t, _Y + k * {2 * n}, _p, _dY + k * {2 * n})) return (int)(1 + k);",
        "    return 0;",
        "}",
        "",
    ]
    jac_src = [
        f"int {name}_jac(double _t, const double *_y, const double *_p, double *_J)",
        "{",
        f"    double _M[{n * n}], _M2[{n * n}], _F[{n}], _R[{2 * n * n}], _dM[{max(2 * n * n * n, 1)}];",
        f"    for (int i = 0; i < {max(2 * n * n * n, 1)}; i++) _dM[i] = 0.0;",
        *jac_body,
        f"    for (int i = 0; i < {n * n}; i++) _M2[i] = _M[i];",
        f"    if (symosc_solve({n}, _M2, _F, 1)) return 1;",
        f"    for (int j = 0; j < {2 * n}; j++)",
        f"        for (int r = 0; r < {n}; r++) {{",
        "            double s = 0.0;",
        f"            for (int c = 0; c < {n}; c++) s += _dM[j * {n * n} + r * {n} + c] * _F[c];",
        f"            _R[r * {2 * n} + j] -= s;",
        "        }",
        f"    if (symosc_solve({n}, _M, _R, {2 * n})) return 1;",
        f"    for (int i = 0; i < {4 * n * n}; i++) _J[i] = 0.0;",
        f"    for (int i = 0; i < {n}; i++) _J[i * {2 * n} + {n} + i] = 1.0;",
        f"    for (int i = 0; i < {2 * n * n}; i++) _J[{2 * n * n} + i] = _R[i];",
        "    return 0;",
        "}",
        "",
    ]
    return "\n".join([*header, *_c.header_lines(text), "", _SOLVE, *(jac_src if jacobian else rhs_src)])


class CFirstOrder:
    """ctypes caller of :func:`c_first_order_source`; the parameters are bound once as a C array."""

    def __init__(self, source: str, n: int, values: list[float], jacobian: bool) -> None:
        self.n = n
        self.source = source
        lib = _build.load(self.source)
        self.lib = lib
        names = ["symosc_ode_jac"] if jacobian else ["symosc_ode_rhs", "symosc_ode_rhs_batch"]
        for attr, sym in zip(["fj"] if jacobian else ["f", "fb"], names, strict=True):
            setattr(self, attr, getattr(lib, sym))
            getattr(self, attr).restype = ctypes.c_int
        self.p = (ctypes.c_double * max(len(values), 1))(*[float(v) for v in values])
        self.ytype = ctypes.c_double * (2 * n)
        self.jtype = ctypes.c_double * (4 * n * n)

    def _buffer(self, y: np.ndarray) -> Any:
        try:
            return self.ytype.from_buffer(y)
        except (TypeError, ValueError):  # read-only, non-contiguous or wrong size
            return self.ytype.from_buffer(np.array(y, dtype=float))

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        if y.ndim == 1:
            out = self.ytype()
            if self.f(ctypes.c_double(t), self._buffer(y), self.p, out):
                raise ModelError(f"mass matrix is singular at t={t}, state={y.tolist()}")
            return np.frombuffer(out)
        Y = np.ascontiguousarray(y.T, dtype=float)
        out = np.empty_like(Y)
        ptr = ctypes.c_void_p
        status = self.fb(
            ctypes.c_long(Y.shape[0]), ctypes.c_double(t), ptr(Y.ctypes.data), self.p, ptr(out.ctypes.data)
        )
        if status:
            raise ModelError(f"mass matrix is singular at t={t}, state={Y[status - 1].tolist()}")
        return out.T

    def jacobian(self, t: float, y: np.ndarray) -> np.ndarray:
        out = self.jtype()
        if self.fj(ctypes.c_double(t), self._buffer(y), self.p, out):
            raise ModelError(f"mass matrix is singular at t={t}, state={y.tolist()}")
        return np.frombuffer(out).reshape(2 * self.n, 2 * self.n)
