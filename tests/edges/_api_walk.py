"""Walk every public callable of symosc with bad arguments (run as a script in a subprocess by test_api_walk).

Public callables are discovered dynamically: symosc itself and every subpackage or top-level module that defines
``__all__`` (and the few modules listed in ``EXTRA``).  Passes (chosen on the command line):

* ``functions``: every required argument gets a value from BAD, all the same value first, then a few fixed
  mixtures (each argument meets a different value in each); a call whose arguments are all nan (or all inf) must not
  return either (a result computed from non-finite input is a silent wrong answer);
* ``classes``: the constructor of every public class, the same way (results and models alike: only generic
  exceptions and hangs are reported, a result class may well hold a nan);
* ``cli``: ``symosc.cli.main`` with bad commands, flags and values: exit code 1 or 2 and a one-line error on
  stderr (argparse's usage lines aside), never a traceback;
* ``scenes``: ``symosc.scene.loads`` with malformed scene texts: a SceneError (or a scene that validates).

Each call runs under SIGALRM with a time cap.  Prints one JSON line per generic exception, time-out or violation.
"""

from __future__ import annotations

import contextlib
import importlib
import inspect
import io
import json
import pkgutil
import re
import shlex
import signal
import sys
import warnings

import numpy as np

import symosc
from symosc.errors import SymoscError

BAD = [None, float("nan"), float("inf"), -1, 0, "abc", 1.5, np.array([[1.0, 2.0, 3.0]])]
BAD_NAMES = ["None", "nan", "inf", "-1", "0", "'abc'", "1.5", "array(1x3)"]
NONFINITE = (1, 2)  # indices of nan and inf in BAD
#: valid-but-expensive requests for any numeric arguments (a Monte Carlo map per call); covered by their own tests
SKIP_FUNCTIONS = {"symosc.identification.error_map"}
#: functions that may return for all-nan (or all-inf) arguments: a summary records any object, nan included;
#: R(k) of dry friction has the documented limit R(inf) = 2
NONFINITE_OK = {"symosc.io.summary": ("nan", "inf"), "symosc.nonlinear.dry_friction_ratio": ("inf",)}
#: also report symosc errors whose message names no argument or states no expectation
CHECK_MESSAGES = True
SKIP_MODULES = {"symosc.cli"}  # the CLI has its own pass
#: public callables of modules without ``__all__``
EXTRA = {"symosc.sweep": ("sweep",)}


class _Timeout(BaseException):
    pass


def _alarm(signum, frame):
    raise _Timeout


def _modules():
    names = [m.name for m in pkgutil.iter_modules(symosc.__path__) if not m.name.startswith("_")]
    for modname in ["symosc", *(f"symosc.{name}" for name in sorted(names))]:
        if modname in SKIP_MODULES:
            continue
        try:
            mod = importlib.import_module(modname)
        except Exception as exc:  # an optional extra missing: report, do not walk
            print(json.dumps({"function": modname, "args": "import", "error": repr(exc)}))
            continue
        yield modname, mod, [*getattr(mod, "__all__", []), *EXTRA.get(modname, ())]


def public_functions():
    seen = set()
    for modname, mod, names in _modules():
        for attr in names:
            obj = getattr(mod, attr, None)
            if inspect.isfunction(obj) and id(obj) not in seen and f"{modname}.{attr}" not in SKIP_FUNCTIONS:
                seen.add(id(obj))
                yield f"{modname}.{attr}", obj


def public_classes():
    seen = set()
    for modname, mod, names in _modules():
        for attr in names:
            obj = getattr(mod, attr, None)
            if inspect.isclass(obj) and not issubclass(obj, BaseException | Warning) and id(obj) not in seen:
                seen.add(id(obj))
                yield f"{modname}.{attr}", obj


def required(fn):
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):
        return []
    return [
        p.name
        for p in sig.parameters.values()
        if p.default is inspect.Parameter.empty and p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
    ]


_EXPECT = re.compile(
    r"expected|must|should|choose|valid|\buse\b|>=|<=|> 0|< 0|positive|negative|finite|at least|at most|one of|"
    r"did you mean|need|require|only|cannot|not allowed|give |pass |instead|range|integer|nonzero|non-zero|"
    r"smaller|larger|greater|less than|substitute",
    re.IGNORECASE,
)


def vague(fn, message: str) -> str | None:
    """Why a symosc error message is vague: it names no argument of ``fn`` or states no expectation."""
    try:
        names = list(inspect.signature(fn).parameters)
    except (TypeError, ValueError):
        names = []
    if names and not any(re.search(rf"(?<![A-Za-z0-9_]){re.escape(p)}(?![A-Za-z0-9_])", message) for p in names):
        return "names no argument"
    if not _EXPECT.search(message):
        return "states no expectation"
    if re.search(r"expected: see help\(|expected: Any\b", message):
        return "the expectation only points to help()"
    return None


