"""The ``symosc`` command line.

Subcommands (``symosc COMMAND --help`` for each):

- ``run SCENE.toml [-o OUTDIR] [--format md|html|json]``: answer a scene's questions, print the scene report, write
  it, ``results.json`` and the figures;
- ``double-pendulum [--set NAME=VALUE]``: natural frequencies of the Table 1 pendulum of Gribkov & Khokhlov (2015);
- ``stability N``: stability of the inverted N-link pendulum on a vibrating pivot (``--plot`` writes the diagram);
- ``mathieu a|b N Q...``: Mathieu characteristic values;
- ``series vdp --order K``: Poincaré series of the van der Pol cycle with its validation;
- ``identify RECORD.csv --dt DT --modes K``: modal identification of a free-oscillation record;
- ``reproduce gribkov2015|belyakov2005|bulgakov|all [--quick]``: the source reproductions (source checkout).

Exit codes: 0 success, 1 error (bad scene, failed computation), 2 usage error.  ``--traceback`` shows the Python
traceback of an error (for developers).
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Sequence
from pathlib import Path

__all__ = ["main"]


def _flag_error(exc: Exception, flags: dict[str, str]) -> _UsageError:
    """A scene error raised for a scene generated from command-line flags, told in terms of the flags: ``flags``
    maps a scene key prefix (``excitation.amplitude``, ``parameters.``) to the flag that set it."""
    key = getattr(exc, "key", "") or ""
    message = getattr(exc, "message", None) or str(exc)
    for prefix, flag in flags.items():
        if key == prefix or (prefix.endswith(".") and key.startswith(prefix)):
            name = key[len(prefix) :] if prefix.endswith(".") else ""
            shown = flag.format(name=name)
            return _UsageError(f"{shown}: {message}")
    return _UsageError(message)


class _UsageError(Exception):
    """A bad command line (exit code 2)."""


class _RangeError(Exception):
    """A value out of range on the command line (exit code 1, one line)."""


# ------------------------------------------------------------------------------------------------ helpers
def _parse_sets(items: Sequence[str] | None, valid: Sequence[str], dims: dict) -> dict[str, object]:
    """``NAME=VALUE`` pairs -> overrides; unknown names and values that are not numbers are usage errors."""
    from .scene._errors import closest
    from .scene._units import UnitError, parse_quantity

    out: dict[str, object] = {}
    for item in items or []:
        name, sep, val = item.partition("=")
        name, val = name.strip(), val.strip()
        if not sep or not name or not val:
            raise _UsageError(f"--set expects NAME=VALUE, got {item!r}; valid names: {', '.join(valid)}")
        if name not in valid:
            raise _UsageError(
                f"--set: unknown parameter {name!r}.{closest(name, valid)} Valid names: {', '.join(valid)}"
            )
        try:
            out[name] = float(val)
        except ValueError:
            try:
                parse_quantity(val, dims.get(name))
            except UnitError as exc:
                raise _UsageError(f"--set {name}: {val!r} is not a number or a quantity ({exc})") from None
            out[name] = val
        try:
            si = parse_quantity(out[name], dims.get(name))
        except UnitError as exc:  # nan, inf
            raise _RangeError(f"--set {name}={val}: {exc}") from None
        if dims.get(name) not in (None, "dimensionless") and not si > 0:
            raise _RangeError(f"--set {name}={val}: {name} must be positive (got {si:g} in SI units)")
    return out


def _print_result(result, fmt: str) -> None:
    import json

    if fmt == "json":
        from .scene._result import _json_default

        print(json.dumps(result.to_json(), indent=2, default=_json_default))
    else:
        print(result.report())


# ------------------------------------------------------------------------------------------------ run
def _run(args: argparse.Namespace) -> int:
    from .scene import load
    from .scene._output import check_output_folder

    t0 = time.perf_counter()
    outdir = Path(args.output) if args.output else Path("symosc-out") / Path(args.scene).stem
    if not args.no_files:
        check_output_folder(outdir)  # before any work: an unwritable or foreign folder is refused at once
    scene = load(args.scene)
    result = scene.run()
    _print_result(result, args.format)
    if not args.no_files:
        paths = result.write(outdir, args.format)
        out = sys.stderr if args.format == "json" else sys.stdout
        print(f"\nwrote {', '.join(str(p) for p in paths)}  ({time.perf_counter() - t0:.2f} s)", file=out)
    return 0


# ------------------------------------------------------------------------------------------------ double pendulum
def _double_pendulum(args: argparse.Namespace) -> int:
    from .scene import loads
    from .scene._builtin import TABLE1_SCENE

    base = loads(TABLE1_SCENE, name="Table 1 scene")
    valid = base.model.parameter_names()
    overrides = _parse_sets(args.set, valid, {k: base.model.dimension(k) for k in valid})
    from .scene import SceneError

    try:
        scene = loads(TABLE1_SCENE, name="symosc double-pendulum --set", overrides=overrides) if overrides else base
        result = scene.run()
    except SceneError as exc:
        raise _flag_error(exc, {"parameters.": "--set {name}"}) from None
    if overrides:
        result = _drop_reference(result)
    print(result.report())
    return 0


def _drop_reference(result):
    """With changed parameters the paper comparison no longer applies: keep the computed columns only."""
    from dataclasses import replace

    from .scene import Table

    qr = result.results[0]
    t = qr.tables[0]
    keep = [i for i, h in enumerate(t.headers) if h not in ("source, Hz", "difference")]
    table = Table(tuple(t.headers[i] for i in keep), tuple(tuple(r[i] for i in keep) for r in t.rows), t.caption)
    lines = tuple(line.split(" (source:")[0] for line in qr.lines if not line.startswith(("source values", "note")))
    return replace(result, results=(replace(qr, tables=(table,), lines=lines),))


# ------------------------------------------------------------------------------------------------ stability
_UNIT_CHAIN = (
    "unit chain: m_i = 1 kg, l_i = 1 m (point links), lc_i = l_i/2, I_i = m_i l_i^2/12 (rigid links), g = 9.81 m/s^2"
)


def _stability_scene(n: int, links: str, sets: dict, frequency: str | None, amplitude: str | None, plot: bool) -> str:
    lines = ['title = "Inverted pendulum on a vibrating pivot"', "[system]", 'model = "n_link_pendulum"', f"n = {n}"]
    lines += [f'links = "{links}"', "inverted = true", 'pivot = "vertical"', "[parameters]"]
    for k, v in sets.items():
        lines.append(f"{k} = {v!r}" if isinstance(v, float) else f'{k} = "{v}"')
    exc = {"frequency": frequency, "amplitude": amplitude}
    if any(exc.values()):
        lines.append("[excitation]")
        lines += [f'{k} = "{v}"' for k, v in exc.items() if v]
    lines += ["[[questions]]", 'kind = "stability_region"', f"figure = {'true' if plot else 'false'}"]
    return "\n".join(lines) + "\n"


def _stability(args: argparse.Namespace) -> int:
    from .models.pendulum import MAX_SYMBOLIC_LINKS
    from .scene import loads
    from .scene._builtin import TABLE1_PARAMETERS

    n, links = args.n, args.links
    if not 1 <= n <= MAX_SYMBOLIC_LINKS:
        raise _UsageError(f"N must be a positive integer <= {MAX_SYMBOLIC_LINKS} (the symbolic chain's limit), got {n}")
    if n == 2 and links == "rigid":
        defaults: dict = dict(TABLE1_PARAMETERS)
        what = "Gribkov & Khokhlov (2015), Table 1"
    else:
        defaults = {"g": 9.81}
        for i in range(1, n + 1):
            defaults[f"m{i}"], defaults[f"l{i}"] = 1.0, 1.0
            if links == "rigid":
                defaults[f"lc{i}"], defaults[f"I{i}"] = 0.5, 1.0 / 12
        what = _UNIT_CHAIN
    from .scene._models import _pendulum_dimension

    valid = [k for k in defaults if not (links == "rigid" and k == f"l{n}")]
    defaults = {k: v for k, v in defaults.items() if k in valid}
    sets = {**defaults, **_parse_sets(args.set, valid, {k: _pendulum_dimension(k) for k in valid})}
    import dataclasses

    text = _stability_scene(n, links, sets, args.frequency, args.amplitude, bool(args.plot))
    from .scene import SceneError

    try:
        result = loads(text, name="stability").run()
    except SceneError as exc:
        flags = {
            "excitation.amplitude": "--amplitude",
            "excitation.frequency": "--frequency",
            "parameters.": "--set {name}",
        }
        raise _flag_error(exc, flags) from None
    qr = result.results[0]
    lines = [line for line in qr.lines if not line.startswith("figure:")]
    if args.plot:
        lines.append(f"figure: {args.plot} (modified Ince–Strutt diagram, first-tone axes)")
    if args.frequency is None:
        lines.append("give --frequency (and --amplitude) for the stable amplitude interval at a pivot frequency")
    figs = tuple(dataclasses.replace(f, filename=Path(args.plot).name) for f in qr.figures) if args.plot else ()
    result = dataclasses.replace(result, results=(dataclasses.replace(qr, lines=tuple(lines), figures=figs),))
    print(f"parameters: {what}" + (" with --set overrides" if args.set else ""))
    print(result.report())
    if args.plot:
        _write_figures(result, Path(args.plot))
    return 0


def _write_figures(result, target: Path) -> None:
    """Write the result's figures only (next to ``target``)."""
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        written = result.write(Path(tmp) / "out", "json")
        for p in written:
            if p.suffix == ".png":
                target.parent.mkdir(parents=True, exist_ok=True)
                p.replace(target)
                print(f"wrote {target}")


