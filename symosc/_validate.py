"""Argument checks shared by the public functions (private).

Each helper raises :class:`~symosc.errors.ParameterError` naming the argument, what was given and what is
expected, so bad input never surfaces as a NumPy/SymPy exception from deep inside.
"""

from __future__ import annotations

import difflib
import functools
import inspect
import numbers
import os
import re
from collections.abc import Iterable
from typing import Any

import numpy as np
from sympy import Basic as sp_Basic
from sympy.polys.polyerrors import BasePolynomialError

from .errors import ModelError, ParameterError
from .errors import SymoscError as SymoscError_

__all__ = [
    "check_bool",
    "check_choice",
    "check_complete_names",
    "check_finite",
    "check_finite_array",
    "check_int",
    "check_known_names",
    "check_memory",
    "check_positive",
    "check_sympy_matrix",
]


def _show(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def check_finite(name: str, value: Any) -> float:
    """``value`` as a finite float (bool, None, strings and nan/inf are refused)."""
    if isinstance(value, bool) or value is None or isinstance(value, str | bytes):
        raise ParameterError(f"{name} must be a finite real number, got {_show(value)}")
    try:
        out = float(value)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a finite real number, got {_show(value)}") from exc
    if not np.isfinite(out):
        raise ParameterError(f"{name} must be finite, got {out}")
    return out


def check_positive(name: str, value: Any, *, allow_zero: bool = False) -> float:
    """``value`` as a finite float that is > 0 (or >= 0 with ``allow_zero``)."""
    out = check_finite(name, value)
    if out < 0 or (out == 0 and not allow_zero):
        raise ParameterError(f"{name} must be {'>= 0' if allow_zero else 'positive'}, got {out}")
    return out


def check_int(name: str, value: Any, *, minimum: int | None = None, maximum: int | None = None) -> int:
    """``value`` as an int (integral floats such as ``3.0`` pass; ``1.5``, nan, strings, bools do not)."""
    if isinstance(value, bool) or value is None or isinstance(value, str | bytes):
        raise ParameterError(f"{name} must be an integer, got {_show(value)}")
    if isinstance(value, numbers.Integral):
        out = int(value)
    else:
        try:
            f = float(value)
        except (TypeError, ValueError) as exc:
            raise ParameterError(f"{name} must be an integer, got {_show(value)}") from exc
        if not np.isfinite(f) or f != int(f):
            raise ParameterError(f"{name} must be an integer, got {_show(value)}")
        out = int(f)
    if minimum is not None and out < minimum:
        raise ParameterError(f"{name} must be >= {minimum}, got {out}")
    if maximum is not None and out > maximum:
        raise ParameterError(f"{name} must be <= {maximum}, got {out}")
    return out


def check_bool(name: str, value: Any) -> bool:
    """``value`` as a bool; only True/False (and NumPy bools) are accepted, not strings such as ``"yes"``."""
    if isinstance(value, bool | np.bool_):
        return bool(value)
    raise ParameterError(f"{name} must be True or False, got {_show(value)}")


def _suggest(value: Any, choices: Iterable[Any]) -> str:
    names = [str(c) for c in choices]
    close = difflib.get_close_matches(str(value), names, n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def check_choice(name: str, value: Any, choices: Iterable[Any]) -> Any:
    """``value`` if it is one of ``choices``; otherwise an error listing them with the closest match."""
    choices = tuple(choices)
    try:
        ok = value in choices
    except TypeError:
        ok = False
    if not ok:
        raise ParameterError(
            f"unknown {name} {_show(value)}{_suggest(value, choices)}; choose one of {', '.join(map(repr, choices))}"
        )
    return value


def check_known_names(what: str, given: Iterable[Any], valid: Iterable[Any]) -> None:
    """Raise when ``given`` holds names that are not in ``valid`` (misspelt parameters go unnoticed otherwise)."""
    valid_names = {str(v): v for v in valid}
    unknown = [g for g in given if str(g) not in valid_names]
    if unknown:
        hints = "".join(_suggest(u, valid_names) for u in unknown[:1])
        raise ParameterError(f"unknown {what} {sorted(map(str, unknown))}{hints}; valid names: {sorted(valid_names)}")


def check_complete_names(what: str, given: Iterable[Any], needed: Iterable[Any]) -> None:
    """Raise when a needed name is missing, listing the unknown names given (with the closest match).

    Extra names are harmless when every needed name is present (a shared dict of values); when one is missing, an
    unknown name given instead is most likely a misspelling, and the error says so.
    """
    given_names = [str(getattr(g, "name", g)) for g in given]
    needed_names = [str(getattr(v, "name", v)) for v in needed]
    missing = sorted(set(needed_names) - set(given_names))
    if not missing:
        return
    unknown = [g for g in given_names if g not in needed_names]
    hints = [f"{u!r} -> {close[0]!r}" for u in unknown if (close := difflib.get_close_matches(u, missing, n=1))]
    extra = f"; unknown {what} given: {', '.join(sorted(unknown))}" if unknown else ""
    hint = f" (misspelt? {', '.join(hints)})" if hints else ""
    raise ParameterError(f"missing values for: {', '.join(missing)}{extra}{hint}; valid names: {sorted(needed_names)}")


def check_sympy_matrix(name: str, value: Any) -> Any:
    """``value`` as a SymPy Matrix (a scalar, None or a ragged nesting is refused, naming the argument)."""
    import sympy

    if isinstance(value, sympy.MatrixBase):
        return value
    if value is None or isinstance(value, str | bytes | numbers.Number | sp_Basic) or np.ndim(value) == 0:
        raise ParameterError(f"{name} must be a matrix (nested list, NumPy array or SymPy Matrix), got {_show(value)}")
    try:
        return sympy.Matrix(value)
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a rectangular matrix: {exc}") from exc


def check_finite_array(name: str, value: Any, *, ndim: int | None = None, complex_ok: bool = False) -> np.ndarray:
    """``value`` as a finite float (or complex) ndarray, optionally of a given number of dimensions."""
    if value is None or isinstance(value, str | bytes):
        raise ParameterError(f"{name} must be an array of numbers, got {_show(value)}")
    try:
        arr = np.asarray(value, dtype=complex if complex_ok else float)
    except (TypeError, ValueError) as exc:
        raise ParameterError(
            f"{name} must be an array of {'complex' if complex_ok else 'real'} numbers: {exc}"
        ) from exc
    if ndim is not None and arr.ndim != ndim:
        raise ParameterError(f"{name} must have {ndim} dimension(s), got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{name} must contain only finite numbers (found nan or inf)")
    return arr


def physical_memory() -> int | None:
    """Bytes of memory this process may use: the machine's physical memory (``os.sysconf``), or the control group's
    limit when a smaller one is set (a container); None when neither can be read."""
    try:
        total = int(os.sysconf("SC_PAGE_SIZE")) * int(os.sysconf("SC_PHYS_PAGES"))
    except (ValueError, OSError, AttributeError):  # pragma: no cover - a platform without sysconf
        total = None
    try:
        with open("/sys/fs/cgroup/memory.max", encoding="ascii") as fh:
            limit = fh.read().strip()
        if limit.isdigit():
            total = int(limit) if total is None else min(total, int(limit))
    except OSError:
        pass
    return total if total and total > 0 else None


def _bytes(n: float) -> str:
    for unit in ("bytes", "KiB", "MiB", "GiB", "TiB", "PiB"):
        if n < 1024 or unit == "PiB":
            return f"{n:.3g} {unit}"
        n /= 1024
    return f"{n:.3g} PiB"  # pragma: no cover


def check_memory(what: str, n_bytes: float, advice: str = "") -> None:
    """Refuse up front a request whose arrays would need more than the memory of the machine.

    ``what`` names the request and the argument that sizes it (``"min_time_1dof(): 5e11 switching times (a/u_m =
    1e12)"``), ``n_bytes`` is the estimate, ``advice`` what to do instead.  A ParameterError with the estimate
    replaces the MemoryError (or the swapping machine) the request would otherwise end in.
    """
    total = physical_memory()
    if total is None or not n_bytes > total:
        return
    raise ParameterError(
        f"{what} would need about {_bytes(float(n_bytes))} of memory, more than this machine has ({_bytes(total)})"
        + (f"; {advice}" if advice else "")
    )


# ------------------------------------------------------------------------------------------ boundary guard
#: exceptions that must not leave the public API when an argument is invalid
_GENERIC = (TypeError, ValueError, AttributeError, ZeroDivisionError, IndexError, KeyError, OverflowError,
            ArithmeticError, LookupError, NotImplementedError, MemoryError, RecursionError,
            BasePolynomialError)  # fmt: skip
_NUMERIC_WORDS = ("float", "int", "Any", "complex", "Number", "Real", "Expr", "ArrayLike", "ndarray", "Basic")


def _suspicious(value: Any, annotation: str) -> str | None:
    """Why ``value`` looks invalid for a parameter annotated ``annotation`` (None when it looks fine)."""
    ann = str(annotation)
    if value is None:
        return "None"
    if isinstance(value, str | bytes):
        return f"the string {_show(value)}"
    if isinstance(value, bool | np.bool_):
        return None
    if isinstance(value, numbers.Number):
        try:
            f = complex(value)
        except (TypeError, ValueError):
            return None
        if not (np.isfinite(f.real) and np.isfinite(f.imag)):
            return f"the non-finite number {value}"
        if f == 0:
            return "zero"
        if f.imag == 0 and f.real < 0:
            return f"the negative number {value}"
        if "int" in ann and "float" not in ann and f.real != int(f.real):
            return f"the non-integer {value}"
        if callable_expected(ann):
            return f"the number {value}"
        if not any(w in ann for w in _NUMERIC_WORDS):
            return f"the number {value}"
        return None
    if isinstance(value, np.ndarray):
        if value.dtype.kind in "fc" and not np.all(np.isfinite(value)):
            return "an array with nan/inf"
        return f"an array of shape {value.shape}"
    return None


def _suspicious_argument(fn: Any, p: inspect.Parameter, value: Any) -> str | None:
    """:func:`_suspicious` for parameter ``p`` of ``fn``: a string that is the default or one of the choices the
    docstring lists (``{"exact", "numeric"}``) is an ordinary option, not a suspect."""
    if isinstance(value, str) and (value == p.default or repr(value) in _choices(fn, p.name)):
        return None
    return _suspicious(value, str(p.annotation))


def _choices(fn: Any, pname: str) -> str:
    kind = _docstring_parameters(inspect.getdoc(fn) or "").get(pname, ("", ""))[0].replace('"', "'")
    return kind if kind.startswith("{") else ""


def callable_expected(annotation: str) -> bool:
    return "Callable" in annotation and "Expr" not in annotation and "Any" not in annotation


_MIXED: dict[type, type] = {}


def _parameter_error_like(exc: BaseException) -> type:
    """ParameterError that is also an instance of the original exception's class (``except KeyError`` keeps
    working for callers that relied on it), when Python allows the mix; plain ParameterError otherwise."""
    kind = type(exc)
    if kind not in _MIXED:
        try:
            _MIXED[kind] = type(
                "ParameterError",
                (ParameterError, kind),
                {"__module__": "symosc.errors", "__str__": BaseException.__str__},  # the message, not kind's format
            )
        except TypeError:  # incompatible instance layouts
            _MIXED[kind] = ParameterError
    return _MIXED[kind]


_SECTION = re.compile(r"^[ \t]*(Parameters|Other Parameters)[ \t]*\n[ \t]*-{3,}[ \t]*\n", re.MULTILINE)
_NEXT_SECTION = re.compile(r"^[ \t]*[A-Z][A-Za-z ]+[ \t]*\n[ \t]*-{3,}[ \t]*$", re.MULTILINE)


def _docstring_parameters(doc: str) -> dict[str, tuple[str, str]]:
    """``{name: (type, first sentence)}`` from the numpydoc "Parameters" sections of ``doc``."""
    out: dict[str, tuple[str, str]] = {}
    if not doc:
        return out
    doc = inspect.cleandoc(doc)
    for match in _SECTION.finditer(doc):
        body = doc[match.end() :]
        stop = _NEXT_SECTION.search(body)
        body = body[: stop.start()] if stop else body
        entries = re.split(r"^(?=\S)", body, flags=re.MULTILINE)
        for entry in entries:
            head, _, rest = entry.partition("\n")
            if not head.strip():
                continue
            names, _, kind = head.partition(" : ")
            text = " ".join(rest.split()).replace("``", "'")
            text = re.sub(r":(?:func|class|meth|attr|mod|data|obj):`~?([^`]+)`", r"\1", text)
            sentence = re.split(r"(?<=[^.]\.)\s(?=[A-Z`(])", text, maxsplit=1)[0] if text else ""
            sentence = sentence.rstrip(".")
            if len(sentence) > 160:
                sentence = sentence[:157] + "..."
            for name in names.split(","):
                name = name.strip().lstrip("*")
                if name.isidentifier():
                    out[name] = (kind.strip(), sentence)
    return out


def _annotation_text(annotation: Any) -> str:
    if annotation is inspect.Parameter.empty:
        return ""
    text = annotation if isinstance(annotation, str) else getattr(annotation, "__name__", str(annotation))
    return str(text).replace("typing.", "")


@functools.lru_cache(maxsize=4096)
def expectation(fn: Any, pname: str) -> str:
    """What argument ``pname`` of ``fn`` must be: the docstring's "Parameters" entry (type and first sentence),
    else the type hint.  Computed once per function and argument (only on the error path)."""
    try:
        params = inspect.signature(fn).parameters
    except (TypeError, ValueError):  # pragma: no cover - builtins
        params = {}
    hint = _annotation_text(params[pname].annotation) if pname in params else ""
    doc = _docstring_parameters(inspect.getdoc(fn) or "")
    kind, sentence = doc.get(pname, ("", ""))
    if not kind and hint in ("", "Any"):  # undocumented: show the value a documented example passes
        example = _example_arguments(fn).get(pname)
        if example is not None:
            return f"a value like {example} (as in the documented example {getattr(fn, '__name__', '')}(...))"
        summary = (inspect.getdoc(fn) or "").strip().split("\n", 1)[0].rstrip(".")
        name = getattr(fn, "__name__", "the function")
        return f"see help({name}): {summary}" if summary else f"see help({name})"
    kind = kind or hint
    if pname in params and params[pname].default is not inspect.Parameter.empty and "default" not in kind:
        kind += f" (default {_show(params[pname].default)})"
    return f"{kind} — {sentence}" if sentence else kind


#: words that state what an argument must be (or what to do instead)
_EXPECTATION = re.compile(
    r"expected|must|should|choose|valid|\buse\b|>=|<=|> 0|< 0|positive|negative|finite|at least|at most|one of|"
    r"did you mean|need|require|only|cannot|not allowed|\bgive\b|\bpass\b|instead|range|integer|nonzero|"
    r"non-zero|smaller|larger|greater|less than|substitute",
    re.IGNORECASE,
)


def names_argument(message: str, pname: str) -> bool:
    """Whether ``message`` mentions the argument ``pname`` as a word."""
    return re.search(rf"(?<![A-Za-z0-9_]){re.escape(pname)}(?![A-Za-z0-9_])", message) is not None


def message_is_explicit(message: str, params: Any) -> bool:
    """A message names one of ``params`` and states an expectation (what to give, or what to do)."""
    return any(names_argument(message, p) for p in params) and _EXPECTATION.search(message) is not None


def _shown_in(value: Any, message: str) -> bool:
    if isinstance(value, bool) or value is None:
        return False
    try:
        text = str(value)
    except Exception:  # pragma: no cover - a value that cannot print itself
        return False
    return 0 < len(text) <= 60 and text in message


def _example_arguments(fn: Any) -> dict[str, str]:
    """``{parameter: source text}`` of the arguments passed to ``fn`` in its docstring's doctest examples."""
    import ast

    name = getattr(fn, "__name__", None)
    doc = inspect.getdoc(fn) or ""
    try:
        params = [
            p.name
            for p in inspect.signature(fn).parameters.values()
            if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
        ]
    except (TypeError, ValueError):  # pragma: no cover - builtins
        return {}
    statements, current = [], []
    for line in doc.splitlines():
        stripped = line.strip()
        if stripped.startswith(">>> "):
            if current:
                statements.append("\n".join(current))
            current = [stripped[4:]]
        elif stripped.startswith("... ") or stripped == "...":
            current.append(stripped[4:])
    if current:
        statements.append("\n".join(current))
    found: dict[str, str] = {}
    for source in statements:
        try:
            tree = ast.parse(source)
        except SyntaxError:
            continue
        for node in ast.walk(tree):
            if not isinstance(node, ast.Call):
                continue
            called = node.func.id if isinstance(node.func, ast.Name) else getattr(node.func, "attr", None)
            if called != name:
                continue
            pairs = list(zip(params, node.args, strict=False)) + [(k.arg, k.value) for k in node.keywords if k.arg]
            for pname, value in pairs:
                text = ast.unparse(value)
                found.setdefault(pname, text if len(text) <= 60 else text[:57] + "...")
    return found


def _closest_option(message: str, given: list[str]) -> str:
    """`` (did you mean 'x'?)`` for the first string in ``given`` close to a word of ``message`` (the message or the
    expectation lists the valid values)."""
    words = set(re.findall(r"[A-Za-z_][A-Za-z0-9_]{0,39}", message))
    words |= set(re.findall(r"['\"]([^'\"\s]{1,40})['\"]", message))
    for value in given:
        close = difflib.get_close_matches(value, sorted(words - {value}), n=1, cutoff=0.6)
        if close:
            return f" (did you mean {close[0]!r}?)"
    return ""


def describe_argument(fn: Any, pname: str, got: str) -> str:
    """``"argument 'n' of f got -1; expected: int — number of links"``."""
    name = getattr(fn, "__name__", "function")
    return f"argument {pname!r} of {name}() got {got}; expected: {expectation(fn, pname)}"


def _tolerance(fname: str, pname: str, value: Any, *, allow_zero: bool = False) -> None:
    if value is None:
        return
    try:
        check_positive(pname, value, allow_zero=allow_zero)
    except ParameterError as exc:
        raise ParameterError(
            f"{fname}(): {exc} (a tolerance: a finite number {'>=' if allow_zero else '>'} 0)"
        ) from None


def _count(fname: str, pname: str, value: Any, *, minimum: int = 1) -> None:
    if value is None:
        return
    try:
        check_int(pname, value, minimum=minimum)
    except ParameterError as exc:
        raise ParameterError(f"{fname}(): {exc} (a count or a limit: an integer >= {minimum})") from None


def _seed(fname: str, pname: str, value: Any) -> None:
    bad = isinstance(value, str | bytes | float | bool) or (isinstance(value, numbers.Integral) and value < 0)
    if bad:
        raise ParameterError(
            f"{fname}(): {pname} must be None, an integer >= 0 or a numpy.random.Generator, got {_show(value)}"
        )


def _conventional_parameters(params: Any) -> dict[str, Any]:
    """Checks for parameters whose meaning the name fixes across symosc: tolerances ``rtol``/``tol`` (> 0),
    ``atol`` (>= 0), ``dps`` and integer limits ``max_*`` (integers >= 1), ``seed``.  Applied up front, only to
    values the caller passes (defaults are trusted)."""
    out: dict[str, Any] = {}
    for pname, p in params.items():
        default = p.default
        if pname in ("rtol", "tol") and (default is None or isinstance(default, float)):
            out[pname] = _tolerance
        elif pname == "atol" and isinstance(default, float):
            out[pname] = functools.partial(_tolerance, allow_zero=True)
        elif pname == "dps" and (default is None or isinstance(default, int)):
            out[pname] = _count
        elif pname.startswith("max_") and isinstance(default, int) and not isinstance(default, bool):
            out[pname] = _count
        elif pname.startswith("max_") and isinstance(default, float):
            out[pname] = _tolerance
        elif pname == "seed" and (default is None or isinstance(default, int)):
            out[pname] = _seed
    return out


def _alternatives(text: str) -> list[str]:
    """The top-level alternatives of an annotation: ``"str | Sequence[str] | None"`` -> three."""
    text = text.strip()
    for wrapper in ("Optional[", "Union["):
        if text.startswith(wrapper) and text.endswith("]"):
            text = (
                text[len(wrapper) : -1].replace(",", "|") if wrapper == "Union[" else text[len(wrapper) : -1] + "|None"
            )
    out, depth, current = [], 0, ""
    for ch in text:
        depth += ch in "[("
        depth -= ch in "])"
        if ch == "|" and depth == 0:
            out.append(current.strip())
            current = ""
        else:
            current += ch
    return [*out, current.strip()]


def _admits_string(annotation: Any) -> bool:
    """Whether a parameter annotated ``annotation`` may receive a string: one of its alternatives is ``str``,
    a path or a ``Literal`` (a string default or a docstring type naming ``str`` admits strings too)."""
    if annotation is inspect.Parameter.empty:
        return False  # decided by the default and the docstring's type
    kinds = ("str", "Path", "os.PathLike", "PathLike")
    return any(
        a in kinds or a.startswith(("Literal", "PathLike", "os.PathLike"))
        for a in _alternatives(_annotation_text(annotation))
    )


def _documented_string(kind: str) -> bool:
    """Whether a docstring type admits a string: ``str``, a path, or a set of string choices ``{"a", "b"}``."""
    return re.search(r"\bstr\b|\bpath\b|^\{", kind.strip(), re.IGNORECASE) is not None


def validated(fn):
    """Decorator written at the definition of a public function: the checks that follow from its signature.

    Up front, on every call, with messages that name the argument and what it must be (the docstring's
    "Parameters" entry):

    * a string is refused where the annotation does not admit one (``hurwitz("abc")`` is not a polynomial in
      the symbols a, b, c), and None where the annotation does not admit None;
    * parameters whose name fixes their meaning across symosc: tolerances ``rtol``/``tol`` (> 0) and ``atol``
      (>= 0), digit counts ``dps`` and limits ``max_*`` (integers >= 1), random ``seed``.

    A generic exception (``TypeError``, ``ValueError``, ``ZeroDivisionError``, ...) raised from inside for a call
    with a suspicious argument (None, nan/inf, zero, a negative number, an array where a matrix was meant) becomes
    a :class:`~symosc.errors.ParameterError` naming those arguments, chained to the original; a
    :class:`~symosc.errors.ModelError` or ``ParameterError`` whose message does not say which argument is at fault
    gets that added.  Checks specific to one function stay in the function, at its top.
    """
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):  # pragma: no cover - builtins
        return fn
    params = sig.parameters
    name = fn.__name__
    renames = getattr(fn, "__symosc_renamed_keywords__", {})  # deprecated keyword -> new (forwarded with a warning)
    conventional = _conventional_parameters(params)
    maybe_refused = frozenset(
        p for p, par in params.items() if not (_admits_string(par.annotation) or isinstance(par.default, str))
    )

    @functools.cache
    def strings_refused() -> frozenset[str]:
        """The parameters that take no string: neither the annotation, the default nor the docstring's type admits
        one (computed on the first call with a string argument)."""
        kinds = _docstring_parameters(inspect.getdoc(fn) or "")
        return frozenset(p for p in maybe_refused if not _documented_string(kinds.get(p, ("", ""))[0]))

    positional_names = [p for p, par in params.items() if par.kind in (par.POSITIONAL_ONLY, par.POSITIONAL_OR_KEYWORD)]
    var_positional = next((p for p, par in params.items() if par.kind is par.VAR_POSITIONAL), None)
    keyword_names = frozenset(
        p for p, par in params.items() if par.kind in (par.POSITIONAL_OR_KEYWORD, par.KEYWORD_ONLY)
    )

    def string_may_be_refused(args, kwargs) -> bool:
        """Whether a string argument goes to a parameter that may refuse strings (True when unsure: extra positional
        arguments, unknown or renamed keywords), so that the signature is bound only then."""
        for i, value in enumerate(args):
            if isinstance(value, str | bytes):
                target = positional_names[i] if i < len(positional_names) else var_positional
                if target is None or target in maybe_refused:
                    return True
        for key, value in kwargs.items():
            if isinstance(value, str | bytes) and (key not in keyword_names or key in maybe_refused):
                return True
        return False

    conventional_names = frozenset(conventional)
    # positional index from which a conventional parameter can be given positionally (never, if none)
    first_position = min((i for i, p in enumerate(params) if p in conventional), default=1 << 30)

    def bind(args, kwargs):
        try:
            return sig.bind(*args, **{renames.get(k, k) if k not in params else k: v for k, v in kwargs.items()})
        except TypeError as exc:
            raise ParameterError(f"{name}(): {exc}") from None

    def refuse_none(args, kwargs):
        for pname, value in bind(args, kwargs).arguments.items():
            p = params[pname]
            if value is None and p.default is not None and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
                ann = str(p.annotation)
                typed = p.annotation is not inspect.Parameter.empty
                if typed and not any(k in ann for k in ("None", "Any", "Optional")):
                    raise ParameterError(f"{name}(): {pname} must not be None; {describe_argument(fn, pname, 'None')}")

    def refuse_strings(args, kwargs):
        for pname, value in bind(args, kwargs).arguments.items():
            p = params[pname]
            if p.kind is p.VAR_KEYWORD or p.name not in strings_refused():
                continue
            values = value if p.kind is p.VAR_POSITIONAL else (value,)
            for each in values:
                if isinstance(each, str | bytes):
                    if _annotation_text(p.annotation) == "bool":
                        raise ParameterError(f"{name}(): {pname} must be True or False, got the string {_show(each)}")
                    raise ParameterError(f"{name}(): {describe_argument(fn, pname, f'the string {_show(each)}')}")

    def translate(exc, args, kwargs):
        bad = []
        for pname, value in bind(args, kwargs).arguments.items():
            p = params[pname]
            if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
                continue
            why = _suspicious_argument(fn, p, value)
            tname = type(value).__name__
            named = f"'{tname}' object" in str(exc) or f"type '{tname}'" in str(exc)
            if why is None and not isinstance(value, sp_Basic) and named:
                why = f"a {type(value).__name__} ({_show(value)})"  # the error is about this argument's type
            if why is not None:
                bad.append(describe_argument(fn, pname, why))
        if not bad:
            raise exc
        strings = [v for k, v in bind(args, kwargs).arguments.items() if isinstance(v, str)]
        text = f"{name}(): invalid argument: {'; '.join(bad)}"
        raise _parameter_error_like(exc)(
            f"{text}{_closest_option(text, strings)} (the call failed with {type(exc).__name__}: {str(exc)[:160]})"
        ) from exc

    def explain(exc, args, kwargs):
        """``exc`` when its message names an argument of ``fn`` and states an expectation; otherwise a copy (same
        class) that also says which argument is at fault and what it must be (from the docstring or the hint).
        A misspelt option value named in the message gets the closest of the values the message quotes."""
        message = str(exc)
        explicit = message_is_explicit(message, params)
        if explicit and "did you mean" in message:
            return exc
        try:
            bound = bind(args, kwargs).arguments
        except ParameterError:
            return exc
        ordinary = {
            k: v for k, v in bound.items() if params[k].kind not in (params[k].VAR_POSITIONAL, params[k].VAR_KEYWORD)
        }
        named = [k for k in ordinary if names_argument(message, k)]
        if isinstance(exc, ModelError) and not isinstance(exc, ParameterError):
            # a model error that merely mentions an argument ("f(A) is not defined") is about the model: completed
            # only for arguments whose value itself looks wrong (nan, a string, zero, an array where a matrix was meant)
            suspicious = {k for k, v in ordinary.items() if _suspicious_argument(fn, params[k], v)}
            if not suspicious:
                return exc
            named = [k for k in named if k in suspicious]
        if explicit:
            text = message + _closest_option(message, [ordinary[k] for k in named if isinstance(ordinary[k], str)])
            if text == message:
                return exc
        elif named:  # the argument is named, the expectation is missing: add it
            extra = "; ".join(f"{k} must be: {expectation(fn, k)}" for k in named[:3])
            text = f"{message} ({extra})"
        else:
            culprits = [(k, why) for k, v in ordinary.items() if (why := _suspicious_argument(fn, params[k], v))]
            if not culprits:
                culprits = [(k, _show(v)) for k, v in ordinary.items() if _shown_in(v, message)]
            if not culprits:
                return exc
            text = f"{name}(): {'; '.join(describe_argument(fn, k, why) for k, why in culprits[:3])}: {message}"
        try:
            new = type(exc)(text)
        except Exception:  # pragma: no cover - an error class with a custom constructor: keep the original
            return exc
        for key, value in exc.__dict__.items():  # extra attributes, without undoing the new message
            new.__dict__.setdefault(key, value)
        return new

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        # the signature is bound only when an argument is None, a tolerance/limit is passed or the call fails
        for value in args:
            if value is None:
                refuse_none(args, kwargs)
                break
        if kwargs:
            for value in kwargs.values():
                if value is None:
                    refuse_none(args, kwargs)
                    break
        if maybe_refused and string_may_be_refused(args, kwargs):
            refuse_strings(args, kwargs)
        if len(args) > first_position or (kwargs and not conventional_names.isdisjoint(kwargs)):
            for pname, value in bind(args, kwargs).arguments.items():
                if pname in conventional:
                    conventional[pname](name, pname, value)
        try:
            return fn(*args, **kwargs)
        except (ParameterError, ModelError) as exc:
            explained = explain(exc, args, kwargs)
            if explained is exc:
                raise
            raise explained from exc
        except SymoscError_:
            raise
        except _GENERIC as exc:
            translate(exc, args, kwargs)
            raise  # pragma: no cover - translate always raises

    wrapper.__symosc_validated__ = True  # type: ignore[attr-defined]
    return wrapper
