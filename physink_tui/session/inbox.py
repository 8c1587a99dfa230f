"""Stamps inputs with the session clock as they arrive, from any thread, and queues them in order; handles nothing.

The one lock here is what makes the runner's promise hold: an entry is stamped and queued in one step, and the
worker reads "now" and takes the queue in one step, so once the worker has read a time, every entry stamped at
or before it is in its hands. Stamps never decrease and are never changed afterwards.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from dataclasses import replace
from typing import Any, ClassVar, Generic, Protocol, TypeVar


class Stamped(Protocol):
    """An input the inbox can stamp: a frozen dataclass with a time ``t`` (a journal entry, a driver's search)."""

    __dataclass_fields__: ClassVar[dict[str, Any]]

    @property
    def t(self) -> float: ...


E = TypeVar("E", bound=Stamped)


class StampingInbox(Generic[E]):
    """A thread-safe queue of inputs (journal entries) stamped with seconds since the session start.

    Args:
        clock: seconds on a monotonic clock (``time.monotonic``; tests pass a fake one).
        start_t: the session time at the moment of construction (the session's ``t``: 0 for a new session), so
            the first stamps continue from it.
    """

    def __init__(self, clock: Callable[[], float], start_t: float = 0.0) -> None:
        self._clock = clock
        self._origin = clock() - start_t
        self._last = start_t
        self._entries: list[E] = []
        self._closed_at: float | None = None
        self.submitted = 0
        """Entries queued so far (read without the lock: it only grows)."""
        self._lock = threading.Lock()
        self._arrived = threading.Condition(self._lock)
        """Notified whenever an entry is queued or the inbox closes (the worker waits on it)."""

    def _now(self) -> float:
        """Seconds since the session start, never less than a time already handed out and never past the time the
        inbox closed (the clock stops there); call with the lock held."""
        if self._closed_at is None:
            self._last = max(self._last, self._clock() - self._origin)
        return self._last

    def now(self) -> float:
        """Seconds since the session start, by the clock."""
        with self._lock:
            return self._now()

    def put(self, entry: E, at: float | None = None) -> E | None:
        """Stamp ``entry`` with the time now and queue it; return the stamped entry, or None once closed (dropped:
        it will never be handled nor journaled).

        ``at`` (seconds since the session start) stamps it earlier — an utterance with the time it began — but
        never before a time already handed out, so stamps still never decrease.
        """
        with self._lock:
            if self._closed_at is not None:
                return None
            stamped = replace(entry, t=self._now() if at is None else max(self._last, min(at, self._now())))
            self._last = stamped.t
            self._entries.append(stamped)
            self.submitted += 1
            self._arrived.notify()
            return stamped

    def take(self) -> tuple[float, list[E]]:
        """The time now and every entry queued so far (all stamped at or before it), in arrival order."""
        with self._lock:
            now = self._now()
            entries, self._entries = self._entries, []
            return now, entries

    def close(self) -> float:
        """Refuse entries from now on and stop the clock; return the time it closed (the same on every call).

        The entries queued before are still there for `take`.
        """
        with self._lock:
            if self._closed_at is None:
                self._closed_at = self._now()
                self._arrived.notify_all()
            return self._closed_at

    @property
    def closed(self) -> bool:
        with self._lock:
            return self._closed_at is not None

    def wait(self, timeout: float) -> None:
        """Block until an entry is queued, the inbox closes, or ``timeout`` real seconds pass (whichever first)."""
        with self._lock:
            if not self._entries and self._closed_at is None and timeout > 0:
                self._arrived.wait(timeout)
