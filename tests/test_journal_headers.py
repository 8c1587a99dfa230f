"""Journals written by anyone: the documented minimal header replays, every value is checked with its key named."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from physink_tui.cli import main
from physink_tui.errors import JournalError
from physink_tui.formats.journal.entries import DEFAULT_TIP_DOWN, DEFAULT_TIP_UP, UNKNOWN_PROGRAM
from physink_tui.formats.journal.reader import BOM, looks_like_journal, read_journal
from physink_tui.input.journal_replay import pen_input_for, replay_journal_input
from physink_tui.session.session import Session

JOURNALS = Path(__file__).resolve().parent / "journals"
FULL_HEADER = json.loads((JOURNALS / "basketball.physink.jsonl").read_text().partition("\n")[0])
DEVICE = FULL_HEADER["devices"]["tablet0"]
MINIMAL = {"format": "physink-journal", "version": 1, "canvas": {"width": 1000, "height": 500},
           "devices": {"tablet0": DEVICE}}
"""The header DESIGN.md documents: only format, version, canvas and devices."""

PEN = {"x": 0.25, "y": 0.75, "p": 0.5, "tip": True, "range": True, "eraser": False, "b1": False, "b2": False}
LINES = [
    {"t": 0.0, "hid": "07 40 eb 07 9a 0e 00 00", "dev": "tablet0"},
    {"t": 0.5, "pen": PEN},
    {"t": 0.6, "pen": {**PEN, "x": 0.5, "y": 0.5}},
    {"t": 0.7, "pen": {**PEN, "p": 0.0, "tip": False}},
    {"t": 0.8, "cmd": "mode", "args": ["demo"]},
    {"t": 0.9, "say": "label ball"},
]


def journal(tmp_path: Path, header: object = None, *lines: object, name: str = "s.physink.jsonl") -> Path:
    """A journal file: ``header`` (MINIMAL by default) and ``lines`` (LINES by default), objects or raw text."""
    path = tmp_path / name
    rows = [MINIMAL if header is None else header, *(lines or LINES)]
    path.write_text("".join((r if isinstance(r, str) else json.dumps(r)) + "\n" for r in rows), encoding="utf-8")
    return path


def fails_at(path: Path, line: int, key: str) -> str:
    """The pattern of a JournalError naming the file, the line and the key."""
    return f'^{re.escape(str(path))}: line {line}: key "{re.escape(key)}": expected '


# ------------------------------------------------------------------------- 1. the minimal header and its defaults


def test_the_minimal_header_reads_with_the_documented_defaults(tmp_path: Path) -> None:
    read = read_journal(journal(tmp_path))
    header = read.header
    assert (header.program, header.tip_down, header.tip_up) == (UNKNOWN_PROGRAM, DEFAULT_TIP_DOWN, DEFAULT_TIP_UP)
    assert (header.tip_down, header.tip_up) == (0.05, 0.01)
    assert header.mapping == {} and header.vocabulary == "" and read.warnings == ()
    assert len(read.entries) == len(LINES)


def test_the_default_mapping_is_the_identity_onto_the_canvas(tmp_path: Path) -> None:
    # a 2:1 canvas: the old default (a 16:10 tablet cropped to the canvas's aspect) moved every point
    mapping = pen_input_for(read_journal(journal(tmp_path)).header).mapping
    for point in [(0.0, 0.0), (0.25, 0.75), (1.0, 1.0), (0.1, 0.9)]:
        assert mapping.to_canvas(*point) == pytest.approx(point)


def test_the_minimal_header_replays_through_the_cli(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = journal(tmp_path)
    assert main(["replay", str(path), "--out", str(tmp_path / "out")]) == 0
    out, err = capsys.readouterr()
    assert "said          'label ball'" in out
    assert "1 strokes" in err
    assert (tmp_path / "out" / "project.json").exists()
    assert Session.from_header(read_journal(path).header).pen.mapping.to_canvas(0.25, 0.75) == pytest.approx(
        (0.25, 0.75))


def test_unknown_header_keys_are_ignored_with_a_warning_on_stderr(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    header = {**MINIMAL, "author": "someone else", "mapping": {"rotation": 0, "skew": 3}}
    path = journal(tmp_path, header)
    assert read_journal(path).header.mapping == {"rotation": 0}
    assert main(["replay", str(path), "--out", str(tmp_path / "out")]) == 0
    err = capsys.readouterr().err
    assert 'line 1: unknown key "author" ignored' in err
    assert 'line 1: unknown key "mapping.skew" ignored' in err


# ------------------------------------------------------------------------- 2. header values by type and range


@pytest.mark.parametrize(
    ("change", "key"),
    [
        ({"mapping": {"area": [None, 0, 1, 1]}}, "mapping.area[0]"),
        ({"mapping": {"area": ["0", "0", "1", "1"]}}, "mapping.area[0]"),
        ({"mapping": {"area": [0, 0, 1]}}, "mapping.area"),
        ({"mapping": {"area": [0.5, 0, 0.5, 1]}}, "mapping.area[2]"),
        ({"mapping": {"area": [0, 0, 1, 1e308]}}, "mapping.area[3]"),
        ({"mapping": {"rotation": 45}}, "mapping.rotation"),
        ({"mapping": {"rotation": False}}, "mapping.rotation"),
        ({"mapping": {"rotation": 90.0}}, "mapping.rotation"),
        ({"mapping": {"left_handed": 1}}, "mapping.left_handed"),
        ({"mapping": {"tablet_width": 10**400}}, "mapping.tablet_width"),
        ({"mapping": {"canvas_height": -3}}, "mapping.canvas_height"),
        ({"mapping": {"keep_aspect": "yes"}}, "mapping.keep_aspect"),
        ({"mapping": [1, 2]}, "mapping"),
        ({"program": ""}, "program"),
        ({"program": ["x"]}, "program"),
        ({"canvas": {"width": "1000", "height": 500}}, "canvas.width"),
        ({"canvas": {"width": 1000, "height": 10**400}}, "canvas.height"),
        ({"tip_thresholds": {"down": 0.01, "up": 0.05}}, "tip_thresholds.up"),
        ({"tip_thresholds": {"down": 0.05}}, "tip_thresholds.up"),
        ({"tip_thresholds": {"down": "0.05", "up": 0.01}}, "tip_thresholds.down"),
        ({"vocabulary": "verb topples\nnoun egg"}, "vocabulary"),
        ({"vocabulary": 7}, "vocabulary"),
        ({"devices": {"tablet0": {**DEVICE, "vid": 70000}}}, "devices.tablet0.vid"),
        ({"devices": {"tablet0": {**DEVICE, "pid": "006e"}}}, "devices.tablet0.pid"),
        ({"devices": {"tablet0": {**DEVICE, "bus": 1.5}}}, "devices.tablet0.bus"),
        ({"devices": {"tablet0": {**DEVICE, "descriptor": "05 0d 0g"}}}, "devices.tablet0.descriptor"),
    ],
    ids=lambda v: json.dumps(v)[:50] if isinstance(v, dict) else None,
)
def test_a_bad_header_value_names_file_line_1_and_the_key(tmp_path: Path, change: dict, key: str) -> None:
    path = journal(tmp_path, {**FULL_HEADER, **change})  # a header the base commit read, but for the change
    with pytest.raises(JournalError, match=fails_at(path, 1, key)):
        read_journal(path)


def test_a_mapping_area_of_strings_is_no_longer_accepted(tmp_path: Path) -> None:
    path = journal(tmp_path, {**FULL_HEADER, "mapping": {**FULL_HEADER["mapping"], "area": ["0", "0", "1", "1"]}})
    with pytest.raises(JournalError, match=fails_at(path, 1, "mapping.area[0]") + r"a number in \[0, 1\], got \"0\""):
        replay_journal_input(path)


def test_a_bad_descriptor_names_file_line_and_device(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    mouse_only = "05 01 09 02 a1 01 c0"  # a descriptor that parses but describes no pen
    path = journal(tmp_path, {**FULL_HEADER, "devices": {"pad7": {**DEVICE, "descriptor": mouse_only}}}, LINES[1])
    with pytest.raises(JournalError, match=f"^{re.escape(str(path))}: line 1: device 'pad7': descriptor describes"):
        replay_journal_input(path)
    assert main(["replay", str(path), "--out", str(tmp_path / "out")]) == 1
    assert f"{path}: line 1: device 'pad7'" in capsys.readouterr().err


def test_a_canvas_too_thin_for_floats_is_refused_naming_the_mapping(tmp_path: Path) -> None:
    path = journal(tmp_path, {**MINIMAL, "canvas": {"width": 1e300, "height": 1e-300}})
    with pytest.raises(JournalError, match=fails_at(path, 1, "mapping") + "canvas and tablet proportions"):
        replay_journal_input(path)


def test_keys_with_control_characters_stay_on_one_line(tmp_path: Path) -> None:
    path = journal(tmp_path, {**FULL_HEADER, "x\ny": 1, "devices": {"tab\nlet": {**DEVICE, "vid": None}}}, LINES[1])
    assert read_journal(path).warnings == ('line 1: unknown key "x\\ny" ignored',)
    path = journal(tmp_path, {**FULL_HEADER, "devices": {"tab\nlet": {**DEVICE, "vid": -1}}}, LINES[1])
    with pytest.raises(JournalError, match=fails_at(path, 1, "devices.tab\\nlet.vid")) as caught:
        read_journal(path)
    assert "\n" not in str(caught.value)


# ------------------------------------------------------------------------- 3. entry lines


@pytest.mark.parametrize(
    ("line", "key"),
    [
        ('{"t":1e308,"say":"hi"}', "t"),
        ('{"t":1e400,"say":"hi"}', "t"),
        ('{"t":Infinity,"say":"hi"}', None),
        ('{"t":NaN,"say":"hi"}', None),
        ('{"t":0.1,"say":"hi"}', "t"),  # before the previous line's 0.9
        ('{"t":1,"cmd":"seek","args":[1e308]}', "args"),
        ('{"t":1,"pen":' + json.dumps({**PEN, "x": 1e308}) + "}", "pen.x"),
        ('{"t":1,"pen":' + json.dumps({**PEN, "p": -0.1}) + "}", "pen.p"),
        ('{"t":1,"pen":' + json.dumps({**PEN, "tip": 1}) + "}", "pen.tip"),
        ('{"t":1,"hid":"7 40","dev":"tablet0"}', "hid"),
        ('{"t":1,"cmd":"label","args":["last",3]}', "args"),
    ],
)
def test_a_bad_entry_names_its_line(tmp_path: Path, line: str, key: str | None) -> None:
    path = journal(tmp_path, FULL_HEADER, *LINES, line)
    where = len(LINES) + 2
    pattern = fails_at(path, where, key) if key else f"^{re.escape(str(path))}: line {where}: not valid JSON"
    with pytest.raises(JournalError, match=pattern):
        read_journal(path)


# ------------------------------------------------------------------------- device lines (hot-plug)

REPORTS = [json.loads(line) for line in (JOURNALS / "basketball.physink.jsonl").read_text().splitlines()[1:400]]


def plugged_in_later(**device: object) -> list[dict]:
    """Reports of ``tablet1``, a device announced by a ``device`` line at t = 0 (its descriptor as given)."""
    return [{"t": 0.0, "device": {"tablet1": {**DEVICE, **device}}},
            *({**r, "dev": "tablet1"} for r in REPORTS if "hid" in r)]


def test_a_device_line_adds_a_tablet_whose_reports_replay(tmp_path: Path) -> None:
    header = {**FULL_HEADER, "devices": {}}
    gestures, events, notes = replay_journal_input(journal(tmp_path, header, *plugged_in_later()))
    assert sum(type(g).__name__ == "StrokeEnded" for g in gestures) >= 1
    assert any("tablet1 appeared" in e for e in events)
    assert any(n.startswith("tablet1: ") and "pen samples" in n for n in notes)


def test_a_tablet_plugged_in_during_the_session_draws_in_it(tmp_path: Path) -> None:
    """The session, not only the input side, takes the device line: the tablet's strokes become the scene."""
    from physink_tui.formats.journal.reader import read_journal as read
    from physink_tui.session.session import Session

    more = [json.loads(line) for line in (JOURNALS / "basketball.physink.jsonl").read_text().splitlines()[1:1500]]
    lines = [{"t": 0.0, "device": {"tablet1": DEVICE}}, *({**r, "dev": "tablet1"} for r in more if "hid" in r)]
    path = journal(tmp_path, {**FULL_HEADER, "devices": {}}, *lines)
    parsed = read(path)
    session = Session.from_header(parsed.header).run(parsed.entries)
    assert session.scene.bodies(), [m.text for m in session.messages]


