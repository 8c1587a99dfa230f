"""Pad buttons (ExpressKeys) in the real captures and descriptors of the shared data folder: found where tablets
send them, never taken from a mouse collection or a pen report."""

from __future__ import annotations

from pathlib import Path

import pytest
from shared_data import shared_path

from physink_tui.errors import DescriptorError
from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.descriptor import ReportDescriptor
from physink_tui.input.hid.pad import PadDecoder

HID_DIR = shared_path("hid", module_level=True)
FILES = sorted(HID_DIR.glob("*.hid"))
MOUSE = 0x0001_0002


def presses(path: Path) -> list[int]:
    """Every pad button going down in the capture, in order."""
    capture = Capture.from_file(path)
    out: list[int] = []
    for device in capture.devices:
        pad = PadDecoder(device.descriptor, device.vid, device.pid, name=device.name)
        held: frozenset[int] = frozenset()
        for event in capture.events_for(device.index):
            buttons = pad.buttons(event.data)
            if buttons is not None:
                out += sorted(buttons - held)
                held = buttons
    return out


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_a_pad_report_is_never_a_pen_sample_nor_a_mouse_button(path: Path) -> None:
    capture = Capture.from_file(path)
    for device in capture.devices:
        try:
            pad = PadDecoder(device.descriptor, device.vid, device.pid, name=device.name)
            pen = HidPenDecoder(device.descriptor, device.vid, device.pid, name=device.name)
        except DescriptorError:
            continue
        mouse_reports = {r.report_id for r in ReportDescriptor.from_bytes(device.descriptor).input_reports()
                         if any(f.application == MOUSE for f in r.fields)}
        for event in capture.events_for(device.index):
            buttons = pad.buttons(event.data)
            if buttons is None:
                continue
            assert pen.decode(event.data, event.t) is None, (path.name, event.line)
            rid = event.data[0] if pad.uses_ids else 0
            assert rid not in mouse_reports or rid in pen.layouts, (path.name, event.line)


def test_a_huion_in_its_vendor_mode_reports_each_key_pressed() -> None:
    """The HS610 capture's pad section: each of its twelve keys pressed once, in order (and the dial's button)."""
    found = presses(HID_DIR / "digimend__Huion_HS610__if0.hid")
    assert [b for b in found if b <= 12] == list(range(1, 13))


def test_a_pad_the_descriptor_describes_reports_its_keys() -> None:
    """The XP-Pen Deco 01 describes its eight keys as buttons outside any application collection."""
    assert presses(HID_DIR / "digimend__XP-Pen_Deco_01__if1.hid") == list(range(1, 9))


def test_tablets_in_mouse_mode_have_no_pad() -> None:
    """KYE/Genius tablets send the pen's buttons in a mouse collection: those are no pad keys."""
    for name in ("digimend__KYE_G-Pen_560__if0.hid", "digimend__KYE_MousePen_i608X_v2__if0.hid"):
        assert presses(HID_DIR / name) == []
