"""The TUI's Textual-free parts: half blocks, the XDG journal folder, the paced journal feed, the tablet watcher,
and the CLI that imports Textual only when the TUI opens."""

from __future__ import annotations

import subprocess
import sys
import threading
import time

import numpy as np
import pytest

from physink_tui.errors import DeviceError
from physink_tui.formats.journal.entries import CommandEntry, DeviceEntry, HidEntry
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.input.hid.reference_descriptors import REFERENCE_DEVICES
from physink_tui.input.replay_clock import ReplayClock
from physink_tui.input.sources import RawReport, SourceEnded
from physink_tui.tui import storage
from physink_tui.tui.halfblocks import UPPER_HALF, HalfBlocks
from physink_tui.tui.live import JournalFeed, default_header
from physink_tui.tui.tablet import DEVICE_ID, TabletWatch
from tests.tui_helpers import HANG_GUARD


def test_half_blocks_put_two_pixels_in_a_cell_and_merge_runs() -> None:
    rgba = np.zeros((4, 6, 4), dtype=np.uint8)
    rgba[0, :3] = (255, 0, 0, 255)  # top row: red on the left half
    rgba[1, :] = (0, 0, 255, 255)   # second row: blue everywhere
    strips = HalfBlocks().strips(rgba)
    assert len(strips) == 2 and all(s.cell_length == 6 for s in strips)
    first = list(strips[0])
    assert [seg.text for seg in first] == [UPPER_HALF * 3, UPPER_HALF * 3]
    assert first[0].style.color.triplet == (255, 0, 0) and first[0].style.bgcolor.triplet == (0, 0, 255)
    assert first[1].style.color.triplet == (0, 0, 0) and first[1].style.bgcolor.triplet == (0, 0, 255)
    assert len(list(strips[1])) == 1


def test_an_odd_last_row_pairs_with_black() -> None:
    rgba = np.full((3, 2, 4), 200, dtype=np.uint8)
    strips = HalfBlocks().strips(rgba)
    assert len(strips) == 2 and next(iter(strips[1])).style.bgcolor.triplet == (0, 0, 0)


def test_journals_go_to_the_xdg_data_folder(monkeypatch, tmp_path) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    assert storage.sessions_dir() == tmp_path / "physink" / "sessions"
    monkeypatch.setenv("XDG_DATA_HOME", "relative/not/allowed")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert storage.sessions_dir() == tmp_path / "home" / ".local" / "share" / "physink" / "sessions"
    first = storage.new_journal_path(tmp_path / "s", now=0)
    first.touch()
    second = storage.new_journal_path(tmp_path / "s", now=0)
    assert first != second and second.name.endswith(".physink.jsonl")


def test_finished_empty_and_unreadable_journals_are_not_offered(tmp_path) -> None:
    header = default_header()
    with JournalWriter.create(tmp_path / "a.physink.jsonl", header) as w:
        w.append(CommandEntry(1.0, "clear", ()))
        w.append(CommandEntry(2.0, "end", ()))
    with JournalWriter.create(tmp_path / "b.physink.jsonl", header):
        pass
    (tmp_path / "c.physink.jsonl").write_text("not a journal\n")
    with JournalWriter.create(tmp_path / "d.physink.jsonl", header) as w:
        w.append(CommandEntry(1.0, "clear", ()))
    assert [p.name for p, _ in storage.unfinished_journals(tmp_path)] == ["d.physink.jsonl"]
    assert storage.unfinished_journals(tmp_path, exclude=tmp_path / "d.physink.jsonl") == []
    with JournalWriter.create(tmp_path / "e.physink.jsonl", header) as w:
        w.append(CommandEntry(1.0, "end", ()))
    assert storage.remove_if_empty(tmp_path / "e.physink.jsonl")
    assert not storage.remove_if_empty(tmp_path / "a.physink.jsonl")


def test_the_feed_submits_entries_at_their_due_time_on_the_runners_clock_and_leaves_out_the_end() -> None:
    got: list[tuple[float, object]] = []
    done = threading.Event()
    entries = [CommandEntry(0.0, "mode", ("demo",)), CommandEntry(0.2, "play", ()), CommandEntry(0.4, "end", ())]
    clock = ReplayClock()
    feed = JournalFeed(entries, lambda e: got.append((clock(), e)), speed=2.0, on_done=done.set, clock=clock)
    feed.start()
    assert done.wait(HANG_GUARD)
    assert [e.name for _, e in got] == ["mode", "play"]
    # 0.2 s of journal at twice the speed: the clock read as each is submitted, however late the thread ran
    assert got[1][0] - got[0][0] == pytest.approx(0.1, abs=1e-9)
    assert clock() >= got[1][0]  # released at the end: it runs on


