"""Vendor behaviours on real captures of ../shared/data/hid: in-range polarity, v2 high byte, no vendor-init note."""

from __future__ import annotations

import re

import numpy as np
import pytest
from shared_data import shared_path

from physink_tui.commands.decode import decode_capture, summary
from physink_tui.input.captures.capture import Capture
from physink_tui.input.hid.batch import decode_batch
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.vendor_init import COMMENT_PREFIX

HID = shared_path("hid")

# README item 4 of the shared folder: byte 1 of report 0x07 in range / leaving, per device and segment.
POLARITY = [
    ("digimend__Huion_K26__if0.hid", "", {0xC0, 0xC1}, {0x80}),
    ("digimend__Ugee_M708__if0.hid", "dumps2/", {0x80, 0x81}, {0xC0}),
]
HS610 = "digimend__Huion_HS610__if0.hid"


def _segments(text: str) -> list[tuple[int, str]]:
    return [(n, line[len("# segment:"):].strip()) for n, line in enumerate(text.splitlines(), 1)
            if line.startswith("# segment:")]


def _segment_of(segments: list[tuple[int, str]], line: int) -> str:
    name = ""
    for start, seg in segments:
        if start > line:
            break
        name = seg
    return name


@pytest.mark.parametrize("case", POLARITY, ids=[c[0] for c in POLARITY])
@pytest.mark.parametrize("path", ["streaming", "batch"])
def test_uclogic_in_range_polarity_is_learnt_from_the_data(case: tuple, path: str) -> None:
    """Both polarities occur with the same descriptor; each decoder must learn which one a tablet uses."""
    name, segment, in_range, leaving = case
    text = (HID / name).read_text(encoding="utf-8", errors="replace")
    capture = Capture.from_text(text)
    device, segs = capture.devices[0], _segments(text)
    events = [e for e in capture.events if e.data[0] == 0x07 and segment in _segment_of(segs, e.line)]
    decoder = HidPenDecoder(device.descriptor, device.vid, device.pid)
    if path == "streaming":
        decoded = [(e, decoder.decode(e.data, e.t, e.line)) for e in events]
        got = {e.line: s.range for e, s in decoded if s is not None}
    else:
        cols = decode_batch(decoder, [e.t for e in events], [e.data for e in events], [e.line for e in events])
        got = {events[int(i)].line: bool(r) for i, r in zip(cols.index, cols.range, strict=True)}
    hovering = [e.line for e in events if e.data[1] in in_range]
    leaving_ = [e.line for e in events if e.data[1] in leaving]
    assert len(hovering) > 100 and leaving_
    wrong_in = [line for line in hovering if not got.get(line, False)]
    wrong_out = [line for line in leaving_ if got.get(line, False)]
    assert not wrong_in, f"{len(wrong_in)} of {len(hovering)} in-range reports out of range, first {wrong_in[:3]}"
    assert not wrong_out, f"{len(wrong_out)} of {len(leaving_)} leaving reports in range, first {wrong_out[:3]}"


def _with_x_scaled(text: str, factor: int) -> str:
    """The capture with every v2 pen report's X rewritten as X * factor over 24 bits (bytes 2-3 low, byte 8 high)."""
    out = []
    for line in text.splitlines():
        parts = line.split()
        if line.startswith("E:") and len(parts) >= 15 and parts[3] == "08" \
                and int(parts[4], 16) & 0xF0 not in (0xE0, 0xF0):
            data = bytearray(bytes.fromhex("".join(parts[3:])))
            x = (int.from_bytes(data[2:4], "little") | data[8] << 16) * factor
            data[2:4], data[8] = (x & 0xFFFF).to_bytes(2, "little"), x >> 16
            line = " ".join([*parts[:3], data.hex(" ")])
        out.append(line)
    return "\n".join(out) + "\n"


def test_huion_v2_high_byte_of_x_on_real_reports() -> None:
    """Real HS610 v2 reports with X re-encoded past 16 bits (a 4x wider tablet) decode to the same positions."""
    text = (HID / HS610).read_text(encoding="utf-8")
    note = f"# {COMMENT_PREFIX} protocol=huion-v2 x_max={{}} y_max=31750 p_max=8191 resolution=5080"
    plain = Capture.from_text(note.format(50800) + "\n" + text)
    wide = Capture.from_text(note.format(4 * 50800) + "\n" + _with_x_scaled(text, 4))
    (_, _, a), = decode_capture(plain)
    (_, _, b), = decode_capture(wide)
    assert len(a) == len(b) > 5000
    assert max(e.data[8] for e in wide.events if len(e.data) == 12 and e.data[1] & 0xF0 == 0x80) > 0
    assert np.allclose(a.x, b.x, atol=1e-9) and np.array_equal(a.y, b.y)


def _vendor_mode_006e(text: str) -> str:
    """The HS610 capture as a 256c:006e tablet recorded after the kernel switched it on: no vendor-init note, and a
    descriptor declaring only the vendor report 0x08, shorter (8 bytes) than the 12 the tablet sends."""
    text = re.sub(rf"^# {re.escape(COMMENT_PREFIX)}.*\n", "", text, flags=re.M)
    text = re.sub(r"^I: 3 256c 006d$", "I: 3 256c 006e", text, flags=re.M)
    return re.sub(r"^R: .*$", "R: 18 06 00 ff 09 01 a1 01 85 08 75 38 95 01 09 01 81 02 c0", text, flags=re.M)


def test_vendor_mode_huion_without_init_note_infers_maxima_and_says_so() -> None:
    text = (HID / HS610).read_text(encoding="utf-8")
    note = f"# {COMMENT_PREFIX} protocol=huion-v2 x_max=50800 y_max=31750 p_max=8191 resolution=5080\n"
    with_note = Capture.from_text(note + text)
    stripped = Capture.from_text(_vendor_mode_006e(note + text))
    assert not any(COMMENT_PREFIX in c for c in stripped.devices[0].comments)
    (_, _, ref), = decode_capture(with_note)
    results = decode_capture(stripped)
    (_, decoder, got), = results
    assert decoder.layouts[0x08].source == "huion-v2"
    assert len(got) == len(ref) > 5000
    # inferred ranges are the largest values seen: positions agree with the true maxima up to that scale
    ax, gx = ref.x[ref.range], got.x[got.range]
    assert gx.max() == pytest.approx(1.0) and np.allclose(gx * ax.max(), ax, atol=1e-6)
    assert np.array_equal(got.tip, ref.tip)
    text_summary = summary(stripped, results)
    assert "warning: maxima unknown" in text_summary and "256c:006e" in text_summary
