"""The kiosk's loop: one tablet, one session at a time, each journaled from its first touch and finalised when it
ends; no UI, no decisions about what the pen drew (the session's), no files of its own (finalise's and store's).

Threads: the tablet's source thread hands every report to `Kiosk._entry` (through a `SourcePump`), which decides
with the hot zones (`ControlFilter`) whether it goes to the session, is held back or presses a button, and starts
a session on the first touch; each session runs on its `SessionRunner`'s worker, journaling every entry it handles
(flushed at once, so a kill loses at most the entries still queued for the next tick); the main thread (`run`)
watches for the end of a session (its hot zone, ``--idle`` seconds of input time without a report, the replayed
capture's end, SIGTERM) and a finaliser thread has a child process write the ended sessions' outputs from their
journals, in order, at a lower priority, while the next session records.

Status goes to ``log`` as plain lines (journald-friendly).
"""

from __future__ import annotations

import json
import queue
import subprocess
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from datetime import UTC, datetime
from pathlib import Path

from physink_tui.errors import JournalError, PhysinkError
from physink_tui.formats.journal.entries import (
    CommandEntry,
    HidEntry,
    JournalDevice,
    JournalEntry,
    JournalHeader,
    PenEntry,
)
from physink_tui.formats.journal.reader import read_journal
from physink_tui.input.pen.mapping import TabletMapping
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.pen.state import TipThresholds
from physink_tui.input.sources import PenSource, SourceEnded
from physink_tui.input.speech.listener import Utterance
from physink_tui.kiosk.controls import PASS, PRESS, ControlFilter
from physink_tui.kiosk.finalise import Ending, child_command, finalise_journal
from physink_tui.kiosk.folder_files import JOURNAL, SUMMARY
from physink_tui.kiosk.hot_zones import HotZones
from physink_tui.kiosk.store import SessionStore
from physink_tui.render.export import Look
from physink_tui.session.journaled import Journaled
from physink_tui.session.modes.base import ModeName
from physink_tui.session.source_pump import SourcePump

MIN_FREE_BYTES = 50_000_000
"""A session starts only with this much free space in the output folder (a session's video is a few MB)."""
POLL_S = 0.05
"""How often the main thread looks at the sessions' ends (seconds)."""
HANDLED_WAIT_S = 5.0
"""At most this long a mode press waits for the session to have handled the inputs before it (a tick or two)."""
VIDEO_LOOK = Look(960, 600, 30)
"""The sessions' videos: smaller than an export's, so finalising keeps up with visitors."""
ZONE_COMMANDS = {"undo": ("undo",), "redo": ("redo",), "clear": ("clear",), "play": ("play",), "stop": ("stop",),
                 "sketch": ("mode", "sketch"), "demo": ("mode", "demo")}


@dataclass(frozen=True, slots=True)
class KioskSettings:
    """``idle_s``: seconds without a report that end a session; ``keep`` / ``max_bytes``: retire the oldest
    finished sessions beyond these (None: keep all); ``look``: the videos' size and rate."""

    idle_s: float = 120.0
    keep: int | None = None
    max_bytes: int | None = None
    look: Look = VIDEO_LOOK


class _Live:
    """The session being recorded: its folder, journal, session and runner."""

    def __init__(self, folder: Path, header: JournalHeader, clock: Callable[[], float], start: float) -> None:
        self.folder = folder
        self.start = start  # the kiosk's clock when the session began
        self.ended_at: float | None = None  # session time its end was decided at (its clock stops there)
        self._kiosk_clock = clock
        journaled = Journaled.create(header, folder / JOURNAL, clock=self.clock)
        self.session, self.runner = journaled.session, journaled.runner
        assert journaled.writer is not None  # (given a path)
        self.writer = journaled.writer
        self.told_stopped = False
        self.runner.start()

    def clock(self) -> float:
        """Seconds since the session began by the kiosk's clock, standing still once its end is decided."""
        return self.ended_at if self.ended_at is not None else self._kiosk_clock() - self.start

    def end_now(self, at: float | None = None) -> None:
        """Stop the session's clock now (or at session time ``at``): what arrives later is not its input."""
        if self.ended_at is None:
            self.ended_at = self.clock() if at is None else at