#: outcome of a call that returned
RETURNED = "returned"


def call(fn, args, cap, *, check_messages=CHECK_MESSAGES):
    """None when the call raised an explicit symosc error, ``RETURNED`` when it returned, else what went wrong."""
    signal.alarm(cap)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fn(*args)
        return RETURNED
    except SymoscError as exc:  # a SceneError locates the fault in the scene text (key, line, fix), not an argument
        why = vague(fn, str(exc)) if check_messages and type(exc).__name__ != "SceneError" else None
        return f"vague {type(exc).__name__} ({why}): {str(exc)[:300]}" if why else None
    except _Timeout:
        return "timeout"
    except RecursionError as exc:
        return repr(exc)[:200]
    except Exception as exc:
        return f"{type(exc).__module__}.{type(exc).__name__}: {str(exc)[:160]}"
    finally:
        signal.alarm(0)


def _mixtures(nargs: int, count: int) -> list[list[int]]:
    """``count`` deterministic mixtures of the BAD values for ``nargs`` arguments: mixture ``i`` gives argument ``j``
    the value ``3 i + j`` (mod len(BAD)), so every argument meets a different value in each mixture and neighbouring
    arguments never share one (the uniform assignments cover that)."""
    return [[(3 * i + j) % len(BAD) for j in range(nargs)] for i in range(count)]


def _walk_one(qual, fn, cap, examples, *, check_messages, nonfinite):
    req = required(fn)
    if not req:
        return
    found: dict[str, str] = {}
    for i in range(len(BAD)):  # the uniform assignments first
        err = call(fn, [BAD[i]] * len(req), cap, check_messages=check_messages)
        if err == RETURNED and nonfinite and i in NONFINITE and BAD_NAMES[i] not in NONFINITE_OK.get(qual, ()):
            err = f"accepts {BAD_NAMES[i]}: returned a result computed from {BAD_NAMES[i]} arguments"
        if err not in (None, RETURNED):
            found.setdefault(err.split(":")[0], ", ".join([BAD_NAMES[i]] * len(req)) + " -> " + err)
    for idx in _mixtures(len(req), examples) if len(req) > 1 else ():
        err = call(fn, [BAD[i] for i in idx], cap, check_messages=check_messages)
        if err not in (None, RETURNED):
            found.setdefault(err.split(":")[0], ", ".join(BAD_NAMES[i] for i in idx) + " -> " + err)
    for kind, detail in found.items():
        print(json.dumps({"function": qual, "kind": kind, "detail": detail}), flush=True)


def walk(cap: int, examples: int) -> None:
    for qual, fn in public_functions():
        _walk_one(qual, fn, cap, examples, check_messages=CHECK_MESSAGES, nonfinite=True)


def walk_classes(cap: int, examples: int) -> None:
    """Constructors: generic exceptions and hangs only (their messages are checked where they are functions)."""
    for qual, cls in public_classes():
        _walk_one(qual, cls, cap, examples, check_messages=False, nonfinite=False)


# ------------------------------------------------------------------------------------------------------ CLI
#: bad command lines (split like a shell would)
CLI_CALLS = """
--bogus | nonsense | --version extra | run | run missing.toml | run /dev/null | run scene.toml --format pdf
double-pendulum --set m1 | double-pendulum --set zz=1 | double-pendulum --set m1=abc | double-pendulum --set m1=-1
double-pendulum --set m1=nan | double-pendulum --set g=inf | double-pendulum --set 'm1=1 kg/s'
double-pendulum --set =1
stability | stability 0 | stability -1 | stability x | stability 1000000 | stability 2 --links rope
stability 2 --frequency abc | stability 2 --frequency nan | stability 2 --frequency '-5 Hz' | stability 2 --amplitude 0
stability 2 --amplitude inf | stability 2 --set lc9=1
mathieu | mathieu c 0 1 | mathieu a -1 1 | mathieu b 0 1 | mathieu a x 1 | mathieu a 0 nan | mathieu a 0 inf
mathieu a 0 abc | mathieu a 1.5 1
series | series duffing --order 2 | series vdp | series vdp --order 0 | series vdp --order -3
series vdp --order 100000 | series vdp --order x | series vdp --order 2 --validate nan
series vdp --order 2 --validate inf | series vdp --order 2 --validate abc
identify | identify missing.csv --modes 1 | identify record.csv | identify record.csv --modes 0
identify record.csv --modes -1 | identify record.csv --modes 1 --dt -1 | identify record.csv --modes 1 --dt nan
identify record.csv --modes 1 --method fft | identify empty.csv --modes 1 | identify garbage.csv --modes 1
reproduce | reproduce nobody
"""
#: files the command lines refer to (written into the scratch folder)
CLI_FILES = {
    "scene.toml": '[system]\nmodel = "n_link_pendulum"\nn = 1\n[[questions]]\nkind = "natural_frequencies"\n',
    "record.csv": "t,x\n" + "".join(f"{0.05 * i},{np.exp(-0.005 * i) * np.cos(0.15 * i)}\n" for i in range(200)),
    "empty.csv": "",
    "garbage.csv": "t,x\n0,abc\n1,\x00\n",
}
_USAGE = re.compile(r"^(usage: |\s)")


