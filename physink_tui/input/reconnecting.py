"""Reopens a pen source after its device is unplugged and plugged back; opens and reads nothing itself.

The consumer sees the inner reader's items with this source's id. When the inner reader ends with an error (the
tablet was unplugged) that `SourceEnded` is passed on at once, so a stroke in progress ends cleanly; then
``open_fn`` is retried every ``retry_s`` until the device is back, and a fresh inner reader carries on. So from
this source, unlike a plain reader, a `SourceEnded` with an error is not the last item: only the final
``SourceEnded(error=None)``, put after `stop` (or when the inner source ends cleanly, e.g. a replay's end), is.
"""

from __future__ import annotations

import queue
import threading
import time
from collections.abc import Callable
from dataclasses import replace

from physink_tui.errors import DeviceError
from physink_tui.input.sources import PenSource, SourceEnded, SourceItem


class ReconnectingSource:
    """A `PenSource` that survives its device going away and coming back.

    Args:
        open_fn: opens a fresh inner source (not started); raises `DeviceError` while the device is absent.
        device_id: the id put on every item passed on.
        retry_s: seconds between attempts to reopen.
        inner: an inner source already opened by the caller (so a wrong device fails at once, before any
            thread); None opens with ``open_fn`` from the start, waiting for the device if it is not there yet.
        on_retry: called with each `DeviceError` from ``open_fn`` (for a status line); never required.
    """

    def __init__(self, open_fn: Callable[[], PenSource], device_id: str = "tablet0", retry_s: float = 0.5,
                 inner: PenSource | None = None,
                 on_retry: Callable[[DeviceError], None] | None = None) -> None:
        self.device_id = device_id
        self._open_fn = open_fn
        self._retry_s = retry_s
        self._on_retry = on_retry
        self._inner = inner
        self._stopping = threading.Event()
        self._lock = threading.Lock()  # guards _inner between the supervisor and stop()
        self._thread: threading.Thread | None = None
        self.reconnects = 0
        """How many times a fresh inner source was opened after the first."""

    def start(self, out: queue.Queue[SourceItem]) -> None:
        """Begin on a supervising thread; return at once."""
        if self._thread is not None:
            raise RuntimeError(f"source {self.device_id!r} starts once")
        self._thread = threading.Thread(target=self._supervise, args=(out,), name=f"reconnect-{self.device_id}",
                                        daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Stop the inner source and the retries, wait for the thread (idempotent)."""
        self._stopping.set()
        with self._lock:
            inner = self._inner
        if inner is not None:
            inner.stop()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join()

    @property
    def running(self) -> bool:
        """Whether the supervising thread is alive."""
        return self._thread is not None and self._thread.is_alive()

    def _supervise(self, out: queue.Queue[SourceItem]) -> None:
        items: queue.Queue[SourceItem] = queue.Queue()
        error: DeviceError | None = None
        opened = 0
        try:
            while True:
                inner = self._take_inner()
                if inner is None:  # stopping
                    break
                opened += 1
                self.reconnects = opened - 1
                ended = self._pump(inner, items, out)
                if ended.error is None or self._stopping.is_set():
                    break
                out.put(replace(ended, device=self.device_id))
        except Exception as exc:  # never raise into the consumer: end with why
            error = DeviceError(f"{self.device_id}: reconnecting stopped on an unexpected error: {exc!r}")
        finally:
            with self._lock:
                inner, self._inner = self._inner, None
            if inner is not None:
                inner.stop()
        out.put(SourceEnded(time.monotonic(), self.device_id, error))

    def _take_inner(self) -> PenSource | None:
        """The inner source to run next: the one given, else opened with retries; None once stopping."""
        with self._lock:
            inner = self._inner
        while inner is None:
            if self._stopping.is_set():
                return None
            try:
                inner = self._open_fn()
            except DeviceError as exc:
                if self._on_retry is not None:
                    self._on_retry(exc)
                if self._stopping.wait(self._retry_s):
                    return None
        with self._lock:
            if self._stopping.is_set():
                self._inner = None
                inner.stop()
                return None
            self._inner = inner
        return inner

    def _pump(self, inner: PenSource, items: queue.Queue[SourceItem], out: queue.Queue[SourceItem]) -> SourceEnded:
        """Runs one inner source, passing its items on, until its SourceEnded (returned, not passed on)."""
        with self._lock:  # stop() either sees this inner started, or we see it stopping
            if self._stopping.is_set():
                return SourceEnded(time.monotonic(), self.device_id, None)
            inner.start(items)
        relabel = inner.device_id != self.device_id
        while True:
            item = items.get()
            if isinstance(item, SourceEnded):
                with self._lock:
                    self._inner = None
                inner.stop()  # releases the device, joins its thread (it has ended already)
                return item
            out.put(replace(item, device=self.device_id) if relabel else item)
