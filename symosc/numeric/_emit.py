"""Print a :class:`~symosc.numeric._dag.Graph` as straight-line C or Python code.

A node used more than once becomes a temporary (``_tK``), a node used once is printed inline where it is used.
Numbers are printed as correctly rounded double literals (``repr(float(value))``: an integer of any size, a
rational with 100-digit parts, ``pi``), so every backend starts from the same doubles; a value beyond the double
range prints as an infinity.  Functions outside the small built-in tables are printed by SymPy's printers with
placeholder arguments.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import sympy as sp

from ..errors import ParameterError
from ._dag import ADD, ARG, CONST, FUNC, MUL, OPAQUE, POW, Graph, reachable
from ._special import REAL_ONLY

ATOM, MULP, ADDP = 3, 2, 1  # precedence of a printed node


@dataclass
class Statement:
    """``target = text``; ``temp`` is the temporary's name (None for an output), ``uses`` the names it reads
    (arguments, preset values and temporaries); ``node`` orders the statements (an output follows its node)."""

    target: str
    text: str
    temp: str | None
    uses: list[str] = field(default_factory=list)
    node: float = 0.0


def double_literal(value: float) -> str | None:
    """A literal that parses to exactly ``value`` in C and Python (None for inf/nan)."""
    if math.isinf(value) or math.isnan(value):
        return None
    text = repr(float(value))
    return text if any(ch in text for ch in ".en") else text + ".0"


def number_value(value: sp.Expr) -> complex | float:
    """The correctly rounded double (or complex) of a SymPy number; +-inf when it overflows."""
    if value is sp.I:
        return 1j
    if value is sp.nan or value is sp.zoo:
        return math.nan
    if value.is_Rational:
        p, q = int(value.p), int(value.q)
        try:
            return p / q  # Python rounds int / int correctly for integers of any size
        except OverflowError:
            return math.inf if p > 0 else -math.inf
    v = value.evalf(30)
    re, im = v.as_real_imag()
    if im != 0:
        return complex(float(re), float(im))
    return float(re)


class Printer:
    """Shared logic; subclasses give the language's literals and function names."""

    language = ""
    pow_operator = False  # Python: ``b**e``; C: ``pow(b, e)``

    def __init__(self, graph: Graph, arg_names: Sequence[str]) -> None:
        self.graph = graph
        self.arg_names = list(arg_names)

    # ----- to be specialised
    def literal(self, value: sp.Expr) -> str:
        raise NotImplementedError

    def call(self, cls: type, args: list[str]) -> str | None:
        """The call of a function from the language's table, or None."""
        raise NotImplementedError

    def fallback(self, expr: sp.Expr) -> str:
        raise NotImplementedError

    # ----- program
    def statements(
        self,
        outputs: Sequence[int],
        targets: Sequence[str],
        *,
        preset: dict[int, str] | None = None,
        temp_prefix: str = "_t",
    ) -> list[Statement]:
        """Statements computing ``targets[i] = outputs[i]``, in evaluation order; each output comes right after
        the last temporary it needs.  ``preset`` maps nodes to names of values computed elsewhere."""
        g = self.graph
        preset = preset or {}
        order, uses = reachable(g, outputs, stop=preset)
        text: dict[int, tuple[str, int, list[str]]] = {}
        out: list[Statement] = []
        kind = g.kind
        for k in order:
            kk = kind[k]
            if k in preset:
                text[k] = (preset[k], ATOM, [preset[k]])
                continue
            if kk == ARG:
                name = self.arg_names[g.data[k]]
                text[k] = (name, ATOM, [name])
                continue
            if kk == CONST:
                lit = self.literal(g.data[k])
                text[k] = (lit, ATOM if not lit.startswith("-") else MULP, [])
                continue
            body, prec, used = self._node_text(k, text)
            if uses.get(k, 0) > 1 or len(body) > 4000:
                name = f"{temp_prefix}{k}"
                out.append(Statement(name, body, name, used, k))
                text[k] = (name, ATOM, [name])
            else:
                text[k] = (body, prec, used)
        for k, target in zip(outputs, targets, strict=True):
            body, _, used = text[k]
            out.append(Statement(target, body, None, used, k + 0.5))
        out.sort(key=lambda st: st.node)
        return out

    def _node_text(self, k: int, text: dict) -> tuple[str, int, list[str]]:
        g = self.graph
        kind, data = g.kind[k], g.data[k]
        used: list[str] = []

        def child(c: int, min_prec: int) -> str:
            t, p, u = text[c]
            used.extend(u)
            return t if p >= min_prec and not (min_prec >= MULP and t.startswith("-")) else f"({t})"

        if kind == ADD:
            parts = []
            for c in data:
                t = child(c, ADDP)
                if parts and t.startswith("-"):
                    parts.append(f" - {t[1:]}")
                elif parts:
                    parts.append(f" + {t}")
                else:
                    parts.append(t)
            return "".join(parts), ADDP, used
        if kind == MUL:
            return self._mul_text(data, text, child)[0], MULP, used
        if kind == POW:
            body, prec, _ = self._pow_text(data[0], data[1], text, child)
            return body, prec, used
        if kind == FUNC:
            cls, children = data
            args = [child(c, ADDP) for c in children]
            called = self.call(cls, args)
            if called is None:
                constants = [g.data[c] if g.kind[c] == CONST else None for c in children]
                called = self._placeholder_call(cls, args, constants)
            return called, ATOM, used
        if kind == OPAQUE:
            deps = g.deps[k]
            used.extend(name for i, name in enumerate(self.arg_names) if deps >> i & 1)
            return f"({self.fallback(data)})", ATOM, used
        raise AssertionError(kind)

    def _placeholder_call(self, cls: type, args: list[str], constants: list) -> str:
        """``cls(args)`` printed by the SymPy printer: constant arguments as themselves (``polygamma(0, x)`` is
        printed as digamma), the others as placeholders without assumptions (so that ``re(z)`` stays ``re(z)``)."""
        holders = [c if c is not None else sp.Symbol(f"symoscPLACEHOLDER{i}X") for i, c in enumerate(constants)]
        try:
            call = cls(*holders, evaluate=False)
        except TypeError:  # a function without the evaluate keyword
            call = cls(*holders)
        code = self.fallback(call)
        for i in reversed(range(len(args))):
            code = code.replace(f"symoscPLACEHOLDER{i}X", f"({args[i]})")
        return f"({code})"

    def _mul_text(self, data, text, child) -> tuple[str, int, list[str]]:
        g = self.graph
        coeff = None
        num, den = [], []
        for c in data:
            v = g.number(c)
            if v is not None:
                coeff = v
                continue
            if g.kind[c] == POW:
                e = g.number(g.data[c][1])
                if e is not None and e.is_negative:
                    den.append((g.data[c][0], -e))
                    continue
            num.append(child(c, MULP))
        dens = [self._power(base, e, text, child, ATOM if len(den) == 1 else MULP) for base, e in den]
        sign = ""
        if coeff is not None:
            if coeff == -1:
                sign = "-"
            elif coeff.is_negative:
                sign = "-"
                num.insert(0, self.literal(-coeff))
            elif coeff != 1:
                num.insert(0, self.literal(coeff))
        top = "*".join(num) if num else self.literal(sp.S.One)
        if dens:
            bottom = dens[0] if len(dens) == 1 else "(" + "*".join(dens) + ")"
            top = f"{top}/{bottom}"
        return sign + top, MULP, []

    def _pow_text(self, base: int, exponent: int, text, child) -> tuple[str, int, list[str]]:
        g = self.graph
        e = g.number(exponent)
        if e is not None and e.is_negative:
            return f"{self.literal(sp.S.One)}/{self._power(base, -e, text, child, ATOM)}", MULP, []
        if e is not None:
            return self._power(base, e, text, child, MULP), MULP, []
        b, x = child(base, ATOM), child(exponent, ADDP)
        return self.general_power(b, x), ATOM, []

    def _power(self, base: int, e: sp.Expr, text, child, min_prec: int) -> str:
        """``base**e`` for a positive number ``e`` (with parentheses where ``min_prec`` needs them)."""
        if e == 1:
            return child(base, min_prec)
        if e == sp.S.Half:
            return self.sqrt(child(base, ADDP))
        if e == 2 and text[base][1] == ATOM:
            b = child(base, ATOM)
            return f"({b}*{b})" if min_prec >= ATOM else f"{b}*{b}"
        return self.number_power(child(base, ATOM), e)

    # ----- language pieces
    def sqrt(self, arg: str) -> str:
        raise NotImplementedError

    def number_power(self, base: str, e: sp.Expr) -> str:
        raise NotImplementedError

    def general_power(self, base: str, e: str) -> str:
        raise NotImplementedError


