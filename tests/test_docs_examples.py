"""Every example of the user guide (``docs/*.md``) runs as written.

A reader copies the examples of a page into a fresh session, in order. So, for each page:

* its ``>>>`` examples (in any fenced block) run as ONE doctest session with empty globals, in page order, with
  ``ELLIPSIS | NORMALIZE_WHITESPACE`` -- the page imports what it uses in its first example;
* its plain ```` ```python ```` blocks (no ``>>>``) are executed in order in one fresh namespace of their own; an
  untagged block right after one shows what it prints, and is compared with what it prints;
* nothing that looks like a runnable example escapes both: a ``>>>`` line outside a fenced block, or a fenced block
  tagged as Python in another spelling, fails the page.

Figures are drawn on the Agg canvas (set in conftest.py) and closed; files an example writes go to a temporary
working directory.
"""

from __future__ import annotations

import doctest
import io
import re
from dataclasses import dataclass
from pathlib import Path

import pytest

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


ROOT = DOCS.parent
_SCRIPT = re.compile(r"^# (?P<name>[A-Za-z_][A-Za-z0-9_]*\.py)\s*$")


@pytest.fixture
def reader_session(tmp_path, monkeypatch):
    """A fresh working directory that holds the repository's ``examples/`` (the pages load scenes from it), on
    ``sys.path`` (a block headed ``# name.py`` is a module the next blocks import); figures, mpmath precision and
    NumPy print options are restored afterwards."""
    import sys

    import matplotlib.pyplot as plt
    import mpmath
    import numpy as np

    (tmp_path / "examples").symlink_to(ROOT / "examples", target_is_directory=True)
    monkeypatch.chdir(tmp_path)
    monkeypatch.syspath_prepend(str(tmp_path))
    modules, dps, printoptions = set(sys.modules), mpmath.mp.dps, np.get_printoptions()
    yield tmp_path
    plt.close("all")
    mpmath.mp.dps = dps
    np.set_printoptions(**printoptions)
    for name in set(sys.modules) - modules:  # the page's own modules (mc_demo.py, ...), not library imports
        if getattr(sys.modules[name], "__file__", None) and str(tmp_path) in sys.modules[name].__file__:
            del sys.modules[name]


def run_doctests(page: Path) -> tuple[int, int, str]:
    """Run the page's ``>>>`` examples as one session with empty globals: (failures, tries, report)."""
    text = page.read_text()
    blocks, _ = fenced_blocks(text)
    test = doctest.DocTestParser().get_doctest(doctest_source(text, blocks), {}, page.name, str(page), 0)
    report = io.StringIO()
    runner = doctest.DocTestRunner(optionflags=OPTIONFLAGS)
    runner.run(test, out=report.write)
    return runner.failures, runner.tries, report.getvalue()


def printed_output_block(text: str, blocks: list[Block], index: int) -> Block | None:
    """The untagged block right after ``blocks[index]`` (only blank lines between): the output it prints."""
    if index + 1 >= len(blocks) or blocks[index + 1].language != "":
        return None
    lines = text.splitlines()
    block, nxt = blocks[index], blocks[index + 1]
    between = lines[block.lineno + len(block.lines) : nxt.lineno - 2]  # after the closing fence, before the opening
    return nxt if all(not line.strip() for line in between) else None


def run_python_blocks(page: Path, workdir: Path) -> tuple[int, list[str]]:
    """Execute the page's plain ```` ```python ```` blocks in order in one namespace.

    A block whose first line is ``# name.py`` is a file the reader saves: it is written to ``workdir`` and run
    as a script (``__name__ == "__main__"``), and the names it defines join the namespace.  A block followed
    directly by an untagged block shows what it prints there: the printed text is compared with it (as doctest
    compares, with the same flags).  Returns the number of blocks run and the output mismatches."""
    import contextlib
    import runpy

    text = page.read_text()
    blocks, _ = fenced_blocks(text)
    namespace: dict = {"__name__": "__main__"}
    checker = doctest.OutputChecker()
    count, mismatches = 0, []
    for k, block in enumerate(blocks):
        if not block.is_python:
            continue
        source = "\n".join(block.lines) + "\n"
        script = _SCRIPT.match(block.lines[0]) if block.lines else None
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            if script:
                path = workdir / script["name"]
                path.write_text(source)
                namespace.update(runpy.run_path(str(path), run_name="__main__"))
            else:
                exec(compile("\n" * (block.lineno - 1) + source, str(page), "exec"), namespace)
        count += 1
        shown = printed_output_block(text, blocks, k)
        if shown is not None:
            want = "\n".join(shown.lines) + "\n"
            if not checker.check_output(want, printed.getvalue(), OPTIONFLAGS):
                mismatches.append(f"line {shown.lineno}:\nshown:\n{want}printed:\n{printed.getvalue()}")
    return count, mismatches


@pytest.mark.parametrize("page", PAGES, ids=[p.name for p in PAGES])
def test_page_examples_run_as_written(page, reader_session):
    blocks, stray = fenced_blocks(page.read_text())
    assert stray == [], f"{page.name}: '>>>' lines outside a fenced block (never run) at lines {stray}"
    odd = [b.lineno for b in blocks if b.language.startswith("py") and not (b.is_python or b.is_doctest)]
    assert odd == [], f"{page.name}: Python blocks with an unknown tag at lines {odd}"
    failures, tries, report = run_doctests(page)
    assert failures == 0, f"{page.name}: {failures} of {tries} examples failed\n{report[-20000:]}"
    ran, mismatches = run_python_blocks(page, reader_session)
    assert mismatches == [], f"{page.name}: printed output differs from the page\n" + "\n".join(mismatches)
    assert ran == sum(b.is_python for b in blocks)


def test_fenced_block_parser():
    """The parser finds ``>>>`` blocks, plain Python blocks, indented fences and stray prompts."""
    text = "\n".join(
        [
            "intro >>> not a prompt",
            "```python",
            ">>> 1 + 1",
            "2",
            "```",
            "  ```python",
            "  x = 1",
            "  ```",
            "````text",
            "```python",
            "````",
            ">>> stray",
        ]
    )
    blocks, stray = fenced_blocks(text)
    assert [(b.language, b.lineno, b.is_doctest, b.is_python) for b in blocks] == [
        ("python", 3, True, False),
        ("python", 7, False, True),
        ("text", 10, False, False),
    ]
    assert blocks[1].lines == ("x = 1",) and stray == [12]
    examples = doctest.DocTestParser().get_examples(doctest_source(text, blocks))
    assert [(e.source, e.want, e.lineno) for e in examples] == [("1 + 1\n", "2\n", 2)]


def test_the_guide_has_examples():
    """Guard against a parser change that silently runs nothing: the guide holds hundreds of examples."""
    n_doctest = n_python = 0
    for page in PAGES:
        text = page.read_text()
        blocks, _ = fenced_blocks(text)
        n_doctest += len(doctest.DocTestParser().get_examples(doctest_source(text, blocks)))
        n_python += sum(b.is_python for b in blocks)
    assert n_doctest > 300 and n_python > 20
