"""HTML scene reports people read: a stylesheet, mathematics as MathML, aligned numbers, figures inline.

The page is self-contained and works offline: the equations are presentation MathML from SymPy's printer (rendered
natively by current browsers, no script or web font), the figures and animations are embedded as data URIs.
:func:`fragment` is the same report without the document shell, for ``SceneResult._repr_html_`` in notebooks.
"""

from __future__ import annotations

import base64
import html
import tomllib
from pathlib import Path
from typing import Any

__all__ = ["document", "fragment", "parameter_text"]

_CSS = """
.symosc-report { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif;
  line-height: 1.5; color: #1f2328; max-width: 62rem; margin: 0 auto; padding: 1.5rem 2rem; }
.symosc-report h1 { font-size: 1.6rem; margin: 0 0 .4rem; border-bottom: 2px solid #d0d7de; padding-bottom: .3rem; }
.symosc-report h2 { font-size: 1.2rem; margin: 2rem 0 .6rem; color: #0b4f8a; }
.symosc-report .meta { color: #57606a; margin: .2rem 0 1rem; }
.symosc-report .meta dt { font-weight: 600; float: left; clear: left; width: 5.5rem; }
.symosc-report .meta dd { margin: 0 0 .2rem 5.5rem; }
.symosc-report table { border-collapse: collapse; margin: .6rem 0 1rem; font-size: .92rem; }
.symosc-report caption { caption-side: top; text-align: left; font-style: italic; color: #57606a; padding: .2rem 0; }
.symosc-report th, .symosc-report td { padding: .25rem .7rem; border-bottom: 1px solid #d8dee4; vertical-align: top; }
.symosc-report th { background: #f6f8fa; text-align: left; border-bottom: 2px solid #d0d7de; }
.symosc-report td.num, .symosc-report th.num { text-align: right; font-variant-numeric: tabular-nums;
  font-family: ui-monospace, SFMono-Regular, Menlo, Consolas, monospace; white-space: nowrap; }
.symosc-report p.line { margin: .25rem 0; }
.symosc-report .math { overflow-x: auto; margin: .5rem 0 .8rem; padding: .4rem .8rem; background: #f6f8fa;
  border-left: 3px solid #0b4f8a; }
.symosc-report math { font-size: 1.1rem; font-family: math, "STIX Two Math", "Cambria Math", "Latin Modern Math",
  "DejaVu Math TeX Gyre", serif; }
.symosc-report figure { margin: 1rem 0; }
.symosc-report figure img { max-width: 100%; border: 1px solid #d8dee4; }
.symosc-report figcaption { color: #57606a; font-size: .9rem; }
.symosc-report .log { font-size: .85rem; }
"""


def parameter_text(scene: Any) -> dict[str, str]:
    """Parameter name -> the value as the scene file wrote it (``"146.804 g*mm^2"``), when it still holds (a value
    replaced by an override is shown in SI)."""
    from ._units import parse_quantity

    try:
        raw = tomllib.loads(scene._ctx.text).get("parameters", {})
    except (tomllib.TOMLDecodeError, AttributeError):
        return {}
    out = {}
    for name, si in scene.values.items():
        written = raw.get(name)
        if isinstance(written, str):
            try:
                value = parse_quantity(written, None)
            except Exception:
                continue
            if abs(value - si) <= 1e-12 * max(abs(si), 1e-300):
                out[name] = written.strip()
    return out


def _numeric(cell: str) -> bool:
    try:
        float(cell.split()[0].rstrip("%").replace("−", "-"))
    except (ValueError, IndexError):
        return False
    return True


