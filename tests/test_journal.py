"""The session journal: exact round trips, errors naming line and key, and what survives crashes and full disks."""

from __future__ import annotations

import errno
import itertools
import json
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physink_tui import __version__
from physink_tui.errors import JournalError
from physink_tui.formats.journal import writer as writer_module
from physink_tui.formats.journal.codec import decode_line, encode_entry
from physink_tui.formats.journal.entries import (
    CommandEntry,
    DeviceEntry,
    HidEntry,
    JournalDevice,
    JournalEntry,
    JournalHeader,
    PenEntry,
    SayEntry,
)
from physink_tui.formats.journal.header_codec import decode_header, encode_header
from physink_tui.formats.journal.reader import iter_journal, read_journal
from physink_tui.formats.journal.value_checks import COMMANDS, MAX_SECONDS, MODES
from physink_tui.formats.journal.writer import FSYNC_INTERVAL, JournalWriter

REPO = Path(__file__).resolve().parent.parent
DESCRIPTOR = bytes.fromhex("05 0d 09 02 a1 01 85 02 09 20 a1 00 09 42 15 00 25 01 75 01 95 01 81 02 c0 c0")
MAPPING = {"rotation": 0, "area": [0.0, 0.0, 1.0, 1.0], "left_handed": False, "canvas_width": 800}
HEADER = JournalHeader(
    800,
    600,
    (
        JournalDevice("tablet0", "Wacom Intuos S Pen", 3, 0x056A, 0x0374, DESCRIPTOR),
        JournalDevice("pad1", None, None, None, None, b"\xa1\xc0"),
    ),
    MAPPING,
    0.05,
    0.01,
)
DEVICE_IDS = ("tablet0", "pad1")

EXAMPLES: list[JournalEntry] = [
    HidEntry(0.0, "tablet0", bytes.fromhex("02 c1 00 10 ff")),
    PenEntry(0.25, 0.5, 0.125, 0.0, False, True, False, False, False),
    PenEntry(0.5, 1.0, 0.0, 1.0, True, True, True, True, True),
    CommandEntry(0.75, "mode", ("demo",)),
    CommandEntry(1.0, "seek", (2.5,)),
    CommandEntry(1.0, "label", ("last", "ball")),
    CommandEntry(1.0, "label", ("body-3", "rotating platform")),
    CommandEntry(1.25, "save", ("/tmp/egg.physink.json",)),
    CommandEntry(1.5, "simulate", ()),
    SayEntry(2.0, "the egg lands in the frying pan"),
    SayEntry(2.0, 'l\'œuf "cassé"\nnew line\u2028 and tab\t'),
]


def write(tmp_path: Path, *lines: str | bytes, header: str | None = None, name: str = "s.physink.jsonl") -> Path:
    """A journal file of the given lines (each gets a newline unless it is bytes), after the header."""
    path = tmp_path / name
    head = encode_header(HEADER) if header is None else header
    parts = [(head + "\n").encode()]
    parts += [line if isinstance(line, bytes) else (line + "\n").encode() for line in lines]
    path.write_bytes(b"".join(parts))
    return path


# ------------------------------------------------------------------------------------------- round trips


@pytest.mark.parametrize("entry", EXAMPLES, ids=lambda e: f"{type(e).__name__}-{getattr(e, 'name', '')}")
def test_every_entry_kind_round_trips_byte_identically(entry: JournalEntry) -> None:
    line = encode_entry(entry, devices=DEVICE_IDS)
    assert "\n" not in line
    back = decode_line(line, 2, devices=DEVICE_IDS)
    assert back == entry
    assert encode_entry(back) == line
    assert json.loads(line)["t"] == entry.t


def test_lines_look_like_the_contract() -> None:
    assert encode_entry(EXAMPLES[0]) == '{"t":0.0,"hid":"02 c1 00 10 ff","dev":"tablet0"}'
    assert encode_entry(EXAMPLES[1]) == (
        '{"t":0.25,"pen":{"x":0.5,"y":0.125,"p":0.0,"tip":false,"range":true,"eraser":false,"b1":false,"b2":false}}'
    )
    assert encode_entry(CommandEntry(3, "play")) == '{"t":3.0,"cmd":"play","args":[]}'
    assert encode_entry(SayEntry(1e-7, "œuf")) == '{"t":1e-07,"say":"œuf"}'


