"""Call each public function's first documented example again with one string option misspelt (run as a script in a
subprocess by test_option_typos).  Prints one JSON line per function and option: the outcome and the message."""

import ast
import doctest
import inspect
import json
import signal
import sys
import warnings

sys.path.insert(0, str(__import__("pathlib").Path(__file__).parent))
from _api_walk import public_functions

from symosc.errors import SymoscError


class TO(BaseException):
    pass


def alarm(*a):
    raise TO


signal.signal(signal.SIGALRM, alarm)
res = []
for qual, fn in public_functions():
    sig = inspect.signature(fn)
    opts = [p.name for p in sig.parameters.values() if isinstance(p.default, str)]
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
        typo = ast.Constant(sig.parameters[o].default + "x")
        args = list(target.args)
        keywords = [k for k in target.keywords if k.arg != o]
        if o in positional and positional.index(o) < len(args):
            args[positional.index(o)] = typo
        else:
            keywords.append(ast.keyword(arg=o, value=typo))
        call = ast.Call(func=target.func, args=args, keywords=keywords)
        src = ast.unparse(call)
        try:
            signal.alarm(20)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                eval(src, ns)
            signal.alarm(0)
            res.append((qual, f"{o}: ACCEPTED", src[:100]))
        except SymoscError as e:
            signal.alarm(0)
            m = str(e)
            ok = "did you mean" in m and o in m
            res.append((qual, f"{o}: {'ok' if ok else 'VAGUE'}", m[:200]))
        except TO:
            res.append((qual, f"{o}: TIMEOUT", src[:100]))
        except BaseException as e:
            signal.alarm(0)
            res.append((qual, f"{o}: GENERIC {type(e).__name__}", str(e)[:150]))
for r in res:
    print(json.dumps(r))
