from __future__ import annotations

import builtins
import itertools
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import mpmath
import numpy as np
import sympy as sp

from .._validate import check_choice
from ..errors import ParameterError, warn
from ..symbols import natural_key
from . import _python
from ._checks import check_all, nonfinite_message, python_condition
from ._emit import comment_text

_BACKENDS = ("numpy", "mpmath", "c", "llvm", "auto")


def _as_symbol_list(args: Any) -> list[sp.Symbol]:
    if isinstance(args, sp.Symbol):
        args = [args]
    if args is None or isinstance(args, (str, bytes)) or not isinstance(args, Iterable):
        raise ParameterError(f"args: expected a sequence of SymPy Symbols, got {args!r}")
    out = []
    for a in args:
        if isinstance(a, (list, tuple)) or (isinstance(a, sp.MatrixBase)):
            out.extend(_as_symbol_list(a))
        elif isinstance(a, sp.Symbol):
            out.append(a)
        else:
            raise ParameterError(f"compile(): args must be SymPy Symbols, got {a!r} ({type(a).__name__})")
    names = [s.name for s in out]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise ParameterError(f"argument names must be unique; repeated: {', '.join(dup)}")
    return out


def _sympified(e: Any) -> sp.Expr:
    if e is None or isinstance(e, (str, bytes)):
        raise ParameterError(f"exprs: expected a SymPy expression, Matrix or sequence of expressions, got {e!r}")
    try:
        out = sp.sympify(e, strict=True)
    except (sp.SympifyError, TypeError) as exc:
        raise ParameterError(f"exprs: cannot turn {e!r} ({type(e).__name__}) into a SymPy expression") from exc
    if not isinstance(out, (sp.Expr, sp.MatrixBase)):
        raise ParameterError(f"exprs: expected an algebraic expression, got {e!r} ({type(out).__name__})")
    return out


def _flatten_exprs(exprs: Any) -> tuple[list[sp.Expr], tuple[int, ...] | None]:
    """Return the flat element list and the output shape (None for a scalar)."""
    if isinstance(exprs, sp.MatrixBase):
        return [_sympified(e) for e in exprs], tuple(exprs.shape)
    if isinstance(exprs, (list, tuple)):
        items = [_sympified(e) for e in exprs]
        if any(isinstance(e, sp.MatrixBase) for e in items):
            raise ParameterError("compile() takes an expression, a Matrix or a flat sequence of expressions")
        return items, (len(items),)
    if isinstance(exprs, np.ndarray):
        return _flatten_exprs(sp.Matrix(exprs) if exprs.ndim == 2 else list(exprs.ravel()))
    return [_sympified(exprs)], None


@dataclass(frozen=True)
class CompiledFunction:
    """A numeric function generated from SymPy expressions by :func:`compile`.

    Call it with one value per argument, in the order of :attr:`args`, or with a mapping through
    :meth:`call`.  :attr:`source` is the generated code (Python for "numpy" and "mpmath", C99 for "c",
    a symengine script for "llvm"); it runs or compiles on its own.  Instances pickle: the expressions
    are stored and the function is rebuilt (from the disk cache for "c") on unpickling.
    """

    args: tuple[sp.Symbol, ...]
    backend: str
    shape: tuple[int, ...] | None
    _source: str | Callable[[], str] = field(repr=False, compare=False)  # text, or what writes it on first use
    dps: int | None
    check: bool
    name: str = ""
    exprs: tuple = field(default=(), repr=False)
    _func: Callable = field(default=None, repr=False, compare=False)
    _checked: Callable = field(default=None, repr=False, compare=False)

    @property
    def source(self) -> str:
        """The generated code (written on first access for "llvm", whose evaluator needs no source text)."""
        if not isinstance(self._source, str):
            object.__setattr__(self, "_source", self._source())
        return self._source

    @property
    def raw(self) -> Callable:
        """The generated function without argument checks (for inner loops such as ODE right-hand sides)."""
        return self._func

    def __call__(self, *values: Any) -> Any:
        if len(values) != len(self.args):
            check_all(self.args, values, self.backend)  # raises, naming the expected arguments
        if self.backend == "mpmath":
            # Convert inputs at the working precision, so that strings such as "1e-10" keep all their digits.
            with mpmath.workdps(self.dps or mpmath.mp.dps):
                if self.check:
                    values = check_all(self.args, values, self.backend)
                else:
                    values = tuple(mpmath.mpmathify(v) for v in values)
                return self._func(*values)
        if self.check:
            return self._checked(*values)
        return self._func(*values)

    def call(self, values: Mapping[Any, Any]) -> Any:
        """Evaluate with a mapping from argument symbols (or their names) to values."""
        return self(*resolve(self.args, values))

    def __reduce__(self):
        shape = self.shape
        exprs: Any = self.exprs[0] if shape is None else (sp.ImmutableMatrix(*_2d(shape), list(self.exprs)))
        if shape is not None and len(shape) == 1:
            exprs = list(self.exprs)
        name = None if self.name.startswith("_symosc_f") else self.name  # a default name is made again
        options = {"backend": self.backend, "dps": self.dps, "check": self.check, "name": name}
        return (_rebuild, (exprs, self.args, options))