def test_header_round_trips_and_records_what_a_replay_needs() -> None:
    line = encode_header(HEADER)
    obj = json.loads(line)
    assert list(obj) == ["format", "version", "program", "canvas", "devices", "mapping", "tip_thresholds"]
    assert obj["format"] == "physink-journal" and obj["version"] == 1
    assert obj["program"] == f"physink-tui {__version__}"
    assert obj["canvas"] == {"width": 800, "height": 600}
    assert obj["devices"]["tablet0"] == {
        "name": "Wacom Intuos S Pen",
        "bus": 3,
        "vid": 0x56A,
        "pid": 0x374,
        "descriptor": DESCRIPTOR.hex(" "),
    }
    assert obj["devices"]["pad1"]["name"] is None
    assert obj["mapping"] == MAPPING
    assert obj["tip_thresholds"] == {"down": 0.05, "up": 0.01}
    back = decode_header(line)
    assert back == HEADER
    assert encode_header(back) == line


def test_header_keeps_its_own_copy_of_the_mapping() -> None:
    mapping = {"area": [0.0, 0.0, 1.0, 1.0]}
    header = JournalHeader(1, 1, (), mapping, 0.05, 0.01)
    mapping["area"].append(5.0)
    assert header.mapping == {"area": [0.0, 0.0, 1.0, 1.0]}


TIMES = st.floats(min_value=0, max_value=MAX_SECONDS) | st.sampled_from(
    [0.0, 5e-324, 2.2250738585072014e-308, 1e-300, 0.1 + 0.2, 1e6, MAX_SECONDS]
)
UNITS = st.floats(min_value=0, max_value=1) | st.sampled_from([5e-324, 1e-310, 1 - 2**-53, 0.1, 1 / 3])
WORDS = st.text(min_size=1)
NO_ARGS = [c for c in COMMANDS if c not in {"mode", "seek", "label", "save", "load"}]
EMPTY_PROJECT = {"format": "physink-project", "version": 1, "program": "x", "canvas": {"width": 8.0, "height": 6.0},
                 "components": [], "next_id": {}, "vocabulary": [], "timeline": None}
ENTRIES = st.one_of(
    st.builds(HidEntry, TIMES, st.sampled_from(DEVICE_IDS), st.binary(min_size=1, max_size=64)),
    st.builds(PenEntry, TIMES, UNITS, UNITS, UNITS, *[st.booleans()] * 5),
    st.builds(CommandEntry, TIMES, st.just("mode"), st.tuples(st.sampled_from(MODES))),
    st.builds(CommandEntry, TIMES, st.just("seek"), st.tuples(TIMES)),
    st.builds(CommandEntry, TIMES, st.just("label"), st.tuples(st.sampled_from(["last", "selected"]) | WORDS, WORDS)),
    st.builds(CommandEntry, TIMES, st.just("save"), st.tuples(WORDS)),
    st.builds(CommandEntry, TIMES, st.just("load"), st.tuples(WORDS), st.just(EMPTY_PROJECT)),
    st.builds(CommandEntry, TIMES, st.sampled_from(NO_ARGS), st.just(())),
    st.builds(SayEntry, TIMES, st.text()),
    st.builds(DeviceEntry, TIMES, st.lists(st.builds(
        JournalDevice, st.sampled_from(DEVICE_IDS), st.none() | st.text(), st.none() | st.integers(0, 0xFFFF),
        st.none() | st.integers(0, 0xFFFF), st.none() | st.integers(0, 0xFFFF), st.binary(min_size=1, max_size=16),
    ), min_size=1, max_size=2, unique_by=lambda d: d.id).map(tuple)),
)
@given(ENTRIES)
def test_any_entry_round_trips_exactly(entry: JournalEntry) -> None:
    line = encode_entry(entry, devices=DEVICE_IDS)
    assert "\n" not in line and "\r" not in line
    back = decode_line(line + "\n", 7, devices=DEVICE_IDS)
    assert back == entry
    assert encode_entry(back) == line


MAPPINGS = st.fixed_dictionaries(
    {},
    optional={
        "canvas_width": st.floats(min_value=1e-300, max_value=1e300) | st.integers(min_value=1, max_value=10**6),
        "tablet_height": st.floats(min_value=1e-3, max_value=1e3),
        "area": st.tuples(st.floats(0, 0.5), st.floats(0, 0.5), st.floats(0.5, 1, exclude_min=True),
                          st.floats(0.5, 1, exclude_min=True)).map(list),
        "rotation": st.sampled_from([0, 90, 180, 270]),
        "left_handed": st.booleans(),
        "keep_aspect": st.booleans(),
    },
)


