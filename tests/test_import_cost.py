"""Import-time regression check: which modules each public subpackage imports (not how long it takes).

SciPy submodules and optional libraries must be imported inside the functions that use them, so that
``import symosc.<subpackage>`` costs little more than SymPy itself.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: never imported by ``import symosc.<subpackage>``
HEAVY = ("scipy", "matplotlib", "pandas", "xarray", "dask", "distributed", "tqdm", "numba", "symengine", "control")


def imported_modules(statement: str) -> set[str]:
    """Module names listed by ``python -X importtime -c statement`` in a fresh interpreter."""
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    proc = subprocess.run(
        [sys.executable, "-X", "importtime", "-c", statement], capture_output=True, text=True, env=env, check=True
    )
    names = set()
    for line in proc.stderr.splitlines():
        if line.startswith("import time:") and "|" in line:
            name = line.rsplit("|", 1)[1].strip()
            if name != "imported package":
                names.add(name)
    return names


SUBPACKAGES = (
    "symosc",
    "symosc.models",
    "symosc.periodic",
    "symosc.nonlinear",
    "symosc.identification",
    "symosc.algebra",
    "symosc.linear",
    "symosc.networks",
    "symosc.operational",
    "symosc.mechanics",
    "symosc.continuation",
)


def _heavy(names: set[str]) -> list[str]:
    return sorted(n for n in names if n.split(".")[0] in HEAVY)


def test_subpackages_import_no_scipy_and_no_optional_library():
    """All subpackages imported in one fresh interpreter: what each imports is a subset of what all import, so no
    heavy module among all means none for any of them (a failure names the subpackages that import one, each in a
    fresh interpreter of its own)."""
    names = imported_modules("import " + ", ".join(SUBPACKAGES))
    assert set(SUBPACKAGES) <= names  # the parser sees the imports themselves
    heavy = _heavy(names)
    culprits = {module: _heavy(imported_modules(f"import {module}")) for module in SUBPACKAGES} if heavy else {}
    assert heavy == [], {module: found for module, found in culprits.items() if found}


def test_the_parser_sees_a_scipy_import():
    """The check above can fail: a module that does import SciPy is reported."""
    names = imported_modules("import symosc.periodic; symosc.periodic.mathieu_mc(1, 3, 2.5, 0.5)")  # Bessel functions
    assert "scipy.special" in names


def loaded_modules(statement: str) -> set[str]:
    """``sys.modules`` after ``statement`` in a fresh interpreter (also modules loaded by importlib)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    code = f"{statement}; import sys; print(' '.join(sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True).stdout
    return set(out.split())


def test_nonlinear_loads_its_families_on_first_use():
    """``import symosc.nonlinear`` loads none of its modules; ``limit_cycle`` loads the series family only."""
    bare = {n for n in loaded_modules("import symosc.nonlinear") if n.startswith("symosc.nonlinear.")}
    assert bare == set()
    used = {n for n in loaded_modules("import symosc.nonlinear as nl; nl.limit_cycle") if n.startswith("symosc.")}
    assert "symosc.nonlinear.series.poincare" in used
    assert not {n for n in used if n.split(".")[2:3] in (["delay"], ["averaging"], ["harmonic"], ["special"])}


def test_nonlinear_public_names_are_the_functions_after_old_module_paths_are_imported():
    """Importing an old module path named like its function (``lindstedt``) does not replace the function on the
    package, and the old path gives the moved module (with a deprecation warning)."""
    code = (
        "import warnings; warnings.simplefilter('error', DeprecationWarning)\n"
        "import symosc.nonlinear as nl, inspect\n"
        "try:\n    import symosc.nonlinear.lindstedt\nexcept DeprecationWarning as w:\n    assert 'series' in str(w)\n"
        "else:\n    raise SystemExit('no warning')\n"
        "warnings.simplefilter('ignore', DeprecationWarning)\n"
        "import symosc.nonlinear.lindstedt, symosc.nonlinear.harmonic_linearization\n"
        "import sys; modules = sys.modules\n"
        "assert modules['symosc.nonlinear.lindstedt'] is modules['symosc.nonlinear.series.lindstedt']\n"
        "assert inspect.isfunction(nl.lindstedt) and inspect.isfunction(nl.harmonic_linearization)"
    )
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    subprocess.run([sys.executable, "-c", code], check=True, env=env)


def test_lazy_table_matches_each_family():
    """The hand-kept table of symosc.nonlinear (family -> public names) agrees with every family's ``__all__``."""
    import importlib

    import symosc.nonlinear as nl

    for family, names in nl._FAMILY_NAMES.items():
        mod = importlib.import_module(f"symosc.nonlinear.{family}")
        assert set(names) <= set(dir(mod)), family
        if hasattr(mod, "__all__"):
            assert set(names) == set(mod.__all__), family
