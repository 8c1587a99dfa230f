"""Source pumps: reports become hid entries, samples pen entries (mapped from tablet space when asked), a source's
end is not submitted but lifts a pen in range, and a returning device is announced before its first report."""

from __future__ import annotations

import queue

import pytest

from physink_tui.errors import DeviceError
from physink_tui.formats.journal.entries import DeviceEntry, HidEntry, JournalDevice, JournalEntry, PenEntry
from physink_tui.input.pen.mapping import TabletMapping
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.scripted_sources import ProgrammaticPenSource
from physink_tui.input.sources import RawReport, SampleReady, SourceEnded, SourceItem
from physink_tui.session.runner import SessionRunner
from physink_tui.session.source_pump import SourcePump

TABLET = JournalDevice("tablet0", "Test Tablet", 3, 0x256C, 0x006D, b"\x05\x0d\x09\x02\xa1\x01\xc0")


class HandFedSource:
    """A `PenSource` whose items the test puts, as a reader's thread would."""

    def __init__(self, device_id: str = "tablet0") -> None:
        self.device_id = device_id
        self.out: queue.Queue[SourceItem] | None = None
        self.stopped = False

    def start(self, out: queue.Queue[SourceItem]) -> None:
        self.out = out

    def stop(self) -> None:
        self.stopped = True


def sample(x: float, y: float, *, tip: bool = True, in_range: bool = True, p: float = 0.5) -> PenSample:
    return PenSample(7.0, x, y, p, tip, in_range, False, False, False, None, None, 0)


def pumped(**kwargs) -> tuple[HandFedSource, list[JournalEntry], SourcePump]:
    source, got = HandFedSource(), []
    pump = SourcePump(source, got.append, **kwargs)
    pump.start()
    return source, got, pump


def test_reports_become_hid_entries_and_the_end_is_not_submitted() -> None:
    ended = []
    source, got, pump = pumped(on_ended=ended.append)
    source.out.put(RawReport(123.0, b"\x02\x01", "tablet0"))
    source.out.put_nowait(RawReport(124.0, b"\x02\x00", "tablet0"))
    source.out.put(SourceEnded(125.0, "tablet0"))
    assert got == [HidEntry(0.0, "tablet0", b"\x02\x01"), HidEntry(0.0, "tablet0", b"\x02\x00")]
    assert ended == [SourceEnded(125.0, "tablet0")]
    pump.stop()
    assert source.stopped


def test_a_device_back_after_an_error_is_announced_before_its_first_report() -> None:
    source, got, _ = pumped(device=TABLET)
    source.out.put(RawReport(1.0, b"\x02\x01", "tablet0"))
    source.out.put(SourceEnded(2.0, "tablet0", DeviceError("tablet0 disappeared")))
    source.out.put(RawReport(5.0, b"\x02\x02", "tablet0"))
    source.out.put(RawReport(5.1, b"\x02\x03", "tablet0"))
    assert got == [HidEntry(0.0, "tablet0", b"\x02\x01"), DeviceEntry(0.0, (TABLET,)),
                   HidEntry(0.0, "tablet0", b"\x02\x02"), HidEntry(0.0, "tablet0", b"\x02\x03")]


def test_the_announced_device_must_be_the_sources() -> None:
    with pytest.raises(ValueError, match="'tablet0' is announced for source 'pad1'"):
        SourcePump(HandFedSource("pad1"), print, device=TABLET)


def test_canvas_samples_become_pen_entries_clamped_to_the_canvas() -> None:
    source, got, _ = pumped()
    source.out.put(SampleReady(sample(0.25, 0.75), "mouse"))
    source.out.put(SampleReady(sample(1.2, -0.1, p=1.5), "mouse"))  # dragged past the edge
    assert got == [PenEntry(0.0, 0.25, 0.75, 0.5, True, True, False, False, False),
                   PenEntry(0.0, 1.0, 0.0, 1.0, True, True, False, False, False)]


def test_tablet_samples_are_mapped_onto_the_canvas() -> None:
    source, got, _ = pumped(mapping=TabletMapping(rotation=180))
    source.out.put(SampleReady(sample(0.25, 0.0), "serial0"))
    assert got == [PenEntry(0.0, 0.75, 1.0, 0.5, True, True, False, False, False)]


def test_a_pen_in_range_when_its_source_ends_is_lifted_where_it_was() -> None:
    source, got, _ = pumped()
    source.out.put(SampleReady(sample(0.3, 0.4), "serial0"))
    source.out.put(SourceEnded(3.0, "serial0", DeviceError("serial0 disappeared")))
    source.out.put(SourceEnded(4.0, "serial0"))  # already lifted: nothing more
    assert got[1:] == [PenEntry(0.0, 0.3, 0.4, 0.0, False, False, False, False, False)]


def test_a_programmatic_pen_through_a_runner_is_stamped_on_arrival() -> None:
    now = [0.0]
    runner = SessionRunner(_Recorder(), clock=lambda: now[0])
    mouse = ProgrammaticPenSource("mouse", clock=lambda: 99.0)
    pump = SourcePump(mouse, runner.submit)
    pump.start()
    now[0] = 0.5
    mouse.push(0.1, 0.2, p=0.4, tip=True)
    now[0] = 0.75
    mouse.push(0.1, 0.3, p=0.0)
    now[0] = 1.0
    pump.stop()  # the pen is in range: lifted at the stop
    runner.stop()
    assert runner.session.handled == [
        PenEntry(0.5, 0.1, 0.2, 0.4, True, True, False, False, False),
        PenEntry(0.75, 0.1, 0.3, 0.0, False, True, False, False, False),
        PenEntry(1.0, 0.1, 0.3, 0.0, False, False, False, False, False),
    ]


class _Recorder:
    def __init__(self) -> None:
        self.t = 0.0
        self.handled: list[JournalEntry] = []

    def handle(self, entry: JournalEntry) -> None:
        self.t = entry.t
        self.handled.append(entry)

    def advance(self, t: float) -> None:
        self.t = max(self.t, t)

    def view(self) -> int:
        return len(self.handled)

    def finish(self, t: float | None = None) -> None:
        pass
