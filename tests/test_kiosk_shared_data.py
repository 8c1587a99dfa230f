"""The kiosk on real tablets' captures from the shared data folder (not our virtual pen): every touch the session's
own pen state machine sees begins once in the control filter, nothing drawn on the canvas is held back, and a
replay through `physink kiosk` records sessions whose journals replay to the same project."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from shared_data import shared_path

from physink_tui.cli import main
from physink_tui.errors import DescriptorError
from physink_tui.formats.journal.entries import JournalDevice
from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.pen.state import PenStateMachine, TipThresholds
from physink_tui.kiosk.controls import HOLD, PASS, PRESS, ControlFilter
from physink_tui.kiosk.folder_files import JOURNAL
from physink_tui.kiosk.hot_zones import default_zones

HID_DIR = shared_path("hid", module_level=True)
FILES = sorted(HID_DIR.glob("*.hid"))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_every_real_touch_begins_once_and_touches_on_the_canvas_pass(path: Path) -> None:
    capture = Capture.from_file(path)
    for d in capture.devices:
        device = JournalDevice("tablet0", d.name, d.bus, d.vid, d.pid, d.descriptor)
        try:
            controls = ControlFilter(device, default_zones(), TipThresholds())
            decoder = HidPenDecoder(d.descriptor, d.vid, d.pid, name=d.name)
        except DescriptorError:
            continue
        machine, touches, began, in_zone = PenStateMachine(TipThresholds()), 0, 0, False
        for e in capture.events_for(d.index):
            verdict = controls.report(e.data, e.t)
            sample = decoder.decode(e.data, e.t)
            if sample is not None:
                was = machine.state.in_contact
                machine.follow(sample)
                touches += machine.state.in_contact and not was
            began += verdict.touch_began
            if verdict.touch_began:
                in_zone = verdict.zone is not None
            pad_report = controls.pad is not None and controls.pad.buttons(e.data) is not None
            if verdict.what in (HOLD, PRESS) and not pad_report:
                assert in_zone, (path.name, e.line)  # only a touch begun in a zone (or a pad report) is held back
            if verdict.touch_began and not in_zone:
                assert verdict.what == PASS
        assert began == touches, path.name


@pytest.mark.parametrize("name", ["digimend__Huion_HS610__if0.hid", "digimend__XP-Pen_Deco_01__if1.hid"])
def test_a_real_capture_replayed_through_the_kiosk_gives_sessions_that_replay(
        name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "out"
    assert main(["kiosk", "--out", str(out), "--replay", str(HID_DIR / name), "--speed", "40", "--video-size",
                 "160x100"]) == 0
    records = [json.loads(line) for line in (out / "index.jsonl").read_text().splitlines()]
    assert records and all(r["ended"] in ("end zone", "end button", "capture ended") for r in records)
    for record in records:
        folder = out / record["session"]
        assert main(["replay", str(folder / JOURNAL), "--out", str(tmp_path / "again")]) == 0
        assert (tmp_path / "again" / "project.json").read_bytes() == (folder / "project.json").read_bytes()
    capsys.readouterr()