@given(
    st.lists(st.text(min_size=1), max_size=3, unique=True),
    MAPPINGS,
    st.floats(min_value=1e-300, max_value=1e300) | st.integers(min_value=1, max_value=10**6),
    st.floats(min_value=0.001, max_value=1),
)
def test_any_header_round_trips_exactly(ids: list[str], mapping: dict, width: float, down: float) -> None:
    devices = tuple(JournalDevice(i, None if n % 2 else i, 3, 0xFFFF, 0, bytes([n + 1])) for n, i in enumerate(ids))
    header = JournalHeader(width, 1e-9, devices, mapping, down, down / 2, program="physink-tui 9.9")
    line = encode_header(header)
    back = decode_header(line)
    assert back == header and back.mapping == mapping
    assert encode_header(back) == line


@settings(max_examples=30, deadline=None)
@given(st.lists(ENTRIES, max_size=40))
def test_written_journals_read_back_equal(tmp_path_factory: pytest.TempPathFactory, entries: list) -> None:
    entries.sort(key=lambda e: e.t)
    path = tmp_path_factory.mktemp("j") / "s.physink.jsonl"
    with JournalWriter.create(path, HEADER) as w:
        for i, entry in enumerate(entries):
            w.append(entry)
            if i % 3 == 0:
                w.flush()
    journal = read_journal(path)
    assert journal.header == HEADER
    assert list(journal.entries) == entries
    assert journal.warnings == () and journal.truncated is None


# --------------------------------------------------------------------------------------- header errors


DELETE = object()


def _header_with(**changes: object) -> str:
    """The header's JSON with ``a__b=value`` set at ``a.b`` (or that key removed for `DELETE`)."""
    obj = json.loads(encode_header(HEADER))
    for dotted, value in changes.items():
        *parents, last = dotted.split("__")
        target = obj
        for key in parents:
            target = target[key]
        if value is DELETE:
            del target[last]
        else:
            target[last] = value
    return json.dumps(obj)


@pytest.mark.parametrize(
    ("changes", "key"),
    [
        ({"format": "physink-project"}, "format"),
        ({"format": DELETE}, "format"),
        ({"version": 2}, "version"),
        ({"version": "1"}, "version"),
        ({"program": 7}, "program"),
        ({"canvas": [800, 600]}, "canvas"),
        ({"canvas__width": 0}, "canvas.width"),
        ({"canvas__height": DELETE}, "canvas.height"),
        ({"devices": []}, "devices"),
        ({"devices__tablet0__vid": 0x10000}, "devices.tablet0.vid"),
        ({"devices__tablet0__bus": True}, "devices.tablet0.bus"),
        ({"devices__tablet0__descriptor": "05 0d 0"}, "devices.tablet0.descriptor"),
        ({"devices__tablet0__descriptor": ""}, "devices.tablet0.descriptor"),
        ({"devices__pad1__name": DELETE}, "devices.pad1.name"),
        ({"mapping": None}, "mapping"),
        ({"tip_thresholds__down": 1.5}, "tip_thresholds.down"),
        ({"tip_thresholds__up": 0.05}, "tip_thresholds.up"),
        ({"tip_thresholds": []}, "tip_thresholds"),
        ({"tip_thresholds__up": DELETE}, "tip_thresholds.up"),
    ],
    ids=lambda v: (
        ",".join(f"{k}={'deleted' if x is DELETE else json.dumps(x)}" for k, x in v.items())
        if isinstance(v, dict)
        else None
    ),
)
def test_header_errors_name_the_key(tmp_path: Path, changes: dict, key: str) -> None:
    path = write(tmp_path, encode_entry(EXAMPLES[1]), header=_header_with(**changes))
    with pytest.raises(JournalError, match=f'^{re.escape(str(path))}: line 1: key "{re.escape(key)}": expected .*'):
        read_journal(path)


