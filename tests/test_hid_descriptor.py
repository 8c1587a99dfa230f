"""Unit tests of the HID report descriptor parser on hand-written descriptor bytes."""

from __future__ import annotations

import pytest

from physink_tui.errors import DescriptorError
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.descriptor import (
    FEATURE,
    INPUT,
    MAX_REPORT_COUNT,
    MAX_REPORT_SIZE_BITS,
    OUTPUT,
    Field,
    ReportDescriptor,
)
from physink_tui.input.hid.pen_layout import pen_layouts

GD_X, GD_Y, GD_MOUSE = 0x0001_0030, 0x0001_0031, 0x0001_0002
DG_PEN, DG_STYLUS = 0x000D_0002, 0x000D_0020
DG_TIP_PRESSURE, DG_IN_RANGE, DG_TIP_SWITCH = 0x000D_0030, 0x000D_0032, 0x000D_0042


def parse(hex_text: str) -> ReportDescriptor:
    return ReportDescriptor.from_bytes(bytes.fromhex(hex_text))


def input_fields(desc: ReportDescriptor, report_id: int = 0) -> tuple[Field, ...]:
    report = desc.input_report(report_id)
    assert report is not None, f"no input report 0x{report_id:02x}"
    return report.fields


# A mouse application around the items under test: Usage Page (GD), Usage (Mouse), Collection (Application).
HEAD = "05 01 09 02 a1 01"
TAIL = "c0"


def wrap(items: str) -> str:
    return f"{HEAD} {items} {TAIL}"


# -- item sizes and long items ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("items", "expected_max"),
    [
        ("25 7f", 127),
        ("26 34 12", 0x1234),
        ("27 78 56 34 12", 0x12345678),
        ("25 7f 24", 0),  # size 0: the value is 0
    ],
    ids=["1-byte", "2-byte", "4-byte", "0-byte"],
)
def test_item_data_sizes(items: str, expected_max: int) -> None:
    desc = parse(wrap(f"09 30 15 00 {items} 75 20 95 01 81 02"))
    (x,) = input_fields(desc)
    assert x.logical_max == expected_max
    assert x.usages == (GD_X,)


def test_zero_size_main_item_is_an_array_input() -> None:
    desc = parse(wrap("05 09 19 01 29 03 15 01 25 03 75 02 95 01 80"))  # 0x80: Input, no data byte
    (f,) = input_fields(desc)
    assert f.flags == 0 and not f.is_variable


def test_four_byte_main_item_data() -> None:
    desc = parse(wrap("09 30 15 00 25 7f 75 08 95 01 83 02 00 00 00"))
    (f,) = input_fields(desc)
    assert f.flags == 0x02 and f.is_variable


@pytest.mark.parametrize("long_item", ["fe 00 10", "fe 03 10 aa bb cc", "fe 02 f1 81 02"],
                         ids=["empty", "three-bytes", "data-looks-like-items"])
def test_long_items_are_skipped(long_item: str) -> None:
    plain = parse(wrap("09 30 15 00 25 7f 75 08 95 01 81 02"))
    with_long = parse(wrap(f"09 30 {long_item} 15 00 25 7f 75 08 95 01 81 02"))
    assert input_fields(with_long)[0].usages == (GD_X,)
    assert [(f.bit_offset, f.size, f.count, f.usages) for f in input_fields(with_long)] == [
        (f.bit_offset, f.size, f.count, f.usages) for f in input_fields(plain)
    ]


# -- global state: push/pop, report ids, bit offsets -----------------------------------------------------


def test_push_and_pop_restore_global_state() -> None:
    desc = parse(
        "05 0d 09 02 a1 01 85 01 15 00 26 ff 7f 75 10 95 01"
        " a4"  # Push: page Digitizer, size 16, report 1
        " 05 01 09 30 75 08 85 02 81 02"  # X, 8 bits, in report 2
        " b4"  # Pop
        " 09 30 81 02"  # usage 0x30 on the restored Digitizer page is Tip Pressure, 16 bits, report 1
        " c0"
    )
    (x,) = input_fields(desc, 2)
    (pressure,) = input_fields(desc, 1)
    assert (x.usages, x.size, x.bit_offset) == ((GD_X,), 8, 8)
    assert (pressure.usages, pressure.size, pressure.bit_offset) == ((DG_TIP_PRESSURE,), 16, 8)


def test_nested_push_pop() -> None:
    desc = parse(wrap("95 01 75 04 a4 75 08 a4 75 10 b4 09 30 81 02 b4 09 31 81 02"))
    x, y = input_fields(desc)
    assert (x.size, y.size) == (8, 4)
    assert (x.bit_offset, y.bit_offset) == (0, 8)