class Kiosk:
    """The recording service over ``store`` (see the module docstring).

    Args:
        store: where sessions go.
        zones: the hot zones (their drawing area is in ``header``'s mapping already).
        settings: idle time, retiring, video look.
        log: where status lines go.
        stop: set it to end the run (what `stop` does), e.g. from a signal handler installed before the kiosk.
    """

    def __init__(self, store: SessionStore, zones: HotZones, settings: KioskSettings,
                 log: Callable[[str], None], stop: threading.Event | None = None) -> None:
        self.store = store
        self.zones = zones
        self.settings = settings
        self.log = log
        self._lock = threading.Lock()  # guards _live, _closing, _last_input
        self._live: _Live | None = None
        self._clock: Callable[[], float] = time.monotonic
        self._mapping: TabletMapping | None = None
        self._last_input = 0.0
        self._closing: list[tuple[_Live, str]] = []  # sessions their end button closed, for the main thread to stop
        self._source_ended = threading.Event()
        self._stop = stop or threading.Event()
        self._finishing: queue.Queue[tuple[Path, Ending] | None] = queue.Queue()
        self._finaliser = threading.Thread(target=self._finalise_queue, name="kiosk-finalise", daemon=True)
        self._full_disk_told = False
        self._replay = False
        self._capture_t = 0.0  # a replay's clock: the time of the capture's latest report
        self._touched = False  # a pen touched the drawing area (a session began, or would have with room)

    # -- recovery ---------------------------------------------------------------------------------------------------

    def recover(self) -> int:
        """Finalise every session a previous run left unfinished (from its journal); returns how many."""
        count = 0
        for folder in self.store.unfinished():
            try:
                journal = read_journal(folder / JOURNAL, salvage=True)
            except JournalError as exc:  # no header to replay it with: kept aside, not tried at every start
                try:
                    kept = self.store.set_aside(folder).name
                except OSError as error:
                    self.log(f"kiosk: cannot recover {folder.name}: {exc} (nor set it aside: {error.strerror})")
                    continue
                self.log(f"kiosk: cannot recover {folder.name}: {exc}; its journal is kept as {kept} and not tried "
                         "again")
                continue
            try:
                lost = f" (its last line was torn at line {journal.truncated})" if journal.truncated else ""
                lost += f"; {journal.dropped}" if journal.dropped is not None else ""
                self.log(f"kiosk: recovering unfinished session {folder.name}: {len(journal.entries)} inputs{lost}")
                summary = finalise_journal(folder, Ending("recovered", folder.name, recovered=True),
                                           self.settings.look)
            except PhysinkError as exc:
                self.log(f"kiosk: cannot recover {folder.name}: {exc}")
                continue
            self._indexed(folder, summary)
            count += 1
        return count

    # -- running ----------------------------------------------------------------------------------------------------

    def run(self, source: PenSource, device: JournalDevice | None, header: JournalHeader, *, replay: bool,
            clock: Callable[[], float] = time.monotonic, mapping: TabletMapping | None = None) -> int:
        """Record sessions from ``source`` until SIGTERM (`stop`) or, for a replay, the end of the capture.

        ``device`` is the HID tablet whose reports the source reads; None for a source of samples in tablet space
        (a serial tablet), which ``mapping`` maps onto the canvas after the hot zones had their look.

        A replay's clock is the capture's own (the time of its latest report; ``clock`` is not used), so the
        sessions it records are the same whatever pace the source plays it at: ``--speed`` changes only how long
        the replay takes. Returns 1 when the pen never touched during a replay (nothing was recorded).
        """
        self._finaliser.start()
        self._controls = ControlFilter(device, self.zones, TipThresholds(header.tip_down, header.tip_up))
        if replay:
            self.use_capture_clock()
            clock = self.capture_time
        self._header, self._clock, self._mapping = header, clock, mapping
        self._last_input = clock()
        pump = SourcePump(source, self._entry, device=None if replay else device, on_ended=self._ended,
                          keep_time=replay)
        what = "the capture" if replay else source.device_id if device is None else device.name or device.id
        self.log(f"kiosk: reading {what}; a session starts when the pen touches the tablet")
        pump.start()
        try:
            while not self._stop.is_set():
                self._stop.wait(POLL_S)
                self._watch()
                if replay and self._source_ended.is_set():
                    break
        finally:
            pump.stop()
            self._end("stopped" if self._stop.is_set() else "capture ended")
            self._finishing.put(None)
            self._finaliser.join()
        if replay and not self._touched and not self._stop.is_set():
            self.log("kiosk: the capture ended without a session: none of its reports is a pen touching the "
                     "tablet's drawing area (nothing was recorded)")
            return 1
        return 0

    def use_capture_clock(self) -> None:
        """From now on the kiosk's clock is a replayed capture's (`run` with ``replay`` does it; call it earlier so
        the listening thread starts on that clock too)."""
        self._replay = True
        self._clock = self.capture_time

    def capture_time(self) -> float:
        """A replay's clock: the capture time of its latest report."""
        return self._capture_t

    def clock(self) -> float:
        """The kiosk's clock (the capture's during a replay), for the listening thread."""
        return self._clock()

    def stop(self) -> None:
        """End the current session (finalised) and the run; safe from a signal handler."""
        self._stop.set()

    def _watch(self) -> None:
        with self._lock:
            live, closing, idle = self._live, self._closing, self._clock() - self._last_input
            self._closing = []
        for ended, why in closing:
            self._close(ended, why)
        if live is None:
            return
        if live.writer.stopped is not None and not live.told_stopped:
            live.told_stopped = True
            self.log(f"kiosk: recording stopped for session {live.folder.name}: {live.writer.stopped}")
        if idle > self.settings.idle_s:
            self._end("idle")

    def _end(self, why: str) -> None:
        """End the session being recorded, and any the end button closed meanwhile."""
        with self._lock:
            live, self._live, closing, self._closing = self._live, None, self._closing, []
        for ended, reason in closing:
            self._close(ended, reason)
        if live is not None:
            self._close(live, why)

    def _close(self, live: _Live, why: str) -> None:
        """Stop a session's runner (its journal gets its end) and queue it for finalising."""
        try:
            live.runner.stop()
        except Exception as exc:  # a bug in the session: its journal is closed; the recovery path finalises it
            self.log(f"kiosk: session {live.folder.name} failed: {exc!r}")
            return
        self.log(f"kiosk: session {live.folder.name} ended ({why}) after {live.session.t:.1f} s")
        self._finishing.put((live.folder, Ending(why, live.folder.name)))

    # -- the listening thread ---------------------------------------------------------------------------------------

    def hear(self, utterance: Utterance) -> None:
        """An utterance from the microphone (``began`` on the kiosk's clock): an accepted one is said to the session
        being recorded, stamped when it began, and counts as input (the visitor is still there); a rejected one
        changes nothing."""
        if utterance.command is None:
            self.log(f"kiosk: speech not understood ({utterance.rejected})")
            return
        with self._lock:
            live = self._live
            if live is not None:
                self._last_input = max(self._last_input, self._clock())
                live.runner.say(utterance.text, max(0.0, utterance.began - live.start))
        if live is None:
            self.log(f'kiosk: heard "{utterance.text}" with no session recording (it starts at the first touch)')
        else:
            self.log(f'kiosk: heard "{utterance.text}"')

    # -- the source thread ------------------------------------------------------------------------------------------

    def _entry(self, entry: JournalEntry) -> None:
        with self._lock:
            live = self._live
            if self._replay and isinstance(entry, HidEntry):
                self._capture_t = max(self._capture_t, entry.t)
                if live is not None and self._capture_t - self._last_input > self.settings.idle_s:
                    live.end_now(self._last_input - live.start + self.settings.idle_s)  # idle, in capture time
                    self._closing.append((live, "idle"))
                    self._live = live = None
            self._last_input = self._clock()
            if isinstance(entry, HidEntry):
                verdict = self._controls.report(entry.data, self._clock())
            elif isinstance(entry, PenEntry) and self._mapping is not None:  # a sample in tablet space
                verdict = self._controls.sample(PenSample(self._clock(), entry.x, entry.y, entry.p, entry.tip,
                                                          entry.range, entry.eraser, entry.b1, entry.b2, None, None, 0))
                x, y = self._mapping.to_canvas(entry.x, entry.y)
                entry = replace(entry, x=x, y=y)
            else:
                if live is not None:
                    live.runner.submit(entry)
                return
            if verdict.what == PRESS:
                actions = [(verdict.zone.action, "end zone")] if verdict.zone is not None else []
                actions += [(a, "end button") for b in verdict.pad if (a := self.zones.pad_action(b)) is not None]
                for action, ending in actions:
                    self._press(live, action, ending)
                return
            if verdict.what != PASS:
                return
            if live is None:
                if not verdict.touch_began:
                    return  # hovering before any session: nothing to record yet
                self._touched = True
                live = self._start()
                if live is None:
                    return
            live.runner.submit(entry)

    def _press(self, live: _Live | None, action: str, ending: str) -> None:
        if live is None:
            return  # a button before the first touch: there is no session to act on
        if action == "end":  # detached at once: what the tablet sends next belongs to the next session
            live.end_now()
            self._closing.append((live, ending))
            self._live = None
            return
        if action == "mode":  # the mode the session's view shows once it has handled what came before the press
            live.runner.wait_handled(HANDLED_WAIT_S)  # (a fast replay must not outrun it: the same at any speed)
            view = live.runner.latest_view()
            demonstrating = view is not None and view.mode == ModeName.DEMO
            action = ModeName.SKETCH if demonstrating else ModeName.DEMO
        command = ZONE_COMMANDS[action]
        live.runner.submit(CommandEntry(0.0, command[0], command[1:]))
        self.log(f"kiosk: {' '.join(command)}")

    def _start(self) -> _Live | None:
        """A new session (called with the lock held); None when there is no room to record."""
        free = self.store.free_bytes()
        if free < MIN_FREE_BYTES:
            if not self._full_disk_told:
                self._full_disk_told = True
                self.log(f"kiosk: not recording: only {free / 1e6:.0f} MB free in {self.store.root} "
                         f"(a session needs {MIN_FREE_BYTES / 1e6:.0f} MB; --keep or --max-disk retire old ones)")
            return None
        self._full_disk_told = False
        started = datetime.now(UTC)
        try:
            folder = self.store.new_folder(started)
            start = self._clock()
            self._live = _Live(folder, self._header, self._clock, start)
        except (OSError, JournalError) as exc:
            self.log(f"kiosk: cannot start a session in {self.store.root}: {exc}")
            return None
        self.log(f"kiosk: session {folder.name} started")
        return self._live

    def _ended(self, ended: SourceEnded) -> None:
        if ended.error is None:
            self._source_ended.set()
        else:
            self.log(f"kiosk: the tablet went away ({ended.error}); the session waits for it to come back")

    # -- the finaliser thread ---------------------------------------------------------------------------------------

    def _finalise_queue(self) -> None:
        while (item := self._finishing.get()) is not None:
            folder, ending = item
            child = subprocess.run(child_command(folder, ending, self.settings.look), capture_output=True, text=True,
                                   check=False)
            if child.returncode != 0:
                why = child.stderr.strip().splitlines()[-1] if child.stderr.strip() else f"status {child.returncode}"
                self.log(f"kiosk: could not finish writing session {folder.name}: {why} (it is finished when the "
                         "kiosk next starts)")
                continue
            self._indexed(folder, json.loads((folder / SUMMARY).read_text(encoding="utf-8")))
            # never the session just written (however small --max-disk is) nor the one being recorded
            self.store.retire(self.settings.keep, self.settings.max_bytes, (folder, self._current_folder()), self.log)

    def _current_folder(self) -> Path | None:
        with self._lock:
            return None if self._live is None else self._live.folder

    def _indexed(self, folder: Path, summary: dict[str, object]) -> None:
        self.store.index(summary)
        files = summary["files"]
        listed = ", ".join(map(str, files)) if isinstance(files, list) else str(files)
        self.log(f"kiosk: session {folder.name} written: {summary['bodies']} bodies, {summary['events']} events, "
                 f"{listed}")
