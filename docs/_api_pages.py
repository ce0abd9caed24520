"""Discover symosc's public API and write the API reference pages (imported by ``conf.py``).

A module is public when no part of its dotted path starts with ``_``; its public names are its ``__all__``.  The
modules are discovered by walking the installed package (so a new subpackage, such as ``continuation``, is
covered without being listed anywhere).  An object exported by several modules (``symosc.nonlinear.limit_cycle``
is also ``symosc.nonlinear.series.limit_cycle``) is documented once, at its shortest public path, and every page
of a module lists the names whose home it is.
"""

from __future__ import annotations

import importlib
import pkgutil
import types
from pathlib import Path


def public_modules() -> list[str]:
    """Every importable public module of symosc (``symosc`` first, then sorted)."""
    import symosc

    found = []
    for info in pkgutil.walk_packages(symosc.__path__, "symosc."):
        if not any(part.startswith("_") for part in info.name.split(".")[1:]):
            found.append(info.name)
    return ["symosc", *sorted(found)]


def api_homes() -> dict[str, list[str]]:
    """``{module: [names]}``: where each public object is documented (its shortest public path)."""
    homes: dict[int, tuple[int, str, str]] = {}
    for modname in public_modules():
        mod = importlib.import_module(modname)
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name)
            if isinstance(obj, types.ModuleType):
                continue
            candidate = (modname.count("."), modname, name)
            if id(obj) not in homes or candidate < homes[id(obj)]:
                homes[id(obj)] = candidate
    out: dict[str, list[str]] = {}
    for _, modname, name in sorted(homes.values(), key=lambda c: (c[1], c[2])):
        out.setdefault(modname, []).append(name)
    return out


def write_api_pages(api: Path) -> dict[str, list[str]]:
    """One page per module that is the home of public objects, with an autosummary of them; an index page."""
    api.mkdir(exist_ok=True)
    for stale in [*(api / "generated").glob("*.rst"), *api.glob("symosc*.rst")]:
        stale.unlink()  # pages of names no longer public are rebuilt, not kept
    homes = api_homes()
    index = ["API reference", "=============", "", "Every public object, generated from the docstrings.", ""]
    index += [".. toctree::", "   :maxdepth: 1", ""] + [f"   {m}" for m in homes]
    (api / "index.rst").write_text("\n".join(index) + "\n")
    objects = {f"{modname}.{name}" for modname, names in homes.items() for name in names}
    for modname, names in homes.items():
        lines = [f"``{modname}``", "=" * (len(modname) + 4), "", f".. automodule:: {modname}", "   :no-members:"]
        # a module named like a function it exports (symosc.sweep.sweep is symosc.sweep): the function is indexed
        lines += ["   :no-index:", ""] if modname in objects else [""]
        lines += [f".. currentmodule:: {modname}", "", ".. autosummary::", "   :toctree: generated", ""]
        lines += [f"   {n}" for n in names]
        (api / f"{modname}.rst").write_text("\n".join(lines) + "\n")
    return homes
