"""Build C sources into shared libraries, cached on disk, and load them with ctypes.

The cache directory is ``$SYMOSC_CACHE_DIR`` if set, else ``$XDG_CACHE_HOME/symosc``, else
``~/.cache/symosc``; it is created private (mode 0700).  A library is named by a hash of its source, the compiler
flags and the compiler's version, carries that hash in the symbol ``symosc_build_id``, and has beside it a digest
of its bytes keyed by the full hash of the source it was built from (HMAC-SHA256).  Before anything is loaded, the
folder and the files must belong to the current user and must not be writable by other users; a library whose
digest does not match (corrupted, truncated, or replaced by another library), that does not load, or that carries
another id is rebuilt, never used.  Builds write to a temporary file and ``os.replace`` it into place, so
concurrent processes building the same library all succeed.

A source of one translation unit is compiled and linked by one compiler process.  A source made of several
(separated by :data:`UNIT_MARKER`) is compiled unit by unit in parallel (one compiler process per core) and
linked.  Generated code is compiled with :data:`GENERATED_FLAGS`, and with GCC also :data:`GCC_GENERATED_FLAGS`
(and :data:`GCC_KERNEL_FLAGS` for the units after the first, which hold straight-line code only).
With GCC on Linux generated code is linked against the math library alone (:data:`LEAN_LIBS`; the C library is in
every Python process already), which takes two thirds of the time of the default link; a library so linked that
does not load is linked again the default way.

The compiler is ``$SYMOSC_CC``, else ``$CC``, else ``cc``.
"""

from __future__ import annotations

import ctypes
import functools
import hashlib
import hmac
import os
import shlex
import shutil
import stat
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

from ..errors import SymoscError

FLAGS = ("-O2", "-std=c99", "-fPIC", "-shared")
#: Flags for generated straight-line code: ``-O1`` runs it as fast as ``-O2`` and builds in about 60 % of the time;
#: ``-fno-math-errno`` (no ``errno`` from math functions; results unchanged) lets the compiler evaluate ``sin`` and
#: ``cos`` of one angle together and ``sqrt`` inline.
GENERATED_FLAGS = ("-O1", "-fno-math-errno", "-Werror=implicit-function-declaration", "-std=c99", "-fPIC", "-shared")
#: Added to :data:`GENERATED_FLAGS` when the compiler is GCC: dead-store elimination and full redundancy elimination
#: (tree and RTL) test every store or load against the earlier ones, which grows with the square of the length of a
#: straight-line function and finds nothing in code that is already free of common subexpressions.  They cut the
#: build of the n = 10 and 20 pendulums' right-hand sides and Jacobians by 10-15 % (GCC 12) and their run time per
#: call not at all (measured to 1 %).
GCC_GENERATED_FLAGS = ("-fno-tree-dse", "-fno-dse", "-fno-tree-fre")
#: Added for the units after the first of generated code built by GCC, which hold straight-line kernel code only
#: (:func:`symosc.numeric._c.kernel_units`): points-to analysis, constant propagation, the dominator optimizations
#: and RTL copy and forward propagation find nothing there either (run time per call unchanged to 1 %) and cost
#: another 10-30 % of its build time.  The first unit, which holds the solver's loops, keeps them.
GCC_KERNEL_FLAGS = (
    "-fno-tree-pta",
    "-fno-tree-ccp",
    "-fno-ipa-modref",
    "-fno-tree-dominator-opts",
    "-fno-cprop-registers",
    "-fno-forward-propagate",
)
LIBS = ("-lm",)
#: The libraries of a GCC link of generated code on Linux: the math library and GCC's support library, not the C
#: library (``-nodefaultlibs``: reading ``libc.so`` is most of the default link's time); the C library's symbols
#: are resolved in the loading process, which has it.
LEAN_LIBS = ("-nodefaultlibs", "-lm", "-lgcc")
UNIT_MARKER = "/* ---- symosc: a new translation unit starts here ---- */"
_ID_LEN = 24
_loaded: dict[str, ctypes.CDLL] = {}
_lock = threading.Lock()


class CompilerError(SymoscError, RuntimeError):
    """No working C compiler, the generated C code did not compile, or the cache folder is not private."""


def cache_dir() -> Path:
    """The directory holding compiled libraries (created on first use, private to the user)."""
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
def _compiler_banner(cc: str) -> str:
    try:
        out = subprocess.run([cc, "--version"], capture_output=True, text=True, timeout=30, check=False)
    except OSError as exc:
        raise CompilerError(f"the C compiler {cc} does not run: {exc}") from exc
    return out.stdout or out.stderr or cc


def _compiler_version(cc: str) -> str:
    return _compiler_banner(cc).splitlines()[0]


def _is_gcc(cc: str) -> bool:
    """True for GCC (its banner names the Free Software Foundation; Clang's, even when called ``gcc``, does not)."""
    banner = _compiler_banner(cc)
    return "Free Software Foundation" in banner and "clang" not in banner.lower()