# -------------------------------------------------------------------------------------- mathieu, series, identify
def _mathieu(args: argparse.Namespace) -> int:
    from .periodic import mathieu_characteristic

    if args.n < 0:
        raise _UsageError(f"N must be >= 0, got {args.n}")
    if args.kind == "b" and args.n < 1:
        raise _UsageError("b_n is defined for N >= 1 (b_0 does not exist)")
    res = mathieu_characteristic(args.kind, args.n, args.q)
    import numpy as np

    print(f"Mathieu characteristic values {args.kind}_{args.n}(q)   [method: {res.method}]")
    print(f"{'q':>14} {args.kind + '_' + str(args.n) + '(q)':>24} {'error estimate':>15}")
    for q, v, e in zip(args.q, np.atleast_1d(res.values), np.atleast_1d(res.error_estimate), strict=True):
        print(f"{q:>14.8g} {float(v):>24.17g} {float(e):>15.1e}")
    return 0


def _series(args: argparse.Namespace) -> int:
    from .scene import loads

    if args.order < 1:
        raise _UsageError(f"--order must be >= 1, got {args.order}")
    eps = ", ".join(repr(float(e)) for e in args.validate) if args.validate else ""
    text = 'title = "van der Pol oscillator"\n[system]\nmodel = "van_der_pol"\n'
    text += f'[[questions]]\nkind = "limit_cycle"\norder = {args.order}\n'
    if eps:
        text += f"validate_eps = [{eps}]\n"
    print(loads(text, name="symosc series").run().report())
    return 0


