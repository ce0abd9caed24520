"""Wall and CPU time of the ``symosc`` commands, and the unit table against pint (the peer for units).

Run ``python benchmarks/cli_timings.py`` from the repository root.  Each command runs in a fresh interpreter
(as a user would start it); CPU time is the child's user + system time, which is what the wall time would be
on an idle machine.  The machine this was recorded on was shared, so wall times are inflated.
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
COMMANDS = [
    "run examples/double_pendulum_frequencies.toml --no-files",
    "run examples/gribkov2015.toml -o {tmp}/gribkov2015",
    "double-pendulum",
    "stability 2 --frequency 100Hz",
    "mathieu a 0 1 10",
    "series vdp --order 6 --validate 0.1",
    "identify examples/data/belyakov_record.csv --modes 3",
    "reproduce gribkov2015 --quick",
]


def child_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def time_command(args: list[str], repeat: int = 3) -> tuple[float, float]:
    env = {**os.environ, "PYTHONPATH": str(ROOT), "MPLBACKEND": "Agg"}
    best_wall = best_cpu = float("inf")
    for _ in range(repeat):
        c0, t0 = child_cpu(), time.perf_counter()
        subprocess.run(args, cwd=ROOT, env=env, check=True, capture_output=True)
        best_wall = min(best_wall, time.perf_counter() - t0)
        best_cpu = min(best_cpu, child_cpu() - c0)
    return best_wall, best_cpu


def main() -> None:
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        print(f"{'command':<62} {'wall, s':>8} {'CPU, s':>8}")
        base = time_command([sys.executable, "-c", "pass"])
        print(f"{'(python -c pass: interpreter start-up)':<62} {base[0]:>8.2f} {base[1]:>8.2f}")
        imp = time_command([sys.executable, "-c", "import symosc"])
        label = "(python -c 'import symosc')"
        print(f"{label:<62} {imp[0]:>8.2f} {imp[1]:>8.2f}")
        for cmd in COMMANDS:
            wall, cpu = time_command([sys.executable, "-m", "symosc.cli", *cmd.format(tmp=tmp).split()])
            print(f"{'symosc ' + cmd.replace('{tmp}/', ''):<62} {wall:>8.2f} {cpu:>8.2f}")
        print()
        code_table = "from symosc.scene._units import parse_quantity as q; q('45 mm', 'length')"
        code_pint = "import symosc, pint; u = pint.UnitRegistry(); u.Quantity('45 mm').to('m').magnitude"
        t_table = time_command([sys.executable, "-c", code_table])
        t_pint = time_command([sys.executable, "-c", code_pint])
        print("units, start-up + first conversion in a fresh interpreter, both after importing symosc (CPU, s):")
        print(f"  symosc.scene unit table: {t_table[1]:.2f}")
        print(f"  pint UnitRegistry:       {t_pint[1]:.2f}  (+{t_pint[1] - t_table[1]:.2f} s)")
        from symosc.scene._units import parse_quantity

        n = 2000
        t0 = time.perf_counter()
        for _ in range(n):
            parse_quantity("146.804 g*mm^2", "moment of inertia")
        ours = (time.perf_counter() - t0) / n
        try:
            import pint

            ureg = pint.UnitRegistry()
            t0 = time.perf_counter()
            for _ in range(n):
                _ = ureg.Quantity("146.804 g*mm^2").to("kg*m^2").magnitude
            theirs = (time.perf_counter() - t0) / n
            print(f"  per conversion: table {ours * 1e6:.1f} us, pint {theirs * 1e6:.1f} us ({theirs / ours:.0f}x)")
        except ImportError:
            print(f"  per conversion: table {ours * 1e6:.1f} us (pint not installed)")


if __name__ == "__main__":
    main()
