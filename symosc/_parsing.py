"""The one parser for expressions that come from files and the command line (private).

Text is never evaluated.  It is parsed by Python's :mod:`ast` and the tree is walked against an explicit grammar
that builds SymPy objects directly:

* **expressions** (:func:`parse_expression`): numbers, names, ``+ - * / **`` (``^`` means ``**``), unary signs
  and calls of a listed set of functions with expression arguments.  No string literals, attribute access,
  subscripts, keywords, comparisons, lambdas or comprehensions;
* **SymPy's ``srepr``** (:func:`parse_srepr`, the format of saved summaries): calls of a listed set of SymPy
  classes and functions with expression arguments, symbol names as string literals, assumptions as boolean
  keywords.

Sizes are bounded before anything is built (text length, nodes, nesting depth, digits of integer literals,
exponents), so a short text cannot ask for a number with billions of digits (``9**9**9``) or an expansion that
exhausts the memory.  Every refusal is an :class:`ExpressionError` naming what was refused and the limit.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Callable, Mapping
from typing import Any

import sympy as sp

from .errors import ParameterError

__all__ = ["LIMITS", "ExpressionError", "parse_expression", "parse_srepr"]

#: the bounds checked before an expression is built
LIMITS = {
    "characters": 100_000,  # length of one expression's text
    "nodes": 20_000,  # syntax-tree nodes
    "depth": 60,  # nesting of operations and calls
    "literal digits": 400,  # digits of one integer literal
    "result digits": 10_000,  # digits of an integer or rational built from literals
    "exponent": 1_000,  # |exponent| of a power whose base is not a plain number
}

#: functions an expression may call (name -> SymPy function); ``pi`` is a constant
FUNCTIONS: dict[str, Callable[..., sp.Expr]] = {
    "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "exp": sp.exp, "log": sp.log, "sqrt": sp.sqrt,
    "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh, "atan": sp.atan, "asin": sp.asin, "acos": sp.acos,
    "Abs": sp.Abs, "abs": sp.Abs, "sign": sp.sign, "Heaviside": sp.Heaviside,
}  # fmt: skip
CONSTANTS: dict[str, sp.Expr] = {"pi": sp.pi}


class ExpressionError(ParameterError):
    """Text that is not an expression of the accepted grammar, or one beyond the size limits."""


def _too_big(kind: str, detail: str) -> ExpressionError:
    return ExpressionError(f"{detail}: beyond the limit on {kind} ({LIMITS[kind]:,})")


def _check_tree(tree: ast.AST) -> None:
    count = sum(1 for _ in ast.walk(tree))
    if count > LIMITS["nodes"]:
        raise _too_big("nodes", f"the expression has {count:,} syntax nodes")


def _parse_text(text: Any, what: str) -> ast.expr:
    if not isinstance(text, str):
        raise ExpressionError(f"{what} must be text, got {type(text).__name__}")
    if len(text) > LIMITS["characters"]:
        raise _too_big("characters", f"{what} is {len(text):,} characters long")
    if "\x00" in text:
        raise ExpressionError(f"{what} contains a NUL character")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except (SyntaxError, ValueError) as exc:  # ValueError: an integer literal beyond Python's own digit limit
        reason = exc.msg if isinstance(exc, SyntaxError) else str(exc)
        if "nested" in reason:  # Python's own parser stops at 200 nested parentheses
            raise _too_big("depth", f"{what} is nested too deeply") from None
        raise ExpressionError(f"{what} is not a SymPy expression: {reason}") from None
    except (RecursionError, MemoryError):  # Python's parser builds long chains recursively too
        raise _too_big("nodes", f"{what} is too long to parse") from None
    _check_tree(tree)
    return tree.body


def _digits(value: sp.Expr) -> int:
    """Decimal digits of an exact rational (0 for anything else)."""
    if isinstance(value, sp.Rational):
        return math.ceil(max(abs(value.p).bit_length(), abs(value.q).bit_length()) * math.log10(2))
    return 0


def _bounded(value: sp.Expr) -> sp.Expr:
    if _digits(value) > LIMITS["result digits"]:
        raise _too_big("result digits", f"a number with about {_digits(value):,} digits")
    return value


def _power(base: sp.Expr, exponent: sp.Expr) -> sp.Expr:
    """``base ** exponent``, refused when the result would be a number with too many digits or the exponent of a
    symbolic base is too large to expand."""
    if isinstance(exponent, sp.Number) and exponent.is_finite:
        size = abs(float(exponent)) if abs(exponent) < 10**300 else math.inf
        if isinstance(base, sp.Rational) and base not in (0, 1, -1):
            digits = size * max(math.log10(abs(base.p)) if base.p else 0, math.log10(base.q))
            if digits > LIMITS["result digits"]:
                raise _too_big("result digits", f"{base}**{exponent} would have about {digits:.3g} digits")
        elif not isinstance(base, sp.Number) and size > LIMITS["exponent"]:
            raise _too_big("exponent", f"the power {exponent} of a symbolic base")
    return _bounded(sp.Pow(base, exponent))


class _Builder:
    """Walks an expression tree against the grammar of :func:`parse_expression`."""

    def __init__(
        self, names: Mapping[str, Any], functions: Mapping[str, Callable], unknown: Callable | None, what: str
    ):
        self.names, self.functions, self.unknown, self.what = names, functions, unknown, what

    def build(self, node: ast.AST, depth: int = 0) -> sp.Expr:
        if depth > LIMITS["depth"]:
            raise _too_big("depth", f"{self.what} is nested too deeply")
        if isinstance(node, ast.Constant):
            return self.constant(node)
        if isinstance(node, ast.Name):
            return self.name(node.id)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add | ast.Sub | ast.Mult | ast.Div):
            return self.chain(node, depth)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow):
            return _power(self.build(node.left, depth + 1), self.build(node.right, depth + 1))
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub | ast.UAdd):
            value = self.build(node.operand, depth + 1)
            return -value if isinstance(node.op, ast.USub) else value
        if isinstance(node, ast.Call):
            return self.call(node, depth)
        raise ExpressionError(f"{self.what}: {_describe(node)} is not allowed in an expression ({_GRAMMAR})")

    def chain(self, node: ast.BinOp, depth: int) -> sp.Expr:
        """A run of ``+ -`` (or of ``* /``) read iteratively: a sum of many terms is long, not deep."""
        additive = isinstance(node.op, ast.Add | ast.Sub)
        kinds = (ast.Add, ast.Sub) if additive else (ast.Mult, ast.Div)
        operands: list[tuple[bool, ast.AST]] = []  # (inverted, operand), right to left
        while isinstance(node, ast.BinOp) and isinstance(node.op, kinds):
            operands.append((isinstance(node.op, ast.Sub | ast.Div), node.right))
            node = node.left
        operands.append((False, node))
        terms = []
        for inverted, operand in reversed(operands):
            term = self.build(operand, depth + 1)
            if inverted:
                term = -term if additive else _power(term, sp.S.NegativeOne)
            terms.append(term)
        return _bounded(sp.Add(*terms) if additive else sp.Mul(*terms))

    def constant(self, node: ast.Constant) -> sp.Expr:
        value = node.value
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise ExpressionError(f"{self.what}: the literal {_show(value)} is not a number ({_GRAMMAR})")
        if isinstance(value, int):
            if len(str(abs(value))) > LIMITS["literal digits"]:
                raise _too_big("literal digits", f"{self.what}: an integer literal of {len(str(abs(value)))} digits")
            return sp.Integer(value)
        if not math.isfinite(value):
            raise ExpressionError(f"{self.what}: the number {value} is not finite")
        return sp.Float(repr(value))

    def name(self, name: str) -> sp.Expr:
        if name in self.names:
            value = self.names[name]
            if isinstance(value, sp.Basic):
                return value
        if name in CONSTANTS:
            return CONSTANTS[name]
        if name in self.functions:
            raise ExpressionError(f"{self.what}: {name} is a function; call it, as in {name}(x)")
        if self.unknown is None:
            known = sorted(n for n, v in self.names.items() if isinstance(v, sp.Basic))
            raise ExpressionError(f"{self.what}: unknown name {name!r}; the names here are {', '.join(known)}")
        return self.unknown(name)

    def call(self, node: ast.Call, depth: int) -> sp.Expr:
        if not isinstance(node.func, ast.Name) or node.func.id not in self.functions:
            called = node.func.id if isinstance(node.func, ast.Name) else _describe(node.func)
            raise ExpressionError(
                f"{self.what}: {called}(...) is not a function an expression may call; "
                f"the functions are {', '.join(sorted(self.functions))}"
            )
        if node.keywords or any(isinstance(a, ast.Starred) for a in node.args):
            raise ExpressionError(f"{self.what}: {node.func.id}(...) takes plain arguments only")
        args = [self.build(a, depth + 1) for a in node.args]
        try:
            return _bounded(self.functions[node.func.id](*args))
        except (TypeError, ValueError) as exc:
            raise ExpressionError(f"{self.what}: {node.func.id}(...) cannot take these arguments ({exc})") from None


_GRAMMAR = "numbers, names, + - * / ** ^, parentheses and calls of functions such as sin, cos, exp, sqrt"


def _show(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _describe(node: ast.AST) -> str:
    kinds = {
        ast.Attribute: "attribute access", ast.Subscript: "a subscript", ast.Lambda: "a lambda",
        ast.Compare: "a comparison", ast.BoolOp: "a boolean operation", ast.IfExp: "a conditional expression",
        ast.ListComp: "a comprehension", ast.GeneratorExp: "a comprehension", ast.List: "a list",
        ast.Tuple: "a tuple", ast.Dict: "a dictionary", ast.Set: "a set", ast.JoinedStr: "an f-string",
        ast.NamedExpr: "an assignment", ast.Starred: "a starred argument", ast.Await: "await",
    }  # fmt: skip
    for kind, text in kinds.items():
        if isinstance(node, kind):
            return text
    if isinstance(node, ast.BinOp):
        return f"the operator {type(node.op).__name__}"
    if isinstance(node, ast.UnaryOp):
        return f"the operator {type(node.op).__name__}"
    return type(node).__name__


def parse_expression(
    text: Any,
    *,
    names: Mapping[str, Any] | None = None,
    functions: Mapping[str, Callable] | None = None,
    unknown: Callable[[str], sp.Expr] | None = None,
    what: str = "the expression",
) -> sp.Expr:
    """Build the SymPy expression written in ``text`` without evaluating the text.

    Parameters
    ----------
    text : str
        The expression, in Python/SymPy syntax (``^`` is a power).
    names : mapping of str to SymPy object, optional
        Names with a fixed meaning (coordinates, parameters).
    functions : mapping of str to callable, optional
        Functions the text may call, in addition to :data:`FUNCTIONS` (sin, cos, exp, ...).
    unknown : callable, optional
        ``unknown(name)`` gives the object for a name not in ``names`` (for example a positive Symbol); without it an
        unknown name is refused.
    what : str
        How errors refer to the text (``"system.T"``).

    Returns
    -------
    sympy.Expr

    Raises
    ------
    ExpressionError
        Text outside the grammar or beyond :data:`LIMITS`.

    Examples
    --------
    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> parse_expression("k*x^2/2 + sin(x)", names={"x": x}, unknown=sp.Symbol)
    k*x**2/2 + sin(x)
    >>> parse_expression("x.__class__", names={"x": x})
    Traceback (most recent call last):
    ...
    symosc._parsing.ExpressionError: the expression: attribute access is not allowed in an expression (numbers, ...
    """
    if isinstance(text, str):
        text = text.replace("^", "**")  # no strings in the grammar: "^" can only be the books' power sign
    tree = _parse_text(text, what)
    table = dict(FUNCTIONS)
    table.update(functions or {})
    expr = _Builder(dict(names or {}), table, unknown, what).build(tree)
    if not isinstance(expr, sp.Expr):
        raise ExpressionError(f"{what} is not a scalar expression")
    return expr


# ---------------------------------------------------------------------------------------------------- srepr
#: the SymPy classes and functions a saved summary may name (``sympy.srepr`` output)
SREPR_CALLABLES: dict[str, Callable[..., Any]] = {
    "Add": sp.Add, "Mul": sp.Mul, "Pow": sp.Pow, "Integer": sp.Integer, "Rational": sp.Rational,
    "Symbol": sp.Symbol, "Dummy": sp.Dummy, "Float": sp.Float,
    "MutableDenseMatrix": sp.Matrix, "ImmutableDenseMatrix": sp.ImmutableMatrix, "Matrix": sp.Matrix,
    "Tuple": sp.Tuple, "Derivative": sp.Derivative, "Function": sp.Function,
    "Abs": sp.Abs, "sign": sp.sign, "Heaviside": sp.Heaviside, "Max": sp.Max, "Min": sp.Min,
    "exp": sp.exp, "log": sp.log, "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "sec": sp.sec,
    "csc": sp.csc, "asin": sp.asin, "acos": sp.acos, "atan": sp.atan, "atan2": sp.atan2, "sinh": sp.sinh,
    "cosh": sp.cosh, "tanh": sp.tanh, "asinh": sp.asinh, "acosh": sp.acosh, "atanh": sp.atanh,
    "besselj": sp.besselj, "bessely": sp.bessely, "gamma": sp.gamma, "erf": sp.erf,
    "re": sp.re, "im": sp.im, "conjugate": sp.conjugate,
}  # fmt: skip
SREPR_CONSTANTS: dict[str, Any] = {
    "pi": sp.pi, "E": sp.E, "I": sp.I, "oo": sp.oo, "zoo": sp.zoo, "nan": sp.nan, "true": sp.true,
    "false": sp.false, "EulerGamma": sp.EulerGamma, "Half": sp.S.Half,
}  # fmt: skip
_STRING_FIRST = {"Symbol", "Dummy", "Float", "Function"}  # callables whose first argument is a string


class _SreprBuilder:
    def build(self, node: ast.AST, depth: int = 0) -> Any:
        if depth > LIMITS["depth"]:
            raise _too_big("depth", "the saved expression is nested too deeply")
        if isinstance(node, ast.Constant) and isinstance(node.value, int) and not isinstance(node.value, bool):
            if len(str(abs(node.value))) > LIMITS["result digits"]:
                raise _too_big("result digits", "an integer in the saved expression")
            return node.value
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            return -self.build(node.operand, depth + 1)
        if isinstance(node, ast.Name) and node.id in SREPR_CONSTANTS:
            return SREPR_CONSTANTS[node.id]
        if isinstance(node, ast.List | ast.Tuple):
            return [self.build(e, depth + 1) for e in node.elts]
        if isinstance(node, ast.Call):
            return self.call(node, depth)
        raise ExpressionError(f"the saved expression contains {_describe(node)}, which a summary never holds")

    def call(self, node: ast.Call, depth: int) -> Any:
        if isinstance(node.func, ast.Call):  # Function('f')(t): an undefined function applied
            func = self.call(node.func, depth + 1)
            if not isinstance(func, sp.core.function.UndefinedFunction):
                raise ExpressionError("the saved expression applies something other than a named function")
            return func(*[self.build(a, depth + 1) for a in node.args])
        name = node.func.id if isinstance(node.func, ast.Name) else None
        if name not in SREPR_CALLABLES:
            raise ExpressionError(f"the saved expression calls {name or _describe(node.func)}, which is not allowed")
        args: list[Any] = []
        for i, a in enumerate(node.args):
            if i == 0 and name in _STRING_FIRST:
                if not (isinstance(a, ast.Constant) and isinstance(a.value, str) and len(a.value) <= 200):
                    raise ExpressionError(f"{name}(...) in the saved expression needs a name (a short string) first")
                args.append(a.value)
            else:
                args.append(self.build(a, depth + 1))
        kwargs: dict[str, Any] = {}
        for k in node.keywords:
            if not (k.arg and isinstance(k.value, ast.Constant) and isinstance(k.value.value, bool | int)):
                raise ExpressionError(f"{name}(...) in the saved expression has a keyword that is not a flag")
            kwargs[k.arg] = k.value.value
        if name == "Pow" and len(args) == 2:
            return _power(*(sp.Integer(a) if isinstance(a, int) else a for a in args))
        try:
            return _bounded(SREPR_CALLABLES[name](*args, **kwargs))
        except (TypeError, ValueError, AttributeError) as exc:
            raise ExpressionError(f"{name}(...) in the saved expression: {exc}") from None


def parse_srepr(text: Any) -> Any:
    """The SymPy object written by :func:`sympy.srepr` in ``text``, built without evaluating the text.

    Parameters
    ----------
    text : str
        ``srepr`` output (the format of :func:`symosc.io.summary`).

    Returns
    -------
    sympy.Basic or sympy.Matrix

    Raises
    ------
    ExpressionError
        Anything that is not a call of a listed SymPy class or function, or beyond :data:`LIMITS`.

    Examples
    --------
    >>> import sympy as sp
    >>> x = sp.Symbol("x", positive=True)
    >>> parse_srepr(sp.srepr(2 * sp.sin(x) / 3)) == 2 * sp.sin(x) / 3
    True
    """
    return _SreprBuilder().build(_parse_text(text, "the saved expression"))
