"""Tilt in degrees from HID units: degrees, radians, exponents and physical offsets."""

from __future__ import annotations

import pytest

from physink_tui.input.hid import descriptor_builder as d
from physink_tui.input.hid.decoder import HidPenDecoder


def pen_with_tilt(tilt_items: bytes, tilt_size: int) -> bytes:
    """A Windows-Ink style pen report 0x02: tip and in-range bits, X/Y 16 bit, then one tilt value."""
    return d.build(
        d.usage_page(0x0D), d.usage(0x02), d.collection("application"), d.report_id(0x02),
        d.usage(0x20), d.collection("physical"),
        d.usage(0x42), d.usage(0x32), d.logical(0, 1), d.report_size(1), d.report_count(2), d.input(),
        d.report_count(6), d.input(d.CONSTANT),
        d.usage_page(0x01), d.usage(0x30), d.usage(0x31), d.logical(0, 10000), d.report_size(16),
        d.report_count(2), d.input(),
        d.usage_page(0x0D), d.usage(0x3D), tilt_items, d.report_size(tilt_size), d.report_count(1), d.input(),
        d.end_collection(), d.end_collection(),
    )


def tilt_of(descriptor: bytes, raw: int, size: int) -> float:
    decoder = HidPenDecoder(descriptor)
    tilt = (raw & ((1 << size) - 1)).to_bytes(size // 8, "little")
    report = bytes([0x02, 0x03]) + (5000).to_bytes(2, "little") * 2 + tilt
    sample = decoder.decode(report, 0.0)
    assert sample is not None
    return sample.tilt_x


@pytest.mark.parametrize(
    ("items", "size", "raw", "degrees"),
    [
        # Microsoft's sample: -9000..9000 hundredths of a degree
        (d.logical(-9000, 9000) + d.physical(-9000, 9000) + d.unit(0x14) + d.unit_exponent(-2), 16, 4500, 45.0),
        # radians (SI rotation) in hundredths: 157 -> 1.57 rad = 89.95 degrees
        (d.logical(-157, 157) + d.physical(-157, 157) + d.unit(0x12) + d.unit_exponent(-2), 16, 157, 89.954),
        # unsigned logical 0..127 mapped onto -64..63 degrees
        (d.logical(0, 127) + d.physical(-64, 63) + d.unit(0x14), 8, 0, -64.0),
        # no unit: logical units are degrees, as Huion and XP-Pen send them
        (d.logical(-127, 127), 8, -30, -30.0),
        # a length unit is not a rotation: logical units are taken as degrees
        (d.logical(-60, 60) + d.physical(-6, 6) + d.unit(0x11), 8, 20, 20.0),
    ],
    ids=["degrees-exp-2", "radians", "physical-offset", "no-unit", "length-unit"],
)
def test_tilt_in_degrees(items: bytes, size: int, raw: int, degrees: float) -> None:
    assert tilt_of(pen_with_tilt(items, size), raw, size) == pytest.approx(degrees, abs=0.01)
