"""The ISDV4 / W8001 serial protocol: query replies, pen packets, resynchronisation, touch packets, fuzzing."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physink_tui.errors import DeviceError
from physink_tui.input.serial_tablets.isdv4 import (
    FALLBACK_QUERY,
    Isdv4Parser,
    Isdv4Query,
    encode_pen_packet,
    encode_query_reply,
    parse_query,
)

QUERY = Isdv4Query(x_max=26202, y_max=16325, p_max=1023, version=0x0105)


def packet(b0: int, x: int, y: int, p: int = 0, tilt: tuple[int, int] = (0, 0)) -> bytes:
    """A pen packet laid out by hand from the kernel's parse_pen_data, independent of `encode_pen_packet`."""
    b6 = ((x & 3) << 5) | ((y & 3) << 3) | ((p >> 7) & 7)
    return bytes([b0, (x >> 9) & 0x7F, (x >> 2) & 0x7F, (y >> 9) & 0x7F, (y >> 2) & 0x7F, p & 0x7F, b6, *tilt])


def test_hand_laid_packet_matches_the_encoder():
    expected = encode_pen_packet(12345, 6789, 777, tip=True, tilt_x=10, tilt_y=20)
    assert packet(0xA1, 12345, 6789, 777, (10, 20)) == expected
    assert packet(0x80, 0, 0) == encode_pen_packet(0, 0, proximity=False)


# --- query reply -----------------------------------------------------------------------------------------------


def test_parse_query_reads_maxima_and_version():
    # 26202 = 0x665A: bytes 1/2 carry bits 15..9 and 8..2, byte 6 bits 6..5 carry bits 1..0
    reply = bytes([0xC0, 0x33, 0x16, 0x1F, 0x71, 0x7F, 0x4F, 0x00, 0x00, 0x02, 0x05])
    q = parse_query(reply)
    assert q == Isdv4Query(x_max=26202, y_max=16325, p_max=1023, tilt_x_max=0, tilt_y_max=0, version=0x0105)
    assert q.has_pen and not q.has_tilt


def test_query_round_trips_and_reports_tilt():
    q = Isdv4Query(x_max=0xFFFF, y_max=1, p_max=255, tilt_x_max=127, tilt_y_max=63, version=0x3FFF)
    assert Isdv4Query.from_bytes(encode_query_reply(q)) == q
    assert q.has_tilt
    assert not Isdv4Query(0, 0, 0).has_pen


@pytest.mark.parametrize(
    ("data", "words"),
    [
        (bytes([0xC0, 1, 2, 3]), "4 bytes"),
        (bytes([0x80]) + bytes(10), "control bits"),  # a pen packet's first byte, not a control packet's
        (bytes([0x40]) + bytes(10), "control bits"),  # no sync bit
        (bytes([0xC0, 1, 2, 0x83]) + bytes(7), "sync bit inside"),
    ],
)
def test_bad_query_replies_raise_device_error(data, words):
    with pytest.raises(DeviceError, match=words):
        parse_query(data)


# --- pen packets -----------------------------------------------------------------------------------------------


def test_coordinates_and_pressure_scale_by_the_query():
    parser = Isdv4Parser(QUERY)
    [s] = parser.feed(packet(0xA1, 13101, 16325, 512), t=2.5)
    assert s.t == 2.5
    assert s.x == pytest.approx(13101 / 26202)
    assert s.y == 1.0
    assert s.p == pytest.approx(512 / 1023)
    assert (s.tip, s.range, s.eraser, s.b1, s.b2) == (True, True, False, False, False)
    assert (s.tilt_x, s.tilt_y, s.report) == (None, None, 0)
    assert parser.pen_packets == 1 and parser.bad_bytes == 0


def test_every_bit_of_x_y_and_pressure_lands_where_the_kernel_puts_it():
    parser = Isdv4Parser(FALLBACK_QUERY)  # maxima 0xFFFF and 0x3FF: raw value = normalised * max
    for bit in range(16):
        [s] = parser.feed(packet(0xA1, 1 << bit, 0xFFFF ^ (1 << bit), 1 << min(bit, 9)), t=0.0)
        assert round(s.x * 0xFFFF) == 1 << bit
        assert round(s.y * 0xFFFF) == 0xFFFF ^ (1 << bit)
        assert round(s.p * 0x3FF) == 1 << min(bit, 9)


