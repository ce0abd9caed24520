"""The ``mathieu_functions`` scene question: periodic Mathieu functions ce_n, se_n (values and a plot over a period).

Options (under ``[[questions]]`` with ``kind = "mathieu_functions"``, model ``mathieu``):

``function``
    ``"ce"`` (default) or ``"se"``.
``n``
    Orders, a list of integers (>= 1 for ``se``).
``q``
    Parameters q, a list of numbers; every (n, q) pair is computed.
``x``
    Optional angles for a table of values (radians, or strings such as ``"30 deg"``).
``derivative``
    Tabulate d/dx instead of the function (default false; the figure always shows the functions).
``figure``
    Draw the functions over one period 0 <= x <= 2 pi (default true).

The answer lists, for each (n, q), the characteristic value (a_n(q) for ce_n, b_n(q) for se_n), the period (pi for
even n, 2 pi for odd n) and the first Fourier coefficients; normalisation DLMF 28.2.30 (McLachlan 1947).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._result import Figure, QuestionResult, Table
from .mechanical import Question, QuestionSpec, _fmt

__all__: list[str] = []

#: points of the plotted curves over 0 <= x <= 2 pi
_POINTS = 241


def _orders(ctx, v, k):
    if isinstance(v, int) and not isinstance(v, bool):
        v = [v]
    if not isinstance(v, list) or not v:
        raise ctx.error(k, f"expected a list of integers >= 0, got {v!r}", "write n = [0, 1, 2]")
    return [ctx.integer(x, k, minimum=0) for x in v]


def _numbers(ctx, v, k):
    return [float(x) for x in ctx.quantities(v, k, "dimensionless")]


def _flag(ctx, v, k):
    return ctx.boolean(v, k)


def _function(ctx, v, k):
    return ctx.choice(v, k, ["ce", "se"])


def mathieu_functions(q: Question) -> QuestionResult:
    from ...periodic import mathieu_fourier_coefficients, mathieu_function

    kind, ns, qs = q.opts["function"], q.opts["n"], q.opts["q"]
    if kind == "se" and 0 in ns:
        raise q.fail("se_0 does not exist (se_n needs n >= 1)", 'remove 0 from n, or use function = "ce"', "n")
    letter = "a" if kind == "ce" else "b"
    pairs = [(n, qq) for n in ns for qq in qs]
    rows, data = [], []
    with q.log.step(
        f"Fourier coefficients of {kind}_n (eigenvectors of the Hill matrices)", f"{len(pairs)} (n, q) pair(s)"
    ):
        for n, qq in pairs:
            co = mathieu_fourier_coefficients(kind, n, qq)
            first = ", ".join(f"{v:+.6g}" for v in co.values[:3])
            rows.append((str(n), f"{qq:g}", f"{co.characteristic_value:.15g}", "pi" if n % 2 == 0 else "2 pi", first))
            data.append({"n": n, "q": qq, "characteristic_value": co.characteristic_value,
                         "coefficients": co.values[:8].tolist(), "indices": co.index[:8].tolist()})  # fmt: skip
    tables = [
        Table(
            ("n", "q", f"{letter}_n(q)", "period", "first coefficients"),
            tuple(rows),
            f"{kind}_n(x, q) = sum of {'A_k cos' if kind == 'ce' else 'B_k sin'} kx (DLMF 28.4), normalised by "
            "DLMF 28.2.30",
        )
    ]
    lines = [f"{kind}_n(x, q) solves y'' + (a - 2q cos 2x) y = 0 at a = {letter}_n(q), x in radians"]
    if q.opts.get("x"):
        xs = np.array(q.opts["x"])
        deriv = q.opts["derivative"]
        name = f"{kind}_n{chr(39) if deriv else ''}(x, q)"
        vrows = []
        with q.log.step(f"values of {name}", f"{len(pairs)} x {xs.size}"):
            for (n, qq), entry in zip(pairs, data, strict=True):
                r = mathieu_function(kind, n, qq, xs, derivative=deriv)
                vals, errs = np.atleast_1d(r.values), np.atleast_1d(r.error_estimate)
                entry["x"], entry["values"], entry["error_estimates"] = xs.tolist(), vals.tolist(), errs.tolist()
                vrows += [(str(n), f"{qq:g}", _fmt(x, ".6g"), f"{v:.15g}", f"{e:.1e}")
                          for x, v, e in zip(xs, vals, errs, strict=True)]  # fmt: skip
        tables.append(Table(("n", "q", "x, rad", name, "error bound"), tuple(vrows), f"values of {name}"))
    figures: tuple = ()
    if q.opts["figure"]:
        x = np.linspace(0.0, 2 * np.pi, _POINTS)
        curves = []
        with q.log.step(f"{kind}_n over one period for the figure", f"{_POINTS} points per curve"):
            for n, qq in pairs:
                y = mathieu_function(kind, n, qq, x).values
                curves.append({"label": f"{kind}_{n}(x, {qq:g})", "y": y.tolist()})
        figures = (
            Figure(
                f"{q.stem}-{kind}.png",
                f"Mathieu functions {kind}_n(x, q) over 0 <= x <= 2 pi (normalisation DLMF 28.2.30)",
                "mathieu_functions",
                {"x": x.tolist(), "curves": curves, "ylabel": f"{kind}_n(x, q)"},
            ),
        )
        lines.append(f"figure: {figures[0].filename}")
    return QuestionResult(
        "mathieu_functions", f"Mathieu functions {kind}_n(x, q)", tuple(lines), tuple(tables), figures,
        {"function": kind, "pairs": data},
    )  # fmt: skip


def draw(ax: Any, *, x: list, curves: list, ylabel: str) -> Any:
    """The figure drawer: each curve against x in radians, with ticks at multiples of pi / 2."""
    for c in curves:
        ax.plot(x, c["y"], label=c["label"])
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set_xticks(np.arange(5) * np.pi / 2, ["0", "π/2", "π", "3π/2", "2π"])
    ax.set_xlabel("x (rad)")
    ax.set_ylabel(ylabel)
    ax.legend(fontsize="small")
    return ax


SPEC = QuestionSpec(
    "mathieu_functions",
    "periodic Mathieu functions ce_n, se_n: values and a plot over a period",
    ("mathieu",),
    {
        "function": (_function, "ce"),
        "n": (_orders, None),
        "q": (_numbers, None),
        "x": (_numbers, None),
        "derivative": (_flag, False),
        "figure": (_flag, True),
    },
    mathieu_functions,
)
