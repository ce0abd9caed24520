"""Import-time regression check: which modules each public subpackage imports (not how long it takes).

SciPy submodules and optional libraries must be imported inside the functions that use them, so that
``import symosc.<subpackage>`` costs little more than SymPy itself.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

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


@pytest.mark.parametrize(
    "module", ["symosc", "symosc.models", "symosc.periodic", "symosc.nonlinear", "symosc.identification"]
)
def test_subpackage_imports_no_scipy_and_no_optional_library(module):
    names = imported_modules(f"import {module}")
    assert module in names  # the parser sees the import itself
    heavy = sorted(n for n in names if n.split(".")[0] in HEAVY)
    assert heavy == []


def test_the_parser_sees_a_scipy_import():
    """The check above can fail: a module that does import SciPy is reported."""
    names = imported_modules("import symosc.periodic; symosc.periodic.mathieu_a(3, 2.5)")
    assert "scipy.special" in names