def test_hover_touch_lift_and_leave():
    parser = Isdv4Parser(QUERY)
    stream = b"".join(
        [
            packet(0xA0, 100, 100, 0),  # in proximity, hovering
            packet(0xA1, 110, 110, 300),  # tip down
            packet(0xA0, 120, 120, 40),  # tip up: a pressure floor while hovering reads as 0
            packet(0x80, 120, 120, 0),  # out of proximity
        ]
    )
    samples = parser.feed(stream, t=1.0)
    assert [(s.range, s.tip) for s in samples] == [(True, False), (True, True), (True, False), (False, False)]
    assert [s.p for s in samples] == [0.0, pytest.approx(300 / 1023), 0.0, 0.0]


def test_side_switches_while_the_pen_is_in_proximity():
    parser = Isdv4Parser(QUERY)
    samples = parser.feed(
        packet(0xA0, 5, 5) + packet(0xA2, 5, 5) + packet(0xA4, 5, 5) + packet(0xA7, 5, 5, 9), t=0.0
    )
    assert [(s.b1, s.b2, s.eraser) for s in samples] == [
        (False, False, False),
        (True, False, False),
        (False, True, False),  # 0x04 after arriving as a pen: side switch 2, not the eraser
        (True, True, False),
    ]
    assert samples[-1].tip


def test_eraser_arrives_with_the_second_switch_set():
    parser = Isdv4Parser(QUERY)
    samples = parser.feed(packet(0xA4, 5, 5) + packet(0xA5, 6, 6, 200) + packet(0x84, 6, 6), t=0.0)
    assert [(s.eraser, s.range, s.tip, s.b2) for s in samples] == [
        (True, True, False, False),
        (True, True, True, False),  # the eraser rubbing: a tip, never "button 2"
        (True, False, False, False),
    ]
    # after leaving, the next arrival without the bit is the pen tip
    [s] = parser.feed(packet(0xA0, 7, 7), t=1.0)
    assert not s.eraser


def test_eraser_losing_its_bit_in_proximity_leaves_before_the_pen_arrives():
    parser = Isdv4Parser(QUERY)
    parser.feed(packet(0xA4, 5, 5), t=0.0)
    samples = parser.feed(packet(0xA0, 6, 6), t=1.0)
    assert [(s.eraser, s.range) for s in samples] == [(True, False), (False, True)]


def test_tilt_only_when_the_query_declares_it():
    with_tilt = Isdv4Parser(Isdv4Query(1000, 1000, 255, tilt_x_max=127, tilt_y_max=127))
    [s] = with_tilt.feed(packet(0xA0, 1, 1, 0, (64, 20)), t=0.0)
    assert (s.tilt_x, s.tilt_y) == (0.0, -44.0)
    [s] = Isdv4Parser(QUERY).feed(packet(0xA0, 1, 1, 0, (64, 20)), t=0.0)
    assert (s.tilt_x, s.tilt_y) == (None, None)


def test_values_past_the_queried_maximum_widen_it():
    parser = Isdv4Parser(Isdv4Query(1000, 1000, 255))
    samples = parser.feed(packet(0xA1, 2000, 500, 300) + packet(0xA0, 1000, 500), t=0.0)
    assert (samples[0].x, samples[0].p) == (1.0, 1.0)
    assert samples[1].x == 0.5
    assert parser.widened == {"x", "p"}
    # a packet out of proximity never widens
    parser.feed(packet(0x80, 1000, 3000), t=0.0)
    assert "y" not in parser.widened


def test_without_a_query_the_full_field_widths_are_used():
    parser = Isdv4Parser()
    assert parser.query is None
    [s] = parser.feed(packet(0xA1, 0xFFFF, 0x8000, 0x3FF), t=0.0)
    assert (s.x, s.y, s.p) == (1.0, pytest.approx(0x8000 / 0xFFFF), 1.0)


def test_a_control_packet_in_the_stream_replaces_the_maxima():
    parser = Isdv4Parser()
    samples = parser.feed(encode_query_reply(QUERY) + packet(0xA0, 13101, 0), t=0.0)
    assert parser.query == QUERY and parser.control_packets == 1
    assert [s.x for s in samples] == [pytest.approx(0.5)]


# --- framing ---------------------------------------------------------------------------------------------------

STROKE = [
    packet(0xA0, 1000, 900),
    packet(0xA1, 1100, 950, 100),
    packet(0xA3, 1200, 1000, 800),
    packet(0xA0, 1300, 1050, 0),
    packet(0x80, 1300, 1050, 0),
]


