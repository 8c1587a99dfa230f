"""Capture timestamps a person could be handed: absurdly large ones and a single glitched one are reported with
their line and never reach an output as Infinity or hold every later report's time."""

from __future__ import annotations

import json
import math
from pathlib import Path

from physink_tui.cli import main
from physink_tui.input.captures.capture import Capture

RECORDED = Path(__file__).resolve().parent / "recorded_hid"


def format_time(t: float) -> str:
    return f"{t:.6f}"


def _with_stamp(line_index: int, stamp: str) -> str:
    """A recorded capture with the timestamp of its ``line_index``-th report replaced by ``stamp``."""
    lines = (RECORDED / "windows-ink-strokes.hid").read_text().splitlines()
    events = [i for i, line in enumerate(lines) if line.startswith("E:")]
    k = events[line_index]
    parts = lines[k].split(None, 2)
    lines[k] = f"E: {stamp} {parts[2]}"
    return "\n".join(lines) + "\n"


def test_a_310_digit_timestamp_is_a_bad_line_not_infinity(tmp_path, capsys) -> None:
    path = tmp_path / "huge.hid"
    path.write_text(_with_stamp(40, "9" * 310 + ".000000"))
    capture = Capture.from_file(path)
    assert all(math.isfinite(e.t) for e in capture.events)
    (bad,) = capture.bad_lines
    assert "not a time a capture could hold" in bad.reason
    code = main(["decode", str(path)])
    out, err = capsys.readouterr()
    assert code == 0
    assert "Infinity" not in out and "NaN" not in out
    assert all(math.isfinite(json.loads(line)["t"]) for line in out.splitlines())
    assert f"line {bad.line}" in err or str(bad.line) in err  # the summary names the damaged line


def test_one_glitched_timestamp_does_not_hold_the_later_reports_time(tmp_path) -> None:
    clean = Capture.from_file(RECORDED / "windows-ink-strokes.hid")
    glitched = Capture.from_text(_with_stamp(40, format_time(clean.events[40].t + 3600.0)))
    (bad,) = glitched.bad_lines
    assert "jumps" in bad.reason and bad.line == clean.events[40].line
    assert [e.t for e in glitched.events] == [e.t for e in clean.events if e.line != bad.line]
    times = [e.t for e in glitched.events]
    assert times == sorted(times) and times[-1] < 3600.0


def test_segment_pauses_are_not_glitches() -> None:
    """Real captures pause between segments and carry on later: only a jump that comes straight back is one."""
    text = _with_stamp(0, format_time(0.0))
    lines = text.splitlines()
    events = [i for i, line in enumerate(lines) if line.startswith("E:")]
    for k in events[60:]:  # everything after the 60th report happens 30 s later
        stamp, rest = lines[k].split(None, 2)[1], lines[k].split(None, 2)[2]
        lines[k] = f"E: {format_time(float(stamp) + 30.0)} {rest}"
    capture = Capture.from_text("\n".join(lines) + "\n")
    assert capture.bad_lines == ()
    assert len(capture.events) == len(events)
