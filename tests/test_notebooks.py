"""Every teaching notebook in docs/notebooks runs top to bottom in a Jupyter kernel (nbclient), its cells assert
the key numbers, it draws at least one figure, and the committed file carries its outputs (the docs render them).

The notebooks run one after another in one kernel per test process (starting a kernel and importing SymPy,
matplotlib and symosc took about 60 % of a notebook's run); the kernel's namespace is cleared (``%reset -f``) and
its figures closed after every notebook, so that no notebook can use what another defined."""

from __future__ import annotations

import os
from pathlib import Path

import nbformat
import pytest
from jupyter_client import KernelManager
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

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


#: clears the kernel after a notebook: user names, then figures (``%reset -f`` keeps imported modules loaded)
_RESET = "%reset -f\nimport matplotlib.pyplot\nmatplotlib.pyplot.close('all')\n%reset -f"


@pytest.fixture(scope="module")
def kernel():
    """One Python kernel for the notebooks of this test process, started with symosc on its path and Agg plots."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("PYTHONPATH", os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
        mp.setenv("MPLBACKEND", "Agg")
        km = KernelManager(kernel_name="python3")
        km.start_kernel(cwd=str(ROOT))
    yield km
    km.shutdown_kernel(now=True)


def _execute(nb, kernel) -> None:
    """Run ``nb`` in the shared ``kernel``, then clear the kernel for the next notebook."""
    if not kernel.is_alive():  # a notebook before this one killed it
        kernel.restart_kernel(now=True)
    # 60 s per cell is ten times the slowest cell.  interrupt_on_timeout also bounds nbclient's wait for the kernel's
    # first reply (a lost kernel_info reply once held a run for 240 s, the old timeout, before it went on);
    # error_on_timeout makes a cell that timed out fail the test (CellExecutionError), as a plain timeout would.
    client = NotebookClient(
        nb,
        km=kernel,
        timeout=60,
        interrupt_on_timeout=True,
        error_on_timeout={"ename": "CellTimeoutError", "evalue": "the cell ran longer than 60 s", "traceback": []},
        resources={"metadata": {"path": str(ROOT)}},
    )
    try:
        client.execute()
    finally:
        if client.kc is not None:
            client.kc.execute_interactive(_RESET, timeout=60)
            client.kc.stop_channels()


def test_a_notebook_does_not_see_the_names_or_figures_of_the_one_before(kernel):
    first = nbformat.v4.new_notebook(
        cells=[nbformat.v4.new_code_cell("import matplotlib.pyplot as plt\nleft_behind = 1\nplt.figure()")]
    )
    _execute(first, kernel)
    second = nbformat.v4.new_notebook(
        cells=[
            nbformat.v4.new_code_cell("import matplotlib.pyplot as plt\nprint(len(plt.get_fignums()))"),
            nbformat.v4.new_code_cell("left_behind"),
        ]
    )
    with pytest.raises(CellExecutionError, match="NameError"):
        _execute(second, kernel)
    assert second.cells[0].outputs[0]["text"].strip() == "0"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_executes(path, kernel):
    nb = nbformat.read(path, as_version=4)
    _execute(nb, kernel)
    assert not [o for c in _code_cells(nb) for o in c.outputs if o.get("output_type") == "error"], path.name
    figures = [o for c in _code_cells(nb) for o in c.outputs if "image/png" in o.get("data", {})]
    assert figures, f"{path.name} drew no figure"