def _unit_flags(cc: str, flags: tuple[str, ...]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """The flags of the first translation unit and of the others: ``flags``, and for generated code built by GCC
    :data:`GCC_GENERATED_FLAGS`, and :data:`GCC_KERNEL_FLAGS` for the units after the first."""
    if flags == GENERATED_FLAGS and _is_gcc(cc):
        return flags + GCC_GENERATED_FLAGS, flags + GCC_GENERATED_FLAGS + GCC_KERNEL_FLAGS
    return flags, flags


def _hashed_flags(cc: str, flags: tuple[str, ...]) -> tuple[str, ...]:
    first, rest = _unit_flags(cc, flags)
    return first if rest == first else (*first, "--other-units", *rest)


def _libs(cc: str, flags: tuple[str, ...]) -> tuple[str, ...]:
    """The link's libraries: :data:`LEAN_LIBS` for generated code built by GCC on Linux, else :data:`LIBS`."""
    return LEAN_LIBS if flags == GENERATED_FLAGS and sys.platform.startswith("linux") and _is_gcc(cc) else LIBS


def _source_hash(source: str, flags: tuple[str, ...], cc: str) -> bytes:
    text = "\0".join([source, " ".join(flags + LIBS), _compiler_version(cc)])
    return hashlib.sha256(text.encode()).digest()


def build_id(source: str, flags: tuple[str, ...] = FLAGS) -> tuple[str, str]:
    """The cache key of ``source`` for the current compiler and ``flags``, and the compiler path."""
    cc = compiler()
    return _source_hash(source, _hashed_flags(cc, flags), cc).hex()[:_ID_LEN], cc


def check_private(path: Path, what: str = "cache folder") -> None:
    """Raise :class:`CompilerError` unless ``path`` belongs to the current user and only they can write it.

    Code is loaded from the cache: a folder (or file) that another user can write could hold their code.
    """
    if not hasattr(os, "getuid"):  # no POSIX ownership (Windows): nothing to check
        return
    try:
        st = os.lstat(path)
    except OSError as exc:
        raise CompilerError(f"cannot inspect the {what} {path}: {exc}") from exc
    if what != "cache folder" and stat.S_ISLNK(st.st_mode):
        raise CompilerError(f"the {what} {path} is a symbolic link; symosc loads compiled code only from its own files")
    if st.st_uid != os.getuid():
        raise CompilerError(
            f"the {what} {path} belongs to another user (uid {st.st_uid}); symosc loads compiled code only from a "
            "folder of your own: set SYMOSC_CACHE_DIR to one"
        )
    if st.st_mode & (stat.S_IWGRP | stat.S_IWOTH):
        raise CompilerError(
            f"the {what} {path} is writable by other users (mode {stat.S_IMODE(st.st_mode):o}); symosc does not load "
            f"compiled code from it: run `chmod go-w {path}` or set SYMOSC_CACHE_DIR to a private folder"
        )


def _private_cache() -> Path:
    """The cache folder, created with mode 0700 when missing, and checked (:func:`check_private`)."""
    directory = cache_dir()
    if not directory.exists():
        try:
            directory.mkdir(mode=0o700, parents=True, exist_ok=True)
        except OSError as exc:
            raise CompilerError(f"cannot create the cache directory {directory} ({exc}); set SYMOSC_CACHE_DIR") from exc
    check_private(directory.resolve())
    return directory


def load(source: str, flags: tuple[str, ...] = FLAGS) -> ctypes.CDLL:
    """The shared library built from ``source`` with ``flags`` (from memory, from the disk cache, or freshly
    built)."""
    cc = compiler()
    full = _source_hash(source, _hashed_flags(cc, flags), cc)
    key = full.hex()[:_ID_LEN]
    with _lock:
        lib = _loaded.get(key)
        if lib is not None:
            return lib
        directory = _private_cache()
        path = directory / f"symosc_{key}.so"
        lib = _try_load(path, key, full)
        if lib is None:
            units = source.split(f"\n{UNIT_MARKER}\n")
            units[0] += f'\nconst char symosc_build_id[] = "{key}";\n'
            libs = _libs(cc, flags)
            _compile(cc, _unit_flags(cc, flags), units, directory, path, full, libs)
            lib = _try_load(path, key, full)
            if lib is None and libs != LIBS:  # e.g. a symbol of a library that -nodefaultlibs left out
                _compile(cc, _unit_flags(cc, flags), units, directory, path, full, LIBS)
                lib = _try_load(path, key, full)
            if lib is None:
                raise CompilerError(f"the library {path} was built but does not load")
        _loaded[key] = lib
        return lib


def _digest_path(path: Path) -> Path:
    return path.with_name(path.name + ".sha256")


def _keyed_digest(key: bytes, data: bytes) -> str:
    return hmac.new(key, data, hashlib.sha256).hexdigest()


def _try_load(path: Path, key: str, full: bytes) -> ctypes.CDLL | None:
    """Load ``path`` if it is the user's own, its bytes match the digest keyed by ``full`` (the hash of the source
    it must have been built from) and it carries ``key``; never dlopen a damaged or foreign file."""
    if not path.exists():
        return None
    check_private(path, "cached library")
    if _digest_path(path).exists():
        check_private(_digest_path(path), "digest file")
    try:
        data = path.read_bytes()
        digest = _digest_path(path).read_text().strip()
    except OSError:
        return None
    if not hmac.compare_digest(_keyed_digest(full, data), digest):
        return None
    try:
        lib = ctypes.CDLL(str(path))
        stored = (ctypes.c_char * (_ID_LEN + 1)).in_dll(lib, "symosc_build_id").value.decode()
    except (OSError, ValueError, UnicodeDecodeError):
        return None
    return lib if stored == key else None


def _run(cmd: list[str]) -> subprocess.Popen:
    try:
        return subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    except OSError as exc:
        raise CompilerError(f"the C compiler failed to run: {' '.join(cmd)}: {exc}") from exc


def _finish(proc: subprocess.Popen, cmd: list[str], out: Path) -> None:
    try:
        _, err = proc.communicate(timeout=1800)
    except subprocess.TimeoutExpired as exc:
        proc.kill()
        raise CompilerError(f"the C compiler did not finish: {' '.join(cmd)}") from exc
    if proc.returncode != 0 or not out.exists():
        tail = "\n".join(err.strip().splitlines()[-15:])
        raise CompilerError(f"C compilation failed ({' '.join(cmd)}):\n{tail}")


def _compile(
    cc: str,
    flags: tuple[tuple[str, ...], tuple[str, ...]],
    units: list[str],
    directory: Path,
    path: Path,
    full: bytes,
    libs: tuple[str, ...],
) -> None:
    """Build ``path`` from ``units`` (``flags``: of the first unit and of the others, see :func:`_unit_flags`)."""
    with tempfile.TemporaryDirectory(dir=directory, prefix=".build_") as tmp:
        out = Path(tmp) / path.name
        sources = []
        for i, text in enumerate(units):
            src = Path(tmp) / f"symosc_{i}.c"
            src.write_text(text)
            sources.append(src)
        if len(sources) == 1:  # compile and link in one process
            cmd = [cc, *flags[0], "-o", str(out), str(sources[0]), *libs]
            _finish(_run(cmd), cmd, out)
        else:
            # One compiler process per unit, as many at a time as there are cores; then one link.
            objects = [src.with_suffix(".o") for src in sources]
            jobs = max(1, os.cpu_count() or 1)
            running: list[tuple[subprocess.Popen, list[str], Path]] = []
            for i, (src, obj) in enumerate(zip(sources, objects, strict=True)):
                if len(running) >= jobs:
                    _finish(*running.pop(0))
                unit_flags = [f for f in flags[min(i, 1)] if f != "-shared"]
                cmd = [cc, *unit_flags, "-c", "-o", str(obj), str(src)]
                running.append((_run(cmd), cmd, obj))
            for job in running:
                _finish(*job)
            cmd = [cc, "-shared", "-o", str(out), *map(str, objects), *libs]
            _finish(_run(cmd), cmd, out)
        digest = Path(tmp) / "digest"
        digest.write_text(_keyed_digest(full, out.read_bytes()))
        # Atomic renames: a concurrent builder or reader sees either the old files or complete new ones (a
        # library and a digest from two builders that differ only make a reader rebuild once more).
        os.replace(out, path)
        os.replace(digest, _digest_path(path))


def clear_memory_cache() -> None:
    """Forget the libraries loaded in this process (the disk cache is kept); used by the tests."""
    with _lock:
        _loaded.clear()


CODEGEN_VERSION = "3"  # bump when generated code changes for the same expressions


def expression_digest(exprs: list, *extra: str) -> str:
    """A process-independent digest of SymPy expressions (shared subtrees hashed once) and ``extra`` strings.

    Used to find previously generated source without generating it again, so that a cached rebuild costs
    milliseconds even for large systems.
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
    """The source generated earlier for ``tag`` (the user's own file, its digest keyed by ``tag``), else
    ``make()`` (stored)."""
    key = tag.encode()
    try:
        directory = _private_cache()
    except CompilerError:
        return make()  # the library build reports the folder's problem
    path = directory / f"source_{tag}.c"
    try:
        if path.exists():
            check_private(path, "cached source")
            stored_digest, text = path.read_text().split("\n", 1)
            if hmac.compare_digest(_keyed_digest(key, text.encode()), stored_digest):
                return text
    except (OSError, ValueError, CompilerError):
        pass
    text = make()
    try:
        with tempfile.NamedTemporaryFile("w", dir=directory, prefix=".source_", delete=False) as fh:
            fh.write(_keyed_digest(key, text.encode()) + "\n" + text)
        os.replace(fh.name, path)
    except OSError:
        pass  # an unwritable cache only costs time
    return text
