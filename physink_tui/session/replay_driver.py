"""Drives a session through recorded entries without threads (`physink replay`, tests): optionally advancing its
clock at a fixed rate between entries, as a live driver does, which must change nothing in the outcome."""

from __future__ import annotations

import math
from collections.abc import Iterable

from physink_tui.formats.journal.entries import JournalEntry
from physink_tui.session.session import Session


def replay(session: Session, entries: Iterable[JournalEntry], ticks: float | None = None) -> Session:
    """Hand every entry to ``session`` in order and finish it. With ``ticks`` (Hz), time also advances to every
    multiple of 1/ticks seconds between entries, the way `SessionRunner` advances a live session.

    Raises:
        ValueError: ``ticks`` is not a positive, finite rate.
    """
    if ticks is not None and not (math.isfinite(ticks) and ticks > 0):
        raise ValueError(f"ticks: expected a positive number of ticks per second, got {ticks!r}")
    tick = 1
    for entry in entries:
        if ticks is not None:
            while tick / ticks < entry.t:
                session.advance(tick / ticks)
                tick += 1
        session.handle(entry)
    session.finish()
    return session
