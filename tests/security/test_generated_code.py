"""Adversarial names, constants and cache files against the code generators (compile backends and codegen.export).

Symbol names reach generated source as identifiers only (checked or replaced) and appear in comments and docstrings
only escaped; ``name=`` that is a keyword is refused (compile) or renamed (export); integer constants beyond the
target's integer range become correctly rounded doubles; the build cache loads only the user's own files whose
keyed digest matches the source.
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import stat
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from symosc import ParameterError
from symosc.codegen import LANGUAGES, export
from symosc.numeric import CompilerError, cache_dir, compile
from symosc.numeric._build import clear_memory_cache

pytestmark = pytest.mark.usefixtures("private_symosc_cache")

CANARY = "symosc_canary_file"


def _payloads(canary: Path) -> list[str]:
    """Names that would run code if pasted into a Python docstring, a C comment or a Julia string."""
    c = str(canary).replace("\\", "/")
    return [
        f'x"""\nopen("{c}", "w").write("1")\n"""',
        f"y'''\nopen('{c}', 'w').write('1')\n'''",
        f'z */ __attribute__((constructor)) static void evil(void) {{ fopen("{c}", "w"); }} /*',
        'w\n#include "/etc/passwd"\n',
        f"v $(run(`touch {c}`)) #= =# % ! \\",
    ]


KEYWORDS = ["int", "for", "lambda", "None", "type", "sum", "numpy", "_w", "_t3", "symosc_mod", "NAN", "M_PI", "end"]


def _reference(values: list[float]) -> float:
    return sum((k + 1) * v for k, v in enumerate(values))


@pytest.mark.parametrize("backend", ["numpy", "mpmath", "c", "llvm"])
def test_injected_and_keyword_names_are_inert_in_every_backend(tmp_path, backend):
    canary = tmp_path / CANARY
    names = _payloads(canary) + KEYWORDS
    syms = [sp.Symbol(n, real=True) for n in names]
    expr = sp.Add(*((k + 1) * s for k, s in enumerate(syms)))
    f = compile([expr, sp.sin(syms[0])], syms, backend=backend)
    values = [0.1 * (k + 1) for k in range(len(syms))]
    got = f(*values)
    assert float(got[0]) == pytest.approx(_reference(values), rel=1e-14)
    if backend in ("numpy", "mpmath", "llvm"):  # the source runs on its own ...
        exec(compile_source(f.source), {"__name__": "generated"})
    else:  # ... or compiles on its own, with every name only in escaped comments
        (tmp_path / "g.c").write_text(f.source)
        subprocess.run(["cc", "-std=c99", "-fsyntax-only", "g.c"], cwd=tmp_path, check=True)
        assert '#include "/etc/passwd"' not in f.source and "constructor" not in f.source.split("*/", 1)[1]
    assert not canary.exists()


def test_first_order_sources_escape_names_of_coordinates_and_parameters(tmp_path):
    """The generated right-hand side (C and Python) of a system whose symbols carry injection attempts."""
    from symosc import dot
    from symosc.mechanics import LagrangianSystem

    canary = tmp_path / CANARY
    q = sp.Symbol("for", real=True)
    m, k = sp.Symbol(_payloads(canary)[2], positive=True), sp.Symbol(_payloads(canary)[0], positive=True)
    fo = LagrangianSystem(m * dot(q) ** 2 / 2, k * q**2 / 2, [q]).first_order()
    values = {m: 2.0, k: 8.0}
    for backend in ("c", "numpy"):
        f = fo.rhs(values, backend=backend)
        assert f(0.0, np.array([0.5, 0.0])).tolist() == [0.0, -2.0]  # q'' = -k q / m
        assert fo.jacobian(values, backend=backend)(0.0, [0.5, 0.0]).tolist() == [[0.0, 1.0], [-4.0, 0.0]]
    assert not canary.exists()


def compile_source(text: str):
    import builtins

    return builtins.compile(text, "<generated>", "exec")


def test_keyword_function_names_are_refused_by_name():
    x = sp.Symbol("x")
    for backend, name in [("numpy", "lambda"), ("numpy", "None"), ("c", "int"), ("c", "for"), ("mpmath", "type")]:
        with pytest.raises(ParameterError, match=f"name {name!r} is a keyword or a library name"):
            compile(x + 1, [x], backend=backend, name=name)
    with pytest.raises(ParameterError, match="ASCII identifier"):
        compile(x + 1, [x], name='f"""')


