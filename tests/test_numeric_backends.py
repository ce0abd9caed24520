"""Compiled backends of symosc.numeric.compile ("c", "llvm", "auto"): agreement with SymPy's 30-digit evalf,
standalone sources, the disk cache, concurrency, pickling and bad input."""

from __future__ import annotations

import ctypes
import os
import pickle
import subprocess
import sys
import textwrap
import warnings
from pathlib import Path

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import example, given, settings
from hypothesis import strategies as st

from symosc import ParameterError
from symosc.numeric import CompilerError, available_backends, cache_dir, compile
from symosc.numeric._build import clear_memory_cache

x, y = sp.symbols("x y", real=True)
m = sp.Symbol("m", positive=True)
COMPILED = ["c", "llvm"]
REPO = Path(__file__).resolve().parents[1]

# Functions every backend prints; evaluated independently by SymPy's evalf at 30 digits.
EXPRS = [
    sp.sin(x) * sp.exp(-m * y**2) + sp.Rational(1, 3) * sp.pi,
    sp.sqrt(m) * sp.cos(x - y) / (1 + x**2),
    sp.log(m + y**2) * sp.atan(x) - sp.tanh(y) ** 3,
    m ** sp.Rational(3, 2) + sp.Abs(x) * sp.cosh(y / 3) + sp.asinh(x * y),
    (x**2 + y**2) ** 2 / (m + 1) - sp.exp(sp.sin(x) * sp.cos(y)),
    sp.gamma(m) * sp.erf(x) + sp.loggamma(m + 1) - sp.erfc(y),  # special functions C99 and LLVM provide
]


pytestmark = pytest.mark.usefixtures("private_symosc_cache")


@pytest.fixture(scope="module")
def compiled():
    return {b: compile(EXPRS, [x, y, m], backend=b) for b in ["numpy", *COMPILED]}


def _reference(xv: float, yv: float, mv: float) -> list[float]:
    subs = {x: sp.Float(xv, 30), y: sp.Float(yv, 30), m: sp.Float(mv, 30)}
    return [float(e.evalf(30, subs=subs)) for e in EXPRS]


def _term_sizes(xv: float, yv: float, mv: float) -> np.ndarray:
    """The sum of the absolute values of each expression's terms: a sum that cancels (``erf(3) - erfc(0)`` is
    -2.2e-5) is known only to rounding errors of this size."""
    subs = {x: sp.Float(xv, 30), y: sp.Float(yv, 30), m: sp.Float(mv, 30)}
    return np.array([float(sum(abs(a.evalf(30, subs=subs)) for a in sp.Add.make_args(e))) for e in EXPRS])


@settings(max_examples=40, deadline=None)
@given(st.floats(-3, 3, allow_subnormal=False), st.floats(-2, 2, allow_subnormal=False), st.floats(0.01, 5))
@example(3.0, 0.0, 1.0)  # the last expression cancels to erf(3) - 1 = -2.2e-5
def test_all_backends_agree_with_30_digit_evalf(compiled, xv, yv, mv):
    ref = np.array(_reference(xv, yv, mv))
    allowed = 1e-12 * np.abs(ref) + 1e-14 * _term_sizes(xv, yv, mv)
    for backend, f in compiled.items():
        for got in (f(xv, yv, mv), f.raw(xv, yv, mv)):
            assert np.all(np.abs(got - ref) <= allowed), (backend, got, ref, allowed)


def test_batched_calls_match_pointwise_and_broadcast(compiled):
    xs = np.linspace(-2, 2, 7)[:, None]
    ys = np.array([0.1, -0.4, 1.5])
    for backend, f in compiled.items():
        out = f(xs, ys, 2.0)
        assert out.shape == (7, 3, len(EXPRS))
        ref = np.array([[_reference(float(a), float(b), 2.0) for b in ys] for a in xs[:, 0]])
        np.testing.assert_allclose(out, ref, rtol=1e-12, err_msg=backend)


