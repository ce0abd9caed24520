"""derivations/belyakov_2005.py: output folders, progress lines and the reproduced Appendix run of Belyakov (2005)."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "derivations" / "belyakov_2005.py"


def _load():
    spec = importlib.util.spec_from_file_location("belyakov_2005", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_quick_and_full_runs_write_to_their_own_folders(tmp_path):
    mod = _load()
    assert mod.output_folder(False).parts[-2:] == ("out", "belyakov_2005")
    assert mod.output_folder(True).parts[-2:] == ("out", "belyakov_2005_quick")
    assert mod.output_folder(True, tmp_path) == tmp_path


def test_appendix_run_matches_the_maple_values(capsys):
    """Belyakov (2005), Appendix 1: the Maple run of Algorithm 1 (m = 15007.77822, Izz = 44031.41489, ...)."""
    _load().appendix_run()
    section = capsys.readouterr().out.split("== Appendix (Maple)")[1].split("==")[0].splitlines()[2:]
    rows = {line.split()[0]: float(line.split()[-1]) for line in section if line.strip()}
    assert set(rows) == {"m", "rx", "rz", "Izz", "Ixx", "Ixz"}
    assert max(abs(v) for v in rows.values()) < 1e-8  # relative differences to the ten-digit Maple values


@pytest.mark.slow
def test_quick_run_reports_progress_and_writes_figures(tmp_path):
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""), MPLBACKEND="Agg")
    proc = subprocess.run(
        [sys.executable, str(SCRIPT), "--quick", "--out", str(tmp_path / "figs")],
        capture_output=True,
        text=True,
        env=env,
        check=True,
        timeout=600,
    )
    progress = [line for line in proc.stdout.splitlines() if line.startswith("[") and " s, total " in line]
    assert len(progress) == 9 and progress[-1].startswith("[9/9 Figs 21-24")
    assert sorted(p.name for p in (tmp_path / "figs").iterdir()) == [
        "belyakov_fig18_signals.png",
        "belyakov_fig20_error_vs_noise.png",
        "belyakov_fig21_22_error_maps.png",
        "belyakov_fig23_24_min_energy.png",
    ]