def _2d(shape: tuple[int, ...]) -> tuple[int, int]:
    return (shape[0], 1) if len(shape) == 1 else shape


def _rebuild(exprs: Any, args: tuple, options: dict) -> CompiledFunction:
    return compile(exprs, list(args), **options)


class _SlowPath:
    """The thorough checked call: names a bad argument, warns when finite arguments give inf/NaN."""

    def __init__(self, fname: str, args: tuple, backend: str, func: Callable) -> None:
        self.fname, self.args, self.backend, self.func = fname, args, backend, func
        self.positive = [i for i, s in enumerate(args) if s.is_positive]
        self.nonnegative = [i for i, s in enumerate(args) if s.is_nonnegative and not s.is_positive]

    def _arrays_if_valid(self, values: tuple) -> tuple | None:
        """Real arrays and scalars checked in a few whole-batch NumPy calls; None sends the call to the naming path."""
        if self.backend == "mpmath" or len(values) != len(self.args):
            return None
        arrs = [np.asarray(v) for v in values]
        if not arrs or any(a.dtype.kind not in "fiu" or a.size == 0 for a in arrs):
            return None
        if not np.isfinite(np.concatenate([a.ravel() for a in arrs])).all():
            return None
        for indices, ok in ((self.positive, np.greater), (self.nonnegative, np.greater_equal)):
            if indices and not ok(np.concatenate([arrs[i].ravel() for i in indices]).min(), 0):
                return None
        return tuple(a.item() if a.ndim == 0 else a for a in arrs)

    def __call__(self, *values: Any) -> Any:
        checked = self._arrays_if_valid(values)
        if checked is None:
            checked = check_all(self.args, values, self.backend)
        if self.backend in ("c", "llvm"):
            for s, v in zip(self.args, checked, strict=True):
                if np.iscomplexobj(v):
                    raise ParameterError(f"{s.name}: the {self.backend} backend takes real values, got {v!r}")
        with np.errstate(all="ignore"):
            out = self.func(*checked)
        if not np.all(np.isfinite(out)):
            warn(nonfinite_message(self.fname, self.args, values), RuntimeWarning)
        return out


class _CChecked:
    def __init__(self, caller: Any, slow: _SlowPath) -> None:
        self.fast, self.slow = caller.fast_checked, slow

    def __call__(self, *values: Any) -> Any:
        status, out = self.fast(values)
        return out if status == 0 else self.slow(*values)


def _check_values(values: Any) -> None:
    if not isinstance(values, Mapping):
        raise ParameterError(f"values must be a mapping (Symbol or name -> number), got {values!r}")


def _iterable(value: Any, what: str) -> tuple:
    try:
        return tuple(value)
    except TypeError:
        raise ParameterError(f"{what} must be a sequence, got {value!r}") from None


def resolve(symbols: Sequence[sp.Symbol], values: Mapping[Any, Any]) -> list[Any]:
    """Pick the value of each symbol from ``values`` (keyed by Symbol or by name).

    Raises :class:`ParameterError` listing every missing name.

    >>> import sympy as sp
    >>> m, g = sp.symbols("m g")
    >>> resolve([m, g], {"m": 2.0, g: 9.81})
    [2.0, 9.81]
    >>> resolve([m, g], {"m": 2.0})
    Traceback (most recent call last):
    ...
    symosc.errors.ParameterError: missing values for: g
    """
    _check_values(values)
    if isinstance(symbols, str | bytes) or not all(isinstance(s, sp.Symbol) for s in _iterable(symbols, "symbols")):
        raise ParameterError(f"symbols must be a sequence of SymPy Symbols, got {symbols!r}")
    by_name: dict[str, Any] = {}
    for k, v in values.items():
        name = k.name if isinstance(k, sp.Symbol) else str(k)
        by_name[name] = v
    missing = [s.name for s in symbols if s.name not in by_name]
    if missing:
        raise ParameterError("missing values for: " + ", ".join(missing))
    return [by_name[s.name] for s in symbols]