@pytest.mark.parametrize(
    ("header", "key"),
    [
        (JournalHeader(-1, 1, (), {}, 0.05, 0.01), "canvas.width"),
        (JournalHeader(1, float("inf"), (), {}, 0.05, 0.01), "canvas.height"),
        (JournalHeader(1, 1, (JournalDevice("", None, None, None, None, b"\x01"),), {}, 0.05, 0.01), "devices"),
        (JournalHeader(1, 1, (JournalDevice("a", None, None, -1, None, b"\x01"),), {}, 0.05, 0.01), "devices.a.vid"),
        (JournalHeader(1, 1, (JournalDevice("a", None, None, 1, None, b""),), {}, 0.05, 0.01), "devices.a.descriptor"),
        (JournalHeader(1, 1, (), {"canvas_width": float("nan")}, 0.05, 0.01), "mapping.canvas_width"),
        (JournalHeader(1, 1, (), {"area": [0, {2, 3}, 1, 1]}, 0.05, 0.01), "mapping.area[1]"),
        (JournalHeader(1, 1, (), {"k": 1}, 0.05, 0.01), "mapping.k"),
        (JournalHeader(1, 1, (), {}, 0.05, 0.01, vocabulary="noun egg"), "vocabulary"),
        (JournalHeader(1, 1, (), {}, 0.01, 0.05), "tip_thresholds.up"),
        (JournalHeader(1, 1, (), {}, 0.05, 0.01, program=""), "program"),
    ],
    ids=lambda v: None if isinstance(v, JournalHeader) else v,
)
def test_invalid_headers_are_refused_before_any_file_exists(tmp_path: Path, header: JournalHeader, key: str) -> None:
    path = tmp_path / "s.physink.jsonl"
    with pytest.raises(JournalError, match=f'header: key "{re.escape(key)}": expected'):
        JournalWriter.create(path, header)
    assert not path.exists()


def test_duplicate_device_ids_are_refused() -> None:
    dev = JournalDevice("a", None, None, None, None, b"\x01")
    with pytest.raises(JournalError, match='device id "a" appears twice'):
        encode_header(JournalHeader(1, 1, (dev, dev), {}, 0.05, 0.01))


# ------------------------------------------------------------------------------------- malformed lines

PEN = '"pen":{"x":0.5,"y":0.5,"p":0.2,"tip":true,"range":true,"eraser":false,"b1":false,"b2":false}'
PEN_X_OUT = PEN.replace("0.5", "1.5", 1)
PEN_TIP_1 = PEN.replace("true", "1", 1)
PEN_NO_B2 = PEN.replace(',"b2":false', "")


@pytest.mark.parametrize(
    ("line", "message"),
    [
        pytest.param(f"{{{PEN}}}", 'key "t": expected a number in \\[0, .*, but it is missing', id="t-missing"),
        pytest.param(f'{{"t":"1",{PEN}}}', 'key "t": expected a number in \\[0, .*, got "1"', id="t-string"),
        pytest.param(f'{{"t":true,{PEN}}}', 'key "t": expected a number in \\[0, .*, got true', id="t-bool"),
        pytest.param(f'{{"t":-0.5,{PEN}}}', 'key "t": expected a number in \\[0, .*, got -0.5', id="t-negative"),
        pytest.param(f'{{"t":NaN,{PEN}}}', "not valid JSON: NaN is not a number JSON allows", id="t-nan"),
        pytest.param(f'{{"t":1e400,{PEN}}}', 'key "t": expected a number in \\[0, ', id="t-overflow"),
        pytest.param('{"t":1.5}', "expected exactly one of hid, pen, cmd, say, device; found none", id="kind-none"),
        pytest.param(
            '{"t":1.5,"say":"a","cmd":"play","args":[]}', "expected exactly one .*; found cmd and say", id="kind-two"
        ),
        pytest.param('{"t":1.5,"hid":"02 zz","dev":"tablet0"}', 'key "hid": expected hex bytes', id="hid-not-hex"),
        pytest.param('{"t":1.5,"hid":"02c1","dev":"tablet0"}', 'key "hid": expected hex bytes', id="hid-no-spaces"),
        pytest.param('{"t":1.5,"hid":"","dev":"tablet0"}', 'key "hid": expected hex bytes', id="hid-empty"),
        pytest.param('{"t":1.5,"hid":"02"}', 'key "dev": expected a device id .*missing', id="dev-missing"),
        pytest.param(
            '{"t":1.5,"hid":"02","dev":"pen9"}', '"dev" "pen9" is not a device of the header', id="dev-unknown"
        ),
        pytest.param('{"t":1.5,"pen":[0.5,0.5]}', 'key "pen": expected an object with x, y', id="pen-not-object"),
        pytest.param(f'{{"t":1.5,{PEN_X_OUT}}}', 'key "pen.x": expected a number in', id="pen-x"),
        pytest.param(f'{{"t":1.5,{PEN_TIP_1}}}', 'key "pen.tip": expected true or false, got 1', id="pen-tip"),
        pytest.param(f'{{"t":1.5,{PEN_NO_B2}}}', 'key "pen.b2": .*missing', id="pen-b2-missing"),
        pytest.param('{"t":1.5,"cmd":"jump","args":[]}', 'key "cmd": expected one of mode, play', id="cmd-unknown"),
        pytest.param('{"t":1.5,"cmd":"play"}', 'key "args": expected a list of arguments', id="cmd-args-missing"),
        pytest.param('{"t":1.5,"cmd":"play","args":"x"}', 'key "args": expected a list, got "x"', id="args-not-list"),
        pytest.param('{"t":1.5,"cmd":"play","args":[1]}', 'key "args": expected no arguments for "play"', id="play-1"),
        pytest.param('{"t":1.5,"cmd":"mode","args":["draw"]}', 'key "args": .* "sketch" or "demo"', id="mode-draw"),
        pytest.param('{"t":1.5,"cmd":"seek","args":["2"]}', 'key "args": expected .* number in \\[0, ', id="seek-str"),
        pytest.param('{"t":1.5,"cmd":"seek","args":[1,2]}', 'key "args": expected .* number in \\[0, ', id="seek-two"),
        pytest.param('{"t":1.5,"cmd":"seek","args":[-1]}', 'key "args": expected .* number in \\[0, ', id="seek-neg"),
        pytest.param('{"t":1.5,"cmd":"label","args":["last"]}', 'key "args": expected two arguments', id="label-1"),
        pytest.param('{"t":1.5,"cmd":"label","args":["last",""]}', 'key "args": expected two arguments', id="label-e"),
        pytest.param('{"t":1.5,"cmd":"save","args":[]}', 'key "args": expected one argument, a non-empty P', id="save"),
        pytest.param('{"t":1.5,"say":["hi"]}', 'key "say": expected a string, got \\["hi"\\]', id="say-not-string"),
        pytest.param('{"t":1.5,"say":"\\ud800"}', 'key "say": expected valid Unicode', id="say-lone-surrogate"),
        pytest.param('{"t":1.5,"say":"hi"', "not valid JSON", id="not-json"),
        pytest.param("[1.5]", "expected a JSON object, got \\[1.5\\]", id="array"),
        pytest.param('{"t":1.5,"t":1.6,"say":"hi"}', 'key "t" appears twice', id="duplicate-key"),
        pytest.param(b'{"t":1.5,"say":"\xff"}\n', "not valid UTF-8", id="bad-utf8"),
    ],
)
def test_a_malformed_line_stops_reading_naming_line_and_key(tmp_path: Path, line: str | bytes, message: str) -> None:
    ok = encode_entry(SayEntry(1.0, "first"))
    path = write(tmp_path, ok, line, encode_entry(SayEntry(9.0, "after")))
    with pytest.raises(JournalError, match=f"^{re.escape(str(path))}: line 3: {message}"):
        read_journal(path)