def _table(headers: Any, rows: Any, caption: str = "", cls: str = "") -> str:
    e = html.escape
    first = rows[0] if rows else headers
    num = [_numeric(c) for c in first]
    cap = f"<caption>{e(caption)}</caption>" if caption else ""

    def cell(tag: str, text: str, numeric: bool) -> str:
        return f"<{tag} class='num'>{e(text)}</{tag}>" if numeric else f"<{tag}>{e(text)}</{tag}>"

    head = "".join(cell("th", h, n) for h, n in zip(headers, num, strict=True))
    body = "".join("<tr>" + "".join(cell("td", c, n) for c, n in zip(r, num, strict=True)) + "</tr>" for r in rows)
    klass = f" class='{cls}'" if cls else ""
    return f"<table{klass}>{cap}<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _math_block(lhs: Any, rhs: Any) -> str:
    from .._printing import mathml

    left = mathml(lhs) + "<mo>=</mo>" if lhs is not None else ""
    return f"<div class='math'><math display='block'><mrow>{left}{mathml(rhs)}</mrow></math></div>"


def _figure(path: str | None, name: str, caption: str) -> str:
    e = html.escape
    if path is None:
        return ""
    p = Path(path)
    if p.is_file():
        kind = "gif" if p.suffix.lower() == ".gif" else "png"
        src = f"data:image/{kind};base64,{base64.b64encode(p.read_bytes()).decode('ascii')}"
    else:
        src = name
    return f"<figure><img src='{e(src)}' alt='{e(caption)}'><figcaption>{e(caption)} ({e(name)})</figcaption></figure>"


def fragment(result: Any, figures: dict[str, str] | None = None) -> str:
    """The scene's results as an HTML fragment (a ``<div>`` with its own stylesheet), for notebooks and pages.

    Parameters
    ----------
    result : SceneResult
        The answers.
    figures : dict, optional
        Figure file name -> path of the drawn file (embedded) or link.

    Returns
    -------
    str
    """
    e = html.escape
    written = getattr(result, "parameter_text", {}) or {}
    out = [f"<div class='symosc-report'><style>{_CSS}</style>", f"<h1>{e(result.title)}</h1><dl class='meta'>"]
    if result.source:
        out.append(f"<dt>Source</dt><dd>{e(result.source)}</dd>")
    if result.system:
        out.append(f"<dt>System</dt><dd>{e(result.system)}</dd>")
    out.append("</dl>")
    if result.parameters:
        rows = [(k, written.get(k, ""), f"{v:.6g}") for k, v in result.parameters.items()]
        out.append(_table(("parameter", "as given", "SI value"), rows, "Parameters"))
    for r in result.results:
        out.append(f"<h2>{e(r.title)}</h2>")
        math: dict[int, list] = {}
        for i, lhs, rhs in getattr(r, "math", ()):
            math.setdefault(i, []).append((lhs, rhs))
        for i, line in enumerate(r.lines):
            if i in math:
                out += [_math_block(lhs, rhs) for lhs, rhs in math[i]]
            elif line and not line.startswith("figure:"):  # written figures are shown below; no file is named
                out.append(f"<p class='line'>{e(line)}</p>")
        out += [_table(t.headers, t.rows, t.caption) for t in r.tables]
        for f in r.figures:
            if figures and f.filename in figures:
                out.append(_figure(figures[f.filename], f.filename, f.caption))
    log = [(str(i + 1), x.step, f"{x.seconds * 1e3:.1f}", x.detail) for i, x in enumerate(result.log)]
    out.append("<h2>Derivation log</h2>")
    out.append(_table(("#", "step", "ms", "detail"), log, "What was derived for these questions", "log"))
    out.append("</div>")
    return "\n".join(out)


def document(result: Any, figures: dict[str, str] | None = None) -> str:
    """The scene's results as a complete, self-contained HTML page (see :func:`fragment`).

    Parameters
    ----------
    result : SceneResult
        The answers.
    figures : dict, optional
        Figure file name -> path of the drawn file (embedded) or link.

    Returns
    -------
    str
    """
    title = html.escape(result.title)
    return (
        "<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'>"
        "<meta name='viewport' content='width=device-width, initial-scale=1'>"
        f"<title>{title}</title></head>\n<body>\n{fragment(result, figures)}\n</body></html>"
    )