def bind(expr: Any, values: Mapping[Any, Any]) -> Any:
    """Substitute numeric ``values`` (keyed by Symbol or name) into ``expr`` exactly (no floats added).

    >>> import sympy as sp
    >>> a, b = sp.symbols("a b")
    >>> bind(a + b, {"a": 1, "b": sp.Rational(1, 2)})
    3/2
    """
    _check_values(values)
    if expr is None or isinstance(expr, str | bytes):
        raise ParameterError(f"expr must be a SymPy expression or matrix, got {expr!r}")
    expr = sp.sympify(expr)
    syms = {s.name: s for s in expr.free_symbols}
    sub = {}
    for k, v in values.items():
        name = k.name if isinstance(k, sp.Symbol) else str(k)
        if name in syms:
            sub[syms[name]] = sp.sympify(v)
    return expr.xreplace(sub)


_counter = itertools.count()


def compile(
    exprs: Any,
    args: Sequence[Any],
    *,
    backend: str = "numpy",
    dps: int | None = None,
    check: bool = True,
    name: str | None = None,
) -> CompiledFunction:
    """Compile a SymPy expression, Matrix or flat sequence of expressions into a numeric callable.

    Parameters
    ----------
    exprs : Expr, Matrix or sequence of Expr
        What to evaluate.  A sequence gives a 1-D result.
    args : sequence of Symbol
        The arguments, in call order.  Nested sequences and column matrices of symbols are flattened.
        Every free symbol of ``exprs`` must be among them.
    backend : {"numpy", "mpmath", "c", "llvm", "auto"}
        ``"numpy"`` broadcasts over array arguments; ``"mpmath"`` evaluates scalars at ``dps`` digits;
        ``"c"`` generates C99, builds it with the system compiler (cached on disk, see
        :func:`~symosc.numeric.cache_dir`) and loops over array arguments in C; ``"llvm"`` uses symengine's
        LLVM JIT (extra ``symosc[fast]``); ``"auto"`` picks ``"c"``, else ``"llvm"``, else ``"numpy"``
        (``.backend`` tells which).  "c" and "llvm" evaluate real values only.
    dps : int, optional
        Decimal digits for the mpmath backend (default: the current ``mpmath.mp.dps``).
    check : bool
        Check argument count, finiteness and declared signs (``positive``/``nonnegative``/``real``
        assumptions) on every call.  The unchecked function is always available as ``.raw``.
    name : str, optional
        Name of the generated function (shown in ``.source``).

    Returns
    -------
    CompiledFunction

    Raises
    ------
    ParameterError
        If ``exprs`` has free symbols that are not arguments (all of them are named), if an argument is
        not a Symbol, if argument names repeat, or if the backend cannot print a function (named).
    CompilerError
        ``backend="c"`` without a working C compiler (the message says what to install).

    See Also
    --------
    symosc.codegen.export : the same expressions written to C, Python, Julia, Fortran or Octave files.
    symosc.mechanics.FirstOrderSystem.rhs : compiled right-hand sides of equations of motion.

    Notes
    -----
    Evaluation follows IEEE/NumPy semantics: ``1/x`` at ``x = 0`` gives ``inf``, ``sqrt(-1)`` gives ``nan``.
    A checked call whose finite arguments give a non-finite result also warns (``RuntimeWarning`` naming the
    function and the argument values); ``.raw`` does not.

    Examples
    --------
    >>> import sympy as sp
    >>> x, k = sp.symbols("x k", real=True)
    >>> f = compile(sp.Matrix([[sp.cos(k * x), 1], [0, x**2]]), [x, k])
    >>> f([0.0, 1.0], 2.0).shape
    (2, 2, 2)
    >>> compile(x + k, [x])
    Traceback (most recent call last):
    ...
    symosc.errors.ParameterError: expression depends on symbols that are not arguments: k
    >>> import mpmath
    >>> h = compile(sp.exp(x), [x], backend="mpmath", dps=30)
    >>> mpmath.nstr(h(1), 30)
    '2.71828182845904523536028747135'
    >>> c = compile(sp.cos(k * x), [x, k], backend="c")  # needs a C compiler
    >>> c([0.0, 1.0], 2.0).round(6).tolist()
    [1.0, -0.416147]
    """
    check_choice("backend", backend, _BACKENDS)
    if exprs is None:
        raise ParameterError("exprs: expected a SymPy expression, Matrix or sequence of expressions, got None")
    arg_syms = _as_symbol_list(args)
    items, shape = _flatten_exprs(exprs)
    free = set().union(*(e.free_symbols for e in items)) if items else set()
    missing = free - set(arg_syms)
    if missing:
        names = ", ".join(s.name for s in sorted(missing, key=natural_key))
        raise ParameterError(f"expression depends on symbols that are not arguments: {names}")
    if backend == "auto":
        return _auto(exprs, arg_syms, dps=dps, check=check, name=name)
    default = "symosc_f" if backend in ("c", "llvm") else f"_symosc_f{next(_counter)}"  # stable C names cache well
    if name is not None:
        _check_function_name(name, backend)
    fname = name or default
    originals = tuple(items)
    items = _evaluate_root_constants(items, (dps or mpmath.mp.dps) + 10 if backend == "mpmath" else 20)
    if backend == "llvm":
        from . import _llvm

        source, func = _llvm.build(fname, arg_syms, items, shape)
        names = [f"_a{i}" for i in range(len(arg_syms))]
        conditions = [python_condition(s, a) for s, a in zip(arg_syms, names, strict=True)]
        test = " and ".join([f"type({a}) in _REAL_TYPES" for a in names] + conditions) or "True"
        wrapper = (
            f"def _checked({', '.join(names)}):\n"
            f"    if {test}:\n"
            f"        _out = _func({', '.join(names)})\n"
            "        if _isfinite(_out).all():\n"
            "            return _out\n"
            f"    return _slow({', '.join(names)})\n"
        )
        namespace = {"_func": func, "_slow": _SlowPath(fname, tuple(arg_syms), backend, func), "_INF": float("inf")}
        namespace |= {"_REAL_TYPES": frozenset({float, int, np.float64}), "_isfinite": np.isfinite}
        exec(builtins.compile(wrapper, f"<symosc:{fname}:checked>", "exec"), namespace)
        checked = namespace["_checked"]
        return CompiledFunction(tuple(arg_syms), backend, shape, source, dps, check, fname, originals, func, checked)

    arg_names = _argument_names(arg_syms)
    renamed = {s: sp.Symbol(n, **s.assumptions0) for s, n in zip(arg_syms, arg_names, strict=True)}
    changed = {s: r for s, r in renamed.items() if s != r}
    if changed:  # (a walk over the whole tree: only when a name must change)
        items = [e.xreplace(changed) for e in items]

    def reduce() -> tuple[list, list]:
        from ._dag import cse

        return cse(items, [renamed[s] for s in arg_syms])

    if backend == "c":
        from . import _build, _c

        tag = _build.expression_digest(items, "compile", fname, repr(shape), *(sp.srepr(s) for s in arg_syms))
        source = _build.memoized_source(tag, lambda: _c.function_source(fname, arg_syms, arg_names, items, shape))
        caller = _c.CCaller(source, fname, len(arg_syms), len(items), shape)
        slow = _SlowPath(fname, tuple(arg_syms), backend, caller)
        checked = _CChecked(caller, slow)
        return CompiledFunction(tuple(arg_syms), backend, shape, source, dps, check, fname, originals, caller, checked)

    doc = f"Generated by symosc.numeric.compile; arguments: {', '.join(comment_text(s.name) for s in arg_syms)}."
    if backend == "mpmath":
        source = _python.mpmath_source(fname, doc, arg_names, *reduce(), shape)
    else:
        source = _python.numpy_source(fname, doc, [renamed[s] for s in arg_syms], items, shape)
    namespace: dict[str, Any] = {"__builtins__": builtins}
    exec(builtins.compile(source, f"<symosc:{fname}>", "exec"), namespace)
    func = namespace[fname]
    checked = None
    if backend == "numpy":
        conditions = [python_condition(s, a) for s, a in zip(arg_syms, arg_names, strict=True)]
        wrapper = _python.checked_wrapper_source(fname, arg_names, conditions, shape)
        namespace["_slow"] = _SlowPath(fname, tuple(arg_syms), backend, func)
        namespace["_REAL_TYPES"] = frozenset({float, int, np.float64})
        namespace["_INF"] = float("inf")
        exec(builtins.compile(wrapper, f"<symosc:{fname}:checked>", "exec"), namespace)
        checked = namespace["_checked"]
    return CompiledFunction(tuple(arg_syms), backend, shape, source, dps, check, fname, originals, func, checked)


