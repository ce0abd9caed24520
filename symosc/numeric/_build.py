"""Build C sources into shared libraries, cached on disk, and load them with ctypes.

The cache directory is ``$SYMOSC_CACHE_DIR`` if set, else ``$XDG_CACHE_HOME/symosc``, else
``~/.cache/symosc``.  A library is named by a hash of its source, the compiler flags and the compiler's
version, carries that hash in the symbol ``symosc_build_id``, and has the SHA-256 of its bytes stored beside
it: a file whose bytes do not match (corrupted or truncated), that does not load or that carries another id is
rebuilt, never used.  Builds write to a temporary file and
``os.replace`` it into place, so concurrent processes building the same library all succeed.

The compiler is ``$SYMOSC_CC``, else ``$CC``, else ``cc``.
"""

from __future__ import annotations

import ctypes
import functools
import hashlib
import os
import shlex
import shutil
import subprocess
import tempfile
import threading
from pathlib import Path

from ..errors import SymoscError

FLAGS = ("-O2", "-std=c99", "-fPIC", "-shared")
LIBS = ("-lm",)
_ID_LEN = 24
_loaded: dict[str, ctypes.CDLL] = {}
_lock = threading.Lock()


class CompilerError(SymoscError, RuntimeError):
    """No working C compiler, or the generated C code did not compile."""


def cache_dir() -> Path:
    """The directory holding compiled libraries (created on first use)."""
    env = os.environ.get("SYMOSC_CACHE_DIR")
    if env:
        return Path(env)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "symosc"


def compiler() -> str:
    """Path of the C compiler, or :class:`CompilerError` naming what to install."""
    name = os.environ.get("SYMOSC_CC") or os.environ.get("CC") or "cc"
    found = shutil.which(shlex.split(name)[0]) if name.strip() else None
    if not found:
        raise CompilerError(
            f"no C compiler found (looked for {name!r} on PATH); install gcc or clang "
            "(e.g. `apt install gcc`, `xcode-select --install`), or point SYMOSC_CC at one, "
            "or use backend='numpy'"
        )
    return found


@functools.lru_cache(maxsize=8)
def _compiler_version(cc: str) -> str:
    try:
        out = subprocess.run([cc, "--version"], capture_output=True, text=True, timeout=30, check=False)
    except OSError as exc:
        raise CompilerError(f"the C compiler {cc} does not run: {exc}") from exc
    return (out.stdout or out.stderr).splitlines()[0] if (out.stdout or out.stderr) else cc


def build_id(source: str) -> tuple[str, str]:
    """The cache key of ``source`` for the current compiler and flags, and the compiler path."""
    cc = compiler()
    text = "\0".join([source, " ".join(FLAGS + LIBS), _compiler_version(cc)])
    return hashlib.sha256(text.encode()).hexdigest()[:_ID_LEN], cc


def load(source: str) -> ctypes.CDLL:
    """The shared library built from ``source`` (from memory, from the disk cache, or freshly built)."""
    key, cc = build_id(source)
    with _lock:
        lib = _loaded.get(key)
        if lib is not None:
            return lib
        directory = cache_dir()
        path = directory / f"symosc_{key}.so"
        lib = _try_load(path, key)
        if lib is None:
            _compile(cc, source + f'\nconst char symosc_build_id[] = "{key}";\n', directory, path)
            lib = _try_load(path, key)
            if lib is None:
                raise CompilerError(f"the library {path} was built but does not load")
        _loaded[key] = lib
        return lib


def _digest_path(path: Path) -> Path:
    return path.with_name(path.name + ".sha256")


def _try_load(path: Path, key: str) -> ctypes.CDLL | None:
    """Load ``path`` if its bytes match the stored digest and it carries ``key`` (never dlopen a damaged file)."""
    try:
        data = path.read_bytes()
        digest = _digest_path(path).read_text().strip()
    except OSError:
        return None
    if hashlib.sha256(data).hexdigest() != digest:
        return None
    try:
        lib = ctypes.CDLL(str(path))
        stored = (ctypes.c_char * (_ID_LEN + 1)).in_dll(lib, "symosc_build_id").value.decode()
    except (OSError, ValueError, UnicodeDecodeError):
        return None
    return lib if stored == key else None


def _compile(cc: str, source: str, directory: Path, path: Path) -> None:
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise CompilerError(f"cannot create the cache directory {directory} ({exc}); set SYMOSC_CACHE_DIR") from exc
    with tempfile.TemporaryDirectory(dir=directory, prefix=".build_") as tmp:
        src = Path(tmp) / "symosc.c"
        src.write_text(source)
        out = Path(tmp) / path.name
        cmd = [cc, *FLAGS, "-o", str(out), str(src), *LIBS]
        try:
            res = subprocess.run(cmd, capture_output=True, text=True, timeout=600, check=False)
        except (OSError, subprocess.TimeoutExpired) as exc:
            raise CompilerError(f"the C compiler failed to run: {' '.join(cmd)}: {exc}") from exc
        if res.returncode != 0 or not out.exists():
            tail = "\n".join(res.stderr.strip().splitlines()[-15:])
            raise CompilerError(f"C compilation failed ({' '.join(cmd)}):\n{tail}")
        digest = Path(tmp) / "digest"
        digest.write_text(hashlib.sha256(out.read_bytes()).hexdigest())
        # Atomic renames: a concurrent builder or reader sees either the old files or complete new ones (a
        # library and a digest from two builders that differ only make a reader rebuild once more).
        os.replace(out, path)
        os.replace(digest, _digest_path(path))


def clear_memory_cache() -> None:
    """Forget the libraries loaded in this process (the disk cache is kept); used by the tests."""
    with _lock:
        _loaded.clear()


CODEGEN_VERSION = "1"  # bump when generated code changes for the same expressions


def expression_digest(exprs: list, *extra: str) -> str:
    """A process-independent digest of SymPy expressions (shared subtrees hashed once) and ``extra`` strings.

    Used to find previously generated source without repeating the common-subexpression elimination, so
    that a cached rebuild costs milliseconds even for large systems.
    """
    import sympy as sp

    memo: dict = {}

    def digest(e) -> bytes:
        d = memo.get(e)
        if d is None:
            if e.args:
                h = hashlib.blake2b(type(e).__name__.encode(), digest_size=16)
                for a in e.args:
                    h.update(digest(a))
                d = h.digest()
            else:
                d = hashlib.blake2b(sp.srepr(e).encode(), digest_size=16).digest()
            memo[e] = d
        return d

    h = hashlib.sha256(CODEGEN_VERSION.encode())
    for e in exprs:
        h.update(digest(sp.sympify(e)))
    for s in extra:
        h.update(b"\0" + s.encode())
    return h.hexdigest()[:_ID_LEN]


def memoized_source(tag: str, make) -> str:
    """The source generated earlier for ``tag`` (checked against its stored SHA-256), else ``make()`` (stored)."""
    path = cache_dir() / f"source_{tag}.c"
    try:
        stored_digest, text = path.read_text().split("\n", 1)
        if hashlib.sha256(text.encode()).hexdigest() == stored_digest:
            return text
    except (OSError, ValueError):
        pass
    text = make()
    try:
        cache_dir().mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile("w", dir=cache_dir(), prefix=".source_", delete=False) as fh:
            fh.write(hashlib.sha256(text.encode()).hexdigest() + "\n" + text)
        os.replace(fh.name, path)
    except OSError:
        pass  # an unwritable cache only costs time
    return text
