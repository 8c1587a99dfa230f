"""The TUI's live session: a journaling `Session` driven by a `SessionRunner`, the mouse as a pen source and a
paced journal feed (the demo); no Textual, no drawing.

Everything the user does reaches the session as a journal entry through the runner (keys as ``cmd`` entries,
the mouse as ``pen`` entries through `ProgrammaticPenSource` and `SourcePump`, a tablet through
`physink_tui.tui.tablet`), so the journal in the XDG data folder rebuilds the session exactly. A replayed journal
(``physink demo``, ``physink tui --replay``) is fed in at its own pace by `JournalFeed`: its entries are submitted
when they are due, stamped by the runner as any input, and the user can carry on from where it stops.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from physink_tui.formats.journal.entries import CommandEntry, JournalEntry, JournalHeader
from physink_tui.input.replay_clock import ReplayClock
from physink_tui.input.scripted_sources import ProgrammaticPenSource
from physink_tui.session.journaled import Journaled
from physink_tui.session.simulation import SessionInput
from physink_tui.session.source_pump import SourcePump

MOUSE = "mouse"
"""The mouse pen's source id (its samples become ``pen`` lines, which name no device)."""
DEFAULT_CANVAS = (1600.0, 1000.0)


def default_header() -> JournalHeader:
    """The header of a session with no tablet yet: the default canvas, libinput's tip thresholds."""
    return JournalHeader(DEFAULT_CANVAS[0], DEFAULT_CANVAS[1], (), {}, 0.05, 0.01, vocabulary="")


class JournalFeed:
    """Submits recorded entries to a runner when they are due (``speed`` times real time), from a thread.

    ``end`` entries are left out: the live session goes on after the feed. ``on_done`` is called on the feed's
    thread when the last entry was submitted (or the feed was stopped). Given the runner's ``clock`` (a
    `ReplayClock`), it paces by it and holds it at each entry's due time until the entry is submitted: each entry
    is stamped with its recorded time (scaled by ``speed``), however late a loaded machine gets to it.
    """

    def __init__(self, entries: Sequence[JournalEntry], submit: Callable[[JournalEntry], object], *,
                 speed: float = 1.0, on_done: Callable[[], object] | None = None,
                 clock: ReplayClock | None = None) -> None:
        if not speed > 0:
            raise ValueError(f"speed: expected > 0, got {speed!r}")
        self.entries = [e for e in entries if not (isinstance(e, CommandEntry) and e.name == "end")]
        self._submit = submit
        self._speed = speed
        self._on_done = on_done
        self._clock = clock
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self.submitted = 0
        self.last_t: float | None = None
        """The stamp of the last entry submitted (what ``submit`` returned), once one was: the session has handled
        all the feed gave it when its view's ``t`` is at least this."""

    def start(self) -> None:
        self._thread = threading.Thread(target=self._run, name="journal-feed", daemon=True)
        self._thread.start()

    @property
    def running(self) -> bool:
        return self._thread is not None and self._thread.is_alive()

    def stop(self) -> None:
        self._stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join()

    def _run(self) -> None:
        if self._clock is not None:
            self._run_on_clock(self._clock)
        else:
            start = time.monotonic()
            first = self.entries[0].t if self.entries else 0.0
            for entry in self.entries:
                delay = (entry.t - first) / self._speed - (time.monotonic() - start)
                if delay > 0 and self._stop.wait(delay):
                    break
                if self._stop.is_set():
                    break
                self._took(self._submit(entry))
        if self._on_done is not None:
            self._on_done()

    def _run_on_clock(self, clock: ReplayClock) -> None:
        origin = clock.running()
        first = self.entries[0].t if self.entries else 0.0
        try:
            for entry in self.entries:
                due = origin + (entry.t - first) / self._speed
                clock.hold_at(due)
                if clock.wait_until(due, self._stop):
                    break
                self._took(self._submit(entry))
        finally:
            clock.release()

    def _took(self, stamped: object) -> None:
        self.submitted += 1
        if isinstance(stamped, JournalEntry):
            self.last_t = stamped.t


class LiveSession:
    """One TUI session: the `Session` (journaling to ``journal_path``), its runner and the mouse pen.

    Args:
        header: the journal header (canvas, devices, mapping); a replayed journal's own header, so its HID lines
            decode.
        journal_path: where the session journals (a new file), or None for no journal (tests).
        prior: entries handled at once before the runner starts (a recovered journal), journaled again.
        max_fps: views published a second at most.
        clock: the runner's clock (seconds on a monotonic scale).
    """

    def __init__(self, header: JournalHeader, *, journal_path: Path | None = None,
                 prior: Sequence[JournalEntry] = (), max_fps: float = 30.0,
                 on_error: Callable[[BaseException], object] | None = None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.header = header
        self.journal_path = journal_path
        self.clock = ReplayClock(clock)
        """The runner's clock: ``clock`` itself, except that a replay holds it at each entry's time (`JournalFeed`)."""
        journaled = Journaled.create(header, journal_path, prior=prior, clock=self.clock, max_fps=max_fps,
                                     on_error=on_error)
        self.session, self.runner = journaled.session, journaled.runner
        self.mouse = ProgrammaticPenSource(MOUSE)
        self.mouse_pump = SourcePump(self.mouse, self.runner.submit)
        self.feed: JournalFeed | None = None
        self._stoppers: list[Callable[[], None]] = []
        self.stopped = False

    @property
    def canvas(self) -> tuple[float, float]:
        return self.session.canvas

    def start(self) -> None:
        """Start the runner and the mouse pen."""
        self.runner.start()
        self.mouse_pump.start()

    def submit(self, entry: SessionInput) -> SessionInput | None:
        return self.runner.submit(entry)

    def command(self, name: str, *args: str | float, project: dict[str, Any] | None = None) -> SessionInput | None:
        """Submit a command (a key or a button)."""
        return self.runner.submit(CommandEntry(0.0, name, tuple(args), project))

    def replay(self, entries: Sequence[JournalEntry], *, speed: float = 1.0,
               on_done: Callable[[], object] | None = None) -> JournalFeed:
        """Feed recorded entries at ``speed`` times real time (one feed at a time)."""
        if self.feed is not None:
            self.feed.stop()
        self.feed = JournalFeed(entries, self.runner.submit, speed=speed, on_done=on_done, clock=self.clock)
        self.feed.start()
        return self.feed

    def on_stop(self, stopper: Callable[[], None]) -> None:
        """Call ``stopper`` (a tablet watcher's stop) before the runner stops."""
        self._stoppers.append(stopper)

    def vocabulary_lines(self) -> tuple[str, ...]:
        """The user's words, for a saved project (a frozen value the session replaces, safe to read)."""
        return self.session.vocabulary_lines()

    def stop(self) -> None:
        """Stop the feed and the sources, then the runner (which journals the end). Idempotent."""
        if self.stopped:
            return
        self.stopped = True
        if self.feed is not None:
            self.feed.stop()
        for stopper in self._stoppers:
            stopper()
        self.mouse_pump.stop()
        self.runner.stop()
