"""Vendor protocols on reports we build by hand: UC-Logic v1, Huion v2, older Wacom, family quirks."""

from __future__ import annotations

import pytest

from physink_tui.errors import DescriptorError
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.vendor_layouts import VID_HUION, VID_UCLOGIC, VID_WACOM, TabletParams

# A Wacom descriptor that only declares a relative mouse report 0x01 (older Wacom tablets).
WACOM_MOUSE_ONLY = bytes.fromhex(
    "05010902a10185010901a1000509190129031500250195037501810295057501810105010930093109381581257f"
    "750895038106c0c0"
)
# A Huion v2 interface: one vendor collection on page 0xFF00 with a 12-byte report 0x08.
HUION_V2_VENDOR = bytes.fromhex("0600ff0901a1018508150026ff0075089509090181 02c0".replace(" ", ""))
# UC-Logic power-on descriptor: only the mouse-mode report 0x09 (B1..B3, abs X/Y 0..2047, pressure).
UCLOGIC_MOUSE_MODE = bytes.fromhex(
    "05010902a10185090901a100050919012903150025019503750181029505810105010930750f9501a4"
    "350046ff07 26ff07 8102 0931 8102 b4 050d 0930 26ff07 46ff07 7510 8102 c0c0".replace(" ", "")
)


def le16(v: int) -> bytes:
    return v.to_bytes(2, "little")


def test_uclogic_v1_string_descriptor_params() -> None:
    payload = le16(0) + le16(40000) + le16(25000) + le16(0) + le16(2047) + le16(5080)
    params = TabletParams.from_uclogic_v1(payload)
    assert params == TabletParams(40000, 25000, 2047, 5080)
    assert TabletParams.from_uclogic_v1(payload[:4]) is None  # too short: no parameters


def test_huion_v2_string_descriptor_params() -> None:
    payload = bytes(2) + (50800).to_bytes(3, "little") + (31750).to_bytes(3, "little") + le16(8191) + le16(5080)
    assert TabletParams.from_huion_v2(payload) == TabletParams(50800, 31750, 8191, 5080)


@pytest.mark.parametrize(
    ("byte1", "tip", "in_range"),
    [(0x81, True, True), (0x80, False, True), (0xC0, False, False)],
    ids=["touching", "hovering", "leaving"],
)
def test_uclogic_v1_inverted_in_range_is_learnt_from_touching_reports(byte1: int, tip: bool, in_range: bool) -> None:
    params = TabletParams(40000, 24000, 2047)
    decoder = HidPenDecoder(UCLOGIC_MOUSE_MODE, VID_UCLOGIC, 0x0081, params=params, protocol="uclogic-v1")
    # the pen touches first: bit 6 clear while touching teaches the polarity (Ugee M708 style)
    decoder.decode(bytes([0x07, 0x81]) + le16(100) + le16(100) + le16(900), 0.0)
    sample = decoder.decode(bytes([0x07, byte1]) + le16(20000) + le16(12000) + le16(500 if tip else 0), 0.01)
    assert sample is not None
    assert (sample.tip, sample.range) == (tip, in_range)
    assert sample.x == pytest.approx(0.5)
    assert sample.p == (pytest.approx(500 / 2047) if tip else 0.0)


def test_uclogic_v1_pad_report_is_not_a_pen_sample() -> None:
    decoder = HidPenDecoder(UCLOGIC_MOUSE_MODE, VID_UCLOGIC, 0x0081, protocol="uclogic-v1")
    assert decoder.decode(bytes([0x07, 0xE0, 0x01, 0, 0, 0, 0, 0]), 0.0) is None
    assert "pad, strip or dial report 0x07" in decoder.stats.ignored


