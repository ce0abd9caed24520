"""Deprecated names: each old name warns once (``DeprecationWarning``) and forwards to the new one.

Old names stay importable for one release so that code written against the earlier spelling keeps working.
"""

from __future__ import annotations

import functools
import types
import warnings
from collections.abc import Callable, Mapping
from typing import Any

_warned: set[str] = set()


def warn_deprecated(old: str, new: str, *, stacklevel: int = 3) -> None:
    """Emit one ``DeprecationWarning`` per old name and process: ``old`` is deprecated, use ``new``."""
    if old in _warned:
        return
    _warned.add(old)
    warnings.warn(
        f"{old} is deprecated and will be removed in the next release; use {new}",
        DeprecationWarning,
        stacklevel=stacklevel,
    )


def reset_warnings() -> None:
    """Forget which names already warned (for tests that check the warning)."""
    _warned.clear()


def module_getattr(module: str, aliases: Mapping[str, str], namespace: dict[str, Any]) -> Callable[[str], Any]:
    """A module ``__getattr__`` that resolves the deprecated ``aliases`` (old -> new name in ``namespace``)."""

    def __getattr__(name: str) -> Any:
        if name in aliases:
            new = aliases[name]
            warn_deprecated(f"{module}.{name}", f"{module}.{new}")
            return namespace[new]
        raise AttributeError(f"module {module!r} has no attribute {name!r}")

    return __getattr__


def renamed_keyword(renames: Mapping[str, str]) -> Callable[[Callable], Callable]:
    """Decorator: the old keyword names in ``renames`` (old -> new) still work, with a warning."""

    def decorate(func: Callable) -> Callable:
        @functools.wraps(func)
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            for old, new in renames.items():
                if old in kwargs:
                    if new in kwargs:
                        from .errors import ParameterError

                        raise ParameterError(f"{func.__name__}: pass {new}= only ({old}= is its deprecated old name)")
                    warn_deprecated(f"{func.__name__}({old}=...)", f"{func.__name__}({new}=...)")
                    kwargs[new] = kwargs.pop(old)
            return func(*args, **kwargs)

        wrapper.__symosc_renamed_keywords__ = {**getattr(func, "__symosc_renamed_keywords__", {}), **renames}
        return wrapper

    return decorate


def deprecated_attribute(new: str) -> Any:
    """A deprecated attribute or method alias: ``old = deprecated_attribute("new")`` inside a class body."""

    class _Alias:
        __doc__ = f"Deprecated alias of ``{new}``."

        def __set_name__(self, owner: type, name: str) -> None:
            self.old = name
            self.owner = owner.__name__

        def __get__(self, obj: Any, objtype: type | None = None) -> Any:
            if obj is None:  # on the class (documentation tools): the alias itself
                return self
            warn_deprecated(f"{self.owner}.{self.old}", f"{self.owner}.{new}")
            return getattr(obj, new)

    return _Alias()


class _ModuleAliases:
    """Import finder for moved modules: ``import old.path`` warns once and gives the module now at the new path.

    The table is declared where the modules moved (:func:`moved_modules`); nothing is imported until an old path is.
    """

    def __init__(self) -> None:
        self.table: dict[str, str] = {}

    def find_spec(self, fullname: str, path: Any = None, target: Any = None) -> Any:
        if fullname not in self.table:
            return None
        import importlib.util

        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec: Any) -> None:
        return None  # a placeholder module; exec_module replaces it in sys.modules by the moved one

    def exec_module(self, module: Any) -> None:
        import importlib
        import sys

        new = self.table[module.__name__]
        warn_deprecated(f"the module path {module.__name__}", new, stacklevel=3)
        sys.modules[module.__name__] = importlib.import_module(new)


_ALIASES = _ModuleAliases()


class _PackageKeepingNames(types.ModuleType):
    """A package whose old module paths share a name with a public function (``symosc.nonlinear.lindstedt``):
    importing the old path does not replace the function on the package by the module."""

    def __setattr__(self, name: str, value: Any) -> None:
        if isinstance(value, types.ModuleType) and f"{self.__name__}.{name}" in _ALIASES.table:
            return
        super().__setattr__(name, value)


def moved_modules(package: str, moves: Mapping[str, str]) -> None:
    """Keep the old module paths ``package.old`` importable (deprecated) after the modules moved to ``package.new``.

    ``moves`` maps old to new names relative to ``package`` (for example ``{"poincare": "series.poincare"}``).  An
    old path named like a public function of the package leaves that function in place.
    """
    import sys

    _ALIASES.table.update({f"{package}.{old}": f"{package}.{new}" for old, new in moves.items()})
    if _ALIASES not in sys.meta_path:
        sys.meta_path.append(_ALIASES)
    sys.modules[package].__class__ = _PackageKeepingNames