def test_matrix_shape_and_scalar_result_in_c():
    f = compile(sp.Matrix([[x, 1], [0, y**2]]), [x, y], backend="c")
    assert f(np.arange(4.0), 3.0).shape == (4, 2, 2)
    np.testing.assert_array_equal(f(2.0, 3.0), [[2.0, 1.0], [0.0, 9.0]])
    g = compile(sp.sqrt(x**2 + y**2), [x, y], backend="c")
    assert float(g(3.0, 4.0)) == 5.0


def test_auto_says_which_backend_it_picked():
    f = compile(sp.sin(x), [x], backend="auto")
    assert f.backend == "c"  # a compiler is installed here
    g = compile(sp.besselj(0, x), [x], backend="auto")  # C and LLVM cannot print J0: NumPy/SciPy evaluates it
    assert g.backend == "numpy"
    assert float(g(2.0)) == pytest.approx(float(mpmath.besselj(0, 2.0)), rel=1e-14)
    assert {"numpy", "mpmath", "c", "llvm"} <= set(available_backends())


# --- standalone sources --------------------------------------------------------------------------------------


def _run(code: str, cwd: Path) -> str:
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=cwd, timeout=120)
    assert res.returncode == 0, res.stderr
    return res.stdout


@pytest.mark.parametrize("backend", ["numpy", "mpmath", "llvm"])
def test_python_sources_run_in_a_fresh_interpreter(tmp_path, backend):
    f = compile(EXPRS, [x, y, m], backend=backend, name="shared")
    (tmp_path / "generated.py").write_text(f.source)
    out = _run("import generated, numpy; print(repr([float(v) for v in generated.shared(0.3, -0.7, 1.9)]))", tmp_path)
    np.testing.assert_allclose(eval(out), _reference(0.3, -0.7, 1.9), rtol=1e-12)


def test_c_source_compiles_on_its_own(tmp_path):
    f = compile(EXPRS, [x, y, m], backend="c", name="shared")
    (tmp_path / "shared.c").write_text(f.source)
    subprocess.run(
        ["cc", "-O2", "-std=c99", "-fPIC", "-shared", "-o", "shared.so", "shared.c", "-lm"], cwd=tmp_path, check=True
    )
    lib = ctypes.CDLL(str(tmp_path / "shared.so"))
    a = (ctypes.c_double * 3)(0.3, -0.7, 1.9)
    out = (ctypes.c_double * len(EXPRS))()
    assert lib.shared(a, out) == 0
    np.testing.assert_allclose(list(out), _reference(0.3, -0.7, 1.9), rtol=1e-12)
    a[2] = -1.0  # m is declared positive: the checked entry names argument 2 (returns index + 1)
    assert lib.shared_checked(a, out) == 3


def test_math_constants_inside_a_piecewise_compile_in_c():
    # SymPy's C printer writes M_PI, M_E, M_SQRT2 for a Piecewise; -std=c99 hides them in glibc's math.h.
    f = compile(sp.Piecewise((sp.pi * x + sp.E, x > 0), (sp.sqrt(2) * x, True)), [x], backend="c")
    assert float(f(1.0)) == pytest.approx(float(sp.pi + sp.E), rel=1e-15)
    assert float(f(-1.0)) == pytest.approx(-(2**0.5), rel=1e-15)


