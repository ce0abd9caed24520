"""Scene output folders are written whole or not at all, and ``results.json`` is the same for two runs."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from symosc.errors import ParameterError
from symosc.scene import load, loads
from symosc.scene._output import MARKER, replacing_folder

EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "examples").glob("*.toml"))
MATHIEU = '[system]\nmodel = "mathieu"\n[[questions]]\nkind = "mathieu_values"\nn = 0\nq = [0, 1]\n'


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_two_runs_of_every_example_write_byte_identical_results(path, tmp_path, monkeypatch):
    monkeypatch.chdir(path.parent)  # examples refer to their data files relative to themselves
    first = load(path).run().write(tmp_path / "a", "json")
    second = load(path).run().write(tmp_path / "b", "json")
    assert [p.name for p in first] == [p.name for p in second]
    assert (tmp_path / "a" / "results.json").read_bytes() == (tmp_path / "b" / "results.json").read_bytes()
    assert b"seconds" not in (tmp_path / "a" / "results.json").read_bytes()
    assert b"seconds" in (tmp_path / "a" / "timings.json").read_bytes()


def _snapshot(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def test_a_failing_run_leaves_the_folder_as_it_was(tmp_path, monkeypatch):
    out = tmp_path / "out"
    result = load(EXAMPLES[0].parent / "mathieu_values.toml").run()
    result.write(out)
    before = _snapshot(out)
    from symosc.scene import _figures

    def broken(*args, **kwargs):
        raise RuntimeError("the figure could not be drawn")

    for name in dir(_figures):
        if not name.startswith("_") and callable(getattr(_figures, name)):
            monkeypatch.setattr(_figures, name, broken)
    with pytest.raises(RuntimeError, match="could not be drawn"):
        result.write(out)
    assert _snapshot(out) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]  # no hidden folder left


def test_an_interrupted_run_leaves_the_folder_as_it_was(tmp_path):
    out = tmp_path / "out"
    loads(MATHIEU).run().write(out)
    before = _snapshot(out)
    with pytest.raises(KeyboardInterrupt), replacing_folder(out) as new:
        (new / "results.json").write_text("half")
        raise KeyboardInterrupt
    assert _snapshot(out) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_a_killed_run_leaves_the_folder_and_its_leftover_is_removed_by_the_next_run(tmp_path):
    """A process killed (SIGKILL) while writing leaves its hidden folder behind and ``out`` untouched; the next run
    removes the leftover of the dead process."""
    out = tmp_path / "out"
    loads(MATHIEU).run().write(out)
    before = _snapshot(out)
    code = (
        "import os, sys\n"
        "from symosc.scene._output import replacing_folder\n"
        f"with replacing_folder({str(out)!r}) as new:\n"
        "    (new / 'results.json').write_text('half')\n"
        "    os.kill(os.getpid(), 9)\n"
    )
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True)
    assert proc.returncode == -9
    assert _snapshot(out) == before
    leftovers = [p for p in tmp_path.iterdir() if p.name != "out"]
    assert len(leftovers) == 1 and leftovers[0].name.startswith(".symosc-out-")
    loads(MATHIEU).run().write(out)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_a_new_run_leaves_no_stale_figures(tmp_path):
    out = tmp_path / "out"
    load(EXAMPLES[0].parent / "mathieu_values.toml").run().write(out)
    assert any(p.suffix == ".png" for p in out.iterdir())
    spring = '[system]\nmodel = "lagrangian"\ncoordinates = ["x"]\nT = "m*x_dot**2/2"\nV = "k*x**2/2"\n'
    spring += '[parameters]\nm = "2 kg"\nk = "50 N/m"\n[[questions]]\nkind = "natural_frequencies"\n'
    loads(spring).run().write(out)
    assert sorted(p.name for p in out.iterdir()) == [MARKER, "report.md", "results.json", "timings.json"]


def test_a_folder_with_other_files_is_refused_before_any_work(tmp_path, capsys):
    from symosc.cli import main

    (tmp_path / "notes.txt").write_text("mine")
    scene = tmp_path / "s.toml"
    scene.write_text(MATHIEU)
    assert main(["run", str(scene), "-o", str(tmp_path)]) == 1
    err = capsys.readouterr().err
    assert "did not write" in err and "notes.txt" not in err
    assert (tmp_path / "notes.txt").read_text() == "mine"
    with pytest.raises(ParameterError, match="is a file"):
        loads(MATHIEU).run().write(scene)
    with pytest.raises(ParameterError, match="unknown fmt"):
        loads(MATHIEU).run().write(tmp_path / "new", "pdf")
    assert not (tmp_path / "new").exists()
