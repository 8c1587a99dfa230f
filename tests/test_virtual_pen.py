"""The virtual pen, its report encoder and descriptor builder, and the recordings in tests/recorded_hid/."""

from __future__ import annotations

import importlib.util
import itertools
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physink_tui.input.captures.capture import Capture
from physink_tui.input.captures.writer import format_capture
from physink_tui.input.hid import descriptor_builder as d
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.descriptor import ReportDescriptor
from physink_tui.input.hid.pen_decoder import CompiledLayout
from physink_tui.input.hid.pen_layout import PenLayout
from physink_tui.input.hid.reference_descriptors import REFERENCE_DEVICES
from physink_tui.input.hid.report_encoder import PenState, encode_report
from physink_tui.input.hid.vendor_layouts import (
    TabletParams,
    uclogic_v1_layout,
    wacom_graphire_layout,
    wacom_penpartner_layout,
)
from physink_tui.input.virtual_pen import Stroke, VirtualPen

RECORDED = Path(__file__).parent / "recorded_hid"


def _load_make_recordings():
    spec = importlib.util.spec_from_file_location("make_recordings", RECORDED / "make_recordings.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


make = _load_make_recordings()
FILES = sorted(make.RECORDINGS)


def _decoder_for(device_id: str) -> HidPenDecoder:
    dev = REFERENCE_DEVICES[device_id]
    return HidPenDecoder(dev.descriptor, dev.vid, dev.pid, protocol=dev.protocol)


# -- the recordings ---------------------------------------------------------------------------------


def test_every_recording_is_on_disk_and_nothing_else() -> None:
    assert sorted(p.name for p in RECORDED.glob("*.hid")) == FILES


@pytest.mark.parametrize("name", FILES, ids=FILES)
def test_recording_decodes_to_the_script(name: str) -> None:
    capture = Capture.from_file(RECORDED / name)
    assert not capture.bad_lines
    assert (RECORDED / name).stat().st_size < 200_000
    rec = make.RECORDINGS[name]
    device = capture.devices[0]
    assert device.descriptor == REFERENCE_DEVICES[rec.device].descriptor
    assert (device.bus, device.vid, device.pid) == (3, REFERENCE_DEVICES[rec.device].vid,
                                                    REFERENCE_DEVICES[rec.device].pid)
    assert any(c.startswith("physink virtual pen: ") for c in device.comments)
    truth = make.pen_for(name).samples(make.DRAWING)
    decoder = _decoder_for(rec.device)
    decoded = [decoder.decode(e.data, e.t, e.line) for e in capture.events]
    assert None not in decoded, decoder.stats.summary()
    assert len(decoded) == len(truth)
    assert [e.t for e in capture.events] == [g.t for g in truth]

    runs = sum(1 for prev, s in itertools.pairwise([None, *decoded]) if s.tip and not (prev and prev.tip))
    assert runs == len(make.DRAWING)
    for s, g in zip(decoded, truth, strict=True):
        assert 0.0 <= s.p <= 1.0
        assert s.tip == g.state.tip, (s, g)
        if g.state.tip:
            assert abs(s.x - g.state.x) <= 0.01 and abs(s.y - g.state.y) <= 0.01, (s, g)
            assert s.p > 0.0
    assert [i for i, s in enumerate(decoded) if not s.range] == [
        i for i, g in enumerate(truth) if g.phase == "leave"
    ]
    assert [i for i, g in enumerate(truth) if not g.state.in_range] == [
        i for i, g in enumerate(truth) if g.phase == "leave"
    ]


@pytest.mark.parametrize("name", FILES, ids=FILES)
def test_regenerating_gives_the_same_bytes(name: str) -> None:
    assert make.render(name) == (RECORDED / name).read_text(encoding="utf-8")


def test_padding_file_sets_unused_bits() -> None:
    capture = Capture.from_file(RECORDED / "xp-pen-style-padding.hid")
    assert all(e.data[1] & 0b1011_1000 == 0b1011_1000 for e in capture.events)  # bits 11-13 and 15 of 0x07
    plain = Capture.from_file(RECORDED / "uclogic-v1-strokes.hid")
    assert all(e.data[1] & 0b1011_1000 == 0 for e in plain.events)


# -- the virtual pen ------------------------------------------------------------------------------


def test_timestamps_never_decrease_and_follow_the_rate() -> None:
    pen = VirtualPen(REFERENCE_DEVICES["windows-ink"], rate_hz=100.0, jitter_s=0.002, seed=7)
    times = [s.t for s in pen.samples(make.DRAWING, start_t=1.0)]
    assert times == sorted(times) and times[0] >= 0.99
    steps = [b - a for a, b in itertools.pairwise(times) if b - a < 0.2]
    assert abs(sum(steps) / len(steps) - 0.01) < 0.001


def test_same_seed_same_capture_other_seed_other_capture() -> None:
    dev = REFERENCE_DEVICES["wacom-ff0d"]
    a = format_capture(VirtualPen(dev, seed=3).record(make.DRAWING))
    assert a == format_capture(VirtualPen(dev, seed=3).record(make.DRAWING))
    assert a != format_capture(VirtualPen(dev, seed=4).record(make.DRAWING))


def test_speed_is_slow_fast_slow() -> None:
    pen = VirtualPen(REFERENCE_DEVICES["windows-ink"], jitter_s=0.0, position_noise=0.0)
    touch = [s.state for s in pen.samples([Stroke.line((0.1, 0.5), (0.9, 0.5))]) if s.phase == "touch"]
    steps = [b.x - a.x for a, b in itertools.pairwise(touch)]
    assert all(step >= 0 for step in steps)
    assert max(steps) > 10 * steps[0] and max(steps) > 10 * steps[-1]
    assert touch[0].x == pytest.approx(0.1) and touch[-1].x == pytest.approx(0.9)
    assert touch[0].p < 0.1 and touch[-1].p < 0.1 and max(t.p for t in touch) > 0.3


def test_the_pen_picks_the_protocol_report() -> None:
    expected = {"windows-ink": 0x02, "wacom-ff0d": 0x10, "uclogic-v1": 0x07, "huion-v2": 0x08}
    for device_id, report_id in expected.items():
        assert report_id in _decoder_for(device_id).layouts
        assert VirtualPen(REFERENCE_DEVICES[device_id]).layout.report_id == report_id
    dev = REFERENCE_DEVICES["uclogic-v1"]
    assert VirtualPen((dev.descriptor, dev.vid, dev.pid, None), report_id=0x09).layout.source == "mouse-mode"
    with pytest.raises(ValueError, match="no pen layout"):
        VirtualPen(dev, report_id=0x03)


def test_stroke_validates_its_points() -> None:
    with pytest.raises(ValueError, match="outside the active area"):
        Stroke(((0.5, 1.5),))
    with pytest.raises(ValueError, match="at least one point"):
        Stroke(())
    dot = VirtualPen(REFERENCE_DEVICES["windows-ink"]).samples([Stroke(((0.5, 0.5),))])
    assert all(s.state.x == 0.5 for s in dot if s.phase == "touch")


# -- encoder: round trip through the decoder --------------------------------------------------------

LAYOUTS = [(f"{dev_id}-0x{rid:02x}", lay) for dev_id in REFERENCE_DEVICES
           for rid, lay in _decoder_for(dev_id).layouts.items()]
# vendor layouts no reference descriptor reaches: inverted in-range bit, tool codes, signed pressure
LAYOUTS += [
    ("vendor-uclogic-v1", uclogic_v1_layout(TabletParams(40000, 25000, 2047))),
    ("vendor-wacom-graphire", wacom_graphire_layout(TabletParams(10206, 7422, 511))),
    ("vendor-wacom-penpartner", wacom_penpartner_layout(TabletParams(5040, 3780, 255))),
]


@st.composite
def pen_states(draw) -> PenState:
    unit = st.floats(0.0, 1.0, allow_nan=False)
    tilt = st.floats(-90.0, 90.0, allow_nan=False)
    in_range = draw(st.booleans())
    flag = st.booleans() if in_range else st.just(False)
    return PenState(draw(unit), draw(unit), draw(unit), draw(flag), in_range, draw(flag), draw(flag),
                    draw(flag), draw(tilt), draw(tilt))


def _expresses_eraser(layout: PenLayout) -> bool:
    """Whether a hovering eraser can be told from the pen (Invert and Eraser bits, or a tool code)."""
    if layout.tool is not None:
        return bool(layout.eraser_tools)
    return not layout.eraser_is_button and layout.invert is not None and layout.eraser is not None


@pytest.mark.parametrize("padding_ones", [False, True], ids=["zeros", "ones"])
@pytest.mark.parametrize("layout", [lay for _, lay in LAYOUTS], ids=[name for name, _ in LAYOUTS])
@settings(max_examples=150, deadline=None)
@given(state=pen_states())
def test_encode_decode_round_trip(layout: PenLayout, padding_ones: bool, state: PenState) -> None:
    report = encode_report(layout, state, padding_ones=padding_ones)
    assert len(report) == layout.length and report[0] == layout.report_id
    compiled = CompiledLayout(layout)
    if layout.learn_in_range:  # a lone report cannot teach polarity: test the inverse with it known
        compiled.in_range_value = 0 if layout.in_range_inverted else 1
    s = compiled.decode(report, 0.0)
    assert not isinstance(s, str), s
    assert s.tip == state.tip
    assert s.b1 == (state.b1 and layout.b1 is not None)
    assert s.b2 == (state.b2 and layout.b2 is not None)
    assert s.range == (state.in_range if layout.in_range is not None else True)
    assert s.eraser == (state.eraser and _expresses_eraser(layout))
    for got, want, v in ((s.x, state.x, layout.x), (s.y, state.y, layout.y)):
        assert abs(got - want) <= 1.0 / (v.hi - v.lo) + 1e-12
    if layout.pressure is not None:
        expected_p = state.p if state.tip else 0.0
        assert abs(s.p - expected_p) <= 1.0 / (layout.pressure.hi - layout.pressure.lo) + 1e-12
        assert (s.p > 0.0) == state.tip
    for got, want, v in ((s.tilt_x, state.tilt_x, layout.tilt_x), (s.tilt_y, state.tilt_y, layout.tilt_y)):
        if v is None:
            assert got is None
        else:
            want = min(max(want, v.lo * v.scale + v.offset), v.hi * v.scale + v.offset)
            assert math.isclose(got, want, abs_tol=abs(v.scale))


def test_windows_ink_eraser_bits() -> None:
    layout = _decoder_for("windows-ink").layouts[0x02]
    hover = encode_report(layout, PenState(0.5, 0.5, eraser=True))
    touch = encode_report(layout, PenState(0.5, 0.5, 0.5, tip=True, eraser=True))
    pen = encode_report(layout, PenState(0.5, 0.5, 0.5, tip=True))
    # byte 1: tip 0x01, barrel 0x02, eraser 0x04, invert 0x08, secondary barrel 0x10, in range 0x20
    assert (hover[1], touch[1], pen[1]) == (0x28, 0x2C, 0x21)


def test_out_of_range_report_clears_in_range_bit_and_pressure() -> None:
    layout = _decoder_for("wacom-ff0d").layouts[0x10]
    report = encode_report(layout, PenState(0.25, 0.75, 0.9, in_range=False))
    assert report[1] == 0 and report[8:10] == b"\0\0"
    assert int.from_bytes(report[2:5], "little") == 11200


# -- descriptor builder -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("item", "expected"),
    [
        (d.logical_maximum(255), "26 ff 00"),
        (d.logical_minimum(-127), "15 81"),
        (d.logical_maximum(127), "25 7f"),
        (d.logical_maximum(128), "26 80 00"),
        (d.logical_minimum(-128), "15 80"),
        (d.logical_minimum(-129), "16 7f ff"),
        (d.logical_maximum(32767), "26 ff 7f"),
        (d.logical_maximum(32768), "27 00 80 00 00"),
        (d.logical(0, 1), "15 00 25 01"),
        (d.physical(-64, 63), "35 c0 45 3f"),
        (d.usage_page(0x0D), "05 0d"),
        (d.usage_page(0xFF0D), "06 0d ff"),
        (d.usage(0x42), "09 42"),
        (d.usage(0x130), "0a 30 01"),
        (d.usage(0xFF0D0130), "0b 30 01 0d ff"),
        (d.usage_range(1, 3), "19 01 29 03"),
        (d.unit(d.UNIT_DEGREES), "65 14"),
        (d.unit_exponent(-2), "55 0e"),
        (d.unit_exponent(0), "55 00"),
        (d.report_size(24), "75 18"),
        (d.report_count(11), "95 0b"),
        (d.report_id(0x10), "85 10"),
        (d.input(d.DATA_VARIABLE), "81 02"),
        (d.input(d.CONSTANT), "81 01"),
        (d.collection("application"), "a1 01"),
        (d.collection(0), "a1 00"),
        (d.end_collection(), "c0"),
        (d.push(), "a4"),
        (d.pop(), "b4"),
    ],
)
def test_builder_item_encodings(item: bytes, expected: str) -> None:
    assert item == bytes.fromhex(expected)


@pytest.mark.parametrize(
    "call",
    [lambda: d.logical_maximum(1 << 31), lambda: d.report_id(0), lambda: d.report_id(256),
     lambda: d.unit_exponent(8), lambda: d.usage(-1), lambda: d.collection("bogus")],
)
def test_builder_rejects_values_it_cannot_encode(call) -> None:
    with pytest.raises(ValueError):
        call()


@settings(max_examples=200, deadline=None)
@given(lo=st.integers(-(1 << 31), (1 << 31) - 1), hi=st.integers(-(1 << 31), (1 << 31) - 1))
def test_builder_logical_range_reads_back(lo: int, hi: int) -> None:
    lo, hi = min(lo, hi), max(lo, hi)
    desc = d.build(d.usage_page(1), d.usage(0x30), d.collection("application"), d.logical(lo, hi),
                   d.report_size(32), d.report_count(1), d.input(), d.end_collection())
    (field,) = ReportDescriptor.from_bytes(desc).input_report(0).fields
    assert (field.logical_min, field.logical_max) == (lo, hi)