def wait_for(condition, what: str) -> None:
    """Wait until ``condition()``; fail only after the hang guard."""
    deadline = time.monotonic() + HANG_GUARD
    while not condition():
        assert time.monotonic() < deadline, f"timed out waiting for {what}"
        time.sleep(0.01)


class _FakeReader:
    """A tablet reader: one report, then nothing until stopped."""

    def __init__(self, device_id: str) -> None:
        self.device_id = device_id
        device = REFERENCE_DEVICES["uclogic-v1"]
        self.info = type("Info", (), {"name": "Fake Tablet", "path": "/dev/hidraw9", "bus": 3, "vid": 0x256C,
                                      "pid": 0x006D, "descriptor": device.descriptor})()
        self._out = None

    def start(self, out) -> None:
        self._out = out
        out.put(RawReport(0.0, b"\x07\x00", self.device_id))

    def stop(self) -> None:
        if self._out is not None:
            self._out.put(SourceEnded(0.0, self.device_id, None))
            self._out = None

    def unplug(self) -> None:
        out, self._out = self._out, None
        out.put(SourceEnded(0.0, self.device_id, DeviceError("the tablet went away")))


def test_the_tablet_watch_says_when_there_is_none_and_picks_one_up_when_plugged_in() -> None:
    plugged = threading.Event()
    submitted, statuses = [], []

    readers: list[_FakeReader] = []

    def opener(spec, device_id):
        if not plugged.is_set():
            raise DeviceError("no pen tablet found")
        readers.append(_FakeReader(device_id))
        return readers[-1]

    watch = TabletWatch(submitted.append, statuses.append, opener=opener, scan_s=0.05)
    watch.start()
    wait_for(lambda: statuses, "a status")
    assert statuses[0].startswith("no tablet") and "mouse" in statuses[0]
    plugged.set()
    wait_for(lambda: any(isinstance(e, HidEntry) for e in submitted), "a report")
    readers[0].unplug()  # mid-stroke: the stroke ends (the pump lifts the pen), the status says so; it comes back
    wait_for(lambda: sum(isinstance(e, DeviceEntry) for e in submitted) >= 2, "the tablet announced again")
    watch.stop()
    assert any("lost" in s for s in statuses) and statuses[-1] == "tablet: Fake Tablet"
    assert sum(isinstance(e, DeviceEntry) for e in submitted) == 2  # announced again before its next report
    assert isinstance(submitted[0], DeviceEntry) and submitted[0].devices[0].id == DEVICE_ID
    assert submitted[0].devices[0].name == "Fake Tablet"
    assert any(isinstance(e, HidEntry) and e.dev == DEVICE_ID for e in submitted)
    assert "tablet: Fake Tablet" in statuses


def test_the_command_line_imports_textual_only_to_open_the_tui() -> None:
    code = ("import sys; from physink_tui import cli; cli.build_parser();"
            "import physink_tui.commands.tui, physink_tui.commands.demo;"
            "print('textual' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


def test_the_tui_command_without_a_terminal_says_so(capsys) -> None:
    from physink_tui import cli

    assert cli.main(["tui"]) == 1
    assert "needs a terminal" in capsys.readouterr().err


def test_tui_replay_reads_a_journal_or_a_capture() -> None:
    from pathlib import Path

    from physink_tui.commands.tui import recorded

    root = Path(__file__).resolve().parent
    header, entries = recorded(str(root / "journals" / "egg_cracker.physink.jsonl"))
    assert header.devices and any(isinstance(e, HidEntry) for e in entries)
    header, entries = recorded(str(root / "recorded_hid" / "windows-ink-strokes.hid"))
    assert (header.canvas_width, header.canvas_height) == (1600.0, 1000.0) and len(entries) > 100
    assert all(isinstance(e, HidEntry) and e.dev == header.devices[0].id for e in entries)


def test_the_timeline_tree_names_the_pairs_the_start_found_in_contact() -> None:
    from physink_tui.timeline.events import Event
    from physink_tui.tui.widgets.timeline_tree import TimelineTree

    names = {"b1": "stopper", "b2": "ball"}
    begun = Event("e1", "start", in_contact=(("b1", "b2"),))
    assert TimelineTree._label(begun, {}, names) == " 0.00 s  start (stopper and ball in contact)"
    assert TimelineTree._label(Event("e1", "start"), {}, names) == " 0.00 s  start"