def test_report_ids_and_bit_offsets() -> None:
    desc = parse(
        "05 0d 09 02 a1 01"
        " 85 01 09 42 15 00 25 01 75 01 95 01 81 02"  # report 1: Tip Switch @ bit 8
        " 75 07 81 03"  # 7 padding bits @ 9
        " 05 01 09 30 26 ff 7f 75 10 95 01 81 02"  # X @ 16
        " 85 02 05 0d 09 30 26 ff 03 81 02"  # report 2: Tip Pressure @ 8
        " 85 01 05 01 09 31 26 ff 7f 81 02"  # back to report 1: Y @ 32
        " 85 03 06 00 ff 09 01 75 08 95 04 b1 02"  # feature report 3, 4 bytes of data
        " 85 01 09 01 75 08 95 02 91 02"  # output report 1 has its own bit counter
        " c0"
    )
    assert desc.uses_report_ids
    r1 = desc.input_report(1)
    assert r1 is not None and r1.size_bytes == 6
    layout = [(f.bit_offset, f.size, f.count) for f in r1.fields]
    assert layout == [(8, 1, 1), (9, 7, 1), (16, 16, 1), (32, 16, 1)]
    assert [f.usages for f in r1.fields] == [(DG_TIP_SWITCH,), (), (GD_X,), (GD_Y,)]
    assert all(f.report_id == 1 and f.kind == INPUT for f in r1.fields)
    r2 = desc.input_report(2)
    assert r2 is not None and r2.size_bytes == 3 and r2.fields[0].bit_offset == 8
    assert desc.input_report(3) is None
    feature = desc.reports[(FEATURE, 3)]
    assert feature.size_bytes == 5 and feature.fields[0].usages == (0xFF00_0001,)
    output = desc.reports[(OUTPUT, 1)]
    assert output.size_bytes == 3 and output.fields[0].bit_offset == 8
    assert [r.report_id for r in desc.input_reports()] == [1, 2]


def test_descriptor_without_report_ids() -> None:
    desc = parse(wrap("09 30 09 31 15 00 26 ff 0f 75 0c 95 02 81 02"))
    assert not desc.uses_report_ids
    report = desc.input_report(0)
    assert report is not None and report.size_bytes == 3  # 24 bits
    (f,) = report.fields
    assert (f.report_id, f.bit_offset, f.size, f.count) == (0, 0, 12, 2)


def test_size_bytes_rounds_up() -> None:
    desc = parse(wrap("85 05 09 30 15 00 25 01 75 01 95 03 81 02"))
    report = desc.input_report(5)
    assert report is not None and report.size_bytes == 2  # id byte + 3 bits


# -- local items: usages -----------------------------------------------------------------------------------


def test_usage_minimum_maximum_on_a_variable_field() -> None:
    desc = parse(wrap("05 09 19 01 29 03 15 00 25 01 75 01 95 03 81 02"))
    (buttons,) = input_fields(desc)
    assert buttons.usages == (0x0009_0001, 0x0009_0002, 0x0009_0003)
    assert [buttons.usage_at(i) for i in range(3)] == list(buttons.usages)


def test_usage_range_on_an_array_field() -> None:
    desc = parse(wrap("05 09 19 01 29 08 15 01 25 08 75 08 95 02 81 00"))
    (keys,) = input_fields(desc)
    assert not keys.is_variable
    assert keys.usages == tuple(0x0009_0000 + i for i in range(1, 9))
    assert (keys.count, keys.size) == (2, 8)


def test_usage_maximum_without_minimum_is_ignored() -> None:
    desc = parse(wrap("09 30 29 05 15 00 25 7f 75 08 95 01 81 02"))
    assert input_fields(desc)[0].usages == (GD_X,)


def test_variable_field_repeats_its_last_usage() -> None:
    desc = parse(wrap("09 30 09 31 15 00 25 7f 75 08 95 04 81 02"))
    (f,) = input_fields(desc)
    assert [f.usage_at(i) for i in range(4)] == [GD_X, GD_Y, GD_Y, GD_Y]


@pytest.mark.parametrize(
    ("usage_items", "expected"),
    [
        ("0b 30 00 01 00", (GD_X,)),  # a 4-byte usage names its own page (Generic Desktop)
        ("0a 30 01", (0x000D_0130,)),  # 2-byte usage takes the current page
        ("1b 01 00 09 00 2b 03 00 09 00", (0x0009_0001, 0x0009_0002, 0x0009_0003)),  # extended min and max
        ("1b 01 00 09 00 29 03", (0x0009_0001, 0x0009_0002, 0x0009_0003)),  # extended min, short max
    ],
    ids=["usage", "two-byte-usage", "usage-min-max", "mixed-min-max"],
)
def test_extended_32_bit_usages(usage_items: str, expected: tuple[int, ...]) -> None:
    desc = parse(f"05 0d 09 02 a1 01 {usage_items} 15 00 25 01 75 01 95 {len(expected):02x} 81 02 c0")
    assert input_fields(desc)[0].usages == expected