_C_FUNCTIONS = {
    "sin": "sin", "cos": "cos", "tan": "tan", "asin": "asin", "acos": "acos", "atan": "atan", "atan2": "atan2",
    "sinh": "sinh", "cosh": "cosh", "tanh": "tanh", "asinh": "asinh", "acosh": "acosh", "atanh": "atanh",
    "exp": "exp", "Abs": "fabs", "floor": "floor", "ceiling": "ceil", "erf": "erf", "erfc": "erfc",
    "gamma": "tgamma", "Sqrt": "sqrt",
}  # fmt: skip


_C_REAL_PARTS = {"re": "({})", "im": "(0.0*({}))", "conjugate": "({})", "arg": "symosc_arg({})"}


class CPrinter(Printer):
    """C99 on doubles."""

    language = "c"

    def __init__(self, graph: Graph, arg_names: Sequence[str], fallback: Callable[[sp.Expr], str]) -> None:
        super().__init__(graph, arg_names)
        self._fallback = fallback

    def literal(self, value: sp.Expr) -> str:
        v = number_value(value)
        if isinstance(v, complex):
            raise ParameterError(
                "the C backend evaluates real-valued expressions only; the expression contains the imaginary unit I "
                "(use backend='numpy')"
            )
        lit = double_literal(v)
        if lit is None:
            return "NAN" if math.isnan(v) else ("HUGE_VAL" if v > 0 else "-HUGE_VAL")
        return lit

    def call(self, cls: type, args: list[str]) -> str | None:
        if cls.__name__ in ("loggamma", "Mod"):  # C's lgamma is log|Gamma|, fmod truncates: see _c.C_HELPERS
            return f"symosc_{cls.__name__.lower()}({', '.join(args)})"
        if len(args) == 1 and cls.__name__ in _C_REAL_PARTS:  # the C backend's arguments are real
            return _C_REAL_PARTS[cls.__name__].format(args[0])
        name = _C_FUNCTIONS.get(cls.__name__)
        if name is None or (cls.__name__ == "atan2") != (len(args) == 2):
            if cls is sp.log and len(args) == 1:
                return f"log({args[0]})"
            return None
        return f"{name}({', '.join(args)})"

    def fallback(self, expr: sp.Expr) -> str:
        return self._fallback(expr)

    def sqrt(self, arg: str) -> str:
        return f"sqrt({arg})"

    def number_power(self, base: str, e: sp.Expr) -> str:
        if e.is_Integer:
            return f"pow({base}, {int(e)})" if abs(int(e)) < 2**31 else f"pow({base}, {self.literal(e)})"
        return f"pow({base}, {self.literal(e)})"

    def general_power(self, base: str, e: str) -> str:
        return f"pow({base}, {e})"


