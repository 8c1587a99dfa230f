"""Reading and writing the hid-recorder text format, on small captures written here."""

from __future__ import annotations

import dataclasses
import os

import pytest

from physink_tui.errors import CaptureFormatError
from physink_tui.input.captures.capture import (
    BAD_TEXT_MAX,
    BadLine,
    Capture,
    CaptureDevice,
    CaptureEvent,
)
from physink_tui.input.captures.writer import format_capture, write_capture

DESCRIPTOR = bytes.fromhex("05 0d 09 02 a1 01 85 02 c0 c0")
BEFORE_R = "event before the report descriptor ('R:' line) of device"
PEN = CaptureDevice(0, "Pen", None, 3, 0x056A, 0x0350, b"\xa1\xc0")

# What the Python hid-recorder writes for one device (descriptor dump shortened), byte for byte.
RECORDER_TEXT = """\
# Wacom Test Pen
# 0x05, 0x0d,  // Usage Page (Digitizers)
R: 10 05 0d 09 02 a1 01 85 02 c0 c0
N: Wacom Test Pen
I: 3 056a 0350
# ReportID: 2 / Tip Switch: 1
E: 000000.000000 4 02 01 10 00
# ReportID: 2 / Tip Switch: 0
E: 000001.959698 4 02 00 00 00
"""

# Two hidraw nodes recorded together, as `hid-recorder /dev/hidraw0 /dev/hidraw1` writes them.
MULTI_TEXT = """\
# recorded on a test machine
D: 0
# Pen
R: 10 05 0d 09 02 a1 01 85 02 c0 c0
N: Pen
P: usb-0000:00:14.0-1/input0
I: 3 056a 0350
D: 1
# Keys
R: 2 a1 c0
N: Keys
I: 3 056a 0351
D: 1
E: 000000.000000 2 01 02
D: 0
# ReportID: 2
E: 000000.010000 4 02 01 10 00
E: 000000.020000 4 02 00 10 00
D: 1
E: 000000.030000 2 01 00
"""


def _capture(*body: str, header: str = "R: 10 05 0d 09 02 a1 01 85 02 c0 c0\nN: Pen\n") -> Capture:
    return Capture.from_text(header + "".join(line + "\n" for line in body))


def _events(capture: Capture) -> list[tuple[float, bytes, int]]:
    return [(e.t, e.data, e.device) for e in capture.events]


# --- reading --------------------------------------------------------------------------------------


def test_reads_what_hid_recorder_writes() -> None:
    capture = Capture.from_text(RECORDER_TEXT, path="pen.hid")

    assert capture.path == "pen.hid"
    assert capture.bad_lines == ()
    assert capture.devices == (
        CaptureDevice(
            index=0,
            name="Wacom Test Pen",
            phys=None,
            bus=3,
            vid=0x056A,
            pid=0x0350,
            descriptor=DESCRIPTOR,
            comments=("Wacom Test Pen", "0x05, 0x0d,  // Usage Page (Digitizers)"),
        ),
    )
    assert _events(capture) == [(0.0, b"\x02\x01\x10\x00", 0), (1.959698, b"\x02\x00\x00\x00", 0)]
    assert [e.line for e in capture.events] == [7, 9]


@pytest.mark.parametrize(
    ("stamp", "seconds"),
    [
        ("000001.959698", 1.959698),
        ("1.959698", 1.959698),
        ("0.007978", 0.007978),
        ("000000.000000", 0.0),
        ("1.5", 1.5),
        ("000012.05", 12.05),
        ("3", 3.0),
        ("1234567.000001", 1234567.000001),
    ],
    ids=["python-padded", "c-unpadded", "c-small", "zero", "short-usec", "padded-usec", "integer", "long"],
)
def test_event_timestamp_forms(stamp: str, seconds: float) -> None:
    capture = _capture(f"E: {stamp} 2 02 ff")

    assert capture.bad_lines == ()
    assert capture.events[0].t == pytest.approx(seconds, abs=1e-9)
    assert capture.events[0].data == b"\x02\xff"


