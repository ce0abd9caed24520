"""symosc.codegen.export: C and Python outputs are compiled/run and compared with the NumPy evaluator; the Julia,
Octave and Fortran kernels are evaluated by a literal transliteration to Python (no such toolchain here)."""

from __future__ import annotations

import ctypes
import re
import subprocess
import sys

import numpy as np
import pytest
import sympy as sp

from symosc import ParameterError
from symosc.codegen import export
from symosc.models import n_link_pendulum

SYSTEM = n_link_pendulum(2, links="rigid", pivot="vertical")  # rheonomic: exercises t and the parameters a, p
FO = SYSTEM.first_order()
PARAMS = {"m1": 1.1, "m2": 0.6, "l1": 0.8, "lc1": 0.45, "lc2": 0.3, "I1": 0.05, "I2": 0.02, "g": 9.81, "a": 0.02,
          "p": 30.0}  # fmt: skip
P = np.array([PARAMS[s.name] for s in SYSTEM.parameters])
STATES = np.random.default_rng(3).uniform(-1.5, 1.5, size=(3, 4))
T = 0.37


def _reference(y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return FO.rhs(PARAMS)(T, y), FO.jacobian(PARAMS)(T, y)


def test_c_export_compiles_and_matches_the_numpy_evaluator(tmp_path):
    text = export(SYSTEM, "c", tmp_path / "pend.c", name="pend")
    assert "p[9] = p (positive)" in text and "y[2] = phi1_dot" in text  # parameters named in order
    header = (tmp_path / "pend.h").read_text()
    assert "int pend_rhs(double t, const double *y, const double *p, double *dy);" in header
    (tmp_path / "use.c").write_text(
        '#include "pend.h"\nint use(double t, const double *y, const double *p,'
        " double *dy) { return pend_rhs(t, y, p, dy); }\n"
    )
    subprocess.run(
        [
            "cc",
            "-O2",
            "-std=c99",
            "-Wall",
            "-Werror",
            "-Wno-unused-variable",
            "-Wno-unused-parameter",
            "-fPIC",
            "-shared",
            "-o",
            "pend.so",
            "pend.c",
            "use.c",
            "-lm",
        ],
        cwd=tmp_path,
        check=True,
    )
    lib = ctypes.CDLL(str(tmp_path / "pend.so"))
    pp = (ctypes.c_double * len(P))(*P)
    for y in STATES:
        dy, J = (ctypes.c_double * 4)(), (ctypes.c_double * 16)()
        yy = (ctypes.c_double * 4)(*y)
        assert lib.use(ctypes.c_double(T), yy, pp, dy) == 0
        assert lib.pend_jacobian(ctypes.c_double(T), yy, pp, J) == 0
        f_ref, j_ref = _reference(y)
        np.testing.assert_allclose(list(dy), f_ref, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(np.reshape(list(J), (4, 4)), j_ref, rtol=1e-12, atol=1e-12)


def test_python_export_runs_in_a_fresh_interpreter(tmp_path):
    export(SYSTEM, "python", tmp_path / "pend.py")
    code = (
        "import numpy, pend\n"
        f"P = numpy.array({P.tolist()})\n"
        f"for y in numpy.array({STATES.tolist()}):\n"
        f"    print(repr(pend.rhs({T}, y, P).tolist()), repr(pend.jacobian({T}, y, P).tolist()))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path, check=True)
    for line, y in zip(out.stdout.splitlines(), STATES, strict=True):
        f_got, j_got = line.split(" [[")
        f_ref, j_ref = _reference(y)
        np.testing.assert_allclose(eval(f_got), f_ref, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(eval("[[" + j_got), j_ref, rtol=1e-12, atol=1e-12)


class _OneBased:
    """y(1) / y[1] / out(1, 2) = ... with 1-based indices, as Julia, Octave and Fortran index."""

    def __init__(self, data):
        self.data = np.asarray(data, dtype=float)

    def _key(self, key):
        return tuple(k - 1 for k in key) if isinstance(key, tuple) else key - 1

    def __call__(self, *key):
        return self.data[self._key(key if len(key) > 1 else key[0])]

    __getitem__ = __call__

    def __setitem__(self, key, value):
        self.data[self._key(key)] = value


def _transliterate(text: str, language: str) -> dict:
    """Run each kernel of ``text`` as Python, line by line, after the minimal syntax substitutions."""
    kernels, current = {}, None
    start = {"julia": r"^function (\w+)\(", "octave": r"^function out = (\w+)\(", "fortran": r"^  subroutine (\w+)\("}
    for line in text.splitlines():
        m = re.match(start[language], line)
        if m:
            current = kernels.setdefault(m.group(1), [])
            continue
        s = line.strip().rstrip(";")
        if current is None or not re.match(r"^(\w+|out[\[(][\d, ]+[\])]) = ", s) or s.startswith(("pi =", "real")):
            if s.startswith(("end", "return")):
                current = None
            continue
        s = re.sub(r"\bout\(([\d, ]+)\) =", r"out[\1] =", s)
        s = s.replace(".*", "*").replace("./", "/").replace(".^", "**").replace("^", "**").replace("//", "/")
        s = re.sub(r"(\d)d0\b", r"\1e0", s)
        current.append(s)
    return kernels


def _evaluate(lines: list[str], y, v=None):
    ns = {"sin": np.sin, "cos": np.cos, "sqrt": np.sqrt, "pi": np.pi, "zeros": lambda *s: _OneBased(np.zeros(s)),
          "t": T, "y": _OneBased(y), "p": _OneBased(P), "v": _OneBased(v if v is not None else [])}  # fmt: skip
    ns["out"] = _OneBased(np.zeros((4, 4)))
    for line in lines:
        exec(line, ns)
    return ns["out"].data


@pytest.mark.parametrize("language", ["julia", "octave", "fortran"])
def test_printed_kernels_evaluate_to_the_same_numbers(language):
    text = export(SYSTEM, language, name="pend")
    kernels = _transliterate(text, language)
    assert set(kernels) >= {"mass_matrix", "forcing", "forcing_jacobian", "mass_matrix_jacobian_times"}
    y = STATES[0]
    M = _evaluate(kernels["mass_matrix"], y)[:2, :2]
    F = _evaluate(kernels["forcing"], y)
    F = F[:2, 0] if F.ndim == 2 and F.shape[1] > 1 and language != "julia" else F.ravel()[:2]
    dF = _evaluate(kernels["forcing_jacobian"], y)[:2, :4]
    qdd = np.linalg.solve(M, F)
    G = _evaluate(kernels["mass_matrix_jacobian_times"], y, qdd)[:2, :4]
    f_ref, j_ref = _reference(y)
    np.testing.assert_allclose(qdd, f_ref[2:], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(np.linalg.solve(M, dF - G), j_ref[2:], rtol=1e-10, atol=1e-10)
    assert re.search(r"(function|subroutine) (J = )?jacobian\(t, y, p", text)


def test_expressions_export_and_bad_input():
    x, k = sp.symbols("x k", real=True)
    text = export([sp.sin(k * x), x**2], "c", args=[x, k], name="f")
    assert "void f(const double *a, double *out)" in text and "a[1] = k" in text
    with pytest.raises(ParameterError, match="args: exporting expressions needs"):
        export(x**2, "python")
    with pytest.raises(ParameterError, match="language must be one of"):
        export(x**2, "rust", args=[x])
    with pytest.raises(ParameterError, match="cannot print besselj"):
        export(sp.besselj(0, x), "c", args=[x])
