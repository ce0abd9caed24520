"""Right-hand side and Jacobian of ``M(q, t) q'' = F(q, q', t)`` in first-order form, for C and NumPy.

The state is ``y = (q, u)`` with ``u = q'``; ``f(t, y) = (u, M^{-1} F)`` and its Jacobian is
``[[0, I], [M^{-1} (dF/dy - (dM/dy) M^{-1} F)]]``.

:class:`Program` puts M (its upper triangle when M is symmetric), F and, for the Jacobian, every structurally
non-zero entry of dF/dy and dM/dy into one :class:`~symosc.numeric._dag.Graph`: the derivatives are taken on the
graph (forward mode, only nodes that depend on the variable), so they share their subexpressions with M and F and
with each other.  Everything that depends on the parameters alone (``l1*l2*(m2 + m3)``) is computed once, when
the parameter values are bound (``setup``); a call evaluates only what depends on t and y.  The C code solves
``M q'' = F`` by Gaussian elimination with partial pivoting in the same call.
"""

from __future__ import annotations

import builtins
import ctypes
from typing import Any

import numpy as np
import sympy as sp

from ..errors import ModelError, ParameterError
from . import _build, _c
from ._core import _argument_names
from ._dag import CONST, Graph, reachable
from ._emit import CPrinter, PythonPrinter, comment_text
from ._special import helper_source


