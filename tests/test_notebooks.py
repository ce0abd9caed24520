"""Every teaching notebook in docs/notebooks runs top to bottom in a Jupyter kernel (nbclient), its cells assert
the key numbers, it draws at least one figure, and the committed file carries its outputs (the docs render them)."""

from __future__ import annotations

import os
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "docs" / "notebooks").glob("*.ipynb"))


def _code_cells(nb):
    return [c for c in nb.cells if c.cell_type == "code"]


def test_there_are_notebooks():
    assert len(NOTEBOOKS) >= 5


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_stored_outputs_are_present(path):
    nb = nbformat.read(path, as_version=4)
    cells = _code_cells(nb)
    assert cells and all(c.outputs for c in cells), f"{path.name}: run it and save it with its outputs"
    assert any("image/png" in o.get("data", {}) for c in cells for o in c.outputs), f"{path.name} draws no figure"
    assert not any(o.get("output_type") == "error" for c in cells for o in c.outputs)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_executes(path, monkeypatch):
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    monkeypatch.setenv("MPLBACKEND", "Agg")
    nb = nbformat.read(path, as_version=4)
    # 60 s per cell is ten times the slowest cell.  interrupt_on_timeout also bounds nbclient's wait for the kernel's
    # first reply (a lost kernel_info reply once held a run for 240 s, the old timeout, before it went on);
    # error_on_timeout makes a cell that timed out fail the test (CellExecutionError), as a plain timeout would.
    client = NotebookClient(
        nb,
        timeout=60,
        interrupt_on_timeout=True,
        error_on_timeout={"ename": "CellTimeoutError", "evalue": "the cell ran longer than 60 s", "traceback": []},
        kernel_name="python3",
        resources={"metadata": {"path": str(ROOT)}},
    )
    client.execute()
    assert not [o for c in _code_cells(nb) for o in c.outputs if o.get("output_type") == "error"], path.name
    figures = [o for c in _code_cells(nb) for o in c.outputs if "image/png" in o.get("data", {})]
    assert figures, f"{path.name} drew no figure"
