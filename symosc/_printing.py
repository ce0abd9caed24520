"""SymPy printer hooks shared by symosc's models and results.

Every public model or result class inherits :class:`SymPyPrintable`, so that ``sympy.latex(obj)``, ``sympy.sstr(obj)``
and ``sympy.pretty(obj)`` give the object's mathematics (its own ``_repr_latex_`` when it has one, otherwise a
``Name(field = value, ...)`` summary with every SymPy field typeset), and Jupyter shows the same LaTeX.
"""

from __future__ import annotations

import dataclasses
import functools
import numbers
from typing import Any

import numpy as np
import sympy as sp

__all__ = ["SymPyPrintable", "latex", "latex_value", "mathml", "strip_math"]

_MAX_FIELDS = 6
_MAX_ITEMS = 6
_MAX_MATRIX = 36


def strip_math(text: str) -> str:
    """``text`` without the ``$...$`` / ``$$...$$`` math delimiters of a ``_repr_latex_`` string."""
    s = text.strip()
    for d in ("$$", "$"):
        if s.startswith(d) and s.endswith(d) and len(s) >= 2 * len(d):
            return s[len(d) : -len(d)].strip()
    return s


#: symbol names printed as another symbol: the small parameter of the series is ``eps`` in code, epsilon in print
_ALIASES = {"eps": (r"\varepsilon", "&#x3B5;")}


def _special_symbols(expr: Any) -> list[sp.Symbol]:
    syms = getattr(expr, "free_symbols", set())
    return [s for s in syms if s.name in _ALIASES or s.name.endswith(("_dot", "_ddot"))]


def latex(expr: Any, **settings: Any) -> str:
    r"""``sympy.latex`` with symosc's conventions: ``eps`` as ``\varepsilon``, ``q_dot``/``q_ddot`` as dotted ``q``.

    >>> import sympy as sp
    >>> print(latex(1 - sp.Symbol("eps") ** 2 / 16 + sp.Symbol("phi1_dot")))
    - \frac{\varepsilon^{2}}{16} + \dot{\phi_{1}} + 1
    """
    names = {}
    for s in _special_symbols(expr):
        if s.name in _ALIASES:
            names[s] = _ALIASES[s.name][0]
        else:
            base, accent = (s.name[:-5], r"\ddot") if s.name.endswith("_ddot") else (s.name[:-4], r"\dot")
            names[s] = f"{accent}{{{sp.latex(sp.Symbol(base))}}}"
    names.update(settings.pop("symbol_names", {}))
    return sp.latex(expr, symbol_names=names, **settings)


def mathml(expr: Any) -> str:
    """Presentation MathML of ``expr`` (no ``<math>`` wrapper), with the conventions of :func:`latex`.

    Browsers render MathML natively, so a report that carries it shows mathematics without scripts or fonts to
    download.

    >>> import sympy as sp
    >>> mathml(sp.Symbol("eps"))
    '<mi>&#x3B5;</mi>'
    """
    special = _special_symbols(expr)
    swap, marks = {}, {}
    for k, s in enumerate(special):
        tag = "symoscmark" + "".join(chr(ord("a") + int(d)) for d in str(k))
        swap[s] = sp.Symbol(tag)
        if s.name in _ALIASES:
            marks[tag] = f"<mi>{_ALIASES[s.name][1]}</mi>"
        else:
            from sympy.printing.conventions import split_super_sub

            ddot = s.name.endswith("_ddot")
            base, accent = (s.name[:-5], "&#xA8;") if ddot else (s.name[:-4], "&#x2D9;")
            name, _, subs = split_super_sub(base)
            core = sp.mathml(sp.Symbol(name), printer="presentation")
            text = f"<mover accent='true'>{core}<mo>{accent}</mo></mover>"  # the dot over the letter, not the index
            if subs:
                text = f"<msub>{text}<mrow>{''.join(f'<mi>{x}</mi>' for x in subs)}</mrow></msub>"
            marks[tag] = text
    e = expr.xreplace(swap) if swap else expr
    out = sp.mathml(e, printer="presentation")
    for tag, text in marks.items():
        out = out.replace(f"<mi>{tag}</mi>", text)
    return out


def _text(s: str) -> str:
    esc = {"\\": r"\backslash ", "{": r"\{", "}": r"\}", "_": r"\_", "&": r"\&", "%": r"\%", "#": r"\#", "$": r"\$"}
    s = "".join(esc.get(c, c) for c in s.replace("\n", " "))
    s = s.replace("^", r"\^{}").replace("~", r"\~{}")
    return rf"\text{{{s}}}"


def _number(v: Any) -> str:
    if isinstance(v, bool | np.bool_):
        return _text(str(bool(v)))
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        f = float(v)
        return (
            sp.latex(sp.Float(f, 6))
            if np.isfinite(f)
            else (r"\infty" if f > 0 else r"-\infty" if f < 0 else r"\mathrm{NaN}")
        )
    if isinstance(v, numbers.Complex):
        c = complex(v)
        return sp.latex(sp.Float(c.real, 6) + sp.I * sp.Float(c.imag, 6))
    raise TypeError(v)