class Program:
    """M, F (and the derivatives) of a first-order system as one graph, with the outputs' layout.

    Attributes: ``n``; ``pairs`` the stored (r, c) entries of M (``r <= c`` when ``symmetric``); ``outputs`` the
    node of each output, in the order M entries, F, dF entries (``df`` = (i, j) pairs), dM entries (``dm`` =
    (entry index into ``pairs``, j) pairs); ``hoisted`` the parameter-only nodes computed at set-up.
    """

    def __init__(
        self, M: sp.Matrix, F: sp.Matrix, t, q, u, params, jacobian: bool, base: Program | None = None
    ) -> None:
        """
        Parameters
        ----------
        M, F : sympy.Matrix
            The mass matrix and the forcing of ``M q'' = F``.
        t, q, u, params : Symbol, sequences of Symbol
            Time, the coordinates, the velocities and the parameters.
        jacobian : bool
            Whether the derivatives of F and M (for the Jacobian) are outputs too.
        base : Program, optional
            A program of the same equations whose graph (with M and F in it) this one extends, so that the
            right-hand side and the Jacobian of one system convert M and F once; the nodes of M and F, hence the
            generated code, are the same as in a fresh graph.
        """
        n = M.shape[0]
        self.n, self.jacobian = n, jacobian
        self.state = [*q, *u]
        self.params = list(params)
        args = [t, *self.state, *self.params]
        self.symbols = args
        if base is not None:
            g = self.graph = base.graph
            self.symmetric, self.pairs = base.symmetric, base.pairs
            m_nodes = base.outputs[: len(self.pairs)]
            f_nodes = base.outputs[len(self.pairs) : len(self.pairs) + n]
        else:
            varying = (1 << (1 + 2 * n)) - 1  # t and the state
            g = self.graph = Graph(args, varying)
            self.symmetric = all(M[i, j] == M[j, i] for i in range(n) for j in range(i + 1, n))
            self.pairs = [(i, j) for i in range(n) for j in range(i if self.symmetric else 0, n)]
            try:
                m_nodes = [g.node(M[i, j]) for i, j in self.pairs]
                f_nodes = [g.node(F[i]) for i in range(n)]
            except ValueError as exc:
                raise ParameterError(f"the equations depend on symbols that are not parameters: {exc}") from exc
        self.outputs = m_nodes + f_nodes
        #: The SymPy expressions of the M and F outputs as given (the llvm backend compiles them directly).
        self.given = base.given if base is not None else [M[i, j] for i, j in self.pairs] + [F[i] for i in range(n)]
        self.df: list[tuple[int, int]] = []
        self.dm: list[tuple[int, int]] = []
        if jacobian:
            try:
                for i, node in enumerate(f_nodes):
                    for j in range(2 * n):
                        d = g.derivative(node, 1 + j)
                        if d != g.zero:
                            self.df.append((i, j))
                            self.outputs.append(d)
                for k, node in enumerate(m_nodes):
                    for j in range(2 * n):
                        d = g.derivative(node, 1 + j)
                        if d != g.zero:
                            self.dm.append((k, j))
                            self.outputs.append(d)
            except NotImplementedError as exc:
                raise ParameterError(f"cannot differentiate the equations of motion: {exc}") from exc
        self.hoisted = self._parameter_only()

    def _parameter_only(self) -> list[int]:
        """Nodes that depend on the parameters only (parameters themselves included) and are needed by a node that
        varies, or are outputs."""
        g = self.graph
        varying = g.varying
        order, _ = reachable(g, self.outputs)
        needed = set()
        for k in order:
            if g.deps[k] & varying:
                for c in g._children(k):
                    needed.add(c)
        needed.update(self.outputs)
        return [k for k in sorted(needed) if not g.deps[k] & varying and g.kind[k] != CONST]

    # ------------------------------------------------------------------ C
    def c_source(self, name: str = "symosc_ode") -> str:
        """C99 source: ``{name}_setup``, ``{name}_rhs``, ``{name}_rhs_batch`` or ``{name}_jac`` (see the header)."""
        g, n = self.graph, self.n
        py = _argument_names(self.symbols)
        names = _c.c_names(py, _RESERVED)
        to_c = {s: sp.Symbol(c, **s.assumptions0) for s, c in zip(self.symbols, names, strict=True)}
        fallback = _c.fallback_printer(to_c)
        ny = 1 + 2 * n
        hnames = [f"_h{j}" for j in range(len(self.hoisted))]
        setup = CPrinter(g, names, fallback).statements(self.hoisted, [f"_H[{j}]" for j in range(len(self.hoisted))])
        preset = dict(zip(self.hoisted, hnames, strict=True))
        main = CPrinter(g, names, fallback).statements(
            self.outputs, [f"_O[{i}]" for i in range(len(self.outputs))], preset=preset
        )
        setup_units, _ = _c.kernel_units(f"{name}_setup_kernel", [("_P", names[ny:])], setup, "_H")
        reserve = _DRIVER_TEXT + _c.text_cost(setup)
        main_units, _ = _c.kernel_units(
            f"{name}_kernel", [("_T", names[:1]), ("_Y", names[1:ny]), ("_H", hnames)], main, "_O", reserve
        )
        listing = ", ".join(comment_text(s.name) for s in self.params) or "none"
        header = [
            "/* Generated by symosc (FirstOrderSystem, backend 'c'): y' = f(t, y) for M(q, t) q'' = F(q, q', t).",
            f"   State y = ({', '.join(comment_text(s.name) for s in self.state)}); parameters p = ({listing}).",
            f"   int {name}_setup(const double *p, double *h)   h (length {name}_hoisted) = values that depend on p",
            "       alone; call once per parameter set, then pass h to:",
            f"   int {name}_rhs(double t, const double *y, const double *h, double *dy)   dy = f(t, y), 2n = {2 * n}",
            f"   int {name}_rhs_batch(long count, double t, const double *Y, const double *h, double *dY)",
            "       Y and dY are count x 2n, row-major (one state per row).",
            f"   int {name}_jac(double t, const double *y, const double *h, double *J)       J = df/dy, 2n x 2n",
            "   Each returns 0, or 1 (+ row index for the batch) when the mass matrix is singular.",
            f"   Build: cc -O1 -fno-math-errno -std=c99 -fPIC -shared -o {name}.so {name}.c -lm */",
            _c.C_PRELUDE,
            f"const int {name}_hoisted = {len(self.hoisted)};",
            "",
            _SOLVE,
            setup_units[0],
            main_units[0],
            f"int {name}_setup(const double *p, double *h)",
            "{",
            f"    {name}_setup_kernel(p, h);",
            "    return 0;",
            "}",
            "",
            *self._c_unpack(name),
            *(self._c_jacobian(name) if self.jacobian else self._c_rhs(name)),
        ]
        return _c.join_units(["\n".join(header), *setup_units[1:], *main_units[1:]])

    def _c_unpack(self, name: str) -> list[str]:
        """``{name}_eval``: the kernel, then M (full, row-major) and F unpacked from its outputs."""
        n, pairs = self.n, self.pairs
        rows = ", ".join(str(r) for r, _ in pairs)
        cols = ", ".join(str(c) for _, c in pairs)
        mirror = [f"        _M[c * {n} + r] = v;"] if self.symmetric else []
        return [
            f"static const int {name}_mr[{len(pairs)}] = {{{rows}}};",
            f"static const int {name}_mc[{len(pairs)}] = {{{cols}}};",
            "",
            f"static void {name}_eval(double t, const double *y, const double *h, double *_O, double *_M, double *_F)",
            "{",
            f"    {name}_kernel(&t, y, h, _O);",
            f"    for (int k = 0; k < {len(pairs)}; k++) {{",
            f"        const int r = {name}_mr[k], c = {name}_mc[k];",
            "        const double v = _O[k];",
            f"        _M[r * {n} + c] = v;",
            *mirror,
            "    }",
            f"    for (int i = 0; i < {n}; i++) _F[i] = _O[{len(pairs)} + i];",
            "}",
            "",
        ]

    def _c_rhs(self, name: str) -> list[str]:
        n = self.n
        return [
            f"int {name}_rhs(double _t, const double *_y, const double *_h, double *_dy)",
            "{",
            f"    double _O[{len(self.outputs)}], _M[{n * n}], _F[{n}];",
            f"    {name}_eval(_t, _y, _h, _O, _M, _F);",
            f"    for (int i = 0; i < {n}; i++) _dy[i] = _y[{n} + i];",
            f"    if (symosc_solve({n}, _M, _F, 1)) return 1;",
            f"    for (int i = 0; i < {n}; i++) _dy[{n} + i] = _F[i];",
            "    return 0;",
            "}",
            "",
            f"int {name}_rhs_batch(long count, double _t, const double *_Y, const double *_h, double *_dY)",
            "{",
            "    for (long k = 0; k < count; k++)",
            f"        if ({name}_rhs(_t, _Y + k * {2 * n}, _h, _dY + k * {2 * n})) return (int)(1 + k);",
            "    return 0;",
            "}",
            "",
        ]

    def _c_jacobian(self, name: str) -> list[str]:
        n, n2 = self.n, 2 * self.n
        base = len(self.pairs) + n
        df_at = ", ".join(str(i * n2 + j) for i, j in self.df) or "0"
        dm_r = ", ".join(str(self.pairs[k][0]) for k, _ in self.dm) or "0"
        dm_c = ", ".join(str(self.pairs[k][1]) for k, _ in self.dm) or "0"
        dm_j = ", ".join(str(j) for _, j in self.dm) or "0"
        mirror = (
            [f"        if (r != c) _R[c * {n2} + j] -= v * _F[r];"] if self.symmetric else []
        )  # dM[c, r] = dM[r, c]
        return [
            f"static const int {name}_df[{max(len(self.df), 1)}] = {{{df_at}}};",
            f"static const int {name}_dmr[{max(len(self.dm), 1)}] = {{{dm_r}}};",
            f"static const int {name}_dmc[{max(len(self.dm), 1)}] = {{{dm_c}}};",
            f"static const int {name}_dmj[{max(len(self.dm), 1)}] = {{{dm_j}}};",
            "",
            f"int {name}_jac(double _t, const double *_y, const double *_h, double *_J)",
            "{",
            f"    double _O[{len(self.outputs)}], _M[{n * n}], _M2[{n * n}], _F[{n}], _R[{n * n2}];",
            f"    {name}_eval(_t, _y, _h, _O, _M, _F);",
            f"    for (int i = 0; i < {n * n}; i++) _M2[i] = _M[i];",
            f"    if (symosc_solve({n}, _M2, _F, 1)) return 1;  /* _F = q'' */",
            f"    for (int i = 0; i < {n * n2}; i++) _R[i] = 0.0;",
            f"    for (int k = 0; k < {len(self.df)}; k++) _R[{name}_df[k]] = _O[{base} + k];",
            f"    for (int k = 0; k < {len(self.dm)}; k++) {{  /* _R -= (dM/dy_j) q'' */",
            f"        const int r = {name}_dmr[k], c = {name}_dmc[k], j = {name}_dmj[k];",
            f"        const double v = _O[{base + len(self.df)} + k];",
            f"        _R[r * {n2} + j] -= v * _F[c];",
            *mirror,
            "    }",
            f"    if (symosc_solve({n}, _M, _R, {n2})) return 1;",
            f"    for (int i = 0; i < {n2 * n2}; i++) _J[i] = 0.0;",
            f"    for (int i = 0; i < {n}; i++) _J[i * {n2} + {n} + i] = 1.0;",
            f"    for (int i = 0; i < {n * n2}; i++) _J[{n * n2} + i] = _R[i];",
            "    return 0;",
            "}",
            "",
        ]

    # ------------------------------------------------------------------ Python
    def python_functions(self) -> dict[str, Any]:
        """``setup(p)``, ``scalar(t, y, h)`` (floats, ``math``) and ``array(t, Y, h)`` (NumPy rows) as functions,
        and ``source``."""
        from ._python import SafeNumPyPrinter, ScalarPrinter

        g = self.graph
        names = _argument_names(self.symbols)
        to_py = {s: sp.Symbol(c, **s.assumptions0) for s, c in zip(self.symbols, names, strict=True)}
        numpy_printer = SafeNumPyPrinter()
        math_printer = ScalarPrinter(SafeNumPyPrinter())
        ny = 1 + 2 * self.n
        hnames = [f"_h{j}" for j in range(len(self.hoisted))]
        preset = dict(zip(self.hoisted, hnames, strict=True))
        nout = len(self.outputs)

        helpers: set[str] = set()

        def body(module: str, printer: Any, outputs, targets, preset) -> list[str]:
            fallback = lambda e: _printed(printer, e.xreplace(to_py))  # noqa: E731
            emitter = PythonPrinter(g, names, module, fallback)
            sts = emitter.statements(outputs, targets, preset=preset)
            helpers.update(emitter.helpers)
            return [f"    {st.target} = {st.text}" for st in sts]

        def unpack(values: list[str], array: str) -> str:
            return f"    {', '.join(values)}, = {array}" if values else ""

        setup = [
            "def setup(_P):",
            unpack(names[ny:], "_P"),
            f"    _H = [0.0] * {len(self.hoisted)}",
            *body("math", math_printer, self.hoisted, [f"_H[{j}]" for j in range(len(self.hoisted))], None),
            "    return _H",
        ]
        kernels = []
        for fname, module, printer in (("scalar", "math", math_printer), ("array", "numpy", numpy_printer)):
            kernels += [
                f"def {fname}({names[0]}, _Y, _H):",
                unpack(names[1:ny], "_Y"),
                unpack(hnames, "_H"),
                f"    _O = [0.0] * {nout}",
                *body(module, printer, self.outputs, [f"_O[{i}]" for i in range(nout)], preset),
                "    return _O",
                "",
            ]
        modules = {"math", "numpy"} | set(numpy_printer.module_imports) | set(math_printer.module_imports)
        modules |= set(math_printer._fallback.module_imports)
        helpers |= numpy_printer.helpers | math_printer._fallback.helpers
        source = "".join(f"import {m}\n" for m in sorted(modules)) + helper_source(helpers) + "\n\n"
        source += "\n".join(line for line in setup if line) + "\n\n\n" + "\n".join(line for line in kernels if line)
        namespace: dict[str, Any] = {"__builtins__": builtins}
        exec(builtins.compile(source, "<symosc:first_order>", "exec"), namespace)
        return {name: namespace[name] for name in ("setup", "scalar", "array")} | {"source": source}

    # ------------------------------------------------------------------ LLVM
    def llvm_function(self) -> dict[str, Any]:
        """The outputs by symengine's LLVM JIT, in the interface of :meth:`python_functions` (no set-up step)."""
        from ._core import compile

        given = len(self.given)  # M and F as given; the derivatives rebuilt from the graph
        exprs = self.given + [self.graph.expression(k) for k in self.outputs[given:]]
        fn = compile(exprs, self.symbols, backend="llvm", check=False)
        raw = fn.raw

        def scalar(t: float, y: list, h: list) -> np.ndarray:
            return raw(t, *y, *h)

        def array(t: float, rows: list, h: list) -> np.ndarray:
            return raw(t, *rows, *h).T

        return {"setup": list, "scalar": scalar, "array": array, "source": lambda: fn.source}


