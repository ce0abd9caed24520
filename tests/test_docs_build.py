"""The documentation site builds with warnings as errors (every phase but the writing of the HTML files), and its
API reference lists every public object: every name in the ``__all__`` of every public module (``symosc.numeric``,
``symosc.io``, ``symosc.sweep``, deeper modules and subpackages that did not exist when this test was written)."""

from __future__ import annotations

import importlib
import importlib.util
import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests.api.public import all_public_exports

DOCS = Path(__file__).resolve().parents[1] / "docs"

#: names the README and the guides lead with: their pages are checked by name, whatever the discovery finds
HEADLINE = [
    ("symosc.numeric", "compile"),
    ("symosc.numeric", "CompiledFunction"),
    ("symosc.io", "load_summary"),
    ("symosc.sweep", "SweepResult"),
    ("symosc.sweep", "SweepFailure"),
    ("symosc.errors", "AccuracyWarning"),
    ("symosc.errors", "SeriesWarning"),
    ("symosc.networks", "parse_netlist"),
]


def _pages_module():
    spec = importlib.util.spec_from_file_location("_api_pages", DOCS / "_api_pages.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _documented(api: Path) -> dict[int, str]:
    """``{id(object): "module.name"}`` for every entry of the autosummary lists of the written pages."""
    out: dict[int, str] = {}
    for page in api.glob("symosc*.rst"):
        text = page.read_text()
        modname = re.search(r"^\.\. currentmodule:: (\S+)$", text, re.M)[1]
        mod = importlib.import_module(modname)
        for name in re.findall(r"^   (\w+)$", text.split(":toctree: generated", 1)[1], re.M):
            out.setdefault(id(getattr(mod, name)), f"{modname}.{name}")
    return out


def _undocumented(api: Path) -> list[str]:
    documented = _documented(api)
    return sorted({f"{m}.{n}" for m, n, obj in all_public_exports() if id(obj) not in documented})


def test_api_pages_list_every_public_name(tmp_path):
    """Every name importable from a public module and listed in its ``__all__`` has an API entry."""
    api = tmp_path / "api"
    _pages_module().write_api_pages(api)
    assert _undocumented(api) == []
    exports = {(m, n) for m, n, _ in all_public_exports()}
    assert set(HEADLINE) <= exports


@pytest.mark.slow
def test_docs_build_without_warnings_and_list_every_public_object(tmp_path):
    """Sphinx's ``dummy`` builder runs every phase of the HTML build (reading and parsing every page, autodoc and
    autosummary, cross-reference resolution) except writing the pages, for two thirds of the time; warnings are
    errors.  Every public object, the headline names and the notebooks must be among the pages it read."""
    out = tmp_path / "build"
    cmd = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-j", "1", "-q", "-b", "dummy", str(DOCS), str(out)]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=900, cwd=DOCS.parent)
    assert run.returncode == 0, run.stderr[-4000:]
    read = out / ".doctrees"  # one parsed document per page
    generated = read / "api" / "generated"
    documented = _documented(DOCS / "api")
    missing = [
        f"{m}.{n}"
        for m, n, obj in all_public_exports()
        if not (generated / f"{documented.get(id(obj))}.doctree").exists()
    ]
    assert missing == [], missing
    headline = {id(getattr(importlib.import_module(m), n)) for m, n in HEADLINE}
    assert all((generated / f"{documented[i]}.doctree").exists() for i in headline)
    assert (read / "notebooks" / "inverted_double_pendulum.doctree").exists()
    # a class page carries its methods' whole docstrings (parameters and all), not only their summary lines
    page = (generated / "symosc.mechanics.FirstOrderSystem.doctree").read_bytes()
    assert b"elimination with partial pivoting" in page  # from the Parameters section of rhs()
    assert b"M^{-1} (dF/dy - (dM/dy) M^{-1} F)" in page  # from the body of jacobian()
