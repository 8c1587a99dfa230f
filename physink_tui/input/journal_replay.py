"""Runs a journal's inputs through the input side: its HID and pen lines to gestures; no scene.

The header gives each device's descriptor (``device`` lines those plugged in later), the tablet-to-canvas
mapping and the tip thresholds, so the replay decodes exactly as the session did; `entry_line` lists commands
and utterances with their times. Acting on the entries is the session's job.
"""

from __future__ import annotations

import os
from typing import Any, TypeVar

from physink_tui.errors import DescriptorError, JournalError
from physink_tui.formats.journal.entries import (
    CommandEntry,
    DeviceEntry,
    HidEntry,
    JournalDevice,
    JournalEntry,
    JournalHeader,
    PenEntry,
    SayEntry,
)
from physink_tui.formats.journal.reader import iter_journal
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.pen.gestures import Gesture, GestureConfig
from physink_tui.input.pen.mapping import TabletMapping, mapping_from_header
from physink_tui.input.pen.pen_input import PenInput
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.pen.state import TipThresholds
from physink_tui.input.sources import RawReport, SourceEnded, SourceItem

P = TypeVar("P", bound=PenInput)

PEN_DEVICE = "pen"
"""The device id of journal ``pen`` lines (canvas samples from the mouse, serial tablets, scripts)."""


class LoggedPenInput(PenInput):
    """A `PenInput` that also keeps every gesture it returns in `log`: a replay lists the gestures of the session's
    own decoding instead of decoding the journal a second time."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.log: list[Gesture] = []

    def handle(self, item: SourceItem) -> list[Gesture]:
        gestures = super().handle(item)
        self.log += gestures
        return gestures

    def feed_canvas_sample(self, device_id: str, sample: PenSample) -> list[Gesture]:
        gestures = super().feed_canvas_sample(device_id, sample)
        self.log += gestures
        return gestures

    def tick(self, t: float) -> list[Gesture]:
        gestures = super().tick(t)
        self.log += gestures
        return gestures


def pen_input_for(header: JournalHeader, where: str = "journal") -> PenInput:
    """The input side a journal header describes: its devices' decoders, its mapping and tip thresholds, and
    the canvas-space device of its ``pen`` lines (`logged_pen_input_for`: one that keeps its gestures).

    Mapping keys the header leaves out take the identity: the canvas size is the header's, the tablet's
    proportions are the canvas's and the whole area is used, so tablet (x, y) in 0..1 lands on canvas (x, y).

    Raises:
        JournalError: ``<where>: line 1: ...`` for a mapping that leaves no usable area or a device whose
            descriptor cannot be decoded (naming the device id).
    """
    return _with_devices(PenInput(*_mapping_and_config(header, where)), header, where)


def logged_pen_input_for(header: JournalHeader, where: str = "journal") -> LoggedPenInput:
    """`pen_input_for`, keeping every gesture it returns (`LoggedPenInput`)."""
    return _with_devices(LoggedPenInput(*_mapping_and_config(header, where)), header, where)


def _mapping_and_config(header: JournalHeader, where: str) -> tuple[TabletMapping, GestureConfig]:
    defaults = {"canvas_width": header.canvas_width, "canvas_height": header.canvas_height}
    defaults |= {"tablet_width": header.canvas_width, "tablet_height": header.canvas_height}
    try:
        mapping = mapping_from_header({**defaults, **header.mapping})
        mapping.to_canvas(0.5, 0.5)  # proportions too extreme for floats leave a zero-sized area
    except ValueError as exc:
        raise JournalError(f'{where}: line 1: key "mapping": {exc}') from None
    except ArithmeticError:
        raise JournalError(f'{where}: line 1: key "mapping": expected canvas and tablet proportions that leave a '
                           f'usable area, got canvas {header.canvas_width!r} x {header.canvas_height!r}') from None
    config = GestureConfig(thresholds=TipThresholds(down=header.tip_down, up=header.tip_up))
    return mapping, config


def _with_devices(pen: P, header: JournalHeader, where: str) -> P:
    for device in header.devices:
        add_journal_device(pen, device, f"{where}: line 1")
    pen.add_sample_device(PEN_DEVICE, canvas_space=True)
    return pen


def add_journal_device(pen: PenInput, device: JournalDevice, where: str) -> None:
    """Add a journal device's decoder to ``pen``; a descriptor that cannot be decoded is a `JournalError`
    naming ``where`` (file and line) and the device id."""
    try:
        decoder = HidPenDecoder(device.descriptor, device.vid, device.pid, name=device.name or None)
    except DescriptorError as exc:
        raise JournalError(f"{where}: device {device.id!r}: {exc}") from None
    pen.add_hid_device(device.id, decoder)


def entry_line(entry: JournalEntry) -> str | None:
    """A command's, utterance's or device line's row in the replay's listing (time first), else None."""
    if isinstance(entry, CommandEntry):
        args = " ".join(str(a) for a in entry.args)
        return f"{entry.t:9.3f}  command       {entry.name} {args}".rstrip()
    if isinstance(entry, SayEntry):
        return f"{entry.t:9.3f}  said          {entry.text!r}"
    if isinstance(entry, DeviceEntry):
        return f"{entry.t:9.3f}  device        {', '.join(d.id for d in entry.devices)} appeared"
    return None


def decoder_notes(pen: PenInput) -> list[str]:
    """Reports read and samples decoded per HID device, for a replay's summary."""
    return [f"{device_id}: {d.decoder.stats.reports} reports, {d.decoder.stats.samples} pen samples"
            for device_id, d in pen.devices.items() if d.decoder is not None]


def replay_journal_input(path: str | os.PathLike[str]) -> tuple[list[Gesture], list[str], list[str]]:
    """Gestures of a journal, one line per command or utterance (time first), and notes."""
    with iter_journal(path) as reader:
        header = reader.header
        pen = pen_input_for(header, str(path))
        gestures: list[Gesture] = []
        events: list[str] = []
        last_t = 0.0
        for entry in reader:
            last_t = entry.t
            if isinstance(entry, HidEntry):
                gestures += pen.handle(RawReport(entry.t, entry.data, entry.dev))
            elif isinstance(entry, PenEntry):
                sample = PenSample(entry.t, entry.x, entry.y, entry.p, entry.tip, entry.range, entry.eraser,
                                   entry.b1, entry.b2, None, None, 0)
                gestures += pen.feed_canvas_sample(PEN_DEVICE, sample)
            elif isinstance(entry, DeviceEntry):
                for device in entry.devices:
                    if device.id in pen.devices:  # a reconnected device: its gesture so far ends here
                        gestures += pen.handle(SourceEnded(entry.t, device.id, None))
                    add_journal_device(pen, device, f"{reader.path}: line {reader.line}")
            if (line := entry_line(entry)) is not None:
                events.append(line)
    for device_id in list(pen.devices):
        gestures += pen.handle(SourceEnded(last_t, device_id, None))
    notes = list(reader.warnings)
    if reader.truncated is not None:
        notes.append(f"line {reader.truncated} is incomplete (the writer stopped mid-line); read up to it")
    return gestures, events, notes + decoder_notes(pen)
