"""Scene-file errors: one paragraph naming the file, the key (and its line), what was expected and the fix."""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable

from ..errors import ModelError

__all__ = ["SceneError", "closest", "locate"]


class SceneError(ModelError):
    """A scene file that cannot be run: the message names the file, the key, the expectation and the fix.

    Attributes
    ----------
    path : str
        The scene file.
    key : str
        Dotted key, e.g. ``"parameters.m1"`` or ``"questions[2].kind"`` (empty for file-level errors).
    line : int or None
        Line of the key in the file, when it can be located.

    Examples
    --------
    >>> str(SceneError("a.toml", "system.n", "expected an integer >= 1, got 0", line=4, fix="write n = 1"))
    "a.toml, line 4: key 'system.n': expected an integer >= 1, got 0. Fix: write n = 1."

    See Also
    --------
    symosc.scene.load : raises it for a bad scene file.
    """

    def __init__(self, path: str, key: str, message: str, *, line: int | None = None, fix: str = "") -> None:
        self.path = str(path)
        self.key = key
        self.line = line
        self.message = message.rstrip(".")
        where = self.path + (f", line {line}" if line else "")
        head = f"{where}: key '{key}': " if key else f"{where}: "
        text = head + message.rstrip(".") + "."
        if fix:
            text += " Fix: " + fix.rstrip(".") + "."
        super().__init__(text)


def closest(name: str, valid: Iterable[str]) -> str:
    """``" Did you mean 'x'?"`` for the closest valid name (empty when nothing is close).

    >>> closest("pivit", ["pivot", "links"])
    " Did you mean 'pivot'?"
    >>> closest("zzz", ["pivot"])
    ''
    """
    match = difflib.get_close_matches(name, list(valid), n=1, cutoff=0.6)
    if not match:
        lowered = {v.lower(): v for v in valid}
        if name.lower() in lowered:
            match = [lowered[name.lower()]]
    return f" Did you mean '{match[0]}'?" if match else ""


_HEADER = re.compile(r"^\s*\[\[?\s*([^\]]+?)\s*\]\]?")
_KEY = re.compile(r"^\s*\"?([A-Za-z0-9_\-.]+)\"?\s*=")


def locate(text: str, key: str) -> int | None:
    """Best-effort line number (1-based) of a dotted ``key`` in TOML ``text``.

    ``questions[2].order`` is looked up in the third ``[[questions]]`` block.

    >>> locate("[system]\\nmodel = 'x'\\n[parameters]\\nm1 = 1\\n", "parameters.m1")
    4
    """
    whole = re.fullmatch(r"(\w+)\[(\d+)\]", key)
    if whole:  # an array-of-tables entry itself: its [[header]] line
        count = -1
        for i, line in enumerate(text.splitlines(), start=1):
            h = _HEADER.match(line)
            if h and line.strip().startswith("[[") and h.group(1) == whole.group(1):
                count += 1
                if count == int(whole.group(2)):
                    return i
        return None
    parts = key.split(".")
    table, name = parts[:-1], parts[-1]
    m = re.fullmatch(r"(\w+)\[(\d+)\]", table[0]) if table else None
    want_header, occurrence = (m.group(1), int(m.group(2))) if m else (".".join(table), 0)
    if m and len(table) > 1:
        name = ".".join([*table[1:], name])
    current, seen = "", {}
    found_table = None
    for i, line in enumerate(text.splitlines(), start=1):
        h = _HEADER.match(line)
        if h:
            current = h.group(1)
            seen[current] = seen.get(current, -1) + 1
            if current == key and not m:
                return i
            if current == want_header and seen[current] == occurrence:
                found_table = i
            continue
        k = _KEY.match(line)
        if k and current == want_header and seen.get(current, 0) == occurrence:
            if k.group(1) == name or k.group(1) == name.split(".")[0]:
                return i
        elif k and not want_header and current == "" and k.group(1) == name:
            return i
        elif k and current == "" and want_header and k.group(1) == want_header:
            return i  # inline table at the top level: key = { ... }
    return found_table