_PY_FUNCTIONS = {
    "sin": "sin", "cos": "cos", "tan": "tan", "asin": "arcsin", "acos": "arccos", "atan": "arctan",
    "atan2": "arctan2", "sinh": "sinh", "cosh": "cosh", "tanh": "tanh", "asinh": "arcsinh", "acosh": "arccosh",
    "atanh": "arctanh", "exp": "exp", "log": "log", "Abs": "abs", "floor": "floor", "ceiling": "ceil",
}  # fmt: skip
_MATH_FUNCTIONS = {
    "sin": "sin", "cos": "cos", "tan": "tan", "asin": "asin", "acos": "acos", "atan": "atan", "atan2": "atan2",
    "sinh": "sinh", "cosh": "cosh", "tanh": "tanh", "asinh": "asinh", "acosh": "acosh", "atanh": "atanh",
    "exp": "exp", "log": "log", "Abs": "fabs", "floor": "floor", "ceiling": "ceil", "erf": "erf", "erfc": "erfc",
    "gamma": "gamma",
}  # fmt: skip


class PythonPrinter(Printer):
    """Python on floats (``module="math"``: real scalars) or NumPy arrays (``module="numpy"``)."""

    language = "python"

    def __init__(self, graph: Graph, arg_names: Sequence[str], module: str, fallback: Callable[[sp.Expr], str]) -> None:
        super().__init__(graph, arg_names)
        self.module = module
        self._fallback = fallback
        self.helpers: set[str] = set()

    def literal(self, value: sp.Expr) -> str:
        v = number_value(value)
        if isinstance(v, complex):
            if self.module != "numpy":
                raise ParameterError("the math-module path evaluates real values; the expression is complex")
            text = repr(v)
            return text if math.isfinite(v.real) and math.isfinite(v.imag) else f"complex({v.real!r}, {v.imag!r})"
        lit = double_literal(v)
        if lit is None:
            return f"{self.module}.nan" if math.isnan(v) else (f"{self.module}.inf" if v > 0 else f"-{self.module}.inf")
        return lit

    def call(self, cls: type, args: list[str]) -> str | None:
        table = _MATH_FUNCTIONS if self.module == "math" else _PY_FUNCTIONS
        name = table.get(cls.__name__)
        if name is None or (cls.__name__ == "atan2") != (len(args) == 2) or (cls is sp.log and len(args) != 1):
            return None
        if self.module == "numpy" and cls.__name__ in REAL_ONLY:  # NumPy refuses complex: say which function
            self.helpers.add("_symosc_real")
            args = [f'_symosc_real("{cls.__name__}", {a})' for a in args]
        return f"{self.module}.{name}({', '.join(args)})"

    def fallback(self, expr: sp.Expr) -> str:
        return self._fallback(expr)

    def sqrt(self, arg: str) -> str:
        return f"{self.module}.sqrt({arg})"

    def number_power(self, base: str, e: sp.Expr) -> str:
        if e.is_Integer:
            return f"{base}**{int(e)}"
        if self.module == "math":  # a negative base raises ValueError (then NumPy gives nan) instead of a complex
            return f"math.pow({base}, {self.literal(e)})"
        return f"numpy.power({base}, {self.literal(e)})"

    def general_power(self, base: str, e: str) -> str:
        return f"{self.module}.pow({base}, {e})" if self.module == "math" else f"numpy.power({base}, {e})"


_SAFE = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_ .,:;()[]{}+-=<>!?&@^~|'")


def comment_text(text: str) -> str:
    """``text`` safe inside a comment or docstring of every target language.

    Every character outside a small printable ASCII set (newlines, quotes, ``*``, ``/``, ``#``, ``$``, backslashes,
    non-ASCII) is shown as a ``\\xNN`` / ``\\uNNNN`` escape, so no symbol name can close a C comment, a Python or Julia
    docstring, or start an interpolation.

    >>> print(comment_text('x */ int main() {"'))
    x \\x2a\\x2f int main() {\\x22
    """
    out = []
    for ch in text:
        if ch in _SAFE:
            out.append(ch)
        elif ord(ch) < 0x100:
            out.append(f"\\x{ord(ch):02x}")
        elif ord(ch) < 0x10000:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(f"\\U{ord(ch):08x}")
    return "".join(out)
