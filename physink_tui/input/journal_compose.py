"""Builds session journals from captures and scripted entries (how tests and tools make sessions).

A capture made with the virtual pen (or recorded from a real tablet) becomes a journal whose header
names the device and the mapping, with one ``hid`` line per report; extra entries (commands, speech,
mouse ``pen`` lines) are merged in by time. Writing goes through `JournalWriter`, so every journal
made here obeys the same rules as one a live session writes.
"""

from __future__ import annotations

import os
from collections.abc import Iterable

from physink_tui.formats.journal.entries import HidEntry, JournalDevice, JournalEntry, JournalHeader
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.input.captures.capture import Capture
from physink_tui.input.pen.mapping import TabletMapping, mapping_to_header
from physink_tui.input.pen.state import TipThresholds


def header_for_capture(capture: Capture, mapping: TabletMapping | None = None,
                       thresholds: TipThresholds | None = None) -> JournalHeader:
    """A header with one device ``tablet<N>`` per capture device."""
    mapping = mapping or TabletMapping()
    thresholds = thresholds or TipThresholds()
    devices = tuple(
        JournalDevice(f"tablet{d.index}", d.name, d.bus, d.vid, d.pid, d.descriptor) for d in capture.devices
    )
    return JournalHeader(mapping.canvas_width, mapping.canvas_height, devices, mapping_to_header(mapping),
                         thresholds.down, thresholds.up)


def capture_entries(capture: Capture, t0: float = 0.0) -> list[HidEntry]:
    """One ``hid`` entry per capture event, at ``t0`` plus the event's time."""
    return [HidEntry(t0 + e.t, f"tablet{e.device}", e.data) for e in capture.events]


def write_journal(path: str | os.PathLike[str], header: JournalHeader, *streams: Iterable[JournalEntry]) -> None:
    """Write a journal of the entries of all ``streams``, merged by time (stable within a stream)."""
    entries = sorted((e for stream in streams for e in stream), key=lambda e: e.t)
    with JournalWriter.create(path, header) as writer:
        for entry in entries:
            writer.append(entry)
