"""Property tests: the descriptor parser and the pen decoder fail on arbitrary bytes only as documented."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physink_tui.errors import DescriptorError
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.descriptor import MAX_REPORT_BYTES, ReportDescriptor
from physink_tui.input.hid.pen_layout import pen_layouts
from physink_tui.input.pen.sample import PenSample

SETTINGS = settings(max_examples=300, deadline=None)
SIZES = (0, 1, 2, 4)

# Prefixes (size bits cleared) of every item the HID 1.11 specification defines.
MAIN_TAGS = [0x80, 0x90, 0xA0, 0xB0, 0xC0]  # Input, Output, Collection, Feature, End Collection
GLOBAL_TAGS = [0x04, 0x14, 0x24, 0x34, 0x44, 0x54, 0x64, 0x74, 0x84, 0x94, 0xA4, 0xB4]
LOCAL_TAGS = [0x08, 0x18, 0x28, 0x38, 0x48, 0x58, 0x78, 0x88, 0x98, 0xA8]
DEFINED_TAGS = MAIN_TAGS + GLOBAL_TAGS + LOCAL_TAGS


def check_parse(data: bytes) -> ReportDescriptor | None:
    """Parse; the only failure allowed is a DescriptorError whose offset lies inside the data."""
    try:
        desc = ReportDescriptor.from_bytes(data)
    except DescriptorError as exc:
        where = exc.offset
        assert where is None or 0 <= where <= len(data), f"offset {where} outside 0..{len(data)}"
        return None
    assert desc.raw == data
    for report in desc.reports.values():
        assert 0 < report.size_bytes <= MAX_REPORT_BYTES + 1
        for f in report.fields:
            assert f.bit_offset + f.size * f.count <= report.size_bytes * 8
            assert f.report_id == report.report_id
    return desc


# -- (i) random bytes ----------------------------------------------------------------------------------------


@SETTINGS
@given(st.binary(max_size=512))
def test_random_bytes_parse_or_raise_descriptor_error(data: bytes) -> None:
    check_parse(data)


# -- (ii) random sequences of well-formed items --------------------------------------------------------------


@st.composite
def short_item(draw: st.DrawFn, tags: list[int] | None = None) -> bytes:
    """One short item: a prefix and exactly the number of data bytes its size code announces."""
    if tags is None:
        prefix = draw(st.integers(0, 255).filter(lambda b: b != 0xFE))
    else:
        prefix = draw(st.sampled_from(tags)) | draw(st.integers(0, 3))
    size = SIZES[prefix & 3]
    if size == 0:
        return bytes([prefix])
    # small values make report ids, sizes, counts and collection kinds plausible more often
    value = draw(st.one_of(st.integers(0, 16), st.integers(0, (1 << (8 * size)) - 1)))
    return bytes([prefix]) + value.to_bytes(size, "little")


@st.composite
def long_item(draw: st.DrawFn) -> bytes:
    data = draw(st.binary(max_size=20))
    return bytes([0xFE, len(data), draw(st.integers(0, 255))]) + data


ITEMS = st.lists(
    st.one_of(short_item(DEFINED_TAGS), short_item(DEFINED_TAGS), short_item(), long_item()), max_size=60
)


@SETTINGS
@given(ITEMS)
def test_well_formed_items_parse_or_raise_descriptor_error(items: list[bytes]) -> None:
    data = b"".join(items)
    desc = check_parse(data)
    if desc is not None:
        pen_layouts(desc)  # finding pen layouts never fails on a parsed descriptor


@SETTINGS
@given(ITEMS)
def test_well_formed_items_inside_a_digitizer_collection(items: list[bytes]) -> None:
    # a Digitizer Pen application around the random items, so that Input items meet plausible state
    data = bytes.fromhex("05 0d 09 02 a1 01 85 02 09 20 a1 00") + b"".join(items) + bytes.fromhex("c0 c0")
    desc = check_parse(data)
    if desc is None:
        return
    try:
        decoder = HidPenDecoder(data, 0x256C, 0x006E)
    except DescriptorError as exc:
        assert "no pen report" in str(exc)
        return
    for rid in decoder.layouts:
        for length in (0, 1, 8, 16):
            check_result(decoder.decode(bytes([rid]) + bytes(range(length)), 0.0), rid)


# -- (iii) decoders from real-looking descriptors ---------------------------------------------------------

# Composed here after the layouts the shared README describes; none is copied from a device.
DEVICES = {
    # Windows-Ink pen, report 0x02: tip, barrel, eraser, invert, in range bits, X/Y 16 bit, pressure, tilt.
    "windows-ink-pen": (
        "05 0d 09 02 a1 01 85 02 09 20 a1 00"
        " 09 42 09 44 09 45 09 3c 09 32 15 00 25 01 75 01 95 05 81 02 95 03 81 03"
        " 05 01 09 30 09 31 26 ff 7f 75 10 95 02 81 02"
        " 05 0d 09 30 26 ff 1f 75 10 95 01 81 02"
        " 09 3d 09 3e 15 a6 25 5a 75 08 95 02 81 02"
        " c0 c0",
        None, None, {0x02},
    ),
    # The same pen without report ids (first byte is data).
    "pen-without-report-id": (
        "05 0d 09 02 a1 01 09 20 a1 00"
        " 09 42 09 44 09 32 15 00 25 01 75 01 95 03 81 02 95 05 81 03"
        " 05 01 09 30 09 31 26 ff 7f 75 10 95 02 81 02"
        " 05 0d 09 30 26 ff 07 75 10 95 01 81 02"
        " c0 c0",
        None, None, {0x00},
    ),
    # UC-Logic power-on "mouse mode" report 0x09 (buttons, absolute X/Y, Tip Pressure); the profile of
    # 5543:0081 adds the vendor v1 report 0x07 with its learnt in-range polarity.
    "uclogic-mouse-mode": (
        "05 01 09 02 a1 01 85 09 09 01 a1 00"
        " 05 09 19 01 29 03 15 00 25 01 95 03 75 01 81 02 95 05 81 01"
        " 05 01 09 30 09 31 26 ff 7f 75 10 95 02 81 02"
        " 05 0d 09 30 26 ff 07 95 01 81 02"
        " c0 c0",
        0x5543, 0x0081, {0x07, 0x09},
    ),
    # KYE-style mouse-mode report 0x09 with an In Range bit and no pressure, declared 6 bytes.
    "kye-mouse-in-range": (
        "05 01 09 02 a1 01 85 09 09 01 a1 00"
        " 05 09 19 01 29 03 15 00 25 01 95 03 75 01 81 02 95 04 81 01"
        " 05 0d 09 32 95 01 81 02"
        " 05 01 09 30 09 31 26 00 60 75 10 95 02 81 02"
        " c0 c0",
        0x0458, 0x500F, {0x09},
    ),
    # Huion "v2" interface: a single vendor collection, report 0x08 of 12 bytes.
    "huion-v2-vendor": (
        "06 00 ff 09 01 a1 01 85 08 75 08 95 0b 15 00 26 ff 00 09 01 81 02 c0",
        0x256C, 0x006D, {0x08},
    ),
    # Wacom vendor page 0xFF0D mirroring the Digitizer usages, 24-bit X/Y (report 0x10).
    "wacom-ff0d": (
        "06 0d ff 09 01 a1 01 85 10 09 20 a1 00"
        " 09 42 09 44 09 5a 09 45 09 3c 09 32 15 00 25 01 75 01 95 06 81 02 95 02 81 03"
        " 0a 30 01 27 ff ff ff 00 75 18 95 01 81 02 0a 31 01 81 02"
        " 09 30 26 ff 1f 75 10 81 02"
        " 09 3d 09 3e 15 c0 25 3f 75 08 95 02 81 02"
        " c0 c0",
        0x056A, 0x0357, {0x10},
    ),
    # An older Wacom whose descriptor shows only a mouse: the Graphire protocol report 0x02 is added.
    "wacom-graphire": (
        "05 01 09 02 a1 01 85 01 09 01 a1 00"
        " 05 09 19 01 29 03 15 00 25 01 95 03 75 01 81 02 95 01 75 05 81 03"
        " 05 01 09 30 09 31 15 81 25 7f 75 08 95 02 81 06"
        " c0 c0",
        0x056A, 0x0010, {0x02},
    ),
}


def make_decoder(name: str) -> HidPenDecoder:
    hex_text, vid, pid, _ = DEVICES[name]
    return HidPenDecoder(bytes.fromhex(hex_text), vid, pid)


@pytest.mark.parametrize("name", list(DEVICES))
def test_real_looking_descriptor_has_the_expected_pen_layouts(name: str) -> None:
    assert set(make_decoder(name).layouts) == DEVICES[name][3]


def check_result(result: PenSample | None, report_id: int) -> None:
    if result is None:
        return
    assert isinstance(result, PenSample)
    for value in (result.x, result.y, result.p):
        assert math.isfinite(value) and 0.0 <= value <= 1.0, result
    for tilt in (result.tilt_x, result.tilt_y):
        assert tilt is None or (math.isfinite(tilt) and -90.0 <= tilt <= 90.0), result
    assert result.tip or result.p == 0.0, result
    assert result.report == report_id


@st.composite
def reports(draw: st.DrawFn, known_ids: list[int]) -> bytes:
    """A report of 0..64 bytes whose first byte is often one of the device's pen report ids."""
    length = draw(st.integers(0, 64))
    if length == 0:
        return b""
    rid = draw(st.one_of(st.sampled_from(known_ids), st.integers(0, 255)))
    return bytes([rid]) + draw(st.binary(min_size=length - 1, max_size=length - 1))


def _decode_property(name: str, data: st.DataObject) -> None:
    decoder = make_decoder(name)
    known = sorted(decoder.layouts) or [0]
    calls = data.draw(st.lists(
        st.tuples(reports(known), st.floats(0.0, 1e6, allow_nan=False, allow_infinity=False)), max_size=40
    ))
    samples = 0
    for report, t in calls:
        result = decoder.decode(report, t)
        if result is not None:
            samples += 1
            rid = report[0] if decoder.uses_ids else 0
            check_result(result, rid)
            assert result.t == t
    stats = decoder.stats
    assert stats.reports == len(calls)
    assert stats.samples == samples
    assert stats.samples + sum(stats.ignored.values()) == stats.reports


@pytest.mark.parametrize("name", list(DEVICES))
@SETTINGS
@given(data=st.data())
def test_decode_never_raises_and_counts_every_report(name: str, data: st.DataObject) -> None:
    _decode_property(name, data)