def available_backends() -> tuple[str, ...]:
    """The backends usable here: "numpy" and "mpmath" always, "c" with a C compiler, "llvm" with symengine.

    >>> {"numpy", "mpmath"} <= set(available_backends())
    True
    """
    from . import _build

    found = ["numpy", "mpmath"]
    try:
        _build.compiler()
        found.append("c")
    except _build.CompilerError:
        pass
    from . import _llvm

    if _llvm.available():
        found.append("llvm")
    return tuple(found)


def _auto(exprs: Any, arg_syms: list, **options: Any) -> CompiledFunction:
    """backend="auto": C when a compiler works, else symengine LLVM, else NumPy (``.backend`` says which).

    A backend that cannot print an expression (e.g. Bessel functions in C) is passed over for the next.
    """
    from ._build import CompilerError

    order = [b for b in ("c", "llvm") if b in available_backends()]
    for backend in order:
        try:
            return compile(exprs, arg_syms, backend=backend, **options)
        except (ParameterError, CompilerError):
            continue
    return compile(exprs, arg_syms, backend="numpy", **options)


def _evaluate_root_constants(items: list[sp.Expr], digits: int) -> list[sp.Expr]:
    """``items`` with algebraic-number constants (``CRootOf``) replaced by floats of ``digits`` significant digits.

    Exact matrix functions of matrices with irreducible cubic (or higher) characteristic polynomials
    contain ``CRootOf`` objects, which no numeric printer knows.
    """
    from ._dag import subexpressions

    roots = {r: r.evalf(digits) for r in subexpressions(items) if isinstance(r, sp.CRootOf)}
    return [e.xreplace(roots) for e in items] if roots else list(items)


