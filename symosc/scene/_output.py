"""Output folders written whole or not at all (private).

A run writes into a fresh hidden sibling of the output folder and, when everything is written, puts it in place of
the old folder with one atomic exchange of the two names (``renameat2(RENAME_EXCHANGE)`` on Linux; elsewhere two
renames in a row), then deletes the old one.  A run that fails or is killed before the exchange leaves the output
folder exactly as it was; a hidden sibling left by a killed run is removed by the next run.  Only folders that a
run wrote (they hold the marker file) or empty ones are ever replaced, so ``-o .`` cannot wipe a working folder.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import os
import shutil
import tempfile
from collections.abc import Iterator
from pathlib import Path

from ..errors import ParameterError

#: written into every output folder: a folder holding it (or an empty one) may be replaced by the next run
MARKER = ".symosc-output"
_PREFIX = ".symosc-"


def check_output_folder(outdir: str | os.PathLike) -> Path:
    """``outdir`` as a Path, refused before any work when it cannot be replaced by a run's output.

    Raises
    ------
    ParameterError
        ``outdir`` is a file, holds files a run did not write, or its parent folder is not writable.
    """
    out = Path(outdir)
    if out.exists():
        if not out.is_dir():
            raise ParameterError(f"the output folder {out} is a file; give a folder name")
        if any(out.iterdir()) and not (out / MARKER).is_file():
            raise ParameterError(
                f"the output folder {out} holds files that symosc did not write; give a new or empty folder "
                "(a run replaces its output folder as a whole)"
            )
    parent = out.absolute().parent
    probe = parent
    while not probe.exists():
        probe = probe.parent
    if not os.access(probe, os.W_OK | os.X_OK):
        raise ParameterError(f"cannot write the output folder {out}: {probe} is not writable")
    return out


def _exchange(a: Path, b: Path) -> bool:
    """Swap the names ``a`` and ``b`` atomically (Linux ``renameat2``); False where that is not available."""
    name = ctypes.util.find_library("c")
    if name is None or not hasattr(os, "fsencode"):
        return False
    try:
        libc = ctypes.CDLL(name, use_errno=True)
        renameat2 = libc.renameat2
    except (OSError, AttributeError):
        return False
    at_fdcwd, rename_exchange = -100, 2
    renameat2.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
    if renameat2(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange) == 0:
        return True
    return False


def _remove_stale(parent: Path, name: str) -> None:
    """Hidden siblings of ``name`` left by runs that were killed (their process is gone)."""
    for p in parent.glob(f"{_PREFIX}{name}-*"):
        pid = p.name.rsplit("-", 2)[-2] if p.name.count("-") >= 2 else ""
        if pid.isdigit() and int(pid) != os.getpid():
            try:
                os.kill(int(pid), 0)
            except ProcessLookupError:
                shutil.rmtree(p, ignore_errors=True)
            except PermissionError:  # another user's live process
                pass


@contextlib.contextmanager
def replacing_folder(outdir: str | os.PathLike) -> Iterator[Path]:
    """Yield a fresh folder to write into; on success it becomes ``outdir`` (the old one is deleted), on an
    exception it is deleted and ``outdir`` is left as it was."""
    out = check_output_folder(outdir)
    parent = out.absolute().parent
    parent.mkdir(parents=True, exist_ok=True)
    _remove_stale(parent, out.name)
    new = Path(tempfile.mkdtemp(dir=parent, prefix=f"{_PREFIX}{out.name}-{os.getpid()}-"))
    try:
        yield new
        (new / MARKER).write_text("written by symosc run; the next run replaces this folder as a whole\n")
        if not out.exists():
            os.replace(new, out)
            return
        if _exchange(new, out):
            shutil.rmtree(new)  # the old output, now under the hidden name
            return
        old = Path(tempfile.mkdtemp(dir=parent, prefix=f"{_PREFIX}{out.name}-{os.getpid()}-old"))
        os.rmdir(old)
        os.replace(out, old)
        os.replace(new, out)
        shutil.rmtree(old, ignore_errors=True)
    except BaseException:
        shutil.rmtree(new, ignore_errors=True)
        raise
