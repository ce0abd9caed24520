"""Scene results and their reports (Markdown, HTML, JSON)."""

from __future__ import annotations

import html
import json
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .._printing import SymPyPrintable
from ._log import LogEntry

__all__ = ["Figure", "QuestionResult", "SceneResult", "Table"]


@dataclass(frozen=True)
class Table(SymPyPrintable):
    """A small table: column headers, rows of formatted cells and an optional caption.

    Examples
    --------
    >>> print(Table(("mode", "f, Hz"), (("1", "2.3276"),)).markdown())
    | mode | f, Hz |
    |---|---|
    | 1 | 2.3276 |

    See Also
    --------
    QuestionResult : holds the tables of one answer.
    """

    headers: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    caption: str = ""

    def markdown(self) -> str:
        lines = [f"*{self.caption}*", ""] if self.caption else []
        lines.append("| " + " | ".join(self.headers) + " |")
        lines.append("|" + "|".join("---" for _ in self.headers) + "|")
        lines += ["| " + " | ".join(r) + " |" for r in self.rows]
        return "\n".join(lines)

    def text(self) -> str:
        widths = [
            max(len(h), *(len(r[i]) for r in self.rows)) if self.rows else len(h) for i, h in enumerate(self.headers)
        ]
        out = [self.caption] if self.caption else []

        def just(cells, first_row):
            return "  ".join(
                c.rjust(w) if _numeric(col) else c.ljust(w) for c, w, col in zip(cells, widths, first_row, strict=True)
            ).rstrip()

        first = self.rows[0] if self.rows else self.headers
        out.append(just(self.headers, first))
        out += [just(r, first) for r in self.rows]
        return "\n".join(out)

    def html(self) -> str:
        cap = f"<caption>{html.escape(self.caption)}</caption>" if self.caption else ""
        head = "".join(f"<th>{html.escape(h)}</th>" for h in self.headers)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in self.rows)
        return f"<table>{cap}<tr>{head}</tr>{body}</table>"


def _numeric(cell: str) -> bool:
    try:
        float(cell.split()[0].rstrip("%"))
    except (ValueError, IndexError):
        return False
    return True


@dataclass(frozen=True)
class Figure(SymPyPrintable):
    """A figure to draw on demand: ``drawer`` names a function of :mod:`symosc.scene._figures`, ``data`` its input.

    Figures are drawn only by :meth:`SceneResult.write` (matplotlib is imported there), so a result stays
    picklable and cheap.

    Examples
    --------
    >>> Figure("ince.png", "Ince–Strutt diagram", "ince_strutt", {"orders": 2, "q_max": 5.0}).drawer
    'ince_strutt'

    See Also
    --------
    SceneResult.write : draws and saves the figures.
    """

    filename: str
    caption: str
    drawer: str
    data: dict = field(default_factory=dict)


@dataclass(frozen=True)
class QuestionResult(SymPyPrintable):
    """The answer to one question: text lines, tables, figures and JSON-ready ``data``.

    Examples
    --------
    >>> QuestionResult("natural_frequencies", "Natural frequencies", data={"omega_rad_s": [1.0]})
    QuestionResult('natural_frequencies', 'Natural frequencies')

    See Also
    --------
    SceneResult : all answers of a scene.
    """

    kind: str
    title: str
    lines: tuple[str, ...] = ()
    tables: tuple[Table, ...] = ()
    figures: tuple[Figure, ...] = ()
    data: dict = field(default_factory=dict)
    math: tuple = field(default=(), repr=False)  # (line index, lhs, rhs): SymPy objects the HTML report typesets

    def __repr__(self) -> str:
        return f"QuestionResult({self.kind!r}, {self.title!r})"

    def _repr_latex_(self) -> str:
        """The LaTeX of the answer (equations of motion) in notebooks; a summary when it has none."""
        latex = self.data.get("latex")
        if isinstance(latex, str):
            return f"$${latex}$$"

        return f"${SymPyPrintable._summary_latex(self)}$"