def test_usage_page_is_applied_at_the_main_item() -> None:
    # hid-core semantics: a short usage takes the page current when the main item is reached
    desc = parse(wrap("05 0d 09 30 05 01 15 00 25 7f 75 08 95 01 81 02"))
    assert input_fields(desc)[0].usages == (GD_X,)


# -- logical and physical ranges, units ----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("items", "lo", "hi", "signed"),
    [
        ("15 81 25 7f", -127, 127, True),
        ("15 80 25 7f", -128, 127, True),
        ("16 00 80 26 ff 7f", -32768, 32767, True),
        ("17 00 00 00 80 27 ff ff ff 7f", -(2**31), 2**31 - 1, True),
        ("15 a6 25 5a", -90, 90, True),
        ("15 00 25 ff", 0, 255, False),  # minimum >= 0: the maximum is unsigned, as in hid-core
        ("15 00 26 ff ff", 0, 65535, False),
        ("15 01 26 00 80", 1, 32768, False),
    ],
    ids=["s8", "s8-full", "s16", "s32", "tilt", "u8-maximum-0xff", "u16-maximum-0xffff", "u16-from-1"],
)
def test_logical_ranges(items: str, lo: int, hi: int, signed: bool) -> None:
    desc = parse(wrap(f"09 30 {items} 75 20 95 01 81 02"))
    (f,) = input_fields(desc)
    assert (f.logical_min, f.logical_max, f.is_signed) == (lo, hi, signed)
    assert (f.physical_min, f.physical_max) == (lo, hi)  # physical range unset: the logical one


def test_physical_range_and_unit() -> None:
    desc = parse(wrap("09 30 15 81 25 7f 35 c4 45 3c 65 14 55 0e 75 08 95 01 81 02"))
    (f,) = input_fields(desc)
    assert (f.physical_min, f.physical_max) == (-60, 60)
    assert (f.unit, f.unit_exponent) == (0x14, -2)


@pytest.mark.parametrize(
    ("item", "exponent"),
    [("55 00", 0), ("55 02", 2), ("55 07", 7), ("55 08", -8), ("55 0d", -3), ("55 0e", -2), ("55 0f", -1),
     ("57 fe ff ff ff", -2)],
    ids=["0", "2", "7", "nibble-8", "nibble-d", "nibble-e", "nibble-f", "four-byte-signed"],
)
def test_unit_exponent_nibble(item: str, exponent: int) -> None:
    desc = parse(wrap(f"09 30 15 00 25 7f {item} 75 08 95 01 81 02"))
    assert input_fields(desc)[0].unit_exponent == exponent


# -- field kinds -------------------------------------------------------------------------------------------


def test_padding_fields() -> None:
    desc = parse(wrap("09 30 15 00 25 01 75 01 95 01 81 02 75 05 95 01 81 03 09 31 75 02 81 02"))
    x, pad, y = input_fields(desc)
    assert pad.usages == () and pad.is_constant and (pad.bit_offset, pad.size) == (1, 5)
    assert "padding" in pad.describe()
    assert (x.bit_offset, y.bit_offset) == (0, 6)
    assert not x.is_constant


def test_zero_width_field_takes_no_bits() -> None:
    desc = parse(wrap("09 30 15 00 25 01 75 08 95 00 81 02 09 31 95 01 81 02"))
    (y,) = input_fields(desc)
    assert (y.usages, y.bit_offset) == ((GD_Y,), 0)


def test_array_vs_variable_vs_relative() -> None:
    desc = parse(wrap(
        "05 09 19 01 29 03 15 00 25 03 75 02 95 01 81 00"  # array of button indices
        " 19 01 29 03 25 01 75 01 95 03 81 02"  # variable buttons
        " 05 01 09 30 15 81 25 7f 75 08 95 01 81 06"  # relative X
    ))
    array, variable, rel = input_fields(desc)
    assert not array.is_variable and array.usages == (0x0009_0001, 0x0009_0002, 0x0009_0003)
    assert variable.is_variable and not variable.is_relative
    assert rel.is_relative and rel.is_variable and rel.is_signed
    assert [f.bit_offset for f in (array, variable, rel)] == [0, 2, 5]


def test_fields_know_their_collections() -> None:
    desc = parse(
        "05 0d 09 02 a1 01 85 02 09 20 a1 00 09 42 15 00 25 01 75 01 95 01 81 02 c0 c0"
    )
    (tip,) = input_fields(desc, 2)
    assert [(c.kind, c.usage) for c in tip.collections] == [(1, DG_PEN), (0, DG_STYLUS)]
    assert tip.application == DG_PEN
    assert [c.offset for c in desc.collections] == [4, 10]
    assert tip.offset == 22


