"""Reads a command's input file once (so pipes and FIFOs work) and names its kind; parses no format itself."""

from __future__ import annotations

import json
import os
import shutil
import stat
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from physink_tui.errors import PhysinkError
from physink_tui.formats.outputs import reason
from physink_tui.formats.timeline_json import FORMAT as TIMELINE_FORMAT

BOM = b"\xef\xbb\xbf"
PROJECT_FORMAT = "physink-project"  # the project codec's FORMAT, kept here so sniffing imports no codec
JOURNAL_FORMAT = "physink-journal"


def read_bytes(path: str | os.PathLike[str], what: str = "input") -> bytes:
    """The whole file at ``path``, read once; `PhysinkError` naming the path and the cause when it cannot be."""
    try:
        with open(path, "rb") as f:
            return f.read()
    except OSError as exc:
        raise PhysinkError(f"{os.fspath(path)}: cannot read the {what}: {reason(exc)}") from None


def _first_json(data: bytes) -> object:
    line = data.split(b"\n", 1)[0]
    try:
        return json.loads(line.decode("utf-8"))
    except (ValueError, RecursionError):
        return None


def sniff(data: bytes, path: str | os.PathLike[str], command: str = "replay") -> str:
    """``"journal"`` or ``"capture"`` for ``replay``'s input; a UTF-8 BOM is allowed.

    Raises:
        PhysinkError: the file is empty, or is a project or timeline (a file of the wrong kind, named as such).
    """
    name = os.fspath(path)
    takes = f"{command} takes a journal (.physink.jsonl) or a capture (.hid)"
    body = data.removeprefix(BOM).lstrip()
    if not body:
        raise PhysinkError(f"{name}: empty file; {takes}")
    if not body.startswith(b"{"):
        return "capture"
    head = _first_json(body)
    if head is None:  # an indented project or timeline spans lines
        head = _first_json(body.replace(b"\n", b" "))
    if isinstance(head, dict) and head.get("format") == PROJECT_FORMAT:
        raise PhysinkError(f"{name}: this is a project (.physink.json); {takes}")
    timeline = isinstance(head, dict) and (head.get("format") == TIMELINE_FORMAT
                                           or ("events" in head and "format" not in head))  # versions 1 and 0
    if timeline:
        raise PhysinkError(f"{name}: this is a timeline (timeline.json); {takes}")
    return "journal"


@contextmanager
def regular_copy(path: str | os.PathLike[str], data: bytes) -> Iterator[Path]:
    """``path`` itself when it is a regular file without a BOM; else a temporary copy of ``data`` (BOM removed).

    Readers that open a path (the journal reader) then see the bytes already read, however the input came:
    a pipe, a FIFO or ``<(cat FILE)`` can be read only once.
    """
    try:
        regular = stat.S_ISREG(os.stat(path).st_mode)
    except OSError:
        regular = False
    if regular and not data.startswith(BOM):
        yield Path(path)
        return
    folder = tempfile.mkdtemp(prefix="physink-input-")
    try:
        copy = Path(folder) / (Path(path).name or "input")
        copy.write_bytes(data.removeprefix(BOM))
        yield copy
    finally:
        shutil.rmtree(folder, ignore_errors=True)
