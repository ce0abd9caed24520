"""The documentation site builds with warnings as errors, and its API reference lists every public object."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tests.api.public import public_objects

DOCS = Path(__file__).resolve().parents[1] / "docs"


@pytest.mark.slow
def test_docs_build_without_warnings_and_list_every_public_object(tmp_path):
    out = tmp_path / "html"
    cmd = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-j", "1", "-q", "-b", "html", str(DOCS), str(out)]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=900, cwd=DOCS.parent)
    assert run.returncode == 0, run.stderr[-4000:]
    generated = out / "api" / "generated"
    missing = [f"{mod}.{name}" for mod, name, _ in public_objects() if not (generated / f"{mod}.{name}.html").exists()]
    assert missing == [], missing
    assert (out / "notebooks" / "inverted_double_pendulum.html").exists()
    assert (out / "performance.html").exists() and (out / "ecosystem.html").exists()


def test_readme_names_the_docs_build_command():
    readme = (DOCS.parent / "README.md").read_text()
    assert "python -m sphinx -W -j 1 -b html docs docs/_build/html" in readme