def test_kernel_limits_are_accepted() -> None:
    assert (MAX_REPORT_SIZE_BITS, MAX_REPORT_COUNT) == (256, 12288)
    desc = parse(wrap("09 30 15 00 25 01 76 00 01 95 01 81 02 75 01 96 00 30 81 03"))
    size_field, count_field = input_fields(desc)
    assert size_field.size == 256
    assert count_field.count == 12288


# -- broken descriptors --------------------------------------------------------------------------------------


BROKEN = [
    ("empty", "", 0),
    ("truncated-item-data", "05 01 09 02 a1 01 26 ff", 6),
    ("truncated-4-byte-item", "05 01 27 ff ff", 2),
    ("truncated-long-item", "05 01 fe 04 00 aa", 2),
    ("long-item-header-only", "05 01 fe 00", 2),
    ("end-collection-without-collection", "05 01 09 02 c0", 4),
    ("unclosed-collection", "05 01 09 02 a1 01 09 01 a1 00 c0", 4),
    ("pop-without-push", "05 01 a4 b4 b4", 4),
    ("report-size-300", "05 01 09 02 a1 01 76 2c 01 c0", 6),
    ("report-count-20000", "05 01 09 02 a1 01 96 20 4e c0", 6),
    ("report-id-0", "05 01 09 02 a1 01 85 00 c0", 6),
    ("report-id-256", "05 01 86 00 01", 2),
    ("reversed-usage-range", "05 09 19 05 29 01", 4),
    ("report-past-16-KiB", "05 01 09 02 a1 01 76 00 01 96 00 30 81 02 c0", 12),
]


@pytest.mark.parametrize(
    ("hex_text", "offset"), [(h, o) for _, h, o in BROKEN], ids=[n for n, _, _ in BROKEN]
)
def test_broken_descriptor_raises_with_offset(hex_text: str, offset: int) -> None:
    with pytest.raises(DescriptorError) as info:
        parse(hex_text)
    assert info.value.offset == offset
    assert f"(at descriptor byte {offset})" in str(info.value)


# -- pen layouts from hand-written pen descriptors -----------------------------------------------------------


def windows_ink_pen(with_x: bool = True, with_y: bool = True) -> bytes:
    """A Windows-Ink style pen report 0x02: 5 switch bits, 3 padding, X/Y 16 bit, pressure 16 bit, tilt."""
    x = "09 30 " if with_x else ""
    y = "09 31 " if with_y else ""
    count = int(with_x) + int(with_y)
    xy = f"05 01 {x}{y}26 ff 7f 75 10 95 {count:02x} 81 02 " if count else ""
    return bytes.fromhex(
        "05 0d 09 02 a1 01 85 02 09 20 a1 00"
        " 09 42 09 44 09 45 09 3c 09 32 15 00 25 01 75 01 95 05 81 02 95 03 81 03 "
        + xy
        + "05 0d 09 30 15 00 26 ff 1f 75 10 95 01 81 02"
        " 09 3d 09 3e 15 a6 25 5a 75 08 95 02 81 02"
        " c0 c0"
    )


def test_windows_ink_pen_yields_a_layout() -> None:
    layouts = pen_layouts(ReportDescriptor.from_bytes(windows_ink_pen()))
    lay = layouts[0x02]
    assert lay.length == 10 and lay.source == "descriptor"
    assert (lay.tip, lay.b1, lay.eraser, lay.invert, lay.in_range) == (8, 9, 10, 11, 12)
    assert lay.x.parts == ((16, 16),) and lay.y.parts == ((32, 16),) and lay.pressure.parts == ((48, 16),)
    assert (lay.x.lo, lay.x.hi, lay.pressure.hi) == (0, 32767, 8191)
    assert lay.tilt_x is not None and lay.tilt_x.signed and (lay.tilt_x.lo, lay.tilt_x.hi) == (-90, 90)


@pytest.mark.parametrize(("with_x", "with_y"), [(False, True), (True, False), (False, False)],
                         ids=["no-x", "no-y", "no-x-no-y"])
def test_pen_report_without_x_or_y_yields_no_layout(with_x: bool, with_y: bool) -> None:
    raw = windows_ink_pen(with_x, with_y)
    desc = ReportDescriptor.from_bytes(raw)
    report = desc.input_report(0x02)
    assert report is not None and any(DG_TIP_SWITCH in f.usages for f in report.fields)
    assert pen_layouts(desc) == {}
    with pytest.raises(DescriptorError, match="no pen report") as info:
        HidPenDecoder(raw)
    assert info.value.offset is None