def test_huion_v2_24_bit_coordinates_and_tilt() -> None:
    params = TabletParams(0x20000, 0x10000, 8191)
    decoder = HidPenDecoder(HUION_V2_VENDOR, VID_HUION, 0x006D, params=params)
    x, y = 0x18000, 0x08000
    report = bytes([0x08, 0x81]) + le16(x & 0xFFFF) + le16(y & 0xFFFF) + le16(4096) + bytes([x >> 16, y >> 16])
    report += bytes([(-30) & 0xFF, 45])
    sample = decoder.decode(report, 1.0)
    assert sample is not None
    assert sample.x == pytest.approx(0.75)
    assert sample.y == pytest.approx(0.5)
    assert sample.p == pytest.approx(4096 / 8191)
    assert (sample.tilt_x, sample.tilt_y) == (-30.0, 45.0)
    assert sample.tip and sample.range
    for frame in (0xE0, 0xF0, 0xF1):
        assert decoder.decode(bytes([0x08, frame]) + bytes(10), 1.1) is None


def test_huion_v2_longer_report_decodes_declared_bits_and_short_one_is_counted() -> None:
    decoder = HidPenDecoder(HUION_V2_VENDOR, VID_HUION, 0x006D)
    assert decoder.decode(bytes([0x08, 0x80]) + bytes(10) + b"\xff\xff", 0.0) is not None
    assert decoder.decode(bytes([0x08, 0x80, 0x00]), 0.1) is None
    assert decoder.stats.ignored["truncated report 0x08"] == 1


@pytest.mark.parametrize(
    ("byte1", "tool_is_eraser", "tip", "b1"),
    [(0x80, False, False, False), (0x81, False, True, False), (0xA1, True, True, False), (0x82, False, False, True)],
    ids=["pen-hover", "pen-touch", "eraser-touch", "button"],
)
def test_wacom_graphire_protocol(byte1: int, tool_is_eraser: bool, tip: bool, b1: bool) -> None:
    decoder = HidPenDecoder(WACOM_MOUSE_ONLY, VID_WACOM, 0x0061)
    pressure = 200 if tip else 0
    sample = decoder.decode(bytes([0x02, byte1]) + le16(1625) + le16(1160) + bytes([pressure, 0]), 0.0)
    assert sample is not None
    assert sample.x == pytest.approx(0.5)
    assert sample.y == pytest.approx(0.5)
    assert (sample.eraser, sample.tip, sample.b1, sample.range) == (tool_is_eraser, tip, b1, True)
    assert sample.p == (pytest.approx(200 / 255) if tip else 0.0)


def test_wacom_graphire_mouse_tool_and_out_of_proximity() -> None:
    decoder = HidPenDecoder(WACOM_MOUSE_ONLY, VID_WACOM, 0x0061)
    assert decoder.decode(bytes([0x02, 0xC0]) + bytes(6), 0.0) is None  # tool 2: the mouse
    out = decoder.decode(bytes([0x02, 0x00]) + bytes(6), 0.1)
    assert out is not None and not out.range and not out.tip


def test_unknown_older_wacom_falls_back_to_graphire_newer_ones_get_no_guess() -> None:
    assert HidPenDecoder(WACOM_MOUSE_ONLY, VID_WACOM, 0x007F).layouts[0x02].source == "wacom-graphire"
    with pytest.raises(DescriptorError, match="no pen report"):
        HidPenDecoder(WACOM_MOUSE_ONLY, VID_WACOM, 0x0379)


def test_two_button_families_read_bit_2_as_a_button_not_an_eraser() -> None:
    # Huion's own descriptor declares bit 2 of the flags byte "Eraser"; the pen has two buttons.
    descriptor = bytes.fromhex(
        "050d0902a1018507 0920a100 0942 0944 0945 093c 0943 0944 150025017501950681020932750195018102"
        "8103 0501 0930 7510 9501 a4 5500 6500 3500 46ff7f 26ff7f 8102 0931 8102 b4 050d 0930 26ff07"
        " 46ff07 8102 c0c0".replace(" ", "")
    )
    for vid, eraser in ((VID_HUION, False), (0x1234, True)):
        decoder = HidPenDecoder(descriptor, vid, 0x0001)
        sample = decoder.decode(bytes([0x07, 0x44]) + le16(10) + le16(10) + le16(0), 0.0)
        assert sample is not None
        assert (sample.b2, sample.eraser) == (not eraser, eraser), hex(vid)
