"""Runs a session live on one worker thread (the only place with threads); decides nothing, reads no device.

Inputs come in from any thread, time passes at a fixed rate, views go out; the session decides what the inputs
mean and the sources read the devices.

Sources (tablet readers through `source_pump`, the mouse, keys, speech) call `SessionRunner.submit` from their
own threads. Each entry is stamped with the runner's clock when it arrives (seconds since the session start)
and never restamped. The worker is the session's only caller: it hands the queued entries to
``session.handle`` in arrival order, moves time on with ``session.advance(now)`` at a fixed rate, never past an
entry it has not handled (see `inbox`), and publishes ``session.view()`` to subscribers at most `MAX_FPS` times a
second (a view showing a command's effect goes out at once, outside that rate: keys are answered without waiting
for the next frame). The session journals every entry it handled (commands it refused included; an entry a journal
cannot hold is refused before it acts and is not journaled); `SessionRunner.stop` ends the session with
``session.finish(now)``, which journals the end, so a replay runs the physics exactly as long.

A replay needs none of this: it calls ``handle`` for each journal entry and ``finish`` at the end's time.

An exception from the session (or a subscriber) is a bug. The worker records it, tells ``on_error``, refuses
later input, calls ``finish`` once (so the journal is closed with what was handled) and ends; `stop` raises the
exception again in the thread that called it.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable
from typing import Generic, Protocol, TypeVar

from physink_tui.formats.journal.entries import CommandEntry, SayEntry
from physink_tui.session.inbox import StampingInbox
from physink_tui.session.simulation import SessionInput

TICK_RATE = 120.0
"""Default times a second the worker moves the session's time on (``session.advance`` calls)."""

MAX_FPS = 30.0
"""Default ceiling on views published a second."""

ViewT = TypeVar("ViewT")
ViewT_co = TypeVar("ViewT_co", covariant=True)


class RunnableSession(Protocol[ViewT_co]):
    """What the runner needs of a session (`physink_tui.session.session.Session` after issue 12)."""

    @property
    def t(self) -> float:
        """Seconds since the session start reached so far."""

    def handle(self, entry: SessionInput) -> None:
        """Consume one entry (time first moves to ``entry.t``); never raises for any input."""

    def advance(self, t: float) -> None:
        """Let time pass to ``t``; nothing when ``t <= self.t``."""

    def view(self) -> ViewT_co:
        """An immutable snapshot for the views."""

    def finish(self, t: float | None = None) -> None:
        """End the session at ``t``: journal the end, close the journal."""