def test_t_going_backwards_is_an_error_naming_the_line(tmp_path: Path) -> None:
    path = write(tmp_path, '{"t":3.5,"say":"a"}', '{"t":3.5,"say":"same t is fine"}', '{"t":3.2,"say":"b"}')
    with pytest.raises(JournalError) as caught:
        read_journal(path)
    assert str(caught.value) == f'{path}: line 4: key "t": expected a number >= the previous t 3.5, got 3.2'


def test_the_writer_refuses_t_going_backwards_and_goes_on(tmp_path: Path) -> None:
    path = tmp_path / "s.physink.jsonl"
    with JournalWriter.create(path, HEADER) as w:
        w.append(SayEntry(3.5, "a"))
        with pytest.raises(JournalError, match=r'say entry: key "t": expected a number >= the previous t 3\.5, got 3'):
            w.append(SayEntry(3.2, "b"))
        w.append(SayEntry(3.5, "c"))
    assert [e.text for e in read_journal(path).entries] == ["a", "c"]


@pytest.mark.parametrize(
    ("entry", "message"),
    [
        (HidEntry(1.0, "pen9", b"\x02"), '"dev" "pen9" is not a device of the header'),
        (HidEntry(1.0, "tablet0", b""), 'key "hid": expected non-empty bytes'),
        (PenEntry(1.0, 0.5, 0.5, float("nan"), True, True, False, False, False), 'key "pen.p"'),
        (PenEntry(1.0, 0.5, 0.5, 0.5, 1, True, False, False, False), 'key "pen.tip": expected true or false, got 1'),
        (CommandEntry(1.0, "mode", ("draw",)), 'key "args"'),
        (CommandEntry(1.0, "fly", ()), 'key "cmd"'),
        (SayEntry(float("inf"), "x"), 'key "t"'),
        (SayEntry(1.0, None), 'key "say"'),  # type: ignore[arg-type]
    ],
    ids=lambda v: None if isinstance(v, str) else type(v).__name__,
)
def test_the_writer_refuses_what_the_reader_would_refuse(tmp_path: Path, entry: JournalEntry, message: str) -> None:
    with JournalWriter.create(tmp_path / "s.physink.jsonl", HEADER) as w, pytest.raises(JournalError, match=message):
        w.append(entry)
    assert read_journal(tmp_path / "s.physink.jsonl").entries == ()