@pytest.mark.parametrize("language", LANGUAGES)
def test_export_escapes_names_and_renames_keywords(tmp_path, language):
    canary = tmp_path / CANARY
    syms = [sp.Symbol(n, real=True) for n in _payloads(canary) + KEYWORDS]
    expr = sp.Add(*((k + 1) * s for k, s in enumerate(syms)))
    name = {"c": "int", "python": "lambda", "julia": "end", "octave": "function", "fortran": "real"}[language]
    text = export([expr], language, args=syms, name=name)
    assert "Renamed" in text and f"{name} -> {name}_" in text
    for payload in _payloads(canary):
        assert payload not in text
    for bad in ('"""\nopen', "*/ __attr", '#include "/etc', "$(run"):
        assert bad not in text
    values = [0.1 * (k + 1) for k in range(len(syms))]
    if language == "python":
        namespace: dict = {}
        exec(compile_source(text), namespace)
        assert namespace[f"{name}_"](values)[0] == pytest.approx(_reference(values), rel=1e-14)
    if language == "c":
        (tmp_path / "e.c").write_text(text)
        subprocess.run(["cc", "-std=c99", "-Wall", "-Werror", "-fPIC", "-shared", "-o", "e.so", "e.c", "-lm"],
                       cwd=tmp_path, check=True)  # fmt: skip
        lib = ctypes.CDLL(str(tmp_path / "e.so"))
        out = (ctypes.c_double * 1)()
        lib.int_((ctypes.c_double * len(values))(*values), out)
        assert out[0] == pytest.approx(_reference(values), rel=1e-14)
    assert not canary.exists()


x = sp.Symbol("x", real=True)
BIG = [
    sp.factorial(21) * x,  # 5.1e19: wraps around as a 64-bit C integer literal
    2**64 * x + 3,
    sp.Integer(10) ** 300 * x**2,
    sp.Rational(10**400 + 1, 10**399) * x,
    sp.Rational(3**210, 7**180) * x,  # 101-digit numerator
    sp.Rational(-(10**100) - 7, 3 * 10**99) * sp.cos(x),
]


def test_big_integer_and_rational_constants_agree_across_backends():
    points = [0.37, -1.9]
    ref = np.array([[float(sp.N(e.subs(x, sp.Rational(p)), 30)) for e in BIG] for p in points])
    for backend in ("numpy", "c", "llvm"):
        f = compile(BIG, [x], backend=backend)
        got = np.array([f(p) for p in points])
        np.testing.assert_allclose(got, ref, rtol=1e-12, err_msg=backend)
    huge = compile([sp.Integer(10) ** 400 * x], [x], backend="c", check=False).raw
    assert np.isposinf(huge(1.0)[0]) and np.isneginf(huge(-1.0)[0])  # beyond the double range: infinity, not 0


@pytest.mark.parametrize("language", ["c", "python"])
def test_exported_big_constants_compute_the_same_numbers(tmp_path, language):
    text = export(BIG, language, args=[x], name="big")
    ref = [float(sp.N(e.subs(x, sp.Rational(37, 100)), 30)) for e in BIG]
    if language == "python":
        namespace: dict = {}
        exec(compile_source(text), namespace)
        got = namespace["big"]([0.37])
    else:
        (tmp_path / "big.c").write_text(text)
        subprocess.run(["cc", "-std=c99", "-fPIC", "-shared", "-o", "big.so", "big.c", "-lm"], cwd=tmp_path, check=True)
        out = (ctypes.c_double * len(BIG))()
        ctypes.CDLL(str(tmp_path / "big.so")).big((ctypes.c_double * 1)(0.37), out)
        got = list(out)
    np.testing.assert_allclose(got, ref, rtol=1e-12)