def test_crlf_and_trailing_whitespace_read_like_plain_lines() -> None:
    messy = RECORDER_TEXT.replace("\n", " \t\r\n").replace("E: 000001", "E:   000001")

    plain, crlf = Capture.from_text(RECORDER_TEXT), Capture.from_text(messy)

    assert crlf.bad_lines == ()
    assert crlf.devices == plain.devices
    assert crlf.events == plain.events
    assert [e.line for e in crlf.events] == [e.line for e in plain.events]


def test_blank_lines_and_a_byte_order_mark_are_ignored() -> None:
    capture = Capture.from_text("\ufeff\n\nR: 2 a1 c0\n\n\nE: 0.0 1 01\n\n")

    assert capture.bad_lines == ()
    assert capture.devices[0].descriptor == b"\xa1\xc0"
    assert capture.events[0].line == 6


def test_comments_anywhere() -> None:
    text = (
        "# file header\n"  # 1: before everything -> device 0
        "#no space\n"  # 2
        "R: 2 a1 c0\n"  # 3
        "#\n"  # 4: empty comment, among the header lines -> kept
        "N: Pen\n"  # 5
        "# after the header, before events\n"  # 6: not a header comment -> dropped
        "E: 0.0 1 01\n"  # 7
        "# between events\n"  # 8
        "E: 0.1 1 02\n"  # 9
        "# trailing\n"  # 10
    )
    capture = Capture.from_text(text)

    assert capture.bad_lines == ()
    assert capture.devices[0].comments == ("file header", "no space", "")
    assert _events(capture) == [(0.0, b"\x01", 0), (0.1, b"\x02", 0)]


def test_several_devices() -> None:
    capture = Capture.from_text(MULTI_TEXT)

    assert capture.bad_lines == ()
    pen, keys = capture.devices
    pen_comments = ("recorded on a test machine", "Pen")
    assert pen == CaptureDevice(
        0, "Pen", "usb-0000:00:14.0-1/input0", 3, 0x056A, 0x0350, DESCRIPTOR, pen_comments
    )
    assert keys == CaptureDevice(1, "Keys", None, 3, 0x056A, 0x0351, b"\xa1\xc0", ("Keys",))
    assert [e.device for e in capture.events] == [1, 0, 0, 1]
    assert [e.t for e in capture.events_for(1)] == [0.0, 0.03]
    assert [e.t for e in capture.events_for(0)] == [0.01, 0.02]
    assert capture.events_for(7) == ()
    assert capture.device(1) is keys
    with pytest.raises(KeyError):
        capture.device(7)


def test_old_c_recorder_writes_d0_for_one_device() -> None:
    capture = Capture.from_text("D: 0\nR: 2 a1 c0\nN: PenPartner\nI: 3 056a 0000\nE: 0.007978 2 01 02\n")

    assert [d.index for d in capture.devices] == [0]
    assert capture.events[0].device == 0
    assert not format_capture(capture).startswith("D:")


def test_times_going_backwards_are_kept() -> None:
    capture = _capture("E: 0.5 1 01", "E: 0.2 1 02", "E: 0.7 1 03")

    assert capture.bad_lines == ()
    assert [e.t for e in capture.events] == [0.5, 0.2, 0.7]


def test_an_event_may_be_empty() -> None:
    assert _capture("E: 0.5 0").events[0].data == b""