def test_unknown_keys_are_warnings_not_errors(tmp_path: Path) -> None:
    header = json.loads(encode_header(HEADER))
    header["recorded_by"] = "kiosk 3"
    header["canvas"]["depth"] = 1
    path = write(
        tmp_path,
        f'{{"t":1.0,{PEN[:-1]},"tilt_x":12}},"source":"mouse"}}',
        '{"t":2.0,"say":"label ball","confidence":0.93,"dev":"tablet0"}',
        header=json.dumps(header),
    )
    journal = read_journal(path)
    assert [type(e) for e in journal.entries] == [PenEntry, SayEntry]
    assert journal.warnings == (
        'line 1: unknown key "canvas.depth" ignored',
        'line 1: unknown key "recorded_by" ignored',
        'line 2: unknown key "source" ignored',
        'line 2: unknown key "pen.tilt_x" ignored',
        'line 3: unknown key "confidence" ignored',
        'line 3: unknown key "dev" ignored',
    )


# ------------------------------------------------------------------------------------ truncated files


@pytest.mark.parametrize(
    "tail",
    [
        pytest.param(b'{"t":9.0,"pen":{"x":0.5,"y', id="cut-mid-line"),
        pytest.param('{"t":9.0,"say":"œuf"}'.encode()[:-5], id="cut-mid-character"),
        pytest.param(b"\0" * 37, id="zero-filled-tail"),
        pytest.param(b"{", id="one-byte"),
    ],
)
def test_a_cut_last_line_is_reported_and_everything_before_it_read(tmp_path: Path, tail: bytes) -> None:
    path = write(tmp_path, *[encode_entry(e) for e in EXAMPLES[1:4]], tail)
    journal = read_journal(path)
    assert journal.entries == tuple(EXAMPLES[1:4])
    assert journal.truncated == 5


def test_a_whole_last_line_without_newline_is_read(tmp_path: Path) -> None:
    path = write(tmp_path, encode_entry(EXAMPLES[1]), encode_entry(EXAMPLES[2]).encode())
    journal = read_journal(path)
    assert journal.entries == tuple(EXAMPLES[1:3]) and journal.truncated is None


def test_a_malformed_last_line_with_its_newline_is_an_error(tmp_path: Path) -> None:
    path = write(tmp_path, encode_entry(EXAMPLES[1]), '{"t":9.0,"pen":{"x":0.5,"y')
    with pytest.raises(JournalError, match=f"^{re.escape(str(path))}: line 3: not valid JSON"):
        read_journal(path)


def test_blank_lines_are_skipped(tmp_path: Path) -> None:
    path = write(tmp_path, "", encode_entry(EXAMPLES[1]), "  \r", encode_entry(EXAMPLES[2]))
    assert read_journal(path).entries == tuple(EXAMPLES[1:3])


@pytest.mark.parametrize(
    ("content", "message"),
    [
        (b"", "empty journal: no header line"),
        (encode_header(HEADER).encode()[:40], "line 1: the header is cut off"),
        (encode_entry(EXAMPLES[1]).encode() + b"\n", 'line 1: key "format": expected "physink-journal"'),
    ],
    ids=["empty", "header-cut", "no-header"],
)
def test_a_journal_needs_its_whole_header(tmp_path: Path, content: bytes, message: str) -> None:
    path = tmp_path / "s.physink.jsonl"
    path.write_bytes(content)
    with pytest.raises(JournalError, match=message):
        read_journal(path)


def test_a_missing_file_is_a_journal_error(tmp_path: Path) -> None:
    with pytest.raises(JournalError, match=r"cannot read journal .*nothing\.physink\.jsonl"):
        read_journal(tmp_path / "nothing.physink.jsonl")


def test_iter_journal_streams_and_reports_at_the_end(tmp_path: Path) -> None:
    path = write(tmp_path, *[encode_entry(e) for e in EXAMPLES[1:3]], b'{"t":')
    with iter_journal(path) as reader:
        assert reader.header == HEADER
        assert next(iter(reader)) == EXAMPLES[1]
        assert reader.truncated is None
        assert list(reader) == [EXAMPLES[2]]
        assert reader.truncated == 4


# ------------------------------------------------------------------------------------------- the writer


