"""Walk every public callable of symosc with bad arguments (run as a script in a subprocess by test_api_walk).

Public callables are discovered dynamically: every subpackage (and top-level module) of symosc that defines
``__all__``; functions only (result classes are built by the functions).  For each function every required
argument gets a value from BAD; hypothesis draws the combinations (all the same bad value, then mixtures).  Each
call runs under SIGALRM with a time cap.  Prints one JSON line per generic exception or time-out.
"""

from __future__ import annotations

import importlib
import inspect
import json
import pkgutil
import re
import signal
import sys
import warnings

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import symosc
from symosc.errors import SymoscError

BAD = [None, float("nan"), float("inf"), -1, 0, "abc", 1.5, np.array([[1.0, 2.0, 3.0]])]
BAD_NAMES = ["None", "nan", "inf", "-1", "0", "'abc'", "1.5", "array(1x3)"]
#: valid-but-expensive requests for any numeric arguments (a Monte Carlo map per call); covered by their own tests
SKIP_FUNCTIONS = {"symosc.identification.error_map"}
#: also report symosc errors whose message names no argument or states no expectation
CHECK_MESSAGES = True
SKIP_MODULES = {"symosc.cli", "symosc.sweep", "symosc.scene", "symosc.numeric"}  # validated by their own tests


class _Timeout(BaseException):
    pass


def _alarm(signum, frame):
    raise _Timeout


def public_functions():
    seen = set()
    names = [m.name for m in pkgutil.iter_modules(symosc.__path__)]
    for name in sorted(names):
        modname = f"symosc.{name}"
        if modname in SKIP_MODULES or name.startswith("_"):
            continue
        try:
            mod = importlib.import_module(modname)
        except Exception as exc:  # an optional extra missing: report, do not walk
            print(json.dumps({"function": modname, "args": "import", "error": repr(exc)}))
            continue
        for attr in getattr(mod, "__all__", []):
            obj = getattr(mod, attr, None)
            if inspect.isfunction(obj) and id(obj) not in seen and f"{modname}.{attr}" not in SKIP_FUNCTIONS:
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


def call(fn, args, cap):
    signal.alarm(cap)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fn(*args)
        return None
    except SymoscError as exc:
        why = vague(fn, str(exc)) if CHECK_MESSAGES else None
        return f"vague {type(exc).__name__} ({why}): {str(exc)[:300]}" if why else None
    except _Timeout:
        return "timeout"
    except RecursionError as exc:
        return repr(exc)[:200]
    except Exception as exc:
        return f"{type(exc).__module__}.{type(exc).__name__}: {str(exc)[:160]}"
    finally:
        signal.alarm(0)


def _make_probe(fn, nargs: int, cap: int, examples: int, found: dict):
    @settings(max_examples=examples, deadline=None, database=None, derandomize=True,
              suppress_health_check=list(HealthCheck))  # fmt: skip
    @given(st.lists(st.integers(0, len(BAD) - 1), min_size=nargs, max_size=nargs))
    def probe(idx):
        err = call(fn, [BAD[i] for i in idx], cap)
        if err is not None:
            found.setdefault(err.split(":")[0], ", ".join(BAD_NAMES[i] for i in idx) + " -> " + err)

    return probe


def walk(cap: int, examples: int) -> None:
    signal.signal(signal.SIGALRM, _alarm)
    for qual, fn in public_functions():
        req = required(fn)
        if not req:
            continue
        found: dict[str, str] = {}

        probe = _make_probe(fn, len(req), cap, examples, found)

        for i in range(len(BAD)):  # the uniform assignments first
            err = call(fn, [BAD[i]] * len(req), cap)
            if err is not None:
                found.setdefault(err.split(":")[0], ", ".join([BAD_NAMES[i]] * len(req)) + " -> " + err)
        if len(req) > 1:
            probe()
        for kind, detail in found.items():
            print(json.dumps({"function": qual, "kind": kind, "detail": detail}), flush=True)


if __name__ == "__main__":
    walk(int(sys.argv[1]) if len(sys.argv) > 1 else 20, int(sys.argv[2]) if len(sys.argv) > 2 else 6)