def _printed(printer: Any, expr: sp.Expr) -> str:
    from ._python import _printed as printed

    return printed(printer, expr)


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
#: The build cost (:func:`symosc.numeric._c.text_cost`) of the solver and the drivers of :meth:`Program.c_source`:
#: the first translation unit, which holds them and the set-up kernel, gets that much less of the kernel.  Chosen
#: for the shortest build of the two units of the n = 10 and 20 pendulums' right-hand sides and Jacobians (GCC 12).
_DRIVER_TEXT = 14000


class CFirstOrder:
    """ctypes caller of :meth:`Program.c_source`; the parameter-only values are computed once, at binding."""

    def __init__(self, source: str, n: int, values: list[float], jacobian: bool, name: str = "symosc_ode") -> None:
        self.n = n
        self.source = source
        lib = _build.load(self.source, _build.GENERATED_FLAGS)
        self.lib = lib
        hoisted = ctypes.c_int.in_dll(lib, f"{name}_hoisted").value
        p = (ctypes.c_double * max(len(values), 1))(*[float(v) for v in values])
        self.h = (ctypes.c_double * max(hoisted, 1))()
        lib[f"{name}_setup"](p, self.h)
        if jacobian:
            self.fj = lib[f"{name}_jac"]
            self.fj.restype = ctypes.c_int
        else:
            self.f, self.fb = lib[f"{name}_rhs"], lib[f"{name}_rhs_batch"]
            self.f.restype = self.fb.restype = ctypes.c_int
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
            if self.f(ctypes.c_double(t), self._buffer(y), self.h, out):
                raise ModelError(f"mass matrix is singular at t={t}, state={y.tolist()}")
            return np.frombuffer(out)
        Y = np.ascontiguousarray(y.T, dtype=float)
        out = np.empty_like(Y)
        ptr = ctypes.c_void_p
        status = self.fb(
            ctypes.c_long(Y.shape[0]), ctypes.c_double(t), ptr(Y.ctypes.data), self.h, ptr(out.ctypes.data)
        )
        if status:
            raise ModelError(f"mass matrix is singular at t={t}, state={Y[status - 1].tolist()}")
        return out.T

    def jacobian(self, t: float, y: np.ndarray) -> np.ndarray:
        out = self.jtype()
        if self.fj(ctypes.c_double(t), self._buffer(y), self.h, out):
            raise ModelError(f"mass matrix is singular at t={t}, state={y.tolist()}")
        return np.frombuffer(out).reshape(2 * self.n, 2 * self.n)


