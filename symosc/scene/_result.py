"""Scene results and their reports (Markdown, HTML, JSON)."""

from __future__ import annotations

import html
import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .._printing import SymPyPrintable
from ._log import LogEntry

__all__ = ["Figure", "QuestionResult", "SceneResult", "Table"]


@dataclass(frozen=True)
class Table(SymPyPrintable):
    """A small table: column headers, rows of formatted cells and an optional caption.

    Attributes
    ----------
    headers : tuple of str
        Column headers.
    rows : tuple of tuple of str
        The rows, each with one formatted cell per header.
    caption : str
        Caption shown above the table (empty for none).

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

    Attributes
    ----------
    filename : str
        Name of the PNG file written into the output folder, such as ``"ince.png"``.
    caption : str
        Caption of the figure in the reports.
    drawer : str
        Name of the drawing function, such as ``"ince_strutt"``; it is called with a Matplotlib Axes and ``data``.
    data : dict
        Keyword arguments of the drawing function (plain numbers, lists and strings, so the figure pickles).

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

    Attributes
    ----------
    kind : str
        The question's kind, such as ``"natural_frequencies"`` (a key of ``symosc.scene.QUESTIONS``).
    title : str
        Heading of the answer in the reports.
    lines : tuple of str
        Text lines of the answer.
    tables : tuple of Table
        Tables of the answer.
    figures : tuple of Figure
        Figures of the answer (drawn by :meth:`SceneResult.write`).
    data : dict
        JSON-ready numbers of the answer (written to ``results.json``).
    math : tuple of (int, Expr, Expr)
        Equations the HTML report typesets as MathML: ``(line index, left-hand side, right-hand side)``.

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

    Attributes
    ----------
    title : str
        Title of the scene.
    source : str
        Free-text source of the scene (empty when none).
    system : str
        Description of the system (empty for a scene without ``[system]``).
    parameters : dict
        Parameter values in SI units, keyed by name.
    results : tuple of QuestionResult
        One answer per question, in the order of the scene file.
    log : tuple of LogEntry
        The derivation log: every step derived or evaluated for the scene.
    parameter_text : dict
        Each parameter's value as the scene file wrote it (``"45 mm"``), for the reports.

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
            out += _text_lines(r)
            for t in r.tables:
                out += ["", t.text()]
        out += ["", self._log_table().text()]
        return "\n".join(out)

    def markdown(self, figures: dict[str, str] | None = None) -> str:
        """This scene's results as a Markdown document.

        Parameters
        ----------
        figures : dict of str to str, optional
            ``{Figure.filename: path or URL}`` of the figures already written; only those are embedded (none
            when omitted).

        Returns
        -------
        str
        """
        out = [f"# {self.title}", ""]
        if self.source:
            out.append(f"Source: {self.source}  ")
        if self.system:
            out.append(f"System: {self.system}  ")
        out += [f"Parameters: {self._params_line()}", ""]
        for r in self.results:
            out += [f"## {r.title}", ""]
            out += [line + "  " for line in _text_lines(r)]
            for t in r.tables:
                out += ["", t.markdown(), ""]
            for f in r.figures:
                if figures and f.filename in figures:
                    out += [f"![{f.caption}]({figures[f.filename]})", ""]
        out += ["## Derivation log", "", self._log_table().markdown(), ""]
        return "\n".join(out)

    def html(self, figures: dict[str, str] | None = None) -> str:
        """A self-contained HTML page: stylesheet, equations as MathML, figures embedded (when ``figures`` maps
        their names to files) or linked.

        Parameters
        ----------
        figures : dict of str to str, optional
            ``{Figure.filename: path or URL}`` of the figures already written; only those are shown (none when
            omitted).

        Returns
        -------
        str
        """
        from ._html import document

        return document(self, figures)

    def to_json(self) -> dict[str, Any]:
        """JSON-ready dict: parameters, each question's data and the derivation log (steps, without timings: two
        runs of the same scene give the same data; :meth:`timings` has the seconds)."""
        return {
            "title": self.title,
            "source": self.source,
            "system": self.system,
            "parameters": dict(self.parameters),
            "questions": [{"kind": r.kind, "title": r.title, **_split_timings(r.data)[0]} for r in self.results],
            "derivation_log": [{"step": e.step, "detail": e.detail} for e in self.log],
        }

    def timings(self) -> dict[str, Any]:
        """The derivation log with the seconds each step took, and the timings inside the answers (keys ending in
        ``_time`` or ``seconds``), written to ``timings.json``."""
        return {
            "derivation_log": [{"step": e.step, "seconds": e.seconds} for e in self.log],
            "questions": [{"kind": r.kind, **_split_timings(r.data)[1]} for r in self.results],
        }

    def write(self, outdir: str | os.PathLike, fmt: str = "md") -> list[Path]:
        """Write ``report.<fmt>``, ``results.json``, ``timings.json`` and the figures (PNG) as the folder ``outdir``.

        The folder is written whole or not at all: everything goes into a fresh hidden sibling folder that then
        replaces ``outdir`` (no figures of an earlier run stay behind; a failure or a kill leaves ``outdir`` as it
        was).  ``outdir`` must be new, empty, or an earlier run's output.  ``results.json`` holds no timings, so two
        runs of a scene give byte-identical files.  Figures need matplotlib; without it ``report.<fmt>`` says so and the
        rest is written.

        Parameters
        ----------
        outdir : str or PathLike
            The output folder.
        fmt : {"md", "html", "json"}
            Format of ``report.<fmt>`` (``"json"``: no report file, only ``results.json``).

        Returns
        -------
        list of Path
            The files written, as paths inside ``outdir``.
        """
        from .._validate import check_choice
        from ._output import replacing_folder

        check_choice("fmt", fmt, ("md", "html", "json"))
        outdir = Path(outdir)
        figs: dict[str, str] = {}
        notes: list[str] = []
        with replacing_folder(outdir) as tmpdir:
            todo = [f for r in self.results for f in r.figures]
            if todo:
                try:
                    import matplotlib

                    matplotlib.use("Agg", force=False)
                    from .._plotting import pyplot

                    plt = pyplot()
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
                            fig.savefig(tmpdir / f.filename, dpi=110, metadata={"Software": None})
                        plt.close(fig)
                        figs[f.filename] = f.filename
            if fmt != "json":
                if fmt == "md":
                    text = self.markdown(figs)
                else:  # the page embeds its figures: it reads them from where they are written
                    text = self.html({k: str(tmpdir / v) for k, v in figs.items()})
                (tmpdir / f"report.{fmt}").write_text(
                    text + ("\n" + "\n".join(notes) if notes else ""), encoding="utf-8"
                )
            (tmpdir / "results.json").write_text(
                json.dumps(self.to_json(), indent=2, default=_json_default) + "\n", encoding="utf-8"
            )
            (tmpdir / "timings.json").write_text(json.dumps(self.timings(), indent=2) + "\n", encoding="utf-8")
            names = sorted(p.name for p in tmpdir.iterdir())
        for n in notes:
            print(n)
        return [outdir / name for name in names]


def _text_lines(r: QuestionResult) -> list[str]:
    """A question's text lines without the ``figure: <file>`` notes: a report shows the figures that were written
    (embedded in Markdown and HTML) and names no file that may not exist (no matplotlib, ``--no-files``)."""
    return [line for line in r.lines if not line.startswith("figure:")]


def _is_timing(key: Any) -> bool:
    return isinstance(key, str) and (key.endswith("_time") or key.endswith("seconds"))


def _split_timings(data: Any) -> tuple[Any, Any]:
    """``(data without timings, the timings)``: wall-clock numbers differ between runs, so they are kept out of
    ``results.json``."""
    if isinstance(data, dict):
        kept, timed = {}, {}
        for k, v in data.items():
            if _is_timing(k):
                timed[k] = v
                continue
            kept[k], sub = _split_timings(v)
            if sub:
                timed[k] = sub
        return kept, timed
    if isinstance(data, list | tuple):
        parts = [_split_timings(v) for v in data]
        timed = [t for _, t in parts]
        return [k for k, _ in parts], (timed if any(timed) else {})
    return data, {}


def _json_default(obj: Any) -> Any:
    import numpy as np

    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, complex):
        return [obj.real, obj.imag]
    return str(obj)