def test_packets_split_at_every_byte_boundary():
    stream = b"".join(STROKE)
    whole = Isdv4Parser(QUERY).feed(stream, t=0.0)
    assert len(whole) == 5
    for cut in range(len(stream) + 1):
        parser = Isdv4Parser(QUERY)
        parts = parser.feed(stream[:cut], t=0.0) + parser.feed(stream[cut:], t=0.0)
        assert parts == whole, cut
    parser = Isdv4Parser(QUERY)
    assert [s for b in stream for s in parser.feed(bytes([b]), t=0.0)] == whole
    assert parser.bad_bytes == 0


def test_garbage_between_packets_is_skipped_counted_and_resynchronised():
    parser = Isdv4Parser(QUERY)
    stream = b"\x01\x7f" + STROKE[0] + b"\x00\x55\x33" + STROKE[1] + STROKE[2]
    assert len(parser.feed(stream, t=0.0)) == 3
    assert parser.bad_bytes == 5
    assert parser.first_bad_reason == "byte 0x01 without the sync bit outside a packet"


def test_a_packet_cut_short_by_a_sync_byte_is_dropped_and_parsing_restarts_there():
    parser = Isdv4Parser(QUERY)
    stream = STROKE[0][:4] + STROKE[1] + STROKE[2][:8] + STROKE[3]
    samples = parser.feed(stream, t=0.0)
    assert [round(s.x * 26202) for s in samples] == [1100, 1300]
    assert parser.bad_bytes == 4 + 8
    assert parser.first_bad_reason == "pen packet 0xa0 cut short after 4 bytes by a new sync byte"


def test_over_long_packets_lose_only_their_extra_bytes():
    # the kernel notes ThinkPad X60s sending packets longer than 9 bytes
    parser = Isdv4Parser(QUERY)
    samples = parser.feed(STROKE[0] + b"\x11\x22" + STROKE[1], t=0.0)
    assert len(samples) == 2 and parser.bad_bytes == 2


@pytest.mark.parametrize("length", [5, 7, 13])
def test_touch_packets_are_not_pen_samples(length):
    touch = bytes([0x91]) + bytes(range(1, length))
    parser = Isdv4Parser(QUERY)
    samples = parser.feed(STROKE[0] + touch + STROKE[1] + touch[:3], t=0.0)
    samples += parser.feed(touch[3:] + STROKE[2], t=0.0)
    assert len(samples) == 3
    assert parser.touch_packets == 2 and parser.bad_bytes == 0


def test_an_incomplete_packet_waits_for_the_next_feed():
    parser = Isdv4Parser(QUERY)
    assert parser.feed(STROKE[0][:8], t=0.0) == []
    [s] = parser.feed(STROKE[0][8:], t=3.0)
    assert s.t == 3.0


# --- fuzzing ---------------------------------------------------------------------------------------------------


@settings(max_examples=300, deadline=None)
@given(chunks=st.lists(st.binary(max_size=40), max_size=30), query=st.sampled_from([None, QUERY, Isdv4Query(1, 1, 1)]))
def test_random_bytes_never_raise_and_samples_stay_in_range(chunks, query):
    parser = Isdv4Parser(query)
    for i, chunk in enumerate(chunks):
        for s in parser.feed(chunk, t=float(i)):
            assert 0.0 <= s.x <= 1.0 and 0.0 <= s.y <= 1.0 and 0.0 <= s.p <= 1.0
            assert s.range or not s.tip
    assert parser.bad_bytes <= sum(len(c) for c in chunks)


@settings(max_examples=200, deadline=None)
@given(
    packets=st.lists(
        st.tuples(st.integers(0, 0xFFFF), st.integers(0, 0xFFFF), st.integers(0, 0x3FF), st.integers(0, 7)),
        min_size=1,
        max_size=12,
    ),
    cuts=st.lists(st.integers(0, 200), max_size=8),
)
def test_any_chunking_of_valid_packets_gives_the_same_samples(packets, cuts):
    stream = b"".join(
        encode_pen_packet(x, y, p, tip=bool(f & 1), side1=bool(f & 2), side2=bool(f & 4)) for x, y, p, f in packets
    )
    whole = Isdv4Parser().feed(stream, t=0.0)
    assert len(whole) >= len(packets)  # plus one eraser-leaves sample per eraser-to-pen switch
    parser, got, start = Isdv4Parser(), [], 0
    for cut in [*sorted(c for c in cuts if c <= len(stream)), len(stream)]:
        got += parser.feed(stream[start:cut], t=0.0)
        start = cut
    assert got == whole and parser.bad_bytes == 0
    for s, (x, y, _p, _f) in zip([s for s in whole if s.range], packets, strict=True):
        assert round(s.x * 0xFFFF) == x and round(s.y * 0xFFFF) == y
