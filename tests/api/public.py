"""Discover symosc's public API by walking the subpackages' ``__all__`` (so new subpackages are covered too)."""

from __future__ import annotations

import doctest
import importlib
import importlib.util
import inspect
import pkgutil
import re
import time
from functools import cache
from typing import Any

import symosc


def subpackages() -> list[str]:
    """Installed ``symosc.<name>`` subpackages (the lazily imported ones), without the command line."""
    return [f"symosc.{n}" for n in symosc._installed_subpackages() if n != "cli"]


@cache
def public_objects() -> tuple[tuple[str, str, Any], ...]:
    """``(module, name, object)`` for every name in ``symosc.__all__`` and each subpackage's ``__all__``."""
    out = []
    for modname in ["symosc", *subpackages()]:
        mod = importlib.import_module(modname)
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name)
            if not inspect.ismodule(obj):
                out.append((modname, name, obj))
    return tuple(out)


@cache
def all_public_exports() -> tuple[tuple[str, str, Any], ...]:
    """``(module, name, object)`` for every name in the ``__all__`` of every public module: each importable module of
    symosc with no ``_`` part in its dotted path (found by walking the package, deeper modules included)."""
    modules = ["symosc"]
    for info in pkgutil.walk_packages(symosc.__path__, "symosc."):
        if not any(part.startswith("_") for part in info.name.split(".")[1:]):
            modules.append(info.name)
    out = []
    for modname in modules:
        mod = importlib.import_module(modname)
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name)
            if not inspect.ismodule(obj):
                out.append((modname, name, obj))
    return tuple(out)


def public_classes() -> tuple[type, ...]:
    """Public classes that are models or results (not exceptions)."""
    seen: dict[type, None] = {}
    for _, _, obj in public_objects():
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            seen[obj] = None
    return tuple(seen)


def _collect(value: Any, classes: tuple[type, ...], found: dict[type, Any], depth: int = 0) -> None:
    """Record instances of ``classes`` in ``value``, its items and its fields (two levels deep)."""
    if isinstance(value, classes):
        for cls in type(value).__mro__:
            if cls in classes:
                found.setdefault(cls, value)
    if depth >= 2 or isinstance(value, str | bytes | type) or inspect.ismodule(value):
        return
    if isinstance(value, list | tuple):
        children = list(value[:20])
    elif isinstance(value, dict):
        children = list(value.values())[:20]
    elif isinstance(value, classes):
        children = list(getattr(value, "__dict__", {}).values())
    else:
        return
    for v in children:
        _collect(v, classes, found, depth + 1)


def _return_text(obj: Any) -> str:
    """The return annotation of ``obj`` (function or method) as text ("" when it has none)."""
    try:
        ann = inspect.signature(obj).return_annotation
    except (TypeError, ValueError):
        return ""
    return str(ann if isinstance(ann, str) else getattr(ann, "__name__", str(ann)))


@cache
def _annotated_callables() -> tuple[tuple[str, Any, str], ...]:
    """``(qualified name, callable or property, return annotation text)`` for every public function and every
    method or property of a public class (read once: ``inspect.signature`` over the whole API takes seconds)."""
    out = []
    for modname, name, obj in public_objects():
        if inspect.isfunction(obj):
            out.append((f"{modname}.{name}", obj, _return_text(obj)))
        elif inspect.isclass(obj):
            for mname, meth in vars(obj).items():
                if inspect.isfunction(meth) or isinstance(meth, property):
                    text = _return_text(meth.fget if isinstance(meth, property) else meth)
                    out.append((f"{modname}.{name}.{mname}", meth, text))
    return tuple(out)


def _producers(cls: type) -> list[tuple[str, Any]]:
    """Where the documentation builds ``cls``: the class itself, then public callables annotated to return it
    (alone or inside a container)."""
    pattern = re.compile(rf"\b{cls.__name__}\b")
    out: list[tuple[str, Any]] = [(f"{cls.__module__}.{cls.__qualname__}", cls)]
    out += [(qualname, obj) for qualname, obj, text in _annotated_callables() if pattern.search(text)]
    return out


@cache
def example_instances() -> dict[type, Any]:
    """One instance of each public class, taken from the documented examples (docstring doctests).

    For each class, the doctests of the class and of the public functions annotated to return it are run (output
    discarded) until an instance turns up; the examples are the documentation's own, so a class that no example
    builds is reported missing rather than hidden.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .examples import FACTORIES

    classes = public_classes()
    found: dict[type, Any] = {}
    for cls in classes:
        if cls.__name__ in FACTORIES:
            _collect(FACTORIES[cls.__name__](), classes, found)
    finder = doctest.DocTestFinder(exclude_empty=True, recurse=False)
    runner = doctest.DocTestRunner(verbose=False, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    done: set[str] = set()
    for cls in classes:
        for qualname, obj in _producers(cls):
            if cls in found:
                break
            if qualname in done:
                continue
            done.add(qualname)
            target = obj.fget if isinstance(obj, property) else obj
            mod = inspect.getmodule(target)
            try:
                tests = finder.find(target, qualname, module=mod, globs=dict(vars(mod)) if mod else {})
            except ValueError:
                continue
            for test in tests:
                runner.run(test, out=lambda s: None, clear_globs=False)
                for k, v in list(test.globs.items()):
                    if mod is None or vars(mod).get(k) is not v:  # only what the example built
                        _collect(v, classes, found)
            plt.close("all")
    return found


if __name__ == "__main__":
    t0 = time.perf_counter()
    inst = example_instances()
    print(f"{time.perf_counter() - t0:.1f} s, {len(inst)} of {len(public_classes())} classes")
    print([c.__name__ for c in public_classes() if c not in inst])
