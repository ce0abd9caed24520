"""Call each public function's first documented example again with one keyword argument made bad (run as a script in
a subprocess by tests/edges/test_api_walk.py).

``options`` mode: each string option misspelt (default + "x"); ``numbers`` mode: each numeric option (int or float
default) set to -1, nan, inf, "abc" and, for integers, 1.5.  Prints one JSON line per function, option and value:
[function, "option: outcome", detail] with outcome ok / VAGUE / ACCEPTED / GENERIC ... / TIMEOUT.
"""

import ast
import doctest
import inspect
import json
import math
import signal
import sys
import warnings

sys.path.insert(0, str(__import__("pathlib").Path(__file__).parent))
from _api_walk import public_functions, vague

from symosc.errors import SymoscError


class TO(BaseException):
    pass


def alarm(*a):
    raise TO


MODE = sys.argv[1] if len(sys.argv) > 1 else "options"


def bad_values(default):
    if MODE == "options":
        return [default + "x"]
    out = [-1, float("nan"), float("inf"), "abc"]
    return [*out, 1.5] if isinstance(default, int) else out


def selected(p):
    if MODE == "options":
        return isinstance(p.default, str)
    return isinstance(p.default, int | float) and not isinstance(p.default, bool)


def main() -> None:
    """Probe every public function with a documented example and print the outcomes, one JSON line each."""
    signal.signal(signal.SIGALRM, alarm)
    res = []
    for qual, fn in public_functions():
        sig = inspect.signature(fn)
        opts = [p.name for p in sig.parameters.values() if selected(p)]
        if not opts:
            continue
        mod = sys.modules[inspect.unwrap(fn).__module__]
        examples = doctest.DocTestParser().get_examples(inspect.getdoc(fn) or "")
        ns = dict(vars(mod))
        target = None
        try:
            signal.alarm(20)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                for ex in examples:
                    tree = ast.parse(ex.source)
                    calls = [
                        n
                        for n in ast.walk(tree)
                        if isinstance(n, ast.Call)
                        and (getattr(n.func, "id", None) == fn.__name__ or getattr(n.func, "attr", None) == fn.__name__)
                    ]
                    if calls:
                        target = calls[0]
                        break
                    exec(compile(tree, "<ex>", "exec"), ns)
            signal.alarm(0)
        except BaseException as e:
            signal.alarm(0)
            res.append((qual, "setup failed", repr(e)[:100]))
            continue
        if target is None:
            res.append((qual, "no example", ""))
            continue
        positional = [p.name for p in sig.parameters.values() if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
        for o in opts:
            for bad in bad_values(sig.parameters[o].default):
                value = (
                    ast.parse(repr(bad), mode="eval").body
                    if not isinstance(bad, float) or math.isfinite(bad)
                    else ast.parse(f"float({str(bad)!r})", mode="eval").body
                )
                args = list(target.args)
                keywords = [k for k in target.keywords if k.arg != o]
                if o in positional and positional.index(o) < len(args):
                    args[positional.index(o)] = value
                else:
                    keywords.append(ast.keyword(arg=o, value=value))
                src = ast.unparse(ast.Call(func=target.func, args=args, keywords=keywords))
                try:
                    # a hang detector, not a speed test: generous, since a loaded 2-core machine makes slow calls (a
                    # continuation that gives up after 2000 steps: 6 s under load) take several times longer
                    signal.alarm(90)
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        eval(src, ns)
                    signal.alarm(0)
                    res.append((qual, f"{o}: ACCEPTED", src[:120]))
                except SymoscError as e:
                    signal.alarm(0)
                    m = str(e)
                    if MODE == "options":
                        ok = "did you mean" in m and o in m
                    else:
                        ok = vague(fn, m) is None
                    res.append((qual, f"{o}: {'ok' if ok else 'VAGUE'}", f"{bad!r}: {m[:200]}"))
                except TO:
                    res.append((qual, f"{o}: TIMEOUT", src[:120]))
                except BaseException as e:
                    signal.alarm(0)
                    res.append((qual, f"{o}: GENERIC {type(e).__name__}", f"{bad!r}: {str(e)[:150]}"))
    for r in res:
        print(json.dumps(r))


if __name__ == "__main__":  # a script: importing it (pytest's doctest collection does) runs nothing
    main()