# --- bad lines ------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("E: 0.1 8 01 02 03 04 05 06 07", "declared 8 bytes, found 7"),
        ("E: 0.1 2 01 02 03", "declared 2 bytes, found 3"),
        ("E: 0.1 4", "declared 4 bytes, found 0"),
        ("E: 0.1 2 01 zz", "bad hex byte 'zz'"),
        ("E: 0.1 2 01 2", "bad hex byte '2'"),
        ("E: 0.1 1 0x01", "bad hex byte '0x01'"),
        ("E: abc 1 01", "timestamp 'abc' is not a number"),
        ("E: -1.0 1 01", "timestamp '-1.0' is not a number"),
        ("E: 1.2.3 1 01", "timestamp '1.2.3' is not a number"),
        ("E: nan 1 01", "timestamp 'nan' is not a number"),
        ("E: 0.1 x 01", "length 'x' is not a decimal number"),
        ("E: 0.1 -1 01", "length '-1' is not a decimal number"),
        ("E: 0.1", "expected 'E: <seconds> <length> <bytes>'"),
        ("E:", "expected 'E: <seconds> <length> <bytes>'"),
        ("X: hello", "unknown line type 'X:' (expected #, D:, R:, N:, P:, I: or E:)"),
        ("hello", "unknown line type 'he' (expected #, D:, R:, N:, P:, I: or E:)"),
        ("I: 3 zz 0001", "'zz' is not a hex number"),
        ("I: 3 056a", "expected 'I: <bus> <vid> <pid>' in hex, found 2 fields"),
        ("I: 3 1056a 0001", "vendor and product ids must fit in 16 bits"),
        ("N: Another name", "second 'N:' line for device 0; the first is kept"),
    ],
    ids=[
        "length-too-long",
        "length-too-short",
        "no-bytes",
        "bad-hex",
        "one-digit-byte",
        "0x-prefix",
        "time-word",
        "time-negative",
        "time-two-dots",
        "time-nan",
        "length-word",
        "length-negative",
        "no-length",
        "empty-event",
        "unknown-prefix",
        "no-prefix",
        "ids-bad-hex",
        "ids-too-few",
        "ids-vid-too-big",
        "second-name",
    ],
)
def test_bad_line_is_recorded_and_skipped(text: str, reason: str) -> None:
    capture = _capture("E: 0.0 1 01", text, "E: 0.2 1 02")

    assert capture.bad_lines == (BadLine(line=4, text=text, reason=reason),)
    assert _events(capture) == [(0.0, b"\x01", 0), (0.2, b"\x02", 0)]
    assert [e.line for e in capture.events] == [3, 5]
    assert capture.devices[0].name == "Pen"


def test_bad_line_text_is_truncated() -> None:
    long_line = "E: 0.1 100 " + " ".join(["zz"] * 100)

    (bad,) = _capture(long_line).bad_lines

    assert bad.text == long_line[:BAD_TEXT_MAX]
    assert len(bad.text) == BAD_TEXT_MAX


def test_bad_ids_leave_the_ids_unset() -> None:
    capture = _capture("I: 3 zz 0001")

    device = capture.devices[0]
    assert (device.bus, device.vid, device.pid) == (None, None, None)
    assert "I:" not in format_capture(capture)