def test_imaginary_unit_is_refused_by_name_where_the_kernel_is_real():
    for language in ("c", "fortran"):
        with pytest.raises(ParameterError, match="imaginary unit I"):
            export(sp.I * x, language, args=[x])
    namespace: dict = {}
    exec(compile_source(export(sp.I * x + 1, "python", args=[x], name="f")), namespace)
    assert namespace["f"]([2.0])[0] == 1 + 2j
    assert "zeros(ComplexF64, 1)" in export(sp.I * x, "julia", args=[x])


# --- the build cache ---------------------------------------------------------------------------------------------


def test_a_library_replaced_in_the_cache_is_rebuilt_not_loaded():
    """An attacker who can write one file swaps in another library (with a plain SHA-256 beside it)."""
    y = sp.Symbol("y", real=True)
    before = set(cache_dir().glob("symosc_*.so"))
    compile(sp.cos(y) * 3 + 1, [y], backend="c")
    (good,) = set(cache_dir().glob("symosc_*.so")) - before
    other = compile(sp.cos(y) * 5 - 7, [y], backend="c")
    (bad,) = set(cache_dir().glob("symosc_*.so")) - before - {good}
    payload = bad.read_bytes()
    good.unlink()
    good.write_bytes(payload)
    Path(str(good) + ".sha256").write_text(hashlib.sha256(payload).hexdigest())
    clear_memory_cache()
    f = compile(sp.cos(y) * 3 + 1, [y], backend="c")
    assert float(f(0.0)) == 4.0 and float(other(0.0)) == -2.0


def test_a_cache_folder_writable_by_others_is_refused(tmp_path, monkeypatch):
    folder = tmp_path / "shared_cache"
    folder.mkdir()
    folder.chmod(0o777)
    monkeypatch.setenv("SYMOSC_CACHE_DIR", str(folder))
    clear_memory_cache()
    z = sp.Symbol("z", real=True)
    with pytest.raises(CompilerError, match="writable by other users"):
        compile(z**3 + 2, [z], backend="c")
    assert compile(z**3 + 2, [z], backend="auto").backend in ("llvm", "numpy")  # auto passes over the C cache
    folder.chmod(0o700)
    assert float(compile(z**3 + 2, [z], backend="c")(2.0)) == 10.0
    assert stat.S_IMODE(os.stat(folder).st_mode) == 0o700


@pytest.mark.skipif(os.geteuid() != 0, reason="changing a file's owner needs root; the tests run as root in .ci/run")
def test_a_cached_library_of_another_user_is_refused(tmp_path, monkeypatch):
    monkeypatch.setenv("SYMOSC_CACHE_DIR", str(tmp_path / "cache"))
    z = sp.Symbol("z", real=True)
    compile(z**5, [z], backend="c")
    (lib,) = list((tmp_path / "cache").glob("symosc_*.so"))
    os.chown(lib, 65534, 65534)
    clear_memory_cache()
    with pytest.raises(CompilerError, match="belongs to another user"):
        compile(z**5, [z], backend="c")


def test_generated_source_memo_with_a_plain_digest_is_not_used():
    w = sp.Symbol("w", real=True)
    before = set(cache_dir().glob("source_*.c"))
    compile(sp.exp(w) * 13, [w], backend="c")
    (memo,) = set(cache_dir().glob("source_*.c")) - before
    text = memo.read_text().split("\n", 1)[1].replace("13.0", "17.0")
    memo.write_text(hashlib.sha256(text.encode()).hexdigest() + "\n" + text)  # a digest anyone can compute
    clear_memory_cache()
    assert float(compile(sp.exp(w) * 13, [w], backend="c")(0.0)) == 13.0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(pytest.main([__file__]))
