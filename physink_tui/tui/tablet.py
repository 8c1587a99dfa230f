"""Finds the pen tablet for the TUI in the background and keeps it connected; no Textual, no decoding.

`TabletWatch` looks for the tablet ``--device`` names (or the first one found) every `SCAN_S` seconds until one
opens: a tablet plugged in after the TUI started is picked up. The device is announced to the session with a
``device`` entry (its descriptor, so the journal can decode its reports), then read through a
`ReconnectingSource` and a `SourcePump`: unplugging it ends the stroke being drawn and plugging it back carries
on. A serial tablet (``--serial PORT``) is read the same way, its samples mapped onto the canvas. What it finds is
said through ``on_status`` (the status bar); reading, decoding and gestures are the input side's and the session's.
"""

from __future__ import annotations

import threading
from collections.abc import Callable

from physink_tui.errors import DeviceError
from physink_tui.formats.journal.entries import DeviceEntry, JournalDevice, JournalEntry
from physink_tui.input.pen.mapping import TabletMapping
from physink_tui.input.reconnecting import ReconnectingSource
from physink_tui.input.sources import PenSource, SourceEnded
from physink_tui.session.source_pump import SourcePump

SCAN_S = 2.0
"""Seconds between looks for a tablet while none is open."""
DEVICE_ID = "usb0"
"""The journal's id of the live HID tablet."""


class TabletWatch:
    """Looks for a tablet on a thread and pumps it into ``submit``.

    Args:
        submit: the runner's submit.
        on_status: called with a short status text (any thread).
        spec: ``--device`` (``auto``, a hidraw path, VID:PID) or None for auto.
        serial: ``--serial PORT``, read instead of a HID tablet.
        mapping: the session's tablet-to-canvas mapping (serial samples are in tablet space).
        opener: opens a reader for a spec (tests pass a fake); default `open_reader`.
    """

    def __init__(self, submit: Callable[[JournalEntry], object], on_status: Callable[[str], object], *,
                 spec: str | None = None, serial: str | None = None, mapping: TabletMapping | None = None,
                 opener: Callable[[str | None, str], PenSource] | None = None, scan_s: float = SCAN_S) -> None:
        self._submit = submit
        self._status = on_status
        self._spec = spec
        self._serial = serial
        self._mapping = mapping or TabletMapping()
        self._opener = opener
        self._scan_s = scan_s
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self.pump: SourcePump | None = None
        self.status = ""

    def start(self) -> None:
        self._thread = threading.Thread(target=self._run, name="tablet-watch", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        self._stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=5)
        if self.pump is not None:
            self.pump.stop()

    def _say(self, text: str) -> None:
        self.status = text
        self._status(text)

    def _open(self, spec: str | None) -> PenSource:
        if self._opener is not None:
            return self._opener(spec, DEVICE_ID)
        if self._serial is not None:
            from physink_tui.input.serial_tablets.reader import SerialPenSource

            source = SerialPenSource(self._serial, DEVICE_ID)
            source.open()
            return source
        from physink_tui.input.hid.readers import open_reader

        return open_reader(spec, DEVICE_ID)

    def _run(self) -> None:
        told = None
        while not self._stop.is_set():
            try:
                reader = self._open(self._spec)
            except DeviceError as exc:
                text = f"no tablet ({exc}); the mouse draws in the scene"
                if text != told:
                    self._say(text if len(text) < 100 else "no tablet found; the mouse draws in the scene")
                    told = text
                if self._stop.wait(self._scan_s):
                    return
                continue
            self._connect(reader)
            return

    def _connect(self, reader: PenSource) -> None:
        info = getattr(reader, "info", None)
        device: JournalDevice | None = None
        name = self._serial or "tablet"
        if info is not None and getattr(info, "descriptor", None):
            name = info.name or info.path
            device = JournalDevice(DEVICE_ID, info.name or None, info.bus, info.vid, info.pid, info.descriptor)
            self._submit(DeviceEntry(0.0, (device,)))
        respec = f"{info.vid:04x}:{info.pid:04x}" if info is not None and info.vid else self._spec

        def reopen() -> PenSource:
            return self._open(respec)

        source = ReconnectingSource(reopen, DEVICE_ID, inner=reader,
                                    on_retry=lambda exc: self._say(f"tablet {name} unplugged; plug it back in"))
        def submit(entry: JournalEntry) -> object:
            if isinstance(entry, DeviceEntry) and self.status != f"tablet: {name}":
                self._say(f"tablet: {name}")  # announced again: it is back
            return self._submit(entry)

        self.pump = SourcePump(source, submit, device=device,
                               mapping=self._mapping if device is None else None, on_ended=self._ended(name))
        self.pump.start()
        self._say(f"tablet: {name}")

    def _ended(self, name: str) -> Callable[[SourceEnded], None]:
        def ended(item: SourceEnded) -> None:
            if item.error is not None:
                self._say(f"tablet {name} lost ({item.error}); the stroke ended, plug it back in")
            elif not self._stop.is_set():
                self._say(f"tablet {name} ended")
        return ended