# --- fatal errors ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "line", "message"),
    [
        ("", None, "no report descriptor ('R:' line) in the capture"),
        ("# only a comment\n\n", None, "no report descriptor ('R:' line) in the capture"),
        ("# header\nN: Pen\nI: 3 056a 0001\n", 2, "device 0 has no report descriptor ('R:' line)"),
        ("N: Pen\nE: 0.0 1 01\nR: 2 a1 c0\n", 2, f"{BEFORE_R} 0"),
        ("E: 0.0 1 01\n", 1, f"{BEFORE_R} 0"),
        ("R: 3 a1 c0\n", 1, "report descriptor declared 3 bytes, found 2"),
        ("R: 2 a1 cz\n", 1, "report descriptor: bad hex byte 'cz'"),
        ("R: two a1 c0\n", 1, "report descriptor length 'two' is not a decimal number"),
        ("R:\n", 1, "report descriptor length '' is not a decimal number"),
        ("R: 0\n", 1, "report descriptor is empty"),
        ("R: 2 a1 c0\nR: 2 a1 c0\n", 2, "second 'R:' line for device 0 (the first is at line 1)"),
        ("D: one\nR: 2 a1 c0\n", 1, "device index 'one' is not a decimal number"),
        ("D: 0\nR: 2 a1 c0\nD: 1\nN: Keys\n", 3, "device 1 has no report descriptor ('R:' line)"),
        ("D: 0\nR: 2 a1 c0\nD: 1\nE: 0.0 1 01\n", 4, f"{BEFORE_R} 1"),
    ],
    ids=[
        "empty-file",
        "only-comments",
        "no-descriptor",
        "event-before-descriptor",
        "event-first",
        "descriptor-length-mismatch",
        "descriptor-bad-hex",
        "descriptor-length-word",
        "descriptor-missing-length",
        "descriptor-empty",
        "descriptor-twice",
        "device-index-word",
        "second-device-without-descriptor",
        "event-for-device-without-descriptor",
    ],
)
def test_unusable_capture_raises_naming_path_and_line(text: str, line: int | None, message: str) -> None:
    with pytest.raises(CaptureFormatError) as info:
        Capture.from_text(text, path="cap.hid")

    assert info.value.path == "cap.hid"
    assert info.value.line == line
    assert message in str(info.value)
    assert str(info.value).startswith("cap.hid:" if line is None else f"cap.hid:{line}: ")


def test_from_file_names_the_file_and_replaces_bad_utf8(tmp_path) -> None:
    good = tmp_path / "good.hid"
    good.write_bytes(b"# caf\xe9\r\nR: 2 a1 c0\r\nN: Pen \xff\r\nE: 0.0 1 01\r\n")
    bad = tmp_path / "bad.hid"
    bad.write_bytes(b"N: Pen\nE: 0.0 1 01\n")

    capture = Capture.from_file(good)
    with pytest.raises(CaptureFormatError) as info:
        Capture.from_file(bad)

    assert capture.path == str(good)
    assert capture.devices[0].comments == ("caf\ufffd",)
    assert capture.devices[0].name == "Pen \ufffd"
    assert (info.value.path, info.value.line) == (str(bad), 2)


# --- writing --------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [RECORDER_TEXT, MULTI_TEXT, "R: 2 a1 c0\nE: 1.5 1 01\nE: 0.007978 0\n", "D: 3\nR: 1 c0\nE: 0.1 1 01\n"],
    ids=["one-device", "two-devices", "unpadded-times", "single-device-not-0"],
)
def test_round_trip(text: str) -> None:
    capture = Capture.from_text(text)

    written = format_capture(capture)
    again = Capture.from_text(written)

    assert again.devices == capture.devices
    assert again.events == capture.events  # CaptureEvent.line is not compared
    assert _events(again) == _events(capture)
    assert format_capture(again) == written


def test_format_is_what_hid_recorder_writes() -> None:
    capture = Capture.from_text(RECORDER_TEXT)

    assert format_capture(capture) == (
        "# Wacom Test Pen\n"
        "# 0x05, 0x0d,  // Usage Page (Digitizers)\n"
        "R: 10 05 0d 09 02 a1 01 85 02 c0 c0\n"
        "N: Wacom Test Pen\n"
        "I: 3 056a 0350\n"
        "E: 000000.000000 4 02 01 10 00\n"
        "E: 000001.959698 4 02 00 00 00\n"
    )


def test_format_of_several_devices_switches_with_d_lines() -> None:
    written = format_capture(Capture.from_text(MULTI_TEXT))

    assert written == (
        "D: 0\n"
        "# recorded on a test machine\n"
        "# Pen\n"
        "R: 10 05 0d 09 02 a1 01 85 02 c0 c0\n"
        "N: Pen\n"
        "P: usb-0000:00:14.0-1/input0\n"
        "I: 3 056a 0350\n"
        "D: 1\n"
        "# Keys\n"
        "R: 2 a1 c0\n"
        "N: Keys\n"
        "I: 3 056a 0351\n"
        "D: 1\n"
        "E: 000000.000000 2 01 02\n"
        "D: 0\n"
        "E: 000000.010000 4 02 01 10 00\n"
        "E: 000000.020000 4 02 00 10 00\n"
        "D: 1\n"
        "E: 000000.030000 2 01 00\n"
    )


