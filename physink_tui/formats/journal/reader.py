"""Reads a journal file back, whole or streamed, stopping at the first malformed line; replays nothing.

A UTF-8 byte order mark before the header is skipped. A last line that is not complete JSON (the process or
the machine died while writing it) is not an error: everything before it is returned and its line number is
reported as `Journal.truncated`. A malformed complete line anywhere raises `JournalError` naming the path, the
line and the key, except when salvaging (recovering a crashed session: the kiosk, the TUI): then every line
before it is kept and `Journal.dropped` says which lines were left out and why. Blank lines are skipped.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from dataclasses import dataclass
from types import TracebackType
from typing import BinaryIO

from physink_tui.errors import JournalError
from physink_tui.formats.journal.codec import decode_line, is_json
from physink_tui.formats.journal.entries import DeviceEntry, JournalEntry, JournalHeader
from physink_tui.formats.journal.header_codec import decode_header

BOM = b"\xef\xbb\xbf"
"""The UTF-8 byte order mark: accepted (and skipped) at the start of a journal."""

JOURNAL_SUFFIX = ".physink.jsonl"
"""The file name ending of a journal."""


def looks_like_journal(first_line: bytes, name: str = "") -> bool:
    """Whether a file starting with ``first_line`` and named ``name`` is meant as a journal, not a capture.

    A journal is JSON text after an optional UTF-8 byte order mark and blanks, or an empty file named
    ``*.physink.jsonl`` (which `read_journal` then reports as an empty journal). `physink replay` should call
    this on the first line it reads instead of looking for ``{`` itself.

    >>> looks_like_journal(BOM + b'{"format":"physink-journal"}'), looks_like_journal(b"D: 0")
    (True, False)
    >>> looks_like_journal(b"", "s.physink.jsonl"), looks_like_journal(b"", "s.hid")
    (True, False)
    """
    head = first_line.removeprefix(BOM).lstrip(b" \t\r\n")
    if not head:
        return os.fspath(name).endswith(JOURNAL_SUFFIX)
    return head.startswith(b"{")


@dataclass(frozen=True, slots=True)
class Journal:
    """A journal as read.

    Attributes:
        path: the file.
        header: its first line.
        entries: every entry after it, in file order (t never decreasing).
        warnings: one message per unknown key, which was ignored (``line 5: unknown key "tilt" ignored``).
        truncated: the 1-based line number of an incomplete last line (cut off mid-write, not returned), or
            None when the file ends with a whole line.
        dropped: when salvaged, what was left out from the first malformed line on; else None.
    """

    path: str
    header: JournalHeader
    entries: tuple[JournalEntry, ...]
    warnings: tuple[str, ...] = ()
    truncated: int | None = None
    dropped: Dropped | None = None


@dataclass(frozen=True, slots=True)
class Dropped:
    """The lines a salvaging read left out: from ``line`` (1-based, the first malformed one) to the end, ``lines``
    of them, and why the first was refused (``reason``, the `JournalError` message without the path)."""

    line: int
    lines: int
    reason: str

    def __str__(self) -> str:
        rest = f" and the {self.lines - 1} after it" if self.lines > 1 else ""
        return f"dropped line {self.line}{rest} ({self.reason})"


def read_journal(path: str | os.PathLike[str], *, salvage: bool = False) -> Journal:
    """Read the whole journal at ``path``; with ``salvage``, up to its first malformed line (`Journal.dropped`).

    Raises:
        JournalError: the file cannot be read, has no complete header, or (unless salvaging) has a malformed
            complete line (``<path>: line 12: key "t": expected a number >= the previous t 3.5, got 3.2``).
    """
    with JournalReader(path, salvage=True) if salvage else iter_journal(path) as reader:
        entries = tuple(reader)
    return Journal(reader.path, reader.header, entries, tuple(reader.warnings), reader.truncated, reader.dropped)


def iter_journal(path: str | os.PathLike[str]) -> JournalReader:
    """Open the journal at ``path`` for streaming: the header is read now, the entries while iterating.

    >>> import os, shutil, tempfile
    >>> from physink_tui.formats.journal.writer import JournalWriter
    >>> from physink_tui.formats.journal.entries import JournalHeader, SayEntry
    >>> folder = tempfile.mkdtemp()
    >>> path = os.path.join(folder, "s.physink.jsonl")
    >>> with JournalWriter.create(path, JournalHeader(4, 3, (), {}, 0.05, 0.01)) as writer:
    ...     writer.append(SayEntry(0.5, "label ball"))
    >>> with iter_journal(path) as reader:
    ...     [entry.text for entry in reader], reader.truncated
    (['label ball'], None)
    >>> shutil.rmtree(folder)
    """
    return JournalReader(path)


class JournalReader:
    """A journal being read: `header` at once, entries by iterating (once), then `warnings` and `truncated`.

    A context manager; the file is also closed when the iteration ends or fails.

    Attributes:
        path: the file.
        header: its header.
        warnings: messages about unknown keys seen so far.
        line: the 1-based line number of the entry last yielded (1 before any), for messages about it.
        truncated: line number of an incomplete last line, set when the iteration reaches it; else None.
    """

    def __init__(self, path: str | os.PathLike[str], *, salvage: bool = False) -> None:
        self.path = os.fspath(path)
        self.warnings: list[str] = []
        self.truncated: int | None = None
        self.dropped: Dropped | None = None
        self._salvage = salvage
        try:
            self._file: BinaryIO = open(self.path, "rb")  # closed by close() or the iteration
        except OSError as e:
            raise JournalError(f"cannot read journal {self.path}: {e.strerror or e}") from None
        try:
            self.header = self._read_header()
        except BaseException:
            self._file.close()
            raise
        self._devices = {d.id for d in self.header.devices}
        self.line = 1
        self._entries = self._read_entries()

    def __iter__(self) -> Iterator[JournalEntry]:
        return self._entries

    def close(self) -> None:
        """Close the file (idempotent)."""
        self._file.close()

    def __enter__(self) -> JournalReader:
        return self

    def __exit__(self, kind: type[BaseException] | None, value: BaseException | None, tb: TracebackType | None) -> None:
        self.close()

    def _read_header(self) -> JournalHeader:
        try:
            raw = self._file.readline()
        except OSError as e:
            raise JournalError(f"cannot read journal {self.path}: {e.strerror or e}") from None
        raw = raw.removeprefix(BOM)  # editors on Windows start UTF-8 files with one
        if not raw:
            raise JournalError(f"{self.path}: empty journal: no header line")
        cut = JournalError(f"{self.path}: line 1: the header is cut off (the file ends inside it)")
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as e:
            if not raw.endswith(b"\n"):
                raise cut from None
            raise JournalError(f"{self.path}: line 1: not valid UTF-8 (byte {e.start + 1})") from None
        if not raw.endswith(b"\n") and not is_json(text):
            raise cut
        try:
            return decode_header(text, 1, self.warnings)
        except JournalError as e:
            raise JournalError(f"{self.path}: {e}") from None

    def _read_entries(self) -> Iterator[JournalEntry]:
        previous: float | None = None
        lineno = 1
        try:
            for raw in self._file:
                lineno += 1
                last = not raw.endswith(b"\n")
                try:
                    text = raw.decode("utf-8")
                except UnicodeDecodeError as e:
                    if last:  # cut inside a multi-byte character
                        self.truncated = lineno
                        return
                    if self._salvage:
                        self._drop(lineno, f"line {lineno}: not valid UTF-8 (byte {e.start + 1})")
                        return
                    raise JournalError(f"{self.path}: line {lineno}: not valid UTF-8 (byte {e.start + 1})") from None
                if not text.strip(" \t\r\n"):
                    continue
                if last and not is_json(text):
                    self.truncated = lineno
                    return
                try:
                    entry = decode_line(
                        text, lineno, previous_t=previous, devices=self._devices, warnings=self.warnings
                    )
                except JournalError as e:
                    if self._salvage:
                        self._drop(lineno, str(e))
                        return
                    raise JournalError(f"{self.path}: {e}") from None
                previous = entry.t
                if isinstance(entry, DeviceEntry):
                    self._devices.update(d.id for d in entry.devices)
                self.line = lineno
                yield entry
        except OSError as e:
            raise JournalError(f"{self.path}: line {lineno}: cannot read: {e.strerror or e}") from None
        finally:
            self._file.close()

    def _drop(self, lineno: int, reason: str) -> None:
        """Salvaging: the lines from ``lineno`` on are left out (counted; a torn last one among them)."""
        rest = sum(1 for _ in self._file)
        self.dropped = Dropped(lineno, 1 + rest, reason)