def _identify(args: argparse.Namespace) -> int:
    from .scene import loads

    record = Path(args.record).resolve()
    if not record.is_file():
        raise RuntimeError(f"record file {args.record!r} not found")
    text = f'title = "Identification of {record.name}"\n[[questions]]\nkind = "identify"\nrecord = {str(record)!r}\n'
    text += f'n_modes = {args.modes}\nmethod = "{args.method}"\n'
    if args.dt is not None:
        text += f"dt = {args.dt!r}\n"
    if args.modes < 1:
        raise _UsageError(f"--modes must be >= 1, got {args.modes}")
    print(loads(text, name="symosc identify").run().report())
    return 0


# ------------------------------------------------------------------------------------------------ reproduce
SOURCES = ("gribkov2015", "belyakov2005", "bulgakov")


def _reproduce(args: argparse.Namespace) -> int:
    import importlib.util

    marker = "gribkov_khokhlov_2015.py"
    candidates = [Path(__file__).resolve().parents[1] / "derivations"]
    candidates += [folder / "derivations" for folder in (Path.cwd(), *Path.cwd().parents)]
    root = next((c for c in candidates if (c / marker).is_file()), None)
    if root is None:
        raise RuntimeError(
            "symosc reproduce runs the scripts in the derivations/ folder of a symosc source checkout, which an "
            "installed package does not contain: run 'symosc reproduce' inside the checkout (or a folder below it), "
            "or 'python derivations/<script>.py' there"
        )

    def module(name: str):
        spec = importlib.util.spec_from_file_location(f"_symosc_derivation_{name}", root / f"{name}.py")
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        return mod

    plan = {
        "gribkov2015": [("gribkov_khokhlov_2015", "table1_natural_frequencies" if args.quick else "main")],
        "belyakov2005": [("belyakov_2005", "main_quick" if args.quick else "main")],
        "bulgakov": [
            ("bulgakov_calculus", "quick" if args.quick else "main"),
            ("bulgakov_nonlinear", "quick" if args.quick else "main"),
        ],
    }
    chosen = SOURCES if args.source == "all" else (args.source,)
    steps = [(src, script, fn) for src in chosen for script, fn in plan[src]]
    t_all = time.perf_counter()
    for k, (src, script, fn) in enumerate(steps, start=1):
        print(f"\n[{k}/{len(steps)}] {src}: derivations/{script}.py{' (quick)' if args.quick else ''}", flush=True)
        t0 = time.perf_counter()
        mod = module(script)
        if fn == "main":
            mod.main([]) if script != "bulgakov_nonlinear" else mod.main()
        elif fn == "main_quick":
            mod.main(["--quick"])
        elif fn == "quick" and script == "bulgakov_calculus":
            mod.main([a for s in mod.SECTIONS if s != "2.21" for a in ("--section", s)])
        elif fn == "quick":
            print(f"{'quantity':<42} | {'book':<22} | {'symosc':<26} | {'diff':<10} | note")
            mod.poincare_van_der_pol()
            mod.lindstedt_examples()
        else:
            getattr(mod, fn)()
        print(f"[{k}/{len(steps)}] {src}: done in {time.perf_counter() - t0:.1f} s", flush=True)
    print(f"\nall done in {time.perf_counter() - t_all:.1f} s")
    return 0