def test_the_writer_never_overwrites(tmp_path: Path) -> None:
    path = tmp_path / "s.physink.jsonl"
    path.write_text("precious\n")
    with pytest.raises(JournalError, match=f"journal {re.escape(str(path))} already exists; a journal is never"):
        JournalWriter.create(path, HEADER)
    assert path.read_text() == "precious\n"


def test_the_writer_appends_only_and_closes_once(tmp_path: Path) -> None:
    path = tmp_path / "s.physink.jsonl"
    w = JournalWriter.create(path, HEADER)
    assert path.read_text() == encode_header(HEADER) + "\n"
    w.append(EXAMPLES[0])
    assert path.stat().st_size == len(encode_header(HEADER)) + 1  # buffered, not written
    w.flush()
    w.append(EXAMPLES[1])
    w.close()
    w.close()
    assert w.lines_written == 3
    assert path.read_text().splitlines()[1:] == [encode_entry(EXAMPLES[0]), encode_entry(EXAMPLES[1])]
    with pytest.raises(JournalError, match="is closed"):
        w.append(EXAMPLES[2])


def test_the_writer_flushes_by_itself_when_much_is_waiting(tmp_path: Path) -> None:
    path = tmp_path / "s.physink.jsonl"
    w = JournalWriter.create(path, HEADER)
    for i in range(2000):
        w.append(SayEntry(i, "x" * 100))
    assert read_journal(path).entries  # without a flush
    w.close()
    assert len(read_journal(path).entries) == 2000


class FakeClock:
    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def test_fsync_at_least_every_interval_of_appends_and_at_close(tmp_path: Path, monkeypatch) -> None:
    clock = FakeClock()
    start = clock.now
    w = JournalWriter.create(tmp_path / "s.physink.jsonl", HEADER, clock=clock)
    synced_at: list[float] = []
    real_fsync = os.fsync
    monkeypatch.setattr(os, "fsync", lambda fd: (synced_at.append(clock.now), real_fsync(fd))[1])
    step = 0.03
    for i in range(1, 101):  # 3 s of appends, one flush per 30 ms
        clock.now += step
        w.append(PenEntry(i * step, 0.5, 0.5, 0.5, True, True, False, False, False))
        w.flush()
    assert 20 <= len(synced_at) <= 34  # about one per 0.1 s, far fewer than one per flush
    gaps = [b - a for a, b in zip([start, *synced_at], [*synced_at, clock.now], strict=True)]
    assert max(gaps[:-1]) < FSYNC_INTERVAL + step
    assert gaps[-1] < FSYNC_INTERVAL  # what is not synced yet is younger than the interval
    # Idle flushes sync what is left once the interval has passed, and then stop syncing.
    synced, pending = len(synced_at), synced_at[-1] != clock.now
    clock.now += 5.0
    w.flush()
    w.flush()
    assert len(synced_at) == synced + pending
    w.append(SayEntry(10.0, "last"))
    w.close()
    assert len(synced_at) == synced + pending + 1 and synced_at[-1] == clock.now


def test_idle_flushes_do_not_fsync(tmp_path: Path, monkeypatch) -> None:
    clock = FakeClock()
    w = JournalWriter.create(tmp_path / "s.physink.jsonl", HEADER, clock=clock)
    calls: list[int] = []
    monkeypatch.setattr(os, "fsync", calls.append)
    for _ in range(10):
        clock.now += 1.0
        w.flush()
    assert calls == []
    w.close()
    assert calls == []  # everything written was synced already