class SessionRunner(Generic[ViewT]):
    """Drives one session from a worker thread. `start`, then `submit` from anywhere, then `stop`.

    Args:
        session: the session to drive; from `start` to `stop` nobody else may call it.
        clock: seconds on a monotonic clock (tests pass a fake one they move by hand).
        tick_rate: `advance` calls a second (> 0).
        max_fps: views published a second at most (> 0).
        on_error: called on the worker thread with an exception the session (or a subscriber) raised.

    Without `start` nothing runs by itself: a caller (a test, a driver with its own loop) calls `step` instead,
    and `stop` finishes the session on the calling thread.
    """

    def __init__(self, session: RunnableSession[ViewT], *, clock: Callable[[], float] = time.monotonic,
                 tick_rate: float = TICK_RATE, max_fps: float = MAX_FPS,
                 on_error: Callable[[BaseException], object] | None = None) -> None:
        if not tick_rate > 0 or not max_fps > 0:
            raise ValueError(f"tick_rate and max_fps must be > 0, got {tick_rate!r} and {max_fps!r}")
        self.session = session
        self.tick_rate = tick_rate
        self.max_fps = max_fps
        self._inbox: StampingInbox[SessionInput] = StampingInbox(clock, session.t)
        self._on_error = on_error
        self._subscribers: list[Callable[[ViewT], None]] = []
        self._latest: ViewT | None = None
        self._view_lock = threading.Lock()  # guards _latest and _subscribers
        self._last_tick = -1  # the index of the last tick that advanced the session (tick k is at k / tick_rate)
        self._published_at = -math.inf  # session time of the last view published
        self._unpublished = True  # the session changed since the last view published
        self._thread: threading.Thread | None = None
        self._finished = False
        self._handled = 0  # entries handled, their view published (`wait_handled`)
        self._handled_changed = threading.Condition()
        self.error: BaseException | None = None
        """The exception that stopped the worker, or None."""

    # -- any thread ------------------------------------------------------------------------------

    def submit(self, entry: SessionInput) -> SessionInput | None:
        """Queue an input, stamped with the time now (its own ``t`` is ignored); return the stamped entry.

        Returns None once `stop` has begun: the entry is dropped, so it is neither handled nor journaled.
        """
        return self._inbox.put(entry)

    def command(self, name: str, *args: str | float) -> SessionInput | None:
        """Submit a command (a key, a pad button): ``runner.command("mode", "demo")``."""
        return self.submit(CommandEntry(0.0, name, tuple(args)))

    def say(self, text: str, began: float | None = None) -> SessionInput | None:
        """Submit a recognised utterance, stamped with ``began`` (session seconds: when it began, e.g.
        `Utterance.began` on the runner's `now` scale) where no later entry has been stamped yet, else when it
        arrives; without ``began``, when it arrives."""
        return self._inbox.put(SayEntry(0.0, text), began)

    def now(self) -> float:
        """Seconds since the session start by the runner's clock (what an entry submitted now is stamped)."""
        return self._inbox.now()

    def subscribe(self, callback: Callable[[ViewT], None]) -> None:
        """Call ``callback(view)`` on the worker thread with every view published (hand it on to the UI thread,
        e.g. with Textual's ``call_from_thread``; do not block in it)."""
        with self._view_lock:
            self._subscribers.append(callback)

    def wait_handled(self, timeout: float) -> bool:
        """Block until every entry submitted so far has been handled and a view showing it published (a driver that
        reads `latest_view` to decide its next input: the kiosk's mode button); False after ``timeout`` seconds,
        or at once when the worker is not running."""
        target = self._inbox.submitted
        with self._handled_changed:
            return self._handled_changed.wait_for(
                lambda: self._handled >= target or not self.running or self._finished, timeout)

    def latest_view(self) -> ViewT | None:
        """The last view published, or None before the first."""
        with self._view_lock:
            return self._latest

    def start(self) -> None:
        """Start the worker thread; return at once."""
        if self._thread is not None or self._inbox.closed:
            raise RuntimeError("a SessionRunner starts once, before stop")
        self._thread = threading.Thread(target=self._work, name="session-runner", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """End the session: handle what was submitted before now, ``finish(now)``, publish the last view, join.

        Call it after stopping the sources (what they submit later is dropped). Idempotent.

        Raises:
            Exception: what the session (or a subscriber) raised on the worker, if it did (also in `error`).
        """
        self._inbox.close()
        if self._thread is None:
            self._finish()
        elif self._thread is not threading.current_thread():
            self._thread.join()
        if self.error is not None:
            raise self.error

    @property
    def running(self) -> bool:
        """Whether the worker thread is alive."""
        return self._thread is not None and self._thread.is_alive()

    # -- the worker ------------------------------------------------------------------------------

    def step(self) -> None:
        """One pass of the worker: handle what arrived, advance if a tick is due, publish if a view is due.

        The worker calls it; call it yourself only when the runner was not started.
        """
        if self._thread is not None and self._thread is not threading.current_thread():
            raise RuntimeError("the runner's worker thread is the session's only caller")
        if self.error is not None or self._finished:
            return
        now, entries = self._inbox.take()
        try:
            self._handle(entries)
            tick = math.floor(now * self.tick_rate)
            if tick > self._last_tick:
                self._last_tick = tick
                self.session.advance(now)
                self._unpublished = True
            command = any(isinstance(e, CommandEntry) for e in entries)  # a key's reaction waits for no frame slot
            if self._unpublished and (command or now - self._published_at >= 1.0 / self.max_fps):
                self._publish(now)
        except Exception as exc:
            self._fail(exc)
        if entries:
            with self._handled_changed:
                self._handled += len(entries)
                self._handled_changed.notify_all()

    def _handle(self, entries: list[SessionInput]) -> None:
        for entry in entries:
            self.session.handle(entry)
        if entries:
            self._unpublished = True

    def _publish(self, now: float) -> None:
        view = self.session.view()
        with self._view_lock:
            self._latest = view
            subscribers = list(self._subscribers)
        self._published_at = now
        self._unpublished = False
        for callback in subscribers:
            callback(view)

    def _fail(self, exc: BaseException) -> None:
        self.error = exc
        self._inbox.close()
        if self._on_error is not None:
            try:
                self._on_error(exc)
            except Exception as inner:  # the first error is the one to report
                exc.add_note(f"on_error raised too: {inner!r}")

    def _finish(self) -> None:
        """The end: the entries stamped before the inbox closed, ``finish`` at the time it closed and the last
        view; after an error only ``finish``. Closes the inbox if it is not yet."""
        if self._finished:
            return
        self._finished = True
        end_t = self._inbox.close()
        _, entries = self._inbox.take()
        if self.error is not None:
            try:
                self.session.finish(end_t)
            except Exception as exc:
                self.error.add_note(f"session.finish({end_t!r}) after the error raised too: {exc!r}")
            return
        try:
            self._handle(entries)
            self.session.finish(end_t)
            self._publish(end_t)
        except Exception as exc:
            self._fail(exc)
        with self._handled_changed:
            self._handled_changed.notify_all()  # a waiter sees the runner finished

    def _next_due(self) -> float:
        """Session time at which `step` next has something to do without new input."""
        due = (self._last_tick + 1) / self.tick_rate
        if self._unpublished:
            due = min(due, self._published_at + 1.0 / self.max_fps)
        return due

    def _work(self) -> None:
        inbox = self._inbox
        while not inbox.closed:
            self.step()
            if self.error is not None:
                break
            inbox.wait(self._next_due() - inbox.now())
        self._finish()