def walk_cli(cap: int) -> None:
    from pathlib import Path

    from symosc.cli import main

    for name, text in CLI_FILES.items():
        Path(name).write_text(text)
    for argv in (shlex.split(c) for line in CLI_CALLS.strip().splitlines() for c in line.split(" | ")):
        err, out = io.StringIO(), io.StringIO()
        signal.alarm(cap)
        try:
            with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out), warnings.catch_warnings():
                warnings.simplefilter("ignore")
                code = main(argv)
        except _Timeout:
            code = "timeout"
        except BaseException as exc:  # anything that leaves main() is a failure
            code = f"raised {type(exc).__name__}: {str(exc)[:160]}"
        finally:
            signal.alarm(0)
        lines = [line for line in err.getvalue().splitlines() if line.strip()]
        message = [line for line in lines if not _USAGE.match(line)]
        problem = None
        if code not in (1, 2):
            problem = f"exit code {code}"
        elif len(message) != 1 or "Traceback" in err.getvalue():
            problem = f"{len(message)} error lines on stderr: {' // '.join(lines)[:300]}"
        if problem:
            print(json.dumps({"function": "symosc " + " ".join(argv), "kind": "cli", "detail": problem}), flush=True)


# --------------------------------------------------------------------------------------------------- scenes
_HEAD = '[system]\nmodel = "n_link_pendulum"\nn = 2\n'
_QUESTION = '[[questions]]\nkind = "natural_frequencies"\n'
#: (text before the question, text after it): a valid scene with one part spoilt
_SPOILT = [
    ("", ""),
    ("abc", None),
    ("[[[", None),
    ("title = ", None),
    ("\x00\x01", None),
    ("title = 1e999", None),
    ('title = "t"\n[system]\n', None),
    (_HEAD, None),
    (_HEAD + "[[questions]]\n", None),
    (_HEAD + '[[questions]]\nkind = "fly"\n', None),
    (_HEAD.replace("2", "-1"), ""),
    (_HEAD.replace("2", "1.5"), ""),
    (_HEAD.replace("2", '"two"'), ""),
    (_HEAD.replace("2", "100000000"), ""),
    (_HEAD.replace("n_link_pendulum", "__import__"), ""),
    ("[system]\nmodel = 3\n", ""),
    (_HEAD + '[parameters]\nm1 = "abc"\n', ""),
    (_HEAD + '[parameters]\nm1 = "1 parsec"\n', ""),
    (_HEAD + "[parameters]\nm1 = nan\n", ""),
    (_HEAD + "[parameters]\nm1 = -inf\n", ""),
    (_HEAD + '[parameters]\nm1 = "2**2**2**2**2**2 kg"\n', ""),
    (_HEAD + "[parameters]\nzz = 1\n", ""),
    (_HEAD + "[parameters]\nm1 = \"__import__('os')\"\n", ""),
    (_HEAD + "[excitation]\nfrequency = -1\n", ""),
    (_HEAD, 'reference_hz = "abc"\n'),
    (_HEAD, "figure = 'yes'\nkind = 'stability_region'\n"),
    ("x = [" + "[" * 100000 + "]" * 100000 + "]\n", None),
]
SCENE_TEXTS = [head if tail is None else head + _QUESTION + tail for head, tail in _SPOILT]


def walk_scenes(cap: int) -> None:
    from symosc.scene import loads

    for i, text in enumerate(SCENE_TEXTS):
        err = call(loads, [text], cap, check_messages=False)
        if err not in (None, RETURNED):
            print(json.dumps({"function": f"symosc.scene.loads(SCENE_TEXTS[{i}])", "kind": "scene", "detail": err}))


if __name__ == "__main__":
    signal.signal(signal.SIGALRM, _alarm)
    cap = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    examples = int(sys.argv[2]) if len(sys.argv) > 2 else 6
    passes = sys.argv[3].split(",") if len(sys.argv) > 3 else ["functions"]
    for name in passes:
        {"functions": lambda: walk(cap, examples), "classes": lambda: walk_classes(cap, examples),
         "cli": lambda: walk_cli(cap), "scenes": lambda: walk_scenes(cap)}[name]()  # fmt: skip