def test_a_source_of_several_units_compiles_as_one_file(tmp_path, monkeypatch):
    from symosc.models import n_link_pendulum
    from symosc.numeric import _build, _c

    monkeypatch.setattr(_c.os, "cpu_count", lambda: 2)
    fo = n_link_pendulum(6).first_order()
    source = fo._program(True).c_source()
    assert source.count(_build.UNIT_MARKER) >= 1  # the kernel has a unit of its own
    (tmp_path / "ode.c").write_text(source)
    flags = ["-O0", "-std=c99", "-Werror=implicit-function-declaration", "-fPIC", "-shared"]
    subprocess.run(["cc", *flags, "-o", "ode.so", "ode.c", "-lm"], cwd=tmp_path, check=True)
    values = {p.name: 1.0 + 0.1 * i for i, p in enumerate(fo.system.parameters)}
    state = np.linspace(-0.4, 0.5, 12)
    lib = ctypes.CDLL(str(tmp_path / "ode.so"))
    p = (ctypes.c_double * len(values))(*[values[s.name] for s in fo.system.parameters])
    h = (ctypes.c_double * ctypes.c_int.in_dll(lib, "symosc_ode_hoisted").value)()
    lib.symosc_ode_setup(p, h)
    jac = (ctypes.c_double * 144)()
    assert lib.symosc_ode_jac(ctypes.c_double(0.0), (ctypes.c_double * 12)(*state), h, jac) == 0
    expected = fo.jacobian(values, backend="numpy")(0.0, state)
    np.testing.assert_allclose(np.array(jac).reshape(12, 12), expected, rtol=1e-11, atol=1e-11)


def test_gcc_is_told_from_clang_by_its_banner(monkeypatch):
    from symosc.numeric import _build

    gcc = "gcc (Debian 12.2.0-14) 12.2.0\nCopyright (C) 2022 Free Software Foundation, Inc.\n"
    clang = "Apple clang version 15.0.0 (clang-1500.1.0.2.5)\nTarget: arm64-apple-darwin23.2.0\n"
    for banner, is_gcc in ((gcc, True), (clang, False), ("cc: unknown\n", False)):
        monkeypatch.setattr(_build, "_compiler_banner", lambda cc, b=banner: b)
        assert _build._is_gcc("cc") is is_gcc
        first, rest = _build._unit_flags("cc", _build.GENERATED_FLAGS)
        assert (first[len(_build.GENERATED_FLAGS) :] == _build.GCC_GENERATED_FLAGS) is is_gcc
        assert (rest == first + _build.GCC_KERNEL_FLAGS) is is_gcc  # kernel-only units
        assert set(_build._unit_flags("cc", _build.FLAGS)[1]) == set(_build.FLAGS)  # hand-written code: as given
    monkeypatch.setattr(_build, "_compiler_banner", lambda cc: clang)
    assert _build._libs("cc", _build.GENERATED_FLAGS) == _build.LIBS


def test_a_lean_library_that_does_not_load_is_linked_again(monkeypatch):
    from symosc.numeric import _build

    if _build._libs(_build.compiler(), _build.GENERATED_FLAGS) == _build.LIBS:
        pytest.skip("the lean link is used with GCC on Linux only")
    links = []
    compile_ = _build._compile
    try_load = _build._try_load

    def recording(cc, flags, units, directory, path, full, libs):
        links.append(libs)
        return compile_(cc, flags, units, directory, path, full, libs)

    monkeypatch.setattr(_build, "_compile", recording)
    monkeypatch.setattr(
        _build, "_try_load", lambda path, key, full: try_load(path, key, full) if links[-1:] == [_build.LIBS] else None
    )
    f = compile(sp.cos(x) * 13 + y, [x, y], backend="c")
    assert float(f(0.0, 1.0)) == 14.0
    assert links == [_build.LEAN_LIBS, _build.LIBS]


def test_rhs_and_jacobian_of_one_system_share_the_graph():
    from symosc.mechanics import FirstOrderSystem
    from symosc.models import n_link_pendulum

    system = n_link_pendulum(3)
    fresh = [FirstOrderSystem(system)._program(j).c_source() for j in (False, True)]
    fo = FirstOrderSystem(system)
    jac, rhs = fo._program(True), fo._program(False)
    assert rhs.graph is jac.graph
    assert [rhs.c_source(), jac.c_source()] == fresh  # the same code as from graphs of their own


# --- the disk cache ------------------------------------------------------------------------------------------