def _fail_third_batch(monkeypatch, path: Path, *, partial: bool, truncate_fails: bool = False) -> list[int]:
    """Makes the journal's third batch hit a full disk (after half of it was written, when ``partial``)."""
    batches: list[int] = []
    real_write = os.write
    inode = path.stat().st_ino

    def fake_write(fd: int, data) -> int:
        if os.fstat(fd).st_ino != inode:
            return real_write(fd, data)
        batches.append(len(data))
        if len(batches) == 3 and partial:
            return real_write(fd, bytes(data[: len(data) // 2 - 7]))  # 4 whole lines and part of the 5th
        if len(batches) >= 3:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return real_write(fd, data)

    monkeypatch.setattr(os, "write", fake_write)
    if truncate_fails:
        monkeypatch.setattr(os, "ftruncate", lambda fd, size: (_ for _ in ()).throw(OSError(errno.EIO, "no")))
    return batches


@pytest.mark.parametrize(
    ("partial", "truncate_fails"),
    [(False, False), (True, False), (True, True)],
    ids=["nothing-written", "half-written", "half-written-cannot-cut"],
)
def test_a_full_disk_stops_the_journal_once_and_keeps_what_was_written(
    tmp_path: Path, monkeypatch, partial: bool, truncate_fails: bool
) -> None:
    path = tmp_path / "s.physink.jsonl"
    w = JournalWriter.create(path, HEADER)
    _fail_third_batch(monkeypatch, path, partial=partial, truncate_fails=truncate_fails)
    says = [SayEntry(float(i), f"utterance number {i}") for i in range(30)]
    errors: list[JournalError] = []
    for batch in range(3):
        for entry in says[batch * 10 : batch * 10 + 10]:
            w.append(entry)
        try:
            w.flush()
        except JournalError as e:
            errors.append(e)
    assert len(errors) == 1
    kept = 20 + (4 if partial else 0)  # 4 whole lines fit in the first half of the third batch
    message = (
        f"journal {path} stopped: disk full (No space left on device); the {kept + 1} lines written so far are intact"
    )
    assert str(errors[0]) == message
    assert w.stopped == message
    for call in (lambda: w.append(SayEntry(99.0, "later")), w.flush):
        with pytest.raises(JournalError) as refused:
            call()
        assert str(refused.value) == message
    w.close()  # the error was raised once; closing says nothing more
    monkeypatch.undo()
    journal = read_journal(path)
    assert journal.entries == tuple(says[:kept])
    assert journal.truncated == (kept + 2 if truncate_fails else None)


def test_a_journal_that_cannot_be_created_is_a_journal_error(tmp_path: Path) -> None:
    with pytest.raises(JournalError, match=r"cannot create journal .*no/such/folder"):
        JournalWriter.create(tmp_path / "no" / "such" / "folder" / "s.physink.jsonl", HEADER)


def test_a_header_that_cannot_be_written_leaves_no_file(tmp_path: Path, monkeypatch) -> None:
    path = tmp_path / "s.physink.jsonl"

    def full(fd: int, data) -> int:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(writer_module.os, "write", full)
    with pytest.raises(JournalError, match=r"cannot create journal .*No space left on device"):
        JournalWriter.create(path, HEADER)
    assert not path.exists()


# ---------------------------------------------------------------------------------------- a hard kill

KILLED_WRITER = r"""
import sys
from physink_tui.formats.journal.entries import CommandEntry, HidEntry, JournalDevice, JournalHeader, PenEntry, SayEntry
from physink_tui.formats.journal.writer import JournalWriter

header = JournalHeader(1, 1, (JournalDevice("tablet0", "Pen", 3, 0x56A, 0x350, b"\xa1\xc0"),), {}, 0.05, 0.01)
w = JournalWriter.create(sys.argv[1], header)
print("ready", flush=True)
i = 0
while True:
    i += 1
    t = i / 1000
    kind = i % 4
    if kind == 0:
        w.append(PenEntry(t, (i % 997) / 997, 0.5, 0.25, True, True, False, False, False))
    elif kind == 1:
        w.append(HidEntry(t, "tablet0", bytes([2, i % 256, 0, 0, 0, 0, 0, 0])))
    elif kind == 2:
        w.append(SayEntry(t, "the egg lands in the frying pan " * (i % 50)))
    else:
        w.append(CommandEntry(t, "seek", (t,)))
    if i % 16 == 0:
        w.flush()
"""


@pytest.mark.skipif(not hasattr(signal, "SIGKILL"), reason="needs SIGKILL")
def test_a_journal_killed_mid_write_reads_back_every_whole_line(tmp_path: Path) -> None:
    path = tmp_path / "killed.physink.jsonl"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(REPO), os.environ.get("PYTHONPATH")]))}
    proc = subprocess.Popen(
        [sys.executable, "-c", KILLED_WRITER, str(path)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env
    )
    try:
        assert proc.stdout is not None and proc.stdout.readline() == b"ready\n", proc.stderr
        deadline = time.monotonic() + 60  # hang guard: the writer is killed once lines are on disk, not after a time
        while path.stat().st_size < 256 * 1024 and time.monotonic() < deadline:
            time.sleep(0.01)
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait()
    assert proc.returncode == -signal.SIGKILL
    journal = read_journal(path)
    times = [e.t for e in journal.entries]
    assert len(times) > 0
    assert all(a < b for a, b in itertools.pairwise(times))
    assert times == [i / 1000 for i in range(1, len(times) + 1)]  # no line lost or mangled before the end
    assert journal.truncated in (None, len(times) + 2)