@dataclass(frozen=True)
class SceneResult(SymPyPrintable):
    """Results of :meth:`Scene.run`: one :class:`QuestionResult` per question and the derivation log.

    ``report()`` is the plain-text report, ``markdown()``/``html()`` the written ones, ``to_json()`` the data;
    ``result["natural_frequencies"]`` is the first answer of that kind.

    Examples
    --------
    >>> from symosc.scene import loads
    >>> res = loads('[system]\\nmodel = "mathieu"\\n[[questions]]\\nkind = "mathieu_values"\\nn = 0\\nq = 0\\n').run()
    >>> res["mathieu_values"].data["values"][0]["value"]
    0.0
    >>> [e.step for e in res.log]
    ['Mathieu characteristic values']

    See Also
    --------
    symosc.scene.load : read and validate a scene file.
    """

    title: str
    source: str
    system: str
    parameters: dict
    results: tuple[QuestionResult, ...]
    log: tuple[LogEntry, ...]
    parameter_text: dict = field(default_factory=dict)  # name -> value as the scene file wrote it ("45 mm")

    def __getitem__(self, kind: str) -> QuestionResult:
        for r in self.results:
            if r.kind == kind:
                return r
        raise KeyError(f"no {kind!r} question in this scene; questions: {[r.kind for r in self.results]}")

    def __repr__(self) -> str:
        return f"SceneResult({self.title!r}, questions={[r.kind for r in self.results]})"

    def _repr_html_(self) -> str:
        from ._html import fragment

        return fragment(self)

    def _log_table(self) -> Table:
        rows = tuple((str(i + 1), e.step, f"{e.seconds * 1e3:.1f}", e.detail) for i, e in enumerate(self.log))
        return Table(("#", "step", "ms", "detail"), rows, "Derivation log (what was derived for these questions)")

    def _params_line(self) -> str:
        shown = self.parameter_text
        return ", ".join(f"{k} = {shown.get(k) or format(v, '.6g')}" for k, v in self.parameters.items()) or "none"

    def report(self) -> str:
        """Plain-text report for the terminal."""
        out = [self.title, "=" * len(self.title)]
        if self.source:
            out.append(f"source: {self.source}")
        if self.system:
            out.append(f"system: {self.system}")
        out.append(f"parameters: {self._params_line()}")
        for r in self.results:
            out += ["", f"-- {r.title}"]
            out += list(r.lines)
            for t in r.tables:
                out += ["", t.text()]
        out += ["", self._log_table().text()]
        return "\n".join(out)

    def markdown(self, figures: dict[str, str] | None = None) -> str:
        out = [f"# {self.title}", ""]
        if self.source:
            out.append(f"Source: {self.source}  ")
        if self.system:
            out.append(f"System: {self.system}  ")
        out += [f"Parameters: {self._params_line()}", ""]
        for r in self.results:
            out += [f"## {r.title}", ""]
            out += [line + "  " for line in r.lines]
            for t in r.tables:
                out += ["", t.markdown(), ""]
            for f in r.figures:
                if figures and f.filename in figures:
                    out += [f"![{f.caption}]({figures[f.filename]})", ""]
        out += ["## Derivation log", "", self._log_table().markdown(), ""]
        return "\n".join(out)

    def html(self, figures: dict[str, str] | None = None) -> str:
        """A self-contained HTML page: stylesheet, equations as MathML, figures embedded (when ``figures`` maps
        their names to files) or linked."""
        from ._html import document

        return document(self, figures)

    def to_json(self) -> dict[str, Any]:
        """JSON-ready dict: parameters, each question's data and the derivation log."""
        return {
            "title": self.title,
            "source": self.source,
            "system": self.system,
            "parameters": dict(self.parameters),
            "questions": [{"kind": r.kind, "title": r.title, **r.data} for r in self.results],
            "derivation_log": [{"step": e.step, "seconds": e.seconds, "detail": e.detail} for e in self.log],
        }

    def write(self, outdir: str | os.PathLike, fmt: str = "md") -> list[Path]:
        """Write ``report.<fmt>``, ``results.json`` and the figures (PNG) into ``outdir``; returns the paths.

        Everything is written to a temporary folder first and moved in at the end: a failure leaves nothing
        half-written.  Figures need matplotlib; without it the scene report says so and the rest is written.
        """
        outdir = Path(outdir)
        outdir.mkdir(parents=True, exist_ok=True)
        figs: dict[str, str] = {}
        notes: list[str] = []
        with tempfile.TemporaryDirectory(dir=outdir, prefix=".symosc-") as tmp:
            tmpdir = Path(tmp)
            todo = [f for r in self.results for f in r.figures]
            if todo:
                try:
                    import matplotlib

                    matplotlib.use("Agg", force=False)
                    import matplotlib.pyplot as plt
                except ImportError:
                    plt = None
                    notes.append("figures skipped: matplotlib is not installed (pip install 'symosc[plot]')")
                if plt is not None:
                    from . import _figures

                    for f in todo:
                        fig, ax = plt.subplots(figsize=(6.5, 4.5))
                        drawn = getattr(_figures, f.drawer)(ax, **f.data)
                        if hasattr(drawn, "save"):  # an animation writes itself (GIF)
                            drawn.save(tmpdir / f.filename)
                        else:
                            fig.tight_layout()
                            fig.savefig(tmpdir / f.filename, dpi=110)
                        plt.close(fig)
                        figs[f.filename] = f.filename
            if fmt == "json":
                main = None
            else:
                main = tmpdir / f"report.{fmt}"
                text = self.markdown(figs) if fmt == "md" else self.html({k: str(tmpdir / v) for k, v in figs.items()})
                main.write_text(text + ("\n" + "\n".join(notes) if notes else ""), encoding="utf-8")
            (tmpdir / "results.json").write_text(
                json.dumps(self.to_json(), indent=2, default=_json_default), encoding="utf-8"
            )
            written = []
            for p in sorted(tmpdir.iterdir()):
                target = outdir / p.name
                os.replace(p, target)
                written.append(target)
        for n in notes:
            print(n)
        return written


def _json_default(obj: Any) -> Any:
    import numpy as np

    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, complex):
        return [obj.real, obj.imag]
    return str(obj)