def test_cache_reuses_and_distinguishes_libraries():
    before = set(cache_dir().glob("symosc_*.so"))
    compile(x**3 + 7 * y, [x, y], backend="c")
    first = set(cache_dir().glob("symosc_*.so")) - before
    compile(x**3 + 7 * y, [x, y], backend="c")
    assert set(cache_dir().glob("symosc_*.so")) - before == first  # same expression: same library
    assert len(first) == 1
    compile(x**3 + 8 * y, [x, y], backend="c")
    assert len(set(cache_dir().glob("symosc_*.so")) - before) == 2  # changed expression: a new library


def test_corrupted_library_is_rebuilt_not_loaded():
    expr = sp.cos(x) * 11 + y
    before = set(cache_dir().glob("symosc_*.so"))
    compile(expr, [x, y], backend="c")
    (path,) = set(cache_dir().glob("symosc_*.so")) - before
    good = path.read_bytes()
    path.unlink()  # a new file (the loaded library stays mapped), damaged in the middle
    path.write_bytes(good[: len(good) // 2] + b"\0" * 64 + good[len(good) // 2 + 64 :])
    clear_memory_cache()
    f = compile(expr, [x, y], backend="c")
    assert float(f(0.0, 1.0)) == 12.0
    assert path.read_bytes() == good  # rebuilt (the build is deterministic), not loaded damaged


def test_two_processes_building_at_once_both_succeed(tmp_path):
    code = textwrap.dedent(
        """
        import sympy as sp
        from symosc.numeric import compile
        a, b = sp.symbols("a b", real=True)
        f = compile([sp.exp(a) * sp.sin(b) + a**5 / 7], [a, b], backend="c")
        print(float(f(0.5, 0.25)[0]))
        """
    )
    env = {**os.environ, "SYMOSC_CACHE_DIR": str(tmp_path / "cache"), "PYTHONPATH": str(REPO)}
    procs = [
        subprocess.Popen(
            [sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, text=True
        )
        for _ in range(2)
    ]
    outs = [p.communicate(timeout=120) for p in procs]
    assert [p.returncode for p in procs] == [0, 0], [o[1] for o in outs]
    ref = float(mpmath.exp(0.5) * mpmath.sin(0.25) + mpmath.mpf(0.5) ** 5 / 7)
    for out, _ in outs:
        assert float(out) == pytest.approx(ref, rel=1e-14)
    assert len(list((tmp_path / "cache").glob("symosc_*.so"))) == 1


@pytest.mark.parametrize("backend", ["numpy", "c", "mpmath"])
def test_pickle_round_trip(backend):
    f = compile(sp.Matrix([[sp.sin(x) * m, y]]), [x, y, m], backend=backend, dps=20 if backend == "mpmath" else None)
    g = pickle.loads(pickle.dumps(f))
    assert (g.backend, g.args, g.shape) == (f.backend, f.args, f.shape)
    if backend == "mpmath":
        assert g(0.5, 2, 3) == f(0.5, 2, 3)
    else:
        np.testing.assert_array_equal(g(0.5, 2.0, 3.0), f(0.5, 2.0, 3.0))
    with pytest.raises(ParameterError, match="m must be positive"):
        g(0.5, 2.0, -3.0)


# --- bad input -----------------------------------------------------------------------------------------------


def test_missing_compiler_is_named(monkeypatch):
    monkeypatch.setenv("SYMOSC_CC", "/nonexistent/cc")
    with pytest.raises(CompilerError, match=r"no C compiler found.*install gcc or clang"):
        compile(x * 13 + 1, [x], backend="c")


def test_unprintable_function_is_named():
    with pytest.raises(ParameterError, match="C backend cannot print besselj"):
        compile(sp.besselj(1, x), [x], backend="c")
    with pytest.raises(ParameterError, match=r"llvm backend cannot compile .*besselj"):
        compile(sp.besselj(1, x), [x], backend="llvm")
    with pytest.raises(ParameterError, match="real-valued"):
        compile(sp.exp(sp.I * x), [x], backend="c")


@pytest.mark.parametrize("backend", COMPILED)
def test_a_dummy_argument_is_its_own_argument(backend):
    # symengine knows a symbol by its name, and converts a Dummy to a symbol of its own: the argument must still
    # be the one in the expression
    d = sp.Dummy("d")
    f = compile([sp.sin(d) + 3 * x, d * x], [d, x], backend=backend)
    np.testing.assert_allclose(f(0.25, -1.0), [np.sin(0.25) - 3.0, -0.25], rtol=1e-15)


def test_an_llvm_source_is_written_when_it_is_read():
    f = compile(EXPRS, [x, y, m], backend="llvm")
    assert not isinstance(f._source, str)  # the evaluator needs no text: nothing printed at build time
    text = f.source
    assert isinstance(f._source, str) and f.source is text and "symengine.Lambdify" in text


@pytest.mark.parametrize("backend", ["numpy", "c", "llvm"])
def test_nan_and_wrong_signs_are_named(backend):
    f = compile(EXPRS, [x, y, m], backend=backend)
    with pytest.raises(ParameterError, match="y must be finite"):
        f(1.0, float("nan"), 1.0)
    with pytest.raises(ParameterError, match="m must be positive"):
        f(1.0, 0.0, 0.0)
    with pytest.raises(ParameterError, match="m must be positive"):
        f(np.array([1.0, 2.0]), 0.0, np.array([1.0, -1.0]))
    with pytest.raises(ParameterError, match=r"expected 3 arguments \(x, y, m\), got 2"):
        f(1.0, 2.0)
    with pytest.raises(ParameterError, match="x: expected a number, got None"):
        f(None, 2.0, 1.0)


@pytest.mark.parametrize("backend", ["numpy", "c"])
def test_division_by_zero_gives_inf_and_a_warning_naming_the_function(backend):
    f = compile(1 / x + y, [x, y], backend=backend, name="reciprocal")
    with pytest.warns(RuntimeWarning, match=r"reciprocal: evaluation gave non-finite values .* at x=0.0, y=1.0"):
        out = f(0.0, 1.0)
    assert np.isposinf(out)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert np.isposinf(f.raw(0.0, 1.0))  # unchecked: IEEE semantics, no exception from the generated code
        assert np.isnan(compile(sp.sqrt(x), [x], backend=backend).raw(-1.0))


def test_bad_compile_inputs_name_the_argument():
    with pytest.raises(ParameterError, match="exprs: expected a SymPy expression"):
        compile(None, [x])
    with pytest.raises(ParameterError, match="args: expected a sequence of SymPy Symbols"):
        compile(x, None)
    with pytest.raises(ParameterError, match="exprs: expected a SymPy expression"):
        compile("x + 1", [x])
    with pytest.raises(ParameterError, match="name must be an ASCII identifier"):
        compile(x, [x], backend="c", name="not valid")


def test_imports_only_what_the_expression_needs():
    plain = compile(sp.sin(x) + y, [x, y]).source
    assert "scipy" not in plain and "import math" in plain
    special = compile(sp.besselj(0, x), [x]).source
    assert "import scipy.special" in special


def test_a_damaged_source_memo_is_regenerated():
    expr = sp.sin(x) * 17 - y
    before = set(cache_dir().glob("source_*.c"))
    compile(expr, [x, y], backend="c")
    (memo,) = set(cache_dir().glob("source_*.c")) - before
    digest, text = memo.read_text().split("\n", 1)
    memo.write_text(digest + "\n" + text.replace("17", "19"))  # stale or tampered text under a valid-looking name
    clear_memory_cache()
    f = compile(expr, [x, y], backend="c")
    assert float(f(np.pi / 2, 1.0)) == 16.0
    assert "17" in f.source and memo.read_text() == digest + "\n" + text
