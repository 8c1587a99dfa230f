"""Every real capture in the shared data folder reads cleanly and survives a write/read round trip.

The files are read in place from ``../shared/data/hid`` next to the repository and never copied into it
(their licences differ). The module skips itself when that folder is not there.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from shared_data import shared_path

from physink_tui.input.captures.capture import Capture
from physink_tui.input.captures.writer import format_capture

HID_DIR = shared_path("hid", module_level=True)

FILES = sorted(HID_DIR.glob("*.hid"))


def _declared_descriptor_length(path: Path) -> int:
    with path.open(encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("R:"):
                return int(line.split()[1])
    raise AssertionError(f"{path.name} has no R: line")


def test_the_folder_holds_captures() -> None:
    assert FILES, f"no *.hid files in {HID_DIR}"


@pytest.mark.parametrize("path", FILES, ids=[p.name for p in FILES])
def test_shared_capture_reads_and_round_trips(path: Path) -> None:
    capture = Capture.from_file(path)

    assert capture.bad_lines == ()
    assert len(capture.devices) == 1
    (device,) = capture.devices
    assert device.index == 0
    assert device.descriptor
    assert len(device.descriptor) == _declared_descriptor_length(path)
    assert all(e.device == 0 for e in capture.events)

    if path.name.startswith("digimend__"):
        assert len(capture.events) > 20
        assert all(e.t >= 0 for e in capture.events)
        assert capture.events[-1].t > 0

    again = Capture.from_text(format_capture(capture))
    assert again.devices == capture.devices
    assert again.events == capture.events  # CaptureEvent.line is left out of equality
    assert [(e.t, e.data) for e in again.events] == [(e.t, e.data) for e in capture.events]