# ------------------------------------------------------------------------------------------------ parser
def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="symosc",
        description="Symbolic-first theory of oscillations: scenes, reproductions of the sources, quick answers.",
        epilog="Exit codes: 0 success, 1 error, 2 usage error.  'symosc COMMAND --help' describes each command.",
    )
    parser.add_argument("--version", action="store_true", help="print the version and exit")
    parser.add_argument(
        "--traceback", dest="traceback_all", action="store_true", help="show Python tracebacks (developers)"
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    def add(name: str, help: str, func, description: str | None = None) -> argparse.ArgumentParser:
        p = sub.add_parser(name, help=help, description=description or help)
        p.add_argument("--traceback", action="store_true", help="show the Python traceback of an error (developers)")
        p.set_defaults(func=func, subparser=p)
        return p

    p = add("run", "answer the questions of a scene file (TOML) and write a report", _run,
            "Answer the questions of a scene file: print the scene report, write report.<format>, results.json and the "
            "figures (PNG, needs matplotlib) into OUTDIR (default symosc-out/<scene name>/).")  # fmt: skip
    p.add_argument("scene", metavar="SCENE.toml", help="the scene file (see docs/scenes.md and examples/)")
    p.add_argument("-o", "--output", metavar="OUTDIR", help="folder for the scene report, results.json and figures")
    p.add_argument("--format", choices=("md", "html", "json"), default="md", help="report format (json: print JSON)")
    p.add_argument("--no-files", action="store_true", help="print only, write nothing")

    p = add("double-pendulum", "natural frequencies and modes of the Table 1 double pendulum", _double_pendulum,
            "Natural frequencies and modes of the double physical pendulum of Gribkov & Khokhlov (2015), Table 1, "
            "hanging on a fixed pivot (the scene examples/double_pendulum_frequencies.toml).  The paper prints "
            "2.289 Hz and 5.094 Hz; its own Table 1 gives 2.3276 Hz and 5.0460 Hz (a table entry or the paper's "
            "model differs: lc2 = 15.16 mm would reproduce the printed values).")  # fmt: skip
    p.add_argument("--set", action="append", metavar="NAME=VALUE",
                   help="override a parameter: a number in SI units or a quantity such as m1='2 g'; names: "
                        "m1 m2 l1 lc1 lc2 I1 I2 g (l2 does not enter the equations)")  # fmt: skip

    p = add("stability", "stability of the inverted N-link pendulum on a vibrating pivot", _stability,
            "Stability region of the inverted N-link pendulum on a vertically vibrating pivot by the modified "
            "Ince–Strutt diagram (Gribkov & Khokhlov 2015).  Parameters: Table 1 for N = 2 rigid links, else the "
            f"{_UNIT_CHAIN}; override with --set.")  # fmt: skip
    p.add_argument("n", type=int, metavar="N", help="number of links")
    p.add_argument("--links", choices=("point", "rigid"), default="rigid", help="point masses or physical links")
    p.add_argument("--set", action="append", metavar="NAME=VALUE", help="override a parameter (SI or 'VALUE UNIT')")
    p.add_argument("--frequency", metavar="F", help="pivot frequency, e.g. '100 Hz' (a bare number is rad/s)")
    p.add_argument("--amplitude", metavar="A", help="pivot amplitude, e.g. '2 mm' (a bare number is m)")
    p.add_argument("--plot", nargs="?", const="stability.png", metavar="FILE.png",
                   help="write the modified Ince–Strutt diagram (default stability.png)")  # fmt: skip

    p = add("mathieu", "Mathieu characteristic values a_N(q) or b_N(q)", _mathieu)
    p.add_argument("kind", choices=("a", "b"), help="even (a) or odd (b) characteristic value")
    p.add_argument("n", type=int, metavar="N", help="index N (>= 0 for a, >= 1 for b)")
    p.add_argument("q", type=float, nargs="+", metavar="Q", help="one or more values of q")

    p = add("series", "Poincaré series of the van der Pol limit cycle, validated numerically", _series,
            "Limit cycle of x'' + x = eps (1 - x^2) x' as series in eps (Bulgakov 1954, §8), exact coefficients, "
            "optionally compared with the numerically integrated cycle.")  # fmt: skip
    p.add_argument("system", choices=("vdp",), help="vdp: the van der Pol oscillator")
    p.add_argument("--order", type=int, required=True, metavar="K", help="highest power of eps")
    p.add_argument(
        "--validate", type=float, nargs="*", metavar="EPS", help="compare with the numeric cycle at these eps"
    )

    p = add("identify", "modal identification of a free-oscillation record (CSV)", _identify,
            "Frequencies and damping of a free-oscillation record (Belyakov 2005): CSV with a header row, one "
            "column per channel, optionally a first column 't'.")  # fmt: skip
    p.add_argument("record", metavar="RECORD.csv")
    p.add_argument("--dt", type=float, help="sampling period in s (default: from the 't' column)")
    p.add_argument("--modes", type=int, required=True, metavar="K", help="number of oscillating modes")
    p.add_argument("--method", choices=("matrix_pencil", "esprit", "prony", "era"), default="matrix_pencil")

    p = add("reproduce", "reproduce a source's tables and figures (source checkout)", _reproduce,
            "Run the reproduction of a source: printed 'source | symosc | difference' tables, figures in "
            "derivations/out/.  Needs the source checkout (the derivations/ folder).")  # fmt: skip
    p.add_argument("source", choices=(*SOURCES, "all"))
    p.add_argument("--quick", action="store_true", help="the fast parts only")
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``symosc`` console script; returns the exit code.

    Examples
    --------
    >>> main(["--version"])
    symosc 0.1.0
    0
    >>> main(["mathieu", "a", "0", "1"])  # doctest: +NORMALIZE_WHITESPACE
    Mathieu characteristic values a_0(q)   [method: ...]
    ...
    0

    See Also
    --------
    symosc.scene.load : the scene files ``symosc run`` reads.
    """
    from . import __version__
    from .errors import SymoscError

    parser = _parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # usage errors (2) and --help (0)
        return int(exc.code or 0)
    args.traceback = getattr(args, "traceback", False) or args.traceback_all
    if args.version:
        print(f"symosc {__version__}")
        return 0
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        return args.func(args)
    except _UsageError as exc:
        if args.traceback:
            raise
        getattr(args, "subparser", parser).print_usage(sys.stderr)
        print(f"symosc {args.command}: usage error: {exc}", file=sys.stderr)
        return 2
    except (SymoscError, RuntimeError, OSError, _RangeError) as exc:
        if args.traceback:
            raise
        print(f"symosc {args.command}: error: {exc}", file=sys.stderr)
        return 1


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
