"""Every example of the user guide (``docs/*.md``) runs as written.

A reader copies the examples of a page into a fresh session, in order. So, for each page:

* its ``>>>`` examples (in any fenced block) run as ONE doctest session with empty globals, in page order, with
  ``ELLIPSIS | NORMALIZE_WHITESPACE`` -- the page imports what it uses in its first example;
* its plain ```` ```python ```` blocks (no ``>>>``) are executed in order in one fresh namespace of their own;
* nothing that looks like a runnable example escapes both: a ``>>>`` line outside a fenced block, or a fenced block
  tagged as Python in another spelling, fails the page.

Figures are drawn on the Agg canvas and closed; files an example writes go to a temporary working directory.
"""

from __future__ import annotations

import doctest
import io
import re
from dataclasses import dataclass
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import pytest  # noqa: E402

DOCS = Path(__file__).resolve().parents[1] / "docs"
PAGES = sorted(DOCS.glob("*.md"))
PYTHON_TAGS = {"python", "py", "python3", "pycon", "{code-cell}", "ipython", "ipython3"}
OPTIONFLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
_FENCE = re.compile(r"^(?P<indent>[ \t]*)(?P<fence>`{3,}|~{3,})(?P<info>.*)$")


@dataclass(frozen=True)
class Block:
    """One fenced block of a page: its info string, first body line (1-based) and body lines (dedented)."""

    info: str
    lineno: int
    lines: tuple[str, ...]

    @property
    def language(self) -> str:
        return self.info.split()[0].lower() if self.info.split() else ""

    @property
    def is_doctest(self) -> bool:
        return any(line.lstrip().startswith(">>>") for line in self.lines)

    @property
    def is_python(self) -> bool:
        return self.language in PYTHON_TAGS and not self.is_doctest


def fenced_blocks(text: str) -> tuple[list[Block], list[int]]:
    """The fenced blocks of a Markdown page and the line numbers of ``>>>`` lines outside every block."""
    blocks: list[Block] = []
    stray: list[int] = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        m = _FENCE.match(lines[i])
        if m is None:
            if lines[i].lstrip().startswith(">>>"):
                stray.append(i + 1)
            i += 1
            continue
        indent, fence = len(m["indent"]), m["fence"]
        close = re.compile(rf"^[ \t]*{re.escape(fence[0])}{{{len(fence)},}}[ \t]*$")
        body: list[str] = []
        j = i + 1
        while j < len(lines) and not close.match(lines[j]):
            body.append(lines[j][indent:] if lines[j][:indent].strip() == "" else lines[j])
            j += 1
        if j == len(lines):
            raise AssertionError(f"line {i + 1}: fenced block is never closed")
        blocks.append(Block(m["info"].strip(), i + 2, tuple(body)))
        i = j + 1
    return blocks, stray


def doctest_source(text: str, blocks: list[Block]) -> str:
    """The page with everything but its ``>>>`` blocks blanked, so that doctest line numbers are page lines."""
    out = [""] * (len(text.splitlines()) + 1)
    for block in blocks:
        if block.is_doctest:
            for k, line in enumerate(block.lines):
                out[block.lineno - 1 + k] = line
            out[block.lineno - 1 + len(block.lines)] = ""  # an example's expected output ends with its block
    return "\n".join(out) + "\n"


@pytest.fixture
def clean_session(tmp_path, monkeypatch):
    """Run in an empty working directory, close every figure afterwards."""
    import matplotlib.pyplot as plt

    monkeypatch.chdir(tmp_path)
    yield
    plt.close("all")


def run_doctests(page: Path) -> tuple[int, int, str]:
    text = page.read_text()
    blocks, _ = fenced_blocks(text)
    test = doctest.DocTestParser().get_doctest(doctest_source(text, blocks), {}, page.name, str(page), 0)
    report = io.StringIO()
    runner = doctest.DocTestRunner(optionflags=OPTIONFLAGS)
    runner.run(test, out=report.write)
    return runner.failures, runner.tries, report.getvalue()


def run_python_blocks(page: Path) -> int:
    blocks, _ = fenced_blocks(page.read_text())
    namespace: dict = {"__name__": "__main__"}
    count = 0
    for block in blocks:
        if block.is_python:
            source = "\n" * (block.lineno - 1) + "\n".join(block.lines) + "\n"
            exec(compile(source, str(page), "exec"), namespace)
            count += 1
    return count


@pytest.mark.parametrize("page", PAGES, ids=[p.name for p in PAGES])
def test_page_examples_run(page, clean_session):
    blocks, stray = fenced_blocks(page.read_text())
    assert stray == [], f"{page.name}: '>>>' lines outside a fenced block at lines {stray}"
    untagged = [b.lineno for b in blocks if b.language.startswith("py") and not (b.is_python or b.is_doctest)]
    assert untagged == []
    failures, tries, report = run_doctests(page)
    assert failures == 0, f"{page.name}: {failures} of {tries} examples failed\n{report[-20000:]}"
    assert tries == sum(b.is_doctest for b in blocks) == 0 or tries >= sum(b.is_doctest for b in blocks)
    run_python_blocks(page)


def test_the_pages_have_examples():
    """Guard against a parser change silently running nothing: the guide as a whole has hundreds of examples."""
    doctests = sum(len(doctest.DocTestParser().get_examples(doctest_source(p.read_text(), fenced_blocks(p.read_text())[0]))) for p in PAGES)
    python = sum(b.is_python for p in PAGES for b in fenced_blocks(p.read_text())[0])
    assert doctests > 300 and python > 20
