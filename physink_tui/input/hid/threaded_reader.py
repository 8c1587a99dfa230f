"""The thread every raw HID reader shares (start, stop, one `SourceEnded` last); no device, no decoding.

`readers` (hidraw, hidapi) and `usb_reader` (pyusb) subclass `ThreadedReader` and supply the device side.
"""

from __future__ import annotations

import queue
import threading
import time

from physink_tui.errors import DeviceError
from physink_tui.input.hid.hidraw import HidrawInfo
from physink_tui.input.sources import SourceEnded, SourceItem

POLL_TIMEOUT_S = 0.1
"""Longest wait in one poll/read; bounds how late a reader notices `stop` when it has no wake-up pipe."""


class ThreadedReader:
    """What every reader shares: one thread running ``_read_loop``, and the end-of-source bookkeeping.

    Subclasses open their device in ``__init__`` and implement ``_read_loop`` (return None when stopped, the
    DeviceError that ended it otherwise), ``_release_device`` and, when they block on a file descriptor, ``_wake``.
    """

    kind = "reader"

    def __init__(self, device_id: str, what: str, info: HidrawInfo | None) -> None:
        self.device_id = device_id
        self.what = what  # "hidraw /dev/hidraw3 (HUION Tablet)", for messages
        self.info = info
        self._stopping = threading.Event()
        self._thread: threading.Thread | None = None
        self._lock = threading.Lock()  # guards _released and the handles _release_device closes
        self._released = False

    def start(self, out: queue.Queue[SourceItem]) -> None:
        """Begin reading on a thread of its own; return at once."""
        if self._thread is not None or self._released:
            raise RuntimeError(f"{self.what}: a reader starts once")
        self._thread = threading.Thread(target=self._run, args=(out,), name=f"{self.kind}-{self.device_id}",
                                        daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Ask the thread to end, wait for it, and release the device (idempotent)."""
        self._stopping.set()
        self._wake()
        thread = self._thread
        if thread is not None and thread is not threading.current_thread():
            thread.join()
        self._release()

    @property
    def running(self) -> bool:
        """Whether the reading thread is alive."""
        return self._thread is not None and self._thread.is_alive()

    def _run(self, out: queue.Queue[SourceItem]) -> None:
        error: DeviceError | None
        try:
            error = self._read_loop(out)
        except Exception as exc:  # a reader never raises into its consumer: the end says why
            error = DeviceError(f"{self.what}: reading stopped on an unexpected error: {exc!r}")
        if self._stopping.is_set():
            error = None
        self._release()
        out.put(SourceEnded(time.monotonic(), self.device_id, error))

    def _release(self) -> None:
        with self._lock:
            if self._released:
                return
            self._released = True
            self._release_device()

    def _read_loop(self, out: queue.Queue[SourceItem]) -> DeviceError | None:
        raise NotImplementedError

    def _wake(self) -> None:
        """Interrupt a blocking wait (readers with a wake-up pipe)."""

    def _release_device(self) -> None:
        raise NotImplementedError
