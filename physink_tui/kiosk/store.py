"""The kiosk's output folder: one folder per session named by its UTC start, ``index.jsonl`` with a line per
finished session, which sessions are unfinished, and retiring the oldest; writes no session files itself.

``index.jsonl`` is append-only: each line is written with one ``write`` on a file opened for appending and
fsynced, so a kill leaves whole lines (at most the last one missing, and that session is finalised again, its line
written then). A session already in the index is never indexed twice. Retiring a session removes its folder and
appends ``{"session": ..., "retired": true}``.
"""

from __future__ import annotations

import json
import os
import shutil
from collections.abc import Callable, Iterable
from datetime import datetime
from pathlib import Path

from physink_tui.errors import PhysinkError
from physink_tui.formats.outputs import reason
from physink_tui.kiosk.folder_files import JOURNAL, SUMMARY

INDEX = "index.jsonl"


class SessionStore:
    """The sessions under ``root`` (made if needed).

    Raises:
        PhysinkError: ``root`` cannot be made (the path and the cause named).
    """

    def __init__(self, root: str | os.PathLike[str]) -> None:
        self.root = Path(root)
        try:
            self.root.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise PhysinkError(f"{self.root}: cannot make the kiosk's output folder: {reason(exc)}") from None

    def new_folder(self, started: datetime) -> Path:
        """A fresh folder for a session started at ``started`` (UTC): ``20261202T031500Z`` (``-2``, ``-3`` ... when
        two start within a second)."""
        base = started.strftime("%Y%m%dT%H%M%SZ")
        name, n = base, 1
        while (self.root / name).exists():
            n += 1
            name = f"{base}-{n}"
        folder = self.root / name
        folder.mkdir()
        return folder

    def set_aside(self, folder: Path) -> Path:
        """Renames an unfinished session's journal that cannot be read at all to ``journal.physink.jsonl.unreadable``
        (the folder then holds no session: it is neither recovered again nor retired); returns the new path."""
        target = folder / (JOURNAL + ".unreadable")
        os.replace(folder / JOURNAL, target)
        return target

    def sessions(self) -> list[Path]:
        """Every session folder (one with a journal), oldest first."""
        return sorted((p for p in self.root.iterdir() if p.is_dir() and (p / JOURNAL).exists()),
                      key=lambda p: p.name)

    def unfinished(self) -> list[Path]:
        """Session folders without their summary: the kiosk stopped before it finished them."""
        return [p for p in self.sessions() if not (p / SUMMARY).exists()]

    def finished(self) -> list[Path]:
        return [p for p in self.sessions() if (p / SUMMARY).exists()]

    def indexed(self) -> set[str]:
        """The sessions the index has a line for (a torn last line is skipped)."""
        seen: set[str] = set()
        try:
            lines = (self.root / INDEX).read_text(encoding="utf-8").splitlines()
        except FileNotFoundError:
            return seen
        for line in lines:
            try:
                record = json.loads(line)
            except json.JSONDecodeError:
                continue
            if isinstance(record, dict) and isinstance(record.get("session"), str) and not record.get("retired"):
                seen.add(record["session"])
        return seen

    def index(self, summary: dict[str, object]) -> bool:
        """Append ``summary`` as the session's index line, unless the index has it already; True if appended."""
        if summary["session"] in self.indexed():
            return False
        self._append(summary)
        return True

    def retire(self, keep: int | None, max_bytes: int | None, spare: Iterable[Path | None] = (),
               log: Callable[[str], None] = print) -> list[str]:
        """Remove the oldest finished sessions until at most ``keep`` remain and they take at most ``max_bytes``
        (None: no limit); never those in ``spare`` (the session just written, the one being recorded), which
        count towards the limits all the same. Returns the names removed."""
        spared = {p for p in spare if p is not None}
        finished = self.finished()
        sizes = {p: _size(p) for p in finished}
        count, total = len(finished), sum(sizes.values())
        removable = [p for p in finished if p not in spared]
        removed = []
        while removable and ((keep is not None and count > keep) or (max_bytes is not None and total > max_bytes)):
            oldest = removable.pop(0)
            shutil.rmtree(oldest, ignore_errors=True)
            count -= 1
            total -= sizes[oldest]
            removed.append(oldest.name)
            self._append({"session": oldest.name, "retired": True})
            log(f"kiosk: retired session {oldest.name} ({sizes[oldest] / 1e6:.1f} MB)")
        return removed

    def free_bytes(self) -> int:
        return shutil.disk_usage(self.root).free

    def _append(self, record: dict[str, object]) -> None:
        line = (json.dumps(record, sort_keys=True) + "\n").encode("utf-8")
        fd = os.open(self.root / INDEX, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
        try:
            os.write(fd, line)
            os.fsync(fd)
        finally:
            os.close(fd)


def _size(folder: Path) -> int:
    return sum(p.stat().st_size for p in folder.rglob("*") if p.is_file())


def parse_size(text: str) -> int:
    """``"500M"``, ``"2G"``, ``"800k"`` or a byte count, as bytes.

    Raises:
        ValueError: anything else (the text named).
    """
    units = {"": 1, "K": 10**3, "M": 10**6, "G": 10**9, "T": 10**12}
    value = text.strip().upper().removesuffix("B")
    unit = value[-1:] if value[-1:] in units else ""
    number = value[: len(value) - len(unit)]
    try:
        size = float(number) * units[unit]
    except ValueError:
        raise ValueError(f"{text!r} is not a size; expected bytes or a number with K, M, G or T") from None
    if not size > 0 or size != size:
        raise ValueError(f"{text!r} is not a size above 0")
    return int(size)