def test_format_of_values_built_in_code() -> None:
    device = CaptureDevice(0, "I2C Pen", None, 0x18, 0x2D1F, 0x0001, b"\xa1\xc0")
    capture = Capture((device,), (CaptureEvent(0.0, b"\x01"), CaptureEvent(61.0000004, b"\x02\x0a")))

    assert format_capture(capture) == (
        "R: 2 a1 c0\nN: I2C Pen\nI: 18 2d1f 0001\nE: 000000.000000 1 01\nE: 000061.000000 2 02 0a\n"
    )


@pytest.mark.parametrize(
    ("capture", "message"),
    [
        (Capture((PEN,), (CaptureEvent(-0.5, b"\x01"),)), "-0.5"),
        (Capture((PEN,), (CaptureEvent(float("nan"), b""),)), "nan"),
        (Capture((dataclasses.replace(PEN, name="Two\nlines"),), ()), "several lines"),
        (Capture((dataclasses.replace(PEN, comments=("a\rb",)),), ()), "several lines"),
        (Capture((PEN,), (CaptureEvent(0.0, b"", device=4),)), "device 4"),
    ],
    ids=["negative-time", "nan-time", "multi-line-name", "multi-line-comment", "unknown-device"],
)
def test_format_rejects_values_it_cannot_write(capture: Capture, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        format_capture(capture)


def test_write_capture_writes_the_file_and_leaves_no_temporary(tmp_path) -> None:
    capture = Capture.from_text(MULTI_TEXT)
    target = tmp_path / "out.hid"

    write_capture(capture, target)

    assert os.listdir(tmp_path) == ["out.hid"]
    assert target.read_text(encoding="utf-8") == format_capture(capture)
    assert Capture.from_file(target).events == capture.events


def test_write_capture_keeps_the_permissions_of_the_file_it_replaces(tmp_path) -> None:
    target = tmp_path / "out.hid"
    target.write_text("old\n")
    target.chmod(0o600)

    write_capture(Capture.from_text(RECORDER_TEXT), target)

    assert target.stat().st_mode & 0o777 == 0o600


@pytest.mark.parametrize("failing", ["replace", "fsync"], ids=["rename-fails", "fsync-fails"])
def test_failed_write_keeps_the_previous_file_and_leaves_no_temporary(tmp_path, monkeypatch, failing) -> None:
    target = tmp_path / "out.hid"
    target.write_text(RECORDER_TEXT)

    def fail(*args: object) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, failing, fail)
    with pytest.raises(OSError, match="No space left"):
        write_capture(Capture.from_text(MULTI_TEXT), target)

    assert os.listdir(tmp_path) == ["out.hid"]
    assert target.read_text() == RECORDER_TEXT


# --- size -----------------------------------------------------------------------------------------


def test_parses_fifty_thousand_events() -> None:
    lines = [
        f"E: {i // 1000:06d}.{i % 1000 * 1000:06d} 6 02 a1 {i & 0xFF:02x} 10 00 ff" for i in range(50_000)
    ]
    text = "R: 10 05 0d 09 02 a1 01 85 02 c0 c0\nN: Pen\nI: 3 056a 0350\n" + "\n".join(lines) + "\n"

    capture = Capture.from_text(text)

    assert len(capture.events) == 50_000
    assert capture.events[-1].t == pytest.approx(49.999)


def test_values_are_frozen() -> None:
    event = CaptureEvent(0.0, b"\x01")

    with pytest.raises(dataclasses.FrozenInstanceError):
        event.t = 1.0  # type: ignore[misc]
    assert dataclasses.replace(event, t=1.0).t == 1.0