def latex_value(value: Any, printer: Any = None) -> str:
    """LaTeX of one field value: SymPy objects typeset, numbers to 6 digits, small arrays as matrices."""
    pr = (lambda e: printer._print(e)) if printer is not None else sp.latex
    if value is None:
        return _text("None")
    if isinstance(value, sp.Basic | sp.MatrixBase) or hasattr(value, "_latex"):
        return pr(value)
    if isinstance(value, numbers.Number | np.number | np.bool_):
        return _number(value)
    if isinstance(value, str):
        return _text(value)
    if isinstance(value, np.ndarray):
        if value.ndim <= 2 and 0 < value.size <= _MAX_MATRIX and value.dtype.kind in "biufc":
            arr = value.reshape(1, -1) if value.ndim <= 1 else value
            return sp.latex(sp.Matrix([[sp.sympify(_rounded(x)) for x in row] for row in arr]))
        return _text(f"array, shape {value.shape}")
    if isinstance(value, tuple | list):
        items = [latex_value(v, printer) for v in value[:_MAX_ITEMS]]
        if len(value) > _MAX_ITEMS:
            items.append(r"\dots")
        return r"\left(" + ", ".join(items) + r"\right)"
    if isinstance(value, dict):
        items = [f"{latex_value(k, printer)}: {latex_value(v, printer)}" for k, v in list(value.items())[:_MAX_ITEMS]]
        if len(value) > _MAX_ITEMS:
            items.append(r"\dots")
        return r"\left\{" + ", ".join(items) + r"\right\}"
    return _text(type(value).__name__)


def _rounded(x: Any) -> Any:
    if isinstance(x, complex | np.complexfloating):
        return sp.Float(float(x.real), 6) + sp.I * sp.Float(float(x.imag), 6)
    if isinstance(x, numbers.Integral):
        return int(x)
    return sp.Float(float(x), 6)


def _cached_names(cls: type) -> set[str]:
    """Names of the ``functools.cached_property`` attributes of ``cls`` and its bases."""
    return {n for c in cls.__mro__ for n, a in vars(c).items() if isinstance(a, functools.cached_property)}


class SymPyPrintable:
    """Mixin with SymPy's printer hooks (``_latex``, ``_sympystr``, ``_pretty``) and ``_repr_latex_``.

    Classes with their own ``_repr_latex_`` are typeset from it; the others as ``\\operatorname{Name}(...)`` with
    their (dataclass) fields.  ``sympy.sstr`` and ``sympy.pretty`` show the readable ``repr``.

    Examples
    --------
    >>> import sympy as sp
    >>> from symosc.nonlinear import limit_cycle
    >>> print(sp.latex(limit_cycle((1 - sp.Symbol("x") ** 2) * sp.Symbol("v"), 2).frequency))
    1 - \\frac{\\varepsilon^{2}}{16} + O\\left(\\varepsilon^{3}\\right)
    """

    __slots__ = ()

    def _summary_latex(self, printer: Any = None) -> str:
        name = rf"\operatorname{{{type(self).__name__}}}"
        if dataclasses.is_dataclass(self):
            fields = [f for f in dataclasses.fields(self) if f.repr][:_MAX_FIELDS]
            parts = [rf"{_text(f.name)} = {latex_value(getattr(self, f.name), printer)}" for f in fields]
            return name + r"\left(" + ", ".join(parts) + r"\right)"
        cached = _cached_names(type(self))  # derived values: not part of the defining data (and not pickled)
        public = [
            (k, v) for k, v in getattr(self, "__dict__", {}).items() if not k.startswith("_") and k not in cached
        ][:_MAX_FIELDS]
        if public:
            parts = [rf"{_text(k)} = {latex_value(v, printer)}" for k, v in public]
            return name + r"\left(" + ", ".join(parts) + r"\right)"
        return name + r"\left(" + _text(repr(self)) + r"\right)"

    def _latex(self, printer: Any = None) -> str:
        own = type(self)._repr_latex_
        if own is not SymPyPrintable._repr_latex_:
            text = own(self)
            if text:
                return strip_math(text)
        return self._summary_latex(printer)

    def _repr_latex_(self) -> str:
        return f"${self._summary_latex()}$"

    def _sympystr(self, printer: Any = None) -> str:
        return repr(self)

    def _pretty(self, printer: Any = None) -> Any:
        from sympy.printing.pretty.stringpict import prettyForm

        lines = repr(self).splitlines() or [""]
        width = max(len(line) for line in lines)
        return prettyForm("\n".join(line.ljust(width) for line in lines))

    def __getstate__(self) -> dict[str, Any]:
        """Pickle the defining data; cached derived values (``functools.cached_property``) are recomputed."""
        state = dict(getattr(self, "__dict__", {}))
        for cls in type(self).__mro__:
            for name, attr in vars(cls).items():
                if isinstance(attr, functools.cached_property):
                    state.pop(name, None)
        return state
