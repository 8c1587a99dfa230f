"""A live session wired up the one way every live driver (the TUI, the kiosk) needs it: the `Session` of a journal
header, journaling to a new file, with earlier entries handled first, and its `SessionRunner`; reads no device."""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from physink_tui.formats.journal.entries import CommandEntry, JournalEntry, JournalHeader
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.session.runner import MAX_FPS, SessionRunner
from physink_tui.session.session import Session
from physink_tui.session.view import SessionView


@dataclass(frozen=True, slots=True)
class Journaled:
    """A session, the journal it writes (None: none) and the runner that drives it (not started yet)."""

    session: Session
    writer: JournalWriter | None
    runner: SessionRunner[SessionView]

    @classmethod
    def create(cls, header: JournalHeader, journal_path: Path | None, *, prior: Sequence[JournalEntry] = (),
               clock: Callable[[], float] = time.monotonic, max_fps: float = MAX_FPS,
               on_error: Callable[[BaseException], object] | None = None) -> Journaled:
        """The session of ``header`` journaling to the new file ``journal_path``; ``prior``: entries of an earlier
        run of it (a recovered journal), handled at once and journaled again, its ``end`` left out.

        Raises:
            JournalError: the journal cannot be created (it exists, or the folder cannot be written).
        """
        session = Session.from_header(header)
        writer = JournalWriter.create(journal_path, header) if journal_path is not None else None
        session.journal = writer
        for entry in prior:
            if not (isinstance(entry, CommandEntry) and entry.name == "end"):
                session.handle(entry)
        return cls(session, writer, SessionRunner(session, clock=clock, max_fps=max_fps, on_error=on_error))
