"""Descriptors the kernel fixes or forgives: skipped items with a warning, a replaced PD1011 descriptor, facts."""

from __future__ import annotations

import pytest

from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.descriptor import ReportDescriptor

# A plain pen: report 0x01, tip and in-range bits, X/Y 0..32767, pressure 0..1023.
PEN_HEAD = bytes.fromhex(
    "050d0902a101850109 20a100 1500250175019502094209328102 95068103"
    "050126ff7f751095010930810209318102 050d26ff0309308102".replace(" ", "")
)
PEN_TAIL = bytes.fromhex("c0c0")
RESERVED_ITEM = bytes.fromhex("0c")  # item type 3 (reserved), no data
UNKNOWN_MAIN = bytes.fromhex("d1ff")  # main item tag 0xD (not Input/Output/Feature/Collection), one data byte


def le16(v: int) -> bytes:
    return v.to_bytes(2, "little")


@pytest.mark.parametrize(("extra", "phrase"), [(RESERVED_ITEM, "reserved item type"),
                                               (UNKNOWN_MAIN, "unknown main item tag 0xd")])
def test_items_the_kernel_skips_are_skipped_with_a_warning(extra: bytes, phrase: str) -> None:
    raw = PEN_HEAD + extra + PEN_TAIL
    desc = ReportDescriptor.from_bytes(raw)
    assert len(desc.warnings) == 1 and phrase in desc.warnings[0]
    assert f"byte {len(PEN_HEAD)}" in desc.warnings[0]
    decoder = HidPenDecoder(raw, 0x1234, 0x5678)
    sample = decoder.decode(bytes([0x01, 0x03]) + le16(16384) + le16(8192) + le16(512), 0.0)
    assert sample is not None and sample.tip and sample.x == pytest.approx(0.5, abs=1e-4)
    assert phrase in decoder.stats.summary() and "warning:" in decoder.stats.summary()


def test_clean_descriptor_has_no_warning() -> None:
    assert ReportDescriptor.from_bytes(PEN_HEAD + PEN_TAIL).warnings == ()


def _pd1011_own_descriptor() -> bytes:
    """A stand-in for the PD1011's own 408-byte descriptor: one vendor-page collection, report 0x02 of 9 bytes."""
    head = bytes.fromhex("0600ff0901a10185020901150026ff00750895098102" "14")
    filler = bytes.fromhex("0901") * ((408 - len(head) - 1) // 2)
    raw = head + filler + bytes.fromhex("c0")
    assert len(raw) == 408
    return raw


def _pd1011_report(x: int, y: int, in_range: bool, tip: bool, pressure: int) -> bytes:
    """Report 0x02 as the fixed layout's facts place it: X, Y LE16, byte 5 bits 1 (range) and 2 (tip), pressure."""
    flags = (0x02 if in_range else 0) | (0x04 if tip else 0) | 0x01  # bit 0 is constant: set to show it is ignored
    return bytes([0x02]) + le16(x) + le16(y) + bytes([flags]) + le16(pressure) + bytes(2)


def test_pd1011_vendor_descriptor_decodes_through_the_fixed_layout() -> None:
    # No real PD1011 capture exists in ../shared/data/hid: descriptor and reports are built from the layout facts.
    decoder = HidPenDecoder(_pd1011_own_descriptor(), 0x0543, 0xE621)
    assert decoder.layouts[0x02].source == "viewsonic-pd1011"
    touching = decoder.decode(_pd1011_report(21696, 13560, True, True, 1026), 0.0)
    hovering = decoder.decode(_pd1011_report(43392, 0, True, False, 5), 0.01)
    leaving = decoder.decode(_pd1011_report(43392, 0, False, False, 5), 0.02)
    assert touching is not None and hovering is not None and leaving is not None
    assert (touching.x, touching.y) == (pytest.approx(0.5), pytest.approx(0.5))
    assert touching.p == pytest.approx((1026 - 5) / (2047 - 5)) and touching.tip and touching.range
    assert (hovering.x, hovering.y, hovering.tip, hovering.range, hovering.p) == (1.0, 0.0, False, True, 0.0)
    assert not leaving.range and not leaving.tip
    assert "PD1011" in decoder.stats.summary()


def test_a_kernel_fixed_pd1011_descriptor_is_read_as_it_is() -> None:
    """A capture made with the kernel's replacement descriptor declares report 0x02 itself: it is used as declared."""
    decoder = HidPenDecoder(PEN_HEAD.replace(b"\x85\x01", b"\x85\x02") + PEN_TAIL, 0x0543, 0xE621)
    assert decoder.layouts[0x02].source == "descriptor"


def test_device_facts_table_is_loaded_and_chooses_by_id_or_name() -> None:
    from physink_tui.input.hid.device_facts import all_facts, match_device
    from physink_tui.input.hid.fixed_layouts import FIXED_DEVICES

    facts = all_facts()
    assert len(facts) > 400
    assert match_device(0x0543, 0xE668).fact.model == "ViewSonic Woodpad PF1030"
    shared = match_device(0x256C, 0x006E)
    assert shared.fact is None and shared.candidates > 20
    named = match_device(0x256C, 0x006E, "HUION Kamvas Pro 13")
    assert named.fact is not None and named.fact.maxima == (58752, 33048, 8191)
    assert match_device(0x256C, 0x006E, "HUION Kamvas Pro 13 Ultra").fact.model == "Huion Kamvas Pro 13"
    assert (0x0543, 0xE621) in FIXED_DEVICES


# A 256c:006e interface after the kernel switched it on: only the vendor report 0x08, declared 8 bytes.
HUION_VENDOR_08 = bytes.fromhex("0600ff0901a101850875389501090181 02c0".replace(" ", ""))


def test_vendor_mode_huion_takes_maxima_from_the_facts_when_its_name_names_the_model() -> None:
    decoder = HidPenDecoder(HUION_VENDOR_08, 0x256C, 0x006E, name="HUION Kamvas Pro 13")
    layout = decoder.layouts[0x08]
    assert (layout.x.hi, layout.y.hi, layout.pressure.hi) == (58752, 33048, 8191)
    assert "Kamvas Pro 13" in decoder.stats.summary()
    x = 58752 // 2 + 70000  # a 24-bit X past the width still decodes (the range widens), 16-bit low part + byte 8
    report = bytes([0x08, 0x81]) + le16(x & 0xFFFF) + le16(33048) + le16(8191) + bytes([x >> 16, 0, 0, 0])
    sample = decoder.decode(report, 0.0)
    assert sample is not None and sample.tip and sample.y == 1.0 and sample.p == 1.0


def test_vendor_mode_huion_of_unknown_model_infers_maxima_with_a_warning() -> None:
    decoder = HidPenDecoder(HUION_VENDOR_08, 0x256C, 0x006E, name="HUION Huion Tablet")
    assert decoder.layouts[0x08].source == "huion-v2"
    assert "inferred from the largest values seen" in decoder.stats.summary()


def test_v2_maxima_assumed_without_facts_are_said_so() -> None:
    twelve = bytes.fromhex("0600ff0901a101850875589501090181 02c0".replace(" ", ""))
    decoder = HidPenDecoder(twelve, 0x256C, 0x006D, name="HUION Huion Tablet")
    assert (decoder.layouts[0x08].x.hi, decoder.layouts[0x08].y.hi) == (50800, 31750)
    assert "assumed x 50800, y 31750" in decoder.stats.summary()