#: Names generated Python code uses besides its own "_"-prefixed ones: modules and the builtins it calls (an
#: argument named ``type`` or ``sum`` would shadow them).
_PYTHON_RESERVED = frozenset({"numpy", "mpmath", "math", "scipy", "functools"} | set(dir(builtins)))


def _argument_names(symbols: list[sp.Symbol]) -> list[str]:
    """Parameter names for the generated code: the symbol's own name where it is a safe identifier, else ``_a<i>``.

    A name is never pasted into code unchecked: it must be an ASCII identifier that is no Python keyword, no name
    the generated code itself uses, and does not start with "_" (temporaries and helpers do).
    """
    import keyword

    names = []
    for i, s in enumerate(symbols):
        ok = s.name.isidentifier() and s.name.isascii() and not keyword.iskeyword(s.name)
        ok = ok and not s.name.startswith("_") and s.name not in _PYTHON_RESERVED and s.name not in names
        names.append(s.name if ok else f"_a{i}")
    return names


def _check_function_name(fname: str, backend: str) -> None:
    """``name=`` must be an identifier that is no keyword or library name of the generated code (named error)."""
    import keyword

    from ._c import _C_KEYWORDS, _C_RESERVED

    if not isinstance(fname, str) or not fname.isidentifier() or not fname.isascii():
        raise ParameterError(f"name must be an ASCII identifier, got {fname!r}")
    clash = keyword.iskeyword(fname) or fname in _PYTHON_RESERVED or fname.startswith(("symosc_solve", "_symosc_"))
    if backend == "c":
        clash = clash or fname in _C_KEYWORDS or fname in _C_RESERVED or fname.startswith(("symosc_mod", "symosc_arg"))
        clash = clash or fname.startswith("symosc_loggamma")
    if clash:
        raise ParameterError(
            f"name {fname!r} is a keyword or a library name of the generated {backend} code; choose another name"
        )
