"""Every public function, constructor and method documents each of its parameters, and every public function checks
its arguments where it is defined (no wrapper is applied to a module from outside)."""

from __future__ import annotations

import ast
import dataclasses
import inspect
from pathlib import Path

from symosc._validate import _docstring_parameters

from .public import public_objects

PACKAGE = Path(__file__).resolve().parents[2] / "symosc"


def _callables():
    """``(label, function, docstring owner)`` for public functions, constructors and public methods."""
    seen = set()
    for modname, name, obj in public_objects():
        found = []
        if inspect.isfunction(obj):
            found.append((f"{modname}.{name}", obj, obj))
        elif inspect.isclass(obj) and not issubclass(obj, BaseException):
            init = obj.__dict__.get("__init__")
            if inspect.isfunction(init):
                found.append((f"{modname}.{name}", init, obj))
            for attr, member in vars(obj).items():
                if not attr.startswith("_") and inspect.isfunction(member):
                    found.append((f"{modname}.{name}.{attr}", member, member))
        for label, fn, owner in found:
            key = (inspect.unwrap(fn).__module__, inspect.unwrap(fn).__qualname__)
            if key not in seen:
                seen.add(key)
                yield label, fn, owner


def _documented(fn, owner) -> set[str]:
    names = set(_docstring_parameters(inspect.getdoc(owner) or ""))
    if owner is not fn:  # a constructor: the class docstring, its own, and a dataclass's "Attributes"
        names |= set(_docstring_parameters(inspect.getdoc(fn) or ""))
        if dataclasses.is_dataclass(owner):
            attributes = (inspect.getdoc(owner) or "").replace("Attributes\n----------", "Parameters\n----------")
            names |= set(_docstring_parameters(attributes))
    return names


def test_every_public_parameter_is_documented():
    missing = {}
    for label, fn, owner in _callables():
        params = inspect.signature(fn).parameters
        documented = _documented(fn, owner)
        absent = [
            p
            for p, par in params.items()
            if p not in ("self", "cls") and par.kind is not par.VAR_KEYWORD and p not in documented
        ]
        if absent:
            missing[label] = absent
    assert missing == {}


def test_the_documentation_check_can_fail():
    def f(x: float, y: float) -> float:
        """Toy.

        Parameters
        ----------
        x : float
            The first.
        """
        return x + y

    assert _documented(f, f) == {"x"}


#: hot scalar paths without the decorator's cost: they accept exact int/float arguments in a fast path and hand
#: everything else to a validated function (``mathieu_characteristic``)
HOT_PATHS = {"symosc.periodic.mathieu_a", "symosc.periodic.mathieu_b"}


def test_public_functions_check_their_arguments_where_they_are_defined():
    """Every public function of an analysis subpackage carries ``@validated`` (or checks in its own body), and no
    package replaces attributes of a module at import time."""
    unchecked = [
        f"{modname}.{name}"
        for modname, name, obj in public_objects()
        if inspect.isfunction(obj)
        and modname.split(".")[1:2]
        in (
            ["algebra"],
            ["linear"],
            ["mechanics"],
            ["models"],
            ["networks"],
            ["operational"],
            ["periodic"],
            ["identification"],
            ["nonlinear"],
            ["continuation"],
        )
        and not getattr(obj, "__symosc_validated__", False)
        and "ParameterError" not in inspect.getsource(inspect.unwrap(obj))
        and f"{modname}.{name}" not in HOT_PATHS
    ]
    assert unchecked == []
    rewriting = []
    for path in PACKAGE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Call) and ast.unparse(node.func).endswith(("setattr", "guard_public_api")):
                target = ast.unparse(node.args[0]) if node.args else ""
                if "sys.modules" in target or target in ("pkg", "home", "module", "mod"):
                    rewriting.append(f"{path.relative_to(PACKAGE.parent)}:{node.lineno}")
    assert rewriting == []