def test_a_report_before_its_device_line_names_the_line(tmp_path: Path) -> None:
    lines = plugged_in_later()
    path = journal(tmp_path, {**FULL_HEADER, "devices": {}}, lines[1], lines[0])
    with pytest.raises(JournalError, match=f'^{re.escape(str(path))}: line 2: "dev" "tablet1" is not a device'):
        read_journal(path)


@pytest.mark.parametrize(
    ("device", "key"),
    [({"vid": 70000}, "device.tablet1.vid"), ({"bus": "usb"}, "device.tablet1.bus"),
     ({"descriptor": "5 0d"}, "device.tablet1.descriptor"), ({"name": 3}, "device.tablet1.name")],
    ids=str,
)
def test_a_bad_device_line_names_its_line_and_key(tmp_path: Path, device: dict, key: str) -> None:
    path = journal(tmp_path, FULL_HEADER, LINES[0], *plugged_in_later(**device)[:3])
    with pytest.raises(JournalError, match=fails_at(path, 3, key)):
        read_journal(path)


def test_a_device_line_with_a_bad_descriptor_names_file_line_and_device(tmp_path: Path) -> None:
    path = journal(tmp_path, FULL_HEADER, LINES[0], *plugged_in_later(descriptor="05 01 09 02 a1 01 c0")[:3])
    with pytest.raises(JournalError, match=f"^{re.escape(str(path))}: line 3: device 'tablet1': descriptor"):
        replay_journal_input(path)


# ------------------------------------------------------------------------- 4. BOM, empty file, file kind


def test_a_byte_order_mark_before_the_header_is_accepted(tmp_path: Path) -> None:
    path = journal(tmp_path, FULL_HEADER)
    path.write_bytes(BOM + path.read_bytes())
    assert looks_like_journal(path.read_bytes()[:64], path.name)
    assert len(read_journal(path).entries) == len(LINES)


def test_an_empty_journal_says_so(tmp_path: Path) -> None:
    path = tmp_path / "s.physink.jsonl"
    path.write_bytes(b"")
    assert looks_like_journal(b"", path.name) and not looks_like_journal(b"", "capture.hid")
    with pytest.raises(JournalError, match=f"^{re.escape(str(path))}: empty journal: no header line$"):
        read_journal(path)


@pytest.mark.parametrize(
    ("head", "journal_like"),
    [(b'{"format"', True), (BOM + b'{"format"', True), (b"  \n{", True), (BOM, False), (b"D: 0", False),
     (b"# comment\nR: 3", False)],
)
def test_looks_like_journal_tells_journals_from_captures(head: bytes, journal_like: bool) -> None:
    assert looks_like_journal(head, "x") is journal_like