class NumpyFirstOrder:
    """f(t, y) and df/dy in Python: ``math`` for one state, NumPy for a batch (and where ``math`` raises, so
    that ``1/0`` gives inf as in every other backend); LAPACK solves."""

    def __init__(self, program: Program, functions: dict[str, Any], values: list[float]) -> None:
        self.n, self.pairs, self.symmetric = program.n, program.pairs, program.symmetric
        self.df, self.dm = program.df, program.dm
        self.scalar, self.array = functions["scalar"], functions["array"]
        self._source = functions["source"]  # the text, or what writes it (llvm: on first access)
        self.h = functions["setup"]([float(v) for v in values])
        rows = [r for r, _ in self.pairs]
        cols = [c for _, c in self.pairs]
        self.index = (np.array(rows + cols), np.array(cols + rows)) if self.symmetric else (rows, cols)

    @property
    def source(self) -> str:
        """The generated code."""
        if callable(self._source):
            self._source = self._source()
        return self._source

    def _values(self, t: float, y: np.ndarray) -> np.ndarray:
        """Outputs for one state (1-D) or a batch (2n, k) -> (k, nout)."""
        if y.ndim == 1:
            try:
                return np.array(self.scalar(float(t), y.tolist(), self.h))
            except (ArithmeticError, ValueError):
                pass
            y = y[:, None]
            with np.errstate(all="ignore"):
                return self._batch(t, y)[0]
        with np.errstate(all="ignore"):
            return self._batch(t, y)

    def _batch(self, t: float, y: np.ndarray) -> np.ndarray:
        outs = self.array(float(t), list(np.asarray(y, dtype=float)), self.h)
        k = y.shape[1]
        return np.stack([np.broadcast_to(np.asarray(o, dtype=float), (k,)) for o in outs], axis=-1)

    def _mass_forcing(self, vals: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        n, m = self.n, len(self.pairs)
        M = np.empty((*vals.shape[:-1], n, n))
        entries = vals[..., :m]
        M[(..., *self.index)] = np.concatenate([entries, entries], axis=-1) if self.symmetric else entries
        return M, vals[..., m : m + n]

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        n = self.n
        M, F = self._mass_forcing(self._values(t, y))
        try:
            if y.ndim == 1:
                return np.concatenate([y[n:], np.linalg.solve(M, F)])
            qdd = np.linalg.solve(M, F[..., None])[..., 0]
        except np.linalg.LinAlgError as exc:
            where = f"state={y.tolist()}" if y.ndim == 1 else "one of the states"
            raise ModelError(f"mass matrix is singular at t={t}, {where}") from exc
        return np.concatenate([y[n:], qdd.T])

    def jacobian(self, t: float, y: np.ndarray) -> np.ndarray:
        n = self.n
        vals = self._values(t, y)
        M, F = self._mass_forcing(vals)
        base = len(self.pairs) + n
        R = np.zeros((n, 2 * n))
        for (i, j), v in zip(self.df, vals[base : base + len(self.df)], strict=True):
            R[i, j] = v
        try:
            qdd = np.linalg.solve(M, F)
            for (k, j), v in zip(self.dm, vals[base + len(self.df) :], strict=True):
                r, c = self.pairs[k]
                R[r, j] -= v * qdd[c]
                if self.symmetric and r != c:
                    R[c, j] -= v * qdd[r]
            X = np.linalg.solve(M, R)
        except np.linalg.LinAlgError as exc:
            raise ModelError(f"mass matrix is singular at t={t}, state={y.tolist()}") from exc
        J = np.zeros((2 * n, 2 * n))
        J[:n, n:] = np.eye(n)
        J[n:] = X
        return J
